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
only when the user confirms them (``--package-path``, ``LAUNCHVERIFY_PACKAGE_PATH``),
and its ``jobs`` is at most the machine's cores; see ``confined``. Any configuration
file is read as launch files are (``reading.read_file``): a regular file of at most the
size limit, never a FIFO, a device or a system file (a ``launchverify.toml`` linked to
``/dev/zero`` is an error at once), and TOML nested too deeply for the parser is an
error, not a crash. A file with mistakes is one error naming all of them, each at its
line with the known key or rule it may misspell (``_Problems``).
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
from launchverify.suggest import did_you_mean, did_you_mean_any
from launchverify.workspace import reading
from launchverify.workspace.paths import relative_file, resolved

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
    """A configuration file launchverify cannot use (exit status 2).

    ``lines``: the message is launchverify's own lines (every problem of the file, one a
    line), each made inert already; else it is one line, made inert whole when shown.
    """

    def __init__(self, message: str = "", *, lines: bool = False) -> None:
        super().__init__(message)
        self.lines = lines

    def shown(self) -> str:
        """Return the message for a terminal, its control characters shown visibly."""
        from launchverify.render.inert import inert, inert_block

        return inert_block(str(self)) if self.lines else inert(str(self))


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
        if not self.exclude:
            return False
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
        found = config_in(candidate)
        if found is not None:
            return found
    return None


def config_in(folder: Path) -> Path | None:
    """Return the configuration file of a folder itself, if it has one.

    A name that is there but no file (a FIFO, a link to a device) is not passed over:
    reading it says why it is refused (``ConfigError``).
    """
    for name in CONFIG_NAMES:
        path = folder / name
        if path.exists() and not path.is_dir() and (name != "pyproject.toml"
                                                    or _has_table(path)):
            return path
    return None


def _has_table(pyproject: Path) -> bool:
    """Return whether a pyproject.toml configures launchverify.

    One that is not valid TOML is someone else's problem, unless it has a
    ``[tool.launchverify]`` table: then its error is ours to report (file and line), not a
    reason to check with the defaults. One that cannot be opened is someone else's
    too; one that opens but is refused for what it is (a device, too large) is reported.
    """
    try:
        text = _read_text(pyproject)
    except ConfigError:
        if os.access(pyproject, os.R_OK):
            raise
        return False
    try:
        return "launchverify" in _parse(pyproject, text).get("tool", {})
    except ConfigError:
        if _TABLE.search(text):
            raise
        return False


MAX_DEPTH = 100  # nested arrays, tables and key parts a configuration may have
# What cannot nest: strings (multi-line ones first) and comments.
_NOT_STRUCTURE = re.compile(r'"""(?:[^\\]|\\.)*?"""|\'\'\'.*?\'\'\'|"(?:[^"\\\n]|\\.)*"'
                            r"|'[^'\n]*'|#[^\n]*", re.DOTALL)
_STRUCTURE = re.compile(r"[\[\]{}.=,\n]")
_TOML_POSITION = re.compile(r"\s*\(at (?:line (\d+), column (\d+)|end of document)\)$")


def _read_text(path: Path) -> str:
    """Return a configuration file's text, read as a launch file is (``read_file``).

    Wherever it is (the user's may be above the workspace, outside the folders a check
    reads), but only a regular file within the size limit, never a system file.
    """
    try:
        data = reading.read_file(path, anywhere=True)
    except reading.Outside:
        raise ConfigError(f"{path}: a system file (below /proc, /sys or /dev): "
                          "not read") from None
    except reading.Unreadable as error:
        raise ConfigError(f"cannot read {path}: {error}") from None
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as error:
        line = data.count(b"\n", 0, error.start) + 1
        raise ConfigError(f"{path}:{line}: invalid TOML: not UTF-8 text") from None


def _refuse_deep(path: Path, text: str) -> None:
    """Refuse TOML nested more than ``MAX_DEPTH`` deep, before tomllib reads it.

    tomllib recurses once per array or inline table (Python's recursion limit, else),
    and its time grows with the square of a dotted key's length: ``a.a.a...`` of
    100,000 parts took minutes. Depth here is the open brackets (arrays, inline tables,
    table headers) plus the dots of the key being written, outside strings and comments.
    """
    if sum(text.count(mark) for mark in ".[{") <= MAX_DEPTH:
        return  # nearly every configuration: nothing to count
    bare = _NOT_STRUCTURE.sub(lambda match: "''" + "\n" * match.group().count("\n"), text)
    brackets = dots = 0
    line = 1
    for match in _STRUCTURE.finditer(bare):
        mark = match.group()
        if mark == ".":
            dots += 1
        else:  # a key ends at '=', ',', a line's end or a bracket
            dots = 0
            line += mark == "\n"
            if mark in "[{":
                brackets += 1
            elif mark in "]}":
                brackets = max(brackets - 1, 0)
        if brackets + dots > MAX_DEPTH:
            raise ConfigError(f"{path}:{line}: invalid TOML: nested more than {MAX_DEPTH} "
                              "deep (arrays, tables and dotted keys)")


def _parse(path: Path, text: str) -> dict[str, Any]:
    """Return a configuration file's TOML, or say where it is invalid (``ConfigError``)."""
    _refuse_deep(path, text)
    if sys.version_info >= (3, 11):  # imported here: a check without a configuration
        import tomllib  # reads no TOML (4 ms of a one-file check)
    else:  # pragma: no cover - Python 3.10
        import tomli as tomllib
    try:
        return tomllib.loads(text)
    except RecursionError:  # tomllib recurses once per nested array or inline table
        raise ConfigError(f"{path}: invalid TOML: nested too deeply (arrays or inline "
                          "tables)") from None
    except (tomllib.TOMLDecodeError, ValueError) as error:
        message = str(error)
        at = _TOML_POSITION.search(message)  # tomllib ends its messages so
        if at is None:
            raise ConfigError(f"{path}: invalid TOML: {message}") from error
        where = f"{at[1]}:{at[2]}" if at[1] else str(_line_count(text))
        raise ConfigError(f"{path}:{where}: invalid TOML: {message[:at.start()]}") from error


def _line_count(text: str) -> int:
    """Return the number of the last line of a text (where its end of document is)."""
    return text.rstrip("\n").count("\n") + 1


class _Problems:
    """What is wrong in one configuration file, gathered so that all are said at once.

    A user fixing a file should not meet its mistakes one run at a time: each problem is
    kept with its line, and ``raise_any`` reports them together, in the file's order.
    """

    def __init__(self, lines: _Lines) -> None:
        self.lines = lines
        self.found: list[tuple[int, str, str]] = []  # line (0: unknown), where, message
        self.unplaced_keys = False  # an unknown key close to no known one

    def add(self, message: str, *keys: str, value: str | None = None) -> None:
        """Record a problem found at a key path (and a string value under it)."""
        line = self.lines.line(*keys, value=value) if keys else None
        where = f"{self.lines.path}:{line}" if line is not None else str(self.lines.path)
        self.found.append((line or 0, where, message))

    def raise_any(self) -> None:
        """Raise one ``ConfigError`` naming every problem (one line alone when one)."""
        if not self.found:
            return
        known = ", ".join(sorted(KNOWN_KEYS))
        problems = sorted(self.found, key=lambda problem: problem[0])  # stable: found order
        if len(problems) == 1:
            _, where, message = problems[0]
            tail = f" (known: {known})" if self.unplaced_keys else ""
            raise ConfigError(f"{where}: {message}{tail}")
        from launchverify.render.inert import inert

        shown = [inert(f"{self.lines.path}: {len(problems)} problems:"),
                 *(inert(f"  {where}: {message}") for _, where, message in problems)]
        if self.unplaced_keys:
            shown.append(f"  (known keys: {known})")
        raise ConfigError("\n".join(shown), lines=True)


class _Lines:
    """Where keys and values are written in a configuration file.

    tomllib gives no positions: a key is looked for as TOML writes one (at a line's
    start, after ``{``, ``,`` or ``.``, or in a table header), each key of a path from
    where the previous one was found, and from the ``[tool.launchverify]`` header in a
    pyproject.toml. Not found (an unusual layout): the file alone is named.
    """

    def __init__(self, path: Path, text: str) -> None:
        self.path = path
        self.lines = text.split("\n")  # TOML's line ends; splitlines knows more
        header = _TABLE.search(text) if path.name == "pyproject.toml" else None
        self.start = text.count("\n", 0, header.start()) if header else 0

    def line(self, *keys: str, value: str | None = None) -> int | None:
        """Return the 1-based line of a key path (and of a string value under it)."""
        found = self.start
        patterns = [_key_pattern(key) for key in keys]
        if value is not None:
            patterns.append(re.compile(f"[\"']{re.escape(value)}[\"']"))
        for pattern in patterns:
            at = next((number for number in range(found, len(self.lines))
                       if not self.lines[number].lstrip().startswith("#")
                       and pattern.search(self.lines[number])), None)
            if at is None:
                return None
            found = at
        return found + 1

    def where(self, *keys: str, value: str | None = None) -> str:
        """Return ``file:line`` for a key path, or the file when the line is not found."""
        line = self.line(*keys, value=value)
        return f"{self.path}:{line}" if line is not None else str(self.path)


def _key_pattern(key: str) -> re.Pattern[str]:
    """Return a pattern finding a TOML key (bare or quoted) where it is defined."""
    written = f"(?:{re.escape(key)}|\"{re.escape(key)}\"|'{re.escape(key)}')"
    return re.compile(f"(?:^|[{{,.])\\s*{written}\\s*[=.]|^\\s*\\[(?:[^\\]]*[.\\s])?"
                      f"{written}\\s*\\]")


def load_config(path: Path) -> Config:
    """Read one configuration file."""
    text = _read_text(path)
    data = _parse(path, text)
    lines = _Lines(path, text)
    if path.name == "pyproject.toml":
        data = data.get("tool", {}).get("launchverify", {})
    if not isinstance(data, dict):
        raise ConfigError(f"{lines.where('launchverify')}: [tool.launchverify] must be a "
                          "table")
    problems = _Problems(lines)
    _unknown_keys(data, problems)
    reader = _Reader(problems, data)
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
            problems.add(f"severity of {code} must be one of {', '.join(SEVERITIES)}, "
                         f"not {level!r}", "severity", code)
    if config.distro is not None and config.distro not in DISTROS:
        problems.add(f"distro must be one of {', '.join(DISTROS)}"
                     f"{did_you_mean(config.distro, DISTROS)}", "distro")
    if config.fail_on is not None and config.fail_on not in SEVERITIES:
        problems.add(f"fail-on must be one of {', '.join(SEVERITIES)}"
                     f"{did_you_mean(config.fail_on, SEVERITIES)}", "fail-on")
    _unknown_rules(config, problems)
    problems.raise_any()
    return config


def _unknown_keys(data: dict[str, Any], problems: _Problems) -> None:
    """Name each unknown key where it is written, with the known key it may misspell.

    ``fail_on`` or ``Select`` is the known key written another way; else the closest
    known key, if one is close.
    """
    for key in sorted(set(data) - KNOWN_KEYS):
        respelt = key.lower().replace("_", "-")
        hint = (f" (did you mean {respelt!r}?)" if respelt in KNOWN_KEYS
                else did_you_mean(key, KNOWN_KEYS))
        problems.unplaced_keys |= not hint
        problems.add(f"unknown key {key!r}{hint}", key)


def unknown_selector(selector: str) -> str | None:
    """Return why a rule selector names no rule, with the closest ones; ``None`` if it does.

    (A selector is a code, a slug or a code prefix: ``LV101``, ``duplicate-node-name``,
    ``LV1``.)
    """
    from launchverify.registry import RegistryError, all_rules, resolve

    try:
        resolve(selector)
    except RegistryError:
        names = [name for rule in all_rules() for name in (rule.code, rule.slug)]
        hint = did_you_mean_any(selector.strip(), names) or \
            " (`launchverify rules` lists every rule)"
        return f"no rule is called {selector!r}{hint}"
    return None


def _unknown_rules(config: Config, problems: _Problems) -> None:
    """Name each selector that names no rule, where it is written (not at check time)."""
    places = [*((("select",), s) for s in config.select or []),
              *((("ignore",), s) for s in config.ignore),
              *((("per-file-ignores", pattern), s)
                for pattern, selectors in config.per_file_ignores.items() for s in selectors),
              *((("severity", s), None) for s in config.severity)]
    for keys, selector in places:
        problem = unknown_selector(selector if selector is not None else keys[-1])
        if problem is not None:
            problems.add(f"{keys[0]}: {problem}", *keys, value=selector)


class _Reader:
    """Typed access to a configuration table.

    A value of the wrong type is a problem (naming the key and its line) and reads as
    unset, so that the rest of the file is still read and every problem said at once.
    """

    def __init__(self, problems: _Problems, data: dict[str, Any]) -> None:
        self.problems = problems
        self.data = data

    def fail(self, key: str, wanted: str, *, under: str | None = None) -> None:
        """Record that a value is not what ``key`` wants (``under.key``)."""
        keys = (key,) if under is None else (under, key)
        shown = key if under is None else f"{under}.{key if '.' not in key else repr(key)}"
        self.problems.add(f"{shown} must be {wanted}", *keys)

    def text(self, key: str) -> str | None:
        value = self.data.get(key)
        if value is not None and not isinstance(value, str):
            self.fail(key, "a string")
            return None
        return value

    def number(self, key: str, *, integer: bool = False) -> float | None:
        value = self.data.get(key)
        if value is None:
            return None
        kinds = (int,) if integer else (int, float)
        if isinstance(value, bool) or not isinstance(value, kinds) or not 0 < value < 1e9:
            self.fail(key, "a positive whole number" if integer else "a positive number")
            return None
        return value

    def texts(self, key: str) -> list[str] | None:
        value = self.data.get(key)
        if value is None:
            return None
        if isinstance(value, str):
            return [value]
        if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
            self.fail(key, "a list of strings")
            return None
        return list(value)

    def names(self, key: str) -> list[str] | None:
        """Return a list of ROS name globs: not empty, no spaces (a name has none)."""
        value = self.texts(key)
        if value is not None and any(not v.strip() or any(c.isspace() for c in v)
                                     for v in value):
            self.fail(key, "a list of name globs (no blanks, no spaces)")
            return None
        return value

    def table(self, key: str) -> dict[str, str]:
        value = self.data.get(key, {})
        if not isinstance(value, dict):
            self.fail(key, "a table")
            return {}
        out = {}
        for name, item in value.items():
            if isinstance(item, bool):
                item = "true" if item else "false"
            if not isinstance(item, (str, int, float)):
                self.fail(str(name), "a string", under=key)
                continue
            out[str(name)] = str(item)
        return out

    def table_of_texts(self, key: str) -> dict[str, list[str]]:
        value = self.data.get(key, {})
        if not isinstance(value, dict):
            self.fail(key, "a table of lists of codes")
            return {}
        out = {}
        for pattern, codes in value.items():
            if isinstance(codes, str):
                codes = [codes]
            if not isinstance(codes, list) or not all(isinstance(c, str) for c in codes):
                self.fail(str(pattern), "a list of codes", under=key)
                continue
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
        """Return the configuration of a (real) folder: its own, else its parent's."""
        known = self._by_folder.get(folder)
        if known is None:
            path = config_in(folder)
            if path is not None:
                path = resolved(path)
                if path not in self._by_path:
                    self._by_path[path] = load_config(path)
                known = self._by_path[path]
            else:
                known = self.root if folder.parent == folder else self._nearest(folder.parent)
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
    """Return ``config`` without what it may not ask for, and a note for each.

    A configuration file inside the workspace or a checked path is the checked tree's
    own: a pull request wrote it. Folders it names outside the workspace would widen what
    Python launch files may read (and so what findings may show), so they count only
    when inside a folder the user confirmed. Its ``jobs`` is at most the machine's cores:
    each worker may hold its memory limit (``isolation.confine.Limits``), so 10,000 of
    them would take the machine. A file elsewhere (``--config ~/lv.toml``, a file above
    the repository) is the user's, and trusted, as ``-j`` is.
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
    jobs, lowered = _jobs_within_cores(config.jobs)
    if lowered:
        notes.append(f"{config.path.name} sets jobs = {config.jobs}: lowered to {jobs}, the "
                     "machine's cores (a -j on the command line is not)")
    return dataclasses.replace(
        config, package_paths=[p for p in config.package_paths if kept(p)],
        workspace=workspace_key, jobs=jobs), notes


def _jobs_within_cores(jobs: int | None) -> tuple[int | None, bool]:
    """Return ``jobs`` capped at the machine's cores, and whether it was lowered."""
    cores = os.cpu_count() or 1
    if jobs is not None and jobs > cores:
        return cores, True
    return jobs, False
