"""Park, "EHL analysis of a tilted tapered roller" (KSTLE 2015): the paper's parameter set.

The paper is dimensionless (lengths by the mean radius R_m, ``P = p/E'``). Its list, with our reading
(docs/ehl.md): ``R_d* = 0.5``, ``|Y_d| = 0.7``, ``theta = 10 deg``, ``U_m = 1e-11``, "T = 2,500" read as
``G = alpha E' = 2500``, ``W = 2e-5`` (total load / (E' R_m^2)), ``E' = 220 GPa``, ``|phi| = 0.002 deg``,
Dowson-Higginson density with 0.58 and 1.68 /GPa, Barus viscosity. The paper gives neither R_m nor the
roller length: ``R_m = 10 mm`` and a length of ``2 R_m`` (longer than the computational domain, +-0.55 d
~ +-0.78 R_m) are adopted; the dimensionless results do not depend on R_m, and ``speed = 1 m/s`` only
sets the SI viscosity (``eta0 = U_m E' R_m / u = 0.022 Pa s``).
"""

MEAN_RADIUS = 0.01
ROLLER = dict(mean_radius=MEAN_RADIUS, half_angle_deg=10.0, length=2.0 * MEAN_RADIUS,
              dub_off_radius=0.5 * MEAN_RADIUS, profile_start=0.7 * MEAN_RADIUS)
DIMENSIONLESS = dict(U=1e-11, G=2500.0, W=2e-5, modulus=220e9)
TILTS_DEG = (0.002, -0.002, 0.0)
SPEED = 1.0
#: The paper's grid (maximum node counts) and domain (units of c, c, d).
GRID = (94, 45)
DOMAIN = (-5.0, 2.5, 0.55)
#: What the paper reports (figures 3-10, read qualitatively).
REPORTED = dict(spike=True, flat_central_film=True, outlet_constriction=True,
                small_end_more_affected=True, pressure_more_affected_than_film=True,
                transverse_peak_inboard_of_min_film=True, untilted_max_pressure_and_min_film_at_small_end=True)
