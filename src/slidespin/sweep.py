"""Parameter sweeps: many cases, chunked, crash-safe and resumable, locally or on Dask.

A sweep specification (TOML, see ``examples/sweep_*.toml``) fixes some parameters and varies
others on a grid or by random sampling. The cases are numbered deterministically and cut into
chunks; each finished chunk is written to ``DIR/chunks/chunk-NNNNNN.parquet`` under a temporary
name and renamed into place, and ``DIR/manifest.json`` records the spec, its hash, the package
version and the chunks done. A sweep killed at any moment loses only its unfinished chunks;
``resume=True`` computes exactly the missing ones.

Executors: by default all local cores (the compiled batch engine, :func:`simulate_cases`);
a ``dask.distributed.Client`` (or any ``concurrent.futures.Executor``) runs consecutive chunks
of at least 1000 cases per task; the results are identical to the local ones, bit for bit.

Parameters a spec may fix or vary (SI units, angles in radians):

==================  ==========================================================
``a``               semi-axis along ξ [m] (required)
``b`` | ``e`` | ``aspect``   semi-axis along η [m], or eccentricity, or b/a (default: circle)
``law``             uniform | linear | boussinesq | hertz
``xi_c``, ``eta_c`` linear-law centroid = mass centre [m]
``fx``              friction coefficient along the tensor's first axis (required)
``fy`` | ``mu``     second coefficient, or μ = fy − fx (one required)
``f``               skew coefficient
``frame``           plane | body
``angle``           principal axes of the tensor [rad]
``mass``            [kg]
``I_star`` | ``moment_of_inertia``   I/(m a²), or I [kg m²] (default: uniform plate)
``g``               [m/s²]
``v0``, ``theta0``  initial speed of G [m/s] and its direction [rad]
``omega0``          initial spin [rad/s]
``phi0``, ``x0``, ``y0``  initial body angle [rad] and position [m]
==================  ==========================================================
"""

from __future__ import annotations

import copy
import hashlib
import json
import math
import os
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from . import _validate as v
from ._cases import validated_columns
from .batch import simulate_cases
from .pressure import LAW_NAMES

__all__ = ["SweepSpec", "load_spec", "sweep", "read_sweep", "compute_chunk", "compute_chunks",
           "connect_dask", "PARAMETERS", "SweepError", "SweepResult"]

PARAMETERS = {
    "a": None, "b": None, "e": None, "aspect": None, "law": "uniform", "xi_c": 0.0,
    "eta_c": 0.0, "fx": None, "fy": None, "mu": None, "f": 0.0, "frame": "plane",
    "angle": 0.0, "mass": 1.0, "I_star": None, "moment_of_inertia": None, "g": 9.81,
    "v0": 0.0, "theta0": 0.0, "omega0": 0.0, "phi0": 0.0, "x0": 0.0, "y0": 0.0,
}
_STRING_PARAMS = {"law": LAW_NAMES, "frame": ("plane", "body")}
_EXCLUSIVE = (("b", "e", "aspect"), ("fy", "mu"), ("I_star", "moment_of_inertia"))
_TOP_KEYS = {"name", "description", "kind", "chunk_size", "rtol", "fixed", "vary", "random"}
RESULT_COLUMNS = (
    "t_stop", "beta_stop", "theta_stop", "phi_stop", "x_stop", "y_stop", "path_length",
    "ending", "status", "n_steps",
)
MANIFEST = "manifest.json"
#: smallest number of cases per task sent to an executor (Dask or concurrent.futures)
MIN_TASK_CASES = 1000


class SweepError(ValueError):
    """A sweep cannot start or resume (bad spec, foreign directory, missing extra)."""


# --------------------------------------------------------------------------- specification
@dataclass(frozen=True)
class SweepSpec:
    """A validated sweep specification.

    Attributes
    ----------
    data : dict
        The specification as parsed from TOML (canonical form; hashed for resuming).
    n_cases : int
        Number of cases.
    chunk_size : int
        Cases per chunk (one file, one task).
    """

    data: dict = field(repr=False)
    n_cases: int
    chunk_size: int

    @property
    def name(self) -> str:
        return self.data.get("name", "")

    @property
    def n_chunks(self) -> int:
        return -(-self.n_cases // self.chunk_size)

    @property
    def digest(self) -> str:
        """SHA-256 of the canonical specification."""
        text = json.dumps(self.data, sort_keys=True, separators=(",", ":"))
        return hashlib.sha256(text.encode()).hexdigest()

    def varied(self) -> list[str]:
        """Names of the varied parameters, in spec order."""
        return list(self.data.get("vary", {}))

    def parameters(self, start: int = 0, stop: int | None = None) -> dict:
        """Parameter columns (name → array) of the cases ``start:stop``."""
        stop = self.n_cases if stop is None else min(stop, self.n_cases)
        idx = np.arange(start, stop)
        fixed = self.data.get("fixed", {})
        vary = self.data.get("vary", {})
        cols: dict = {}
        if self.data.get("kind", "grid") == "grid":
            axes = [_grid_values(k, spec) for k, spec in vary.items()]
            shape = [len(ax) for ax in axes]
            if axes:
                sub = np.unravel_index(idx, shape)
                for (k, ax), s in zip(zip(vary, axes), sub):
                    cols[k] = np.asarray(ax)[s]
        else:
            rnd = self.data["random"]
            # one independent stream per parameter, drawn for all cases: reproducible for any
            # chunk, whatever the order chunks are computed in
            for j, (k, spec) in enumerate(vary.items()):
                rng = np.random.default_rng([int(rnd.get("seed", 0)), j])
                allv = _random_values(k, spec, rng, self.n_cases)
                cols[k] = allv[start:stop]
        for k, val in fixed.items():
            cols[k] = np.full(idx.size, val, dtype=object if isinstance(val, str) else float)
        cols["case_id"] = idx
        return cols


def _grid_values(name, spec):
    if isinstance(spec, list):
        if not spec:
            raise SweepError(f"[vary] {name} is an empty list")
        return [_check_value(name, x) for x in spec]
    if isinstance(spec, dict):
        _only(spec, {"start", "stop", "num", "log"}, f"[vary] {name}")
        num = spec.get("num")
        if isinstance(num, bool) or not isinstance(num, int) or num < 1:
            raise SweepError(f"[vary] {name}.num = {num!r} is invalid; valid range: integer >= 1")
        lo = v.finite(f"[vary] {name}.start", spec.get("start"))
        hi = v.finite(f"[vary] {name}.stop", spec.get("stop"))
        if spec.get("log", False):
            if lo <= 0 or hi <= 0:
                raise SweepError(f"[vary] {name}: log spacing needs start, stop > 0")
            vals = np.geomspace(lo, hi, num)
        else:
            vals = np.linspace(lo, hi, num)
        return [_check_value(name, float(x)) for x in vals]
    raise SweepError(f"[vary] {name} = {spec!r}: give a list of values or "
                     "{start, stop, num[, log]}")


def _random_values(name, spec, rng, n):
    if isinstance(spec, list):
        vals = [_check_value(name, x) for x in spec]
        pick = rng.integers(0, len(vals), size=n)
        arr = np.empty(n, dtype=object if isinstance(vals[0], str) else float)
        arr[:] = [vals[i] for i in pick]
        return arr
    _only(spec, {"low", "high", "log"}, f"[vary] {name}")
    lo = v.finite(f"[vary] {name}.low", spec.get("low"))
    hi = v.finite(f"[vary] {name}.high", spec.get("high"))
    if spec.get("log", False):
        return np.exp(rng.uniform(math.log(lo), math.log(hi), size=n))
    return rng.uniform(lo, hi, size=n)


def _only(table, allowed, where):
    if not isinstance(table, dict):
        raise SweepError(f"{where} must be a table, got {table!r}")
    for k in table:
        if k not in allowed:
            raise SweepError(f"unknown key {k!r} in {where}; valid keys: {', '.join(sorted(allowed))}")


def _check_value(name, value):
    if name in _STRING_PARAMS:
        return v.choice(name, value, _STRING_PARAMS[name])
    return v.finite(name, value)


def _validate_spec(data: dict) -> SweepSpec:
    _only(data, _TOP_KEYS, "the sweep spec")
    kind = v.choice("kind", data.get("kind", "grid"), ("grid", "random"))
    fixed = data.get("fixed", {})
    vary = data.get("vary", {})
    _only(fixed, set(PARAMETERS), "[fixed]")
    _only(vary, set(PARAMETERS), "[vary]")
    both = sorted(set(fixed) & set(vary))
    if both:
        raise SweepError(f"parameter {both[0]!r} is both fixed and varied")
    given = set(fixed) | set(vary)
    for group in _EXCLUSIVE:
        if len(given & set(group)) > 1:
            raise SweepError(f"give at most one of {', '.join(group)}")
    for req in ("a", "fx"):
        if req not in given:
            raise SweepError(f"the sweep spec must fix or vary {req!r}")
    if not given & {"fy", "mu"}:
        raise SweepError("the sweep spec must fix or vary 'fy' or 'mu'")
    for k, val in fixed.items():
        _check_value(f"[fixed] {k}", val) if k not in _STRING_PARAMS else _check_value(k, val)
    chunk = data.get("chunk_size", 1000)
    if isinstance(chunk, bool) or not isinstance(chunk, int) or chunk < 1:
        raise SweepError(f"chunk_size = {chunk!r} is invalid; valid range: integer >= 1")
    if "rtol" in data:
        v.in_range("rtol", data["rtol"], 0.0, 1e-3, lo_open=True)
    if kind == "grid":
        if "random" in data:
            raise SweepError("[random] is only for kind = 'random'")
        n = 1
        for k, spec in vary.items():
            n *= len(_grid_values(k, spec))
    else:
        rnd = data.get("random")
        if rnd is None:
            raise SweepError("kind = 'random' needs a [random] table with 'samples'")
        _only(rnd, {"samples", "seed"}, "[random]")
        n = rnd.get("samples")
        if isinstance(n, bool) or not isinstance(n, int) or n < 1:
            raise SweepError(f"[random] samples = {n!r} is invalid; valid range: integer >= 1")
        seed = rnd.get("seed", 0)
        if isinstance(seed, bool) or not isinstance(seed, int) or seed < 0:
            raise SweepError(f"[random] seed = {seed!r} is invalid; valid range: integer >= 0")
        for k, spec in vary.items():
            _random_values(k, spec, np.random.default_rng(0), 1)
    canonical = copy.deepcopy(data)
    canonical["kind"] = kind
    canonical["chunk_size"] = chunk
    spec = SweepSpec(canonical, int(n), int(chunk))
    # validate every case's physics up front (cheap: no integration), so that a bad value
    # fails before any work starts, naming the parameter
    for start in range(0, spec.n_cases, 200_000):
        _case_fields(spec.parameters(start, start + 200_000))
    return spec


def load_spec(spec) -> SweepSpec:
    """A :class:`SweepSpec` from a path to a TOML file, a dict, or a spec (returned as is)."""
    if isinstance(spec, SweepSpec):
        return spec
    if isinstance(spec, dict):
        return _validate_spec(spec)
    from .case import read_toml

    try:
        data = read_toml(spec, "sweep spec")
    except ValueError as exc:
        raise SweepError(str(exc)) from None
    try:
        return _validate_spec(data)
    except ValueError as exc:
        raise SweepError(f"{spec}: {exc}") from None


# --------------------------------------------------------------------------- computing
def _case_fields(cols: dict) -> dict:
    """Map sweep parameters to :func:`simulate_cases` fields (validated there)."""
    n = cols["case_id"].size

    def get(k):
        if k in cols:
            return cols[k]
        return np.full(n, PARAMETERS[k], dtype=object if isinstance(PARAMETERS[k], str) else float)

    a = get("a").astype(float)
    if "b" in cols:
        b = cols["b"].astype(float)
    elif "e" in cols:
        e = cols["e"].astype(float)
        bad = ~((e >= 0) & (e < 1))
        if bad.any():
            i = int(np.flatnonzero(bad)[0])
            raise SweepError(f"e = {float(e[i])!r} (case {i}) is invalid; valid range: [0, 1)")
        b = a * np.sqrt(1.0 - e * e)
    elif "aspect" in cols:
        b = a * cols["aspect"].astype(float)
    else:
        b = a
    fx = get("fx").astype(float)
    fy = cols["fy"].astype(float) if "fy" in cols else fx + cols["mu"].astype(float)
    mass = get("mass").astype(float)
    if "I_star" in cols:
        inertia = cols["I_star"].astype(float) * mass * a * a
    elif "moment_of_inertia" in cols:
        inertia = cols["moment_of_inertia"].astype(float)
    else:
        inertia = mass * (a * a + b * b) / 4.0
    v0 = get("v0").astype(float)
    if (v0 < 0).any():
        i = int(np.flatnonzero(v0 < 0)[0])
        raise SweepError(f"v0 = {float(v0[i])!r} (case {i}) is invalid; valid range: >= 0")
    th = get("theta0").astype(float)
    fields = dict(
        a=a, b=b, law=get("law"), xi_c=get("xi_c").astype(float),
        eta_c=get("eta_c").astype(float), fx=fx, fy=fy, f=get("f").astype(float),
        frame=get("frame"), angle=get("angle").astype(float), mass=mass,
        moment_of_inertia=inertia, g=get("g").astype(float), x=get("x0").astype(float),
        y=get("y0").astype(float), phi=get("phi0").astype(float), vx=v0 * np.cos(th),
        vy=v0 * np.sin(th), omega=get("omega0").astype(float),
    )
    try:
        validated_columns(fields)
    except ValueError as exc:
        raise SweepError(str(exc)) from None
    return fields


def compute_chunk(spec_data: dict, index: int) -> dict:
    """Compute chunk ``index`` of a sweep (a pure function: usable as a Dask task).

    Returns a dict of equal-length columns: the case inputs and the stop results.
    """
    spec = load_spec(spec_data) if not isinstance(spec_data, SweepSpec) else spec_data
    _limit_threads_in_dask_worker()
    start = index * spec.chunk_size
    cols = spec.parameters(start, start + spec.chunk_size)
    fields = _case_fields(cols)
    res = simulate_cases(fields, rtol=float(spec.data.get("rtol", 1e-10)))
    out = {"case_id": cols["case_id"].astype(np.int64)}
    for k in ("a", "b", "law", "xi_c", "eta_c", "fx", "fy", "f", "frame", "angle", "mass",
              "moment_of_inertia", "g", "x", "y", "phi", "vx", "vy", "omega"):
        val = np.asarray(fields[k])
        out[{"x": "x0", "y": "y0", "phi": "phi0", "vx": "vx0", "vy": "vy0",
             "omega": "omega0"}.get(k, k)] = val.astype(str) if val.dtype == object else val
    out["I_star"] = out["moment_of_inertia"] / (out["mass"] * out["a"] ** 2)
    out["mu"] = out["fy"] - out["fx"]
    out["aspect"] = out["b"] / out["a"]
    out["v0"] = np.hypot(out["vx0"], out["vy0"])
    out["theta0"] = np.arctan2(out["vy0"], out["vx0"])
    d = res.as_dict()
    for k in RESULT_COLUMNS:
        val = d[k]
        out[k] = val.astype(str) if val.dtype == object else val
    return out


def _limit_threads_in_dask_worker() -> None:
    """Inside a Dask worker, use as many compute threads as the worker has task threads,
    so that N workers on N cores do not oversubscribe them."""
    if "distributed" not in sys.modules:
        return
    try:
        from distributed import get_worker

        worker = get_worker()
    except (ImportError, ValueError):
        return
    from ._jit import set_threads

    set_threads(getattr(worker.state, "nthreads", None) or getattr(worker, "nthreads", 1))


def compute_chunks(spec_data: dict, indices) -> list:
    """:func:`compute_chunk` for several chunks in one task (a list of tables)."""
    return [compute_chunk(spec_data, int(i)) for i in indices]


# --------------------------------------------------------------------------- storage
def _require_pyarrow():
    try:
        import pyarrow  # noqa: F401
        import pyarrow.parquet  # noqa: F401
    except ImportError:  # pragma: no cover - pyarrow is a dependency
        raise SweepError("sweeps write Parquet files and need pyarrow: pip install pyarrow") from None


def _atomic_write_bytes(path: Path, data: bytes) -> None:
    tmp = path.with_name(f".{path.name}.tmp-{os.getpid()}")
    with open(tmp, "wb") as fh:
        fh.write(data)
        fh.flush()
        os.fsync(fh.fileno())
    os.replace(tmp, path)


def _write_chunk(out: Path, index: int, table: dict) -> None:
    import pyarrow as pa
    import pyarrow.parquet as pq

    path = out / "chunks" / f"chunk-{index:06d}.parquet"
    tmp = path.with_name(f".{path.name}.tmp-{os.getpid()}")
    pq.write_table(pa.table({k: np.asarray(val) for k, val in table.items()}), tmp)
    with open(tmp, "rb") as fh:
        os.fsync(fh.fileno())
    os.replace(tmp, path)


def _chunks_done(out: Path) -> set[int]:
    done = set()
    d = out / "chunks"
    if d.is_dir():
        for p in d.glob("chunk-*.parquet"):
            try:
                done.add(int(p.stem.split("-")[1]))
            except ValueError:
                continue
    return done


def _write_manifest(out: Path, spec: SweepSpec, done: set[int]) -> None:
    from . import __version__

    doc = {
        "slidespin_version": __version__,
        "spec_sha256": spec.digest,
        "spec": spec.data,
        "n_cases": spec.n_cases,
        "chunk_size": spec.chunk_size,
        "n_chunks": spec.n_chunks,
        "chunks_done": sorted(done),
        "complete": len(done) == spec.n_chunks,
    }
    _atomic_write_bytes(out / MANIFEST, (json.dumps(doc, indent=1) + "\n").encode())


def _read_manifest(out: Path) -> dict | None:
    p = out / MANIFEST
    if not p.exists():
        return None
    try:
        return json.loads(p.read_text())
    except (OSError, json.JSONDecodeError) as exc:
        raise SweepError(f"{p} is unreadable ({exc}); it is not a slidespin sweep directory") from None


def _prepare(out: Path, spec: SweepSpec, resume: bool) -> set[int]:
    if out.exists() and not out.is_dir():
        raise SweepError(f"out = {str(out)!r} exists and is not a directory")
    man = _read_manifest(out) if out.is_dir() else None
    if man is None:
        if out.is_dir() and any(out.iterdir()):
            raise SweepError(f"out = {str(out)!r} is a non-empty directory without a sweep "
                             "manifest; choose a new or empty directory")
        try:
            (out / "chunks").mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            raise SweepError(f"out = {str(out)!r} cannot be created: {exc.strerror}") from None
        if not os.access(out, os.W_OK):
            raise SweepError(f"out = {str(out)!r} is not writable")
        _write_manifest(out, spec, set())
        return set()
    if man.get("spec_sha256") != spec.digest:
        raise SweepError(
            f"{str(out)!r} holds a different sweep (spec hash {str(man.get('spec_sha256'))[:12]}…, "
            f"this spec {spec.digest[:12]}…); use another directory"
        )
    done = _chunks_done(out)
    if not resume:
        raise SweepError(
            f"{str(out)!r} already holds this sweep ({len(done)} of {spec.n_chunks} chunks "
            "done); pass --resume (resume=True) to finish it"
        )
    if not os.access(out, os.W_OK):
        raise SweepError(f"out = {str(out)!r} is not writable")
    # leftovers of a killed run: temporary files are never valid results
    for p in (out / "chunks").glob(".chunk-*.tmp-*"):
        p.unlink(missing_ok=True)
    return done


# --------------------------------------------------------------------------- progress
class _Progress:
    def __init__(self, total: int, done: int, enabled: bool):
        self.total, self.done, self.enabled = total, done, enabled
        self.t0 = time.monotonic()
        self.start_done = done

    def update(self, n: int) -> None:
        self.done += n
        if not self.enabled:
            return
        el = time.monotonic() - self.t0
        rate = (self.done - self.start_done) / el if el > 0 else 0.0
        eta = (self.total - self.done) / rate if rate > 0 else float("nan")
        frac = self.done / self.total if self.total else 1.0
        bar = "#" * int(30 * frac)
        eta_s = f"{eta:5.0f}s" if math.isfinite(eta) else "    ?"
        sys.stderr.write(f"\r[{bar:<30}] {self.done}/{self.total} cases  {rate:8.0f} cases/s  "
                         f"ETA {eta_s}")
        sys.stderr.flush()

    def close(self) -> None:
        if self.enabled:
            sys.stderr.write("\n")


# --------------------------------------------------------------------------- driver
@dataclass(frozen=True)
class SweepResult:
    """Outcome of :func:`sweep`: where it is, how many chunks were computed now, how long."""

    out: Path
    n_cases: int
    n_chunks: int
    chunks_computed: int
    cases_computed: int
    seconds: float

    @property
    def cases_per_second(self) -> float:
        """Throughput of this run (0 if nothing was left to compute)."""
        return self.cases_computed / self.seconds if self.cases_computed else 0.0


def sweep(spec, out, executor=None, *, resume: bool = False, progress: bool | None = None,
          task_cases: int = MIN_TASK_CASES) -> SweepResult:
    """Run (or resume) a parameter sweep and store its results in ``out``.

    Parameters
    ----------
    spec : str, Path, dict or SweepSpec
        Sweep specification (a TOML path or its parsed dict).
    out : str or Path
        Result directory: ``manifest.json`` and ``chunks/chunk-NNNNNN.parquet``.
    executor : None, dask.distributed.Client or concurrent.futures.Executor
        ``None`` runs on all local cores; otherwise one chunk is submitted per task.
    resume : bool
        Finish a sweep that was interrupted: only missing chunks are computed. Without it an
        existing sweep directory is refused, and a directory of a different spec always is.
    progress : bool or None
        Progress bar on stderr; ``None`` means only when stderr is a terminal.
    task_cases : int, default 1000
        With an executor, the least number of cases per task (whole chunks are grouped).

    Returns
    -------
    SweepResult
    """
    _require_pyarrow()
    if isinstance(task_cases, bool) or not isinstance(task_cases, int) or task_cases < 1:
        raise SweepError(f"task_cases = {task_cases!r} is invalid; valid range: integer >= 1")
    spec = load_spec(spec)
    out = Path(out)
    done = _prepare(out, spec, resume)
    todo = [i for i in range(spec.n_chunks) if i not in done]
    show = sys.stderr.isatty() if progress is None else bool(progress)
    bar = _Progress(spec.n_cases, min(len(done) * spec.chunk_size, spec.n_cases), show)
    t0 = time.perf_counter()

    def chunk_len(i):
        return min(spec.chunk_size, spec.n_cases - i * spec.chunk_size)

    def finish(i, table):
        _write_chunk(out, i, table)
        done.add(i)
        _write_manifest(out, spec, done)
        bar.update(chunk_len(i))

    try:
        if executor is None:
            for i in todo:
                finish(i, compute_chunk(spec, i))
        else:
            # one task computes consecutive chunks totalling >= MIN_TASK_CASES cases, so that
            # scheduling overhead stays small; each chunk is still written on its own
            per_task = max(1, -(-task_cases // spec.chunk_size))
            groups = [todo[i:i + per_task] for i in range(0, len(todo), per_task)]
            if _is_dask_client(executor):
                from distributed import as_completed

                futs = {executor.submit(compute_chunks, spec.data, g, pure=False): g
                        for g in groups}
                done_iter = as_completed(list(futs))
            else:
                import concurrent.futures as cf

                futs = {executor.submit(compute_chunks, spec.data, g): g for g in groups}
                done_iter = cf.as_completed(futs)
            for fut in done_iter:
                for i, table in zip(futs[fut], fut.result()):
                    finish(i, table)
    finally:
        bar.close()
    return SweepResult(out, spec.n_cases, spec.n_chunks, len(todo),
                       sum(chunk_len(i) for i in todo), time.perf_counter() - t0)


def _is_dask_client(obj) -> bool:
    return type(obj).__name__ == "Client" and type(obj).__module__.startswith("distributed")


def connect_dask(address: str | None = None, workers: int | None = None):
    """A ``dask.distributed.Client``: to ``address`` (tcp://HOST:PORT) or a new LocalCluster."""
    try:
        from distributed import Client, LocalCluster
    except ImportError:
        raise SweepError(
            "Dask is not installed: pip install 'slidespin[cluster]' (dask[distributed])"
        ) from None
    if address:
        try:
            return Client(address, timeout="10s")
        except (OSError, TimeoutError) as exc:
            raise SweepError(f"--scheduler {address!r}: cannot connect ({exc})") from None
    cluster = LocalCluster(n_workers=workers or 2, threads_per_worker=1, host="127.0.0.1",
                           dashboard_address=None, processes=True)
    return Client(cluster)


def read_sweep(out) -> dict:
    """All results of a sweep directory as one table: column name → array, sorted by case.

    Raises
    ------
    ValueError
        If ``out`` is not a sweep directory. An unfinished sweep is read as far as it got
        (the manifest says which chunks are done).
    """
    _require_pyarrow()
    import pyarrow as pa
    import pyarrow.parquet as pq

    out = Path(out)
    if _read_manifest(out) is None:
        raise SweepError(f"{str(out)!r} is not a sweep directory (no {MANIFEST})")
    files = sorted((out / "chunks").glob("chunk-*.parquet"))
    if not files:
        return {}
    table = pa.concat_tables([pq.read_table(f) for f in files])
    cols = {name: table.column(name).to_numpy(zero_copy_only=False) for name in table.column_names}
    order = np.argsort(cols["case_id"], kind="stable")
    return {k: val[order] for k, val in cols.items()}


def benchmark(n_local: int = 1_000_000, n_dask: int = 100_000, workers: int = 2,
              chunk_size: int = 10_000, out=None) -> dict:
    """Measure sweep throughput on all local cores and through a local Dask cluster.

    Runs a random sweep (uniform/Hertz laws, random shapes, tensors and starts) of
    ``n_local`` cases with the local engine and ``n_dask`` cases through a ``LocalCluster``
    of ``workers`` single-threaded processes on 127.0.0.1, both written to Parquet like any
    sweep. Returns cases per second for each, per core, and the Dask/local ratio per core.
    """
    import os
    import shutil
    import tempfile

    def spec(n):
        return {
            "name": "benchmark", "kind": "random", "chunk_size": int(chunk_size),
            "random": {"samples": int(n), "seed": 7},
            "fixed": {"a": 0.05, "mass": 1.0},
            "vary": {"aspect": {"low": 0.3, "high": 1.0}, "law": ["uniform", "hertz"],
                     "fx": {"low": 0.2, "high": 0.5}, "mu": {"low": 0.0, "high": 0.3},
                     "I_star": {"low": 0.2, "high": 1.0}, "v0": {"low": 0.2, "high": 2.0},
                     "omega0": {"low": -30.0, "high": 30.0},
                     "theta0": {"low": -3.14, "high": 3.14}},
        }

    base = Path(out) if out else Path(tempfile.mkdtemp(prefix="slidespin-bench-"))
    cores = os.cpu_count() or 1
    result = {"cores": cores, "workers": workers}
    try:
        # warm-up (compilation) outside the timings
        compute_chunk(load_spec(dict(spec(2), chunk_size=2)), 0)
        if n_local:
            t0 = time.perf_counter()
            sweep(spec(n_local), base / "local", progress=False)
            dt = time.perf_counter() - t0
            result.update(local_cases=n_local, local_seconds=dt, local_cases_per_s=n_local / dt,
                          local_cases_per_s_per_core=n_local / dt / cores)
        if n_dask:
            client = connect_dask(None, workers)
            try:
                client.run(compute_chunk, dict(spec(2), chunk_size=2), 0)  # warm workers
                t0 = time.perf_counter()
                sweep(spec(n_dask), base / "dask", executor=client, progress=False)
                dt = time.perf_counter() - t0
            finally:
                cluster = getattr(client, "cluster", None)
                client.close()
                if cluster is not None:
                    cluster.close()
            result.update(dask_cases=n_dask, dask_seconds=dt, dask_cases_per_s=n_dask / dt,
                          dask_cases_per_s_per_core=n_dask / dt / min(workers, cores))
            if n_local:
                result["dask_over_local_per_core"] = (result["dask_cases_per_s_per_core"]
                                                      / result["local_cases_per_s_per_core"])
    finally:
        if out is None:
            shutil.rmtree(base, ignore_errors=True)
    return result
