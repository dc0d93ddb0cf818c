"""The paper's semi-analytic route (eq. 8–9 and 12–13), vectorised in NumPy.

The paper integrates the friction integrals (4) and (11) over η in closed form and leaves a
quadrature over ξ. This module implements that route faithfully, with switches for the two
printed formulas that are wrong, so that their effect can be measured (MODEL §7):

* ``i1="printed"`` uses eq. 9's printed I₁ = (1/κ) ln[(2√Q₊ + 2κ²h + D₁κ)/(2√Q₋ − 2κ²h + D₁κ)];
  ``i1="corrected"`` (default) uses I₁ = (1/κ) ln[(2√Q₊ + 2κh + D₁)/(2√Q₋ − 2κh + D₁)],
  Q± = D₀ ± D₁κh + κ²h² (erratum 3).
* ``c31="printed"`` uses eq. 13's printed η³ terms, −C₃₁D₁(3D₀/4 + 5D₁²/16) I₁ and no
  C₃₁κ²h²/3 in the (1/κ)I₂ bracket; ``c31="corrected"`` (default) uses +C₃₁D₁(3D₀/4 − 5D₁²/16)
  and adds the missing term (erratum 6). Only the linear law has C₃₁ ≠ 0.

With the defaults the result is the exact wrench, and agrees with
:func:`slidespin.friction_wrench` to quadrature accuracy (see ``tests/paper/test_semianalytic.py``).

Units and conventions (paper eq. 7): lengths in units of the semi-axis a, the friction force
per unit load P = m g and the moment per P a. ``beta`` is β = v/ω ≥ 0 for ω > 0, the only sign
the coefficients (6) are written for (erratum 4); :func:`rhs` extends them to ω < 0 by the
symmetry (v, ω) → (−v, −ω). The paper's state is (x, y, φ, v, ϑ, ω) with v = v₁√(ag/π),
ω = ω₁√(g/(aπ)), t = t₁√(aπ/g) (erratum 2), in which eq. 8 reads

    v̇ = −π F_τ/P,   ϑ̇ = −π F_n/(P v),   ω̇ = −π M_Cζ/(P a I*).

Method
------
η-integration (closed form, any limits [η_lo, η_hi], Q(η) = η² + D₁η + D₀ = (η + D₁/2)² + d²):

    K₀ = ∫ dη/√Q = ln[(2√Q(η_hi) + 2η_hi + D₁)/(2√Q(η_lo) + 2η_lo + D₁)]      (κ I₁ of eq. 9)
    K₁ = [√Q] − (D₁/2) K₀
    K₂ = [(η/2 − 3D₁/4)√Q] + (3D₁²/8 − D₀/2) K₀
    K₃ = [(η²/3 − 5D₁η/12 + 5D₁²/8 − 2D₀/3)√Q] + D₁(3D₀/4 − 5D₁²/16) K₀

K₀ is evaluated without cancellation (each logarithm of a sum of non-negative terms; d = |ξ +
β sin(ϑ − φ)| is computed directly, not as √(D₀ − D₁²/4)). For symmetric limits ±κh these are
exactly the combinations of I₁, I₂, I₃ in eq. 8 and 13.

ξ-quadrature: ξ = sin t removes the square-root ends of h(ξ) = √(1 − ξ²); the t-interval is
split where the instantaneous centre of rotation (ICR) projects (there K₀ has a logarithmic
singularity when the ICR is inside the patch), and each half is mapped by t − t* ∝ s³ and
integrated by Gauss–Legendre in s with ``nodes`` points. Against the compiled wrench of
:func:`slidespin.friction_wrench` the default 48 nodes give 1e-14 for most states and 1e-10
with the ICR just outside the rim; 128 nodes give 1e-14 throughout (tests/paper/test_semianalytic.py).

Reference point (erratum 7): the paper does not say which point its linear-law equations
(11) refer to. ``reference="mass_centre"`` (default, as slidespin) measures positions, the
velocity v and the moment from the mass centre G = (ξc, ηc); ``reference="centre"`` from the
patch centre C, i.e. eq. 11 read literally with C treated as the mass centre.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from functools import lru_cache
from typing import NamedTuple

import numpy as np

from slidespin import _validate as v

__all__ = [
    "PaperModel",
    "PaperWrench",
    "wrench",
    "eta_integrals",
    "rhs",
    "uniform_rhs",
    "integrate",
    "SemiAnalyticRun",
]

_VARIANTS = ("corrected", "printed")
_REFERENCES = ("mass_centre", "centre")
_BIG_BETA = 1e7  # beyond this β (units of a) the motion is treated as a pure translation


@dataclass(frozen=True, slots=True)
class PaperModel:
    """Parameters of the paper's semi-analytic equations (8)–(9) and (11)–(13).

    Parameters
    ----------
    kappa : float
        κ = b/a = √(1 − e²), in (0, 1].
    fx, fy : float
        Friction coefficients (> 0); μ = fy − fx.
    f : float, default 0
        Skew coefficient of the tensor (2).
    xi_c, eta_c : float, default 0
        Centroid of the linear pressure law (10) in units of a (both 0: the uniform law of
        §2.1). Must satisfy xi_c² + (eta_c/κ)² ≤ 1/16 (pressure ≥ 0).
    inertia_ratio : float or None
        I* = I/(m a²) about the reference point; ``None`` is the uniform plate (1 + κ²)/4
        (eq. 7).
    reference : {"mass_centre", "centre"}
        Point the velocity and the moment refer to (see the module notes, erratum 7).
    i1, c31 : {"corrected", "printed"}
        Which form of I₁ (eq. 9, erratum 3) and of the C₃₁ terms (eq. 13, erratum 6) to use.
    nodes : int, default 48
        Gauss–Legendre points on each of the two halves of the ξ-interval (4 to 2000).

    Examples
    --------
    >>> m = PaperModel.from_eccentricity(0.866, fx=0.42, fy=0.54)
    >>> round(m.kappa, 4), round(m.mu, 2)
    (0.5, 0.12)
    """

    kappa: float
    fx: float
    fy: float
    f: float = 0.0
    xi_c: float = 0.0
    eta_c: float = 0.0
    inertia_ratio: float | None = None
    reference: str = "mass_centre"
    i1: str = "corrected"
    c31: str = "corrected"
    nodes: int = 48

    def __post_init__(self) -> None:
        k = v.in_range("kappa", self.kappa, 0.0, 1.0, lo_open=True)
        object.__setattr__(self, "kappa", k)
        object.__setattr__(self, "fx", v.positive("fx", self.fx))
        object.__setattr__(self, "fy", v.positive("fy", self.fy))
        object.__setattr__(self, "f", v.finite("f", self.f))
        xc = v.finite("xi_c", self.xi_c)
        ec = v.finite("eta_c", self.eta_c)
        core = xc * xc + (ec / k) ** 2
        if core > 1.0 / 16.0 * (1.0 + 1e-12):
            raise ValueError(
                f"(xi_c, eta_c) = ({xc!r}, {ec!r}) is invalid: xi_c^2 + (eta_c/kappa)^2 = "
                f"{core:.6g}; valid range: [0, 0.0625] (otherwise the pressure turns negative)"
            )
        object.__setattr__(self, "xi_c", xc)
        object.__setattr__(self, "eta_c", ec)
        if self.inertia_ratio is None:
            object.__setattr__(self, "inertia_ratio", (1.0 + k * k) / 4.0)
        else:
            object.__setattr__(
                self, "inertia_ratio", v.positive("inertia_ratio", self.inertia_ratio)
            )
        object.__setattr__(self, "reference", v.choice("reference", self.reference, _REFERENCES))
        object.__setattr__(self, "i1", v.choice("i1", self.i1, _VARIANTS))
        object.__setattr__(self, "c31", v.choice("c31", self.c31, _VARIANTS))
        n = self.nodes
        if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or not 4 <= n <= 2000:
            raise ValueError(f"nodes = {n!r} is invalid; valid range: integer in [4, 2000]")

    @classmethod
    def from_eccentricity(cls, eccentricity: float, **kwargs) -> PaperModel:
        """Model for an ellipse of eccentricity e in [0, 1) (κ = √(1 − e²), eq. 7)."""
        e = v.in_range("eccentricity", eccentricity, 0.0, 1.0, hi_open=True)
        return cls(math.sqrt(1.0 - e * e), **kwargs)

    @property
    def mu(self) -> float:
        """μ = fy − fx."""
        return self.fy - self.fx

    @property
    def reference_point(self) -> tuple[float, float]:
        """Body coordinates (ξ, η) of the reference point, units of a."""
        return (self.xi_c, self.eta_c) if self.reference == "mass_centre" else (0.0, 0.0)

    def with_(self, **changes) -> PaperModel:
        """Copy with some parameters changed (validated)."""
        return replace(self, **changes)


class PaperWrench(NamedTuple):
    """The paper's friction components per unit load: F_τ/P, F_n/P and M_Cζ/(P a)."""

    tangential: np.ndarray
    normal: np.ndarray
    moment_paper: np.ndarray


@lru_cache(maxsize=64)
def _gauss(n: int):
    x, w = np.polynomial.legendre.leggauss(n)
    s = 0.5 * (x + 1.0)  # nodes on [0, 1]
    return s, 0.5 * w


def eta_integrals(
    lo, hi, d1, d0, d, *, i1: str = "corrected", c31: str = "corrected", kappa: float = 1.0
):
    """K_n = ∫ η^n/√(η² + D₁η + D₀) dη over [lo, hi], n = 0..3, in closed form (eq. 8–9, 13).

    Parameters
    ----------
    lo, hi : array_like
        Limits of the η-integration (units of a).
    d1, d0 : array_like
        D₁ and D₀ of eq. 6.
    d : array_like
        d = √(D₀ − D₁²/4) ≥ 0, passed in so that it can be computed without cancellation.
    i1, c31 : {"corrected", "printed"}
        Variants of K₀ (erratum 3) and K₃ (erratum 6). The printed K₀ is the logarithm of
        eq. 9's printed I₁ with ±κh replaced by the limits: ln[(2√Q(hi) + κ(2hi + D₁))/
        (2√Q(lo) + κ(2lo + D₁))].
    kappa : float, default 1
        κ = b/a, used only by the printed K₀ (with κ = 1 it equals the corrected one).

    Returns
    -------
    K0, K1, K2, K3 : ndarray
    """
    i1 = v.choice("i1", i1, _VARIANTS)
    c31 = v.choice("c31", c31, _VARIANTS)
    lo_, hi_, d1_, d0_, d_ = (np.asarray(x, dtype=float) for x in (lo, hi, d1, d0, d))
    kappa = v.in_range("kappa", kappa, 0.0, 1.0, lo_open=True)
    return _eta_integrals(lo_, hi_, d1_, d0_, d_, i1, c31, kappa)


def _eta_integrals(lo, hi, d1, d0, d, i1, c31, kappa):
    y_hi = hi + 0.5 * d1
    y_lo = lo + 0.5 * d1
    r_hi = np.hypot(y_hi, d)  # √Q(hi)
    r_lo = np.hypot(y_lo, d)
    if i1 == "printed":
        with np.errstate(divide="ignore", invalid="ignore"):
            k0 = np.log(
                (2.0 * r_hi + kappa * (2.0 * hi + d1)) / (2.0 * r_lo + kappa * (2.0 * lo + d1))
            )
    else:
        with np.errstate(divide="ignore", invalid="ignore"):
            pos = np.log((y_hi + r_hi) / (y_lo + r_lo))  # both y ≥ 0
            neg = np.log((r_lo - y_lo) / (r_hi - y_hi))  # both y ≤ 0
            mid = np.log(y_hi + r_hi) + np.log(r_lo - y_lo) - 2.0 * np.log(d)  # y_lo < 0 < y_hi
        k0 = np.where(y_lo >= 0.0, pos, np.where(y_hi <= 0.0, neg, mid))
    k1 = (r_hi - r_lo) - 0.5 * d1 * k0
    k2 = (
        (0.5 * hi - 0.75 * d1) * r_hi
        - (0.5 * lo - 0.75 * d1) * r_lo
        + (0.375 * d1 * d1 - 0.5 * d0) * k0
    )
    base = 0.625 * d1 * d1 - 2.0 * d0 / 3.0
    if c31 == "printed":
        p_hi = -5.0 * d1 * hi / 12.0 + base
        p_lo = -5.0 * d1 * lo / 12.0 + base
        k3 = p_hi * r_hi - p_lo * r_lo - d1 * (0.75 * d0 + 0.3125 * d1 * d1) * k0
    else:
        p_hi = hi * hi / 3.0 - 5.0 * d1 * hi / 12.0 + base
        p_lo = lo * lo / 3.0 - 5.0 * d1 * lo / 12.0 + base
        k3 = p_hi * r_hi - p_lo * r_lo + d1 * (0.75 * d0 - 0.3125 * d1 * d1) * k0
    return k0, k1, k2, k3


def _xi_nodes(xi_star, n):
    """Nodes ξ and weights for ∫₋₁¹ · dξ, split at ξ* and clustered there (shape (..., 2n))."""
    s, w = _gauss(n)
    t_star = np.arcsin(np.clip(xi_star, -1.0 + 1e-12, 1.0 - 1e-12))[..., None]
    s3 = s**3
    jac = 3.0 * s * s * w
    left = t_star - (t_star + 0.5 * math.pi) * s3
    right = t_star + (0.5 * math.pi - t_star) * s3
    wl = (t_star + 0.5 * math.pi) * jac
    wr = (0.5 * math.pi - t_star) * jac
    t = np.concatenate([left, right], axis=-1)
    wt = np.concatenate([np.broadcast_to(wl, left.shape), np.broadcast_to(wr, right.shape)], -1)
    return np.sin(t), wt * np.cos(t)  # dξ = cos t dt


def wrench(model: PaperModel, beta, theta, phi) -> PaperWrench:
    """F_τ/P, F_n/P and M_Cζ/(P a) by the paper's semi-analytic route, for ω > 0.

    Parameters
    ----------
    model : PaperModel
        Patch, friction, pressure centroid, reference point and errata switches.
    beta : array_like
        β = v/ω ≥ 0 in units of a (v: speed of the reference point).
    theta : array_like
        Direction ϑ of the velocity [rad].
    phi : array_like
        Body angle φ [rad].

    Returns
    -------
    PaperWrench
        Arrays of the broadcast shape of the inputs (floats for scalars).

    Notes
    -----
    Eq. 8 (uniform law) and eq. 13 (linear law), integrand coefficients (6) and (12), with the
    corrections of MODEL §7 unless the model asks for the printed forms. The integrals are
    those of eq. 4/11 divided by m g (force) and m g a (moment): eq. 8's accelerations are
    π times these in the paper's units.
    """
    if not isinstance(model, PaperModel):
        raise ValueError(f"model = {model!r} is invalid; valid values: a PaperModel")
    b, th, ph = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (beta, theta, phi)))
    if not (np.all(np.isfinite(b)) and np.all(b >= 0.0)):
        bad = b[~(np.isfinite(b) & (b >= 0.0))].flat[0]
        raise ValueError(f"beta = {bad!r} is invalid; valid range: finite and >= 0 (omega > 0)")
    if not (np.all(np.isfinite(th)) and np.all(np.isfinite(ph))):
        raise ValueError("theta and phi must be finite")
    scalar = b.ndim == 0
    b, th, ph = (x[..., None] for x in (b, th, ph))
    kap = model.kappa
    fx, f, mu = model.fx, model.f, model.mu
    xr, yr = model.reference_point
    sd, cd = np.sin(th - ph), np.cos(th - ph)
    st, ct = np.sin(th), np.cos(th)
    sp, cp = np.sin(ph), np.cos(ph)
    # ICR in the reference frame: ξ̃* = −β sin(ϑ − φ); in the patch frame ξ* = ξ̃* + ξr
    xi, wxi = _xi_nodes((xr - b * sd)[..., 0], model.nodes)
    h = np.sqrt(np.maximum(1.0 - xi * xi, 0.0))
    x = xi - xr  # ξ̃, measured from the reference point
    lo = -kap * h - yr
    hi = kap * h - yr
    d1 = -2.0 * b * cd
    d0 = b * b + x * x + 2.0 * b * x * sd
    d = np.abs(x + b * sd)
    k0, k1, k2, k3 = _eta_integrals(lo, hi, d1, d0, d, model.i1, model.c31, kap)
    # coefficients (6), with ξ measured from the reference point
    a0 = b * (fx + mu * st * st) + x * (f * cd + mu * st * cp + fx * sd)
    a1 = f * sd - mu * st * sp - fx * cd
    b0 = b * (mu * st * ct - f) + x * (-f * sd + mu * ct * cp + fx * cd)
    b1 = f * cd - mu * ct * sp + fx * sd
    c0 = x * b * (-f * cd + mu * st * cp + fx * sd) + x * x * (fx + mu * cp * cp)
    c1 = b * (-f * sd - mu * st * sp - fx * cd) - 2.0 * x * mu * cp * sp
    c2 = fx + mu * sp * sp
    # pressure (10), corrected (erratum 5): p/p0 = 1 + 4ξc ξ + 4ηc η/κ² = P0(ξ) + P1 η̃
    p1 = 4.0 * model.eta_c / (kap * kap)
    p0 = 1.0 + 4.0 * model.xi_c * xi + p1 * yr
    tau = p0 * a0 * k0 + (p0 * a1 + p1 * a0) * k1 + p1 * a1 * k2
    nor = p0 * b0 * k0 + (p0 * b1 + p1 * b0) * k1 + p1 * b1 * k2
    mom = p0 * c0 * k0 + (p0 * c1 + p1 * c0) * k1 + (p0 * c2 + p1 * c1) * k2 + p1 * c2 * k3
    scale = 1.0 / (math.pi * kap)
    out = [scale * np.sum(q * wxi, axis=-1) for q in (tau, nor, mom)]
    if scalar:
        out = [float(q) for q in out]
    return PaperWrench(*out)


def _translation(model: PaperModel, theta, phi):
    """Pure translation (ω = 0): F = −P 𝔽 v̂ and the moment of that force about the reference."""
    ct, st = math.cos(theta), math.sin(theta)
    fx_, fy_, f = model.fx, model.fy, model.f
    gx, gy = fx_ * ct + f * st, -f * ct + fy_ * st  # 𝔽 v̂ (the force is −𝔽 v̂)
    f_tau = gx * ct + gy * st
    f_n = -gx * st + gy * ct
    xr, yr = model.reference_point
    dx, dy = model.xi_c - xr, model.eta_c - yr  # pressure centroid from the reference point
    c, s = math.cos(phi), math.sin(phi)
    wx, wy = c * dx - s * dy, s * dx + c * dy
    m_paper = wx * gy - wy * gx  # −M with M = (w × (−𝔽v̂))
    return f_tau, f_n, m_paper


def rhs(t, y, model: PaperModel):
    """Right-hand side of the paper's eq. 8 (uniform law) or eq. 13 (linear law).

    Parameters
    ----------
    t : float
        Time t₁ (unused: the system is autonomous).
    y : array_like (6,)
        (x, y, φ, v, ϑ, ω) in the paper's units (eq. 7): lengths in a, v in √(ag/π),
        ω in √(g/(aπ)), t in √(aπ/g).
    model : PaperModel

    Returns
    -------
    ndarray (6,)

    Notes
    -----
    ω < 0 uses the symmetry of the wrench under (v, ω) → (−v, −ω): the components at
    (β = v/|ω|, ϑ + π) with M_Cζ reversed; v < 0 (a trial step of the solver overshooting
    the stop) is the speed |v| in the direction ϑ + π. For |ω| < v/1e7 the motion is a pure
    translation.
    The right-hand side is singular at v = 0 (ϑ̇ = −π F_n/(P v)), as in the paper; see
    :func:`integrate` for a stop event.
    """
    _x, _y, phi, vel, theta, om = (float(q) for q in y)
    speed = abs(vel)
    direction = theta if vel >= 0.0 else theta + math.pi  # a step may overshoot v = 0
    if om != 0.0 and speed < _BIG_BETA * abs(om):
        sgn = 1.0 if om > 0.0 else -1.0
        th = direction if sgn > 0.0 else direction + math.pi
        w = wrench(model, speed / abs(om), th, phi)
        f_tau, f_n, m_paper = w.tangential, w.normal, sgn * w.moment_paper
    else:
        f_tau, f_n, m_paper = _translation(model, direction, phi)
    if vel < 0.0:  # components along (cos ϑ, sin ϑ) = −(direction of motion)
        f_tau, f_n = -f_tau, -f_n
    dth = -math.pi * f_n / vel if vel != 0.0 else 0.0
    return np.array(
        [
            vel * math.cos(theta),
            vel * math.sin(theta),
            om,
            -math.pi * f_tau,
            dth,
            -math.pi * m_paper / _inertia(model),
        ]
    )


@lru_cache(maxsize=32)
def _inertia(model: PaperModel) -> float:
    """I* of a validated model (``__post_init__`` replaces ``None`` by the plate's)."""
    istar = model.inertia_ratio
    assert istar is not None
    return istar


def _uniform_model(kappa, fx, fy, f, inertia_ratio, nodes, i1):
    return PaperModel(kappa, fx, fy, f, inertia_ratio=inertia_ratio, nodes=nodes, i1=i1)


def uniform_rhs(t, y, kappa, fx, fy, f=0.0, inertia_ratio=None, nodes=48, i1="corrected"):
    """The paper's eq. 8 for the uniform law, with the signature ``scipy.integrate.solve_ivp``
    expects (``fun(t, y, *args)``).

    Parameters
    ----------
    t : float
        Time t₁ (paper units).
    y : array_like (6,)
        (x, y, φ, v, ϑ, ω) in paper units (eq. 7).
    kappa, fx, fy, f : float
        κ = b/a and the friction tensor (2).
    inertia_ratio : float or None
        I*; ``None`` is the uniform plate (1 + κ²)/4.
    nodes : int
        Gauss–Legendre points per half of the ξ-interval.
    i1 : {"corrected", "printed"}
        Form of eq. 9's I₁.

    Examples
    --------
    >>> import math
    >>> from scipy.integrate import solve_ivp
    >>> y0 = [0.0, 0.0, math.pi / 2, 1.0, math.pi / 4, 1.0]
    >>> sol = solve_ivp(uniform_rhs, (0.0, 0.1), y0, args=(0.5, 0.42, 0.54), rtol=1e-8)
    >>> sol.status
    0
    """
    return rhs(
        t,
        y,
        _uniform_model(
            float(kappa),
            float(fx),
            float(fy),
            float(f),
            None if inertia_ratio is None else float(inertia_ratio),
            int(nodes),
            str(i1),
        ),
    )


class _StopEvent:
    """``solve_ivp`` event: √(v² + I* ω²) falls through ``level`` (the run's end)."""

    terminal = True
    direction = -1.0

    def __init__(self, istar: float, level: float) -> None:
        self.istar = istar
        self.level = level

    def __call__(self, t, y, _model) -> float:
        return math.sqrt(y[3] ** 2 + self.istar * y[5] ** 2) - self.level


@dataclass(frozen=True)
class SemiAnalyticRun:
    """A motion integrated with ``scipy.integrate.solve_ivp`` on the paper's equations.

    All quantities in the paper's units (eq. 7). ``t_stop`` is the time at which
    s = √(v² + I* ω²) fell below ``stop`` times its initial value (the event), ``beta_stop``
    = v/ω and ``theta_stop`` = ϑ there; ``status`` is solve_ivp's (1: stopped by the event).
    """

    t: np.ndarray
    x: np.ndarray
    y: np.ndarray
    phi: np.ndarray
    v: np.ndarray
    theta: np.ndarray
    omega: np.ndarray
    t_stop: float
    beta_stop: float
    theta_stop: float
    nfev: int
    status: int
    message: str


def integrate(
    model: PaperModel,
    *,
    v0: float = 1.0,
    omega0: float = 1.0,
    theta0: float = math.pi / 4,
    phi0: float = 0.0,
    stop: float = 1e-6,
    rtol: float = 1e-8,
    atol: float = 1e-12,
    method: str = "DOP853",
    t_max: float = 1e3,
) -> SemiAnalyticRun:
    """Integrate the paper's equations (8) or (11)–(13) in time until the body (nearly) stops.

    This is the paper's own route: semi-analytic wrench, a general-purpose ODE solver in the
    physical time, and a cut-off. It is the baseline the regularised compiled integrator of
    :func:`slidespin.simulate` is measured against.

    Parameters
    ----------
    model : PaperModel
    v0, omega0, theta0, phi0 : float
        Initial state in paper units (the paper's runs: v₀ = ω₀ = 1, ϑ₀ = π/4).
    stop : float, default 1e-6
        The run ends when √(v² + I* ω²) falls below ``stop`` times its initial value.
    rtol, atol : float
        Tolerances of ``solve_ivp``.
    method : str, default "DOP853"
        ``solve_ivp`` method.
    t_max : float
        Upper bound of the time span (paper units).
    """
    # lazy: scipy.integrate is slow to import and needed only here
    from scipy.integrate import solve_ivp

    if not isinstance(model, PaperModel):
        raise ValueError(f"model = {model!r} is invalid; valid values: a PaperModel")
    v0 = v.in_range("v0", v0, 0.0, math.inf)
    omega0 = v.finite("omega0", omega0)
    stop = v.in_range("stop", stop, 0.0, 1.0, lo_open=True, hi_open=True)
    istar = _inertia(model)
    s0 = math.sqrt(v0 * v0 + istar * omega0 * omega0)
    if s0 == 0.0:
        raise ValueError("v0 and omega0 are both 0: the body is at rest")

    event = _StopEvent(istar, stop * s0)
    y0 = [0.0, 0.0, v.finite("phi0", phi0), v0, v.finite("theta0", theta0), omega0]
    sol = solve_ivp(
        rhs,
        (0.0, v.positive("t_max", t_max)),
        y0,
        method=method,
        rtol=rtol,
        atol=atol,
        events=event,
        args=(model,),
    )
    yy = sol.y
    beta = yy[3, -1] / yy[5, -1] if yy[5, -1] != 0.0 else math.inf
    t_stop = float(sol.t_events[0][0]) if sol.t_events[0].size else float(sol.t[-1])
    return SemiAnalyticRun(
        t=sol.t,
        x=yy[0],
        y=yy[1],
        phi=yy[2],
        v=yy[3],
        theta=yy[4],
        omega=yy[5],
        t_stop=t_stop,
        beta_stop=float(beta),
        theta_stop=float(yy[4, -1]),
        nfev=int(sol.nfev),
        status=int(sol.status),
        message=str(sol.message),
    )
