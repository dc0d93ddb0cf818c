"""Normal-pressure laws on the contact patch (MODEL §3).

Every law is normalised so that the pressure integrates to the normal load P = m g over the
patch, for ellipses and circles alike. With q = ξ²/a² + η²/b²:

==========  ===============================================  ==========================
law         p(ξ, η)                                          paper
==========  ===============================================  ==========================
uniform     P/(π a b)                                        §2.1
linear      P/(π a b) · (1 + 4 ξc ξ/a² + 4 ηc η/b²)          eq. 10 (corrected, erratum 5)
Boussinesq  P/(2π a b) · (1 − q)^(−1/2)                       appendix
Hertz       3P/(2π a b) · (1 − q)^(1/2)                       appendix (erratum 8)
==========  ===============================================  ==========================

Departures from the paper: eq. 10 prints p₁ = Pξc/I_ηη with the *mass* moments of inertia;
the pressure centroid lies at (ξc, ηc) only with the *area* moments πa³b/4 and πab³/4, i.e.
p₁ = 4p₀ξc/a², p₂ = 4p₀ηc/b² (MODEL §7, erratum 5). The appendix's Hertz p₀ = 3mg/(2πa) lacks
a factor 1/a (erratum 8). For the linear law the mass centre G lies above the pressure
centroid (ξc, ηc) so that the body does not tip; for the other laws G is the patch centre C.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar, Protocol

import numpy as np
from numpy.typing import ArrayLike, NDArray

from slidespin import _validate as v
from slidespin.contact.ellipse import Ellipse
from slidespin.contact.shapes import Disk

__all__ = [
    "UniformPressure",
    "LinearPressure",
    "BoussinesqPressure",
    "HertzPressure",
    "PressureLaw",
    "pressure_law_from_name",
    "LAW_NAMES",
]

# integer codes understood by the compiled kernel
LAW_UNIFORM, LAW_LINEAR, LAW_BOUSSINESQ, LAW_HERTZ = 0, 1, 2, 3
#: the names of the pressure laws, in the order of their integer codes ``LAW_*``
LAW_NAMES = ("uniform", "linear", "boussinesq", "hertz")


class _SemiAxes(Protocol):
    """A patch with semi-axes a, b [m]: an ellipse or a circle (or a ``Disk``, which is one)."""

    @property
    def a(self) -> float: ...

    @property
    def b(self) -> float: ...


class _Law:
    __slots__ = ()

    code: ClassVar[int]
    name: ClassVar[str]

    @property
    def centroid(self) -> tuple[float, float]:
        """Pressure centroid (= mass centre G) in the body frame [m]."""
        return (0.0, 0.0)

    def check_patch(self, patch: _SemiAxes) -> None:  # noqa: D401 - overridden where it matters
        """Raise ``ValueError`` if this law is not valid on ``patch``."""

    def density(
        self, patch: Ellipse, xi: ArrayLike, eta: ArrayLike, load: float = 1.0
    ) -> NDArray[np.float64]:
        """Pressure p(ξ, η) [Pa] at body-frame points (arrays allowed); 0 outside the patch.

        Parameters
        ----------
        patch : Ellipse or Circle
            The contact patch (a ``Circle``, i.e. a ``Disk`` centred at the origin, is the
            ellipse with a = b).
        xi, eta : array_like
            Body-frame coordinates [m], finite.
        load : float
            Normal load P = m g [N], in [0, 1e300].
        """
        if isinstance(patch, Disk) and patch.centre == (0.0, 0.0):  # a Circle: a = b
            patch = Ellipse(patch.outer_radius, patch.outer_radius)
        if not isinstance(patch, Ellipse):
            raise ValueError(
                f"patch = {v._short(patch)} is invalid; valid values: an Ellipse, or a Circle "
                "(a Disk centred at the origin); for any footprint use "
                "slidespin.contact.pressure_map.density"
            )
        xi = v.real_array("xi", xi)
        eta = v.real_array("eta", eta)
        load = v.bounded("load", load, 0.0, 1e300, "N")
        try:
            xi, eta = np.broadcast_arrays(xi, eta)
        except ValueError:
            raise ValueError(
                f"xi, eta have shapes {xi.shape}, {eta.shape} that do not broadcast together; "
                "valid values: arrays of one shape (or a scalar and an array)"
            ) from None
        with np.errstate(over="ignore"):  # far outside: q = inf, p = 0
            q = (xi / patch.a) ** 2 + (eta / patch.b) ** 2
        inside = q < 1.0
        p = np.where(inside, self._shape(patch, xi, eta, np.minimum(q, 1.0)), 0.0)
        return load / (math.pi * patch.a * patch.b) * p

    def _shape(self, patch, xi, eta, q):  # pragma: no cover - abstract
        raise NotImplementedError


@dataclass(frozen=True, slots=True)
class UniformPressure(_Law):
    """Uniform pressure P/(π a b) (paper §2.1)."""

    code: ClassVar[int] = LAW_UNIFORM
    name: ClassVar[str] = "uniform"

    def _shape(self, patch, xi, eta, q):
        return np.ones_like(q)


@dataclass(frozen=True, slots=True)
class LinearPressure(_Law):
    """Linear pressure with its centroid, and the mass centre G, at (ξc, ηc) (paper eq. 10).

    Parameters
    ----------
    xi_c, eta_c : float
        Body-frame coordinates of the pressure centroid = mass centre [m], same length units
        as the patch, finite with magnitude at most 2.5e5 m (a quarter of the largest patch). The pressure stays non-negative on the patch only if
        (ξc/a)² + (ηc/b)² ≤ 1/16; this is checked when the law is combined with a patch
        (:class:`slidespin.Body`).

    Notes
    -----
    p = P/(πab) (1 + 4ξc ξ/a² + 4ηc η/b²): eq. 10 with the area moments of the ellipse
    (MODEL §7, erratum 5).
    """

    xi_c: float = 0.0
    eta_c: float = 0.0
    code: ClassVar[int] = LAW_LINEAR
    name: ClassVar[str] = "linear"

    def __post_init__(self) -> None:
        for name in ("xi_c", "eta_c"):
            x = v.finite(name, getattr(self, name))
            # the core of a valid patch lies within a/4 <= 2.5e5 m of its centre
            object.__setattr__(self, name, v.symmetric(name, x, v.LENGTH[1] / 4.0, "m"))

    @property
    def centroid(self) -> tuple[float, float]:
        """Pressure centroid (= mass centre G) in the body frame [m]: (ξc, ηc)."""
        return (self.xi_c, self.eta_c)

    def core_measure(self, patch: _SemiAxes) -> float:
        """(ξc/a)² + (ηc/b)²; the pressure is non-negative iff this is ≤ 1/16."""
        return (self.xi_c / patch.a) ** 2 + (self.eta_c / patch.b) ** 2

    def check_patch(self, patch: _SemiAxes) -> None:
        """Raise ``ValueError`` unless p ≥ 0 on the ellipse ``patch`` (the centroid lies in its
        core, (ξc/a)² + (ηc/b)² ≤ 1/16; MODEL §3)."""
        c = self.core_measure(patch)
        if c > 1.0 / 16.0 * (1.0 + 1e-12):
            raise ValueError(
                f"LinearPressure centroid (xi_c, eta_c) = ({self.xi_c!r}, {self.eta_c!r}) m lies "
                f"outside the core of the patch (a={patch.a!r}, b={patch.b!r}): "
                f"(xi_c/a)^2 + (eta_c/b)^2 = {c:.6g}; valid range: [0, 0.0625] "
                "(otherwise the pressure turns negative)"
            )

    def _shape(self, patch, xi, eta, q):
        return 1.0 + 4.0 * self.xi_c * xi / patch.a**2 + 4.0 * self.eta_c * eta / patch.b**2


@dataclass(frozen=True, slots=True)
class BoussinesqPressure(_Law):
    """Boussinesq (rigid flat punch) pressure P/(2πab) (1 − q)^(−1/2) (paper appendix)."""

    code: ClassVar[int] = LAW_BOUSSINESQ
    name: ClassVar[str] = "boussinesq"

    def _shape(self, patch, xi, eta, q):
        with np.errstate(divide="ignore"):
            return 0.5 / np.sqrt(1.0 - q)


@dataclass(frozen=True, slots=True)
class HertzPressure(_Law):
    """Hertz pressure 3P/(2πab) (1 − q)^(1/2) (paper appendix, erratum 8)."""

    code: ClassVar[int] = LAW_HERTZ
    name: ClassVar[str] = "hertz"

    def _shape(self, patch, xi, eta, q):
        return 1.5 * np.sqrt(1.0 - q)


#: the type of a pressure law on an ellipse (a footprint also takes a PressureMap)
PressureLaw = UniformPressure | LinearPressure | BoussinesqPressure | HertzPressure


def pressure_law_from_name(name: str, **params: float) -> PressureLaw:
    """Build a pressure law from its name (``uniform``, ``linear``, ``boussinesq``, ``hertz``).

    Parameters
    ----------
    name : str
        Law name, case-insensitive.
    **params : float
        ``xi_c`` and ``eta_c`` [m] for the linear law; none for the others.
    """
    key = v.choice("pressure law", name, LAW_NAMES)
    cls = {
        "uniform": UniformPressure,
        "linear": LinearPressure,
        "boussinesq": BoussinesqPressure,
        "hertz": HertzPressure,
    }[key]
    allowed = {"linear": ("xi_c", "eta_c")}.get(key, ())
    unknown = sorted(set(params) - set(allowed))
    if unknown:
        raise ValueError(
            f"pressure law {key!r} takes no parameter {unknown[0]!r}; valid parameters: "
            + (", ".join(allowed) if allowed else "none")
        )
    return cls(**params)
