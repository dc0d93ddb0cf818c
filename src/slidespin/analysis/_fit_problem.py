"""The least-squares problem behind :func:`slidespin.analysis.fit.fit` (MODEL §12; internal).

:class:`_Problem` keeps the bookkeeping of one fit: the free physical parameters, then each
run's free start components, with their guesses, typical sizes and bounds (G of a linear law
in the core of the patch, where the pressure is ≥ 0; MODEL §10). For a trial point it builds
the body and tensor, simulates each run, and returns the weighted residuals at the measured
times and their Jacobian, run by run: exact, from the motion's sensitivities at the measured
times (:mod:`slidespin.motion.sensitivity`, MODEL §15: one sensitivity run per run and
Jacobian), or by central differences of whole simulations (two per parameter and run).
"""

from __future__ import annotations

import math

import numpy as np

from slidespin import _validate as v
from slidespin.analysis.fit_data import _PAIR, CHANNELS, START, hermite_columns, trajectory_at
from slidespin.contact.body import Body
from slidespin.contact.friction import ANGLE_MAX, FrictionTensor
from slidespin.contact.pressure import LinearPressure
from slidespin.contact.shapes import Blade
from slidespin.motion.simulate import simulate
from slidespin.motion.state import State

#: step budget of a simulation inside a fit before its end speed is checked
QUICK_STEPS = 4000


def _core_scale(patch, offset: tuple[float, float]) -> float:
    """Largest s in [0, 1] for which the linear law with G = r_c + s·offset is ≥ 0 on the
    footprint ``patch`` (r_c its area centroid; MODEL §10).

    The law is p ∝ 1 + gᵀ(r − r_c) with J g = A (r_G − r_c): g is linear in the offset, so the
    minimum of gᵀ(r − r_c) over the footprint (at a polygon vertex or on a disk's rim) scales
    with s and p ≥ 0 holds up to s = −1/min.
    """
    d = np.asarray(offset, dtype=float)
    if not np.any(d):
        return 1.0
    rc = np.asarray(patch.centroid, dtype=float)
    grad = np.linalg.solve(np.asarray(patch.second_moment, dtype=float), patch.area * d)
    arrays = patch.to_arrays()
    low = math.inf
    if arrays.edges.size:
        low = float(np.min((arrays.edges[:, :2] - rc) @ grad))
    gn = float(np.hypot(*grad))
    for xo, yo, radius, sign in arrays.circles:
        if sign > 0:
            low = min(low, float(grad @ (np.array([xo, yo]) - rc)) - gn * radius)
    return 1.0 if low >= -1.0 else -1.0 / low


def _wrap(a):
    return (a + np.pi) % (2.0 * np.pi) - np.pi


class _Problem:
    """Parameter bookkeeping and residuals of one fit (internal; not part of the API)."""

    def __init__(
        self, runs, body, friction, free, start_fixed, start_free, guess, g, rtol, max_step, fd_step,
        jacobian="differences",
    ):  # fmt: skip
        self.runs = runs
        self.mode = jacobian
        self.body = body
        self.friction = friction
        self.free = free
        self.g = g
        self.rtol = rtol
        self.max_step = max_step
        self.fd_step = fd_step
        a = body.length_unit  # the semi-axis a of an ellipse, the extent of a footprint
        xg, yg = body.mass_centre
        base = {
            "fx": friction.fx,
            "fy": friction.fy,
            "f": friction.f,
            "angle": friction.angle,
            "xi_c": xg,
            "eta_c": yg,
            "moment_of_inertia": body.moment_of_inertia,
        }
        self.base = base
        if isinstance(body.patch, Blade):
            # a line contact takes the uniform line load only: G stays over its centre
            # (xi_c, eta_c cannot be freed, _check_free refuses them without a linear law)
            cx, cy = body.patch.centroid
            xi_lo = xi_hi = cx
            eta_lo = eta_hi = cy
            typ_xi = typ_eta = a / 4.0
        elif body.is_footprint:
            # G's range: the core of the footprint (p >= 0) along each axis through the
            # area centroid; objects() projects a point outside the core back onto it
            cx, cy = body.patch.centroid
            xi_lo, xi_hi = (
                cx + sgn * a * _core_scale(body.patch, (sgn * a, 0.0)) for sgn in (-1.0, 1.0)
            )
            eta_lo, eta_hi = (
                cy + sgn * a * _core_scale(body.patch, (0.0, sgn * a)) for sgn in (-1.0, 1.0)
            )
            typ_xi = typ_eta = a / 4.0
        else:
            b = body.patch.b
            xi_lo, xi_hi, eta_lo, eta_hi = -a / 4.0, a / 4.0, -b / 4.0, b / 4.0
            typ_xi, typ_eta = a / 4.0, b / 4.0
        fmax = max(friction.fx, friction.fy)
        typ = {
            "fx": fmax,
            "fy": fmax,
            "f": fmax,
            "angle": 1.0,
            "xi_c": typ_xi,
            "eta_c": typ_eta,
            "moment_of_inertia": body.moment_of_inertia,
        }
        c_lo, c_hi = v.COEFFICIENT  # FrictionTensor's range
        skew = v.SKEW
        lo = {
            "fx": c_lo,
            "fy": c_lo,
            "f": -skew,
            "angle": -ANGLE_MAX,
            "xi_c": xi_lo,
            "eta_c": eta_lo,
            "moment_of_inertia": 1e-4 * body.moment_of_inertia,
        }
        hi = {
            "fx": c_hi,
            "fy": c_hi,
            "f": skew,
            "angle": ANGLE_MAX,
            "xi_c": xi_hi,
            "eta_c": eta_hi,
            "moment_of_inertia": 1e4 * body.moment_of_inertia,
        }
        names, x0, typs, lbs, ubs, owner = [], [], [], [], [], []
        for p in free:
            names.append(p)
            x0.append(base[p])
            typs.append(typ[p])
            lbs.append(lo[p])
            ubs.append(hi[p])
            owner.append(-1)
        self.n_phys = len(free)
        self.start_index = []  # per run: list of (component index, parameter index)
        self.start_base = []
        for k, run in enumerate(runs):
            st = guess[k]
            vals = st.as_array()
            speed = max(math.hypot(st.vx, st.vy), a * abs(st.omega), 1e-2 * math.sqrt(g * a))
            tp = {"x": a, "y": a, "phi": 1.0, "vx": speed, "vy": speed, "omega": speed / a}
            self.start_base.append(vals.copy())
            idx = []
            if start_fixed[k] is None:
                comps = (
                    start_free
                    if start_free is not None
                    else tuple(
                        comp
                        for c in CHANNELS
                        if c in run and np.isfinite(run[c]).any()
                        for comp in (c, _PAIR[c])
                    )
                )
                for comp in START:
                    if comp in comps:
                        j = START.index(comp)
                        idx.append((j, len(names)))
                        names.append(f"run{k}.{comp}")
                        x0.append(vals[j])
                        typs.append(tp[comp])
                        lbs.append(-np.inf)
                        ubs.append(np.inf)
                        owner.append(k)
            self.start_index.append(idx)
        self.names = tuple(names)
        self.x0 = np.array(x0, dtype=float)
        self.typ = np.array(typs, dtype=float)
        self.lb = np.array(lbs, dtype=float)
        self.ub = np.array(ubs, dtype=float)
        self.owner = np.array(owner, dtype=int)
        # observation layout: per run, per channel, the finite rows
        self.obs = []  # per run: list of (channel, mask)
        self.slices = []
        n = 0
        for run in runs:
            items = []
            start = n
            for c in CHANNELS:
                if c in run:
                    m = np.isfinite(run[c])
                    if m.any():
                        items.append((c, m))
                        n += int(m.sum())
            self.obs.append(items)
            self.slices.append(slice(start, n))
        self.n_obs = n
        self.chan_of_row = np.empty(n, dtype=object)
        for k, items in enumerate(self.obs):
            i = self.slices[k].start
            for c, m in items:
                cnt = int(m.sum())
                self.chan_of_row[i : i + cnt] = c
                i += cnt
        self.sigma = {c: 1.0 for c in CHANNELS}
        self._cache = None

    # -- building the model objects --------------------------------------------------------
    def physical(self, p) -> dict:
        vals = dict(self.base)
        for i, name in enumerate(self.free):
            vals[name] = float(p[i])
        return vals

    def objects(self, vals):
        fr = FrictionTensor(vals["fx"], vals["fy"], vals["f"], self.friction.frame, vals["angle"])
        pressure = self.body.pressure
        if "xi_c" in self.free or "eta_c" in self.free:
            xi, eta = vals["xi_c"], vals["eta_c"]
            patch = self.body.patch
            if self.body.is_footprint:
                # projection towards the area centroid onto the core (p >= 0 on the footprint)
                cx, cy = patch.centroid
                s = _core_scale(patch, (xi - cx, eta - cy))
                if s < 1.0:
                    s *= 1.0 - 1e-12
                    xi, eta = cx + s * (xi - cx), cy + s * (eta - cy)
            else:
                c = (xi / patch.a) ** 2 + (eta / patch.b) ** 2
                if c > 1.0 / 16.0:  # radial projection onto the core of the patch
                    s = math.sqrt(1.0 / 16.0 / c) * (1.0 - 1e-12)
                    xi, eta = xi * s, eta * s
            pressure = LinearPressure(xi, eta)
        body = Body(self.body.patch, pressure, self.body.mass, vals["moment_of_inertia"])
        return body, fr

    def start(self, p, k) -> np.ndarray:
        s = self.start_base[k].copy()
        for j, i in self.start_index[k]:
            s[j] = p[i]
        return s

    def simulate(self, vals, start, t_need=math.inf):
        """Trajectory from ``start``; it must be exact up to ``t_need`` [s] at least."""
        body, fr = self.objects(vals)
        state = State(*start)
        traj = simulate(
            body, fr, state, g=self.g, rtol=self.rtol, max_step=self.max_step, max_steps=QUICK_STEPS
        )
        if traj.status == "max_steps":
            # A slow approach to the stop (MODEL §9, e.g. near pure sliding) may take many
            # steps at speeds that no longer move the body visibly, or after the last
            # measured time. The final row may be an extrapolated stop: judge by the last
            # integrator step before it, and run again with the full budget only if that
            # step is inside the measured times and still moving.
            k = body.radius_of_gyration
            s0 = math.sqrt(state.vx**2 + state.vy**2 + (k * state.omega) ** 2)
            i = max(0, traj.t.size - 2)
            s_end = math.hypot(traj.speed[i], k * traj.omega[i])
            if traj.t[i] < t_need and not s_end <= 1e-9 * s0:
                traj = simulate(body, fr, state, g=self.g, rtol=self.rtol, max_step=self.max_step)
        return traj

    def model_run(self, vals, start, k):
        """Simulated channels at the measured times of run k (dict) and the trajectory."""
        run = self.runs[k]
        traj = self.simulate(vals, start, run["t"][-1] - run["t"][0])
        at = trajectory_at(traj, run["t"] - run["t"][0])
        return at, traj

    def raw_residual_run(self, vals, start, k) -> np.ndarray:
        """Measured − simulated at the observed rows of run k (data units, φ wrapped)."""
        at, _ = self.model_run(vals, start, k)
        run = self.runs[k]
        parts = []
        for c, m in self.obs[k]:
            d = run[c][m] - at[c][m]
            parts.append(_wrap(d) if c == "phi" else d)
        return np.concatenate(parts) if parts else np.empty(0)

    def scale_rows(self, k) -> np.ndarray:
        run_rows = self.chan_of_row[self.slices[k]]
        return np.array([1.0 / self.sigma[c] for c in run_rows])

    def raw_residuals(self, p) -> np.ndarray:
        vals = self.physical(p)
        return np.concatenate(
            [self.raw_residual_run(vals, self.start(p, k), k) for k in range(len(self.runs))]
        )

    def residuals(self, p) -> np.ndarray:
        key = p.tobytes()
        if self._cache is not None and self._cache[0] == key and self._cache[1] == self._sig():
            return self._cache[2]
        raw = self.raw_residuals(p)
        r = raw * self.weights()
        self._cache = (key, self._sig(), r)
        return r

    def _sig(self):
        return tuple(self.sigma[c] for c in CHANNELS)

    def weights(self) -> np.ndarray:
        return np.array([1.0 / self.sigma[c] for c in self.chan_of_row])

    def jacobian(self, p) -> np.ndarray:
        """The Jacobian of the weighted residuals, run by run: exact (``mode`` "exact", the
        sensitivities at the measured times; a run whose sensitivities cannot be computed
        falls back to differences) or central differences; exact columns for the start
        positions x₀, y₀ (the motion is invariant under translation) either way."""
        J = np.zeros((self.n_obs, p.size))
        for k in range(len(self.runs)):
            if self.mode != "exact" or not self._exact_run(p, k, J):
                self._differences_run(p, k, J)
        return J

    def _exact_run(self, p, k, J) -> bool:
        """Fill run k's columns of ``J`` from the sensitivities; False if they cannot be
        computed for this run (its motion does not stop, or does not move)."""
        sl = self.slices[k]
        w = self.weights()[sl]
        vals = self.physical(p)
        body, fr = self.objects(vals)
        if ("xi_c" in self.free or "eta_c" in self.free) and (
            body.pressure.centroid != (vals["xi_c"], vals["eta_c"])
        ):
            return False  # G projected onto the core: the residual's is another function
        cols = [(name, i) for i, name in enumerate(self.free)]
        for j, i in self.start_index[k]:
            comp = START[j]
            if comp in ("x", "y"):
                rows = self.chan_of_row[sl] == comp
                J[sl, i] = np.where(rows, -w, 0.0)
            else:
                cols.append(("phi0" if comp == "phi" else comp, i))
        if not cols:
            return True
        try:
            traj = simulate(body, fr, State(*self.start(p, k)), g=self.g, rtol=self.rtol,
                            max_step=self.max_step, sensitivities=[c for c, _ in cols])  # fmt: skip
        except (ValueError, RuntimeError):
            return False
        sens = traj.sensitivities
        assert sens is not None  # asked for above
        run = self.runs[k]
        t = run["t"] - run["t"][0]
        # one interpolant for every column: (x, y, φ) of each parameter, at fixed t
        pos = np.column_stack([sens[name][c] for name, _ in cols for c in ("x", "y", "phi")])
        vel = np.column_stack([sens[name][c] for name, _ in cols for c in ("vx", "vy", "omega")])
        at = hermite_columns(sens.t, pos, vel, t, traj.t_stop <= 0.0)
        for j, (_, i) in enumerate(cols):
            J[sl, i] = (
                -np.concatenate([at[m, 3 * j + CHANNELS.index(c)] for c, m in self.obs[k]]) * w
            )
        return True

    def _differences_run(self, p, k, J) -> None:
        """Central differences of run k's residuals (its physical and start columns)."""
        r0 = self.residuals(p)
        w = self.weights()
        sl = self.slices[k]
        cols = [i for i in range(self.n_phys)] + [i for _, i in self.start_index[k]]
        for i in cols:
            comp = self.names[i].split(".")[-1] if i >= self.n_phys else None
            if comp in ("x", "y"):
                rows = self.chan_of_row[sl] == comp
                J[sl, i] = np.where(rows, -w[sl], 0.0)
                continue
            h = self.fd_step * self.typ[i]
            up = min(p[i] + h, self.ub[i])
            dn = max(p[i] - h, self.lb[i])
            vals_up, vals_dn = p.copy(), p.copy()
            vals_up[i], vals_dn[i] = up, dn
            r_up = self.raw_residual_run(self.physical(vals_up), self.start(vals_up, k), k)
            r_dn = (
                r0[sl] / w[sl]
                if dn == p[i]
                else self.raw_residual_run(self.physical(vals_dn), self.start(vals_dn, k), k)
            )
            if up == p[i]:
                r_up = r0[sl] / w[sl]
            d = r_up - r_dn
            # φ residuals are wrapped: a difference across the cut is not a derivative
            d = np.where(self.chan_of_row[sl] == "phi", _wrap(d), d)
            J[sl, i] = d / (up - dn) * w[sl]
