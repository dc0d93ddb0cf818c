"""The measurements of ``slidespin bench`` on the ellipse engine (:mod:`slidespin.cli.bench`).

The demo case and its pieces, the compiled timing loop of the engine's inner wrench call
(:mod:`slidespin.contact._kernel_ellipse`, MODEL §3), one trajectory to the converged stop
(:mod:`slidespin.motion._integrator`), batch throughput (:func:`slidespin.motion.batch.simulate_many`),
the peak memory of a batch and the JIT compile time (each in a subprocess), and the machine.
Timings are wall-clock; no test asserts them.
"""

from __future__ import annotations

import json
import math
import os
import platform
import subprocess
import sys
import tempfile
import time

import numpy as np

from slidespin._jit import jit, numba
from slidespin.cli.main import demo_case
from slidespin.contact import _engine
from slidespin.contact._kernel_ellipse import (
    WORKSPACE_SHAPE,
    wrench_array,
    wrench_constants,
    wrench_fast,
)
from slidespin.contact.wrench import friction_wrench

_LAWS = ("uniform", "linear", "boussinesq", "hertz")


#: the progress bar of the running ``slidespin bench`` (set by :func:`slidespin.cli.bench.run`;
#: ``None`` outside it): stages advance it, details name what runs now. It is drawn only on a
#: terminal and never with ``--quiet``, so nothing else of the bench is written to stderr.
PROGRESS = None
_started = [False]


def _stage(msg):
    """A new stage of the bench starts: the bar counts the previous one done and shows ``msg``."""
    bar = PROGRESS
    if bar is None:
        return
    if _started[0]:
        bar.update(1)
    _started[0] = True
    bar.set_description(f"bench: {msg}")


def _log(msg):
    """What runs now, within a stage (shown beside the bar)."""
    if PROGRESS is not None:
        PROGRESS.set_postfix_str(msg)


# ---------------------------------------------------------------------------------------------
# the demo case and its pieces


def _demo():
    case = demo_case()
    return case.body, case.friction, case.initial_state, case.g


def _natural(body, friction, state, g):
    """Parameter vector and regularised initial state of :func:`slidespin.simulate`."""
    # deferred: keeps `slidespin --help` fast (the numerical stack is not imported for parsing)
    from slidespin.motion import _flow

    a = body.patch.a
    par = body.kernel_params(friction)
    v_unit, t_unit = math.sqrt(a * g), math.sqrt(a / g)
    y0 = _flow.initial_state(
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
    friction_wrench(body, friction, 0.3, 0.1, 4.0)
    return _best(lambda: friction_wrench(body, friction, 0.3, 0.1, 4.0), 5, 200) * 1e6


# ---------------------------------------------------------------------------------------------
# trajectories and batches


def bench_trajectory(quick):
    """Demo trajectory: compiled integration (no records) per trajectory, the Python call
    ``simulate`` and its overhead beyond its compiled part, at rtol 1e-10 and 1e-8."""
    # deferred: keeps `slidespin --help` fast (the numerical stack is not imported for parsing)
    from slidespin.motion import _integrator
    from slidespin.motion.simulate import simulate

    body, fr, st, g = _demo()
    par, y0 = _natural(body, fr, st, g)
    out = {}
    number = 20 if quick else 100
    for rtol in (1e-10, 1e-8):

        def compiled(record=False):
            return _integrator.integrate(
                par, y0, rtol, rtol, rtol, min(rtol, 1e-8), 200_000, np.inf, record, False
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
        simulate(body, fr, st, g=g, rtol=rtol)
        t_sim = _best(lambda: simulate(body, fr, st, g=g, rtol=rtol), 5, number)
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
    # deferred: keeps `slidespin --help` fast (the numerical stack is not imported for parsing)
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
# the machine


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
    import scipy  # lazy: only its version is reported, and only when the bench runs

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
