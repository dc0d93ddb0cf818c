"""Fuzz of every public constructor and function (issue 11): bad input gets a ValueError that
names the parameter, never another exception, never a hang, never a silent NaN or inf.

Inputs are drawn from 0, ±tiny, ±huge, ±inf, NaN, bools, strings, None, complex numbers,
lists, numpy scalars, integers beyond float range and arbitrary floats. Each call runs under
two time limits: an interval timer that raises in Python code, and, for compiled code that no
signal can interrupt, ``faulthandler`` which dumps the stacks and ends the test process (a
failed run, not a blocked one). Results are walked and every float must be finite unless the
documentation gives the non-finite value a meaning (β* = inf for pure sliding, θ* = NaN for
pure spinning, …); those places are listed next to each check.

The number of examples is small so that the module runs in well under a minute; set
``SLIDESPIN_FUZZ_EXAMPLES=2000`` (and ``SLIDESPIN_FUZZ_RANDOM=1`` for fresh draws) to go
further.
"""

from __future__ import annotations

import contextlib
import dataclasses
import faulthandler
import math
import os
import signal

import numpy as np
import pytest
from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st

import slidespin as ss

EXAMPLES = int(os.environ.get("SLIDESPIN_FUZZ_EXAMPLES", "60"))
SOFT_SECONDS = 20  # interval timer: raises Hang in Python code
HARD_SECONDS = 120  # faulthandler: ends the process if compiled code never returns

FUZZ = settings(
    max_examples=EXAMPLES,
    deadline=None,  # the hard limits below are the time limit; a deadline would be flaky on
    # a loaded machine, and a first call may load compiled code from the cache
    derandomize=not os.environ.get("SLIDESPIN_FUZZ_RANDOM"),
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture],
    database=None,
)


class Hang(BaseException):
    """Raised by the interval timer; a BaseException so that no ``except Exception`` eats it."""


@contextlib.contextmanager
def time_limit(soft=SOFT_SECONDS, hard=HARD_SECONDS):
    def alarm(signum, frame):
        raise Hang(f"no answer within {soft} s")

    old = signal.signal(signal.SIGALRM, alarm)
    signal.setitimer(signal.ITIMER_REAL, soft)
    faulthandler.dump_traceback_later(hard, exit=True)
    try:
        yield
    finally:
        faulthandler.cancel_dump_traceback_later()
        signal.setitimer(signal.ITIMER_REAL, 0.0)
        signal.signal(signal.SIGALRM, old)


# ------------------------------------------------------------------------------------------
# inputs
# ------------------------------------------------------------------------------------------
SPECIAL = [
    0,
    0.0,
    -0.0,
    1,
    -1,
    -1.0,
    5e-324,
    1e-320,
    1e-300,
    1e-200,
    1e-13,
    1e-12,
    1e-9,
    1e-8,
    1e-6,
    1e-3,
    0.05,
    0.25,
    0.3,
    0.9999999,
    1.0,
    5.0,
    30.0,
    1e3,
    1e6,
    1e8,
    1e12,
    1e15,
    1e200,
    1e300,
    1.7976931348623157e308,
    -1e300,
    -1.7976931348623157e308,
    math.inf,
    -math.inf,
    math.nan,
    True,
    False,
    "1",
    "nan",
    "",
    None,
    10**400,
    -(10**400),
    2**64,
    2**63,
    1j,
    [1.0, 2.0],
    (0.1,),
    np.float32(0.25),
    np.int64(7),
    np.float64("nan"),
    np.bool_(True),
]
numbers = st.one_of(
    st.sampled_from(SPECIAL),
    st.floats(allow_nan=True, allow_infinity=True),
    st.integers(min_value=-(10**30), max_value=10**30),
    st.text(max_size=3),
)
arrays = st.one_of(
    numbers,
    st.lists(st.one_of(st.floats(), st.sampled_from(SPECIAL[:40])), min_size=1, max_size=4),
)

# valid objects, drawn across their whole ranges (log-uniform in magnitude)


def log_uniform(lo, hi):
    return st.floats(math.log10(lo), math.log10(hi)).map(lambda e: min(max(10.0**e, lo), hi))


@st.composite
def patches(draw):
    a = draw(st.one_of(st.sampled_from([1e-9, 1e6, 0.05]), log_uniform(1e-9, 1e6)))
    k = draw(st.one_of(st.sampled_from([1e-3, 30.0, 1.0]), log_uniform(1e-3, 30.0)))
    b = min(max(k * a, 1e-9), 1e6)
    if not 1e-3 <= b / a <= 30.0:
        b = a
    return ss.Circle(a) if draw(st.booleans()) and b == a else ss.Ellipse(a, b)


@st.composite
def laws(draw, patch=None):
    kind = draw(st.sampled_from(["uniform", "linear", "boussinesq", "hertz"]))
    if kind == "linear":
        a, b = (patch.a, patch.b) if patch is not None else (1.0, 1.0)
        r = draw(st.floats(0.0, 0.25))
        t = draw(st.floats(0.0, 2.0 * math.pi))
        return ss.LinearPressure(r * a * math.cos(t), r * b * math.sin(t))
    return {
        "uniform": ss.UniformPressure(),
        "boussinesq": ss.BoussinesqPressure(),
        "hertz": ss.HertzPressure(),
    }[kind]


coefficients = st.one_of(st.sampled_from([1e-6, 5.0, 0.3]), log_uniform(1e-6, 5.0))
frictions = st.builds(
    ss.FrictionTensor,
    coefficients,
    coefficients,
    st.one_of(st.just(0.0), st.floats(-5.0, 5.0)),
    st.sampled_from(["plane", "body"]),
    st.floats(-6.28, 6.28),  # |angle| ≤ 2π (FrictionTensor refuses more)
)


@st.composite
def bodies(draw):
    patch = draw(patches())
    law = draw(laws(patch))
    mass = draw(st.one_of(st.sampled_from([1e-12, 1e12, 1.0]), log_uniform(1e-12, 1e12)))
    i_star = draw(st.one_of(st.none(), st.sampled_from([1e-8, 1e8]), log_uniform(1e-8, 1e8)))
    if i_star is None:
        return ss.Body(patch, law, mass)
    return ss.Body(patch, law, mass, i_star * mass * patch.a**2)


def maybe_junk(valid):
    """Mostly valid objects, sometimes anything at all."""
    return st.one_of(valid, valid, valid, numbers)


# ------------------------------------------------------------------------------------------
# the checks
# ------------------------------------------------------------------------------------------
def call(fn, names, *args, **kwargs):
    """Run ``fn``; a ValueError must name one of ``names``; any other exception fails.

    Returns the result, or None if a ValueError was raised.
    """
    label = getattr(fn, "__qualname__", repr(fn))
    try:
        with time_limit():
            out = fn(*args, **kwargs)
        event(f"{label}: result")
        return out
    except ValueError as err:
        event(f"{label}: ValueError")
        msg = str(err)
        assert any(n in msg for n in names), (names, msg)
        assert "\n" not in msg and len(msg) < 2000, msg
        return None


def finite_everywhere(obj, allowed=(), where="result"):
    """Every float reachable from ``obj`` is finite, except the attributes in ``allowed``."""
    if obj is None or isinstance(obj, (str, bool)):
        return
    if isinstance(obj, (float, np.floating, int, np.integer)):
        assert math.isfinite(float(obj)), f"{where} = {obj!r}"
        return
    if isinstance(obj, complex):
        assert math.isfinite(obj.real) and math.isfinite(obj.imag), f"{where} = {obj!r}"
        return
    if isinstance(obj, np.ndarray):
        if obj.dtype.kind in "fc":
            assert np.all(np.isfinite(obj)), f"{where} has non-finite entries"
        return
    if dataclasses.is_dataclass(obj):
        for f in dataclasses.fields(obj):
            if f.name in allowed:
                continue
            finite_everywhere(getattr(obj, f.name), allowed, f"{where}.{f.name}")
        return
    if isinstance(obj, (tuple, list)):
        for i, x in enumerate(obj):
            finite_everywhere(x, allowed, f"{where}[{i}]")
        return


@pytest.fixture(scope="module", autouse=True)
def warm_up():
    """Load (or compile) the kernel once, outside the time limits."""
    body = ss.Body(ss.Circle(0.05), ss.UniformPressure(), 1.0)
    ss.friction_wrench(body, ss.FrictionTensor(0.3, 0.4), 1.0, 0.0, 1.0)
    ss.terminal_ratio(body, ss.FrictionTensor(0.3, 0.4), 0.0)
    ss.inertia_intervals(ss.HertzPressure(), ss.FrictionTensor(0.3, 0.4))


def arg(data, valid, label):
    """A valid value, or (one time in five) anything at all."""
    if data.draw(st.integers(0, 4), label=f"{label} is junk") == 0:
        return data.draw(numbers, label=label)
    return data.draw(valid, label=label)


LENGTH = st.one_of(st.sampled_from([1e-9, 1e6, 0.05, 1.0]), log_uniform(1e-9, 1e6))
ASPECT = st.one_of(st.sampled_from([1e-3, 30.0, 1.0]), log_uniform(1e-3, 30.0))
FINITE = st.floats(allow_nan=False, allow_infinity=False)
finite_arrays = st.one_of(
    FINITE,
    st.lists(FINITE, min_size=1, max_size=4),
    st.sampled_from([0.0, 5e-324, 1e-300, 1e300, -1.7976931348623157e308]),
)


# ------------------------------------------------------------------------------------------
# constructors
# ------------------------------------------------------------------------------------------
@FUZZ
@given(st.data())
def test_ellipse(data):
    a = arg(data, LENGTH, "a")
    k = data.draw(ASPECT, label="b/a")
    b = arg(data, st.just(min(max(k * a, 1e-9), 1e6) if isinstance(a, float) else 0.1), "b")
    e = call(ss.Ellipse, ("a =", "a must", "b =", "b must", "b/a ="), a, b)
    if e is not None:
        finite_everywhere((e.a, e.b, e.aspect, e.eccentricity, e.area, e.plate_inertia_ratio()))
        assert 1e-3 <= e.b / e.a <= 30.0
    ecc = arg(data, st.one_of(st.sampled_from([0.0, 0.999999]), st.floats(0.0, 0.999999)), "e")
    p = call(
        ss.Ellipse.from_eccentricity,
        ("a =", "a must", "eccentricity =", "eccentricity must"),
        a,
        ecc,
    )
    if p is not None:
        finite_everywhere((p.a, p.b, p.eccentricity, p.area))


@FUZZ
@given(st.data())
def test_circle_and_outline(data):
    c = call(ss.Circle, ("radius",), arg(data, LENGTH, "radius"))
    if c is not None:
        finite_everywhere((c.radius, c.area))
        out = call(c.outline, ("n =",), arg(data, st.integers(2, 1000), "n"))
        if out is not None:
            finite_everywhere(out)


@FUZZ
@given(st.data(), st.sampled_from(["uniform", "linear", "boussinesq", "hertz"]))
def test_pressure_laws(data, kind):
    patch = data.draw(patches(), label="patch")
    if kind == "linear":
        r = data.draw(st.floats(0.0, 0.25), label="r")
        t = data.draw(st.floats(0.0, 2.0 * math.pi), label="t")
        xi_c = arg(data, st.just(r * patch.a * math.cos(t)), "xi_c")
        eta_c = arg(data, st.just(r * patch.b * math.sin(t)), "eta_c")
        p = call(ss.LinearPressure, ("xi_c", "eta_c"), xi_c, eta_c)
    else:
        p = call(
            {
                "uniform": ss.UniformPressure,
                "boussinesq": ss.BoussinesqPressure,
                "hertz": ss.HertzPressure,
            }[kind],
            (),
        )
        assert p is not None
    if p is None:
        return
    scale = st.floats(-2.0, 2.0).map(lambda x: x * patch.a)
    xi = arg(data, st.one_of(scale, st.lists(scale, min_size=1, max_size=4), FINITE), "xi")
    eta = arg(data, st.one_of(scale, st.lists(scale, min_size=1, max_size=4), FINITE), "eta")
    load = arg(data, st.one_of(st.just(0.0), log_uniform(1e-18, 1e18)), "load")
    out = call(p.density, ("xi", "eta", "load"), patch, xi, eta, load)
    if out is not None:
        # Boussinesq's p is integrable but unbounded at the rim; finite at every point given
        finite_everywhere(out)
        assert np.all(out >= 0.0)


@FUZZ
@given(st.data())
def test_friction_tensor(data):
    fx = arg(data, coefficients, "fx")
    fy = arg(data, coefficients, "fy")
    f = arg(data, st.one_of(st.just(0.0), st.sampled_from([-5.0, 5.0]), st.floats(-5.0, 5.0)), "f")
    frame = arg(data, st.sampled_from(["plane", "body", "Body", "world"]), "frame")
    angle = arg(data, st.one_of(st.just(0.0), FINITE), "angle")
    angle_deg = data.draw(st.one_of(st.none(), FINITE, numbers), label="angle_deg")
    t = call(
        ss.FrictionTensor,
        ("fx", "fy", "f =", "f must", "frame", "angle"),
        fx,
        fy,
        f,
        frame,
        angle,
        angle_deg=angle_deg,
    )
    if t is not None:
        finite_everywhere(
            (t.fx, t.fy, t.f, t.angle, t.mu, t.matrix, t.world_matrix(1.0), t.norm, t.angle_deg)
        )
    c = call(ss.FrictionTensor.isotropic, ("coefficient",), fx)
    if c is not None:
        finite_everywhere(c.matrix)


@FUZZ
@given(st.data())
def test_body(data):
    patch = arg(data, patches(), "patch")
    law = arg(data, laws(patch if isinstance(patch, ss.Ellipse) else None), "law")
    mass = arg(
        data, st.one_of(st.sampled_from([1e-12, 1e12, 1.0]), log_uniform(1e-12, 1e12)), "mass"
    )
    i_star = arg(data, st.one_of(st.sampled_from([1e-8, 1e8]), log_uniform(1e-8, 1e8)), "I*")
    inertia = None
    if data.draw(st.booleans(), label="explicit inertia"):
        ok = all(isinstance(x, float) for x in (i_star, mass)) and isinstance(patch, ss.Ellipse)
        inertia = arg(data, st.just(i_star * mass * patch.a**2 if ok else 1.0), "inertia")
    names = ("patch", "pressure", "mass", "moment_of_inertia", "core of the patch")
    b = call(ss.Body, names, patch, law, mass, inertia)
    if b is not None:
        finite_everywhere(
            (b.mass, b.moment_of_inertia, b.inertia_ratio, b.radius_of_gyration, b.mass_centre)
        )
        assert 1e-8 * (1 - 1e-12) <= b.inertia_ratio <= 1e8 * (1 + 1e-12)
    b = call(ss.Body.from_inertia_ratio, names + ("inertia_ratio",), patch, law, mass, i_star)
    if b is not None:
        finite_everywhere((b.moment_of_inertia, b.inertia_ratio))


POSITIONS = st.one_of(st.sampled_from([0.0, 1e100, -1e100]), st.floats(-1e100, 1e100))
SPEEDS = st.one_of(st.sampled_from([0.0, 5e-324, 1e-300, 1e8, -1e8]), st.floats(-1e8, 1e8))
SPINS = st.one_of(st.sampled_from([0.0, 1e-300, 1e12, -1e12]), st.floats(-1e12, 1e12))


@FUZZ
@given(st.data())
def test_state(data):
    x, y = arg(data, POSITIONS, "x"), arg(data, POSITIONS, "y")
    phi = arg(data, FINITE, "phi")
    vx, vy, omega = arg(data, SPEEDS, "vx"), arg(data, SPEEDS, "vy"), arg(data, SPINS, "omega")
    s = call(
        ss.State,
        ("x =", "x must", "y =", "y must", "phi", "vx", "vy", "omega"),
        x,
        y,
        phi,
        vx,
        vy,
        omega,
    )
    if s is not None:
        finite_everywhere((s.as_array(), s.speed))
    speed = arg(data, st.floats(0.0, 1e8), "speed")
    theta = arg(data, FINITE, "theta")
    s = call(
        ss.State.from_speed,
        ("speed", "omega", "theta", "phi", "x =", "x must", "y =", "y must"),
        speed,
        omega,
        theta,
        phi,
        x,
        y,
    )
    if s is not None:
        finite_everywhere(s.as_array())


# ------------------------------------------------------------------------------------------
# functions
# ------------------------------------------------------------------------------------------
@FUZZ
@given(st.data())
def test_friction_wrench(data):
    body = arg(data, bodies(), "body")
    friction = arg(data, frictions, "friction")
    vx, vy, omega = (arg(data, finite_arrays, n) for n in ("vx", "vy", "omega"))
    phi = arg(data, st.one_of(st.just(0.0), finite_arrays), "phi")
    g = arg(data, st.one_of(st.just(9.81), log_uniform(1e-6, 1e6)), "g")
    tol = arg(data, st.one_of(st.just(1e-12), log_uniform(1e-13, 1e-2)), "tol")
    names = ("body", "friction", "vx", "vy", "omega", "phi", "g =", "g must", "tol", "broadcast")
    w = call(ss.friction_wrench, names, body, friction, vx, vy, omega, phi, g, tol=tol)
    if w is not None:
        finite_everywhere(w)
        # dissipative: friction power F·v + M ω ≤ 0 (MODEL §2), to the quadrature target,
        # with the velocities scaled to unit size (the products could overflow otherwise)
        u = np.broadcast_arrays(*(np.asarray(x, float) for x in (vx, vy, omega)))
        big = np.maximum(np.maximum(np.abs(u[0]), np.abs(u[1])), np.abs(u[2]))
        big = np.where(big > 0.0, big, 1.0)
        p = w.power(u[0] / big, u[1] / big, u[2] / big) / (body.mass * g)
        reach = 1.0 + body.patch.a + np.hypot(*body.mass_centre)
        assert np.all(p <= 10.0 * tol * reach * (1.0 + 1.0 / body.patch.a)), p


BRACKETS = st.tuples(log_uniform(1e-9, 1e9), log_uniform(1e-9, 1e9)).map(sorted).map(tuple)


@FUZZ
@given(st.data())
def test_terminal_ratio(data):
    body = arg(data, bodies(), "body")
    friction = arg(data, frictions, "friction")
    phi, theta = arg(data, FINITE, "phi"), arg(data, FINITE, "theta")
    bracket = data.draw(
        st.one_of(st.none(), st.none(), BRACKETS, numbers, st.tuples(numbers, numbers)),
        label="bracket",
    )
    if (
        isinstance(bracket, tuple)
        and isinstance(body, ss.Body)
        and len(bracket) == 2
        and all(isinstance(x, float) for x in bracket)
    ):
        bracket = tuple(x * body.patch.a for x in bracket)
    names = ("body", "friction", "phi", "theta", "bracket")
    r = call(ss.terminal_ratio, names, body, friction, phi, theta, bracket=bracket)
    if r is not None:
        # documented: inf (spin dies first), NaN (every root repels); else finite and ≥ 0
        assert math.isinf(r) or math.isnan(r) or (math.isfinite(r) and r >= 0.0), r


@settings(FUZZ, max_examples=max(EXAMPLES // 4, 5))
@given(st.data())
def test_terminal_states(data):
    body = arg(data, bodies(), "body")
    friction = arg(data, frictions, "friction")
    phi = arg(data, FINITE, "phi")
    states = call(ss.terminal_states, ("body", "friction", "phi"), body, friction, phi)
    if states is None:
        return
    for s in states:
        assert s.ending in ("mixed", "pure_sliding", "pure_spinning")
        # documented non-finite values: β* = ±inf in pure sliding; θ* is NaN on a circle of
        # fixed points (``continuum``) and may be NaN for a pure spin approached along every
        # direction alike (TerminalState's docstring)
        finite_everywhere(s, allowed=("beta", "beta_ratio", "theta"))
        if s.ending == "mixed":
            assert math.isfinite(s.beta) and (s.continuum or math.isfinite(s.theta))
        elif s.ending == "pure_spinning":
            assert s.beta == 0.0
        else:
            assert math.isinf(s.beta) and (s.continuum or math.isfinite(s.theta))


table2_laws = st.sampled_from(
    [
        ss.UniformPressure(),
        ss.BoussinesqPressure(),
        ss.HertzPressure(),
        ss.LinearPressure(0.0, 0.0),
        ss.LinearPressure(0.01, 0.0),
    ]
)
orthotropic = st.builds(
    lambda fx, k: ss.FrictionTensor(fx, min(fx * k, 5.0)),
    coefficients,
    st.one_of(st.just(1.0), log_uniform(1.0, 1e6)),
)


@FUZZ
@given(st.data())
def test_table2_functions(data):
    law = arg(data, table2_laws, "law")
    friction = arg(data, st.one_of(orthotropic, orthotropic, frictions), "friction")
    ratio = arg(
        data,
        st.one_of(log_uniform(1e-9, 1e9), st.lists(log_uniform(1e-9, 1e9), min_size=1, max_size=3)),
        "ratio",
    )
    i_star = arg(data, log_uniform(1e-8, 1e8), "I*")
    names = ("pressure", "friction", "mu =", "ratio", "inertia_ratio")
    for fn in (ss.inertia_intervals, ss.paper_inertia_intervals):
        iv = call(fn, names, law, friction)
        if iv is not None:
            finite_everywhere(tuple(iv))
    j = call(ss.inertia_for_ratio, names, law, friction, ratio)
    if j is not None:
        finite_everywhere(j)
    k = call(ss.circle_terminal_ratio, names, law, friction, i_star)
    if k is not None:
        assert k == math.inf or (math.isfinite(k) and k >= 0.0), k  # inf: pure sliding


# ------------------------------------------------------------------------------------------
# simulate (owned by the integrator's maintainer; kept apart so that it can be enabled
# or marked on its own)
# ------------------------------------------------------------------------------------------
states = st.builds(ss.State, POSITIONS, POSITIONS, st.floats(-1e6, 1e6), SPEEDS, SPEEDS, SPINS)


@settings(FUZZ, max_examples=max(EXAMPLES // 2, 5))
@given(st.data())
def test_simulate(data):
    body = arg(data, bodies(), "body")
    friction = arg(data, frictions, "friction")
    state = arg(data, states, "state")
    g = arg(data, st.one_of(st.just(9.81), log_uniform(1e-6, 1e6)), "g")
    rtol = arg(data, st.one_of(st.just(1e-10), log_uniform(1e-14, 1e-3)), "rtol")
    max_steps = arg(data, st.integers(1, 2000), "max_steps")
    max_step = data.draw(
        st.one_of(st.none(), st.none(), log_uniform(1e-6, 1e6), numbers), label="max_step"
    )
    if isinstance(max_steps, int) and not isinstance(max_steps, bool) and max_steps > 2000:
        max_steps = 2000  # a budget, not a test of patience
    names = ("body", "friction", "initial_state", "g =", "g must", "rtol", "max_steps", "max_step")
    tr = call(
        ss.simulate,
        names,
        body,
        friction,
        state,
        g=g,
        rtol=rtol,
        max_steps=max_steps,
        max_step=max_step,
    )
    if tr is None:
        return
    # documented non-finite values: beta (inf pure sliding, NaN at rest / spiral), theta_stop
    # and beta_stop likewise (README, "How a motion ends")
    for name in (
        "t",
        "x",
        "y",
        "phi",
        "vx",
        "vy",
        "omega",
        "speed",
        "tangential",
        "normal",
        "moment_paper",
    ):
        arr = getattr(tr, name)
        assert np.all(np.isfinite(arr)), (name, arr)
    assert math.isfinite(tr.t_stop) and tr.t_stop >= 0.0
    finite_everywhere(tr.stop_state.as_array())


# Inputs of issue 11 that reach the integrator (simulate, simulate_many). Each runs in its own
# process, so that a hang or a crash cannot take this module down: each must be refused up
# front naming the parameter, or give finite results.
_SETUP = (
    "import json, math, sys, slidespin as ss, slidespin.motion.batch as sb\n"
    "B = ss.Body(ss.Circle(0.05), ss.UniformPressure(), 1.0)\n"
    "F = ss.FrictionTensor(0.3, 0.4)\n"
)
_PROBE = (
    _SETUP
    + r"""
try:
    r = eval(sys.argv[1])
except ValueError as err:
    print(json.dumps(["ValueError", str(err)]))
except BaseException as err:
    print(json.dumps([type(err).__name__, str(err)[:300]]))
else:
    t = getattr(r, "t_stop", None)
    ok = t is not None and bool(__import__("numpy").all(__import__("numpy").isfinite(t)))
    print(json.dumps(["result", "finite" if ok else repr(t)[:300]]))
"""
)
LEAD_INPUTS = [
    ("ss.simulate(B, F, ss.State(vx=1.0), g=5e-324)", "g ="),
    ("ss.simulate(B, F, ss.State(vx=1.0), max_steps=2**64)", "max_steps ="),
    ("sb.simulate_many(B, F, [[0.0, 0.0, 0.0, 1.0, 0.0, 0.0]], g=5e-324)", "g ="),
    ("sb.simulate_many(B, F, [[0.0, 0.0, 0.0, 1.0, 0.0, 0.0]], max_steps=2**64)", "max_steps ="),
]


@pytest.mark.parametrize("expr, name", LEAD_INPUTS, ids=[x[0][:48] for x in LEAD_INPUTS])
def test_integrator_issue_inputs(expr, name):
    import json
    import subprocess
    import sys

    r = subprocess.run(
        [sys.executable, "-c", _PROBE, expr],
        capture_output=True,
        text=True,
        timeout=300,
        check=False,
    )
    kind, text = json.loads(r.stdout.strip().splitlines()[-1])
    if kind == "ValueError":
        assert name in text, text
    else:
        assert kind == "result" and text == "finite", (kind, text)
