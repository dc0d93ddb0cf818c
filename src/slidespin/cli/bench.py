"""``slidespin bench``: how fast the compiled engine is, against the routes it replaces.

Everything is measured in one run on this machine and printed as a table (or as JSON with
``--json``) and written to ``DIR/bench.json`` (``--out DIR``, default ``./slidespin-out``;
``--no-save`` writes nothing):

* the friction wrench from compiled code, per pressure law, ICR inside and outside the patch
  (the engine's inner call: constants and workspace reused), with its node counts;
* one trajectory to the converged stop (the demo case; and the mean over a batch, one thread);
* footprints (:mod:`slidespin.contact.shapes`): the exact footprint wrench from compiled code on an
  octagon and on a ring, its error against the slow reference (``tests/footprint_reference.py``
  of a source checkout), a trajectory to the converged stop on each, and the batch throughput
  on each as a ratio to the ellipse's measured in the same run;
* trajectories per second on all cores (:func:`slidespin.motion.batch.simulate_many`), and the peak
  memory of a batch (measured in a subprocess);
* the Python-call overhead of :func:`slidespin.motion.simulate` beyond its compiled part;
* the JIT compile time of the first call, cold (empty numba cache, in a subprocess) and with
  the cache;
* the accuracy reached: the wrench against the slow adaptive reference (``tests/reference.py``
  of a source checkout) and the trajectory against a run at rtol = 1e-13;
* the baselines: (a) the naive route, ``scipy.integrate.dblquad`` for Fx, Fy and M at every
  right-hand side driven by ``solve_ivp`` RK45 (rtol 1e-8) with a stop event, time-boxed by
  ``--naive-seconds`` (its per-RHS cost is measured; its full time is that cost times the
  number of right-hand sides the same solver needs on the same problem, counted with the
  compiled wrench); (b) the paper's semi-analytic route in vectorised NumPy
  (:mod:`slidespin.paper.semianalytic`) driven by ``solve_ivp``.

The demo case is the elliptic plate of ``slidespin demo`` (e = 0.866, a = 0.1 m, uniform
pressure, fx = 0.42, fy = 0.54, v₀ = 1 m/s, ω₀ = 5 rad/s, ϑ₀ = π/4). Timings are wall-clock;
no test asserts them. Also runnable as ``python -m slidespin.cli.bench``. This module follows the
plugin contract of :mod:`slidespin.cli.main`: ``configure(parser)`` and ``run(args) -> int``.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import platform
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from slidespin._jit import jit, numba
from slidespin.contact import _engine
from slidespin.contact._kernel_ellipse import WORKSPACE_SHAPE, wrench_constants, wrench_fast

__all__ = ["configure", "run", "main", "GOALS"]

#: the goals of the issue (2-core machine), for the PASS/MISS column
GOALS = {
    "wrench_uniform_linear_us": 2.0,
    "wrench_boussinesq_hertz_us": 5.0,
    "trajectory_ms": 0.5,
    "batch_per_s": 10_000.0,
    "simulate_overhead_us": 50.0,
    "first_call_cold_s": 10.0,
    "first_call_cached_s": 1.5,
    "speedup_semianalytic": 1e3,
    "speedup_naive": 1e5,
    "footprint_wrench_us": 1.0,
    "footprint_trajectory_ms": 0.5,
    "footprint_batch_ratio": 2.0,
}

_LAWS = ("uniform", "linear", "boussinesq", "hertz")


def configure(parser) -> None:
    """Add the arguments of ``slidespin bench`` to an argparse (sub)parser."""
    parser.description = (
        "Benchmark the compiled engine (wrench, trajectory, batch, compile time, accuracy) "
        "against the naive dblquad + solve_ivp route and the paper's semi-analytic NumPy "
        "route, all measured in this run."
    )
    parser.add_argument(
        "--quick",
        action="store_true",
        help="smaller samples and a 10 s naive time box (under a minute)",
    )
    parser.add_argument(
        "--naive-seconds",
        type=float,
        default=None,
        metavar="S",
        help="time box of the naive baseline (default 60, quick 10)",
    )
    parser.add_argument(
        "--batch",
        type=int,
        default=None,
        metavar="N",
        help="trajectories in the throughput batch (default 40000, quick 4000)",
    )
    parser.add_argument(
        "--memory-cases",
        type=int,
        default=None,
        metavar="N",
        help="cases of the peak-memory batch (default 100000, quick 10000; "
        "1000000 for the full-size check)",
    )
    parser.add_argument(
        "--sweep-local",
        type=int,
        default=None,
        metavar="N",
        help="cases of the local sweep (default 1000000, quick 20000)",
    )
    parser.add_argument(
        "--sweep-dask",
        type=int,
        default=None,
        metavar="N",
        help="cases of the sweep through a 2-worker LocalCluster "
        "(default 100000, quick 10000; 0 to skip)",
    )
    parser.add_argument(
        "--no-compile", action="store_true", help="skip the cold/cached compile-time subprocesses"
    )
    parser.add_argument(
        "--json", action="store_true", help="print all figures as JSON instead of the table"
    )
    parser.add_argument(
        "--out",
        metavar="DIR",
        default=None,
        help="directory for bench.json (default ./slidespin-out, created if missing)",
    )
    parser.add_argument("--no-save", action="store_true", help="write no file")


def _defaults(args):
    quick = bool(getattr(args, "quick", False))
    naive = args.naive_seconds if args.naive_seconds is not None else (10.0 if quick else 60.0)
    batch = args.batch if args.batch is not None else (4000 if quick else 40_000)
    mem = args.memory_cases if args.memory_cases is not None else (10_000 if quick else 100_000)
    if not (naive > 0 and math.isfinite(naive)):
        raise ValueError(f"--naive-seconds = {naive!r} is invalid; valid range: > 0")
    for name, val in (("--batch", batch), ("--memory-cases", mem)):
        if val < 10:
            raise ValueError(f"{name} = {val!r} is invalid; valid range: integer >= 10")
    out = None
    if not args.no_save:
        from slidespin.cli.main import DEFAULT_OUT_DIR, check_output_path

        folder = args.out if args.out is not None else DEFAULT_OUT_DIR
        if os.path.exists(folder) and not os.path.isdir(folder):
            raise ValueError(f"--out = {folder!r} is a file; valid values: a directory")
        out = check_output_path(os.path.join(folder, "bench.json"), "--out", create_parent=True)
    elif args.out is not None:
        raise ValueError("--out and --no-save exclude each other; give one")
    return quick, naive, batch, mem, out


def _log(msg):
    print(f"  ... {msg}", file=sys.stderr, flush=True)


# ---------------------------------------------------------------------------------------------
# the demo case and its pieces


def _demo():
    from slidespin.cli.main import demo_case

    case = demo_case()
    return case.body, case.friction, case.initial_state, case.g


def _natural(body, friction, state, g):
    """Parameter vector and regularised initial state of :func:`slidespin.motion.simulate`."""
    from slidespin.motion import _ode

    a = body.patch.a
    par = body.kernel_params(friction)
    v_unit, t_unit = math.sqrt(a * g), math.sqrt(a / g)
    y0 = _ode.initial_state(
        par,
        state.vx / v_unit,
        state.vy / v_unit,
        state.omega * t_unit,
        state.x / a,
        state.y / a,
        state.phi,
    )
    return par, y0


def _best(fn, repeat=5, number=1):
    """Best mean time of ``number`` calls over ``repeat`` rounds [s]."""
    best = math.inf
    for _ in range(repeat):
        t = time.perf_counter()
        for _ in range(number):
            fn()
        best = min(best, (time.perf_counter() - t) / number)
    return best


# ---------------------------------------------------------------------------------------------
# compiled timing loops


@jit(error_model="numpy")
def _wrench_loop(law, bn, xg, yg, t, cx, cy, omega, reps):
    """The engine's inner wrench call (constants and workspace reused) for the ICR at each
    (cx, cy), ``reps`` times over; returns a checksum and the mean node count."""
    tn = math.sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2] + t[3] * t[3])
    kc = wrench_constants(bn, law, xg, yg, tn, 1e-12)
    W = np.empty(WORKSPACE_SHAPE)
    s = 0.0
    nodes = 0
    for r in range(reps):
        for i in range(cx.size):
            vx = (cy[i] - yg) * omega
            vy = -(cx[i] - xg) * omega
            fx, fy, m, st, meth, n = wrench_fast(
                law, kc, t[0], t[1], t[2], t[3], vx, vy, omega, 1e-12, W
            )
            s += fx + fy + m
            nodes += n
    return s, nodes / (reps * cx.size)


def _icr_states(bn, where, n, rng):
    """ICR positions (body frame, units of a) uniformly inside q < 0.9² or in 1.1² < q < 10²."""
    out = []
    while len(out) < n:
        r = math.sqrt(rng.uniform(0, 0.81)) if where == "inside" else rng.uniform(1.1, 10.0)
        t = rng.uniform(0, 2 * math.pi)
        out.append((r * math.cos(t), r * bn * math.sin(t)))
    c = np.array(out)
    return np.ascontiguousarray(c[:, 0]), np.ascontiguousarray(c[:, 1])


def bench_wrench(quick, rng):
    """Time per wrench [µs] for each law, ICR inside and outside (demo patch b/a = 0.5)."""
    bn = math.sqrt(1 - 0.866**2)
    t = np.array([0.42, 0.1, -0.1, 0.54])
    n = 200 if quick else 1000
    res = {}
    for code, law in enumerate(_LAWS):
        xg, yg = (0.1, 0.05 * bn) if law == "linear" else (0.0, 0.0)
        for where in ("inside", "outside"):
            cx, cy = _icr_states(bn, where, n, rng)
            _wrench_loop(code, bn, xg, yg, t, cx, cy, 1.0, 1)
            reps = 5 if quick else 20
            dt = _best(lambda: _wrench_loop(code, bn, xg, yg, t, cx, cy, 1.0, reps), repeat=3)
            _, nodes = _wrench_loop(code, bn, xg, yg, t, cx, cy, 1.0, 1)
            res[f"{law}_{where}"] = {"us": dt / (reps * n) * 1e6, "nodes": float(nodes)}
    return res


def bench_wrench_python(body, friction):
    """Wall time of one friction_wrench() call from Python [µs] (validation included)."""
    import slidespin as ss

    ss.friction_wrench(body, friction, 0.3, 0.1, 4.0)
    return _best(lambda: ss.friction_wrench(body, friction, 0.3, 0.1, 4.0), 5, 200) * 1e6


# ---------------------------------------------------------------------------------------------
# trajectories and batches


def bench_trajectory(quick):
    """Demo trajectory: compiled integration (no records) per trajectory, the Python call
    ``simulate`` and its overhead beyond its compiled part, at rtol 1e-10 and 1e-8."""
    import slidespin as ss
    from slidespin.contact._kernel_ellipse import wrench_array
    from slidespin.motion import _ode

    body, fr, st, g = _demo()
    par, y0 = _natural(body, fr, st, g)
    out = {}
    number = 20 if quick else 100
    for rtol in (1e-10, 1e-8):

        def compiled(record=False):
            return _ode.integrate(
                par, y0, rtol, rtol, rtol, min(rtol, 1e-8), 200_000, np.inf, record
            )

        r = compiled()
        t_int = _best(compiled, 5, number)
        # what simulate() runs compiled: integration with records + wrench on the records
        r2 = compiled(True)
        rows = np.vstack([r2[6][:, 1:], r2[0][None, :]])
        k = par[_engine.P_K]

        def post():
            return wrench_array(
                par[0],
                int(par[1]),
                par[2],
                par[3],
                par[4],
                par[5],
                par[6],
                par[7],
                par[8] != 0.0,
                rows[:, 7].copy(),
                rows[:, 0].copy(),
                rows[:, 1].copy(),
                rows[:, 2] / k,
                1e-12,
            )

        t_rec = _best(lambda: compiled(True), 5, number)
        t_post = _best(post, 5, number)
        ss.simulate(body, fr, st, g=g, rtol=rtol)
        t_sim = _best(lambda: ss.simulate(body, fr, st, g=g, rtol=rtol), 5, number)
        out[f"rtol={rtol:g}"] = {
            "integrate_ms": t_int * 1e3,
            "steps": int(r[2]),
            "rhs": int(r[3]),
            "us_per_rhs": t_int / r[3] * 1e6,
            "simulate_ms": t_sim * 1e3,
            "simulate_compiled_ms": (t_rec + t_post) * 1e3,
            "simulate_overhead_us": max(t_sim - t_rec - t_post, 0.0) * 1e6,
            "t_stop_s": float(r[0][4] * math.sqrt(body.patch.a / g)),
        }
    return out


def _batch_states(n, rng):
    """Random starts of the demo body: |v| ≤ 1.4 m/s in any direction, |ω| ≤ 20 rad/s, φ₀."""
    s = np.zeros((n, 6))
    s[:, 2] = rng.uniform(0, 2 * math.pi, n)
    s[:, 3] = rng.uniform(-1, 1, n)
    s[:, 4] = rng.uniform(-1, 1, n)
    s[:, 5] = rng.uniform(-20, 20, n)
    return s


def bench_batch(s):
    """Trajectories per second of simulate_many from the starts ``s``, on all cores and on
    one."""
    from slidespin.motion.batch import simulate_many

    n = len(s)
    body, fr, _, g = _demo()
    simulate_many(body, fr, s[:8], g=g)
    threads = numba.get_num_threads()
    t = time.perf_counter()
    res = simulate_many(body, fr, s, g=g)
    t_all = time.perf_counter() - t
    one = s[: max(10, n // 4)]
    numba.set_num_threads(1)
    try:
        t = time.perf_counter()
        simulate_many(body, fr, one, g=g)
        t_one = (time.perf_counter() - t) / len(one)
    finally:
        numba.set_num_threads(threads)
    counts = {name: int((res.ending == name).sum()) for name in set(res.ending)}
    return {
        "cases": n,
        "threads": threads,
        "per_s": n / t_all,
        "per_s_one_thread": 1.0 / t_one,
        "ms_per_trajectory_one_thread": t_one * 1e3,
        "mean_steps": float(res.n_steps.mean()),
        "endings": counts,
        "all_stopped": bool(np.all(res.status == "stopped")),
    }


# ---------------------------------------------------------------------------------------------
# footprints

#: the benchmark's footprints [m]: an irregular convex octagon (8 vertices, radii 0.08-0.1 m)
#: and a ring (a curling stone's running band, scaled: 0.05-0.065 m)
_OCTAGON = tuple(
    (r * math.cos(t), r * math.sin(t))
    for r, t in zip(
        (0.100, 0.090, 0.095, 0.080, 0.100, 0.085, 0.092, 0.088),
        (0.0, 0.8, 1.55, 2.4, 3.2, 3.9, 4.75, 5.5),
    )
)
_RING = (0.05, 0.065)


def _footprints():
    """{name: (footprint, Body)} of the footprint rows (uniform pressure, 1 kg)."""
    import slidespin as ss
    from slidespin.contact.shapes import Annulus, Polygon

    out = {}
    for name, fp in (("octagon", Polygon(_OCTAGON)), ("ring", Annulus(*_RING))):
        out[name] = (fp, ss.Body(fp, ss.UniformPressure(), mass=1.0))
    return out


def _footprint_icr(where, n, rng):
    """Body-frame velocities of G (ω = 1) for ICRs uniform in the disk of radius 1 about G
    ("near") or in the annulus 1.1-10 ("far"), natural units (lengths in the extent)."""
    r = np.sqrt(rng.uniform(0.0, 1.0, n)) if where == "near" else rng.uniform(1.1, 10.0, n)
    t = rng.uniform(0.0, 2.0 * math.pi, n)
    cx, cy = r * np.cos(t), r * np.sin(t)  # ICR relative to G
    return np.ascontiguousarray(cy), np.ascontiguousarray(-cx), np.ones(n)


def _footprint_accuracy(fp, body, fr, n, rng):
    """Largest error of the compiled footprint wrench (public footprint_wrench) against the
    slow independent reference, in units of the load and load x extent, over n motion states
    (ICR near, on the outline's scale and far; None if the reference is not available)."""
    from slidespin.contact.footprint_wrench import footprint_wrench

    ref = _reference_module("footprint_reference.py")
    if ref is None:
        return None
    ext = body.length_unit
    xg, yg = body.mass_centre
    worst = 0.0
    for i in range(n):
        r = (0.3, 0.9, 2.0, 40.0)[i % 4] * ext * math.sqrt(rng.uniform(0.05, 1.0))
        t = rng.uniform(0.0, 2.0 * math.pi)
        om, phi = rng.choice([-1.0, 1.0]) * rng.uniform(0.5, 3.0), rng.uniform(-3.0, 3.0)
        cbx, cby = xg + r * math.cos(t), yg + r * math.sin(t)
        vbx, vby = (cby - yg) * om, -(cbx - xg) * om
        c, sn = math.cos(phi), math.sin(phi)
        vx, vy = c * vbx - sn * vby, sn * vbx + c * vby
        w = footprint_wrench(fp, body.pressure, fr, vx, vy, om, phi)
        want = ref.reference_wrench(
            fp, ("uniform",), fr.matrix, vx, vy, om, phi=phi, frame=fr.frame
        )
        worst = max(
            worst, abs(w.force_x - want[0]), abs(w.force_y - want[1]), abs(w.moment - want[2]) / ext
        )
    return worst


def bench_footprint(quick, rng, states):
    """The footprint rows: the compiled exact wrench per call (ICR near and far), its error
    against the slow reference, a trajectory to the converged stop (rtol 1e-10, the demo's
    friction and start), and simulate_many throughput from ``states`` (the ellipse batch's
    starts) as a ratio to the demo ellipse's on the same starts, timed alternately, for an
    octagon and a ring."""
    from slidespin.contact._kernel_footprint import time_wrenches
    from slidespin.motion import _ode
    from slidespin.motion.batch import simulate_many

    demo_body, fr, st, g = _demo()
    n = 200 if quick else 1000
    reps = 5 if quick else 20
    out = {}
    for name, (fp, body) in _footprints().items():
        d: dict = {"vertices": len(getattr(fp, "vertices", ())), "extent_m": body.length_unit}
        par, fe, fc, geo = body.engine_params(fr)
        t = par[_engine.P_T00], par[_engine.P_T01], par[_engine.P_T10], par[_engine.P_T11]
        for where in ("near", "far"):
            vx, vy, om = (np.tile(x, reps) for x in _footprint_icr(where, n, rng))
            time_wrenches(fe, fc, geo, *t, vx[:2], vy[:2], om[:2])
            dt = _best(lambda: time_wrenches(fe, fc, geo, *t, vx, vy, om), repeat=3)
            d[f"wrench_us_icr_{where}"] = dt / vx.size * 1e6
        err = _footprint_accuracy(fp, body, fr, 8 if quick else 24, rng)
        if err is not None:
            d["wrench_max_abs_error"] = err
            d["wrench_error_states"] = 8 if quick else 24
        # trajectory: the compiled integrator's footprint specialisation, no records
        a = body.length_unit
        v_unit, t_unit = math.sqrt(a * g), math.sqrt(a / g)
        y0 = _ode.initial_state(
            par, st.vx / v_unit, st.vy / v_unit, st.omega * t_unit, st.x / a, st.y / a, st.phi
        )
        fpa = _engine.footprint_argument(par, fe, fc, geo)

        def traj():
            return _ode.integrate_fp(
                par, fpa, y0, 1e-10, 1e-10, 1e-10, 1e-10, 200_000, np.inf, False
            )

        r = traj()
        d["trajectory_ms"] = _best(traj, 5, 20 if quick else 100) * 1e3
        d["trajectory_steps"] = int(r[2])
        d["trajectory_rhs"] = int(r[3])
        d["status"] = int(r[1])
        # batch: the same starts as the ellipse's batch, all threads; the ellipse's batch is
        # timed again alternately with this one (best of 3 each), so that the ratio compares
        # the two under the same load of a shared machine
        simulate_many(body, fr, states[:8], g=g)
        t_fp, t_el = math.inf, math.inf
        for _ in range(3):
            t0 = time.perf_counter()
            res = simulate_many(body, fr, states, g=g)
            t_fp = min(t_fp, time.perf_counter() - t0)
            t0 = time.perf_counter()
            simulate_many(demo_body, fr, states, g=g)
            t_el = min(t_el, time.perf_counter() - t0)
        d["batch_per_s"] = len(states) / t_fp
        d["batch_mean_steps"] = float(res.n_steps.mean())
        d["ellipse_batch_per_s"] = len(states) / t_el
        d["ellipse_over_footprint"] = t_fp / t_el
        out[name] = d
    return out


_MEMORY_SCRIPT = r"""
import json, sys, time
import numpy as np
from slidespin.motion.batch import simulate_many
from slidespin.cli.main import demo_case
n = int(sys.argv[1])
case = demo_case()
rng = np.random.default_rng(2)
s = np.zeros((n, 6)); s[:, 3] = rng.uniform(-1, 1, n); s[:, 4] = rng.uniform(-1, 1, n)
s[:, 5] = rng.uniform(-20, 20, n)
simulate_many(case.body, case.friction, s[:8], g=case.g)
print("READY", flush=True)
sys.stdin.readline()
t = time.perf_counter()
res = simulate_many(case.body, case.friction, s, g=case.g)
dt = time.perf_counter() - t
print(json.dumps({"cases": n, "seconds": dt, "input_mb": s.nbytes / 2**20,
                  "result_mb": sum(a.nbytes for a in vars(res).values()) / 2**20}), flush=True)
"""


def _rss_mb(pid):
    try:
        with open(f"/proc/{pid}/statm", encoding="ascii") as fh:
            return int(fh.read().split()[1]) * os.sysconf("SC_PAGE_SIZE") / 2**20
    except (OSError, ValueError, IndexError):
        return math.nan


def bench_memory(n):
    """Resident memory of one simulate_many batch of n cases: a fresh process is warmed up
    (compiled code loaded), then its RSS is sampled every millisecond from outside while the
    batch runs; the growth over the warmed-up RSS is what the batch holds at its peak."""
    p = subprocess.Popen(
        [sys.executable, "-c", _MEMORY_SCRIPT, str(n)],
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        line = p.stdout.readline()
        if not line.startswith("READY"):
            p.kill()
            return {"error": (p.stderr.read().strip().splitlines() or ["failed"])[-1]}
        base = _rss_mb(p.pid)
        if not math.isfinite(base):
            p.kill()
            return {"error": "no /proc: resident memory not measurable here"}
        p.stdin.write("go\n")
        p.stdin.flush()
        peak = base
        while p.poll() is None:
            peak = max(peak, _rss_mb(p.pid) if p.poll() is None else peak)
            time.sleep(0.001)
        out, err = p.communicate(timeout=60)
    finally:
        if p.poll() is None:  # pragma: no cover
            p.kill()
    if p.returncode != 0:
        return {"error": (err.strip().splitlines() or ["failed"])[-1]}
    d = json.loads(out.strip().splitlines()[-1])
    d.update(
        baseline_mb=base,
        peak_mb=peak,
        growth_mb=peak - base,
        bytes_per_case=(peak - base) * 2**20 / n,
    )
    return d


# ---------------------------------------------------------------------------------------------
# compile time


_COMPILE_SCRIPT = r"""
import json, math, time
t0 = time.perf_counter()
import numpy as np
import slidespin as ss
from slidespin.motion.batch import simulate_many
from slidespin.cli.main import demo_case
t_import = time.perf_counter() - t0
case = demo_case()
out = {"import_s": t_import}
t = time.perf_counter()
ss.simulate(case.body, case.friction, case.initial_state, g=case.g)
out["simulate_s"] = time.perf_counter() - t
t = time.perf_counter()
simulate_many(case.body, case.friction, np.array([[0, 0, 0, 0.5, 0.2, 3.0]]), g=case.g)
out["simulate_many_s"] = time.perf_counter() - t
t = time.perf_counter()
ss.friction_wrench(case.body, case.friction, 0.3, 0.1, 4.0)
out["friction_wrench_s"] = time.perf_counter() - t
from slidespin.contact.shapes import Rectangle
t = time.perf_counter()
ss.simulate(ss.Body(Rectangle(0.3, 0.1), ss.UniformPressure(), mass=1.0), case.friction,
            case.initial_state, g=case.g)
out["footprint_simulate_s"] = time.perf_counter() - t
print(json.dumps(out))
"""


def bench_compile():
    """First calls in a fresh process: cold (empty numba cache) and again with the cache."""
    out = {}
    with tempfile.TemporaryDirectory(prefix="slidespin-bench-cache-") as cache:
        env = dict(os.environ, NUMBA_CACHE_DIR=cache)
        env.pop("NUMBA_DISABLE_JIT", None)
        for label in ("cold", "cached"):
            _log(f"compile time, {label} cache (subprocess)")
            r = subprocess.run(
                [sys.executable, "-c", _COMPILE_SCRIPT],
                capture_output=True,
                text=True,
                env=env,
                timeout=1800,
            )
            if r.returncode != 0:
                out[label] = {"error": r.stderr.strip().splitlines()[-1] if r.stderr else "?"}
                continue
            out[label] = json.loads(r.stdout.strip().splitlines()[-1])
    return out


# ---------------------------------------------------------------------------------------------
# accuracy


def _reference_module(name="reference.py"):
    """``tests/<name>`` of a source checkout as a module, or None (an installed package)."""
    path = Path(__file__).resolve().parents[2] / "tests" / name
    if not path.is_file():
        return None
    import importlib.util

    spec = importlib.util.spec_from_file_location("_slidespin_" + path.stem, path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def bench_accuracy(quick):
    """Wrench vs the slow reference (if this is a source checkout); trajectory vs rtol 1e-13."""
    import warnings

    import slidespin as ss
    from slidespin.contact.pressure import pressure_law_from_name

    out = {}
    ref = _reference_module()
    if ref is None:
        out["wrench"] = {"note": "tests/reference.py not found (installed package)"}
    else:
        rng = np.random.default_rng(11)
        worst = 0.0
        count = 0
        kinds = ("inside", "near rim", "on rim", "outside", "far")
        for law in _LAWS:
            for bn in (0.5, 1.0) if quick else (0.5, 1.0, 0.1, 2.0):
                a, b = 1.0, bn
                pl = (
                    ss.LinearPressure(0.1, -0.05 * b)
                    if law == "linear"
                    else (pressure_law_from_name(law))
                )
                body = ss.Body(ss.Ellipse(a, b), pl, mass=1.0)
                fr = ss.FrictionTensor(0.42, 0.61, f=0.13, angle=0.3)
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
                    w = ss.friction_wrench(body, fr, vx, vy, om, phi, g=1.0)
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
    runs = {rt: ss.simulate(body, fr, st, g=g, rtol=rt) for rt in (1e-10, 1e-8, 1e-13)}
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
    from scipy.integrate import dblquad

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
    from scipy.integrate import solve_ivp

    import slidespin as ss

    body, fr, st, g = _demo()
    opts = dict(method="RK45", rtol=1e-8, atol=1e-10)
    # how many right-hand sides the same solver needs: run it with the compiled wrench
    fast = lambda vx, vy, om, phi: (lambda w: (w.force_x, w.force_y, w.moment))(  # noqa: E731
        ss.friction_wrench(body, fr, vx, vy, om, phi, g=g)
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


# ---------------------------------------------------------------------------------------------
# report


def _machine():
    cpu = platform.processor() or "?"
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as fh:
            for line in fh:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    import scipy

    return {
        "cpu": cpu,
        "logical_cpus": os.cpu_count(),
        "numba_threads": numba.get_num_threads(),
        "threading_layer": numba.config.THREADING_LAYER,
        "python": platform.python_version(),
        "numpy": np.__version__,
        "scipy": scipy.__version__,
        "numba": numba.__version__,
        "platform": platform.platform(),
    }


def _verdict(value, goal, smaller_is_better=True):
    if value is None or not math.isfinite(value):
        return "n/a"
    ok = value <= goal if smaller_is_better else value >= goal
    return "PASS" if ok else "MISS"


def _rows(r):
    """(quantity, value, goal, verdict) rows of the table."""
    rows = []
    w = r["wrench_us"]
    for law in _LAWS:
        goal = GOALS[
            "wrench_uniform_linear_us"
            if law in ("uniform", "linear")
            else "wrench_boussinesq_hertz_us"
        ]
        for where in ("inside", "outside"):
            d = w[f"{law}_{where}"]
            rows.append(
                (
                    f"wrench, {law}, ICR {where} ({d['nodes']:.0f} nodes)",
                    f"{d['us']:.2f} µs",
                    f"≤ {goal:g} µs",
                    _verdict(d["us"], goal),
                )
            )
    rows.append(
        (
            "wrench, one friction_wrench() call from Python",
            f"{r['wrench_python_us']:.1f} µs",
            "",
            "",
        )
    )
    tj = r["trajectory"]["rtol=1e-10"]
    rows.append(
        (
            f"trajectory to the converged stop, demo, rtol 1e-10 ({tj['steps']} steps, "
            f"{tj['rhs']} RHS)",
            f"{tj['integrate_ms']:.3f} ms",
            f"≤ {GOALS['trajectory_ms']:g} ms",
            _verdict(tj["integrate_ms"], GOALS["trajectory_ms"]),
        )
    )
    t8 = r["trajectory"]["rtol=1e-08"]
    rows.append(
        (
            f"trajectory, demo, rtol 1e-8 ({t8['steps']} steps, {t8['rhs']} RHS)",
            f"{t8['integrate_ms']:.3f} ms",
            "",
            "",
        )
    )
    b = r["batch"]
    rows.append(
        (
            f"trajectory, batch mean, one thread ({b['mean_steps']:.0f} steps)",
            f"{b['ms_per_trajectory_one_thread']:.3f} ms",
            "",
            "",
        )
    )
    rows.append(
        (
            f"batch, {b['threads']} threads ({b['cases']} cases)",
            f"{b['per_s']:,.0f} /s",
            f"≥ {GOALS['batch_per_s']:,.0f} /s",
            _verdict(b["per_s"], GOALS["batch_per_s"], False),
        )
    )
    for name, d in r.get("footprint", {}).items():
        shape = f"{name} ({d['vertices']} vertices)" if d["vertices"] else name
        goal = GOALS["footprint_wrench_us"]
        for where, label in (("near", "ICR within 1 extent"), ("far", "ICR 1.1-10 extents")):
            us = d[f"wrench_us_icr_{where}"]
            rows.append(
                (
                    f"footprint wrench, {shape}, {label}",
                    f"{us * 1e3:.0f} ns",
                    f"≤ {goal * 1e3:g} ns",
                    _verdict(us, goal),
                )
            )
        if "wrench_max_abs_error" in d:
            rows.append(
                (
                    f"footprint wrench, {name}: error vs slow reference "
                    f"({d['wrench_error_states']} states)",
                    f"{d['wrench_max_abs_error']:.1e}",
                    "≤ 1e-10",
                    _verdict(d["wrench_max_abs_error"], 1e-10),
                )
            )
        goal = GOALS["footprint_trajectory_ms"]
        rows.append(
            (
                f"footprint trajectory to the converged stop, {name}, rtol 1e-10 "
                f"({d['trajectory_steps']} steps, {d['trajectory_rhs']} RHS)",
                f"{d['trajectory_ms']:.3f} ms",
                f"≤ {goal:g} ms",
                _verdict(d["trajectory_ms"], goal),
            )
        )
        goal = GOALS["footprint_batch_ratio"]
        rows.append(
            (
                f"footprint batch, {name}: ellipse / footprint throughput "
                f"({d['batch_per_s']:,.0f} /s vs {d['ellipse_batch_per_s']:,.0f} /s)",
                f"{d['ellipse_over_footprint']:.2f} x",
                f"≤ {goal:g} x",
                _verdict(d["ellipse_over_footprint"], goal),
            )
        )
    mem = r.get("memory", {})
    if "bytes_per_case" in mem:
        rows.append(
            (
                f"batch memory: peak growth, {mem['cases']:,} cases (inputs "
                f"{mem['input_mb']:.1f} MB, results {mem['result_mb']:.1f} MB)",
                f"{mem['growth_mb']:.1f} MB = {mem['bytes_per_case']:.0f} B/case",
                "",
                "",
            )
        )
    rows.append(
        (
            "simulate(): Python overhead beyond its compiled part",
            f"{tj['simulate_overhead_us']:.0f} µs",
            f"≤ {GOALS['simulate_overhead_us']:g} µs",
            _verdict(tj["simulate_overhead_us"], GOALS["simulate_overhead_us"]),
        )
    )
    rows.append(("simulate(): whole call, demo", f"{tj['simulate_ms']:.3f} ms", "", ""))
    comp = r.get("compile", {})
    for label, goal in (
        ("cold", GOALS["first_call_cold_s"]),
        ("cached", GOALS["first_call_cached_s"]),
    ):
        d = comp.get(label)
        if d and "simulate_s" in d:
            first = d["import_s"] + d["simulate_s"]
            rows.append(
                (
                    f"first simulate() incl. import, {label} numba cache",
                    f"{first:.2f} s",
                    f"≤ {goal:g} s",
                    _verdict(first, goal),
                )
            )
            rows.append(
                (f"  then first simulate_many(), {label}", f"{d['simulate_many_s']:.2f} s", "", "")
            )
            if "footprint_simulate_s" in d:
                rows.append(
                    (
                        f"  then first simulate() of a footprint (Rectangle), {label}",
                        f"{d['footprint_simulate_s']:.2f} s",
                        "",
                        "",
                    )
                )
    acc = r["accuracy"]
    if "max_abs_error" in acc.get("wrench", {}):
        rows.append(
            (
                f"accuracy: wrench vs slow reference ({acc['wrench']['states']} states)",
                f"{acc['wrench']['max_abs_error']:.1e}",
                "≤ 1e-10",
                _verdict(acc["wrench"]["max_abs_error"], 1e-10),
            )
        )
    a10 = acc["trajectory_rtol=1e-10"]
    rows.append(
        (
            "accuracy: demo at rtol 1e-10 vs 1e-13: t_stop, beta*, theta*",
            f"{a10['t_stop_rel']:.0e}, {a10['beta_stop_rel']:.0e}, {a10['theta_stop_abs']:.0e}",
            "1e-8, 1e-6, 1e-6",
            "",
        )
    )
    nv = r["naive"]
    rows.append(
        (
            f"naive: dblquad+RK45, per RHS ({nv['rhs_done']} RHS in {nv['elapsed_s']:.0f} s)",
            f"{nv['s_per_rhs']:.3f} s",
            "",
            "",
        )
    )
    label = (
        "measured"
        if nv["finished"]
        else (
            f"estimated: {nv['rhs_needed']} RHS; reached {100 * nv['fraction_of_t_stop']:.0f}% "
            "of t_stop"
        )
    )
    rows.append((f"naive: one trajectory ({label})", f"{nv['full_time_s']:.0f} s", "", ""))
    ours = tj["integrate_ms"] * 1e-3
    sp_naive = nv["full_time_s"] / ours
    rows.append(
        (
            "speed-up vs naive, per trajectory",
            f"{sp_naive:.1e} x",
            f"≥ {GOALS['speedup_naive']:.0e} x",
            _verdict(sp_naive, GOALS["speedup_naive"], False),
        )
    )
    rows.append(
        (
            "speed-up vs naive, per RHS (wrench + step)",
            f"{nv['s_per_rhs'] / (tj['us_per_rhs'] * 1e-6):.1e} x",
            "",
            "",
        )
    )
    sa = r["semianalytic"]
    if "error" not in sa:
        for key, d in sa.items():
            rows.append(
                (
                    f"semi-analytic NumPy + solve_ivp, {key} ({d['rhs']} RHS)",
                    f"{d['s_per_trajectory'] * 1e3:.0f} ms",
                    "",
                    "",
                )
            )
        d = sa["defaults (DOP853, rtol 1e-8, stop 1e-6)"]
        sp = d["s_per_trajectory"] / ours
        rows.append(
            (
                "speed-up vs semi-analytic, per trajectory (ours at rtol 1e-10)",
                f"{sp:,.0f} x",
                f"≥ {GOALS['speedup_semianalytic']:,.0f} x",
                _verdict(sp, GOALS["speedup_semianalytic"], False),
            )
        )
        sp8 = d["s_per_trajectory"] / (t8["integrate_ms"] * 1e-3)
        rows.append(
            (
                "speed-up vs semi-analytic, per trajectory (both at rtol 1e-8)",
                f"{sp8:,.0f} x",
                "",
                _verdict(sp8, GOALS["speedup_semianalytic"], False),
            )
        )
        rows.append(
            (
                "speed-up vs semi-analytic, per RHS",
                f"{d['s_per_rhs'] / (tj['us_per_rhs'] * 1e-6):,.0f} x",
                "",
                "",
            )
        )
    sw = r.get("sweep", {})
    if "local_cases_per_s" in sw:
        rows.append(
            (
                f"sweep, all local cores, {sw['local_cases']:,} cases to Parquet",
                f"{sw['local_cases_per_s']:,.0f} /s",
                "≥ 10,000 /s",
                _verdict(sw["local_cases_per_s"], 10_000, False),
            )
        )
    if "dask_cases_per_s" in sw:
        rows.append(
            (
                f"sweep, 2-worker Dask LocalCluster, {sw['dask_cases']:,} cases",
                f"{sw['dask_cases_per_s']:,.0f} /s",
                "",
                "",
            )
        )
    if "dask_over_local_per_core" in sw:
        rows.append(
            (
                "sweep, Dask per core / local per core",
                f"{sw['dask_over_local_per_core']:.2f}",
                "≥ 0.8",
                _verdict(sw["dask_over_local_per_core"], 0.8, False),
            )
        )
    if "error" in sw:
        rows.append(("sweep", sw["error"], "", ""))
    return rows


def format_table(r) -> str:
    rows = _rows(r)
    w0 = max(len(x[0]) for x in rows)
    w1 = max(len(x[1]) for x in rows)
    w2 = max(len(x[2]) for x in rows)
    head = f"| {'quantity':{w0}} | {'measured':>{w1}} | {'goal':{w2}} | verdict |"
    sep = f"|{'-' * (w0 + 2)}|{'-' * (w1 + 2)}|{'-' * (w2 + 2)}|---------|"
    lines = [head, sep]
    for q, m, g, v in rows:
        lines.append(f"| {q:{w0}} | {m:>{w1}} | {g:{w2}} | {v:7} |")
    return "\n".join(lines)


def run(args) -> int:
    """Run the benchmarks; print the table; write JSON. Returns the exit status."""
    quick, naive_s, n_batch, n_mem, out_path = _defaults(args)
    rng = np.random.default_rng(20261122)
    r = {"machine": _machine(), "quick": quick}
    t0 = time.perf_counter()
    if not args.no_compile:
        r["compile"] = bench_compile()
    _log("warming up (numba cache or compile)")
    import slidespin as ss
    from slidespin.motion.batch import simulate_many

    body, fr, st, g = _demo()
    t = time.perf_counter()
    ss.simulate(body, fr, st, g=g)
    simulate_many(body, fr, np.array([[0, 0, 0, 0.5, 0.2, 3.0]]), g=g)
    ss.friction_wrench(body, fr, 0.3, 0.1, 4.0)
    _wrench_loop(0, 0.5, 0.0, 0.0, np.array([0.4, 0.0, 0.0, 0.5]), np.zeros(1), np.zeros(1), 1.0, 1)
    r["warmup_s"] = time.perf_counter() - t
    _log("wrench")
    r["wrench_us"] = bench_wrench(quick, rng)
    r["wrench_python_us"] = bench_wrench_python(body, fr)
    _log("trajectory")
    r["trajectory"] = bench_trajectory(quick)
    _log(f"batch of {n_batch} trajectories")
    states = _batch_states(n_batch, rng)
    r["batch"] = bench_batch(states)
    _log("footprints: octagon and ring (wrench, reference, trajectory, batch)")
    r["footprint"] = bench_footprint(quick, rng, states)
    _log(f"peak memory of a batch of {n_mem} (subprocess)")
    r["memory"] = bench_memory(n_mem)
    _log("accuracy")
    r["accuracy"] = bench_accuracy(quick)
    _log("semi-analytic NumPy baseline")
    r["semianalytic"] = bench_semianalytic(quick)
    _log(f"naive dblquad baseline (time box {naive_s:g} s)")
    r["naive"] = bench_naive(naive_s)
    n_sl = (
        args.sweep_local
        if getattr(args, "sweep_local", None) is not None
        else (20_000 if quick else 1_000_000)
    )
    n_sd = (
        args.sweep_dask
        if getattr(args, "sweep_dask", None) is not None
        else (10_000 if quick else 100_000)
    )
    for name, val in (("--sweep-local", n_sl), ("--sweep-dask", n_sd)):
        if val < 0:
            raise ValueError(f"{name} = {val!r} is invalid; valid range: integer >= 0")
    if n_sl or n_sd:
        _log(f"sweeps: {n_sl} cases locally, {n_sd} through a 2-worker LocalCluster")
        from slidespin.studies.sweep import SweepError
        from slidespin.studies.sweep import benchmark as sweep_benchmark

        try:
            r["sweep"] = sweep_benchmark(
                n_local=n_sl,
                n_dask=n_sd,
                workers=2,
                chunk_size=10_000 if n_sl >= 100_000 else 2_000,
            )
        except SweepError as exc:  # e.g. Dask not installed
            r["sweep"] = {"error": str(exc)}
    r["goals"] = GOALS
    r["bench_seconds"] = time.perf_counter() - t0
    table = format_table(r)
    m = r["machine"]
    head = (
        f"slidespin bench on {m['cpu']} ({m['logical_cpus']} logical CPUs, "
        f"{m['numba_threads']} numba threads, {m['threading_layer']} layer), Python "
        f"{m['python']}, numba {m['numba']}, NumPy {m['numpy']}, SciPy {m['scipy']}"
        f"{' [quick]' if quick else ''}; {r['bench_seconds']:.0f} s"
    )
    r["table"] = table
    text = json.dumps(r, indent=2, default=float)
    if out_path:
        from slidespin._io import write_outputs

        write_outputs([(out_path, (text + "\n").encode("utf-8"))])
    if args.json:
        print(text)
    else:
        print(head)
        print(table)
        if out_path:
            print(f"JSON: {out_path}")
    return 0


def main(argv=None) -> int:
    """``python -m slidespin.cli.bench``: the same as ``slidespin bench``."""
    parser = argparse.ArgumentParser(prog="python -m slidespin.cli.bench")
    configure(parser)
    args = parser.parse_args(argv)
    try:
        return run(args)
    except ValueError as exc:
        print(f"slidespin bench: error: {exc}", file=sys.stderr)
        return 2


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
