"""The numbers of the sensitivities' collocation (slidespin.motion._sensitivity_colloc)
against independent truth: the Lobatto IIIA tableau's order conditions, the collocation
step's order 8 on a linear system against scipy's DOP853 at rtol 1e-13, and the plain run's
dense output against a re-integration of the same step by scipy."""

from __future__ import annotations

import math

import numpy as np
from scipy.integrate import solve_ivp

import slidespin as ss
from slidespin.contact._engine import kernel_constants
from slidespin.contact._kernel_ellipse_jac import JAC_WORKSPACE_SHAPE
from slidespin.motion import _integrator
from slidespin.motion import _sensitivity_colloc as colloc
from slidespin.motion._flow import NY, initial_state, rhs


def test_lobatto_tableau_is_the_order_8_collocation_method():
    c, a = colloc.LOBATTO_C, colloc.LOBATTO_A
    # the points: the ends and ±√(3/7) about the middle (P'_4's roots)
    r = math.sqrt(3.0 / 7.0)
    np.testing.assert_allclose(c, [0.0, (1 - r) / 2, 0.5, (1 + r) / 2, 1.0], atol=1e-15)
    b = a[-1]
    for k in range(1, 9):  # the weights integrate polynomials of degree ≤ 7 exactly
        assert abs(b @ c ** (k - 1) - 1.0 / k) < 1e-14, k
    assert abs(b @ c**8 - 1.0 / 9) > 1e-6  # and not degree 8: order 8, not more
    for k in range(1, 6):  # collocation: each stage integrates degree ≤ 4 exactly
        np.testing.assert_allclose(a @ c ** (k - 1), c**k / k, atol=1e-14)
    np.testing.assert_array_equal(a[0], 0.0)  # the first stage is explicit


def _linear_system(p):
    """J(τ) (NY × NY, non-zero in the core columns only) and B(τ) (p × NY) of a smooth
    linear variational equation S' = J S + Bᵀ."""
    core = colloc.CORE

    def jac(t):
        j = np.zeros((NY, NY))
        for i in range(NY):
            for q, col in enumerate(core):
                j[i, col] = 0.4 * math.sin(0.7 * t + i + 2 * q) / (1 + 0.1 * i)
        return j

    def bee(t):
        return np.array([[math.cos(0.5 * t * (k + 1) + i) for i in range(NY)] for k in range(p)])

    return jac, bee


def _collocate(jac, bee, s0, t_end, n):
    p = s0.shape[1]
    nl = colloc.NL
    s = s0.copy()
    K = np.empty((nl, NY, p))
    Z = np.empty((nl, NY, p))
    M = np.empty((colloc.NI, colloc.NI))
    R = np.empty((colloc.NI, p))
    h = t_end / n
    for step in range(n):
        ts = (step + colloc.LOBATTO_C) * h
        jc = np.array([jac(t)[:, colloc.CORE] for t in ts])
        bs = np.array([bee(t) for t in ts])
        assert colloc.collocation_step(s, K, Z, jc, bs, h, M, R)
    return s


def test_collocation_step_has_order_8_on_a_linear_system():
    p = 3
    jac, bee = _linear_system(p)
    s0 = np.arange(NY * p, dtype=float).reshape(NY, p) / (NY * p)
    t_end = 6.0

    def f(t, y):
        return (jac(t) @ y.reshape(NY, p) + bee(t).T).ravel()

    exact = solve_ivp(f, (0.0, t_end), s0.ravel(), method="DOP853", rtol=1e-13, atol=1e-14)
    ref = exact.y[:, -1].reshape(NY, p)
    errs = [np.max(np.abs(_collocate(jac, bee, s0, t_end, n) - ref)) for n in (6, 12)]
    # halving the step divides the error by 2⁸ = 256 for order 8 (measured: 241, then 255)
    assert errs[0] / errs[1] > 150.0, errs
    assert errs[1] < 1e-9 * np.max(np.abs(ref)), errs


def test_dense_output_of_a_plain_step_matches_a_re_integration():
    body = ss.Body(ss.Ellipse(0.1, 0.06), ss.LinearPressure(0.01, 0.005), mass=1.0)
    par, fe, fc, geo = body.engine_params(ss.FrictionTensor(0.3, 0.4, 0.05))
    y0 = initial_state(par, 1.0, 0.3, 0.2, 0.0, 0.0, 0.3)
    out = _integrator.integrate_on(
        par, fe, fc, geo, y0, 1e-10, 1e-10, 1e-10, 1e-10, 100_000, math.inf, True, True
    )
    rec = out[6]
    assert rec.shape[1] == 1 + NY + 13 * NY
    i = rec.shape[0] // 3
    h = rec[i + 1, 0] - rec[i, 0]
    ya = rec[i, 1 : 1 + NY]
    F = np.empty((colloc.N_DENSE, NY))
    colloc._dense(par, kernel_constants(par), np.empty(JAC_WORKSPACE_SHAPE), None, ya, h,
           rec[i + 1, 1 + NY :], np.empty((16, NY)), F, np.empty(NY))  # fmt: skip
    work = np.empty(NY)

    def f(t, y):
        rhs(par, fe, fc, geo, y, work)
        return work.copy()

    for x in (0.0, 0.3, 0.77, 1.0):
        got = np.empty(NY)
        colloc.dense_at(x, ya, F, got)
        if x == 0.0:
            want = ya
        else:
            want = solve_ivp(f, (0.0, x * h), ya, method="DOP853", rtol=1e-13, atol=1e-14).y[:, -1]
        # the dense output is of order 7: good to about the plain run's own error (1e-10)
        np.testing.assert_allclose(got, want, rtol=0, atol=1e-9)


def test_the_papers_case_is_collocated_on_the_plain_runs_steps():
    # the paper's ellipse (b/a = 0.5, uniform) under an anisotropic tensor: the ICR crosses
    # into the patch and settles a few per cent inside the rim, where the wrench's derivative
    # needs a finer rule than the wrench's own; the collocation must still run on every one
    # of the plain run's steps (one sensitivity step per plain step), not fall back to the
    # joint integration (also exact, at twice the cost)
    body = ss.Body(ss.Ellipse.from_eccentricity(0.1, 0.866), ss.UniformPressure(), mass=1.0)
    run = ss.simulate(body, ss.FrictionTensor(0.4, 0.5), ss.State(vx=1.0, omega=3.0),
                      sensitivities=("fx", "vx"))  # fmt: skip
    assert run.ending == "mixed"
    assert run.sensitivities.n_steps == run.n_steps
