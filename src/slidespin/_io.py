"""Small helpers for the edges that write files (CLI outputs, sweep chunks)."""

from __future__ import annotations

import errno

__all__ = ["os_error_kind"]


def os_error_kind(exc: OSError) -> str:
    """What an ``OSError`` from a write means, in words a user can act on."""
    return {
        errno.ENOSPC: "disk full",
        getattr(errno, "EDQUOT", -1): "disk quota exceeded",
        errno.EACCES: "permission denied",
        errno.EPERM: "permission denied",
        errno.EROFS: "read-only file system",
    }.get(exc.errno, exc.strerror or type(exc).__name__)
