"""
The limit surface of a disk
===========================

Every direction of sliding and spinning of a body gives one friction wrench (force and moment
about G); together they form the limit surface, the boundary of the set of wrenches friction
can supply (MODEL §11, :func:`slidespin.limit_surface`). For a uniform disk under isotropic
friction its extremes are closed forms: pure sliding gives the force μ m g, pure spinning the
moment (2/3) μ m g R.
"""

import matplotlib.pyplot as plt

import slidespin as ss

R, mu, m, g = 0.05, 0.3, 1.0, 9.81
body = ss.Body(ss.Circle(R), ss.UniformPressure(), mass=m)
ls = ss.limit_surface(body, ss.FrictionTensor.isotropic(mu), n=400, g=g)
s = ls.summary()
print(f"largest force {s['max_force']:.10f} N (mu m g = {mu * m * g:.10f})")
print(
    f"ellipsoid fit: radial error {s['ellipsoid_error']:.3e}; "
    f"convex quartic: {s['quartic_error']:.3e}"
)

# %%
# The sampled wrenches in 3-D (force components and the moment in units of the length ℓ).
ax = ls.plot()
plt.tight_layout()

# %%
# The top of the surface is pure spinning about G: its wrench, from
# :func:`slidespin.friction_wrench` at v = 0, is the largest moment friction can supply. The
# sampled directions come close to it (the largest sampled moment above) without hitting it.
top = ss.friction_wrench(body, ss.FrictionTensor.isotropic(mu), vx=0.0, vy=0.0, omega=1.0, g=g)
print(f"largest sampled moment = {s['max_moment']:.10f} N m")
print(f"closed form (2/3) mu m g R = {2.0 / 3.0 * mu * m * g * R:.10f} N m")

# %%
# The one number: the moment of pure spinning [N m] (it resists the spin: negative).
print(f"pure-spin moment = {top.moment:.12f} N m")
