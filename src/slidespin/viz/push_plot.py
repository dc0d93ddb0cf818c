"""The figure of a pushed run (MODEL §13): the body's poses along the pusher's path, the pusher
and the contact, and the pusher's force and the energy balance against time, the contact modes
shaded.

matplotlib is imported lazily (:mod:`slidespin.viz._mpl`); the figure has fixed margins in
inches, no layout engine. Nothing here computes physics: the poses between the recorded rows
are the cubic Hermite interpolants on the recorded velocities of
:func:`slidespin.viz.animate.frame_states`, and the pusher's own position is read from its
path (:meth:`~slidespin.motion.pushers.PointPusher.position`,
:meth:`~slidespin.motion.pushers.LinePusher.ends`).
"""

from __future__ import annotations

import math

import numpy as np

from slidespin.contact.outline import body_outline, to_plane
from slidespin.viz._mpl import _cmap, _figure, _rect
from slidespin.viz.animate import _hermite, _switch_steps
from slidespin.viz.trajectory_plot import WIDE_PATH, outline_world

__all__ = ["MODE_COLOURS", "MODE_GID", "mode_colour", "draw_modes", "plot_pushed_trajectory"]

#: colour of each point-pusher contact mode (:data:`slidespin.motion.outcomes.PUSH_MODES`); a
#: line pusher's ``face_*`` modes take the same colours, its ``vertex_*`` modes a lighter shade
#: and its ``end_*`` modes a darker one; any other mode name gets the next colour of
#: ``_SPARE``
MODE_COLOURS = {
    "separated": "0.55",
    "sticking": "C2",
    "sliding_left": "C1",
    "sliding_right": "C4",
}
_SPARE = ("C8", "C9", "C7")
#: ``gid`` of the shaded spans that mark the contact modes on a time axis (for finding them)
MODE_GID = "mode"


def _blend(colour: str, other: str, amount: float) -> str:
    """``colour`` moved by ``amount`` towards ``other``, as a hex string."""
    from matplotlib.colors import to_hex, to_rgb  # lazy: matplotlib only to draw

    a, b = to_rgb(colour), to_rgb(other)
    r, g, bl = ((1.0 - amount) * x + amount * y for x, y in zip(a, b))
    return str(to_hex((r, g, bl)))


def mode_colour(mode: str, seen: dict | None = None) -> str:
    """The colour of a contact mode: :data:`MODE_COLOURS` (and its shades for a line pusher's
    modes), else a spare colour per new name (``seen`` remembers which, so that one figure
    keeps one colour per mode)."""
    if mode in MODE_COLOURS:
        return MODE_COLOURS[mode]
    head, _, family = mode.partition("_")
    if family in MODE_COLOURS and head in ("face", "vertex", "end"):
        base = MODE_COLOURS[family]
        if head == "face":
            return base
        return _blend(base, "white", 0.45) if head == "vertex" else _blend(base, "black", 0.4)
    seen = {} if seen is None else seen
    if mode not in seen:
        seen[mode] = _SPARE[len(seen) % len(_SPARE)]
    return seen[mode]


def _phases(traj) -> list[tuple[str, float, float]]:
    if hasattr(traj, "phases") and callable(traj.phases):
        return list(traj.phases())
    out: list[tuple[str, float, float]] = []
    for t, m in zip(np.asarray(traj.t, dtype=float), traj.mode):
        if out and out[-1][0] == m:
            out[-1] = (m, out[-1][1], float(t))
        else:
            if out:
                out[-1] = (out[-1][0], out[-1][1], float(t))
            out.append((m, float(t), float(t)))
    return out


def draw_modes(ax, phases, seen: dict | None = None, alpha: float = 0.16) -> None:
    """Shade each phase ``(mode, t0, t1)`` on a time axis in its mode's colour (below the
    data, ``gid`` :data:`MODE_GID`)."""
    for mode, t0, t1 in phases:
        if t1 > t0:
            span = ax.axvspan(t0, t1, color=mode_colour(mode, seen), alpha=alpha, lw=0, zorder=0)
            span.set_gid(MODE_GID)


def _states(traj, tq):
    """G's pose at the times tq (Hermite on the recorded velocities; linear across a step
    whose rows differ in mode, :func:`slidespin.viz.animate.frame_states`)."""
    t = np.asarray(traj.t, dtype=float)
    lin = _switch_steps(traj, t.size)
    x = _hermite(t, np.asarray(traj.x, float), np.asarray(traj.vx, float), tq, lin)
    y = _hermite(t, np.asarray(traj.y, float), np.asarray(traj.vy, float), tq, lin)
    phi = _hermite(t, np.asarray(traj.phi, float), np.asarray(traj.omega, float), tq, lin)
    return x, y, phi


def _row_values(traj, tq, values):
    """Recorded values at the times tq: linear within the row interval holding each time
    (rows are doubled at switches, so an interval never spans a switch); NaN stays NaN."""
    t = np.asarray(traj.t, dtype=float)
    vals = np.asarray(values, dtype=float)
    if t.size == 1:
        return np.repeat(vals[:1], tq.size, axis=0)
    i = np.clip(np.searchsorted(t, tq, side="right") - 1, 0, t.size - 2)
    h = t[i + 1] - t[i]
    with np.errstate(divide="ignore", invalid="ignore"):
        w = np.where(h > 0, (tq - t[i]) / np.where(h > 0, h, 1.0), 0.0)
    w = np.clip(w, 0.0, 1.0)
    switch = _switch_steps(traj, t.size)
    if switch is not None:  # a step across a change of mode holds its first row's values
        w = np.where(switch[i], 0.0, w)
    if vals.ndim == 2:
        w = w[:, None]
    return (1.0 - w) * vals[i] + w * vals[i + 1]


def _row_modes(traj, tq) -> list[str]:
    t = np.asarray(traj.t, dtype=float)
    i = np.clip(np.searchsorted(t, tq, side="right") - 1, 0, t.size - 1)
    # at the last time the mode of the last row
    return [traj.mode[k] for k in i]


def _area(pts: np.ndarray) -> float:
    x, y = pts[:, 0], pts[:, 1]
    return 0.5 * abs(float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1))))


def plot_pushed_trajectory(
    traj,
    *,
    outline=None,
    n_poses: int = 8,
    title: str | None = None,
):
    """A pushed run: poses along the path with the pusher, force and energy against time.

    The plane panel draws the body at ``n_poses`` instants evenly spaced in time (the
    footprint's outline, fading from light to dark; the contact outline dashed where it
    differs from the footprint: a non-convex footprint's hull, or ``outline``), the path of
    the mass centre G, the pusher's path (dashed) and the pusher at the same instants (a dot
    for a finger, a segment for a line pusher), and, at the instants in contact, the contact
    point and the pusher's force as an arrow. The time panels draw the magnitude of the
    pusher's force coloured by contact mode, and the energy balance (pusher work, plane
    friction dissipation, kinetic energy; contact slip and impact losses when they occur);
    the modes are shaded on both (:data:`MODE_GID`) and plastic impacts marked.

    Parameters
    ----------
    traj : PushedTrajectory
        The result of :func:`slidespin.simulate` with ``pusher=``.
    outline : None, vertices (n, 2), a footprint or an Ellipse
        The ``outline=`` the run was given (body frame [m]), drawn dashed; default the
        patch's convex hull.
    n_poses : int
        Number of poses drawn, in [2, 40].
    title : str, optional
        First line of the figure title.

    Returns
    -------
    matplotlib.figure.Figure
        Its axes, in order: the plane, the pusher's force, the energy.
    """
    from matplotlib.lines import Line2D  # lazy: matplotlib is imported only to draw
    from matplotlib.patches import Patch

    if isinstance(n_poses, bool) or not isinstance(n_poses, (int, np.integer)):
        raise ValueError(f"n_poses = {n_poses!r} is invalid; valid range: integer in [2, 40]")
    if not 2 <= n_poses <= 40:
        raise ValueError(f"n_poses = {n_poses!r} is invalid; valid range: integer in [2, 40]")
    body, pusher = traj.body, traj.pusher
    line = hasattr(pusher, "length")
    t = np.asarray(traj.t, dtype=float)
    t0, t1 = float(t[0]), float(t[-1])
    seen: dict = {}

    # ---- the poses and the pusher at n_poses instants, and G's path on a fine grid
    tp = np.linspace(t0, t1, n_poses)
    xp, yp, pp = _states(traj, tp)
    tf = np.linspace(t0, t1, 600) if t1 > t0 else np.array([t0])
    xf, yf, _ = _states(traj, tf)
    ell = body.length_unit
    hull = body_outline(body, outline)
    hull_pts = hull.boundary(181)
    foot = outline_world(body, 0.0, 0.0, 0.0) + np.asarray(body.mass_centre)  # G-relative
    pieces = np.split(foot, np.flatnonzero(np.isnan(foot[:, 0])))  # NaN rows separate pads
    foot_area = sum(_area(c[~np.isnan(c[:, 0])]) for c in pieces if np.sum(~np.isnan(c[:, 0])) > 2)
    show_hull = outline is not None or abs(_area(hull_pts) - foot_area) > 1e-6 * _area(hull_pts)
    path_t = np.unique(np.concatenate((pusher.path[:, 0], tf)))
    path_t = path_t[
        (path_t >= min(t0, pusher.path[0, 0])) & (path_t <= max(t1, pusher.path[-1, 0]))
    ]
    if line:
        centre = np.asarray(pusher.pose(path_t))[:, :2]
        ends = np.asarray(pusher.ends(tp))  # (n, 2, 2)
        finger = np.zeros((n_poses, 2))
    else:
        centre = np.asarray(pusher.position(path_t))
        finger = np.asarray(pusher.position(tp))
        ends = np.zeros((n_poses, 2, 2))
    modes = _row_modes(traj, tp)
    contact = _row_values(traj, tp, traj.contact_point)
    force = _row_values(traj, tp, traj.pusher_force)
    if not line:  # a finger in contact touches the body where it is
        touching = np.array([m != "separated" for m in modes])
        contact[touching] = finger[touching]
    fmag = np.hypot(*np.asarray(traj.pusher_force, dtype=float).T)

    # ---- the units: cm below a metre
    xs = np.concatenate((xf, centre[:, 0]))
    ys = np.concatenate((yf, centre[:, 1]))
    extent = max(float(np.ptp(xs)), float(np.ptp(ys))) + 2.0 * ell
    scale, unit = (1e2, "cm") if extent < 1.0 else (1.0, "m")

    head = f"status: {traj.status}, pushed to t = {t1:.4g} s" + (
        f" ({traj.message})" if getattr(traj, "message", "") else ""
    )
    suptitle = f"{title}\n{head}" if title else head
    fig = _figure(12.0, 7.0)
    ax = fig.add_axes((0.1, 0.1, 0.8, 0.8))
    greys = _cmap("Greys")
    reds = _cmap("Reds")
    for k in range(n_poses):
        frac = k / max(n_poses - 1, 1)
        shade = greys(0.3 + 0.6 * frac)
        w = outline_world(body, xp[k], yp[k], pp[k]) * scale
        ax.plot(w[:, 0], w[:, 1], color=shade, lw=1.0, zorder=2)
        if k == n_poses - 1:
            ax.fill(w[:, 0], w[:, 1], color="C0", alpha=0.12, lw=0, zorder=1)
        if show_hull:
            hw = to_plane(hull_pts, xp[k], yp[k], pp[k]) * scale
            ax.plot(hw[:, 0], hw[:, 1], color=shade, lw=0.7, ls=(0, (3, 2)), zorder=2)
        c, s = math.cos(pp[k]), math.sin(pp[k])
        ax.plot(  # a tick along the body axis ξ shows the orientation
            [xp[k] * scale, (xp[k] + 0.5 * ell * c) * scale],
            [yp[k] * scale, (yp[k] + 0.5 * ell * s) * scale],
            color=shade,
            lw=0.9,
            zorder=2,
        )
        pshade = reds(0.35 + 0.6 * frac)
        if line:
            e = ends[k] * scale
            ax.plot(e[:, 0], e[:, 1], color=pshade, lw=2.6, solid_capstyle="butt", zorder=5)
        else:
            ax.plot(finger[k, 0] * scale, finger[k, 1] * scale, "o", color=pshade, ms=5, zorder=5)
    ax.plot(xf * scale, yf * scale, color="C0", lw=1.5, zorder=3)
    ax.plot(centre[:, 0] * scale, centre[:, 1] * scale, color="C3", lw=1.0, ls="--", zorder=3)
    wp = pusher.path[:, 1:3] * scale
    ax.plot(wp[:, 0], wp[:, 1], "D", color="C3", ms=3.5, zorder=4)
    on = np.isfinite(contact[:, 0])
    if on.any():
        ax.plot(
            contact[on, 0] * scale, contact[on, 1] * scale, "x", color="k", ms=6, mew=1.4, zorder=6
        )
        fmax = float(np.nanmax(fmag)) if np.isfinite(fmag).any() else 0.0
        if fmax > 0.0:
            k_arrow = 0.8 * ell * scale / fmax  # the largest force is 0.8 ℓ long
            ax.quiver(
                contact[on, 0] * scale,
                contact[on, 1] * scale,
                force[on, 0] * k_arrow,
                force[on, 1] * k_arrow,
                angles="xy",
                scale_units="xy",
                scale=1.0,
                color="C3",
                width=0.004,
                zorder=7,
            )
    ax.plot(xp[0] * scale, yp[0] * scale, "o", color="C0", ms=5, zorder=6)
    ax.plot(xp[-1] * scale, yp[-1] * scale, "s", color="C0", ms=5, zorder=6)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel(f"x [{unit}]")
    ax.set_ylabel(f"y [{unit}]")
    ax.set_title(
        f"{'line pusher' if line else 'finger'} (μp = {pusher.mu:g}) and body at "
        f"{n_poses} instants, light to dark",
        fontsize=10,
        y=1.0,
    )
    ax.grid(alpha=0.2)

    # ---- the layout from the shape of the plane panel
    box = ax.dataLim
    aspect = max(box.width, 1e-12) / max(box.height, 1e-12)
    wide = aspect >= WIDE_PATH
    top = 0.2 + 0.21 * (suptitle.count("\n") + 1) + 0.3
    n_handles = (
        5 + show_hull + len({str(m) for m in traj.mode}) + bool(traj.impacts) + 3
        + bool(np.any(np.asarray(traj.contact_slip_work) != 0.0))
        + bool(np.any(np.asarray(traj.impact_loss) != 0.0))
    )  # fmt: skip
    legend_h = 0.2 * math.ceil(n_handles / 5) + 0.1
    bottom = 0.55 + legend_h + 0.1
    left, gap, right = 0.85, 0.95, 0.25
    if wide:
        width = 12.0
        w_path = width - left - right
        h_path = min(max(w_path / aspect, 1.4), 3.6)
        h_time = 2.3
        height = top + h_path + 0.9 + h_time + bottom
        fig.set_size_inches(width, height)
        ax.set_position(_rect(fig, left, height - top - h_path, w_path, h_path))
        w_time = (width - left - right - gap) / 2
        rects = [_rect(fig, left + k * (w_time + gap), bottom, w_time, h_time) for k in range(2)]
    else:
        height = 7.4
        h_path = height - top - bottom
        w_path = min(max(h_path * aspect, 3.0), 6.8)
        w_time = 4.8
        width = left + w_path + gap + w_time + right
        fig.set_size_inches(width, height)
        ax.set_position(_rect(fig, left, bottom, w_path, h_path))
        hgap = 0.45
        h_time = (h_path - hgap) / 2
        x0 = left + w_path + gap
        rects = [
            _rect(fig, x0, bottom + (1 - k) * (h_time + hgap), w_time, h_time) for k in range(2)
        ]
    ax_f = fig.add_axes(rects[0])
    ax_e = fig.add_axes(rects[1], sharex=ax_f)

    # ---- the force, coloured by mode
    phases = _phases(traj)
    for k in range(t.size - 1):
        if traj.mode[k + 1] != traj.mode[k]:  # a switch at t[k+1]: held, then the jump
            if t[k + 1] > t[k]:
                ax_f.plot(
                    t[k : k + 2], [fmag[k], fmag[k]], color=mode_colour(traj.mode[k], seen),
                    lw=1.8, zorder=3,
                )  # fmt: skip
            ax_f.plot(
                [t[k + 1], t[k + 1]], fmag[k : k + 2], color=mode_colour(traj.mode[k + 1], seen),
                lw=1.0, zorder=3,
            )  # fmt: skip
        elif t[k + 1] > t[k]:
            ax_f.plot(
                t[k : k + 2], fmag[k : k + 2], color=mode_colour(traj.mode[k], seen), lw=1.8,
                zorder=3,
            )  # fmt: skip
    if t.size == 1:
        ax_f.plot(t, fmag, "o", color=mode_colour(traj.mode[0], seen), ms=3)
    for ti, lx, ly, _ in traj.impacts:
        ax_f.axvline(ti, color="k", lw=0.8, ls=":", zorder=2)
    ax_f.set_ylabel("|force| [N]")
    ax_f.set_ylim(bottom=0.0)
    ax_f.set_title("pusher's force on the body, coloured by contact mode", fontsize=10, y=1.0)

    # ---- the energy balance
    e_handles = []
    e_handles += ax_e.plot(t, traj.pusher_work, color="C3", lw=1.5, label="pusher work")
    e_handles += ax_e.plot(
        t, traj.friction_work, color="C5", lw=1.3, label="plane friction dissipation"
    )
    e_handles += ax_e.plot(t, traj.kinetic_energy, color="C0", lw=1.3, label="kinetic energy")
    if np.any(np.asarray(traj.contact_slip_work) != 0.0):
        e_handles += ax_e.plot(
            t, traj.contact_slip_work, color="C6", lw=1.2, ls="--", label="contact slip dissipation"
        )
    if np.any(np.asarray(traj.impact_loss) != 0.0):
        e_handles += ax_e.plot(
            t, traj.impact_loss, color="k", lw=1.0, ls=":", label="impact losses"
        )
    ax_e.set_ylabel("energy [J]")
    ax_e.set_title("energy balance", fontsize=10, y=1.0)
    for a in (ax_f, ax_e):
        draw_modes(a, phases, seen)
        a.grid(alpha=0.25)
        if t1 > t0:
            a.set_xlim(t0, t1)
        if wide:
            a.set_xlabel("t [s]")
    if not wide:
        ax_f.tick_params(labelbottom=False)
        ax_e.set_xlabel("t [s]")

    # ---- one legend below everything
    handles: list = [
        Line2D([], [], color="C0", lw=1.5, label="path of G (○ start, □ end)"),
        Line2D(
            [],
            [],
            color="C3",
            lw=1.0,
            ls="--",
            marker="D",
            ms=3.5,
            label="pusher's path, waypoints",
        ),
        Line2D(
            [],
            [],
            color="C3",
            lw=2.6 if line else 0,
            marker="" if line else "o",
            ms=5,
            label="line pusher" if line else "finger",
        ),  # fmt: skip
        Line2D([], [], color="k", lw=0, marker="x", ms=6, mew=1.4, label="contact point"),
        Line2D([], [], color="C3", lw=1.2, marker=">", ms=4, label="pusher's force"),
    ]
    if show_hull:
        handles.append(Line2D([], [], color="0.4", lw=0.8, ls=(0, (3, 2)), label="contact outline"))
    present = list(dict.fromkeys(m for m, _, _ in phases))
    handles += [
        Patch(
            facecolor=mode_colour(m, seen), alpha=0.5, edgecolor="none", label=m.replace("_", " ")
        )
        for m in present
    ]
    if traj.impacts:
        handles.append(Line2D([], [], color="k", lw=0.8, ls=":", label="plastic impact"))
    handles += e_handles
    fig.legend(
        handles=handles,
        loc="lower center",
        bbox_to_anchor=(0.5, 0.08 / height),
        ncols=5,
        fontsize=8,
        frameon=False,
    )
    fig.suptitle(suptitle, fontsize=11, y=1.0 - 0.12 / height, va="top")
    return fig
