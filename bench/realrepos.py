"""Time launchverify on real repositories against the real launch library.

The repositories come from the real-world corpus that ``../shared/realworld`` builds
(``extract_corpus.py``: the launch files, packages and configuration of 41 public
repositories laid out like a workspace; never committed). For each repository asked for,
this runs

- ``launchverify check REPO --workspace CORPUS`` with no cache (cold), then twice with a
  cache folder of its own (the second run is the warm one), and reports wall seconds and
  the peak resident memory of the process tree;
- when the oracle's environment is set (``ORACLE``, ``ORACLE_PY``, ``ORACLE_PYTHONPATH``,
  ``ORACLE_HELPER_PACKAGE_PATH``, as ``../shared/oracle/README.md`` assembles it), the real
  launch library on the same repository's launch files, one process per file as
  ``ros2 launch`` would run them (``run_oracle.py --jobs 1``), and the ratio.

    python bench/realrepos.py --corpus /tmp/lv-corpus \\
        --repo ros-navigation/navigation2 --repo autowarefoundation/autoware_launch
    python bench/realrepos.py --corpus /tmp/lv-corpus --against /tmp/old/bin/launchverify
    python bench/realrepos.py --corpus /tmp/lv-corpus --min-files 20 --repeat 1
    python bench/realrepos.py --corpus /tmp/lv-corpus --startup --repeat 20
    python bench/realrepos.py --corpus /tmp/lv-corpus --whole --repeat 1

The commit of each repository is printed from the corpus manifest, so figures can be
compared between runs. Standard library only.
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

DEFAULT_REPOS = ("ros-navigation/navigation2", "autowarefoundation/autoware_launch")


def launchverify() -> list[str]:
    """Return the command of the launchverify next to the running Python."""
    found = Path(sys.executable).with_name("launchverify")
    return [str(found)] if found.exists() else [sys.executable, "-m", "launchverify"]


def timed(command: list[str], env: dict[str, str] | None = None) -> tuple[float, int]:
    """Run a command; return wall seconds and the peak RSS (MB) of its process tree."""
    wrapper = [sys.executable, "-c", _MEASURE, *command]
    started = time.perf_counter()
    done = subprocess.run(wrapper, env=env, capture_output=True, text=True, check=False)
    seconds = time.perf_counter() - started
    if done.returncode not in (0, 1):
        raise SystemExit(f"failed ({done.returncode}): {' '.join(command)}\n{done.stderr}")
    peak = int(done.stderr.strip().splitlines()[-1])
    return seconds, peak


# Runs the command as a child and prints the largest resident size among its descendants
# (ru_maxrss of RUSAGE_CHILDREN: the largest single process, in kB on Linux).
_MEASURE = """
import resource, subprocess, sys
code = subprocess.run(sys.argv[1:], stdout=subprocess.DEVNULL).returncode
print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss // 1024, file=sys.stderr)
sys.exit(code)
"""


def check_times(corpus: Path, folder: Path, repeat: int,
                against: list[str] | None = None) -> dict[str, object]:
    """Time cold and warm checks of one repository folder.

    ``against``: another launchverify, whose cold checks alternate with ours round by
    round, so that both see the machine in the same state.
    """
    arguments = ["check", str(folder), "--workspace", str(corpus),
                 "--format", "json", "--exit-zero", "-q"]
    base = [*launchverify(), *arguments]
    # as installed: with PYTHONDONTWRITEBYTECODE set, an editable install (the checkout)
    # compiled every module again on every run
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    cold, other = [], []
    for _ in range(repeat):
        cold.append(timed([*base, "--no-cache"], env))
        if against is not None:
            other.append(timed([*against, *arguments, "--no-cache"], env))
    cache = Path(tempfile.mkdtemp(prefix="lv-bench-cache-"))
    try:
        warm = []
        for _ in range(repeat):
            shutil.rmtree(cache, ignore_errors=True)
            timed([*base, "--cache-dir", str(cache)], env)  # fills the cache
            warm.append(timed([*base, "--cache-dir", str(cache)], env))
    finally:
        shutil.rmtree(cache, ignore_errors=True)
    out = subprocess.run([*base, "--no-cache"], capture_output=True, text=True, check=False)
    summary = json.loads(out.stdout)["summary"]
    return {
        "files": summary["files"],
        "cold": statistics.median(s for s, _ in cold),
        "against": statistics.median(s for s, _ in other) if other else None,
        "warm": statistics.median(s for s, _ in warm),
        "peak_mb": max(m for _, m in cold),
    }


_ONE_XML = """<launch>
  <arg name="robot" default="r1"/>
  <group>
    <push_ros_namespace namespace="$(var robot)"/>
    <node pkg="demo_nodes_cpp" exec="talker" name="talker"/>
    <node pkg="demo_nodes_cpp" exec="listener" name="listener"/>
  </group>
</launch>
"""
_ONE_PY = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('robot', default_value='r1'),
        Node(package='demo_nodes_cpp', executable='talker',
             namespace=LaunchConfiguration('robot')),
    ])
"""


def startup_times(repeat: int) -> dict[str, float]:
    """Time ``--version`` and one-file checks (XML, Python), alternating, in a small workspace.

    The workspace is one package with the two files (written here); medians of
    ``repeat`` rounds after one warm-up round (bytecode and caches as a user has them).
    """
    workspace = Path(tempfile.mkdtemp(prefix="lv-bench-startup-"))
    try:
        package = workspace / "src" / "demo"
        (package / "launch").mkdir(parents=True)
        (package / "package.xml").write_text(
            '<package format="3"><name>demo</name><version>0.0.0</version>'
            "<description>d</description><maintainer email='a@b.c'>a</maintainer>"
            "<license>MIT</license></package>\n")
        (package / "launch" / "one.launch.xml").write_text(_ONE_XML)
        (package / "launch" / "one.launch.py").write_text(_ONE_PY)
        env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
        commands = {
            "version": [*launchverify(), "--version"],
            "xml": [*launchverify(), "check", str(package / "launch" / "one.launch.xml"),
                    "--workspace", str(workspace), "--no-cache", "-q", "--exit-zero"],
            "python": [*launchverify(), "check", str(package / "launch" / "one.launch.py"),
                       "--workspace", str(workspace), "--no-cache", "-q", "--exit-zero"],
        }
        seconds: dict[str, list[float]] = {name: [] for name in commands}
        for round_ in range(repeat + 1):
            for name, command in commands.items():
                started = time.perf_counter()
                subprocess.run(command, env=env, stdout=subprocess.DEVNULL, check=False)
                if round_:  # the first round warms up
                    seconds[name].append(time.perf_counter() - started)
        return {name: statistics.median(values) for name, values in seconds.items()}
    finally:
        shutil.rmtree(workspace, ignore_errors=True)


def oracle_seconds(corpus: Path, repo: str | None) -> tuple[float, int] | None:
    """Time the real launch library over a repository's launch files, one process each.

    ``repo`` ``None``: over every launch file of the corpus.
    """
    needed = ("ORACLE", "ORACLE_PY", "ORACLE_PYTHONPATH")
    if any(name not in os.environ for name in needed):
        return None
    out = Path(tempfile.mkdtemp(prefix="lv-bench-oracle-")) / "results.jsonl"
    command = [sys.executable, str(Path(os.environ["ORACLE"]) / "run_oracle.py"),
               "--corpus", str(corpus), "--out", str(out), "--jobs", "1",
               *(["--repo", repo] if repo else ["--all"])]
    started = time.perf_counter()
    subprocess.run(command, capture_output=True, check=False,
                   env={**os.environ, "CORPUS": str(corpus)})
    seconds = time.perf_counter() - started
    files = sum(1 for _ in out.open()) if out.exists() else 0
    shutil.rmtree(out.parent, ignore_errors=True)
    return seconds, files


def largest(manifest: dict[str, object], at_least: int) -> list[str]:
    """Return the corpus's repositories with at least ``at_least`` launch files, largest first."""
    counts: dict[str, int] = {}
    launch_files = manifest.get("launch_files", [])
    for entry in launch_files if isinstance(launch_files, list) else []:
        if isinstance(entry, dict) and isinstance(entry.get("repo"), str):
            counts[entry["repo"]] = counts.get(entry["repo"], 0) + 1
    return sorted((r for r, n in counts.items() if n >= at_least),
                  key=lambda r: (-counts[r], r))


def whole(corpus: Path, repeat: int) -> int:
    """Print one cold check of the whole corpus against the real library over its files."""
    command = [*launchverify(), "check", str(corpus), "--workspace", str(corpus),
               "--format", "json", "--exit-zero", "-q", "--no-cache"]
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    ours, library = [], []
    for _ in range(repeat):
        ours.append(timed(command, env))
        found = oracle_seconds(corpus, None)
        if found is not None:
            library.append(found[0])
    seconds = statistics.median(s for s, _ in ours)
    peak = max(m for _, m in ours)
    print(f"whole corpus: launchverify {seconds:.2f} s cold (peak {peak} MB)", end="")
    if library:
        real = statistics.median(library)
        print(f", the real library {real:.1f} s: {real / seconds:.1f}x")
    else:
        print(" (no oracle environment: no ratio)")
    return 0


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--corpus", type=Path, required=True,
                        help="the corpus ../shared/realworld/extract_corpus.py built")
    parser.add_argument("--repo", action="append", metavar="OWNER/NAME",
                        help=f"a repository of the corpus (default: {', '.join(DEFAULT_REPOS)})")
    parser.add_argument("--min-files", type=int, metavar="N",
                        help="every repository of the corpus with at least N launch files, "
                             "largest first (instead of --repo)")
    parser.add_argument("--repeat", type=int, default=3, help="runs per figure (median)")
    parser.add_argument("--against", metavar="LAUNCHVERIFY",
                        help="another launchverify executable (an older install) to time "
                             "cold, alternating with this one")
    parser.add_argument("--startup", action="store_true",
                        help="only time one-file checks against `launchverify --version`")
    parser.add_argument("--whole", action="store_true",
                        help="only time one cold check of the whole corpus, against the "
                             "real library over every launch file (with the oracle's "
                             "environment), the two alternating")
    args = parser.parse_args()
    if args.whole:
        return whole(args.corpus, args.repeat)
    if args.startup:
        figures = startup_times(max(args.repeat, 10))
        base = figures["version"]
        for name, value in figures.items():
            print(f"{name:<8} {value:.3f} s  {value / base:.1f}x --version")
        return 0
    against = [args.against] if args.against else None
    manifest = json.loads((args.corpus / "manifest.json").read_text())
    commits = {r.get("repo", r.get("name")): r.get("commit", "?")
               for r in manifest.get("repos", []) if isinstance(r, dict)}
    print(f"{'repository':<42} {'files':>5} {'cold s':>7} {'warm s':>7} {'peak MB':>7} "
          f"{'oracle s':>8} {'ratio':>6}" + (f" {'against s':>9}" if against else ""))
    repos = args.repo or DEFAULT_REPOS
    if args.min_files is not None:
        repos = largest(manifest, args.min_files)
    for repo in repos:
        folder = args.corpus / repo.replace("/", "+")
        if not folder.is_dir():
            print(f"{repo}: not in the corpus", file=sys.stderr)
            continue
        figures = check_times(args.corpus, folder, args.repeat, against)
        oracle = oracle_seconds(args.corpus, repo)
        ratio = f"{oracle[0] / figures['cold']:.1f}x" if oracle else "-"
        print(f"{repo:<42} {figures['files']:>5} {figures['cold']:>7.2f} "
              f"{figures['warm']:>7.2f} {figures['peak_mb']:>7} "
              f"{(f'{oracle[0]:.1f}' if oracle else '-'):>8} {ratio:>6}"
              + (f" {figures['against']:>9.2f}" if against else "")
              + f"   commit {str(commits.get(repo, '?'))[:12]}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
