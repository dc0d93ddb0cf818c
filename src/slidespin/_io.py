"""Small helpers for the edges that write files (CLI outputs, sweep chunks)."""

from __future__ import annotations

import errno
import os
import stat

__all__ = ["os_error_kind", "read_regular_file"]


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
