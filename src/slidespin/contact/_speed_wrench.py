"""The wrench under a speed-dependent law for every patch and pressure (MODEL §14): the data the
compiled kernel (:mod:`slidespin.contact._kernel_speed`) reads, and the loop over states.

A patch becomes edges and signed axis-parallel ellipses in the body frame [m]; the pressure,
for unit load, a linear law p₀ + p₁ξ + p₂η (uniform and linear laws, on an ellipse the
paper's eq. 10) or the Boussinesq or Hertz law of an ellipse or a Disk; a far-field area rule
with the pressure in its weights. Pure translation (ω = 0) is exact: every point slips at |v|,
so the wrench is g(|v|) times the constant law's (the exact kernels).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from slidespin.contact._kernel_speed import P_BOUSSINESQ, P_HERTZ, P_LINEAR, speed_wrench_body
from slidespin.contact.ellipse import Ellipse
from slidespin.contact.pressure import (
    BoussinesqPressure,
    HertzPressure,
    LinearPressure,
)
from slidespin.contact.pressure_map import (
    _unit_rule,
    area_rule,
    mass_centre,
    pressure_coefficients,
)
from slidespin.contact.shapes import Disk
from slidespin.contact.speed_laws import PowerLaw, Stribeck

__all__ = [
    "SPEED_TOL",
    "speed_tol",
    "SpeedPatch",
    "law_arrays",
    "speed_patch",
    "speed_wrench_one",
    "speed_wrench_world",
]

#: the kernel's absolute target, in units of the load and load × extent
SPEED_TOL = 1e-11
_AREA_NODES = 24


def speed_tol(friction) -> float:
    """The kernel's target for ``friction``: ``SPEED_TOL`` relative to the tensor's norm when
    that is below 1 (the wrench scales with it), never below 1e-15 (round-off)."""
    return max(1e-15, SPEED_TOL * min(1.0, friction.norm))


@dataclass(frozen=True)
class SpeedPatch:
    """A patch and its pressure as the speed-law kernel reads them (module notes)."""

    edges: np.ndarray
    conics: np.ndarray
    pcode: int
    pp: np.ndarray
    g: tuple[float, float]
    frame: tuple[float, float, float]
    far_pts: np.ndarray
    far_w: np.ndarray


def _ellipse_rule(ox, oy, a, b, n=_AREA_NODES):
    """Polar area rule on an ellipse, graded towards the rim (√d and 1/√d rims are smooth in
    it): n radii, 2n + 2 angles; returns points and area weights."""
    r, wr = _unit_rule(n, True)
    wr = wr * r
    nt = 2 * n + 2
    th = 2.0 * np.pi * np.arange(nt) / nt
    rr, tt = np.meshgrid(r, th, indexing="ij")
    pts = np.column_stack((ox + a * (rr * np.cos(tt)).ravel(), oy + b * (rr * np.sin(tt)).ravel()))
    wts = np.repeat(wr * (2.0 * np.pi / nt) * a * b, nt)
    return pts, wts


def speed_patch(patch, pressure) -> SpeedPatch:
    """The kernel's form of ``patch`` (an Ellipse or a footprint of
    :mod:`slidespin.contact.shapes`) under ``pressure``, for unit load."""
    no_edges = np.zeros((0, 4))
    if isinstance(patch, Ellipse) or (
        isinstance(patch, Disk) and isinstance(pressure, (BoussinesqPressure, HertzPressure))
    ):
        if isinstance(patch, Ellipse):
            ox, oy, a, b = 0.0, 0.0, patch.a, patch.b
        else:
            (ox, oy), a, b = patch.centre, patch.radius, patch.radius
        conics = np.array([[ox, oy, a, b, 1.0]])
        pts, w = _ellipse_rule(ox, oy, a, b)
        area = math.pi * a * b
        gx, gy = ox, oy
        if isinstance(pressure, BoussinesqPressure):
            pcode, pp = P_BOUSSINESQ, np.array([ox, oy, a, b, 1.0 / (2.0 * area)])
        elif isinstance(pressure, HertzPressure):
            pcode, pp = P_HERTZ, np.array([ox, oy, a, b, 3.0 / (2.0 * area)])
        elif isinstance(pressure, LinearPressure):  # paper eq. 10, G = (ξc, ηc)
            gx, gy = pressure.xi_c, pressure.eta_c
            pcode = P_LINEAR
            pp = np.array([1.0, 4.0 * gx / a**2, 4.0 * gy / b**2]) / area
        else:
            pcode, pp = P_LINEAR, np.array([1.0 / area, 0.0, 0.0])
        dens = _density_np(pcode, pp, pts)
        return SpeedPatch(no_edges, conics, pcode, pp, (gx, gy), (ox, oy, max(a, b)), pts, w * dens)
    arrays = patch.to_arrays()
    conics = np.array([[x, y, r, r, sg] for x, y, r, sg in arrays.circles], dtype=float).reshape(
        -1, 5
    )
    p0, p1, p2 = pressure_coefficients(patch, pressure, 1.0)
    pp = np.array([p0, p1, p2])
    pts, w = area_rule(patch, _AREA_NODES, graded=True)
    gx, gy = mass_centre(patch, pressure)
    ox, oy, ext = (float(x) for x in arrays.frame)
    return SpeedPatch(
        np.ascontiguousarray(arrays.edges, dtype=float),
        conics,
        P_LINEAR,
        pp,
        (gx, gy),
        (ox, oy, ext),
        pts,
        w * _density_np(P_LINEAR, pp, pts),
    )


def _density_np(pcode, pp, pts):
    x, y = pts[:, 0], pts[:, 1]
    if pcode == P_LINEAR:
        return pp[0] + pp[1] * x + pp[2] * y
    s = np.maximum(1.0 - ((x - pp[0]) / pp[2]) ** 2 - ((y - pp[1]) / pp[3]) ** 2, 0.0)
    with np.errstate(divide="ignore"):
        return pp[4] / np.sqrt(s) if pcode == P_BOUSSINESQ else pp[4] * np.sqrt(s)


def law_arrays(law) -> tuple[int, np.ndarray, np.ndarray, bool]:
    """(code, parameters, break speeds, singular at zero speed) of a speed law."""
    code, lp = law.kernel_args()
    singular = (isinstance(law, PowerLaw) and law.q > 0.0) or (
        isinstance(law, Stribeck) and float(law.delta) != round(law.delta)
    )
    return code, lp, np.sort(law.break_speeds()), singular


def speed_wrench_one(sp: SpeedPatch, tensor, body_frame, law_args, phi, vx, vy, omega, tol):
    """(Fx, Fy, M, error estimate) in the fixed frame for unit load of one state (ω ≠ 0);
    ``law_args`` from :func:`law_arrays`."""
    code, lp, rb, sing = law_args
    gx, gy = sp.g
    ox, oy, ext = sp.frame
    c, s = math.cos(phi), math.sin(phi)
    if body_frame:
        tb = np.ascontiguousarray(tensor)
    else:
        rot = np.array([[c, -s], [s, c]])
        tb = np.ascontiguousarray(rot.T @ tensor @ rot)
    vbx = c * vx + s * vy
    vby = -s * vx + c * vy
    f0, f1, m, missed, err = speed_wrench_body(
        sp.edges,
        sp.conics,
        sp.pcode,
        sp.pp,
        gx,
        gy,
        ox,
        oy,
        ext,
        tb,
        code,
        lp,
        rb,
        sing,
        sp.far_pts,
        sp.far_w,
        vbx,
        vby,
        float(omega),
        tol,
    )
    if missed:
        err = max(err, 10.0 * tol)
    return c * f0 - s * f1, s * f0 + c * f1, m, err


def speed_wrench_world(sp: SpeedPatch, tensor, body_frame, law, phi, vx, vy, omega, tol):
    """(Fx, Fy, M) in the fixed frame for unit load, per state (flat arrays, ω ≠ 0 each),
    and the largest error estimate met (units of the load and load × extent)."""
    args = law_arrays(law)
    n = vx.size
    fx, fy, mm = np.empty(n), np.empty(n), np.empty(n)
    worst = 0.0
    for i in range(n):
        fx[i], fy[i], mm[i], err = speed_wrench_one(
            sp,
            tensor,
            body_frame,
            args,
            float(phi[i]),
            float(vx[i]),
            float(vy[i]),
            float(omega[i]),
            tol,
        )
        worst = max(worst, err)
    return fx, fy, mm, worst
