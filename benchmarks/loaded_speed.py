"""Loaded runs (MODEL §11): the compiled engine against the Python path, timed.

Times a few loaded runs with ``method="auto"`` (the compiled engine, for loads given as
tables) and ``method="scipy"`` (the Python path: ``scipy.integrate.solve_ivp`` with Python
right-hand sides, the only path before the compiled engine and still the path of loads given
as Python functions), warm (each run once before timing: numba's cache loaded, the first
compile excluded), best of ``--repeat`` runs, and prints the ratios. Where the case has a
closed form, it prints each engine's error against it too.

    .venv/bin/python benchmarks/loaded_speed.py            # best of 5
    .venv/bin/python benchmarks/loaded_speed.py --repeat 1 # quicker

Wall-clock times depend on the machine and its load; the tests assert accuracy, never time.
"""

from __future__ import annotations

import argparse
import math
import time

from numpy.polynomial import Polynomial as Poly

import slidespin as ss
from slidespin.contact.incline import Incline
from slidespin.contact.shapes import Rectangle
from slidespin.motion.loaded import simulate_loaded
from slidespin.motion.loads import Load

G = 9.81
BOX = ss.Body(Rectangle(0.4, 0.3), ss.UniformPressure(), mass=5.0)
ISO = ss.FrictionTensor.isotropic(0.35)
DISK = ss.Body(ss.Circle(0.05), ss.UniformPressure(), 1.0)
TIMES, FORCES = [0.0, 2.0, 3.0, 3.1], [0.0, 25.0, 25.0, 0.0]


def pushed_box_distance():
    """Distance of the pushed box of examples/pushed_box.toml, by hand (polynomials)."""
    m, mu = BOX.mass, 0.35
    mg = mu * m * G
    t0 = 2.0 * mg / 25.0
    v = x = 0.0
    for ta, tb, fa, fb in zip(TIMES[:-1], TIMES[1:], FORCES[:-1], FORCES[1:]):
        if tb <= t0:
            continue
        slope = (fb - fa) / (tb - ta)
        lo = max(ta, t0)
        vel = ((Poly([fa - slope * ta, slope]) - mg) / m).integ(lbnd=lo) + v
        x += vel.integ(lbnd=lo)(tb)
        v = vel(tb)
    return x + 0.5 * v * v / (mu * G)


def slope_distance(alpha, mu, t_end):
    return 0.5 * G * (math.sin(alpha) - mu * math.cos(alpha)) * t_end**2


CASES = [
    (
        "pushed box: stick, slip, stick (examples/pushed_box.toml)",
        lambda m: simulate_loaded(
            BOX,
            ISO,
            ss.State(),
            load=Load.piecewise_linear(TIMES, FORCES, [0.0] * 4),
            t_end=5.0,
            method=m,
        ),
        pushed_box_distance(),
    ),
    (
        "box pushed off G: it turns as it slides",
        lambda m: simulate_loaded(
            BOX,
            ISO,
            ss.State(),
            load=Load.piecewise_linear(
                [0.0, 1.0, 1.5, 1.6], [0.0, 30.0, 30.0, 0.0], [0.0] * 4, at=(0.1, 0.12)
            ),
            t_end=3.0,
            method=m,
        ),
        None,
    ),
    (
        "disk on a slope above the friction angle",
        lambda m: simulate_loaded(
            DISK,
            ss.FrictionTensor(0.3, 0.3),
            ss.State(),
            incline=Incline(math.atan(0.3) + 0.1),
            t_end=1.0,
            method=m,
        ),
        slope_distance(math.atan(0.3) + 0.1, 0.3, 1.0),
    ),
    (
        "disk pushed along a slope",
        lambda m: simulate_loaded(
            DISK,
            ss.FrictionTensor(0.3, 0.3),
            ss.State(),
            load=Load(force=(1.0, 0.5)),
            incline=Incline(0.2, 0.3),
            t_end=1.0,
            method=m,
        ),
        None,
    ),
    (
        "ellipse twisted beyond its friction torque",
        lambda m: simulate_loaded(
            ss.Body(ss.Ellipse(0.06, 0.03), ss.UniformPressure(), 0.5),
            ss.FrictionTensor(0.3, 0.3),
            ss.State(),
            load=Load(torque=0.15),
            t_end=1.0,
            method=m,
        ),
        None,
    ),
    (
        "spinning ellipse on a slope, anisotropic friction",
        lambda m: simulate_loaded(
            ss.Body(ss.Ellipse(0.06, 0.03), ss.LinearPressure(0.005, 0.002), 0.5),
            ss.FrictionTensor(0.25, 0.4, 0.03),
            ss.State(vx=-1.0, vy=0.3, omega=15.0),
            incline=Incline(0.35, downhill=1.0),
            t_end=1.0,
            method=m,
        ),
        None,
    ),
]


def best_of(run, repeat):
    run()  # warm: numba's cache loaded (or compiled), the statics' first calls done
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        tr = run()
        times.append(time.perf_counter() - t0)
    return min(times), tr


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=5, help="timed runs per case (best)")
    args = parser.parse_args(argv)
    print(f"{'case':56s} {'compiled':>10s} {'Python':>10s} {'ratio':>7s}  distance error")
    for name, run, truth in CASES:
        fast, tr_fast = best_of(lambda r=run: r("auto"), args.repeat)
        slow, tr_slow = best_of(lambda r=run: r("scipy"), max(1, args.repeat // 2))
        err = ""
        if truth is not None:
            d_fast = math.hypot(tr_fast.x[-1], tr_fast.y[-1])
            d_slow = math.hypot(tr_slow.x[-1], tr_slow.y[-1])
            err = f"{abs(d_fast / truth - 1):.1e} / {abs(d_slow / truth - 1):.1e}"
        print(f"{name:56s} {fast * 1e3:8.2f} ms {slow * 1e3:8.1f} ms {slow / fast:6.0f}x  {err}")


if __name__ == "__main__":
    main()
