"""Re-checking after an edit, against checking cold the trees the edit reaches (issue 33).

For each repository: a copy is checked with a fresh result cache; then, one at a time, a
file some root read (a launch or parameter file, picked at random) is edited (a comment
added, a line removed or doubled) and the workspace is checked again with the cache. The
yardstick, measured in the same minutes: a cold check (``--no-cache``) of exactly the
roots that read the edited file. Each re-check's findings are compared with a cold check
of the whole workspace: they must be the same, one for one.

    python bench/incremental.py --corpus /tmp/lv-corpus [--repos NAME...] [--edits 6]
        [--seed 1]

Prints, per edit, the roots re-checked, seconds for the re-check and for the cold check
of those trees, their ratio (the issue's target: at most 2), and whether the findings
agree.
"""

from __future__ import annotations

import argparse
import json
import os
import pickle
import random
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

LAUNCHVERIFY = Path(sys.executable).parent / "launchverify"
DEFAULT_REPOS = ("ros-navigation+navigation2", "autowarefoundation+autoware_launch",
                 "ros-controls+ros2_control_demos")
SUFFIXES = (".py", ".xml", ".yaml", ".yml", ".launch")


def check(folder: Path, *paths: str, cache: Path | None = None) -> tuple[list[object], float]:
    """Return a check's findings and its wall seconds."""
    command = [str(LAUNCHVERIFY), "check", "--format", "json", "--exit-zero", *paths]
    command += ["--cache-dir", str(cache)] if cache is not None else ["--no-cache"]
    environment = dict(os.environ)
    environment.pop("PYTHONDONTWRITEBYTECODE", None)  # as users have it
    started = time.perf_counter()
    done = subprocess.run(command, cwd=folder, capture_output=True, text=True, check=False,
                          env=environment)
    seconds = time.perf_counter() - started
    return json.loads(done.stdout)["findings"], seconds


def roots_reading(cache: Path) -> dict[str, set[str]]:
    """Return, per file, the roots whose kept result says they read it."""
    stored = next(cache.glob("*.roots.pickle"))
    with stored.open("rb") as handle:
        kept = pickle.load(handle)  # our own cache, written by this run
    out: dict[str, set[str]] = {}
    for root, result in kept.roots.items():
        for path in result.reads or ():
            out.setdefault(path, set()).add(str(root))
    return out


def edit(path: Path, rng: random.Random) -> str:
    """Edit a file the way a user might; return what was done."""
    lines = path.read_text(errors="replace").splitlines(keepends=True)
    kind = rng.choice(["comment", "drop", "double"]) if len(lines) > 2 else "comment"
    if kind == "comment":
        lines.append("\n# edited\n" if path.suffix != ".xml" else "\n<!-- edited -->\n")
    elif kind == "drop":
        del lines[rng.randrange(len(lines))]
    else:
        at = rng.randrange(len(lines))
        lines.insert(at, lines[at])
    path.write_text("".join(lines))
    return kind


def measure(repo: Path, edits: int, rng: random.Random) -> list[float]:
    """Print each edit's figures for one repository; return the ratios."""
    work = Path(tempfile.mkdtemp(prefix="lv-bench-incremental-"))
    tree = work / repo.name
    shutil.copytree(repo, tree, symlinks=True)
    cache = work / "cache"
    try:
        _, cold_all = check(tree, ".", cache=cache)
        reading = roots_reading(cache)
        candidates = sorted(p for p in reading if p.startswith(str(tree) + "/")
                            and p.endswith(SUFFIXES) and Path(p).is_file())
        print(f"{repo.name}: whole workspace cold {cold_all:.2f} s, "
              f"{len(candidates)} files read by roots")
        ratios = []
        for _ in range(edits):
            target = Path(rng.choice(candidates))
            roots = sorted(reading.get(str(target), ()))
            kind = edit(target, rng)
            time.sleep(0.05)
            found, again = check(tree, ".", cache=cache)
            _, trees = check(tree, *roots)
            whole, _ = check(tree, ".")
            ratio = again / trees
            ratios.append(ratio)
            print(f"  {kind:7} {target.relative_to(tree)}: {len(roots)} roots, re-check "
                  f"{again:.2f} s, cold of those trees {trees:.2f} s, ratio {ratio:.2f}, "
                  f"{'same findings' if found == whole else 'FINDINGS DIFFER'}", flush=True)
            reading = roots_reading(cache)  # an edit may change what roots read
        return ratios
    finally:
        shutil.rmtree(work, ignore_errors=True)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--corpus", type=Path, required=True)
    parser.add_argument("--repos", nargs="+", default=list(DEFAULT_REPOS))
    parser.add_argument("--edits", type=int, default=6)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args(argv)
    rng = random.Random(args.seed)
    ratios = []
    for name in args.repos:
        ratios += measure(args.corpus / name, args.edits, rng)
    if ratios:
        print(f"ratio re-check / cold of the trees reached: median "
              f"{statistics.median(ratios):.2f}, max {max(ratios):.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
