"""One progress bar for every long run a user starts (tqdm, on stderr).

A bar is drawn only on a terminal: ``enabled=None`` (the default of every public entry that
takes ``progress=``) means "if stderr is a TTY"; ``True`` forces it, ``False`` (the CLI's
``--quiet``) silences it. Nothing else is printed, so output piped to a file or a CI log stays
clean. Import anywhere: this module imports no layer.
"""

from __future__ import annotations

import sys
from typing import Any

from tqdm.auto import tqdm

__all__ = ["progress_bar", "show_progress"]


def show_progress(enabled: bool | None) -> bool:
    """Whether to draw a bar: ``enabled`` if given, else whether stderr is a terminal."""
    if enabled is None:
        try:
            return bool(sys.stderr.isatty())
        except (AttributeError, ValueError):  # a closed or replaced stderr
            return False
    return bool(enabled)


def progress_bar(total: int, desc: str, unit: str = "case", enabled: bool | None = None) -> Any:
    """A tqdm bar of ``total`` steps named ``desc`` (``update(n)``, ``close()``; a context
    manager), drawn on stderr when :func:`show_progress` says so and a silent no-op otherwise."""
    return tqdm(
        total=int(total),
        desc=desc,
        unit=unit,
        disable=not show_progress(enabled),
        file=sys.stderr,
        dynamic_ncols=True,
        leave=False,
    )
