"""Pushers: a finger (a point) and a flat edge (a segment) moved along a prescribed path (MODEL §13).

A pusher prescribes a motion and the contact decides the force. Both pushers here are frozen
value objects, validated on construction, that say where the pusher is and how fast it moves
at any time; what the body does is the business of the quasi-static and dynamic pushing
engines (:mod:`slidespin.motion.quasi_static`, :mod:`slidespin.motion.pushed`), and the
body's outline that the pusher touches is :mod:`slidespin.contact.outline`.

MODEL §13 symbols and code names:

=========  ===============================================  ==============================
MODEL      meaning                                          code
=========  ===============================================  ==============================
p(t)       the finger's position in the plane frame OXY     :meth:`PointPusher.position`
ṗ(t)       its velocity                                     :meth:`PointPusher.velocity`
μp         the pusher–body Coulomb coefficient              ``mu``
(c, θ)     a line pusher's centre and direction             :meth:`LinePusher.pose`
L          a line pusher's length                           ``length``
=========  ===============================================  ==============================

Both paths are **piecewise linear in time** between their rows (waypoints), and the pusher
is held at its first row before the first time and at its last row after the last time (zero
velocity there). The velocity is right-continuous: at a waypoint time t_i it is the velocity
of the segment [t_i, t_{i+1}) that starts there. :attr:`~PointPusher.knots` lists the times
where the velocity jumps, where an integrator must stop and restart.

Every bad input raises a one-line ``ValueError`` that names the parameter, its value and the
valid range, before any work: bools are not numbers, NaN and infinities are refused, times
must increase strictly, each segment's speed must stay within 10⁸ m/s (a line pusher's turn
rate within 10¹² rad/s: the ranges of :class:`slidespin.State`), and rows must have the
right length.
"""

from __future__ import annotations

import numbers
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike, NDArray

from slidespin import _validate as v
from slidespin.contact.motion_cone import pusher_mu

__all__ = ["LinePusher", "MAX_WAYPOINTS", "PointPusher"]

#: most rows of a pusher's path (each is kept in memory, and an integrator stops at every knot)
MAX_WAYPOINTS = 1_000_000


# ------------------------------------------------------------------------------------------
# validation


def _no_bools(name: str, value: object) -> None:
    """Refuse bools among the rows: ``[[0, True, 1]]`` would otherwise read as ``[[0, 1, 1]]``."""
    if isinstance(value, np.ndarray):
        if value.dtype.kind == "b" or (
            value.dtype.kind == "O"
            and any(isinstance(x, (bool, np.bool_)) for x in value.ravel().tolist())
        ):
            raise ValueError(
                f"{name} contains bools; valid values: rows of finite real numbers (a bool is "
                "not a number)"
            )
        return
    if not isinstance(value, (list, tuple)):
        return
    for i, row in enumerate(value):
        items = row.tolist() if isinstance(row, np.ndarray) else row
        if isinstance(items, (bool, np.bool_)):
            raise ValueError(f"{name}[{i}] = {items!r} is invalid: a bool is not a row of numbers")
        if isinstance(items, (list, tuple)):
            for j, x in enumerate(items):
                if isinstance(x, (bool, np.bool_)):
                    raise ValueError(
                        f"{name}[{i}][{j}] = {x!r} is invalid: a bool is not a number; valid "
                        "values: finite real numbers"
                    )


def _rows(name: str, value: object, columns: tuple[str, ...], units: tuple[str, ...]):
    """``value`` as a read-only float array (n, k) of k = len(columns) finite entries, n ≥ 1,
    times (column 0) strictly increasing, |positions| ≤ 10¹⁰⁰ m."""
    k = len(columns)
    layout = "(" + ", ".join(columns) + ")"
    if isinstance(value, (str, bytes, bytearray, memoryview)) or value is None:
        raise ValueError(
            f"{name} = {v._short(value)} is invalid; valid values: a sequence of rows {layout}"
        )
    _no_bools(name, value)
    if np.ma.is_masked(value):  # np.asarray drops a mask: its entries would be read as data
        raise ValueError(f"{name} has masked entries; valid values: rows {layout} of numbers")
    try:
        arr = np.asarray(value)
    except (ValueError, TypeError, OverflowError):
        raise ValueError(
            f"{name} = {v._short(value)} is invalid; valid values: a sequence of rows {layout} "
            "of equal length"
        ) from None
    if arr.dtype.kind not in "fiu":
        raise ValueError(
            f"{name} = {v._short(value)} is invalid; valid values: a sequence of rows {layout} "
            "of finite real numbers"
        )
    if arr.ndim != 2 or arr.shape[1] != k or arr.shape[0] < 1:
        raise ValueError(
            f"{name} has shape {arr.shape}; valid values: shape (n, {k}) with n >= 1, rows "
            f"{layout} (one waypoint is [[{', '.join(columns)}]])"
        )
    if arr.shape[0] > MAX_WAYPOINTS:
        raise ValueError(
            f"{name} has {arr.shape[0]} rows; valid range: at most MAX_WAYPOINTS = "
            f"{MAX_WAYPOINTS} (resample a longer record)"
        )
    with np.errstate(all="ignore"):
        arr = arr.astype(float)
    bad = ~np.isfinite(arr)
    if bad.any():
        i, j = (int(x) for x in np.argwhere(bad)[0])
        raise ValueError(
            f"{name}[{i}, {j}] ({columns[j]}) = {float(arr[i, j])!r} {units[j]} is not finite; "
            "valid range: any finite real number"
        )
    pos = np.abs(arr[:, 1:3])
    if np.any(pos > v.POSITION):
        i, j = (int(x) for x in np.argwhere(pos > v.POSITION)[0])
        raise ValueError(
            f"{name}[{i}, {j + 1}] ({columns[j + 1]}) = {float(arr[i, j + 1])!r} m is invalid; "
            f"valid range: [{-v.POSITION:g}, {v.POSITION:g}] m"
        )
    step = np.diff(arr[:, 0])
    if np.any(step <= 0.0):
        i = int(np.flatnonzero(step <= 0.0)[0]) + 1
        raise ValueError(
            f"{name}[{i}, 0] (t) = {float(arr[i, 0])!r} s is not after {name}[{i - 1}, 0] = "
            f"{float(arr[i - 1, 0])!r} s; valid values: strictly increasing times [s]"
        )
    arr = np.ascontiguousarray(arr)
    arr.flags.writeable = False
    return arr


def _rates(name: str, arr: NDArray[np.float64], limits: tuple[tuple[str, float, str], ...]):
    """Each segment's rates of change (n − 1, k − 1), checked against ``limits``: per rate
    column (what, bound, unit); the speed is checked as |(vx, vy)|."""
    dt = np.diff(arr[:, 0])
    with np.errstate(all="ignore"):
        rates = np.diff(arr[:, 1:], axis=0) / dt[:, None]
    speed = np.hypot(rates[:, 0], rates[:, 1]) if len(rates) else np.zeros(0)
    checks = [(speed, limits[0])] + [
        (np.abs(rates[:, j + 2]), limits[j + 1]) for j in range(len(limits) - 1)
    ]
    for vals, (what, bound, unit) in checks:
        bad = ~(vals <= bound)  # NaN and inf too
        if bad.any():
            i = int(np.flatnonzero(bad)[0])
            raise ValueError(
                f"{name}: the segment from t = {float(arr[i, 0])!r} s to "
                f"{float(arr[i + 1, 0])!r} s has {what} {float(vals[i]):.6g} {unit}; valid "
                f"range: at most {bound:g} {unit}"
            )
    out = np.ascontiguousarray(rates)
    out.flags.writeable = False
    return out


def _time(t: object) -> tuple[NDArray[np.float64], bool]:
    """``t`` as a 1-D float array of finite times, and whether it was a scalar."""
    if isinstance(t, (bool, np.bool_)):
        raise ValueError(
            f"t = {t!r} is invalid: a bool is not a time; valid values: finite times [s]"
        )
    if isinstance(t, np.ndarray) and t.dtype.kind == "b":
        raise ValueError("t contains bools; valid values: finite times [s]")
    arr = v.real_array("t", t, unit="s")
    if arr.ndim > 1:
        raise ValueError(
            f"t has shape {arr.shape}; valid values: a time [s] or a 1-D array of them"
        )
    return np.atleast_1d(arr), arr.ndim == 0


def _locate(times: NDArray[np.float64], t: NDArray[np.float64]):
    """(segment index i, weight w, inside) for each t: t = (1 − w) t_i + w t_{i+1} inside
    [t_0, t_n); outside, i is the first or last row and w = 0 (held there)."""
    n = times.size
    if n == 1:
        zeros = np.zeros(t.size, dtype=np.intp)
        return zeros, np.zeros(t.size), np.zeros(t.size, dtype=bool)
    i = np.searchsorted(times, t, side="right") - 1
    inside = (i >= 0) & (i < n - 1)
    ic = np.clip(i, 0, n - 2)
    w = np.where(inside, (t - times[ic]) / (times[ic + 1] - times[ic]), 0.0)
    held = np.where(i < 0, 0, n - 1)  # the row the pusher is held at
    return np.where(inside, ic, held), w, inside


def _interp(arr: NDArray[np.float64], t: NDArray[np.float64]) -> NDArray[np.float64]:
    """Columns 1: of ``arr`` at the times t, as (1 − w) v_i + w v_{i+1} (never overflows)."""
    i, w, inside = _locate(arr[:, 0], t)
    vals = arr[i, 1:].copy()
    if inside.any():
        j = i[inside]
        ww = w[inside][:, None]
        vals[inside] = (1.0 - ww) * arr[j, 1:] + ww * arr[j + 1, 1:]
    return vals


def _rate(arr: NDArray[np.float64], rates: NDArray[np.float64], t: NDArray[np.float64]):
    """Right-continuous rates at t: the rate of the segment [t_i, t_{i+1}) holding t; 0 before
    the first time and from the last time on."""
    i, _, inside = _locate(arr[:, 0], t)
    out = np.zeros((t.size, arr.shape[1] - 1))
    if inside.any():
        out[inside] = rates[i[inside]]
    return out


def _knots(times: NDArray[np.float64], rates: NDArray[np.float64]) -> NDArray[np.float64]:
    """The times where the right-continuous rate jumps (compared exactly): between two
    segments whose rates differ, and at the first and last times if the pusher moves there."""
    if times.size == 1:
        out = np.zeros(0)
    else:
        zero = np.zeros((1, rates.shape[1]))
        padded = np.vstack((zero, rates, zero))
        jump = np.any(padded[1:] != padded[:-1], axis=1)
        out = times[jump].copy()
    out.flags.writeable = False
    return out


def _pair(name: str, value: object, size: int, what: str) -> NDArray[np.float64]:
    """A sequence of ``size`` finite real numbers (no bools, no strings)."""
    bad = f"{name} = {v._short(value)} is invalid; valid values: {what}"
    if isinstance(value, (str, bytes, bytearray, memoryview)) or value is None:
        raise ValueError(bad)
    try:
        items = list(value)  # type: ignore[call-overload]
    except TypeError:
        raise ValueError(bad) from None
    if len(items) != size:
        raise ValueError(bad)
    out = []
    for i, x in enumerate(items):
        if isinstance(x, np.generic):
            x = x.item()
        if isinstance(x, bool) or not isinstance(x, numbers.Real):
            raise ValueError(
                f"{name}[{i}] = {v._short(x)} ({type(x).__name__}) is invalid; valid values: a "
                "finite real number"
            )
        out.append(v.finite(f"{name}[{i}]", x))
    return np.array(out)


def _span(t_start: object, t_end: object) -> tuple[float, float]:
    t0 = v.finite("t_start", t_start if not isinstance(t_start, np.generic) else t_start.item())
    t1 = v.finite("t_end", t_end if not isinstance(t_end, np.generic) else t_end.item())
    if not t1 > t0:
        raise ValueError(
            f"t_end = {t1!r} s is invalid; valid range: a finite time > t_start = {t0!r} s"
        )
    return t0, t1


def _path_repr(arr: NDArray[np.float64]) -> str:
    if arr.shape[0] == 1:
        return f"<held at t = {arr[0, 0]:.6g} s>"
    return f"<{arr.shape[0]} waypoints over [{arr[0, 0]:.6g}, {arr[-1, 0]:.6g}] s>"


# ------------------------------------------------------------------------------------------
# the pushers


@dataclass(frozen=True, slots=True, eq=False)
class PointPusher:
    """A finger: a point of the plane moved along a piecewise-linear path (MODEL §13).

    Parameters
    ----------
    path : sequence of (t, x, y)
        Waypoints: time t [s] and the finger's position (x, y) [m] in the plane frame OXY.
        At least one row (one row: a finger held still), at most :data:`MAX_WAYPOINTS`;
        every entry finite (no bools), |x|, |y| ≤ 1e100 m, times strictly increasing, each
        segment's speed at most 1e8 m/s. The finger moves linearly in time between rows, and
        is held at the first row before the first time and at the last row after the last
        time.
    mu : float, default 0
        μp, the Coulomb coefficient between the finger and the body: finite and ≥ 0.

    Attributes
    ----------
    path : ndarray, shape (n, 3)
        The waypoints as floats (read-only).
    mu : float
        μp.

    Notes
    -----
    MODEL §13: the finger is the point p(t); at a contact with the body's outline it applies
    λ = λn n + λt t with λn ≥ 0 and |λt| ≤ μp λn. :meth:`velocity` is ṗ(t), right-continuous:
    at a waypoint time it is the velocity of the segment that starts there.

    Examples
    --------
    >>> finger = PointPusher([(0.0, -0.2, 0.0), (2.0, 0.2, 0.0)], mu=0.3)
    >>> finger.position(1.0).tolist(), finger.velocity(1.0).tolist()
    ([0.0, 0.0], [0.2, 0.0])
    >>> finger.velocity(2.0).tolist()  # held at the last waypoint from t = 2 s on
    [0.0, 0.0]
    """

    path: NDArray[np.float64]
    mu: float = 0.0
    _rates: NDArray[np.float64] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        arr = _rows("path", self.path, ("t", "x", "y"), ("s", "m", "m"))
        rates = _rates("path", arr, (("speed", v.SPEED, "m/s"),))
        object.__setattr__(self, "path", arr)
        object.__setattr__(self, "mu", pusher_mu(self.mu))
        object.__setattr__(self, "_rates", rates)

    @classmethod
    def constant_velocity(
        cls,
        start: ArrayLike,
        velocity: ArrayLike,
        t_end: float,
        mu: float = 0.0,
        t_start: float = 0.0,
    ) -> PointPusher:
        """A finger moving from ``start`` at constant ``velocity`` from ``t_start`` to ``t_end``.

        Parameters
        ----------
        start : (float, float)
            Position (x, y) [m] at ``t_start``, plane frame.
        velocity : (float, float)
            Velocity (vx, vy) [m/s], at most 1e8 m/s; :meth:`velocity` returns it exactly.
        t_end : float
            When the finger stops [s], finite and > ``t_start``; it is held there afterwards.
        mu : float, default 0
            μp, finite and ≥ 0.
        t_start : float, default 0
            When the finger starts [s] (held at ``start`` before).
        """
        p0 = _pair("start", start, 2, "a pair (x, y) of finite numbers [m]")
        vel = _pair("velocity", velocity, 2, "a pair (vx, vy) of finite numbers [m/s]")
        t0, t1 = _span(t_start, t_end)
        p1 = p0 + vel * (t1 - t0)
        out = cls(np.array([(t0, *p0), (t1, *p1)]), mu)
        if np.all(np.isfinite(p1)) and np.hypot(*vel) <= v.SPEED:
            exact = vel[None, :].copy()
            exact.flags.writeable = False
            object.__setattr__(out, "_rates", exact)
        return out

    @property
    def times(self) -> NDArray[np.float64]:
        """The waypoint times [s] (read-only), shape (n,)."""
        return self.path[:, 0]

    @property
    def knots(self) -> NDArray[np.float64]:
        """The times [s] where the velocity jumps (read-only): between segments of different
        velocity, and at the first and last times if the finger moves there."""
        return _knots(self.times, self._rates)

    @property
    def duration(self) -> tuple[float, float]:
        """(first, last) waypoint time [s]."""
        return (float(self.path[0, 0]), float(self.path[-1, 0]))

    def position(self, t: ArrayLike) -> NDArray[np.float64]:
        """p(t) [m], plane frame: shape (2,) for a float t, (n, 2) for an array of n times.

        Linear between the waypoints ((1 − w) p_i + w p_{i+1}, exact at the waypoints), held
        at the first and last waypoints outside their times."""
        tt, scalar = _time(t)
        out = _interp(self.path, tt)
        return out[0] if scalar else out

    def velocity(self, t: ArrayLike) -> NDArray[np.float64]:
        """ṗ(t) [m/s], plane frame, right-continuous: shape (2,) for a float t, (n, 2) for an
        array. Zero before the first time and from the last time on."""
        tt, scalar = _time(t)
        out = _rate(self.path, self._rates, tt)
        return out[0] if scalar else out

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, PointPusher):
            return NotImplemented
        return (
            self.mu == other.mu
            and self.path.shape == other.path.shape
            and bool(np.array_equal(self.path, other.path))
            and bool(np.array_equal(self._rates, other._rates))
        )

    def __hash__(self) -> int:
        return hash(("PointPusher", self.path.tobytes(), self.mu))

    def __repr__(self) -> str:
        return f"PointPusher(path={_path_repr(self.path)}, mu={self.mu!r})"


@dataclass(frozen=True, slots=True, eq=False)
class LinePusher:
    """A flat pusher: a segment of given length moved along a piecewise-linear path (MODEL §13).

    Parameters
    ----------
    length : float
        Length L of the segment [m], in [1e-9, 1e6].
    path : sequence of (t, x, y, angle)
        Waypoints: time t [s], the segment's centre (x, y) [m] in the plane frame and its
        direction angle [rad] from OX: the segment runs from centre − L/2 (cos a, sin a) to
        centre + L/2 (cos a, sin a). At least one row, at most :data:`MAX_WAYPOINTS`; every
        entry finite (no bools), |x|, |y| ≤ 1e100 m, times strictly increasing, each
        segment's centre speed at most 1e8 m/s and turn rate at most 1e12 rad/s. Centre and
        angle move linearly in time between rows (the angle is not wrapped: 0 → 2π is a full
        turn), held at the first and last rows outside their times.
    mu : float, default 0
        μp, the Coulomb coefficient between the pusher and the body: finite and ≥ 0.

    Notes
    -----
    MODEL §13: in face contact with a flat edge of the body the pusher carries a distributed
    line load whose resultant lies on the shared segment; otherwise it touches the body at a
    point (an end of the pusher, or a vertex of the body). :meth:`velocity` is the
    right-continuous (vx, vy, ω) of the segment's centre and its turn rate.

    Examples
    --------
    >>> edge = LinePusher(0.1, [(0.0, 0.0, -0.2, 0.0), (1.0, 0.0, 0.0, 0.0)])
    >>> edge.ends(1.0).tolist()
    [[-0.05, 0.0], [0.05, 0.0]]
    >>> edge.velocity(0.5).tolist()
    [0.0, 0.2, 0.0]
    """

    length: float
    path: NDArray[np.float64]
    mu: float = 0.0
    _rates: NDArray[np.float64] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        length = v.bounded("length", self.length, *v.LENGTH, "m")
        arr = _rows("path", self.path, ("t", "x", "y", "angle"), ("s", "m", "m", "rad"))
        rates = _rates("path", arr, (("speed", v.SPEED, "m/s"), ("turn rate", v.SPIN, "rad/s")))
        object.__setattr__(self, "length", length)
        object.__setattr__(self, "path", arr)
        object.__setattr__(self, "mu", pusher_mu(self.mu))
        object.__setattr__(self, "_rates", rates)

    @classmethod
    def constant_velocity(
        cls,
        start_pose: ArrayLike,
        velocity: ArrayLike,
        t_end: float,
        length: float,
        mu: float = 0.0,
        t_start: float = 0.0,
    ) -> LinePusher:
        """A line pusher of ``length`` moving from ``start_pose`` at constant ``velocity``.

        Parameters
        ----------
        start_pose : (float, float, float)
            (x, y, angle) [m, m, rad] of the centre and direction at ``t_start``.
        velocity : (float, float, float)
            (vx, vy, ω) [m/s, m/s, rad/s] of the centre and the direction;
            :meth:`velocity` returns it exactly.
        t_end : float
            When the pusher stops [s], finite and > ``t_start``.
        length : float
            L [m], in [1e-9, 1e6] (required: ``LinePusher.constant_velocity(pose, vel,
            t_end, length=0.1)``).
        mu, t_start
            As in :meth:`PointPusher.constant_velocity`.
        """
        p0 = _pair("start_pose", start_pose, 3, "a triple (x, y, angle) of finite numbers")
        vel = _pair("velocity", velocity, 3, "a triple (vx, vy, omega) of finite numbers")
        t0, t1 = _span(t_start, t_end)
        p1 = p0 + vel * (t1 - t0)
        out = cls(length, np.array([(t0, *p0), (t1, *p1)]), mu)
        exact = vel[None, :].copy()
        exact.flags.writeable = False
        object.__setattr__(out, "_rates", exact)  # the checks above passed for the rounded rates
        return out

    @property
    def times(self) -> NDArray[np.float64]:
        """The waypoint times [s] (read-only), shape (n,)."""
        return self.path[:, 0]

    @property
    def knots(self) -> NDArray[np.float64]:
        """The times [s] where the velocity (vx, vy, ω) jumps (read-only)."""
        return _knots(self.times, self._rates)

    @property
    def duration(self) -> tuple[float, float]:
        """(first, last) waypoint time [s]."""
        return (float(self.path[0, 0]), float(self.path[-1, 0]))

    def pose(self, t: ArrayLike) -> NDArray[np.float64]:
        """(x, y, angle) of the centre [m] and direction [rad]: shape (3,) for a float t,
        (n, 3) for an array of n times."""
        tt, scalar = _time(t)
        out = _interp(self.path, tt)
        return out[0] if scalar else out

    def velocity(self, t: ArrayLike) -> NDArray[np.float64]:
        """(vx, vy, ω) [m/s, m/s, rad/s], right-continuous: shape (3,) or (n, 3); zero before
        the first time and from the last time on."""
        tt, scalar = _time(t)
        out = _rate(self.path, self._rates, tt)
        return out[0] if scalar else out

    def ends(self, t: ArrayLike) -> NDArray[np.float64]:
        """The two ends [m], centre ∓ L/2 (cos a, sin a): shape (2, 2) (rows: the − end, the
        + end) for a float t, (n, 2, 2) for an array."""
        tt, scalar = _time(t)
        p = _interp(self.path, tt)
        half = 0.5 * self.length
        d = half * np.column_stack((np.cos(p[:, 2]), np.sin(p[:, 2])))
        out = np.stack((p[:, :2] - d, p[:, :2] + d), axis=1)
        return out[0] if scalar else out

    def direction(self, t: ArrayLike) -> NDArray[np.float64]:
        """Unit vector (cos a, sin a) along the segment: shape (2,) or (n, 2)."""
        tt, scalar = _time(t)
        a = _interp(self.path, tt)[:, 2]
        out = np.column_stack((np.cos(a), np.sin(a)))
        return out[0] if scalar else out

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, LinePusher):
            return NotImplemented
        return (
            self.length == other.length
            and self.mu == other.mu
            and self.path.shape == other.path.shape
            and bool(np.array_equal(self.path, other.path))
            and bool(np.array_equal(self._rates, other._rates))
        )

    def __hash__(self) -> int:
        return hash(("LinePusher", self.length, self.path.tobytes(), self.mu))

    def __repr__(self) -> str:
        return f"LinePusher(length={self.length!r}, path={_path_repr(self.path)}, mu={self.mu!r})"
