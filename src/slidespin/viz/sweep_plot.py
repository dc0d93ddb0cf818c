"""Figures of a parameter sweep: a result column as a heat map over two swept parameters, or
against one (:func:`plot_sweep`), with unconverged and flagged cases marked, and readable axis
labels with units for the sweep's columns (:func:`axis_label`).

Every figure has a title that says what is shown over what (the value, how cells are
summarised, the axes, the number of cases). matplotlib is imported lazily, only by the function
that draws; the layout is fixed margins in inches sized from the text it holds (tick labels,
title lines, notes), computed once when the figure is built; nothing here computes physics.
"""

from __future__ import annotations

import re
import textwrap
from typing import TYPE_CHECKING

import numpy as np

from slidespin.motion.outcomes import FLAGGED, LOADED_UNCONVERGED, UNCONVERGED
from slidespin.viz._mpl import _cmap, _figure, _rect

if TYPE_CHECKING:
    from matplotlib.artist import Artist

__all__ = ["plot_sweep", "axis_label"]


_LABELS = {
    "a": "$a$ [m]",
    "b": "$b$ [m]",
    "fx": "$f_x$",
    "fy": "$f_y$",
    "f": "$f$ (skew)",
    "mu": r"$\mu = f_y - f_x$",
    "I_star": r"$I^* = I/(m a^2)$",
    "moment_of_inertia": "$I$ [kg m²]",
    "mass": "$m$ [kg]",
    "angle": "tensor angle [rad]",
    "v0": "$v_0$ [m/s]",
    "omega0": r"$\omega_0$ [rad/s]",
    "theta0": r"$\vartheta_0$ [rad]",
    "phi0": r"$\varphi_0$ [rad]",
    "x0": "$x_0$ [m]",
    "y0": "$y_0$ [m]",
    "vx0": "$v_{x0}$ [m/s]",
    "vy0": "$v_{y0}$ [m/s]",
    "xi_c": r"$\xi_c$ [m]",
    "eta_c": r"$\eta_c$ [m]",
    "t_stop": "stop time [s]",
    "beta_stop": r"$\beta^*$ [m]",
    "theta_stop": r"$\vartheta^*$ [rad]",
    "phi_stop": r"$\varphi$ at the stop [rad]",
    "x_stop": "$x$ at the stop [m]",
    "y_stop": "$y$ at the stop [m]",
    "aspect": "$b/a$",
    "e": "eccentricity",
    "path_length": "distance travelled [m]",
    "n_steps": "integrator steps",
    "g": "$g$ [m/s²]",
    "case_id": "case number",
    "law": "pressure law",
    "frame": "tensor frame",
    "ending": "ending",
    "status": "status",
}
#: categorical result columns, drawn with one colour per name
_CATEGORIES = {
    "ending": ("mixed", "pure_sliding", "pure_spinning", "spiral", "at_rest"),
    "status": (
        "stopped",
        "at_rest",
        "marginal",
        "saddle",
        "max_steps",
        "step_too_small",
        "non_finite",
    ),
}


def axis_label(name: str) -> str:
    """Readable axis label with units for a sweep column (no raw underscores)."""
    return _LABELS.get(name, name.replace("_", " "))


def _short(name: str) -> str:
    """The symbol of a column for a title: its axis label without the unit or the definition
    (``$\\mu = f_y - f_x$`` → ``$\\mu$``, ``stop time [s]`` → ``stop time``)."""
    label = re.sub(r"\s*\[[^\]]*\]$", "", axis_label(name))
    m = re.match(r"^\$([^$]*?) = [^$]*\$(.*)$", label)
    return f"${m.group(1)}${m.group(2)}" if m else label


def _text_inches(text: str, size: float) -> float:
    """Width [in] of ``text`` at ``size`` points in the default font (mathtext between ``$``
    signs), measured by a 1-inch Agg renderer at 72 dpi, without drawing the figure."""
    # lazy: matplotlib is imported only to draw
    from matplotlib.backends.backend_agg import RendererAgg
    from matplotlib.font_manager import FontProperties

    if not text:
        return 0.0
    ismath = text.count("$") >= 2 and text.count("$") % 2 == 0
    w, _, _ = RendererAgg(72, 72, 72).get_text_width_height_descent(
        text, FontProperties(size=size), ismath=ismath
    )
    return float(w) / 72.0


def _tick_inches(axis) -> float:
    """Width [in] of the widest tick label ``axis`` will draw (its locator and formatter at
    the current view, evaluated without drawing)."""
    import matplotlib  # lazy: matplotlib is imported only to draw
    from matplotlib.font_manager import FontProperties

    lo, hi = sorted(axis.get_view_interval())
    tol = 1e-9 * max(abs(lo), abs(hi), 1.0)
    locs = [v for v in axis.get_major_locator()() if lo - tol <= v <= hi + tol]
    labels = axis.get_major_formatter().format_ticks(locs) if locs else []
    rc = matplotlib.rcParams
    label_size = rc["ytick.labelsize"] if axis.axis_name == "y" else rc["xtick.labelsize"]
    size = FontProperties(size=label_size).get_size_in_points()
    return max((_text_inches(t, size) for t in labels), default=0.0)


def _description(value, x, y, *, what, n_cases, per_cell=1, line_per=None, dots=False) -> str:
    """The title of a sweep figure: what is plotted, over what, from how many cases."""
    v, cases = _short(value), f"{n_cases} case{'s' if n_cases != 1 else ''}"
    if y is not None:
        if dots:
            return f"{v} over {_short(x)} and {_short(y)}: each dot one case, {cases}"
        cell = f"{what} of {per_cell} cases per cell, " if per_cell > 1 else ""
        return f"{v} over the ({_short(x)}, {_short(y)}) grid: {cell}{cases}"
    head = f"{v} against {_short(x)}"
    if line_per:
        head += f", one line per value of {_short(line_per)}"
    return head + (f": each dot one case, {cases}" if dots else f" ({cases})")


def _categorical(values) -> bool:
    return np.asarray(values).dtype.kind in "USO"


def _codes(name, values):
    """Category codes of a string column and the category names (known order first)."""
    vals = np.asarray(values).astype(str)
    known = _CATEGORIES.get(name, ())
    names = [c for c in known if c in set(vals.tolist())]
    names += sorted(set(vals.tolist()) - set(names))
    lookup = {c: i for i, c in enumerate(names)}
    return np.array([lookup[c] for c in vals], dtype=float), names


def _numeric(table, name):
    """A column as floats (codes for strings) and its category names (None if numeric)."""
    col = np.asarray(table[name])
    if _categorical(col):
        return _codes(name, col)
    if col.dtype.kind not in "fiub":
        raise ValueError(f"column {name!r} has values of type {col.dtype}; valid: numbers or names")
    return col.astype(float), None


def _fmt(x) -> str:
    return f"{x:.6g}" if isinstance(x, (float, np.floating)) else str(x)


def _constant_value(table, name):
    col = np.asarray(table[name])
    u = np.unique(col.astype(str) if _categorical(col) else col)
    return u[0] if u.size == 1 else None


def _independent_axes(table, x, varied):
    """Varied parameters besides ``x`` that ``x`` does not determine (other sweep axes)."""
    names = varied if varied is not None else []
    out = []
    xs = np.asarray(table[x]).astype(str)
    for k in names:
        if k == x or k not in table:
            continue
        ks = np.asarray(table[k]).astype(str)
        if np.unique(ks).size < 2:
            continue
        pairs = np.unique(np.char.add(np.char.add(xs, "|"), ks))
        if pairs.size > np.unique(xs).size:
            out.append(k)
    return out


def plot_sweep(
    table: dict,
    x: str,
    value: str,
    y: str | None = None,
    title: str | None = None,
    *,
    include_unconverged: bool = False,
    varied=None,
    kind: str | None = None,
    left_out=None,
):
    """Heat map of ``value`` over (``x``, ``y``), or ``value`` against ``x``.

    Parameters
    ----------
    table : dict
        Column name → array, as returned by :func:`slidespin.studies.sweep_read.read_sweep` (with
        ``include_unconverged=True``: this function leaves those cases out itself, and marks
        where they were).
    x, y : str
        Columns for the axes (``y`` optional). Both must vary in the sweep: a fixed parameter
        is refused with a message naming its value.
    value : str
        Column shown (colour or ordinate). Name columns (``ending``, ``status``, ``law``) are
        drawn as categories, one colour per name (the most frequent name per heat-map cell).
        Non-finite values (β* = ∞ of pure sliding, undefined ϑ*) are left blank.
    include_unconverged : bool, default False
        Keep the cases whose status is in :data:`slidespin.motion.outcomes.UNCONVERGED` or
        :data:`~slidespin.motion.outcomes.LOADED_UNCONVERGED`; by default
        they are left out and their cells (or positions on the x axis) are marked ✕.
        Cells or points with a flagged status (marginal, saddle) are marked ○.
    varied : list of str, optional
        The sweep's varied parameters (from its manifest). Without ``y``, a grid sweep with
        one other axis draws one line per value of that axis (at most 12); with more axes
        it is refused (give ``y``). A random sweep is drawn as points, never joined.
    title : str, optional
        First line(s) of the title. The title always says what is shown over what: the
        value, how a heat-map cell summarises its cases (mean, most frequent), the axes and
        the number of cases drawn (``β* over the (μ, I*) grid: 9 cases``).
    kind : {"grid", "random"}, optional
        The sweep's kind (from its manifest); by default guessed from the data.
    left_out : ignored
        Kept for callers of an earlier version.

    Returns
    -------
    matplotlib.figure.Figure
        Made through pyplot if pyplot is imported, else on an Agg canvas; fixed margins
        sized from its text (no layout engine). Its axes: the plot, then the colour bar of
        a heat map.
    """
    # lazy: matplotlib is imported only to draw
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    for name in (x, value) + ((y,) if y else ()):
        if name not in table:
            raise ValueError(f"column {name!r} is not in the sweep; valid: {', '.join(table)}")
    if not table or np.asarray(table[x]).size == 0:
        raise ValueError("the sweep table is empty")
    varied = list(varied) if varied is not None else None
    for flag, col in (("--x", x), ("--y", y)):
        if col is None:
            continue
        const = _constant_value(table, col)
        if const is not None:
            hint = f"; varied: {', '.join(varied)}" if varied else ""
            raise ValueError(
                f"{flag} {col} is fixed at {_fmt(const)} in this sweep: nothing "
                f"to plot against{hint}"
            )
    if y is not None and y == x:
        raise ValueError(f"--x and --y are both {x!r}; give two different columns")

    status = np.asarray(table["status"]).astype(str) if "status" in table else None
    n_all = np.asarray(table[x]).size
    bad = (
        np.zeros(n_all, bool)
        if status is None or include_unconverged
        else np.isin(status, sorted(UNCONVERGED | LOADED_UNCONVERGED))
    )
    flagged = np.zeros(n_all, bool) if status is None else np.isin(status, sorted(FLAGGED))
    keep = ~bad

    xs_all, xcats = _numeric(table, x)
    vs_all, vcats = _numeric(table, value)
    xs, vs = xs_all[keep], vs_all[keep]
    finite = np.isfinite(vs)
    fig = _figure(6.4, 4.8)  # resized below, when the text it holds is known
    ax = fig.add_axes((0.15, 0.15, 0.6, 0.7))
    cmap_cat = None
    mesh = None  # what the colour bar shows (a heat map)
    describe: dict = {"what": "mean", "n_cases": int(keep.sum())}
    if vcats is not None:
        from matplotlib.colors import BoundaryNorm, ListedColormap  # lazy: only to draw

        describe["what"] = "most frequent"
        base = _cmap("tab10")
        cmap_cat = ListedColormap([base(i % 10) for i in range(len(vcats))])
        norm_cat = BoundaryNorm(np.arange(len(vcats) + 1) - 0.5, len(vcats))
    handles: list[Artist] = []

    if y is None:
        if kind is None:
            kind = "grid"
        others = _independent_axes(table, x, varied) if varied is not None else []
        if kind == "random":
            ax.plot(xs[finite], vs[finite], "o", ms=2.5, alpha=0.6, lw=0)
            describe["dots"] = True
            others_txt = ", ".join(_short(k) for k in (varied or []) if k != x)
            if others_txt:
                describe["also"] = f"also varied: {others_txt}"
        elif len(others) > 1 or (
            others and np.unique(np.asarray(table[others[0]]).astype(str)).size > 12
        ):
            raise ValueError(
                f"the sweep varies {', '.join([x] + others)}: a line against --x {x} alone "
                f"would join cases of different {', '.join(others)}; give --y {others[0]} "
                "for a heat map"
            )
        elif others:
            k = others[0]
            kcol = np.asarray(table[k])[keep]
            kvals = np.unique(kcol)
            colors = _cmap("viridis")(np.linspace(0.0, 0.9, kvals.size))
            describe["line_per"] = k
            for c, kv in zip(colors, kvals):
                sel = (kcol == kv) & finite
                order = np.argsort(xs[sel], kind="stable")
                style = "o" if vcats is not None else "o-"
                ax.plot(
                    xs[sel][order],
                    vs[sel][order],
                    style,
                    ms=3,
                    lw=1.2,
                    color=c,
                    label=f"{axis_label(k)} = {_fmt(kv)}",
                )
            ax.legend(fontsize=7, frameon=False, loc="best")
        else:
            order = np.argsort(xs, kind="stable")
            style = "o" if vcats is not None else "o-"
            ax.plot(xs[order][finite[order]], vs[order][finite[order]], style, ms=3, lw=1.2)
        if flagged[keep].any():
            fl = flagged[keep] & finite
            ax.plot(xs[fl], vs[fl], "o", ms=8, mfc="none", mec="C3", mew=0.9)
        if bad.any():
            ax.plot(
                xs_all[bad],
                np.full(bad.sum(), 0.02),
                "x",
                color="C3",
                ms=6,
                transform=ax.get_xaxis_transform(),
                clip_on=False,
            )
        if vcats is not None:
            ax.set_yticks(range(len(vcats)), [c.replace("_", " ") for c in vcats])
            ax.set_ylim(-0.5, len(vcats) - 0.5)
        elif not finite.all():
            handles.append(
                Patch(
                    facecolor="white",
                    edgecolor="0.6",
                    label=f"not drawn: {int((~finite).sum())} cases with "
                    f"{axis_label(value)} not finite (β* = ∞: pure sliding; "
                    "no ϑ*: spiral or pure spinning)",
                )
            )
        ax.set_ylabel(axis_label(value))
        ax.grid(alpha=0.3)
    else:
        ys_all, ycats = _numeric(table, y)
        ys = ys_all[keep]
        ux, uy = np.unique(xs_all), np.unique(ys_all)
        on_grid = ux.size > 1 and uy.size > 1 and ux.size * uy.size <= n_all
        if on_grid:
            # a grid: average the finite values falling in each (x, y) cell (for names: the
            # most frequent one)
            ix, iy = np.searchsorted(ux, xs), np.searchsorted(uy, ys)
            if vcats is None:
                total = np.zeros((uy.size, ux.size))
                count = np.zeros((uy.size, ux.size))
                np.add.at(total, (iy[finite], ix[finite]), vs[finite])
                np.add.at(count, (iy[finite], ix[finite]), 1.0)
                with np.errstate(invalid="ignore"):
                    grid = total / count
                mesh = ax.pcolormesh(ux, uy, grid, shading="nearest", cmap="viridis")
            else:
                votes = np.zeros((uy.size, ux.size, len(vcats)))
                np.add.at(votes, (iy, ix, vs.astype(int)), 1.0)
                grid = np.where(votes.sum(axis=2) > 0, votes.argmax(axis=2), np.nan)
                mesh = ax.pcolormesh(ux, uy, grid, shading="nearest", cmap=cmap_cat, norm=norm_cat)
            describe["per_cell"] = n_all // (ux.size * uy.size)
            cell_bad = np.zeros((uy.size, ux.size), bool)
            cell_bad[np.searchsorted(uy, ys_all[bad]), np.searchsorted(ux, xs_all[bad])] = True
            cell_flag = np.zeros((uy.size, ux.size), bool)
            fl = flagged & keep
            cell_flag[np.searchsorted(uy, ys_all[fl]), np.searchsorted(ux, xs_all[fl])] = True
            by, bx = np.nonzero(cell_bad)
            fy_, fx_ = np.nonzero(cell_flag & ~cell_bad)
            blank = ~np.isfinite(grid) & ~cell_bad
        else:
            if vcats is None:
                mesh = ax.scatter(xs[finite], ys[finite], c=vs[finite], s=12, cmap="viridis")
            else:
                mesh = ax.scatter(xs, ys, c=vs, s=12, cmap=cmap_cat, norm=norm_cat)
            describe["dots"] = True
            bx, by = xs_all[bad], ys_all[bad]
            fl = flagged & keep
            fx_, fy_ = xs_all[fl], ys_all[fl]
            on_grid = False
            blank = np.array([not finite.all()])
        if on_grid:
            bx, by = ux[bx], uy[by]
            fx_, fy_ = ux[fx_], uy[fy_]
        import matplotlib.patheffects as pe  # lazy: only to draw

        halo = [pe.withStroke(linewidth=2.6, foreground="w")]  # visible on any colour
        if len(bx):
            ax.plot(bx, by, "x", color="k", ms=5, mew=1.1, lw=0, path_effects=halo)
        if len(fx_):
            ax.plot(fx_, fy_, "o", ms=5, mfc="none", mec="C3", mew=1.1, lw=0, path_effects=halo)
        if ycats is not None:
            ax.set_yticks(range(len(ycats)), ycats)
        ax.set_ylabel(axis_label(y))
        if blank.any():
            handles.append(
                Patch(
                    facecolor="white",
                    edgecolor="0.6",
                    label=f"blank: {axis_label(value)} not finite (β* = ∞: pure "
                    "sliding; no ϑ*: spiral or pure spinning)",
                )
            )
    if xcats is not None:
        ax.set_xticks(range(len(xcats)), xcats)
    if bad.any() and status is not None:
        counts = {k: int(c) for k, c in zip(*np.unique(status[bad], return_counts=True))}
        handles.append(
            Line2D(
                [],
                [],
                ls="none",
                marker="x",
                color="k" if y else "C3",
                label=f"left out: {int(bad.sum())} unconverged cases ("
                + ", ".join(f"{k} {c}" for k, c in counts.items())
                + "); --include-unconverged keeps them",
            )
        )
    if flagged[keep].any() and status is not None:
        counts = {k: int(c) for k, c in zip(*np.unique(status[flagged & keep], return_counts=True))}
        handles.append(
            Line2D(
                [],
                [],
                ls="none",
                marker="o",
                mfc="none",
                mec="C3",
                label="flagged (analytic limit reported): "
                + ", ".join(f"{k} {c}" for k, c in counts.items()),
            )
        )
    ax.set_xlabel(axis_label(x))

    also = describe.pop("also", None)
    text = _description(value, x, y, **describe)
    if also:
        text += f"; {also}"
    lines = textwrap.wrap(text, 72)
    if title:
        lines = textwrap.wrap(title, 72) + lines
    ax.set_title("\n".join(lines), fontsize=9, y=1.0)

    # ---- the layout [in], computed once: the axes keep 5.0 x 3.3 in whatever the text is
    cax = None
    if mesh is not None:
        cax = fig.add_axes((0.85, 0.15, 0.03, 0.7))
        if vcats is None:
            fig.colorbar(mesh, cax=cax, label=axis_label(value))
        else:
            cb = fig.colorbar(mesh, cax=cax, label=axis_label(value), ticks=np.arange(len(vcats)))
            cb.ax.set_yticklabels([c.replace("_", " ") for c in vcats])
    label_h = 0.25  # an axis label at 10 pt, with its pad
    left = 0.15 + label_h + _tick_inches(ax.yaxis) + 0.1
    right = 0.25
    if cax is not None:  # the colour bar, its tick labels and its label
        right = 0.15 + 0.16 + 0.1 + _tick_inches(cax.yaxis) + label_h + 0.1
    top = 0.2 + 0.16 * len(lines)
    notes_h = 0.17 * len(handles) + 0.05 if handles else 0.0
    bottom = 0.3 + label_h + notes_h + 0.1  # tick labels, x label, then the notes
    width = max(6.4, left + 4.0 + right)
    height = top + 3.3 + bottom
    fig.set_size_inches(width, height)
    w_ax = width - left - right
    ax.set_position(_rect(fig, left, bottom, w_ax, 3.3))
    if cax is not None:
        cax.set_position(_rect(fig, left + w_ax + 0.15, bottom, 0.16, 3.3))
    if handles:  # below the axes and their x label, outside them (no overlap)
        fig.legend(
            handles=handles,
            loc="lower left",
            bbox_to_anchor=(0.05 / width, 0.08 / height),
            fontsize=7,
            frameon=False,
            borderaxespad=0.0,
            handletextpad=0.6,
        )
    return fig
