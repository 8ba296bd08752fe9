"""Time ``launchverify report`` (with its computation graph) against ``check``.

Generates the fleet workspace of ``tests/flow_workspace.py`` (22 nodes per robot, C++ and
Python sources) for each robot count, or takes given launch files, and prints the wall
seconds (min/median/max) of ``check`` and ``report`` on it, and the report's size.

    python bench/flow_report.py [--robots 9 45] [--repeat 3]
    python bench/flow_report.py --launch FILE --workspace DIR
"""

from __future__ import annotations

import argparse
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tests"))

from flow_workspace import FLEET_NODES, NODES_PER_ROBOT, write_workspace

LAUNCHVERIFY = Path(sys.executable).parent / "launchverify"


def _time(command: list[str], repeat: int) -> list[float]:
    runs = []
    for _ in range(repeat):
        started = time.perf_counter()
        subprocess.run(command, check=False, capture_output=True)
        runs.append(time.perf_counter() - started)
    return runs


def _measure(launch: Path, workspace: Path, repeat: int, label: str) -> None:
    with tempfile.TemporaryDirectory() as out:
        page = Path(out) / "report.html"
        common = [str(launch), "--workspace", str(workspace), "--no-cache"]
        check = _time([str(LAUNCHVERIFY), "check", *common], repeat)
        report = _time([str(LAUNCHVERIFY), "report", str(launch), "--workspace",
                        str(workspace), "-o", str(page)], repeat)
        size = page.stat().st_size if page.exists() else 0
    print(f"{label}: check {_spread(check)} s, report {_spread(report)} s, "
          f"page {size / 1024:.0f} KiB")


def _spread(runs: list[float]) -> str:
    return f"{min(runs):.2f} / {statistics.median(runs):.2f} / {max(runs):.2f}"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--robots", type=int, nargs="+", default=[9])
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--launch", type=Path)
    parser.add_argument("--workspace", type=Path)
    args = parser.parse_args()
    if args.launch is not None:
        _measure(args.launch, args.workspace or args.launch.parent, args.repeat,
                 str(args.launch))
        return 0
    for robots in args.robots:
        with tempfile.TemporaryDirectory() as folder:
            root = write_workspace(Path(folder), robots)
            _measure(root, Path(folder), args.repeat,
                     f"{robots} robots, {robots * NODES_PER_ROBOT + FLEET_NODES} nodes")
    return 0


if __name__ == "__main__":
    sys.exit(main())
