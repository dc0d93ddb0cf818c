"""Identification of friction parameters from tracked motion (MODEL §12).

Experimentalists track a sliding and spinning body (the position of its mass centre G and its
angle) and want the friction behind the motion. :func:`fit` finds the parameters θ, shared by
all runs, and each run's start state by weighted least squares,

    minimise  Σ_runs Σ_channels Σ_i ρ(r²),   r = (measured − simulated)/σ_channel,

with the simulation evaluated at the measured times, and reports the estimates with standard
errors from the covariance (JᵀJ)⁻¹ at the optimum (σ estimated from the residuals where it is
not given), the correlation matrix, and an honest verdict on identifiability.

The tracked runs are read and checked by :mod:`slidespin.analysis.fit_data`; the least-squares
problem lives in ``slidespin.analysis._fit_problem``; the outcome is a
:class:`~slidespin.analysis.fit_result.FitResult`.

Parameters that may be fitted (``free``), with their code names:

=====================  ================================================  =========================
name                   meaning                                           bounds
=====================  ================================================  =========================
``fx``, ``fy``         principal coefficients of 𝔽 (paper eq. 2)         > 0 (dissipative), within
                                                                         FrictionTensor's range
``f``                  skew coefficient of 𝔽                             FrictionTensor's range
``angle``              angle of 𝔽's principal axes [rad]                 [−2π, 2π], FrictionTensor's
``xi_c``, ``eta_c``    linear law's pressure centroid = G [m] (eq. 10)   |ξc| ≤ a/4, |ηc| ≤ b/4;
                                                                         a footprint: its core
``moment_of_inertia``  I about G [kg m²]                                 [1e-4, 1e4] × the guess
=====================  ================================================  =========================

The body may rest on an ellipse or on any footprint of :mod:`slidespin.contact.shapes` (uniform or
linear pressure, MODEL §10), a ``Blade`` included (its uniform line load keeps G over its
centre: ``xi_c``, ``eta_c`` are not free there). G of the linear law is kept in the core of the patch, where the
pressure is ≥ 0: the ellipse's (ξc/a)² + (ηc/b)² ≤ 1/16, a footprint's core (for a rectangle
the middle-third rhombus |ξc|/(L/6) + |ηc|/(W/6) ≤ 1); a trial G outside it is projected onto
it towards the area centroid. On a footprint the length a below is its extent ℓ
(:attr:`slidespin.Body.length_unit`).

The tensor's ``frame`` (plane or body) is discrete and is not fitted by :func:`fit`: it is
taken from the ``friction`` given. :func:`compare_frames` fits both frames and returns the
better by the likelihood (:func:`frame_score`).

Each run has its own start state (x, y, φ, vx, vy, ω) at its first measured time. A position
channel present in a run makes that run's position and velocity along it free (x → x, vx;
y → y, vy; phi → φ, ω); the other components stay at ``start_guess`` (default zero) unless
``start_free`` says otherwise; ``starts`` fixes a run's whole start state.

Numerics. ``simulate`` records the integrator's steps; the trajectory between them is the
cubic Hermite interpolant of (x, vx), (y, vy), (φ, ω), whose error with the defaults
(rtol = 1e-12, the integrator's own steps) is below 1e-6 a and 1e-5 rad (measured against a
dense run in the tests; typically 3e-7 a), far below any tracking noise; after the stop the
body rests at the stop state. The Jacobian is computed one run at a time (a run depends only
on the shared parameters and its own start): by central differences of whole simulations,
or with ``jacobian="exact"`` from the motion's sensitivities (MODEL §15;
:mod:`slidespin.motion.sensitivity`), interpolated to the measured times like the motion
(∂x/∂θ with its rate ∂vx/∂θ at fixed t), one sensitivity run per run and Jacobian. The
derivatives with respect to the start position x₀, y₀ are exact either way: the motion is
invariant under translation. Trajectories depend on the parameters smoothly except through the stop
time, where x(t) is still continuously differentiable (the velocity vanishes at the stop).

Identifiability. The Jacobian is scaled by each parameter's typical size (``fx``, ``fy``,
``f``: max(fx, fy) of the guess; ``angle``: 1 rad; ``xi_c``, ``eta_c``: a/4, b/4 (ℓ/4 on a footprint); ``I``: its
guess; start positions: a; start velocities: the run's speed scale). A singular value s < 1 of
that matrix is a combination of parameters that a change of its typical size moves the total
χ² by less than 1: the data cannot determine it. Parameters taking part in it (weight ≥ 0.1)
are reported as not identifiable, with an infinite standard error, and an
:class:`IdentifiabilityWarning` names them; so does any pair whose |correlation| exceeds
``corr_limit`` (0.99).
"""

from __future__ import annotations

import contextlib
import math
import numbers
import time
import warnings
from collections.abc import Mapping
from dataclasses import replace

import numpy as np
from scipy.optimize import least_squares

from slidespin import _validate as v
from slidespin.analysis._fit_problem import _Problem, _wrap
from slidespin.analysis.fit_data import (
    _UNITS,
    CHANNELS,
    START,
    _guess_start,
    _noise_from_data,
    as_runs,
)
from slidespin.analysis.fit_result import FitResult
from slidespin.contact.body import Body, check_body_friction
from slidespin.contact.friction import FrictionTensor
from slidespin.contact.pressure import LinearPressure
from slidespin.motion.state import State

__all__ = [
    "LOSSES",
    "MAX_FD_STEP",
    "MIN_FD_STEP",
    "PARAMETERS",
    "FitWarning",
    "IdentifiabilityWarning",
    "compare_frames",
    "fit",
    "frame_score",
]

#: parameters that :func:`fit` can free
PARAMETERS = ("fx", "fy", "f", "angle", "xi_c", "eta_c", "moment_of_inertia")
#: how :func:`fit` computes its Jacobian (central differences, or MODEL §15's sensitivities)
JACOBIANS = ("differences", "exact")
#: loss functions of :func:`scipy.optimize.least_squares` accepted by :func:`fit`
LOSSES = ("linear", "soft_l1", "huber", "cauchy", "arctan")
#: singular values of the typical-size-scaled Jacobian below this are undetermined directions
SINGULAR_TOL = 1.0
#: a parameter with at least this weight in an undetermined direction is not identifiable
WEIGHT_TOL = 0.1
#: trust-region solver of least_squares: "exact" (an SVD of the Jacobian each step) converges
#: in far fewer evaluations than "lsmr" on ill-conditioned problems
TR_SOLVER = "exact"
#: smallest relative central-difference step ``fd_step`` of :func:`fit` (below, the
#: differences drown in the integrator's error)
MIN_FD_STEP = 1e-8
#: largest relative central-difference step ``fd_step`` of :func:`fit`
MAX_FD_STEP = 0.1


class FitWarning(UserWarning):
    """Something about a fit the user should know (no convergence, a parameter at a bound)."""


class IdentifiabilityWarning(FitWarning):
    """The data cannot determine some parameters (their names are in the message)."""


# --------------------------------------------------------------------------------------------
# the linear algebra at the optimum


def _one_blas_thread():
    """Limit BLAS to one thread (if threadpoolctl is installed): the SVD of a tall Jacobian
    (3000 x 33) takes 5 ms on one thread but up to 0.9 s with threads on a busy machine."""
    try:
        # lazy: threadpoolctl is an optional dependency
        from threadpoolctl import threadpool_limits
    except ImportError:  # pragma: no cover - optional
        return contextlib.nullcontext()
    return threadpool_limits(1, user_api="blas")


def _undetermined(J, typ):
    """SVD of the Jacobian scaled by typical sizes; indices of undetermined parameters."""
    # QR first: the SVD of the small triangle is cheap where a threaded SVD of the tall
    # Jacobian can be slow on a busy machine
    r = np.linalg.qr(J * typ[None, :], mode="r")
    _, s, vt = np.linalg.svd(r)
    bad = set()
    for i in np.flatnonzero(s < SINGULAR_TOL):
        bad.update(int(j) for j in np.flatnonzero(np.abs(vt[i]) >= WEIGHT_TOL))
    return s, vt, bad


def _loss_weights(z, loss):
    """ρ'(z) of scipy's losses, z = (r/f_scale)²: the IRLS weight of each residual."""
    if loss == "linear":
        return np.ones_like(z)
    if loss == "soft_l1":
        return 1.0 / np.sqrt(1.0 + z)
    if loss == "huber":
        return np.where(z <= 1.0, 1.0, 1.0 / np.sqrt(np.maximum(z, 1.0)))
    if loss == "cauchy":
        return 1.0 / (1.0 + z)
    return 1.0 / (1.0 + z * z)  # arctan


# --------------------------------------------------------------------------------------------
# the fit


def _check_free(free, body):
    if isinstance(free, str):
        free = tuple(s.strip() for s in free.split(",") if s.strip())
    try:
        free = tuple(free)
    except TypeError:
        raise ValueError(
            f"free = {free!r} is invalid; valid values: names from {', '.join(PARAMETERS)}"
        ) from None
    for p in free:
        if p not in PARAMETERS:
            raise ValueError(
                f"free parameter {p!r} is unknown; valid names: {', '.join(PARAMETERS)} "
                "(the tensor's frame is discrete: compare_frames, or --frame best, fits both)"
            )
    dup = sorted({p for p in free if free.count(p) > 1})
    if dup:
        raise ValueError(
            f"free parameter {dup[0]!r} is given twice; valid values: distinct names from "
            f"{', '.join(PARAMETERS)}"
        )
    if ("xi_c" in free or "eta_c" in free) and not isinstance(body.pressure, LinearPressure):
        raise ValueError(
            f"free parameters xi_c, eta_c need a body with LinearPressure; this body has "
            f"{type(body.pressure).__name__}; valid values: a body with LinearPressure(xi_c, "
            "eta_c) (not on a Blade), or free parameters without xi_c, eta_c"
        )
    return free


def _check_states(name, value, n, allow_none):
    if value is None:
        return [None] * n
    if isinstance(value, State):
        return [value] * n
    if isinstance(value, (list, tuple)) and len(value) == n:
        for i, s in enumerate(value):
            if not (isinstance(s, State) or (allow_none and s is None)):
                raise ValueError(
                    f"{name}[{i}] = {s!r} is invalid; valid values: a State"
                    + (" or None" if allow_none else "")
                )
        return list(value)
    raise ValueError(
        f"{name} = {value!r} is invalid; valid values: None, a State, or a list of "
        f"{n} States (one per run)"
    )


def fit(
    data,
    body: Body,
    friction: FrictionTensor,
    free=("fx", "fy", "f"),
    *,
    starts=None,
    start_guess=None,
    start_free=None,
    sigma=None,
    loss: str = "linear",
    f_scale: float = 2.0,
    g: float = 9.81,
    rtol: float = 1e-12,
    max_step: float | None = None,
    fd_step: float = 1e-4,
    corr_limit: float = 0.99,
    max_nfev: int | None = None,
    jacobian: str = "differences",
) -> FitResult:
    """Fit friction parameters (and each run's start state) to tracked motion (MODEL §12).

    Parameters
    ----------
    data : run or list of runs
        A run maps ``t`` [s] and any of ``x``, ``y`` [m] (mass centre G) and ``phi`` [rad]
        to arrays (a dict or a NumPy structured array;
        :func:`~slidespin.analysis.fit_data.read_runs` reads CSV). Runs share the physical
        parameters; each has its own start state at its first time.
    body : Body
        Patch, pressure law, mass and moment of inertia (the guess of any that is free).
    friction : FrictionTensor
        The tensor; its values are the start guesses of the free ones, its frame is kept.
    free : sequence of str or str, default ("fx", "fy", "f")
        Physical parameters to fit, from ``PARAMETERS`` (also ``"fx,fy,f"``).
    starts : None, State, or list of (State or None)
        Known start states (at each run's first time); a run with ``None`` has its start
        fitted. A single State applies to every run.
    start_guess : None, State, or list of (State or None)
        Values of the start components the data do not give (default: zero), and the guess
        of those in ``start_free``. Channels present in a run give its own guess (a quadratic
        fit to its first points).
    start_free : sequence of str, optional
        Start components fitted in every run whose start is not known, from
        ``x, y, phi, vx, vy, omega``. Default: the pairs of the channels measured in the run.
    sigma : dict, optional
        Noise level of each channel, ``{'x': m, 'y': m, 'phi': rad}``; channels missing here
        have their σ estimated from the residuals (RMS, or the MAD for a robust ``loss``).
    loss : {"linear", "soft_l1", "huber", "cauchy", "arctan"}
        Loss of :func:`scipy.optimize.least_squares`; a robust one limits outliers' pull.
    f_scale : float, default 2
        Residual (in units of σ) beyond which a robust loss down-weights a point.
    g : float, default 9.81
        Gravitational acceleration [m/s²].
    rtol, max_step : float
        Passed to :func:`slidespin.simulate`. With the defaults (1e-12, the integrator's own
        steps) the model between steps (cubic Hermite) is within 1e-6 a and 1e-5 rad of a
        dense run (tests/analysis/test_fit.py), far below tracking noise.
    fd_step : float, default 1e-4
        Central-difference step, relative to each parameter's typical size; valid:
        [:data:`MIN_FD_STEP`, :data:`MAX_FD_STEP`] = [1e-8, 0.1] (a smaller step differences
        round-off of the simulated motion, a larger one is no longer a derivative).
    corr_limit : float, default 0.99
        |correlation| above which a pair of parameters is reported as not separable.
    max_nfev : int, optional
        Budget of residual evaluations for each least-squares pass.
    jacobian : {"differences", "exact"}, default "differences"
        How the Jacobian is computed: ``"differences"``, central differences of whole
        simulations with ``fd_step`` (two simulations per parameter and run), or ``"exact"``,
        from the motion's sensitivities at the measured times
        (:mod:`slidespin.motion.sensitivity`, MODEL §15: one sensitivity run per run, no
        step-size error; a run whose motion does not stop falls back to differences). Both
        reach the same estimates (``examples/fit_benchmark.py``: within 1e-3 of a standard
        error); "exact" is 3.4× faster there (docs/sensitivities.md), but a run whose
        motion does not stop falls back to differences, hence not the default.

    Returns
    -------
    FitResult

    Warns
    -----
    IdentifiabilityWarning
        When the data cannot determine some parameters (named in the message).
    FitWarning
        When the optimiser did not converge or a parameter ends at a bound.

    Notes
    -----
    With σ estimated, the fit alternates least squares and σ̂² = Σr²/(n_c (N − P)/N) per
    channel until σ̂ changes by less than 5 %; the covariance is (JᵀJ)⁻¹ with J the Jacobian
    of r = residual/σ̂ at the optimum, i.e. (J₀ᵀJ₀)⁻¹σ̂² (MODEL §12). For a robust loss, J's rows
    are weighted by √ρ'(r²/f_scale²) (iteratively reweighted least squares).
    """
    t_start = time.perf_counter()
    check_body_friction(body, friction)
    runs = as_runs(data)
    free = _check_free(free, body)
    loss = v.choice("loss", loss, LOSSES)
    f_scale = v.positive("f_scale", f_scale)
    g = v.positive("g", g, "m/s^2")
    rtol = v.in_range("rtol", rtol, 0.0, 1e-3, lo_open=True)
    max_step = None if max_step is None else v.positive("max_step", max_step)
    fd_step = v.in_range("fd_step", fd_step, MIN_FD_STEP, MAX_FD_STEP)
    if jacobian not in JACOBIANS:
        raise ValueError(
            f"jacobian = {v._short(jacobian)} is invalid; valid values: {', '.join(JACOBIANS)}"
        )
    corr_limit = v.in_range("corr_limit", corr_limit, 0.0, 1.0, lo_open=True)
    if max_nfev is not None and (
        isinstance(max_nfev, bool) or not isinstance(max_nfev, numbers.Integral) or max_nfev < 1
    ):
        raise ValueError(f"max_nfev = {max_nfev!r} is invalid; valid range: integer >= 1")
    n = len(runs)
    fixed = _check_states("starts", starts, n, True)
    guesses = _check_states("start_guess", start_guess, n, True)
    if start_free is not None:
        start_free = tuple(start_free)
        for c in start_free:
            if c not in START:
                raise ValueError(
                    f"start_free component {c!r} is unknown; valid: {', '.join(START)}"
                )
    present = [c for c in CHANNELS if any(c in r and np.isfinite(r[c]).any() for r in runs)]
    given = {}
    if sigma is not None:
        if not isinstance(sigma, Mapping):
            raise ValueError(
                f"sigma = {sigma!r} is invalid; valid values: a dict such as "
                "{'x': 1e-3, 'y': 1e-3, 'phi': 1e-2}"
            )
        for c, s in sigma.items():
            if c not in CHANNELS:
                raise ValueError(f"sigma channel {c!r} is unknown; valid: x, y, phi")
            given[c] = v.positive(f"sigma[{c!r}]", s, _UNITS[c])
    guess_states = []
    for k, run in enumerate(runs):
        if fixed[k] is not None:
            guess_states.append(fixed[k])
        else:
            guess_states.append(_guess_start(run, guesses[k] or State()))
    prob = _Problem(
        runs, body, friction, free, fixed, start_free, guess_states, g, rtol, max_step, fd_step,
        jacobian,
    )  # fmt: skip
    n_par = len(prob.names)
    if prob.n_obs <= n_par:
        raise ValueError(
            f"too few measured values: {prob.n_obs} for {n_par} fitted parameters "
            f"({', '.join(prob.names)}); valid range: more measured values than fitted "
            "parameters"
        )
    estimated = {c: c not in given for c in present}
    floor = {"x": 1e-10 * body.length_unit, "y": 1e-10 * body.length_unit, "phi": 1e-10}
    for c in present:
        prob.sigma[c] = given.get(c) or max(_noise_from_data(runs, c), floor[c])

    p = np.clip(prob.x0, prob.lb, prob.ub)
    fun = prob.residuals

    def jac(q):
        return prob.jacobian(q)

    nfev = 0
    res = None
    caught: list[str] = []
    for _ in range(6):
        with _one_blas_thread():
            res = least_squares(
                fun,
                p,
                jac=jac,
                bounds=(prob.lb, prob.ub),
                x_scale=prob.typ,
                loss=loss,
                f_scale=f_scale,
                method="trf",
                ftol=1e-9,
                xtol=1e-9,
                gtol=1e-9,
                max_nfev=max_nfev,
                tr_solver=TR_SOLVER,
            )
        p = res.x
        nfev += int(res.nfev)
        if not any(estimated.values()):
            break
        raw = prob.raw_residuals(p)
        changed = False
        for c in present:
            if not estimated[c]:
                continue
            rc = raw[prob.chan_of_row == c]
            frac = max(1.0 - n_par / prob.n_obs, 1e-3)
            if loss == "linear":
                s = math.sqrt(float(np.sum(rc * rc)) / (rc.size * frac))
            else:
                s = 1.4826 * float(np.median(np.abs(rc - np.median(rc)))) / math.sqrt(frac)
            s = max(s, floor[c])
            if abs(math.log(s / prob.sigma[c])) > math.log(1.05):
                changed = True
            prob.sigma[c] = s
        if not changed:
            break
    assert res is not None  # the loop runs at least once

    # covariance, identifiability
    r = prob.residuals(p)
    J = prob.jacobian(p)
    if loss != "linear":
        J = J * np.sqrt(_loss_weights((r / f_scale) ** 2, loss))[:, None]
    s, vt, not_ident = _undetermined(J, prob.typ)
    smax = float(s[0]) if s.size else 0.0
    condition = smax / float(s[-1]) if s.size and s[-1] > 0 else math.inf
    s_safe = np.maximum(s, max(smax, 1e-300) * 1e-15)
    cov_t = (vt.T / s_safe**2) @ vt
    cov = cov_t * np.outer(prob.typ, prob.typ)
    d = np.sqrt(np.diag(cov))
    corr = cov / np.outer(d, d)
    np.fill_diagonal(corr, 1.0)
    se = d.copy()
    # A start velocity the data do not tell from zero may carry the only information on a
    # parameter (a run sliding along x tells fy only through its noise-sized vy): judge
    # identifiability also with such velocities set to zero.
    p_null = p.copy()
    for j, name in enumerate(prob.names):
        if name.split(".")[-1] in ("vx", "vy", "omega") and abs(p[j]) < 2.0 * d[j]:
            p_null[j] = 0.0
    if np.any(p_null != p):
        J0 = prob.jacobian(p_null)
        if loss != "linear":
            J0 = J0 * np.sqrt(_loss_weights((prob.residuals(p_null) / f_scale) ** 2, loss))[:, None]
        not_ident |= _undetermined(J0, prob.typ)[2]
    for j in not_ident:
        se[j] = math.inf
        corr[j, :] = corr[:, j] = math.nan  # meaningless for an undetermined parameter
        corr[j, j] = 1.0
    names = prob.names
    identifiable = {name: (j not in not_ident) for j, name in enumerate(names)}

    msgs: list[tuple[type[FitWarning], str]] = []
    if not_ident:
        which = [names[j] for j in sorted(not_ident)]
        msgs.append(
            (
                IdentifiabilityWarning,
                (
                    f"the data cannot determine {', '.join(which)}: a change of their "
                    "typical size moves chi2 by less than 1 (standard errors reported as "
                    "inf)"
                ),
            )
        )
    pairs = []
    for i in range(n_par):
        for j in range(i + 1, n_par):
            if i in not_ident and j in not_ident:
                continue
            if abs(corr[i, j]) > corr_limit:
                pairs.append(f"{names[i]} and {names[j]} ({corr[i, j]:+.4f})")
    if pairs:
        msgs.append(
            (
                IdentifiabilityWarning,
                "the data hardly separate "
                + "; ".join(pairs)
                + f" (|correlation| > {corr_limit:g}): only a combination is determined",
            )
        )
    if not res.success:
        msgs.append((FitWarning, f"the least-squares fit did not converge: {res.message}"))
    at_bound = [
        f"{names[j]} = {p[j]:.6g} (valid range [{prob.lb[j]:.6g}, {prob.ub[j]:.6g}])"
        for j in range(n_par)
        if res.active_mask[j] != 0
    ]
    if at_bound:
        msgs.append((FitWarning, f"the fit ended at a bound: {'; '.join(at_bound)}"))
    for cls, m in msgs:
        warnings.warn(m, cls, stacklevel=2)
        caught.append(m)

    vals = prob.physical(p)
    fit_body, fit_fr = prob.objects(vals)
    data_out, fitted, resid, trajs, start_states, start_errs = [], [], [], [], [], []
    raw = prob.raw_residuals(p)
    for k, run in enumerate(runs):
        st = prob.start(p, k)
        at, traj = prob.model_run(vals, st, k)
        trajs.append(traj)
        start_states.append(State(*st))
        start_errs.append({names[i].split(".")[-1]: float(se[i]) for _, i in prob.start_index[k]})
        dd = {"t": run["t"].copy()}
        ff = {"t": run["t"].copy()}
        rr = {"t": run["t"].copy()}
        for c in CHANNELS:
            if c in run:
                dd[c] = run[c].copy()
                ff[c] = at[c]
                diff = run[c] - at[c]
                rr[c] = _wrap(diff) if c == "phi" else diff
        data_out.append(dd)
        fitted.append(ff)
        resid.append(rr)
    chi2 = float(np.sum(r * r))
    dof = prob.n_obs - n_par
    rms = {c: float(np.sqrt(np.mean(raw[prob.chan_of_row == c] ** 2))) for c in present}
    return FitResult(
        estimates={name: float(vals[name]) for name in free},
        std_errors={name: float(se[i]) for i, name in enumerate(free)},
        parameter_names=names,
        values=p.copy(),
        covariance=cov,
        correlation=corr,
        identifiable=identifiable,
        singular_values=s,
        condition=condition,
        starts=tuple(start_states),
        start_errors=tuple(start_errs),
        body=fit_body,
        friction=fit_fr,
        chi2=chi2,
        dof=dof,
        reduced_chi2=chi2 / dof,
        rms=rms,
        sigma={c: float(prob.sigma[c]) for c in present},
        sigma_estimated=estimated,
        n_points=prob.n_obs,
        n_runs=n,
        data=tuple(data_out),
        fitted=tuple(fitted),
        residuals=tuple(resid),
        trajectories=tuple(trajs),
        loss=loss,
        success=bool(res.success),
        message=str(res.message),
        nfev=nfev,
        warnings=tuple(caught),
        seconds=time.perf_counter() - t_start,
    )


def frame_score(result: FitResult) -> float:
    """−2 log-likelihood (up to a constant shared by fits of the same data) of a fit.

    With σ given for every channel it is χ²; with σ estimated it is the profile
    Σ_c n_c ln(SS_c/n_c) over the channels (SS_c the sum of squared residuals). Fits of the
    same data with the same number of parameters compare by this number: lower is better.
    """
    if not any(result.sigma_estimated.values()):
        return float(result.chi2)
    score = 0.0
    for c, estimated in result.sigma_estimated.items():
        r = np.concatenate([res[c][np.isfinite(res[c])] for res in result.residuals if c in res])
        if estimated:
            score += r.size * math.log(max(float(np.mean(r * r)), 1e-300))
        else:
            score += float(np.sum(r * r)) / result.sigma[c] ** 2
    return score


def compare_frames(data, body: Body, friction: FrictionTensor, free=("fx", "fy", "f"), **kwargs):
    """Fit with the tensor fixed to the plane and to the body; return the better fit.

    The frame is discrete, so it is chosen by fitting both (same free parameters, same
    options as :func:`fit`) and comparing :func:`frame_score` (−2 log-likelihood; both fits
    have the same number of parameters).

    Returns
    -------
    best : FitResult
        The fit with the lower score.
    scores : dict
        ``{"plane": score, "body": score}``.
    fits : dict
        Both fits.
    """
    if not isinstance(friction, FrictionTensor):
        raise ValueError(f"friction = {friction!r} is invalid; valid values: a FrictionTensor")
    fits, scores = {}, {}
    for frame in ("plane", "body"):
        fits[frame] = fit(data, body, replace(friction, frame=frame), free, **kwargs)
        scores[frame] = frame_score(fits[frame])
    best = min(scores, key=lambda frame: scores[frame])
    return fits[best], scores, fits
