"""Random rough surfaces with a prescribed autocorrelation and height statistics.

Two generators, one result type (:class:`RoughSurface`):

* ``method="linear"`` -- Patir's linear transformation (N. Patir, "A numerical procedure for random
  generation of rough surfaces", Wear 47 (1978) 263-277; used by Lee & Rhim, eqs. (1)-(6)):

      Z_ij = sum_{k=0}^{n-1} sum_{l=0}^{m-1} a_kl eta_{i+k, j+l}                          (3)

  with eta i.i.d., zero mean, unit variance, and the coefficients a_kl solved from the discrete
  autocorrelation R_pq = sum_k sum_l a_kl a_{k+p, l+q}.  For a separable ACF the 2-D system
  splits into two 1-D systems (a_kl = b_k c_l) solved by Newton's method; for the paper's
  triangular ACF with lambda = n dx the solution is the moving average a_kl = R0 / sqrt(n m)
  (eq. (2)).  A non-separable ACF (the exponential one) is solved by Gauss-Newton least squares
  over all independent lags of the truncated support.  The convolution itself is done by FFT
  (scipy.signal), no Python loop over the grid.

* ``method="fft"`` -- spectral synthesis, the FFT equivalent for large surfaces (Hu & Tonder,
  Int. J. Mach. Tools Manuf. 32 (1992) 83-90): the periodic sampled ACF is transformed to the
  power spectrum S, and Z = IFFT( sqrt(S) FFT(eta) ), i.e. a circular convolution of eta with the
  zero-phase kernel a = IFFT(sqrt(S)), whose circular autocorrelation is exactly the target ACF.

Non-Gaussian heights (both methods) follow Patir (1978): because Z is a linear filter of i.i.d.
eta, its skewness and excess kurtosis are those of eta scaled by the kernel,

      Sk_Z = Sk_eta * sum a^3 / (sum a^2)^(3/2),    Ku_Z - 3 = (Ku_eta - 3) * sum a^4 / (sum a^2)^2,

so eta is drawn with the inflated moments (Sk_eta, Ku_eta):

* ``heights="gamma"``: standardised gamma variates (shape k = 4 / Sk_eta^2), as in Lee & Rhim
  (drawn by numpy's Marsaglia-Tsang squeeze/rejection method).  The kurtosis is then implied:
  Ku_Z = 3 + 1.5 Sk_eta^2 * sum a^4/(sum a^2)^2  (= 3 + 1.5 Sk_Z^2 for the moving average).
* ``heights="johnson"``: Johnson translation system (S_U, S_B or S_L chosen from (Sk, Ku); Johnson,
  Biometrika 36 (1949) 149-176; used by Patir 1978) for any feasible skewness and kurtosis.
* ``heights="gaussian"``: standard normal eta.

ACF models (separation tau = (tau_x, tau_y), correlation lengths (lx, ly), R0 = Rq):

* ``"triangular"`` (Lee & Rhim eq. (1)):  R = R0^2 (1 - |tau_x|/lx)(1 - |tau_y|/ly) inside, 0 outside;
  lx is where the ACF reaches zero.
* ``"exponential"`` (Patir 1978; Patir & Cheng 1978):
  R = R0^2 exp(-ln(10) sqrt((tau_x/lx)^2 + (tau_y/ly)^2)); lx is where the ACF decays to 10 %
  (Patir writes 2.3 for ln 10 = 2.3026).

For both models the ratio of the lengths where the ACF falls to one half equals lx/ly, so the
Peklenik number gamma = lambda_0.5x / lambda_0.5y of Patir & Cheng equals lx/ly.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy import optimize
from transient.checks import check_int, check_positive, check_range

__all__ = [
    "ACF_MODELS",
    "HEIGHT_MODELS",
    "RoughSurface",
    "acf_model",
    "patir_coefficients",
    "johnson_standard_sampler",
    "measured_acf",
]

ACF_MODELS = ("triangular", "exponential")
HEIGHT_MODELS = ("auto", "gaussian", "gamma", "johnson")
LN10 = math.log(10.0)


# --------------------------------------------------------------------------------------------
# validation helper (shared by the roughness / asperity / flow-factor modules)
# --------------------------------------------------------------------------------------------



# --------------------------------------------------------------------------------------------
# ACF models
# --------------------------------------------------------------------------------------------
def acf_model(kind: str, tau_x, tau_y, lx: float, ly: float):
    """Normalised model ACF R(tau_x, tau_y) / R0^2 (see module docstring for the formulas)."""
    tx = np.abs(np.asarray(tau_x, dtype=float)) / lx
    ty = np.abs(np.asarray(tau_y, dtype=float)) / ly
    if kind == "triangular":
        return np.clip(1.0 - tx, 0.0, None) * np.clip(1.0 - ty, 0.0, None)
    if kind == "exponential":
        return np.exp(-LN10 * np.sqrt(tx * tx + ty * ty))
    raise ValueError(f"acf must be one of {ACF_MODELS}, got {kind!r}")


def _acf_half_level_factor(kind: str) -> float:
    """lambda* / lambda_0.5 for the model (triangular: 2; exponential: ln10/ln2)."""
    return 2.0 if kind == "triangular" else LN10 / math.log(2.0)


# --------------------------------------------------------------------------------------------
# Patir's coefficients a_kl
# --------------------------------------------------------------------------------------------
def _autocorr_1d(b: np.ndarray) -> np.ndarray:
    n = b.size
    return np.array([b[: n - p] @ b[p:] for p in range(n)])


def _solve_1d(r: np.ndarray, tol: float = 1e-13, maxiter: int = 100) -> np.ndarray:
    """Newton solution of sum_k b_k b_{k+p} = r_p, p = 0..n-1 (Patir 1978, 1-D form)."""
    n = r.size
    # a one-sided (decreasing) start: at a symmetric b the Jacobian is singular, because the
    # autocorrelation is invariant under reversal of b
    b = 1.0 - np.arange(n) / (n + 1.0)
    b *= math.sqrt(r[0] / np.sum(b * b))
    idx = np.arange(n)
    for _ in range(maxiter):
        F = _autocorr_1d(b) - r
        if np.max(np.abs(F)) < tol * r[0]:
            return b
        # J[p, j] = b_{j+p} + b_{j-p}
        bp = np.concatenate([np.zeros(n), b, np.zeros(n)])
        J = bp[n + idx[None, :] + idx[:, None]] + bp[n + idx[None, :] - idx[:, None]]
        b = b - np.linalg.solve(J, F)
    raise RuntimeError(f"Patir 1-D coefficient system did not converge (residual {np.max(np.abs(F)):.2e})")


def _autocorr_2d_lags(a: np.ndarray, P: np.ndarray, Q: np.ndarray) -> np.ndarray:
    """R_pq = sum_kl a_kl a_{k+p,l+q} for the lag lists P (>= 0), Q (any sign)."""
    from scipy import signal  # imported on use: 1 s of import time for every process otherwise

    full = signal.correlate(a, a, mode="full", method="direct")  # index (p + n-1, q + m-1)
    n, m = a.shape
    return full[P + n - 1, Q + m - 1]


def _solve_2d(R: np.ndarray, a0: np.ndarray, tol: float = 1e-10):
    """Least-squares solution of R_pq = sum a_kl a_{k+p,l+q} over p in [0, n), q in (-m, m)."""
    n, m = a0.shape
    P, Q = np.meshgrid(np.arange(n), np.arange(-m + 1, m), indexing="ij")
    keep = ~((P == 0) & (Q < 0))  # R_{0,-q} = R_{0,q}: keep independent lags only
    P, Q = P[keep], Q[keep]
    target = R[P, Q + m - 1]
    K, L = np.meshgrid(np.arange(n), np.arange(m), indexing="ij")
    K, L = K.ravel(), L.ravel()

    def fun(x):
        return _autocorr_2d_lags(x.reshape(n, m), P, Q) - target

    def jac(x):
        a = x.reshape(n, m)
        pad = np.zeros((3 * n, 3 * m))
        pad[n:2 * n, m:2 * m] = a
        # dR_pq / da_kl = a_{k+p, l+q} + a_{k-p, l-q}
        return (pad[n + K[None, :] + P[:, None], m + L[None, :] + Q[:, None]]
                + pad[n + K[None, :] - P[:, None], m + L[None, :] - Q[:, None]])

    sol = optimize.least_squares(fun, a0.ravel(), jac=jac, method="lm", xtol=tol, ftol=tol, gtol=tol)
    a = sol.x.reshape(n, m)
    return a, float(np.max(np.abs(sol.fun)))


def patir_coefficients(acf: str, spacing, correlation_lengths, cutoff: float = 0.01):
    """Coefficients a_kl (unit variance: sum a^2 = 1) of Patir's linear transformation.

    Returns ``(a, residual)``: ``a`` has shape (m, n) = (y lags, x lags) and ``residual`` is the
    largest absolute error of its discrete ACF against the target over the support (normalised).

    triangular: separable, exact (1-D Newton per axis); support lags |p| dx < lx.
    exponential: non-separable; target truncated where R < ``cutoff`` (default 1 %), solved by
    Levenberg-Marquardt least squares over all independent lags (initial guess: the zero-phase
    spectral kernel); the residual reports the truncation/fit error.
    """
    dx, dy = spacing
    lx, ly = correlation_lengths
    if acf == "triangular":
        nx = max(1, math.ceil(lx / dx - 1e-9))
        ny = max(1, math.ceil(ly / dy - 1e-9))
        bx = _solve_1d(np.clip(1.0 - np.arange(nx) * dx / lx, 0, None))
        by = _solve_1d(np.clip(1.0 - np.arange(ny) * dy / ly, 0, None))
        a = np.outer(by, bx)
        res = max(np.max(np.abs(_autocorr_1d(bx) - (1.0 - np.arange(nx) * dx / lx))),
                  np.max(np.abs(_autocorr_1d(by) - (1.0 - np.arange(ny) * dy / ly))))
        return a, float(res)
    if acf == "exponential":
        # support where R >= cutoff along each axis: tau/l < ln(1/cutoff)/ln10
        reach = math.log(1.0 / cutoff) / LN10
        nx = max(1, math.ceil(reach * lx / dx))
        ny = max(1, math.ceil(reach * ly / dy))
        if nx * ny > 2500:
            raise ValueError(f"linear transformation with exponential ACF needs {ny}x{nx} coefficients "
                             f"(> 2500); use method='fft' for correlation lengths this long")
        qy, qx = np.meshgrid(np.arange(-ny + 1, ny) * dy, np.arange(-nx + 1, nx) * dx, indexing="ij")
        Rfull = acf_model("exponential", qx, qy, lx, ly)  # shape (2ny-1, 2nx-1), index (p+ny-1, q+nx-1)
        Rfull[Rfull < cutoff] = 0.0
        R = Rfull[ny - 1:, :]  # p >= 0 (y lag), q any sign (x lag)
        # initial guess: centred zero-phase kernel of the truncated ACF, cut to (ny, nx)
        big = (4 * ny, 4 * nx)
        Rp = np.zeros(big)
        Rp[np.ix_(np.arange(-ny + 1, ny) % big[0], np.arange(-nx + 1, nx) % big[1])] = Rfull
        k = np.fft.fftshift(np.fft.ifft2(np.sqrt(np.clip(np.fft.fft2(Rp).real, 0, None))).real)
        cy, cx = big[0] // 2 - ny // 2, big[1] // 2 - nx // 2
        a0 = k[cy:cy + ny, cx:cx + nx].copy()
        a0 /= math.sqrt(np.sum(a0 ** 2))
        a, res = _solve_2d(R, a0)
        return a, res
    raise ValueError(f"acf must be one of {ACF_MODELS}, got {acf!r}")


def _fft_spectrum_sqrt(acf: str, shape, spacing, correlation_lengths) -> np.ndarray:
    """sqrt of the power spectrum of the periodically sampled, normalised ACF (zero-phase filter)."""
    ny, nx = shape
    dx, dy = spacing
    lx, ly = correlation_lengths
    jx = np.minimum(np.arange(nx), nx - np.arange(nx)) * dx
    jy = np.minimum(np.arange(ny), ny - np.arange(ny)) * dy
    R = acf_model(acf, jx[None, :], jy[:, None], lx, ly)
    S = np.fft.rfft2(R).real
    return np.sqrt(np.clip(S, 0.0, None))


# --------------------------------------------------------------------------------------------
# Johnson translation system
# --------------------------------------------------------------------------------------------
_GH_X, _GH_W = np.polynomial.hermite_e.hermegauss(160)
_GH_W = _GH_W / _GH_W.sum()


def _std_moments_from_raw(m1, m2, m3, m4):
    var = m2 - m1 ** 2
    mu3 = m3 - 3 * m1 * m2 + 2 * m1 ** 3
    mu4 = m4 - 4 * m1 * m3 + 6 * m1 ** 2 * m2 - 3 * m1 ** 4
    return m1, var, mu3 / var ** 1.5, mu4 / var ** 2


def _su_moments(mu, s):
    """Mean, variance, skewness, kurtosis of Y = sinh(mu + s Z), Z ~ N(0,1).

    Mean and variance exact (E exp(j(mu + sZ)) = exp(j mu + j^2 s^2/2)); third and fourth central
    moments by 160-node Gauss-Hermite quadrature of (Y - mean)^k (no raw-moment cancellation).
    """
    m = math.exp(0.5 * s * s) * math.sinh(mu)
    var = 0.5 * (math.exp(2 * s * s) * math.cosh(2 * mu) - 1.0) - m * m
    d = np.sinh(mu + s * _GH_X) - m
    d2 = d * d
    v_q = float(_GH_W @ d2)
    return m, var, float(_GH_W @ (d2 * d)) / v_q ** 1.5, float(_GH_W @ (d2 * d2)) / v_q ** 2


def _sb_moments(mu, s):
    """Mean, variance, skewness, kurtosis of Y = 1/(1+exp(-(mu + s Z))) (Gauss-Hermite, 160 nodes)."""
    y = 0.5 * (1.0 + np.tanh(0.5 * (mu + s * _GH_X)))
    m = [float(_GH_W @ y ** k) for k in (1, 2, 3, 4)]
    return _std_moments_from_raw(*m)


def _lognormal_skew_kurt(s):
    w = math.exp(s * s)
    return (w + 2) * math.sqrt(w - 1), w ** 4 + 2 * w ** 3 + 3 * w ** 2 - 3


def johnson_standard_sampler(skewness: float, kurtosis: float):
    """Return (family, f) with f(Z) a standardised Johnson variate of the given Sk and Ku.

    Johnson (1949): X = f((Z - gamma)/delta), f = sinh (S_U), logistic (S_B), exp (S_L), Z ~ N(0,1).
    The family follows from the lognormal line Ku_L(Sk): S_U above it, S_B below it.  The two
    shape parameters are found by nested 1-D root finding on exact (S_U, S_L) or 160-node
    Gauss-Hermite (S_B) moments.  Requires Ku > Sk^2 + 1 (Pearson's bound).
    """
    sk, ku = float(skewness), float(kurtosis)
    if not ku > sk * sk + 1.0:
        raise ValueError(f"infeasible height statistics: kurtosis {ku:g} must exceed skewness^2 + 1 = "
                         f"{sk * sk + 1:g}")
    sign = -1.0 if sk < 0 else 1.0
    sk = abs(sk)

    def standardise(fun, mean, var):
        sd = math.sqrt(var)
        return lambda z: sign * (fun(z) - mean) / sd

    if sk < 1e-12 and abs(ku - 3.0) < 1e-12:
        return "normal", lambda z: sign * np.asarray(z, dtype=float)
    # lognormal line at this skewness
    if sk > 0:
        s_L = optimize.brentq(lambda s: _lognormal_skew_kurt(s)[0] - sk, 1e-8, 5.0, xtol=1e-14)
        ku_L = _lognormal_skew_kurt(s_L)[1]
    else:
        s_L, ku_L = 0.0, 3.0
    if abs(ku - ku_L) < 1e-9:
        w = math.exp(s_L ** 2)
        mean, var = math.sqrt(w), w * (w - 1)
        return "SL", standardise(lambda z: np.exp(s_L * np.asarray(z)), mean, var)

    if ku > ku_L:  # S_U: Y = sinh(mu + s Z), mu >= 0 gives positive skew; needs s > s_L
        def mu_for(s):
            if sk == 0:
                return 0.0
            f = lambda mu: _su_moments(mu, s)[2] - sk
            hi = 1.0
            while f(hi) < 0:
                hi *= 2.0
                if hi > 40:
                    return None  # skewness only reached as mu -> inf: on the lognormal line
            return optimize.brentq(f, 0.0, hi, xtol=1e-13)

        def g(s):
            mu = mu_for(s)
            return -1.0 if mu is None else _su_moments(mu, s)[3] - ku
        lo = s_L * (1.0 + 1e-4) + 1e-4
        hi = s_L + 0.5
        while g(hi) < 0:
            hi *= 1.5
            if hi > 20:
                raise ValueError(f"Johnson S_U fit failed for Sk={sk}, Ku={ku}")
        s = optimize.brentq(g, lo, hi, xtol=1e-13)
        mu = mu_for(s)
        m, v, _, _ = _su_moments(mu, s)
        return "SU", standardise(lambda z: np.sinh(mu + s * np.asarray(z)), m, v)

    # S_B: Y = logistic(mu + s Z), mu <= 0 gives positive skew; kurtosis falls from ku_L (s -> s_L)
    def mu_for_b(s):
        if sk == 0:
            return 0.0
        f = lambda mu: _sb_moments(mu, s)[2] - sk
        lo = -1.0
        while f(lo) < 0:
            lo *= 2.0
            if lo < -200:
                raise ValueError("Johnson S_B fit failed (skewness unreachable)")
        return optimize.brentq(f, lo, 0.0, xtol=1e-13)

    def gb(s):
        return _sb_moments(mu_for_b(s), s)[3] - ku
    s_lo = s_L * (1.0 + 1e-4) + 1e-4
    if gb(s_lo) < 0:  # target lies (numerically) on the lognormal line
        w = math.exp(s_L ** 2)
        return "SL", standardise(lambda z: np.exp(s_L * np.asarray(z)), math.sqrt(w), w * (w - 1))
    s_hi = 2.0 * s_lo + 0.5
    while gb(s_hi) > 0:
        s_hi *= 1.5
        if s_hi > 12:
            raise ValueError(f"Johnson S_B fit failed for Sk={sk}, Ku={ku} (too close to the bound "
                             f"Ku = Sk^2 + 1)")
    s = optimize.brentq(gb, s_lo, s_hi, xtol=1e-12)
    mu = mu_for_b(s)
    m, v, _, _ = _sb_moments(mu, s)
    return "SB", standardise(lambda z: 0.5 * (1.0 + np.tanh(0.5 * (mu + s * np.asarray(z)))), m, v)


# --------------------------------------------------------------------------------------------
# measured statistics
# --------------------------------------------------------------------------------------------
def _pair(name, value, unit, low, high, integer=False):
    """A scalar (used twice) or a pair of numbers in [low, high] (whole numbers if ``integer``)."""
    if isinstance(value, (str, bytes)) or value is None:
        raise ValueError(f"{name} = {value!r} [{unit}]; allowed: a number or a pair of numbers in [{low:g}, {high:g}]")
    pair = (value, value) if np.isscalar(value) else tuple(value)
    if len(pair) != 2:
        raise ValueError(f"{name} = {value!r} [{unit}]; allowed: a number or a pair of numbers in [{low:g}, {high:g}]")
    check = check_int if integer else check_range
    return tuple(check(f"{name}[{i}]", v, unit, low, high) for i, v in enumerate(pair))


def measured_acf(z: np.ndarray, max_lag=None, periodic: bool = False) -> np.ndarray:
    """Normalised ACF of the mean-removed heights, R(p, q) / R(0, 0), for lags |p|, |q| <= max_lag.

    Non-periodic estimate (zero-padded FFT) divided by the overlap count (unbiased), or circular if
    ``periodic``.  Returns an array of shape (2 Ly + 1, 2 Lx + 1) centred on lag (0, 0).
    """
    z = np.asarray(z, dtype=float)
    z = z - z.mean()
    ny, nx = z.shape
    if max_lag is None:
        Ly, Lx = ny // 4, nx // 4
    else:
        Ly, Lx = (max_lag, max_lag) if np.isscalar(max_lag) else max_lag
        Ly, Lx = min(int(Ly), ny - 1), min(int(Lx), nx - 1)
    if periodic:
        F = np.fft.rfft2(z)
        c = np.fft.irfft2(F * np.conj(F), s=z.shape) / z.size
    else:
        sy, sx = 2 * ny, 2 * nx
        F = np.fft.rfft2(z, s=(sy, sx))
        c = np.fft.irfft2(F * np.conj(F), s=(sy, sx))
        cnt_y = ny - np.minimum(np.arange(sy), sy - np.arange(sy))
        cnt_x = nx - np.minimum(np.arange(sx), sx - np.arange(sx))
        c = c / np.maximum(np.outer(cnt_y, cnt_x), 1)
    c = np.roll(np.roll(c, Ly, axis=0), Lx, axis=1)[: 2 * Ly + 1, : 2 * Lx + 1]
    return c / c[Ly, Lx]


def _first_crossing(r: np.ndarray, level: float, log: bool = False) -> float:
    """First lag index at which the 1-D ACF r[0..] drops to ``level``, interpolated linearly in r
    (exact for the triangular ACF) or in log r (``log``, exact for the exponential ACF)."""
    below = np.nonzero(r <= level)[0]
    if below.size == 0:
        return math.nan
    i = int(below[0])
    if i == 0:
        return 0.0
    if log and r[i] > 0:
        return (i - 1) + math.log(r[i - 1] / level) / math.log(r[i - 1] / r[i])
    return (i - 1) + (r[i - 1] - level) / (r[i - 1] - r[i])


# --------------------------------------------------------------------------------------------
# the surface
# --------------------------------------------------------------------------------------------
@dataclass
class RoughSurface:
    """A sampled rough surface: heights [m] on a (ny, nx) grid of spacing (dx, dy) [m].

    Statistics (about the mean plane): ``rq`` [m], ``skewness``, ``kurtosis`` (3 for Gaussian),
    ``correlation_lengths`` (lx, ly) [m], ``gamma`` = lx/ly, ``acf()``.  ``meta`` records how the
    surface was generated (target values, kernel moments, eta family ...).
    """

    heights: np.ndarray
    spacing: tuple
    acf_kind: str | None = None
    periodic: bool = False
    meta: dict = field(default_factory=dict)

    def __post_init__(self):
        self.heights = np.asarray(self.heights, dtype=float)
        if self.heights.ndim != 2 or min(self.heights.shape) < 2:
            raise ValueError(f"heights must be a 2-D array of at least 2x2 samples, got shape "
                             f"{self.heights.shape}")
        sp = (self.spacing, self.spacing) if np.isscalar(self.spacing) else tuple(self.spacing)
        if len(sp) != 2:
            raise ValueError(f"spacing must be a number or (dx, dy) [m], got {self.spacing!r}")
        self.spacing = (check_positive("spacing dx", sp[0], "m"), check_positive("spacing dy", sp[1], "m"))

    def __repr__(self):
        ny, nx = self.heights.shape
        return (f"RoughSurface(shape=({ny}, {nx}), spacing=({self.spacing[0]:g}, {self.spacing[1]:g}) m, "
                f"rq={self.rq:.4g} m, acf_kind={self.acf_kind!r}, periodic={self.periodic})")

    # ---- generation ---------------------------------------------------------------------
    @classmethod
    def generate(cls, shape, spacing, rq, skewness: float = 0.0, kurtosis: float | None = None,
                 correlation_lengths=None, acf: str = "triangular", seed=None, method: str = "fft",
                 heights: str = "auto", cutoff: float = 0.01) -> "RoughSurface":
        """Generate a random surface.

        Parameters (SI): shape (ny, nx); spacing dx or (dx, dy) [m]; rq [m] > 0; skewness [-];
        kurtosis [-] (default 3; implied and not allowed for ``heights="gamma"``);
        correlation_lengths (lx, ly) or l [m] (> 0; need shape >= 2 l/d (fft) so the periodic ACF does
        not overlap itself; default ``None``: isotropic, one eighth of the shorter side of the sampled
        area, which fits both ACF models); acf in ``ACF_MODELS``; seed for numpy's default_rng; method "fft"
        (periodic, any size) or "linear" (Patir, non-periodic); heights in ``HEIGHT_MODELS``
        ("auto": Gaussian when Sk = 0 and Ku = 3, Johnson otherwise); cutoff: ACF truncation level
        of the linear method with the exponential ACF.
        """
        if acf not in ACF_MODELS:
            raise ValueError(f"acf must be one of {ACF_MODELS}, got {acf!r}")
        if method not in ("fft", "linear"):
            raise ValueError(f"method must be 'fft' or 'linear', got {method!r}")
        if heights not in HEIGHT_MODELS:
            raise ValueError(f"heights must be one of {HEIGHT_MODELS}, got {heights!r}")
        ny, nx = _pair("shape", shape, "samples", 2, 8192, integer=True)
        if nx * ny > 2 ** 26:
            raise ValueError(f"shape = {shape!r} [samples] holds {nx * ny} samples; allowed: at most 2^26")
        dx, dy = _pair("spacing", spacing, "m", 1e-9, 1e-2)
        rq = check_range("rq", rq, "m", 1e-10, 1e-3, why="(0.1 nm to 1 mm)")
        if correlation_lengths is None:
            correlation_lengths = min(nx * dx, ny * dy) / 8.0
        lx, ly = _pair("correlation_lengths", correlation_lengths, "m", 1e-9, 1.0)
        sk = check_range("skewness", skewness, "-", -10.0, 10.0)
        if heights == "gamma":
            if kurtosis is not None:
                raise ValueError("kurtosis is implied by the gamma height model (Ku = 3 + 1.5 Sk_eta^2 "
                                 "sum a^4/(sum a^2)^2); use heights='johnson' to prescribe it")
            if sk == 0:
                raise ValueError("parameter skewness = 0 [-] out of range for heights='gamma': must be != 0")
            ku = None
        else:
            ku = 3.0 if kurtosis is None else check_range("kurtosis", kurtosis, "-", 1.0, low_open=True)
        if heights == "auto":
            heights = "gaussian" if (sk == 0 and ku == 3.0) else "johnson"
        if heights == "gaussian" and (sk != 0 or ku != 3.0):
            raise ValueError(f"heights='gaussian' needs skewness 0 and kurtosis 3, got {sk:g}, {ku:g}")
        rng = np.random.default_rng(seed)

        if method == "fft":
            reach = 1.0 if acf == "triangular" else 3.0  # exponential: R(3 l) = 1e-3
            if nx * dx < 2 * reach * lx or ny * dy < 2 * reach * ly:
                raise ValueError(f"shape x spacing = {nx * dx:g} x {ny * dy:g} m is too small for correlation_lengths "
                                 f"({lx:g}, {ly:g}) m with method='fft': need each side >= "
                                 f"{2 * reach:g} x correlation length")
            sqS = _fft_spectrum_sqrt(acf, (ny, nx), (dx, dy), (lx, ly))
            kern = np.fft.irfft2(sqS, s=(ny, nx))  # zero-phase kernel, sum k^2 = R(0) = 1
            fit_res = 0.0
            eta_shape = (ny, nx)
        else:
            kern, fit_res = patir_coefficients(acf, (dx, dy), (lx, ly), cutoff=cutoff)
            eta_shape = (ny + kern.shape[0] - 1, nx + kern.shape[1] - 1)
        kv = kern.ravel()
        s2 = float(kv @ kv)
        if heights == "gaussian":
            A3 = A4 = math.nan  # not needed for Gaussian heights
        else:
            k2 = kv * kv
            A3 = float(k2 @ kv) / s2 ** 1.5
            A4 = float(k2 @ k2) / s2 ** 2

        n_eta = eta_shape[0] * eta_shape[1]
        family = heights
        if heights == "gaussian":
            sk_eta, ku_eta = 0.0, 3.0
            eta = rng.standard_normal(n_eta)
        elif heights == "gamma":
            if abs(A3) < 1e-12:
                raise ValueError("the filter kernel has zero third moment: skewness cannot be transferred")
            sk_eta = sk / A3
            k = 4.0 / sk_eta ** 2
            ku_eta = 3.0 + 6.0 / k
            g = rng.gamma(k, 1.0, n_eta)
            eta = math.copysign(1.0, sk_eta) * (g - k) / math.sqrt(k)
            ku = 3.0 + (ku_eta - 3.0) * A4
        else:  # johnson
            sk_eta = sk / A3 if sk != 0 else 0.0
            ku_eta = 3.0 + (ku - 3.0) / A4
            if not ku_eta > sk_eta ** 2 + 1.0:
                raise ValueError(
                    f"infeasible (skewness, kurtosis) = ({sk:g}, {ku:g}) for this kernel: the i.i.d. "
                    f"input would need Sk = {sk_eta:.3g}, Ku = {ku_eta:.3g} (Ku must exceed Sk^2 + 1); "
                    f"raise the kurtosis or shorten the correlation lengths")
            family, f = johnson_standard_sampler(sk_eta, ku_eta)
            eta = f(rng.standard_normal(n_eta))
        eta = eta.reshape(eta_shape)

        if method == "fft":
            z = np.fft.irfft2(np.fft.rfft2(eta) * sqS, s=(ny, nx))
        else:
            from scipy import signal

            z = signal.fftconvolve(eta, kern[::-1, ::-1], mode="valid")  # = correlate(eta, a)
        z *= rq / math.sqrt(s2)
        if not np.all(np.isfinite(z)):
            raise ValueError(f"skewness = {sk:g}, kurtosis = {ku} [-]: the {family} height system gives no finite "
                             "heights here (nearly Gaussian: give skewness = 0 and kurtosis = 3)")
        meta = dict(method=method, heights=family, target_rq=rq, target_skewness=sk, target_kurtosis=ku,
                    target_correlation_lengths=(lx, ly), eta_skewness=sk_eta, eta_kurtosis=ku_eta,
                    kernel_A3=A3, kernel_A4=A4, kernel_shape=kern.shape, acf_fit_residual=fit_res,
                    seed=seed)
        return cls(heights=z, spacing=(dx, dy), acf_kind=acf, periodic=(method == "fft"), meta=meta)

    # ---- statistics ---------------------------------------------------------------------
    @property
    def shape(self):
        return self.heights.shape

    def _centred(self):
        return self.heights - self.heights.mean()

    @property
    def rq(self) -> float:
        """RMS roughness about the mean plane [m]."""
        return float(np.sqrt(np.mean(self._centred() ** 2)))

    @property
    def skewness(self) -> float:
        zc = self._centred()
        return float(np.mean(zc ** 3) / np.mean(zc ** 2) ** 1.5)

    @property
    def kurtosis(self) -> float:
        zc = self._centred()
        return float(np.mean(zc ** 4) / np.mean(zc ** 2) ** 2)

    def acf(self, max_lag=None):
        """Measured normalised ACF: returns (tau_x [m], tau_y [m], R) with R[iy, ix] centred on 0."""
        R = measured_acf(self.heights, max_lag, periodic=self.periodic)
        Ly, Lx = (R.shape[0] - 1) // 2, (R.shape[1] - 1) // 2
        return (np.arange(-Lx, Lx + 1) * self.spacing[0], np.arange(-Ly, Ly + 1) * self.spacing[1], R)

    def decay_lengths(self, level: float = 0.5):
        """Lags (x, y) [m] at which the measured ACF along each axis first falls to ``level``."""
        R = measured_acf(self.heights, None, periodic=self.periodic)
        Ly, Lx = (R.shape[0] - 1) // 2, (R.shape[1] - 1) // 2
        lg = self.acf_kind == "exponential"
        return (float(_first_crossing(R[Ly, Lx:], level, lg) * self.spacing[0]),
                float(_first_crossing(R[Ly:, Lx], level, lg) * self.spacing[1]))

    @property
    def correlation_lengths(self):
        """Measured (lx, ly) [m] in the convention of the generating ACF model.

        Estimated from the half-decay lengths lambda_0.5 (the least noisy level):
        triangular lx = 2 lambda_0.5x, exponential lx = (ln10/ln2) lambda_0.5x.  For a surface
        without a model, Patir's definition (decay to 10 %) is returned.
        """
        if self.acf_kind in ACF_MODELS:
            f = _acf_half_level_factor(self.acf_kind)
            l5 = self.decay_lengths(0.5)
            return (float(f * l5[0]), float(f * l5[1]))
        return self.decay_lengths(0.1)

    @property
    def gamma(self) -> float:
        """Peklenik number gamma = lambda_0.5x / lambda_0.5y (= lx/ly for both ACF models)."""
        l5 = self.decay_lengths(0.5)
        return float(l5[0] / l5[1])

    def statistics(self) -> dict:
        lx, ly = self.correlation_lengths
        return dict(rq=self.rq, skewness=self.skewness, kurtosis=self.kurtosis, lx=lx, ly=ly, gamma=lx / ly)

    def height_density(self, bins: int = 256):
        """Discrete height density of the surface (see asperity.DiscreteDensity)."""
        from transient.physics.asperity import DiscreteDensity
        return DiscreteDensity.from_samples(self.heights.ravel(), bins=bins)
