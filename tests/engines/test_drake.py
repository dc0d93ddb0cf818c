"""The Drake coupling (MODEL §16) against slidespin's own simulate (the independent truth)."""

from __future__ import annotations

import math

import numpy as np
import pytest

pytest.importorskip("pydrake")

from pydrake.common.value import AbstractValue  # noqa: E402
from pydrake.geometry import (  # noqa: E402
    AddContactMaterial,
    AddRigidHydroelasticProperties,
    Cylinder,
    HalfSpace,
    ProximityProperties,
)
from pydrake.math import RigidTransform  # noqa: E402
from pydrake.multibody.math import SpatialForce  # noqa: E402
from pydrake.multibody.plant import (  # noqa: E402
    AddMultibodyPlant,
    CoulombFriction,
    ExternallyAppliedSpatialForce,
    MultibodyPlant,
    MultibodyPlantConfig,
)
from pydrake.multibody.tree import SpatialInertia, UnitInertia  # noqa: E402
from pydrake.systems.analysis import Simulator  # noqa: E402
from pydrake.systems.framework import DiagramBuilder, EventStatus  # noqa: E402

import slidespin as ss  # noqa: E402
from slidespin.drake import (  # noqa: E402
    PatchFriction,
    add_patch_friction,
    example_diagram,
    set_planar_state,
)

pytestmark = pytest.mark.xdist_group("drake")

G = 9.81
MU = 0.3


def _planar(plant, pc, body):
    X = plant.GetFreeBodyPose(pc, body)
    V = plant.EvalBodySpatialVelocityInWorld(pc, body)
    R = X.rotation().matrix()
    p = X.translation()
    v = V.translational()
    return (p[0], p[1], math.atan2(R[1, 0], R[0, 0]), v[0], v[1], V.rotational()[2])


def _settle(ex, seconds=0.05, phi=0.0):
    """A simulator with the body settled at rest on the floor (the soft contact's depth)."""
    sim = Simulator(ex.diagram)
    pc = ex.plant.GetMyMutableContextFromRoot(sim.get_mutable_context())
    set_planar_state(ex.plant, pc, ex.body, ss.State(phi=phi), height=ex.thickness / 2)
    sim.Initialize()
    sim.AdvanceTo(seconds)
    return sim, pc


CASES = {
    # the brief's case: a puck, uniform pressure, isotropic μ, launched with speed and spin
    "puck": (
        ss.Body(ss.Disk(0.05), ss.UniformPressure(), mass=0.2),
        ss.FrictionTensor(MU, MU),
        ss.State(vx=1.0, vy=0.0, omega=20.0),
    ),
    # a box on an anisotropic floor, launched obliquely at an angle
    "box-anisotropic": (
        ss.Body(ss.Rectangle(0.1, 0.06), ss.UniformPressure(), mass=0.5),
        ss.FrictionTensor(0.2, 0.4),
        ss.State(phi=0.3, vx=0.8, vy=0.3, omega=15.0),
    ),
}


@pytest.mark.parametrize("case", list(CASES))
def test_launch_matches_simulate(case):
    body, friction, start = CASES[case]
    truth = ss.simulate(body, friction, start, g=G)
    ex = example_diagram(body, friction, time_step=1e-3)
    sim, pc = _settle(ex, phi=start.phi)
    t0 = sim.get_context().get_time()
    z = ex.plant.GetFreeBodyPose(pc, ex.body).translation()[2]
    set_planar_state(ex.plant, pc, ex.body, start, height=z)
    ex.patch.reset()  # the launch is a change of state, not a load
    rec = [(t0, *_planar(ex.plant, pc, ex.body))]

    def monitor(context):
        rec.append((context.get_time(), *_planar(ex.plant, pc, ex.body)))
        return EventStatus.Succeeded()

    sim.set_monitor(monitor)
    sim.AdvanceTo(t0 + truth.t_stop + 0.05)
    a = np.array(rec)
    moving = (np.hypot(a[:, 4], a[:, 5]) > 1e-6) | (np.abs(a[:, 6]) > 1e-4)
    t_stop = a[np.nonzero(moving)[0][-1] + 1, 0] - t0
    dist = math.hypot(a[-1, 1] - a[0, 1], a[-1, 2] - a[0, 2])
    rot = float(np.unwrap(a[:, 3])[-1] - a[0, 3])
    d_truth = math.hypot(truth.x[-1] - truth.x[0], truth.y[-1] - truth.y[0])
    r_truth = truth.phi[-1] - truth.phi[0]
    # the x, y of the stop too (the direction of travel), to 0.5 % of the distance
    shift = (a[-1, 1] - a[0, 1] - truth.x[-1] + truth.x[0], a[-1, 2] - a[0, 2] - truth.y[-1])
    assert math.hypot(*shift) < 5e-3 * d_truth
    assert t_stop == pytest.approx(truth.t_stop, rel=5e-3)  # to the step
    assert ex.patch.stop_time - t0 == pytest.approx(truth.t_stop, rel=1e-3)  # interpolated
    assert dist == pytest.approx(d_truth, rel=5e-3)
    assert rot == pytest.approx(r_truth, rel=5e-3)
    # at rest after the stop: sticking, no creep, the normal force is the weight
    assert ex.patch.coupling.state == "stick"
    assert np.all(np.abs(a[-20:, 4:6]) < 1e-9)
    assert ex.patch.normal == pytest.approx(body.mass * G, rel=1e-3)


def test_box_below_threshold_does_not_creep():
    ex = example_diagram(BOX, ss.FrictionTensor(MU, MU), time_step=1e-3)
    sim, pc = _settle(ex)
    before = _planar(ex.plant, pc, ex.body)
    # 95 % of the static threshold μ m g, at G, along a diagonal, from now on
    push = ExternallyAppliedSpatialForce()
    push.body_index = ex.body.index()
    push.p_BoBq_B = np.zeros(3)
    f = 0.95 * MU * 0.5 * G
    push.F_Bq_W = SpatialForce(tau=np.zeros(3), f=[f * 0.6, f * 0.8, 0.0])
    patch_ctx = ex.patch.GetMyMutableContextFromRoot(sim.get_mutable_context())
    ex.patch.get_applied_spatial_force_input_port().FixValue(patch_ctx, AbstractValue.Make([push]))
    sim.AdvanceTo(sim.get_context().get_time() + 3.0)
    after = _planar(ex.plant, pc, ex.body)
    assert math.hypot(after[0] - before[0], after[1] - before[1]) < 1e-6
    assert abs(after[2] - before[2]) < 1e-6
    assert ex.patch.coupling.state == "stick"


BOX = ss.Body(ss.Rectangle(0.1, 0.06), ss.UniformPressure(), mass=0.5)


@pytest.fixture(scope="module")
def box_depth():
    """The box's settled depth in the soft floor under its weight [m]."""
    ex = example_diagram(BOX, ss.FrictionTensor(MU, MU), time_step=1e-3)
    _, pc = _settle(ex, 0.1)
    return ex.thickness / 2 - ex.plant.GetFreeBodyPose(pc, ex.body).translation()[2]


@pytest.mark.parametrize("alpha", [0.2, 0.35])
def test_box_on_incline(alpha, box_depth):
    """Below atan μ (0.29) the box stays at rest from the first step (N = m g cos α and
    gravity's pull are known then); above, it slides down at g (sin α − μ cos α)."""
    ex = example_diagram(BOX, ss.FrictionTensor(MU, MU), time_step=1e-3, incline=alpha)
    sim = Simulator(ex.diagram)
    pc = ex.plant.GetMyMutableContextFromRoot(sim.get_mutable_context())
    height = ex.thickness / 2 - box_depth * math.cos(alpha)  # resting in the soft floor
    set_planar_state(ex.plant, pc, ex.body, ss.State(), height=height, support=ex.support)
    sim.Initialize()
    X_SW = ex.support.inverse()
    p0 = X_SW.multiply(ex.plant.GetFreeBodyPose(pc, ex.body).translation())
    sim.AdvanceTo(1.0)
    p1 = X_SW.multiply(ex.plant.GetFreeBodyPose(pc, ex.body).translation())
    assert ex.patch.normal == pytest.approx(0.5 * G * math.cos(alpha), rel=1e-6)
    assert abs(p1[1] - p0[1]) < 1e-9
    if math.tan(alpha) < MU:
        assert abs(p1[0] - p0[0]) < 1e-6
        assert ex.patch.coupling.state == "stick"
    else:
        slide = 0.5 * G * (math.sin(alpha) - MU * math.cos(alpha))
        assert p1[0] - p0[0] == pytest.approx(slide, rel=5e-3)


def _plant(time_step=1e-3, friction=0.0, sampled=True):
    builder = DiagramBuilder()
    plant, scene_graph = AddMultibodyPlant(
        MultibodyPlantConfig(time_step=time_step, use_sampled_output_ports=sampled), builder
    )
    props = ProximityProperties()
    AddRigidHydroelasticProperties(properties=props)
    AddContactMaterial(friction=CoulombFriction(friction, friction), properties=props)
    plant.RegisterCollisionGeometry(plant.world_body(), RigidTransform(), HalfSpace(), "f", props)
    puck = plant.AddRigidBody("puck", SpatialInertia(0.2, np.zeros(3), UnitInertia(1, 1, 1)))
    puck_props = ProximityProperties()
    AddContactMaterial(friction=CoulombFriction(friction, friction), properties=puck_props)
    plant.RegisterCollisionGeometry(puck, RigidTransform(), Cylinder(0.05, 0.01), "p", puck_props)
    plant.Finalize()
    return builder, plant


BODY = ss.Body(ss.Disk(0.05), ss.UniformPressure(), mass=0.2)
FRICTION = ss.FrictionTensor(MU, MU)


def test_bad_inputs():
    _, plant = _plant(time_step=0.0)
    with pytest.raises(ValueError, match="continuous plant"):
        PatchFriction(plant, "puck", BODY, FRICTION)
    builder, plant = _plant()
    with pytest.raises(ValueError, match="body = 'nope'"):
        PatchFriction(plant, "nope", BODY, FRICTION)
    with pytest.raises(ValueError, match="world body"):
        PatchFriction(plant, plant.world_body(), BODY, FRICTION)
    with pytest.raises(TypeError, match="body = 3"):
        PatchFriction(plant, 3, BODY, FRICTION)
    with pytest.raises(TypeError, match="slidespin.Body"):
        PatchFriction(plant, "puck", "disk", FRICTION)
    with pytest.raises(ValueError, match="not finalized"):
        PatchFriction(MultibodyPlant(1e-3), "puck", BODY, FRICTION)
    other = _plant()[1]
    patch = PatchFriction(plant, plant.GetBodyByName("puck"), BODY, FRICTION)
    assert patch.inertia == pytest.approx(0.2) and patch.mass == pytest.approx(0.2)
    with pytest.raises(ValueError, match="another plant"):
        PatchFriction(plant, other.GetBodyByName("puck"), BODY, FRICTION)
    _, unsampled = _plant(sampled=False)
    with pytest.raises(ValueError, match="algebraic loop"):
        PatchFriction(unsampled, "puck", BODY, FRICTION)
    assert PatchFriction(unsampled, "puck", BODY, FRICTION, normal_force=1.962).normal == 0.0
    builder, plant = _plant(friction=0.5)
    with pytest.raises(ValueError, match="Drake friction"):
        add_patch_friction(builder, plant, "puck", BODY, FRICTION)
    with pytest.raises(ValueError, match="mesh|valid values"):
        example_diagram(ss.Body(ss.Ellipse(0.05, 0.03), ss.UniformPressure(), 0.2), FRICTION)
    builder, plant = _plant()  # frictionless, but point contact: the normal force jumps
    with pytest.warns(UserWarning, match="hydroelastic"):
        add_patch_friction(builder, plant, "puck", BODY, FRICTION)
