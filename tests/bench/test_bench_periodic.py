"""The periodic bench's equal-accuracy settle: the revolutions an oracle-stopped settle must run."""

from transient.bench.periodic import oracle_revolutions


def test_oracle_stops_at_the_first_revolution_within_for_good():
    # revolution 3 is within the target but 4 is not again: the settle must run to revolution 5
    assert oracle_revolutions([1e-2, 1e-3, 1e-5, 2e-4, 5e-5, 3e-5], 1e-4) == 5


def test_oracle_within_from_the_first_revolution():
    assert oracle_revolutions([1e-6, 2e-6], 1e-4) == 1


def test_oracle_never_within_counts_every_revolution():
    assert oracle_revolutions([1e-2, 5e-3, 2e-3], 1e-4) == 3
