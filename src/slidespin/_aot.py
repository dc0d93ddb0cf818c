"""The ahead-of-time compiled core, when the install built one from these very sources.

The package's build (``hatch_build.py``) compiles the integrator's entries, the small-batch
loop and the wrench-array loops once with numba's ``pycc`` (:mod:`slidespin._aot_build`)
into the extension module ``slidespin._aot_core``, so that a first ``friction_wrench``,
``simulate`` or small ``simulate_many`` of an ellipse or a footprint compiles nothing. The module is the same numba source compiled ahead
of time: its results are those of the JIT bit for bit (tested). It is used only if

- it exists and imports (a build without a C compiler, or with ``SLIDESPIN_AOT=0`` at build
  time, has none),
- ``SLIDESPIN_AOT`` is not ``0`` and ``NUMBA_DISABLE_JIT`` is not set (the plain-Python mode
  of the tests), and
- every source file it was compiled from is unchanged (SHA-256 against its manifest
  ``_aot_core.json``): after an edit of the sources (an editable install) the JIT compiles
  the edited code instead, and a :class:`CoreWarning` says so once (rebuild with
  ``pip install -e .``).

Otherwise the JIT runs, as before. A private root helper: this module imports neither numba
nor any layer, so that every layer may ask it (the kernels' array loops in ``contact``, the
integrator and the batch in ``motion``).
"""

from __future__ import annotations

import hashlib
import importlib
import json
import os
import warnings
from pathlib import Path
from types import ModuleType

__all__ = ["CoreWarning", "core", "status"]

#: the extension module and its manifest (names set by slidespin._aot_build)
MODULE = "slidespin._aot_core"
MANIFEST = "_aot_core.json"
_PACKAGE_DIR = Path(__file__).resolve().parent


class CoreWarning(UserWarning):
    """The ahead-of-time compiled core is out of date with the sources; the JIT is used."""


_state: dict = {"checked": False, "module": None, "why": ""}


def _off(name: str) -> bool:
    return os.environ.get(name, "").strip() not in ("", "0")


def _load() -> tuple[ModuleType | None, str]:
    if os.environ.get("SLIDESPIN_AOT", "1").strip() == "0":
        return None, "switched off (SLIDESPIN_AOT=0)"
    if _off("NUMBA_DISABLE_JIT"):
        return None, "not used while NUMBA_DISABLE_JIT is set"
    try:
        module = importlib.import_module(MODULE)
    except ImportError:
        return None, "not built by this install (the JIT compiles on first use)"
    try:
        manifest = json.loads(Path(module.__file__ or "").with_name(MANIFEST).read_text())
        sources = dict(manifest["sources"])
    except (OSError, ValueError, KeyError, TypeError):
        return None, f"its manifest {MANIFEST} is missing or unreadable"
    for rel, digest in sources.items():
        try:
            now = hashlib.sha256((_PACKAGE_DIR / rel).read_bytes()).hexdigest()
        except OSError:
            now = ""
        if now != digest:
            why = (
                f"built from other sources (slidespin/{rel} has changed since); the JIT "
                "compiles the current code instead (rebuild: pip install -e .)"
            )
            warnings.warn_explicit(
                f"slidespin's ahead-of-time compiled core is {why}",
                CoreWarning,
                filename="slidespin",
                lineno=0,
                module="slidespin._aot",
            )
            return None, why
    return module, f"in use ({manifest.get('target_cpu', '?')} CPU, numba {manifest.get('numba')})"


def core() -> ModuleType | None:
    """The compiled core module if it may be used (see the module docstring), else None."""
    if not _state["checked"]:
        _state["module"], _state["why"] = _load()
        _state["checked"] = True
    return _state["module"]


def status() -> str:
    """One line saying whether the ahead-of-time compiled core is used, and if not why."""
    core()
    return "ahead-of-time compiled core: " + _state["why"]
