"""Thrust ball bearing: per-ball starvation and replenishment between passes (seed 002, Jeong et al.)."""

from transient.models.ball.bearing import ThrustBallBearing

__all__ = ["ThrustBallBearing"]
