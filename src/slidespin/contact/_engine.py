"""The array form of a contact and the one compiled entry to the wrench kernels (MODEL §2, §9–10).

Every patch reaches the compiled kernels in one array form: the parameter vector ``par``
(``NPAR`` entries: the ellipse's b/a, pressure law and G; the friction tensor and its frame;
the radius of gyration k; the quadrature target; the shape flag and the symmetry flags) and,
for a footprint, the arrays (edges, circles, geo) of :mod:`slidespin.contact._kernel_footprint`
(``None`` in place of them for an ellipse). :meth:`slidespin.Body.engine_params` builds it.

:func:`accelerations` is the one compiled entry: it dispatches on the type of the footprint
argument when numba types the call (an ``overload``), so each compiled caller (the integrator,
the stop classification) holds only the kernel it needs. :class:`TwistWrench` is the same
dispatch for Python callers (statics, the stick–slip integrator, the limit surface): the
wrench W = (Fx, Fy, M about G) of a twist (vx, vy, ω) at body angle φ, in natural units
(unit normal load, lengths in the body's length unit ℓ = :attr:`slidespin.Body.length_unit`).
The elliptic kernel (:mod:`slidespin.contact._kernel_ellipse`) is a quadrature to ``tol``; the
footprint kernel (:mod:`slidespin.contact._kernel_footprint`, which hands a one-edge footprint,
a blade, to :mod:`slidespin.contact._kernel_blade`) is exact.
"""

from __future__ import annotations

import math

import numpy as np

from slidespin import _aot
from slidespin._jit import is_none_type, jit, overload
from slidespin.contact._kernel_ellipse import (
    STATUS_OK,
    wrench_constants,
    wrench_world,
    wrench_world_fast,
)
from slidespin.contact._kernel_ellipse_jac import jacobian_world
from slidespin.contact._kernel_footprint import NGEO
from slidespin.contact._kernel_footprint import wrench_world as fp_wrench_world
from slidespin.contact._kernel_footprint_jac import jacobian_world as fp_jacobian_world

__all__ = [
    "NPAR",
    "TwistWrench",
    "accelerations",
    "accelerations_jacobian",
    "elliptic_args",
    "footprint_argument",
    "kernel_constants",
    "no_footprint",
    "world_kernels",
]

# parameter vector layout
P_BN, P_LAW, P_XG, P_YG, P_T00, P_T01, P_T10, P_T11, P_BODY, P_K, P_WTOL = range(11)
# footprints (MODEL §10): P_SHAPE = SHAPE_FOOTPRINT selects the footprint kernel, which reads
# the arrays (edges, circles, geo) passed alongside ``par`` (lengths in the footprint's
# extent); P_CSYM = 1 if the pressure is centrally symmetric about G (pure spin about G is an
# invariant set), P_RSYM = 1 if it is axisymmetric about G (a centred disk or ring, uniform).
# For an ellipse these three are 0, the arrays are empty and unused.
P_SHAPE, P_CSYM, P_RSYM = 11, 12, 13


def elliptic_args(
    par: np.ndarray,
) -> tuple[float, int, float, float, float, float, float, float, bool]:
    """The elliptic kernel's body and tensor arguments from ``par``: (b/a, law, ξ_G, η_G,
    t00, t01, t10, t11, body frame), in the order of :func:`slidespin.contact._kernel_ellipse.wrench_world`
    and :func:`slidespin.contact._kernel_ellipse.wrench_array` (a Python helper, not compiled)."""
    return (
        par[P_BN],
        int(par[P_LAW]),
        par[P_XG],
        par[P_YG],
        par[P_T00],
        par[P_T01],
        par[P_T10],
        par[P_T11],
        par[P_BODY] != 0.0,
    )


NPAR = 14
SHAPE_ELLIPSE, SHAPE_FOOTPRINT = 0, 1


@jit(error_model="numpy")
def kernel_constants(par):
    """The wrench kernel's per-body constants for the parameter vector ``par``."""
    t00, t01, t10, t11 = par[P_T00], par[P_T01], par[P_T10], par[P_T11]
    return wrench_constants(
        par[P_BN],
        int(par[P_LAW]),
        par[P_XG],
        par[P_YG],
        math.sqrt(t00 * t00 + t01 * t01 + t10 * t10 + t11 * t11),
        par[P_WTOL],
    )


def accelerations(par, kc, W, fp, u1, u2, u3, phi):
    """A(u, φ) = (Fx, Fy, M/k)/(m g) in natural units, and the wrench status.

    ``kc`` are the kernel constants (:func:`kernel_constants`), ``W`` a kernel workspace;
    ``fp`` the footprint: ``None`` for the ellipse kernel, else the tuple (edges, circles,
    geo) of the exact footprint kernel (natural units, unit load), which is exact (status 0).
    From compiled code the choice is made when numba types the call (``overload`` on the
    type of ``fp``): each compiled caller holds one kernel. This body runs as Python only
    (``NUMBA_DISABLE_JIT=1``).
    """
    if fp is None:
        return _ellipse_accelerations(par, kc, W, fp, u1, u2, u3, phi)
    return _footprint_accelerations(par, kc, W, fp, u1, u2, u3, phi)


def _ellipse_accelerations(par, kc, W, fp, u1, u2, u3, phi):
    k = par[P_K]
    fx, fy, m, st = wrench_world_fast(
        int(par[P_LAW]),
        kc,
        par[P_T00],
        par[P_T01],
        par[P_T10],
        par[P_T11],
        par[P_BODY] != 0.0,
        phi,
        u1,
        u2,
        u3 / k,
        par[P_WTOL],
        W,
    )
    return fx, fy, m / k, st


def _footprint_accelerations(par, kc, W, fp, u1, u2, u3, phi):
    k = par[P_K]
    fe, fc, geo = fp
    fx, fy, m = fp_wrench_world(
        fe,
        fc,
        geo,
        par[P_T00],
        par[P_T01],
        par[P_T10],
        par[P_T11],
        par[P_BODY] != 0.0,
        phi,
        u1,
        u2,
        u3 / k,
    )
    return fx, fy, m / k, 0


@overload(accelerations, jit_options={"error_model": "numpy"})
def _accelerations_of_type(par, kc, W, fp, u1, u2, u3, phi):
    """Compiled calls of :func:`accelerations`: the kernel for the type of ``fp``."""
    return _ellipse_accelerations if is_none_type(fp) else _footprint_accelerations


def accelerations_jacobian(par, kc, W, fp, u1, u2, u3, phi, jo):
    """:func:`accelerations` with the wrench's exact derivatives, for the variational
    equations (MODEL §15): writes ``jo`` (``JAC_SIZE``) as
    :func:`slidespin.contact._kernel_ellipse_jac.jacobian_world` does for the twist
    (u1, u2, u3/k) (the wrench, its isotropic parts, its derivatives with respect to the
    twist and to φ) and returns (A₁, A₂, A₃, status, available). ``W`` is a derivative
    workspace (:func:`slidespin.contact._kernel_ellipse_jac.jac_workspace`). Where the derivative is not available (the ellipse's adaptive fallback; a
    blade; a translation of a footprint) ``available`` is False and the caller differences."""
    if fp is None:
        return _ellipse_jacobian(par, kc, W, fp, u1, u2, u3, phi, jo)
    return _footprint_jacobian(par, kc, W, fp, u1, u2, u3, phi, jo)


def _ellipse_jacobian(par, kc, W, fp, u1, u2, u3, phi, jo):
    k = par[P_K]
    st, ok = jacobian_world(
        int(par[P_LAW]),
        kc,
        par[P_T00],
        par[P_T01],
        par[P_T10],
        par[P_T11],
        par[P_BODY] != 0.0,
        phi,
        u1,
        u2,
        u3 / k,
        par[P_WTOL],
        W,
        jo,
    )
    return jo[0], jo[1], jo[2] / k, st, ok


def _footprint_jacobian(par, kc, W, fp, u1, u2, u3, phi, jo):
    k = par[P_K]
    fe, fc, geo = fp
    ok = fp_jacobian_world(
        fe,
        fc,
        geo,
        par[P_T00],
        par[P_T01],
        par[P_T10],
        par[P_T11],
        par[P_BODY] != 0.0,
        phi,
        u1,
        u2,
        u3 / k,
        jo,
    )
    return jo[0], jo[1], jo[2] / k, 0, ok


@overload(accelerations_jacobian, jit_options={"error_model": "numpy"})
def _accelerations_jacobian_of_type(par, kc, W, fp, u1, u2, u3, phi, jo):
    """Compiled calls of :func:`accelerations_jacobian`: the kernel for the type of ``fp``."""
    return _ellipse_jacobian if is_none_type(fp) else _footprint_jacobian


def footprint_argument(par, fe, fc, geo):
    """The footprint argument ``fp`` of the compiled functions for the parameter vector
    ``par`` and the footprint arrays of :meth:`slidespin.Body.kernel_params`: ``None`` for an
    ellipse (the arrays are ignored), else the tuple (edges, circles, geo) as C-contiguous
    float arrays (the types every caller passes: one compiled specialisation)."""
    if par[P_SHAPE] != SHAPE_FOOTPRINT:
        return None
    return (
        np.ascontiguousarray(fe, dtype=np.float64),
        np.ascontiguousarray(fc, dtype=np.float64),
        np.ascontiguousarray(geo, dtype=np.float64),
    )


def no_footprint():
    """The (edges, circles, geo) arguments for an elliptic patch: empty and unused."""
    return np.empty((0, 4)), np.empty((0, 4)), np.zeros(NGEO)


def world_kernels():
    """(ellipse, footprint) ``wrench_world`` for one twist, called from Python (the statics,
    :class:`TwistWrench`): the ahead-of-time compiled entries when the install built them
    (:mod:`slidespin._aot`; the same code, the same numbers; scalar arguments must then be
    Python floats, ints and bools, arrays C-contiguous float64), else the JIT's (which
    compiles the kernel on its first call)."""
    aot = _aot.core()
    if aot is None:
        return wrench_world, fp_wrench_world
    return aot.wrench_world_ellipse, aot.wrench_world_footprint


#: the elliptic kernel's error target (units of the load and load × ℓ)
TOL = 1e-13


class TwistWrench:
    """u ↦ W(u) at angle φ for one body and friction tensor (natural units).

    Attributes
    ----------
    par : ndarray
        The engine's parameter vector (:data:`slidespin.motion.NPAR` entries).
    edges, circles, geo : ndarray
        The footprint's arrays in units of ℓ (empty and unused for an ellipse).
    footprint : bool
        True for a footprint (``par[P_SHAPE] == SHAPE_FOOTPRINT``).
    k : float
        Radius of gyration √(I/m) in units of ℓ.
    """

    __slots__ = (
        "_args", "_fp_world", "_world", "circles", "edges", "footprint", "geo", "k", "par", "tol"
    )  # fmt: skip

    def __init__(self, body, friction, tol: float = TOL) -> None:
        par, fe, fc, geo = body.engine_params(friction, tol)
        self.par, self.edges, self.circles, self.geo = par, fe, fc, geo
        self.tol = tol
        self.k = float(par[P_K])
        self.footprint = bool(par[P_SHAPE] == SHAPE_FOOTPRINT)
        p = par
        self._args: tuple
        # the ahead-of-time compiled entries when the install built them (slidespin._aot):
        # the statics call this once per twist, and would otherwise compile the kernel
        ellipse_world, footprint_world = world_kernels()
        if self.footprint:
            self._args = (
                np.ascontiguousarray(fe, dtype=np.float64),
                np.ascontiguousarray(fc, dtype=np.float64),
                np.ascontiguousarray(geo, dtype=np.float64),
                float(p[P_T00]),
                float(p[P_T01]),
                float(p[P_T10]),
                float(p[P_T11]),
                bool(p[P_BODY] != 0.0),
            )
            self._fp_world = footprint_world
        else:
            bn, law, *rest, body_frame = elliptic_args(p)
            self._args = (float(bn), int(law), *(float(x) for x in rest), bool(body_frame))
            self._world = ellipse_world

    def __call__(
        self, phi: float, vx: float, vy: float, omega: float
    ) -> tuple[float, float, float]:
        """(Fx, Fy, M about G) per unit load (M per unit load × ℓ) of the twist (vx, vy, ω)
        [ℓ/time, ℓ/time, 1/time] at body angle ``phi`` [rad]; only its direction matters.

        Raises RuntimeError if the elliptic quadrature misses its target (never seen for
        valid inputs; the footprint kernel is exact)."""
        if self.footprint:
            fx, fy, m = self._fp_world(*self._args, phi, vx, vy, omega)
            return fx, fy, m
        fx, fy, m, st = self._world(*self._args, phi, vx, vy, omega, self.tol)
        if st != STATUS_OK:  # pragma: no cover - guard
            raise RuntimeError("the wrench quadrature missed its error target")
        return fx, fy, m
