"""``slidespin aim CASE.toml --target x,y[,phi]``: the launch that stops at a target (MODEL §15).

Reads the body, friction tensor, g and tolerance of a case file, its ``[load]``,
``[spring]``, ``[incline]`` and ``[solver] t_end`` (the stop is then where the body first
sticks, or where it rests at ``t_end``), and its ``[initial]`` table as the launch position
and angle, the velocities that stay fixed and (if not zero) the first guess of the free ones;
prints the launch found by :func:`slidespin.aim` (``--json``: as JSON), or exits with status
1 and the nearest reachable stop when the target cannot be reached. What aiming cannot use
is refused, never ignored (:data:`UNUSED`): ``[pusher]`` (a pushed body's motion is the
pusher's, not a launch's). Plugin of :mod:`slidespin.cli.main` (``configure(parser)``,
``run(args)``).
"""

from __future__ import annotations

import json

# nothing heavy at the top: the parser is built from this module (`slidespin --help`)

__all__ = ["configure", "run", "UNUSED"]

#: what a case file may give that ``slidespin aim`` cannot honour (refused)
UNUSED = (
    ("pusher", None, "aiming solves for a launch; a pushed body moves as the pusher drives it"),
)


def configure(parser) -> None:
    """Add the arguments of ``slidespin aim`` to an argparse (sub)parser."""
    parser.description = (
        "Find the launch velocities (vx, vy, omega, or a subset) with which the body of a case "
        "file stops at a target pose (MODEL §15)."
    )
    parser.add_argument("case", metavar="CASE.toml", help="case file (examples/*.toml)")
    parser.add_argument(
        "--target",
        required=True,
        metavar="X,Y[,PHI]",
        help="where G must stop [m] and the body's total angle there [rad], e.g. 1.0,0.5,2.0 "
        "(a value starting with '-' needs '=': --target=-1.0,0.5)",
    )
    parser.add_argument(
        "--free",
        default="vx,vy,omega",
        metavar="NAMES",
        help="the launch components to solve for (default vx,vy,omega; the velocity may be "
        "given as speed,direction instead of vx,vy); the others are the case's [initial] values",
    )
    parser.add_argument(
        "--tol", type=float, default=1e-10, help="largest miss in m and rad (default 1e-10)"
    )
    parser.add_argument("--json", action="store_true", help="print the result as JSON")


def run(args) -> int:
    """Aim, print; returns the exit status (1 for an unreachable target)."""
    # deferred: keeps `slidespin --help` fast (the numerical stack is not imported for parsing)
    from slidespin.analysis.aim import AIM_FREE, UnreachableTarget, aim, check_target
    from slidespin.motion.loaded_trajectory import LoadedTrajectory
    from slidespin.motion.simulate import simulate
    from slidespin.motion.state import State
    from slidespin.motion.trajectory import Trajectory
    from slidespin.studies.case import read_case, refuse_unused

    try:
        target = check_target(args.target.split(","))
    except ValueError:
        raise ValueError(
            f"--target = {args.target!r} is invalid; valid values: x,y or x,y,phi (finite "
            "numbers, m and rad), e.g. 1.0,0.5,2.0"
        ) from None
    free = tuple(x.strip() for x in args.free.split(",") if x.strip())
    if not free or len(set(free)) != len(free) or not all(n in AIM_FREE for n in free):
        raise ValueError(
            f"--free = {args.free!r} is invalid; valid values: distinct names among "
            f"{','.join(AIM_FREE)}, comma-separated (e.g. vx,vy)"
        )
    case, data = read_case(args.case, initial_required=False)
    refuse_unused(args.case, data, "slidespin aim", UNUSED)
    try:
        start = aim(case.body, case.friction, target, start=case.initial_state, free=free,
                    g=case.g, rtol=case.rtol, tol=args.tol, load=case.load,
                    incline=case.incline, t_end=case.t_end)  # fmt: skip
    except UnreachableTarget as exc:
        if args.json:
            n, s = exc.nearest, exc.start
            print(json.dumps({
                "reachable": False, "message": str(exc), "target": list(target),
                "free": list(free), "miss": exc.miss,
                "position_miss": exc.position_miss, "angle_miss": exc.angle_miss,
                "nearest": {"x": n.x, "y": n.y, "phi": n.phi},
                "launch": {"vx": s.vx, "vy": s.vy, "omega": s.omega},
            }, indent=2))  # fmt: skip
        else:
            print(f"unreachable        : {exc}")
        return 1
    tr = simulate(case.body, case.friction, start, case.g, case.rtol, load=case.load,
                  incline=case.incline, t_end=case.t_end)  # fmt: skip
    if isinstance(tr, LoadedTrajectory):  # at rest where it first sticks (or at t_end)
        stop = State(x=float(tr.x[-1]), y=float(tr.y[-1]), phi=float(tr.phi[-1]))
        last = tr.phases[-1] if tr.phases else ("slip", 0.0, 0.0)
        t_stop = last[1] if last[0] == "stick" else float(tr.t[-1])
    elif isinstance(tr, Trajectory):
        stop, t_stop = tr.stop_state, tr.t_stop
    else:  # pragma: no cover - a [pusher] is refused above
        raise RuntimeError(f"slidespin aim: unexpected {type(tr).__name__}")
    if args.json:
        print(json.dumps({
            "reachable": True, "target": list(target), "free": list(free),
            "launch": {"x": start.x, "y": start.y, "phi": start.phi, "vx": start.vx,
                       "vy": start.vy, "omega": start.omega},
            "stop": {"t_stop": t_stop, "x": stop.x, "y": stop.y, "phi": stop.phi},
        }, indent=2))  # fmt: skip
        return 0
    print(f"case               : {case.name or args.case}")
    print(f"target             : {', '.join(f'{x:.10g}' for x in target)}")
    print(f"launch             : vx = {start.vx:.12g} m/s, vy = {start.vy:.12g} m/s, "
          f"omega = {start.omega:.12g} rad/s (free: {', '.join(free)})")  # fmt: skip
    print(f"stops              : x = {stop.x:.12g} m, y = {stop.y:.12g} m, phi = "
          f"{stop.phi:.12g} rad at t = {t_stop:.10g} s")  # fmt: skip
    return 0
