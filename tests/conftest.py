"""Settings for the whole suite."""

from __future__ import annotations

import atexit
import os
import shutil
import sys
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
    group.addoption("--no-loadscope-reorder", action="store_true", help="ignored")


# The files that take longest, longest first (``pytest --durations=0`` on 2 cores, summed
# per file). xdist hands out whole files in collection
# order (``--no-loadscope-reorder``): a long file started last would leave the other
# core idle for its whole length, as the newcomer's two installs (50 s) once did.
SLOW_FIRST = ("test_hostile_pr.py", "test_corpus.py", "test_lifecycle.py", "test_hostile.py",
              "test_newcomer.py", "test_isolation.py", "test_executor.py", "test_diff.py",
              "test_incremental.py", "test_fixes.py", "test_python_frontend.py",
              "test_model_sweep.py", "test_integrations.py", "test_cli.py",
              "test_report_browser.py", "test_fanout.py", "test_worker_reuse.py",
              "test_metamorphic_unknowns.py")


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    """Run the slowest files first (each file's tests keep their order)."""
    rank = {name: index for index, name in enumerate(SLOW_FIRST)}
    items.sort(key=lambda item: rank.get(item.path.name, len(rank)))


def pytest_configure() -> None:
    """Check afresh everywhere: tests reuse paths with new contents, and monkeypatch.

    The result cache between runs is tested on its own (tests/test_cache.py), with a
    folder of its own; subprocesses inherit this too.
    """
    os.environ["LAUNCHVERIFY_NO_CACHE"] = "1"
    # The suite starts launchverify hundreds of times: a machine that keeps Python from
    # writing bytecode (PYTHONDONTWRITEBYTECODE) would have each start compile every
    # module again, and pytest rewrite every test module in every worker. Bytecode goes to
    # __pycache__ folders, which git ignores; launch files are still evaluated without it
    # (the sandbox turns it off for what it imports).
    os.environ.pop("PYTHONDONTWRITEBYTECODE", None)
    sys.dont_write_bytecode = False
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
