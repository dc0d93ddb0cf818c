"""One loaded run in natural units (MODEL §11): the slip equations with applied loads, and
the static-friction set C that decides stick.

During slip the Newton–Euler equations are m dv/dt = F + Q, I dω/dt = M + T + r_Q × Q
(:mod:`slidespin.motion.loads`). They are integrated in the regularised time of MODEL §5: with
s = √(vx² + vy² + k² ω²), k = √(I/m), u = (vx, vy, k ω)/s, the friction accelerations
A(u) = cos α (Fx, Fy, M/k)/(m g) (degree 0 in the speed) and the applied ones
B(t, φ) = (Qx, Qy, T_G/k)/(m g), Newton–Euler read dv/dt = A + B, so s ds/dt = s u·(A + B) and

    ds/dt = u·X,    du/dt = (X − (u·X) u)/s,     X = A + B,

and with dt = s dτ:

    du/dτ = X − (u·X) u,   d ln s/dτ = u·X,   dt/dτ = s,
    dx/dτ = s² u₁,  dy/dτ = s² u₂,  dφ/dτ = s² u₃/k,

plus the friction and load work, dW_f/dτ = s² u·A and dW_Q/dτ = s² u·B. This is MODEL §5's
system with X in place of A; B does not scale with s, so u·X may be positive (the body
speeds up). The stop (s → 0 with u·X < 0) is an exponential approach in τ as before.

Every patch: the ellipses and circles of the paper and the footprints of MODEL §10 (a
``Blade``, a line contact, included); the friction wrench comes from
:class:`slidespin.contact._engine.TwistWrench` (the elliptic or the exact footprint kernel)
and the static-friction set C from ``slidespin.contact.static_set.static_support``. Natural
units use the body's length unit (:attr:`slidespin.Body.length_unit`).

MODEL §14 on this path: a Stribeck or table speed law (A then depends on s as well: the
wrench of the actual slip speeds, through :mod:`slidespin.motion._law_motion`; g(0) times the
kinetic wrench at the start from rest); and a tall body, whose pressure centroid moves with
the friction force and the loads' heights (:class:`slidespin.contact.tall.TallContact`): at
rest C is that of the pressure the applied force makes, and the hull's gauge at the centroid
decides tipping (at rest in :meth:`_Problem.gauge_normal`, in slip by an event on
:meth:`_Problem.tip_gauge`).
"""

from __future__ import annotations

import math

import numpy as np

from slidespin._validate import _short
from slidespin.contact._engine import TwistWrench
from slidespin.contact.speed_laws import PowerLaw, law_is_constant
from slidespin.contact.static_set import static_support
from slidespin.contact.statics import WRENCH_MAX, _load_factor_nat, _norm, _onset_from_par
from slidespin.contact.tall import TallContact, TallTwist
from slidespin.motion._law_motion import LawFlow

_TOL = 1e-13
#: ln s beyond which s² overflows (a trial stage the step control must reject)
_LN_S_MAX = 350.0
#: the minimisation of the load factor stops where the gradient is below this (sup norm),
#: scipy's BFGS ``gtol`` in :func:`slidespin.contact.statics._load_factor_nat`
_GTOL = 1e-13


def _load_factor(sup, b, d0=None):
    """(λ*, d*) as :func:`slidespin.contact.statics._load_factor_nat` (the same function
    min over d·b > 0 of h(d)/(d·b), on the same slice d = b̂ + p e1 + q e2, to the same
    gradient bound), by Newton's method with a difference Hessian from the warm start d0
    (else from d = b̂, the statics' start), without the set-up of
    ``scipy.optimize.minimize`` (0.4 ms a call, where a warm start often needs one support
    evaluation). Where Newton's method does not reach the bound in a few iterations, the
    scipy minimisation runs instead, from where Newton's method got to."""
    nb = _norm(b)
    if not 0.0 < nb < math.inf:
        return _load_factor_nat(sup, b, d0)
    b0, b1, b2 = float(b[0]) / nb, float(b[1]) / nb, float(b[2]) / nb
    # e1 = b̂ × (1, 0, 0) or b̂ × (0, 1, 0), e2 = b̂ × e1 (the statics' frame)
    if abs(b0) < 0.9:
        e1 = (0.0, b2, -b1)
    else:
        e1 = (-b2, 0.0, b0)
    n1 = math.sqrt(e1[0] ** 2 + e1[1] ** 2 + e1[2] ** 2)
    e1 = (e1[0] / n1, e1[1] / n1, e1[2] / n1)
    e2 = (b1 * e1[2] - b2 * e1[1], b2 * e1[0] - b0 * e1[2], b0 * e1[1] - b1 * e1[0])
    p = q = 0.0  # the statics' cold start: d = b̂
    if d0 is not None:
        dot = float(d0[0]) * b0 + float(d0[1]) * b1 + float(d0[2]) * b2
        if dot > 1e-3:
            p = (float(d0[0]) * e1[0] + float(d0[1]) * e1[1] + float(d0[2]) * e1[2]) / dot
            q = (float(d0[0]) * e2[0] + float(d0[1]) * e2[1] + float(d0[2]) * e2[2]) / dot

    def direction(p, q):
        return np.array(
            [b0 + p * e1[0] + q * e2[0], b1 + p * e1[1] + q * e2[1], b2 + p * e1[2] + q * e2[2]]
        )

    def fun(p, q):
        h, grad = sup(direction(p, q))
        g0 = float(grad[0]) * e1[0] + float(grad[1]) * e1[1] + float(grad[2]) * e1[2]
        g1 = float(grad[0]) * e2[0] + float(grad[1]) * e2[1] + float(grad[2]) * e2[2]
        return float(h), g0, g1

    h, g0, g1 = fun(p, q)
    for _ in range(12):
        if max(abs(g0), abs(g1)) <= _GTOL:
            d = direction(p, q)
            return h / nb, d / math.sqrt(float(d @ d))
        eps = 1e-7 * max(1.0, abs(p), abs(q))
        _, a0, a1 = fun(p + eps, q)
        _, c0, c1 = fun(p, q + eps)
        h00 = (a0 - g0) / eps
        h11 = (c1 - g1) / eps
        h01 = 0.5 * ((a1 - g1) + (c0 - g0)) / eps
        det = h00 * h11 - h01 * h01
        if not (det > 0.0 and h00 > 0.0):
            break
        dp = -(h11 * g0 - h01 * g1) / det
        dq = -(h00 * g1 - h01 * g0) / det
        for _k in range(20):  # backtracking: the ratio must not rise
            h_new, n0, n1_ = fun(p + dp, q + dq)
            if h_new <= h:
                break
            dp *= 0.5
            dq *= 0.5
        else:
            break
        p, q, h, g0, g1 = p + dp, q + dq, h_new, n0, n1_
    return _load_factor_nat(sup, b, direction(p, q))


class _Scaled:
    """A wrench times a constant factor (a speed law at zero slip speed), called as a
    ``TwistWrench``."""

    __slots__ = ("factor", "k", "tw")

    def __init__(self, tw, factor) -> None:
        self.tw, self.factor, self.k = tw, factor, tw.k

    def __call__(self, phi, vx, vy, omega):
        fx, fy, m = self.tw(phi, vx, vy, omega)
        return fx * self.factor, fy * self.factor, m * self.factor


def _check_law_loaded(body, friction) -> None:
    """Refuse, before any work, a speed law a loaded run cannot start from rest with."""
    law = friction.speed_law
    if isinstance(law, PowerLaw):
        raise ValueError(
            f"speed_law = {law!r} is not available under loads, slopes or t_end: its factor "
            "(|w|/v0)^(-q) is infinite at zero slip speed, so a body at rest could never "
            "start; valid values here: a Stribeck or SpeedTable law, or no law (free "
            "motion takes the power law)"
        )
    g0 = float(law.factor(0.0))
    if g0 > friction.static * (1.0 + 1e-12):
        raise ValueError(
            f"static = {friction.static!r} is invalid with speed_law = {law!r} under a load: "
            f"the law's factor at zero speed is {g0!r}, above what static friction holds, "
            f"so a body could not start from rest; valid values: static >= {g0!r}"
        )
    if body.height > 0.0:
        raise ValueError(
            f"speed_law = {law!r} is not available for a tall body (height = "
            f"{body.height!r} m) yet; valid values: no speed law, or height = 0"
        )


class _Problem:
    """Everything in natural units (a = m = g = 1, time √(a/g)) for one loaded run."""

    def __init__(self, body, friction, load, incline, g, springs=()):
        self.body, self.friction, self.load, self.incline, self.g = body, friction, load, incline, g
        # springs (slidespin.motion.springs) depend on the state: evaluated at ``pose`` (x, y
        # of G) and ``vel`` (vx, vy, k ω), natural units, which the slip's right-hand side
        # sets from its state and the phase loop sets to the pose where the body sticks
        self.springs = tuple(springs)
        self.pose = (0.0, 0.0)
        self.vel = (0.0, 0.0, 0.0)
        self.a = body.length_unit
        self.t_unit = math.sqrt(self.a / g)
        self.v_unit = math.sqrt(self.a * g)
        # a speed-dependent law (MODEL §14): the wrench of the slip speed, g(0) × the kinetic
        # wrench at the start from rest; the static set is the kinetic one times ``static``
        self.law = None if law_is_constant(friction.speed_law) else friction.speed_law
        self.flow = None
        self.g0 = 1.0
        if self.law is not None:
            _check_law_loaded(body, friction)
            self.flow = LawFlow(body, friction, g)
            self.g0 = float(self.law.factor(0.0))
        self.tw = TwistWrench(body, friction.kinetic, _TOL)  # the wrench of any patch
        self.k = self.tw.k
        # a tall body (MODEL §14): the pressure moves with the friction force and the loads'
        # heights; ``rp`` is the pressure centroid of the last wrench (natural, body frame)
        self.tall = TallContact(body, friction, _TOL) if body.height > 0.0 else None
        self.rp = self.tall.rg if self.tall is not None else (0.0, 0.0)
        self.tipped = False  # the last gauge at rest was the hull's (the body tips)
        # a constant tilt keeps its factors as numbers (bit for bit the fixed-plane run)
        self.fixed_tilt = incline is None or incline.is_constant
        self.nf = 1.0 if incline is None or not self.fixed_tilt else incline.normal_factor
        if incline is None or not self.fixed_tilt:
            self.grav = (0.0, 0.0)
        else:
            dx, dy = incline.direction
            self.grav = (incline.downhill_factor * dx, incline.downhill_factor * dy)
        self.constant = (load is None or load.is_constant) and self.fixed_tilt and not springs
        self.python_only = bool(springs) or self.tall is not None or self.law is not None
        self.n_rhs = 0
        self.failure = ""
        self._support = {}
        self._d_last = None
        self._mass_centre = body.mass_centre  # (a property that builds the footprint's)
        self._normal = (math.nan, math.nan, 0.0, None)  # (t, φ, γ, d) of the last gauge

    def nf_at(self, t):
        """cos α at the natural time t (the constant cos α for a fixed tilt)."""
        if self.fixed_tilt:
            return self.nf
        return self.incline.normal_factor_at(t * self.t_unit)

    def b(self, t, phi):
        """Applied accelerations (Qx, Qy, T_G/k)/(m g), scaled natural coordinates."""
        if self.fixed_tilt:
            bx, by = self.grav
        else:
            sa = self.incline.downhill_factor_at(t * self.t_unit)
            dx, dy = self.incline.direction
            bx, by = sa * dx, sa * dy
        bm = 0.0
        if self.load is not None or self.springs:
            qx, qy, mz = self._applied(t, phi)
            mg = self.body.mass * self.g
            bx += qx / mg
            by += qy / mg
            bm = mz / (mg * self.a * self.k)
            big = max(abs(qx), abs(qy), abs(mz) / self.a) / mg
            if not big <= WRENCH_MAX:
                raise ValueError(
                    f"load = {_short(self.load)} gives (Qx, Qy, T) = ({qx:.6g} N, {qy:.6g} N, "
                    f"{mz:.6g} N m) at t = {t * self.t_unit:.6g} s, {big:.3g} in units of "
                    f"(m g, m g, m g a); valid range: force and torque up to {WRENCH_MAX:g} "
                    "m g (m g a)"
                )
        return bx, by, bm

    def _applied(self, t, phi):
        """(Qx, Qy, moment about G) [N, N, N m] of the loads and springs at natural time t,
        the springs at ``pose`` and ``vel``."""
        qx = qy = mz = 0.0
        ts = t * self.t_unit
        if self.load is not None:
            qx, qy, mz = self.load.wrench(ts, phi, self._mass_centre)
        if self.springs:
            a, vu = self.a, self.v_unit
            x, y = self.pose[0] * a, self.pose[1] * a
            vx, vy = self.vel[0] * vu, self.vel[1] * vu
            om = self.vel[2] / self.k / self.t_unit
            for spring in self.springs:
                sx, sy, sm = spring.wrench(ts, x, y, phi, vx, vy, om, self._mass_centre)
                qx, qy, mz = qx + sx, qy + sy, mz + sm
        return qx, qy, mz

    def friction_acc(self, u1, u2, u3, phi, t=0.0, s=0.0):
        """Friction accelerations (natural units) in the direction u at angle φ, time t and
        speed s (which only a speed law reads; s = 0: the start from rest, g(0))."""
        nf = self.nf if self.fixed_tilt else self.nf_at(t)
        if self.flow is not None:
            a = self.flow.accel((u1, u2, u3), s, phi)
            return a[0] * nf, a[1] * nf, a[2] * nf
        if self.tall is not None:
            fx, fy, m, self.rp = self.tall.solve(phi, u1, u2, u3 / self.k, self.sigma(t, phi))
        else:
            fx, fy, m = self.tw(phi, u1, u2, u3 / self.k)
        return fx * nf, fy * nf, m * nf / self.k

    def sigma(self, t, phi):
        """Σ (h − h_Q) Q / P in the body frame, natural units (MODEL §14): the loads' tilt
        of a tall body (zero for loads at G's height)."""
        if self.load is None:
            return (0.0, 0.0)
        rx, ry = self.load.raised_force(t * self.t_unit, phi, self.body.height)
        scale = self.body.mass * self.g * self.nf_at(t) * self.a
        c, s = math.cos(phi), math.sin(phi)
        return ((c * rx + s * ry) / scale, (-s * rx + c * ry) / scale)

    def rest_centroid(self, t, phi):
        """r_p of the body at rest at (t, φ): static friction balances the applied force,
        F = −ΣQ, so r_p = r_G + h ΣQ/P − σ (natural units, body frame; MODEL §14)."""
        tall = self.tall
        bx, by, _ = self.b(t, phi)
        nf = self.nf_at(t)
        c, s = math.cos(phi), math.sin(phi)
        fx, fy = (c * bx + s * by) / nf, (-s * bx + c * by) / nf
        sx, sy = self.sigma(t, phi)
        return (tall.rg[0] + tall.h * fx - sx, tall.rg[1] + tall.h * fy - sy)

    def tip_gauge(self, y):
        """The hull's gauge at the pressure centroid of the slip state y (1: tipping)."""
        u = y[0:3] / math.sqrt(float(y[0] ** 2 + y[1] ** 2 + y[2] ** 2))
        if self.springs:
            s = math.exp(y[3])
            self.pose = (y[5], y[6])
            self.vel = (s * u[0], s * u[1], s * u[2])
        self.friction_acc(u[0], u[1], u[2], y[7], y[4])
        return self.tall.tip_gauge(self.rp)

    def rhs(self, tau, y):
        self.n_rhs += 1
        if not y[3] < _LN_S_MAX:
            # a wild trial stage of a loose tolerance (rtol up to 1e-3), with s² beyond the
            # floats: not finite, so that the step control rejects the step (math.exp would
            # raise OverflowError, and s² u with u = 0 would warn)
            return np.full(10, np.nan)
        u1, u2, u3 = y[0], y[1], y[2]
        inv = 1.0 / math.sqrt(u1 * u1 + u2 * u2 + u3 * u3)
        u1 *= inv
        u2 *= inv
        u3 *= inv
        s = math.exp(y[3])
        ax, ay, am = self.friction_acc(u1, u2, u3, y[7], y[4], s)
        if self.springs:
            self.pose = (y[5], y[6])
            self.vel = (s * u1, s * u2, s * u3)
        bx, by, bm = self.b(y[4], y[7])
        xx, xy, xm = ax + bx, ay + by, am + bm
        ux = u1 * xx + u2 * xy + u3 * xm
        s2 = s * s
        return np.array(
            [
                xx - ux * u1,
                xy - ux * u2,
                xm - ux * u3,
                ux,
                s,
                s2 * u1,
                s2 * u2,
                s2 * u3 / self.k,
                s2 * (u1 * ax + u2 * ay + u3 * am),
                s2 * (u1 * bx + u2 * by + u3 * bm),
            ]
        )

    def jac(self, tau, y):
        """Forward-difference Jacobian of :meth:`rhs` (the columns of x, y, W vanish)."""
        f0 = self.rhs(tau, y)
        jm = np.zeros((10, 10))
        for j in (0, 1, 2, 3, 4, 7):
            h = 1e-7 * max(1.0, abs(y[j]))
            yh = y.copy()
            yh[j] += h
            jm[:, j] = (self.rhs(tau, yh) - f0) / h
        return jm

    def hold_at(self, pos):
        """The body at rest at ``pos`` (x, y, φ natural): where the springs are evaluated
        while it sticks."""
        self.pose = (float(pos[0]), float(pos[1]))
        self.vel = (0.0, 0.0, 0.0)

    def stiffness(self, y):
        """Ratio of the fastest relaxation rate of u to the growth rate |u·X| (in τ)."""
        jm = self.jac(0.0, y)[:3, :3]
        u = y[:3] / np.linalg.norm(y[:3])
        proj = np.eye(3) - np.outer(u, u)
        kappa = float(np.max(np.abs(np.linalg.eigvals(proj @ jm @ proj))))
        rate = abs(float(self.rhs(0.0, y)[3]))
        return kappa / max(rate, 1e-300)

    def support(self, phi, t=None):
        """The support function of C at angle φ (for a tall body, with the pressure of the
        body at rest under the load at time t)."""
        if self.tall is not None:
            rp = self.rest_centroid(0.0 if t is None else t, phi)
            key = (float(phi), rp)
            if key not in self._support:
                if len(self._support) > 8:
                    self._support.clear()
                self._support[key] = self.tall.at(rp).support(self.friction, float(phi))
            return self._support[key]
        key = float(phi)
        if key not in self._support:
            if len(self._support) > 8:
                self._support.clear()
            self._support[key] = static_support(self.tw, self.friction, key)
        return self._support[key]

    def w_nat(self, t, phi):
        """The applied wrench per unit normal load, in the coordinates of C (natural)."""
        bx, by, bm = self.b(t, phi)
        return np.array([bx, by, bm * self.k]) / self.nf_at(t)

    def gauge(self, t, phi, w=None):
        """γ = 1/λ*: the body at rest holds iff γ ≤ 1."""
        return self.gauge_normal(t, phi, w)[0]

    def gauge_normal(self, t, phi, w=None):
        """(γ, d*): the gauge and the outward normal of C where the ray through the load
        leaves it (None for a zero load). The last one is kept: asked again at the same
        (t, φ), it is not computed again."""
        t_last, phi_last, g_last, d_last = self._normal
        own = w is None and self.tall is None  # (a tall body's verdict is not kept)
        if w is None and not own:
            w = self.w_nat(t, phi)
        if own:
            if t == t_last and phi == phi_last:
                return g_last, d_last
            w = self.w_nat(t, phi)
        if not w.any():
            return 0.0, None
        tip = 0.0
        if self.tall is not None:
            # a tall body at rest: it tips when the pressure centroid reaches the hull
            # (gauge 1), and slides when the load leaves C of the shifted pressure
            tip = self.tall.tip_gauge(self.rest_centroid(t, phi))
            if tip >= 1.0:
                self.tipped = True
                return tip, None
        lam, self._d_last = _load_factor(self.support(phi, t), w, self._d_last)
        if self.tall is not None:
            self.tipped = tip >= 1.0 / lam
            if self.tipped:
                return tip, None
        if own:
            self._normal = (t, phi, 1.0 / lam, self._d_last)
        return 1.0 / lam, self._d_last

    def onset(self, t, phi):
        """Onset (u, λ, residual) at a time where :meth:`gauge` has found γ > 1.

        Raises :class:`~slidespin.contact.statics.OnsetNotFound` if the solve fails.
        """
        b = np.array(self.b(t, phi))
        tw = self.tw if self.tall is None else TallTwist(self.tall, self.sigma(t, phi))
        if self.g0 != 1.0:
            tw = _Scaled(tw, self.g0)  # the law at zero slip speed
        return _onset_from_par(
            tw,
            self.friction,
            phi,
            b,
            self.nf_at(t),
            self.support(phi, t),
            slipping=True,
            d0=self._d_last,
        )
