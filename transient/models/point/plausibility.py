"""Plausible inputs of an EHL point contact: the ranges real contacts (rolling bearings, traction drives,
ball-on-disc rigs) lie in, used to name a unit slip (a radius in mm, a viscosity in mPa s, a load in kN) where it
shows up as something else. Such a slip moves the contact far from EHL: its flooded inlet (Hamrock-Dowson's
critical meniscus) lies tens of Hertz widths upstream, the domain follows it, and the grid no longer resolves the
Hertz zone. These ranges are advice in that message, not limits: the model runs outside them.
"""

from __future__ import annotations

#: name -> (low, high, unit, the usual slip)
PLAUSIBLE = {
    "radius_x": (1e-4, 1.0, "m", "a radius in mm?"),
    "viscosity": (1e-4, 10.0, "Pa s", "a viscosity in mPa s (cP)?"),
    "speed": (1e-4, 100.0, "m/s", "a speed in mm/s?"),
}

#: the maximum Hertz pressure [Pa] of a loaded EHL point contact (a load in kN gives a tenth of it)
HERTZ_PRESSURE = (0.2e9, 5e9)


def implausible(radius_x, viscosity, speed, load, hertz_pressure) -> list[str]:
    """Each input outside :data:`PLAUSIBLE` as ``"name = value unit (plausible low ... high unit: the usual
    slip)"``; when they are all plausible, the load if the Hertz pressure it gives is outside
    :data:`HERTZ_PRESSURE`."""
    out = []
    for name, value in (("radius_x", radius_x), ("viscosity", viscosity), ("speed", speed)):
        lo, hi, unit, slip = PLAUSIBLE[name]
        if not lo <= value <= hi:
            out.append(f"{name} = {value:g} {unit} (plausible {lo:g} ... {hi:g} {unit}: {slip})")
    lo, hi = HERTZ_PRESSURE
    if not out and not lo <= hertz_pressure <= hi:  # judged by its pressure only when the rest is plausible
        out.append(f"load = {load:g} N (a Hertz pressure of {hertz_pressure / 1e9:.3g} GPa; plausible {lo / 1e9:g} ... "
                   f"{hi / 1e9:g} GPa: a load in kN?)")
    return out


def grid_message(grid, per_b, per_a, min_nodes, meniscus_b, found: list[str]) -> str:
    """The one-line refusal of a grid too coarse for the Hertz zone: led by the implausible inputs ``found``
    (:func:`implausible`) when there are any, since they, not the grid, are then what to change."""
    grid_text = (f"grid = {grid!r} puts {per_b:.3g} x {per_a:.3g} nodes per Hertz semi-axes b x a; allowed: at least "
                 f"{min_nodes}")
    if not found:
        return f"{grid_text} (more nodes or a smaller domain)"
    return (f"implausible for an EHL point contact: {'; '.join(found)}. With these inputs the domain reaches "
            f"{meniscus_b:.3g} b upstream (to the flooded inlet) and the {grid_text}")


def default_grid_message(grid, meniscus_b, found: list[str]) -> str:
    """The one-line refusal to choose the default grid for implausible inputs ``found`` (:func:`implausible`):
    the grid they ask for is named, and an explicit ``grid`` runs them as given."""
    return (f"implausible for an EHL point contact: {'; '.join(found)}. With these inputs the domain reaches "
            f"{meniscus_b:.3g} b upstream (to the flooded inlet) and the default grid would be {grid[0]} x {grid[1]} "
            f"nodes; allowed: plausible inputs, or an explicit grid to run them as given")
