"""``slidespin fit``: friction parameters from tracked motion (MODEL §12, :mod:`slidespin.analysis.fit`).

Usage::

    slidespin fit DATA.csv --case CASE.toml [--free fx,fy,f] [--sigma x=1e-3,y=1e-3,phi=0.01]
                  [--loss linear|soft_l1|huber|cauchy|arctan] [--frame case|plane|body|best]
                  [--fixed-start]
                  [--json] [--plot OUT.png]

``DATA.csv`` has the columns ``t,x,y,phi`` (any of x, y, phi may be absent) and an optional
``run`` column; the case file (the format of ``slidespin simulate``) gives the body, the
friction tensor (the start guess of the free parameters, and the frame unless ``--frame``
says otherwise; ``best`` fits both frames and keeps the likelier), ``[solver] g`` and
``[solver] rtol`` (the tolerance of every simulation of the fit; default that of
:func:`slidespin.analysis.fit.fit`, 1e-12). Its ``[initial]`` table is optional: with
``--fixed-start`` it is the known start state of every run (at the run's first time);
otherwise each run's start is fitted and ``[initial]`` only supplies the start components the
data do not give. The fit models a body coasting on a level plane: a case file with
``[load]``, ``[incline]``, ``[solver] t_end`` or ``[solver] max_steps`` is refused (fitting
under loads is not supported), never fitted as if they were not there.

Without ``--json`` a table of estimates ± standard errors is printed; ``--json`` prints
``{"estimates": {...}, "std_errors": {...}, "correlation": {...}, "chi2": ..., ...}``
(non-finite numbers as ``null``). Warnings (parameters the data cannot determine, no
convergence) go to standard error as ``slidespin: warning: ...`` lines and into the JSON's
``warnings``. Exit status 0, or 1 if the optimiser did not converge; 2 for bad input, found
before any work. This module follows the plugin contract of :mod:`slidespin.cli.main`:
``configure(parser)`` and ``run(args) -> int``.
"""

from __future__ import annotations

import dataclasses
import io
import json
import os
import sys
import warnings

from slidespin._io import check_figure_path, write_outputs

# nothing heavy at the top: the parser is built from this module (`slidespin --help`); the
# fit (SciPy) and the figure (matplotlib) are imported by run()

__all__ = ["configure", "load_fit_case", "parse_sigma", "plot_fit", "run", "UNUSED"]

#: the names of :mod:`slidespin.analysis.fit` and :mod:`slidespin.analysis.fit_data` that the
#: parser shows (a test keeps them equal; spelled here so that the parser does not import SciPy)
PARAMETERS = ("fx", "fy", "f", "angle", "xi_c", "eta_c", "moment_of_inertia")
LOSSES = ("linear", "soft_l1", "huber", "cauchy", "arctan")
CHANNELS = ("x", "y", "phi")

_COASTING = "the fit models a body coasting on a level plane; fitting under loads is not supported"
#: what a case file may give that ``slidespin fit`` cannot honour (refused, never ignored)
UNUSED = (
    ("pusher", None, _COASTING + "; slidespin simulate runs a pushed case"),
    ("load", None, _COASTING),
    ("incline", None, _COASTING),
    ("solver", ("t_end",), _COASTING + " (each run ends at its last measured time)"),
    (
        "solver",
        ("max_steps",),
        "the fit bounds its work by its evaluations, not by integrator steps",
    ),
)


def configure(parser) -> None:
    """Add the arguments of ``slidespin fit`` to an argparse (sub)parser."""
    parser.description = (
        "Fit friction parameters (and each run's start state) to tracked positions and angles "
        "by least squares, with standard errors, correlations and an identifiability check."
    )
    parser.epilog = (
        "DATA.csv columns: t [s], x, y [m], phi [rad] (any of x, y, phi may be absent; an empty "
        "cell is a missing value) and an optional run label column 'run'. Free parameters: "
        + ", ".join(PARAMETERS)
        + ". The tensor's frame is taken from the case file unless "
        "--frame says otherwise."
    )
    parser.add_argument("data", metavar="DATA.csv", help="tracked runs (CSV)")
    parser.add_argument(
        "--case",
        required=True,
        metavar="CASE.toml",
        help="body, friction (start guess) and g, as for 'slidespin simulate'",
    )
    parser.add_argument(
        "--free",
        default="fx,fy,f",
        metavar="NAMES",
        help="comma-separated parameters to fit (default fx,fy,f)",
    )
    parser.add_argument(
        "--sigma",
        default=None,
        metavar="x=SX,y=SY,phi=SPHI",
        help="noise level of channels [m, rad]; others are estimated from the residuals",
    )
    parser.add_argument(
        "--loss",
        default="linear",
        choices=LOSSES,
        help="least-squares loss; a robust one limits outliers (default linear)",
    )
    parser.add_argument(
        "--frame",
        default="case",
        choices=("case", "plane", "body", "best"),
        help="frame of the tensor: as in the case file (default), plane, body, "
        "or best: fit both and keep the likelier",
    )
    parser.add_argument(
        "--fixed-start",
        action="store_true",
        help="the case's [initial] state is the known start of every run",
    )
    parser.add_argument("--json", action="store_true", help="print the results as JSON")
    parser.add_argument(
        "--plot",
        metavar="OUT.png",
        default=None,
        help="write a figure of measured vs fitted paths and angles, with residuals",
    )
    parser.add_argument(
        "--quiet",
        action="store_true",
        help="no progress bar (the bar is drawn only when stderr is a terminal)",
    )


def parse_sigma(text: str | None) -> dict | None:
    """``"x=1e-3,phi=0.01"`` → ``{'x': 0.001, 'phi': 0.01}`` (validated)."""
    if text is None:
        return None
    # deferred: keeps `slidespin --help` fast (NumPy is not imported for parsing)
    from slidespin import _validate as v

    out = {}
    for item in text.split(","):
        item = item.strip()
        if not item:
            continue
        key, sep, val = item.partition("=")
        key = key.strip()
        if not sep or key not in CHANNELS:
            raise ValueError(
                f"--sigma item {item!r} is invalid; valid: x=VALUE, y=VALUE, "
                "phi=VALUE (metres, radians), comma-separated"
            )
        if key in out:
            raise ValueError(f"--sigma gives {key!r} twice; valid: each of x, y, phi at most once")
        try:
            num = float(val)
        except ValueError:
            raise ValueError(
                f"--sigma {key} = {val.strip()!r} is not a number; valid range: finite and > 0"
            ) from None
        out[key] = v.positive(f"--sigma {key}", num, "rad" if key == "phi" else "m")
    if not out:
        raise ValueError(f"--sigma = {text!r} gives no channel; valid: x=VALUE,y=VALUE,phi=VALUE")
    return out


def load_fit_case(path):
    """Read a case file with :mod:`slidespin.studies.case`; ``[initial]`` may be left out.

    Returns the :class:`~slidespin.studies.case.Case` (at rest at the origin without ``[initial]``)
    and whether the file had an ``[initial]`` table. What the fit cannot honour
    (:data:`UNUSED`: a pusher, loads, a tilt, ``t_end``, ``max_steps``) is refused, naming the file and
    the key.
    """
    case, data = _read_fit_case(path)
    return case, "initial" in data


def _read_fit_case(path):
    # deferred: keeps `slidespin --help` fast (the numerical stack is not imported for parsing)
    from slidespin.studies.case import read_case, refuse_unused

    case, data = read_case(path, initial_required=False)
    refuse_unused(path, data, "slidespin fit", UNUSED)
    return case, data


def _free(text: str, body):
    # deferred: keeps `slidespin --help` fast (SciPy is not imported for parsing)
    from slidespin.analysis.fit import _check_free

    names = tuple(s.strip() for s in text.split(",") if s.strip())
    try:
        return _check_free(names, body)
    except ValueError as exc:
        raise ValueError(f"--free: {exc}") from None


def run(args) -> int:
    """Run ``slidespin fit``; returns the exit status."""
    if args.plot:
        check_figure_path(args.plot, "--plot")
    sigma = parse_sigma(args.sigma)
    case, data = _read_fit_case(args.case)
    if args.fixed_start and "initial" not in data:
        raise ValueError(
            f"--fixed-start needs an [initial] table in the case file {args.case!r}; valid: "
            "a case file with [initial] (the known start of every run), or no --fixed-start"
        )
    free = _free(args.free, case.body)
    # deferred: keeps `slidespin --help` fast (SciPy is not imported for parsing)
    from slidespin.analysis.fit import compare_frames, fit
    from slidespin.analysis.fit_data import read_runs
    from slidespin.cli._busy import busy

    runs, labels = read_runs(args.data, labels=True)
    kw = {"starts": case.initial_state} if args.fixed_start else {"start_guess": case.initial_state}
    if "rtol" in data.get("solver", {}):  # else the fit's own default (1e-12)
        kw["rtol"] = case.rtol
    friction = case.friction
    if args.frame in ("plane", "body"):
        friction = dataclasses.replace(friction, frame=args.frame)
    scores = None
    quiet = getattr(args, "quiet", False)
    with (
        warnings.catch_warnings(record=True) as caught,
        busy("fit", enabled=False if quiet else None),
    ):
        warnings.simplefilter("always")
        try:
            if args.frame == "best":
                res, scores, _ = compare_frames(
                    runs, case.body, friction, free, sigma=sigma, loss=args.loss, g=case.g, **kw
                )
            else:
                res = fit(
                    runs, case.body, friction, free, sigma=sigma, loss=args.loss, g=case.g, **kw
                )
        except ValueError as exc:
            raise ValueError(f"{args.data}: {exc}") from None
    del caught  # the chosen fit's own warnings are in res.warnings (not the other frame's)
    for message in res.warnings:
        print(f"slidespin: warning: {message}", file=sys.stderr)
    files = []
    if args.plot:
        fig = plot_fit(res, labels=labels, title=case.name or None)
        buf = io.BytesIO()
        fig.savefig(buf, format=os.path.splitext(args.plot)[1].lower().lstrip("."), dpi=150)
        files.append((args.plot, buf.getvalue()))
    if args.json:
        out = res.summary()
        out["runs"] = labels
        if scores is not None:
            out["frame_scores"] = scores
        out["data"] = str(args.data)
        out["case"] = str(args.case)
        print(json.dumps(out, indent=2))
    else:
        print(f"data        : {args.data} ({len(runs)} run(s): {', '.join(labels)})")
        print(f"case        : {case.name or args.case} (frame {res.friction.frame})")
        if scores is not None:
            other = "body" if res.friction.frame == "plane" else "plane"
            print(
                f"frame       : {res.friction.frame} is likelier than {other}: -2 log L "
                f"lower by {scores[other] - scores[res.friction.frame]:.4g}"
            )
        print(res.table(labels))
    if files:
        write_outputs(files)
        if not args.json:
            print(f"figure      : {args.plot}")
    return 0 if res.success else 1


def plot_fit(result, labels=None, title=None):
    """Figure of a fit: measured points and fitted lines, with residuals
    (:func:`slidespin.viz.fit_plot.plot_fit`). Returns the figure."""
    from slidespin.viz.fit_plot import plot_fit as draw  # deferred: matplotlib

    return draw(result, labels=labels, title=title)
