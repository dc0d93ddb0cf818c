"""Bit-for-bit fingerprint of the numbers slidespin prints, to show a refactor changes nothing.

Seeded computations through the public API only (``import slidespin as ss``) and the command
line (``python -m slidespin`` subprocesses), so it survives modules moving; floats are stored
as ``float.hex`` (CLI JSON parsed and re-encoded; raw stdout hashed as well). Sections: demo,
cases (200 seeded stops: simulate_cases, simulate_bodies, simulate, simulate_many), wrench
(every patch kind, a PressureMap), analysis (terminal states, inertia intervals, limit surface,
statics, loaded motion), reproduce (every target, --json), bench (the deterministic figures of
a minimal --quick run). Timings and PNG bytes are left out. Usage, from the repository root:

    python tools/fingerprint.py record /tmp/fingerprint-before.json   # before the refactor
    python tools/fingerprint.py check /tmp/fingerprint-before.json    # per section: identical,
    python tools/fingerprint.py check FILE --only cases,wrench        # or the first differences
"""

from __future__ import annotations

import argparse
import dataclasses
import hashlib
import json
import math
import os
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

import slidespin as ss

SEED = 2026
PI = math.pi
SCALARS = (int, float, complex, str)
LAWS = ("uniform", "linear", "boussinesq", "hertz")
LOADED = ("t", "x", "y", "phi", "vx", "vy", "omega", "friction_work", "load_work")
STOPS = ("t_stop", "beta_stop", "theta_stop", "x_stop", "y_stop", "phi_stop", "path_length")
STOPS += ("saddle_energy", "n_steps", "status", "ending")
TRAJ = ("t_stop", "beta_stop", "theta_stop", "status", "ending", "n_steps", "n_rhs", "stop_state")
SERIES = ("t", "x", "y", "phi", "omega", "path_length")
WRENCH = ("force_x", "force_y", "moment", "tangential", "normal", "moment_paper", "theta")
NAMES = ("demo", "cases", "wrench", "analysis", "reproduce", "bench")
REPRODUCE = ("table1", "table2", "fig2", "fig3", "fig4", "errata", "phase", "all")
BENCH = "bench --quick --no-compile --json --no-save --naive-seconds 1 --batch 10"
BENCH += " --memory-cases 10 --sweep-local 0 --sweep-dask 0"
FP_KEYS = "extent_m wrench_max_abs_error trajectory_steps trajectory_rhs status batch_mean_steps"


def enc(v) -> str:
    """One value as an exact string (floats as hex, arrays element by element)."""
    if isinstance(v, (np.generic, np.ndarray)):
        v = v.tolist()
    if isinstance(v, float):
        return v.hex()
    if isinstance(v, complex):
        return f"({v.real.hex()},{v.imag.hex()}j)"
    if isinstance(v, (list, tuple)):
        return "[" + ",".join(map(enc, v)) + "]"
    return repr(v)


def digest(a) -> str:
    """sha256 of a text or of an array's float64 bytes."""
    data = a.encode() if isinstance(a, str) else np.asarray(a, dtype=float).tobytes()
    return hashlib.sha256(data).hexdigest()[:24]


def flat(out: dict, key: str, v) -> None:
    """Put ``v`` into ``out`` under ``key``, recursing into records and non-scalar sequences."""
    if hasattr(v, "_asdict"):
        v = v._asdict()
    elif dataclasses.is_dataclass(v) and not isinstance(v, type):
        v = dataclasses.asdict(v)
    if isinstance(v, dict):
        items = v.items()
    elif isinstance(v, (list, tuple)) and not all(isinstance(x, SCALARS) for x in v):
        items = enumerate(v)
    else:
        out[key] = enc(v)
        return
    for k, x in items:
        flat(out, f"{key}/{k}", x)


def cli(args, tmp) -> tuple[str, int]:
    """stdout (``tmp`` written as <TMP>) and exit status of ``python -m slidespin ARGS``."""
    cmd = [sys.executable, "-m", "slidespin", *args]
    p = subprocess.run(cmd, cwd=tmp, capture_output=True, text=True, timeout=900)
    return p.stdout.replace(os.path.realpath(tmp), "<TMP>").replace(tmp, "<TMP>"), p.returncode


def put_output(out: dict, key: str, run: tuple[str, int], drop=("seconds",)) -> None:
    """CLI output: exit status, hash of the text, its JSON flattened (or its lines), sans drop."""
    text, status = run
    out[f"{key}/exit"] = str(status)
    lines = [ln for ln in text.splitlines() if not any(f'"{k}":' in ln for k in drop)]
    out[f"{key}/raw"] = digest("\n".join(lines))
    try:
        data = json.loads(text)
    except ValueError:
        data = {f"line{i:03d}": line for i, line in enumerate(text.splitlines())}
    flat(out, key, {k: x for k, x in data.items() if k not in drop})


def sec_demo(tmp):
    out: dict = {}
    put_output(out, "plot", cli(["demo", "--plot", os.path.join(tmp, "demo.png")], tmp))
    put_output(out, "json", cli(["demo", "--json"], tmp))
    return out


def put_stops(out, prefix, res):
    d = res.as_dict()
    for i in range(len(res)):
        out[f"{prefix}/{i:03d}"] = ";".join(f"{k}={enc(d[k][i])}" for k in STOPS)


def put_traj(out, key, tr):
    flat(out, key, {k: getattr(tr, k) for k in TRAJ})
    out[key + "/series"] = ";".join(digest(getattr(tr, k)) for k in SERIES)


def law_of(name, xi=0.0, eta=0.0):
    return getattr(ss, name.capitalize() + "Pressure")(*((xi, eta) if name == "linear" else ()))


def ellipse_columns(rng, n):
    """Columns of n random elliptic cases for simulate_cases (the last two: at rest, and the
    Hertz circle at I* = 1/2, a marginal stop)."""
    spans = {"a": (0.02, 0.2), "b": (0.2, 1.0), "fx": (0.1, 0.8), "fy": (0.1, 0.8), "x": (-1, 1)}
    spans |= {"y": (-1, 1), "phi": (-PI, PI), "angle": (-PI, PI), "mass": (0.2, 5.0), "g": (1, 20)}
    spans |= {"omega": (-30, 30), "speed": (0, 2), "theta": (-PI, PI), "f": (-0.2, 0.2)}
    c = {k: rng.uniform(lo, hi, n) for k, (lo, hi) in spans.items()}
    u, law, (r, t) = rng.uniform(0, 1, (6, n)), rng.integers(0, 4, n), rng.uniform(0, 1, (2, n))
    c["b"] *= c["a"]
    c["law"] = [LAWS[k] for k in law]
    c["xi_c"] = np.where(law == 1, 0.24 * np.sqrt(r) * np.cos(2 * PI * t) * c["a"], 0.0)
    c["eta_c"] = np.where(law == 1, 0.24 * np.sqrt(r) * np.sin(2 * PI * t) * c["b"], 0.0)
    c["f"] = np.where(u[1] < 0.3, c["f"] * np.minimum(c["fx"], c["fy"]), 0.0)
    c["frame"] = ["plane" if x < 0.5 else "body" for x in u[2]]
    inertia = c["mass"] * c["a"] ** 2 * (0.1 + 0.7 * u[0])
    c["moment_of_inertia"] = np.where(u[3] < 0.5, np.nan, inertia)
    c["g"] = np.where(u[4] < 0.8, 9.81, c["g"])
    c["vx"], c["vy"] = c["speed"] * np.cos(c["theta"]), c["speed"] * np.sin(c["theta"])
    c["omega"] = np.where(u[5] < 0.05, 0.0, c.pop("omega"))
    del c["speed"], c["theta"]
    c["vx"][-2] = c["vy"][-2] = c["omega"][-2] = c["xi_c"][-1] = c["eta_c"][-1] = c["f"][-1] = 0.0
    c["law"][-1], c["b"][-1], c["fy"][-1] = "hertz", c["a"][-1], c["fx"][-1]
    c["moment_of_inertia"][-1] = 0.5 * c["mass"][-1] * c["a"][-1] ** 2
    return c


def footprint_body(rng, kind):
    """A random body on a footprint of ``kind`` (rectangle, disk, ring, convex polygon, pads)
    under uniform, linear (G near the area centroid) or, for a disk, Hertz/Boussinesq load."""
    s = rng.uniform(0.03, 0.3)
    c, ang = tuple(rng.uniform(-0.2, 0.2, 2) * s), rng.uniform(-PI, PI)
    if kind == 0:
        fp = ss.Rectangle(s, s * rng.uniform(0.1, 1.0), centre=c, angle=ang)
    elif kind == 1:
        fp = ss.Disk(s, centre=c)
    elif kind == 2:
        fp = ss.Annulus(s * rng.uniform(0.3, 0.95), s, centre=c)
    elif kind == 3:  # 3-9 vertices on an ellipse: convex
        k, q = int(rng.integers(3, 10)), rng.uniform(0.3, 1.0)
        t = np.linspace(0, 2 * PI, k, endpoint=False) + rng.uniform(-0.4, 0.4, k) * PI / k
        fp = ss.Polygon(list(zip((s * np.cos(t)).tolist(), (q * s * np.sin(t)).tolist())), c, ang)
    else:
        w = s * rng.uniform(0.05, 0.3)
        disk = ss.Disk(w, centre=(s * rng.uniform(1.2, 2.0), 0.0))
        fp = ss.Pads([ss.Rectangle(s, w, centre=(0, -s)), ss.Rectangle(s, w, centre=(0, s)), disk])
    mass, u = rng.uniform(0.2, 5.0), rng.uniform(0, 1)
    off = rng.uniform(-0.05, 0.05, 2) * fp.extent
    inertia = mass * fp.extent**2 * rng.uniform(0.1, 0.8) if rng.uniform(0, 1) < 0.5 else None
    if u < 0.4:
        law = ss.LinearPressure(*(np.asarray(fp.centroid) + off).tolist())
    elif kind == 1 and u > 0.85:
        law = ss.HertzPressure() if u > 0.93 else ss.BoussinesqPressure()
    else:
        law = ss.UniformPressure()
    return ss.Body(fp, law, mass=mass, moment_of_inertia=inertia)


def random_friction(rng):
    fx, fy, f, u, frame, angle = rng.uniform([0.1, 0.1, -0.2, 0, 0, -PI], [0.8, 0.8, 0.2, 1, 1, PI])
    f = f * min(fx, fy) if u < 0.3 else 0.0
    return ss.FrictionTensor(fx, fy, f, "body" if frame < 0.5 else "plane", angle)


def random_states(rng, n):
    spd, th = rng.uniform(0.0, 2.0, n), rng.uniform(-PI, PI, n)
    v = np.column_stack([spd * np.cos(th), spd * np.sin(th), rng.uniform(-30, 30, n)])
    return np.column_stack([rng.uniform(-1, 1, (n, 3)), v])


def sec_cases(tmp):
    out: dict = {}
    rng = np.random.default_rng(SEED)
    c = ellipse_columns(rng, 100)
    put_stops(out, "ellipse", ss.simulate_cases(c))
    for i in [*range(0, 100, 10), 98, 99]:  # the same cases one by one through simulate()
        inertia = None if np.isnan(c["moment_of_inertia"][i]) else c["moment_of_inertia"][i]
        law = law_of(c["law"][i], c["xi_c"][i], c["eta_c"][i])
        body = ss.Body(ss.Ellipse(c["a"][i], c["b"][i]), law, c["mass"][i], inertia)
        fr = ss.FrictionTensor(*(c[k][i] for k in ("fx", "fy", "f", "frame", "angle")))
        st = ss.State(*(c[k][i] for k in ("x", "y", "phi", "vx", "vy", "omega")))
        put_traj(out, f"ellipse-simulate/{i:03d}", ss.simulate(body, fr, st, g=c["g"][i]))
    bodies = [footprint_body(rng, i % 5) for i in range(100)]
    frictions = [random_friction(rng) for _ in range(100)]
    states = random_states(rng, 100)
    put_stops(out, "footprint", ss.simulate_bodies(bodies, frictions, states))
    for i in range(0, 100, 7):
        tr = ss.simulate(bodies[i], frictions[i], ss.State(*states[i]))
        put_traj(out, f"footprint-simulate/{i:03d}", tr)
    demo = ss.Body(ss.Ellipse(0.1, 0.05), ss.UniformPressure(), mass=1.0)
    put_stops(out, "many", ss.simulate_many(demo, random_friction(rng), random_states(rng, 20)))
    blade = ss.Body(ss.Blade(0.3), ss.UniformPressure(), mass=2.0)
    put_stops(out, "blade", ss.simulate_many(blade, random_friction(rng), random_states(rng, 10)))
    return out


def sec_wrench(tmp):
    out: dict = {}
    rng = np.random.default_rng(SEED + 1)
    el, uni = ss.Ellipse(0.1, 0.06), ss.UniformPressure()
    bodies = {f"ellipse-{n}": ss.Body(el, law_of(n, 0.01, -0.005), mass=1.3) for n in LAWS}
    bodies["circle-uniform"] = ss.Body(ss.Circle(0.08), uni, mass=0.7)
    bodies["circle-hertz"] = ss.Body(ss.Circle(0.08), ss.HertzPressure(), mass=0.7)
    runners = [ss.Rectangle(0.4, 0.02, centre=(0, y)) for y in (-0.1, 0.1)]
    fps = {
        "rectangle": ss.Rectangle(0.2, 0.1, centre=(0.01, 0.02), angle=0.3),
        "disk": ss.Disk(0.07),
        "annulus": ss.Annulus(0.05, 0.065),
        "polygon": ss.Polygon([(0, 0), (4, 0), (4, 1), (1, 1), (1, 3), (0, 3)], angle=0.2),
        "pads": ss.Pads([*runners, ss.Disk(0.03, centre=(0.3, 0.0))]),
    }
    for name, fp in fps.items():
        bodies[f"{name}-uniform"] = ss.Body(fp, uni, mass=2.0)
        xi, eta = fp.centroid
        bodies[f"{name}-linear"] = ss.Body(fp, ss.LinearPressure(xi + 0.003, eta - 0.002), mass=2.0)
    bodies["disk-boussinesq"] = ss.Body(fps["disk"], ss.BoussinesqPressure(), mass=2.0)
    bodies["blade"] = ss.Body(ss.Blade(0.3), uni, mass=1.5)
    bodies["blade-offset"] = ss.Body(ss.Blade(0.3, centre=(0.0, 0.05), angle=0.4), uni, mass=1.5)
    for name, body in bodies.items():
        fr = random_friction(rng)
        (vx, vy), om = rng.uniform(-1, 1, (2, 20)), rng.uniform(-20, 20, 20)
        phi = rng.uniform(-3, 3)
        vx[0] = vy[0] = om[1] = 0.0  # a pure spin and a pure slide
        w = ss.friction_wrench(body, fr, vx, vy, om, phi)
        flat(out, name, {k: np.asarray(getattr(w, k)) for k in WRENCH})
        w1 = ss.friction_wrench(body, fr, float(vx[5]), float(vy[5]), float(om[5]), phi, g=3.7)
        out[f"{name}/scalar"] = enc([getattr(w1, k) for k in WRENCH])
    pm = ss.PressureMap(lambda x, e: 1.0 + 2.0 * x + 10.0 * e * e)
    fr = random_friction(rng)
    vx, vy, om = rng.uniform(-1, 1, 20), rng.uniform(-1, 1, 20), rng.uniform(-20, 20, 20)
    body = ss.Body(ss.Rectangle(0.2, 0.1), pm, 1.0)  # the load m g = 9.81 N
    w = ss.friction_wrench(body, fr, vx, vy, om, 0.2)
    flat(out, "pressure-map", {k: np.asarray(getattr(w, k)) for k in WRENCH})
    return out


def sec_analysis(tmp):
    out: dict = {}
    fr, uni = ss.FrictionTensor(0.42, 0.54), ss.UniformPressure()
    bodies = {
        "ellipse": ss.Body(ss.Ellipse(0.1, 0.05), uni, mass=1.0),
        "ellipse-linear": ss.Body(ss.Ellipse(0.1, 0.06), ss.LinearPressure(0.01, 0.005), mass=1.0),
        "rectangle": ss.Body(ss.Rectangle(0.2, 0.12), uni, mass=2.0),
    }
    for name, body in bodies.items():
        flat(out, f"terminal_states/{name}", ss.terminal_states(body, fr, 0.3))
        for th in (0.0, 0.7):
            out[f"terminal_ratio/{name}/{th}"] = enc(ss.terminal_ratio(body, fr, 0.3, th))
    ortho = ss.FrictionTensor(0.3, 0.45)
    for n in LAWS:
        law = law_of(n)
        flat(out, f"inertia_intervals/{n}", ss.inertia_intervals(law, ortho))
        flat(out, f"paper_inertia_intervals/{n}", ss.paper_inertia_intervals(law, ortho))
        out[f"circle_terminal_ratio/{n}"] = enc(ss.circle_terminal_ratio(law, ortho, 0.6))
        out[f"inertia_for_ratio/{n}"] = enc(ss.inertia_for_ratio(law, ortho, np.array([0.2, 0.5])))
    flat(out, "inertia_intervals/annulus", ss.inertia_intervals(uni, ortho, ss.Annulus(0.05, 0.06)))
    for name in ("ellipse", "rectangle"):
        ls = vars(ss.limit_surface(bodies[name], fr, n=24, phi=0.2, quartic_directions=24))
        flat(out, f"limit_surface/{name}", {k: ls[k] for k in ls if k not in ("body", "friction")})
    box = bodies["rectangle"]
    aniso = ss.FrictionTensor(0.3, 0.4, f=0.01, frame="body", angle=0.2)
    load = ss.Load(force=(5.0, 1.5), torque=0.3, frame="body", at=(0.05, 0.02))
    statics = {
        "load": (load.wrench(0.0, phi=0.4, mass_centre=box.mass_centre), None),
        "load-weak": ((1.0, 0.5, 0.01), None),
        "incline": ((0.0, 0.0, 0.0), ss.Incline(math.radians(25.0), downhill=0.3)),
        "incline+load": ((1.0, -0.5, 0.02), ss.Incline(math.radians(12.0))),
    }
    for name, (w, inc) in statics.items():
        out[f"statics/{name}/can_stick"] = enc(ss.can_stick(box, aniso, w, 0.4, incline=inc))
        out[f"statics/{name}/load_factor"] = enc(ss.load_factor(box, aniso, w, 0.4, incline=inc))
        flat(out, f"statics/{name}/onset", ss.onset(box, aniso, w, 0.4, incline=inc))
    out["statics/critical_tilt"] = enc(ss.critical_tilt(box, aniso, downhill=0.3, phi=0.4))
    push = ss.Load.piecewise_linear([0, 2, 3, 3.1], [0, 25, 25, 0], [0, 0, 0, 0])
    box5 = ss.Body(ss.Rectangle(0.4, 0.3), uni, mass=5.0)
    puck = ss.Body(ss.Circle(0.04), uni, mass=0.2)
    iso, slope = ss.FrictionTensor.isotropic, ss.Incline(math.radians(20.0))
    runs = {
        "pushed-box": (box5, iso(0.35), ss.State(), push, None, 5.0),
        "puck-slope": (puck, iso(0.3), ss.State(omega=30.0), None, slope, 1.0),
        "aniso-load": (box, aniso, ss.State(vx=0.3, omega=2.0), load, ss.Incline(0.1), 2.0),
    }
    for name, (body, f, st, ld, inc, t_end) in runs.items():
        tr = ss.simulate_loaded(body, f, st, load=ld, incline=inc, t_end=t_end)
        k = f"simulate_loaded/{name}"
        flat(out, k, {a: getattr(tr, a)[-1] for a in LOADED} | {"phases": list(tr.phases)})
        out[k + "/outcome"] = enc([tr.status, tr.ending, tr.n_rhs, tr.energy_error])
        out[k + "/series"] = ";".join(digest(getattr(tr, a)) for a in SERIES[:-1])
    return out


def sec_reproduce(tmp):
    out: dict = {}
    for target in REPRODUCE:
        t0, folder = time.perf_counter(), os.path.join(tmp, target)
        put_output(out, target, cli(["reproduce", target, "--json", "--out", folder], tmp))
        print(f"    reproduce {target}: {time.perf_counter() - t0:.1f} s")
    for name in sorted(os.listdir(os.path.join(tmp, "all"))):  # the files 'all' writes
        if name.endswith((".json", ".txt", ".html")):
            with open(os.path.join(tmp, "all", name), encoding="utf-8") as fh:
                text = fh.read().replace(tmp, "<TMP>")
            text = re.sub(r"reproduce all</code> in \d+ s", "reproduce all</code> in <T> s", text)
            put_output(out, f"all-files/{name}", (text, 0))
    return out


def sec_bench(tmp):
    """The deterministic figures of a minimal quick bench (all timings left out)."""
    text, status = cli(BENCH.split(), tmp)
    out: dict = {"exit": str(status)}
    r = json.loads(text)
    flat(out, "accuracy", r["accuracy"])
    for part, keys in (("footprint", FP_KEYS), ("trajectory", "steps rhs t_stop_s")):
        flat(out, part, {n: {k: d.get(k) for k in keys.split()} for n, d in r[part].items()})
    rows = [line for line in r["table"].splitlines() if line.strip("| ").startswith("accuracy")]
    flat(out, "table", {i: " ".join(line.split()) for i, line in enumerate(rows)})
    return out


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("mode", choices=("record", "check"))
    p.add_argument("file", help="fingerprint JSON file")
    p.add_argument("--only", help=f"comma-separated subset of {','.join(NAMES)}")
    args = p.parse_args(argv)
    sys.stdout.reconfigure(line_buffering=True)
    names = [s.strip() for s in args.only.split(",")] if args.only else list(NAMES)
    if bad := [s for s in names if s not in NAMES]:
        p.error(f"unknown section(s) {bad}; valid: {', '.join(NAMES)}")
    check = args.mode == "check"
    recorded = json.loads(Path(args.file).read_text(encoding="utf-8"))["sections"] if check else {}
    if missing := [s for s in names if check and s not in recorded]:
        p.error(f"{args.file} has no section(s) {missing}")
    result, t0 = {}, time.perf_counter()
    with tempfile.TemporaryDirectory(prefix="slidespin-fp-") as tmp:
        for name in names:
            t1 = time.perf_counter()
            result[name] = globals()["sec_" + name](tmp)
            print(f"[{name}] {len(result[name])} keys, {time.perf_counter() - t1:.1f} s")
    print(f"total {time.perf_counter() - t0:.1f} s")
    if not check:
        text = json.dumps({"slidespin": ss.__version__, "sections": result}, indent=1)
        Path(args.file).write_text(text + "\n", encoding="utf-8")
        print(f"recorded {sum(map(len, result.values()))} keys in {args.file}")
        return 0
    ok = True
    for name in names:  # compare, section by section
        want, got = recorded[name], result[name]
        keys = list(dict.fromkeys([*want, *got]))
        diff = [k for k in keys if want.get(k) != got.get(k)]
        ok &= not diff
        print(f"{name}: {f'{len(diff)} keys DIFFER' if diff else 'identical'} ({len(keys)} keys)")
        for k in diff[:8]:
            print(f"  {k}\n    recorded: {want.get(k, '<missing>')}")
            print(f"    now:      {got.get(k, '<missing>')}")
    print("IDENTICAL" if ok else "DIFFERENT")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
