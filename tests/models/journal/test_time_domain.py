"""One statement of what the time-domain films take: the journal orbit and the rotor system refuse the same bearing
settings in the same words, from one table whose entries are lifted one line at a time."""

from types import SimpleNamespace

import pytest

from transient import JournalBearing, JournalOrbit, Rotor, RotorBearingSystem
from transient.models.journal import time_domain
from transient.models.journal.time_domain import NOT_IN_TIME_DOMAIN, check_time_domain
from transient.params.rho_kim import BEARING, ROTOR

ALIGNED_SMOOTH = dict(cavitation="elrod", roughness=None, misalignment=(0.0, 0.0), thermal=None)
REFUSED = {"cavitation": ("reynolds", "cavitation = 'reynolds'; allowed: 'elrod'"),
           "thermal": (object(), "thermal = ThermalFilm(...); allowed: None")}


@pytest.mark.parametrize("name", sorted(NOT_IN_TIME_DOMAIN))
def test_each_setting_is_refused_in_one_wording_by_the_models_that_refuse_it(name):
    value, words = REFUSED[name]
    bearing = SimpleNamespace(**dict(ALIGNED_SMOOTH, **{name: value}))
    texts = []
    for owner, where in (("JournalOrbit", ""), ("RotorBearingSystem", "bearings[3] ")):
        if owner not in NOT_IN_TIME_DOMAIN[name].refused_by:
            check_time_domain(owner, bearing, where)  # lifted for this model: taken
            continue
        with pytest.raises(ValueError) as e:
            check_time_domain(owner, bearing, where)
        assert str(e.value).startswith(f"{owner}: {where}{words} (")
        texts.append(str(e.value).split(": ", 1)[1].removeprefix(where))
    assert texts and len(set(texts)) == 1
    check_time_domain("JournalOrbit", SimpleNamespace(**ALIGNED_SMOOTH))  # the films' own settings pass


def test_lifting_a_refusal_for_one_model_is_one_entry(monkeypatch):
    entry = NOT_IN_TIME_DOMAIN["cavitation"]
    monkeypatch.setitem(time_domain.NOT_IN_TIME_DOMAIN, "cavitation", entry._replace(refused_by=("RotorBearingSystem",)))
    reynolds = SimpleNamespace(**dict(ALIGNED_SMOOTH, cavitation="reynolds"))
    check_time_domain("JournalOrbit", reynolds)
    with pytest.raises(ValueError, match=r"^RotorBearingSystem: cavitation = 'reynolds'"):
        check_time_domain("RotorBearingSystem", reynolds)


def test_the_models_use_the_statement():
    b = JournalBearing(**BEARING, grid=(16, 4), cavitation="reynolds")
    with pytest.raises(ValueError) as orbit:
        JournalOrbit(b, ROTOR["rotor_mass"], 0.0, ROTOR["load"], 3000.0)
    rotor = Rotor.example()
    with pytest.raises(ValueError) as system:
        RotorBearingSystem(rotor, {n: b for n in rotor.bearing_nodes})
    node = rotor.bearing_nodes[0]
    assert str(orbit.value) == "JournalOrbit: " + str(system.value).removeprefix(
        f"RotorBearingSystem: bearings[{node!r}] ")
