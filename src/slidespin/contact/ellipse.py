"""The elliptic contact patch of the paper (its circle is :class:`slidespin.Disk`, also named
``Circle``).

Paper symbols and code names (MODEL §1):

=========  ==========================  =====================
paper      meaning                     code
=========  ==========================  =====================
a, b       semi-axes (a along ξ)       ``Ellipse.a``, ``Ellipse.b``
e          eccentricity √(1 − b²/a²)   ``Ellipse.eccentricity``
κ          b/a = √(1 − e²)             ``Ellipse.aspect``
=========  ==========================  =====================

The patch is centred at the body-frame origin C; the body axis ξ runs along ``a``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

from slidespin import _validate as v

if TYPE_CHECKING:
    import numpy as np
    from numpy.typing import NDArray

__all__ = ["Ellipse", "Patch"]

_E_MAX = 0.999999  # b/a = 1.41e-3, just inside the thinnest valid patch (b/a = 1e-3)


def _check_aspect(a: float, b: float) -> None:
    k = b / a
    lo, hi = v.ASPECT
    if not lo <= k <= hi:
        hint = " (for b > a, swap the axes and turn the body by 90 deg)" if k > hi else ""
        raise ValueError(
            f"b/a = {k:.6g} (a = {a!r} m, b = {b!r} m) is invalid; valid range: "
            f"[{lo:g}, {hi:g}]: the wrench quadrature cannot reach its error target "
            f"beyond it{hint}"
        )


@dataclass(frozen=True, slots=True)
class Ellipse:
    """Elliptic contact patch with semi-axes ``a`` (along the body axis ξ) and ``b`` (along η).

    Parameters
    ----------
    a : float
        Semi-axis along ξ [m], in [1e-9, 1e6].
    b : float
        Semi-axis along η [m], in [1e-9, 1e6], with b/a in [1e-3, 30]. ``b > a`` is allowed
        (the long axis is then η).

    Notes
    -----
    The compiled wrench works in units of a and meets its error target (1e-13 m g, m g a)
    for 1e-3 ≤ b/a ≤ 30 only (measured: docs/errors.md, "Valid ranges"); outside it the
    patch is refused. A patch with b > 30 a is the same patch with the axes swapped: give
    ``Ellipse(b, a)`` and turn the body (and a body-fixed tensor) by 90°.

    Examples
    --------
    >>> Ellipse.from_eccentricity(0.1, 0.866).b  # doctest: +ELLIPSIS
    0.0500...
    """

    a: float
    b: float

    def __post_init__(self) -> None:
        a = v.bounded("a", self.a, *v.LENGTH, "m")
        b = v.bounded("b", self.b, *v.LENGTH, "m")
        _check_aspect(a, b)
        object.__setattr__(self, "a", a)
        object.__setattr__(self, "b", b)

    @classmethod
    def from_eccentricity(cls, a: float, eccentricity: float) -> Ellipse:
        """Ellipse with semi-major axis ``a`` [m] along ξ and eccentricity ``e`` in [0, e_max].

        e_max = 0.999999 (b/a = 1.41e-3): the thinnest patch the wrench quadrature
        honours has b/a = 1e-3 (see :class:`Ellipse`); for thinner ones give ``a`` and ``b``.

        Notes
        -----
        b = κ a with κ = √(1 − e²) (paper eq. 7).
        """
        a = v.bounded("a", a, *v.LENGTH, "m")
        e = v.bounded("eccentricity", eccentricity, 0.0, _E_MAX)
        b = a * math.sqrt(1.0 - e * e)
        if b < v.LENGTH[0]:
            raise ValueError(
                f"eccentricity = {e!r} with a = {a!r} m gives b = a sqrt(1 - e^2) = {b:.6g} m; "
                f"valid range: b in [{v.LENGTH[0]:g}, {v.LENGTH[1]:g}] m"
            )
        return cls(a, b)

    @property
    def aspect(self) -> float:
        """κ = b/a (dimensionless)."""
        return self.b / self.a

    @property
    def eccentricity(self) -> float:
        """Eccentricity of the patch, measured on its longer axis (0 for a circle)."""
        lo, hi = sorted((self.a, self.b))
        return math.sqrt(1.0 - (lo / hi) ** 2)

    @property
    def area(self) -> float:
        """Patch area π a b [m²]."""
        return math.pi * self.a * self.b

    def plate_inertia_ratio(self) -> float:
        """I/(m a²) of a uniform plate of this shape: (1 + κ²)/4 (MODEL §1)."""
        return (1.0 + self.aspect**2) / 4.0

    def outline(self, n: int = 181) -> NDArray[np.float64]:
        """Body-frame outline points (ξ, η) [m], shape (n, 2), closed; n in [2, 1e6]."""
        import numpy as np

        if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or not 2 <= n <= 10**6:
            raise ValueError(f"n = {v._short(n)} is invalid; valid range: integer in [2, 1000000]")

        t = np.linspace(0.0, 2.0 * np.pi, n)
        return np.column_stack((self.a * np.cos(t), self.b * np.sin(t)))


Patch = Ellipse
