"""A puck at rest, pushed off-centre by a force that ramps up and is released (MODEL §11).

A uniform disk (radius 5 cm, 1 kg, μ = 0.3 on a level plane) is pushed at the point
(0, 2 cm) of its rim region by a horizontal force that grows to 5 N in 1 s and falls back to 0
at 2 s. Static friction holds it until the push (with its moment about G) leaves the set C
of wrenches friction can supply; it then slides and turns, and sticks again once its kinetic
energy is gone. Prints the time at which it starts to move [s] and draws the push, the speed
and the spin, with the stick and slip phases shaded.

    python examples/pushed_puck.py [OUT.png]
"""

from __future__ import annotations

import sys

import numpy as np

import slidespin as ss


def push(t):
    """Force [N] in the plane frame: a triangle 0 → 5 N → 0 over 2 s (as a function; the run
    uses the same push as a table, which runs in compiled code: about 70 times faster)."""
    return (5.0 * max(0.0, 1.0 - abs(t - 1.0)), 0.0)


def compute():
    puck = ss.Body(ss.Circle(0.05), ss.UniformPressure(), mass=1.0)
    friction = ss.FrictionTensor.isotropic(0.3)
    # the triangle of push(t), exactly, by its knots
    load = ss.Load.piecewise_linear(
        [0.0, 1.0, 2.0, 3.0], [0, 5, 0, 0], [0, 0, 0, 0], at=(0.0, 0.02)
    )
    return ss.simulate_loaded(puck, friction, ss.State(), load=load, t_end=3.0, max_step=0.5)


def main(out="pushed_puck.png"):
    tr = compute()
    t_start = tr.slip_intervals[0][0]
    print(
        f"the puck starts to move at t = {t_start:.9f} s; phases: "
        + ", ".join(f"{k} {a:.4f}-{b:.4f} s" for k, a, b in tr.phases)
    )
    if out:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        fig, ax = plt.subplots(figsize=(6.4, 3.6))
        tt = np.linspace(0.0, tr.t[-1], 301)
        ax.plot(tt, [push(x)[0] / 5.0 for x in tt], "k:", label="push / 5 N")
        ax.plot(tr.t, tr.speed, label="speed of G [m/s]")
        ax.plot(tr.t, tr.omega / 10.0, label="ω / 10 [rad/s]")
        for a, b in tr.slip_intervals:
            ax.axvspan(a, b, color="C1", alpha=0.12, lw=0)
        ax.set_xlabel("t [s]")
        ax.set_title("pushed puck: stick, slip (shaded), stick", fontsize=10)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(out, dpi=120)
        plt.close(fig)
    return t_start


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "pushed_puck.png")
