"""A sweep directory on disk: Parquet chunks, the manifest, the lock, and resuming.

Each finished chunk is written to ``DIR/chunks/chunk-NNNNNN.parquet`` under a temporary name
and renamed into place, and ``DIR/manifest.json`` records the spec, its hash, the package
version, the chunks done and how many cases ended with each status and each ending
(:mod:`slidespin.motion.outcomes`, :func:`count_outcomes`). Resuming checks every chunk file
(readable Parquet, columns, row count, case numbers) and removes damaged ones for
recomputation. Running a sweep again on its own finished directory checks every chunk file
and writes nothing: the sweep is reported complete. A directory of another spec is refused,
naming the keys that differ. ``DIR/.lock`` (pid and host) keeps a second sweep off a directory
in use; a lock whose process is gone is taken over. A write that fails (disk full, permission denied)
raises :class:`~slidespin.studies.sweep_spec.SweepError` naming the file and leaves a
directory that ``resume=True`` completes.
"""

from __future__ import annotations

import json
import os
import socket
from pathlib import Path

import numpy as np

from slidespin._io import os_error_kind
from slidespin._version import __version__
from slidespin.motion.outcomes import (
    ENDINGS,
    LOADED_ENDINGS,
    LOADED_STATUSES,
    LOADED_UNCONVERGED,
    STATUSES,
    UNCONVERGED,
)
from slidespin.studies.sweep_chunk import CHUNK_COLUMNS, chunk_columns
from slidespin.studies.sweep_loads import STATICS_ENDINGS, STATICS_STATUSES
from slidespin.studies.sweep_spec import SweepError, SweepSpec

__all__ = ["count_outcomes", "spec_differences"]


#: the file in a sweep directory that records the spec, the chunks done and the counts
MANIFEST = "manifest.json"


def _require_pyarrow():
    try:
        # lazy: pyarrow is heavy; checked only when a sweep is run or read
        import pyarrow  # noqa: F401
        import pyarrow.parquet  # noqa: F401
    except ImportError:  # pragma: no cover - pyarrow is a dependency
        raise SweepError(
            "sweeps write Parquet files and need pyarrow: pip install pyarrow"
        ) from None


def _vocabulary(spec: SweepSpec) -> tuple:
    """(statuses, endings) a chunk of ``spec`` may hold."""
    if spec.mode == "statics":
        return STATICS_STATUSES, STATICS_ENDINGS
    if spec.mode == "loaded":
        return LOADED_STATUSES, LOADED_ENDINGS
    return STATUSES, ENDINGS


LOCK = ".lock"
#: largest manifest read (its chunk list has one number per chunk)
MAX_MANIFEST_BYTES = 128_000_000
#: statuses in the order of the summaries: converged, flagged, unconverged
STATUS_ORDER = (
    "stopped",
    "at_rest",
    "marginal",
    "saddle",
    "max_steps",
    "step_too_small",
    "non_finite",
)


def _os_error(exc: OSError, path, resumable: bool = True) -> SweepError:
    """A one-line :class:`~slidespin.studies.sweep_spec.SweepError` saying what went wrong while
    writing ``path``."""
    what = os_error_kind(exc)
    tail = (
        (
            "; the finished chunks are kept: free the problem and rerun with --resume "
            "(resume=True) to finish the sweep"
        )
        if resumable
        else ""
    )
    return SweepError(f"{what} while writing {str(path)!r} ({exc.strerror}){tail}")


def _atomic_write_bytes(path: Path, data: bytes) -> None:
    tmp = path.with_name(f".{path.name}.tmp-{os.getpid()}")
    try:
        with open(tmp, "wb") as fh:
            fh.write(data)
            fh.flush()
            os.fsync(fh.fileno())
        os.replace(tmp, path)
    except OSError as exc:
        tmp.unlink(missing_ok=True)
        raise _os_error(exc, path) from None


def _chunk_path(out: Path, index: int) -> Path:
    return out / "chunks" / f"chunk-{index:06d}.parquet"


def _parquet_write(table, path) -> None:
    """Write a pyarrow table (a seam for tests that simulate a full disk)."""
    # lazy: pyarrow is heavy, needed only to write or read chunk files
    import pyarrow.parquet as pq

    pq.write_table(table, path)


def _write_chunk(out: Path, index: int, table: dict, columns: tuple = CHUNK_COLUMNS) -> None:
    # lazy: pyarrow is heavy, needed only to write or read chunk files
    import pyarrow as pa

    path = _chunk_path(out, index)
    tmp = path.with_name(f".{path.name}.tmp-{os.getpid()}")
    try:
        _parquet_write(pa.table({k: np.asarray(table[k]) for k in columns}), tmp)
        with open(tmp, "rb") as fh:
            os.fsync(fh.fileno())
        os.replace(tmp, path)
    except OSError as exc:
        tmp.unlink(missing_ok=True)
        raise _os_error(exc, path) from None


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


def _read_chunk(path: Path):
    """A chunk file as a pyarrow table; ``SweepError`` naming the file if unreadable."""
    # lazy: pyarrow is heavy, needed only to write or read chunk files
    import pyarrow.parquet as pq

    try:
        return pq.read_table(path)
    except Exception as exc:  # noqa: BLE001 - pyarrow raises several types for bad files
        raise SweepError(
            f"{str(path)!r} is not a readable Parquet file (valid: one written by slidespin "
            f"sweep; {type(exc).__name__}: "
            f"{str(exc).splitlines()[0] if str(exc) else ''}); rerun "
            "slidespin sweep SPEC --out DIR --resume to recompute it"
        ) from None


def _verify_chunk(out: Path, spec: SweepSpec, index: int):
    """The status and ending columns of chunk ``index`` if its file is sound (readable,
    the right columns, rows and case numbers, known statuses), else ``None``."""
    statuses, endings = _vocabulary(spec)
    start = index * spec.chunk_size
    n = min(spec.chunk_size, spec.n_cases - start)
    try:
        table = _read_chunk(_chunk_path(out, index))
    except SweepError:
        return None
    if tuple(table.column_names) != chunk_columns(spec) or table.num_rows != n:
        return None
    try:
        ids = table.column("case_id").to_numpy()
        status = table.column("status").to_numpy(zero_copy_only=False).astype(str)
        ending = table.column("ending").to_numpy(zero_copy_only=False).astype(str)
    except Exception:  # noqa: BLE001 - wrong types in a foreign or damaged file
        return None
    if not np.array_equal(ids, np.arange(start, start + n)):
        return None
    if not (np.isin(status, statuses).all() and np.isin(ending, endings).all()):
        return None
    return status, ending


def count_outcomes(status, ending=None) -> dict:
    """Cases per status (and per ending): ``{"status": {name: n}, "ending": {...},
    "unconverged": n}``, names in the order of :mod:`slidespin.motion.outcomes`, zeros left out."""

    def tally(values, names):
        values = np.asarray(values).astype(str)
        names = list(names) + sorted(set(values.tolist()) - set(names))
        counts = {nm: int(np.count_nonzero(values == nm)) for nm in names}
        return {k: c for k, c in counts.items() if c}

    out = {"status": tally(status, STATUS_ORDER)}
    if ending is not None:
        out["ending"] = tally(ending, ENDINGS)
    out["unconverged"] = sum(
        c for k, c in out["status"].items() if k in UNCONVERGED or k in LOADED_UNCONVERGED
    )
    return out


def _add_counts(total: dict, status, ending) -> None:
    new = count_outcomes(status, ending)
    for key in ("status", "ending"):
        for k, c in new[key].items():
            total[key][k] = total[key].get(k, 0) + c


def _write_manifest(out: Path, spec: SweepSpec, done: set[int], counts: dict | None = None) -> None:
    counts = counts or {"status": {}, "ending": {}}
    doc = {
        "slidespin_version": __version__,
        "spec_sha256": spec.digest,
        "spec": spec.data,
        "n_cases": spec.n_cases,
        "chunk_size": spec.chunk_size,
        "n_chunks": spec.n_chunks,
        "chunks_done": sorted(done),
        "complete": len(done) == spec.n_chunks,
        # over the chunks done (all cases once complete)
        "status_counts": dict(counts["status"]),
        "ending_counts": dict(counts["ending"]),
        "unconverged": sum(
            c for k, c in counts["status"].items() if k in UNCONVERGED or k in LOADED_UNCONVERGED
        ),
    }
    _atomic_write_bytes(out / MANIFEST, (json.dumps(doc, indent=1) + "\n").encode())


def _read_manifest(out: Path) -> dict | None:
    p = out / MANIFEST
    if not p.exists():
        return None
    if not p.is_file():
        raise SweepError(
            f"{str(p)!r} is not a regular file; it is not a slidespin sweep directory (valid: "
            "a directory written by slidespin sweep)"
        )
    try:
        with open(p, "rb") as fh:
            raw = fh.read(MAX_MANIFEST_BYTES + 1)
        if len(raw) > MAX_MANIFEST_BYTES:
            raise SweepError(
                f"{str(p)!r} is larger than {MAX_MANIFEST_BYTES} bytes; it is not "
                "a slidespin sweep manifest (valid: one written by slidespin sweep)"
            )
        doc = json.loads(raw.decode("utf-8"))
    except (OSError, UnicodeDecodeError, json.JSONDecodeError, RecursionError) as exc:
        raise SweepError(
            f"{str(p)!r} is unreadable ({exc}); it is not a slidespin sweep directory (valid: "
            "a directory written by slidespin sweep)"
        ) from None
    if not isinstance(doc, dict):
        raise SweepError(
            f"{str(p)!r} is not a slidespin sweep manifest (valid: a JSON object written by "
            "slidespin sweep)"
        )
    return doc


def _check_out(out: Path) -> dict | None:
    """Refuse a file or a foreign non-empty directory; return the manifest if any."""
    if out.exists() and not out.is_dir():
        raise SweepError(
            f"out = {str(out)!r} exists and is not a directory; valid: a new, empty or sweep "
            "directory"
        )
    man = _read_manifest(out) if out.is_dir() else None
    if man is None and out.is_dir() and any(p.name != LOCK for p in out.iterdir()):
        raise SweepError(
            f"out = {str(out)!r} is a non-empty directory without a sweep "
            "manifest; valid: a new or empty directory, or one written by slidespin sweep"
        )
    return man


def _flat(doc, path: tuple = ()) -> dict:
    """``{("vary", "mu"): [...], ("kind",): "grid", ...}``: the leaves of a spec."""
    if isinstance(doc, dict) and (not path or path[0] in ("fixed", "vary", "random")):
        out: dict = {}
        for k, val in doc.items():
            out.update(_flat(val, path + (str(k),)))
        return out
    return {path: doc}


def spec_differences(old, new: dict, limit: int = 3) -> str:
    """What differs between the spec a directory holds and ``new``, key by key (``[vary] mu
    = [0.0, 0.1] there, [0.0, 0.2] here``), at most ``limit`` keys and how many more."""
    if not isinstance(old, dict):
        return "its manifest records no readable spec"
    a, b = _flat(old), _flat(new)
    keys = sorted(set(a) | set(b), key=lambda k: (len(k), k))
    diffs = [k for k in keys if a.get(k, _ABSENT) != b.get(k, _ABSENT)]

    def name(k):
        return k[0] if len(k) == 1 else f"[{k[0]}] {'.'.join(k[1:])}"

    def show(val):
        return "absent" if val is _ABSENT else _short(val)

    parts = [
        f"{name(k)} = {show(a.get(k, _ABSENT))} there, {show(b.get(k, _ABSENT))} in this spec"
        for k in diffs[:limit]
    ]
    if len(diffs) > limit:
        parts.append(f"and {len(diffs) - limit} more")
    return "; ".join(parts) or "the same keys, written differently"


_ABSENT = object()


def _short(value, n: int = 60) -> str:
    text = repr(value)
    return text if len(text) <= n else text[: n - 1] + "…"


def _ranges(indices) -> str:
    """``[0, 1, 2, 5]`` → ``"0-2, 5"`` (chunk numbers, for messages; at most 6 runs)."""
    runs: list[list[int]] = []
    for i in sorted(indices):
        if runs and i == runs[-1][1] + 1:
            runs[-1][1] = i
        else:
            runs.append([i, i])
    text = [f"{a}" if a == b else f"{a}-{b}" for a, b in runs[:6]]
    if len(runs) > 6:
        text.append("...")
    return ", ".join(text)


def _prepare(out: Path, spec: SweepSpec, resume: bool):
    """Set up ``out`` (called holding the lock). Returns the sound chunks done, the number
    of damaged chunk files removed for recomputation, the counts of the sound chunks, and
    whether the sweep was complete already (then nothing is written)."""
    man = _check_out(out)
    counts: dict[str, dict[str, int]] = {"status": {}, "ending": {}}
    if man is None:
        try:
            (out / "chunks").mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            raise SweepError(
                f"out = {str(out)!r} cannot be created: {exc.strerror}; valid: a path whose "
                "parent directory exists and is writable"
            ) from None
        if not os.access(out, os.W_OK):
            raise SweepError(
                f"out = {str(out)!r} is not writable; valid: a directory this user may write"
            )
        _write_manifest(out, spec, set(), counts)
        return set(), 0, counts, False
    if man.get("spec_sha256") != spec.digest:
        raise SweepError(
            f"{str(out)!r} holds a different sweep: {spec_differences(man.get('spec'), spec.data)}"
            f"; valid: the spec that made it (recorded in {MANIFEST}), or another directory"
        )
    done = _chunks_done(out)
    if not resume:
        missing = [i for i in range(spec.n_chunks) if i not in done]
        if missing:
            raise SweepError(
                f"{str(out)!r} already holds this sweep, unfinished: "
                f"{spec.n_chunks - len(missing)} of {spec.n_chunks} chunks done, chunk "
                f"{_ranges(missing)} missing; pass --resume (resume=True) to finish it (valid: "
                "--resume, or another directory)"
            )
        # finished: every chunk file is checked, nothing is written
        bad = sorted(i for i in done if i >= spec.n_chunks)
        for i in range(spec.n_chunks):
            ok = _verify_chunk(out, spec, i)
            if ok is None:
                bad.append(i)
            else:
                _add_counts(counts, *ok)
        if bad:
            raise SweepError(
                f"{str(out)!r} holds this sweep, but chunk file {_ranges(sorted(bad))} is "
                f"damaged or foreign ({_chunk_path(out, bad[0]).name}: unreadable, or not "
                "its rows and columns); pass --resume (resume=True) to compute it again (valid: "
                "--resume, or another directory)"
            )
        return set(range(spec.n_chunks)), 0, counts, True
    if not os.access(out, os.W_OK):
        raise SweepError(
            f"out = {str(out)!r} is not writable; valid: a directory this user may write"
        )
    (out / "chunks").mkdir(exist_ok=True)
    # leftovers of a killed run: temporary files are never valid results
    for p in (out / "chunks").glob(".chunk-*.tmp-*"):
        p.unlink(missing_ok=True)
    # every chunk file is checked (readable, columns, rows, case numbers); bad ones go
    sound, repaired = set(), 0
    for i in sorted(done):
        ok = _verify_chunk(out, spec, i) if i < spec.n_chunks else None
        if ok is None:
            _chunk_path(out, i).unlink(missing_ok=True)
            repaired += 1
        else:
            sound.add(i)
            _add_counts(counts, *ok)
    return sound, repaired, counts, False


class _Lock:
    """``DIR/.lock`` created with O_EXCL, holding ``pid host``: one sweep per directory.

    A lock left by a process that no longer exists on this host is stale and taken over.
    """

    def __init__(self, out: Path):
        self.path = out / LOCK
        self.held = False

    def __enter__(self):
        me = f"{os.getpid()} {socket.gethostname()}\n"
        for _ in range(2):
            try:
                fd = os.open(self.path, os.O_CREAT | os.O_EXCL | os.O_WRONLY, 0o644)
            except FileExistsError:
                pid, host = _lock_owner(self.path)
                if pid is not None and host == socket.gethostname() and not _pid_alive(pid):
                    self.path.unlink(missing_ok=True)  # stale: its process is gone
                    continue
                who = f"pid {pid} on {host}" if pid is not None else "another process"
                raise SweepError(
                    f"{str(self.path.parent)!r} is in use by another slidespin sweep ({who}; "
                    f"lock file {str(self.path)!r}); wait for it to finish, or delete the lock "
                    "file if that process no longer runs (valid: a directory no other sweep uses)"
                ) from None
            except OSError as exc:
                raise _os_error(exc, self.path, resumable=False) from None
            try:
                os.write(fd, me.encode())
            finally:
                os.close(fd)
            self.held = True
            return self
        raise SweepError(
            f"cannot take the lock {str(self.path)!r}; valid: a directory no other sweep uses"
        )  # pragma: no cover

    def __exit__(self, *exc):
        if self.held:
            self.path.unlink(missing_ok=True)
            self.held = False
        return False


def _lock_owner(path: Path):
    try:
        with open(path, "rb") as fh:
            text = fh.read(200).decode("utf-8", errors="replace").split()
        return int(text[0]), (text[1] if len(text) > 1 else "")
    except (OSError, ValueError, IndexError):
        return None, ""


def _pid_alive(pid: int) -> bool:
    if pid <= 0:
        return False
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:  # exists, owned by someone else
        return True
    except OSError:
        return True
    return True
