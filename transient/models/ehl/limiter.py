"""The slope limiter of the EHL films' second-order upwind Couette flux (line, roller and point contacts): van
Albada's ``s(a, b) = a b (a + b)/(a^2 + b^2)`` where ``a b > 0``, else 0 (van Albada, van Leer & Roberts, *Astron.
Astrophys.* 108, 1982); second order where the mass flux is smooth, first order at its extrema (the flux law in
:mod:`transient.models.ehl.rows`)."""

from numba import njit


@njit(cache=True, error_model="numpy")
def van_albada(a, b):
    """Limited slope ``s(a, b)`` (this module's docstring) and its derivatives ``ds/da``, ``ds/db``."""
    if a * b <= 0.0:
        return 0.0, 0.0, 0.0
    num = a * b * (a + b)
    den = a * a + b * b
    s = num / den
    return s, ((2.0 * a * b + b * b) * den - 2.0 * a * num) / (den * den), \
        ((a * a + 2.0 * a * b) * den - 2.0 * b * num) / (den * den)
