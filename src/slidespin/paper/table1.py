"""Table 1 of the paper: the terminal ratio β(μ) of an elliptic plate, and the true one.

The paper's Table 1 (§3.1) prints β/a for e = 0.866, uniform pressure, I* = (1 + κ²)/4, f = 0,
μ = fy − fx = 0 … 0.24 and φ = π/4, π/3, π/2. It is *not* a simulation output: it is the root
of eq. 16, β = I* F_τ/M_Cζ, with the velocity direction ϑ = 0 imposed and F_n ignored
(MODEL §6). The paper does not print fx; β depends on fx and μ only through μ/fx, so the
μ = 0 column is parameter-free and fx is inferred from the other 24 cells by least squares.

:func:`compute` reproduces the paper's method with the compiled wrench
(:func:`slidespin.analysis.terminal.terminal_ratio`), infers fx, compares every cell with the printed
value, finds the range of fx consistent with each printed digit, and gives beside each cell
the true terminal motion at that φ (:func:`slidespin.analysis.terminal.terminal_states`): for φ = π/2
it is the paper's root with ϑ* = 0; for φ = π/4 and π/3 it has ϑ* ≠ 0 and a larger β*.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

import numpy as np
from scipy.optimize import brentq, minimize_scalar

from slidespin import _validate as v
from slidespin.analysis.terminal import terminal_ratio, terminal_states
from slidespin.contact.friction import FrictionTensor
from slidespin.paper import _shared as sh

__all__ = [
    "PRINTED",
    "MU",
    "PHI",
    "PHI_LABELS",
    "Table1Cell",
    "Table1Result",
    "paper_ratio",
    "ratio_table",
    "infer_fx",
    "consistent_fx",
    "true_terminal_state",
    "compute",
    "plot",
    "main",
]

#: Table 1 as printed: rows φ = π/4, π/3, π/2; columns μ = 0, 0.03, …, 0.24 (β in units of a)
PRINTED = np.array(
    [
        [0.404, 0.446, 0.486, 0.524, 0.561, 0.599, 0.642, 0.704, 0.787],
        [0.494, 0.521, 0.547, 0.572, 0.597, 0.620, 0.643, 0.667, 0.689],
        [0.577, 0.593, 0.608, 0.623, 0.637, 0.650, 0.664, 0.677, 0.690],
    ]
)
#: the columns of Table 1: μ = fy − fx = 0, 0.03, …, 0.24
MU = np.round(0.03 * np.arange(9), 2)
#: the rows of Table 1: the body angles φ = π/4, π/3, π/2 [rad]
PHI = sh.PHI0
#: the rows' labels, as printed
PHI_LABELS = sh.PHI_LABELS
HALF_UNIT = 0.0005  # half a unit of the printed last digit
#: the round value of fx shown beside the least-squares one
ROUND_FX = 0.42
_BRACKET = (0.05, 5.0)  # contains the single root of eq. 16 near the paper's cells (units of a)


def paper_ratio(fx: float, mu: float, phi: float) -> float:
    """β/a of Table 1 for one cell: root of eq. 16 with ϑ = 0, uniform plate, e = 0.866."""
    body = sh.uniform_body()
    fr = FrictionTensor(fx, fx + mu)
    a = body.length_unit  # the semi-axis a of the ellipse
    try:
        beta = terminal_ratio(body, fr, phi, 0.0, bracket=(_BRACKET[0] * a, _BRACKET[1] * a))
    except ValueError:  # far from the paper's parameters: scan for the root
        beta = terminal_ratio(body, fr, phi, 0.0)
    return beta / a


def ratio_table(fx: float) -> np.ndarray:
    """The 3 × 9 table of β/a (rows φ, columns μ) for a given fx."""
    fx = v.positive("fx", fx)
    return np.array([[paper_ratio(fx, mu, phi) for mu in MU] for phi in PHI])


@dataclass(frozen=True)
class FxFit:
    """Least-squares estimate of the unprinted fx from the 24 cells with μ > 0."""

    fx: float
    rms: float  # root-mean-square difference over the 24 cells (units of a)
    max_abs: float  # largest |difference| over the 24 cells


@lru_cache(maxsize=1)
def infer_fx() -> FxFit:
    """fx minimising Σ (β(fx, μ, φ) − β_printed)² over the 24 cells with μ > 0.

    A scan of fx in [0.15, 2] locates the minimum, which a bounded Brent search refines to
    1e-9. The μ = 0 column does not depend on fx and is left out.
    """

    def residuals(fx):
        return (
            np.array([[paper_ratio(fx, mu, phi) for mu in MU[1:]] for phi in PHI]) - PRINTED[:, 1:]
        )

    def sse(fx):
        return float(np.sum(residuals(fx) ** 2))

    grid = np.geomspace(0.15, 2.0, 12)
    vals = [sse(x) for x in grid]
    i = int(np.argmin(vals))
    lo, hi = grid[max(i - 1, 0)], grid[min(i + 1, grid.size - 1)]
    res = minimize_scalar(sse, bounds=(lo, hi), method="bounded", options={"xatol": 1e-10})
    r = residuals(res.x)
    return FxFit(float(res.x), float(np.sqrt(np.mean(r**2))), float(np.abs(r).max()))


def consistent_fx(lo: float = 0.3, hi: float = 0.6) -> np.ndarray:
    """For each cell with μ > 0, the interval of fx for which β rounds to the printed value.

    β(fx) decreases monotonically with fx (the anisotropy μ/fx falls), so the interval is
    bounded by the roots of β(fx) = printed ± 0.0005 in [lo, hi].

    Returns
    -------
    ndarray (3, 8, 2)
        [fx_min, fx_max] per cell (rows φ, columns μ = 0.03 … 0.24).
    """
    lo = v.positive("lo", lo)
    hi = v.positive("hi", hi)
    return _consistent_fx(lo, hi).copy()


@lru_cache(maxsize=2)
def _consistent_fx(lo: float, hi: float) -> np.ndarray:
    out = np.empty((3, 8, 2))
    for i, phi in enumerate(PHI):
        for j, mu in enumerate(MU[1:]):
            target = PRINTED[i, j + 1]
            for k, edge in enumerate((+HALF_UNIT, -HALF_UNIT)):

                def g(fx, t=target + edge, mu=mu, phi=phi):
                    return paper_ratio(fx, mu, phi) - t

                out[i, j, k] = brentq(g, lo, hi, xtol=1e-12)
    return out


def _best_overlap(intervals: np.ndarray):
    """Largest number of cell intervals sharing a common fx, and that common interval."""
    flat = intervals.reshape(-1, 2)
    events = sorted(
        [(x, +1) for x in flat[:, 0]] + [(x, -1) for x in flat[:, 1]], key=lambda e: (e[0], -e[1])
    )
    best, count, start, span = 0, 0, None, (math.nan, math.nan)
    for k, (x, step) in enumerate(events):
        count += step
        if count > best:
            best, start = count, x
            span = (x, events[k + 1][0])
    del start
    return best, span


def true_terminal_state(fx: float, mu: float, phi: float):
    """The attracting mixed terminal motion at φ with ω > 0 and ϑ* in (−π/2, π/2]."""
    body = sh.uniform_body()
    states = terminal_states(body, FrictionTensor(fx, fx + mu), phi)
    for s in states:
        forward = -math.pi / 2 < s.theta <= math.pi / 2
        if s.stable and s.ending == "mixed" and s.u[2] > 0 and forward:
            return s
    return next(s for s in states if s.stable)


@dataclass(frozen=True)
class Table1Cell:
    """One cell of Table 1 (β in units of a)."""

    phi: float
    phi_label: str
    mu: float
    beta: float  # ours, by the paper's method
    paper: float  # printed
    true_beta: float  # the true terminal ratio at this φ
    true_theta: float  # its direction ϑ* [rad]
    true_ending: str

    @property
    def diff(self) -> float:
        """beta − paper."""
        return self.beta - self.paper

    @property
    def matches(self) -> bool:
        """Whether ``beta`` rounds to the printed value (|diff| ≤ 0.0005)."""
        return abs(self.diff) <= HALF_UNIT + 1e-12


@dataclass(frozen=True)
class Table1Result:
    """Table 1 reproduced. ``fx_source`` is ``"least squares"`` or ``"given"``."""

    fx: float
    fx_source: str
    fit: FxFit | None
    cells: tuple
    fx_intervals: np.ndarray | None  # (3, 8, 2): fx range consistent with each printed cell
    best_count: int | None  # most cells consistent with one fx
    best_interval: tuple | None  # the fx interval achieving it
    round_cells: tuple | None = None  # the cells at ROUND_FX (with a least-squares fx)

    @property
    def matching(self) -> int:
        """Cells (of 27) whose value rounds to the printed one at ``fx``."""
        return len(self.cells) - len(self.mismatches)

    @property
    def round_mismatches(self) -> tuple:
        """Cells that do not round to the printed value at fx = ROUND_FX."""
        return tuple(c for c in (self.round_cells or ()) if not c.matches)

    @property
    def round_matching(self) -> int | None:
        """Cells (of 27) that round to the printed value at fx = ROUND_FX."""
        if self.round_cells is None:
            return None
        return len(self.round_cells) - len(self.round_mismatches)

    def likely_fx(self) -> str:
        """Which fx the authors most likely used, from the measured counts (one sentence)."""
        if self.round_cells is None:
            return ""
        lo, hi = self.best_interval if self.best_interval else (math.nan, math.nan)
        in_best = lo <= ROUND_FX <= hi
        round_matching = len(self.round_cells) - len(self.round_mismatches)
        if round_matching > self.matching:
            why = (
                f"it is a round value, it makes {round_matching} of 27 cells round to "
                f"the print against {self.matching} for the least-squares fx = "
                f"{self.fx:.5f}"
            )
            if in_best:
                why += (
                    f", and it lies in the interval [{lo:.5f}, {hi:.5f}] that makes the "
                    "most fx-dependent cells round right"
                )
            return f"the authors most likely used fx = {ROUND_FX:g}: {why}."
        return (
            f"the least-squares fx = {self.fx:.5f} makes {self.matching} of 27 cells round "
            f"right, fx = {ROUND_FX:g} makes {round_matching}: the printed digits do "
            "not single out a round value."
        )

    def grid(self, name: str) -> np.ndarray:
        """A 3 × 9 array of one cell attribute (``beta``, ``paper``, ``true_beta``, ...)."""
        return np.array([getattr(c, name) for c in self.cells]).reshape(3, 9)

    @property
    def max_abs_diff(self) -> float:
        """The largest |computed − printed| over the table."""
        return max(abs(c.diff) for c in self.cells)

    @property
    def mismatches(self) -> tuple:
        """Cells whose value does not round to the printed one."""
        return tuple(c for c in self.cells if not c.matches)

    def as_dict(self) -> dict:
        """The numbers as plain data (JSON-ready)."""
        d = {
            "fx": self.fx,
            "fx_source": self.fx_source,
            "cells": [
                {
                    "phi": c.phi,
                    "phi_label": c.phi_label,
                    "mu": c.mu,
                    "beta": c.beta,
                    "paper": c.paper,
                    "diff": c.diff,
                    "matches": c.matches,
                    "true_beta": sh.num(c.true_beta),
                    "true_theta": sh.num(c.true_theta),
                    "true_ending": c.true_ending,
                }
                for c in self.cells
            ],
            "max_abs_diff": self.max_abs_diff,
            "mismatches": [
                {
                    "phi_label": c.phi_label,
                    "mu": c.mu,
                    "beta": c.beta,
                    "paper": c.paper,
                    "diff": c.diff,
                }
                for c in self.mismatches
            ],
        }
        if self.fit is not None:
            d["fit"] = {"rms": self.fit.rms, "max_abs": self.fit.max_abs}
        if self.round_cells is not None:
            d["round_fx"] = {
                "fx": ROUND_FX,
                "matching": self.round_matching,
                "of": 27,
                "mismatches": [
                    {
                        "phi_label": c.phi_label,
                        "mu": c.mu,
                        "beta": c.beta,
                        "paper": c.paper,
                        "diff": c.diff,
                    }
                    for c in self.round_mismatches
                ],
                "least_squares_matching": self.matching,
                "likely": self.likely_fx(),
            }
        if self.best_count is not None and self.best_interval is not None:
            d["fx_consistency"] = {
                "best_count": self.best_count,
                "of": 24,
                "interval": [self.best_interval[0], self.best_interval[1]],
            }
        return d

    def to_text(self) -> str:
        """The numbers as a printed table."""
        lines = [
            "Table 1 - beta/a from eq. 16 with theta = 0 imposed (the paper's method)",
            "uniform pressure, e = 0.866, I* = (1 + kappa^2)/4, f = 0, fy = fx + mu",
        ]
        if self.fit is not None:
            lines.append(
                f"fx inferred by least squares from the 24 cells with mu > 0: fx = {self.fx:.5f}"
                f"  (rms {self.fit.rms * 1e3:.2f}e-3, max {self.fit.max_abs * 1e3:.2f}e-3)"
            )
        else:
            lines.append(f"fx = {self.fx:.5f} (given)")
        lines.append("")
        head = "mu".rjust(20) + "".join(f"{m:9.2f}" for m in MU)
        lines.append(head)
        for i, lab in enumerate(PHI_LABELS):
            row = self.cells[9 * i : 9 * i + 9]
            lines.append(f"phi = {lab:<5} ours      " + "".join(f"{c.beta:9.5f}" for c in row))
            lines.append("            paper     " + "".join(f"{c.paper:9.3f}" for c in row))
            lines.append(
                "            diff[1e-3]"
                + "".join(f"{c.diff * 1e3:+8.3f}" + ("*" if not c.matches else " ") for c in row)
            )
            lines.append("            true beta*" + "".join(f"{c.true_beta:9.5f}" for c in row))
            lines.append(
                "            true th*  "
                + "".join(f"{round(c.true_theta, 5) + 0.0:9.5f}" for c in row)
            )
            lines.append("")
        lines.append(
            f"max |diff| = {self.max_abs_diff * 1e3:.2f}e-3; "
            f"{24 + 3 - len(self.mismatches)} of 27 cells round to the printed value"
            + (" (* marks the others)" if self.mismatches else "")
        )
        if self.best_count is not None and self.best_interval is not None:
            lo, hi = self.best_interval
            lines.append(
                "the least-squares fx above minimises the differences; no fx makes every cell "
                f"round right: the best, fx in [{lo:.5f}, {hi:.5f}] (e.g. 0.42), makes "
                f"{self.best_count} of the 24 fx-dependent cells round to the print"
            )
        if self.round_cells is not None:
            off = (
                ", ".join(
                    f"phi = {c.phi_label}, mu = {c.mu:.2f}: {c.diff * 1e3:+.2f}e-3"
                    for c in self.round_mismatches
                )
                or "none"
            )
            lines.append(
                f"round value fx = {ROUND_FX:g}: {self.round_matching} of 27 cells round to the "
                f"printed value (least squares: {self.matching} of 27); off: {off}"
            )
            lines.append(self.likely_fx())
        lines.append(
            "true beta*, th* [rad]: the attracting terminal motion at that phi "
            "(F_n = 0, theta not imposed)"
        )
        return "\n".join(lines)


def compute(fx: float | None = None, *, consistency: bool = True) -> Table1Result:
    """Reproduce Table 1.

    Parameters
    ----------
    fx : float, optional
        Friction coefficient along OX; by default inferred by least squares (:func:`infer_fx`).
    consistency : bool, default True
        Also compute the fx interval consistent with each printed cell (:func:`consistent_fx`).

    Returns
    -------
    Table1Result
    """
    if fx is None:
        fit = infer_fx()
        fx_val, source = fit.fx, "least squares"
    else:
        fit, fx_val, source = None, v.positive("fx", fx), "given"
    cells = []
    for i, phi in enumerate(PHI):
        for j, mu in enumerate(MU):
            beta = paper_ratio(fx_val, mu, phi)
            ts = true_terminal_state(fx_val, mu, phi)
            cells.append(
                Table1Cell(
                    phi=phi,
                    phi_label=PHI_LABELS[i],
                    mu=float(mu),
                    beta=beta,
                    paper=float(PRINTED[i, j]),
                    true_beta=ts.beta_ratio,
                    true_theta=ts.theta,
                    true_ending=ts.ending,
                )
            )
    intervals = best = span = None
    if consistency:
        intervals = consistent_fx()
        best, span = _best_overlap(intervals)
    round_cells = None
    if fit is not None:  # beside the least-squares fx, the round value
        round_cells = tuple(
            Table1Cell(
                phi=phi,
                phi_label=PHI_LABELS[i],
                mu=float(mu),
                beta=paper_ratio(ROUND_FX, mu, phi),
                paper=float(PRINTED[i, j]),
                true_beta=math.nan,
                true_theta=math.nan,
                true_ending="",
            )
            for i, phi in enumerate(PHI)
            for j, mu in enumerate(MU)
        )
    return Table1Result(fx_val, source, fit, tuple(cells), intervals, best, span, round_cells)


def plot(result: Table1Result):
    """β/a against μ: ours (lines), printed (markers) and the true terminal ratio (dashed)."""
    with sh.style():
        fig = sh.new_figure(7.2, 3.3)
        ax1, ax2 = fig.subplots(1, 2)
        beta, paper = result.grid("beta"), result.grid("paper")
        true_b, true_t = result.grid("true_beta"), result.grid("true_theta")
        for i, lab in enumerate(PHI_LABELS):
            c = sh.PHI_COLORS[i]
            ax1.plot(MU, beta[i], color=c, label=f"φ = {lab}: eq. 16, ϑ = 0")
            ax1.plot(MU, paper[i], "o", color=c, ms=4, mfc="none")
            ax1.plot(MU, true_b[i], "--", color=c, lw=1.1)
            ax2.plot(MU, true_t[i], "--", color=c, lw=1.1, label=f"φ = {lab}")
        ax1.plot([], [], "o", color="0.3", ms=4, mfc="none", label="printed (Table 1)")
        ax1.plot([], [], "--", color="0.3", lw=1.1, label="true terminal β*")
        ax1.set_xlabel("μ = fy − fx")
        ax1.set_ylabel("β/a = v/(aω) at the stop")
        ax1.set_title(
            f"Table 1: eq. 16 with ϑ = 0 vs true terminal state (fx = {result.fx:.4f})",
            fontsize=8.5,
        )
        ax1.legend(loc="upper left")
        ax2.axhline(0.0, color="0.5", lw=0.6, zorder=0)
        ax2.set_xlabel("μ = fy − fx")
        ax2.set_ylabel("ϑ* [rad]")
        ax2.set_title("true terminal direction of the velocity", fontsize=8.5)
        ax2.legend(loc="lower left")
    return fig


def main(
    out=None, *, as_json: bool = False, fx: float | None = None, fmt: str = "png", stream=None
) -> Table1Result:
    """Print Table 1 (text or JSON) and, if ``out`` is given, write table1.json/.txt and a
    figure. ``fx`` overrides the least-squares value."""
    if out is not None:
        sh.prepare_out(out)
    return sh.emit_table("table1", compute(fx), out, as_json, stream, plot, fmt)


if __name__ == "__main__":  # pragma: no cover
    main()
