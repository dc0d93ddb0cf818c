"""The package version, in one place (``slidespin --version`` prints it; sweep manifests record it)."""

__version__ = "0.1.0"
