"""The friction wrench of a twist at a body angle, for any patch (one dispatch, MODEL §2, §10).

The statics (:mod:`slidespin.statics`), the stick–slip integrator (:mod:`slidespin.loaded`)
and the limit surface need one operation: the sliding friction wrench W = (Fx, Fy, M about G)
of the twist (vx, vy, ω) at body angle φ, in natural units (unit normal load, lengths in the
body's length unit ℓ = :attr:`slidespin.Body.length_unit`). :class:`TwistWrench` holds the
compiled engine's parameters of a body (:meth:`slidespin.Body.engine_params`) and dispatches
on the shape flag as :func:`slidespin._ode.accelerations` does: the elliptic kernel
(:func:`slidespin._kernel.wrench_world`, quadrature to ``tol``) for an ellipse or circle, the
exact footprint kernel (:func:`slidespin._footprint_kernel.wrench_world`) for a footprint.
"""

from __future__ import annotations

from . import _ode
from ._footprint_kernel import wrench_world as fp_wrench_world
from ._kernel import STATUS_OK, wrench_world

__all__ = ["TwistWrench"]

#: the elliptic kernel's error target (units of the load and load × ℓ)
TOL = 1e-13


class TwistWrench:
    """u ↦ W(u) at angle φ for one body and friction tensor (natural units).

    Attributes
    ----------
    par : ndarray
        The engine's parameter vector (:data:`slidespin._ode.NPAR` entries).
    edges, circles, geo : ndarray
        The footprint's arrays in units of ℓ (empty and unused for an ellipse).
    footprint : bool
        True for a footprint (``par[P_SHAPE] == SHAPE_FOOTPRINT``).
    k : float
        Radius of gyration √(I/m) in units of ℓ.
    """

    __slots__ = ("_args", "circles", "edges", "footprint", "geo", "k", "par", "tol")

    def __init__(self, body, friction, tol: float = TOL) -> None:
        par, fe, fc, geo = body.engine_params(friction, tol)
        self.par, self.edges, self.circles, self.geo = par, fe, fc, geo
        self.tol = tol
        self.k = float(par[_ode.P_K])
        self.footprint = bool(par[_ode.P_SHAPE] == _ode.SHAPE_FOOTPRINT)
        p = par
        self._args: tuple
        if self.footprint:
            self._args = (
                fe,
                fc,
                geo,
                p[_ode.P_T00],
                p[_ode.P_T01],
                p[_ode.P_T10],
                p[_ode.P_T11],
                p[_ode.P_BODY] != 0.0,
            )
        else:
            self._args = (*_ode.elliptic_args(p),)

    def __call__(
        self, phi: float, vx: float, vy: float, omega: float
    ) -> tuple[float, float, float]:
        """(Fx, Fy, M about G) per unit load (M per unit load × ℓ) of the twist (vx, vy, ω)
        [ℓ/time, ℓ/time, 1/time] at body angle ``phi`` [rad]; only its direction matters.

        Raises RuntimeError if the elliptic quadrature misses its target (never seen for
        valid inputs; the footprint kernel is exact)."""
        if self.footprint:
            fx, fy, m = fp_wrench_world(*self._args, phi, vx, vy, omega)
            return fx, fy, m
        fx, fy, m, st = wrench_world(*self._args, phi, vx, vy, omega, self.tol)
        if st != STATUS_OK:  # pragma: no cover - guard
            raise RuntimeError("the wrench quadrature missed its error target")
        return fx, fy, m
