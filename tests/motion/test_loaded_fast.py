"""The compiled loaded engine (MODEL §11) against independent truth.

Truth here is never a number printed by an engine: closed forms (a box pushed by a ramped
force, integrated by hand as piecewise polynomials; a push that grazes the threshold, whose
stop is where the impulse beyond μ m g balances; a block on a slope below and above the
friction angle; a disk pushed along a slope; an ellipse twisted about its centre, whose
friction torque is a one-dimensional quadrature written here), the energy balance (work of
the loads = kinetic energy change + friction dissipation), symmetry (a push through G along
an axis neither turns the box nor moves it sideways), and, where nothing closed is known,
agreement with the Python path (``method="scipy"``), computed alongside. The events: the
slip starts where the gauge of C at the load reaches 1 + GAUGE_TOL, to 1e-12 s; the stops
are located exactly, to the integration's accuracy (1e-12 s at rtol 1e-12, and for a
grazing push at the default).

Measured before the compiled engine (the Python path, then the default; 2 shared cores):
the pushed box of ``examples/pushed_box.toml`` took 330 to 850 ms and hit its closed-form
distance to 3.9e-10; the compiled engine takes 1.4 to 2.5 ms and hits it to 1e-11
(``benchmarks/loaded_speed.py`` prints the ratios). The tolerances below are the claims.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from numpy.polynomial import Polynomial as Poly
from scipy.integrate import quad

import slidespin as ss
from slidespin.contact.incline import Incline
from slidespin.contact.shapes import Rectangle
from slidespin.motion.loaded import GAUGE_TOL, simulate_loaded
from slidespin.motion.loads import Load

G = 9.81
MU = 0.35
BOX = ss.Body(Rectangle(0.4, 0.3), ss.UniformPressure(), mass=5.0)
ISO = ss.FrictionTensor.isotropic(MU)
TIMES, FORCES = [0.0, 2.0, 3.0, 3.1], [0.0, 25.0, 25.0, 0.0]
PUSH = Load.piecewise_linear(TIMES, FORCES, [0.0] * 4)


def ramp_truth(times, fx, m, mu, g=G):
    """Start, stop, distance and load work of a box pushed along x through G by a
    piecewise-linear force: v' = (F − μ m g)/m while it slides, by hand (polynomials)."""
    mg = mu * m * g
    t0 = next(
        ta + (mg - fa) / (fb - fa) * (tb - ta)
        for ta, tb, fa, fb in zip(times[:-1], times[1:], fx[:-1], fx[1:])
        if fb > mg >= fa
    )
    v = x = work = 0.0
    for ta, tb, fa, fb in zip(times[:-1], times[1:], fx[:-1], fx[1:]):
        if tb <= t0:
            continue
        slope = (fb - fa) / (tb - ta)
        force = Poly([fa - slope * ta, slope])
        lo = max(ta, t0)
        vel = ((force - mg) / m).integ(lbnd=lo) + v
        x += vel.integ(lbnd=lo)(tb)
        work += (force * vel).integ(lbnd=lo)(tb)
        v = vel(tb)
    t1 = times[-1] + v / (mu * g)  # no force after the last sample: decelerates at μ g
    x += 0.5 * v * v / (mu * g)
    return t0, t1, x, work


# ------------------------------------------------------------------------------------------
# the pushed box: stick, slip, stick
# ------------------------------------------------------------------------------------------
def test_pushed_box_against_its_closed_form():
    tr = simulate_loaded(BOX, ISO, ss.State(), load=PUSH, t_end=5.0)
    t0, t1, dist, work = ramp_truth(TIMES, FORCES, BOX.mass, MU)
    assert tr.status == "ok" and tr.ending == "stopped_stuck"
    assert [k for k, _, _ in tr.phases] == ["stick", "slip", "stick"]
    # stick → slip: where the gauge of C at the load reaches 1 + GAUGE_TOL (the engine
    # holds loads within 1e-12 of the threshold), γ = F(t)/(μ m g) here, to 1e-12 s
    t_gauge = t0 * (1.0 + GAUGE_TOL)
    assert 0.0 <= tr.phases[1][1] - t_gauge <= 1e-12
    assert tr.phases[0][2] == tr.phases[1][1]
    # slip → stick: the stop, to the integration's accuracy (5e-11 s at rtol 1e-10)
    assert tr.phases[1][2] == pytest.approx(t1, abs=5e-11)
    assert tr.t_stop == tr.phases[1][2] and tr.t[-1] == 5.0
    assert tr.x[-1] == pytest.approx(dist, rel=1e-10)
    # symmetry: a push through G along an axis of the box neither turns it nor moves it
    # sideways
    assert np.all(tr.y == 0.0) and np.all(tr.phi == 0.0) and np.all(tr.omega == 0.0)
    # energy: the load's work = friction dissipation (μ m g × distance) + ΔKE (= 0)
    assert tr.load_work[-1] == pytest.approx(work, rel=1e-9)
    assert -tr.friction_work[-1] == pytest.approx(MU * BOX.mass * G * dist, rel=1e-9)
    assert tr.kinetic_energy[-1] == 0.0
    assert tr.energy_error <= 1e-9 * work
    ke = tr.kinetic_energy
    assert np.max(np.abs(ke - ke[0] - tr.load_work - tr.friction_work)) <= 1e-9 * work
    # the knots of the push are steps of the integration (the load's slope jumps there)
    for knot in (2.0, 3.0, 3.1):
        assert np.min(np.abs(tr.t - knot)) <= 1e-12


def test_pushed_box_stop_converges_with_the_tolerance():
    """The slip → stick event is located exactly; what remains is the integration's error,
    which falls with rtol (to 1e-12 s at rtol 1e-12)."""
    _, t1, dist, _ = ramp_truth(TIMES, FORCES, BOX.mass, MU)
    errors = []
    for rtol in (1e-10, 1e-12):
        tr = simulate_loaded(BOX, ISO, ss.State(), load=PUSH, t_end=5.0, rtol=rtol)
        errors.append(abs(tr.phases[1][2] - t1))
        assert tr.x[-1] == pytest.approx(dist, rel=10 * rtol)
    assert errors[1] <= 1e-12 < errors[0]


def test_pushed_box_from_the_case_file_is_the_example():
    """examples/pushed_box.toml is this box and push (its comment: slip at 1.3734 s)."""
    from pathlib import Path

    from slidespin.studies.case import load_case

    case = load_case(Path(__file__).resolve().parents[2] / "examples" / "pushed_box.toml")
    assert case.t_end == 5.0 and case.load == PUSH
    tr = ss.simulate(case.body, case.friction, case.initial_state, load=case.load, t_end=case.t_end)
    t0, t1, dist, _ = ramp_truth(TIMES, FORCES, BOX.mass, MU)
    assert t0 == pytest.approx(1.3734, abs=1e-12)
    assert tr.phases[1][1] == pytest.approx(t0, abs=2e-12)
    assert tr.x[-1] == pytest.approx(dist, rel=1e-10)


# ------------------------------------------------------------------------------------------
# slopes and pushes on a disk, a twisted ellipse
# ------------------------------------------------------------------------------------------
@pytest.mark.parametrize("delta", [0.0, 0.3])
def test_block_on_a_slope_below_and_above_the_friction_angle(delta):
    disk = ss.Body(ss.Circle(0.05), ss.UniformPressure(), 1.0)
    fr = ss.FrictionTensor.isotropic(0.3)
    below = simulate_loaded(
        disk, fr, ss.State(), incline=Incline(math.atan(0.3) - 1e-6, delta), t_end=1.0, g=G
    )
    assert below.ending == "at_rest_throughout" and below.x[-1] == 0.0
    alpha, t_end = math.atan(0.3) + 0.1, 1.0
    tr = simulate_loaded(disk, fr, ss.State(), incline=Incline(alpha, delta), t_end=t_end, g=G)
    acc = G * (math.sin(alpha) - 0.3 * math.cos(alpha))
    dist = 0.5 * acc * t_end**2
    assert tr.status == "ok" and tr.ending == "moving_at_t_end" and tr.t[-1] == t_end
    assert math.hypot(tr.x[-1], tr.y[-1]) == pytest.approx(dist, rel=1e-10)
    assert math.atan2(tr.y[-1], tr.x[-1]) == pytest.approx(delta, abs=1e-12)
    assert tr.speed[-1] == pytest.approx(acc * t_end, rel=1e-10)
    assert tr.load_work[-1] == pytest.approx(tr.gravity_work, rel=1e-10)
    assert tr.energy_error <= 1e-9 * tr.kinetic_energy[-1]


def test_constant_push_on_a_slope():
    """A disk pushed by (1, 0.5) N on a slope: it slides along the resultant of the push and
    the pull, with a = |Q + m g sin α d|/m − μ g cos α (isotropic friction, no turning)."""
    disk = ss.Body(ss.Circle(0.05), ss.UniformPressure(), 1.0)
    alpha, delta, mu, t_end = 0.2, 0.3, 0.3, 1.0
    tr = simulate_loaded(
        disk,
        ss.FrictionTensor.isotropic(mu),
        ss.State(),
        load=Load(force=(1.0, 0.5)),
        incline=Incline(alpha, delta),
        t_end=t_end,
        g=G,
    )
    pull = G * math.sin(alpha)
    q = np.array([1.0 + pull * math.cos(delta), 0.5 + pull * math.sin(delta)])
    acc = np.linalg.norm(q) - mu * G * math.cos(alpha)
    end = 0.5 * acc * t_end**2 * q / np.linalg.norm(q)
    assert tr.ending == "moving_at_t_end" and [k for k, _, _ in tr.phases] == ["slip"]
    assert tr.x[-1] == pytest.approx(end[0], rel=1e-10)
    assert tr.y[-1] == pytest.approx(end[1], rel=1e-10)
    assert abs(tr.phi[-1]) <= 1e-15
    assert tr.energy_error <= 1e-9 * tr.kinetic_energy[-1]


def test_torque_on_an_ellipse_spins_it_about_its_centre():
    """A uniform elliptic plate twisted by T beyond its friction torque T_c spins about its
    centre (pure spin is invariant for a centrally symmetric pressure): φ = ½ (T − T_c) t²/I,
    T_c = μ p ∫∫ r dA = μ p ∫ R(θ)³/3 dθ, R the ellipse's radius at θ (quadrature here)."""
    a, b, m, mu, torque, t_end = 0.06, 0.03, 0.5, 0.3, 0.15, 1.0
    body = ss.Body(ss.Ellipse(a, b), ss.UniformPressure(), m)
    radius = lambda th: a * b / math.hypot(b * math.cos(th), a * math.sin(th))  # noqa: E731
    integral = quad(lambda th: radius(th) ** 3 / 3.0, 0.0, 2.0 * math.pi, epsabs=0.0, epsrel=1e-13)
    t_c = mu * m * G / (math.pi * a * b) * integral[0]
    tr = simulate_loaded(
        body, ss.FrictionTensor.isotropic(mu), ss.State(), load=Load(torque=torque), t_end=t_end
    )
    assert torque > t_c and tr.ending == "moving_at_t_end"
    phi = 0.5 * (torque - t_c) / body.moment_of_inertia * t_end**2
    assert tr.phi[-1] == pytest.approx(phi, rel=1e-10)
    assert tr.omega[-1] == pytest.approx(2.0 * phi / t_end, rel=1e-10)
    assert abs(tr.x[-1]) <= 1e-15 and abs(tr.y[-1]) <= 1e-15
    assert tr.load_work[-1] == pytest.approx(torque * phi, rel=1e-10)
    assert -tr.friction_work[-1] == pytest.approx(t_c * phi, rel=1e-9)
    assert tr.energy_error <= 1e-9 * tr.load_work[-1]
    below = simulate_loaded(
        body,
        ss.FrictionTensor.isotropic(mu),
        ss.State(),
        load=Load(torque=t_c * (1.0 - 1e-9)),
        t_end=t_end,
    )
    assert below.ending == "at_rest_throughout"


# ------------------------------------------------------------------------------------------
# no closed form: energy, and the Python path computed alongside
# ------------------------------------------------------------------------------------------
def test_off_centre_push_agrees_with_the_python_path_and_balances_energy():
    push = Load.piecewise_linear(
        [0.0, 1.0, 1.5, 1.6], [0.0, 30.0, 30.0, 0.0], [0.0] * 4, at=(0.1, 0.12)
    )
    fast = simulate_loaded(BOX, ISO, ss.State(), load=push, t_end=3.0)
    slow = simulate_loaded(BOX, ISO, ss.State(), load=push, t_end=3.0, method="scipy")
    assert [k for k, _, _ in fast.phases] == [k for k, _, _ in slow.phases]
    for (_, a0, b0), (_, a1, b1) in zip(fast.phases, slow.phases):
        assert a0 == pytest.approx(a1, rel=1e-9) and b0 == pytest.approx(b1, rel=1e-9)
    reach = math.hypot(fast.x[-1], fast.y[-1])
    assert abs(fast.x[-1] - slow.x[-1]) <= 1e-9 * reach
    assert abs(fast.y[-1] - slow.y[-1]) <= 1e-9 * reach
    assert abs(fast.phi[-1] - slow.phi[-1]) <= 1e-9  # rad (it turns by 6.7e-3 rad)
    ke = fast.kinetic_energy
    scale = fast.load_work[-1]
    assert np.max(np.abs(ke - ke[0] - fast.load_work - fast.friction_work)) <= 1e-9 * scale
    assert np.all(np.diff(fast.friction_work) <= 0.0)  # friction only dissipates


def test_anisotropic_ellipse_on_a_slope_balances_energy():
    body = ss.Body(ss.Ellipse(0.06, 0.03), ss.LinearPressure(0.005, 0.002), 0.5)
    friction = ss.FrictionTensor(0.25, 0.4, 0.03)
    slope = Incline(0.35, downhill=1.0)
    state = ss.State(vx=-1.0, vy=0.3, omega=15.0)
    fast = simulate_loaded(body, friction, state, incline=slope, t_end=1.0, g=G)
    slow = simulate_loaded(body, friction, state, incline=slope, t_end=1.0, g=G, method="scipy")
    ke0 = fast.kinetic_energy[0]
    assert fast.energy_error <= 1e-9 * ke0
    assert fast.load_work[-1] == pytest.approx(fast.gravity_work, rel=1e-9)
    for name in ("x", "y"):
        assert getattr(fast, name)[-1] == pytest.approx(getattr(slow, name)[-1], abs=1e-9 * 0.06)
    assert fast.phi[-1] == pytest.approx(slow.phi[-1], abs=1e-9)


def test_a_load_given_as_a_function_takes_the_python_path():
    """The same push as a Python function and as a table: the same motion (the function by
    the Python path, the table by the compiled engine); method="compiled" refuses the
    function by name."""
    f = Load(force=lambda t: (float(np.interp(t, TIMES, FORCES)), 0.0))
    tr = simulate_loaded(BOX, ISO, ss.State(), load=f, t_end=5.0)
    _, t1, dist, _ = ramp_truth(TIMES, FORCES, BOX.mass, MU)
    assert tr.phases[1][2] == pytest.approx(t1, abs=1e-8)
    assert tr.x[-1] == pytest.approx(dist, rel=1e-8)
    with pytest.raises(ValueError, match="method = 'compiled'"):
        simulate_loaded(BOX, ISO, ss.State(), load=f, t_end=5.0, method="compiled")


def test_the_compiled_engine_run_as_python_gives_the_same_motion():
    """NUMBA_DISABLE_JIT=1 runs the compiled engine as plain Python (a fresh process): the
    pushed box again, against its closed form."""
    import json
    import os
    import subprocess
    import sys

    code = (
        "import json, slidespin as ss\n"
        "from slidespin.contact.shapes import Rectangle\n"
        "from slidespin.motion.loaded import simulate_loaded\n"
        "from slidespin.motion.loads import Load\n"
        "box = ss.Body(Rectangle(0.4, 0.3), ss.UniformPressure(), mass=5.0)\n"
        f"push = Load.piecewise_linear({TIMES}, {FORCES}, [0.0] * 4)\n"
        "tr = simulate_loaded(box, ss.FrictionTensor(0.35, 0.35), ss.State(), load=push,"
        " t_end=5.0)\n"
        "print(json.dumps([tr.phases[1][1], tr.phases[1][2], float(tr.x[-1]), tr.status]))\n"
    )
    env = {**os.environ, "NUMBA_DISABLE_JIT": "1"}
    out = subprocess.run(
        [sys.executable, "-c", code], env=env, capture_output=True, text=True, timeout=600
    )
    assert out.returncode == 0, out.stderr
    start, stop, x, status = json.loads(out.stdout.strip().splitlines()[-1])
    t0, t1, dist, _ = ramp_truth(TIMES, FORCES, BOX.mass, MU)
    assert status == "ok"
    assert 0.0 <= start - t0 * (1.0 + GAUGE_TOL) <= 1e-12
    assert stop == pytest.approx(t1, abs=5e-11) and x == pytest.approx(dist, rel=1e-10)


def graze_truth(delta, excess, m, fc):
    """Stop (after the peak at t1 = 1 s) and distance of a body started δ = ``delta`` after
    the threshold by the triangle push 0 → (1 + excess) fc (at t1) → 0, by hand: with
    D = t1 − t_a = excess/(1 + excess) (F(t_a) = fc; no cancellation) and k the push's rate,
    v = k [(t − t_a)² − δ²]/(2m) to t1, then v1 + k (D u − u²/2)/m at t1 + u, zero at
    u* = D + √(D² + 2 m v1/k)."""
    k = fc * (1.0 + excess)  # N/s: the push rises to its peak in 1 s
    d = excess / (1.0 + excess)
    v1 = k * (d * d - delta * delta) / (2.0 * m)
    u = d + math.sqrt(d * d + 2.0 * m * v1 / k)
    x_rise = k / (2.0 * m) * ((d**3 - delta**3) / 3.0 - delta * delta * (d - delta))
    x_fall = v1 * u + k / m * (d * u * u / 2.0 - u**3 / 6.0)
    return u, x_rise + x_fall


@pytest.mark.parametrize("excess", [1e-3, 1e-6])
def test_a_push_that_grazes_the_threshold_stops_where_the_impulse_balances(excess):
    """A triangle push whose peak is beyond μ m g by 1e-3 or 1e-6 of it: the box starts,
    never reaches the slow speed, and stops again where ∫ (F − μ m g) dt = 0 (for the start
    at the threshold, 1 + √2 times the rise beyond the peak): the slow start's stall (ds/dt
    through 0 at the peak) and the stop of the implicit stepper in τ, to 1e-12 s."""
    fc = MU * BOX.mass * G
    peak = fc * (1.0 + excess)
    load = Load.piecewise_linear([0.0, 1.0, 2.0], [0.0, peak, 0.0], [0.0] * 3)
    tr = simulate_loaded(BOX, ISO, ss.State(), load=load, t_end=3.0)
    assert tr.status == "ok" and tr.ending == "stopped_stuck"
    assert [k for k, _, _ in tr.phases] == ["stick", "slip", "stick"]
    t_a = fc / peak  # F = μ m g
    start, stop = tr.phases[1][1], tr.phases[1][2]
    assert 0.0 <= start - t_a * (1.0 + GAUGE_TOL) <= 1e-12
    u, dist = graze_truth(start - t_a, excess, BOX.mass, fc)
    assert u == pytest.approx((1.0 + math.sqrt(2.0)) * excess, rel=2 * excess)
    assert stop - 1.0 == pytest.approx(u, abs=1e-12)
    assert tr.x[-1] == pytest.approx(dist, rel=1e-8)
    if excess == 1e-6:  # below the slow speed throughout: the slow start's stall and back
        assert np.all(tr.speed <= 1e-6)


def test_the_python_slow_start_takes_over_where_the_compiled_one_stops(monkeypatch):
    """Where the compiled Newton solve of the slaved direction fails (forced here at the
    first step), the Python slow start goes on from the state reached: the same motion."""
    import slidespin.motion._loaded_engine as engine
    from slidespin.motion._loaded_dop853 import R_SLAVE
    from slidespin.motion._loaded_flow import MODE_SLAVED

    ref = simulate_loaded(BOX, ISO, ss.State(), load=PUSH, t_end=5.0)
    real = engine.run_dop853

    def failing(slip, mode, y0, *args):
        if mode == MODE_SLAVED:
            return y0.copy(), R_SLAVE, 0, 0, np.empty((0, 9))
        return real(slip, mode, y0, *args)

    monkeypatch.setattr(engine, "run_dop853", failing)
    tr = simulate_loaded(BOX, ISO, ss.State(), load=PUSH, t_end=5.0)
    assert tr.status == "ok" and [k for k, _, _ in tr.phases] == ["stick", "slip", "stick"]
    assert tr.phases[1][1] == ref.phases[1][1]
    assert tr.phases[1][2] == pytest.approx(ref.phases[1][2], rel=1e-10)
    assert tr.x[-1] == pytest.approx(ref.x[-1], rel=1e-9)


def test_the_compiled_load_is_the_load_s_own_definition():
    """The compiled engine reads the load from a table of its knots: at any time and body
    angle it is Load.wrench and the slope's pull (slidespin.motion.loads.applied_wrench),
    for a body-frame force off G with a torque and a tilt, each piecewise linear on its own
    knots, and beyond their ends."""
    from slidespin.motion._loaded_flow import applied, load_table
    from slidespin.motion._loaded_problem import _Problem
    from slidespin.motion.loads import applied_wrench

    load = Load(
        force=Load.piecewise_linear([0.0, 1.0, 2.5], [0.0, 3.0, -1.0], [1.0, 2.0, 0.0]).force,
        torque=Load.piecewise_linear([0.5, 2.0], [0.0, 0.0], [0.0, 0.0], [0.1, -0.2]).torque,
        frame="body",
        at=(0.05, -0.02),
    )
    tilt = Incline.piecewise_linear([0.0, 3.0], [0.1, 0.4], downhill=0.7)
    prob = _Problem(BOX, ISO, load, tilt, G)
    tab = load_table(prob)
    mg = BOX.mass * G
    rng = np.random.default_rng(3)
    for t in np.concatenate([[0.0, 0.5, 1.0, 2.0, 2.5, 3.0, 4.0], rng.uniform(0.0, 4.0, 20)]):
        for phi in (0.0, 0.9, -2.0):
            bx, by, bm, nf = applied(tab, t / prob.t_unit, phi)
            qx, qy, mz = applied_wrench(BOX, t, phi, load, tilt, G)
            k = BOX.radius_of_gyration
            assert bx * mg == pytest.approx(qx, abs=1e-14 * mg)
            assert by * mg == pytest.approx(qy, abs=1e-14 * mg)
            assert bm * k * mg == pytest.approx(mz, abs=1e-14 * mg * 0.25)
            assert nf == pytest.approx(math.cos(tilt.angle_at(t)), abs=1e-15)
