"""Figures of one run: a trajectory (the path of the mass centre with the patch outline drawn
along it, β(t) and ϑ(t) with their terminal values β*, ϑ*, the speed and the spin; MODEL §5,
§9), and a loaded run (MODEL §11) with its stick phases shaded and the applied load.

matplotlib is imported lazily, only by the functions that draw. The figures are built with
fixed margins (no layout engine), and through pyplot only when pyplot is already imported (an
interactive session or a notebook, where ``plt.show()`` shows them); otherwise they are bare
figures on an Agg canvas, for ``savefig``. Every function takes data objects (a
:class:`~slidespin.motion.trajectory.Trajectory` or a
:class:`~slidespin.motion.loaded_trajectory.LoadedTrajectory`), draws on the axes it is given
or creates a figure, and returns the axes or the figure; nothing here computes physics.
"""

from __future__ import annotations

import math

import numpy as np

from slidespin.motion.springs import applied_wrench_state, has_springs
from slidespin.viz._mpl import _cmap, _figure, _grid, _rect

__all__ = [
    "plot_trajectory",
    "plot_loaded_trajectory",
    "outline_world",
    "draw_path",
    "draw_beta",
    "draw_angle",
    "draw_stick",
    "applied_load_history",
    "BETA_LIMIT",
    "ANGLE_NOISE",
    "STICK_GID",
    "WIDE_PATH",
]

#: |β/a| beyond which β/a is not drawn (the centre of rotation is more than 10 semi-axes
#: away: the motion is nearly pure sliding, and β/a → ±∞ where ω changes sign)
BETA_LIMIT = 10.0
#: a direction that varies by less than this [rad] is drawn as constant (round-off, 1e-15)
ANGLE_NOISE = 1e-9
#: ``gid`` of the shaded spans that mark the stick phases of a loaded run (for finding them)
STICK_GID = "stick"
#: number of instants at which the applied load of a loaded run is drawn
LOAD_SAMPLES = 801
#: data aspect (width/height of the path with its outlines) from which the path is drawn
#: across the top of its figure, above a row of time panels, rather than in a column beside
#: them (a long straight slide or push would leave a column mostly empty)
WIDE_PATH = 3.0


def outline_world(body, x, y, phi, n: int = 121) -> np.ndarray:
    """Patch outline in the fixed frame with G at (x, y) and body angle φ; shape (·, 2) [m].

    For a footprint every closed curve of ``patch.outlines()`` (each pad, a ring's two
    circles) is included, separated by a row of NaN (matplotlib breaks the line there).
    """
    if getattr(body, "is_footprint", False):
        parts = []
        for curve in body.patch.outlines(n):
            parts.append(np.asarray(curve, dtype=float))
            parts.append(np.full((1, 2), np.nan))
        pts = np.vstack(parts[:-1])
    else:
        pts = body.patch.outline(n)
    pts = pts - np.asarray(body.mass_centre)
    c, s = math.cos(phi), math.sin(phi)
    return np.column_stack((x + c * pts[:, 0] - s * pts[:, 1], y + s * pts[:, 0] + c * pts[:, 1]))


def draw_path(
    ax,
    traj,
    n_outlines: int = 9,
    color: str = "C0",
    label: str | None = "path of G",
    end_label: str = "stop",
):
    """Path of the mass centre with the patch outline drawn along it.

    The outlines are spaced evenly in the amount of motion (distance travelled by G plus
    a times the angle turned), so that they spread over the whole path rather than crowd
    where the body is slow; their shade darkens with time. ``traj`` is a
    :class:`~slidespin.Trajectory` or a
    :class:`~slidespin.motion.loaded_trajectory.LoadedTrajectory` (any object with arrays
    ``t, x, y, phi`` and a ``body``); ``end_label`` names the marker of the last point.
    Lengths are in cm when the drawn extent (path and patch) is below 1 m, in m otherwise.
    """
    a = traj.body.length_unit  # the semi-axis a, or a footprint's extent
    extent = max(float(np.ptp(traj.x)), float(np.ptp(traj.y))) + 2.0 * a
    scale, unit = (1e2, "cm") if extent < 1.0 else (1.0, "m")  # cm below a metre
    ax.plot(traj.x * scale, traj.y * scale, color=color, lw=1.6, label=label, zorder=3)
    path_length = getattr(traj, "path_length", None)
    if path_length is None:  # a loaded run: the distance along the recorded points
        path_length = np.concatenate(([0.0], np.cumsum(np.hypot(np.diff(traj.x), np.diff(traj.y)))))
    progress = path_length + a * np.concatenate(([0.0], np.cumsum(np.abs(np.diff(traj.phi)))))
    if progress[-1] > 0.0:
        times = np.interp(np.linspace(0.0, progress[-1], n_outlines), progress, traj.t)
    else:
        times = np.linspace(0.0, traj.t[-1], n_outlines)
    cmap = _cmap("Greys")
    for i, ti in enumerate(times):
        xi = np.interp(ti, traj.t, traj.x)
        yi = np.interp(ti, traj.t, traj.y)
        pi = np.interp(ti, traj.t, traj.phi)
        ol = outline_world(traj.body, xi, yi, pi) * scale
        shade = cmap(0.35 + 0.55 * i / max(n_outlines - 1, 1))
        ax.plot(ol[:, 0], ol[:, 1], color=shade, lw=0.9, zorder=2)
        # a tick along the body axis ξ shows the orientation
        c, s = math.cos(pi), math.sin(pi)
        a = traj.body.length_unit * scale
        ax.plot(
            [xi * scale, xi * scale + a * c],
            [yi * scale, yi * scale + a * s],
            color=shade,
            lw=0.9,
            zorder=2,
        )
    ax.plot(traj.x[0] * scale, traj.y[0] * scale, "o", color=color, ms=5, zorder=4, label="start")
    ax.plot(
        traj.x[-1] * scale, traj.y[-1] * scale, "s", color="C3", ms=5, zorder=4, label=end_label
    )
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel(f"x [{unit}]")
    ax.set_ylabel(f"y [{unit}]")
    return ax


def plot_trajectory(traj, title: str | None = None, n_outlines: int = 9):
    """Four-panel summary of a trajectory: path with outlines, β(t) and ϑ(t), v(t) and ω(t).

    Parameters
    ----------
    traj : Trajectory or LoadedTrajectory
        Result of :func:`slidespin.simulate`. A loaded run (with ``phases``) is drawn by
        :func:`plot_loaded_trajectory`.
    title : str, optional
        Figure title.
    n_outlines : int
        Number of patch outlines drawn along the path (equal time intervals).

    Returns
    -------
    matplotlib.figure.Figure
        Made through pyplot if pyplot is imported (``plt.show()`` shows it), else on an Agg
        canvas (``fig.savefig`` writes it). Its axes, in order: path, β, ϑ, speed, spin.
    """
    if hasattr(traj, "phases"):
        return plot_loaded_trajectory(traj, title=title, n_outlines=n_outlines)
    # fixed margins [in]: room for the tick labels and the label of each y axis, the titles
    # above each row and the suptitle. The path panel takes the shape of the path (equal
    # scales): beside a 2 x 2 block of time panels, up to 4.65 in wide, or, for a long path
    # (WIDE_PATH), across the top above a row of the four; the figure is 12.5 in wide at most
    height, left, right, bottom, gap = 6.2, 0.75, 0.2, 0.55, 0.85
    top = 0.65 if title else 0.4
    fig = _figure(12.5, height)
    ax_path = fig.add_axes((0.1, 0.1, 0.4, 0.8))
    draw_path(ax_path, traj, n_outlines)
    box = ax_path.dataLim
    aspect = max(box.width, 1e-12) / max(box.height, 1e-12)
    wide = aspect >= WIDE_PATH
    if wide:
        width, h_time, hgap, gap = 12.5, 2.3, 0.85, 0.95
        w_path = width - left - right
        h_path = min(max(w_path / aspect, 1.3), 3.2)
        height = top + h_path + hgap + h_time + bottom
        fig.set_size_inches(width, height)
        ax_path.set_position(_rect(fig, left, height - top - h_path, w_path, h_path))
        gs = _grid(
            fig, 1, 4, left=left, right=right, bottom=bottom, top=top + h_path + hgap, wgap=gap
        )
        cells = [gs[0, k] for k in range(4)]
    else:
        h_path = height - top - bottom
        w_path = min(max(h_path * aspect, 3.0), 4.65)
        width = left + w_path + gap + 2 * 2.6 + gap + right  # two columns of time panels
        fig.set_size_inches(width, height)
        ax_path.set_position(_rect(fig, left, bottom, w_path, h_path))
        gs = _grid(
            fig,
            2,
            2,
            left=left + w_path + gap,
            right=right,
            bottom=bottom,
            top=top,
            wgap=gap,
            hgap=0.8,
        )
        cells = [gs[0, 0], gs[0, 1], gs[1, 0], gs[1, 1]]
    ax_beta, ax_theta, ax_v, ax_w = (fig.add_subplot(c) for c in cells)

    if wide:  # above the panel, right of its title: a long path leaves no room inside
        ax_path.legend(
            loc="lower right",
            bbox_to_anchor=(1.0, 1.0),
            ncols=3,
            fontsize=8,
            frameon=False,
            borderaxespad=0.1,
        )
    else:
        ax_path.legend(loc="best", fontsize=8, frameon=False)
    # titles at a given height (y=1.0; no ticks on top): matplotlib then skips measuring the
    # top tick labels of every axes at every draw (a fifth of the drawing time)
    ax_path.set_title("path of the mass centre", fontsize=10, y=1.0)

    t = traj.t
    a = traj.body.length_unit
    footprint = bool(getattr(traj.body, "is_footprint", False))
    symbol = "β/ℓ" if footprint else "β/a"
    draw_beta(ax_beta, t, traj.beta / a, traj.beta_stop / a, symbol=symbol)
    ax_beta.set_ylabel("β/ℓ = v/(ℓω), ℓ = extent" if footprint else "β/a = v/(aω)")
    ax_beta.set_title("distance to the centre of rotation", fontsize=10, y=1.0)

    draw_angle(ax_theta, t, traj.theta, traj.theta_stop, "ϑ*", speed=traj.speed)
    ax_theta.set_ylabel("ϑ [rad]")
    ax_theta.set_title("direction of the velocity of G", fontsize=10, y=1.0)

    ax_v.plot(t, traj.speed, color="C2")
    ax_v.set_ylabel("v [m/s]")
    ax_v.set_title("speed of G", fontsize=10, y=1.0)
    ax_w.plot(t, traj.omega, color="C4")
    ax_w.set_ylabel("ω [rad/s]")
    ax_w.set_title("spin rate", fontsize=10, y=1.0)
    for ax in (ax_beta, ax_theta, ax_v, ax_w):
        ax.set_xlabel("t [s]")
        ax.axvline(traj.t_stop, color="C3", lw=0.8, ls=":")
        ax.set_xlim(0.0, traj.t_stop * 1.02)
        ax.grid(alpha=0.25)
    if title:
        fig.suptitle(title, fontsize=11, y=1.0 - 0.12 / fig.get_size_inches()[1], va="top")
    return fig


def draw_stick(ax, phases, color: str = "0.86"):
    """Shade the stick phases ``("stick", t0, t1)`` of ``phases`` on a time axis.

    Each span gets ``gid`` :data:`STICK_GID` and is drawn below the data (it never hides a
    curve). Returns the list of spans.
    """
    spans = []
    for kind, t0, t1 in phases:
        if kind == "stick":
            span = ax.axvspan(t0, t1, color=color, lw=0, zorder=0)
            span.set_gid(STICK_GID)
            spans.append(span)
    return spans


def applied_load_history(traj, n: int = LOAD_SAMPLES):
    """The applied wrench of a loaded run on a time grid, for drawing.

    The load is the input of the run (:mod:`slidespin.motion.loads`), evaluated at ``n`` evenly
    spaced times over [0, t_final] plus the phase boundaries; the body angle, which turns a
    body-frame force and the moment arm of an off-centre force, is interpolated linearly
    between the recorded instants. On a slope the pull of gravity along the plane,
    m g sin α, is part of the force.

    Parameters
    ----------
    traj : LoadedTrajectory
        A loaded run (``load``, ``incline``, ``g``, ``body``, ``t``, ``phi``, ``phases``).
    n : int
        Number of evenly spaced times.

    Returns
    -------
    t, force_x, force_y, moment : ndarray
        Time [s], force in the plane frame [N] and moment about G [N m].
    """
    t_rec = np.asarray(traj.t, dtype=float)
    edges = [b for _, a, b in traj.phases] + [a for _, a, b in traj.phases]
    t = np.unique(np.concatenate((np.linspace(0.0, t_rec[-1], n), edges, t_rec[-1:])))
    t = t[(t >= 0.0) & (t <= t_rec[-1])]
    # a spring's force depends on the state, interpolated between the recorded rows; other
    # loads need the angle only
    names = ("x", "y", "phi", "vx", "vy", "omega")
    cols = [
        np.interp(t, t_rec, np.asarray(getattr(traj, name), dtype=float))
        if name == "phi" or has_springs(traj.load)
        else np.zeros_like(t)
        for name in names
    ]
    out = np.array(
        [
            applied_wrench_state(traj.body, ti, st, traj.load, traj.incline, traj.g)
            for ti, st in zip(t, zip(*cols))
        ],
        dtype=float,
    ).reshape(-1, 3)
    return t, out[:, 0], out[:, 1], out[:, 2]


_LOADED_END_LABELS = {
    "stopped_stuck": "end: stuck",
    "at_rest_throughout": "end: never moved",
    "moving_at_t_end": "end: moving at t_end",
    "steady_sliding": "end: steady sliding",
}


def _flat(ax, values, symbol: str, unit: str, meaning: str) -> bool:
    """Say so on ``ax`` if ``values`` are constant, with limits around the value.

    A curve that does not change (ω ≡ 0 of a push through G) would otherwise sit on an
    axis spanning round-off, or on matplotlib's default ±0.05. Returns True if flat.
    """
    v = np.asarray(values, dtype=float)
    v = v[np.isfinite(v)]
    if v.size == 0:
        return False
    big = float(np.max(np.abs(v)))
    if float(np.ptp(v)) > 1e-9 * big:
        return False
    if big == 0.0:
        ax.set_ylim(-1.0, 1.0)
        ax.set_yticks([0.0])
        text = f"{symbol} = 0 throughout: {meaning}"
    else:
        c = float(np.mean(v))
        ax.set_ylim(c - 0.5 * abs(c), c + 0.5 * abs(c))
        text = f"{symbol} = {c:.4g} {unit} throughout"
    ax.text(
        0.5,
        0.75,
        text,
        transform=ax.transAxes,
        ha="center",
        va="center",
        fontsize=9,
        color="0.3",
    )
    return True


def plot_loaded_trajectory(traj, title: str | None = None, n_outlines: int = 9):
    """Summary of a loaded run (MODEL §11): path with outlines, speed, spin and the load.

    The path of the mass centre with the patch outline along it, and against time: the speed
    of G, the spin rate and the applied load (force components in the plane frame and the
    moment about G; on a slope, the pull of gravity along the plane included), with the stick
    phases shaded (:data:`STICK_GID`). The path panel takes the shape of the path (equal
    scales on x and y): a long path (wider than :data:`WIDE_PATH` times its height) is drawn
    across the top of the figure above the three time panels, any other beside them. A
    curve that does not change (no spin, no motion) is said to be constant in its panel, and
    a force component that is zero throughout is not drawn (its legend entry says so). The
    legend sits below the axes, outside them, so it never covers the data; the figure title
    gives the ending and the status.

    Parameters
    ----------
    traj : LoadedTrajectory
        Result of :func:`slidespin.simulate` with a load, a slope or ``t_end``
        (:func:`slidespin.motion.loaded.simulate_loaded`).
    title : str, optional
        First line of the figure title.
    n_outlines : int
        Number of patch outlines drawn along the path.

    Returns
    -------
    matplotlib.figure.Figure
        Its axes, in order: path, speed, spin, applied force (or the moment alone when
        there is no force), and the moment about G on a right-hand axis when both a force
        and a moment are applied.
    """
    from matplotlib.patches import Patch  # lazy: matplotlib is imported only to draw

    head = f"ending: {traj.ending}, status: {traj.status}"
    if getattr(traj, "tip_time", None) is not None:  # a tall body tipped (MODEL §14)
        head += f" at t = {traj.tip_time:.6g} s"
    suptitle = f"{title}\n{head}" if title else head
    fig = _figure(12.0, 7.4)  # resized below, once the extent of the path is known
    ax_path = fig.add_axes((0.1, 0.1, 0.8, 0.8))
    end_label = _LOADED_END_LABELS.get(traj.ending, f"end: {traj.ending}")
    draw_path(ax_path, traj, n_outlines, end_label=end_label)
    where = "path of the mass centre"
    if traj.incline is not None:
        inc = traj.incline
        a0 = math.degrees(inc.angle_at(0.0))
        a1 = math.degrees(inc.angle_at(float(traj.t[-1])))
        tilt = f"{a0:.4g}°" if inc.is_constant else f"{a0:.4g}°→{a1:.4g}°"
        where += f" (plane tilted {tilt}, downhill {math.degrees(inc.downhill):.4g}° from x)"
    ax_path.set_title(where, fontsize=10, y=1.0)

    tq, qx, qy, mz = applied_load_history(traj)
    fx_on, fy_on = bool(np.any(qx != 0.0)), bool(np.any(qy != 0.0))
    force_on = fx_on or fy_on
    moment_on = bool(np.any(mz != 0.0))
    twin = force_on and moment_on

    # ---- the layout, in inches, from the shape of the path (its data limits, with outlines)
    box = ax_path.dataLim
    aspect = max(box.width, 1e-12) / max(box.height, 1e-12)
    wide = aspect >= WIDE_PATH
    # the legend's entries: the path's (path, start, end), the stick phases, the load's
    n_handles = len(ax_path.get_legend_handles_labels()[0]) + 1 + fx_on + fy_on + moment_on
    ncols = min(n_handles, 4)
    legend_h = 0.2 * math.ceil(n_handles / ncols) + 0.1
    top = 0.2 + 0.21 * (suptitle.count("\n") + 1) + 0.3  # the suptitle, then the axes' titles
    bottom = 0.55 + legend_h + 0.1  # tick labels and t [s], then the legend
    left, gap = 0.85, 0.95  # the tick labels and the label of a y axis
    right = 0.85 if twin else 0.25  # the moment's axis on the right of the load panel
    if wide:
        width = 12.0
        w_path = width - left - 0.25
        h_path = min(max(w_path / aspect, 1.2), 3.4)
        h_time = 2.3
        height = top + h_path + 0.9 + h_time + bottom
        fig.set_size_inches(width, height)
        ax_path.set_position(_rect(fig, left, height - top - h_path, w_path, h_path))
        w_time = (width - left - right - 2 * gap) / 3
        time_rects = [
            _rect(fig, left + k * (w_time + gap), bottom, w_time, h_time) for k in range(3)
        ]
    else:
        height = 7.4
        h_path = height - top - bottom
        w_path = min(max(h_path * aspect, 2.6), 6.5)
        w_time = 5.0
        width = left + w_path + gap + w_time + right
        fig.set_size_inches(width, height)
        ax_path.set_position(_rect(fig, left, bottom, w_path, h_path))
        hgap = 0.4  # the titles of the panels below
        h_time = (h_path - 2 * hgap) / 3
        x0 = left + w_path + gap
        time_rects = [
            _rect(fig, x0, bottom + (2 - k) * (h_time + hgap), w_time, h_time) for k in range(3)
        ]
    ax_v = fig.add_axes(time_rects[0])
    ax_w = fig.add_axes(time_rects[1], sharex=ax_v)
    ax_q = fig.add_axes(time_rects[2], sharex=ax_v)

    t = np.asarray(traj.t, dtype=float)
    style = "o-" if t.size == 1 else "-"  # a run that ends at t = 0 is one point
    ax_v.plot(t, traj.speed, style, color="C2", ms=3)
    ax_v.set_ylabel("v [m/s]")
    ax_v.set_title("speed of G", fontsize=10, y=1.0)
    if not _flat(ax_v, traj.speed, "v", "m/s", "G does not move"):
        ax_v.set_ylim(bottom=0.0)  # a speed
    ax_w.plot(t, traj.omega, style, color="C4", ms=3)
    ax_w.set_ylabel("ω [rad/s]")
    ax_w.set_title("spin rate", fontsize=10, y=1.0)
    _flat(ax_w, traj.omega, "ω", "rad/s", "the body does not turn")

    load_handles = []
    qstyle = "o-" if tq.size == 1 else "-"
    if force_on:
        # a component that is zero throughout is not drawn: its entry says so (the colours
        # differ from the path's, C0, which shares the legend)
        if fx_on:
            label = "$Q_x$ (force, x)" + ("" if fy_on else "; $Q_y$ = 0")
            load_handles += ax_q.plot(tq, qx, qstyle, color="C1", ms=3, label=label)
        if fy_on:
            label = "$Q_y$ (force, y)" + ("" if fx_on else "; $Q_x$ = 0")
            load_handles += ax_q.plot(tq, qy, qstyle, color="C9", ms=3, label=label)
        ax_q.set_ylabel("force [N]")
        if moment_on:
            ax_m = ax_q.twinx()
            load_handles += ax_m.plot(
                tq,
                mz,
                qstyle.replace("-", "--"),
                color="C5",
                ms=3,
                label="moment about G (right axis)",
            )
            ax_m.set_ylabel("moment [N m]")
    elif moment_on:
        load_handles += ax_q.plot(tq, mz, qstyle, color="C5", ms=3, label="moment about G")
        ax_q.set_ylabel("moment [N m]")
    else:
        ax_q.set_ylabel("force [N]")
        ax_q.text(
            0.5,
            0.5,
            "no applied load",
            transform=ax_q.transAxes,
            ha="center",
            va="center",
            fontsize=9,
            color="0.4",
        )
    ax_q.set_title(
        "applied load" + (" (with gravity along the slope)" if traj.incline is not None else ""),
        fontsize=10,
        y=1.0,
    )

    t_final = float(t[-1])
    for ax in (ax_v, ax_w, ax_q):
        draw_stick(ax, traj.phases)
        ax.grid(alpha=0.25)
        if t_final > 0.0:
            ax.set_xlim(0.0, t_final)
        if wide:
            ax.set_xlabel("t [s]")
    if not wide:  # stacked: one time axis, labelled below the lowest panel
        for ax in (ax_v, ax_w):
            ax.tick_params(labelbottom=False)
        ax_q.set_xlabel("t [s]")

    handles, _ = ax_path.get_legend_handles_labels()
    handles.append(Patch(facecolor="0.86", edgecolor="none", label="stick (held at rest)"))
    handles += load_handles
    fig.legend(
        handles=handles,
        loc="lower center",
        bbox_to_anchor=(0.5, 0.1 / height),
        ncols=min(len(handles), 4),
        fontsize=8,
        frameon=False,
    )
    fig.suptitle(suptitle, fontsize=11, y=1.0 - 0.12 / height, va="top")
    return fig


def draw_beta(ax, t, ratio, ratio_stop, limit: float = BETA_LIMIT, symbol: str = "β/a"):
    """β/a against t, without the excursions to ±∞ where ω changes sign.

    Points with |β/a| > ``limit`` are not drawn (the line is broken there, not joined
    across ±∞); the axis spans the points drawn and the terminal value, and the legend says
    that parts are off the scale (a legend, placed where it covers no line, rather than a
    note at a fixed place, which could sit on the terminal value). ``symbol`` names the
    ratio in the legend: ``"β/a"`` for an ellipse, ``"β/ℓ"`` for a footprint (ℓ its extent).
    """
    ratio = np.asarray(ratio, dtype=float)
    shown = np.where(np.isfinite(ratio) & (np.abs(ratio) <= limit), ratio, np.nan)
    ax.plot(t, shown, color="C0")
    span = [
        v
        for v in (
            np.nanmin(shown) if np.isfinite(shown).any() else np.nan,
            np.nanmax(shown) if np.isfinite(shown).any() else np.nan,
        )
        if math.isfinite(v)
    ]
    num, _, den = symbol.partition("/")
    star = f"{num}*/{den}" if den else f"{num}*"
    if math.isfinite(ratio_stop):
        ax.axhline(ratio_stop, color="0.5", lw=0.8, ls="--", label=f"{star} = {_num(ratio_stop)}")
        if abs(ratio_stop) <= limit:
            span.append(ratio_stop)
    elif ratio_stop == math.inf:
        ax.plot([], [], " ", label=f"{num}* = ∞ (pure sliding)")
    if span:
        lo, hi = min(span), max(span)
        pad = max(0.05 * (hi - lo), 0.02 * max(abs(lo), abs(hi)), 0.05)
        ax.set_ylim(lo - pad, hi + pad)
    with np.errstate(invalid="ignore"):
        off = ~np.isnan(ratio) & ~(np.abs(ratio) <= limit)
    if off.any():
        ax.plot([], [], " ", label=f"|{symbol}| > {limit:g}: off the scale")
    if ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize=8, frameon=False, loc="best")
    return ax


def _num(x: float) -> str:
    """``x`` with 4 decimals, never "-0.0000" (round-off of a zero)."""
    return f"{float(f'{x:.4f}') + 0.0:.4f}"


def draw_angle(
    ax,
    t,
    angle,
    angle_stop,
    symbol: str = "ϑ*",
    noise: float = ANGLE_NOISE,
    speed=None,
):
    """An angle against t, unwrapped (no jumps of 2π); a constant one is drawn as such.

    If the angle varies by less than ``noise`` [rad] (round-off of a direction that does not
    change, ~1e-15), the axis is centred on it with a ±0.1 rad span instead of magnifying the
    noise, and the legend says it is constant. With ``speed`` (the speed of G at the same
    instants), the direction of the velocity is not drawn where the speed is exactly 0: it is
    undefined there (a stop by pure spinning ends with v = 0 before ω = 0), and a value such
    as atan2(0, 0) = 0 would draw a drop that is not in the motion. Only a value equal to the
    terminal direction ``angle_stop`` (mod 2π) is kept at such an instant.
    """
    angle = np.asarray(angle, dtype=float)
    ok = np.isfinite(angle)
    if speed is not None:
        at_rest = np.asarray(speed, dtype=float) == 0.0
        if math.isfinite(angle_stop):
            with np.errstate(invalid="ignore"):
                turn = np.remainder(angle - angle_stop + math.pi, 2.0 * math.pi) - math.pi
            at_rest &= ~(np.abs(turn) <= 1e-9)  # the data already gives the limit there
        ok &= ~at_rest
    unwrapped = np.full_like(angle, np.nan)
    if ok.any():
        unwrapped[ok] = np.unwrap(angle[ok])
    ax.plot(t, unwrapped, color="C1")
    stop = angle_stop
    if math.isfinite(angle_stop) and ok.any():
        last = unwrapped[ok][-1]  # the same direction, on the unwrapped branch
        stop = angle_stop + 2 * math.pi * round((last - angle_stop) / (2 * math.pi))
    vals = unwrapped[ok]
    if vals.size and np.ptp(vals) < noise:
        centre = float(np.mean(vals))
        ax.set_ylim(centre - 0.1, centre + 0.1)
        ax.plot([], [], " ", label=f"constant: {_num(centre)} rad")
    if math.isfinite(stop):
        ax.axhline(stop, color="0.5", lw=0.8, ls="--", label=f"{symbol} = {_num(angle_stop)} rad")
    elif ok.any():
        ax.plot([], [], " ", label=f"{symbol} undefined (no limiting direction)")
    if ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize=8, frameon=False, loc="best")
    return ax
