"""The sliding body and its kinematic state.

Paper symbols and code names (MODEL §1): m → ``mass``, I → ``moment_of_inertia`` (about the
vertical axis through the mass centre G), I* = I/(m a²) → ``inertia_ratio``; the state
(x, y, φ, ẋ, ẏ, φ̇) of paper eq. 3–4 → ``State(x, y, phi, vx, vy, omega)``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from . import _validate as v
from .friction import FrictionTensor
from .geometry import Ellipse
from .pressure import BoussinesqPressure, HertzPressure, LinearPressure, UniformPressure

__all__ = ["Body", "State"]

_LAWS = (UniformPressure, LinearPressure, BoussinesqPressure, HertzPressure)


@dataclass(frozen=True, slots=True)
class Body:
    """A flat rigid body resting on its contact patch.

    Parameters
    ----------
    patch : Ellipse or Circle
        The contact patch.
    pressure : UniformPressure, LinearPressure, BoussinesqPressure or HertzPressure
        Normal-pressure law on the patch. The mass centre G lies above the pressure
        centroid: the patch centre, or (ξc, ηc) for the linear law.
    mass : float
        Mass m [kg], in [1e-12, 1e12].
    moment_of_inertia : float or None
        I about the vertical axis through G [kg m²], with I* = I/(m a²) in [1e-8, 1e8]
        (docs/errors.md, "Valid ranges"). ``None`` means
        I = m (a² + b²)/4, the inertia of a uniform plate of the patch's shape about its
        centre; this is the paper's I* = (1 + κ²)/4 (eq. 7). For the linear law, whose G is
        off-centre, give I explicitly if the body is not such a plate.

    Examples
    --------
    >>> from slidespin import Ellipse, UniformPressure
    >>> body = Body(Ellipse(0.1, 0.05), UniformPressure(), mass=2.0)
    >>> round(body.inertia_ratio, 4)
    0.3125
    """

    patch: Ellipse
    pressure: object
    mass: float
    moment_of_inertia: float | None = None

    def __post_init__(self) -> None:
        if not isinstance(self.patch, Ellipse):
            raise ValueError(
                f"patch = {self.patch!r} is invalid; valid values: an Ellipse or a Circle"
            )
        if not isinstance(self.pressure, _LAWS):
            raise ValueError(
                f"pressure = {self.pressure!r} is invalid; valid values: UniformPressure(), "
                "LinearPressure(xi_c, eta_c), BoussinesqPressure(), HertzPressure()"
            )
        self.pressure.check_patch(self.patch)
        m = v.bounded("mass", self.mass, *v.MASS, "kg")
        object.__setattr__(self, "mass", m)
        a = self.patch.a
        if self.moment_of_inertia is None:
            inertia = m * (a**2 + self.patch.b**2) / 4.0
        else:
            inertia = v.positive("moment_of_inertia", self.moment_of_inertia, "kg m^2")
            lo, hi = v.INERTIA_RATIO
            i_star = inertia / m / a / a
            if not lo * (1.0 - 1e-12) <= i_star <= hi * (1.0 + 1e-12):  # round-off of I* m a²
                raise ValueError(
                    f"moment_of_inertia = {inertia!r} kg m^2 is invalid for mass = {m!r} kg and "
                    f"a = {a!r} m: I/(m a^2) = {i_star:.6g}; valid range: [{lo:g}, {hi:g}] "
                    f"m a^2 = [{lo * m * a * a:.6g}, {hi * m * a * a:.6g}] kg m^2"
                )
        object.__setattr__(self, "moment_of_inertia", inertia)

    @classmethod
    def from_inertia_ratio(cls, patch, pressure, mass: float, inertia_ratio: float) -> "Body":
        """Body with I = I* m a² for a given dimensionless inertia I* in [1e-8, 1e8]."""
        i_star = v.bounded("inertia_ratio", inertia_ratio, *v.INERTIA_RATIO)
        m = v.bounded("mass", mass, *v.MASS, "kg")
        if not isinstance(patch, Ellipse):
            raise ValueError(f"patch = {patch!r} is invalid; valid values: an Ellipse or a Circle")
        return cls(patch, pressure, m, i_star * m * patch.a**2)

    @property
    def inertia_ratio(self) -> float:
        """I* = I/(m a²) (paper §3, appendix)."""
        return self.moment_of_inertia / (self.mass * self.patch.a**2)

    @property
    def radius_of_gyration(self) -> float:
        """k = √(I/m) [m]."""
        return math.sqrt(self.moment_of_inertia / self.mass)

    @property
    def mass_centre(self) -> tuple[float, float]:
        """G in the body frame [m] (the pressure centroid)."""
        return self.pressure.centroid

    def kernel_params(self, friction: FrictionTensor, wrench_tol: float = 1e-12) -> np.ndarray:
        """Parameter vector of the compiled engine, in natural units (a = m = g = 1)."""
        from . import _ode

        a = self.patch.a
        xg, yg = self.mass_centre
        t = friction.matrix
        par = np.empty(_ode.NPAR)
        par[_ode.P_BN] = self.patch.b / a
        par[_ode.P_LAW] = self.pressure.code
        par[_ode.P_XG] = xg / a
        par[_ode.P_YG] = yg / a
        par[_ode.P_T00], par[_ode.P_T01] = t[0]
        par[_ode.P_T10], par[_ode.P_T11] = t[1]
        par[_ode.P_BODY] = 1.0 if friction.frame == "body" else 0.0
        par[_ode.P_K] = self.radius_of_gyration / a
        par[_ode.P_WTOL] = wrench_tol
        return par


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
        limits = (("x", v.POSITION, "m"), ("y", v.POSITION, "m"), ("phi", None, "rad"),
                  ("vx", v.SPEED, "m/s"), ("vy", v.SPEED, "m/s"), ("omega", v.SPIN, "rad/s"))
        for name, bound, unit in limits:
            x = v.finite(name, getattr(self, name))
            if bound is not None:
                x = v.symmetric(name, x, bound, unit)
            object.__setattr__(self, name, x)

    @classmethod
    def from_speed(
        cls, speed: float, omega: float, theta: float = 0.0, phi: float = 0.0,
        x: float = 0.0, y: float = 0.0,
    ) -> "State":
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
