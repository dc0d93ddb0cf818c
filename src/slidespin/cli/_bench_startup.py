"""The first five minutes, measured: what a new user waits for (``slidespin bench``).

Each figure is measured in fresh subprocesses of this interpreter, as a user would meet it:

* ``import_cpu_s``: CPU of ``import slidespin`` (minus a bare interpreter's start);
* ``version_cpu_s``: CPU of ``slidespin --version`` (the whole process);
* ``demo_cold_cpu_s``: CPU of a first ``slidespin demo`` from an empty numba cache (a new
  temporary ``NUMBA_CACHE_DIR``): everything a first run costs, compiling included;
* ``demo_warm_cpu_s`` / ``demo_warm_wall_s``: the same command again, cache warm;
* ``pushed_box_ms``: one loaded trajectory of ``examples/pushed_box.toml`` (a box pushed by a
  ramped force: stick, slip, stick), in process, best of several after a warm-up;
* ``core``: whether the ahead-of-time compiled core is in use (:mod:`slidespin._aot`).

CPU is user + system time of the child processes (``resource.getrusage``), so a busy machine
inflates wall times but not these. Nothing here asserts a time; ``bench`` compares them with
its goals.
"""

from __future__ import annotations

import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

__all__ = ["bench_startup", "PUSHED_BOX"]

#: the pushed box's case (the same numbers as examples/pushed_box.toml)
PUSHED_BOX = """
name = "pushed box"
[patch]
shape = "rectangle"
length = 0.4
width = 0.3
[pressure]
law = "uniform"
[friction]
fx = 0.35
fy = 0.35
[body]
mass = 5.0
[initial]
[load]
times = [0.0, 2.0, 3.0, 3.1]
profile_fx = [0.0, 25.0, 25.0, 0.0]
profile_fy = [0.0, 0.0, 0.0, 0.0]
[solver]
t_end = 5.0
"""


def _child_cpu(argv: list[str], env: dict, cwd: str) -> tuple[float, float]:
    """(CPU seconds, wall seconds) of one child process; raises if it fails."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    done = subprocess.run(argv, env=env, cwd=cwd, capture_output=True, text=True, timeout=900)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if done.returncode != 0:
        raise RuntimeError(f"{' '.join(argv)} failed: {done.stderr.strip()[-400:]}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return cpu, wall


def _best_cpu(argv, env, cwd, repeats: int) -> float:
    return min(_child_cpu(argv, env, cwd)[0] for _ in range(repeats))


def bench_startup(quick: bool = False) -> dict:
    """Measure the first-run figures listed in the module docstring; returns a dict."""
    from slidespin import _aot  # deferred: keeps `bench --help` light
    from slidespin.studies.case import load_case  # deferred: idem

    py = sys.executable
    repeats = 2 if quick else 3
    out: dict = {"core": _aot.status()}
    with tempfile.TemporaryDirectory(prefix="slidespin-startup-") as tmp:
        env = dict(os.environ, MPLBACKEND="Agg", NUMBA_CACHE_DIR=str(Path(tmp) / "numba"))
        env.pop("NUMBA_DISABLE_JIT", None)
        bare = _best_cpu([py, "-c", "pass"], env, tmp, repeats)
        out["import_cpu_s"] = max(
            0.0, _best_cpu([py, "-c", "import slidespin"], env, tmp, repeats) - bare
        )
        cli = [py, "-m", "slidespin.cli.main"]
        out["version_cpu_s"] = _best_cpu([*cli, "--version"], env, tmp, repeats)
        out["help_cpu_s"] = _best_cpu([*cli, "--help"], env, tmp, repeats)
        out["demo_cold_cpu_s"], out["demo_cold_wall_s"] = _child_cpu([*cli, "demo"], env, tmp)
        warm = [_child_cpu([*cli, "demo"], env, tmp) for _ in range(repeats)]
        out["demo_warm_cpu_s"] = min(c for c, _ in warm)
        out["demo_warm_wall_s"] = min(w for _, w in warm)
        case = Path(tmp) / "pushed_box.toml"
        case.write_text(PUSHED_BOX)
        out["pushed_box_ms"] = _pushed_box_ms(load_case(case), 3 if quick else 10)
    return out


def _pushed_box_ms(c, repeats: int) -> float:
    """Best wall time [ms] of one loaded trajectory of the case ``c`` (after a warm-up)."""
    from slidespin.motion.simulate import simulate  # deferred: the numerical stack

    def once():
        return simulate(
            c.body,
            c.friction,
            c.initial_state,
            load=c.load,
            incline=c.incline,
            t_end=c.t_end,
            g=c.g,
            rtol=c.rtol,
        )

    once()  # compile / warm
    best = float("inf")
    for _ in range(repeats):
        t0 = time.perf_counter()
        once()
        best = min(best, time.perf_counter() - t0)
    return best * 1e3
