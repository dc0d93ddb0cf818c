"""Make the SYNTHETIC pushing dataset of this folder, in the MIT push dataset's JSON layout.

The data are not measured. Four pushes of a square steel block (90 mm, 0.837 kg, like the
dataset's ``rect1``) by a point finger are simulated with slidespin's dynamic pushing model
(``ss.simulate(..., pusher=ss.PointPusher(...))``, MODEL §13) under the known parameters

    friction: fx = 0.22, fy = 0.30, f = 0, plane frame (an anisotropic, grained surface)
    pressure: linear law with its centroid (= G) at (xi_c, eta_c) = (4, -2) mm
    finger:   mu_p = 0.25 (point contact, no probe radius)

Each push starts with the block at rest and the finger 4 mm from one face, then pushes at
25-30 mm/s for 1.5 s along a path of two straight pieces. The three streams are sampled at
100 Hz on slightly different clocks (as the dataset's are) and Gaussian noise is added with a
fixed seed: 0.1 mm and 2 mrad on the object pose (motion capture), 0.05 N on the force and
1e-4 N m on the torque; the finger's positions are rounded to 1 µm (robot encoders). Values
are rounded to the printed digits. ``ft_wrench`` follows the dataset's sign: the force of the
object on the finger (the negative of the pusher's force on the object).

Every file says ``"source": "synthetic ..."``; ``"truth"`` holds the generating parameters
(the independent truth of tests/analysis/test_fit_push.py). Run

    python examples/push_data/make_synthetic_pushes.py

to write the files again (same seed, same files).
"""

from __future__ import annotations

import json
import math
import os

import numpy as np

import slidespin as ss

# the push fit's own sampler of a pushed run at given times (not a top-level name)
from slidespin.analysis.fit_push import pushed_at

SEED = 20261125
SIDE = 0.09  # [m]
MASS = 0.837  # [kg]
XI_C, ETA_C = 0.004, -0.002  # [m]
TRUTH = {"fx": 0.22, "fy": 0.30, "f": 0.0, "angle": 0.0, "xi_c": XI_C, "eta_c": ETA_C}
MU_P = 0.25
RATE = 100.0  # samples per second of every stream
DURATION = 1.5  # [s]
NOISE = {"x": 1e-4, "y": 1e-4, "phi": 2e-3, "force": 0.05, "torque": 1e-4}
GAP = 0.004  # the finger's start distance from the face [m]
#: (body pose x, y, phi [m, m, rad]; face: -1 the -xi face, -2 the -eta face; offset along
#: the face [m]; directions of the two pieces in the body frame [rad]; speed [m/s])
PUSHES = (
    ((0.30, 0.00, 0.0), -1, 0.000, (0.0, 0.35), 0.030),
    ((0.30, 0.05, 0.4), -1, 0.018, (0.0, -0.2), 0.025),
    ((0.28, -0.04, -0.6), -2, -0.012, (0.1, -0.3), 0.030),
    ((0.32, 0.02, 1.2), -1, -0.020, (0.2, 0.0), 0.028),
)
#: each stream's clock starts this late [s] (the dataset's streams are not synchronised)
OFFSETS = {"tip_pose": 0.0, "object_pose": 0.0031, "ft_wrench": 0.0017}
T0 = 1764100000.0  # an arbitrary UNIX time for the first sample, as the dataset has
HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = (
    "synthetic: simulated by slidespin's dynamic pushing model (MODEL section 13) with known "
    "parameters and seeded noise, written by examples/push_data/make_synthetic_pushes.py; "
    "not a measurement"
)


def body() -> ss.Body:
    """The pushed block (the truth's pressure centre)."""
    inertia = MASS * (2.0 * SIDE**2) / 12.0 + MASS * (XI_C**2 + ETA_C**2)
    return ss.Body(ss.Rectangle(SIDE, SIDE), ss.LinearPressure(XI_C, ETA_C), MASS, inertia)


def friction() -> ss.FrictionTensor:
    """The true friction tensor."""
    return ss.FrictionTensor(TRUTH["fx"], TRUTH["fy"], TRUTH["f"], "plane", TRUTH["angle"])


def _rot(phi: float) -> np.ndarray:
    c, s = math.cos(phi), math.sin(phi)
    return np.array([[c, -s], [s, c]])


def finger_path(pose, face, offset, dirs, speed) -> np.ndarray:
    """Rows (t, x, y): the finger's waypoints in the plane frame, 0 to DURATION."""
    x0, y0, phi = pose
    h = 0.5 * SIDE
    # body frame relative to the patch centre; G sits at (XI_C, ETA_C) from it
    if face == -1:
        start_b = np.array([-h - GAP, offset])
        base = 0.0
    else:
        start_b = np.array([offset, -h - GAP])
        base = 0.5 * math.pi
    start_b = start_b - np.array([XI_C, ETA_C])
    rot = _rot(phi)
    p0 = np.array([x0, y0]) + rot @ start_b
    half = 0.5 * DURATION
    d1 = rot @ np.array([math.cos(base + dirs[0]), math.sin(base + dirs[0])])
    d2 = rot @ np.array([math.cos(base + dirs[1]), math.sin(base + dirs[1])])
    p1 = p0 + speed * half * d1
    p2 = p1 + speed * half * d2
    return np.array([[0.0, *p0], [half, *p1], [DURATION, *p2]])


def simulate_push(pose, path):
    """The dynamic push over [0, DURATION] and each stream's sample times."""
    finger = ss.PointPusher(path, mu=MU_P)
    times = {k: off + np.arange(int(round(DURATION * RATE))) / RATE for k, off in OFFSETS.items()}
    traj = ss.simulate(
        body(), friction(), ss.State(*pose), pusher=finger, t_end=DURATION, rtol=1e-11
    )
    if traj.status != "ok":
        raise RuntimeError(f"the push did not run to its end: {traj.message}")
    return finger, times, traj


def make(seed: int = SEED) -> list[dict]:
    """The pushes as JSON-ready dicts (MIT layout, plus ``source``, ``truth``, ``noise``)."""
    rng = np.random.default_rng(seed)
    out = []
    for k, (pose, face, offset, dirs, speed) in enumerate(PUSHES):
        path = finger_path(pose, face, offset, dirs, speed)
        finger, times, traj = simulate_push(pose, path)
        tt = times["tip_pose"]
        tip = finger.position(tt)
        tip = np.round(tip, 6)  # 1 µm encoders
        to = times["object_pose"]
        at = pushed_at(traj, to)
        obj = np.column_stack(
            (
                at["x"] + NOISE["x"] * rng.standard_normal(to.size),
                at["y"] + NOISE["y"] * rng.standard_normal(to.size),
                at["phi"] + NOISE["phi"] * rng.standard_normal(to.size),
            )
        )
        tf = times["ft_wrench"]
        af = pushed_at(traj, tf)
        # the dataset's sign: the force of the object on the finger
        force = -np.column_stack((af["force_x"], af["force_y"]))
        force = force + NOISE["force"] * rng.standard_normal((tf.size, 2))
        torque = NOISE["torque"] * rng.standard_normal(tf.size)

        def rows(t, cols, digits):
            t = np.round(T0 + t, 4)
            return [
                [float(a)] + [round(float(c), d) for c, d in zip(r, digits)]
                for a, r in zip(t, cols)
            ]

        doc = {
            "source": SOURCE,
            "truth": {**TRUTH, "mu_p": MU_P, "side": SIDE, "mass": MASS},
            "noise": NOISE,
            "tip_pose": rows(tt, tip, (6, 6)),
            "object_pose": rows(to, obj, (6, 6, 5)),
            "ft_wrench": rows(tf, np.column_stack((force, torque)), (4, 4, 6)),
        }
        name = f"synthetic_shape=square90_v={round(speed * 1000)}_push={k + 1}.json"
        out.append({"name": name, "doc": doc})
    return out


def main(directory: str = HERE) -> list[str]:
    """Write the pushes into ``directory``; return the paths."""
    paths = []
    for item in make():
        path = os.path.join(directory, item["name"])
        with open(path, "w", encoding="utf-8") as f:
            json.dump(item["doc"], f, separators=(",", ":"))
            f.write("\n")
        paths.append(path)
    return paths


if __name__ == "__main__":
    for p in main():
        print(f"{os.path.basename(p)}: {os.path.getsize(p)} bytes")
