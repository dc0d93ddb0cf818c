"""Private input checks of :mod:`slidespin.motion.batch`: the initial states of a batch given
as an (N, 6) array, a sequence of :class:`~slidespin.State`, a pandas DataFrame or a dict of
columns (read by column name, :data:`STATE_COLUMNS`), checked row by row with one-line
errors naming the row and the field, and the run options (``_check_run``).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from slidespin import _validate as v
from slidespin.motion.simulate import check_solver_options
from slidespin.motion.state import State

#: the fields of :class:`~slidespin.State`: the columns of an (N, 6) array of initial states
STATE_FIELDS = ("x", "y", "phi", "vx", "vy", "omega")

#: column names of a table of initial states → the quantity each gives (see
#: :data:`slidespin.motion.batch.STATE_COLUMNS`)
STATE_COLUMNS = {
    **{name: name for name in STATE_FIELDS},
    **{name + "0": name for name in STATE_FIELDS},
    "speed": "speed",
    "v0": "speed",
    "theta": "theta",
    "theta0": "theta",
}


_STATE_BOUNDS = (
    (v.POSITION, "m"),
    (v.POSITION, "m"),
    (None, "rad"),
    (v.SPEED, "m/s"),
    (v.SPEED, "m/s"),
    (v.SPIN, "rad/s"),
)
_FORMS = (
    "an (N, 6) array of rows (x, y, phi, vx, vy, omega), a sequence of slidespin.State, or a "
    "table (pandas DataFrame or dict of columns) with named columns"
)


def _array_label(i: int, j: int) -> str:
    return f"initial_states[{i}, {j}] ({STATE_FIELDS[j]})"


def _is_table(obj: object) -> bool:
    """A dict of columns, or a DataFrame-like object (``columns`` and item access)."""
    if isinstance(obj, Mapping):
        return True
    return (
        not isinstance(obj, np.ndarray) and hasattr(obj, "columns") and hasattr(obj, "__getitem__")
    )


def _table_rows(table: Any) -> tuple[np.ndarray, Any]:
    """(N, 6) rows (x, y, phi, vx, vy, omega) from a table read by column name
    (:data:`STATE_COLUMNS`), and the label of entry (i, j) for messages."""
    names = list(table.keys()) if isinstance(table, Mapping) else list(table.columns)
    valid = ", ".join(STATE_COLUMNS)
    for c in names:
        if not isinstance(c, str) or c not in STATE_COLUMNS:
            hint = (
                " (a table is read by column name, not by position: name the columns, or pass "
                "an (N, 6) array of rows (x, y, phi, vx, vy, omega))"
                if not isinstance(c, str)
                else ""
            )
            raise ValueError(
                f"initial_states has the column {c!r}, which names no part of the initial "
                f"state{hint}; valid columns: {valid}"
            )
    given: dict[str, str] = {}  # quantity -> column
    for c in names:
        q = STATE_COLUMNS[c]
        if q in given:
            raise ValueError(
                f"initial_states has the columns {given[q]!r} and {c!r}, two names of {q}; "
                "valid: one column per quantity"
            )
        given[q] = c
    polar = any(q in given for q in ("speed", "theta"))
    if polar and any(q in given for q in ("vx", "vy")):
        raise ValueError(
            "initial_states gives the velocity twice, as "
            + ", ".join(repr(given[q]) for q in ("vx", "vy", "speed", "theta") if q in given)
            + "; valid: either vx and vy, or speed and theta"
        )
    required = ("speed", "theta", "omega") if polar else ("vx", "vy", "omega")
    missing = [q for q in required if q not in given]
    if missing:
        raise ValueError(
            f"initial_states lacks the column {missing[0]!r}; valid tables have the required "
            "columns omega and the velocity "
            "(vx and vy, or speed and theta); optional: x, y, phi (default 0); the names with "
            "a 0 (vx0, ..., v0, theta0) are accepted too"
        )
    cols: dict[str, np.ndarray] = {}
    for q, c in given.items():
        try:
            arr = np.asarray(table[c])
        except (TypeError, ValueError):
            arr = np.asarray(None, dtype=object)
        if arr.ndim != 1 or arr.dtype.kind not in "fiu":
            raise ValueError(
                f"initial_states[{c!r}] is invalid (shape {arr.shape}, dtype {arr.dtype}); "
                "valid values: a 1-D column of real numbers"
            )
        cols[q] = arr.astype(float)
    sizes = sorted({a.size for a in cols.values()})
    if len(sizes) > 1:
        raise ValueError(
            f"initial_states has columns of lengths {sizes}; valid: columns of one length N"
        )
    n = sizes[0]
    rows = np.zeros((n, 6))
    for j, q in enumerate(STATE_FIELDS):
        if q in cols:
            rows[:, j] = cols[q]
    if polar:
        speed, theta = cols["speed"], cols["theta"]
        ok = np.isfinite(speed) & (speed >= 0.0) & (speed <= v.SPEED)
        for name, arr, good, rng in (
            (given["speed"], speed, ok, f"[0, {v.SPEED:g}] m/s"),
            (given["theta"], theta, np.isfinite(theta), "any finite real number [rad]"),
        ):
            if not good.all():
                i = int(np.flatnonzero(~good)[0])
                raise ValueError(
                    f"initial_states[{name!r}][{i}] = {float(arr[i])!r} is invalid; "
                    f"valid range: {rng}"
                )
        # State.from_speed's arithmetic (libm cos and sin): the same numbers as simulate()
        rows[:, 3] = [sp * math.cos(th) for sp, th in zip(speed.tolist(), theta.tolist())]
        rows[:, 4] = [sp * math.sin(th) for sp, th in zip(speed.tolist(), theta.tolist())]

    def label(i: int, j: int) -> str:
        q = STATE_FIELDS[j]
        col = given.get(q, f"{q}, from speed and theta")
        return f"initial_states[{col!r}][{i}]" if q in given else f"initial_states row {i} ({col})"

    return rows, label


def _state_rows(initial_states: Any) -> tuple[np.ndarray, Any]:
    """The initial states as (N, 6) rows (x, y, phi, vx, vy, omega) and the label of entry
    (i, j) for messages; shapes and types are checked, values by :func:`_check_run`."""
    obj = initial_states
    if isinstance(obj, State):
        raise ValueError(
            f"initial_states = {v._short(obj)} is one State; valid values: {_FORMS} "
            "(for one case, [state])"
        )
    if _is_table(obj):
        return _table_rows(obj)
    if isinstance(obj, (list, tuple)) and any(isinstance(x, State) for x in obj):
        for i, x in enumerate(obj):
            if not isinstance(x, State):
                raise ValueError(
                    f"initial_states[{i}] = {v._short(x)} is invalid in a sequence of State; "
                    "valid values: slidespin.State objects only"
                )
        return np.array([x.as_array() for x in obj], dtype=float), _array_label
    if isinstance(obj, (list, tuple)) and len(obj) == 0:
        return np.empty((0, 6)), _array_label
    try:
        if isinstance(obj, (str, bytes)) or np.asarray(obj).dtype.kind == "b":
            raise TypeError
        st = np.asarray(obj, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(
            "initial_states must be an (N, 6) array of real numbers (x, y, phi, vx, vy, "
            f"omega); got {v._short(obj)}; valid values: {_FORMS}"
        ) from None
    return st, _array_label


def _check_run(initial_states, n, rtol, max_steps, g):
    """Validate the initial states (:func:`_state_rows`; N = ``n`` if given; the ranges of
    :class:`~slidespin.State`) and the solver options of :func:`simulate_many` and
    :func:`simulate_bodies`; the states as (N, 6) rows (x, y, phi, vx, vy, omega)."""
    st, label = _state_rows(initial_states)
    if st.ndim != 2 or st.shape[1] != 6 or (n is not None and st.shape[0] != n):
        rows = "N" if n is None else str(n)
        raise ValueError(
            f"initial_states has shape {st.shape}; valid: ({rows}, 6), one row "
            "(x, y, phi, vx, vy, omega) per case"
        )
    rtol, max_steps = check_solver_options(rtol, max_steps)
    g = v.bounded("g", g, *v.GRAVITY, "m/s^2")
    bad = ~np.isfinite(st)
    if bad.any():
        i, j = (int(x[0]) for x in np.nonzero(bad))
        raise ValueError(
            f"{label(i, j)} = {float(st[i, j])!r} is not finite; "
            "valid range: any finite real number"
        )
    for j, (bound, unit) in enumerate(_STATE_BOUNDS):
        if bound is not None and st.shape[0] and np.abs(st[:, j]).max() > bound:
            i = int(np.argmax(np.abs(st[:, j]) > bound))
            raise ValueError(
                f"{label(i, j)} = {float(st[i, j])!r} {unit} is invalid; valid range: "
                f"[{-bound:g}, {bound:g}] {unit} (the range of slidespin.State)"
            )
    return st, rtol, max_steps, g
