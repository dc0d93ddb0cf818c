"""Speed-dependent friction laws (MODEL §14): a factor g(|w|) on the friction tensor.

A contact point slipping with velocity w feels the traction τ = −p g(|w|) 𝔽 ŵ: the tensor of
:class:`~slidespin.FrictionTensor` holds the kinetic coefficients, and the law scales the whole
tensor point by point with the local slip speed |w| [m/s]. Three laws:

=================================  ====================================================
law                                g(u), u = |w|
=================================  ====================================================
``PowerLaw(q, v0)``                (u/v0)^(−q), 0 ≤ q < 1 (q = ½: the curling literature's)
``Stribeck(static_ratio, vs, δ)``  1 + (μs/μk − 1) exp(−(u/vs)^δ)    (g(0) = μs/μk, g(∞) = 1)
``SpeedTable(speeds, factors)``    the monotone cubic (PCHIP) through the pairs, held flat
                                   beyond the first and the last speed
=================================  ====================================================

Stribeck's form is MODEL §14's [μk + (μs − μk) exp(−(u/vs)^δ)]/μk. With a law the wrench is
no longer homogeneous of degree 0 in the twist (MODEL §2): it depends on the speeds
themselves. On a line through the instantaneous centre the slip speed is |ω| ρ, which is how
the kernel (:mod:`slidespin.contact._kernel_speed`) integrates it.

Each law has ``factor(speed)`` (NumPy, any shape) and ``kernel_args()``, the (code, parameter
vector) pair the compiled kernel reads (:func:`slidespin.contact._kernel_speed.speed_factor`).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import ClassVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from slidespin import _validate as v

__all__ = ["PowerLaw", "SpeedLaw", "SpeedTable", "Stribeck"]

LAW_POWER, LAW_STRIBECK, LAW_TABLE = 1, 2, 3
#: exponent q of a power law: 0 ≤ q ≤ 0.95 (q → 1 makes the traction at the
#: instantaneous centre non-integrable against the patch's slip speeds)
POWER_Q = (0.0, 0.95)
#: reference and Stribeck speeds [m/s]
LAW_SPEED = (1e-9, 1e6)
#: μs/μk of a Stribeck law and the static ratio of a tensor
STATIC_RATIO = (1.0, 100.0)
#: Stribeck exponent δ
STRIBECK_DELTA = (0.25, 10.0)
#: factors of a speed table
TABLE_FACTOR = (1e-6, 1e6)
#: largest number of pairs of a speed table
TABLE_MAX = 1000


def _speeds(speed: ArrayLike) -> NDArray[np.float64]:
    u = v.real_array("speed", speed, unit="m/s")
    if np.any(u < 0.0):
        raise ValueError(f"speed = {v._short(u)} is invalid; valid range: slip speeds >= 0 m/s")
    return u


@dataclass(frozen=True, slots=True)
class PowerLaw:
    """The power law g = (|w|/v0)^(−q) of the slip speed |w| (MODEL §14).

    Parameters
    ----------
    q : float
        Exponent, in [0, 0.95]; q = ½ is the law the curling literature uses for ice
        (friction falling as |w|^(−½)); q = 0 is the constant law.
    v0 : float, default 1
        Reference speed [m/s] at which the factor is 1, in [1e-9, 1e6].

    Notes
    -----
    The factor grows without bound as |w| → 0 (for q > 0): the traction is still integrable
    over the patch because q < 1. A body at rest is held by the static set of the tensor
    times ``FrictionTensor(static=...)``, not by this law.

    Examples
    --------
    >>> float(PowerLaw(0.5, 1.0).factor(4.0))
    0.5
    """

    q: float
    v0: float = 1.0
    code: ClassVar[int] = LAW_POWER

    def __post_init__(self) -> None:
        object.__setattr__(self, "q", v.bounded("q", self.q, *POWER_Q))
        object.__setattr__(self, "v0", v.bounded("v0", self.v0, *LAW_SPEED, "m/s"))

    @property
    def is_constant(self) -> bool:
        """True if the factor is 1 at every speed (q = 0)."""
        return self.q == 0.0

    def factor(self, speed: ArrayLike) -> NDArray[np.float64]:
        """g(u) at slip speeds ``speed`` [m/s] (≥ 0; +inf at 0 for q > 0)."""
        u = _speeds(speed)
        if self.q == 0.0:
            return np.ones_like(u)
        with np.errstate(divide="ignore"):
            return np.asarray((u / self.v0) ** (-self.q), dtype=float)

    def kernel_args(self) -> tuple[int, NDArray[np.float64]]:
        """(code, parameters) for the compiled kernel: ``LAW_POWER``, (q, v0)."""
        return LAW_POWER, np.array([self.q, self.v0])

    def break_speeds(self) -> NDArray[np.float64]:
        """Speeds [m/s] where the factor changes character (none for a power law)."""
        return np.empty(0)


@dataclass(frozen=True, slots=True)
class Stribeck:
    """The Stribeck law g = 1 + (μs/μk − 1) exp(−(|w|/vs)^δ) (MODEL §14).

    Parameters
    ----------
    static_ratio : float
        μs/μk, the factor at rest, in [1, 100]; the tensor's coefficients are the kinetic
        ones (the factor tends to 1 at high speed). It is also the tensor's static ratio:
        ``FrictionTensor(..., speed_law=Stribeck(1.5, 0.01)).static`` is 1.5.
    vs : float
        Stribeck speed [m/s], in [1e-9, 1e6].
    delta : float, default 2
        Exponent δ, in [0.25, 10] (2: Gaussian; 1: exponential decay).

    Examples
    --------
    >>> round(float(Stribeck(1.5, 0.1).factor(0.1)), 12)  # 1 + 0.5 e^(-1)
    1.183939720586
    """

    static_ratio: float
    vs: float
    delta: float = 2.0
    code: ClassVar[int] = LAW_STRIBECK

    def __post_init__(self) -> None:
        r = v.bounded("static_ratio", self.static_ratio, *STATIC_RATIO)
        object.__setattr__(self, "static_ratio", r)
        object.__setattr__(self, "vs", v.bounded("vs", self.vs, *LAW_SPEED, "m/s"))
        object.__setattr__(self, "delta", v.bounded("delta", self.delta, *STRIBECK_DELTA))

    @property
    def is_constant(self) -> bool:
        """True if the factor is 1 at every speed (μs/μk = 1)."""
        return self.static_ratio == 1.0

    def factor(self, speed: ArrayLike) -> NDArray[np.float64]:
        """g(u) at slip speeds ``speed`` [m/s] (≥ 0)."""
        u = _speeds(speed)
        return 1.0 + (self.static_ratio - 1.0) * np.exp(-((u / self.vs) ** self.delta))

    def kernel_args(self) -> tuple[int, NDArray[np.float64]]:
        """(code, parameters) for the compiled kernel: ``LAW_STRIBECK``, (μs/μk, vs, δ)."""
        return LAW_STRIBECK, np.array([self.static_ratio, self.vs, self.delta])

    def break_speeds(self) -> NDArray[np.float64]:
        """Speeds [m/s] around which the factor falls: vs × 2^k, k = −4 … 3 (the kernel
        splits its radial rule there, so that a narrow fall is resolved)."""
        return self.vs * 2.0 ** np.arange(-4.0, 4.0)


def pchip_slopes(x: NDArray[np.float64], y: NDArray[np.float64]) -> NDArray[np.float64]:
    """The slopes of the monotone piecewise cubic Hermite interpolant (Fritsch–Carlson,
    with the three-point end rule of Fritsch & Butland): where the data turn, the slope is
    0, so the cubic never overshoots them."""
    h = np.diff(x)
    d = np.diff(y) / h
    n = x.size
    m = np.zeros(n)
    if n == 2:
        m[:] = d[0]
        return m
    for k in range(1, n - 1):
        if d[k - 1] * d[k] > 0.0:
            w1 = 2.0 * h[k] + h[k - 1]
            w2 = h[k] + 2.0 * h[k - 1]
            m[k] = (w1 + w2) / (w1 / d[k - 1] + w2 / d[k])
    for k, (h0, h1, d0, d1) in (
        (0, (h[0], h[1], d[0], d[1])),
        (n - 1, (h[-1], h[-2], d[-1], d[-2])),
    ):
        s = ((2.0 * h0 + h1) * d0 - h0 * d1) / (h0 + h1)
        if s * d0 <= 0.0:
            s = 0.0
        elif d0 * d1 <= 0.0 and abs(s) > abs(3.0 * d0):
            s = 3.0 * d0
        m[k] = s
    return m


@dataclass(frozen=True, slots=True)
class SpeedTable:
    """A measured law: factors g at slip speeds, interpolated by a monotone cubic (MODEL §14).

    Parameters
    ----------
    speeds : sequence of float
        Slip speeds [m/s], 2 to 1000 of them, strictly increasing, the first ≥ 0, the last
        ≤ 1e6.
    factors : sequence of float
        The factor g at each speed, in [1e-6, 1e6] (dimensionless: it multiplies the
        tensor's coefficients).

    Notes
    -----
    Between the speeds g is the piecewise cubic Hermite interpolant with Fritsch–Carlson
    slopes (PCHIP, as :class:`scipy.interpolate.PchipInterpolator`): monotone wherever the
    data are, continuous with its first derivative. Below the first speed and above the
    last, g is held at the first and the last factor.

    Examples
    --------
    >>> law = SpeedTable([0.0, 0.1, 1.0], [1.4, 1.1, 1.0])
    >>> float(law.factor(0.1))
    1.1
    """

    speeds: tuple = ()
    factors: tuple = ()
    _slopes: tuple = field(default=(), init=False, repr=False, compare=False)
    code: ClassVar[int] = LAW_TABLE

    def __post_init__(self) -> None:
        s = v.real_array("speeds", self.speeds, unit="m/s")
        f = v.real_array("factors", self.factors)
        if s.ndim != 1 or not 2 <= s.size <= TABLE_MAX:
            raise ValueError(
                f"speeds = {v._short(self.speeds)} is invalid; valid values: a sequence of 2 "
                f"to {TABLE_MAX} speeds [m/s]"
            )
        if f.shape != s.shape:
            raise ValueError(
                f"factors = {v._short(self.factors)} is invalid; valid values: one factor per "
                f"speed ({s.size} of them)"
            )
        if s[0] < 0.0 or s[-1] > LAW_SPEED[1] or np.any(np.diff(s) <= 0.0):
            raise ValueError(
                f"speeds = {v._short(s)} is invalid; valid values: strictly increasing, from "
                f">= 0 to <= {LAW_SPEED[1]:g} m/s"
            )
        bad = (f < TABLE_FACTOR[0]) | (f > TABLE_FACTOR[1])
        if bad.any():
            i = int(np.flatnonzero(bad)[0])
            raise ValueError(
                f"factors[{i}] = {float(f[i])!r} is invalid; valid range: [{TABLE_FACTOR[0]:g}, "
                f"{TABLE_FACTOR[1]:g}]"
            )
        object.__setattr__(self, "speeds", tuple(float(x) for x in s))
        object.__setattr__(self, "factors", tuple(float(x) for x in f))
        object.__setattr__(self, "_slopes", tuple(float(x) for x in pchip_slopes(s, f)))

    @property
    def is_constant(self) -> bool:
        """True if every factor is 1."""
        return all(x == 1.0 for x in self.factors)

    def factor(self, speed: ArrayLike) -> NDArray[np.float64]:
        """g(u) at slip speeds ``speed`` [m/s] (≥ 0)."""
        u = _speeds(speed)
        s = np.array(self.speeds)
        f = np.array(self.factors)
        m = np.array(self._slopes)
        uc = np.clip(u, s[0], s[-1])
        k = np.clip(np.searchsorted(s, uc, side="right") - 1, 0, s.size - 2)
        h = s[k + 1] - s[k]
        t = (uc - s[k]) / h
        h00 = (1.0 + 2.0 * t) * (1.0 - t) ** 2
        h10 = t * (1.0 - t) ** 2
        h01 = t * t * (3.0 - 2.0 * t)
        h11 = t * t * (t - 1.0)
        return np.asarray(h00 * f[k] + h10 * h * m[k] + h01 * f[k + 1] + h11 * h * m[k + 1])

    def kernel_args(self) -> tuple[int, NDArray[np.float64]]:
        """(code, parameters) for the compiled kernel: ``LAW_TABLE``, (n, speeds, factors,
        slopes)."""
        n = len(self.speeds)
        return LAW_TABLE, np.concatenate(([float(n)], self.speeds, self.factors, self._slopes))

    def break_speeds(self) -> NDArray[np.float64]:
        """The table's speeds [m/s]: the cubic's second derivative jumps there."""
        return np.array(self.speeds)


#: the speed-dependent laws a :class:`~slidespin.FrictionTensor` takes
SpeedLaw = PowerLaw | Stribeck | SpeedTable


def check_speed_law(law: object) -> None:
    """A ``ValueError`` naming ``speed_law`` unless it is None or one of the three laws."""
    if law is not None and not isinstance(law, (PowerLaw, Stribeck, SpeedTable)):
        raise ValueError(
            f"speed_law = {v._short(law)} is invalid; valid values: None (the constant law), "
            "PowerLaw(q, v0), Stribeck(static_ratio, vs, delta) or SpeedTable(speeds, factors)"
        )


def law_is_constant(law: object) -> bool:
    """True for None and for a law whose factor is 1 everywhere."""
    return law is None or bool(law.is_constant)  # type: ignore[attr-defined]
