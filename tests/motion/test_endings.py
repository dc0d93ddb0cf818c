"""Endings and statuses that do not depend on solver settings (issue #10, item 6).

What a run reports as ``stopped`` must be a property of the motion: the same ending, β* and ϑ*
whatever ``rtol`` and ``max_step`` (MODEL §5, §9; :mod:`slidespin.motion.outcomes`). Independent
truths used here:

* self-consistency across solver settings (rtol 1e-6 … 1e-12, ``max_step``) over a random
  sample drawn like a user's Monte Carlo sweep (``examples/sweep_random.toml``, widened to
  the linear law, fx > fy, turned and body-fixed tensors);
* the boundaries of the paper's Table 2 (circle, orthotropic friction), written here from the
  printed formulas and, for I₁ and I₃, derived again from the pressure moments by 1-D
  quadrature: I₁ = (fy/fx)⟨ξ²⟩, I₃ = ((fx + fy)/fx) ∫p r dS / ∫p/r dS (a = 1);
* symmetry: an isotropic disk keeps the direction of its velocity (the mirror through G
  perpendicular to v maps the slip field to minus its mirror image, so F_n = 0);
* the closed form of pure sliding under a skew tensor (a logarithmic-type spiral), integrated
  over one turn with scipy and summed as a geometric series.

Violations are reported with the case (body, friction, state) and the values, never hidden by
a looser tolerance.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from scipy.integrate import quad, solve_ivp

import slidespin as ss
from slidespin.analysis.intervals import inertia_intervals
from slidespin.motion.batch import simulate_cases
from slidespin.motion.outcomes import STATUSES

A = 0.05  # semi-axis a [m] of every sampled patch
G = 9.81
LAW_NAMES = ("uniform", "linear", "boussinesq", "hertz")
TABLE2_LAWS = ("uniform", "boussinesq", "hertz")
N_RANDOM = 3000  # Monte Carlo cases (the batch engine runs them at 4 rtols in a few seconds)
RTOLS = (1e-6, 1e-8, 1e-10, 1e-12)
BETA_REL = 1e-6
THETA_ABS = 1e-5


def _law(name, xi_c=0.0, eta_c=0.0):
    return {
        "uniform": ss.UniformPressure(),
        "boussinesq": ss.BoussinesqPressure(),
        "hertz": ss.HertzPressure(),
    }.get(name) or ss.LinearPressure(xi_c, eta_c)


def _angle_diff(a, b):
    """|a − b| modulo 2π, in [0, π]."""
    return np.abs((np.asarray(a) - np.asarray(b) + math.pi) % (2.0 * math.pi) - math.pi)


# ------------------------------------------------------------------------------------------
# Table 2 written independently of slidespin.analysis.intervals
# ------------------------------------------------------------------------------------------
def table2_printed(law, fx, fy):
    """(I₁, I₂, I₃) from the paper's Table 2 (uniform row 1 with its parenthesis restored,
    MODEL §7 erratum 9); μ = fy − fx."""
    mu = fy - fx
    return {
        "uniform": ((fx + mu) / (4 * fx), (5 * fx + 4 * mu) / (15 * fx), (2 * fx + mu) / (3 * fx)),
        "boussinesq": (
            (fx + mu) / (3 * fx),
            (4 * fx + 3 * mu) / (8 * fx),
            (2 * fx + mu) / (2 * fx),
        ),
        "hertz": ((fx + mu) / (5 * fx), (6 * fx + 5 * mu) / (24 * fx), (2 * fx + mu) / (4 * fx)),
    }[law]


#: p(r) on the unit disk up to a constant (MODEL §3) as (1 − r)^e · h(r), for quad's
#: algebraic weight: e and h
_RADIAL = {
    "uniform": (0.0, lambda r: 1.0),
    "boussinesq": (-0.5, lambda r: 1.0 / math.sqrt(1.0 + r)),
    "hertz": (0.5, lambda r: math.sqrt(1.0 + r)),
}


def table2_derived(law, fx, fy):
    """(I₁, I₃) from the small-spin and small-slide expansions of the wrench of a disk (a = 1):
    I₁ = lim β M/F_τ = (fy/fx)⟨ξ²⟩ = (fy/fx)⟨r²⟩/2, I₃ = lim_{β→0} = ((fx + fy)/fx) ∫p r/∫p/r
    (radial integrals ∫ p(r) rⁿ dr by quad)."""
    e, h = _RADIAL[law]

    def mom(n):
        if e == 0.0:
            return 1.0 / (n + 1.0)
        return quad(
            lambda r: h(r) * r**n, 0.0, 1.0, weight="alg", wvar=(0.0, e), epsabs=1e-15, epsrel=1e-14
        )[0]

    i1 = fy / fx * 0.5 * mom(3) / mom(1)
    i3 = (fx + fy) / fx * mom(2) / mom(0)
    return i1, i3


@pytest.mark.parametrize("law", TABLE2_LAWS)
@pytest.mark.parametrize("fx, fy", [(0.3, 0.3), (0.3, 0.45), (0.2, 0.5)])
def test_table2_boundaries_three_routes(law, fx, fy):
    """The printed formulas, the moment derivation and slidespin's J(β) limits agree."""
    printed = table2_printed(law, fx, fy)
    i1, i3 = table2_derived(law, fx, fy)
    assert i1 == pytest.approx(printed[0], rel=1e-10)
    assert i3 == pytest.approx(printed[2], rel=1e-10)
    lib = inertia_intervals(_law(law), ss.FrictionTensor(fx, fy))
    assert lib == pytest.approx(printed, rel=1e-9)


# ------------------------------------------------------------------------------------------
# the random sample (a user's Monte Carlo sweep) and the Table 2 boundary cases
# ------------------------------------------------------------------------------------------
def draw_cases(n, seed):
    """Cases for :func:`simulate_cases`, drawn like examples/sweep_random.toml and wider:
    all four laws (linear with |offset| ≤ 0.15 of each semi-axis), 40 % circles, fx and fy in
    either order, skew f, 30 % turned tensors, plane and body frames, I* log-uniform in
    [0.1, 1.5] (across the Table 2 intervals of every law)."""
    rng = np.random.default_rng(seed)
    law = rng.integers(0, 4, n)
    circle = rng.random(n) < 0.4
    b = A * np.where(circle, 1.0, rng.uniform(0.2, 1.0, n))
    fx = rng.uniform(0.1, 0.6, n)
    fy = np.maximum(fx + rng.uniform(-0.2, 0.4, n), 0.05)
    theta = rng.uniform(-math.pi, math.pi, n)
    v0 = rng.uniform(0.1, 2.0, n)
    return {
        "a": A,
        "b": b,
        "law": np.array(LAW_NAMES)[law],
        "xi_c": np.where(law == 1, A * rng.uniform(-0.15, 0.15, n), 0.0),
        "eta_c": np.where(law == 1, b * rng.uniform(-0.15, 0.15, n), 0.0),
        "fx": fx,
        "fy": fy,
        "f": rng.uniform(-0.1, 0.1, n),
        "frame": np.array(("plane", "body"))[rng.integers(0, 2, n)],
        "angle": np.where(rng.random(n) < 0.3, rng.uniform(0.0, math.pi, n), 0.0),
        "mass": 1.0,
        "moment_of_inertia": np.exp(rng.uniform(math.log(0.1), math.log(1.5), n)) * A * A,
        "vx": v0 * np.cos(theta),
        "vy": v0 * np.sin(theta),
        "omega": rng.uniform(-30.0, 30.0, n),
        "phi": rng.uniform(0.0, math.pi, n),
    }


def boundary_cases(seed):
    """Circles, f = 0, I* exactly on I₁, I₂, I₃ of Table 2 from ``inertia_intervals`` and from
    the printed formulas, for the three laws of Table 2, from random tensors and starts."""
    rng = np.random.default_rng(seed)
    rows = []
    for law in TABLE2_LAWS:
        for source in ("library", "printed"):
            for j in range(3):
                for _ in range(2):
                    fx = rng.uniform(0.15, 0.5)
                    fy = fx + rng.uniform(0.0, 0.3)
                    fr = ss.FrictionTensor(fx, fy)
                    bounds = (
                        inertia_intervals(_law(law), fr)
                        if source == "library"
                        else table2_printed(law, fx, fy)
                    )
                    th, v0 = rng.uniform(-math.pi, math.pi), rng.uniform(0.2, 2.0)
                    rows.append(
                        {
                            "law": law,
                            "fx": fx,
                            "fy": fy,
                            "i_star": bounds[j],
                            "which": j + 1,
                            "vx": v0 * math.cos(th),
                            "vy": v0 * math.sin(th),
                            "omega": rng.uniform(-30.0, 30.0),
                            "phi": rng.uniform(0, 3),
                        }
                    )
    return rows


def _boundary_columns(rows):
    def col(k):
        return np.array([r[k] for r in rows])

    return {
        "a": A,
        "b": A,
        "law": col("law"),
        "fx": col("fx"),
        "fy": col("fy"),
        "f": 0.0,
        "mass": 1.0,
        "moment_of_inertia": col("i_star") * A * A,
        "vx": col("vx"),
        "vy": col("vy"),
        "omega": col("omega"),
        "phi": col("phi"),
    }


def case_text(cases, i):
    """The case i of a column dict as the Python that rebuilds it (for failure messages)."""
    c = {k: (np.asarray(v)[i] if np.ndim(v) else v) for k, v in cases.items()}
    c = {k: (v.item() if isinstance(v, np.generic) else v) for k, v in c.items()}
    law = c.get("law", "uniform")
    pres = (
        f"LinearPressure({c['xi_c']!r}, {c['eta_c']!r})"
        if law == "linear"
        else {
            "uniform": "UniformPressure()",
            "boussinesq": "BoussinesqPressure()",
            "hertz": "HertzPressure()",
        }[law]
    )
    return (
        f"case {i}: Body(Ellipse({c['a']!r}, {c['b']!r}), {pres}, {c['mass']!r}, "
        f"moment_of_inertia={c['moment_of_inertia']!r}), FrictionTensor({c['fx']!r}, "
        f"{c['fy']!r}, f={c.get('f', 0.0)!r}, frame={c.get('frame', 'plane')!r}, "
        f"angle={c.get('angle', 0.0)!r}), State(0, 0, {c['phi']!r}, {c['vx']!r}, "
        f"{c['vy']!r}, {c['omega']!r})"
    )


def case_objects(cases, i):
    """(body, friction, state) of case i."""
    c = {k: (np.asarray(v)[i] if np.ndim(v) else v) for k, v in cases.items()}
    c = {k: (v.item() if isinstance(v, np.generic) else v) for k, v in c.items()}
    body = ss.Body(
        ss.Ellipse(c["a"], c["b"]),
        _law(c.get("law", "uniform"), c.get("xi_c", 0.0), c.get("eta_c", 0.0)),
        c["mass"],
        moment_of_inertia=c["moment_of_inertia"],
    )
    fr = ss.FrictionTensor(
        c["fx"],
        c["fy"],
        f=c.get("f", 0.0),
        frame=c.get("frame", "plane"),
        angle=c.get("angle", 0.0),
    )
    return body, fr, ss.State(0.0, 0.0, c["phi"], c["vx"], c["vy"], c["omega"])


@pytest.fixture(scope="module")
def sample():
    """The random sample and the boundary cases at every rtol of ``RTOLS``."""
    rand = draw_cases(N_RANDOM, 2026)
    rows = boundary_cases(7)
    bnd = _boundary_columns(rows)
    out = {"cases": rand, "boundary": bnd, "rows": rows, "rand": {}, "bnd": {}}
    for r in RTOLS:
        out["rand"][r] = simulate_cases(rand, rtol=r).as_dict()
        out["bnd"][r] = simulate_cases(bnd, rtol=r).as_dict()
    return out


def _values(res, i):
    return {k: res[k][i] for k in ("status", "ending", "beta_stop", "theta_stop", "t_stop")}


def _report(bad, cases, res_a, res_b, ra, rb):
    lines = [f"{len(bad)} stopped cases change between rtol {ra:g} and {rb:g}:"]
    for i in bad[:12]:
        lines.append(
            f"  {case_text(cases, i)}\n    rtol {ra:g}: {_values(res_a, i)}\n"
            f"    rtol {rb:g}: {_values(res_b, i)}"
        )
    return "\n".join(lines)


def _both_stopped(ra, rb):
    return (ra["status"] == "stopped") & (rb["status"] == "stopped")


def _beta_disagrees(ba, bb):
    ba, bb = np.asarray(ba, float), np.asarray(bb, float)
    with np.errstate(invalid="ignore", divide="ignore"):
        close = np.abs(ba - bb) <= BETA_REL * np.abs(bb)
    same_special = (ba == bb) | (np.isnan(ba) & np.isnan(bb))  # inf, 0, NaN
    return ~(close | same_special)


def _theta_disagrees(ta, tb):
    ta, tb = np.asarray(ta, float), np.asarray(tb, float)
    both_nan = np.isnan(ta) & np.isnan(tb)
    with np.errstate(invalid="ignore"):
        close = _angle_diff(ta, tb) <= THETA_ABS
    return ~(both_nan | close)


def test_most_random_cases_stop(sample):
    """At least 97 % of a Monte Carlo sample reach ``stopped`` at the default rtol, and every
    status is one of the documented names."""
    res = sample["rand"][1e-10]
    assert set(res["status"]) <= set(STATUSES)
    frac = float(np.mean(res["status"] == "stopped"))
    names, counts = np.unique(res["status"], return_counts=True)
    assert frac >= 0.97, f"only {frac:.4f} of {N_RANDOM} cases stopped: {dict(zip(names, counts))}"


@pytest.mark.parametrize("rtol", [1e-6, 1e-8, 1e-10])
def test_random_endings_do_not_depend_on_rtol(sample, rtol):
    """Whenever both runs say ``stopped``, the ending is the same at rtol 1e-6, 1e-8, 1e-10
    as at 1e-12 (random sample and Table 2 boundary cases)."""
    for key, cases in (("rand", sample["cases"]), ("bnd", sample["boundary"])):
        ra, rb = sample[key][rtol], sample[key][1e-12]
        bad = np.flatnonzero(_both_stopped(ra, rb) & (ra["ending"] != rb["ending"]))
        assert bad.size == 0, _report(bad, cases, ra, rb, rtol, 1e-12)


def test_random_theta_does_not_depend_on_rtol(sample):
    """ϑ* of stopped runs: both NaN or both finite and within 1e-5 rad (mod 2π) between rtol
    1e-10 and 1e-12."""
    for key, cases in (("rand", sample["cases"]), ("bnd", sample["boundary"])):
        ra, rb = sample[key][1e-10], sample[key][1e-12]
        bad = np.flatnonzero(
            _both_stopped(ra, rb) & _theta_disagrees(ra["theta_stop"], rb["theta_stop"])
        )
        assert bad.size == 0, _report(bad, cases, ra, rb, 1e-10, 1e-12)


def _beta_bad(sample, key, spiral):
    ra, rb = sample[key][1e-10], sample[key][1e-12]
    is_spiral = (ra["ending"] == "spiral") | (rb["ending"] == "spiral")
    sel = is_spiral if spiral else ~is_spiral
    return (
        np.flatnonzero(
            _both_stopped(ra, rb) & sel & _beta_disagrees(ra["beta_stop"], rb["beta_stop"])
        ),
        ra,
        rb,
    )


def test_random_beta_does_not_depend_on_rtol(sample):
    """β* of stopped runs other than spirals: 1e-6 relative, or the same inf (pure sliding)
    or 0 (pure spinning), between rtol 1e-10 and 1e-12."""
    for key, cases in (("rand", sample["cases"]), ("bnd", sample["boundary"])):
        bad, ra, rb = _beta_bad(sample, key, spiral=False)
        assert bad.size == 0, _report(bad, cases, ra, rb, 1e-10, 1e-12)


def test_random_spiral_beta_does_not_depend_on_rtol(sample):
    """β* of stopped spiral endings is the same (inf: the spin died; NaN: it did not) at
    rtol 1e-10 and 1e-12."""
    bad, ra, rb = _beta_bad(sample, "rand", spiral=True)
    assert bad.size == 0, _report(bad, sample["cases"], ra, rb, 1e-10, 1e-12)


def test_random_pure_spinning_theta_nan_or_stable(sample):
    """Pure-spinning endings (issue #10: ϑ* changed by up to π with rtol): ϑ* is NaN at
    every rtol of 1e-8, 1e-10, 1e-12, or finite at all three and within 1e-5 rad."""
    r8, r10, r12 = (sample["rand"][r] for r in (1e-8, 1e-10, 1e-12))
    spin = (
        (r8["ending"] == "pure_spinning")
        & (r10["ending"] == "pure_spinning")
        & (r12["ending"] == "pure_spinning")
        & (r8["status"] == "stopped")
        & (r10["status"] == "stopped")
        & (r12["status"] == "stopped")
    )
    assert spin.sum() >= 50  # the sample has plenty of them
    for ra, rtol in ((r8, 1e-8), (r10, 1e-10)):
        bad = np.flatnonzero(spin & _theta_disagrees(ra["theta_stop"], r12["theta_stop"]))
        assert bad.size == 0, _report(bad, sample["cases"], ra, r12, rtol, 1e-12)


def test_sample_boundary_cases_get_their_analytic_endings(sample):
    """The boundary cases of the sample (random tensors, starts and φ₀): at every rtol, I₁ ends
    pure_sliding with β* = inf, I₃ pure_spinning with β* = 0 (marginal or stopped), I₂ mixed
    with |β*|/a = 1 (stopped)."""
    rows = sample["rows"]
    bad = []
    for r in RTOLS:
        res = sample["bnd"][r]
        for i, row in enumerate(rows):
            st, end, beta = res["status"][i], res["ending"][i], res["beta_stop"][i]
            ok = {
                1: st in ("marginal", "stopped") and end == "pure_sliding" and beta == math.inf,
                2: st == "stopped" and end == "mixed" and abs(abs(beta) / A - 1.0) <= BETA_REL,
                3: st in ("marginal", "stopped") and end == "pure_spinning" and beta == 0.0,
            }[row["which"]]
            if not ok:
                bad.append(
                    f"rtol {r:g}, I{row['which']}: {case_text(sample['boundary'], i)}: "
                    f"{_values(res, i)}"
                )
    assert not bad, "\n".join(bad)


def test_flagged_cases_carry_their_saddle_energy(sample):
    """``saddle`` results carry saddle_energy in (0, 1); every other status carries NaN."""
    for key in ("rand", "bnd"):
        for r in RTOLS:
            res = sample[key][r]
            se = np.asarray(res["saddle_energy"], float)
            saddle = res["status"] == "saddle"
            assert np.all((se[saddle] > 0.0) & (se[saddle] < 1.0)), (key, r, se[saddle])
            assert np.all(np.isnan(se[~saddle])), (key, r)


def test_every_ending_class_is_sampled(sample):
    """The sample exercises every ending (else the tests above prove little)."""
    ends = sample["rand"][1e-10]["ending"]
    for name in ("mixed", "pure_sliding", "pure_spinning", "spiral"):
        assert (ends == name).sum() >= 50, name


# ------------------------------------------------------------------------------------------
# max_step (simulate) on a subset of the sample
# ------------------------------------------------------------------------------------------
def _max_step_subset(sample, per_ending=8):
    res = sample["rand"][1e-10]
    pick = []
    for name in ("mixed", "pure_sliding", "pure_spinning", "spiral"):
        idx = np.flatnonzero((res["ending"] == name) & (res["status"] == "stopped"))
        pick += idx[:per_ending].tolist()
    # and the laws/tensors not yet represented: one linear-law body-frame case
    lin = np.flatnonzero(
        (sample["cases"]["law"] == "linear")
        & (sample["cases"]["frame"] == "body")
        & (res["status"] == "stopped")
    )
    pick += [int(i) for i in lin[:4] if i not in pick]
    return pick


def test_max_step_does_not_change_stopped_results(sample):
    """Whenever both runs say ``stopped``: the same ending, β* (1e-6) and ϑ* (1e-5 rad) with
    ``max_step=None`` and ``max_step=0.05`` (simulate, default rtol)."""
    cases = sample["cases"]
    bad = []
    for i in _max_step_subset(sample):
        body, fr, st = case_objects(cases, i)
        t1 = ss.simulate(body, fr, st)
        t2 = ss.simulate(body, fr, st, max_step=0.05)
        if t1.status != "stopped" or t2.status != "stopped":
            continue
        if (
            t1.ending != t2.ending
            or _beta_disagrees(t1.beta_stop, t2.beta_stop)
            or _theta_disagrees(t1.theta_stop, t2.theta_stop)
        ):
            bad.append(
                f"{case_text(cases, i)}\n    max_step None: {t1!r}\n    max_step 0.05: {t2!r}"
            )
    assert not bad, "\n".join(bad)


# ------------------------------------------------------------------------------------------
# regressions: the cases of issue #10 and those found by the sample above
# ------------------------------------------------------------------------------------------
SADDLE_CASE = (
    ss.Body(
        ss.Ellipse.from_eccentricity(0.1, 0.866), ss.UniformPressure(), 1, moment_of_inertia=0.001
    ),
    ss.FrictionTensor(0.42, 0.42 + 0.006153846153846176),
    ss.State(0, 0, math.pi / 4, 0.5**0.5, 0.5**0.5, 5),
)


def test_issue_saddle_case_flagged_or_settings_independent():
    """Issue #10 (a): β* was ±0.10367 according to rtol and max_step, all 'stopped'. Now the
    four runs must be honestly flagged or agree; a saddle flag carries a finite energy in
    (0, 1), and the ending is the same in all four."""
    body, fr, st = SADDLE_CASE
    runs = [
        ss.simulate(body, fr, st),
        ss.simulate(body, fr, st, rtol=1e-8),
        ss.simulate(body, fr, st, rtol=1e-12),
        ss.simulate(body, fr, st, max_step=0.05),
    ]
    text = "\n".join(repr(t) for t in runs)
    assert len({t.ending for t in runs}) == 1, text
    stopped = [t for t in runs if t.status == "stopped"]
    for t in stopped[1:]:
        assert not _beta_disagrees(t.beta_stop, stopped[0].beta_stop), text
        assert not _theta_disagrees(t.theta_stop, stopped[0].theta_stop), text
    for t in runs:
        assert t.status in STATUSES, text
        if t.status == "saddle":
            assert math.isfinite(t.saddle_energy) and 0.0 < t.saddle_energy < 1.0, text
        else:
            assert math.isnan(t.saddle_energy), text


@pytest.mark.parametrize("fx", [0.2, 0.5])
def test_issue_marginal_hertz_disk(fx):
    """Issue #10 (b): the Hertz disk with I* = 1/2 = I₃ (isotropic friction) approaches pure
    spinning algebraically: β*/a was 0.0136 … 0.00016 at rtol 1e-6 … 1e-12. Now: the analytic
    limit β* = 0, ending pure_spinning, status marginal, at every rtol."""
    body = ss.Body(ss.Circle(0.05), ss.HertzPressure(), 1)
    assert body.inertia_ratio == pytest.approx(table2_printed("hertz", fx, fx)[2], rel=1e-15)
    for rtol in RTOLS:
        tr = ss.simulate(
            body, ss.FrictionTensor(fx, fx), ss.State.from_speed(1, 20, 0.3), rtol=rtol
        )
        assert (tr.status, tr.ending, tr.beta_stop) == ("marginal", "pure_spinning", 0.0), (
            rtol,
            tr,
        )


WEAK_CASES = [  # found by random samples (weakly attracting mixed fixed points)
    (
        ss.Body(
            ss.Ellipse(0.05, 0.02761147135862422),
            ss.UniformPressure(),
            1.0,
            moment_of_inertia=0.0017549849641631983,
        ),
        ss.FrictionTensor(
            0.1830499360107842, 0.05, f=-0.01326560726576273, angle=0.04774824355486471
        ),
        ss.State(
            0, 0, 2.2384365818896743, 0.9759268536928589, -0.7310816049671182, -26.92589535470267
        ),
    ),
    (
        ss.Body(
            ss.Ellipse(0.05, 0.021497762098087125),
            ss.LinearPressure(1.0179638921181678e-05, -0.0003291797963406119),
            1.0,
            moment_of_inertia=0.0013976687902004417,
        ),
        ss.FrictionTensor(0.10915639701884713, 0.05, f=0.001651139271987151),
        ss.State(
            0, 0, 1.647732650360997, 0.9183474109215127, -0.33155355154085164, 10.432171435751115
        ),
    ),
]


_WEAK_XFAIL = pytest.mark.xfail(
    strict=True,
    reason=(
        "known limit (issue #10): at a weakly attracting mixed fixed point (eigenvalue_ratio "
        "-0.056) beta* at the frozen final phi amplifies the integration error of phi_stop ~18x: "
        "-0.0495896 vs -0.0495895 m between rtol 1e-10 and 1e-12 (2e-6; was 3.7e-6 before phi "
        "got an absolute tolerance); rtol 1e-13: -0.0495895130"
    ),
)


@pytest.mark.parametrize("case", [pytest.param(0, marks=_WEAK_XFAIL), 1])
def test_weak_fixed_point_beta_regression(case):
    """Found by random samples (ellipses, fx > fy, spinning several turns before they stop):
    β* must agree to 1e-6 between rtol 1e-10 and 1e-12 when both say ``stopped``."""
    body, fr, st = WEAK_CASES[case]
    t10 = ss.simulate(body, fr, st, rtol=1e-10)
    t12 = ss.simulate(body, fr, st, rtol=1e-12)
    if t10.status == "stopped" and t12.status == "stopped":
        assert t10.ending == t12.ending
        assert not _beta_disagrees(t10.beta_stop, t12.beta_stop), (t10, t12)
    else:  # flagged honestly: pass
        assert {t10.status, t12.status} <= set(STATUSES)


SPIRAL_CASES = [
    (
        ss.Body(
            ss.Circle(0.05),
            ss.LinearPressure(-0.0020830611080099176, -0.004788148508472319),
            1.0,
            moment_of_inertia=0.0005565256700265922,
        ),
        ss.FrictionTensor(
            0.2593791951993214, 0.20167953119121104, f=0.044833357972838495, frame="body"
        ),
        ss.State(
            0, 0, 1.4994274608857485, 0.7033283268756602, -0.6075393333993169, 7.7747055316625335
        ),
    ),
    (
        ss.Body(
            ss.Circle(0.05), ss.BoussinesqPressure(), 1.0, moment_of_inertia=0.0007778147323165563
        ),
        ss.FrictionTensor(
            0.2772040871554792, 0.44201285949163216, f=-0.08736439788415284, angle=2.003097176707236
        ),
        ss.State(
            0, 0, 1.1537810640804418, 0.6983691200732901, -0.13694040360401472, 28.045577479965445
        ),
    ),
]


@pytest.mark.parametrize("case", range(len(SPIRAL_CASES)))
def test_spiral_beta_regression(case):
    """Found by the random sample: a spiral ending must report the same β* (inf or NaN) at
    rtol 1e-8, 1e-10, 1e-12 and with max_step = 0.05."""
    body, fr, st = SPIRAL_CASES[case]
    runs = [ss.simulate(body, fr, st, rtol=r) for r in (1e-8, 1e-10, 1e-12)]
    runs.append(ss.simulate(body, fr, st, max_step=0.05))
    stopped = [t for t in runs if t.status == "stopped"]
    assert len({t.ending for t in stopped}) <= 1, runs
    betas = [t.beta_stop for t in stopped]
    assert all(b == math.inf for b in betas) or all(math.isnan(b) for b in betas), runs


SPIN_CASES = [  # found by the random sample (cases 1426 and 2327 of draw_cases(3000, 2026))
    (
        ss.Body(
            ss.Ellipse(0.05, 0.010303102269376849),
            ss.HertzPressure(),
            1.0,
            moment_of_inertia=0.001975300271237699,
        ),
        ss.FrictionTensor(0.14858252129923374, 0.05, f=-0.04540615540514359, frame="body"),
        ss.State(
            0, 0, 1.866659243706846, -1.2623863575147818, 0.18065333677948744, -29.324075626474684
        ),
    ),
    (
        ss.Body(
            ss.Ellipse(0.05, 0.010562572224549493),
            ss.UniformPressure(),
            1.0,
            moment_of_inertia=0.003213096602449305,
        ),
        ss.FrictionTensor(
            0.17588331656228082, 0.06086386114522213, f=-0.039554829100677424, frame="body"
        ),
        ss.State(
            0, 0, 1.7227834509512927, -0.7670114774988998, 0.9524730689666113, 13.275420516226497
        ),
    ),
    # cases 3691 and 5462 of draw_cases(20000, 99): flips even between rtol 1e-12 and 1e-13
    (
        ss.Body(
            ss.Ellipse(0.05, 0.01091843712048407),
            ss.HertzPressure(),
            1.0,
            moment_of_inertia=0.0034258049004496104,
        ),
        ss.FrictionTensor(
            0.4808218889127691, 0.3089998718214164, f=-0.013018583248641732, frame="body"
        ),
        ss.State(
            0, 0, 1.2346053793007836, -0.2013552282249235, 0.12591258513890344, 26.85531194450988
        ),
    ),
    (
        ss.Body(
            ss.Ellipse(0.05, 0.01157643541284275),
            ss.HertzPressure(),
            1.0,
            moment_of_inertia=0.0033724744965222455,
        ),
        ss.FrictionTensor(0.13482471952531197, 0.05, f=-0.049836964248456364, frame="body"),
        ss.State(
            0, 0, 3.0732024977173866, 0.6046722055840362, -1.6034698092176127, 13.862871630230039
        ),
    ),
]


@pytest.mark.parametrize("case", range(len(SPIN_CASES)))
def test_pure_spinning_theta_regression(case):
    """A pure-spinning ending reports ϑ* NaN (no limiting direction) or the same ϑ* (1e-5 rad)
    at rtol 1e-8, 1e-10, 1e-12 and with max_step = 0.05, whenever it says ``stopped``."""
    body, fr, st = SPIN_CASES[case]
    runs = [ss.simulate(body, fr, st, rtol=r) for r in (1e-8, 1e-10, 1e-12)]
    runs.append(ss.simulate(body, fr, st, max_step=0.05))
    stopped = [t for t in runs if t.status == "stopped"]
    assert len({t.ending for t in stopped}) <= 1, runs
    for t in stopped[1:]:
        assert not _theta_disagrees(t.theta_stop, stopped[0].theta_stop), runs


# ------------------------------------------------------------------------------------------
# Table 2: every boundary gets its analytic ending, every interval its ending class
# ------------------------------------------------------------------------------------------
STARTS = [(1.0, 20.0, 0.3), (0.5, -40.0, 2.0), (2.0, 5.0, -1.2)]  # (v0 [m/s], ω0, ϑ0)
TENSORS = [(0.3, 0.45), (0.2, 0.5)]  # orthotropic, fx < fy, f = 0


def _table2_cases(targets):
    """Columns for simulate_cases: every law × tensor × start × I* from ``targets(law, fx,
    fy)`` (a list of (label, I*))."""
    rows = []
    for law in TABLE2_LAWS:
        for fx, fy in TENSORS:
            for label, i_star in targets(law, fx, fy):
                for v0, w0, th in STARTS:
                    rows.append(
                        {
                            "law": law,
                            "fx": fx,
                            "fy": fy,
                            "i_star": i_star,
                            "label": label,
                            "vx": v0 * math.cos(th),
                            "vy": v0 * math.sin(th),
                            "omega": w0,
                            "phi": 0.4,
                        }
                    )
    return rows, _boundary_columns(rows)


def _table2_row_text(row, res, i):
    return (
        f"{row['law']} disk a={A}, FrictionTensor({row['fx']}, {row['fy']}), "
        f"I*={row['i_star']!r} ({row['label']}), start vx={row['vx']:.6g} "
        f"vy={row['vy']:.6g} omega={row['omega']}: {_values(res, i)}"
    )


@pytest.mark.parametrize("rtol", [1e-8, 1e-10, 1e-12])
def test_table2_boundaries_get_their_analytic_endings(rtol):
    """I* = I₁: pure sliding (β* = inf); I* = I₃: pure spinning (β* = 0); status marginal or
    stopped, never another ending. I₁, I₃ from the printed formulas, the moment derivation
    and slidespin.inertia_intervals (they differ by < 1e-10). At I₂ (a hyperbolic fixed
    point): mixed with |β*|/a = 1, stopped."""

    def targets(law, fx, fy):
        pr = table2_printed(law, fx, fy)
        de = table2_derived(law, fx, fy)
        lib = inertia_intervals(_law(law), ss.FrictionTensor(fx, fy))
        return [
            ("I1 printed", pr[0]),
            ("I1 derived", de[0]),
            ("I1 library", lib.i1),
            ("I3 printed", pr[2]),
            ("I3 derived", de[1]),
            ("I3 library", lib.i3),
            ("I2 printed", pr[1]),
        ]

    rows, cols = _table2_cases(targets)
    res = simulate_cases(cols, rtol=rtol).as_dict()
    bad = []
    for i, row in enumerate(rows):
        st, end, beta = res["status"][i], res["ending"][i], res["beta_stop"][i]
        if row["label"].startswith("I1"):
            ok = st in ("marginal", "stopped") and end == "pure_sliding" and beta == math.inf
        elif row["label"].startswith("I3"):
            ok = st in ("marginal", "stopped") and end == "pure_spinning" and beta == 0.0
        else:
            ok = st == "stopped" and end == "mixed" and abs(abs(beta) / A - 1.0) <= BETA_REL
        if not ok:
            bad.append(_table2_row_text(row, res, i))
    assert not bad, f"{len(bad)} of {len(rows)} boundary runs wrong:\n" + "\n".join(bad)


def test_table2_interiors_get_their_ending_class():
    """Strictly inside each interval: pure sliding below I₁; mixed with k = |β*|/a > 1 in
    (I₁, I₂), k < 1 in (I₂, I₃); pure spinning above I₃; status stopped. The terminal
    velocity is along the low-friction axis OX (ϑ* = 0 mod π) unless the ending is pure
    spinning."""

    def targets(law, fx, fy):
        i1, i2, i3 = table2_printed(law, fx, fy)
        return [
            ("below I1", 0.6 * i1),
            ("(I1, I2)", 0.5 * (i1 + i2)),
            ("(I2, I3)", 0.5 * (i2 + i3)),
            ("above I3", 1.4 * i3),
        ]

    rows, cols = _table2_cases(targets)
    res = simulate_cases(cols).as_dict()
    bad = []
    for i, row in enumerate(rows):
        st, end = res["status"][i], res["ending"][i]
        k = abs(res["beta_stop"][i]) / A
        th = res["theta_stop"][i]
        ok = (
            st == "stopped"
            and {
                "below I1": end == "pure_sliding" and k == math.inf,
                "(I1, I2)": end == "mixed" and 1.0 < k < math.inf,
                "(I2, I3)": end == "mixed" and 0.0 < k < 1.0,
                "above I3": end == "pure_spinning" and k == 0.0,
            }[row["label"]]
        )
        if row["label"] != "above I3":
            ok = ok and abs(math.remainder(th, math.pi)) <= 1e-6
        if not ok:
            bad.append(_table2_row_text(row, res, i))
    assert not bad, f"{len(bad)} of {len(rows)} interior runs wrong:\n" + "\n".join(bad)


# ------------------------------------------------------------------------------------------
# ϑ* of an isotropic disk: the direction of the velocity is frozen by symmetry
# ------------------------------------------------------------------------------------------
ISO_STARTS = [(1.0, 20.0, 0.3), (0.4, -35.0, 3.1), (1.7, 8.0, -2.5)]  # (v0, ω0, ϑ0)


def _isotropic_runs(where, rtols=(1e-10,), max_steps=(None,)):
    """Runs of an isotropic disk (every law of Table 2) with I* in the region ``where``;
    yields (law, ϑ₀, settings, trajectory, expected ending)."""
    fx = 0.35
    ending = {"above I3": "pure_spinning", "(I1, I3)": "mixed", "below I1": "pure_sliding"}
    for law in TABLE2_LAWS:
        i1, _, i3 = table2_printed(law, fx, fx)
        i_star = {"above I3": 1.5 * i3, "(I1, I3)": 0.5 * (i1 + i3), "below I1": 0.5 * i1}[where]
        body = ss.Body.from_inertia_ratio(ss.Circle(A), _law(law), 1.3, i_star)
        for v0, w0, th in ISO_STARTS:
            for rtol in rtols:
                for ms in max_steps:
                    tr = ss.simulate(
                        body,
                        ss.FrictionTensor(fx, fx),
                        ss.State.from_speed(v0, w0, th, 0.9),
                        rtol=rtol,
                        max_step=ms,
                    )
                    yield law, th, {"rtol": rtol, "max_step": ms}, tr, ending[where]


def test_isotropic_disk_pure_spinning_keeps_its_direction():
    """Isotropic friction on a disk with a centred law: the mirror through G perpendicular to
    v maps the slip field to minus its mirror image, so F_n = 0 at every instant, ϑ stays ϑ₀,
    and the pure-spinning ending has ϑ* = ϑ₀ to 1e-9 (mod 2π): its vanishing velocity has a
    fixed direction."""
    for law, th, kw, tr, ending in _isotropic_runs("above I3", rtols=(1e-8, 1e-10, 1e-12)):
        assert tr.status == "stopped" and tr.ending == ending, (law, kw, tr)
        assert _angle_diff(tr.theta_stop, th) <= 1e-9, (law, th, kw, tr)


def test_isotropic_disk_mixed_and_sliding_keep_their_direction():
    """The same symmetry for mixed and pure-sliding endings: ϑ* = ϑ₀ to 1e-9 at rtol 1e-8,
    1e-10, 1e-12 and with max_step = 0.05 (the direction never moves)."""
    bad = []
    for where in ("(I1, I3)", "below I1"):
        for law, th, kw, tr, ending in _isotropic_runs(where, rtols=(1e-8, 1e-10, 1e-12)):
            if (
                tr.status != "stopped"
                or tr.ending != ending
                or _angle_diff(tr.theta_stop, th) > 1e-9
            ):
                bad.append(
                    f"{law} {where} theta0={th} {kw}: {tr!r} (ϑ*−ϑ₀ = {tr.theta_stop - th:.3g})"
                )
        for law, th, kw, tr, ending in _isotropic_runs(where, max_steps=(0.05,)):
            if tr.status == "stopped" and _angle_diff(tr.theta_stop, th) > 1e-9:
                bad.append(f"{law} {where} theta0={th} {kw}: {tr!r}")
    assert not bad, "\n".join(bad)


# ------------------------------------------------------------------------------------------
# spiral: pure sliding under a skew tensor with |f| > |μ|/2
# ------------------------------------------------------------------------------------------
def spiral_reference(fx, fy, f, v0, theta0, g=G):
    """(t_stop, |r_stop| vector, path length) of pure sliding under 𝔽 = [[fx, f], [-f, fy]].

    v̇ = −g v̂·𝔽v̂ = −g (fx c² + fy s²), v ϑ̇ = −g n̂·𝔽v̂ = g (f − μ s c) (c, s = cos ϑ, sin ϑ,
    n̂ = (−s, c)). With |f| > |μ|/2, ϑ turns monotonically; in ψ = |ϑ − ϑ₀|,
    d ln v/dψ = −α/|D|, dt/dψ = v/(g|D|), d(x, y)/dψ = v²(c, s)/(g|D|), dℓ/dψ = v²/(g|D|),
    α = fx c² + fy s², D = f − μ s c. Every turn of 2π multiplies v by q = e^(−Λ), so t by q
    and displacements by q²: one turn by scipy, then the geometric series."""
    mu = fy - fx
    sgn = math.copysign(1.0, f)

    def rhs(psi, y):
        th = theta0 + sgn * psi
        c, s = math.cos(th), math.sin(th)
        d = abs(f - mu * s * c)
        v = v0 * math.exp(y[0])
        w = v * v / (g * d)
        return [-(fx * c * c + fy * s * s) / d, v / (g * d), w * c, w * s, w]

    sol = solve_ivp(rhs, (0.0, 2.0 * math.pi), [0.0] * 5, method="DOP853", rtol=1e-13, atol=1e-16)
    ln_q, t1, x1, y1, l1 = sol.y[:, -1]
    q = math.exp(ln_q)
    return t1 / (1.0 - q), np.array([x1, y1]) / (1.0 - q * q), l1 / (1.0 - q * q)


def test_spiral_reference_closed_form_for_mu_zero():
    """The reference reproduces v₀/(c g), v₀²/(2 c g) and v₀²/(g √(4c² + f²)) at μ = 0."""
    c, f, v0 = 0.4, 0.3, 1.5
    t, r, ell = spiral_reference(c, c, f, v0, 0.7)
    assert t == pytest.approx(v0 / (c * G), rel=1e-11)
    assert ell == pytest.approx(v0**2 / (2 * c * G), rel=1e-11)
    assert np.hypot(*r) == pytest.approx(v0**2 / (G * math.sqrt(4 * c * c + f * f)), rel=1e-11)


@pytest.mark.parametrize("law", LAW_NAMES)
@pytest.mark.parametrize(
    "fx, fy, f, theta0",
    [
        (0.3, 0.5, 0.15, 0.4),  # μ = 0.2, f > μ/2
        (0.45, 0.25, -0.11, -2.0),  # μ = −0.2, |f| > |μ|/2, turning the other way
        (0.2, 0.2, 0.05, 1.0),  # μ = 0
    ],
)
def test_pure_sliding_spiral(law, fx, fy, f, theta0):
    """Pure sliding (ω₀ = 0) under a skew tensor with |f| > |μ|/2: ending ``spiral``, status
    ``stopped``, ϑ* NaN, β* inf; t_stop, the stop position and the path length as the
    reference (relative 1e-9)."""
    v0 = 1.2
    body = ss.Body(ss.Ellipse(A, 0.6 * A), _law(law, 0.1 * A, -0.1 * 0.6 * A), 1.0)
    tr = ss.simulate(
        body, ss.FrictionTensor(fx, fy, f=f), ss.State.from_speed(v0, 0.0, theta0, 0.3)
    )
    t_ref, r_ref, l_ref = spiral_reference(fx, fy, f, v0, theta0)
    assert (tr.status, tr.ending) == ("stopped", "spiral"), tr
    assert math.isnan(tr.theta_stop) and tr.beta_stop == math.inf, tr
    assert tr.t_stop == pytest.approx(t_ref, rel=1e-9)
    assert tr.distance == pytest.approx(l_ref, rel=1e-9)
    assert [tr.stop_state.x, tr.stop_state.y] == pytest.approx(
        r_ref, rel=1e-9, abs=1e-9 * np.hypot(*r_ref)
    )


def test_pure_sliding_spiral_in_batch_and_body_frame():
    """The same through simulate_cases, with the tensor turned by ``angle`` and fixed to the
    body (ω = 0 keeps φ fixed, so the world tensor is turned by φ + angle; the skew part is
    invariant, the reference is solved in the turned frame and turned back)."""
    fx, fy, f, v0, th0, phi0, ang = 0.3, 0.55, 0.14, 0.9, 0.2, 0.7, 0.3
    rot = phi0 + ang
    res = simulate_cases(
        {
            "a": A,
            "b": 0.5 * A,
            "law": "hertz",
            "fx": fx,
            "fy": fy,
            "f": f,
            "frame": "body",
            "angle": ang,
            "vx": v0 * math.cos(th0),
            "vy": v0 * math.sin(th0),
            "omega": 0.0,
            "phi": phi0,
        }
    )
    t_ref, r_ref, l_ref = spiral_reference(fx, fy, f, v0, th0 - rot)
    c, s = math.cos(rot), math.sin(rot)
    r_ref = np.array([c * r_ref[0] - s * r_ref[1], s * r_ref[0] + c * r_ref[1]])
    assert (res.status[0], res.ending[0]) == ("stopped", "spiral")
    assert math.isnan(res.theta_stop[0]) and res.beta_stop[0] == math.inf
    assert res.t_stop[0] == pytest.approx(t_ref, rel=1e-9)
    assert res.path_length[0] == pytest.approx(l_ref, rel=1e-9)
    assert [res.x_stop[0], res.y_stop[0]] == pytest.approx(
        r_ref, rel=1e-9, abs=1e-9 * np.hypot(*r_ref)
    )


# ------------------------------------------------------------------------------------------
# JSON and column output carry the status
# ------------------------------------------------------------------------------------------
def test_summary_and_json_carry_status_ending_saddle_energy():
    body, fr, st = SADDLE_CASE
    for tr in (ss.simulate(body, fr, st), ss.simulate(body, fr, ss.State.from_speed(1, 5, 0.7))):
        d = tr.summary()
        assert d["status"] == tr.status and d["ending"] == tr.ending
        assert d["status_message"] == tr.status_message
        se = json.loads(tr.to_json())["saddle_energy"]
        if math.isnan(tr.saddle_energy):
            assert d["saddle_energy"] is None and se is None
        else:
            assert d["saddle_energy"] == tr.saddle_energy == se


def test_stop_results_as_dict_carries_status_and_saddle_energy():
    body, fr, st = SADDLE_CASE
    cases = {
        "a": body.patch.a,
        "b": body.patch.b,
        "fx": np.array([fr.fx, 0.3]),
        "fy": np.array([fr.fy, 0.4]),
        "moment_of_inertia": body.moment_of_inertia,
        "mass": 1.0,
        "phi": st.phi,
        "vx": st.vx,
        "vy": st.vy,
        "omega": st.omega,
    }
    res = simulate_cases(cases)
    d = res.as_dict()
    assert list(d["status"]) == list(res.status) and len(d["status"]) == 2
    assert set(d["status"]) <= set(STATUSES)
    se = np.asarray(d["saddle_energy"], float)
    for i in range(2):
        tr = ss.simulate(*case_objects(cases, i))
        assert d["status"][i] == tr.status and d["ending"][i] == tr.ending
        if d["status"][i] == "saddle":
            assert 0.0 < se[i] < 1.0
        else:
            assert math.isnan(se[i])
