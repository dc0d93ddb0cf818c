"""Loads that depend on the state: a spring (and dashpot) to a moving anchor (MODEL §14).

A :class:`Spring` joins a body point r_S (``at``, body frame, measured from the patch centre
C like every body-frame coordinate) to an anchor a(t) that moves on a prescribed path in the
plane: the spring–block tribometer, a sled pulled on a rope, a puck on a leash. With
d = p_S − a(t) (p_S the point's position in the plane) and its rate ḋ = v_S − ȧ(t),

    Q = −k d − c ḋ                                    (rest length L₀ = 0),
    Q = −[k (|d| − L₀) + c ḋ·d̂] d̂                     (L₀ > 0: along the spring only),

at p_S, so its moment about G is (R(φ)(r_S − r_G)) × Q. The anchor's path is a table of
rows (t, x, y), linear between rows and held at the first and last (a drive at constant
speed V is two rows, (0, x₀, y₀) and (T, x₀ + V T, y₀)); ȧ is the slope of the segment.

A spring enters a loaded run (:func:`slidespin.motion.loaded.simulate_loaded`, through
``simulate(..., load=...)``) alone or in a list with :class:`~slidespin.Load` objects: the run
takes the Python path, which evaluates the spring at the state during slip and at the pose
where the body sticks (where the force changes only as the anchor moves).
"""

from __future__ import annotations

import bisect
import math
from dataclasses import dataclass, field

import numpy as np

from slidespin import _validate as v
from slidespin.contact.body import Body
from slidespin.contact.incline import Incline
from slidespin.motion.loads import MAX_KNOTS, Load, applied_wrench

__all__ = ["LoadSum", "Spring", "applied_wrench_state", "has_springs", "split_loads"]

#: stiffness [N/m] and damping [N s/m] ranges
STIFFNESS = (1e-9, 1e12)
DAMPING_MAX = 1e12


def _pair(name: str, value: object) -> tuple[float, float]:
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        arr = np.array([math.nan])
    if arr.shape != (2,) or not np.all(np.isfinite(arr)) or isinstance(value, (str, bytes)):
        raise ValueError(
            f"{name} = {v._short(value)} is invalid; valid values: a pair (xi, eta) of finite "
            "numbers [m]"
        )
    return float(arr[0]), float(arr[1])


@dataclass(frozen=True, slots=True)
class Spring:
    """A linear spring (and dashpot) from a body point to an anchor on a prescribed path.

    Parameters
    ----------
    stiffness : float
        Spring rate k [N/m], in [1e-9, 1e12].
    anchor_path : array_like, shape (n, 3)
        Rows (t [s], x [m], y [m]) of the anchor in the plane frame, 1 to 10⁶ of them, times
        strictly increasing; linear between rows, held beyond the first and the last. One
        row is a fixed anchor.
    at : (float, float), default (0, 0)
        The body point r_S where the spring is attached, in the body frame [m] (from the
        patch centre C), at G's height: on a tall body (``Body(..., height=h)``) the
        spring's pull does not tilt the body (MODEL §14; put a ``Load`` with ``height``
        for a force applied above or below G).
    damping : float, default 0
        Dashpot rate c [N s/m], in [0, 1e12].
    rest_length : float, default 0
        Unstretched length L₀ [m], ≥ 0; with L₀ > 0 spring and dashpot act along the spring
        only.

    Examples
    --------
    >>> drive = Spring(200.0, [(0.0, 0.0, 0.0), (10.0, 0.5, 0.0)])  # pulled at 5 cm/s
    >>> drive.anchor(4.0)
    (0.2, 0.0)
    >>> drive.force(1.0, (0.0, 0.0), (0.0, 0.0))  # the anchor 5 cm ahead pulls with 10 N
    (10.0, 0.0)
    """

    stiffness: float
    anchor_path: tuple = ()
    at: tuple = (0.0, 0.0)
    damping: float = 0.0
    rest_length: float = 0.0
    _times: tuple = field(default=(), init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        object.__setattr__(
            self, "stiffness", v.bounded("stiffness", self.stiffness, *STIFFNESS, "N/m")
        )
        object.__setattr__(
            self, "damping", v.bounded("damping", self.damping, 0.0, DAMPING_MAX, "N s/m")
        )
        object.__setattr__(
            self, "rest_length", v.bounded("rest_length", self.rest_length, 0.0, 1e6, "m")
        )
        object.__setattr__(self, "at", _pair("at", self.at))
        rows = v.real_array("anchor_path", self.anchor_path)
        if rows.ndim == 1 and rows.size == 3:
            rows = rows[None, :]
        if rows.ndim != 2 or rows.shape[1] != 3 or not 1 <= rows.shape[0] <= MAX_KNOTS:
            raise ValueError(
                f"anchor_path = {v._short(self.anchor_path)} is invalid; valid values: rows "
                f"(t [s], x [m], y [m]), 1 to {MAX_KNOTS} of them"
            )
        if np.any(np.diff(rows[:, 0]) <= 0.0):
            i = int(np.flatnonzero(np.diff(rows[:, 0]) <= 0.0)[0])
            raise ValueError(
                f"anchor_path rows {i} and {i + 1} have times {rows[i, 0]!r} and "
                f"{rows[i + 1, 0]!r} s; valid values: strictly increasing times"
            )
        object.__setattr__(self, "anchor_path", tuple(tuple(float(x) for x in r) for r in rows))
        object.__setattr__(self, "_times", tuple(float(x) for x in rows[:, 0]))

    def _segment(self, t: float) -> tuple[float, float, float, float]:
        """(x, y, ẋ, ẏ) of the anchor at time t [s]."""
        rows, times = self.anchor_path, self._times
        if len(rows) == 1 or t <= times[0]:
            return rows[0][1], rows[0][2], 0.0, 0.0
        if t >= times[-1]:
            return rows[-1][1], rows[-1][2], 0.0, 0.0
        i = bisect.bisect_right(times, t) - 1
        (t0, x0, y0), (t1, x1, y1) = rows[i], rows[i + 1]
        w = (t - t0) / (t1 - t0)
        return (
            (1.0 - w) * x0 + w * x1,
            (1.0 - w) * y0 + w * y1,
            (x1 - x0) / (t1 - t0),
            (y1 - y0) / (t1 - t0),
        )

    def anchor(self, t: float) -> tuple[float, float]:
        """The anchor's position (x, y) [m] at time t [s]."""
        x, y, _, _ = self._segment(float(t))
        return (x, y)

    @property
    def knots(self) -> tuple[float, ...]:
        """The times [s] of the anchor's path."""
        return self._times

    def force(
        self,
        t: float,
        point: tuple[float, float],
        point_velocity: tuple[float, float],
    ) -> tuple[float, float]:
        """The force Q [N] on the body at the attachment point at ``point`` [m], moving with
        ``point_velocity`` [m/s], at time t [s] (module notes)."""
        ax, ay, avx, avy = self._segment(float(t))
        dx, dy = point[0] - ax, point[1] - ay
        ddx, ddy = point_velocity[0] - avx, point_velocity[1] - avy
        k, c, rest = self.stiffness, self.damping, self.rest_length
        if rest == 0.0:
            return (-k * dx - c * ddx, -k * dy - c * ddy)
        length = math.hypot(dx, dy)
        if length == 0.0:
            return (0.0, 0.0)  # no direction: a spring at zero length pushes nowhere
        ux, uy = dx / length, dy / length
        mag = k * (length - rest) + c * (ddx * ux + ddy * uy)
        return (-mag * ux, -mag * uy)

    def wrench(
        self,
        t: float,
        x: float,
        y: float,
        phi: float,
        vx: float = 0.0,
        vy: float = 0.0,
        omega: float = 0.0,
        mass_centre: tuple[float, float] = (0.0, 0.0),
    ) -> tuple[float, float, float]:
        """(Qx, Qy, moment about G) [N, N, N m] with the body's G at (x, y) [m], angle φ
        [rad], velocity (vx, vy) [m/s] of G and spin ω [rad/s], at time t [s]."""
        c, s = math.cos(phi), math.sin(phi)
        dx, dy = self.at[0] - mass_centre[0], self.at[1] - mass_centre[1]
        rx, ry = c * dx - s * dy, s * dx + c * dy
        qx, qy = self.force(t, (x + rx, y + ry), (vx - omega * ry, vy + omega * rx))
        return (qx, qy, rx * qy - ry * qx)


def split_loads(load: object) -> tuple[Load | LoadSum | None, tuple[Spring, ...]]:
    """(the time-dependent loads as one :class:`~slidespin.Load` or None, the springs) of a
    ``load=`` argument: a Load, a Spring, or a list or tuple of them. Several Loads are
    summed (:class:`LoadSum`)."""
    items: list = list(load) if isinstance(load, (list, tuple)) else [load]
    loads, springs = [], []
    for i, item in enumerate(items):
        if isinstance(item, Load):
            loads.append(item)
        elif isinstance(item, Spring):
            springs.append(item)
        else:
            where = "" if len(items) == 1 and not isinstance(load, (list, tuple)) else f"[{i}]"
            raise ValueError(
                f"load{where} = {v._short(item)} is invalid; valid values: a slidespin.Load, "
                "a slidespin.Spring, or a list of them"
            )
    if not loads:
        return None, tuple(springs)
    if len(loads) == 1:
        return loads[0], tuple(springs)
    return LoadSum(tuple(loads)), tuple(springs)


@dataclass(frozen=True)
class LoadSum:
    """Several :class:`~slidespin.Load` objects acting together (their wrenches add)."""

    loads: tuple

    @property
    def is_constant(self) -> bool:
        """True when every load is constant."""
        return all(ld.is_constant for ld in self.loads)

    @property
    def is_piecewise_linear(self) -> bool:
        """False: there is no single table of several loads (the Python path runs them)."""
        return False

    @property
    def knots(self) -> tuple[float, ...]:
        """The union of the loads' sample times [s]."""
        return tuple(sorted({t for ld in self.loads for t in ld.knots}))

    def raised_force(self, t: float, phi: float, height: float) -> tuple[float, float]:
        """The sum of the loads' (h − h_Q) Q [N m] (:meth:`slidespin.Load.raised_force`)."""
        rx = ry = 0.0
        for ld in self.loads:
            a, b = ld.raised_force(t, phi, height)
            rx, ry = rx + a, ry + b
        return (rx, ry)

    def wrench(
        self, t: float, phi: float = 0.0, mass_centre: tuple[float, float] = (0.0, 0.0)
    ) -> tuple[float, float, float]:
        """The sum of the loads' wrenches (Qx, Qy, moment about G) [N, N, N m]."""
        qx = qy = m = 0.0
        for ld in self.loads:
            a, b, c = ld.wrench(t, phi, mass_centre)
            qx, qy, m = qx + a, qy + b, m + c
        return (qx, qy, m)


def has_springs(load: object) -> bool:
    """True if a ``load=`` argument holds a :class:`Spring`."""
    items = load if isinstance(load, (list, tuple)) else [load]
    return any(isinstance(item, Spring) for item in items)


def applied_wrench_state(
    body: Body,
    t: float,
    state: tuple[float, float, float, float, float, float],
    load: object = None,
    incline: Incline | None = None,
    g: float = 9.81,
) -> tuple[float, float, float]:
    """Total applied wrench (Qx, Qy, moment about G) [N, N, N m] of loads, springs and a
    slope, with the body in ``state`` = (x, y, φ, vx, vy, ω) (SI) at time t [s]; ``load``
    as ``simulate``'s (a Load, a Spring, a list of them, or None)."""
    x, y, phi, vx, vy, om = state
    qx, qy, mz = applied_wrench(body, t, phi, None, incline, g)
    if load is None:
        return (qx, qy, mz)
    time_load, springs = split_loads(load)
    if time_load is not None:
        a, b, c = time_load.wrench(t, phi, body.mass_centre)
        qx, qy, mz = qx + a, qy + b, mz + c
    for spring in springs:
        a, b, c = spring.wrench(t, x, y, phi, vx, vy, om, body.mass_centre)
        qx, qy, mz = qx + a, qy + b, mz + c
    return (qx, qy, mz)
