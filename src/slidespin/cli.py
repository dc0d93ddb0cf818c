"""Command-line interface: ``slidespin demo | simulate | reproduce | bench``.

Errors in the input (bad values, unknown keys, unreadable files, unwritable outputs) print one
line naming the parameter, its value and the valid range, and exit with status 2 before any
work starts and without writing anything. Unexpected internal errors print a short message
asking for a report; ``--debug`` shows the traceback.
"""

from __future__ import annotations

import argparse
import importlib
import json
import math
import os
import sys

__all__ = ["main", "demo_case", "check_output_path"]

# Subcommands living in other modules: each exposes ``configure(parser)`` and ``run(args)``.
_PLUGINS = (
    ("reproduce", "slidespin.paper.cli", "reproduce the paper's tables and figures"),
    ("bench", "slidespin.bench", "benchmark the compiled engine against naive approaches"),
)

ISSUE_URL = "https://github.com/slidespin/slidespin/issues"


def demo_case():
    """The demo: elliptic plate e = 0.866, a = 0.1 m, uniform pressure, fx = 0.42, fy = 0.54,
    v₀ = 1 m/s, ω₀ = 5 rad/s, ϑ₀ = π/4 (``examples/demo.toml`` describes the same case)."""
    from .body import Body, State
    from .case import Case
    from .friction import FrictionTensor
    from .geometry import Ellipse
    from .pressure import UniformPressure

    body = Body(Ellipse.from_eccentricity(0.1, 0.866), UniformPressure(), mass=1.0)
    return Case(
        body=body,
        friction=FrictionTensor(0.42, 0.54),
        initial_state=State.from_speed(1.0, 5.0, theta=math.pi / 4),
        name="demo: elliptic plate, uniform pressure, anisotropic friction",
    )


def check_output_path(path: str, what: str) -> str:
    """Raise ``ValueError`` unless ``path`` can be written (checked before any work)."""
    path = os.fspath(path)
    parent = os.path.dirname(os.path.abspath(path)) or "."
    if os.path.isdir(path):
        raise ValueError(f"{what} = {path!r} is a directory; valid values: a file path")
    if not os.path.isdir(parent):
        raise ValueError(f"{what} = {path!r}: the directory {parent!r} does not exist")
    if not os.access(parent, os.W_OK):
        raise ValueError(f"{what} = {path!r}: the directory {parent!r} is not writable")
    return path


def _print_summary(case, traj, out) -> None:
    s = traj.summary()
    a = case.body.patch.a
    lines = [
        f"case        : {case.name or '(unnamed)'}",
        f"status      : {s['status']}  ({traj.n_steps} steps)",
        f"stop time   : {traj.t_stop:.10g} s",
        f"distance    : {traj.distance:.10g} m  (G ends at x = {traj.stop_state.x:.6g} m, "
        f"y = {traj.stop_state.y:.6g} m)",
        f"rotation    : {traj.stop_state.phi - case.initial_state.phi:.10g} rad",
        f"beta_stop   : {traj.beta_stop:.10g} m  (beta/a = {traj.beta_stop / a:.10g})",
        f"theta_stop  : {traj.theta_stop:.10g} rad  ({math.degrees(traj.theta_stop):.6g} deg)",
        f"ending      : {traj.ending}",
    ]
    print("\n".join(lines), file=out)


def _run_case(case, args) -> int:
    from .simulate import simulate

    outputs = [(args.plot, "--plot"), (args.csv, "--csv")]
    for path, flag in outputs:
        if path:
            check_output_path(path, flag)
    traj = simulate(
        case.body, case.friction, case.initial_state, g=case.g, rtol=case.rtol,
        max_steps=case.max_steps, max_step=0.05 if args.plot else None,
    )
    if args.json:
        print(json.dumps(traj.summary(), indent=2))
    else:
        _print_summary(case, traj, sys.stdout)
    if args.csv:
        traj.to_csv(args.csv)
        if not args.json:
            print(f"trajectory  : {args.csv}")
    if args.plot:
        from .plotting import plot_trajectory

        fig = plot_trajectory(traj, title=case.name or None)
        fig.savefig(args.plot, dpi=150)
        if not args.json:
            print(f"figure      : {args.plot}")
    return 0 if traj.status in ("stopped", "at_rest") else 1


def _cmd_demo(args) -> int:
    if args.plot is None:
        args.plot = "slidespin-demo.png"
    return _run_case(demo_case(), args)


def _cmd_simulate(args) -> int:
    from .case import load_case

    return _run_case(load_case(args.case), args)


def _add_outputs(p, default_plot=None) -> None:
    p.add_argument("--json", action="store_true", help="print the stop summary as JSON")
    p.add_argument("--plot", metavar="OUT.png", default=default_plot,
                   help="write a figure of the motion")
    p.add_argument("--csv", metavar="OUT.csv", help="write the trajectory as CSV")


def build_parser() -> argparse.ArgumentParser:
    from . import __version__

    parser = argparse.ArgumentParser(
        prog="slidespin",
        description="Sliding and spinning of a flat body on a plane under anisotropic dry "
        "friction with an elliptic contact patch.",
    )
    parser.add_argument("--version", action="version", version=f"slidespin {__version__}")
    parser.add_argument("--debug", action="store_true", help="show tracebacks of internal errors")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    sub.required = True

    p = sub.add_parser("demo", help="simulate the demo case, print the stop, draw a figure")
    _add_outputs(p)
    p.set_defaults(func=_cmd_demo)
    p.epilog = "The figure goes to slidespin-demo.png unless --plot says otherwise."

    p = sub.add_parser("simulate", help="simulate a case described in a TOML file")
    p.add_argument("case", metavar="CASE.toml", help="case file (see examples/)")
    _add_outputs(p)
    p.set_defaults(func=_cmd_simulate)

    for name, module, help_text in _PLUGINS:
        try:
            mod = importlib.import_module(module)
        except ModuleNotFoundError as exc:
            if exc.name and module.startswith(exc.name):
                continue  # that part of slidespin is not installed in this version
            raise
        p = sub.add_parser(name, help=help_text)
        mod.configure(p)
        p.set_defaults(func=mod.run)
    return parser


def main(argv=None) -> int:
    """Entry point of the ``slidespin`` command; returns the exit status."""
    argv = sys.argv[1:] if argv is None else list(argv)
    debug = "--debug" in argv
    try:
        parser = build_parser()
        args = parser.parse_args(argv)
        return int(args.func(args) or 0)
    except ValueError as exc:
        if debug:
            raise
        print(f"slidespin: error: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:  # pragma: no cover
        print("slidespin: interrupted", file=sys.stderr)
        return 130
    except Exception as exc:  # noqa: BLE001 - last-resort report, see module docstring
        if debug:
            raise
        print(
            f"slidespin: internal error: {type(exc).__name__}: {exc}\n"
            f"This is a bug in slidespin. Please report it at {ISSUE_URL} with the command "
            "line and the case file; rerun with --debug to see the traceback.",
            file=sys.stderr,
        )
        return 3


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
