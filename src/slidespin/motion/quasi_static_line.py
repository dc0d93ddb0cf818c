"""Quasi-static pushing by a flat pusher (a :class:`~slidespin.motion.pushers.LinePusher`),
inertia neglected (MODEL §13).

The pusher is a segment of length L with prescribed centre and direction; it pushes with the
side of its segment that faces the mass centre G at the start (its pushing normal N, into the
body). The body's outline ∂B is convex (a polygon, a hull of discs or an ellipse, relative to G:
:func:`slidespin.contact.outline.body_outline`). At every instant the plane friction on its
limit surface balances the pusher: W(û) + Σ J_cᵀ λ = 0 (MODEL §11, §13), with the exact
friction wrench W of MODEL §2 and §10 and λ in the pusher's Coulomb cone |λt| ≤ μp λn.

The contact modes (:data:`LINE_PUSH_MODES`, names as in :class:`~slidespin.QuasiStaticPush`):

``"separated"``
    The pusher does not touch the body (or moves away from it, or is at rest): the body rests.
    The pusher's arrival is located by root finding on the separating-axis gap.
``"face_sticking"``
    The pusher's face lies flat on an edge of the body over the shared segment [σ_lo, σ_hi]
    (positions along the pusher from its − end). The line load's resultant may sit anywhere on
    the shared segment and anywhere in the cone: the body moves rigidly with the pusher while
    the wrench −W(û_pusher) has its resultant inside the segment and the cone (Lynch & Mason's
    stable pushing, on the exact limit surface).
``"face_sliding_left"``, ``"face_sliding_right"``
    The face stays flat and the body slides along it; the resultant lies on the cone edge
    n + μp t (left: the pusher slides towards +t = ẑ × N over the body) or n − μp t (right),
    inside the shared segment. One root in the slide rate.
``"vertex_sticking"``, ``"vertex_sliding_left"``, ``"vertex_sliding_right"``
    A point contact of a body vertex (or the ellipse's nearest point) with the pusher's face,
    normal N: a finger whose velocity is that of the pusher's material point there. The body
    turns relative to the pusher until an edge lies flat on the face (event → face contact)
    or the vertex reaches an end of the pusher. This is also *rotation about an end of the
    shared segment* when that end is a body corner.
``"end_sticking"``, ``"end_sliding_left"``, ``"end_sliding_right"``
    A point contact of an end of the pusher with an edge of the body (normal: the edge's
    inward normal): *rotation about an end of the shared segment* when that end is the
    pusher's end; events when the face turns flat onto the edge or the end reaches a vertex.

With μp = 0 the two sliding modes are one (λt = 0) and are reported as ``*_sliding_left``
(the slip may reverse within it); ``*_sticking`` is reported only while λt = 0 holds (a
symmetric push). A pusher at rest moves nothing (``"separated"``, force 0). An end of the
pusher reaching a body corner continues on the next edge, or leaves the corner when it moves
away from the body; if no mode is consistent the run ends with status ``"indeterminate"``.
On a hull of discs (pads with disks) a disc touches the face at its support point (a
``vertex_*`` contact with the margins of a corner) and an end of the pusher slides on an
edge or an arc (``end_*``), :mod:`slidespin.motion._qs_line_hull`.

Point contacts are solved as in :mod:`slidespin.motion.quasi_static` (one bracketed root for
sticking, one for the cone edge when sliding). Each mode is integrated with scipy's DOP853 on
the pose of G; path knots are integration boundaries and every mode switch is an event located
by root finding on the dense output (to ~1e-12 s). At a switch the next mode is the first
consistent one (its own margins ≥ 0; for a point contact leaving a face, the face must open).
"""

from __future__ import annotations

import math

import numpy as np

from slidespin import _validate as v
from slidespin.contact._engine import TwistWrench
from slidespin.contact.body import Body, require_thin
from slidespin.contact.friction import FrictionTensor
from slidespin.contact.outline import body_outline
from slidespin.motion._qs_line_hull import hull_features, hull_gap
from slidespin.motion._qs_pieces import PhaseBudget, Pieces, check_max_phases
from slidespin.motion.outcomes import PUSH_MODES
from slidespin.motion.state import reduced_angle

__all__ = ["LINE_PUSH_MODES", "push_line_quasi_static"]

#: the line pusher's modes (a subset of :data:`slidespin.motion.outcomes.PUSH_MODES`, whose
#: indices are the result's ``mode_code``, as for a finger)
LINE_PUSH_MODES = (
    "separated",
    "face_sticking",
    "face_sliding_left",
    "face_sliding_right",
    "vertex_sticking",
    "vertex_sliding_left",
    "vertex_sliding_right",
    "end_sticking",
    "end_sliding_left",
    "end_sliding_right",
)
_BASE = {"face": 1, "vertex": 4, "end": 7}
_SIGMA = (0.0, 1.0, -1.0)  # stick, left, right
_TOUCH = 1e-9  # least contact tolerance [ℓ] (it is 100 rtol when larger)
_ACCEPT = 1e-9  # a candidate mode's margins may be this negative at a switch
_ROUND = 1e-12
_EVENT_GUARD = 1e-12
_HALF_PI = 0.5 * math.pi


class _NoMode(RuntimeError):
    """No consistent quasi-static contact mode (or a root solve failed)."""


def _cross(a, b) -> float:
    return float(a[0] * b[1] - a[1] * b[0])


def _brent(f, lo, hi, guess=None, width=1e-3):
    """A root of f in [lo, hi], first searched about ``guess``; :class:`_NoMode` if none."""
    from scipy.optimize import brentq  # lazy: scipy.optimize costs ~0.8 s to import

    a, b = (lo, hi) if lo <= hi else (hi, lo)
    if guess is not None and a < guess < b:
        w = width * (b - a)
        while w < b - a:
            l2, h2 = max(a, guess - w), min(b, guess + w)
            fl, fh = f(l2), f(h2)
            if fl == 0.0 or fh == 0.0:
                return l2 if fl == 0.0 else h2
            if (fl < 0.0) != (fh < 0.0):
                try:
                    return brentq(f, l2, h2, xtol=1e-15, rtol=1e-15, maxiter=200)
                except ValueError:
                    pass
            w *= 16.0
    fa, fb = f(a), f(b)
    if fa == 0.0 or fb == 0.0:
        return a if fa == 0.0 else b
    if (fa < 0.0) == (fb < 0.0):
        if min(abs(fa), abs(fb)) <= _ROUND:
            return a if abs(fa) <= abs(fb) else b
        raise _NoMode("no sign change of the balance in its bracket")
    try:
        return brentq(f, a, b, xtol=1e-15, rtol=1e-15, maxiter=200)
    except ValueError:
        raise _NoMode("the balance changed sign only at round-off level") from None


class _Line:
    """One body, tensor, outline and line pusher: geometry and mode solves (SI units)."""

    def __init__(self, body, friction, pusher, g, outline, side) -> None:
        require_thin(body, "pushed runs")
        self.tw = TwistWrench(body, friction)
        self.ell = body.length_unit
        self.load = body.mass * g
        self.mu = float(pusher.mu)
        self.edge_angle = math.atan(self.mu)
        self.L = float(pusher.length)
        self.side = side
        self.out = outline
        self.poly = outline.kind == "hull"  # a polygon, or a hull of discs (pads with disks)
        if self.poly:
            self.verts = outline.vertices  # the corners, or the discs' centres
            self.radii = outline.discs[:, 2].copy()
            self.ea, self.eb = outline.edges[:, 0, :], outline.edges[:, 1, :]  # the edges' ends
            e = self.eb - self.ea
            self.lengths = np.hypot(e[:, 0], e[:, 1])
            self.normals = outline.edge_normals  # inward
        self.round = self.poly and bool(np.any(self.radii > 0.0))
        self.warm: dict = {}
        self.touch = _TOUCH * self.ell

    # geometry (plane orientation, positions relative to G) --------------------------------
    def frame(self, t, q, seg):
        ta, pose_a, rate = seg
        cx, cy, a = pose_a + rate * (t - ta)
        d = np.array([math.cos(a), math.sin(a)])
        npush = self.side * np.array([-d[1], d[0]])
        cp = np.array([cx - q[0], cy - q[1]])
        ends = (cp - 0.5 * self.L * d, cp + 0.5 * self.L * d)
        c, s = math.cos(q[2]), math.sin(q[2])
        rot = np.array([[c, -s], [s, c]])
        return {"d": d, "N": npush, "cp": cp, "E": ends, "rot": rot, "rate": rate, "phi": q[2]}

    def wvel(self, fr, r):
        """Velocity of the pusher's material point at r (relative to G) [m/s]."""
        vx, vy, om = fr["rate"]
        cp = fr["cp"]
        return np.array([vx - om * (r[1] - cp[1]), vy + om * (r[0] - cp[0])])

    def gap(self, fr) -> float:
        """Separating-axis gap between the pusher segment and ∂B [m] (> 0 apart)."""
        e0, e1 = fr["E"]
        if self.round:
            return hull_gap(self, fr)
        if self.poly:
            vw = self.verts @ fr["rot"].T
            best = -math.inf
            for u in (*(-(self.normals @ fr["rot"].T)), fr["N"]):
                pb, ps = vw @ u, (float(e0 @ u), float(e1 @ u))
                best = max(best, min(ps) - pb.max(), pb.min() - max(ps))
            return best
        a, b = self.out.axes
        ang = fr["phi"] + self.out.angle
        c, s = math.cos(ang), math.sin(ang)
        ctr = fr["rot"] @ self.out.centre

        def loc(p):
            dx, dy = p - ctr
            return np.array([(c * dx + s * dy) / a, (-s * dx + c * dy) / b])

        p0, p1 = loc(e0), loc(e1)
        dd = p1 - p0
        w = float(np.clip(-(p0 @ dd) / max(dd @ dd, 1e-300), 0.0, 1.0))
        return (math.hypot(*(p0 + w * dd)) - 1.0) * min(a, b)

    def features(self, fr):
        """Contact features touching the pusher (empty when apart): ("face", i),
        ("vertex", i), ("smooth",), ("end", k, j) (j = -1: the ellipse)."""
        tol = self.touch
        if self.gap(fr) > tol:
            return []
        e0, d, npush = fr["E"][0], fr["d"], fr["N"]
        out = []
        if self.round:
            return hull_features(self, fr, tol)
        if self.poly:
            vw = self.verts @ fr["rot"].T
            dn, ds = (vw - e0) @ npush, (vw - e0) @ d
            line = np.abs(dn) <= tol
            on = [bool(line[i]) and -tol <= ds[i] <= self.L + tol for i in range(len(vw))]
            nv = len(vw)
            for i in range(nv):
                j = (i + 1) % nv
                lo, hi = max(min(ds[i], ds[j]), 0.0), min(max(ds[i], ds[j]), self.L)
                if line[i] and line[j] and hi - lo > tol:
                    return [("face", i)]
            out = [("vertex", i) for i in range(nv) if on[i]]
            nw = self.normals @ fr["rot"].T
            for k, ek in enumerate(fr["E"]):
                for j in range(nv):
                    u = float((ek - vw[j]) @ (vw[(j + 1) % nv] - vw[j])) / self.lengths[j] ** 2
                    ut = tol / self.lengths[j]
                    if abs(float((ek - vw[j]) @ nw[j])) <= tol and -ut <= u <= 1.0 + ut:
                        out.append(("end", k, j))
            return out
        sb = self.out.support(fr["rot"].T @ (-npush))
        sw = fr["rot"] @ sb
        if abs(float((sw - e0) @ npush)) <= tol and -tol <= float((sw - e0) @ d) <= self.L + tol:
            out.append(("smooth",))
        for k, ek in enumerate(fr["E"]):
            if abs(self.out.closest(fr["rot"].T @ ek)[2]) <= tol:
                out.append(("end", k, -1))
        return out

    def point(self, fr, feat):
        """(r_c, inward n, pusher point velocity, geometric margins ≥ 0 while valid)."""
        e0, d, npush, ell = fr["E"][0], fr["d"], fr["N"], self.ell
        if feat[0] in ("vertex", "smooth"):
            if feat[0] == "vertex":
                i = feat[1]
                rc = fr["rot"] @ self.verts[i] - self.radii[i] * npush  # a disc's support
                nw = self.normals @ fr["rot"].T
                m = (_cross(-nw[i - 1], -npush), _cross(-npush, -nw[i]))
            else:
                rc = fr["rot"] @ self.out.support(fr["rot"].T @ (-npush))
                m = ()
            s = float((rc - e0) @ d)
            return rc, npush, self.wvel(fr, rc), (s / ell, (self.L - s) / ell, *m)
        k, j = feat[1], feat[2]
        ek = fr["E"][k]
        dout = d if k == 0 else -d
        if feat[0] == "endarc":  # an end on disc j's arc: the normal inside its cone
            cw = fr["rot"] @ self.verts[j]
            n = (cw - ek) / math.hypot(*(cw - ek))
            rc = cw - self.radii[j] * n
            nw = self.normals @ fr["rot"].T
            geo = (_cross(-nw[j - 1], -n), _cross(-n, -nw[j]))
        elif j < 0:
            cb, nb, _ = self.out.closest(fr["rot"].T @ ek)
            rc, n = fr["rot"] @ cb, fr["rot"] @ nb
            geo: tuple = ()
        else:
            a, b = fr["rot"] @ self.ea[j], fr["rot"] @ self.eb[j]
            n = fr["rot"] @ self.normals[j]
            u = float((ek - a) @ (b - a)) / self.lengths[j] ** 2
            rc = a + u * (b - a)
            geo = (u * self.lengths[j] / ell, (1.0 - u) * self.lengths[j] / ell)
        return rc, n, self.wvel(fr, ek), (*geo, -float(dout @ n))

    def shared(self, fr, i):
        """The shared segment of face i: (σ_lo, σ_hi, feature at lo, feature at hi)."""
        j = (i + 1) % len(self.verts)
        ends = np.array([self.ea[i], self.eb[i]]) @ fr["rot"].T
        sa, sb = ((ends - fr["E"][0]) @ fr["d"]).tolist()
        (slo, ilo), (shi, ihi) = sorted(((sa, i), (sb, j)))
        lo = ("vertex", ilo) if slo >= 0.0 else ("end", 0, i)
        hi = ("vertex", ihi) if shi <= self.L else ("end", 1, i)
        return max(slo, 0.0), min(shi, self.L), lo, hi

    # wrench solves ------------------------------------------------------------------------
    def stick(self, phi, rc, vdir, key):
        """Twist (vx/ℓ, vy/ℓ, ω) whose point rc moves along vdir with no friction moment about
        it; returns (twist(s), cos s, friction force per P)."""
        rx, ry = rc[0] / self.ell, rc[1] / self.ell

        def twist(s):
            cs, sn = math.cos(s), math.sin(s)
            return (cs * vdir[0] + sn * ry, cs * vdir[1] - sn * rx, sn)

        def balance(s):
            fx, fy, m = self.tw(phi, *twist(s))
            return m - (rx * fy - ry * fx)

        s = _brent(balance, -_HALF_PI, _HALF_PI, self.warm.get(key))
        self.warm[key] = s
        nu = twist(s)
        fx, fy, _ = self.tw(phi, *nu)
        return nu, math.cos(s), np.array([fx, fy])

    def solve(self, mode, t, q, seg):
        """(twist (vx, vy, ω) [SI], λ/P, margins ≥ 0 while the mode holds, contact point r_c)."""
        kind, sub, feat = mode
        fr = self.frame(t, q, seg)
        if kind == "face":
            return self._face(fr, sub, feat[1])
        rc, n, w, geo = self.point(fr, feat)
        tg = np.array([-n[1], n[0]])
        speed = math.hypot(*w)
        if speed == 0.0:
            raise _NoMode("the pusher is at rest at the contact")
        pn, pt = float(w @ n), float(w @ tg)
        phi = q[2]
        if sub == 0:
            nu, cs, f = self.stick(phi, rc, w / speed, ("stick", feat))
            k = speed / cs
            lam = -f
            ln, lt = float(lam @ n), float(lam @ tg)
            sc = math.hypot(ln, lt)
            ev = ((self.mu * ln - lt) / sc + _ROUND, (self.mu * ln + lt) / sc + _ROUND)
        else:
            sig = _SIGMA[sub]
            psi0 = math.atan2(pt, pn)
            target = sig * self.edge_angle

            def edge(psi):
                vd = math.cos(psi) * n + math.sin(psi) * tg
                _, _, f = self.stick(phi, rc, vd, ("slide", feat))
                return sig * (math.atan2(-f @ tg, -f @ n) - target)

            key = ("psi", feat, sub)
            try:
                psi = _brent(edge, psi0, -sig * _HALF_PI, self.warm.get(key))
            except _NoMode:
                psi = _brent(edge, psi0, sig * _HALF_PI, self.warm.get(key))
            self.warm[key] = psi
            vd = math.cos(psi) * n + math.sin(psi) * tg
            nu, cs, f = self.stick(phi, rc, vd, ("slide", feat))
            k = pn / math.cos(psi) / cs
            lam = -f
            # μp = 0: both edges are λt = 0, one sliding mode whose slip may reverse
            ev = (sig * (psi0 - psi) + _ROUND if self.mu > 0.0 else 1.0,)
        twist = np.array([nu[0] * k, nu[1] * k, nu[2] * k / self.ell])
        return twist, lam, (*ev, pn / speed, *geo), rc

    def _face(self, fr, sub, i):
        ell, d, npush, cp = self.ell, fr["d"], fr["N"], fr["cp"]
        vx, vy, om = fr["rate"]
        nat = np.array([(vx + om * cp[1]) / ell, (vy - om * cp[0]) / ell, om])
        size = float(np.linalg.norm(nat))
        if size == 0.0:
            raise _NoMode("the pusher is at rest on the face")
        tg = np.array([-npush[1], npush[0]])
        if sub == 0:
            nu, kscale = nat / size, size
            fx, fy, m = self.tw(fr["phi"], *nu)
        else:
            sig = _SIGMA[sub]
            slide = np.array([-sig * tg[0], -sig * tg[1], 0.0])

            def direction(chi):
                return math.cos(chi) * nat / size + math.sin(chi) * slide

            def edge(chi):
                f = self.tw(fr["phi"], *direction(chi))
                return sig * (math.atan2(-(f[0] * tg[0] + f[1] * tg[1]),
                                         -(f[0] * npush[0] + f[1] * npush[1]))
                              - sig * self.edge_angle)  # fmt: skip

            key = ("chi", i, sub)
            chi = _brent(edge, -_HALF_PI + 1e-9, _HALF_PI - 1e-9, self.warm.get(key))
            self.warm[key] = chi
            nu, kscale = direction(chi), size / math.cos(chi)
            fx, fy, m = self.tw(fr["phi"], *nu)
        lam = np.array([-fx, -fy])
        ln, lt = float(lam @ npush), float(lam @ tg)
        sc = math.hypot(ln, lt)
        slo, shi, _, _ = self.shared(fr, i)
        e0 = fr["E"][0]
        dl = _cross(d, lam)
        sres = (-m * ell - _cross(e0, lam)) / dl if dl != 0.0 else 0.5 * (slo + shi)
        if sub == 0:
            mech = ((self.mu * ln - lt) / sc + _ROUND, (self.mu * ln + lt) / sc + _ROUND)
        else:
            mech = (chi + _ROUND if self.mu > 0.0 else 1.0,)
        ev = (*mech, ln / sc, (sres - slo) / ell, (shi - sres) / ell)
        twist = np.array([nu[0] * kscale * ell, nu[1] * kscale * ell, nu[2] * kscale])
        return twist, lam, ev, e0 + sres * d

    # choosing modes -----------------------------------------------------------------------
    def ok(self, mode, t, q, seg) -> bool:
        try:
            _, _, ev, _ = self.solve(mode, t, q, seg)
        except _NoMode:
            return False
        return min(ev) >= -_ACCEPT

    def opens(self, mode, t, q, seg, other) -> bool:
        """A point contact at one end of face contact: does the rest of the face open?"""
        try:
            nu, _, ev, rc = self.solve(mode, t, q, seg)
        except _NoMode:
            return False
        if min(ev) < -_ACCEPT:
            return False
        fr = self.frame(t, q, seg)
        rel = nu[2] - fr["rate"][2]
        arm = other - rc
        scale = math.hypot(*fr["rate"][:2]) + abs(fr["rate"][2]) * self.ell + math.hypot(*nu[:2])
        # ≥ 0: a resultant that reached the end continuously starts turning at rate 0
        return rel * float(np.array([-arm[1], arm[0]]) @ fr["N"]) >= -_ACCEPT * scale

    def choose(self, t, q, seg, exclude=()):
        """The consistent mode (kind, sub, feature) at (t, q); ("sep", 0, None) if none."""
        fr = self.frame(t, q, seg)
        feats = self.features(fr)
        if not feats or not np.any(seg[2]):
            return ("sep", 0, None)
        # μp = 0: one sliding mode (reported as left) whose slip may reverse; sticking only
        # while λt = 0 holds (a symmetric push)
        subs = (0, 1, 2) if self.mu > 0.0 else (0, 1)
        for feat in feats:
            if feat[0] == "face":
                slo, shi, flo, fhi = self.shared(fr, feat[1])
                for sub in subs:
                    mode = ("face", sub, feat)
                    if mode not in exclude and self.ok(mode, t, q, seg):
                        return mode
                pts = ((flo, fr["E"][0] + shi * fr["d"]), (fhi, fr["E"][0] + slo * fr["d"]))
                for pf, other in pts:
                    kind = "end" if pf[0] in ("end", "endarc") else "vertex"
                    for sub in subs:
                        mode = (kind, sub, pf)
                        if mode not in exclude and self.opens(mode, t, q, seg, other):
                            return mode
                continue
            kind = "end" if feat[0] in ("end", "endarc") else "vertex"
            for sub in subs:
                mode = (kind, sub, feat)
                if mode not in exclude and self.ok(mode, t, q, seg):
                    return mode
        if self.approaching(t, q, seg):
            raise _NoMode(f"no consistent contact mode of the line pusher at t = {t!r} s")
        return ("sep", 0, None)

    def approaching(self, t, q, seg) -> bool:
        """Would the pusher move into the body if the body stayed at rest (first order)?"""
        fr = self.frame(t, q, seg)
        vx, vy, om = seg[2]
        scale = math.hypot(vx, vy) + abs(om) * (0.5 * self.L + math.hypot(*fr["cp"]))
        if scale == 0.0:
            return False
        dt = 1e-6 * self.ell / scale
        return self.gap(self.frame(t + dt, q, seg)) - self.gap(fr) < -1e-3 * scale * dt

    def touch_time(self, q, seg, t, tb):
        """First time in (t, tb] at which the pusher reaches the resting body (or None); a
        pusher touching at t must first leave it."""
        from scipy.optimize import brentq, minimize_scalar  # lazy: see _brent

        def h(tau):
            return self.gap(self.frame(tau, q, seg))

        grid = np.linspace(t, tb, 65)
        vals = np.array([h(x) for x in grid])
        away = np.flatnonzero(vals > self.touch)
        if not away.size:
            return None
        k0 = int(away[0])  # from here on the pusher is apart
        hit = np.flatnonzero(vals[k0:] <= 0.0)
        if hit.size:
            hi = grid[k0 + hit[0]]
        else:
            k = k0 + int(np.argmin(vals[k0:]))
            lo, up = grid[max(k - 1, k0)], grid[min(k + 1, 64)]
            r = minimize_scalar(h, bounds=(lo, up), method="bounded", options={"xatol": 1e-14})
            if r.fun > 0.0:
                return None
            hi = float(r.x)
        lo = grid[k0 + hit[0] - 1] if hit.size else grid[k0]
        return brentq(h, lo, hi, xtol=1e-15, rtol=1e-15, maxiter=200)


def _integrate(prob, mode, seg, t, tb, q, rtol):
    """Integrate one mode from (t, q) towards tb: (dense, t_end, q_end, fired?)."""
    from scipy.integrate import solve_ivp  # lazy: see _brent

    memo: dict = {}
    guard = t + _EVENT_GUARD * max(tb - t, 1e-300)

    def res(tt, y):
        key = (tt, y[0], y[1], y[2])
        got = memo.get(key)
        if got is None:
            if len(memo) > 64:
                memo.clear()
            got = memo[key] = prob.solve(mode, tt, y, seg)
        return got

    events = []
    for k in range(len(res(t, q)[2])):

        def ev(tt, y, k=k):
            val = res(tt, y)[2][k]
            return val if tt > guard else abs(val) + 1e-300

        ev.terminal = True  # type: ignore[attr-defined]
        ev.direction = -1.0  # type: ignore[attr-defined]
        events.append(ev)
    atol = np.array([rtol * prob.ell, rtol * prob.ell, rtol])
    sol = solve_ivp(
        lambda tt, y: res(tt, y)[0],
        (t, tb),
        q,
        method="DOP853",
        rtol=rtol,
        atol=atol,
        dense_output=True,
        events=events,
    )
    if sol.status < 0:
        raise _NoMode(f"the integration failed at t = {sol.t[-1]!r} s: {sol.message}")
    return sol.sol, float(sol.t[-1]), sol.y[:, -1].copy(), sol.status == 1


def _check(body, friction, pusher, times, start, g, rtol):
    if not isinstance(body, Body):
        raise ValueError(f"body = {v._short(body)} is invalid; valid values: a slidespin.Body")
    if not isinstance(friction, FrictionTensor):
        raise ValueError(
            f"friction = {v._short(friction)} is invalid; valid values: a FrictionTensor"
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
    q = np.zeros(3) if start is None else v.real_array("start", start)
    if q.shape != (3,):
        raise ValueError(
            f"start has shape {q.shape}; valid values: the pose (x [m], y [m], phi [rad])"
        )
    g = v.bounded("g", g, *v.GRAVITY, "m/s^2")
    rtol = v.bounded("rtol", rtol, 1e-13, 1e-3)
    return t, q.astype(float), g, rtol


def push_line_quasi_static(
    body: Body, friction: FrictionTensor, pusher, times, start=None, *, outline=None,
    g: float = 9.81, rtol: float = 1e-10, max_phases: int = 10_000,
) -> dict:  # fmt: skip
    """The quasi-static motion of ``body`` pushed by a line pusher (MODEL §13).

    Called by :func:`slidespin.push_quasi_static` for a
    :class:`~slidespin.motion.pushers.LinePusher`.

    Parameters
    ----------
    body : Body
        The pushed body; its outline (``outline=``, default the footprint's convex hull or
        the ellipse) is a polygon, a hull of discs or an ellipse.
    friction : FrictionTensor
        Plane friction (isotropic or anisotropic, plane- or body-fixed).
    pusher : LinePusher
        The flat pusher: length, path of (t, x, y, angle) rows, μp.
    times : array_like
        Strictly increasing output times [s]; the motion starts at ``times[0]``.
    start : (x, y, phi), optional
        Pose of G [m, m, rad] at ``times[0]``, default (0, 0, 0); the pusher must not start
        inside the outline.
    outline, g, rtol, max_phases
        As in :func:`slidespin.push_quasi_static` (``g`` in [1e-6, 1e6] m/s², ``rtol`` in
        [1e-13, 1e-3], ``max_phases`` in [1, 1e9]).

    Returns
    -------
    dict
        The fields of :class:`~slidespin.QuasiStaticPush`, ``mode_code`` indexing
        :data:`LINE_PUSH_MODES` (``modes``).

    Notes
    -----
    MODEL §13, quasi-static limit, with the modes of the module notes. The pusher pushes with
    the side of its segment that faces G at ``times[0]`` (if G lies on its line: the side it
    moves towards); it must not start inside the outline. ``contact_x``, ``contact_y`` give the point contact, or the resultant's point on
    the shared segment in face contact.
    """
    t_out, q, g, rtol = _check(body, friction, pusher, times, start, g, rtol)
    max_phases = check_max_phases(max_phases)
    q[2], turns = reduced_angle(float(q[2]))  # the turns are added back to the result
    t0, t1 = float(t_out[0]), float(t_out[-1])
    out = body_outline(body, outline)
    pose0 = np.asarray(pusher.pose(t0), dtype=float)
    dn = (-math.sin(pose0[2]), math.cos(pose0[2]))
    side_val = -((pose0[0] - q[0]) * dn[0] + (pose0[1] - q[1]) * dn[1])
    seg0 = (t0, pose0, np.asarray(pusher.velocity(t0), dtype=float))
    if side_val == 0.0:  # G on the pusher's line: the side it moves towards pushes
        side_val = float(seg0[2][0] * dn[0] + seg0[2][1] * dn[1]) or 1.0
    prob = _Line(body, friction, pusher, g, out, 1.0 if side_val > 0.0 else -1.0)
    prob.touch = max(_TOUCH, 100.0 * rtol) * prob.ell  # the contact drifts by ~rtol
    gap0 = prob.gap(prob.frame(t0, q, seg0))
    if gap0 < -_TOUCH * prob.ell:
        raise ValueError(
            f"start = {tuple(float(x) for x in q)} is invalid: the pusher starts {-gap0:.6g} m "
            "inside the body's outline; valid values: a pose with the pusher on or outside it"
        )
    knots = sorted({float(k) for k in np.asarray(pusher.knots, dtype=float) if t0 < k < t1})
    bounds = [t0, *knots, t1]
    pieces = Pieces(max_phases)
    status, message = "ok", f"followed the path to t = {t1!r} s"
    try:
        for ta, tb in zip(bounds[:-1], bounds[1:]):
            seg = (
                ta,
                np.asarray(pusher.pose(ta), float),
                np.asarray(pusher.velocity(ta), float),
            )
            t, repeats = ta, 0
            exclude: tuple = ()
            while t < tb:
                mode = prob.choose(t, q, seg, exclude)
                if mode[0] == "sep":
                    hit = prob.touch_time(q, seg, t, tb)
                    t_next = tb if hit is None else hit
                    pieces.append((t, t_next, mode, seg, q.copy()))
                    if hit is None or hit >= tb or hit == t:
                        break
                    t, exclude = t_next, ()
                    continue
                dense, t_ev, q_ev, fired = _integrate(prob, mode, seg, t, tb, q, rtol)
                repeats = repeats + 1 if t_ev - t <= 1e-12 * max(abs(t), 1.0) else 0
                if repeats > 20:
                    raise _NoMode(f"the contact mode chatters at t = {t!r} s")
                pieces.append((t, t_ev, mode, seg, dense))
                t, q, exclude = t_ev, q_ev, ((mode,) if fired else ())
        if not pieces:
            pieces.append((t0, t1, ("sep", 0, None), seg0, q.copy()))
    except _NoMode as exc:
        status, message = "indeterminate", str(exc)
    except PhaseBudget as exc:
        status, message = "max_phases", str(exc)
    fields = _assemble(prob, t_out, pieces, status, message)
    fields["phi"] = fields["phi"] + turns
    return fields


def _code(mode) -> int:
    return 0 if mode[0] == "sep" else _BASE[mode[0]] + mode[1]


def _assemble(prob, t_out, pieces, status, message) -> dict:
    n = t_out.size
    keys = ("x", "y", "phi", "vx", "vy", "omega", "cx", "cy", "fx", "fy")
    cols = {k: np.full(n, np.nan) for k in keys}
    code = np.zeros(n, dtype=np.int64)
    starts = np.array([p[0] for p in pieces]) if pieces else np.zeros(0)
    last_end = pieces[-1][1] if pieces else -math.inf
    for j, tau in enumerate(t_out):
        if tau > last_end or not pieces:
            continue
        k = max(int(np.searchsorted(starts, tau, side="right")) - 1, 0)
        ta, tb, mode, seg, data = pieces[k]
        q = np.asarray(data(tau) if callable(data) else data, dtype=float)
        cols["x"][j], cols["y"][j], cols["phi"][j] = q
        code[j] = _code(mode)
        if mode[0] == "sep":
            for key in ("vx", "vy", "omega", "fx", "fy"):
                cols[key][j] = 0.0
            continue
        try:
            nu, lam, _, rc = prob.solve(mode, tau, q, seg)
        except _NoMode:
            continue
        cols["vx"][j], cols["vy"][j], cols["omega"][j] = nu
        cols["fx"][j], cols["fy"][j] = lam * prob.load
        cols["cx"][j], cols["cy"][j] = q[0] + rc[0], q[1] + rc[1]
    sw_t, sw_m = [], []
    for a, b in zip(pieces[:-1], pieces[1:]):
        if _code(a[2]) != _code(b[2]):
            sw_t.append(b[0])
            sw_m.append(LINE_PUSH_MODES[_code(b[2])])
    return {
        "t": t_out,
        "x": cols["x"],
        "y": cols["y"],
        "phi": cols["phi"],
        "vx": cols["vx"],
        "vy": cols["vy"],
        "omega": cols["omega"],
        "mode": np.array([LINE_PUSH_MODES[c] for c in code]),
        "mode_code": np.array([PUSH_MODES.index(LINE_PUSH_MODES[c]) for c in code], dtype=np.int64),
        "contact_x": cols["cx"],
        "contact_y": cols["cy"],
        "force_x": cols["fx"],
        "force_y": cols["fy"],
        "switch_times": np.array(sw_t, dtype=float),
        "switch_modes": tuple(sw_m),
        "status": status,
        "message": message,
        "modes": PUSH_MODES,
    }
