"""Make the SYNTHETIC tracking dataset ``examples/fit_synthetic.csv`` for ``slidespin fit``.

The data are not measured: five runs of an elliptic plate (a = 0.1 m, e = 0.866, uniform
pressure, m = 1 kg) are simulated with slidespin under the known tensor

    fx = 0.42, fy = 0.54, f = 0.03 (plane frame)

sampled at 200 instants each (about 330 frames per second, past the stop), and Gaussian
noise is added: 0.5 mm on x and y, 0.01 rad on phi (a typical video tracker), rounded to
1 µm and 1e-5 rad. The CSV has the columns ``run,t,x,y,phi`` and no comment line (a comment
would break plain CSV readers); docs/fit.md records that the file is synthetic and how it
was made. Run ``python examples/fit_synthetic.py`` to write it again (same seed, same file).
"""

from __future__ import annotations

import math
import os

import numpy as np

import slidespin as ss

# the fit's own sampler of a trajectory at given times (not a top-level name)
from slidespin.analysis.fit_data import trajectory_at

TRUTH = {"fx": 0.42, "fy": 0.54, "f": 0.03}
SIGMA = {"x": 5e-4, "y": 5e-4, "phi": 1e-2}
N_POINTS = 200
SEED = 20261123
STARTS = (  # speed [m/s], spin [rad/s], direction theta [rad], body angle phi [rad]
    (1.6, 6.0, 0.3, 0.0),
    (1.2, -12.0, 1.9, 0.8),
    (2.0, 3.0, -0.7, 2.0),
    (1.0, 20.0, 3.0, -1.0),
    (1.8, -4.0, -2.2, 0.4),
)
PATH = os.path.join(os.path.dirname(os.path.abspath(__file__)), "fit_synthetic.csv")


def body() -> ss.Body:
    """The plate of ``examples/fit_case.toml``."""
    return ss.Body(ss.Ellipse.from_eccentricity(0.1, 0.866), ss.UniformPressure(), mass=1.0)


def make_runs(seed: int = SEED, n_points: int = N_POINTS, truth=None, sigma=None):
    """The synthetic runs: a list of ``{'t', 'x', 'y', 'phi'}`` and their true start states."""
    truth = dict(TRUTH if truth is None else truth)
    sigma = dict(SIGMA if sigma is None else sigma)
    rng = np.random.default_rng(seed)
    friction = ss.FrictionTensor(truth["fx"], truth["fy"], truth.get("f", 0.0))
    runs, starts = [], []
    for k, (speed, omega, theta, phi) in enumerate(STARTS):
        st = ss.State.from_speed(speed, omega, theta, phi, x=0.05 * k, y=-0.03 * k)
        # dense steps: the synthetic truth is far more accurate than the tracking noise
        traj = ss.simulate(body(), friction, st, max_step=0.01)
        t = np.arange(n_points) / 330.0 + 1.0 * k  # one run per second of the clock
        clean = trajectory_at(traj, t - t[0])
        run = {"t": t}
        for c in ("x", "y", "phi"):
            run[c] = clean[c] + rng.normal(0.0, sigma[c], n_points)
        runs.append(run)
        starts.append(st)
    return runs, starts


def write_csv(runs, path: str = PATH) -> None:
    """Write the runs as ``run,t,x,y,phi`` (1 µm and 1e-5 rad resolution)."""
    with open(path, "w", encoding="utf-8", newline="") as fh:
        fh.write("run,t,x,y,phi\n")
        for k, run in enumerate(runs):
            fh.writelines(
                f"{k},{run['t'][i]:.6f},{run['x'][i]:.6f},{run['y'][i]:.6f},{run['phi'][i]:.5f}\n"
                for i in range(run["t"].size)
            )


def main() -> None:
    runs, starts = make_runs()
    write_csv(runs)
    print(f"wrote {PATH}: {len(runs)} synthetic runs x {N_POINTS} points")
    print(
        "truth: "
        + ", ".join(f"{k} = {val}" for k, val in TRUTH.items())
        + f"; noise sigma: x, y {SIGMA['x']} m, phi {SIGMA['phi']} rad"
    )
    for k, st in enumerate(starts):
        print(
            f"run {k} start: speed {st.speed:.3g} m/s, omega {st.omega:.3g} rad/s, "
            f"theta {math.atan2(st.vy, st.vx):.3g} rad, phi {st.phi:.3g} rad"
        )


if __name__ == "__main__":
    main()
