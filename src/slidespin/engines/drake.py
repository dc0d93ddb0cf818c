"""slidespin's exact patch friction inside Drake (MODEL §16).

A discrete :class:`~pydrake.multibody.plant.MultibodyPlant` integrates the body in 3-D and
resolves the normal contact; :class:`PatchFriction` (a Drake ``LeafSystem``) supplies the
tangential friction of the flat contact, step by step, through the engine-independent
:class:`slidespin.engines._coupling.SteppedFriction` (slip: the exact wrench W(ν) of the patch;
stick: a discrete projection onto the static set, so a body under a sub-threshold load does
not creep).

Wiring (see :func:`add_patch_friction`)::

    plant.get_body_poses_output_port()                 -> patch "body_poses"
    plant.get_body_spatial_velocities_output_port()    -> patch "body_spatial_velocities"
    plant.get_contact_results_output_port()            -> patch "contact_results"
    (your other ExternallyAppliedSpatialForce list)    -> patch "applied_spatial_force"
    patch "spatial_forces" -> plant.get_applied_spatial_force_input_port()

Frames. The support is a fixed plane given by ``support`` = X_WS (its z axis the normal, its
origin on the plane; default the world's z = 0 plane). The body's frame B has its z axis along
the footprint's normal and its x axis along the footprint's ξ axis; its mass centre is the
plant's (the slidespin body's G). Each step, the planar twist ν = (vx, vy, ω) of G in the
support frame and the angle φ of B's x axis projected on the plane go to ``SteppedFriction``;
the wrench (Fx, Fy, M) it returns is applied as a force at the point of the plane below G (so
Drake sees the tipping moment of friction) plus the moment M about the normal.

The normal force N is the sum, over the plant's contacts between this body and others, of
each contact force's component along the support normal (those that push the body off the
support; a body pressing from above counts through the floor's reaction). It comes from the
plant's **sampled** contact results (``use_sampled_output_ports``, Drake's default for a
discrete plant): the forces of the step that produced the current state. That port has no
direct feedthrough from the applied forces, so there is no algebraic loop (an unsampled
plant's contact results depend on the applied forces: the loop is real, and a ValueError says
so). At the first step after :meth:`Simulator.Initialize <pydrake.systems.analysis.Simulator>`
the sampled results are still empty; N is then ``initial_normal``, by default m g cos(tilt)
(gravity's component along the support normal: a body resting on the support). Pass
``initial_normal=0`` for a body that starts off the support.

Loads. ``SteppedFriction`` needs the planar wrench f of everything else on the body over the
step (for the stick decision). This adapter gives its known part (gravity's tangential
component and the forces of the ``applied_spatial_force`` input, exact for the current step);
``SteppedFriction`` estimates the rest (other contacts, generalized forces) from the previous
step, M (ν_k − ν_{k−1})/h − W_{k−1} − f_known,k−1: exact for loads the adapter sees, one
step late for the others.

The body's own tangential friction in Drake must be zero (slidespin supplies it): give its
collision geometries ``CoulombFriction(0, 0)`` (Drake combines friction coefficients
pairwise as 2 μ₁μ₂/(μ₁+μ₂), so a frictionless body has frictionless contacts whatever the
floor's). With ``scene_graph`` (which :func:`add_patch_friction` finds in the builder) a
ValueError names any collision geometry of the body with nonzero friction.

Engine state. The coupling keeps the previous step (for the load estimate) in Python, not
in the Drake context: it is reset at ``Simulator.Initialize()``; call :meth:`PatchFriction.reset`
after you change the context's state by hand (a launch velocity), or the change is read as a
one-step load.

May import: :mod:`slidespin.engines` (and below), pydrake.
"""

from __future__ import annotations

import math
import warnings
from typing import NamedTuple

import numpy as np

try:
    from pydrake.common.value import AbstractValue
    from pydrake.geometry import (
        AddCompliantHydroelasticProperties,
        AddContactMaterial,
        AddRigidHydroelasticProperties,
        Box,
        Cylinder,
        HalfSpace,
        ProximityProperties,
        SceneGraph,
    )
    from pydrake.math import RigidTransform, RollPitchYaw, RotationMatrix
    from pydrake.multibody.math import SpatialForce, SpatialVelocity
    from pydrake.multibody.plant import (
        AddMultibodyPlant,
        ContactResults,
        CoulombFriction,
        ExternallyAppliedSpatialForce,
        MultibodyPlant,
        MultibodyPlantConfig,
    )
    from pydrake.multibody.tree import (
        ModelInstanceIndex,
        RigidBody,
        SpatialInertia,
        UnitInertia,
    )
    from pydrake.systems.framework import Diagram, DiagramBuilder, LeafSystem
except ImportError as exc:  # pragma: no cover - exercised only without the extra
    raise ImportError(
        'slidespin.drake needs Drake (pydrake): pip install "slidespin[drake]"'
    ) from exc

from slidespin import _validate as v
from slidespin.contact.body import Body
from slidespin.contact.friction import FrictionTensor
from slidespin.engines._coupling import SteppedFriction, check_coupled
from slidespin.engines.scenes import prism_parts

__all__ = [
    "ExampleDiagram",
    "PatchFriction",
    "add_patch_friction",
    "example_diagram",
    "set_planar_state",
]


def _find_body(plant: MultibodyPlant, body) -> RigidBody:
    """The plant's RigidBody for ``body`` (a RigidBody of this plant or its name)."""
    if isinstance(body, str):
        try:
            found = plant.GetBodyByName(body)
        except RuntimeError as exc:
            names = sorted(plant.get_body(i).name() for i in _body_indices(plant))
            raise ValueError(
                f"body = {body!r} is invalid: no unique body of that name in the plant; valid "
                f"values: one of {names[:20]} (or its RigidBody)"
            ) from exc
        body = found
    if not isinstance(body, RigidBody):
        raise TypeError(
            f"body = {body!r} is invalid; valid values: a RigidBody of the plant or its name"
        )
    index = body.index()
    if body.GetParentPlant() is not plant:
        raise ValueError(
            f"body = {body.name()!r} is invalid: it is a body of another plant; valid "
            "values: a RigidBody of the plant given as ``plant`` (or its name)"
        )
    if index == plant.world_body().index():
        raise ValueError(
            "body = 'world' is invalid: the world body does not slide; valid values: a "
            "moving body of the plant"
        )
    return body


def _body_indices(plant: MultibodyPlant) -> list:
    out = []
    for m in range(plant.num_model_instances()):
        out.extend(plant.GetBodyIndices(ModelInstanceIndex(m)))
    return out


def _check_plant(plant) -> None:
    if not isinstance(plant, MultibodyPlant):
        raise TypeError(f"plant = {plant!r} is invalid; valid values: a MultibodyPlant")
    if not plant.is_finalized():
        raise ValueError(
            "plant is invalid: it is not finalized; valid values: a finalized discrete "
            "MultibodyPlant (call plant.Finalize() first)"
        )
    if not plant.time_step() > 0.0:
        raise ValueError(
            f"plant.time_step() = {plant.time_step()!r} is invalid: a continuous plant; valid "
            "range: > 0 s (the coupling's stick-slip projection is a per-step law, MODEL §16: "
            "build the plant with MultibodyPlantConfig(time_step=1e-3) or similar)"
        )


def check_frictionless(scene_graph: SceneGraph, plant: MultibodyPlant, body: RigidBody) -> None:
    """Raise ValueError naming every collision geometry of ``body`` whose CoulombFriction is
    not (0, 0) or is missing (Drake would use its default): slidespin supplies the tangential
    friction (MODEL §16), so Drake's own must be off for this body."""
    inspector = scene_graph.model_inspector()
    bad = []
    for gid in plant.GetCollisionGeometriesForBody(body):
        props = inspector.GetProximityProperties(gid)
        mu = None
        if props is not None and props.HasProperty("material", "coulomb_friction"):
            mu = props.GetProperty("material", "coulomb_friction")
        if mu is None:
            bad.append(f"{inspector.GetName(gid)!r} (no coulomb_friction property)")
        elif mu.static_friction() != 0.0 or mu.dynamic_friction() != 0.0:
            bad.append(
                f"{inspector.GetName(gid)!r} (static {mu.static_friction():g}, dynamic "
                f"{mu.dynamic_friction():g})"
            )
    point = [
        inspector.GetName(gid)
        for gid in plant.GetCollisionGeometriesForBody(body)
        if not (
            (props := inspector.GetProximityProperties(gid)) is not None
            and props.HasProperty("hydroelastic", "compliance_type")
        )
    ]
    if point and not bad:
        warnings.warn(
            f"body {body.name()!r}: its collision geometries {point} have no hydroelastic "
            "properties, so Drake resolves the flat contact with point contact, whose few "
            "points come and go from step to step: the normal force, and with it the "
            "coupled friction, jumps (a box measured 5 % off); give them compliant "
            "hydroelastic properties (AddCompliantHydroelasticProperties, as "
            "example_diagram does)",
            UserWarning,
            stacklevel=3,
        )
    if bad:
        raise ValueError(
            f"body {body.name()!r} is invalid for the coupling: its collision geometries "
            f"{', '.join(bad)} have Drake friction; valid values: CoulombFriction(0, 0) on "
            "every collision geometry of the body (AddContactMaterial(friction="
            "CoulombFriction(0.0, 0.0), ...)): slidespin supplies the tangential friction "
            "(MODEL §16)"
        )


class PatchFriction(LeafSystem):
    """The exact friction of a flat contact patch, as a Drake system (MODEL §16).

    Parameters
    ----------
    plant : MultibodyPlant
        A finalized **discrete** plant (its ``time_step()`` is the coupling's step h; a
        continuous plant raises ValueError).
    body : RigidBody or str
        The sliding body of ``plant`` (or its name). Its frame's z axis is the footprint's
        normal, its x axis the footprint's ξ axis.
    slidespin_body : Body
        The thin slidespin body (footprint, pressure law; ``height`` 0). Its mass is not used:
        the plant's mass m and moment of inertia about the body's z axis through its mass
        centre (the default spatial inertia) enter the stick projection.
    friction : FrictionTensor
        The friction tensor (constant law, ``static`` ≥ 1 allowed). A plane-frame tensor's
        axes are the support frame's x, y axes.
    support : RigidTransform or None
        X_WS, the fixed support plane (z axis the normal, origin on the plane). None: the
        world's z = 0 plane.
    scene_graph : SceneGraph or None
        If given, the body's collision geometries are checked for zero Drake friction
        (ValueError otherwise).
    initial_normal : float or None
        The normal force [N] of the first step after initialization, when the sampled contact
        results are still empty. None: m g cos(tilt), gravity's component along the support
        normal.
    normal_force : float or None
        None (default): N from the plant's sampled contact results (input port
        ``contact_results``; needs ``use_sampled_output_ports``). A float: a constant N [N]
        and no contact-results port (e.g. for a plant without sampled ports).

    Notes
    -----
    Input ports: ``body_poses``, ``body_spatial_velocities`` (the plant's), ``contact_results``
    (unless ``normal_force`` is given) and ``applied_spatial_force`` (optional: a list of
    ExternallyAppliedSpatialForce, passed through to the output and counted as a known load).
    Output port ``spatial_forces``: the list for ``plant.get_applied_spatial_force_input_port()``.
    Attributes ``coupling`` (the :class:`~slidespin.engines._coupling.SteppedFriction`; ``coupling.state`` is ``"slip"``,
    ``"stick"`` or ``"free"``), ``body_index``, ``normal`` (the last normal force [N]) and
    ``wrench`` (the last (Fx, Fy, M)).
    """

    def __init__(
        self,
        plant: MultibodyPlant,
        body,
        slidespin_body: Body,
        friction: FrictionTensor,
        *,
        support: RigidTransform | None = None,
        scene_graph: SceneGraph | None = None,
        initial_normal: float | None = None,
        normal_force: float | None = None,
    ) -> None:
        super().__init__()
        _check_plant(plant)
        body = _find_body(plant, body)
        check_coupled(slidespin_body, friction)
        if support is None:
            support = RigidTransform()
        if not isinstance(support, RigidTransform):
            raise TypeError(
                f"support = {support!r} is invalid; valid values: a RigidTransform X_WS or None"
            )
        if scene_graph is not None:
            if not isinstance(scene_graph, SceneGraph):
                raise TypeError(
                    f"scene_graph = {scene_graph!r} is invalid; valid values: the plant's "
                    "SceneGraph or None"
                )
            check_frictionless(scene_graph, plant, body)
        self.plant = plant
        self.body = body
        self.body_index = body.index()
        self._i = int(self.body_index)
        self.slidespin_body = slidespin_body
        self.friction = friction
        R = support.rotation().matrix()
        self._S = R[:, :2].copy()  # the plane's x, y axes in W
        self._n = R[:, 2].copy()  # its normal in W
        self._o = support.translation().copy()
        # mass, mass centre and moment of inertia about the body's z axis through it
        m = float(body.default_mass())
        p_com = np.asarray(body.default_com(), dtype=float)
        I_o = body.default_rotational_inertia().CopyToFullMatrix3()
        I_c = I_o - m * (np.dot(p_com, p_com) * np.eye(3) - np.outer(p_com, p_com))
        if not m > 0.0:
            raise ValueError(
                f"body {body.name()!r} has mass {m!r}, which is invalid; valid range: > 0 kg"
            )
        self.mass, self.inertia, self._p_com = m, float(I_c[2, 2]), p_com
        self.coupling = SteppedFriction(
            slidespin_body, friction, self.mass, self.inertia, float(plant.time_step())
        )
        gvec = np.asarray(plant.gravity_field().gravity_vector(), dtype=float)
        self._gravity = m * np.array([gvec @ self._S[:, 0], gvec @ self._S[:, 1], 0.0])
        if initial_normal is None:
            initial_normal = max(0.0, -m * float(gvec @ self._n))
        self.initial_normal = _nonneg("initial_normal", initial_normal)
        self._fixed_normal = None if normal_force is None else _nonneg("normal_force", normal_force)
        self._geometries = set(plant.GetCollisionGeometriesForBody(body))

        self._poses = self.DeclareAbstractInputPort(
            "body_poses", plant.get_body_poses_output_port().Allocate()
        )
        self._velocities = self.DeclareAbstractInputPort(
            "body_spatial_velocities", plant.get_body_spatial_velocities_output_port().Allocate()
        )
        if self._fixed_normal is None:
            if not plant.has_sampled_output_ports():
                raise ValueError(
                    "plant is invalid for normal_force=None: its output ports are not sampled, "
                    "so its contact results depend on the applied forces this system computes "
                    "(an algebraic loop); valid values: a plant built with "
                    "MultibodyPlantConfig(use_sampled_output_ports=True) (Drake's default), "
                    "or a constant normal_force [N]"
                )
            self._contacts = self.DeclareAbstractInputPort(
                "contact_results", AbstractValue.Make(ContactResults())
            )
        self._applied = self.DeclareAbstractInputPort(
            "applied_spatial_force", AbstractValue.Make([ExternallyAppliedSpatialForce()])
        )
        self.DeclareAbstractOutputPort(
            "spatial_forces",
            lambda: AbstractValue.Make([ExternallyAppliedSpatialForce()]),
            self._calc,
        )
        self.DeclareInitializationPublishEvent(self._on_init)
        self.normal = 0.0
        self.wrench = np.zeros(3)
        self.reset()
        self._first = True

    # -- state kept outside the context ------------------------------------------------
    def reset(self) -> None:
        """Forget the previous step: call it after changing the context's state by hand (a
        launch velocity), so that the change is not read as a load. The normal force still
        comes from the contact results (``initial_normal`` serves only the first step after
        ``Simulator.Initialize()``, which calls this too)."""
        self.coupling.reset()
        self._first = False
        self._cur: tuple | None = None  # (t, nu, w) of the last step

    def _on_init(self, context) -> None:
        self.reset()
        self._first = True

    @property
    def stop_time(self) -> float:
        """The time [s] at which the last slip stopped, interpolated within its step by
        :class:`~slidespin.engines._coupling.SteppedFriction` (NaN before any stop)."""
        return float(getattr(self.coupling, "stop_time", math.nan))

    # -- ports --------------------------------------------------------------------------
    def get_body_poses_input_port(self):
        """Input: the plant's ``get_body_poses_output_port()``."""
        return self.GetInputPort("body_poses")

    def get_body_spatial_velocities_input_port(self):
        """Input: the plant's ``get_body_spatial_velocities_output_port()``."""
        return self.GetInputPort("body_spatial_velocities")

    def get_contact_results_input_port(self):
        """Input: the plant's (sampled) ``get_contact_results_output_port()``."""
        return self.GetInputPort("contact_results")

    def get_applied_spatial_force_input_port(self):
        """Input (optional): other forces for the plant, passed through and counted."""
        return self.GetInputPort("applied_spatial_force")

    def get_spatial_forces_output_port(self):
        """Output: the list for ``plant.get_applied_spatial_force_input_port()``."""
        return self.GetOutputPort("spatial_forces")

    # -- the step -----------------------------------------------------------------------
    def _normal_force(self, context) -> float:
        if self._fixed_normal is not None:
            return self._fixed_normal
        cr = self._contacts.Eval(context)
        n, total, seen = self._n, 0.0, False
        mine = self._geometries
        for i in range(cr.num_hydroelastic_contacts()):
            info = cr.hydroelastic_contact_info(i)
            s = info.contact_surface()
            a, b = s.id_M() in mine, s.id_N() in mine
            if a == b:
                continue
            f = np.asarray(info.F_Ac_W().translational()) * (1.0 if a else -1.0)
            seen = True
            total += max(0.0, float(f @ n))
        for i in range(cr.num_point_pair_contacts()):
            info = cr.point_pair_contact_info(i)
            a = info.bodyA_index() == self.body_index
            b = info.bodyB_index() == self.body_index
            if a == b:
                continue
            f = np.asarray(info.contact_force()) * (1.0 if b else -1.0)  # on body B
            seen = True
            total += max(0.0, float(f @ n))
        if not seen and self._first:
            return self.initial_normal
        return total

    def _calc(self, context, output) -> None:
        t = float(context.get_time())
        X_WB = self._poses.Eval(context)[self._i]
        V_WB = self._velocities.Eval(context)[self._i]
        port = self._applied
        applied = list(port.Eval(context)) if port.HasValue(context) else []
        R_WB = X_WB.rotation().matrix()
        p_BoG_W = R_WB @ self._p_com
        p_WG = X_WB.translation() + p_BoG_W
        w_W = np.asarray(V_WB.rotational())
        v_WG = np.asarray(V_WB.translational()) + _cross(w_W, p_BoG_W)
        S, n = self._S, self._n
        nu = np.array([v_WG @ S[:, 0], v_WG @ S[:, 1], w_W @ n])
        xb = R_WB[:, 0]
        phi = math.atan2(float(xb @ S[:, 1]), float(xb @ S[:, 0]))
        # the known planar load: gravity along the plane and the applied forces on the body
        known = self._gravity.copy()
        for f in applied:
            if f.body_index != self.body_index:
                continue
            F = f.F_Bq_W
            p_WQ = X_WB.translation() + R_WB @ np.asarray(f.p_BoBq_B)
            force = np.asarray(F.translational())
            moment = np.asarray(F.rotational()) + _cross(p_WQ - p_WG, force)
            known += np.array([force @ S[:, 0], force @ S[:, 1], moment @ n])
        cur, h = self._cur, self.coupling.dt
        off_grid = abs(t / h - round(t / h)) > 1e-6  # not a plant step: a publish, a monitor
        if cur is not None and (off_grid or (cur[0] == t and np.array_equal(cur[1], nu))):
            w = cur[2]
        else:
            normal = self._normal_force(context)
            # the loads this system does not see (other contacts) the coupling takes from
            # the step before; gravity and the applied forces are known now
            w = self.coupling.step(t, nu, phi, normal, known=known)
            self._cur = (t, nu, np.array(w, dtype=float))
            self._first = False
            self.normal, self.wrench = normal, np.array(w, dtype=float)
        out = list(applied)
        if np.any(w != 0.0):
            d = float((p_WG - self._o) @ n)
            p_WQ = p_WG - d * n  # the point of the plane below G
            force = S[:, 0] * w[0] + S[:, 1] * w[1]
            f = ExternallyAppliedSpatialForce()
            f.body_index = self.body_index
            f.p_BoBq_B = R_WB.T @ (p_WQ - X_WB.translation())
            f.F_Bq_W = SpatialForce(tau=n * w[2], f=force)
            out.append(f)
        output.set_value(out)


def _cross(a, b) -> np.ndarray:
    """a × b of two 3-vectors (np.cross costs ten times more for one pair)."""
    return np.array(
        [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
    )


def _nonneg(name: str, value) -> float:
    x = v.finite(name, value)
    if x < 0.0:
        raise ValueError(f"{name} = {value!r} is invalid; valid range: >= 0 N")
    return x


def _scene_graph_of(builder: DiagramBuilder) -> SceneGraph | None:
    for system in builder.GetSystems():
        if isinstance(system, SceneGraph):
            return system
    return None


def add_patch_friction(
    builder: DiagramBuilder,
    plant: MultibodyPlant,
    body,
    slidespin_body: Body,
    friction: FrictionTensor,
    **kwargs,
) -> PatchFriction:
    """Add a :class:`PatchFriction` to ``builder`` and connect it to ``plant`` (MODEL §16).

    Connects the plant's body poses, spatial velocities and (sampled) contact results to the
    system and its ``spatial_forces`` output to ``plant.get_applied_spatial_force_input_port()``
    (which must not be connected yet: route other spatial forces through the system's
    ``applied_spatial_force`` input instead). The builder's SceneGraph, if any, is used to
    check that the body's collision geometries are frictionless in Drake. Keyword arguments
    go to :class:`PatchFriction` (``support``, ``initial_normal``, ``normal_force``).
    """
    if not isinstance(builder, DiagramBuilder):
        raise TypeError(f"builder = {builder!r} is invalid; valid values: a DiagramBuilder")
    kwargs.setdefault("scene_graph", _scene_graph_of(builder))
    patch = builder.AddSystem(PatchFriction(plant, body, slidespin_body, friction, **kwargs))
    patch.set_name(f"slidespin_patch_friction_{patch.body.name()}")
    builder.Connect(plant.get_body_poses_output_port(), patch.get_body_poses_input_port())
    builder.Connect(
        plant.get_body_spatial_velocities_output_port(),
        patch.get_body_spatial_velocities_input_port(),
    )
    if patch._fixed_normal is None:
        builder.Connect(
            plant.get_contact_results_output_port(), patch.get_contact_results_input_port()
        )
    builder.Connect(
        patch.get_spatial_forces_output_port(), plant.get_applied_spatial_force_input_port()
    )
    return patch


# -- the example scene ------------------------------------------------------------------
class ExampleDiagram(NamedTuple):
    """What :func:`example_diagram` returns: the built diagram, its plant, scene graph, the
    sliding body, the coupling system, the prisms' thickness [m] and the support plane X_WS
    (for :func:`set_planar_state`)."""

    diagram: Diagram
    plant: MultibodyPlant
    scene_graph: SceneGraph
    body: RigidBody
    patch: PatchFriction
    thickness: float
    support: RigidTransform


def example_diagram(
    slidespin_body: Body,
    friction: FrictionTensor,
    time_step: float = 1e-3,
    *,
    thickness: float | None = None,
    incline: float = 0.0,
    hydroelastic_modulus: float = 1e7,
    hunt_crossley_dissipation: float = 20.0,
    name: str = "body",
) -> ExampleDiagram:
    """A flat body on a floor (a rigid half space tilted by ``incline`` about the world y
    axis; downhill is the plane's +x) with the coupling, as a Drake diagram (MODEL §16).

    The body's geometry is the prisms of :func:`slidespin.engines.scenes.prism_parts` (boxes
    and cylinders; a mesh outline raises ValueError) of thickness ``thickness``, compliant
    hydroelastic with zero Drake friction; its frame origin is G, its inertia the slidespin
    body's mass and moment of inertia about the normal (and a plate's about the horizontal
    axes). The plant uses Drake's defaults otherwise (SAP "lagged", sampled output ports).
    Start it with :func:`set_planar_state`::

        ex = example_diagram(body, friction)
        sim = Simulator(ex.diagram)
        pc = ex.plant.GetMyMutableContextFromRoot(sim.get_mutable_context())
        set_planar_state(ex.plant, pc, ex.body, ss.State(), height=ex.thickness / 2,
                         support=ex.support)
        sim.Initialize()
        sim.AdvanceTo(0.05)  # settle into the soft contact
        z = ex.support.inverse().multiply(ex.plant.GetFreeBodyPose(pc, ex.body).translation())[2]
        set_planar_state(ex.plant, pc, ex.body, ss.State(vx=1.0, omega=20.0), height=z,
                         support=ex.support)
        ex.patch.reset()  # the launch is a change of state, not a load
        sim.AdvanceTo(1.0)

    Parameters
    ----------
    slidespin_body, friction : Body, FrictionTensor
        The thin body and its tensor.
    time_step : float
        The plant's step [s], > 0.
    thickness : float or None
        Prism thickness [m]; None: 0.2 × the body's length unit.
    incline : float
        Tilt of the floor [rad], in [0, π/2).
    hydroelastic_modulus : float
        The body's hydroelastic modulus [Pa], > 0.
    hunt_crossley_dissipation : float
        The body's Hunt–Crossley dissipation [s/m], >= 0.
    name : str
        The body's name in the plant.
    """
    check_coupled(slidespin_body, friction)
    h = v.positive("time_step", time_step, "s")
    ell = slidespin_body.length_unit
    t = 0.2 * ell if thickness is None else v.positive("thickness", thickness, "m")
    alpha = v.bounded("incline", incline, 0.0, math.pi / 2 * (1 - 1e-9), "rad")
    modulus = v.positive("hydroelastic_modulus", hydroelastic_modulus, "Pa")
    hc = _nonneg_s("hunt_crossley_dissipation", hunt_crossley_dissipation)
    parts = prism_parts(slidespin_body)
    for kind, *_ in parts:
        if kind == "mesh":
            raise ValueError(
                f"slidespin_body.patch = {slidespin_body.patch!r} is invalid for the Drake "
                "example scene; valid values: a rectangle, a disk, a ring or pads of them "
                "(build the Drake geometry of an ellipse or a polygon yourself)"
            )
    builder = DiagramBuilder()
    plant, scene_graph = AddMultibodyPlant(MultibodyPlantConfig(time_step=h), builder)
    floor = ProximityProperties()
    AddRigidHydroelasticProperties(properties=floor)
    AddContactMaterial(friction=CoulombFriction(0.0, 0.0), properties=floor)
    X_WS = RigidTransform(RollPitchYaw(0.0, alpha, 0.0), np.zeros(3))
    plant.RegisterCollisionGeometry(plant.world_body(), X_WS, HalfSpace(), "floor", floor)
    m = float(slidespin_body.mass)
    izz = slidespin_body.moment_of_inertia
    if izz is None:
        izz = slidespin_body._inertia
    ixx = 0.5 * izz + m * t * t / 12.0
    body = plant.AddRigidBody(
        name, SpatialInertia(m, np.zeros(3), UnitInertia(ixx / m, ixx / m, izz / m))
    )
    props = ProximityProperties()
    AddCompliantHydroelasticProperties(
        resolution_hint=ell / 2.0, hydroelastic_modulus=modulus, properties=props
    )
    AddContactMaterial(dissipation=hc, friction=CoulombFriction(0.0, 0.0), properties=props)
    for k, (kind, c, ang, size) in enumerate(parts):
        X_BP = RigidTransform(RollPitchYaw(0.0, 0.0, ang), [c[0], c[1], 0.0])
        shape = Box(2 * size[0], 2 * size[1], t) if kind == "box" else Cylinder(size[0], t)
        plant.RegisterCollisionGeometry(body, X_BP, shape, f"{name}_{k}", props)
    plant.Finalize()
    patch = add_patch_friction(builder, plant, body, slidespin_body, friction, support=X_WS)
    diagram = builder.Build()
    return ExampleDiagram(diagram, plant, scene_graph, body, patch, t, X_WS)


def _nonneg_s(name: str, value) -> float:
    x = v.finite(name, value)
    if x < 0.0:
        raise ValueError(f"{name} = {value!r} is invalid; valid range: >= 0 s/m")
    return x


def set_planar_state(
    plant: MultibodyPlant,
    plant_context,
    body,
    state,
    *,
    height: float,
    support: RigidTransform | None = None,
) -> None:
    """Put a free body flat on the support plane in a slidespin ``State``.

    G at (x, y) in the plane frame and ``height`` [m] along its normal (half the prism
    thickness for :func:`example_diagram`), the body's z axis along the normal, its x axis
    at angle φ, and the twist (vx, vy, ω) of G; ``support`` = X_WS as in :class:`PatchFriction`
    (for :func:`example_diagram` with an incline α: ``RigidTransform(RollPitchYaw(0, α, 0),
    [0, 0, 0])``). Assumes the body's frame origin is its mass centre.
    """
    body = _find_body(plant, body)
    X_WS = RigidTransform() if support is None else support
    R_WS = X_WS.rotation()
    p_SG = np.array([state.x, state.y, float(height)])
    X_WB = RigidTransform(
        R_WS.multiply(RotationMatrix.MakeZRotation(state.phi)), X_WS.multiply(p_SG)
    )
    plant.SetFreeBodyPose(plant_context, body, X_WB)
    R = R_WS.matrix()
    plant.SetFreeBodySpatialVelocity(
        plant_context,
        body,
        SpatialVelocity(
            w=R @ np.array([0.0, 0.0, state.omega]), v=R @ np.array([state.vx, state.vy, 0.0])
        ),
    )
