"""Finite-volume machinery: grids, the 5-point stencil and the generalised Reynolds operator."""
