"""``slidespin limit-surface CASE.toml``: the limit surface of a case's body (MODEL §11).

Reads the body (an ellipse, a circle or any footprint of ``[patch]``), friction tensor, body
angle (``[initial] phi``), g and tilt (``[incline]``: the normal load m g cos α; a ``[load]``
plays no part and is ignored) of a case file, samples the limit surface
(:func:`slidespin.contact.limit_surface.limit_surface`), prints the fits and their errors, and
optionally writes JSON, npz and a 3-D figure. Plugin of :mod:`slidespin.cli.main`
(``configure(parser)``, ``run(args)``).
"""

from __future__ import annotations

import io
import json
import os

import numpy as np

from slidespin._io import check_figure_path, check_output_path, write_outputs

__all__ = ["configure", "run"]


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
    from slidespin.contact.limit_surface import limit_surface
    from slidespin.studies.case import load_case

    if isinstance(args.n, bool) or args.n < 10:
        raise ValueError(f"--n = {args.n!r} is invalid; valid range: integer >= 10")
    plot = check_figure_path(args.plot, "--plot") if args.plot else None
    npz = check_output_path(args.npz, "--npz") if args.npz else None
    if npz and not npz.endswith(".npz"):
        raise ValueError(f"--npz = {npz!r} is invalid; valid values: a path ending in .npz")
    case = load_case(args.case)
    ls = limit_surface(
        case.body,
        case.friction,
        n=args.n,
        phi=case.initial_state.phi,
        g=case.g,
        length=args.length,
        incline=case.incline,
    )
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
        print(ls.to_json(samples=args.samples))
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
    write_outputs(files)
    for path, _ in files:
        if not args.json:
            print(f"wrote              : {path}")
    return 0
