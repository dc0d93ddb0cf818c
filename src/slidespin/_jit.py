"""The one place that imports numba, and only when something needs it.

A function decorated with :func:`jit` is a deferred function until numba is needed: its first
call (or :func:`numba_module`) imports numba (0.3–0.7 s) and makes every deferred function,
``overload`` and ``prange`` numba's at once, rebinding the module globals that hold them, so
compiled callers see dispatchers only. A run served by the ahead-of-time compiled core
(:mod:`slidespin._aot`: the demo, a first loaded run) never imports numba.

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
import threading
import warnings
from types import ModuleType

__all__ = [
    "jit",
    "prange",
    "numba_module",
    "set_threads",
    "CacheWarning",
    "overload",
    "is_none_type",
    "compile_note",
]

# ---------------------------------------------------------------- numba, imported when needed
_state: dict = {"numba": None}
_lock = threading.RLock()
_pending: list = []  # the deferred functions, made numba's at the first need
_overloads: list = []  # (function, options, implementation) of deferred ``overload``s


class _Deferred:
    """A function decorated with :func:`jit` before numba was imported.

    Calling it (or reading a dispatcher attribute) imports numba and turns every deferred
    function into its numba dispatcher at once (:func:`numba_module`), so that compiled
    callers see dispatchers for all their callees; module globals bound to it are rebound
    to the dispatcher then. ``py_func`` is the Python function, as on a dispatcher."""

    def __init__(self, fn, options):
        self.py_func = fn
        self.options = options
        self.dispatcher = None
        for name in ("__name__", "__qualname__", "__module__", "__doc__"):
            setattr(self, name, getattr(fn, name, None))
        self.__wrapped__ = fn

    def __call__(self, *args, **kwargs):
        if self.dispatcher is None:
            numba_module()
        if any(isinstance(a, _Deferred) for a in args):  # held before the swap
            args = tuple(a.dispatcher if isinstance(a, _Deferred) else a for a in args)
        return self.dispatcher(*args, **kwargs)

    def __getattr__(self, name):  # a dispatcher's attribute (signatures, compile, ...)
        if name.startswith("__") or name == "dispatcher":
            raise AttributeError(name)
        numba_module()
        return getattr(self.dispatcher, name)

    def __repr__(self):
        return f"<slidespin jit function {self.__qualname__} (numba not imported yet)>"


class _PRange:
    """``numba.prange`` before numba is imported (``range`` when called from Python)."""

    def __call__(self, *args):
        return range(*args)


_PRANGE = _PRange()
prange = _PRANGE


def numba_module() -> ModuleType:
    """The numba module, imported now if not yet: every deferred :func:`jit` function and
    ``overload`` is then made numba's, and every module global bound to one of them (or to
    the ``prange`` placeholder) is rebound, before any of them compiles.

    Importing numba costs about 0.3–0.7 s; a run served by the ahead-of-time compiled core
    (:mod:`slidespin._aot`) never needs it. This defers an import for its cost, not to dodge
    an import cycle."""
    nb = _state["numba"]
    if nb is not None:
        return nb
    with _lock:
        if _state["numba"] is not None:
            return _state["numba"]
        import numba as module
        from numba.core import event
        from numba.extending import overload as nb_overload

        placeholder = _PRANGE  # (the module's ``prange`` is rebound in the loop below)
        for d in _pending:
            d.dispatcher = _build(module, d.py_func, d.options)
        for func, options, impl in _overloads:
            nb_overload(func, **options)(impl)
        for mod in list(sys.modules.values()):
            g = getattr(mod, "__dict__", None)
            if not isinstance(g, dict):
                continue
            for key, val in list(g.items()):
                if isinstance(val, _Deferred):
                    g[key] = val.dispatcher
                elif val is placeholder and key != "_PRANGE":
                    g[key] = module.prange
        event.register("numba:compile", _CompileListener())
        _pending.clear()
        _overloads.clear()
        _state["numba"] = module
        return module


def __getattr__(name: str):
    if name == "numba":  # ``from slidespin._jit import numba``: the module itself
        return numba_module()
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def overload(func, **options):
    """``numba.extending.overload(func, **options)``, registered when numba is imported."""

    def decorate(impl):
        if _state["numba"] is not None:
            from numba.extending import overload as nb_overload

            return nb_overload(func, **options)(impl)
        with _lock:
            if _state["numba"] is None:
                _overloads.append((func, options, impl))
                return impl
        return decorate(impl)

    return decorate


class CacheWarning(UserWarning):
    """numba's on-disk cache is not writable; slidespin fell back to a temporary or no cache."""


_fallback: dict = {"dir": None, "noted": False}


def set_threads(n: int) -> None:
    """Limit the threads of compiled parallel loops (e.g. one per Dask worker thread)."""
    nb = numba_module()
    most = nb.config.NUMBA_NUM_THREADS
    nb.set_num_threads(max(1, min(int(n), most)))


def is_none_type(numba_type) -> bool:
    """True if ``numba_type`` (an argument type seen by an ``overload`` typing function) is
    ``None``'s: the typing function then returns the implementation for a missing argument.

    ``overload`` (``numba.extending.overload``) is how one compiled source specialises on
    the type of an argument: called from compiled code, the plain-Python stub it decorates is
    replaced by the implementation its typing function returns for the argument types, and
    only that one is compiled (and cached with its caller).
    """
    return isinstance(numba_type, numba_module().types.NoneType)


def _no_locator(err: Exception) -> bool:
    return "no locator available" in str(err)


def _note(text: str) -> None:
    if not _fallback["noted"]:
        _fallback["noted"] = True
        # warn_explicit without a source line: one line on stderr, still filterable
        warnings.warn_explicit(
            text, CacheWarning, filename="slidespin", lineno=0, module="slidespin._jit"
        )


def _build(nb, fn, options):
    """``numba.njit(**options)(fn)``, with ``cache=True`` falling back as the module says."""
    if not options.get("cache", True):
        return nb.njit(**options)(fn)
    try:
        return nb.njit(**options)(fn)
    except RuntimeError as err:
        if not _no_locator(err):
            raise
    # no writable cache directory: a private temporary one for this process
    config = nb.core.config
    if _fallback["dir"] is None:
        try:
            _fallback["dir"] = tempfile.mkdtemp(prefix="slidespin-numba-")
        except OSError:
            _fallback["dir"] = ""
    if _fallback["dir"]:
        saved = config.CACHE_DIR
        config.CACHE_DIR = _fallback["dir"]
        try:
            out = nb.njit(**options)(fn)
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
            config.CACHE_DIR = saved
    _note("numba has no writable cache directory; compiling without a disk cache")
    return nb.njit(**{**options, "cache": False})(fn)


def jit(fn=None, **options):
    """``numba.njit`` with ``cache=True``; use bare (``@jit``) or with options.

    Until numba is needed the result is a deferred function (numba is imported at its first
    call, :func:`numba_module`); after, numba's dispatcher. If numba finds no writable cache
    directory, a private temporary one is used (or none); see the module's docstring.
    """
    options.setdefault("cache", True)

    def make(f):
        with _lock:
            nb = _state["numba"]
            if nb is None:
                d = _Deferred(f, options)
                _pending.append(d)
                return d
        return _build(nb, f, options)

    return make if fn is None else make(fn)


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


def _CompileListener():
    """A numba event listener that prints :func:`compile_note` at the first compile of a
    slidespin function (numba raises the ``numba:compile`` event only when nothing is
    cached)."""
    from numba.core import event as nb_event

    class Listener(nb_event.Listener):
        def on_start(self, event):
            _on_compile(event)

        def on_end(self, event):
            pass

    return Listener()


def _on_compile(event):
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
