"""Parallel thrust pad with rough surfaces: average-Reynolds squeeze film and asperity contact (seed 000)."""

from transient.models.pad.pad import ThrustPad

__all__ = ["ThrustPad"]
