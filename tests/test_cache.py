"""The result cache between runs: an unchanged tree is not checked again, a change is seen."""

from __future__ import annotations

import json
import time
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given
from hypothesis import strategies as st

from launchverify.cli import main
from launchverify.findings import cache

TOP = """<launch>
  <include file="$(dirname)/robot.launch.xml">
    <arg name="use_sim_time" value="true"/>
  </include>
</launch>
"""
ROBOT = """<launch>
  <arg name="robot" default="r1"/>
  <node pkg="demo_nodes_cpp" exec="talker" name="talker">
    <param from="$(dirname)/params.yaml"/>
    <param name="robot" value="$(var robot)"/>
  </node>
</launch>
"""
PARAMS = """talker:
  ros__parameters:
    rate: 10
"""


@pytest.fixture
def tree(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    monkeypatch.delenv("LAUNCHVERIFY_NO_CACHE", raising=False)
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    # files written a moment before a check are kept (a user's are seconds old): results
    # are stored or not by what happened during the check alone
    monkeypatch.setattr(cache, "CLOCK_SLACK", 0.0)
    root = tmp_path / "ws"
    root.mkdir()
    (root / "top.launch.xml").write_text(TOP)
    (root / "robot.launch.xml").write_text(ROBOT)
    (root / "params.yaml").write_text(PARAMS)
    return root


def check(capsys: pytest.CaptureFixture[str], root: Path, *extra: str) -> tuple[set[str], bool]:
    """Return the findings (code and line) and whether the report came from the cache."""
    main(["check", str(root), "--workspace", str(root), "--format", "json", "--exit-zero",
          *extra])
    document = json.loads(capsys.readouterr().out)
    codes = {f"{f['code']}:{Path(f['file']).name}:{f['line']}" for f in document["findings"]}
    # what a test changes next gets a later time than what this check stamped (the
    # clock's ticks are milliseconds; the slack that guards it is 0 in these tests)
    time.sleep(0.02)
    return codes, document["summary"].get("cached", False)


def test_unchanged_tree_is_read_from_the_cache(tree: Path,
                                               capsys: pytest.CaptureFixture[str]) -> None:
    first, cached = check(capsys, tree)
    assert first == {"LV204:top.launch.xml:3"} and not cached
    second, cached = check(capsys, tree)
    assert second == first and cached
    assert list((tree.parent / "cache" / "launchverify").glob("*.json"))


def test_an_edited_included_file_is_checked_again(tree: Path,
                                                  capsys: pytest.CaptureFixture[str]) -> None:
    check(capsys, tree)
    # at once, within the clock's resolution: the content hash tells
    (tree / "robot.launch.xml").write_text(ROBOT.replace('"robot"', '"use_sim_time"', 1)
                                           .replace("$(var robot)", "$(var use_sim_time)"))
    findings, cached = check(capsys, tree)
    assert not cached and "LV204:top.launch.xml:3" not in findings


def test_an_edited_parameter_file_of_the_same_size_is_seen(
        tree: Path, capsys: pytest.CaptureFixture[str]) -> None:
    check(capsys, tree)
    (tree / "params.yaml").write_text(PARAMS.replace("talker:", "talkex:"))
    findings, cached = check(capsys, tree)
    assert not cached and "LV402:params.yaml:1" in findings


def test_a_file_edited_while_the_check_runs_is_checked_again(
        tree: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch) -> None:
    """Saved after the check read it: what was checked is not what is there, so the result
    is not kept (stamped after the check, it would have matched the new content)."""
    import launchverify.engine as engine

    real = engine.run_check

    def edited_meanwhile(options: engine.CheckOptions, *args: Any, **kwargs: Any
                         ) -> engine.Report:
        report = real(options, *args, **kwargs)
        (tree / "params.yaml").write_text(PARAMS.replace("talker:", "talkex:"))
        return report

    monkeypatch.setattr(engine, "run_check", edited_meanwhile)
    findings, cached = check(capsys, tree)
    assert "LV402:params.yaml:1" not in findings and not cached
    monkeypatch.setattr(engine, "run_check", real)
    findings, cached = check(capsys, tree)
    assert not cached and "LV402:params.yaml:1" in findings


def test_a_file_removed_while_the_check_runs_is_checked_again(
        tree: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch) -> None:
    """A removed file leaves no stamp: its folder's time says the tree changed meanwhile."""
    import launchverify.engine as engine

    (tree / "extra.launch.xml").write_text(
        '<launch><node pkg="demo_nodes_cpp" exec="talker" name="a"/>'
        '<node pkg="demo_nodes_cpp" exec="talker" name="a"/></launch>\n')
    real = engine.run_check

    def removed_meanwhile(options: engine.CheckOptions, *args: Any, **kwargs: Any
                          ) -> engine.Report:
        report = real(options, *args, **kwargs)
        (tree / "extra.launch.xml").unlink()
        return report

    monkeypatch.setattr(engine, "run_check", removed_meanwhile)
    findings, cached = check(capsys, tree)
    assert "LV101:extra.launch.xml:1" in findings and not cached
    monkeypatch.setattr(engine, "run_check", real)
    findings, cached = check(capsys, tree)
    assert not cached and "LV101:extra.launch.xml:1" not in findings


def test_only_times_before_the_check_settle_a_result() -> None:
    """A time within the clock's slack of the start counts as during the check; a time in
    whole seconds (a file system without finer ones) within two seconds does too."""
    started = 1_000_000.0
    second = 1_000_000_000

    def settled_at(offset: float, whole: bool = False) -> bool:
        time_ns = int((started + offset) * second)
        time_ns -= time_ns % second if whole else -123  # (never whole when it should not be)
        return cache.settled({"f": (1, time_ns, None)}, started) and cache.settled(
            {}, started, {"folder": (1, 2, time_ns)})

    assert settled_at(-1.0)
    assert not settled_at(-cache.CLOCK_SLACK / 2)
    assert not settled_at(+0.5)
    assert not settled_at(-1.0, whole=True)
    assert settled_at(-cache.RACY_SECONDS - 1, whole=True)


def test_a_new_file_in_a_folder_below_is_seen(tree: Path,
                                              capsys: pytest.CaptureFixture[str]) -> None:
    """No folder is listed again: the folder's own time says a file came."""
    (tree / "launch").mkdir()
    (tree / "launch" / "a.launch.xml").write_text("<launch/>\n")
    check(capsys, tree)
    assert check(capsys, tree)[1]
    (tree / "launch" / "b.launch.xml").write_text(
        '<launch><node pkg="demo_nodes_cpp" exec="talker" name="a"/>'
        '<node pkg="demo_nodes_cpp" exec="talker" name="a"/></launch>\n')
    findings, cached = check(capsys, tree)
    assert not cached and "LV101:b.launch.xml:1" in findings


def test_a_removed_folder_is_seen(tree: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (tree / "doc" / "old").mkdir(parents=True)
    check(capsys, tree)
    assert check(capsys, tree)[1]
    (tree / "doc" / "old").rmdir()
    assert not check(capsys, tree)[1]


def test_what_happens_in_build_folders_keeps_the_result(
        tree: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """colcon's build, install and log folders are never walked: building changes nothing."""
    (tree / "build").mkdir()
    check(capsys, tree)
    (tree / "build" / "CMakeCache.txt").write_text("rebuilt")
    (tree / "build" / "pkg").mkdir()
    assert check(capsys, tree)[1]


def test_a_new_file_is_seen(tree: Path, capsys: pytest.CaptureFixture[str]) -> None:
    check(capsys, tree)
    (tree / "other.launch.xml").write_text(
        '<launch><node pkg="demo_nodes_cpp" exec="talker" name="a"/>'
        '<node pkg="demo_nodes_cpp" exec="talker" name="a"/></launch>\n')
    findings, cached = check(capsys, tree)
    assert not cached and "LV101:other.launch.xml:1" in findings


def test_a_removed_file_is_seen(tree: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (tree / "notes.txt").write_text("not read by the check, but below the workspace")
    check(capsys, tree)
    assert check(capsys, tree)[1]
    (tree / "notes.txt").unlink()
    assert not check(capsys, tree)[1]


def test_a_file_read_outside_the_workspace_is_followed(
        tree: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """A baseline (or an installed package's file) outside the walked folders counts."""
    baseline = tree.parent / "baseline.json"
    main(["check", str(tree), "--workspace", str(tree), "--write-baseline", str(baseline)])
    capsys.readouterr()
    assert check(capsys, tree, "--baseline", str(baseline)) == (set(), False)
    assert check(capsys, tree, "--baseline", str(baseline)) == (set(), True)
    recorded = json.loads(baseline.read_text())
    baseline.write_text(json.dumps({**recorded, "findings": []}))
    findings, cached = check(capsys, tree, "--baseline", str(baseline))
    assert not cached and findings == {"LV204:top.launch.xml:3"}


def test_other_options_are_another_result(tree: Path,
                                          capsys: pytest.CaptureFixture[str]) -> None:
    check(capsys, tree)
    findings, cached = check(capsys, tree, "--ignore", "LV204")
    assert not cached and not findings


def test_no_cache_neither_reads_nor_writes(tree: Path,
                                           capsys: pytest.CaptureFixture[str],
                                           monkeypatch: pytest.MonkeyPatch) -> None:
    check(capsys, tree, "--no-cache")
    assert not (tree.parent / "cache").exists()
    monkeypatch.setenv("LAUNCHVERIFY_NO_CACHE", "1")
    check(capsys, tree)
    assert not (tree.parent / "cache").exists()
    monkeypatch.delenv("LAUNCHVERIFY_NO_CACHE")
    check(capsys, tree)
    assert check(capsys, tree)[1]


def test_a_damaged_cache_is_recomputed(tree: Path, capsys: pytest.CaptureFixture[str]) -> None:
    elsewhere = tree.parent / "elsewhere"
    check(capsys, tree, "--cache-dir", str(elsewhere))
    for stored in elsewhere.glob("*.json"):
        stored.write_bytes(b"not a result")
    findings, cached = check(capsys, tree, "--cache-dir", str(elsewhere))
    assert findings == {"LV204:top.launch.xml:3"} and not cached
    assert check(capsys, tree, "--cache-dir", str(elsewhere))[1]


def test_a_cache_folder_inside_the_workspace_does_not_invalidate_itself(
        tree: Path, capsys: pytest.CaptureFixture[str]) -> None:
    inside = tree / "lvcache"
    check(capsys, tree, "--cache-dir", str(inside))
    assert check(capsys, tree, "--cache-dir", str(inside))[1]


def test_text_summary_says_the_result_is_cached(tree: Path,
                                                capsys: pytest.CaptureFixture[str]) -> None:
    main(["check", str(tree), "--workspace", str(tree), "--exit-zero"])
    capsys.readouterr()
    main(["check", str(tree), "--workspace", str(tree), "--exit-zero"])
    assert "unchanged since the cached run" in capsys.readouterr().out


def test_linked_folders_are_walked_once(tree: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """Links back to a parent, two per level, would make the walk exponential."""
    (tree / "a").mkdir()
    (tree / "a" / "up").symlink_to(tree)
    (tree / "a" / "again").symlink_to(tree)
    first, _ = check(capsys, tree)
    assert check(capsys, tree) == (first, True)


def test_a_fifo_in_the_workspace_never_blocks_the_cache(
        tree: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """A FIFO made just now would be hashed as a racy file: opening it would wait forever."""
    import os

    os.mkfifo(tree / "pipe.yaml")
    first, _ = check(capsys, tree)
    assert check(capsys, tree) == (first, True)


def test_extracted_interfaces_are_kept_between_runs(tmp_path: Path) -> None:
    """A check that misses the result cache still reuses what a source file creates."""
    from launchverify.findings.cache import ResultCache, blobs, in_use
    from launchverify.topology import files

    source = tmp_path / "talker.cpp"
    source.write_text('#include <rclcpp/rclcpp.hpp>\nstruct T : rclcpp::Node {\n'
                      '  T() : Node("talker") { pub_ = create_publisher<std_msgs::msg::String>'
                      '("chatter", 10); }\n};\n')
    cache = ResultCache(tmp_path / "cache")
    files.clear_cache()
    with in_use(cache):
        first = files.file_interfaces(source)
        store = blobs("interfaces")
    assert blobs("interfaces") is None  # outside the block: no store
    assert store is not None and len(list(store.folder.glob("*.json"))) == 1
    assert [e.name for e in first.endpoints] == ["chatter"]
    files.clear_cache()  # another process
    with in_use(cache):
        again = files.file_interfaces(tmp_path / "talker.cpp")
    assert files.cache_stats() == {"parsed": 0, "reused": 1}
    assert again == first
    for stored in store.folder.glob("*.json"):
        stored.write_bytes(b"damaged")
    files.clear_cache()
    with in_use(cache):
        assert files.file_interfaces(source) == first  # read again
    assert files.cache_stats()["parsed"] == 1


def test_links_are_followed_inside_only_but_in_our_own_code(tmp_path: Path) -> None:
    """A workspace's link out is not walked; launchverify's own code is (a strict editable
    install links every module into the checkout: edits must change the code stamp)."""
    from launchverify.findings.cache import _walk

    (tmp_path / "checkout").mkdir()
    (tmp_path / "checkout" / "rule.py").write_text("x = 1\n")
    (tmp_path / "install").mkdir()
    (tmp_path / "install" / "rule.py").symlink_to(tmp_path / "checkout" / "rule.py")
    linked = str(tmp_path / "install" / "rule.py")
    assert linked not in _walk([str(tmp_path / "install")])
    assert linked in _walk([str(tmp_path / "install")], own=True)
    (tmp_path / "ws").mkdir()
    (tmp_path / "ws" / "everything").symlink_to("/")
    assert _walk([str(tmp_path / "ws")]) == {}


# --------------------------------------------------------------------------- plain data


def test_a_check_s_results_come_back_as_they_were_stored() -> None:
    """The report and each root's kept results of a real check, through plain data."""
    from launchverify.engine import CheckOptions, run_check
    from launchverify.findings import plain

    corpus = Path(__file__).parent.parent / "corpus"
    report = run_check(CheckOptions(paths=[corpus / "naming", corpus / "parameters"]),
                       None, keep=True)
    assert report.findings and report.kept is not None and report.kept.roots
    detached = report.detached()
    assert plain.loads(plain.dumps(detached)) == detached
    kept = plain.loads(plain.dumps(report.kept))
    assert isinstance(kept, cache.Kept)
    assert kept.roots == report.kept.roots and kept.token == report.kept.token


def test_only_launchverify_s_own_records_are_rebuilt() -> None:
    """A class of another module, a class whose fields changed, a field of the wrong type,
    a reference to nothing, or data nested past the bound: each is malformed."""
    from launchverify.findings import plain

    span = ["launchverify.span", "Span", ["file", "line", "column", "end_line", "end_column"]]
    good = [[span], ["/a"], [0, ["p", 0], 3, 1, None, None]]
    assert plain.loads(json.dumps(good).encode()) == cache_span("/a", 3)
    for bad in (
        [[["os", "system", []]], [], [0]],
        [[["launchverify.span", "Span", ["file", "line"]]], ["/a"], [0, ["p", 0], 3]],
        [[span], ["/a"], [0, ["p", 0], "three", 1, None, None]],
        [[span], [], [0, ["p", 0], 3, 1, None, None]],
        [[["launchverify.findings.plain", "Malformed", []]], [], [0]],
        [[], [], ["r", 0]],
        [[], [], ["x", 1]],
        [[], [], json.loads("[" * 300 + '"l"' + "]" * 300)],
    ):
        with pytest.raises(plain.Malformed):
            plain.loads(json.dumps(bad).encode())
    for cut in (b"", b"[", b"\xff\xfe", b"[[],[],", b"[" * 100_000):
        with pytest.raises(plain.Malformed):
            plain.loads(cut)
    with pytest.raises(plain.Malformed):  # nothing but launchverify's own is written
        plain.dumps([object()])


def cache_span(file: str, line: int) -> object:
    from launchverify.span import Span

    return Span(Path(file), line)


@given(st.recursive(
    st.none() | st.booleans() | st.integers() | st.text()
    | st.floats(allow_nan=False) | st.builds(Path, st.text(min_size=1)),
    lambda inner: st.lists(inner) | st.tuples(inner, inner)
    | st.frozensets(st.text() | st.integers()) | st.dictionaries(st.text() | st.integers(), inner),
    max_leaves=30))
def test_plain_values_come_back_equal(value: object) -> None:
    from launchverify.findings import plain

    assert plain.loads(plain.dumps(value)) == value


def test_a_default_cache_folder_reached_through_the_user_s_own_link_is_used(
        tmp_path: Path, capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch) -> None:
    """Checked from a home whose ``.cache`` is a link elsewhere: that is the user's link
    (no checked tree holds it), so the cache works there."""
    monkeypatch.delenv("LAUNCHVERIFY_NO_CACHE", raising=False)
    monkeypatch.setattr(cache, "CLOCK_SLACK", 0.0)
    home, elsewhere, root = tmp_path / "home", tmp_path / "elsewhere", tmp_path / "ws"
    for folder in (home, elsewhere, root):
        folder.mkdir()
    (home / ".cache").symlink_to(elsewhere)
    (root / "top.launch.xml").write_text(TOP)
    (root / "robot.launch.xml").write_text(ROBOT)
    (root / "params.yaml").write_text(PARAMS)
    monkeypatch.setenv("XDG_CACHE_HOME", str(home / ".cache"))
    monkeypatch.chdir(home)
    first = check(capsys, root)
    assert check(capsys, root) == (first[0], True)
    assert list((elsewhere / "launchverify").glob("*.json"))
