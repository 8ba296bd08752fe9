"""Settings for the whole suite."""

from __future__ import annotations

import atexit
import os
import shutil
import tempfile
from collections.abc import Iterator

import pytest


def pytest_addoption(parser: pytest.Parser, pluginmanager: pytest.PytestPluginManager) -> None:
    """Take pyproject's xdist options in one process when xdist is off (``-p no:xdist``).

    The suite runs in parallel by default (``--numprocesses=auto`` in addopts); without
    the plugin those options would be unknown and pytest would not start at all.
    """
    if pluginmanager.has_plugin("xdist"):
        return
    group = parser.getgroup("xdist", "xdist is off: the suite runs in this process")
    group.addoption("--numprocesses", action="store", default=None, help="ignored")
    group.addoption("--dist", action="store", default="no", help="ignored")


def pytest_configure() -> None:
    """Check afresh everywhere: tests reuse paths with new contents, and monkeypatch.

    The result cache between runs is tested on its own (tests/test_cache.py), with a
    folder of its own; subprocesses inherit this too.
    """
    os.environ["LAUNCHVERIFY_NO_CACHE"] = "1"
    # the results cache's secret (``findings/sealed.py``) is made in a folder of the
    # session's, never in the home of whoever runs the tests
    if "XDG_STATE_HOME" not in os.environ:
        state = tempfile.mkdtemp(prefix="launchverify-state-")
        os.environ["XDG_STATE_HOME"] = state
        atexit.register(shutil.rmtree, state, ignore_errors=True)


@pytest.fixture(autouse=True)
def _reads_unconfined() -> Iterator[None]:
    """Lift a check's read confinement after each test (it lasts until the next check)."""
    yield
    from launchverify.workspace import reading

    reading.confine(None)
