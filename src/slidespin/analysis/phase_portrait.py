"""Phase portraits: trajectories in the (a ω, v) plane, converging on the terminal ratios.

The picture behind Table 2 and eq. 14–16: near the stop the direction of motion converges to a
fixed point of the sphere flow (MODEL §5), so every trajectory enters the origin along a ray
v = β* ω (a mixed ending), along the v-axis (pure sliding) or along the a ω-axis (pure
spinning). :func:`phase_portrait` simulates motions of equal start energy and samples their
curves; the rays are the :func:`~slidespin.analysis.terminal.terminal_states` at the start
angle (MODEL §6).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray
from scipy.integrate import solve_ivp

from slidespin import _validate as v
from slidespin.analysis._natural import _params
from slidespin.analysis.terminal import TerminalState, terminal_states
from slidespin.contact import _engine
from slidespin.contact.body import Body, check_body_friction
from slidespin.contact.friction import FrictionTensor
from slidespin.motion import _flow
from slidespin.motion.simulate import simulate
from slidespin.motion.state import State

__all__ = ["phase_portrait", "PhasePortrait"]


@dataclass(frozen=True)
class PhasePortrait:
    """Trajectories of one body in the (a ω, v) plane, converging on its terminal ratios.

    Attributes
    ----------
    body, friction : Body, FrictionTensor
        The system.
    spin : tuple of ndarray
        a ω(t) [m/s] along each trajectory (a: semi-axis along ξ).
    speed : tuple of ndarray
        v(t) [m/s] along each trajectory.
    beta_stop : ndarray
        Terminal ratio β*/a of each trajectory (inf: pure sliding, 0: pure spinning).
    endings : tuple of str
        Ending of each trajectory.
    terminal : tuple of TerminalState
        Fixed points at the initial body angle (the rays v = β* ω of the portrait).
    phi, theta : float
        Initial body angle and direction of the velocity [rad].
    """

    body: Body
    friction: FrictionTensor
    spin: tuple[NDArray[np.float64], ...]
    speed: tuple[NDArray[np.float64], ...]
    beta_stop: NDArray[np.float64]
    endings: tuple[str, ...]
    terminal: tuple[TerminalState, ...]
    phi: float
    theta: float


def _dense_curve(par, y0, s_end, points):
    """(u, s) sampled evenly in the regularised time τ from y0 until s = s_end (MODEL §5).

    Integrates the compiled right-hand side of :mod:`slidespin.motion._flow` with scipy's DOP853 and
    its dense output; used only to draw smooth curves (the stop itself comes from simulate).
    """
    out = np.empty(_flow.NY)
    fe, fc, geo = par.fp if getattr(par, "fp", None) is not None else _engine.no_footprint()
    plain = np.asarray(par).copy()

    def f(tau, y):
        _flow.rhs(plain, fe, fc, geo, y, out)
        return out.copy()

    def reached(tau, y):
        return y[3] - math.log(s_end)

    reached.terminal = True
    sol = solve_ivp(
        f, (0.0, 1e4), y0, method="DOP853", rtol=1e-9, atol=1e-12, dense_output=True, events=reached
    )
    tau = np.linspace(0.0, sol.t[-1], points)
    y = sol.sol(tau)
    u = y[:3] / np.linalg.norm(y[:3], axis=0)
    return u, np.exp(y[3])


def phase_portrait(
    body: Body,
    friction: FrictionTensor,
    *,
    n: int = 13,
    speed: float = 1.0,
    phi: float = 0.0,
    theta: float = 0.0,
    g: float = 9.81,
    points: int = 300,
) -> PhasePortrait:
    """Simulate ``n`` motions starting on a quarter ellipse of equal kinetic energy.

    The initial states are v₀ = s cos α, k ω₀ = s sin α (k = √(I/m)) for n angles α evenly
    spaced in (0, π/2), so every ratio v₀/(a ω₀) is represented. Each is integrated to its
    stop with :func:`slidespin.simulate` (terminal ratio and ending); the curve drawn is the
    same regularised system sampled densely until s has fallen to 1e-4 of its start, then
    closed at the origin.

    Parameters
    ----------
    body, friction : Body, FrictionTensor
        The system.
    n : int, default 13
        Number of trajectories (1 to 200).
    speed : float, default 1
        s = √(v₀² + k² ω₀²) [m/s] in [1e-12, 1e8], the same for every trajectory.
    phi, theta : float, default 0
        Initial body angle φ₀ and direction ϑ₀ of the velocity [rad].
    g : float, default 9.81
        Gravitational acceleration [m/s²] in [1e-6, 1e6].
    points : int, default 300
        Points per curve (10 to 100000).

    Returns
    -------
    PhasePortrait
    """
    check_body_friction(body, friction)
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or not 1 <= n <= 200:
        raise ValueError(f"n = {n!r} is invalid; valid range: integer in [1, 200]")
    if (
        isinstance(points, bool)
        or not isinstance(points, (int, np.integer))
        or not 10 <= points <= 100_000
    ):
        raise ValueError(f"points = {points!r} is invalid; valid range: integer in [10, 100000]")
    s0 = v.bounded("speed", speed, 1e-12, v.SPEED, "m/s")
    phi = v.finite("phi", phi)
    theta = v.finite("theta", theta)
    g = v.bounded("g", g, *v.GRAVITY, "m/s^2")
    k = body.radius_of_gyration
    a = body.length_unit
    par = _params(body, friction, 1e-12)
    kn = par[_engine.P_K]  # k/a
    v_unit, t_unit = math.sqrt(a * g), math.sqrt(a / g)
    spins, speeds, betas, endings = [], [], [], []
    for i in range(n):
        alpha = 0.5 * math.pi * (i + 0.5) / n
        st = State.from_speed(s0 * math.cos(alpha), s0 * math.sin(alpha) / k, theta, phi)
        tr = simulate(body, friction, st, g=g, rtol=1e-9)
        betas.append(tr.beta_stop / a if math.isfinite(tr.beta_stop) else tr.beta_stop)
        endings.append(tr.ending)
        vxn, vyn, wn = st.vx / v_unit, st.vy / v_unit, st.omega * t_unit
        sn = math.sqrt(vxn * vxn + vyn * vyn + (kn * wn) ** 2)
        y0 = np.array([vxn / sn, vyn / sn, kn * wn / sn, math.log(sn), 0.0, 0.0, 0.0, phi, 0.0])
        u, s = _dense_curve(par, y0, 1e-4 * sn, points - 1)
        spins.append(np.append(s * u[2] / kn * v_unit, 0.0))  # a ω = (s u₃/k) · a
        speeds.append(np.append(s * np.hypot(u[0], u[1]) * v_unit, 0.0))
    return PhasePortrait(
        body=body,
        friction=friction,
        spin=tuple(spins),
        speed=tuple(speeds),
        beta_stop=np.array(betas),
        endings=tuple(endings),
        terminal=terminal_states(body, friction, phi),
        phi=phi,
        theta=theta,
    )
