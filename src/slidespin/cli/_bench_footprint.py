"""The footprint rows of ``slidespin bench`` (:mod:`slidespin.cli.bench`, MODEL §10).

On an irregular convex octagon and on a ring (:mod:`slidespin.contact.shapes`): the exact
footprint wrench from compiled code (ICR near and far), its error against the slow reference
(``tests/references/footprint_reference.py`` of a source checkout), a trajectory to the converged stop, and
the batch throughput as a ratio to the demo ellipse's measured in the same run.
"""

from __future__ import annotations

import math
import time

import numpy as np

from slidespin.cli._bench_accuracy import _reference_module
from slidespin.cli._bench_cases import _best, _demo
from slidespin.contact import _engine
from slidespin.contact._kernel_footprint import time_wrenches
from slidespin.contact.body import Body
from slidespin.contact.pressure import UniformPressure
from slidespin.contact.shapes import Annulus, Polygon
from slidespin.contact.wrench import footprint_wrench

# ---------------------------------------------------------------------------------------------
# footprints

#: the benchmark's footprints [m]: an irregular convex octagon (8 vertices, radii 0.08-0.1 m)
#: and a ring (a curling stone's running band, scaled: 0.05-0.065 m)
_OCTAGON = tuple(
    (r * math.cos(t), r * math.sin(t))
    for r, t in zip(
        (0.100, 0.090, 0.095, 0.080, 0.100, 0.085, 0.092, 0.088),
        (0.0, 0.8, 1.55, 2.4, 3.2, 3.9, 4.75, 5.5),
    )
)
_RING = (0.05, 0.065)


def _footprints():
    """{name: (footprint, Body)} of the footprint rows (uniform pressure, 1 kg)."""
    out = {}
    for name, fp in (("octagon", Polygon(_OCTAGON)), ("ring", Annulus(*_RING))):
        out[name] = (fp, Body(fp, UniformPressure(), mass=1.0))
    return out


def _footprint_icr(where, n, rng):
    """Body-frame velocities of G (ω = 1) for ICRs uniform in the disk of radius 1 about G
    ("near") or in the annulus 1.1-10 ("far"), natural units (lengths in the extent)."""
    r = np.sqrt(rng.uniform(0.0, 1.0, n)) if where == "near" else rng.uniform(1.1, 10.0, n)
    t = rng.uniform(0.0, 2.0 * math.pi, n)
    cx, cy = r * np.cos(t), r * np.sin(t)  # ICR relative to G
    return np.ascontiguousarray(cy), np.ascontiguousarray(-cx), np.ones(n)


def _footprint_accuracy(fp, body, fr, n, rng):
    """Largest error of the compiled footprint wrench (public footprint_wrench) against the
    slow independent reference, in units of the load and load x extent, over n motion states
    (ICR near, on the outline's scale and far; None if the reference is not available)."""
    ref = _reference_module("footprint_reference.py")
    if ref is None:
        return None
    ext = body.length_unit
    xg, yg = body.mass_centre
    worst = 0.0
    for i in range(n):
        r = (0.3, 0.9, 2.0, 40.0)[i % 4] * ext * math.sqrt(rng.uniform(0.05, 1.0))
        t = rng.uniform(0.0, 2.0 * math.pi)
        om, phi = rng.choice([-1.0, 1.0]) * rng.uniform(0.5, 3.0), rng.uniform(-3.0, 3.0)
        cbx, cby = xg + r * math.cos(t), yg + r * math.sin(t)
        vbx, vby = (cby - yg) * om, -(cbx - xg) * om
        c, sn = math.cos(phi), math.sin(phi)
        vx, vy = c * vbx - sn * vby, sn * vbx + c * vby
        w = footprint_wrench(fp, body.pressure, fr, vx, vy, om, phi)
        want = ref.reference_wrench(
            fp, ("uniform",), fr.matrix, vx, vy, om, phi=phi, frame=fr.frame
        )
        worst = max(
            worst, abs(w.force_x - want[0]), abs(w.force_y - want[1]), abs(w.moment - want[2]) / ext
        )
    return worst


def bench_footprint(quick, rng, states):
    """The footprint rows: the compiled exact wrench per call (ICR near and far), its error
    against the slow reference, a trajectory to the converged stop (rtol 1e-10, the demo's
    friction and start), and simulate_many throughput from ``states`` (the ellipse batch's
    starts) as a ratio to the demo ellipse's on the same starts, timed alternately, for an
    octagon and a ring."""
    # deferred: keeps `slidespin --help` fast (the numerical stack is not imported for parsing)
    from slidespin.motion import _flow, _integrator
    from slidespin.motion.batch import simulate_many

    demo_body, fr, st, g = _demo()
    n = 200 if quick else 1000
    reps = 5 if quick else 20
    out = {}
    for name, (fp, body) in _footprints().items():
        d: dict = {"vertices": len(getattr(fp, "vertices", ())), "extent_m": body.length_unit}
        par, fe, fc, geo = body.engine_params(fr)
        t = par[_engine.P_T00], par[_engine.P_T01], par[_engine.P_T10], par[_engine.P_T11]
        for where in ("near", "far"):
            vx, vy, om = (np.tile(x, reps) for x in _footprint_icr(where, n, rng))
            time_wrenches(fe, fc, geo, *t, vx[:2], vy[:2], om[:2])
            dt = _best(lambda: time_wrenches(fe, fc, geo, *t, vx, vy, om), repeat=3)
            d[f"wrench_us_icr_{where}"] = dt / vx.size * 1e6
        err = _footprint_accuracy(fp, body, fr, 8 if quick else 24, rng)
        if err is not None:
            d["wrench_max_abs_error"] = err
            d["wrench_error_states"] = 8 if quick else 24
        # trajectory: the compiled integrator's footprint specialisation, no records
        a = body.length_unit
        v_unit, t_unit = math.sqrt(a * g), math.sqrt(a / g)
        y0 = _flow.initial_state(
            par, st.vx / v_unit, st.vy / v_unit, st.omega * t_unit, st.x / a, st.y / a, st.phi
        )
        fpa = _engine.footprint_argument(par, fe, fc, geo)

        def traj():
            return _integrator.integrate_fp(
                par, fpa, y0, 1e-10, 1e-10, 1e-10, 1e-10, 200_000, np.inf, False, False
            )

        r = traj()
        d["trajectory_ms"] = _best(traj, 5, 20 if quick else 100) * 1e3
        d["trajectory_steps"] = int(r[2])
        d["trajectory_rhs"] = int(r[3])
        d["status"] = int(r[1])
        # batch: the same starts as the ellipse's batch, all threads; the ellipse's batch is
        # timed again alternately with this one (best of 3 each), so that the ratio compares
        # the two under the same load of a shared machine
        simulate_many(body, fr, states[:8], g=g)
        t_fp, t_el = math.inf, math.inf
        for _ in range(3):
            t0 = time.perf_counter()
            res = simulate_many(body, fr, states, g=g)
            t_fp = min(t_fp, time.perf_counter() - t0)
            t0 = time.perf_counter()
            simulate_many(demo_body, fr, states, g=g)
            t_el = min(t_el, time.perf_counter() - t0)
        d["batch_per_s"] = len(states) / t_fp
        d["batch_mean_steps"] = float(res.n_steps.mean())
        d["ellipse_batch_per_s"] = len(states) / t_el
        d["ellipse_over_footprint"] = t_fp / t_el
        out[name] = d
    return out
