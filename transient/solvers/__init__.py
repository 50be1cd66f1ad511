"""Numerical solvers: the integrator facade, one sparse Newton, the long-run driver."""
