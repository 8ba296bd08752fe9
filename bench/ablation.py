"""Ablation: take launchverify's knowledge away, one kind at a time; no error may appear.

What launchverify cannot see must be unknown, never an error. This harness checks that
principle on real repositories, as the team cannot wait for users to hit its breaches. For
each repository of the real-world corpus (``../shared/realworld``) it checks the
repository as usual (the baseline), then again with one kind of knowledge taken away:

- ``modules``: every module a launch file imports that is not launch, launch_ros or
  Python's own is absent (``LAUNCHVERIFY_ABLATE=modules``): vendor helpers, workspace
  packages, installed libraries, launchverify's models of other packages;
- ``packages``: every package outside the repository is removed from the workspace;
- ``environment``: the baseline gives every environment variable the launch files name a
  value (``--env``), the ablation gives none;
- ``includes``: every package that a launch file names from another package (what it
  includes, its parameter files' packages) is removed from the workspace.

An error-level finding in an ablated check that the baseline does not have (same code,
file and line) is an *added error*: a place where an unknown value became an error. It
may add infos, or lose findings; it may not add errors. Added errors are counted on the
launch files the real launch library evaluates cleanly (``--oracle``, as
``../shared/oracle/run_oracle.py`` writes them; roots and what they include), and shown
apart for the others. Temporary workspaces are hard-linked copies, so the corpus is never
changed.

    python bench/ablation.py --corpus /tmp/lv-corpus --oracle results.jsonl
    python bench/ablation.py --corpus /tmp/lv-corpus --oracle results.jsonl \\
        --repo ros-navigation/navigation2 --kinds modules,packages

Standard library only. Exit 1 when an ablation adds an error on an oracle-clean file.
"""

from __future__ import annotations

import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from collections.abc import Iterable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path

KINDS = ("modules", "packages", "environment", "includes")

# A package named in a launch file: $(find-pkg-share x), FindPackageShare('x'),
# get_package_share_directory('x'), $(find-pkg-prefix x), get_package_prefix('x').
_NAMED_PACKAGE = re.compile(
    r"""(?:find-pkg-(?:share|prefix)\s+|FindPackage(?:Share|Prefix)\(\s*(?:package\s*=\s*)?['"]|"""
    r"""get_package_(?:share_directory|prefix)\(\s*['"])([A-Za-z][A-Za-z0-9_]*)""")
# An environment variable a launch file reads.
_VARIABLE = re.compile(
    r"""(?:environ\s*\[\s*|environ\.get\(\s*|getenv\(\s*|EnvironmentVariable\(\s*(?:name\s*=\s*)?)"""
    r"""['"]([A-Za-z_][A-Za-z0-9_]*)['"]|\$\(env\s+([A-Za-z_][A-Za-z0-9_]*)""")
_LAUNCH_SUFFIXES = (".py", ".xml", ".yaml", ".yml")


def launchverify() -> list[str]:
    """Return the command of the launchverify next to the running Python."""
    found = Path(sys.executable).with_name("launchverify")
    return [str(found)] if found.exists() else [sys.executable, "-m", "launchverify"]


@dataclass(frozen=True)
class Finding:
    """An error-level finding, keyed by what does not depend on the workspace's place."""

    code: str
    file: str  # relative to the workspace
    line: int
    root: str  # the root whose check reached it (relative), or the file itself
    message: str

    @property
    def key(self) -> tuple[str, str, int]:
        return (self.code, self.file, self.line)


@dataclass
class Outcome:
    """What one ablation of one repository added."""

    repo: str
    kind: str
    seconds: float
    added: list[Finding] = field(default_factory=list)


def check(target: Path, workspace: Path, *, env: dict[str, str] | None = None,
          extra: Iterable[str] = ()) -> list[Finding]:
    """Check ``target`` in ``workspace``; return its error-level findings."""
    command = [*launchverify(), "check", str(target), "--workspace", str(workspace),
               "--format", "json", "--no-cache", "--exit-zero", *extra]
    done = subprocess.run(command, capture_output=True, text=True, check=False,
                          cwd=workspace, env={**os.environ, **(env or {})})
    if done.returncode == 2 and "no launch files found" in done.stderr:
        return []  # a package whose launch files are all ROS 1 ones, say
    if done.returncode != 0:
        raise SystemExit(f"failed ({done.returncode}): {' '.join(command)}\n{done.stderr}")
    found = []
    for item in json.loads(done.stdout)["findings"]:
        if item["severity"] != "error":
            continue
        file = _relative(item["file"], workspace)
        chain = item.get("include_chain") or []
        root = _relative(chain[0]["file"], workspace) if chain else file
        found.append(Finding(item["code"], file, int(item["line"]), root, item["message"]))
    return found


def _relative(name: str, workspace: Path) -> str:
    path = Path(name)
    path = path if path.is_absolute() else workspace / path
    try:
        return path.resolve().relative_to(workspace.resolve()).as_posix()
    except ValueError:
        return path.as_posix()


def launch_files(folder: Path) -> list[Path]:
    """Return the text files of a repository a launch file could be (for the scans)."""
    return [p for p in sorted(folder.rglob("*"))
            if p.is_file() and p.suffix in _LAUNCH_SUFFIXES and "launch" in p.as_posix()]


def named_packages(folder: Path) -> set[str]:
    """Return the packages the repository's launch files name by their share or prefix."""
    names: set[str] = set()
    for path in launch_files(folder):
        names.update(_NAMED_PACKAGE.findall(path.read_text(errors="replace")))
    return names


def named_variables(folder: Path) -> set[str]:
    """Return the environment variables the repository's launch files read."""
    names: set[str] = set()
    for path in launch_files(folder):
        for quoted, substituted in _VARIABLE.findall(path.read_text(errors="replace")):
            names.add(quoted or substituted)
    return names


def sample_value(name: str) -> str:
    """Return a value a robot's environment might give the variable."""
    upper = name.upper()
    if upper.endswith(("PATH", "DIR", "FILE", "HOME", "PREFIX")):
        return "/opt/robot"
    if upper.endswith(("ID", "NUM", "COUNT", "DOMAIN")):
        return "0"
    if upper.startswith(("USE_", "ENABLE")):
        return "false"
    return {"TURTLEBOT3_MODEL": "burger", "ROS_DISTRO": "jazzy", "USER": "robot",
            "LOGNAME": "robot"}.get(upper, "robot")


def packages_of(corpus: Path) -> dict[str, list[Path]]:
    """Return every package folder of the corpus (sources and install copies) by name."""
    found: dict[str, list[Path]] = {}
    for manifest in corpus.rglob("package.xml"):
        match = re.search(r"<name>\s*([^<\s]+)\s*</name>", manifest.read_text(errors="replace"))
        if match:
            found.setdefault(match.group(1), []).append(manifest.parent)
    return found


def linked_copy(source: Path, target: Path) -> None:
    """Copy a folder as hard links (nothing is written to the corpus)."""
    target.parent.mkdir(parents=True, exist_ok=True)
    shutil.copytree(source, target, copy_function=os.link, symlinks=True)


def ablate(corpus: Path, repo: str, kinds: list[str], scratch: Path,
           packages: dict[str, list[Path]]) -> tuple[list[Finding], list[Outcome]]:
    """Check one repository as usual and under each ablation; return what each added."""
    folder_name = repo.replace("/", "+")
    folder = corpus / folder_name
    installed = corpus / "_install" / folder_name
    baseline = check(folder, corpus)
    outcomes = []
    for kind in kinds:
        started = time.perf_counter()
        known = {f.key for f in baseline}
        if kind == "modules":
            found = check(folder, corpus, env={"LAUNCHVERIFY_ABLATE": "modules"})
        elif kind == "environment":
            # the known environment is the reference; the baseline knows none of it
            given = [f"--env={n}={sample_value(n)}" for n in sorted(named_variables(folder))]
            known = {f.key for f in check(folder, corpus, extra=given)}
            found = baseline
        elif kind == "packages":
            workspace = scratch / f"{folder_name}-packages"
            linked_copy(folder, workspace / folder_name)
            if installed.is_dir():
                linked_copy(installed, workspace / "_install" / folder_name)
            found = check(workspace / folder_name, workspace)
            shutil.rmtree(workspace)
        else:  # includes
            found = []
            workspace = scratch / f"{folder_name}-includes"
            linked_copy(corpus, workspace)
            for package, named in included_packages(folder, packages).items():
                own = workspace / package.relative_to(corpus)
                with set_aside(workspace, [workspace / place.relative_to(corpus)
                                           for name in named for place in packages[name]]):
                    found += check(own, workspace)
            shutil.rmtree(workspace)
        seconds = time.perf_counter() - started
        added = [f for f in found if f.key not in known]
        outcomes.append(Outcome(repo, kind, seconds, sorted(set(added), key=_order)))
    return baseline, outcomes


@contextmanager
def set_aside(workspace: Path, folders: list[Path]) -> Iterator[None]:
    """Move folders into a dot folder (which no walk enters) for a block, then back."""
    aside = workspace / ".ablated"
    moved = []
    for number, folder in enumerate(folders):
        if folder.is_dir():
            target = aside / str(number)
            target.parent.mkdir(exist_ok=True)
            folder.rename(target)
            moved.append((folder, target))
    try:
        yield
    finally:
        for folder, target in reversed(moved):
            target.rename(folder)


def included_packages(folder: Path, packages: dict[str, list[Path]]) -> dict[Path, set[str]]:
    """Return, for each package of ``folder``, the other packages its launch files name."""
    named: dict[Path, set[str]] = {}
    for manifest in sorted(folder.rglob("package.xml")):
        own = manifest.parent
        inner = {m.parent for m in own.rglob("package.xml")} - {own}
        names = set()
        for path in launch_files(own):
            if not any(path.is_relative_to(i) for i in inner):
                names.update(_NAMED_PACKAGE.findall(path.read_text(errors="replace")))
        names = {n for n in names if n in packages
                 and not any(own.is_relative_to(place) for place in packages[n])}
        if names:
            named[own] = names
    return named


def _order(finding: Finding) -> tuple[str, int, str]:
    return (finding.file, finding.line, finding.code)


def oracle_clean(results: Path) -> set[str]:
    """Return the launch files the real library evaluated cleanly (corpus-relative)."""
    clean: set[str] = set()
    for line in results.read_text().splitlines():
        entry = json.loads(line)
        if entry.get("status") == "ok" and not entry.get("errors"):
            clean.add(f"{entry['repo'].replace('/', '+')}/{entry['path']}")
    return clean


def on_clean(finding: Finding, clean: set[str], installed: dict[str, str]) -> bool:
    """Return whether a finding was reached from a file the real library evaluates."""
    return any(installed.get(name, name) in clean for name in (finding.root, finding.file))


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--corpus", type=Path, required=True,
                        help="the corpus ../shared/realworld/extract_corpus.py built")
    parser.add_argument("--oracle", type=Path, required=True,
                        help="the real library's results (../shared/oracle/run_oracle.py)")
    parser.add_argument("--repo", action="append", metavar="OWNER/NAME",
                        help="a repository of the corpus (default: all)")
    parser.add_argument("--kinds", default=",".join(KINDS),
                        help=f"comma-separated, of {', '.join(KINDS)} (default: all)")
    parser.add_argument("--json", type=Path, help="write every added error here")
    args = parser.parse_args()
    kinds = [k for k in args.kinds.split(",") if k]
    if unknown := set(kinds) - set(KINDS):
        parser.error(f"unknown kinds: {', '.join(sorted(unknown))}")
    corpus = args.corpus.resolve()
    manifest = json.loads((corpus / "manifest.json").read_text())
    repos = args.repo or sorted({e["repo"] for e in manifest["launch_files"]})
    installed = {e["install_path"]: f"{e['repo'].replace('/', '+')}/{e['path']}"
                 for e in manifest["launch_files"] if e.get("install_path")}
    clean = oracle_clean(args.oracle)
    packages = packages_of(corpus)
    totals = {kind: [0, 0] for kind in kinds}  # added on clean files, elsewhere
    report: list[dict[str, object]] = []
    baseline_errors = 0
    started = time.perf_counter()
    with tempfile.TemporaryDirectory(prefix="lv-ablation-") as scratch:
        for repo in repos:
            baseline, outcomes = ablate(corpus, repo, kinds, Path(scratch), packages)
            baseline_errors += len(baseline)
            for outcome in outcomes:
                for finding in outcome.added:
                    clean_file = on_clean(finding, clean, installed)
                    totals[outcome.kind][0 if clean_file else 1] += 1
                    mark = "ADDED" if clean_file else "added (not oracle-clean)"
                    print(f"{mark} [{outcome.kind}] {finding.file}:{finding.line} "
                          f"{finding.code} {finding.message[:160]}")
                    report.append({"repo": repo, "kind": outcome.kind, "code": finding.code,
                                   "file": finding.file, "line": finding.line,
                                   "root": finding.root, "message": finding.message,
                                   "oracle_clean": clean_file})
            summary = " ".join(f"{o.kind}={len(o.added)}" for o in outcomes)
            print(f"{repo:<50} baseline errors {len(baseline):>3}  {summary}", flush=True)
    clean_in_repos = sum(1 for name in clean if name.split("/")[0] in
                         {r.replace("/", "+") for r in repos})
    print(f"\n{len(repos)} repositories, {clean_in_repos} launch files the real library "
          f"evaluates cleanly, {baseline_errors} baseline errors, "
          f"{time.perf_counter() - started:.0f} s")
    for kind, (on, off) in totals.items():
        print(f"{kind:<12} added errors: {on} on oracle-clean files, {off} elsewhere")
    if args.json:
        args.json.write_text(json.dumps(report, indent=1) + "\n")
    return 1 if any(on for on, _ in totals.values()) else 0


if __name__ == "__main__":
    sys.exit(main())
