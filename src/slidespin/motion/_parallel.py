"""Many independent trajectories at once: :func:`integrate_fp` in parallel (``prange``).

The compiled batch behind :mod:`slidespin.motion.batch`: each case runs
:func:`slidespin.motion._integrator.integrate_fp` itself, without per-step records, from the
initial state of :func:`slidespin.motion._flow.initial_state` (the same arithmetic as
:func:`slidespin.motion.simulate.simulate`, so that batch and single runs agree to the last
bit). The elliptic and the footprint cases run through the compiled specialisation of their
kind (MODEL §10; :mod:`slidespin.motion._integrator`, "Footprints").
"""

from __future__ import annotations

import math

import numpy as np

from slidespin import _aot
from slidespin._jit import jit, prange
from slidespin.contact._engine import P_SHAPE, SHAPE_FOOTPRINT
from slidespin.motion._flow import NY, initial_state
from slidespin.motion._integrator import ST_AT_REST, integrate_fp

#: a batch of at most this many cases runs serially on the ahead-of-time compiled core when
#: there is one (:mod:`slidespin._aot`; the same source without ``prange``, the same
#: numbers): a first small batch then compiles nothing (the parallel loop takes ~40 s of CPU
#: to compile once), at most a factor of the core count slower than the parallel loop
SERIAL_MAX = 1000


def stop_direction(yend):
    """|u₁₂| and ϑ of each stop state (:func:`_stop_direction`), on the ahead-of-time compiled
    core when there is one."""
    aot = _aot.core()
    yend = np.ascontiguousarray(yend, dtype=np.float64)
    return _stop_direction(yend) if aot is None else aot.stop_direction(yend)


@jit(error_model="numpy")
def _stop_direction(yend):
    """|u₁₂| and the direction ϑ = atan2(u₂, u₁) of each stop state, with the same libm
    functions as :func:`slidespin.simulate` (math.hypot, math.atan2), bit for bit."""
    n = yend.shape[0]
    u12 = np.empty(n)
    theta = np.empty(n)
    for i in range(n):
        u12[i] = math.hypot(yend[i, 0], yend[i, 1])
        theta[i] = math.atan2(yend[i, 1], yend[i, 0])
    return u12, theta


def integrate_many(pars, *args):
    """:func:`integrate_fp` for many independent cases in parallel (no per-step records).

    Called as ``integrate_many(pars, edges, circles, eidx, cidx, geos, init, rtol, atol, utol,
    s_drop, max_steps)``: variadic after ``pars`` so that callers may splat the footprint
    arrays (``*fps``) as they did into the compiled function this wrapper replaced (mypy maps
    a splatted tuple of unknown length onto every remaining named parameter).

    Parameters
    ----------
    pars : ndarray (N, NPAR)
        One parameter vector per case.
    edges, circles : ndarray (·, 4)
        The footprints' edges and circles of all cases, stacked (natural units of each case):
        case i's are rows ``eidx[i, 0]:eidx[i, 1]`` and ``cidx[i, 0]:cidx[i, 1]`` (cases may
        share rows).
    eidx, cidx : ndarray (N, 2) of int64
        Row ranges into ``edges`` and ``circles`` (all zero for ellipses).
    geos : ndarray (N, NGEO)
        The footprints' kernel constants (unused for ellipses).
    init : ndarray (N, 6)
        Initial (vx, vy, ω, x, y, φ) per case in natural units (:func:`initial_state`).

    Returns
    -------
    y_stop : ndarray (N, NY)
        Stop states (a body at rest keeps its initial state, with ln s = −inf).
    status, n_steps, n_rhs, n_wrench_failed : ndarray (N,) of int64
    term : ndarray (N, 4)
        ϑ*, the saddle's ln(s/s₀), λ/|u·A| and β*/a per case (see :func:`integrate_fp`).

    Notes
    -----
    The elliptic and the footprint cases run through the specialisation of their kind
    (:func:`_integrate_many` with ``fps`` None or the footprint arrays), each compiled on its
    first use; a batch that mixes both runs twice, on each kind's rows (the cases are
    independent: the same results as one run).
    """
    edges, circles, eidx, cidx, geos, init, rtol, atol, utol, s_drop, max_steps = args
    c = np.ascontiguousarray
    pars = c(pars, dtype=np.float64)
    init = c(init, dtype=np.float64)
    foot = pars[:, P_SHAPE] == SHAPE_FOOTPRINT
    args = (float(rtol), float(atol), float(utol), float(s_drop), int(max_steps))
    fps = (
        c(edges, dtype=np.float64),
        c(circles, dtype=np.float64),
        c(eidx, dtype=np.int64),
        c(cidx, dtype=np.int64),
        c(geos, dtype=np.float64),
    )
    if not foot.any():
        return _run(pars, None, init, *args)
    if foot.all():
        return _run(pars, fps, init, *args)
    n = pars.shape[0]
    out = (
        np.empty((n, NY)),
        np.empty(n, dtype=np.int64),
        np.empty(n, dtype=np.int64),
        np.empty(n, dtype=np.int64),
        np.empty(n, dtype=np.int64),
        np.empty((n, 4)),
    )
    ell = np.flatnonzero(~foot)
    res = _run(c(pars[ell]), None, c(init[ell]), *args)
    for whole, part in zip(out, res):
        whole[ell] = part
    fpi = np.flatnonzero(foot)
    res = _run(
        c(pars[fpi]),
        fps[:2] + (c(fps[2][fpi]), c(fps[3][fpi]), c(fps[4][fpi])),
        c(init[fpi]),
        *args,
    )
    for whole, part in zip(out, res):
        whole[fpi] = part
    return out


def _run(pars, fps, init, *args):
    """:func:`_integrate_many`, or its serial twin on the compiled core (:data:`SERIAL_MAX`)."""
    aot = _aot.core()
    if aot is None or pars.shape[0] > SERIAL_MAX:
        return _integrate_many(pars, fps, init, *args)
    if fps is None:
        return aot.integrate_batch_ellipse(pars, init, *args)
    return aot.integrate_batch_footprint(pars, *fps, init, *args)


@jit(parallel=True, error_model="numpy")
def _integrate_many(pars, fps, init, rtol, atol, utol, s_drop, max_steps):
    """:func:`integrate_many` for cases of one kind: ``fps`` is None (ellipses) or the tuple
    (edges, circles, eidx, cidx, geos) of its arguments."""
    n = init.shape[0]
    out = np.empty((n, NY))
    status = np.empty(n, dtype=np.int64)
    steps = np.empty(n, dtype=np.int64)
    rhss = np.empty(n, dtype=np.int64)
    fails = np.empty(n, dtype=np.int64)
    terms = np.empty((n, 4))
    no_record = max_steps < 0
    for i in prange(n):
        y0 = initial_state(
            pars[i], init[i, 0], init[i, 1], init[i, 2], init[i, 3], init[i, 4], init[i, 5]
        )
        if y0[3] == -np.inf:
            for c in range(NY):
                out[i, c] = y0[c]
            status[i] = ST_AT_REST
            steps[i] = 0
            rhss[i] = 0
            fails[i] = 0
            for c in range(4):
                terms[i, c] = math.nan
            continue
        # ``no_record`` is False as a variable: a literal False would compile integrate_fp() a
        # second time, specialised, instead of reusing the version simulate() compiled
        if fps is None:
            yend, st, ns, nr, nf, rate, rec, term = integrate_fp(
                pars[i], None, y0, rtol, atol, utol, s_drop, max_steps, np.inf, no_record,
                no_record,
            )  # fmt: skip
        else:
            edges, circles, eidx, cidx, geos = fps
            # contiguous copies: the same array types as simulate() passes (one compilation)
            fp = (
                np.ascontiguousarray(edges[eidx[i, 0] : eidx[i, 1]]),
                np.ascontiguousarray(circles[cidx[i, 0] : cidx[i, 1]]),
                np.ascontiguousarray(geos[i]),
            )
            yend, st, ns, nr, nf, rate, rec, term = integrate_fp(
                pars[i], fp, y0, rtol, atol, utol, s_drop, max_steps, np.inf, no_record,
                no_record,
            )  # fmt: skip
        for c in range(NY):
            out[i, c] = yend[c]
        for c in range(4):
            terms[i, c] = term[c]
        status[i] = st
        steps[i] = ns
        rhss[i] = nr
        fails[i] = nf
    return out, status, steps, rhss, fails, terms
