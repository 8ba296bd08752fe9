"""The three source folders install as one namespace: every subpackage must be listed."""

from __future__ import annotations

import sys
from pathlib import Path

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib

ROOT = Path(__file__).resolve().parent.parent
FOLDERS = {"verifier": "launchverify", "rules": "launchverify.rules",
           "models": "launchverify.models"}


def test_every_package_folder_is_listed_in_pyproject() -> None:
    config = tomllib.loads((ROOT / "pyproject.toml").read_text())
    listed = set(config["tool"]["setuptools"]["packages"])
    found = set()
    for folder, package in FOLDERS.items():
        for init in (ROOT / folder).rglob("__init__.py"):
            parts = init.parent.relative_to(ROOT / folder).parts
            found.add(".".join([package, *parts]))
    assert found == listed


def test_no_generic_top_level_packages() -> None:
    # The install gives `launchverify` only: `rules`, `models`, `verifier` may be found
    # solely as the checkout's own folders (the tests run from it), whatever the
    # checkout's folder is called, never as an installed copy.
    import importlib.machinery

    elsewhere = [entry for entry in sys.path if Path(entry or ".").resolve() != ROOT]
    for name in ("rules", "models", "verifier"):
        spec = importlib.machinery.PathFinder.find_spec(name, elsewhere)
        origin = None if spec is None or spec.origin is None else Path(spec.origin).resolve()
        assert origin is None or origin.parent == ROOT / name, (name, origin)


def test_the_test_extra_runs_the_suite_in_parallel() -> None:
    """The README's test command runs on every core: the extra brings the plugin that
    pyproject's addopts ask for (without it, tests/conftest.py would quietly run the suite
    in one process)."""
    config = tomllib.loads((ROOT / "pyproject.toml").read_text())
    extras = config["project"]["optional-dependencies"]
    addopts = config["tool"]["pytest"]["ini_options"]["addopts"].split()
    assert "--numprocesses=auto" in addopts
    for extra in ("test", "dev"):
        assert any(d.startswith("pytest-xdist") for d in extras[extra]), extra
