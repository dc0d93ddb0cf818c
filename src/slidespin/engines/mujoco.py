"""slidespin's exact patch friction inside MuJoCo (MODEL §16): ``attach`` and ``detach``.

After ``attach(model, data, "box", body, friction)`` a plain ``mujoco.mj_step(model, data)``
steps the scene with slidespin's friction on that body's flat contact with its support:

* **The engine's own friction is switched off for that pair**: the body's geoms get condim 1
  and the support's geoms a priority below theirs, so the body–support contacts are
  frictionless normal contacts; contacts of the body with anything else (a finger, another
  body) keep their condim and friction (equal priorities: MuJoCo's max rule). ``detach``
  restores both. (The support's contacts with other geoms then take the other geom's
  condim and friction instead of the maximum of the two: the same whenever the support's
  friction is not above theirs.)
* **Each step** a passive-force callback (``mujoco.set_mjcb_passive``, a ctypes function
  pointer, so that models still compile while bodies are attached; a callback already set is
  chained, called first) reads the body's planar twist relative to its support, its angle
  and the normal force, asks :class:`slidespin.engines._coupling.SteppedFriction` for the
  wrench (the exact W(ν) in slip; the discrete projection onto the static set where the slip
  would stop within the step) and adds it to ``data.qfrc_passive`` with ``mj_applyFT``: the
  force at the point of the contact plane below the mass centre (so the engine sees the right
  tipping moment), the moment about the plane's normal.

Why a passive callback: ``xfrc_applied`` is the user's (a push, a controller) and would have
to be re-set before every step by the user; an engine plugin would need a compiled C++ build
against each MuJoCo release; the passive callback runs inside ``mj_step`` (and ``mj_forward``)
after the collision and before the constraint solve, which is when the wrench is known, and
costs one Python call per step.

**Cost.** A *steady* step (the same contact as in the step before, a normal force changing by
less than 1 %, a slip whose implicit midpoint converges, or a rest that the cheap bound on the
static set confirms: nearly every step of a slide or a rest) is done whole by one compiled
call (:mod:`slidespin.engines._stepcore`, in the ahead-of-time core), which reads MuJoCo's
arrays in place and adds the wrench to ``qfrc_passive`` itself, usually with one wrench
evaluation: 2.5–5.5 µs per body and step in all, sliding or at rest, measured
(``benchmarks/engines/engines_bench.py``). Any other step (a first contact, a launch or a
kick, a touchdown, a stop within the step, a breakaway, a gauge the bounds cannot decide, a
moving support) is done by the Python path below, from the same state (the tests run every
scene both ways and compare them step by step).

**The normal force** N is the engine's: the normal component of the constraint force on the
body in the previous step (``data.qfrc_constraint`` of its free joint, along the support's
normal; a push with a component along the normal adds to it, as it loads the contact). At the
first step of a contact (and after a reset) there is no previous step: the callback runs one
``mj_forward`` on a copy of ``data`` without the friction, which gives that step's normal force
and the planar load of everything else (gravity, pushes, actuators, other contacts), so the
first step already sticks or slips correctly.

**Frames.** The support's plane frame: its normal n from the contacts (from the support to the
body), its x axis the support geom's x axis projected on the plane; a plane-frame friction
tensor's axes are those. The body's footprint is in the MuJoCo body's frame: its ξ axis is the
body's local x axis (projected on the plane), its pressure centroid under the body's centre
of mass. The mass and the moment of inertia about the normal are MuJoCo's (those it
integrates with); the footprint and the pressure law are the :class:`slidespin.Body`'s.

Requirements: a free body (a ``freejoint``), the Euler or implicit integrators (RK4 evaluates
the forces at intermediate states, which the discrete projection does not allow: refused),
and a thin ``Body`` with a constant friction law (``static`` ≥ 1 allowed).
"""

from __future__ import annotations

import copy
import ctypes
import math
import warnings
import weakref
from pathlib import Path
from typing import Any

import numpy as np

from slidespin import _aot
from slidespin import _validate as v
from slidespin.contact.body import Body
from slidespin.contact.friction import FrictionTensor
from slidespin.engines import _stepcore as sc
from slidespin.engines._coupling import Held, SteppedFriction, check_coupled
from slidespin.studies.case import Case, load_case

try:
    import mujoco
except ImportError as exc:  # pragma: no cover - the extra is installed in CI
    raise ImportError(
        'slidespin.mujoco needs MuJoCo: pip install "slidespin[mujoco]" (or pip install mujoco)'
    ) from exc

__all__ = ["Coupling", "attach", "attached", "detach", "set_twist"]

#: the engine's normal force is steady when it changes by less than this from one step to the
#: next: the previous step's is then used; else (a touchdown, a bounce) this step's own, from a
#: frictionless ``mj_forward`` on a copy of the data
_STEADY = sc.STEADY
_RK4 = int(mujoco.mjtIntegrator.mjINT_RK4)

#: data address → (weak reference to the data, weak reference to its model, {body id →
#: Coupling}); the references tell a data freed without ``detach`` from a new one at the same
#: address
_ATTACHED: dict[int, tuple[weakref.ref, weakref.ref, dict[int, Coupling]]] = {}
#: model address → {geom id → (condim, priority) before the first attach}
_SAVED: dict[int, tuple[weakref.ref, dict[int, tuple[int, int]]]] = {}
_CHAINED: list = []  # the passive callback that was set before ours (at most one)
_CALLBACK = ctypes.CFUNCTYPE(None, ctypes.c_void_p, ctypes.c_void_p)
#: the class of ctypes function pointers (what ``get_mjcb_passive`` returns for a C callback)
_CFUNCPTR: Any = ctypes._CFuncPtr  # type: ignore[attr-defined]


def _raw_passive(m_ptr, d_ptr) -> None:
    """MuJoCo's passive callback, called with raw pointers (a ctypes function pointer).

    A Python callable set with ``set_mjcb_passive`` is called through Python wrappers of the
    model and data, which MuJoCo's compiler does not have for the data it steps while it
    compiles a model: with one set, ``MjModel.from_xml_string`` fails. Through raw pointers
    the callback looks the data up among the coupled ones and returns at once for any other,
    so models compile while bodies are attached."""
    prev = _CHAINED[0] if _CHAINED else None
    if prev is not None and isinstance(prev, _CFUNCPTR):
        prev(m_ptr, d_ptr)
    entry = _ATTACHED.get(d_ptr)
    if entry is None:
        return
    d, m = entry[0](), entry[1]()
    if d is None or m is None or m._address != m_ptr:
        return
    if prev is not None and not isinstance(prev, _CFUNCPTR):
        prev(m, d)  # a Python callback set before: for the coupled data (it has wrappers)
    try:
        for c in entry[2].values():
            c._apply(m, d)
    except Exception as exc:  # an exception cannot cross MuJoCo's C stack: say it loudly
        for c in entry[2].values():
            c.error = exc
        warnings.warn(
            f"slidespin.mujoco: the coupling failed in this step ({type(exc).__name__}: {exc}); "
            "no friction was applied; Coupling.error holds the exception",
            RuntimeWarning,
            stacklevel=1,
        )


_PASSIVE = _CALLBACK(_raw_passive)  # kept alive here: MuJoCo holds only its address


class Coupling:
    """One body coupled to slidespin's friction in one ``(model, data)`` (returned by
    :func:`attach`).

    Attributes
    ----------
    body_name : str
        The MuJoCo body.
    friction : SteppedFriction
        The step's core: its ``state`` (``"slip"``, ``"stick"`` or ``"free"``) and its
        counters.
    wrench : (float, float, float)
        The last wrench (Fx, Fy [N] along the support's axes, M [N m] about its normal).
    normal_force : float
        The last normal force N [N].
    error : Exception or None
        An exception the coupling met in a step (the step then applied no friction, and a
        RuntimeWarning said so: an exception cannot cross MuJoCo's C stack); None.
    compiled : bool
        Whether steady steps go to the compiled steady step (default True); False does every
        step in Python (the same numbers to round-off, 5–8 times the cost: for comparisons).
    s : ndarray
        The state of the body's coupling (that of ``friction``), read and written by the
        compiled steady step.
    """

    @property
    def wrench(self) -> tuple[float, float, float]:
        """The last wrench (Fx, Fy [N] along the support's axes, M [N m] about its normal)."""
        return self.friction._w

    @property
    def normal_force(self) -> float:
        """The last normal force N [N]."""
        return float(self.s[sc.C_NORMAL])

    @normal_force.setter
    def normal_force(self, value: float) -> None:
        self.s[sc.C_NORMAL] = value

    #: (time, N used, the engine's N of the step before it, read then) of the last step in
    #: contact, or None; the normal force taken ahead of the engine's (a first step's
    #: weight); the body's weight m g [N] (world frame)
    _last = Held(sc.C_LAST_T, 3, sc.C_LAST_OK)
    _debt = Held(sc.C_DEBT)
    _weight = Held(sc.C_WEIGHT, 3)

    def __init__(self, model, data, body_id: int, body: Body, friction: FrictionTensor, support):
        self.body_name = model.body(body_id).name
        self.body_id = body_id
        self._model_address = model._address
        self.dof = int(model.jnt_dofadr[model.body_jntadr[body_id]])
        self.geoms = np.arange(
            model.body_geomadr[body_id], model.body_geomadr[body_id] + model.body_geomnum[body_id]
        )
        self.support = np.asarray(support, dtype=int)
        mujoco.mj_kinematics(model, data)
        mass = float(model.body_mass[body_id])
        # the moment of inertia about the support normal (the body's local z at attach)
        rot = data.ximat[body_id].reshape(3, 3)
        inertia_world = rot @ np.diag(model.body_inertia[body_id]) @ rot.T
        zb = data.xmat[body_id].reshape(3, 3)[:, 2]
        izz = float(zb @ inertia_world @ zb)
        self.friction = SteppedFriction(body, friction, mass, izz, float(model.opt.timestep))
        self.s = self.friction.s  # the state, shared with the compiled steady step
        self.normal_force = 0.0
        self._last = None
        self._bset = {int(g) for g in self.geoms}
        self._sset = {int(g) for g in self.support}
        self._frames: dict[int, tuple] = {}
        self._movers: dict[int, int] = {}
        self._force, self._torque, self._point = np.zeros(3), np.zeros(3), np.zeros(3)
        self._res = np.zeros(6)
        self.error: Exception | None = None
        self._warned_rk4 = False
        self._weight = tuple((mass * model.opt.gravity).tolist())
        self._debt = 0.0
        # the compiled steady step (slidespin.engines._stepcore) and its arguments: MuJoCo's
        # arrays of this data (views of its buffers, which do not move), the kernel's
        tw = self.friction.tw
        self._arrays = (
            data.qvel, data.xmat, data.xipos, data.xpos, data.qfrc_constraint,
            data.qfrc_applied, data.xfrc_applied, data.qfrc_passive,
        )  # fmt: skip
        self._kernel_args = (tw.par, tw.edges, tw.circles, tw.geo) if tw.footprint else (tw.par,)
        self._steady = steady_kernel(tw.footprint)
        self.compiled = True

    def _frame(self, m, d, i: int, sg: int, sign: float):
        """(n, e1, e2, point on the plane) of the support at contact ``i`` (support geom
        ``sg``; ``sign`` turns the contact normal to point from the support to the body).
        Kept for a support fixed in the world (its plane does not move)."""
        cached = self._frames.get(sg)
        if cached is not None:
            return cached
        con = d.contact
        n = sign * np.array(con.frame[i, :3])
        n /= np.linalg.norm(n)
        ax = d.geom_xmat[sg].reshape(3, 3)
        e1 = ax[:, 0] - (ax[:, 0] @ n) * n
        if np.linalg.norm(e1) < 1e-6:  # the support's x axis along the normal: its y axis
            e1 = ax[:, 1] - (ax[:, 1] @ n) * n
        e1 /= np.linalg.norm(e1)
        e2 = np.cross(n, e1)
        out = (tuple(n.tolist()), tuple(e1.tolist()), tuple(e2.tolist()), tuple(con.pos[i]))
        if _fixed_in_world(m, int(m.geom_bodyid[sg])):
            self._frames[sg] = out
        return out

    def _free(self, d) -> None:
        self.friction.airborne(d.time)
        self.normal_force = 0.0
        self._last = None

    def _apply(self, m, d) -> None:
        if d.ncon == 0:
            return self._free(d)
        pairs = d.contact.geom
        opt = m.opt
        if (  # a steady step: compiled, from MuJoCo's arrays to qfrc_passive
            self.compiled
            and opt.integrator != _RK4
            and self._steady(
                *self._arrays,
                pairs,
                self.body_id,
                self.dof,
                d.time,
                opt.timestep,
                self.s,
                *self._kernel_args,
            )  # fmt: skip
            == sc.DONE
        ):
            return None
        bset, sset = self._bset, self._sset
        found = -1
        for i, (g1, g2) in enumerate(pairs.tolist()):
            if g1 in sset and g2 in bset:
                found, sg, sign = i, g1, 1.0
                break
            if g1 in bset and g2 in sset:
                found, sg, sign = i, g2, -1.0
                break
        if found < 0:
            return self._free(d)
        frame = self._frame(m, d, found, sg, sign)
        (n0, n1, n2), (a0, a1, a2), (c0, c1, c2), pc = frame
        # the contact found, for the compiled steady step of the next step: its geom pair,
        # and its support's frame if the support is static
        st = self.s
        st[sc.C_CI] = found
        st[sc.C_G1], st[sc.C_G2] = pairs[found]
        st[sc.C_FRAME_OK] = 0.0
        if sg in self._frames and not self._support_body(m, sg):
            st[sc.C_N : sc.C_N + 3], st[sc.C_E1 : sc.C_E1 + 3] = frame[0], frame[1]
            st[sc.C_E2 : sc.C_E2 + 3], st[sc.C_PC : sc.C_PC + 3] = frame[2], frame[3]
            st[sc.C_FRAME_OK] = 1.0
        b, a = self.body_id, self.dof
        gx, gy, gz = d.xipos[b].tolist()
        ox, oy, oz = d.xpos[b].tolist()
        r00, r01, r02, r10, r11, r12, r20, r21, r22 = d.xmat[b].tolist()
        vx, vy, vz, u0, u1, u2 = d.qvel[a : a + 6].tolist()
        # ω in the world frame, and the velocity of G = that of the frame origin + ω × (G − O)
        wx = r00 * u0 + r01 * u1 + r02 * u2
        wy = r10 * u0 + r11 * u1 + r12 * u2
        wz = r20 * u0 + r21 * u1 + r22 * u2
        rx, ry, rz = gx - ox, gy - oy, gz - oz
        vx += wy * rz - wz * ry
        vy += wz * rx - wx * rz
        vz += wx * ry - wy * rx
        sb = self._support_body(m, sg)
        if sb:  # a moving support: the twist relative to it
            res = self._res
            mujoco.mj_objectVelocity(m, d, mujoco.mjtObj.mjOBJ_BODY, sb, res, 0)
            sx, sy, sz = (d.xipos[sb]).tolist()
            p0, p1, p2, q0, q1, q2 = res.tolist()
            dx, dy, dz = gx - sx, gy - sy, gz - sz
            vx -= q0 + p1 * dz - p2 * dy
            vy -= q1 + p2 * dx - p0 * dz
            vz -= q2 + p0 * dy - p1 * dx
            wx, wy, wz = wx - p0, wy - p1, wz - p2
        nu = (
            vx * a0 + vy * a1 + vz * a2,
            vx * c0 + vy * c1 + vz * c2,
            wx * n0 + wy * n1 + wz * n2,
        )
        phi = math.atan2(r00 * c0 + r10 * c1 + r20 * c2, r00 * a0 + r10 * a1 + r20 * a2)
        t = d.time
        opt = m.opt
        h = opt.timestep
        fr = self.friction
        if h != fr.dt:  # the model's step changed since the last step: start afresh
            fr.dt = h
            fr.reset()
            self._last = None
        if opt.integrator == _RK4:
            return self._refuse_rk4()
        load = None
        last = self._last
        if last is not None and last[0] == t:
            normal, lag = last[1], last[2]  # the same step again (mj_forward, then mj_step)
        elif last is not None and abs(t - last[0] - h) <= min(1e-9 * max(h, t), 0.5 * h):
            # the engine's normal force of the step before, while it is steady; while it
            # changes from step to step (a touchdown, a bounce), this step's own
            f0, f1, f2 = d.qfrc_constraint[a : a + 3].tolist()
            lag = f0 * n0 + f1 * n1 + f2 * n2
            if lag > 0.0 and abs(lag - last[2]) <= _STEADY * max(lag, abs(last[2])):
                normal = lag
            else:  # (also when the step before had no reading: last[2] is NaN)
                normal, load = self._dry_run(m, d, (n0, n1, n2), (a0, a1, a2), (c0, c1, c2))
            if self._debt > 0.0 and normal > 0.0:  # repay a first step's weight
                pay = min(self._debt, normal)
                normal -= pay
                self._debt -= pay
        else:
            normal, load = self._dry_run(m, d, (n0, n1, n2), (a0, a1, a2), (c0, c1, c2))
            lag = math.nan
            self._debt = 0.0
            if not normal > 0.0:
                # resting exactly on the support, MuJoCo's soft contact carries no load in
                # its first step and catches up in the next: friction takes the weight's
                # share now and the same from the engine's next loads, so that its normal
                # impulse in all is the engine's, and a launch starts with its half step
                wx0, wx1, wx2 = self._weight
                normal = max(0.0, -(wx0 * n0 + wx1 * n1 + wx2 * n2))
                self._debt = normal
        self._last = (t, normal, lag)
        # the loads known before the solve: gravity, xfrc_applied, qfrc_applied (the rest,
        # contacts and actuators, the coupling takes from the step before)
        q0, q1, q2, s0, s1, s2 = (d.qfrc_applied[a : a + 6]).tolist()
        x0, x1, x2, y0, y1, y2 = d.xfrc_applied[b].tolist()
        mg0, mg1, mg2 = self._weight
        px, py, pz = q0 + x0 + mg0, q1 + x1 + mg1, q2 + x2 + mg2
        # qfrc_applied's torque: body frame, about the frame origin; to G: + (O − G) × F
        t0 = r00 * s0 + r01 * s1 + r02 * s2 + y0 - (ry * q2 - rz * q1)
        t1 = r10 * s0 + r11 * s1 + r12 * s2 + y1 - (rz * q0 - rx * q2)
        t2 = r20 * s0 + r21 * s1 + r22 * s2 + y2 - (rx * q1 - ry * q0)
        known = (
            px * a0 + py * a1 + pz * a2,
            px * c0 + py * c1 + pz * c2,
            t0 * n0 + t1 * n1 + t2 * n2,
        )
        w = self.friction.step(t, nu, phi, normal, load, known)
        self.normal_force = normal
        if not normal > 0.0:
            return None
        fw, tq, pt = self._force, self._torque, self._point
        w0, w1, w2 = w
        fw[0] = w0 * a0 + w1 * c0
        fw[1] = w0 * a1 + w1 * c1
        fw[2] = w0 * a2 + w1 * c2
        tq[0], tq[1], tq[2] = w2 * n0, w2 * n1, w2 * n2
        # the point of the contact plane below G
        depth = (gx - pc[0]) * n0 + (gy - pc[1]) * n1 + (gz - pc[2]) * n2
        pt[0], pt[1], pt[2] = gx - depth * n0, gy - depth * n1, gz - depth * n2
        mujoco.mj_applyFT(m, d, fw, tq, pt, b, d.qfrc_passive)
        if sb:
            mujoco.mj_applyFT(m, d, -fw, -tq, pt, sb, d.qfrc_passive)
        return None

    def _support_body(self, m, sg: int) -> int:
        """The support geom's body if it moves (0 for the world and static bodies)."""
        sb = self._movers.get(sg)
        if sb is None:
            sb = int(m.geom_bodyid[sg])
            sb = sb if sb and m.body_dofnum[sb] > 0 else 0
            self._movers[sg] = sb
        return sb

    def _refuse_rk4(self) -> None:
        if not self._warned_rk4:
            self._warned_rk4 = True
            warnings.warn(
                f"slidespin.mujoco: model.opt.integrator = RK4 is invalid for the coupling of "
                f"{self.body_name!r}; valid values: Euler, implicit, implicitfast (the "
                "discrete projection acts once per step): no friction is applied while it is "
                "RK4",
                RuntimeWarning,
                stacklevel=1,
            )

    def _dry_run(self, m, d, n, e1, e2):
        """(N, planar load) of this step without the friction: ``mj_forward`` on a copy."""
        d2 = copy.copy(d)  # a new MjData: the callback does not know it, adds nothing
        mujoco.mj_forward(m, d2)
        b, a = self.body_id, self.dof
        n, e1, e2 = np.array(n), np.array(e1), np.array(e2)
        normal = float(d2.qfrc_constraint[a : a + 3] @ n)
        rot = d2.xmat[b].reshape(3, 3)
        omega = rot @ d2.qvel[a + 3 : a + 6]
        alpha = rot @ d2.qacc[a + 3 : a + 6]
        r = d2.xipos[b] - d2.xpos[b]
        acc = d2.qacc[a : a + 3] + np.cross(alpha, r) + np.cross(omega, np.cross(omega, r))
        fr = self.friction
        load = (fr.m * float(acc @ e1), fr.m * float(acc @ e2), fr.inertia * float(alpha @ n))
        return normal, load


def _fixed_in_world(m, body: int) -> bool:
    """Whether a body cannot move: the world, or a body that neither it nor any ancestor
    has dofs or is a mocap body (a table welded to the world, say)."""
    while body > 0:
        if m.body_dofnum[body] > 0 or m.body_mocapid[body] >= 0:
            return False
        body = int(m.body_parentid[body])
    return True


def steady_kernel(footprint: bool):
    """The compiled steady step for an ellipse or a footprint: the ahead-of-time compiled
    core's entry when the install built it (:mod:`slidespin._aot`), else the JIT's (compiled
    on the first steady step, then cached)."""
    name = "steady_footprint" if footprint else "steady_ellipse"
    aot = getattr(_aot.core(), name, None)
    return aot if aot is not None else getattr(sc, name)


def _body_id(model, body_name) -> int:
    if not isinstance(body_name, str):
        raise TypeError(f"body_name = {body_name!r} is invalid; valid values: a body's name")
    bid = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, body_name)
    if bid < 0:
        names = [model.body(i).name for i in range(1, model.nbody)]
        raise ValueError(
            f"body_name = {body_name!r} is invalid; valid values: a body of the model, one of "
            f"{v._short(names, 200)}"
        )
    jnt = model.body_jntadr[bid]
    if model.body_jntnum[bid] != 1 or model.jnt_type[jnt] != mujoco.mjtJoint.mjJNT_FREE:
        raise ValueError(
            f"body_name = {body_name!r} is invalid: the body has no free joint (a "
            "<freejoint/> alone); valid values: a free body resting on its support"
        )
    if model.body_geomnum[bid] == 0:
        raise ValueError(f"body_name = {body_name!r} is invalid: the body has no geom")
    return bid


def _support_ids(model, support) -> list[int]:
    if support is None:
        ids = [i for i in range(model.ngeom) if model.geom_bodyid[i] == 0]
        if not ids:
            raise ValueError(
                "support = None is invalid for this model: the world body has no geom; valid "
                "values: the names of the support's geoms"
            )
        return ids
    names = [support] if isinstance(support, str) else list(support)
    if not names:
        raise ValueError(
            f"support = {support!r} is invalid; valid values: None (the world body's geoms) "
            "or the names of one or more geoms"
        )
    ids = []
    for name in names:
        gid = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, str(name))
        if gid < 0:
            raise ValueError(
                f"support = {support!r} is invalid: no geom named {name!r}; valid values: "
                "names of the model's geoms"
            )
        ids.append(gid)
    return ids


def _saved(model) -> dict[int, tuple[int, int]]:
    """The saved (condim, priority) of ``model``'s geoms (not those of a freed model)."""
    entry = _SAVED.get(model._address)
    if entry is None or entry[0]() is not model:
        entry = (weakref.ref(model), {})
        _SAVED[model._address] = entry
    return entry[1]


def _save(model, gid: int) -> None:
    saved = _saved(model)
    if gid not in saved:
        saved[gid] = (int(model.geom_condim[gid]), int(model.geom_priority[gid]))


def _inputs(body, friction):
    if isinstance(body, (str, Path)):
        body = load_case(body)
    if isinstance(body, Case):
        if friction is not None:
            raise ValueError(
                "friction is invalid with a case: valid values: None (the case's friction)"
            )
        return body.body, body.friction
    if friction is None:
        raise ValueError("friction = None is invalid; valid values: a FrictionTensor")
    return body, friction


def attach(
    model, data, body_name: str, body, friction: FrictionTensor | None = None, *, support=None
) -> Coupling:
    """Apply slidespin's exact friction to a free body of a MuJoCo model (MODEL §16).

    After this call a plain ``mujoco.mj_step(model, data)`` steps with slidespin's friction on
    the contact of that body with its support (see the module docstring for how).

    Parameters
    ----------
    model, data : mujoco.MjModel, mujoco.MjData
        The scene (its integrator Euler, implicit or implicitfast).
    body_name : str
        The free body (a ``<freejoint/>``) whose flat contact slidespin supplies.
    body : Body, Case, str or Path
        The slidespin body (footprint and pressure law; its frame is the MuJoCo body's, its
        pressure centroid under the body's centre of mass), or a case (a :class:`Case` or a
        case file's path) giving the body and its friction.
    friction : FrictionTensor or None
        Its friction tensor (None with a case).
    support : str, sequence of str or None
        The geoms the body rests on; None: every geom of the world body (a floor, a plane, a
        static table).

    Returns
    -------
    Coupling
        The handle: its last wrench, normal force and state (slip, stick, free).

    Raises
    ------
    ValueError
        An unknown or non-free body, an unknown support geom, the RK4 integrator, a body
        already attached in this ``data``, a tall body or a speed law (see
        :func:`slidespin.engines._coupling.check_coupled`).
    """
    if not isinstance(model, mujoco.MjModel) or not isinstance(data, mujoco.MjData):
        raise TypeError(
            f"model, data = {type(model).__name__}, {type(data).__name__} are invalid; valid "
            "values: a mujoco.MjModel and its mujoco.MjData"
        )
    body, friction = _inputs(body, friction)
    check_coupled(body, friction)
    if model.opt.integrator == mujoco.mjtIntegrator.mjINT_RK4:
        raise ValueError(
            "model.opt.integrator = RK4 is invalid for a coupling; valid values: Euler, "
            "implicit, implicitfast (the discrete projection acts once per step)"
        )
    bid = _body_id(model, body_name)
    if bid in _couplings(data):
        raise ValueError(
            f"body_name = {body_name!r} is invalid: already attached in this data; detach it first"
        )
    support_ids = _support_ids(model, support)
    geoms = range(model.body_geomadr[bid], model.body_geomadr[bid] + model.body_geomnum[bid])
    if set(geoms) & set(support_ids):
        raise ValueError(
            f"support = {support!r} is invalid: it names a geom of {body_name!r} itself"
        )
    top = max(int(model.geom_priority[g]) for g in geoms)
    for g in geoms:
        _save(model, g)
        model.geom_condim[g] = 1
    for g in support_ids:
        _save(model, g)
        model.geom_priority[g] = min(int(model.geom_priority[g]), top - 1)
    coupling = Coupling(model, data, bid, body, friction, support_ids)
    _couplings(data, model)[bid] = coupling
    current = mujoco.get_mjcb_passive()
    if not _installed(current):
        _CHAINED[:] = [current]
        mujoco.set_mjcb_passive(_PASSIVE)
    return coupling


def _installed(current) -> bool:
    """Whether MuJoCo's passive callback is ours (the getter returns a new ctypes object)."""
    return (
        isinstance(current, _CFUNCPTR)
        and ctypes.cast(current, ctypes.c_void_p).value
        == ctypes.cast(_PASSIVE, ctypes.c_void_p).value
    )


def _couplings(data, model=None) -> dict[int, Coupling]:
    """The couplings of ``data`` (forgetting those of a freed data at its address); with
    ``model``, the entry is made if there is none."""
    entry = _ATTACHED.get(data._address)
    if entry is None or entry[0]() is not data:
        _ATTACHED.pop(data._address, None)
        if model is None:
            return {}
        entry = (weakref.ref(data), weakref.ref(model), {})
        _ATTACHED[data._address] = entry
    return entry[2]


def attached(data) -> list[str]:
    """The names of the bodies coupled in ``data``."""
    return [c.body_name for c in _couplings(data).values()]


def detach(model, data, body_name: str | None = None) -> None:
    """Undo :func:`attach` for one body (``body_name``) or for every body of ``data`` (None):
    the geoms' condim and priority come back, and the passive callback chained before is
    restored when no coupling is left."""
    couplings = _couplings(data)
    if body_name is None:
        ids = list(couplings)
    else:
        bid = _body_id(model, body_name)
        if bid not in couplings:
            raise ValueError(
                f"body_name = {body_name!r} is invalid: not attached in this data; attached: "
                f"{attached(data)}"
            )
        ids = [bid]
    for bid in ids:
        del couplings[bid]
    for address, (dref, _, cs) in list(_ATTACHED.items()):  # this data's, and freed ones
        if not cs or dref() is None:
            del _ATTACHED[address]
    still = {
        g
        for _, _, cs in _ATTACHED.values()
        for c in cs.values()
        if c._model_address == model._address
        for g in (*c.geoms, *c.support)
    }
    saved = _saved(model)
    for g in list(saved):
        if g not in still:
            model.geom_condim[g], model.geom_priority[g] = saved.pop(g)
    if not saved:
        _SAVED.pop(model._address, None)
    if not _ATTACHED and _installed(mujoco.get_mjcb_passive()):
        mujoco.set_mjcb_passive(_CHAINED[0] if _CHAINED else None)
        _CHAINED.clear()


def set_twist(model, data, body_name: str, vx: float, vy: float, omega: float) -> None:
    """Launch a free body: set its planar twist (vx, vy [m/s] of its mass centre along the
    world x and y axes, ω [rad/s] about the world z axis; the other three components 0).

    MuJoCo's free joint holds the velocity of the body frame's origin (world frame) and the
    angular velocity in the body frame; this converts, so that the mass centre moves as
    given even when it is not at the body frame's origin.
    """
    bid = _body_id(model, body_name)
    for name, value in (("vx", vx), ("vy", vy), ("omega", omega)):
        v.finite(name, value)
    mujoco.mj_kinematics(model, data)
    a = int(model.jnt_dofadr[model.body_jntadr[bid]])
    w = np.array([0.0, 0.0, float(omega)])
    r = data.xipos[bid] - data.xpos[bid]
    data.qvel[a : a + 3] = np.array([float(vx), float(vy), 0.0]) - np.cross(w, r)
    data.qvel[a + 3 : a + 6] = data.xmat[bid].reshape(3, 3).T @ w
