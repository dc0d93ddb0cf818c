"""``slidespin animate CASE.toml --out run.gif``: an animated GIF of a case's motion.

Reads a case file (:func:`slidespin.studies.case.load_case`), simulates it with the same settings as
``slidespin simulate`` (to the stop, or through stick and slip up to ``t_end`` for a case with
``[load]``, ``[incline]`` or ``[solver] t_end``, or pushed along its path for a case with
``[pusher]``, the pusher drawn in every frame) and writes the GIF of
:func:`slidespin.viz.animate.animate`.
The output path, its format (``.gif``), ``--fps`` and ``--frames`` are checked before the case
is read or anything is computed. Plugin of :mod:`slidespin.cli.main` (``configure(parser)``,
``run(args)``).
"""

from __future__ import annotations

import os

from slidespin._io import check_output_path
from slidespin.cli.main import CLI_MAX_STEP, DEFAULT_OUT_DIR, _exit_status, _loaded_exit_status

# nothing heavy at the top: the parser is built from this module (`slidespin --help`); the
# figure stack (NumPy, matplotlib, Pillow) is imported by run()

__all__ = ["configure", "run", "MAX_FPS", "MAX_FRAMES"]

#: the bounds of ``--fps`` and ``--frames``: those of :mod:`slidespin.viz.animate` (a test keeps
#: them equal; spelled here so that the parser does not import the figure stack)
MAX_FPS = 50
MAX_FRAMES = 120


def configure(parser) -> None:
    """Add the arguments of ``slidespin animate`` to an argparse (sub)parser."""
    parser.description = (
        "Simulate a case file and write an animated GIF of the body sliding and turning, "
        "with the velocity of G and the instantaneous centre of rotation (Pillow; no ffmpeg)."
    )
    parser.add_argument("case", metavar="CASE.toml", help="case file (examples/*.toml)")
    parser.add_argument(
        "--out",
        metavar="OUT.gif",
        default=None,
        help="GIF to write (default slidespin-out/<case>.gif)",
    )
    parser.add_argument(
        "--fps",
        type=int,
        default=20,
        metavar="N",
        help=f"frames per second, 1 to {MAX_FPS} (default 20)",
    )
    parser.add_argument(
        "--frames",
        type=int,
        default=60,
        metavar="N",
        help=f"number of frames, evenly spaced in time, 2 to {MAX_FRAMES} (default 60)",
    )


def run(args) -> int:
    """Check the outputs, simulate, draw and write; returns the exit status."""
    default = args.out is None
    out = args.out
    if default:
        stem = os.path.splitext(os.path.basename(args.case))[0] or "animation"
        out = os.path.join(DEFAULT_OUT_DIR, stem + ".gif")
    if not out.lower().endswith(".gif"):
        raise ValueError(
            f"--out = {out!r}: unknown animation format "
            f"{os.path.splitext(out)[1] or '(no extension)'!r}; valid extension: .gif"
        )
    out = check_output_path(out, "--out", create_parent=default)
    # deferred: keeps `slidespin --help` fast (the numerical stack is not imported for parsing)
    from slidespin.motion.simulate import simulate
    from slidespin.studies.case import load_case
    from slidespin.viz.animate import _check_int, animate

    _check_int("--fps", args.fps, 1, MAX_FPS)
    _check_int("--frames", args.frames, 2, MAX_FRAMES)

    case = load_case(args.case)
    pushed = getattr(case, "pusher", None) is not None
    if pushed:
        # [pusher]: the pushed dynamics, as `slidespin simulate` runs it
        from slidespin.cli._pushed import exit_status, simulate_case

        traj = simulate_case(case)
        status = exit_status(traj.status)
    elif getattr(case, "loaded", False):
        # [load], [incline] or t_end: the stick-slip engine, as `slidespin simulate` runs it
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
        status = _loaded_exit_status(traj.status)
    else:
        traj = simulate(
            case.body,
            case.friction,
            case.initial_state,
            g=case.g,
            rtol=case.rtol,
            max_steps=case.max_steps,
            max_step=CLI_MAX_STEP,
        )
        status = _exit_status(traj.status)
    if default:
        os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    animate(traj, out, fps=args.fps, frames=args.frames, title=case.name or None)
    print(f"case        : {case.name or args.case}")
    if pushed:
        print(f"status      : {traj.status}  (pushed to t = {float(traj.t[-1]):.6g} s)")
    else:
        print(f"status      : {traj.status}  (ending {traj.ending}, t_stop {traj.t_stop:.6g} s)")
    print(
        f"animation   : {out}  ({args.frames} frames at {args.fps} fps, "
        f"{os.path.getsize(out) / 1024:.0f} KiB)"
    )
    return status
