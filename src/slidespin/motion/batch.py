"""Many trajectories at once: the compiled engine run in parallel over all cores.

``simulate_many`` integrates one body under one friction tensor from N initial states;
``simulate_bodies`` one body object per case (any patches: ellipses and footprints mixed,
e.g. a sweep over a ring's width); ``simulate_cases`` takes every parameter per case (patch,
law, tensor, inertia, g, state) as columns, which is what parameter sweeps need. All return
a :class:`StopResults` of arrays.

Initial states (:func:`simulate_many`, :func:`simulate_bodies`) are an (N, 6) array of rows
(x, y, phi, vx, vy, omega), a sequence of :class:`~slidespin.State`, or a table (a pandas
DataFrame, or a dict of columns) read by column *name* (:data:`STATE_COLUMNS`).

Memory: no per-step data is kept. The cases run in chunks of at most ``CHUNK`` through
:func:`slidespin.motion._parallel.integrate_many` (``prange`` over the cases of a chunk), so
besides the inputs only the results and a copy of the initial states are held for all N
(122 bytes per case) and the working arrays for one chunk; each worker thread integrates in a
fixed ~20 kB. When a progress bar is drawn the chunks are smaller, about 1 % of the batch
(``chunk_size``), so that it moves. The cases are independent: the chunking does not
change any number.
"""

from __future__ import annotations

import math
import warnings
from collections import Counter
from collections.abc import Iterable
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike

from slidespin import _validate as v
from slidespin._progress import progress_bar, show_progress
from slidespin.contact import _engine
from slidespin.contact.body import Body, require_thin
from slidespin.contact.friction import FrictionTensor
from slidespin.motion import _integrator, _parallel
from slidespin.motion._batch_inputs import STATE_COLUMNS, STATE_FIELDS, _check_run
from slidespin.motion._cases import CASE_FIELDS, validated_columns
from slidespin.motion._report import _html_table
from slidespin.motion._stops import ENDING_TOL
from slidespin.motion.outcomes import ENDINGS, STATUSES
from slidespin.motion.sensitivity import STOP_OUTPUTS, check_parameters, check_setup
from slidespin.motion.simulate import check_solver_options, simulate
from slidespin.motion.state import State

if TYPE_CHECKING:
    import pandas as pd  # type: ignore[import-untyped]  # pandas ships no type information

__all__ = [
    "StopResults",
    "simulate_many",
    "simulate_bodies",
    "simulate_cases",
    "CASE_FIELDS",
    "STATE_FIELDS",
    "STATE_COLUMNS",
    "INPUT_COLUMNS",
]

#: per-case inputs of :func:`simulate_cases` and their defaults (None: required)
CASE_FIELDS = CASE_FIELDS

#: the fields of :class:`~slidespin.State`: the columns of an (N, 6) array of initial states
STATE_FIELDS = STATE_FIELDS

#: column names of a table of initial states (a DataFrame or a dict of columns) → the
#: quantity each gives: the :class:`~slidespin.State` fields, the sweep tables' names with a
#: 0 (``x0``, ..., ``omega0``, ``v0``, ``theta0``), and ``speed``, ``theta`` of
#: ``State.from_speed``. Required: ``omega`` and the velocity, as ``vx`` and ``vy`` or
#: as ``speed`` [m/s] and ``theta`` [rad]; ``x``, ``y``, ``phi`` default to 0.
STATE_COLUMNS = STATE_COLUMNS

#: the columns of :meth:`StopResults.to_pandas` that hold the initial state (the sweep
#: tables' names: the State fields with a 0), before the result columns
INPUT_COLUMNS = tuple(name + "0" for name in STATE_FIELDS)

#: most cases per call of the parallel engine (bounds the temporary arrays of a batch)
CHUNK = 1 << 16
#: fewest cases per call of the parallel engine in a large batch (``chunk_size``)
MIN_CHUNK = 4096

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
        terminal direction ϑ* [rad] (NaN where no limiting direction exists: at rest,
        ``spiral`` endings, pure spinning with a turning velocity; see
        :class:`slidespin.Trajectory`).
    ending_code, status_code : ndarray of int8
        Indices into :data:`ENDINGS` and status names; ``ending``/``status`` give strings.
    n_steps : ndarray of int
        Integrator steps per case.
    saddle_energy : ndarray
        For ``saddle`` statuses, the fraction of the initial kinetic energy down to which the
        saddle's ending was observed (NaN otherwise; see :class:`slidespin.Trajectory`).
    initial_states : ndarray, shape (N, 6), or None
        The initial states the cases started from, rows (x, y, phi, vx, vy, omega) in SI
        units (a copy; velocities given as speed and direction are converted). None only
        for results built by hand.
    sensitivities : dict or None
        With ``simulate_many(..., sensitivities=...)``: the stop's derivatives per case as
        columns ``d_<q>/d_<parameter>`` (q in t_stop, x, y, phi, beta_stop; SI units; NaN
        where a case has none: at rest, or not stopped), MODEL §15.
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
    saddle_energy: np.ndarray
    initial_states: np.ndarray | None = field(default=None, repr=False)
    sensitivities: dict[str, np.ndarray] | None = field(default=None, repr=False)

    def __len__(self) -> int:
        return self.t_stop.size

    def __repr__(self) -> str:
        counts = Counter(self.status.tolist())
        ends = Counter(self.ending.tolist())
        fmt = lambda c: ", ".join(f"{k}: {n}" for k, n in sorted(c.items()))  # noqa: E731
        return f"StopResults({len(self)} cases; status {{{fmt(counts)}}}; ending {{{fmt(ends)}}})"

    def to_pandas(self) -> pd.DataFrame:
        """The cases as a :class:`pandas.DataFrame`, one row per case, SI units. Needs pandas.

        The first columns are the initial state, named like the :class:`~slidespin.State`
        fields with a 0 (:data:`INPUT_COLUMNS`: ``x0``, ``y0``, ``phi0``, ``vx0``, ``vy0``,
        ``omega0``, as in the sweep tables; the 0 keeps them apart from the results such as
        ``x_stop``), then the results: the columns of :meth:`as_dict`, with ``ending`` and
        ``status`` as strings. The input columns are names :func:`simulate_many` reads, so
        ``simulate_many(body, friction, df[list(INPUT_COLUMNS)])`` runs the cases again.
        """
        try:
            # lazy: pandas is optional and slow to import
            import pandas as pd  # type: ignore[import-untyped]
        except ImportError:  # pragma: no cover - depends on the environment
            raise ImportError("StopResults.to_pandas needs pandas: pip install pandas") from None
        columns: dict[str, np.ndarray] = {}
        if self.initial_states is not None:
            columns.update(
                {name: self.initial_states[:, j] for j, name in enumerate(INPUT_COLUMNS)}
            )
        columns.update(self.as_dict())
        return pd.DataFrame(columns)

    def _repr_html_(self) -> str:
        """Cases per status and per ending, for notebooks (no arrays)."""
        c = self.counts()
        items = {"cases": len(self)}
        items.update({f"status {k}": n for k, n in sorted(c["status"].items())})
        items.update({f"ending {k}": n for k, n in sorted(c["ending"].items())})
        return _html_table("StopResults", items)

    def counts(self) -> dict[str, dict[str, int]]:
        """Number of cases per status and per ending: ``{"status": {...}, "ending": {...}}``."""
        return {
            "status": dict(Counter(self.status.tolist())),
            "ending": dict(Counter(self.ending.tolist())),
        }

    @property
    def ending(self) -> np.ndarray:
        """Ending names (:data:`slidespin.motion.outcomes.ENDINGS`)."""
        return np.asarray(ENDINGS, dtype=object)[self.ending_code]

    @property
    def status(self) -> np.ndarray:
        """Status names (:data:`slidespin.motion.outcomes.STATUSES`)."""
        return np.asarray(STATUSES, dtype=object)[self.status_code]

    def as_dict(self) -> dict[str, np.ndarray]:
        """Result column name → array, with string columns for ending and status (the
        results only; :meth:`to_pandas` adds the initial states)."""
        out = {
            k: getattr(self, k)
            for k in (
                "t_stop",
                "x_stop",
                "y_stop",
                "phi_stop",
                "path_length",
                "beta_stop",
                "theta_stop",
                "saddle_energy",
                "n_steps",
            )
        }
        out["ending"] = self.ending
        out["status"] = self.status
        if self.sensitivities is not None:
            out.update(self.sensitivities)
        return out


def simulate_cases(
    cases: dict[str, Any], rtol: float = 1e-10, max_steps: int = 200_000
) -> StopResults:
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
    rtol, max_steps = check_solver_options(rtol, max_steps)
    col, inertia = validated_columns(cases)
    return _run(col, inertia, rtol, max_steps)


def _run(col, inertia, rtol, max_steps) -> StopResults:
    def pars_of(lo, hi):
        """Parameter rows of cases lo..hi (natural units)."""
        a = col["a"][lo:hi]
        lin = col["law"][lo:hi] == 1
        ang = col["angle"][lo:hi]
        c, s = np.cos(ang), np.sin(ang)
        fx, fy, f = col["fx"][lo:hi], col["fy"][lo:hi], col["f"][lo:hi]
        pars = np.empty((hi - lo, _engine.NPAR))
        pars[:, _engine.P_BN] = col["b"][lo:hi] / a
        pars[:, _engine.P_LAW] = col["law"][lo:hi]
        pars[:, _engine.P_XG] = np.where(lin, col["xi_c"][lo:hi] / a, 0.0)
        pars[:, _engine.P_YG] = np.where(lin, col["eta_c"][lo:hi] / a, 0.0)
        # R(angle) [[fx, f], [-f, fy]] R(angle)^T
        pars[:, _engine.P_T00] = fx * c * c + fy * s * s
        pars[:, _engine.P_T11] = fx * s * s + fy * c * c
        pars[:, _engine.P_T01] = (fx - fy) * c * s + f
        pars[:, _engine.P_T10] = (fx - fy) * c * s - f
        pars[:, _engine.P_BODY] = col["frame"][lo:hi]
        pars[:, _engine.P_K] = np.sqrt(inertia[lo:hi] / col["mass"][lo:hi]) / a
        pars[:, _engine.P_WTOL] = 1e-12
        pars[:, _engine.P_SHAPE] = _engine.SHAPE_ELLIPSE
        pars[:, _engine.P_CSYM] = 0.0
        pars[:, _engine.P_RSYM] = 0.0
        return pars

    return _integrate_all(col["a"].size, pars_of, col["a"], col["g"], col, rtol, max_steps)


def _no_footprints(n):
    """Footprint arguments of :func:`slidespin.motion._parallel.integrate_many` for n elliptic
    cases."""
    empty = np.empty((0, 4))
    zeros = np.zeros((n, 2), dtype=np.int64)
    return empty, empty, zeros, zeros, np.zeros((n, _engine.NGEO))


def chunk_size(n: int) -> int:
    """Cases per call of the parallel engine for a batch of ``n``: about 1 % of the batch (a
    progress bar then moves in steps of 1 %), at least ``MIN_CHUNK`` and at most
    ``CHUNK`` (the temporary arrays stay small).

    Used only while a progress bar is drawn (otherwise the chunks are ``CHUNK``). The
    floor keeps the chunking from slowing the batch measurably: a call of 4096 cases takes
    seconds (about a millisecond of CPU per case), against a fixed cost per call of the
    parallel engine of about 30 ms (measured on 2 cores, 2026-11) and an idle tail (each
    call ends when its slowest thread does: about 0.4 % of the time at 4096 cases per call,
    0.1 % at 65536, estimated from the spread of step counts of random starts): 1–2 % in
    all at 4096 cases per call, less in larger batches; the price of a bar that moves.
    """
    return max(1, min(CHUNK, max(MIN_CHUNK, math.ceil(n / 100))))


def _integrate_all(
    n, pars_of, a, g, st, rtol, max_steps, footprints_of=None, progress=False, desc="cases"
) -> StopResults:
    """Integrate n cases in chunks of ``chunk_size`` and convert to SI stop results.

    ``pars_of(lo, hi)``: parameter rows of cases lo..hi (natural units); ``a``, ``g``: length
    unit (semi-axis or footprint extent) and gravity (arrays of length n, or scalars); ``st``:
    mapping with the initial ``x, y, phi, vx, vy, omega`` (SI, arrays of length n);
    ``footprints_of(lo, hi)``: the footprint arguments (edges, circles, edge row ranges,
    circle row ranges, geo rows) of :func:`slidespin.motion._parallel.integrate_many` for cases
    lo..hi (None: all ellipses); ``progress``: draw a bar named ``desc``
    (:func:`slidespin._progress.progress_bar`: None means "if stderr is a terminal"). Only
    the results and the initial states are held for all n cases.
    """
    a = np.broadcast_to(np.asarray(a, dtype=float), (n,))
    g = np.broadcast_to(np.asarray(g, dtype=float), (n,))
    initial = np.empty((n, 6))
    for j, name in enumerate(STATE_FIELDS):
        initial[:, j] = st[name]
    res = StopResults(
        t_stop=np.empty(n),
        x_stop=np.empty(n),
        y_stop=np.empty(n),
        phi_stop=np.empty(n),
        path_length=np.empty(n),
        beta_stop=np.empty(n),
        theta_stop=np.empty(n),
        ending_code=np.empty(n, dtype=np.int8),
        status_code=np.empty(n, dtype=np.int8),
        n_steps=np.empty(n, dtype=np.int64),
        saddle_energy=np.empty(n),
        initial_states=initial,
    )
    fails = 0
    show = show_progress(progress)
    step = chunk_size(n) if show else max(1, min(CHUNK, n))
    with progress_bar(n, desc, enabled=show) as bar:
        for lo in range(0, n, step):
            hi = min(n, lo + step)
            fails += _integrate_chunk(
                res, lo, hi, pars_of, a, g, st, rtol, max_steps, footprints_of
            )
            bar.update(hi - lo)
    if fails:  # pragma: no cover - guard
        raise RuntimeError(
            f"{fails} cases had wrench evaluations above their error target; please report"
        )
    return res


def _integrate_chunk(res, lo, hi, pars_of, a, g, st, rtol, max_steps, footprints_of) -> int:
    """Integrate cases lo..hi into ``res``; the number of cases whose wrench evaluations
    missed their error target."""
    pars = pars_of(lo, hi)
    ac = a[lo:hi]
    t_unit = np.sqrt(ac / g[lo:hi])
    v_unit = np.sqrt(ac * g[lo:hi])
    # the same arithmetic as simulate(): natural units here, y0 in compiled code
    init = np.empty((hi - lo, 6))
    init[:, 0] = st["vx"][lo:hi] / v_unit
    init[:, 1] = st["vy"][lo:hi] / v_unit
    init[:, 2] = st["omega"][lo:hi] * t_unit
    init[:, 3] = st["x"][lo:hi] / ac
    init[:, 4] = st["y"][lo:hi] / ac
    init[:, 5] = st["phi"][lo:hi]
    fps = _no_footprints(hi - lo) if footprints_of is None else footprints_of(lo, hi)
    yend, status, steps, _, nf, term = _parallel.integrate_many(
        pars, *fps, init, rtol, rtol, rtol, min(rtol, 1e-8), max_steps
    )
    _stop_values(res, lo, hi, yend, status, steps, term, pars[:, _engine.P_K], ac, t_unit, st)
    return int((nf > 0).sum())


def _stop_values(res, lo, hi, yend, status, steps, term, k, a, t_unit, st):
    """Fill cases lo..hi of ``res`` from the stop states, exactly as simulate() does
    (:func:`slidespin.motion.simulate._terminal_values`, vectorised)."""
    rest = status == _integrator.ST_AT_REST
    u3 = yend[:, 2]
    u12, _ = _parallel.stop_direction(yend)
    converged = np.isin(
        status, (_integrator.ST_STOPPED, _integrator.ST_MARGINAL, _integrator.ST_SADDLE)
    )
    spiral = status == _integrator.ST_SPIRAL
    # classification and β* from u*, then the spiral override
    ending = np.where(np.abs(u3) <= ENDING_TOL, 1, np.where(u12 <= ENDING_TOL, 2, 0))
    beta = term[:, 3].copy()
    beta = np.where(converged & (ending == 1), np.inf, beta)
    beta = np.where(converged & (ending == 2), 0.0, beta)
    # (a spiral's β* is decided in the integrator: inf if the spin dies out, else NaN)
    theta = term[:, 0]
    ending = np.where(spiral, 4, ending)
    # a body at rest stays where it is
    res.ending_code[lo:hi] = np.where(rest, 3, ending)
    res.status_code[lo:hi] = np.where(spiral, _integrator.ST_STOPPED, status)
    res.beta_stop[lo:hi] = np.where(rest, np.nan, beta * a)
    res.theta_stop[lo:hi] = np.where(rest | spiral, np.nan, theta)
    res.t_stop[lo:hi] = np.where(rest, 0.0, yend[:, 4] * t_unit)
    res.x_stop[lo:hi] = np.where(rest, st["x"][lo:hi], yend[:, 5] * a)
    res.y_stop[lo:hi] = np.where(rest, st["y"][lo:hi], yend[:, 6] * a)
    res.phi_stop[lo:hi] = np.where(rest, st["phi"][lo:hi], yend[:, 7])
    res.path_length[lo:hi] = np.where(rest, 0.0, yend[:, 8] * a)
    res.saddle_energy[lo:hi] = np.where(np.isfinite(term[:, 1]), np.exp(2.0 * term[:, 1]), np.nan)
    res.n_steps[lo:hi] = steps


#: bounds of the initial-state columns: those of :class:`~slidespin.State` (None: any finite)
def simulate_many(
    body: Body,
    friction: FrictionTensor,
    initial_states: Any,
    g: float = 9.81,
    rtol: float = 1e-10,
    max_steps: int = 200_000,
    *,
    progress: bool | None = None,
    sensitivities: Iterable[str] | None = None,
) -> StopResults:
    """Integrate one body from N initial states to their stops, in parallel.

    Parameters
    ----------
    body : Body
        Any patch that :func:`slidespin.simulate` takes (ellipses and footprints, the
        ``Blade`` included).
    friction : FrictionTensor
    initial_states : array_like (N, 6), sequence of State, DataFrame or dict of columns
        The initial states in SI units, one per case, as

        * an array of rows (x, y, phi, vx, vy, omega), read by position;
        * a sequence of :class:`~slidespin.State`;
        * a table, a pandas DataFrame or a dict of 1-D columns, read by column *name*
          (:data:`STATE_COLUMNS`): ``omega`` [rad/s] and the velocity, as ``vx`` and
          ``vy`` [m/s] or as ``speed`` [m/s] and ``theta`` [rad] (``State.from_speed``),
          are required; ``x``, ``y`` [m] and ``phi`` [rad] default to 0. The sweep tables'
          names with a 0 (``x0``, ..., ``omega0``, ``v0``, ``theta0``) are accepted too, so
          the inputs of :meth:`StopResults.to_pandas` can be passed back. Any other column
          is refused (a ``ValueError`` listing the valid names): a table is never read by
          position.

        Every value must lie in the range of :class:`~slidespin.State` (|x|, |y| ≤ 1e100 m,
        |vx|, |vy| ≤ 1e8 m/s, |omega| ≤ 1e12 rad/s, phi finite).
    g : float
        Gravitational acceleration [m/s²], in [1e-6, 1e6].
    rtol : float
        Integrator tolerance, as in :func:`slidespin.simulate`, in (0, 1e-3].
    max_steps : int
        Step budget per case, an integer in [1, 1e9].
    progress : bool or None, default None
        Draw a progress bar on stderr (:func:`slidespin._progress.progress_bar`); None: only
        if stderr is a terminal. With a bar the cases run in chunks of about 1 % of the
        batch (``chunk_size``) so that it moves, at a cost of 1–2 % of the run time;
        the chunking changes no number.
    sensitivities : sequence of str, optional
        Parameters (as in :func:`slidespin.stop_sensitivities`) whose stop derivatives each
        case gets, as the columns ``d_<q>/d_<parameter>`` of ``StopResults.sensitivities``
        (and of ``as_dict``, ``to_pandas``). Computed case by case in Python (one
        sensitivity run each, MODEL §15), not in the parallel batch engine (a sensitivity run
        costs 10–15 plain runs for 6 parameters: docs/sensitivities.md).

    Returns
    -------
    StopResults
        Gives the same numbers as :func:`slidespin.simulate` case by case, and keeps the
        initial states (``StopResults.initial_states``).
    """
    if progress is not None and not isinstance(progress, (bool, np.bool_)):
        raise ValueError(
            f"progress = {v._short(progress)} is invalid; valid values: True, False or None "
            "(a bar only if stderr is a terminal)"
        )
    if not isinstance(body, Body):
        raise ValueError(f"body = {body!r} is invalid; valid values: a slidespin.Body")
    if not isinstance(friction, FrictionTensor):
        raise ValueError(f"friction = {friction!r} is invalid; valid values: a FrictionTensor")
    st, rtol, max_steps, g = _check_run(initial_states, None, rtol, max_steps, g)
    # the parameter vector of simulate() itself, so that the numbers agree to the last bit
    require_thin(body, "simulate_many")
    par, fe, fc, geo = body.engine_params(friction)
    states = {name: st[:, i] for i, name in enumerate(("x", "y", "phi", "vx", "vy", "omega"))}

    def footprints_of(lo, hi):
        """One footprint shared by every case: every row range covers all its rows."""
        m = hi - lo
        eidx = np.zeros((m, 2), dtype=np.int64)
        cidx = np.zeros((m, 2), dtype=np.int64)
        eidx[:, 1] = fe.shape[0]
        cidx[:, 1] = fc.shape[0]
        return fe, fc, eidx, cidx, np.repeat(geo[None, :], m, axis=0)

    names = None if sensitivities is None else check_parameters(sensitivities, "sensitivities")
    if names is not None:
        _check_setups([body], names)
    res = _integrate_all(
        st.shape[0],
        lambda lo, hi: np.repeat(par[None, :], hi - lo, axis=0),
        body.length_unit,
        g,
        states,
        rtol,
        max_steps,
        footprints_of if body.is_footprint else None,
        progress=progress,
        desc="simulate_many",
    )
    if names is not None:
        cols = _stop_sensitivity_columns(
            [body] * st.shape[0], [friction] * st.shape[0], st, res.status, names, g, rtol,
            max_steps, progress,
        )  # fmt: skip
        res = replace(res, sensitivities=cols)
    return res


def sensitivity_columns(names) -> tuple[str, ...]:
    """The names of the stop's derivative columns, ``d_<q>/d_<parameter>``, in order."""
    return tuple(f"d_{q}/d_{p}" for p in names for q in STOP_OUTPUTS)


def _check_setups(bodies, names) -> None:
    """Refuse, before any run, a parameter a case's body cannot vary (naming the case)."""
    checked: set = set()
    for i, b in enumerate(bodies):
        if id(b) not in checked:
            checked.add(id(b))
            check_setup(b, names, case=i if len(bodies) > 1 else None)


def _stop_sensitivity_columns(bodies, frictions, st, status, names, g, rtol, max_steps,
                              progress):  # fmt: skip
    """The stop's derivatives of each case (rows of ``st``, its body and tensor) as columns
    d_<q>/d_<parameter>; NaN for a case that does not stop (``status`` of the batch run; at
    rest included), and for one whose sensitivity run fails (counted in a warning)."""
    cols = {c: np.full(st.shape[0], np.nan) for c in sensitivity_columns(names)}
    failed: list[int] = []
    with progress_bar(st.shape[0], "sensitivities", enabled=progress) as bar:
        for i, row in enumerate(st):
            if status[i] == "stopped":
                state = State(*(float(x) for x in row))
                try:
                    sens = simulate(bodies[i], frictions[i], state, g, rtol,
                                    max_steps=max_steps, sensitivities=names).sensitivities  # fmt: skip
                except RuntimeError:
                    failed.append(i)
                    sens = None
                if sens is not None:
                    for p in names:
                        for q in STOP_OUTPUTS:
                            cols[f"d_{q}/d_{p}"][i] = sens.stop[p][q]
            bar.update(1)
    if failed:
        warnings.warn(
            f"{len(failed)} case(s) of {st.shape[0]} (rows {v._short(failed, 80)}): the "
            "sensitivity run did not converge; their derivative columns are NaN",
            RuntimeWarning,
            stacklevel=3,
        )
    return cols


def simulate_bodies(
    bodies,  # sequence of Body (checked below)
    friction: FrictionTensor | Iterable[FrictionTensor],
    initial_states: ArrayLike,
    g: float = 9.81,
    rtol: float = 1e-10,
    max_steps: int = 200_000,
    sensitivities: Iterable[str] | None = None,
) -> StopResults:
    """Integrate N cases, one :class:`~slidespin.Body` per case, in parallel.

    The bodies may rest on any patches, ellipses and footprints mixed (e.g. rings of
    different widths, rectangles of different aspects: a sweep over footprint parameters);
    every footprint's arrays go to the compiled engine stacked, each case reading its own rows.

    Parameters
    ----------
    bodies : sequence of Body, length N
    friction : FrictionTensor or sequence of N FrictionTensor
    initial_states : array_like (N, 6), sequence of N State, DataFrame or dict of columns
        As in :func:`simulate_many`, with N rows.
    g, rtol, max_steps
        As in :func:`simulate_many` (g shared by all cases).
    sensitivities : sequence of str, optional
        As in :func:`simulate_many`: the stop's derivatives of each case as the columns
        ``d_<q>/d_<parameter>`` (case by case, one sensitivity run each).

    Returns
    -------
    StopResults
        The same numbers as :func:`slidespin.simulate` case by case, to the last bit.
    """
    given = bodies
    try:
        bodies = list(bodies) if not isinstance(bodies, Body) else None
    except TypeError:
        bodies = None
    if bodies is None or not bodies or not all(isinstance(b, Body) for b in bodies):
        raise ValueError(
            f"bodies = {v._short(given)} is invalid; valid values: a non-empty sequence of "
            "slidespin.Body (one per case; for one body and many states, simulate_many)"
        )
    n = len(bodies)
    if isinstance(friction, FrictionTensor):
        frictions = [friction] * n
    else:
        try:
            frictions = list(friction)
        except TypeError:
            frictions = []
        if len(frictions) != n or not all(isinstance(f, FrictionTensor) for f in frictions):
            raise ValueError(
                f"friction = {v._short(friction)} is invalid; valid values: a FrictionTensor "
                f"or a sequence of {n} FrictionTensor (one per body)"
            )
    st, rtol, max_steps, g = _check_run(initial_states, n, rtol, max_steps, g)
    # each distinct (body, friction) once; the parameter vectors of simulate() itself
    cache: dict = {}
    engines = []
    for b, f in zip(bodies, frictions):
        key = (id(b), id(f))
        if key not in cache:
            require_thin(b, "simulate_many")
            cache[key] = b.engine_params(f)
        engines.append(cache[key])
    pars = np.array([e[0] for e in engines])
    length = np.array([b.length_unit for b in bodies])
    states = {name: st[:, i] for i, name in enumerate(("x", "y", "phi", "vx", "vy", "omega"))}

    def footprints_of(lo: int, hi: int) -> tuple[np.ndarray, ...]:
        """The footprints of cases lo..hi stacked, with each case's row ranges."""
        es, cs = [], []
        eidx = np.zeros((hi - lo, 2), dtype=np.int64)
        cidx = np.zeros((hi - lo, 2), dtype=np.int64)
        ne = nc = 0
        rows: dict = {}
        for j, (par, fe, fc, geo) in enumerate(engines[lo:hi]):
            key = (id(fe), id(fc))
            if key not in rows:  # a shared body's arrays are stored once
                rows[key] = ((ne, ne + fe.shape[0]), (nc, nc + fc.shape[0]))
                es.append(fe)
                cs.append(fc)
                ne += fe.shape[0]
                nc += fc.shape[0]
            eidx[j], cidx[j] = rows[key]
        edges = np.ascontiguousarray(np.vstack(es).reshape(-1, 4))
        circles = np.ascontiguousarray(np.vstack(cs).reshape(-1, 4))
        geos = np.ascontiguousarray(np.array([e[3] for e in engines[lo:hi]]))
        return edges, circles, eidx, cidx, geos

    names = None if sensitivities is None else check_parameters(sensitivities, "sensitivities")
    if names is not None:
        _check_setups(bodies, names)
    res = _integrate_all(
        n, lambda lo, hi: pars[lo:hi], length, g, states, rtol, max_steps, footprints_of
    )
    if names is not None:
        cols = _stop_sensitivity_columns(
            bodies, frictions, st, res.status, names, g, rtol, max_steps, False
        )
        res = replace(res, sensitivities=cols)
    return res
