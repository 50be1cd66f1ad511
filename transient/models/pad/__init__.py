"""Parallel thrust pad with rough surfaces: average-Reynolds squeeze film and asperity contact (Lee & Rhim)."""

from transient.models.pad.pad import ThrustPad

__all__ = ["ThrustPad"]
