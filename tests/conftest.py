"""Shared test helpers."""

import os

import pytest


def in_ci() -> bool:
    """True under CI (CI=true), where every optional test dependency must be installed."""
    return os.environ.get("CI", "").strip().lower() in ("true", "1", "yes")


def require(module: str):
    """``pytest.importorskip(module)``, except under CI, where a missing test dependency
    fails the test instead of skipping it silently (``.ci/run`` installs them all)."""
    if in_ci():
        import importlib

        return importlib.import_module(module)
    return pytest.importorskip(module)
