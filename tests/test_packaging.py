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
    import importlib.util

    for name in ("rules", "models", "verifier"):
        spec = importlib.util.find_spec(name)
        assert spec is None or "launchverify" not in str(spec.origin), name
