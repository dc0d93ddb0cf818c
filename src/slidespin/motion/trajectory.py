"""The result of a free run: :class:`Trajectory` (MODEL §4–5), made by
:func:`slidespin.motion.simulate.simulate`.

The rows are the integrator's steps from the initial state to the stop, in SI units, with the
paper's quantities (v, ϑ, β = v/ω, F_τ, F_n, M); the last row is the stop and holds the
terminal limits (β*, ϑ*). Its figure is drawn by :mod:`slidespin.viz.trajectory_plot`, loaded
by name on first use (the plotting layer sits above this one).
"""

from __future__ import annotations

import csv
import importlib
import inspect
import io
import json
import math
from dataclasses import dataclass, field
from os import PathLike
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from slidespin import _validate as v
from slidespin.contact.body import Body
from slidespin.contact.friction import FrictionTensor
from slidespin.motion._report import _html_table
from slidespin.motion.outcomes import status_message
from slidespin.motion.sensitivity import Sensitivities
from slidespin.motion.state import State

if TYPE_CHECKING:
    import pandas as pd  # type: ignore[import-untyped]  # pandas ships no type information

__all__ = ["Trajectory"]


@dataclass(frozen=True)
class Trajectory:
    """Motion of the body from its initial state to the stop (SI units throughout).

    Attributes
    ----------
    t, x, y, phi, vx, vy, omega : ndarray
        Time [s], mass-centre position [m], body angle [rad], velocity of G [m/s] and spin
        [rad/s] at the integrator's steps, ending with the stop itself.
    speed, theta, beta : ndarray
        v = |v_G| [m/s], its direction ϑ [rad] and β = v/ω [m] (signed like ω; ±inf where
        ω = 0). The last row is the stop, where v = ω = 0: it holds the limits along the
        motion, ``speed[-1] == 0``, ``theta[-1] == theta_stop`` and ``beta[-1] ==
        beta_stop`` (so a pure-spinning stop keeps the direction its vanishing velocity
        converged to, instead of the 0 that atan2(0, 0) would give). Where no limiting
        direction exists (ϑ* is NaN: a pure-spinning stop whose vanishing velocity keeps
        turning, a ``spiral``, a body at rest) ``theta[-1]`` is NaN too, and at rest
        ``beta`` is NaN.
    tangential, normal, moment_paper : ndarray
        The paper's F_τ, F_n [N] and M_Cζ [N m] (eq. 4) along the motion; at the stop, the
        friction wrench of the terminal direction with F_τ, F_n its components along and
        across ϑ*. Where ϑ* does not exist they stay finite: 0 for a pure-spinning stop
        (the net force vanishes at a pure-spinning fixed point, so its components tend to 0
        whatever the direction does), and for a ``spiral`` the components along the last
        direction reached (they need not converge).
    path_length : ndarray
        Distance travelled by G [m].
    t_stop : float
        Stop time [s].
    stop_state : State
        Position and angle at the stop (velocities zero).
    beta_stop, theta_stop : float
        Terminal ratio β* = lim v/ω [m] and terminal direction ϑ* [rad] of the velocity of G
        (MODEL §5, §9), taken from the fixed point of the flow of the direction of motion
        that the trajectory approaches, not from its last step: +inf for a pure-sliding
        ending, 0 for a pure-spinning one. ϑ* is NaN where no limiting direction exists: a
        pure-spinning ending whose vanishing velocity keeps turning, a ``spiral`` ending, a
        body at rest. β* is NaN at rest and for a spiral with spin.
    ending : str
        ``mixed``, ``pure_sliding`` (ω/v → 0), ``pure_spinning`` (v/ω → 0), ``at_rest``, or
        ``spiral``: the body stops (t_stop, position and angle are converged) while the
        direction of its motion keeps turning, so there is no terminal direction; ϑ* is then
        NaN, and β* too unless the spin has died out first (β* = inf). This happens e.g. in
        pure sliding under a skew tensor with |f| > |μ|/2, where 𝔽 has no real eigenvector,
        and on limit cycles of the direction of motion.
    status : str
        How far the reported stop can be trusted (:mod:`slidespin.motion.outcomes`): ``stopped``
        (converged; independent of ``rtol`` and ``max_step``), ``marginal`` (an algebraic
        approach at a boundary between endings: β*, ϑ* are the analytic limit), ``saddle``
        (round-off chooses the exit from a saddle: the values are the saddle's, valid down
        to ``saddle_energy``), ``max_steps``, ``step_too_small``, ``non_finite`` (values as
        reached, not converged) or ``at_rest``.
    saddle_energy : float
        For ``status == "saddle"``: the fraction of the initial kinetic energy down to which
        the motion was observed to approach the saddle's ending; NaN otherwise.
    eigenvalue_ratio : float
        Largest real part of the eigenvalues of the direction flow at the terminal fixed point
        divided by its decay rate |u·A| (negative: attracting; near 0: marginal); NaN where no
        fixed point was reached.
    n_steps, n_rhs : int
        Integrator steps and right-hand-side evaluations.
    sensitivities : Sensitivities or None
        With ``simulate(..., sensitivities=...)``: the derivatives of the path and of the
        stop with respect to those parameters
        (:class:`slidespin.motion.sensitivity.Sensitivities`); ``None`` otherwise.
    """

    t: NDArray[np.float64]
    x: NDArray[np.float64]
    y: NDArray[np.float64]
    phi: NDArray[np.float64]
    vx: NDArray[np.float64]
    vy: NDArray[np.float64]
    omega: NDArray[np.float64]
    speed: NDArray[np.float64]
    theta: NDArray[np.float64]
    beta: NDArray[np.float64]
    tangential: NDArray[np.float64]
    normal: NDArray[np.float64]
    moment_paper: NDArray[np.float64]
    path_length: NDArray[np.float64]
    t_stop: float
    stop_state: State
    beta_stop: float
    theta_stop: float
    ending: str
    status: str
    n_steps: int
    n_rhs: int
    body: Body = field(repr=False)
    friction: FrictionTensor = field(repr=False)
    initial_state: State = field(repr=False)
    g: float = 9.81
    saddle_energy: float = math.nan
    eigenvalue_ratio: float = math.nan
    sensitivities: Sensitivities | None = field(default=None, repr=False)

    def __repr__(self) -> str:
        return (
            f"Trajectory(status={self.status!r}, ending={self.ending!r}, "
            f"t_stop={self.t_stop:.6g} s, distance={self.distance:.6g} m, "
            f"beta_stop={self.beta_stop:.6g} m, theta_stop={self.theta_stop:.6g} rad, "
            f"n_steps={self.n_steps}, n_points={self.t.size})"
        )

    @property
    def status_message(self) -> str:
        """One-line explanation of ``status``."""
        return status_message(self.status)

    @property
    def distance(self) -> float:
        """Distance travelled by G until the stop [m]."""
        return float(self.path_length[-1])

    @property
    def beta_stop_ratio(self) -> float:
        """β*/ℓ, the terminal ratio in units of the semi-axis a (as in the paper's tables), or
        of the extent of a footprint (:attr:`slidespin.Body.length_unit`)."""
        return self.beta_stop / self.body.length_unit

    def summary(self) -> dict[str, Any]:
        """The stop results as a JSON-ready dict (SI units).

        Non-finite values are ``None`` (JSON ``null``), always for a reason that ``ending``
        gives: β* = ∞ for ``pure_sliding``, β* and ϑ* undefined for ``spiral`` and
        ``at_rest``. Numbers stay numbers, so scripts need not parse strings. With
        sensitivities, ``stop_sensitivities`` holds the stop's derivatives
        (:meth:`slidespin.motion.sensitivity.Sensitivities.to_dict`).
        """

        def num(x):
            x = float(x)
            return x if math.isfinite(x) else None

        s = self.stop_state
        return {
            "t_stop": num(self.t_stop),
            "x_stop": num(s.x),
            "y_stop": num(s.y),
            "phi_stop": num(s.phi),
            "distance": num(self.distance),
            "beta_stop": num(self.beta_stop),
            "beta_stop_over_a": num(self.beta_stop_ratio),
            "theta_stop": num(self.theta_stop),
            "ending": self.ending,
            "status": self.status,
            "status_message": self.status_message,
            "saddle_energy": num(self.saddle_energy),
            "eigenvalue_ratio": num(self.eigenvalue_ratio),
            "n_steps": int(self.n_steps),
            **(
                {"stop_sensitivities": self.sensitivities.to_dict()}
                if self.sensitivities is not None
                else {}
            ),
        }

    def to_json(self, path: str | PathLike[str] | None = None) -> str:
        """Write (or return) the stop summary as JSON."""
        text = json.dumps(self.summary(), indent=2)
        if path is not None:
            with open(path, "w", encoding="utf-8") as fh:
                fh.write(text + "\n")
        return text

    COLUMNS = (
        "t",
        "x",
        "y",
        "phi",
        "vx",
        "vy",
        "omega",
        "speed",
        "theta",
        "beta",
        "tangential",
        "normal",
        "moment_paper",
        "path_length",
    )

    def to_pandas(self) -> pd.DataFrame:
        """The trajectory as a :class:`pandas.DataFrame`, one row per recorded step, the
        columns of :meth:`to_csv` (SI units), and with sensitivities the columns
        ``d_<q>/d_<parameter>`` (∂q/∂θ at fixed t); the stop summary (with the stop's
        derivatives) is in ``DataFrame.attrs``.
        Needs pandas (``pip install pandas``)."""
        try:
            # lazy: pandas is optional and slow to import
            import pandas as pd  # type: ignore[import-untyped]
        except ImportError:  # pragma: no cover - depends on the environment
            raise ImportError("Trajectory.to_pandas needs pandas: pip install pandas") from None
        cols = {c: np.asarray(getattr(self, c), dtype=float) for c in self.COLUMNS}
        if self.sensitivities is not None:  # ∂q/∂θ along the path: columns d_q/d_θ
            cols.update(self.sensitivities.columns())
        df = pd.DataFrame(cols)
        df.attrs.update(self.summary())
        return df

    def _repr_html_(self) -> str:
        """A short summary table for notebooks (no arrays)."""
        return _html_table("Trajectory", self.summary())

    def plot(self, **kwargs: Any) -> Any:
        """Four-panel figure of the run: the path of G with the patch drawn along it, β(t) and
        ϑ(t) with their terminal values β*, ϑ*, the speed v(t) and the spin ω(t).

        The accessor pattern of pandas' ``DataFrame.plot``: the plotting layer
        (:mod:`slidespin.viz.trajectory_plot`, and matplotlib) is loaded by name on first
        use, so that the motion layer does not import it (the layer contract in
        ``pyproject.toml``) and ``import slidespin`` stays light. Needs matplotlib.

        Parameters
        ----------
        **kwargs
            Passed to :func:`slidespin.viz.trajectory_plot.plot_trajectory`: ``title`` (str
            or None, the figure title) and ``n_outlines`` (int in [0, 1000], default 9, the
            number of patch outlines drawn along the path). Any other keyword is refused
            with a ``TypeError`` naming the valid ones.

        Returns
        -------
        matplotlib.figure.Figure
            The figure (draw it with ``fig.savefig(path)``, or ``plt.show()`` when pyplot is
            in use).

        Examples
        --------
        >>> fig = tr.plot(title="disk")  # doctest: +SKIP
        >>> fig.savefig("disk.png")  # doctest: +SKIP
        """
        module = importlib.import_module("slidespin.viz.trajectory_plot")
        draw = module.plot_trajectory
        valid = [p for p in inspect.signature(draw).parameters if p != "traj"]
        unknown = sorted(set(kwargs) - set(valid))
        if unknown:
            raise TypeError(
                f"Trajectory.plot() got the keyword {unknown[0]!r}; valid keywords: "
                + ", ".join(valid)
            )
        title = kwargs.get("title")
        if title is not None and not isinstance(title, str):
            raise TypeError(f"title = {v._short(title)} is invalid; valid values: a str or None")
        if "n_outlines" in kwargs:
            n = kwargs["n_outlines"]
            if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or not 0 <= n <= 1000:
                raise ValueError(
                    f"n_outlines = {v._short(n)} is invalid; valid range: integer in [0, 1000]"
                )
            kwargs["n_outlines"] = int(n)
        return draw(self, **kwargs)

    def to_csv(self, path: str | PathLike[str] | None = None) -> str:
        """Write (or return) the trajectory as CSV, one row per step (SI units)."""
        buf = io.StringIO()
        w = csv.writer(buf, lineterminator="\n")
        w.writerow(self.COLUMNS)
        cols = [getattr(self, c) for c in self.COLUMNS]
        for row in zip(*cols):
            w.writerow([repr(float(x)) for x in row])
        text = buf.getvalue()
        if path is not None:
            with open(path, "w", encoding="utf-8", newline="") as fh:
                fh.write(text)
        return text
