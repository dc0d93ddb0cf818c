"""Settings and helpers shared by the reproductions (not public API).

The paper's runs (§3, MODEL §6): an elliptic plate with e = 0.866, I* = (1 + κ²)/4, plane-fixed
orthotropic friction (f = 0), v₀ = ω₀ = 1 and ϑ₀ = π/4 in the paper's units (eq. 7):
v = v₁√(ag/π), ω = ω₁√(g/(aπ)), t = t₁√(aπ/g) (erratum 2). The reproductions use a = 1 m,
m = 1 kg and g = 9.81 m/s² and convert to the paper's units for display.
"""

from __future__ import annotations

import math
import os
from contextlib import contextmanager

from slidespin.contact.body import Body
from slidespin.contact.ellipse import Ellipse
from slidespin.contact.pressure import LinearPressure, UniformPressure

ECCENTRICITY = 0.866
A = 1.0  # semi-axis a [m]
MASS = 1.0  # [kg]
G = 9.81  # [m/s²]
#: where figures and ``all`` go without --out (the same folder as every slidespin command)
DEFAULT_OUT = "slidespin-out"
PHI0 = (math.pi / 4, math.pi / 3, math.pi / 2)
PHI_LABELS = ("π/4", "π/3", "π/2")
THETA0 = math.pi / 4
LINEAR_CENTROID = (0.1, 0.1)  # ξc, ηc in units of a (paper §3.2)

# paper units (eq. 7, with erratum 2)
SPEED_UNIT = math.sqrt(A * G / math.pi)  # [m/s]
SPIN_UNIT = math.sqrt(G / (A * math.pi))  # [rad/s]
TIME_UNIT = math.sqrt(A * math.pi / G)  # [s]


def patch() -> Ellipse:
    """The paper's ellipse, a = 1 m, e = 0.866 (κ = 0.50004)."""
    return Ellipse.from_eccentricity(A, ECCENTRICITY)


def uniform_body() -> Body:
    """Uniform pressure (§2.1), I* = (1 + κ²)/4 (eq. 7)."""
    return Body(patch(), UniformPressure(), MASS)


def linear_body() -> Body:
    """Linear pressure (eq. 10) with centroid ξc = ηc = 0.1a, I* = (1 + κ²)/4 about G."""
    p = patch()
    xi_c, eta_c = LINEAR_CENTROID
    return Body(p, LinearPressure(xi_c * p.a, eta_c * p.a), MASS)


def num(x):
    """JSON-ready float (``inf``/``nan`` as strings)."""
    x = float(x)
    if math.isnan(x):
        return "nan"
    return x if math.isfinite(x) else ("inf" if x > 0 else "-inf")


def prepare_out(out) -> str:
    """Create the output directory ``out`` if needed; ``ValueError`` if it cannot be used."""
    path = os.fspath(out)
    if os.path.exists(path) and not os.path.isdir(path):
        raise ValueError(f"--out = {path!r} is a file; valid values: a directory")
    parent = os.path.dirname(os.path.abspath(path))
    if not os.path.isdir(path):
        if not os.path.isdir(parent):
            raise ValueError(f"--out = {path!r}: the parent directory {parent!r} does not exist")
        os.makedirs(path, exist_ok=True)
    if not os.access(path, os.W_OK):
        raise ValueError(f"--out = {path!r} is not writable")
    return path


_RC = {
    "font.size": 9.0,
    "axes.titlesize": 9.5,
    "axes.labelsize": 9.0,
    "legend.fontsize": 8.0,
    "xtick.labelsize": 8.0,
    "ytick.labelsize": 8.0,
    "axes.spines.top": False,
    "axes.spines.right": False,
    "axes.grid": True,
    "grid.alpha": 0.25,
    "grid.linewidth": 0.6,
    "lines.linewidth": 1.5,
    "legend.frameon": False,
    "savefig.dpi": 150,
    "savefig.bbox": "tight",
    "figure.dpi": 100,
}


@contextmanager
def style():
    """Matplotlib style of the reproductions (imported lazily)."""
    import matplotlib

    with matplotlib.rc_context(_RC):
        yield


def emit_table(name: str, res, out, as_json: bool, stream, plot=None, fmt: str = "png"):
    """Print a table result (text, or JSON with ``as_json``) and, if ``out`` is given, write
    ``<name>.json``, ``<name>.txt`` and, with ``plot``, the figure ``<name>.<fmt>``.

    ``res`` needs ``as_dict()`` and ``to_text()``; ``out`` must have been prepared already.
    """
    import json
    import sys

    stream = stream or sys.stdout
    text = res.to_text()
    print(json.dumps(res.as_dict(), indent=2) if as_json else text, file=stream)
    if out is not None:
        with open(os.path.join(out, f"{name}.json"), "w", encoding="utf-8") as fh:
            json.dump(res.as_dict(), fh, indent=2)
        with open(os.path.join(out, f"{name}.txt"), "w", encoding="utf-8") as fh:
            fh.write(text + "\n")
        if plot is not None:
            save(plot(res), out, name, fmt)
    return res


def new_figure(width: float, height: float):
    """A matplotlib Figure with an Agg canvas, made without pyplot (no global state)."""
    # lazy: matplotlib is slow to import and needed only to draw
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(width, height), layout="constrained")
    FigureCanvasAgg(fig)
    return fig


def save(fig, out, name: str, fmt: str = "png") -> str:
    """Write ``fig`` to ``out/name.fmt`` and return the path."""
    if fmt not in FORMATS:
        raise ValueError(f"format = {fmt!r} is invalid; valid values: {', '.join(FORMATS)}")
    path = os.path.join(prepare_out(out), f"{name}.{fmt}")
    fig.savefig(path, dpi=150, bbox_inches="tight", metadata=_metadata(fmt))
    return path


def _metadata(fmt: str) -> dict:
    # reproducible files: no creation date in PNG/PDF/SVG metadata
    if fmt == "png":
        return {"Software": None}
    if fmt == "pdf":
        return {"CreationDate": None, "Creator": None, "Producer": None}
    if fmt == "svg":
        return {"Date": None, "Creator": None}
    return {}


FORMATS = ("png", "pdf", "svg")
PHI_COLORS = ("C0", "C1", "C2")
