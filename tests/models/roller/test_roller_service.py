"""The tapered roller on a coarse clustered grid: convergence, the steady fields as a table, maps in SI units."""

import numpy as np
import pytest

from transient.models.roller import RollerContact, TaperedRoller
from transient.params import park
from transient.plots.roller import maps


@pytest.fixture(scope="module")
def coarse():
    c = RollerContact.from_dimensionless(**park.DIMENSIONLESS, roller=TaperedRoller(**park.ROLLER), speed=park.SPEED,
                                         grid=("clustered", 48, 24))
    return c.steady()


def test_clustered_48_by_24_converges(coarse):
    assert coarse.success and abs(coarse.load_error) < 1e-6 and coarse.h_min > 0


def test_steady_fields_export_as_a_node_table(coarse):
    df = coarse.to_dataframe()
    assert len(df) == coarse.x.size * coarse.y.size and list(df.columns) == ["x", "y", "pressure", "film"]
    assert df.attrs["units"] == {"x": "m", "y": "m", "pressure": "Pa", "film": "m"}
    j, i = 3, 5
    row = df.iloc[j * coarse.x.size + i]
    assert (row.x, row.y, row.pressure, row.film) == (coarse.x[i], coarse.y[j], coarse.pressure[j, i], coarse.film[j, i])


def test_maps_in_gpa_and_micrometres(coarse):
    fig = maps(coarse, "pressure", units="SI")
    cbar = fig.axes[-1]
    assert "GPa" in cbar.get_ylabel() and "mm" in fig.axes[0].get_xlabel()
    assert np.isclose(cbar.get_ylim()[1], coarse.p_max * 1e-9, rtol=0.1)
    assert "um" in maps(coarse, "film", units="SI").axes[-1].get_ylabel().replace(r"$\mu$", "u")
    with pytest.raises(ValueError, match="units"):
        maps(coarse, units="imperial")
