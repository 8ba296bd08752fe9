"""Benchmark ``launchverify check`` on the generated workspace.

Generates ``bench/generated`` when it is missing or was generated with other settings,
then runs ``launchverify check bench/generated --format json`` (the launchverify installed
next to the running Python) once to warm up and ``--repeat`` times measured, and prints
files checked, findings by code, wall seconds (min/median/max), CPU seconds, seconds per
file, the peak resident memory of the child processes and the load average (the numbers
mean little on a busy machine).

    .venv/bin/python bench/run.py [--files 500] [--repeat 5] [--jobs N]
        [--launchverify OTHER/bin/launchverify]   # e.g. an older version, to compare
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import resource
import statistics
import subprocess
import sys
import time
from collections import Counter
from pathlib import Path
from typing import Any

from generate import DEFAULT_OUT, generate, is_current

REPO = Path(__file__).resolve().parent.parent
LAUNCHVERIFY = Path(sys.executable).parent / "launchverify"


def children_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def run_once(program: Path, target: Path, jobs: int | None = None
             ) -> tuple[float, float, dict[str, Any]]:
    """Run one check; return its wall time, its CPU time and its JSON report.

    CPU time counts every process of the check (workers and their zygote included).
    """
    cpu = children_cpu()
    started = time.perf_counter()
    done = subprocess.run(
        [str(program), "check", str(target), "--format", "json", "--no-cache",
         *(["--jobs", str(jobs)] if jobs else [])],
        cwd=REPO, capture_output=True, text=True, check=False,
    )
    wall = time.perf_counter() - started
    if done.returncode not in (0, 1):  # 1 only means error-level findings
        sys.exit(f"launchverify failed (exit {done.returncode}):\n{done.stderr}")
    return wall, children_cpu() - cpu, json.loads(done.stdout)


def startup_seconds(program: Path, repeat: int) -> str:
    """Return the median time of ``launchverify --version`` (interpreter and imports)."""
    times = []
    for _ in range(repeat):
        started = time.perf_counter()
        done = subprocess.run([str(program), "--version"], capture_output=True,
                              check=False)
        if done.returncode != 0:
            return "n/a (launchverify --version failed)"
        times.append(time.perf_counter() - started)
    return f"{statistics.median(times):.3f}"


def code_version(program: Path) -> str:
    """Return the launchverify version and the git commit it runs from (``+dirty``)."""
    version = subprocess.run([str(program), "--version"], capture_output=True,
                             text=True, check=False).stdout.strip()
    try:
        commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=REPO,
                                capture_output=True, text=True, check=True).stdout.strip()
        dirty = subprocess.run(
            ["git", "status", "--porcelain", "--untracked-files=no", "--", "verifier",
             "rules", "models"], cwd=REPO, capture_output=True, text=True, check=True,
        ).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return version
    return f"{version} at {commit}{'+dirty' if dirty else ''}"


def display(path: Path) -> str:
    try:
        return str(path.resolve().relative_to(REPO))
    except ValueError:
        return str(path)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--files", type=int, default=500, help="launch files (default 500)")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--repeat", type=int, default=5, help="measured runs (default 5)")
    parser.add_argument("--warmup", type=int, default=1, help="unmeasured runs first")
    parser.add_argument("--out", type=Path, default=DEFAULT_OUT, help="generated tree")
    parser.add_argument("--regenerate", action="store_true", help="generate even if current")
    parser.add_argument("--jobs", type=int, help="passed as --jobs (default: launchverify's)")
    parser.add_argument("--launchverify", type=Path, help="the launchverify to run (default: "
                        "the one next to this Python)")
    args = parser.parse_args(argv)
    program = args.launchverify.absolute() if args.launchverify else LAUNCHVERIFY
    if not program.exists():
        sys.exit(f"no launchverify at {program}")
    if args.repeat < 1:
        parser.error("--repeat must be at least 1")

    out = args.out.resolve()
    if args.regenerate or not is_current(out, args.files, args.seed):
        started = time.perf_counter()
        generate(out, args.files, args.seed)
        print(f"generated {args.files} launch files in {display(out)} "
              f"({time.perf_counter() - started:.1f} s)")
    target = Path(display(out))

    load_before = os.getloadavg()[0]
    for _ in range(args.warmup):
        run_once(program, target, args.jobs)
    walls: list[float] = []
    cpus: list[float] = []
    reported: list[float] = []
    report: dict[str, Any] = {}
    for _ in range(args.repeat):
        wall, cpu, report = run_once(program, target, args.jobs)
        walls.append(wall)
        cpus.append(cpu)
        reported.append(report["summary"]["seconds"])
    load_after = os.getloadavg()[0]
    peak_kib = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss  # KiB on Linux
    startup = startup_seconds(program, 3)

    files = report["summary"]["files"]
    codes = Counter(f["code"] for f in report["findings"])
    median = statistics.median(walls)
    rows = [
        ("launch files checked", f"{files}"),
        ("findings", ", ".join(f"{c}: {n}" for c, n in sorted(codes.items())) or "none"),
        ("wall seconds min/median/max",
         f"{min(walls):.3f} / {median:.3f} / {max(walls):.3f}"),
        ("CPU seconds (median, user+sys)", f"{statistics.median(cpus):.3f}"),
        ("reported seconds (median)", f"{statistics.median(reported):.3f}"),
        ("seconds per file (median wall)", f"{median / max(files, 1):.5f}"),
        ("start-up (launchverify --version)", startup),
        ("peak RSS of a child", f"{peak_kib / 1024:.1f} MiB"),
    ]
    print(f"\nlaunchverify check {target} --format json: {args.repeat} runs "
          f"after {args.warmup} warm-up; seed {args.seed}, {os.cpu_count()} CPUs, "
          f"Python {platform.python_version()}, "
          f"{code_version(program) if program == LAUNCHVERIFY else program}"
          f"{f', --jobs {args.jobs}' if args.jobs else ''}")
    rows.append(("load average before/after", f"{load_before:.2f} / {load_after:.2f}"))
    width = max(len(name) for name, _ in rows)
    for name, value in rows:
        print(f"  {name:<{width}}  {value}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
