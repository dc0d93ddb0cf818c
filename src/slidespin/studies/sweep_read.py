"""Reading a sweep back: :func:`read_sweep` (one table, sorted by case), :func:`to_pandas` and
:func:`split_unconverged`.

The cases whose status is unconverged (``max_steps``, ``step_too_small``, ``non_finite``;
:data:`slidespin.motion.outcomes.UNCONVERGED`) are left out unless
``include_unconverged=True``. An unfinished sweep is read as far as it got.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from slidespin.motion.outcomes import LOADED_UNCONVERGED, UNCONVERGED
from slidespin.studies.sweep_spec import SweepError
from slidespin.studies.sweep_store import MANIFEST, _read_chunk, _read_manifest, _require_pyarrow

__all__ = ["read_sweep", "to_pandas", "split_unconverged"]


def read_sweep(out, *, include_unconverged: bool = False) -> dict:
    """The results of a sweep directory as one table: column name → array, sorted by case.

    Parameters
    ----------
    out : str or Path
        Sweep directory.
    include_unconverged : bool, default False
        Keep the cases whose status is in :data:`slidespin.motion.outcomes.UNCONVERGED`
        (``max_steps``, ``step_too_small``, ``non_finite``: values as reached, not a stop).
        By default they are left out; :func:`split_unconverged` counts them.

    Raises
    ------
    ValueError
        If ``out`` is not a sweep directory or a chunk file is unreadable (the message names
        it). An unfinished sweep is read as far as it got.
    """
    _require_pyarrow()
    # lazy: pyarrow is heavy, needed only to write or read chunk files
    import pyarrow as pa

    out = Path(out)
    if not out.is_dir() or _read_manifest(out) is None:
        raise SweepError(f"{str(out)!r} is not a sweep directory (no {MANIFEST})")
    files = sorted((out / "chunks").glob("chunk-*.parquet"))
    if not files:
        return {}
    try:
        table = pa.concat_tables([_read_chunk(f) for f in files])
    except pa.ArrowInvalid as exc:
        raise SweepError(
            f"the chunk files of {str(out)!r} do not fit together ({exc}); rerun "
            "slidespin sweep SPEC --out DIR --resume to check them"
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
    table = read_sweep(out, include_unconverged=True)
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
