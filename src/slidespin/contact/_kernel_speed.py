"""The compiled wrench under a speed-dependent friction law (MODEL §14), for every patch.

The traction is τ = −p g(|w|) 𝔽 ŵ (:mod:`slidespin.contact.speed_laws`). In polar coordinates
(ρ, ψ) about the instantaneous centre of rotation c, the slip direction on a ray c + ρ ê is
constant (ŵ = sign(ω) ẑ × ê) and the slip speed is |ω| ρ, so

    F = Σ −𝔽 ŵ(ψ) ∫ dψ K₁(ψ),   M = ∫ dψ [K_x(ψ) τ_y − K_y(ψ) τ_x],
    K₁ = ∫ p g(|ω|ρ) ρ dρ,   (K_x, K_y) = ∫ p g(|ω|ρ) ρ (r − r_G) dρ,

the chord integrals of the constant law with the factor inside (MODEL §10, §14). The patch is
data: straight edges (polygons, rectangles), and axis-parallel ellipses with a sign (an
ellipse or circle patch, disks, and the holes of rings), which each ray cuts in exact
intervals (edge crossings, the roots of a quadratic); the pressure is linear (p₀ + p₁ξ + p₂η:
uniform and linear laws) or the Boussinesq or Hertz law of an ellipse.

Rules. The angle is split where the integrand's form changes (vertex directions; tangents from
c to each ellipse; the directions to its centre and ±90° from it; graded breaks beside the
vertices of an edge that passes near c, as for user maps, :mod:`slidespin.contact._map_wrench`).
Each panel gets ``N_OUT`` Gauss–Legendre nodes in u with ψ = ψa + (ψb − ψa)(1 − cos πu)/2 and
is bisected until its halves agree with it to ``tol`` × width/2π (absolute, in units of the
load and load × extent; or to 1e-14 of the panel's own size, the floor round-off leaves), at
most ``_MAX_SPLITS`` times per wrench (the panels left then count
as missed, and the caller reports it). Each ray interval is split at the radii |ω|⁻¹ × the law's break
speeds (a table's knots; vs × 2^k for Stribeck), and each piece gets ``N_IN`` graded
Gauss–Legendre nodes (t = (1 − cos πs)/2: the √d and 1/√d rims of Hertz and Boussinesq become
smooth). A ray that starts at c (the centre inside the patch) under a law singular at zero
speed (a power law, a Stribeck law with non-integer δ) is split geometrically towards c,
[ρ₁ 2^(−k−1), ρ₁ 2^(−k)] for k < ``N_GEOM``, with the last piece [0, ε] in closed form (the
leading term p(c) ∫ g(|ω|ρ) ρ^(1,2) dρ, relative error ~ε/ρ₁); a ray that starts a short
distance ρ₀ after c (c just outside the patch) is split the same way towards ρ₀, down to
pieces of width ρ₀, each with 10 plain Gauss–Legendre nodes. A power law on a uniform or
linear pressure needs no radial rule: p g ρ is then a sum of powers ρ^(n−q), integrated in
closed form (the check rule below is then the Gauss rule, an independent estimate). The
accepted panels are then
integrated again with ``N_CHECK`` radial nodes: the difference is the returned radial error
estimate. When c is far (|c − o| > ``FAR`` × extent) the integrand is smooth on the patch and the
area rule given by the caller is used (nodes with pressure weights); pure translation (ω = 0)
is g(|v|) times the constant law's exact wrench, in :func:`slidespin.contact.wrench.friction_wrench`.
"""

from __future__ import annotations

import math

import numpy as np

from slidespin._jit import jit
from slidespin.contact.pressure_map import _unit_rule

__all__ = ["FAR", "P_LINEAR", "P_BOUSSINESQ", "P_HERTZ", "speed_factor", "speed_wrench_body"]

P_LINEAR, P_BOUSSINESQ, P_HERTZ = 0, 1, 2
FAR = 24.0  # the area rule beyond FAR × extent from the reference point
N_OUT = 12
N_IN = 20
N_CHECK = 14
N_GEOM = 14
_MAX_LEVELS = 44
#: most bisections per wrench: beyond, every panel left is taken as it is and counted as
#: missed (a target below round-off would otherwise bisect without end)
_MAX_SPLITS = 20000
_MAX_GRADED = 60


_UO, _WO = _unit_rule(N_OUT, False)
_UI, _WI = _unit_rule(N_IN, True)
_UC, _WC = _unit_rule(N_CHECK, True)
_UG, _WG = _unit_rule(10, False)
_UP, _WP = _unit_rule(N_IN, False)  # plain rules for the θ of an ellipse's rim (smooth there)
_UPC, _WPC = _unit_rule(N_CHECK, False)


@jit
def speed_factor(code, lp, u):
    """g(u) of the law (``code``, ``lp``) of :mod:`slidespin.contact.speed_laws` at a slip
    speed u ≥ 0 [m/s]."""
    if code == 1:  # power law (q, v0)
        if u <= 0.0:
            return math.inf
        return (u / lp[1]) ** (-lp[0])
    if code == 2:  # Stribeck (mus/muk, vs, delta)
        return 1.0 + (lp[0] - 1.0) * math.exp(-((u / lp[1]) ** lp[2]))
    # table: n, speeds, factors, slopes; flat beyond the ends
    n = int(lp[0])
    if u <= lp[1]:
        return lp[1 + n]
    if u >= lp[n]:
        return lp[2 * n]
    lo, hi = 0, n - 1
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if lp[1 + mid] <= u:
            lo = mid
        else:
            hi = mid
    s0 = lp[1 + lo]
    h = lp[2 + lo] - s0
    t = (u - s0) / h
    f0, f1 = lp[1 + n + lo], lp[2 + n + lo]
    m0, m1 = lp[1 + 2 * n + lo], lp[2 + 2 * n + lo]
    omt = 1.0 - t
    return (
        (1.0 + 2.0 * t) * omt * omt * f0
        + t * omt * omt * h * m0
        + t * t * (3.0 - 2.0 * t) * f1
        + t * t * (t - 1.0) * h * m1
    )


@jit
def _density(pcode, pp, x, y):
    if pcode == 0:
        return pp[0] + pp[1] * x + pp[2] * y
    dx = (x - pp[0]) / pp[2]
    dy = (y - pp[1]) / pp[3]
    s = 1.0 - dx * dx - dy * dy
    if s <= 0.0:
        return 0.0
    if pcode == 1:
        return pp[4] / math.sqrt(s)
    return pp[4] * math.sqrt(s)


@jit
def _crossings(edges, conics, cx, cy, ex, ey, out):
    """Distances along the line c + ρ ê at which it crosses the patch's boundary, sorted;
    returns their number."""
    k = 0
    for i in range(edges.shape[0]):
        ax, ay, bx, by = edges[i, 0], edges[i, 1], edges[i, 2], edges[i, 3]
        sa = (ax - cx) * ey - (ay - cy) * ex
        sb = (bx - cx) * ey - (by - cy) * ex
        if (sa > 0.0) != (sb > 0.0):
            t = sa / (sa - sb)
            out[k] = (ax + t * (bx - ax) - cx) * ex + (ay + t * (by - ay) - cy) * ey
            k += 1
    for i in range(conics.shape[0]):
        ox, oy, a, b = conics[i, 0], conics[i, 1], conics[i, 2], conics[i, 3]
        dx, dy = cx - ox, cy - oy
        qa = (ex / a) ** 2 + (ey / b) ** 2
        qb = dx * ex / (a * a) + dy * ey / (b * b)
        qc = (dx / a) ** 2 + (dy / b) ** 2 - 1.0
        disc = qb * qb - qa * qc
        if disc > 0.0:
            h = math.sqrt(disc)
            q = -(qb + h) if qb >= 0.0 else -(qb - h)
            if q != 0.0:
                r1, r2 = q / qa, qc / q
            else:  # the line through the centre (qb = 0, h = 0 cannot happen here)
                r1, r2 = -h / qa, h / qa
            out[k] = min(r1, r2)
            out[k + 1] = max(r1, r2)
            k += 2
    for i in range(1, k):  # insertion sort (a few entries)
        x = out[i]
        j = i - 1
        while j >= 0 and out[j] > x:
            out[j + 1] = out[j]
            j -= 1
        out[j + 1] = x
    return k


@jit
def _piece(pcode, pp, cx, cy, dgx, dgy, ex, ey, lcode, lp, aom, r0, r1, us, ws, acc, rim):
    """Add ∫ p g ρ (1, r − r_G) dρ over [r0, r1] with the rule (us, ws) to ``acc``.

    For the Boussinesq and Hertz laws of an ellipse (``rim`` = (ρ₁, ρ₂, A): the ray's two
    crossings of the ellipse and 1 − q = A (ρ − ρ₁)(ρ₂ − ρ) on it) the rule is applied in θ,
    ρ = ρ_m + h sin θ (ρ_m, h the chord's mid-point and half-length): p dρ is then smooth,
    (c/√A) dθ and c √A h² cos²θ dθ, however close [r0, r1] comes to the rim."""
    if pcode == 0:
        ln = r1 - r0
        for j in range(us.size):
            rho = r0 + ln * us[j]
            p = _density(pcode, pp, cx + rho * ex, cy + rho * ey)
            if p == 0.0:
                continue
            w = ln * ws[j] * p * speed_factor(lcode, lp, aom * rho) * rho
            acc[0] += w
            acc[1] += w * (dgx + rho * ex)
            acc[2] += w * (dgy + rho * ey)
        return
    rho1, rho2, qa = rim[0], rim[1], rim[2]
    mid = 0.5 * (rho1 + rho2)
    half = 0.5 * (rho2 - rho1)
    if not half > 0.0:
        return
    # θ = asin((ρ − ρ_m)/h) as an atan2 of (ρ − ρ_m, √((ρ − ρ₁)(ρ₂ − ρ))): exact ±π/2 at
    # the rim (asin near 1 would lose half the digits, a sliver of 1e-8 of the chord)
    t0 = math.atan2(r0 - mid, math.sqrt(max(0.0, (r0 - rho1) * (rho2 - r0))))
    t1 = math.atan2(r1 - mid, math.sqrt(max(0.0, (r1 - rho1) * (rho2 - r1))))
    span = t1 - t0
    sq = math.sqrt(qa)
    # in θ the rim is smooth: plain Gauss–Legendre (a graded rule would crowd its nodes at
    # the ends and bring a nearby zero slip speed closer, in its own variable)
    if us.size == N_IN:
        us, ws = _UP, _WP
    elif us.size == N_CHECK:
        us, ws = _UPC, _WPC
    for j in range(us.size):
        th = t0 + span * us[j]
        rho = mid + half * math.sin(th)
        if pcode == 1:  # Boussinesq: p dρ = c/√(A (ρ − ρ₁)(ρ₂ − ρ)) dρ = (c/√A) dθ
            pd = pp[4] / sq
        else:  # Hertz: c √A h² cos²θ dθ
            ct = math.cos(th)
            pd = pp[4] * sq * half * half * ct * ct
        w = span * ws[j] * pd * speed_factor(lcode, lp, aom * rho) * rho
        acc[0] += w
        acc[1] += w * (dgx + rho * ex)
        acc[2] += w * (dgy + rho * ey)


@jit
def _ray(
    edges,
    conics,
    pcode,
    pp,
    cx,
    cy,
    gx,
    gy,
    ex,
    ey,
    lcode,
    lp,
    rbreaks,
    sing0,
    aom,
    n_in,
    cross,
    acc,
):
    """(K₁, K_x, K_y) of the ray c + ρ ê, ρ ≥ 0 (module notes), into ``acc``."""
    acc[0] = 0.0
    acc[1] = 0.0
    acc[2] = 0.0
    us, ws = (_UI, _WI) if n_in == N_IN else (_UC, _WC)
    k = _crossings(edges, conics, cx, cy, ex, ey, cross)
    dgx, dgy = cx - gx, cy - gy
    rim = np.zeros(3)
    if pcode != 0 and k >= 2:  # the ellipse of a Boussinesq or Hertz law: (ρ₁, ρ₂, A)
        rim[0], rim[1] = cross[0], cross[1]
        rim[2] = (ex / conics[0, 2]) ** 2 + (ey / conics[0, 3]) ** 2
    closed = lcode == 1 and pcode == 0 and n_in == N_IN
    if closed:  # a power law on a linear pressure: p g ρ is a sum of powers of ρ
        q = lp[0]
        cq = (aom / lp[1]) ** (-q)
        pc = pp[0] + pp[1] * cx + pp[2] * cy  # p(c + ρ ê) = pc + pe ρ
        pe = pp[1] * ex + pp[2] * ey
    for i in range(0, k - 1, 2):
        a = max(cross[i], 0.0)
        b = max(cross[i + 1], 0.0)
        if not b > a:
            continue
        if closed:
            j1 = (b ** (2.0 - q) - a ** (2.0 - q)) / (2.0 - q)  # ∫ ρ^(1−q)
            j2 = (b ** (3.0 - q) - a ** (3.0 - q)) / (3.0 - q)  # ∫ ρ^(2−q)
            j3 = (b ** (4.0 - q) - a ** (4.0 - q)) / (4.0 - q)  # ∫ ρ^(3−q)
            k1 = cq * (pc * j1 + pe * j2)
            k2 = cq * (pc * j2 + pe * j3)  # ∫ p g ρ · ρ
            acc[0] += k1
            acc[1] += dgx * k1 + ex * k2
            acc[2] += dgy * k1 + ey * k2
            continue
        lo = a
        for m in range(rbreaks.size + 1):
            hi = b
            if m < rbreaks.size:
                rb = rbreaks[m] / aom
                if rb <= lo:
                    continue
                if rb < b:
                    hi = rb
            if sing0 and lo == 0.0:
                top = hi
                for level in range(N_GEOM):
                    _piece(
                        pcode,
                        pp,
                        cx,
                        cy,
                        dgx,
                        dgy,
                        ex,
                        ey,
                        lcode,
                        lp,
                        aom,
                        0.5 * top,
                        top,
                        _UG,
                        _WG,
                        acc,
                        rim,
                    )
                    top *= 0.5
                # [0, top] in closed form, leading term
                p = _density(pcode, pp, cx, cy)
                if lcode == 1:
                    q = lp[0]
                    gq = (aom / lp[1]) ** (-q)
                    i1 = gq * top ** (2.0 - q) / (2.0 - q)
                    i2 = gq * top ** (3.0 - q) / (3.0 - q)
                else:
                    gm = speed_factor(lcode, lp, aom * 0.5 * top)
                    i1 = gm * top * top / 2.0
                    i2 = gm * top * top * top / 3.0
                acc[0] += p * i1
                acc[1] += p * (dgx * i1 + ex * i2)
                acc[2] += p * (dgy * i1 + ey * i2)
            elif sing0 and lo < hi - lo:
                # c just outside: the singular speed zero lies at distance lo before the
                # piece; geometric towards it down to a width of lo, then one plain piece
                top = hi
                while 0.5 * (top - lo) > lo:
                    mid = lo + 0.5 * (top - lo)
                    _piece(
                        pcode,
                        pp,
                        cx,
                        cy,
                        dgx,
                        dgy,
                        ex,
                        ey,
                        lcode,
                        lp,
                        aom,
                        mid,
                        top,
                        _UG,
                        _WG,
                        acc,
                        rim,
                    )
                    top = mid
                _piece(
                    pcode, pp, cx, cy, dgx, dgy, ex, ey, lcode, lp, aom, lo, top, _UG, _WG, acc, rim
                )
            else:
                _piece(
                    pcode, pp, cx, cy, dgx, dgy, ex, ey, lcode, lp, aom, lo, hi, us, ws, acc, rim
                )
            lo = hi
            if lo >= b:
                break


@jit
def _panel(
    edges,
    conics,
    pcode,
    pp,
    cx,
    cy,
    gx,
    gy,
    tb,
    sg,
    lcode,
    lp,
    rbreaks,
    sing0,
    aom,
    lo,
    hi,
    n_in,
    cross,
    acc,
    out,
):
    """(Fx, Fy, M) of the angular panel [lo, hi] into ``out`` (body frame, about G)."""
    out[0] = 0.0
    out[1] = 0.0
    out[2] = 0.0
    width = hi - lo
    for j in range(N_OUT):
        u = _UO[j]
        psi = lo + width * 0.5 * (1.0 - math.cos(math.pi * u))
        wpsi = width * 0.5 * math.pi * math.sin(math.pi * u) * _WO[j]
        ex, ey = math.cos(psi), math.sin(psi)
        _ray(
            edges,
            conics,
            pcode,
            pp,
            cx,
            cy,
            gx,
            gy,
            ex,
            ey,
            lcode,
            lp,
            rbreaks,
            sing0,
            aom,
            n_in,
            cross,
            acc,
        )
        tx = -sg * (tb[0, 0] * -ey + tb[0, 1] * ex)  # −𝔽 ŵ, ŵ = sign(ω) ẑ × ê
        ty = -sg * (tb[1, 0] * -ey + tb[1, 1] * ex)
        out[0] += wpsi * acc[0] * tx
        out[1] += wpsi * acc[0] * ty
        out[2] += wpsi * (acc[1] * ty - acc[2] * tx)


@jit
def _breaks(edges, conics, cx, cy):
    """The panel ends in [ψ₀, ψ₀ + 2π] (module notes)."""
    n = edges.shape[0] * (1 + 2 * _MAX_GRADED) + 6 * conics.shape[0] + 1
    br = np.empty(n)
    k = 0
    for i in range(edges.shape[0]):
        ax, ay, bx, by = edges[i, 0], edges[i, 1], edges[i, 2], edges[i, 3]
        br[k] = math.atan2(ay - cy, ax - cx)
        k += 1
        ln = math.hypot(bx - ax, by - ay)
        if ln == 0.0:
            continue
        tx, ty = (bx - ax) / ln, (by - ay) / ln
        d = abs((ax - cx) * ty - (ay - cy) * tx)
        if d == 0.0:
            continue
        nx, ny = ty, -tx
        if (ax - cx) * nx + (ay - cy) * ny < 0.0:
            nx, ny = -nx, -ny
        hand = 1.0 if nx * ty - ny * tx > 0.0 else -1.0
        psi0 = math.atan2(ny, nx)
        for sv in ((ax - cx) * tx + (ay - cy) * ty, (bx - cx) * tx + (by - cy) * ty):
            kk = abs(sv) / 2.0
            count = 0
            while kk > d and count < _MAX_GRADED:
                br[k] = psi0 + math.copysign(math.atan(kk / d), sv) * hand
                k += 1
                kk *= 0.5
                count += 1
    for i in range(conics.shape[0]):
        ox, oy, a, b = conics[i, 0], conics[i, 1], conics[i, 2], conics[i, 3]
        dx, dy = ox - cx, oy - cy
        base = math.atan2(dy, dx)
        br[k] = base
        br[k + 1] = base + math.pi
        br[k + 2] = base + 0.5 * math.pi
        br[k + 3] = base - 0.5 * math.pi
        k += 4
        # tangents from c: in the coordinates (ξ/a, η/b) the ellipse is the unit circle
        sx, sy = dx / a, dy / b
        dist = math.hypot(sx, sy)
        if dist > 1.0:
            sbase = math.atan2(sy, sx)
            half = math.asin(1.0 / dist)
            for sgn in (-1.0, 1.0):
                ang = sbase + sgn * half
                br[k] = math.atan2(b * math.sin(ang), a * math.cos(ang))
                k += 1
    two_pi = 2.0 * math.pi
    vals = np.sort(np.mod(br[:k], two_pi))
    out = np.empty(k + 1)
    m = 0
    for i in range(k):
        if m == 0 or vals[i] > out[m - 1]:
            out[m] = vals[i]
            m += 1
    if m == 0:
        out[0] = 0.0
        m = 1
    out[m] = out[0] + two_pi
    return out[: m + 1]


@jit
def _polar(
    edges, conics, pcode, pp, cx, cy, gx, gy, ext, tb, sg, lcode, lp, rbreaks, sing0, aom, tol
):
    """Adaptive polar rule about c (module notes): (Fx, Fy, M, unconverged panels, radial
    error estimate)."""
    ncr = 2 * (edges.shape[0] + 2 * conics.shape[0]) + 2
    cross = np.empty(ncr)
    acc = np.zeros(3)
    whole = np.zeros(3)
    left = np.zeros(3)
    right = np.zeros(3)
    br = _breaks(edges, conics, cx, cy)
    cap = br.size + 4 * _MAX_LEVELS + 8
    s_lo = np.empty(cap)
    s_hi = np.empty(cap)
    s_val = np.empty((cap, 3))
    s_lev = np.empty(cap, dtype=np.int64)
    top = 0
    for i in range(br.size - 1):
        _panel(
            edges,
            conics,
            pcode,
            pp,
            cx,
            cy,
            gx,
            gy,
            tb,
            sg,
            lcode,
            lp,
            rbreaks,
            sing0,
            aom,
            br[i],
            br[i + 1],
            N_IN,
            cross,
            acc,
            whole,
        )
        s_lo[top] = br[i]
        s_hi[top] = br[i + 1]
        s_val[top, :] = whole
        s_lev[top] = 0
        top += 1
    total = np.zeros(3)
    done_lo = [0.0]
    done_hi = [0.0]
    done_lo.pop()
    done_hi.pop()
    missed = 0
    splits = 0
    two_pi = 2.0 * math.pi
    while top > 0:
        top -= 1
        lo, hi, lev = s_lo[top], s_hi[top], s_lev[top]
        whole[:] = s_val[top, :]
        mid = 0.5 * (lo + hi)
        _panel(
            edges,
            conics,
            pcode,
            pp,
            cx,
            cy,
            gx,
            gy,
            tb,
            sg,
            lcode,
            lp,
            rbreaks,
            sing0,
            aom,
            lo,
            mid,
            N_IN,
            cross,
            acc,
            left,
        )
        _panel(
            edges,
            conics,
            pcode,
            pp,
            cx,
            cy,
            gx,
            gy,
            tb,
            sg,
            lcode,
            lp,
            rbreaks,
            sing0,
            aom,
            mid,
            hi,
            N_IN,
            cross,
            acc,
            right,
        )
        diff = max(
            abs(left[0] + right[0] - whole[0]),
            abs(left[1] + right[1] - whole[1]),
            abs(left[2] + right[2] - whole[2]) / ext,
        )
        splits += 1
        spent = splits >= _MAX_SPLITS
        # the target, or round-off: halves that agree to 1e-14 of the panel's size are all
        # that floating point can tell apart
        mag = max(abs(whole[0]), abs(whole[1]), abs(whole[2]) / ext)
        target = max(tol * (hi - lo) / two_pi, 1e-14 * mag)
        if diff <= target or hi - lo < 1e-13 or lev >= _MAX_LEVELS or spent:
            if diff > target and hi - lo >= 1e-13:
                missed += 1
            for c in range(3):
                total[c] += left[c] + right[c]
            done_lo.append(lo)
            done_hi.append(hi)
        else:
            s_lo[top], s_hi[top], s_lev[top] = lo, mid, lev + 1
            s_val[top, :] = left
            s_lo[top + 1], s_hi[top + 1], s_lev[top + 1] = mid, hi, lev + 1
            s_val[top + 1, :] = right
            top += 2
    check = np.zeros(3)
    for i in range(len(done_lo)):
        _panel(
            edges,
            conics,
            pcode,
            pp,
            cx,
            cy,
            gx,
            gy,
            tb,
            sg,
            lcode,
            lp,
            rbreaks,
            sing0,
            aom,
            done_lo[i],
            done_hi[i],
            N_CHECK,
            cross,
            acc,
            whole,
        )
        for c in range(3):
            check[c] += whole[c]
    err = max(abs(check[0] - total[0]), abs(check[1] - total[1]), abs(check[2] - total[2]) / ext)
    return total[0], total[1], total[2], missed, err


@jit
def speed_wrench_body(
    edges,
    conics,
    pcode,
    pp,
    gx,
    gy,
    ox,
    oy,
    ext,
    tb,
    lcode,
    lp,
    rbreaks,
    sing0,
    far_pts,
    far_w,
    vx,
    vy,
    om,
    tol,
):
    """The wrench (Fx, Fy, M about G) in the body frame for unit load, of the body-frame
    twist (vx, vy) [m/s], ω [rad/s] ≠ 0, with the body-frame tensor ``tb``; also the number
    of angular panels that missed ``tol`` and the radial error estimate (module notes)."""
    cx, cy = gx - vy / om, gy + vx / om
    aom = abs(om)
    dist = math.hypot(cx - ox, cy - oy)
    far = dist > FAR * ext
    if far and lcode == 3 and dist < 1e4 * ext:
        # a table's knot inside the patch's range of slip speeds: its kink needs the polar rule
        lo_s, hi_s = aom * (dist - ext), aom * (dist + ext)
        for i in range(rbreaks.size):
            if lo_s <= rbreaks[i] <= hi_s:
                far = False
    if far:
        fx = 0.0
        fy = 0.0
        mm = 0.0
        for i in range(far_w.size):
            x, y = far_pts[i, 0], far_pts[i, 1]
            wx = vx - om * (y - gy)
            wy = vy + om * (x - gx)
            sp = math.hypot(wx, wy)
            w = far_w[i] * speed_factor(lcode, lp, sp) / sp
            tx = -(tb[0, 0] * wx + tb[0, 1] * wy) * w
            ty = -(tb[1, 0] * wx + tb[1, 1] * wy) * w
            fx += tx
            fy += ty
            mm += (x - gx) * ty - (y - gy) * tx
        return fx, fy, mm, 0, 0.0
    sg = 1.0 if om > 0.0 else -1.0
    return _polar(
        edges, conics, pcode, pp, cx, cy, gx, gy, ext, tb, sg, lcode, lp, rbreaks, sing0, aom, tol
    )
