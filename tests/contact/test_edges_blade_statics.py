"""Static friction of a Blade (a line contact) under any friction tensor (MODEL §10–11).

A blade under anisotropic friction used to divide by its zero area. Independent truths: the
support function of the static set C, h(d) = ∫ q |𝔽ᵀ(d_F + d_M J r′(s))| ds, integrated along
the blade here by adaptive quadrature; the load factor as a brute-force minimisation of
h(d)/(d·W_a) over wrench directions; closed forms (a force W through G:
λ* = P/|𝔽⁻¹W|, for any patch with G over its pressure centroid; a pure torque on a blade
along ξ under a diagonal tensor: λ* = fy P L/(4 T)); the onset's defining relation checked
with a wrench integrated along the blade here; and the motion of a blade pulled along its
axis, x = (Q − fx m g) t²/(2m).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import minimize

import slidespin as ss
from slidespin.contact import statics
from slidespin.contact.limit_surface import limit_surface
from slidespin.contact.shapes import Blade
from slidespin.contact.static_set import support_function

G = 9.81
MASS = 2.0
TENSORS = (
    ss.FrictionTensor(0.3, 0.5),
    ss.FrictionTensor(0.25, 0.6, 0.1, angle=0.7),
    ss.FrictionTensor(0.4, 0.2, -0.05, frame="body", angle=-0.3),
)


def blade_body(length=0.4, centre=(0.0, 0.0), angle=0.0):
    return ss.Body(Blade(length, centre=centre, angle=angle), ss.UniformPressure(), MASS)


def _frame(body, phi):
    """Blade direction in the world and its half length."""
    bl = body.patch
    c, s = math.cos(phi + bl.angle), math.sin(phi + bl.angle)
    return np.array([c, s]), 0.5 * bl.length


def h_ref(body, friction, d, phi=0.0):
    """h(d) [N] by quadrature along the blade (G over its centre)."""
    e, half = _frame(body, phi)
    st = friction.world_matrix(phi).T
    q = MASS * G / (2.0 * half)
    a = st @ np.asarray(d[:2], float)
    b = d[2] * st @ np.array([-e[1], e[0]])  # d_M S J r′(s) = s b
    pts = []
    if b @ b > 0.0:
        s0 = -(a @ b) / (b @ b)
        pts = [s0] if -half < s0 < half else []
    val, _ = quad(
        lambda s: q * math.hypot(*(a + s * b)),
        -half,
        half,
        points=pts or None,
        epsabs=0.0,
        epsrel=1e-13,
        limit=200,
    )
    return val


def wrench_ref(body, friction, twist, phi=0.0):
    """(Fx, Fy, M about G) [N, N, N m] of the sliding blade by quadrature (MODEL §2)."""
    e, half = _frame(body, phi)
    t = friction.world_matrix(phi)
    q = MASS * G / (2.0 * half)
    vx, vy, om = twist

    def part(s, k):
        x, y = s * e
        wx, wy = vx - om * y, vy + om * x
        n = math.hypot(wx, wy)
        tx, ty = -(t[0, 0] * wx + t[0, 1] * wy) / n, -(t[1, 0] * wx + t[1, 1] * wy) / n
        return q * (tx, ty, x * ty - y * tx)[k]

    # the slip vanishes (and turns) where the ICR's projection falls
    pts = []
    if om != 0.0:
        s0 = (-vx * e[1] + vy * e[0]) / -om
        pts = [s0] if -half < s0 < half else []
    return np.array(
        [
            quad(part, -half, half, args=(k,), points=pts or None, epsrel=1e-12, limit=200)[0]
            for k in range(3)
        ]
    )


@pytest.mark.parametrize("friction", TENSORS)
def test_support_function_matches_quadrature(friction):
    body = blade_body(centre=(0.1, -0.2), angle=0.4)
    rng = np.random.default_rng(11)
    for _ in range(6):
        d = rng.normal(size=3) * np.array([1.0, 1.0, 5.0])
        phi = rng.uniform(-3.0, 3.0)
        h, point = support_function(body, friction, d, phi, g=G)
        assert h == pytest.approx(h_ref(body, friction, d, phi), rel=1e-11)
        # the support point is the gradient of h (central differences of the reference)
        step = 1e-6
        grad = [
            (
                h_ref(body, friction, d + step * np.eye(3)[i], phi)
                - h_ref(body, friction, d - step * np.eye(3)[i], phi)
            )
            / (2.0 * step)
            for i in range(3)
        ]
        assert point == pytest.approx(grad, rel=1e-6, abs=1e-8 * MASS * G)
        assert float(np.dot(d, point)) == pytest.approx(h, rel=1e-11)


@pytest.mark.parametrize("friction", TENSORS)
def test_load_factor_of_a_force_closed_form(friction):
    """A force W through G: λ* = P/|𝔽⁻¹ W| (the image of the unit disk under 𝔽, scaled)."""
    body = blade_body(angle=0.25)
    for ang in (0.0, 1.0, 2.5, -2.0):
        for phi in (0.0, 0.8):
            w = 7.0 * np.array([math.cos(ang), math.sin(ang)])
            lam = statics.load_factor(body, friction, (w[0], w[1], 0.0), phi, g=G)
            exact = MASS * G / np.linalg.norm(np.linalg.solve(friction.world_matrix(phi), w))
            assert lam == pytest.approx(exact, rel=1e-9)


def test_torque_and_axis_closed_forms():
    """A blade along ξ, 𝔽 = diag(fx, fy): along the blade fx P/Q, across fy P/Q, a pure
    torque fy P L/(4 T) (only the slip across the blade resists a spin about G)."""
    fx, fy, length = 0.3, 0.5, 0.4
    body = blade_body(length)
    fr = ss.FrictionTensor(fx, fy)
    p = MASS * G
    assert statics.load_factor(body, fr, (2.0, 0.0, 0.0), g=G) == pytest.approx(fx * p / 2.0)
    assert statics.load_factor(body, fr, (0.0, 2.0, 0.0), g=G) == pytest.approx(fy * p / 2.0)
    lam = statics.load_factor(body, fr, (0.0, 0.0, 0.1), g=G)
    assert lam == pytest.approx(fy * p * length / 4.0 / 0.1, rel=1e-9)
    assert statics.can_stick(body, fr, (0.0, 0.0, 0.99 * fy * p * length / 4.0), g=G)
    assert not statics.can_stick(body, fr, (0.0, 0.0, 1.01 * fy * p * length / 4.0), g=G)
    # the tilt: tan α_c = λ*(m g d) = 1/|𝔽⁻¹ d|
    assert statics.critical_tilt(body, fr, downhill=0.0) == pytest.approx(math.atan(fx))
    assert statics.critical_tilt(body, fr, downhill=math.pi / 2) == pytest.approx(math.atan(fy))


@pytest.mark.parametrize("friction", TENSORS[1:])
def test_load_factor_matches_brute_force(friction):
    body = blade_body(centre=(0.05, 0.0), angle=-0.6)
    rng = np.random.default_rng(5)
    for _ in range(3):
        load = rng.normal(size=3) * np.array([5.0, 5.0, 0.5])
        phi = rng.uniform(-1.0, 1.0)
        bh = load / np.linalg.norm(load)
        e1 = np.cross(bh, [1.0, 0.0, 0.0])
        e1 /= np.linalg.norm(e1)
        e2 = np.cross(bh, e1)

        def ratio(pq, load=load, bh=bh, e1=e1, e2=e2, phi=phi):
            d = bh + pq[0] * e1 + pq[1] * e2
            return h_ref(body, friction, d, phi) / float(d @ load)

        best = min(
            (
                minimize(
                    ratio,
                    x0,
                    method="Nelder-Mead",
                    options={"xatol": 1e-10, "fatol": 1e-14, "maxiter": 4000},
                )
                for x0 in (np.zeros(2), np.array([0.5, -0.5]), np.array([-1.0, 1.0]))
            ),
            key=lambda r: r.fun,
        )
        lam = statics.load_factor(body, friction, load, phi, g=G)
        assert lam == pytest.approx(best.fun, rel=1e-7)


@pytest.mark.parametrize("friction", TENSORS)
def test_onset_satisfies_its_equation(friction):
    """M⁻¹(W_a + W(u)) is a positive multiple λ of the scaled twist u (MODEL §11)."""
    body = blade_body(angle=0.3)
    k = body.radius_of_gyration
    for load in ((15.0, 3.0, 0.0), (-2.0, 14.0, 0.8), (0.0, 0.0, 1.5)):
        o = statics.onset(body, friction, load, 0.2, g=G)
        assert o is not None and o.acceleration > 0.0
        w = wrench_ref(body, friction, o.twist, 0.2)
        acc = np.array(
            [
                (w[0] + load[0]) / MASS,
                (w[1] + load[1]) / MASS,
                (w[2] + load[2]) * k / body.moment_of_inertia,
            ]
        )
        assert acc == pytest.approx(o.acceleration * o.direction, abs=1e-7 * G)


def test_onset_along_the_blade_closed_form():
    body = blade_body()
    o = statics.onset(body, ss.FrictionTensor(0.3, 0.5), (10.0, 0.0, 0.0), g=G)
    assert o.direction == pytest.approx([1.0, 0.0, 0.0], abs=1e-12)
    assert o.acceleration == pytest.approx((10.0 - 0.3 * MASS * G) / MASS, rel=1e-12)


def test_limit_surface_of_an_anisotropic_blade():
    body = blade_body(angle=0.2)
    fr = TENSORS[1]
    ls = limit_surface(body, fr, n=40, g=G)
    for i in (0, 7, 19, 33):
        d = np.array([ls.vx[i], ls.vy[i], ls.omega[i]])
        assert ls.support[i] == pytest.approx(h_ref(body, fr, d), rel=1e-10)
        w = wrench_ref(body, fr, d)
        assert [ls.force_x[i], ls.force_y[i], ls.moment[i]] == pytest.approx(w, abs=1e-10)
    # the sliding wrenches lie in C: their power never exceeds the support function
    assert np.all(ls.dissipation_gap >= 0.0)
    power = -(ls.force_x * ls.vx + ls.force_y * ls.vy + ls.moment * ls.omega)
    assert np.all(power <= ls.support * (1.0 + 1e-12))


def test_loaded_blade_slides_along_its_axis_in_closed_form():
    """A blade at rest pulled along its axis by Q > fx m g accelerates uniformly; below the
    threshold it stays at rest (static friction, anisotropic tensor)."""
    body = blade_body()
    fr = ss.FrictionTensor(0.3, 0.5)
    q = 1.5 * 0.3 * MASS * G
    tr = ss.simulate(body, fr, ss.State(), g=G, load=ss.Load(force=(q, 0.0)), t_end=0.4)
    acc = (q - 0.3 * MASS * G) / MASS
    assert tr.x[-1] == pytest.approx(0.5 * acc * tr.t[-1] ** 2, rel=1e-8)
    assert np.max(np.abs(tr.y)) < 1e-12 and np.max(np.abs(tr.phi)) < 1e-12
    held = ss.simulate(
        body, fr, ss.State(), g=G, load=ss.Load(force=(0.0, 0.9 * 0.5 * MASS * G)), t_end=0.4
    )
    assert np.max(np.abs(held.x)) == 0.0 and np.max(np.abs(held.y)) == 0.0
