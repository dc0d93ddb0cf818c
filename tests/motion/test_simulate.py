"""Integration to the stop: against a plain solve_ivp in t, published values, convergence,
energy balance and symmetry (MODEL §5, §8)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import slidespin as ss
from conftest import make_law


def demo_setup():
    body = ss.Body(ss.Ellipse.from_eccentricity(0.1, 0.866), ss.UniformPressure(), mass=1.0)
    return body, ss.FrictionTensor(0.42, 0.54), ss.State.from_speed(1.0, 5.0, math.pi / 4)


def plain_stop(body, fr, st, g=9.81, cut=1e-9):
    """Naive route: Newton–Euler in t with solve_ivp and a stop event at s = cut·s₀."""
    m, inertia = body.mass, body.moment_of_inertia
    k2 = inertia / m

    def rhs(t, y):
        w = ss.friction_wrench(body, fr, y[3], y[4], y[5], y[2], g=g)
        return [y[3], y[4], y[5], w.force_x / m, w.force_y / m, w.moment / inertia]

    s0 = math.sqrt(st.vx**2 + st.vy**2 + k2 * st.omega**2)

    def stop(t, y):
        return math.sqrt(y[3] ** 2 + y[4] ** 2 + k2 * y[5] ** 2) - cut * s0

    stop.terminal = True
    sol = solve_ivp(
        rhs,
        (0.0, 100.0),
        [st.x, st.y, st.phi, st.vx, st.vy, st.omega],
        method="DOP853",
        rtol=1e-12,
        atol=1e-14,
        events=stop,
    )
    assert sol.status == 1
    return sol.t[-1], sol.y[:, -1]


def test_stop_agrees_with_plain_solve_ivp():
    body, fr, st = demo_setup()
    tr = ss.simulate(body, fr, st)
    t_plain, y_plain = plain_stop(body, fr, st)
    assert tr.status == "stopped"
    # the plain run stops at s = 1e-9 s0: what is left is O(1e-9) in t and O(1e-18) in x
    assert tr.t_stop == pytest.approx(t_plain, rel=1e-8)
    assert tr.stop_state.x == pytest.approx(y_plain[0], abs=1e-10)
    assert tr.stop_state.y == pytest.approx(y_plain[1], abs=1e-10)
    assert tr.stop_state.phi == pytest.approx(y_plain[2], abs=1e-9)


def test_stop_agrees_with_plain_solve_ivp_linear_law_body_tensor():
    body = ss.Body(ss.Ellipse(0.05, 0.03), ss.LinearPressure(0.004, -0.003), mass=0.7)
    fr = ss.FrictionTensor(0.2, 0.5, f=0.1, frame="body", angle=0.3)
    st = ss.State(0.01, -0.02, 0.4, 0.3, -0.2, 8.0)
    tr = ss.simulate(body, fr, st)
    t_plain, y_plain = plain_stop(body, fr, st)
    assert tr.t_stop == pytest.approx(t_plain, rel=1e-8)
    assert np.allclose([tr.stop_state.x, tr.stop_state.y], y_plain[:2], atol=1e-10, rtol=0)


@pytest.mark.parametrize("law", ["uniform", "linear", "boussinesq", "hertz"])
def test_converged_when_tolerance_tightens(law):
    body = ss.Body(ss.Ellipse(0.1, 0.06), make_law(law, 0.1, 0.06), mass=1.0)
    fr = ss.FrictionTensor(0.35, 0.5, f=0.05)
    st = ss.State.from_speed(0.8, 6.0, 0.3, 0.2)
    runs = [ss.simulate(body, fr, st, rtol=r) for r in (1e-10, 1e-12)]
    assert all(r.status == "stopped" for r in runs)
    assert runs[0].ending == runs[1].ending
    assert runs[0].t_stop == pytest.approx(runs[1].t_stop, rel=1e-8)
    assert runs[0].theta_stop == pytest.approx(runs[1].theta_stop, abs=1e-6)
    if runs[0].ending == "mixed":
        assert runs[0].beta_stop == pytest.approx(runs[1].beta_stop, rel=1e-6)


@pytest.mark.parametrize("v0, w0, th0", [(1.0, 10.0, 0.0), (0.3, 40.0, 1.0), (2.0, 2.0, -2.0)])
def test_uniform_disk_terminal_ratio_is_published_value(v0, w0, th0):
    """Uniformly loaded disk, I* = 1/2, isotropic: v/(aω) → 0.653 (Voyenli & Eriksen 1985;
    Weidman & Malhotra 2007), whatever the start; it ends along the initial direction."""
    a = 0.05
    body = ss.Body.from_inertia_ratio(ss.Circle(a), ss.UniformPressure(), 1.0, 0.5)
    tr = ss.simulate(body, ss.FrictionTensor.isotropic(0.3), ss.State.from_speed(v0, w0, th0))
    assert tr.ending == "mixed"
    assert tr.beta_stop / a == pytest.approx(0.653, abs=5e-4)


def test_boussinesq_disk_at_table2_boundary_stops_with_k_equal_one():
    """Isotropic Boussinesq disk: Table 2 puts k = 1 exactly at I* = (4fx+3μ)/(8fx) = 1/2."""
    a = 0.05
    body = ss.Body.from_inertia_ratio(ss.Circle(a), ss.BoussinesqPressure(), 2.0, 0.5)
    tr = ss.simulate(body, ss.FrictionTensor.isotropic(0.3), ss.State(0, 0, 0, 1.0, 0.0, 20.0))
    assert tr.beta_stop / a == pytest.approx(1.0, abs=1e-6)


def test_pure_translation_closed_form_stop():
    """ω₀ = 0: the body slides straight with deceleration g |𝔽 v̂| along −𝔽v̂ … only if 𝔽v̂ ∥ v̂;
    along a principal axis t_stop = v₀/(fx g) and the distance is v₀²/(2 fx g)."""
    body = ss.Body(ss.Ellipse(0.1, 0.05), ss.HertzPressure(), mass=1.0)
    fr = ss.FrictionTensor(0.4, 0.7)
    tr = ss.simulate(body, fr, ss.State(0, 0, 0.3, 1.5, 0.0, 0.0), g=9.81)
    assert tr.t_stop == pytest.approx(1.5 / (0.4 * 9.81), rel=1e-10)
    assert tr.distance == pytest.approx(1.5**2 / (2 * 0.4 * 9.81), rel=1e-10)
    assert tr.ending == "pure_sliding" and math.isinf(tr.beta_stop)


def test_pure_spin_closed_form_stop():
    """v₀ = 0 on a disk with isotropic friction: ω̇ = −(2/3) f m g a / I, so t_stop = I ω₀/M."""
    a, f, m = 0.1, 0.3, 1.0
    body = ss.Body(ss.Circle(a), ss.UniformPressure(), mass=m)
    tr = ss.simulate(body, ss.FrictionTensor.isotropic(f), ss.State(omega=7.0))
    torque = 2.0 / 3.0 * f * m * 9.81 * a
    assert tr.t_stop == pytest.approx(body.moment_of_inertia * 7.0 / torque, rel=1e-10)
    assert tr.ending == "pure_spinning" and tr.beta_stop == 0.0 and tr.distance < 1e-15


def test_energy_balance_along_the_trajectory():
    """Kinetic energy lost between samples equals the work of the friction power, and
    never increases (MODEL §8)."""
    body, fr, st = demo_setup()
    tr = ss.simulate(body, fr, st, max_step=0.01)
    m, inertia = body.mass, body.moment_of_inertia
    energy = 0.5 * m * (tr.vx**2 + tr.vy**2) + 0.5 * inertia * tr.omega**2
    assert np.all(np.diff(energy) <= 1e-12 * energy[0])
    # power from the wrench recomputed at each sample (not from the integrator's state)
    w = ss.friction_wrench(body, fr, tr.vx, tr.vy, tr.omega, tr.phi)
    power = w.power(tr.vx, tr.vy, tr.omega)
    work = np.concatenate([[0.0], np.cumsum(0.5 * (power[1:] + power[:-1]) * np.diff(tr.t))])
    assert np.allclose(energy - energy[0], work, atol=2e-5 * energy[0])
    assert energy[-1] == 0.0


def test_rotating_the_whole_setup_rotates_the_motion():
    body = ss.Body(ss.Ellipse(0.1, 0.04), ss.BoussinesqPressure(), mass=1.0)
    alpha = 0.77
    st = ss.State(0.0, 0.0, 0.2, 0.6, 0.2, 4.0)
    c, s = math.cos(alpha), math.sin(alpha)
    st_rot = ss.State(0.0, 0.0, 0.2 + alpha, c * 0.6 - s * 0.2, s * 0.6 + c * 0.2, 4.0)
    tr1 = ss.simulate(body, ss.FrictionTensor(0.3, 0.6, f=0.1), st)
    tr2 = ss.simulate(body, ss.FrictionTensor(0.3, 0.6, f=0.1, angle=alpha), st_rot)
    assert tr2.t_stop == pytest.approx(tr1.t_stop, rel=1e-8)
    x1, y1 = tr1.stop_state.x, tr1.stop_state.y
    assert tr2.stop_state.x == pytest.approx(c * x1 - s * y1, abs=1e-10)
    assert tr2.stop_state.y == pytest.approx(s * x1 + c * y1, abs=1e-10)
    assert tr2.theta_stop == pytest.approx(tr1.theta_stop + alpha, abs=1e-6)
    assert tr2.beta_stop == pytest.approx(tr1.beta_stop, rel=1e-6)


def test_trajectory_arrays_and_exports(tmp_path):
    body, fr, st = demo_setup()
    tr = ss.simulate(body, fr, st)
    n = tr.t.size
    for name in tr.COLUMNS:
        arr = getattr(tr, name)
        assert arr.shape == (n,) and np.all(np.isfinite(arr)), name
    assert tr.t[0] == 0.0 and tr.t[-1] == tr.t_stop
    assert tr.speed[0] == pytest.approx(1.0) and tr.speed[-1] == 0.0
    assert tr.beta[-1] == pytest.approx(tr.beta_stop)
    tr.to_csv(tmp_path / "t.csv")
    rows = (tmp_path / "t.csv").read_text().splitlines()
    assert rows[0].split(",") == list(tr.COLUMNS) and len(rows) == n + 1
    import json

    data = json.loads(tr.to_json(tmp_path / "s.json"))
    assert data["t_stop"] == tr.t_stop and data["ending"] == "mixed"


def test_initial_state_at_rest():
    body, fr, _ = demo_setup()
    tr = ss.simulate(body, fr, ss.State(1.0, 2.0, 0.5))
    assert tr.status == "at_rest" and tr.t_stop == 0.0 and tr.ending == "at_rest"
    assert (tr.stop_state.x, tr.stop_state.y, tr.stop_state.phi) == (1.0, 2.0, 0.5)


def test_skew_tensor_spiral_stop_closed_form():
    """𝔽 = c·I + f·J (|f| > |μ|/2 = 0: no real eigenvector) in pure sliding: the speed drops
    at c g, the direction turns for ever (ϑ = ϑ₀ ± (f/c) ln(v/v₀)), the body stops on a
    logarithmic spiral: t_stop = v₀/(c g), path length v₀²/(2 c g), and the stop lies at
    distance v₀²/(g √(4c² + f²)) from the start. There is no terminal direction."""
    c, f, v0, g = 0.4, 0.3, 1.5, 9.81
    body = ss.Body(ss.Ellipse(0.1, 0.06), ss.HertzPressure(), mass=2.0)
    tr = ss.simulate(body, ss.FrictionTensor(c, c, f=f), ss.State.from_speed(v0, 0.0, 0.7))
    assert tr.status == "stopped" and tr.ending == "spiral"
    assert math.isnan(tr.theta_stop) and tr.beta_stop == math.inf
    assert tr.t_stop == pytest.approx(v0 / (c * g), rel=1e-10)
    assert tr.distance == pytest.approx(v0**2 / (2 * c * g), rel=1e-10)
    assert math.hypot(tr.stop_state.x, tr.stop_state.y) == pytest.approx(
        v0**2 / (g * math.sqrt(4 * c * c + f * f)), rel=1e-9
    )


@pytest.mark.parametrize("mu, i_star", [(0.2030, 0.5118), (0.006153846153846176, 0.16101694915)])
def test_slow_approaches_are_not_spirals(mu, i_star):
    """Near a Table 2 boundary the direction converges slowly (algebraically), or lingers by a
    saddle before leaving it: that is not a spiral stop (found in examples/sweep_quick.toml)."""
    body = ss.Body.from_inertia_ratio(
        ss.Ellipse.from_eccentricity(0.1, 0.866), ss.UniformPressure(), 1.0, i_star
    )
    tr = ss.simulate(
        body,
        ss.FrictionTensor(0.42, 0.42 + mu),
        ss.State.from_speed(1.0, 5.0, math.pi / 4, math.pi / 4),
    )
    assert tr.status == "stopped" and tr.ending in ("mixed", "pure_spinning")
