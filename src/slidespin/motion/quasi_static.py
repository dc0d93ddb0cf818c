"""Quasi-static pushing: a body led by a finger with inertia neglected (MODEL §13).

In the quasi-static limit (ν̇ → 0) the plane friction is on its limit surface (MODEL §11) and
balances the pusher's wrench at every instant:

    W(û) + J_cᵀ λ = 0,      λ = λn n + λt t,  λn ≥ 0,  |λt| ≤ μp λn,

with û the unit twist direction (vx, vy, ℓ ω)/|·| of the body, c the contact point on the
body's outline, n the inward unit normal there, t = ẑ × n, and μp the pusher's Coulomb
coefficient. Dry friction is rate-independent, so W depends on û only; the contact
kinematics fix the size of the twist. The contact modes (names as in :class:`QuasiStaticPush`):

``"sticking"``
    The body point at c moves with the finger, J_c ν = ṗ (2 equations); the moment balance
    about c, M_c(û) = 0, fixes the rest (one root in the angle between translating with the
    finger and turning about c). Valid while λ = −F(û) lies in the friction cone.
``"sliding_left"``, ``"sliding_right"``
    λ on the edge n ± μp t of the cone: the finger slides to its left (+t, seen from the
    finger looking into the body along n) or to its right (−t) over the body, which pushes it
    back along the edge λt = +μp λn (left) or −μp λn (right). The friction wrench is then a
    force on the line through c along −λ (its direction: 1 equation; no moment about c:
    1 more); the normal velocity match (J_c ν − ṗ)·n = 0 fixes |ν|.
``"separated"``
    λ = 0: the finger is away from the body, or moves away from it (ṗ·n ≤ 0), and the body
    rests where it is (no quasi-static motion without a load) until the finger touches it
    again; the touch time is located by root finding on the finger's path.

At a corner of a polygonal outline the contact normal may be anything between the two edges'
normals: the finger sticks at the corner while λ stays in the union of their friction cones,
else slides onto an edge or leaves the corner (``"separated"``); a finger at rest next to the
body (ṗ = 0) moves nothing and its force is reported as 0 (it is indeterminate).

Each mode is integrated with scipy's DOP853 at a tight tolerance on the pose (x, y, φ) of
G; path knots are integration boundaries and mode switches are located as events (root
finding on the dense output), so the poses are accurate to about the tolerance.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from slidespin import _validate as v
from slidespin.contact._engine import TwistWrench
from slidespin.contact.body import Body, require_thin
from slidespin.contact.friction import FrictionTensor
from slidespin.contact.outline import Outline, body_outline
from slidespin.motion._qs_pieces import PhaseBudget, Pieces, check_max_phases
from slidespin.motion.outcomes import PUSH_MODES
from slidespin.motion.pushers import LinePusher
from slidespin.motion.quasi_static_line import push_line_quasi_static
from slidespin.motion.state import reduced_angle

__all__ = ["QuasiStaticPush", "push_quasi_static"]

#: contact modes of a point pusher, by their integer code in :attr:`QuasiStaticPush.mode_code`
SEP, STICK, LEFT, RIGHT = 0, 1, 2, 3
_SIGMA = {LEFT: 1.0, RIGHT: -1.0}
#: a finger closer than this to the outline (units of ℓ) touches it; farther inside is refused
_TOUCH = 1e-9
#: events within this time [s, relative to the segment] of a piece's start are its own switch
_EVENT_GUARD = 1e-12
_HALF_PI = 0.5 * math.pi
#: balances (moments per P ℓ, angles) and cone margins this small are zero within round-off
_ROUND = 1e-12


@dataclass(frozen=True)
class QuasiStaticPush:
    """The quasi-static motion of a pushed body at the requested times (MODEL §13).

    Attributes
    ----------
    t : ndarray
        Times [s], as requested.
    x, y : ndarray
        Position of the mass centre G in the plane frame [m].
    phi : ndarray
        Body angle [rad] (continuous, not wrapped).
    vx, vy, omega : ndarray
        The quasi-static twist at G [m/s, m/s, rad/s] (right-continuous at switches).
    mode : ndarray of str
        A finger: ``"separated"``, ``"sticking"``, ``"sliding_left"`` or ``"sliding_right"``
        (module notes). A line pusher (:mod:`slidespin.motion.quasi_static_line`):
        ``"separated"``; ``"face_sticking"`` (face flat on a body edge, the body moves with
        the pusher), ``"face_sliding_left"``, ``"face_sliding_right"`` (face flat, the body
        slides along it); ``"vertex_sticking"``, ``"vertex_sliding_left"``,
        ``"vertex_sliding_right"`` (a body vertex, or an ellipse's nearest point, on the
        pusher's face); ``"end_sticking"``, ``"end_sliding_left"``, ``"end_sliding_right"``
        (an end of the pusher on a body edge). Rotation about an end of a shared face segment
        is a ``vertex_*`` mode when that end is a body corner, an ``end_*`` mode when it is
        the pusher's end. Right-continuous: at a switch time the mode that follows.
    mode_code : ndarray of int
        The same as indices into ``modes``.
    contact_x, contact_y : ndarray
        Contact point in the plane frame [m] (the finger's position; in a line pusher's face
        contact, the point of the shared segment where the line load's resultant acts; NaN
        when separated).
    force_x, force_y : ndarray
        Force of the pusher on the body in the plane frame [N] (0 when separated).
    switch_times : ndarray
        Times [s] at which the mode changed.
    switch_modes : tuple of str
        The mode entered at each switch time.
    status : str
        ``"ok"``, ``"indeterminate"`` if no consistent contact mode was found, or
        ``"max_phases"`` past the budget of pieces (then the arrays hold NaN from that time
        on and ``message`` says why; the vocabulary of
        :data:`slidespin.motion.outcomes.PUSHED_STATUSES`).
    message : str
        One line on how the run ended.
    modes : tuple of str
        The vocabulary ``mode_code`` indexes: :data:`slidespin.motion.outcomes.PUSH_MODES`,
        for a finger and a line pusher alike (one set of codes, as in a dynamic run).
    """

    t: NDArray[np.float64]
    x: NDArray[np.float64]
    y: NDArray[np.float64]
    phi: NDArray[np.float64]
    vx: NDArray[np.float64]
    vy: NDArray[np.float64]
    omega: NDArray[np.float64]
    mode: NDArray[np.str_]
    mode_code: NDArray[np.int64]
    contact_x: NDArray[np.float64]
    contact_y: NDArray[np.float64]
    force_x: NDArray[np.float64]
    force_y: NDArray[np.float64]
    switch_times: NDArray[np.float64]
    switch_modes: tuple[str, ...]
    status: str
    message: str
    modes: tuple[str, ...] = PUSH_MODES


class _NoMode(RuntimeError):
    """No consistent quasi-static contact mode (or a root solve failed)."""


# ------------------------------------------------------------------------------------------
# the body's outline, relative to G in the body's orientation
# ------------------------------------------------------------------------------------------
class _Outline:
    """The contact outline ∂B (:func:`slidespin.contact.outline.body_outline`) with the
    polygon's edges as arrays: ``verts`` (CCW), ``dirs``, ``lengths``, inward ``normals``;
    any other outline (an ellipse, a hull with round parts) is handled as smooth."""

    def __init__(self, outline: Outline) -> None:
        self.shape = outline
        self.verts: np.ndarray | None = None
        if outline.is_polygon:
            self.verts = outline.vertices
            d = np.roll(self.verts, -1, axis=0) - self.verts
            self.lengths = np.hypot(d[:, 0], d[:, 1])
            self.dirs = d / self.lengths[:, None]
            self.normals = outline.edge_normals

    @property
    def polygonal(self) -> bool:
        return self.verts is not None

    def level(self, pb: np.ndarray) -> float:
        """A convex function of the point, < 0 inside, 0 on ∂B, > 0 outside [m]."""
        if self.verts is not None:
            return float(np.max(-np.sum((pb - self.verts) * self.normals, axis=1)))
        return float(self.shape.closest(pb)[2])

    def smooth_contact(self, pb: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(closest point of ∂B, inward unit normal there)."""
        q, n, _ = self.shape.closest(pb)
        return q, n

    def nearest_edge(self, pb: np.ndarray) -> tuple[int, float]:
        """(edge index, parameter along it in [0, 1]) of the polygon point nearest to pb."""
        assert self.verts is not None
        rel = pb - self.verts
        s = np.clip(np.sum(rel * self.dirs, axis=1) / self.lengths, 0.0, 1.0)
        foot = self.verts + (s * self.lengths)[:, None] * self.dirs
        i = int(np.argmin(np.hypot(*(pb - foot).T)))
        return i, float(s[i])


# ------------------------------------------------------------------------------------------
# the quasi-static solves
# ------------------------------------------------------------------------------------------
def _brent(f, lo, hi, guess=None, width=1e-3):
    """A root of f in [lo, hi] (f(lo), f(hi) of opposite signs or zero), searched first in a
    small bracket about ``guess``; raises :class:`_NoMode` without a sign change."""
    from scipy.optimize import brentq  # lazy: scipy.optimize costs ~0.8 s to import

    a, b = (lo, hi) if lo <= hi else (hi, lo)
    if guess is not None and a < guess < b:
        w = width * (b - a)
        while w < b - a:
            l2, h2 = max(a, guess - w), min(b, guess + w)
            fl, fh = f(l2), f(h2)
            if fl == 0.0:
                return l2
            if fh == 0.0:
                return h2
            if (fl < 0.0) != (fh < 0.0):
                try:
                    return brentq(f, l2, h2, xtol=1e-15, rtol=1e-15, maxiter=200)
                except ValueError:  # a warm-started inner root moved f(l2) across 0
                    pass
            w *= 16.0
    fa, fb = f(a), f(b)
    if fa == 0.0:
        return a
    if fb == 0.0:
        return b
    if (fa < 0.0) == (fb < 0.0):
        if min(abs(fa), abs(fb)) <= _ROUND:  # a root at an end, within round-off
            return a if abs(fa) <= abs(fb) else b
        raise _NoMode("no sign change of the balance in its bracket")
    try:
        return brentq(f, a, b, xtol=1e-15, rtol=1e-15, maxiter=200)
    except ValueError:  # an end value at round-off level changed sign on re-evaluation
        raise _NoMode("the balance changed sign only at round-off level") from None


class _Problem:
    """One body, tensor and pusher: the contact geometry and the mode solves (SI units)."""

    def __init__(self, body: Body, friction: FrictionTensor, pusher, g: float, outline) -> None:
        require_thin(body, "pushed runs")
        self.tw = TwistWrench(body, friction)
        self.ell = body.length_unit
        self.load = body.mass * g
        self.rg = np.zeros(2)  # outline points are relative to G
        self.outline = _Outline(outline)
        self.pusher = pusher
        self.mu = float(pusher.mu)
        self.edge_angle = math.atan(self.mu)
        self.warm: dict = {}

    # geometry ---------------------------------------------------------------------------
    def body_point(self, q, p) -> np.ndarray:
        c, s = math.cos(q[2]), math.sin(q[2])
        dx, dy = p[0] - q[0], p[1] - q[1]
        return np.array([c * dx + s * dy, -s * dx + c * dy]) + self.rg

    def gap(self, q, p) -> float:
        """The outline's level function at the finger [m] (> 0 away from the body)."""
        return self.outline.level(self.body_point(q, p))

    def contact(self, q, p, feature):
        """(r_c = c − G in the plane frame, inward normal n, edge parameter) for the finger at
        p touching the ``feature`` ("smooth", ("edge", i) or ("vertex", i))."""
        pb = self.body_point(q, p)
        out = self.outline
        u = 0.5
        if feature == "smooth":
            cb, nb = out.smooth_contact(pb)
        elif feature[0] == "edge":
            i = feature[1]
            rel = pb - out.verts[i]
            u = float(rel @ out.dirs[i]) / out.lengths[i]
            cb, nb = out.verts[i] + u * out.lengths[i] * out.dirs[i], out.normals[i]
        else:
            i = feature[1]
            cb = out.verts[i]
            nb = out.normals[i] + out.normals[i - 1]
            nb = nb / math.hypot(nb[0], nb[1])
        c, s = math.cos(q[2]), math.sin(q[2])
        rot = np.array([[c, -s], [s, c]])
        return rot @ (cb - self.rg), rot @ nb, u

    # wrench -----------------------------------------------------------------------------
    def stick(self, phi, rc, vdir, key):
        """Sticking twist for a contact point velocity along the unit ``vdir``: returns
        (ν(s) as (vx, vy, ℓω) with J_c ν(s) = cos s · vdir, cos s, friction (Fx, Fy)/P)."""
        rx, ry = rc[0] / self.ell, rc[1] / self.ell
        rot = (ry, -rx, 1.0)  # (vx/ℓ, vy/ℓ, ω) for turning about c at ω = 1

        def twist(s):
            cs, sn = math.cos(s), math.sin(s)
            return (cs * vdir[0] + sn * rot[0], cs * vdir[1] + sn * rot[1], sn)

        def balance(s):  # friction moment about c per P ℓ
            fx, fy, m = self.tw(phi, *twist(s))
            return m - (rx * fy - ry * fx)

        s = _brent(balance, -_HALF_PI, _HALF_PI, self.warm.get(key))
        self.warm[key] = s
        nu = twist(s)
        fx, fy, _ = self.tw(phi, *nu)
        return nu, math.cos(s), (fx, fy)

    def solve(self, mode, feature, t, q, seg):
        """(ν = (vx, vy, ω), λ/P, event values ≥ 0 while the mode holds, r_c) at (t, q), the
        finger on the segment ``seg`` = (t_a, p(t_a), ṗ) of its path."""
        ta, pa, pdot = seg
        p = pa + pdot * (t - ta)
        rc, n, u = self.contact(q, p, feature)
        tg = np.array([-n[1], n[0]])
        speed = math.hypot(pdot[0], pdot[1])
        pn, pt = float(pdot @ n), float(pdot @ tg)
        if mode == SEP or speed == 0.0:
            return np.zeros(3), np.zeros(2), (pn / speed if speed else 0.0,), rc
        if mode == STICK:
            nu, cs, f = self.stick(q[2], rc, pdot / speed, ("stick", feature))
            k = speed / cs
            lam = np.array([-f[0], -f[1]])
            ln, lt = float(lam @ n), float(lam @ tg)
            if feature != "smooth" and feature[0] == "vertex":
                ev = self._corner_events(q[2], feature[1], lam)
            else:
                scale = math.hypot(ln, lt)
                m = (self.mu * ln - lt) / scale + _ROUND, (self.mu * ln + lt) / scale + _ROUND
                ev = (*m, pn / speed)
        else:
            sig = _SIGMA[mode]
            psi0 = math.atan2(pt, pn)
            target = sig * self.edge_angle

            def edge(psi):
                vd = math.cos(psi) * n + math.sin(psi) * tg
                _, _, f = self.stick(q[2], rc, vd, ("slide", feature))
                return sig * (
                    math.atan2(-f[0] * tg[0] - f[1] * tg[1], -f[0] * n[0] - f[1] * n[1]) - target
                )

            key = ("psi", feature, mode)
            try:
                psi = _brent(edge, psi0, -sig * _HALF_PI, self.warm.get(key))
            except _NoMode:  # beyond the switch back to sticking (stages past an event)
                psi = _brent(edge, psi0, sig * _HALF_PI, self.warm.get(key))
            self.warm[key] = psi
            vd = math.cos(psi) * n + math.sin(psi) * tg
            nu, cs, f = self.stick(q[2], rc, vd, ("slide", feature))
            k = pn / math.cos(psi) / cs
            lam = np.array([-f[0], -f[1]])
            ev = (sig * (psi0 - psi) + _ROUND, pn / speed)
            if feature != "smooth":
                ev = ev + (u, 1.0 - u)
        twist = np.array([nu[0] * k, nu[1] * k, nu[2] * k / self.ell])
        return twist, lam, ev, rc

    def _corner_events(self, phi, i, lam):
        """Angular room of λ inside the union of the friction cones at vertex i [rad]."""
        out = self.outline
        c, s = math.cos(phi), math.sin(phi)
        lb = np.array([c * lam[0] + s * lam[1], -s * lam[0] + c * lam[1]])  # body frame
        n0, n1 = out.normals[i - 1], out.normals[i]
        a = math.atan2(lb[1], lb[0])
        a0 = math.atan2(n0[1], n0[0]) - self.edge_angle
        a1 = a0 + math.atan2(n0[0] * n1[1] - n0[1] * n1[0], n0 @ n1) + 2.0 * self.edge_angle
        a = a0 + (a - a0 + math.pi) % (2.0 * math.pi) - math.pi
        return (a - a0 + _ROUND, a1 - a + _ROUND)

    # modes ------------------------------------------------------------------------------
    def feature_at(self, q, p):
        """The outline feature the finger at p touches: "smooth", ("edge", i), ("vertex", i)."""
        out = self.outline
        if not out.polygonal:
            return "smooth"
        i, u = out.nearest_edge(self.body_point(q, p))
        tol = 1e-9 * self.ell / out.lengths[i]
        if u <= tol:
            return ("vertex", i)
        if u >= 1.0 - tol:
            return ("vertex", (i + 1) % len(out.verts))
        return ("edge", i)

    def choose(self, t, q, seg, exclude=()):
        """The consistent mode (code, feature) of the finger touching the body at (t, q)."""
        ta, pa, pdot = seg
        p = pa + pdot * (t - ta)
        if self.gap(q, p) > _TOUCH * self.ell or not np.any(pdot):
            return SEP, None
        feature = self.feature_at(q, p)
        if feature != "smooth" and feature[0] == "vertex":
            return self._choose_corner(t, q, seg, feature[1], exclude)
        _, n, _ = self.contact(q, p, feature)
        if float(pdot @ n) <= 0.0:
            return SEP, None
        _, lam, ev, _ = self.solve(STICK, feature, t, q, seg)
        if ev[0] >= -_ROUND and ev[1] >= -_ROUND:
            return STICK, feature
        return (LEFT if ev[0] < 0.0 else RIGHT), feature

    def _choose_corner(self, t, q, seg, i, exclude):
        """Mode at vertex i: sticking there, sliding onto either edge, or leaving the corner."""
        out = self.outline
        pdot = seg[2]
        if STICK not in exclude:
            _, _, ev, _ = self.solve(STICK, ("vertex", i), t, q, seg)
            if min(ev) >= -_ROUND:
                return STICK, ("vertex", i)
        prev = (i - 1) % len(out.verts)
        for mode, feature in ((RIGHT, ("edge", i)), (LEFT, ("edge", prev))):
            try:
                _, lam, ev, rc = self.solve(mode, feature, t, q, seg)
            except _NoMode:
                continue
            _, n, _ = self.contact(q, seg[1] + pdot * (t - seg[0]), feature)
            if ev[0] >= 0.0 and ev[1] > 0.0 and float(lam @ n) > 0.0:
                return mode, feature
        c, s = math.cos(q[2]), math.sin(q[2])
        pb = np.array([c * pdot[0] + s * pdot[1], -s * pdot[0] + c * pdot[1]])
        if not (pb @ out.normals[prev] > 0.0 and pb @ out.normals[i] > 0.0):
            return SEP, None
        raise _NoMode(f"no consistent contact mode at the corner {out.verts[i]} at t = {t!r} s")

    def after_event(self, mode, feature, which, t, q, seg):
        """The mode entered when event ``which`` of ``mode`` fires (module notes)."""
        corner = feature != "smooth" and feature is not None and feature[0] == "vertex"
        if mode == STICK:
            if corner:
                return self._choose_corner(t, q, seg, feature[1], (STICK,))
            return ((LEFT, feature), (RIGHT, feature), (SEP, None))[which]
        if which == 0:
            return STICK, feature
        if which == 1:
            return SEP, None
        nv = len(self.outline.verts)
        return self._choose_corner(t, q, seg, (feature[1] + which - 2) % nv, ())

    def touch_time(self, q, seg, t, tb):
        """First time in (t, tb] at which the finger on ``seg`` reaches the resting body."""
        from scipy.optimize import brentq, minimize_scalar  # lazy: see _brent

        ta, pa, pdot = seg

        def d(tau):
            return self.gap(q, pa + pdot * (tau - ta))

        if d(t) <= _TOUCH * self.ell:  # touching and leaving (convex gap): no return here
            return None
        grid = np.linspace(t, tb, 65)
        vals = np.array([d(x) for x in grid])
        hit = np.flatnonzero(vals <= 0.0)
        if hit.size:
            hi = grid[hit[0]]
        else:
            k = int(np.argmin(vals))
            lo, up = grid[max(k - 1, 0)], grid[min(k + 1, 64)]
            r = minimize_scalar(d, bounds=(lo, up), method="bounded", options={"xatol": 1e-14})
            if r.fun > 0.0:
                return None
            hi = float(r.x)
        return brentq(d, t, hi, xtol=1e-15, rtol=1e-15, maxiter=200)


# ------------------------------------------------------------------------------------------
# the driver
# ------------------------------------------------------------------------------------------
def _integrate(prob, mode, feature, seg, t, tb, q, rtol):
    """Integrate one mode from (t, q) towards tb: (dense solution, t_end, q_end, event)."""
    from scipy.integrate import solve_ivp  # lazy: see _brent

    memo: dict = {}
    guard = t + _EVENT_GUARD * max(tb - t, 1e-300)

    def res(tt, y):
        key = (tt, y[0], y[1], y[2])
        got = memo.get(key)
        if got is None:
            if len(memo) > 64:
                memo.clear()
            got = memo[key] = prob.solve(mode, feature, tt, y, seg)
        return got

    def rhs(tt, y):
        return res(tt, y)[0]

    n_ev = len(res(t, q)[2])
    events = []
    for k in range(n_ev):

        def ev(tt, y, k=k):
            val = res(tt, y)[2][k]
            return val if tt > guard else abs(val) + 1e-300

        ev.terminal = True  # type: ignore[attr-defined]
        ev.direction = -1.0  # type: ignore[attr-defined]
        events.append(ev)
    atol = np.array([rtol * prob.ell, rtol * prob.ell, rtol])
    sol = solve_ivp(
        rhs, (t, tb), q, method="DOP853", rtol=rtol, atol=atol, dense_output=True, events=events
    )
    if sol.status < 0:
        raise _NoMode(f"the integration failed at t = {sol.t[-1]!r} s: {sol.message}")
    which = None
    if sol.status == 1:
        which = next(k for k, te in enumerate(sol.t_events) if len(te))
    return sol.sol, float(sol.t[-1]), sol.y[:, -1].copy(), which


def _check_inputs(body, friction, pusher, times, start):
    if not isinstance(body, Body):
        raise ValueError(f"body = {v._short(body)} is invalid; valid values: a slidespin.Body")
    if not isinstance(friction, FrictionTensor):
        raise ValueError(
            f"friction = {v._short(friction)} is invalid; valid values: a FrictionTensor"
        )
    if not all(callable(getattr(pusher, a, None)) for a in ("position", "velocity")) or not (
        hasattr(pusher, "knots") and hasattr(pusher, "mu")
    ):
        raise ValueError(
            f"pusher = {v._short(pusher)} is invalid; valid values: a slidespin.PointPusher "
            "or LinePusher"
        )
    t = v.real_array("times", times)
    if t.ndim != 1 or t.size < 1:
        raise ValueError(
            f"times has shape {t.shape}; valid values: a 1-D array of at least one time [s]"
        )
    if t.size > 1 and not np.all(np.diff(t) > 0.0):
        k = int(np.flatnonzero(np.diff(t) <= 0.0)[0])
        raise ValueError(
            f"times[{k + 1}] = {t[k + 1]!r} s is invalid; valid range: > times[{k}] = "
            f"{t[k]!r} s (times strictly increasing)"
        )
    if start is None:
        q = np.zeros(3)
    else:
        q = v.real_array("start", start)
        if q.shape != (3,):
            raise ValueError(
                f"start has shape {q.shape}; valid values: the pose (x [m], y [m], phi [rad])"
            )
    return t, q.astype(float)


def push_quasi_static(
    body: Body,
    friction: FrictionTensor,
    pusher,
    times: ArrayLike,
    start: ArrayLike | None = None,
    *,
    outline=None,
    g: float = 9.81,
    rtol: float = 1e-10,
    max_phases: int = 10_000,
) -> QuasiStaticPush:
    """The quasi-static motion of ``body`` pushed by a finger along its path (MODEL §13).

    Parameters
    ----------
    body : Body
        The pushed body: its footprint's convex hull (an ellipse: the ellipse) is the outline
        the finger touches.
    friction : FrictionTensor
        Plane friction (isotropic or anisotropic, plane- or body-fixed).
    pusher : PointPusher or LinePusher
        The finger: a piecewise-linear path (``position``, ``velocity``, ``knots``) and its
        Coulomb coefficient ``mu`` against the body; or a flat pusher (a segment with its
        pose), handled by :func:`slidespin.motion.quasi_static_line.push_line_quasi_static`
        (face, vertex and end contacts, MODEL §13) with the same parameters.
    times : array_like
        Strictly increasing output times [s]; the motion starts at ``times[0]``.
    start : (x, y, phi), optional
        Pose of G [m, m, rad] at ``times[0]``; default (0, 0, 0). The finger must not start
        inside the outline.
    outline : None, array_like (n, 2), footprint or Ellipse, optional
        The outline the finger touches, in the body frame (default: the footprint's convex
        hull, or the ellipse); :func:`slidespin.contact.outline.body_outline`.
    g : float, default 9.81
        Gravitational acceleration [m/s²] in [1e-6, 1e6] (the forces scale with m g).
    rtol : float, default 1e-10
        Relative tolerance of the integration in [1e-13, 1e-3] (absolute: ``rtol`` × ℓ on
        the position, ``rtol`` on the angle).
    max_phases : int, default 10000
        Budget of pieces (contact modes between switches and path knots) in [1, 1e9]; beyond
        it the push ends with status ``"max_phases"`` (values as reached, NaN after), as a
        dynamic run does.

    Returns
    -------
    QuasiStaticPush
        Poses, twists, modes, contact points and pusher forces at ``times``.

    Notes
    -----
    MODEL §13, quasi-static limit: W(û) + J_cᵀ λ = 0 with the exact friction wrench W of
    MODEL §2 and §10 on the limit surface (§11); the modes and their equations are in the
    module notes. Paths are integrated segment by segment between their knots; contact-mode
    switches and the finger's arrival are located by root finding (to ~1e-12 s). Every
    sticking solve is one bracketed root (the moment about c changes sign between turning
    about c either way), every sliding solve a bracketed root of the cone-edge condition over
    the direction of the contact point's velocity.
    """
    if isinstance(pusher, LinePusher):
        fields = push_line_quasi_static(
            body,
            friction,
            pusher,
            times,
            start,
            outline=outline,
            g=g,
            rtol=rtol,
            max_phases=max_phases,
        )
        return QuasiStaticPush(**fields)
    t_out, q = _check_inputs(body, friction, pusher, times, start)
    max_phases = check_max_phases(max_phases)
    q[2], turns = reduced_angle(float(q[2]))  # the turns are added back to the result
    g = v.bounded("g", g, *v.GRAVITY, "m/s^2")
    rtol = v.bounded("rtol", rtol, 1e-13, 1e-3)
    v.bounded("pusher.mu", pusher.mu, 0.0, math.inf)
    prob = _Problem(body, friction, pusher, g, body_outline(body, outline))
    t0, t1 = float(t_out[0]), float(t_out[-1])
    p0 = np.asarray(pusher.position(t0), dtype=float)
    gap0 = prob.gap(q, p0)
    if gap0 < -_TOUCH * prob.ell:
        raise ValueError(
            f"start = {tuple(float(x) for x in q)} is invalid: the finger at "
            f"({p0[0]!r}, {p0[1]!r}) m starts {-gap0:.6g} m inside the body's outline; valid "
            "values: a pose with the finger on or outside the outline"
        )
    knots = sorted({float(k) for k in np.asarray(pusher.knots, dtype=float) if t0 < k < t1})
    bounds = [t0, *knots, t1]
    pieces = Pieces(max_phases)  # (ta, tb, mode, feature, seg, q or dense solution)
    status, message = "ok", f"followed the path to t = {t1!r} s"
    try:
        for ta, tb in zip(bounds[:-1], bounds[1:]):
            seg = (
                ta,
                np.asarray(pusher.position(ta), float),
                np.asarray(pusher.velocity(ta), float),
            )
            t = ta
            mode, feature = prob.choose(t, q, seg)
            while t < tb:
                if mode == SEP:
                    hit = prob.touch_time(q, seg, t, tb)
                    t_next = tb if hit is None else hit
                    pieces.append((t, t_next, SEP, None, seg, q.copy()))
                    t = t_next
                    if hit is None or hit >= tb:
                        break
                    mode, feature = prob.choose(t, q, seg)
                    if mode == SEP:  # a graze: the finger passes along the outline
                        pieces.append((t, tb, SEP, None, seg, q.copy()))
                        break
                    continue
                dense, t_ev, q_ev, which = _integrate(prob, mode, feature, seg, t, tb, q, rtol)
                pieces.append((t, t_ev, mode, feature, seg, dense))
                t, q = t_ev, q_ev
                if which is not None:
                    mode, feature = prob.after_event(mode, feature, which, t, q, seg)
            if tb == t1 and not pieces:
                pieces.append((t0, t1, mode, feature, seg, q.copy()))
        if t0 == t1:
            seg = (t0, p0, np.asarray(pusher.velocity(t0), float))
            mode, feature = prob.choose(t0, q, seg)
            pieces.append((t0, t1, mode, feature, seg, q.copy()))
    except _NoMode as exc:
        status, message = "indeterminate", str(exc)
    except PhaseBudget as exc:
        status, message = "max_phases", str(exc)
    out = _assemble(prob, t_out, pieces, status, message)
    return dataclasses.replace(out, phi=out.phi + turns) if turns else out


def _assemble(prob, t_out, pieces, status, message) -> QuasiStaticPush:
    """The result at the output times from the integrated pieces (right-continuous)."""
    n = t_out.size
    cols = {
        k: np.full(n, np.nan)
        for k in ("x", "y", "phi", "vx", "vy", "omega", "cx", "cy", "fx", "fy")
    }
    code = np.zeros(n, dtype=np.int64)
    starts = np.array([p[0] for p in pieces]) if pieces else np.zeros(0)
    last_end = pieces[-1][1] if pieces else -math.inf
    for j, tau in enumerate(t_out):
        if tau > last_end or not pieces:
            continue
        k = max(int(np.searchsorted(starts, tau, side="right")) - 1, 0)
        ta, tb, mode, feature, seg, data = pieces[k]
        q = np.asarray(data(tau) if callable(data) else data, dtype=float)
        cols["x"][j], cols["y"][j], cols["phi"][j] = q
        code[j] = mode
        if mode == SEP:
            cols["vx"][j] = cols["vy"][j] = cols["omega"][j] = 0.0
            cols["fx"][j] = cols["fy"][j] = 0.0
            continue
        nu, lam, _, rc = prob.solve(mode, feature, tau, q, seg)
        cols["vx"][j], cols["vy"][j], cols["omega"][j] = nu
        cols["fx"][j], cols["fy"][j] = lam * prob.load
        cols["cx"][j], cols["cy"][j] = q[0] + rc[0], q[1] + rc[1]
    sw_t, sw_m = [], []
    for a, b in zip(pieces[:-1], pieces[1:]):
        if a[2] != b[2]:
            sw_t.append(b[0])
            sw_m.append(PUSH_MODES[b[2]])
    return QuasiStaticPush(
        t=t_out,
        x=cols["x"],
        y=cols["y"],
        phi=cols["phi"],
        vx=cols["vx"],
        vy=cols["vy"],
        omega=cols["omega"],
        mode=np.array([PUSH_MODES[c] for c in code]),
        mode_code=code,
        contact_x=cols["cx"],
        contact_y=cols["cy"],
        force_x=cols["fx"],
        force_y=cols["fy"],
        switch_times=np.array(sw_t, dtype=float),
        switch_modes=tuple(sw_m),
        status=status,
        message=message,
    )
