"""Terminal motion (slidespin.analysis.terminal): eq. 14–16, fixed points of the sphere flow, Table 2.

Independent truths used here: the published terminal ratio of the uniformly loaded disk
(I* = 1/2, isotropic friction: v/(aω) = 0.653, Voyenli & Eriksen 1985), the closed forms of
the Table 2 limits (I₁ = fy⟨ξ²⟩/fx with ⟨ξ²⟩ = 1/4, 1/3, 1/5; the printed formulas), the
symmetries of the problem, and cross-checks between independent methods (root of eq. 16 vs
fixed points on the sphere vs integration to the stop with simulate).
"""

import math

import numpy as np
import pytest

from slidespin import (
    Body,
    BoussinesqPressure,
    Circle,
    Ellipse,
    FrictionTensor,
    HertzPressure,
    LinearPressure,
    State,
    UniformPressure,
    friction_wrench,
)
from slidespin.analysis.intervals import (
    circle_terminal_ratio,
    inertia_for_ratio,
    inertia_intervals,
    paper_inertia_intervals,
)
from slidespin.analysis.phase_portrait import phase_portrait
from slidespin.analysis.terminal import terminal_ratio, terminal_states
from slidespin.motion.simulate import simulate

ELLIPSE = Ellipse.from_eccentricity(1.0, 0.866)
FR = FrictionTensor(0.42, 0.54)
LAWS = [UniformPressure(), BoussinesqPressure(), HertzPressure()]
SECOND_MOMENT = {"uniform": 1 / 4, "boussinesq": 1 / 3, "hertz": 1 / 5}  # ⟨ξ²⟩/a²


def _stable_mixed(states, theta_near=0.0):
    cands = [s for s in states if s.stable and s.ending == "mixed" and s.u[2] > 0]
    return min(cands, key=lambda s: abs(math.remainder(s.theta - theta_near, 2 * math.pi)))


# ------------------------------------------------------------------------------------------
# the published disk
# ------------------------------------------------------------------------------------------
def test_uniform_disk_stops_with_published_ratio():
    disk = Body.from_inertia_ratio(Circle(0.07), UniformPressure(), 2.0, 0.5)
    iso = FrictionTensor(0.25, 0.25)
    beta = terminal_ratio(disk, iso, phi=0.3)
    assert round(beta / 0.07, 3) == 0.653  # published: 0.653
    assert circle_terminal_ratio(UniformPressure(), iso, 0.5) == pytest.approx(
        beta / 0.07, abs=1e-10
    )
    best = _stable_mixed(terminal_states(disk, iso, 0.3))
    assert best.continuum and math.isnan(best.theta)  # a circle of fixed points
    assert best.beta == pytest.approx(beta, abs=1e-10)


def test_published_ratio_by_simulation():
    disk = Body.from_inertia_ratio(Circle(0.05), UniformPressure(), 1.0, 0.5)
    tr = simulate(disk, FrictionTensor(0.3, 0.3), State.from_speed(0.4, 30.0, 1.0))
    assert tr.ending == "mixed"
    assert round(tr.beta_stop / 0.05, 3) == 0.653


# ------------------------------------------------------------------------------------------
# eq. 16: the paper's root
# ------------------------------------------------------------------------------------------
def test_terminal_ratio_is_root_of_eq16():
    body = Body(ELLIPSE, UniformPressure(), 1.0)
    phi = math.pi / 3
    beta = terminal_ratio(body, FR, phi)
    w = friction_wrench(body, FR, beta, 0.0, 1.0, phi)
    assert beta == pytest.approx(body.inertia_ratio * w.tangential / w.moment_paper, rel=1e-12)


def test_terminal_ratio_bracket_and_length_units():
    small = Body(Ellipse.from_eccentricity(0.02, 0.866), UniformPressure(), 3.0)
    big = Body(ELLIPSE, UniformPressure(), 1.0)
    b1 = terminal_ratio(small, FR, 0.7)
    assert b1 / 0.02 == pytest.approx(terminal_ratio(big, FR, 0.7), rel=1e-12)
    assert terminal_ratio(small, FR, 0.7, bracket=(0.001, 0.1)) == pytest.approx(b1, rel=1e-12)
    with pytest.raises(ValueError, match="bracket"):
        terminal_ratio(small, FR, 0.7, bracket=(0.05, 0.1))  # no root inside


def test_terminal_ratio_limits_outside_table2_intervals():
    fr = FrictionTensor(0.3, 0.45)
    i1, _, i3 = inertia_intervals(UniformPressure(), fr)
    slow = Body.from_inertia_ratio(Circle(1.0), UniformPressure(), 1.0, 0.8 * i1)
    heavy = Body.from_inertia_ratio(Circle(1.0), UniformPressure(), 1.0, 1.2 * i3)
    assert terminal_ratio(slow, fr, 0.0) == math.inf
    assert terminal_ratio(heavy, fr, 0.0) == 0.0


def test_eq16_root_is_terminal_only_when_normal_force_vanishes():
    body = Body(ELLIPSE, UniformPressure(), 1.0)
    # φ = π/2: the ellipse's axes lie along the friction axes; the root is a fixed point
    b = terminal_ratio(body, FR, math.pi / 2)
    best = _stable_mixed(terminal_states(body, FR, math.pi / 2))
    assert best.beta == pytest.approx(b, abs=1e-9)
    assert abs(best.theta) < 1e-9
    # φ = π/4: F_n ≠ 0 at the paper's root; the true terminal state turns the velocity
    b = terminal_ratio(body, FR, math.pi / 4)
    assert abs(friction_wrench(body, FR, b, 0.0, 1.0, math.pi / 4, g=1.0).normal) > 0.02
    best = _stable_mixed(terminal_states(body, FR, math.pi / 4))
    assert best.theta < -0.3
    assert best.beta - b > 0.05
    vx, vy = best.beta * math.cos(best.theta), best.beta * math.sin(best.theta)
    w = friction_wrench(body, FR, vx, vy, 1.0, math.pi / 4, g=1.0)
    assert abs(w.normal) < 1e-9  # eq. 14: F_n = 0 ...
    assert best.beta == pytest.approx(
        body.inertia_ratio * w.tangential / w.moment_paper, rel=1e-9
    )  # ... and eq. 16 at (β*, ϑ*)


# ------------------------------------------------------------------------------------------
# fixed points of the sphere flow
# ------------------------------------------------------------------------------------------
@pytest.mark.parametrize(
    "law", [UniformPressure(), LinearPressure(0.1, 0.1)], ids=["uniform", "linear"]
)
def test_terminal_states_agree_with_integration_to_the_stop(law):
    body = Body(ELLIPSE, law, 1.0)
    tr = simulate(body, FR, State.from_speed(1.0, 2.0, math.pi / 4, 1.0))
    assert tr.ending == "mixed"
    best = _stable_mixed(terminal_states(body, FR, tr.stop_state.phi), tr.theta_stop)
    assert best.beta == pytest.approx(tr.beta_stop, abs=1e-7)
    assert best.theta == pytest.approx(tr.theta_stop, abs=1e-7)


def test_fixed_points_are_fixed_and_come_in_antipodal_pairs():
    body = Body(ELLIPSE, LinearPressure(0.1, 0.05), 1.0)
    fr = FrictionTensor(0.3, 0.5, 0.03)
    states = terminal_states(body, fr, 0.9)
    us = [np.array(s.u) for s in states]
    for s, u in zip(states, us):
        assert any(np.allclose(-u, w, atol=1e-9) for w in us)
        k = body.radius_of_gyration
        w = friction_wrench(body, fr, u[0], u[1], u[2] / k, 0.9, g=1.0)
        a = np.array([w.force_x, w.force_y, w.moment / k])
        assert np.linalg.norm(a - (a @ u) * u) < 1e-8  # A ∥ u
        assert a @ u < 0.0  # friction opposes the motion
    # a pure spin about G (off the patch centre) leaves a net force: no pure-spin ending
    assert not any(s.ending == "pure_spinning" for s in states)


def test_pure_sliding_along_friction_axes():
    body = Body(ELLIPSE, UniformPressure(), 1.0)
    slides = [
        s
        for s in terminal_states(body, FrictionTensor(0.3, 0.5), 0.4)
        if s.ending == "pure_sliding"
    ]
    thetas = sorted(round(s.theta % (2 * math.pi), 12) for s in slides)
    assert thetas == pytest.approx([0.0, math.pi / 2, math.pi, 3 * math.pi / 2])
    # the skew part turns a sliding body: no pure-sliding terminal motion when |f| > |μ|/2
    skew = terminal_states(body, FrictionTensor(0.3, 0.5, 0.15), 0.4)
    assert not any(s.ending == "pure_sliding" for s in skew)


@pytest.mark.parametrize(
    "regime, ending", [(1, "pure_sliding"), (2, "mixed"), (3, "mixed"), (4, "pure_spinning")]
)
def test_stable_ending_matches_table2_regime(regime, ending):
    fr = FrictionTensor(0.3, 0.45)
    i1, i2, i3 = inertia_intervals(HertzPressure(), fr)
    i_star = {1: 0.5 * i1, 2: 0.5 * (i1 + i2), 3: 0.5 * (i2 + i3), 4: 2.0 * i3}[regime]
    disk = Body.from_inertia_ratio(Circle(1.0), HertzPressure(), 1.0, i_star)
    stable = [s for s in terminal_states(disk, fr, 0.0) if s.stable]
    assert {s.ending for s in stable} == {ending}
    assert all(abs(math.sin(s.theta)) < 1e-9 for s in stable if s.ending != "pure_spinning")
    if ending == "mixed":
        k = [s.beta_ratio for s in stable if s.u[2] > 0][0]
        assert (k > 1.0) == (regime == 2)
        assert k == pytest.approx(circle_terminal_ratio(HertzPressure(), fr, i_star), rel=1e-9)


# ------------------------------------------------------------------------------------------
# Table 2: the inertia boundaries
# ------------------------------------------------------------------------------------------
@pytest.mark.parametrize("law", LAWS, ids=lambda law: law.name)
@pytest.mark.parametrize("fx, fy", [(0.3, 0.3), (0.3, 0.45), (0.2, 0.7)])
def test_inertia_intervals_match_closed_forms(law, fx, fy):
    fr = FrictionTensor(fx, fy)
    num = inertia_intervals(law, fr)
    assert num == pytest.approx(tuple(paper_inertia_intervals(law, fr)), abs=1e-10)
    # I1 = J(∞) = fy⟨ξ²⟩/fx: the small-spin limit of the moment, derived independently
    assert num.i1 == pytest.approx(fy * SECOND_MOMENT[law.name] / fx, abs=1e-10)
    assert num.i1 < num.i2 < num.i3


def test_inertia_for_ratio_is_decreasing_and_hits_the_boundaries():
    fr = FrictionTensor(0.3, 0.45)
    beta = np.geomspace(1e-3, 1e3, 200)
    j = inertia_for_ratio(BoussinesqPressure(), fr, beta)
    assert np.all(np.diff(j) < 0.0)
    i1, i2, i3 = inertia_intervals(BoussinesqPressure(), fr)
    assert inertia_for_ratio(BoussinesqPressure(), fr, 1.0) == pytest.approx(i2, abs=1e-14)
    assert i1 < j.min() and j.max() < i3


def test_interval_regime_and_ending():
    iv = inertia_intervals(UniformPressure(), FrictionTensor(0.3, 0.3))
    assert [iv.regime(x) for x in (0.1, 0.3, 0.5, 1.0)] == [1, 2, 3, 4]
    assert iv.ending(0.1) == "pure_sliding" and iv.ending(1.0) == "pure_spinning"


@pytest.mark.parametrize(
    "bad, match",
    [
        (dict(pressure=LinearPressure(0.01, 0.0)), "pressure"),
        (dict(friction=FrictionTensor(0.3, 0.4, 0.1)), "friction.f"),
        (dict(friction=FrictionTensor(0.3, 0.4, angle=0.2)), "friction.angle"),
        (dict(friction=FrictionTensor(0.4, 0.3)), "mu = fy - fx"),
    ],
)
def test_table2_input_errors(bad, match):
    kw = dict(pressure=UniformPressure(), friction=FrictionTensor(0.3, 0.4)) | bad
    with pytest.raises(ValueError, match=match):
        inertia_intervals(kw["pressure"], kw["friction"])


def test_input_errors_name_the_parameter():
    body = Body(ELLIPSE, UniformPressure(), 1.0)
    with pytest.raises(ValueError, match="phi"):
        terminal_states(body, FR, math.nan)
    with pytest.raises(ValueError, match="theta"):
        terminal_ratio(body, FR, 0.0, theta=math.inf)
    with pytest.raises(ValueError, match="body"):
        terminal_ratio("disk", FR, 0.0)
    with pytest.raises(ValueError, match="ratio"):
        inertia_for_ratio(UniformPressure(), FR, [1.0, -2.0])
    with pytest.raises(ValueError, match="n = 0"):
        phase_portrait(body, FR, n=0)


# ------------------------------------------------------------------------------------------
# phase portrait
# ------------------------------------------------------------------------------------------
def test_phase_portrait_converges_on_the_terminal_ratio():
    disk = Body.from_inertia_ratio(Circle(0.1), UniformPressure(), 1.0, 0.5)
    pp = phase_portrait(disk, FrictionTensor(0.3, 0.3), n=3, points=50)
    assert pp.endings == ("mixed",) * 3
    assert np.allclose(pp.beta_stop, 0.6530017892, atol=1e-8)
    for spin, speed in zip(pp.spin, pp.speed):
        assert spin[-1] == 0.0 and speed[-1] == 0.0 and spin.size == 50
        # the curve converges on the terminal ray v = 0.653 a ω
        ratio = speed[:-1] / spin[:-1]
        # drawn down to s = 1e-4 s0, where u has not quite converged (it does like a power of s)
        assert abs(ratio[-1] - 0.6530017892) < 0.03
        assert abs(ratio[-1] - 0.6530017892) < abs(ratio[len(ratio) // 2] - 0.6530017892)
        # the starts lie on the ellipse of equal energy, s = 1 m/s
        k = disk.radius_of_gyration / 0.1
        assert math.hypot(speed[0], k * spin[0]) == pytest.approx(1.0, rel=1e-12)
