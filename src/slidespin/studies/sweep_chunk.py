"""One chunk of a sweep: its columns (the layout of a chunk file) and its computation.

:func:`compute_chunk` is a pure function of the spec and the chunk number (usable as a Dask
task): the cases of the chunk go to the compiled batch engine
(:func:`~slidespin.motion.batch.simulate_cases` for the ellipse,
:func:`~slidespin.motion.batch.simulate_bodies` for footprints, one batch per value of g) or,
for ``compute = "statics"`` | ``"loaded"``, to :mod:`slidespin.studies.sweep_loads`. The
results are identical whatever the executor, bit for bit.
"""

from __future__ import annotations

import sys

import numpy as np

from slidespin._jit import set_threads
from slidespin.motion.batch import sensitivity_columns, simulate_bodies, simulate_cases
from slidespin.studies._sweep_inputs import _case_fields, _case_inputs, _input_table
from slidespin.studies.sweep_loads import (
    LOAD_COLUMNS,
    LOADED_COLUMNS,
    STATICS_COLUMNS,
    CaseError,
    compute_loaded,
    compute_statics,
)
from slidespin.studies.sweep_parse import load_spec
from slidespin.studies.sweep_spec import SweepError, SweepSpec

__all__ = ["compute_chunk", "compute_chunks", "chunk_columns", "CHUNK_COLUMNS"]


#: the result columns of a stop sweep (``compute = "stop"``), one per case
RESULT_COLUMNS = (
    "t_stop",
    "beta_stop",
    "theta_stop",
    "phi_stop",
    "x_stop",
    "y_stop",
    "path_length",
    "ending",
    "status",
    "saddle_energy",
    "n_steps",
)


#: the columns of every chunk file, in order (inputs, derived inputs, results)
CHUNK_COLUMNS = (
    "case_id",
    "a",
    "b",
    "law",
    "xi_c",
    "eta_c",
    "fx",
    "fy",
    "f",
    "frame",
    "angle",
    "mass",
    "moment_of_inertia",
    "g",
    "x0",
    "y0",
    "phi0",
    "vx0",
    "vy0",
    "omega0",
    "I_star",
    "mu",
    "aspect",
    "v0",
    "theta0",
) + RESULT_COLUMNS
#: the geometry columns of a footprint chunk, per shape (derived keys included)
_SHAPE_COLUMNS = {
    "disk": ("radius",),
    "annulus": ("outer_radius", "inner_radius", "ring_width", "radius_ratio"),
    "rectangle": ("length", "width", "aspect"),
    "polygon": ("scale",),
}
_FOOTPRINT_COMMON = (
    "length_unit",
    "law",
    "xi_c",
    "eta_c",
    "fx",
    "fy",
    "f",
    "frame",
    "angle",
    "mass",
    "moment_of_inertia",
    "g",
    "x0",
    "y0",
    "phi0",
    "vx0",
    "vy0",
    "omega0",
    "I_star",
    "mu",
    "v0",
    "theta0",
)


def chunk_columns(spec: SweepSpec) -> tuple:
    """The columns of every chunk file of ``spec``, in order: inputs, derived inputs, results.

    An ellipse sweep computing stops has :data:`CHUNK_COLUMNS` (the layout of every earlier
    sweep). A footprint sweep has ``shape``, its geometry columns (``annulus``:
    ``outer_radius``, ``inner_radius``, ``ring_width``, ``radius_ratio``; ``rectangle``:
    ``length``, ``width``, ``aspect``; ``disk``: ``radius``; ``polygon``: ``scale``;
    ``pads``: ``n_pads``, ``pad_spacing``, the pad's size and ``pad_shape``) and
    ``length_unit`` (ℓ of I* = I/(m ℓ²)) in the place of ``a``, ``b``, ``aspect``. Statics
    and loaded sweeps add the load and tilt columns and their own results
    (``slidespin.studies.sweep_loads``).
    """
    shape = spec.shape
    if shape == "ellipse":
        inputs = CHUNK_COLUMNS[: -len(RESULT_COLUMNS)]
    else:
        if shape == "pads":
            size = (
                ("pad_length", "pad_width")
                if spec.data["fixed"].get("pad_shape") == "rectangle"
                else ("pad_radius",)
            )
            geo: tuple = ("n_pads", "pad_spacing", *size, "pad_shape")
        else:
            geo = _SHAPE_COLUMNS[shape]
        inputs = ("case_id", "shape", *geo, *_FOOTPRINT_COMMON)
    inputs += _degree_columns(spec)
    if spec.mode == "statics":
        return inputs + LOAD_COLUMNS + STATICS_COLUMNS
    if spec.mode == "loaded":
        return inputs + LOAD_COLUMNS + LOADED_COLUMNS
    return inputs + RESULT_COLUMNS + sensitivity_columns(spec.sensitivities)


def _degree_columns(spec: SweepSpec) -> tuple:
    """``theta0_deg``, ``phi0_deg``: the start angles in degrees, a column when the spec gives
    them (beside ``theta0``, ``phi0`` in radians), so that a sweep is read and plotted by the
    names it was written with. Sweeps without them keep the layout of every earlier sweep."""
    given = set(spec.data.get("fixed", {})) | set(spec.data.get("vary", {}))
    return tuple(k for k in ("theta0_deg", "phi0_deg") if k in given)


def compute_chunk(spec_data: dict | SweepSpec, index: int, on_case=None) -> dict:
    """Compute chunk ``index`` of a sweep (a pure function: usable as a Dask task).

    Returns a dict of equal-length columns (:func:`chunk_columns`): the case inputs and the
    results (the stop, the statics, or the loaded run: the spec's ``compute``). ``on_case``,
    if given, is called with no argument after each statics or loaded case (one Python call
    per case: a progress bar moves with them); the compiled stop sweeps compute a chunk at
    once and do not call it.
    """
    spec = load_spec(spec_data) if not isinstance(spec_data, SweepSpec) else spec_data
    _limit_threads_in_dask_worker()
    start = index * spec.chunk_size
    cols = spec.parameters(start, start + spec.chunk_size)
    rtol = float(spec.data.get("rtol", 1e-10))
    # the engines' own default budget unless the spec gives one (the same number)
    budget = {"max_steps": spec.max_steps} if "max_steps" in spec.data else {}
    if spec.shape == "ellipse" and spec.mode == "stop" and not spec.sensitivities:
        fields = _case_fields(cols)
        out = _input_table(cols, fields)
        out.update({k: np.asarray(cols[k], dtype=float) for k in _degree_columns(spec)})
        _add_results(out, simulate_cases(fields, rtol=rtol, **budget))
        return out
    inp = _case_inputs(spec, cols)
    out = dict(inp.table)
    out.update({k: np.asarray(cols[k], dtype=float) for k in _degree_columns(spec)})
    given = set(spec.data.get("fixed", {})) | set(spec.data.get("vary", {}))
    if spec.mode != "stop":
        args = (inp.bodies, inp.frictions, inp.states, inp.g, inp.loads or {}, given)
        try:
            if spec.mode == "statics":
                out.update(compute_statics(*args, on_case=on_case))
            else:
                out.update(compute_loaded(*args, rtol, max_steps=spec.max_steps, on_case=on_case))
        except CaseError as exc:
            # a per-case failure the checks before the run did not foresee: name the case
            raise SweepError(f"case {int(cols['case_id'][exc.index])}: {exc}") from exc
    else:
        # one batch per value of g (simulate_bodies shares g across its cases)
        parts = []
        for gv in np.unique(inp.g):
            sel = np.flatnonzero(inp.g == gv)
            # (a parameter a body cannot vary was refused when the spec was read)
            res = simulate_bodies(
                [inp.bodies[i] for i in sel],
                [inp.frictions[i] for i in sel],
                inp.states[sel],
                float(gv),
                rtol,
                sensitivities=spec.sensitivities or None,
                **budget,
            ).as_dict()
            parts.append((sel, res))
        for k in RESULT_COLUMNS + sensitivity_columns(spec.sensitivities):
            col = None
            for sel, res in parts:
                val = np.asarray(res[k])
                if col is None:
                    col = np.empty(
                        inp.g.size, dtype=object if val.dtype.kind in "OU" else val.dtype
                    )
                col[sel] = val
            assert col is not None
            out[k] = col.astype(str) if col.dtype == object else col
    return out


def _add_results(out: dict, res) -> None:
    d = res.as_dict()
    for k in RESULT_COLUMNS:
        val = d[k]
        out[k] = val.astype(str) if val.dtype == object else val


def _limit_threads_in_dask_worker() -> None:
    """Inside a Dask worker, use as many compute threads as the worker has task threads,
    so that N workers on N cores do not oversubscribe them."""
    if "distributed" not in sys.modules:
        return
    try:
        # lazy: Dask is an optional extra, loaded only inside a Dask worker
        from distributed import get_worker

        worker = get_worker()
    except (ImportError, ValueError):
        return
    nthreads = getattr(worker.state, "nthreads", None) or getattr(worker, "nthreads", None)
    set_threads(int(nthreads or 1))


def compute_chunks(spec_data: dict, indices) -> list:
    """:func:`compute_chunk` for several chunks in one task (a list of tables)."""
    return [compute_chunk(spec_data, int(i)) for i in indices]
