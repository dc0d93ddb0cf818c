"""
A spinning puck on a slope
==========================

A uniform disk (radius 4 cm, 0.2 kg, μ = 0.3) is released with a spin of 30 rad/s on a plane
tilted by 20°, steeper than its friction angle (tan 20° = 0.364 > μ). While it spins, the
friction under the patch points in every direction and only part of it resists the slide
downhill, so the puck accelerates faster than a block that does not spin,
a = g (sin α − μ cos α); once the spin has died out it slides like that block
(``examples/puck_on_slope.py``; loads and slopes: :class:`slidespin.Incline`,
:func:`slidespin.simulate_loaded`).
"""

import math

import matplotlib.pyplot as plt
import numpy as np

import slidespin as ss

alpha, mu, g = math.radians(20.0), 0.3, 9.81
puck = ss.Body(ss.Circle(0.04), ss.UniformPressure(), mass=0.2)
friction = ss.FrictionTensor.isotropic(mu)
slope = ss.Incline(alpha, downhill=0.0)  # downhill along +x
tr = ss.simulate_loaded(
    puck, friction, ss.State(omega=30.0), incline=slope, t_end=1.0, max_step=0.2
)
for kind, start, end in tr.phases:  # (kind, start [s], end [s]) of each stick or slip phase
    print(f"{kind}: {start:.4f} s to {end:.4f} s")

# %%
# Speed and spin over time, against the two closed forms that bound the motion: the block
# that does not spin, v = g (sin α − μ cos α) t, and no friction at all, v = g sin α t.
t = np.asarray(tr.t)
fig, ax = plt.subplots(figsize=(6.4, 3.8))
ax.plot(t, tr.speed, label="spinning puck: speed of G [m/s]")
ax.plot(t, g * (math.sin(alpha) - mu * math.cos(alpha)) * t, "--", label="non-spinning block [m/s]")
ax.plot(t, tr.omega / 30.0, label="ω/ω₀")
ax.set_xlabel("t [s]")
ax.legend()
ax.set_title("spinning puck on a 20° slope, μ = 0.3", fontsize=10)

# %%
# The one number: the distance down the slope after 1 s [m]. A block that does not spin
# would cover g (sin α − μ cos α)/2 = 0.295 m.
distance = math.hypot(tr.x[-1] - tr.x[0], tr.y[-1] - tr.y[0])
print(f"distance after 1 s = {distance:.9f} m")
