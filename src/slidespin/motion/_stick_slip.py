"""The phases of a loaded run (MODEL §11): the stick and its end, the slow start and the
slip, for the problem of :mod:`slidespin.motion._loaded_problem`.

Stick and slip, exactly (no regularised friction):

* at rest, the body stays while −W_a(t) lies in the static-friction set C
  (:mod:`slidespin.contact.static_set`), to within GAUGE_TOL = 1e-12 (relative) of its
  boundary; for a time-varying load the moment W_a leaves C is the root of
  γ(t) − 1 − GAUGE_TOL, γ the gauge of C at W_a(t) (the inverse load factor), located by
  Brent's method to ``time_tol`` after a scan: at every knot of a piecewise-linear load or
  tilt (exact: γ is convex between knots, so no excursion is missed) and, for callables, on
  a grid of step ``scan_step`` (default at most SCAN_STEP_MAX = 1 ms; an excursion beyond C
  longer than the step is always found, a shorter one may be missed);
* a tilt may vary in time (``Incline(callable)``, :meth:`Incline.piecewise_linear`): the
  factor cos α(t) of the friction accelerations and of C and the pull sin α(t) d follow it;
* it starts in the onset direction u (A_a + A(u) = λ u, λ > 0;
  :func:`slidespin.contact.statics.onset`); s grows linearly, s ≈ λ (t − t₀), so the slip
  starts analytically at a small s. A ramped load starts the body at the threshold, where
  λ = 0⁺ (computed as round-off of either sign); s then grows like (t − t₀)² as λ(t) grows.
  Should the onset solve fail (a direction always exists beyond C, so only numerically), the
  run ends there, at rest, with status ``no_onset`` and a message, never an exception;
* it stops when s falls to a tiny fraction of its scale (the rest of the approach is added
  in closed form, t += s/|u·X|), and then sticks if −W_a ∈ C there, or starts again at once
  in the new onset direction (a body thrown up a slope steeper than the friction angle
  stops and slides back down).

The slip equations become stiff where s is small while the load changes slowly (the
direction u relaxes in O(1) τ while the motion evolves over O(1/λ) τ), so a slip from rest
is integrated by ``Radau`` (implicit, order 5) of :func:`scipy.integrate.solve_ivp` while it
is stiff, then by ``DOP853``: :class:`PythonSlip`, the path of loads given as Python
functions (each right-hand side calls the compiled wrench kernel once, and the load, from
Python). Loads given as tables run the same phases in compiled code
(:class:`slidespin.motion._loaded_engine.CompiledSlip`); the stick test and its exit time
(:func:`_stick_exit`) serve both.
"""

from __future__ import annotations

import math

import numpy as np

from slidespin.contact.statics import OnsetNotFound, _load_factor_nat, _onset_nat

#: a body at rest is held while the gauge γ = 1/λ* ≤ 1 + GAUGE_TOL. Within 1e-12 of the
#: threshold the onset rate λ (∝ γ − 1) is below the round-off of the friction kernel, its
#: sign is noise, and the motion such a load could produce is nil; the margin keeps the
#: decision to slip and the onset it leads to consistent (a load held exactly at the
#: threshold would otherwise start, stall and start again at the same instant)
GAUGE_TOL = 1e-12
#: cap [s] on the default step of the scan for a time-varying load leaving C (a callable
#: load whose excursion beyond C lasts longer than the step is always found)
SCAN_STEP_MAX = 1e-3
#: the default scan takes at most this many points per stick phase (so for stick phases
#: longer than SCAN_STEP_MAX × SCAN_POINTS_MAX = 200 s the default step is duration/2e5)
SCAN_POINTS_MAX = 200_000
#: the most scan samples one run may ask for (t_end / scan_step): each is a load evaluation,
#: and the grid of a stick phase is built at once (1e-9 s over 20 s would be 22 GiB)
SCAN_SAMPLES_MAX = 1_000_000
#: a stick phase with more points to look at than this bounds the gauge between them
#: (three minimisations up front; for fewer points the gauge at each is cheaper)
BOUND_POINTS = 16


def _quasi_static(prob, t0, pos, work, t_end, rtol, s_slow, s0=0.0, u0=None):
    """Slow start from rest at t0 with u slaved to the onset direction u*(t, φ).

    While s is tiny the direction relaxes to u* in a time ~ s/κ, far faster than the load
    or the angle change, so u = u*(t, φ) + O(s): integrate, in t, ds/dt = λ = u*·X,
    dr/dt = s u*, and the work, until s reaches ``s_slow`` (then the full equations take
    over), λ falls to 0 (the load has re-entered C), s falls back to 0 (a load that only
    grazed the boundary of C), or t_end. At the threshold λ(t0) = 0 (within round-off) and
    grows as the load does. Returns (t, pos, work, s, u, reason, rows) with rows
    (t, s, x, y, φ, u, W_f, W_Q). ``s0`` and ``u0`` continue a slow start from the speed s0
    in (near) the slaved direction u0 (where the compiled engine's Newton solve of the
    direction failed); by default it starts from rest in the onset direction.

    Raises :class:`~slidespin.contact.statics.OnsetNotFound` when no slip direction is found.
    """
    if u0 is None:
        u0 = prob.onset(t0, pos[2])[0]
    cache = {"u": np.asarray(u0, dtype=float)}
    k = prob.k

    def slaved(t, z):
        phi = z[3]
        prob.hold_at(z[1:3])  # s is below the slow speed: the springs as at rest
        b = np.array(prob.b(t, phi))
        acc = _friction_fun(prob, phi, t)
        got = _onset_nat(acc, b, cache["u"], quick=True)
        if got is None:
            got = _onset_nat(acc, b, cache["u"], allow_negative=True)
        if got is None:
            raise OnsetNotFound(
                f"the slow start lost its slip direction at t = {t * prob.t_unit:.12g} s"
            )
        u, lam, _ = got
        cache["u"] = u
        a = np.array(acc(u))
        return u, lam, a, b

    def rhs(t, z):
        prob.n_rhs += 1
        u, lam, a, b = slaved(t, z)
        s = z[0]
        return np.array([lam, s * u[0], s * u[1], s * u[2] / k, s * (u @ a), s * (u @ b)])

    def ev_fast(t, z):
        return z[0] - s_slow

    ev_fast.terminal = True
    ev_fast.direction = 1.0

    def ev_stall(t, z):
        return slaved(t, z)[1]

    ev_stall.terminal = True
    ev_stall.direction = -1.0

    def ev_back(t, z):  # s back through 0: the load only grazed C, the body stays
        return z[0]

    ev_back.terminal = True
    ev_back.direction = -1.0

    def ev_end(t, z):
        return t - t_end

    ev_end.terminal = True
    ev_end.direction = 1.0
    events = [ev_fast, ev_stall, ev_back] + ([] if math.isinf(t_end) else [ev_end])
    z0 = np.array([s0, pos[0], pos[1], pos[2], work[0], work[1]])
    t_hi = t0 + 1e6 if math.isinf(t_end) else t_end + 1.0
    from scipy.integrate import solve_ivp  # lazy: scipy.integrate costs ~0.5 s to import

    try:
        sol = solve_ivp(rhs, (t0, t_hi), z0, method="DOP853", rtol=rtol, atol=1e-18, events=events)
    except ValueError as exc:
        # solve_ivp locates an event by Brent's method on its dense output, which fails when
        # the event changed sign with round-off between the step and the location (λ of a
        # slaved direction solved again, at the threshold): the integrator gave up there
        if "different signs" not in str(exc):
            raise
        prob.failure = f"the location of a slow-start event failed ({exc})"
        u = np.asarray(cache["u"], dtype=float)
        row = np.concatenate([[t0, s0], pos, u, work])
        return t0, np.array(pos, dtype=float), np.array(work, dtype=float), s0, u, "failed", [row]
    z = sol.y[:, -1]
    te = sol.t[-1]
    reason = "t_end"
    if sol.status == -1:  # the integrator gave up: the values as reached, and why
        reason = "failed"
        prob.failure = str(sol.message)
    if sol.status == 1:
        for i, name in enumerate(("fast", "stall", "stall", "t_end")):
            if i < len(sol.t_events) and sol.t_events[i].size:
                reason = name
                te = sol.t_events[i][0]
                z = sol.y_events[i][0]
                break
    u = slaved(te, z)[0]
    rows = []
    for tt, zz in zip(sol.t[1:], sol.y[:, 1:].T):
        uu = slaved(tt, zz)[0]
        rows.append(np.concatenate([[tt, zz[0]], zz[1:4], uu, zz[4:6]]))
    rows[-1] = np.concatenate([[te, z[0]], z[1:4], u, z[4:6]])
    return te, z[1:4].copy(), z[4:6].copy(), max(float(z[0]), 0.0), u, reason, rows


def _friction_fun(prob, phi, t):
    return lambda u: np.array(prob.friction_acc(u[0], u[1], u[2], phi, t))


def _knots_nat(prob, t0, t_end):
    """Sample times of piecewise-linear loads and tilts in (t0, t_end], natural units."""
    times = set()
    for obj in (prob.load, prob.incline, *prob.springs):
        if obj is not None:
            times.update(tk / prob.t_unit for tk in obj.knots)
    return sorted(tk for tk in times if t0 < tk < t_end)


def _exact_at_knots(prob):
    """True when looking at the knots alone cannot miss the load leaving C.

    A piecewise-linear load on a fixed plane is affine in t between knots (the body is at
    rest, φ fixed), so the gauge γ of the convex set C at it is convex there and exceeds 1
    somewhere in a segment only if it does at an end. A piecewise-linear tilt with no
    other load gives γ = tan α(t) γ(d), monotone between knots. A spring of zero rest
    length without a dashpot (:mod:`slidespin.motion.springs`) pulls a stuck body with a
    force affine in t between the knots of its anchor's path, so it keeps this property.
    """
    load, inc = prob.load, prob.incline
    springs_affine = all(sp.rest_length == 0.0 and sp.damping == 0.0 for sp in prob.springs)
    if not springs_affine:
        return False
    if inc is None or inc.is_constant:
        if load is None:
            return bool(prob.springs)
        return load.is_piecewise_linear
    return load is None and not prob.springs and inc.knots != ()


def default_scan_step(duration: float) -> float:
    """Default ``scan_step`` [s] of :func:`simulate_loaded` for a stick phase that may last
    ``duration`` [s]: min(duration/400, max(SCAN_STEP_MAX, duration/SCAN_POINTS_MAX))."""
    return min(duration / 400.0, max(SCAN_STEP_MAX, duration / SCAN_POINTS_MAX))


def _stick_exit(prob, t0, phi, t_end, scan, t_tol, w_many=None, g0=None):
    """First time after t0 at which the gauge γ(t) exceeds 1 + GAUGE_TOL, or None (stays
    stuck).

    γ is evaluated at every knot of a piecewise-linear load or tilt and (unless that is
    exact, :func:`_exact_at_knots`) on a grid of step ``scan`` (natural units; default
    :func:`default_scan_step`). Where the load has moved little from the last point at which
    γ was computed, γ is bounded instead of computed: γ is a gauge of the symmetric convex
    set C, so γ(w) ≤ γ(w₀) + Σᵢ |wᵢ − w₀ᵢ| γ(eᵢ) (the triangle inequality), and a point
    with that bound below 1 is inside C without the minimisation. The bound needs γ(eᵢ)
    (three minimisations): it is used only for more than BOUND_POINTS points, and with
    ``w_many`` (the applied wrench at many times at once, from the compiled load table)
    it is evaluated a chunk of points at a time. ``g0``: γ at t0, if known.

    Where the gauge is convex between two points (:func:`_exact_at_knots`), the moment it
    passes 1 + GAUGE_TOL is found by Newton's method from the right end (:func:`_exit_newton`:
    the slope of γ from the normal of C, two or three minimisations), else (and should
    Newton's method leave the bracket) by Brent's method.
    """
    if prob.constant or math.isinf(t_end):
        return None
    # a tall body's C moves with the load (MODEL §14): no convexity, no triangle bound
    exact = _exact_at_knots(prob) and prob.tall is None
    points = _knots_nat(prob, t0, t_end)
    if scan is not None or not exact:
        h = (
            scan
            if scan is not None
            else (default_scan_step((t_end - t0) * prob.t_unit) / prob.t_unit)
        )
        n = int(math.ceil((t_end - t0) / h))
        grid = t0 + h * np.arange(1, n + 1)
        points = np.union1d(grid[grid < t_end], np.asarray(points, dtype=float)).tolist()
    points.append(t_end)
    memo = {} if g0 is None else {t0: g0 - (1.0 + GAUGE_TOL)}

    def f(tt):
        # γ carries round-off that depends on the minimiser's warm start; a load held at the
        # threshold would then change sign between the scan and Brent's own evaluation of
        # the same end point ("f(a) and f(b) must have different signs"): one value per time
        if tt not in memo:
            memo[tt] = prob.gauge(tt, phi) - (1.0 + GAUGE_TOL)
        return memo[tt]

    fa = f(t0)
    if fa > 0.0:  # pragma: no cover - γ > 1 at the scan start: slip at once
        return t0
    ge = None
    ws = None
    if len(points) > BOUND_POINTS and prob.tall is None:
        # the gauge of the unit wrenches, for the bound (C is symmetric: γ(−e) = γ(e))
        sup = prob.support(phi)
        ge = np.array([1.0 / _load_factor_nat(sup, e)[0] for e in np.eye(3)])
        if w_many is not None:
            ws = w_many(np.asarray(points, dtype=float), phi)
    w_anchor, g_anchor = prob.w_nat(t0, phi), fa + 1.0 + GAUGE_TOL
    ta = t0
    i = 0
    n_pts = len(points)
    while i < n_pts:
        if ws is not None:
            # skip, a chunk at a time, the points the bound puts certainly inside C
            chunk = ws[i : i + 4096]
            bound = g_anchor + np.abs(chunk - w_anchor) @ ge
            bad = np.flatnonzero(~(bound * (1.0 + 1e-8) < 1.0))
            if bad.size == 0:
                i += chunk.shape[0]
                ta = points[i - 1]
                continue
            if bad[0] > 0:
                ta = points[i + int(bad[0]) - 1]
            i += int(bad[0])
        tb = points[i]
        i += 1
        w = ws[i - 1] if ws is not None else prob.w_nat(tb, phi)
        if ge is not None and ws is None:
            bound = g_anchor + float(np.abs(w - w_anchor) @ ge)
            if bound * (1.0 + 1e-8) < 1.0:  # certainly inside C
                ta = tb
                continue
        fb = f(tb)
        if fb > 0.0:
            if exact:
                r, ta, tb = _exit_newton(prob, phi, ta, tb, t_tol, f)
                if r is not None:
                    return r
            f(ta)  # the bracket's left end (inside C, perhaps only bounded so far)
            from scipy.optimize import brentq  # lazy: see slidespin.contact.statics

            r = brentq(f, ta, tb, xtol=t_tol, rtol=1e-15, maxiter=200)
            # return a time at which the load is already beyond C (slip starts there)
            for _ in range(60):
                if r >= tb or f(r) > 0.0:
                    return min(r, tb)
                r += t_tol
            return tb
        ta, w_anchor, g_anchor = tb, w, fb + 1.0 + GAUGE_TOL
    return None


def _exit_newton(prob, phi, ta, tb, t_tol, f):
    """The time in (ta, tb] where the gauge γ, convex there with γ(ta) ≤ 1 + GAUGE_TOL <
    γ(tb), reaches 1 + GAUGE_TOL, by Newton's method from tb: the iterates stay to the right
    of the root (γ > 1 + GAUGE_TOL, the load beyond C) and fall to it monotonically. The
    slope is dγ/dt = γ (d*·w′)/(d*·w), d* the normal of C at the load (the envelope of
    γ(w) = max_d d·w/h(d)), w′ a difference quotient. Returns (t, ta, tb), or (None, lo,
    hi) with the bracket it narrowed to where the iteration leaves the bracket, stalls or
    meets the round-off of γ at the root (Brent's method then runs on [lo, hi])."""
    t = tb
    width = tb - ta
    for _ in range(40):
        f(t)
        g, d = prob.gauge_normal(t, phi)
        if d is None:
            return None, ta, t
        w = prob.w_nat(t, phi)
        delta = 1e-7 * width
        dw = (w - prob.w_nat(t - delta, phi)) / delta
        dd = float(d @ w)
        slope = g * float(d @ dw) / dd if dd > 0.0 else math.nan
        if not slope > 0.0:
            return None, ta, t
        step = (g - 1.0 - GAUGE_TOL) / slope
        t_new = t - step
        if not ta < t_new <= t:
            return None, ta, t
        if f(t_new) <= 0.0:
            # Newton's step met the round-off of γ at the root: the first of a few steps of
            # t_tol/2 to the right at which the load is beyond C (else Brent on [t_new, t])
            for k in range(1, 9):
                t_k = min(t_new + 0.5 * k * t_tol, t)
                if f(t_k) > 0.0:
                    return t_k, ta, t
            return None, t_new, t
        t = t_new
        if step <= t_tol:
            return t, ta, t
    return None, ta, t


def ev_none(tau, y):
    """An event that never happens (keeps the events' indices fixed)."""
    return 1.0


class _StepBudget(Exception):
    """Raised from inside solve_ivp when a slip phase has used its budget of steps."""


def _slip(prob, y0, ln_stop, t_end, rtol, method, h_max, steps_left, ln_switch=None):
    """Integrate one slip phase in τ; returns (y_end, recorded rows, steps, reason).

    ``reason``: ``stop``, ``t_end``, ``max_steps``, ``switch`` (ln s reached ``ln_switch``),
    ``tip`` (a tall body's pressure centroid reached the footprint's hull, MODEL §14)
    or ``failed`` (the integrator gave up; its message in ``prob.failure``).
    """

    def ev_stop(tau, y):
        return y[3] - ln_stop

    ev_stop.terminal = True
    ev_stop.direction = -1.0

    def ev_end(tau, y):
        return y[4] - t_end

    ev_end.terminal = True
    ev_end.direction = 1.0

    def ev_switch(tau, y):
        return y[3] - ln_switch

    ev_switch.terminal = True
    ev_switch.direction = 1.0

    def ev_tip(tau, y):  # a tall body tips: its pressure centroid reaches the hull
        return prob.tip_gauge(y) - 1.0

    ev_tip.terminal = True
    ev_tip.direction = 1.0
    events = [ev_stop, ev_end, ev_switch if ln_switch is not None else ev_none]
    if prob.tall is not None:
        events.append(ev_tip)
    # solve_ivp evaluates every event once per accepted step (and once at the start); this
    # one never changes sign and only counts the steps, so that max_steps bounds the work
    # inside one call too (a chunk alone may take unboundedly many steps)
    taken = []

    def ev_watch(tau, y):
        taken.append(y.copy())
        if steps + len(taken) - 1 > steps_left:
            raise _StepBudget
        return 1.0

    events.append(ev_watch)
    if prob.tall is not None and prob.tip_gauge(y0) >= 1.0:
        return y0, [], 0, "tip"  # a tall body that tips as soon as it moves
    atol = np.full(10, rtol * 1e-2)
    implicit = method in ("Radau", "BDF", "LSODA")
    if implicit:
        # the kernel's quadrature noise (~1e-13) times the long τ-steps an implicit method
        # takes near a threshold would defeat a tighter bound on u
        atol[:3] = max(atol[0], 1e-10)
    from scipy.integrate import solve_ivp  # lazy: see _quasi_static

    tau0 = 0.0
    chunk = 1e4
    rec = []
    steps = 0
    y = y0
    while True:
        extra = {"jac": prob.jac} if implicit else {}
        taken.clear()
        try:
            sol = solve_ivp(
                prob.rhs,
                (tau0, tau0 + chunk),
                y,
                method=method,
                rtol=rtol,
                atol=atol,
                events=events,
                max_step=h_max,
                **extra,
            )
        except ValueError as exc:  # an event's location failed (round-off, see above)
            if "different signs" not in str(exc):
                raise
            rec.extend(taken[1:])
            steps += max(len(taken) - 1, 0)
            prob.failure = f"the location of an event failed ({exc})"
            return (taken[-1] if taken else y), rec, steps, "failed"
        except _StepBudget:  # the accepted steps so far, the last one as reached
            rec.extend(taken[1:])
            steps += len(taken) - 1
            return (taken[-1] if taken else y), rec, steps, "max_steps"
        steps += sol.t.size - 1
        y = sol.y[:, -1].copy()
        if sol.status == -1:  # the integrator gave up: the values as reached, and why
            rec.extend(sol.y[:, 1:].T)
            prob.failure = str(sol.message)
            return y, rec, steps, "failed"
        if sol.status == 1:
            rec.extend(sol.y[:, 1:-1].T)
            if sol.t_events[0].size:
                ye = sol.y_events[0][0].copy()
                # closed-form tail of the approach to rest: t += s/|u·X|
                u = ye[0:3] / np.linalg.norm(ye[0:3])
                ax, ay, am = prob.friction_acc(u[0], u[1], u[2], ye[7], ye[4])
                prob.hold_at(ye[5:8])
                bx, by, bm = prob.b(ye[4], ye[7])
                rate = -(u[0] * (ax + bx) + u[1] * (ay + by) + u[2] * (am + bm))
                s = math.exp(ye[3])
                if rate > 0.0:
                    ye[4] += s / rate
                    ye[5:8] += 0.5 * s * s / rate * np.array([u[0], u[1], u[2] / prob.k])
                rec.append(ye)
                return ye, rec, steps, "stop"
            if sol.t_events[1].size:
                ye = sol.y_events[1][0].copy()
                rec.append(ye)
                return ye, rec, steps, "t_end"
            if sol.t_events[2].size:
                ye = sol.y_events[2][0].copy()
                rec.append(ye)
                return ye, rec, steps, "switch"
            ye = sol.y_events[3][0].copy()
            rec.append(ye)
            return ye, rec, steps, "tip"
        rec.extend(sol.y[:, 1:].T)
        if steps >= steps_left:
            return y, rec, steps, "max_steps"
        tau0 = sol.t[-1]


#: relaxation-to-growth ratio above which a slip from rest is integrated by Radau
_STIFF = 100.0


class PythonSlip:
    """The slow start and slip of a loaded run with :func:`scipy.integrate.solve_ivp` and
    Python right-hand sides: the path of loads and tilts given as Python callables, and of
    ``method="scipy"`` or a named solve_ivp method (the compiled engine,
    :class:`slidespin.motion._loaded_engine.CompiledSlip`, has the same two methods).

    ``method`` ``"auto"``: Radau for a slip that starts from rest while it is stiff
    (looked at again each time s has grown e^5-fold), DOP853 otherwise; else the named
    solve_ivp method throughout.
    """

    def __init__(self, prob, method, rtol, h_max, slow_speed):
        self.prob = prob
        self.method = method
        self.rtol = rtol
        self.h_max = h_max
        self.slow = slow_speed
        self.calls = 0
        self.failure = ""

    def onset(self, t, phi):
        """The onset direction (:meth:`_Problem.onset`; raises
        :class:`~slidespin.contact.statics.OnsetNotFound`)."""
        return self.prob.onset(t, phi)[0]

    def slow_start(self, t0, pos, work, u0, t_end, steps):
        """:func:`_quasi_static` from rest in the onset direction u0; rows as
        (t, x, y, φ, vx, vy, k ω, W_f, W_Q). Returns (t, pos, work, s, u, reason, rows,
        steps)."""
        t, p, w, s, u, reason, rec = _quasi_static(
            self.prob, t0, pos, work, t_end, self.rtol, self.slow, u0=u0
        )
        if reason == "failed":
            self.failure = self.prob.failure
        rows = [np.concatenate([[r[0]], r[2:5], r[1] * r[5:8], r[8:10]]) for r in rec]
        return t, p, w, s, u, reason, rows, 0

    def slip(self, u, s, t, pos, work, ln_stop, t_end, steps, from_rest=False):
        """The slip from (u, s) at t to the stop or t_end. Returns (t, pos, work, vel,
        reason, rows, steps)."""
        prob, method = self.prob, self.method
        y0 = np.concatenate([u, [math.log(s), t, pos[0], pos[1], pos[2]], work])
        phase_method = "DOP853" if method == "auto" else method
        if from_rest and method == "auto" and prob.stiffness(y0) > _STIFF:
            phase_method = "Radau"
        rows = []
        used = 0
        while True:
            # Radau while stiff; every time s has grown e^5-fold, look again
            ln_switch = y0[3] + 5.0 if phase_method == "Radau" and method == "auto" else None
            y_end, rec, nst, reason = _slip(
                prob,
                y0,
                ln_stop,
                t_end,
                self.rtol,
                phase_method,
                self.h_max,
                steps - used,
                ln_switch,
            )
            used += nst
            for r in rec:
                sr = math.exp(r[3])
                rows.append(np.concatenate([[r[4]], r[5:8], sr * r[0:3], r[8:10]]))
            if reason != "switch":
                break
            y0 = y_end
            if prob.stiffness(y0) <= _STIFF:
                phase_method = "DOP853"
        if reason == "failed":
            self.failure = prob.failure
        vel = np.zeros(3) if reason == "stop" else math.exp(y_end[3]) * y_end[0:3]
        return float(y_end[4]), y_end[5:8].copy(), y_end[8:10].copy(), vel, reason, rows, used
