"""``slidespin reproduce``: the paper's tables and figures, with its errata, in one command.

Usage::

    slidespin reproduce table1  [--fx FX] [--out DIR] [--json] [--format png|pdf|svg]
    slidespin reproduce table2  [--fx FX] [--mu MU] [--out DIR] [--json] [--format ...]
    slidespin reproduce fig2|fig3|fig4 [--fx FX] [--mu MU] [--out DIR] [--format png|pdf|svg]
    slidespin reproduce errata  [--fx FX] [--out DIR] [--json]
    slidespin reproduce phase   [--out DIR] [--format ...]
    slidespin reproduce all     [--out DIR] [--mu MU] [--format ...] [--json]

Tables and errata print to the terminal and, with ``--out``, also write JSON/text (and a
figure for the tables). Figures go to ``--out``; ``all``
writes everything with an ``index.html``. Without ``--out``, figures and ``all`` go to
``./slidespin-out`` (never straight into the working directory); tables only print.
The tables and figures themselves live in :mod:`slidespin.paper` (MODEL §6–7), one module per
target; this module is only the command. It follows the plugin contract of
:mod:`slidespin.cli.main`: ``configure(parser)`` and ``run(args) -> int``.
"""

from __future__ import annotations

import importlib
import math

# nothing heavy at the top: the parser is built from this module (`slidespin --help`); the
# paper's modules (SciPy, matplotlib) are imported by run()

__all__ = ["configure", "run", "TARGETS", "FORMATS"]

#: what ``slidespin reproduce`` takes: one name per table, figure or check, or ``all``
TARGETS = ("table1", "table2", "fig2", "fig3", "fig4", "errata", "phase", "all")
#: figure formats of ``--format`` (those of :data:`slidespin.paper._shared.FORMATS`, which a
#: test keeps equal; spelled here so that the parser does not import the paper's modules)
FORMATS = ("png", "pdf", "svg")

_HELP = {
    "table1": "Table 1: beta of eq. 16, fx inferred, vs printed, and the true terminal states",
    "table2": "Table 2: inertia boundaries (numeric vs printed), a simulation per interval",
    "fig2": "Figure 2: beta(t), theta(t), uniform pressure, with the paths",
    "fig3": "Figure 3: beta(t), theta(t), linear pressure, with the paths",
    "fig4": "Figure 4: F_n(t), linear pressure",
    "errata": "every erratum of the paper, printed vs corrected, with the error it causes",
    "phase": "phase portraits v against a*omega converging on the terminal ratio",
    "all": "everything into one folder with an index.html",
}

# which options each target accepts
_ACCEPTS = {
    "table1": {"fx", "format"},
    "table2": {"fx", "mu", "format"},
    "fig2": {"fx", "mu", "format"},
    "fig3": {"fx", "mu", "format"},
    "fig4": {"fx", "mu", "format"},
    "errata": {"fx"},
    "phase": {"format"},
    "all": {"fx", "mu", "format"},
}


def configure(parser) -> None:
    """Add the arguments of ``slidespin reproduce`` to an argparse (sub)parser."""
    parser.description = (
        "Reproduce the paper's Table 1, Table 2, Figures 2-4 and its errata with slidespin; "
        "'all' writes everything into one folder with an index.html."
    )
    parser.epilog = "targets: " + "; ".join(f"{k}: {h}" for k, h in _HELP.items())
    parser.add_argument(
        "target", choices=TARGETS, metavar="TARGET", help="one of " + ", ".join(TARGETS)
    )
    parser.add_argument(
        "--out",
        metavar="DIR",
        default=None,
        help="output directory (created if missing); figures and 'all' "
        "default to ./slidespin-out, tables only print without it",
    )
    parser.add_argument("--json", action="store_true", help="print the results as JSON")
    parser.add_argument(
        "--fx",
        type=float,
        default=None,
        metavar="FX",
        help="friction coefficient along OX (> 0); default: inferred from Table 1 (table2: 0.3)",
    )
    parser.add_argument(
        "--mu",
        type=float,
        default=None,
        metavar="MU",
        help="anisotropy mu = fy - fx; default 0.12 (figures), 0.15 (table2)",
    )
    parser.add_argument(
        "--format",
        default=None,
        choices=FORMATS,
        dest="format",
        help="figure file format (default png)",
    )
    parser.add_argument(
        "--quiet",
        action="store_true",
        help="no progress bar (the bar is drawn only when stderr is a terminal)",
    )


def _check(args) -> dict:
    # deferred: keeps `slidespin --help` fast (NumPy and the paper's modules load on use)
    from slidespin import _validate as v
    from slidespin.paper import _shared as sh

    target = args.target
    given = {name for name in ("fx", "mu", "format") if getattr(args, name) is not None}
    extra = sorted(given - _ACCEPTS[target])
    if extra:
        ok = sorted(t for t, acc in _ACCEPTS.items() if extra[0] in acc)
        raise ValueError(
            f"--{extra[0]} = {getattr(args, extra[0])!r} does not apply to '{target}'; "
            f"valid for the targets: {', '.join(ok)}; '{target}' takes "
            + (", ".join(f"--{o}" for o in sorted(_ACCEPTS[target])) or "none of them")
        )
    kw = {}
    if args.fx is not None:
        kw["fx"] = v.positive("--fx", args.fx)
    if args.mu is not None:
        mu = v.finite("--mu", args.mu)
        if target == "table2":
            mu = v.in_range("--mu", mu, 0.0, math.inf)
        else:
            fx = kw.get("fx")
            if fx is not None and fx + mu <= 0.0:
                raise ValueError(f"--mu = {mu!r} is invalid; valid range: > -fx = {-fx:g}")
        kw["mu"] = mu
    if args.format is not None:
        kw["fmt"] = args.format
    if args.out is not None:
        sh.prepare_out(args.out)
    return kw


def run(args) -> int:
    """Run ``slidespin reproduce TARGET``; returns the exit status."""
    from slidespin.cli._busy import busy

    kw = _check(args)
    target = args.target
    with busy(f"reproduce {target}", enabled=False if getattr(args, "quiet", False) else None):
        # deferred: keeps `slidespin --help` fast (SciPy, matplotlib load on use)
        module = importlib.import_module(
            "slidespin.paper.report" if target == "all" else f"slidespin.paper.{target}"
        )
        module.main(args.out, as_json=args.json, **kw)
    return 0
