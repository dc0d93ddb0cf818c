"""Sensitivities of a free motion to its parameters, along the path and at the stop (MODEL §15).

For parameters θ (the friction entries, the pressure centre, the moment of inertia, the start's
velocities) the sensitivity S = ∂y/∂θ of the regularised state y (MODEL §5) follows the
variational equation dS/dτ = (∂G/∂y) S + ∂G/∂θ, integrated with the motion (forward mode) by
:mod:`slidespin.motion._sensitivity_core`. From it:

- at the stop: ∂t_stop/∂θ, the stop pose's ∂x, ∂y, ∂φ (the limits of the sensitivities of
  t, x, y, φ as τ → ∞, where they converge with s), and ∂β*/∂θ from the terminal direction
  u* and its sensitivity by the implicit function theorem on u*'s fixed-point condition (a
  mixed ending; 0 for a pure sliding or pure spinning ending that attracts nearby motions,
  whose β* stays ∞ or 0; NaN for a spiral, which has no terminal direction);
- along the path, at the trajectory's own times t_i: the derivatives at fixed t,
  ∂q(t_i)/∂θ = ∂q/∂θ|τ − q̇ ∂t/∂θ|τ, of q = x, y, φ, vx, vy, ω.

:func:`slidespin.simulate` (``sensitivities=``) and :func:`slidespin.stop_sensitivities` are
the public entries; this module holds the parameter names, their perturbations and the run.

The variational equation's right-hand side uses the wrench's exact derivatives where the
kernels give them (an ellipse under every law: analytic; a footprint: exact in the ICR and
the pressure centre, differenced in the ICR only for a far ICR or a thin ring) and a central
difference of the whole right-hand side where they have none (a blade, a translation); it is
solved by collocation on the plain run's own steps, or integrated with the motion (see
:mod:`slidespin.motion._sensitivity_core`). Cost (``benchmarks/sensitivities_bench.py``):
2.2-2.8x a plain run for 6 parameters, 2.7-3.2x for 9 (2.8-3.1x and 3.4-5.1x with a
footprint's derivatives differenced; 6.9-7.6x and 9.7-14.3x integrated with the motion;
18-55x before the kernels' derivatives; docs/sensitivities.md).
"""

from __future__ import annotations

import dataclasses
import math
import warnings
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import NDArray

from slidespin import _validate as v
from slidespin.contact import _engine
from slidespin.contact._kernel_ellipse import wrench_array as ellipse_wrench_array
from slidespin.contact.body import Body
from slidespin.contact.friction import FrictionTensor
from slidespin.contact.pressure import LinearPressure, UniformPressure
from slidespin.motion import _dop853 as _dop
from slidespin.motion import _integrator
from slidespin.motion import _sensitivity_core as _core
from slidespin.motion._flow import NY
from slidespin.motion.state import State

__all__ = [
    "PARAMETERS",
    "EXTRA_PARAMETERS",
    "STOP_OUTPUTS",
    "PATH_OUTPUTS",
    "Sensitivities",
    "check_parameters",
    "check_setup",
    "compute",
]

#: the parameters a motion can be differentiated with respect to: the friction tensor's
#: entries, the pressure centre (ξc, ηc) = G in the body frame [m], the moment of inertia
#: about G [kg m²] and the start's velocities (SI)
PARAMETERS = ("fx", "fy", "f", "xi_c", "eta_c", "moment_of_inertia", "vx", "vy", "omega")
#: also accepted, for fitting: the tensor's angle [rad] and the start's body angle φ₀ [rad]
EXTRA_PARAMETERS = ("angle", "phi0")
#: the stop's quantities, in :func:`slidespin.stop_sensitivities`' dicts
STOP_OUTPUTS = ("t_stop", "x", "y", "phi", "beta_stop")
#: the path's quantities, at fixed time (``Sensitivities.path``)
PATH_OUTPUTS = ("x", "y", "phi", "vx", "vy", "omega")

#: relative step of the central differences inside the variational equation
REL_STEP = 1e-5
#: the wrench kernels' error target in a sensitivity run (the elliptic quadrature; the
#: footprint kernels are exact)
WRENCH_TOL = 1e-12
#: the sensitivity run's tolerance (relative and absolute, natural units) at least: tighter,
#: the step control chases the central differences' round-off (1e-16/REL_STEP) in S and can
#: take tens of times more steps (a curling stone: 6500 at 1e-10, 600 at 1e-9); at 1e-8 a
#: small derivative (∂t_stop/∂ηc, 1 % of the others) was 1.3e-6 off, at 1e-9 4e-8
RUN_TOL = 1e-9
#: solve the sensitivities by collocation on the plain run's steps
#: (:mod:`slidespin.motion._sensitivity_colloc`) when its tolerance is at least this tight;
#: else (or where the kernel has no derivatives) integrate them with the motion
COLLOCATE_RTOL = 1e-9
#: the run goes on until s < e^(−LN_DROP) s₀ and the stop's sensitivities move by less than
#: CONV_TOL (relative)
LN_DROP = 30.0
CONV_TOL = 1e-8
MAX_STEPS = 200_000


@dataclass(frozen=True)
class Sensitivities:
    """Derivatives of a motion with respect to its parameters (MODEL §15), SI units.

    Attributes
    ----------
    parameters : tuple of str
        The parameters (names of :data:`PARAMETERS`).
    t : ndarray (n,)
        The trajectory's times [s] (the last is the stop).
    path : dict
        ``path[p][q]``: ∂q(t)/∂p at the times ``t`` (fixed t), for q in ``x, y, phi, vx, vy,
        omega``; the last row is the stop's.
    stop : dict
        ``stop[p][q]``: ∂q/∂p of the stop, q in ``t_stop, x, y, phi, beta_stop``: the
        dict :func:`slidespin.stop_sensitivities` returns.
    n_steps : int
        Steps of the sensitivity run.
    """

    parameters: tuple[str, ...]
    t: NDArray[np.float64] = field(repr=False)
    path: dict[str, dict[str, NDArray[np.float64]]] = field(repr=False)
    stop: dict[str, dict[str, float]]
    n_steps: int = 0

    def __getitem__(self, name: str) -> dict[str, NDArray[np.float64]]:
        """``sens["fx"]``: the path's derivatives with respect to ``fx``."""
        if name not in self.path:
            raise KeyError(
                f"parameter = {name!r} is not among these sensitivities; valid values: "
                f"{', '.join(self.parameters)}"
            )
        return self.path[name]

    def columns(self) -> dict[str, NDArray[np.float64]]:
        """The path's derivatives as named columns ``d_<q>/d_<parameter>`` (SI units)."""
        return {f"d_{q}/d_{p}": self.path[p][q] for p in self.parameters for q in PATH_OUTPUTS}

    def to_dict(self) -> dict[str, Any]:
        """The stop's derivatives as a JSON-ready dict (``None`` for a non-finite value)."""
        return {
            p: {q: (x if math.isfinite(x) else None) for q, x in d.items()}
            for p, d in self.stop.items()
        }


def check_setup(body: Body, names: tuple[str, ...], case: int | None = None) -> None:
    """Refuse, before any run, parameters the body cannot vary: ``xi_c``, ``eta_c`` need a
    pressure centre that can move (the uniform or linear law on an ellipse or an area
    footprint); ``case``, if given, is named in the message (a batch's row)."""
    if "xi_c" in names or "eta_c" in names:
        _centre(body, case)


def check_parameters(parameters: Any, name: str = "parameters") -> tuple[str, ...]:
    """Validate the parameter names: a non-empty sequence of distinct names of
    :data:`PARAMETERS` or :data:`EXTRA_PARAMETERS` (a single name is taken as a one-element
    tuple); an error names the argument ``name``."""
    if isinstance(parameters, str):
        parameters = (parameters,)
    try:
        names = tuple(parameters)
    except TypeError:
        names = None
    ok = (
        names is not None
        and len(names) > 0
        and all(isinstance(p, str) and p in PARAMETERS + EXTRA_PARAMETERS for p in names)
        and len(set(names)) == len(names)
    )
    if not ok:
        raise ValueError(
            f"{name} = {v._short(parameters)} is invalid; valid values: a non-empty "
            f"sequence of distinct names among {', '.join(PARAMETERS + EXTRA_PARAMETERS)}"
        )
    return names  # type: ignore[return-value]


def _centre(body: Body, case: int | None = None) -> tuple[float, float]:
    """(ξc, ηc) of a body whose pressure centre can move: the linear law's, or the uniform
    law's centroid (the linear law with that centroid is the uniform law)."""
    p = body.pressure
    if isinstance(p, LinearPressure):
        return p.xi_c, p.eta_c
    if isinstance(p, UniformPressure) and type(body.patch).__name__ != "Blade":
        return body.mass_centre
    raise ValueError(
        ("" if case is None else f"case {case}: ")
        + "parameters xi_c, eta_c need a pressure centre that can move: pressure = "
        f"{body.pressure!r} on patch = {type(body.patch).__name__}(...) has none; valid "
        "values: UniformPressure() or LinearPressure(xi_c, eta_c) on an Ellipse or an area "
        "footprint"
    )


def _perturbed(
    body: Body, friction: FrictionTensor, state: State, name: str, value: float
) -> tuple[Body, FrictionTensor, State]:
    """The body, tensor and start with parameter ``name`` set to ``value``."""
    if name in ("fx", "fy", "f", "angle"):
        # (angle_deg, an init-only alias that replace() would copy from the old angle)
        entries: dict[str, Any] = {name: value, "angle_deg": None}
        return body, dataclasses.replace(friction, **entries), state
    if name in ("vx", "vy", "omega", "phi0"):
        return body, friction, dataclasses.replace(state, **{name.rstrip("0"): value})
    inertia = body.moment_of_inertia
    pressure = body.pressure
    if name == "moment_of_inertia":
        inertia = value
    else:
        xi, eta = _centre(body)
        pressure = LinearPressure(value, eta) if name == "xi_c" else LinearPressure(xi, value)
    try:
        return Body(body.patch, pressure, body.mass, inertia, body.height), friction, state
    except ValueError as exc:
        raise ValueError(
            f"parameter {name!r} cannot be varied about its value here: {exc}"
        ) from None


def _value(body: Body, friction: FrictionTensor, state: State, name: str) -> float:
    """The current value of parameter ``name`` (SI)."""
    if name in ("fx", "fy", "f", "angle"):
        return float(getattr(friction, name))
    if name in ("vx", "vy", "omega", "phi0"):
        return float(getattr(state, name.rstrip("0")))
    if name == "moment_of_inertia":
        return float(body.moment_of_inertia)  # type: ignore[arg-type]
    return float(_centre(body)[0 if name == "xi_c" else 1])


def _step(body: Body, friction: FrictionTensor, state: State, name: str) -> float:
    """The central difference's step h for parameter ``name`` (SI), REL_STEP of its scale."""
    if name in ("fx", "fy", "f"):
        return REL_STEP * max(friction.fx, friction.fy)
    if name in ("xi_c", "eta_c"):
        return REL_STEP * body.length_unit
    if name in ("angle", "phi0"):
        return REL_STEP  # of a radian
    if name == "moment_of_inertia":
        return REL_STEP * float(body.moment_of_inertia)  # type: ignore[arg-type]
    k = body.radius_of_gyration
    speed = math.sqrt(state.vx**2 + state.vy**2 + (k * state.omega) ** 2)
    if not speed > 0.0:  # (simulate refuses a start at rest before this)
        raise ValueError(f"state = {state!r} is at rest: no velocity to vary")
    return REL_STEP * (speed if name != "omega" else speed / k)


def _rows(body: Body, friction: FrictionTensor, state: State, g: float):
    """(par, geo, y0) of a body, tensor and start in natural units."""
    par, _, _, geo = body.engine_params(friction.kinetic, WRENCH_TOL)
    st = state
    return par, geo, _start(par, body.length_unit, g, st.vx, st.vy, st.omega, st.x, st.y, st.phi)


def _start(par, a: float, g: float, vx, vy, omega, x, y, phi) -> NDArray[np.float64]:
    """The regularised initial state of a start (SI) for the rows ``par`` (length unit
    ``a``): :func:`slidespin.motion._flow.initial_state`'s arithmetic, in Python (a call
    of the compiled one from here would compile it: it is not in the ahead-of-time core)."""
    t_unit, v_unit = math.sqrt(a / g), math.sqrt(a * g)
    vx, vy, wn = vx / v_unit, vy / v_unit, omega * t_unit
    k = float(par[_engine.P_K])
    y0 = np.zeros(NY)
    y0[5], y0[6], y0[7] = x / a, y / a, phi
    s0 = math.sqrt(vx * vx + vy * vy + (k * wn) ** 2)
    if s0 == 0.0:
        y0[3] = -math.inf
        return y0
    y0[0], y0[1], y0[2], y0[3] = vx / s0, vy / s0, k * wn / s0, math.log(s0)
    return y0


def _rows_moved(
    body: Body,
    friction: FrictionTensor,
    state: State,
    name: str,
    value: float,
    g: float,
    base: tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]],
):
    """:func:`_rows` of :func:`_perturbed` for a parameter of the tensor or the body: for the
    tensor's entries and the inertia, the body's own rows ``base`` = (par, geo, y₀) with the
    entries the parameter moves (the tensor's, the radius of gyration), without the engine
    rows made afresh (a new tensor or body would make a footprint's geometry again); for the
    pressure centre, the new body's rows. (The start's parameters move y₀ only:
    :func:`_start_derivative`.)"""
    if name in ("xi_c", "eta_c"):
        return _rows(*_perturbed(body, friction, state, name, value), g)
    par = base[0].copy()
    a = body.length_unit
    st = state
    unit = _entry_direction(friction, name)
    if unit is not None:
        # the tensor is linear in its entries: 𝔽 + (value − entry) R E Rᵀ
        # (:func:`_entry_direction`), without a new (validated) FrictionTensor, so also
        # about an entry at the end of its range (the rows only carry the rates)
        d = value - getattr(friction, name)
        for i, e in zip(_TENSOR_ROWS, unit, strict=True):
            par[i] += d * e
        return par, base[1], base[2]
    if name == "moment_of_inertia" and _inertia_in_range(body, value):
        # k = √(I/m) in units of a, without a new (validated) Body
        par[_engine.P_K] = math.sqrt(value / body.mass) / a
        return par, base[1], _start(par, a, g, st.vx, st.vy, st.omega, st.x, st.y, st.phi)
    b, fr, st = _perturbed(body, friction, state, name, value)
    if name == "moment_of_inertia":
        par[_engine.P_K] = b.radius_of_gyration / a
        return par, base[1], _start(par, a, g, st.vx, st.vy, st.omega, st.x, st.y, st.phi)
    t = fr.kinetic.matrix
    par[_engine.P_T00], par[_engine.P_T01] = t[0]
    par[_engine.P_T10], par[_engine.P_T11] = t[1]
    return par, base[1], base[2]


#: the engine rows' tensor entries (𝔽₀₀, 𝔽₀₁, 𝔽₁₀, 𝔽₁₁)
_TENSOR_ROWS = (_engine.P_T00, _engine.P_T01, _engine.P_T10, _engine.P_T11)


def _entry_direction(friction: FrictionTensor, name: str) -> tuple[float, ...] | None:
    """∂𝔽/∂θ (entries 00, 01, 10, 11, as :data:`_TENSOR_ROWS`) of the kinetic tensor for a
    tensor entry θ = fx, fy, f: R E Rᵀ, R the turn by its angle, E the entry's unit matrix
    (fx: [[1, 0], [0, 0]]; fy: [[0, 0], [0, 1]]; f: [[0, 1], [−1, 0]], unchanged by the
    turn); None for another parameter."""
    if name not in ("fx", "fy", "f"):
        return None
    if name == "f":
        return (0.0, 1.0, -1.0, 0.0)
    c, sn = math.cos(friction.angle), math.sin(friction.angle)
    if name == "fx":
        return (c * c, c * sn, c * sn, sn * sn)
    return (sn * sn, -c * sn, -c * sn, c * c)


def _inertia_in_range(body: Body, value: float) -> bool:
    """Whether a moment of inertia ``value`` is one Body accepts for ``body`` (I/(m a²) in
    its range; else the slow path makes the Body, and its error)."""
    lo, hi = v.INERTIA_RATIO
    return value > 0.0 and lo <= value / body.mass / body.length_unit**2 <= hi


#: the start's parameters (they move y₀ only)
_START = ("vx", "vy", "omega", "phi0")


def _start_derivative(y0, par, name: str, t_unit: float, v_unit: float) -> list[float]:
    """∂y₀/∂θ (per SI unit of θ) of the regularised start y₀ = (u, ln s, 0, x, y, φ, 0), with
    s u = (vx, vy, k ω) in natural units, for a start parameter θ: the velocity's
    ∂u = (e − u u_e)/s, ∂ln s = u_e/s along the component e it moves."""
    d = [0.0] * NY
    if name == "phi0":
        d[7] = 1.0
        return d
    u = (float(y0[0]), float(y0[1]), float(y0[2]))
    inv_s = math.exp(-float(y0[3]))
    e = ("vx", "vy", "omega").index(name)
    scale = inv_s / v_unit if e < 2 else inv_s * float(par[_engine.P_K]) * t_unit
    d[:3] = [-ui * u[e] * scale for ui in u]
    d[e] += scale
    d[3] = u[e] * scale
    return d


def compute(
    body: Body,
    friction: FrictionTensor,
    state: State,
    parameters: tuple[str, ...],
    g: float,
    rtol: float,
    ending: str,
    eigenvalue_ratio: float,
    taus: NDArray[np.float64],
    rows: NDArray[np.float64],
    accel: NDArray[np.float64],
    stages: NDArray[np.float64] | None = None,
    engine: tuple | None = None,
) -> Sensitivities:
    """Run the sensitivities of a free motion whose plain run (:func:`slidespin.simulate`)
    stopped with ``ending`` at a fixed point with ``eigenvalue_ratio``; ``taus`` are its
    records' regularised times, ``rows`` its states there and then at the stop (natural units),
    ``accel`` the natural accelerations (Fx, Fy, M/k) at the rows (for the fixed-t
    conversion), ``stages`` the plain run's records with its steps' stages (``integrate_on``
    with ``stages``) for the collocation on its steps, or None to integrate the sensitivities
    with the motion; ``engine`` the body's engine rows
    (:meth:`~slidespin.contact.body.Body.engine_params` at ``WRENCH_TOL``) if the caller has
    them. Validated inputs only (``simulate`` checks them)."""
    names = tuple(parameters)
    a = body.length_unit
    t_unit = math.sqrt(a / g)
    v_unit = math.sqrt(a * g)
    if engine is None:
        engine = body.engine_params(friction.kinetic, WRENCH_TOL)
    par0, fe, fc, geo0 = engine
    y0 = rows[0]  # the plain run's start: the same arithmetic as _rows
    npar = len(names)
    pars = np.empty((1 + 2 * npar, par0.size))  # (the rows a parameter moves replaced below)
    pars[:] = par0
    geos = np.empty((1 + 2 * npar, geo0.size))
    geos[:] = geo0
    hs = np.empty(npar)
    Y0 = np.zeros(NY * (1 + npar))
    Y0[:NY] = y0
    dk = np.zeros(npar)  # ∂k/∂θ (natural radius of gyration; only the inertia moves it)
    for k, name in enumerate(names):
        h = _step(body, friction, state, name)
        hs[k] = h
        if name in _START:  # the rows stay; ∂y₀/∂θ in closed form
            Y0[NY * (k + 1) : NY * (k + 2)] = _start_derivative(y0, par0, name, t_unit, v_unit)
            continue
        val = _value(body, friction, state, name)
        unit = _entry_direction(friction, name)
        if unit is not None:
            # the tensor is linear in its entries: 𝔽 ± h R E Rᵀ in the rows of θ ± h, in
            # place (the rows' other entries, G and the start do not move); an entry at the
            # end of its valid range too (fx = 5, fy = 1e-6: the rows only carry rates)
            for row, dh in ((1 + 2 * k, h), (2 + 2 * k, -h)):
                for i, e in zip(_TENSOR_ROWS, unit, strict=True):
                    pars[row, i] += dh * e
            continue
        pp, gp, yp = _rows_moved(body, friction, state, name, val + h, g, (par0, geo0, y0))
        if name in ("xi_c", "eta_c"):
            # G, the ellipse's law and the footprint's pressure coefficients are linear in
            # the pressure centre (MODEL §10): the row at val − h mirrors the one at val + h
            # (one new body's geometry per parameter, not two; the start does not move)
            pm, gm, ym = pp.copy(), 2.0 * geo0 - gp, yp
            for i in (_engine.P_XG, _engine.P_YG):
                pm[i] = 2.0 * par0[i] - pp[i]
        else:
            pm, gm, ym = _rows_moved(body, friction, state, name, val - h, g, (par0, geo0, y0))
        pars[1 + 2 * k], pars[2 + 2 * k] = pp, pm
        if gp is not geo0 or gm is not geo0:
            geos[1 + 2 * k], geos[2 + 2 * k] = gp, gm
        if yp is not y0 or ym is not y0:
            Y0[NY * (k + 1) : NY * (k + 2)] = (yp - ym) / (2.0 * h)
            dk[k] = (pp[_engine.P_K] - pm[_engine.P_K]) / (2.0 * h)
    tol = max(rtol, RUN_TOL)
    yterm = np.asarray(rows[-1], dtype=np.float64).copy()  # the stop: u*, φ*
    yterm[:3] /= math.sqrt(yterm[0] ** 2 + yterm[1] ** 2 + yterm[2] ** 2)
    collocate = stages is not None
    if stages is None:
        stages = np.zeros((taus.size, 1 + NY + (_dop.N_STAGES + 1) * NY))
    Y, F, status, nsteps, fails, rec, term = _core.run(
        pars, fe, fc, geos, hs, Y0, tol, tol, LN_DROP, CONV_TOL, collocate, MAX_STEPS, taus,
        rows[:-1], stages, yterm,
    )  # fmt: skip
    if status != _core.SS_CONVERGED or fails:
        raise RuntimeError(
            f"the sensitivity run ended with status {status} after {nsteps} steps "
            f"({fails} wrench evaluations off their target) before its derivatives "
            "converged; please report this case"
        )
    k0 = par0[_engine.P_K]
    stop: dict[str, dict[str, float]] = {}
    path: dict[str, dict[str, NDArray[np.float64]]] = {}
    u_stop, phi_stop = rows[-1, :3], rows[-1, 7]
    su = np.full((npar, 3), np.nan)
    if ending == "mixed":
        s_phi = Y[NY + 7 :: NY][:npar]
        su, ok = _core.terminal_direction_sensitivity(u_stop, term, s_phi)
        if not ok:  # no exact terms there, or J_T (nearly) singular: the general route
            su = _terminal_sensitivity(pars, fe, fc, geos, hs, u_stop, phi_stop, s_phi, term)
    kinked = _breaks_symmetry(par0, friction, names) if ending == "mixed" else ()
    jumps = _leaves_invariant_set(ending, eigenvalue_ratio, names)
    if ending == "spiral":
        warnings.warn(
            "the motion ends in a spiral (its direction keeps turning: no terminal direction "
            "and no beta_stop): the derivatives of beta_stop are NaN",
            RuntimeWarning,
            stacklevel=3,
        )
    if jumps:
        warnings.warn(
            f"the motion ends {ending} at a fixed point that does not attract nearby motions "
            f"(eigenvalue ratio {eigenvalue_ratio:.3g} >= 0): beta_stop jumps under a change "
            f"of {', '.join(jumps)}, and its derivative is NaN",
            RuntimeWarning,
            stacklevel=3,
        )
    if kinked:
        warnings.warn(
            f"beta_stop is not differentiable with respect to {', '.join(kinked)} here: the "
            "body is round about G under an isotropic tensor, so every direction of the "
            "terminal velocity is one (a circle of terminal states), and a change of "
            f"{', '.join(kinked)} breaks that symmetry (beta_stop changes like |change|); "
            "their beta_stop derivatives are NaN",
            RuntimeWarning,
            stacklevel=3,
        )
    fixed = _core.path_at_fixed_time(rows, accel, rec, Y, k0, dk, a, t_unit, v_unit)
    # (Python floats from here: a few dozen scalars, no NumPy scalar arithmetic)
    yl, sul, dkl = Y.tolist(), su.tolist(), dk.tolist()
    ul, kf = u_stop.tolist(), float(k0)
    for k, name in enumerate(names):
        o = NY * (k + 1)
        beta = _beta_derivative(ending, ul, sul[k], kf, dkl[k]) * a
        stop[name] = {
            "t_stop": yl[o + 4] * t_unit,
            "x": yl[o + 5] * a,
            "y": yl[o + 6] * a,
            "phi": yl[o + 7],
            "beta_stop": math.nan if name in kinked or name in jumps else beta,
        }
        path[name] = dict(zip(PATH_OUTPUTS, fixed[:, :, k], strict=True))
    return Sensitivities(
        parameters=names, t=rows[:, 4] * t_unit, path=path, stop=stop, n_steps=int(nsteps)
    )


def _accelerations(par, fe, fc, geo, phi: float, U: NDArray) -> NDArray:
    """A(u, φ) = (Fx, Fy, M/k) (natural units) for the unit directions ``U`` (n, 3)."""
    k = par[_engine.P_K]
    n = U.shape[0]
    ph = np.full(n, phi)
    if par[_engine.P_SHAPE] == _engine.SHAPE_FOOTPRINT:
        fx, fy, mm = _integrator.wrench_rows(par, fe, fc, geo, ph, U[:, 0], U[:, 1], U[:, 2] / k)
    else:
        args = _engine.elliptic_args(par)
        fx, fy, mm, _ = ellipse_wrench_array(*args, ph, U[:, 0], U[:, 1], U[:, 2] / k,
                                             WRENCH_TOL)  # fmt: skip
    return np.column_stack([fx, fy, mm / k])


def _sphere_flow(par, fe, fc, geo, phi: float, U: NDArray) -> NDArray:
    """T(u) = A − (u·A) u, the flow of the direction (MODEL §5), at the directions ``U``
    (normalised here)."""
    U = U / np.linalg.norm(U, axis=1)[:, None]
    A = _accelerations(par, fe, fc, geo, phi, U)
    return A - np.sum(U * A, axis=1)[:, None] * U


def _terminal_sensitivity(pars, fe, fc, geos, hs, u, phi, s_phi, term) -> NDArray:
    """∂u*/∂θ_k of the terminal direction (a mixed ending), by the implicit function theorem
    on its fixed-point condition T(u*, φ*; θ) = 0 on the sphere (MODEL §5, §15):
    J_T ∂u* = −(∂T/∂φ ∂φ*/∂θ + ∂T/∂θ) in the tangent plane at u*, with ∂φ*/∂θ = ``s_phi``
    from the run. J_T, ∂T/∂φ and ∂T/∂θ are the rows 0–2 of the run's ``term`` (the exact
    derivatives of :func:`slidespin.motion._sensitivity_rhs.stop_terms`); where the kernel
    has none there (a blade; a derivative off its error target), J_T and ∂T/∂φ are central
    differences of the exact wrench
    (steps ``REL_STEP``). (Integrating S_u to its limit instead converges only at the fixed
    point's eigenvalue, slowly near a Table 2 boundary.)"""
    u = u / math.sqrt(u @ u)
    eye = np.eye(3)
    if np.all(np.isfinite(term[:NY])):
        jac = term[:3, :3]
        dphi = term[:3, 7]
    else:
        par, geo = pars[0], geos[0]
        d = REL_STEP
        U = np.vstack([u + d * eye, u - d * eye])
        T = _sphere_flow(par, fe, fc, geo, phi, U)
        jac = (T[:3] - T[3:]).T / (2.0 * d)  # columns ∂T/∂u_i
        tp = _sphere_flow(par, fe, fc, geo, phi + d, u[None, :])[0]
        tm = _sphere_flow(par, fe, fc, geo, phi - d, u[None, :])[0]
        dphi = (tp - tm) / (2.0 * d)
    # an orthonormal basis (B) of the tangent plane at u
    e = eye[int(np.argmin(np.abs(u)))]
    b1 = e - (e @ u) * u
    b1 /= math.sqrt(b1 @ b1)
    b2 = np.array([u[1] * b1[2] - u[2] * b1[1], u[2] * b1[0] - u[0] * b1[2],
                   u[0] * b1[1] - u[1] * b1[0]])  # fmt: skip
    B = np.column_stack([b1, b2])
    jt = B.T @ jac @ B
    rhs = dphi[:, None] * np.asarray(s_phi)[None, :] + term[NY : NY + hs.size, :3].T
    return (B @ _solve_transverse(jt, -(B.T @ rhs))).T


def _leaves_invariant_set(ending: str, ratio: float, names: tuple[str, ...]) -> tuple[str, ...]:
    """The parameters among ``names`` whose change takes a motion off the invariant set it
    ends on when that ending does not attract nearby motions (eigenvalue ratio ≥ 0: the
    start lies on the set): β* jumps there. Pure translation stays pure translation under
    any parameter but the spin (the traction has one direction and no moment about the
    pressure centroid G); pure spin about G stays pure spin (the pressure is centrally
    symmetric about G, MODEL §9) unless the start gets a velocity or G moves."""
    if ending not in ("pure_sliding", "pure_spinning") or ratio < 0.0:
        return ()
    moving = ("omega",) if ending == "pure_sliding" else ("vx", "vy", "xi_c", "eta_c")
    return tuple(n for n in names if n in moving)


def _breaks_symmetry(par, friction: FrictionTensor, names: tuple[str, ...]) -> tuple[str, ...]:
    """The parameters among ``names`` that break the rotational symmetry of a round body
    (axisymmetric pressure about G) under an isotropic tensor (fx = fy, any f): at such a
    point β* has a kink in them (MODEL §9: the terminal directions form a circle)."""
    kin = friction.kinetic
    if kin.fx != kin.fy:
        return ()
    if par[_engine.P_SHAPE] == _engine.SHAPE_FOOTPRINT:
        round_body = par[_engine.P_RSYM] != 0.0
    else:
        round_body = par[_engine.P_BN] == 1.0 and par[_engine.P_XG] == par[_engine.P_YG] == 0.0
    if not round_body:
        return ()
    return tuple(n for n in names if n in ("fx", "fy", "xi_c", "eta_c"))


def _solve_transverse(jt: NDArray, b: NDArray) -> NDArray:
    """J_T x = b in the tangent plane (b a column per parameter); where J_T is singular (a body symmetric about G under an
    isotropic tensor has a circle of terminal directions: the velocity's direction is free,
    β* the same all along it), the part of b along the zero eigenvalue's eigenvector only
    moves u* along that circle and is dropped: x is the response across it, which is what
    changes β*."""
    lam, vec = np.linalg.eig(jt)
    big = float(np.max(np.abs(lam)))
    try:
        if big == 0.0 or float(np.min(np.abs(lam))) > 1e-7 * big:
            return np.linalg.solve(jt, b)
        coef = np.linalg.solve(vec, b)
    except np.linalg.LinAlgError:  # a defective J_T: the least-squares response
        return np.linalg.lstsq(jt, b, rcond=1e-7)[0]
    keep = np.abs(lam) > 1e-7 * big
    return np.real(vec[:, keep] @ (coef[keep] / lam[keep, None]))


def _beta_derivative(
    ending: str, u: Sequence[float], su: Sequence[float], k: float, dk: float
) -> float:
    """∂(β*/ℓ)/∂θ with β*/ℓ = k u₁₂/u₃ (MODEL §5) at the terminal direction ``u`` and its
    sensitivity ``su``; 0 for a pure ending (β* stays ∞ or 0 nearby), NaN for a spiral
    (no terminal direction)."""
    if ending == "spiral":
        return math.nan
    if ending != "mixed":
        return 0.0
    u1, u2, u3 = u[0], u[1], u[2]
    nrm = math.sqrt(u1 * u1 + u2 * u2 + u3 * u3)
    u1, u2, u3 = u1 / nrm, u2 / nrm, u3 / nrm
    u12 = math.hypot(u1, u2)
    du12 = (u1 * su[0] + u2 * su[1]) / u12
    du3 = su[2]
    return dk * u12 / u3 + k * (du12 * u3 - u12 * du3) / (u3 * u3)
