"""Rho & Kim, Table 1: the journal bearing and rotor of the noise paper, SI.

p_s = 1 atm; mu, beta, D, L/D = 0.3, C = D/1000; W = 981 N, unbalance e = 0.01 C. The rotor mass is not
stated: m = W / g = 100 kg is adopted (the load is the rotor's weight).
"""

BEARING = dict(diameter=0.08, length=0.024, clearance=80e-6, viscosity=0.029, bulk_modulus=1e9,
               supply_pressure=101325.0)
ROTOR = dict(rotor_mass=100.0, unbalance=0.8e-6, load=981.0)
#: What the paper reports (our reproduction targets).
REPORTED = dict(speed_rpm=6000.0, peak_speed_rpm=5000.0, threshold_rpm=7800.0)
