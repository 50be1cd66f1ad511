"""Accuracy of the finite-volume Reynolds operator against closed forms (transient.verification.reference).

The discretised cases live in :mod:`transient.verification.cases` (shared with scenarios/film_validation.py)."""

import numpy as np
import pytest

from transient.verification.cases import observed_orders, short_bearing_case, sommerfeld_case, squeeze_plate_case


@pytest.mark.parametrize("delta", [0.0, 0.5])
def test_sommerfeld_second_order(delta):
    grids = (40, 80, 160, 320)
    out = [sommerfeld_case(n, delta) for n in grids]
    orders = observed_orders(grids, [o.p_err for o in out])
    # measured: uniform p error 8.1e-3 .. 1.27e-4, orders 2.00 2.00 2.00;
    #           stretched (delta 0.5) 5.6e-3 .. 8.5e-5, orders 2.01 2.02 2.01
    assert np.all((orders > 1.8) & (orders < 2.2)), orders
    # measured force error on n = 320: 9.1e-5 (uniform), 6.1e-5 (stretched)
    assert out[-1].fy_err < 1.5e-4
    # Fx = 0: exact antisymmetry on the uniform centred grid; a discretisation error on the stretched one
    # (measured 1.3e-6 of |Fy|)
    assert out[-1].fx_rel < (1e-10 if delta == 0.0 else 1e-5)


def test_short_bearing_limit():
    """Full 2 pi film, negative pressures kept: the finite bearing tends to Ocvirk's as L/D -> 0."""
    out = [short_bearing_case(LD) for LD in (0.1, 0.05, 0.025)]
    fy = np.array([o.fy_err for o in out])
    # measured (240 x 160 cells): 1.22e-2, 3.13e-3, 8.1e-4 -- the (L/D)^2 trend of the short-bearing
    # approximation (the z discretisation contributes ~2e-4 at this resolution)
    assert fy[0] < 1.5e-2
    assert np.all(fy[1:] < fy[:-1] / 3.0), fy
    assert all(o.fx_rel < 1e-10 for o in out)


@pytest.mark.parametrize("ratio", [1, 2, 4])
def test_squeeze_rectangular_plates(ratio):
    # measured relative errors 9.4e-4, 6.2e-4, 5.4e-4 (ratios 1, 2, 4; 64 cells across the short side)
    assert squeeze_plate_case(ratio, n=64).err < 5e-3


def test_squeeze_stretched_grid_second_order():
    grids = (16, 32, 64)
    errs = [squeeze_plate_case(2, n=n, delta=0.5).err for n in grids]
    orders = observed_orders(grids, errs)
    # measured: 1.12e-2, 2.82e-3, 7.1e-4 (orders 1.99, 2.00)
    assert np.all((orders > 1.8) & (orders < 2.2)), (errs, orders)
