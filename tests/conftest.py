"""Shared fixtures: bodies and tensors used across the test modules.

The tests mirror the package's layers (``contact/``, ``motion/``, ``analysis/``, ``studies/``,
``viz/``, ``cli/``, ``paper/``; ``api/`` checks the whole public surface, ``docs/`` the site
and the gallery). The slow independent references they compare against live apart in
``references/`` (written from MODEL.md, importing nothing of slidespin's kernels) and are put
on the import path here, as ``reference`` and ``footprint_reference`` (and every test folder
after them, for the few helpers shared across folders).
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest

import slidespin as ss

sys.path.insert(0, str(Path(__file__).resolve().parent / "references"))
# a few test modules share helpers with a module of another layer's folder (e.g. the sweep
# plot's tests use the sweep tests' fake engine): every folder is importable, so that any
# one test file also runs alone (test basenames are unique across tests/)
for _folder in sorted(Path(__file__).resolve().parent.iterdir()):
    if _folder.is_dir() and not _folder.name.startswith((".", "_")):
        sys.path.append(str(_folder))

LAWS = ("uniform", "linear", "boussinesq", "hertz")


def make_law(name: str, a: float = 1.0, b: float = 0.5):
    """The four pressure laws; the linear one with an off-centre centroid inside the core."""
    if name == "linear":
        return ss.LinearPressure(0.12 * a, -0.08 * b)
    return {
        "uniform": ss.UniformPressure(),
        "boussinesq": ss.BoussinesqPressure(),
        "hertz": ss.HertzPressure(),
    }[name]


def state_with_icr(body, cx, cy, phi, omega=1.0):
    """World velocity (vx, vy) of G whose instantaneous centre of rotation is at body-frame
    point (cx, cy) [m] (measured from the patch centre C) when the body angle is phi."""
    xg, yg = body.mass_centre
    vbx = (cy - yg) * omega
    vby = -(cx - xg) * omega
    c, s = math.cos(phi), math.sin(phi)
    return c * vbx - s * vby, s * vbx + c * vby


@pytest.fixture
def rng():
    return np.random.default_rng(20261122)
