"""The ``launchverify`` command line.

Exit status: 0 when no error-level finding, 1 when there is one, 2 for a usage error or an
internal failure (never a traceback on the user's screen).
"""

from __future__ import annotations

import argparse
import os
import sys
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from pathlib import Path

from launchverify import __version__
from launchverify.engine import (
    CheckOptions,
    UsageError,
    build_index,
    canonical,
    parse_arguments,
    parse_environment,
    run_check,
)
from launchverify.registry import RegistryError
from launchverify.rule import Severity

EXIT_OK, EXIT_FINDINGS, EXIT_ERROR = 0, 1, 2


def _codes(text: str | None) -> list[str] | None:
    if text is None:
        return None
    return [part.strip() for part in text.split(",") if part.strip()]


def build_parser() -> argparse.ArgumentParser:
    """Return the argument parser of the whole command line."""
    parser = argparse.ArgumentParser(
        prog="launchverify",
        description="Formal verifier and static analyser for ROS 2 launch files.",
    )
    parser.add_argument("--version", action="version", version=f"launchverify {__version__}")
    commands = parser.add_subparsers(dest="command", metavar="COMMAND")

    check = commands.add_parser(
        "check", help="check launch files and report findings",
        description="Check launch files (files, or folders searched for launch files). "
        "Arguments written name:=value are passed to the launch as on ros2 launch.",
    )
    check.add_argument("targets", nargs="+", metavar="PATH|name:=value")
    check.add_argument("--workspace", type=Path, help="folder to search for packages "
                       "(default: the nearest colcon workspace or git root)")
    check.add_argument("--format", choices=("text", "json"), default="text")
    check.add_argument("--select", help="comma-separated codes, slugs or prefixes to run")
    check.add_argument("--ignore", help="comma-separated codes, slugs or prefixes to skip")
    check.add_argument("--color", choices=("auto", "always", "never"), default="auto")
    check.add_argument("--explain", action="store_true",
                       help="under each finding, the steps that lead to it (lifecycle "
                       "traces)")
    check.add_argument("--env", action="append", default=[], metavar="NAME=VALUE",
                       help="an environment variable of the machine that will run the "
                       "launch (repeatable); unset ones are free values")

    graph = commands.add_parser(
        "graph", help="print what a launch file would start",
        description="Evaluate one launch file and print its nodes, processes, includes and "
        "arguments under the given arguments.",
    )
    graph.add_argument("targets", nargs="+", metavar="FILE|name:=value")
    graph.add_argument("--workspace", type=Path)
    graph.add_argument("--format", choices=("json", "text"), default="json")
    graph.add_argument("--symbolic", action="store_true",
                       help="every action with its path condition, values as expressions")
    graph.add_argument("--env", action="append", default=[], metavar="NAME=VALUE")
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; return the exit status."""
    parser = build_parser()
    args, extra = parser.parse_known_args(argv)
    # name:=value may follow options (`check f.xml --format json x:=1`); argparse leaves
    # those as unknown tokens.
    unknown = [token for token in extra if ":=" not in token or token.startswith("-")]
    if unknown:
        parser.error(f"unrecognized arguments: {' '.join(unknown)}")
    if extra:
        args.targets = [*args.targets, *extra]
    if args.command is None:
        parser.print_help()
        return EXIT_ERROR
    try:
        if args.command == "check":
            return _check(args)
        return _graph(args)
    except (UsageError, RegistryError) as error:
        print(f"launchverify: error: {error}", file=sys.stderr)
        return EXIT_ERROR
    except KeyboardInterrupt:
        return EXIT_ERROR
    except Exception as error:  # a bug of ours: say so plainly, never a traceback
        print(f"launchverify: internal error: {type(error).__name__}: {error}\n"
              "Please report this with the launch file that caused it.", file=sys.stderr)
        return EXIT_ERROR


def _check(args: argparse.Namespace) -> int:
    from launchverify.render.json_out import render_json
    from launchverify.render.text import render_text

    paths, arguments = parse_arguments(args.targets)
    if not paths:
        raise UsageError("no PATH given")
    report = run_check(CheckOptions(
        paths=[Path(p) for p in paths], arguments=arguments, workspace=args.workspace,
        select=_codes(args.select), ignore=_codes(args.ignore),
        environment=parse_environment(args.env),
    ))
    failed = any(f.severity is Severity.ERROR for f in report.findings)
    with _output_may_close():
        if args.format == "json":
            render_json(report, sys.stdout)
        else:
            color = {"auto": None, "always": True, "never": False}[args.color]
            render_text(report, sys.stdout, color=color, explain=args.explain)
    return EXIT_FINDINGS if failed else EXIT_OK


def _graph(args: argparse.Namespace) -> int:
    from launchverify.evaluate.runner import evaluate
    from launchverify.render.graph_out import render_graph_json, render_graph_text

    paths, arguments = parse_arguments(args.targets)
    if len(paths) != 1:
        raise UsageError("graph takes exactly one launch file")
    path = Path(paths[0])
    if not path.is_file():
        raise UsageError(f"no such file: {paths[0]!r}")
    workspace, index = build_index([path], args.workspace)
    graph = evaluate(canonical(path), index=index, workspace=workspace, pinned=arguments,
                     environment=parse_environment(args.env))
    with _output_may_close():
        if args.format == "json":
            render_graph_json(graph, sys.stdout, symbolic=args.symbolic)
        else:
            render_graph_text(graph, sys.stdout, symbolic=args.symbolic)
    return EXIT_OK


@contextmanager
def _output_may_close() -> Iterator[None]:
    """Stop writing quietly when the reader goes away (``launchverify check | head``)."""
    try:
        yield
        sys.stdout.flush()
    except BrokenPipeError:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
