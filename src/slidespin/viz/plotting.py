"""Figures (matplotlib is imported lazily, only by the functions that draw).

Every function takes data objects (a :class:`~slidespin.Trajectory`), draws on the axes it is
given or creates a figure, and returns the figure; nothing here computes physics.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from matplotlib.artist import Artist

__all__ = [
    "plot_trajectory",
    "plot_loaded_trajectory",
    "outline_world",
    "draw_path",
    "draw_beta",
    "draw_angle",
    "draw_stick",
    "applied_load_history",
    "plot_sweep",
    "axis_label",
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


def _plt():
    import matplotlib

    if matplotlib.get_backend().lower() not in ("agg", "module://matplotlib_inline.backend_inline"):
        try:
            import matplotlib.pyplot as plt  # noqa: F401
        except Exception:  # pragma: no cover - headless fallback
            matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


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
    :class:`~slidespin.Trajectory` or a :class:`~slidespin.motion.loaded.LoadedTrajectory` (any
    object with arrays ``t, x, y, phi`` and a ``body``); ``end_label`` names the marker of
    the last point. Lengths are in cm when the drawn extent (path and patch) is below 1 m,
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
        Result of :func:`slidespin.motion.simulate`. A loaded run (with ``phases``) is drawn by
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
    from slidespin.motion.loads import applied_wrench

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
        Result of :func:`slidespin.motion.simulate` with a load, a slope or ``t_end``
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
    from matplotlib.patches import Patch

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
        Column name → array, as returned by :func:`slidespin.studies.sweep.read_sweep` (with
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
    kind : {"grid", "random"}, optional
        The sweep's kind (from its manifest); by default guessed from the data.
    left_out : ignored
        Kept for callers of an earlier version.

    Returns
    -------
    matplotlib.figure.Figure
    """
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    from slidespin.motion.outcomes import FLAGGED, LOADED_UNCONVERGED, UNCONVERGED

    plt = _plt()
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
    fig, ax = plt.subplots(figsize=(6.4, 4.8), layout="constrained")
    cmap_cat = None
    if vcats is not None:
        from matplotlib.colors import BoundaryNorm, ListedColormap

        base = plt.get_cmap("tab10")
        cmap_cat = ListedColormap([base(i % 10) for i in range(len(vcats))])
        norm_cat = BoundaryNorm(np.arange(len(vcats) + 1) - 0.5, len(vcats))
    handles: list[Artist] = []

    if y is None:
        if kind is None:
            kind = "grid"
        others = _independent_axes(table, x, varied) if varied is not None else []
        if kind == "random":
            ax.plot(xs[finite], vs[finite], "o", ms=2.5, alpha=0.6, lw=0)
            others_txt = ", ".join(k.replace("_", " ") for k in (varied or []) if k != x)
            if not title:
                title = "each dot one case" + (f"; also varied: {others_txt}" if others_txt else "")
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
            colors = plt.get_cmap("viridis")(np.linspace(0.0, 0.9, kvals.size))
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
            per_cell = n_all // (ux.size * uy.size)
            if per_cell > 1 and not title:
                what = "most frequent" if vcats is not None else "mean"
                title = f"{axis_label(value)}: {what} of {per_cell} cases per cell"
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
            bx, by = xs_all[bad], ys_all[bad]
            fl = flagged & keep
            fx_, fy_ = xs_all[fl], ys_all[fl]
            on_grid = False
            blank = np.array([not finite.all()])
        if on_grid:
            bx, by = ux[bx], uy[by]
            fx_, fy_ = ux[fx_], uy[fy_]
        import matplotlib.patheffects as pe

        halo = [pe.withStroke(linewidth=2.6, foreground="w")]  # visible on any colour
        if len(bx):
            ax.plot(bx, by, "x", color="k", ms=5, mew=1.1, lw=0, path_effects=halo)
        if len(fx_):
            ax.plot(fx_, fy_, "o", ms=5, mfc="none", mec="C3", mew=1.1, lw=0, path_effects=halo)
        if vcats is None:
            fig.colorbar(mesh, ax=ax, label=axis_label(value))
        else:
            cb = fig.colorbar(mesh, ax=ax, label=axis_label(value), ticks=np.arange(len(vcats)))
            cb.ax.set_yticklabels([c.replace("_", " ") for c in vcats])
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
    if handles:  # below the axes, outside them: the layout makes room (no overlap)
        fig.legend(handles=handles, loc="outside lower left", fontsize=7, frameon=False)
    if title:
        import textwrap

        ax.set_title(textwrap.fill(title, 72), fontsize=9)
    return fig
