"""A progress bar for a command whose work reports no steps (``reproduce``, ``fit``).

:func:`busy` wraps the shared bar of :mod:`slidespin._progress` (drawn on stderr only when it
is a terminal, never with ``--quiet``): the bar has one step, the whole task, and shows the
time elapsed, refreshed twice a second by a daemon thread until the task ends. It prints
nothing else, and nothing at all when not drawn (no thread is started then). While the bar is
drawn, what the task prints on stdout is held and printed once the bar is gone, so that the
two never share a line of the terminal.
"""

from __future__ import annotations

import contextlib
import io
import sys
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

__all__ = ["busy"]

#: seconds between two refreshes of the elapsed time
REFRESH_SECONDS = 0.5


@contextmanager
def busy(desc: str, enabled: bool | None = None, total: int = 1) -> Iterator[Any]:
    """A bar named ``desc`` of ``total`` steps (``update(n)`` on the yielded bar), whose
    elapsed time keeps moving while the work runs; completed and closed on exit."""
    # deferred: tqdm is imported only by a command that runs, not by `slidespin --help`
    from slidespin._progress import progress_bar, show_progress

    bar = progress_bar(total, desc, unit="task", enabled=enabled)
    stop = threading.Event()
    thread = None
    held = io.StringIO()
    hold = (
        contextlib.nullcontext() if not show_progress(enabled) else contextlib.redirect_stdout(held)
    )
    if show_progress(enabled):

        def tick() -> None:
            while not stop.wait(REFRESH_SECONDS):
                bar.refresh()

        thread = threading.Thread(target=tick, name=f"slidespin {desc}", daemon=True)
        thread.start()
    try:
        with hold:
            yield bar
        if bar.n < total:
            bar.update(total - bar.n)
    finally:
        stop.set()
        if thread is not None:
            thread.join()
        bar.close()
        if held.getvalue():
            sys.stdout.write(held.getvalue())
