"""
Watching it slide and spin: an animation
========================================

:func:`slidespin.animate` turns a trajectory into an animated GIF (Pillow, no ffmpeg):
the outline of the patch at each instant, the velocity of the mass centre G as an arrow and
the instantaneous centre of rotation (ICR) as a cross. ``slidespin animate CASE.toml --out
run.gif`` does the same from a case file. Here we write the GIF of the demo (into a temporary
folder) and draw a film strip of the same frames. The GIF, made the same way when the site is
built, plays on the :doc:`front page </index>` and here:

.. image:: /_generated/demo.gif
   :alt: The demo plate sliding and turning to its stop, with the velocity of G and the ICR
"""

import math
import os
import tempfile

import matplotlib.pyplot as plt
import numpy as np

import slidespin as ss

body = ss.Body(ss.Ellipse.from_eccentricity(0.1, 0.866), ss.UniformPressure(), mass=1.0)
traj = ss.simulate(
    body, ss.FrictionTensor(0.42, 0.54), ss.State.from_speed(1.0, omega=5.0, theta=math.pi / 4)
)

with tempfile.TemporaryDirectory() as tmp:
    path = ss.animate(traj, os.path.join(tmp, "demo.gif"), fps=20, frames=60)
    print(f"GIF: 60 frames, {os.path.getsize(path) / 1024:.0f} KiB")

# %%
# The frames are evenly spaced in time; between the integrator's steps (about 40 here) the
# position and the angle are cubic Hermite interpolants on the recorded velocities. The ICR
# lies where the velocity of the body point vanishes, G + (−vy, vx)/ω: far away while the
# plate mostly slides, closer as the spin takes over.
st = ss.frame_states(traj, 8)
fig, ax = plt.subplots(figsize=(6.4, 4.2))
outline = body.patch.outline(121) - np.asarray(body.mass_centre)
for k in range(st.t.size):
    c, s = math.cos(st.phi[k]), math.sin(st.phi[k])
    xw = st.x[k] + c * outline[:, 0] - s * outline[:, 1]
    yw = st.y[k] + s * outline[:, 0] + c * outline[:, 1]
    ax.plot(xw, yw, color=plt.cm.viridis(k / (st.t.size - 1)), lw=1.2)
    ax.quiver(
        st.x[k],
        st.y[k],
        st.vx[k],
        st.vy[k],
        angles="xy",
        scale_units="xy",
        scale=25,
        color="C1",
        width=0.004,
    )
    if st.omega[k] != 0.0:  # the ICR, where it lies near the plate
        ix, iy = st.x[k] - st.vy[k] / st.omega[k], st.y[k] + st.vx[k] / st.omega[k]
        if abs(ix - st.x[k]) < 0.15 and abs(iy - st.y[k]) < 0.15:
            ax.plot(ix, iy, "x", color=plt.cm.viridis(k / (st.t.size - 1)), ms=7, mew=2)
ax.plot(traj.x, traj.y, color="0.5", lw=0.8)
ax.set_aspect("equal")
ax.set_xlabel("x [m]")
ax.set_ylabel("y [m]")
ax.set_title(
    "8 frames of the demo, start (purple) to stop (yellow); arrows: velocity of G, crosses: ICR",
    fontsize=9,
)

# %%
# The last frame is the stop itself. The one number: the plate's rotation at the stop [rad].
print(f"rotation at the stop = {st.phi[-1] - st.phi[0]:.9f} rad")
