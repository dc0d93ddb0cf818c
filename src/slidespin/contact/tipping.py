"""Tipping: whether a growing load slides or tips a tall body at rest, and where a tall
body presses (MODEL §14).

:func:`breakaway` answers, for a load scaled up from zero, which comes first: the load
leaving the static-friction set C (slide), or the pressure centroid reaching the convex hull
of the footprint (tip); :func:`pressure_centre` is the pressure centroid of a tall body at
rest or sliding. The mechanics are in :mod:`slidespin.contact.tall`; the load objects are
duck-typed as in :mod:`slidespin.contact.statics` (anything with ``wrench(t, phi,
mass_centre)`` and, for heights, ``raised_force(t, phi, height)``, such as
:class:`slidespin.Load`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from slidespin import _validate as v
from slidespin.contact._engine import TwistWrench
from slidespin.contact._speed_wrench import law_arrays, speed_tol
from slidespin.contact.body import Body
from slidespin.contact.friction import FrictionTensor
from slidespin.contact.incline import Incline
from slidespin.contact.speed_laws import law_is_constant
from slidespin.contact.static_set import _check, _normal, static_support
from slidespin.contact.statics import (
    _applied,
    _check_load,
    _inputs,
    _load_factor_nat,
    _raised,
    _tall,
    _with_pull,
)
from slidespin.contact.tall import TallContact
from slidespin.contact.tall_speed import TallSpeed

__all__ = ["Breakaway", "breakaway", "pressure_centre"]


@dataclass(frozen=True, slots=True)
class Breakaway:
    """How a body at rest gives way as a load grows from zero: it slides or it tips
    (MODEL §11, §14; :func:`breakaway`).

    Attributes
    ----------
    mode : str
        ``"slide"`` or ``"tip"``: what happens first as the load is scaled up (``"hold"``
        for a zero load, which nothing moves).
    load_factor : float
        λ* = min(slide_factor, tip_factor): the load can be multiplied by λ* before the
        body gives way (:func:`slidespin.load_factor`; ``inf`` for a zero load).
    slide_factor : float
        The factor at which the load leaves the static-friction set C of the pressure it
        has moved (for a factor beyond ``tip_factor``, with the pressure held at the hull's
        edge: what a body that could not tip would do).
    tip_factor : float
        The factor at which the pressure centroid reaches the convex hull of the footprint
        (``inf`` for a body of height 0 or a load that does not move the pressure).
    """

    mode: str
    load_factor: float
    slide_factor: float
    tip_factor: float


def breakaway(
    body: Body,
    friction: FrictionTensor,
    applied_wrench,
    phi: float = 0.0,
    g: float = 9.81,
    *,
    incline: Incline | None = None,
    t: float = 0.0,
) -> Breakaway:
    """Whether a growing load slides or tips a body at rest, and at which factor (MODEL §14).

    Arguments as in :func:`slidespin.load_factor`. For a tall body (``Body(..., height=h)``) a load
    such as ``slidespin.Load(force=..., height=h_Q)`` moves the pressure centroid to
    r_G + λ [Σ h_Q Q + h Q_gravity]/P under λ times the load (static friction balances the
    force at the plane); a triple acts at G's height. The body tips when that centroid
    reaches the convex hull of the footprint, and slides when the load leaves the set C of
    the moved pressure (lift-off included). For a body of height 0 the mode is ``"slide"``
    and ``tip_factor`` is ``inf``.

    Examples
    --------
    A uniform box of base width w = 0.4 m pushed at height h_Q slides first iff
    μ < w/(2 h_Q), else it tips at Q = P w/(2 h_Q):

    >>> from slidespin import Body, FrictionTensor, Load, UniformPressure
    >>> from slidespin.contact.shapes import Rectangle
    >>> box = Body(Rectangle(0.4, 0.3), UniformPressure(), mass=2.0, height=0.5)
    >>> fr = FrictionTensor(0.5, 0.5)
    >>> b = breakaway(box, fr, Load(force=(1.0, 0.0), height=0.5), g=10.0)
    >>> b.mode, round(b.tip_factor, 9), round(b.slide_factor, 9)  # P w/(2 h_Q) = 8 N; μ P = 10 N
    ('tip', 8.0, 10.0)
    >>> breakaway(box, fr, Load(force=(1.0, 0.0), height=0.3), g=10.0).mode
    'slide'
    """
    phi, _w, nf, g, b = _inputs(body, friction, applied_wrench, phi, g, incline, t)
    if not _check_load("applied_wrench", b, incline):
        return Breakaway("hold", math.inf, math.inf, math.inf)
    if body.height > 0.0:
        lam, mode, slide, tip, *_ = _tall(
            body, friction, applied_wrench, b, phi, t, body.mass * g * nf
        )
        return Breakaway(mode, lam, slide, tip)
    sup = static_support(TwistWrench(body, friction.kinetic), friction, phi)
    lam = _load_factor_nat(sup, b)[0]
    return Breakaway("slide", lam, lam, math.inf)


def pressure_centre(
    body: Body,
    friction: FrictionTensor,
    state,
    load=None,
    g: float = 9.81,
    *,
    incline: Incline | None = None,
    t: float = 0.0,
) -> tuple[float, float]:
    """The pressure centroid r_p of a body in ``state`` [m, body frame] (MODEL §14).

    Sliding (v or ω ≠ 0): r_p = r_G − [h F + Σ (h − h_Q) Q]/P, solved together with the
    friction force F of the moved pressure (lift-off included; under a speed law, F of the
    actual slip speeds, without lift-off). At rest, static friction
    balances the applied force: r_p = r_G + [Σ h_Q Q + h Q_gravity]/P (the body may then
    be past tipping: compare with the footprint, or ask :func:`breakaway`). For a body of
    height 0 it is G.

    Parameters
    ----------
    body, friction : Body, FrictionTensor
    state : State
        The body's angle and twist (``phi``, ``vx``, ``vy``, ``omega``; SI).
    load : Load or None
        Applied loads (with ``height`` where they act above or below G), or a triple
        (Qx, Qy, M) acting at G's height; at time ``t``.
    g : float
        Gravitational acceleration [m/s²].
    incline : Incline or None
        A plane of fixed tilt: P = m g cos α, and gravity's pull acts at G.

    Examples
    --------
    A tall disk sliding with isotropic friction presses ahead of G by h μ:

    >>> from slidespin import Body, Disk, FrictionTensor, State, UniformPressure
    >>> disk = Body(Disk(0.1), UniformPressure(), mass=1.0, height=0.05)
    >>> [round(x, 12) for x in pressure_centre(disk, FrictionTensor(0.3, 0.3), State(vx=1.0))]
    [0.015, 0.0]
    """
    _check(body, friction)
    if not all(hasattr(state, n) for n in ("phi", "vx", "vy", "omega")):
        raise ValueError(
            f"state = {v._short(state)} is invalid; valid values: a slidespin.State (its "
            "phi, vx, vy and omega are used)"
        )
    phi = v.finite("state.phi", state.phi)
    vx, vy, om = (v.finite(f"state.{n}", getattr(state, n)) for n in ("vx", "vy", "omega"))
    g = v.bounded("g", g, *v.GRAVITY, "m/s^2")
    gx, gy = body.mass_centre
    if body.height == 0.0:
        return (float(gx), float(gy))
    w = np.zeros(3) if load is None else _applied(body, load, phi, t)
    nf = _normal(incline, 1.0)
    w = _with_pull(body, w, incline, g)
    normal_load = body.mass * g * nf
    ell = body.length_unit
    rx, ry = (0.0, 0.0) if load is None else _raised(body, load, phi, t)
    c, s = math.cos(phi), math.sin(phi)
    sig = ((c * rx + s * ry) / (normal_load * ell), (-s * rx + c * ry) / (normal_load * ell))
    if (vx, vy, om) != (0.0, 0.0, 0.0) and not law_is_constant(friction.speed_law):
        # under a speed law the friction, hence the shift, depends on the slip speeds
        fast = TallSpeed(body, friction, law_arrays(friction.speed_law), speed_tol(friction))
        rp = fast(phi, vx, vy, om, (sig[0] * ell, sig[1] * ell))[3]
        return (float(rp[0]), float(rp[1]))
    tall = TallContact(body, friction.kinetic)
    if (vx, vy, om) != (0.0, 0.0, 0.0):
        rp = tall.solve(phi, vx / ell, vy / ell, om, sig)[3]
    else:
        fx, fy = w[0] / normal_load, w[1] / normal_load
        fxb, fyb = c * fx + s * fy, -s * fx + c * fy
        rp = (tall.rg[0] + tall.h * fxb - sig[0], tall.rg[1] + tall.h * fyb - sig[1])
    return (float(rp[0] * ell), float(rp[1] * ell))
