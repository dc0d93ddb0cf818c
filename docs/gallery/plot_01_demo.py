"""
The demo: an elliptic plate stops under anisotropic friction
=============================================================

An elliptic plate (a = 0.1 m, e = 0.866, so b = 0.05 m; uniform pressure; 1 kg) slides on a
plane whose friction is stronger across OX than along it (fx = 0.42, fy = 0.54). It is thrown
at 1 m/s at 45° with a spin of 5 rad/s. This is ``slidespin demo``.
"""

# %%
# Build the body, the friction tensor and the start, and integrate to the stop. ``max_step``
# only asks for more recorded points (for the figure); the stop does not depend on it.
import math

import slidespin as ss

body = ss.Body(ss.Ellipse.from_eccentricity(0.1, 0.866), ss.UniformPressure(), mass=1.0)
friction = ss.FrictionTensor(fx=0.42, fy=0.54)
start = ss.State.from_speed(1.0, omega=5.0, theta=math.pi / 4)
traj = ss.simulate(body, friction, start, max_step=0.05)
print(traj)

# %%
# The ending is ``mixed``: v and ω vanish together with v → β* ω. The velocity does **not**
# end along a principal axis of the tensor (ϑ* ≠ 0), which the paper states for an ellipse;
# it does for a circle (MODEL §7, erratum 11).
print(f"ending {traj.ending}, status {traj.status}")
print(f"beta*/a = {traj.beta_stop_ratio:.6f}, theta* = {math.degrees(traj.theta_stop):.3f} deg")

# %%
# The figure of ``slidespin demo``: the path with the outline of the plate, β/a and ϑ over
# time.
fig = ss.plot_trajectory(traj, title="demo: elliptic plate, anisotropic friction")

# %%
# The one number this example stands for: the stop time [s].
print(f"t_stop = {traj.t_stop:.10f} s")
