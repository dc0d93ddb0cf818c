"""The anisotropic friction tensor of the paper (eq. 1–2, MODEL §2).

A contact point slipping with velocity w feels the traction τ = −p 𝔽 w/|w|, with

    𝔽 = [[fx, f], [−f, fy]]          (paper eq. 2),   μ = fy − fx.

Only the symmetric part of 𝔽 dissipates (w·𝔽w = fx wx² + fy wy²), so the law is dissipative
exactly when fx > 0 and fy > 0; the skew coefficient f is free.

Frames. The paper fixes 𝔽 to the plane (``frame="plane"``). slidespin also offers a tensor
fixed to the body (``frame="body"``: skis, scales, textured soles), whose world-frame matrix
is R(φ) 𝔽 R(φ)ᵀ, and a tensor whose principal axes are turned by ``angle`` from OX (plane) or
from Cξ (body): 𝔽 → R(angle) 𝔽 R(angle)ᵀ. The skew part f·J is unchanged by any rotation.

Beyond the paper (MODEL §14): ``static`` (μs/μk ≥ 1) scales the set of wrenches the tensor
holds at rest, and ``speed_law`` (:mod:`slidespin.contact.speed_laws`) multiplies the whole
tensor by a factor of the local slip speed.
"""

from __future__ import annotations

import math
from dataclasses import InitVar, dataclass

import numpy as np
from numpy.typing import NDArray

from slidespin import _validate as v
from slidespin.contact.speed_laws import (
    STATIC_RATIO,
    PowerLaw,
    SpeedTable,
    Stribeck,
    check_speed_law,
    law_is_constant,
)

__all__ = ["FrictionTensor", "FRAMES"]

#: the frames a :class:`FrictionTensor` may be fixed to: the plane (the paper) or the body
FRAMES = ("plane", "body")
#: largest |angle| [rad] of the principal axes: 2π (a larger number is almost surely degrees)
ANGLE_MAX = 2.0 * math.pi * (1.0 + 1e-15)


def _rot(angle: float) -> NDArray[np.float64]:
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[c, -s], [s, c]])


@dataclass(frozen=True, slots=True)
class FrictionTensor:
    """Anisotropic dry-friction tensor 𝔽 = [[fx, f], [−f, fy]] (paper eq. 2).

    Parameters
    ----------
    fx, fy : float
        Friction coefficients along the tensor's principal axes (dimensionless), in
        [1e-6, 5].
    f : float, default 0
        Skew coefficient (dimensionless), in [-5, 5].
    frame : {"plane", "body"}, default "plane"
        Whether the tensor is fixed to the plane (as in the paper) or turns with the body.
    angle : float, default 0
        Angle [rad] of the principal axes from OX (plane frame) or from the body axis Cξ
        (body frame), in [−2π, 2π] (the axes repeat every π; a larger number is refused
        as a likely angle in degrees: give ``angle_deg`` then).
    angle_deg : float, optional (keyword)
        The same angle in degrees, in [−360, 360] (the ``angle_deg`` key of case files);
        give exactly one of ``angle`` and ``angle_deg``. Stored as ``angle`` [rad];
        ``tensor.angle_deg`` reads it back in degrees.
    static : float, default 1 (keyword)
        μs/μk, in [1, 100]: at rest the tensor holds ``static`` times its kinetic set of
        wrenches (MODEL §14, "Static above kinetic"); the coefficients above are the kinetic
        ones. With a :class:`~slidespin.Stribeck` law the ratio is the law's
        ``static_ratio`` (give it there; ``static`` then reads it back).
    speed_law : PowerLaw, Stribeck, SpeedTable or None, default None (keyword)
        A factor g(|w|) of the local slip speed on the whole tensor (MODEL §14,
        :mod:`slidespin.contact.speed_laws`); None is the paper's constant law.

    Notes
    -----
    The ranges are what the wrench quadrature honours: its error target is absolute
    (1e-13 m g in :mod:`slidespin.analysis.terminal`), so it is met only for a tensor of bounded norm
    (up to about 10 on the thinnest valid patch, b/a = 1e-3) (measured: docs/errors.md, "Valid ranges"); coefficients below
    1e-6 stop a body only after 1e6 times the usual distance. Dry-friction coefficients of
    real materials lie between about 0.001 and 5.

    Examples
    --------
    >>> FrictionTensor(0.42, 0.54).mu
    0.12000000000000005
    >>> round(FrictionTensor(0.3, 0.4, angle_deg=90.0).angle, 12)
    1.570796326795
    """

    fx: float
    fy: float
    f: float = 0.0
    frame: str = "plane"
    angle: float = 0.0
    angle_deg: InitVar[float | None] = None
    static: float = 1.0
    speed_law: PowerLaw | Stribeck | SpeedTable | None = None

    def __post_init__(self, angle_deg: float | None = None) -> None:  # noqa: RUF033 - InitVar
        check_speed_law(self.speed_law)
        static = v.bounded("static", self.static, *STATIC_RATIO)
        if isinstance(self.speed_law, Stribeck):
            ratio = self.speed_law.static_ratio
            if static not in (1.0, ratio):
                raise ValueError(
                    f"static = {static!r} is invalid with speed_law = {self.speed_law!r}; valid "
                    f"values: 1 (the default) or the law's static_ratio = {ratio!r}, which "
                    "sets mu_s/mu_k"
                )
            static = ratio
        object.__setattr__(self, "static", static)
        object.__setattr__(self, "fx", v.bounded("fx", self.fx, *v.COEFFICIENT))
        object.__setattr__(self, "fy", v.bounded("fy", self.fy, *v.COEFFICIENT))
        f = v.finite("f", self.f)
        object.__setattr__(self, "f", v.symmetric("f", f, v.SKEW))
        object.__setattr__(self, "frame", v.choice("frame", self.frame, FRAMES))
        angle = v.finite("angle", self.angle)
        if not abs(angle) <= ANGLE_MAX:
            raise ValueError(
                f"angle = {angle!r} rad is invalid; valid range: [-{ANGLE_MAX:.6g}, "
                f"{ANGLE_MAX:.6g}] rad (|angle| <= 2π; the axes repeat every π); degrees? "
                f"give angle_deg={angle!r}"
            )
        if angle_deg is not None:
            deg = v.bounded("angle_deg", angle_deg, -360.0, 360.0, "deg")
            if angle != 0.0 and not math.isclose(angle, math.radians(deg), rel_tol=1e-12):
                raise ValueError(
                    f"FrictionTensor gives both angle = {angle!r} rad and angle_deg = {deg!r} "
                    "deg; valid values: exactly one of them (angle in rad or angle_deg in deg)"
                )
            angle = math.radians(deg)
        object.__setattr__(self, "angle", angle)
        top = static * max(self.fx, self.fy, abs(self.f))
        if static != 1.0 and top > v.COEFFICIENT[1]:
            raise ValueError(
                f"static = {static!r} is invalid for fx = {self.fx!r}, fy = {self.fy!r}, f = "
                f"{self.f!r}; valid range: [1, {v.COEFFICIENT[1] / top * static:.6g}] (the "
                f"static coefficients static*fx, static*fy, static*|f| must stay <= "
                f"{v.COEFFICIENT[1]:g})"
            )

    @classmethod
    def from_degrees(
        cls, fx: float, fy: float, f: float = 0.0, frame: str = "plane", angle_deg: float = 0.0
    ) -> FrictionTensor:
        """The tensor with its principal axes turned by ``angle_deg`` degrees."""
        return cls(fx, fy, f, frame, angle_deg=angle_deg)

    @classmethod
    def isotropic(cls, coefficient: float) -> FrictionTensor:
        """Isotropic Coulomb friction with the given coefficient (in [1e-6, 5])."""
        c = v.bounded("coefficient", coefficient, *v.COEFFICIENT)
        return cls(c, c)

    def __repr__(self) -> str:
        extra = ""
        if self.static != 1.0 and not isinstance(self.speed_law, Stribeck):
            extra += f", static={self.static!r}"
        if self.speed_law is not None:
            extra += f", speed_law={self.speed_law!r}"
        return (
            f"FrictionTensor(fx={self.fx!r}, fy={self.fy!r}, f={self.f!r}, "
            f"frame={self.frame!r}, angle={self.angle!r}{extra})"
        )

    @property
    def is_constant(self) -> bool:
        """True if the tensor is the paper's: one coefficient at rest and at every speed
        (``static`` = 1 and no speed law, or a law whose factor is 1 everywhere)."""
        return self.static == 1.0 and law_is_constant(self.speed_law)

    @property
    def kinetic(self) -> FrictionTensor:
        """The same tensor with the constant law and no static excess (the coefficients as
        given)."""
        if self.static == 1.0 and self.speed_law is None:
            return self
        return FrictionTensor(self.fx, self.fy, self.f, self.frame, self.angle)

    @property
    def static_tensor(self) -> FrictionTensor:
        """The constant tensor whose set of wrenches holds a body at rest: the coefficients
        times ``static`` (MODEL §14)."""
        if self.static == 1.0 and self.speed_law is None:
            return self
        r = self.static
        return FrictionTensor(r * self.fx, r * self.fy, r * self.f, self.frame, self.angle)

    @property
    def mu(self) -> float:
        """Anisotropy μ = fy − fx used by the paper."""
        return self.fy - self.fx

    @property
    def matrix(self) -> NDArray[np.float64]:
        """2×2 tensor in its own frame (plane or body), principal axes turned by ``angle``."""
        base = np.array([[self.fx, self.f], [-self.f, self.fy]])
        if self.angle == 0.0:
            return base
        r = _rot(self.angle)
        return r @ base @ r.T

    def world_matrix(self, phi: float = 0.0) -> NDArray[np.float64]:
        """2×2 tensor in the fixed frame OXY when the body angle is ``phi`` [rad]."""
        m = self.matrix
        if self.frame == "body":
            r = _rot(phi)
            m = r @ m @ r.T
        return m

    @property
    def norm(self) -> float:
        """Spectral norm of the tensor (largest traction per unit pressure)."""
        return float(np.linalg.norm(self.matrix, 2))


# ``angle_deg`` is an init-only argument; on an instance it reads the angle in degrees. (A
# dataclass InitVar has no class attribute that mypy knows of, so it cannot see this one.)
FrictionTensor.angle_deg = property(  # type: ignore[attr-defined]
    lambda self: math.degrees(self.angle), doc="``angle`` in degrees (read-only)."
)
