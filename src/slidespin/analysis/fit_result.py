"""The outcome of a fit, :class:`FitResult` (MODEL §12).

Estimates with standard errors, covariance and correlation, the identifiability verdict,
each run's fitted start and motion, and the goodness of fit; shown as text
(:meth:`FitResult.table`), in notebooks (an HTML table), as JSON (:meth:`FitResult.summary`)
or as a :class:`pandas.DataFrame` (:meth:`FitResult.to_pandas`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from html import escape

import numpy as np

from slidespin import _validate as v
from slidespin.analysis.fit_data import _UNITS, START, trajectory_at
from slidespin.contact.body import Body
from slidespin.contact.friction import FrictionTensor

__all__ = ["FitResult"]


def _num(x):
    x = float(x)
    return x if math.isfinite(x) else None


@dataclass(frozen=True, slots=True, repr=False)
class FitResult:
    """Outcome of :func:`~slidespin.analysis.fit.fit` (SI units throughout).

    Attributes
    ----------
    estimates, std_errors : dict
        Fitted value and standard error of each free physical parameter (``free``). The
        standard error is ``inf`` for a parameter the data cannot determine.
    parameter_names : tuple of str
        All fitted parameters: the free physical ones, then each run's free start components
        as ``run{k}.{x|y|phi|vx|vy|omega}``.
    values : ndarray
        Their fitted values.
    covariance, correlation : ndarray
        Covariance (JᵀJ)⁻¹ σ̂² (MODEL §12) and correlation of ``parameter_names`` (NaN in
        the rows of parameters that are not identifiable).
    identifiable : dict
        For each of ``parameter_names``, whether the data determine it (the module docstring
        of :mod:`slidespin.analysis.fit`).
    singular_values : ndarray
        Singular values of the Jacobian scaled by the parameters' typical sizes.
    condition : float
        Their ratio, largest over smallest.
    starts : tuple of State
        Each run's start state at its first measured time.
    start_errors : tuple of dict
        Standard errors of each run's fitted start components.
    body, friction : Body, FrictionTensor
        The body and tensor with the fitted values.
    chi2, dof, reduced_chi2 : float
        Σ r² with r = residual/σ, N − P, and their ratio (≈ 1 when σ is estimated).
    rms : dict
        Root-mean-square residual of each channel [m or rad].
    sigma : dict
        Noise level used for each channel [m or rad]; ``sigma_estimated`` says which were
        estimated from the residuals.
    n_points, n_runs : int
        Observations (channel values) used, and runs.
    data, fitted, residuals : tuple of dict
        Per run: measured, simulated and measured − simulated (φ wrapped to (−π, π]) values at
        the measured times, keyed ``t``, ``x``, ``y``, ``phi`` (NaN where not measured).
    trajectories : tuple of Trajectory
        The fitted motion of each run (time from the run's first measured time).
    success, message, nfev : bool, str, int
        Convergence of the optimiser and the number of residual evaluations.
    warnings : tuple of str
        Messages of the warnings issued by the fit.
    seconds : float
        Wall time of the fit.
    """

    estimates: dict
    std_errors: dict
    parameter_names: tuple
    values: np.ndarray
    covariance: np.ndarray
    correlation: np.ndarray
    identifiable: dict
    singular_values: np.ndarray
    condition: float
    starts: tuple
    start_errors: tuple
    body: Body
    friction: FrictionTensor
    chi2: float
    dof: int
    reduced_chi2: float
    rms: dict
    sigma: dict
    sigma_estimated: dict
    n_points: int
    n_runs: int
    data: tuple = field(repr=False)
    fitted: tuple = field(repr=False)
    residuals: tuple = field(repr=False)
    trajectories: tuple = field(repr=False)
    loss: str = "linear"
    success: bool = True
    message: str = ""
    nfev: int = 0
    warnings: tuple = ()
    seconds: float = 0.0

    def __repr__(self) -> str:
        parts = []
        for k, val in self.estimates.items():
            se = self.std_errors[k]
            parts.append(
                f"{k}={val:.6g} ± {se:.2g}"
                if math.isfinite(se)
                else f"{k}={val:.6g} (not identifiable)"
            )
        notes = f", warnings={len(self.warnings)}" if self.warnings else ""
        return (
            f"FitResult({', '.join(parts)}; chi2/dof={self.reduced_chi2:.3g}, "
            f"runs={self.n_runs}, points={self.n_points}, success={self.success}{notes})"
        )

    def _repr_html_(self) -> str:
        """Estimates ± standard errors, 95 % intervals, the fit's warnings (identifiability,
        correlations, bounds) and its goodness for notebooks (no arrays)."""
        head = "".join(
            f"<th>{h}</th>" for h in ("parameter", "estimate", "std error", "95% interval")
        )
        rows = []
        for k, val in self.estimates.items():
            se = self.std_errors[k]
            if math.isfinite(se):
                lo, hi = self.interval(k)
                cells = (f"{val:.6g}", f"{se:.3g}", f"[{lo:.6g}, {hi:.6g}]")
            else:
                cells = (f"{val:.6g}", "inf", "not identifiable")
            rows.append(
                f"<tr><th style='text-align:left'>{escape(k)}</th>"
                + "".join(f"<td>{c}</td>" for c in cells)
                + "</tr>"
            )
        stats = {
            "chi2 / dof": f"{self.chi2:.6g} / {self.dof} = {self.reduced_chi2:.4g}",
            "points, runs": f"{self.n_points} values in {self.n_runs} run(s)",
            "noise sigma": ", ".join(
                f"{c} {x:.3g} {_UNITS[c]}{' (estimated)' if self.sigma_estimated[c] else ''}"
                for c, x in self.sigma.items()
            ),
            "converged": f"{self.success} ({self.message})",
        }
        for m in self.warnings:
            stats.setdefault("warnings", "")
            stats["warnings"] += ("<br>" if stats["warnings"] else "") + escape(m)
        for k, text in stats.items():
            body = text if k == "warnings" else escape(text)
            rows.append(
                f"<tr><th style='text-align:left'>{escape(k)}</th><td colspan='3'>{body}</td></tr>"
            )
        return f"<table><caption>FitResult</caption><tr>{head}</tr>{''.join(rows)}</table>"

    def to_pandas(self, level: float = 0.95):
        """Every fitted parameter as a :class:`pandas.DataFrame` (one row each, indexed by
        ``parameter_names``): ``estimate``, ``std_error`` and the normal-approximation
        interval at ``level`` (``ci_low``, ``ci_high``; ±inf where not identifiable), and
        ``identifiable``. The free physical parameters come first, then each run's start
        components ``run{k}.{x|y|phi|vx|vy|omega}``; the goodness of fit (:meth:`summary`)
        is in ``DataFrame.attrs``. Needs pandas (``pip install pandas``)."""
        try:
            # lazy: pandas is optional (and slow to import)
            import pandas as pd  # type: ignore[import-untyped]  # no stubs installed
        except ImportError:  # pragma: no cover - depends on the environment
            raise ImportError("FitResult.to_pandas needs pandas: pip install pandas") from None
        from scipy.stats import norm  # lazy: scipy.stats takes ~0.4 s to import

        level = v.in_range("level", level, 0.0, 1.0, lo_open=True, hi_open=True)
        z = float(norm.ppf(0.5 + level / 2.0))
        est, se = [], []
        for name, val in zip(self.parameter_names, self.values):
            if name in self.std_errors:
                est.append(self.estimates[name])
                se.append(self.std_errors[name])
            else:
                run, comp = name.split(".")
                est.append(float(val))
                se.append(self.start_errors[int(run[3:])][comp])
        e, s = np.array(est, dtype=float), np.array(se, dtype=float)
        df = pd.DataFrame(
            {
                "estimate": e,
                "std_error": s,
                "ci_low": e - z * s,
                "ci_high": e + z * s,
                "identifiable": [bool(self.identifiable[n]) for n in self.parameter_names],
            },
            index=pd.Index(list(self.parameter_names), name="parameter"),
        )
        df.attrs.update(self.summary())
        df.attrs["level"] = level
        return df

    @property
    def names(self) -> tuple:
        """The free physical parameters, in order."""
        return tuple(self.estimates)

    def interval(self, name: str, level: float = 0.95) -> tuple[float, float]:
        """Normal-approximation confidence interval of a free parameter."""
        from scipy.stats import norm  # lazy: scipy.stats takes ~0.4 s to import

        z = float(norm.ppf(0.5 + level / 2.0))
        val, se = self.estimates[name], self.std_errors[name]
        return (val - z * se, val + z * se)

    def physical_correlation(self) -> dict:
        """Correlation among the free physical parameters as a nested dict."""
        n = len(self.estimates)
        names = list(self.estimates)
        return {
            a: {b: _num(self.correlation[i, j]) for j, b in enumerate(names)}
            for i, a in enumerate(names[:n])
        }

    def summary(self) -> dict:
        """JSON-ready dict (non-finite numbers are ``None``)."""
        starts = []
        for k, st in enumerate(self.starts):
            d = {c: _num(getattr(st, c)) for c in START}
            d["std_errors"] = {c: _num(e) for c, e in self.start_errors[k].items()}
            d["t0"] = _num(self.data[k]["t"][0])
            starts.append(d)
        return {
            "estimates": {k: _num(x) for k, x in self.estimates.items()},
            "std_errors": {k: _num(x) for k, x in self.std_errors.items()},
            "correlation": self.physical_correlation(),
            "identifiable": dict(self.identifiable),
            "chi2": _num(self.chi2),
            "dof": int(self.dof),
            "reduced_chi2": _num(self.reduced_chi2),
            "rms": {k: _num(x) for k, x in self.rms.items()},
            "sigma": {k: _num(x) for k, x in self.sigma.items()},
            "sigma_estimated": dict(self.sigma_estimated),
            "condition": _num(self.condition),
            "n_points": int(self.n_points),
            "n_runs": int(self.n_runs),
            "starts": starts,
            "frame": self.friction.frame,
            "loss": self.loss,
            "success": bool(self.success),
            "message": self.message,
            "nfev": int(self.nfev),
            "warnings": list(self.warnings),
            "seconds": _num(self.seconds),
        }

    def table(self, labels=None) -> str:
        """The estimates ± standard errors and the goodness of fit as text.

        ``labels`` names the runs (default 0, 1, ...), e.g. the ``run`` column of the CSV.
        """
        labels = [str(k) for k in range(self.n_runs)] if labels is None else list(labels)
        lines = [f"{'parameter':<18} {'estimate':>14} {'std error':>12}  95% interval"]
        for k, val in self.estimates.items():
            se = self.std_errors[k]
            if math.isfinite(se):
                lo, hi = self.interval(k)
                lines.append(f"{k:<18} {val:>14.8g} {se:>12.3g}  [{lo:.6g}, {hi:.6g}]")
            else:
                lines.append(f"{k:<18} {val:>14.8g} {'inf':>12}  not identifiable")
        names = list(self.estimates)
        if len(names) > 1:
            lines.append("correlation:")
            for i, a in enumerate(names):
                row = " ".join(
                    f"{self.correlation[i, j]:+7.3f}"
                    if math.isfinite(self.correlation[i, j])
                    else f"{'n/a':>7}"
                    for j in range(len(names))
                )
                lines.append(f"  {a:<16} {row}")
        for k, st in enumerate(self.starts):
            lines.append(
                f"{'run ' + labels[k] + ' start':<18}: x={st.x:.6g} m, y={st.y:.6g} m, phi={st.phi:.6g} rad, "
                f"vx={st.vx:.6g} m/s, vy={st.vy:.6g} m/s, omega={st.omega:.6g} rad/s"
            )
        rms = ", ".join(f"{c} {x:.3g} {_UNITS[c]}" for c, x in self.rms.items())
        sig = ", ".join(
            f"{c} {x:.3g} {_UNITS[c]}{' (estimated)' if self.sigma_estimated[c] else ''}"
            for c, x in self.sigma.items()
        )
        lines += [
            f"chi2 / dof        : {self.chi2:.6g} / {self.dof} = {self.reduced_chi2:.4g}",
            f"rms residual      : {rms}",
            f"noise sigma       : {sig}",
            (
                f"points, runs      : {self.n_points} values in {self.n_runs} run(s); "
                f"{self.nfev} evaluations, {self.seconds:.3g} s"
            ),
            f"converged         : {self.success} ({self.message})",
        ]
        return "\n".join(lines)

    def predict(self, run: int, t) -> dict:
        """Fitted x, y, φ of run ``run`` at absolute times ``t`` [s] (the data's clock)."""
        t = np.asarray(t, dtype=float) - self.data[run]["t"][0]
        return trajectory_at(self.trajectories[run], t)
