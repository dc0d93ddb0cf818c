"""Figures (matplotlib is imported lazily, only by the functions that draw).

Every function takes data objects (a :class:`~slidespin.Trajectory`), draws on the axes it is
given or creates a figure, and returns the figure; nothing here computes physics.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["plot_trajectory", "outline_world", "draw_path"]


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
    """Patch outline in the fixed frame with G at (x, y) and body angle φ; shape (n, 2) [m]."""
    pts = body.patch.outline(n) - np.asarray(body.mass_centre)
    c, s = math.cos(phi), math.sin(phi)
    return np.column_stack((x + c * pts[:, 0] - s * pts[:, 1], y + s * pts[:, 0] + c * pts[:, 1]))


def draw_path(ax, traj, n_outlines: int = 9, color: str = "C0", label: str | None = "path of G"):
    """Path of the mass centre with the patch outline drawn along it.

    The outlines are spaced evenly in the amount of motion (distance travelled by G plus
    a times the angle turned), so that they spread over the whole path rather than crowd
    where the body is slow; their shade darkens with time.
    """
    scale, unit = (1e2, "cm") if traj.body.patch.a < 0.5 else (1.0, "m")
    ax.plot(traj.x * scale, traj.y * scale, color=color, lw=1.6, label=label, zorder=3)
    a = traj.body.patch.a
    progress = traj.path_length + a * np.concatenate(([0.0], np.cumsum(np.abs(np.diff(traj.phi)))))
    if progress[-1] > 0.0:
        times = np.interp(np.linspace(0.0, progress[-1], n_outlines), progress, traj.t)
    else:
        times = np.linspace(0.0, traj.t_stop, n_outlines)
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
        a = traj.body.patch.a * scale
        ax.plot([xi * scale, xi * scale + a * c], [yi * scale, yi * scale + a * s],
                color=shade, lw=0.9, zorder=2)
    ax.plot(traj.x[0] * scale, traj.y[0] * scale, "o", color=color, ms=5, zorder=4, label="start")
    ax.plot(traj.x[-1] * scale, traj.y[-1] * scale, "s", color="C3", ms=5, zorder=4, label="stop")
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel(f"x [{unit}]")
    ax.set_ylabel(f"y [{unit}]")
    return ax


def plot_trajectory(traj, title: str | None = None, n_outlines: int = 9):
    """Four-panel summary of a trajectory: path with outlines, β(t) and ϑ(t), v(t) and ω(t).

    Parameters
    ----------
    traj : Trajectory
        Result of :func:`slidespin.simulate`.
    title : str, optional
        Figure title.
    n_outlines : int
        Number of patch outlines drawn along the path (equal time intervals).

    Returns
    -------
    matplotlib.figure.Figure
    """
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
    a = traj.body.patch.a
    beta = np.clip(traj.beta / a, -1e3, 1e3)
    ax_beta.plot(t, beta, color="C0")
    if math.isfinite(traj.beta_stop):
        ax_beta.axhline(traj.beta_stop / a, color="0.5", lw=0.8, ls="--",
                        label=f"β*/a = {traj.beta_stop / a:.4f}")
        ax_beta.legend(fontsize=8, frameon=False)
    ax_beta.set_ylabel("β/a = v/(aω)")
    ax_beta.set_title("distance to the centre of rotation", fontsize=10)

    ax_theta.plot(t, traj.theta, color="C1")
    ax_theta.axhline(traj.theta_stop, color="0.5", lw=0.8, ls="--",
                     label=f"ϑ* = {traj.theta_stop:.4f} rad")
    ax_theta.legend(fontsize=8, frameon=False)
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


_LABELS = {
    "a": "a [m]", "b": "b [m]", "fx": "f_x", "fy": "f_y", "f": "f (skew)", "mu": "μ = f_y − f_x",
    "I_star": "I* = I/(m a²)", "moment_of_inertia": "I [kg m²]", "mass": "m [kg]",
    "angle": "tensor angle [rad]", "v0": "v₀ [m/s]", "omega0": "ω₀ [rad/s]",
    "theta0": "ϑ₀ [rad]", "phi0": "φ₀ [rad]", "t_stop": "stop time [s]",
    "beta_stop": "β* [m]", "theta_stop": "ϑ* [rad]", "phi_stop": "φ at the stop [rad]",
    "x_stop": "x at the stop [m]", "aspect": "b/a", "e": "eccentricity", "y_stop": "y at the stop [m]",
    "path_length": "distance travelled [m]", "n_steps": "integrator steps", "g": "g [m/s²]",
}


def axis_label(name: str) -> str:
    """Readable axis label with units for a sweep column."""
    return _LABELS.get(name, name)


def plot_sweep(table: dict, x: str, value: str, y: str | None = None, title: str | None = None):
    """Heat map of ``value`` over (``x``, ``y``), or a line plot of ``value`` against ``x``.

    Parameters
    ----------
    table : dict
        Column name → array, as returned by :func:`slidespin.sweep.read_sweep`.
    x, y : str
        Input columns for the axes (``y`` optional).
    value : str
        Result column shown (colour or ordinate). Infinite values (pure-sliding β*) are
        left blank.

    Returns
    -------
    matplotlib.figure.Figure
    """
    plt = _plt()
    for name in (x, value) + ((y,) if y else ()):
        if name not in table:
            raise ValueError(f"column {name!r} is not in the sweep; valid: {', '.join(table)}")
    xs = np.asarray(table[x], dtype=float)
    vs = np.asarray(table[value], dtype=float)
    fig, ax = plt.subplots(figsize=(6.4, 4.8), layout="constrained")
    finite = np.isfinite(vs)
    if y is None:
        order = np.argsort(xs, kind="stable")
        ax.plot(xs[order][finite[order]], vs[order][finite[order]], "o-", ms=3, lw=1.2)
        ax.set_ylabel(axis_label(value))
        ax.grid(alpha=0.3)
    else:
        ys = np.asarray(table[y], dtype=float)
        ux, uy = np.unique(xs), np.unique(ys)
        if ux.size > 1 and uy.size > 1 and ux.size * uy.size <= xs.size:
            # a grid: average the finite values falling in each (x, y) cell
            ix, iy = np.searchsorted(ux, xs), np.searchsorted(uy, ys)
            total = np.zeros((uy.size, ux.size))
            count = np.zeros((uy.size, ux.size))
            np.add.at(total, (iy[finite], ix[finite]), vs[finite])
            np.add.at(count, (iy[finite], ix[finite]), 1.0)
            with np.errstate(invalid="ignore"):
                grid = total / count
            mesh = ax.pcolormesh(ux, uy, grid, shading="nearest", cmap="viridis")
            per_cell = xs.size // (ux.size * uy.size)
            if per_cell > 1 and not title:
                title = f"{axis_label(value)}: mean of {per_cell} cases per cell"
        else:
            mesh = ax.scatter(xs[finite], ys[finite], c=vs[finite], s=12, cmap="viridis")
        fig.colorbar(mesh, ax=ax, label=axis_label(value))
        ax.set_ylabel(axis_label(y))
        if not finite.all():
            fig.text(0.01, 0.005, f"blank cells: {axis_label(value)} not finite "
                     "(β* = ∞: pure sliding; NaN: no terminal direction, a spiral stop)",
                     fontsize=7, color="0.3", va="bottom")
    ax.set_xlabel(axis_label(x))
    if title:
        ax.set_title(title, fontsize=10)
    return fig
