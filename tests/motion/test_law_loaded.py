"""Speed-dependent laws in loaded runs (MODEL §14) against independent truth: the 1-D
equation of a pulled block integrated apart (scipy, tight tolerance), the linear stability of
steady sliding on a spring with a dashpot (the decay rate (c + F′(v))/(2m) and the critical
drive speed where c + F′(v) = 0), the energy balance, and the refusals."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

import slidespin as ss
from slidespin.contact.shapes import Rectangle

G = 9.81
MUK, RATIO, VS = 0.3, 1.5, 0.02
pytestmark = pytest.mark.xdist_group("law_loaded")


def _block(m=1.0):
    return ss.Body(Rectangle(0.02, 0.02), ss.UniformPressure(), mass=m)


def _stribeck(delta=2.0):
    return ss.FrictionTensor(MUK, MUK, speed_law=ss.Stribeck(RATIO, VS, delta))


def _force(v, m=1.0, delta=2.0):
    """Kinetic friction of the block at speed v [N] (the law, a point mass)."""
    return m * G * MUK * (1.0 + (RATIO - 1.0) * math.exp(-((v / VS) ** delta)))


@pytest.mark.parametrize("delta", [2.0, 1.0])
def test_a_block_pulled_beyond_static_friction_follows_the_1d_law(delta):
    m, q = 1.0, 5.0  # Q = 5 N > μs m g = 4.41 N
    tr = ss.simulate(_block(m), _stribeck(delta), ss.State(),
                     load=ss.Load(force=(q, 0.0)), t_end=0.5, g=G)  # fmt: skip
    assert tr.status == "ok" and tr.phases[0][0] == "slip"
    ref = solve_ivp(lambda t, y: [y[1], (q - _force(y[1], m, delta)) / m], (0.0, 0.5),
                    [0.0, 0.0], method="DOP853", rtol=1e-13, atol=1e-15)  # fmt: skip
    assert tr.vx[-1] == pytest.approx(ref.y[1, -1], rel=1e-8)
    assert tr.x[-1] == pytest.approx(ref.y[0, -1], rel=1e-8)
    assert tr.energy_error <= 1e-10 * max(tr.kinetic_energy[-1], 1e-12)


def test_a_pull_below_static_friction_holds_and_above_starts():
    m = 1.0
    hold = ss.simulate(_block(m), _stribeck(), ss.State(), load=ss.Load(force=(4.4, 0.0)),
                       t_end=0.2, g=G)  # fmt: skip
    assert hold.ending == "at_rest_throughout"
    go = ss.simulate(_block(m), _stribeck(), ss.State(), load=ss.Load(force=(4.42, 0.0)),
                     t_end=0.2, g=G)  # fmt: skip
    assert go.ending != "at_rest_throughout"


def _critical_speed(c, m=1.0):
    """The drive speed above which steady sliding on a spring with a dashpot c is stable:
    c + F′(v) = 0 (the larger root; F′ < 0 for the Stribeck law with δ = 2)."""

    def slope_plus_c(v):
        return c - m * G * MUK * (RATIO - 1.0) * 2.0 * v / VS**2 * math.exp(-((v / VS) ** 2))

    return brentq(slope_plus_c, VS / math.sqrt(2.0), 20.0 * VS, xtol=1e-15)


def _steady_run(v, c, k=100.0, m=1.0, t_end=6.0, kick=1.01, max_step=None):
    fr = _stribeck()
    spring = ss.Spring(k, [(0.0, 0.0, 0.0), (100.0, 100.0 * v, 0.0)], damping=c)
    x0 = -_force(v, m) / k  # the stretch of steady sliding
    return ss.simulate(_block(m), fr, ss.State(x=x0, vx=kick * v), load=spring, t_end=t_end,
                       g=G, max_step=max_step)  # fmt: skip


def test_steady_sliding_on_a_spring_decays_at_the_linear_rate_above_the_critical_speed():
    m, k, c = 1.0, 100.0, 0.5
    vc = _critical_speed(c, m)
    v = 1.3 * vc
    tr = _steady_run(v, c, k, m, max_step=0.05)  # (dense points for the envelope)
    assert tr.status == "ok" and len(tr.phases) == 1  # it never sticks
    # linearised: m ξ'' + (c + F'(v)) ξ' + k ξ = 0, amplitude ∝ exp(−(c + F')/(2m) t)
    fprime = -m * G * MUK * (RATIO - 1.0) * 2.0 * v / VS**2 * math.exp(-((v / VS) ** 2))
    rate = (c + fprime) / (2.0 * m)
    dev = tr.vx - v
    peaks = [i for i in range(1, dev.size - 1) if dev[i] > dev[i - 1] and dev[i] >= dev[i + 1]]
    tp = tr.t[peaks]
    # the peaks of the recorded points carry the step's sampling: fit the envelope
    # through the largest |ξ'| per period
    period = 2.0 * math.pi / math.sqrt(k / m - rate**2)
    env_t, env = [], []
    for j in range(1, int(tr.t[-1] / period)):
        sel = (tr.t >= j * period) & (tr.t < (j + 1) * period)
        if sel.sum() > 20:
            i = np.argmax(np.abs(dev[sel]))
            env_t.append(tr.t[sel][i])
            env.append(abs(dev[sel][i]))
    slope = np.polyfit(env_t, np.log(env), 1)[0]
    assert tp.size > 3
    assert -slope == pytest.approx(rate, rel=2e-3)  # measured: 3e-5 (a 1 % kick)


def test_below_the_critical_speed_steady_sliding_grows_into_stick_slip():
    c = 0.5
    vc = _critical_speed(c)
    tr = _steady_run(0.8 * vc, c, t_end=8.0)
    assert tr.status == "ok"
    assert any(kind == "stick" for kind, *_ in tr.phases)


def test_energy_balance_of_a_spinning_box_under_a_law_and_a_load():
    body = ss.Body(Rectangle(0.3, 0.2), ss.UniformPressure(), mass=1.0)
    fr = ss.FrictionTensor(0.4, 0.25, 0.05, speed_law=ss.Stribeck(1.3, 0.05))
    tr = ss.simulate(body, fr, ss.State(vx=0.6, omega=5.0), load=ss.Load(force=(0.5, 0.2)),
                     t_end=0.6, g=G)  # fmt: skip
    assert tr.status == "ok"
    assert tr.energy_error <= 1e-9 * tr.kinetic_energy[0]


def test_laws_a_loaded_run_cannot_start_with_are_refused():
    with pytest.raises(ValueError, match="PowerLaw"):
        ss.simulate(_block(), ss.FrictionTensor(0.3, 0.3, speed_law=ss.PowerLaw(0.5)),
                    ss.State(vx=1.0), load=ss.Load(force=(1.0, 0.0)), t_end=1.0)  # fmt: skip
    table = ss.FrictionTensor(0.3, 0.3, speed_law=ss.SpeedTable([0.0, 1.0], [1.2, 1.0]))
    with pytest.raises(ValueError, match=r"static >= 1\.2"):
        ss.simulate(_block(), table, ss.State(), load=ss.Load(force=(1.0, 0.0)), t_end=1.0)
    ok = ss.FrictionTensor(0.3, 0.3, static=1.2,
                           speed_law=ss.SpeedTable([0.0, 1.0], [1.2, 1.0]))  # fmt: skip
    tr = ss.simulate(_block(), ok, ss.State(), load=ss.Load(force=(1.0, 0.0)), t_end=0.1)
    assert tr.status == "ok"
