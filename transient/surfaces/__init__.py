"""Rough surfaces: generation and numerical flow factors."""
