"""Self-checks of the quadrature oracle in tests/reference.py against closed forms and exact
identities that do not use its internals (MODEL.md section 8)."""

from __future__ import annotations

import math
import os
import sys

import numpy as np
import pytest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from reference import _compute, reference_dissipation, reference_wrench  # noqa: E402

# any non-converged quadrature in the oracle is a UserWarning (scipy's IntegrationWarning is one)
pytestmark = pytest.mark.filterwarnings("error::UserWarning")

LAWS = ("uniform", "linear", "boussinesq", "hertz")
SPIN_FACTOR = {"uniform": 2.0 / 3.0, "boussinesq": math.pi / 4.0, "hertz": 3.0 * math.pi / 16.0}

A, B = 0.9, 0.54  # an ellipse (e = 0.8)
T_GEN = np.array([[0.31, 0.12], [-0.07, 0.55]])  # general (non-symmetric) tensor, fx, fy > 0


def rot(t):
    c, s = math.cos(t), math.sin(t)
    return np.array([[c, -s], [s, c]])


def centroid(law, a, b):
    return (0.05 * a, -0.03 * b) if law == "linear" else (0.0, 0.0)


def velocity_for_icr(xi_i, eta_i, omega, phi, xi_c, eta_c):
    """(vx, vy) of G such that the ICR is at body point (xi_i, eta_i)."""
    d = rot(phi) @ np.array([xi_i - xi_c, eta_i - eta_c])  # world offset of the ICR from G
    return omega * d[1], -omega * d[0]


def wrench_icr(law, a, b, T, phi, rad, ang, omega, P=1.0):
    """Wrench with the ICR at scaled polar position (rad, ang): (a rad cos, b rad sin)."""
    xc, yc = centroid(law, a, b)
    vx, vy = velocity_for_icr(a * rad * math.cos(ang), b * rad * math.sin(ang), omega, phi, xc, yc)
    return np.array(reference_wrench(a, b, law, T, phi, vx, vy, omega, xc, yc, P)), (vx, vy)


# 1. pure translation ------------------------------------------------------------------------
@pytest.mark.parametrize("law", LAWS)
def test_pure_translation(law):
    xc, yc = centroid(law, A, B)
    for T, phi, v, P in [
        (T_GEN, 0.7, (0.4, -0.7), 1.0),
        (np.array([[0.2, 0.0], [0.0, 0.6]]), -2.1, (0.0, 3.0), 2.5),
        (np.array([[0.5, -0.3], [0.3, 0.4]]), 0.0, (-1e-3, 2e-4), 1.0),
    ]:
        v = np.asarray(v)
        F = np.array(reference_wrench(A, B, law, T, phi, v[0], v[1], 0.0, xc, yc, P))
        expected = -P * (T @ v) / np.linalg.norm(v)
        assert np.abs(F[:2] - expected).max() < 1e-13
        assert abs(F[2]) < 1e-13


# 2. pure spin of a circle ---------------------------------------------------------------------
@pytest.mark.parametrize("law", ["uniform", "boussinesq", "hertz"])
@pytest.mark.parametrize("omega", [2.3, -0.4])
def test_pure_spin_circle(law, omega):
    a, f, P = 0.7, 0.35, 1.7
    Fx, Fy, M = reference_wrench(a, a, law, f * np.eye(2), 0.3, 0.0, 0.0, omega, P=P)
    assert abs(Fx) < 1e-14 and abs(Fy) < 1e-14
    assert M == pytest.approx(
        -math.copysign(1.0, omega) * f * P * a * SPIN_FACTOR[law], rel=1e-13, abs=1e-14
    )


def test_pure_spin_linear_is_uniform_when_centroid_at_centre():
    r_lin = reference_wrench(0.8, 0.8, "linear", 0.3 * np.eye(2), 1.0, 0.0, 0.0, 1.0)
    assert r_lin[2] == pytest.approx(-0.3 * 0.8 * 2.0 / 3.0, rel=1e-13)


# 3. continuity through the rim ----------------------------------------------------------------
@pytest.mark.parametrize("law", LAWS)
def test_rim_continuity(law):
    for ang in (0.0, 0.9, math.pi / 2, 4.0):
        on, _ = wrench_icr(law, A, B, T_GEN, 0.4, 1.0, ang, 1.3)
        for rad in (1.0 - 1e-9, 1.0 + 1e-9):
            near, _ = wrench_icr(law, A, B, T_GEN, 0.4, rad, ang, 1.3)
            assert np.abs(near - on).max() < 1e-8
        # a Lipschitz-like approach on both sides (the wrench has bounded derivative there)
        d_in = wrench_icr(law, A, B, T_GEN, 0.4, 1.0 - 1e-5, ang, 1.3)[0] - on
        d_out = wrench_icr(law, A, B, T_GEN, 0.4, 1.0 + 1e-5, ang, 1.3)[0] - on
        # equal and opposite to first order (the remainder is O(1e-5^1.5) for Boussinesq)
        assert np.abs(d_in + d_out).max() < 0.02 * np.abs(d_in).max() + 1e-12


# 4. energy balance ----------------------------------------------------------------------------
@pytest.mark.parametrize("law", LAWS)
def test_power_equals_dissipation(law):
    xc, yc = centroid(law, A, B)
    phi = -0.6
    states = [(0.37, -0.55, 0.0), (0.0, 0.0, -1.9)]
    for rad, ang, om in [
        (0.4, 1.0, 1.1),
        (1.0, 2.2, -0.7),
        (1 + 1e-7, 0.3, 2.0),
        (2.5, -1.0, 0.8),
        (40.0, 0.5, -0.05),
    ]:
        vx, vy = velocity_for_icr(A * rad * math.cos(ang), B * rad * math.sin(ang), om, phi, xc, yc)
        states.append((vx, vy, om))
    for vx, vy, om in states:
        Fx, Fy, M = reference_wrench(A, B, law, T_GEN, phi, vx, vy, om, xc, yc)
        power = Fx * vx + Fy * vy + M * om
        diss = reference_dissipation(A, B, law, T_GEN, phi, vx, vy, om, xc, yc)
        assert diss < 0.0
        assert power == pytest.approx(diss, rel=1e-12, abs=1e-14)


# 5. rotation equivariance ---------------------------------------------------------------------
@pytest.mark.parametrize("law", LAWS)
def test_rotation_equivariance(law):
    xc, yc = centroid(law, A, B)
    alpha = 1.234
    Ra = rot(alpha)
    for phi, v, om in [
        (0.3, (0.2, -0.4), 1.5),
        (2.0, (1.0, 0.3), -0.2),
        (-1.0, (0.1, 0.0), 0.0),
        (0.0, (0.0, 0.0), 1.0),
    ]:
        v = np.asarray(v, dtype=float)
        base = np.array(reference_wrench(A, B, law, T_GEN, phi, v[0], v[1], om, xc, yc))
        v2 = Ra @ v
        turned = np.array(
            reference_wrench(A, B, law, Ra @ T_GEN @ Ra.T, phi + alpha, v2[0], v2[1], om, xc, yc)
        )
        assert np.abs(turned[:2] - Ra @ base[:2]).max() < 1e-13
        assert abs(turned[2] - base[2]) < 1e-13


# symmetry and homogeneity ---------------------------------------------------------------------
def test_zero_state_and_homogeneity():
    assert reference_wrench(A, B, "hertz", T_GEN, 0.3, 0.0, 0.0, 0.0) == (0.0, 0.0, 0.0)
    for law in LAWS:
        xc, yc = centroid(law, A, B)
        base = np.array(reference_wrench(A, B, law, T_GEN, 0.3, 0.2, -0.1, 0.8, xc, yc))
        scaled = np.array(reference_wrench(A, B, law, T_GEN, 0.3, 0.74, -0.37, 2.96, xc, yc))
        flipped = np.array(reference_wrench(A, B, law, T_GEN, 0.3, -0.2, 0.1, -0.8, xc, yc))
        assert np.abs(scaled - base).max() < 1e-13
        assert np.abs(flipped + base).max() < 1e-13


# far ICR --------------------------------------------------------------------------------------
@pytest.mark.parametrize("law", LAWS)
def test_far_icr(law):
    xc, yc = centroid(law, A, B)
    phi, ang = 0.5, 0.8
    trans = None
    moments = {}
    for D in (1e4, 1e6):
        icr = np.array([xc, yc]) + D * A * np.array([math.cos(ang), math.sin(ang)])
        vx, vy = velocity_for_icr(icr[0], icr[1], 1.0, phi, xc, yc)
        F = np.array(reference_wrench(A, B, law, T_GEN, phi, vx, vy, 1.0, xc, yc))
        if trans is None:
            trans = np.array(reference_wrench(A, B, law, T_GEN, phi, vx, vy, 0.0, xc, yc))
            assert np.abs(F[:2] - trans[:2]).max() < 1e-4 * np.abs(trans[:2]).max()
            assert 1e-7 < abs(F[2]) < 1e-3
        moments[D] = F[2]
    # M ~ c/D: no cancellation noise at |ICR| = 1e6 a (where M ~ 1e-7)
    assert moments[1e6] * 1e6 == pytest.approx(moments[1e4] * 1e4, rel=1e-3)


# the two internal methods agree where both apply ------------------------------------------------
@pytest.mark.parametrize("law", LAWS)
def test_line_and_direct_methods_agree(law):
    xc, yc = centroid(law, A, B)
    phi = 0.7
    for rad, ang, om in [(1.5, 0.4, 1.3), (3.0, 2.5, -0.8), (1.02, -1.2, 0.6)]:
        vx, vy = velocity_for_icr(A * rad * math.cos(ang), B * rad * math.sin(ang), om, phi, xc, yc)
        args = (A, B, law, T_GEN, phi, vx, vy, om, xc, yc, 1.0, 1e-13)
        line = _compute(*args, method="polar")
        direct = _compute(*args, method="direct")
        assert np.abs(line - direct).max() < 1e-12 * max(1.0, abs(line[3]))


def test_line_and_direct_methods_agree_icr_inside():
    # the direct method is slow with the ICR inside (the integrand's direction jumps there),
    # but adaptive quadrature still reaches ~1e-13
    law = "boussinesq"
    vx, vy = velocity_for_icr(A * 0.3, B * 0.2, 1.3, 0.7, 0.0, 0.0)
    args = (A, B, law, T_GEN, 0.7, vx, vy, 1.3, 0.0, 0.0, 1.0)
    line = _compute(*args, 1e-13, method="polar")
    direct = _compute(*args, 1e-11, method="direct")
    assert np.abs(line - direct)[:3].max() < 1e-11
