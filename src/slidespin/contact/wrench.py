"""The friction force and moment on the body for a given motion state (paper eq. 1–4, MODEL §2, §10).

:func:`friction_wrench` is the one public wrench, for every patch: it returns the force in the
fixed frame and the moment about the mass centre G (counter-clockwise positive), and the
paper's components (MODEL §4):

    F_τ = −F·(cos ϑ, sin ϑ),   F_n = −F·(−sin ϑ, cos ϑ),   M_paper = −M,

so that v̇ = −F_τ/m, ϑ̇ = −F_n/(m v), ω̇ = −M_paper/I (paper eq. 4). By patch:

* An ellipse or circle (and a ``Disk`` under Boussinesq or Hertz pressure, the circle of its
  radius): the compiled quadrature of :mod:`slidespin.contact._kernel_ellipse`, to an absolute
  error of about 1e-12 m g (force) and 1e-12 m g a (moment) for every state, including an
  instantaneous centre of rotation inside the patch or on its rim.
* A footprint under uniform or linear pressure: the compiled exact kernel
  (:mod:`slidespin.contact._kernel_footprint`: closed forms for polygons, complete elliptic
  integrals for disks and rings), to ≲ 3e-12 P and P·extent in the tests, for every state.
* A ``Blade`` (a line contact under a uniform line load): the closed form of
  :mod:`slidespin.contact._kernel_blade`, exact for every motion state.
* A user pressure map (:class:`~slidespin.PressureMap`): the adaptive quadrature about the
  instantaneous centre of :mod:`slidespin.contact._map_wrench` (to ``map_tol``).

:func:`footprint_wrench` is the same wrench for a patch and a pressure given without a body
(a normal load ``load`` in place of m g); :func:`friction_wrench` calls it for footprints.

Departure from the printed paper: eq. 3's y′ and moment are garbled in print; slidespin uses
y′ = ξ sin φ + η cos φ and mom = x′τ_y − y′τ_x (MODEL §7, erratum 1), with positions
measured from G.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from slidespin import _aot
from slidespin import _validate as v
from slidespin.contact import _engine
from slidespin.contact._kernel_blade import blade_wrench_array
from slidespin.contact._kernel_ellipse import STATUS_OK, wrench_array
from slidespin.contact._kernel_footprint import wrench_array as fp_wrench_array
from slidespin.contact._map_wrench import MAP_TOL, MAP_TOL_RANGE, map_prepare, map_wrench_world
from slidespin.contact._speed_wrench import speed_patch, speed_tol, speed_wrench_world
from slidespin.contact.body import Body
from slidespin.contact.ellipse import Ellipse
from slidespin.contact.friction import FrictionTensor
from slidespin.contact.pressure import (
    BoussinesqPressure,
    HertzPressure,
    LinearPressure,
    UniformPressure,
)
from slidespin.contact.pressure_map import (
    PressureMap,
    _blade_law,
    footprint_law_error,
    kernel_geometry,
)
from slidespin.contact.shapes import Annulus, Blade, Disk, Pads, Polygon, Rectangle
from slidespin.contact.speed_laws import law_is_constant

__all__ = ["Wrench", "footprint_wrench", "friction_wrench"]


@dataclass(frozen=True, slots=True)
class Wrench:
    """Friction force and moment on the body (floats, or arrays for array input).

    Attributes
    ----------
    force_x, force_y : float or ndarray
        Friction force in the fixed frame [N].
    moment : float or ndarray
        Friction moment about the mass centre G [N m], counter-clockwise positive.
    tangential, normal : float or ndarray
        The paper's F_τ and F_n [N] (eq. 4): minus the force components along and across the
        velocity of G. For v = 0 the direction ϑ = 0 is used.
    moment_paper : float or ndarray
        The paper's M_Cζ = −M [N m].
    theta : float or ndarray
        Direction ϑ of the velocity of G [rad] (0 when v = 0).
    """

    force_x: float | NDArray[np.float64]
    force_y: float | NDArray[np.float64]
    moment: float | NDArray[np.float64]
    tangential: float | NDArray[np.float64]
    normal: float | NDArray[np.float64]
    moment_paper: float | NDArray[np.float64]
    theta: float | NDArray[np.float64]

    @classmethod
    def from_world(
        cls,
        fx: NDArray[np.float64],
        fy: NDArray[np.float64],
        mm: NDArray[np.float64],
        theta: NDArray[np.float64],
        shape: tuple[int, ...],
        scalar: bool,
    ) -> Wrench:
        """The wrench from flat arrays of the force [N], moment [N m] and direction ϑ of the
        velocity of G, with the paper's F_τ, F_n, M_Cζ (eq. 4), in ``shape`` (floats if
        ``scalar``)."""
        c, s = np.cos(theta), np.sin(theta)
        ft = -(fx * c + fy * s)
        fn = -(-fx * s + fy * c)
        out = [x.reshape(shape) for x in (fx, fy, mm, ft, fn, -mm, theta)]
        if scalar:
            return cls(*(float(x) for x in out))
        return cls(*out)

    def power(
        self,
        vx: float | NDArray[np.float64],
        vy: float | NDArray[np.float64],
        omega: float | NDArray[np.float64],
    ) -> float | NDArray[np.float64]:
        """Friction power F·v + M ω [W] for the state the wrench was computed at (≤ 0)."""
        return self.force_x * vx + self.force_y * vy + self.moment * omega


def _check_array(name: str, value: ArrayLike) -> NDArray[np.float64]:
    return v.real_array(name, value)


def _direction(vx, vy, omega, a):
    """(vx/a, vy/a, ω) scaled by their largest magnitude, per element (MODEL §2).

    The wrench is homogeneous of degree 0 in (v, ω), so only this direction matters; scaling
    first keeps every component in [−1, 1] whatever the magnitudes (1e±300 included), so
    that nothing overflows or underflows in the kernel. Components below 1e-200 of the
    largest one are set to 0: the wrench is Lipschitz in the direction, so this changes it
    by far less than any quadrature target.
    """
    big = np.maximum(np.maximum(np.abs(vx), np.abs(vy)), np.abs(omega))
    big = np.where(big > 0.0, big, 1.0)
    ux, uy, uw = vx / big, vy / big, omega / big  # all in [-1, 1]
    ux, uy = ux / a, uy / a  # a in [1e-9, 1e6]: |ux|, |uy| <= 1e9
    big = np.maximum(np.maximum(np.abs(ux), np.abs(uy)), np.abs(uw))
    big = np.where(big > 0.0, big, 1.0)
    out = []
    for x in (ux / big, uy / big, uw / big):
        out.append(np.where(np.abs(x) < 1e-200, 0.0, x))
    return out


def motion_arrays(
    vx: ArrayLike, vy: ArrayLike, omega: ArrayLike, phi: ArrayLike
) -> tuple[
    NDArray[np.float64],
    NDArray[np.float64],
    NDArray[np.float64],
    NDArray[np.float64],
    tuple[int, ...],
    bool,
]:
    """Validate and broadcast the motion state (arrays accepted): returns flat float arrays
    (vx, vy, ω, φ), the broadcast shape and whether every input was a scalar."""
    arrays = [
        _check_array(n, x) for n, x in (("vx", vx), ("vy", vy), ("omega", omega), ("phi", phi))
    ]
    scalar = all(a.ndim == 0 for a in arrays)
    try:
        b = np.broadcast_arrays(*arrays)
    except ValueError:
        raise ValueError(
            "vx, vy, omega, phi have shapes "
            + ", ".join(str(a.shape) for a in arrays)
            + " that do not broadcast together; valid values: arrays of one shape (or "
            "scalars and arrays of one shape)"
        ) from None
    vxf, vyf, omf, phf = (np.ascontiguousarray(x, dtype=float).ravel() for x in b)
    return vxf, vyf, omf, phf, b[0].shape, scalar


def friction_wrench(
    body: Body,
    friction: FrictionTensor,
    vx: ArrayLike,
    vy: ArrayLike,
    omega: ArrayLike,
    phi: ArrayLike = 0.0,
    g: float = 9.81,
    *,
    tol: float = 1e-12,
    map_tol: float = MAP_TOL,
) -> Wrench:
    """Friction force and moment on ``body`` for the motion state (vx, vy, ω) at angle φ.

    Parameters
    ----------
    body : Body
        Patch (an ellipse or any footprint), pressure law, mass and inertia.
    friction : FrictionTensor
        Friction tensor (plane- or body-fixed).
    vx, vy : float or array_like
        Velocity of the mass centre G in the fixed frame [m/s], any finite values.
    omega : float or array_like
        Spin rate [rad/s], counter-clockwise positive, any finite values.
    phi : float or array_like, default 0
        Body angle [rad], any finite values.
    g : float, default 9.81
        Gravitational acceleration [m/s²] in [1e-6, 1e6]; the normal load is P = m g.
    tol : float, default 1e-12
        Absolute error target of the quadrature, in units of m g (force) and m g a (moment),
        in [1e-13, 1e-2] (below 1e-13 round-off defeats it on the thinnest valid patches).

    Returns
    -------
    Wrench
        Floats for scalar input, arrays of the broadcast shape otherwise.

    Notes
    -----
    For a footprint patch (:mod:`slidespin.contact.shapes`) this is
    :func:`footprint_wrench` with the load m g: exact (closed forms, MODEL §10) for
    every motion state, and ``tol`` is not used.

    With a speed law (``FrictionTensor(..., speed_law=...)``, MODEL §14) the traction is
    −p g(|w|) 𝔽 ŵ and the wrench depends on the speeds themselves: it is computed by the
    compiled rule of :mod:`slidespin.contact._kernel_speed` to 1e-11 min(1, |𝔽|) of the load
    (``tol`` and ``map_tol`` are not used). Otherwise:

    The wrench depends only on the direction of (vx, vy, a ω): it is homogeneous of degree 0
    (MODEL §2). That direction is formed after scaling by the largest magnitude, so states
    of any finite size (1e-300 … 1e300) give the same wrench as their unit-size copies. At rest (v = ω = 0) static friction is undetermined and a zero wrench is
    returned. Paper eq. 3–4, corrected per MODEL §7 (errata 1, 4, 7).

    Examples
    --------
    >>> from slidespin import Body, Circle, UniformPressure, FrictionTensor
    >>> body = Body(Circle(0.1), UniformPressure(), mass=1.0)
    >>> w = friction_wrench(body, FrictionTensor(0.3, 0.3), 0.0, 0.0, 1.0, g=10.0)
    >>> round(w.moment, 12)  # -(2/3) f m g a for a spinning disk
    -0.2
    """
    if not isinstance(body, Body):
        raise ValueError(f"body = {body!r} is invalid; valid values: a slidespin.Body")
    if not isinstance(friction, FrictionTensor):
        raise ValueError(f"friction = {friction!r} is invalid; valid values: a FrictionTensor")
    g = v.bounded("g", g, *v.GRAVITY, "m/s^2")
    tol = v.bounded("tol", tol, *v.WRENCH_TOL)
    if not law_is_constant(friction.speed_law):
        return _law_wrench(body.patch, body.pressure, friction, vx, vy, omega, phi, body.mass * g)
    if body.is_footprint:  # the exact footprint kernel (MODEL §10); ``tol`` is not needed
        return footprint_wrench(
            body.patch,
            body.pressure,
            friction,
            vx,
            vy,
            omega,
            phi,
            load=body.mass * g,
            map_tol=map_tol,
        )
    vxa, vya, oma, pha, shape, scalar = motion_arrays(vx, vy, omega, phi)
    a = body.length_unit  # the semi-axis a of the ellipse
    par = body.kernel_params(friction, tol)
    ux, uy, uw = (np.ascontiguousarray(x) for x in _direction(vxa, vya, oma, a))
    fx, fy, mm, st = wrench_array(
        *_engine.elliptic_args(par),
        pha,
        ux,
        uy,
        uw,
        tol,
    )
    bad = (st != STATUS_OK) | ~np.isfinite(fx) | ~np.isfinite(fy) | ~np.isfinite(mm)
    if bad.any():  # pragma: no cover - not reached for valid inputs (docs/errors.md)
        i = int(np.flatnonzero(bad)[0])
        raise RuntimeError(
            f"friction_wrench: the quadrature missed tol = {tol:g} for {int(bad.sum())} "
            f"state(s), the first vx = {vxa[i]!r}, vy = {vya[i]!r}, omega = {oma[i]!r}, "
            f"phi = {pha[i]!r} (b/a = {par[_engine.P_BN]!r}, {friction!r}); every input is "
            "inside its valid range, so this is a bug in slidespin: please report it"
        )
    load = body.mass * g
    fx = fx * load
    fy = fy * load
    mm = mm * load * a
    return Wrench.from_world(fx, fy, mm, np.arctan2(vya, vxa), shape, scalar)


def footprint_wrench(
    footprint,
    pressure,
    friction: FrictionTensor,
    vx,
    vy,
    omega,
    phi=0.0,
    load: float = 1.0,
    *,
    map_tol: float = MAP_TOL,
) -> Wrench:
    """Friction force and moment on a body on ``footprint`` for the motion (vx, vy, ω) at φ.

    Parameters
    ----------
    footprint : Polygon, Rectangle, Disk, Annulus, Pads or Blade
        The contact footprint in the body frame [m] (a Blade: uniform pressure only).
    pressure : UniformPressure, LinearPressure, PressureMap, BoussinesqPressure or HertzPressure
        Normal pressure on the footprint (normalised to ``load``); the mass centre G is its
        centroid (:func:`slidespin.contact.pressure_map.mass_centre`). Boussinesq and Hertz on a
        single ``Disk`` only (G at its centre; the elliptic kernel, module notes).
    friction : FrictionTensor
        Friction tensor (plane- or body-fixed).
    vx, vy : float or array_like
        Velocity of G in the fixed frame [m/s].
    omega : float or array_like
        Spin rate [rad/s], counter-clockwise positive.
    phi : float or array_like, default 0
        Body angle [rad].
    load : float, default 1
        Normal load P = m g [N].
    map_tol : float in [1e-12, 1e-2], default 1e-9
        Error target of the user-map quadrature, in units of P (force) and P × extent
        (moment); unused for uniform and linear pressure (exact).

    Returns
    -------
    Wrench
        Force in the fixed frame [N], moment about G [N m] and the paper's components;
        floats for scalar input, arrays of the broadcast shape otherwise.

    Notes
    -----
    MODEL §2 (traction −p 𝔽 ŵ) over the footprint of MODEL §10. The wrench depends only on the
    direction of (vx, vy, ω); at rest (v = ω = 0) a zero wrench is returned.

    Examples
    --------
    >>> from slidespin import FrictionTensor, UniformPressure
    >>> from slidespin.contact.shapes import Annulus
    >>> w = footprint_wrench(Annulus(0.05, 0.1), UniformPressure(), FrictionTensor(0.3, 0.3),
    ...                      0.0, 0.0, 1.0, load=10.0)
    >>> round(w.moment, 12)  # −(2/3) μ P (R³ − r³)/(R² − r²)
    -0.233333333333
    """
    if not isinstance(footprint, (Polygon, Rectangle, Annulus, Pads, Blade)):
        raise ValueError(
            f"footprint = {footprint!r} is invalid; valid values: Polygon, Rectangle, Disk, "
            "Annulus, Pads or Blade"
        )
    if isinstance(footprint, Blade) and not isinstance(
        pressure, (BoussinesqPressure, HertzPressure)
    ):
        _blade_law(footprint, pressure)  # a Blade takes the uniform line load only
    if isinstance(pressure, (BoussinesqPressure, HertzPressure)):
        if not isinstance(footprint, Disk):
            raise ValueError(footprint_law_error(footprint, pressure))
    elif not isinstance(pressure, (UniformPressure, LinearPressure, PressureMap)):
        raise ValueError(
            f"pressure = {pressure!r} is invalid; valid values: UniformPressure(), "
            "LinearPressure(xi_c, eta_c), PressureMap(function), and on a single Disk "
            "BoussinesqPressure(), HertzPressure()"
        )
    if not isinstance(friction, FrictionTensor):
        raise ValueError(f"friction = {friction!r} is invalid; valid values: a FrictionTensor")
    load = v.positive("load", load, "N")
    map_tol = v.bounded("map_tol", map_tol, *MAP_TOL_RANGE)
    if not law_is_constant(friction.speed_law):
        return _law_wrench(footprint, pressure, friction, vx, vy, omega, phi, load)
    if isinstance(pressure, (BoussinesqPressure, HertzPressure)):
        return _round_wrench(footprint, pressure, friction, vx, vy, omega, phi, load)
    vxa, vya, oma, pha, shape, scalar = motion_arrays(vx, vy, omega, phi)
    theta = np.arctan2(vya, vxa)
    # the dry-friction wrench depends on the direction of (v, ω) only (MODEL §2): scale each
    # triple by a power of two (exact) to magnitude ≤ 1, so that no product in the kernel
    # overflows for velocities near the largest float
    _, expo = np.frexp(np.maximum(np.maximum(np.abs(vxa), np.abs(vya)), np.abs(oma)))
    vxa, vya, oma = (np.ldexp(x, -expo) for x in (vxa, vya, oma))
    t = friction.matrix
    body_frame = friction.frame == "body"
    arrays = footprint.to_arrays()
    if isinstance(pressure, PressureMap):
        fx = np.empty(vxa.size)
        fy = np.empty(vxa.size)
        mm = np.empty(vxa.size)
        prep = map_prepare(footprint, pressure, arrays, map_tol)
        for i in range(vxa.size):
            fx[i], fy[i], mm[i] = map_wrench_world(
                prep, t, body_frame, pha[i], vxa[i], vya[i], oma[i], map_tol
            )
    elif isinstance(footprint, Blade):  # the exact line-contact kernel
        fx, fy, mm = blade_wrench_array(
            *arrays.edges[0],
            *footprint.centroid,
            1.0,
            t[0, 0],
            t[0, 1],
            t[1, 0],
            t[1, 1],
            body_frame,
            pha,
            vxa,
            vya,
            oma,
        )
    else:
        geo = kernel_geometry(footprint, pressure, arrays)
        # the ahead-of-time compiled loop when the install built it (slidespin._aot)
        aot = _aot.core()
        run = fp_wrench_array if aot is None else aot.wrench_array_footprint
        c64 = np.ascontiguousarray
        fx, fy, mm = run(
            c64(arrays.edges, dtype=np.float64),
            c64(arrays.circles, dtype=np.float64),
            c64(geo, dtype=np.float64),
            *(float(x) for x in t.ravel()),
            bool(body_frame),
            *(c64(x, dtype=np.float64) for x in (pha, vxa, vya, oma)),
        )
    fx = fx * load
    fy = fy * load
    mm = mm * load
    return Wrench.from_world(fx, fy, mm, theta, shape, scalar)


def _law_wrench(patch, pressure, friction, vx, vy, omega, phi, load) -> Wrench:
    """The wrench under the tensor's speed law (MODEL §14): ω = 0 exactly as g(|v|) times the
    constant law's wrench, the rest by :mod:`slidespin.contact._kernel_speed` to
    :func:`~slidespin.contact._speed_wrench.speed_tol` (absolute, units of the load and load ×
    extent: 1e-11 × min(1, |𝔽|))."""
    if isinstance(patch, Blade) or isinstance(pressure, PressureMap):
        raise ValueError(
            f"speed_law = {friction.speed_law!r} is not available on "
            + ("a Blade" if isinstance(patch, Blade) else "a PressureMap")
            + "; valid values: speed_law=None there (speed laws run on ellipses, polygons, "
            "rectangles, disks, rings and pads under uniform, linear, Boussinesq or Hertz "
            "pressure)"
        )
    vxa, vya, oma, pha, shape, scalar = motion_arrays(vx, vy, omega, phi)
    law = friction.speed_law
    fx, fy, mm = np.zeros(vxa.size), np.zeros(vxa.size), np.zeros(vxa.size)
    slide = oma == 0.0
    if slide.any():  # pure translation: every point slips at |v|
        kin = friction.kinetic
        if isinstance(patch, Ellipse):
            w0 = friction_wrench(
                Body(patch, pressure, 1.0), kin, vxa[slide], vya[slide], 0.0, pha[slide], g=1.0
            )
        else:
            w0 = footprint_wrench(patch, pressure, kin, vxa[slide], vya[slide], 0.0, pha[slide])
        speed = np.hypot(vxa[slide], vya[slide])
        moving = speed > 0.0
        gv = np.ones_like(speed)
        gv[moving] = law.factor(speed[moving])
        fx[slide] = np.asarray(w0.force_x) * gv
        fy[slide] = np.asarray(w0.force_y) * gv
        mm[slide] = np.asarray(w0.moment) * gv
    spin = ~slide
    if spin.any():
        sp = speed_patch(patch, pressure)
        tol = speed_tol(friction)
        f0, f1, m, err = speed_wrench_world(
            sp,
            friction.matrix,
            friction.frame == "body",
            law,
            pha[spin],
            vxa[spin],
            vya[spin],
            oma[spin],
            tol,
        )
        if err > 100.0 * tol:  # pragma: no cover - not reached for valid inputs
            raise RuntimeError(
                f"friction_wrench: the speed-law quadrature reached only ~{err:.1e} (units of "
                f"the load and load x extent), not {tol:g}, for {friction!r} on "
                f"{patch!r}; every input is inside its valid range, so this is a bug in "
                "slidespin: please report it"
            )
        fx[spin], fy[spin], mm[spin] = f0, f1, m
    return Wrench.from_world(fx * load, fy * load, mm * load, np.arctan2(vya, vxa), shape, scalar)


def _round_wrench(disk, pressure, friction, vx, vy, omega, phi, load) -> Wrench:
    """The wrench on a disk under Boussinesq or Hertz pressure: the circle of its radius with
    G at its centre, by the elliptic kernel (:func:`slidespin.friction_wrench`, unit load),
    scaled to ``load``."""
    w = friction_wrench(Body(disk, pressure, 1.0), friction, vx, vy, omega, phi, g=1.0)
    return Wrench(
        w.force_x * load,
        w.force_y * load,
        w.moment * load,
        w.tangential * load,
        w.normal * load,
        w.moment_paper * load,
        w.theta,
    )


# ---------------------------------------------------------------------------------------------
# user pressure maps
