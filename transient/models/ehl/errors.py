"""The EHL solves' failure and warning types, shared by the line, roller and point contacts."""


class EHLConvergenceError(RuntimeError):
    """A steady EHL solve did not converge; ``result`` is the last iterate, flagged ``success=False``."""

    def __init__(self, message: str, result):
        super().__init__(message)
        self.result = result


class InexactStepWarning(RuntimeWarning):
    """Newton steps of a steady EHL solve were taken with their linear solve (GMRES) short of its tolerance."""
