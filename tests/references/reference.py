"""Slow, independent, high-accuracy quadrature reference for the friction wrench.

This module is a *test oracle*: it shares no code with ``slidespin`` and uses no closed-form
radial antiderivatives.  Every integral is done numerically by nested adaptive quadrature
(``scipy.integrate.quad`` inside, ``scipy.integrate.quad_vec`` outside).

Model (docs: MODEL.md sections 1-3)
-----------------------------------
Elliptic patch ``q = xi^2/a^2 + eta^2/b^2 <= 1`` centred at the body origin C.  A body point r has
world offset ``r' = R(phi) (r - r_G)`` from the mass centre G and velocity
``w = (vx - omega y', vy + omega x')``; its traction is ``tau = -p T w/|w|``.  The wrench is
``F = int tau dS`` and ``M = int (x' tau_y - y' tau_x) dS`` (about G, counter-clockwise positive).

Method
------
*Line coordinates through the instantaneous centre of rotation (ICR).*  With ``omega != 0`` every
point is ``r = r_I + rho e(psi)`` (body frame, ``e = (cos, sin)``) and
``w = omega rho u(psi + phi)`` with ``u(t) = (-sin t, cos t)``: the slip direction depends on the
line direction psi only.  Letting rho run over the whole real line (signed) and psi over a half
turn, the factor ``sign(rho)`` of the direction cancels against ``|rho|`` of the area element, so

    F = -sgn(omega) int T u I1(psi) dpsi,
    M = -sgn(omega) int [ (e x T u) I2(psi) + (d' x T u) I1(psi) ] dpsi,     d' = r'_I,
    I_k(psi) = int_chord p(rho) rho^k drho,

where the chord ``[r1, r2]`` is the intersection of the line with the ellipse.  The integrand of
``I_k`` is a polynomial times the pressure; the pressure of the Boussinesq / Hertz laws is
written ``c * (A (rho - r1)(r2 - rho))^(-+1/2)`` and its end behaviour is handed to QUADPACK's
algebraic weight (``weight='alg'``), so the radial integrals are accurate to rounding.

* ICR strictly/just inside or on the rim: psi over ``[psi0, psi0 + pi]`` where psi0 is the
  direction along which the chord through the ICR is bisected by it in the scaled metric (the
  only place where the outer integrand can vary abruptly, near the rim).
* ICR outside: psi over the sector of lines meeting the ellipse (tangent directions computed
  geometrically), with ``psi = mid + half*sin(s)`` to smooth the square-root ends.
* ICR far away (``|r_I| > FAR * max(a, b)``) or ``omega == 0``: the line form would cancel terms
  of size ``|ICR|``, so a direct 2D quadrature in elliptic-polar coordinates
  ``xi = a sin(s) cos t, eta = b sin(s) sin t`` is used instead; ``r = sin s`` absorbs the
  square-root behaviour of the Boussinesq / Hertz weights, and ``w`` is computed directly.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
from scipy.integrate import quad, quad_vec

__all__ = ["reference_wrench", "reference_dissipation", "LAWS"]

LAWS = ("uniform", "linear", "boussinesq", "hertz")

#: ICR distance from C (in units of max(a, b)) beyond which the direct 2D quadrature is used.
FAR = 4.0

_INNER_EPSABS = 1e-16
_INNER_EPSREL = 1e-13
_LIMIT = 400


def _q(f, lo, hi, **kw):
    """scipy.integrate.quad with tight tolerances; QUADPACK's roundoff flags (expected for the
    polynomial radial integrands, which are integrated exactly) are not turned into warnings,
    but a large error estimate is."""
    res = quad(
        f, lo, hi, epsabs=_INNER_EPSABS, epsrel=_INNER_EPSREL, limit=_LIMIT, full_output=1, **kw
    )
    val, err = res[0], res[1]
    # crude size of int |f w|: sampled max of |f| times the interval length (times its power
    # 2 alpha for the algebraic weight)
    h = hi - lo
    fmax = max(abs(f(lo + k * h / 4.0)) for k in range(5))
    scale = fmax * h
    if kw.get("weight") == "alg":
        scale *= math.pi * h ** (2.0 * kw["wvar"][0])
    # QUADPACK's estimates are pessimistic here (about 3e-14 relative for the exact
    # Clenshaw-Curtis moments of QAWS); only a gross failure is reported
    if not err <= 1e-12 * scale + 1e-300:
        warnings.warn(f"reference: radial quadrature error estimate {err:.2e}", stacklevel=2)
    return val


def _check(info, err, epsabs, what):
    if info.status != 0 and not err <= 10.0 * epsabs:
        warnings.warn(
            f"reference: {what} quadrature status {info.status}, err {err:.2e}", stacklevel=3
        )


class _State:
    """Validated inputs plus derived geometry."""

    def __init__(self, a, b, law, tensor_world, phi, vx, vy, omega, xi_c, eta_c, P):
        if law not in LAWS:
            raise ValueError(f"unknown pressure law {law!r}; expected one of {LAWS}")
        self.a = float(a)
        self.b = float(b)
        if not (self.a > 0 and self.b > 0):
            raise ValueError("semi-axes must be positive")
        self.law = law
        T = np.asarray(tensor_world, dtype=float)
        if T.shape != (2, 2):
            raise ValueError("tensor_world must be a 2x2 array")
        self.T = T
        self.t11, self.t12 = float(T[0, 0]), float(T[0, 1])
        self.t21, self.t22 = float(T[1, 0]), float(T[1, 1])
        self.phi = float(phi)
        self.cphi, self.sphi = math.cos(self.phi), math.sin(self.phi)
        self.vx, self.vy, self.omega = float(vx), float(vy), float(omega)
        self.P = float(P)
        if law == "linear":
            self.xi_g, self.eta_g = float(xi_c), float(eta_c)
        else:
            self.xi_g, self.eta_g = 0.0, 0.0
        self.xi_c, self.eta_c = self.xi_g, self.eta_g  # pressure centroid (linear law only)

    # body -> world offset from G
    def world_offset(self, xi, eta):
        dx, dy = xi - self.xi_g, eta - self.eta_g
        return self.cphi * dx - self.sphi * dy, self.sphi * dx + self.cphi * dy

    def Tmul(self, x, y):
        return self.t11 * x + self.t12 * y, self.t21 * x + self.t22 * y


# --------------------------------------------------------------------------------------------
# direct 2D quadrature (omega == 0 or far ICR)
# --------------------------------------------------------------------------------------------
def _direct(st: _State, epsabs: float) -> np.ndarray:
    """(Fx, Fy, M, D) by nested adaptive quadrature in elliptic-polar coordinates.

    xi = a sin(s) cos(t), eta = b sin(s) sin(t), s in [0, pi/2], t in [0, 2 pi];
    dS = a b sin(s) cos(s) ds dt.
    """
    a, b, P, law = st.a, st.b, st.P, st.law
    vx, vy, om = st.vx, st.vy, st.omega
    if law in ("uniform", "linear"):
        c0 = P / math.pi  # p dS = P/(pi a b) * a b sin cos

        def weight(ss, cs):
            return c0 * ss * cs
    elif law == "boussinesq":
        c0 = P / (2.0 * math.pi)  # P/(2 pi a b) / cos(s) * a b sin cos

        def weight(ss, cs):
            return c0 * ss
    else:  # hertz
        c0 = 3.0 * P / (2.0 * math.pi)  # 3P/(2 pi a b) cos(s) * a b sin cos

        def weight(ss, cs):
            return c0 * ss * cs * cs

    lin = law == "linear"
    vs = math.hypot(vx, vy, om * max(a, b))
    kx = 4.0 * st.xi_c / (a * a)
    ky = 4.0 * st.eta_c / (b * b)

    def inner(s, ct, st_):
        ss, cs = math.sin(s), math.cos(s)
        xi, eta = a * ss * ct, b * ss * st_
        pw = weight(ss, cs)
        if lin:
            pw *= 1.0 + kx * xi + ky * eta
        xw, yw = st.world_offset(xi, eta)
        wx, wy = vx - om * yw, vy + om * xw
        n = math.hypot(wx, wy)
        ux, uy = wx / n, wy / n
        tx, ty = st.Tmul(ux, uy)
        tx, ty = -pw * tx, -pw * ty
        # the power density is divided by the velocity scale vs (restored below) so that all
        # four components are O(P) and share one absolute tolerance
        return np.array([tx, ty, xw * ty - yw * tx, (ux * tx + uy * ty) * (n / vs)])

    def outer(t):
        ct, st_ = math.cos(t), math.sin(t)
        res, err, info = quad_vec(
            inner,
            0.0,
            0.5 * math.pi,
            epsabs=epsabs * 0.1,
            epsrel=_INNER_EPSREL,
            norm="max",
            limit=_LIMIT,
            full_output=True,
            args=(ct, st_),
        )
        _check(info, err, epsabs * 0.1, "inner direct")
        return res

    res, err, info = quad_vec(
        outer,
        0.0,
        2.0 * math.pi,
        epsabs=epsabs,
        epsrel=_INNER_EPSREL,
        norm="max",
        limit=_LIMIT,
        full_output=True,
        points=(0.5 * math.pi, math.pi, 1.5 * math.pi),
    )
    _check(info, err, epsabs, "outer direct")
    res[3] *= vs
    return res


# --------------------------------------------------------------------------------------------
# line coordinates through the ICR
# --------------------------------------------------------------------------------------------
def _chord(st: _State, xI, yI, C1, c, s):
    """Signed chord [r1, r2] of the line r_I + rho (c, s) inside the ellipse, and A."""
    a2, b2 = st.a * st.a, st.b * st.b
    A = c * c / a2 + s * s / b2
    B = 2.0 * (xI * c / a2 + yI * s / b2)
    disc = B * B - 4.0 * A * C1
    if disc < 0.0:
        disc = 0.0
    sq = math.sqrt(disc)
    qq = -0.5 * (B + sq) if B >= 0.0 else -0.5 * (B - sq)
    if qq == 0.0:
        return 0.0, 0.0, A
    x1, x2 = qq / A, C1 / qq
    return (x1, x2, A) if x1 <= x2 else (x2, x1, A)


def _radial(st: _State, xI, yI, C1, c, s):
    """I1 = int p rho drho, I2 = int p rho^2 drho over the signed chord (numerically)."""
    r1, r2, A = _chord(st, xI, yI, C1, c, s)
    if not r2 > r1:
        return 0.0, 0.0
    a, b, P, law = st.a, st.b, st.P, st.law
    if law == "uniform":
        p0 = P / (math.pi * a * b)
        i1 = _q(lambda r: r, r1, r2)
        i2 = _q(lambda r: r * r, r1, r2)
        return p0 * i1, p0 * i2
    if law == "linear":
        p0 = P / (math.pi * a * b)
        kx = 4.0 * st.xi_c / (a * a)
        ky = 4.0 * st.eta_c / (b * b)

        def p(r):
            return p0 * (1.0 + kx * (xI + r * c) + ky * (yI + r * s))

        i1 = _q(lambda r: p(r) * r, r1, r2)
        i2 = _q(lambda r: p(r) * r * r, r1, r2)
        return i1, i2
    # 1 - q(rho) = A (rho - r1) (r2 - rho)
    if law == "boussinesq":
        k = P / (2.0 * math.pi * a * b) / math.sqrt(A)
        wv = (-0.5, -0.5)
    else:  # hertz
        k = 3.0 * P / (2.0 * math.pi * a * b) * math.sqrt(A)
        wv = (0.5, 0.5)
    i1 = _q(lambda r: r, r1, r2, weight="alg", wvar=wv)
    i2 = _q(lambda r: r * r, r1, r2, weight="alg", wvar=wv)
    return k * i1, k * i2


def _polar(st: _State, epsabs: float) -> np.ndarray:
    """(Fx, Fy, M, D) by line coordinates through the ICR (requires omega != 0)."""
    om = st.omega
    a, b, phi = st.a, st.b, st.phi
    # ICR: world offset from G, then body coordinates
    dxw, dyw = -st.vy / om, st.vx / om
    xI = st.xi_g + st.cphi * dxw + st.sphi * dyw
    yI = st.eta_g - st.sphi * dxw + st.cphi * dyw
    X, Y = xI / a, yI / b
    C0 = X * X + Y * Y
    C1 = C0 - 1.0
    sg = 1.0 if om > 0 else -1.0

    def integrand(psi):
        c, s = math.cos(psi), math.sin(psi)
        i1, i2 = _radial(st, xI, yI, C1, c, s)
        th = psi + phi
        ux, uy = -math.sin(th), math.cos(th)
        ex, ey = uy, -ux  # e(th) = (cos th, sin th)
        tux, tuy = st.Tmul(ux, uy)
        fx, fy = -sg * tux * i1, -sg * tuy * i1
        m = -sg * ((ex * tuy - ey * tux) * i2 + (dxw * tuy - dyw * tux) * i1)
        d = -(ux * tux + uy * tuy) * i2  # times |omega| below
        return np.array([fx, fy, m, d])

    kw = dict(epsabs=epsabs, epsrel=_INNER_EPSREL, norm="max", limit=_LIMIT, full_output=True)
    if C1 <= 0.0:
        # inside or on the rim: a half turn of lines, starting where B(psi) = 0
        psi0 = math.atan2(X / a, -Y / b) if C0 > 0.0 else 0.0
        res, err, info = quad_vec(integrand, psi0, psi0 + math.pi, **kw)
    else:
        # outside: the sector between the two tangents (scaled metric: unit circle)
        # In scaled coordinates (X, Y) = (xi/a, eta/b) the patch is the unit disc; from the
        # point P = |P| n (n = unit radial, t = unit tangential) the tangent points are
        # T = (n +/- sqrt(C1) t)/|P| and T - P = (-C1 n +/- sqrt(C1) t)/|P|, i.e. the tangent
        # directions are proportional to -sqrt(C1) n +/- t (no cancellation as C1 -> 0; the
        # textbook acos(1/|P|) form collapses the sector to zero width when C1 ~ 1e-16).
        rad = math.sqrt(C0)
        nx, ny = X / rad, Y / rad
        sq1 = math.sqrt(C1)
        psic = math.atan2(-yI, -xI)
        dev = []
        for sgn_t in (1.0, -1.0):
            dX = -sq1 * nx - sgn_t * ny
            dY = -sq1 * ny + sgn_t * nx
            d = math.atan2(b * dY, a * dX) - psic
            d = (d + math.pi) % (2.0 * math.pi) - math.pi
            dev.append(d)
        lo, hi = min(dev), max(dev)
        mid, half = psic + 0.5 * (lo + hi), 0.5 * (hi - lo)

        def sub(t):
            return integrand(mid + half * math.sin(t)) * (half * math.cos(t))

        res, err, info = quad_vec(sub, -0.5 * math.pi, 0.5 * math.pi, **kw)
    _check(info, err, epsabs, "polar")
    res[3] *= abs(om)
    return res


def _compute(a, b, law, tensor_world, phi, vx, vy, omega, xi_c, eta_c, P, epsabs, method=None):
    st = _State(a, b, law, tensor_world, phi, vx, vy, omega, xi_c, eta_c, P)
    if st.vx == 0.0 and st.vy == 0.0 and st.omega == 0.0:
        return np.zeros(4)
    if method is None:
        if st.omega == 0.0:
            method = "direct"
        else:
            dxw, dyw = -st.vy / st.omega, st.vx / st.omega
            xI = st.xi_g + st.cphi * dxw + st.sphi * dyw
            yI = st.eta_g - st.sphi * dxw + st.cphi * dyw
            method = "direct" if math.hypot(xI, yI) > FAR * max(st.a, st.b) else "polar"
    if method == "direct":
        return _direct(st, epsabs)
    if method == "polar":
        if st.omega == 0.0:
            raise ValueError("polar method needs omega != 0")
        return _polar(st, epsabs)
    raise ValueError(method)


def reference_wrench(
    a, b, law, tensor_world, phi, vx, vy, omega, xi_c=0.0, eta_c=0.0, P=1.0, epsabs=1e-13
):
    """Return (Fx, Fy, M): total friction force (world frame) and moment about the mass centre G
    (counter-clockwise positive)."""
    r = _compute(a, b, law, tensor_world, phi, vx, vy, omega, xi_c, eta_c, P, epsabs)
    return float(r[0]), float(r[1]), float(r[2])


def reference_dissipation(
    a, b, law, tensor_world, phi, vx, vy, omega, xi_c=0.0, eta_c=0.0, P=1.0, epsabs=1e-13
):
    """Return -int p (w . T . w)/|w| dS, the rate of work of friction, computed as its own
    integrand (not from the wrench)."""
    r = _compute(a, b, law, tensor_world, phi, vx, vy, omega, xi_c, eta_c, P, epsabs)
    return float(r[3])
