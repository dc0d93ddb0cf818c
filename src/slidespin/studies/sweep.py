"""Parameter sweeps: many cases, chunked, crash-safe and resumable, locally or on Dask.

:func:`sweep` runs (or resumes) a sweep specification (TOML, see ``examples/sweep_*.toml``;
its parameters, defaults and limits: :mod:`slidespin.studies.sweep_spec`, read by
:func:`~slidespin.studies.sweep_parse.load_spec`). The cases are numbered deterministically and
cut into chunks (:func:`~slidespin.studies.sweep_chunk.compute_chunk`); each finished chunk is
written to ``DIR/chunks/chunk-NNNNNN.parquet`` and recorded in ``DIR/manifest.json``
(:mod:`slidespin.studies.sweep_store`). A sweep killed at any moment loses only its unfinished
chunks; ``resume=True`` checks every chunk file, recomputes damaged ones and computes the
missing ones; running a finished sweep again checks its chunk files and reports it complete,
computing and writing nothing. ``DIR/.lock`` keeps a second sweep off a directory in use.
:func:`~slidespin.studies.sweep_read.read_sweep` and
:func:`~slidespin.studies.sweep_read.to_pandas` read a sweep back.

Executors: by default all local cores (the compiled batch engine,
:func:`~slidespin.motion.batch.simulate_cases`); a ``dask.distributed.Client`` (or any
``concurrent.futures.Executor``) runs consecutive chunks of at least :data:`MIN_TASK_CASES`
cases per task; the results are identical to the local ones, bit for bit.

Each distinct patch is built once per chunk and the cases go to
:func:`slidespin.motion.batch.simulate_bodies` together: every case equals a single
:func:`slidespin.simulate` call on the same body, to the last bit.

The top-level key ``compute`` chooses the result of each case: ``"stop"`` (default; the
compiled batch engine), ``"statics"`` (critical tilt, load factor, sticks or slides) or
``"loaded"`` (a run with applied loads and tilt to ``t_end``); the last two add the load and
tilt keys ``load_fx``, ``load_fy``, ``load_torque``, ``load_frame``, ``incline_angle`` (or
``incline_angle_deg``), ``incline_downhill`` and ``t_end`` (``slidespin.studies.sweep_loads``).
"""

from __future__ import annotations

import concurrent.futures as cf
import os
import shutil
import tempfile
import time
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path

from slidespin.motion.outcomes import ENDINGS, FLAGGED, LOADED_UNCONVERGED, UNCONVERGED
from slidespin.studies.sweep_chunk import chunk_columns, compute_chunk, compute_chunks
from slidespin.studies.sweep_parse import load_spec
from slidespin.studies.sweep_read import to_pandas
from slidespin.studies.sweep_spec import SweepError
from slidespin.studies.sweep_store import (
    STATUS_ORDER,
    _add_counts,
    _check_out,
    _Lock,
    _prepare,
    _require_pyarrow,
    _write_chunk,
    _write_manifest,
)

__all__ = ["sweep", "SweepResult", "connect_dask", "MIN_TASK_CASES"]


#: smallest number of cases per task sent to an executor (Dask or concurrent.futures)
MIN_TASK_CASES = 1000


# --------------------------------------------------------------------------- progress
def _progress_bar(total: int, done: int, enabled: bool | None):
    """The shared bar (:func:`slidespin._progress.progress_bar`: on a terminal only, never
    with ``progress=False``), started at the ``done`` cases of earlier runs (they count in the
    bar, not in its rate)."""
    # lazy: tqdm is needed only while a sweep runs
    from slidespin._progress import progress_bar

    bar = progress_bar(total, "sweep", unit="case", enabled=enabled)
    if done:
        # tqdm's own `initial`: counted as done, not as work of this run
        bar.n = bar.last_print_n = bar.initial = done
        bar.refresh()
    return bar


# --------------------------------------------------------------------------- driver
@dataclass(frozen=True)
class SweepResult:
    """Outcome of :func:`sweep`: where it is, how many chunks were computed now, how long,
    and how the cases ended.

    ``status_counts`` and ``ending_counts`` count the cases of the whole sweep (every chunk
    done, also those of earlier runs) per status and per ending (:mod:`slidespin.motion.outcomes`);
    ``chunks_repaired`` is the number of damaged chunk files found by ``resume`` and computed
    again.
    """

    out: Path
    n_cases: int
    n_chunks: int
    chunks_computed: int
    cases_computed: int
    seconds: float
    status_counts: dict = field(default_factory=dict)
    ending_counts: dict = field(default_factory=dict)
    chunks_repaired: int = 0
    #: the sweep was finished before this call: its chunk files were checked, nothing computed
    already_complete: bool = False

    @property
    def cases_per_second(self) -> float:
        """Throughput of this run (0 if nothing was left to compute)."""
        return self.cases_computed / self.seconds if self.cases_computed else 0.0

    @property
    def n_unconverged(self) -> int:
        """Cases whose status is in :data:`slidespin.motion.outcomes.UNCONVERGED`."""
        return sum(
            c for k, c in self.status_counts.items() if k in UNCONVERGED or k in LOADED_UNCONVERGED
        )

    @property
    def n_flagged(self) -> int:
        """Cases whose status is in :data:`slidespin.motion.outcomes.FLAGGED` (marginal, saddle)."""
        return sum(c for k, c in self.status_counts.items() if k in FLAGGED)

    def to_pandas(self, *, include_unconverged: bool = False):
        """The sweep's results as a :class:`pandas.DataFrame`
        (:func:`~slidespin.studies.sweep_read.to_pandas` of ``out``)."""
        return to_pandas(self.out, include_unconverged=include_unconverged)


def sweep(
    spec,
    out,
    executor=None,
    *,
    resume: bool = False,
    progress: bool | None = None,
    task_cases: int | None = None,
) -> SweepResult:
    """Run (or resume) a parameter sweep and store its results in ``out``.

    Parameters
    ----------
    spec : str, Path, dict or SweepSpec
        Sweep specification (a TOML path or its parsed dict).
    out : str or Path
        Result directory: ``manifest.json`` and ``chunks/chunk-NNNNNN.parquet``. While a
        sweep runs, ``out/.lock`` (holding its process id and host) makes any other sweep on
        the same directory refuse to start; a lock whose process is gone is taken over.
    executor : None, dask.distributed.Client or concurrent.futures.Executor
        ``None`` runs on all local cores; otherwise one chunk is submitted per task.
    resume : bool
        Finish a sweep that was interrupted: only missing chunks are computed. Every chunk
        file already there is checked first (readable Parquet, its columns, row count and
        case numbers); damaged ones are computed again. Without ``resume`` an unfinished or
        damaged sweep directory is refused (the message says which chunks), a finished one is
        checked and reported complete (``already_complete``; nothing is computed or written),
        and a directory of a different spec is always refused, naming the keys that differ.
    progress : bool or None
        Progress bar on stderr; ``None`` means only when stderr is a terminal.
    task_cases : int or None
        With an executor, the least number of cases per task (whole chunks are grouped).
        ``None``: :data:`MIN_TASK_CASES` for stop sweeps, one chunk per task for statics and
        loaded sweeps (a loaded case takes milliseconds to seconds).

    Returns
    -------
    SweepResult

    Raises
    ------
    SweepError
        A bad spec, a foreign or busy directory, or a write that failed (disk full,
        permission denied): the message says which file; the chunks finished so far are kept
        and ``resume=True`` completes the sweep.
    """
    _require_pyarrow()
    if task_cases is not None and (
        isinstance(task_cases, bool) or not isinstance(task_cases, int) or task_cases < 1
    ):
        raise SweepError(f"task_cases = {task_cases!r} is invalid; valid range: integer >= 1")
    _check_executor(executor)
    if not isinstance(out, (str, os.PathLike)) or not str(out):
        raise SweepError(
            f"out = {out!r:.60} is invalid; valid values: a directory path (str or "
            "os.PathLike), new, empty or holding this sweep"
        )
    for name, flag in (("resume", resume), ("progress", progress)):
        if not (isinstance(flag, bool) or (flag is None and name == "progress")):
            valid = "True, False or None" if name == "progress" else "True, False"
            raise SweepError(f"{name} = {flag!r:.60} is invalid; valid values: {valid}")
    spec = load_spec(spec)
    if task_cases is None:
        task_cases = MIN_TASK_CASES if spec.mode == "stop" else 1
    out = Path(out)
    _check_out(out)  # before creating anything
    if not out.is_dir():
        try:
            out.mkdir(parents=True)
        except FileExistsError:
            pass
        except OSError as exc:
            raise SweepError(
                f"out = {str(out)!r} cannot be created: {exc.strerror}; valid: a path whose "
                "parent directory exists and is writable"
            ) from None
    with _Lock(out):
        return _run_sweep(spec, out, executor, resume, progress, task_cases)


def _check_executor(executor) -> None:
    """``None``, a ``dask.distributed.Client`` or a ``concurrent.futures.Executor``."""
    if executor is None or _is_dask_client(executor) or isinstance(executor, cf.Executor):
        return
    raise SweepError(
        f"executor = {executor!r:.60} is invalid; valid values: None (all local cores), a "
        "dask.distributed.Client (see connect_dask) or a concurrent.futures.Executor"
    )


def _run_sweep(spec, out, executor, resume, progress, task_cases) -> SweepResult:
    t0 = time.perf_counter()
    done, repaired, counts, complete = _prepare(out, spec, resume)
    if repaired:
        _write_manifest(out, spec, done, counts)
    todo = [i for i in range(spec.n_chunks) if i not in done]
    columns = chunk_columns(spec)
    bar = _progress_bar(
        spec.n_cases,
        sum(_chunk_len(spec, i) for i in done),
        False if complete or not todo else progress,
    )
    counted = {"cases": 0}  # cases of the chunk under way already counted by on_case

    def on_case():
        counted["cases"] += 1
        bar.update(1)

    def finish(i, table):
        _write_chunk(out, i, table, columns)
        done.add(i)
        _add_counts(counts, table["status"], table["ending"])
        _write_manifest(out, spec, done, counts)
        bar.update(_chunk_len(spec, i) - counted["cases"])
        counted["cases"] = 0

    try:
        if executor is None:
            for i in todo:
                # statics and loaded cases take milliseconds to minutes each: the bar moves
                # with every case (a compiled stop chunk is done at once)
                finish(i, compute_chunk(spec, i, on_case=on_case))
        else:
            # one task computes consecutive chunks totalling >= MIN_TASK_CASES cases, so that
            # scheduling overhead stays small; each chunk is still written on its own
            per_task = max(1, -(-task_cases // spec.chunk_size))
            groups = [todo[i : i + per_task] for i in range(0, len(todo), per_task)]
            if _is_dask_client(executor):
                # lazy: Dask is an optional extra, needed only with a Dask executor
                from distributed import as_completed

                futs = {
                    executor.submit(compute_chunks, spec.data, g, pure=False): g for g in groups
                }
                done_iter: Iterable = as_completed(list(futs))
            else:
                futs = {executor.submit(compute_chunks, spec.data, g): g for g in groups}
                done_iter = cf.as_completed(futs)
            for fut in done_iter:
                for i, table in zip(futs[fut], fut.result()):
                    finish(i, table)
    finally:
        bar.close()

    def ordered(d, names):
        return {k: d[k] for k in list(names) + sorted(set(d) - set(names)) if d.get(k)}

    return SweepResult(
        out,
        spec.n_cases,
        spec.n_chunks,
        len(todo),
        sum(_chunk_len(spec, i) for i in todo),
        time.perf_counter() - t0,
        ordered(counts["status"], STATUS_ORDER),
        ordered(counts["ending"], ENDINGS),
        repaired,
        complete,
    )


def _chunk_len(spec, i):
    return min(spec.chunk_size, spec.n_cases - i * spec.chunk_size)


def _is_dask_client(obj) -> bool:
    return type(obj).__name__ == "Client" and type(obj).__module__.startswith("distributed")


def connect_dask(address: str | None = None, workers: int | None = None):
    """A ``dask.distributed.Client``: to ``address`` (``tcp://HOST:PORT``) or a new LocalCluster."""
    try:
        # lazy: Dask is an optional extra (slidespin[cluster])
        from distributed import Client, LocalCluster
    except ImportError:
        raise SweepError(
            "Dask is not installed: pip install 'slidespin[cluster]' (dask[distributed])"
        ) from None
    if workers is not None and (
        isinstance(workers, bool) or not isinstance(workers, int) or workers < 1
    ):
        raise SweepError(f"workers = {workers!r} is invalid; valid range: integer >= 1")
    if address:
        if workers is not None:
            raise SweepError(
                f"workers = {workers!r} is for a new local cluster; with address = "
                f"{address!r} the scheduler's own workers run the sweep (valid: one of them)"
            )
        try:
            return Client(address, timeout="10s")
        except (OSError, TimeoutError) as exc:
            raise SweepError(
                f"--scheduler {address!r}: cannot connect ({exc}); valid: the address of a "
                "running Dask scheduler, tcp://HOST:PORT"
            ) from None
    cluster = LocalCluster(
        n_workers=workers or 2,
        threads_per_worker=1,
        host="127.0.0.1",
        dashboard_address=None,
        processes=True,
    )
    return Client(cluster)


def benchmark(
    n_local: int = 1_000_000,
    n_dask: int = 100_000,
    workers: int = 2,
    chunk_size: int = 10_000,
    out=None,
) -> dict:
    """Measure sweep throughput on all local cores and through a local Dask cluster.

    Runs a random sweep (uniform/Hertz laws, random shapes, tensors and starts) of
    ``n_local`` cases with the local engine and ``n_dask`` cases through a ``LocalCluster``
    of ``workers`` single-threaded processes on 127.0.0.1, both written to Parquet like any
    sweep. Returns cases per second for each, per core, and the Dask/local ratio per core.
    """

    def spec(n):
        return {
            "name": "benchmark",
            "kind": "random",
            "chunk_size": int(chunk_size),
            "random": {"samples": int(n), "seed": 7},
            "fixed": {"a": 0.05, "mass": 1.0},
            "vary": {
                "aspect": {"low": 0.3, "high": 1.0},
                "law": ["uniform", "hertz"],
                "fx": {"low": 0.2, "high": 0.5},
                "mu": {"low": 0.0, "high": 0.3},
                "I_star": {"low": 0.2, "high": 1.0},
                "v0": {"low": 0.2, "high": 2.0},
                "omega0": {"low": -30.0, "high": 30.0},
                "theta0": {"low": -3.14, "high": 3.14},
            },
        }

    base = Path(out) if out else Path(tempfile.mkdtemp(prefix="slidespin-bench-"))
    cores = os.cpu_count() or 1
    result: dict[str, float] = {"cores": cores, "workers": workers}
    try:
        # warm-up (compilation) outside the timings
        compute_chunk(load_spec(dict(spec(2), chunk_size=2)), 0)
        if n_local:
            t0 = time.perf_counter()
            sweep(spec(n_local), base / "local", progress=False)
            dt = time.perf_counter() - t0
            result.update(
                local_cases=n_local,
                local_seconds=dt,
                local_cases_per_s=n_local / dt,
                local_cases_per_s_per_core=n_local / dt / cores,
            )
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
            result.update(
                dask_cases=n_dask,
                dask_seconds=dt,
                dask_cases_per_s=n_dask / dt,
                dask_cases_per_s_per_core=n_dask / dt / min(workers, cores),
            )
            if n_local:
                result["dask_over_local_per_core"] = (
                    result["dask_cases_per_s_per_core"] / result["local_cases_per_s_per_core"]
                )
    finally:
        if out is None:
            shutil.rmtree(base, ignore_errors=True)
    return result
