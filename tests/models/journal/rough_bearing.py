"""The rough Rho & Kim journal bearing of the rough-film tests and their check of the equilibrium's force sensitivity
against finite differences."""

import numpy as np

from transient import JournalBearing, Roughness, steel_asperity_contact
from transient.params import rho_kim


def rough_bearing(sigma, grid, bearing=None, **roughness):
    """The Rho & Kim bearing on ``grid`` cells with steel asperities of composite roughness ``sigma`` [m] (boundary
    friction 0.12, 80 % of the variance on the journal); ``roughness`` to the :class:`~transient.Roughness`,
    ``bearing`` (a dict) over the bearing's parameters."""
    r = Roughness(steel_asperity_contact(sigma), boundary_friction=0.12, journal_variance_share=0.8, **roughness)
    return JournalBearing(**{**rho_kim.BEARING, **(bearing or {})}, grid=grid, roughness=r)


def check_force_sensitivity(f, q, fd_jacobian):
    """dF/d(X, Y) of film + asperities (the equilibrium's Newton matrix) of the steady film ``f`` at the position
    ``q`` against central differences (step 1e-6) of the force of steady films solved at the neighbouring
    positions; the asperities carry more than 5 % of the force there."""
    u = f.solve(*q)[0]
    F, dF, _ = f.force_sensitivity(u, *q)
    assert np.hypot(*f.contact_force(*q)) > 0.05 * np.hypot(*F)
    J = fd_jacobian(lambda p: f.force(f.solve(*p)[0], *p), q, 2, step=1e-6, relative=False)
    np.testing.assert_allclose(dF, J, rtol=2e-5, atol=2e-5 * np.abs(dF).max())
