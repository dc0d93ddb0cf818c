"""Bounded work for every input of a loaded run (MODEL §11): a budget that says it was
reached, or a named error before any work.

* a scan of a stick phase finer than SCAN_SAMPLES_MAX samples per run is refused before it
  starts, naming scan_step, t_end and the limit (1e-9 s over 20 s asked for 22 GiB);
* rtol at its documented bound, 1e-3, runs every path (compiled and Python) to a finite end
  (a trial step of ln s beyond the floats is rejected, not raised or propagated);
* a box spun up forever by a constant torque under anisotropic friction ends at the step
  budget with status ``max_steps`` (it ran past 400 s before);
* a run to t_end = 1e7 s ends with the closed form where there is one.

No wall-clock assertion: the budgets are counts, and the statuses and messages say which one
ended the run.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import slidespin as ss
from slidespin.contact.incline import Incline
from slidespin.contact.shapes import Rectangle
from slidespin.motion.loaded import SCAN_SAMPLES_MAX, simulate_loaded
from slidespin.motion.loads import Load

G = 9.81
BOX = ss.Body(Rectangle(0.4, 0.3), ss.UniformPressure(), mass=5.0)
ISO = ss.FrictionTensor.isotropic(0.35)
ANISO = ss.FrictionTensor(0.25, 0.45)
PUSH = Load.piecewise_linear([0.0, 2.0, 3.0, 3.1], [0.0, 25.0, 25.0, 0.0], [0.0] * 4)
PULSE = Load(force=lambda t: (2.0 * 0.35 * 5.0 * G if 0.5 < t < 0.6 else 0.0, 0.0))


def test_a_scan_beyond_the_sample_limit_is_refused_before_it_starts():
    with pytest.raises(ValueError) as err:
        ss.simulate(BOX, ISO, ss.State(), load=PULSE, t_end=20.0, scan_step=1e-9)
    msg = str(err.value)
    assert "scan_step = 1e-09 s" in msg and "t_end = 20.0 s" in msg
    assert f"{SCAN_SAMPLES_MAX:,}" in msg and "2e+10 samples" in msg
    # the same for a table given a scan step, and for a tilt in time
    with pytest.raises(ValueError, match="scan_step"):
        simulate_loaded(BOX, ISO, ss.State(), load=PUSH, t_end=100.0, scan_step=1e-5)
    with pytest.raises(ValueError, match="scan_step"):
        simulate_loaded(
            BOX, ISO, ss.State(), incline=Incline(lambda t: 0.01 * t), t_end=10.0, scan_step=1e-6
        )
    # at the limit it runs (a constant load is never scanned: any step is accepted)
    tr = simulate_loaded(BOX, ISO, ss.State(), load=PULSE, t_end=1.0, scan_step=1e-6)
    assert tr.ending == "stopped_stuck"
    simulate_loaded(BOX, ISO, ss.State(), load=Load((1.0, 0.0)), t_end=20.0, scan_step=1e-12)


@pytest.mark.parametrize("method", ["auto", "scipy"])
@pytest.mark.parametrize(
    "case",
    [
        dict(body=BOX, friction=ISO, initial_state=ss.State(), load=PUSH, t_end=5.0),
        dict(body=BOX, friction=ANISO, initial_state=ss.State(), load=Load(torque=5.0), t_end=1.0),
        dict(
            body=ss.Body(ss.Ellipse(0.06, 0.03), ss.LinearPressure(0.005, 0.002), 0.5),
            friction=ss.FrictionTensor(0.25, 0.4, 0.03),
            initial_state=ss.State(vx=-1.0, vy=0.3, omega=15.0),
            incline=Incline(0.35, downhill=1.0),
            t_end=1.0,
        ),
        dict(body=BOX, friction=ISO, initial_state=ss.State(vx=1.2)),
        dict(body=BOX, friction=ISO, initial_state=ss.State(), load=PULSE, t_end=1.0),
    ],
    ids=["pushed-box", "twisted-box", "ellipse-on-slope", "coasting", "pulse"],
)
def test_rtol_at_its_bound_runs_every_path_to_a_finite_end(case, method):
    tr = simulate_loaded(**case, rtol=1e-3, method=method)
    assert tr.status == "ok"
    for name in ("t", "x", "y", "phi", "vx", "vy", "omega", "kinetic_energy", "load_work"):
        assert np.all(np.isfinite(getattr(tr, name))), name
    assert math.isfinite(tr.energy_error)


def test_rtol_at_its_bound_is_still_about_right():
    """rtol = 1e-3 is loose, not wrong: the pushed box's distance to about 1e-3."""
    tight = simulate_loaded(BOX, ISO, ss.State(), load=PUSH, t_end=5.0)
    loose = simulate_loaded(BOX, ISO, ss.State(), load=PUSH, t_end=5.0, rtol=1e-3)
    assert loose.x[-1] == pytest.approx(tight.x[-1], rel=1e-2)
    assert loose.phases[1][2] == pytest.approx(tight.phases[1][2], rel=1e-2)


def test_a_box_spun_up_forever_ends_at_the_step_budget():
    """A constant torque beyond the box's friction torque spins it up without end (ω grows
    linearly, each turn needs its steps under anisotropic friction): to t_end = 1e4 s that is
    more steps than any budget, and the run ends at max_steps with the values reached."""
    tr = simulate_loaded(BOX, ANISO, ss.State(), load=Load(torque=5.0), t_end=1e4, max_steps=5000)
    assert tr.status == "max_steps" and "max_steps = 5000" in tr.message
    assert tr.ending == "moving_at_t_end" and tr.t[-1] < 1e4
    assert tr.t.size <= 5000 + 3  # the start, the steps, the last state
    assert tr.omega[-1] > 0.0 and tr.phi[-1] > 0.0
    assert tr.energy_error <= 1e-8 * tr.load_work[-1]
    # the default budget (2e5 steps) ends the same way (2 s, where it took more than 400 s)
    tr = simulate_loaded(BOX, ANISO, ss.State(), load=Load(torque=5.0), t_end=1e4)
    assert tr.status == "max_steps" and tr.t[-1] < 1e4


def test_the_slow_start_counts_against_the_step_budget():
    tr = simulate_loaded(BOX, ISO, ss.State(), load=PUSH, t_end=5.0, max_steps=1)
    assert tr.status == "max_steps" and tr.phases[-1][0] == "slip"
    assert tr.t[-1] < 5.0


def test_runs_to_ten_million_seconds():
    mu = 0.35
    # the pushed box stops at 3.67 s and stays: nothing to look at after its last knot
    tr = simulate_loaded(BOX, ISO, ss.State(), load=PUSH, t_end=1e7)
    assert tr.status == "ok" and tr.ending == "stopped_stuck" and tr.t[-1] == 1e7
    assert tr.phases[-1] == ("stick", tr.t_stop, 1e7)
    # a slope steeper than the friction angle: x = ½ g (sin α − μ cos α) t²
    alpha = 0.4
    tr = simulate_loaded(BOX, ISO, ss.State(), incline=Incline(alpha), t_end=1e7)
    acc = G * (math.sin(alpha) - mu * math.cos(alpha))
    assert tr.status == "ok" and tr.ending == "moving_at_t_end"
    assert tr.x[-1] == pytest.approx(0.5 * acc * 1e14, rel=1e-9)
    # sliding at the friction angle: the speed holds, x = v t (atan(0.35) in floats is the
    # friction angle to round-off: the pull and friction differ by ~1e-16 m g, which over
    # 1e7 s changes x by ~5e-9 of itself, the same in the Python path)
    tr = simulate_loaded(BOX, ISO, ss.State(vx=0.5), incline=Incline(math.atan(mu)), t_end=1e7)
    assert tr.status == "ok" and tr.ending == "steady_sliding"
    assert tr.x[-1] == pytest.approx(0.5e7, rel=2e-8)
