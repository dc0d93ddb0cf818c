"""Tracked runs: the input of :func:`slidespin.analysis.fit.fit` (MODEL §12).

A run holds the measured times ``t`` [s] and any of the channels ``x``, ``y`` [m] (position of
the mass centre G) and ``phi`` [rad] (body angle), one value per time; NaN marks a missing
value. :func:`read_runs` reads runs from a CSV file, :func:`as_runs` validates them in memory,
and :func:`trajectory_at` evaluates a simulated motion at the measured times (the cubic
Hermite interpolant of the integrator's steps). The start guesses and rough noise levels a fit
begins from are read off the data here too.
"""

from __future__ import annotations

import csv
import io
import math
import os
from collections.abc import Mapping

import numpy as np
from numpy.typing import NDArray
from scipy.interpolate import CubicHermiteSpline

from slidespin._io import read_regular_file
from slidespin.motion.state import State

__all__ = ["CHANNELS", "MAX_DATA_BYTES", "as_runs", "read_runs", "trajectory_at"]

#: measured channels of a run: positions of G [m] and the body angle [rad]
CHANNELS = ("x", "y", "phi")
START = ("x", "y", "phi", "vx", "vy", "omega")
_UNITS = {"x": "m", "y": "m", "phi": "rad"}
_PAIR = {"x": "vx", "y": "vy", "phi": "omega"}
#: largest data file :func:`read_runs` reads [bytes]
MAX_DATA_BYTES = 100_000_000


def _channel(name, values, n, where):
    try:
        arr = np.asarray(values, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(
            f"{where}: column {name!r} must hold numbers; valid values: real numbers (NaN "
            "marks a missing value)"
        ) from None
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
        raise ValueError(
            f"{where}: the column 't' (time [s]) is missing; valid columns: t and any of x, y, phi"
        )
    try:
        t = np.asarray(get("t"), dtype=float)
    except (TypeError, ValueError):
        raise ValueError(
            f"{where}: column 't' must hold numbers; valid values: finite, strictly "
            "increasing times [s]"
        ) from None
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
        raise ValueError(
            f"{where}: no measured value; valid values: at least one finite value of x, y or phi"
        )
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
        One ``{'t': ..., 'x': ..., ...}`` per run, ready for
        :func:`~slidespin.analysis.fit.fit`; with ``labels=True``, the pair (runs, run
        labels) (label ``'0'`` without a run column).

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
        raise ValueError(
            f"data file {name!r} is not a UTF-8 text (CSV) file; valid values: a UTF-8 CSV "
            "file with a header line t,x,y,phi[,run]"
        ) from None
    try:
        rows = list(csv.reader(io.StringIO(text, newline="")))
    except csv.Error as exc:
        raise ValueError(
            f"data file {name!r} cannot be read: {exc}; valid values: a CSV file with a "
            "header line t,x,y,phi[,run]"
        ) from None
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
        raise ValueError(
            f"{name}: line {head_line}: column {dup[0]!r} appears twice; valid values: each "
            "of t, x, y, phi, run at most once"
        )
    if "t" not in cols:
        raise ValueError(
            f"{name}: line {head_line}: the column 't' (time [s]) is missing; valid "
            "columns: t and any of x, y, phi (and run)"
        )
    if not set(cols) & set(CHANNELS):
        raise ValueError(
            f"{name}: line {head_line}: no column x, y or phi; valid columns: t and at least "
            "one of x, y, phi (and run)"
        )
    if len(lines) == 1:
        raise ValueError(
            f"{name}: no data rows after the header; valid values: at least one row of numbers"
        )
    runs: dict[str, dict[str, list]] = {}
    for line, r in lines[1:]:
        if len(r) != len(cols):
            raise ValueError(
                f"{name}: line {line} has {len(r)} fields; valid values: {len(cols)} fields, "
                "one per column of the header"
            )
        label = "0"
        vals = {}
        for c, cell in zip(cols, r):
            cell = cell.strip()
            if c == "run":
                if not cell:
                    raise ValueError(
                        f"{name}: line {line}, column 'run': empty run label; valid values: "
                        "a non-empty label"
                    )
                label = cell
                continue
            if cell == "" or cell.lower() == "nan":
                if c == "t":
                    raise ValueError(
                        f"{name}: line {line}, column 't': missing time; valid values: a "
                        "finite time [s] on every line"
                    )
                vals[c] = math.nan
                continue
            try:
                x = float(cell)
            except ValueError:
                raise ValueError(
                    f"{name}: line {line}, column {c!r}: {cell!r} is not a number; valid "
                    "values: a finite number, or an empty cell for a missing value"
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
                f"time of run {label!r}: {run['t'][-1]!r}); valid values: strictly increasing "
                "times within a run"
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
                "measured x, y or phi; valid values: at least one finite value per run"
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
    pos = np.column_stack((traj.x, traj.y, traj.phi))
    vel = np.column_stack((traj.vx, traj.vy, traj.omega))
    return hermite_at(traj.t, pos, vel, t, traj.t_stop <= 0.0)


def hermite_at(ts, pos, vel, t, at_rest: bool = False) -> dict:
    """The cubic Hermite interpolant of positions ``pos`` (n, 3: x, y, φ) with rates ``vel``
    (n, 3) at the increasing times ``ts`` (the last the stop), at times ``t``; from the last
    time on, the last row. :func:`trajectory_at` for a trajectory, and for its sensitivities
    (∂x/∂θ with rate ∂vx/∂θ at fixed t, MODEL §15). Returns ``{'x', 'y', 'phi'}``."""
    val = hermite_columns(ts, pos, vel, t, at_rest)
    return {c: val[..., i] for i, c in enumerate(CHANNELS)}


def hermite_columns(ts, pos, vel, t, at_rest: bool = False) -> NDArray[np.float64]:
    """:func:`hermite_at` for any number of columns: ``pos`` and ``vel`` (n, m), the
    interpolant at ``t`` as an array (t.shape + (m,)) (one spline for all columns: the
    sensitivities of every parameter at once)."""
    t = np.asarray(t, dtype=float)
    if ts.size < 2 or at_rest:
        return np.broadcast_to(pos[-1], t.shape + pos.shape[1:]).copy()
    thr = 1e-12 * ts[-1]
    idx = np.concatenate(([0], 1 + np.flatnonzero(np.diff(ts) > thr)))
    last = ts.size - 1
    if idx[-1] != last:
        if ts[last] - ts[idx[-1]] > thr:
            idx = np.append(idx, last)
        else:
            idx[-1] = last
    if idx.size < 2:
        return np.broadcast_to(pos[-1], t.shape + pos.shape[1:]).copy()
    spline = CubicHermiteSpline(ts[idx], pos[idx], vel[idx], axis=0, extrapolate=False)
    tt = np.clip(t, ts[0], ts[last])
    val = np.asarray(spline(tt))
    val[tt >= ts[last]] = pos[last]
    return val


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
