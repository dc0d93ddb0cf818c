"""The inertia intervals of a round patch: the paper's appendix Table 2 (MODEL §6–7).

For a circular patch under orthotropic friction (f = 0, μ = fy − fx ≥ 0) the terminal velocity
runs along the low-friction axis (ϑ* = 0) and the terminal ratio β = v/(a ω) solves
J(β) = I*, with J(β) = β M_Cζ/F_τ (eq. 15–16 solved for I*). The inertia ratios I₁ < I₂ < I₃
at which the ending changes are J(∞), J(1) and J(0⁺).

:func:`inertia_intervals`
    I₁, I₂, I₃ computed from J (also for a centred disk or ring, MODEL §10).
:func:`paper_inertia_intervals`
    The formulas printed in the paper's Table 2 (erratum 9 restored).
:func:`inertia_for_ratio`, :func:`circle_terminal_ratio`
    J(β) and its inverse, the terminal ratio of a given I*.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import brentq

from slidespin import _validate as v
from slidespin.analysis._natural import _WRENCH_TOL, _fp_world, _missed, _params
from slidespin.contact import _engine
from slidespin.contact._kernel_ellipse import STATUS_OK, wrench_array
from slidespin.contact.body import Body
from slidespin.contact.ellipse import Ellipse
from slidespin.contact.friction import FrictionTensor
from slidespin.contact.pressure import (
    BoussinesqPressure,
    HertzPressure,
    LinearPressure,
    PressureLaw,
    UniformPressure,
)
from slidespin.contact.pressure_map import symmetry
from slidespin.contact.shapes import Annulus, Disk, is_footprint

__all__ = [
    "inertia_intervals",
    "paper_inertia_intervals",
    "InertiaIntervals",
    "inertia_for_ratio",
    "circle_terminal_ratio",
]


class InertiaIntervals(NamedTuple):
    """Boundaries I₁ < I₂ < I₃ of the dimensionless inertia I* = I/(m a²) (paper Table 2).

    I* in (0, I₁): the spin dies first (ω/v → 0, ``pure_sliding``); (I₁, I₂): v = k a ω with
    k > 1; (I₂, I₃): k < 1 (both ``mixed``); (I₃, ∞): the sliding dies first (v/ω → 0,
    ``pure_spinning``).
    """

    i1: float
    i2: float
    i3: float

    def regime(self, inertia_ratio: float) -> int:
        """Row of Table 2 (1–4) that contains ``inertia_ratio``."""
        x = v.positive("inertia_ratio", inertia_ratio)
        return 1 + int(x > self.i1) + int(x > self.i2) + int(x > self.i3)

    def ending(self, inertia_ratio: float) -> str:
        """Ending for ``inertia_ratio``: ``pure_sliding``, ``mixed`` or ``pure_spinning``."""
        return {1: "pure_sliding", 2: "mixed", 3: "mixed", 4: "pure_spinning"}[
            self.regime(inertia_ratio)
        ]


_TABLE2_LAWS = (UniformPressure, BoussinesqPressure, HertzPressure)


def _check_table2(pressure, friction):
    if isinstance(pressure, LinearPressure):
        if pressure.centroid != (0.0, 0.0):
            raise ValueError(
                f"pressure = {pressure!r} is invalid for Table 2; valid values: a law "
                "symmetric about the centre (UniformPressure(), BoussinesqPressure(), "
                "HertzPressure(), or LinearPressure(0, 0))"
            )
    elif not isinstance(pressure, _TABLE2_LAWS):
        raise ValueError(
            f"pressure = {pressure!r} is invalid; valid values: UniformPressure(), "
            "BoussinesqPressure(), HertzPressure()"
        )
    if not isinstance(friction, FrictionTensor):
        raise ValueError(f"friction = {friction!r} is invalid; valid values: a FrictionTensor")
    if friction.f != 0.0:
        raise ValueError(
            f"friction.f = {friction.f!r} is invalid for Table 2; valid range: 0 (orthotropic "
            "friction, paper eq. 17)"
        )
    if friction.angle != 0.0:
        raise ValueError(
            f"friction.angle = {friction.angle!r} is invalid for Table 2; valid range: 0 "
            "(principal axes along OX, OY)"
        )
    if friction.mu < 0.0:
        raise ValueError(
            f"mu = fy - fx = {friction.mu!r} is invalid for Table 2; valid range: >= 0 "
            "(fx is the lower coefficient; swap fx and fy)"
        )


def _circle_params(pressure, friction, patch=None):
    """Engine parameters of the round patch of Table 2 in units of its radius: the paper's
    circle (the unit ellipse with a = b, on the elliptic engine, as in the paper), or a
    centred Disk or Annulus (scaled to outer radius 1)."""
    if patch is None:
        body = Body(Ellipse(1.0, 1.0), pressure, 1.0)
        return _params(body, friction)
    if isinstance(patch, Disk) and not Body(patch, pressure, 1.0).is_footprint:
        # a Disk under Boussinesq or Hertz pressure is a circle for the engine (G at its centre)
        return _params(Body(Ellipse(1.0, 1.0), pressure, 1.0), friction)
    ok = isinstance(patch, Annulus) and is_footprint(patch)
    if ok:
        ring = Annulus(patch.inner_radius / patch.outer_radius, 1.0)
        body = Body(ring, pressure, 1.0)
        ok = symmetry(ring, pressure)[1] and patch.centre == (0.0, 0.0)
    if not ok:
        raise ValueError(
            f"patch = {patch!r} is invalid for Table 2; valid values: None or a Circle, or a "
            "centred Disk or Annulus under uniform pressure (an axisymmetric footprint), or a "
            "Disk under Boussinesq or Hertz pressure"
        )
    return _params(body, friction)


def _j_values(par, beta):
    """J(β) = β M_Cζ/F_τ at ϑ = 0, φ = 0, ω = 1 for an array of β (units of a)."""
    beta = np.ascontiguousarray(np.ravel(beta), dtype=float)
    n = beta.size
    if getattr(par, "fp", None) is not None:
        fx, fy, m = _fp_world(par, np.zeros(n), beta, np.zeros(n), np.ones(n))
        return beta * (-m) / (-fx)
    fx, fy, m, st = wrench_array(
        *_engine.elliptic_args(par),
        np.zeros(n),
        beta,
        np.zeros(n),
        np.ones(n),
        _WRENCH_TOL,
    )
    if (st != STATUS_OK).any() or not np.all(np.isfinite(fx + fy + m)):
        raise RuntimeError(_missed(par))  # pragma: no cover - guard
    return beta * (-m) / (-fx)


def inertia_for_ratio(
    pressure: PressureLaw,
    friction: FrictionTensor,
    ratio: ArrayLike,
    patch: Annulus | None = None,
) -> float | NDArray[np.float64]:
    """J(β): the inertia ratio I* whose terminal ratio is β = v/(a ω) (circle, MODEL §6).

    Parameters
    ----------
    pressure : UniformPressure, BoussinesqPressure or HertzPressure
        Pressure law on the circular patch.
    friction : FrictionTensor
        Orthotropic tensor (f = 0, angle 0) with fx ≤ fy; the terminal velocity is along the
        low-friction axis OX (ϑ* = 0).
    ratio : float or array_like
        β/a = v/(a ω), in [1e-9, 1e9].
    patch : Circle, Disk or Annulus, optional
        The round patch (default a circle); a centred ``Annulus`` under uniform pressure
        gives the ring's J(β), with a its outer radius.

    Returns
    -------
    float or ndarray
        J(β) = β M_Cζ(β)/F_τ(β) at ϑ = 0 (eq. 15–16 solved for I*).
    """
    _check_table2(pressure, friction)
    arr = v.real_array("ratio", ratio, *v.RATIO)
    out = _j_values(_circle_params(pressure, friction, patch), arr).reshape(arr.shape)
    return float(out) if out.ndim == 0 else out


def _richardson(values, factor):
    """Two Richardson steps for an expansion in h², h⁴ sampled at h, h/q, h/q² (q = factor)."""
    j0, j1, j2 = values
    q2 = factor * factor
    r1 = (q2 * j1 - j0) / (q2 - 1.0)
    r2 = (q2 * j2 - j1) / (q2 - 1.0)
    q4 = q2 * q2
    return (q4 * r2 - r1) / (q4 - 1.0)


def inertia_intervals(
    pressure, friction: FrictionTensor, patch: Annulus | None = None
) -> InertiaIntervals:
    """Boundaries (I₁, I₂, I₃) of Table 2, computed numerically from J(β) (MODEL §6).

    Parameters
    ----------
    pressure : UniformPressure, BoussinesqPressure, HertzPressure or Body
        Pressure law on a circular patch; or a ``Body`` on a circle, disk or centred ring
        (its law and patch are used; ``patch`` must then be None).
    friction : FrictionTensor
        Orthotropic friction (f = 0, principal axes along OX, OY) with μ = fy − fx ≥ 0.
    patch : Circle, Disk or Annulus, optional
        The round patch: a circle by default; a centred ``Annulus(r, R)`` (or ``Disk``)
        under uniform pressure gives the ring's boundaries, with I* = I/(m R²). For isotropic
        friction they are I₁ = (R² + r²)/(4R²), I₃ = (2/3)(R² + Rr + r²)/R² (from the
        small- and large-β limits of the wrench), and a thin ring has I₂ → 1 (MODEL §10).

    Returns
    -------
    InertiaIntervals
        I₁ = J(∞), I₂ = J(1), I₃ = J(0⁺).

    Notes
    -----
    J(β) = β M_Cζ/F_τ at ϑ = 0 is evaluated with the compiled wrench (absolute error 1e-13).
    J(β) − I₁ = O(β⁻²) and J(β) − I₃ = O(β²), so both limits are Richardson-extrapolated
    from β = 100, 200, 400 and β = 1e-2, 5e-3, 2.5e-3 (error below 1e-10). The paper's
    appendix gives closed forms (:func:`paper_inertia_intervals`); no formula is used here.

    Examples
    --------
    >>> from slidespin import UniformPressure, FrictionTensor
    >>> [round(x, 6) for x in inertia_intervals(UniformPressure(), FrictionTensor(0.3, 0.3))]
    [0.25, 0.333333, 0.666667]
    """
    if isinstance(pressure, Body):  # inertia_intervals(body, friction), like its siblings
        if patch is not None:
            raise ValueError(
                f"patch = {patch!r} is invalid with a Body; valid values: None (the body's "
                "own patch)"
            )
        body = pressure
        pressure, patch = body.pressure, body.patch  # type: ignore[assignment]
    _check_table2(pressure, friction)
    par = _circle_params(pressure, friction, patch)
    big = _j_values(par, np.array([100.0, 200.0, 400.0]))
    small = _j_values(par, np.array([1e-2, 5e-3, 2.5e-3]))
    i2 = float(_j_values(par, np.array([1.0]))[0])
    return InertiaIntervals(float(_richardson(big, 2.0)), i2, float(_richardson(small, 2.0)))


def paper_inertia_intervals(pressure: PressureLaw, friction: FrictionTensor) -> InertiaIntervals:
    """Boundaries (I₁, I₂, I₃) from the formulas printed in the paper's Table 2.

    ======================  ==================  ======================  ================
    law                     I₁                  I₂                      I₃
    ======================  ==================  ======================  ================
    uniform                 (fx+μ)/(4fx)        (5fx+4μ)/(15fx)         (2fx+μ)/(3fx)
    Boussinesq              (fx+μ)/(3fx)        (4fx+3μ)/(8fx)          (2fx+μ)/(2fx)
    Hertz                   (fx+μ)/(5fx)        (6fx+5μ)/(24fx)         (2fx+μ)/(4fx)
    ======================  ==================  ======================  ================

    Notes
    -----
    The uniform law's row 1 is printed "(0, (fx+μ)) / (4fx)"; the parenthesis is restored
    here (MODEL §7, erratum 9).
    """
    _check_table2(pressure, friction)
    fx, mu = friction.fx, friction.mu
    if isinstance(pressure, (UniformPressure, LinearPressure)):
        vals = ((fx + mu) / (4 * fx), (5 * fx + 4 * mu) / (15 * fx), (2 * fx + mu) / (3 * fx))
    elif isinstance(pressure, BoussinesqPressure):
        vals = ((fx + mu) / (3 * fx), (4 * fx + 3 * mu) / (8 * fx), (2 * fx + mu) / (2 * fx))
    else:
        vals = ((fx + mu) / (5 * fx), (6 * fx + 5 * mu) / (24 * fx), (2 * fx + mu) / (4 * fx))
    return InertiaIntervals(*vals)


def circle_terminal_ratio(
    pressure: PressureLaw,
    friction: FrictionTensor,
    inertia_ratio: float,
    patch: Annulus | None = None,
) -> float:
    """Terminal ratio k = v/(a ω) of a circular patch with inertia ratio I* (J⁻¹, MODEL §6).

    Returns ``inf`` for I* ≤ I₁ (pure sliding) and ``0.0`` for I* ≥ I₃ (pure spinning);
    otherwise the root of J(k) = I*, along the low-friction axis (ϑ* = 0). ``inertia_ratio``
    must lie in [1e-8, 1e8], the range of :class:`slidespin.Body`. ``patch``: as in
    :func:`inertia_intervals` (a centred ring gives v/(R ω)).

    Examples
    --------
    >>> from slidespin import UniformPressure, FrictionTensor
    >>> round(circle_terminal_ratio(UniformPressure(), FrictionTensor(0.2, 0.2), 0.5), 3)
    0.653
    """
    _check_table2(pressure, friction)
    i_star = v.bounded("inertia_ratio", inertia_ratio, *v.INERTIA_RATIO)
    par = _circle_params(pressure, friction, patch)

    def g(log_beta):
        return float(_j_values(par, np.array([math.exp(log_beta)]))[0]) - i_star

    lo, hi = math.log(1e-7), math.log(1e7)
    glo, ghi = g(lo), g(hi)
    if glo <= 0.0:
        return 0.0
    if ghi >= 0.0:
        return math.inf
    return math.exp(brentq(g, lo, hi, xtol=1e-14, rtol=1e-15, maxiter=300))
