"""The compiled engine of a loaded run (MODEL §11): the slow start and the slip of each phase
in compiled code, for loads and tilts given as tables (constant or piecewise linear).

:func:`slidespin.motion.loaded.simulate_loaded` runs the phases (stick, onset, slip) in
Python and asks an engine for the onset direction and the two integrations of a slip phase:

* :meth:`CompiledSlip.onset`: Newton's method from the outward normal of the
  static-friction set C at the load (the Python onset's first start), else the Python onset
  with all its starts;
* :meth:`CompiledSlip.slow_start`: from rest, with the direction slaved to the onset
  direction, until s reaches the slow speed (:mod:`slidespin.motion._loaded_dop853`,
  ``MODE_SLAVED``); where the compiled Newton solve of the direction fails, the Python slow
  start (:func:`slidespin.motion._stick_slip._quasi_static`, which has several starts) takes
  over from the state reached;
* :meth:`CompiledSlip.slip`: the full equations to the stop or ``t_end``. While the problem
  is stiff (the ratio of :func:`slidespin.motion._loaded_flow.stiffness` above ``STIFF`` =
  100, the Python path's threshold for Radau) Radau IIA
  (:mod:`slidespin.motion._loaded_radau`), then DOP853
  (:mod:`slidespin.motion._loaded_dop853`); either in the time t while the body speeds up
  or holds its speed (the motion is polynomial-like in t, and the knots are landed on
  exactly) and in the regularised time τ once the speed has fallen below half its peak
  (smooth through the stop).

Everything else (whether static friction holds, when a load leaves C) is the Python path's
statics (:mod:`slidespin.motion._stick_slip`, :mod:`slidespin.contact.statics`), called a
handful of times per phase. All compiled work goes through the one entry
:func:`slidespin.motion._loaded_core.run_loaded` (one compile per kind of patch).
"""

from __future__ import annotations

import math

import numpy as np

from slidespin import _aot
from slidespin.contact._engine import footprint_argument
from slidespin.contact.statics import _ONSET_LAM_TOL
from slidespin.motion._loaded_core import (
    TASK_DOP853,
    TASK_ONSET,
    TASK_RADAU,
    TASK_STIFFNESS,
    run_loaded,
)
from slidespin.motion._loaded_dop853 import (
    R_BACK,
    R_DECAY,
    R_FAILED,
    R_FAST,
    R_MAX_STEPS,
    R_SLAVE,
    R_STALL,
    R_STOP,
    R_SWITCH,
    R_T_END,
)
from slidespin.motion._loaded_flow import (
    MODE_SLAVED,
    MODE_T,
    MODE_TAU,
    NY,
    applied_many,
    table_breaks,
)
from slidespin.motion._stick_slip import _quasi_static

#: stiffness ratio above which a slip is integrated by the implicit Radau method
STIFF = 100.0
#: the integrators' step-size floor, as said in a ``step_too_small`` message
_FAILED = "the step size fell below 1e-12 of the independent variable"
_REASONS = {
    R_STOP: "stop",
    R_T_END: "t_end",
    R_MAX_STEPS: "max_steps",
    R_FAILED: "failed",
    R_FAST: "fast",
    R_STALL: "stall",
    R_BACK: "stall",  # s back through 0: the load only grazed C (the Python path's name)
}


def _guard(nfail):
    """The elliptic quadrature meets its error target for every valid input (as in
    :func:`slidespin.simulate`); should it not, say so rather than go on."""
    if nfail:  # pragma: no cover - guard, not reached in tests
        raise RuntimeError(
            f"simulate_loaded: {nfail} wrench evaluations missed their error target; please report"
        )


def _run(task, slip, mode, y0, rtol, atol, h_max, t_end, ln_stop, s_arg, t_tol, steps):
    """:func:`~slidespin.motion._loaded_core.run_loaded` for the patch of ``slip``: by the
    ahead-of-time compiled core when the install built one from these sources
    (:mod:`slidespin._aot`; the same code, the same numbers), else by the JIT."""
    tail = (
        slip.tab, float(mode), y0, float(rtol), atol, float(h_max), float(t_end), slip.breaks,
        float(ln_stop), float(s_arg), float(t_tol), int(steps),
    )  # fmt: skip
    aot = _aot.core()
    if aot is None:
        return run_loaded(task, slip.par, slip.fp, *tail)
    if slip.fp is None:
        return aot.loaded_ellipse(task, slip.par, *tail)
    return aot.loaded_footprint(task, slip.par, *slip.fp, *tail)


def run_dop853(slip, mode, y0, atol, h_max, t_end, ln_stop, s_fast, steps):
    """The explicit stepper (:func:`~slidespin.motion._loaded_dop853.run_dop853`) through
    the compiled entry: (y, reason, steps, kernel calls, rows)."""
    y, reason, n, calls, nfail, rec, _ = _run(
        TASK_DOP853, slip, mode, y0, slip.rtol, atol, h_max, t_end, ln_stop, s_fast, slip.t_tol,
        steps,
    )  # fmt: skip
    _guard(nfail)
    return y, int(reason), int(n), int(calls), rec


def run_radau(slip, mode, y0, atol, t_end, ln_stop, stiff_min, steps):
    """The implicit stepper (:func:`~slidespin.motion._loaded_radau.run_radau`) through the
    compiled entry: (y, reason, steps, kernel calls, rows)."""
    y, reason, n, calls, nfail, rec, _ = _run(
        TASK_RADAU, slip, mode, y0, slip.rtol, atol, slip.h_max, t_end, ln_stop, stiff_min,
        slip.t_tol, steps,
    )  # fmt: skip
    _guard(nfail)
    return y, int(reason), int(n), int(calls), rec


def slaved_direction(slip, u, t, phi):
    """Newton's solve of the onset direction from u at (t, φ) through the compiled entry
    (:func:`~slidespin.motion._loaded_flow.slaved_direction`): (ok, u*, λ, kernel calls)."""
    y0 = np.zeros(NY)
    y0[0:3] = u
    y0[4] = t
    y0[7] = phi
    _, _, _, calls, _, _, aux = _run(
        TASK_ONSET, slip, MODE_TAU, y0, 0.0, slip.atol, 0.0, 0.0, 0.0, 0.0, 0.0, 0
    )
    return aux[5] != 0.0, aux[0:3].copy(), float(aux[3]), int(calls)


class CompiledSlip:
    """The compiled onset, slow start and slip of one loaded run (natural units of
    ``prob``).

    Parameters
    ----------
    prob : slidespin.motion._loaded_problem._Problem
        The run.
    tab : ndarray
        Its load table (:func:`slidespin.motion._loaded_flow.load_table`).
    rtol : float
        Relative tolerance (absolute rtol·1e-2, as the Python path).
    h_max : float
        Largest step in τ (``inf`` for none; in t, the step is at most h_max·s).
    slow_speed : float
        s (natural) up to which a start from rest is slaved to the onset direction.
    t_tol : float
        Accuracy (natural time) of located events.
    """

    def __init__(self, prob, tab, rtol, h_max, slow_speed, t_tol):
        self.prob = prob
        tw = prob.tw
        self.par = np.ascontiguousarray(tw.par, dtype=np.float64)
        self.fp = footprint_argument(self.par, tw.edges, tw.circles, tw.geo)
        self.tab = tab
        self.breaks = np.ascontiguousarray(table_breaks(tab))
        self.rtol = float(rtol)
        self.atol = np.full(NY, rtol * 1e-2)
        self.h_max = float(h_max)
        self.slow = float(slow_speed)
        self.t_tol = float(t_tol)
        self.calls = 0
        self.failure = ""
        self.stiff_min = STIFF

    def _stiffness(self, u, t, phi):
        y0 = np.zeros(NY)
        y0[0:3] = u
        y0[4] = t
        y0[7] = phi
        _, _, _, calls, _, _, aux = _run(
            TASK_STIFFNESS, self, MODE_TAU, y0, 0.0, self.atol, 0.0, 0.0, 0.0, 0.0, 0.0, 0
        )
        self.calls += int(calls)
        return float(aux[0])

    def onset(self, t, phi):
        """The onset direction u at a time where the load has left C: Newton's method from
        the outward normal d* of C at the load (the first start of the Python onset,
        :func:`slidespin.contact.statics._onset_nat`), compiled; accepted with a residual
        below 1e-11 and a rate λ > −1e-12 (1 + |A_a|) (the Python onset's bounds), else
        the Python onset with all its starts (which raises
        :class:`~slidespin.contact.statics.OnsetNotFound` if it fails too)."""
        prob = self.prob
        _, d = prob.gauge_normal(t, phi)
        if d is not None:
            u0 = np.array([d[0], d[1], prob.k * d[2]])
            u0 /= np.linalg.norm(u0)
            ok, u, lam, calls = slaved_direction(self, u0, t, phi)
            self.calls += calls
            lam_tol = _ONSET_LAM_TOL * (1.0 + float(np.linalg.norm(prob.b(t, phi))))
            if ok and lam > -lam_tol:
                return u
        return prob.onset(t, phi)[0]

    def w_many(self, times, phi):
        """The applied wrench per unit normal load (the coordinates of C) at many times."""
        out = np.empty((times.size, 3))
        applied_many(self.tab, np.ascontiguousarray(times, dtype=np.float64), float(phi), out)
        return out

    def slow_start(self, t0, pos, work, u0, t_end, steps):
        """The slow start from rest at t0 in the onset direction u0 (as
        :func:`~slidespin.motion._stick_slip._quasi_static`). Returns (t, pos, work, s, u,
        reason, rows, steps) with reason ``fast``, ``stall``, ``t_end``, ``max_steps`` or
        ``failed``; rows (t, x, y, φ, vx, vy, k ω, W_f, W_Q)."""
        y0 = np.zeros(NY)
        y0[0:3] = u0
        y0[4] = t0
        y0[5:8] = pos
        y0[8:10] = work
        # the Python slow start's atol (1e-18; u, constant in a step, and t, dt/dt = 1,
        # carry no error)
        y, reason, nst, calls, rec = run_dop853(
            self, MODE_SLAVED, y0, np.full(NY, 1e-18), math.inf, t_end, -math.inf, self.slow, steps
        )
        self.calls += calls
        rows = list(rec)
        if reason == R_SLAVE:
            # the compiled Newton solve lost the direction: the Python slow start (several
            # starts, then the sphere flow) goes on from the state reached
            t, p, w, s, u, why, more = _quasi_static(
                self.prob,
                float(y[4]),
                y[5:8].copy(),
                y[8:10].copy(),
                t_end,
                self.rtol,
                self.slow,
                s0=float(y[3]),
                u0=y[0:3].copy(),
            )
            for r in more:
                rows.append(np.concatenate([[r[0]], r[2:5], r[1] * r[5:8], r[8:10]]))
            if why == "failed":
                self.failure = self.prob.failure
            return t, p, w, s, u, why, rows, nst
        if reason == R_FAILED:
            self.failure = _FAILED
        u = y[0:3] / np.linalg.norm(y[0:3])
        s = max(float(y[3]), 0.0)
        return float(y[4]), y[5:8].copy(), y[8:10].copy(), s, u, _REASONS[reason], rows, nst

    def slip(self, u, s, t, pos, work, ln_stop, t_end, steps, from_rest=False):
        """The slip from (u, s) at t to the stop or ``t_end``. Returns (t, pos, work, vel,
        reason, rows, steps) with reason ``stop``, ``t_end``, ``max_steps`` or ``failed``."""
        y = np.zeros(NY)
        y[0:3] = u
        y[4] = t
        y[5:8] = pos
        y[8:10] = work
        rows = []
        used = 0
        stiff = self._stiffness(u, t, pos[2]) > STIFF
        # speeding up or holding: in t (polynomial-like there); slowing down: in τ
        mode = MODE_T if self._growth(u, t, pos[2]) >= 0.0 else MODE_TAU
        y[3] = s if mode == MODE_T else math.log(s)
        while True:
            left = max(steps - used, 0)
            atol = self.atol.copy()
            if mode == MODE_T:
                atol[3] = self.rtol * 1e-2 * y[3]  # s: relative, like ln s in τ
                atol[4] = 1.0  # t: dt/dt = 1 is integrated exactly (sets only the first step)
            if stiff:
                atol[:3] = max(atol[0], 1e-10)  # (the Python path's bound for Radau)
                y, reason, nst, calls, rec = run_radau(
                    self, mode, y, atol, t_end, ln_stop, self.stiff_min, left
                )
            else:
                y, reason, nst, calls, rec = run_dop853(
                    self, mode, y, atol, self.h_max, t_end, ln_stop, 0.0, left
                )
            self.calls += calls
            used += nst
            rows.extend(rec)
            s_now = float(y[3]) if mode == MODE_T else math.exp(float(y[3]))
            if reason == R_SWITCH:
                stiff = False
                continue
            if reason == R_DECAY:  # on in τ
                y[3] = math.log(s_now)
                mode = MODE_TAU
                stiff = self._stiffness(y[0:3], float(y[4]), float(y[7])) > STIFF
                continue
            break
        if reason == R_FAILED:
            self.failure = _FAILED
        u_end = y[0:3] / np.linalg.norm(y[0:3])
        vel = np.zeros(3) if reason == R_STOP else s_now * u_end
        return float(y[4]), y[5:8].copy(), y[8:10].copy(), vel, _REASONS[reason], rows, used

    def _growth(self, u, t, phi):
        """u·X at (u, t, φ): the rate of ln s in τ."""
        prob = self.prob
        ax, ay, am = prob.friction_acc(u[0], u[1], u[2], phi, t)
        bx, by, bm = prob.b(t, phi)
        return u[0] * (ax + bx) + u[1] * (ay + by) + u[2] * (am + bm)
