"""Pointwise physical laws: cavitation switch, lubricant viscosity and density, layered films, contact, film-thickness formulas.

Nothing here knows a grid: finite-volume machinery lives in :mod:`transient.fv`, and ``fv`` and
``physics`` never import each other.
"""
