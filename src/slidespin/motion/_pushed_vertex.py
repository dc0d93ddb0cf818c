"""Private helpers of :mod:`slidespin.motion.pushed`: a finger at a corner of a polygonal outline
(MODEL §13).

A sharp corner has no normal: its admissible contact forces are the cone spanned by the two
adjacent edges' friction cones (from the edge before's ray n₀ − μp t₀ to the edge after's
n₁ + μp t₁). The finger sticks at the corner (the body point at the vertex moves with it, the
sticking equations of an edge point) while λ stays in that cone; when λ reaches its boundary the
finger slides onto an adjacent edge (``sliding_right`` onto the edge after the corner,
``sliding_left`` onto the edge before) or leaves (λ·n_both < 0, n_both the bisector of the
normals). A plastic impact at a corner makes u = 0 when that impulse lies in the cone, else it
takes the edge impulse of the side it leaves by. Natural units (ℓ, m, g = 1).
"""

from __future__ import annotations

import math

import numpy as np

from slidespin.motion._pushed_geometry import _rot

_AT = 1e-9  # [ℓ] a contact this close to a polygon's vertex is at the corner
_CONE_TOL = 1e-12  # relative slack of the corner's cone
_SEP, _STICK, _LEFT, _RIGHT = 0, 1, 2, 3


def corner_at(ol, piece, s):
    """The vertex index the outline point (piece, s) sits at, or None (on an arc, or where an
    edge meets an arc smoothly)."""
    if not ol.poly or piece >= len(ol.L):
        return None
    if s <= _AT and ol.is_corner(piece):
        return piece
    if s >= float(ol.L[piece]) - _AT and ol.is_corner((piece + 1) % len(ol.L)):
        return (piece + 1) % len(ol.L)
    return None


def _frame(ol, j, phi, mu):
    """World inward normals of the edges before and after vertex j, the cone's rays a, b and
    the bisector n_both."""
    c, sn = _rot(phi)

    def w(p):
        return (c * p[0] - sn * p[1], sn * p[0] + c * p[1])

    n0, n1 = w(ol.N[j - 1]), w(ol.N[j])
    a = (n0[0] + mu * n0[1], n0[1] - mu * n0[0])  # n₀ − μ t₀, t = ẑ × n
    b = (n1[0] - mu * n1[1], n1[1] + mu * n1[0])  # n₁ + μ t₁
    h = math.hypot(n0[0] + n1[0], n0[1] + n1[1])
    return n0, n1, a, b, ((n0[0] + n1[0]) / h, (n0[1] + n1[1]) / h)


def cone_room(ol, j, phi, mu, lam):
    """(λ·n_both, room from ray a, room to ray b): all ≥ 0 while λ lies in the corner's cone."""
    _, _, a, b, nb = _frame(ol, j, phi, mu)
    sc = _CONE_TOL * (abs(lam[0]) + abs(lam[1]))
    ra = a[0] * lam[1] - a[1] * lam[0] + sc
    rb = lam[0] * b[1] - lam[1] * b[0] + sc
    if a[0] * b[1] - a[1] * b[0] < 0.0:  # a cone wider than a half plane
        ra = rb = max(ra, rb)
    return lam[0] * nb[0] + lam[1] * nb[1], ra, rb


def stick_room(eng, t, y):
    """The corner cone's rooms of the sticking force at (t, y) (the sticking phase's events)."""
    return cone_room(eng.ol, eng.vert, y[0], eng.mu, eng.stick_acc(t, y)[1])


def normal_velocity(eng, u):
    """u·n at the corner: the larger of the two edges' (> 0: the finger leaves)."""
    n0, n1, _, _, _ = _frame(eng.ol, eng.vert, eng.X[2], eng.mu)
    return max(u[0] * n0[0] + u[1] * n0[1], u[0] * n1[0] + u[1] * n1[1])


def impulse(eng, lam, u, kmat):
    """The plastic impulse at the corner: the sticking one ``lam`` if in the cone, else the
    edge impulse (on its cone's edge, u·n = 0 after) of the side it leaves by."""
    n0, n1, _, _, _ = _frame(eng.ol, eng.vert, eng.X[2], eng.mu)
    room = cone_room(eng.ol, eng.vert, eng.X[2], eng.mu, lam)
    if min(room) >= 0.0:
        return lam
    n = np.array(n0 if room[1] < room[2] else n1)
    tt = np.array((-n[1], n[0]))
    nn = n + eng.mu * math.copysign(1.0, float(lam @ tt)) * tt
    return nn * (-float(n @ u) / float(n @ kmat @ nn))


def _candidates(eng):
    j = eng.vert
    prev = (j - 1) % len(eng.ol.L)
    n0, n1, _, _, _ = _frame(eng.ol, j, eng.X[2], eng.mu)
    return ((j, 0.0, 1.0, _RIGHT, n1), (prev, float(eng.ol.L[prev]), -1.0, _LEFT, n0))


def decide(eng, t, exclude=()):
    """The mode at the corner eng.vert: sticking there, sliding onto an adjacent edge, or
    separated (the engine's piece, s and direction set for a slide)."""
    x, j = eng.X, eng.vert
    u = eng.contact_velocity()[0]
    moving = math.hypot(u[0], u[1]) > eng.vtol()
    if not moving and _STICK not in exclude:
        if min(stick_room(eng, t, [x[2], x[5]])) >= 0.0:
            return _STICK
    for piece, s, dirn, mode, n in _candidates(eng):
        if mode in exclude:
            continue
        ut = -u[0] * n[1] + u[1] * n[0]
        if moving and not (abs(u[0] * n[0] + u[1] * n[1]) <= eng.vtol() and dirn * ut > 0.0):
            continue
        eng.vert, eng.piece, eng.s, eng.dirn = None, piece, s, dirn
        _, sdd, lam, *_ = eng.slide_acc(t, [x[2], x[5], s, ut])
        if lam[0] * n[0] + lam[1] * n[1] >= 0.0 and (moving or dirn * sdd > 0.0):
            return mode
        eng.vert, eng.piece, eng.s = j, j, 0.0
    return _SEP


def off_edge(eng, t, idx):
    """The mode after a sliding finger reaches an end of its piece (event 2: s = 0, 3: s = L):
    where the outline is smooth there (an edge meeting a disc's arc) it slides on along the
    next piece in the same mode; at a corner the corner decides."""
    on = eng.ol.beyond(eng.piece, idx == 3)
    if on is not None:
        eng.piece, eng.s = on
        return eng.mode
    eng.vert = eng.piece if idx == 2 else (eng.piece + 1) % len(eng.ol.L)
    eng.piece, eng.s = eng.vert, 0.0
    return decide(eng, t)
