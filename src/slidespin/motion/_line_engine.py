"""The line pusher's engine on a polygonal outline (MODEL §13): the face, vertex and end
contacts, their switches, impacts and phases, as described in :mod:`slidespin.motion.pushed_line`
(whose :func:`~slidespin.motion.pushed_line.simulate_line` runs it). The round outlines'
engine, :mod:`slidespin.motion._line_round`, derives from it. Natural units (ℓ, m, g = 1).
"""

from __future__ import annotations

import math

import numpy as np

from slidespin.motion._pushed_geometry import (
    _cross,
    _gap,
    _identify,
    _integrate_contact,
    _point_impulse,
    _rest,
    _rot,
    _Run,
    _separated,
    _wrench,
    _zx,
)
from slidespin.motion.outcomes import PUSH_MODES

_SEP = 0
#: + 0 sticking, + 1 left, + 2 right; a round outline's arc rolling on the face reports as a
#: vertex, an end on an arc as an end (motion/_line_round.py)
_BASE = {"face": 4, "vertex": 7, "end": 10, "roll": 7, "endarc": 10}
_TOUCH = 1e-9  # |gap| [ℓ] within which the pusher given at t = 0 touches the outline
_GAP_TOL = 1e-13  # [ℓ] a separated pusher re-contacts where the gap falls below −_GAP_TOL
_CONE_TOL = 1e-12
#: μp = 0: sticking is λt = 0, which a symmetric push keeps only to the integration's error
#: (it then flipped between sticking and sliding hundreds of times a second); the cone is
#: taken this wide (of λn), an error of the same order as the integration's
_CONE_TOL_FRICTIONLESS = 1e-8
_VEL_TOL = 1e-11
_STOP_DROP = 1e-13
_ZENO = 1e-5  # a rocking face whose approach falls below this (of the speed scale, at least
# √(g ℓ)) lands flat: above the floor √(2 a _GAP_TOL) ~ 5e-7 that the events' slack leaves to
# rocking, which a slow pusher's speed scale alone put the threshold under


def _turn(c, sn, v):
    """R(φ) v for (c, sn) = (cos φ, sin φ)."""
    return (c * v[0] - sn * v[1], sn * v[0] + c * v[1])


class _Engine(_Run):
    """One line-pushed run; ``self.X`` = (x, y, φ, vx, vy, ω), works ``self.W`` = (pusher,
    friction, slip, load), ``self.loss``; the contact: ``kind`` (face, vertex, end), ``j``
    (the body vertex on the face, the face's edge, or the edge under the end), ``side`` (±1:
    the face normal into the body is side·ẑ × e) and ``endsign`` (the end at σ = ±h)."""

    def __init__(self, prob, ol, line, rtol, max_steps):
        super().__init__(prob, ol, line.mu, rtol, max_steps)
        self.ln = line
        self.mode = _SEP
        self.kind, self.j, self.side, self.endsign = "face", 0, 1.0, 1.0
        self.dirn, self.stick = 1.0, True
        vmax = float(np.max(np.hypot(line.v[:, 0], line.v[:, 1]) + line.h * np.abs(line.v[:, 2])))
        self.vscale = max(vmax, 1e-300)

    # ---- forces and kinematics -------------------------------------------------------

    def kin(self, t, y):
        """The contact kinematics at (t, y = (φ, ω, ζ, ζ̇, ...)): G's velocity, the terms of
        a_G = A0 + ω̇ a1 + ζ̈ a2, r = c − G, n, t, the pusher's velocity at c, u."""
        phi, om, z, zd = y[0], y[1], y[2], y[3]
        p, th, pv, w = self.ln.state(self.seg, t)
        e = (math.cos(th), math.sin(th))
        ze = _zx(e)
        c, sn = _rot(phi)
        ol = self.ol
        if self.kind == "end":
            cp = self.cpoint(t, y)
            rel = (cp[0] - p[0], cp[1] - p[1])
            vc = (pv[0] - w * rel[1], pv[1] + w * rel[0])
            i = self.j
            r = _turn(c, sn, (ol.V[i, 0] + z * ol.E[i, 0], ol.V[i, 1] + z * ol.E[i, 1]))
            d, n = _turn(c, sn, ol.E[i]), _turn(c, sn, ol.N[i])
            zd_ = _zx(d)
            a0 = (
                -w * w * rel[0] + om * om * r[0] - 2.0 * om * zd * zd_[0],
                -w * w * rel[1] + om * om * r[1] - 2.0 * om * zd * zd_[1],
            )
            a2 = (-d[0], -d[1])
            vpm = vc
            vg = (vc[0] + om * r[1] - zd * d[0], vc[1] - om * r[0] - zd * d[1])
        else:
            r = _turn(c, sn, ol.V[self.j])
            n = (self.side * ze[0], self.side * ze[1])
            vpm = (pv[0] - w * z * e[1], pv[1] + w * z * e[0])
            vc = (vpm[0] + zd * e[0], vpm[1] + zd * e[1])
            a0 = (
                -w * w * z * e[0] + 2.0 * w * zd * ze[0] + om * om * r[0],
                -w * w * z * e[1] + 2.0 * w * zd * ze[1] + om * om * r[1],
            )
            a2 = e
            vg = (vc[0] + om * r[1], vc[1] - om * r[0])
        u = (zd * a2[0], zd * a2[1])
        return vg, a0, (r[1], -r[0]), a2, r, n, _zx(n), vpm, u, w

    def acc(self, t, y):
        """(ω̇, ζ̈, λ, τ, vG, powers, r, n, t, u·t) in the current mode."""
        vg, a0, a1, a2, r, n, tt, vpm, u, w = self.kin(t, y)
        phi, om = y[0], y[1]
        fx, fy, m, qx, qy, tq = _wrench(self.prob, t, phi, vg[0], vg[1], om)
        bx, by = fx + qx - a0[0], fy + qy - a0[1]
        k2 = self.k * self.k
        face = self.kind == "face"
        tau = 0.0
        if self.stick and face:
            omd, zdd = 0.0, 0.0
            lam = (-bx, -by)
        elif self.stick:  # a point contact: a_G = A0 + ω̇ a1 (a round outline rolls: _round)
            omd = (m + tq - _cross(r, (bx, by))) / (k2 - _cross(r, a1))
            zdd = self.stick_zdd(omd)
            lam = (omd * a1[0] - bx, omd * a1[1] - by)
        else:
            sig = -self.mu * self.dirn
            nt = (n[0] + sig * tt[0], n[1] + sig * tt[1])
            if face:
                det = -a2[0] * nt[1] + a2[1] * nt[0]
                zdd = (-bx * nt[1] + by * nt[0]) / det
                lnn = (a2[0] * by - a2[1] * bx) / det
                omd = 0.0
            else:
                mat = np.array(
                    [[a1[0], a2[0], -nt[0]], [a1[1], a2[1], -nt[1]], [k2, 0.0, -_cross(r, nt)]]
                )
                omd, zdd, lnn = np.linalg.solve(mat, np.array([bx, by, m + tq]))
            lam = (lnn * nt[0], lnn * nt[1])
        if face:
            tau = -(m + tq + _cross(r, lam))
        ut = u[0] * tt[0] + u[1] * tt[1]
        pw = (
            lam[0] * vpm[0] + lam[1] * vpm[1] + tau * w,
            fx * vg[0] + fy * vg[1] + m * om,
            -(lam[0] * u[0] + lam[1] * u[1]),
            qx * vg[0] + qy * vg[1] + tq * om,
        )
        return omd, zdd, lam, tau, vg, pw, r, n, tt, ut

    def overlap(self, t, y):
        """The shared segment of a face contact, [lo, hi] along t from the face's vertex."""
        p, th, _, _ = self.ln.state(self.seg, t)
        z, h = y[2], self.ln.h
        et = -self.side  # e·t
        a, b = et * (-h - z), et * (h - z)
        return max(-float(self.ol.L[self.j]), min(a, b)), min(0.0, max(a, b))

    # ---- the full state, rows ---------------------------------------------------------

    def cpoint(self, t, y):
        """The contact point on the pusher: its end, or the point σ = y[2] of its face."""
        p, th, _, _ = self.ln.state(self.seg, t)
        sig = self.endsign * self.ln.h if self.kind in ("end", "endarc") else y[2]
        return (p[0] + sig * math.cos(th), p[1] + sig * math.sin(th))

    def full(self, t, y):
        omd, zdd, lam, tau, vg, pw, r, n, tt, ut = self.acc(t, y)
        c = self.cpoint(t, y)
        self.X = np.array([c[0] - r[0], c[1] - r[1], y[0], vg[0], vg[1], y[1]])
        self.W = np.array(y[4:8])
        cpt = c
        if self.kind == "face" and lam[0] * n[0] + lam[1] * n[1] > 0.0:
            s = -tau / (lam[0] * n[0] + lam[1] * n[1])
            cpt = (c[0] + s * tt[0], c[1] + s * tt[1])
        return lam, cpt

    def record(self, t, mode, lam=(0.0, 0.0), cpt=(math.nan, math.nan)):
        p = self.ln.state(self.seg, t)[0]
        self.rows.append(
            [t, *self.X, lam[0], lam[1], cpt[0], cpt[1], mode, *self.W, self.loss, p[0], p[1]]
        )

    def code(self):
        return _BASE[self.kind] + (0 if self.stick else (1 if self.dirn < 0 else 2))

    def y_now(self, t):
        """The reduced state of the current contact from ``self.X``."""
        x = self.X
        p, th, pv, w = self.ln.state(self.seg, t)
        e = (math.cos(th), math.sin(th))
        c, sn = _rot(x[2])
        if self.kind == "end":
            cp = self.cpoint(t, None)
            i = self.j
            dx, dy = cp[0] - x[0], cp[1] - x[1]
            q = (c * dx + sn * dy - self.ol.V[i, 0], -sn * dx + c * dy - self.ol.V[i, 1])
            z = q[0] * self.ol.E[i, 0] + q[1] * self.ol.E[i, 1]
            d = _turn(c, sn, self.ol.E[i])
            rel = (cp[0] - p[0], cp[1] - p[1])
            vc = (pv[0] - w * rel[1], pv[1] + w * rel[0])
            r = (cp[0] - x[0], cp[1] - x[1])
            ub = (x[3] - x[5] * r[1] - vc[0], x[4] + x[5] * r[0] - vc[1])
            zd = -(ub[0] * d[0] + ub[1] * d[1])
        else:
            vb = self.ol.V[self.j]
            cb = (x[0] + c * vb[0] - sn * vb[1], x[1] + sn * vb[0] + c * vb[1])
            z = (cb[0] - p[0]) * e[0] + (cb[1] - p[1]) * e[1]
            r = (cb[0] - x[0], cb[1] - x[1])
            vcb = (x[3] - x[5] * r[1], x[4] + x[5] * r[0])
            vpm = (pv[0] - w * (cb[1] - p[1]), pv[1] + w * (cb[0] - p[0]))
            zd = (vcb[0] - vpm[0]) * e[0] + (vcb[1] - vpm[1]) * e[1]
        om = w if self.kind == "face" else x[5]
        return np.array([x[2], om, z, 0.0 if self.stick else zd, *self.W])

    def record_now(self, t):
        if self.mode == _SEP:
            self.record(t, _SEP)
            return
        lam, cpt = self.full(t, self.y_now(t))
        self.record(t, self.mode, lam, cpt)

    # ---- the contact's set-up, impacts, decisions --------------------------------------

    def contact_velocity(self, t):
        """(u, n, t, r, vpm) at the current contact from ``self.X`` (no slip removed)."""
        saved = self.stick
        self.stick = False
        y = self.y_now(t)
        self.stick = saved
        if self.kind == "face":
            y[1] = self.X[5]
        vg, _, _, _, r, n, tt, vpm, _, _ = self.kin(t, y)
        x = self.X
        u = (x[3] - x[5] * r[1] - vpm[0], x[4] + x[5] * r[0] - vpm[1])
        return u, n, tt, r, vpm

    def vtol(self):
        x = self.X
        return _VEL_TOL * (self.vscale + math.hypot(x[3], x[4]) + abs(self.k * x[5]))

    def apply_impulse(self, t, lam, tau, r, vpm, w):
        x = self.X
        k2 = self.k * self.k
        ke0 = 0.5 * (x[3] ** 2 + x[4] ** 2 + k2 * x[5] ** 2)
        x[3] += lam[0]
        x[4] += lam[1]
        x[5] += (_cross(r, lam) + tau) / k2
        ke1 = 0.5 * (x[3] ** 2 + x[4] ** 2 + k2 * x[5] ** 2)
        work = float(lam[0] * vpm[0] + lam[1] * vpm[1] + tau * w)
        self.W[0] += work
        self.loss += work - (ke1 - ke0)
        self.impacts.append((t, float(lam[0]), float(lam[1]), float(work - (ke1 - ke0))))

    def point_impact(self, t):
        """Plastic impact at a point contact: u·n = 0 after, u = 0 if in the cone."""
        u, n, tt, r, vpm = self.contact_velocity(t)
        lam = _point_impulse(u, n, tt, r, self.k * self.k, self.mu, _CONE_TOL)
        self.apply_impulse(t, lam, 0.0, r, vpm, 0.0)

    def face_impact(self, t):
        """Plastic impact of a face: the body takes the pusher's twist if the impulse is in
        the cone and its resultant on the shared segment; else on the cone's edge (ω = θ̇,
        u·n = 0); a resultant beyond the segment is a point impact at its nearer end."""
        u, n, tt, r, vpm = self.contact_velocity(t)
        x = self.X
        w = self.ln.state(self.seg, t)[3]
        k2 = self.k * self.k
        # body twist after = the pusher's: v_G = vpm(c) − w ẑ×r, ω = w
        lam = (vpm[0] + w * r[1] - x[3], vpm[1] - w * r[0] - x[4])
        ln, lt = lam[0] * n[0] + lam[1] * n[1], lam[0] * tt[0] + lam[1] * tt[1]
        if abs(lt) > self.mu * ln + _CONE_TOL * (abs(ln) + abs(lt)):
            sig = self.mu * math.copysign(1.0, lt)
            nt = (n[0] + sig * tt[0], n[1] + sig * tt[1])
            un = (x[3] - w * r[1] - vpm[0]) * n[0] + (x[4] + w * r[0] - vpm[1]) * n[1]
            lam = (-un * nt[0], -un * nt[1])
            ln = -un
        tau = k2 * (w - x[5]) - _cross(r, lam)
        lo, hi = self.overlap(t, self.y_now(t))
        s = -tau / ln if ln > 0.0 else 0.0
        slack = 1e-12 * max(1.0, hi - lo)
        approach = min(un_end for un_end in self.face_normal_speeds(t))
        zeno = _ZENO * max(self.vscale, 1.0)  # of the pusher's speed, at least of √(g ℓ)
        if ln > 0.0 and (lo - slack <= s <= hi + slack or -approach < zeno):
            self.apply_impulse(t, lam, tau, r, vpm, w)
            return
        # the resultant leaves the segment: an impact at one end only (the end whose impulse
        # leaves the other end not approaching; the arriving end first), as the two-point
        # plastic impact's complementarity asks
        saved = (self.X.copy(), self.W.copy(), self.loss, len(self.impacts), self.kind, self.j)
        for at_hi in (s < lo, s > hi):
            self.pivot(t, at_hi)
            self.point_impact(t)
            kind, j, endsign = self.kind, self.j, self.endsign
            self.kind, self.j = saved[4], saved[5]
            if min(self.face_normal_speeds(t)) >= -self.vtol():
                self.kind, self.j, self.endsign = kind, j, endsign
                return
            self.X, self.W, self.loss = saved[0].copy(), saved[1].copy(), saved[2]
            del self.impacts[saved[3] :]
        self.apply_impulse(t, lam, tau, r, vpm, w)  # pragma: no cover - no one-end impact fits

    def face_normal_speeds(self, t):
        """u·n at the two ends of the shared segment of a face contact (from ``self.X``)."""
        u, n, _, _, _ = self.contact_velocity(t)
        un = u[0] * n[0] + u[1] * n[1]
        w = self.ln.state(self.seg, t)[3]
        lo, hi = self.overlap(t, self.y_now(t))
        return (un - (self.X[5] - w) * lo, un - (self.X[5] - w) * hi)

    def pivot(self, t, at_hi):
        """Face → a point contact at the end of the shared segment (hi: toward V_j)."""
        lo, hi = self.overlap(t, self.y_now(t))
        i = self.j
        if at_hi and hi >= 0.0:
            self.kind = "vertex"
        elif not at_hi and lo <= -float(self.ol.L[i]):
            self.kind, self.j = "vertex", (i + 1) % len(self.ol.L)
        else:
            p, th, _, _ = self.ln.state(self.seg, t)
            y = self.y_now(t)
            et = -self.side
            end_s = hi if at_hi else lo  # along t from V_i: the pusher's end at σ = ±h
            sig = y[2] + end_s * et  # σ of that end: (V_j + s t − p)·e
            self.kind, self.endsign = "end", 1.0 if sig > 0.0 else -1.0

    def try_mode(self, t, stick, dirn=1.0):
        """Set a trial mode and return (λn, λt, u·t accel sign info, in-segment) for it."""
        self.stick, self.dirn = stick, dirn
        y = self.y_now(t)
        if self.kind == "face":
            y[1] = self.ln.state(self.seg, t)[3]
        omd, zdd, lam, tau, _, _, r, n, tt, ut = self.acc(t, y)
        ln = lam[0] * n[0] + lam[1] * n[1]
        lt = lam[0] * tt[0] + lam[1] * tt[1]
        inside, hi_side = True, False
        if self.kind == "face" and ln > 0.0:
            lo, hi = self.overlap(t, y)
            s = -tau / ln
            inside, hi_side = lo <= s <= hi, s > hi
        return ln, lt, self.slip_accel(t, y, omd, zdd, tt), inside, hi_side

    def stick_zdd(self, omd):
        """σ̈ (or s̈) while sticking: 0 (a vertex, or the end at a fixed body point)."""
        return 0.0

    def slip_accel(self, t, y, omd, zdd, tt):
        """d(u·t)/dt of a point contact at u = 0 in the trial mode."""
        a2 = self.kin(t, y)[3]
        return zdd * (a2[0] * tt[0] + a2[1] * tt[1])

    def gap(self, seg, t, x, y, phi):
        """The signed gap between the pusher and the outline (> 0 apart)."""
        return _gap(self.ol, self.ln, seg, t, x, y, phi)[0]

    def decide(self, t, exclude=(), depth=0):
        """The consistent mode of the current contact geometry (or a pivot, or separation)."""
        if depth > 3:
            return -1
        u, n, tt, _, _ = self.contact_velocity(t)
        if self.kind != "face" and abs(u[0] * n[0] + u[1] * n[1]) > self.vtol():
            return self.arrive(t)  # after a pivot: moving off (or into) the new contact
        ut = u[0] * tt[0] + u[1] * tt[1]
        if abs(ut) > self.vtol():
            dirn = 1.0 if ut > 0.0 else -1.0
            ln, _, _, inside, hi_side = self.try_mode(t, False, dirn)
            if ln < 0.0:
                return self.turn_off_face(t, depth) if self.kind == "face" else _SEP
            if not inside:
                self.pivot(t, hi_side)
                return self.decide(t, depth=depth + 1)
            return self.code()
        ln, lt, _, inside, hi_side = self.try_mode(t, True)
        if ln < 0.0:
            return self.turn_off_face(t, depth) if self.kind == "face" else _SEP
        cone = abs(lt) <= self.mu * ln + self.cone_tol() * (abs(ln) + abs(lt))
        if inside and cone and self.code() not in exclude:
            return self.code()
        first = -1.0 if lt > 0.0 else 1.0
        for dirn in (first, -first):  # a face sliding with its resultant on the segment
            ln2, _, utd, inside2, hi2 = self.try_mode(t, False, dirn)
            if self.code() in exclude or ln2 < 0.0 or dirn * utd < 0.0:
                continue
            if inside2:
                return self.code()
            if inside:
                hi_side = hi2
            inside = False
        if not inside or self.kind == "face":  # rotate about the end the resultant passes
            self.pivot(t, hi_side)
            return self.decide(t, depth=depth + 1)
        return _SEP if ln < 0.0 else -1

    def turn_off_face(self, t, depth):
        """A flush face that the pusher would have to pull (λn < 0) while the body turns
        relative to it: the contact at the end of the shared segment about which the other
        end turns away from the face (ω̇ ≥ 0 about the ``hi`` end, ≤ 0 about ``lo``, θ̈ = 0
        on a path segment) if it pushes there, else separation."""
        saved = (self.kind, self.j, self.endsign)
        for at_hi in (True, False):
            self.pivot(t, at_hi)
            mode = self.decide(t, depth=depth + 1)
            if mode not in (_SEP, -1) and (self.acc(t, self.y_now(t))[0] >= 0.0) == at_hi:
                return mode
            self.kind, self.j, self.endsign = saved
        return _SEP

    def arrive(self, t, impacts=True):
        """The mode once a contact starts or the pusher's velocity jumps (impact if any)."""
        x = self.X
        pv = self.ln.v[self.seg]
        if not np.any(x[3:]) and not np.any(pv):
            return _SEP
        u, n, _, _, _ = self.contact_velocity(t)
        un = u[0] * n[0] + u[1] * n[1]
        if self.kind == "face":  # u·n along the shared segment: un − (ω − θ̇) s
            ends = self.face_normal_speeds(t)
            if min(ends) > self.vtol():
                return _SEP
            if impacts and min(ends) < -self.vtol():
                self.face_impact(t)
            elif max(ends) > self.vtol():  # turning off the face about one end
                self.pivot(t, ends[1] < ends[0])
            return self.decide(t)
        if un > self.vtol():
            return _SEP
        if un < -self.vtol() and impacts:
            self.point_impact(t)
        return self.decide(t)

    # ---- phases ------------------------------------------------------------------------

    def flush(self, t, y, vb):
        """The distance (+ slack) of the body vertex vb from the pusher's line, positive on
        the body's side, in the phase's state y; 1 while the edge from the contact to vb
        shares no length with the pusher (it passes beyond the pusher's end)."""
        p, th, _, _ = self.ln.state(self.seg, t)
        r, c, q = self.kin(t, y)[4], self.cpoint(t, y), _turn(*_rot(y[0]), vb)
        q = (c[0] - r[0] + q[0] - p[0], c[1] - r[1] + q[1] - p[1])
        s0 = self.endsign * self.ln.h if self.kind == "end" else y[2]
        s1, h = q[0] * math.cos(th) + q[1] * math.sin(th), self.ln.h
        if min(max(s0, s1), h) - max(min(s0, s1), -h) <= 1e-12 * h:
            return 1.0
        return self.side * (-q[0] * math.sin(th) + q[1] * math.cos(th)) + _GAP_TOL

    def feature_events(self, t0, nt):
        """The events of the contact's geometry (labelled): the face's resultant at an end of
        the shared segment; a vertex past the pusher's end or an edge turning flush; an end
        at a corner or its edge turning flush."""
        nv = len(self.ol.L)
        events: list = []
        if self.kind == "face":
            events.append(("lo", lambda t, y: -nt(t, y)[2] - self.overlap(t, y)[0] * nt(t, y)[0]))
            events.append(("hi", lambda t, y: self.overlap(t, y)[1] * nt(t, y)[0] + nt(t, y)[2]))
        elif self.kind == "vertex":
            h = self.ln.h
            events.append(("off", lambda t, y: h - y[2]))
            events.append(("off", lambda t, y: h + y[2]))
            # an edge at the vertex turning flush: watched at its far end (labelled by edge)
            j = self.j
            for edge, vb in (((j - 1) % nv, self.ol.V[(j - 1) % nv]), (j, self.edge_end(j))):
                events.append((("flush", edge), lambda t, y, vb=vb: self.flush(t, y, vb)))
        else:
            length = float(self.ol.L[self.j])
            events.append(("corner", lambda t, y: y[2]))
            events.append(("corner", lambda t, y: length - y[2]))
            # the edge turning flush with the face: at its vertex on the pusher's side of the
            # end (flush() is 1 for the other, beyond the end; a turning pusher may swap them)
            i = self.j
            for vb in (self.ol.V[i], self.edge_end(i)):
                events.append((("flush", i), lambda t, y, vb=vb: self.flush(t, y, vb)))
        return events

    def edge_end(self, i):
        """The far end of edge i (body frame): the next vertex, or on a hull of discs the
        point where the edge meets the next disc."""
        return self.ol.V[i] + self.ol.L[i] * self.ol.E[i]

    def zdot(self, y):
        """dy[2]/dt: σ̇ (or ṡ) is the state's y[3] (a rolling contact's follows from φ)."""
        return y[3]

    def cone_tol(self):
        """The slack of the friction cone's edges, relative to λn (wider when μp = 0)."""
        return _CONE_TOL if self.mu > 0.0 else _CONE_TOL_FRICTIONLESS

    def run_contact(self, t0, t1):
        mu, tol = self.mu, self.cone_tol()

        def fun(t, y):
            omd, zdd, _, _, _, pw, *_ = self.acc(t, y)
            return np.array([y[1], omd, self.zdot(y), zdd, *pw])

        def nt(t, y):
            _, _, lam, tau, _, _, _, n, tt, ut = self.acc(t, y)
            return lam[0] * n[0] + lam[1] * n[1], lam[0] * tt[0] + lam[1] * tt[1], tau, ut

        events = [("sep", lambda t, y: nt(t, y)[0])]
        if self.stick:
            events.append(
                ("cone", lambda t, y: mu * nt(t, y)[0] - nt(t, y)[1] + tol * abs(nt(t, y)[0]))
            )
            events.append(
                ("cone", lambda t, y: mu * nt(t, y)[0] + nt(t, y)[1] + tol * abs(nt(t, y)[0]))
            )
        else:
            events.append(("slip", lambda t, y: self.dirn * nt(t, y)[3]))
        events += self.feature_events(t0, nt)

        def rec(t, y):
            lam, cpt = self.full(t, y)
            self.record(t, self.mode, lam, cpt)

        y0 = self.y_now(t0)
        reason, t, y, idx, steps = _integrate_contact(
            fun, t0, y0, t1, [g for _, g in events], self.rtol, self.atol, self.steps_left, rec
        )
        self.steps_left -= steps
        self.full(t, y)
        return reason, t, (events[idx][0] if reason == "event" else None)

    # ---- contacts from geometry --------------------------------------------------------

    def identify(self, t):
        """Set the contact's feature where the gap closes, and put it exactly on the pusher."""
        kind, j, side, endsign, dx, dy = _identify(self.ol, self.ln, self.seg, t, self.X)
        self.kind, self.j, self.side = kind, j, side
        if endsign:
            self.endsign = endsign
        self.X[0] += dx
        self.X[1] += dy

    def run_separated(self, t0, t1):
        """The free body (MODEL §5) until t1, the pusher's arrival or the stop."""
        seg = self.seg

        def gap(t, x, y, phi):
            return self.gap(seg, t, x, y, phi) + _GAP_TOL

        return _separated(self, t0, t1, gap, _STOP_DROP)

    def wait(self, t0, t1):
        """A body at rest, separated, until t1 or the pusher arrives."""
        x, seg = self.X, self.seg
        return _rest(
            self,
            t0,
            t1,
            np.any(self.ln.v[seg]),
            lambda t: self.gap(seg, t, x[0], x[1], x[2]) + _GAP_TOL,
        )

    def to_face(self, t, edge):
        """A point contact whose edge turned flush: face contact on that edge."""
        self.kind, self.j = "face", edge

    # ---- the run -----------------------------------------------------------------------

    def switch(self, t, new):
        if new == -1:
            return False
        if new != self.mode:
            self.switches.append((t, PUSH_MODES[self.mode], PUSH_MODES[new]))
        self.mode = new
        self.record_now(t)
        return True

    def start_contact(self, t):
        """The gap closed (or is closed at t = 0): identify, impact, decide."""
        self.identify(t)
        return self.switch(t, self.arrive(t))

    def run(self, t_end, max_phases):
        self.seg = self.ln.segment(0.0)[0]
        x = self.X
        gap0 = self.gap(self.seg, 0.0, x[0], x[1], x[2])
        self.mode = _SEP
        if abs(gap0) <= _TOUCH:
            self.identify(0.0)
            before, w0, loss0 = self.X.copy(), self.W.copy(), self.loss
            n_imp = len(self.impacts)
            mode = self.arrive(0.0)
            if mode == -1:
                self.record(0.0, _SEP)
                return "indeterminate", 0.0
            if len(self.impacts) > n_imp:  # the pusher arrives at t = 0: the state before
                after, w, loss = self.X, self.W.copy(), self.loss
                self.X, self.W, self.loss = before, w0, loss0
                self.record(0.0, _SEP)
                self.X, self.W, self.loss = after, w, loss
                self.switch(0.0, mode)
            else:
                self.mode = mode
                self.record_now(0.0)
        else:
            self.record(0.0, _SEP)
        t = 0.0
        while t < t_end:
            stop = self.next_phase(t, max_phases)
            if stop:
                return stop, t
            self.seg, _, te = self.ln.segment(t)
            t1 = min(te, t_end)
            if self.mode == _SEP:
                if not np.any(self.X[3:]):
                    reason, t = self.wait(t, t1)
                    if reason == "no_onset":
                        return "no_onset", t
                else:
                    reason, t = self.run_separated(t, t1)
                if reason == "contact":
                    if not self.start_contact(t):
                        return "indeterminate", t
                    continue
                if reason == "stop":
                    continue
                if reason == "end" and self.rows[-1][0] != t1:
                    self.record(t1, _SEP)
            else:
                reason, t, label = self.run_contact(t, t1)
                if reason == "event":
                    if label == "sep" and self.rows[-1][0] == t:  # λn = 0 at the root (§13):
                        self.rows[-1][7:9] = [0.0, 0.0]  # no force, not the root's noise
                    if not self.switch(t, self.after_event(t, label)):
                        return "indeterminate", t
                    continue
            if reason == "max_steps":
                return "max_steps", t
            if reason == "failed":
                return "step_too_small", t
            t = t1
            if t >= t_end:
                break
            self.seg = self.ln.segment(t)[0]
            if self.mode != _SEP:
                self.stick = False  # the pusher's velocity jumps: re-decide from the velocities
                if not self.switch(t, self.arrive(t)):
                    return "indeterminate", t
        return "ok", t

    def after_event(self, t, label):
        """The new mode after a contact event."""
        mode = self.mode
        if label in ("sep", "off"):  # λn < 0, or a vertex past the pusher's end
            return _SEP
        if label in ("lo", "hi"):
            self.pivot(t, label == "hi")
            return self.decide(t)
        if label == "corner":  # the pusher's end reaches a vertex: that vertex on the face
            z, nv = self.y_now(t)[2], len(self.ol.L)
            self.kind = "vertex"
            self.j = self.j if z < 0.5 * self.ol.L[self.j] else (self.j + 1) % nv
            return self.arrive(t)  # its velocity normal to the face: away, or an impact
        if isinstance(label, tuple):  # ("flush", edge): the edge turns onto the face
            self.to_face(t, label[1])
            return self.arrive(t)
        return self.decide(t, exclude=(mode,))
