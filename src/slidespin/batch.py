"""Many trajectories at once: the compiled engine run in parallel over all cores.

``simulate_many`` integrates one body under one friction tensor from N initial states;
``simulate_cases`` takes every parameter per case (patch, law, tensor, inertia, g, state),
which is what parameter sweeps need. Both return a :class:`StopResults` of arrays and hold
no per-step data, so memory grows only with N (about 200 bytes per case).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from . import _ode
from .body import Body
from .friction import FrictionTensor
from .pressure import LAW_NAMES
from .simulate import ENDING_TOL, ENDINGS, STATUSES

__all__ = ["StopResults", "simulate_many", "simulate_cases", "CASE_FIELDS"]

#: per-case inputs of :func:`simulate_cases` and their defaults (None: required)
CASE_FIELDS = {
    "a": None, "b": None, "law": "uniform", "xi_c": 0.0, "eta_c": 0.0,
    "fx": None, "fy": None, "f": 0.0, "frame": "plane", "angle": 0.0,
    "mass": 1.0, "moment_of_inertia": math.nan, "g": 9.81,
    "x": 0.0, "y": 0.0, "phi": 0.0, "vx": 0.0, "vy": 0.0, "omega": 0.0,
}
_ENDING_CODE = {name: i for i, name in enumerate(ENDINGS)}


@dataclass(frozen=True)
class StopResults:
    """Stop results of N trajectories (SI units), one array entry per case.

    Attributes
    ----------
    t_stop : ndarray
        Stop time [s].
    x_stop, y_stop, phi_stop : ndarray
        Position of G [m] and body angle [rad] at the stop.
    path_length : ndarray
        Distance travelled by G [m].
    beta_stop, theta_stop : ndarray
        Terminal ratio β* [m] (inf pure sliding, 0 pure spinning, NaN at rest) and the
        terminal direction ϑ* [rad] (NaN at rest and for ``spiral`` endings, which have none:
        see :class:`slidespin.Trajectory`).
    ending_code, status_code : ndarray of int8
        Indices into :data:`ENDINGS` and status names; ``ending``/``status`` give strings.
    n_steps : ndarray of int
        Integrator steps per case.
    """

    t_stop: np.ndarray
    x_stop: np.ndarray
    y_stop: np.ndarray
    phi_stop: np.ndarray
    path_length: np.ndarray
    beta_stop: np.ndarray
    theta_stop: np.ndarray
    ending_code: np.ndarray
    status_code: np.ndarray
    n_steps: np.ndarray

    def __len__(self) -> int:
        return self.t_stop.size

    @property
    def ending(self) -> np.ndarray:
        """Ending names (``mixed``, ``pure_sliding``, ``pure_spinning``, ``at_rest``)."""
        return np.asarray(ENDINGS, dtype=object)[self.ending_code]

    @property
    def status(self) -> np.ndarray:
        """Status names (``stopped``, ``max_steps``, ``step_too_small``, ``at_rest``)."""
        names = np.empty(len(STATUSES), dtype=object)
        for code, name in STATUSES.items():
            names[code] = name
        return names[self.status_code]

    def as_dict(self) -> dict:
        """Column name → array, with string columns for ending and status."""
        out = {k: getattr(self, k) for k in (
            "t_stop", "x_stop", "y_stop", "phi_stop", "path_length", "beta_stop", "theta_stop",
            "n_steps")}
        out["ending"] = self.ending
        out["status"] = self.status
        return out


def _column(name, value, n, kind="real"):
    arr = np.asarray(value)
    if arr.ndim > 1 or (arr.ndim == 1 and arr.size not in (1, n)):
        raise ValueError(f"{name} has shape {arr.shape}; valid: a scalar or an array of length {n}")
    if kind == "real":
        if arr.dtype.kind not in "fiu":
            raise ValueError(f"{name} must be real numbers, got dtype {arr.dtype}")
        arr = arr.astype(float)
    return np.broadcast_to(arr, (n,)) if arr.ndim == 0 or arr.size == 1 else arr


def _check(name, arr, ok, valid):
    bad = ~ok
    if bad.any():
        i = int(np.flatnonzero(bad)[0])
        raise ValueError(f"{name} = {arr[i]!r} (case {i}) is invalid; valid range: {valid}")


def simulate_cases(cases: dict, rtol: float = 1e-10, max_steps: int = 200_000) -> StopResults:
    """Integrate N independent cases to their stops, in parallel over all cores.

    Parameters
    ----------
    cases : dict
        Per-case inputs, each a scalar (shared) or a 1-D array of length N: ``a``, ``b`` [m],
        ``law`` (name or code 0-3), ``xi_c``, ``eta_c`` [m] (linear law), ``fx``, ``fy``, ``f``,
        ``frame`` ("plane"/"body" or 0/1), ``angle`` [rad], ``mass`` [kg],
        ``moment_of_inertia`` [kg m²] (NaN: uniform plate), ``g`` [m/s²], and the initial
        ``x``, ``y`` [m], ``phi`` [rad], ``vx``, ``vy`` [m/s], ``omega`` [rad/s]. See
        :data:`CASE_FIELDS` for defaults.
    rtol : float
        Integrator tolerance, as in :func:`slidespin.simulate`.
    max_steps : int
        Step budget per case.

    Returns
    -------
    StopResults
    """
    unknown = sorted(set(cases) - set(CASE_FIELDS))
    if unknown:
        raise ValueError(f"unknown case field {unknown[0]!r}; valid: {', '.join(CASE_FIELDS)}")
    missing = [k for k, d in CASE_FIELDS.items() if d is None and k not in cases]
    if missing:
        raise ValueError(f"missing case field {missing[0]!r}")
    sizes = {np.size(v) for v in cases.values() if np.ndim(v) == 1 and np.size(v) != 1}
    if len(sizes) > 1:
        raise ValueError(f"case arrays have different lengths {sorted(sizes)}")
    n = sizes.pop() if sizes else 1
    col = {}
    for k, d in CASE_FIELDS.items():
        val = cases.get(k, d)
        if k in ("law", "frame"):
            arr = np.asarray(val)
            names = LAW_NAMES if k == "law" else ("plane", "body")
            if arr.dtype.kind in "USO":
                lookup = {nm: i for i, nm in enumerate(names)}
                flat = np.atleast_1d(arr).ravel()
                try:
                    codes = np.array([lookup[str(x).lower()] for x in flat], dtype=float)
                except KeyError as exc:
                    raise ValueError(
                        f"{k} = {exc.args[0]!r} is invalid; valid values: {', '.join(names)}"
                    ) from None
                val = codes
            arr = _column(k, val, n)
            _check(k, arr, np.isin(arr, np.arange(len(names))), f"one of {', '.join(names)}")
            col[k] = arr
        else:
            col[k] = _column(k, val, n)
    for k in ("a", "b", "fx", "fy", "mass", "g"):
        _check(k, col[k], np.isfinite(col[k]) & (col[k] > 0), "finite and > 0")
    for k in ("xi_c", "eta_c", "f", "angle", "x", "y", "phi", "vx", "vy", "omega"):
        _check(k, col[k], np.isfinite(col[k]), "finite")
    inertia = col["moment_of_inertia"]
    inertia = np.where(np.isnan(inertia), col["mass"] * (col["a"] ** 2 + col["b"] ** 2) / 4, inertia)
    _check("moment_of_inertia", inertia, np.isfinite(inertia) & (inertia > 0), "finite and > 0")
    is_lin = col["law"] == 1
    core = (col["xi_c"] / col["a"]) ** 2 + (col["eta_c"] / col["b"]) ** 2
    _check("xi_c, eta_c (core measure (xi_c/a)^2 + (eta_c/b)^2)", core,
           ~is_lin | (core <= 1.0 / 16.0 * (1 + 1e-12)), "[0, 0.0625]")
    return _run(col, inertia, rtol, max_steps)


def _run(col, inertia, rtol, max_steps) -> StopResults:
    n = col["a"].size
    a = col["a"]
    k = np.sqrt(inertia / col["mass"]) / a
    lin = col["law"] == 1
    ang = col["angle"]
    c, s = np.cos(ang), np.sin(ang)
    fx, fy, f = col["fx"], col["fy"], col["f"]
    # R(angle) [[fx, f], [-f, fy]] R(angle)^T
    t00 = fx * c * c + fy * s * s
    t11 = fx * s * s + fy * c * c
    t01 = (fx - fy) * c * s + f
    t10 = (fx - fy) * c * s - f
    pars = np.empty((n, _ode.NPAR))
    pars[:, _ode.P_BN] = col["b"] / a
    pars[:, _ode.P_LAW] = col["law"]
    pars[:, _ode.P_XG] = np.where(lin, col["xi_c"] / a, 0.0)
    pars[:, _ode.P_YG] = np.where(lin, col["eta_c"] / a, 0.0)
    pars[:, _ode.P_T00], pars[:, _ode.P_T01] = t00, t01
    pars[:, _ode.P_T10], pars[:, _ode.P_T11] = t10, t11
    pars[:, _ode.P_BODY] = col["frame"]
    pars[:, _ode.P_K] = k
    pars[:, _ode.P_WTOL] = 1e-12
    g = col["g"]
    t_unit = np.sqrt(a / g)
    v_unit = np.sqrt(a * g)
    vx, vy, wn = col["vx"] / v_unit, col["vy"] / v_unit, col["omega"] * t_unit
    s0 = np.sqrt(vx * vx + vy * vy + (k * wn) ** 2)
    rest = s0 == 0.0
    safe = np.where(rest, 1.0, s0)
    y0 = np.empty((n, _ode.NY))
    y0[:, 0], y0[:, 1], y0[:, 2] = vx / safe, vy / safe, k * wn / safe
    with np.errstate(divide="ignore"):
        y0[:, 3] = np.where(rest, -np.inf, np.log(safe))
    y0[:, 4] = 0.0
    y0[:, 5], y0[:, 6], y0[:, 7] = col["x"] / a, col["y"] / a, col["phi"]
    y0[:, 8] = 0.0
    yend, status, steps, fails = _ode.integrate_many(
        pars, y0, float(rtol), float(rtol), float(rtol), min(float(rtol), 1e-8), int(max_steps)
    )
    if fails.any():  # pragma: no cover - guard
        raise RuntimeError(f"{int((fails > 0).sum())} cases had wrench evaluations above their "
                           "error target; please report")
    u1, u2, u3 = yend[:, 0], yend[:, 1], yend[:, 2]
    u12 = np.hypot(u1, u2)
    ending = np.where(np.abs(u3) <= ENDING_TOL, 1, np.where(u12 <= ENDING_TOL, 2, 0))
    ending = np.where(rest, 3, ending)
    spiral = status == _ode.ST_SPIRAL
    ending = np.where(spiral, 4, ending).astype(np.int8)
    status = np.where(spiral, _ode.ST_STOPPED, status)
    with np.errstate(divide="ignore", invalid="ignore"):
        beta = k * u12 / u3 * a
    beta = np.where(ending == 1, np.inf, beta)
    beta = np.where(ending == 2, 0.0, beta)
    beta = np.where(rest, np.nan, beta)
    beta = np.where(spiral & (np.abs(u3) > ENDING_TOL), np.nan, beta)
    theta = np.where(rest | spiral, np.nan, np.arctan2(u2, u1))
    return StopResults(
        t_stop=yend[:, 4] * t_unit,
        x_stop=yend[:, 5] * a,
        y_stop=yend[:, 6] * a,
        phi_stop=yend[:, 7].copy(),
        path_length=yend[:, 8] * a,
        beta_stop=beta,
        theta_stop=theta,
        ending_code=ending,
        status_code=status.astype(np.int8),
        n_steps=steps,
    )


def simulate_many(
    body: Body,
    friction: FrictionTensor,
    initial_states,
    g: float = 9.81,
    rtol: float = 1e-10,
    max_steps: int = 200_000,
) -> StopResults:
    """Integrate one body from N initial states to their stops, in parallel.

    Parameters
    ----------
    body : Body
    friction : FrictionTensor
    initial_states : array_like, shape (N, 6)
        Rows (x, y, phi, vx, vy, omega) in SI units.
    g : float
        Gravitational acceleration [m/s²].
    rtol : float
        Integrator tolerance, as in :func:`slidespin.simulate`.
    max_steps : int
        Step budget per case.

    Returns
    -------
    StopResults
        Gives the same numbers as :func:`slidespin.simulate` case by case.
    """
    if not isinstance(body, Body):
        raise ValueError(f"body = {body!r} is invalid; valid values: a slidespin.Body")
    if not isinstance(friction, FrictionTensor):
        raise ValueError(f"friction = {friction!r} is invalid; valid values: a FrictionTensor")
    st = np.asarray(initial_states, dtype=float)
    if st.ndim != 2 or st.shape[1] != 6:
        raise ValueError(
            f"initial_states has shape {st.shape}; valid: (N, 6) rows of (x, y, phi, vx, vy, omega)"
        )
    xg, yg = body.mass_centre
    fields = dict(
        a=body.patch.a, b=body.patch.b, law=body.pressure.code, xi_c=xg, eta_c=yg,
        fx=friction.fx, fy=friction.fy, f=friction.f, frame=friction.frame,
        angle=friction.angle, mass=body.mass, moment_of_inertia=body.moment_of_inertia, g=g,
        x=st[:, 0], y=st[:, 1], phi=st[:, 2], vx=st[:, 3], vy=st[:, 4], omega=st[:, 5],
    )
    return simulate_cases(fields, rtol=rtol, max_steps=max_steps)
