"""The sliding body: its contact patch, pressure law, mass and moment of inertia.

Paper symbols and code names (MODEL §1): m → ``mass``, I → ``moment_of_inertia`` (about the
vertical axis through the mass centre G), I* = I/(m a²) → ``inertia_ratio``. The body lives
with the contact (not with the motion, whose state is :class:`slidespin.State`): the wrench,
the static-friction set and the limit surface are functions of the patch, of G above it and
of the load m g.

Beyond the paper (MODEL §10) the patch may be any footprint of :mod:`slidespin.contact.shapes`
(``Polygon``, ``Rectangle``, ``Disk``, ``Annulus``, ``Pads``) under uniform or linear
pressure, or a ``Blade`` (a line contact) under a uniform line load. A ``Disk`` (placed
anywhere) also takes the Boussinesq and Hertz laws, which are defined on circles (MODEL §3,
§10): it is then the circle of its radius with G at its centre, and runs on the elliptic
engine exactly like ``Ellipse(radius, radius)``. ``Circle`` is another name of ``Disk``: the
paper's circle under uniform or linear pressure runs on the exact disk kernel; give
``Ellipse(r, r)`` for the paper's own engine (its quadrature, as ``slidespin reproduce`` does). The length unit ℓ (:attr:`Body.length_unit`, the
footprint's ``extent``: the radius of a disk or ring, the half-diagonal of a centred
rectangle, half a blade) plays the role of the ellipse's semi-axis a in I* = I/(m ℓ²), β*/ℓ
and the natural units of the integrator.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from slidespin import _validate as v
from slidespin.contact import _engine
from slidespin.contact import shapes as _fp
from slidespin.contact.ellipse import Ellipse
from slidespin.contact.friction import FrictionTensor
from slidespin.contact.pressure import (
    BoussinesqPressure,
    HertzPressure,
    LinearPressure,
    PressureLaw,
    UniformPressure,
)
from slidespin.contact.pressure_map import (
    PressureMap,
    footprint_law_error,
    kernel_geometry,
    map_scale,
    pressure_coefficients,
    round_law,
    scaled_arrays,
    symmetry,
)
from slidespin.contact.pressure_map import mass_centre as pressure_centroid
from slidespin.contact.speed_laws import law_is_constant

__all__ = ["Body", "check_body_friction", "require_thin"]

_LAWS = (UniformPressure, LinearPressure, BoussinesqPressure, HertzPressure)
#: how many friction tensors' :meth:`Body.engine_params` a body keeps (oldest dropped first)
ENGINE_CACHE = 8


@dataclass(frozen=True, slots=True)
class Body:
    """A flat rigid body resting on its contact patch.

    Parameters
    ----------
    patch : Ellipse or a footprint
        The contact patch: an ellipse (the paper's), or a footprint of
        :mod:`slidespin.contact.shapes` (``Polygon``, ``Rectangle``, ``Disk``, ``Annulus``,
        ``Pads``, ``Blade``; MODEL §10). Every patch, a ``Blade`` (a line contact) included,
        works with every feature: :func:`slidespin.friction_wrench`, :func:`slidespin.simulate`
        (also under loads and on slopes, with static friction), ``simulate_many``, the
        terminal analysis, the statics (:func:`slidespin.can_stick`, ``load_factor``,
        ``onset``, ``critical_tilt``), the limit surface and ``fit``, for any friction tensor.
    pressure : UniformPressure, LinearPressure, BoussinesqPressure, HertzPressure or PressureMap
        Normal-pressure law on the patch. The mass centre G lies above the pressure
        centroid: the patch centre (the area centroid of a footprint), or (ξc, ηc) for the
        linear law. Area footprints take the uniform and linear laws (the linear law must
        stay ≥ 0 on the footprint), a ``Blade`` ``UniformPressure()`` only (a uniform line
        load, G over its centre); a ``Disk`` also takes ``BoussinesqPressure()`` and
        ``HertzPressure()`` (G at the disk's centre; the body is then the circle of that
        radius, run by the elliptic engine: :attr:`is_footprint` is False); a user
        ``PressureMap`` on an area footprint (G at its centroid) works with
        :func:`slidespin.friction_wrench` only: simulation, statics and terminal analysis need
        a compiled kernel and refuse it with a ``ValueError``.
    mass : float
        Mass m [kg], in [1e-12, 1e12].
    moment_of_inertia : float or None
        I about the vertical axis through G [kg m²], with I* = I/(m ℓ²) in [1e-8, 1e8]
        (docs/errors.md, "Valid ranges"; ℓ = :attr:`length_unit`). ``None`` means the
        inertia of a uniform plate of the patch's shape about its centre: I = m (a² + b²)/4
        for an ellipse (and m R²/2 for a disk under Boussinesq or Hertz pressure), the paper's
        I* = (1 + κ²)/4 (eq. 7); ``patch.plate_inertia(mass)`` (m L²/12 for a blade)
        for a footprint, about its area centroid (for ``Pads`` a plate covering the pads
        only, with no mass between them: give I explicitly for a sled or a chair). For the
        linear law, whose G is off-centre, give I explicitly if the body is not such a plate.
    height : float, default 0
        Height h of the mass centre above the plane [m], in [0, 1e6] (MODEL §14; a
        principal axis of inertia vertical). 0 is the paper's thin body. A tall body shifts
        its pressure: the friction force, acting in the plane, and loads applied at other
        heights (``Load(..., height=)``) tilt it, so the pressure centroid moves to
        r_p = r_G − [h F + Σ (h − h_Q) Q]/P; where the linear law would turn negative the
        footprint lifts off, and the body tips when r_p reaches the footprint's convex hull
        (:mod:`slidespin.contact.tall`). Works with the uniform and the linear law on an
        ellipse or an area footprint (not a ``Blade``: a line contact has no width to resist
        tipping), in the loaded engine (:func:`slidespin.simulate` takes a tall body on its
        Python path) and the statics; lift-off works on area footprints (a disk's or a
        ring's circles clipped as polygons of 16384 sides), not on an ``Ellipse`` patch.

    Examples
    --------
    >>> from slidespin import Ellipse, UniformPressure
    >>> body = Body(Ellipse(0.1, 0.05), UniformPressure(), mass=2.0)
    >>> round(body.inertia_ratio, 4)
    0.3125
    >>> from slidespin import Annulus
    >>> ring = Body(Annulus(0.05, 0.06), UniformPressure(), mass=1.0)
    >>> round(ring.inertia_ratio, 4)  # (R² + r²)/(2 R²) in units of ℓ = R
    0.8472
    """

    patch: Ellipse | _fp.Footprint
    pressure: PressureLaw
    mass: float
    moment_of_inertia: float | None = None
    height: float = 0.0
    # engine_params per friction tensor (the object is immutable; see engine_params)
    _cache: dict | None = field(default=None, init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        patch = self.patch
        if not (_fp.is_footprint(patch) or isinstance(patch, Ellipse)):
            raise ValueError(
                f"patch = {patch!r} is invalid; valid values: an Ellipse or a Circle, or a "
                "footprint (Polygon, Rectangle, Disk, Annulus, Pads, Blade)"
            )
        footprint = _fp.is_footprint(patch) and not round_law(patch, self.pressure)
        if footprint:
            if isinstance(self.pressure, PressureMap) and not isinstance(patch, _fp.Blade):
                map_scale(patch, self.pressure)  # raises for a map < 0, non-finite or zero
            elif not isinstance(self.pressure, (UniformPressure, LinearPressure)):
                raise ValueError(footprint_law_error(patch, self.pressure))
            else:
                pressure_coefficients(patch, self.pressure)  # raises where p < 0
        elif not isinstance(self.pressure, _LAWS):
            raise ValueError(
                f"pressure = {self.pressure!r} is invalid; valid values: UniformPressure(), "
                "LinearPressure(xi_c, eta_c), BoussinesqPressure(), HertzPressure()"
            )
        elif isinstance(patch, (Ellipse, _fp.Disk)):  # an ellipse, or a disk: a circle
            self.pressure.check_patch(patch)
        m = v.bounded("mass", self.mass, *v.MASS, "kg")
        object.__setattr__(self, "mass", m)
        a = _length_unit(patch)
        lo, hi = v.INERTIA_RATIO
        unit = "extent" if footprint else "a"
        if self.moment_of_inertia is None:
            if isinstance(patch, Ellipse) or (isinstance(patch, _fp.Disk) and not footprint):
                inertia = m * (a**2 + patch.b**2) / 4.0
            else:
                inertia = patch.plate_inertia(m)
                # the default plate inertia obeys the same I* range as a given one (a
                # footprint's second moment may under- or overflow, or be far off the scale)
                with np.errstate(all="ignore"):
                    i_star = inertia / m / a / a
                if not (
                    math.isfinite(inertia)
                    and inertia > 0.0
                    and lo * (1.0 - 1e-12) <= i_star <= hi * (1.0 + 1e-12)
                ):
                    raise ValueError(
                        f"patch = {v._short(self.patch, 100)} is invalid with mass = {m!r} kg: its plate "
                        f"inertia I = {inertia!r} kg m^2 gives I/(m {unit}^2) = {i_star:.6g}; "
                        f"valid range: [{lo:g}, {hi:g}] (give moment_of_inertia explicitly)"
                    )
        else:
            inertia = v.positive("moment_of_inertia", self.moment_of_inertia, "kg m^2")
            i_star = inertia / m / a / a
            if not lo * (1.0 - 1e-12) <= i_star <= hi * (1.0 + 1e-12):  # round-off of I* m a²
                raise ValueError(
                    f"moment_of_inertia = {inertia!r} kg m^2 is invalid for mass = {m!r} kg and "
                    f"{unit} = {a!r} m: I/(m {unit}^2) = {i_star:.6g}; valid range: "
                    f"[{lo:g}, {hi:g}] m {unit}^2 = [{lo * m * a * a:.6g}, "
                    f"{hi * m * a * a:.6g}] kg m^2"
                )
        object.__setattr__(self, "moment_of_inertia", inertia)
        h = v.bounded("height", self.height, 0.0, v.LENGTH[1], "m")
        if h > 0.0:
            if isinstance(patch, _fp.Blade) or not isinstance(
                self.pressure, (UniformPressure, LinearPressure)
            ):
                raise ValueError(
                    f"height = {h!r} m is invalid for patch = {type(patch).__name__}(...) with "
                    f"pressure = {self.pressure!r}; valid values: height = 0, or a height > 0 "
                    "with UniformPressure() or LinearPressure(xi_c, eta_c) on an Ellipse or "
                    "an area footprint (a Blade, a line contact, cannot resist tipping)"
                )
        object.__setattr__(self, "height", h)

    def __getstate__(self):
        """The fields, without the engine-parameter cache (a pickled body stays small)."""
        return (self.patch, self.pressure, self.mass, self.moment_of_inertia, self.height)

    def __setstate__(self, state) -> None:
        names = ("patch", "pressure", "mass", "moment_of_inertia", "height")
        for name, value in zip(names, state):
            object.__setattr__(self, name, value)
        if len(state) < len(names):  # a body pickled before ``height`` existed
            object.__setattr__(self, "height", 0.0)
        object.__setattr__(self, "_cache", None)

    @classmethod
    def from_inertia_ratio(cls, patch, pressure, mass: float, inertia_ratio: float) -> Body:
        """Body with I = I* m ℓ² for a given dimensionless inertia I* in [1e-8, 1e8] (ℓ = a
        for an ellipse, the extent of a footprint: :attr:`length_unit`)."""
        i_star = v.bounded("inertia_ratio", inertia_ratio, *v.INERTIA_RATIO)
        m = v.bounded("mass", mass, *v.MASS, "kg")
        if not (isinstance(patch, Ellipse) or _fp.is_footprint(patch)):
            raise ValueError(
                f"patch = {patch!r} is invalid; valid values: an Ellipse or a Circle, or a "
                "footprint (Polygon, Rectangle, Disk, Annulus, Pads, Blade)"
            )
        return cls(patch, pressure, m, i_star * m * _length_unit(patch) ** 2)

    @property
    def is_footprint(self) -> bool:
        """True if the body runs on the footprint kernel: its patch is a footprint of
        :mod:`slidespin.contact.shapes`, except a ``Disk`` under Boussinesq or Hertz pressure,
        which is a circle and runs on the elliptic engine (False, as for an ellipse)."""
        return _fp.is_footprint(self.patch) and not round_law(self.patch, self.pressure)

    @property
    def length_unit(self) -> float:
        """ℓ [m]: the semi-axis a of an ellipse, the ``extent`` of a footprint (the largest
        distance from its area centroid to a point of it: R for a disk or ring). The unit of
        I* = I/(m ℓ²), of β*/ℓ and of the integrator's natural units."""
        return _length_unit(self.patch)

    @property
    def _inertia(self) -> float:
        """I [kg m²]: :attr:`moment_of_inertia`, which ``__post_init__`` always sets (the
        default plate inertia for ``None``), typed as a float."""
        inertia = self.moment_of_inertia
        assert inertia is not None  # set by __post_init__
        return inertia

    @property
    def inertia_ratio(self) -> float:
        """I* = I/(m ℓ²) (paper §3, appendix; ℓ = a for an ellipse)."""
        return self._inertia / (self.mass * self.length_unit**2)

    @property
    def radius_of_gyration(self) -> float:
        """k = √(I/m) [m]."""
        return math.sqrt(self._inertia / self.mass)

    @property
    def mass_centre(self) -> tuple[float, float]:
        """G in the body frame [m] (the pressure centroid)."""
        patch = self.patch
        if isinstance(patch, _fp.Disk) and round_law(patch, self.pressure):
            return (float(patch.centre[0]), float(patch.centre[1]))  # G over the disk's centre
        if not isinstance(patch, Ellipse):
            return pressure_centroid(patch, self.pressure)
        return self.pressure.centroid

    def kernel_params(self, friction: FrictionTensor, wrench_tol: float = 1e-12) -> np.ndarray:
        """Parameter vector of the compiled engine, in natural units (a = m = g = 1), for an
        elliptic patch; raises ``ValueError`` for a footprint (see :meth:`engine_params`), so
        that code written for ellipses refuses footprints clearly."""
        if self.is_footprint:
            raise ValueError(
                f"patch = {self.patch!r} is a footprint; this function supports elliptic "
                "patches only (an Ellipse, or a Disk under Boussinesq or Hertz pressure); "
                "valid here: such a patch. Footprints (a Blade too) work with every public "
                "function (simulate, also loaded, simulate_many, friction_wrench, the terminal "
                "analysis, the statics, limit_surface, fit); engine_params gives their arrays"
            )
        return self.engine_params(friction, wrench_tol)[0]

    def engine_params(self, friction: FrictionTensor, wrench_tol: float = 1e-12):
        """(par, edges, circles, geo): the compiled engine's parameter vector and footprint
        arrays in natural units (ℓ = m = g = 1, ℓ = :attr:`length_unit`).

        For an ellipse the arrays are empty (0, 4) and ``geo`` is zeros (unused); for a
        footprint they are :func:`slidespin.contact.pressure_map.scaled_arrays` and
        :func:`~slidespin.contact.pressure_map.kernel_geometry` in units of ℓ, unit load, and
        ``par`` carries the shape flag and the symmetry flags of
        :func:`slidespin.contact.pressure_map.symmetry` (MODEL §9–10).

        Computed once per friction tensor (its fx, fy, f, frame and angle) and
        ``wrench_tol``, and kept on the body (the last ``ENGINE_CACHE`` of them): every
        call returns fresh copies, which the caller may change without touching the cache.
        """
        if not isinstance(friction, FrictionTensor):
            raise ValueError(
                f"friction = {v._short(friction)} is invalid; valid values: a FrictionTensor"
            )
        require_constant_law(friction, "this function")
        tol = v.finite("wrench_tol", wrench_tol)
        key = (friction.fx, friction.fy, friction.f, friction.frame, friction.angle, tol)
        cache = self._cache
        if cache is None:
            cache = {}
            object.__setattr__(self, "_cache", cache)
        got = cache.get(key)
        if got is None:
            got = self._engine_params(friction, tol)
            for arr in got:
                arr.flags.writeable = False  # the cached copy is never handed out
            while len(cache) >= ENGINE_CACHE:
                cache.pop(next(iter(cache)))
            cache[key] = got
        return tuple(arr.copy() for arr in got)

    def _engine_params(self, friction: FrictionTensor, wrench_tol: float):
        """:meth:`engine_params`, computed."""
        if isinstance(self.pressure, PressureMap):
            raise ValueError(
                f"pressure = {self.pressure!r} works with friction_wrench only (an adaptive "
                "quadrature, not a compiled kernel); valid values for simulation, statics and "
                "terminal analysis: UniformPressure(), LinearPressure(xi_c, eta_c)"
            )
        t = friction.matrix
        patch = self.patch
        if self.is_footprint and not isinstance(patch, Ellipse):  # the footprint kernel
            ell = self.length_unit
            arrays = patch.to_arrays()
            sc = scaled_arrays(arrays, ell)
            geo = kernel_geometry(patch, self.pressure, arrays, length=ell)
            central, axial = symmetry(patch, self.pressure)
            par = np.zeros(_engine.NPAR)
            par[_engine.P_BN] = 1.0  # (the ellipse kernel's constants: valid, unused)
            par[_engine.P_T00], par[_engine.P_T01] = t[0]
            par[_engine.P_T10], par[_engine.P_T11] = t[1]
            par[_engine.P_BODY] = 1.0 if friction.frame == "body" else 0.0
            par[_engine.P_K] = self.radius_of_gyration / ell
            par[_engine.P_WTOL] = wrench_tol
            par[_engine.P_SHAPE] = _engine.SHAPE_FOOTPRINT
            par[_engine.P_CSYM] = 1.0 if central else 0.0
            par[_engine.P_RSYM] = 1.0 if axial else 0.0
            return (
                par,
                np.ascontiguousarray(sc.edges),
                np.ascontiguousarray(sc.circles),
                np.ascontiguousarray(geo),
            )
        assert isinstance(patch, (Ellipse, _fp.Disk))  # an ellipse, or a disk: a circle
        a = patch.a
        # G relative to the ellipse's centre (a disk under Boussinesq or Hertz: its centre)
        xg, yg = self.pressure.centroid
        par = np.empty(_engine.NPAR)
        par[_engine.P_BN] = patch.b / a
        par[_engine.P_LAW] = self.pressure.code
        par[_engine.P_XG] = xg / a
        par[_engine.P_YG] = yg / a
        par[_engine.P_T00], par[_engine.P_T01] = t[0]
        par[_engine.P_T10], par[_engine.P_T11] = t[1]
        par[_engine.P_BODY] = 1.0 if friction.frame == "body" else 0.0
        par[_engine.P_K] = self.radius_of_gyration / a
        par[_engine.P_WTOL] = wrench_tol
        par[_engine.P_SHAPE] = _engine.SHAPE_ELLIPSE
        par[_engine.P_CSYM] = 0.0
        par[_engine.P_RSYM] = 0.0
        return (par,) + _engine.no_footprint()


def _length_unit(patch: Ellipse | _fp.Footprint) -> float:
    """ℓ: the semi-axis a of an ellipse, the extent of a footprint [m] (the radius of a disk,
    its a, whatever the pressure law)."""
    return patch.a if isinstance(patch, Ellipse) else float(patch.extent)


def require_constant_law(friction: FrictionTensor, feature: str) -> None:
    """A ``ValueError`` naming ``speed_law`` if the tensor has a speed-dependent law
    (MODEL §14) and ``feature`` does not take one yet."""
    if not law_is_constant(friction.speed_law):
        raise ValueError(
            f"speed_law = {friction.speed_law!r} is not available in {feature} yet; valid "
            "values: speed_law=None. Speed-dependent laws work with friction_wrench, "
            "footprint_wrench, simulate (free motion; Stribeck and SpeedTable laws also "
            "under loads, slopes and springs) and the static set (can_stick, load_factor, "
            "critical_tilt, support_function, which use the static ratio)"
        )


def require_thin(body, feature: str) -> None:
    """A ``ValueError`` naming ``height`` if the body is tall (MODEL §14) and ``feature``
    does not take tall bodies yet."""
    if getattr(body, "height", 0.0) > 0.0:
        raise ValueError(
            f"height = {body.height!r} m is not available in {feature} yet; valid values: "
            "height = 0. Tall bodies work with simulate (free, loaded, on slopes: the Python "
            "path of the stick-slip engine), the statics (can_stick, load_factor, onset, "
            "breakaway) and pressure_centre"
        )


def check_body_friction(body, friction, *, elliptic_only: str | None = None) -> None:
    """Raise ``ValueError`` unless ``body`` is a :class:`Body` and ``friction`` a
    :class:`~slidespin.FrictionTensor`; with ``elliptic_only`` (the name of the feature), also
    unless the body rests on an ellipse (the feature does not take footprints yet).
    """
    if not isinstance(body, Body):
        raise ValueError(f"body = {body!r} is invalid; valid values: a slidespin.Body")
    if not isinstance(friction, FrictionTensor):
        raise ValueError(f"friction = {friction!r} is invalid; valid values: a FrictionTensor")
    if elliptic_only and body.is_footprint:
        raise ValueError(
            f"body.patch = {type(body.patch).__name__}(...) is not supported by {elliptic_only} "
            "yet; valid values: an Ellipse patch"
        )
