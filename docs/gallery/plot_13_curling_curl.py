"""
Does a speed law or a tall stone make a curling stone curl?
===========================================================

A curling stone released with a slow counter-clockwise turn curls about a metre to the
*left* of its line over a 28 m throw, after one to three turns (Penner 2001; Nyberg et al.
2013; Shegelski & Lozowski 2018). :doc:`plot_09_curling_stone` showed that Coulomb friction on
the symmetric running band gives no curl at all. Two ingredients the literature has proposed
are in slidespin (MODEL §14): friction that falls with the sliding speed as v^(−1/2), and the
forward shift of the pressure of a *tall* stone decelerated by friction acting at the ice
(its mass centre is about h = 0.06 m up: r_p = r_G − h F/P). We run them on the stone of
``examples/curling_stone.toml`` and state what the model gives.

**The finding, plainly:** neither reproduces the curl. The v^(−1/2) law alone gives *no* curl
(zero by symmetry: the front and the back of the band slide equally fast, so the law scales
their mirrored lateral forces equally); it only changes how the spin and the speed die out.
The tall stone's load shift presses the front harder, and the front's friction, which points
against the band's spin there, pushes the stone to the *right*: 3.5 mm over the throw (below),
the wrong way and nearly three hundred times too small. A front–back asymmetry of the load
alone turns a rotating cylinder the way a curling stone does not; the literature's proposed
resolutions (a front–back asymmetry of the ice's friction itself, from melt water or from the
pebbles' scratches) are not in the model. (The v^(−1/2) law and the tall stone together are not
run here: under a power law the friction, and so the load shift h F/P, grows without bound as
the stone stops, so the band would lift off and the stone tip; slidespin refuses that pair.)
"""

import math

import matplotlib.pyplot as plt

import slidespin as ss

m, inertia, g = 19.96, 0.2113, 9.81
band = ss.Annulus(0.0595, 0.0655)  # the running band: 6 mm wide, mean radius 62.5 mm
mu, v0, w0 = 0.0068, 1.93, 0.7  # released down the sheet (+y), turning counter-clockwise
start = ss.State.from_speed(v0, w0, theta=math.pi / 2)

runs = {
    "Coulomb μ = 0.0068": (ss.FrictionTensor(mu, mu), 0.0),
    "μ (v / 1 m/s)^(−1/2)": (ss.FrictionTensor(mu, mu, speed_law=ss.PowerLaw(0.5, 1.0)), 0.0),
    "Coulomb, tall stone h = 0.06 m": (ss.FrictionTensor(mu, mu), 0.06),
}
paths = {}
for name, (friction, height) in runs.items():
    stone = ss.Body(band, ss.UniformPressure(), mass=m, moment_of_inertia=inertia, height=height)
    tr = ss.simulate(stone, friction, start)
    paths[name] = tr
    print(
        f"{name:32s} status {tr.status:7s}  stops after {tr.t[-1]:6.2f} s at "
        f"{tr.y[-1]:6.2f} m down the sheet, {1000 * tr.x[-1]:+8.3f} mm across "
        f"(+: to the right), {tr.phi[-1] / (2 * math.pi):4.2f} turns"
    )

# %%
# The path across the sheet
# -------------------------
# The lateral offset x against the distance y down the sheet, in millimetres (a real stone
# ends about 1000 mm to the left, off the scale of this plot).
fig, ax = plt.subplots(figsize=(6.4, 3.8))
for name, tr in paths.items():
    ax.plot(tr.y, 1000 * tr.x, label=name)
ax.axhline(0.0, color="0.6", lw=0.8)
ax.set_xlabel("distance down the sheet y [m]")
ax.set_ylabel("offset across x [mm] (+: right)")
ax.set_title("counter-clockwise stone: observed curl ≈ −1000 mm (left)", fontsize=10)
ax.legend(fontsize=8)
fig.tight_layout()

# %%
# Where the pressure sits
# -----------------------
# The tall stone decelerating at μ g presses ahead of its centre by h μ = 0.41 mm: the front
# of the band carries a little more than the back (:func:`slidespin.pressure_centre`).
tall = ss.Body(band, ss.UniformPressure(), mass=m, moment_of_inertia=inertia, height=0.06)
xi, eta = ss.pressure_centre(tall, ss.FrictionTensor(mu, mu), start)
print(f"pressure shift = {1000 * math.hypot(xi, eta):.12f} mm ahead of the centre")

# %%
# The three offsets at the stop, for the record (+: to the right of the line)
print(f"coulomb curl = {1000 * paths['Coulomb μ = 0.0068'].x[-1]:.6e} mm")
print(f"law curl = {1000 * paths['μ (v / 1 m/s)^(−1/2)'].x[-1]:.6e} mm")
print(f"tall curl = {1000 * paths['Coulomb, tall stone h = 0.06 m'].x[-1]:.6f} mm")
