"""The ``launchverify`` command line.

Exit status: 0 when no finding at or above ``--fail-on`` (default: error), 1 when there is
one, 2 for a usage error or an internal failure (never a traceback on the user's screen),
141 when the reader of the output went away before the end (``launchverify check | head``:
the command stops quietly, as other tools do; 141 is what a shell shows for a tool that
SIGPIPE stopped, so ``set -o pipefail`` scripts see the same as with ``cat``), 130 on
Ctrl-C (as for a tool SIGINT stopped; every output is written whole or not at all). A launch
started by ``run`` is the exception: it goes on as ros2 launch's would, its output kept in
the run folder's logs, and its own status is the exit status.
"""

from __future__ import annotations

import argparse
import dataclasses
import gc
import io
import json
import os
import select
import shlex
import sys
from collections.abc import Callable, Sequence
from contextlib import nullcontext
from pathlib import Path
from typing import TYPE_CHECKING, Any, NoReturn, TextIO, cast

from launchverify import __version__
from launchverify.ament import excluded_by_ament
from launchverify.config import (
    Config,
    ConfigError,
    confined,
    confirmed_package_paths,
    find_config,
    load_config,
    unknown_selector,
)
from launchverify.diff import command as diff_command
from launchverify.engine import (
    DEFAULT_TIME_LIMIT,
    END_OF_OPTIONS,
    CheckOptions,
    Report,
    UsageError,
    after_end_of_options,
    build_index,
    canonical,
    check_workspace,
    confine_reads,
    output_file,
    parse_arguments,
    parse_environment,
    run_check,
    run_check_cached,
)
from launchverify.findings.baseline import BaselineError, write_baseline
from launchverify.findings.cache import ResultCache, default_cache_dir, disabled_by_environment
from launchverify.findings.fixes import Outcome, fix_all, hidden, unified_diff
from launchverify.models.distros import DISTROS
from launchverify.process.collector import collector_paused
from launchverify.process.command import LONG_RUNNING
from launchverify.registry import RegistryError
from launchverify.render.inert import InertWriter, inert, inert_block
from launchverify.rule import Rule, Severity
from launchverify.suggest import did_you_mean_any
from launchverify.topology import command as topology_command
from launchverify.workspace import reading
from launchverify.workspace.includers import Includers
from launchverify.workspace.packages import discover_workspace, find_workspace
from launchverify.workspace.paths import display_path

if TYPE_CHECKING:
    from launchverify.graph import LaunchGraph

EXIT_OK, EXIT_FINDINGS, EXIT_ERROR = 0, 1, 2
EXIT_READER_GONE = 128 + 13  # as a shell shows a tool stopped by SIGPIPE (`cmd | head`)
EXIT_INTERRUPTED = 128 + 2  # as a shell shows a tool stopped by SIGINT (Ctrl-C)


FORMATS = ("text", "concise", "json", "sarif", "junit", "github")


def option_codes(given: list[str] | None) -> list[str] | None:
    """Return the selectors of a repeatable comma-separated option (all of them)."""
    if given is None:
        return None
    return [part.strip() for text in given for part in text.split(",") if part.strip()]


WORKSPACE_HELP = ("folder to search for packages (default: the nearest colcon workspace or git "
                  "root)")
ENV_HELP = ("an environment variable of the machine that will run the launch (repeatable); "
            "unset ones are free values")
ONE_FILE_HELP = "the launch file, then launch arguments written name:=value (as on ros2 launch)"


def _add_check_options(command: argparse.ArgumentParser) -> None:
    """Options shared by ``check`` and ``report``: what to check and how."""
    command.add_argument("targets", nargs="*", metavar="PATH|name:=value",
                         help="launch files, or folders searched for them (default: .); "
                         "launch arguments written name:=value, as on ros2 launch")
    command.add_argument("--workspace", type=Path, metavar="FOLDER", help=WORKSPACE_HELP)
    command.add_argument("--select", action="append", metavar="CODES",
                         help="comma-separated codes, slugs or prefixes to run (repeatable)")
    command.add_argument("--ignore", action="append", metavar="CODES",
                         help="comma-separated codes, slugs or prefixes to skip (repeatable)")
    command.add_argument("--exclude", action="append", default=[], metavar="GLOB",
                         help="leave out discovered files matching GLOB (repeatable)")
    command.add_argument("--env", action="append", default=[], metavar="NAME=VALUE",
                         help=ENV_HELP)
    command.add_argument("--config", type=Path, metavar="FILE",
                         help="configuration file (default: the nearest launchverify.toml "
                         "or pyproject.toml with [tool.launchverify])")
    command.add_argument("--isolated", action="store_true",
                         help="ignore configuration files")
    command.add_argument("--package-path", action="append", default=[], type=Path,
                         metavar="FOLDER",
                         help="also search FOLDER for packages, and let checks read it "
                         "(repeatable; also $LAUNCHVERIFY_PACKAGE_PATH); confirms a "
                         "configuration file's package-paths outside the workspace")
    command.add_argument("--baseline", type=Path, metavar="FILE",
                         help="report only findings not recorded in FILE")
    command.add_argument("--distro", choices=DISTROS,
                         help="the ROS 2 distribution to check for (default: $ROS_DISTRO, "
                         "else features of every distribution are accepted)")
    command.add_argument("-j", "--jobs", type=_positive_int, metavar="N",
                         help="use up to N processes: Python launch files evaluated ahead, "
                         "each in its own confined process, and the rules shared out "
                         "between processes (default: the number of CPUs)")
    command.add_argument("--time-limit", type=_positive_float, metavar="SECONDS",
                         help="stop a Python launch file's evaluation, its "
                         "OpaqueFunctions included, after SECONDS (default: 10)")
    command.add_argument("--max-file-size", type=_positive_float, metavar="MB",
                         help="do not read files larger than MB megabytes (default: 10)")
    command.add_argument("-v", "--verbose", action="store_true",
                         help="say how Python launch files were confined")
    command.add_argument("--affected", action="store_true",
                         help="the paths are changed files of any kind (launch, parameter, "
                         "URDF, package.xml): check the launch files they may break, "
                         "includers too (what the pre-commit hook runs)")
    command.add_argument("--launch-files-only", action="store_true",
                         help="skip given files that do not look like launch files (as in "
                         "folders); for pre-commit, which passes every matching file")
    command.add_argument("--exit-zero", action="store_true",
                         help="exit 0 even when there are findings")
    command.add_argument("--fail-on", choices=("error", "warning", "info"),
                         help="lowest severity that fails the check, exit status 1 "
                         "(default: the configuration's fail-on, else error)")


def _positive_int(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a whole number") from None
    if value < 1:
        raise argparse.ArgumentTypeError("must be at least 1")
    return value


def _positive_float(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None
    if not 0 < value < 1e9:
        raise argparse.ArgumentTypeError("must be a positive number")
    return value


class Parser(argparse.ArgumentParser):
    """argparse, with short usage errors and suggestions, as ruff and git give them.

    A wrong option value is one line and a pointer to ``--help``, not the whole usage; a
    misspelt subcommand, choice or option says what was probably meant.
    """

    def error(self, message: str) -> NoReturn:
        """Print ``launchverify check: error: ...`` and where help is; exit 2."""
        self.exit(EXIT_ERROR, inert(f"{self.prog}: error: {message}") +
                  f"\nsee '{self.prog} --help'\n")

    def _check_value(self, action: argparse.Action, value: Any) -> None:
        """Refuse a value outside the choices, naming the closest (the same on every Python)."""
        if action.choices is None or value in action.choices:
            return
        choices = [str(choice) for choice in action.choices]
        hint = did_you_mean_any(str(value), choices) or f" (choose from {', '.join(choices)})"
        raise argparse.ArgumentError(action, f"invalid choice: {str(value)!r}{hint}")

    def unknown_options(self, tokens: list[str]) -> NoReturn:
        """Refuse options this (sub)command does not have, with the one meant if clear."""
        known = [option for action in self._actions for option in action.option_strings]
        first = tokens[0].split("=", 1)[0]
        self.error(f"unrecognized arguments: {' '.join(tokens)}"
                   f"{did_you_mean_any(first, known, count=1)}")


def build_parser() -> argparse.ArgumentParser:
    """Return the argument parser of the whole command line."""
    parser = Parser(
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
    _add_check_options(check)
    check.add_argument("--format", "--output-format", dest="format", choices=FORMATS,
                       default="text", help="how findings are written (default: text; "
                       "--output-format is ruff's spelling)")
    check.add_argument("-o", "--output", type=output_file, metavar="FILE",
                       help="write the report to FILE instead of standard output ('-': "
                       "standard output)")
    check.add_argument("--color", choices=("auto", "always", "never"), default="auto",
                       help="color the text output (default: auto, on a terminal unless "
                       "NO_COLOR is set)")
    check.add_argument("--explain", action="store_true",
                       help="under each finding: related lines, the trace, why it matters "
                       "and how to fix it")
    check.add_argument("-q", "--quiet", action="store_true",
                       help="print findings only: no summary, no progress")
    check.add_argument("--statistics", action="store_true",
                       help="print how many findings each rule has, instead of them, and how "
                       "many questions went to the solver")
    check.add_argument("--write-baseline", type=Path, metavar="FILE",
                       help="record the findings in FILE (then use --baseline FILE)")
    check.add_argument("--xunit-file", type=Path, metavar="FILE",
                       help="also write JUnit XML to FILE (what colcon test-result reads)")
    check.add_argument("--stdin-filename", type=Path, metavar="PATH",
                       help="with the path '-': check standard input as the content of "
                       "PATH (an editor's unsaved buffer; PATH must exist)")
    check.add_argument("--fix", action="store_true",
                       help="apply the safe fixes to the files, check again until none is "
                       "left, and report what remains (with '-': print the fixed buffer)")
    check.add_argument("--unsafe-fixes", action="store_true",
                       help="with --fix or --diff, apply the unsafe fixes too (a guess among "
                       "several candidates, a comment's free text removed)")
    check.add_argument("--diff", action="store_true",
                       help="print what --fix would change as a unified diff and write "
                       "nothing; exit 1 when there is something to fix")
    check.add_argument("--no-cache", action="store_true",
                       help="check everything again: neither read nor write the cache of "
                       "results (also LAUNCHVERIFY_NO_CACHE=1)")
    check.add_argument("--cache-dir", type=Path, metavar="DIR",
                       help="where results are kept between runs (default: "
                       "$XDG_CACHE_HOME/launchverify, else ~/.cache/launchverify)")

    report = commands.add_parser(
        "report", help="write a self-contained HTML report",
        description="Check launch files and write one HTML file (works offline): summary, "
        "findings with code frames, include trees and a picture of the launched system.",
    )
    _add_check_options(report)
    report.add_argument("-o", "--output", type=output_file,
                        default=Path("launchverify-report.html"), metavar="FILE",
                        help="where to write it (default: launchverify-report.html; '-': "
                        "standard output)")

    graph = commands.add_parser(
        "graph", help="print what a launch file would start",
        description="Evaluate one launch file and print its nodes, processes, includes, "
        "arguments, lifecycle bring-up and, from the workspace's own sources, the topics, "
        "services and actions its nodes use, under the given arguments.",
    )
    graph.add_argument("targets", nargs="+", metavar="FILE|name:=value", help=ONE_FILE_HELP)
    graph.add_argument("--workspace", type=Path, metavar="FOLDER", help=WORKSPACE_HELP)
    graph.add_argument("--format", choices=("json", "text"), default="json",
                       help="json for programs (default), text for people")
    graph.add_argument("--symbolic", action="store_true",
                       help="every action with its path condition, values as expressions")
    graph.add_argument("--env", action="append", default=[], metavar="NAME=VALUE",
                       help=ENV_HELP)

    run = commands.add_parser(
        "run", help="verify a launch file, then start it",
        description="Verify a launch file and, when it has no error, start it with ros2 "
        "launch's run-time semantics (processes, event handlers, timers, respawn, "
        "shutdown). Arguments written name:=value are passed as on ros2 launch.",
    )
    run.add_argument("targets", nargs="+", metavar="FILE|name:=value", help=ONE_FILE_HELP)
    run.add_argument("--workspace", type=Path, metavar="FOLDER",
                     help=WORKSPACE_HELP + "; its install/ folder is searched for executables")
    run.add_argument("--env", action="append", default=[], metavar="NAME=VALUE",
                     help="environment given to the check (the processes get the real one)")
    run.add_argument("--dry-run", action="store_true",
                     help="print every command that would run, and start nothing")
    run.add_argument("--force", action="store_true",
                     help="start even when the check finds errors")
    run.add_argument("--engine", choices=("embedded", "ros2"), default="embedded",
                     help="ros2: hand the verified file to the real ros2 launch")
    run.add_argument("--log-dir", type=Path, metavar="DIR",
                     help="where the run folder goes (default: ROS_LOG_DIR or ~/.ros/log)")

    rules = commands.add_parser(
        "rules", help="list every rule",
        description="List every rule: code, slug, severity and what it finds. "
        "'launchverify explain CODE' prints one rule's documentation.",
    )
    rules.add_argument("--format", choices=("text", "json", "markdown"), default="text",
                       help="markdown: every rule's documentation (docs/rules.md)")

    explain = commands.add_parser(
        "explain", help="print a rule's documentation",
        description="Print a rule's documentation: what it finds, why it matters, an "
        "example and how to fix it.",
    )
    explain.add_argument("rule", metavar="CODE|SLUG",
                         help="a code (LV101), a slug (duplicate-node-name) or a code "
                         "prefix (LV1: every rule whose code starts so)")

    lsp = commands.add_parser(
        "lsp", help="run the language server (for editors)",
        description="Speak the Language Server Protocol on standard input and output: "
        "diagnostics as you type, code actions for fixes, hover and go to definition. "
        "Needs pygls: pip install 'launchverify[lsp]'.",
    )
    lsp.add_argument("--tcp", metavar="HOST:PORT",
                     help="listen on a TCP port instead of standard input and output")

    completion = commands.add_parser(
        "completion", help="print a shell completion script",
        description="Print a completion script: eval \"$(launchverify completion bash)\" "
        "in ~/.bashrc, the same with zsh in ~/.zshrc, or launchverify completion fish | "
        "source in fish's config.",
    )
    completion.add_argument("shell", choices=("bash", "zsh", "fish"),
                            help="the shell the script is for")
    topology_command.add_parser(commands)
    diff_command.add_parser(commands)
    return parser


def _subcommand(parser: argparse.ArgumentParser, name: str | None) -> Parser:
    """Return the parser of a subcommand (the whole command line's without one)."""
    for action in parser._actions:  # argparse exposes subparsers only this way
        if isinstance(action, argparse._SubParsersAction) and name in action.choices:
            return cast(Parser, action.choices[name])
    return cast(Parser, parser)


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; return the exit status."""
    parser = build_parser()
    args = parse_command_line(parser, list(sys.argv[1:] if argv is None else argv))
    if args.command is None:
        parser.print_help()
        return EXIT_ERROR
    handlers = {"check": _check, "report": _report, "graph": _graph, "rules": _rules,
                "explain": _explain, "run": _run, "completion": _completion, "lsp": _lsp,
                "interfaces": topology_command.run, "diff": diff_command.run}
    # Until the output is written (process.collector says why); not for the commands
    # that run long, a server and a launch, whose garbage must go as they run.
    long_running = args.command in LONG_RUNNING
    if long_running:
        gc.enable()  # paused from the start by the command (launchverify.process.command)
    paused = nullcontext() if long_running else collector_paused()
    try:
        with paused:
            return _until_reader_leaves(handlers[args.command], args)
    except UsageError as error:
        print(f"launchverify: error: {error.shown()}", file=sys.stderr)
        return EXIT_ERROR
    except ConfigError as error:  # every problem of the file, one a line
        print(f"launchverify: error: {error.shown()}", file=sys.stderr)
        return EXIT_ERROR
    except (RegistryError, BaselineError) as error:
        print(inert(f"launchverify: error: {error}"), file=sys.stderr)
        return EXIT_ERROR
    except KeyboardInterrupt:  # Ctrl-C: what was being written was never written half
        return EXIT_INTERRUPTED
    except Exception as error:  # a bug of ours: say so plainly, never a traceback
        print(inert(f"launchverify: internal error: {type(error).__name__}: {error}") + "\n"
              "Please report this with the launch file that caused it.", file=sys.stderr)
        return EXIT_ERROR


def parse_command_line(parser: argparse.ArgumentParser, argv: list[str]) -> argparse.Namespace:
    """Parse the command line: of a command taking paths, every token after ``--`` is one.

    argparse alone reads an option after ``--`` once a path came before it, and drops the
    ``--`` that tells a file named ``x:=1`` from a launch argument; pre-commit appends file
    names, which a pull request chooses. So what follows ``--`` is kept out of argparse's
    sight, then put among the paths behind ``--`` (which ``engine.parse_arguments`` reads).
    """
    before, after = after_end_of_options(argv)
    positional = _paths_positional(parser, before) if END_OF_OPTIONS in argv else None
    if positional is None:  # argparse's own reading (`explain -- LV101`)
        return _parse_known(parser, argv)
    default = positional.default
    positional.required, positional.default = False, None  # the paths after -- count too
    args = _parse_known(parser, before)
    given = getattr(args, positional.dest) or []
    if positional.dest == "targets":  # paths and name:=value: the -- keeps them apart
        args.targets = [*given, END_OF_OPTIONS, *after]
    else:
        convert = positional.type if callable(positional.type) else str
        setattr(args, positional.dest, [*given, *map(convert, after)] or default)
    return args


def _paths_positional(parser: argparse.ArgumentParser, tokens: list[str]
                      ) -> argparse.Action | None:
    """Return the positional argument of the command's paths, when the command takes paths."""
    command = next((token for token in tokens if not token.startswith("-")), None)
    if command is None:
        return None
    return next((action for action in _subcommand(parser, command)._actions
                 if not action.option_strings and action.dest in ("targets", "paths")), None)


def _parse_known(parser: argparse.ArgumentParser, argv: list[str]) -> argparse.Namespace:
    """Parse options, then the paths and name:=value that follow them, argparse's leftovers.

    They may come after options (`check a --select LV1 b x:=1`).
    """
    args, extra = parser.parse_known_args(argv)
    unknown = [token for token in extra if token.startswith("-") and token != "-"]
    if unknown or (extra and not hasattr(args, "targets")):
        _subcommand(parser, args.command).unknown_options(unknown or extra)
    if extra:
        args.targets = [*args.targets, *extra]
    return args


def _until_reader_leaves(handler: Callable[[argparse.Namespace], int],
                         args: argparse.Namespace) -> int:
    """Run a command; stop quietly when its reader goes away (``launchverify ... | head``).

    Python's recipe: what is left to write goes to devnull, so the interpreter's last
    flush does not fail again. A broken pipe that is not standard output's or standard
    error's (a worker's, a started process's) is a bug, and raised.
    """
    try:
        status = handler(args)
        sys.stdout.flush()  # a closed pipe shows here, not in the interpreter's exit
    except BrokenPipeError:
        gone = _closed_standard_streams()
        if not gone:
            raise
        devnull = os.open(os.devnull, os.O_WRONLY)
        for descriptor in gone:
            os.dup2(devnull, descriptor)
        os.close(devnull)
        return EXIT_READER_GONE
    return status


def _closed_standard_streams() -> list[int]:
    """Return the descriptors of standard output and error whose reader has gone.

    A pipe's writing end polls as an error (Linux) or hang-up (BSD, macOS) once no one
    reads it. Without ``poll`` (Windows), standard output is taken to be the one.
    """
    if not hasattr(select, "poll"):  # pragma: no cover - Windows
        return [sys.__stdout__.fileno()] if sys.__stdout__ is not None else []
    gone = []
    for stream in (sys.stdout, sys.stderr):
        try:
            descriptor = stream.fileno()
        except (AttributeError, OSError, ValueError):  # replaced by a caller (a test)
            continue
        poller = select.poll()
        poller.register(descriptor, select.POLLOUT)
        if any(events & (select.POLLERR | select.POLLHUP) for _, events in poller.poll(0)):
            gone.append(descriptor)
    return gone


def check_options(args: argparse.Namespace, *, progress: bool = False
                  ) -> tuple[CheckOptions, Config]:
    """Merge the command line with the configuration file into what to check.

    The command line wins: ``--select`` replaces the file's select, ``--ignore`` adds to
    its ignore, ``name:=value`` and ``--env`` override its arguments and environment.
    """
    paths, arguments = parse_arguments(args.targets)
    if not paths and args.affected:
        raise UsageError("--affected needs the changed files")
    paths = paths or ["."]  # as ruff: the working folder
    refuse_unknown_selectors(args)
    parameter_files = [] if args.affected or args.launch_files_only else _named_files(paths)
    config = Config()
    if not args.isolated:
        found = args.config or find_config(Path(paths[0]))
        if args.config is not None and not args.config.is_file():
            raise UsageError(f"no such configuration file: {str(args.config)!r}")
        if found is not None:
            config = load_config(found)
    config = _confined(config, paths, args)
    options = CheckOptions(
        paths=[Path(p) for p in paths],
        arguments={**config.arguments, **arguments},
        workspace=args.workspace or config.workspace,
        select=option_codes(args.select) if args.select is not None else config.select,
        ignore=[*config.ignore, *(option_codes(args.ignore) or [])],
        command_select=option_codes(args.select),
        command_ignore=option_codes(args.ignore) or [],
        nested_configs=not args.isolated and args.config is None,
        affected=args.affected,
        parameter_files=parameter_files,
        environment={**config.environment, **parse_environment(args.env)},
        config=config,
        exclude=[*args.exclude, *excluded_by_ament()],
        baseline=args.baseline,
        launch_files_only=args.launch_files_only,
        distro=args.distro or config.distro or _ros_distro(),
        jobs=args.jobs or config.jobs,
        time_limit=args.time_limit or config.time_limit or DEFAULT_TIME_LIMIT,
        max_file_size=int((args.max_file_size or config.max_file_size or 10) * 1e6),
        progress=_progress_bar() if progress else None,
    )
    return options, config


def _named_files(paths: list[str]) -> list[Path]:
    """Return the parameter files among the files given; refuse what is neither kind.

    A file given by name is read for what it is: a launch file, or a parameter file
    (checked through the launch files that load it, as ``--affected`` does); a README or
    a C++ source is a usage error, not a launch file that fails to parse. What a folder's
    walk finds is judged by the walk.
    """
    from launchverify.workspace.discover import WHAT_IS_READ, named_kind

    parameters = []
    for text in paths:
        path = Path(text)
        if not path.is_file():  # a folder, or missing (said by the check)
            continue
        kind = named_kind(path)
        if kind is None:
            raise UsageError(f"{text!r} is neither a launch file nor a parameter file: "
                             f"{WHAT_IS_READ}; --affected checks the launch files any "
                             "changed file may break (a URDF, a package.xml)")
        if kind == "parameters":
            parameters.append(path)
    return parameters


def refuse_unknown_selectors(args: argparse.Namespace) -> None:
    """Refuse a ``--select``/``--ignore`` that names no rule, before any work."""
    for option, given in (("--select", args.select), ("--ignore", args.ignore)):
        for selector in option_codes(given) or []:
            problem = unknown_selector(selector)
            if problem is not None:
                raise UsageError(f"{option}: {problem}")


def _confined(config: Config, paths: list[str], args: argparse.Namespace) -> Config:
    """Return the configuration as the user allows it (see ``config.confined``).

    What the checked tree's own file may not widen is left out (and said on stderr); the
    package folders the user named are added.
    """
    confirmed = confirmed_package_paths(args.package_path)
    workspace = check_workspace([Path(p) for p in paths], args.workspace).folder
    config, notes = confined(config, [Path(p) for p in paths], workspace, confirmed)
    for note in notes:
        print(inert(f"launchverify: note: {note}"), file=sys.stderr)
    known = set(config.package_paths)
    return dataclasses.replace(config, package_paths=[
        *config.package_paths, *(p for p in confirmed if p not in known)])


def _ros_distro() -> str | None:
    """Return the sourced installation's distribution (``ROS_DISTRO``) when it is known."""
    distro = os.environ.get("ROS_DISTRO", "").strip().lower()
    return distro if distro in DISTROS else None


def _read_stdin(args: argparse.Namespace) -> bool:
    """Read an editor's buffer for ``check - --stdin-filename PATH``; say whether there was.

    The content stands for PATH's for every reader (Python workers included), so findings
    point into the buffer; nothing is written, and the cache is left alone.
    """
    given, _ = after_end_of_options(args.targets)  # after `--`, '-' is a file named so
    if "-" not in given:
        if args.stdin_filename is not None:
            raise UsageError("--stdin-filename goes with the path '-' (standard input)")
        return False
    if args.stdin_filename is None:
        raise UsageError("checking standard input ('-') needs --stdin-filename PATH")
    if not args.stdin_filename.is_file():
        raise UsageError(f"--stdin-filename {str(args.stdin_filename)!r}: no such file "
                         "(the buffer is checked where that file is, with its includes)")
    from launchverify.workspace.reading import set_unsaved

    set_unsaved(args.stdin_filename, sys.stdin.buffer.read())
    args.targets = [str(args.stdin_filename) if t == "-" else t for t in given] + \
        args.targets[len(given):]
    return True


def _writable_outputs(args: argparse.Namespace, *paths: Path | None) -> tuple[Path, ...]:
    """Refuse, before any work, an output ``write_file`` would refuse; return its anchors.

    Outputs go through no link below the working folder or a checked tree: the
    check's workspace, and the workspace of each path given (see ``process.outputs``).
    """
    if all(path is None for path in paths):
        return ()
    from launchverify.process.outputs import check_outputs  # (only when writing: start-up)

    return check_outputs(paths, lambda: _checked_trees(args))


def _checked_trees(args: argparse.Namespace) -> tuple[Path, ...]:
    """Return the workspaces of what a check reads (each found once per folder given)."""
    paths = [Path(token) for token in parse_arguments(args.targets)[0] if token != "-"]
    stdin = getattr(args, "stdin_filename", None)
    starts = dict.fromkeys(path if path.is_dir() else path.parent
                           for path in [*(paths or [Path()]), *([stdin] if stdin else [])])
    trees = [discover_workspace(starts).folder, *(find_workspace(start) for start in starts)]
    return tuple(dict.fromkeys([*trees, *([args.workspace] if args.workspace else [])]))


def _check(args: argparse.Namespace) -> int:
    inside = _writable_outputs(args, args.output, args.write_baseline, args.xunit_file)
    _fix_usage(args)
    buffered = _read_stdin(args)
    options, config = check_options(args, progress=not args.quiet and sys.stderr.isatty())
    cache = None if buffered else _result_cache(args)
    report = run_check_cached(options, cache)
    if cache is not None and cache.refused is not None and not args.quiet:
        print(f"launchverify: note: {inert(cache.refused)}", file=sys.stderr)
    if args.diff:
        return _diff(args, options, report, inside)
    report_out = sys.stdout
    if args.fix:
        report = _fix(args, options, report, args.stdin_filename if buffered else None)
        report_out = sys.stderr if buffered else sys.stdout  # stdout has the fixed buffer
    if args.write_baseline is not None:
        write_baseline(args.write_baseline, report.findings, inside=inside)
    if args.xunit_file is not None:
        from launchverify.process.outputs import write_file
        from launchverify.render.junit import render_junit

        junit = io.StringIO()
        render_junit(report, junit, checked=report.checked)
        write_file(args.xunit_file, junit.getvalue(), inside=inside)
    if args.output is not None:
        from launchverify.process.outputs import write_file

        text = io.StringIO()
        _render(args, report, text, color=False)
        write_file(args.output, text.getvalue(), inside=inside)
    else:
        color = {"auto": None, "always": True, "never": False}[args.color]
        if color is None and os.environ.get("NO_COLOR"):  # no-color.org: plain text
            color = False
        _render(args, report, report_out, color=color)
    sys.stdout.flush()
    _say_workspace(report, args.verbose, args.quiet)
    _say_protections(report, args.verbose)
    return _exit_status(report, args, config)


def _exit_status(report: Report, args: argparse.Namespace, config: Config) -> int:
    """Return the exit status of ``check`` and ``report``: 1 when a finding fails them."""
    if args.exit_zero:
        return EXIT_OK
    return EXIT_FINDINGS if fails(report, args, config) else EXIT_OK


def _fix_usage(args: argparse.Namespace) -> None:
    """Refuse combinations of the fix options that cannot mean anything."""
    if args.diff and (args.write_baseline or args.xunit_file):
        raise UsageError("--diff writes nothing: it does not go with --write-baseline or "
                         "--xunit-file")


def _fixed(report: Report, options: CheckOptions, unsafe: bool,
           stdin: Path | None = None) -> Outcome:
    """Apply the fixes in memory, checking again after each pass; say what was refused.

    With standard input, only the buffer is fixed (the files on disk are not ours to
    change then).
    """
    only = None if stdin is None else canonical(stdin)
    outcome = fix_all(report, lambda: run_check(options), unsafe=unsafe,
                      editable=None if only is None else lambda path: path == only)
    for note in outcome.notes:
        print(f"launchverify: note: {note}", file=sys.stderr)
    return outcome


def _diff(args: argparse.Namespace, options: CheckOptions, report: Report,
          inside: tuple[Path, ...]) -> int:
    """Print what ``--fix`` would change as a unified diff; write nothing.

    Exit 1 when there is something to fix (as ruff's ``--diff``), else 0.
    """
    outcome = _fixed(report, options, args.unsafe_fixes, args.stdin_filename)
    text = unified_diff(outcome, report.display_path)
    if args.output is not None:
        from launchverify.process.outputs import write_file

        write_file(args.output, text, inside=inside)
    else:
        # exact for a pipe (patch), inert for a reviewer's eyes
        sys.stdout.write(inert_block(text) if sys.stdout.isatty() else text)
    if not args.quiet:
        count = outcome.count
        print(f"Would fix {count} finding{'s' if count != 1 else ''}"
              f"{_hidden_note(outcome.report, args.unsafe_fixes)}.", file=sys.stderr)
    return EXIT_FINDINGS if outcome.fixed and not args.exit_zero else EXIT_OK


def _fix(args: argparse.Namespace, options: CheckOptions, report: Report,
         stdin: Path | None) -> Report:
    """Apply the fixes and return the check of the fixed files.

    The files are written; for standard input, the fixed buffer goes to standard output.
    """
    outcome = _fixed(report, options, args.unsafe_fixes, stdin)
    if stdin is not None:
        path = canonical(stdin)
        data = outcome.fixed.get(path, reading.unsaved(path))
        assert data is not None  # the buffer read for '-'
        reading.set_unsaved(path, data)  # what the findings now point into
        sys.stdout.buffer.write(data)
        sys.stdout.flush()
    else:
        _write_fixed(outcome.fixed)
    if not args.quiet:
        remaining = len(outcome.report.findings)
        print(f"Fixed {outcome.count} finding{'s' if outcome.count != 1 else ''} "
              f"({remaining} remaining){_hidden_note(outcome.report, args.unsafe_fixes)}.",
              file=sys.stderr)
    return outcome.report


# The files fixes edit are named by their real paths (``canonical``: how a check knows a
# file), with no link on the way when the check read them: one there now is refused.
_NO_LINK_ANYWHERE = (Path("/"),)


def _write_fixed(fixed: dict[Path, bytes]) -> None:
    """Write the fixed files (each atomically, keeping its mode), never through a link.

    Every file is checked before the first is written, so a refusal leaves all as they
    were (a link swapped in after that is still never written through).
    """
    from launchverify.process.outputs import check_writable, write_file

    for path in sorted(fixed):
        check_writable(path, inside=_NO_LINK_ANYWHERE)
    for path, data in sorted(fixed.items()):
        write_file(path, data, inside=_NO_LINK_ANYWHERE)


def _hidden_note(report: Report, unsafe: bool) -> str:
    """Return ``"; 2 hidden fixes can be enabled with --unsafe-fixes"`` when there are."""
    count = hidden(report.findings, unsafe)
    if not count:
        return ""
    return (f"; {count} hidden fix{'es' if count != 1 else ''} can be enabled with "
            "--unsafe-fixes")


def _result_cache(args: argparse.Namespace) -> ResultCache | None:
    """Return the cache of results a check uses, or ``None`` when asked for none."""
    if args.no_cache or disabled_by_environment():
        return None
    return ResultCache(args.cache_dir or default_cache_dir(), named=args.cache_dir is not None)


def _say_workspace(report: Report, verbose: bool, quiet: bool) -> None:
    """Say where packages were found (``-v``), and a choice the user may not expect."""
    found = report.workspace
    if found is None:
        return
    if verbose:
        print(inert(f"launchverify: workspace {found.folder} ({found.how})"), file=sys.stderr)
    if found.note and not quiet:
        print(inert(f"launchverify: note: {found.note}"), file=sys.stderr)


def _say_protections(report: Report, verbose: bool) -> None:
    """Say once how Python launch files were confined: always when a layer was missing."""
    if not report.python_files or report.protections is None:
        return
    missing = "unavailable" in report.protections
    if verbose or missing:
        print(f"launchverify: {'note: ' if missing else ''}{report.python_files} Python launch "
              f"file(s) evaluated in confined processes; {report.protections}",
              file=sys.stderr)


def fails(report: Report, args: argparse.Namespace, config: Config) -> bool:
    """Return whether a finding reaches ``--fail-on`` (else the configuration, else error)."""
    threshold = Severity(args.fail_on or config.fail_on or "error").rank
    return any(f.severity.rank >= threshold for f in report.findings)


def _render(args: argparse.Namespace, report: Report, out: TextIO,
            color: bool | None) -> None:
    """Write the report in the format asked for."""
    if args.statistics and args.format == "text":
        from launchverify.render.text import render_statistics

        render_statistics(report, out, quiet=args.quiet)
    elif args.format == "text":
        from launchverify.render.text import render_text

        render_text(report, out, color=color, explain=args.explain, quiet=args.quiet,
                    unsafe_fixes=args.unsafe_fixes)
    elif args.format == "concise":
        from launchverify.render.concise import render_concise

        render_concise(report, out, color=color, quiet=args.quiet,
                       unsafe_fixes=args.unsafe_fixes)
    elif args.format == "json":
        from launchverify.render.json_out import render_json

        render_json(report, out)
    elif args.format == "sarif":
        from launchverify.render.sarif import render_sarif

        render_sarif(report, out)
    elif args.format == "junit":
        from launchverify.render.junit import render_junit

        render_junit(report, out, checked=report.checked)
    else:
        from launchverify.render.github import render_github

        render_github(report, out)


def _report(args: argparse.Namespace) -> int:
    from launchverify.process.outputs import write_file
    from launchverify.render.html_report import render_html
    from launchverify.topology.compose import WorkspaceInterfaces

    inside = _writable_outputs(args, args.output)
    options, config = check_options(args, progress=sys.stderr.isatty())
    report = run_check(options)
    _say_workspace(report, args.verbose, quiet=False)
    _say_protections(report, args.verbose)
    _, index = build_index(options.paths, options.workspace, options.config.package_paths)
    page = io.StringIO()
    render_html(report, page, interfaces=WorkspaceInterfaces(index))
    if args.output is None:  # -o -
        sys.stdout.write(page.getvalue())
        sys.stdout.flush()
        where = "wrote the report to standard output"
    else:
        write_file(args.output, page.getvalue(), inside=inside)
        where = f"wrote {args.output}"
    print(f"{where} ({len(report.findings)} findings in {report.files} files)",
          file=sys.stderr)
    return _exit_status(report, args, config)


def _run(args: argparse.Namespace) -> int:
    from launchverify.executor.runner import RunOptions, Verdict, run
    from launchverify.render.text import render_text

    paths, arguments = parse_arguments(args.targets)
    if len(paths) != 1 or not Path(paths[0]).is_file():
        raise UsageError("run takes exactly one launch file")
    def checked(verdict: Verdict) -> None:
        if verdict.report.findings:
            render_text(verdict.report, sys.stderr, color=None, quiet=True)
        if verdict.elsewhere:
            print(inert(f"launchverify: note: {verdict.elsewhere} error(s) hold only for "
                        f"other argument values; `launchverify check {shlex.quote(paths[0])}`"
                        " lists them"), file=sys.stderr)
        if verdict.refused:
            print("launchverify: not started: the check found errors (--force starts "
                  "anyway)", file=sys.stderr)

    options = RunOptions(
        check=CheckOptions(paths=[Path(paths[0])], arguments=arguments,
                           workspace=args.workspace, environment=parse_environment(args.env),
                           distro=_ros_distro()),
        dry_run=args.dry_run, force=args.force, engine=args.engine, log_dir=args.log_dir,
        arguments=arguments, on_checked=checked)
    status, _ = run(options, sys.stdout, sys.stderr)
    return status


def _rules(args: argparse.Namespace) -> int:
    from launchverify.registry import all_rules

    rules = all_rules()
    if args.format == "json":
        json.dump([{"code": r.code, "slug": r.slug, "severity": r.severity.value,
                    "summary": r.summary()} for r in rules], sys.stdout, indent=2)
        sys.stdout.write("\n")
    elif args.format == "markdown":
        sys.stdout.write(rules_markdown(rules))
    else:
        for rule in rules:
            print(f"{rule.code}  {rule.slug:<32} {rule.severity.value:<8} "
                  f"{rule.summary()}")
    return EXIT_OK


def rules_markdown(rules: Sequence[type[Rule]]) -> str:
    """Return every rule's documentation as one Markdown page (``docs/rules.md``)."""
    parts = ["# Rules\n\n<!-- generated by `launchverify rules --format markdown` -->\n\n"
             "| Code | Slug | Severity | Summary |\n|---|---|---|---|\n"]
    parts += [f"| [{r.code}](#{r.code.lower()}-{r.slug}) | {r.slug} | {r.severity.value} | "
              f"{r.summary()} |\n" for r in rules]
    for rule in rules:
        body = rule.documentation().replace("\n## ", "\n### ")
        parts.append(f"\n## {rule.code} {rule.slug}\n\nSeverity: {rule.severity.value}\n\n"
                     f"{body}\n")
    return "".join(parts)


def _completion(args: argparse.Namespace) -> int:
    from launchverify.registry import all_rules
    from launchverify.render.completion import completion_script

    codes = [rule.code for rule in all_rules()]
    sys.stdout.write(completion_script(args.shell, build_parser(), codes))
    return EXIT_OK


def _lsp(args: argparse.Namespace) -> int:
    from launchverify.lsp import serve  # imports pygls only when the server starts

    return serve(args.tcp)


def _explain(args: argparse.Namespace) -> int:
    from launchverify.registry import resolve

    problem = unknown_selector(args.rule)
    if problem is not None:
        raise UsageError(problem)
    found = [r for r in resolve(args.rule) if args.rule.strip() in (r.code, r.slug)] or \
        resolve(args.rule)
    for index, rule in enumerate(found):
        if index:
            print()
        print(f"# {rule.code} {rule.slug} ({rule.severity.value})\n")
        print(rule.documentation())
    return EXIT_OK


def _progress_bar() -> Callable[[int, int], None]:
    """Return a callback drawing a progress bar on stderr once a check is large."""
    from rich.progress import Progress

    state: dict[str, Any] = {}

    def update(done: int, total: int) -> None:
        if total < 20:
            return
        if "bar" not in state:
            from rich.console import Console

            bar = Progress(transient=True, console=Console(stderr=True))
            bar.start()
            state["bar"], state["task"] = bar, bar.add_task("checking launch files",
                                                            total=total)
        state["bar"].update(state["task"], completed=done)
        if done >= total:
            state["bar"].stop()

    return update


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
    confine_reads(index, workspace, [path])
    graph = evaluate(canonical(path), index=index, workspace=workspace, pinned=arguments,
                     environment=parse_environment(args.env))
    graph.included_elsewhere = Includers.of_workspace(index.workspaces).included(graph.root)
    from launchverify.topology.compose import WorkspaceInterfaces

    interfaces = WorkspaceInterfaces(index)
    if args.format == "json":
        render_graph_json(graph, sys.stdout, symbolic=args.symbolic, interfaces=interfaces)
    else:
        render_graph_text(graph, cast(TextIO, InertWriter(sys.stdout)),
                          symbolic=args.symbolic, interfaces=interfaces)
    return _graph_stopped(graph, args.format)


def _graph_stopped(graph: LaunchGraph, output_format: str) -> int:
    """Exit 1 when the launch could not be read or failed: say where, on stderr.

    A graph of a file that does not parse, or whose evaluation raised, is empty or cut
    short: printing it alone would pass for "nothing to start".
    """
    from launchverify.problems import ProblemKind

    stoppers = [record.problem for record in graph.problems
                if record.problem.kind in (ProblemKind.PARSE, ProblemKind.EVALUATION)]
    if not stoppers:
        return EXIT_OK
    for problem in stoppers:
        span = problem.span
        print(inert(f"{display_path(span.file)}:{span.line}:{span.column}: {problem.message}"),
              file=sys.stderr)
    what = "graph" if output_format == "json" else "the graph above"
    print(f"launchverify: {what} is incomplete: the launch stops at the error(s) above",
          file=sys.stderr)
    return EXIT_FINDINGS
