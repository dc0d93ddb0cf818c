"""
The paper's Figure 2 and Table 2
================================

:mod:`slidespin.paper` reproduces every table and figure of the paper (``slidespin reproduce
all``; :doc:`/paper`). Figure 2: the elliptic plate (e = 0.866, uniform pressure) thrown with
v₀ = ω₀ = 1 (paper units) at ϑ₀ = π/4 from three body angles φ₀; β(t) = v/ω and ϑ(t) converge
on the terminal motion, which for the ellipse does not have ϑ* = 0.
"""

import io

import matplotlib.pyplot as plt

import slidespin as ss

res = ss.paper.fig2.compute()
print(res.to_text())

# %%
# ``fig2.plot`` draws the figure as ``slidespin reproduce fig2`` writes it (a figure outside
# pyplot, so that the library never opens windows); here it is shown as an image.
buf = io.BytesIO()
ss.paper.fig2.plot(res).savefig(buf, format="png", dpi=100)
buf.seek(0)
fig, ax = plt.subplots(figsize=(7.6, 6.4))
ax.imshow(plt.imread(buf))
ax.set_axis_off()
fig.tight_layout()

# %%
# Table 2: the inertia boundaries I₁ < I₂ < I₃ of a circular patch, computed numerically from
# the friction wrench (:func:`slidespin.inertia_intervals`) and from the formulas printed in
# the paper (:func:`slidespin.paper_inertia_intervals`, with the misplaced parenthesis of the
# uniform row restored), for fx = 0.3, μ = 0.15.
friction = ss.FrictionTensor(0.3, 0.45)
worst = 0.0
for law in (ss.UniformPressure(), ss.BoussinesqPressure(), ss.HertzPressure()):
    num = ss.inertia_intervals(law, friction)
    printed = ss.paper_inertia_intervals(law, friction)
    print(
        f"{type(law).__name__:20s} numeric {tuple(round(x, 10) for x in num)}  "
        f"printed {tuple(round(x, 10) for x in printed)}"
    )
    worst = max(worst, max(abs(x - y) for x, y in zip(num, printed)))

# %%
# The one number: the largest difference between the numeric and the printed boundaries.
print(f"largest Table 2 difference = {worst:.3e}")
