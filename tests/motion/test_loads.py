"""Applied loads, slopes, stick and slip (MODEL §11), against closed forms.

Truth: a block on a slope (sticks for tan α ≤ μ, else x = ½ g (sin α − μ cos α) t²), the same
along a principal axis of an orthotropic tensor, a disk pushed or twisted above its threshold
(constant acceleration), a coasting or spinning disk stopping (v₀/(μ g), I ω₀/T_c), a ramped
push on a disk solved by hand (piecewise-polynomial impulse, root by brentq, position by quad),
the work of gravity from the displacement alone, and the example scripts' pinned numbers.
"""

from __future__ import annotations

import json
import math
import runpy
from pathlib import Path

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import brentq

import slidespin as ss
from slidespin.contact.incline import Incline
from slidespin.motion.loaded import simulate_loaded
from slidespin.motion.loads import Load, applied_wrench
from slidespin.studies.load_tables import load_from_table

G = 9.81
EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def disk(law=None, r=0.05, m=1.0):
    return ss.Body(ss.Circle(r), law or ss.UniformPressure(), m)


# ------------------------------------------------------------------------------------------
# value objects
# ------------------------------------------------------------------------------------------
def test_load_wrench_body_frame_and_lever_arm():
    body = ss.Body(ss.Ellipse(0.1, 0.05), ss.LinearPressure(0.01, 0.0), 1.0)
    load = Load(force=(2.0, 0.0), torque=0.1, frame="body", at=(0.05, 0.03))
    phi = 0.5
    qx, qy, mz = load.wrench(0.0, phi, body.mass_centre)
    assert (qx, qy) == pytest.approx((2 * math.cos(phi), 2 * math.sin(phi)), abs=1e-15)
    # r_Q − r_G = (0.04, 0.03) in the body frame; its moment is frame-independent
    assert mz == pytest.approx(0.1 + (0.04 * 0.0 - 0.03 * 2.0), abs=1e-15)


def test_time_dependent_load_and_incline():
    load = Load(force=lambda t: (t, -t), torque=lambda t: 2 * t)
    assert load.wrench(1.5) == (1.5, -1.5, 3.0)
    assert not load.is_constant and Load().is_constant
    slope = Incline(0.3, downhill=math.pi / 2)
    gx, gy = slope.gravity_force(2.0, G)
    assert gx == pytest.approx(0.0, abs=1e-12) and gy == pytest.approx(2 * G * math.sin(0.3))
    w = applied_wrench(disk(), 1.5, 0.0, load, slope, G)
    assert w[1] == pytest.approx(-1.5 + 1.0 * G * math.sin(0.3))


@pytest.mark.parametrize(
    "build, match",
    [
        (lambda: Load(force=(1.0,)), "force"),
        (lambda: Load(force="push"), "force"),
        (lambda: Load(torque="x"), "torque"),
        (lambda: Load(frame="world"), "frame"),
        (lambda: Load(at=(0.0, math.inf)), "at"),
        (lambda: Incline(math.pi / 2), "angle"),
        (lambda: Incline(-0.1), "angle"),
        (lambda: Incline(0.2, downhill=math.nan), "downhill"),
    ],
)
def test_validation(build, match):
    with pytest.raises(ValueError, match=match):
        build()


def test_simulate_loaded_validation():
    with pytest.raises(ValueError, match="t_end"):
        simulate_loaded(
            disk(), ss.FrictionTensor(0.3, 0.3), ss.State(), load=Load(force=lambda t: (t, 0.0))
        )
    with pytest.raises(ValueError, match="load"):
        simulate_loaded(disk(), ss.FrictionTensor(0.3, 0.3), ss.State(), load=(1, 0), t_end=1)
    with pytest.raises(ValueError, match="never stop"):
        simulate_loaded(disk(), ss.FrictionTensor(0.3, 0.3), ss.State(vx=1.0), incline=Incline(0.5))


# ------------------------------------------------------------------------------------------
# slopes
# ------------------------------------------------------------------------------------------
@pytest.mark.parametrize("mu, alpha, delta", [(0.3, 0.29, 0.0), (0.3, math.atan(0.3), 0.4)])
def test_block_on_slope_sticks_up_to_the_friction_angle(mu, alpha, delta):
    tr = simulate_loaded(
        disk(),
        ss.FrictionTensor.isotropic(mu),
        ss.State(),
        incline=Incline(alpha, delta),
        t_end=1.0,
        g=G,
    )
    assert tr.ending == "at_rest_throughout"
    assert tr.x[-1] == 0.0 and tr.y[-1] == 0.0


@pytest.mark.parametrize("law", [ss.UniformPressure(), ss.HertzPressure()])
def test_block_on_slope_slides_with_the_closed_form_acceleration(law):
    mu, alpha, delta, t_end = 0.3, 0.45, 0.7, 0.8
    tr = simulate_loaded(
        disk(law),
        ss.FrictionTensor.isotropic(mu),
        ss.State(x=0.1),
        incline=Incline(alpha, delta),
        t_end=t_end,
        g=G,
    )
    acc = G * (math.sin(alpha) - mu * math.cos(alpha))
    dist = 0.5 * acc * t_end**2
    assert tr.ending == "moving_at_t_end"
    assert tr.t[-1] == pytest.approx(t_end, abs=1e-12)
    assert tr.x[-1] - 0.1 == pytest.approx(dist * math.cos(delta), abs=1e-9)
    assert tr.y[-1] == pytest.approx(dist * math.sin(delta), abs=1e-9)
    assert tr.speed[-1] == pytest.approx(acc * t_end, abs=1e-9)
    assert abs(tr.omega[-1]) < 1e-9


@pytest.mark.parametrize("axis", ["x", "y"])
def test_orthotropic_slope_along_a_principal_axis(axis):
    fx, fy, turn = 0.25, 0.45, 0.3  # principal axes turned by 0.3 rad from OX
    friction = ss.FrictionTensor(fx, fy, angle=turn)
    mu, delta = (fx, turn) if axis == "x" else (fy, turn + math.pi / 2)
    body = ss.Body(ss.Circle(0.05), ss.UniformPressure(), 1.0)
    below = simulate_loaded(
        body, friction, ss.State(), incline=Incline(math.atan(mu) - 1e-6, delta), t_end=0.5, g=G
    )
    assert below.ending == "at_rest_throughout"
    alpha = math.atan(mu) + 0.1
    tr = simulate_loaded(body, friction, ss.State(), incline=Incline(alpha, delta), t_end=0.5, g=G)
    dist = 0.5 * G * (math.sin(alpha) - mu * math.cos(alpha)) * 0.25
    assert math.hypot(tr.x[-1], tr.y[-1]) == pytest.approx(dist, abs=1e-9)
    assert math.atan2(tr.y[-1], tr.x[-1]) == pytest.approx(delta, abs=1e-8)


def test_steady_sliding_at_the_friction_angle():
    mu = 0.3
    tr = simulate_loaded(
        disk(),
        ss.FrictionTensor.isotropic(mu),
        ss.State(vx=0.5),
        incline=Incline(math.atan(mu)),
        t_end=1.0,
        g=G,
    )
    assert tr.ending == "steady_sliding"
    assert tr.x[-1] == pytest.approx(0.5, abs=1e-9)


# ------------------------------------------------------------------------------------------
# pushes and torques on a disk at rest
# ------------------------------------------------------------------------------------------
@pytest.mark.parametrize("excess", [1e-6, 0.2])
def test_disk_pushed_above_threshold_accelerates(excess):
    mu, m, t_end = 0.3, 1.0, 0.5
    p = mu * m * G * (1 + excess)
    tr = simulate_loaded(
        disk(m=m),
        ss.FrictionTensor.isotropic(mu),
        ss.State(),
        load=Load(force=(0.0, p)),
        t_end=t_end,
        g=G,
    )
    assert tr.ending == "moving_at_t_end"
    assert tr.y[-1] == pytest.approx(0.5 * (p / m - mu * G) * t_end**2, rel=1e-8, abs=1e-14)
    below = simulate_loaded(
        disk(m=m),
        ss.FrictionTensor.isotropic(mu),
        ss.State(),
        load=Load(force=(0.0, mu * m * G * (1 - 1e-9))),
        t_end=t_end,
        g=G,
    )
    assert below.ending == "at_rest_throughout"


@pytest.mark.parametrize(
    "law, constant",
    [(ss.UniformPressure(), 2 / 3), (ss.BoussinesqPressure(), math.pi / 4)],
)
def test_disk_twisted_above_threshold_spins_up(law, constant):
    mu, r, m, t_end = 0.3, 0.05, 1.0, 0.4
    body = disk(law, r, m)
    t_c = constant * mu * m * G * r
    torque = 1.3 * t_c
    tr = simulate_loaded(
        body,
        ss.FrictionTensor.isotropic(mu),
        ss.State(),
        load=Load(torque=torque),
        t_end=t_end,
        g=G,
    )
    assert tr.phi[-1] == pytest.approx(
        0.5 * (torque - t_c) / body.moment_of_inertia * t_end**2, rel=1e-8
    )
    assert abs(tr.x[-1]) + abs(tr.y[-1]) < 1e-12
    below = simulate_loaded(
        body,
        ss.FrictionTensor.isotropic(mu),
        ss.State(),
        load=Load(torque=t_c * (1 - 1e-9)),
        t_end=t_end,
        g=G,
    )
    assert below.ending == "at_rest_throughout"


def test_coasting_and_spinning_disks_stop_at_the_closed_form_times():
    mu, r = 0.3, 0.05
    body = disk(r=r)
    tr = simulate_loaded(body, ss.FrictionTensor.isotropic(mu), ss.State(vx=1.2), g=G)
    assert tr.ending == "stopped_stuck" and tr.t[-1] == pytest.approx(1.2 / (mu * G), rel=1e-10)
    assert tr.t_stop == tr.t[-1]
    assert tr.x[-1] == pytest.approx(1.2**2 / (2 * mu * G), rel=1e-10)
    spin = simulate_loaded(body, ss.FrictionTensor.isotropic(mu), ss.State(omega=20.0), g=G)
    t_c = 2 / 3 * mu * G * r
    assert spin.t[-1] == pytest.approx(body.moment_of_inertia * 20.0 / t_c, rel=1e-10)


# ------------------------------------------------------------------------------------------
# stick, slip, stick; energy
# ------------------------------------------------------------------------------------------
def _ramp_truth(f0, t1, fc, m):
    """Triangle push F(t) = f0 (1 − |t − t1|/t1) on a disk with threshold fc: closed form."""

    def impulse(t):  # ∫₀ᵗ F
        if t <= t1:
            return f0 * t * t / (2 * t1)
        if t <= 2 * t1:
            d = t - t1
            return f0 * t1 / 2 + f0 * (d - d * d / (2 * t1))
        return f0 * t1

    ta = t1 * fc / f0

    def vel(t):
        return (impulse(t) - impulse(ta) - fc * (t - ta)) / m

    tb = brentq(vel, t1, 2 * t1 + 10.0, xtol=1e-15, rtol=1e-15)
    x = (
        quad(vel, ta, t1, epsabs=1e-14, epsrel=1e-14)[0]
        + quad(vel, t1, tb, epsabs=1e-14, epsrel=1e-14, points=[2 * t1] if tb > 2 * t1 else None)[0]
    )
    return ta, tb, x


def test_ramped_push_sticks_slips_and_sticks_again():
    mu, m, f0, t1 = 0.3, 1.0, 5.0, 1.0
    fc = mu * m * G
    load = Load(force=lambda t: (f0 * max(0.0, 1.0 - abs(t - t1) / t1), 0.0))
    tr = simulate_loaded(
        disk(m=m), ss.FrictionTensor.isotropic(mu), ss.State(), load=load, t_end=3.0, g=G
    )
    ta, tb, x = _ramp_truth(f0, t1, fc, m)
    assert [k for k, _, _ in tr.phases] == ["stick", "slip", "stick"]
    (_, _, s1), (_, p0, p1), (_, _, q1) = tr.phases
    assert s1 == pytest.approx(ta, abs=1e-9) and p0 == s1
    assert p1 == pytest.approx(tb, abs=1e-8) and q1 == pytest.approx(3.0)
    assert tr.x[-1] == pytest.approx(x, rel=1e-8)
    assert tr.ending == "stopped_stuck" and tr.t_stop == p1
    assert tr.energy_error < 1e-9 * f0 * x
    assert json.loads(tr.to_json())["phases"][1][0] == "slip"
    assert tr.to_csv().count("\n") == tr.t.size + 1


def test_energy_balance_and_gravity_work_on_a_slope():
    body = ss.Body(ss.Ellipse(0.06, 0.03), ss.LinearPressure(0.005, 0.002), 0.5)
    friction = ss.FrictionTensor(0.25, 0.4, 0.03)
    slope = Incline(0.35, downhill=1.0)
    tr = simulate_loaded(
        body, friction, ss.State(vx=-1.0, vy=0.3, omega=15.0), incline=slope, t_end=1.0, g=G
    )
    ke0 = tr.kinetic_energy[0]
    assert tr.energy_error < 1e-9 * ke0
    assert tr.load_work[-1] == pytest.approx(tr.gravity_work, rel=1e-9)
    assert np.all(np.diff(tr.friction_work) <= 1e-15)  # friction only dissipates


# ------------------------------------------------------------------------------------------
# the example scripts pin one number each
# ------------------------------------------------------------------------------------------
def test_example_pushed_puck_starts_when_the_push_leaves_c(tmp_path):
    ns = runpy.run_path(str(EXAMPLES / "pushed_puck.py"))
    t_start = ns["main"](str(tmp_path / "pushed.png"))
    assert (tmp_path / "pushed.png").stat().st_size > 0
    # at the start the push (5 t N at (0, 2 cm)) lies on the boundary of C
    from slidespin.contact.statics import load_factor

    lam = load_factor(
        disk(), ss.FrictionTensor.isotropic(0.3), (5 * t_start, 0.0, -0.02 * 5 * t_start)
    )
    assert lam == pytest.approx(1.0, abs=1e-9)


def test_example_puck_on_slope_outruns_a_block(tmp_path):
    ns = runpy.run_path(str(EXAMPLES / "puck_on_slope.py"))
    dist = ns["main"](str(tmp_path / "slope.png"))
    block = 0.5 * G * (math.sin(math.radians(20)) - 0.3 * math.cos(math.radians(20)))
    assert block < dist < 0.5 * G * math.sin(math.radians(20))
    assert dist == pytest.approx(0.666402206, abs=2e-9)


def test_thrown_up_a_steep_slope_stops_and_slides_back():
    mu, alpha, v0, t_end = 0.3, 0.5, 1.5, 1.0
    tr = simulate_loaded(
        disk(),
        ss.FrictionTensor.isotropic(mu),
        ss.State(vx=-v0),
        incline=Incline(alpha),
        t_end=t_end,
        g=G,
    )
    up = G * (math.sin(alpha) + mu * math.cos(alpha))
    down = G * (math.sin(alpha) - mu * math.cos(alpha))
    t_top = v0 / up
    assert [k for k, _, _ in tr.phases] == ["slip", "slip"]
    assert tr.phases[0][2] == pytest.approx(t_top, abs=1e-10)
    x_end = -(v0**2) / (2 * up) + 0.5 * down * (t_end - t_top) ** 2
    assert tr.x[-1] == pytest.approx(x_end, abs=1e-9)
    assert tr.vx[-1] == pytest.approx(down * (t_end - t_top), abs=1e-9)


def test_tables_of_a_case_file():
    from slidespin.studies.load_tables import incline_from_table, load_from_table

    load = load_from_table(
        {"fx": 1.0, "fy": -2.0, "torque": 0.5, "frame": "body", "at": [0.01, 0.0]}
    )
    assert load.force == (1.0, -2.0) and load.torque == 0.5 and load.at == (0.01, 0.0)
    ramp = load_from_table(
        {
            "times": [0.0, 1.0, 2.0],
            "profile_fx": [0.0, 5.0, 0.0],
            "profile_fy": [0.0, 0.0, 0.0],
            "profile_torque": [0.0, 1.0, 0.0],
        }
    )
    assert ramp.wrench(0.25) == pytest.approx((1.25, 0.0, 0.25))
    assert ramp.wrench(5.0) == (0.0, 0.0, 0.0) and not ramp.is_constant
    slope = incline_from_table({"angle_deg": 30.0, "downhill_deg": 90.0})
    assert slope.angle == pytest.approx(math.pi / 6) and slope.downhill == pytest.approx(
        math.pi / 2
    )
    for bad, match in [
        ({"fx": 1.0, "force": 2.0}, "both 'force' and 'fx'"),
        ({"fx": 1.0, "times": [0.0, 1.0]}, "not both"),
        ({"times": [0.0, 1.0], "profile_fx": [0.0, 1.0]}, "profile_fy"),
        ({"times": [1.0, 0.0], "profile_fx": [0, 1], "profile_fy": [0, 1]}, r"\[load\] times"),
        ({"frame": "world"}, r"\[load\] frame"),
    ]:
        with pytest.raises(ValueError, match=match):
            load_from_table(bad)
    for bad, match in [
        ({"downhill": 0.1}, "angle"),
        ({"angle": 2.0}, r"\[incline\] angle"),
        ({"angle": 0.1, "angle_deg": 5.0}, "both"),
    ]:
        with pytest.raises(ValueError, match=match):
            incline_from_table(bad)


def test_piecewise_linear_ramp_matches_the_closed_form():
    mu, m, f0, t1 = 0.3, 1.0, 5.0, 1.0
    load = Load.piecewise_linear([0.0, t1, 2 * t1], [0.0, f0, 0.0], [0.0, 0.0, 0.0])
    tr = simulate_loaded(
        disk(m=m),
        ss.FrictionTensor.isotropic(mu),
        ss.State(),
        load=load,
        t_end=2.5,
        g=G,
        scan_step=0.05,
    )
    ta, tb, x = _ramp_truth(f0, t1, mu * m * G, m)
    assert tr.slip_intervals[0] == pytest.approx((ta, tb), abs=1e-8)
    assert tr.x[-1] == pytest.approx(x, rel=1e-8)


# ------------------------------------------------------------------------------------------
# a push off G through the threshold (regression: "no onset direction found; please report")
# ------------------------------------------------------------------------------------------
def _off_centre_pushes():
    profile = Load.piecewise_linear(
        [0.0, 1.0, 2.0], [0.0, 5.0, 0.0], [0.0, 0.0, 0.0], at=(0.0, 0.02)
    )
    written = Load(force=lambda t: (5.0 * max(0.0, 1.0 - abs(t - 1.0)), 0.0), at=(0.0, 0.02))
    table = load_from_table(
        {
            "times": [0.0, 1.0, 2.0],
            "profile_fx": [0.0, 5.0, 0.0],
            "profile_fy": [0.0, 0.0, 0.0],
            "at": [0.0, 0.02],
        }
    )
    return profile, written, table


def test_off_centre_ramp_starts_at_the_independent_threshold_however_written():
    """The push 0 → 5 N → 0 at (0, 2 cm) reaches the threshold F_c (independent 1-D
    minimisation, tests/test_statics.py) at t = F_c/5 on its linear rise; the slip starts
    there with the onset rate 0⁺, whether the push is a piecewise-linear profile, a lambda
    or a case-file table (the three round the load differently at the threshold)."""
    from test_statics import off_centre_push_threshold

    f_c, _ = off_centre_push_threshold(0.05, 0.3, 1.0, 0.02)
    runs = [
        ss.simulate(disk(), ss.FrictionTensor(0.3, 0.3), ss.State(), load=load, t_end=3.0, g=G)
        for load in _off_centre_pushes()
    ]
    for tr in runs:
        assert tr.status == "ok" and tr.message == "" and tr.ending == "stopped_stuck"
        assert [k for k, _, _ in tr.phases] == ["stick", "slip", "stick"]
        # the engine holds loads within GAUGE_TOL = 1e-12 of the threshold: 5e-13 s here
        assert tr.phases[1][1] == pytest.approx(f_c / 5.0, abs=5e-12)
        # it slides and turns (clockwise: the push acts above G), then stops after the release
        assert tr.x[-1] > 0.0 and tr.phi[-1] < 0.0 and tr.phases[1][2] > 2.0
        assert tr.energy_error < 1e-9 * 5.0 * tr.x[-1]
    for tr in runs[1:]:
        for (k0, a0, b0), (k1, a1, b1) in zip(runs[0].phases, tr.phases):
            assert k0 == k1 and abs(a0 - a1) <= 1e-9 and abs(b0 - b1) <= 1e-9
        assert tr.x[-1] == pytest.approx(runs[0].x[-1], rel=1e-8)
        assert tr.phi[-1] == pytest.approx(runs[0].phi[-1], rel=1e-8)


@pytest.mark.parametrize("method", ["auto", "scipy"])
def test_an_onset_that_cannot_be_found_ends_the_run_honestly(monkeypatch, method):
    """No input may reach a RuntimeError: a failed onset solve (a slip direction always
    exists beyond C, so this is a solver failure, forced here) ends the run at that time,
    at rest, with status "no_onset" and a message; in the compiled engine (whose Newton
    solve from the normal of C is forced to fail too, so that the Python onset with all
    its starts runs) and in the Python path."""
    import slidespin.contact.statics as st
    import slidespin.motion._loaded_engine as engine
    from test_statics import off_centre_push_threshold

    f_c, _ = off_centre_push_threshold(0.05, 0.3, 1.0, 0.02)
    monkeypatch.setattr(st, "_onset_nat", lambda *args, **kwargs: None)
    monkeypatch.setattr(engine, "slaved_direction", lambda *args: (False, None, 0.0, 0))
    tr = simulate_loaded(
        disk(),
        ss.FrictionTensor(0.3, 0.3),
        ss.State(),
        load=_off_centre_pushes()[0],
        t_end=3.0,
        g=G,
        method=method,
    )
    assert tr.status == "no_onset"
    assert "could not be started" in tr.message and "load factor" in tr.message
    assert [k for k, _, _ in tr.phases] == ["stick"]
    assert tr.phases[0][2] == pytest.approx(f_c / 5.0, abs=1e-9) == tr.t[-1]
    assert tr.speed[-1] == 0.0 and tr.x[-1] == 0.0
    summary = json.loads(tr.to_json())
    assert summary["status"] == "no_onset" and summary["message"] == tr.message


def test_a_profile_that_reaches_the_threshold_at_a_kink_or_stays_on_it():
    """Profiles whose corner sits exactly on the threshold F_c (independent minimisation):
    rising on after the corner, the body starts at the corner; held there (a plateau at F_c,
    or one rounding above it), it stays at rest, since a load on the boundary of C is held
    (MODEL §11). Before, the plateau failed inside Brent's method and then repeated empty
    slip phases at one instant up to max_phases."""
    from test_statics import off_centre_push_threshold

    f_c, _ = off_centre_push_threshold(0.05, 0.3, 1.0, 0.02)
    fr = ss.FrictionTensor(0.3, 0.3)
    rise = Load.piecewise_linear(
        [0.0, 1.0, 2.0], [0.0, f_c, 2 * f_c], [0.0, 0.0, 0.0], at=(0.0, 0.02)
    )
    tr = simulate_loaded(disk(), fr, ss.State(), load=rise, t_end=2.0, g=G)
    assert tr.status == "ok" and [k for k, _, _ in tr.phases] == ["stick", "slip"]
    assert tr.phases[1][1] == pytest.approx(1.0, abs=5e-12)
    for top in (f_c, f_c * (1 + 4.4e-16)):
        hold = Load.piecewise_linear(
            [0.0, 1.0, 3.0], [0.0, top, top], [0.0, 0.0, 0.0], at=(0.0, 0.02)
        )
        tr = simulate_loaded(disk(), fr, ss.State(), load=hold, t_end=3.0, g=G)
        assert tr.status == "ok" and tr.ending == "at_rest_throughout"
        assert tr.phases == (("stick", 0.0, 3.0),)


@pytest.mark.parametrize("method", ["auto", "scipy"])
def test_an_integrator_that_gives_up_ends_the_run_with_a_status(monkeypatch, method):
    """An integrator failure (forced here) ends the run with status "step_too_small", the
    values as reached and the integrator's message, in the slow start and in a slip: in
    the compiled engine (its steppers made to report a failure) and in the Python path
    (solve_ivp made to)."""
    import scipy.integrate as lo  # the Python path imports solve_ivp from it when it runs

    import slidespin.motion._loaded_dop853 as dop
    import slidespin.motion._loaded_engine as engine

    if method == "scipy":
        real = lo.solve_ivp

        def failing(*args, **kwargs):
            sol = real(*args, **kwargs)
            sol.status, sol.message = -1, "forced failure"
            return sol

        monkeypatch.setattr(lo, "solve_ivp", failing)
        said = "forced failure"
    else:
        for name in ("run_dop853", "run_radau"):
            real_run = getattr(engine, name)

            def failing_run(*args, _real=real_run):
                out = _real(*args)
                return (out[0], dop.R_FAILED, *out[2:])

            monkeypatch.setattr(engine, name, failing_run)
        said = "step size fell below"
    fr = ss.FrictionTensor(0.3, 0.3)
    for state, load, where in [
        (ss.State(vx=1.2), None, "slip integrator"),
        (ss.State(), _off_centre_pushes()[0], "slow start"),
    ]:
        tr = simulate_loaded(disk(), fr, state, load=load, t_end=3.0, g=G, method=method)
        assert tr.status == "step_too_small"
        assert where in tr.message and said in tr.message
        assert tr.phases[-1][0] == "slip" and tr.phases[-1][2] == pytest.approx(tr.t[-1])
