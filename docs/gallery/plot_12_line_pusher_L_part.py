"""
A line pusher pushing an off-centre L-shaped part
=================================================

A flat pusher (a segment 12 cm long, :class:`slidespin.LinePusher`, μp = 0.5) pushes an
L-shaped part (a polygon footprint 20 cm × 16 cm with 6 cm wide arms, 1 kg, uniform
pressure, μ = 0.3 on the table) on its long bottom edge, 3 cm to the right of the part's
mass centre G. The pusher touches the outline's convex hull (dashed where it bridges the
L's notch, :func:`slidespin.body_outline`).

It moves straight up at 0.13 m/s: the edge lies flush against its face and the part is
carried without turning (``face_sticking``: Lynch and Mason's stable pushing, the resultant
of the line load staying on the shared segment and inside the friction cone). At t = 2 s the pusher turns a corner of its path, heading up and to the right
while turning by 30°: the part leaves the face for a few milliseconds, is caught by the
pusher's end, which slides along the bottom edge (``end_sliding_right``) and turns the part,
then one of the part's vertices slides on the pusher's face (``vertex_sliding_right``), and
the part leaves the pusher and slides to rest. The line pusher's modes (face, vertex, end
contact; sticking or sliding either way) switch exactly, as a finger's do.
"""

import math

import matplotlib.pyplot as plt

import slidespin as ss
from slidespin.viz.push_plot import plot_pushed_trajectory

L = ss.Polygon([(0, 0), (0.2, 0), (0.2, 0.06), (0.06, 0.06), (0.06, 0.16), (0, 0.16)])
part = ss.Body(L, ss.UniformPressure(), mass=1.0)
xi_g, eta_g = part.mass_centre  # G in the footprint's frame [m]; the part starts with G at 0
print(f"G at ({xi_g:.4f}, {eta_g:.4f}) m from the L's corner")

# rows (t [s], x [m], y [m], angle [rad]) of the pusher's centre and direction
pusher = ss.LinePusher(
    0.12,
    [
        (0.0, 0.03, -0.16, 0.0),
        (2.0, 0.03, 0.10, 0.0),  # straight up at 0.13 m/s, 3 cm right of G
        (3.5, 0.23, 0.25, math.radians(30.0)),  # the corner: up and right, turning
    ],
    mu=0.5,
)
tr = ss.simulate(part, ss.FrictionTensor.isotropic(0.3), ss.State(), pusher=pusher, t_end=4.0)
for mode, t0, t1 in tr.phases():
    print(f"{mode:20s} {t0:.4f} - {t1:.4f} s")
print(f"final pose x = {tr.x[-1]:.4f} m, y = {tr.y[-1]:.4f} m, phi = {tr.phi[-1]:.4f} rad")

# %%
# The part at eight instants, the pusher at the same instants (a segment), the contact
# points and the pusher's force; against time the force coloured by contact mode (the
# line pusher's face, vertex and end contacts in shades of the finger's colours).
fig = plot_pushed_trajectory(tr, title="line pusher and L-shaped part")
plt.show()

# %%
# The one number: when the pusher's face meets the part's bottom edge [s]. The edge is
# η_G = 0.056667 m below G; the pusher starts 0.16 m below G at 0.13 m/s:
# (0.16 − η_G) / 0.13 = 0.794871795 s.
print(f"face contact = {tr.switches[0][0]:.9f} s")
