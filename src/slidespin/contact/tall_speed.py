"""A tall body under a speed-dependent law (MODEL §14), for free motion.

The pressure moves with the friction force as in :mod:`slidespin.contact.tall`, and the
speed-law kernel (:mod:`slidespin.contact._speed_wrench`) reads the moved pressure: the same
patch with the linear law of centroid r_p, G kept. Lift-off is not integrated here (a
centroid where the linear law turns negative raises
:class:`~slidespin.contact.tall.LiftOffUnsupported`), except in a pure translation, whose
wrench about G needs only the centroid.
"""

from __future__ import annotations

import math

import numpy as np

from slidespin.contact._speed_wrench import SpeedPatch, speed_patch, speed_wrench_one
from slidespin.contact.ellipse import Ellipse
from slidespin.contact.pressure import LinearPressure
from slidespin.contact.pressure_map import pressure_coefficients
from slidespin.contact.tall import LIFT_TOL, LiftOffUnsupported, _broyden, _lift_message

__all__ = ["TallSpeed"]


class TallSpeed:
    """A tall body's wrench under a speed-dependent law (MODEL §14), for free motion.

    The speed-law kernel (:mod:`slidespin.contact._speed_wrench`) takes the pressure's
    coefficients and G apart, so the pressure at r_p is the same patch with the linear law
    of centroid r_p (G kept); r_p = r_G − h F(r_p)/P is solved by Broyden's method as in
    :meth:`slidespin.contact.tall.TallContact.solve`. SI lengths (m) and unit load. The
    law's wrench at a pure translation does not depend on the pressure's shape (g(|v|) times
    the constant law's force, and the moment about G is (r_p − r_G) × F), so there r_p
    follows directly, lifted off or not. Lift-off under a speed law is not integrated: a
    centroid where the linear law turns negative raises :class:`LiftOffUnsupported`.
    """

    def __init__(self, body, friction, law_args, tol) -> None:
        self.base = speed_patch(body.patch, body.pressure)
        self.patch = body.patch
        self.h = body.height
        self.rg = self.base.g
        self.tensor = friction.matrix
        self.body_frame = friction.frame == "body"
        self.args = law_args
        self.tol = tol
        self.law = friction.speed_law
        self.kinetic = friction.kinetic.matrix
        self._dens = _density(self.base.pp, self.base.far_pts)
        self.worst = 0.0

    def _patch_at(self, r) -> SpeedPatch:
        patch = self.patch
        if isinstance(patch, Ellipse):
            a, b = patch.a, patch.b
            area = math.pi * a * b
            pp = np.array([1.0, 4.0 * r[0] / a**2, 4.0 * r[1] / b**2]) / area
            if 4.0 * math.hypot(r[0] / a, r[1] / b) > 1.0 + LIFT_TOL:
                raise LiftOffUnsupported(_lift_message(r, "this ellipse"))
        else:
            try:
                pp = np.array(pressure_coefficients(patch, LinearPressure(*r), 1.0))
            except ValueError:
                raise LiftOffUnsupported(
                    _lift_message(r, "this footprint under a speed law")
                ) from None
        base = self.base
        dens = _density(pp, base.far_pts)
        return SpeedPatch(base.edges, base.conics, base.pcode, pp, base.g, base.frame,
                          base.far_pts, base.far_w / self._dens * dens)  # fmt: skip

    def __call__(self, phi, vx, vy, omega, sigma=(0.0, 0.0)):
        """(Fx, Fy, M about G) per unit load [1, 1, m] and the pressure centroid r_p [m];
        ``sigma`` = Σ (h − h_Q) Q / P [m, body frame], the loads' tilt."""
        c, s = math.cos(phi), math.sin(phi)
        rg = (self.rg[0] - sigma[0], self.rg[1] - sigma[1])  # (where r_p sits without F)
        if omega == 0.0:
            sp = math.hypot(vx, vy)
            fw = self.tensor if not self.body_frame else _to_world(self.tensor, c, s)
            gv = float(self.law.factor(sp))
            fx = -gv * (fw[0, 0] * vx + fw[0, 1] * vy) / sp
            fy = -gv * (fw[1, 0] * vx + fw[1, 1] * vy) / sp
            fb = (c * fx + s * fy, -s * fx + c * fy)
            # (a translation's wrench about G needs only the centroid: lifted off or not)
            d = (rg[0] - self.h * fb[0] - self.rg[0], rg[1] - self.h * fb[1] - self.rg[1])
            dx, dy = c * d[0] - s * d[1], s * d[0] + c * d[1]
            return fx, fy, dx * fy - dy * fx, (self.rg[0] + d[0], self.rg[1] + d[1])

        def resid(r):
            fx, fy, m, err = speed_wrench_one(self._patch_at(r), self.tensor, self.body_frame,
                                              self.args, phi, vx, vy, omega, self.tol)  # fmt: skip
            self.worst = max(self.worst, err)
            fb = (c * fx + s * fy, -s * fx + c * fy)
            res = np.array([r[0] - rg[0] + self.h * fb[0], r[1] - rg[1] + self.h * fb[1]])
            return res, (fx, fy, m)

        # converged to the kernel's own accuracy (tol of the load, times h)
        scale = max(abs(self.rg[0]), abs(self.rg[1]), self.h)
        step_tol = max(1e-14 * scale, 10.0 * self.tol * self.h)
        return _broyden(resid, np.array(rg, dtype=float), np.eye(2), lambda xv: step_tol)


def _density(pp, pts):
    return pp[0] + pp[1] * pts[:, 0] + pp[2] * pts[:, 1]


def _to_world(tb, c, s):
    rot = np.array([[c, -s], [s, c]])
    return rot @ tb @ rot.T
