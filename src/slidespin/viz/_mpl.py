"""matplotlib for the figures of :mod:`slidespin.viz`, imported on first use.

matplotlib is imported only by the functions that draw, so that importing slidespin does not
import it. A figure is made through pyplot only when pyplot is already in use (an interactive
session, a notebook, a script that imports it, the docs gallery: there ``plt.show()`` shows it
and ``plt.close`` closes it); otherwise it is a bare :class:`matplotlib.figure.Figure` on an
Agg canvas, ready for ``savefig``, without importing pyplot at all (about half a second) and
without any global state. The layouts are fixed margins in inches (:func:`_grid`), set once
when the figure is built: no layout engine measures the text again at every draw.
"""

from __future__ import annotations

import sys


def _plt():
    """matplotlib.pyplot, imported now (Agg if the configured backend cannot start)."""
    # lazy: matplotlib is slow to import, and only the functions that draw need it
    import matplotlib

    if matplotlib.get_backend().lower() not in ("agg", "module://matplotlib_inline.backend_inline"):
        try:
            import matplotlib.pyplot as plt  # noqa: F401
        except Exception:  # pragma: no cover - headless fallback
            matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def _figure(width: float, height: float):
    """A new figure of ``width`` × ``height`` inches, with no layout engine.

    Through pyplot if pyplot has been imported (so that ``plt.show()`` shows it), else a
    :class:`~matplotlib.figure.Figure` on an Agg canvas (pyplot is not imported).
    """
    if "matplotlib.pyplot" in sys.modules:
        return _plt().figure(figsize=(width, height))
    # lazy: matplotlib is imported only to draw
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(width, height))
    FigureCanvasAgg(fig)
    return fig


def _cmap(name: str):
    """A registered colormap by name (no pyplot)."""
    import matplotlib

    return matplotlib.colormaps[name]


def _rect(fig, left: float, bottom: float, width: float, height: float) -> list[float]:
    """An axes rectangle given in inches from the lower left corner, as figure fractions."""
    w, h = fig.get_size_inches()
    return [left / w, bottom / h, width / w, height / h]


def _grid(
    fig,
    nrows: int,
    ncols: int,
    *,
    left: float,
    right: float,
    bottom: float,
    top: float,
    wgap: float = 0.0,
    hgap: float = 0.0,
    **kw,
):
    """A GridSpec with its margins and the gaps between cells given in inches.

    ``left``, ``right``, ``bottom``, ``top`` are the margins, ``wgap`` and ``hgap`` the space
    between columns and rows [in]; ``kw`` goes to :meth:`~matplotlib.figure.Figure.add_gridspec`
    (``width_ratios``, ``height_ratios``).
    """
    w, h = fig.get_size_inches()
    inner_w, inner_h = w - left - right, h - top - bottom
    cell_w = (inner_w - wgap * (ncols - 1)) / ncols
    cell_h = (inner_h - hgap * (nrows - 1)) / nrows
    return fig.add_gridspec(
        nrows,
        ncols,
        left=left / w,
        right=1.0 - right / w,
        bottom=bottom / h,
        top=1.0 - top / h,
        wspace=wgap / cell_w if ncols > 1 else None,
        hspace=hgap / cell_h if nrows > 1 else None,
        **kw,
    )
