"""The plane the body rests on, tilted by an angle that may vary in time (MODEL §11).

On a plane tilted by α whose steepest-descent direction is d = (cos δ, sin δ) in the plane
frame, the normal load is P = m g cos α and gravity adds Q_g = m g sin α d at G. The body is
thin: the tipping moment of friction acting below G is neglected and the pressure law is
unchanged (it scales with P, so the friction wrench and the static-friction set scale by
cos α). Symbols and code names: α → ``Incline.angle`` [rad], δ → ``Incline.downhill`` [rad].
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from slidespin import _validate as v
from slidespin.contact._profile import Profile, as_real, check_angle, check_times, show_value

__all__ = ["Incline"]


@dataclass(frozen=True, slots=True)
class Incline:
    """A plane tilted by ``angle`` whose steepest descent points along ``downhill`` (MODEL §11).

    Parameters
    ----------
    angle : float or callable
        Tilt α of the plane from the horizontal [rad], in [0, π/2) (radians: use
        ``math.radians`` for degrees), or a function ``angle(t)`` of the time t [s]
        returning one (a tilt that grows; see also :meth:`piecewise_linear`).
    downhill : float, default 0
        Direction δ of steepest descent in the plane frame OXY [rad], measured from OX.

    Notes
    -----
    The body is thin: the normal load is P = m g cos α, the pressure law keeps its shape,
    and gravity adds the force m g sin α (cos δ, sin δ) at G. The moment that friction,
    acting in the contact plane below G, exerts about a horizontal axis (tipping) is
    neglected. A tilt varying in time changes both: the static-friction set scales by
    cos α(t) and the pull by sin α(t); the plane turns about a fixed horizontal axis slowly
    enough that its own motion adds no inertial force (quasi-static tilting).

    Examples
    --------
    >>> slope = Incline(math.radians(30.0))
    >>> round(slope.normal_factor, 6), round(slope.downhill_factor, 6)
    (0.866025, 0.5)
    >>> rising = Incline.piecewise_linear([0.0, 10.0], [0.0, math.radians(40.0)])
    >>> round(math.degrees(rising.angle_at(5.0)), 9)
    20.0
    """

    angle: float | Callable[[float], float]
    downhill: float = 0.0

    def __post_init__(self) -> None:
        if not callable(self.angle):
            object.__setattr__(self, "angle", check_angle("angle", self.angle))
        object.__setattr__(self, "downhill", v.finite("downhill", as_real(self.downhill)))

    @classmethod
    def piecewise_linear(
        cls, times: ArrayLike, angles: ArrayLike, downhill: float = 0.0, *, name: str = "angles"
    ) -> Incline:
        """A tilt interpolated linearly between samples, constant beyond the first and last.

        Parameters
        ----------
        times : sequence of float
            Strictly increasing times [s] (at least 2).
        angles : sequence of float
            Tilt α [rad] at those times, each in [0, π/2).
        downhill : float
            Direction δ of steepest descent [rad].
        name : str
            Name of ``angles`` in error messages (a case file's key).

        Notes
        -----
        The stick test looks at every sample time: with no other load (or a constant one)
        the body at rest holds iff tan α(t) is below the threshold, and tan α is monotone
        between samples, so the start of the slip is never missed.
        """
        t = v.real_array("times", times)
        a = v.real_array(name, angles)
        check_times(t)
        if a.shape != t.shape:
            raise ValueError(
                f"{name} = {show_value(np.atleast_1d(a))} is invalid; valid values: {t.size} "
                "angles [rad], one per time"
            )
        for x in a:
            check_angle(name, float(x))
        return cls(Profile(tuple(float(x) for x in t), tuple(float(x) for x in a)), downhill)

    @property
    def is_constant(self) -> bool:
        """True when the tilt does not depend on time."""
        return not callable(self.angle)

    @property
    def knots(self) -> tuple[float, ...]:
        """Sample times [s] of a :meth:`piecewise_linear` tilt (empty otherwise)."""
        return self.angle.times if isinstance(self.angle, Profile) else ()

    def angle_at(self, t: float) -> float:
        """Tilt α [rad] at time t [s]."""
        if callable(self.angle):
            return check_angle(f"angle({float(t)!r})", self.angle(t))
        return self.angle

    def _fixed(self, what: str) -> float:
        if callable(self.angle):
            raise ValueError(
                f"incline = {self!r} has a tilt that varies in time, so it has no single "
                f"{what}; valid here: a fixed tilt (use {what}_at(t), or "
                "Incline(incline.angle_at(t)) for the plane at t)"
            )
        return self.angle

    @property
    def normal_factor(self) -> float:
        """cos α: the normal load is P = m g cos α (a constant tilt)."""
        return math.cos(self._fixed("normal_factor"))

    @property
    def downhill_factor(self) -> float:
        """sin α: gravity pulls m g sin α along the plane (a constant tilt)."""
        return math.sin(self._fixed("downhill_factor"))

    def normal_factor_at(self, t: float) -> float:
        """cos α(t)."""
        return math.cos(self.angle_at(t))

    def downhill_factor_at(self, t: float) -> float:
        """sin α(t)."""
        return math.sin(self.angle_at(t))

    @property
    def direction(self) -> tuple[float, float]:
        """Unit vector of steepest descent (cos δ, sin δ) in the plane frame."""
        return (math.cos(self.downhill), math.sin(self.downhill))

    def gravity_force(
        self, mass: float, g: float = 9.81, t: float | None = None
    ) -> tuple[float, float]:
        """Component of gravity along the plane, m g sin α (cos δ, sin δ) [N] (at time t [s]
        for a tilt that varies in time; ``t`` is required then)."""
        mass = v.bounded("mass", mass, *v.MASS, "kg")
        g = v.bounded("g", g, *v.GRAVITY, "m/s^2")
        if t is None:
            f = mass * g * self.downhill_factor
        else:
            f = mass * g * self.downhill_factor_at(t)
        dx, dy = self.direction
        return (f * dx, f * dy)
