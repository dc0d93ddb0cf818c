"""Phase portraits: v against a ω for many initial states, converging on the terminal ratio.

The picture behind Table 2 and eq. 14–16. Near the stop the direction of motion converges to
a fixed point (MODEL §5), so every trajectory in the (a ω, v) plane enters the origin along a
ray v = k a ω (a mixed ending), along the v-axis (ω/v → 0) or along the a ω-axis (v/ω → 0).
:func:`compute` draws the uniformly loaded disk under isotropic friction, for which the motion
stays in this plane, with one inertia ratio I* in each of the four intervals of Table 2; the
third panel (I* = 1/2) is the published case, k = 0.653. :func:`plot_phase_portrait` draws any
:class:`slidespin.analysis.phase_portrait.PhasePortrait`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from slidespin.analysis.intervals import inertia_intervals
from slidespin.analysis.phase_portrait import PhasePortrait, phase_portrait
from slidespin.contact.body import Body
from slidespin.contact.ellipse import Ellipse
from slidespin.contact.friction import FrictionTensor
from slidespin.contact.pressure import UniformPressure
from slidespin.paper import _figures as fg
from slidespin.paper import _shared as sh

__all__ = ["PhaseResult", "compute", "plot_phase_portrait", "plot", "main"]

FRICTION = FrictionTensor(0.3, 0.3)
RADIUS = 0.1  # [m]
SPEED = 1.0  # s0 = √(v0² + k² ω0²) [m/s]


@dataclass(frozen=True)
class PhaseResult:
    """Four phase portraits of the uniform disk, one per interval of Table 2."""

    intervals: tuple  # (I1, I2, I3) for the uniform law, μ = 0
    inertia_ratios: tuple
    portraits: tuple  # PhasePortrait objects

    def as_dict(self) -> dict:
        """The numbers as plain data (JSON-ready)."""
        panels: list[dict] = []
        out = {
            "law": "uniform",
            "friction": "isotropic",
            "intervals": list(self.intervals),
            "panels": panels,
        }
        for i_star, pp in zip(self.inertia_ratios, self.portraits):
            panels.append(
                {
                    "inertia_ratio": i_star,
                    "terminal": [s.as_dict() for s in pp.terminal if s.u[2] >= 0.0],
                    "beta_stop": [sh.num(x) for x in pp.beta_stop],
                    "endings": list(pp.endings),
                }
            )
        return out

    def to_text(self) -> str:
        """The numbers as a printed table."""
        i1, i2, i3 = self.intervals
        lines = [
            "Phase portraits: uniform disk, isotropic friction; "
            f"Table 2 boundaries I1 = {i1:.4f}, I2 = {i2:.4f}, I3 = {i3:.4f}",
            "I*       ending of every trajectory            k = v/(a omega) at the stop "
            "(min .. max)",
        ]
        for i_star, pp in zip(self.inertia_ratios, self.portraits):
            ends = sorted(set(pp.endings))
            fin = pp.beta_stop[np.isfinite(pp.beta_stop)]
            rng = f"{np.abs(fin).min():.6f} .. {np.abs(fin).max():.6f}" if fin.size else "inf"
            lines.append(f"{i_star:<8.4f} {', '.join(ends):<37} {rng}")
        return "\n".join(lines)


def compute(n: int = 11) -> PhaseResult:
    """Simulate ``n`` motions of the uniform disk for I* in each of the 4 intervals of Table 2."""
    bounds = tuple(inertia_intervals(UniformPressure(), FRICTION))
    i1, i2, i3 = bounds
    ratios = (0.6 * i1, 0.5 * (i1 + i2), 0.5, 1.5 * i3)  # the third is the published case
    portraits = []
    for i_star in ratios:
        body = Body.from_inertia_ratio(Ellipse(RADIUS, RADIUS), UniformPressure(), 1.0, i_star)
        portraits.append(phase_portrait(body, FRICTION, n=n, speed=SPEED))
    return PhaseResult(bounds, ratios, tuple(portraits))


def plot_phase_portrait(
    portrait: PhasePortrait, ax=None, *, color: str = "C0", legend: bool = True
):
    """Draw a phase portrait: trajectories in the (a ω, v) plane and the terminal rays.

    Parameters
    ----------
    portrait : PhasePortrait
        Result of :func:`slidespin.analysis.phase_portrait.phase_portrait`.
    ax : matplotlib Axes, optional
        Axes to draw on; a new figure is made if omitted.
    color : str
        Colour of the trajectories.
    legend : bool, default True
        Draw a legend on the axes.

    Returns
    -------
    matplotlib Axes
    """
    if ax is None:
        fig = sh.new_figure(4.0, 3.6)
        ax = fig.subplots()
    xmax = max(float(np.max(np.abs(s))) for s in portrait.spin)
    ymax = max(float(np.max(s)) for s in portrait.speed)
    for i, (spin, speed) in enumerate(zip(portrait.spin, portrait.speed)):
        ax.plot(spin, speed, color=color, lw=0.9, alpha=0.85)
        ax.plot(
            spin[:1],
            speed[:1],
            "o",
            color=color,
            ms=2.5,
            label="start (equal energy)" if i == 0 else None,
        )
    r = 1.05 * max(xmax, ymax)
    labelled = set()
    for s in portrait.terminal:
        if s.u[2] < 0.0 or (s.ending == "mixed" and s.beta_ratio < 0.0):
            continue
        style = {
            "color": "k" if s.stable else "0.55",
            "ls": "-" if s.stable else "--",
            "lw": 1.8 if s.stable else 1.0,
            "zorder": 4,
        }
        kind = "attracting" if s.stable else "repelling"
        if s.ending == "mixed":
            k = s.beta_ratio
            t = r / math.hypot(1.0, k)
            label = f"{kind}: v = {k:.3f} aω"
            ax.plot([0.0, t], [0.0, k * t], label=label, **style)
        elif s.ending == "pure_sliding":
            key = ("sliding", s.stable)
            if key in labelled:
                continue
            labelled.add(key)
            ax.plot([0.0, 0.0], [0.0, r], label=f"{kind}: ω/v → 0", **style)
        else:
            key = ("spinning", s.stable)
            if key in labelled:
                continue
            labelled.add(key)
            ax.plot([0.0, r], [0.0, 0.0], label=f"{kind}: v/ω → 0", **style)
    ax.set_xlim(-0.02 * xmax, 1.05 * xmax)
    ax.set_ylim(-0.02 * ymax, 1.05 * ymax)
    ax.set_xlabel("a ω [m/s]")
    ax.set_ylabel("v [m/s]")
    if legend:
        ax.legend(loc="upper right", fontsize=7, frameon=True, framealpha=0.9, edgecolor="none")
    return ax


_REGIME = ("I* < I₁", "I₁ < I* < I₂", "I₂ < I* < I₃", "I* > I₃")


def _ending_text(pp):
    stable = [s for s in pp.terminal if s.stable and s.u[2] >= 0.0]
    s = stable[0]
    if s.ending == "mixed":
        return f"v → {abs(s.beta_ratio):.3f} aω"
    return "ω/v → 0" if s.ending == "pure_sliding" else "v/ω → 0"


def plot(result: PhaseResult):
    """The four phase portraits in a 2 × 2 figure."""
    # lazy: matplotlib is slow to import and needed only to draw
    from matplotlib.lines import Line2D

    with sh.style():
        fig = sh.new_figure(7.4, 7.0)
        axes = fig.subplots(2, 2).ravel()
        for ax, i_star, pp, regime in zip(axes, result.inertia_ratios, result.portraits, _REGIME):
            plot_phase_portrait(pp, ax, legend=False)
            ax.set_title(f"I* = {i_star:.3g} ({regime}): {_ending_text(pp)}")
        i1, i2, i3 = result.intervals
        n = len(result.portraits[0].spin)
        fig.suptitle(
            f"Uniform disk, isotropic friction: v against aω from {n} starts of equal energy "
            f"(I₁ = {i1:.3g}, I₂ = {i2:.3g}, I₃ = {i3:.3g})",
            fontsize=9.5,
        )
        handles = [
            Line2D([], [], color="C0", lw=0.9, marker="o", ms=2.5, label="motion from its start"),
            Line2D([], [], color="k", lw=1.8, label="attracting terminal motion"),
            Line2D([], [], color="0.55", lw=1.0, ls="--", label="repelling terminal motion"),
        ]
        fig.legend(handles=handles, loc="outside lower center", ncol=3, fontsize=8)
    return fig


def main(out=None, *, as_json: bool = False, fmt: str = "png", stream=None) -> PhaseResult:
    """Print the endings and write ``phase.<fmt>`` (and phase.json) into ``out``."""
    return fg.main_figure("phase", lambda: compute(), plot, out, as_json, fmt, stream)


if __name__ == "__main__":  # pragma: no cover
    main()
