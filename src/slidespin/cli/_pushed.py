"""``slidespin simulate`` (and ``animate``) on a case with a ``[pusher]`` (MODEL §13).

The run is :func:`slidespin.simulate` with ``pusher=`` and ``t_end=`` (through
:func:`slidespin.simulate_pushed` when the case gives ``[pusher] outline``, which ``simulate``
does not take), with the case's loads, tilt and solver settings. Outputs: a summary (status,
final pose, the contact modes in time, the work of the pusher and the energy balance), the
same as JSON (``--json``), the recorded rows as CSV (``--csv``: :data:`CSV_COLUMNS`) and the
figure of :func:`slidespin.viz.push_plot.plot_pushed_trajectory` (``--plot``).

Exit status: 0 when the run reached ``t_end`` (status ``ok``), 1 when it ended early (any
other status of :data:`slidespin.motion.outcomes.PUSHED_STATUSES`), 2 on bad input.
"""

from __future__ import annotations

import csv
import io
import json
import math
import sys

from slidespin._io import render_figure, write_outputs

__all__ = ["CSV_COLUMNS", "pushed_csv", "pushed_summary", "run_pushed_case", "simulate_case"]

#: columns of ``--csv`` for a pushed run (SI units; the names of
#: :class:`~slidespin.motion.pushed_trajectory.PushedTrajectory`, a pair split into _x, _y);
#: a line pusher adds ``pusher_angle`` [rad] after ``pusher_position_y``. A contact point is
#: an empty cell while the pusher is separated.
CSV_COLUMNS = (
    "t",
    "x",
    "y",
    "phi",
    "vx",
    "vy",
    "omega",
    "mode",
    "pusher_position_x",
    "pusher_position_y",
    "pusher_force_x",
    "pusher_force_y",
    "contact_point_x",
    "contact_point_y",
    "kinetic_energy",
    "pusher_work",
    "friction_work",
    "contact_slip_work",
    "load_work",
    "impact_loss",
)


def simulate_case(case):
    """Run a pushed case (``case.pusher`` set): the :class:`PushedTrajectory` of its run."""
    # deferred: keeps `slidespin --help` fast (the numerical stack is not imported for parsing)
    from slidespin.motion.simulate import simulate

    if case.outline is not None:
        from slidespin.motion.pushed import simulate_pushed

        return simulate_pushed(
            case.body,
            case.friction,
            case.initial_state,
            case.pusher,
            case.t_end,
            g=case.g,
            rtol=case.rtol,
            max_steps=case.max_steps,
            load=case.load,
            incline=case.incline,
            outline=case.outline,
        )
    return simulate(
        case.body,
        case.friction,
        case.initial_state,
        g=case.g,
        rtol=case.rtol,
        max_steps=case.max_steps,
        load=case.load,
        incline=case.incline,
        t_end=case.t_end,
        pusher=case.pusher,
    )


def _phases(traj) -> list[tuple[str, float, float]]:
    """(mode, t0, t1) intervals of a pushed run."""
    if hasattr(traj, "phases"):
        return list(traj.phases())
    out: list[tuple[str, float, float]] = []
    for t, mode in zip(traj.t, traj.mode):
        if out and out[-1][0] == mode:
            out[-1] = (mode, out[-1][1], float(t))
        else:
            if out:
                out[-1] = (out[-1][0], out[-1][1], float(t))
            out.append((mode, float(t), float(t)))
    return [p for p in out if p[2] > p[1] or len(out) == 1]


def pushed_summary(case, traj) -> dict:
    """The run's outcome as a JSON-ready dict: ``PushedTrajectory.summary()`` with the final
    velocities, the pusher (kind, μp), the relative energy error and the modes in time."""
    out = dict(traj.summary())
    f = traj.final_state

    def num(x):
        x = float(x)
        return x if math.isfinite(x) else None

    out.update(
        {
            "vx_final": num(f.vx),
            "vy_final": num(f.vy),
            "omega_final": num(f.omega),
            "pusher_kind": "line" if hasattr(case.pusher, "length") else "point",
            "pusher_mu": case.pusher.mu,
            "relative_energy_error": num(traj.relative_energy_error),
            "phases": [[m, a, b] for m, a, b in _phases(traj)],
            "mode_switches": [[t, m0, m1] for t, m0, m1 in traj.switches],
        }
    )
    return out


def pushed_csv(traj) -> str:
    """The recorded rows as CSV (:data:`CSV_COLUMNS`), every digit of every float."""
    import numpy as np

    line = hasattr(traj.pusher, "length")
    cols = list(CSV_COLUMNS)
    if line:
        cols.insert(cols.index("pusher_position_y") + 1, "pusher_angle")
    data = {
        "t": traj.t,
        "x": traj.x,
        "y": traj.y,
        "phi": traj.phi,
        "vx": traj.vx,
        "vy": traj.vy,
        "omega": traj.omega,
        "mode": traj.mode,
        "pusher_position_x": traj.pusher_position[:, 0],
        "pusher_position_y": traj.pusher_position[:, 1],
        "pusher_force_x": traj.pusher_force[:, 0],
        "pusher_force_y": traj.pusher_force[:, 1],
        "contact_point_x": traj.contact_point[:, 0],
        "contact_point_y": traj.contact_point[:, 1],
        "kinetic_energy": traj.kinetic_energy,
        "pusher_work": traj.pusher_work,
        "friction_work": traj.friction_work,
        "contact_slip_work": traj.contact_slip_work,
        "load_work": traj.load_work,
        "impact_loss": traj.impact_loss,
    }
    if line:
        data["pusher_angle"] = np.asarray(traj.pusher.pose(np.asarray(traj.t)))[:, 2]

    def cell(x):
        if isinstance(x, str):
            return x
        x = float(x)
        return repr(x) if math.isfinite(x) else ""

    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(cols)
    for row in zip(*(data[c] for c in cols)):
        w.writerow([cell(x) for x in row])
    return buf.getvalue()


def _print_summary(case, traj, s: dict, out) -> None:
    p = case.pusher
    kind = s["pusher_kind"]
    what = f"{kind}, mu = {p.mu:g}" + (f", length {p.length:g} m" if kind == "line" else "")
    t0, t1 = p.duration
    lines = [
        f"case        : {case.name or '(unnamed)'}",
        f"pusher      : {what}, {p.path.shape[0]} waypoints over [{t0:g}, {t1:g}] s",
        f"status      : {s['status']}" + ("" if s["status"] == "ok" else f"  ({s['message']})"),
        f"end time    : {s['t_final']:.10g} s",
        f"position    : x = {s['x_final']:.6g} m, y = {s['y_final']:.6g} m, "
        f"phi = {s['phi_final']:.6g} rad",
        f"velocity    : vx = {s['vx_final']:.6g} m/s, vy = {s['vy_final']:.6g} m/s, "
        f"omega = {s['omega_final']:.6g} rad/s",
        f"modes       : {_modes_text(s['phases'])}",
        f"switches    : {s['switches']}, impacts: {s['impacts']}",
        f"pusher work : {s['pusher_work']:.6g} J  (plane friction {s['friction_work']:.6g} J, "
        f"contact slip {s['contact_slip_work']:.6g} J, impacts {s['impact_loss']:.6g} J)",
        f"energy error: {s['energy_error']:.3g} J  ({s['relative_energy_error']:.3g} of the "
        "largest term)",
    ]
    print("\n".join(lines), file=out)


def _modes_text(phases, limit: int = 10) -> str:
    """One phase a line (the first ``limit``), ``mode  t0 - t1 s``."""
    parts = [f"{m:<21s}{a:.6g} - {b:.6g} s" for m, a, b in phases[:limit]]
    if len(phases) > limit:
        parts.append(f"... ({len(phases)} phases; all in --json)")
    return "\n              ".join(parts) or "none"


def exit_status(status: str) -> int:
    """0 for a pushed run that reached ``t_end``, 1 for one that ended early."""
    return 0 if status == "ok" else 1


def run_pushed_case(case, args) -> int:
    """``slidespin simulate`` on a pushed case (outputs checked by the caller)."""
    traj = simulate_case(case)
    summary = pushed_summary(case, traj)
    files = []
    if args.csv:
        files.append((args.csv, pushed_csv(traj).encode("utf-8")))
    if args.plot:
        # deferred: matplotlib only when a figure is asked for
        from slidespin.viz.push_plot import plot_pushed_trajectory

        fig = plot_pushed_trajectory(traj, outline=case.outline, title=case.name or None)
        files.append((args.plot, render_figure(fig, args.plot)))
    write_outputs(files)
    if args.json:
        print(json.dumps(summary, indent=2))
    else:
        _print_summary(case, traj, summary, sys.stdout)
        if args.csv:
            print(f"trajectory  : {args.csv}  ({traj.t.size} rows)")
        if args.plot:
            print(f"figure      : {args.plot}")
    return exit_status(traj.status)
