"""Table 2 of the paper: how a circular patch stops, against its inertia ratio I*.

For a circle under orthotropic friction (f = 0, μ = fy − fx ≥ 0) the axis of I* = I/(m a²)
splits at I₁ < I₂ < I₃ into four endings (appendix, statement 1): ω/v → 0 (``pure_sliding``),
v = k a ω with k > 1, with k < 1 (both ``mixed``) and v/ω → 0 (``pure_spinning``). The
boundaries are values of J(β) = β M_Cζ/F_τ at ϑ = 0 (MODEL §6): I₁ = J(∞), I₂ = J(1),
I₃ = J(0⁺). :func:`compute` evaluates them numerically for the three laws (uniform,
Boussinesq, Hertz) with :func:`slidespin.analysis.intervals.inertia_intervals`, compares them with the
printed formulas (the uniform law's row 1 with its parenthesis restored, erratum 9), and
simulates one motion inside each of the four intervals to show the stated ending.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from slidespin import _validate as v
from slidespin.analysis.intervals import (
    circle_terminal_ratio,
    inertia_for_ratio,
    inertia_intervals,
    paper_inertia_intervals,
)
from slidespin.contact.body import Body
from slidespin.contact.ellipse import Ellipse
from slidespin.contact.friction import FrictionTensor
from slidespin.contact.pressure import BoussinesqPressure, HertzPressure, UniformPressure
from slidespin.motion.simulate import simulate
from slidespin.motion.state import State
from slidespin.paper import _shared as sh

__all__ = [
    "LAWS",
    "Table2Row",
    "Table2Run",
    "Table2Result",
    "compute",
    "plot",
    "main",
]

#: the pressure laws of Table 2's rows: (name as printed, law)
LAWS = (
    ("uniform", UniformPressure()),
    ("Boussinesq", BoussinesqPressure()),
    ("Hertz", HertzPressure()),
)
EXPECTED = {1: "pure_sliding", 2: "mixed, k > 1", 3: "mixed, k < 1", 4: "pure_spinning"}
LAW_COLORS = {"uniform": "C0", "Boussinesq": "C3", "Hertz": "C2"}
PUBLISHED = (0.5, 0.653)  # uniform isotropic disk: I* = 1/2 stops with v/(aω) = 0.653


@dataclass(frozen=True)
class Table2Row:
    """Boundaries of one law for one friction tensor."""

    law: str
    fx: float
    mu: float
    numeric: tuple  # (I1, I2, I3) from J(β)
    printed: tuple  # (I1, I2, I3) from the printed formulas

    @property
    def max_abs_diff(self) -> float:
        """The largest |computed − printed| over the table."""
        return max(abs(a - b) for a, b in zip(self.numeric, self.printed))


@dataclass(frozen=True)
class Table2Run:
    """A simulated circle with I* inside one interval of Table 2."""

    law: str
    fx: float
    mu: float
    regime: int  # row of Table 2 (1–4)
    inertia_ratio: float
    expected: str
    ending: str  # from the simulation
    k: float  # β*/a from the simulation (inf: pure sliding, 0: pure spinning)
    k_theory: float  # J⁻¹(I*) (circle_terminal_ratio)
    theta_stop: float

    @property
    def observed(self) -> str:
        """The ending found by the simulation, in the wording of Table 2."""
        if self.ending == "mixed":
            return "mixed, k > 1" if self.k > 1.0 else "mixed, k < 1"
        return self.ending

    @property
    def agrees(self) -> bool:
        """True if the observed ending is the one Table 2 expects."""
        return self.observed == self.expected


@dataclass(frozen=True)
class Table2Result:
    """Table 2 reproduced: rows for μ = 0 and for the chosen (fx, μ), runs, and curves."""

    rows: tuple
    runs: tuple
    curves: dict  # (law, mu) -> (I* array, k array)

    def as_dict(self) -> dict:
        """The numbers as plain data (JSON-ready)."""
        return {
            "rows": [
                {
                    "law": r.law,
                    "fx": r.fx,
                    "mu": r.mu,
                    "numeric": {"I1": r.numeric[0], "I2": r.numeric[1], "I3": r.numeric[2]},
                    "printed": {"I1": r.printed[0], "I2": r.printed[1], "I3": r.printed[2]},
                    "max_abs_diff": r.max_abs_diff,
                }
                for r in self.rows
            ],
            "runs": [
                {
                    "law": r.law,
                    "fx": r.fx,
                    "mu": r.mu,
                    "regime": r.regime,
                    "inertia_ratio": r.inertia_ratio,
                    "expected": r.expected,
                    "observed": r.observed,
                    "ending": r.ending,
                    "k": sh.num(r.k),
                    "k_theory": sh.num(r.k_theory),
                    "theta_stop": sh.num(r.theta_stop),
                    "agrees": r.agrees,
                }
                for r in self.runs
            ],
        }

    def to_text(self) -> str:
        """The numbers as a printed table."""
        lines = [
            "Table 2 - inertia intervals of a circular patch (f = 0): I1 = J(inf), "
            "I2 = J(1), I3 = J(0+)"
        ]
        for mu in sorted({r.mu for r in self.rows}):
            sub = [r for r in self.rows if r.mu == mu]
            fx = sub[0].fx
            lines.append("")
            lines.append(
                f"mu = {mu:g}"
                + (
                    "  (isotropic; no parameter)"
                    if mu == 0
                    else f"  (fx = {fx:g}, fy = {fx + mu:g})"
                )
            )
            lines.append("law          boundary   numeric          printed formula  |diff|")
            for r in sub:
                for j, name in enumerate(("I1", "I2", "I3")):
                    lines.append(
                        f"{(r.law if j == 0 else ''):<12} {name:<10} {r.numeric[j]:<16.12f} "
                        f"{r.printed[j]:<16.12f} {abs(r.numeric[j] - r.printed[j]):.1e}"
                    )
        lines.append("")
        lines.append("simulations (circle, v0 = a*omega0, theta0 = pi/4) - one per interval:")
        lines.append(
            "law          mu     row  I*       expected         observed         "
            "k = beta*/a   J^-1(I*)"
        )
        for r in self.runs:
            lines.append(
                f"{r.law:<12} {r.mu:<6g} {r.regime:<4d} {r.inertia_ratio:<8.4f} "
                f"{r.expected:<16} {r.observed:<16} {_fmt_k(r.k):<13} {_fmt_k(r.k_theory)}"
            )
        n_ok = sum(r.agrees for r in self.runs)
        lines.append(f"{n_ok} of {len(self.runs)} simulations end as Table 2 states")
        return "\n".join(lines)


def _fmt_k(k):
    return "inf" if math.isinf(k) else f"{k:.6f}"


def _inertia_in(bounds, regime):
    i1, i2, i3 = bounds
    return {1: 0.5 * i1, 2: 0.5 * (i1 + i2), 3: 0.5 * (i2 + i3), 4: 1.4 * i3}[regime]


def _run(law_name, law, fx, mu, regime, i_star):
    body = Body.from_inertia_ratio(Ellipse(sh.A, sh.A), law, sh.MASS, i_star)
    st = State.from_speed(1.0, 1.0 / sh.A, theta=sh.THETA0)
    tr = simulate(body, FrictionTensor(fx, fx + mu), st, g=sh.G)
    k = tr.beta_stop / sh.A
    kt = circle_terminal_ratio(law, FrictionTensor(fx, fx + mu), i_star)
    return Table2Run(
        law_name, fx, mu, regime, i_star, EXPECTED[regime], tr.ending, k, kt, tr.theta_stop
    )


def compute(fx: float = 0.3, mu: float = 0.15, *, runs: bool = True) -> Table2Result:
    """Reproduce Table 2 for μ = 0 and for the given (fx, μ).

    Parameters
    ----------
    fx : float, default 0.3
        Lower friction coefficient (> 0).
    mu : float, default 0.15
        Anisotropy μ = fy − fx ≥ 0.
    runs : bool, default True
        Also simulate one motion inside each interval (24 runs).

    Returns
    -------
    Table2Result
    """
    fx = v.positive("fx", fx)
    mu = v.in_range("mu", mu, 0.0, math.inf)
    settings = [(fx, 0.0)] + ([(fx, mu)] if mu != 0.0 else [])
    rows, sims, curves = [], [], {}
    beta = np.geomspace(10**-2.5, 10**2.5, 300)
    for f_x, m_u in settings:
        fr = FrictionTensor(f_x, f_x + m_u)
        for name, law in LAWS:
            num_b = tuple(inertia_intervals(law, fr))
            rows.append(Table2Row(name, f_x, m_u, num_b, tuple(paper_inertia_intervals(law, fr))))
            curves[(name, m_u)] = (inertia_for_ratio(law, fr, beta), beta)
            if runs:
                for regime in (1, 2, 3, 4):
                    sims.append(_run(name, law, f_x, m_u, regime, _inertia_in(num_b, regime)))
    return Table2Result(tuple(rows), tuple(sims), curves)


def plot(result: Table2Result):
    """Terminal ratio k = v/(aω) against I* for the three laws, boundaries marked."""
    # lazy: matplotlib is slow to import and needed only to draw
    from matplotlib.lines import Line2D

    mus = sorted({r.mu for r in result.rows})
    with sh.style():
        fig = sh.new_figure(3.6 * len(mus), 4.3)
        axes = np.atleast_1d(fig.subplots(1, len(mus), sharey=True))
        for ax, mu in zip(axes, mus):
            rows = [r for r in result.rows if r.mu == mu]
            for r in rows:
                c = LAW_COLORS[r.law]
                i_star, k = result.curves[(r.law, mu)]
                ax.plot(i_star, k, color=c, label=r.law)
                i1, i2, i3 = r.numeric
                ax.axvline(i1, color=c, ls=":", lw=0.8)
                ax.axvline(i3, color=c, ls=":", lw=0.8)
                ax.plot([i2], [1.0], "o", color=c, ms=4)
                runs = [q for q in result.runs if q.law == r.law and q.mu == mu]
                for q in runs:
                    if q.ending == "mixed":
                        y, mk = q.k, "x"
                    elif q.ending == "pure_sliding":
                        y, mk = 150.0, "^"
                    else:
                        y, mk = 0.0067, "v"
                    ax.plot([q.inertia_ratio], [y], mk, color=c, ms=5, mew=1.2)
            ax.axhline(1.0, color="0.5", lw=0.7)
            if mu == 0.0:
                ax.plot([PUBLISHED[0]], [PUBLISHED[1]], "*", color="k", ms=9, zorder=5)
                ax.set_title("isotropic friction (μ = 0)")
            else:
                fx = rows[0].fx
                ax.set_title(f"fx = {fx:g}, μ = fy − fx = {mu:g}")
            ax.set_yscale("log")
            ax.set_ylim(0.005, 200.0)
            ax.set_xlim(0.0, 1.05 * max(r.numeric[2] for r in rows) * 1.5)
            ax.set_xlabel("I* = I/(m a²)")
            ax.set_ylabel("terminal ratio k = v/(aω)")
        handles = [
            Line2D([], [], color=LAW_COLORS[name], label=f"{name} law") for name, _ in LAWS
        ] + [
            Line2D([], [], ls=":", color="0.3", lw=0.8, label="I₁, I₃ (numeric)"),
            Line2D([], [], ls="", marker="o", color="0.3", ms=4, label="I₂ (k = 1)"),
            Line2D(
                [], [], ls="", marker="*", color="k", ms=9, label="published: I* = 1/2 → k = 0.653"
            ),
            Line2D([], [], ls="", marker="x", color="0.3", label="simulation: mixed ending"),
            Line2D([], [], ls="", marker="^", color="0.3", label="simulation: ω/v → 0"),
            Line2D([], [], ls="", marker="v", color="0.3", label="simulation: v/ω → 0"),
        ]
        fig.legend(handles=handles, loc="outside lower center", ncol=3, fontsize=7.5)
    return fig


def main(
    out=None,
    *,
    as_json: bool = False,
    fx: float = 0.3,
    mu: float = 0.15,
    fmt: str = "png",
    stream=None,
) -> Table2Result:
    """Print Table 2 (text or JSON) and, if ``out`` is given, write table2.json and a figure."""
    if out is not None:
        sh.prepare_out(out)
    return sh.emit_table("table2", compute(fx, mu), out, as_json, stream, plot, fmt)


if __name__ == "__main__":  # pragma: no cover
    main()
