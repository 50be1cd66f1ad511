"""The line and the roller contact's transient results from their runs: the series ``h_central``, ``h_min``,
``p_max``, ``h0``, ``load`` at the outputs and the final profile (the result type's ``snapshot_fields``) of the
contact's steady result at the last state -- for an IDA run on the penalty form (:func:`squeeze_result`) and for the
BDF2 run on the film content (:func:`content_outputs`, the ``sample`` and ``result`` of
:func:`~transient.models.roller.line_step.run_content_transient`)."""

from __future__ import annotations

import numpy as np


def squeeze_result(result_type, sol, wall, rows, ratio, t_ref: float, w_ref: float, film_scale: float):
    """``result_type`` (:class:`~transient.models.roller.results.LineTransient` or ``RollerTransient``) of an IDA
    run (:func:`~transient.models.roller.transient.run_squeeze`'s ``sol, wall, rows``: the steady results at its
    outputs) in time unit ``t_ref`` [s], load ratio ``ratio(tau)`` of the load ``w_ref`` and film scale
    ``film_scale`` [m]."""
    last = rows[-1]
    return result_type(t=sol.t * t_ref, h_central=np.array([r.h_central for r in rows]),
                       h_min=np.array([r.h_min for r in rows]), p_max=np.array([r.p_max for r in rows]),
                       h0=sol.y[:, -1] * film_scale, load=np.array([ratio(t) for t in sol.t]) * w_ref,
                       **{name: getattr(last, name) for name in result_type.snapshot_fields},
                       success=sol.success, message=sol.message, stats=sol.stats, n_steps=sol.stats.n_steps,
                       n_jacobians=sol.stats.n_jac, wall_time=wall, final_state=sol.y[-1].copy(),
                       final_time=float(sol.t[-1] * t_ref))


def content_outputs(result_type, steady_at, n: int, ratio, t_ref: float, w_ref: float, film_scale: float):
    """``(sample, result)`` of a film-content run on ``u = [p (n), content (n), h0]``: ``steady_at(y, content)``
    is the contact's steady result at ``y = [p, h0]`` (``content`` None at the outputs, the last state's at the
    end); ``ratio``, ``t_ref``, ``w_ref``, ``film_scale`` as in :func:`squeeze_result`."""

    def state(u):
        return np.append(u[:n], u[-1])

    def sample(tau, u):
        r = steady_at(state(u), None)
        return dict(h_central=r.h_central, h_min=r.h_min, p_max=r.p_max, h0=u[-1] * film_scale,
                    load=ratio(tau) * w_ref)

    def result(a, u, stats, message):
        last = steady_at(state(u), u[n: 2 * n])
        return result_type(t=a["t"] * t_ref, h_central=a["h_central"], h_min=a["h_min"], p_max=a["p_max"],
                           h0=a["h0"], load=a["load"],
                           **{name: getattr(last, name) for name in result_type.snapshot_fields}, success=True,
                           message=message or "completed", stats=stats, n_steps=stats.n_steps,
                           n_jacobians=stats.n_jac, wall_time=stats.wall_time, final_state=state(u),
                           final_time=float(a["t"][-1]) * t_ref if len(a["t"]) else 0.0)

    return sample, result
