"""A line pusher on a round outline (an ellipse, a circle, or a hull of discs: pads with
disks): the contacts of :mod:`slidespin.motion.pushed_line` on curved pieces (MODEL §13).

A flat face touches a smooth curve at one point, so two contact kinds join those of the
polygon engine (:mod:`slidespin.motion._line_engine`: ``face``, ``vertex``, ``end``, which a
hull of discs keeps for its straight edges and sharp corners):

``roll``    the curve on the pusher's face (reported as ``vertex_*``): the outline's point
            whose outward normal is the face's, −n; it moves along the face (σ, the state
            y[2]) and along the outline as the body turns relative to the pusher. With β the
            outline's normal angle (world), β̇ = θ̇ − ω, ρ the radius of curvature there and
            q = c − G, d = ∂c/∂β = −ρ t (t = ẑ × n):

                Ġ = ṗ + σ̇ e + σ θ̇ ẑ×e − ω ẑ×q − β̇ d,   u = (σ̇ − ρ̃ β̇) e,  ρ̃ = e·d,

            a_G = A0 + ω̇ (d − ẑ×q) + σ̈ e with A0 = 2σ̇θ̇ ẑ×e − σθ̇² e + ω² q − 2ωβ̇ ẑ×d −
            β̇² c_ββ. *Sticking* is rolling without slip, u = 0: σ̇ = ρ̃ β̇, one degree of
            freedom; *sliding*, two, the 3×3 solve of the vertex contact (ρ = 0 is a vertex).
``endarc``  an end of the pusher on the curve (reported as ``end_*``), as a finger
            (:mod:`slidespin.motion.pushed`) at the end's moving point: the arc length (an
            ellipse: the parametric angle) s on the curve, y[2]; sticking holds s fixed.

Switches besides those of every contact (separation, the cone's edge, u·t crossing 0): a
rolling contact reaching an end of the face (σ = ±h) becomes an end contact; an end contact
whose face turns into the body (ε e·n crossing 0, ε the end's side) becomes a rolling
contact at σ = εh. On a hull of discs an arc rolling until the face is parallel to the next
edge makes that edge flush (a face impact, as a polygon's vertex turning onto a face); an
end on an arc slides on onto the next edge (and back), with no switch of mode; a face
turning about the end of its shared segment at a disc rolls on that disc's arc.

The gap while separated is exact in its zero set: on an ellipse the implicit function
(|M (x − c0)| − 1) min(A, B) with M = diag(1/A, 1/B) R_γᵀ, minimised over the segment in
closed form (a disk's: the distance from its centre less its radius); on a hull of discs the
separating-axis gap over the face's normals, the edges' normals and the directions from the
discs' centres to the pusher's ends (the distance itself while apart). Natural units
(ℓ, m, g = 1).
"""

from __future__ import annotations

import math

import numpy as np

from slidespin.motion._line_engine import _Engine, _turn
from slidespin.motion._pushed_geometry import _FLAT, _rot, _zx, disc_hull_axes

__all__ = ["RoundEngine"]

_HYST = 1e-12  # [ℓ or rad] the slack of the switches between a rolling and an end contact


class RoundEngine(_Engine):
    """A line-pushed body with an ellipse (or circle) outline, or a hull of discs; the
    contact kinds ``roll`` and ``endarc`` on curves, and the polygon engine's ``face``,
    ``vertex`` and ``end`` on a hull's straight edges and sharp corners."""

    _rt = (0.0, 0.0, 0.0, 0.0)  # (ρ̃, β̇, e·c_ββ, σ̇) of the last rolling kin

    # ---- kinematics ------------------------------------------------------------------

    def normal_point(self, beta):
        """(c, ρ, ρ') of the curve under the contact at outward normal angle β (body
        frame): the ellipse's, or disc j's of a hull."""
        if not self.ol.poly:
            return self.ol.normal_point(beta)
        r, cx, cy = float(self.ol.R[self.j]), self.ol.C[self.j, 0], self.ol.C[self.j, 1]
        return (cx + r * math.cos(beta), cy + r * math.sin(beta)), r, 0.0

    def piece(self):
        """The outline piece under an end on a curve: the ellipse, or arc j of a hull."""
        return len(self.ol.L) + self.j if self.ol.poly else 0

    def roll_geometry(self, t, phi):
        """The rolling contact's (p, ṗ, θ̇, e, ẑ×e, n, t, q, d, c_ββ) at pose angle φ."""
        p, th, pv, w = self.ln.state(self.seg, t)
        e = (math.cos(th), math.sin(th))
        ze = _zx(e)
        n = (self.side * ze[0], self.side * ze[1])
        tt = _zx(n)
        c, sn = _rot(phi)
        cb, rho, drho = self.normal_point(math.atan2(-n[1], -n[0]) - phi)
        q = _turn(c, sn, cb)
        d = (-rho * tt[0], -rho * tt[1])
        cbb = (-drho * tt[0] + rho * n[0], -drho * tt[1] + rho * n[1])
        return p, pv, w, e, ze, n, tt, q, d, cbb

    def kin(self, t, y):
        if self.kind == "endarc":
            return self.end_kin(t, y)
        if self.kind != "roll":
            return super().kin(t, y)
        phi, om, z = y[0], y[1], y[2]
        p, pv, w, e, ze, n, tt, q, d, cbb = self.roll_geometry(t, phi)
        bd = w - om
        rt = e[0] * d[0] + e[1] * d[1]
        zd = rt * bd if self.stick else y[3]
        ecb = e[0] * cbb[0] + e[1] * cbb[1]
        self._rt = (rt, bd, ecb, zd)
        vpm = (pv[0] + w * z * ze[0], pv[1] + w * z * ze[1])
        vc = (vpm[0] + zd * e[0], vpm[1] + zd * e[1])
        qp, dp = _zx(q), _zx(d)
        vg = (vc[0] - om * qp[0] - bd * d[0], vc[1] - om * qp[1] - bd * d[1])
        a0 = [
            2.0 * zd * w * ze[i]
            - z * w * w * e[i]
            + om * om * q[i]
            - 2.0 * om * bd * dp[i]
            - bd * bd * cbb[i]
            for i in (0, 1)
        ]
        a1 = (d[0] - qp[0], d[1] - qp[1])
        if self.stick:  # σ̈ = −ρ̃ ω̇ + β̇² e·c_ββ folded into a_G
            a1 = (a1[0] - rt * e[0], a1[1] - rt * e[1])
            a0 = [a0[i] + bd * bd * ecb * e[i] for i in (0, 1)]
        slip = zd - rt * bd
        u = (slip * e[0], slip * e[1])
        return vg, tuple(a0), a1, e, q, n, tt, vpm, u, w

    def end_kin(self, t, y):
        """An end of the pusher on the curve at s = y[2]."""
        phi, om, s, sd = y[0], y[1], y[2], y[3]
        p, th, pv, w = self.ln.state(self.seg, t)
        e = (math.cos(th), math.sin(th))
        rel = (self.endsign * self.ln.h * e[0], self.endsign * self.ln.h * e[1])
        vc = (pv[0] - w * rel[1], pv[1] + w * rel[0])
        c, sn = _rot(phi)
        cb, c1, c2, nb = self.ol.geom(self.piece(), s)
        r, d, dd, n = _turn(c, sn, cb), _turn(c, sn, c1), _turn(c, sn, c2), _turn(c, sn, nb)
        dp = _zx(d)
        a0 = tuple(
            -w * w * rel[i] + om * om * r[i] - 2.0 * om * sd * dp[i] - sd * sd * dd[i]
            for i in (0, 1)
        )
        vg = (vc[0] + om * r[1] - sd * d[0], vc[1] - om * r[0] - sd * d[1])
        return vg, a0, (r[1], -r[0]), (-d[0], -d[1]), r, n, _zx(n), vc, (-sd * d[0], -sd * d[1]), w

    def stick_zdd(self, omd):
        if self.kind != "roll":
            return 0.0
        rt, bd, ecb, _ = self._rt
        return -rt * omd + bd * bd * ecb

    def slip_accel(self, t, y, omd, zdd, tt):
        if self.kind != "roll":
            return super().slip_accel(t, y, omd, zdd, tt)
        self.kin(t, y)
        rt, bd, ecb, _ = self._rt
        e = self.ln.state(self.seg, t)[1]
        et = math.cos(e) * tt[0] + math.sin(e) * tt[1]
        return (zdd + rt * omd - bd * bd * ecb) * et

    # ---- the reduced state from the full one ----------------------------------------

    def arc_s(self, bx, by):
        """s of the body point (bx, by) on the current curve: an arc's length from its
        start (hull), or the ellipse's parametric angle."""
        if not self.ol.poly:
            return self.ol.locate(bx, by)[1]
        i, r = self.j, float(self.ol.R[self.j])
        ang = math.atan2(by - self.ol.C[i, 1], bx - self.ol.C[i, 0]) - self.ol.th0[i]
        rel = (ang + math.pi) % (2.0 * math.pi) - math.pi  # near the arc's start: ≥ −π
        span = self.ol.AL[i] / r
        if rel < -0.5 * (2.0 * math.pi - span):  # nearer its end across the gap
            rel += 2.0 * math.pi
        return r * rel

    def y_now(self, t):
        if self.kind not in ("roll", "endarc"):
            return super().y_now(t)
        x = self.X
        p, th, pv, w = self.ln.state(self.seg, t)
        c, sn = _rot(x[2])
        if self.kind == "endarc":
            cp = self.cpoint(t, None)
            dx, dy = cp[0] - x[0], cp[1] - x[1]
            s = self.arc_s(c * dx + sn * dy, -sn * dx + c * dy)
            d = _turn(c, sn, self.ol.geom(self.piece(), s)[1])
            rel = (cp[0] - p[0], cp[1] - p[1])
            vc = (pv[0] - w * rel[1], pv[1] + w * rel[0])
            ub = (x[3] - x[5] * dy - vc[0], x[4] + x[5] * dx - vc[1])
            sd = -(ub[0] * d[0] + ub[1] * d[1]) / (d[0] * d[0] + d[1] * d[1])
            return np.array([x[2], x[5], s, 0.0 if self.stick else sd, *self.W])
        _, _, _, e, ze, _, _, q, d, _ = self.roll_geometry(t, x[2])
        cw = (x[0] + q[0], x[1] + q[1])
        z = (cw[0] - p[0]) * e[0] + (cw[1] - p[1]) * e[1]
        vb = (x[3] - x[5] * q[1], x[4] + x[5] * q[0])  # the body's material point at c
        vpm = (pv[0] + w * z * ze[0], pv[1] + w * z * ze[1])
        rt = e[0] * d[0] + e[1] * d[1]
        zd = rt * (w - x[5]) + (vb[0] - vpm[0]) * e[0] + (vb[1] - vpm[1]) * e[1]
        return np.array([x[2], x[5], z, zd, *self.W])

    # ---- the gap, the contact's feature ---------------------------------------------

    def _scaled(self, seg, t, x, y, phi):
        """The pusher's ends in the ellipse's unit-circle frame."""
        p, th, _, _ = self.ln.state(seg, t)
        ol, h = self.ol, self.ln.h
        e = (math.cos(th), math.sin(th))
        c, sn = _rot(phi)
        out = []
        for sg in (-h, h):
            wx, wy = p[0] + sg * e[0] - x, p[1] + sg * e[1] - y
            bx, by = c * wx + sn * wy, -sn * wx + c * wy
            lx, ly = ol._local(bx, by)
            out.append((lx / ol.A, ly / ol.B))
        return out

    def nearest(self, seg, t, x, y, phi):
        """(τ, |·|): the segment's point nearest the unit circle's centre, τ ∈ [0, 1]."""
        (ax, ay), (bx, by) = self._scaled(seg, t, x, y, phi)
        dx, dy = bx - ax, by - ay
        den = dx * dx + dy * dy
        tau = min(max(-(ax * dx + ay * dy) / den, 0.0), 1.0) if den > 0.0 else 0.0
        return tau, math.hypot(ax + tau * dx, ay + tau * dy)

    def axes(self, seg, t, x, y, phi):
        """A hull of discs: the separating axes u (into the body) with their gaps
        min_K u·x − max_S u·y, and tags ("face", side), ("edge", i), ("disc", i, end)."""
        ol = self.ol
        p, th, _, _ = self.ln.state(seg, t)
        e = np.array([math.cos(th), math.sin(th)])
        ends = np.array(p) + np.outer([-self.ln.h, self.ln.h], e)
        c, sn = _rot(phi)
        rot = np.array([[c, -sn], [sn, c]])
        cw = np.array([x, y]) + ol.C @ rot.T
        gaps, u, tags = disc_hull_axes(cw, ol.R, ol.N @ rot.T, ends, e)
        return gaps, u, tags, cw, ends

    def gap(self, seg, t, x, y, phi):
        if self.ol.poly:
            return float(self.axes(seg, t, x, y, phi)[0].max())
        return (self.nearest(seg, t, x, y, phi)[1] - 1.0) * min(self.ol.A, self.ol.B)

    def identify(self, t):
        """The contact where the gap closes; G is moved (by the gap, ≤ 1e-9 ℓ) so that the
        contact is exact."""
        if self.ol.poly:
            self.identify_hull(t)
            return
        x = self.X
        p, th, _, _ = self.ln.state(self.seg, t)
        ze = (-math.sin(th), math.cos(th))
        tau = self.nearest(self.seg, t, x[0], x[1], x[2])[0]
        c, sn = _rot(x[2])
        if 0.0 < tau < 1.0:
            cw = _turn(c, sn, self.ol.c0)
            self.kind = "roll"
            self.side = (
                1.0 if (x[0] + cw[0] - p[0]) * ze[0] + (x[1] + cw[1] - p[1]) * ze[1] > 0 else -1.0
            )
            q = self.roll_geometry(t, x[2])[7]
            off = (x[0] + q[0] - p[0]) * ze[0] + (x[1] + q[1] - p[1]) * ze[1]
            x[0] -= off * ze[0]
            x[1] -= off * ze[1]
            return
        self.kind, self.endsign = "endarc", (1.0 if tau >= 1.0 else -1.0)
        cp = self.cpoint(t, None)
        dx, dy = cp[0] - x[0], cp[1] - x[1]
        s = self.ol.locate(c * dx + sn * dy, -sn * dx + c * dy)[1]
        r = _turn(c, sn, self.ol.geom(0, s)[0])
        x[0] += dx - r[0]
        x[1] += dy - r[1]

    def identify_hull(self, t):
        """identify() on a hull of discs: of the axes that attain the gap (to _FLAT), the
        face's if a disc touches it within the segment (an edge flush if two do), else an
        edge's (an end on it; a face if the pusher lies along it), else a disc's (an end on
        its arc)."""
        x, ol = self.X, self.ol
        g, u, tags, cw, ends = self.axes(self.seg, t, x[0], x[1], x[2])
        p, th, _, _ = self.ln.state(self.seg, t)
        e = np.array([math.cos(th), math.sin(th)])
        ze = (-e[1], e[0])
        nk, h = len(ol.L), self.ln.h
        tied = [m for m in np.flatnonzero(g >= g.max() - _FLAT)]
        near: list = []
        for m in tied:
            if tags[m][0] == "face":
                sup = cw @ u[m] - ol.R
                near = [i for i in range(nk) if sup[i] - sup.min() <= _FLAT]
                sig = [(cw[i] - ol.R[i] * u[m] - np.array(p)) @ e for i in near]
                if any(abs(sg) <= h + _FLAT for sg in sig):
                    break
                near = []
        rank = {"face": 0, "edge": 1, "disc": 2}

        def order(k):  # edges before arcs; of two ends, the one whose face stays outside
            tag = tags[k]
            end = 1 if tag[0] == "disc" and tag[2] == 1 else 0
            if tag[0] == "edge":
                end = 1 if ends[1] @ u[k] >= ends[0] @ u[k] else 0
            return rank[tag[0]], -(2 * end - 1) * float(e @ u[k])

        m = next((k for k in tied if tags[k][0] == "face"), None) if near else None
        if m is None:
            m = min((k for k in tied if tags[k][0] != "face"), key=order)
        tag, um = tags[m], u[m]
        x[0] -= g[m] * um[0]  # onto the pusher, along the separating axis
        x[1] -= g[m] * um[1]
        if tag[0] == "face":
            self.side = tag[1]
            i = min(near, key=lambda q: float(cw[q] @ um - ol.R[q]))
            # two discs on the face: the edge between them whose inward normal is the face's
            # (of two discs, both edges join them)
            flush = [
                q for q in range(nk) if q in near and (q + 1) % nk in near and q != (q + 1) % nk
            ]
            if flush:
                c, sn = _rot(x[2])
                self.kind = "face"
                self.j = max(flush, key=lambda q: float(um @ _turn(c, sn, ol.N[q])))
            else:
                self.kind, self.j = ("vertex" if ol.R[i] == 0.0 else "roll"), i
            return
        # an end on an edge or an arc: the deeper end, the outline's normal there
        self.endsign = (
            1.0
            if (tag[0] == "disc" and tag[2] == 1)
            or (tag[0] == "edge" and ends[1] @ um >= ends[0] @ um)
            else -1.0
        )
        self.side = 1.0 if um[0] * ze[0] + um[1] * ze[1] > 0.0 else -1.0
        self.kind, self.j = ("end", tag[1]) if tag[0] == "edge" else ("endarc", tag[1])
        if self.kind == "end":  # as the polygon engine: a parallel pusher makes a face
            depth = ends @ um
            if abs(depth[0] - depth[1]) <= _FLAT:
                self.kind = "face"

    # ---- phases ----------------------------------------------------------------------

    def zdot(self, y):
        return self._rt[3] if self.kind == "roll" else y[3]

    def feature_events(self, t0, nt):
        """Rolling: the face's ends, and on a hull the arc's ends (an edge turning flush);
        an end on a curve: the face turning onto the curve, and on a hull the arc's ends
        (the end sliding on onto an edge); else the polygon engine's."""
        if self.kind not in ("roll", "endarc"):
            return super().feature_events(t0, nt)
        h, arc, events = self.ln.h, self.ol.poly, []
        if self.kind == "roll":
            events.append(("roll_off", lambda t, y: h * (1.0 + _HYST) - y[2]))
            events.append(("roll_off", lambda t, y: h * (1.0 + _HYST) + y[2]))
            if arc:
                events.append(("arc_lo", lambda t, y: self.arc_angle(t, y) + _HYST))
                events.append(
                    ("arc_hi", lambda t, y: self.arc_span() - self.arc_angle(t, y) + _HYST)
                )
        else:
            events.append(("tangent", lambda t, y: self.face_turn(t, y) + _HYST))
            if arc:
                length = float(self.ol.AL[self.j])
                events.append(("arc_lo", lambda t, y: y[2] + _HYST))
                events.append(("arc_hi", lambda t, y: length - y[2] + _HYST))
        return events

    def arc_span(self):
        return float(self.ol.AL[self.j] / self.ol.R[self.j])

    def arc_angle(self, t, y):
        """The rolling contact's normal angle on disc j from its arc's start (rad),
        continuous across the arc (wrapped about its middle)."""
        th = self.ln.state(self.seg, t)[1]
        beta = th - self.side * 0.5 * math.pi - y[0]  # the outward normal −n, body frame
        mid = self.ol.th0[self.j] + 0.5 * self.arc_span()
        return (beta - mid + math.pi) % (2.0 * math.pi) - math.pi + 0.5 * self.arc_span()

    def face_turn(self, t, y):
        """ε e·n at an end contact: < 0 where the face from the end would enter the body."""
        th = self.ln.state(self.seg, t)[1]
        n = self.end_kin(t, y)[5]
        return self.endsign * (math.cos(th) * n[0] + math.sin(th) * n[1])

    def pivot(self, t, at_hi):
        super().pivot(t, at_hi)
        if self.kind == "vertex" and self.ol.R[self.j] > 0.0:
            self.kind = "roll"  # the face turns about the end of its segment at a disc

    def after_event(self, t, label):
        """The new mode after a contact event: the curve's events here, the polygon
        engine's for faces, corners and edges (a corner met by a sliding end that is a
        disc's arc: the end slides on onto it)."""
        nk = len(self.ol.L) if self.ol.poly else 0
        if label == "corner" and self.kind == "end":  # the end at an edge's end
            z = self.y_now(t)[2]
            i = self.j if z < 0.5 * self.ol.L[self.j] else (self.j + 1) % nk
            if self.ol.R[i] > 0.0:  # the end slides on onto disc i's arc
                self.kind, self.j = "endarc", i
                return self.arrive(t)
        if label == "roll_off":  # the rolling contact reaches an end of the face
            self.endsign = 1.0 if self.y_now(t)[2] > 0.0 else -1.0
            self.kind = "endarc"
            return self.arrive(t)
        if label == "tangent":  # the face turns onto the curve at the end
            y = self.y_now(t)
            n = self.end_kin(t, y)[5]
            th = self.ln.state(self.seg, t)[1]
            ze = (-math.sin(th), math.cos(th))
            self.side = 1.0 if n[0] * ze[0] + n[1] * ze[1] > 0.0 else -1.0
            self.kind = "roll"
            return self.arrive(t)
        if label in ("arc_lo", "arc_hi") and self.kind == "roll":  # an edge turns flush
            self.kind, self.j = "face", (self.j - 1) % nk if label == "arc_lo" else self.j
            return self.arrive(t)
        if label in ("arc_lo", "arc_hi"):  # the end slides off the arc onto an edge
            self.kind, self.j = "end", (self.j - 1) % nk if label == "arc_lo" else self.j
            return self.arrive(t)
        return super().after_event(t, label)
