"""Statistical asperity contact (Greenwood & Tripp 1971; Bhushan 1998; Lee & Rhim eqs. (15)-(19)).

Heights z of the equivalent rough surface (z = z1 + z2, measured from its mean plane, positive
towards the smooth counter-surface) have a density phi(z); the nominal separation of the mean plane
from the smooth surface is h0, so the local gap is h0 - z and contact occurs where z > h0.  With
N asperities per unit area, all of radius Rp (1/Rp = 1/Rp1 + 1/Rp2) and Hertzian elastic contact:

    W_asp / A = (4/3) N E' Rp^(1/2) int_{h0}^{inf} (z - h0)^(3/2) phi(z) dz       (Lee & Rhim 15)
    A_re  / A = pi N Rp int_{h0}^{inf} (z - h0) phi(z) dz                       (Lee & Rhim 16)
    p_r       = W_asp / A_re  (mean real contact pressure)
    psi       = (E'/H) sqrt(Rq/Rp) < 1  (plasticity index, elastic contact only)  (Lee & Rhim 17)

E' is the Hertz contact modulus 1/E' = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (the paper's notation list;
for steel on steel, E = 210 GPa, nu = 0.3: E' = 115.4 GPa).  Beware that Greenwood & Tripp and
Hamrock write E' for twice this value.

For Gaussian heights of standard deviation sigma the integrals are sigma^n F_n(h0/sigma) with the
Greenwood-Tripp functions :func:`greenwood_tripp`; for a generated surface they are evaluated on
its discrete (histogram) density, :class:`DiscreteDensity`, as in Lee & Rhim.

Note: Greenwood-Williamson use summit heights; Lee & Rhim (and this module) use the surface height
density in their place, with Rq as sigma.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy import special

from transient.checks import check_positive, check_range

__all__ = [
    "greenwood_tripp",
    "greenwood_tripp_derivative",
    "DiscreteDensity",
    "AsperityContact",
    "SummitContact",
    "STEEL_CONTACT",
    "steel_asperity_contact",
]

_SQRT2PI = math.sqrt(2.0 * math.pi)


def _npdf(h):
    return np.exp(-0.5 * h * h) / _SQRT2PI


def greenwood_tripp(n, h):
    """Greenwood-Tripp function F_n(h) = int_h^inf (s - h)^n phi(s) ds, phi the standard normal pdf.

    ``h`` is in units of sigma (array-like, vectorised); ``n`` > -1 (typically 0, 1, 3/2, 2, 5/2).

    Closed forms (with the upper-tail probability Q(h) = 1 - Phi(h) = phi(h) M(h), M the Mills
    ratio sqrt(pi/2) erfcx(h/sqrt(2)), used to avoid cancellation at large h):
        F_0 = Q(h);   F_1 = phi(h) - h Q(h);   F_2 = (1 + h^2) Q(h) - h phi(h);
    any n (Gradshteyn & Ryzhik 3.462.1, parabolic cylinder function D_v of scipy.special.pbdv):
        F_n(h) = Gamma(n + 1) / sqrt(2 pi) * exp(-h^2/4) * D_{-n-1}(h).
    Relative accuracy against 1e-13 quadrature: ~1e-15 (n = 0, 1, 2), <= 2e-9 (n = 3/2, 5/2).
    Published values (Greenwood & Tripp 1971): F_{3/2}(0) = 0.4300, F_{5/2}(0) = 0.6166.
    F_n underflows to 0 for h > ~38.
    """
    n = float(n)
    if not n > -1.0:
        raise ValueError(f"parameter n = {n:g} [-] out of range: allowed (-1, inf)")
    h = np.asarray(h, dtype=float)
    if n in (0.0, 1.0, 2.0):
        pdf = _npdf(h)
        pos = h > 0
        # Q(h): erfc for h <= 0 (no cancellation), phi * Mills ratio for h > 0
        ha = np.where(pos, h, 0.0)
        mills = math.sqrt(math.pi / 2.0) * special.erfcx(ha / math.sqrt(2.0))
        q = np.where(pos, pdf * mills, 0.5 * special.erfc(h / math.sqrt(2.0)))
        if n == 0.0:
            out = q
        elif n == 1.0:
            out = np.where(pos, pdf * (1.0 - ha * mills), pdf - h * q)
        else:
            out = np.where(pos, pdf * ((1.0 + ha * ha) * mills - ha), (1.0 + h * h) * q - h * pdf)
    else:
        with np.errstate(over="ignore", under="ignore", invalid="ignore"):
            d, _ = special.pbdv(-n - 1.0, h)
            out = special.gamma(n + 1.0) / _SQRT2PI * np.exp(-0.25 * h * h) * d
        out = np.where(h > 38.0, 0.0, out)
    return out if out.ndim else float(out)


def greenwood_tripp_derivative(n, h):
    """dF_n/dh = -n F_{n-1}(h) for n > 0 (and -phi(h) for n = 0)."""
    n = float(n)
    if n == 0.0:
        out = -_npdf(np.asarray(h, dtype=float))
        return out if out.ndim else float(out)
    if not n > 0.0:
        raise ValueError(f"parameter n = {n:g} [-] out of range: allowed 0 or (0, inf)")
    return -n * greenwood_tripp(n - 1.0, h)


# ------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class DiscreteDensity:
    """Piecewise-uniform height density: probability ``prob[k]`` spread evenly over
    [edges[k], edges[k+1]] [m] (a histogram of a generated surface, mean plane at z = 0).

    Integrals are exact for this density (so they are continuous and differentiable in h0):
        I_n(h0) = int (z - h0)_+^n phi(z) dz
                = sum_k prob_k [(b_k - h0)_+^(n+1) - (a_k - h0)_+^(n+1)] / ((n + 1)(b_k - a_k)).
    """

    edges: np.ndarray
    prob: np.ndarray

    def __post_init__(self):
        e = np.asarray(self.edges, dtype=float)
        p = np.asarray(self.prob, dtype=float)
        if e.ndim != 1 or p.ndim != 1 or e.size != p.size + 1 or p.size < 1:
            raise ValueError(f"edges (K+1) and prob (K) must be 1-D, got {e.shape} and {p.shape}")
        if np.any(np.diff(e) <= 0):
            raise ValueError("edges [m] must be strictly increasing")
        if np.any(p < 0) or not abs(p.sum() - 1.0) < 1e-9:
            raise ValueError(f"prob must be non-negative and sum to 1, sum = {p.sum():.12g}")
        object.__setattr__(self, "edges", e)
        object.__setattr__(self, "prob", p)

    @classmethod
    def from_samples(cls, z, bins: int = 256, remove_mean: bool = True) -> "DiscreteDensity":
        """Histogram of samples z [m] (mean removed by default) with ``bins`` equal bins."""
        z = np.asarray(z, dtype=float).ravel()
        if z.size < 2:
            raise ValueError("need at least 2 height samples")
        bins = int(check_range("bins", bins, "-", 1))
        if remove_mean:
            z = z - z.mean()
        cnt, edges = np.histogram(z, bins=bins)
        return cls(edges=edges, prob=cnt / cnt.sum())

    @classmethod
    def gaussian(cls, sigma: float, bins: int = 400, width: float = 8.0) -> "DiscreteDensity":
        """Gaussian of std sigma [m] discretised on +-width sigma (mainly for tests)."""
        sigma = check_range("sigma", sigma, "m", 1e-10, 1e-3, why="(0.1 nm to 1 mm)")
        e = np.linspace(-width, width, bins + 1)
        p = np.diff(special.ndtr(e))
        return cls(edges=e * sigma, prob=p / p.sum())

    @property
    def mean(self) -> float:
        c = 0.5 * (self.edges[1:] + self.edges[:-1])
        return float(self.prob @ c)

    @property
    def sigma(self) -> float:
        """Standard deviation of the piecewise-uniform density [m] (includes within-bin spread)."""
        a, b = self.edges[:-1], self.edges[1:]
        m2 = self.prob @ ((a * a + a * b + b * b) / 3.0)
        return float(math.sqrt(m2 - self.mean ** 2))

    def integral(self, n, h0):
        """I_n(h0) = int_{h0}^inf (z - h0)^n phi(z) dz [m^n], vectorised in h0 [m]; n >= 0."""
        n = float(n)
        if not n >= 0.0:
            raise ValueError(f"parameter n = {n:g} [-] out of range: allowed [0, inf)")
        h = np.asarray(h0, dtype=float)
        a, b = self.edges[:-1], self.edges[1:]
        hh = h[..., None]
        up = np.clip(b - hh, 0.0, None) ** (n + 1.0)
        lo = np.clip(a - hh, 0.0, None) ** (n + 1.0)
        out = ((up - lo) / ((n + 1.0) * (b - a))) @ self.prob
        return out if out.ndim else float(out)

    def cdf(self, z):
        """P(Z <= z)."""
        return 1.0 - self.integral(0, z)

    def contact_factor(self, h0):
        """Wu-Zheng contact factor phi_c = d(h_bar)/d(h0) = P(z < h0) (see flow_factors)."""
        return self.cdf(h0)

    def mean_gap(self, h0):
        """Average film thickness h_bar = int_{z < h0} (h0 - z) phi(z) dz [m] (Lee & Rhim eq. 7)."""
        h = np.asarray(h0, dtype=float)
        # int (h0 - z)_+ phi = h0 - mean + int (z - h0)_+ phi
        out = h - self.mean + self.integral(1, h)
        return out if np.ndim(out) else float(out)


# ------------------------------------------------------------------------------------------
STEEL_CONTACT = dict(
    e_prime=1.154e11,   # Pa, Hertz contact modulus, steel/steel E = 210 GPa, nu = 0.3
    hardness=4.0e9,     # Pa, ~400 HV through-hardened steel (range 2-7 GPa)
    n_rq_rp=0.04,       # N Rq Rp [-], Lee & Rhim eq. (19), typical 0.03-0.05 (Greenwood-Williamson)
    sqrt_rq_rp=0.01,    # sqrt(Rq/Rp) [-], Lee & Rhim eq. (19); gives psi = 0.29 (elastic)
)
"""Default steel-on-steel contact constants (Lee & Rhim do not give N, Rp, E', H).

Chosen so that contact is elastic (psi = (E'/H) sqrt(Rq/Rp) = 28.9 * 0.01 = 0.29 < 1, as eq. (17)
requires) with the Greenwood-Williamson density group N Rq Rp = 0.04 (published surfaces span
0.03-0.05).  For Rq = 5 um: Rp = Rq / 0.01^2 = 50 mm and N = 0.04/(Rq Rp) = 1.6e5 m^-2.
"""


@dataclass(frozen=True)
class AsperityContact:
    """Greenwood-Tripp elastic asperity contact of a rough surface on a smooth one (SI units).

    asperity_density N [1/m^2] > 0; asperity_radius Rp [m] > 0; e_prime E' [Pa] > 0 (Hertz contact
    modulus); hardness H [Pa] > 0; and the height density: ``sigma`` [m] (Gaussian) or ``density``
    (:class:`DiscreteDensity`, e.g. ``surface.height_density()``), sigma then defaulting to the
    density's standard deviation.  ``elastic_only`` (default True) rejects psi >= 1.
    """

    asperity_density: float
    asperity_radius: float
    e_prime: float
    hardness: float
    sigma: float | None = None
    density: DiscreteDensity | None = None
    elastic_only: bool = True

    def __post_init__(self):
        set_ = lambda k, v: object.__setattr__(self, k, v)  # noqa: E731
        set_("asperity_density", check_range("asperity_density N", self.asperity_density, "1/m^2", 1e3, 1e16))
        set_("asperity_radius", check_range("asperity_radius Rp", self.asperity_radius, "m", 1e-9, 1.0))
        set_("e_prime", check_range("e_prime E'", self.e_prime, "Pa", 1e6, 1e13))
        set_("hardness", check_range("hardness H", self.hardness, "Pa", 1e6, 1e12))
        if self.density is None and self.sigma is None:
            raise ValueError("give the height density: sigma [m] (Gaussian) or density (DiscreteDensity)")
        if self.density is not None and not isinstance(self.density, DiscreteDensity):
            raise ValueError(f"density must be a DiscreteDensity, got {type(self.density).__name__}")
        sig = self.density.sigma if self.sigma is None else self.sigma
        set_("sigma", check_range("sigma (Rq)", sig, "m", 1e-10, 1e-3))
        psi = self.plasticity_index
        if self.elastic_only and not psi < 1.0:
            raise ValueError(
                f"plasticity index psi = (e_prime / hardness) sqrt(sigma / asperity_radius) = ({self.e_prime:g} Pa / "
                f"{self.hardness:g} Pa) * sqrt({self.sigma:g} m / {self.asperity_radius:g} m) = {psi:.4g} out of range: "
                f"the elastic Greenwood-Tripp model needs psi < 1 (Lee & Rhim eq. 17); lower sqrt(Rq/Rp) "
                f"or E'/H, or pass elastic_only=False")

    @property
    def plasticity_index(self) -> float:
        """psi = (E'/H) sqrt(Rq/Rp) (Greenwood-Williamson; Lee & Rhim eq. 17)."""
        return self.e_prime / self.hardness * math.sqrt(self.sigma / self.asperity_radius)

    def _I(self, n, h0):
        if self.density is not None:
            return self.density.integral(n, h0)
        return self.sigma ** n * greenwood_tripp(n, np.asarray(h0, dtype=float) / self.sigma)

    def load(self, h0):
        """Asperity load per unit nominal area W_asp/A [Pa] at separation h0 [m] (eq. 15)."""
        c = 4.0 / 3.0 * self.asperity_density * self.e_prime * math.sqrt(self.asperity_radius)
        return c * self._I(1.5, h0)

    def load_derivative(self, h0):
        """d(W_asp/A)/d(h0) [Pa/m] = -(3/2) (4/3) N E' Rp^(1/2) I_(1/2)(h0)."""
        c = 4.0 / 3.0 * self.asperity_density * self.e_prime * math.sqrt(self.asperity_radius)
        return -1.5 * c * self._I(0.5, h0)

    def real_area_fraction(self, h0):
        """Real contact area per unit nominal area A_re/A [-] (eq. 16)."""
        return math.pi * self.asperity_density * self.asperity_radius * self._I(1.0, h0)

    def contact_count(self, h0):
        """Number of asperity contacts per unit nominal area [1/m^2]: N P(z > h0)."""
        return self.asperity_density * self._I(0.0, h0)

    def mean_contact_pressure(self, h0):
        """Mean real contact pressure p_r = W_asp / A_re [Pa] (nan where there is no contact)."""
        w = np.asarray(self.load(h0), dtype=float)
        a = np.asarray(self.real_area_fraction(h0), dtype=float)
        out = np.divide(w, a, out=np.full_like(w, np.nan), where=a > 0)
        return out if out.ndim else float(out)


def steel_asperity_contact(rq: float, density: DiscreteDensity | None = None, **overrides) -> AsperityContact:
    """AsperityContact for steel on steel with roughness Rq [m], from :data:`STEEL_CONTACT`.

    Rp = Rq / sqrt_rq_rp^2, N = n_rq_rp / (Rq Rp) (Lee & Rhim eq. 19).  ``overrides`` may replace
    any key of STEEL_CONTACT.  Gaussian heights unless a discrete ``density`` is given.
    """
    unknown = set(overrides) - set(STEEL_CONTACT)
    if unknown:
        raise ValueError(f"unknown steel contact constants {sorted(unknown)}; allowed {sorted(STEEL_CONTACT)}")
    c = {**STEEL_CONTACT, **overrides}
    rq = check_range("rq", rq, "m", 1e-10, 1e-4, why="(0.1 nm to 100 um for steel asperities)")
    s = check_positive("sqrt_rq_rp", c["sqrt_rq_rp"], "-")
    g = check_positive("n_rq_rp", c["n_rq_rp"], "-")
    rp = rq / s ** 2
    return AsperityContact(asperity_density=g / (rq * rp), asperity_radius=rp, e_prime=c["e_prime"],
                           hardness=c["hardness"], sigma=rq if density is None else None, density=density)


_GT_TWO_SURFACES = 16.0 * math.sqrt(2.0) * math.pi / 15.0


@dataclass(frozen=True)
class SummitContact(AsperityContact):
    """Greenwood-Tripp contact of two rough surfaces on their summits (Greenwood & Tripp, Proc. IMechE 185 (1970)
    625-633, the form of Sander et al., Tribol. Int. 96 (2016) 173-183)::

        p_a(h) = K E' F_5/2((h - delta) / sigma_s),   K = 16 sqrt(2) pi / 15 (eta beta sigma_s)^2 sqrt(sigma_s / beta)

    with ``h`` the nominal gap between the surfaces' mean planes, ``delta`` = ``summit_height`` [m] the summits' mean
    plane above the surfaces' (the two surfaces' sum), ``sigma_s`` = ``summit_sigma`` [m] the composite standard
    deviation of summit heights, ``eta`` = ``asperity_density`` [1/m^2], ``beta`` = ``asperity_radius`` [m] and E'
    = ``e_prime`` with 1/E' = sum (1 - nu_i^2) / E_i. ``sigma`` [m] stays the composite RMS roughness of the surface
    heights (the average flow model's). ``elastic_only`` defaults to False here (a soft bearing alloy's asperities
    yield; the law is the elastic one all the same)."""

    summit_sigma: float | None = None
    summit_height: float = 0.0
    elastic_only: bool = False

    def __post_init__(self):
        super().__post_init__()
        if self.summit_sigma is None:
            raise ValueError("summit_sigma = None [m]; allowed: the summits' composite standard deviation, 1e-10 to "
                             "1e-3 m")
        object.__setattr__(self, "summit_sigma", check_range("summit_sigma", self.summit_sigma, "m", 1e-10, 1e-3))
        object.__setattr__(self, "summit_height", check_range("summit_height", self.summit_height, "m", 0.0, 1e-3))

    @property
    def k_factor(self) -> float:
        """K = 16 sqrt(2) pi / 15 (eta beta sigma_s)^2 sqrt(sigma_s / beta) [-]."""
        s, b = self.summit_sigma, self.asperity_radius
        return _GT_TWO_SURFACES * (self.asperity_density * b * s) ** 2 * math.sqrt(s / b)

    def _lam(self, h0):
        return (np.asarray(h0, dtype=float) - self.summit_height) / self.summit_sigma

    def load(self, h0):
        """Asperity load per unit nominal area [Pa] at the gap h0 [m] between the mean planes."""
        return self.k_factor * self.e_prime * greenwood_tripp(2.5, self._lam(h0))

    def load_derivative(self, h0):
        """d(load)/d(h0) [Pa/m] = -(5/2) K E' F_3/2(lambda) / sigma_s."""
        return -2.5 * self.k_factor * self.e_prime * greenwood_tripp(1.5, self._lam(h0)) / self.summit_sigma

    def real_area_fraction(self, h0):
        """Real contact area per unit nominal area [-]: pi^2 (eta beta sigma_s)^2 F_2(lambda)."""
        return math.pi ** 2 * (self.asperity_density * self.asperity_radius * self.summit_sigma) ** 2 * \
            greenwood_tripp(2.0, self._lam(h0))

    def contact_count(self, h0):
        raise NotImplementedError("SummitContact: the count of contacting summit pairs is not modelled")
