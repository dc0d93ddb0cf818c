"""The slip equations of a loaded body (MODEL §11) in compiled form: the applied load from
tables, the right-hand sides in τ and in t, the slaved onset direction and the stiffness.

This is the compiled twin of :mod:`slidespin.motion._loaded_problem` (whose docstring derives
the system): with s = √(vx² + vy² + k² ω²), u = (vx, vy, k ω)/s, the friction accelerations
A(u, φ) = cos α (Fx, Fy, M/k)/(m g) and the applied ones B(t, φ) = (Qx, Qy, T_G/k)/(m g),
X = A + B,

    du/dτ = X − (u·X) u,   d ln s/dτ = u·X,   dt/dτ = s,
    dx/dτ = s² u₁,  dy/dτ = s² u₂,  dφ/dτ = s² u₃/k,  dW_f/dτ = s² u·A,  dW_Q/dτ = s² u·B.

One state layout serves three right-hand sides (the ``mode`` argument, a float so that no
integer literal reaches a compiled call):

* ``MODE_TAU``: y = (u, ln s, t, x, y, φ, W_f, W_Q) in the regularised time τ (dt = s dτ),
  smooth through a stop;
* ``MODE_T``: y = (u, s, t, x, y, φ, W_f, W_Q) in the time t itself (the derivatives above
  divided by s, with s in place of ln s): the form for a start from rest, where the motion
  is polynomial in t (s ∝ (t − t₀)² for a ramp) but has a pole in τ;
* ``MODE_SLAVED``: the slow start, t independent, u slaved to the onset direction u*(t, φ)
  (A_a + A(u*) = λ u*, solved by Newton's method from the previous direction, which the
  state carries in its first three entries, whose derivatives are zero): ds/dt = λ,
  dx/dt = s u*₁, ... (:func:`slidespin.motion._stick_slip._quasi_static`).

The load comes from one float array ``tab`` (:func:`load_table`): a constant or
piecewise-linear force and torque (plane or body frame, at a body point) and a constant or
piecewise-linear tilt, interpolated by bisection of the knots, O(log n) per evaluation. A
load given as a Python callable has no table: the Python path runs it
(:mod:`slidespin.motion._stick_slip`). The friction wrench is
:func:`slidespin.contact._engine.accelerations`, the one compiled entry, with the patch
``fp`` passed as data (``None`` for an ellipse, the footprint's arrays otherwise).
"""

from __future__ import annotations

import math

import numpy as np

from slidespin._jit import jit
from slidespin.contact._engine import P_K, accelerations
from slidespin.contact._profile import Profile

#: state length and the length of a right-hand side (which also returns the direction u it
#: used, in entries NY..NY+2: the slaved direction u* in MODE_SLAVED)
NY = 10
NOUT = NY + 3
MODE_TAU = 0.0
MODE_T = 1.0
MODE_SLAVED = 2.0
#: right-hand-side status: 0 ok, else the wrench missed its target or the slaved direction
#: was not found (the Python path then takes over)
RHS_WRENCH = 1
RHS_SLAVE = 2

# table header: knot counts, load frame, lever arm (natural, from G), downhill direction,
# radius of gyration, offsets of the four arrays
(
    H_NL,
    H_NI,
    H_BODY,
    H_ATX,
    H_ATY,
    H_DX,
    H_DY,
    H_K,
    H_LT,
    H_LV,
    H_IT,
    H_IA,
) = range(12)
HEAD = 12
#: the slaved direction: Newton's residual target, its acceptance bound (the Python path's
#: ``quick`` onset accepts 1e-11) and its iteration cap
SLAVE_RES = 1e-14
SLAVE_ACCEPT = 1e-11
SLAVE_ITER = 30


def load_table(prob) -> np.ndarray | None:
    """The table of the load and tilt of the problem ``prob`` (natural units), or None when
    either is a Python callable (the Python path then runs the run).

    A piecewise-linear force and torque may have different knots: the table holds their
    union, at which each is evaluated exactly (so the interpolation reproduces each).
    """
    load, inc = prob.load, prob.incline
    tu, a, k = prob.t_unit, prob.a, prob.k
    mg = prob.body.mass * prob.g
    if load is not None and not load.is_piecewise_linear:
        return None
    if inc is not None and not inc.is_constant and inc.knots == ():
        return None
    if load is None:
        lt = np.zeros(1)
        lv = np.zeros((1, 3))
        body = 0.0
        atx = aty = 0.0
    else:
        knots = load.knots
        times = np.asarray(knots if knots else (0.0,), dtype=float)
        lv = np.empty((times.size, 3))
        lv[:, 0:2] = _columns_at(load.force, times, 2) / mg
        lv[:, 2] = _columns_at(load.torque, times, 1)[:, 0] / (mg * a)
        lt = times / tu
        body = 1.0 if load.frame == "body" else 0.0
        if load.at is None:
            atx = aty = 0.0
        else:
            gx, gy = prob.body.mass_centre
            atx, aty = (load.at[0] - gx) / a, (load.at[1] - gy) / a
    if inc is None:
        it, ia = np.zeros(1), np.zeros(1)
        dx = dy = 0.0
    else:
        dx, dy = inc.direction
        if inc.is_constant:
            it, ia = np.zeros(1), np.array([float(inc.angle)])
        else:
            prof = inc.angle
            it = np.asarray(prof.times, dtype=float) / tu
            ia = np.asarray(prof.columns[0], dtype=float)
    nl, ni = lt.size, it.size
    head = np.zeros(HEAD)
    head[H_NL], head[H_NI] = nl, ni
    head[H_BODY], head[H_ATX], head[H_ATY] = body, atx, aty
    head[H_DX], head[H_DY], head[H_K] = dx, dy, k
    head[H_LT] = HEAD
    head[H_LV] = HEAD + nl
    head[H_IT] = HEAD + 4 * nl
    head[H_IA] = HEAD + 4 * nl + ni
    return np.ascontiguousarray(np.concatenate([head, lt, lv.ravel(), it, ia]))


def _columns_at(value, times: np.ndarray, ncol: int) -> np.ndarray:
    """A constant (a number or a pair) or a piecewise-linear profile at ``times``, (n, ncol):
    the profile's own samples where its knots are ``times``, else its interpolation
    (1 − w) v₀ + w v₁ (constant beyond the ends), as the profile evaluates itself."""
    if not isinstance(value, Profile):
        return np.broadcast_to(np.atleast_1d(np.asarray(value, dtype=float)), (times.size, ncol))
    tt = np.asarray(value.times, dtype=float)
    cols = np.asarray(value.columns, dtype=float).T  # (n knots, ncol)
    if tt.shape == times.shape and np.array_equal(tt, times):
        return cols
    i = np.clip(np.searchsorted(tt, times, side="right") - 1, 0, tt.size - 2)
    w = np.clip((times - tt[i]) / (tt[i + 1] - tt[i]), 0.0, 1.0)[:, None]
    return (1.0 - w) * cols[i] + w * cols[i + 1]


def table_breaks(tab: np.ndarray) -> np.ndarray:
    """The knots of the table's load and tilt (natural times), sorted, without repeats."""
    nl, ni = int(tab[H_NL]), int(tab[H_NI])
    lt = tab[int(tab[H_LT]) : int(tab[H_LT]) + nl] if nl > 1 else np.empty(0)
    it = tab[int(tab[H_IT]) : int(tab[H_IT]) + ni] if ni > 1 else np.empty(0)
    return np.unique(np.concatenate([lt, it]))


@jit(error_model="numpy")
def _segment(tab, off, n, t):
    """(i, w): t lies in [T_i, T_{i+1}) of the n knots at tab[off:], w its fraction (w = 0
    before the first knot and from the last on: the ends are held)."""
    if n < 2 or t <= tab[off]:
        return 0, 0.0
    if t >= tab[off + n - 1]:
        return n - 1, 0.0
    lo = 0
    hi = n - 1
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if tab[off + mid] <= t:
            lo = mid
        else:
            hi = mid
    return lo, (t - tab[off + lo]) / (tab[off + hi] - tab[off + lo])


@jit(error_model="numpy")
def applied(tab, t, phi):
    """(bx, by, bm, nf): the applied accelerations (Qx, Qy, T_G/k)/(m g) at the natural time
    t and body angle φ, and the normal factor cos α(t)."""
    nl = int(tab[H_NL])
    ni = int(tab[H_NI])
    i, w = _segment(tab, int(tab[H_LT]), nl, t)
    o = int(tab[H_LV]) + 3 * i
    if w == 0.0:
        qx = tab[o]
        qy = tab[o + 1]
        mz = tab[o + 2]
    else:
        qx = (1.0 - w) * tab[o] + w * tab[o + 3]
        qy = (1.0 - w) * tab[o + 1] + w * tab[o + 4]
        mz = (1.0 - w) * tab[o + 2] + w * tab[o + 5]
    c = math.cos(phi)
    sn = math.sin(phi)
    if tab[H_BODY] != 0.0:
        qx, qy = c * qx - sn * qy, sn * qx + c * qy
    atx = tab[H_ATX]
    aty = tab[H_ATY]
    if atx != 0.0 or aty != 0.0:
        rx = c * atx - sn * aty
        ry = sn * atx + c * aty
        mz += rx * qy - ry * qx
    j, wa = _segment(tab, int(tab[H_IT]), ni, t)
    oa = int(tab[H_IA]) + j
    alpha = tab[oa] if wa == 0.0 else (1.0 - wa) * tab[oa] + wa * tab[oa + 1]
    sa = math.sin(alpha)
    return qx + sa * tab[H_DX], qy + sa * tab[H_DY], mz / tab[H_K], math.cos(alpha)


@jit(error_model="numpy")
def applied_many(tab, times, phi, out):
    """The applied wrench per unit normal load in the coordinates of the static-friction set
    C, (bx, by, k bm)/cos α, at each of ``times`` (the Python path's ``w_nat``)."""
    k = tab[H_K]
    for i in range(times.size):
        bx, by, bm, nf = applied(tab, times[i], phi)
        out[i, 0] = bx / nf
        out[i, 1] = by / nf
        out[i, 2] = bm * k / nf


@jit(error_model="numpy")
def _frame(u1, u2, u3):
    """An orthonormal tangent frame (e1, e2) at the unit vector u (the Python onset's)."""
    if abs(u1) < 0.9:
        e1x, e1y, e1z = 0.0, u3, -u2  # u × (1, 0, 0)
    else:
        e1x, e1y, e1z = -u3, 0.0, u1  # u × (0, 1, 0)
    n = math.sqrt(e1x * e1x + e1y * e1y + e1z * e1z)
    e1x /= n
    e1y /= n
    e1z /= n
    e2x = u2 * e1z - u3 * e1y
    e2y = u3 * e1x - u1 * e1z
    e2z = u1 * e1y - u2 * e1x
    return e1x, e1y, e1z, e2x, e2y, e2z


@jit(error_model="numpy")
def _unit_at(v, p, q):
    """(v₀ + p e1 + q e2)/|·| with (e1, e2) = v[3:9]."""
    x1 = v[0] + p * v[3] + q * v[6]
    x2 = v[1] + p * v[4] + q * v[7]
    x3 = v[2] + p * v[5] + q * v[8]
    n = math.sqrt(x1 * x1 + x2 * x2 + x3 * x3)
    return x1 / n, x2 / n, x3 / n


@jit(error_model="numpy")
def _tangential(v, x1, x2, x3, X1, X2, X3, r):
    """r = (t·e1, t·e2, λ, u) for t = X − λ u, λ = u·X."""
    lam = x1 * X1 + x2 * X2 + x3 * X3
    t1 = X1 - lam * x1
    t2 = X2 - lam * x2
    t3 = X3 - lam * x3
    r[0] = t1 * v[3] + t2 * v[4] + t3 * v[5]
    r[1] = t1 * v[6] + t2 * v[7] + t3 * v[8]
    r[2] = lam
    r[3] = x1
    r[4] = x2
    r[5] = x3


@jit(error_model="numpy")
def slaved_direction(par, kc, W, fp, tab, t, phi, u1, u2, u3, out):
    """The onset direction u* (A_a + A(u*) = λ u*) near u by Newton's method in the tangent
    plane at u (difference Jacobian, steps halved while they do not lower the residual), as
    the Python ``quick`` onset does; fills out = (u*, λ, |residual|) and returns (ok, kernel
    calls). λ may have either sign.

    (One call site of the kernel, in a loop over the points each iteration needs: numba
    compiles every function that reaches the kernel together with it.)
    """
    bx, by, bm, nf = applied(tab, t, phi)
    v = np.empty(9)
    v[0] = u1
    v[1] = u2
    v[2] = u3
    e = _frame(u1, u2, u3)
    for i in range(6):
        v[3 + i] = e[i]
    r0 = np.empty(6)
    rp = np.empty(6)
    rq = np.empty(6)
    rc = np.empty(6)
    d = 1e-7
    p = 0.0
    q = 0.0
    dp = 0.0
    dq = 0.0
    res = math.inf
    calls = 0
    st = 0
    it = 0
    tries = 0
    role = 0  # the point evaluated next: 0 the iterate, 1 and 2 its differences, 3 a step
    pp = 0.0
    qq = 0.0
    while True:
        x1, x2, x3 = _unit_at(v, pp, qq)
        ax, ay, am, sk = accelerations(par, kc, W, fp, x1, x2, x3, phi)
        st += sk
        calls += 1
        r = r0 if role == 0 else (rp if role == 1 else (rq if role == 2 else rc))
        _tangential(v, x1, x2, x3, bx + ax * nf, by + ay * nf, bm + am * nf, r)
        if role == 0:
            res = math.hypot(r0[0], r0[1])
        elif role == 2:
            j11 = (rp[0] - r0[0]) / d
            j21 = (rp[1] - r0[1]) / d
            j12 = (rq[0] - r0[0]) / d
            j22 = (rq[1] - r0[1]) / d
            det = j11 * j22 - j12 * j21
            if det == 0.0 or not math.isfinite(det):
                break
            dp = -(j22 * r0[0] - j12 * r0[1]) / det
            dq = -(-j21 * r0[0] + j11 * r0[1]) / det
            tries = 0
        elif role == 3:
            rn = math.hypot(rc[0], rc[1])
            if rn < res or rn <= SLAVE_RES:
                p += dp
                q += dq
                for i in range(6):
                    r0[i] = rc[i]
                res = rn
                it += 1
                if abs(dp) + abs(dq) < 1e-15:
                    break
                role = 0  # the new iterate is evaluated already
            else:
                tries += 1
                if tries >= 8:
                    break
                dp *= 0.5
                dq *= 0.5
                pp = p + dp
                qq = q + dq
                continue
        if role == 0:
            if res <= SLAVE_RES or st != 0 or it >= SLAVE_ITER:
                break
            role = 1
            pp = p + d
            qq = q
        elif role == 1:
            role = 2
            pp = p
            qq = q + d
        else:
            role = 3
            pp = p + dp
            qq = q + dq
    out[0] = r0[3]
    out[1] = r0[4]
    out[2] = r0[5]
    out[3] = r0[2]
    out[4] = res
    return st == 0 and res < SLAVE_ACCEPT, calls


@jit(error_model="numpy")
def rhs(par, kc, W, fp, tab, mode, y, out):
    """The right-hand side of ``mode`` at y (module docstring); returns (status, kernel
    calls). out[NY:NY+3] is the direction used (u normalised, or u* when slaved)."""
    k = par[P_K]
    calls = 1
    slave_ok = True
    lam = 0.0
    if mode == MODE_SLAVED:
        dirn = np.empty(5)
        slave_ok, n = slaved_direction(par, kc, W, fp, tab, y[4], y[7], y[0], y[1], y[2], dirn)
        calls += n
        u1 = dirn[0]
        u2 = dirn[1]
        u3 = dirn[2]
        lam = dirn[3]
    else:
        inv = 1.0 / math.sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2])
        u1 = y[0] * inv
        u2 = y[1] * inv
        u3 = y[2] * inv
    bx, by, bm, nf = applied(tab, y[4], y[7])
    ax, ay, am, st = accelerations(par, kc, W, fp, u1, u2, u3, y[7])
    ax *= nf
    ay *= nf
    am *= nf
    out[NY] = u1
    out[NY + 1] = u2
    out[NY + 2] = u3
    if mode == MODE_SLAVED:
        s = y[3]
        out[0] = 0.0
        out[1] = 0.0
        out[2] = 0.0
        out[3] = lam
        out[4] = 1.0
        q = s
    else:
        xx = ax + bx
        xy = ay + by
        xm = am + bm
        ux = u1 * xx + u2 * xy + u3 * xm
        if mode == MODE_T:
            s = y[3]
            g = 1.0 / s
            out[4] = 1.0
            q = s
        else:
            # beyond e^709 the speed overflows: a wild trial stage, rejected by the step control
            s = math.exp(y[3]) if y[3] < 709.0 else math.inf
            g = 1.0
            out[4] = s
            q = s * s
        out[0] = (xx - ux * u1) * g
        out[1] = (xy - ux * u2) * g
        out[2] = (xm - ux * u3) * g
        out[3] = ux
    out[5] = q * u1
    out[6] = q * u2
    out[7] = q * u3 / k
    out[8] = q * (u1 * ax + u2 * ay + u3 * am)
    out[9] = q * (u1 * bx + u2 * by + u3 * bm)
    if not slave_ok:
        return RHS_SLAVE, calls
    return (RHS_WRENCH if st != 0 else 0), calls


@jit(error_model="numpy")
def stiffness(par, kc, W, fp, tab, u1, u2, u3, t, phi):
    """Ratio of the fastest relaxation rate of the direction u (in τ) to the growth rate
    |u·X|: the largest modulus of the eigenvalues of the sphere flow's tangent Jacobian
    (forward differences, as the Python path's ``stiffness``) over |u·X|. Returns
    (ratio, kernel calls)."""
    y = np.zeros(NY)
    y[0] = u1
    y[1] = u2
    y[2] = u3
    y[4] = t
    y[7] = phi
    f0 = np.empty(NOUT)
    fh = np.empty(NOUT)
    rhs(par, kc, W, fp, tab, MODE_TAU, y, f0)
    jm = np.empty((3, 3))
    for j in range(3):
        h = 1e-7 * max(1.0, abs(y[j]))
        keep = y[j]
        y[j] = keep + h
        rhs(par, kc, W, fp, tab, MODE_TAU, y, fh)
        y[j] = keep
        for i in range(3):
            jm[i, j] = (fh[i] - f0[i]) / h
    n = math.sqrt(u1 * u1 + u2 * u2 + u3 * u3)
    e = _frame(u1 / n, u2 / n, u3 / n)
    # the 2 × 2 restriction to the tangent plane: B_ij = e_i · J e_j
    b = np.empty((2, 2))
    for i in range(2):
        for j in range(2):
            acc = 0.0
            for r in range(3):
                col = 0.0
                for c in range(3):
                    col += jm[r, c] * e[3 * j + c]
                acc += e[3 * i + r] * col
            b[i, j] = acc
    tr = b[0, 0] + b[1, 1]
    det = b[0, 0] * b[1, 1] - b[0, 1] * b[1, 0]
    disc = tr * tr - 4.0 * det
    if disc >= 0.0:
        sq = math.sqrt(disc)
        kappa = max(abs(0.5 * (tr + sq)), abs(0.5 * (tr - sq)))
    else:
        kappa = math.sqrt(abs(det))
    return kappa / max(abs(f0[3]), 1e-300), 4
