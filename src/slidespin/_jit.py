"""The one place that imports numba.

Compiled functions in slidespin take plain floats and arrays only. ``jit`` is ``numba.njit``
with on-disk caching (``cache=True``) and without fast-math (the wrench is computed to 1e-10
and must not be reassociated). Setting ``NUMBA_DISABLE_JIT=1`` runs everything as Python.

Import anywhere. numba caches compiled code next to the source (``__pycache__``) or in the
user's cache directory (``NUMBA_CACHE_DIR``, else ``~/.cache/numba``), and refuses to build a
cached function at all ("no locator available") when none of them is writable: a read-only
install used by an account without a writable home. slidespin then caches in a private
temporary directory made for this process (``tempfile.mkdtemp``: never shared, since numba's
cache files are pickles), or compiles without a cache if even that fails, and says so once
on stderr (a :class:`CacheWarning`). Nothing else changes: the code compiled is the same.

Compiling is slow (tens of seconds for the integrator), so the first compile of a slidespin
function in a process says so once on stderr, with a rough cost (:func:`compile_note`); a
function loaded from numba's cache, or from the ahead-of-time compiled core
(:mod:`slidespin._aot`), compiles nothing and prints nothing.
"""

from __future__ import annotations

import sys
import tempfile
import warnings

import numba
from numba import prange
from numba.core import config as _config
from numba.core import event as _event
from numba.extending import overload

__all__ = [
    "jit",
    "prange",
    "numba",
    "set_threads",
    "CacheWarning",
    "overload",
    "is_none_type",
    "compile_note",
]


class CacheWarning(UserWarning):
    """numba's on-disk cache is not writable; slidespin fell back to a temporary or no cache."""


_fallback: dict = {"dir": None, "noted": False}


def set_threads(n: int) -> None:
    """Limit the threads of compiled parallel loops (e.g. one per Dask worker thread)."""
    most = _config.NUMBA_NUM_THREADS  # type: ignore[attr-defined]
    numba.set_num_threads(max(1, min(int(n), most)))


def is_none_type(numba_type) -> bool:
    """True if ``numba_type`` (an argument type seen by an ``overload`` typing function) is
    ``None``'s: the typing function then returns the implementation for a missing argument.

    ``overload`` (``numba.extending.overload``) is how one compiled source specialises on
    the type of an argument: called from compiled code, the plain-Python stub it decorates is
    replaced by the implementation its typing function returns for the argument types, and
    only that one is compiled (and cached with its caller).
    """
    return isinstance(numba_type, numba.types.NoneType)


def _no_locator(err: Exception) -> bool:
    return "no locator available" in str(err)


def _note(text: str) -> None:
    if not _fallback["noted"]:
        _fallback["noted"] = True
        # warn_explicit without a source line: one line on stderr, still filterable
        warnings.warn_explicit(
            text, CacheWarning, filename="slidespin", lineno=0, module="slidespin._jit"
        )


def _njit_cached(fn, options):
    """``numba.njit(**options)(fn)`` with ``cache=True``, falling back as the module says."""
    try:
        return numba.njit(**options)(fn)
    except RuntimeError as err:
        if not _no_locator(err):
            raise
    # no writable cache directory: a private temporary one for this process
    if _fallback["dir"] is None:
        try:
            _fallback["dir"] = tempfile.mkdtemp(prefix="slidespin-numba-")
        except OSError:
            _fallback["dir"] = ""
    if _fallback["dir"]:
        saved = _config.CACHE_DIR
        _config.CACHE_DIR = _fallback["dir"]
        try:
            out = numba.njit(**options)(fn)
        except RuntimeError as err:
            if not _no_locator(err):
                raise
        else:
            _note(
                "numba cannot write its cache next to the package or in the home "
                f"directory; compiled code is cached in {_fallback['dir']} for this process only"
            )
            return out
        finally:
            _config.CACHE_DIR = saved
    _note("numba has no writable cache directory; compiling without a disk cache")
    return numba.njit(**{**options, "cache": False})(fn)


def jit(fn=None, **options):
    """``numba.njit`` with ``cache=True``; use bare (``@jit``) or with options.

    If numba finds no writable cache directory, a private temporary one is used (or none);
    see the module's docstring.
    """
    options.setdefault("cache", True)
    if not options["cache"]:
        return numba.njit(**options) if fn is None else numba.njit(**options)(fn)
    if fn is None:
        return lambda f: _njit_cached(f, options)
    return _njit_cached(fn, options)


# ---------------------------------------------------------------- the one note on compiling
#: rough CPU seconds of a first compile, by the compiled entry called from Python (measured
#: from an empty cache on 2 shared cores; the rest: up to about a minute)
COMPILE_SECONDS = {"integrate_fp": 30, "integrate_many": 40, "accelerations": 10, "run_loaded": 60}
_compiling: dict = {"noted": False, "enabled": True}


def compile_note(name: str) -> str:
    """The line printed once on stderr when slidespin first compiles ``name`` in a process."""
    seconds = COMPILE_SECONDS.get(name)
    cost = f"about {seconds} s" if seconds else "up to about a minute"
    return (
        f"slidespin: compiling the numerical kernels once ({name}: {cost}); "
        "later runs load them from numba's on-disk cache"
    )


class _CompileListener(_event.Listener):
    """Prints :func:`compile_note` at the first compile of a slidespin function (numba
    raises the ``numba:compile`` event only when nothing is cached)."""

    def on_start(self, event):
        if _compiling["noted"] or not _compiling["enabled"]:
            return
        func = getattr(event.data.get("dispatcher"), "py_func", None)
        if not getattr(func, "__module__", "").startswith("slidespin."):
            return
        _compiling["noted"] = True
        try:
            sys.stderr.write(compile_note(func.__name__) + "\n")
            sys.stderr.flush()
        except (AttributeError, OSError, ValueError):  # no usable stderr
            pass

    def on_end(self, event):
        pass


_event.register("numba:compile", _CompileListener())
