"""The one place that imports numba.

Compiled functions in slidespin take plain floats and arrays only. ``jit`` is ``numba.njit``
with on-disk caching (``cache=True``) and without fast-math (the wrench is computed to 1e-10
and must not be reassociated). Setting ``NUMBA_DISABLE_JIT=1`` runs everything as Python.
"""

from __future__ import annotations

import numba
from numba import prange

__all__ = ["jit", "prange", "numba", "set_threads"]


def set_threads(n: int) -> None:
    """Limit the threads of compiled parallel loops (e.g. one per Dask worker thread)."""
    numba.set_num_threads(max(1, min(int(n), numba.config.NUMBA_NUM_THREADS)))


def jit(fn=None, **options):
    """``numba.njit`` with ``cache=True``; use bare (``@jit``) or with options."""
    options.setdefault("cache", True)
    if fn is None:
        return numba.njit(**options)
    return numba.njit(**options)(fn)
