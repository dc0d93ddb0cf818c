"""The engines' own contact parameters fitted to slidespin's exact motions (MODEL §16).

For users who cannot couple slidespin to their engine (:mod:`slidespin.engines`) but want the
best their engine's own friction can do: :func:`engine_parameters` launches the body in the
engine (:mod:`slidespin.engines._native`) over a few launches, compares each run's stop time,
stop position and rotation with :func:`slidespin.simulate`'s, and adjusts the engine's free
friction parameters by least squares (:func:`scipy.optimize.least_squares`) on the relative
errors. It returns the parameters keyed by the engine's own names, with the errors that
remain, and those of the engine's defaults, so that the gain (and what no parameter can fix)
is visible.

What each engine can represent, and so what is fitted:

* **MuJoCo** (``friction`` = (μ, μ_torsion, μ_roll), ``condim`` 4, ``cone`` ``"elliptic"``):
  μ and μ_torsion are fitted; μ_roll stays at MuJoCo's 1e-4 (condim 4 has no rolling
  friction). A geom's friction is isotropic in the plane.
* **PyBullet** (``lateralFriction``, ``spinningFriction``, ``rollingFriction``,
  ``anisotropicFriction``): the lateral and spinning coefficients are fitted, and for an
  anisotropic tensor the ratio of the anisotropic scale factors along the body's axes
  ((1, r, 1), fixed to the **body**). The values are the body's with a floor whose own
  lateral friction is 1 and spinning friction 0 (Bullet multiplies the lateral coefficients
  of the pair and adds spinning × the other's lateral).
* **Drake** (``static_friction``, ``dynamic_friction``, ``contact_model``
  ``"hydroelastic_with_fallback"``, ``hydroelastic_modulus``, ``resolution_hint``,
  ``hunt_crossley_dissipation``, ``discrete_contact_approximation`` ``"sap"``): a compliant
  hydroelastic body on a rigid half-space, whose pressure is spread over the whole footprint
  (so its torsional friction comes out of the patch itself). The dynamic coefficient and the
  hydroelastic modulus E are fitted (E between 10^0.5 and 10^2.5 × the mean pressure m g/A,
  the body sinking by 30 % to 0.3 % of half its thickness): a stiff patch tips onto its rim
  under the moment of friction about G (the contact plane lies below G, and a spinning body
  precesses), which loads the rim and brakes the spin harder than slidespin's thin body,
  whose pressure law does not change; a softer patch keeps the pressure closer to it. The
  static coefficient is ``friction.static`` × the dynamic one; ``resolution_hint`` (ℓ/8)
  only tessellates disks and meshes. Drake's Coulomb friction is isotropic.

No engine represents the skew part f of the tensor, a speed law, or (MuJoCo, Drake) any
anisotropy: those are fitted by the best isotropic, constant coefficients, and
``EngineParameters.notes`` says so; the remaining errors show what it costs.

Measured (mujoco 4.0, pybullet 3.2.7, pydrake 1.58; the default launches, dt = 1 ms;
uniform pressure; the worst relative error over the three launches of the stop time /
distance / rotation, as ``EngineParameters.errors`` defines them; box 0.2 × 0.1 m, 1 kg;
puck: disk of radius 0.05 m, 0.2 kg; ring: 0.06–0.065 m, 0.5 kg; μ = 0.3 unless said; the
fit's wall time on one core):

=========  =================  ==================  ==================  ==================  ======
engine     body               default             naive μ             fitted              time
=========  =================  ==================  ==================  ==================  ======
MuJoCo     box                0.81 / 0.74 / 0.84  0.43 / 0.16 / 0.47  0.31 / 0.18 / 0.37  1.3 s
MuJoCo     puck               0.73 / 0.71 / 0.80  0.29 / 0.07 / 0.33  0.24 / 0.07 / 0.29  0.6 s
MuJoCo     box, (0.2, 0.4)    0.80 / 0.80 / 0.85  0.42 / 0.31 / 0.51  0.19 / 0.30 / 0.25  0.8 s
MuJoCo     ring               0.66 / 0.71 / 0.71  0.06 / 0.04 / 0.05  0.04 / 0.05 / 0.05  3.8 s
PyBullet   box                0.66 / 0.51 / 0.67  0.41 / 0.22 / 0.44  0.31 / 0.25 / 0.36  2.4 s
PyBullet   puck               0.52 / 0.47 / 0.59  0.26 / 0.14 / 0.32  0.12 / 0.12 / 0.27  2.2 s
PyBullet   box, (0.2, 0.4)    0.65 / 0.58 / 0.67  0.41 / 0.34 / 0.45  0.12 / 0.32 / 0.18  6.9 s
PyBullet   ring               2.09 / 0.48 / 0.51  2.14 / 0.14 / 0.05  2.06 / 0.20 / 0.20  8.0 s
Drake      box                0.41 / 0.24 / 0.44  —                   0.12 / 0.04 / 0.11  7.4 s
Drake      puck               4.32 / 0.18 / 0.23  —                   0.11 / 0.07 / 0.10  12.7 s
Drake      box, (0.2, 0.4)    0.41 / 0.30 / 0.45  —                   0.07 / 0.21 / 0.06  7.9 s
Drake      ring               0.04 / 0.08 / 0.07  —                   0.01 / 0.02 / 0.03  24.7 s
=========  =================  ==================  ==================  ==================  ======

MuJoCo and PyBullet put a few contacts on the footprint's corners or rim, where friction
brakes the spin about 1.5 times harder than over the whole patch (a disk: μ N R instead of
2/3 μ N R); no torsional coefficient can remove torque (the fitted ones are near 0), so the
fit trades the stop of the spinning launches against that of the sliding ones, and 20–35 %
remains. PyBullet's ring (32 boxes) rocks on its edge after its spin dies and creeps for
seconds (its stop time error stays ~2). Drake's compliant patch carries the torque of the
whole footprint and comes within ~10 %.

May import: :mod:`slidespin.engines._native`, :mod:`slidespin.engines.scenes`,
:mod:`slidespin.motion`, :mod:`slidespin.contact` and the private root helpers.
"""

from __future__ import annotations

import math
import time
from collections.abc import Sequence

import numpy as np

from slidespin import _validate as v
from slidespin.contact.body import Body
from slidespin.contact.friction import FrictionTensor
from slidespin.engines import _native
from slidespin.engines.scenes import prism_parts
from slidespin.motion.simulate import simulate
from slidespin.motion.state import State

__all__ = ["EngineParameters", "engine_parameters", "default_launches"]

ENGINE_NAMES = ("mujoco", "pybullet", "drake")
#: a rotation error is relative to the larger of slidespin's rotation and this [rad]
ROTATION_FLOOR = 0.5
#: least-squares budget (engine evaluations) per engine
MAX_EVALUATIONS = {"mujoco": 40, "pybullet": 30, "drake": 10}
#: MuJoCo's default geom friction and condim; Bullet's default lateral friction
MUJOCO_DEFAULT = {"friction": (1.0, 0.005, 0.0001), "condim": 3, "cone": "elliptic"}
BULLET_DEFAULT_LATERAL = 0.5
ERROR_KEYS = ("t_stop", "distance", "rotation")


class EngineParameters(dict):
    """An engine's contact parameters fitted to slidespin's motions, with their errors.

    A ``dict`` whose keys are the engine's own parameter names only: copy the values into
    the engine's model (MuJoCo's geom ``friction`` and ``condim`` with ``cone="elliptic"``;
    ``pybullet.changeDynamics(body, -1, **params)``; Drake's proximity properties), or pass
    MuJoCo's as ``contact=`` to :func:`slidespin.engines.scenes.mujoco_xml`. The fit's context
    lives in attributes.

    Attributes
    ----------
    engine : str
        ``"mujoco"``, ``"pybullet"`` or ``"drake"``.
    launches : tuple of State
        The launches the parameters were fitted on.
    errors : dict
        ``{"fitted": …, "default": …, "naive": …}`` (``naive`` for MuJoCo and PyBullet
        only), each ``{"launches": [{"t_stop", "distance", "rotation", "stopped"}, …],
        "worst": {"t_stop", "distance", "rotation"}}`` (the worst values also directly:
        ``errors["fitted"]["rotation"]``): the relative errors (absolute values) of the
        engine's runs with the fitted parameters, with the engine's defaults (MuJoCo:
        friction (1, 0.005, 0.0001), condim 3; PyBullet: lateralFriction 0.5, no spinning
        friction; Drake: point contact with the mean coefficient), and with the naive choice
        of the mean coefficient as the engine's sliding friction and nothing else. Errors:
        stop time ``|Δt|/t``; distance ``|Δp|/max(d, ℓ)``, Δp the miss of the stop
        position, d the distance slidespin's body travels and ℓ its length unit; rotation
        ``|Δφ|/max(|φ|, 0.5 rad)``, φ slidespin's rotation from launch to stop. A run that does not stop
        within its time limit (3 × slidespin's longest stop) counts with its values there,
        and its ``stopped`` is False.
    default, naive : dict
        The baseline parameters (engine names), whose errors are in ``errors``.
    notes : tuple of str
        What the engine cannot represent of this body and friction.
    fit_time : float
        Wall time of the whole call [s].
    """

    engine: str
    launches: tuple
    errors: dict
    default: dict
    naive: dict
    notes: tuple
    fit_time: float

    def summary(self) -> str:
        """A Markdown table of the worst errors of the fitted parameters and the baselines."""
        rows = [
            f"{self.engine}: {_short(dict(self))}",
            "",
            f"Worst relative errors over the {len(self.launches)} launches fitted on (stop "
            "time |Δt|/t, distance |Δp|/max(d, ℓ), rotation |Δφ|/max(|φ|, 0.5 rad)), for the "
            "fitted parameters, the engine's defaults and the naive choice (the mean "
            "coefficient as sliding friction, nothing else). The fit minimises the three "
            "together, over every launch: one error may end above a baseline's.",
            "",
            "| parameters | stop time | distance | rotation |",
            "|---|---|---|---|",
        ]
        for name, e in self.errors.items():
            w = e["worst"]
            rows.append(
                f"| {name} | {w['t_stop']:.3g} | {w['distance']:.3g} | {w['rotation']:.3g} |"
            )
        rows += ["", *self.notes, f"fit time {self.fit_time:.1f} s"]
        return "\n".join(rows)

    def __repr__(self) -> str:
        w = self.errors["fitted"]["worst"]
        return (
            f"EngineParameters({_short(dict(self))}, engine={self.engine!r}, worst fitted "
            f"errors: t_stop {w['t_stop']:.3g}, distance {w['distance']:.3g}, rotation "
            f"{w['rotation']:.3g})"
        )


def _short(params: dict) -> str:
    """The parameters with their numbers to 6 significant digits (for reading)."""

    def fmt(value):
        if isinstance(value, float):
            return f"{value:.6g}"
        if isinstance(value, tuple):
            return "(" + ", ".join(fmt(v) for v in value) + ")"
        return repr(value)

    return "{" + ", ".join(f"{k!r}: {fmt(v)}" for k, v in params.items()) + "}"


# ------------------------------------------------------------------------------------------
# inputs
# ------------------------------------------------------------------------------------------
def _mean_mu(friction: FrictionTensor) -> float:
    return 0.5 * (friction.fx + friction.fy)


def default_launches(body: Body, friction: FrictionTensor, *, g: float = 9.81,
                     distance: float = 2.0) -> tuple[State, ...]:  # fmt: skip
    """Three launches in the body's natural scales: pure translation, slide with spin,
    spin-dominated.

    V = √(2 μ̄ g D ℓ) is the speed that slides the body ``distance`` (D) length units ℓ
    under the mean coefficient μ̄ = (fx + fy)/2, and k its radius of gyration.

    Parameters
    ----------
    body : Body
    friction : FrictionTensor
    g : float
        Gravity [m/s²].
    distance : float
        D, the sliding distance of the translation, in length units ℓ.

    Returns
    -------
    tuple of State
        (V at 30° from x, no spin), (V along x, ω = V/(2k)), (0.2 V along y, ω = 2 V/k)
        at angle φ₀ = 0.3 rad.
    """
    ell, k = body.length_unit, body.radius_of_gyration
    speed = math.sqrt(2.0 * _mean_mu(friction) * g * distance * ell)
    c, s = math.cos(math.pi / 6), math.sin(math.pi / 6)
    return (
        State(vx=speed * c, vy=speed * s),
        State(vx=speed, omega=speed / (2.0 * k)),
        State(vy=0.2 * speed, omega=2.0 * speed / k, phi=0.3),
    )


def _check(body, friction, engine, launches, g, dt) -> tuple[str, tuple[State, ...]]:
    engine = v.choice("engine", engine, ENGINE_NAMES)
    if not isinstance(body, Body):
        raise TypeError(f"body = {v._short(body)} is invalid; valid values: a slidespin.Body")
    if not isinstance(friction, FrictionTensor):
        raise TypeError(
            f"friction = {v._short(friction)} is invalid; valid values: a slidespin.FrictionTensor"
        )
    prism_parts(body)  # raises ValueError naming body.patch for a footprint no scene builds
    v.bounded("g", g, *v.GRAVITY, "m/s²")
    v.bounded("dt", dt, 1e-5, 1e-2, "s")
    if launches is None:
        launches = default_launches(body, friction, g=g)
    if isinstance(launches, State):
        launches = (launches,)
    launches = tuple(launches)
    if not launches or not all(isinstance(s, State) for s in launches):
        raise ValueError(
            f"launches = {v._short(launches, 100)} is invalid; valid values: None or a "
            "non-empty sequence of slidespin.State"
        )
    for i, s in enumerate(launches):
        if s.vx == 0.0 and s.vy == 0.0 and s.omega == 0.0:
            raise ValueError(
                f"launches[{i}] = {s!r} is invalid; valid values: a State with a non-zero "
                "velocity or spin"
            )
    return engine, launches


def _notes(engine: str, body: Body, friction: FrictionTensor) -> tuple[str, ...]:
    out = []
    aniso = friction.fx != friction.fy
    if aniso and engine in ("mujoco", "drake"):
        out.append(
            f"{engine}: the friction is isotropic in the plane; the anisotropic tensor "
            f"(fx={friction.fx:g}, fy={friction.fy:g}) is fitted by one isotropic coefficient"
        )
    if aniso and engine == "pybullet" and friction.frame != "body":
        out.append(
            "pybullet: anisotropicFriction is fixed to the body's axes, the tensor to the "
            "plane: fitted as a body-fixed anisotropy, exact only while the body does not turn"
        )
    if aniso and engine == "pybullet" and friction.angle != 0.0:
        out.append("pybullet: the tensor's axes are turned from the body's: not represented")
    if friction.f != 0.0:
        out.append(f"{engine}: the skew part f={friction.f:g} of the tensor is not represented")
    if friction.speed_law is not None and not friction.speed_law.is_constant:
        out.append(f"{engine}: the speed law is not represented (constant coefficients)")
    if type(body.pressure).__name__ != "UniformPressure":
        out.append(
            f"{engine}: the pressure law {type(body.pressure).__name__} is not represented "
            "(the engine spreads the load its own way over the prism's contacts)"
        )
    if body.height != 0.0:
        out.append(
            f"{engine}: body.height={body.height:g} is not represented (prism of "
            f"thickness {_native.THICKNESS:g} ℓ)"
        )
    return tuple(out)


# ------------------------------------------------------------------------------------------
# errors
# ------------------------------------------------------------------------------------------
class _Targets:
    """slidespin's stops for the launches, and the scales of the relative errors."""

    def __init__(self, body: Body, friction: FrictionTensor, launches, g: float) -> None:
        self.launches = launches
        self.t, self.p, self.phi, self.d_scale, self.phi_scale = [], [], [], [], []
        ell = body.length_unit
        for s in launches:
            tr = simulate(body, friction, s, g=g)
            st = tr.stop_state
            self.t.append(float(tr.t_stop))
            self.p.append((float(st.x), float(st.y)))
            self.phi.append(float(st.phi))
            self.d_scale.append(max(math.hypot(st.x - s.x, st.y - s.y), ell))
            self.phi_scale.append(max(abs(st.phi - s.phi), ROTATION_FLOOR))
        #: the engines run to at most this long after each launch
        self.t_max = max(3.0 * max(self.t), max(self.t) + 0.2)

    def residuals(self, runs) -> np.ndarray:
        """Signed relative errors (t, distance, rotation) per launch, flattened."""
        out = []
        for i, r in enumerate(runs):
            out.append((r.t_stop - self.t[i]) / self.t[i])
            miss = math.hypot(r.x - self.p[i][0], r.y - self.p[i][1])
            out.append(miss / self.d_scale[i])
            out.append((r.phi - self.phi[i]) / self.phi_scale[i])
        return np.asarray(out)


def _launch_errors(residuals: np.ndarray, stopped: Sequence[bool] | None = None) -> dict:
    """``{"launches": [...], "worst": {...}}`` from the residual vector of ``_Targets.residuals``
    (each launch's entry also says whether the engine's run ``stopped`` within its time)."""
    e = np.abs(np.asarray(residuals, dtype=float)).reshape(-1, 3)
    stopped = [True] * len(e) if stopped is None else list(stopped)
    per = [
        {**{k: float(row[j]) for j, k in enumerate(ERROR_KEYS)}, "stopped": bool(s)}
        for row, s in zip(e, stopped, strict=True)
    ]
    worst = {k: float(e[:, j].max()) for j, k in enumerate(ERROR_KEYS)}
    return {"launches": per, "worst": worst, **worst}


# ------------------------------------------------------------------------------------------
# the engines' free parameters
# ------------------------------------------------------------------------------------------
def _footprint_area(body: Body) -> float:
    area = getattr(body.patch, "area", None)
    if area is not None:
        return float(area)
    total = 0.0  # pragma: no cover - every patch has an area today
    for kind, _, _, size in prism_parts(body):
        if kind == "box":
            total += 4.0 * size[0] * size[1]
        elif kind == "cylinder":
            total += math.pi * size[0] ** 2
        else:
            x, y = np.asarray(size).T
            total += 0.5 * abs(float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1))))
    return total


class _Model:
    """An engine's parameters as a function of the fitted vector x (scaled to O(1))."""

    def __init__(self, engine: str, body: Body, friction: FrictionTensor, g: float) -> None:
        self.engine, self.body, self.friction = engine, body, friction
        self.mu = _mean_mu(friction)
        self.ell = body.length_unit
        self.aniso = engine == "pybullet" and friction.fx != friction.fy
        if engine == "drake":
            # the pressure field is E × depth / (t/2): E = 10^s × (mean pressure m g / A)
            # sinks the body by 10^-s × t/2
            self.pressure = body.mass * g / _footprint_area(body)
            self.hint = 0.125 * self.ell

    def start(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(x0, lower, upper)."""
        if self.engine == "drake":  # (μ / μ̄, log10 of E over the mean pressure)
            return np.array([1.0, 1.5]), np.array([0.3, 0.5]), np.array([3.0, 2.5])
        x0 = [1.0, 0.02]
        lo, hi = [0.3, 0.0], [3.0, 1.0]
        if self.aniso:
            x0.append(self.friction.fy / self.friction.fx)
            lo.append(0.05)
            hi.append(20.0)
        return np.array(x0), np.array(lo), np.array(hi)

    def scan(self, x0) -> list[np.ndarray]:
        """The points of the coarse scan before the least squares: μ (and Drake's modulus)."""
        if self.engine == "drake":
            return [np.array([a, s]) for s in (1.0, 1.75, 2.5) for a in (0.85, 0.93, 1.0, 1.1)]
        out = []
        for scale in (0.6, 0.8, 1.0, 1.25, 1.6):
            x = np.array(x0, dtype=float)
            x[0] = scale
            out.append(x)
        return out

    def params(self, x) -> dict:
        mu = float(x[0]) * self.mu
        if self.engine == "mujoco":
            return {"friction": (mu, float(x[1]) * self.ell, 1e-4), "condim": 4, "cone": "elliptic"}
        if self.engine == "pybullet":
            aniso = (1.0, float(x[2]), 1.0) if self.aniso else (1.0, 1.0, 1.0)
            return {
                "lateralFriction": mu,
                "spinningFriction": float(x[1]) * self.ell,
                "rollingFriction": 0.0,
                "anisotropicFriction": aniso,
            }
        static = max(float(self.friction.static), 1.0)
        return {
            "static_friction": static * mu,
            "dynamic_friction": mu,
            "contact_model": "hydroelastic_with_fallback",
            "hydroelastic_modulus": self.pressure * 10.0 ** float(x[1]),
            "resolution_hint": self.hint,
            "hunt_crossley_dissipation": 10.0,
            "discrete_contact_approximation": "sap",
        }

    def baselines(self) -> dict:
        """The engine's defaults, and the naive choice (μ̄ as the sliding friction)."""
        if self.engine == "mujoco":
            naive = dict(MUJOCO_DEFAULT, friction=(self.mu, 0.005, 0.0001))
            return {"default": dict(MUJOCO_DEFAULT), "naive": naive}
        if self.engine == "pybullet":
            base = {"spinningFriction": 0.0, "rollingFriction": 0.0,
                    "anisotropicFriction": (1.0, 1.0, 1.0)}  # fmt: skip
            return {
                "default": dict(base, lateralFriction=BULLET_DEFAULT_LATERAL),
                "naive": dict(base, lateralFriction=self.mu),
            }
        point = {
            "static_friction": max(float(self.friction.static), 1.0) * self.mu,
            "dynamic_friction": self.mu,
            "contact_model": "point",
            "discrete_contact_approximation": "sap",
        }
        return {"default": point}


# ------------------------------------------------------------------------------------------
# the fit
# ------------------------------------------------------------------------------------------
def engine_parameters(
    body: Body,
    friction: FrictionTensor,
    engine: str = "mujoco",
    *,
    launches: Sequence[State] | None = None,
    g: float = 9.81,
    dt: float = 1e-3,
) -> EngineParameters:
    """The engine's own contact parameters that best reproduce slidespin's motions.

    Each launch is run by :func:`slidespin.simulate` (the target) and by the engine with
    its own friction (:mod:`slidespin.engines._native`: the scene of
    :func:`slidespin.engines.scenes.mujoco_xml`, or the same prisms in PyBullet and Drake,
    settled on the floor, then launched and stepped until the planar speed and spin vanish).
    The engine's free parameters minimise, by :func:`scipy.optimize.least_squares`, the sum
    of squares of the relative errors of every launch's stop time, stop position and
    rotation (see ``EngineParameters.errors``). What is free in each engine, and what no
    engine parameter can represent (anisotropy in MuJoCo and Drake, a body-fixed anisotropy
    only in PyBullet, the skew part, speed laws), is in the module docstring; such a tensor
    is fitted by its best isotropic (or body-fixed) coefficients, said in
    ``EngineParameters.notes``, and the remaining errors show the cost.

    Parameters
    ----------
    body : Body
        The thin body; its footprint must be one the engine scenes build (a rectangle, a
        disk, a ring, an ellipse, a convex polygon, or pads of them).
    friction : FrictionTensor
        The friction of slidespin's motions (the targets).
    engine : {"mujoco", "pybullet", "drake"}
        The engine whose parameters are fitted.
    launches : sequence of State or None
        The launches fitted on; None: :func:`default_launches` (pure translation, slide with
        spin, spin-dominated, each stopping within about 2 body lengths). Fewer and shorter
        launches fit faster.
    g : float
        Gravity [m/s²], in [1e-6, 1e6].
    dt : float
        The engine's time step [s], in [1e-5, 1e-2]: the parameters are fitted for it.

    Returns
    -------
    EngineParameters
        A dict of the engine's parameter names (MuJoCo: ``friction``, ``condim``, ``cone``;
        PyBullet: ``lateralFriction``, ``spinningFriction``, ``rollingFriction``,
        ``anisotropicFriction``; Drake: ``static_friction``, ``dynamic_friction``,
        ``contact_model``, ``hydroelastic_modulus``, ``resolution_hint``,
        ``hunt_crossley_dissipation``, ``discrete_contact_approximation``), with attributes
        ``engine``, ``launches``, ``errors`` (fitted vs the engine's defaults), ``notes``,
        ``fit_time``.

    Raises
    ------
    ValueError
        For an unknown engine, a footprint the scenes cannot build, a bad ``g``, ``dt`` or
        launch (the message names the parameter, the value and the valid range).
    TypeError
        If ``body`` or ``friction`` is not a slidespin object.
    ImportError
        If the engine is not installed (``pip install "slidespin[mujoco]"``, ``[pybullet]``
        or ``[drake]``).

    Notes
    -----
    Wall time: about 1–5 s for MuJoCo and PyBullet with the default launches of a box or a
    puck, 5–30 s for Drake (its runs step ~10× slower); it grows with the launches' stop
    times over ``dt``.
    """
    t0 = time.perf_counter()
    engine, launches = _check(body, friction, engine, launches, g, dt)
    _native._import(engine)  # ImportError with the install hint before any work
    from scipy.optimize import least_squares  # lazy: scipy.optimize is slow to import

    targets = _Targets(body, friction, launches, g)
    model = _Model(engine, body, friction, g)

    def run(params: dict) -> tuple[np.ndarray, list[bool]]:
        runs = _native.run_native(engine, body, params, launches, g=g, dt=dt,
                                  t_max=targets.t_max)  # fmt: skip
        return targets.residuals(runs), [r.stopped for r in runs]

    cache: dict[tuple, tuple] = {}  # every evaluation: key -> (x, residuals, stopped)

    def fun(x) -> np.ndarray:
        key = tuple(np.round(x, 12))
        if key not in cache:
            cache[key] = (np.array(x, dtype=float), *run(model.params(x)))
        return cache[key][1]

    x0, lo, hi = model.start()
    # a coarse scan first: the engines' responses are steps of dt, far from smooth
    for x in model.scan(x0):
        fun(x)
    x_start = min(cache.values(), key=lambda c: float(c[1] @ c[1]))[0]
    least_squares(
        fun, x_start, bounds=(lo, hi), diff_step=0.05, x_scale=np.maximum(np.abs(x_start), 0.05),
        max_nfev=MAX_EVALUATIONS[engine], method="trf",
    )  # fmt: skip
    # the best point evaluated (the finite differences of a stepped response may end elsewhere)
    x_best, r_best, s_best = min(cache.values(), key=lambda c: float(c[1] @ c[1]))
    fitted = model.params(x_best)
    errors = {"fitted": _launch_errors(r_best, s_best)}
    base = model.baselines()
    for name, params in base.items():
        errors[name] = _launch_errors(*run(params))
    out = EngineParameters(fitted)
    out.engine = engine
    out.launches = launches
    out.errors = errors
    out.default = base["default"]
    out.naive = base.get("naive", base["default"])
    out.notes = _notes(engine, body, friction)
    out.fit_time = time.perf_counter() - t0
    return out
