"""The package version (one place: the package root re-exports it, saved results record it)."""

__version__ = "0.1.0"
