"""Thin-film levelling with re-wetting fronts: finite volumes on a mesh that follows the front.

Scaled equation (lengths in ``x_ref = a'``, films in ``h_ref = h_inf``, time in
``T = 3 eta a'^4 / (sigma h_inf^3)``; :mod:`transient.models.ball.levelling`)::

    H_t + q_x = 0,    q = H^3 H_xxx                                                       (TF)

with no floor on the mobility: where the ball has passed, the race carries the film the contact left
behind, ``eps = h_out / h_inf`` (the precursor), and a ridge of oil re-wets that track by a capillary
front advancing over it. The front has an inner length ``~ eps V^(-1/3)`` (``V`` its speed; the
precursor-film travelling wave ``H^3 H''' = V (H - eps)``), 1e-5 .. 1e-3 of ``a'``: a uniform grid
that resolves it across the whole track is 1e4-1e5 cells, and every cell the front crosses costs
the integrator steps. Here the grid moves with the front instead.

Mesh (``FrontMesh``): faces ``x_j = alpha_j + beta_j s`` (affine in the front position ``s``):

* a left zone ``[0, s - d1]`` of ``n_left`` uniform cells (the dry track ahead of the front), stretched
  with ``s`` (``beta`` from 0 to 1);
* a rigid cluster ``[s - d1, s + d2]`` (``beta = 1``, moves with the front) with a face at ``s`` and
  cells growing geometrically from ``dx_min`` on both sides (``dx_min ~ eps / 2``: the inner scale);
* a compression zone ``[s + d2, x_fix]`` (``beta`` from 1 to 0) and a fixed zone ``[x_fix, X]``
  whose faces never move (so the remap between passes is the identity there).

Unknowns: the cell contents ``c_i = H_i dx_i`` (so the discrete volume ``sum c_i`` is a linear
invariant: conserved to round-off by the BDF steps whatever the mesh does) and, while the front is
followed, ``s``. Arbitrary Lagrangian-Eulerian fluxes through the moving faces::

    dc_i/dt = -(F_{i+1} - F_i),   F_j = q_j - Hu_j v_j,   v_j = beta_j ds/dt

(``Hu_j`` the value of the cell upwind of the face relative to its motion: ahead of the front the oil is
the precursor, which has no mobility to damp the odd-even wiggles a central value would make)

``q_j = Hf_j^3 6 H[z_{j-2}, .., z_{j+1}]`` (the third divided difference of the four cell values
around the face: exact for cubics on any mesh; ``(H_{j+1} - 3 H_j + 3 H_{j-1} - H_{j-2})/dx^3`` on a
uniform one), ``Hf_j`` the linear interpolation of the two neighbours at the face. Boundaries by
ghost cells mirrored in position: symmetry at ``x = 0``; at ``x = X`` the reservoir (``H = H_res``,
``H_xx = 0``: ghosts odd about ``H_res``) or a closed wall (even ghosts, no flux).

Front law: the cell just behind ``s`` (index ``jc``) is held at the level ``H* = kappa eps``::

    ds/dt = [ (q_{jc+1} - q_jc) - (c_jc - dx_jc H*) / tau ] / D+,   D = Hf_{jc+1} - Hf_jc

(``D+ = (D + sqrt(D^2 + delta^2))/2``). With this speed ``dH_jc/dt = -(H_jc - H*)/tau`` exactly: the
mesh follows the level set ``H = H*`` of the front foot (a quasi-Lagrangian coordinate), wherever it
goes, at whatever speed; a stalled front (``q`` flat) stops the mesh. The law depends on five cells and
``s``, so the Jacobian is the pentadiagonal band plus five dense columns (the ALE term of every moving
face depends on ``ds/dt``), the ``s`` column and a short ``s`` row: analytic, in a fixed CSC pattern,
checked against finite differences in the tests.

When ``s`` reaches ``s_stop`` (the front meets its mirror image at the centreline) or ``s_max`` the mesh
is frozen (terminal event, restart with ``s`` fixed: same faces, same contents, no remap).
"""

from __future__ import annotations

import math

import numba as nb
import numpy as np
import scipy.sparse as sp

from transient.checks import check_choice
from transient.solvers.integrate import Problem, solve

RESERVOIR, CLOSED = 0, 1


# --------------------------------------------------------------------------------------------------
# mesh
# --------------------------------------------------------------------------------------------------

def _geometric(d0: float, r: float, length: float) -> np.ndarray:
    """Offsets ``0, d0, d0 + d0 r, ...`` up to ``length`` (last one exactly ``length``, the last cell merged
    into its neighbour if it would be shorter than half the previous one)."""
    out = [0.0]
    d = d0
    while out[-1] + d < length:
        out.append(out[-1] + d)
        d *= r
    if len(out) > 1 and length - out[-1] < 0.5 * (out[-1] - out[-2]):
        out[-1] = length
    else:
        out.append(length)
    return np.array(out)


def _graded(d0: float, r: float, d_max: float, length: float) -> np.ndarray:
    """Offsets from 0 to ``length``: geometric from ``d0`` at rate ``r`` up to ``d_max``, then uniform."""
    out = [0.0]
    d = d0
    while out[-1] + d < length:
        out.append(out[-1] + d)
        d = min(d * r, d_max)
    if len(out) > 1 and length - out[-1] < 0.5 * (out[-1] - out[-2]):
        out[-1] = length
    else:
        out.append(length)
    return np.array(out)


class FrontMesh:
    """Faces ``x_j(s) = alpha_j + beta_j s`` on ``[0, X]`` with a rigid fine cluster centred on the front ``s``.

    Parameters (scaled lengths)
    ----------
    length : ``X``; s0 : the front position the mesh is designed at (the band edge, 1).
    dx_min : finest cell, at the front; growth : geometric growth rate of the cells behind the front,
    growth_ahead : ahead of it (the dry track: the foot of the front, then nothing happens);
    d_ahead, d_behind : cluster extents ``d1``, ``d2``; dx_max : largest cell near the track;
    dx_far : largest cell of the fixed zone; x_fix : start of the fixed zone (default ``s0 + d2 + 1.5``).
    ``refine`` divides every cell size and every ``growth - 1`` (the grid convergence knob).
    """

    def __init__(self, length: float, dx_min: float, *, s0: float = 1.0, growth: float = 1.12,
                 growth_ahead: float = 1.25, d_ahead: float = 0.02, d_behind: float = 0.3, dx_max: float = 0.08,
                 dx_far: float = 0.25, x_fix: float | None = None, refine: float = 1.0):
        if not (np.isfinite(length) and length > 0):
            raise ValueError(f"length = {length!r} [x_ref] must be finite and > 0")
        if not (0 < dx_min < 1e-1):
            raise ValueError(f"dx_min = {dx_min!r} [x_ref] must be in (0, 0.1)")
        if not refine > 0:
            raise ValueError(f"refine = {refine!r} [-] must be > 0")
        f = float(refine)
        dx_min, dx_max, dx_far = dx_min / f, dx_max / f, dx_far / f
        growth, growth_ahead = 1.0 + (growth - 1.0) / f, 1.0 + (growth_ahead - 1.0) / f
        X = float(length)
        d1, d2 = float(d_ahead), float(d_behind)
        if x_fix is None:
            x_fix = 1.0 + d2 + 1.5
        x_fix = min(x_fix, 1.0 + d2 + 0.6 * (X - 1.0 - d2))
        if not (s0 - d1 > 0 and s0 + d2 < x_fix < X):
            raise ValueError(f"front mesh does not fit: s0 = {s0}, d_ahead = {d1}, d_behind = {d2}, x_fix = {x_fix}, "
                             f"length = {X} [x_ref]")
        ahead = _geometric(dx_min, growth_ahead, d1)            # offsets from the front, 0 .. d1
        behind = _geometric(dx_min, growth, d2)                 # 0 .. d2
        # left zone [0, s - d1], designed at s0: graded from the cluster's outer cell towards x = 0
        left = _graded((ahead[-1] - ahead[-2]) * growth_ahead, growth_ahead, min(dx_max, 0.04 * s0), s0 - d1)
        u = 1.0 - left[::-1] / left[-1]                         # x = (s - d1) u, u from 0 to 1
        comp = _graded((behind[-1] - behind[-2]) * growth, growth, dx_max, x_fix - s0 - d2)   # at s = s0
        far = x_fix + _graded(comp[-1] - comp[-2], growth, dx_far, X - x_fix)
        far[-1] = X
        a_left, b_left = -d1 * u, u
        a_cl = np.concatenate([-ahead[::-1], behind[1:]])       # cluster: x = s + offset
        b_cl = np.ones_like(a_cl)
        phi = comp / comp[-1]                                   # compression: x = (s + d2) + (x_fix - s - d2) phi
        a_cp = d2 + (x_fix - d2) * phi
        b_cp = 1.0 - phi
        alpha = np.concatenate([a_left, a_cl[1:], a_cp[1:], far[1:]])
        beta = np.concatenate([b_left, b_cl[1:], b_cp[1:], np.zeros(far.size - 1)])
        alpha[0], beta[0] = 0.0, 0.0
        self.alpha, self.beta = alpha, beta
        self.n = alpha.size - 1
        self.n_left = left.size - 1
        self.jc = self.n_left + ahead.size - 1                  # face index at x = s
        self.length, self.s0, self.d_ahead, self.d_behind, self.x_fix = X, float(s0), d1, d2, float(x_fix)
        self.dx_min = dx_min
        self.options = dict(growth=growth, growth_ahead=growth_ahead, d_ahead=d1, d_behind=d2, dx_max=dx_max,
                            dx_far=dx_far, x_fix=x_fix)  # refined values: redesign() passes refine=1
        # follow the front down to s0/3 (then a mesh designed for that s0 takes over: `final` is False) or,
        # on the last mesh, to 1.5 d1; and up to where the compression zone would be squeezed to a
        # twentieth of its design width
        self.final = s0 / 3.0 <= 1.5 * d1
        self.s_stop = 1.5 * d1 if self.final else s0 / 3.0
        self.s_max = x_fix - d2 - 0.05 * (x_fix - s0 - d2)
        self.s_lo = 0.5 * (d1 + self.s_stop)            # the geometry is evaluated with s clamped to here
        self.s_hi = 0.5 * (self.s_max + x_fix - d2)
        x = self.faces(s0)
        if np.any(np.diff(x) <= 0):
            raise ValueError("front mesh faces are not increasing")

    def redesign(self, s0: float) -> "FrontMesh":
        """The same cluster (identical cells around the front) with the left zone designed for ``s0``."""
        return FrontMesh(self.length, self.dx_min, s0=s0, **self.options)

    def faces(self, s: float) -> np.ndarray:
        return self.alpha + self.beta * s

    def widths(self, s: float) -> np.ndarray:
        return np.diff(self.faces(s))

    def centres(self, s: float) -> np.ndarray:
        x = self.faces(s)
        return 0.5 * (x[:-1] + x[1:])


class FixedMesh:
    """A mesh that does not move (``beta = 0``), same interface as :class:`FrontMesh` (references, tests)."""

    def __init__(self, faces):
        faces = np.asarray(faces, dtype=float)
        if faces.ndim != 1 or faces.size < 6 or faces[0] != 0.0 or np.any(np.diff(faces) <= 0):
            raise ValueError("faces must start at 0, increase strictly and make at least 5 cells")
        self.alpha, self.beta = faces.copy(), np.zeros_like(faces)
        self.n, self.jc, self.length = faces.size - 1, 2, float(faces[-1])
        self.s0 = self.s_stop = self.s_max = self.s_lo = self.s_hi = 0.0
        self.final = True
        self.dx_min = float(np.diff(faces).min())

    def faces(self, s: float = 0.0) -> np.ndarray:
        return self.alpha.copy()

    def widths(self, s: float = 0.0) -> np.ndarray:
        return np.diff(self.alpha)

    def centres(self, s: float = 0.0) -> np.ndarray:
        return 0.5 * (self.alpha[:-1] + self.alpha[1:])


# --------------------------------------------------------------------------------------------------
# numba kernels
# --------------------------------------------------------------------------------------------------

@nb.njit(cache=True)
def _geometry(c, s, alpha, beta, X, h_res, closed, xf, dw, z, dz, h, dh, ze, dze, he, dhe, re, she):
    """Faces, widths, centres, values and their s-derivatives (fixed contents); ghost-extended arrays
    (index e + 2 for e = -2 .. n+1): position, d position/ds, value, d value/ds, real cell, d value/d real."""
    n = c.size
    for j in range(n + 1):
        xf[j] = alpha[j] + beta[j] * s
    for i in range(n):
        w = xf[i + 1] - xf[i]
        dw[i] = beta[i + 1] - beta[i]
        z[i] = 0.5 * (xf[i] + xf[i + 1])
        dz[i] = 0.5 * (beta[i] + beta[i + 1])
        h[i] = c[i] / w
        dh[i] = -h[i] * dw[i] / w
    for i in range(n):
        ze[i + 2], dze[i + 2], he[i + 2], dhe[i + 2], re[i + 2], she[i + 2] = z[i], dz[i], h[i], dh[i], i, 1.0
    for g in range(2):  # left mirror: e = -1 -> cell 0, e = -2 -> cell 1
        e, r = 1 - g, g
        ze[e], dze[e], he[e], dhe[e], re[e], she[e] = -z[r], -dz[r], h[r], dh[r], r, 1.0
    for g in range(2):  # right: e = n -> cell n-1, e = n+1 -> cell n-2
        e, r = n + 2 + g, n - 1 - g
        ze[e], dze[e], re[e] = 2.0 * X - z[r], -dz[r], r
        if closed:
            he[e], dhe[e], she[e] = h[r], dh[r], 1.0
        else:
            he[e], dhe[e], she[e] = 2.0 * h_res - h[r], -dh[r], -1.0


@nb.njit(cache=True)
def _face(j, ze, dze, he, dhe, xfj, dxfj, mob0, dq_dh, dhf_dh, out):
    """Flux ``q`` and face value ``Hf`` at face j (between cells j-1 and j) with their derivatives by the
    four stencil values (``dq_dh``, ``dhf_dh``) and by s at fixed contents;
    out = (q, hf, dq_ds, dhf_ds, mobility, d mobility/d H_left, d mobility/d H_right)."""
    z0, z1, z2, z3 = ze[j], ze[j + 1], ze[j + 2], ze[j + 3]
    h0, h1, h2, h3 = he[j], he[j + 1], he[j + 2], he[j + 3]
    # weights of the third divided difference (6 times it is H_xxx of the cubic through the four points)
    w0 = 1.0 / ((z0 - z1) * (z0 - z2) * (z0 - z3))
    w1 = 1.0 / ((z1 - z0) * (z1 - z2) * (z1 - z3))
    w2 = 1.0 / ((z2 - z0) * (z2 - z1) * (z2 - z3))
    w3 = 1.0 / ((z3 - z0) * (z3 - z1) * (z3 - z2))
    d3 = w0 * h0 + w1 * h1 + w2 * h2 + w3 * h3
    # d d3 / d z_m at fixed values: sum_{a != m} h_a w_a / (z_a - z_m) - h_m w_m sum_{b != m} 1/(z_m - z_b)
    g0 = h1 * w1 / (z1 - z0) + h2 * w2 / (z2 - z0) + h3 * w3 / (z3 - z0) \
        - h0 * w0 * (1.0 / (z0 - z1) + 1.0 / (z0 - z2) + 1.0 / (z0 - z3))
    g1 = h0 * w0 / (z0 - z1) + h2 * w2 / (z2 - z1) + h3 * w3 / (z3 - z1) \
        - h1 * w1 * (1.0 / (z1 - z0) + 1.0 / (z1 - z2) + 1.0 / (z1 - z3))
    g2 = h0 * w0 / (z0 - z2) + h1 * w1 / (z1 - z2) + h3 * w3 / (z3 - z2) \
        - h2 * w2 * (1.0 / (z2 - z0) + 1.0 / (z2 - z1) + 1.0 / (z2 - z3))
    g3 = h0 * w0 / (z0 - z3) + h1 * w1 / (z1 - z3) + h2 * w2 / (z2 - z3) \
        - h3 * w3 * (1.0 / (z3 - z0) + 1.0 / (z3 - z1) + 1.0 / (z3 - z2))
    dd3_ds = (g0 * dze[j] + g1 * dze[j + 1] + g2 * dze[j + 2] + g3 * dze[j + 3]
              + w0 * dhe[j] + w1 * dhe[j + 1] + w2 * dhe[j + 2] + w3 * dhe[j + 3])
    th = (xfj - z1) / (z2 - z1)
    hf = (1.0 - th) * h1 + th * h2
    dth = (dxfj - dze[j + 1]) / (z2 - z1) - th * (dze[j + 2] - dze[j + 1]) / (z2 - z1)
    dhf_ds = (1.0 - th) * dhe[j + 1] + th * dhe[j + 2] + (h2 - h1) * dth
    # mobility: Zhornitskaya & Bertozzi's positivity-preserving mean of h^3 over the two neighbours,
    # a = (hR - hL) / int_hL^hR s^-3 ds = 2 hL^2 hR^2 / (hL + hR)  (= h^3 when they are equal)
    if h1 > 0.0 and h2 > 0.0:
        sm2 = h1 + h2
        mob = 2.0 * h1 * h1 * h2 * h2 / sm2 + mob0
        dm_l = 2.0 * h1 * h2 * h2 * (h1 + 2.0 * h2) / (sm2 * sm2)
        dm_r = 2.0 * h2 * h1 * h1 * (h2 + 2.0 * h1) / (sm2 * sm2)
    else:
        mob = mob0
        dm_l = 0.0
        dm_r = 0.0
    dq_dh[0] = 6.0 * mob * w0
    dq_dh[1] = 6.0 * (mob * w1 + dm_l * d3)
    dq_dh[2] = 6.0 * (mob * w2 + dm_r * d3)
    dq_dh[3] = 6.0 * mob * w3
    dhf_dh[0] = 0.0
    dhf_dh[1] = 1.0 - th
    dhf_dh[2] = th
    dhf_dh[3] = 0.0
    out[0] = 6.0 * mob * d3
    out[1] = hf
    out[2] = 6.0 * (mob * dd3_ds + (dm_l * dhe[j + 1] + dm_r * dhe[j + 2]) * d3)
    out[3] = dhf_ds
    out[4] = mob
    out[5] = dm_l
    out[6] = dm_r


@nb.njit(cache=True)
def _face_q(j, ze, he, xfj, mob0, out):
    """``_face`` without derivatives (the right-hand side): out = (q, hf, mobility)."""
    z0, z1, z2, z3 = ze[j], ze[j + 1], ze[j + 2], ze[j + 3]
    h0, h1, h2, h3 = he[j], he[j + 1], he[j + 2], he[j + 3]
    d01, d02, d03, d12, d13, d23 = z0 - z1, z0 - z2, z0 - z3, z1 - z2, z1 - z3, z2 - z3
    d3 = h0 / (d01 * d02 * d03) - h1 / (d01 * d12 * d13) + h2 / (d02 * d12 * d23) - h3 / (d03 * d13 * d23)
    th = (xfj - z1) / (z2 - z1)
    if h1 > 0.0 and h2 > 0.0:
        mob = 2.0 * h1 * h1 * h2 * h2 / (h1 + h2) + mob0
    else:
        mob = mob0
    out[0] = 6.0 * mob * d3
    out[1] = (1.0 - th) * h1 + th * h2
    out[2] = mob


@nb.njit(cache=True)
def _pos(indptr, indices, r, c):
    lo, hi = indptr[c], indptr[c + 1] - 1
    while lo <= hi:
        mid = (lo + hi) // 2
        v = indices[mid]
        if v == r:
            return mid
        if v < r:
            lo = mid + 1
        else:
            hi = mid - 1
    return -1


N_WORK = 24


@nb.njit(cache=True)
def front_kernel(y, moving, s_fixed, s_lo, s_hi, alpha, beta, X, h_res, closed, mob0, jc, hstar, tau, delta,
                 wk, iwk, out, want_jac, indptr, indices, data):
    """Right-hand side of the ALE thin-film system (module docstring) into ``out``; with ``want_jac`` also
    its Jacobian into the CSC ``data`` (pattern ``indptr``/``indices``). State: contents c (and s if moving).
    ``wk`` (N_WORK, n + 4) and ``iwk`` (1, n + 4) are scratch."""
    n = alpha.size - 1
    c = y[:n]
    s = y[n] if moving else s_fixed
    clamped = False
    if moving and (s < s_lo or s > s_hi):   # a trial state beyond the events: keep the geometry valid
        s = min(max(s, s_lo), s_hi)
        clamped = True
    xf, dw, z, dz, h, dh = wk[0], wk[1], wk[2], wk[3], wk[4], wk[5]
    ze, dze, he, dhe, she = wk[6], wk[7], wk[8], wk[9], wk[10]
    q, hf, dq_ds, dhf_ds, F = wk[11], wk[12], wk[13], wk[14], wk[15]
    mob, dml, dmr, hadv, fsd = wk[16], wk[17], wk[18], wk[19], wk[20]
    fa_l, fa_r, fa_s = wk[21], wk[22], wk[23]
    re = iwk[0]
    _geometry(c, s, alpha, beta, X, h_res, closed, xf, dw, z, dz, h, dh, ze, dze, he, dhe, re, she)
    if clamped:
        for i in range(n + 4):
            dze[i] = 0.0
            dhe[i] = 0.0
    m_d = n + 1 if want_jac else 1
    dq_dc = np.empty((m_d, 4))   # by the real cells re[j + a] (chain dH/dc = she / width)
    dhf_dc = np.empty((m_d, 4))
    tmp_q = np.empty(4)
    tmp_f = np.empty(4)
    o7 = np.empty(7)
    last = n if not closed else n - 1
    for j in range(n + 1):
        q[j] = 0.0
        hf[j] = 0.0
        dq_ds[j] = 0.0
        dhf_ds[j] = 0.0
        F[j] = 0.0
    for j in range(1, last + 1):
        if not want_jac:
            _face_q(j, ze, he, xf[j], mob0, o7)
            q[j], hf[j], mob[j] = o7[0], o7[1], o7[2]
            continue
        _face(j, ze, dze, he, dhe, xf[j], beta[j], mob0, tmp_q, tmp_f, o7)
        q[j], hf[j], dq_ds[j], dhf_ds[j] = o7[0], o7[1], o7[2], o7[3]
        mob[j], dml[j], dmr[j] = o7[4], o7[5], o7[6]
        for a in range(4):
            r = re[j + a]
            inv_w = she[j + a] / (xf[r + 1] - xf[r])
            dq_dc[j, a] = tmp_q[a] * inv_w
            dhf_dc[j, a] = tmp_f[a] * inv_w
    # front speed
    sdot = 0.0
    ds_dc = np.zeros(5)   # by cells jc-2 .. jc+2
    ds_ds = 0.0
    if moving:
        num = (q[jc + 1] - q[jc]) - (c[jc] - (xf[jc + 1] - xf[jc]) * hstar) / tau
        den = hf[jc + 1] - hf[jc]
        root = math.sqrt(den * den + delta * delta)
        den_r = 0.5 * (den + root) if den >= 0.0 else 0.5 * delta * delta / (root - den)  # no cancellation
        sdot = num / den_r
    if moving and want_jac:
        dr = 0.5 * (1.0 + den / root)
        # d num, d den by cells (stencils of faces jc and jc+1 span cells jc-2 .. jc+2)
        dnum = np.zeros(5)
        dden = np.zeros(5)
        for a in range(4):
            k1 = re[jc + 1 + a] - (jc - 2)
            k0 = re[jc + a] - (jc - 2)
            dnum[k1] += dq_dc[jc + 1, a]
            dnum[k0] -= dq_dc[jc, a]
            dden[k1] += dhf_dc[jc + 1, a]
            dden[k0] -= dhf_dc[jc, a]
        dnum[2] -= 1.0 / tau
        for k in range(5):
            ds_dc[k] = (dnum[k] - sdot * dr * dden[k]) / den_r
        dnum_s = (dq_ds[jc + 1] - dq_ds[jc]) + (beta[jc + 1] - beta[jc]) * hstar / tau
        dden_s = dhf_ds[jc + 1] - dhf_ds[jc]
        ds_ds = 0.0 if clamped else (dnum_s - sdot * dr * dden_s) / den_r
    # fluxes through the moving faces: the content carried is the face value, blended towards the upwind
    # cell's by the cell Peclet number Pe = |v| dz^3 / mobility (psi = Pe^2/(1+Pe^2)): central (second order)
    # where capillarity dominates, upwind in the precursor ahead of the front, where nothing damps wiggles
    # (while the front is fast, Pe ~ 1 at the followed cell and the law holds it near H* rather than at it)
    for j in range(1, last + 1):
        v = beta[j] * sdot
        hadv[j] = 0.0
        fsd[j] = 0.0
        fa_l[j] = 0.0
        fa_r[j] = 0.0
        fa_s[j] = 0.0
        if beta[j] == 0.0:
            F[j] = q[j]
            continue
        kl, kr = j + 1, j + 2
        up_l = 1.0 if v < 0.0 else 0.0
        hu = up_l * he[kl] + (1.0 - up_l) * he[kr]
        hc = hf[j]
        dzz = ze[kr] - ze[kl]
        dz3 = dzz * dzz * dzz
        if mob[j] > 0.0:
            pe = abs(v) * dz3 / mob[j]
            psi = pe * pe / (1.0 + pe * pe)
            dpsi = 2.0 * pe / ((1.0 + pe * pe) * (1.0 + pe * pe))
            dpe_l = -pe * dml[j] / mob[j]
            dpe_r = -pe * dmr[j] / mob[j]
            dpe_s = pe * (3.0 * (dze[kr] - dze[kl]) / dzz - (dml[j] * dhe[kl] + dmr[j] * dhe[kr]) / mob[j])
            dpe_v = (1.0 if v > 0.0 else -1.0) * dz3 / mob[j]
        else:
            psi, dpsi, dpe_l, dpe_r, dpe_s, dpe_v = 1.0, 0.0, 0.0, 0.0, 0.0, 0.0
        ha = hc + psi * (hu - hc)
        hadv[j] = ha
        F[j] = q[j] - v * ha
        if not want_jac:
            continue
        # derivatives of ha: by H_left, H_right (fixed sdot), by s (fixed c and sdot), by v
        th = (xf[j] - ze[kl]) / dzz
        dha_l = (1.0 - psi) * (1.0 - th) + psi * up_l + (hu - hc) * dpsi * dpe_l
        dha_r = (1.0 - psi) * th + psi * (1.0 - up_l) + (hu - hc) * dpsi * dpe_r
        dhu_s = up_l * dhe[kl] + (1.0 - up_l) * dhe[kr]
        dha_s = (1.0 - psi) * dhf_ds[j] + psi * dhu_s + (hu - hc) * dpsi * dpe_s
        dha_v = (hu - hc) * dpsi * dpe_v
        rl, rr = re[kl], re[kr]
        fa_l[j] = -v * dha_l * she[kl] / (xf[rl + 1] - xf[rl])
        fa_r[j] = -v * dha_r * she[kr] / (xf[rr + 1] - xf[rr])
        fa_s[j] = -v * dha_s
        fsd[j] = -beta[j] * (ha + v * dha_v)
    for i in range(n):
        out[i] = -(F[i + 1] - F[i])
    if moving:
        out[n] = sdot
    if not want_jac:
        return
    for k in range(data.size):
        data[k] = 0.0
    for j in range(1, last + 1):
        for side in range(2):   # face j enters row j-1 with -1 and row j with +1
            r = j - 1 + side
            if r < 0 or r >= n:
                continue
            sg = 2.0 * side - 1.0
            for a in range(4):
                vq = dq_dc[j, a]
                if a == 1:
                    vq += fa_l[j]
                elif a == 2:
                    vq += fa_r[j]
                if vq != 0.0:
                    data[_pos(indptr, indices, r, re[j + a])] += sg * vq
            if moving:
                data[_pos(indptr, indices, r, n)] += sg * (dq_ds[j] + fa_s[j] + fsd[j] * ds_ds)
                if fsd[j] != 0.0:
                    for k in range(5):
                        data[_pos(indptr, indices, r, jc - 2 + k)] += sg * fsd[j] * ds_dc[k]
    if moving:
        for k in range(5):
            data[_pos(indptr, indices, n, jc - 2 + k)] += ds_dc[k]
        data[_pos(indptr, indices, n, n)] += ds_ds


# --------------------------------------------------------------------------------------------------
# the levelling problem on a front mesh
# --------------------------------------------------------------------------------------------------

class FrontLevelling:
    """The scaled thin-film equation on a :class:`FrontMesh` (module docstring).

    Parameters
    ----------
    mesh : the mesh; bc : ``"reservoir"`` (``H = h_res`` at ``x = X``) or ``"closed"``.
    mobility_film : ``b`` of an optional mobility floor ``Hf^3 + b^3`` (0: none; kept only to compare
        with the regularised formulation).
    hstar : the level the mesh follows (``kappa eps``); tau : its relaxation time (scaled);
    delta : regularisation of the front law's denominator.
    """

    def __init__(self, mesh: FrontMesh, bc: str = "reservoir", h_res: float = 1.0, mobility_film: float = 0.0,
                 hstar: float = 1e-3, tau: float = 1e-3, delta: float | None = None):
        check_choice("bc", bc, ("reservoir", "closed"))
        if not (hstar > 0 and tau > 0):
            raise ValueError(f"hstar = {hstar!r}, tau = {tau!r} [scaled] must be > 0")
        self.mesh = mesh
        self.bc = bc
        self.closed = bc == "closed"
        self.h_res = float(h_res)
        self.mobility_film = float(mobility_film)
        self.mob0 = self.mobility_film ** 3
        self.hstar, self.tau = float(hstar), float(tau)
        self.delta = 0.05 * self.hstar if delta is None else float(delta)
        n, jc = mesh.n, mesh.jc
        self.wk = np.zeros((N_WORK, n + 4))
        self.iwk = np.zeros((1, n + 4), dtype=np.int64)
        cached = getattr(mesh, "_patterns", None)   # the pattern depends on the mesh only
        if cached is None:
            cached = {False: self._pattern(n, jc, False), True: self._pattern(n, jc, True)}
            mesh._patterns = cached
        self.patterns = cached

    @staticmethod
    def _pattern(n, jc, moving):
        rows, cols = [], []
        for d in range(-2, 3):
            r = np.arange(n)
            c = r + d
            keep = (c >= 0) & (c < n)
            rows.append(r[keep])
            cols.append(c[keep])
        if moving:
            rows.append(np.arange(n + 1))
            cols.append(np.full(n + 1, n))
            for k in range(jc - 2, jc + 3):
                rows.append(np.arange(n + 1))
                cols.append(np.full(n + 1, k))
        m = n + 1 if moving else n
        rows, cols = np.concatenate(rows), np.concatenate(cols)
        pat = sp.csc_matrix((np.ones(rows.size), (rows, cols)), shape=(m, m))
        pat.sum_duplicates()
        pat.sort_indices()
        pat.data[:] = 1.0
        return pat

    # state helpers --------------------------------------------------------------------------------
    def state(self, h: np.ndarray, s: float, moving: bool = True) -> np.ndarray:
        c = np.asarray(h, float) * self.mesh.widths(s)
        return np.append(c, s) if moving else c

    def profile(self, y: np.ndarray, s: float | None = None) -> tuple[np.ndarray, np.ndarray]:
        """(centres, H) of a state (``s`` given for a frozen state)."""
        n = self.mesh.n
        s = float(y[n]) if s is None else s
        return self.mesh.centres(s), y[:n] / self.mesh.widths(s)

    def _call(self, y, moving, s_fixed, out, want_jac, data):
        pat = self.patterns[moving]
        m = self.mesh
        front_kernel(y, moving, s_fixed, m.s_lo, m.s_hi, m.alpha, m.beta, m.length, self.h_res, self.closed,
                     self.mob0, m.jc, self.hstar, self.tau, self.delta, self.wk, self.iwk, out, want_jac,
                     pat.indptr, pat.indices,
                     data if want_jac else np.empty(0))

    def rhs(self, y, moving=True, s_fixed=0.0):
        out = np.empty(y.size)
        self._call(np.ascontiguousarray(y, float), moving, s_fixed, out, False, None)
        return out

    def jac_matrix(self, y, moving=True, s_fixed=0.0) -> sp.csc_matrix:
        pat = self.patterns[moving]
        data = np.zeros(pat.nnz)
        self._call(np.ascontiguousarray(y, float), moving, s_fixed, np.empty(y.size), True, data)
        return sp.csc_matrix((data, pat.indices, pat.indptr), shape=pat.shape)

    def problem(self, y0: np.ndarray, moving: bool = True, s_fixed: float = 0.0, name: str = "front_levelling"):
        """The facade's :class:`Problem`; while moving, terminal events at ``s = s_stop`` and ``s = s_max``."""
        m = self.mesh
        pat = self.patterns[moving]
        args = (moving, float(s_fixed), m.s_lo, m.s_hi, m.alpha, m.beta, m.length, self.h_res, self.closed, self.mob0, m.jc,
                self.hstar, self.tau, self.delta, self.wk, self.iwk)
        indptr, indices = pat.indptr, pat.indices
        dummy = np.empty(0)
        n = m.n
        s_stop, s_max = m.s_stop, m.s_max

        def rhs(t, y, out):
            front_kernel(y, *args, out, False, indptr, indices, dummy)

        scratch = np.empty(pat.shape[0])

        def jac(t, y, data):
            front_kernel(y, *args, scratch, True, indptr, indices, data)

        kw = {}
        if moving:
            def events(t, y, g):
                g[0] = y[n] - s_stop
                g[1] = y[n] - s_max

            kw = dict(events=events, n_events=2, event_terminal=[True, True], event_direction=[-1, 1])
        return Problem(y0=np.array(y0, dtype=float), rhs=rhs, jac_pattern=pat, jac_rhs=jac, name=name, **kw)


    def seed_front(self, c: np.ndarray, s: float) -> np.ndarray:
        """Contents with the cell just behind the front at the followed level ``H*`` exactly (the difference
        taken from / given to the next cell: volume kept), so that the mesh starts on the foot of the front."""
        c = np.array(c, dtype=float)
        jc = self.mesh.jc
        w = self.mesh.widths(s)
        d = c[jc] - self.hstar * w[jc]
        if c[jc + 1] + d > 0:
            c[jc + 1] += d
            c[jc] -= d
        return c

    def with_mesh(self, mesh) -> "FrontLevelling":
        """The same equation on another mesh."""
        return FrontLevelling(mesh, self.bc, self.h_res, self.mobility_film, self.hstar, self.tau, self.delta)

    def advance(self, c: np.ndarray, s: float, t_end: float, *, moving: bool = True, method: str = "cvode",
                rtol: float = 1e-6, atol: float = 1e-10, linear_solver: str = "auto", stats: dict | None = None,
                max_order: int | None = 2):
        """Integrate ``[0, t_end]`` from contents ``c`` with the front at ``s``. The mesh follows the front; when
        ``s`` reaches ``s_stop`` a mesh redesigned for the new position takes over (same cluster: the front is
        copied exactly, the rest remapped conservatively), on the last one (or at ``s_max``) the mesh stays
        where it is. Returns ``(levelling, c, s, moving)`` at ``t_end`` (``levelling`` on the final mesh);
        ``stats`` (if given) accumulates steps, rhs and Jacobian calls, remeshes and freezes.

        ``max_order`` caps the BDF order of CVODE (default 2, A-stable): the moving faces add an advective part
        whose eigenvalues leave the real axis, where BDF3-5 are not stable; CVODE then keeps cutting its
        step (measured: 2.2x more steps with order 5 on the reference sequence)."""
        lev = self
        m = lev.mesh
        moving = bool(moving and m.s_stop < s < m.s_max)
        t = 0.0
        c = np.array(c, dtype=float)
        while True:
            m = lev.mesh
            y0 = np.append(c, s) if moving else c
            tol = atol * m.widths(s)   # atol is a film tolerance (scaled): contents carry the cell width
            if moving:
                tol = np.append(tol, 0.1 * m.dx_min)
            opts = {"max_order": int(max_order)} if (max_order and method in ("cvode", "ida")) else None
            res = solve(lev.problem(y0, moving, s), np.array([0.0, t_end - t]), method=method, rtol=rtol,
                        atol=tol, linear_solver=linear_solver, options=opts)
            if stats is not None:
                stats["n_steps"] = stats.get("n_steps", 0) + res.stats.n_steps
                stats["n_rhs"] = stats.get("n_rhs", 0) + res.stats.n_rhs
                stats["n_jac"] = stats.get("n_jac", 0) + res.stats.n_jac
            if not res.success:
                raise RuntimeError(f"levelling failed ({method}, {'moving' if moving else 'frozen'} mesh, "
                                   f"from s = {s:.4g}): {res.message}")
            if moving and res.t_events.size:
                yv = res.y_events[-1]
                c, s = np.array(yv[:m.n]), float(yv[m.n])
                t += float(res.t_events[-1])
                if int(res.i_events[-1]) == 0 and not m.final:
                    new = m.redesign(s)
                    c = remap(m.faces(s), c, new.faces(s))
                    lev = lev.with_mesh(new)
                    key = "n_remesh"
                else:
                    moving = False
                    key = "n_freeze"
                if stats is not None:
                    stats[key] = stats.get(key, 0) + 1
                if t >= t_end * (1.0 - 1e-12):
                    return lev, c, s, moving
                continue
            yv = res.y[-1]
            if moving:
                return lev, np.array(yv[:m.n]), float(yv[m.n]), moving
            return lev, np.array(yv), s, moving


# --------------------------------------------------------------------------------------------------
# conservative remap and cell integrals
# --------------------------------------------------------------------------------------------------

def remap(x_old: np.ndarray, c_old: np.ndarray, x_new: np.ndarray) -> np.ndarray:
    """Contents on the cells ``x_new`` of the piecewise-linear (minmod-limited) reconstruction of the cells
    ``x_old`` with contents ``c_old``: conservative (the total is kept to round-off when both meshes span
    the same interval) and exact for linear profiles."""
    w = np.diff(x_old)
    h = c_old / w
    zc = 0.5 * (x_old[:-1] + x_old[1:])
    slope = np.zeros_like(h)
    if h.size > 2:
        dl = (h[1:-1] - h[:-2]) / (zc[1:-1] - zc[:-2])
        dr = (h[2:] - h[1:-1]) / (zc[2:] - zc[1:-1])
        slope[1:-1] = np.where(dl * dr > 0, np.sign(dl) * np.minimum(np.abs(dl), np.abs(dr)), 0.0)
        slope[0], slope[-1] = dl[0], dr[-1]   # one-sided at the ends (exact for linear profiles)
    # cumulative integral of the reconstruction at arbitrary points
    cum = np.concatenate([[0.0], np.cumsum(c_old)])

    def integral(x):
        k = np.clip(np.searchsorted(x_old, x, side="right") - 1, 0, h.size - 1)
        a = x_old[k]
        d = x - a
        # int_a^x (h + slope (t - zc)) dt
        return cum[k] + h[k] * d + slope[k] * 0.5 * ((x - zc[k]) ** 2 - (a - zc[k]) ** 2)

    x_new = np.asarray(x_new, float)
    if x_new[0] != x_old[0] or x_new[-1] != x_old[-1]:
        raise ValueError("remap: both meshes must span the same interval")
    I = integral(x_new)
    I[0], I[-1] = 0.0, cum[-1]
    return np.diff(I)


def sine_hump_share(x_faces: np.ndarray, start: float, width: float) -> np.ndarray:
    """Share of each cell in the hump ``sin(pi (x - start)/width)`` on ``[start, start + width]`` (sums to 1)."""
    a = np.clip(x_faces, start, start + width)
    F = -np.cos(np.pi * (a - start) / width)
    return np.diff(F) / 2.0
