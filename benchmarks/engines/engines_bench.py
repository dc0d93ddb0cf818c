"""slidespin against the engines (MODEL §16): accuracy, wall time, and the coupling's cost.

Runs the issue's five cases in slidespin (the reference), in MuJoCo and Drake with slidespin's
friction coupled, and in the engines with their own friction, both with their defaults (the
case's μ where the engine takes one; MuJoCo condim 3) and with the parameters
``engine_parameters`` fits; prints each one's relative errors in stop time, distance and
rotation and its wall time per simulated second, and the coupling's overhead per MuJoCo step.

    .venv/bin/python benchmarks/engines/engines_bench.py            # all engines installed
    .venv/bin/python benchmarks/engines/engines_bench.py --quick    # no fits, MuJoCo only

Needs the extras (``pip install "slidespin[engines]"``); an engine that is missing is skipped.
Wall-clock times depend on the machine and its load: the overhead is measured against plain
``mj_step`` in the same run, and the tests assert accuracy, never time.
"""

from __future__ import annotations

import argparse
import importlib.util
import math
import time

import numpy as np

import slidespin as ss
from slidespin.engines import _native
from slidespin.engines.scenes import mujoco_xml

G = 9.81
HAVE = {e: importlib.util.find_spec(m) is not None for e, m in
        (("mujoco", "mujoco"), ("drake", "pydrake"), ("pybullet", "pybullet"))}  # fmt: skip

PUCK = ss.Body(ss.Disk(0.05), ss.UniformPressure(), mass=0.17)
BOX = ss.Body(ss.Rectangle(0.2, 0.1), ss.UniformPressure(), mass=1.0)
STONE = ss.Body(ss.Annulus(0.060, 0.066), ss.UniformPressure(), mass=19.0, moment_of_inertia=0.14)
LAUNCHES = {
    "spinning puck": (PUCK, ss.FrictionTensor(0.3, 0.3), ss.State(vx=1.2, omega=25.0)),
    "box launched with spin": (BOX, ss.FrictionTensor(0.35, 0.35), ss.State(vx=0.9, vy=0.4, omega=9.0)),
    "curling-stone ring": (STONE, ss.FrictionTensor(0.012, 0.012), ss.State(vx=1.5, omega=1.5)),
}  # fmt: skip


def _errors(ref, t_stop, x, y, phi):
    dist = math.hypot(ref.x[-1], ref.y[-1])
    return (
        abs(t_stop - ref.t_stop) / ref.t_stop,
        math.hypot(x - ref.x[-1], y - ref.y[-1]) / dist,
        abs(phi - ref.phi[-1]) / max(abs(ref.phi[-1]), 1e-12),
    )


def _row(name, errs, wall_per_s):
    e = " ".join(f"{v:9.2e}" for v in errs)
    print(f"  {name:34s} {e}   {wall_per_s:9.4f}")


# -- coupled MuJoCo ------------------------------------------------------------------------
def mujoco_coupled(body, friction, state, dt, t_max=30.0):
    import mujoco

    import slidespin.mujoco as smj

    m = mujoco.MjModel.from_xml_string(mujoco_xml(body, timestep=dt))
    d = mujoco.MjData(m)
    c = smj.attach(m, d, "body", body, friction)
    for _ in range(int(0.2 / dt)):
        mujoco.mj_step(m, d)
    x0, y0, t0 = d.qpos[0], d.qpos[1], d.time
    yaw = lambda: 2.0 * math.atan2(d.qpos[6], d.qpos[3])  # noqa: E731
    rot, last = 0.0, yaw()
    smj.set_twist(m, d, "body", state.vx, state.vy, state.omega)
    wall = time.perf_counter()
    mujoco.mj_step(m, d)
    while c.friction.state != "stick" and d.time - t0 < t_max:
        mujoco.mj_step(m, d)
        rot += math.remainder(yaw() - last, 2 * math.pi)
        last = yaw()
    wall = time.perf_counter() - wall
    rot += math.remainder(yaw() - last, 2 * math.pi)
    smj.detach(m, d)
    return c.friction.stop_time - t0, d.qpos[0] - x0, d.qpos[1] - y0, rot, wall / (d.time - t0)


# -- coupled Drake -------------------------------------------------------------------------
def drake_coupled(body, friction, state, dt, t_max=30.0):
    from pydrake.systems.analysis import Simulator

    from slidespin.drake import example_diagram, set_planar_state

    ex = example_diagram(body, friction, dt)
    sim = Simulator(ex.diagram)
    pc = ex.plant.GetMyMutableContextFromRoot(sim.get_mutable_context())
    set_planar_state(ex.plant, pc, ex.body, ss.State(), height=ex.thickness / 2)
    sim.Initialize()
    sim.AdvanceTo(0.05)
    z = ex.plant.GetFreeBodyPose(pc, ex.body).translation()[2]
    set_planar_state(ex.plant, pc, ex.body, state, height=z)
    ex.patch.reset()
    t0 = sim.get_context().get_time()
    wall = time.perf_counter()
    rot, last = 0.0, 0.0
    while True:
        sim.AdvanceTo(sim.get_context().get_time() + dt)
        R = ex.plant.GetFreeBodyPose(pc, ex.body).rotation().matrix()
        yaw = math.atan2(R[1, 0], R[0, 0])
        rot += math.remainder(yaw - last, 2 * math.pi)
        last = yaw
        now = sim.get_context().get_time() - t0
        if (ex.patch.coupling.state == "stick" and now > 2 * dt) or now > t_max:
            break
    wall = time.perf_counter() - wall
    p = ex.plant.GetFreeBodyPose(pc, ex.body).translation()
    return ex.patch.stop_time - t0, p[0], p[1], rot, wall / now


# -- the engines' own friction -------------------------------------------------------------
def native(engine, body, params, state, dt, t_max=30.0):
    wall = time.perf_counter()
    (run,) = _native.run_native(engine, body, params, [state], g=G, dt=dt, t_max=t_max)
    wall = time.perf_counter() - wall
    return run.t_stop, run.x, run.y, run.phi, wall / max(run.t_stop, 1e-9)


def defaults(engine, friction):
    mu = 0.5 * (friction.fx + friction.fy)
    if engine == "mujoco":
        return {"friction": (mu, 0.005, 0.0001), "condim": 3, "cone": "elliptic"}
    if engine == "pybullet":
        return {"lateralFriction": mu, "spinningFriction": 0.0, "rollingFriction": 0.0,
                "anisotropicFriction": (1.0, 1.0, 1.0)}  # fmt: skip
    return {"static_friction": mu, "dynamic_friction": mu, "contact_model": "point"}


def launches(quick: bool) -> None:
    print("Launches: relative errors against slidespin.simulate, and wall time [s] per simulated s")
    print(f"  {'':34s} {'t_stop':>9s} {'distance':>9s} {'rotation':>9s}   {'wall/s':>9s}")
    for case, (body, friction, state) in LAUNCHES.items():
        ss.simulate(body, friction, state, g=G)  # warm: the first call loads the core
        wall = time.perf_counter()
        ref = ss.simulate(body, friction, state, g=G)
        wall = time.perf_counter() - wall
        print(f"{case} (slidespin: t_stop {ref.t_stop:.4f} s, {wall / ref.t_stop:.4f} s per s)")
        if HAVE["mujoco"]:
            for dt in (1e-3, 1e-2):
                *r, w = mujoco_coupled(body, friction, state, dt)
                _row(f"MuJoCo + slidespin, {dt * 1e3:g} ms", _errors(ref, *r), w)
        if HAVE["drake"] and not quick:
            *r, w = drake_coupled(body, friction, state, 1e-3)
            _row("Drake + slidespin, 1 ms", _errors(ref, *r), w)
        for engine in ("mujoco", "pybullet", "drake"):
            if not HAVE[engine] or (quick and engine != "mujoco"):
                continue
            *r, w = native(engine, body, defaults(engine, friction), state, 1e-3)
            _row(f"{engine}, own friction, case μ", _errors(ref, *r), w)
            if quick:
                continue
            fitted = ss.engine_parameters(body, friction, engine)
            *r, w = native(engine, body, dict(fitted), state, 1e-3)
            _row(f"{engine}, own friction, fitted", _errors(ref, *r), w)


# -- a ramped push and a slope (MuJoCo) ------------------------------------------------------
def push_and_slope() -> None:
    import mujoco

    import slidespin.mujoco as smj

    body, friction = BOX, ss.FrictionTensor(0.3, 0.3)
    times, force = [0.0, 1.0, 1.4, 2.0], [0.0, 4.0, 4.0, 0.0]
    load = ss.Load.piecewise_linear(times, force, [0.0] * 4)
    ref = ss.simulate(body, friction, ss.State(), load=load, g=G, t_end=3.0)
    print(
        f"\nA box pushed by a ramped force (stick, slip, stick): slidespin slides {ref.x[-1]:.5f} m"
    )
    for label, contact in (("MuJoCo + slidespin", None),
                           ("MuJoCo, own friction (condim 3)", {"friction": (0.3, 0.005, 1e-4), "condim": 3})):  # fmt: skip
        m = mujoco.MjModel.from_xml_string(mujoco_xml(body, contact=contact))
        d = mujoco.MjData(m)
        if contact is None:
            smj.attach(m, d, "body", body, friction)
        for _ in range(200):
            mujoco.mj_step(m, d)
        x0, t0 = d.qpos[0], d.time
        while d.time - t0 < 3.0 - 1e-9:
            d.xfrc_applied[1, 0] = np.interp(d.time - t0 + 5e-4, times, force)
            mujoco.mj_step(m, d)
        err = (d.qpos[0] - x0 - ref.x[-1]) / ref.x[-1]
        print(f"  {label:34s} distance error {err:+.2e}")
        if contact is None:
            smj.detach(m, d)
    alpha = math.atan(0.95 * 0.3)
    print(
        f"\nA box on a slope at 95 % of the friction angle ({math.degrees(alpha):.2f} deg): creep over 10 s"
    )
    for label, contact in (("MuJoCo + slidespin", None),
                           ("MuJoCo, own friction (condim 3)", {"friction": (0.3, 0.005, 1e-4), "condim": 3})):  # fmt: skip
        m = mujoco.MjModel.from_xml_string(mujoco_xml(body, contact=contact, incline=alpha))
        d = mujoco.MjData(m)
        if contact is None:
            smj.attach(m, d, "body", body, friction)
        for _ in range(200):
            mujoco.mj_step(m, d)
        p0 = d.qpos[:3].copy()
        for _ in range(10_000):
            mujoco.mj_step(m, d)
        print(f"  {label:34s} {np.linalg.norm(d.qpos[:3] - p0):.2e} m")
        if contact is None:
            smj.detach(m, d)


# -- the coupling's overhead per step --------------------------------------------------------
PLATE = ss.Body(ss.Ellipse(0.09, 0.05), ss.UniformPressure(), mass=0.6)
OVERHEAD = {  # (body, friction, a long slide: twist vx, vy [m/s], omega [rad/s])
    "box (footprint)": (BOX, ss.FrictionTensor(0.35, 0.35), (30.0, 0.0, 40.0)),
    "puck (disk)": (PUCK, ss.FrictionTensor(0.3, 0.3), (30.0, 0.0, 60.0)),
    "curling stone (ring)": (STONE, ss.FrictionTensor(0.012, 0.012), (3.0, 0.0, 2.0)),
    "plate (ellipse kernel)": (PLATE, ss.FrictionTensor(0.2, 0.3, f=0.05), (30.0, 5.0, 40.0)),
}


def kernel_us(body, friction, n: int = 20000) -> float:
    """One evaluation of the patch's wrench in compiled code [µs] (array loop, no Python)."""
    rng = np.random.default_rng(1)
    vx, vy, om = rng.normal(size=(3, n))
    ss.friction_wrench(body, friction, vx[:10], vy[:10], om[:10])
    t = time.perf_counter()
    ss.friction_wrench(body, friction, vx, vy, om, phi=0.3)
    return (time.perf_counter() - t) / n * 1e6


def overhead(n: int = 5000) -> None:
    """The coupling's cost per body and step against plain ``mj_step`` (the same scene with
    MuJoCo's own friction), split into its fixed part (a body at rest: no wrench evaluation)
    and the wrench evaluations of a slide (counted by the coupling, each timed in compiled
    code); and how many steps the compiled steady step did."""
    import mujoco

    import slidespin.mujoco as smj

    def per_step(body, friction, dt, coupled, twist):
        """µs per step, wrench evaluations and compiled steps per step; ``coupled`` False:
        the same scene, contacts frictionless (condim 1, as coupled) but no callback."""
        m = mujoco.MjModel.from_xml_string(mujoco_xml(body, timestep=dt))
        d = mujoco.MjData(m)
        c = smj.attach(m, d, "body", body, friction)
        saved = mujoco.get_mjcb_passive()
        if not coupled:
            mujoco.set_mjcb_passive(None)
        try:
            for _ in range(int(0.2 / dt)):
                mujoco.mj_step(m, d)
            best, evals, compiled = math.inf, 0.0, 0.0
            for _ in range(3):
                smj.set_twist(m, d, "body", *twist)
                for _ in range(5):
                    mujoco.mj_step(m, d)
                e0, c0 = c.friction.evaluations, c.friction.compiled_steps
                t = time.perf_counter()
                for _ in range(n // 10):
                    mujoco.mj_step(m, d)
                best = min(best, (time.perf_counter() - t) / (n // 10))
                evals = (c.friction.evaluations - e0) / (n // 10)
                compiled = (c.friction.compiled_steps - c0) / (n // 10)
        finally:
            mujoco.set_mjcb_passive(saved)
            smj.detach(m, d)
        return best * 1e6, evals, compiled

    print("\nThe coupling's cost per MuJoCo step and body (best of 3; µs)")
    print(f"  {'':24s} {'dt':>5s} {'plain':>6s} {'at rest':>8s} {'sliding':>8s} "
          f"{'evals':>6s} {'× eval':>7s} {'compiled':>9s}")  # fmt: skip
    for name, (body, friction, twist) in OVERHEAD.items():
        k_us = kernel_us(body, friction)
        for dt in (1e-3, 1e-2):
            plain, _, _ = per_step(body, friction, dt, False, twist)
            rest, _, _ = per_step(body, friction, dt, True, (0.0, 0.0, 0.0))
            slide, evals, compiled = per_step(body, friction, dt, True, twist)
            print(f"  {name:24s} {dt * 1e3:3.0f}ms {plain:6.1f} {rest - plain:8.1f} "
                  f"{slide - plain:8.1f} {evals:6.2f} {k_us:6.2f}µ {compiled:8.0%}")  # fmt: skip
    print(
        "  (plain: mj_step of the same scene, its contacts frictionless as coupled, no "
        "callback; at rest, sliding: the coupling's overhead over plain; evals: wrench "
        "evaluations per sliding step, each costing '× eval' in compiled code; compiled: "
        "the share of sliding steps the compiled steady step did)"
    )


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="no fits; MuJoCo only")
    args = ap.parse_args()
    print("engines installed:", ", ".join(e for e, ok in HAVE.items() if ok) or "none")
    launches(args.quick)
    if HAVE["mujoco"]:
        push_and_slope()
        overhead()


if __name__ == "__main__":
    main()
