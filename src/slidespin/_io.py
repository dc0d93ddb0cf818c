"""Small helpers for the edges that write files (CLI outputs, sweep chunks)."""

from __future__ import annotations

import errno
import os
import stat

__all__ = [
    "FIGURE_FORMATS",
    "check_figure_path",
    "check_output_path",
    "distinct_outputs",
    "os_error_kind",
    "read_regular_file",
    "render_figure",
    "write_failure",
    "write_outputs",
]

#: figure formats the CLI writes, by file extension
FIGURE_FORMATS = ("png", "pdf", "svg", "eps", "jpg", "jpeg", "tif", "tiff")


def os_error_kind(exc: OSError) -> str:
    """What an ``OSError`` from a write means, in words a user can act on."""
    return {
        errno.ENOSPC: "disk full",
        getattr(errno, "EDQUOT", -1): "disk quota exceeded",
        errno.EACCES: "permission denied",
        errno.EPERM: "permission denied",
        errno.EROFS: "read-only file system",
    }.get(exc.errno, exc.strerror or type(exc).__name__)


def read_regular_file(
    path: str | bytes | os.PathLike[str] | os.PathLike[bytes], what: str, kind: str, max_bytes: int
) -> bytes:
    """The bytes of the regular file ``path`` (at most ``max_bytes``), or a one-line
    ``ValueError`` naming ``what`` and the path.

    A FIFO, socket or device is refused without reading (opened non-blocking, so a FIFO
    with no writer does not wait); a larger file is refused.
    """
    name = os.fsdecode(os.fspath(path))
    fd: int | None = None
    try:
        # O_NONBLOCK: opening a FIFO must not wait for a writer
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
    except FileNotFoundError:
        raise ValueError(f"{what} {name!r} does not exist") from None
    except IsADirectoryError:
        raise ValueError(f"{what} {name!r} is a directory, not a {kind} file") from None
    except (OSError, ValueError) as exc:  # ValueError: an embedded NUL
        msg = getattr(exc, "strerror", None) or str(exc)
        raise ValueError(f"{what} {name!r} cannot be read: {msg}") from None
    try:
        st = os.fstat(fd)
        if stat.S_ISDIR(st.st_mode):
            raise ValueError(f"{what} {name!r} is a directory, not a {kind} file")
        if not stat.S_ISREG(st.st_mode):
            raise ValueError(
                f"{what} {name!r} is not a regular file (a pipe, socket or "
                f"device); valid: a {kind} file"
            )
        if st.st_size > max_bytes:
            raise ValueError(
                f"{what} {name!r} is {st.st_size} bytes; valid: at most {max_bytes} bytes"
            )
        with os.fdopen(fd, "rb") as fh:
            fd = None
            raw = fh.read(max_bytes + 1)
    except OSError as exc:
        raise ValueError(f"{what} {name!r} cannot be read: {exc.strerror}") from None
    finally:
        if fd is not None:
            os.close(fd)
    if len(raw) > max_bytes:  # grew while being read
        raise ValueError(
            f"{what} {name!r} is larger than {max_bytes} bytes; valid: at most {max_bytes} bytes"
        )
    return raw


def check_output_path(path: str, what: str, *, create_parent: bool = False) -> str:
    """Raise ``ValueError`` unless ``path`` can be written (checked before any work).

    With ``create_parent``, a missing parent directory is allowed if it can be created (its
    nearest existing ancestor is writable); it is created only when the file is written.
    """
    path = os.fspath(path)
    if not path:
        raise ValueError(f"{what} = '' is invalid; valid values: a file path")
    parent = os.path.dirname(os.path.abspath(path)) or "."
    if os.path.isdir(path):
        raise ValueError(f"{what} = {path!r} is a directory; valid values: a file path")
    if os.path.exists(path) and not os.path.isfile(path):
        raise ValueError(f"{what} = {path!r} exists and is not a regular file")
    probe_dir = parent
    if not os.path.isdir(parent):
        if not create_parent:
            raise ValueError(f"{what} = {path!r}: the directory {parent!r} does not exist")
        while not os.path.isdir(probe_dir):
            up = os.path.dirname(probe_dir)
            if up == probe_dir or (os.path.exists(probe_dir) and not os.path.isdir(probe_dir)):
                raise ValueError(f"{what} = {path!r}: the directory {parent!r} cannot be created")
            probe_dir = up
    try:  # a real probe: permissions, read-only file systems, quotas
        import tempfile

        with tempfile.NamedTemporaryFile(dir=probe_dir, prefix=".slidespin-probe-"):
            pass
    except OSError as exc:
        raise ValueError(
            f"{what} = {path!r}: the directory {probe_dir!r} is not writable ({exc.strerror})"
        ) from None
    if os.path.exists(path) and not os.access(path, os.W_OK):
        raise ValueError(f"{what} = {path!r} exists and is not writable")
    return path


def check_figure_path(path: str, what: str, *, create_parent: bool = False) -> str:
    """:func:`check_output_path` plus a known figure format, taken from the extension."""
    path = check_output_path(path, what, create_parent=create_parent)
    ext = os.path.splitext(path)[1].lower().lstrip(".")
    if ext not in FIGURE_FORMATS:
        raise ValueError(
            f"{what} = {path!r}: unknown figure format {ext or '(no extension)'!r}; "
            f"valid extensions: {', '.join('.' + f for f in FIGURE_FORMATS)}"
        )
    return path


def distinct_outputs(*pairs) -> None:
    """Refuse two outputs that are the same file."""
    seen: dict[str, str] = {}
    for path, what in pairs:
        if path:
            key = os.path.realpath(path)
            if key in seen:
                raise ValueError(
                    f"{what} = {path!r} is the same file as {seen[key]}; give different paths"
                )
            seen[key] = what


def render_figure(fig, path: str) -> bytes:
    import io

    buf = io.BytesIO()
    fmt = os.path.splitext(path)[1].lower().lstrip(".")
    # PNG at zlib level 1: a third of the demo's save time, for a file about a third larger
    extra = {"pil_kwargs": {"compress_level": 1}} if fmt == "png" else {}
    fig.savefig(buf, format=fmt, dpi=150, **extra)
    return buf.getvalue()


def write_outputs(files) -> None:
    """Write ``[(path, bytes), ...]`` whole or not at all.

    Each file goes to a temporary name in its directory and is renamed into place; if any
    write fails (disk full, permission denied), the files of this call already in place are
    removed and a one-line ``ValueError`` names the file and the reason.
    """
    written = []
    try:
        for path, data in files:
            parent = os.path.dirname(os.path.abspath(path))
            os.makedirs(parent, exist_ok=True)
            tmp = os.path.join(parent, f".{os.path.basename(path)}.tmp-{os.getpid()}")
            try:
                with open(tmp, "wb") as fh:
                    fh.write(data)
                os.replace(tmp, path)
            except BaseException:
                try:
                    os.unlink(tmp)
                except OSError:
                    pass
                raise
            written.append(path)
    except OSError as exc:
        for p in written:
            try:
                os.unlink(p)
            except OSError:
                pass
        raise ValueError(write_failure(exc, path)) from None


def write_failure(exc: OSError, path) -> str:
    what = os_error_kind(exc)
    return f"{what} while writing {str(path)!r} ({exc.strerror}); nothing was written"
