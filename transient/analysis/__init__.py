"""Post-processing of simulated responses: periodicity detection, spectra, bearing acoustics. Takes Results and
arrays, never models."""

from transient.analysis.acoustics import (BearingNoise, a_weighting, analyse_pressure, energy_average,
                                          film_transitions, transmission_coefficient)
from transient.analysis.periodic import NotPeriodicError, find_settled, require_periodic
from transient.analysis.spectra import amplitude_spectrum, harmonic_amplitudes, mean_and_fluctuation

__all__ = ["BearingNoise", "NotPeriodicError", "a_weighting", "amplitude_spectrum", "analyse_pressure",
           "energy_average", "film_transitions", "find_settled", "harmonic_amplitudes", "mean_and_fluctuation",
           "require_periodic", "transmission_coefficient"]
