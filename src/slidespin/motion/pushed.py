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
an ellipse or a circle, or ``outline=``), relative to G. A hull of pads with disks is a
sequence of straight edges and circular arcs meeting smoothly: a sliding finger passes from one
to the next without a switch (an event at the junction restarts the step, where the curvature
jumps). At a sharp corner (a polygon's vertex) the finger sticks while λ lies in the union of
the two edges' friction cones, else slides onto an edge or leaves
(:mod:`slidespin.motion._pushed_vertex`).

A :class:`~slidespin.motion.pushers.LinePusher` is handed to
:func:`slidespin.motion.pushed_line.simulate_line` (face, vertex and end contacts); the outline,
path and stepping helpers shared by both engines are in :mod:`slidespin.motion._pushed_geometry`.

Integration: :class:`scipy.integrate.DOP853` stepped phase by phase (restarted at every
switch and path knot, landing on the knots exactly), in the time t while in contact and in
the regularised time τ of MODEL §5 while separated. Natural units throughout (ℓ, m, g = 1;
ℓ = :attr:`slidespin.Body.length_unit`).
"""

from __future__ import annotations

import math

import numpy as np

from slidespin import _validate as v
from slidespin.contact.body import Body
from slidespin.contact.friction import FrictionTensor
from slidespin.contact.incline import Incline
from slidespin.motion import _pushed_vertex as corner
from slidespin.motion._loaded_problem import _Problem
from slidespin.motion._pushed_geometry import (
    _Finger,
    _integrate,
    _integrate_contact,
    _Outline,
    _rot,
    _Run,
    check_inputs,
)
from slidespin.motion._stick_slip import GAUGE_TOL
from slidespin.motion.loads import Load
from slidespin.motion.outcomes import PUSH_MODES
from slidespin.motion.pushed_line import simulate_line
from slidespin.motion.pushed_trajectory import PushedTrajectory, _assemble
from slidespin.motion.pushers import LinePusher, PointPusher
from slidespin.motion.state import State, reduced_angle

__all__ = ["simulate_pushed"]


_SEP, _STICK, _LEFT, _RIGHT = 0, 1, 2, 3
_TOUCH = 1e-9  # |gap| [ℓ] within which a finger given at t = 0 touches the outline
_GAP_TOL = 1e-13  # [ℓ] a separated finger re-contacts where the gap falls below −_GAP_TOL
_CONE_TOL = 1e-12  # relative slack of the friction cone (sticking with μp = 0 and λt = 0)
_VEL_TOL = 1e-11  # relative velocity [of the speed scale] below which u·n, u·t count as 0
_STOP_DROP = 1e-13  # a separated body stops when its speed falls below this of its scale


# ------------------------------------------------------------------------------------------
# the engine


class _Engine(_Run):
    """One pushed run in natural units; the state between phases is ``self.X`` = (x, y, φ,
    vx, vy, ω), the works ``self.W`` = (pusher, friction, slip, load) and ``self.loss``."""

    def __init__(self, prob, outline, finger, rtol, max_steps):
        super().__init__(prob, outline, finger.mu, rtol, max_steps)
        self.fg = finger
        self.vert = None  # the vertex of a corner contact (_pushed_vertex)
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

        events = [ev_n, ev_p, ev_m]
        if self.vert is not None:  # at a corner: the union of the edges' cones
            events = [lambda t, y, i=i: corner.stick_room(self, t, y)[i] for i in range(3)]
        y0 = np.array([self.X[2], self.X[5], *self.W])
        return self._phase(fun, t0, y0, t1, events, rec, self._full_stick)

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
            length = self.ol.length(self.piece)
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
        reason, t, y, idx, steps = _integrate_contact(
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
        if self.vert is not None:
            lam = corner.impulse(self, lam, np.array(u), kmat)
        elif abs(lt) > self.mu * ln + _CONE_TOL * (abs(ln) + abs(lt)):
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
        if self.vert is not None:
            return corner.decide(self, t, exclude)
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
        self.vert = corner.corner_at(self.ol, self.piece, self.s)
        if self.vert is not None:
            self.piece, self.s = self.vert, 0.0
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
        if self.vert is not None:
            un = corner.normal_velocity(self, u)
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
        while t < t_end:
            stop = self.next_phase(t, max_phases)
            if stop:
                return stop, t
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
                    if idx >= 2 and mode != _STICK:  # the finger reaches a corner
                        new = corner.off_edge(self, t, idx)
                    elif idx == 0:  # λn < 0
                        new = _SEP
                    else:
                        new = self.decide(t, exclude=(mode,))
                    if idx == 0 and self.rows[-1][0] == t:  # λn = 0 at the root (§13): the
                        self.rows[-1][7:9] = [0.0, 0.0]  # cone leaves λt = 0, not root noise
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
    pusher: PointPusher | LinePusher,
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
    """Integrate a body pushed by a finger or a line pusher over [0, t_end] (MODEL §13, §11).

    Parameters
    ----------
    body, friction : Body, FrictionTensor
        The body and its friction tensor (every patch with an area: ellipses, disks, rings,
        polygons, rectangles, pads; a blade with ``outline=``).
    state : State
        Initial position, angle and velocities (SI). The finger at t = 0 either touches the
        outline (within 1e-9 of the body's length unit ℓ: the contact starts there, with a
        plastic impact if it moves into the body) or lies outside it (separated until it
        arrives); a finger inside the body is refused.
    pusher : PointPusher or LinePusher
        The finger (:class:`slidespin.motion.pushers.PointPusher`) or a flat pusher
        (:class:`~slidespin.motion.pushers.LinePusher`, any outline; its modes in
        :mod:`slidespin.motion.pushed_line`): its path and μp.
    t_end : float
        End of the run [s], in (0, 1e9].
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
    t_end, g, rtol = check_inputs(
        body, friction, state, pusher, t_end, g, rtol, max_steps, max_phases, load, incline
    )
    if isinstance(pusher, LinePusher):
        return simulate_line(
            body,
            friction,
            state,
            pusher,
            t_end,
            g=g,
            rtol=rtol,
            max_steps=int(max_steps),
            max_phases=int(max_phases),
            load=load,
            incline=incline,
            outline=outline,
        )
    prob = _Problem(body, friction, load, incline, g)
    prob.b(0.0, state.phi)  # the load's range, before any work
    a, tu, vu = prob.a, prob.t_unit, prob.v_unit
    geometry = _Outline(body, a, outline)
    finger = _Finger(pusher, a, tu)
    eng = _Engine(prob, geometry, finger, rtol, int(max_steps))
    phi0, eng.turns = reduced_angle(state.phi)
    eng.X = np.array(
        [state.x / a, state.y / a, phi0, state.vx / vu, state.vy / vu, state.omega * tu]
    )
    px, py = finger.pos(finger.segment(0.0)[0], 0.0)
    c, sn = _rot(phi0)
    dx, dy = px - eng.X[0], py - eng.X[1]
    gap0 = geometry.gap(c * dx + sn * dy, -sn * dx + c * dy)
    if gap0 < -_TOUCH:
        raise ValueError(
            f"pusher = {v._short(pusher)} is invalid with state = {v._short(state)}: the finger "
            f"starts {-gap0 * a:.6g} m inside the body's outline; valid: on the outline (within "
            f"{_TOUCH:g} of the body's length unit) or outside it"
        )
    status, t_stop = eng.run(t_end / tu, int(max_phases))
    return _assemble(
        eng, status, t_stop, t_end, max_steps, max_phases, prob, body, friction, state, pusher, g
    )
