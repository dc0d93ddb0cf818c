"""The figure of ``slidespin simulate --plot`` (issue #10 item 5): the β/a panel is not
flattened by the excursion to ±∞ where ω changes sign, a constant direction is not drawn as
rounding noise, and the example cases show motion that changes."""

from __future__ import annotations

import math
from pathlib import Path

import matplotlib
import numpy as np
import pytest

matplotlib.use("Agg")

import slidespin as ss  # noqa: E402
from slidespin.cli.main import CLI_MAX_STEP  # noqa: E402
from slidespin.studies.case import load_case  # noqa: E402
from slidespin.viz.trajectory_plot import BETA_LIMIT, plot_trajectory  # noqa: E402

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def run(name):
    case = load_case(EXAMPLES / f"{name}.toml")
    return case, ss.simulate(
        case.body,
        case.friction,
        case.initial_state,
        g=case.g,
        rtol=case.rtol,
        max_step=CLI_MAX_STEP,
    )


def panels(traj):
    fig = plot_trajectory(traj)
    return fig.axes[1], fig.axes[2]  # β/a, ϑ


def test_beta_panel_is_not_flattened_by_the_sign_change_of_omega():
    case, tr = run("hertz")
    beta, _ = panels(tr)
    lo, hi = beta.get_ylim()
    assert -1.2 * BETA_LIMIT <= lo < hi <= 1.2 * BETA_LIMIT
    s0 = case.initial_state  # the start, from the case file: v/(a ω) = 0.8/(0.02 · −15)
    start = math.hypot(s0.vx, s0.vy) / (case.body.patch.a * s0.omega)
    assert start == pytest.approx(-0.8 / 0.3, rel=1e-14)
    assert lo < start < hi
    (line,) = [ln for ln in beta.get_lines() if len(ln.get_xdata()) > 2]
    y = np.asarray(line.get_ydata(), dtype=float)
    assert np.nanmax(np.abs(y)) <= BETA_LIMIT  # nothing beyond the limit is drawn
    assert np.isnan(y).any()  # the excursion is cut, not joined across ±∞


def test_constant_direction_is_not_drawn_as_noise():
    case, tr = run("uniform_circle")  # isotropic, vy = 0: ϑ = 0 exactly in the physics
    assert np.ptp(tr.theta) < 1e-9
    _, theta = panels(tr)
    lo, hi = theta.get_ylim()
    assert hi - lo >= 0.19 and lo < 0.0 < hi
    assert any(t.get_text().startswith("constant") for t in theta.get_legend().get_texts())


def test_boussinesq_example_shows_beta_and_theta_evolving():
    case, tr = run("boussinesq")
    assert tr.status == "stopped" and tr.ending == "mixed"
    a = case.body.patch.a
    beta = tr.beta / a
    assert abs(beta[-1] - beta[0]) > 0.2  # not the degenerate β ≡ 1 of I* = I2, v = aω
    assert np.ptp(tr.theta) > 0.2
    assert tr.beta_stop / a < 1.0  # I2 < I* < I3 of Table 2: a mixed ending with β* < a
