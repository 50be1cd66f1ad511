"""Lee & Rhim: the parallel thrust pad study. The paper gives no pad, oil or contact values; these
are our stated choices (steel contact values are in :data:`transient.physics.asperity.STEEL_CONTACT`).

Pad L = B = 20 mm, mu = 0.03 Pa s, load 600 N (apparent pressure 1.5 MPa), start at h0 = 5 Rq from rest;
surfaces: Gaussian heights, Rq = 5.0 um (Fig. 4a), triangular ACF, spacing 2 um, correlation lengths
lx = l0 sqrt(gamma), ly = l0 / sqrt(gamma) with l0 = 16 um (the same correlation area for every gamma);
Fig. 4b: gamma-type heights, Rq = 2.07 um, Sk = 0.3.
"""

PAD = dict(length=0.02, width=0.02, viscosity=0.03)
LOAD = 600.0
SURFACE = dict(rq=5.0e-6, spacing=2e-6, l0=16e-6, acf="triangular")
SURFACE_4B = dict(rq=2.07e-6, skewness=0.3, heights="gamma")
GAMMAS = (1 / 3, 1.0, 3.0)
