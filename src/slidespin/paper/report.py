"""Everything at once: every table, figure and erratum into one folder with an ``index.html``.

``slidespin reproduce all --out DIR`` calls :func:`main`. The page embeds every table as HTML
and every figure by a relative link to the PNG next to it, so the folder can be moved, zipped
or opened offline. Each reproduction also leaves its numbers as JSON and text beside it.
"""

from __future__ import annotations

import html
import json
import math
import os
import platform
import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

from slidespin._version import __version__
from slidespin.paper import _shared as sh
from slidespin.paper import errata, fig2, fig3, fig4, phase, table1, table2
from slidespin.paper._figures import FigureRuns

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["Report", "compute", "write_html", "main"]


@dataclass(frozen=True)
class Report:
    """All reproductions (results of each module's ``compute``)."""

    table1: table1.Table1Result
    table2: table2.Table2Result
    fig2: FigureRuns
    fig3: FigureRuns
    fig4: FigureRuns
    errata: errata.ErrataResult
    phase: phase.PhaseResult
    mu: float
    seconds: float

    def as_dict(self) -> dict:
        """The numbers as plain data (JSON-ready)."""
        return {
            name: getattr(self, name).as_dict()
            for name in ("table1", "table2", "fig2", "fig3", "fig4", "errata", "phase")
        }


def compute(
    mu: float = 0.12, table2_fx: float = 0.3, table2_mu: float = 0.15, fx: float | None = None
) -> Report:
    """Run every reproduction (about 30 s)."""
    t0 = time.perf_counter()
    t1 = table1.compute()
    fx_fig = t1.fx if fx is None else fx
    f2 = fig2.compute(mu=mu, fx=fx_fig)
    f3 = fig3.compute(mu=mu, fx=fx_fig)
    f4 = fig4.compute(mu=mu, fx=fx_fig)
    t2 = table2.compute(table2_fx, table2_mu)
    er = errata.compute(fx_fig)
    ph = phase.compute()
    return Report(t1, t2, f2, f3, f4, er, ph, mu, time.perf_counter() - t0)


# ------------------------------------------------------------------------------------------
# HTML
# ------------------------------------------------------------------------------------------
_CSS = """
body { font-family: -apple-system, "Segoe UI", Helvetica, Arial, sans-serif; max-width: 1020px;
       margin: 2em auto; padding: 0 1em; color: #222; line-height: 1.45; }
h1 { font-size: 1.5em; } h2 { font-size: 1.2em; margin-top: 2em; border-bottom: 1px solid #ccc; }
table { border-collapse: collapse; margin: 0.8em 0; font-size: 0.86em; }
th, td { border: 1px solid #ccc; padding: 2px 7px; text-align: right; }
th { background: #f3f3f3; } td.l, th.l { text-align: left; }
td.bad { background: #fde2e2; } td.ok { background: #e6f4e6; }
img { max-width: 100%; border: 1px solid #eee; }
figure { margin: 1em 0; } figcaption { font-size: 0.9em; color: #444; }
code { background: #f5f5f5; padding: 0 3px; } .small { font-size: 0.85em; color: #555; }
nav a { margin-right: 1em; }
"""


def _e(x) -> str:
    return html.escape(str(x))


def _f(x, nd=4):
    x = float(x)
    if math.isnan(x):
        return "–"
    if math.isinf(x):
        return "∞" if x > 0 else "−∞"
    return f"{x:.{nd}f}"


def _figure(src, caption):
    return (
        f'<figure><a href="{_e(src)}"><img src="{_e(src)}" alt="{_e(caption)}"></a>'
        f"<figcaption>{caption}</figcaption></figure>"
    )


def _table1_html(res) -> str:
    mus = table1.MU
    rows = [
        "<table><tr><th class=l>φ</th><th class=l></th>"
        + "".join(f"<th>μ = {m:.2f}</th>" for m in mus)
        + "</tr>"
    ]
    for i, lab in enumerate(table1.PHI_LABELS):
        cells = res.cells[9 * i : 9 * i + 9]
        rows.append(
            f"<tr><td class=l rowspan=5>{lab}</td><td class=l>ours (eq. 16)</td>"
            + "".join(f"<td>{c.beta:.4f}</td>" for c in cells)
            + "</tr>"
        )
        rows.append(
            "<tr><td class=l>printed</td>"
            + "".join(f"<td>{c.paper:.3f}</td>" for c in cells)
            + "</tr>"
        )
        rows.append(
            "<tr><td class=l>diff [10⁻³]</td>"
            + "".join(
                f"<td class={'ok' if c.matches else 'bad'}>{c.diff * 1e3:+.2f}</td>" for c in cells
            )
            + "</tr>"
        )
        rows.append(
            "<tr><td class=l>true β*</td>"
            + "".join(f"<td>{_f(c.true_beta)}</td>" for c in cells)
            + "</tr>"
        )
        rows.append(
            "<tr><td class=l>true ϑ* [rad]</td>"
            + "".join(f"<td>{_f(c.true_theta + 0.0)}</td>" for c in cells)
            + "</tr>"
        )
    rows.append("</table>")
    return "\n".join(rows)


def _table2_html(res) -> str:
    out = []
    for mu in sorted({r.mu for r in res.rows}):
        sub = [r for r in res.rows if r.mu == mu]
        title = "μ = 0 (isotropic)" if mu == 0 else f"fx = {sub[0].fx:g}, μ = {mu:g}"
        out.append(
            f"<p><b>{title}</b></p><table><tr><th class=l>law</th><th>boundary</th>"
            "<th>numeric J(β)</th><th>printed formula</th><th>|diff|</th></tr>"
        )
        for r in sub:
            for j, name in enumerate(("I₁ = J(∞)", "I₂ = J(1)", "I₃ = J(0⁺)")):
                law = f"<td class=l rowspan=3>{r.law}</td>" if j == 0 else ""
                out.append(
                    f"<tr>{law}<td>{name}</td><td>{r.numeric[j]:.12f}</td>"
                    f"<td>{r.printed[j]:.12f}</td>"
                    f"<td>{abs(r.numeric[j] - r.printed[j]):.1e}</td></tr>"
                )
        out.append("</table>")
    out.append(
        "<p><b>One simulation inside each interval</b> (circle, v₀ = aω₀, ϑ₀ = π/4):</p>"
        "<table><tr><th class=l>law</th><th>μ</th><th>row</th><th>I*</th>"
        "<th class=l>stated ending</th><th class=l>simulated ending</th>"
        "<th>k = β*/a</th><th>J⁻¹(I*)</th></tr>"
    )
    for r in res.runs:
        cls = "ok" if r.agrees else "bad"
        out.append(
            f"<tr><td class=l>{r.law}</td><td>{r.mu:g}</td><td>{r.regime}</td>"
            f"<td>{r.inertia_ratio:.4f}</td><td class=l>{r.expected}</td>"
            f"<td class='l {cls}'>{r.observed}</td><td>{_f(abs(r.k), 6)}</td>"
            f"<td>{_f(r.k_theory, 6)}</td></tr>"
        )
    out.append("</table>")
    return "\n".join(out)


def _runs_html(res) -> str:
    rows = [
        "<table><tr><th>φ₀</th><th>t_stop / √(aπ/g)</th><th>β*/a</th><th>ϑ* [rad]</th>"
        "<th>φ at the stop [rad]</th><th>F_n/(mg) at the stop</th><th class=l>ending</th>"
        "</tr>"
    ]
    for r in res.summary():
        rows.append(
            f"<tr><td>{r['phi0_label']}</td><td>{r['t_stop']:.5f}</td>"
            f"<td>{_f(float(r['beta_stop']))}</td>"
            f"<td>{float(r['theta_stop']):+.4f}</td><td>{r['phi_stop']:.4f}</td>"
            f"<td>{r['normal_stop']:.1e}</td><td class=l>{r['ending']}</td></tr>"
        )
    rows.append("</table>")
    return "\n".join(rows)


def _errata_html(res) -> str:
    out = [
        "<table><tr><th>#</th><th class=l>where</th><th class=l>printed → corrected</th>"
        "<th class=l>measure</th><th class=l>printed gives</th>"
        "<th class=l>corrected gives</th><th class=l>effect</th></tr>"
    ]
    for e in res.errata:
        check = f"<br><span class=small>check: {_e(e.check)}</span>" if e.check else ""
        out.append(
            f"<tr><td>{e.number}</td><td class=l>{_e(e.where)}</td>"
            f"<td class=l><code>{_e(e.printed)}</code><br>→ <code>{_e(e.corrected)}</code></td>"
            f"<td class=l>{_e(e.measure)}</td><td class=l>{_e(e.printed_value)}</td>"
            f"<td class=l>{_e(e.corrected_value)}</td><td class=l>{_e(e.effect)}{check}</td></tr>"
        )
    out.append("</table>")
    return "\n".join(out)


def write_html(rep: Report, out: str) -> str:
    """Write ``out/index.html`` for a :class:`Report` whose figures are already in ``out``."""
    t1 = rep.table1
    lo, hi = t1.best_interval or (math.nan, math.nan)  # None without the consistency scan
    rms = f" (rms {t1.fit.rms * 1e3:.2f}·10⁻³)" if t1.fit is not None else ""
    mism = (
        ", ".join(
            f"(φ = {c.phi_label}, μ = {c.mu:.2f}: {c.diff * 1e3:+.3f}·10⁻³)" for c in t1.mismatches
        )
        or "none"
    )
    n_ok = sum(r.agrees for r in rep.table2.runs)
    t2max = max(r.max_abs_diff for r in rep.table2.rows)
    parts = [
        "<!DOCTYPE html><html lang=en><head><meta charset=utf-8>",
        "<title>slidespin: reproduction of the paper</title>",
        f"<style>{_CSS}</style></head><body>",
        "<h1>Reproduction of “About the movement of a solid body on a plane surface in "
        "accordance with elliptic contact area and anisotropic friction”</h1>",
        f"<p class=small>slidespin {_e(__version__)}, Python {_e(platform.python_version())}; "
        f"generated by <code>slidespin reproduce all</code> in {rep.seconds:.0f} s. "
        "Every number below was computed for this page; the physics and the errata are "
        "documented in docs/model.md of slidespin.</p>",
        "<nav><a href=#t1>Table 1</a><a href=#t2>Table 2</a><a href=#f2>Figure 2</a>"
        "<a href=#f3>Figure 3</a><a href=#f4>Figure 4</a><a href=#phase>Phase portraits</a>"
        "<a href=#errata>Errata</a></nav>",
        "<h2 id=t1>Table 1 — terminal ratio β(μ) of the elliptic plate</h2>",
        "<p>The paper's method: the root of eq. 16, β = I*F_τ/M_Cζ, with the velocity direction "
        "ϑ = 0 imposed and F_n ignored (uniform pressure, e = 0.866, I* = (1 + κ²)/4, f = 0). "
        f"fx is not printed; least squares over the 24 cells with μ > 0 give "
        f"<b>fx = {t1.fx:.5f}</b>{rms}. "
        f"Largest difference {t1.max_abs_diff * 1e3:.2f}·10⁻³; "
        f"{27 - len(t1.mismatches)} of 27 cells round to the printed value; the others: "
        f"{mism}. No single fx makes more than {t1.best_count} of the 24 fx-dependent cells "
        f"round correctly (fx ∈ [{lo:.5f}, {hi:.5f}]). "
        + (
            f"With the round value fx = {table1.ROUND_FX:g}, <b>{t1.round_matching} of 27</b> "
            f"cells round to the printed value (least squares: {t1.matching} of 27): "
            f"{_e(t1.likely_fx())} "
            if t1.round_cells is not None
            else ""
        )
        + "Beside each cell, the <b>true terminal motion</b> at that φ (a fixed point of the "
        "flow of the direction of motion, F_n = 0 and ϑ free): it coincides with the paper's "
        "root only for φ = π/2.</p>",
        _table1_html(t1),
        _figure(
            "table1.png",
            "Left: β/a of eq. 16 (lines), printed (circles), true terminal "
            "ratio (dashed). Right: the true terminal direction ϑ*.",
        ),
        "<h2 id=t2>Table 2 — how a circular patch stops, against I*</h2>",
        "<p>Boundaries I₁ = J(∞), I₂ = J(1), I₃ = J(0⁺) of J(β) = β M_Cζ/F_τ at ϑ = 0, "
        "computed numerically, against the printed formulas (uniform row 1 with its "
        f"parenthesis restored): largest difference {t2max:.1e}. {n_ok} of "
        f"{len(rep.table2.runs)} simulations end as Table 2 states.</p>",
        _table2_html(rep.table2),
        _figure(
            "table2.png",
            "Terminal ratio k = v/(aω) against I* for the three pressure "
            "laws; dotted: I₁ and I₃, dots: I₂ (k = 1), crosses and triangles: simulations, "
            "star: the published uniform disk (I* = 1/2, k = 0.653).",
        ),
        f"<h2 id=f2>Figure 2 — uniform pressure (fx = {rep.fig2.fx:.5f}, μ = {rep.mu:g})</h2>",
        "<p>v₀ = ω₀ = 1, ϑ₀ = π/4 in the paper's units; the paper gives neither fx nor μ. "
        "Sliding and spinning do stop together, but the velocity at the stop is not along "
        "the low-friction axis (ϑ* ≠ 0): the ellipse turns during the motion and ϑ* depends on "
        "its final orientation.</p>",
        _runs_html(rep.fig2),
        _figure(
            "fig2.png",
            "β(t) and ϑ(t); below, the path of the mass centre with the "
            "outline of the patch at equal time intervals.",
        ),
        "<h2 id=f3>Figure 3 — linear pressure, ξc = ηc = 0.1a</h2>",
        "<p>The mass centre G lies over the pressure centroid; β and v refer to G (erratum 7).</p>",
        _runs_html(rep.fig3),
        _figure("fig3.png", "β(t) and ϑ(t) for the linear law, with the paths."),
        "<h2 id=f4>Figure 4 — F_n(t), linear pressure</h2>",
        "<p>F_n → 0 at the stop of every run: the terminal condition of eq. 14–16.</p>",
        _figure("fig4.png", "The friction force across the velocity, in units of m g."),
        "<h2 id=phase>Phase portraits</h2>",
        "<p>The uniform disk under isotropic friction, one I* in each interval of Table 2: "
        "every trajectory enters the origin along the attracting ray.</p>",
        _figure(
            "phase.png",
            "v against aω from 11 initial states of equal energy; solid: "
            "attracting terminal motion, dashed: repelling ones.",
        ),
        "<h2 id=errata>Errata of the printed paper</h2>",
        _errata_html(rep.errata),
        "<h2>Files</h2><p>Numbers as JSON and text: "
        + ", ".join(
            f'<a href="{n}">{n}</a>'
            for n in (
                "table1.json",
                "table2.json",
                "fig2.json",
                "fig3.json",
                "fig4.json",
                "phase.json",
                "errata.json",
                "table1.txt",
                "table2.txt",
                "errata.txt",
            )
        )
        + ".</p></body></html>",
    ]
    path = os.path.join(out, "index.html")
    with open(path, "w", encoding="utf-8") as fh:
        fh.write("\n".join(parts) + "\n")
    return path


def main(
    out=None,
    *,
    as_json: bool = False,
    mu: float = 0.12,
    fx=None,
    table2_fx: float = 0.3,
    table2_mu: float = 0.15,
    fmt: str = "png",
    stream=None,
) -> Report:
    """Write every table, figure and erratum into ``out`` (default ``slidespin-out``) with
    an ``index.html``; print a summary (or JSON with ``as_json``)."""
    import sys

    stream = stream or sys.stdout
    out = sh.prepare_out(sh.DEFAULT_OUT if out is None else out)
    if fmt not in sh.FORMATS:
        raise ValueError(f"--format = {fmt!r} is invalid; valid values: {', '.join(sh.FORMATS)}")
    rep = compute(mu=mu, table2_fx=table2_fx, table2_mu=table2_mu, fx=fx)
    files = []
    for name, res in (
        ("table1", rep.table1),
        ("table2", rep.table2),
        ("fig2", rep.fig2),
        ("fig3", rep.fig3),
        ("fig4", rep.fig4),
        ("phase", rep.phase),
        ("errata", rep.errata),
    ):
        path = os.path.join(out, f"{name}.json")
        with open(path, "w", encoding="utf-8") as fh:
            json.dump(res.as_dict(), fh, indent=2)
        files.append(path)
        if name in ("table1", "table2", "errata"):
            path = os.path.join(out, f"{name}.txt")
            with open(path, "w", encoding="utf-8") as fh:
                fh.write(res.to_text() + "\n")
            files.append(path)
    plots: tuple[tuple[str, Callable[[], Figure]], ...] = (
        ("table1", lambda: table1.plot(rep.table1)),
        ("table2", lambda: table2.plot(rep.table2)),
        ("fig2", lambda: fig2.plot(rep.fig2)),
        ("fig3", lambda: fig3.plot(rep.fig3)),
        ("fig4", lambda: fig4.plot(rep.fig4)),
        ("phase", lambda: phase.plot(rep.phase)),
    )
    for name, plot in plots:
        fig = plot()
        files.append(sh.save(fig, out, name, "png"))  # the page shows PNG
        if fmt != "png":
            files.append(sh.save(fig, out, name, fmt))
    index = write_html(rep, out)
    files.append(index)
    if as_json:
        print(
            json.dumps(
                {"index": index, "files": files, "seconds": rep.seconds, "fx": rep.table1.fx},
                indent=2,
            ),
            file=stream,
        )
    else:
        print(f"wrote {len(files)} files into {out}; open {index}", file=stream)
    return rep


if __name__ == "__main__":  # pragma: no cover
    main()
