"""Thrust ball bearing: per-ball starvation and replenishment between passes (Jeong et al.)."""

from transient.models.ball.bearing import ThrustBallBearing

__all__ = ["ThrustBallBearing"]
