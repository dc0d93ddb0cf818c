"""The kinematic state of the body: position, angle and velocities (paper eq. 3–4).

Paper symbols and code names (MODEL §1): the state (x, y, φ, ẋ, ẏ, φ̇) of paper eq. 3–4 →
``State(x, y, phi, vx, vy, omega)``; the paper's speed v and direction ϑ of the velocity of G
→ :meth:`State.from_speed` (``speed``, ``theta``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from slidespin import _validate as v

__all__ = ["State"]


@dataclass(frozen=True, slots=True)
class State:
    """Kinematic state of the body in the fixed frame OXY.

    Parameters
    ----------
    x, y : float
        Position of the mass centre G [m], |x|, |y| ≤ 1e100.
    phi : float
        Body angle φ between OX and the body axis Cξ [rad], any finite value.
    vx, vy : float
        Velocity of G [m/s], |vx|, |vy| ≤ 1e8 (non-relativistic).
    omega : float
        Spin rate φ̇ [rad/s], counter-clockwise positive, |ω| ≤ 1e12.

    Notes
    -----
    The bounds keep the motion representable: the distance to the stop grows like v²/(μ g),
    and the turns like ω²; docs/errors.md ("Valid ranges") gives the reasoning.
    """

    x: float = 0.0
    y: float = 0.0
    phi: float = 0.0
    vx: float = 0.0
    vy: float = 0.0
    omega: float = 0.0

    def __post_init__(self) -> None:
        limits = (
            ("x", v.POSITION, "m"),
            ("y", v.POSITION, "m"),
            ("phi", None, "rad"),
            ("vx", v.SPEED, "m/s"),
            ("vy", v.SPEED, "m/s"),
            ("omega", v.SPIN, "rad/s"),
        )
        for name, bound, unit in limits:
            x = v.finite(name, getattr(self, name))
            if bound is not None:
                x = v.symmetric(name, x, bound, unit)
            object.__setattr__(self, name, x)

    @classmethod
    def from_speed(
        cls,
        speed: float,
        omega: float,
        theta: float = 0.0,
        phi: float = 0.0,
        x: float = 0.0,
        y: float = 0.0,
    ) -> State:
        """State from the paper's variables: speed v in [0, 1e8] m/s in direction ϑ, spin ω.

        ``theta`` and ``phi`` are in radians (``math.radians(45)``, not 45).
        """
        v0 = v.bounded("speed", speed, 0.0, v.SPEED, "m/s")
        th = v.finite("theta", theta)
        return cls(x, y, phi, v0 * math.cos(th), v0 * math.sin(th), omega)

    @property
    def speed(self) -> float:
        """|v_G| [m/s]."""
        return math.hypot(self.vx, self.vy)

    def as_array(self) -> np.ndarray:
        """(x, y, phi, vx, vy, omega) as a float array."""
        return np.array([self.x, self.y, self.phi, self.vx, self.vy, self.omega])


def reduced_angle(phi: float) -> tuple[float, float]:
    """(φ − 2πk, 2πk), k the nearest number of turns: the engines run on the reduced start
    angle (a body at φ = 1e12 rad would otherwise turn on the last digits of its angle) and
    the result adds the turns back."""
    turns = 2.0 * math.pi * round(phi / (2.0 * math.pi))
    return phi - turns, turns
