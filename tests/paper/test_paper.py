"""Reproduction of the paper (slidespin.paper): every compute() pinned to the printed values.

Table 1 is pinned cell by cell to its printed three decimals; Table 2 boundary by boundary to
its printed formulas; the figures' runs to the terminal conditions they must satisfy; each
erratum to the numbers that show it. Figures get smoke tests (file written, non-empty, every
axes labelled), and the CLI is driven as a user would.
"""

import json
import math
import os
import re

import numpy as np
import pytest

from slidespin.analysis.terminal import terminal_states
from slidespin.cli.main import main as cli_main
from slidespin.paper import errata, fig2, fig3, fig4, phase, report, table1, table2

# cells where our value, with the least-squares fx, does not round to the printed one:
# (φ label, μ) -> our β − printed β, measured (units of a); documented in docs/paper.md
KNOWN_OFF = {("π/3", 0.09): 0.504e-3, ("π/3", 0.21): -0.804e-3, ("π/2", 0.15): 0.518e-3}


@pytest.fixture(scope="module")
def paper_table1():
    return table1.compute()


@pytest.fixture(scope="module")
def paper_table2():
    return table2.compute()


@pytest.fixture(scope="module")
def figure2():
    return fig2.compute()


@pytest.fixture(scope="module")
def figure3():
    return fig3.compute()


# ------------------------------------------------------------------------------------------
# Table 1
# ------------------------------------------------------------------------------------------
def test_table1_mu0_column_needs_no_parameter():
    for i, phi in enumerate(table1.PHI):
        for fx in (0.2, 0.42, 1.0):  # μ = 0: fx drops out
            assert abs(table1.paper_ratio(fx, 0.0, phi) - table1.PRINTED[i, 0]) <= 0.0005


def test_table1_inferred_fx_is_the_least_squares_minimum(paper_table1):
    fx = paper_table1.fx
    assert fx == pytest.approx(0.41986, abs=2e-5)

    def sse(f):
        return float(np.sum((table1.ratio_table(f)[:, 1:] - table1.PRINTED[:, 1:]) ** 2))

    assert sse(fx) < sse(fx - 5e-4) and sse(fx) < sse(fx + 5e-4)
    assert paper_table1.fit.rms < 0.5e-3


@pytest.mark.parametrize("i", range(3))
@pytest.mark.parametrize("j", range(9))
def test_table1_cell(paper_table1, i, j):
    """Every cell within the printed precision (half a unit of the 3rd decimal), except the
    three measured exceptions, which are within one unit and stay what they are."""
    cell = paper_table1.cells[9 * i + j]
    assert cell.paper == table1.PRINTED[i, j]
    key = (cell.phi_label, round(cell.mu, 2))
    if key in KNOWN_OFF:
        assert cell.diff == pytest.approx(KNOWN_OFF[key], abs=0.01e-3)
        assert abs(cell.diff) < 1e-3
    else:
        assert abs(cell.diff) <= 0.5e-3


def test_table1_round_fx_reproduces_all_but_one_cell():
    res = table1.compute(fx=0.42, consistency=False)
    assert res.fx_source == "given"
    off = [(c.phi_label, round(c.mu, 2)) for c in res.mismatches]
    assert off == [("π/3", 0.21)]  # printed 0.667; ours 0.6661
    assert res.mismatches[0].diff == pytest.approx(-0.86e-3, abs=0.02e-3)


def test_table1_shows_the_round_fx_beside_the_least_squares_one(paper_table1):
    res = paper_table1
    assert res.fx_source == "least squares" and res.matching == 27 - len(KNOWN_OFF)
    # the same cells as an independent compute(fx=0.42) (test above): only π/3, μ = 0.21 off
    assert [(c.phi_label, round(c.mu, 2)) for c in res.round_mismatches] == [("π/3", 0.21)]
    assert res.round_matching == 26
    text = res.to_text()
    assert "round value fx = 0.42: 26 of 27 cells round to the printed value" in text
    assert "(least squares: 24 of 27)" in text
    assert "the authors most likely used fx = 0.42" in text
    d = json.loads(json.dumps(res.as_dict()))
    assert d["round_fx"]["matching"] == 26 and d["round_fx"]["least_squares_matching"] == 24
    assert d["round_fx"]["mismatches"][0]["diff"] == pytest.approx(-0.86e-3, abs=0.02e-3)


def test_table1_no_single_fx_fits_every_cell(paper_table1):
    assert paper_table1.best_count == 23
    lo, hi = paper_table1.best_interval
    assert 0.4199 < lo < hi < 0.4201


def test_table1_true_terminal_states(paper_table1):
    for c in paper_table1.cells:
        assert c.true_ending == "mixed"
        if c.phi_label == "π/2":  # the paper's root is a true terminal state
            assert c.true_beta == pytest.approx(c.beta, abs=1e-9)
            assert abs(c.true_theta) < 1e-9
        else:  # it is not: the velocity turns and β* differs
            assert c.true_theta < -0.2
            assert abs(c.true_beta - c.beta) > 0.01
    # isotropic friction: the true terminal motion does not depend on φ (velocity ⟂ ξ)
    iso = [c for c in paper_table1.cells if c.mu == 0.0]
    assert np.ptp([c.true_beta for c in iso]) < 1e-9
    for c in iso:
        assert c.true_theta == pytest.approx(c.phi - math.pi / 2, abs=1e-9)


def test_table1_json(paper_table1):
    d = json.loads(json.dumps(paper_table1.as_dict()))
    assert d["fx"] == paper_table1.fx
    assert len(d["cells"]) == 27
    assert {"phi", "mu", "beta", "paper", "true_beta", "true_theta"} <= set(d["cells"][0])


# ------------------------------------------------------------------------------------------
# Table 2
# ------------------------------------------------------------------------------------------
@pytest.mark.parametrize("mu", [0.0, 0.15])
@pytest.mark.parametrize("law", ["uniform", "Boussinesq", "Hertz"])
@pytest.mark.parametrize("k", range(3))
def test_table2_boundary(paper_table2, mu, law, k):
    """Each boundary computed from J(β) equals the printed formula (exact rationals)."""
    row = next(r for r in paper_table2.rows if r.law == law and r.mu == mu)
    fx = row.fx
    printed = {
        "uniform": ((fx + mu) / (4 * fx), (5 * fx + 4 * mu) / (15 * fx), (2 * fx + mu) / (3 * fx)),
        "Boussinesq": (
            (fx + mu) / (3 * fx),
            (4 * fx + 3 * mu) / (8 * fx),
            (2 * fx + mu) / (2 * fx),
        ),
        "Hertz": ((fx + mu) / (5 * fx), (6 * fx + 5 * mu) / (24 * fx), (2 * fx + mu) / (4 * fx)),
    }[law]
    assert row.numeric[k] == pytest.approx(printed[k], abs=1e-10)


def test_table2_simulations_end_as_stated(paper_table2):
    assert len(paper_table2.runs) == 24
    for r in paper_table2.runs:
        assert r.agrees, (r.law, r.mu, r.regime, r.observed)
        if r.ending == "mixed":  # simulation vs J⁻¹: two independent routes to k
            assert r.k == pytest.approx(r.k_theory, rel=1e-7)
    published = next(
        r for r in paper_table2.runs if r.law == "uniform" and r.mu == 0.0 and r.regime == 3
    )
    assert published.inertia_ratio == pytest.approx(0.5, abs=1e-12)
    assert round(published.k, 3) == 0.653


def test_table2_rejects_negative_mu():
    with pytest.raises(ValueError, match="mu"):
        table2.compute(mu=-0.1, runs=False)


# ------------------------------------------------------------------------------------------
# Figures 2–4
# ------------------------------------------------------------------------------------------
def test_figure_runs_stop_at_terminal_states(figure2, figure3):
    for res in (figure2, figure3):
        assert res.fx == pytest.approx(0.41986, abs=2e-5) and res.mu == 0.12
        for tr in res.runs:
            assert tr.status == "stopped" and tr.ending == "mixed"
            assert abs(tr.normal[-1]) < 1e-8  # F_n → 0 (Figure 4, eq. 14)
            states = [
                s
                for s in terminal_states(tr.body, tr.friction, tr.stop_state.phi)
                if s.stable and s.ending == "mixed"
            ]
            best = min(
                states,
                key=lambda s: (
                    abs(s.beta - tr.beta_stop)
                    + abs(math.remainder(s.theta - tr.theta_stop, 2 * math.pi))
                ),
            )
            assert best.beta == pytest.approx(tr.beta_stop, abs=1e-7)
            assert best.theta == pytest.approx(tr.theta_stop, abs=1e-7)


def test_the_ellipse_does_not_stop_with_theta_zero(figure2):
    thetas = [tr.theta_stop for tr in figure2.runs]
    assert thetas == pytest.approx([-0.2145, -0.0376, 0.3143], abs=2e-4)


def test_figure4_uses_figure3_runs(figure3):
    res = fig4.compute()
    assert res.runs is figure3.runs


def _labelled(fig):
    axes = fig.get_axes()
    assert axes
    for ax in axes:
        assert ax.get_xlabel().strip() and ax.get_ylabel().strip()
    return axes


def _png_ok(path):
    with open(path, "rb") as fh:
        head = fh.read(8)
    return head == b"\x89PNG\r\n\x1a\n" and os.path.getsize(path) > 20_000


@pytest.mark.parametrize("module", [fig2, fig3, fig4], ids=["fig2", "fig3", "fig4"])
def test_figure_smoke(module, tmp_path, capsys):
    res = module.main(tmp_path)
    out = capsys.readouterr().out
    assert _png_ok(tmp_path / f"{module.NAME}.png")
    assert json.loads((tmp_path / f"{module.NAME}.json").read_text())["fx"] == res.fx
    assert "ending" in out
    axes = _labelled(module.plot(res))
    assert any(ax.get_legend() is not None for ax in axes)


def test_figures_default_to_slidespin_out(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    assert cli_main(["reproduce", "fig2"]) == 0
    assert os.listdir(tmp_path) == ["slidespin-out"]  # nothing in the working directory
    assert sorted(os.listdir(tmp_path / "slidespin-out")) == ["fig2.json", "fig2.png"]
    assert "slidespin-out/fig2.png" in capsys.readouterr().out


def test_table_figures_smoke(paper_table1, paper_table2, tmp_path):
    for plot, res in ((table1.plot, paper_table1), (table2.plot, paper_table2)):
        fig = plot(res)
        _labelled(fig)
        fig.savefig(tmp_path / "x.png")
        assert _png_ok(tmp_path / "x.png")


# ------------------------------------------------------------------------------------------
# phase portraits
# ------------------------------------------------------------------------------------------
def test_phase_portraits_one_per_regime(tmp_path):
    res = phase.compute(n=3)
    assert res.inertia_ratios[2] == 0.5
    endings = [set(pp.endings) for pp in res.portraits]
    assert endings == [{"pure_sliding"}, {"mixed"}, {"mixed"}, {"pure_spinning"}]
    assert np.all(res.portraits[1].beta_stop > 1.0)
    assert np.allclose(res.portraits[2].beta_stop, 0.653, atol=5e-4)  # published
    fig = phase.plot(res)
    _labelled(fig)
    fig.savefig(tmp_path / "phase.png")
    assert _png_ok(tmp_path / "phase.png")


# ------------------------------------------------------------------------------------------
# errata
# ------------------------------------------------------------------------------------------
def test_errata_numbers():
    res = errata.compute()
    e = {x.number: x.values for x in res.errata}
    assert [x.number for x in res.errata] == list(range(1, 12))
    assert e[1]["check"] < 1e-9 and e[1]["max_relative_error"] > 0.01  # eq. 3's y'
    assert e[2]["corrected_s"] == pytest.approx(e[2]["simulate_s"], rel=1e-5)  # eq. 7
    assert e[2]["printed_s"] / e[2]["corrected_s"] == pytest.approx(9.81 / math.pi, rel=1e-12)
    # eq. 9: the corrected I1 reproduces Table 1's μ = 0 column, the printed one has no root
    assert np.allclose(e[3]["column_corrected_I1"], e[3]["column_paper"], atol=5e-4)
    assert all(math.isinf(x) for x in e[3]["column_printed_I1"])
    assert e[3]["wrench_error_corrected"] < 1e-12 < 0.1 < e[3]["wrench_error_printed"]
    assert np.allclose(e[4]["literal"], -np.array(e[4]["true"]), atol=1e-12)  # ω < 0
    assert e[5]["centroid_corrected"] == pytest.approx(0.01, rel=1e-6)
    assert e[5]["centroid_printed"] == pytest.approx(0.01 * math.pi * 0.1 * 0.05, rel=1e-6)
    assert e[6]["t1_printed"] < 0.1 * e[6]["t1_corrected"]  # eq. 13's C31 terms
    assert e[7]["t1_mass_centre"] == pytest.approx(e[7]["simulate_t1"], rel=1e-5)
    assert e[7]["beta_mass_centre"] == pytest.approx(e[7]["simulate_beta"], abs=1e-4)
    assert abs(e[7]["theta_centre"] - e[7]["theta_mass_centre"]) > 0.1
    assert e[8]["load_printed"] == pytest.approx(0.1, rel=1e-6)  # Hertz p0
    assert e[8]["load_corrected"] == pytest.approx(1.0, rel=1e-5)
    assert (e[9]["literal"], e[9]["corrected"]) == pytest.approx((0.45, 0.375))
    assert e[9]["numeric"] == pytest.approx(0.375, abs=1e-12)
    assert abs(e[11]["circle_theta"]) < 1e-8
    assert max(abs(x) for x in e[11]["ellipse_theta"]) > 0.3
    text = res.to_text()
    assert text.count("printed  :") == 11
    assert "MODEL.md" not in text and "docs/model.md" in text


# ------------------------------------------------------------------------------------------
# all + CLI
# ------------------------------------------------------------------------------------------
def test_report_writes_a_self_contained_folder(tmp_path, capsys):
    report.main(tmp_path / "all")
    folder = tmp_path / "all"
    page = (folder / "index.html").read_text(encoding="utf-8")
    images = re.findall(r'<img src="([^"]+)"', page)
    assert sorted(images) == sorted(
        ["table1.png", "table2.png", "fig2.png", "fig3.png", "fig4.png", "phase.png"]
    )
    for name in images:
        assert "/" not in name and _png_ok(folder / name)
    for name in re.findall(r'<a href="([^"#]+)"', page):
        assert (folder / name).exists(), name
    assert "0.41986" in page and "Errata" in page
    assert "MODEL.md" not in page and "docs/model.md" in page
    assert "<b>26 of 27</b>" in page and "most likely used fx = 0.42" in page
    assert "open" in capsys.readouterr().out


def test_cli_table1_json(capsys):
    assert cli_main(["reproduce", "table1", "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["fx"] == pytest.approx(0.41986, abs=2e-5)
    assert len(d["cells"]) == 27
    assert {"phi", "mu", "beta", "paper", "true_beta", "true_theta"} <= set(d["cells"][5])


@pytest.mark.parametrize(
    "argv, match",
    [
        (["reproduce", "phase", "--mu", "0.1"], "--mu"),
        (["reproduce", "table2", "--fx", "-1"], "--fx"),
        (["reproduce", "table2", "--mu", "-0.2"], "--mu"),
    ],
)
def test_cli_bad_input(argv, match, capsys):
    assert cli_main(argv) == 2
    err = capsys.readouterr().err
    assert err.startswith("slidespin: error:") and match in err and err.count("\n") == 1


def test_cli_out_must_be_a_directory(tmp_path, capsys):
    f = tmp_path / "file"
    f.write_text("x")
    assert cli_main(["reproduce", "fig2", "--out", str(f)]) == 2
    assert "--out" in capsys.readouterr().err
