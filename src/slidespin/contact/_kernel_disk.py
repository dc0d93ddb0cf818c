"""Compiled disk and ring terms of the footprint kernel (MODEL §10).

The tensors G_k = ∫ x^{⊗k}/|x| dS of a disk about a point c at distance D of its centre, in
the frame (u, v) of u = (o − c)/D, from the chord moments I_n = ∫ sin^{2n}ψ h dψ (complete
elliptic integrals by the AGM, or a binomial series below m = ``SERIES_MAX_M``); a thin
ring's in double-double arithmetic; and, for the twist derivatives, their D-derivatives.
The method, its accuracy and its cost are in the notes of
:mod:`slidespin.contact._kernel_footprint` ("Disks", "Thin rings"), the derivatives in those
of :mod:`slidespin.contact._kernel_footprint_jac`. Plain arrays and floats only; imports
nothing of slidespin but the JIT decorator.
"""

from __future__ import annotations

import math

import numpy as np

from slidespin._jit import jit

#: below this parameter m the elliptic moments are summed as a series
SERIES_MAX_M = 0.45
SERIES_TERMS = 48


def _series_tables():
    """Coefficients of U_n(m) = Σ_j a_j w_{n+j} m^j and V_n(m) = Σ_j b_j (w_{n+j} − w_{n+j+1}) m^j,
    n = 0..3, with √(1 − x) = Σ a_j x^j, (1 − x)^(−1/2) = Σ b_j x^j, w_i = ∫₀^{π/2} sin^{2i}."""
    nt = SERIES_TERMS + 5
    a = np.empty(nt)
    b = np.empty(nt)
    a[0] = b[0] = 1.0
    for j in range(1, nt):
        a[j] = a[j - 1] * (j - 1.5) / j
        b[j] = b[j - 1] * (j - 0.5) / j
    w = 0.5 * math.pi * b  # ∫₀^{π/2} sin^{2i} = (π/2) C(2i, i)/4^i
    su = np.empty((4, SERIES_TERMS))
    sv = np.empty((4, SERIES_TERMS))
    for n in range(4):
        for j in range(SERIES_TERMS):
            su[n, j] = a[j] * w[n + j]
            sv[n, j] = b[j] * (w[n + j] - w[n + j + 1])
    return su, sv


SERIES_U, SERIES_V = _series_tables()


# ---------------------------------------------------------------------------------------------
# complete elliptic integrals and the disk moments


@jit(error_model="numpy")
def elliptic_ke(m):
    """Complete elliptic integrals K(m), E(m) of parameter m = k² in [0, 1) (AGM)."""
    a = 1.0
    b = math.sqrt(1.0 - m)
    s = 0.5 * m  # 2⁻¹ c₀², c₀ = √m
    pw = 0.5
    for _ in range(40):
        cn = 0.5 * (a - b)
        an = 0.5 * (a + b)
        b = math.sqrt(a * b)
        a = an
        pw *= 2.0
        s += pw * cn * cn
        if abs(cn) <= 1e-17 * a:
            break
    k = 0.5 * math.pi / a
    return k, k * (1.0 - s)


@jit(error_model="numpy", inline="always")
def t_recurrence(m):
    """T_n = ∫₀^{π/2} sin^{2n}ψ/√(1 − m sin²ψ) dψ = tk_n K(m) + te_n E(m), n = 0..4, by the
    recurrence of the module notes: (tk₀, te₀, …, tk₄, te₄) (m > 0)."""
    tk0, te0 = 1.0, 0.0
    tk1, te1 = 1.0 / m, -1.0 / m
    f = 1.0 / (3.0 * m)
    tk2 = (2.0 * (1.0 + m) * tk1 - tk0) * f
    te2 = (2.0 * (1.0 + m) * te1 - te0) * f
    f = 1.0 / (5.0 * m)
    tk3 = (4.0 * (1.0 + m) * tk2 - 3.0 * tk1) * f
    te3 = (4.0 * (1.0 + m) * te2 - 3.0 * te1) * f
    f = 1.0 / (7.0 * m)
    tk4 = (6.0 * (1.0 + m) * tk3 - 5.0 * tk2) * f
    te4 = (6.0 * (1.0 + m) * te3 - 5.0 * te2) * f
    return tk0, te0, tk1, te1, tk2, te2, tk3, te3, tk4, te4


@jit(error_model="numpy")
def disk_moments(m, outside):
    """(Q₀, Q₁, Q₂, Q₃): U_n(m) = ∫₀^{π/2} s^{2n}√(1 − m s²) dψ (``outside`` false) or
    V_n(m) = ∫₀^{π/2} s^{2n} c²/√(1 − m s²) dψ (``outside`` true), s = sin ψ, c = cos ψ,
    for m in [0, 1]."""
    if m >= 1.0:
        return 1.0, 1.0 / 3.0, 0.2, 1.0 / 7.0
    if m < SERIES_MAX_M:
        q0 = 0.0
        q1 = 0.0
        q2 = 0.0
        q3 = 0.0
        for j in range(SERIES_TERMS - 1, -1, -1):
            if outside:
                q0 = q0 * m + SERIES_V[0, j]
                q1 = q1 * m + SERIES_V[1, j]
                q2 = q2 * m + SERIES_V[2, j]
                q3 = q3 * m + SERIES_V[3, j]
            else:
                q0 = q0 * m + SERIES_U[0, j]
                q1 = q1 * m + SERIES_U[1, j]
                q2 = q2 * m + SERIES_U[2, j]
                q3 = q3 * m + SERIES_U[3, j]
        return q0, q1, q2, q3
    kk, ee = elliptic_ke(m)
    tk0, te0, tk1, te1, tk2, te2, tk3, te3, tk4, te4 = t_recurrence(m)
    g = 1.0 if outside else m
    q0 = (tk0 - g * tk1) * kk + (te0 - g * te1) * ee
    q1 = (tk1 - g * tk2) * kk + (te1 - g * te2) * ee
    q2 = (tk2 - g * tk3) * kk + (te2 - g * te3) * ee
    q3 = (tk3 - g * tk4) * kk + (te3 - g * te4) * ee
    return q0, q1, q2, q3


# ---------------------------------------------------------------------------------------------
# thin rings in double-double arithmetic (module notes)

#: relative width (R − r)/R below which a ring's disk and hole are subtracted in
#: double-double arithmetic (above it the plain difference is within 1e-13 of the reference)
THIN_RING = 1e-2
_SPLIT = 134217729.0  # 2²⁷ + 1 (Dekker's split)
_PI_2 = (1.5707963267948966, 6.123233995736766e-17)  # π/2 as a double-double


@jit(error_model="numpy", inline="always")
def _qsum(a, b):
    s = a + b
    return s, b - (s - a)


@jit(error_model="numpy", inline="always")
def _tsum(a, b):
    s = a + b
    t = s - a
    return s, (a - (s - t)) + (b - t)


@jit(error_model="numpy", inline="always")
def _tprod(a, b):
    p = a * b
    t = _SPLIT * a
    ah = t - (t - a)
    t = _SPLIT * b
    bh = t - (t - b)
    return p, ((ah * bh - p) + ah * (b - bh) + (a - ah) * bh) + (a - ah) * (b - bh)


@jit(error_model="numpy", inline="always")
def _dadd(a, b):
    s, e = _tsum(a[0], b[0])
    t, f = _tsum(a[1], b[1])
    s, e = _qsum(s, e + t)
    return _qsum(s, e + f)


@jit(error_model="numpy", inline="always")
def _dsub(a, b):
    return _dadd(a, (-b[0], -b[1]))


@jit(error_model="numpy", inline="always")
def _dmul(a, b):
    p, e = _tprod(a[0], b[0])
    return _qsum(p, e + (a[0] * b[1] + a[1] * b[0]))


@jit(error_model="numpy", inline="always")
def _dscale(a, x):
    """a × the float x."""
    p, e = _tprod(a[0], x)
    return _qsum(p, e + a[1] * x)


@jit(error_model="numpy", inline="always")
def _ddiv(a, b):
    q1 = a[0] / b[0]
    r = _dsub(a, _dscale(b, q1))
    q2 = r[0] / b[0]
    r = _dsub(r, _dscale(b, q2))
    return _dadd(_qsum(q1, q2), (r[0] / b[0], 0.0))


@jit(error_model="numpy", inline="always")
def _dsqrt(a):
    if a[0] <= 0.0:
        return 0.0, 0.0
    x = math.sqrt(a[0])
    r = _dsub(a, _tprod(x, x))
    return _qsum(x, r[0] / (2.0 * x))


@jit(error_model="numpy")
def _dd_ke(m):
    """K(m), E(m) in double-double for m = (hi, lo) in [0, 1) (the AGM of :func:`elliptic_ke`)."""
    one = (1.0, 0.0)
    a = one
    b = _dsqrt(_dsub(one, m))
    s = _dscale(m, 0.5)
    pw = 0.5
    for _ in range(60):
        cn = _dscale(_dsub(a, b), 0.5)
        an = _dscale(_dadd(a, b), 0.5)
        b = _dsqrt(_dmul(a, b))
        a = an
        pw *= 2.0
        s = _dadd(s, _dscale(_dmul(cn, cn), pw))
        if abs(cn[0]) <= 1e-33 * a[0]:
            break
    k = _ddiv(_PI_2, a)
    return k, _dmul(k, _dsub(one, s))


@jit(error_model="numpy", inline="always")
def _dd_step(n, opm, t1, t0, m):
    """T_{n+1} = (2n (1 + m) T_n − (2n − 1) T_{n−1}) / ((2n + 1) m), one coefficient."""
    num = _dsub(_dscale(_dmul(opm, t1), 2.0 * n), _dscale(t0, 2.0 * n - 1.0))
    return _ddiv(num, _dscale(m, 2.0 * n + 1.0))


@jit(error_model="numpy", inline="always")
def _dd_q(g, kk, ee, ta, tb, ea, eb):
    """(T_a − g T_b) in its K and E parts, times K and E (the last step of the moments)."""
    return _dadd(_dmul(_dsub(ta, _dmul(g, tb)), kk), _dmul(_dsub(ea, _dmul(g, eb)), ee))


@jit(error_model="numpy")
def _dd_disk_moments(m, outside):
    """:func:`disk_moments` in double-double: (Q₀, Q₁, Q₂, Q₃) as four (hi, lo) pairs."""
    one = (1.0, 0.0)
    if m[0] > 1.0 or (m[0] == 1.0 and m[1] >= 0.0):  # the ICR on the rim: 1, 1/3, 1/5, 1/7
        return one, _ddiv(one, (3.0, 0.0)), _ddiv(one, (5.0, 0.0)), _ddiv(one, (7.0, 0.0))
    if m[0] < SERIES_MAX_M:
        q0 = q1 = q2 = q3 = (0.0, 0.0)
        tab = SERIES_V if outside else SERIES_U
        for j in range(SERIES_TERMS - 1, -1, -1):  # Horner (the truncation is smooth in m)
            q0, q1 = _dadd(_dmul(q0, m), (tab[0, j], 0.0)), _dadd(_dmul(q1, m), (tab[1, j], 0.0))
            q2, q3 = _dadd(_dmul(q2, m), (tab[2, j], 0.0)), _dadd(_dmul(q3, m), (tab[3, j], 0.0))
        return q0, q1, q2, q3
    kk, ee = _dd_ke(m)
    opm = _dadd(one, m)
    inv = _ddiv(one, m)
    tk0, te0 = one, (0.0, 0.0)
    tk1, te1 = inv, (-inv[0], -inv[1])
    tk2, te2 = _dd_step(1, opm, tk1, tk0, m), _dd_step(1, opm, te1, te0, m)
    tk3, te3 = _dd_step(2, opm, tk2, tk1, m), _dd_step(2, opm, te2, te1, m)
    tk4, te4 = _dd_step(3, opm, tk3, tk2, m), _dd_step(3, opm, te3, te2, m)
    g = one if outside else m
    return (
        _dd_q(g, kk, ee, tk0, tk1, te0, te1),
        _dd_q(g, kk, ee, tk1, tk2, te1, te2),
        _dd_q(g, kk, ee, tk2, tk3, te2, te3),
        _dd_q(g, kk, ee, tk3, tk4, te3, te4),
    )


@jit(error_model="numpy")
def _dd_chords(dd, rr):
    """I_n = ∫ sin^{2n}ψ h dψ, n = 0..3, of the disk of radius ``rr`` seen from distance ``dd``
    of its centre (module notes), as four double-double pairs."""
    d2 = _tprod(dd, dd)
    r2 = _tprod(rr, rr)
    if dd <= rr:
        q0, q1, q2, q3 = _dd_disk_moments(_ddiv(d2, r2), False)
        f = (2.0 * rr, 0.0)
        k2 = (1.0, 0.0)
    else:
        k2 = _ddiv(r2, d2)
        q0, q1, q2, q3 = _dd_disk_moments(k2, True)
        f = _dscale(_ddiv((rr, 0.0), (dd, 0.0)), 2.0 * rr)
    k4 = _dmul(k2, k2)
    q1, q2, q3 = _dmul(q1, k2), _dmul(q2, k4), _dmul(q3, _dmul(k4, k2))
    return _dmul(f, q0), _dmul(f, q1), _dmul(f, q2), _dmul(f, q3)


@jit(error_model="numpy")
def ring_terms(dd, big, small):
    """:func:`round_terms` of the ring ``small`` ≤ ρ ≤ ``big`` (a disk minus a disk), seen from
    distance ``dd`` of its centre, without the cancellation of the two (section notes)."""
    a0, a1, a2, a3 = _dd_chords(dd, big)
    b0, b1, b2, b3 = _dd_chords(dd, small)
    d0, d1, d2, d3 = _dsub(a0, b0), _dsub(a1, b1), _dsub(a2, b2), _dsub(a3, b3)
    w = (big - small) * (big + small)  # R² − r², exact to rounding
    return assemble(dd, big * big, d0[0], d1[0], d2[0], d3[0], w, b0[0], b1[0], b2[0])


@jit(error_model="numpy", inline="always")
def assemble(dd, r2, i0, i1, i2, i3, w, h0, h1, h2):
    """(G₁ᵤ, G₂ᵤᵤ, G₂ᵥᵥ, G₃ᵤᵤᵤ, G₃ᵤᵥᵥ) of a disk of radius √r2 (w = 0) about a point at distance
    ``dd`` of its centre (u towards the centre, v across) from its chord moments I_n = ``i``;
    of a ring, from the differences ΔI_n = ``i`` of its disk and hole, the hole's own I_n =
    ``h`` and w = R² − r² (ρ² X of the ring is R² ΔX + w X_hole)."""
    d2 = dd * dd
    c2 = i0 - i1  # ∫ cos²ψ h
    c4 = c2 - (i1 - i2)
    c2s2 = i1 - i2
    c4s2 = c2s2 - (i2 - i3)
    r2c2 = r2 * c2 + w * (h0 - h1)
    r2c4 = r2 * c4 + w * (h0 - 2.0 * h1 + h2)
    r2c2s2 = r2 * c2s2 + w * (h1 - h2)
    return (
        2.0 * dd * c2,
        2.0 * d2 * c4 + (2.0 / 3.0) * (r2c2 - d2 * c2s2),
        2.0 * d2 * c2s2 + (2.0 / 3.0) * (r2 * i1 + w * h1 - d2 * i2),
        2.0 * d2 * dd * (c4 - c4s2) + 2.0 * dd * (r2c4 - d2 * c4s2),
        2.0 * d2 * dd * c4s2 + 2.0 * dd * (r2c2s2 - d2 * (i2 - i3)),
    )


@jit(error_model="numpy")
def round_terms(dd, rr):
    """(G₁ᵤ, G₂ᵤᵤ, G₂ᵥᵥ, G₃ᵤᵤᵤ, G₃ᵤᵥᵥ) of the disk of radius ``rr`` about a point at distance
    ``dd`` of its centre, u the unit vector towards the centre, v = ẑ × u (module notes)."""
    if dd <= rr:
        q0, q1, q2, q3 = disk_moments((dd / rr) ** 2, False)
        f = 2.0 * rr
    else:
        k = rr / dd
        q0, q1, q2, q3 = disk_moments(k * k, True)
        k2 = k * k
        f = 2.0 * rr * k
        q1 *= k2
        q2 *= k2 * k2
        q3 *= k2 * k2 * k2
    return assemble(dd, rr * rr, f * q0, f * q1, f * q2, f * q3, 0.0, 0.0, 0.0, 0.0)


@jit(error_model="numpy", inline="always")
def thin_hole(circles, i):
    """True if circle i is a disk whose hole, row i + 1 (same centre, sign −1), leaves a ring
    thinner than THIN_RING (relative width)."""
    return (
        circles[i, 3] > 0.0
        and i + 1 < circles.shape[0]
        and circles[i + 1, 3] < 0.0
        and circles[i + 1, 0] == circles[i, 0]
        and circles[i + 1, 1] == circles[i, 1]
        and circles[i, 2] - circles[i + 1, 2] < THIN_RING * circles[i, 2]
    )


# ---------------------------------------------------------------------------------------------
# the disk's tensors with their derivatives in D (:mod:`slidespin.contact._kernel_footprint_jac`)


#: (2U₁ − U₀)/m as a series: coefficient j of U_n is SERIES_U[n, j], and 2U₁ − U₀ has none at j = 0
_DELTA = 2.0 * SERIES_U[1, 1:] - SERIES_U[0, 1:]


@jit(error_model="numpy")
def disk_moments_both(m):
    """U₀..U₃ and V₀..V₃ of :func:`slidespin.contact._kernel_footprint.disk_moments` at one
    m in [0, 1] (one AGM for both), and (2U₁ − U₀)/m without its cancellation at small m."""
    if m >= 1.0:
        return 1.0, 1.0 / 3.0, 0.2, 1.0 / 7.0, 1.0, 1.0 / 3.0, 0.2, 1.0 / 7.0, -1.0 / 3.0
    if m < SERIES_MAX_M:
        u0 = u1 = u2 = u3 = v0 = v1 = v2 = v3 = dl = 0.0
        for j in range(SERIES_TERMS - 1, -1, -1):
            u0 = u0 * m + SERIES_U[0, j]
            u1 = u1 * m + SERIES_U[1, j]
            u2 = u2 * m + SERIES_U[2, j]
            u3 = u3 * m + SERIES_U[3, j]
            v0 = v0 * m + SERIES_V[0, j]
            v1 = v1 * m + SERIES_V[1, j]
            v2 = v2 * m + SERIES_V[2, j]
            v3 = v3 * m + SERIES_V[3, j]
            if j < SERIES_TERMS - 1:
                dl = dl * m + _DELTA[j]
        return u0, u1, u2, u3, v0, v1, v2, v3, dl
    kk, ee = elliptic_ke(m)
    tk0, te0, tk1, te1, tk2, te2, tk3, te3, tk4, te4 = t_recurrence(m)
    u0 = (tk0 - m * tk1) * kk + (te0 - m * te1) * ee
    u1 = (tk1 - m * tk2) * kk + (te1 - m * te2) * ee
    u2 = (tk2 - m * tk3) * kk + (te2 - m * te3) * ee
    u3 = (tk3 - m * tk4) * kk + (te3 - m * te4) * ee
    v0 = (tk0 - tk1) * kk + (te0 - te1) * ee
    v1 = (tk1 - tk2) * kk + (te1 - te2) * ee
    v2 = (tk2 - tk3) * kk + (te2 - te3) * ee
    v3 = (tk3 - tk4) * kk + (te3 - te4) * ee
    return u0, u1, u2, u3, v0, v1, v2, v3, (2.0 * u1 - u0) / m


@jit(error_model="numpy")
def round_terms_jac(dd, rr):
    """:func:`slidespin.contact._kernel_footprint.round_terms` g = (G₁ᵤ, G₂ᵤᵤ, G₂ᵥᵥ, G₃ᵤᵤᵤ,
    G₃ᵤᵥᵥ) of the disk of radius ``rr`` at distance D = ``dd``, their D-derivatives g', and
    the coefficients of the frame's turn (t₁, t₂, t₃ₐ, t₃ᵦ) = (G₁ᵤ, G₂ᵥᵥ − G₂ᵤᵤ, 2G₃ᵤᵥᵥ −
    G₃ᵤᵤᵤ, −3G₃ᵤᵥᵥ)/D (module notes): 14 floats, finite at D = 0 and on the rim."""
    big = rr
    d2 = dd * dd
    r2 = big * big
    if dd <= big:
        u0, u1, u2, u3, v0, v1, v2, v3, dl = disk_moments_both(d2 / r2)
        i0, i1, i2, i3 = 2.0 * big * u0, 2.0 * big * u1, 2.0 * big * u2, 2.0 * big * u3
        f = -2.0 * dd / big
        c2p, c2s2p, e23p = f * v1, f * v2, f * v3
        yp = -6.0 * dd * big * u2
        hole = 2.0 * dl * dd / big  # (2I₁ − I₀)/D = 2R (2U₁ − U₀)/D
    else:
        k = big / dd
        m = k * k
        u0, u1, u2, u3, v0, v1, v2, v3, dl = disk_moments_both(m)
        f = 2.0 * big * k
        i0, i1, i2, i3 = f * v0, f * m * v1, f * m * m * v2, f * m * m * m * v3
        c2p, c2s2p, e23p = -2.0 * m * u1, -2.0 * m * m * u2, -2.0 * m * m * m * u3
        yp = -2.0 * r2 * m * m * v2 - 2.0 * dd * i2
        hole = (2.0 * i1 - i0) / dd
    c2 = i0 - i1
    c2s2 = i1 - i2
    e23 = i2 - i3
    c4 = c2 - c2s2
    c4s2 = c2s2 - e23
    c4p = c2p - c2s2p
    c4s2p = c2s2p - e23p
    g3a = 2.0 * d2 * (c4 - c4s2) + 2.0 * (r2 * c4 - d2 * c4s2)  # G₃ᵤᵤᵤ/D
    g3b = 2.0 * d2 * c4s2 + 2.0 * (r2 * c2s2 - d2 * e23)  # G₃ᵤᵥᵥ/D
    g3ap = 4.0 * dd * (c4 - c4s2) + 2.0 * d2 * (c4p - c4s2p)
    g3ap += 2.0 * (r2 * c4p - 2.0 * dd * c4s2 - d2 * c4s2p)
    g3bp = 4.0 * dd * c4s2 + 2.0 * d2 * c4s2p + 2.0 * (r2 * c2s2p - 2.0 * dd * e23 - d2 * e23p)
    return (
        2.0 * dd * c2,
        2.0 * d2 * c4 + (2.0 / 3.0) * (r2 * c2 - d2 * c2s2),
        2.0 * d2 * c2s2 + (2.0 / 3.0) * (r2 * i1 - d2 * i2),
        dd * g3a,
        dd * g3b,
        2.0 * c2 + 2.0 * dd * c2p,
        4.0 * dd * c4 + 2.0 * d2 * c4p + (2.0 / 3.0) * (r2 * c2p - 2.0 * dd * c2s2 - d2 * c2s2p),
        4.0 * dd * c2s2 + 2.0 * d2 * c2s2p + (2.0 / 3.0) * yp,
        g3a + dd * g3ap,
        g3b + dd * g3bp,
        2.0 * c2,
        2.0 * dd * (c2s2 - c4) + (2.0 / 3.0) * (r2 * hole - dd * (2.0 * i2 - i1)),
        2.0 * g3b - g3a,
        -3.0 * g3b,
    )
