"""Engine scenes built from a slidespin body: a flat body on a plane, as MuJoCo's MJCF.

:func:`mujoco_xml` writes the scene the tests, the benchmarks and the gallery run: a floor
plane (tilted about its y axis by ``incline``), and the body as a free body whose frame origin is
its mass centre G, its x axis the body axis ξ, its geoms prisms of the footprint of thickness
``thickness`` resting on the plane (a rectangle as a box, a disk as a cylinder, a ring as
``ring_segments`` boxes, an ellipse or a convex polygon as a mesh prism, pads as the union of
theirs). The inertia is explicit: the body's mass and its moment of inertia about the normal
(``Body.moment_of_inertia``, the plate's by default), and those of a plate of the
given thickness about the horizontal axes.

The contact: ``contact=None`` (the default, for a coupling) gives the body's geoms condim 1 (no
tangential friction: slidespin supplies it); ``contact={"friction": (μ, μ_torsion, μ_roll),
"condim": 4}`` (or 6) the engine's own elliptic-cone friction, with the parameters that
:func:`slidespin.engines.parameters.engine_parameters` fits.

May import: :mod:`slidespin.contact`; writes text only (no engine imported here).
"""

from __future__ import annotations

import math

import numpy as np

from slidespin import _validate as v
from slidespin.contact.body import Body
from slidespin.contact.ellipse import Ellipse
from slidespin.contact.shapes import Annulus, Pads, Polygon, Rectangle

__all__ = ["mujoco_xml", "prism_parts"]

#: sides of the polygon that stands for an ellipse in a mesh prism
ELLIPSE_SIDES = 64


def _f(x) -> str:
    return " ".join(f"{float(c):.17g}" for c in np.ravel(x))


def prism_parts(body: Body, ring_segments: int = 32) -> list[tuple]:
    """The body's footprint as engine primitives, positions relative to G (body frame) [m].

    Returns a list of ``("box", (cx, cy), angle, (half_length, half_width))``,
    ``("cylinder", (cx, cy), 0, (radius,))`` and ``("mesh", (0, 0), 0, vertices)`` (a convex
    prism's outline, an ``(n, 2)`` array relative to G). Raises ValueError naming ``body``
    for a footprint no prism represents (a non-convex polygon, a blade).
    """
    gx, gy = body.mass_centre
    out: list[tuple] = []

    def add(p) -> None:
        if isinstance(p, Pads):
            for q in p.patches:
                add(q)
        elif isinstance(p, Rectangle):
            c = (p.centre[0] - gx, p.centre[1] - gy)
            out.append(("box", c, float(p.angle), (p.length / 2.0, p.width / 2.0)))
        elif isinstance(p, Annulus):
            c = (p.centre[0] - gx, p.centre[1] - gy)
            if p.inner_radius == 0.0:
                out.append(("cylinder", c, 0.0, (p.outer_radius,)))
                return
            r_mid = 0.5 * (p.inner_radius + p.outer_radius)
            half_t = math.pi * r_mid / ring_segments * 1.02  # a little overlap
            half_w = 0.5 * (p.outer_radius - p.inner_radius)
            for k in range(ring_segments):
                a = 2.0 * math.pi * k / ring_segments
                pos = (c[0] + r_mid * math.cos(a), c[1] + r_mid * math.sin(a))
                out.append(("box", pos, a, (half_w, half_t)))
        elif isinstance(p, Ellipse):
            if p.a == p.b:
                out.append(("cylinder", (-gx, -gy), 0.0, (p.a,)))
                return
            t = np.linspace(0.0, 2.0 * math.pi, ELLIPSE_SIDES, endpoint=False)
            verts = np.column_stack([p.a * np.cos(t) - gx, p.b * np.sin(t) - gy])
            out.append(("mesh", (0.0, 0.0), 0.0, verts))
        elif isinstance(p, Polygon):
            verts = np.asarray(p.vertices, dtype=float)
            from scipy.spatial import ConvexHull  # lazy: only a polygon needs it

            hull = ConvexHull(verts)
            if not math.isclose(hull.volume, abs(_area(verts)), rel_tol=1e-9):
                raise ValueError(
                    f"body.patch = {v._short(p, 100)} is invalid for an engine scene: a "
                    "non-convex polygon; valid values: a convex polygon, a rectangle, a disk, "
                    "a ring, an ellipse or pads of them (build the engine's geometry yourself "
                    "for others)"
                )
            out.append(("mesh", (0.0, 0.0), 0.0, verts[hull.vertices] - [gx, gy]))
        else:
            raise ValueError(
                f"body.patch = {v._short(p, 100)} is invalid for an engine scene; valid values: "
                "Rectangle, Disk, Annulus, Ellipse, a convex Polygon or Pads of them"
            )

    add(body.patch)
    return out


def _area(verts) -> float:
    x, y = verts[:, 0], verts[:, 1]
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))


def mujoco_xml(
    body: Body,
    *,
    name: str = "body",
    thickness: float | None = None,
    incline: float = 0.0,
    timestep: float = 1e-3,
    contact: dict | None = None,
    ring_segments: int = 32,
    position: tuple[float, float] = (0.0, 0.0),
) -> str:
    """MJCF text of the body resting on a plane (see the module docstring).

    Parameters
    ----------
    body : Body
        The thin body (its footprint, mass, moment of inertia).
    name : str
        The MuJoCo body's name (its geoms are ``name_0``, ``name_1``, …).
    thickness : float or None
        Thickness of the prisms [m]; None: 0.2 × the body's length unit.
    incline : float
        Tilt α of the plane about its y axis [rad], in [0, π/2): downhill is the plane's +x.
    timestep : float
        The engine's step [s].
    contact : dict or None
        None: condim 1 (for a coupling); else ``{"friction": (μ, μ_t, μ_r), "condim": 4 or
        6}`` for the engine's own elliptic-cone friction on the body's geoms and the floor.
    ring_segments : int
        Boxes standing for a ring.
    position : (float, float)
        Start position of G on the plane (plane frame) [m].
    """
    if not isinstance(body, Body):
        raise TypeError(f"body = {body!r} is invalid; valid values: a slidespin.Body")
    ell = body.length_unit
    t = 0.2 * ell if thickness is None else v.positive("thickness", thickness, "m")
    alpha = v.bounded("incline", incline, 0.0, math.pi / 2 * (1 - 1e-9), "rad")
    dt = v.positive("timestep", timestep, "s")
    parts = prism_parts(body, ring_segments)
    if contact is None:
        gparams = 'condim="1"'
        floor = 'condim="1"'
    else:
        mu = tuple(float(c) for c in contact["friction"])
        condim = int(contact.get("condim", 4))
        if condim not in (3, 4, 6) or len(mu) != 3:
            raise ValueError(
                f"contact = {contact!r} is invalid; valid values: friction = (μ, μ_torsion, "
                "μ_roll) and condim 3, 4 or 6"
            )
        gparams = f'condim="{condim}" friction="{_f(mu)}"'
        floor = gparams
    m = body.mass
    izz = body.moment_of_inertia if body.moment_of_inertia is not None else body._inertia
    # a plate about its horizontal axes: half the polar inertia plus the thickness's share
    ixx = iyy = 0.5 * izz + m * t * t / 12.0
    assets, geoms = [], []
    for k, (kind, c, ang, size) in enumerate(parts):
        gname = f"{name}_{k}"
        if kind == "box":
            geoms.append(
                f'<geom name="{gname}" type="box" size="{_f(size)} {t / 2:.17g}" '
                f'pos="{_f(c)} 0" euler="0 0 {ang:.17g}" {gparams} mass="0"/>'
            )
        elif kind == "cylinder":
            geoms.append(
                f'<geom name="{gname}" type="cylinder" size="{size[0]:.17g} {t / 2:.17g}" '
                f'pos="{_f(c)} 0" {gparams} mass="0"/>'
            )
        else:
            verts = np.asarray(size)
            pts = np.vstack(
                [np.column_stack([verts, np.full(len(verts), -t / 2)]),
                 np.column_stack([verts, np.full(len(verts), t / 2)])]
            )  # fmt: skip
            assets.append(f'<mesh name="{gname}_mesh" vertex="{_f(pts)}"/>')
            geoms.append(
                f'<geom name="{gname}" type="mesh" mesh="{gname}_mesh" {gparams} mass="0"/>'
            )
    ca, sa = math.cos(alpha), math.sin(alpha)
    # G on the tilted plane: position (x, y) in the plane frame, t/2 along its normal
    px, py = position
    g_world = np.array([ca * px, py, -sa * px]) + (t / 2.0) * np.array([sa, 0.0, ca])
    return f"""<mujoco model="slidespin-{name}">
  <compiler angle="radian"/>
  <option timestep="{dt:.17g}" cone="elliptic" integrator="Euler"/>
  <asset>{"".join(assets)}</asset>
  <worldbody>
    <geom name="floor" type="plane" size="0 0 1" euler="0 {alpha:.17g} 0" {floor}/>
    <body name="{name}" pos="{_f(g_world)}" euler="0 {alpha:.17g} 0">
      <freejoint name="{name}_free"/>
      <inertial pos="0 0 0" mass="{m:.17g}" diaginertia="{ixx:.17g} {iyy:.17g} {izz:.17g}"/>
      {"".join(geoms)}
    </body>
  </worldbody>
</mujoco>
"""
