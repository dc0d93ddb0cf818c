"""pyplot for the figures of :mod:`slidespin.viz`, imported on first use.

matplotlib is imported only by the functions that draw, so that importing slidespin does not
import it; without a display (a headless machine) pyplot falls back to the Agg backend.
"""

from __future__ import annotations


def _plt():
    """matplotlib.pyplot, imported now (Agg if the configured backend cannot start)."""
    # lazy: matplotlib is slow to import, and only the functions that draw need it
    import matplotlib

    if matplotlib.get_backend().lower() not in ("agg", "module://matplotlib_inline.backend_inline"):
        try:
            import matplotlib.pyplot as plt  # noqa: F401
        except Exception:  # pragma: no cover - headless fallback
            matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt
