"""``launchverify diff``: the command line of a diff between two trees.

``launchverify diff [BASE [HEAD]] [PATH...] [name:=value ...]``: BASE defaults to the
merge base of HEAD with the default branch, HEAD to the working tree. ``--against
OTHER`` compares a folder (or file) with another instead. Exit status 1 when the head
side brings new error-level findings (with ``--fail-on-change``, any change in what the
launch files start), 0 otherwise, 2 for a usage error.
"""

from __future__ import annotations

import argparse
import dataclasses
import io
import sys
import time
from collections.abc import Iterator
from contextlib import ExitStack, contextmanager
from pathlib import Path
from typing import Any, TextIO

from launchverify.engine import (
    UsageError,
    after_end_of_options,
    output_file,
    parse_arguments,
    parse_environment,
)
from launchverify.models.distros import DISTROS

EXIT_OK, EXIT_CHANGED = 0, 1


def add_parser(commands: Any) -> None:
    """Register ``diff`` on the command line's subparsers."""
    command = commands.add_parser(
        "diff", help="show what a change does to the launched system",
        description="Evaluate the launch files of two revisions (or two folders) and "
        "show what differs in what they start: nodes added, removed or renamed, "
        "parameter values (wherever they are set), remappings, arguments, lifecycle "
        "bring-ups, and the findings introduced, fixed or changed. BASE defaults to the "
        "merge base with the default branch, HEAD to the working tree; revisions are read "
        "from git without checking anything out.")
    command.add_argument("targets", nargs="*", metavar="BASE|HEAD|PATH|name:=value",
                         help="up to two revisions first, then launch files or folders "
                         "(default: the whole repository), then launch arguments")
    command.add_argument("--against", type=Path, metavar="FILE_OR_FOLDER",
                         help="compare PATH (default: .) with this file or folder instead "
                         "of git revisions")
    command.add_argument("--format", choices=("text", "json", "markdown", "github"),
                         default="text", help="text for people (default), json for "
                         "programs, markdown for a pull-request comment, github for "
                         "annotations on changed lines")
    command.add_argument("-o", "--output", type=output_file, metavar="FILE",
                         help="write to FILE instead of standard output ('-': standard "
                         "output)")
    command.add_argument("--json", type=Path, metavar="FILE", dest="json_file",
                         help="also write the diff as JSON to FILE (one run for a comment "
                         "and a program)")
    command.add_argument("--color", choices=("auto", "always", "never"), default="auto",
                         help="colour the text format (default: when writing to a terminal)")
    command.add_argument("--fail-on-change", action="store_true",
                         help="exit 1 on any change in what the launch files start, not "
                         "only on new errors")
    command.add_argument("--max-items", type=int, default=50, metavar="N",
                         help="markdown: show at most N launch files and N changes of each "
                         "(default: 50), then say how many more")
    command.add_argument("--witnesses", type=int, default=0, metavar="N",
                         help="also compare both sides under up to N argument assignments "
                         "that start nodes on one side only (two checks each)")
    command.add_argument("--select", action="append", metavar="CODES",
                         help="comma-separated codes, slugs or prefixes to run")
    command.add_argument("--ignore", action="append", metavar="CODES",
                         help="comma-separated codes, slugs or prefixes to skip")
    command.add_argument("--env", action="append", default=[], metavar="NAME=VALUE",
                         help="an environment variable of the machine that will run the "
                         "launch (repeatable)")
    command.add_argument("--isolated", action="store_true", help="ignore configuration files")
    command.add_argument("--distro", choices=DISTROS,
                         help="the ROS 2 distribution to check for")
    command.add_argument("-j", "--jobs", type=int, metavar="N",
                         help="processes for each side's check (default: the number of CPUs)")
    command.add_argument("--time-limit", type=float, default=10.0, metavar="SECONDS",
                         help="per Python launch file (default: 10)")


def run(args: argparse.Namespace) -> int:
    """Run a diff; return the exit status."""
    from launchverify.cli import option_codes, refuse_unknown_selectors
    from launchverify.diff.compare import compare
    from launchverify.diff.snapshot import Request, take

    started = time.perf_counter()
    refuse_unknown_selectors(args)  # (both before any work, as for check)
    inside = _writable_outputs(args)
    tokens, arguments = parse_arguments(args.targets)
    literal = len(after_end_of_options(args.targets)[1])  # after --: paths, not revisions
    request = Request(paths=("",), arguments=arguments,
                      environment=parse_environment(args.env),
                      select=option_codes(args.select),
                      ignore=tuple(option_codes(args.ignore) or ()),
                      isolated=args.isolated, distro=args.distro, jobs=args.jobs,
                      time_limit=args.time_limit)
    with ExitStack() as stack:
        if args.against is not None:
            pairs, renamed = _folders(args.against, tokens)
        else:
            pairs, renamed = stack.enter_context(_revisions(tokens, literal))
        (base, base_paths), (head, head_paths) = pairs
        before = take(base.root, dataclasses.replace(request, paths=base_paths))
        after = take(head.root, dataclasses.replace(request, paths=head_paths))
        diff = compare(before, after, renamed)
        assignments = []
        for witness in _witnesses(diff, arguments)[:max(0, args.witnesses)]:
            given = dataclasses.replace(request, arguments={**arguments, **witness})
            under = compare(take(base.root, dataclasses.replace(given, paths=base_paths)),
                            take(head.root, dataclasses.replace(given, paths=head_paths)),
                            renamed)
            assignments.append({"arguments": witness,
                                "launches": _new_changes(under["launches"],
                                                         diff["launches"])})
    diff = {"base": {"label": base.label, "commit": base.commit},
            "head": {"label": head.label, "commit": head.commit},
            "arguments": arguments, **diff, "assignments": assignments,
            "seconds": {"base": round(before.seconds, 3), "head": round(after.seconds, 3),
                        "total": round(time.perf_counter() - started, 3)}}
    _write(diff, args, inside)
    summary = diff["summary"]
    changed = summary["launches_changed"] or summary["findings_introduced"] \
        or summary["findings_fixed"] or summary["findings_changed"]
    if summary["errors_introduced"] or (args.fail_on_change and changed):
        return EXIT_CHANGED
    return EXIT_OK


def _witnesses(diff: dict[str, Any], given: dict[str, str]) -> list[dict[str, str]]:
    """Return the distinct argument values under which some node starts on one side only."""
    found: list[dict[str, str]] = []
    for launch in diff["launches"]:
        for change in launch["conditional"]:
            values = {k: v for k, v in (change.get("witness") or {}).items()
                      if given.get(k) != v}
            if values and values not in found:
                found.append(values)
    return found


def _new_changes(under: list[dict[str, Any]], default: list[dict[str, Any]]
                 ) -> list[dict[str, Any]]:
    """Return the launches' changes under other arguments that the defaults' do not show."""
    from launchverify.diff.render import changes

    shown = {(launch["file"], sentence) for launch in default
             for _, sentence, _, _ in changes(launch)}
    out = []
    for launch in under:
        new = [{"mark": mark, "change": sentence, "file": file, "line": line}
               for mark, sentence, file, line in changes(launch)
               if (launch["file"], sentence) not in shown]
        if new:
            out.append({"file": launch["file"], "changes": new})
    return out


def _writable_outputs(args: argparse.Namespace) -> tuple[Path, ...]:
    """Refuse, before any work, an output that would go through a link; return its anchors.

    Below the working folder and the trees compared (the repository, or the two folders
    of ``--against``) no link is followed (see ``process.outputs``).
    """
    if args.output is None and args.json_file is None:
        return ()
    from launchverify.process.outputs import check_outputs

    return check_outputs((args.output, args.json_file), lambda: _compared_trees(args))


def _compared_trees(args: argparse.Namespace) -> tuple[Path, ...]:
    """Return the folders a diff reads: ``--against``'s two, else the repository's top."""
    if args.against is not None:
        here = next(map(Path, parse_arguments(args.targets)[0]), Path())
        return tuple(path if path.is_dir() else path.parent for path in (args.against, here))
    from launchverify.diff.sides import repository_of

    try:
        return (repository_of(Path.cwd()),)
    except UsageError:  # not in a repository: said as the diff starts
        return ()


def _write(diff: dict[str, Any], args: argparse.Namespace, inside: tuple[Path, ...]) -> None:
    from launchverify.diff import render

    if args.json_file is not None:
        with _output(args.json_file, inside) as out:
            render.render_json(diff, out)
    with _output(args.output, inside) as out:
        if args.format == "json":
            render.render_json(diff, out)
        elif args.format == "markdown":
            render.render_markdown(diff, out, max_items=max(1, args.max_items))
        elif args.format == "github":
            render.render_github(diff, out)
        else:
            colour = args.color == "always" or (args.color == "auto" and args.output is None
                                                and sys.stdout.isatty())
            render.render_text(diff, out, colour=colour)


@contextmanager
def _output(path: Path | None, inside: tuple[Path, ...]) -> Iterator[TextIO]:
    """Yield where to render: standard output, or a buffer then written to ``path``."""
    if path is None:
        yield sys.stdout
        return
    from launchverify.process.outputs import write_file

    out = io.StringIO()
    yield out
    write_file(path, out.getvalue(), inside=inside)


Pairs = tuple[tuple[Any, tuple[str, ...]], tuple[Any, tuple[str, ...]]]


def _folders(other: Path, tokens: list[str]) -> tuple[Pairs, dict[str, str]]:
    """Return the two sides of ``--against``: two folders, or two files."""
    from launchverify.diff.sides import Side

    if len(tokens) > 1:
        raise UsageError("--against compares one file or folder with one other")
    here = Path(tokens[0] if tokens else ".")
    for path in (other, here):
        if not path.exists():
            raise UsageError(f"no such file or folder: {str(path)!r}")
    if other.is_dir() != here.is_dir():
        raise UsageError("--against compares two folders or two files")
    if other.is_dir():
        return ((Side(str(other), other.resolve()), ("",)),
                (Side(str(here), here.resolve()), ("",))), {}
    base = Side(str(other), other.resolve().parent)
    head = Side(str(here), here.resolve().parent)
    return ((base, (other.name,)), (head, (here.name,))), {other.name: here.name}


@contextmanager
def _revisions(tokens: list[str], literal: int = 0
               ) -> Iterator[tuple[Pairs, dict[str, str]]]:
    """Yield the two sides of a diff between revisions (the working tree by default).

    The last ``literal`` tokens came after ``--``: paths, whatever revision they may name.
    """
    from launchverify.diff.sides import (
        Side,
        checked_out,
        commit_of,
        default_base,
        exported,
        renamed,
        repository_of,
    )
    from launchverify.workspace import reading

    repository = repository_of(Path.cwd())
    revisions: list[str] = []
    while len(tokens) > literal and len(revisions) < 2 and not Path(tokens[0]).exists() \
            and _is_revision(repository, tokens[0]):
        revisions.append(tokens.pop(0))
    paths = tuple(_inside(repository, Path(token)) for token in tokens) or ("",)
    base_label = revisions[0] if revisions else "merge base"
    base_commit = commit_of(repository, revisions[0] if revisions else
                            default_base(repository))
    limit = reading.DEFAULT_LIMIT
    with ExitStack() as stack:
        base = stack.enter_context(exported(repository, base_commit, base_label, limit))
        if len(revisions) == 2:
            head_commit: str | None = commit_of(repository, revisions[1])
            assert head_commit is not None
            if checked_out(repository, head_commit):  # the working tree is that commit
                head = Side(revisions[1], repository, head_commit)
            else:
                head = stack.enter_context(exported(repository, head_commit, revisions[1],
                                                    limit))
        else:
            head_commit = None
            head = Side("working tree", repository)
        yield ((base, paths), (head, paths)), renamed(repository, base_commit, head_commit)


def _is_revision(repository: Path, token: str) -> bool:
    from launchverify.diff.sides import commit_of

    try:
        return bool(commit_of(repository, token))
    except UsageError:
        return False


def _inside(repository: Path, path: Path) -> str:
    """Return a path given on the command line relative to the repository's top."""
    try:
        return path.resolve().relative_to(repository.resolve()).as_posix()
    except ValueError:
        raise UsageError(f"{str(path)!r} is not inside the repository "
                         f"{str(repository)!r}") from None
