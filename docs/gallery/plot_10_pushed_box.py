"""
A pushed box: stick, slip, stick on a rectangular footprint
===========================================================

A cardboard box on a table (base 40 cm × 30 cm, 5 kg, uniform pressure, μ = 0.35) is pushed
at its mass centre by a horizontal force that ramps from 0 to 25 N over 2 s, is held for 1 s
and is released over 0.1 s (``examples/pushed_box.toml``; run it with
``slidespin simulate examples/pushed_box.toml``). Static friction on the rectangle
(:func:`slidespin.can_stick`, the exact set C of wrenches the footprint can supply) holds the box
until the push reaches μ m g = 17.17 N, at t = 17.1675 / 12.5 = 1.3734 s; the box then slides,
and sticks again once the kinetic energy the push gave it is gone. Stick is decided against
the exact set, never by a smoothed friction law.
"""

from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

import slidespin as ss

# the repository's examples/ folder (this script lives in docs/gallery/)
EXAMPLES = Path(ss.__file__).resolve().parents[2] / "examples"
case = ss.load_case(EXAMPLES / "pushed_box.toml")
tr = ss.simulate_loaded(
    case.body, case.friction, case.initial_state, load=case.load, t_end=case.t_end, max_step=0.5
)
for kind, t0, t1 in tr.phases:
    print(f"{kind:5s} {t0:.4f} - {t1:.4f} s")
print(f"distance {tr.x[-1]:.4f} m, energy error {tr.energy_error:.1e} J")

# %%
# The push, the speed of the box and the friction force, with the slip phase shaded. While
# the box sticks, friction balances the push exactly; while it slides, friction is μ m g.
fig, ax = plt.subplots(figsize=(6.4, 3.8))
tt = np.linspace(0.0, tr.t[-1], 501)
push = np.array([case.load.force_at(x)[0] for x in tt])
mg = case.body.mass * case.g
friction = np.where(
    np.array([any(a < x < b for a, b in tr.slip_intervals) for x in tt]), -0.35 * mg, -push
)
ax.plot(tt, push / 10.0, "k:", label="push / 10 N")
ax.plot(tt, friction / 10.0, "C2--", label="friction / 10 N")
ax.plot(tr.t, tr.speed, "C0", label="speed of G [m/s]")
for t0, t1 in tr.slip_intervals:
    ax.axvspan(t0, t1, color="C1", alpha=0.15)
ax.set_xlabel("t [s]")
ax.legend(loc="upper right", fontsize=8)

# %%
# The one number: when the box starts to move [s] (μ m g / 12.5 N/s = 1.3734 s).
print(f"start of slip = {tr.slip_intervals[0][0]:.9f} s")
