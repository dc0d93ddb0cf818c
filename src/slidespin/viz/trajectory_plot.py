"""Figures of one run: a trajectory (the path of the mass centre with the patch outline drawn
along it, β(t) and ϑ(t) with their terminal values β*, ϑ*, the speed and the spin; MODEL §5,
§9), and a loaded run (MODEL §11) with its stick phases shaded and the applied load.

matplotlib is imported lazily, only by the functions that draw (:func:`slidespin.viz._mpl._plt`).
Every function takes data objects (a :class:`~slidespin.motion.simulate.Trajectory` or a
:class:`~slidespin.motion.loaded_trajectory.LoadedTrajectory`), draws on the axes it is given
or creates a figure, and returns the axes or the figure; nothing here computes physics.
"""

from __future__ import annotations

import math

import numpy as np

from slidespin.motion.loads import applied_wrench
from slidespin.viz._mpl import _plt

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
    ``t, x, y, phi`` and a ``body``); ``end_label`` names the marker of the last point. Lengths are in cm when the drawn extent (path and patch) is below 1 m,
    in m otherwise.
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
    cmap = _plt().get_cmap("Greys")
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
    """
    if hasattr(traj, "phases"):
        return plot_loaded_trajectory(traj, title=title, n_outlines=n_outlines)
    plt = _plt()
    fig = plt.figure(figsize=(12.5, 6.2), layout="constrained")
    gs = fig.add_gridspec(2, 3, width_ratios=[1.8, 1.0, 1.0])
    ax_path = fig.add_subplot(gs[:, 0])
    ax_beta = fig.add_subplot(gs[0, 1])
    ax_theta = fig.add_subplot(gs[0, 2])
    ax_v = fig.add_subplot(gs[1, 1])
    ax_w = fig.add_subplot(gs[1, 2])

    draw_path(ax_path, traj, n_outlines)
    ax_path.legend(loc="best", fontsize=8, frameon=False)
    ax_path.set_title("path of the mass centre", fontsize=10)

    t = traj.t
    a = traj.body.length_unit
    draw_beta(ax_beta, t, traj.beta / a, traj.beta_stop / a)
    ax_beta.set_ylabel("β/ℓ = v/(ℓω), ℓ = extent" if traj.body.is_footprint else "β/a = v/(aω)")
    ax_beta.set_title("distance to the centre of rotation", fontsize=10)

    draw_angle(ax_theta, t, traj.theta, traj.theta_stop, "ϑ*")
    ax_theta.set_ylabel("ϑ [rad]")
    ax_theta.set_title("direction of the velocity of G", fontsize=10)

    ax_v.plot(t, traj.speed, color="C2")
    ax_v.set_ylabel("v [m/s]")
    ax_v.set_title("speed of G", fontsize=10)
    ax_w.plot(t, traj.omega, color="C4")
    ax_w.set_ylabel("ω [rad/s]")
    ax_w.set_title("spin rate", fontsize=10)
    for ax in (ax_beta, ax_theta, ax_v, ax_w):
        ax.set_xlabel("t [s]")
        ax.axvline(traj.t_stop, color="C3", lw=0.8, ls=":")
        ax.set_xlim(0.0, traj.t_stop * 1.02)
        ax.grid(alpha=0.25)
    if title:
        fig.suptitle(title, fontsize=11)
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
    phi = np.interp(t, t_rec, np.asarray(traj.phi, dtype=float))
    out = np.array(
        [
            applied_wrench(traj.body, ti, pi, traj.load, traj.incline, traj.g)
            for ti, pi in zip(t, phi)
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


def plot_loaded_trajectory(traj, title: str | None = None, n_outlines: int = 9):
    """Summary of a loaded run (MODEL §11): path with outlines, speed, spin and the load.

    Left, the path of the mass centre with the patch outline along it. Right, against time:
    the speed of G, the spin rate and the applied load (force components in the plane frame
    and the moment about G; on a slope, the pull of gravity along the plane included), with
    the stick phases shaded (:data:`STICK_GID`). The legend sits below the axes, outside
    them, so it never covers the data; the figure title gives the ending and the status.

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

    plt = _plt()
    fig = plt.figure(figsize=(12.0, 7.4), layout="constrained")
    gs = fig.add_gridspec(3, 2, width_ratios=[1.35, 1.0])
    ax_path = fig.add_subplot(gs[:, 0])
    ax_v = fig.add_subplot(gs[0, 1])
    ax_w = fig.add_subplot(gs[1, 1], sharex=ax_v)
    ax_q = fig.add_subplot(gs[2, 1], sharex=ax_v)

    end_label = _LOADED_END_LABELS.get(traj.ending, f"end: {traj.ending}")
    draw_path(ax_path, traj, n_outlines, end_label=end_label)
    where = "path of the mass centre"
    if traj.incline is not None:
        inc = traj.incline
        a0 = math.degrees(inc.angle_at(0.0))
        a1 = math.degrees(inc.angle_at(float(traj.t[-1])))
        tilt = f"{a0:.4g}°" if inc.is_constant else f"{a0:.4g}°→{a1:.4g}°"
        where += f" (plane tilted {tilt}, downhill {math.degrees(inc.downhill):.4g}° from x)"
    ax_path.set_title(where, fontsize=10)

    t = np.asarray(traj.t, dtype=float)
    style = "o-" if t.size == 1 else "-"  # a run that ends at t = 0 is one point
    ax_v.plot(t, traj.speed, style, color="C2", ms=3)
    ax_v.set_ylabel("v [m/s]")
    ax_v.set_ylim(bottom=0.0)  # a speed
    ax_v.set_title("speed of G", fontsize=10)
    ax_w.plot(t, traj.omega, style, color="C4", ms=3)
    ax_w.set_ylabel("ω [rad/s]")
    ax_w.set_title("spin rate", fontsize=10)

    tq, qx, qy, mz = applied_load_history(traj)
    force_on = bool(np.any(qx != 0.0) or np.any(qy != 0.0))
    moment_on = bool(np.any(mz != 0.0))
    load_handles = []
    qstyle = "o-" if tq.size == 1 else "-"
    if force_on:
        load_handles += ax_q.plot(tq, qx, qstyle, color="C0", ms=3, label="$Q_x$ (force, x)")
        load_handles += ax_q.plot(tq, qy, qstyle, color="C1", ms=3, label="$Q_y$ (force, y)")
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
    )

    t_final = float(t[-1])
    for ax in (ax_v, ax_w, ax_q):
        draw_stick(ax, traj.phases)
        ax.grid(alpha=0.25)
        if t_final > 0.0:
            ax.set_xlim(0.0, t_final)
    for ax in (ax_v, ax_w):
        ax.tick_params(labelbottom=False)
    ax_q.set_xlabel("t [s]")

    handles, _ = ax_path.get_legend_handles_labels()
    handles.append(Patch(facecolor="0.86", edgecolor="none", label="stick (held at rest)"))
    handles += load_handles
    fig.legend(
        handles=handles,
        loc="outside lower center",
        ncols=min(len(handles), 4),
        fontsize=8,
        frameon=False,
    )
    head = f"ending: {traj.ending}, status: {traj.status}"
    fig.suptitle(f"{title}\n{head}" if title else head, fontsize=11)
    return fig


def draw_beta(ax, t, ratio, ratio_stop, limit: float = BETA_LIMIT):
    """β/a against t, without the excursions to ±∞ where ω changes sign.

    Points with |β/a| > ``limit`` are not drawn (the line is broken there, not joined
    across ±∞); the axis spans the points drawn and the terminal value, and a note says
    that parts are off the scale.
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
    if math.isfinite(ratio_stop):
        ax.axhline(ratio_stop, color="0.5", lw=0.8, ls="--", label=f"β*/a = {ratio_stop:.4f}")
        if abs(ratio_stop) <= limit:
            span.append(ratio_stop)
    elif ratio_stop == math.inf:
        ax.plot([], [], " ", label="β* = ∞ (pure sliding)")
    if span:
        lo, hi = min(span), max(span)
        pad = max(0.05 * (hi - lo), 0.02 * max(abs(lo), abs(hi)), 0.05)
        ax.set_ylim(lo - pad, hi + pad)
    with np.errstate(invalid="ignore"):
        off = ~np.isnan(ratio) & ~(np.abs(ratio) <= limit)
    if off.any():
        ax.text(
            0.98,
            0.02,
            f"|β/a| > {limit:g} off the scale",
            transform=ax.transAxes,
            ha="right",
            va="bottom",
            fontsize=7,
            color="0.4",
        )
    if ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize=8, frameon=False)
    return ax


def draw_angle(ax, t, angle, angle_stop, symbol: str = "ϑ*", noise: float = ANGLE_NOISE):
    """An angle against t, unwrapped (no jumps of 2π); a constant one is drawn as such.

    If the angle varies by less than ``noise`` [rad] (round-off of a direction that does not
    change, ~1e-15), the axis is centred on it with a ±0.1 rad span instead of magnifying the
    noise, and the legend says it is constant.
    """
    angle = np.asarray(angle, dtype=float)
    ok = np.isfinite(angle)
    unwrapped = angle.copy()
    if ok.any():
        unwrapped[ok] = np.unwrap(angle[ok])
    ax.plot(t, unwrapped, color="C1")
    stop = angle_stop
    if math.isfinite(angle_stop) and ok.any():
        last = unwrapped[ok][-1]  # the same direction, on the unwrapped branch
        stop = angle_stop + 2 * math.pi * round((last - angle_stop) / (2 * math.pi))
    vals = unwrapped[ok]
    if vals.size and np.ptp(vals) < noise:
        centre = float(np.mean(vals)) + 0.0
        ax.set_ylim(centre - 0.1, centre + 0.1)
        ax.plot([], [], " ", label=f"constant: {centre:.4f} rad")
    if math.isfinite(stop):
        ax.axhline(stop, color="0.5", lw=0.8, ls="--", label=f"{symbol} = {angle_stop:.4f} rad")
    elif ok.any():
        ax.plot([], [], " ", label=f"{symbol} undefined (no limiting direction)")
    if ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize=8, frameon=False)
    return ax
