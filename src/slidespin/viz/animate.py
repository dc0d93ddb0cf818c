"""Animations: the footprint sliding and turning along its path, written as a GIF.

:func:`animate` draws, frame by frame, the outline of the contact patch (or footprint) at
the body's position and angle, the path of the mass centre G, the velocity of G as an arrow
and the instantaneous centre of rotation (ICR) as a marker, and writes an animated GIF with
Pillow (:class:`matplotlib.animation.PillowWriter`: no ffmpeg is needed). Frames are spaced
evenly in time from the first recorded instant to the last one (the stop, for a
:class:`~slidespin.Trajectory`), at most :data:`MAX_FRAMES` of them, so a GIF stays small
(the demo: about 0.2 MB).

:func:`frame_states` gives the states drawn, for use in other figures: the positions and the
angle are interpolated between the integrator's steps by cubic Hermite polynomials on the
recorded velocities (ẋ = vx, ẏ = vy, φ̇ = ω), the velocities linearly. Any object with arrays
``t, x, y, phi, vx, vy, omega`` and a ``body`` works (:class:`~slidespin.Trajectory`,
:class:`~slidespin.motion.loaded_trajectory.LoadedTrajectory`,
:class:`~slidespin.motion.pushed_trajectory.PushedTrajectory`; a pushed run's steps across a
change of contact mode, whose end row already holds the velocity after the switch, are
interpolated linearly).

A pushed run (:class:`~slidespin.motion.pushed_trajectory.PushedTrajectory`, MODEL §13) also
shows its pusher in every frame: a finger as a dot, a line pusher as a segment, with the
pusher's path dashed.

Geometry (MODEL §1-2): a point r = (ξ, η) of the body frame is drawn at
G + R(φ)(r − r_G) with r_G = ``body.mass_centre``; the ICR, where the velocity of the body
point vanishes, is at G + (−vy, vx)/ω (drawn only while it lies inside the view).
"""

from __future__ import annotations

import math
import os
from typing import Any, NamedTuple

import numpy as np

from slidespin._io import check_output_path, write_failure

__all__ = ["MAX_FPS", "MAX_FRAMES", "FrameStates", "animate", "frame_states"]

#: the most frames a GIF may have (keeps the file small and the writing quick)
MAX_FRAMES = 120
#: the highest frame rate accepted (GIF delays are whole hundredths of a second)
MAX_FPS = 50


class FrameStates(NamedTuple):
    """States at the frames of an animation (SI units, arrays of one length)."""

    t: np.ndarray
    x: np.ndarray
    y: np.ndarray
    phi: np.ndarray
    vx: np.ndarray
    vy: np.ndarray
    omega: np.ndarray


def _check_int(name: str, value: Any, lo: int, hi: int) -> int:
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or not lo <= value <= hi:
        raise ValueError(f"{name} = {value!r} is invalid; valid range: integer in [{lo}, {hi}]")
    return int(value)


def _arrays(trajectory) -> dict:
    names = ("t", "x", "y", "phi", "vx", "vy", "omega")
    try:
        cols = {k: np.asarray(getattr(trajectory, k), dtype=float) for k in names}
        body = trajectory.body
    except (AttributeError, TypeError, ValueError):
        raise ValueError(
            f"trajectory = {type(trajectory).__name__} is invalid; valid values: a Trajectory "
            "or LoadedTrajectory (arrays t, x, y, phi, vx, vy, omega and a body)"
        ) from None
    n = cols["t"].size
    if n < 1 or any(c.ndim != 1 or c.size != n for c in cols.values()):
        raise ValueError(
            "trajectory is invalid: its arrays t, x, y, phi, vx, vy, omega must be "
            "one-dimensional, non-empty and of one length"
        )
    if not all(np.all(np.isfinite(c)) for c in cols.values()):
        raise ValueError(
            "trajectory is invalid: it holds non-finite values (status "
            f"{getattr(trajectory, 'status', '?')!r}); only finite motions can be "
            "drawn"
        )
    if np.any(np.diff(cols["t"]) < 0):
        raise ValueError("trajectory is invalid: its times t decrease")
    cols["body"] = body
    return cols


def _hermite(
    t: np.ndarray,
    y: np.ndarray,
    dy: np.ndarray,
    tq: np.ndarray,
    linear: np.ndarray | None = None,
) -> np.ndarray:
    """Cubic Hermite interpolation of y (slopes dy) at tq; zero-length steps give y[i].

    ``linear`` (one bool per step) marks the steps interpolated linearly instead: a pushed
    run's step whose end row already holds the velocity after a mode switch or an impact
    (the slope there is not the step's)."""
    if t.size == 1:
        return np.full(tq.shape, y[0])
    i = np.clip(np.searchsorted(t, tq, side="right") - 1, 0, t.size - 2)
    h = t[i + 1] - t[i]
    with np.errstate(divide="ignore", invalid="ignore"):
        s = np.where(h > 0, (tq - t[i]) / np.where(h > 0, h, 1.0), 0.0)
    s = np.clip(s, 0.0, 1.0)
    h00 = (1 + 2 * s) * (1 - s) ** 2
    h10 = s * (1 - s) ** 2
    h01 = s * s * (3 - 2 * s)
    h11 = s * s * (s - 1)
    out = h00 * y[i] + h10 * h * dy[i] + h01 * y[i + 1] + h11 * h * dy[i + 1]
    if linear is not None:
        lin = linear[i]
        out = np.where(lin, (1.0 - s) * y[i] + s * y[i + 1], out)
    return out


def _switch_steps(trajectory, n: int) -> np.ndarray | None:
    """The steps of a pushed run (rows with a ``mode``) whose two rows differ in mode: there
    the end row holds the velocity after the switch, so the step is interpolated linearly."""
    mode = getattr(trajectory, "mode", None)
    if mode is None or isinstance(mode, str) or len(mode) != n or n < 2:
        return None
    m = np.asarray(mode)
    return m[1:] != m[:-1]


def _linear(t: np.ndarray, y: np.ndarray, tq: np.ndarray) -> np.ndarray:
    if t.size == 1:
        return np.full(tq.shape, y[0])
    return np.interp(tq, t, y)


def frame_states(trajectory, frames: int = 60) -> FrameStates:
    """States at ``frames`` instants spaced evenly from the first recorded time to the last.

    Parameters
    ----------
    trajectory : Trajectory or LoadedTrajectory
        A simulated motion (arrays ``t, x, y, phi, vx, vy, omega``).
    frames : int
        Number of instants, in [2, :data:`MAX_FRAMES`].

    Returns
    -------
    FrameStates
        ``t`` [s], ``x``, ``y`` [m] (G, fixed frame), ``phi`` [rad], ``vx``, ``vy`` [m/s],
        ``omega`` [rad/s]. Positions and angle are cubic Hermite interpolants on the recorded
        velocities (third-order accurate in the step; the recorded points are reproduced
        exactly); velocities are interpolated linearly.
    """
    frames = _check_int("frames", frames, 2, MAX_FRAMES)
    c = _arrays(trajectory)
    t = c["t"]
    tq = np.linspace(t[0], t[-1], frames)
    lin = _switch_steps(trajectory, t.size)
    return FrameStates(
        t=tq,
        x=_hermite(t, c["x"], c["vx"], tq, lin),
        y=_hermite(t, c["y"], c["vy"], tq, lin),
        phi=_hermite(t, c["phi"], c["omega"], tq, lin),
        vx=_linear(t, c["vx"], tq),
        vy=_linear(t, c["vy"], tq),
        omega=_linear(t, c["omega"], tq),
    )


def _outlines(patch) -> list[np.ndarray]:
    """Closed body-frame outlines (ξ, η) [m] of an ellipse, circle or footprint."""
    if hasattr(patch, "outlines"):
        return [np.asarray(o, dtype=float) for o in patch.outlines()]
    return [np.asarray(patch.outline(121), dtype=float)]


def _extent(outlines: list[np.ndarray], centre: np.ndarray) -> float:
    return float(max(np.max(np.hypot(*(o - centre).T)) for o in outlines))


def _to_world(pts: np.ndarray, centre: np.ndarray, x: float, y: float, phi: float) -> np.ndarray:
    p = pts - centre
    c, s = math.cos(phi), math.sin(phi)
    return np.column_stack((x + c * p[:, 0] - s * p[:, 1], y + s * p[:, 0] + c * p[:, 1]))


def _pusher_frames(trajectory, t: np.ndarray) -> np.ndarray | None:
    """The pusher of a pushed run at the frame times: (frames, 1, 2) for a finger, (frames, 2,
    2) for a line pusher's two ends [m]; None for a run without a pusher."""
    pusher = getattr(trajectory, "pusher", None)
    if pusher is None:
        return None
    if hasattr(pusher, "ends"):
        return np.asarray(pusher.ends(t), dtype=float).reshape(t.size, 2, 2)
    return np.asarray(pusher.position(t), dtype=float).reshape(t.size, 1, 2)


def animate(
    trajectory,
    path,
    fps: int = 20,
    frames: int = 60,
    *,
    dpi: int = 80,
    figsize: tuple[float, float] = (4.8, 4.0),
    title: str | None = None,
) -> str:
    """Write an animated GIF of the body sliding and turning along its path.

    Each frame shows the outline of the patch (or footprint) at the body's position and
    angle, a body-fixed radius from G along ξ (so that the spin of a disk shows), the path
    of G, the velocity of G as an arrow, the ICR as a cross while it lies in the view, and
    the time.

    Parameters
    ----------
    trajectory : Trajectory or LoadedTrajectory
        The motion to draw, e.g. from :func:`slidespin.simulate`.
    path : str or os.PathLike
        Output file; must end in ``.gif``. Written whole or not at all (a temporary file in
        the same directory is renamed into place).
    fps : int
        Frames per second of the GIF, in [1, :data:`MAX_FPS`]. The animation is slowed down
        or sped up so that ``frames`` frames span the motion: it lasts ``frames / fps`` s.
    frames : int
        Number of frames, in [2, :data:`MAX_FRAMES`], spaced evenly in time from the start
        to the last recorded instant (:func:`frame_states`). Pillow merges identical
        consecutive frames, so a body that never moves gives a one-frame GIF.
    dpi : int
        Resolution [dots per inch], in [20, 300].
    figsize : (float, float)
        Figure size [inch].
    title : str or None
        Title drawn above the axes.

    Returns
    -------
    str
        The path written.

    Raises
    ------
    ValueError
        For a bad ``path`` (not ``.gif``, a directory, an unwritable place), ``fps``,
        ``frames``, ``dpi`` or trajectory, before anything is drawn or written.

    Examples
    --------
    >>> import slidespin as ss                                    # doctest: +SKIP
    >>> from slidespin.viz.animate import animate                     # doctest: +SKIP
    >>> traj = ss.simulate(body, friction, start)                 # doctest: +SKIP
    >>> animate(traj, "run.gif", fps=20, frames=60)               # doctest: +SKIP
    'run.gif'
    """
    if not isinstance(path, (str, os.PathLike)):
        raise ValueError(
            f"path = {path!r} ({type(path).__name__}) is invalid; valid values: "
            "a str or os.PathLike file path ending in .gif"
        )
    path = os.fspath(path)
    if not isinstance(path, str) or not path.lower().endswith(".gif"):
        raise ValueError(f"path = {path!r} is invalid; valid values: a file path ending in .gif")
    check_output_path(path, "path")
    fps = _check_int("fps", fps, 1, MAX_FPS)
    frames = _check_int("frames", frames, 2, MAX_FRAMES)
    dpi = _check_int("dpi", dpi, 20, 300)
    st = frame_states(trajectory, frames)
    body = trajectory.body

    # a bare Figure (no pyplot): no window, no global state, any backend
    # lazy: matplotlib (and Pillow, through PillowWriter) are imported only to draw
    from matplotlib.animation import FuncAnimation, PillowWriter
    from matplotlib.figure import Figure

    centre = np.asarray(body.mass_centre, dtype=float)
    outlines = _outlines(body.patch)
    ext = _extent(outlines, centre)
    pusher = _pusher_frames(trajectory, st.t)
    # view: every frame's outline (and the pusher of a pushed run) plus a margin
    xs = np.concatenate(
        [st.x - ext, st.x + ext] + ([pusher[..., 0].ravel()] if pusher is not None else [])
    )
    ys = np.concatenate(
        [st.y - ext, st.y + ext] + ([pusher[..., 1].ravel()] if pusher is not None else [])
    )
    x0, x1, y0, y1 = xs.min(), xs.max(), ys.min(), ys.max()
    span = max(x1 - x0, y1 - y0)
    margin = 0.08 * span
    x0, x1, y0, y1 = x0 - margin, x1 + margin, y0 - margin, y1 + margin
    speed = np.hypot(st.vx, st.vy)
    vmax = float(speed.max())
    # the fastest arrow is a quarter of the view
    scale = 0.25 * span / vmax if vmax > 0 else 0.0

    fig = Figure(figsize=figsize, dpi=dpi)
    ax = fig.add_subplot()
    ax.set_aspect("equal")
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    if title:
        ax.set_title(title, fontsize=9, y=1.0)
    ax.plot(st.x, st.y, color="0.6", lw=0.8, zorder=1)
    lines = [ax.plot([], [], color="C0", lw=1.6, zorder=3)[0] for _ in outlines]
    radius_line = ax.plot([], [], color="C0", lw=1.0, zorder=3)[0]
    g_dot = ax.plot([], [], "o", color="C0", ms=3, zorder=4)[0]
    icr = ax.plot([], [], "x", color="C3", ms=7, mew=1.8, zorder=4, label="ICR")[0]
    arrow = ax.quiver(
        [st.x[0]],
        [st.y[0]],
        [0.0],
        [0.0],
        angles="xy",
        scale_units="xy",
        scale=1.0,
        color="C1",
        width=0.006,
        zorder=5,
        label="velocity of G",
    )
    text = ax.text(0.02, 0.97, "", transform=ax.transAxes, va="top", fontsize=8)
    push_line = None
    pushed_at = pusher if pusher is not None else np.zeros((0, 1, 2))
    if pusher is not None:  # a finger (a dot) or a line pusher (a segment), and its path
        ax.plot(
            pusher[:, :, 0].mean(axis=1), pusher[:, :, 1].mean(axis=1), color="C3", lw=0.8,
            ls="--", zorder=1,
        )  # fmt: skip
        style = "o-" if pusher.shape[1] == 1 else "-"
        push_line = ax.plot([], [], style, color="C3", lw=3.0, ms=6, zorder=6, label="pusher")[0]
    ax.legend(loc="lower right", fontsize=7, frameon=False)
    fig.tight_layout()
    xi_tip = centre + np.array([ext, 0.0])

    def draw(k: int):
        x, y, phi = st.x[k], st.y[k], st.phi[k]
        for line, o in zip(lines, outlines):
            w = _to_world(o, centre, x, y, phi)
            line.set_data(w[:, 0], w[:, 1])
        tip = _to_world(xi_tip[None, :], centre, x, y, phi)[0]
        radius_line.set_data([x, tip[0]], [y, tip[1]])
        g_dot.set_data([x], [y])
        arrow.set_offsets([[x, y]])
        arrow.set_UVC(st.vx[k] * scale, st.vy[k] * scale)
        om = st.omega[k]
        ix = iy = math.nan
        if om != 0.0:
            ix, iy = x - st.vy[k] / om, y + st.vx[k] / om
        if x0 <= ix <= x1 and y0 <= iy <= y1:
            icr.set_data([ix], [iy])
        else:
            icr.set_data([], [])
        text.set_text(f"t = {st.t[k]:.4f} s   v = {speed[k]:.3g} m/s   ω = {om:.3g} rad/s")
        if push_line is not None:
            push_line.set_data(pushed_at[k, :, 0], pushed_at[k, :, 1])
            return lines + [radius_line, g_dot, icr, arrow, text, push_line]
        return lines + [radius_line, g_dot, icr, arrow, text]

    anim = FuncAnimation(fig, draw, frames=frames, blit=False, repeat=False)
    parent = os.path.dirname(os.path.abspath(path))
    tmp = os.path.join(parent, f".{os.path.basename(path)}.tmp-{os.getpid()}.gif")
    try:
        anim.save(tmp, writer=PillowWriter(fps=fps), dpi=dpi)
        os.replace(tmp, path)
    except OSError as exc:
        raise ValueError(write_failure(exc, path)) from None
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)
    return path
