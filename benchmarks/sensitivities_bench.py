"""Sensitivity runs (MODEL §15) against plain runs, and aiming, timed.

For a few free motions: the plain :func:`slidespin.simulate`, the same with
``sensitivities=`` for 1, 3, 6 and 9 parameters, and the Richardson-extrapolated central
differences of whole simulations that a user would otherwise run (4 simulations per
parameter at rtol 1e-12); warm (each run once before timing), best of ``--repeat``. Prints the
ratios to the plain run, the steps of each, and the time of
:func:`slidespin.aim` for a target made by a known launch.

    .venv/bin/python benchmarks/sensitivities_bench.py            # best of 5
    .venv/bin/python benchmarks/sensitivities_bench.py --repeat 1 # quicker

Wall-clock times depend on the machine and its load; the tests assert accuracy, never time.
"""

from __future__ import annotations

import argparse
import time

import slidespin as ss

SIX = ("fx", "fy", "f", "moment_of_inertia", "vx", "omega")
NINE = ("fx", "fy", "f", "xi_c", "eta_c", "moment_of_inertia", "vx", "vy", "omega")
CASES = {
    "ellipse, linear law, skew tensor": (
        ss.Body(ss.Ellipse(0.1, 0.06), ss.LinearPressure(0.01, 0.005), mass=1.0),
        ss.FrictionTensor(0.3, 0.4, 0.05),
        ss.State(vx=1.0, vy=0.3, omega=5.0),
    ),
    "box (rectangle footprint)": (
        ss.Body(ss.Rectangle(0.4, 0.3), ss.UniformPressure(), mass=5.0),
        ss.FrictionTensor(0.35, 0.35),
        ss.State(vx=1.5, vy=0.3, omega=4.0),
    ),
    "curling stone (ring)": (
        ss.Body(ss.Annulus(0.0595, 0.0655), ss.UniformPressure(), 19.96, 0.2113),
        ss.FrictionTensor(0.0068, 0.0068),
        ss.State(vy=1.93, omega=0.7),
    ),
    # the two dearest cases found: the cheapest plain step (a Hertz wrench), and an ICR that
    # settles a few per cent inside the rim (the derivative's rule one size up)
    "Hertz ellipse, turned tensor": (
        ss.Body(ss.Ellipse(0.08, 0.05), ss.HertzPressure(), mass=2.0),
        ss.FrictionTensor(0.25, 0.4, 0.03, angle=0.3),
        ss.State(vx=0.8, vy=-0.4, omega=-6.0),
    ),
    "paper's ellipse, linear law": (
        ss.Body(ss.Ellipse.from_eccentricity(0.1, 0.866), ss.LinearPressure(0.01, 0.0), 1.0),
        ss.FrictionTensor(0.42, 0.54),
        ss.State.from_speed(1.0, 5.0, 0.785),
    ),
}


def best(fn, repeat):
    fn()
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t)
    return min(times), out


def main(repeat: int) -> None:
    for name, (body, friction, state) in CASES.items():
        print(f"\n{name}")
        t0, tr = best(lambda: ss.simulate(body, friction, state), repeat)
        print(f"  plain run              {t0 * 1e3:9.2f} ms   {tr.n_steps:4d} steps  1.0x")
        for names in (("vx",), ("fx", "fy", "f"), SIX, NINE):
            if isinstance(body.pressure, ss.HertzPressure) and "xi_c" in names:
                names = tuple(n for n in names if n not in ("xi_c", "eta_c"))  # (G fixed)
            t, tr = best(lambda: ss.simulate(body, friction, state, sensitivities=names), repeat)
            n = tr.sensitivities.n_steps
            print(
                f"  sensitivities, {len(names)} par.  {t * 1e3:9.2f} ms   {n:4d} steps "
                f"{t / t0:6.1f}x  ({', '.join(names)})"
            )
        t, _ = best(lambda: [ss.simulate(body, friction, state, rtol=1e-12) for _ in range(24)],
                    1)  # fmt: skip
        print(f"  differences, 6 par.    {t * 1e3:9.2f} ms   (24 runs at rtol 1e-12) "
              f"{t / t0:6.1f}x")  # fmt: skip
        s = tr.stop_state
        start = ss.State(state.x, state.y, state.phi)
        t, got = best(lambda: ss.aim(body, friction, (s.x, s.y, s.phi), start=start), repeat)
        print(f"  aim (x, y, phi)        {t * 1e3:9.2f} ms   launch error "
              f"{abs(got.vx - state.vx) + abs(got.vy - state.vy):.1e} m/s")  # fmt: skip


if __name__ == "__main__":
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--repeat", type=int, default=5)
    main(ap.parse_args().repeat)
