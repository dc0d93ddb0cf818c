"""Normal pressure on any footprint (MODEL §10): uniform, linear, or a user map.

Every law is normalised to the load P = m g: ∫_Ω p dS = P. The mass centre G lies above the
pressure centroid ∫ p r dS / P (so that the body rests without tipping).

==================================  ==============================================================
law                                 p(ξ, η) on the footprint Ω
==================================  ==============================================================
``UniformPressure()``               P/A                              (G = area centroid r_c)
``LinearPressure(xi_c, eta_c)``     (P/A)(1 + gᵀ(r − r_c)),  J g = A (r_G − r_c)  (G = (ξc, ηc))
``PressureMap(function)``           P · f(ξ, η)/∫_Ω f dS              (G = its centroid)
``PressureMap.from_grid(...)``      the same with f the bicubic spline through sampled values
==================================  ==============================================================

with A = |Ω|, r_c the area centroid and J = ∫(r − r_c)(r − r_c)ᵀ dS (each footprint's
``second_moment``).
For an ellipse the linear law is the paper's eq. 10 (corrected, MODEL §7 erratum 5); for three
small pads it gives their statically determined loads. ``UniformPressure`` and
``LinearPressure`` are the value objects of :mod:`slidespin.contact.pressure`; here they are applied to
any footprint. The linear law must be ≥ 0 on Ω: it is linear, so its minimum lies at a
polygon vertex or at the point of a disk's rim farthest down its gradient, where it is
checked exactly. A user map is checked at its quadrature nodes (:func:`area_rule`).
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from slidespin import _validate as v
from slidespin.contact._kernel_footprint import NGEO
from slidespin.contact.ellipse import Ellipse
from slidespin.contact.footprint_arrays import FootprintArrays, linear_load
from slidespin.contact.pressure import (
    BoussinesqPressure,
    HertzPressure,
    LinearPressure,
    UniformPressure,
)
from slidespin.contact.shapes import (
    Annulus,
    Blade,
    Disk,
    Pads,
    Polygon,
    Rectangle,
    as_patches,
)

__all__ = [
    "PressureMap",
    "area_rule",
    "contains",
    "density",
    "kernel_geometry",
    "map_scale",
    "mass_centre",
    "pressure_coefficients",
    "scaled_arrays",
    "symmetry",
]

#: Gauss–Legendre order per triangle side and per ring direction of :func:`area_rule`
AREA_RULE_NODES = 24


def _check_footprint(fp, blade: bool = False) -> None:
    """Raise unless ``fp`` is an area footprint (or, with ``blade``, also a Blade)."""
    if blade and isinstance(fp, Blade):
        return
    if isinstance(fp, Blade):
        raise ValueError(
            f"footprint = {fp!r} is invalid here: a Blade is a line contact with no area "
            "(no areal pressure, quadrature or inside); valid values: Polygon, Rectangle, "
            "Disk, Annulus or Pads"
        )
    if not isinstance(fp, (Polygon, Rectangle, Annulus, Pads)):
        raise ValueError(
            f"footprint = {fp!r} is invalid; valid values: Polygon, Rectangle, Disk, Annulus, "
            "Pads or Blade"
        )


def _blade_law(footprint, pressure) -> bool:
    """True for a Blade under uniform (line) pressure; a ``ValueError`` for a Blade under any
    other law; False for every area footprint."""
    if not isinstance(footprint, Blade):
        return False
    if not isinstance(pressure, UniformPressure):
        raise ValueError(
            f"pressure = {pressure!r} is invalid on a Blade; valid values: UniformPressure() "
            "(a uniform line load; G over the blade's centre)"
        )
    return True


class _GridMap:
    """The bicubic interpolating spline through grid samples, as a picklable callable."""

    def __init__(self, xi, eta, values):
        from scipy.interpolate import RectBivariateSpline

        self.grid = (
            np.asarray(xi, dtype=float),
            np.asarray(eta, dtype=float),
            np.asarray(values, dtype=float),
        )
        self._spline = RectBivariateSpline(*self.grid, kx=3, ky=3, s=0)

    def __call__(self, xi, eta):
        xi = np.asarray(xi, dtype=float)
        eta = np.broadcast_to(np.asarray(eta, dtype=float), xi.shape)
        return self._spline.ev(xi.ravel(), eta.ravel()).reshape(xi.shape)

    def __reduce__(self):
        return (_GridMap, self.grid)

    def __repr__(self) -> str:
        x, y, _ = self.grid
        return f"<bicubic spline on a {x.size} x {y.size} grid>"


@dataclass(frozen=True, slots=True)
class PressureMap:
    """A user pressure map p(ξ, η), normalised to the load on the footprint it is used with.

    Parameters
    ----------
    function : callable
        ``function(xi, eta)`` takes two float arrays of equal shape (body-frame coordinates
        [m]) and returns the pressure at those points, any positive scale (it is normalised
        so that ∫_Ω p dS = P). It must be smooth and ≥ 0 on the footprint; its accuracy
        limits the wrench's (MODEL §10).

    Examples
    --------
    >>> pm = PressureMap(lambda xi, eta: 1.0 + 0.0 * xi)      # uniform
    >>> film = PressureMap.from_grid([0, 1, 2, 3], [0, 1, 2, 3], np.ones((4, 4)))
    """

    function: Callable

    def __post_init__(self) -> None:
        if not callable(self.function):
            raise ValueError(
                f"function = {self.function!r} is invalid; valid values: a callable p(xi, eta)"
            )

    @classmethod
    def from_grid(cls, xi, eta, values) -> PressureMap:
        """A map from samples on a rectangular grid (pressure film, finite-element output).

        Parameters
        ----------
        xi, eta : array_like, 1-D
            Strictly increasing grid coordinates [m], at least 4 each; the grid must cover
            the footprint.
        values : array_like, shape (len(xi), len(eta))
            Pressure samples (any positive scale), ``values[i, j]`` at (xi[i], eta[j]).

        Notes
        -----
        The map is the interpolating bicubic spline (``scipy.interpolate.RectBivariateSpline``,
        s = 0); outside the grid it is extrapolated, so the grid should cover the footprint.
        """
        x = v.real_array("xi", xi, unit="m")
        y = v.real_array("eta", eta, unit="m")
        z = v.real_array("values", values)
        for name, g in (("xi", x), ("eta", y)):
            if g.ndim != 1 or g.size < 4 or not np.all(np.isfinite(g)) or np.any(np.diff(g) <= 0):
                raise ValueError(
                    f"{name} = {v._short(g.tolist())} is invalid; valid values: at least 4 "
                    "finite, strictly increasing grid coordinates in m"
                )
        if z.shape != (x.size, y.size) or not np.all(np.isfinite(z)):
            raise ValueError(
                f"values has shape {z.shape} (or non-finite entries); valid values: finite "
                f"samples of shape ({x.size}, {y.size})"
            )
        return cls(_GridMap(x, y, z))

    def __call__(self, xi, eta):
        """The raw map at body-frame points: ``xi``, ``eta`` broadcast to one shape, and the
        function's values, a float array of that shape (a ``ValueError`` otherwise)."""
        xi, eta = _points(xi, eta)
        raw = self.function(xi, eta)
        try:
            f = np.asarray(raw, dtype=float)
        except (TypeError, ValueError):
            f = None
        if f is None or f.shape != xi.shape:
            if f is None or not isinstance(raw, np.ndarray):
                got = f"{v._short(raw)} ({type(raw).__name__})"
            else:
                got = f"an array of shape {f.shape}"
            raise ValueError(
                f"pressure map: function(xi, eta) returned {got} for inputs of shape "
                f"{xi.shape}; valid values: an array of real numbers of the inputs' shape "
                "(e.g. 1.0 + 0.0 * xi for a constant map)"
            )
        return f


def _points(xi, eta) -> tuple[np.ndarray, np.ndarray]:
    """``xi``, ``eta`` as float arrays of one (broadcast) shape, or a ``ValueError`` naming
    them."""
    xi = v.real_array("xi", xi, unit="m")
    eta = v.real_array("eta", eta, unit="m")
    try:
        xi, eta = np.broadcast_arrays(xi, eta)
    except ValueError:
        raise ValueError(
            f"xi has shape {xi.shape} and eta has shape {eta.shape}, which do not broadcast "
            "together; valid values: arrays of one shape (or a scalar and an array)"
        ) from None
    return xi, eta


# ---------------------------------------------------------------------------------------------
# quadrature over the footprint (smooth integrands)


def _unit_rule(n: int, graded: bool) -> tuple[np.ndarray, np.ndarray]:
    """n Gauss–Legendre nodes and weights on [0, 1]; ``graded``: after the substitution
    t = (1 − cos πs)/2, which turns √t, 1/√t (and the same at t = 1) into smooth functions
    of s."""
    x, w = np.polynomial.legendre.leggauss(n)
    s = 0.5 * (x + 1.0)
    ws = 0.5 * w
    if not graded:
        return s, ws
    return 0.5 * (1.0 - np.cos(np.pi * s)), ws * 0.5 * np.pi * np.sin(np.pi * s)


def area_rule(footprint, n: int = AREA_RULE_NODES, graded: bool = False):
    """Quadrature nodes and weights over the footprint, for smooth integrands.

    Polygons are triangulated (ear clipping) and each triangle gets the n × n collapsed
    Gauss–Legendre rule (exact for polynomials of degree 2n − 2); a ring r ≤ ρ ≤ R gets n
    Gauss–Legendre points in ρ and 2n + 2 equally spaced angles (exact for trigonometric
    degree 2n + 1).

    With ``graded=True`` every Gauss–Legendre coordinate t ∈ [0, 1] (both of a triangle's,
    a ring's radius) is first substituted t = (1 − cos πs)/2: the nodes crowd towards the
    boundary as s², so that an integrand with a square-root edge behaviour, √d or 1/√d in
    the distance d to a polygon side or a ring's rim (a Hertz- or Boussinesq-shaped map),
    becomes smooth in s and is integrated to ~1e-12 (measured, n = 24), while smooth
    integrands keep their spectral accuracy (no longer exact for polynomials).

    Returns
    -------
    points : ndarray, shape (k, 2)
        Body-frame nodes [m], all inside the footprint.
    weights : ndarray, shape (k,)
        Positive weights [m²]; they add up to the area.
    """
    _check_footprint(footprint)
    x, w = _unit_rule(n, graded)
    pts, wts = [], []
    for p in as_patches(footprint):
        if isinstance(p, Annulus):
            nt = 2 * n + 2
            th = 2.0 * np.pi * np.arange(nt) / nt
            r = p.inner_radius + (p.outer_radius - p.inner_radius) * x
            wr = (p.outer_radius - p.inner_radius) * w * r * (2.0 * np.pi / nt)
            rr, tt = np.meshgrid(r, th, indexing="ij")
            pts.append(
                np.column_stack(
                    (
                        p.centre[0] + (rr * np.cos(tt)).ravel(),
                        p.centre[1] + (rr * np.sin(tt)).ravel(),
                    )
                )
            )
            wts.append(np.repeat(wr, nt))
            continue
        for a, b, c in p.triangles():
            jac = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
            uu, vv = np.meshgrid(x, x, indexing="ij")
            ww = np.outer(w * x, w) * jac
            px = a[0] + uu * ((b[0] - a[0]) + vv * (c[0] - b[0]))
            py = a[1] + uu * ((b[1] - a[1]) + vv * (c[1] - b[1]))
            pts.append(np.column_stack((px.ravel(), py.ravel())))
            wts.append(ww.ravel())
    return np.vstack(pts), np.concatenate(wts)


def contains(footprint, xi, eta) -> np.ndarray:
    """True where (ξ, η) lies inside the footprint (boundary points may go either way)."""
    _check_footprint(footprint)
    xi = np.asarray(xi, dtype=float)
    eta = np.asarray(eta, dtype=float)
    inside = np.zeros(np.broadcast(xi, eta).shape, dtype=bool)
    for p in as_patches(footprint):
        if isinstance(p, Annulus):
            r = np.hypot(xi - p.centre[0], eta - p.centre[1])
            inside |= (r <= p.outer_radius) & (r >= p.inner_radius)
            continue
        poly = p.points if isinstance(p, Polygon) else p.as_polygon().points
        q = np.roll(poly, -1, axis=0)
        odd = np.zeros_like(inside)
        for (ax, ay), (bx, by) in zip(poly, q):
            crosses = (ay > eta) != (by > eta)
            with np.errstate(divide="ignore", invalid="ignore"):
                xint = ax + (eta - ay) * (bx - ax) / (by - ay)
            odd ^= crosses & (xi < xint)
        inside |= odd
    return inside


# ---------------------------------------------------------------------------------------------
# the laws


#: default accuracy target of a map's normalisation (relative, and G relative to the extent)
MAP_SCALE_TOL = 1e-9
#: order of the second, coarser graded rule that checks :func:`map_scale`
MAP_CHECK_NODES = 16


def _map_values(pmap: PressureMap, pts: np.ndarray) -> np.ndarray:
    """The raw map at the nodes ``pts``; a ``ValueError`` for a wrong shape, non-finite or
    negative values."""
    f = pmap(pts[:, 0], pts[:, 1])  # its shape is checked by PressureMap.__call__
    if not np.all(np.isfinite(f)):
        k = int(np.flatnonzero(~np.isfinite(f))[0])
        raise ValueError(
            f"pressure map: function(xi, eta) returned non-finite values, e.g. p = "
            f"{float(f[k])!r} at (xi, eta) = ({float(pts[k, 0])!r}, {float(pts[k, 1])!r}) m; "
            "valid values: finite p >= 0 on the footprint"
        )
    if np.any(f < 0.0):
        k = int(np.argmin(f))
        raise ValueError(
            f"pressure map: p = {float(f[k])!r} < 0 at (xi, eta) = ({float(pts[k, 0])!r}, "
            f"{float(pts[k, 1])!r}) m; valid range: p >= 0 on the footprint"
        )
    return f


def map_scale(
    footprint, pmap: PressureMap, tol: float = MAP_SCALE_TOL
) -> tuple[float, float, float]:
    """(∫f dS, ∫f ξ dS, ∫f η dS) of the raw map f over the footprint.

    By the graded rule of :func:`area_rule` (``graded=True``, n = 24), which integrates
    smooth maps and maps with a square-root edge behaviour (√d or 1/√d in the distance d to
    a polygon side or a ring's rim: Hertz- and Boussinesq-shaped maps) to ~1e-12. Its error
    is estimated by a second graded rule (n = ``MAP_CHECK_NODES`` = 16): where they differ by
    more than ``tol`` (relative for ∫f, relative to ∫f × extent for the moments: G's
    accuracy in units of the extent), a ``RuntimeWarning`` names the accuracy reached (a map
    with a kink, a jump or another edge singularity inside or on the footprint).
    """
    pts, w = area_rule(footprint, graded=True)
    f = _map_values(pmap, pts)
    total = float(w @ f)
    if not total > 0.0:
        raise ValueError(
            f"pressure map: integral over the footprint = {total:.6g}; valid range: > 0"
        )
    out = (total, float(w @ (f * pts[:, 0])), float(w @ (f * pts[:, 1])))
    pc, wc = area_rule(footprint, MAP_CHECK_NODES, graded=True)
    fc = _map_values(pmap, pc)
    check = (float(wc @ fc), float(wc @ (fc * pc[:, 0])), float(wc @ (fc * pc[:, 1])))
    ext = footprint.extent
    err = max(
        abs(out[0] - check[0]) / total,
        abs(out[1] - check[1]) / (total * ext),
        abs(out[2] - check[2]) / (total * ext),
    )
    if err > tol:
        warnings.warn(
            f"pressure map: its normalisation and pressure centroid reached only ~{err:.1e} "
            f"(two quadrature rules differ), not {tol:.1e}: the map is not smooth on the "
            "footprint (a kink, a jump, or an edge behaviour other than sqrt(d) or "
            "1/sqrt(d)); the load, G and the wrench carry that error",
            RuntimeWarning,
            stacklevel=3,
        )
    return out


def pressure_coefficients(footprint, pressure, load: float = 1.0) -> tuple[float, float, float]:
    """Coefficients (p₀, p₁, p₂) of p = p₀ + p₁ξ + p₂η [Pa, Pa/m, Pa/m] on the footprint.

    Parameters
    ----------
    footprint : Polygon, Rectangle, Disk, Annulus, Pads or Blade
        For a Blade, (P/L, 0, 0): the uniform line load [N/m] (its only law).
    pressure : UniformPressure or LinearPressure
    load : float
        Normal load P [N], finite and > 0.

    Raises
    ------
    ValueError
        For a linear law whose pressure turns negative somewhere on the footprint.

    Notes
    -----
    Linear law (MODEL §10): p = (P/A)(1 + gᵀ(r − r_c)) with J g = A (r_G − r_c); its
    centroid is r_G since ∫(r − r_c)(r − r_c)ᵀ dS g = J g.
    """
    _check_footprint(footprint, blade=True)
    load = v.positive("load", load, "N")
    if _blade_law(footprint, pressure):
        assert isinstance(footprint, Blade)
        return load / footprint.length, 0.0, 0.0
    a, rc, jm = footprint._central()
    if isinstance(pressure, UniformPressure):
        return load / a, 0.0, 0.0
    if not isinstance(pressure, LinearPressure):
        raise ValueError(
            f"pressure = {pressure!r} is invalid here; valid values: UniformPressure(), "
            "LinearPressure(xi_c, eta_c) (a PressureMap is not linear)"
        )

    def make():
        arrays = footprint.to_arrays()
        rcv = np.array(rc)
        rg = np.array([pressure.xi_c, pressure.eta_c])
        g = np.linalg.solve(jm, a * (rg - rcv))
        p0 = load / a * (1.0 - g @ rcv)
        p1, p2 = load / a * g
        _check_nonnegative(arrays, (p0, p1, p2), pressure, load / a)
        return float(p0), float(p1), float(p2)

    # computed once per footprint, law and load (the objects are immutable); a law that
    # turns negative raises every time (nothing is cached then)
    return footprint._cached(("linear", pressure.xi_c, pressure.eta_c, load), make)


def _check_nonnegative(arrays: FootprintArrays, coef, pressure, mean: float) -> None:
    p0, p1, p2 = coef
    worst, where = math.inf, (math.nan, math.nan)
    for x, y in arrays.edges[:, :2]:
        val = p0 + p1 * x + p2 * y
        if val < worst:
            worst, where = val, (x, y)
    gn = math.hypot(p1, p2)
    for x, y, r, sg in arrays.circles:
        if sg <= 0:
            continue
        val = p0 + p1 * x + p2 * y - gn * r
        if val < worst:
            px, py = (x - r * p1 / gn, y - r * p2 / gn) if gn > 0 else (x + r, y)
            worst, where = val, (px, py)
    if worst < -1e-12 * mean:
        raise ValueError(
            f"LinearPressure(xi_c={pressure.xi_c!r}, eta_c={pressure.eta_c!r}) turns negative on "
            f"the footprint: p = {worst:.6g} Pa at (xi, eta) = ({where[0]:.6g}, {where[1]:.6g}) m; "
            "valid range: a centroid for which p >= 0 everywhere (closer to the area centroid "
            f"({arrays.frame[0]:.6g}, {arrays.frame[1]:.6g}) m)"
        )


def _round_disk(footprint, pressure) -> bool:
    """True for a Disk under Boussinesq or Hertz pressure (defined on circles, MODEL §3); a
    ``ValueError`` for these laws on any other footprint."""
    if not isinstance(pressure, (BoussinesqPressure, HertzPressure)):
        return False
    if not isinstance(footprint, Disk):
        raise ValueError(footprint_law_error(footprint, pressure))
    return True


def mass_centre(footprint, pressure) -> tuple[float, float]:
    """The mass centre G = the pressure centroid [m] in the body frame (the centre of a Disk
    under Boussinesq or Hertz pressure, of a Blade)."""
    _check_footprint(footprint, blade=True)
    if _round_disk(footprint, pressure) or _blade_law(footprint, pressure):
        return (float(footprint.centre[0]), float(footprint.centre[1]))
    if isinstance(pressure, UniformPressure):
        return footprint.centroid
    if isinstance(pressure, LinearPressure):
        return (pressure.xi_c, pressure.eta_c)
    if isinstance(pressure, PressureMap):
        total, sx, sy = map_scale(footprint, pressure)
        return (sx / total, sy / total)
    raise ValueError(
        f"pressure = {pressure!r} is invalid; valid values: UniformPressure(), "
        "LinearPressure(xi_c, eta_c), PressureMap(function)"
    )


def density(footprint, pressure, xi, eta, load: float = 1.0) -> np.ndarray:
    """Pressure p(ξ, η) [Pa] at body-frame points (arrays allowed); 0 outside the footprint.

    Uniform, linear and map laws on any footprint; Boussinesq and Hertz on a single Disk
    (the circle's law of MODEL §3 about the disk's centre)."""
    load = v.positive("load", load, "N")
    xi, eta = _points(xi, eta)
    _check_footprint(footprint)
    if _round_disk(footprint, pressure):
        cx, cy = footprint.centre
        return np.asarray(
            pressure.density(Ellipse(footprint.radius, footprint.radius), xi - cx, eta - cy, load)
        )
    inside = contains(footprint, xi, eta)
    if isinstance(pressure, PressureMap):
        total, _, _ = map_scale(footprint, pressure)
        p = pressure(xi, eta) * (load / total)
    else:
        p0, p1, p2 = pressure_coefficients(footprint, pressure, load)
        p = p0 + p1 * xi + p2 * eta
    return np.where(inside, p, 0.0)


def kernel_geometry(
    footprint, pressure, arrays: FootprintArrays | None = None, length: float = 1.0
) -> np.ndarray:
    """The ``geo`` vector of the compiled kernel for unit load (P = 1).

    Layout :data:`slidespin.contact._kernel_footprint.GEO_FIELDS`: reference point and extent (from
    ``arrays.frame``), pressure coefficients (p₀, p₁, p₂), mass centre G, pressure centroid,
    load ∫p dS. Only uniform and linear laws (the kernel's exact path).

    Parameters
    ----------
    length : float, default 1
        Length unit [m] of the kernel's input: pass the same ``length`` to
        :func:`scaled_arrays` (e.g. a characteristic size, for natural units). ``arrays``, if
        given, must be in metres.
    """
    length = v.positive("length", length, "m")
    arrays = footprint.to_arrays() if arrays is None else arrays
    p0, p1, p2 = pressure_coefficients(footprint, pressure, 1.0)
    if isinstance(footprint, Blade):  # a line load: p₀ per unit length, not area
        p0 /= length
    xg, yg = mass_centre(footprint, pressure)
    geo = np.empty(NGEO)
    geo[0:3] = arrays.frame / length
    geo[3] = p0 * length**2  # pressure per unit load and unit area (area in length²)
    geo[4:6] = (p1 * length**3, p2 * length**3)
    if not isinstance(footprint, Blade):
        # the load of the arrays the kernel reads (scaled: rounded) is exactly 1; a thin
        # ring's width in units of ℓ carries a rounding of ~1e-16 ℓ/(R − r) (MODEL §10)
        geo[3:6] /= linear_load(scaled_arrays(arrays, length), *geo[3:6])
    geo[6:8] = (xg / length, yg / length)
    geo[8:10] = geo[6:8]  # G is the pressure centroid
    geo[10] = 1.0
    return geo


def scaled_arrays(arrays: FootprintArrays, length: float) -> FootprintArrays:
    """The footprint arrays with lengths in units of ``length`` [m] (signs unchanged)."""
    length = v.positive("length", length, "m")
    circles = arrays.circles.copy()
    circles[:, :3] /= length
    return FootprintArrays(
        np.ascontiguousarray(arrays.edges / length), circles, arrays.frame / length
    )


def symmetry(footprint, pressure, rtol: float = 1e-12) -> tuple[bool, bool]:
    """(central, axial): whether the pressure on the footprint is centrally symmetric about G
    (invariant under r → 2G − r), and whether it is axisymmetric about G.

    Decided conservatively, from the arrays: only a uniform pressure (p₁ = p₂ = 0 exactly;
    a linear law centred on the area centroid is uniform) qualifies; central symmetry needs
    every reflected edge and circle to match one of the footprint's to ``rtol`` × extent (a
    rectangle, a disk, a ring, a centred regular polygon, symmetric pads); axial symmetry
    needs no edges and every circle centred on G (a centred disk or ring). Under central
    symmetry pure spin about G is an invariant set of the motion; under axial symmetry (and
    an isotropic tensor) every rotation of a terminal motion is one too (MODEL §9).
    """
    _check_footprint(footprint, blade=True)
    if _blade_law(footprint, pressure):  # a segment under a uniform load, G at its centre
        return True, False
    if isinstance(pressure, PressureMap):
        return False, False
    _, p1, p2 = pressure_coefficients(footprint, pressure, 1.0)
    if p1 != 0.0 or p2 != 0.0:
        return False, False
    arrays = footprint.to_arrays()
    gx, gy = mass_centre(footprint, pressure)
    tol = rtol * float(arrays.frame[2])
    e, c = arrays.edges, arrays.circles
    axial = e.shape[0] == 0 and all(math.hypot(x - gx, y - gy) <= tol for x, y, _, _ in c)
    refl_e = np.column_stack(
        (2 * gx - e[:, 0], 2 * gy - e[:, 1], 2 * gx - e[:, 2], 2 * gy - e[:, 3])
    )
    refl_c = np.column_stack((2 * gx - c[:, 0], 2 * gy - c[:, 1], c[:, 2], c[:, 3]))

    def matched(refl, orig):
        # every reflected row within tol (max-norm) of an original row: a k-d tree query,
        # O(n log n) for a polygon of many vertices
        if refl.shape[0] == 0:
            return True
        if orig.shape[0] == 0:
            return False
        from scipy.spatial import cKDTree

        dist, _ = cKDTree(orig).query(refl, p=np.inf)
        return bool(np.all(dist <= tol))

    central = matched(refl_e, e) and matched(refl_c, c)
    return bool(central), bool(axial)


def round_law(patch: object, pressure: object) -> bool:
    """A ``Disk`` under the Boussinesq or Hertz law: a circle, for the elliptic engine."""
    return isinstance(patch, Disk) and isinstance(pressure, (BoussinesqPressure, HertzPressure))


def footprint_law_error(patch, pressure) -> str:
    """The message for a pressure law a footprint does not take (MODEL §10)."""
    if isinstance(pressure, (BoussinesqPressure, HertzPressure)):
        law = type(pressure).__name__
        if isinstance(patch, Pads):
            why = (
                "on Pads the pads' load shares are not determined by the law; give "
                "UniformPressure() or LinearPressure(xi_c, eta_c), or one Disk"
            )
        elif isinstance(patch, Annulus) and patch.inner_radius == 0.0:
            why = f"use Disk({patch.outer_radius!r}) for a full disk"
        else:
            name = type(patch).__name__
            why = f"it is not defined on {'an' if name[0] in 'AEIOU' else 'a'} {name}"
        valid = (
            "UniformPressure()"
            if isinstance(patch, Blade)
            else "UniformPressure(), LinearPressure(xi_c, eta_c)"
        )
        return (
            f"pressure = {law}() is invalid on patch = {v._short(patch, 100)}: {why}; "
            f"{law} is defined on an Ellipse or a single Disk (Circle) (MODEL §3, §10); "
            f"valid values on this patch: {valid}"
        )
    return (
        f"pressure = {pressure!r} is invalid on a footprint; valid values: "
        "UniformPressure(), LinearPressure(xi_c, eta_c), PressureMap(function) (for "
        "friction_wrench only), and on a single Disk also BoussinesqPressure() and "
        "HertzPressure()"
    )
