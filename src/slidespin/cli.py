"""Command-line interface: ``slidespin demo | simulate | sweep | sweep-read | sweep-plot |
reproduce | bench``.

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

import numpy as np

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
    try:  # a real probe: permissions, read-only file systems, quotas
        import tempfile

        with tempfile.NamedTemporaryFile(dir=parent, prefix=".slidespin-probe-"):
            pass
    except OSError as exc:
        raise ValueError(
            f"{what} = {path!r}: the directory {parent!r} is not writable ({exc.strerror})"
        ) from None
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


def _cmd_sweep(args) -> int:
    from .sweep import connect_dask, load_spec, sweep

    if args.workers is not None and args.workers < 1:
        raise ValueError(f"--workers = {args.workers} is invalid; valid range: integer >= 1")
    spec = load_spec(args.spec)
    client = None
    if args.scheduler or args.workers:
        client = connect_dask(args.scheduler, args.workers)
    try:
        res = sweep(spec, args.out, executor=client, resume=args.resume,
                    progress=False if args.quiet else None)
    finally:
        if client is not None:
            cluster = getattr(client, "cluster", None)
            client.close()
            if cluster is not None and not args.scheduler:
                cluster.close()
    if not args.quiet:
        print(f"sweep       : {spec.name or args.spec}")
        print(f"cases       : {res.n_cases} in {res.n_chunks} chunks "
              f"({res.chunks_computed} computed now)")
        if res.cases_computed:
            print(f"time        : {res.seconds:.3g} s  ({res.cases_per_second:.0f} cases/s)")
        print(f"results     : {res.out}")
    return 0


def _cmd_sweep_read(args) -> int:
    from .sweep import read_sweep

    check_output_path(args.csv, "--csv")
    table = read_sweep(args.dir)
    import csv

    names = list(table)
    with open(args.csv, "w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh)
        w.writerow(names)
        n = len(table[names[0]]) if names else 0
        for i in range(n):
            w.writerow([_cell(table[k][i]) for k in names])
    print(f"{n} cases -> {args.csv}")
    return 0


def _cell(x):
    if isinstance(x, (float, np.floating)):
        return repr(float(x))
    if isinstance(x, (np.integer,)):
        return int(x)
    return x


def _cmd_sweep_plot(args) -> int:
    from .plotting import plot_sweep
    from .sweep import read_sweep

    out = check_output_path(args.out, "--out")
    table = read_sweep(args.dir)
    if not table:
        raise ValueError(f"{args.dir!r} holds no finished chunk yet")
    fig = plot_sweep(table, args.x, args.value, args.y)
    fig.savefig(out, dpi=150)
    print(f"figure      : {out}")
    return 0


def _add_outputs(p, default_plot=None) -> None:
    p.add_argument("--json", action="store_true", help="print the stop summary as JSON")
    p.add_argument("--plot", metavar="OUT.png", default=default_plot,
                   help="write a figure of the motion")
    p.add_argument("--csv", metavar="OUT.csv", help="write the trajectory as CSV")


class _Parser(argparse.ArgumentParser):
    """argparse with one-line errors (exit status 2), like every other slidespin error."""

    def error(self, message):
        print(f"slidespin: error: {self.prog.split()[-1]}: {message} "
              f"(see '{self.prog} --help')", file=sys.stderr)
        sys.exit(2)


def build_parser() -> argparse.ArgumentParser:
    from . import __version__

    parser = _Parser(
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

    p = sub.add_parser("sweep", help="run a parameter sweep (locally or on a Dask cluster)")
    p.add_argument("spec", metavar="SPEC.toml", help="sweep specification (see examples/sweep_*.toml)")
    p.add_argument("--out", required=True, metavar="DIR", help="result directory")
    p.add_argument("--scheduler", metavar="ADDRESS",
                   help="Dask scheduler, e.g. tcp://HOST:8786 (default: local cores)")
    p.add_argument("--workers", type=int, metavar="N",
                   help="start a local Dask cluster with N worker processes")
    p.add_argument("--resume", action="store_true", help="finish an interrupted sweep")
    p.add_argument("--quiet", action="store_true", help="no progress bar, no summary")
    p.set_defaults(func=_cmd_sweep)

    p = sub.add_parser("sweep-read", help="gather a sweep's results into one CSV table")
    p.add_argument("dir", metavar="DIR", help="sweep result directory (from slidespin sweep)")
    p.add_argument("--csv", required=True, metavar="OUT.csv")
    p.set_defaults(func=_cmd_sweep_read)

    p = sub.add_parser("sweep-plot", help="heat map or line plot of a sweep result")
    p.add_argument("dir", metavar="DIR", help="sweep result directory (from slidespin sweep)")
    p.add_argument("--x", required=True, help="input column for the x axis, e.g. fx")
    p.add_argument("--y", help="input column for the y axis (heat map), e.g. I_star")
    p.add_argument("--value", default="beta_stop", help="result column shown (default beta_stop)")
    p.add_argument("--out", default="sweep.png", metavar="OUT.png",
                   help="figure file (default sweep.png in the current directory)")
    p.set_defaults(func=_cmd_sweep_plot)

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
        try:
            args = parser.parse_args(argv)
        except SystemExit as exc:  # --help, --version, or a one-line usage error
            return int(exc.code or 0)
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
