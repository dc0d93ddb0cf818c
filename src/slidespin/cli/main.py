"""Command-line interface: ``slidespin demo | simulate | sweep | sweep-read | sweep-plot |
reproduce | bench | fit | limit-surface | animate``.

Errors in the input (bad values, unknown keys, unreadable files, unwritable outputs, an
unknown figure format) print one line naming the file, the parameter, its value and the valid
range, and exit with status 2 before any work starts and without writing anything. A write
that fails after the work (disk full, permission denied) also exits with status 2 and says
which file; outputs are written whole or not at all. Unexpected internal errors print a short
message asking for a report and exit with status 3; ``--debug`` shows the traceback.

Exit status: 0 success; 1 the command ran but a result did not converge (a case whose status
is ``max_steps``, ``step_too_small`` or ``non_finite``, a loaded run whose status is
``max_steps``, ``max_phases``, ``step_too_small`` or ``no_onset``, or a pushed run (a case
with ``[pusher]``) whose status is not ``ok``; see
:mod:`slidespin.motion.outcomes`); 2 bad input or a failed write; 3 internal error.

Files written without an explicit path go to ``./slidespin-out/`` (:data:`DEFAULT_OUT_DIR`),
never straight into the working directory.
"""

from __future__ import annotations

import argparse
import csv
import gc
import importlib
import json
import math
import os
import sys
from pathlib import Path

# Only light modules at the top (the standard library, slidespin._io, slidespin._version):
# building the parser must not import NumPy, SciPy, numba or matplotlib, so that `--help`
# answers at once (tests/cli/test_edges_help.py). The commands import them when they run.
from slidespin._io import (
    FIGURE_FORMATS,
    check_figure_path,
    check_output_path,
    distinct_outputs,
    render_figure,
    write_failure,
    write_outputs,
)

# the version lives in a root helper, so that reading it imports none of the layers
from slidespin._version import __version__

__all__ = [
    "main",
    "demo_case",
    "check_output_path",
    "check_figure_path",
    "write_outputs",
    "DEFAULT_OUT_DIR",
    "FIGURE_FORMATS",
]

#: where files go when the command line gives no path (created when first needed)
DEFAULT_OUT_DIR = "slidespin-out"
#: figure formats accepted by ``--plot`` and ``sweep-plot --out`` (the file's extension)
#: largest step in the regularised time τ of ``simulate``/``demo``: about 1000 recorded
#: points, the same whether or not --plot or --csv is given
CLI_MAX_STEP = 0.05

# Subcommands living in other modules: each exposes ``configure(parser)`` and ``run(args)``.
_PLUGINS = (
    ("reproduce", "slidespin.cli.reproduce", "reproduce the paper's tables and figures"),
    ("bench", "slidespin.cli.bench", "benchmark the compiled engine against naive approaches"),
    ("fit", "slidespin.cli.fit", "fit friction parameters to tracked motion (CSV of t, x, y, phi)"),
    (
        "limit-surface",
        "slidespin.cli.limit_surface",
        "sample and fit the limit surface of a case's body",
    ),
    ("aim", "slidespin.cli.aim", "find the launch that stops a case's body at a target pose"),
    (
        "animate",
        "slidespin.cli.animate",
        "write an animated GIF of a case's motion (Pillow; no ffmpeg)",
    ),
)

ISSUE_URL = "https://github.com/slidespin/slidespin/issues"


def demo_case():
    """The demo: elliptic plate e = 0.866, a = 0.1 m, uniform pressure, fx = 0.42, fy = 0.54,
    v₀ = 1 m/s, ω₀ = 5 rad/s, ϑ₀ = π/4 (``examples/demo.toml`` describes the same case)."""
    # deferred: keeps `slidespin --help` fast (the numerical stack is not imported for parsing)
    from slidespin.contact.body import Body
    from slidespin.contact.ellipse import Ellipse
    from slidespin.contact.friction import FrictionTensor
    from slidespin.contact.pressure import UniformPressure
    from slidespin.motion.state import State
    from slidespin.studies.case import Case

    body = Body(Ellipse.from_eccentricity(0.1, 0.866), UniformPressure(), mass=1.0)
    return Case(
        body=body,
        friction=FrictionTensor(0.42, 0.54),
        initial_state=State.from_speed(1.0, 5.0, theta=math.pi / 4),
        name="demo: elliptic plate, uniform pressure, anisotropic friction",
    )


def _print_summary(case, traj, out) -> None:
    s = traj.summary()
    a = case.body.length_unit
    unit = "extent" if case.body.is_footprint else "a"

    def deg(x):
        return f"{math.degrees(x):.6g} deg" if math.isfinite(x) else "undefined"

    lines = [
        f"case        : {case.name or '(unnamed)'}",
        f"status      : {s['status']}  ({traj.n_steps} steps)",
    ]
    if s["status"] not in ("stopped", "at_rest"):
        # deferred: keeps `slidespin --help` fast (the parser imports no layer)
        from slidespin.motion.outcomes import status_message

        try:
            lines.append(f"              {status_message(s['status'])}")
        except ValueError:
            pass
    lines += [
        f"stop time   : {traj.t_stop:.10g} s",
        f"distance    : {traj.distance:.10g} m  (G ends at x = {traj.stop_state.x:.6g} m, "
        f"y = {traj.stop_state.y:.6g} m)",
        f"rotation    : {traj.stop_state.phi - case.initial_state.phi:.10g} rad",
        f"beta_stop   : {traj.beta_stop:.10g} m  (beta/{unit} = {traj.beta_stop / a:.10g})",
        f"theta_stop  : {traj.theta_stop:.10g} rad  ({deg(traj.theta_stop)})",
        f"ending      : {traj.ending}",
    ]
    print("\n".join(lines), file=out)


def _stop_summary(case, traj) -> dict:
    """``Trajectory.summary()`` with the terminal ratio under a name that fits every patch:
    ``beta_stop_over_length_unit`` = β*/ℓ and ``length_unit`` = ℓ [m] (the semi-axis a of an
    ellipse, the extent of a footprint), next to ``beta_stop_over_a`` (the same number, kept
    under its old name for scripts that read it)."""
    out: dict = {}
    for key, value in traj.summary().items():
        out[key] = value
        if key == "beta_stop_over_a":
            out["beta_stop_over_length_unit"] = value
            out["length_unit"] = case.body.length_unit
    return out


def _exit_status(status: str) -> int:
    """0 for a converged or flagged (analytic-limit) stop, 1 for an unconverged one."""
    # deferred: keeps `slidespin --help` fast (the parser imports no layer)
    from slidespin.motion.outcomes import UNCONVERGED

    return 1 if status in UNCONVERGED else 0


def _run_case(case, args) -> int:
    # deferred: keeps `slidespin --help` fast (the numerical stack is not imported for parsing)
    from slidespin.motion.simulate import simulate

    # every output path and format first: nothing is computed or written if one is bad
    if args.plot:
        check_figure_path(args.plot, "--plot", create_parent=args.plot_is_default)
    if args.csv:
        check_output_path(args.csv, "--csv")
    distinct_outputs((args.plot, "--plot"), (args.csv, "--csv"))
    if getattr(case, "pusher", None) is not None:
        # a [pusher]: the pushed dynamics (MODEL §13)
        from slidespin.cli._pushed import run_pushed_case

        return run_pushed_case(case, args)
    if case.loaded:
        return _run_loaded_case(case, args)
    # the same recorded points whatever the outputs asked for (CSV rows never depend on --plot)
    traj = simulate(
        case.body,
        case.friction,
        case.initial_state,
        g=case.g,
        rtol=case.rtol,
        max_steps=case.max_steps,
        # under a speed law every step costs milliseconds: the integrator's own steps
        max_step=CLI_MAX_STEP if case.friction.speed_law is None else None,
    )
    files = []
    if args.csv:
        files.append((args.csv, traj.to_csv().encode("utf-8")))
    if args.plot:
        from slidespin.viz.trajectory_plot import plot_trajectory

        fig = plot_trajectory(traj, title=case.name or None)
        files.append((args.plot, render_figure(fig, args.plot)))
    write_outputs(files)
    if args.json:
        print(json.dumps(_stop_summary(case, traj), indent=2))
    else:
        _print_summary(case, traj, sys.stdout)
        if args.csv:
            print(f"trajectory  : {args.csv}  ({traj.t.size} rows)")
        if args.plot:
            print(f"figure      : {args.plot}")
    return _exit_status(traj.status)


def _run_loaded_case(case, args) -> int:
    """A case with ``[load]``, ``[incline]`` or ``[solver] t_end``: the stick-slip engine."""
    # deferred: keeps `slidespin --help` fast (the numerical stack is not imported for parsing)
    from slidespin.motion.simulate import simulate

    traj = simulate(
        case.body,
        case.friction,
        case.initial_state,
        g=case.g,
        rtol=case.rtol,
        max_steps=case.max_steps,
        load=case.load,
        incline=case.incline,
        t_end=case.t_end,
    )
    summary = _loaded_summary(traj)
    files = []
    if args.csv:
        files.append((args.csv, traj.to_csv().encode("utf-8")))
    if args.plot:
        from slidespin.viz.trajectory_plot import plot_loaded_trajectory

        fig = plot_loaded_trajectory(traj, title=case.name or None)
        files.append((args.plot, render_figure(fig, args.plot)))
    write_outputs(files)
    if args.json:
        print(json.dumps(summary, indent=2))
    else:
        _print_loaded_summary(case, traj, summary, sys.stdout)
        if args.csv:
            print(f"trajectory  : {args.csv}  ({traj.t.size} rows)")
        if args.plot:
            print(f"figure      : {args.plot}")
    return _loaded_exit_status(traj.status)


def _loaded_summary(traj) -> dict:
    """``LoadedTrajectory.summary()`` with the vocabulary's explanations of its status and
    ending (:mod:`slidespin.motion.outcomes`); a name outside the vocabulary is an internal error."""
    # deferred: keeps `slidespin --help` fast (the parser imports no layer)
    from slidespin.motion.outcomes import ending_message, status_message

    summary = dict(traj.summary())
    try:
        summary["status_message"] = status_message(summary["status"], loaded=True)
        summary["ending_message"] = ending_message(summary["ending"], loaded=True)
    except ValueError as exc:  # a bug in the engine, not bad input (exit status 3)
        raise RuntimeError(f"the loaded run reported an unknown outcome: {exc}") from None
    return summary


def _print_loaded_summary(case, traj, summary: dict, out) -> None:
    def num(x, unit: str) -> str:
        return "undefined" if x is None else f"{x:.10g} {unit}"

    lines = [
        f"case        : {case.name or '(unnamed)'}",
        f"status      : {summary['status']}  ({summary['status_message']})",
    ]
    if summary.get("message"):
        lines.append(f"              {summary['message']}")
    lines += [
        f"ending      : {summary['ending']}  ({summary['ending_message']})",
        f"end time    : {num(summary['t_final'], 's')}",
        f"stop time   : {num(summary['t_stop'], 's')}",
        f"position    : x = {summary['x_final']:.6g} m, y = {summary['y_final']:.6g} m, "
        f"phi = {summary['phi_final']:.6g} rad",
        f"velocity    : vx = {summary['vx_final']:.6g} m/s, vy = {summary['vy_final']:.6g} m/s, "
        f"omega = {summary['omega_final']:.6g} rad/s",
        f"phases      : {_phases_text(traj.phases)}",
        f"energy error: {summary['energy_error']:.3g} J",
    ]
    if traj.incline is not None:
        lines.append(f"gravity work: {summary['gravity_work']:.10g} J")
    print("\n".join(lines), file=out)


def _phases_text(phases, limit: int = 6) -> str:
    """``stick 0-0.475 s, slip 0.475-2.06 s, ...`` (the first ``limit`` phases)."""
    parts = [f"{kind} {a:.6g}-{b:.6g} s" for kind, a, b in phases[:limit]]
    if len(phases) > limit:
        parts.append(f"... ({len(phases)} phases; all in --json)")
    return ", ".join(parts) or "none"


def _loaded_exit_status(status: str) -> int:
    """0 for a loaded run that reached its end, 1 for one that ended early."""
    # deferred: keeps `slidespin --help` fast (the parser imports no layer)
    from slidespin.motion.outcomes import LOADED_UNCONVERGED

    return 1 if status in LOADED_UNCONVERGED else 0


def _cmd_demo(args) -> int:
    args.plot_is_default = args.plot is None
    if args.plot is None:
        args.plot = os.path.join(DEFAULT_OUT_DIR, "demo.png")
    return _run_case(demo_case(), args)


def _cmd_simulate(args) -> int:
    # deferred: keeps `slidespin --help` fast (the numerical stack is not imported for parsing)
    from slidespin.studies.case import load_case

    args.plot_is_default = False
    return _run_case(load_case(args.case), args)


def _cmd_sweep(args) -> int:
    # deferred: keeps `slidespin --help` fast (the numerical stack is not imported for parsing)
    from slidespin.studies.sweep import connect_dask, sweep
    from slidespin.studies.sweep_parse import load_spec
    from slidespin.studies.sweep_store import _check_out

    if args.workers is not None and args.workers < 1:
        raise ValueError(f"--workers = {args.workers} is invalid; valid range: integer >= 1")
    if args.scheduler and args.workers:
        raise ValueError(
            f"--scheduler = {args.scheduler!r} and --workers = {args.workers} exclude each "
            "other (--workers starts a local cluster); valid: one of them"
        )
    spec = load_spec(args.spec)
    _check_out(Path(args.out))
    client = None
    if args.scheduler or args.workers:
        client = connect_dask(args.scheduler, args.workers)
    try:
        res = sweep(
            spec,
            args.out,
            executor=client,
            resume=args.resume,
            progress=False if args.quiet else None,
        )
    finally:
        if client is not None:
            cluster = getattr(client, "cluster", None)
            client.close()
            if cluster is not None and not args.scheduler:
                cluster.close()
    if res.already_complete:
        if not args.quiet:
            print(
                f"sweep       : {spec.name or args.spec}: complete already in {res.out} "
                f"({res.n_cases} cases in {res.n_chunks} chunks, all checked; nothing "
                f"computed): {_counts_text(res.status_counts)}"
            )
    elif not args.quiet:
        print(f"sweep       : {spec.name or args.spec}")
        print(
            f"cases       : {res.n_cases} in {res.n_chunks} chunks "
            f"({res.chunks_computed} computed now)"
        )
        if res.chunks_repaired:
            print(f"repaired    : {res.chunks_repaired} damaged chunk files computed again")
        if res.cases_computed:
            print(f"time        : {res.seconds:.3g} s  ({res.cases_per_second:.0f} cases/s)")
        print(f"statuses    : {_counts_text(res.status_counts)}")
        print(f"endings     : {_counts_text(res.ending_counts)}")
        print(f"results     : {res.out}")
    if res.n_unconverged:
        print(
            f"slidespin: warning: {res.n_unconverged} of {res.n_cases} cases did not converge "
            f"({_unconverged_text(res.status_counts)}); sweep-read and sweep-plot leave them "
            "out unless --include-unconverged",
            file=sys.stderr,
        )
        return 1
    return 0


def _counts_text(counts: dict) -> str:
    return ", ".join(f"{k} {v}" for k, v in counts.items()) or "none"


def _unconverged_text(counts: dict) -> str:
    # deferred: keeps `slidespin --help` fast (the parser imports no layer)
    from slidespin.motion.outcomes import LOADED_UNCONVERGED, UNCONVERGED

    unconverged = UNCONVERGED | LOADED_UNCONVERGED
    return _counts_text({k: v for k, v in counts.items() if k in unconverged})


def _read_table(args):
    """The sweep table for sweep-read/sweep-plot, and a note on the cases left out."""
    # deferred: keeps `slidespin --help` fast (the numerical stack is not imported for parsing)
    from slidespin.studies.sweep_read import read_sweep, split_unconverged

    table = read_sweep(args.dir, include_unconverged=True)
    if not table:
        raise ValueError(
            f"{args.dir!r} holds no finished chunk yet; valid: a sweep directory with at "
            "least one finished chunk"
        )
    if args.include_unconverged:
        return table, {}
    return split_unconverged(table)


def _cmd_sweep_read(args) -> int:
    check_output_path(args.csv, "--csv")
    table, left = _read_table(args)
    names = list(table)
    n = len(table[names[0]]) if names else 0
    # streamed to a temporary file renamed into place: whole or nothing, in bounded memory
    parent = os.path.dirname(os.path.abspath(args.csv))
    tmp = os.path.join(parent, f".{os.path.basename(args.csv)}.tmp-{os.getpid()}")
    try:
        with open(tmp, "w", newline="", encoding="utf-8") as fh:
            w = csv.writer(fh, lineterminator="\n")
            w.writerow(names)
            cols = [(table[k], _cell_writer(table[k])) for k in names]
            for i in range(n):
                w.writerow([cell(col[i]) for col, cell in cols])
        os.replace(tmp, args.csv)
    except OSError as exc:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise ValueError(write_failure(exc, args.csv)) from None
    note = ""
    if left:
        note = (
            f"; {sum(left.values())} unconverged cases left out ({_counts_text(left)}): "
            "--include-unconverged keeps them"
        )
    print(f"{n} cases -> {args.csv}{note}")
    return 0


def _cell_writer(column):
    """How the cells of one column are written: floats as ``repr`` (every digit), integers as
    integers, anything else as is."""
    kind = getattr(getattr(column, "dtype", None), "kind", "O")
    if kind == "f":
        return lambda x: repr(float(x))
    if kind in "iu":
        return int
    return lambda x: repr(x) if isinstance(x, float) else x


def _cmd_sweep_plot(args) -> int:
    # deferred: keeps `slidespin --help` fast (the numerical stack is not imported for parsing)
    from slidespin.studies.sweep_read import read_sweep, split_unconverged
    from slidespin.studies.sweep_store import _read_manifest
    from slidespin.viz.sweep_plot import plot_sweep

    default = args.out is None
    out = args.out or os.path.join(DEFAULT_OUT_DIR, "sweep.png")
    out = check_figure_path(out, "--out", create_parent=default)
    table = read_sweep(args.dir, include_unconverged=True)
    if not table:
        raise ValueError(
            f"{args.dir!r} holds no finished chunk yet; valid: a sweep directory with at "
            "least one finished chunk"
        )
    left = {} if args.include_unconverged else split_unconverged(table)[1]
    man = _read_manifest(Path(args.dir)) or {}
    spec = man.get("spec", {}) if isinstance(man.get("spec"), dict) else {}
    varied = list(spec.get("vary", {})) if isinstance(spec.get("vary", {}), dict) else None
    fig = plot_sweep(
        table,
        args.x,
        args.value,
        args.y,
        varied=varied,
        include_unconverged=args.include_unconverged,
        kind=spec.get("kind", "grid"),
    )
    write_outputs([(out, render_figure(fig, out))])
    print(f"figure      : {out}")
    if left:
        print(
            f"left out    : {sum(left.values())} unconverged cases ({_counts_text(left)}); "
            "--include-unconverged keeps them"
        )
    return 0


def _add_outputs(p, default_plot=None) -> None:
    p.add_argument("--json", action="store_true", help="print the stop summary as JSON")
    p.add_argument(
        "--plot",
        metavar="OUT.png",
        default=default_plot,
        help="write a figure of the motion (format from the extension: "
        + ", ".join(FIGURE_FORMATS)
        + ")",
    )
    p.add_argument(
        "--csv",
        metavar="OUT.csv",
        help="write the trajectory as CSV (about 1000 rows; the same with or without --plot)",
    )


def _add_include(p) -> None:
    p.add_argument(
        "--include-unconverged",
        action="store_true",
        help="keep the cases that did not converge (status max_steps, "
        "step_too_small, non_finite: values as reached); left out by default",
    )


class _Parser(argparse.ArgumentParser):
    """argparse with one-line errors (exit status 2), like every other slidespin error:
    ``slidespin: error: MESSAGE`` for the command line as a whole, ``slidespin: error:
    COMMAND: MESSAGE`` for one command's arguments (the program's name is said once)."""

    def error(self, message):
        words = self.prog.split()
        where = f"{' '.join(words[1:])}: " if len(words) > 1 else ""
        print(
            f"slidespin: error: {where}{message} (see '{self.prog} --help')",
            file=sys.stderr,
        )
        sys.exit(2)


class _Commands:
    """The subcommands' parsers by name (to say which command an unknown argument was given
    to: argparse's own message names only the program)."""

    def __init__(self, sub):
        self.sub = sub
        self.parsers: dict[str, argparse.ArgumentParser] = {}

    def add(self, name, **kwargs):
        p = self.sub.add_parser(name, **kwargs)
        self.parsers[name] = p
        return p


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(
        prog="slidespin",
        description="Sliding and spinning of a flat body on a plane under anisotropic dry "
        "friction, on a contact patch of any shape (ellipse, polygon, rectangle, ring, pads).",
    )
    parser.add_argument("--version", action="version", version=f"slidespin {__version__}")
    parser.add_argument("--debug", action="store_true", help="show tracebacks of internal errors")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    sub.required = True
    commands = _Commands(sub)

    p = commands.add("demo", help="simulate the demo case, print the stop, draw a figure")
    _add_outputs(p)
    p.set_defaults(func=_cmd_demo)
    p.epilog = (
        f"The figure goes to {DEFAULT_OUT_DIR}/demo.png unless --plot says otherwise. "
        "Exit status: 0 stopped, 1 not converged, 2 bad input, 3 internal error."
    )

    p = commands.add("simulate", help="simulate a case described in a TOML file")
    p.add_argument("case", metavar="CASE.toml", help="case file (see examples/)")
    _add_outputs(p)
    p.set_defaults(func=_cmd_simulate)

    p = commands.add("sweep", help="run a parameter sweep (locally or on a Dask cluster)")
    p.add_argument(
        "spec", metavar="SPEC.toml", help="sweep specification (see examples/sweep_*.toml)"
    )
    p.add_argument("--out", required=True, metavar="DIR", help="result directory")
    p.add_argument(
        "--scheduler",
        metavar="ADDRESS",
        help="Dask scheduler, e.g. tcp://HOST:8786 (default: local cores)",
    )
    p.add_argument(
        "--workers",
        type=int,
        metavar="N",
        help="start a local Dask cluster with N worker processes",
    )
    p.add_argument("--resume", action="store_true", help="finish an interrupted sweep")
    p.add_argument("--quiet", action="store_true", help="no progress bar, no summary")
    p.set_defaults(func=_cmd_sweep)
    p.epilog = (
        "The summary counts the cases per status and per ending (also in "
        "DIR/manifest.json). Exit status 1 if some cases did not converge "
        "(max_steps, step_too_small, non_finite), 2 on bad input, a busy directory "
        "(DIR/.lock) or a failed write (the sweep can then be finished with --resume). "
        "Run again on its finished DIR, a sweep is checked and reported complete (exit 0, "
        "one line; nothing computed or written)."
    )

    p = commands.add("sweep-read", help="gather a sweep's results into one CSV table")
    p.add_argument("dir", metavar="DIR", help="sweep result directory (from slidespin sweep)")
    p.add_argument("--csv", required=True, metavar="OUT.csv")
    _add_include(p)
    p.set_defaults(func=_cmd_sweep_read)

    p = commands.add("sweep-plot", help="heat map or line plot of a sweep result")
    p.add_argument("dir", metavar="DIR", help="sweep result directory (from slidespin sweep)")
    p.add_argument("--x", required=True, help="input column for the x axis, e.g. fx")
    p.add_argument("--y", help="input column for the y axis (heat map), e.g. I_star")
    p.add_argument(
        "--value",
        default="beta_stop",
        help="result column shown (default beta_stop); ending and status are drawn as categories",
    )
    p.add_argument(
        "--out",
        default=None,
        metavar="OUT.png",
        help=f"figure file (default {DEFAULT_OUT_DIR}/sweep.png; format from the extension)",
    )
    _add_include(p)
    p.set_defaults(func=_cmd_sweep_plot)

    for name, module, help_text in _PLUGINS:
        try:
            mod = importlib.import_module(module)
        except ModuleNotFoundError as exc:
            if exc.name and module.startswith(exc.name):
                continue  # that part of slidespin is not installed in this version
            raise
        p = commands.add(name, help=help_text)
        mod.configure(p)
        p.set_defaults(func=mod.run)
    parser.set_defaults(_commands=commands.parsers)
    return parser


def main(argv=None) -> int:
    """Entry point of the ``slidespin`` command; returns the exit status.

    Run as the command (``argv`` None: the console script, ``python -m slidespin``), the
    objects a command made are frozen for the garbage collector before it returns
    (``gc.freeze``): the interpreter's collection at exit then skips them, which spares
    0.25–0.4 s after matplotlib (measured on 2 shared cores). Nothing is lost: files are
    closed and atexit handlers still run; only cyclic garbage left at exit is not walked.
    """
    if argv is None:
        try:
            return _main(sys.argv[1:])
        finally:
            gc.freeze()
    return _main(list(argv))


def _main(argv: list) -> int:
    debug = "--debug" in argv
    if argv == ["--version"]:  # answered before the parser loads every command's module
        print(f"slidespin {__version__}")
        return 0
    try:
        parser = build_parser()
        try:
            args, extra = parser.parse_known_args(argv)
            if extra:  # named after the command they were given to, not the program
                owner = args._commands.get(args.command, parser)
                owner.error(f"unrecognized arguments: {' '.join(extra)}")
        except SystemExit as exc:  # --help, --version, or a one-line usage error
            return int(exc.code or 0)
        del args._commands
        return int(args.func(args) or 0)
    except ValueError as exc:
        if debug:
            raise
        print(f"slidespin: error: {_one_line(str(exc))}", file=sys.stderr)
        return 2
    except OSError as exc:  # a file operation outside the checked paths (disk full, ...)
        if debug:
            raise
        where = f" ({str(exc.filename)!r})" if exc.filename else ""
        print(f"slidespin: error: {exc.strerror or exc}{where}", file=sys.stderr)
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


def _one_line(text: str) -> str:
    """Messages are one line (a TOML parser may quote a line break)."""
    return " ".join(text.split("\n"))


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
