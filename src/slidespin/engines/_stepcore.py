"""The steady step of a MuJoCo coupling, compiled: no Python between the engine's arrays and
the wrench (MODEL §16).

:class:`slidespin.engines._coupling.SteppedFriction` and
:class:`slidespin.engines.mujoco.Coupling` keep their state in one float array ``s`` (the
layout below). Most steps of a coupled body are *steady*: the same contact as in the step
before, a normal force that changes by less than 1 % from step to step, and either a slip
whose implicit midpoint (MODEL §16) converges by fixed-point iteration, or a rest that the
cheap upper bound on the static set's gauge confirms. :func:`steady_step` does such a step
whole, from MuJoCo's arrays (read in place) to ``qfrc_passive`` (written in place, as
``mj_applyFT`` would), and returns :data:`DONE`; any other step (a first contact, a launch
or an impulse, a touchdown, a stop within the step, a breakaway, a gauge the bounds cannot
decide, a moving support) it leaves untouched and returns :data:`PYTHON`, and the Python
path of the coupling does it exactly as before, from the same state. Its arithmetic is the
Python path's, line for line (the tests compare the two paths step by step): the two share
their state, not their code, because the compiled path cannot call the statics'
optimisers, and the Python path cannot afford numba's compile on import.

The slip's implicit midpoint is started from the friction per unit load of the last three
slip steps, extrapolated (quadratically once three are known): the fixed point is then
usually met to its tolerance by the first wrench evaluation, and accepted there (one wrench
evaluation per steady step).

May import: the contact layer's kernels, the private root helpers. Plain floats and arrays
only.
"""

from __future__ import annotations

import math

from slidespin._jit import is_none_type, jit, overload
from slidespin.contact._engine import (
    P_BN,
    P_BODY,
    P_LAW,
    P_T00,
    P_T01,
    P_T10,
    P_T11,
    P_WTOL,
    P_XG,
    P_YG,
)
from slidespin.contact._kernel_ellipse import wrench_world as ellipse_world
from slidespin.contact._kernel_footprint import wrench_world as footprint_world

__all__ = ["DONE", "PYTHON", "NSTATE", "steady_step"]

#: :func:`steady_step`'s answers: the step is done; the Python path must do it
DONE, PYTHON = 0, 1

# -- the state vector ``s`` (one per coupled body) ------------------------------------------
# SteppedFriction: constants
S_M, S_I, S_ELL, S_K, S_DT, S_CAP, S_RIN, S_ROUT, S_BODYFRAME = range(9)
# … the last step: time (NaN: none), twist (+ flag), wrench, key (+ flag)
S_T = 9
S_NU, S_NU_OK = 10, 13
S_W = 14
S_KEY, S_KEY_OK = 17, 23
# … the unknown load (accepted, raw; + flag), the known load (+ flag)
S_U, S_U_OK, S_URAW = 24, 27, 28
S_KNOWN, S_KNOWN_OK = 31, 34
# … state (0 free, 1 slip, 2 stick), slipping flag, stop time, exact checks
S_STATE, S_SLIPPING, S_STOP, S_EXACT = 35, 36, 37, 38
# … the last exact gauge: angle, body-frame wrench, gauge (+ flag)
S_REF_PHI, S_REF_B, S_REF_G, S_REF_OK = 39, 40, 43, 44
# … friction per unit load of the last slip steps (newest first) and how many are known
S_H0, S_H1, S_H2, S_NH = 45, 48, 51, 54
# … counters: wrench evaluations, steps, steps done compiled
S_EVALS, S_STEPS, S_FAST = 55, 56, 57
# Coupling (MuJoCo): the last step in contact: time, N used, the engine's N then (+ flag)
C_LAST_T, C_LAST_N, C_LAST_LAG, C_LAST_OK = 58, 59, 60, 61
C_DEBT = 62
# … the contact found then (index, geom pair) and its support's frame if static (+ flag)
C_CI, C_G1, C_G2 = 63, 64, 65
C_N, C_E1, C_E2, C_PC, C_FRAME_OK = 66, 69, 72, 75, 78
# … the last normal force applied (0 out of contact; the last wrench is S_W), the weight
C_NORMAL = 79
C_WEIGHT = 80
NSTATE = 83

#: state codes
FREE, SLIP, STICK = 0.0, 1.0, 2.0

#: the constants of the Python path (slidespin.engines._coupling, mujoco), repeated here so
#: that this module compiles alone; the tests check they agree
JUMP = 5.0
REST = 1e-9
FIXED_POINT_ITERATIONS = 8
FIXED_POINT_TOL = 1e-8
STEADY = 1e-2


def wrench(par, fp, phi, vx, vy, omega):
    """(Fx, Fy, M about G, status) per unit load (M per unit load and ℓ) of the twist
    (vx, vy [ℓ/time], ω) at angle φ: the kernels :class:`slidespin.contact._engine.TwistWrench`
    calls, with the same arguments (the same numbers). ``fp`` None: the ellipse's; else
    (edges, circles, geo). This body runs as Python only (``NUMBA_DISABLE_JIT=1``)."""
    if fp is None:
        return _ellipse_wrench(par, fp, phi, vx, vy, omega)
    return _footprint_wrench(par, fp, phi, vx, vy, omega)


def _ellipse_wrench(par, fp, phi, vx, vy, omega):
    return ellipse_world(
        par[P_BN], int(par[P_LAW]), par[P_XG], par[P_YG], par[P_T00], par[P_T01], par[P_T10],
        par[P_T11], par[P_BODY] != 0.0, phi, vx, vy, omega, par[P_WTOL],
    )  # fmt: skip


def _footprint_wrench(par, fp, phi, vx, vy, omega):
    fe, fc, geo = fp
    fx, fy, m = footprint_world(
        fe, fc, geo, par[P_T00], par[P_T01], par[P_T10], par[P_T11], par[P_BODY] != 0.0,
        phi, vx, vy, omega,
    )  # fmt: skip
    return fx, fy, m, 0


@overload(wrench, jit_options={"error_model": "numpy"})
def _wrench_of_type(par, fp, phi, vx, vy, omega):
    """Compiled calls of :func:`wrench`: the kernel for the type of ``fp``."""
    return _ellipse_wrench if is_none_type(fp) else _footprint_wrench


@jit(error_model="numpy")
def predicted_friction(s, slot):
    """The friction per unit load (x, y, M/ℓ) expected in this step from the last slip
    steps' (``s[S_H0:]``…): the last one, or its linear or quadratic extrapolation."""
    nh = int(s[S_NH])
    h0 = s[S_H0 + slot]
    if nh <= 1:
        return h0
    h1 = s[S_H1 + slot]
    if nh == 2:
        return 2.0 * h0 - h1
    return 3.0 * h0 - 3.0 * h1 + s[S_H2 + slot]


@jit(error_model="numpy")
def push_history(s, w0, w1, w2, normal, ell, slip_midpoint):
    """Record this step's friction for the next step's prediction: a slip solved at its
    implicit midpoint following one (``s[S_SLIPPING]``) extends the history, another slip
    starts it, anything else (stick, a launch, implicit Euler, onset) clears it."""
    if not slip_midpoint:
        s[S_NH] = 0.0
        return
    if s[S_SLIPPING] != 0.0:
        for j in range(3):
            s[S_H2 + j] = s[S_H1 + j]
            s[S_H1 + j] = s[S_H0 + j]
        s[S_NH] = min(s[S_NH] + 1.0, 3.0)
    else:
        s[S_NH] = 1.0
    s[S_H0] = w0 / normal
    s[S_H0 + 1] = w1 / normal
    s[S_H0 + 2] = w2 / (normal * ell)


@jit(error_model="numpy")
def gauge_upper(s, b0, b1, b2, phi):
    """An upper bound on the gauge γ(b) of the static set C at angle φ for a wrench b in
    natural units (per unit load, M per ℓ; b ∈ C iff γ ≤ 1), from the last exact gauge
    γ_ref of b_ref at φ_ref (``s[S_REF_...]``); +∞ without one.

    γ is subadditive and C holds the ball of radius r_in, so γ(b) ≤ γ(b_ref) + |b − b_ref|/r_in
    (body frame). A body-frame (or isotropic) tensor's C is fixed in the body; a plane-frame
    tensor's turns with the body: its body-frame tensor Rᵀ𝔽R moves by at most 2σ_max|Δφ|,
    so every wrench of C(φ_ref) lies within δ = 2|Δφ| r_out of C(φ) (r_out: the bound on
    |W| per unit load), and C(φ_ref) ⊆ (1 + δ/r_in) C(φ): γ(b_ref) ≤ (1 + δ/r_in) γ_ref.
    """
    if b0 == 0.0 and b1 == 0.0 and b2 == 0.0:
        return 0.0
    if s[S_REF_OK] == 0.0:
        return math.inf
    c, sn = math.cos(phi), math.sin(phi)
    d0 = c * b0 + sn * b1 - s[S_REF_B]
    d1 = -sn * b0 + c * b1 - s[S_REF_B + 1]
    d2 = b2 - s[S_REF_B + 2]
    g_ref = s[S_REF_G]
    if s[S_BODYFRAME] == 0.0:
        g_ref *= 1.0 + 2.0 * abs(phi - s[S_REF_PHI]) * s[S_ROUT] / s[S_RIN]
    return g_ref + math.sqrt(d0 * d0 + d1 * d1 + d2 * d2) / s[S_RIN]


@jit(error_model="numpy")
def steady_step(
    qvel, xmat, xipos, xpos, qfrc_constraint, qfrc_applied, xfrc_applied, qfrc_passive,
    geom, b, a, t, h, s, par, fp,
):  # fmt: skip
    """Do one steady step of a coupled MuJoCo body in place, or nothing.

    Parameters
    ----------
    qvel, xmat, xipos, xpos, qfrc_constraint, qfrc_applied, xfrc_applied, qfrc_passive
        MuJoCo's arrays of the data (2-D where MuJoCo's are: ``xmat`` (nbody, 9), …);
        ``qfrc_passive`` is added to.
    geom : (ncon, 2) int32 array
        The contacts' geom pairs.
    b, a : int
        The body and its free joint's first dof.
    t, h : float
        The engine's time and step [s].
    s : float array
        The coupling's state (layout above), updated when the step is done.
    par, fp
        The kernel's parameter vector and footprint (None for an ellipse).

    Returns
    -------
    int
        :data:`DONE`, or :data:`PYTHON` (nothing written but the evaluations counter).
    """
    # -- the same contact as in the step just before, on a static support ------------------
    if s[C_LAST_OK] == 0.0 or s[C_FRAME_OK] == 0.0 or s[C_DEBT] != 0.0 or h != s[S_DT]:
        return PYTHON
    ci = int(s[C_CI])
    if ci >= geom.shape[0] or geom[ci, 0] != s[C_G1] or geom[ci, 1] != s[C_G2]:
        return PYTHON
    if t == s[C_LAST_T] or t == s[S_T]:
        return PYTHON  # the same step again (mj_forward, then mj_step): the Python path
    # the step just after the last one (the Python path's test, kept below half a step at
    # any time, so that a repeated time never passes for the next step)
    tol_t = min(1e-9 * max(h, abs(t)), 0.5 * h)
    if not abs(t - s[C_LAST_T] - h) <= tol_t or not abs(t - s[S_T] - h) <= tol_t:
        return PYTHON
    if s[S_NU_OK] == 0.0 or s[S_U_OK] == 0.0:
        return PYTHON
    n0, n1, n2 = s[C_N], s[C_N + 1], s[C_N + 2]
    a0, a1, a2 = s[C_E1], s[C_E1 + 1], s[C_E1 + 2]
    c0, c1, c2 = s[C_E2], s[C_E2 + 1], s[C_E2 + 2]
    # -- the normal force: the engine's of the step before, steady ------------------------
    lag = qfrc_constraint[a] * n0 + qfrc_constraint[a + 1] * n1 + qfrc_constraint[a + 2] * n2
    last_lag = s[C_LAST_LAG]
    if not (lag > 0.0 and abs(lag - last_lag) <= STEADY * max(lag, abs(last_lag))):
        return PYTHON
    normal = lag
    # -- the planar twist relative to the support, and the angle --------------------------
    gx, gy, gz = xipos[b, 0], xipos[b, 1], xipos[b, 2]
    rx, ry, rz = gx - xpos[b, 0], gy - xpos[b, 1], gz - xpos[b, 2]
    r00, r01, r02 = xmat[b, 0], xmat[b, 1], xmat[b, 2]
    r10, r11, r12 = xmat[b, 3], xmat[b, 4], xmat[b, 5]
    r20, r21, r22 = xmat[b, 6], xmat[b, 7], xmat[b, 8]
    vx, vy, vz = qvel[a], qvel[a + 1], qvel[a + 2]
    u0, u1, u2 = qvel[a + 3], qvel[a + 4], qvel[a + 5]
    wx = r00 * u0 + r01 * u1 + r02 * u2
    wy = r10 * u0 + r11 * u1 + r12 * u2
    wz = r20 * u0 + r21 * u1 + r22 * u2
    vx += wy * rz - wz * ry
    vy += wz * rx - wx * rz
    vz += wx * ry - wy * rx
    nu0 = vx * a0 + vy * a1 + vz * a2
    nu1 = vx * c0 + vy * c1 + vz * c2
    nu2 = wx * n0 + wy * n1 + wz * n2
    phi = math.atan2(r00 * c0 + r10 * c1 + r20 * c2, r00 * a0 + r10 * a1 + r20 * a2)
    # -- the loads known before the solve: gravity, xfrc_applied, qfrc_applied ------------
    q0, q1, q2 = qfrc_applied[a], qfrc_applied[a + 1], qfrc_applied[a + 2]
    s0, s1, s2 = qfrc_applied[a + 3], qfrc_applied[a + 4], qfrc_applied[a + 5]
    x0, x1, x2 = xfrc_applied[b, 0], xfrc_applied[b, 1], xfrc_applied[b, 2]
    y0, y1, y2 = xfrc_applied[b, 3], xfrc_applied[b, 4], xfrc_applied[b, 5]
    m, inertia, ell, k = s[S_M], s[S_I], s[S_ELL], s[S_K]
    px = q0 + x0 + s[C_WEIGHT]
    py = q1 + x1 + s[C_WEIGHT + 1]
    pz = q2 + x2 + s[C_WEIGHT + 2]
    # qfrc_applied's torque: body frame, about the frame origin; to G: + (O − G) × F
    t0 = r00 * s0 + r01 * s1 + r02 * s2 + y0 - (ry * q2 - rz * q1)
    t1 = r10 * s0 + r11 * s1 + r12 * s2 + y1 - (rz * q0 - rx * q2)
    t2 = r20 * s0 + r21 * s1 + r22 * s2 + y2 - (rx * q1 - ry * q0)
    k0 = px * a0 + py * a1 + pz * a2
    k1 = px * c0 + py * c1 + pz * c2
    k2 = t0 * n0 + t1 * n1 + t2 * n2
    # -- SteppedFriction.step: rest, the load of the step before, the impulse test ----------
    key0, key1, key2 = nu0, nu1, nu2
    tol = REST * h * normal * s[S_CAP] / m
    moving = nu0 * nu0 + nu1 * nu1 + (ell * nu2) ** 2 > tol * tol
    if not moving:
        nu0 = nu1 = nu2 = 0.0
    w0, w1, w2 = s[S_W], s[S_W + 1], s[S_W + 2]
    e0 = m * (nu0 - s[S_NU]) / h - w0
    e1 = m * (nu1 - s[S_NU + 1]) / h - w1
    e2 = inertia * (nu2 - s[S_NU + 2]) / h - w2
    if s[S_KNOWN_OK] != 0.0:
        e0 -= s[S_KNOWN]
        e1 -= s[S_KNOWN + 1]
        e2 -= s[S_KNOWN + 2]
    thr = JUMP * normal * s[S_CAP]
    if _dist(e0, e1, e2, s, S_U, ell) > thr and _dist(e0, e1, e2, s, S_URAW, ell) > thr:
        return PYTHON  # an impulse: a launch, done by the Python path
    f0, f1, f2 = e0 + k0, e1 + k1, e2 + k2
    slipping = s[S_STATE] == SLIP
    # -- stick or stop: the wrench that zeroes the twist, if the cheap bound puts it in C --
    r0 = -m * nu0 / h - f0
    r1 = -m * nu1 / h - f1
    r2 = -inertia * nu2 / h - f2
    b0, b1, b2 = r0 / normal, r1 / normal, r2 / (ell * normal)
    stick = False
    if b0 * b0 + b1 * b1 + b2 * b2 <= s[S_ROUT] ** 2:
        if not gauge_upper(s, b0, b1, b2, phi) <= 1.0:
            return PYTHON  # the exact gauge decides: the Python path
        if slipping:
            return PYTHON  # a stop within this step: its time, by the Python path
        stick = True
    if stick:
        w0, w1, w2 = r0, r1, r2
    else:
        if not moving:
            return PYTHON  # breaking away from rest: the onset direction
        # -- slip: the implicit midpoint z = x + τ (a + A(z)), τ = h/2 --------------------
        tau = 0.5 * h
        x0, x1, x2 = nu0, nu1, k * nu2
        l0, l1, l2 = f0 / m, f1 / m, f2 / (m * k)
        g0, g1, g2 = x0, x1, x2
        cn = normal / m
        if slipping and s[S_NH] > 0.0:  # the friction of the last slip steps, extrapolated
            g0 += tau * (l0 + cn * predicted_friction(s, 0))
            g1 += tau * (l1 + cn * predicted_friction(s, 1))
            g2 += tau * (l2 + cn * predicted_friction(s, 2) * ell / k)
        elif slipping:  # the friction of the step before
            g0 += tau * (l0 + w0 / m)
            g1 += tau * (l1 + w1 / m)
            g2 += tau * (l2 + w2 / (m * k))
        ng = math.sqrt(g0 * g0 + g1 * g1 + g2 * g2)
        if not ng > 0.0:
            g0, g1, g2 = x0, x1, x2
            ng = math.sqrt(g0 * g0 + g1 * g1 + g2 * g2)
        v0, v1, v2 = g0 / ng, g1 / ng, g2 / ng
        done = False
        for _ in range(FIXED_POINT_ITERATIONS):
            ax, ay, mo, st = wrench(par, fp, phi, v0 / ell, v1 / ell, v2 / k)
            s[S_EVALS] += 1.0
            if st != 0:
                return PYTHON
            z0 = x0 + tau * (l0 + cn * ax)
            z1 = x1 + tau * (l1 + cn * ay)
            z2 = x2 + tau * (l2 + cn * mo * ell / k)
            nz = math.sqrt(z0 * z0 + z1 * z1 + z2 * z2)
            if nz == 0.0:
                return PYTHON
            q0, q1, q2 = z0 / nz, z1 / nz, z2 / nz
            moved = abs(q0 - v0) + abs(q1 - v1) + abs(q2 - v2)
            v0, v1, v2 = q0, q1, q2
            if moved <= FIXED_POINT_TOL:
                done = True
                w0, w1, w2 = normal * ax, normal * ay, normal * mo * ell
                break
        if not done:
            return PYTHON
    # -- the step is done: the state, then the force on the body -------------------------
    s[S_SLIPPING] = 1.0 if slipping else 0.0
    push_history(s, w0, w1, w2, normal, ell, not stick)
    s[S_STATE] = STICK if stick else SLIP
    s[S_T] = t
    s[S_NU], s[S_NU + 1], s[S_NU + 2], s[S_NU_OK] = nu0, nu1, nu2, 1.0
    s[S_W], s[S_W + 1], s[S_W + 2] = w0, w1, w2
    s[S_KEY], s[S_KEY + 1], s[S_KEY + 2], s[S_KEY + 3] = t, key0, key1, key2
    s[S_KEY + 4], s[S_KEY + 5], s[S_KEY_OK] = phi, normal, 1.0
    s[S_URAW], s[S_URAW + 1], s[S_URAW + 2] = e0, e1, e2
    s[S_U], s[S_U + 1], s[S_U + 2] = e0, e1, e2
    s[S_KNOWN], s[S_KNOWN + 1], s[S_KNOWN + 2], s[S_KNOWN_OK] = k0, k1, k2, 1.0
    s[S_STEPS] += 1.0
    s[S_FAST] += 1.0
    s[C_LAST_T], s[C_LAST_N], s[C_LAST_LAG] = t, normal, lag
    s[C_NORMAL] = normal
    fx = w0 * a0 + w1 * c0
    fy = w0 * a1 + w1 * c1
    fz = w0 * a2 + w1 * c2
    tx, ty, tz = w2 * n0, w2 * n1, w2 * n2
    # the point of the contact plane below G, relative to the body frame's origin
    depth = (gx - s[C_PC]) * n0 + (gy - s[C_PC + 1]) * n1 + (gz - s[C_PC + 2]) * n2
    px = rx - depth * n0
    py = ry - depth * n1
    pz = rz - depth * n2
    tx += py * fz - pz * fy
    ty += pz * fx - px * fz
    tz += px * fy - py * fx
    qfrc_passive[a] += fx
    qfrc_passive[a + 1] += fy
    qfrc_passive[a + 2] += fz
    # the free joint's rotational dofs turn about the body's axes (xmat's columns)
    qfrc_passive[a + 3] += r00 * tx + r10 * ty + r20 * tz
    qfrc_passive[a + 4] += r01 * tx + r11 * ty + r21 * tz
    qfrc_passive[a + 5] += r02 * tx + r12 * ty + r22 * tz
    return DONE


@jit(error_model="numpy")
def _dist(e0, e1, e2, s, i, ell):
    """|e − s[i:i+3]| for wrenches (F, F, M), the moment per ℓ."""
    return math.sqrt((e0 - s[i]) ** 2 + (e1 - s[i + 1]) ** 2 + ((e2 - s[i + 2]) / ell) ** 2)


@jit(error_model="numpy")
def steady_ellipse(
    qvel, xmat, xipos, xpos, qfrc_constraint, qfrc_applied, xfrc_applied, qfrc_passive,
    geom, b, a, t, h, s, par,
):  # fmt: skip
    """:func:`steady_step` for an elliptic patch (the entry the coupling calls)."""
    return steady_step(
        qvel, xmat, xipos, xpos, qfrc_constraint, qfrc_applied, xfrc_applied, qfrc_passive,
        geom, b, a, t, h, s, par, None,
    )  # fmt: skip


@jit(error_model="numpy")
def steady_footprint(
    qvel, xmat, xipos, xpos, qfrc_constraint, qfrc_applied, xfrc_applied, qfrc_passive,
    geom, b, a, t, h, s, par, fe, fc, geo,
):  # fmt: skip
    """:func:`steady_step` for a footprint (edges, circles, geo: the kernel's arrays)."""
    return steady_step(
        qvel, xmat, xipos, xpos, qfrc_constraint, qfrc_applied, xfrc_applied, qfrc_passive,
        geom, b, a, t, h, s, par, (fe, fc, geo),
    )  # fmt: skip
