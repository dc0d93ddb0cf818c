"""Fuzz of the public functions and constructors added after tests/test_fuzz.py (issue 11):
footprints, pressure maps, loads and inclines, static friction, the stick–slip engine, the
limit surface, fitting and animation.

The rules are those of tests/test_fuzz.py, whose helpers are reused: any input either gives a
``ValueError`` whose one-line message names the parameter, or a result whose floats are all
finite (unless the documentation gives a non-finite value a meaning, noted at each check);
never another exception, never a hang (an interval timer for Python code, ``faulthandler``
for compiled code). Each example draws every argument valid, or one of them (chosen per
example) from the junk of tests/test_fuzz.py, so that about half the calls reach the
numerics.

Known failures are kept twice: as explicit regression tests at the end of this module,
marked ``xfail(strict=True)`` with the input and the outcome (they turn into failures the day
the library is fixed, so that the mark and the matching filter are removed), and as
predicates passed to :func:`known`, with which the fuzz rejects just those inputs, so that it
keeps hunting for new failures instead of finding the known ones again. Inputs that could
exhaust the machine (a hang that allocates memory) run only in a subprocess with limits.
"""

from __future__ import annotations

import math
import os
import subprocess
import sys
import warnings

import numpy as np
import pytest
from hypothesis import HealthCheck, event, given, reject, settings
from hypothesis import strategies as st

import slidespin as ss
from slidespin.contact.shapes import is_footprint
from slidespin.contact.wrench import footprint_wrench
import test_fuzz
from slidespin.analysis import fit as ssfit
from slidespin.analysis import fit_data
from slidespin.viz.animate import animate
from test_fuzz import (
    EXAMPLES,
    FINITE,
    FUZZ,
    Hang,
    bodies,
    finite_everywhere,
    frictions,
    log_uniform,
    numbers,
    states,
    time_limit,
)

API = settings(FUZZ, suppress_health_check=list(HealthCheck))


def call(fn, names, *args, **kwargs):
    """test_fuzz.call, with the arguments in the message of a hang (Hypothesis does not
    report the example of a BaseException)."""
    try:
        return test_fuzz.call(fn, names, *args, **kwargs)
    except Hang as err:
        raise Hang(
            f"{err}: {getattr(fn, '__qualname__', fn)}(*{args!r}, **{kwargs!r})"[:4000]
        ) from None


def budget(divisor):
    """Examples for a test that costs ``divisor`` times a cheap one (at least 4)."""
    return settings(API, max_examples=max(EXAMPLES // divisor, 4))


class Args:
    """Draws the arguments of one call: all valid, or one of them (chosen per example) junk."""

    def __init__(self, data, *names):
        self.data = data
        self.bad = data.draw(
            st.sampled_from((None,) * max(2, len(names)) + names), label="junk argument"
        )

    def __call__(self, label, valid, junk=numbers):
        return self.data.draw(junk if label == self.bad else valid, label=label)


# ------------------------------------------------------------------------------------------
# known failures (each has an xfail regression test below; remove both once fixed)
# ------------------------------------------------------------------------------------------
def _real(x):
    return isinstance(x, (int, float, np.integer, np.floating)) and not isinstance(
        x, (bool, np.bool_)
    )


def _magnitudes(obj):
    """Absolute values of every real number inside ``obj`` (nested tuples and lists)."""
    if _real(obj):
        try:
            yield abs(float(obj))
        except OverflowError:
            yield math.inf
    elif isinstance(obj, (tuple, list)):
        for x in obj:
            yield from _magnitudes(x)


def _as_float_array(x):
    """``np.asarray(x, dtype=float)`` succeeds."""
    try:
        np.asarray(x, dtype=float)
    except (TypeError, ValueError, OverflowError):
        return False
    return True


def known(condition, label):
    """Reject an input that hits a known failure (named in the statistics)."""
    if condition:
        event(f"known failure skipped: {label}")
        reject()


def outside(x, lo, hi):
    """``x`` is a finite positive real outside [lo, hi] (accepted by a bare positivity check)."""
    return _real(x) and math.isfinite(float(x)) and 0.0 < float(x) and not lo <= float(x) <= hi


def far_centre(centre, size):
    """The placement moves the footprint more than 1e5 of its size (its digits are lost)."""
    return size > 0.0 and any(m > 1e5 * size for m in _magnitudes(centre))


def anisotropic(friction, body=None):
    """fx/fy or fy/fx, times the patch's a/b or b/a, beyond 1e4 (the static-friction
    quadrature misses its target)."""
    if not isinstance(friction, ss.FrictionTensor):
        return False
    ratio = max(friction.fx, friction.fy) / min(friction.fx, friction.fy)
    if isinstance(body, ss.Body) and isinstance(body.patch, ss.Ellipse):
        ratio *= max(body.patch.a / body.patch.b, body.patch.b / body.patch.a)
    return ratio > 1e4


STATICS_ANISOTROPY = "fx/fy beyond 1e4 (test_known_statics_anisotropy)"


@pytest.fixture(scope="module", autouse=True)
def warm_up():
    """Load (or compile) the kernels once, outside the time limits."""
    body = ss.Body(ss.Circle(0.05), ss.UniformPressure(), 1.0)
    fr = ss.FrictionTensor(0.3, 0.4)
    ss.friction_wrench(body, fr, 1.0, 0.0, 1.0)
    box = ss.Body(ss.Rectangle(0.1, 0.05), ss.UniformPressure(), 1.0)
    ss.friction_wrench(box, fr, 1.0, 0.0, 1.0)
    ss.simulate(box, fr, ss.State(vx=0.1), max_steps=20)
    ss.simulate(body, fr, ss.State(), load=ss.Load((1.0, 0.0)), t_end=0.01, max_steps=20)
    # a slip under a load: the compiled loaded engine of an ellipse and of a footprint
    for b in (body, box):
        ss.simulate(b, fr, ss.State(), load=ss.Load((10.0, 0.0)), t_end=0.01, max_steps=20)
    ss.onset(body, fr, (10.0, 0.0, 0.0))


# ------------------------------------------------------------------------------------------
# footprints
# ------------------------------------------------------------------------------------------
# footprint sizes: lengths in [1e-9, 1e6] m (docs/errors.md), with room for a star polygon's
# smaller radii (0.3 size) and for three pads spaced 3 sizes apart
SIZE = st.one_of(st.sampled_from([1e-8, 1e5, 0.05, 1.0]), log_uniform(1e-8, 1e5))
ANGLE = st.one_of(st.just(0.0), st.floats(-10.0, 10.0), FINITE)
junk_pairs = st.one_of(numbers, st.tuples(numbers, numbers), st.lists(numbers, max_size=3))


def centres(size):
    return st.tuples(st.floats(-5.0, 5.0), st.floats(-5.0, 5.0)).map(
        lambda c: (c[0] * size, c[1] * size)
    )


@st.composite
def star_vertices(draw, size):
    """A simple polygon: 3–8 vertices, one in each of n equal sectors (in its first 80 %), at
    radii in [0.3, 1] × size, in either orientation."""
    n = draw(st.integers(3, 8))
    cuts = draw(st.lists(st.floats(0.0, 0.8), min_size=n, max_size=n))
    rad = draw(st.lists(st.floats(0.3, 1.0), min_size=n, max_size=n))
    pts = [
        (
            r * size * math.cos(2 * math.pi * (k + c) / n),
            r * size * math.sin(2 * math.pi * (k + c) / n),
        )
        for k, (c, r) in enumerate(zip(cuts, rad))
    ]
    if draw(st.booleans()):
        pts.reverse()
    return pts


@st.composite
def simple_patches(draw, centre=(0.0, 0.0), size=None):
    """A valid Polygon, Rectangle, Disk or Annulus of about ``size`` at ``centre``."""
    size = draw(SIZE) if size is None else size
    kind = draw(st.sampled_from(["polygon", "rectangle", "disk", "annulus"]))
    angle = draw(st.floats(-4.0, 4.0))
    if kind == "polygon":
        return ss.Polygon(draw(star_vertices(size)), centre, angle)
    if kind == "rectangle":
        return ss.Rectangle(size, size * draw(st.floats(0.1, 1.0)), centre, angle)
    if kind == "disk":
        return ss.Disk(size, centre)
    return ss.Annulus(size * draw(st.one_of(st.just(0.0), st.floats(0.2, 0.95))), size, centre)


@st.composite
def footprints(draw):
    """A simple patch, or Pads of 1–3 disjoint ones (spaced 3 sizes apart)."""
    size = draw(SIZE)
    if draw(st.booleans()):
        return draw(simple_patches(size=size))
    k = draw(st.integers(1, 3))
    return ss.Pads([draw(simple_patches((3.0 * size * i, 0.0), size)) for i in range(k)])


def check_footprint(fp):
    finite_everywhere(
        (
            fp.area,
            fp.centroid,
            fp.second_moment,
            fp.extent,
            fp.polar_moment,
            tuple(fp.to_arrays()),
            fp.outlines(16),
        ),
        where=type(fp).__name__,
    )
    assert fp.area > 0.0 and fp.extent > 0.0
    finite_everywhere(call(fp.plate_inertia, ("mass",), 1.0), where="plate_inertia")


@API
@given(data=st.data())
def test_polygon(data):
    args = Args(data, "vertices", "centre", "angle")
    size = data.draw(SIZE, label="size")
    vertices = args(
        "vertices",
        star_vertices(size),
        st.one_of(
            numbers,
            st.lists(junk_pairs, max_size=5),
            st.lists(st.tuples(FINITE, FINITE), max_size=6),
        ),
    )
    centre = args("centre", centres(size), junk_pairs)
    angle = args("angle", ANGLE)
    p = call(ss.Polygon, ("vertices", "centre", "angle"), vertices, centre, angle)
    if p is not None:
        check_footprint(p)
        finite_everywhere((p.points, p.triangles(), p.outline()))


@API
@given(data=st.data(), kind=st.sampled_from(["rectangle", "disk", "annulus"]))
def test_rectangle_disk_annulus(data, kind):
    size = data.draw(SIZE, label="size")
    if kind == "rectangle":
        args = Args(data, "length", "width", "centre", "angle")
        dims = (args("length", st.just(size)), args("width", SIZE))
        names = ("length", "width", "centre", "angle")
    elif kind == "disk":
        args = Args(data, "radius", "centre", "angle")
        dims = (args("radius", st.just(size)),)
        names = ("radius", "centre", "angle")
    else:
        args = Args(data, "inner_radius", "outer_radius", "centre", "angle")
        dims = (
            args("inner_radius", st.floats(0.0, 0.999).map(lambda k: k * size)),
            args("outer_radius", st.just(size)),
        )
        names = ("inner_radius", "outer_radius", "centre", "angle")
    centre = args("centre", centres(size), junk_pairs)
    angle = args("angle", ANGLE)
    cls = {"rectangle": ss.Rectangle, "disk": ss.Disk, "annulus": ss.Annulus}[kind]
    p = call(cls, names, *dims, centre, angle)
    if p is not None:
        check_footprint(p)
        if kind == "rectangle":
            finite_everywhere((p.as_polygon().points, p.triangles()))


@API
@given(data=st.data())
def test_pads(data):
    size = data.draw(SIZE, label="size")
    k = data.draw(st.integers(0, 4), label="k")
    spacing = data.draw(
        st.sampled_from([3.0, 3.0, 3.0, 1.0, 0.0]), label="spacing"
    )  # 1, 0: overlap
    items = []
    for i in range(k):
        if data.draw(st.integers(0, 9), label="junk pad") == 9:
            items.append(data.draw(st.one_of(numbers, st.just(ss.Circle(0.1))), label="pad"))
        else:
            items.append(data.draw(simple_patches((spacing * size * i, 0.0), size), label="pad"))
    if k >= 2 and data.draw(st.booleans(), label="nest") and is_footprint(items[0]):
        items = [ss.Pads(items[:1])] + items[1:]
    patches = data.draw(st.one_of(st.just(items), st.just(tuple(items)), numbers), label="patches")
    p = call(ss.Pads, ("patches",), patches)
    if p is not None:
        check_footprint(p)
        assert abs(p.area - sum(q.area for q in p.patches)) <= 1e-9 * p.area


@budget(3)
@given(data=st.data())
def test_pressure_map(data):
    fp = data.draw(footprints(), label="footprint")
    ell = fp.extent
    cx, cy = fp.centroid
    kind = data.draw(st.sampled_from(["function", "grid", "junk"]), label="kind")
    if kind == "function":
        slope = data.draw(st.floats(-0.5, 0.5), label="slope")
        f = data.draw(
            st.sampled_from(
                [
                    lambda x, y: 1.0 + slope * (x - cx) / ell,
                    lambda x, y: np.exp(-(((y - cy) / ell) ** 2)),
                    lambda x, y: 1.0 + 0.0 * x,
                ]
            ),
            label="function",
        )
        pm = call(ss.PressureMap, ("function",), f)
    elif kind == "grid":
        args = Args(data, "xi", "eta", "values")
        n = data.draw(st.integers(3, 6), label="n")  # 3: refused (at least 4)
        xi = args("xi", st.just(list(np.linspace(cx - 2 * ell, cx + 2 * ell, n))))
        eta = args("eta", st.just(list(np.linspace(cy - 2 * ell, cy + 2 * ell, n))))
        values = args("values", st.just(np.ones((n, n))))
        pm = call(ss.PressureMap.from_grid, ("xi", "eta", "values"), xi, eta, values)
    else:
        pm = call(ss.PressureMap, ("function",), data.draw(numbers, label="function"))
        assert pm is None
    if pm is None:
        return
    args = Args(data, "map_tol", "footprint", "pressure")
    friction = data.draw(frictions, label="friction")
    vx = data.draw(st.floats(-1.0, 1.0), label="vx")
    vy = data.draw(st.floats(-1.0, 1.0), label="vy")
    omega = data.draw(st.floats(-1.0, 1.0), label="omega") / ell
    map_tol = args("map_tol", st.one_of(st.just(1e-9), log_uniform(1e-9, 1e-3)))
    footprint = args("footprint", st.just(fp))
    pressure = args("pressure", st.just(pm))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # a documented accuracy warning
        w = call(
            footprint_wrench,
            ("map_tol", "footprint", "pressure"),
            footprint,
            pressure,
            friction,
            vx,
            vy,
            omega,
            0.0,
            1.0,
            map_tol=map_tol,
        )
    if w is not None:
        finite_everywhere(w)


# ------------------------------------------------------------------------------------------
# the footprint wrench, footprint bodies and their motion
# ------------------------------------------------------------------------------------------
@st.composite
def footprint_laws(draw, fp):
    """Uniform, or linear with G within a tenth of the extent of the area centroid."""
    if draw(st.booleans()):
        return ss.UniformPressure()
    cx, cy = fp.centroid
    r = draw(st.floats(0.0, 0.1)) * fp.extent
    t = draw(st.floats(0.0, 2.0 * math.pi))
    try:
        return ss.LinearPressure(cx + r * math.cos(t), cy + r * math.sin(t))
    except ValueError:  # G beyond the bound of LinearPressure (|xi_c|, |eta_c| <= 2.5e5 m)
        return ss.UniformPressure()


finite_arrays = st.one_of(
    FINITE,
    st.lists(FINITE, min_size=1, max_size=4),
    st.sampled_from([0.0, 5e-324, 1e-300, 1e300, -1.7976931348623157e308]),
)
MASS = st.one_of(st.sampled_from([1e-12, 1e12, 1.0]), log_uniform(1e-12, 1e12))
I_STAR = st.one_of(st.sampled_from([1e-8, 1e8]), log_uniform(1e-8, 1e8))
G = st.one_of(st.just(9.81), log_uniform(1e-6, 1e6))


@API
@given(data=st.data())
def test_footprint_wrench(data):
    args = Args(data, "footprint", "pressure", "friction", "vx", "vy", "omega", "phi", "load")
    fp = args("footprint", footprints())
    law = args(
        "pressure",
        footprint_laws(fp) if is_footprint(fp) else st.just(ss.UniformPressure()),
    )
    friction = args("friction", frictions)
    vx, vy, omega = (args(n, finite_arrays) for n in ("vx", "vy", "omega"))
    phi = args("phi", st.one_of(st.just(0.0), finite_arrays))
    load = args("load", st.one_of(st.just(1.0), log_uniform(1e-12, 1e12)))
    names = (
        "footprint",
        "pressure",
        "friction",
        "vx",
        "vy",
        "omega",
        "phi",
        "load",
        "broadcast",
        "LinearPressure(",
    )
    w = call(footprint_wrench, names, fp, law, friction, vx, vy, omega, phi, load)
    if w is None:
        return
    finite_everywhere(w)
    # dissipative: F·v + M ω ≤ 0 (MODEL §2), velocities scaled to unit size
    u = np.broadcast_arrays(*(np.asarray(x, float) for x in (vx, vy, omega)))
    big = np.maximum(np.maximum(np.abs(u[0]), np.abs(u[1])), np.abs(u[2]))
    big = np.where(big > 0.0, big, 1.0)
    ux, uy, uw = u[0] / big, u[1] / big, u[2] / big * fp.extent
    top = np.maximum(np.maximum(np.abs(ux), np.abs(uy)), np.abs(uw))
    top = np.where(top > 0.0, top, 1.0)
    p = (
        np.asarray(w.force_x) * ux / top
        + np.asarray(w.force_y) * uy / top
        + np.asarray(w.moment) / fp.extent * uw / top
    ) / load
    assert np.all(p <= 1e-9), p


@budget(2)
@given(data=st.data())
def test_footprint_body_and_simulate(data):
    args = Args(
        data, "patch", "pressure", "mass", "moment_of_inertia", "initial_state", "g", "max_steps"
    )
    fp = args("patch", footprints())
    law = args(
        "pressure",
        footprint_laws(fp) if is_footprint(fp) else st.just(ss.UniformPressure()),
    )
    mass = args("mass", MASS)
    inertia = None
    if data.draw(st.booleans(), label="explicit inertia"):
        ok = _real(mass) and is_footprint(fp)
        i_star = data.draw(I_STAR, label="I*")
        inertia = args(
            "moment_of_inertia", st.just(i_star * float(mass) * fp.extent**2 if ok else 1.0)
        )
    # a linear law that turns negative on the footprint is named by its repr
    body = call(
        ss.Body,
        ("patch", "pressure", "mass", "moment_of_inertia", "LinearPressure("),
        fp,
        law,
        mass,
        inertia,
    )
    if body is None:
        return
    finite_everywhere(
        (
            body.mass,
            body.moment_of_inertia,
            body.inertia_ratio,
            body.radius_of_gyration,
            body.mass_centre,
            body.length_unit,
        )
    )
    friction = data.draw(frictions, label="friction")
    state = args("initial_state", states)
    g = args("g", G)
    max_steps = args("max_steps", st.integers(1, 300))
    if _real(max_steps) and 300 < max_steps < 2**62:
        max_steps = 300  # a budget, not a test of patience
    tr = call(
        ss.simulate,
        ("initial_state", "g =", "g must", "max_steps"),
        body,
        friction,
        state,
        g=g,
        max_steps=max_steps,
    )
    if tr is None:
        return
    for name in (
        "t",
        "x",
        "y",
        "phi",
        "vx",
        "vy",
        "omega",
        "speed",
        "tangential",
        "normal",
        "moment_paper",
    ):
        assert np.all(np.isfinite(getattr(tr, name))), name
    assert math.isfinite(tr.t_stop) and tr.t_stop >= 0.0
    finite_everywhere(tr.stop_state.as_array())


# ------------------------------------------------------------------------------------------
# loads and inclines
# ------------------------------------------------------------------------------------------
FORCE = st.one_of(st.just(0.0), st.floats(-1e3, 1e3), FINITE)
pairs = st.tuples(FORCE, FORCE)


@API
@given(data=st.data())
def test_load(data):
    args = Args(data, "force", "torque", "frame", "at")
    force = args("force", st.one_of(pairs, st.just(lambda t: (t, 0.0))), junk_pairs)
    torque = args("torque", st.one_of(FORCE, st.just(lambda t: 0.5 * t)))
    frame = args(
        "frame", st.sampled_from(["plane", "body", "Body"]), st.one_of(numbers, st.just("world"))
    )
    at = args("at", st.one_of(st.none(), pairs), junk_pairs)
    load = call(ss.Load, ("force", "torque", "frame", "at"), force, torque, frame, at)
    if load is not None:
        t = data.draw(st.floats(0.0, 1e3), label="t")
        phi = data.draw(st.floats(-10.0, 10.0), label="phi")
        # a huge force far from G may overflow the moment: refused by name when evaluated
        w = call(load.wrench, ("force", "torque", "at"), t, phi, (0.01, -0.02))
        if w is not None:
            finite_everywhere((w, load.force_at(t), load.torque_at(t)))
    args = Args(data, "times", "fx", "fy", "torque")
    n = data.draw(st.integers(1, 4), label="n")  # 1: refused (at least 2)
    times = args("times", st.just(list(np.linspace(0.0, 1.0, n))))
    fx = args("fx", st.lists(FORCE, min_size=n, max_size=n))
    fy = args("fy", st.lists(FORCE, min_size=n, max_size=n))
    torque = args("torque", st.one_of(st.none(), st.lists(FORCE, min_size=n, max_size=n)))
    pl = call(ss.Load.piecewise_linear, ("times", "fx", "fy", "torque"), times, fx, fy, torque)
    if pl is not None:
        # the interpolant of huge samples may overflow between them: refused when evaluated
        for fn, a in (
            (pl.force_at, (0.5,)),
            (pl.torque_at, (0.5,)),
            (pl.wrench, (2.0, 1.0, (1.0, 2.0))),
        ):
            finite_everywhere(call(fn, ("force", "torque"), *a))


@API
@given(data=st.data())
def test_incline(data):
    args = Args(data, "angle", "downhill")
    angle = args("angle", st.floats(0.0, math.pi / 2.0, exclude_max=True))
    downhill = args("downhill", ANGLE)
    inc = call(ss.Incline, ("angle", "downhill"), angle, downhill)
    if inc is not None:
        finite_everywhere(
            (
                inc.normal_factor,
                inc.downhill_factor,
                inc.direction,
                inc.gravity_force(data.draw(MASS, label="mass"), data.draw(G, label="g")),
            )
        )
        assert inc.normal_factor > 0.0


# ------------------------------------------------------------------------------------------
# static friction
# ------------------------------------------------------------------------------------------
FOOTPRINT_BODY = ss.Body(ss.Rectangle(0.1, 0.05), ss.UniformPressure(), 1.0)
body_junk = st.one_of(numbers, st.just(FOOTPRINT_BODY))  # footprints: refused, "body.patch"
STATIC_NAMES = ("body", "friction", "applied_wrench", "phi", "g =", "g must", "incline", "downhill")
incline_values = st.one_of(
    st.none(), st.builds(ss.Incline, st.floats(0.0, 1.5), st.floats(-4.0, 4.0))
)


def wrenches(body):
    """Applied wrenches up to 5 m g (force) and 5 m g ℓ (moment), or zero."""
    scale, arm = (body.mass * 9.81, body.length_unit) if isinstance(body, ss.Body) else (1, 1)
    unit = st.floats(-5.0, 5.0)
    return st.one_of(
        st.tuples(unit, unit, unit).map(lambda w: (w[0] * scale, w[1] * scale, w[2] * scale * arm)),
        st.just((0.0, 0.0, 0.0)),
        st.tuples(FORCE, FORCE, FORCE),
    )


def static_args(data, onset=False):
    args = Args(data, "body", "friction", "applied_wrench", "phi", "g", "incline")
    body = args("body", bodies(), body_junk)
    friction = args("friction", frictions)
    wrench = args(
        "applied_wrench",
        wrenches(body),
        st.one_of(junk_pairs, st.lists(numbers, min_size=3, max_size=3)),
    )
    phi = args("phi", st.floats(-10.0, 10.0))
    g = args("g", G)
    incline = args("incline", incline_values)
    return body, friction, wrench, phi, g, incline


def _tiny(wrench, body, g):
    """The wrench is below 1e-290 m g: λ* = μ m g/|W| overflows (inf is its float value)."""
    return all(
        abs(float(x)) <= 1e-290 * body.mass * float(g) * min(body.length_unit, 1.0) for x in wrench
    )


@budget(2)
@given(data=st.data())
def test_load_factor_and_can_stick(data):
    body, friction, wrench, phi, g, incline = static_args(data)
    lam = call(ss.load_factor, STATIC_NAMES, body, friction, wrench, phi, g, incline=incline)
    if lam is None:
        return
    # documented: inf for a zero load
    assert (math.isfinite(lam) and lam > 0.0) or (lam == math.inf and _tiny(wrench, body, g)), (
        lam,
        wrench,
    )
    stick = call(ss.can_stick, STATIC_NAMES, body, friction, wrench, phi, g, incline=incline)
    assert stick is (lam >= 1.0)


@budget(3)
@given(data=st.data())
def test_onset(data):
    body, friction, wrench, phi, g, incline = static_args(data, onset=True)
    o = call(ss.onset, STATIC_NAMES, body, friction, wrench, phi, g, incline=incline)
    event(f"onset: {'slips' if o is not None else 'holds or refused'}")
    if o is not None:  # None: the body holds (documented)
        finite_everywhere(o)
        assert o.acceleration > 0.0


@budget(2)
@given(data=st.data())
def test_critical_tilt(data):
    args = Args(data, "body", "friction", "downhill", "phi")
    body = args("body", bodies(), body_junk)
    friction = args("friction", frictions)
    downhill = args("downhill", ANGLE)
    phi = args("phi", st.floats(-10.0, 10.0))
    a = call(ss.critical_tilt, STATIC_NAMES, body, friction, downhill, phi)
    if a is not None:
        assert math.isfinite(a) and 0.0 < a < math.pi / 2.0, a


# ------------------------------------------------------------------------------------------
# simulate with loads, inclines, t_end (the stick–slip engine)
# ------------------------------------------------------------------------------------------
@budget(2)
@given(data=st.data())
def test_simulate_loaded(data):
    args = Args(
        data, "body", "friction", "initial_state", "load", "incline", "t_end", "g", "max_steps"
    )
    body = args("body", bodies(), body_junk)
    friction = args("friction", frictions)
    a = body.length_unit if isinstance(body, ss.Body) else 1.0
    unit = st.one_of(st.just(0.0), st.floats(-10.0, 10.0))
    state = args(
        "initial_state",
        st.builds(
            lambda x, y, phi, vx, vy, w: ss.State(
                x * a,
                y * a,
                phi,
                vx * math.sqrt(9.81 * a),
                vy * math.sqrt(9.81 * a),
                w * math.sqrt(9.81 / a),
            ),
            st.floats(-1e3, 1e3),
            st.floats(-1e3, 1e3),
            st.floats(-10.0, 10.0),
            unit,
            unit,
            unit,
        ),
        st.one_of(numbers, states),
    )  # states: the whole range of State (fast ones skipped)
    scale = body.mass * 9.81 if isinstance(body, ss.Body) else 1.0
    load = args(
        "load",
        st.one_of(
            st.none(),
            st.builds(
                ss.Load,
                st.tuples(st.floats(-2.0, 2.0), st.floats(-2.0, 2.0)).map(
                    lambda f: (f[0] * scale, f[1] * scale)
                ),
            ),
            st.just(ss.Load(force=lambda t: (scale * min(t, 1.0), 0.0))),
        ),
    )
    incline = args("incline", incline_values)
    t_end = args(
        "t_end",
        st.one_of(log_uniform(1e-6, 0.2), st.none())
        if not isinstance(load, ss.Load) or load.is_constant
        else log_uniform(1e-6, 0.2),
    )
    g = args("g", G)
    max_steps = args("max_steps", st.integers(1, 200))
    if _real(max_steps) and 200 < max_steps:
        max_steps = 200  # a budget, not a test of patience
    if load is None and incline is None and t_end is None:
        t_end = 0.01  # the loaded engine, not the plain one (test_fuzz.py)
    names = (
        "body",
        "friction",
        "initial_state",
        "load",
        "incline",
        "t_end",
        "g =",
        "g must",
        "max_steps",
    )
    tr = call(
        ss.simulate,
        names,
        body,
        friction,
        state,
        g=g,
        max_steps=max_steps,
        load=load,
        incline=incline,
        t_end=t_end,
    )
    if tr is None:
        return
    for name in (
        "t",
        "x",
        "y",
        "phi",
        "vx",
        "vy",
        "omega",
        "kinetic_energy",
        "friction_work",
        "load_work",
    ):
        assert np.all(np.isfinite(getattr(tr, name))), name
    finite_everywhere((tr.energy_error, tr.gravity_work))


# ------------------------------------------------------------------------------------------
# limit surface
# ------------------------------------------------------------------------------------------
COUNT_JUNK = st.sampled_from(
    [9, 5, 0, -1, 10.0, 2.5, "20", None, True, math.nan, 1j, 2**63, 10**400]
)


@budget(4)
@given(data=st.data())
def test_limit_surface(data):
    args = Args(
        data, "body", "friction", "n", "phi", "g", "length", "incline", "quartic_directions"
    )
    body = args("body", bodies(), body_junk)
    friction = args("friction", frictions)
    n = args("n", st.integers(10, 24), COUNT_JUNK)
    phi = args("phi", st.floats(-10.0, 10.0))
    g = args("g", G)
    k = body.radius_of_gyration if isinstance(body, ss.Body) else 1.0
    length = args("length", st.one_of(st.none(), log_uniform(1e-3, 1e3).map(lambda x: x * k)))
    incline = args("incline", incline_values)
    quartic = args("quartic_directions", st.integers(6, 20), COUNT_JUNK)

    names = (
        "body",
        "friction",
        "n =",
        "phi",
        "g =",
        "g must",
        "length",
        "incline",
        "quartic_directions",
    )
    ls = call(
        ss.limit_surface,
        names,
        body,
        friction,
        n,
        phi,
        g,
        length=length,
        incline=incline,
        quartic_directions=quartic,
    )
    if ls is not None:
        finite_everywhere(ls, allowed=("body", "friction"))
        assert np.all(ls.dissipation_gap >= 0.0)


# ------------------------------------------------------------------------------------------
# fitting
# ------------------------------------------------------------------------------------------
_FIT_BODY = ss.Body(ss.Circle(0.05), ss.UniformPressure(), 1.0)
_FIT_FRICTION = ss.FrictionTensor(0.3, 0.35)


def _tiny_run():
    tr = ss.simulate(_FIT_BODY, _FIT_FRICTION, ss.State(vx=0.5, omega=3.0), max_step=0.2)
    t = np.linspace(0.0, 0.8 * tr.t_stop, 6)
    return {
        "t": t,
        "x": np.interp(t, tr.t, tr.x),
        "y": np.interp(t, tr.t, tr.y),
        "phi": np.interp(t, tr.t, tr.phi),
    }


CELLS = st.one_of(
    st.sampled_from(
        ["", "nan", "inf", "-inf", "1e400", "x", " 1.5 ", "0x10", "1,2", '"3"', "\x00", "é"]
    ),
    FINITE.map(repr),
    st.text(max_size=4),
)


@budget(2)
@given(data=st.data())
def test_read_runs(data, tmp_path_factory):
    cols = data.draw(
        st.one_of(
            st.just(["t", "x", "y", "phi"]),
            st.just(["t", "x", "run"]),
            st.lists(st.sampled_from(["t", "x", "y", "phi", "run", "T", "z", ""]), max_size=5),
        ),
        label="header",
    )
    nrows = data.draw(st.integers(0, 5), label="rows")
    rows = [
        [str(0.1 * i) if c == "t" else ("a" if c == "run" else str(0.01 * i)) for c in cols]
        for i in range(nrows)
    ]
    if rows and data.draw(st.booleans(), label="spoil a cell"):
        i = data.draw(st.integers(0, nrows - 1), label="row")
        k = data.draw(st.integers(0, len(cols)), label="column")
        rows[i] = rows[i][:k] + [data.draw(CELLS, label="value")] + rows[i][k + 1 :]
    text = "\n".join(",".join(r) for r in [cols] + rows) + "\n"
    raw = (
        data.draw(st.binary(max_size=20), label="raw bytes")
        if data.draw(st.integers(0, 5), label="bytes") == 5
        else None
    )
    path = tmp_path_factory.mktemp("runs") / "runs.csv"
    if raw is None:
        path.write_text(text, encoding="utf-8")
    else:
        path.write_bytes(raw)
    where = data.draw(
        st.sampled_from(["file", "file", "file", "missing", "directory"]), label="path kind"
    )
    target = {"file": path, "missing": path.with_name("none.csv"), "directory": path.parent}[where]
    runs = call(fit_data.read_runs, ("data file", str(path.parent)), target)
    event(f"read_runs: {where}, {'raw bytes' if raw is not None else 'text'}")
    if runs is not None:
        for r in runs:
            assert np.all(np.isfinite(r["t"]))
            for c in ("x", "y", "phi"):
                if c in r:  # NaN marks a missing value (documented); never ±inf
                    assert not np.any(np.isinf(r[c]))


@pytest.fixture(scope="module")
def tiny_run():
    return _tiny_run()


@budget(6)
@given(data=st.data())
def test_fit(data, tiny_run):
    args = Args(
        data,
        "data",
        "body",
        "friction",
        "free",
        "loss",
        "g",
        "rtol",
        "fd_step",
        "sigma",
        "max_nfev",
    )
    run = {k: v.copy() for k, v in tiny_run.items()}
    spoil = (
        data.draw(st.sampled_from(["none", "t", "x", "column", "empty"]), label="spoil")
        if args.bad == "data"
        else "none"
    )
    if spoil == "t":
        run["t"][2] = data.draw(
            st.sampled_from([math.nan, math.inf, run["t"][1], -1.0]), label="t value"
        )
    elif spoil == "x":
        run["x"][1] = data.draw(st.sampled_from([math.inf, -math.inf]), label="x value")
    elif spoil == "column":
        run["z"] = run["x"]
    elif spoil == "empty":
        run = []
    body = args("body", st.just(_FIT_BODY), st.one_of(numbers, st.just(FOOTPRINT_BODY)))
    friction = args("friction", st.just(_FIT_FRICTION))
    free = args(
        "free",
        st.sampled_from([("fx", "fy"), "fx", "fx,f"]),
        st.one_of(numbers, st.sampled_from([("mu",), (), ("fx", "fx")])),
    )
    loss = args("loss", st.sampled_from(["linear", "huber"]), st.one_of(numbers, st.just("l2")))
    g = args("g", st.just(9.81))
    rtol = args("rtol", st.just(1e-10))
    fd_step = args("fd_step", st.just(1e-4))
    sigma = args(
        "sigma",
        st.one_of(st.none(), st.just({"x": 1e-4})),
        st.one_of(numbers, st.sampled_from([{"q": 1.0}, {"x": -1.0}, {"x": "a"}])),
    )
    max_nfev = args("max_nfev", st.just(2), st.sampled_from([0, -1, 2.5, True, "3", 2**70]))
    names = (
        "data",
        "body",
        "friction",
        "free",
        "loss",
        "g =",
        "g must",
        "rtol",
        "fd_step",
        "sigma",
        "max_nfev",
        "column",
        "run",
    )
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # FitWarning, IdentifiabilityWarning: documented
        res = call(
            ssfit.fit,
            names,
            run,
            body,
            friction,
            free,
            loss=loss,
            g=g,
            rtol=rtol,
            fd_step=fd_step,
            sigma=sigma,
            max_nfev=max_nfev,
        )
    if res is not None:
        # documented: an unidentifiable parameter gets an infinite standard error (and
        # covariance); the estimates, the start states and the fit statistics are finite
        finite_everywhere(
            (
                res.values,
                tuple(res.estimates.values()),
                res.chi2,
                tuple(res.rms.values()),
                tuple(s.as_array() for s in res.starts),
            )
        )


# ------------------------------------------------------------------------------------------
# animation: bad arguments only (nothing is rendered)
# ------------------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def short_trajectory():
    return ss.simulate(_FIT_BODY, _FIT_FRICTION, ss.State(vx=0.2, omega=2.0))


@API
@given(data=st.data())
def test_animate_bad_arguments(data, short_trajectory, tmp_path_factory):
    d = tmp_path_factory.mktemp("anim")
    (d / "sub.gif").mkdir()
    ok = str(d / "run.gif")
    bad = data.draw(
        st.sampled_from(["path", "fps", "frames", "dpi", "trajectory"]), label="bad argument"
    )

    def out_of(lo, hi):
        return st.one_of(
            st.integers(-(10**6), 10**6).filter(lambda x: not lo <= x <= hi),
            numbers.filter(
                lambda x: (
                    not (
                        isinstance(x, (int, np.integer))
                        and not isinstance(x, (bool, np.bool_))
                        and lo <= x <= hi
                    )
                )
            ),
        )

    path = data.draw(
        st.one_of(
            st.sampled_from(
                [
                    str(d / "run.png"),
                    str(d),
                    str(d / "no" / "run.gif"),
                    "",
                    str(d / "sub.gif"),
                    str(d / "run.GIF.txt"),
                ]
            ),
            numbers,
        )
        if bad == "path"
        else st.just(ok),
        label="path",
    )
    fps = data.draw(out_of(1, 50) if bad == "fps" else st.just(20), label="fps")
    frames = data.draw(out_of(2, 120) if bad == "frames" else st.just(2), label="frames")
    dpi = data.draw(out_of(20, 300) if bad == "dpi" else st.just(20), label="dpi")
    traj = data.draw(
        st.one_of(numbers, st.just(ss.State()))
        if bad == "trajectory"
        else st.just(short_trajectory),
        label="trajectory",
    )
    out = call(animate, (bad,), traj, path, fps, frames, dpi=dpi)
    assert out is None, f"the bad {bad} was accepted"
    assert not os.path.exists(ok)


# ------------------------------------------------------------------------------------------
# regression tests: the known failures, one input each (xfail strict: when the library is
# fixed, remove the mark and the matching ``known`` filter above; test_regression_* are
# failures found here and fixed since)
# ------------------------------------------------------------------------------------------
B = ss.Body(ss.Circle(0.05), ss.UniformPressure(), 1.0)
F = ss.FrictionTensor(0.3, 0.4)


def clean(fn, names, *args, allowed=(), soft=20, **kwargs):
    """The issue-11 contract for one call: a ValueError naming one of ``names``, or a result
    whose floats are all finite (``allowed``: documented non-finite attributes)."""
    try:
        with time_limit(soft=soft):
            out = fn(*args, **kwargs)
    except ValueError as err:
        msg = str(err)
        assert any(n in msg for n in names), (names, msg)
        assert "\n" not in msg, msg
        return None
    except Hang as err:  # a BaseException: turn it into a plain failure for xfail
        pytest.fail(f"hang: {err}")
    finite_everywhere(out, allowed)
    return out


def xfail(reason):
    return pytest.mark.xfail(strict=True, reason=reason)


def test_regression_footprint_scale_tiny_rectangle():
    """Fixed (was a strict xfail): Rectangle(1e-300, 1e-300).area raises ZeroDivisionError (footprint._frame divides by  the area, which underflows to 0); no footprint dimension is range-checked"""
    r = clean(ss.Rectangle, ("length", "width"), 1e-300, 1e-300)
    if r is not None:
        clean(lambda: r.area, ("length", "width"))


def test_regression_footprint_scale_tiny_annulus():
    """Fixed (was a strict xfail): Annulus(0.0, 5e-324).area raises ZeroDivisionError (area underflows to 0)"""
    r = clean(ss.Annulus, ("inner_radius", "outer_radius"), 0.0, 5e-324)
    if r is not None:
        clean(lambda: r.area, ("outer_radius",))


def test_regression_footprint_scale_huge_disk():
    """Fixed (was a strict xfail): Disk(1e300).area silently returns inf (pi r^2 overflows); so do second_moment and  plate_inertia for any dimension beyond ~1e77 (r^4 overflows)"""
    d = clean(ss.Disk, ("radius",), 1e300)
    if d is not None:
        clean(lambda: (d.area, d.second_moment, d.plate_inertia(1.0)), ("radius",))


def test_regression_footprint_scale_body_huge():
    """Fixed (was a strict xfail): Body(Rectangle(1e300, 1.0), ...) was accepted with
    moment_of_inertia = nan; the footprint's dimensions are now range-checked."""
    body = clean(
        lambda: ss.Body(ss.Rectangle(1e300, 1.0), ss.UniformPressure(), 1.0),
        ("patch", "length", "moment_of_inertia"),
    )
    if body is not None:
        clean(lambda: (body.inertia_ratio, body.radius_of_gyration), ("patch",))


def test_regression_footprint_scale_body_tiny():
    """Fixed (was a strict xfail): Body(Disk(1e-160), ...) was accepted with
    moment_of_inertia = 0.0, far outside I* in [1e-8, 1e8]."""
    body = clean(
        lambda: ss.Body(ss.Disk(1e-160), ss.UniformPressure(), 1.0),
        ("patch", "radius", "moment_of_inertia"),
    )
    if body is not None:
        assert body.moment_of_inertia > 0.0 and 1e-8 <= body.inertia_ratio <= 1e8


def test_regression_footprint_far_centre():
    """Fixed (was a strict xfail): Polygon([(3e-10, 0), (0, 3e-10), (-3e-10, 0)], centre=(0.0, 8388609.0)).area raises  ZeroDivisionError (found by test_polygon): the placed vertices collapse to round-off  of the centre (simplicity and area are checked before placement)"""
    p = clean(
        ss.Polygon,
        ("vertices", "centre"),
        [(3e-10, 0.0), (0.0, 3e-10), (-3e-10, 0.0)],
        (0.0, 8388609.0),
    )
    if p is not None:
        clean(lambda: p.area, ("vertices", "centre"))


def test_regression_rectangle_aspect():
    """Fixed (was a strict xfail): Rectangle(1e8, 1e-9, angle=1.0).area raises ZeroDivisionError (found by  test_rectangle_disk_annulus): the shoelace area of an aspect-1e17 rectangle cancels  to 0; no aspect bound"""
    r = clean(ss.Rectangle, ("length", "width"), 1e8, 1e-9, (0.0, 0.0), 1.0)
    if r is not None:
        clean(lambda: r.area, ("length", "width"))


def test_regression_rectangle_aspect_triangles():
    """Fixed (was a strict xfail): Rectangle(1e-9, 1e5) is accepted, but its triangles() (and as_polygon()) raise  ValueError 'vertices: edges 1 and 3 of the polygon intersect' about vertices the  user never gave: Polygon's tolerances refuse the rectangle's own corners"""
    r = clean(ss.Rectangle, ("length", "width"), 1e-9, 1e5)
    if r is not None:
        clean(r.triangles, ("length", "width"))


def test_regression_statics_anisotropy():
    """Fixed (was a strict xfail): load_factor(B, FrictionTensor(1e-6, 5.0), (9.81, 0.0, 0.4905)) and onset(...) raise  RuntimeError 'statics: the wrench quadrature missed its error target' (found by  test_load_factor_and_can_stick): the static-friction support function fails for  fx/fy beyond ~1e4, inside FrictionTensor's range"""
    clean(ss.load_factor, ("friction",), B, ss.FrictionTensor(1e-6, 5.0), (9.81, 0.0, 0.4905))


def test_regression_statics_anisotropy_limit_surface():
    """Fixed (was a strict xfail): limit_surface(B, FrictionTensor(5e-5, 5.0), n=30) raises RuntimeError 'statics: the  wrench quadrature missed its error target' (found by test_limit_surface; 5e-4 works)"""
    clean(ss.limit_surface, ("friction",), B, ss.FrictionTensor(5e-5, 5.0), 30)


def test_regression_statics_anisotropy_aspect():
    """Fixed (was a strict xfail): limit_surface(Body(Ellipse(1.0, 1e-3), UniformPressure(), 1.0), FrictionTensor(1e-6,  0.01), n=10) raises the same RuntimeError (found by test_limit_surface): fx/fy = 1e-4  with b/a = 1e-3 (FrictionTensor(0.01, 1e-6) works)"""
    clean(
        ss.limit_surface,
        ("friction", "body"),
        ss.Body(ss.Ellipse(1.0, 1e-3), ss.UniformPressure(), 1.0),
        ss.FrictionTensor(1e-6, 0.01),
        10,
    )


def test_regression_fit_fd_step(tiny_run):
    """fd_step=5e-324 once gave scipy's 'array must not contain infs or NaNs'."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        clean(
            ssfit.fit,
            ("fd_step",),
            tiny_run,
            _FIT_BODY,
            _FIT_FRICTION,
            ("fx", "fy"),
            fd_step=5e-324,
            max_nfev=2,
        )


def test_regression_from_grid_non_numeric():
    """A string grid once gave 'could not convert string to float', naming nothing."""
    clean(ss.PressureMap.from_grid, ("xi",), "abc", [0, 1, 2, 3], np.ones((4, 4)))


def test_regression_footprint_wrench_huge_velocity():
    """Fixed (was a strict xfail): the speed |v| overflowed to NaN; the velocity triple is
    now scaled first, as in friction_wrench."""
    clean(
        footprint_wrench,
        ("vx", "vy"),
        ss.Disk(0.05),
        ss.UniformPressure(),
        F,
        -1.7976931348623157e308,
        5.274575347766127e307,
        0.0,
        1.0,
    )


@pytest.mark.parametrize(
    "fx", [[1j, 0.0], ["", 0.0], [10**400, 0.0]], ids=["complex", "string", "huge-int"]
)
def test_regression_piecewise_non_numeric(fx):
    """Fixed (was a strict xfail): complex, string and huge-int samples raised TypeError,
    an unnamed ValueError or OverflowError."""
    clean(ss.Load.piecewise_linear, ("fx",), [0.0, 1.0], fx, [0.0, 0.0])


def test_regression_load_overflow():
    """Fixed (was a strict xfail): Load(force=(1e308, 1e308), torque=1e308, at=(1e308, 1e308)).wrench(0.0, 0.3)  returns moment = nan silently (r x Q overflows, inf - inf); Load accepts any finite  force, torque and point"""
    load = clean(ss.Load, ("force", "torque", "at"), (1e308, 1e308), 1e308, "plane", (1e308, 1e308))
    if load is not None:
        clean(load.wrench, ("force", "torque", "at"), 0.0, 0.3)


def test_regression_incline_gravity_force():
    """Fixed (was a strict xfail): Incline(1.5707963267948963).gravity_force(1e300, 1e300) returns (inf, nan): mass  and g are not checked"""
    clean(ss.Incline(1.5707963267948963).gravity_force, ("mass", "g"), 1e300, 1e300)


def test_regression_statics_scale_huge_wrench():
    """Fixed (was a strict xfail): load_factor(B, F, (1e308, 0, 0)) returns nan silently (the natural-unit wrench  overflows in the optimiser)"""
    clean(ss.load_factor, ("applied_wrench",), B, F, (1e308, 0.0, 0.0))


def test_regression_statics_scale_huge_g():
    """Fixed (was a strict xfail): load_factor(B, F, (1, 0, 0), g=1e300) returns nan silently: the statics take any  g > 0 (v.positive), unlike simulate's [1e-6, 1e6]"""
    clean(ss.load_factor, ("g =", "g must"), B, F, (1.0, 0.0, 0.0), g=1e300)


def test_regression_statics_tiny_wrench():
    """Fixed (was a strict xfail): load_factor(B, F, (1e-200, 0, 0)) returns nan silently (1e-160 still gives  2.95e160; the documented value for a zero load is inf)"""
    clean(ss.load_factor, ("applied_wrench",), B, F, (1e-200, 0.0, 0.0))


def test_regression_statics_tiny_wrench_onset():
    """Fixed (was a strict xfail): onset(B, F, (0, 0, 1e-200)) raises slidespin.contact.statics.OnsetNotFound (a RuntimeError,  'load factor nan < 1'): a torque of 1e-200 N m is held, the answer is None"""
    assert clean(ss.onset, ("applied_wrench",), B, F, (0.0, 0.0, 1e-200)) is None


def test_regression_statics_scale_onset():
    """Fixed (was a strict xfail): onset(B, F, (1e300, 0, 0)) raises ZeroDivisionError"""
    clean(ss.onset, ("applied_wrench",), B, F, (1e300, 0.0, 0.0))


def test_regression_load_overflow_simulate():
    """Fixed (was a strict xfail): simulate(B, F, State(), load=Load(force=(1e300, 0)), t_end=0.1) raises  ZeroDivisionError (the onset of slip from rest)"""
    clean(
        ss.simulate,
        ("load", "force"),
        B,
        F,
        ss.State(),
        load=ss.Load(force=(1e300, 0.0)),
        t_end=0.1,
        max_steps=50,
    )


def test_regression_loaded_tiny_g():
    """Fixed (was a strict xfail): simulate(B, F, State(vx=1), t_end=0.1, g=5e-324) raises ZeroDivisionError: the  stick-slip engine takes any g > 0, unlike the plain simulate's [1e-6, 1e6]"""
    clean(ss.simulate, ("g =", "g must"), B, F, ss.State(vx=1.0), t_end=0.1, g=5e-324, max_steps=50)


def test_regression_onset_hang():
    """Fixed (was a strict xfail): onset(Body(Circle(1.0), UniformPressure(), 1.0, 1e-8), FrictionTensor(1e-6, 0.3,  3.2), (49.05, 0.0, -20.0)) runs for minutes (no answer in 5 s; found by test_onset):  when the Newton polish fails, statics._onset_nat's sphere flow takes  20 (|b| + 1)/0.05 explicit steps, b = (Qx, Qy, T/k)/(m g) (her"""
    clean(
        ss.onset,
        ("applied_wrench",),
        ss.Body(ss.Circle(1.0), ss.UniformPressure(), 1.0, 1e-8),
        ss.FrictionTensor(1e-6, 0.3, 3.2),
        (49.05, 0.0, -20.0),
        soft=5,
    )


def test_regression_loaded_slow():
    """Fixed (was a strict xfail): simulate(Body(Ellipse(1.0, 30.0), BoussinesqPressure(), 1.0, 1.1), FrictionTensor(5.0,  1e-6, frame='body'), State(vy=-1e8, omega=1e12), t_end=100.0, max_steps=170) gives no  answer in 8 s (more than 20 s seen; found by test_simulate_loaded): max_steps does not  bound the stick-slip engine's time (t"""
    clean(
        ss.simulate,
        ("initial_state", "max_steps"),
        ss.Body(ss.Ellipse(1.0, 30.0), ss.BoussinesqPressure(), 1.0, 1.1),
        ss.FrictionTensor(5.0, 1e-6, frame="body"),
        ss.State(vy=-1e8, omega=1e12),
        t_end=100.0,
        max_steps=170,
        soft=8,
    )


def test_regression_loaded_small_inertia_hang():
    """Fixed (was a strict xfail): simulate(Body(Circle(7.208866044813389e-09), LinearPressure(-1.4095064383009482e-09,  2.408410640106899e-10), m = 64644193.78904398, I = 3.359413279288511e-17 (I* = 1e-8)),  FrictionTensor(5.0, 5.0, frame='body'), State(x=7.2e-14, phi=6.866, vy=1.108e-05,  omega=334721.6), g=1.0, max_steps=105, load"""
    m = 64644193.78904398
    body = ss.Body(
        ss.Circle(7.208866044813389e-09),
        ss.LinearPressure(-1.4095064383009482e-09, 2.408410640106899e-10),
        m,
        3.359413279288511e-17,
    )
    clean(
        ss.simulate,
        ("initial_state", "max_steps", "load", "body"),
        body,
        ss.FrictionTensor(5.0, 5.0, frame="body"),
        ss.State(
            x=7.20886604481339e-14,
            phi=6.866106445768917,
            vy=1.1080433196663747e-05,
            omega=334721.6030157184,
        ),
        g=1.0,
        max_steps=105,
        load=ss.Load(force=lambda t: (m * 9.81 * min(t, 1.0), 0.0)),
        incline=ss.Incline(0.0, 0.10479001032225019),
        t_end=0.0005781182710400609,
        soft=8,
    )


def test_regression_limit_surface_length():
    """Fixed (was a strict xfail): limit_surface(B, F, n=10, length=1e-300) raises ValueError 'SVD did not converge in  Linear Least Squares', which names no parameter (length is only checked > 0)"""
    clean(ss.limit_surface, ("length",), B, F, 10, length=1e-300)


def test_regression_limit_surface_huge_n():
    """Fixed (was a strict xfail): limit_surface(B, F, n=2**70) raises ValueError 'Maximum allowed size exceeded'  (numpy), which names no parameter: n has no upper bound"""
    clean(ss.limit_surface, ("n =",), B, F, 2**70)


def test_regression_animate_path_type(short_trajectory):
    """path=None once gave a TypeError from os.fspath."""
    clean(animate, ("path",), short_trajectory, None)


@pytest.mark.parametrize("path", [None, 1.5], ids=["None", "float"])
def test_regression_read_runs_path_type(path):
    """None and 1.5 once gave a TypeError from open()."""
    clean(fit_data.read_runs, ("data file", "path"), path)


def test_regression_read_runs_pipe():
    """An int path was once read as a file descriptor: a pipe blocked for ever."""
    r, w = os.pipe()
    try:
        clean(fit_data.read_runs, ("data file", "path"), r, soft=3)
    finally:
        for fd in (r, w):
            try:
                os.close(fd)
            except OSError:
                pass


def test_regression_read_runs_fifo(tmp_path):
    """A FIFO with no writer once blocked for ever in open()."""
    fifo = tmp_path / "runs.csv"
    os.mkfifo(fifo)
    clean(fit_data.read_runs, ("data file",), str(fifo), soft=3)


# hangs that allocate memory: run in a subprocess with a memory limit and a time limit
_PROBE = r"""
import json, resource, sys, warnings
resource.setrlimit(resource.RLIMIT_AS, (3 * 2**29, 3 * 2**29))
import numpy as np, slidespin as ss
B = ss.Body(ss.Circle(0.05), ss.UniformPressure(), 1.0)
F = ss.FrictionTensor(0.3, 0.4)
warnings.simplefilter("ignore")
try:
    r = eval(sys.argv[1])
except ValueError as err:
    print(json.dumps(["ValueError", str(err)]))
except BaseException as err:
    print(json.dumps([type(err).__name__, str(err)[:300]]))
else:
    print(json.dumps(["result", repr(r)[:300]]))
"""


def _in_subprocess(expr, name, seconds=20):
    import json

    try:
        r = subprocess.run(
            [sys.executable, "-c", _PROBE, expr],
            capture_output=True,
            text=True,
            timeout=seconds,
            check=False,
        )
    except subprocess.TimeoutExpired:
        pytest.fail(f"{expr}: no answer within {seconds} s")
    lines = r.stdout.strip().splitlines()
    assert lines, r.stderr[-2000:]
    kind, text = json.loads(lines[-1])
    assert kind == "ValueError" and name in text, (kind, text)


def test_regression_map_tol_hang():
    """map_tol=1e-300 once bisected without bound (memory)."""
    _in_subprocess(
        "ss.friction_wrench(ss.Body(ss.Rectangle(0.1, 0.05), ss.PressureMap(lambda x, y: "
        "1.0 + 0.0 * x), 1.0), F, 1.0, 0.0, 1.0, map_tol=1e-300)",
        "map_tol",
    )


def test_regression_limit_surface_quartic_hang():
    """Fixed (was a strict xfail): limit_surface(B, F, n=10, quartic_directions=10**9) tries to build 2e9 directions  (MemoryError under a 1.5 GB limit; a hang without one): no upper bound"""
    _in_subprocess("ss.limit_surface(B, F, n=10, quartic_directions=10**9)", "quartic_directions")
