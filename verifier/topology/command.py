"""``launchverify interfaces``: list what each node of a workspace creates, from its sources.

Kept here rather than in ``cli.py`` so the command line only registers it; nothing of
tree-sitter is imported until the command runs.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path
from typing import TYPE_CHECKING, Any, TextIO, cast

from launchverify.render.encodable import write_json
from launchverify.workspace.paths import display_path

if TYPE_CHECKING:
    from launchverify.topology.model import NodeInterface

EXIT_OK, EXIT_ERROR = 0, 2


def add_parser(commands: Any) -> None:
    """Register the ``interfaces`` command on the command line's subparsers."""
    command = commands.add_parser(
        "interfaces", help="list the topics, services and actions nodes create (from sources)",
        description="Read the C++ and Python sources of every package below the given "
        "folders (or the given source files) without building them, and list what each "
        "executable or component creates: publishers, subscriptions, services, clients, "
        "action servers and clients, with names as written and where a name is unknown "
        "until run time, why.",
    )
    command.add_argument("paths", nargs="*", type=Path, default=[Path()], metavar="PATH",
                         help="workspace or package folder, or a source file (default: .)")
    command.add_argument("--format", choices=("text", "json"), default="text",
                         help="text for people (default), json for programs")
    command.add_argument("-v", "--verbose", action="store_true",
                         help="also list each node's declared parameters and say which "
                         "source files had parts the reader skipped (once per file)")


def run(args: argparse.Namespace, out: TextIO | None = None) -> int:
    """Print the node interfaces found below ``args.paths``; return the exit status."""
    from launchverify.topology.files import cache_stats, file_interfaces, language_of
    from launchverify.topology.model import FileInterfaces, NodeInterface
    from launchverify.topology.nodes import SKIPPED, workspace_interfaces  # no parser yet

    stream = out or sys.stdout
    missing = [p for p in args.paths if not p.exists()]
    if missing:
        print(f"launchverify: error: no such file or folder: {missing[0]}", file=sys.stderr)
        return EXIT_ERROR
    started = time.perf_counter()
    folders = [p.resolve() for p in args.paths if p.is_dir()]
    files = [p.resolve() for p in args.paths if not p.is_dir()]
    interfaces: list[NodeInterface] = list(workspace_interfaces(folders))
    singles: list[FileInterfaces] = [file_interfaces(f) for f in files]
    for single in singles:
        if language_of(single.file) is None:
            continue
        problems = (single.problem,) if single.problem else ()
        names = {n.name for n in single.node_names}
        interfaces.append(NodeInterface("", single.file.name, None,
                                        names.pop() if len(names) == 1 else None,
                                        single.endpoints, (single.file,), problems))
    elapsed = time.perf_counter() - started
    if args.format == "json":
        write_json({"interfaces": [_as_json(i) for i in interfaces],
                    "files_parsed": cache_stats()["parsed"],
                    "seconds": round(elapsed, 3)}, stream)
    else:
        from launchverify.render.inert import InertWriter

        safe = cast(TextIO, InertWriter(stream))  # names come from the checked sources
        said: set[str] = set()  # a file's skipped parts, once, and only when asked
        for interface in interfaces:
            notes = []
            for problem in interface.problems:
                if problem.endswith(SKIPPED) and (not args.verbose or problem in said):
                    continue
                said.add(problem)
                notes.append(problem)
            _print_text(interface, safe, notes, args.verbose)
        count = sum(len(i.endpoints) for i in interfaces)
        print(f"{len(interfaces)} executables or components, {count} endpoints, "
              f"{cache_stats()['parsed']} files parsed in {elapsed:.2f} s", file=stream)
    return EXIT_OK


def _as_json(interface: NodeInterface) -> dict[str, Any]:
    return {
        "package": interface.package, "executable": interface.executable,
        "component": interface.component, "node_name": interface.node_name,
        "sources": [display_path(p) for p in interface.sources],
        "problems": list(interface.problems),
        "endpoints": [{
            "kind": e.kind.value, "name": e.name, "type": e.type,
            "name_parameter": e.name_parameter, "parameter_default": e.parameter_default,
            "qos": e.qos, "via": e.via, "owner": e.owner, "note": e.note,
            "unresolved_reason": e.unresolved_reason,
            "reliability": e.profile.reliability if e.profile else None,
            "durability": e.profile.durability if e.profile else None,
            "file": display_path(e.span.file), "line": e.span.line, "column": e.span.column,
        } for e in interface.endpoints],
        "parameters": [{
            "name": p.name, "type": p.type, "default": p.default, "dynamic": p.dynamic,
            "required": p.required, "read_only": p.read_only, "via": p.via,
            "limits": [[check, list(arguments)] for check, arguments in p.limits],
            "file": display_path(p.span.file), "line": p.span.line,
        } for p in interface.parameters],
        "parameters_open": interface.parameters_open,
    }


def _print_text(interface: NodeInterface, stream: TextIO, notes: list[str],
                verbose: bool = False) -> None:
    title = f"{interface.package} {interface.executable}".strip()
    if interface.component and interface.component != interface.executable:
        title += f" (component {interface.component})"
    if interface.node_name:
        title += f"  node name: {interface.node_name}"
    print(title, file=stream)
    for e in interface.endpoints:
        name = e.name if e.name is not None else "?"
        if e.name_parameter:
            name += f"  (parameter {e.name_parameter})"
        where = f"{display_path(e.span.file)}:{e.span.line}"
        line = f"  {e.kind.value:<14} {name:<32} {e.type or '?':<40} {where}"
        if e.via:
            line += f"  [{e.via}]"
        print(line, file=stream)
        if e.unresolved_reason:
            print(f"  {'':<14} unknown: {e.unresolved_reason}", file=stream)
    if verbose:
        for p in interface.parameters:
            default = "" if p.default is None else f" = {p.default!r}"
            flags = "".join(f"  [{w}]" for w, on in (("required", p.required),
                                                     ("any type", p.dynamic)) if on)
            print(f"  {'parameter':<14} {p.name + default:<32} {p.type or '?':<40} "
                  f"{display_path(p.span.file)}:{p.span.line}{flags}", file=stream)
        if interface.parameters and interface.parameters_open:
            print(f"  {'':<14} may take other parameters: {interface.parameters_open}",
                  file=stream)
    for note in notes:
        print(f"  note: {note}", file=stream)
