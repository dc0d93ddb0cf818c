"""Figure 2 of the paper: β(t) and ϑ(t) of the elliptic plate under uniform pressure.

The paper's run (§3.1): e = 0.866, uniform pressure, I* = (1 + κ²)/4, v₀ = ω₀ = 1, ϑ₀ = π/4
(paper units, eq. 7) and φ₀ = π/4, π/3, π/2; fx (not printed) is inferred from Table 1 and
μ (not printed either) defaults to 0.12. Each run is integrated to its stop by
:func:`slidespin.simulate`, and the path of the body is drawn with its outline.

The paper states that "sliding and spinning stop at the same moment with ϑ = 0". They do stop
together (a mixed ending, β* finite), but ϑ* = 0 only for φ₀ = π/2, where the ellipse's axes
stay aligned with the friction axes by symmetry; for φ₀ = π/4 and π/3 the velocity at the stop
is turned from OX (erratum 11).
"""

from __future__ import annotations

from slidespin.paper import _figures as fg
from slidespin.paper import _shared as sh

__all__ = ["compute", "plot", "main"]

NAME = "fig2"


def compute(mu: float = fg.DEFAULT_MU, fx: float | None = None) -> fg.FigureRuns:
    """Simulate the three runs of Figure 2 (uniform pressure).

    Parameters
    ----------
    mu : float, default 0.12
        Anisotropy μ = fy − fx.
    fx : float, optional
        Friction coefficient along OX; by default the value inferred from Table 1.
    """
    return fg.run_figure("Figure 2", sh.uniform_body(), "uniform", mu, fx)


def plot(result: fg.FigureRuns):
    """β(t), ϑ(t) and the paths (returns a matplotlib Figure)."""
    return fg.plot_beta_theta(
        result,
        f"Figure 2 - uniform pressure, e = 0.866, fx = {result.fx:.4f}, μ = {result.mu:g}",
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
    """Print the stop of each run and write ``fig2.<fmt>`` (and fig2.json) into ``out``."""
    return fg.main_figure(NAME, compute, plot, out, as_json, fmt, stream, mu=mu, fx=fx)


if __name__ == "__main__":  # pragma: no cover
    main()
