"""The limit surface: the friction wrenches of all motion directions (MODEL §11).

For a unit twist û = (vx, vy, ℓ ω)/|·| (ℓ a length scale) the sliding friction wrench W(û)
= (Fx, Fy, M about G) is that of MODEL §2; it depends on the direction only. The set
L = {W(û)} is the limit surface of planar-pushing work (Goyal, Ruina & Papadopoulos 1991).
For isotropic friction L bounds the static-friction set C of
:mod:`slidespin.contact.static_set` and the twist is normal to it (maximum dissipation:
−W(û)·û = h(û), the support function of C). For an anisotropic tensor τ = −p 𝔽 ŵ is not of
maximum dissipation and L may lie inside C;
``dissipation_gap`` = h(û) − (−W(û)·û) ≥ 0 reports by how much.

Every patch: the paper's ellipses and circles and the footprints of MODEL §10, a
``Blade`` (a line contact) included. The samples are
:func:`slidespin.friction_wrench`'s exact wrenches; the support h is that of
``slidespin.contact.static_set.static_support``.

Fits used in planar pushing, in the normalised wrench w = (Fx/P, Fy/P, M/(P ℓ)):

* ellipsoid  wᵀ A w = 1, A symmetric (6 coefficients; Lee & Cutkosky 1991, Howe & Cutkosky
  1996), least squares;
* convex quartic  H(w) = Σ_k c_k (n_k·w)⁴ = 1 with c_k ≥ 0 over a fixed set of directions
  n_k (a sum of fourth powers of linear forms is convex, so the fit is convex by
  construction; cf. the convex polynomial model of Zhou, Paolini, Bagnell & Mason 2017),
  non-negative least squares, returned as the 15 coefficients of the homogeneous quartic.

Each fit reports its radial error max |F(w_i)^(1/d) − 1| over the samples (d = 2, 4: the
relative distance of the sampled wrench from the fitted surface along its ray) and the
largest angle between the fitted surface's normal and the twist.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, field

import numpy as np
from scipy.optimize import nnls

from slidespin import _validate as v
from slidespin._validate import _short
from slidespin.contact._engine import TwistWrench
from slidespin.contact.body import Body, check_body_friction, require_constant_law
from slidespin.contact.friction import FrictionTensor
from slidespin.contact.incline import Incline
from slidespin.contact.static_set import check_anisotropy, static_support
from slidespin.contact.wrench import friction_wrench

__all__ = ["QUARTIC_EXPONENTS", "LimitSurface", "limit_surface", "sphere_directions"]

#: largest n (twist directions; each one kernel call, the fits grow linearly)
MAX_DIRECTIONS = 100_000
#: largest quartic_directions (the quartic's design matrix is n × quartic_directions)
MAX_QUARTIC_DIRECTIONS = 1_000

#: exponents (i, j, k) of the 15 monomials w₁ⁱ w₂ʲ w₃ᵏ of the quartic, in this order
QUARTIC_EXPONENTS = tuple((i, j, 4 - i - j) for i in range(4, -1, -1) for j in range(4 - i, -1, -1))


def sphere_directions(n: int) -> np.ndarray:
    """n nearly uniform unit vectors on the sphere (Fibonacci lattice), shape (n, 3)."""
    i = np.arange(n) + 0.5
    z = 1.0 - 2.0 * i / n
    r = np.sqrt(np.maximum(0.0, 1.0 - z * z))
    t = math.pi * (3.0 - math.sqrt(5.0)) * i
    return np.column_stack((r * np.cos(t), r * np.sin(t), z))


def _quartic_features(w):
    return np.column_stack(
        [w[:, 0] ** i * w[:, 1] ** j * w[:, 2] ** k for i, j, k in QUARTIC_EXPONENTS]
    )


def _quartic_value_grad(coef, w):
    val = _quartic_features(w) @ coef
    grad = np.zeros_like(w)
    for c, (i, j, k) in zip(coef, QUARTIC_EXPONENTS):
        if i:
            grad[:, 0] += c * i * w[:, 0] ** (i - 1) * w[:, 1] ** j * w[:, 2] ** k
        if j:
            grad[:, 1] += c * j * w[:, 0] ** i * w[:, 1] ** (j - 1) * w[:, 2] ** k
        if k:
            grad[:, 2] += c * k * w[:, 0] ** i * w[:, 1] ** j * w[:, 2] ** (k - 1)
    return val, grad


def _power4_to_monomials(dirs, weights):
    """Σ c_k (n_k·w)⁴ as the 15 monomial coefficients."""
    coef = np.zeros(len(QUARTIC_EXPONENTS))
    for idx, (i, j, k) in enumerate(QUARTIC_EXPONENTS):
        multi = math.factorial(4) // (math.factorial(i) * math.factorial(j) * math.factorial(k))
        coef[idx] = multi * np.sum(weights * dirs[:, 0] ** i * dirs[:, 1] ** j * dirs[:, 2] ** k)
    return coef


def _angle(a, b):
    c = np.sum(a * b, axis=1) / (np.linalg.norm(a, axis=1) * np.linalg.norm(b, axis=1))
    return np.arccos(np.clip(c, -1.0, 1.0))


@dataclass(frozen=True)
class LimitSurface:
    """Sampled limit surface with its ellipsoid and convex-quartic fits.

    Attributes
    ----------
    vx, vy, omega : ndarray
        Unit twist directions [m/s, m/s, rad/s], vx² + vy² + (ℓ ω)² = 1.
    force_x, force_y, moment : ndarray
        Exact friction wrenches [N, N, N m] (moment about G, counter-clockwise).
    support : ndarray
        h(û) [N·(m/s)]: the largest dissipation static friction could offer for the
        twist, the support function of C (MODEL §11).
    dissipation_gap : ndarray
        h(û) + W(û)·û ≥ 0 [N·(m/s)]: 0 for isotropic friction (maximum dissipation).
    length : float
        ℓ [m] of the twist and wrench normalisation.
    normal_load : float
        P [N].
    ellipsoid : ndarray, shape (3, 3)
        A with wᵀ A w = 1 on the fitted surface, w = (Fx/P, Fy/P, M/(P ℓ)).
    ellipsoid_error, ellipsoid_normal_error : float
        Largest radial error |√(wᵀAw) − 1| and largest angle [rad] between A w and the twist.
    quartic : ndarray, shape (15,)
        Coefficients of the convex quartic over ``QUARTIC_EXPONENTS``.
    quartic_error, quartic_normal_error : float
        Largest radial error |H(w)^(1/4) − 1| and normal angle [rad].
    """

    vx: np.ndarray
    vy: np.ndarray
    omega: np.ndarray
    force_x: np.ndarray
    force_y: np.ndarray
    moment: np.ndarray
    support: np.ndarray
    dissipation_gap: np.ndarray
    length: float
    normal_load: float
    ellipsoid: np.ndarray
    ellipsoid_error: float
    ellipsoid_normal_error: float
    quartic: np.ndarray
    quartic_error: float
    quartic_normal_error: float
    phi: float = 0.0
    body: Body | None = field(default=None, repr=False)
    friction: FrictionTensor | None = field(default=None, repr=False)

    def __repr__(self) -> str:
        return (
            f"LimitSurface(n={self.vx.size}, phi={self.phi:.6g} rad, "
            f"normal_load={self.normal_load:.6g} N, length={self.length:.6g} m, "
            f"ellipsoid_error={self.ellipsoid_error:.3g}, "
            f"quartic_error={self.quartic_error:.3g}, "
            f"max_dissipation_gap={float(np.max(self.dissipation_gap)):.3g})"
        )

    @property
    def twists(self) -> np.ndarray:
        """(n, 3) unit twists (vx, vy, ℓ ω)."""
        return np.column_stack((self.vx, self.vy, self.length * self.omega))

    @property
    def wrenches(self) -> np.ndarray:
        """(n, 3) normalised wrenches w = (Fx/P, Fy/P, M/(P ℓ))."""
        p, ell = self.normal_load, self.length
        return np.column_stack((self.force_x / p, self.force_y / p, self.moment / (p * ell)))

    def summary(self) -> dict:
        """Fit parameters and errors as a JSON-ready dict."""
        return {
            "n": int(self.vx.size),
            "phi": self.phi,
            "length": self.length,
            "normal_load": self.normal_load,
            "max_force": float(np.max(np.hypot(self.force_x, self.force_y))),
            "max_moment": float(np.max(np.abs(self.moment))),
            "max_dissipation_gap": float(np.max(self.dissipation_gap)),
            "ellipsoid": self.ellipsoid.tolist(),
            "ellipsoid_error": self.ellipsoid_error,
            "ellipsoid_normal_error": self.ellipsoid_normal_error,
            "quartic_exponents": [list(e) for e in QUARTIC_EXPONENTS],
            "quartic": self.quartic.tolist(),
            "quartic_error": self.quartic_error,
            "quartic_normal_error": self.quartic_normal_error,
        }

    def to_json(self, path=None, *, samples: bool = True) -> str:
        """Write (or return) the summary, with the samples unless ``samples=False``."""
        d = self.summary()
        if samples:
            for name in (
                "vx",
                "vy",
                "omega",
                "force_x",
                "force_y",
                "moment",
                "support",
                "dissipation_gap",
            ):
                d[name] = getattr(self, name).tolist()
        text = json.dumps(d, indent=2)
        if path is not None:
            with open(path, "w", encoding="utf-8") as fh:
                fh.write(text + "\n")
        return text

    def arrays(self) -> dict:
        """Every array and the fits, as written by :meth:`to_npz`."""
        return {
            "vx": self.vx,
            "vy": self.vy,
            "omega": self.omega,
            "force_x": self.force_x,
            "force_y": self.force_y,
            "moment": self.moment,
            "support": self.support,
            "dissipation_gap": self.dissipation_gap,
            "length": self.length,
            "normal_load": self.normal_load,
            "ellipsoid": self.ellipsoid,
            "quartic": self.quartic,
            "quartic_exponents": np.array(QUARTIC_EXPONENTS),
        }

    def to_npz(self, path) -> None:
        """Write every array and the fits to a NumPy ``.npz`` file."""
        np.savez(path, **self.arrays())

    def plot(self, ax=None):
        """3-D figure: the sampled wrenches (coloured by ω) and the fitted ellipsoid.

        At most 5 ticks per axis (a long thin patch has a narrow force range and a wide
        moment range, whose default ticks crowd), the axis labels pushed clear of the tick
        labels, and the colour bar set apart to the right so that it hides no label.

        Returns the matplotlib ``Axes3D``.
        """
        import matplotlib.pyplot as plt  # lazy: matplotlib is slow to import, needed only to draw
        from matplotlib.ticker import MaxNLocator

        if ax is None:
            fig = plt.figure(figsize=(7.4, 5.8))
            ax = fig.add_subplot(projection="3d")
        w = self.wrenches
        sc = ax.scatter(
            w[:, 0],
            w[:, 1],
            w[:, 2],
            c=self.length * self.omega,
            cmap="coolwarm",
            s=8,
            depthshade=False,
        )
        # the fitted ellipsoid wᵀAw = 1 as a wireframe
        vals, vecs = np.linalg.eigh(self.ellipsoid)
        if np.all(vals > 0):
            uu, vv = np.meshgrid(np.linspace(0, 2 * np.pi, 37), np.linspace(0, np.pi, 19))
            sph = np.stack((np.cos(uu) * np.sin(vv), np.sin(uu) * np.sin(vv), np.cos(vv)))
            pts = np.einsum("ij,jkl->ikl", vecs @ np.diag(1.0 / np.sqrt(vals)), sph)
            ax.plot_wireframe(pts[0], pts[1], pts[2], color="0.6", linewidth=0.4)
        for axis in (ax.xaxis, ax.yaxis, ax.zaxis):
            axis.set_major_locator(MaxNLocator(nbins=4, min_n_ticks=3))
        ax.tick_params(labelsize=8, pad=1)
        ax.set_xlabel("$F_x/P$", labelpad=6)
        ax.set_ylabel("$F_y/P$", labelpad=6)
        ax.set_zlabel("$M/(P\\ell)$", labelpad=6)
        ax.set_title(
            f"limit surface, ℓ = {self.length:.4g} m\n(ellipsoid error "
            f"{self.ellipsoid_error:.2%}, quartic {self.quartic_error:.2%})",
            fontsize=9,
        )
        # the colour bar well to the right of the 3-D box: a 3-D axes' z label sits outside
        # its box, where a colour bar at the default pad would cover it
        ax.figure.colorbar(sc, ax=ax, shrink=0.55, pad=0.14, label="ℓω of the twist")
        return ax


def limit_surface(
    body: Body,
    friction: FrictionTensor,
    n: int = 400,
    phi: float = 0.0,
    g: float = 9.81,
    *,
    length: float | None = None,
    incline: Incline | None = None,
    quartic_directions: int = 200,
) -> LimitSurface:
    """Sample the limit surface of ``body`` and fit an ellipsoid and a convex quartic.

    Parameters
    ----------
    body, friction : Body, FrictionTensor
        The body and its friction tensor.
    n : int, default 400
        Number of twist directions (a Fibonacci lattice on the unit sphere of
        (vx, vy, ℓ ω)), ≥ 10.
    phi : float, default 0
        Body angle [rad] (matters for non-circular patches and body-fixed tensors).
    g : float, default 9.81
        Gravitational acceleration [m/s²].
    length : float or None
        ℓ [m]; default the radius of gyration √(I/m).
    incline : Incline or None
        A slope scales the normal load P = m g cos α.
    quartic_directions : int, default 200
        Number of directions n_k in the convex-quartic dictionary.

    Returns
    -------
    LimitSurface

    Examples
    --------
    >>> from slidespin import Body, Circle, UniformPressure, FrictionTensor
    >>> disk = Body(Circle(0.1), UniformPressure(), mass=1.0)
    >>> ls = limit_surface(disk, FrictionTensor(0.3, 0.3), n=50, g=10.0)
    >>> round(float(ls.dissipation_gap.max()), 10)  # isotropic: maximum dissipation
    0.0
    """
    check_body_friction(body, friction)
    require_constant_law(friction, "limit_surface (the wrenches of unit twists)")
    check_anisotropy(body, friction, "limit_surface")
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or not 10 <= n <= MAX_DIRECTIONS:
        raise ValueError(
            f"n = {_short(n)} is invalid; valid range: integer in [10, {MAX_DIRECTIONS}]"
        )
    if (
        isinstance(quartic_directions, bool)
        or not isinstance(quartic_directions, (int, np.integer))
        or not 6 <= quartic_directions <= MAX_QUARTIC_DIRECTIONS
    ):
        raise ValueError(
            f"quartic_directions = {_short(quartic_directions)} is invalid; valid range: "
            f"integer in [6, {MAX_QUARTIC_DIRECTIONS}]"
        )
    phi = v.finite("phi", phi)
    g = v.bounded("g", g, *v.GRAVITY, "m/s^2")
    ell = body.radius_of_gyration if length is None else v.bounded("length", length, *v.LENGTH, "m")
    if incline is not None and not isinstance(incline, Incline):
        raise ValueError(f"incline = {incline!r} is invalid; valid values: an Incline or None")
    nf = 1.0 if incline is None else incline.normal_factor
    load = body.mass * g * nf
    u = sphere_directions(int(n))
    vx, vy, om = u[:, 0], u[:, 1], u[:, 2] / ell
    w = friction_wrench(body, friction, vx, vy, om, phi, g)
    fx, fy, mz = (np.asarray(x) * nf for x in (w.force_x, w.force_y, w.moment))
    # support function of C for the wrench direction d = twist
    a = body.length_unit
    sup = static_support(TwistWrench(body, friction, 1e-13), friction, phi)
    h = np.array([sup(np.array([x, y, o * a]))[0] for x, y, o in zip(vx, vy, om)]) * load
    gap = np.maximum(h + (fx * vx + fy * vy + mz * om), 0.0)

    wn = np.column_stack((fx / load, fy / load, mz / (load * ell)))
    # ellipsoid wᵀ A w = 1
    feats = np.column_stack(
        (
            wn[:, 0] ** 2,
            wn[:, 1] ** 2,
            wn[:, 2] ** 2,
            2 * wn[:, 0] * wn[:, 1],
            2 * wn[:, 0] * wn[:, 2],
            2 * wn[:, 1] * wn[:, 2],
        )
    )
    c, *_ = np.linalg.lstsq(feats, np.ones(len(wn)), rcond=None)
    amat = np.array([[c[0], c[3], c[4]], [c[3], c[1], c[5]], [c[4], c[5], c[2]]])
    q2 = np.einsum("ni,ij,nj->n", wn, amat, wn)
    ell_err = float(np.max(np.abs(np.sqrt(np.maximum(q2, 0.0)) - 1.0)))
    ell_nerr = float(np.max(_angle(wn @ amat, -u)))  # W(û) has outward normal −û
    # convex quartic Σ c_k (n_k·w)⁴, c_k ≥ 0
    dirs = sphere_directions(2 * int(quartic_directions))
    dirs = dirs[dirs[:, 2] > 0.0]  # ±n give the same term
    dirs = np.vstack((dirs, np.eye(3)))
    design = (wn @ dirs.T) ** 4
    weights, _ = nnls(design, np.ones(len(wn)), maxiter=50 * design.shape[1])
    coef = _power4_to_monomials(dirs, weights)
    val, grad = _quartic_value_grad(coef, wn)
    q_err = float(np.max(np.abs(np.maximum(val, 0.0) ** 0.25 - 1.0)))
    q_nerr = float(np.max(_angle(grad, -u)))
    return LimitSurface(
        vx=vx,
        vy=vy,
        omega=om,
        force_x=fx,
        force_y=fy,
        moment=mz,
        support=h,
        dissipation_gap=gap,
        length=float(ell),
        normal_load=float(load),
        ellipsoid=amat,
        ellipsoid_error=ell_err,
        ellipsoid_normal_error=ell_nerr,
        quartic=coef,
        quartic_error=q_err,
        quartic_normal_error=q_nerr,
        phi=phi,
        body=body,
        friction=friction,
    )
