"""
A finger pushing a box around a corner: sticking, sliding, separation
=====================================================================

A finger (a point pusher, :class:`slidespin.PointPusher`) prescribes a **motion**, and the
contact decides the force (MODEL §13). Here a finger with Coulomb coefficient μp = 0.3
against a box (base 20 cm × 15 cm, 2 kg, uniform pressure, μ = 0.35 on the table) comes
from the left at 0.2 m/s, 3 cm below the box's centre line, and turns a corner of its path
at t = 2 s towards the upper right (``examples/finger_box.toml``; run it with
``slidespin simulate examples/finger_box.toml --plot finger.png``).

The finger reaches the box's left face at t = 0.5 s with a plastic impact and **sticks**:
below G, it turns the box while carrying it. As the box turns, the force leaves the friction
cone and the finger **slides** along the face; after the corner of the path it slides the
other way, sticks again, slides, and, when its path ends at t = 3 s, the box **separates**
from it and slides to rest. Every switch is an event located to ~1e-12 s, and the energy
balance (pusher work = kinetic energy change + plane friction + contact slip + impact losses)
closes to round-off.
"""

from pathlib import Path

import matplotlib.pyplot as plt

import slidespin as ss
from slidespin.viz.push_plot import plot_pushed_trajectory

# the repository's examples/ folder (this script lives in docs/gallery/)
EXAMPLES = Path(ss.__file__).resolve().parents[2] / "examples"
case = ss.load_case(EXAMPLES / "finger_box.toml")
tr = ss.simulate(case.body, case.friction, case.initial_state, pusher=case.pusher, t_end=case.t_end)
for mode, t0, t1 in tr.phases():
    print(f"{mode:14s} {t0:.4f} - {t1:.4f} s")
print(
    f"pusher work {tr.pusher_work[-1]:.4f} J, relative energy error {tr.relative_energy_error:.1e}"
)

# %%
# The body at eight instants (light to dark), the finger's path and the finger at the same
# instants, the contact points with the finger's force, and against time the force coloured
# by contact mode and the energy balance, the modes shaded.
fig = plot_pushed_trajectory(tr, title=case.name)
plt.show()

# %%
# The one number: when the finger first touches the box [s]. It starts 0.1 m from the
# box's left face and moves at 0.2 m/s: 0.5 s.
print(f"first contact = {tr.switches[0][0]:.9f} s")
