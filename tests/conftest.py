"""Settings for the whole suite."""

from __future__ import annotations

import os
import tempfile
from collections.abc import Iterator

import pytest


def pytest_configure() -> None:
    """Check afresh everywhere: tests reuse paths with new contents, and monkeypatch.

    The result cache between runs is tested on its own (tests/test_cache.py), with a
    folder of its own; subprocesses inherit this too.
    """
    os.environ["LAUNCHVERIFY_NO_CACHE"] = "1"
    # the results cache's secret (``findings/sealed.py``) is made in a folder of the
    # session's, never in the home of whoever runs the tests
    os.environ.setdefault("XDG_STATE_HOME", tempfile.mkdtemp(prefix="launchverify-state-"))


@pytest.fixture(autouse=True)
def _reads_unconfined() -> Iterator[None]:
    """Lift a check's read confinement after each test (it lasts until the next check)."""
    yield
    from launchverify.workspace import reading

    reading.confine(None)
