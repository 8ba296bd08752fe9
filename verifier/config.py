"""Project configuration: ``launchverify.toml`` or ``[tool.launchverify]`` in pyproject.toml.

Found by walking up from the first checked path (the nearest file wins; in one folder
``launchverify.toml`` before ``pyproject.toml``, and a pyproject without the table does
not count), as ruff and mypy find theirs. Relative paths in it are relative to its folder.

    select = ["LV1", "LV5"]                  # codes, slugs or prefixes
    ignore = ["LV404"]
    per-file-ignores = {"test/**" = ["LV101"]}
    exclude = ["build/**", "legacy/*.launch.xml"]
    arguments = {use_sim_time = "true"}      # like name:=value on the command line
    environment = {ROBOT_NAME = "alpha"}     # like --env
    workspace = "../.."
    package-paths = ["/opt/ros/jazzy", "../vendor_ws/src"]
    severity = {LV404 = "error", LV202 = "info"}
    fail-on = "warning"
    distro = "humble"                        # default: $ROS_DISTRO, else any
    jobs = 4                                 # processes (Python files, rules)
    time-limit = 10                          # seconds per Python evaluation
    max-file-size = 10                       # MB; larger files are not read
    external-names = ["/gps/*", "scan"]      # fed from outside the launch (LV602)
    single-writer-topics = ["*cmd_vel"]      # one publisher at a time (LV604)

Name globs (``external-names``, ``single-writer-topics``) match fully qualified topic,
service and action names; a glob without a leading ``/`` matches at any namespace depth
(``scan`` is ``/scan`` and ``/robot1/scan``). Like the arguments, they hold for the whole
check (the configuration of the check, not the one nearest each file).

A configuration file inside the checked tree comes with the pull request being checked:
the folders it names outside the workspace (``package-paths``, ``workspace``) are read
only when the user confirms them (``--package-path``, ``LAUNCHVERIFY_PACKAGE_PATH``);
see ``confined``.
"""

from __future__ import annotations

import dataclasses
import fnmatch
import os
import re
import sys
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from launchverify.models.distros import DISTROS
from launchverify.workspace.paths import relative_file, resolved

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover - Python 3.10
    import tomli as tomllib

CONFIG_NAMES = ("launchverify.toml", "pyproject.toml")
PACKAGE_PATH_VARIABLE = "LAUNCHVERIFY_PACKAGE_PATH"  # folders the user lets checks read
_TABLE = re.compile(r"^\s*\[\s*tool\s*\.\s*launchverify\b", re.MULTILINE)
SEVERITIES = ("error", "warning", "info")
KNOWN_KEYS = frozenset({
    "select", "ignore", "per-file-ignores", "exclude", "arguments", "environment",
    "workspace", "package-paths", "severity", "fail-on", "distro", "jobs", "time-limit",
    "max-file-size", "external-names", "single-writer-topics",
})


class ConfigError(ValueError):
    """A configuration file launchverify cannot use (exit status 2)."""


@dataclass
class Config:
    """What a configuration file says; empty when there is none."""

    path: Path | None = None
    select: list[str] | None = None
    ignore: list[str] = field(default_factory=list)
    per_file_ignores: dict[str, list[str]] = field(default_factory=dict)
    exclude: list[str] = field(default_factory=list)
    arguments: dict[str, str] = field(default_factory=dict)
    environment: dict[str, str] = field(default_factory=dict)
    workspace: Path | None = None
    package_paths: list[Path] = field(default_factory=list)
    severity: dict[str, str] = field(default_factory=dict)
    fail_on: str | None = None
    distro: str | None = None
    jobs: int | None = None
    time_limit: float | None = None  # seconds
    max_file_size: float | None = None  # MB
    external_names: list[str] = field(default_factory=list)  # name globs
    single_writer_topics: list[str] | None = None  # name globs; None: the rule's default

    @property
    def root(self) -> Path:
        """Return the folder relative paths and patterns are read from."""
        return self.path.parent if self.path is not None else Path.cwd()

    def ignored_in(self, file: Path) -> list[str]:
        """Return the selectors ``per-file-ignores`` applies to a file."""
        relative = relative_file(file, self.root)
        return [code for pattern, codes in self.per_file_ignores.items()
                if matches(relative, pattern) for code in codes]

    def excludes(self, file: Path) -> bool:
        """Return whether a discovered file is excluded from the check."""
        relative = relative_file(file, self.root)
        return any(matches(relative, pattern) for pattern in self.exclude)


def matches(relative: str, pattern: str) -> bool:
    """Match a path (posix, relative) against a glob; a pattern without ``/`` matches names.

    ``*`` crosses folders, as in ruff's per-file-ignores; ``dir/`` or ``dir/**`` matches
    everything below ``dir``.
    """
    pattern = pattern.strip().removeprefix("./")
    if pattern.endswith("/"):
        pattern += "**"
    if "/" not in pattern:
        return fnmatch.fnmatchcase(relative.rsplit("/", 1)[-1], pattern) or \
            fnmatch.fnmatchcase(relative, pattern)
    if pattern.endswith("/**") and relative.startswith(pattern[:-2]):
        return True
    return fnmatch.fnmatchcase(relative, pattern)


def find_config(start: Path) -> Path | None:
    """Return the nearest configuration file above ``start`` (itself included)."""
    folder = resolved(start)
    if not folder.is_dir():
        folder = folder.parent
    for candidate in (folder, *folder.parents):
        for name in CONFIG_NAMES:
            path = candidate / name
            if path.is_file() and (name != "pyproject.toml" or _has_table(path)):
                return path
    return None


def _has_table(pyproject: Path) -> bool:
    """Return whether a pyproject.toml configures launchverify.

    One that is not valid TOML is someone else's problem, unless it has a
    ``[tool.launchverify]`` table: then its error is ours to report (file and line), not a
    reason to check with the defaults.
    """
    try:
        return "launchverify" in _read(pyproject).get("tool", {})
    except ConfigError:
        try:
            text = pyproject.read_text(encoding="utf-8", errors="replace")
        except OSError:
            return False
        if _TABLE.search(text):
            raise
        return False


def _read(path: Path) -> dict[str, Any]:
    try:
        with path.open("rb") as handle:
            return tomllib.load(handle)
    except OSError as error:
        raise ConfigError(f"cannot read {path}: {error.strerror}") from error
    except (tomllib.TOMLDecodeError, ValueError, RecursionError) as error:
        raise ConfigError(f"{path}: invalid TOML: {error}") from error


def load_config(path: Path) -> Config:
    """Read one configuration file."""
    data = _read(path)
    if path.name == "pyproject.toml":
        data = data.get("tool", {}).get("launchverify", {})
    if not isinstance(data, dict):
        raise ConfigError(f"{path}: [tool.launchverify] must be a table")
    unknown = sorted(set(data) - KNOWN_KEYS)
    if unknown:
        raise ConfigError(f"{path}: unknown key(s) {', '.join(unknown)}; known: "
                          f"{', '.join(sorted(KNOWN_KEYS))}")
    reader = _Reader(path, data)
    base = path.parent
    workspace = reader.text("workspace")
    config = Config(
        path=path,
        select=reader.texts("select") if "select" in data else None,
        ignore=reader.texts("ignore") or [],
        per_file_ignores=reader.table_of_texts("per-file-ignores"),
        exclude=reader.texts("exclude") or [],
        arguments=reader.table("arguments"),
        environment=reader.table("environment"),
        workspace=(base / workspace) if workspace else None,
        package_paths=[base / p for p in reader.texts("package-paths") or []],
        severity=reader.table("severity"),
        fail_on=reader.text("fail-on"),
        distro=reader.text("distro"),
        jobs=int(n) if (n := reader.number("jobs", integer=True)) is not None else None,
        time_limit=reader.number("time-limit"),
        max_file_size=reader.number("max-file-size"),
        external_names=reader.names("external-names") or [],
        single_writer_topics=reader.names("single-writer-topics"),
    )
    for code, level in config.severity.items():
        if level not in SEVERITIES:
            raise ConfigError(f"{path}: severity of {code} must be one of "
                              f"{', '.join(SEVERITIES)}, not {level!r}")
    if config.distro is not None and config.distro not in DISTROS:
        raise ConfigError(f"{path}: distro must be one of {', '.join(DISTROS)}")
    if config.fail_on is not None and config.fail_on not in SEVERITIES:
        raise ConfigError(f"{path}: fail-on must be one of {', '.join(SEVERITIES)}")
    return config


class _Reader:
    """Typed access to a configuration table, with errors that name the key."""

    def __init__(self, path: Path, data: dict[str, Any]) -> None:
        self.path = path
        self.data = data

    def fail(self, key: str, wanted: str) -> ConfigError:
        return ConfigError(f"{self.path}: {key} must be {wanted}")

    def text(self, key: str) -> str | None:
        value = self.data.get(key)
        if value is not None and not isinstance(value, str):
            raise self.fail(key, "a string")
        return value

    def number(self, key: str, *, integer: bool = False) -> float | None:
        value = self.data.get(key)
        if value is None:
            return None
        kinds = (int,) if integer else (int, float)
        if isinstance(value, bool) or not isinstance(value, kinds) or not 0 < value < 1e9:
            raise self.fail(key, "a positive whole number" if integer else "a positive number")
        return value

    def texts(self, key: str) -> list[str] | None:
        value = self.data.get(key)
        if value is None:
            return None
        if isinstance(value, str):
            return [value]
        if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
            raise self.fail(key, "a list of strings")
        return list(value)

    def names(self, key: str) -> list[str] | None:
        """Return a list of ROS name globs: not empty, no spaces (a name has none)."""
        value = self.texts(key)
        if value is not None and any(not v.strip() or any(c.isspace() for c in v)
                                     for v in value):
            raise self.fail(key, "a list of name globs (no blanks, no spaces)")
        return value

    def table(self, key: str) -> dict[str, str]:
        value = self.data.get(key, {})
        if not isinstance(value, dict):
            raise self.fail(key, "a table")
        out = {}
        for name, item in value.items():
            if isinstance(item, bool):
                item = "true" if item else "false"
            if not isinstance(item, (str, int, float)):
                raise self.fail(f"{key}.{name}", "a string")
            out[str(name)] = str(item)
        return out

    def table_of_texts(self, key: str) -> dict[str, list[str]]:
        value = self.data.get(key, {})
        if not isinstance(value, dict):
            raise self.fail(key, "a table of lists of codes")
        out = {}
        for pattern, codes in value.items():
            if isinstance(codes, str):
                codes = [codes]
            if not isinstance(codes, list) or not all(isinstance(c, str) for c in codes):
                raise self.fail(f"{key}.{pattern!r}", "a list of codes")
            out[str(pattern)] = list(codes)
        return out


class ConfigTree:
    """The nearest configuration of each file, as ruff finds it.

    The configuration of the check (``root``: the one nearest the first path, or given
    with ``--config``) decides what is global: arguments, environment, workspace, package
    paths, distro, limits. What is about files (``select``, ``ignore``,
    ``per-file-ignores``, ``severity``, ``exclude``) comes, for each file, from the
    configuration nearest to it: a package's own ``launchverify.toml`` holds for its files
    when the check starts at the workspace root. The command line's ``--select`` and
    ``--ignore`` apply on top of every one.
    """

    def __init__(self, root: Config, nested: bool = True) -> None:
        self.root = root
        self.nested = nested
        self._by_folder: dict[Path, Config] = {}
        self._by_file: dict[Path, Config] = {}
        self._by_path: dict[Path, Config] = {} if root.path is None else {
            resolved(root.path): root}

    def nearest(self, file: Path) -> Config:
        """Return the configuration that holds for a file."""
        if not self.nested:
            return self.root
        known = self._by_file.get(file)  # every finding asks for its file's
        if known is None:
            known = self._by_file[file] = self._nearest(resolved(file).parent)
        return known

    def _nearest(self, folder: Path) -> Config:
        known = self._by_folder.get(folder)
        if known is None:
            path = find_config(folder)
            if path is None:
                known = self.root
            else:
                path = resolved(path)
                if path not in self._by_path:
                    self._by_path[path] = load_config(path)
                known = self._by_path[path]
            self._by_folder[folder] = known
        return known

    def others(self) -> list[Config]:
        """Return the configurations met so far besides the root one."""
        return [c for c in self._by_path.values() if c is not self.root]


def confirmed_package_paths(given: Sequence[Path] = ()) -> list[Path]:
    """Return the package folders the user named: ``--package-path`` and the variable."""
    listed = os.environ.get(PACKAGE_PATH_VARIABLE, "")
    return [*given, *(Path(part) for part in listed.split(os.pathsep) if part)]


def confined(config: Config, checked: Sequence[Path], workspace: Path,
             confirmed: Sequence[Path]) -> tuple[Config, list[str]]:
    """Return ``config`` without the folders it may not add, and a note for each.

    A configuration file inside the workspace or a checked path is the checked tree's
    own: a pull request wrote it. Folders it names outside the workspace would widen what
    Python launch files may read (and so what findings may show), so they count only
    when inside a folder the user confirmed. A file elsewhere (``--config ~/lv.toml``, a
    file above the repository) is the user's, and trusted.
    """
    if config.path is None:
        return config, []
    home = resolved(workspace)
    if not any(resolved(config.path).is_relative_to(resolved(path))
               for path in (home, *checked)):
        return config, []
    allowed = [home, *(resolved(path) for path in confirmed)]

    def kept(folder: Path) -> bool:
        return any(resolved(folder).is_relative_to(root) for root in allowed)

    notes = [f"{config.path.name} names {key} {str(folder)!r}, outside the workspace: "
             f"not read (a folder given with --package-path or {PACKAGE_PATH_VARIABLE} "
             "confirms it)"
             for key, folder in [*(("package path", p) for p in config.package_paths),
                                 *([("workspace", config.workspace)] if config.workspace
                                   else [])]
             if not kept(folder)]
    workspace_key = config.workspace if config.workspace and kept(config.workspace) else None
    return dataclasses.replace(
        config, package_paths=[p for p in config.package_paths if kept(p)],
        workspace=workspace_key), notes
