"""The check pipeline: discover -> load -> evaluate -> rules -> findings.

Each launch file found is evaluated as a root, as ``ros2 launch`` would start it; a file
that others include is evaluated through its includers too. Findings from every root are
merged; rules marked ``every_context`` keep a finding only when every evaluation that
reached its file agrees (an argument unused standalone may be read by an includer).
"""

from __future__ import annotations

import dataclasses
import os
import time
from collections import Counter
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass, field
from functools import partial
from pathlib import Path
from typing import TYPE_CHECKING, TypeVar

from launchverify.config import Config, ConfigTree, matches
from launchverify.findings.cache import (
    Entry,
    FolderStamp,
    Kept,
    ResultCache,
    in_use,
    options_text,
    settled,
    stamps_of,
)
from launchverify.problems import NotFollowed
from launchverify.process.collector import collector_paused
from launchverify.rule import Finding, Rule, RuleContext, Severity
from launchverify.span import Span
from launchverify.workspace import reading
from launchverify.workspace.packages import (
    PackageIndex,
    Workspace,
    discover_workspace,
    workspace_prefixes,
)
from launchverify.workspace.paths import display_path, relative_file

if TYPE_CHECKING:
    from launchverify.findings.incremental import Incremental, RootResult
    from launchverify.findings.verdicts import Verdicts
    from launchverify.graph import LaunchGraph
    from launchverify.ir.symbolic import PathCondition
    from launchverify.workspace.includers import Includers

# The evaluator, the rules and the worker pool are imported where a check runs: a cached
# run (the report stored, nothing changed) never needs them, and importing them all took
# half of such a run.

DEFAULT_TIME_LIMIT = 10.0
T = TypeVar("T")


class UsageError(Exception):
    """Bad input from the user (exit status 2).

    Its message is made inert whole when shown (``shown``): a line break in a name from a
    checked file must not forge another line. ``lines``: the message is launchverify's own
    lines, whatever it quotes of the checked files made inert already (their line breaks
    are kept).
    """

    def __init__(self, message: str = "", *, lines: bool = False) -> None:
        super().__init__(message)
        self.lines = lines

    def shown(self) -> str:
        """Return the message for a terminal, its control characters shown visibly."""
        from launchverify.render.inert import inert, inert_block

        return inert_block(str(self)) if self.lines else inert(str(self))


class NoLaunchFiles(UsageError):
    """The paths given hold no launch file (``diff``: a side without any, not an error)."""


@dataclass
class CheckOptions:
    """What ``launchverify check`` was asked to do (the configuration file already merged)."""

    paths: list[Path]
    arguments: dict[str, str] = field(default_factory=dict)
    workspace: Path | None = None
    select: list[str] | None = None
    ignore: list[str] | None = None
    environment: dict[str, str] = field(default_factory=dict)
    config: Config = field(default_factory=Config)
    exclude: list[str] = field(default_factory=list)  # globs, relative to the working dir
    baseline: Path | None = None
    launch_files_only: bool = False  # given files must look like launch files too
    distro: str | None = None  # the ROS 2 distribution to check for (None: any)
    jobs: int | None = None  # Python files evaluated ahead at once (None: default_jobs())
    time_limit: float = DEFAULT_TIME_LIMIT  # seconds per Python evaluation
    max_file_size: int = reading.DEFAULT_LIMIT  # bytes; larger files are not read
    progress: Callable[[int, int], None] | None = None  # (files evaluated, files in all)
    # For the nearest configuration of each file (ConfigTree): what the command line said
    # itself, and whether files may have configurations of their own (not with --config
    # FILE or --isolated).
    command_select: list[str] | None = None
    command_ignore: list[str] = field(default_factory=list)
    nested_configs: bool = False
    affected: bool = False  # paths are changed files: check the launch files they affect
    # Parameter files among the paths: checked through the launch files that load them,
    # as ``affected`` checks a changed one.
    parameter_files: list[Path] = field(default_factory=list)


@dataclass
class Report:
    """The outcome of a check."""

    findings: list[Finding]
    files: int
    seconds: float
    display: dict[Path, str]
    graphs: list[LaunchGraph] = field(default_factory=list)
    checked: list[Path] = field(default_factory=list)  # the launch files checked as roots
    suppressed: int = 0  # findings silenced by inline comments
    baselined: int = 0  # findings dropped because the baseline records them
    python_files: int = 0  # Python launch files evaluated, each in a confined process
    protections: str | None = None  # which confinement layers held, as workers said
    # What reporters would derive from the graphs, kept when a cached report has none.
    unseen: list[tuple[str, Span]] | None = None
    queries: int | None = None
    loaded: set[Path] | None = None
    # the folders the check read below, to read code frames below again when the report
    # comes from the cache (``reading.confine``)
    readable: tuple[str, ...] | None = None
    cached: bool = False  # read from the cache between runs, not checked again
    kept: Kept | None = None  # what the next check may keep of this one (not stored with it)
    packages: PackageIndex | None = None  # the index the check built (not stored with it)
    workspace: Workspace | None = None  # where packages were found, and why there
    unfollowed: list[NotFollowed] | None = None  # kept as ``unseen`` is (``not_followed``)
    sourced: bool = False  # an underlay was sourced (AMENT_PREFIX_PATH was set)
    distro: str | None = None  # the distribution checked for (``--distro``), if one

    def display_path(self, path: Path) -> str:
        """Return a path as the user gave it, else relative to the working directory."""
        return self.display.get(path) or display_path(path)

    def loaded_files(self) -> set[Path]:
        """Return every launch file the check loaded (roots and what they include)."""
        if self.loaded is not None:
            return self.loaded
        return {path for graph in self.graphs for path in graph.files}

    def solver_queries(self) -> int:
        """Return how many times z3 was asked (``check --statistics``)."""
        if self.queries is not None:
            return self.queries
        from launchverify.smt import solver_queries

        return solver_queries(self.graphs)

    def detached(self) -> Report:
        """Return this report without its graphs, what reporters need kept (to store).

        Findings keep no path condition either: it only chose which findings to keep, and
        reading it back would import the evaluator's values for nothing.
        """
        findings = [dataclasses.replace(f, path=()) if f.path else f for f in self.findings]
        return dataclasses.replace(self, findings=findings, graphs=[],
                                   unseen=self.not_judged(), queries=self.solver_queries(),
                                   unfollowed=self.not_followed(),
                                   loaded=self.loaded_files(), kept=None, packages=None,
                                   readable=reading.confined_to())

    def not_judged(self) -> list[tuple[str, Span]]:
        """Return where evaluations were incomplete (reason, place), each once, as met.

        Claims that something is absent are not made on a launch that reaches these.
        """
        if self.unseen is not None:
            return self.unseen
        seen: set[tuple[str, Path, int]] = set()
        out = []
        for graph in self.graphs:
            for reason, span in graph.unseen():
                if (reason, span.file, span.line) not in seen:
                    seen.add((reason, span.file, span.line))
                    out.append((reason, span))
        return out

    def not_followed(self) -> list[NotFollowed]:
        """Return the includes and package references found in no workspace or underlay."""
        if self.unfollowed is not None:
            return self.unfollowed
        return list(dict.fromkeys(item for graph in self.graphs
                                  for item in graph.not_followed()))

    def coverage(self) -> Coverage:
        """Return how much of the launch was not followed, for the summary."""
        items = self.not_followed()
        uses = Counter(item.package for item in items if item.kind == "package")
        ranked = sorted(uses.items(), key=lambda pair: (-pair[1], pair[0]))
        return Coverage(sum(1 for item in items if item.kind == "include"), tuple(ranked))


@dataclass(frozen=True)
class Coverage:
    """What a check did not follow: not found in the workspace or any underlay."""

    includes: int  # includes whose package is found nowhere (each place once)
    packages: tuple[tuple[str, int], ...]  # packages found nowhere, how many places name
    # each, most named first

    def __bool__(self) -> bool:
        return bool(self.includes or self.packages)


END_OF_OPTIONS = "--"


def after_end_of_options(tokens: list[str]) -> tuple[list[str], list[str]]:
    """Return the tokens before the first ``--`` and those after it (paths, whatever they say).

    The command line keeps the ``--`` it was given among the paths (argparse drops it), so
    that a file named ``x:=1`` or ``--output=f`` after it stays a file: pre-commit appends
    the names of committed files, which a pull request chooses.
    """
    if END_OF_OPTIONS not in tokens:
        return list(tokens), []
    end = tokens.index(END_OF_OPTIONS)
    return list(tokens[:end]), list(tokens[end + 1:])


def parse_arguments(tokens: list[str]) -> tuple[list[str], dict[str, str]]:
    """Split command-line tokens into paths and ``name:=value`` launch arguments.

    Every token after ``--`` is a path.
    """
    given, literal = after_end_of_options(tokens)
    paths: list[str] = []
    arguments: dict[str, str] = {}
    for token in given:
        if ":=" not in token:
            paths.append(token)
            continue
        name, _, value = token.partition(":=")
        if not name or not value:
            raise UsageError(
                f"malformed launch argument {token!r}, expected format '<name>:=<value>'"
            )
        arguments[name] = value
    return [*paths, *literal], arguments


def parse_environment(pairs: list[str]) -> dict[str, str]:
    """Read ``--env NAME=VALUE`` options."""
    environment: dict[str, str] = {}
    for pair in pairs:
        name, equals, value = pair.partition("=")
        if not name or not equals:
            raise UsageError(f"malformed --env {pair!r}, expected NAME=VALUE")
        environment[name] = value
    return environment


def output_file(text: str) -> Path | None:
    """Read ``-o FILE``: ``-`` is standard output (``None``).

    As ``check -`` reads standard input; a file named ``-`` is written ``./-``.
    """
    return None if text == "-" else Path(text)


def canonical(path: Path) -> Path:
    """Return the identity used for a file: absolute, with symlinks resolved."""
    return Path(os.path.realpath(path))


def build_index(paths: list[Path], workspace: Path | None,
                extra: list[Path] | None = None) -> tuple[Path, PackageIndex]:
    """Return the workspace and the package index for a check.

    ``extra`` folders are searched for packages too: an install prefix (with
    ``share/ament_index``) as installed packages, any other folder as sources.
    """
    found, sources, prefixes = package_folders(paths, workspace, extra)
    return found.folder, PackageIndex.from_environment(sources, prefixes, near=paths)


def confine_reads(index: PackageIndex, workspace: Path, paths: Iterable[Path]
                  ) -> tuple[str, ...]:
    """Let launchverify read only what a Python launch file may (and the paths given).

    Held until the next check: the reporters read code frames after it. A launch file
    that includes ``/etc/passwd``, or a link out of the workspace, gets a finding on the
    include instead of the file's content in a code frame. Returns the folders workers
    may read.
    """
    from launchverify.isolation.confine import readable_folders

    readable = readable_folders(index, workspace)
    reading.confine([*readable, *(canonical(p) for p in paths)])
    return readable


def check_workspace(paths: list[Path], workspace: Path | None) -> Workspace:
    """Return the one workspace every path of a check shares (``workspace``: as given)."""
    if workspace is not None:
        if not workspace.is_dir():
            raise UsageError(f"workspace {str(workspace)!r} is not a folder")
        return Workspace(canonical(workspace), "as given")
    return discover_workspace(paths)


def package_folders(paths: list[Path], workspace: Path | None, extra: list[Path] | None = None
                    ) -> tuple[Workspace, list[Path], list[Path]]:
    """Return the workspace, the folders of package sources and the install prefixes."""
    found = check_workspace(paths, workspace)
    root = found.folder
    sources, prefixes = [root], []
    for folder in extra or ():
        if not folder.is_dir():
            raise UsageError(f"package path {str(folder)!r} is not a folder")
        if (folder / "share" / "ament_index").is_dir():
            prefixes.append(canonical(folder))
        else:
            sources.append(canonical(folder))
    return found, sources, prefixes


def _require_paths(options: CheckOptions) -> None:
    """Refuse a path that does not exist (a usage error, before any work)."""
    for path in options.paths:
        if not path.exists():
            raise UsageError(f"no such file or folder: {str(path)!r}")


def run_check(options: CheckOptions, stored: tuple[Entry, Kept] | None = None,
              *, keep: bool = False) -> Report:
    """Check launch files and return the findings, de-duplicated and sorted.

    ``stored``: the last check's result for the same options (its roots that read no
    edited file are not checked again); ``keep``: say in ``Report.kept`` what the next
    check may keep of this one.
    """
    from launchverify.findings.incremental import Incremental
    from launchverify.parallel.forked import Background
    from launchverify.workspace.affected import affected_launch_files
    from launchverify.workspace.discover import discover
    from launchverify.workspace.includers import Includers

    started = time.perf_counter()
    _require_paths(options)
    reading.confine(None)  # the last check's folders; this one's are set once indexed
    config = options.config
    other_reads: set[str] = set()  # what the check reads besides the roots' own files
    incremental = Incremental(stored, other_reads, keep=keep or stored is not None)
    # the workspace's includers are read again by every check: what they say is not kept
    includers_in = partial(_unrecorded, Includers.of_workspace)
    with collector_paused(), reading.recording(other_reads if incremental.on else None):
        tree = ConfigTree(config, nested=options.nested_configs)
        workspace, sources, prefixes = package_folders(options.paths, options.workspace,
                                                       config.package_paths)
        folders = (workspace, sources, prefixes)
        if options.affected:  # pre-commit: what the changed files may break, or nothing
            includers = includers_in(sources)
            found = _as_given(affected_launch_files(options.paths, includers), options.paths)
            return _check_files(options, tree, folders, lambda: includers, started, found,
                                incremental)
        # the scan starts before the index is built: small trees waited for it (it reads
        # every launch file of the workspace)
        parameters = set(options.parameter_files)
        with Background(partial(includers_in, sources)) as scan:
            found = _unrecorded(partial(discover, filter_files=options.launch_files_only),
                                [path for path in options.paths if path not in parameters])
            if parameters:  # the launch files that load them, as --affected finds them
                loading = affected_launch_files(options.parameter_files, scan.result())
                if not found and not loading:
                    raise NoLaunchFiles(_unloaded(options.parameter_files))
                found += _as_given(loading, options.paths)
            return _check_files(options, tree, folders, scan.result, started, found,
                                incremental)


def _unloaded(parameter_files: list[Path]) -> str:
    """Say that no launch file loads the parameter files given (nothing to check them in)."""
    named = ", ".join(repr(str(path)) for path in parameter_files)
    return (f"no launch file of the workspace loads {named}: a parameter file is checked "
            "through the launch files that load it (give the workspace with --workspace, "
            "or check the launch file)")


def _as_given(files: Iterable[Path], given: Iterable[Path]) -> list[Path]:
    """Return launch files found for the paths given (real paths) as the output shows them.

    A file given is named as it was given; another one relative to the working folder
    when it is below it (``display_path``), as a folder's walk names what it finds.
    """
    named = {canonical(path): path for path in given}
    return [named.get(file) or Path(display_path(file)) for file in files]


def _unrecorded(function: Callable[..., T], *args: object) -> T:
    """Call a function whose reads no result kept between checks rests on."""
    with reading.recording(None):
        return function(*args)


def _check_files(options: CheckOptions, tree: ConfigTree,
                 folders: tuple[Workspace, list[Path], list[Path]],
                 includers_of: Callable[[], Includers], started: float,
                 found: list[Path], incremental: Incremental) -> Report:
    """Check the launch files found (the workspace's includers may be read meanwhile).

    ``folders``: the workspace, package sources and install prefixes (``package_folders``).
    """
    from launchverify.evaluate.files import FileCache
    from launchverify.evaluate.runner import evaluate
    from launchverify.findings.baseline import apply_baseline
    from launchverify.findings.bounds import bounded
    from launchverify.findings.fixes import within
    from launchverify.findings.incremental import settled_places
    from launchverify.findings.scope import below
    from launchverify.findings.verdicts import merge
    from launchverify.frontends import launch_format
    from launchverify.isolation.confine import Limits
    from launchverify.isolation.lazy import LazyPython
    from launchverify.models import distros
    from launchverify.rule import Settled
    from launchverify.workspace.interfaces import Interfaces

    config = options.config
    found_workspace, sources, prefixes = folders
    workspace = found_workspace.folder
    ahead = any(launch_format(f) == "python" for f in found)
    if ahead:
        from launchverify.isolation.zygote import start_ahead

        start_ahead()  # its interpreter imports the models while the index is built
    index = PackageIndex.from_environment(sources, prefixes, near=options.paths)
    readable = confine_reads(index, workspace, options.paths)
    if not found and not (options.launch_files_only or options.affected):  # pre-commit: quiet
        given = ", ".join(str(p) for p in options.paths)
        raise NoLaunchFiles(f"no launch files found in {given}")
    files = [f for f in found
             if not tree.nearest(f).excludes(f) and not _excluded(f, options.exclude)]
    selection = Selection(options, tree)
    display: dict[Path, str] = {}
    for file in files:  # one root per real file, shown by its own path rather than a link's
        if canonical(file) == file.absolute() or canonical(file) not in display:
            display[canonical(file)] = str(file)
    files = [Path(shown) for shown in display.values()]
    if not files:
        selection.rules()  # a selection that names no rule is still an error
        return Report([], 0, time.perf_counter() - started, display,
                      workspace=found_workspace)
    limits = Limits(seconds=options.time_limit)
    roots = [canonical(f) for f in files]
    rules = selection.rules()
    kept = incremental.start(roots, rules)
    graphs: dict[Path, LaunchGraph] = {}
    included: dict[Path, bool] = {}
    evaluations = 0
    protections = None

    def evaluate_roots(targets: list[Path]) -> None:
        """Evaluate roots (Python files in workers), noting what each read."""
        nonlocal evaluations, protections
        with LazyPython(index=index, workspace=workspace, jobs=options.jobs or default_jobs(),
                        limits=limits, distro=options.distro, environment=options.environment,
                        arguments=options.arguments, readable=readable) as python:
            loader = FileCache(index, workspace, python)
            python.prefetch(root for root in targets if launch_format(root) == "python")
            loader.read_ahead(targets)
            for root in targets:
                loader.asked = set()
                graphs[root] = evaluate(root, index=index, workspace=workspace,
                                        pinned=options.arguments,
                                        environment=options.environment, loader=loader)
                incremental.evaluated(graphs[root], loader.asked, python.reads)
                if options.progress is not None:  # (kept roots count as done)
                    done = len(graphs) + len(kept)  # (contexts are counted as they come)
                    options.progress(done, max(done, len(roots)))
            evaluations += python.evaluated
            protections = protections or python.protections

    with distros.checking(options.distro), reading.size_limit(options.max_file_size):
        evaluate_roots([root for root in roots if root not in kept])
        includers = includers_of()
        scope_roots = roots
        contexts = [] if options.affected else _contexts(  # (affected: they are checked)
            roots, includers, lambda f: tree.nearest(f).excludes(f)
            or _excluded(f, options.exclude), graphs, kept, incremental, evaluate_roots)
        roots = [*roots, *contexts]
        while True:  # roots another root's edit concerns: who includes them, their family
            targets = {target for g in graphs.values() for inc in g.includes
                       if (target := inc.target) is not None}
            targets.update(target for result in kept.values() for target in result.includes)
            included = {root: root in targets or includers.included(root) for root in roots}
            again = incremental.concerned(graphs, kept, included)
            if not again:
                break
            evaluate_roots([root for root in roots if root in again])
        for root, graph in graphs.items():
            graph.included_elsewhere = included[root]
        if ahead:  # started for files that were all excluded, say
            from launchverify.isolation.zygote import discard_ahead

            discard_ahead()
        # rules judge for the distro too (lifecycle labels)
        interfaces = Interfaces([graphs[r] for r in roots if r in graphs],
                                kept={r: (k.interface, k.picked) for r, k in kept.items()},
                                order=roots)
        ctx = RuleContext(packages=index, interfaces=interfaces,
                          options=rule_options(config, options.arguments))
        verdicts, instance = judge([graphs[r] for r in roots if r in graphs], rules, ctx,
                                   jobs=options.jobs or default_jobs())
        judged = {verdict.root: verdict for verdict in verdicts}
        while again := incremental.unsettled(kept, judged):  # kept roots that skipped a place
            evaluate_roots([root for root in roots if root in again])
            for root in again:
                graphs[root].included_elsewhere = included[root]
            ctx.settled = {code: Settled(places) for code, places
                           in settled_places(judged.values()).items()}
            more, _ = judge([graphs[r] for r in roots if r in again], rules, ctx,
                            jobs=options.jobs or default_jobs())
            judged.update((verdict.root, verdict) for verdict in more)
        everyone = [judged[r] if r in judged else kept[r].verdicts for r in roots]
        if incremental.plan is not None:  # every rule concludes from the verdicts alone
            instance = lambda r: rules[r]()  # noqa: E731
        inside = below(options.paths)
        findings = merge(everyone, rules, ctx, instance, _isolated, frozenset(contexts),
                         lambda finding: inside(finding.span.file))
        if not options.affected:
            findings = _in_scope(findings, inside, scope_roots, contexts, graphs, kept,
                                 rules, includers)
    for context in contexts:  # what the next check keeps is its paths' own
        graphs.pop(context, None)
        judged.pop(context, None)
        kept.pop(context, None)
    report = incremental.report(scope_roots, graphs, judged, kept, rules)
    loaded = report.loaded_files()
    findings, suppressed = _unrecorded(_suppress, [bounded(f) for f in findings], loaded, rules)
    findings = within(_configured(findings, tree, selection), workspace)  # fixes: ours only
    baselined = 0
    if options.baseline is not None:
        findings, baselined = apply_baseline(options.baseline, findings)
    return dataclasses.replace(
        report, findings=sorted(findings, key=Finding.sort_key), files=len(loaded),
        seconds=time.perf_counter() - started, display=display, checked=scope_roots,
        suppressed=suppressed, baselined=baselined, python_files=evaluations,
        protections=protections, packages=index, workspace=found_workspace,
        sourced=bool(os.environ.get("AMENT_PREFIX_PATH")), distro=options.distro)


def _contexts(roots: list[Path], includers: Includers, excluded: Callable[[Path], bool],
            graphs: dict[Path, LaunchGraph], kept: dict[Path, RootResult],
            incremental: Incremental, evaluate_roots: Callable[[list[Path]], None]
            ) -> list[Path]:
    """Evaluate the launch files that include the roots; return those that do.

    They are the roots' contexts (``findings/scope.py``). One whose evaluation did not
    load a root (an includer of another file of that name) is dropped.
    """
    from launchverify.findings.scope import confirmed, context_roots, files_of

    context = context_roots(roots, includers, excluded)
    if not context:
        return []
    if incremental.plan is not None:
        kept.update(incremental.plan.kept(context))
    evaluate_roots([root for root in context if root not in kept])
    contexts = confirmed(context, roots, lambda root: files_of(root, graphs, kept))
    for root in set(context) - set(contexts):
        graphs.pop(root, None)
        kept.pop(root, None)
    return contexts


def _in_scope(findings: list[Finding], inside: Callable[[Path], bool],
              scope_roots: list[Path], contexts: list[Path],
              graphs: dict[Path, LaunchGraph], kept: dict[Path, RootResult],
              rules: list[type[Rule]], includers: Includers) -> list[Finding]:
    """Keep the findings of the paths' launches (``findings/scope.py``)."""
    from launchverify.findings.scope import consensus, files_of, in_scope

    reached = {f for root in scope_roots for f in files_of(root, graphs, kept)}
    context_only = {f for root in contexts for f in files_of(root, graphs, kept)} - reached
    evaluated = {*scope_roots, *contexts}
    return in_scope(findings, inside, context_only,
                    {rule.code for rule in rules if consensus(rule)},
                    lambda file: bool(includers.naming(file) - evaluated))


def rule_options(config: Config, arguments: dict[str, str] | None = None
                 ) -> dict[str, object]:
    """Return what rules read from the configuration of the check (``RuleContext.options``).

    ``single-writer-topics`` is absent when the configuration does not set it: the rule
    then uses its own default. ``argument-sources`` says where each pinned launch argument
    was given (the configuration file's name, else the command line), for messages.
    """
    options: dict[str, object] = {"external-names": tuple(config.external_names)}
    if config.single_writer_topics is not None:
        options["single-writer-topics"] = tuple(config.single_writer_topics)
    configured = f"in {config.path.name if config.path is not None else 'the configuration'}"
    options["argument-sources"] = {
        name: configured if config.arguments.get(name) == value else "on the command line"
        for name, value in (arguments or {}).items()}
    return options


def run_check_cached(options: CheckOptions, cache: ResultCache | None) -> Report:
    """Check, or return the stored report when nothing it rests on has changed.

    A report from the cache is read under the confinement its check had: the reporters
    read code frames after it, and a link out of the workspace must stay unread.
    """
    if cache is None:
        return run_check(options)
    started = time.perf_counter()
    _require_paths(options)
    folders, files = _inputs(options)
    key = cache.key([options_text(options, skip=("progress", "jobs")), folders, files]) \
        if cache.usable(folders) else None
    if key is None:
        return run_check(options)
    entry = cache.stored(key)
    if entry is not None and cache.valid(key, entry):
        report = entry.report
        assert isinstance(report, Report)  # (``stored`` returns no other)
        reading.confine(report.readable if report.readable is not None else folders)
        return dataclasses.replace(report, seconds=time.perf_counter() - started,
                                   cached=True)
    kept = None if entry is None else cache.kept(key, entry)  # what an edit may leave
    stored = None if entry is None or kept is None else (entry, kept)
    cache.prepare()
    now = time.time()
    with in_use(cache):
        report = run_check(options, stored, keep=True)
    read = {str(path) for path in report.loaded_files()}
    if report.kept is not None:
        read.update(path for result in report.kept.roots.values()
                    if (reads := getattr(result, "reads", None)) is not None for path in reads)
    folder_stamps: dict[str, FolderStamp] = {}
    listings: dict[str, str] = {}
    stamps = stamps_of(folders, [*files, *read], now, skip=str(cache.folder),
                       folder_stamps=folder_stamps, listings=listings)
    if settled(stamps, now, folder_stamps):  # else what was read may not be what is there
        entry = Entry(report.detached(), stamps, folder_stamps, listings=listings)
        if report.kept is not None:
            report.kept.started = now
            cache.store_kept(key, report.kept)
            entry.kept = report.kept.token
        cache.store(key, entry)
    return dataclasses.replace(report, kept=None)


def _inputs(options: CheckOptions) -> tuple[list[str], list[str]]:
    """Return the folders a check may read anything below, and single files it reads.

    The workspace and the package paths are walked whole; of install prefixes (the
    workspace's and ``AMENT_PREFIX_PATH``'s) only the ament index, whose folder changes
    when a package is installed or removed; the baseline and configuration files.
    """
    workspace = check_workspace(options.paths, options.workspace).folder  # as the check
    folders = [workspace, *(canonical(p) for p in options.config.package_paths)]
    files: list[Path] = []
    for path in options.paths:
        target = canonical(path)
        if not any(target.is_relative_to(folder) for folder in folders):
            (folders if target.is_dir() else files).append(target)
    raw = os.environ.get("AMENT_PREFIX_PATH", "")
    prefixes = [*workspace_prefixes(workspace), *(Path(p) for p in raw.split(os.pathsep) if p)]
    files += [prefix / "share" / "ament_index" / "resource_index" / "packages"
              for prefix in prefixes]
    files += [p for p in (options.baseline, options.config.path) if p is not None]
    return [str(f) for f in folders], [str(canonical(f)) for f in files]


def default_jobs() -> int:
    """Return how many Python files to evaluate ahead at once: one per CPU.

    (Measured on 2 CPUs: 2 ahead beats 1, the walk waiting less, though it shares a CPU.)
    """
    return os.cpu_count() or 1


def _excluded(file: Path, patterns: list[str]) -> bool:
    """Return whether a command-line (or ament) exclude pattern names a file."""
    if not patterns:
        return False
    relative = relative_file(file, Path.cwd())
    absolute = file.absolute().as_posix()
    return any(matches(absolute if pattern.startswith("/") else relative, pattern)
               for pattern in patterns)


def _suppress(findings: list[Finding], files: set[Path],
              rules: list[type[Rule]]) -> tuple[list[Finding], int]:
    """Apply inline suppressions; judge the comments that silenced nothing (LV004)."""
    from launchverify.findings.suppressions import apply_suppressions
    from launchverify.registry import all_rules
    from launchverify.rules.health.unused_suppression import UnusedSuppression

    kept, comments = apply_suppressions(findings, files)
    suppressed = len(findings) - len(kept)
    if UnusedSuppression in rules:
        ran = frozenset(rule.code for rule in rules)
        every_rule_ran = ran == frozenset(rule.code for rule in all_rules())
        judge = UnusedSuppression()
        for comment in comments:
            finding = judge.judge(comment, ran, every_rule_ran)
            if finding is not None:
                kept.append(finding)
    return kept, suppressed


class Selection:
    """The rules each configuration selects, the command line's choice applied on top."""

    def __init__(self, options: CheckOptions, tree: ConfigTree) -> None:
        self.options = options
        self.tree = tree
        self._codes: dict[int, frozenset[str]] = {}

    def of(self, config: Config) -> list[type[Rule]]:
        """Return the rules a configuration selects (the check's own: ``options``)."""
        from launchverify.registry import select as select_rules

        if config is self.tree.root:
            return select_rules(self.options.select, self.options.ignore)
        chosen = (self.options.command_select if self.options.command_select is not None
                  else config.select)
        return select_rules(chosen, [*config.ignore, *self.options.command_ignore])

    def rules(self) -> list[type[Rule]]:
        """Return the rules to run: those any configuration in play selects."""
        chosen = {rule: None for rule in self.of(self.tree.root)}
        for config in self.tree.others():
            chosen.update({rule: None for rule in self.of(config)})
        return list(chosen)

    def codes(self, config: Config) -> frozenset[str]:
        """Return the codes a configuration selects (cached)."""
        if id(config) not in self._codes:
            self._codes[id(config)] = frozenset(rule.code for rule in self.of(config))
        return self._codes[id(config)]


def _configured(findings: list[Finding], tree: ConfigTree,
                selection: Selection) -> list[Finding]:
    """Apply each file's configuration: its selection, severities and per-file ignores."""
    levels: dict[int, dict[str, Severity]] = {}
    ignored: dict[Path, set[str]] = {}  # per file: many findings share one
    out = []
    for finding in findings:
        file = finding.span.file
        config = tree.nearest(file)
        if finding.code not in selection.codes(config):
            continue
        if file not in ignored:
            ignored[file] = {code for selector in config.ignored_in(file)
                             for code in _codes_of(selector)}
        if finding.code in ignored[file]:
            continue
        if id(config) not in levels:
            levels[id(config)] = {code: Severity(level)
                                  for selector, level in config.severity.items()
                                  for code in _codes_of(selector)}
        level = levels[id(config)].get(finding.code)
        out.append(finding if level is None else dataclasses.replace(finding, severity=level))
    return out


def _codes_of(selector: str) -> list[str]:
    from launchverify.registry import resolve

    return [rule.code for rule in resolve(selector)]


def dead(graph: LaunchGraph, path: PathCondition) -> bool:
    """Return whether a path condition holds under no value the user can give.

    (A finding there is about code this root never runs: an include another argument of
    the includer switched off.)
    """
    from launchverify.smt import reasoner_for

    cache = graph.derived.setdefault("dead paths", {})
    known = cache.get(path)
    if known is None:
        known = reasoner_for(graph).unreachable(path)
        cache[path] = known
    return bool(known)


def _isolated(rule: Rule, findings: Callable[[], Iterable[Finding]], file: Path | None
              ) -> Iterator[Finding]:
    """Yield a rule's findings; if the rule fails, LV005 on the file instead of a crash."""
    try:
        yield from findings()
    except Exception as error:  # a bug of ours must not end the check
        from launchverify.rules.health.internal_error import InternalError

        yield InternalError().rule_failed(rule.code, file or Path.cwd(), error)


def judge(graphs: list[LaunchGraph], rules: list[type[Rule]], ctx: RuleContext,
          jobs: int = 1) -> tuple[list[Verdicts], Callable[[int], Rule]]:
    """Run every rule on every graph (in up to ``jobs`` processes): each graph's verdicts.

    Also returns each rule's object in this process (the one whose ``finish`` concludes).
    """
    from launchverify.findings.verdicts import verdicts_of
    from launchverify.parallel.fanout import RuleRun, rule_findings

    run = RuleRun(graphs, rules, ctx, _isolated, dead)
    found = rule_findings(run, jobs)
    return verdicts_of(run, found), run.instance


def run_rules(graphs: list[LaunchGraph], rules: list[type[Rule]],
              ctx: RuleContext, jobs: int = 1) -> list[Finding]:
    """Run every rule on every graph (in up to ``jobs`` processes) and merge the findings."""
    from launchverify.findings.verdicts import merge

    verdicts, instance = judge(graphs, rules, ctx, jobs)
    return merge(verdicts, rules, ctx, instance, _isolated)
