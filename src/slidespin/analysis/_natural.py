"""The compiled wrench in natural units (a = m = g = 1), shared by the terminal analysis.

``_params`` packs a body and tensor into the engine's parameter vector (lengths in units of a,
the ellipse's semi-axis or the footprint's extent ℓ); ``_wrench_nat`` gives the friction force
and moment per unit load for a velocity of G and a spin, through the compiled elliptic kernel
(MODEL §2–3) or the exact footprint kernel (MODEL §10). Used by
:mod:`slidespin.analysis.terminal` (eq. 14–16, the sphere flow of MODEL §5),
:mod:`slidespin.analysis.intervals` (Table 2) and :mod:`slidespin.analysis.phase_portrait`.
"""

from __future__ import annotations

import math

import numpy as np

from slidespin.contact import _engine
from slidespin.contact._kernel_ellipse import STATUS_OK, wrench_world
from slidespin.contact._kernel_footprint import wrench_array as fp_wrench_array
from slidespin.contact._kernel_footprint import wrench_world as fp_wrench_world
from slidespin.contact.body import require_thin

_WRENCH_TOL = 1e-13  # absolute target of the wrench quadrature (units of m g and m g a)


def _missed(par) -> str:
    """Message of the quadrature guard: only reached by a bug, since every input is checked."""
    return (
        f"terminal: the wrench quadrature missed its error target {_WRENCH_TOL:g} (b/a = "
        f"{par[_engine.P_BN]!r}, tensor [[{par[_engine.P_T00]!r}, {par[_engine.P_T01]!r}], "
        f"[{par[_engine.P_T10]!r}, {par[_engine.P_T11]!r}]], law {int(par[_engine.P_LAW])}); every input "
        "is inside its valid range (docs/errors.md), so this is a bug in slidespin: please "
        "report it"
    )


class _Par(np.ndarray):
    """The engine's parameter vector, carrying the footprint arrays (``fp``: (edges, circles,
    geo) in natural units, or None for an ellipse) to the wrench wrappers below."""

    fp = None


def _params(body, friction, tol=_WRENCH_TOL):
    """:meth:`slidespin.Body.engine_params` as one :class:`_Par` (natural units, ℓ = 1)."""
    require_thin(body, "the terminal analysis and fit")
    par, fe, fc, geo = body.engine_params(friction, tol)
    p = par.view(_Par)
    p.fp = (fe, fc, geo) if body.is_footprint else None
    return p


def _fp_world(par, phi, vx, vy, omega):
    """(Fx, Fy, M) per unit load on a footprint (exact kernel), arrays or scalars."""
    fe, fc, geo = par.fp
    args = (
        fe,
        fc,
        geo,
        par[_engine.P_T00],
        par[_engine.P_T01],
        par[_engine.P_T10],
        par[_engine.P_T11],
        par[_engine.P_BODY] != 0.0,
    )
    if np.ndim(vx) == 0:
        return fp_wrench_world(*args, float(phi), float(vx), float(vy), float(omega))
    return fp_wrench_array(*args, phi, vx, vy, omega)


def _wrench_nat(par, phi, vx, vy, omega):
    """(Fx, Fy, M) per unit load, a = 1, for a velocity of G (vx, vy) and spin ω."""
    if getattr(par, "fp", None) is not None:
        return _fp_world(par, phi, vx, vy, omega)
    fx, fy, m, st = wrench_world(
        *_engine.elliptic_args(par),
        phi,
        vx,
        vy,
        omega,
        _WRENCH_TOL,
    )
    if st != STATUS_OK or not (math.isfinite(fx) and math.isfinite(fy) and math.isfinite(m)):
        raise RuntimeError(_missed(par))  # pragma: no cover - guard
    return fx, fy, m
