"""Identification of friction from tracked pushes (MODEL §12 with §13's pushers).

A robot's finger pushes an object along a measured path; the object's pose is tracked and,
where a force sensor carries the finger, the pusher's force is measured too (the MIT push
dataset's layout, :mod:`slidespin.analysis.push_data`). :func:`fit_pushes` finds the physical
parameters θ shared by the pushes (the friction tensor's ``fx``, ``fy``, ``f``, ``angle``,
the pressure centre ``xi_c``, ``eta_c`` of a linear law, and, for the dynamic model, the
moment of inertia) and each push's start pose, by weighted least squares (MODEL §12)

    minimise  Σ_pushes Σ_channels Σ_i ρ(r²),   r = (measured − model)/σ_channel,

over the channels ``x``, ``y`` [m], ``phi`` [rad] of the object (at its tracked times) and,
when the push has ``ft_wrench`` samples and ``use_force`` is true, ``force_x``, ``force_y``
[N] of the pusher's force on the object (at the force samples' times; the negated sensor
force, :meth:`~slidespin.analysis.push_data.PushRun.pusher_force`). The model of a push is the
body led by a :class:`~slidespin.PointPusher` along the measured tip path, from rest at the
push's start pose at its first tracked time:

``model="dynamic"`` (default)
    :func:`slidespin.simulate` with the pusher (MODEL §13 dynamics: contact modes, plastic
    impacts, stick–slip on the plane), exact for pushes of any speed; the poses between the
    integrator's steps are the cubic Hermite interpolant of (x, vx), (y, vy), (φ, ω), the
    force is interpolated linearly (at the default ``rtol`` the interpolants move by ~2e-8 m,
    3e-7 rad and 2e-4 N against a run at rtol = 1e-11: far below tracking noise).
``model="quasi_static"``
    :func:`slidespin.push_quasi_static`: inertia neglected, the plane friction on its limit
    surface balancing the finger's force (MODEL §13, quasi-static limit), the standard model
    of slow pushing. Its poses do not depend on the friction's overall level (dry friction
    is rate-independent and the limit surface only scales), so **without force data only
    the tensor's shape is identifiable** (ratios such as fy/fx, f/fx, the angle, the
    pressure centre): the identifiability check names the undetermined combination.
    ``moment_of_inertia`` cannot be fitted. It misses the force m·a and the impact transients
    of a real push: on the four shipped synthetic pushes (25-30 mm/s, made with the dynamic
    model, fx and fy fitted with the force) its pose residuals match the tracking noise, its
    force residuals reach 1.8x the force noise (chi2/dof 1.5), and fx, fy come out 0.2-0.25 %
    low (1.6-1.8 standard errors), where the dynamic model gives chi2/dof 1.04 and
    -0.6 standard errors. It is also not cheaper here: the engine solves the limit surface at
    every output time (~1 ms each), so a push tracked at 100 Hz costs ~0.35 s against
    ~0.1 s for the dynamic run (that fit: 68 s against 26 s on a busy 2-core machine).

The measured tip path is thinned before it is used (``path_tolerance``): a row is dropped
while the piecewise-linear-in-time path through the kept rows stays within the tolerance of
every measured row (Ramer–Douglas–Peucker in time), so that a straight robot motion sampled
at 250 Hz becomes a few waypoints, and the engines do not restart at every sample.

Statistics, standard errors, correlations and the identifiability verdict are those of
:func:`slidespin.fit` (see :mod:`slidespin.analysis.fit`): the covariance (JᵀJ)⁻¹ σ̂² at the
optimum, with J by central differences (every column: a push is not invariant under a
translation of the object alone); σ of a channel not given in ``sigma`` is estimated from
the residuals. The result is a :class:`PushFitResult` (a :class:`~slidespin.FitResult`).

Assumptions: the object's tracked pose is the pose of G and of the body frame; the finger
is a point (a round probe of radius r is a point touching the outline grown by r: give
that ``outline``); μp (``mu``) is known; the object is at rest at its first tracked time.
"""

from __future__ import annotations

import math
import numbers
import time
import warnings
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field, replace

import numpy as np
from scipy.optimize import least_squares

from slidespin import _validate as v
from slidespin.analysis._fit_problem import _wrap
from slidespin.analysis._push_problem import (
    _FORCE,
    _POSE,
    PUSH_CHANNELS,
    _Push,
    _PushProblem,
    pushed_at,
)
from slidespin.analysis._push_problem import (
    TOUCH_FRACTION as TOUCH_FRACTION,
)
from slidespin.analysis.fit import (
    LOSSES,
    MAX_FD_STEP,
    MIN_FD_STEP,
    PARAMETERS,
    TR_SOLVER,
    FitWarning,
    IdentifiabilityWarning,
    _loss_weights,
    _one_blas_thread,
    _undetermined,
)
from slidespin.analysis.fit_result import FitResult
from slidespin.analysis.push_data import PushRun
from slidespin.contact.body import Body, check_body_friction
from slidespin.contact.friction import FrictionTensor
from slidespin.contact.pressure import LinearPressure
from slidespin.motion.pushed import simulate_pushed
from slidespin.motion.pushed_trajectory import PushedTrajectory
from slidespin.motion.quasi_static import QuasiStaticPush, push_quasi_static
from slidespin.motion.state import State

__all__ = ["MODELS", "PUSH_CHANNELS", "PushFitResult", "fit_pushes", "pushed_at"]

#: models of a push that :func:`fit_pushes` offers
MODELS = ("dynamic", "quasi_static")
#: relative tolerances of least_squares (ftol, xtol, gtol): a change of 1e-7 in the
#: parameters is far below any standard error from tracked pushes, and the push engines'
#: own error (rtol 1e-8) makes tighter tolerances cost iterations without moving them
LSQ_TOL = 1e-7
_UNITS = {"x": "m", "y": "m", "phi": "rad", "force_x": "N", "force_y": "N"}


# --------------------------------------------------------------------------------------------
# the result


@dataclass(frozen=True, slots=True, repr=False)
class PushFitResult(FitResult):
    """Outcome of :func:`fit_pushes`: a :class:`~slidespin.FitResult` whose channels include
    the pusher's force (MODEL §12–13).

    Differences from :class:`~slidespin.FitResult`: ``rms``, ``sigma`` and
    ``sigma_estimated`` may hold ``force_x``, ``force_y`` [N]; ``data``, ``fitted`` and
    ``residuals`` hold, per push, ``t``, ``x``, ``y``, ``phi`` at the tracked times and, with
    force data, ``t_force``, ``force_x``, ``force_y`` (times from the file's origin, as
    :class:`~slidespin.analysis.push_data.PushRun`); ``trajectories`` are
    :class:`~slidespin.QuasiStaticPush` or :class:`~slidespin.PushedTrajectory` objects
    (time from the push's first tracked time); ``starts`` are the poses at rest there.

    Attributes
    ----------
    model : str
        ``"quasi_static"`` or ``"dynamic"``.
    pushers : tuple of PointPusher
        The thinned finger path of each push (time from its first tracked time).
    t_starts : tuple of float
        Each push's first tracked time [s] (the file's clock).
    mu : float
        μp used.
    """

    model: str = "dynamic"
    pushers: tuple = field(default=(), repr=False)
    t_starts: tuple = ()
    mu: float = 0.0
    outline: object = field(default=None, repr=False)
    g: float = 9.81
    rtol: float = 1e-8

    def __repr__(self) -> str:
        text = FitResult.__repr__(self)
        return "Push" + text[:-1] + f", model={self.model!r})"

    def _pose_only(self) -> FitResult:
        keep = {c: x for c, x in self.rms.items() if c in _POSE}
        return replace(
            self,
            rms=keep,
            sigma={c: x for c, x in self.sigma.items() if c in _POSE},
            sigma_estimated={c: x for c, x in self.sigma_estimated.items() if c in _POSE},
        )

    def table(self, labels=None) -> str:
        """The estimates ± standard errors and the goodness of fit as text (forces too)."""
        text = FitResult.table(self._pose_only(), labels)
        extra = [
            f"force {c[-1]} rms, sigma : {self.rms[c]:.3g} N, {self.sigma[c]:.3g} N"
            + (" (estimated)" if self.sigma_estimated[c] else "")
            for c in _FORCE
            if c in self.rms
        ]
        return "\n".join([text, f"model             : {self.model}", *extra])

    def _repr_html_(self) -> str:
        return FitResult._repr_html_(self._pose_only())

    def predict(self, run: int, t) -> dict:
        """Fitted pose and pusher force of push ``run`` at times ``t`` [s] (the file's clock,
        ≥ the push's first tracked time), by running the fitted model again."""
        t = np.atleast_1d(np.asarray(t, dtype=float)) - self.t_starts[run]
        st = self.starts[run]
        pose = (st.x, st.y, st.phi)
        finger = self.pushers[run]
        traj: QuasiStaticPush | PushedTrajectory
        if self.model == "quasi_static":
            times = np.unique(np.concatenate(([0.0], t)))
            traj = push_quasi_static(
                self.body, self.friction, finger, times, pose, outline=self.outline, g=self.g,
                rtol=self.rtol,
            )  # fmt: skip
        else:
            traj = simulate_pushed(
                self.body, self.friction, State(*pose), finger, max(float(t.max()), 1e-9),
                g=self.g, rtol=self.rtol, outline=self.outline,
            )  # fmt: skip
        return pushed_at(traj, t)


# --------------------------------------------------------------------------------------------
# the fit


def _check_free(free, body, model):
    if isinstance(free, str):
        free = tuple(s.strip() for s in free.split(",") if s.strip())
    try:
        free = tuple(free)
    except TypeError:
        raise ValueError(
            f"free = {free!r} is invalid; valid values: names from {', '.join(PARAMETERS)}"
        ) from None
    if not free:
        raise ValueError("free = () is invalid; valid values: at least one parameter name")
    for p in free:
        if p not in PARAMETERS:
            raise ValueError(
                f"free parameter {p!r} is unknown; valid names: {', '.join(PARAMETERS)}"
            )
    dup = sorted({p for p in free if free.count(p) > 1})
    if dup:
        raise ValueError(f"free parameter {dup[0]!r} is given twice; valid: distinct names")
    if "moment_of_inertia" in free and model == "quasi_static":
        raise ValueError(
            "free parameter 'moment_of_inertia' is invalid with model='quasi_static' (inertia "
            "is neglected there); valid values: model='dynamic', or no moment_of_inertia"
        )
    if ("xi_c" in free or "eta_c" in free) and not isinstance(body.pressure, LinearPressure):
        raise ValueError(
            f"free parameters xi_c, eta_c need a body with LinearPressure; this body has "
            f"{type(body.pressure).__name__}; valid values: a body with LinearPressure(xi_c, "
            "eta_c), or free parameters without xi_c, eta_c"
        )
    return free


def _check_runs(runs) -> list[PushRun]:
    if isinstance(runs, PushRun):
        return [runs]
    if isinstance(runs, Sequence) and not isinstance(runs, (str, bytes)) and runs:
        for i, r in enumerate(runs):
            if not isinstance(r, PushRun):
                raise ValueError(
                    f"runs[{i}] = {type(r).__name__} is invalid; valid values: PushRun (from "
                    "read_push or read_pushes)"
                )
        return list(runs)
    raise ValueError(
        f"runs = {runs!r} is invalid; valid values: a PushRun or a non-empty list of PushRuns "
        "(read_pushes)"
    )


def _force_noise(pushes, c) -> float:
    parts = [np.diff(p.force[c], 2) for p in pushes if p.force is not None and p.force[c].size >= 3]
    if not parts:
        return 1.0
    d = np.concatenate(parts)
    return float(1.4826 * np.median(np.abs(d - np.median(d))) / math.sqrt(6.0))


def _pose_noise(pushes, c) -> float:
    parts = [np.diff(p.pose[c], 2) for p in pushes if p.pose[c].size >= 3]
    d = np.concatenate(parts) if parts else np.zeros(1)
    return float(1.4826 * np.median(np.abs(d - np.median(d))) / math.sqrt(6.0))


def fit_pushes(
    body: Body,
    runs,
    friction: FrictionTensor,
    free=("fx", "fy"),
    *,
    mu: float = 0.0,
    model: str = "dynamic",
    use_force: bool = True,
    fit_starts: bool = True,
    outline=None,
    sigma=None,
    loss: str = "linear",
    f_scale: float = 2.0,
    g: float = 9.81,
    rtol: float = 1e-8,
    path_tolerance: float = 1e-5,
    force_settle: float = 0.03,
    fd_step: float = 1e-4,
    corr_limit: float = 0.99,
    max_nfev: int | None = None,
) -> PushFitResult:
    """Fit friction parameters (and each push's start pose) to tracked pushes (MODEL §12–13).

    Parameters
    ----------
    body : Body
        The pushed object: footprint, pressure law, mass, moment of inertia (guesses of any
        that are free). Its footprint's convex hull is the outline the finger touches unless
        ``outline`` is given.
    runs : PushRun or list of PushRun
        The pushes (:func:`~slidespin.analysis.push_data.read_pushes`).
    friction : FrictionTensor
        Start guesses of the free tensor entries; its frame is kept.
    free : sequence of str or str, default ("fx", "fy")
        Parameters to fit, from ``fx, fy, f, angle, xi_c, eta_c, moment_of_inertia``
        (``moment_of_inertia`` with ``model="dynamic"`` only; ``xi_c``, ``eta_c`` with a
        ``LinearPressure`` body).
    mu : float, default 0
        μp, the finger's Coulomb coefficient against the object (known, not fitted).
    model : {"dynamic", "quasi_static"}, default "dynamic"
        The push model (module notes).
    use_force : bool, default True
        Fit the pusher's force where a push has ``ft_wrench`` samples.
    fit_starts : bool, default True
        Fit each push's start pose (x, y, φ at its first tracked time, at rest); else use the
        first tracked pose.
    outline : None, vertices (n, 2), a footprint or an Ellipse
        The outline the finger touches, body frame [m] (:func:`slidespin.body_outline`);
        for a round probe of radius r, the object's outline grown by r.
    sigma : dict, optional
        Noise levels ``{'x': m, 'y': m, 'phi': rad, 'force_x': N, 'force_y': N}``; channels
        not given are estimated from the residuals.
    loss, f_scale, corr_limit, max_nfev, fd_step
        As for :func:`slidespin.fit`.
    g : float, default 9.81
        Gravitational acceleration [m/s²].
    rtol : float, default 1e-8
        Tolerance of the push engines (the quasi-static poses to about rtol × ℓ).
    path_tolerance : float, default 1e-5
        Largest deviation [m] of the thinned finger path from the measured tip rows
        (0: every row is a waypoint).
    force_settle : float, default 0.03
        Force samples before the first touch, and for this long [s] after it, are left out:
        the first touch is the first sample whose force exceeds ``TOUCH_FRACTION`` (20 %) of
        the push's largest. The force jumps there (MODEL §13: a plastic impact, then the
        contact force at once), so a sample near the touch would make the residuals jump
        with a trial start pose and spoil the differences of the Jacobian.

    Returns
    -------
    PushFitResult

    Warns
    -----
    IdentifiabilityWarning
        When the data cannot determine some parameters (e.g. the friction level from poses
        alone under the quasi-static model).
    FitWarning
        When the optimiser did not converge, a parameter ends at a bound, or a push model
        ended early (indeterminate contact) at the optimum.

    Notes
    -----
    MODEL §12: r = (measured − simulated)/σ per channel, the covariance (JᵀJ)⁻¹ σ̂² at the
    optimum; MODEL §13: the pushed motion, quasi-static or dynamic. With σ estimated, least
    squares and σ̂² = Σr²/(n_c (N − P)/N) alternate until σ̂ changes by less than 5 %.
    """
    t_clock = time.perf_counter()
    check_body_friction(body, friction)
    runs = _check_runs(runs)
    model = v.choice("model", model, MODELS)
    free = _check_free(free, body, model)
    mu = v.bounded("mu", mu, 0.0, math.inf)
    loss = v.choice("loss", loss, LOSSES)
    f_scale = v.positive("f_scale", f_scale)
    g = v.positive("g", g, "m/s^2")
    rtol = v.in_range("rtol", rtol, 1e-13, 1e-3)
    tol = v.bounded("path_tolerance", path_tolerance, 0.0, math.inf, "m")
    settle = v.bounded("force_settle", force_settle, 0.0, math.inf, "s")
    fd_step = v.in_range("fd_step", fd_step, MIN_FD_STEP, MAX_FD_STEP)
    corr_limit = v.in_range("corr_limit", corr_limit, 0.0, 1.0, lo_open=True)
    if max_nfev is not None and (
        isinstance(max_nfev, bool) or not isinstance(max_nfev, numbers.Integral) or max_nfev < 1
    ):
        raise ValueError(f"max_nfev = {max_nfev!r} is invalid; valid range: integer >= 1")
    for name, flag in (("use_force", use_force), ("fit_starts", fit_starts)):
        if not isinstance(flag, (bool, np.bool_)):
            raise ValueError(f"{name} = {flag!r} is invalid; valid values: True or False")
    pushes = [_Push(r, mu, tol, bool(use_force), settle) for r in runs]
    given: dict[str, float] = {}
    if sigma is not None:
        if not isinstance(sigma, Mapping):
            raise ValueError(
                f"sigma = {sigma!r} is invalid; valid values: a dict such as {{'x': 1e-4, "
                "'y': 1e-4, 'phi': 2e-3, 'force_x': 0.05, 'force_y': 0.05}"
            )
        for c, s in sigma.items():
            if c not in PUSH_CHANNELS:
                raise ValueError(
                    f"sigma channel {c!r} is unknown; valid: {', '.join(PUSH_CHANNELS)}"
                )
            given[c] = v.positive(f"sigma[{c!r}]", s, _UNITS[c])
    guesses = [State(p.pose["x"][0], p.pose["y"][0], p.pose["phi"][0]) for p in pushes]
    fixed = [None] * len(pushes) if fit_starts else list(guesses)
    prob = _PushProblem(
        pushes, body, friction, free, fixed, guesses, g, rtol, fd_step, model, outline
    )
    n_par = len(prob.names)
    if prob.n_obs <= n_par:
        raise ValueError(
            f"too few measured values: {prob.n_obs} for {n_par} fitted parameters; valid "
            "range: more measured values than fitted parameters"
        )
    present = [c for c in PUSH_CHANNELS if np.any(prob.chan_of_row == c)]
    estimated = {c: c not in given for c in present}
    ell = body.length_unit
    floor = {"x": 1e-10 * ell, "y": 1e-10 * ell, "phi": 1e-10}
    floor.update({c: 1e-10 * body.mass * g for c in _FORCE})
    for c in present:
        rough = _pose_noise(pushes, c) if c in _POSE else _force_noise(pushes, c)
        prob.sigma[c] = given.get(c) or max(rough, floor[c])

    p = np.clip(prob.x0, prob.lb, prob.ub)
    nfev = 0
    res = None
    for _ in range(6):
        with _one_blas_thread():
            res = least_squares(
                prob.residuals,
                p,
                jac=prob.jacobian,
                bounds=(prob.lb, prob.ub),
                x_scale=prob.typ,
                loss=loss,
                f_scale=f_scale,
                method="trf",
                ftol=LSQ_TOL,
                xtol=LSQ_TOL,
                gtol=LSQ_TOL,
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
    assert res is not None

    prob.failures.clear()
    r = prob.residuals(p)
    J = prob.jacobian(p)
    if loss != "linear":
        J = J * np.sqrt(_loss_weights((r / f_scale) ** 2, loss))[:, None]
    s, vt, not_ident = _undetermined(J, prob.typ)
    smax = float(s[0]) if s.size else 0.0
    condition = smax / float(s[-1]) if s.size and s[-1] > 0 else math.inf
    s_safe = np.maximum(s, max(smax, 1e-300) * 1e-15)
    cov = ((vt.T / s_safe**2) @ vt) * np.outer(prob.typ, prob.typ)
    d = np.sqrt(np.diag(cov))
    corr = cov / np.outer(d, d)
    np.fill_diagonal(corr, 1.0)
    se = d.copy()
    for j in not_ident:
        se[j] = math.inf
        corr[j, :] = corr[:, j] = math.nan
        corr[j, j] = 1.0
    names = prob.names
    msgs: list[tuple[type[FitWarning], str]] = []
    if not_ident:
        which = [names[j] for j in sorted(not_ident)]
        hint = (
            " (quasi-static poses do not fix the friction's level: add force data or use "
            "model='dynamic')"
            if model == "quasi_static" and not any(c in present for c in _FORCE)
            else ""
        )
        msgs.append(
            (
                IdentifiabilityWarning,
                f"the data cannot determine {', '.join(which)}: a change of their typical "
                f"size moves chi2 by less than 1 (standard errors reported as inf){hint}",
            )
        )
    pairs = [
        f"{names[i]} and {names[j]} ({corr[i, j]:+.4f})"
        for i in range(n_par)
        for j in range(i + 1, n_par)
        if not (i in not_ident and j in not_ident) and abs(corr[i, j]) > corr_limit
    ]
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
    prob.failures.clear()
    vals = prob.physical(p)
    fit_body, fit_fr = prob.objects(vals)
    data_out, fitted, resid, trajs, starts, start_errs = [], [], [], [], [], []
    for k, push in enumerate(pushes):
        st = prob.start(p, k)
        at, traj = prob.model_run(vals, st, k)
        trajs.append(traj)
        starts.append(State(*st))
        start_errs.append({names[i].split(".")[-1]: float(se[i]) for _, i in prob.start_index[k]})
        t_abs = push.t_pose + push.t_start
        dd: dict = {"t": t_abs.copy()}
        ff: dict = {"t": t_abs.copy()}
        rr: dict = {"t": t_abs.copy()}
        for c in _POSE:
            dd[c] = push.pose[c].copy()
            ff[c] = at[c]
            diff = push.pose[c] - at[c]
            rr[c] = _wrap(diff) if c == "phi" else diff
        if push.force is not None:
            tf = push.t_force + push.t_start
            for out in (dd, ff, rr):
                out["t_force"] = tf.copy()
            for c in _FORCE:
                dd[c] = push.force[c].copy()
                ff[c] = at[c]
                rr[c] = push.force[c] - at[c]
        data_out.append(dd)
        fitted.append(ff)
        resid.append(rr)
    if prob.failures:
        msgs.append(
            (FitWarning, "a push model ended early at the optimum: " + "; ".join(prob.failures))
        )
    caught = []
    for cls, m in msgs:
        warnings.warn(m, cls, stacklevel=2)
        caught.append(m)
    raw = prob.raw_residuals(p)
    chi2 = float(np.sum(r * r))
    dof = prob.n_obs - n_par
    rms = {c: float(np.sqrt(np.mean(raw[prob.chan_of_row == c] ** 2))) for c in present}
    return PushFitResult(
        estimates={name: float(vals[name]) for name in free},
        std_errors={name: float(se[i]) for i, name in enumerate(free)},
        parameter_names=names,
        values=p.copy(),
        covariance=cov,
        correlation=corr,
        identifiable={name: (j not in not_ident) for j, name in enumerate(names)},
        singular_values=s,
        condition=condition,
        starts=tuple(starts),
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
        n_runs=len(pushes),
        data=tuple(data_out),
        fitted=tuple(fitted),
        residuals=tuple(resid),
        trajectories=tuple(trajs),
        loss=loss,
        success=bool(res.success),
        message=str(res.message),
        nfev=nfev,
        warnings=tuple(caught),
        seconds=time.perf_counter() - t_clock,
        model=model,
        pushers=tuple(pp.pusher for pp in pushes),
        t_starts=tuple(pp.t_start for pp in pushes),
        mu=mu,
        outline=outline,
        g=g,
        rtol=rtol,
    )
