"""Jeong, Lee, Yoo & Cho: the thrust ball bearing of the starvation paper, SI.

Table 1: E = 207 GPa, nu = 0.3, pitch diameter 31 mm, ball 3 mm, surface tension 0.036 N/m, viscosity
0.02 Pa s; the pressure-viscosity coefficient is not stated (2.0e-8 1/Pa, a typical mineral oil, adopted).
Table 2, the reference operating point: 30 N, 80 rpm, ambient film 100 um, 6 balls, conformity 0.52.

``MAP_SETTINGS`` are our stated choices for the regime maps (not the paper's): the physical replenishment
model (front-following mesh, no mobility floor, precursor = outlet film h_c/2), CVODE BDF2 at rtol 1e-3
(docs/ball.md: the inlet films move by < 0.5 % against rtol 1e-5, the verdicts not at all).
"""

BEARING = dict(pitch_diameter=0.031, ball_diameter=0.003, n_balls=6, conformity=0.52, youngs_modulus=207e9,
               poisson_ratio=0.3, viscosity=0.02, pressure_viscosity=2.0e-8, surface_tension=0.036)
REFERENCE = dict(load=30.0, speed_rpm=80.0, ambient_film=100e-6, n_balls=6)
#: The regime boundaries the paper reports (Figs. 7-9): the last value of each regime.
REPORTED = dict(n_balls=dict(flooded=5, starved=6), speed_rpm=dict(flooded=78.0, starved=82.0),
                load=dict(flooded=25.0, starved=40.0))
#: The swept ranges of Figs. 7-11.
RANGES = dict(n_balls=tuple(range(1, 12)), speed_rpm=(70.0, 75.0, 80.0, 85.0, 90.0),
              load=(10.0, 20.0, 30.0, 40.0, 50.0, 60.0), ambient_film=(100e-6, 125e-6, 150e-6))
MAP_SETTINGS = dict(replenishment="thin_film", grid="front", rtol=1e-3, atol=1e-7)
