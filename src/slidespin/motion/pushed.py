"""Dynamic pushing with a finger: the full dynamics of a body pushed by a point pusher (MODEL §13).

A :class:`~slidespin.motion.pushers.PointPusher` prescribes the finger's path p(t); the contact
decides the force. With ν = (vx, vy, ω) the twist at G, M = diag(m, m, I), W(ν) the exact
plane friction wrench (MODEL §2, §10) and Q, T the applied loads and slope (MODEL §11):

    M ν̇ = W(ν) + (Q, T) + J_cᵀ λ,     λ = λn n + λt t,  λn ≥ 0,  |λt| ≤ μp λn,

with c the contact point on the body's outline, n the inward unit normal there, t = ẑ × n, and
u = J_c ν − ṗ the velocity of the body point at c relative to the finger. The modes and their
switches (MODEL §13):

==================  ==========================================================================
``separated``       gap > 0, λ = 0: the body slides freely (the regularised equations of
                    MODEL §5 with loads, :mod:`slidespin.motion._loaded_problem`) and stops;
                    at rest it stays (no load, or a load inside the static set C, MODEL §11)
``sticking``        u = 0: the contact point is a fixed body point on the finger, so the pose
                    follows from φ and p(t): one degree of freedom, (I + m|r|²) ω̇ =
                    M + T − r × (F + Q − m p̈), λ = m a_G − F − Q (r from G to c)
``sliding_left``,   u·n = 0, u·t ≠ 0, λt = −μp λn sign(u·t): the finger runs along the
``sliding_right``   outline, c = c(s); two degrees of freedom (φ, s), a 3×3 solve for
                    (ω̇, s̈, λn). *Left* and *right* are seen from the finger looking into
                    the body along n: ``sliding_left`` when the finger moves towards +t
                    relative to the body (u·t < 0), ``sliding_right`` when towards −t
==================  ==========================================================================

The contact constraint is kept exactly in these reduced coordinates (no drift: the finger
is on the outline by construction, and u·n = 0 identically). Switches are events located on
the integrator's dense output by Brent's method to ~1e-15 of the time scale √(ℓ/g): sticking
→ sliding when λ reaches the cone's edge; sliding → sticking (or reversed sliding) when u·t
crosses 0; contact → separated when λn crosses 0, and when a sliding finger runs off a
corner of a polygonal outline; separated → contact when the gap closes. A finger that
arrives with a relative normal velocity into the body (also at t = 0 and at a path knot where
ṗ jumps) makes a **plastic impact**: the impulse Λ at c that makes u = 0 if it lies in the
cone, else the impulse on the cone's edge (on the side of the sticking impulse) that makes
u·n = 0; the energy lost, Λ·ṗ − ΔKE ≥ 0, is reported.

Energy (MODEL §13): pusher work + load work = ΔKE + plane friction dissipation + contact slip
dissipation (∫ μp λn |u·t| dt) + impact losses, each integrated with the motion;
``energy_error`` is the residual (an accuracy check).

The outline is :func:`slidespin.contact.outline.body_outline`'s (the footprint's convex hull,
an ellipse or a circle, or ``outline=``), relative to G. Not handled (a ``ValueError`` before
any work): hulls mixing arcs and straight segments (pads with disks), and a line pusher. A
finger touching a polygon exactly at a corner takes the normal of the edge its position
projects on (a corner has no normal); a finger sliding off a corner separates there.

Integration: :class:`scipy.integrate.DOP853` stepped phase by phase (restarted at every
switch and path knot, landing on the knots exactly), in the time t while in contact and in
the regularised time τ of MODEL §5 while separated. Natural units throughout (ℓ, m, g = 1;
ℓ = :attr:`slidespin.Body.length_unit`).
"""

from __future__ import annotations

import math

import numpy as np

from slidespin import _validate as v
from slidespin.contact.body import Body, check_body_friction
from slidespin.contact.friction import FrictionTensor
from slidespin.contact.incline import Incline
from slidespin.contact.outline import body_outline
from slidespin.contact.static_set import check_anisotropy
from slidespin.motion._loaded_problem import _Problem
from slidespin.motion._stick_slip import GAUGE_TOL
from slidespin.motion.loads import Load
from slidespin.motion.outcomes import PUSH_MODES
from slidespin.motion.pushed_trajectory import PushedTrajectory
from slidespin.motion.pushers import LinePusher, PointPusher
from slidespin.motion.state import State

__all__ = ["simulate_pushed"]


_SEP, _STICK, _LEFT, _RIGHT = 0, 1, 2, 3
_TOUCH = 1e-9  # |gap| [ℓ] within which a finger given at t = 0 touches the outline
_GAP_TOL = 1e-13  # [ℓ] a separated finger re-contacts where the gap falls below −_GAP_TOL
_CONE_TOL = 1e-12  # relative slack of the friction cone (sticking with μp = 0 and λt = 0)
_VEL_TOL = 1e-11  # relative velocity [of the speed scale] below which u·n, u·t count as 0
_STOP_DROP = 1e-13  # a separated body stops when its speed falls below this of its scale


def _rot(phi):
    return math.cos(phi), math.sin(phi)


# ------------------------------------------------------------------------------------------
# the outline (body frame, relative to G, natural units)


class _Outline:
    """Convex outline: a CCW polygon (pieces = edges, s = arc length from the edge's start)
    or an ellipse (one periodic piece, s = the parametric angle)."""

    def __init__(self, body: Body, a: float, outline=None):
        ol = body_outline(body, outline)
        self.poly = ol.kind == "hull"
        if not self.poly:
            self.c0 = (float(ol.centre[0]) / a, float(ol.centre[1]) / a)
            self.A, self.B = ol.axes[0] / a, ol.axes[1] / a
            self.cb, self.sb = _rot(float(ol.angle))
            return
        if not ol.is_polygon:
            raise ValueError(
                f"body = {v._short(body)} is invalid for a pushed run: its outline has round "
                "parts on a hull with straight ones (pads with disks), which the pushing engine "
                "does not handle yet; valid: a polygonal outline, an ellipse or a circle (give "
                "outline=)"
            )
        hull = np.asarray(ol.vertices, dtype=float) / a
        self.V = hull
        e = np.roll(hull, -1, axis=0) - hull
        self.L = np.hypot(e[:, 0], e[:, 1])
        self.E = e / self.L[:, None]
        self.N = np.column_stack((-self.E[:, 1], self.E[:, 0]))  # inward (CCW)

    def gap(self, q0, q1):
        """An implicit signed gap of the body point (q0, q1): > 0 outside, 0 on the outline."""
        if self.poly:
            d = -(self.N[:, 0] * (q0 - self.V[:, 0]) + self.N[:, 1] * (q1 - self.V[:, 1]))
            return float(d.max())
        x, y = self._local(q0, q1)
        x, y = x / self.A, y / self.B
        return (math.sqrt(x * x + y * y) - 1.0) * min(self.A, self.B)

    def _local(self, q0, q1):
        dx, dy = q0 - self.c0[0], q1 - self.c0[1]
        return self.cb * dx + self.sb * dy, -self.sb * dx + self.cb * dy

    def locate(self, q0, q1):
        """(piece, s) of the outline point nearest to the body point (q0, q1) on the outline."""
        if self.poly:
            d = -(self.N[:, 0] * (q0 - self.V[:, 0]) + self.N[:, 1] * (q1 - self.V[:, 1]))
            i = int(np.argmax(d))
            s = (q0 - self.V[i, 0]) * self.E[i, 0] + (q1 - self.V[i, 1]) * self.E[i, 1]
            return i, min(max(s, 0.0), float(self.L[i]))
        x, y = self._local(q0, q1)
        return 0, math.atan2(y / self.B, x / self.A)

    def geom(self, piece, s):
        """Body frame c(s), c'(s), c''(s) and the inward unit normal n(s)."""
        if self.poly:
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


def _integrate(fun, t0, y0, t1, events, rtol, atol, budget, rec):
    """DOP853 from t0 to t1 with terminal events g(t, y) that fire where g falls below 0.

    Returns (reason, t, y, index, steps): reason ``end``, ``event`` (index), ``max_steps``
    or ``failed``. Every accepted step is passed to ``rec(t, y)``."""
    from scipy.integrate import DOP853  # lazy: scipy's import cost
    from scipy.optimize import brentq

    solver = DOP853(fun, t0, y0, t1, rtol=rtol, atol=atol)
    g_old = [e(t0, y0) for e in events]
    steps = 0
    while True:
        if steps >= budget:
            return "max_steps", solver.t, solver.y, -1, steps
        t_old = solver.t
        solver.step()
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
        g_old = g_new


# ------------------------------------------------------------------------------------------
# the engine


class _Engine:
    """One pushed run in natural units; the state between phases is ``self.X`` = (x, y, φ,
    vx, vy, ω), the works ``self.W`` = (pusher, friction, slip, load) and ``self.loss``."""

    def __init__(self, prob, outline, finger, rtol, max_steps):
        self.prob, self.ol, self.fg = prob, outline, finger
        self.k = prob.k
        self.mu = finger.mu
        self.rtol, self.atol = rtol, rtol * 1e-2
        self.steps_left = max_steps
        self.rows: list = []
        self.switches: list = []
        self.impacts: list = []
        self.W = np.zeros(4)
        self.loss = 0.0
        self.seg = 0
        vmax = float(np.max(np.hypot(finger.v[:, 0], finger.v[:, 1]))) if finger.v.size else 0.0
        self.vscale = max(vmax, 1e-300)

    # ---- forces ----------------------------------------------------------------------

    def wrench(self, t, phi, vx, vy, om):
        """Plane friction (Fx, Fy, M) and loads (Qx, Qy, T) at the twist (vx, vy, ω)."""
        k = self.k
        s = math.sqrt(vx * vx + vy * vy + (k * om) ** 2)
        if s > 0.0:
            ax, ay, am = self.prob.friction_acc(vx / s, vy / s, k * om / s, phi, t)
        else:  # pragma: no cover - a body at rest in contact with a moving finger
            ax = ay = am = 0.0
        bx, by, bm = self.prob.b(t, phi)
        return ax, ay, am * k, bx, by, bm * k

    def kin(self, phi, piece, s):
        """World r (G → c), d = R c', d2 = R c'', n (inward), t = ẑ × n."""
        c, sn = _rot(phi)
        cb, c1, c2, nb = self.ol.geom(piece, s)
        r = (c * cb[0] - sn * cb[1], sn * cb[0] + c * cb[1])
        d = (c * c1[0] - sn * c1[1], sn * c1[0] + c * c1[1])
        d2 = (c * c2[0] - sn * c2[1], sn * c2[0] + c * c2[1])
        n = (c * nb[0] - sn * nb[1], sn * nb[0] + c * nb[1])
        return r, d, d2, n, (-n[1], n[0])

    def stick_acc(self, t, y):
        """Sticking: y = (φ, ω, works...). Returns (ω̇, λ, vG, powers, r, n)."""
        phi, om = y[0], y[1]
        pv = self.fg.v[self.seg]
        r, _, _, n, _ = self.kin(phi, self.piece, self.s)
        rp = (-r[1], r[0])
        vx, vy = pv[0] - om * rp[0], pv[1] - om * rp[1]
        fx, fy, m, qx, qy, tq = self.wrench(t, phi, vx, vy, om)
        k2 = self.k * self.k
        omd = (m + tq - (r[0] * (fy + qy) - r[1] * (fx + qx))) / (k2 + r[0] ** 2 + r[1] ** 2)
        lx = -omd * rp[0] + om * om * r[0] - fx - qx
        ly = -omd * rp[1] + om * om * r[1] - fy - qy
        pw = (lx * pv[0] + ly * pv[1], fx * vx + fy * vy + m * om, 0.0, qx * vx + qy * vy + tq * om)
        return omd, (lx, ly), (vx, vy), pw, r, n

    def slide_acc(self, t, y):
        """Sliding: y = (φ, ω, s, ṡ, works...). Returns (ω̇, s̈, λ, vG, powers, r, n, u·t)."""
        phi, om, s, sd = y[0], y[1], y[2], y[3]
        pv = self.fg.v[self.seg]
        r, d, d2, n, tt = self.kin(phi, self.piece, s)
        rp, dp = (-r[1], r[0]), (-d[1], d[0])
        vx = pv[0] - om * rp[0] - sd * d[0]
        vy = pv[1] - om * rp[1] - sd * d[1]
        fx, fy, m, qx, qy, tq = self.wrench(t, phi, vx, vy, om)
        sig = -self.mu * self.dirn
        nx, ny = n[0] + sig * tt[0], n[1] + sig * tt[1]
        rhs = np.array(
            [
                fx + qx - om * om * r[0] + 2.0 * om * sd * dp[0] + sd * sd * d2[0],
                fy + qy - om * om * r[1] + 2.0 * om * sd * dp[1] + sd * sd * d2[1],
                m + tq,
            ]
        )
        mat = np.array(
            [
                [-rp[0], -d[0], -nx],
                [-rp[1], -d[1], -ny],
                [self.k * self.k, 0.0, -(r[0] * ny - r[1] * nx)],
            ]
        )
        omd, sdd, ln = np.linalg.solve(mat, rhs)
        lx, ly = ln * nx, ln * ny
        ut = -sd * (d[0] * tt[0] + d[1] * tt[1])
        pw = (
            lx * pv[0] + ly * pv[1],
            fx * vx + fy * vy + m * om,
            self.mu * ln * abs(ut),
            qx * vx + qy * vy + tq * om,
        )
        return omd, sdd, (lx, ly), (vx, vy), pw, r, n, ut

    # ---- phases ----------------------------------------------------------------------

    def record(self, t, mode, lam=(0.0, 0.0), cpt=(math.nan, math.nan)):
        x = self.X
        p = self.fg.pos(self.seg, t)
        self.rows.append(
            [t, *x, lam[0], lam[1], cpt[0], cpt[1], mode, *self.W, self.loss, p[0], p[1]]
        )

    def _full_stick(self, t, y):
        omd, lam, vg, _, r, n = self.stick_acc(t, y)
        p = self.fg.pos(self.seg, t)
        self.X = np.array([p[0] - r[0], p[1] - r[1], y[0], vg[0], vg[1], y[1]])
        self.W = np.array(y[2:6])
        return lam, p, None

    def _full_slide(self, t, y):
        omd, sdd, lam, vg, _, r, n, ut = self.slide_acc(t, y)
        p = self.fg.pos(self.seg, t)
        self.X = np.array([p[0] - r[0], p[1] - r[1], y[0], vg[0], vg[1], y[1]])
        self.W = np.array([y[4], y[5], y[6], y[7]])
        return lam, p, ut

    def run_stick(self, t0, t1):
        mu = self.mu

        def fun(t, y):
            omd, lam, vg, pw, r, n = self.stick_acc(t, y)
            return np.array([y[1], omd, *pw])

        def lam_nt(t, y):
            _, lam, _, _, _, n = self.stick_acc(t, y)
            ln = lam[0] * n[0] + lam[1] * n[1]
            lt = -lam[0] * n[1] + lam[1] * n[0]
            return ln, lt, abs(ln) + abs(lt)

        def ev_n(t, y):
            return lam_nt(t, y)[0]

        def ev_p(t, y):
            ln, lt, sc = lam_nt(t, y)
            return mu * ln - lt + _CONE_TOL * sc

        def ev_m(t, y):
            ln, lt, sc = lam_nt(t, y)
            return mu * ln + lt + _CONE_TOL * sc

        def rec(t, y):
            lam, p, _ = self._full_stick(t, y)
            self.record(t, _STICK, lam, p)

        y0 = np.array([self.X[2], self.X[5], *self.W])
        return self._phase(fun, t0, y0, t1, [ev_n, ev_p, ev_m], rec, self._full_stick)

    def run_slide(self, t0, t1):
        def fun(t, y):
            omd, sdd, lam, vg, pw, *_ = self.slide_acc(t, y)
            return np.array([y[1], omd, y[3], sdd, *pw])

        def ev_n(t, y):
            lam, n = self.slide_acc(t, y)[2], self.slide_acc(t, y)[6]
            return lam[0] * n[0] + lam[1] * n[1]

        def ev_slip(t, y):
            return self.dirn * self.slide_acc(t, y)[7]

        events = [ev_n, ev_slip]
        if self.ol.poly:
            length = float(self.ol.L[self.piece])
            events += [lambda t, y: y[2], lambda t, y: length - y[2]]

        def rec(t, y):
            lam, p, _ = self._full_slide(t, y)
            self.record(t, _LEFT if self.dirn < 0 else _RIGHT, lam, p)

        r, d, _, n, tt = self.kin(self.X[2], self.piece, self.s)
        pv = self.fg.v[self.seg]
        ux = self.X[3] - self.X[5] * r[1] - pv[0]
        uy = self.X[4] + self.X[5] * r[0] - pv[1]
        sd = -(ux * d[0] + uy * d[1]) / (d[0] ** 2 + d[1] ** 2)
        y0 = np.array([self.X[2], self.X[5], self.s, sd, *self.W])
        out = self._phase(fun, t0, y0, t1, events, rec, self._full_slide)
        self.s = float(out[2][2])
        return out

    def run_separated(self, t0, t1):
        """The free body in the regularised time τ (MODEL §5) until t1, a contact or the stop."""
        prob, k = self.prob, self.k
        vx, vy, om = self.X[3], self.X[4], self.X[5]
        s0 = math.sqrt(vx * vx + vy * vy + (k * om) ** 2)
        y0 = np.array(
            [vx / s0, vy / s0, k * om / s0, math.log(s0), t0, *self.X[:3], self.W[1], self.W[3]]
        )
        ln_stop = math.log(max(s0, self.vscale) * _STOP_DROP)
        seg = self.seg

        def gap(tau, y):
            px, py = self.fg.pos(seg, y[4])
            c, sn = _rot(y[7])
            dx, dy = px - y[5], py - y[6]
            return self.ol.gap(c * dx + sn * dy, -sn * dx + c * dy) + _GAP_TOL

        events = [gap, lambda tau, y: y[3] - ln_stop]
        if t1 < math.inf:
            events.append(lambda tau, y: t1 - y[4])

        def to_full(tau, y):
            u = y[:3] / math.sqrt(y[0] ** 2 + y[1] ** 2 + y[2] ** 2)
            s = math.exp(y[3])
            self.X = np.array([y[5], y[6], y[7], s * u[0], s * u[1], s * u[2] / k])
            self.W[1], self.W[3] = y[8], y[9]

        def rec(tau, y):
            to_full(tau, y)
            self.record(y[4], _SEP)

        reason, tau, y, idx, steps = _integrate(
            prob.rhs, 0.0, y0, math.inf, events, self.rtol, self.atol, self.steps_left, rec
        )
        self.steps_left -= steps
        to_full(tau, y)
        t = float(y[4])
        if reason == "event" and idx == 2:
            return "end", t1, idx
        if reason == "event" and idx == 1:
            self.X[3:] = 0.0
            self.rows[-1][4:7] = [0.0, 0.0, 0.0]
            return "stop", t, idx
        return reason, t, idx

    def _phase(self, fun, t0, y0, t1, events, rec, full):
        reason, t, y, idx, steps = _integrate(
            fun, t0, y0, t1, events, self.rtol, self.atol, self.steps_left, rec
        )
        self.steps_left -= steps
        full(t, y)
        return reason, t, y, idx

    # ---- switches --------------------------------------------------------------------

    def contact_velocity(self):
        """u = J_c ν − ṗ at the current contact, with n, t and r (world)."""
        x = self.X
        r, _, _, n, tt = self.kin(x[2], self.piece, self.s)
        pv = self.fg.v[self.seg]
        u = (x[3] - x[5] * r[1] - pv[0], x[4] + x[5] * r[0] - pv[1])
        return u, n, tt, r

    def vtol(self):
        x = self.X
        return _VEL_TOL * (self.vscale + math.hypot(x[3], x[4]) + abs(self.k * x[5]))

    def impact(self, t):
        """Plastic impact at the contact (MODEL §13): u·n = 0 after, u = 0 if in the cone."""
        u, n, tt, r = self.contact_velocity()
        k2 = self.k * self.k
        rp = (-r[1], r[0])
        kmat = np.array(
            [
                [1.0 + rp[0] ** 2 / k2, rp[0] * rp[1] / k2],
                [rp[0] * rp[1] / k2, 1.0 + rp[1] ** 2 / k2],
            ]
        )
        lam = -np.linalg.solve(kmat, np.array(u))
        ln, lt = lam @ n, lam @ tt
        if abs(lt) > self.mu * ln + _CONE_TOL * (abs(ln) + abs(lt)):
            sig = self.mu * math.copysign(1.0, lt)
            nn = np.array(n) + sig * np.array(tt)
            un = u[0] * n[0] + u[1] * n[1]
            lam = nn * (-un / float(np.array(n) @ kmat @ nn))
        x = self.X
        pv = self.fg.v[self.seg]
        ke0 = 0.5 * (x[3] ** 2 + x[4] ** 2 + k2 * x[5] ** 2)
        x[3] += lam[0]
        x[4] += lam[1]
        x[5] += (r[0] * lam[1] - r[1] * lam[0]) / k2
        ke1 = 0.5 * (x[3] ** 2 + x[4] ** 2 + k2 * x[5] ** 2)
        work = float(lam[0] * pv[0] + lam[1] * pv[1])
        self.W[0] += work
        self.loss += work - (ke1 - ke0)
        self.impacts.append((t, float(lam[0]), float(lam[1]), float(work - (ke1 - ke0))))

    def decide(self, t, exclude=()):
        """The consistent contact mode at t (u·n = 0), not one of ``exclude``."""
        u, n, tt, r = self.contact_velocity()
        ut = u[0] * tt[0] + u[1] * tt[1]
        x = self.X
        if abs(ut) > self.vtol():
            self.dirn = 1.0 if ut > 0.0 else -1.0
            mode = _RIGHT if ut > 0.0 else _LEFT
            if mode not in exclude:
                _, d, _, _, _ = self.kin(x[2], self.piece, self.s)
                sd = -(u[0] * d[0] + u[1] * d[1]) / (d[0] ** 2 + d[1] ** 2)
                lam, n2 = self.slide_acc(t, [x[2], x[5], self.s, sd])[2], n
                return mode if lam[0] * n2[0] + lam[1] * n2[1] >= 0.0 else _SEP
        _, lam, _, _, _, _ = self.stick_acc(t, [x[2], x[5]])
        ln, lt = lam[0] * n[0] + lam[1] * n[1], lam[0] * tt[0] + lam[1] * tt[1]
        if ln < 0.0:
            return _SEP
        if _STICK not in exclude and abs(lt) <= self.mu * ln + _CONE_TOL * (abs(ln) + abs(lt)):
            return _STICK
        first = -1.0 if lt > 0.0 else 1.0  # friction saturates on the side of λt
        for dirn in (first, -first):
            mode = _RIGHT if dirn > 0.0 else _LEFT
            if mode in exclude:
                continue
            self.dirn = dirn
            omd, sdd, lam2, _, _, _, _, _ = self.slide_acc(t, [x[2], x[5], self.s, 0.0])
            _, d, _, _, _ = self.kin(x[2], self.piece, self.s)
            utd = -sdd * (d[0] * tt[0] + d[1] * tt[1])
            if lam2[0] * n[0] + lam2[1] * n[1] < 0.0:
                return _SEP
            if dirn * utd >= 0.0:
                return mode
        return -1  # no consistent mode

    def touch(self, t):
        """Put the contact on the outline where the finger is (G moved by the gap, ≤ 1e-9 ℓ)."""
        x = self.X
        px, py = self.fg.pos(self.seg, t)
        c, sn = _rot(x[2])
        dx, dy = px - x[0], py - x[1]
        self.piece, self.s = self.ol.locate(c * dx + sn * dy, -sn * dx + c * dy)
        r = self.kin(x[2], self.piece, self.s)[0]
        x[0], x[1] = px - r[0], py - r[1]

    def contact_switch(self, t, impacts=True):
        """The mode after a contact starts or the finger's velocity jumps (impact if any)."""
        x = self.X
        pv = self.fg.v[self.seg]
        if not np.any(x[3:]) and not np.any(pv):
            return _SEP  # both at rest: nothing pushes
        u, n, _, _ = self.contact_velocity()
        un = u[0] * n[0] + u[1] * n[1]
        if un > self.vtol():
            return _SEP
        if un < -self.vtol() and impacts:
            self.impact(t)
        return self.decide(t)

    def wait(self, t0, t1):
        """A body at rest, separated, until t1 or the finger arrives (static friction holds
        it: no load, or a load inside C, MODEL §11)."""
        from scipy.optimize import brentq, minimize_scalar  # lazy: scipy's import cost

        prob = self.prob
        if (prob.load is not None or prob.incline is not None) and prob.gauge(
            t0, self.X[2]
        ) > 1.0 + GAUGE_TOL:
            return "no_onset", t0
        if not np.any(self.fg.v[self.seg]) or not t1 < math.inf:
            return "end", t1
        x = self.X
        c, sn = _rot(x[2])

        def g(t):
            px, py = self.fg.pos(self.seg, t)
            dx, dy = px - x[0], py - x[1]
            return self.ol.gap(c * dx + sn * dy, -sn * dx + c * dy) + _GAP_TOL

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

    # ---- the run ---------------------------------------------------------------------

    def record_now(self, t):
        """A row at t in the current mode (after a switch)."""
        x = self.X
        if self.mode == _SEP:
            self.record(t, _SEP)
        elif self.mode == _STICK:
            lam = self.stick_acc(t, [x[2], x[5]])[1]
            self.record(t, _STICK, lam, self.fg.pos(self.seg, t))
        else:
            u, n, tt, r = self.contact_velocity()
            _, d, _, _, _ = self.kin(x[2], self.piece, self.s)
            sd = -(u[0] * d[0] + u[1] * d[1]) / (d[0] ** 2 + d[1] ** 2)
            lam = self.slide_acc(t, [x[2], x[5], self.s, sd])[2]
            self.record(t, self.mode, lam, self.fg.pos(self.seg, t))

    def switch(self, t, new):
        if new == -1:
            return False
        if new in (_LEFT, _RIGHT):
            self.dirn = -1.0 if new == _LEFT else 1.0
        if new != self.mode:
            self.switches.append((t, PUSH_MODES[self.mode], PUSH_MODES[new]))
        self.mode = new
        self.record_now(t)
        return True

    def run(self, t_end, max_phases):
        self.seg = self.fg.segment(0.0)[0]
        px, py = self.fg.pos(self.seg, 0.0)
        x = self.X
        c, sn = _rot(x[2])
        self.mode = _SEP
        status, t = "ok", 0.0
        gap0 = self.ol.gap(c * (px - x[0]) + sn * (py - x[1]), -sn * (px - x[0]) + c * (py - x[1]))
        if abs(gap0) <= _TOUCH:  # the contact holds from t = 0: no switch at t = 0
            self.touch(0.0)
            before = self.X.copy()
            mode = self.contact_switch(0.0)
            if mode == -1:
                self.record(0.0, _SEP)
                return "indeterminate", 0.0
            if self.impacts:  # the finger arrives at t = 0: the state before, separated
                after, w, loss = self.X, self.W.copy(), self.loss
                self.X, self.W[:], self.loss = before, 0.0, 0.0
                self.record(0.0, _SEP)
                self.X, self.W, self.loss = after, w, loss
                self.switch(0.0, mode)
            else:  # touching and moving with the body: the contact mode from the start
                self.mode = mode
                if mode in (_LEFT, _RIGHT):
                    self.dirn = -1.0 if mode == _LEFT else 1.0
                self.record_now(0.0)
        else:
            self.record(0.0, _SEP)
        phases, same_t, t_last = 0, 0, -1.0
        while t < t_end:
            phases += 1
            if phases > max_phases:
                return "max_phases", t
            same_t = same_t + 1 if t == t_last else 0
            if same_t > 8:
                return "indeterminate", t
            t_last = t
            self.seg, _, te = self.fg.segment(t)
            t1 = min(te, t_end)
            mode = self.mode
            if mode == _SEP and not np.any(self.X[3:]):
                reason, t = self.wait(t, t1)
                if reason == "no_onset":
                    return "no_onset", t
                if reason == "contact":
                    self.touch(t)
                    self.record(t, _SEP)
                    if not self.switch(t, self.contact_switch(t)):
                        return "indeterminate", t
                    continue
                self.record(t, _SEP)
            elif mode == _SEP:
                reason, t, idx = self.run_separated(t, t1)
                if reason == "event":  # the finger arrives
                    self.touch(t)
                    if not self.switch(t, self.contact_switch(t)):
                        return "indeterminate", t
                    continue
                if reason == "stop":
                    continue
            else:
                run = self.run_stick if mode == _STICK else self.run_slide
                reason, t, _, idx = run(t, t1)
                if reason == "event":
                    if idx == 0 or idx >= 2 and mode != _STICK:  # λn < 0, or off a corner
                        new = _SEP
                    else:
                        new = self.decide(t, exclude=(mode,))
                    if not self.switch(t, new):
                        return "indeterminate", t
                    continue
            if reason == "max_steps":
                return "max_steps", t
            if reason == "failed":
                return "step_too_small", t
            t = t1  # a knot (or t_end)
            if t >= t_end:
                break
            self.seg = self.fg.segment(t)[0]
            if self.mode != _SEP:
                if not self.switch(t, self.contact_switch(t)):
                    return "indeterminate", t
        return status, t


# ------------------------------------------------------------------------------------------
# the entry


def simulate_pushed(
    body: Body,
    friction: FrictionTensor,
    state: State,
    pusher: PointPusher,
    t_end: float,
    *,
    g: float = 9.81,
    rtol: float = 1e-10,
    max_steps: int = 200_000,
    max_phases: int = 10_000,
    load: Load | None = None,
    incline: Incline | None = None,
    outline: object = None,
) -> PushedTrajectory:
    """Integrate a body pushed by a finger over [0, t_end] (MODEL §13, with §11's loads).

    Parameters
    ----------
    body, friction : Body, FrictionTensor
        The body and its friction tensor (any patch whose outline is handled: ellipses,
        disks, rings, polygons, rectangles, pads of polygons).
    state : State
        Initial position, angle and velocities (SI). The finger at t = 0 either touches the
        outline (within 1e-9 of the body's length unit ℓ: the contact starts there, with a
        plastic impact if it moves into the body) or lies outside it (separated until it
        arrives); a finger inside the body is refused.
    pusher : PointPusher
        The finger: its path and μp (:class:`slidespin.motion.pushers.PointPusher`).
    t_end : float
        End of the run [s], finite and > 0.
    g : float, default 9.81
        Gravitational acceleration [m/s²], in [1e-6, 1e6].
    rtol : float, default 1e-10
        Relative tolerance of the integration (absolute tolerance rtol·1e-2 in natural
        units), in (0, 1e-3].
    max_steps : int, default 200000
        Budget of integrator steps over the run (status ``max_steps`` when it runs out).
    max_phases : int, default 10000
        Budget of phases (mode switches and knots; status ``max_phases``).
    load : Load or None
        Applied force and torque (MODEL §11).
    incline : Incline or None
        A tilted plane (MODEL §11).
    outline : None, vertices (n, 2), a footprint or an Ellipse
        The outline the finger touches, body frame [m], for a body wider than its patch
        (:func:`slidespin.contact.outline.body_outline`); default: the patch's.

    Returns
    -------
    PushedTrajectory
        The motion, the finger's force, the contact point and mode over time, the switches,
        impacts and energy balance; ``status`` says whether the run reached ``t_end``.

    Notes
    -----
    MODEL §13: M ν̇ = W(ν) + J_cᵀ λ (+ loads, §11) with the contact modes separated,
    sticking, sliding left and right, plastic impacts, and exact switches (module notes).
    """
    check_body_friction(body, friction)
    if load is not None or incline is not None:
        check_anisotropy(body, friction, "static friction under a load or on an incline")
    if not isinstance(state, State):
        raise ValueError(f"state = {v._short(state)} is invalid; valid values: a slidespin.State")
    if isinstance(pusher, LinePusher):
        raise ValueError(
            f"pusher = {v._short(pusher)} is invalid: the dynamics of a line pusher is not "
            "implemented yet; valid values: a PointPusher"
        )
    if not isinstance(pusher, PointPusher):
        raise ValueError(f"pusher = {v._short(pusher)} is invalid; valid values: a PointPusher")
    if load is not None and not isinstance(load, Load):
        raise ValueError(
            f"load = {v._short(load)} is invalid; valid values: a slidespin.Load or None"
        )
    if incline is not None and not isinstance(incline, Incline):
        raise ValueError(
            f"incline = {v._short(incline)} is invalid; valid values: a slidespin.Incline or None"
        )
    t_end = v.positive("t_end", t_end, "s")
    g = v.bounded("g", g, *v.GRAVITY, "m/s^2")
    rtol = v.in_range("rtol", rtol, 0.0, 1e-3, lo_open=True)
    for name, val in (("max_steps", max_steps), ("max_phases", max_phases)):
        if isinstance(val, bool) or not isinstance(val, (int, np.integer)) or val < 1:
            raise ValueError(f"{name} = {val!r} is invalid; valid range: integer >= 1")
    prob = _Problem(body, friction, load, incline, g)
    prob.b(0.0, state.phi)  # the load's range, before any work
    a, tu, vu = prob.a, prob.t_unit, prob.v_unit
    geometry = _Outline(body, a, outline)
    finger = _Finger(pusher, a, tu)
    eng = _Engine(prob, geometry, finger, rtol, int(max_steps))
    eng.X = np.array(
        [state.x / a, state.y / a, state.phi, state.vx / vu, state.vy / vu, state.omega * tu]
    )
    px, py = finger.pos(finger.segment(0.0)[0], 0.0)
    c, sn = _rot(state.phi)
    dx, dy = px - eng.X[0], py - eng.X[1]
    gap0 = geometry.gap(c * dx + sn * dy, -sn * dx + c * dy)
    if gap0 < -_TOUCH:
        raise ValueError(
            f"pusher = {v._short(pusher)} is invalid with state = {v._short(state)}: the finger "
            f"starts {-gap0 * a:.6g} m inside the body's outline; valid: on the outline (within "
            f"{_TOUCH:g} of the body's length unit) or outside it"
        )
    status, t_stop = eng.run(t_end / tu, int(max_phases))
    messages = {
        "max_steps": f"the budget of max_steps = {max_steps} integrator steps ran out",
        "max_phases": f"more than max_phases = {max_phases} phases",
        "step_too_small": "the integrator could not meet its tolerance",
        "no_onset": "a separated body at rest under a load beyond static friction (its slow "
        "start is not integrated by the pushing engine)",
        "indeterminate": "no contact mode is consistent here (a Painleve-type paradox)",
    }
    message = "" if status == "ok" else f"{messages[status]} at t = {t_stop * tu:.12g} s"
    arr = np.array(eng.rows, dtype=float)
    scale = body.mass * g * a
    k = prob.k
    ke = 0.5 * (arr[:, 4] ** 2 + arr[:, 5] ** 2 + (k * arr[:, 6]) ** 2) * scale
    wp, wf, ws, wl, loss = (arr[:, j] * scale for j in (12, 13, 14, 15, 16))
    err = abs((ke[-1] - ke[0]) - wf[-1] + ws[-1] + loss[-1] - wp[-1] - wl[-1])
    codes = arr[:, 11].astype(int)
    cpt = arr[:, 9:11] * a
    cpt[codes == _SEP] = math.nan
    t_si = arr[:, 0] * tu
    if status == "ok":
        t_si[-1] = t_end
    return PushedTrajectory(
        t=t_si,
        x=arr[:, 1] * a,
        y=arr[:, 2] * a,
        phi=arr[:, 3].copy(),
        vx=arr[:, 4] * vu,
        vy=arr[:, 5] * vu,
        omega=arr[:, 6] / tu,
        pusher_position=arr[:, 17:19] * a,
        pusher_force=arr[:, 7:9] * body.mass * g,
        contact_point=cpt,
        mode=tuple(PUSH_MODES[c] for c in codes),
        mode_code=codes,
        switches=tuple((float(t * tu), m0, m1) for t, m0, m1 in eng.switches),
        impacts=tuple(
            (float(t * tu), lx * body.mass * vu, ly * body.mass * vu, e * scale)
            for t, lx, ly, e in eng.impacts
        ),
        kinetic_energy=ke,
        pusher_work=wp,
        friction_work=-wf,
        contact_slip_work=ws,
        load_work=wl,
        impact_loss=loss,
        energy_error=float(err),
        status=status,
        message=message,
        n_rhs=prob.n_rhs,
        body=body,
        friction=friction,
        initial_state=state,
        pusher=pusher,
        g=g,
    )
