"""The MuJoCo coupling's compiled steady step (slidespin.engines._stepcore) against its Python
path, step by step.

The Python path is the one tests/engines/test_mujoco.py validates against slidespin's own
motions (the independent truth); here each scene is run twice, once with the compiled steady
step allowed (``Coupling.compiled``) and once with every step in Python, and the two runs must
be the same run: positions, velocities, wrenches and states at every step, and the stop time.
The compiled step writes ``qfrc_passive`` itself (as ``mj_applyFT`` would, which the Python
path calls), so this also checks its force and moment arms. And the compiled step must do
most steps, with about one wrench evaluation each (counted, not timed).
"""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

mujoco = pytest.importorskip("mujoco")

import slidespin as ss  # noqa: E402
import slidespin.mujoco as smj  # noqa: E402
from slidespin.contact.shapes import Annulus, Disk, Rectangle  # noqa: E402
from slidespin.engines import mujoco as engine_mujoco  # noqa: E402

pytestmark = pytest.mark.xdist_group("mujoco")
G = 9.81

PUCK = ss.Body(Disk(0.05), ss.UniformPressure(), mass=0.17)
BOX = ss.Body(Rectangle(0.2, 0.1), ss.UniformPressure(), mass=1.0)
STONE = ss.Body(Annulus(0.060, 0.066), ss.UniformPressure(), mass=19.0, moment_of_inertia=0.14)
PLATE = ss.Body(ss.Ellipse(0.09, 0.05), ss.UniformPressure(), mass=0.6)  # the elliptic kernel

LAUNCHES = {
    "puck": (PUCK, ss.FrictionTensor(0.3, 0.3), (1.2, 0.0, 25.0)),
    "box": (BOX, ss.FrictionTensor(0.35, 0.35), (0.9, 0.4, 9.0)),
    "stone": (STONE, ss.FrictionTensor(0.012, 0.012), (1.5, 0.0, 1.5)),
    "anisotropic box": (BOX, ss.FrictionTensor(0.25, 0.45, angle=0.3), (0.8, -0.3, 6.0)),
    "body-frame tensor": (BOX, ss.FrictionTensor(0.25, 0.45, frame="body"), (0.8, 0.2, -7.0)),
    "elliptic plate": (PLATE, ss.FrictionTensor(0.2, 0.3, f=0.05), (0.7, 0.3, -8.0)),
    "static above kinetic": (BOX, ss.FrictionTensor(0.3, 0.3, static=1.4), (0.6, 0.0, 5.0)),
}


def _run(body, friction, dt, compiled, scene, steps, *, xml=None, support=None, t0=0.0,
         forward=False):  # fmt: skip
    """Run ``scene(model, data, coupling, i)`` before each of ``steps`` steps (each preceded
    by ``mj_forward`` if ``forward``; the scene ``xml``, default the body's own, from time
    ``t0``); the rows of (x, y, yaw, vx, vy, ω, wrench, N) after each step, the states, the
    stop time and the coupling's counters."""
    m = mujoco.MjModel.from_xml_string(xml or smj.mujoco_xml(body, timestep=dt))
    d = mujoco.MjData(m)
    d.time = t0
    c = smj.attach(m, d, "body", body, friction, support=support)
    c.compiled = compiled
    rows, states = [], []
    try:
        for i in range(steps):
            scene(m, d, c, i)
            if forward:
                mujoco.mj_forward(m, d)
            mujoco.mj_step(m, d)
            yaw = 2.0 * math.atan2(d.qpos[6], d.qpos[3])
            rows.append(np.r_[d.qpos[:2], yaw, d.qvel[:2], d.qvel[5], c.wrench, c.normal_force])
            states.append(c.friction.state)
        f = c.friction
        return np.array(rows), states, f.stop_time, (f.steps, f.compiled_steps, f.evaluations)
    finally:
        smj.detach(m, d)


def _same_run(a, b):
    """The same planar run to round-off, step by step: x, y, yaw, vx, vy, ω and the wrench
    within 1e-9 of their scales (1 m and 1 rad; the largest speed; the normal force), the
    same states. (The two paths apply the same wrench with different round-off: the Python
    path through ``mj_applyFT``. A puck's rocking about horizontal axes, a soft-contact mode
    of 1e-4 rad/s, amplifies that to 1e-8 in its tilt: the tilt is not compared.)"""
    rows_a, states_a, stop_a, _ = a
    rows_b, states_b, stop_b, _ = b
    assert states_a == states_b
    rows_a[:, 2], rows_b[:, 2] = np.unwrap(rows_a[:, 2]), np.unwrap(rows_b[:, 2])
    big = np.abs(rows_b).max(axis=0)
    speed = max(big[3], big[4], big[5], 1e-3)
    scale = np.r_[1.0, 1.0, max(big[2], 1.0), speed, speed, speed, np.full(3, big[9])]
    assert np.all(np.abs(rows_a[:, :9] - rows_b[:, :9]) <= 1e-9 * scale)
    # the engine's normal force feels the rocking: 1e-8
    assert np.all(np.abs(rows_a[:, 9] - rows_b[:, 9]) <= 1e-8 * big[9])
    if math.isnan(stop_b):
        assert math.isnan(stop_a)
    else:
        assert stop_a == pytest.approx(stop_b, rel=1e-10)


def _launch_scene(twist, settle):
    def scene(m, d, c, i):
        if i == settle:
            smj.set_twist(m, d, "body", *twist)

    return scene


@pytest.mark.parametrize("name", list(LAUNCHES))
@pytest.mark.parametrize("dt", [1e-3, 1e-2])
def test_launches_the_same_step_by_step(name, dt):
    body, friction, twist = LAUNCHES[name]
    vx, vy, omega = twist
    tr = ss.simulate(body, friction, ss.State(vx=vx, vy=vy, omega=omega), g=G)
    settle = int(0.2 / dt)
    steps = settle + int((tr.t_stop + 0.2) / dt)
    scene = _launch_scene(twist, settle)
    fast = _run(body, friction, dt, True, scene, steps)
    slow = _run(body, friction, dt, False, scene, steps)
    _same_run(fast, slow)
    assert fast[1][-1] == "stick" and math.isfinite(fast[2])
    steps_done, compiled, _ = fast[3]
    assert slow[3][1] == 0  # the Python path alone
    # in Python: the first steps of the contact, the launch, the stop and the steps after it
    # while the body settles; the rest (sliding, resting) compiled
    assert steps_done - compiled <= 15


def test_a_sliding_step_costs_about_one_wrench_evaluation():
    """At 1 ms the implicit midpoint, started from the extrapolated friction of the last slip
    steps, meets its tolerance with the first evaluation in nearly every step (counted)."""
    body, friction, twist = LAUNCHES["box"]
    dt = 1e-3
    counts = []

    def scene(m, d, c, i):
        if i == 200:
            smj.set_twist(m, d, "body", *twist)
        f = c.friction
        counts.append((f.state, f.compiled_steps, f.evaluations))

    _run(body, friction, dt, True, scene, 700)
    per_step = [
        e1 - e0
        for (s0, c0, e0), (s1, c1, e1) in zip(counts[:-1], counts[1:])
        if s0 == s1 == "slip" and c1 == c0 + 1  # a compiled slip step
    ]
    assert len(per_step) > 300
    assert np.median(per_step) == 1
    assert np.mean(per_step) <= 1.5  # more only where the twist nears its stop


def test_stick_slip_and_pushes_the_same_step_by_step():
    """A ramped push (stick, slip, stick) and a push at 95 % of the threshold: the compiled
    step holds rest by the cheap bound on the static set, the Python path decides the rest."""
    body, friction = BOX, ss.FrictionTensor(0.3, 0.3)
    times, force = [0.0, 1.0, 1.4, 2.0], [0.0, 4.0, 4.0, 0.0]
    dt = 1e-3

    def ramp(m, d, c, i):
        d.xfrc_applied[1, 0] = np.interp(i * dt - 0.2, times, force) if i >= 200 else 0.0
        d.xfrc_applied[1, 5] = 0.05 * d.xfrc_applied[1, 0]  # with a torque

    fast = _run(body, friction, dt, True, ramp, 3400)
    _same_run(fast, _run(body, friction, dt, False, ramp, 3400))
    assert {"stick", "slip"} <= set(fast[1])
    assert fast[3][1] >= 0.9 * fast[3][0]

    def hold(m, d, c, i):
        d.xfrc_applied[1, 0] = 0.95 * 0.3 * body.mass * G if i >= 200 else 0.0

    fast = _run(body, friction, dt, True, hold, 3000)
    _same_run(fast, _run(body, friction, dt, False, hold, 3000))
    assert np.linalg.norm(fast[0][-1, :2] - fast[0][300, :2]) < 1e-6  # no creep
    assert fast[3][1] >= 0.9 * fast[3][0]
    assert fast[3][2] < 20  # at rest: no wrench evaluations


def test_on_a_slope_the_same():
    """Up a slope below the friction angle, then held there: the same run both ways."""
    body, friction = BOX, ss.FrictionTensor(0.4, 0.4)
    xml = smj.mujoco_xml(body, timestep=1e-3, incline=math.atan(0.9 * 0.4))
    scene = _launch_scene((0.3, 0.1, 2.0), 200)
    fast = _run(body, friction, 1e-3, True, scene, 2200, xml=xml)
    _same_run(fast, _run(body, friction, 1e-3, False, scene, 2200, xml=xml))
    assert fast[1][-1] == "stick"
    assert fast[3][1] > 2000  # compiled steps
    assert np.ptp(fast[0][-500:, :2], axis=0).max() < 1e-9  # it stays


def test_several_bodies_each_with_its_compiled_step():
    xml = smj.mujoco_xml(PUCK, name="a")
    xml2 = smj.mujoco_xml(BOX, name="b", position=(1.0, 0.0))
    body_b = xml2[xml2.index('<body name="b"') : xml2.index("</worldbody>")]
    scene = xml.replace("</worldbody>", body_b + "</worldbody>")
    runs = []
    for compiled in (True, False):
        m = mujoco.MjModel.from_xml_string(scene)
        d = mujoco.MjData(m)
        ca = smj.attach(m, d, "a", PUCK, ss.FrictionTensor(0.3, 0.3))
        cb = smj.attach(m, d, "b", BOX, ss.FrictionTensor(0.35, 0.35))
        ca.compiled = cb.compiled = compiled
        try:
            for _ in range(200):
                mujoco.mj_step(m, d)
            smj.set_twist(m, d, "a", 1.0, 0.0, 20.0)
            smj.set_twist(m, d, "b", -0.5, 0.2, 5.0)
            out = []
            for _ in range(800):
                mujoco.mj_step(m, d)
                out.append(d.qpos[[0, 1, 7, 8]].copy())  # the two bodies' x and y
            runs.append((np.array(out), ca.friction.compiled_steps, cb.friction.compiled_steps))
        finally:
            smj.detach(m, d)
    assert np.abs(runs[0][0] - runs[1][0]).max() <= 1e-9
    assert min(runs[0][1:]) > 900


def test_forward_then_step_at_the_same_time_applies_the_same_wrench():
    """mj_forward then mj_step evaluate the passive forces twice at one time: the same
    wrench, whichever path did the first."""
    body, friction, twist = LAUNCHES["box"]
    m = mujoco.MjModel.from_xml_string(smj.mujoco_xml(body))
    d = mujoco.MjData(m)
    c = smj.attach(m, d, "body", body, friction)
    try:
        for _ in range(200):
            mujoco.mj_step(m, d)
        smj.set_twist(m, d, "body", *twist)
        for _ in range(50):
            mujoco.mj_step(m, d)
        before = c.friction.compiled_steps
        mujoco.mj_forward(m, d)
        first, passive = c.wrench, d.qfrc_passive.copy()
        mujoco.mj_step(m, d)
        assert c.wrench == first
        assert c.friction.compiled_steps == before + 1  # the forward was the compiled one
        np.testing.assert_allclose(d.qfrc_passive, passive, rtol=1e-12, atol=1e-12)
    finally:
        smj.detach(m, d)


def test_the_steady_step_comes_from_the_ahead_of_time_core_when_built():
    """A first attach compiles nothing where the install built the core (CI's does)."""
    from slidespin import _aot

    core = _aot.core()
    if core is None:
        pytest.skip(f"no ahead-of-time core in use: {_aot.status()}")
    assert engine_mujoco.steady_kernel(True) is core.steady_footprint
    assert engine_mujoco.steady_kernel(False) is core.steady_ellipse


def test_on_a_table_welded_to_the_world_the_steady_step_is_compiled_too():
    """A support whose body has no joint (a table) is fixed: its plane is kept and the
    compiled step does the steady steps, with the Python path's numbers."""
    body, friction, twist = LAUNCHES["box"]
    top = 0.4
    xml = smj.mujoco_xml(body, timestep=1e-3)
    z = float(re.search(r'<body name="body" pos="0 0 ([^"]+)"', xml).group(1))
    xml = xml.replace(
        '<geom name="floor" type="plane" size="0 0 1" euler="0 0 0" condim="1"/>',
        f'<body name="table" pos="0.3 0 {top / 2}"><geom name="top" type="box" '
        f'size="1 1 {top / 2}"/></body>',
    ).replace(f'<body name="body" pos="0 0 {z!r}"', f'<body name="body" pos="0 0 {top + z!r}"')
    scene = _launch_scene(twist, 200)
    fast = _run(body, friction, 1e-3, True, scene, 800, xml=xml, support="top")
    _same_run(fast, _run(body, friction, 1e-3, False, scene, 800, xml=xml, support="top"))
    assert fast[0][-1, 0] > 0.1  # it slid
    steps, compiled, _ = fast[3]
    assert steps - compiled <= 15


@pytest.mark.parametrize("t0", [0.0, 2e6])
def test_forward_then_step_is_one_step_at_any_time(t0):
    """mj_forward before each mj_step evaluates each time twice: one step each, also late in
    a long simulation (where 1e-9 of the time exceeds the step), the same on both paths."""
    body, friction, twist = LAUNCHES["box"]
    scene = _launch_scene(twist, 200)
    fast = _run(body, friction, 1e-3, True, scene, 600, t0=t0, forward=True)
    slow = _run(body, friction, 1e-3, False, scene, 600, t0=t0, forward=True)
    _same_run(fast, slow)
    assert fast[3][0] == slow[3][0] == 600  # one step per mj_step
