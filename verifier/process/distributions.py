"""Installed distributions' entry points and project URLs, read without importlib.metadata.

``importlib.metadata`` imports the email parser, zipfile, csv and more (15 ms, a tenth of
a one-file check) to answer two small questions: which ``launchverify.rules`` plugins are
installed, and where launchverify's documentation lives. Both are plain text in each
distribution's ``*.dist-info`` (or ``*.egg-info``) folder on ``sys.path``, read here in
path order, the first distribution of a name winning, as ``importlib.metadata`` does.
"""

from __future__ import annotations

import re
import sys
from collections.abc import Iterator
from functools import cache
from pathlib import Path

_SUFFIXES = (".dist-info", ".egg-info")


def _normalized(name: str) -> str:
    return re.sub(r"[-_.]+", "-", name).lower()


@cache
def distributions() -> tuple[tuple[str, Path], ...]:
    """Return (normalized name, metadata folder) of each distribution, first one winning."""
    seen: dict[str, Path] = {}
    for entry in sys.path:
        try:
            found = sorted(Path(entry or ".").iterdir())
        except OSError:
            continue
        for folder in found:
            if folder.name.endswith(_SUFFIXES):
                project = _normalized(folder.name.rsplit(".", 1)[0].partition("-")[0])
                seen.setdefault(project, folder)
    return tuple(seen.items())


def entry_points(group: str) -> Iterator[tuple[str, str]]:
    """Yield (name, ``module:attribute``) of every entry point in ``group``."""
    for _project, folder in distributions():
        try:
            text = (folder / "entry_points.txt").read_text(encoding="utf-8")
        except (OSError, UnicodeDecodeError):
            continue
        section = None
        for line in text.splitlines():
            stripped = line.strip()
            if not stripped or stripped.startswith(("#", ";")):
                continue
            if stripped.startswith("[") and stripped.endswith("]"):
                section = stripped[1:-1].strip()
            elif section == group and "=" in stripped:
                name, _, value = stripped.partition("=")
                yield name.strip(), value.strip()


def project_urls(project: str) -> dict[str, str]:
    """Return a distribution's ``Project-URL`` entries by lower-case label."""
    wanted = _normalized(project)
    folder = next((f for name, f in distributions() if name == wanted), None)
    if folder is None:
        return {}
    try:
        text = (folder / ("METADATA" if folder.suffix == ".dist-info" else "PKG-INFO")
                ).read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError):
        return {}
    urls: dict[str, str] = {}
    for line in text.split("\n\n", 1)[0].splitlines():  # the headers
        key, _, value = line.partition(":")
        if key.strip().lower() == "project-url":
            label, _, url = value.partition(",")
            if url.strip():
                urls[label.strip().lower()] = url.strip()
    return urls


def load(reference: str) -> object:
    """Return what ``module:attribute.path`` names (an entry point's value)."""
    import importlib

    module_name, _, attributes = reference.partition(":")
    found: object = importlib.import_module(module_name.strip())
    for attribute in filter(None, attributes.strip().split(".")):
        found = getattr(found, attribute.split("[")[0].strip())
    return found
