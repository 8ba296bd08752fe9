"""Re-checking after an edit: only the roots that read an edited file are checked again.

Each test checks a tree with the result cache, edits it, and compares the next check with
a check from scratch: the same findings, and only the roots that had to be evaluated
again were (``Report.graphs`` holds the roots evaluated by that check).
"""

from __future__ import annotations

import os
import random
import shutil
import time
from pathlib import Path

import pytest
from test_cache import PARAMS, ROBOT, TOP

from launchverify.engine import (
    DEFAULT_TIME_LIMIT,
    CheckOptions,
    Report,
    run_check,
    run_check_cached,
)
from launchverify.findings import cache
from launchverify.findings.cache import ResultCache

CORPUS = Path(__file__).resolve().parents[1] / "corpus"

ALONE = """<launch>
  <node pkg="demo_nodes_cpp" exec="listener" name="listener"/>
</launch>
"""
# Two launch files of one family: the stand-in declares what the real one uses.
REAL = """<launch>
  <arg name="robot_model" default="a"/>
  <arg name="sensor_model" default="b"/>
  <arg name="vehicle_id" default="c"/>
  <arg name="map_path" default="d"/>
  <node pkg="demo_nodes_cpp" exec="talker" name="real_{robot_model}_{sensor_model}">
    <param name="v" value="$(var vehicle_id)$(var map_path)$(var robot_model)$(var sensor_model)"/>
  </node>
</launch>
""".replace("{robot_model}", "$(var robot_model)").replace("{sensor_model}",
                                                             "$(var sensor_model)")
STAND_IN = """<launch>
  <arg name="robot_model" default="a"/>
  <arg name="sensor_model" default="b"/>
  <arg name="vehicle_id" default="c"/>
  <arg name="map_path" default="d"/>
  <node pkg="demo_nodes_cpp" exec="listener" name="dummy_$(var robot_model)"/>
</launch>
"""
# A Python launch file whose node names come from a YAML file it opens itself.
OPENER = '''import os
import yaml
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    with open(os.path.join(os.path.dirname(__file__), "robots.yaml")) as handle:
        names = yaml.safe_load(handle)["robots"]
    return LaunchDescription([Node(package="demo_nodes_cpp", executable="talker", name=n)
                              for n in names])
'''


@pytest.fixture
def tree(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    monkeypatch.delenv("LAUNCHVERIFY_NO_CACHE", raising=False)
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)
    monkeypatch.setattr(cache, "CLOCK_SLACK", 0.0)  # as test_cache: results kept
    root = tmp_path / "ws"
    root.mkdir()
    for name, text in (("top.launch.xml", TOP), ("robot.launch.xml", ROBOT),
                       ("params.yaml", PARAMS), ("alone.launch.xml", ALONE)):
        (root / name).write_text(text)
    return root


def _options(root: Path, time_limit: float = DEFAULT_TIME_LIMIT) -> CheckOptions:
    return CheckOptions(paths=[root], workspace=root, time_limit=time_limit)


def _findings(report: Report) -> list[tuple[object, ...]]:
    return [(f.code, str(f.span.file), f.span.line, f.span.column, f.message, f.severity)
            for f in report.findings]


def recheck(root: Path, store: ResultCache, time_limit: float = DEFAULT_TIME_LIMIT) -> set[str]:
    """Check with the cache; assert it finds what a check from scratch finds.

    Returns the names of the roots this check evaluated.
    """
    report = run_check_cached(_options(root, time_limit), store)
    time.sleep(0.02)  # what a test changes next gets a later time than the stamps
    assert _findings(report) == _findings(run_check(_options(root, time_limit)))
    return {graph.root.name for graph in report.graphs}


def test_an_edited_included_file_rechecks_only_its_includers(tree: Path, tmp_path: Path
                                                             ) -> None:
    store = ResultCache(tmp_path / "cache")
    assert recheck(tree, store) == {"top.launch.xml", "robot.launch.xml", "alone.launch.xml"}
    robot = tree / "robot.launch.xml"
    robot.write_text(ROBOT.replace('default="r1"', 'default="r2"'))
    assert recheck(tree, store) == {"top.launch.xml", "robot.launch.xml"}
    assert run_check_cached(_options(tree), store).cached  # and then nothing at all


def test_an_edited_parameter_file_rechecks_the_roots_that_load_it(tree: Path,
                                                                  tmp_path: Path) -> None:
    store = ResultCache(tmp_path / "cache")
    recheck(tree, store)
    (tree / "params.yaml").write_text(PARAMS.replace("talker:", "talkr:"))  # LV402 now
    assert recheck(tree, store) == {"top.launch.xml", "robot.launch.xml"}
    report = run_check_cached(_options(tree), store)
    assert {f.code for f in report.findings} >= {"LV402"}


def test_an_editor_saving_by_rename_keeps_the_other_roots(tree: Path, tmp_path: Path) -> None:
    store = ResultCache(tmp_path / "cache")
    recheck(tree, store)
    saved = tree / "robot.launch.xml.new"
    saved.write_text(ROBOT.replace('default="r1"', 'default="r3"'))
    saved.replace(tree / "robot.launch.xml")  # the folder's time changes, not its names
    assert recheck(tree, store) == {"top.launch.xml", "robot.launch.xml"}


def test_a_file_renamed_over_another_with_its_size_and_time_is_seen(
        tree: Path, tmp_path: Path) -> None:
    robot = tree / "robot.launch.xml"
    old = time.time_ns() - 60 * 10**9  # not racy: stamped by size and time alone
    os.utime(robot, ns=(old, old))
    store = ResultCache(tmp_path / "cache")
    recheck(tree, store)
    before = robot.stat()
    other = tree / "robot.launch.xml.new"
    other.write_text(ROBOT.replace('default="r1"', 'default="r9"'))  # the same size
    os.utime(other, ns=(before.st_atime_ns, before.st_mtime_ns))  # as `cp -p` keeps it
    other.replace(robot)
    assert recheck(tree, store) == {"top.launch.xml", "robot.launch.xml"}


def test_a_new_file_rechecks_everything(tree: Path, tmp_path: Path) -> None:
    store = ResultCache(tmp_path / "cache")
    recheck(tree, store)
    (tree / "notes.txt").write_text("what exists may decide an include\n")
    assert recheck(tree, store) == {"top.launch.xml", "robot.launch.xml", "alone.launch.xml"}


def test_a_file_no_root_read_rechecks_everything(tree: Path, tmp_path: Path) -> None:
    (tree / "notes.txt").write_text("a\n")
    store = ResultCache(tmp_path / "cache")
    recheck(tree, store)
    (tree / "notes.txt").write_text("b\n")  # who read it is not known: no root says so
    assert len(recheck(tree, store)) == 3


def test_an_interface_change_rechecks_the_family(tree: Path, tmp_path: Path) -> None:
    (tree / "sensing.launch.xml").write_text(REAL)
    (tree / "dummy_sensing.launch.xml").write_text(STAND_IN)
    store = ResultCache(tmp_path / "cache")
    recheck(tree, store)  # the stand-in's unused arguments are its family's: quiet
    # the real file stops using vehicle_id: the stand-in's declaration is unused now
    (tree / "sensing.launch.xml").write_text(REAL.replace("$(var vehicle_id)", ""))
    again = recheck(tree, store)
    assert {"sensing.launch.xml", "dummy_sensing.launch.xml"} <= again


def test_random_edits_of_a_corpus_tree_give_what_a_check_from_scratch_gives(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(cache, "CLOCK_SLACK", 0.0)
    root = tmp_path / "ws"
    # Without the corpus's endless loop: it takes the whole time limit in each of the ten
    # checks (most of this test's time), and a file that never ends has no result to keep
    shutil.copytree(CORPUS / "python", root, ignore=shutil.ignore_patterns("endless_loop"))
    store = ResultCache(tmp_path / "cache")
    recheck(root, store)
    files = sorted(p for p in root.rglob("*") if p.suffix in (".py", ".xml", ".yaml"))
    rng = random.Random(7)
    for _ in range(2):  # each edit is two checks of 100 trees (one cached, one fresh)
        path = rng.choice(files)
        lines = path.read_text().splitlines(keepends=True)
        if lines:
            del lines[rng.randrange(len(lines))]  # a line removed: often a finding more
        path.write_text("".join(lines))
        recheck(root, store)


def test_what_a_worker_says_it_read_is_bounded_and_confined(tmp_path: Path) -> None:
    """The list comes from the launch file's process: outside names are never looked at."""
    from launchverify.isolation.pool import MAX_READS, IsolatedPython
    from launchverify.workspace import reading
    from launchverify.workspace.packages import PackageIndex

    inside = tmp_path / "ws" / "robots.yaml"
    pool = IsolatedPython(PackageIndex(), tmp_path / "ws", readable=(str(tmp_path / "ws"),))
    reading.confine([tmp_path / "ws"])
    try:
        pool._note_reads(Path("a.py"), [str(inside), "/etc/shadow", "relative.yaml"])
        assert pool.reads(Path("a.py")) == {str(inside)}
        pool._note_reads(Path("b.py"), ["x"] * (MAX_READS + 1))
        pool._note_reads(Path("c.py"), {"not": "a list"})
        assert pool.reads(Path("b.py")) is None and pool.reads(Path("c.py")) is None
        pool._note_reads(Path("c.py"), [str(inside)])  # unknown stays unknown
        assert pool.reads(Path("c.py")) is None
    finally:
        reading.confine(None)
        pool.close()


IMPORTER = '''import os
import sys

from launch import LaunchDescription
from launch_ros.actions import Node

sys.path.append(os.path.dirname(__file__))
from fleet_names import NAMES  # noqa: E402


def generate_launch_description():
    return LaunchDescription([Node(package="demo_nodes_cpp", executable="talker", name=n)
                              for n in NAMES])
'''


@pytest.mark.parametrize(("launch", "data", "before", "after"), [
    (OPENER, "robots.yaml", "robots: [a, b]\n", "robots: [a, a]\n"),
    (IMPORTER, "fleet_names.py", "NAMES = ['a', 'b']\n", "NAMES = ['a', 'a']\n"),
], ids=["opened", "imported"])
def test_a_file_python_code_reads_is_read_by_its_root(
        tree: Path, tmp_path: Path, launch: str, data: str, before: str, after: str) -> None:
    (tree / "fleet.launch.py").write_text(launch)
    (tree / data).write_text(before)
    store = ResultCache(tmp_path / "cache")
    recheck(tree, store)
    (tree / data).write_text(after)  # LV101 now
    assert recheck(tree, store) == {"fleet.launch.py"}  # the others kept
    assert "LV101" in {f.code for f in run_check_cached(_options(tree), store).findings}


PART = """<launch>
  <arg name="flag" default="true"/>
  <node pkg="demo_nodes_cpp" exec="talker" name="talker" if="$(var flag)"/>
</launch>
"""
MIDDLE = """<launch>
  <arg name="g" default="true"/>
  <arg name="h" default="true"/>
  <group if="$(var g)">
    <include file="$(dirname)/part.xml">
      <arg name="flag" value="$(var h)"/>
    </include>
  </group>
</launch>
"""
PASSES = """<launch>
  <arg name="x" default="true"/>
  <arg name="y" default="true"/>
  <include file="$(dirname)/middle.xml">
    <arg name="g" value="$(var x)"/>
    <arg name="h" value="$(var {h})"/>
  </include>
  <node pkg="demo_nodes_cpp" exec="listener" name="listener" if="$(var y)"/>
</launch>
"""


def test_a_root_that_skipped_a_place_another_no_longer_settles_is_judged_again(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """LV206 asks every context: a_ shows the condition varying, so b_ skipped it.

    Where the node is reached in b_, its condition is what the group asks already; in
    a_ it is another argument, until a_ passes the same.
    """
    monkeypatch.setattr(cache, "CLOCK_SLACK", 0.0)
    root = tmp_path / "ws"
    root.mkdir()
    (root / "part.xml").write_text(PART)
    (root / "middle.xml").write_text(MIDDLE)
    (root / "a_settles.launch.xml").write_text(PASSES.format(h="y"))
    (root / "b_kept.launch.xml").write_text(PASSES.format(h="x"))
    store = ResultCache(tmp_path / "cache")
    recheck(root, store)
    (root / "a_settles.launch.xml").write_text(PASSES.format(h="x"))
    assert recheck(root, store) == {"a_settles.launch.xml", "b_kept.launch.xml"}
    assert "LV206" in {f.code for f in run_check_cached(_options(root), store).findings}


def test_what_the_rules_read_counts_for_every_root(tmp_path: Path) -> None:
    """Node sources the wiring rules read are no root's: an edit there checks all again."""
    root = tmp_path / "ws"
    shutil.copytree(CORPUS / "wiring" / "velocity_commands", root)
    report = run_check(CheckOptions(paths=[root], workspace=root, jobs=1), keep=True)
    assert report.kept is not None
    sources = {str(p) for p in (root / "base_wiring" / "src").glob("*.cpp")}
    assert sources & report.kept.other_reads
    read_by_roots = {p for result in report.kept.roots.values() for p in result.reads or ()}
    assert not sources & read_by_roots


def test_a_forked_process_says_what_its_rules_read(tmp_path: Path) -> None:
    """The rules shared out to a child read there: the child's reads reach the record."""
    from launchverify.engine import _isolated, dead
    from launchverify.parallel import fanout
    from launchverify.registry import all_rules
    from launchverify.rule import RuleContext
    from launchverify.workspace import reading
    from launchverify.workspace.packages import PackageIndex

    root = tmp_path / "ws"
    shutil.copytree(CORPUS / "wiring" / "velocity_commands", root)
    # graphs no node contract rule has seen (a graph keeps the views they build)
    graphs = run_check(CheckOptions(paths=[root], workspace=root, select=["LV101"])).graphs
    rules = list(all_rules())
    ctx = RuleContext(packages=PackageIndex.from_environment([root], []))
    run = fanout.RuleRun(graphs, rules, ctx, _isolated, dead)
    fanout._SHARED.update(run=run, pieces=fanout.pieces(run), counter=fanout.NextPiece(
        len(fanout.pieces(run))))
    recorded: set[str] = set()
    try:
        with reading.recording(recorded):
            *_, reads = fanout._child()
    finally:
        fanout._SHARED.clear()
    sources = {str(p) for p in (root / "base_wiring" / "src").glob("*.cpp")}
    assert sources & reads and not recorded  # (the parent notes them when they come back)
