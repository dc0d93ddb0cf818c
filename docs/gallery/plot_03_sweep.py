"""
A sweep: how a disk stops, against anisotropy and inertia
=========================================================

The paper's Table 2 says how a circular patch stops under orthotropic friction: along the
inertia axis I* = I/(m a²) the ending changes at I₁ < I₃ from pure sliding (the spin dies
first) to mixed (v and ω vanish together) to pure spinning (the sliding dies first). We run a
small grid of a few hundred cases through the compiled batch engine,
:func:`slidespin.simulate_cases` (what ``slidespin sweep`` runs chunk by chunk, locally or on
Dask), and lay the paper's printed boundaries over the endings found.
"""

import matplotlib.pyplot as plt
import numpy as np

import slidespin as ss

a, mass, fx = 0.05, 1.0, 0.3
mu = np.linspace(0.0, 0.2, 12)  # anisotropy fy - fx
i_star = np.linspace(0.12, 0.98, 22)  # I / (m a^2)
MU, IS = np.meshgrid(mu, i_star, indexing="ij")
cases = {
    "a": a,
    "b": a,
    "law": "uniform",
    "fx": fx,
    "fy": fx + MU.ravel(),
    "mass": mass,
    "moment_of_inertia": IS.ravel() * mass * a * a,
    "vx": 0.6,
    "vy": 0.6,
    "omega": 20.0,  # thrown at 45 deg between the principal axes
}
res = ss.simulate_cases(cases)
print(res)

# %%
# The endings on the grid, with the boundaries I₁(μ), I₃(μ) of the formulas printed in the
# paper (:func:`slidespin.paper_inertia_intervals`).
code = {"pure_sliding": 0, "mixed": 1, "pure_spinning": 2}
ending = np.array([code[e] for e in res.ending]).reshape(MU.shape)
fig, ax = plt.subplots(figsize=(6.4, 4.2))
ax.pcolormesh(mu, i_star, ending.T, cmap="viridis", shading="nearest")
printed = [
    ss.paper_inertia_intervals(ss.UniformPressure(), ss.FrictionTensor(fx, fx + m)) for m in mu
]
ax.plot(mu, [p.i1 for p in printed], "w-", lw=2, label="I₁ (printed)")
ax.plot(mu, [p.i3 for p in printed], "w--", lw=2, label="I₃ (printed)")
ax.set_xlabel("μ = fy − fx")
ax.set_ylabel("I* = I/(m a²)")
ax.set_title("ending: pure sliding (dark), mixed, pure spinning (light)", fontsize=10)
ax.legend(loc="lower right")

# %%
# The one number: how many of the cases end in a mixed motion (the rest end in pure sliding
# or pure spinning). ``tests/docs/test_gallery.py`` counts the grid points between the printed
# boundaries and expects the same number.
print(f"mixed endings = {int(np.sum(ending == 1))} of {res.t_stop.size}")
