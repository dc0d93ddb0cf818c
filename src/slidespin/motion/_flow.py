"""The regularised equations of motion of MODEL §5: the state vector, its initial value
(:func:`initial_state`) and its right-hand side (:func:`rhs`).

State (natural units: lengths in a, time in √(a/g), mass m, so forces are in m g):

    y = (u₁, u₂, u₃, ln s, t, x, y, φ, ℓ),   s = √(vx² + vy² + k² ω²),  u = (vx, vy, k ω)/s,

with k = √(I/m) the radius of gyration. With dt = s dτ and A(u, φ) = (Fx, Fy, M/k)/(m g):

    du/dτ = A − (u·A) u,   d ln s/dτ = u·A < 0,   dt/dτ = s,
    dx/dτ = s² u₁,  dy/dτ = s² u₂,  dφ/dτ = s² u₃ / k,  dℓ/dτ = s² √(u₁² + u₂²),

ℓ being the length of the path of G.

This system is smooth through the stop: s decays exponentially in τ while u converges to a
fixed point u* of the sphere flow (its first three components), which
:mod:`slidespin.motion._stops` classifies; :mod:`slidespin.motion._integrator` integrates
it. A(u, φ) is :func:`slidespin.contact._engine.accelerations` for the patch ``fp`` (``None``
for an ellipse, else the footprint's arrays; :func:`~slidespin.contact._engine.footprint_argument`).
"""

from __future__ import annotations

import math

import numpy as np

from slidespin._jit import jit
from slidespin.contact._engine import P_K, accelerations, footprint_argument, kernel_constants
from slidespin.contact._kernel_ellipse import WORKSPACE_SHAPE

#: length of the state vector y
NY = 9


@jit(error_model="numpy", inline="always")
def unit_direction(y):
    """(u₁, u₂, u₃, 1/|z|): the state's direction z = y[:3] normalised."""
    u1 = y[0]
    u2 = y[1]
    u3 = y[2]
    inv = 1.0 / math.sqrt(u1 * u1 + u2 * u2 + u3 * u3)
    return u1 * inv, u2 * inv, u3 * inv, inv


@jit(error_model="numpy", inline="always")
def flow(ax, ay, am, u1, u2, u3, ln_s, k, out):
    """The right-hand side (module notes) from the accelerations A = (ax, ay, am) at the
    unit direction u, into ``out``; returns (u·A, s, s², √(u₁² + u₂²))."""
    ua = u1 * ax + u2 * ay + u3 * am
    out[0] = ax - ua * u1
    out[1] = ay - ua * u2
    out[2] = am - ua * u3
    out[3] = ua
    s = math.exp(ln_s)
    s2 = s * s
    r = math.sqrt(u1 * u1 + u2 * u2)
    out[4] = s
    out[5] = s2 * u1
    out[6] = s2 * u2
    out[7] = s2 * u3 / k
    out[8] = s2 * r
    return ua, s, s2, r


@jit(error_model="numpy")
def _rhs(par, kc, W, fp, y, out):
    """Right-hand side of the regularised system; returns the wrench status."""
    u1, u2, u3, _ = unit_direction(y)
    ax, ay, am, st = accelerations(par, kc, W, fp, u1, u2, u3, y[7])
    flow(ax, ay, am, u1, u2, u3, y[3], par[P_K], out)
    return st


@jit(error_model="numpy")
def _rhs_once(par, fp, y, out):
    return _rhs(par, kernel_constants(par), np.empty(WORKSPACE_SHAPE), fp, y, out)


def rhs(par, fe, fc, geo, y, out):
    """Right-hand side of the regularised system (one call; the integrator keeps its
    constants and workspace); returns the wrench status. ``fe``, ``fc``, ``geo``: the
    footprint arrays (:func:`no_footprint` for an ellipse; ignored unless ``par[P_SHAPE]`` is
    ``SHAPE_FOOTPRINT``)."""
    return _rhs_once(par, footprint_argument(par, fe, fc, geo), y, out)


@jit(error_model="numpy")
def initial_state(par, vx, vy, wn, x, y, phi):
    """Regularised initial state (MODEL §5) from the velocity (vx, vy) of G, the spin ω (as
    ``wn``) and the position (x, y, φ), all in natural units; a body at rest gets
    ln s = −inf. The same arithmetic as :func:`slidespin.simulate`, so that batch and single
    runs agree to the last bit."""
    k = par[P_K]
    y0 = np.zeros(NY)
    s0 = math.sqrt(vx * vx + vy * vy + (k * wn) ** 2)
    y0[5] = x
    y0[6] = y
    y0[7] = phi
    if s0 == 0.0:
        y0[3] = -np.inf
        return y0
    y0[0] = vx / s0
    y0[1] = vy / s0
    y0[2] = k * wn / s0
    y0[3] = math.log(s0)
    return y0
