"""
A pushed puck: stick, slip, stick
=================================

A puck at rest (radius 5 cm, 1 kg, μ = 0.3) is pushed 2 cm off its centre by a horizontal
force that grows to 5 N in 1 s and falls back to 0 at 2 s. Static friction holds it until the
push, with its moment about G, leaves the set of wrenches friction can supply
(:func:`slidespin.can_stick`, :func:`slidespin.onset`); it then slides and turns, and sticks again once its kinetic
energy is gone (``examples/pushed_puck.py``). Stick is decided against the exact set, never
by a smoothed friction law.
"""

import matplotlib.pyplot as plt
import numpy as np

import slidespin as ss


def push(t):
    """Force [N] in the plane frame: a triangle 0 -> 5 N -> 0 over 2 s."""
    return (5.0 * max(0.0, 1.0 - abs(t - 1.0)), 0.0)


puck = ss.Body(ss.Circle(0.05), ss.UniformPressure(), mass=1.0)
tr = ss.simulate_loaded(
    puck,
    ss.FrictionTensor.isotropic(0.3),
    ss.State(),
    # the triangle of push(t) as a table: run in compiled code, about 70 times faster than
    # ss.Load(force=push, at=(0.0, 0.02)), which gives the same phases
    load=ss.Load.piecewise_linear([0.0, 1.0, 2.0, 3.0], [0, 5, 0, 0], [0, 0, 0, 0], at=(0.0, 0.02)),
    t_end=3.0,
    max_step=0.5,
)
for kind, t0, t1 in tr.phases:
    print(f"{kind:5s} {t0:.4f} - {t1:.4f} s")

# %%
# The push, the speed and the spin, with the slip phase shaded. The push starts the puck
# below μ m g = 2.94 N: its moment about G helps it out of static friction.
fig, ax = plt.subplots(figsize=(6.4, 3.8))
tt = np.linspace(0.0, tr.t[-1], 301)
ax.plot(tt, [push(x)[0] / 5.0 for x in tt], "k:", label="push / 5 N")
ax.plot(tr.t, tr.speed, label="speed of G [m/s]")
ax.plot(tr.t, tr.omega, label="ω [rad/s]")
for t0, t1 in tr.slip_intervals:
    ax.axvspan(t0, t1, color="C1", alpha=0.15)
ax.set_xlabel("t [s]")
ax.legend()

# %%
# The one number: when the puck starts to move [s].
print(f"start of slip = {tr.slip_intervals[0][0]:.9f} s")
