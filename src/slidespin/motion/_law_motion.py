"""Free motion to the stop under a speed-dependent friction law (MODEL §5, §14).

With a law g(|w|) the wrench is no longer homogeneous of degree 0 in the twist, so the
regularised time of MODEL §5 is generalised. Let ν = (vx, vy, k ω) in natural units
(ℓ = m = g = 1, k = √(I/m)/ℓ), s = |ν|, u = ν/s and a(ν) the accelerations (Fx, Fy, M/k).
With h(s) = s^q for a power law (q its exponent) and h = 1 for every other law, and
Ã(s, u) = h(s) a(s u), the motion obeys, in the time τ with dt = s h(s) dτ,

    du/dτ = Ã − (u·Ã) u,   d ln s/dτ = u·Ã,   dt/dτ = s h,   d(x, y)/dτ = s² h (u₁, u₂),
    dφ/dτ = s² h u₃/k.

A power law makes a homogeneous of degree −q (a(λν) = λ^(−q) a(ν)), so Ã = a(u) does not
depend on s: the sphere flow is exactly that of MODEL §5 for the law's own direction field,
and a body under q > 0 stops in finite time with v and ω vanishing together, their ratio
converging to a fixed point u* like the constant law's (or to a pure sliding or spinning
one). Every other law tends to its zero-speed factor g(0) as the slip speeds vanish: the
flow tends to the constant law's with the tensor g(0) 𝔽, which has the constant law's
fixed points (the terminal β* is the constant law's) and its exponential approach.

The run ends when the direction has converged (|du/dτ| ≤ max(1e-10, 10 rtol): an explicit
step near a stable fixed point jitters about it at the tolerance) and the time and the
distance left, s h/((1 + q)|u·Ã|) and s² h/((2 + q)|u·Ã|) for the exponential tail, are
below 1e-15 of the time and the length unit; these tails are added to the stop. A direction
of motion that keeps turning once the tails are negligible (by more than 4π: a skewed tensor
with |f| ≥ |μ|/2, MODEL §7) ends the run with the ending ``spiral`` (no ϑ*, no β*). A
direction still moving after ln s has fallen by 720 (s/s₀ ~ 1e-313), or by 150 more once
the tails are negligible, is reported ``marginal`` (an algebraic approach, MODEL §9: a thin
ring with I* near 1): its ending, β* and ϑ* are the direction reached, not a converged
limit; t_stop and the stop pose are converged.

Steps: scipy's DOP853 (rtol = atol = ``rtol`` in natural units), one wrench of
:mod:`slidespin.contact._kernel_speed` per stage (1–10 ms): a free run takes seconds, not
the milliseconds of the compiled constant-law integrator.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.integrate import DOP853

from slidespin.contact._engine import TwistWrench
from slidespin.contact._speed_wrench import (
    law_arrays,
    speed_patch,
    speed_tol,
    speed_wrench_one,
)
from slidespin.contact.speed_laws import PowerLaw
from slidespin.contact.tall_speed import TallSpeed
from slidespin.motion.state import State
from slidespin.motion.trajectory import Trajectory

__all__ = ["simulate_law"]

#: smallest physical slip-speed scale [m/s] at which a bounded law is evaluated; below it
#: g(|w|) equals g(0) to far below round-off for every valid law
SPEED_FLOOR = 1e-250
#: the direction has converged when |du/dτ| is below this
DIRECTION_TOL = 1e-10
#: a direction of motion that turns by more than this [rad] once the tails are negligible
#: ends the run as a ``spiral``
SPIRAL_TURN = 4.0 * math.pi
#: a fall of ln s by this much without convergence ends the run (``marginal``)
LN_S_SPAN = 720.0
#: once the tails are negligible, the direction gets this much further fall of ln s (s
#: another e^150 ≈ 1e65 times smaller) to converge before the run ends ``marginal``
LN_S_AFTER = 150.0


class LawFlow:
    """Ã(s, u) at angle φ for one body, tensor and law (natural units; module notes)."""

    def __init__(self, body, friction, g: float) -> None:
        self.law = friction.speed_law
        self.q = self.law.q if isinstance(self.law, PowerLaw) else 0.0
        self.a = body.length_unit
        self.t_unit = math.sqrt(self.a / g)
        self.v_unit = math.sqrt(self.a * g)
        self.tw = TwistWrench(body, friction.kinetic)  # ω = 0: g(|v|) × the constant law
        self.k = self.tw.k
        self.sp = speed_patch(body.patch, body.pressure)
        self.tensor = friction.matrix
        self.body_frame = friction.frame == "body"
        self.args = law_arrays(self.law)
        # the wrench's target relative to the tensor (1e-11 |𝔽|): the adaptive rule's choices
        # are then noise below the step control's tolerance
        self.tol = speed_tol(friction)
        self.n_wrench = 0
        self.worst = 0.0
        # a tall body (MODEL §14): the pressure moves with the friction force
        self.tall = None
        if body.height > 0.0:
            if self.q > 0.0:
                raise ValueError(
                    f"height = {body.height!r} m is not available with speed_law = "
                    f"{self.law!r}: its friction, and so the load shift h F/P, grows without "
                    "bound as the body stops, and the footprint would lift off and tip; valid "
                    "values: height = 0, or a Stribeck or SpeedTable law"
                )
            self.tall = TallSpeed(body, friction, self.args, self.tol)

    def accel(self, u, s, phi):
        """Ã = h(s) a(s u) (module notes) as (Ã₁, Ã₂, Ã₃)."""
        if self.q > 0.0 and self.tall is None:
            scale = 1.0  # homogeneous: Ã = a(u) (not for a tall body: its r_p moves with s)
        else:
            unit = max(abs(u[0]), abs(u[1]), abs(u[2]) / self.k) * self.v_unit
            scale = s if s * unit >= SPEED_FLOOR else SPEED_FLOOR / unit
        vx = scale * u[0] * self.v_unit
        vy = scale * u[1] * self.v_unit
        om = scale * u[2] / self.k / self.t_unit
        self.n_wrench += 1
        if self.tall is not None:
            fx, fy, m, _ = self.tall(phi, vx, vy, om)
            self.worst = max(self.worst, self.tall.worst)
            hq = s**self.q if self.q > 0.0 else 1.0  # Ã = h(s) a(s u), h = s^q
            return np.array([fx * hq, fy * hq, m * hq / self.a / self.k])
        if om == 0.0:
            fx, fy, m = self.tw(phi, u[0], u[1], 0.0)
            gv = float(self.law.factor(math.hypot(vx, vy))) if (vx or vy) else 1.0
            return np.array([fx * gv, fy * gv, m * gv / self.k])
        fx, fy, m, err = speed_wrench_one(
            self.sp, self.tensor, self.body_frame, self.args, phi, vx, vy, om, self.tol
        )
        self.worst = max(self.worst, err)
        return np.array([fx, fy, m / self.a / self.k])

    def rhs(self, tau, y):
        u = y[:3] / math.sqrt(y[0] ** 2 + y[1] ** 2 + y[2] ** 2)
        s = math.exp(y[3])
        acc = self.accel(u, s, y[7])
        ua = float(u @ acc)
        du = acc - ua * u
        h = s**self.q if self.q > 0.0 else 1.0
        dt = s * h
        out = np.empty(9)
        out[:3] = du
        out[3] = ua
        out[4] = dt
        out[5] = s * dt * u[0]
        out[6] = s * dt * u[1]
        out[7] = s * dt * u[2] / self.k
        out[8] = s * dt * math.hypot(u[0], u[1])
        return out


def simulate_law(body, friction, initial_state: State, g: float, rtol: float, max_steps: int,
                 h_max: float, classify) -> Trajectory:  # fmt: skip
    """:func:`slidespin.simulate` of a free body under ``friction.speed_law`` (module
    notes); the initial state is not at rest. ``classify(u12, u3)`` names the ending
    (:func:`slidespin.motion.simulate.classify_ending`)."""
    flow = LawFlow(body, friction, g)
    a, k = flow.a, flow.k
    s0 = initial_state
    vxn, vyn, wn = s0.vx / flow.v_unit, s0.vy / flow.v_unit, s0.omega * flow.t_unit
    speed0 = math.sqrt(vxn * vxn + vyn * vyn + (k * wn) ** 2)
    y0 = np.array([vxn / speed0, vyn / speed0, k * wn / speed0, math.log(speed0), 0.0,
                   s0.x / a, s0.y / a, s0.phi, 0.0])  # fmt: skip
    solver = DOP853(flow.rhs, 0.0, y0, math.inf, max_step=h_max, rtol=rtol, atol=rtol)
    rows = [y0.copy()]
    status = "stopped"
    steps = 0
    tail_t = tail_x = tail_y = tail_phi = tail_path = 0.0
    spiral = False
    turn = math.nan  # how far the direction of v has turned since the tails became negligible
    theta_prev = math.atan2(y0[1], y0[0])
    ln_small = math.nan  # ln s where the tails first became negligible
    while True:
        if steps >= max_steps:
            status = "max_steps"
            break
        msg = solver.step()
        steps += 1
        if solver.status == "failed":
            status = "step_too_small" if "step size" in str(msg) else "non_finite"
            break
        y = solver.y
        if not np.all(np.isfinite(y)):
            status = "non_finite"
            break
        rows.append(y.copy())
        u = y[:3] / math.sqrt(y[0] ** 2 + y[1] ** 2 + y[2] ** 2)
        s = math.exp(y[3])
        acc = flow.accel(u, s, y[7])
        ua = float(u @ acc)
        moving = float(np.linalg.norm(acc - ua * u))
        h = s**flow.q if flow.q > 0.0 else 1.0
        rate = abs(ua)
        rem_t = s * h / ((1.0 + flow.q) * rate) if rate > 0.0 else math.inf
        rem_x = s * s * h / ((2.0 + flow.q) * rate) if rate > 0.0 else math.inf
        small = rem_t <= 1e-15 * max(y[4], 1e-300) and rem_x <= 1e-15
        theta = math.atan2(u[1], u[0])
        if small:
            step_turn = (theta - theta_prev + math.pi) % (2.0 * math.pi) - math.pi
            turn = 0.0 if math.isnan(turn) else turn + step_turn
        theta_prev = theta
        if small and (moving <= max(DIRECTION_TOL, 10.0 * rtol) or abs(turn) > SPIRAL_TURN):
            spiral = abs(turn) > SPIRAL_TURN
            tail_t, tail_path = rem_t, rem_x * math.hypot(u[0], u[1])
            tail_x, tail_y, tail_phi = rem_x * u[0], rem_x * u[1], rem_x * u[2] / k
            break
        if small and math.isnan(ln_small):
            ln_small = y[3]
            # the stop time and pose have converged: ``max_step`` (points for plotting) no
            # longer applies, only the direction's convergence is left to see
            solver.max_step = math.inf
        if y[3] < math.log(speed0) - LN_S_SPAN or y[3] < ln_small - LN_S_AFTER:
            status = "stopped" if moving <= max(DIRECTION_TOL, 10.0 * rtol) else "marginal"
            break
    rows_a = np.array(rows)
    end = rows_a[-1].copy()
    end[4] += tail_t
    end[5] += tail_x
    end[6] += tail_y
    end[7] += tail_phi
    end[8] += tail_path
    converged = status in ("stopped", "marginal")
    ending = "spiral" if spiral else classify
    return _trajectory(body, friction, initial_state, g, flow, rows_a, end, status, converged,
                       steps, solver.nfev, ending)  # fmt: skip


def _trajectory(body, friction, initial_state, g, flow, rows, end, status, converged, steps,
                nfev, classify):  # fmt: skip
    a, k = flow.a, flow.k
    if converged:
        rows = np.vstack([rows, end[None, :]])
    nrm = np.sqrt(rows[:, 0] ** 2 + rows[:, 1] ** 2 + rows[:, 2] ** 2)
    u1, u2, u3 = rows[:, 0] / nrm, rows[:, 1] / nrm, rows[:, 2] / nrm
    s = np.exp(rows[:, 3])
    if converged:
        s[-1] = 0.0
    weight = body.mass * g
    fx = np.empty(len(rows))
    fy = np.empty(len(rows))
    mm = np.empty(len(rows))
    for i in range(len(rows)):
        uu = np.array([u1[i], u2[i], u3[i]])
        if s[i] > 0.0:
            h = s[i] ** flow.q if flow.q > 0.0 else 1.0
            acc = flow.accel(uu, s[i], rows[i, 7]) / h
        elif flow.q > 0.0:
            acc = np.full(3, math.nan)  # a power law's friction diverges as the body stops
        else:
            acc = flow.accel(uu, 0.0, rows[i, 7])  # the zero-speed limit g(0) × constant law
        fx[i], fy[i], mm[i] = acc[0], acc[1], acc[2] * k
    u12 = np.hypot(u1, u2)
    theta = np.arctan2(u2, u1)
    with np.errstate(divide="ignore", invalid="ignore"):
        beta = np.where(u3 != 0.0, k * u12 / np.abs(u3) * np.sign(u3), math.inf) * a
    if isinstance(classify, str):  # the spiral
        ending = classify
    else:
        ending = classify(float(u12[-1]), float(u3[-1])) if converged else "mixed"
    beta_stop = float(beta[-1])
    theta_stop = float(theta[-1])
    if ending == "spiral":  # the direction of motion keeps turning: no ϑ*, no β*
        beta_stop = theta_stop = math.nan
        beta[-1] = math.nan
    elif converged and ending == "pure_sliding":
        beta_stop = math.inf
    elif converged and ending == "pure_spinning":
        beta_stop = 0.0
        theta_stop = math.nan
        beta[-1] = 0.0
    theta[-1] = theta_stop
    c, sn = np.cos(theta), np.sin(theta)
    tangential = -(fx * c + fy * sn) * weight
    normal = -(-fx * sn + fy * c) * weight
    if converged and ending == "pure_spinning":
        tangential[-1] = normal[-1] = 0.0
    t_unit, v_unit = flow.t_unit, flow.v_unit
    return Trajectory(
        t=rows[:, 4] * t_unit,
        x=rows[:, 5] * a,
        y=rows[:, 6] * a,
        phi=rows[:, 7].copy(),
        vx=s * u1 * v_unit,
        vy=s * u2 * v_unit,
        omega=s * u3 / k / t_unit,
        speed=s * u12 * v_unit,
        theta=theta,
        beta=beta,
        tangential=tangential,
        normal=normal,
        moment_paper=-mm * weight * a,
        path_length=rows[:, 8] * a,
        t_stop=float(end[4] * t_unit),
        stop_state=State(end[5] * a, end[6] * a, end[7]),
        beta_stop=beta_stop,
        theta_stop=theta_stop,
        ending=ending,
        status=status,
        n_steps=int(steps),
        n_rhs=int(nfev),
        body=body,
        friction=friction,
        initial_state=initial_state,
        g=g,
    )
