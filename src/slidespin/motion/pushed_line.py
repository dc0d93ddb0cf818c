"""Dynamic pushing with a flat pusher: the full dynamics of a body pushed by a line pusher (MODEL §13).

A :class:`~slidespin.motion.pushers.LinePusher` prescribes the pose (centre p(t), direction
e(t) = (cos θ, sin θ)) of a segment of half-length h; the contact decides the force. With
ν = (vx, vy, ω) the twist at G, W(ν) the exact plane friction and (Q, T) the loads (MODEL §11):

    M ν̇ = W(ν) + (Q, T) + (λ, r × λ + τ),   λ = λn n + λt t,  λn ≥ 0,  |λt| ≤ μp λn,

with c the reference contact point, r = c − G, n the inward unit normal (into the body),
t = ẑ × n, and τ the couple of a distributed line load about c (face contact only). The
modes (codes 4–12 of :data:`slidespin.motion.outcomes.PUSH_MODES`; left and right as for a
finger, :mod:`slidespin.motion.pushed`: ``*_left`` when u·t < 0, u the body's velocity at c
relative to the pusher's material point there):

=======================  =====================================================================
``face_sticking``        a body edge flush with the pusher's face, the body moving rigidly
                         with the pusher: ν is the pusher's twist, λ = m a_G − F − Q and the
                         couple τ = −(M + T + r × λ) follow; the resultant's point on the
                         face, c + s t with s = −τ/λn, must lie on the shared segment
``face_sliding_left``,   the edge flush (φ − θ fixed, ω = θ̇), sliding along the face:
``face_sliding_right``   one degree of freedom σ (the edge's vertex along the pusher), a 2×2
                         solve for (σ̈, λn) with λt = −μp λn sign(u·t), then τ as above
``vertex_*``             a body vertex on the pusher's face (n the face normal): the vertex's
                         place σ along the face and φ; sticking (σ̇ = 0, one degree of
                         freedom) or sliding (two, a 3×3 solve for (ω̇, σ̈, λn))
``end_*``                an end of the pusher on a body edge (n the edge's normal): the
                         contact's arc length s along the edge and φ, as for a finger
=======================  =====================================================================

Switches (events located by Brent's method on the dense output, to ~1e-15 of √(ℓ/g)): λn
crossing 0 (separation); λ at the cone's edge; u·t crossing 0; in face contact, the resultant
at an end of the shared segment: the contact **rotates about that end** (``vertex_*`` at a
body vertex, ``end_*`` at the pusher's end); in a point contact, a neighbouring vertex
reaching the pusher's line: a **plastic face impact** (the pusher's twist if the impulse is in
the cone with its resultant on the segment, else the cone's edge, else an impact at one end
only, the two-point impact's complementarity; a rocking sequence whose approach falls below
1e-5 of the speed scale lands flat) and face contact; a vertex sliding off the pusher's end
separates, an end sliding onto a body vertex makes a vertex contact; the separating-axis gap
closing (arrival). Impacts on arrival and at knots are plastic, as for a finger. Energy:
pusher work (λ·ṗ(c) + τ θ̇, impulses included) + load work = ΔKE + plane friction + contact
slip (−λ·u = μp λn |u·t|) + impact losses. The engine of these contacts on a polygon is
:mod:`slidespin.motion._line_engine`; on an ellipse, a circle or a hull with arcs (pads with disks),
:mod:`slidespin.motion._line_round` (a curve rolling or sliding on the face, ``vertex_*``, or
an end on a curve, ``end_*``). Natural units throughout (ℓ, m, g = 1).
"""

from __future__ import annotations

import numpy as np

from slidespin import _validate as v
from slidespin.motion._line_engine import _TOUCH, _Engine
from slidespin.motion._line_round import RoundEngine
from slidespin.motion._loaded_problem import _Problem
from slidespin.motion._pushed_geometry import _Line, _Outline
from slidespin.motion.pushed_trajectory import PushedTrajectory, _assemble
from slidespin.motion.state import reduced_angle

__all__ = ["simulate_line"]


def simulate_line(
    body, friction, state, pusher, t_end, g, rtol, max_steps, max_phases, load, incline, outline
) -> PushedTrajectory:
    """A body pushed by a line pusher over [0, t_end] (MODEL §13, with §11's loads): the
    arguments of :func:`slidespin.motion.pushed.simulate_pushed`, checked there; the outline
    must not start inside the outline (a one-line ``ValueError``).
    Returns a :class:`~slidespin.motion.pushed_trajectory.PushedTrajectory` with the modes
    of the module notes (``contact_point``: the resultant's point on the face, or the point
    contact; ``pusher_position``: the pusher's centre)."""
    prob = _Problem(body, friction, load, incline, g)
    prob.b(0.0, state.phi)
    a, tu, vu = prob.a, prob.t_unit, prob.v_unit
    ol = _Outline(body, a, outline)
    line = _Line(pusher, a, tu)
    eng = (RoundEngine if ol.round or not ol.poly else _Engine)(
        prob, ol, line, rtol, int(max_steps)
    )
    phi0, eng.turns = reduced_angle(state.phi)
    eng.X = np.array(
        [state.x / a, state.y / a, phi0, state.vx / vu, state.vy / vu, state.omega * tu]
    )
    gap0 = eng.gap(line.segment(0.0)[0], 0.0, *eng.X[:3])
    if gap0 < -_TOUCH:
        raise ValueError(
            f"pusher = {v._short(pusher)} is invalid with state = {v._short(state)}: the pusher "
            f"starts {-gap0 * a:.6g} m inside the body's outline; valid: touching it (within "
            f"{_TOUCH:g} of the body's length unit) or outside it"
        )
    status, t_stop = eng.run(t_end / tu, int(max_phases))
    return _assemble(
        eng, status, t_stop, t_end, max_steps, max_phases, prob, body, friction, state, pusher, g
    )
