"""Identification of friction parameters from tracked motion (MODEL §12).

Experimentalists track a sliding and spinning body (the position of its mass centre G and its
angle) and want the friction behind the motion. :func:`fit` finds the parameters θ, shared by
all runs, and each run's start state by weighted least squares,

    minimise  Σ_runs Σ_channels Σ_i ρ(r²),   r = (measured − simulated)/σ_channel,

with the simulation evaluated at the measured times, and reports the estimates with standard
errors from the covariance (JᵀJ)⁻¹ at the optimum (σ estimated from the residuals where it is
not given), the correlation matrix, and an honest verdict on identifiability.

Parameters that may be fitted (``free``), with their code names:

=====================  ================================================  =========================
name                   meaning                                           bounds
=====================  ================================================  =========================
``fx``, ``fy``         principal coefficients of 𝔽 (paper eq. 2)         > 0 (dissipative), within
                                                                         FrictionTensor's range
``f``                  skew coefficient of 𝔽                             FrictionTensor's range
``angle``              angle of 𝔽's principal axes [rad]                 any
``xi_c``, ``eta_c``    linear law's pressure centroid = G [m] (eq. 10)   |ξc| ≤ a/4, |ηc| ≤ b/4;
                                                                         a footprint: its core
``moment_of_inertia``  I about G [kg m²]                                 [1e-4, 1e4] × the guess
=====================  ================================================  =========================

The body may rest on an ellipse or on any footprint of :mod:`slidespin.contact.shapes` (uniform or
linear pressure, MODEL §10). G of the linear law is kept in the core of the patch, where the
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
body rests at the stop state. The Jacobian is by central
differences, one run at a time (a run depends only on the shared parameters and its own start;
the derivatives with respect to the start position x₀, y₀ are exact: the motion is invariant
under translation). Trajectories depend on the parameters smoothly except through the stop
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

import csv
import io
import math
import numbers
import os
import time
import warnings
from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np

from slidespin import _validate as v
from slidespin._io import read_regular_file
from slidespin.contact.body import Body, check_body_friction
from slidespin.contact.friction import FrictionTensor
from slidespin.contact.pressure import LinearPressure
from slidespin.motion.state import State

__all__ = [
    "CHANNELS",
    "LOSSES",
    "MAX_DATA_BYTES",
    "MAX_FD_STEP",
    "MIN_FD_STEP",
    "PARAMETERS",
    "FitResult",
    "FitWarning",
    "IdentifiabilityWarning",
    "as_runs",
    "compare_frames",
    "fit",
    "frame_score",
    "read_runs",
    "trajectory_at",
]

#: parameters that :func:`fit` can free
PARAMETERS = ("fx", "fy", "f", "angle", "xi_c", "eta_c", "moment_of_inertia")
#: measured channels of a run: positions of G [m] and the body angle [rad]
CHANNELS = ("x", "y", "phi")
START = ("x", "y", "phi", "vx", "vy", "omega")
#: loss functions of :func:`scipy.optimize.least_squares` accepted by :func:`fit`
LOSSES = ("linear", "soft_l1", "huber", "cauchy", "arctan")
_UNITS = {"x": "m", "y": "m", "phi": "rad"}
_PAIR = {"x": "vx", "y": "vy", "phi": "omega"}
#: singular values of the typical-size-scaled Jacobian below this are undetermined directions
SINGULAR_TOL = 1.0
#: a parameter with at least this weight in an undetermined direction is not identifiable
WEIGHT_TOL = 0.1
#: trust-region solver of least_squares: "exact" (an SVD of the Jacobian each step) converges
#: in far fewer evaluations than "lsmr" on ill-conditioned problems
TR_SOLVER = "exact"
#: step budget of a simulation inside a fit before its end speed is checked
QUICK_STEPS = 4000
#: largest data file :func:`read_runs` reads [bytes]
MAX_DATA_BYTES = 100_000_000
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
# data


def _channel(name, values, n, where):
    try:
        arr = np.asarray(values, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"{where}: column {name!r} must hold numbers") from None
    if arr.ndim != 1 or arr.shape[0] != n:
        raise ValueError(
            f"{where}: column {name!r} has shape {arr.shape}; valid: one value per time ({n})"
        )
    bad = np.flatnonzero(np.isinf(arr))
    if bad.size:
        raise ValueError(
            f"{where}: column {name!r} row {bad[0]} is {arr[bad[0]]!r}; valid: a finite number "
            "(NaN or an empty cell marks a missing value)"
        )
    return arr


def _as_run(obj, where: str) -> dict:
    if isinstance(obj, np.ndarray) and obj.dtype.names:
        names = tuple(obj.dtype.names)
        get = obj.__getitem__
    elif isinstance(obj, Mapping):
        names = tuple(obj)
        get = obj.__getitem__
    elif hasattr(obj, "columns") and hasattr(obj, "__getitem__"):  # a pandas DataFrame
        names = tuple(str(c) for c in obj.columns)
        get = obj.__getitem__
    else:
        raise ValueError(
            f"{where} = {type(obj).__name__} is invalid; valid values: a mapping (dict) or a "
            "NumPy structured array with 't' and any of 'x', 'y', 'phi'"
        )
    allowed = ("t",) + CHANNELS
    for k in names:
        if k not in allowed:
            raise ValueError(f"{where}: unknown column {k!r}; valid columns: t, x, y, phi")
    if "t" not in names:
        raise ValueError(f"{where}: the column 't' (time [s]) is missing")
    try:
        t = np.asarray(get("t"), dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"{where}: column 't' must hold numbers") from None
    if t.ndim != 1 or t.size == 0:
        raise ValueError(f"{where}: column 't' has shape {t.shape}; valid: a 1-D array of times")
    bad = np.flatnonzero(~np.isfinite(t))
    if bad.size:
        raise ValueError(f"{where}: column 't' row {bad[0]} is {t[bad[0]]!r}; valid: finite")
    back = np.flatnonzero(np.diff(t) <= 0.0)
    if back.size:
        i = back[0] + 1
        raise ValueError(
            f"{where}: column 't' row {i} is {t[i]!r} <= the previous time {t[i - 1]!r}; valid: "
            "strictly increasing times"
        )
    run = {"t": t}
    for c in CHANNELS:
        if c in names:
            run[c] = _channel(c, get(c), t.size, where)
    if not any(np.isfinite(run[c]).any() for c in CHANNELS if c in run):
        raise ValueError(f"{where}: no measured value; give at least one of x, y, phi")
    return run


def as_runs(data) -> list[dict]:
    """Validate ``data`` and return it as a list of runs ``{'t', 'x'?, 'y'?, 'phi'?}``.

    Parameters
    ----------
    data : mapping, structured array, DataFrame, or a list of them
        One run, or several. A run has the times ``t`` [s] (finite, strictly increasing) and
        any of ``x``, ``y`` [m] (position of G) and ``phi`` [rad] (body angle), one value per
        time; NaN marks a missing value.

    Raises
    ------
    ValueError
        Naming the run, the column and the row.
    """
    if (isinstance(data, (Mapping, np.ndarray)) or hasattr(data, "columns")) and not (
        isinstance(data, np.ndarray) and data.dtype.names is None
    ):
        return [_as_run(data, "data")]
    if isinstance(data, (list, tuple)):
        if not data:
            raise ValueError("data = [] holds no run; valid values: one or more runs")
        return [_as_run(r, f"data[{i}]") for i, r in enumerate(data)]
    raise ValueError(
        f"data = {type(data).__name__} is invalid; valid values: a run (dict or structured "
        "array with 't' and any of 'x', 'y', 'phi') or a list of runs"
    )


def read_runs(path, *, labels: bool = False):
    """Read tracked runs from a CSV file with columns ``t,x,y,phi`` and an optional ``run``.

    Any of ``x``, ``y``, ``phi`` may be absent; an empty cell (or ``nan``) is a missing
    value. Rows are grouped by the ``run`` label (in order of first appearance); within a
    run the times must increase. Units: s, m, rad.

    Parameters
    ----------
    path : str or os.PathLike
        A regular file of at most :data:`MAX_DATA_BYTES` bytes of UTF-8 text; any other
        type (``None``, a number, a file descriptor), a FIFO, socket or device is refused
        without reading.

    Returns
    -------
    list of dict
        One ``{'t': ..., 'x': ..., ...}`` per run, ready for :func:`fit`; with
        ``labels=True``, the pair (runs, run labels) (label ``'0'`` without a run column).

    Raises
    ------
    ValueError
        One line naming the file, the column and the line of the file.
    """
    if not isinstance(path, (str, os.PathLike)):
        raise ValueError(
            f"data file path = {path!r} ({type(path).__name__}) is invalid; "
            "valid values: a str or os.PathLike path to a CSV file"
        )
    name = os.fsdecode(os.fspath(path))
    raw = read_regular_file(path, "data file", "CSV", MAX_DATA_BYTES)
    try:
        text = raw.decode("utf-8-sig")
    except UnicodeDecodeError:
        raise ValueError(f"data file {name!r} is not a UTF-8 text (CSV) file") from None
    try:
        rows = list(csv.reader(io.StringIO(text, newline="")))
    except csv.Error as exc:
        raise ValueError(f"data file {name!r} cannot be read: {exc}") from None
    lines = [(i + 1, r) for i, r in enumerate(rows) if r and any(cell.strip() for cell in r)]
    if not lines:
        raise ValueError(f"{name}: the file is empty; valid: a header line t,x,y,phi[,run]")
    head_line, head = lines[0]
    cols = [c.strip().lower() for c in head]
    allowed = ("t",) + CHANNELS + ("run",)
    for c in cols:
        if c not in allowed:
            raise ValueError(
                f"{name}: line {head_line}: unknown column {c!r}; valid columns: t, x, y, phi, run"
            )
    dup = sorted({c for c in cols if cols.count(c) > 1})
    if dup:
        raise ValueError(f"{name}: line {head_line}: column {dup[0]!r} appears twice")
    if "t" not in cols:
        raise ValueError(f"{name}: line {head_line}: the column 't' (time [s]) is missing")
    if not set(cols) & set(CHANNELS):
        raise ValueError(f"{name}: line {head_line}: no column x, y or phi")
    if len(lines) == 1:
        raise ValueError(f"{name}: no data rows after the header")
    runs: dict[str, dict[str, list]] = {}
    for line, r in lines[1:]:
        if len(r) != len(cols):
            raise ValueError(f"{name}: line {line} has {len(r)} fields; the header has {len(cols)}")
        label = "0"
        vals = {}
        for c, cell in zip(cols, r):
            cell = cell.strip()
            if c == "run":
                if not cell:
                    raise ValueError(f"{name}: line {line}, column 'run': empty run label")
                label = cell
                continue
            if cell == "" or cell.lower() == "nan":
                if c == "t":
                    raise ValueError(f"{name}: line {line}, column 't': missing time")
                vals[c] = math.nan
                continue
            try:
                x = float(cell)
            except ValueError:
                raise ValueError(
                    f"{name}: line {line}, column {c!r}: {cell!r} is not a number"
                ) from None
            if not math.isfinite(x):
                raise ValueError(
                    f"{name}: line {line}, column {c!r}: {cell!r} is not finite; valid: a finite "
                    "number, or an empty cell for a missing value"
                )
            vals[c] = x
        run = runs.setdefault(label, {"line": [], **{c: [] for c in cols if c != "run"}})
        if run["t"] and vals["t"] <= run["t"][-1]:
            raise ValueError(
                f"{name}: line {line}, column 't': {vals['t']!r} does not increase (previous "
                f"time of run {label!r}: {run['t'][-1]!r})"
            )
        run["line"].append(line)
        for c, x in vals.items():
            run[c].append(x)
    out = []
    for label, run in runs.items():
        d = {c: np.array(run[c], dtype=float) for c in ("t",) + CHANNELS if c in run}
        if not any(np.isfinite(d[c]).any() for c in CHANNELS if c in d):
            raise ValueError(
                f"{name}: run {label!r} (lines {run['line'][0]}-{run['line'][-1]}) has no "
                "measured x, y or phi"
            )
        out.append(d)
    return (out, list(runs)) if labels else out


# --------------------------------------------------------------------------------------------
# the model at the measured times


def trajectory_at(traj, t) -> dict:
    """Position and angle of a :class:`~slidespin.Trajectory` at times ``t`` [s].

    Between the recorded steps the motion is the cubic Hermite interpolant of (x, vx),
    (y, vy), (φ, ω) (exact for constant accelerations); from the stop time on the body rests
    at the stop state. Times are measured from the trajectory's start (t ≥ 0).

    Returns
    -------
    dict
        ``{'x': ..., 'y': ..., 'phi': ...}`` arrays shaped like ``t`` [m, m, rad].
    """
    from scipy.interpolate import CubicHermiteSpline

    t = np.asarray(t, dtype=float)
    ts = traj.t
    pos = np.column_stack((traj.x, traj.y, traj.phi))
    if ts.size < 2 or traj.t_stop <= 0.0:
        return {c: np.full(t.shape, pos[-1, i]) for i, c in enumerate(CHANNELS)}
    vel = np.column_stack((traj.vx, traj.vy, traj.omega))
    thr = 1e-12 * ts[-1]
    idx = np.concatenate(([0], 1 + np.flatnonzero(np.diff(ts) > thr)))
    last = ts.size - 1
    if idx[-1] != last:
        if ts[last] - ts[idx[-1]] > thr:
            idx = np.append(idx, last)
        else:
            idx[-1] = last
    if idx.size < 2:
        return {c: np.full(t.shape, pos[-1, i]) for i, c in enumerate(CHANNELS)}
    spline = CubicHermiteSpline(ts[idx], pos[idx], vel[idx], axis=0, extrapolate=False)
    tt = np.clip(t, ts[0], ts[last])
    val = spline(tt)
    val[tt >= ts[last]] = pos[last]
    return {c: val[..., i] for i, c in enumerate(CHANNELS)}


def _core_scale(patch, offset: tuple[float, float]) -> float:
    """Largest s in [0, 1] for which the linear law with G = r_c + s·offset is ≥ 0 on the
    footprint ``patch`` (r_c its area centroid; MODEL §10).

    The law is p ∝ 1 + gᵀ(r − r_c) with J g = A (r_G − r_c): g is linear in the offset, so the
    minimum of gᵀ(r − r_c) over the footprint (at a polygon vertex or on a disk's rim) scales
    with s and p ≥ 0 holds up to s = −1/min.
    """
    d = np.asarray(offset, dtype=float)
    if not np.any(d):
        return 1.0
    rc = np.asarray(patch.centroid, dtype=float)
    grad = np.linalg.solve(np.asarray(patch.second_moment, dtype=float), patch.area * d)
    arrays = patch.to_arrays()
    low = math.inf
    if arrays.edges.size:
        low = float(np.min((arrays.edges[:, :2] - rc) @ grad))
    gn = float(np.hypot(*grad))
    for xo, yo, radius, sign in arrays.circles:
        if sign > 0:
            low = min(low, float(grad @ (np.array([xo, yo]) - rc)) - gn * radius)
    return 1.0 if low >= -1.0 else -1.0 / low


def _wrap(a):
    return (a + np.pi) % (2.0 * np.pi) - np.pi


class _Problem:
    """Parameter bookkeeping and residuals of one fit (internal; not part of the API)."""

    def __init__(
        self, runs, body, friction, free, start_fixed, start_free, guess, g, rtol, max_step, fd_step
    ):
        self.runs = runs
        self.body = body
        self.friction = friction
        self.free = free
        self.g = g
        self.rtol = rtol
        self.max_step = max_step
        self.fd_step = fd_step
        a = body.length_unit  # the semi-axis a of an ellipse, the extent of a footprint
        xg, yg = body.mass_centre
        base = {
            "fx": friction.fx,
            "fy": friction.fy,
            "f": friction.f,
            "angle": friction.angle,
            "xi_c": xg,
            "eta_c": yg,
            "moment_of_inertia": body.moment_of_inertia,
        }
        self.base = base
        if body.is_footprint:
            # G's range: the core of the footprint (p >= 0) along each axis through the
            # area centroid; objects() projects a point outside the core back onto it
            cx, cy = body.patch.centroid
            xi_lo, xi_hi = (
                cx + sgn * a * _core_scale(body.patch, (sgn * a, 0.0)) for sgn in (-1.0, 1.0)
            )
            eta_lo, eta_hi = (
                cy + sgn * a * _core_scale(body.patch, (0.0, sgn * a)) for sgn in (-1.0, 1.0)
            )
            typ_xi = typ_eta = a / 4.0
        else:
            b = body.patch.b
            xi_lo, xi_hi, eta_lo, eta_hi = -a / 4.0, a / 4.0, -b / 4.0, b / 4.0
            typ_xi, typ_eta = a / 4.0, b / 4.0
        fmax = max(friction.fx, friction.fy)
        typ = {
            "fx": fmax,
            "fy": fmax,
            "f": fmax,
            "angle": 1.0,
            "xi_c": typ_xi,
            "eta_c": typ_eta,
            "moment_of_inertia": body.moment_of_inertia,
        }
        c_lo, c_hi = v.COEFFICIENT  # FrictionTensor's range
        skew = v.SKEW
        lo = {
            "fx": c_lo,
            "fy": c_lo,
            "f": -skew,
            "angle": -np.inf,
            "xi_c": xi_lo,
            "eta_c": eta_lo,
            "moment_of_inertia": 1e-4 * body.moment_of_inertia,
        }
        hi = {
            "fx": c_hi,
            "fy": c_hi,
            "f": skew,
            "angle": np.inf,
            "xi_c": xi_hi,
            "eta_c": eta_hi,
            "moment_of_inertia": 1e4 * body.moment_of_inertia,
        }
        names, x0, typs, lbs, ubs, owner = [], [], [], [], [], []
        for p in free:
            names.append(p)
            x0.append(base[p])
            typs.append(typ[p])
            lbs.append(lo[p])
            ubs.append(hi[p])
            owner.append(-1)
        self.n_phys = len(free)
        self.start_index = []  # per run: list of (component index, parameter index)
        self.start_base = []
        for k, run in enumerate(runs):
            st = guess[k]
            vals = st.as_array()
            speed = max(math.hypot(st.vx, st.vy), a * abs(st.omega), 1e-2 * math.sqrt(g * a))
            tp = {"x": a, "y": a, "phi": 1.0, "vx": speed, "vy": speed, "omega": speed / a}
            self.start_base.append(vals.copy())
            idx = []
            if start_fixed[k] is None:
                comps = (
                    start_free
                    if start_free is not None
                    else tuple(
                        comp
                        for c in CHANNELS
                        if c in run and np.isfinite(run[c]).any()
                        for comp in (c, _PAIR[c])
                    )
                )
                for comp in START:
                    if comp in comps:
                        j = START.index(comp)
                        idx.append((j, len(names)))
                        names.append(f"run{k}.{comp}")
                        x0.append(vals[j])
                        typs.append(tp[comp])
                        lbs.append(-np.inf)
                        ubs.append(np.inf)
                        owner.append(k)
            self.start_index.append(idx)
        self.names = tuple(names)
        self.x0 = np.array(x0, dtype=float)
        self.typ = np.array(typs, dtype=float)
        self.lb = np.array(lbs, dtype=float)
        self.ub = np.array(ubs, dtype=float)
        self.owner = np.array(owner, dtype=int)
        # observation layout: per run, per channel, the finite rows
        self.obs = []  # per run: list of (channel, mask)
        self.slices = []
        n = 0
        for run in runs:
            items = []
            start = n
            for c in CHANNELS:
                if c in run:
                    m = np.isfinite(run[c])
                    if m.any():
                        items.append((c, m))
                        n += int(m.sum())
            self.obs.append(items)
            self.slices.append(slice(start, n))
        self.n_obs = n
        self.chan_of_row = np.empty(n, dtype=object)
        for k, items in enumerate(self.obs):
            i = self.slices[k].start
            for c, m in items:
                cnt = int(m.sum())
                self.chan_of_row[i : i + cnt] = c
                i += cnt
        self.sigma = {c: 1.0 for c in CHANNELS}
        self._cache = None

    # -- building the model objects --------------------------------------------------------
    def physical(self, p) -> dict:
        vals = dict(self.base)
        for i, name in enumerate(self.free):
            vals[name] = float(p[i])
        return vals

    def objects(self, vals):
        fr = FrictionTensor(vals["fx"], vals["fy"], vals["f"], self.friction.frame, vals["angle"])
        pressure = self.body.pressure
        if "xi_c" in self.free or "eta_c" in self.free:
            xi, eta = vals["xi_c"], vals["eta_c"]
            patch = self.body.patch
            if self.body.is_footprint:
                # projection towards the area centroid onto the core (p >= 0 on the footprint)
                cx, cy = patch.centroid
                s = _core_scale(patch, (xi - cx, eta - cy))
                if s < 1.0:
                    s *= 1.0 - 1e-12
                    xi, eta = cx + s * (xi - cx), cy + s * (eta - cy)
            else:
                c = (xi / patch.a) ** 2 + (eta / patch.b) ** 2
                if c > 1.0 / 16.0:  # radial projection onto the core of the patch
                    s = math.sqrt(1.0 / 16.0 / c) * (1.0 - 1e-12)
                    xi, eta = xi * s, eta * s
            pressure = LinearPressure(xi, eta)
        body = Body(self.body.patch, pressure, self.body.mass, vals["moment_of_inertia"])
        return body, fr

    def start(self, p, k) -> np.ndarray:
        s = self.start_base[k].copy()
        for j, i in self.start_index[k]:
            s[j] = p[i]
        return s

    def simulate(self, vals, start, t_need=math.inf):
        """Trajectory from ``start``; it must be exact up to ``t_need`` [s] at least."""
        from slidespin.motion.simulate import simulate

        body, fr = self.objects(vals)
        state = State(*start)
        traj = simulate(
            body, fr, state, g=self.g, rtol=self.rtol, max_step=self.max_step, max_steps=QUICK_STEPS
        )
        if traj.status == "max_steps":
            # A slow approach to the stop (MODEL §9, e.g. near pure sliding) may take many
            # steps at speeds that no longer move the body visibly, or after the last
            # measured time. The final row may be an extrapolated stop: judge by the last
            # integrator step before it, and run again with the full budget only if that
            # step is inside the measured times and still moving.
            k = body.radius_of_gyration
            s0 = math.sqrt(state.vx**2 + state.vy**2 + (k * state.omega) ** 2)
            i = max(0, traj.t.size - 2)
            s_end = math.hypot(traj.speed[i], k * traj.omega[i])
            if traj.t[i] < t_need and not s_end <= 1e-9 * s0:
                traj = simulate(body, fr, state, g=self.g, rtol=self.rtol, max_step=self.max_step)
        return traj

    def model_run(self, vals, start, k):
        """Simulated channels at the measured times of run k (dict) and the trajectory."""
        run = self.runs[k]
        traj = self.simulate(vals, start, run["t"][-1] - run["t"][0])
        at = trajectory_at(traj, run["t"] - run["t"][0])
        return at, traj

    def raw_residual_run(self, vals, start, k) -> np.ndarray:
        """Measured − simulated at the observed rows of run k (data units, φ wrapped)."""
        at, _ = self.model_run(vals, start, k)
        run = self.runs[k]
        parts = []
        for c, m in self.obs[k]:
            d = run[c][m] - at[c][m]
            parts.append(_wrap(d) if c == "phi" else d)
        return np.concatenate(parts) if parts else np.empty(0)

    def scale_rows(self, k) -> np.ndarray:
        run_rows = self.chan_of_row[self.slices[k]]
        return np.array([1.0 / self.sigma[c] for c in run_rows])

    def raw_residuals(self, p) -> np.ndarray:
        vals = self.physical(p)
        return np.concatenate(
            [self.raw_residual_run(vals, self.start(p, k), k) for k in range(len(self.runs))]
        )

    def residuals(self, p) -> np.ndarray:
        key = p.tobytes()
        if self._cache is not None and self._cache[0] == key and self._cache[1] == self._sig():
            return self._cache[2]
        raw = self.raw_residuals(p)
        r = raw * self.weights()
        self._cache = (key, self._sig(), r)
        return r

    def _sig(self):
        return tuple(self.sigma[c] for c in CHANNELS)

    def weights(self) -> np.ndarray:
        return np.array([1.0 / self.sigma[c] for c in self.chan_of_row])

    def jacobian(self, p) -> np.ndarray:
        """Central differences, run by run; exact columns for the start positions x₀, y₀."""
        r0 = self.residuals(p)
        J = np.zeros((self.n_obs, p.size))
        w = self.weights()
        for k in range(len(self.runs)):
            sl = self.slices[k]
            cols = [i for i in range(self.n_phys)] + [i for _, i in self.start_index[k]]
            for i in cols:
                comp = self.names[i].split(".")[-1] if i >= self.n_phys else None
                if comp in ("x", "y"):
                    rows = self.chan_of_row[sl] == comp
                    J[sl, i] = np.where(rows, -w[sl], 0.0)
                    continue
                h = self.fd_step * self.typ[i]
                up = min(p[i] + h, self.ub[i])
                dn = max(p[i] - h, self.lb[i])
                vals_up, vals_dn = p.copy(), p.copy()
                vals_up[i], vals_dn[i] = up, dn
                r_up = self.raw_residual_run(self.physical(vals_up), self.start(vals_up, k), k)
                r_dn = (
                    r0[sl] / w[sl]
                    if dn == p[i]
                    else self.raw_residual_run(self.physical(vals_dn), self.start(vals_dn, k), k)
                )
                if up == p[i]:
                    r_up = r0[sl] / w[sl]
                d = r_up - r_dn
                # φ residuals are wrapped: a difference across the cut is not a derivative
                d = np.where(self.chan_of_row[sl] == "phi", _wrap(d), d)
                J[sl, i] = d / (up - dn) * w[sl]
        return J


# --------------------------------------------------------------------------------------------
# start guesses and noise levels


def _guess_start(run, default: State) -> State:
    """Start state at t[0] from a quadratic fit to the first points of each channel."""
    vals = default.as_array().copy()
    t = run["t"] - run["t"][0]
    for c in CHANNELS:
        if c not in run:
            continue
        m = np.isfinite(run[c])
        if not m.any():
            continue
        tc, yc = t[m], run[c][m]
        if c == "phi":
            yc = np.unwrap(yc)
        n = tc.size
        k = int(min(n, max(5, min(40, n // 4))))
        tc, yc = tc[:k], yc[:k]
        deg = min(2, k - 1)
        if deg == 0:
            vals[START.index(c)] = yc[0]
            continue
        coef = np.polynomial.polynomial.polyfit(tc, yc, deg)
        vals[START.index(c)] = coef[0]
        vals[START.index(_PAIR[c])] = coef[1]
    return State(*vals)


def _noise_from_data(runs, c) -> float:
    """Rough σ of a channel from second differences of the data (initial weights only)."""
    parts = []
    for run in runs:
        if c in run:
            y = run[c][np.isfinite(run[c])]
            if c == "phi":
                y = np.unwrap(y)
            if y.size >= 3:
                parts.append(np.diff(y, 2))
    if not parts:
        return 1.0
    d = np.concatenate(parts)
    mad = 1.4826 * np.median(np.abs(d - np.median(d)))
    return float(mad / math.sqrt(6.0))


def _one_blas_thread():
    """Limit BLAS to one thread (if threadpoolctl is installed): the SVD of a tall Jacobian
    (3000 x 33) takes 5 ms on one thread but up to 0.9 s with threads on a busy machine."""
    try:
        from threadpoolctl import threadpool_limits
    except ImportError:  # pragma: no cover - optional
        import contextlib

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
# result


def _num(x):
    x = float(x)
    return x if math.isfinite(x) else None


@dataclass(frozen=True, slots=True, repr=False)
class FitResult:
    """Outcome of :func:`fit` (SI units throughout).

    Attributes
    ----------
    estimates, std_errors : dict
        Fitted value and standard error of each free physical parameter (``free``). The
        standard error is ``inf`` for a parameter the data cannot determine.
    parameter_names : tuple of str
        All fitted parameters: the free physical ones, then each run's free start components
        as ``run{k}.{x|y|phi|vx|vy|omega}``.
    values : ndarray
        Their fitted values.
    covariance, correlation : ndarray
        Covariance (JᵀJ)⁻¹ σ̂² (MODEL §12) and correlation of ``parameter_names`` (NaN in
        the rows of parameters that are not identifiable).
    identifiable : dict
        For each of ``parameter_names``, whether the data determine it (module docstring).
    singular_values : ndarray
        Singular values of the Jacobian scaled by the parameters' typical sizes.
    condition : float
        Their ratio, largest over smallest.
    starts : tuple of State
        Each run's start state at its first measured time.
    start_errors : tuple of dict
        Standard errors of each run's fitted start components.
    body, friction : Body, FrictionTensor
        The body and tensor with the fitted values.
    chi2, dof, reduced_chi2 : float
        Σ r² with r = residual/σ, N − P, and their ratio (≈ 1 when σ is estimated).
    rms : dict
        Root-mean-square residual of each channel [m or rad].
    sigma : dict
        Noise level used for each channel [m or rad]; ``sigma_estimated`` says which were
        estimated from the residuals.
    n_points, n_runs : int
        Observations (channel values) used, and runs.
    data, fitted, residuals : tuple of dict
        Per run: measured, simulated and measured − simulated (φ wrapped to (−π, π]) values at
        the measured times, keyed ``t``, ``x``, ``y``, ``phi`` (NaN where not measured).
    trajectories : tuple of Trajectory
        The fitted motion of each run (time from the run's first measured time).
    success, message, nfev : bool, str, int
        Convergence of the optimiser and the number of residual evaluations.
    warnings : tuple of str
        Messages of the warnings issued by the fit.
    seconds : float
        Wall time of the fit.
    """

    estimates: dict
    std_errors: dict
    parameter_names: tuple
    values: np.ndarray
    covariance: np.ndarray
    correlation: np.ndarray
    identifiable: dict
    singular_values: np.ndarray
    condition: float
    starts: tuple
    start_errors: tuple
    body: Body
    friction: FrictionTensor
    chi2: float
    dof: int
    reduced_chi2: float
    rms: dict
    sigma: dict
    sigma_estimated: dict
    n_points: int
    n_runs: int
    data: tuple = field(repr=False)
    fitted: tuple = field(repr=False)
    residuals: tuple = field(repr=False)
    trajectories: tuple = field(repr=False)
    loss: str = "linear"
    success: bool = True
    message: str = ""
    nfev: int = 0
    warnings: tuple = ()
    seconds: float = 0.0

    def __repr__(self) -> str:
        parts = []
        for k, val in self.estimates.items():
            se = self.std_errors[k]
            parts.append(
                f"{k}={val:.6g} ± {se:.2g}"
                if math.isfinite(se)
                else f"{k}={val:.6g} (not identifiable)"
            )
        notes = f", warnings={len(self.warnings)}" if self.warnings else ""
        return (
            f"FitResult({', '.join(parts)}; chi2/dof={self.reduced_chi2:.3g}, "
            f"runs={self.n_runs}, points={self.n_points}, success={self.success}{notes})"
        )

    def _repr_html_(self) -> str:
        """Estimates ± standard errors, 95 % intervals, the fit's warnings (identifiability,
        correlations, bounds) and its goodness for notebooks (no arrays)."""
        from html import escape

        head = "".join(
            f"<th>{h}</th>" for h in ("parameter", "estimate", "std error", "95% interval")
        )
        rows = []
        for k, val in self.estimates.items():
            se = self.std_errors[k]
            if math.isfinite(se):
                lo, hi = self.interval(k)
                cells = (f"{val:.6g}", f"{se:.3g}", f"[{lo:.6g}, {hi:.6g}]")
            else:
                cells = (f"{val:.6g}", "inf", "not identifiable")
            rows.append(
                f"<tr><th style='text-align:left'>{escape(k)}</th>"
                + "".join(f"<td>{c}</td>" for c in cells)
                + "</tr>"
            )
        stats = {
            "chi2 / dof": f"{self.chi2:.6g} / {self.dof} = {self.reduced_chi2:.4g}",
            "points, runs": f"{self.n_points} values in {self.n_runs} run(s)",
            "noise sigma": ", ".join(
                f"{c} {x:.3g} {_UNITS[c]}{' (estimated)' if self.sigma_estimated[c] else ''}"
                for c, x in self.sigma.items()
            ),
            "converged": f"{self.success} ({self.message})",
        }
        for m in self.warnings:
            stats.setdefault("warnings", "")
            stats["warnings"] += ("<br>" if stats["warnings"] else "") + escape(m)
        for k, text in stats.items():
            body = text if k == "warnings" else escape(text)
            rows.append(
                f"<tr><th style='text-align:left'>{escape(k)}</th><td colspan='3'>{body}</td></tr>"
            )
        return f"<table><caption>FitResult</caption><tr>{head}</tr>{''.join(rows)}</table>"

    def to_pandas(self, level: float = 0.95):
        """Every fitted parameter as a :class:`pandas.DataFrame` (one row each, indexed by
        ``parameter_names``): ``estimate``, ``std_error`` and the normal-approximation
        interval at ``level`` (``ci_low``, ``ci_high``; ±inf where not identifiable), and
        ``identifiable``. The free physical parameters come first, then each run's start
        components ``run{k}.{x|y|phi|vx|vy|omega}``; the goodness of fit (:meth:`summary`)
        is in ``DataFrame.attrs``. Needs pandas (``pip install pandas``)."""
        try:
            import pandas as pd  # type: ignore[import-untyped]  # no stubs installed
        except ImportError:  # pragma: no cover - depends on the environment
            raise ImportError("FitResult.to_pandas needs pandas: pip install pandas") from None
        from scipy.stats import norm

        level = v.in_range("level", level, 0.0, 1.0, lo_open=True, hi_open=True)
        z = float(norm.ppf(0.5 + level / 2.0))
        est, se = [], []
        for name, val in zip(self.parameter_names, self.values):
            if name in self.std_errors:
                est.append(self.estimates[name])
                se.append(self.std_errors[name])
            else:
                run, comp = name.split(".")
                est.append(float(val))
                se.append(self.start_errors[int(run[3:])][comp])
        e, s = np.array(est, dtype=float), np.array(se, dtype=float)
        df = pd.DataFrame(
            {
                "estimate": e,
                "std_error": s,
                "ci_low": e - z * s,
                "ci_high": e + z * s,
                "identifiable": [bool(self.identifiable[n]) for n in self.parameter_names],
            },
            index=pd.Index(list(self.parameter_names), name="parameter"),
        )
        df.attrs.update(self.summary())
        df.attrs["level"] = level
        return df

    @property
    def names(self) -> tuple:
        """The free physical parameters, in order."""
        return tuple(self.estimates)

    def interval(self, name: str, level: float = 0.95) -> tuple[float, float]:
        """Normal-approximation confidence interval of a free parameter."""
        from scipy.stats import norm

        z = float(norm.ppf(0.5 + level / 2.0))
        val, se = self.estimates[name], self.std_errors[name]
        return (val - z * se, val + z * se)

    def physical_correlation(self) -> dict:
        """Correlation among the free physical parameters as a nested dict."""
        n = len(self.estimates)
        names = list(self.estimates)
        return {
            a: {b: _num(self.correlation[i, j]) for j, b in enumerate(names)}
            for i, a in enumerate(names[:n])
        }

    def summary(self) -> dict:
        """JSON-ready dict (non-finite numbers are ``None``)."""
        starts = []
        for k, st in enumerate(self.starts):
            d = {c: _num(getattr(st, c)) for c in START}
            d["std_errors"] = {c: _num(e) for c, e in self.start_errors[k].items()}
            d["t0"] = _num(self.data[k]["t"][0])
            starts.append(d)
        return {
            "estimates": {k: _num(x) for k, x in self.estimates.items()},
            "std_errors": {k: _num(x) for k, x in self.std_errors.items()},
            "correlation": self.physical_correlation(),
            "identifiable": dict(self.identifiable),
            "chi2": _num(self.chi2),
            "dof": int(self.dof),
            "reduced_chi2": _num(self.reduced_chi2),
            "rms": {k: _num(x) for k, x in self.rms.items()},
            "sigma": {k: _num(x) for k, x in self.sigma.items()},
            "sigma_estimated": dict(self.sigma_estimated),
            "condition": _num(self.condition),
            "n_points": int(self.n_points),
            "n_runs": int(self.n_runs),
            "starts": starts,
            "frame": self.friction.frame,
            "loss": self.loss,
            "success": bool(self.success),
            "message": self.message,
            "nfev": int(self.nfev),
            "warnings": list(self.warnings),
            "seconds": _num(self.seconds),
        }

    def table(self, labels=None) -> str:
        """The estimates ± standard errors and the goodness of fit as text.

        ``labels`` names the runs (default 0, 1, ...), e.g. the ``run`` column of the CSV.
        """
        labels = [str(k) for k in range(self.n_runs)] if labels is None else list(labels)
        lines = [f"{'parameter':<18} {'estimate':>14} {'std error':>12}  95% interval"]
        for k, val in self.estimates.items():
            se = self.std_errors[k]
            if math.isfinite(se):
                lo, hi = self.interval(k)
                lines.append(f"{k:<18} {val:>14.8g} {se:>12.3g}  [{lo:.6g}, {hi:.6g}]")
            else:
                lines.append(f"{k:<18} {val:>14.8g} {'inf':>12}  not identifiable")
        names = list(self.estimates)
        if len(names) > 1:
            lines.append("correlation:")
            for i, a in enumerate(names):
                row = " ".join(
                    f"{self.correlation[i, j]:+7.3f}"
                    if math.isfinite(self.correlation[i, j])
                    else f"{'n/a':>7}"
                    for j in range(len(names))
                )
                lines.append(f"  {a:<16} {row}")
        for k, st in enumerate(self.starts):
            lines.append(
                f"{'run ' + labels[k] + ' start':<18}: x={st.x:.6g} m, y={st.y:.6g} m, phi={st.phi:.6g} rad, "
                f"vx={st.vx:.6g} m/s, vy={st.vy:.6g} m/s, omega={st.omega:.6g} rad/s"
            )
        rms = ", ".join(f"{c} {x:.3g} {_UNITS[c]}" for c, x in self.rms.items())
        sig = ", ".join(
            f"{c} {x:.3g} {_UNITS[c]}{' (estimated)' if self.sigma_estimated[c] else ''}"
            for c, x in self.sigma.items()
        )
        lines += [
            f"chi2 / dof        : {self.chi2:.6g} / {self.dof} = {self.reduced_chi2:.4g}",
            f"rms residual      : {rms}",
            f"noise sigma       : {sig}",
            (
                f"points, runs      : {self.n_points} values in {self.n_runs} run(s); "
                f"{self.nfev} evaluations, {self.seconds:.3g} s"
            ),
            f"converged         : {self.success} ({self.message})",
        ]
        return "\n".join(lines)

    def predict(self, run: int, t) -> dict:
        """Fitted x, y, φ of run ``run`` at absolute times ``t`` [s] (the data's clock)."""
        t = np.asarray(t, dtype=float) - self.data[run]["t"][0]
        return trajectory_at(self.trajectories[run], t)


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
        raise ValueError(f"free parameter {dup[0]!r} is given twice")
    if ("xi_c" in free or "eta_c" in free) and not isinstance(body.pressure, LinearPressure):
        raise ValueError(
            f"free parameters xi_c, eta_c need a body with LinearPressure; this body has "
            f"{type(body.pressure).__name__}"
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
) -> FitResult:
    """Fit friction parameters (and each run's start state) to tracked motion (MODEL §12).

    Parameters
    ----------
    data : run or list of runs
        A run maps ``t`` [s] and any of ``x``, ``y`` [m] (mass centre G) and ``phi`` [rad]
        to arrays (a dict or a NumPy structured array; :func:`read_runs` reads CSV). Runs
        share the physical parameters; each has its own start state at its first time.
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
        Passed to :func:`slidespin.motion.simulate`. With the defaults (1e-12, the integrator's own
        steps) the model between steps (cubic Hermite) is within 1e-6 a and 1e-5 rad of a
        dense run (tests/test_fit.py), far below tracking noise.
    fd_step : float, default 1e-4
        Central-difference step, relative to each parameter's typical size; valid:
        [:data:`MIN_FD_STEP`, :data:`MAX_FD_STEP`] = [1e-8, 0.1] (a smaller step differences
        round-off of the simulated motion, a larger one is no longer a derivative).
    corr_limit : float, default 0.99
        |correlation| above which a pair of parameters is reported as not separable.
    max_nfev : int, optional
        Budget of residual evaluations for each least-squares pass.

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
    from scipy.optimize import least_squares

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
        runs, body, friction, free, fixed, start_free, guess_states, g, rtol, max_step, fd_step
    )
    n_par = len(prob.names)
    if prob.n_obs <= n_par:
        raise ValueError(
            f"too few measured values: {prob.n_obs} for {n_par} fitted parameters "
            f"({', '.join(prob.names)}); need more values than parameters"
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
    from dataclasses import replace

    if not isinstance(friction, FrictionTensor):
        raise ValueError(f"friction = {friction!r} is invalid; valid values: a FrictionTensor")
    fits, scores = {}, {}
    for frame in ("plane", "body"):
        fits[frame] = fit(data, body, replace(friction, frame=frame), free, **kwargs)
        scores[frame] = frame_score(fits[frame])
    best = min(scores, key=lambda frame: scores[frame])
    return fits[best], scores, fits
