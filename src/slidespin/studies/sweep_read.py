"""Reading a sweep back: :func:`read_sweep` (one table, sorted by case; or, for a grid, an
``xarray.Dataset`` on the grid, :func:`to_xarray`), :func:`to_pandas` and
:func:`split_unconverged`.

The cases whose status is unconverged (``max_steps``, ``step_too_small``, ``non_finite``;
:data:`slidespin.motion.outcomes.UNCONVERGED`) are left out unless
``include_unconverged=True`` (on a grid, their results are NaN). An unfinished sweep is read
as far as it got (as a table; a grid needs every case).
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from slidespin.motion.outcomes import LOADED_UNCONVERGED, UNCONVERGED
from slidespin.studies.sweep_spec import SweepError
from slidespin.studies.sweep_store import MANIFEST, _read_chunk, _read_manifest, _require_pyarrow

__all__ = ["read_sweep", "to_pandas", "to_xarray", "split_unconverged"]


def read_sweep(out, *, include_unconverged: bool = False, as_xarray: bool = False):
    """The results of a sweep directory as one table: column name → array, sorted by case.

    With ``as_xarray=True``, a grid sweep is returned as an ``xarray.Dataset`` on its grid
    instead (:func:`to_xarray`; needs the optional extra ``slidespin[xarray]``).

    Parameters
    ----------
    out : str or Path
        Sweep directory.
    include_unconverged : bool, default False
        Keep the cases whose status is in :data:`slidespin.motion.outcomes.UNCONVERGED`
        (``max_steps``, ``step_too_small``, ``non_finite``: values as reached, not a stop).
        By default they are left out; :func:`split_unconverged` counts them.
    as_xarray : bool, default False
        Return an ``xarray.Dataset`` on the grid (:func:`to_xarray`).

    Raises
    ------
    ValueError
        If ``out`` is not a sweep directory or a chunk file is unreadable (the message names
        it). An unfinished sweep is read as far as it got.
    ImportError
        With ``as_xarray=True`` if xarray is not installed (the message says how to install it).
    """
    if not isinstance(as_xarray, bool):
        raise SweepError(f"as_xarray = {as_xarray!r:.60} is invalid; valid values: True, False")
    if not isinstance(include_unconverged, bool):
        raise SweepError(
            f"include_unconverged = {include_unconverged!r:.60} is invalid; valid values: "
            "True, False"
        )
    if as_xarray:
        return to_xarray(out, include_unconverged=include_unconverged)
    return _read_table(out, include_unconverged)


def _read_table(out, include_unconverged: bool) -> dict:
    _require_pyarrow()
    # lazy: pyarrow is heavy, needed only to write or read chunk files
    import pyarrow as pa

    if not isinstance(out, (str, Path)) and not hasattr(out, "__fspath__"):
        raise SweepError(
            f"out = {out!r:.60} is invalid; valid values: a sweep directory path (str or "
            "os.PathLike)"
        )
    out = Path(out)
    if not out.is_dir() or _read_manifest(out) is None:
        raise SweepError(
            f"{str(out)!r} is not a sweep directory (no {MANIFEST}); valid: a directory "
            "written by slidespin sweep"
        )
    files = sorted((out / "chunks").glob("chunk-*.parquet"))
    if not files:
        return {}
    try:
        table = pa.concat_tables([_read_chunk(f) for f in files])
    except pa.ArrowInvalid as exc:
        raise SweepError(
            f"the chunk files of {str(out)!r} do not fit together ({exc}); rerun "
            "slidespin sweep SPEC --out DIR --resume to check them (valid: the chunk files of "
            "one sweep)"
        ) from None
    cols = {name: table.column(name).to_numpy(zero_copy_only=False) for name in table.column_names}
    order = np.argsort(cols["case_id"], kind="stable")
    cols = {k: val[order] for k, val in cols.items()}
    return cols if include_unconverged else split_unconverged(cols)[0]


def to_pandas(out, *, include_unconverged: bool = False):
    """A sweep directory's results as a :class:`pandas.DataFrame`, one row per case.

    The table of :func:`read_sweep` (same columns, sorted by ``case_id``, unconverged cases
    left out unless ``include_unconverged``), read from the Parquet chunks; the spec, its
    name and the cases left out per status are in ``DataFrame.attrs``. Needs pandas
    (``pip install pandas``; it is in the ``test`` extra).

    Raises
    ------
    ImportError
        If pandas is not installed (the message says how to install it).
    SweepError
        If ``out`` is not a sweep directory or a chunk is unreadable.
    """
    try:
        # lazy: pandas is optional (the test extra), needed only by to_pandas
        import pandas as pd  # type: ignore[import-untyped]  # pandas ships no type information
    except ImportError:  # pragma: no cover - depends on the environment
        raise ImportError(
            "a sweep as a pandas DataFrame (to_pandas) needs pandas: pip install pandas "
            "(or pip install 'slidespin[test]')"
        ) from None
    table = _read_table(out, True)
    kept, left = (table, {}) if include_unconverged else split_unconverged(table)
    df = pd.DataFrame({k: np.asarray(val) for k, val in kept.items()})
    man = _read_manifest(Path(out)) or {}
    spec = man.get("spec", {}) if isinstance(man.get("spec"), dict) else {}
    df.attrs.update(name=spec.get("name", ""), spec=spec, left_out=left)
    return df


def split_unconverged(table: dict):
    """``(kept, left_out)``: the table without the unconverged cases, and the number left out
    per status (``{}`` if none). A table without a ``status`` column is kept whole."""
    if not table or "status" not in table:
        return table, {}
    status = np.asarray(table["status"]).astype(str)
    bad = np.isin(status, sorted(UNCONVERGED | LOADED_UNCONVERGED))
    if not bad.any():
        return table, {}
    left = {k: int(c) for k, c in zip(*np.unique(status[bad], return_counts=True))}
    return {k: np.asarray(val)[~bad] for k, val in table.items()}, left


def to_xarray(out, *, include_unconverged: bool = False):
    """A grid sweep's results as an ``xarray.Dataset`` on its grid.

    The swept parameters (the spec's ``[vary]`` keys, in its order) are the dimensions, with
    the grid's values as coordinates (strings for ``law``, ``frame``, ...); every column of the
    chunk files (:func:`~slidespin.studies.sweep_chunk.chunk_columns`: the inputs, derived
    inputs and results, ``case_id`` included) is a data variable on those dimensions (a
    column named like a swept parameter is that coordinate, with the spec's exact values), so
    that
    ``ds.beta_stop.sel(mu=0.1)`` is the terminal ratio over the other axes. The cases whose
    status is unconverged keep their status and inputs, but their floating-point results are
    NaN unless ``include_unconverged=True`` (a grid keeps every cell); how many per status is
    in ``attrs["left_out"]`` (JSON), the spec in ``attrs["spec"]`` (JSON), its name in
    ``attrs["name"]``.

    Needs xarray, an optional dependency: ``pip install slidespin[xarray]``.

    Raises
    ------
    ImportError
        If xarray is not installed (the message says how to install it).
    SweepError
        If ``out`` is not a sweep directory, is not a grid (``kind = "random"`` has no grid:
        read it as a table), or is unfinished (a grid needs every case: finish it with
        ``--resume``).
    """
    try:
        # lazy: xarray is an optional extra (slidespin[xarray]), needed only here
        import xarray as xr
    except ImportError:
        raise ImportError(
            "a sweep as an xarray.Dataset (read_sweep(..., as_xarray=True), to_xarray) needs "
            "xarray: pip install slidespin[xarray] (or pip install xarray)"
        ) from None
    # lazy: the spec module imports the numerical stack this module does not need otherwise
    from slidespin.studies.sweep_chunk import RESULT_COLUMNS
    from slidespin.studies.sweep_loads import LOADED_COLUMNS, STATICS_COLUMNS
    from slidespin.studies.sweep_parse import load_spec
    from slidespin.studies.sweep_spec import _grid_values

    table = _read_table(out, True)
    man = _read_manifest(Path(out)) or {}
    if not isinstance(man.get("spec"), dict):
        raise SweepError(
            f"{str(out)!r}: its {MANIFEST} records no spec; valid: a directory written by "
            "slidespin sweep"
        )
    spec = load_spec(man["spec"])
    if spec.data.get("kind", "grid") != "grid":
        raise SweepError(
            f"{str(out)!r} holds a random sweep (kind = 'random'), which has no grid; valid "
            "for as_xarray: a grid sweep (read a random one as a table, read_sweep() or "
            "to_pandas())"
        )
    n = len(table.get("case_id", ()))
    if n != spec.n_cases:
        raise SweepError(
            f"{str(out)!r} is unfinished ({n} of {spec.n_cases} cases); valid for as_xarray: "
            "a finished grid (slidespin sweep SPEC --out DIR --resume finishes it)"
        )
    vary = spec.data.get("vary", {})
    dims = tuple(vary)
    coords = {k: np.asarray(_grid_values(k, vary[k])) for k in dims}
    shape = tuple(len(c) for c in coords.values())
    kept, left = (table, {}) if include_unconverged else split_unconverged(table)
    results = set(RESULT_COLUMNS) | set(STATICS_COLUMNS) | set(LOADED_COLUMNS)
    bad = ~np.isin(np.asarray(table["case_id"]), np.asarray(kept["case_id"]))
    data_vars = {}
    for name, col in table.items():
        if name in coords:  # the swept parameter itself: its coordinate, the spec's values
            continue
        arr = np.asarray(col)
        if arr.dtype == object:
            arr = arr.astype(str)
        if name in results and arr.dtype.kind == "f" and bad.any():
            arr = np.where(bad, np.nan, arr)
        data_vars[name] = (dims, arr.reshape(shape))
    return xr.Dataset(
        data_vars,
        coords=coords,
        attrs={
            "name": spec.name,
            "spec": json.dumps(spec.data, sort_keys=True),
            "left_out": json.dumps(left),
        },
    )
