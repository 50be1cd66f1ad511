"""A thick elastic ring (a bearing housing) under uniform internal pressure: the radial give of its bore.

Lame's solution in plane stress (S. P. Timoshenko & J. N. Goodier, Theory of Elasticity, 3rd ed., 1970, sec. 28),
bore radius ``a``, outer radius ``b``, free outer surface, pressure ``p`` on the bore::

    u(a) = K p,   K = (a / E) ((b^2 + a^2) / (b^2 - a^2) + nu)

``K`` [m/Pa] is the compliance a Winkler bore (:class:`~transient.models.journal.roughness.Roughness`,
``bore_compliance``) takes for a housing of these dimensions: the give of the uniform-pressure (breathing) mode,
applied cell by cell.
"""

from __future__ import annotations

from transient.checks import check_positive, check_range


def bore_compliance(bore_radius, outer_radius, youngs_modulus, poisson_ratio) -> float:
    """Radial compliance ``K = u(a) / p`` [m/Pa] of the bore of a thick ring in plane stress (module docstring):
    bore radius ``a`` [m], outer radius ``b > a`` [m], Young's modulus ``E`` [Pa], Poisson's ratio ``nu``."""
    a = check_positive("bore_radius", bore_radius, "m")
    b = check_range("outer_radius", outer_radius, "m", a, float("inf"), low_open=True, high_open=True,
                    why="(the ring's outer radius exceeds its bore's)")
    E = check_positive("youngs_modulus", youngs_modulus, "Pa")
    nu = check_range("poisson_ratio", poisson_ratio, "-", -1.0, 0.5, low_open=True, high_open=True)
    return a / E * ((b * b + a * a) / (b * b - a * a) + nu)
