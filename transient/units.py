"""The unit conversions every model needs (SI at the API; shaft speeds are given in rpm)."""

from __future__ import annotations

import math


def rpm_to_rad_s(speed_rpm) -> float:
    """Angular speed [rad/s] of a shaft turning at ``speed_rpm`` [rpm]: ``2 pi n / 60``."""
    return 2.0 * math.pi * float(speed_rpm) / 60.0


def rpm_to_hz(speed_rpm):
    """Revolutions per second [1/s] of ``speed_rpm`` [rpm] (arrays pass through)."""
    return speed_rpm / 60.0
