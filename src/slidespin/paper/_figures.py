"""Shared machinery of Figures 2–4: the paper's three runs and their plots (not public API).

The runs (paper §3, MODEL §6): e = 0.866, I* = (1 + κ²)/4, plane-fixed friction fx,
fy = fx + μ, f = 0; v₀ = ω₀ = 1 and ϑ₀ = π/4 in the paper's units (eq. 7), φ₀ = π/4, π/3, π/2.
The paper prints neither fx nor μ for its figures: fx is the value inferred from Table 1 and
μ defaults to 0.12.
"""

from __future__ import annotations

import json
import os
from dataclasses import dataclass
from functools import lru_cache

from slidespin import _validate as v
from slidespin.contact.friction import FrictionTensor
from slidespin.motion.simulate import simulate
from slidespin.motion.state import State
from slidespin.paper import _shared as sh
from slidespin.paper.table1 import infer_fx
from slidespin.viz.trajectory_plot import draw_path

DEFAULT_MU = 0.12


@dataclass(frozen=True)
class FigureRuns:
    """The three runs of a figure (``runs[i]`` starts at φ₀ = PHI0[i])."""

    name: str
    law: str
    fx: float
    mu: float
    runs: tuple  # Trajectory objects (SI units, a = 1 m, g = 9.81 m/s²)

    def summary(self) -> list:
        rows = []
        for phi0, lab, tr in zip(sh.PHI0, sh.PHI_LABELS, self.runs):
            rows.append(
                {
                    "phi0": phi0,
                    "phi0_label": lab,
                    "t_stop": tr.t_stop / sh.TIME_UNIT,  # paper units
                    "beta_stop": sh.num(tr.beta_stop / sh.A),
                    "theta_stop": sh.num(tr.theta_stop),
                    "phi_stop": tr.stop_state.phi,
                    "ending": tr.ending,
                    "status": tr.status,
                    "normal_stop": tr.normal[-1] / (sh.MASS * sh.G),
                }
            )
        return rows

    def as_dict(self) -> dict:
        return {
            "figure": self.name,
            "law": self.law,
            "fx": self.fx,
            "mu": self.mu,
            "units": "paper units (eq. 7): t in sqrt(a pi/g), beta in a",
            "runs": self.summary(),
        }

    def to_text(self) -> str:
        lines = [
            f"{self.name}: {self.law} pressure, e = 0.866, fx = {self.fx:.5f}, "
            f"mu = {self.mu:g}, v0 = omega0 = 1, theta0 = pi/4 (paper units)",
            "phi0    t_stop    beta*/a    theta* [rad]   phi_stop [rad]  ending",
        ]
        for r in self.summary():
            lines.append(
                f"{r['phi0_label']:<7} {r['t_stop']:<9.5f} {float(r['beta_stop']):<10.6f} "
                f"{float(r['theta_stop']):<+14.6f} {r['phi_stop']:<15.6f} {r['ending']}"
            )
        lines.append("(times in sqrt(a pi/g); beta measured from the mass centre G)")
        return "\n".join(lines)


def resolve_fx(fx):
    """fx from Table 1's least-squares fit unless given."""
    if fx is None:
        return infer_fx().fx
    return v.positive("fx", fx)


def run_figure(name: str, body, law: str, mu: float, fx) -> FigureRuns:
    """Simulate the paper's three runs for ``body`` (SI units, a = 1 m)."""
    fx = resolve_fx(fx)
    mu = v.finite("mu", mu)
    if fx + mu <= 0.0:
        raise ValueError(f"mu = {mu!r} is invalid; valid range: > -fx = {-fx:.5g} (fy > 0)")
    return FigureRuns(name, law, fx, mu, _runs(body, fx, mu))


@lru_cache(maxsize=8)
def _runs(body, fx, mu):
    fr = FrictionTensor(fx, fx + mu)
    runs = []
    for phi0 in sh.PHI0:
        st = State.from_speed(sh.SPEED_UNIT, sh.SPIN_UNIT, sh.THETA0, phi0)
        # max_step (in the regularised time) only densifies the records for smooth curves
        runs.append(simulate(body, fr, st, g=sh.G, max_step=0.05))
    return tuple(runs)


def _time(tr):
    return tr.t / sh.TIME_UNIT


def _path_panels(fig, gs, row, res):
    axes = []
    for i, (lab, tr) in enumerate(zip(sh.PHI_LABELS, res.runs)):
        ax = fig.add_subplot(gs[row, 2 * i : 2 * i + 2])
        draw_path(ax, tr, n_outlines=6, color=sh.PHI_COLORS[i], label=None)
        if i == 0:
            ax.legend(loc="lower right", fontsize=7, handlelength=1.0)
        ax.set_xlabel("x/a")
        ax.set_ylabel("y/a")
        ax.set_title(f"path, φ₀ = {lab}", fontsize=9)
        ax.grid(alpha=0.2)
        axes.append(ax)
    return axes


def plot_beta_theta(res: FigureRuns, title: str):
    """β(t) and ϑ(t) of the three runs (paper units), with the paths below."""
    with sh.style():
        fig = sh.new_figure(7.6, 6.4)
        gs = fig.add_gridspec(2, 6, height_ratios=[1.0, 0.9])
        ax_b = fig.add_subplot(gs[0, :3])
        ax_t = fig.add_subplot(gs[0, 3:])
        for i, (lab, tr) in enumerate(zip(sh.PHI_LABELS, res.runs)):
            c = sh.PHI_COLORS[i]
            t = _time(tr)
            ax_b.plot(
                t, tr.beta / sh.A, color=c, label=f"φ₀ = {lab}: β* = {tr.beta_stop / sh.A:.3f} a"
            )
            ax_b.axhline(tr.beta_stop / sh.A, color=c, ls="--", lw=0.8)
            ax_t.plot(t, tr.theta, color=c, label=f"φ₀ = {lab}: ϑ* = {tr.theta_stop:+.3f} rad")
            ax_t.plot([t[-1]], [tr.theta_stop], "o", color=c, ms=4)
        ax_t.axhline(0.0, color="0.5", lw=0.8, zorder=0)
        ax_b.set_xlabel("t / √(aπ/g)")
        ax_b.set_ylabel("β/a = v/(aω)")
        ax_b.set_title("distance from G to the centre of rotation")
        ax_b.legend(loc="best")
        ax_t.set_xlabel("t / √(aπ/g)")
        ax_t.set_ylabel("ϑ [rad]")
        ax_t.set_title("direction of the velocity of G")
        ax_t.legend(loc="best")
        _path_panels(fig, gs, 1, res)
        fig.suptitle(title, fontsize=10)
    return fig


def plot_normal(res: FigureRuns, title: str):
    """F_n(t)/(m g) of the three runs (paper units), with the paths below."""
    with sh.style():
        fig = sh.new_figure(7.6, 6.2)
        gs = fig.add_gridspec(2, 6, height_ratios=[1.0, 0.9])
        ax = fig.add_subplot(gs[0, :])
        for i, (lab, tr) in enumerate(zip(sh.PHI_LABELS, res.runs)):
            c = sh.PHI_COLORS[i]
            ax.plot(_time(tr), tr.normal / (sh.MASS * sh.G), color=c, label=f"φ₀ = {lab}")
            ax.plot([_time(tr)[-1]], [tr.normal[-1] / (sh.MASS * sh.G)], "o", color=c, ms=4)
        ax.axhline(0.0, color="0.5", lw=0.8, zorder=0)
        ax.set_xlabel("t / √(aπ/g)")
        ax.set_ylabel(r"$F_n\,/\,(m g)$")
        ax.set_title("friction force across the velocity (dots: value at the stop)")
        ax.legend(loc="best")
        _path_panels(fig, gs, 1, res)
        fig.suptitle(title, fontsize=10)
    return fig


def main_figure(name, compute, plot, out, as_json, fmt, stream, **kw):
    """Shared ``main`` of the figure modules: print the summary, write the figure."""
    import sys

    stream = stream or sys.stdout
    out = sh.DEFAULT_OUT if out is None else out
    sh.prepare_out(out)
    if fmt not in sh.FORMATS:
        raise ValueError(f"--format = {fmt!r} is invalid; valid values: {', '.join(sh.FORMATS)}")
    res = compute(**kw)
    path = sh.save(plot(res), out, name, fmt)
    with open(os.path.join(out, f"{name}.json"), "w", encoding="utf-8") as fh:
        json.dump(res.as_dict(), fh, indent=2)
    if as_json:
        d = res.as_dict()
        d["file"] = path
        print(json.dumps(d, indent=2), file=stream)
    else:
        print(res.to_text(), file=stream)
        print(f"figure: {path}", file=stream)
    return res
