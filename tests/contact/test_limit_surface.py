"""The limit surface (MODEL §11) against the Contensou closed forms and maximum dissipation.

Contensou closed forms for a uniformly loaded disk of radius R, isotropic μ, twist with the
instantaneous centre of rotation at distance ε R from the centre (ε = v/(R|ω|)); K, E are the
complete elliptic integrals of modulus k (scipy's ellipk/ellipe take m = k²):

    ε ≤ 1:  F/(μP) = 4/(3π) [(ε²+1) E(ε) + (ε²−1) K(ε)]/ε,
            M/(μPR) = 4/(9π) [(4−2ε²) E(ε) + (ε²−1) K(ε)],
    ε ≥ 1:  F/(μP) = 4/(3π) [(ε²+1) E(1/ε) − (ε²−1) K(1/ε)],
            M/(μPR) = 4/(9π) [2ε(2−ε²) E(1/ε) + (ε²−1)(2ε²−3) K(1/ε)/ε],

the force opposing v and the moment opposing ω (Contensou 1963; the forms for ε ≤ 1 and the
force for ε ≥ 1 are those of Farkas, Bartels, Unger & Wolf, PRL 90, 248302 (2003); the moment
for ε ≥ 1 was derived for this test). Derivation: with p = P/(πR²), R = 1 and the ICR at c,
ŵ = J ê_ρ, so F = −(μP/π) J ∫(r − c)/|r − c| dS = (μP/π) J ∇Φ(c) and
M = −(μP/π) (Φ − c·∇Φ), where Φ(c) = ∫_disk |r − c| dS; the angular integral is
4(r + c) E(2√(rc)/(r + c)) = 4 max(r, c) [2E(k) − (1 − k²) K(k)], k = min/max, and
∫ k [2E − (1 − k²) K] dk = (7/9)[(1+k²)E − (1−k²)K] − (2/3)[E − (1−k²)K] − k²(1−k²)K/3.
For ε ≥ 2 the test sums the power series of K and E instead (the closed forms cancel digits).

Maximum dissipation (Goyal, Ruina & Papadopoulos 1991): with isotropic friction the twist is
normal to the limit surface, checked by central differences of the exact wrenches, independent
of any fit.
"""

from __future__ import annotations

import json
import math

import matplotlib
import numpy as np
import pytest
from scipy.special import ellipe, ellipk

import slidespin as ss
from slidespin.contact.limit_surface import QUARTIC_EXPONENTS, limit_surface, sphere_directions
from slidespin.contact.statics import load_factor

matplotlib.use("Agg")
G = 9.81


def _series(q, terms=90):
    """[(ε²+1)E − (ε²−1)K]·q and ε·[2ε(2−ε²)E + (ε²−1)(2ε²−3)K/ε]·q², q = 1/ε² ≤ 1/4,
    from the power series K = (π/2) Σ aₙ qⁿ, E = (π/2) Σ bₙ qⁿ, with the cancelling leading
    coefficients dropped exactly (the closed forms lose digits as ε grows)."""
    a = [1.0]
    for n in range(1, terms + 3):
        a.append(a[-1] * ((2 * n - 1) / (2 * n)) ** 2)
    b = [-a[n] / (2 * n - 1) for n in range(len(a))]
    at = lambda n: a[n] if n >= 0 else 0.0
    bt = lambda n: b[n] if n >= 0 else 0.0
    f = sum((bt(n) + bt(n - 1) - at(n) + at(n - 1)) * q ** (n - 1) for n in range(1, terms))
    m = sum(
        (4 * bt(n - 1) - 2 * bt(n) + 2 * at(n) - 5 * at(n - 1) + 3 * at(n - 2)) * q ** (n - 2)
        for n in range(2, terms)
    )
    return math.pi / 2 * f, math.pi / 2 * m


def contensou(eps):
    """(F/(μP), M/(μPR)) of a uniformly loaded disk for ε = v/(R|ω|)."""
    if eps <= 1.0:
        m = eps * eps
        e, k = ellipe(m), ellipk(m)
        f = 4 / (3 * math.pi) * ((m + 1) * e + (m - 1) * k) / eps if eps > 0 else 0.0
        mom = 4 / (9 * math.pi) * ((4 - 2 * m) * e + (m - 1) * k)
        return f, mom
    m = eps * eps
    if eps >= 2.0:
        f, mm = _series(1.0 / m)
        return 4 / (3 * math.pi) * f, 4 / (9 * math.pi) * mm / eps
    e, k = ellipe(1.0 / m), ellipk(1.0 / m)
    f = 4 / (3 * math.pi) * ((m + 1) * e - (m - 1) * k)
    mom = 4 / (9 * math.pi) * (2 * eps * (2 - m) * e + (m - 1) * (2 * m - 3) * k / eps)
    return f, mom


def test_closed_form_limits():
    assert contensou(0.0) == pytest.approx((0.0, 2 / 3), abs=1e-15)  # pure spin, MODEL §8
    f, m = contensou(1e4)
    assert f == pytest.approx(1.0, abs=1e-7) and m == pytest.approx(1 / (4 * 1e4), rel=1e-4)
    below, above = contensou(1 - 1e-9), contensou(1 + 1e-9)
    assert below == pytest.approx(above, abs=1e-7)  # continuous across the rim
    # the series branch agrees with the closed form where both are accurate
    lo, hi = contensou(2.0 - 1e-12), contensou(2.0)
    assert lo == pytest.approx(hi, rel=1e-12)


def test_uniform_disk_follows_contensou():
    r, m, mu = 0.08, 1.5, 0.35
    body = ss.Body(ss.Circle(r), ss.UniformPressure(), m)
    ls = limit_surface(body, ss.FrictionTensor.isotropic(mu), n=120, g=G, length=r)
    p = m * G
    for vx, vy, om, fx, fy, mz in zip(ls.vx, ls.vy, ls.omega, ls.force_x, ls.force_y, ls.moment):
        v = math.hypot(vx, vy)
        eps = v / (r * abs(om))
        f, mm = contensou(eps)
        assert fx == pytest.approx(-mu * p * f * vx / v, abs=1e-10 * mu * p)
        assert fy == pytest.approx(-mu * p * f * vy / v, abs=1e-10 * mu * p)
        assert mz == pytest.approx(-math.copysign(mu * p * r * mm, om), abs=1e-10 * mu * p * r)


@pytest.mark.parametrize(
    "body",
    [
        ss.Body(ss.Ellipse(0.1, 0.05), ss.LinearPressure(0.01, -0.005), 1.0),
        ss.Body(ss.Circle(0.05), ss.HertzPressure(), 2.0),
    ],
)
def test_isotropic_twist_is_normal_to_the_limit_surface(body):
    fr = ss.FrictionTensor.isotropic(0.4)
    ell = body.radius_of_gyration
    rng = np.random.default_rng(13)
    for u in rng.normal(size=(6, 3)):
        u /= np.linalg.norm(u)
        e1 = np.cross(u, [1.0, 0.0, 0.0])
        e1 /= np.linalg.norm(e1)
        e2 = np.cross(u, e1)
        for e in (e1, e2):
            h = 1e-4
            tw = np.array([u + h * e, u - h * e])
            w = ss.friction_wrench(body, fr, tw[:, 0], tw[:, 1], tw[:, 2] / ell, 0.3, g=G)
            dw = np.array(
                [
                    w.force_x[0] - w.force_x[1],
                    w.force_y[0] - w.force_y[1],
                    (w.moment[0] - w.moment[1]) / ell,
                ]
            )
            # the tangent of the surface at W(u) is orthogonal to the twist u
            assert abs(dw @ u) < 1e-6 * np.linalg.norm(dw)


def test_isotropic_surface_bounds_c_and_anisotropic_lies_inside():
    body = ss.Body(ss.Ellipse(0.1, 0.06), ss.UniformPressure(), 1.0)
    iso = limit_surface(body, ss.FrictionTensor.isotropic(0.3), n=40, g=G)
    assert np.max(np.abs(iso.dissipation_gap)) < 1e-11 * np.max(iso.support)
    aniso_fr = ss.FrictionTensor(0.2, 0.5, 0.05)
    ani = limit_surface(body, aniso_fr, n=40, g=G)
    assert np.all(ani.dissipation_gap >= 0.0) and np.max(ani.dissipation_gap) > 1e-3
    # every sliding wrench is one static friction could supply: it lies in C (λ* ≥ 1)
    for i in range(0, 40, 7):
        w = (ani.force_x[i], ani.force_y[i], ani.moment[i])
        assert load_factor(body, aniso_fr, w, g=G) >= 1.0 - 1e-10


def test_fits_report_their_own_errors_and_the_quartic_is_convex():
    body = ss.Body(ss.Circle(0.05), ss.UniformPressure(), 1.0)
    ls = limit_surface(body, ss.FrictionTensor.isotropic(0.3), n=200, g=G)
    w = ls.wrenches
    q2 = np.einsum("ni,ij,nj->n", w, ls.ellipsoid, w)
    assert ls.ellipsoid_error == pytest.approx(np.max(np.abs(np.sqrt(q2) - 1)), rel=1e-12)
    feats = np.column_stack(
        [w[:, 0] ** i * w[:, 1] ** j * w[:, 2] ** k for i, j, k in QUARTIC_EXPONENTS]
    )
    assert ls.quartic_error == pytest.approx(
        np.max(np.abs((feats @ ls.quartic) ** 0.25 - 1)), rel=1e-12
    )
    # a disk's surface is axially symmetric: A has equal force entries and no coupling
    a = ls.ellipsoid
    assert a[0, 0] == pytest.approx(a[1, 1], rel=1e-2)
    assert ls.quartic_error < ls.ellipsoid_error < 0.1
    # convexity: the Hessian of the quartic is positive semidefinite everywhere
    for x in sphere_directions(50):
        hess = np.zeros((3, 3))
        for c, (i, j, k) in zip(ls.quartic, QUARTIC_EXPONENTS):
            e = np.array([i, j, k])
            for p in range(3):
                for q in range(3):
                    ee = e.copy()
                    coef = ee[p]
                    ee[p] -= 1
                    coef *= ee[q]
                    ee[q] -= 1
                    if coef and (ee >= 0).all():
                        hess[p, q] += c * coef * np.prod(x**ee)
        assert np.linalg.eigvalsh(hess).min() >= -1e-12 * np.abs(hess).max()


def test_exports_and_figure(tmp_path):
    body = ss.Body(ss.Ellipse(0.1, 0.05), ss.UniformPressure(), 1.0)
    ls = limit_surface(body, ss.FrictionTensor(0.3, 0.4), n=30, g=G)
    d = json.loads(ls.to_json(tmp_path / "ls.json"))
    assert d["n"] == 30 and len(d["force_x"]) == 30
    ls.to_npz(tmp_path / "ls.npz")
    with np.load(tmp_path / "ls.npz") as z:
        np.testing.assert_array_equal(z["moment"], ls.moment)
    ax = ls.plot()
    ax.figure.savefig(tmp_path / "ls.png")
    assert (tmp_path / "ls.png").stat().st_size > 0


def test_cli_plugin(tmp_path, capsys):
    import argparse

    from slidespin.cli import limit_surface as ls_cli

    case = tmp_path / "case.toml"
    case.write_text(
        '[patch]\nshape = "circle"\nradius = 0.05\n[pressure]\nlaw = "uniform"\n'
        "[friction]\nfx = 0.3\nfy = 0.3\n[body]\nmass = 1.0\n[initial]\n"
    )
    parser = argparse.ArgumentParser()
    ls_cli.configure(parser)
    args = parser.parse_args([str(case), "--n", "20", "--json", "--npz", str(tmp_path / "o.npz")])
    assert ls_cli.run(args) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["n"] == 20 and out["max_dissipation_gap"] < 1e-12
    # largest force of the isotropic disk: μ P (pure sliding)
    assert out["max_force"] <= 0.3 * 9.81 + 1e-12
    with pytest.raises(ValueError, match="--n"):
        ls_cli.run(parser.parse_args([str(case), "--n", "3"]))


def test_validation():
    body = ss.Body(ss.Circle(0.05), ss.UniformPressure(), 1.0)
    with pytest.raises(ValueError, match="n = 5"):
        limit_surface(body, ss.FrictionTensor(0.3, 0.3), n=5)
    with pytest.raises(ValueError, match="length"):
        limit_surface(body, ss.FrictionTensor(0.3, 0.3), length=-1.0)
