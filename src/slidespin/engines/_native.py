"""One launch of a flat body in a rigid-body engine with the engine's own friction.

The runners (:func:`run_mujoco`, :func:`run_pybullet`, :func:`run_drake`) build the scene of
:mod:`slidespin.engines.scenes` in the engine (MuJoCo's MJCF of :func:`mujoco_xml`; PyBullet
and Drake from the same primitives, :func:`prism_parts`, of the same thickness 0.2 ℓ and
inertia), let the body settle on the floor at rest, launch it with the planar state of a
:class:`slidespin.State` and step until it stops. They measure what :func:`slidespin.simulate`
reports: the stop time, the stop position of the mass centre G and the body angle φ
(continuous, unwrapped: a body that turns twice reports 4π). A run *stops* at the first step
where the planar speed of G is below ``STOP_FRACTION`` × the launch's speed scale
V = ``max(|v₀|, k |ω₀|)`` (k the radius of gyration) and the spin below the same fraction × V/k;
a run that has not stopped by ``t_max`` returns its values there with ``stopped`` False.

The engines' friction parameters, keyed by the engine's own names (as
:func:`slidespin.engines.parameters.engine_parameters` returns them):

* MuJoCo: ``friction`` (μ, μ_torsion, μ_roll), ``condim`` (3, 4 or 6), ``cone``
  (``"elliptic"``; the scene's): set on the body's geoms and the floor (MuJoCo combines a
  pair by the element-wise maximum, so both carry the same).
* PyBullet: ``lateralFriction``, ``spinningFriction``, ``rollingFriction``,
  ``anisotropicFriction`` (3 scale factors along the body's axes) on the body; the floor has
  lateralFriction 1 and no spinning or rolling friction (Bullet multiplies the lateral
  coefficients and adds spinning × the other's lateral, so these are the pair's values).
* Drake: ``static_friction``, ``dynamic_friction`` (a :class:`CoulombFriction` on the body and
  the floor, which Drake combines into the same values), ``contact_model`` (``"point"`` or
  ``"hydroelastic_with_fallback"``), ``hydroelastic_modulus`` [Pa], ``resolution_hint`` [m],
  ``hunt_crossley_dissipation`` [s/m] and ``discrete_contact_approximation`` (``"sap"``):
  with hydroelastic contact the body is compliant and the floor a rigid half-space.

May import: :mod:`slidespin.engines.scenes`, :mod:`slidespin.contact`,
:mod:`slidespin.motion` (the State); each engine is imported lazily by its runner.
"""

from __future__ import annotations

import logging
import math
import tempfile
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from slidespin.contact.body import Body
from slidespin.engines.scenes import mujoco_xml, prism_parts
from slidespin.motion.state import State

__all__ = ["NativeRun", "run_mujoco", "run_pybullet", "run_drake", "run_native", "ENGINES"]

#: the engines, with the extra that installs each
ENGINES = {"mujoco": "mujoco", "pybullet": "pybullet", "drake": "drake"}
#: a run stops when its speed < STOP_FRACTION V and its spin < STOP_FRACTION V/k
STOP_FRACTION = 2e-3
#: time given to the body to settle on the floor before the launch [s]
SETTLE_TIME = 0.1
#: thickness of the prisms, in units of the body's length unit ℓ (as in mujoco_xml)
THICKNESS = 0.2
#: sides of the polygon that stands for a disk in the PyBullet scene
DISK_SIDES = 32


@dataclass(frozen=True)
class NativeRun:
    """The end of one launch in an engine (SI units).

    Attributes
    ----------
    t_stop : float
        Time from the launch to the stop [s] (``t_max`` if it did not stop).
    x, y : float
        Position of the mass centre G at the stop, in the plane [m].
    phi : float
        Body angle at the stop, unwrapped from the launch's φ₀ [rad].
    stopped : bool
        Whether the run stopped before ``t_max``.
    """

    t_stop: float
    x: float
    y: float
    phi: float
    stopped: bool


def _import(engine: str):
    """Import an engine's Python package, or raise ImportError saying how to install it."""
    try:
        if engine == "mujoco":
            import mujoco

            return mujoco
        if engine == "pybullet":
            import pybullet

            return pybullet
        import pydrake.all

        return pydrake.all
    except ImportError as exc:  # pragma: no cover - exercised only without the engine
        raise ImportError(
            f"engine = {engine!r} needs the {engine} package, which is not installed: "
            f'pip install "slidespin[{ENGINES[engine]}]"'
        ) from exc


def _scales(body: Body, state: State) -> tuple[float, float]:
    """(v_eps, omega_eps): the stop thresholds of a launch."""
    k = body.radius_of_gyration
    speed = max(math.hypot(state.vx, state.vy), k * abs(state.omega), 1e-9)
    return STOP_FRACTION * speed, STOP_FRACTION * speed / k


def _inertia(body: Body) -> tuple[float, float, float, float]:
    """(thickness, Ixx, Iyy, Izz) of the prism, as mujoco_xml gives them."""
    t = THICKNESS * body.length_unit
    izz = body.moment_of_inertia if body.moment_of_inertia is not None else body._inertia
    ixx = 0.5 * izz + body.mass * t * t / 12.0
    return t, ixx, ixx, izz


def _wrap(d: float) -> float:
    return (d + math.pi) % (2.0 * math.pi) - math.pi


class _Tracker:
    """Unwraps the yaw step by step and decides the stop."""

    def __init__(self, body: Body, state: State, dt: float, t_max: float) -> None:
        self.v_eps, self.w_eps = _scales(body, state)
        self.n_max = max(1, int(math.ceil(t_max / dt)))
        self.dt = dt
        self.phi = float(state.phi)

    def yaw(self, yaw_prev: float, yaw_now: float) -> None:
        self.phi += _wrap(yaw_now - yaw_prev)

    def still(self, vx: float, vy: float, wz: float) -> bool:
        return math.hypot(vx, vy) < self.v_eps and abs(wz) < self.w_eps


def _yaw_quat(w: float, x: float, y: float, z: float) -> float:
    return math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))


# ------------------------------------------------------------------------------------------
# MuJoCo
# ------------------------------------------------------------------------------------------
def _mujoco_runs(body, params, states, g, dt, t_max):
    mujoco = _import("mujoco")
    contact = {"friction": tuple(params["friction"]), "condim": int(params.get("condim", 4))}
    cone = str(params.get("cone", "elliptic"))
    xml = mujoco_xml(body, timestep=dt, contact=contact)
    if cone != "elliptic":
        xml = xml.replace('cone="elliptic"', f'cone="{cone}"')
    model = mujoco.MjModel.from_xml_string(xml)
    model.opt.gravity[:] = (0.0, 0.0, -g)
    data = mujoco.MjData(model)
    for _ in range(int(round(SETTLE_TIME / dt))):
        mujoco.mj_step(model, data)
    z0, warm = float(data.qpos[2]), data.qacc_warmstart.copy()
    out = []
    for s in states:
        mujoco.mj_resetData(model, data)
        data.qpos[:3] = (s.x, s.y, z0)
        data.qpos[3:7] = (math.cos(s.phi / 2), 0.0, 0.0, math.sin(s.phi / 2))
        data.qvel[:] = 0.0
        data.qvel[0], data.qvel[1], data.qvel[5] = s.vx, s.vy, s.omega
        data.qacc_warmstart[:] = warm
        tr = _Tracker(body, s, dt, t_max)
        yaw = _wrap(s.phi)
        stopped, n = False, 0
        qpos, qvel = data.qpos, data.qvel
        while n < tr.n_max:
            mujoco.mj_step(model, data)
            n += 1
            y_now = _yaw_quat(*qpos[3:7])
            tr.yaw(yaw, y_now)
            yaw = y_now
            if tr.still(qvel[0], qvel[1], qvel[5]):
                stopped = True
                break
        out.append(NativeRun(n * dt, float(qpos[0]), float(qpos[1]), tr.phi, stopped))
    return out


def run_mujoco(body: Body, params: dict, state: State, *, g: float = 9.81, dt: float = 1e-3,
               t_max: float = 5.0) -> NativeRun:  # fmt: skip
    """One launch in MuJoCo with its own friction (see the module docstring).

    Parameters
    ----------
    body : Body
        The thin body (a footprint :func:`prism_parts` represents).
    params : dict
        ``friction`` (μ, μ_torsion, μ_roll), ``condim`` (3, 4 or 6), ``cone``.
    state : State
        The launch: position, angle and planar velocity of G [SI].
    g : float
        Gravity [m/s²].
    dt : float
        The engine's step [s].
    t_max : float
        Longest motion simulated after the launch [s].

    Returns
    -------
    NativeRun
    """
    return _mujoco_runs(body, params, [state], g, dt, t_max)[0]


# ------------------------------------------------------------------------------------------
# PyBullet
# ------------------------------------------------------------------------------------------
def _prism_obj(outline, t: float) -> str:
    """Wavefront OBJ text of a convex prism of thickness t over an outline (n, 2)."""
    v = np.asarray(outline, dtype=float)
    n = len(v)
    lines = [f"v {a:.17g} {b:.17g} {z:.17g}" for z in (-t / 2, t / 2) for a, b in v]
    lines += [f"f {i + 1} {(i + 1) % n + 1} {(i + 1) % n + 1 + n}" for i in range(n)]
    lines += [f"f {i + 1} {(i + 1) % n + 1 + n} {i + 1 + n}" for i in range(n)]
    return "\n".join(lines) + "\n"


def _pybullet_shape(p, cid, body, folder):
    """The body's collision shape: a compound of boxes and convex prisms (a disk as a
    ``DISK_SIDES``-gon: Bullet's cylinder–plane contact wobbles on a spinning disk)."""
    t = THICKNESS * body.length_unit
    types, half, names, pos, orn = [], [], [], [], []
    for k, (kind, c, ang, size) in enumerate(prism_parts(body)):
        if kind == "box":
            types.append(p.GEOM_BOX)
            half.append([size[0], size[1], t / 2])
            names.append("")
            pos.append([c[0], c[1], 0.0])
            orn.append([0.0, 0.0, math.sin(ang / 2), math.cos(ang / 2)])
            continue
        if kind == "cylinder":
            a = np.linspace(0.0, 2.0 * math.pi, DISK_SIDES, endpoint=False)
            # the polygon of the disk's area: a little larger circumradius
            r = size[0] * math.sqrt(
                2.0 * math.pi / (DISK_SIDES * math.sin(2.0 * math.pi / DISK_SIDES))
            )
            outline = np.column_stack([c[0] + r * np.cos(a), c[1] + r * np.sin(a)])
        else:
            outline = np.asarray(size, dtype=float)
        path = f"{folder}/part_{k}.obj"
        with open(path, "w", encoding="utf-8") as fh:
            fh.write(_prism_obj(outline, t))
        types.append(p.GEOM_MESH)
        half.append([0.0, 0.0, 0.0])
        names.append(path)
        pos.append([0.0, 0.0, 0.0])
        orn.append([0.0, 0.0, 0.0, 1.0])
    return p.createCollisionShapeArray(
        shapeTypes=types, halfExtents=half, fileNames=names,
        collisionFramePositions=pos, collisionFrameOrientations=orn, physicsClientId=cid,
    )  # fmt: skip


def _pybullet_runs(body, params, states, g, dt, t_max):
    p = _import("pybullet")
    cid = p.connect(p.DIRECT)
    folder = tempfile.TemporaryDirectory(prefix="slidespin-pybullet-")
    try:
        p.setGravity(0.0, 0.0, -g, physicsClientId=cid)
        p.setPhysicsEngineParameter(fixedTimeStep=dt, numSubSteps=0, physicsClientId=cid)
        floor = p.createMultiBody(
            0.0, p.createCollisionShape(p.GEOM_PLANE, physicsClientId=cid), physicsClientId=cid
        )
        p.changeDynamics(floor, -1, lateralFriction=1.0, spinningFriction=0.0,
                         rollingFriction=0.0, restitution=0.0, physicsClientId=cid)  # fmt: skip
        t, ixx, iyy, izz = _inertia(body)
        uid = p.createMultiBody(
            baseMass=body.mass, baseCollisionShapeIndex=_pybullet_shape(p, cid, body, folder.name),
            basePosition=[0.0, 0.0, t / 2], physicsClientId=cid,
        )  # fmt: skip
        aniso = [float(c) for c in params.get("anisotropicFriction", (1.0, 1.0, 1.0))]
        p.changeDynamics(
            uid, -1, localInertiaDiagonal=[ixx, iyy, izz], linearDamping=0.0,
            angularDamping=0.0, restitution=0.0, collisionMargin=1e-4 * body.length_unit,
            lateralFriction=float(params.get("lateralFriction", 0.5)),
            spinningFriction=float(params.get("spinningFriction", 0.0)),
            rollingFriction=float(params.get("rollingFriction", 0.0)),
            anisotropicFriction=aniso, activationState=p.ACTIVATION_STATE_DISABLE_SLEEPING,
            physicsClientId=cid,
        )  # fmt: skip
        for _ in range(int(round(SETTLE_TIME / dt))):
            p.stepSimulation(physicsClientId=cid)
        z0 = p.getBasePositionAndOrientation(uid, physicsClientId=cid)[0][2]
        out = []
        for s in states:
            quat = (0.0, 0.0, math.sin(s.phi / 2), math.cos(s.phi / 2))
            p.resetBasePositionAndOrientation(uid, [s.x, s.y, z0], quat, physicsClientId=cid)
            p.resetBaseVelocity(uid, [s.vx, s.vy, 0.0], [0.0, 0.0, s.omega], physicsClientId=cid)
            tr = _Tracker(body, s, dt, t_max)
            yaw, stopped, n = _wrap(s.phi), False, 0
            pos = (s.x, s.y)
            while n < tr.n_max:
                p.stepSimulation(physicsClientId=cid)
                n += 1
                pos, q = p.getBasePositionAndOrientation(uid, physicsClientId=cid)
                y_now = _yaw_quat(q[3], q[0], q[1], q[2])
                tr.yaw(yaw, y_now)
                yaw = y_now
                lin, ang = p.getBaseVelocity(uid, physicsClientId=cid)
                if tr.still(lin[0], lin[1], ang[2]):
                    stopped = True
                    break
            out.append(NativeRun(n * dt, float(pos[0]), float(pos[1]), tr.phi, stopped))
        return out
    finally:
        p.disconnect(physicsClientId=cid)
        folder.cleanup()


def run_pybullet(body: Body, params: dict, state: State, *, g: float = 9.81, dt: float = 1e-3,
                 t_max: float = 5.0) -> NativeRun:  # fmt: skip
    """One launch in PyBullet with its own friction (see the module docstring).

    Parameters
    ----------
    body : Body
        The thin body (a footprint :func:`prism_parts` represents; pads only of rectangles
        and disks).
    params : dict
        ``lateralFriction``, ``spinningFriction``, ``rollingFriction``,
        ``anisotropicFriction`` (the body's; the floor's lateral friction is 1).
    state, g, dt, t_max
        As in :func:`run_mujoco`.

    Returns
    -------
    NativeRun
    """
    return _pybullet_runs(body, params, [state], g, dt, t_max)[0]


# ------------------------------------------------------------------------------------------
# Drake
# ------------------------------------------------------------------------------------------
def _drake_runs(body, params, states, g, dt, t_max):
    d = _import("drake")
    log = logging.getLogger("drake")
    level = log.level
    log.setLevel(logging.ERROR)  # Drake warns that a rigid half-space has no deformable contact
    try:
        return _drake_scene_runs(d, body, params, states, g, dt, t_max)
    finally:
        log.setLevel(level)


def _drake_scene_runs(d, body, params, states, g, dt, t_max):
    t, ixx, iyy, izz = _inertia(body)
    model = str(params.get("contact_model", "point"))
    cfg = d.MultibodyPlantConfig(
        time_step=dt, contact_model=model,
        discrete_contact_approximation=str(params.get("discrete_contact_approximation", "sap")),
    )  # fmt: skip
    builder = d.DiagramBuilder()
    plant, _ = d.AddMultibodyPlant(cfg, builder)
    m = body.mass
    inertia = d.SpatialInertia(m, np.zeros(3), d.UnitInertia(ixx / m, iyy / m, izz / m))
    rb = plant.AddRigidBody("body", inertia)
    friction = d.CoulombFriction(
        float(params.get("static_friction", params.get("dynamic_friction", 0.5))),
        float(params.get("dynamic_friction", 0.5)),
    )
    hydro = model != "point"
    weight = m * g
    dissipation = float(params.get("hunt_crossley_dissipation", 10.0))

    def props(compliant: bool):  # -> pydrake.geometry.ProximityProperties
        pp = d.ProximityProperties()
        # point stiffness: the weight sinks the body by ~1e-3 ℓ
        d.AddContactMaterial(dissipation, weight / (1e-3 * body.length_unit), friction, pp)
        if hydro and compliant:
            d.AddCompliantHydroelasticProperties(
                float(params["resolution_hint"]), float(params["hydroelastic_modulus"]), pp
            )
        elif hydro:
            d.AddRigidHydroelasticProperties(pp)
        return pp

    for k, (kind, c, ang, size) in enumerate(prism_parts(body)):
        pose = d.RigidTransform(d.RotationMatrix.MakeZRotation(ang), [c[0], c[1], 0.0])
        if kind == "box":
            shape = d.Box(2 * size[0], 2 * size[1], t)
        elif kind == "cylinder":
            shape = d.Cylinder(size[0], t)
        else:
            obj = _prism_obj(size, t)
            shape = d.Convex(d.InMemoryMesh(mesh_file=d.MemoryFile(obj, ".obj", "prism")))
        plant.RegisterCollisionGeometry(rb, pose, shape, f"body_{k}", props(True))
    plant.RegisterCollisionGeometry(
        plant.world_body(), d.HalfSpace.MakePose([0, 0, 1], [0, 0, 0]), d.HalfSpace(),
        "floor", props(False),
    )  # fmt: skip
    plant.mutable_gravity_field().set_gravity_vector([0.0, 0.0, -g])
    plant.Finalize()
    diagram = builder.Build()
    sim = d.Simulator(diagram)
    ctx = sim.get_mutable_context()
    pctx = plant.GetMyMutableContextFromRoot(ctx)
    plant.SetFreeBodyPose(pctx, rb, d.RigidTransform([0.0, 0.0, t / 2]))
    sim.Initialize()
    sim.AdvanceTo(SETTLE_TIME)
    z0 = float(plant.EvalBodyPoseInWorld(pctx, rb).translation()[2])
    out = []
    for s in states:
        ctx.SetTime(0.0)
        pose = d.RigidTransform(d.RotationMatrix.MakeZRotation(s.phi), [s.x, s.y, z0])
        plant.SetFreeBodyPose(pctx, rb, pose)
        plant.SetFreeBodySpatialVelocity(
            pctx, rb, d.SpatialVelocity([0.0, 0.0, s.omega], [s.vx, s.vy, 0.0])
        )
        sim.Initialize()
        tr = _Tracker(body, s, dt, t_max)
        yaw, stopped, n = _wrap(s.phi), False, 0
        x, y = s.x, s.y
        while n < tr.n_max:
            n += 1
            sim.AdvanceTo(n * dt)
            q = plant.GetPositions(pctx)  # quaternion (w, x, y, z), then position
            v = plant.GetVelocities(pctx)  # angular (world), then linear
            x, y = float(q[4]), float(q[5])
            y_now = _yaw_quat(*q[:4])
            tr.yaw(yaw, y_now)
            yaw = y_now
            if tr.still(v[3], v[4], v[2]):
                stopped = True
                break
        out.append(NativeRun(n * dt, x, y, tr.phi, stopped))
    return out


def run_drake(body: Body, params: dict, state: State, *, g: float = 9.81, dt: float = 1e-3,
              t_max: float = 5.0) -> NativeRun:  # fmt: skip
    """One launch in Drake (a discrete MultibodyPlant) with its own friction.

    Parameters
    ----------
    body : Body
        The thin body (a footprint :func:`prism_parts` represents).
    params : dict
        ``static_friction``, ``dynamic_friction``, ``contact_model`` (``"point"`` or
        ``"hydroelastic_with_fallback"``), and for hydroelastic contact
        ``hydroelastic_modulus`` [Pa] and ``resolution_hint`` [m];
        ``hunt_crossley_dissipation`` [s/m] and ``discrete_contact_approximation``.
    state, g, dt, t_max
        As in :func:`run_mujoco`.

    Returns
    -------
    NativeRun
    """
    return _drake_runs(body, params, [state], g, dt, t_max)[0]


_RUNNERS = {"mujoco": _mujoco_runs, "pybullet": _pybullet_runs, "drake": _drake_runs}


def run_native(engine: str, body: Body, params: dict, states: Sequence[State], *,
               g: float = 9.81, dt: float = 1e-3, t_max: float = 5.0) -> list[NativeRun]:  # fmt: skip
    """Several launches in one engine scene (built once): one :class:`NativeRun` each."""
    return _RUNNERS[engine](body, params, list(states), g, dt, t_max)
