"""Test helpers (not part of the postproc package)."""
