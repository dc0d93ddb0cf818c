"""The MuJoCo coupling (MODEL §16) against slidespin's own motions (independent truth for the
coupling: the exact integrator of :func:`slidespin.simulate`, not the coupling's step).

The five cases of the issue: a spinning puck, a box launched with spin, a curling-stone ring,
a box under a ramped push (stick, slip, stick), a box on a slope below the friction angle;
at 1 ms (0.5 %) and 10 ms (2 %). And: a push at 95 % of the threshold moves < 1e-6 m in
10 s; static above kinetic; anisotropic tensors; detach restores the model; bad input.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

mujoco = pytest.importorskip("mujoco")

import slidespin as ss  # noqa: E402
import slidespin.mujoco as smj  # noqa: E402
from slidespin.contact.shapes import Annulus, Disk, Rectangle  # noqa: E402

pytestmark = pytest.mark.xdist_group("mujoco")
G = 9.81


def _scene(body, dt=1e-3, incline=0.0):
    model = mujoco.MjModel.from_xml_string(smj.mujoco_xml(body, timestep=dt, incline=incline))
    return model, mujoco.MjData(model)


def _yaw(d):
    q = d.qpos[3:7]
    return 2.0 * math.atan2(q[3], q[0])


def _launch(body, friction, state, dt, t_max=5.0):
    """Coupled run of a launch: (stop time, dx, dy, rotation) relative to the launch."""
    m, d = _scene(body, dt)
    c = smj.attach(m, d, "body", body, friction)
    try:
        for _ in range(int(0.2 / dt)):  # settle into the soft contact
            mujoco.mj_step(m, d)
        x0, y0, t0 = d.qpos[0], d.qpos[1], d.time
        rot, yaw = 0.0, _yaw(d)

        def step():
            nonlocal rot, yaw
            mujoco.mj_step(m, d)
            rot += math.remainder(_yaw(d) - yaw, 2 * math.pi)  # unwrapped
            yaw = _yaw(d)

        smj.set_twist(m, d, "body", state.vx, state.vy, state.omega)
        step()
        while c.friction.state != "stick" and d.time - t0 < t_max:
            step()
        assert c.friction.state == "stick"
        for _ in range(5):  # at rest it stays
            step()
        return c.friction.stop_time - t0, d.qpos[0] - x0, d.qpos[1] - y0, rot
    finally:
        smj.detach(m, d)


PUCK = ss.Body(Disk(0.05), ss.UniformPressure(), mass=0.17)
BOX = ss.Body(Rectangle(0.2, 0.1), ss.UniformPressure(), mass=1.0)
# a curling stone: the running band, a ring of 63 mm radius and 6 mm width
STONE = ss.Body(Annulus(0.060, 0.066), ss.UniformPressure(), mass=19.0, moment_of_inertia=0.14)

CASES = {
    "puck": (PUCK, ss.FrictionTensor(0.3, 0.3), ss.State(vx=1.2, vy=0.0, omega=25.0)),
    "box": (BOX, ss.FrictionTensor(0.35, 0.35), ss.State(vx=0.9, vy=0.4, omega=9.0)),
    "stone": (STONE, ss.FrictionTensor(0.012, 0.012), ss.State(vx=1.5, vy=0.0, omega=1.5)),
    "anisotropic box": (
        BOX,
        ss.FrictionTensor(0.25, 0.45, angle=0.3),
        ss.State(vx=0.8, vy=-0.3, omega=6.0),
    ),
    "body-frame tensor": (
        BOX,
        ss.FrictionTensor(0.25, 0.45, frame="body"),
        ss.State(vx=0.8, vy=0.2, omega=-7.0),
    ),
}


@pytest.mark.parametrize("name", list(CASES))
@pytest.mark.parametrize(("dt", "tol"), [(1e-3, 5e-3), (1e-2, 2e-2)])
def test_coupled_launches_agree_with_slidespin(name, dt, tol):
    body, friction, state = CASES[name]
    tr = ss.simulate(body, friction, state, g=G)
    t_stop, dx, dy, rot = _launch(body, friction, state, dt, t_max=2 * tr.t_stop + 1)
    dist = math.hypot(tr.x[-1], tr.y[-1])
    assert abs(t_stop - tr.t_stop) <= tol * tr.t_stop
    assert math.hypot(dx - tr.x[-1], dy - tr.y[-1]) <= tol * dist
    assert abs(rot - tr.phi[-1]) <= tol * abs(tr.phi[-1])


def test_a_ramped_push_sticks_slips_and_sticks_as_slidespin_says():
    body, friction = BOX, ss.FrictionTensor(0.3, 0.3)
    times, force = [0.0, 1.0, 1.4, 2.0], [0.0, 4.0, 4.0, 0.0]
    load = ss.Load.piecewise_linear(times, force, [0.0] * 4)
    tr = ss.simulate(body, friction, ss.State(), load=load, g=G, t_end=3.0)
    kinds = [p[0] for p in tr.phases]
    assert kinds[:3] == ["stick", "slip", "stick"]
    slip = tr.phases[1]
    dt = 1e-3
    m, d = _scene(body, dt)
    c = smj.attach(m, d, "body", body, friction)
    try:
        for _ in range(200):
            mujoco.mj_step(m, d)
        x0, t0 = d.qpos[0], d.time
        states = []
        while d.time - t0 < 3.0 - 1e-9:
            # the push at the middle of the step (the engine holds it over the step)
            d.xfrc_applied[1, 0] = np.interp(d.time - t0 + dt / 2, times, force)
            mujoco.mj_step(m, d)
            states.append((d.time - t0, c.friction.state))
        starts = [t for (t, s), (_, p) in zip(states[1:], states[:-1]) if s == "slip" != p]
        assert len(starts) == 1
        assert abs(starts[0] - slip[1]) <= 2 * dt
        assert abs(c.friction.stop_time - t0 - slip[2]) <= 2 * dt
        assert abs(d.qpos[0] - x0 - tr.x[-1]) <= 5e-3 * tr.x[-1]
    finally:
        smj.detach(m, d)


def test_a_push_at_95_percent_of_the_threshold_does_not_creep():
    body, friction = BOX, ss.FrictionTensor(0.3, 0.3)
    m, d = _scene(body, 1e-3)
    smj.attach(m, d, "body", body, friction)
    try:
        for _ in range(200):
            mujoco.mj_step(m, d)
        x0 = d.qpos[:2].copy()
        d.xfrc_applied[1, 0] = 0.95 * 0.3 * body.mass * G  # N: the threshold is μ m g
        for _ in range(10_000):
            mujoco.mj_step(m, d)
        assert np.linalg.norm(d.qpos[:2] - x0) < 1e-6
        # and 5 % above the threshold it slides at (F − μ m g)/m
        d.xfrc_applied[1, 0] = 1.05 * 0.3 * body.mass * G
        for _ in range(1000):
            mujoco.mj_step(m, d)
        assert d.qvel[0] == pytest.approx(0.05 * 0.3 * G * 1.0, rel=1e-2)
    finally:
        smj.detach(m, d)


def test_a_box_on_a_slope_below_the_friction_angle_stays():
    body, friction = BOX, ss.FrictionTensor(0.4, 0.4)
    alpha = math.atan(0.9 * 0.4)
    m, d = _scene(body, 1e-3, incline=alpha)
    smj.attach(m, d, "body", body, friction)
    try:
        for _ in range(200):
            mujoco.mj_step(m, d)
        x0 = d.qpos[:3].copy()
        for _ in range(5000):
            mujoco.mj_step(m, d)
        assert np.linalg.norm(d.qpos[:3] - x0) < 1e-6
    finally:
        smj.detach(m, d)


def test_above_the_friction_angle_it_slides_with_the_kinetic_acceleration():
    body, friction = BOX, ss.FrictionTensor(0.3, 0.3, static=1.5)
    alpha = math.atan(0.4)  # between μk = 0.3 and μs = 0.45: held at rest
    m, d = _scene(body, 1e-3, incline=alpha)
    c = smj.attach(m, d, "body", body, friction)
    try:
        for _ in range(1000):
            mujoco.mj_step(m, d)
        assert c.friction.state == "stick"
        assert np.linalg.norm(d.qvel[:3]) < 1e-9
        # a kick: once sliding, kinetic friction cannot stop it (tan α > μk)
        v0 = 0.2  # m/s down the slope (the plane's x axis)
        d.qvel[:3] = v0 * np.array([math.cos(alpha), 0.0, -math.sin(alpha)])
        for _ in range(500):
            mujoco.mj_step(m, d)
        speed = float(np.linalg.norm(d.qvel[:3]))
        accel = G * (math.sin(alpha) - 0.3 * math.cos(alpha))
        assert speed == pytest.approx(v0 + accel * 0.5, rel=2e-3)
    finally:
        smj.detach(m, d)


def test_several_bodies_at_once_and_detach_restores_the_model():
    xml = smj.mujoco_xml(PUCK, name="a")
    xml2 = smj.mujoco_xml(BOX, name="b", position=(1.0, 0.0))
    # one scene with both bodies: the second body's <body> element into the first's world
    body_b = xml2[xml2.index('<body name="b"') : xml2.index("</worldbody>")]
    scene = xml.replace("</worldbody>", body_b + "</worldbody>")
    m = mujoco.MjModel.from_xml_string(scene)
    d = mujoco.MjData(m)
    condim, priority = m.geom_condim.copy(), m.geom_priority.copy()
    calls = []
    mujoco.set_mjcb_passive(lambda mm, dd: calls.append(1))
    try:
        smj.attach(m, d, "a", PUCK, ss.FrictionTensor(0.3, 0.3))
        smj.attach(m, d, "b", BOX, ss.FrictionTensor(0.35, 0.35))
        assert sorted(smj.attached(d)) == ["a", "b"]
        with pytest.raises(ValueError, match="already attached"):
            smj.attach(m, d, "a", PUCK, ss.FrictionTensor(0.3, 0.3))
        for _ in range(200):
            mujoco.mj_step(m, d)
        assert len(calls) >= 200  # the callback set before is chained (and the dry runs)
        smj.detach(m, d, "a")
        assert smj.attached(d) == ["b"]
        smj.detach(m, d)
        assert smj.attached(d) == []
        np.testing.assert_array_equal(m.geom_condim, condim)
        np.testing.assert_array_equal(m.geom_priority, priority)
        assert mujoco.get_mjcb_passive() is not None  # the user's callback is back
    finally:
        mujoco.set_mjcb_passive(None)


def test_models_compile_while_a_body_is_attached():
    m, d = _scene(BOX)
    smj.attach(m, d, "body", BOX, ss.FrictionTensor(0.3, 0.3))
    try:
        other = mujoco.MjModel.from_xml_string(smj.mujoco_xml(PUCK))  # MuJoCo steps it
        assert other.nbody == 2
        mujoco.mj_step(other, mujoco.MjData(other))  # an uncoupled data steps as before
    finally:
        smj.detach(m, d)


def test_attach_from_a_case_file(tmp_path):
    case = tmp_path / "box.toml"
    case.write_text(
        '[patch]\nshape = "rectangle"\nlength = 0.2\nwidth = 0.1\n[pressure]\nlaw = "uniform"\n'
        "[friction]\nfx = 0.35\nfy = 0.35\n[body]\nmass = 1.0\n"
        "[initial]\nspeed = 0.9\nomega = 5.0\n"
    )
    m, d = _scene(BOX)
    c = smj.attach(m, d, "body", case)
    try:
        assert c.friction.friction == ss.FrictionTensor(0.35, 0.35)
    finally:
        smj.detach(m, d)


def test_bad_input_is_refused_with_the_parameter_named():
    m, d = _scene(BOX)
    fr = ss.FrictionTensor(0.3, 0.3)
    with pytest.raises(ValueError, match="body_name = 'nope'"):
        smj.attach(m, d, "nope", BOX, fr)
    with pytest.raises(ValueError, match="friction = None"):
        smj.attach(m, d, "body", BOX)
    with pytest.raises(ValueError, match="body.height"):
        smj.attach(
            m, d, "body", ss.Body(Rectangle(0.2, 0.1), ss.UniformPressure(), 1.0, height=0.1), fr
        )
    with pytest.raises(ValueError, match="speed_law"):
        smj.attach(m, d, "body", BOX, ss.FrictionTensor(0.3, 0.3, speed_law=ss.PowerLaw(0.1)))
    with pytest.raises(ValueError, match="support"):
        smj.attach(m, d, "body", BOX, fr, support="table")
    with pytest.raises(ValueError, match=r"support = \[\]"):
        smj.attach(m, d, "body", BOX, fr, support=[])
    with pytest.raises(TypeError, match="model, data"):
        smj.attach(None, d, "body", BOX, fr)
    m.opt.integrator = mujoco.mjtIntegrator.mjINT_RK4
    with pytest.raises(ValueError, match="RK4"):
        smj.attach(m, d, "body", BOX, fr)
    assert smj.attached(d) == []
    fixed = mujoco.MjModel.from_xml_string(
        '<mujoco><worldbody><body name="b"><geom type="box" size=".1 .1 .1"/></body>'
        "</worldbody></mujoco>"
    )
    with pytest.raises(ValueError, match="free joint"):
        smj.attach(fixed, mujoco.MjData(fixed), "b", BOX, fr)


def test_on_a_moving_platform_the_twist_is_relative_to_it():
    """A box on the top of a heavy platform that slides at 0.5 m/s (a flat box top as the
    support): at rest on it, it rides along; launched at 1 m/s relative to it, it stops
    after v²/(2 μ g) relative to the platform, as slidespin says for a fixed plane."""
    body, friction = BOX, ss.FrictionTensor(0.3, 0.3)
    xml = smj.mujoco_xml(body, name="box")
    top = 0.05  # the platform's top, where the box's plane is
    platform = (
        '<body name="platform" pos="0 0 0.025"><joint name="slide" type="slide" axis="1 0 0"/>'
        '<geom name="deck" type="box" size="5 1 0.025" mass="1e6"/></body>'
    )
    xml = xml.replace('<body name="box" pos="', f'{platform}<body name="box" pos="')
    m = mujoco.MjModel.from_xml_string(xml)
    d = mujoco.MjData(m)
    d.qpos[m.jnt_qposadr[m.body("box").jntadr[0]] + 2] += top  # on the deck
    smj.attach(m, d, "box", body, friction, support="deck")
    try:
        d.qvel[0] = 0.5  # the platform's slide joint
        smj.set_twist(m, d, "box", 0.5, 0.0, 0.0)
        for _ in range(300):
            mujoco.mj_step(m, d)
        rel0 = d.body("box").xpos[0] - d.body("platform").xpos[0]
        for _ in range(300):
            mujoco.mj_step(m, d)
        rel1 = d.body("box").xpos[0] - d.body("platform").xpos[0]
        assert abs(rel1 - rel0) < 1e-6  # rides along, stuck
        smj.set_twist(m, d, "box", 1.5, 0.0, 0.0)  # 1 m/s relative to the deck
        for _ in range(1000):
            mujoco.mj_step(m, d)
        rel2 = d.body("box").xpos[0] - d.body("platform").xpos[0]
        assert rel2 - rel1 == pytest.approx(1.0 / (2 * 0.3 * G), rel=5e-3)
    finally:
        smj.detach(m, d)


@pytest.mark.parametrize("integrator", ["implicit", "implicitfast"])
def test_the_implicit_integrators_agree_too(integrator):
    body, friction, state = CASES["box"]
    tr = ss.simulate(body, friction, state, g=G)
    xml = smj.mujoco_xml(body).replace('integrator="Euler"', f'integrator="{integrator}"')
    m = mujoco.MjModel.from_xml_string(xml)
    d = mujoco.MjData(m)
    c = smj.attach(m, d, "body", body, friction)
    try:
        for _ in range(200):
            mujoco.mj_step(m, d)
        x0, y0, t0 = d.qpos[0], d.qpos[1], d.time
        smj.set_twist(m, d, "body", state.vx, state.vy, state.omega)
        mujoco.mj_step(m, d)
        while c.friction.state != "stick" and d.time - t0 < 5.0:
            mujoco.mj_step(m, d)
        assert abs(c.friction.stop_time - t0 - tr.t_stop) <= 5e-3 * tr.t_stop
        assert math.hypot(
            d.qpos[0] - x0 - tr.x[-1], d.qpos[1] - y0 - tr.y[-1]
        ) <= 5e-3 * math.hypot(tr.x[-1], tr.y[-1])
    finally:
        smj.detach(m, d)


def test_a_finger_keeps_its_friction_with_the_body_and_pushes_it():
    """The body–floor contacts lose MuJoCo's tangential friction (condim 1); a finger's
    contact with the body keeps its own (condim 3), and a finger driven into the box at
    10 cm/s pushes it along once the push exceeds μ m g."""
    xml = (
        smj.mujoco_xml(BOX, name="box")
        .replace(
            "</worldbody>",
            '<body name="finger" pos="-0.2 0 0.015"><joint name="fx" type="slide" axis="1 0 0"/>'
            '<geom name="tip" type="sphere" size="0.004" mass="1"/></body></worldbody>'
            '<actuator><velocity joint="fx" kv="1000"/></actuator>',
        )
        .replace('integrator="Euler"', 'integrator="implicitfast"')
    )
    m = mujoco.MjModel.from_xml_string(xml)
    d = mujoco.MjData(m)
    smj.attach(m, d, "box", BOX, ss.FrictionTensor(0.3, 0.3))
    try:
        d.ctrl[0] = 0.1  # m/s
        for _ in range(2000):
            mujoco.mj_step(m, d)
        tip, box0, floor = m.geom("tip").id, m.geom("box_0").id, m.geom("floor").id
        dims = {tuple(sorted(g)): int(dim) for g, dim in zip(d.contact.geom, d.contact.dim)}
        assert dims[tuple(sorted((tip, box0)))] == 3
        assert dims[tuple(sorted((floor, box0)))] == 1
        # the finger moved ~0.2 m: 0.1 m to the box's back face, then pushed it ~0.1 m at the
        # actuator's speed less its lag under the push μ m g (0.1 − 2.94/1000 m/s)
        assert d.body("box").xpos[0] == pytest.approx(0.1, abs=0.01)
        assert d.qvel[m.body("box").dofadr[0]] == pytest.approx(0.1 - 0.3 * G / 1000, abs=2e-4)
    finally:
        smj.detach(m, d)


@pytest.mark.parametrize(("dt", "tol"), [(1e-3, 5e-3), (1e-2, 2e-2)])
def test_a_launch_from_exact_contact_without_settling(dt, tol):
    """The body placed exactly on the floor and launched at once: MuJoCo's soft contact
    carries no load in its first step; the coupling takes the weight's share there and repays
    it from the engine's next loads."""
    body, friction, state = CASES["box"]
    tr = ss.simulate(body, friction, state, g=G)
    m, d = _scene(body, dt)
    c = smj.attach(m, d, "body", body, friction)
    try:
        smj.set_twist(m, d, "body", state.vx, state.vy, state.omega)
        x0, y0 = d.qpos[0], d.qpos[1]
        mujoco.mj_step(m, d)
        while c.friction.state != "stick" and d.time < 5.0:
            mujoco.mj_step(m, d)
        assert abs(c.friction.stop_time - tr.t_stop) <= tol * tr.t_stop
        assert math.hypot(d.qpos[0] - x0 - tr.x[-1], d.qpos[1] - y0 - tr.y[-1]) <= tol * math.hypot(
            tr.x[-1], tr.y[-1]
        )
    finally:
        smj.detach(m, d)


def test_a_changed_time_step_and_integrator_are_followed():
    body, friction, state = CASES["box"]
    tr = ss.simulate(body, friction, state, g=G)
    m, d = _scene(body, 2e-3)
    c = smj.attach(m, d, "body", body, friction)
    try:
        for _ in range(100):
            mujoco.mj_step(m, d)
        m.opt.timestep = 1e-3  # after attach: the coupling follows
        x0, t0 = d.qpos[0], d.time
        smj.set_twist(m, d, "body", state.vx, state.vy, state.omega)
        mujoco.mj_step(m, d)
        while c.friction.state != "stick" and d.time - t0 < 5.0:
            mujoco.mj_step(m, d)
        assert c.friction.dt == 1e-3
        assert d.qpos[0] - x0 == pytest.approx(tr.x[-1], rel=5e-3)
        m.opt.integrator = mujoco.mjtIntegrator.mjINT_RK4
        with pytest.warns(RuntimeWarning, match="RK4") as record:
            for _ in range(10):
                mujoco.mj_step(m, d)
        assert len(record) == 1  # said once
    finally:
        smj.detach(m, d)
