"""Benchmark of ``slidespin.fit``: three friction parameters (fx, fy, f) fitted to five runs
of 200 tracked instants each (x, y, phi: 3000 values), every run's start state fitted too
(33 parameters in all), noise sigma estimated from the residuals; with the Jacobian by
central differences (the default) and exact (the motion's sensitivities, MODEL §15).

Prints the wall time of each repetition and the speed-up of the exact Jacobian; asserts
nothing (docs/fit.md quotes one run).
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
    best, results = {}, {}
    for mode in ("differences", "exact"):
        times = []
        for i in range(repeats):
            t = time.perf_counter()
            res = ss.fit(runs, body, guess, jacobian=mode)
            times.append(time.perf_counter() - t)
            print(
                f"fit {i + 1}, jacobian={mode}: {times[-1]:.2f} s  ({res.nfev} residual "
                f"evaluations, {len(res.parameter_names)} parameters, {res.n_points} values)"
            )
        print(res)
        print(
            f"jacobian={mode}: median {statistics.median(times):.2f} s, best {min(times):.2f} s "
            f"over {repeats} fits"
        )
        best[mode], results[mode] = min(times), res
    est = {m: [r.estimates[p] for p in ("fx", "fy", "f")] for m, r in results.items()}
    diff = max(abs(a - b) for a, b in zip(est["exact"], est["differences"]))
    err = max(results["exact"].std_errors[p] for p in ("fx", "fy", "f"))
    print(
        f"speed-up of the exact Jacobian: {best['differences'] / best['exact']:.1f}x; the "
        f"estimates differ by {diff:.1e} at most ({diff / err:.1e} of a standard error); "
        f"{platform.processor() or platform.machine()}, {os.cpu_count()} CPUs, Python "
        f"{platform.python_version()}"
    )


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 3)
