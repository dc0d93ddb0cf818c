"""Figure 3 of the paper: β(t) and ϑ(t) of the elliptic plate under linear pressure.

The paper's run (§3.2): as Figure 2 but with the linear pressure law (10) whose centroid is
ξc = ηc = 0.1a. slidespin places the mass centre G over the pressure centroid (so the body
does not tip) and writes the equations of motion at G; β is the distance from G to the
instantaneous centre of rotation. The paper says its equations (11) were "obtained for ellipse
center" without saying how G enters (erratum 7); :mod:`slidespin.paper.errata` measures the
difference. The figure shows the paths with the outline of the patch.
"""

from __future__ import annotations

from slidespin.paper import _figures as fg
from slidespin.paper import _shared as sh

__all__ = ["compute", "plot", "main"]

NAME = "fig3"


def compute(mu: float = fg.DEFAULT_MU, fx: float | None = None) -> fg.FigureRuns:
    """Simulate the three runs of Figures 3 and 4 (linear pressure, ξc = ηc = 0.1a).

    Parameters
    ----------
    mu : float, default 0.12
        Anisotropy μ = fy − fx.
    fx : float, optional
        Friction coefficient along OX; by default the value inferred from Table 1.
    """
    return fg.run_figure("Figure 3", sh.linear_body(), "linear (xi_c = eta_c = 0.1a)", mu, fx)


def plot(result: fg.FigureRuns):
    """β(t), ϑ(t) and the paths (returns a matplotlib Figure)."""
    return fg.plot_beta_theta(
        result,
        "Figure 3 - linear pressure (ξc = ηc = 0.1a), e = 0.866, "
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
    """Print the stop of each run and write ``fig3.<fmt>`` (and fig3.json) into ``out``."""
    return fg.main_figure(NAME, compute, plot, out, as_json, fmt, stream, mu=mu, fx=fx)


if __name__ == "__main__":  # pragma: no cover
    main()
