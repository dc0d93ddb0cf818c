"""Loads at their edges: sample tables refused with named errors (bools, non-finite or
non-increasing times, beyond the knot budget), O(log n) evaluation of long tables, callables
checked at construction, and the documented cost of a callable.

Truths: linear interpolation reproduces an affine function exactly (to round-off) and a
table's own samples at its knots; a callable's expected signature is ``f(t)``.
"""

from __future__ import annotations

import functools
import math
import time

import numpy as np
import pytest

from slidespin.motion import loads
from slidespin.motion.loads import MAX_KNOTS, Load

# ------------------------------------------------------------------------------------------
# piecewise_linear: what is refused, and how it is named
# ------------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "times, words",
    [
        ([True, 2, 3], ["times[0] = True", "bool", "valid values"]),
        ([0, 1.0, False], ["times[2] = False", "bool"]),
        (np.array([True, False]), ["times", "bool", "valid values"]),
        ([0.0, 1.0, math.nan], ["times", "nan", "not finite", "valid range"]),
        ([0.0, math.inf, 3.0], ["times", "inf", "not finite"]),
        ([0.0, 2.0, 1.0], ["times[2] = 1.0 s is not after times[1] = 2.0 s", "increasing"]),
        ([0.0, 1.0, 1.0], ["times[2] = 1.0 s is not after", "strictly increasing"]),
        ([0.0], ["times has shape (1,)", "2 to 1,000,000"]),
        ([[0.0, 1.0], [2.0, 3.0]], ["times has shape (2, 2)", "1-D"]),
        ("0, 1", ["times", "real number"]),
    ],
)
def test_bad_times_are_refused_by_name(times, words):
    n = np.size(times) if not isinstance(times, str) else 2
    with pytest.raises(ValueError) as info:
        Load.piecewise_linear(times, np.zeros(n).reshape(np.shape(times) or (n,)), np.zeros(n))
    msg = str(info.value)
    assert "np.float64" not in msg and "array(" not in msg, msg
    for w in words:
        assert w in msg, (w, msg)


@pytest.mark.parametrize("column", ["fx", "fy", "torque"])
def test_bool_samples_are_refused_in_every_column(column):
    cols = {"fx": [0.0, 1.0, 2.0], "fy": [0.0, 0.0, 0.0], "torque": [0.0, 0.0, 0.0]}
    cols[column] = [0.0, True, 2.0]
    with pytest.raises(ValueError, match=rf"{column}\[1\] = True .*bool.*valid values"):
        Load.piecewise_linear([0.0, 1.0, 2.0], cols["fx"], cols["fy"], cols["torque"])


def test_knot_budget():
    """At most MAX_KNOTS samples; one more is refused naming the budget."""
    assert MAX_KNOTS == 1_000_000
    t = np.arange(MAX_KNOTS + 1, dtype=float)
    with pytest.raises(ValueError, match=r"times has shape \(1000001,\).*2 to 1,000,000"):
        Load.piecewise_linear(t, t, t)


# ------------------------------------------------------------------------------------------
# piecewise_linear: values and cost
# ------------------------------------------------------------------------------------------


def test_long_table_is_exact_and_logarithmic():
    """10⁵ knots of an affine force: exact values anywhere, the samples at the knots, the
    end values beyond; and evaluation does not scan the table (the old code copied the
    knots at every call: ~15 ms each at 10⁵ knots; bisection takes microseconds)."""
    n = 100_000
    rng = np.random.default_rng(7)
    t = np.cumsum(rng.uniform(0.5, 1.5, n)) * 1e-4
    fx, fy, tq = 3.0 * t + 1.0, -2.0 * t, np.sin(t)
    load = Load.piecewise_linear(t, fx, fy, tq)
    for x in rng.uniform(t[0], t[-1], 200):
        qx, qy = load.force_at(x)
        assert qx == pytest.approx(3.0 * x + 1.0, rel=1e-12)
        assert qy == pytest.approx(-2.0 * x, rel=1e-12, abs=1e-15)
    for i in rng.integers(0, n, 50):
        assert load.force_at(t[i]) == (fx[i], fy[i]) and load.torque_at(t[i]) == tq[i]
    assert load.force_at(t[0] - 5.0) == (fx[0], fy[0])
    assert load.force_at(t[-1] + 5.0) == (fx[-1], fy[-1])
    assert load.knots == tuple(t.tolist())
    queries = rng.uniform(t[0], t[-1], 2000)
    start = time.perf_counter()
    for x in queries:
        load.wrench(x, 0.3)
    per_call = (time.perf_counter() - start) / queries.size
    assert per_call < 1e-3, per_call  # O(n) scans cost ≥ 5 ms here; bisection ~20 µs


def test_profile_agrees_with_the_shared_interpolation():
    """Bisection changes the cost, not the numbers: the same (1 − w) v₀ + w v₁."""
    from slidespin.contact._profile import interp

    t = (0.0, 0.3, 0.31, 1.7, 2.0)
    v = (1.0, -2.0, 5.0, 0.25, 3.0)
    load = Load.piecewise_linear(t, v, v)
    for x in np.linspace(-1.0, 3.0, 401):
        assert load.force_at(x)[0] == interp(x, t, v)


def test_non_finite_time_is_refused_at_evaluation():
    load = Load.piecewise_linear([0.0, 1.0], [0.0, 1.0], [0.0, 0.0])
    with pytest.raises(ValueError, match=r"t = nan is not finite; valid range"):
        load.force_at(math.nan)


# ------------------------------------------------------------------------------------------
# callables: checked at construction
# ------------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "kwargs, error, words",
    [
        (dict(force=lambda: (1.0, 0.0)), TypeError, ["force", "()", "force(t) -> (Qx, Qy)"]),
        (dict(force=lambda t, u: (1.0, 0.0)), TypeError, ["(t, u)", "one argument"]),
        (dict(force=lambda *, t: (1.0, 0.0)), TypeError, ["one argument"]),
        (dict(force=lambda t: 1.0), ValueError, ["force(0.0) returned 1.0", "a pair"]),
        (dict(force=lambda t: (1.0, 2.0, 3.0)), ValueError, ["returned (1.0, 2.0, 3.0)"]),
        (dict(force=lambda t: (math.nan, 0.0)), ValueError, ["returned (nan, 0.0)", "finite"]),
        (dict(force=lambda t: 1.0 / t), ValueError, ["force(0.0) raised ZeroDivisionError"]),
        (dict(torque=lambda: 1.0), TypeError, ["torque(t) -> T [N m]"]),
        (dict(torque=lambda t: (1.0, 0.0)), ValueError, ["torque(0.0) returned (1.0, 0.0)"]),
        (dict(torque=lambda t: True), ValueError, ["torque(0.0) returned True"]),
        (dict(torque=lambda t: "1"), ValueError, ["torque(0.0) returned '1'"]),
        (dict(torque=lambda t: 10**400), ValueError, ["torque(0.0) returned"]),
    ],
)
def test_wrong_callables_are_refused_when_built(kwargs, error, words):
    with pytest.raises(error) as info:
        Load(**kwargs)
    msg = str(info.value)
    assert "valid values" in msg, msg
    for w in words:
        assert w in msg, (w, msg)


def test_good_callables_are_accepted_and_called_once_when_built():
    calls = []

    def push(t, scale=2.0):
        calls.append(t)
        return (scale * t, 0.0)

    class Twist:
        def __call__(self, t):
            return 0.5 * t

    load = Load(force=push, torque=Twist())
    assert calls == [0.0]
    assert load.wrench(1.5) == (3.0, 0.0, 0.75)
    assert Load(force=functools.partial(push, scale=3.0)).force_at(2.0) == (6.0, 0.0)
    # a builtin without a signature is left to the trial call
    assert Load(torque=np.sin).torque_at(0.5) == pytest.approx(math.sin(0.5), rel=1e-15)


def test_the_cost_of_a_callable_is_documented():
    doc = Load.__doc__ or ""
    assert "20 µs" in doc and "piecewise_linear" in doc and "Python" in doc
    assert "Prefer the tabulated" in doc
    assert "MAX_KNOTS" in (Load.piecewise_linear.__doc__ or "")
    assert loads.MAX_KNOTS == MAX_KNOTS
