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

import bisect
import inspect
import math
import numbers
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from slidespin import _validate as v
from slidespin.contact._profile import Profile, as_real, check_pair, show_value
from slidespin.contact.body import Body
from slidespin.contact.incline import Incline

__all__ = ["LOAD_FRAMES", "MAX_KNOTS", "Load", "applied_wrench"]

#: frames a :class:`Load`'s force may be given in
LOAD_FRAMES = ("plane", "body")

#: most samples (knots) of a :meth:`Load.piecewise_linear` load: each is kept as Python
#: floats (about 130 MB for four columns of 10⁶), and the stick test of a loaded run looks
#: at every knot (:func:`slidespin.motion.loaded.simulate_loaded`); resample a longer record
MAX_KNOTS = 1_000_000

ForceSpec = tuple | Callable[[float], tuple]
TorqueSpec = float | Callable[[float], float]


class _Samples(Profile):
    """A :class:`~slidespin.contact._profile.Profile` evaluated by bisection of its knots:
    O(log n) per evaluation, bit for bit the same values (the linear interpolation
    (1 − w) v₀ + w v₁ of :func:`slidespin.contact._profile.interp`)."""

    __slots__ = ()

    def __call__(self, t: float) -> Any:
        t = float(t)
        tt = self.times
        if not math.isfinite(t):
            raise ValueError(f"t = {t!r} is not finite; valid range: any finite time [s]")
        if t <= tt[0]:
            vals = tuple(c[0] for c in self.columns)
        elif t >= tt[-1]:
            vals = tuple(c[-1] for c in self.columns)
        else:
            i = bisect.bisect_right(tt, t) - 1
            w = (t - tt[i]) / (tt[i + 1] - tt[i])
            vals = tuple((1.0 - w) * c[i] + w * c[i + 1] for c in self.columns)
        return vals if len(vals) > 1 else vals[0]


def _signature_error(name: str, fn: Callable, expected: str) -> TypeError | None:
    """A TypeError if ``fn`` cannot be called as ``fn(t)`` (None if it can, or if Python
    cannot tell: builtins without a signature are left to the trial call)."""
    try:
        sig = inspect.signature(fn)
    except (TypeError, ValueError):
        return None
    try:
        sig.bind(0.0)
    except TypeError:
        return TypeError(
            f"{name} = {v._short(fn)} takes the arguments {sig}; valid values: a function of "
            f"one argument, the time t [s]: {expected}"
        )
    return None


def _checked_callable(name: str, fn: Callable, pair: bool) -> None:
    """Check a time-dependent force (``pair``) or torque once, at construction: it must be
    callable as ``fn(t)`` and return a pair of finite numbers [N] (a finite number [N m])
    at t = 0, the first time any run asks for."""
    expected = f"{name}(t) -> (Qx, Qy) [N]" if pair else f"{name}(t) -> T [N m]"
    what = "a pair of finite numbers" if pair else "one finite number"
    if isinstance(fn, Profile):  # built by piecewise_linear: checked there
        return
    err = _signature_error(name, fn, expected)
    if err is not None:
        raise err
    try:
        out = fn(0.0)
    except Exception as exc:  # noqa: BLE001 - any failure of user code, named
        raise ValueError(
            f"{name}(0.0) raised {type(exc).__name__}: {exc}; valid values: a function "
            f"{expected} of the time t [s] >= 0 returning {what}"
        ) from exc
    try:
        if pair:
            check_pair(f"{name}(0.0)", out)
            ok = True
        else:
            x = as_real(out)
            ok = not isinstance(x, bool) and isinstance(x, numbers.Real) and math.isfinite(x)
    except (ValueError, TypeError, OverflowError):  # e.g. an int beyond the floats
        ok = False
    if not ok:
        raise ValueError(
            f"{name}(0.0) returned {show_value(out)}; valid values: a function {expected} "
            f"of the time t [s] returning {what}"
        )


def _no_bools(name: str, value: object) -> None:
    """Refuse bools among samples: ``[True, 2, 3]`` would otherwise read as ``[1, 2, 3]``."""
    if isinstance(value, (bool, np.bool_)):
        bad: list[tuple[int, object]] = [(0, value)]
    elif isinstance(value, np.ndarray):
        if value.dtype.kind == "b":
            raise ValueError(
                f"{name} = {show_value(value)} is invalid: bools are not numbers here; "
                "valid values: finite real numbers"
            )
        if value.dtype.kind != "O":
            return
        bad = [(i, x) for i, x in enumerate(value.ravel()) if isinstance(x, (bool, np.bool_))]
    elif isinstance(value, (list, tuple)):
        bad = [(i, x) for i, x in enumerate(value) if isinstance(x, (bool, np.bool_))]
    else:
        return
    if bad:
        i, x = bad[0]
        raise ValueError(
            f"{name}[{i}] = {x!r} is invalid: a bool is not a number; valid values: "
            "finite real numbers"
        )


def _sample_times(value: object) -> np.ndarray:
    """The knots of :meth:`Load.piecewise_linear`: 2 to :data:`MAX_KNOTS` finite, strictly
    increasing times [s]; the message names the first bad entry."""
    _no_bools("times", value)
    t = v.real_array("times", value, unit="s")
    if t.ndim != 1 or not 2 <= t.size <= MAX_KNOTS:
        raise ValueError(
            f"times has shape {t.shape}; valid: a 1-D sequence of 2 to {MAX_KNOTS:,} times [s] "
            "(resample a longer record)"
        )
    step = np.diff(t)
    if np.any(step <= 0.0):
        i = int(np.flatnonzero(step <= 0.0)[0]) + 1
        raise ValueError(
            f"times[{i}] = {float(t[i])!r} s is not after times[{i - 1}] = "
            f"{float(t[i - 1])!r} s; valid values: strictly increasing times [s]"
        )
    return t


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
        ``torque(t)`` returning it.
    frame : {"plane", "body"}, default "plane"
        Whether ``force`` is given in the fixed frame OXY or in the body frame Cξη (then it
        turns with the body: Q_world = R(φ) Q).
    at : (float, float) or None, default None
        Body-frame point r_Q = (ξ, η) [m] where the force acts, measured from the patch
        centre C like every body-frame coordinate; ``None`` means the mass centre G (no
        moment from Q). For every pressure law except the linear one, G = C.
    height : float or None, default None
        Height h_Q [m] above the plane at which the force acts, in [0, 1e6], for a tall body
        (``Body(..., height=h)``, MODEL §14): the force then tilts the body and moves its
        pressure centroid by −(h − h_Q) Q / P. ``None`` means G's height (no tilt), as for
        gravity's pull on a slope; on a body of height 0 every height is the same.

    Raises
    ------
    TypeError
        If a callable cannot be called with one argument, ``force(t)`` / ``torque(t)``.
    ValueError
        If a value is not finite, or a callable, called once at t = 0 when the load is
        built, fails or returns something other than a pair of finite numbers (a finite
        number for ``torque``).

    Notes
    -----
    **Cost of a callable.** A function of time is Python code: the loaded engine calls it
    from Python at every right-hand-side evaluation of a slip phase and at every point of
    the scan of a stick phase (``scan_step``), about 20 µs per evaluation with the engine's
    overhead, and a callable's stick phases must be scanned on a time grid because nothing
    is known about it between samples. The same push given as a table runs in compiled code
    (:mod:`slidespin.motion._loaded_core`) and is checked exactly at its knots instead: the
    triangular push of ``examples/pushed_puck.py`` takes 6.9 s as a Python function and 0.1 s
    as :meth:`piecewise_linear` (measured; the phases agree to 4e-11 s). Prefer the tabulated
    forms (a constant, or :meth:`piecewise_linear` with as many knots as the push needs, up
    to :data:`MAX_KNOTS`); a callable is for loads that depend on t in a way no table
    captures.

    A callable is called once at t = 0 when the load is built (to check its signature and
    what it returns), then only at the times the integrator asks for; it must be a
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
    height: float | None = None

    def __post_init__(self) -> None:
        if callable(self.force):
            _checked_callable("force", self.force, pair=True)
        else:
            object.__setattr__(self, "force", check_pair("force", self.force))
        if callable(self.torque):
            _checked_callable("torque", self.torque, pair=False)
        else:
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
        if self.height is not None:
            object.__setattr__(
                self, "height", v.bounded("height", self.height, 0.0, v.LENGTH[1], "m")
            )

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
        height: float | None = None,
    ) -> Load:
        """A load interpolated linearly between samples, constant beyond the first and last.

        Parameters
        ----------
        times : sequence of float
            Strictly increasing, finite times [s], at least 2 and at most
            :data:`MAX_KNOTS` (10⁶); bools are refused.
        fx, fy : sequence of float
            Force components [N] at those times, in ``frame``: finite, one per time.
        torque : sequence of float or None
            Torque [N m] at those times (default 0).
        frame, at, height
            As in :class:`Load`.
        names : (str, str, str) or None
            Names of ``fx``, ``fy``, ``torque`` in error messages (a case file's keys).

        Notes
        -----
        Evaluation bisects the knots: O(log n) per time, so a long record (10⁵ knots) costs
        about what a short one does. The stick test of :func:`slidespin.simulate` looks at
        every sample time (knot): the load is affine between knots, and so the gauge of the
        static-friction set at the load is convex there, so a load that leaves the set is
        always found, however short the excursion
        (:func:`slidespin.motion.loaded.simulate_loaded`, ``scan_step``).

        Examples
        --------
        >>> push = Load.piecewise_linear([0.0, 1.0, 2.0], [0.0, 5.0, 0.0], [0.0, 0.0, 0.0])
        >>> push.force_at(0.5), push.force_at(3.0)
        ((2.5, 0.0), (0.0, 0.0))
        """
        nx, ny, nt = names or ("fx", "fy", "torque")
        t = _sample_times(times)
        cols = []
        for name, c in ((nx, fx), (ny, fy), (nt, torque)):
            if c is None:
                cols.append(np.zeros_like(t))
                continue
            _no_bools(name, c)
            arr = v.real_array(name, c)
            if arr.shape != t.shape:
                raise ValueError(
                    f"{name} = {show_value(np.atleast_1d(arr))} is invalid; valid "
                    f"values: {t.size} finite numbers, one per time"
                )
            cols.append(arr)
        tt, a, b, m = (tuple(arr.tolist()) for arr in (t, *cols))
        torque_fn = _Samples(tt, m) if any(m) else 0.0
        return cls(force=_Samples(tt, a, b), torque=torque_fn, frame=frame, at=at, height=height)

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
        profiles = [f for f in (self.force, self.torque) if isinstance(f, Profile)]
        if not profiles:
            return ()
        first = profiles[0].times
        if all(p.times is first or p.times == first for p in profiles):
            return tuple(first)  # one table (piecewise_linear): sorted already
        times: set[float] = set()
        for p in profiles:
            times.update(p.times)
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

    def raised_force(self, t: float, phi: float, height: float) -> tuple[float, float]:
        """(h − h_Q) Q [N m] in the fixed frame: the force's lever about G's height ``height``
        = h [m] (zero for a load at G's height, ``height=None``; MODEL §14)."""
        if self.height is None:
            return (0.0, 0.0)
        qx, qy, _ = self.wrench(t, phi)
        lever = height - self.height
        return (lever * qx, lever * qy)


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
