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
from typing import TYPE_CHECKING, Any, TypeVar

import numpy as np
from numpy.typing import ArrayLike

from . import _validate as v

if TYPE_CHECKING:
    from .body import Body

_T = TypeVar("_T")

__all__ = [
    "LOAD_FRAMES",
    "Incline",
    "Load",
    "applied_wrench",
    "load_from_table",
    "incline_from_table",
]

#: frames a :class:`Load`'s force may be given in
LOAD_FRAMES = ("plane", "body")

ForceSpec = tuple | Callable[[float], tuple]
TorqueSpec = float | Callable[[float], float]


def _check_pair(
    name: str, value: Any, keys: tuple[str, str] | None = None
) -> tuple[float, float]:  # any value; checked here
    """A pair of finite floats; ``keys`` names the components (e.g. the TOML keys fx, fy)."""
    try:
        items = tuple(value)
    except TypeError:
        raise ValueError(
            f"{name} = {_show(value)} is invalid; valid values: a pair of finite numbers "
            "or a function of time returning one"
        ) from None
    if len(items) != 2:
        raise ValueError(f"{name} = {_show(value)} has {len(items)} components; valid: 2")
    k0, k1 = keys if keys is not None else (f"{name}[0]", f"{name}[1]")
    return (v.finite(k0, _real(items[0])), v.finite(k1, _real(items[1])))


def _show(value: object) -> str:
    """A short repr with NumPy scalars and arrays shown as plain numbers (no np.float64(...))."""
    if isinstance(value, np.ndarray):
        value = value.tolist()
    elif isinstance(value, np.generic):
        value = value.item()
    elif isinstance(value, (tuple, list)):
        value = type(value)(x.item() if isinstance(x, np.generic) else x for x in value)
    return v._short(value)


class _Profile:
    """Samples interpolated linearly in time (constant beyond the ends): the callable that
    :meth:`Load.piecewise_linear` and :meth:`Incline.piecewise_linear` build.

    Its ``times`` (the knots) are where the stick test of :func:`slidespin.simulate` always
    looks: between two knots the profile is affine in t.
    """

    __slots__ = ("times", "columns")

    def __init__(self, times: tuple[float, ...], *columns: tuple[float, ...]) -> None:
        self.times = times
        self.columns = columns

    def __call__(self, t: float) -> Any:
        vals = tuple(_interp(t, self.times, c) for c in self.columns)
        return vals if len(vals) > 1 else vals[0]

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, _Profile):
            return NotImplemented
        return self.times == other.times and self.columns == other.columns

    def __hash__(self) -> int:
        return hash((self.times, self.columns))

    def __repr__(self) -> str:
        return (
            f"<piecewise linear: {len(self.times)} samples over "
            f"[{self.times[0]:.6g}, {self.times[-1]:.6g}] s>"
        )


def _check_times(t: np.ndarray) -> None:
    if t.ndim != 1 or t.size < 2 or not np.all(np.isfinite(t)) or np.any(np.diff(t) <= 0):
        raise ValueError(
            f"times = {_show(np.atleast_1d(t))} is invalid; valid values: "
            "at least 2 finite, strictly increasing times [s]"
        )


def _interp(t: float, tt: tuple[float, ...], vals: tuple[float, ...]) -> float:
    """Linear interpolation, constant beyond the ends, as (1 − w) v₀ + w v₁: never
    overflows for finite samples (np.interp forms the slope, which can)."""
    t = float(t)
    if t <= tt[0]:
        return vals[0]
    if t >= tt[-1]:
        return vals[-1]
    i = int(np.searchsorted(tt, t, side="right")) - 1
    w = (t - tt[i]) / (tt[i + 1] - tt[i])
    return (1.0 - w) * vals[i] + w * vals[i + 1]


def _real(x: object) -> object:
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
                    f"torque = {_show(self.torque)} is invalid; valid values: a finite number "
                    "[N m] or a function of time returning one"
                )
            object.__setattr__(self, "torque", v.finite("torque", _real(self.torque)))
        object.__setattr__(self, "frame", v.choice("frame", self.frame, LOAD_FRAMES))
        if self.at is not None:
            at = _check_pair("at", self.at)
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
        the excursion (:func:`slidespin.loaded.simulate_loaded`, ``scan_step``).

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
        _check_times(t)
        for name, c in zip((nx, ny, nt), cols):
            if c.shape != t.shape or not np.all(np.isfinite(c)):
                raise ValueError(
                    f"{name} = {_show(np.atleast_1d(c))} is invalid; valid "
                    f"values: {t.size} finite numbers, one per time"
                )
        tt, a, b, m = (tuple(float(x) for x in arr) for arr in (t, *cols))
        torque_fn = _Profile(tt, m) if any(m) else 0.0
        return cls(force=_Profile(tt, a, b), torque=torque_fn, frame=frame, at=at)

    @property
    def is_constant(self) -> bool:
        """True when neither the force nor the torque depends on time."""
        return not callable(self.force) and not callable(self.torque)

    @property
    def is_piecewise_linear(self) -> bool:
        """True when force and torque are each constant or built by :meth:`piecewise_linear`
        (affine in t between the :attr:`knots`)."""
        return all(not callable(f) or isinstance(f, _Profile) for f in (self.force, self.torque))

    @property
    def knots(self) -> tuple[float, ...]:
        """Sample times [s] of a :meth:`piecewise_linear` load (empty otherwise)."""
        times: set[float] = set()
        for f in (self.force, self.torque):
            if isinstance(f, _Profile):
                times.update(f.times)
        return tuple(sorted(times))

    def force_at(self, t: float) -> tuple[float, float]:
        """Force (Qx, Qy) [N] in ``frame`` at time t [s]."""
        if callable(self.force):
            return _check_pair(f"force({float(t)!r})", self.force(t))
        return self.force

    def torque_at(self, t: float) -> float:
        """Torque T [N m] at time t [s]."""
        if callable(self.torque):
            return v.finite(f"torque({float(t)!r})", _real(self.torque(t)))
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
            object.__setattr__(self, "angle", _check_angle("angle", self.angle))
        object.__setattr__(self, "downhill", v.finite("downhill", _real(self.downhill)))

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
        _check_times(t)
        if a.shape != t.shape:
            raise ValueError(
                f"{name} = {_show(np.atleast_1d(a))} is invalid; valid values: {t.size} "
                "angles [rad], one per time"
            )
        for x in a:
            _check_angle(name, float(x))
        return cls(_Profile(tuple(float(x) for x in t), tuple(float(x) for x in a)), downhill)

    @property
    def is_constant(self) -> bool:
        """True when the tilt does not depend on time."""
        return not callable(self.angle)

    @property
    def knots(self) -> tuple[float, ...]:
        """Sample times [s] of a :meth:`piecewise_linear` tilt (empty otherwise)."""
        return self.angle.times if isinstance(self.angle, _Profile) else ()

    def angle_at(self, t: float) -> float:
        """Tilt α [rad] at time t [s]."""
        if callable(self.angle):
            return _check_angle(f"angle({float(t)!r})", self.angle(t))
        return self.angle

    def _fixed(self, what: str) -> float:
        if callable(self.angle):
            raise ValueError(
                f"incline = {self!r} has a tilt that varies in time, so it has no single "
                f"{what}; use {what}_at(t), or Incline(incline.angle_at(t)) for the plane at t"
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


def _check_angle(name: str, value: object) -> float:
    """A tilt in [0, π/2) rad; the message says the unit and suggests math.radians."""
    x = v._as_float(name, _real(value))
    if not (math.isfinite(x) and 0.0 <= x < math.pi / 2.0):
        hint = f"; degrees? use math.radians({x:g})" if 1.5707963267948966 <= x < 90.0 else ""
        raise ValueError(
            f"{name} = {x!r} rad is invalid; valid range: [0, 1.5708) rad, i.e. [0, π/2){hint}"
        )
    return x


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


#: keys of a ``[load]`` table in a case file (see :func:`load_from_table`)
LOAD_KEYS = (
    "force",
    "fx",
    "fy",
    "torque",
    "frame",
    "at",
    "times",
    "profile_fx",
    "profile_fy",
    "profile_torque",
)
#: keys of an ``[incline]`` table in a case file (see :func:`incline_from_table`)
INCLINE_KEYS = (
    "angle",
    "angle_deg",
    "downhill",
    "downhill_deg",
    "times",
    "profile_angle",
    "profile_angle_deg",
)


def _table_value(where: str, build: Callable[..., _T], *args: Any, **kwargs: Any) -> _T:
    try:
        return build(*args, **kwargs)
    except ValueError as exc:
        msg = str(exc)
        raise ValueError(msg if msg.startswith("[") else f"[{where}] {msg}") from None


def load_from_table(table: dict, where: str = "load") -> Load:
    """Build a :class:`Load` from a ``[load]`` TOML table; every key is checked.

    A constant load takes ``fx``, ``fy`` [N] (or ``force = [Fx, Fy]``, the name of the
    Python API; not both), ``torque`` [N m], ``frame`` ("plane" or "body") and
    ``at`` = [ξ, η] [m] (body frame, from the patch centre; default G). A load
    varying in time takes ``times`` [s] with ``profile_fx``, ``profile_fy`` [N] and
    optionally ``profile_torque`` [N m] at those times, interpolated linearly
    (:meth:`Load.piecewise_linear`), instead of ``fx``, ``fy``, ``torque``.

    Examples
    --------
    >>> load_from_table({"fx": 2.0, "torque": 0.1}).wrench(0.0)
    (2.0, 0.0, 0.1)
    """
    if not isinstance(table, dict):
        raise ValueError(f"[{where}] must be a table, got {table!r}")
    unknown = sorted(set(table) - set(LOAD_KEYS))
    if unknown:
        raise ValueError(
            f"unknown key {unknown[0]!r} in [{where}]; valid keys: " + ", ".join(sorted(LOAD_KEYS))
        )
    frame = table.get("frame", "plane")
    at = table.get("at")
    if "force" in table:
        both = [k for k in ("fx", "fy") if k in table]
        if both:
            raise ValueError(
                f"[{where}] gives both 'force' and {both[0]!r}; give force = [Fx, Fy] or "
                "fx, fy, not both"
            )
    profile = [k for k in ("times", "profile_fx", "profile_fy", "profile_torque") if k in table]
    if profile:
        constant = [k for k in ("force", "fx", "fy", "torque") if k in table]
        if constant:
            raise ValueError(
                f"[{where}] give either {constant[0]!r} (a constant load) or "
                "times/profile_* (a load varying in time), not both"
            )
        for key in ("times", "profile_fx", "profile_fy"):
            if key not in table:
                raise ValueError(f"[{where}] is missing the required key {key!r} of a profile")
        return _table_value(
            where,
            Load.piecewise_linear,
            table["times"],
            table["profile_fx"],
            table["profile_fy"],
            table.get("profile_torque"),
            frame,
            at,
            names=("profile_fx", "profile_fy", "profile_torque"),
        )
    if "force" in table:
        force = _table_value(where, _check_pair, "force", table["force"])
    else:
        force = _table_value(
            where,
            _check_pair,
            "force",
            (table.get("fx", 0.0), table.get("fy", 0.0)),
            ("fx", "fy"),
        )
    return _table_value(where, Load, force, table.get("torque", 0.0), frame, at)


def incline_from_table(table: dict, where: str = "incline") -> Incline:
    """Build an :class:`Incline` from an ``[incline]`` TOML table (``angle`` or ``angle_deg``,
    ``downhill`` or ``downhill_deg``; radians unless the key ends in ``_deg``).

    A tilt varying in time takes ``times`` [s] with ``profile_angle`` [rad] or
    ``profile_angle_deg`` at those times, interpolated linearly
    (:meth:`Incline.piecewise_linear`), instead of ``angle``.

    Examples
    --------
    >>> incline_from_table({"angle_deg": 30.0}).downhill_factor  # doctest: +ELLIPSIS
    0.4999...
    >>> rising = incline_from_table({"times": [0.0, 10.0], "profile_angle_deg": [0.0, 30.0]})
    >>> round(math.degrees(rising.angle_at(5.0)), 9)
    15.0
    """
    if not isinstance(table, dict):
        raise ValueError(f"[{where}] must be a table, got {table!r}")
    unknown = sorted(set(table) - set(INCLINE_KEYS))
    if unknown:
        raise ValueError(
            f"unknown key {unknown[0]!r} in [{where}]; valid keys: " + ", ".join(INCLINE_KEYS)
        )

    def angle(key, default=None):
        if key in table and f"{key}_deg" in table:
            raise ValueError(f"[{where}] gives both {key} and {key}_deg; give one")
        if f"{key}_deg" in table:
            deg = v.finite(f"[{where}] {key}_deg", _real(table[f"{key}_deg"]))
            if key == "angle" and not 0.0 <= deg < 90.0:
                raise ValueError(
                    f"[{where}] angle_deg = {deg!r} is invalid; valid range: [0, 90) degrees"
                )
            return math.radians(deg)
        if key not in table:
            if default is None:
                raise ValueError(f"[{where}] is missing the required key 'angle' (or angle_deg)")
            return default
        return v.finite(f"[{where}] {key}", _real(table[key]))

    profile = [k for k in ("times", "profile_angle", "profile_angle_deg") if k in table]
    if profile:
        fixed = [k for k in ("angle", "angle_deg") if k in table]
        if fixed:
            raise ValueError(
                f"[{where}] give either {fixed[0]!r} (a fixed tilt) or times/profile_angle "
                "(a tilt varying in time), not both"
            )
        if "times" not in table:
            raise ValueError(f"[{where}] is missing the required key 'times' of a profile")
        if ("profile_angle" in table) == ("profile_angle_deg" in table):
            raise ValueError(
                f"[{where}] give one of 'profile_angle' [rad] or 'profile_angle_deg' with 'times'"
            )
        if "profile_angle_deg" in table:
            deg = _table_value(where, v.real_array, "profile_angle_deg", table["profile_angle_deg"])
            if np.any(deg >= 90.0) or np.any(deg < 0.0):
                raise ValueError(
                    f"[{where}] profile_angle_deg = {_show(deg)} is invalid; valid range: "
                    "[0, 90) degrees"
                )
            angles: Any = np.radians(deg)
            name = "profile_angle_deg (in rad)"
        else:
            angles, name = table["profile_angle"], "profile_angle"
        return _table_value(
            where,
            Incline.piecewise_linear,
            table["times"],
            angles,
            angle("downhill", 0.0),
            name=name,
        )
    return _table_value(where, Incline, angle("angle"), angle("downhill", 0.0))
