"""Where launchverify runs besides the terminal: ament/colcon tests and pre-commit."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from launchverify.ament import main_with_errors

ROOT = Path(__file__).resolve().parent.parent
PACKAGE_XML = """<?xml version="1.0"?>
<package format="3">
  <name>robot_bringup</name>
  <version>0.1.0</version>
  <description>Bring-up</description>
  <maintainer email="dev@example.com">dev</maintainer>
  <license>Apache-2.0</license>
  <export><build_type>ament_python</build_type></export>
</package>
"""
DUPLICATE = """<launch>
  <node pkg="demo_nodes_cpp" exec="talker" name="talker"/>
  <node pkg="demo_nodes_cpp" exec="listener" name="talker"/>
</launch>
"""
CLEAN = """<launch>
  <node pkg="demo_nodes_cpp" exec="talker" name="talker"/>
</launch>
"""


@pytest.fixture
def package(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    root = tmp_path / "robot_bringup"
    (root / "launch").mkdir(parents=True)
    (root / "test").mkdir()
    (root / "package.xml").write_text(PACKAGE_XML)
    (root / "launch" / "bad.launch.xml").write_text(DUPLICATE)
    (root / "launch" / "good.launch.xml").write_text(CLEAN)
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)
    monkeypatch.delenv("AMENT_LINT_AUTO_FILE_EXCLUDE", raising=False)
    monkeypatch.chdir(root / "test")  # where a package's linter tests run
    return root


def test_main_with_errors_checks_the_package_it_runs_in(package: Path) -> None:
    rc, errors = main_with_errors(argv=[])
    assert rc == 1
    assert len(errors) == 1 and "LV101 [duplicate-node-name]" in errors[0]
    assert "bad.launch.xml:3:3" in errors[0]


def test_a_broken_configuration_fails_the_test_with_its_place(package: Path) -> None:
    (package / "launchverify.toml").write_text('selct = ["LV1"]\n')
    rc, errors = main_with_errors(argv=[])
    assert rc == 2
    assert len(errors) == 1 and "launchverify.toml:1" in errors[0] and "select" in errors[0]


def test_ament_exclude_list_is_honoured(package: Path,
                                        monkeypatch: pytest.MonkeyPatch) -> None:
    excluded = package / "launch" / "bad.launch.xml"
    monkeypatch.setenv("AMENT_LINT_AUTO_FILE_EXCLUDE", f"{excluded};/nonexistent/x.xml")
    assert main_with_errors(argv=[]) == (0, [])


def test_xunit_file_is_what_colcon_test_result_reads(package: Path, tmp_path: Path) -> None:
    result = tmp_path / "launchverify.xunit.xml"
    rc, _ = main_with_errors(argv=[str(package / "launch"), "--xunit-file", str(result)])
    assert rc == 1
    root = ET.parse(result).getroot()
    suites = [root] if root.tag == "testsuite" else list(root.iter("testsuite"))
    # colcon test-result sums these attributes over every testsuite
    assert sum(int(s.get("tests", 0)) for s in suites) == 2
    assert sum(int(s.get("failures", 0)) for s in suites) == 1
    cases = {c.get("name", ""): c for c in root.iter("testcase")}
    bad = next(c for name, c in cases.items() if name.endswith("bad.launch.xml"))
    assert bad.find("failure") is not None


def test_the_cli_writes_the_xunit_file_too(package: Path, tmp_path: Path) -> None:
    from launchverify.cli import main

    result = tmp_path / "x.xml"
    assert main(["check", str(package), "-q", "--xunit-file", str(result)]) == 1
    assert ET.parse(result).getroot().iter("testcase")


def test_pytest_marker_is_registered_for_strict_runs(package: Path) -> None:
    (package / "test" / "test_launchverify.py").write_text("""
import pytest
from launchverify.ament import main_with_errors


@pytest.mark.launchverify
def test_launchverify():
    rc, errors = main_with_errors(argv=[])
    assert rc == 1, errors
""")
    done = subprocess.run(
        [sys.executable, "-m", "pytest", "--strict-markers", "-q", "-p", "no:cacheprovider",
         "-m", "launchverify", "test_launchverify.py"],
        cwd=package / "test", capture_output=True, text=True, timeout=120, check=False)
    assert done.returncode == 0, done.stdout + done.stderr
    assert "1 passed" in done.stdout


def _git(cwd: Path, *argv: str) -> None:
    subprocess.run(["git", *argv], cwd=cwd, check=True, capture_output=True, timeout=60,
                   env={**os.environ, "GIT_AUTHOR_NAME": "t", "GIT_AUTHOR_EMAIL": "t@x",
                        "GIT_COMMITTER_NAME": "t", "GIT_COMMITTER_EMAIL": "t@x"})


@pytest.fixture(scope="module")
def pre_commit_hook(tmp_path_factory: pytest.TempPathFactory) -> tuple[list[str], dict[str, str]]:
    """Return the pre-commit command running this tree's hook, and the environment to run
    it in.

    The command is what ``pre-commit try-repo REPO launchverify`` runs (a configuration
    naming the repository's commit and the hook), with a store shared by the tests:
    try-repo makes a store of its own each time, and so installs launchverify anew each
    time (about 30 s); here pre-commit installs it once.
    """
    pre_commit = shutil.which("pre-commit", path=str(Path(sys.executable).parent))
    if pre_commit is None:
        pytest.skip("pre-commit is not installed (pip install -e '.[test]')")
    tmp_path = tmp_path_factory.mktemp("pre-commit")
    hooks = tmp_path / "hooks"
    for name in ("pyproject.toml", "README.md", "LICENSE", ".pre-commit-hooks.yaml"):
        if (ROOT / name).exists():
            shutil.copy(ROOT / name, hooks / name) if hooks.exists() else (
                hooks.mkdir(), shutil.copy(ROOT / name, hooks / name))
    for folder in ("verifier", "rules", "models"):
        shutil.copytree(ROOT / folder, hooks / folder,
                        ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
    _git(hooks, "init", "-q")
    _git(hooks, "add", ".")
    _git(hooks, "commit", "-q", "-m", "hooks")
    commit = subprocess.run(["git", "rev-parse", "HEAD"], cwd=hooks, check=True,
                            capture_output=True, text=True, timeout=60).stdout.strip()
    config = tmp_path / "pre-commit-config.yaml"  # outside the checked repositories
    config.write_text(f"repos:\n- repo: {hooks}\n  rev: {commit}\n"
                      "  hooks:\n  - id: launchverify\n")
    env = {**os.environ, "PRE_COMMIT_HOME": str(tmp_path / "cache"),
           "PIP_DISABLE_PIP_VERSION_CHECK": "1"}
    env.pop("AMENT_PREFIX_PATH", None)
    return [pre_commit, "run", "--config", str(config)], env


def test_pre_commit_hook_end_to_end(
        tmp_path: Path, pre_commit_hook: tuple[list[str], dict[str, str]]) -> None:
    """pre-commit installs launchverify from this tree and runs the hook."""
    pre_commit, env = pre_commit_hook
    work = tmp_path / "work"
    (work / "launch").mkdir(parents=True)
    (work / "launch" / "bad.launch.xml").write_text(DUPLICATE)
    (work / "launch" / "good.launch.xml").write_text(CLEAN)
    (work / "notes.xml").write_text("<notes/>")
    _git(work, "init", "-q")
    _git(work, "add", ".")
    done = subprocess.run([*pre_commit, "--all-files"],
                          cwd=work, capture_output=True, text=True, timeout=600, env=env,
                          check=False)
    output = done.stdout + done.stderr
    assert done.returncode == 1, output
    assert "LV101 [duplicate-node-name]" in output and "bad.launch.xml:3:3" in output
    (work / "launch" / "bad.launch.xml").write_text(CLEAN.replace("talker\"/>",
                                                                  "other\"/>"))
    done = subprocess.run([*pre_commit, "--all-files"],
                          cwd=work, capture_output=True, text=True, timeout=600, env=env,
                          check=False)
    assert done.returncode == 0, done.stdout + done.stderr
    # A change that breaks a file it does not touch: the included file now requires an
    # argument its includer does not pass. Only the included file is staged.
    (work / "launch" / "top.launch.xml").write_text(
        '<launch>\n  <include file="$(dirname)/part.launch.xml"/>\n</launch>\n')
    (work / "launch" / "part.launch.xml").write_text(CLEAN.replace("talker\"/>", "part\"/>"))
    _git(work, "add", ".")
    _git(work, "commit", "-q", "-m", "tree")
    (work / "launch" / "part.launch.xml").write_text(CLEAN.replace(
        "<launch>", '<launch>\n  <arg name="robot"/>').replace("talker\"/>",
                                                              'part" args="$(var robot)"/>'))
    _git(work, "add", "launch/part.launch.xml")
    done = subprocess.run(pre_commit,
                          cwd=work, capture_output=True, text=True, timeout=600, env=env,
                          check=False)
    output = done.stdout + done.stderr
    assert done.returncode == 1, output
    assert "top.launch.xml:2:3: error LV208" in output, output


DUPLICATE_YAML = """launch:
- node: {pkg: demo_nodes_cpp, exec: talker, name: talker}
- node: {pkg: demo_nodes_cpp, exec: listener, name: talker}
"""


def test_pre_commit_passes_committed_names_as_paths_never_as_options(
        tmp_path: Path, pre_commit_hook: tuple[list[str], dict[str, str]]) -> None:
    """Files named like options reach the hook as files: the hook fails on their mistakes
    and writes nothing (without the entry's ``--``, it passed on 0 files and wrote one)."""
    pre_commit, env = pre_commit_hook
    work = tmp_path / "work"
    work.mkdir()
    (work / "--exclude=*launch.xml").write_text(DUPLICATE)
    (work / "--output=x.launch.yaml").write_text(DUPLICATE_YAML)
    (work / "robot:=x.launch.xml").write_text(DUPLICATE)  # a path, not a launch argument
    _git(work, "init", "-q")
    _git(work, "add", "--", ".")
    done = subprocess.run([*pre_commit, "--all-files"],
                          cwd=work, capture_output=True, text=True, timeout=600, env=env,
                          check=False)
    output = done.stdout + done.stderr
    assert done.returncode == 1, output
    for name in ("--exclude=*launch.xml:3:3", "--output=x.launch.yaml:3:3",
                 "robot:=x.launch.xml:3:3"):
        assert f"{name}: error LV101 [duplicate-node-name]" in output, output
    assert not (work / "x.launch.yaml").exists()
    assert {p.name for p in work.iterdir()} == {
        ".git", "--exclude=*launch.xml", "--output=x.launch.yaml", "robot:=x.launch.xml"}


def test_affected_launch_files_are_what_a_change_may_break(tmp_path: Path) -> None:
    """Includers of a changed launch file, users of a changed parameter file, a package's
    launch files for its package.xml; transitively up the includes."""
    from launchverify.workspace.affected import affected_launch_files
    from launchverify.workspace.includers import Includers

    package = tmp_path / "src" / "bot"
    (package / "launch").mkdir(parents=True)
    (package / "config").mkdir()
    (package / "package.xml").write_text("<package><name>bot</name></package>")
    (package / "config" / "params.yaml").write_text("talker:\n  ros__parameters: {}\n")
    files = {
        "top.launch.xml": '<launch><include file="$(find-pkg-share bot)/launch/'
                          'robot.launch.xml"/></launch>',
        "robot.launch.xml": '<launch><node pkg="a" exec="b" name="talker"><param '
                            'from="$(find-pkg-share bot)/config/params.yaml"/></node></launch>',
        "other.launch.xml": '<launch><node pkg="a" exec="b" name="other"/></launch>',
    }
    for name, text in files.items():
        (package / "launch" / name).write_text(text)

    def names(*changed: Path) -> list[str]:
        includers = Includers.of_workspace([tmp_path])
        return [p.name for p in affected_launch_files(changed, includers)]

    assert names(package / "config" / "params.yaml") == ["robot.launch.xml", "top.launch.xml"]
    assert names(package / "launch" / "robot.launch.xml") == ["robot.launch.xml",
                                                              "top.launch.xml"]
    assert names(package / "launch" / "top.launch.xml") == ["top.launch.xml"]
    assert names(package / "package.xml") == sorted(files)
    assert names(tmp_path / "README.md") == []


def test_launch_files_only_skips_given_files_that_are_not_launch_files(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """pre-commit passes every name matching its pattern, launch tests included."""
    from launchverify.cli import main

    test = tmp_path / "test_talker_launch.py"
    test.write_text("def generate_test_description():\n    return None\n")
    launch = tmp_path / "bad.launch.xml"
    launch.write_text(DUPLICATE)
    assert main(["check", str(test), "--format", "json"]) == 1  # LV001: no entry point
    capsys.readouterr()
    assert main(["check", str(test), str(launch), "--launch-files-only", "-q"]) == 1
    out = capsys.readouterr().out
    assert "LV101" in out and "LV001" not in out


def test_includers_scan_rereads_what_changed(tmp_path: Path,
                                             monkeypatch: pytest.MonkeyPatch) -> None:
    """A long-lived process remembers each file's names by its stamp: an edited file, or
    an editor's unsaved buffer, is read again."""
    import os

    from launchverify.workspace import includers as scan
    from launchverify.workspace.reading import unsaved_buffers

    launch = tmp_path / "launch"
    launch.mkdir()
    top, part = launch / "top.launch.xml", launch / "part.launch.xml"
    part.write_text("<launch/>")
    top.write_text('<launch><include file="$(dirname)/part.launch.xml"/></launch>')
    old = 1_000_000_000
    for path in (top, part):
        os.utime(path, ns=(old, old))  # not racy: remembered
    assert scan.Includers.of_workspace([tmp_path]).included(part)
    assert str(top) in scan._REMEMBERED
    monkeypatch.setattr(scan, "read_file", lambda *a, **k: pytest.fail("read again"))
    assert scan.Includers.of_workspace([tmp_path]).included(part)  # from memory
    monkeypatch.undo()
    top.write_text("<launch/>")  # another size: read again
    os.utime(top, ns=(old, old))
    assert not scan.Includers.of_workspace([tmp_path]).included(part)
    with unsaved_buffers({top: b'<launch><include file="part.launch.xml"/></launch>'}):
        assert scan.Includers.of_workspace([tmp_path]).included(part)
