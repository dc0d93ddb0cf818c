"""Applied loads and inclined planes (MODEL §11).

An applied force Q, given in the plane frame OXY or in the body frame Cξη, acts at a body
point r_Q; an applied torque T acts about the vertical. Each may be constant or a function of
time t [s] (a push that ramps up and is released). During slip the Newton–Euler equations of
MODEL §4 become (MODEL §11)

    m dv/dt = F + Q,    I dω/dt = M + T + (R(φ)(r_Q − r_G)) × Q,

with F, M the friction force and moment about G. On a plane tilted by α whose steepest-descent
direction is d = (cos δ, sin δ) in the plane frame, the normal load is P = m g cos α and gravity
adds Q_g = m g sin α d at G. The body is thin: the tipping moment of friction acting below G is
neglected and the pressure law is unchanged (it scales with P, so the friction wrench and the
static-friction set scale by cos α).

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

from . import _validate as v

__all__ = ["LOAD_FRAMES", "Incline", "Load", "applied_wrench"]

LOAD_FRAMES = ("plane", "body")

ForceSpec = tuple | Callable[[float], tuple]
TorqueSpec = float | Callable[[float], float]


def _check_pair(name: str, value) -> tuple[float, float]:
    try:
        items = tuple(value)
    except TypeError:
        raise ValueError(
            f"{name} = {value!r} is invalid; valid values: a pair of finite numbers "
            "or a function of time returning one"
        ) from None
    if len(items) != 2:
        raise ValueError(f"{name} = {value!r} has {len(items)} components; valid: 2")
    return (v.finite(f"{name}[0]", _real(items[0])), v.finite(f"{name}[1]", _real(items[1])))


def _real(x):
    """Plain float for NumPy scalars (numbers.Real rejects none of them, but be explicit)."""
    if isinstance(x, np.generic):
        return x.item()
    return x


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
            object.__setattr__(self, "force", _check_pair("force", self.force))
        if not callable(self.torque):
            if isinstance(self.torque, bool) or not isinstance(_real(self.torque), numbers.Real):
                raise ValueError(
                    f"torque = {self.torque!r} is invalid; valid values: a finite number [N m] "
                    "or a function of time returning one"
                )
            object.__setattr__(self, "torque", v.finite("torque", _real(self.torque)))
        object.__setattr__(self, "frame", v.choice("frame", self.frame, LOAD_FRAMES))
        if self.at is not None:
            object.__setattr__(self, "at", _check_pair("at", self.at))

    @property
    def is_constant(self) -> bool:
        """True when neither the force nor the torque depends on time."""
        return not callable(self.force) and not callable(self.torque)

    def force_at(self, t: float) -> tuple[float, float]:
        """Force (Qx, Qy) [N] in ``frame`` at time t [s]."""
        if callable(self.force):
            return _check_pair(f"force({t!r})", self.force(t))
        return self.force

    def torque_at(self, t: float) -> float:
        """Torque T [N m] at time t [s]."""
        if callable(self.torque):
            return v.finite(f"torque({t!r})", _real(self.torque(t)))
        return self.torque

    def wrench(self, t: float, phi: float = 0.0, mass_centre=(0.0, 0.0)):
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
        return (qx, qy, moment)


@dataclass(frozen=True, slots=True)
class Incline:
    """A plane tilted by ``angle`` whose steepest descent points along ``downhill`` (MODEL §11).

    Parameters
    ----------
    angle : float
        Tilt α of the plane from the horizontal [rad], in [0, π/2).
    downhill : float, default 0
        Direction δ of steepest descent in the plane frame OXY [rad], measured from OX.

    Notes
    -----
    The body is thin: the normal load is P = m g cos α, the pressure law keeps its shape,
    and gravity adds the force m g sin α (cos δ, sin δ) at G. The moment that friction,
    acting in the contact plane below G, exerts about a horizontal axis (tipping) is
    neglected.

    Examples
    --------
    >>> slope = Incline(math.radians(30.0))
    >>> round(slope.normal_factor, 6), round(slope.downhill_factor, 6)
    (0.866025, 0.5)
    """

    angle: float
    downhill: float = 0.0

    def __post_init__(self) -> None:
        a = v.in_range("angle", self.angle, 0.0, math.pi / 2.0, hi_open=True)
        object.__setattr__(self, "angle", a)
        object.__setattr__(self, "downhill", v.finite("downhill", self.downhill))

    @property
    def normal_factor(self) -> float:
        """cos α: the normal load is P = m g cos α."""
        return math.cos(self.angle)

    @property
    def downhill_factor(self) -> float:
        """sin α: gravity pulls m g sin α along the plane."""
        return math.sin(self.angle)

    @property
    def direction(self) -> tuple[float, float]:
        """Unit vector of steepest descent (cos δ, sin δ) in the plane frame."""
        return (math.cos(self.downhill), math.sin(self.downhill))

    def gravity_force(self, mass: float, g: float = 9.81) -> tuple[float, float]:
        """Component of gravity along the plane, m g sin α (cos δ, sin δ) [N]."""
        f = mass * g * self.downhill_factor
        dx, dy = self.direction
        return (f * dx, f * dy)


def applied_wrench(body, t: float, phi: float, load: Load | None = None,
                   incline: Incline | None = None, g: float = 9.81):
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
        gx, gy = incline.gravity_force(body.mass, g)
        qx += gx
        qy += gy
    return (qx, qy, mz)
