"""The journal bearing's own error: a load the film (and, for a rough bearing, its asperities) cannot carry."""


class NoEquilibriumError(RuntimeError, ValueError):
    """The film cannot carry the load at this speed inside the clearance (names ``load`` and ``speed_rpm``)."""
