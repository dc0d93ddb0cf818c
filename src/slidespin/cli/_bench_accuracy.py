"""What ``slidespin bench`` measures the engine against (:mod:`slidespin.cli.bench`).

* accuracy: the wrench against the slow adaptive reference (``tests/references/reference.py`` of a source
  checkout) and the demo trajectory against a run at rtol = 1e-13;
* the baselines: (a) the naive route, ``scipy.integrate.dblquad`` for Fx, Fy and M at every
  right-hand side driven by ``solve_ivp`` RK45 with a stop event, time-boxed; (b) the paper's
  semi-analytic route in vectorised NumPy (:mod:`slidespin.paper.semianalytic`, eq. 8-9)
  driven by ``solve_ivp``.
"""

from __future__ import annotations

import importlib.util
import math
import time
import warnings
from pathlib import Path

import numpy as np

from slidespin.cli._bench_cases import _LAWS, _best, _demo
from slidespin.contact.body import Body
from slidespin.contact.ellipse import Ellipse
from slidespin.contact.friction import FrictionTensor
from slidespin.contact.pressure import LinearPressure, pressure_law_from_name
from slidespin.contact.wrench import friction_wrench

# ---------------------------------------------------------------------------------------------
# accuracy


def _reference_module(name="reference.py"):
    """``tests/references/<name>`` of a source checkout as a module, or None (an installed package)."""
    path = Path(__file__).resolve().parents[3] / "tests" / "references" / name
    if not path.is_file():
        return None
    spec = importlib.util.spec_from_file_location("_slidespin_" + path.stem, path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def bench_accuracy(quick):
    """Wrench vs the slow reference (if this is a source checkout); trajectory vs rtol 1e-13."""
    # deferred: keeps `slidespin --help` fast (the numerical stack is not imported for parsing)
    from slidespin.motion.simulate import simulate

    out = {}
    ref = _reference_module()
    if ref is None:
        out["wrench"] = {"note": "tests/references/reference.py not found (installed package)"}
    else:
        rng = np.random.default_rng(11)
        worst = 0.0
        count = 0
        kinds = ("inside", "near rim", "on rim", "outside", "far")
        for law in _LAWS:
            for bn in (0.5, 1.0) if quick else (0.5, 1.0, 0.1, 2.0):
                a, b = 1.0, bn
                pl = (
                    LinearPressure(0.1, -0.05 * b)
                    if law == "linear"
                    else (pressure_law_from_name(law))
                )
                body = Body(Ellipse(a, b), pl, mass=1.0)
                fr = FrictionTensor(0.42, 0.61, f=0.13, angle=0.3)
                xg, yg = body.mass_centre
                for kind in kinds:
                    r = {
                        "inside": 0.6,
                        "near rim": 1 - 1e-6,
                        "on rim": 1.0,
                        "outside": 2.5,
                        "far": 300.0,
                    }[kind]
                    t = rng.uniform(0, 2 * math.pi)
                    cx, cy = r * a * math.cos(t), r * b * math.sin(t)
                    om, phi = 1.3, 0.4
                    vbx, vby = (cy - yg) * om, -(cx - xg) * om
                    c, s = math.cos(phi), math.sin(phi)
                    vx, vy = c * vbx - s * vby, s * vbx + c * vby
                    w = friction_wrench(body, fr, vx, vy, om, phi, g=1.0)
                    with warnings.catch_warnings():
                        warnings.simplefilter("ignore")
                        want = ref.reference_wrench(
                            a,
                            b,
                            law,
                            fr.world_matrix(phi),
                            phi,
                            vx,
                            vy,
                            om,
                            xi_c=xg,
                            eta_c=yg,
                            P=1.0,
                        )
                    err = max(
                        abs(w.force_x - want[0]), abs(w.force_y - want[1]), abs(w.moment - want[2])
                    )
                    worst = max(worst, err)
                    count += 1
        out["wrench"] = {"max_abs_error": worst, "states": count, "contract": 1e-10}
    body, fr, st, g = _demo()
    runs = {rt: simulate(body, fr, st, g=g, rtol=rt) for rt in (1e-10, 1e-8, 1e-13)}
    ref13 = runs[1e-13]
    for rt in (1e-10, 1e-8):
        tr = runs[rt]
        out[f"trajectory_rtol={rt:g}"] = {
            "t_stop_rel": abs(tr.t_stop - ref13.t_stop) / ref13.t_stop,
            "beta_stop_rel": abs(tr.beta_stop - ref13.beta_stop) / abs(ref13.beta_stop),
            "theta_stop_abs": abs(tr.theta_stop - ref13.theta_stop),
            "distance_rel": abs(tr.distance - ref13.distance) / ref13.distance,
        }
    out["reference_run"] = {
        "t_stop": ref13.t_stop,
        "beta_stop": ref13.beta_stop,
        "theta_stop": ref13.theta_stop,
    }
    return out


# ---------------------------------------------------------------------------------------------
# baselines


class _TimeUp(Exception):
    pass


def _naive_wrench(body, friction, vx, vy, omega, phi, g):
    """Force and moment by ``scipy.integrate.dblquad`` over the patch, one call per
    component, default tolerances: what a script built from the paper's formulas does."""
    from scipy.integrate import dblquad  # lazy: SciPy is needed by this baseline only

    a, b = body.patch.a, body.patch.b
    xg, yg = body.mass_centre
    p0 = body.mass * g / (math.pi * a * b)
    law = body.pressure.name
    T = friction.world_matrix(phi)
    c, s = math.cos(phi), math.sin(phi)

    def pressure(xi, eta):
        q = xi * xi / (a * a) + eta * eta / (b * b)
        if law == "uniform":
            return p0
        if law == "linear":
            return p0 * (1 + 4 * xg * xi / a**2 + 4 * yg * eta / b**2)
        if law == "boussinesq":
            return 0.5 * p0 / math.sqrt(max(1 - q, 1e-300))
        return 1.5 * p0 * math.sqrt(max(1 - q, 0.0))

    def traction(eta, xi):
        dx, dy = xi - xg, eta - yg
        x, y = c * dx - s * dy, s * dx + c * dy
        wx, wy = vx - omega * y, vy + omega * x
        nw = math.hypot(wx, wy)
        if nw == 0.0:
            return 0.0, 0.0, x, y
        p = pressure(xi, eta)
        tx = -p * (T[0, 0] * wx + T[0, 1] * wy) / nw
        ty = -p * (T[1, 0] * wx + T[1, 1] * wy) / nw
        return tx, ty, x, y

    lo = lambda xi: -b * math.sqrt(max(1 - xi * xi / (a * a), 0.0))  # noqa: E731
    hi = lambda xi: b * math.sqrt(max(1 - xi * xi / (a * a), 0.0))  # noqa: E731
    fx = dblquad(lambda eta, xi: traction(eta, xi)[0], -a, a, lo, hi)[0]
    fy = dblquad(lambda eta, xi: traction(eta, xi)[1], -a, a, lo, hi)[0]
    m = dblquad(
        lambda eta, xi: (lambda r: r[2] * r[1] - r[3] * r[0])(traction(eta, xi)), -a, a, lo, hi
    )[0]
    return fx, fy, m


def _naive_problem(body, friction, st, g, wrench):
    """solve_ivp pieces of the naive route in physical time with a stop event."""
    m, inertia = body.mass, body.moment_of_inertia
    k2 = inertia / m
    s0 = math.sqrt(st.vx**2 + st.vy**2 + k2 * st.omega**2)

    def rhs(t, y):
        fx, fy, mm = wrench(y[3], y[4], y[5], y[2])
        return [y[3], y[4], y[5], fx / m, fy / m, mm / inertia]

    def stop(t, y):
        return math.sqrt(y[3] ** 2 + y[4] ** 2 + k2 * y[5] ** 2) - 1e-6 * s0

    stop.terminal = True
    stop.direction = -1
    y0 = [st.x, st.y, st.phi, st.vx, st.vy, st.omega]
    return rhs, stop, y0


def bench_naive(seconds):
    """The naive route, time-boxed: per-RHS cost, progress, and the estimated full time."""
    from scipy.integrate import solve_ivp  # lazy: SciPy is needed by the baselines only

    body, fr, st, g = _demo()
    opts = dict(method="RK45", rtol=1e-8, atol=1e-10)
    # how many right-hand sides the same solver needs: run it with the compiled wrench
    fast = lambda vx, vy, om, phi: (lambda w: (w.force_x, w.force_y, w.moment))(  # noqa: E731
        friction_wrench(body, fr, vx, vy, om, phi, g=g)
    )
    rhs, stop, y0 = _naive_problem(body, fr, st, g, fast)
    sol = solve_ivp(rhs, (0.0, 100.0), y0, events=stop, **opts)
    needed = int(sol.nfev)
    t_stop_fast = float(sol.t[-1])
    # the naive route itself, until the stop or the time box
    calls = [0]
    t_start = time.perf_counter()

    def slow(vx, vy, om, phi):
        if time.perf_counter() - t_start > seconds:
            raise _TimeUp
        calls[0] += 1
        return _naive_wrench(body, fr, vx, vy, om, phi, g)

    rhs, stop, y0 = _naive_problem(body, fr, st, g, slow)
    progress = {"t": 0.0}

    def rhs_tracked(t, y):
        progress["t"] = max(progress["t"], t)
        return rhs(t, y)

    finished = False
    try:
        sol = solve_ivp(rhs_tracked, (0.0, 100.0), y0, events=stop, **opts)
        finished = sol.status == 1
    except _TimeUp:
        pass
    elapsed = time.perf_counter() - t_start
    per_rhs = elapsed / max(calls[0], 1)
    return {
        "method": "dblquad (Fx, Fy, M) per RHS + solve_ivp RK45, rtol 1e-8, stop at s = 1e-6 s0",
        "time_box_s": seconds,
        "finished": finished,
        "rhs_done": calls[0],
        "elapsed_s": elapsed,
        "s_per_rhs": per_rhs,
        "t_reached_s": progress["t"],
        "fraction_of_t_stop": progress["t"] / t_stop_fast,
        "rhs_needed": needed,
        "full_time_s": elapsed if finished else per_rhs * needed,
        "full_time_is_estimate": not finished,
    }


def bench_semianalytic(quick):
    """The paper's semi-analytic route (vectorised NumPy, eq. 8-9) driven by solve_ivp."""
    # deferred: keeps `slidespin --help` fast (the numerical stack is not imported for parsing)
    try:
        from slidespin.paper import semianalytic as sa
    except ImportError:  # pragma: no cover - the module ships with slidespin
        return {"error": "slidespin.paper.semianalytic is not available"}
    body, fr, st, g = _demo()
    a = body.patch.a
    model = sa.PaperModel(
        body.patch.b / a,
        fr.fx,
        fr.fy,
        fr.f,
        inertia_ratio=body.moment_of_inertia / (body.mass * a * a),
    )
    v_unit = math.sqrt(a * g / math.pi)
    w_unit = math.sqrt(g / (a * math.pi))
    speed = math.hypot(st.vx, st.vy)
    kw = dict(
        v0=speed / v_unit, omega0=st.omega / w_unit, theta0=math.atan2(st.vy, st.vx), phi0=st.phi
    )
    out = {}
    for label, opts in (
        ("defaults (DOP853, rtol 1e-8, stop 1e-6)", {}),
        ("RK45, rtol 1e-8, stop 1e-8", dict(method="RK45", stop=1e-8)),
    ):
        run = sa.integrate(model, **kw, **opts)
        t = _best(lambda: sa.integrate(model, **kw, **opts), 2 if quick else 3)
        y = [0.0, 0.0, st.phi, 1.0, 0.5, 1.0]
        per_rhs = _best(lambda: sa.rhs(0.0, y, model), 3, 50)
        out[label] = {
            "s_per_trajectory": t,
            "rhs": run.nfev,
            "s_per_rhs": per_rhs,
            "t_stop_s": run.t_stop * math.sqrt(a * math.pi / g),
            "beta_stop_m": run.beta_stop * a,
            "status": run.status,
        }
    return out
