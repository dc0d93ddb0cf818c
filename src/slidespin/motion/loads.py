"""Applied loads, and the total applied wrench of loads and a slope (MODEL §11).

An applied force Q, given in the plane frame OXY or in the body frame Cξη, acts at a body
point r_Q; an applied torque T acts about the vertical. Each may be constant or a function of
time t [s] (a push that ramps up and is released). During slip the Newton–Euler equations of
MODEL §4 become (MODEL §11)

    m dv/dt = F + Q,    I dω/dt = M + T + (R(φ)(r_Q − r_G)) × Q,

with F, M the friction force and moment about G. On a plane tilted by α whose steepest-descent
direction is d = (cos δ, sin δ) in the plane frame, the normal load is P = m g cos α and gravity
adds Q_g = m g sin α d at G. The body is thin: the tipping moment of friction acting below G is
neglected and the pressure law is unchanged (it scales with P, so the friction wrench and the
static-friction set scale by cos α). The plane itself is :class:`slidespin.Incline`
(:mod:`slidespin.contact.incline`: the contact's support, below the motion).

Symbols and code names: Q → ``Load.force`` [N], T → ``Load.torque`` [N m], r_Q → ``Load.at``
[m] (body frame, origin at the patch centre C; ``None`` = the mass centre G), α →
``Incline.angle`` [rad], δ → ``Incline.downhill`` [rad].
"""

from __future__ import annotations

import math
import numbers
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from slidespin import _validate as v
from slidespin.contact._profile import Profile, as_real, check_pair, check_times, show_value
from slidespin.contact.body import Body
from slidespin.contact.incline import Incline

__all__ = ["LOAD_FRAMES", "Load", "applied_wrench"]

#: frames a :class:`Load`'s force may be given in
LOAD_FRAMES = ("plane", "body")

ForceSpec = tuple | Callable[[float], tuple]
TorqueSpec = float | Callable[[float], float]


@dataclass(frozen=True, slots=True)
class Load:
    """An applied force and torque on the body, constant or varying in time (MODEL §11).

    Parameters
    ----------
    force : (float, float) or callable
        Applied force Q = (Qx, Qy) [N] in ``frame``, or a function ``force(t)`` of the time
        t [s] returning such a pair.
    torque : float or callable, default 0
        Applied torque T about the vertical [N m], counter-clockwise positive, or a function
        ``torque(t)``.
    frame : {"plane", "body"}, default "plane"
        Whether ``force`` is given in the fixed frame OXY or in the body frame Cξη (then it
        turns with the body: Q_world = R(φ) Q).
    at : (float, float) or None, default None
        Body-frame point r_Q = (ξ, η) [m] where the force acts, measured from the patch
        centre C like every body-frame coordinate; ``None`` means the mass centre G (no
        moment from Q). For every pressure law except the linear one, G = C.

    Notes
    -----
    A callable is evaluated only at the times the integrator asks for; it must be a
    deterministic function of t and return finite values. Its discontinuities (a push
    released suddenly) are handled, but the integrator locates them only to its step
    size; give a continuous ramp where the timing matters.

    Examples
    --------
    >>> Load(force=(2.0, 0.0)).wrench(0.0, phi=0.3, mass_centre=(0.0, 0.0))
    (2.0, 0.0, 0.0)
    >>> ramp = Load(force=lambda t: (min(t, 1.0) * 3.0, 0.0))
    >>> ramp.wrench(0.5)[0]
    1.5
    """

    force: ForceSpec = (0.0, 0.0)
    torque: TorqueSpec = 0.0
    frame: str = "plane"
    at: tuple | None = None

    def __post_init__(self) -> None:
        if not callable(self.force):
            object.__setattr__(self, "force", check_pair("force", self.force))
        if not callable(self.torque):
            if isinstance(self.torque, bool) or not isinstance(as_real(self.torque), numbers.Real):
                raise ValueError(
                    f"torque = {show_value(self.torque)} is invalid; valid values: a finite number "
                    "[N m] or a function of time returning one"
                )
            object.__setattr__(self, "torque", v.finite("torque", as_real(self.torque)))
        object.__setattr__(self, "frame", v.choice("frame", self.frame, LOAD_FRAMES))
        if self.at is not None:
            at = check_pair("at", self.at)
            for i, x in enumerate(at):  # the placement range of footprints (MAX_OFFSET)
                v.symmetric(f"at[{i}]", x, v.LENGTH[1], "m")
            object.__setattr__(self, "at", at)

    @classmethod
    def piecewise_linear(
        cls,
        times: ArrayLike,
        fx: ArrayLike,
        fy: ArrayLike,
        torque: ArrayLike | None = None,
        frame: str = "plane",
        at: tuple[float, float] | None = None,
        *,
        names: tuple[str, str, str] | None = None,
    ) -> Load:
        """A load interpolated linearly between samples, constant beyond the first and last.

        Parameters
        ----------
        times : sequence of float
            Strictly increasing times [s] (at least 2).
        fx, fy : sequence of float
            Force components [N] at those times, in ``frame``.
        torque : sequence of float or None
            Torque [N m] at those times (default 0).
        frame, at
            As in :class:`Load`.
        names : (str, str, str) or None
            Names of ``fx``, ``fy``, ``torque`` in error messages (a case file's keys).

        Notes
        -----
        The stick test of :func:`slidespin.simulate` looks at every sample time (knot): the
        load is affine between knots, and so the gauge of the static-friction set at the
        load is convex there, so a load that leaves the set is always found, however short
        the excursion (:func:`slidespin.motion.loaded.simulate_loaded`, ``scan_step``).

        Examples
        --------
        >>> push = Load.piecewise_linear([0.0, 1.0, 2.0], [0.0, 5.0, 0.0], [0.0, 0.0, 0.0])
        >>> push.force_at(0.5), push.force_at(3.0)
        ((2.5, 0.0), (0.0, 0.0))
        """
        nx, ny, nt = names or ("fx", "fy", "torque")
        t = v.real_array("times", times)
        cols = [v.real_array(name, c) for name, c in ((nx, fx), (ny, fy))]
        cols.append(np.zeros_like(t) if torque is None else v.real_array(nt, torque))
        check_times(t)
        for name, c in zip((nx, ny, nt), cols):
            if c.shape != t.shape or not np.all(np.isfinite(c)):
                raise ValueError(
                    f"{name} = {show_value(np.atleast_1d(c))} is invalid; valid "
                    f"values: {t.size} finite numbers, one per time"
                )
        tt, a, b, m = (tuple(float(x) for x in arr) for arr in (t, *cols))
        torque_fn = Profile(tt, m) if any(m) else 0.0
        return cls(force=Profile(tt, a, b), torque=torque_fn, frame=frame, at=at)

    @property
    def is_constant(self) -> bool:
        """True when neither the force nor the torque depends on time."""
        return not callable(self.force) and not callable(self.torque)

    @property
    def is_piecewise_linear(self) -> bool:
        """True when force and torque are each constant or built by :meth:`piecewise_linear`
        (affine in t between the :attr:`knots`)."""
        return all(not callable(f) or isinstance(f, Profile) for f in (self.force, self.torque))

    @property
    def knots(self) -> tuple[float, ...]:
        """Sample times [s] of a :meth:`piecewise_linear` load (empty otherwise)."""
        times: set[float] = set()
        for f in (self.force, self.torque):
            if isinstance(f, Profile):
                times.update(f.times)
        return tuple(sorted(times))

    def force_at(self, t: float) -> tuple[float, float]:
        """Force (Qx, Qy) [N] in ``frame`` at time t [s]."""
        if callable(self.force):
            return check_pair(f"force({float(t)!r})", self.force(t))
        return self.force

    def torque_at(self, t: float) -> float:
        """Torque T [N m] at time t [s]."""
        if callable(self.torque):
            return v.finite(f"torque({float(t)!r})", as_real(self.torque(t)))
        return self.torque

    def wrench(
        self, t: float, phi: float = 0.0, mass_centre: tuple[float, float] = (0.0, 0.0)
    ) -> tuple[float, float, float]:
        """Applied wrench (Qx, Qy, moment about G) in the fixed frame [N, N, N m].

        Parameters
        ----------
        t : float
            Time [s].
        phi : float
            Body angle φ [rad].
        mass_centre : (float, float)
            G in the body frame [m] (``Body.mass_centre``).
        """
        qx, qy = self.force_at(t)
        c, s = math.cos(phi), math.sin(phi)
        if self.frame == "body":
            qx, qy = c * qx - s * qy, s * qx + c * qy
        moment = self.torque_at(t)
        if self.at is not None:
            dx = self.at[0] - mass_centre[0]
            dy = self.at[1] - mass_centre[1]
            rx, ry = c * dx - s * dy, s * dx + c * dy
            moment += rx * qy - ry * qx
        if not math.isfinite(moment):  # |r| |Q| or T + r × Q beyond the floats
            raise ValueError(
                f"force = ({qx:.6g}, {qy:.6g}) N at at = {self.at!r} m with torque = "
                f"{self.torque_at(t):.6g} N m gives a moment that overflows; valid range: "
                "|torque| + |at - G| |force| below 1.8e308 N m"
            )
        return (qx, qy, moment)


def applied_wrench(
    body: Body,
    t: float,
    phi: float,
    load: Load | None = None,
    incline: Incline | None = None,
    g: float = 9.81,
) -> tuple[float, float, float]:
    """Total applied wrench (Qx, Qy, moment about G) [N, N, N m] of a load and a slope.

    Parameters
    ----------
    body : Body
        The body (mass and mass centre are used).
    t : float
        Time [s].
    phi : float
        Body angle [rad].
    load : Load or None
        Applied force and torque.
    incline : Incline or None
        Tilted plane; adds m g sin α along the downhill direction, at G.
    g : float
        Gravitational acceleration [m/s²].
    """
    qx = qy = mz = 0.0
    if load is not None:
        qx, qy, mz = load.wrench(t, phi, body.mass_centre)
    if incline is not None:
        gx, gy = incline.gravity_force(body.mass, g, None if incline.is_constant else t)
        qx += gx
        qy += gy
    return (qx, qy, mz)
