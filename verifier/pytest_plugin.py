"""pytest plugin (entry point ``pytest11``): registers the ``launchverify`` marker.

ament packages mark their linter tests (``@pytest.mark.launchverify``,
``@pytest.mark.linter``) so that ``colcon test --pytest-args -m launchverify`` selects
them; registering the marker keeps ``--strict-markers`` runs quiet.
"""

from __future__ import annotations

import pytest


def pytest_configure(config: pytest.Config) -> None:
    """Register the marker."""
    config.addinivalue_line("markers", "launchverify: tests that run launchverify on "
                            "launch files (launchverify.ament.main_with_errors)")
