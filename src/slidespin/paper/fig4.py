"""Figure 4 of the paper: the force across the velocity, F_n(t), under linear pressure.

Same runs as Figure 3 (linear pressure, ξc = ηc = 0.1a). The paper notes that F_n tends to
zero for all three runs as the body stops; that is the terminal condition F_n = 0 of eq. 14–16
(a fixed point of the flow of the direction of motion, MODEL §5–6), and it holds at the stop of
every run here.
"""

from __future__ import annotations

from slidespin.paper import _figures as fg
from slidespin.paper import fig3

__all__ = ["compute", "plot", "main"]

NAME = "fig4"


def compute(mu: float = fg.DEFAULT_MU, fx: float | None = None) -> fg.FigureRuns:
    """The runs of Figure 3 (linear pressure), named Figure 4."""
    res = fig3.compute(mu=mu, fx=fx)
    return fg.FigureRuns("Figure 4", res.law, res.fx, res.mu, res.runs)


def plot(result: fg.FigureRuns):
    """F_n(t)/(m g) and the paths (returns a matplotlib Figure)."""
    return fg.plot_normal(
        result,
        "Figure 4 - linear pressure (ξc = ηc = 0.1a), e = 0.866, "
        f"fx = {result.fx:.4f}, μ = {result.mu:g}",
    )


def main(
    out=None,
    *,
    as_json: bool = False,
    mu: float = fg.DEFAULT_MU,
    fx=None,
    fmt: str = "png",
    stream=None,
) -> fg.FigureRuns:
    """Print the stop of each run and write ``fig4.<fmt>`` (and fig4.json) into ``out``."""
    return fg.main_figure(NAME, compute, plot, out, as_json, fmt, stream, mu=mu, fx=fx)


if __name__ == "__main__":  # pragma: no cover
    main()
