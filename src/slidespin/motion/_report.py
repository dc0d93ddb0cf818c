"""Notebook summaries of results: the short HTML table behind every ``_repr_html_`` of a
result (:class:`~slidespin.motion.trajectory.Trajectory`,
:class:`~slidespin.motion.loaded_trajectory.LoadedTrajectory`,
:class:`~slidespin.motion.batch.StopResults`); no arrays, only the summary values.
"""

from __future__ import annotations

from html import escape
from typing import Any


def _html_table(title: str, items: dict[str, Any]) -> str:
    """A two-column HTML table of ``items`` (for ``_repr_html_``)."""

    def cell(x):
        return f"{x:.6g}" if isinstance(x, float) else escape(str(x))

    rows = "".join(
        f"<tr><th style='text-align:left'>{escape(str(k))}</th><td>{cell(x)}</td></tr>"
        for k, x in items.items()
    )
    return f"<table><caption>{escape(title)}</caption>{rows}</table>"
