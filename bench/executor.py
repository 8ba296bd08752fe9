"""Executor benchmark: how long ``launchverify run`` takes to bring N processes up and down.

Writes a launch file of N ``<executable>`` processes (``sh -c 'echo ready; exec sleep'``,
so the processes themselves cost next to nothing), runs ``launchverify run`` on it and
reads its output: the time to the first process started (verification, evaluation and
planning), to all N started, to all N ready (their first line printed), then sends
SIGINT and times the shutdown until launchverify exits.

    python bench/executor.py [--processes 10 100] [--repeat 3]
"""

from __future__ import annotations

import argparse
import signal
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

LAUNCHVERIFY = Path(sys.executable).parent / "launchverify"


def render(count: int) -> str:
    """Return a launch file of ``count`` processes."""
    lines = ["<launch>"]
    lines += [f'  <executable cmd="sh -c \'echo ready {i}; exec sleep 600\'" name="p{i}" '
              'output="screen"/>' for i in range(count)]
    lines.append("</launch>")
    return "\n".join(lines) + "\n"


def measure(path: Path, count: int, logs: Path) -> tuple[float, float, float, float]:
    """Return seconds to first start, all started, all ready, and shutdown."""
    started_at = time.perf_counter()
    child = subprocess.Popen([str(LAUNCHVERIFY), "run", str(path), "--log-dir", str(logs)],
                             stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    assert child.stdout is not None
    first = everyone = ready = 0.0
    started = readied = 0
    for line in child.stdout:
        now = time.perf_counter() - started_at
        if "process started with pid" in line:
            started += 1
            first = first or now
            if started == count:
                everyone = now
        elif "] ready " in line:
            readied += 1
            if readied == count:
                ready = now
                break
    stop = time.perf_counter()
    child.send_signal(signal.SIGINT)
    child.communicate(timeout=60)
    return first, everyone, ready, time.perf_counter() - stop


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--processes", type=int, nargs="+", default=[10, 100])
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    print("| processes | first started | all started | all ready | shutdown |")
    print("|---:|---:|---:|---:|---:|")
    for count in args.processes:
        with tempfile.TemporaryDirectory() as folder:
            path = Path(folder) / "bench.launch.xml"
            path.write_text(render(count))
            measure(path, count, Path(folder) / "logs")  # warm-up
            runs = [measure(path, count, Path(folder) / "logs") for _ in range(args.repeat)]
        medians = [statistics.median(run[i] for run in runs) for i in range(4)]
        print(f"| {count} | " + " | ".join(f"{m:.3f} s" for m in medians) + " |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
