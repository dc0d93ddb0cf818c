"""Figure of a fit of friction to tracked motion (:func:`slidespin.analysis.fit.fit`): the
measured positions and angles against the fitted motion, and the residuals.

The measured points are drawn as open circles (at most :data:`MARKS_PER_RUN` of them per run on
the path and angle panels, where a good fit puts them on the curve) and the fitted motion as a
darker line of the same run's colour through them, so that the two can be told apart even where
they coincide (a run's colour still tells the runs apart); the residual panels show every
point. matplotlib is imported lazily, only by the function that draws; the figure has fixed
margins (no layout engine) and is made through pyplot only if pyplot is already imported
(:mod:`slidespin.viz.trajectory_plot` says more).
"""

from __future__ import annotations

import numpy as np

from slidespin.viz._mpl import _figure, _grid

__all__ = ["plot_fit", "FIT_SAMPLES", "MARKS_PER_RUN"]

#: number of instants at which each run's fitted motion is drawn
FIT_SAMPLES = 400
#: most measured points marked per run on the path and angle panels (evenly taken: every
#: k-th point, k the same for all runs; the legend says which); residuals show every point
MARKS_PER_RUN = 60


def _shade(colour, factor: float):
    """``colour`` mixed with black (``factor`` < 1, darker) as an RGB tuple."""
    from matplotlib.colors import to_rgb  # lazy: matplotlib is imported only to draw

    return tuple(factor * c for c in to_rgb(colour))


def plot_fit(result, labels=None, title=None):
    """Measured (open circles) against fitted (lines) paths and angles, with residuals.

    Panels: the path y(x) of G; the body angle φ(t); the position residuals x (dots) and y
    (crosses) against t [mm]; the angle residuals against t [mrad]. Each run has its own
    colour: its measured points open circles (every k-th point, at most
    :data:`MARKS_PER_RUN` per run), its fitted motion a darker line through them. A panel
    whose quantity was not measured says so.

    Parameters
    ----------
    result : FitResult
        Result of :func:`slidespin.analysis.fit.fit` (its ``data``, ``residuals``,
        ``predict``, ``estimates``, ``std_errors`` and ``reduced_chi2``).
    labels : list of str, optional
        Run names for the legend (default: 0, 1, ...).
    title : str, optional
        First line of the figure title; the estimates and χ²/dof follow.

    Returns
    -------
    matplotlib.figure.Figure
        Its axes, in order: path, angle, position residuals, angle residuals.
    """
    from matplotlib.lines import Line2D  # lazy: matplotlib is imported only to draw

    width, height = 12.0, 8.0
    fig = _figure(width, height)
    # the legend (runs, then the two kinds of mark) sits right of the angle panel, outside
    gs = _grid(fig, 2, 2, left=0.85, right=1.75, bottom=0.55, top=1.0, wgap=0.95, hgap=0.85)
    ax_path, ax_phi = fig.add_subplot(gs[0, 0]), fig.add_subplot(gs[0, 1])
    ax_rp, ax_ra = fig.add_subplot(gs[1, 0]), fig.add_subplot(gs[1, 1])
    labels = labels or [str(k) for k in range(result.n_runs)]
    step = max(1, -(-max(len(d["t"]) for d in result.data) // MARKS_PER_RUN))
    marks = dict(ls="none", marker="o", ms=4.0, mfc="white", mew=0.9, zorder=2)
    for k in range(result.n_runs):
        col = f"C{k % 10}"
        dark = _shade(col, 0.6)
        d, r = result.data[k], result.residuals[k]
        tt = np.linspace(d["t"][0], d["t"][-1], FIT_SAMPLES)
        pred = result.predict(k, tt)
        name = f"run {labels[k]}"
        if "x" in d and "y" in d:
            ax_path.plot(d["x"][::step], d["y"][::step], mec=col, **marks)
            ax_path.plot(pred["x"], pred["y"], "-", lw=1.3, color=dark, zorder=3, label=name)
        if "phi" in d:
            ax_phi.plot(d["t"][::step], d["phi"][::step], mec=col, **marks)
            ax_phi.plot(tt, pred["phi"], "-", lw=1.3, color=dark, zorder=3, label=name)
            ax_ra.plot(d["t"], r["phi"] * 1e3, ".", ms=3, color=col, alpha=0.7, label=name)
        for c, mk in (("x", "."), ("y", "x")):
            if c in d:
                ax_rp.plot(d["t"], r[c] * 1e3, mk, ms=3, color=col, alpha=0.7, label=f"{name}: {c}")
    ax_path.set(xlabel="x [m]", ylabel="y [m]")
    ax_path.set_title("path of G: measured (circles), fitted (lines)", fontsize=10, y=1.0)
    ax_path.set_aspect("equal", adjustable="datalim")
    ax_phi.set(xlabel="t [s]", ylabel="φ [rad]")
    ax_phi.set_title("body angle: measured (circles), fitted (lines)", fontsize=10, y=1.0)
    ax_rp.set(xlabel="t [s]", ylabel="residual [mm]")
    ax_rp.set_title("position residuals, measured − fitted (x dots, y crosses)", fontsize=10, y=1.0)
    ax_ra.set(xlabel="t [s]", ylabel="residual [mrad]")
    ax_ra.set_title("angle residuals, measured − fitted", fontsize=10, y=1.0)
    for ax in (ax_rp, ax_ra):
        ax.axhline(0.0, color="0.5", lw=0.8)
    # the two kinds of mark, in grey, after the runs' own entries
    every = (
        "" if step == 1 else f"\n(every {step}th point)" if step > 3 else f"\n(1 point in {step})"
    )
    kinds = [
        Line2D([], [], mec="0.35", label="measured" + every, **marks),
        Line2D([], [], color="0.25", lw=1.3, label="fitted"),
    ]
    runs = ax_path.get_legend_handles_labels()[0] or ax_phi.get_legend_handles_labels()[0]
    if runs:
        ax_phi.legend(
            handles=runs + kinds,
            fontsize=8,
            loc="upper left",
            bbox_to_anchor=(1.02, 1.0),
            borderaxespad=0.0,
            frameon=False,
        )
    for ax in (ax_path, ax_phi, ax_rp, ax_ra):
        if ax.has_data():
            ax.grid(alpha=0.3)
        else:
            ax.text(
                0.5,
                0.5,
                "not measured",
                ha="center",
                va="center",
                transform=ax.transAxes,
                color="0.5",
            )
    est = ", ".join(
        f"{k} = {val:.4g} ± {result.std_errors[k]:.2g}" for k, val in result.estimates.items()
    )
    fig.suptitle(
        (f"{title}\n" if title else "")
        + (est or "start states only")
        + f"   (χ²/dof = {result.reduced_chi2:.3g})",
        y=1.0 - 0.1 / height,
        va="top",
    )
    return fig
