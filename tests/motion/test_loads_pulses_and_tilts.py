"""Loaded runs at their edges: short pulses, tilts that grow, gravity's pull in the statics,
messages and reprs (found in the API review of issue #13), each against independent truth:
closed forms and 1-D equations of motion integrated here by hand (scipy quad and brentq on
the analytic speed), never against the code under test.

* P1-1: a short load pulse is found whatever t_end (callable: the capped scan step;
  piecewise linear: its knots), a sine load is not sampled at its zeros.
* P1-2: ``can_stick``, ``load_factor``, ``onset`` with ``incline=`` include gravity's pull.
* P1-4: a tilt that grows in time: slip starts where tan α(t) = μ, v(t) = ∫ g (sin α − μ cos α).
* P2-1, P2-2, the messages, the reprs, t[-1] = t_end.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import brentq

import slidespin as ss
from slidespin.contact.limit_surface import limit_surface
from slidespin.contact.shapes import Rectangle
from slidespin.motion.loaded import SCAN_STEP_MAX, default_scan_step, simulate_loaded
from slidespin.contact.incline import Incline
from slidespin.motion.loads import Load
from slidespin.studies.load_tables import incline_from_table, load_from_table
from slidespin.studies.case import load_case

G = 9.81
MU = 0.3
BOX = ss.Body(Rectangle(0.2, 0.1), ss.UniformPressure(), mass=1.0)
ISO = ss.FrictionTensor(MU, MU)
MUMG = MU * BOX.mass * G  # 2.943 N: the push that static friction holds at most


# ------------------------------------------------------------------------------------------
# P1-1: short pulses are not missed when t_end is long
# ------------------------------------------------------------------------------------------
@pytest.mark.parametrize("t_end", [1.0, 10.0, 100.0])
def test_callable_pulse_found_for_any_t_end(t_end):
    # 2 μ m g during 0.5 < t < 0.6: a = μ g while pushed, then −μ g: v(0.6) = 0.1 μ g, stop
    # at 0.7 s, after x = 2 · ½ μ g 0.1² = 0.01 μ g
    pulse = Load(force=lambda t: (2.0 * MUMG if 0.5 < t < 0.6 else 0.0, 0.0))
    tr = ss.simulate(BOX, ISO, ss.State(), load=pulse, t_end=t_end)
    assert tr.status == "ok" and tr.ending == "stopped_stuck"
    kinds = [k for k, _, _ in tr.phases]
    assert kinds == ["stick", "slip", "stick"]
    (_, s0, s1), (_, p0, p1), (_, q0, q1) = tr.phases
    assert s0 == 0.0 and s1 == pytest.approx(0.5, abs=1e-9)
    assert p0 == s1 and p1 == pytest.approx(0.7, abs=1e-8)
    assert q0 == p1 and q1 == t_end
    assert tr.x[-1] == pytest.approx(0.01 * MU * G, rel=1e-8)
    assert abs(tr.y[-1]) < 1e-12 and abs(tr.phi[-1]) < 1e-12


def _pw_reference(times, forces, t_end):
    """Slip start, stop and distance of a unit mass pushed along x by a piecewise-linear
    force, integrated by hand: v(t) = ∫_{t1}^t (F − μ g) ds while v > 0."""

    def force(t):
        return float(np.interp(t, times, forces))

    def speed(t):
        pts = [p for p in times if t1 < p < t]
        return quad(force, t1, t, points=pts or None, epsabs=1e-14, epsrel=1e-13)[0] - MU * G * (
            t - t1
        )

    i = next(j for j in range(1, len(times)) if forces[j] > MUMG)
    t1 = times[i - 1] + (MUMG - forces[i - 1]) / (forces[i] - forces[i - 1]) * (
        times[i] - times[i - 1]
    )
    t_peak = times[int(np.argmax(forces))]
    t_stop = brentq(speed, t_peak + 1e-12, t_end, xtol=1e-15, rtol=1e-15)
    dist = quad(
        speed,
        t1,
        t_stop,
        points=[p for p in times if t1 < p < t_stop],
        epsabs=1e-15,
        epsrel=1e-13,
        limit=200,
    )[0]
    return t1, t_stop, dist


@pytest.mark.parametrize(
    "times, forces",
    [
        ([0.0, 0.5, 0.6, 0.7], [0.0, 0.0, 10.0, 0.0]),  # the reviewer's profile
        # a 0.2 ms spike at t = 50 s: far shorter than any scan step, found at its knots
        ([0.0, 50.0, 50.0001, 50.0002], [0.0, 0.0, 30.0, 0.0]),
    ],
)
def test_piecewise_linear_pulse_found_at_its_knots(times, forces):
    t_end = 100.0
    tr = ss.simulate(
        BOX, ISO, ss.State(), load=Load.piecewise_linear(times, forces, [0.0] * 4), t_end=t_end
    )
    t1, t_stop, dist = _pw_reference(times, forces, t_end)
    assert [k for k, _, _ in tr.phases] == ["stick", "slip", "stick"]
    assert tr.phases[1][1] == pytest.approx(t1, abs=1e-9)
    assert tr.phases[1][2] == pytest.approx(t_stop, abs=1e-8)
    assert tr.x[-1] == pytest.approx(dist, rel=1e-7)
    # even with a scan step far longer than the excursion, the knots find it
    tr2 = ss.simulate(
        BOX,
        ISO,
        ss.State(),
        load=Load.piecewise_linear(times, forces, [0.0] * 4),
        t_end=t_end,
        scan_step=30.0,
    )
    assert tr2.phases[1][1] == pytest.approx(t1, abs=1e-9)


def test_sine_load_not_sampled_at_its_zeros():
    # F = 1.5 μ m g sin(2π t / T), T = 0.1 s, t_end = 20 s: the old scan (step 0.05 s = T/2)
    # sampled the zeros only. Slip starts where sin = 2/3; with v > 0 the hand-integrated
    # speed is v(t) = (A/ω)(cos ω t1 − cos ω t) − μ g (t − t1)
    period, amp = 0.1, 1.5 * MUMG
    om = 2.0 * math.pi / period
    sine = Load(force=lambda t: (amp * math.sin(om * t), 0.0))
    # default step ≤ 1 ms; the first 6 phases suffice (the whole run has 800)
    tr = simulate_loaded(BOX, ISO, ss.State(), load=sine, t_end=20.0, max_phases=3)
    assert tr.status == "max_phases"
    t1 = math.asin(MUMG / amp) / om

    def speed(t):
        return amp / om * (math.cos(om * t1) - math.cos(om * t)) - MU * G * (t - t1)

    t_stop = brentq(speed, t1 + 0.25 * period, t1 + period, xtol=1e-15)
    assert tr.phases[0][0] == "stick" and tr.phases[0][2] == pytest.approx(t1, abs=1e-9)
    assert tr.phases[1][0] == "slip" and tr.phases[1][2] == pytest.approx(t_stop, abs=1e-8)
    # the body is at rest at each start: the next half period repeats it backwards
    assert [k for k, _, _ in tr.phases] == ["stick", "slip"] * 3
    starts = np.array([a for k, a, _ in tr.phases if k == "slip"])
    assert np.allclose(starts - 0.5 * period * np.arange(3), t1, atol=1e-8)
    ends = np.array([b for k, _, b in tr.phases if k == "slip"])
    assert np.allclose(ends - 0.5 * period * np.arange(3), t_stop, atol=1e-8)


def test_scan_step_passes_through_simulate():
    # the documented limit of a callable: an excursion shorter than the scan step may be
    # missed. With a 0.3 s step the grid 0.3, 0.6, 0.9 never lands inside 0.5 < t < 0.6
    pulse = Load(force=lambda t: (2.0 * MUMG if 0.5 < t < 0.6 else 0.0, 0.0))
    coarse = ss.simulate(BOX, ISO, ss.State(), load=pulse, t_end=10.0, scan_step=0.3)
    assert coarse.ending == "at_rest_throughout"
    fine = ss.simulate(BOX, ISO, ss.State(), load=pulse, t_end=10.0, scan_step=0.05)
    assert fine.ending == "stopped_stuck"
    with pytest.raises(ValueError, match="scan_step"):
        ss.simulate(BOX, ISO, ss.State(), load=pulse, t_end=10.0, scan_step=-1.0)


def test_default_scan_step_is_capped():
    assert default_scan_step(0.1) == pytest.approx(0.1 / 400)
    assert default_scan_step(100.0) == SCAN_STEP_MAX == 1e-3
    assert default_scan_step(1000.0) == pytest.approx(1000.0 / 200_000)


# ------------------------------------------------------------------------------------------
# P1-2: statics on an incline include gravity's downhill pull
# ------------------------------------------------------------------------------------------
@pytest.mark.parametrize("downhill", [0.0, 0.7])
def test_block_holds_on_slope_iff_tan_below_mu(downhill):
    crit = math.atan(MU)
    for alpha, holds in ((crit - 1e-6, True), (crit + 1e-6, False), (1.2, False), (0.1, True)):
        inc = Incline(alpha, downhill)
        assert ss.can_stick(BOX, ISO, (0.0, 0.0, 0.0), incline=inc) is holds
        assert ss.load_factor(BOX, ISO, (0.0, 0.0, 0.0), incline=inc) == pytest.approx(
            MU / math.tan(alpha), rel=1e-10
        )
        o = ss.onset(BOX, ISO, (0.0, 0.0, 0.0), incline=inc)
        if holds:
            assert o is None
        else:
            assert o.acceleration == pytest.approx(
                G * (math.sin(alpha) - MU * math.cos(alpha)), rel=1e-9
            )
            assert o.direction[0] == pytest.approx(math.cos(downhill), abs=1e-9)
            assert o.direction[1] == pytest.approx(math.sin(downhill), abs=1e-9)
            # simulate agrees: it slides
            tr = ss.simulate(BOX, ISO, ss.State(), incline=inc, t_end=0.1)
            assert tr.ending == "moving_at_t_end"


def test_orthotropic_slope_along_principal_axis():
    fr = ss.FrictionTensor(0.3, 0.5)
    for alpha in (0.4, 0.5):  # tan: 0.423 (holds along y, slides along x), 0.546
        along_x = Incline(alpha, 0.0)
        along_y = Incline(alpha, math.pi / 2)
        assert ss.load_factor(BOX, fr, (0.0, 0.0, 0.0), incline=along_x) == pytest.approx(
            0.3 / math.tan(alpha), rel=1e-9
        )
        assert ss.load_factor(BOX, fr, (0.0, 0.0, 0.0), incline=along_y) == pytest.approx(
            0.5 / math.tan(alpha), rel=1e-9
        )
        assert ss.can_stick(BOX, fr, (0.0, 0.0, 0.0), incline=along_y) is (math.tan(alpha) <= 0.5)


def test_extra_push_adds_to_the_pull():
    # a push P up the slope (−x) and the pull m g sin α down it: the net force |m g sin α − P|
    # against μ m g cos α
    alpha = 0.5
    inc = Incline(alpha)
    pull = BOX.mass * G * math.sin(alpha)
    cap = MU * BOX.mass * G * math.cos(alpha)
    for push in (0.5 * pull, pull - cap * 0.999, pull + cap * 1.001, 2.0 * pull):
        lam = ss.load_factor(BOX, ISO, (-push, 0.0, 0.0), incline=inc)
        assert lam == pytest.approx(cap / abs(pull - push), rel=1e-9)


# ------------------------------------------------------------------------------------------
# P1-4: a tilt that grows in time
# ------------------------------------------------------------------------------------------
def _tilt_reference(alpha, t_start, t, kinks=()):
    """v(t) = ∫ g (sin α − μ cos α) ds from the start of the slip (v > 0 throughout)."""
    pts = [k for k in kinks if t_start < k < t] or None
    return quad(
        lambda s: G * (math.sin(alpha(s)) - MU * math.cos(alpha(s))),
        t_start,
        t,
        points=pts,
        epsabs=1e-14,
        epsrel=1e-12,
    )[0]


@pytest.mark.parametrize("kind", ["callable", "piecewise"])
def test_growing_tilt_starts_where_tan_alpha_is_mu(kind):
    rate, delta, t_end = 0.1, 0.4, 5.0
    if kind == "callable":
        inc = Incline(lambda t: rate * t, downhill=delta)
    else:
        inc = Incline.piecewise_linear([0.0, 10.0], [0.0, 10.0 * rate], downhill=delta)
    tr = ss.simulate(BOX, ISO, ss.State(), incline=inc, t_end=t_end)

    def alpha(t):
        return rate * t

    t_star = math.atan(MU) / rate  # closed form: tan α(t*) = μ
    assert tr.phases[0] == ("stick", 0.0, pytest.approx(t_star, abs=1e-9))
    assert tr.phases[1][0] == "slip" and tr.ending == "moving_at_t_end"
    assert tr.t[-1] == t_end
    v_end = _tilt_reference(alpha, t_star, t_end)
    dist = quad(
        lambda t: _tilt_reference(alpha, t_star, t), t_star, t_end, epsabs=1e-15, epsrel=1e-12
    )[0]
    assert math.hypot(tr.vx[-1], tr.vy[-1]) == pytest.approx(v_end, rel=1e-8)
    assert tr.vy[-1] / tr.vx[-1] == pytest.approx(math.tan(delta), rel=1e-9)
    assert math.hypot(tr.x[-1], tr.y[-1]) == pytest.approx(dist, rel=1e-8)
    # energy: ΔKE = W_f + W_gravity, each against its hand integral
    m = BOX.mass
    w_grav = quad(
        lambda t: m * G * math.sin(alpha(t)) * _tilt_reference(alpha, t_star, t),
        t_star,
        t_end,
        epsabs=1e-15,
        epsrel=1e-12,
    )[0]
    w_fric = -quad(
        lambda t: MU * m * G * math.cos(alpha(t)) * _tilt_reference(alpha, t_star, t),
        t_star,
        t_end,
        epsabs=1e-15,
        epsrel=1e-12,
    )[0]
    assert tr.load_work[-1] == pytest.approx(w_grav, rel=1e-8)
    assert tr.gravity_work == pytest.approx(w_grav, rel=1e-8)
    assert tr.friction_work[-1] == pytest.approx(w_fric, rel=1e-8)
    assert tr.kinetic_energy[-1] == pytest.approx(0.5 * m * v_end**2, rel=1e-8)
    assert tr.energy_error < 1e-9 * tr.kinetic_energy[-1]


def test_tilt_up_and_down_sticks_slips_and_sticks_again():
    # α rises to 0.5 rad over 2 s, holds 0.5 s, falls back to 0 over 2 s
    times, angles = [0.0, 2.0, 2.5, 4.5], [0.0, 0.5, 0.5, 0.0]
    inc = Incline.piecewise_linear(times, angles)

    def alpha(t):
        return float(np.interp(t, times, angles))

    def speed(t):  # closed form: on a segment α = α₀ + r (s − s₀), ∫ sin α = Δ(−cos α)/r
        total = 0.0
        for s0, s1, a0, a1 in zip(
            times[:-1] + [times[-1]], times[1:] + [math.inf], angles, angles[1:] + [angles[-1]]
        ):
            lo, hi = max(s0, t_star), min(s1, t)
            if hi <= lo:
                continue
            r = (a1 - a0) / (s1 - s0) if math.isfinite(s1) else 0.0
            al, ah = a0 + r * (lo - s0), a0 + r * (hi - s0)
            if r == 0.0:
                total += (hi - lo) * (math.sin(a0) - MU * math.cos(a0))
            else:
                total += (math.cos(al) - math.cos(ah) - MU * (math.sin(ah) - math.sin(al))) / r
        return G * total

    t_star = math.atan(MU) / 0.25
    assert speed(3.0) == pytest.approx(_tilt_reference(alpha, t_star, 3.0, times), rel=1e-10)
    t_stop = brentq(speed, 3.4, 8.0, xtol=1e-14)
    tr = ss.simulate(BOX, ISO, ss.State(), incline=inc, t_end=8.0)
    assert [k for k, _, _ in tr.phases] == ["stick", "slip", "stick"]
    assert tr.phases[1][1] == pytest.approx(t_star, abs=1e-9)
    assert tr.phases[1][2] == pytest.approx(t_stop, abs=1e-7)
    assert tr.ending == "stopped_stuck" and tr.t[-1] == 8.0


def test_time_varying_tilt_refused_where_a_fixed_plane_is_needed():
    inc = Incline(lambda t: 0.1 * t)
    with pytest.raises(ValueError, match="varies in time"):
        ss.can_stick(BOX, ISO, (0.0, 0.0, 0.0), incline=inc)
    with pytest.raises(ValueError, match="t_end"):
        ss.simulate(BOX, ISO, ss.State(), incline=inc, t_end=None, load=Load())
    with pytest.raises(ValueError, match=r"angle\(2\.0\)"):  # the tilt leaves [0, π/2)
        Incline(lambda t: t).angle_at(2.0)


# ------------------------------------------------------------------------------------------
# P2-1, P2-2 and messages
# ------------------------------------------------------------------------------------------
def test_load_passed_positionally_is_explained():
    with pytest.raises(ValueError, match="load=, incline=, t_end= by keyword"):
        ss.simulate(BOX, ISO, ss.State(), Load(force=(5.0, 0.0)))
    with pytest.raises(ValueError, match="by keyword"):
        ss.simulate(BOX, ISO, ss.State(), 9.81, Incline(0.2))


def test_force_alias_in_case_tables(tmp_path):
    assert load_from_table({"force": [3.0, -1.0], "torque": 0.5}).wrench(0.0) == (3.0, -1.0, 0.5)
    with pytest.raises(ValueError, match="both 'force' and 'fy'"):
        load_from_table({"force": [3.0, 0.0], "fy": 1.0})
    with pytest.raises(ValueError, match="force"):
        load_from_table({"force": [3.0, 0.0, 1.0]})
    path = tmp_path / "push.toml"
    path.write_text(
        '[patch]\nshape = "rectangle"\nlength = 0.2\nwidth = 0.1\n[pressure]\nlaw = "uniform"\n'
        "[friction]\nfx = 0.3\nfy = 0.3\n[body]\nmass = 1.0\n[initial]\n"
        "[load]\nforce = [5.0, 0.0]\n[solver]\nt_end = 0.5\n"
    )
    case = load_case(path)
    assert case.load == Load(force=(5.0, 0.0))


@pytest.mark.parametrize(
    "build, words",
    [
        (lambda: incline_from_table({"angle_deg": 95}), ["angle_deg", "95", "[0, 90)"]),
        (lambda: Incline(30), ["rad", "math.radians(30)"]),
        (lambda: Incline(np.float64(30.0)), ["rad", "math.radians"]),
        (lambda: load_from_table({"fx": "ten"}), ["fx", "'ten'"]),
        (lambda: Load(at=(1e7, 0.0)), ["at[0]", "1e+06"]),
        (
            # finite at t = 0 (checked when the load is built), NaN later
            lambda: Load(force=lambda t: (math.nan if t > 0.25 else 0.0, 0.0)).force_at(
                np.float64(0.5)
            ),
            ["force(0.5)"],
        ),
        (
            lambda: load_from_table(
                {"times": [0, 1], "profile_fx": np.array([0.0, 1.0, 2.0]), "profile_fy": [0, 0]}
            ),
            ["profile_fx", "[0.0, 1.0, 2.0]"],
        ),
        (lambda: Load.piecewise_linear(np.array([1.0, 0.0]), [0, 1], [0, 0]), ["times"]),
        (lambda: Incline.piecewise_linear([0.0, 1.0], [0.0, 2.0]), ["angles", "2.0"]),
    ],
)
def test_messages_name_the_input_without_numpy_reprs(build, words):
    with pytest.raises(ValueError) as info:
        build()
    msg = str(info.value)
    assert "np.float64" not in msg and "array(" not in msg, msg
    for w in words:
        assert w in msg, (w, msg)


# ------------------------------------------------------------------------------------------
# reprs and the final time
# ------------------------------------------------------------------------------------------
def test_loaded_trajectory_repr_and_final_time():
    tr = ss.simulate(BOX, ISO, ss.State(vx=1.0), load=Load(force=(1.0, 0.0)), t_end=1.0)
    assert tr.t[-1] == 1.0  # exactly t_end (no round-off from the natural time unit)
    text = repr(tr)
    assert len(text) < 400 and "array" not in text
    for w in ("status='ok'", "ending='", "t_final=1 s", "phases=", "final_position="):
        assert w in text, text
    html = tr._repr_html_()
    assert html.startswith("<table") and "array" not in html and len(html) < 4000
    # a stop before t_end is not moved onto t_end; the body is at rest, then stuck till t_end
    s = ss.simulate(BOX, ISO, ss.State(vx=0.5), t_end=10.0)
    v0 = 0.5
    assert s.t_stop == pytest.approx(v0 / (MU * G), rel=1e-9) and s.t[-1] == 10.0


def test_limit_surface_repr_is_short():
    ls = limit_surface(BOX, ISO, n=400)
    text = repr(ls)
    assert len(text) < 400 and "array" not in text and "n=400" in text


def test_tilt_profile_in_a_case_file(tmp_path):
    # [incline] times + profile_angle_deg: α = 3° per second, downhill along +y
    path = tmp_path / "tilt.toml"
    path.write_text(
        '[patch]\nshape = "rectangle"\nlength = 0.2\nwidth = 0.1\n[pressure]\nlaw = "uniform"\n'
        "[friction]\nfx = 0.3\nfy = 0.3\n[body]\nmass = 1.0\n[initial]\n"
        "[incline]\ntimes = [0.0, 10.0]\nprofile_angle_deg = [0.0, 30.0]\ndownhill_deg = 90.0\n"
        "[solver]\nt_end = 7.0\n"
    )
    case = load_case(path)
    rate = math.radians(3.0)
    assert case.incline.angle_at(4.0) == pytest.approx(4.0 * rate, rel=1e-15)
    tr = ss.simulate(
        case.body, case.friction, case.initial_state, incline=case.incline, t_end=case.t_end
    )
    t_star = math.atan(MU) / rate
    assert tr.phases[0][2] == pytest.approx(t_star, abs=1e-9)
    v_end = _tilt_reference(lambda t: rate * t, t_star, 7.0)
    # it slides straight down (+y): to the integration's accuracy on the direction (the
    # explicit stepper carries the direction's round-off up to about its tolerance)
    assert tr.vy[-1] == pytest.approx(v_end, rel=1e-8) and abs(tr.vx[-1]) < 1e-9 * v_end
    for bad, words in [
        ({"times": [0.0, 1.0], "profile_angle_deg": [0.0, 95.0]}, ["profile_angle_deg", "[0, 90)"]),
        ({"times": [0.0, 1.0], "profile_angle": [0.0, 2.0]}, ["profile_angle", "2.0"]),
        ({"times": [0.0, 1.0], "profile_angle": [0.0, 0.1], "angle": 0.1}, ["not both"]),
        ({"profile_angle": [0.0, 0.1]}, ["times"]),
    ]:
        with pytest.raises(ValueError) as info:
            incline_from_table(bad)
        assert all(w in str(info.value) for w in words), str(info.value)
