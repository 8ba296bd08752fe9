"""The entry point of an evaluation."""

from __future__ import annotations

from pathlib import Path

from launchverify.evaluate.files import FileCache
from launchverify.evaluate.walker import Walker
from launchverify.graph import LaunchGraph, ProblemRecord
from launchverify.problems import Problem, ProblemKind
from launchverify.span import Span
from launchverify.workspace.packages import PackageIndex


def evaluate(
    root: Path,
    *,
    index: PackageIndex,
    workspace: Path,
    pinned: dict[str, str] | None = None,
    environment: dict[str, str] | None = None,
    loader: FileCache | None = None,
    included_elsewhere: bool = False,
) -> LaunchGraph:
    """Evaluate ``root`` as ``ros2 launch root name:=value...`` would, without running it.

    Args:
        root: the launch file, as an absolute path.
        index: packages to resolve ``pkg=`` and ``$(find-pkg-share)`` against.
        workspace: files outside it are inputs of the machine, not part of the tree.
        pinned: argument values given like ``name:=value`` on the command line.
        environment: environment variables of the machine that will run the launch.
        loader: shared file cache (a fresh one when omitted).
        included_elsewhere: the file is also included by others in this check.

    Returns:
        The launch graph of everything the evaluation found.
    """
    graph = LaunchGraph(root=root, pinned=dict(pinned or {}),
                        environment=dict(environment or {}),
                        included_elsewhere=included_elsewhere)
    cache = loader or FileCache(index, workspace, environment=environment)
    try:
        Walker(graph, index, cache, workspace).run()
    except Exception as error:  # a bug of ours: LV005 on this root, the check goes on
        graph = LaunchGraph(root=root, pinned=dict(pinned or {}),
                            environment=dict(environment or {}),
                            included_elsewhere=included_elsewhere)
        text = str(error).splitlines()[0][:200] if str(error) else ""
        graph.problems.append(ProblemRecord(Problem(
            ProblemKind.INTERNAL, "launchverify failed while evaluating this file "
            f"({type(error).__name__}{': ' + text if text else ''})", Span.of_file(root))))
    finally:
        if loader is None:
            cache.close()
    return graph
