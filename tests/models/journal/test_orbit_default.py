"""``JournalOrbit.run``'s default method: the variable-order BDF on the content film (``method="bdf2"``, order up to
5, each step bounded in journal travel, 50 steps per revolution as a safety bound), against a tight IDA reference
in the same run: on a small orbit its steps follow the rotor's error test (far fewer than plain BDF2's cap of 550
per revolution, and than IDA's) for an error of the order of IDA's at its own default rtol (1e-7 C) and twenty times
smaller than plain BDF2's."""

import numpy as np
import pytest

from transient.models.journal.bearing import JournalBearing
from transient.models.journal.orbit import JournalOrbit
from transient.params.rho_kim import BEARING, ROTOR
from transient.solvers.settings import Integration, LongRun, Recording

C = BEARING["clearance"]
REC, LR = Recording(outputs_per_revolution=20), LongRun(progress=False)


def _error(r, ref):
    return float(np.max(np.hypot(r.x - ref.x, r.y - ref.y)) / C)


@pytest.mark.filterwarnings("ignore:groove.width_deg")
def test_the_default_is_the_bdf_and_on_a_small_orbit_it_follows_the_error_test():
    o = JournalOrbit(JournalBearing(**BEARING, grid=(40, 6)), ROTOR["rotor_mass"], 0.01 * C, ROTOR["load"], 6000.0)
    ref = o.run(1.0, integration=Integration(rtol=1e-9, atol=1e-12), recording=REC, long_run=LR)
    ida = o.run(1.0, integration=Integration(), recording=REC, long_run=LR)  # IDA at its default rtol 1e-6
    default = o.run(1.0, recording=REC, long_run=LR)
    plain = o.run(1.0, integration=Integration(method="bdf2", max_order=2, steps_per_revolution=550), recording=REC,
                  long_run=LR)
    assert default.success and default.method == "bdf2"
    assert default.stats.n_steps < 0.5 * plain.stats.n_steps  # plain BDF2 is held at >= 550 by its cap
    assert default.stats.n_steps < ida.stats.n_steps
    assert _error(default, ref) <= 3.0 * _error(ida, ref)  # measured 1.7x (7.8e-8 C against 4.6e-8 C), 0.53x the steps
    assert _error(default, ref) < 0.1 * _error(plain, ref)
