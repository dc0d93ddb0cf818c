"""``slidespin limit-surface CASE.toml``: the limit surface of a case's body (MODEL §11).

Reads the body (an ellipse, a circle or any footprint of ``[patch]``), friction tensor, body
angle (``[initial] phi0``), g and tilt (``[incline]``: the normal load m g cos α) of a case
file, samples the limit surface (:func:`slidespin.contact.limit_surface.limit_surface`), prints
the fits and their errors, and optionally writes JSON, npz and a 3-D figure. The case's start
velocities (``[initial] v0``, ``theta0``, ``omega0`` or ``vx0``, ``vy0``), if not all zero, give
the start twist: its friction wrench, the point of the surface the motion starts at, is
printed (JSON ``start``). What the limit surface cannot use is refused, never ignored
(:data:`UNUSED`): ``[load]``, ``[solver] t_end``, ``rtol``, ``max_steps`` and ``[initial] x0``,
``y0``. Plugin of :mod:`slidespin.cli.main` (``configure(parser)``, ``run(args)``).
"""

from __future__ import annotations

import io
import json
import math
import os

from slidespin._io import check_figure_path, check_output_path, write_outputs

# nothing heavy at the top: the parser is built from this module (`slidespin --help`)

__all__ = ["configure", "run", "UNUSED"]

_NO_MOTION = "the limit surface is a property of the contact; it integrates no motion"
#: what a case file may give that ``slidespin limit-surface`` cannot honour (refused)
UNUSED = (
    (
        "pusher",
        None,
        "the limit surface is the friction's alone; slidespin simulate runs a pushed case",
    ),
    (
        "load",
        None,
        "the limit surface is the friction's alone; slidespin simulate runs a loaded case",
    ),
    ("solver", ("t_end", "rtol", "max_steps"), _NO_MOTION),
    (
        "initial",
        ("x0", "y0"),
        "the limit surface does not depend on where the body is (phi0 and the start "
        "velocities are used)",
    ),
)


def configure(parser) -> None:
    """Add the arguments of ``slidespin limit-surface`` to an argparse (sub)parser."""
    parser.description = (
        "Sample the limit surface (friction wrenches of all motion directions) of the body "
        "of a case file and fit an ellipsoid and a convex quartic (MODEL §11)."
    )
    parser.add_argument("case", metavar="CASE.toml", help="case file (examples/*.toml)")
    parser.add_argument(
        "--n",
        type=int,
        default=400,
        metavar="N",
        help="number of twist directions (default 400, at least 10)",
    )
    parser.add_argument(
        "--length",
        type=float,
        default=None,
        metavar="L",
        help="length scale ℓ [m] of the twist (vx, vy, ℓω); default √(I/m)",
    )
    parser.add_argument(
        "--json",
        action="store_true",
        help="print the fits (and with --samples the samples) as JSON",
    )
    parser.add_argument(
        "--samples", action="store_true", help="with --json, include every sampled twist and wrench"
    )
    parser.add_argument("--npz", metavar="OUT.npz", default=None, help="write all arrays")
    parser.add_argument("--plot", metavar="OUT.png", default=None, help="write a 3-D figure")


def run(args) -> int:
    """Compute, print and write; returns the exit status."""
    # deferred: keeps `slidespin --help` fast (the numerical stack is not imported for parsing)
    import numpy as np

    from slidespin.contact.limit_surface import MAX_DIRECTIONS, limit_surface
    from slidespin.studies.case import read_case, refuse_unused

    if isinstance(args.n, bool) or not 10 <= args.n <= MAX_DIRECTIONS:
        raise ValueError(
            f"--n = {args.n!r} is invalid; valid range: integer in [10, {MAX_DIRECTIONS}]"
        )
    plot = check_figure_path(args.plot, "--plot") if args.plot else None
    npz = check_output_path(args.npz, "--npz") if args.npz else None
    if npz and not npz.endswith(".npz"):
        raise ValueError(f"--npz = {npz!r} is invalid; valid values: a path ending in .npz")
    if args.samples and not args.json:
        raise ValueError(
            "--samples is for --json (it adds the samples to the JSON); valid: "
            "--json --samples, or neither"
        )
    case, data = read_case(args.case)
    refuse_unused(args.case, data, "slidespin limit-surface", UNUSED)
    ls = limit_surface(
        case.body,
        case.friction,
        n=args.n,
        phi=case.initial_state.phi,
        g=case.g,
        length=args.length,
        incline=case.incline,
    )
    start = _start(case, ls)
    files = []
    if npz:
        buf = io.BytesIO()
        np.savez(buf, **ls.arrays())
        files.append((npz, buf.getvalue()))
    if plot:
        import matplotlib  # lazy: matplotlib is needed only for --plot

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        ax = ls.plot()
        buf = io.BytesIO()
        ax.figure.savefig(buf, format=os.path.splitext(plot)[1].lstrip(".").lower(), dpi=150)
        plt.close(ax.figure)
        files.append((plot, buf.getvalue()))
    if args.json:
        doc = json.loads(ls.to_json(samples=args.samples))
        doc["start"] = start
        print(json.dumps(doc, indent=2))
    else:
        s = ls.summary()
        print(f"case               : {case.name or args.case}")
        print(
            f"samples            : {s['n']} twist directions, ℓ = {s['length']:.6g} m, "
            f"P = {s['normal_load']:.6g} N"
        )
        print(f"largest force      : {s['max_force']:.10g} N")
        print(f"largest moment     : {s['max_moment']:.10g} N m")
        print(
            f"ellipsoid fit      : radial error {s['ellipsoid_error']:.3e}, normal error "
            f"{s['ellipsoid_normal_error']:.3e} rad"
        )
        print(
            f"convex quartic fit : radial error {s['quartic_error']:.3e}, normal error "
            f"{s['quartic_normal_error']:.3e} rad"
        )
        print(
            f"dissipation gap    : {s['max_dissipation_gap']:.3e} W per m/s "
            "(0: maximum dissipation, the twist is normal to the surface)"
        )
        print(
            "ellipsoid matrix A : "
            + json.dumps([[round(x, 10) for x in r] for r in s["ellipsoid"]])
        )
        if start is None:
            print("start twist        : none (the case starts at rest)")
        else:
            tw, w = start["twist"], start["wrench"]
            print(
                f"start twist        : (vx, vy, ℓω)/|.| = ({tw[0]:.6g}, {tw[1]:.6g}, "
                f"{tw[2]:.6g}); its friction wrench (Fx, Fy, M) = ({w[0]:.10g} N, "
                f"{w[1]:.10g} N, {w[2]:.10g} N m)"
            )
    write_outputs(files)
    for path, _ in files:
        if not args.json:
            print(f"wrote              : {path}")
    return 0


def _start(case, ls):
    """The case's start twist (unit, (vx, vy, ℓω)) and its friction wrench [N, N, N m]
    (scaled to the surface's normal load), or ``None`` for a case that starts at rest."""
    # deferred: keeps `slidespin --help` fast (the numerical stack is not imported for parsing)
    from slidespin.contact.wrench import friction_wrench

    st = case.initial_state
    ell = ls.length
    norm = math.sqrt(st.vx**2 + st.vy**2 + (ell * st.omega) ** 2)
    if norm == 0.0:
        return None
    w = friction_wrench(case.body, case.friction, st.vx, st.vy, st.omega, st.phi, case.g)
    scale = ls.normal_load / (case.body.mass * case.g)  # cos α on an incline
    return {
        "twist": [st.vx / norm, st.vy / norm, ell * st.omega / norm],
        "wrench": [float(w.force_x) * scale, float(w.force_y) * scale, float(w.moment) * scale],
    }
