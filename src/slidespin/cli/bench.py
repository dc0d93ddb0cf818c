"""``slidespin bench``: how fast the compiled engine is, against the routes it replaces.

Everything is measured in one run on this machine and printed as a table (or as JSON with
``--json``) and written to ``DIR/bench.json`` (``--out DIR``, default ``./slidespin-out``;
``--no-save`` writes nothing):

* the friction wrench from compiled code, per pressure law, ICR inside and outside the patch
  (the engine's inner call: constants and workspace reused), with its node counts;
* one trajectory to the converged stop (the demo case; and the mean over a batch, one thread);
* footprints (:mod:`slidespin.contact.shapes`): the exact footprint wrench from compiled code on an
  octagon and on a ring, its error against the slow reference (``tests/references/footprint_reference.py``
  of a source checkout), a trajectory to the converged stop on each, and the batch throughput
  on each as a ratio to the ellipse's measured in the same run;
* trajectories per second on all cores (:func:`slidespin.motion.batch.simulate_many`), and the peak
  memory of a batch (measured in a subprocess);
* the Python-call overhead of :func:`slidespin.simulate` beyond its compiled part;
* the JIT compile time of the first call, cold (empty numba cache, in a subprocess) and with
  the cache; and what a new user waits for (:mod:`slidespin.cli._bench_startup`): the CPU of a
  first ``slidespin demo`` from an empty numba cache, a second one's wall time,
  ``--version``, ``--help``, ``import slidespin``, and one loaded trajectory (the pushed box);
* the accuracy reached: the wrench against the slow adaptive reference (``tests/references/reference.py``
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

This module holds the command, the goals and the table; the measurements live in
:mod:`slidespin.cli._bench_cases` (ellipse engine, batch, memory, compile time),
:mod:`slidespin.cli._bench_footprint` (footprints) and :mod:`slidespin.cli._bench_accuracy`
(accuracy and the two baselines).
"""

from __future__ import annotations

import argparse
import json
import math
import os
import sys
import time

from slidespin._io import check_output_path, write_outputs
from slidespin.cli.main import DEFAULT_OUT_DIR

# nothing heavy at the top: the parser is built from this module (`slidespin --help`); the
# measurements (NumPy, numba, SciPy) are imported by run()

__all__ = ["configure", "run", "main", "GOALS"]

#: the pressure laws of the wrench rows (those of :mod:`slidespin.cli._bench_cases`)
_LAWS = ("uniform", "linear", "boussinesq", "hertz")

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
    # the first five minutes (slidespin.cli._bench_startup): CPU of whole processes
    "demo_cold_cpu_s": 10.0,
    "demo_warm_wall_s": 1.5,
    "version_cpu_s": 0.5,
    "help_cpu_s": 0.5,
    "import_cpu_s": 0.7,
    "pushed_box_ms": 5.0,
}


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
        help="smaller samples and a 10 s naive time box (about 2 min on 2 shared cores)",
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
    parser.add_argument(
        "--quiet",
        action="store_true",
        help="no progress bar (the bar is drawn only when stderr is a terminal)",
    )


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
        folder = args.out if args.out is not None else DEFAULT_OUT_DIR
        if os.path.exists(folder) and not os.path.isdir(folder):
            raise ValueError(f"--out = {folder!r} is a file; valid values: a directory")
        out = check_output_path(os.path.join(folder, "bench.json"), "--out", create_parent=True)
    elif args.out is not None:
        raise ValueError(
            f"--out = {args.out!r} and --no-save exclude each other; valid: one of them"
        )
    return quick, naive, batch, mem, out


# ---------------------------------------------------------------------------------------------
# report


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
    first = r.get("first_run")
    if first:
        for key, label, unit in (
            ("demo_cold_cpu_s", "first `slidespin demo`, empty numba cache (CPU)", "s"),
            ("demo_warm_wall_s", "`slidespin demo` again (wall)", "s"),
            ("version_cpu_s", "`slidespin --version` (CPU)", "s"),
            ("help_cpu_s", "`slidespin --help` (CPU)", "s"),
            ("import_cpu_s", "`import slidespin` (CPU)", "s"),
            ("pushed_box_ms", "loaded trajectory: the pushed box (stick, slip, stick)", "ms"),
        ):
            value, goal = first[key], GOALS[key]
            rows.append((label, f"{value:.2f} {unit}", f"≤ {goal:g} {unit}", _verdict(value, goal)))
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


#: the stages of a run, one step of the progress bar each
_STAGES = 12


def run(args) -> int:
    """Run the benchmarks; print the table; write JSON. Returns the exit status."""
    quick, naive_s, n_batch, n_mem, out_path = _defaults(args)
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
    # deferred: keeps `slidespin --help` fast (the numerical stack is not imported for parsing)
    from slidespin._progress import progress_bar
    from slidespin.cli import _bench_cases

    quiet = getattr(args, "quiet", False)
    with progress_bar(_STAGES, "bench", unit="stage", enabled=False if quiet else None) as bar:
        _bench_cases.PROGRESS, _bench_cases._started[0] = bar, False
        try:
            report = _run(args, quick, naive_s, n_batch, n_mem, out_path, n_sl, n_sd)
            bar.update(bar.total - bar.n)  # the last stage, the report, is done too
        finally:
            _bench_cases.PROGRESS = None
    # printed once the bar is gone (it shares the terminal)
    print(report)
    return 0


def _run(args, quick, naive_s, n_batch, n_mem, out_path, n_sl, n_sd) -> str:
    """Measure everything, write ``bench.json``; return the text to print."""
    # deferred: keeps `slidespin --help` fast (the numerical stack is not imported for parsing)
    import numpy as np

    from slidespin.cli._bench_accuracy import bench_accuracy, bench_naive, bench_semianalytic
    from slidespin.cli._bench_cases import (
        _batch_states,
        _demo,
        _machine,
        _stage,
        _wrench_loop,
        bench_batch,
        bench_compile,
        bench_memory,
        bench_trajectory,
        bench_wrench,
        bench_wrench_python,
    )
    from slidespin.cli._bench_footprint import bench_footprint
    from slidespin.cli._bench_startup import bench_startup
    from slidespin.contact.wrench import friction_wrench
    from slidespin.motion.batch import simulate_many
    from slidespin.motion.simulate import simulate

    rng = np.random.default_rng(20261122)
    r = {"machine": _machine(), "quick": quick}
    t0 = time.perf_counter()
    _stage("compile time and the first run (subprocesses)")
    if not args.no_compile:
        r["compile"] = bench_compile()
        r["first_run"] = bench_startup(quick)
    _stage("warming up (numba cache or compile)")

    body, fr, st, g = _demo()
    t = time.perf_counter()
    simulate(body, fr, st, g=g)
    simulate_many(body, fr, np.array([[0, 0, 0, 0.5, 0.2, 3.0]]), g=g)
    friction_wrench(body, fr, 0.3, 0.1, 4.0)
    _wrench_loop(0, 0.5, 0.0, 0.0, np.array([0.4, 0.0, 0.0, 0.5]), np.zeros(1), np.zeros(1), 1.0, 1)
    r["warmup_s"] = time.perf_counter() - t
    _stage("wrench")
    r["wrench_us"] = bench_wrench(quick, rng)
    r["wrench_python_us"] = bench_wrench_python(body, fr)
    _stage("trajectory")
    r["trajectory"] = bench_trajectory(quick)
    _stage(f"batch of {n_batch} trajectories")
    states = _batch_states(n_batch, rng)
    r["batch"] = bench_batch(states)
    _stage("footprints: octagon and ring (wrench, reference, trajectory, batch)")
    r["footprint"] = bench_footprint(quick, rng, states)
    _stage(f"peak memory of a batch of {n_mem} (subprocess)")
    r["memory"] = bench_memory(n_mem)
    _stage("accuracy")
    r["accuracy"] = bench_accuracy(quick)
    _stage("semi-analytic NumPy baseline")
    r["semianalytic"] = bench_semianalytic(quick)
    _stage(f"naive dblquad baseline (time box {naive_s:g} s)")
    r["naive"] = bench_naive(naive_s)
    _stage(f"sweeps: {n_sl} cases locally, {n_sd} through a 2-worker LocalCluster")
    if n_sl or n_sd:
        from slidespin.studies.sweep import benchmark as sweep_benchmark
        from slidespin.studies.sweep_spec import SweepError

        try:
            r["sweep"] = sweep_benchmark(
                n_local=n_sl,
                n_dask=n_sd,
                workers=2,
                chunk_size=10_000 if n_sl >= 100_000 else 2_000,
            )
        except SweepError as exc:  # e.g. Dask not installed
            r["sweep"] = {"error": str(exc)}
    _stage("report")
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
        write_outputs([(out_path, (text + "\n").encode("utf-8"))])
    if args.json:
        return text
    return "\n".join([head, table] + ([f"JSON: {out_path}"] if out_path else []))


def main(argv=None) -> int:
    """``python -m slidespin.cli.bench``: the same as ``slidespin bench``."""
    parser = argparse.ArgumentParser(prog="python -m slidespin.cli.bench")
    configure(parser)
    args = parser.parse_args(argv)
    try:
        return run(args)
    except ValueError as exc:
        print(f"slidespin: error: bench: {exc}", file=sys.stderr)
        return 2


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
