"""Private helpers of the dynamic pushing engines (MODEL §13): the body's outline, the pushers'
paths, the event-locating stepper and the shared phases, used by :mod:`slidespin.motion.pushed`
(a finger) and :mod:`slidespin.motion.pushed_line` (a flat pusher).

========================  ======================================================================
``_Outline``              the convex outline relative to G in natural units (a CCW hull,
                          pieces = edges and arcs, or an ellipse, one periodic piece), with
                          its signed gap, the nearest outline point and the geometry c(s),
                          c', c'', n(s)
``_Finger``               a point pusher's path as linear segments between its velocity knots
``_integrate``            DOP853 (or Radau IIA) from t0 to t1 with terminal events located by
                          Brent's method on the dense output (to ~1e-15 of the time scale)
``_integrate_contact``    a contact phase: DOP853, going on in Radau IIA when it turns stiff
                          (a slow pusher), and back where Radau struggles
``check_inputs``          the checks common to both engines' entries (one-line ``ValueError``)
``_Line``                 a line pusher's path: (p, θ, ṗ, θ̇) on segments of constant rates
``_gap``, ``_identify``   the separating-axis gap between a line pusher and a polygonal
                          outline (continuous in time, > 0 apart), and the contact's feature
                          (face, vertex or end) where it closes
``_separated``,           a line-pushed body sliding free in the regularised time of MODEL §5,
``_rest``                 and at rest until the pusher arrives
``_wrench``,              the plane friction and loads at a twist; the plastic impulse at a
``_point_impulse``        point contact (in the cone, else on its edge)
========================  ======================================================================

The finger's helpers were split out of :mod:`slidespin.motion.pushed` without a change of
behaviour (the same code, moved; that engine keeps its own separated phases); natural units
throughout (ℓ, m, g = 1; ℓ = :attr:`slidespin.Body.length_unit`).
"""

from __future__ import annotations

import math

import numpy as np

from slidespin import _validate as v
from slidespin.contact.body import Body, check_body_friction
from slidespin.contact.incline import Incline
from slidespin.contact.outline import body_outline
from slidespin.contact.static_set import check_anisotropy
from slidespin.motion._stick_slip import GAUGE_TOL
from slidespin.motion.loads import Load
from slidespin.motion.pushers import LinePusher, PointPusher
from slidespin.motion.state import State

_FLAT = 1e-9  # [ℓ] a second vertex this close to a line pusher makes a face contact


def _rot(phi):
    return math.cos(phi), math.sin(phi)


# ------------------------------------------------------------------------------------------
# the outline (body frame, relative to G, natural units)


class _Outline:
    """Convex outline (body frame, relative to G, natural units), as pieces along which a
    contact point moves: a hull's straight edges (pieces 0..k−1, edge i from disc i to disc
    i + 1, s = arc length from its start) and, on a hull of discs (pads with disks), the arcs
    of the discs of radius > 0 (piece k + i on disc i, s = arc length from the end of edge
    i − 1); or an ellipse (one periodic piece, s = the parametric angle). All pieces run
    counter-clockwise. Where an edge meets an arc the outline is smooth (a contact slides on
    from one piece to the next); a disc of radius 0 is a corner (a polygon's vertex)."""

    def __init__(self, body: Body, a: float, outline=None):
        ol = body_outline(body, outline)
        self.poly = ol.kind == "hull"  # pieces with ends (a hull)
        self.round = False  # a hull with arcs (pads with disks)
        if not self.poly:
            self.c0 = (float(ol.centre[0]) / a, float(ol.centre[1]) / a)
            self.A, self.B = ol.axes[0] / a, ol.axes[1] / a
            self.cb, self.sb = _rot(float(ol.angle))
            return
        edges = np.asarray(ol.edges, dtype=float) / a
        self.V = edges[:, 0, :].copy()  # the edges' starts (a polygon's vertices)
        e = edges[:, 1, :] - edges[:, 0, :]
        self.L = np.hypot(e[:, 0], e[:, 1])
        self.E = e / np.maximum(self.L, 1e-300)[:, None]
        self.N = -np.column_stack((np.cos(ol.edge_angles), np.sin(ol.edge_angles)))  # inward
        self.R = np.asarray(ol.discs[:, 2], dtype=float) / a
        self.C = np.asarray(ol.discs[:, :2], dtype=float) / a
        self.round = bool(np.any(self.R > 0.0))
        # arc i runs from edge i − 1's outward normal angle to edge i's, counter-clockwise
        th1 = np.asarray(ol.edge_angles, dtype=float)
        th0 = np.roll(th1, 1)
        self.th0 = th0
        self.AL = self.R * np.mod(th1 - th0, 2.0 * math.pi)
        # the chord polygon through the edges' ends: the hull is it and the discs together
        pts = edges.reshape(-1, 2)
        keep = np.hypot(*(pts - np.roll(pts, 1, axis=0)).T) > 1e-12
        self.P = pts[keep]
        d = np.roll(self.P, -1, axis=0) - self.P
        self.PN = np.column_stack((-d[:, 1], d[:, 0]))  # inward (CCW), unnormalised

    def length(self, piece):
        """The length of a hull's piece (an edge or an arc)."""
        k = len(self.L)
        return float(self.L[piece]) if piece < k else float(self.AL[piece - k])

    def is_corner(self, i):
        """True where hull disc i is a sharp corner (radius 0)."""
        return not self.round or self.R[i] == 0.0

    def beyond(self, piece, end):
        """The piece a contact sliding off ``piece`` at its ``end`` (0: its start, 1: its end)
        slides on to, with its s there, or None at a corner (a vertex of the outline)."""
        k = len(self.L)
        if piece < k:  # edge i: from disc i to disc i + 1
            i = (piece + 1) % k if end else piece
            if self.is_corner(i):
                return None
            return (k + i, 0.0) if end else (k + i, float(self.AL[i]))
        i = piece - k  # arc i: from edge i − 1 to edge i
        return (i, 0.0) if end else ((i - 1) % k, float(self.L[(i - 1) % k]))

    def gap(self, q0, q1):
        """An implicit signed gap of the body point (q0, q1): > 0 outside, 0 on the outline."""
        if self.poly:
            d = -(self.N[:, 0] * (q0 - self.V[:, 0]) + self.N[:, 1] * (q1 - self.V[:, 1]))
            if not self.round:
                return float(d.max())
            # a hull of discs: the signed distance to the nearest piece, negative inside (in
            # the chord polygon or in a disc: their union is the hull)
            piece, s = self.locate(q0, q1)
            c = self.geom(piece, s)[0]
            dist = math.hypot(q0 - c[0], q1 - c[1])
            inside = bool(
                np.all(
                    self.PN[:, 0] * (q0 - self.P[:, 0]) + self.PN[:, 1] * (q1 - self.P[:, 1]) >= 0.0
                )
            ) or bool(np.any(np.hypot(q0 - self.C[:, 0], q1 - self.C[:, 1]) <= self.R))
            return -dist if inside else dist
        x, y = self._local(q0, q1)
        x, y = x / self.A, y / self.B
        return (math.sqrt(x * x + y * y) - 1.0) * min(self.A, self.B)

    def _local(self, q0, q1):
        dx, dy = q0 - self.c0[0], q1 - self.c0[1]
        return self.cb * dx + self.sb * dy, -self.sb * dx + self.cb * dy

    def locate(self, q0, q1):
        """(piece, s) of the outline point nearest to the body point (q0, q1) on the outline."""
        if self.poly:
            if self.round:
                return self._nearest(q0, q1)
            d = -(self.N[:, 0] * (q0 - self.V[:, 0]) + self.N[:, 1] * (q1 - self.V[:, 1]))
            i = int(np.argmax(d))
            s = (q0 - self.V[i, 0]) * self.E[i, 0] + (q1 - self.V[i, 1]) * self.E[i, 1]
            return i, min(max(s, 0.0), float(self.L[i]))
        x, y = self._local(q0, q1)
        return 0, math.atan2(y / self.B, x / self.A)

    def _nearest(self, q0, q1):
        """The nearest point over all pieces of a hull of discs (edges, then arcs)."""
        k = len(self.L)
        best, out = math.inf, (0, 0.0)
        for i in range(k):
            s = (q0 - self.V[i, 0]) * self.E[i, 0] + (q1 - self.V[i, 1]) * self.E[i, 1]
            s = min(max(s, 0.0), float(self.L[i]))
            dd = math.hypot(
                q0 - self.V[i, 0] - s * self.E[i, 0], q1 - self.V[i, 1] - s * self.E[i, 1]
            )
            if dd < best:
                best, out = dd, (i, s)
        for i in range(k):
            if self.R[i] == 0.0:
                continue
            dx, dy = q0 - self.C[i, 0], q1 - self.C[i, 1]
            rel = (math.atan2(dy, dx) - self.th0[i]) % (2.0 * math.pi)
            span = self.AL[i] / self.R[i]
            if rel > span:  # beyond the arc: its nearer end
                rel = span if rel - span < 2.0 * math.pi - rel else 0.0
            s = min(rel * self.R[i], float(self.AL[i]))
            th = self.th0[i] + s / self.R[i]
            cx, cy = (
                self.C[i, 0] + self.R[i] * math.cos(th),
                self.C[i, 1] + self.R[i] * math.sin(th),
            )
            dd = math.hypot(q0 - cx, q1 - cy)
            if dd < best:
                best, out = dd, (k + i, s)
        return out

    def normal_point(self, beta):
        """An ellipse's point with outward normal angle ``beta`` (body frame), by its support
        function h(b) = √(A² cos² b + B² sin² b), b = β − γ: c = c0 + R_γ (h u + h' u⊥),
        with the radius of curvature ρ = h + h'' and ρ' = dρ/dβ (c' = ρ u⊥(β), c'' = ρ' u⊥ −
        ρ u). Returns (c, ρ, ρ')."""
        b = beta - math.atan2(self.sb, self.cb)
        cs, sn = math.cos(b), math.sin(b)
        dd = self.B * self.B - self.A * self.A
        h = math.hypot(self.A * cs, self.B * sn)
        s2, c2 = 2.0 * sn * cs, cs * cs - sn * sn
        h1 = 0.5 * dd * s2 / h
        h2 = (dd * c2 - h1 * h1) / h
        h3 = (-2.0 * dd * s2 - 3.0 * h1 * h2) / h
        lx, ly = h * cs - h1 * sn, h * sn + h1 * cs
        c = (
            self.c0[0] + self.cb * lx - self.sb * ly,
            self.c0[1] + self.sb * lx + self.cb * ly,
        )
        return c, h + h2, h1 + h3

    def geom(self, piece, s):
        """Body frame c(s), c'(s), c''(s) and the inward unit normal n(s)."""
        if self.poly:
            k = len(self.L)
            if piece >= k:  # an arc of disc i (s = arc length)
                i = piece - k
                r = float(self.R[i])
                th = self.th0[i] + s / r
                cs, sn = math.cos(th), math.sin(th)
                return (
                    (self.C[i, 0] + r * cs, self.C[i, 1] + r * sn),
                    (-sn, cs),
                    (-cs / r, -sn / r),
                    (-cs, -sn),
                )
            vx, vy = self.V[piece]
            ex, ey = self.E[piece]
            return (vx + s * ex, vy + s * ey), (ex, ey), (0.0, 0.0), tuple(self.N[piece])
        cs, sn = math.cos(s), math.sin(s)
        a, b, cb, sb = self.A, self.B, self.cb, self.sb
        h = math.hypot(b * cs, a * sn)

        def turn(x, y):
            return cb * x - sb * y, sb * x + cb * y

        c = turn(a * cs, b * sn)
        return (
            (self.c0[0] + c[0], self.c0[1] + c[1]),
            turn(-a * sn, b * cs),
            turn(-a * cs, -b * sn),
            turn(-b * cs / h, -a * sn / h),
        )


# ------------------------------------------------------------------------------------------
# what every pushed run keeps


class _Run:
    """The state every pushed engine keeps (natural units): the problem, outline, μp,
    tolerances and step budget; the rows, switches and impacts; ``self.X`` = (x, y, φ, vx,
    vy, ω) between phases, the works ``self.W`` = (pusher, friction, slip, load) and the
    impact loss ``self.loss``."""

    def __init__(self, prob, ol, mu, rtol, max_steps):
        self.prob, self.ol = prob, ol
        self.k = prob.k
        self.mu = mu
        self.rtol, self.atol = rtol, rtol * 1e-2
        self.steps_left = max_steps
        self.rows: list = []
        self.switches: list = []
        self.impacts: list = []
        self.W = np.zeros(4)
        self.loss = 0.0
        self.turns = 0.0  # 2π times the whole turns taken off the start angle
        self.seg = 0
        self._phases, self._same_t, self._t_last = 0, 0, -1.0

    def next_phase(self, t, max_phases):
        """Count a phase starting at t: ``"max_phases"`` past the budget, ``"indeterminate"``
        after 8 phases at one instant (no progress), else None."""
        self._phases += 1
        if self._phases > max_phases:
            return "max_phases"
        self._same_t = self._same_t + 1 if t == self._t_last else 0
        if self._same_t > 8:
            return "indeterminate"
        self._t_last = t
        return None


# ------------------------------------------------------------------------------------------
# the finger (natural units)


class _Finger:
    """The finger's path as linear segments between the knots where its velocity jumps."""

    def __init__(self, pusher: PointPusher, a: float, tu: float):
        self.mu = float(pusher.mu)
        knots = np.unique(np.concatenate(([0.0], np.asarray(pusher.knots, dtype=float))))
        knots = knots[knots >= 0.0]
        self.t = knots / tu  # segment starts
        self.p = np.asarray(pusher.position(knots), dtype=float).reshape(-1, 2) / a
        self.v = np.asarray(pusher.velocity(knots), dtype=float).reshape(-1, 2) * tu / a

    def segment(self, t):
        """(index, start, end) of the segment holding the natural time t (right-continuous)."""
        k = int(np.searchsorted(self.t, t, side="right")) - 1
        k = max(k, 0)
        end = float(self.t[k + 1]) if k + 1 < self.t.size else math.inf
        return k, float(self.t[k]), end

    def pos(self, k, t):
        dt = t - self.t[k]
        return self.p[k, 0] + dt * self.v[k, 0], self.p[k, 1] + dt * self.v[k, 1]


# ------------------------------------------------------------------------------------------
# stepping with events


def _integrate(fun, t0, y0, t1, events, rtol, atol, budget, rec, stiff=False):
    """DOP853 (or Radau IIA if ``stiff``) from t0 to t1 with terminal events g(t, y) that
    fire where g falls below 0.

    Returns (reason, t, y, index, steps): reason ``end``, ``event`` (index), ``max_steps``
    or ``failed``. Every accepted step is passed to ``rec(t, y)``."""
    from scipy.integrate import DOP853, Radau  # lazy: scipy's import cost
    from scipy.optimize import brentq

    solver = (Radau if stiff else DOP853)(fun, t0, y0, t1, rtol=rtol, atol=atol)
    g_old = [e(t0, y0) for e in events]
    steps, h_max, small = 0, 0.0, 0
    while True:
        if steps >= budget:
            return "max_steps", solver.t, solver.y, -1, steps
        t_old = solver.t
        try:
            with np.errstate(over="ignore", invalid="ignore"):  # Radau's difference Jacobian
                solver.step()
        except (ValueError, np.linalg.LinAlgError):  # Radau's Newton ran off to inf/NaN
            if not stiff:
                raise
            return "failed", solver.t, solver.y, -1, steps
        steps += 1
        if solver.status == "failed":
            return "failed", solver.t, solver.y, -1, steps
        t_new, y_new = solver.t, solver.y
        g_new = [e(t_new, y_new) for e in events]
        hits = [i for i, gn in enumerate(g_new) if gn < 0.0]
        if hits:
            sol = solver.dense_output()
            best, t_hit = -1, t_new
            for i in hits:
                if g_old[i] < 0.0:
                    root = t_old  # already beyond at the start: a switch at once
                else:
                    f = events[i]
                    root = brentq(
                        lambda tt: f(tt, sol(tt)), t_old, t_new, xtol=1e-300, rtol=8.9e-16
                    )
                    # the root's far side, so that the switch sees g < 0 (or = 0)
                    if f(root, sol(root)) > 0.0 and root < t_new:
                        root = np.nextafter(root, t_new)
                if root <= t_hit:
                    best, t_hit = i, root
            if best >= 0:
                y_hit = sol(t_hit) if t_hit < t_new else y_new
                rec(t_hit, y_hit)
                return "event", t_hit, y_hit, best, steps
        rec(t_new, y_new)
        if solver.status == "finished":
            return "end", t_new, y_new, -1, steps
        h_max = max(h_max, t_new - t_old)
        small = small + 1 if t_new - t_old < _STRUGGLE * h_max else 0
        if stiff and small > _STRUGGLE_STEPS:  # Radau near a non-smooth point
            return "struggling", t_new, y_new, -1, steps
        g_old = g_new


_STIFF_AFTER = 200  # DOP853 steps in one contact phase before it goes on in Radau IIA
_STRUGGLE = 1e-3  # Radau steps this much below its largest, ...
_STRUGGLE_STEPS = 50  # ... this many in a row, hand the phase back to DOP853


def _integrate_contact(fun, t0, y0, t1, events, rtol, atol, budget, rec):
    """A contact phase: DOP853, then Radau IIA once DOP853 has taken ``_STIFF_AFTER`` steps.

    A slow pusher makes the contact phases stiff: the body relaxes to the pusher's motion in
    a time ~ V/(μ g) against a path time ~ ℓ/V, so an explicit method takes ~ μ g ℓ/V² steps
    (the implicit one a number that does not grow as V falls). Where Radau's Newton iteration
    fails (a body coming to rest on the plane, where the friction wrench jumps) or its steps
    stay below ``_STRUGGLE`` times its largest for ``_STRUGGLE_STEPS`` steps (its Newton
    iteration straddling such a point), the phase goes on in DOP853 for ``_STIFF_AFTER``
    steps, then in Radau again, and so on. Same returns
    as :func:`_integrate`, steps summed."""
    total, stiff = 0, False
    while True:
        cap = budget - total if stiff else min(_STIFF_AFTER, budget - total)
        reason, t, y, idx, n = _integrate(fun, t0, y0, t1, events, rtol, atol, cap, rec, stiff)
        total += n
        more = ("failed", "struggling") if stiff else ("max_steps",)
        if total >= budget or reason not in more:
            break
        t0, y0, stiff = t, y, not stiff
    return reason, t, y, idx, total


# ------------------------------------------------------------------------------------------
# the checks common to the entries


def check_inputs(
    body, friction, state, pusher, t_end, g, rtol, max_steps, max_phases, load, incline
):
    """Validate a pushed run's arguments (one-line ``ValueError`` naming the parameter);
    returns (t_end, g, rtol) as floats. A point or a line pusher is accepted."""
    check_body_friction(body, friction)
    if load is not None or incline is not None:
        check_anisotropy(body, friction, "static friction under a load or on an incline")
    if not isinstance(state, State):
        raise ValueError(f"state = {v._short(state)} is invalid; valid values: a slidespin.State")
    if not isinstance(pusher, (PointPusher, LinePusher)):
        raise ValueError(
            f"pusher = {v._short(pusher)} is invalid; valid values: a PointPusher or a LinePusher"
        )
    if load is not None and not isinstance(load, Load):
        raise ValueError(
            f"load = {v._short(load)} is invalid; valid values: a slidespin.Load or None"
        )
    if incline is not None and not isinstance(incline, Incline):
        raise ValueError(
            f"incline = {v._short(incline)} is invalid; valid values: a slidespin.Incline or None"
        )
    t_end = v.in_range("t_end", t_end, 0.0, v.T_END, lo_open=True)
    g = v.bounded("g", g, *v.GRAVITY, "m/s^2")
    rtol = v.in_range("rtol", rtol, 0.0, 1e-3, lo_open=True)
    for name, val in (("max_steps", max_steps), ("max_phases", max_phases)):
        if (
            isinstance(val, bool)
            or not isinstance(val, (int, np.integer))
            or not 1 <= val <= v.MAX_STEPS
        ):
            raise ValueError(
                f"{name} = {v._short(val)} is invalid; valid range: integer in [1, {v.MAX_STEPS}]"
            )
    return t_end, g, rtol


# ------------------------------------------------------------------------------------------
# the line pusher: its path, the gap, the contact's feature, the separated phases


def _cross(a, b):
    return a[0] * b[1] - a[1] * b[0]


def _zx(a):
    return (-a[1], a[0])


class _Line:
    """The pusher's path as segments of constant (ṗ, θ̇) between its knots (natural units)."""

    def __init__(self, pusher, a, tu):
        self.mu = float(pusher.mu)
        self.h = 0.5 * float(pusher.length) / a
        knots = np.unique(np.concatenate(([0.0], np.asarray(pusher.knots, dtype=float))))
        knots = knots[knots >= 0.0]
        self.t = knots / tu
        pose = np.asarray(pusher.pose(knots), dtype=float).reshape(-1, 3)
        vel = np.asarray(pusher.velocity(knots), dtype=float).reshape(-1, 3)
        self.p = np.column_stack((pose[:, :2] / a, pose[:, 2]))
        self.v = np.column_stack((vel[:, :2] * tu / a, vel[:, 2] * tu))

    def segment(self, t):
        k = max(int(np.searchsorted(self.t, t, side="right")) - 1, 0)
        end = float(self.t[k + 1]) if k + 1 < self.t.size else math.inf
        return k, float(self.t[k]), end

    def state(self, k, t):
        """(p, θ, ṗ, θ̇) at t on segment k."""
        dt = t - self.t[k]
        pk, vk = self.p[k], self.v[k]
        return (pk[0] + dt * vk[0], pk[1] + dt * vk[1]), pk[2] + dt * vk[2], vk[:2], vk[2]


def _gap(ol, line, k, t, x, y, phi):
    """Separating-axis signed gap between the pusher's segment and the outline (> 0 apart),
    and the axis that attains it: ("body", i) an edge normal, ("line", ±1) the face normal."""
    p, th, _, _ = line.state(k, t)
    c, s = _rot(phi)
    V = np.column_stack((x + c * ol.V[:, 0] - s * ol.V[:, 1], y + s * ol.V[:, 0] + c * ol.V[:, 1]))
    e = (math.cos(th), math.sin(th))
    ends = np.array(
        [[p[0] - line.h * e[0], p[1] - line.h * e[1]], [p[0] + line.h * e[0], p[1] + line.h * e[1]]]
    )
    N = np.column_stack((c * ol.N[:, 0] - s * ol.N[:, 1], s * ol.N[:, 0] + c * ol.N[:, 1]))
    # edge axes: the pusher's ends against the inward normal of edge i
    dn = -(
        (ends[:, None, 0] - V[None, :, 0]) * N[None, :, 0]
        + (ends[:, None, 1] - V[None, :, 1]) * N[None, :, 1]
    )
    body = dn.min(axis=0)  # the end deepest along each edge normal
    i = int(np.argmax(body))
    best, which = float(body[i]), ("body", i)
    n0 = (-e[1], e[0])
    d = (V[:, 0] - p[0]) * n0[0] + (V[:, 1] - p[1]) * n0[1]
    for side in (1.0, -1.0):
        g = float((side * d).min())
        if g > best:
            best, which = g, ("line", side)
    return best, which


def _identify(ol, line, seg, t, x):
    """The contact's feature where the gap between the line pusher and the outline closes:
    (kind, j, side, endsign, dx, dy): a ``face`` on edge j, a ``vertex`` j on the face or an
    ``end`` (σ = endsign·h) on edge j; side·ẑ × e is the face normal into the body; (dx, dy)
    moves G so that the contact is exact (by the gap, ≤ 1e-9 ℓ)."""
    p, th, _, _ = line.state(seg, t)
    e = (math.cos(th), math.sin(th))
    n0 = _zx(e)
    _, which = _gap(ol, line, seg, t, x[0], x[1], x[2])
    c, sn = _rot(x[2])
    V = ol.V
    nv = len(V)
    Vw = np.column_stack((x[0] + c * V[:, 0] - sn * V[:, 1], x[1] + sn * V[:, 0] + c * V[:, 1]))
    d = (Vw[:, 0] - p[0]) * n0[0] + (Vw[:, 1] - p[1]) * n0[1]
    if which[0] == "line":
        side = which[1]
        dd = side * d
        j = int(np.argmin(dd))
        nb = [q for q in ((j - 1) % nv, (j + 1) % nv) if dd[q] - dd[j] <= _FLAT]
        kind = "vertex"
        if nb:
            kind, j = "face", (j if nb[-1] == (j + 1) % nv else (j - 1) % nv)
        shift = dd[j]
        return kind, j, side, 0.0, -side * shift * n0[0], -side * shift * n0[1]
    i = which[1]
    h = line.h
    ends = [(p[0] - h * e[0], p[1] - h * e[1]), (p[0] + h * e[0], p[1] + h * e[1])]
    N = (c * ol.N[i, 0] - sn * ol.N[i, 1], sn * ol.N[i, 0] + c * ol.N[i, 1])
    depth = [(q[0] - Vw[i, 0]) * N[0] + (q[1] - Vw[i, 1]) * N[1] for q in ends]
    m = int(np.argmax(depth))
    side = 1.0 if N[0] * n0[0] + N[1] * n0[1] > 0.0 else -1.0
    kind = "face" if abs(depth[0] - depth[1]) <= _FLAT else "end"  # parallel: a face
    return kind, i, side, (-1.0, 1.0)[m], -depth[m] * N[0], -depth[m] * N[1]


def disc_hull_axes(centres, radii, inward, ends, direction):
    """The separating axes of a hull of discs and a segment (any consistent units, one frame):
    the discs' ``centres`` (k, 2) and ``radii``, the edges' ``inward`` unit normals (k, 2), the
    segment's ``ends`` (2, 2) and unit ``direction``. Returns (gaps, u, tags): for each axis u
    (pointing into the body) min over the hull of u·x − max over the segment of u·y (the
    largest is the distance while apart, ≤ 0 in contact), tagged ("face", ±1) for ±ẑ × the
    direction, ("edge", i), or ("disc", i, k) for the direction from end k to disc i's centre."""
    n0 = np.array([-direction[1], direction[0]])
    us, tags = [n0, -n0], [("face", 1.0), ("face", -1.0)]
    us += list(inward)
    tags += [("edge", i) for i in range(len(inward))]
    for i in np.flatnonzero(radii > 0.0):
        for k in (0, 1):
            dv = centres[i] - ends[k]
            dn = math.hypot(dv[0], dv[1])
            if dn > 0.0:
                us.append(dv / dn)
                tags.append(("disc", int(i), k))
    u = np.array(us)
    kmin = (u @ centres.T - radii[None, :]).min(axis=1)
    return kmin - (u @ ends.T).max(axis=1), u, tags


def _separated(eng, t0, t1, gap, stop_drop):
    """The free body of engine ``eng`` in the regularised time τ (MODEL §5) until t1, the
    pusher's arrival (``gap(t, x, y, φ)`` falls below 0) or the stop: (reason, t)."""
    prob, k = eng.prob, eng.k
    vx, vy, om = eng.X[3], eng.X[4], eng.X[5]
    s0 = math.sqrt(vx * vx + vy * vy + (k * om) ** 2)
    y0 = np.array([vx / s0, vy / s0, k * om / s0, math.log(s0), t0, *eng.X[:3], eng.W[1], eng.W[3]])
    ln_stop = math.log(max(s0, eng.vscale) * stop_drop)
    events = [lambda tau, y: gap(y[4], y[5], y[6], y[7]), lambda tau, y: y[3] - ln_stop]
    if t1 < math.inf:
        events.append(lambda tau, y: t1 - y[4])

    def to_full(tau, y):
        u = y[:3] / math.sqrt(y[0] ** 2 + y[1] ** 2 + y[2] ** 2)
        s = math.exp(y[3])
        eng.X = np.array([y[5], y[6], y[7], s * u[0], s * u[1], s * u[2] / k])
        eng.W[1], eng.W[3] = y[8], y[9]

    def rec(tau, y):
        to_full(tau, y)
        eng.record(y[4], 0)

    reason, tau, y, idx, steps = _integrate(
        prob.rhs, 0.0, y0, math.inf, events, eng.rtol, eng.atol, eng.steps_left, rec
    )
    eng.steps_left -= steps
    to_full(tau, y)
    t = float(y[4])
    if reason == "event" and idx == 2:
        eng.rows[-1][0] = t1  # the row at the root (t1 to an ulp) is the row at t1
        return "end", t1
    if reason == "event" and idx == 1:
        eng.X[3:] = 0.0
        eng.rows[-1][4:7] = [0.0, 0.0, 0.0]
        return "stop", t
    return ("contact" if reason == "event" else reason), t


def _rest(eng, t0, t1, moving, g):
    """A body at rest, separated, until t1 or the pusher arrives (``g(t)`` falls below 0):
    (reason, t); static friction holds it (no load, or a load inside C, MODEL §11)."""
    from scipy.optimize import brentq, minimize_scalar  # lazy: scipy's import cost

    prob = eng.prob
    if (prob.load is not None or prob.incline is not None) and prob.gauge(
        t0, eng.X[2]
    ) > 1.0 + GAUGE_TOL:
        return "no_onset", t0
    if not moving or not t1 < math.inf:
        return "end", t1
    hi = t1
    if g(t1) >= 0.0:
        res = minimize_scalar(
            g, bounds=(t0, t1), method="bounded", options={"xatol": 1e-13 * max(1.0, t1)}
        )
        if not res.fun < 0.0:
            return "end", t1
        hi = float(res.x)
    if g(t0) < 0.0:
        return "contact", t0
    return "contact", brentq(g, t0, hi, xtol=1e-300, rtol=8.9e-16)


def _wrench(prob, t, phi, vx, vy, om):
    """Plane friction (Fx, Fy, M) and loads (Qx, Qy, T) at the twist (vx, vy, ω), natural
    units (MODEL §2, §11)."""
    k = prob.k
    s = math.sqrt(vx * vx + vy * vy + (k * om) ** 2)
    if s > 0.0:
        ax, ay, am = prob.friction_acc(vx / s, vy / s, k * om / s, phi, t)
    else:  # pragma: no cover - a body at rest in contact with a moving pusher
        ax = ay = am = 0.0
    bx, by, bm = prob.b(t, phi)
    return ax, ay, am * k, bx, by, bm * k


def _point_impulse(u, n, tt, r, k2, mu, cone_tol):
    """The plastic impulse at a point contact (MODEL §13): u = 0 after if it lies in the
    cone, else on the cone's edge (on the side of the sticking impulse) with u·n = 0 after;
    u the relative velocity, r = c − G, k² = I/m (natural units, m = 1)."""
    rp = _zx(r)
    kmat = np.eye(2) + np.outer(rp, rp) / k2
    lam = -np.linalg.solve(kmat, np.array(u))
    ln, lt = lam @ n, lam @ tt
    if abs(lt) > mu * ln + cone_tol * (abs(ln) + abs(lt)):
        nn = np.array(n) + mu * math.copysign(1.0, lt) * np.array(tt)
        lam = nn * (-(u[0] * n[0] + u[1] * n[1]) / float(np.array(n) @ kmat @ nn))
    return lam
