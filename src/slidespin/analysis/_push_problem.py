"""Private model of :func:`slidespin.analysis.fit_push.fit_pushes` (MODEL §12–13): one tracked
push as the body led by a :class:`~slidespin.PointPusher` along its thinned tip path
(:class:`_Push`, :func:`_simplify`), the pose and force of a pushed run at the measured times
(:func:`pushed_at`), and the weighted residuals and their Jacobian over all pushes
(:class:`_PushProblem`, a :class:`slidespin.analysis._fit_problem._Problem`). The module's
docstring of :mod:`slidespin.analysis.fit_push` describes the method.
"""

from __future__ import annotations

import numpy as np

from slidespin.analysis._fit_problem import _Problem, _wrap
from slidespin.analysis.push_data import PushRun
from slidespin.motion.pushed import simulate_pushed
from slidespin.motion.pushers import PointPusher
from slidespin.motion.quasi_static import push_quasi_static
from slidespin.motion.state import State

#: measured channels of a push: the object's pose and the pusher's force
PUSH_CHANNELS = ("x", "y", "phi", "force_x", "force_y")
#: a push's first touch: its force first exceeds this fraction of the push's largest force
TOUCH_FRACTION = 0.2
_POSE = ("x", "y", "phi")
_FORCE = ("force_x", "force_y")


# --------------------------------------------------------------------------------------------
# the model at the measured times


def pushed_at(traj, t) -> dict:
    """Pose and pusher force of a pushed run at times ``t`` [s] (from the run's start).

    ``traj`` is a :class:`~slidespin.PushedTrajectory` (poses: the cubic Hermite interpolant
    of the integrator's rows with their velocities; force: linear between rows, the later
    row at a switch) or a :class:`~slidespin.QuasiStaticPush` computed at exactly these times.

    Returns
    -------
    dict
        ``x``, ``y``, ``phi`` [m, m, rad] and ``force_x``, ``force_y`` [N], arrays like ``t``.
    """
    t = np.asarray(t, dtype=float)
    if hasattr(traj, "force_x"):  # a QuasiStaticPush at the requested times
        idx = np.searchsorted(traj.t, t)
        idx = np.clip(idx, 0, traj.t.size - 1)
        return {
            "x": traj.x[idx],
            "y": traj.y[idx],
            "phi": traj.phi[idx],
            "force_x": traj.force_x[idx],
            "force_y": traj.force_y[idx],
        }
    ts = traj.t
    pos = np.column_stack((traj.x, traj.y, traj.phi))
    vel = np.column_stack((traj.vx, traj.vy, traj.omega))
    tt = np.clip(t, ts[0], ts[-1])
    # one cubic Hermite piece per interval between distinct times, from the last row at its
    # start to the first row at its end (an impact's velocity jump is not smoothed over)
    seg = np.flatnonzero(np.diff(ts) > 0.0)
    if seg.size:
        k = np.clip(np.searchsorted(ts[seg], tt, side="right") - 1, 0, seg.size - 1)
        i0, i1 = seg[k], seg[k] + 1
        h = (ts[i1] - ts[i0])[..., None]
        s = ((tt - ts[i0])[..., None]) / h
        h00 = 2 * s**3 - 3 * s**2 + 1
        h10 = s**3 - 2 * s**2 + s
        h01 = -2 * s**3 + 3 * s**2
        h11 = s**3 - s**2
        val = h00 * pos[i0] + h10 * h * vel[i0] + h01 * pos[i1] + h11 * h * vel[i1]
        last = tt >= ts[-1]
        val[last] = pos[-1]
    else:
        val = np.broadcast_to(pos[-1], tt.shape + (3,)).copy()
    force = traj.pusher_force
    # linear in time; at a repeated time np.interp takes the segment that starts there
    fx = np.interp(tt, ts, force[:, 0])
    fy = np.interp(tt, ts, force[:, 1])
    return {"x": val[..., 0], "y": val[..., 1], "phi": val[..., 2], "force_x": fx, "force_y": fy}


def _simplify(rows: np.ndarray, tol: float) -> np.ndarray:
    """Rows (t, x, y) thinned so that the path through the kept rows, linear in time, is within
    ``tol`` [m] of every row (Ramer–Douglas–Peucker in time; ends kept)."""
    n = rows.shape[0]
    if tol <= 0.0 or n <= 2:
        return rows
    keep = np.zeros(n, dtype=bool)
    keep[0] = keep[-1] = True
    stack = [(0, n - 1)]
    while stack:
        i, j = stack.pop()
        if j - i < 2:
            continue
        mid = rows[i + 1 : j]
        s = (mid[:, 0] - rows[i, 0]) / (rows[j, 0] - rows[i, 0])
        interp = rows[i, 1:] + s[:, None] * (rows[j, 1:] - rows[i, 1:])
        dev = np.hypot(*(mid[:, 1:] - interp).T)
        m = int(np.argmax(dev))
        if dev[m] > tol:
            k = i + 1 + m
            keep[k] = True
            stack.append((i, k))
            stack.append((k, j))
    return rows[keep]


class _Push:
    """One push prepared for the fit: its clock, the thinned finger path, the sample times."""

    def __init__(self, run: PushRun, mu: float, tol: float, use_force: bool, settle: float) -> None:
        self.source = run.source
        o = run.object_pose
        # samples after the tip's last row are dropped: the finger's path is not known there
        t_last = float(run.tip[-1, 0])
        o = o[o[:, 0] <= t_last]
        if o.shape[0] < 2:
            raise ValueError(
                f"{run.source}: fewer than 2 object_pose rows up to the last tip_pose time "
                f"{t_last!r} s; valid: a push whose object is tracked while the finger is"
            )
        self.t_start = float(o[0, 0])
        self.t_pose = o[:, 0] - self.t_start
        self.pose = {"x": o[:, 1].copy(), "y": o[:, 2].copy(), "phi": np.unwrap(o[:, 3])}
        tip = _simplify(np.asarray(run.tip, dtype=float), tol).copy()
        tip[:, 0] -= self.t_start
        self.pusher = PointPusher(tip, mu=mu)
        self.force = None
        self.t_force = np.empty(0)
        pf = run.pusher_force()
        if use_force and pf is not None:
            m = (pf[:, 0] >= self.t_start) & (pf[:, 0] <= t_last)
            # the force jumps at the first touch (a plastic impact, then sliding or sticking
            # at once): a sample near it would make the residuals jump with the start pose
            mag = np.hypot(pf[:, 1], pf[:, 2])
            on = np.flatnonzero(m & (mag > TOUCH_FRACTION * (mag[m].max() if m.any() else 0.0)))
            if on.size:
                m &= pf[:, 0] >= pf[on[0], 0] + settle
            if m.sum() >= 1:
                self.t_force = pf[m, 0] - self.t_start
                self.force = {"force_x": pf[m, 1].copy(), "force_y": pf[m, 2].copy()}
        self.times = np.unique(np.concatenate((self.t_pose, self.t_force)))
        self.t_end = float(self.times[-1])


def _ffill(a: np.ndarray) -> np.ndarray:
    """Non-finite model values (a run that ended early) hold the last finite value."""
    ok = np.isfinite(a)
    if ok.all():
        return a
    if not ok.any():
        return np.zeros_like(a)
    idx = np.where(ok, np.arange(a.size), 0)
    np.maximum.accumulate(idx, out=idx)
    out = a[idx]
    first = int(np.argmax(ok))
    out[:first] = a[first]
    return out


class _PushProblem(_Problem):
    """:class:`_Problem` with pushes: every run is simulated with its finger; the residuals
    include the pusher's force; the Jacobian is by central differences for every column."""

    def __init__(
        self, pushes, body, friction, free, start_fixed, guess, g, rtol, fd_step, model, outline
    ):
        pose_runs = [{"t": p.t_pose, **p.pose} for p in pushes]
        comps = ("x", "y", "phi")  # at rest: the start velocities stay 0
        super().__init__(
            pose_runs, body, friction, free, start_fixed, comps, guess, g, rtol, None, fd_step
        )
        self.pushes = pushes
        self.model = model
        self.outline = outline
        self.failures: list[str] = []
        # observation layout: per run, the pose channels at the tracked times, then the force
        self.obs = []
        self.slices = []
        chans: list[str] = []
        n = 0
        for p in pushes:
            items = []
            start = n
            for c in _POSE:
                items.append((c, p.pose[c]))
                chans += [c] * p.t_pose.size
                n += p.t_pose.size
            if p.force is not None:
                for c in _FORCE:
                    items.append((c, p.force[c]))
                    chans += [c] * p.t_force.size
                    n += p.t_force.size
            self.obs.append(items)
            self.slices.append(slice(start, n))
        self.n_obs = n
        self.chan_of_row = np.array(chans, dtype=object)
        self.sigma = {c: 1.0 for c in PUSH_CHANNELS}

    def _sig(self):
        return tuple(self.sigma[c] for c in PUSH_CHANNELS)

    def model_run(self, vals, start, k):
        """Model channels at the measured times of push k (dict) and the run."""
        p = self.pushes[k]
        body, fr = self.objects(vals)
        pose = (float(start[0]), float(start[1]), float(start[2]))
        try:
            if self.model == "quasi_static":
                traj = push_quasi_static(
                    body,
                    fr,
                    p.pusher,
                    p.times,
                    pose,
                    outline=self.outline,
                    g=self.g,
                    rtol=self.rtol,
                )
            else:
                traj = simulate_pushed(
                    body, fr, State(*pose), p.pusher, p.t_end, g=self.g, rtol=self.rtol,
                    outline=self.outline,
                )  # fmt: skip
        except ValueError as exc:  # e.g. a trial start pose with the finger inside the body
            raise ValueError(f"push {k} ({p.source}): {exc}") from None
        if traj.status != "ok":
            self.failures.append(f"push {k}: {traj.message}")
        at_pose = pushed_at(traj, p.t_pose)
        out = {c: _ffill(at_pose[c]) for c in _POSE}
        if p.force is not None:
            at_f = pushed_at(traj, p.t_force)
            out.update({c: _ffill(at_f[c]) for c in _FORCE})
        return out, traj

    def raw_residual_run(self, vals, start, k) -> np.ndarray:
        at, _ = self.model_run(vals, start, k)
        parts = []
        for c, meas in self.obs[k]:
            d = meas - at[c]
            parts.append(_wrap(d) if c == "phi" else d)
        return np.concatenate(parts)

    def jacobian(self, p) -> np.ndarray:
        """Central differences, push by push, for every column (the last one is kept)."""
        key = (p.tobytes(), self._sig())
        cached = getattr(self, "_jac_cache", None)
        if cached is not None and cached[0] == key:
            return cached[1]
        r0 = self.residuals(p)
        J = np.zeros((self.n_obs, p.size))
        w = self.weights()
        for k in range(len(self.runs)):
            sl = self.slices[k]
            cols = list(range(self.n_phys)) + [i for _, i in self.start_index[k]]
            for i in cols:
                h = self.fd_step * self.typ[i]
                up = min(p[i] + h, self.ub[i])
                dn = max(p[i] - h, self.lb[i])
                q_up, q_dn = p.copy(), p.copy()
                q_up[i], q_dn[i] = up, dn
                r_up = (
                    r0[sl] / w[sl]
                    if up == p[i]
                    else self.raw_residual_run(self.physical(q_up), self.start(q_up, k), k)
                )
                r_dn = (
                    r0[sl] / w[sl]
                    if dn == p[i]
                    else self.raw_residual_run(self.physical(q_dn), self.start(q_dn, k), k)
                )
                d = r_up - r_dn
                d = np.where(self.chan_of_row[sl] == "phi", _wrap(d), d)
                J[sl, i] = d / (up - dn) * w[sl]
        self._jac_cache = (key, J)
        return J
