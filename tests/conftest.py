"""Settings for the whole suite."""

from __future__ import annotations

import os


def pytest_configure() -> None:
    """Check afresh everywhere: tests reuse paths with new contents, and monkeypatch.

    The result cache between runs is tested on its own (tests/test_cache.py), with a
    folder of its own; subprocesses inherit this too.
    """
    os.environ["LAUNCHVERIFY_NO_CACHE"] = "1"
