"""The curve of a speed-dependent friction law (MODEL §14).

:func:`plot_speed_law` draws the factor g(|w|) that multiplies the friction tensor at the
local slip speed |w| (:mod:`slidespin.contact.speed_laws`), with the static ratio μs/μk at
rest, on a logarithmic speed axis.
"""

from __future__ import annotations

import numpy as np

from slidespin import _validate as v
from slidespin.contact.friction import FrictionTensor
from slidespin.contact.speed_laws import PowerLaw, SpeedTable, Stribeck

__all__ = ["plot_speed_law"]


def plot_speed_law(law, speeds=None, ax=None, *, label: str | None = None):
    """Plot a speed law's factor g(|w|) against the slip speed.

    Parameters
    ----------
    law : PowerLaw, Stribeck, SpeedTable or FrictionTensor
        The law, or a friction tensor with one (then its static ratio is marked at the left
        edge as "static": the factor of a body at rest).
    speeds : array_like or None
        Slip speeds [m/s], > 0 and finite (a logarithmic axis). Default: 400 speeds from
        1e-4 to 10 m/s, widened to two decades around a Stribeck law's vs and a table's
        speeds.
    ax : matplotlib Axes or None
        Where to draw (default: a new figure).
    label : str or None
        The curve's legend label (default: the law's repr).

    Returns
    -------
    matplotlib.axes.Axes

    Examples
    --------
    >>> import slidespin as ss
    >>> ax = plot_speed_law(ss.Stribeck(1.5, 0.01))
    >>> ax.get_xscale()
    'log'
    """
    import matplotlib.pyplot as plt  # lazy: matplotlib is imported only to draw

    static = None
    if isinstance(law, FrictionTensor):
        if law.speed_law is None:
            raise ValueError(
                f"law = {v._short(law)} has no speed law; valid values: a PowerLaw, Stribeck "
                "or SpeedTable, or a FrictionTensor with speed_law="
            )
        static = law.static
        law = law.speed_law
    if not isinstance(law, (PowerLaw, Stribeck, SpeedTable)):
        raise ValueError(
            f"law = {v._short(law)} is invalid; valid values: a PowerLaw, Stribeck or "
            "SpeedTable, or a FrictionTensor with one"
        )
    if speeds is None:
        lo, hi = 1e-4, 10.0
        marks = np.asarray(law.break_speeds(), dtype=float)
        if isinstance(law, Stribeck):
            marks = np.append(marks, law.vs)
        marks = marks[marks > 0.0]
        if marks.size:
            lo, hi = min(lo, marks.min() / 100.0), max(hi, marks.max() * 100.0)
        speeds = np.geomspace(lo, hi, 400)
    else:
        speeds = v.real_array("speeds", speeds).ravel()
        if speeds.size < 2 or not np.all(speeds > 0.0):
            raise ValueError(
                f"speeds = {v._short(speeds)} is invalid; valid values: at least two finite "
                "speeds > 0 [m/s] (a logarithmic axis)"
            )
        speeds = np.sort(speeds)
    if ax is None:
        _, ax = plt.subplots(figsize=(5.6, 3.6))
    ax.plot(speeds, law.factor(speeds), label=label or repr(law))
    if static is not None:
        ax.plot([speeds[0]], [static], "k<", ms=7, label=f"static = {static:g} (at rest)")
    ax.set_xscale("log")
    ax.set_xlabel("slip speed |w| [m/s]")
    ax.set_ylabel("factor g(|w|) of the tensor")
    ax.grid(alpha=0.25, which="both")
    ax.legend(fontsize=8)
    return ax
