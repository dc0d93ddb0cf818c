"""The footprint wrench's twist and angle derivatives (MODEL §10, §15) against independent
truth: Richardson-extrapolated central differences of the footprint reference
(tests/references/footprint_reference.py, adaptive quadrature sharing no code with the
kernel), the wrench's homogeneity, and the isotropic parts Q, N against the reference
wrench of unit tensors."""

from __future__ import annotations

import math

import numpy as np
import pytest
from footprint_reference import reference_wrench
from stop_differences import richardson

import slidespin as ss
from slidespin.contact import _engine
from slidespin.contact import _kernel_footprint_jac as KFJ
from slidespin.contact._jacobian import JAC_SIZE
from slidespin.contact.pressure_map import kernel_geometry
from slidespin.contact.shapes import Annulus, Pads, Polygon, Rectangle

L_SHAPE = [(0.0, 0.0), (0.3, 0.0), (0.3, 0.1), (0.1, 0.1), (0.1, 0.25), (0.0, 0.25)]
TENSOR = ss.FrictionTensor(0.3, 0.5, f=0.12, angle=0.4)
BODY_TENSOR = ss.FrictionTensor(0.35, 0.55, f=-0.08, frame="body", angle=-0.3)

#: (footprint, pressure, tensor, ICR in the body frame relative to G [in extents], ω, φ)
CASES = {
    "rectangle-inside": (Rectangle(0.3, 0.1), ss.UniformPressure(), TENSOR, (0.2, 0.1), 2.0, 0.3),
    "L-outside": (
        Polygon(L_SHAPE, centre=(-0.1, -0.1)),
        ss.LinearPressure(-0.005, 0.01),
        BODY_TENSOR,
        (0.45, 0.6),
        -1.5,
        1.1,
    ),
    "ring-hole": (Annulus(0.06, 0.1), ss.UniformPressure(), TENSOR, (0.15, -0.1), 3.0, -0.6),
    "ring-band": (Annulus(0.06, 0.1), ss.UniformPressure(), BODY_TENSOR, (0.3, 0.55), 1.0, 0.2),
    "pads-far": (
        Pads(
            [
                Rectangle(0.06, 0.2, centre=(0.12, 0.0)),
                Polygon([(0, 0.1), (0.05, 0.15), (-0.05, 0.15)]),
            ]
        ),
        ss.UniformPressure(),
        TENSOR,
        (30.0, -12.0),
        0.4,
        2.0,
    ),
}


def _setup(case, cases=CASES):
    fp, pressure, fr, icr, omega, phi = cases[case]
    body = ss.Body(fp, pressure, mass=1.0)
    par, fe, fc, geo = body.engine_params(fr.kinetic, 1e-14)
    ell = body.length_unit
    t = tuple(float(par[i]) for i in (_engine.P_T00, _engine.P_T01, _engine.P_T10, _engine.P_T11))
    frame = "body" if par[_engine.P_BODY] else "plane"
    ref_law = (
        ("linear", *pressure.centroid) if isinstance(pressure, ss.LinearPressure) else ("uniform",)
    )
    return body, fe, fc, geo, ell, t, frame, ref_law, icr, omega, phi


def _twist(body, ell, icr, omega, phi, at=None):
    """Natural twist (v/ℓ, ω) of G in the fixed frame whose ICR is ``icr`` extents from G,
    or (``at``, metres) at that point of the body frame."""
    if at is None:
        ext = body.patch.to_arrays().frame[2]
        d = np.array(icr) * ext / ell
    else:
        d = (np.array(at) - np.array(body.mass_centre)) / ell
    vb = -omega * np.array([-d[1], d[0]])  # c − r_G = ẑ×v/ω
    c, s = math.cos(phi), math.sin(phi)
    return np.array([c * vb[0] - s * vb[1], s * vb[0] + c * vb[1], omega])


def _kernel(fe, fc, geo, t, frame, phi, tw):
    out = np.empty(JAC_SIZE)
    ok = KFJ.jacobian_world(
        np.ascontiguousarray(fe), np.ascontiguousarray(fc), np.ascontiguousarray(geo),
        *t, frame == "body", phi, *tw, out,
    )  # fmt: skip
    return ok, out


def _evaluated(case):
    """The case's :func:`_setup`, its patch, the twist of its ICR and the kernel's (ok, out)
    there."""
    setup = _setup(case)
    body, fe, fc, geo, ell, t, frame, _, icr, omega, phi = setup
    tw = _twist(body, ell, icr, omega, phi)
    return setup, CASES[case][0], tw, *_kernel(fe, fc, geo, t, frame, phi, tw)


def _ref(fp, ref_law, t, frame, ell, phi, tw):
    tensor = np.array([[t[0], t[1]], [t[2], t[3]]])
    r = reference_wrench(fp, ref_law, tensor, tw[0] * ell, tw[1] * ell, tw[2], phi=phi, frame=frame)
    return np.array([r[0], r[1], r[2] / ell])


def _ref_twist_jacobian(fp, ref_law, t, frame, ell, phi, tw, step):
    """∂(Fx, Fy, M)/∂(vx, vy, ω) of the reference by Richardson differences at ``step``."""
    ref = np.empty((3, 3))
    for k in range(3):

        def f(x, k=k):
            w = tw.copy()
            w[k] = x
            return _ref(fp, ref_law, t, frame, ell, phi, w)

        ref[:, k] = richardson(f, tw[k], step)
    return ref


@pytest.mark.parametrize("case", sorted(CASES))
def test_jacobian_matches_reference_differences(case):
    (_, _, _, _, ell, t, frame, ref_law, _, _, phi), fp, tw, ok, out = _evaluated(case)
    assert ok
    assert out[:3] == pytest.approx(_ref(fp, ref_law, t, frame, ell, phi, tw), abs=1e-9)
    scale = np.linalg.norm(tw)
    ref = np.empty((3, 4))
    ref[:, :3] = _ref_twist_jacobian(fp, ref_law, t, frame, ell, phi, tw, 2e-3 * scale)
    ref[:, 3] = richardson(lambda p: _ref(fp, ref_law, t, frame, ell, p, tw), phi, 2e-3)
    got = np.column_stack([out[9:18].reshape(3, 3), out[18:21]])
    big = np.abs(ref).max()
    assert np.abs(got - ref).max() <= 1e-6 * big, (got, ref)


@pytest.mark.parametrize("case", sorted(CASES))
def test_jacobian_annihilates_the_twist(case):
    _, _, tw, _, out = _evaluated(case)
    jac = out[9:18].reshape(3, 3)
    assert np.abs(jac @ tw).max() <= 1e-8 * np.abs(jac).max() * np.linalg.norm(tw)


@pytest.mark.parametrize("case", ["rectangle-inside", "L-outside", "ring-band"])
def test_isotropic_parts_give_the_wrench_of_any_tensor(case):
    (_, _, _, _, ell, _, _, ref_law, _, _, phi), fp, tw, _, out = _evaluated(case)
    c, s = math.cos(phi), math.sin(phi)
    R = np.array([[c, -s], [s, c]])
    for i in range(2):
        for j in range(2):
            e = np.zeros((2, 2))
            e[i, j] = 1.0  # in the body frame
            r = reference_wrench(fp, ref_law, e, tw[0] * ell, tw[1] * ell, tw[2], phi=phi,
                                 frame="body")  # fmt: skip
            fb = R.T @ np.array(r[:2])
            assert fb == pytest.approx(-e @ out[3:5], abs=1e-10)
            assert r[2] / ell == pytest.approx(-out[5 + 2 * i + j], abs=1e-10)


def test_translation_is_left_to_differences():
    # ω = 0 (a translation): no derivative, the caller differences the right-hand side
    body, fe, fc, geo, ell, t, frame, *_ = _setup("rectangle-inside")
    ok, out = _kernel(fe, fc, geo, t, frame, 0.3, np.array([1.0, 0.5, 0.0]))
    assert not ok and np.isnan(out[9:]).all() and np.isfinite(out[:3]).all()


#: (footprint, pressure, tensor, ICR as a point of the body frame [m], ω, φ): the ICR where
#: the exact derivative's special cases are (a circle's centre and rim, an edge's line, near a
#: vertex), and a thin ring (differenced in c). The wrench is only C¹ across a rim or an edge
#: (its second derivative has a logarithmic singularity there): the reference's steps are
#: short (1e-4 of the twist), for its differences to converge
AT_POINTS = {
    "disk-centre": (ss.Disk(0.05), ss.UniformPressure(), TENSOR, (0.0, 0.0), 2.0, 0.4),
    "ring-centre-linear": (
        Annulus(0.06, 0.1),
        ss.LinearPressure(0.004, -0.006),
        BODY_TENSOR,
        (0.0, 0.0),
        -1.2,
        0.7,
    ),
    "ring-on-rim": (Annulus(0.06, 0.1), ss.UniformPressure(), TENSOR, (0.0, 0.1), 1.5, 0.0),
    "ring-on-hole-rim-linear": (
        Annulus(0.06, 0.1),
        ss.LinearPressure(-0.005, 0.003),
        TENSOR,
        (0.06 / math.sqrt(2.0), 0.06 / math.sqrt(2.0)),
        0.8,
        -0.2,
    ),
    "rectangle-edge-line": (
        Rectangle(0.3, 0.1),
        ss.LinearPressure(0.01, 0.004),
        TENSOR,
        (0.15, 0.02),
        -2.0,
        0.3,
    ),
    # (at the vertex itself the second derivative's singularity is odd: the central
    # differences converge like h log h there, too slowly to be a reference)
    "L-near-reflex-vertex": (
        Polygon(L_SHAPE),
        ss.UniformPressure(),
        BODY_TENSOR,
        (0.104, 0.097),
        1.0,
        0.9,
    ),
    "thin-ring": (Annulus(0.0995, 0.1), ss.UniformPressure(), TENSOR, (0.03, -0.12), 1.0, 0.5),
}


@pytest.mark.parametrize("case", sorted(AT_POINTS))
def test_jacobian_where_the_icr_meets_the_footprints_features(case):
    body, fe, fc, geo, ell, t, frame, ref_law, point, omega, phi = _setup(case, AT_POINTS)
    fp = AT_POINTS[case][0]
    tw = _twist(body, ell, None, omega, phi, at=point)
    ok, out = _kernel(fe, fc, geo, t, frame, phi, tw)
    assert ok
    ref = _ref_twist_jacobian(fp, ref_law, t, frame, ell, phi, tw, 1e-4 * abs(omega))
    got = out[9:18].reshape(3, 3)
    assert np.abs(got - ref).max() <= 1e-6 * np.abs(ref).max(), (got, ref)


@pytest.mark.parametrize("point", [(1.0, 0.3), (1.0, 0.0), (0.5, 0.0), (0.0, 1.0)])
def test_edge_through_the_icr_is_the_limit_of_its_neighbours(point):
    # an edge whose line passes exactly through c has no area but its boundary term (the
    # branch d = 0 of edge_lines): ∂G/∂c there is the limit from either side (G is C¹)
    edges = np.array([[0, 0, 1, 0], [1, 0, 1, 1], [1, 1, 0, 1], [0, 1, 0, 0]], dtype=float)
    circles = np.zeros((0, 4))
    dg = np.empty(27)
    KFJ.fan_tensors_jac(edges, circles, point[0], point[1], dg)
    at = dg.copy()
    for off in ((1e-9, 3e-10), (-1e-9, 2e-10), (4e-10, -1e-9), (-3e-10, -1e-9)):
        KFJ.fan_tensors_jac(edges, circles, point[0] + off[0], point[1] + off[1], dg)
        assert np.abs(dg - at).max() <= 1e-7 * np.abs(at).max()


@pytest.mark.parametrize("case", ["L-outside", "ring-band", "rectangle-inside", "pads-far"])
def test_pressure_centre_derivative_matches_reference_differences(case):
    # moving the pressure centre moves G (the ICR with it, at a fixed twist of G; the
    # moment's arm) and the linear law through it: the kernel's ∂W/∂G and ∂W/∂p (out[21:36])
    # chained with the law's rates (the coefficients are linear in the centre; rates from
    # the library's geometry rows, checked in test_footprint_wrench) against Richardson
    # differences of the reference, whose law and G move together
    (body, _, _, _, ell, t, frame, _, _, _, phi), fp, tw, ok, out = _evaluated(case)
    assert ok
    xi, eta = body.mass_centre  # the pressure centre (G) of either law
    arrays = fp.to_arrays()
    h = 1e-4 * ell
    for j in range(2):
        e = np.array([h, 0.0]) if j == 0 else np.array([0.0, h])
        gp = kernel_geometry(fp, ss.LinearPressure(xi + e[0], eta + e[1]), arrays, length=ell)
        gm = kernel_geometry(fp, ss.LinearPressure(xi - e[0], eta - e[1]), arrays, length=ell)
        rate = (gp - gm) / (2.0 * h)  # per metre; G and p in the kernel's units
        got = rate[6] * out[21:24] + rate[7] * out[24:27]
        for i in range(3):
            got = got + rate[3 + i] * out[27 + 3 * i : 30 + 3 * i]

        def f(x, j=j):
            c = [xi, eta]
            c[j] = x
            return _ref(fp, ("linear", *c), t, frame, ell, phi, tw)

        ref = richardson(f, (xi, eta)[j], 2e-3 * ell)
        assert np.abs(got - ref).max() <= 1e-6 * max(np.abs(ref).max(), 1e-3), (j, got, ref)
