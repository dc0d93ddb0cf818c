"""Benchmark of ``slidespin.fit``: three friction parameters (fx, fy, f) fitted to five runs
of 200 tracked instants each (x, y, phi: 3000 values), every run's start state fitted too
(33 parameters in all), noise sigma estimated from the residuals.

Prints the wall time of each repetition; asserts nothing (docs/fit.md quotes one run).
Usage: ``python examples/fit_benchmark.py [REPEATS]``.
"""

from __future__ import annotations

import os
import platform
import statistics
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import fit_synthetic as fs

import slidespin as ss


def main(repeats: int = 3) -> None:
    runs, _ = fs.make_runs()
    body = fs.body()
    guess = ss.FrictionTensor(0.3, 0.3)  # the start guess of examples/fit_case.toml
    t = time.perf_counter()
    ss.simulate(body, guess, ss.State(vx=1.0, omega=3.0))  # compiled kernel (cache or JIT)
    print(f"warm-up (numba cache or compile): {time.perf_counter() - t:.2f} s")
    times = []
    for i in range(repeats):
        t = time.perf_counter()
        res = ss.fit(runs, body, guess)
        times.append(time.perf_counter() - t)
        print(
            f"fit {i + 1}: {times[-1]:.2f} s  ({res.nfev} residual evaluations, "
            f"{len(res.parameter_names)} parameters, {res.n_points} values)"
        )
    print(res)
    print(
        f"median {statistics.median(times):.2f} s, best {min(times):.2f} s over {repeats} "
        f"fits; {platform.processor() or platform.machine()}, {os.cpu_count()} CPUs, "
        f"Python {platform.python_version()}"
    )


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 3)
