"""The journal orbit's settling verdict (Fig. 3) is the criterion its figure plots: a run whose revolutions never
come within 1 % of the last is not called settled."""

from transient.study.journal import settled_from


def test_a_run_that_never_comes_within_1_percent_is_not_settled():
    assert settled_from([0.5, 0.1, 0.05, 0.02, 0.0], amplitude=1.0) == 0  # the last revolution is the reference


def test_settled_from_the_first_revolution_that_stays_within():
    assert settled_from([0.5, 0.02, 0.008, 0.012, 0.004, 0.0], amplitude=1.0) == 5
    assert settled_from([0.5, 0.009, 0.008, 0.004, 0.0], amplitude=1.0) == 2
    assert settled_from([0.0], amplitude=1.0) == 0
