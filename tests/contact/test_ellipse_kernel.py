"""The compiled wrench kernel's quadrature rules, one by one, against the slow reference
(tests/reference.py): every rule and every switch between rules, the node-count rule and its
a-posteriori check, the node and weight tables, and the workspace entry points."""

from __future__ import annotations

import json
import math
import os
import subprocess
import sys

import numpy as np
import pytest

from reference import reference_wrench
from slidespin.contact import _kernel_ellipse as K
from slidespin.contact import _kernel_ellipse_adaptive as KA
from slidespin.contact import _kernel_ellipse_rules as R

TOL = 1e-10  # the contract, absolute, unit load and a = 1
LAW = {"uniform": 0, "linear": 1, "boussinesq": 2, "hertz": 3}
TENSOR = (0.42, 0.13, -0.13, 0.61)  # body frame (φ = 0), skew part included


def centroid(law, bn):
    return (0.12, -0.08 * bn) if law == "linear" else (0.0, 0.0)


def kernel(bn, law, cx, cy, om=1.3, tol=1e-12, tensor=TENSOR):
    """Kernel wrench and quadrature for the ICR at body point (cx, cy), φ = 0."""
    xg, yg = centroid(law, bn)
    vx, vy = (cy - yg) * om, -(cx - xg) * om
    fx, fy, m, status, method, nodes = K.wrench_body_info(
        bn, LAW[law], xg, yg, *tensor, vx, vy, om, tol
    )
    return np.array([fx, fy, m]), status, R.METHOD_NAMES[method], nodes


def reference(bn, law, cx, cy, om=1.3, tensor=TENSOR):
    xg, yg = centroid(law, bn)
    vx, vy = (cy - yg) * om, -(cx - xg) * om
    t = np.array([[tensor[0], tensor[1]], [tensor[2], tensor[3]]])
    return np.array(
        reference_wrench(1.0, bn, law, t, 0.0, vx, vy, om, xi_c=xg, eta_c=yg, P=1.0)[:3]
    )


def rim(bn, t, r):
    """ICR at r times the rim point at parameter t."""
    return r * math.cos(t), r * bn * math.sin(t)


# one state per rule: (b/a, law, ICR) -> the rule the kernel must pick for it
RULE_STATES = {
    "trapezoid": (1.0, "uniform", (0.3, 0.2)),
    "trapezoid-mapped": (0.3, "boussinesq", (0.2, 0.1)),
    "sine-trapezoid": (0.15, "linear", (1.2, 0.06)),
    "sine-trapezoid-mapped": (0.1, "uniform", (1.1, 0.05)),
    "clenshaw-curtis": (0.5, "hertz", (3.0, 2.0)),
    "clenshaw-curtis-mapped": (0.1, "hertz", (1.05, 0.02)),
    "clenshaw-curtis-inside": (0.5, "uniform", rim(0.5, 0.7, 1 - 1e-2)),
    "adaptive-inside": (0.5, "linear", rim(0.5, 0.7, 1 - 1e-7)),
    "adaptive-outside": (0.5, "uniform", rim(0.5, 0.7, 1 + 1e-7)),
}


@pytest.mark.parametrize("rule", list(RULE_STATES))
@pytest.mark.parametrize("om", [1.3, -0.4])
def test_each_rule_is_used_and_matches_reference(rule, om):
    bn, law, (cx, cy) = RULE_STATES[rule]
    got, status, method, nodes = kernel(bn, law, cx, cy, om)
    assert method == rule, (method, nodes)
    assert status == K.STATUS_OK
    assert np.max(np.abs(got - reference(bn, law, cx, cy, om))) < TOL


@pytest.mark.parametrize("law", ["uniform", "linear", "boussinesq", "hertz"])
@pytest.mark.parametrize("side", [-1, 1])
def test_approach_to_the_rim_crosses_every_switch(law, side):
    """ICR at distance 10⁻ᵏ from the rim, k = 1..12: for uniform and linear pressure the
    rules switch (trapezoid → Clenshaw–Curtis → adaptive inside; sine-trapezoid → adaptive
    outside); every state stays within the contract."""
    bn, t = 0.5, 0.7
    methods = []
    for k in range(1, 13):
        cx, cy = rim(bn, t, 1 + side * 10.0**-k)
        got, status, method, _ = kernel(bn, law, cx, cy)
        methods.append(method)
        assert status == K.STATUS_OK
        assert np.max(np.abs(got - reference(bn, law, cx, cy))) < TOL, (k, method)
    if law in ("uniform", "linear"):
        want = (
            {"clenshaw-curtis-inside", "adaptive-inside"}
            if side < 0
            else {"sine-trapezoid", "adaptive-outside"}
        )
        assert want <= set(methods), methods
    else:  # no branch point at tangent lines: one rule all the way to the rim
        assert len(set(methods)) == 1, methods


def test_switch_at_the_rim_is_continuous():
    """On, just inside and just outside the rim the wrench agrees to the contract and is
    continuous (Lipschitz in the distance to the rim)."""
    for law in ("uniform", "linear", "boussinesq", "hertz"):
        on, _, _, _ = kernel(0.5, law, *rim(0.5, 1.1, 1.0))
        assert np.max(np.abs(on - reference(0.5, law, *rim(0.5, 1.1, 1.0)))) < TOL
        for eps in (1e-6, 1e-9, 1e-12):
            for side in (-1, 1):
                near, _, _, _ = kernel(0.5, law, *rim(0.5, 1.1, 1 + side * eps))
                assert np.max(np.abs(near - on)) < 10 * eps + TOL


@pytest.mark.parametrize("law", ["uniform", "hertz"])
def test_map_switch_over_the_aspect_ratio(law):
    """b/a from 1 down to 0.02 (and above 1): the plain and the √κ-mapped trapezoid take
    turns; both meet the contract."""
    methods = set()
    for bn in (1.0, 0.9, 0.7, 0.5, 0.3, 0.1, 0.05, 0.02, 1.5, 3.0):
        cx, cy = 0.25, 0.3 * bn
        got, status, method, _ = kernel(bn, law, cx, cy)
        methods.add(method)
        assert np.max(np.abs(got - reference(bn, law, cx, cy))) < TOL, (bn, method)
    assert {"trapezoid", "trapezoid-mapped"} <= methods


@pytest.mark.parametrize("law", ["uniform", "boussinesq"])
def test_outside_map_threshold(law):
    """Sectors narrower and wider than MAP_MIN_HALF_WIDTH (ICR far and near, thin patch)."""
    bn = 0.1
    seen = set()
    for dist in (1.02, 1.1, 1.5, 3.0, 6.0, 30.0, 1e3, 1e6):
        cx, cy = dist * 0.6, dist * 0.8 * bn
        got, status, method, _ = kernel(bn, law, cx, cy)
        seen.add(method)
        assert np.max(np.abs(got - reference(bn, law, cx, cy))) < TOL, (dist, method)
    assert any(m.endswith("-mapped") for m in seen) and any(
        not m.endswith("-mapped") for m in seen
    ), seen


@pytest.mark.parametrize("tol", [1e-6, 1e-9, 1e-12, 1e-14])
def test_tolerance_is_honoured(tol):
    """Looser targets need fewer nodes and still meet them; tighter ones double the rules
    or fall back to the adaptive quadrature (both are exercised here)."""
    states = [
        (0.5, "uniform", 0.3, 0.1),
        (0.5, "hertz", 2.0, 0.5),
        (0.2, "linear", 0.9, 0.05),
        (0.5, "boussinesq", *rim(0.5, 0.4, 1 - 1e-5)),
        (0.5, "uniform", 30.0, -4.0),
    ]
    for bn, law, cx, cy in states:
        got, status, method, _ = kernel(bn, law, cx, cy, tol=tol)
        assert status == K.STATUS_OK
        assert np.max(np.abs(got - reference(bn, law, cx, cy))) < max(tol, 1e-13), (law, method)


def test_looser_tolerance_uses_fewer_nodes():
    for bn, law, cx, cy in [(0.5, "uniform", 0.3, 0.1), (0.3, "hertz", 2.0, 0.2)]:
        counts = [kernel(bn, law, cx, cy, tol=tol)[3] for tol in (1e-4, 1e-8, 1e-12)]
        assert counts[0] <= counts[1] <= counts[2] and counts[0] < counts[2], counts


def test_trapezoid_converges_at_the_predicted_rate():
    """Error of the inside trapezoid rule vs N: the log-linear slope is at least the rate
    2d predicted from the singularity distance d (Trefethen & Weideman 2014, Thm 3.2)."""
    bn, cx, cy = 0.5, 0.35, 0.2
    lam1, lam2, c2, s2 = R._q_form(1.0 / bn**2, cx, cy)
    d = min(math.atanh(bn), math.atanh(math.sqrt(lam1 / lam2)))  # plain angle, uniform law
    W = K.workspace()

    def T(n):
        return np.array(
            R._run_rule(
                W,
                None,
                R.METHOD_TRAPEZOID,
                n,
                0,
                1 / bn**2,
                1 / bn,
                0.0,
                0.0,
                0.0,
                0.0,
                *TENSOR,
                cx,
                cy,
                1.0,
                0.0,
                0.0,
                0.0,
                0.0,
                0.0,
            )[:3]
        )

    exact = T(256)
    ns = np.array([8, 12, 16, 24, 32])
    errs = np.array([np.max(np.abs(T(n) - exact)) for n in ns])
    slope = np.polyfit(ns, np.log(errs), 1)[0]
    assert slope < -0.9 * 2 * d, (slope, 2 * d)


def test_node_rule_grows_as_the_branch_point_approaches():
    """Uniform pressure: the node count grows as the ICR nears the rim (D's zeros approach
    the real axis); Boussinesq pressure has no such branch point, its count does not."""
    prev = 0
    for r in (0.0, 0.5, 0.8, 0.9, 0.95):
        n = kernel(0.5, "uniform", *rim(0.5, 0.3, r))[3]
        assert n >= prev
        prev = n
    counts = {kernel(0.5, "boussinesq", *rim(0.5, 0.3, r))[3] for r in (0.0, 0.5, 0.9, 0.999)}
    assert len(counts) == 1, counts


def test_estimate_of_nested_rules():
    assert R._estimate(1e-3, 0.0) == 0.0
    assert R._estimate(1e-3, 2e-3) == 2e-3  # not converging: the difference itself
    assert R._estimate(1e-2, 1e-4) == pytest.approx(1e-8)  # geometric: e2³/e1²


def test_clenshaw_curtis_tables_are_exact_for_polynomials():
    for n in R.CC_SIZES:
        o = R._CC_OFFSETS[R._CC_INDEX[n]]
        on = R._NODE_OFFSETS[R._NODE_INDEX[n]]
        x = R._COS[on : on + n + 1]
        for w, m in ((R._CC_W1, n), (R._CC_W2, n // 2), (R._CC_W4, n // 4)):
            ww = w[o : o + n + 1]
            for p in range(0, m + 1, 3):
                exact = 0.0 if p % 2 else 2.0 / (p + 1)
                assert abs(ww @ x**p - exact) < 1e-14, (n, m, p)


def test_node_tables():
    for n in R.NODE_SIZES:
        o = R._NODE_OFFSETS[R._NODE_INDEX[n]]
        t = np.arange(n + 1) * math.pi / n
        assert np.max(np.abs(R._COS[o : o + n + 1] - np.cos(t))) < 1e-15
        assert np.max(np.abs(R._SIN[o : o + n + 1] - np.sin(t))) < 1e-15
        assert R._SIN[o] == 0.0 and R._SIN[o + n] == 0.0


def test_polynomial_sine_and_cosine():
    t = np.linspace(-math.pi / 2, math.pi / 2, 2001)
    got = np.array([R._sincos(x) for x in t])
    assert np.max(np.abs(got[:, 0] - np.cos(t))) < 4e-16
    assert np.max(np.abs(got[:, 1] - np.sin(t))) < 4e-16


def test_workspace_entry_points_agree():
    """wrench_fast / wrench_world_fast with reused constants and workspace give exactly the
    numbers of the one-call functions."""
    rng = np.random.default_rng(5)
    W = K.workspace()
    for law in range(4):
        bn = 0.6
        xg, yg = (0.1, 0.03) if law == 1 else (0.0, 0.0)
        t = (0.3, 0.05, -0.02, 0.7)
        kc = K.wrench_constants(bn, law, xg, yg, math.sqrt(sum(x * x for x in t)), 1e-12)
        for _ in range(6):
            vx, vy, om, phi = rng.normal(size=4)
            one = K.wrench_body_info(bn, law, xg, yg, *t, vx, vy, om, 1e-12)
            fast = K.wrench_fast(law, kc, *t, vx, vy, om, 1e-12, W)
            assert one == fast
            w1 = K.wrench_world(bn, law, xg, yg, *t, False, phi, vx, vy, om, 1e-12)
            w2 = K.wrench_array(
                bn,
                law,
                xg,
                yg,
                *t,
                False,
                np.array([phi]),
                np.array([vx]),
                np.array([vy]),
                np.array([om]),
                1e-12,
            )
            assert w1 == tuple(x[0] for x in w2)


def test_adaptive_fallback_grows_its_interval_table():
    """A blade (b/a = 1e-4: the A-points lie 1e-4 off the real axis, beyond any tabulated
    rule) at a tight target needs more intervals than the table's initial capacity."""
    bn, cx, cy = 1e-4, 0.3, 2e-5
    got, status, method, nodes = kernel(bn, "uniform", cx, cy, tol=1e-15)
    assert method == "adaptive-inside" and nodes > 15 * KA.GK_INITIAL_CAPACITY
    assert status == K.STATUS_OK
    assert np.max(np.abs(got - reference(bn, "uniform", cx, cy))) < 1e-12


def test_every_rule_as_plain_python():
    """The kernel run as plain Python (NUMBA_DISABLE_JIT=1) gives the compiled numbers for a
    state of every rule."""
    states = [(bn, LAW[law], cx, cy) for bn, law, (cx, cy) in RULE_STATES.values()]
    code = (
        "import json, sys\n"
        "from slidespin.contact import _kernel_ellipse as K\n"
        "out = []\n"
        f"for bn, law, cx, cy in {states!r}:\n"
        "    xg, yg = (0.12, -0.08 * bn) if law == 1 else (0.0, 0.0)\n"
        "    r = K.wrench_body_info(bn, law, xg, yg, *" + repr(TENSOR) + ",\n"
        "                           (cy - yg) * 1.3, -(cx - xg) * 1.3, 1.3, 1e-12)\n"
        "    out.append([r[0], r[1], r[2], r[4]])\n"
        "print(json.dumps(out))\n"
    )
    env = dict(os.environ, NUMBA_DISABLE_JIT="1")
    r = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, env=env, timeout=600
    )
    assert r.returncode == 0, r.stderr
    for (bn, law, cx, cy), got in zip(states, json.loads(r.stdout)):
        name = [k for k, v in LAW.items() if v == law][0]
        want, _, method, _ = kernel(bn, name, cx, cy)
        assert R.METHOD_NAMES[got[3]] == method
        assert np.allclose(got[:3], want, atol=1e-13, rtol=0)
