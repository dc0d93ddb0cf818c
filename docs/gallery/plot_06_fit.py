"""
Fitting friction to tracked motion
==================================

``examples/fit_synthetic.csv`` holds five tracked runs of an elliptic plate (a = 0.1 m,
e = 0.866, 1 kg), 200 instants each at 330 frames per second. The data are **synthetic**:
``examples/fit_synthetic.py`` simulated them with the tensor fx = 0.42, fy = 0.54, f = 0.03 and
added 0.5 mm and 0.01 rad of noise. :func:`slidespin.fit` recovers the tensor with standard
errors, from the start guess fx = fy = 0.3, f = 0 (the full story: :doc:`/fit`).
"""

from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

import slidespin as ss

# the repository's examples/ folder (this script lives in docs/gallery/)
EXAMPLES = Path(ss.__file__).resolve().parents[2] / "examples"
runs = ss.read_runs(EXAMPLES / "fit_synthetic.csv")
body = ss.Body(ss.Ellipse.from_eccentricity(0.1, 0.866), ss.UniformPressure(), mass=1.0)
res = ss.fit(runs, body, ss.FrictionTensor(0.3, 0.3), free=("fx", "fy", "f"))
print(res)

# %%
# Data and fitted model of the first run.
run = runs[0]
t = np.linspace(run["t"][0], run["t"][-1], 400)
model = res.predict(0, t)
fig, ax = plt.subplots(figsize=(6.4, 3.8))
ax.plot(run["x"], run["y"], ".", ms=2, color="0.5", label="tracked G (synthetic)")
ax.plot(model["x"], model["y"], "C0-", label="fitted model")
ax.set_aspect("equal")
ax.set_xlabel("x [m]")
ax.set_ylabel("y [m]")
ax.legend()

# %%
# The one number: the fitted fx (truth 0.42), with its standard error.
print(f"fx = {res.estimates['fx']:.6f} +- {res.std_errors['fx']:.6f}")
