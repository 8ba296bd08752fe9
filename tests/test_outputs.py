"""``process.outputs``: launchverify's own writes go only where the path says.

The command-line tests of every output are in ``test_hostile.py`` (issue 42: outputs);
these pin the module's rules one by one: links below an anchor, links above, the last
component, atomic replacement, modes, and the folder API a cache uses.
"""

from __future__ import annotations

import errno
import os
import stat
from pathlib import Path

import pytest

from launchverify.engine import UsageError
from launchverify.process import outputs
from launchverify.process.outputs import check_writable, open_folder, replace_in, write_file


@pytest.fixture
def tree(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """A checkout (the working folder) and, beside it, a folder of the user's."""
    (tmp_path / "tree" / "reports").mkdir(parents=True)
    (tmp_path / "mine").mkdir()
    (tmp_path / "mine" / "victim").write_text("keep")
    monkeypatch.chdir(tmp_path / "tree")
    return tmp_path / "tree"


def _refusal(path: str | Path, **options: object) -> str:
    with pytest.raises(UsageError) as raised:
        write_file(path, "new", **options)  # type: ignore[arg-type]
    return str(raised.value)


def _names(folder: Path) -> list[str]:
    return sorted(entry.name for entry in folder.iterdir())


def _leftovers(folder: Path) -> list[str]:
    return [name for name in _names(folder) if name.startswith(".launchverify-")]


def test_a_relative_path_is_written(tree: Path) -> None:
    write_file("reports/x.sarif", "{}\n")
    assert (tree / "reports" / "x.sarif").read_text() == "{}\n"
    assert _leftovers(tree / "reports") == []


def test_a_link_as_the_last_component_is_refused(tree: Path) -> None:
    (tree / "out.sarif").symlink_to(tree.parent / "mine" / "victim")
    message = _refusal("out.sarif")
    assert message == ("cannot write 'out.sarif': it is a link (launchverify writes only "
                       "where the path says)")
    assert (tree.parent / "mine" / "victim").read_text() == "keep"
    assert (tree / "out.sarif").is_symlink()


def test_a_dangling_link_is_refused_and_nothing_is_created(tree: Path) -> None:
    (tree / "out.sarif").symlink_to(tree.parent / "mine" / "created")
    assert "it is a link" in _refusal("out.sarif")
    (tree / "gone").symlink_to(tree.parent / "mine" / "nothing")
    assert "'gone' is a link" in _refusal("gone/x.sarif")
    assert not (tree.parent / "mine" / "created").exists()
    assert not (tree.parent / "mine" / "nothing").exists()


@pytest.mark.parametrize("given", ["reports/x.sarif", "ABSOLUTE"])
def test_a_linked_folder_below_the_working_folder_is_refused(tree: Path, given: str) -> None:
    (tree / "reports").rmdir()
    (tree / "reports").symlink_to(tree.parent / "mine")
    path = str(tree / "reports" / "x.sarif") if given == "ABSOLUTE" else given
    shown = str(tree / "reports") if given == "ABSOLUTE" else "reports"
    assert _refusal(path) == (f"cannot write {path!r}: {shown!r} is a link (launchverify "
                              "writes only where the path says)")
    assert _names(tree.parent / "mine") == ["victim"]


def test_a_link_below_a_named_folder_is_refused(tree: Path, tmp_path: Path) -> None:
    """``inside``: the checked workspace, wherever the working folder is."""
    workspace = tmp_path / "ws"
    workspace.mkdir()
    (workspace / "reports").symlink_to(tmp_path / "mine")
    target = workspace / "reports" / "x.sarif"
    write_file(target, "followed: no anchor says otherwise")
    (tmp_path / "mine" / "x.sarif").unlink()
    assert "is a link" in _refusal(target, inside=[workspace])
    assert not (tmp_path / "mine" / "x.sarif").exists()


def test_links_above_every_anchor_are_the_users_and_followed(tree: Path, tmp_path: Path) -> None:
    """``/tmp`` or a home folder reached through a link: the user's own machine."""
    (tmp_path / "home").symlink_to(tmp_path / "mine")
    (tmp_path / "mine" / "up").symlink_to("../mine")
    write_file(tmp_path / "home" / "up" / "report.sarif", "{}")
    assert (tmp_path / "mine" / "report.sarif").read_text() == "{}"
    (tmp_path / "mine" / "last").symlink_to("victim")
    assert "it is a link" in _refusal(tmp_path / "home" / "last")  # never the last one
    assert (tmp_path / "mine" / "victim").read_text() == "keep"


def test_a_link_of_the_user_leading_into_the_tree_meets_the_trees_rule(
        tree: Path, tmp_path: Path) -> None:
    (tree / "evil").symlink_to(tmp_path / "mine")
    (tmp_path / "shortcut").symlink_to(tree / "evil")
    message = _refusal(tmp_path / "shortcut" / "x.sarif")
    assert f"{str(tree / 'evil')!r} is a link" in message
    (tmp_path / "good").symlink_to(tree / "reports")
    write_file(tmp_path / "good" / "x.sarif", "{}")
    assert (tree / "reports" / "x.sarif").read_text() == "{}"


def test_dot_dot_is_read_as_written(tree: Path, tmp_path: Path) -> None:
    (tree / "reports" / "link").symlink_to(tmp_path / "mine")
    write_file("reports/link/../x.sarif", "{}")  # reports/x.sarif, not mine/../x.sarif
    assert (tree / "reports" / "x.sarif").exists() and not (tmp_path / "x.sarif").exists()
    write_file("../beside.sarif", "{}")
    assert (tmp_path / "beside.sarif").exists()


@pytest.mark.parametrize("kind", ["fifo", "folder"])
def test_the_last_component_must_be_a_regular_file(tree: Path, kind: str) -> None:
    if kind == "fifo":
        os.mkfifo(tree / "out")
    else:
        (tree / "out").mkdir()
    kind_shown = "a FIFO" if kind == "fifo" else "a folder"
    assert _refusal("out") == f"cannot write 'out': it is {kind_shown}"
    with pytest.raises(UsageError, match="it is a"):
        check_writable("out")


def test_a_missing_folder_is_said(tree: Path) -> None:
    assert _refusal("missing/deeper/x") == "cannot write 'missing/deeper/x': no folder 'missing'"
    with pytest.raises(UsageError, match="no folder 'missing'"):
        check_writable("missing/x")
    check_writable("reports/new.sarif")  # a new file in a folder that exists
    assert not (tree / "reports" / "new.sarif").exists()


def test_a_replaced_file_keeps_its_mode_and_a_new_one_gets_the_umask(tree: Path) -> None:
    kept = tree / "robot.launch.xml"
    kept.write_text("<launch/>")
    kept.chmod(0o751)
    write_file(kept, "<launch></launch>")
    assert stat.S_IMODE(kept.stat().st_mode) == 0o751 and kept.read_text() == "<launch></launch>"
    old = os.umask(0o027)
    try:
        write_file("new.sarif", "{}")
    finally:
        os.umask(old)
    assert stat.S_IMODE((tree / "new.sarif").stat().st_mode) == 0o640


def test_text_that_utf8_cannot_hold_is_escaped_not_lost(tree: Path) -> None:
    write_file("odd.txt", "caf\u00e9 \udcff\n")
    assert (tree / "odd.txt").read_bytes() == "caf\u00e9 \\udcff\n".encode()


@pytest.mark.parametrize("failing", ["write", "fsync", "replace", "interrupt"])
def test_an_interrupted_write_leaves_the_old_file_and_no_temporary(
        tree: Path, monkeypatch: pytest.MonkeyPatch, failing: str) -> None:
    (tree / "reports" / "x.sarif").write_text("old")

    def fail(*_: object, **__: object) -> None:
        if failing == "interrupt":
            raise KeyboardInterrupt
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    monkeypatch.setattr(outputs.os, "replace" if failing == "interrupt" else failing, fail)
    if failing == "interrupt":
        with pytest.raises(KeyboardInterrupt):
            write_file("reports/x.sarif", "new" * 1000)
    else:
        assert "No space left on device" in _refusal("reports/x.sarif")
    monkeypatch.undo()
    assert (tree / "reports" / "x.sarif").read_text() == "old"
    assert _leftovers(tree / "reports") == []


def test_a_cache_writes_many_entries_into_one_opened_folder(tree: Path, tmp_path: Path) -> None:
    folder = open_folder("cache/launchverify", create=True, mode=0o700)
    try:
        assert replace_in(folder, "a.json", b"1") and replace_in(folder, "a.json", b"2")
        (tree / "cache" / "launchverify" / "b.json").symlink_to(tmp_path / "mine" / "victim")
        assert not replace_in(folder, "b.json", b"x")  # an entry that is a link: left
        assert not replace_in(folder, "../escape", b"x")
        assert sorted(os.listdir(folder)) == ["a.json", "b.json"]  # noqa: PTH208 (a descriptor)
    finally:
        os.close(folder)
    assert (tree / "cache" / "launchverify" / "a.json").read_bytes() == b"2"
    assert (tmp_path / "mine" / "victim").read_text() == "keep"
    assert stat.S_IMODE((tree / "cache" / "launchverify").stat().st_mode) & 0o077 == 0


def test_a_folder_that_is_a_link_is_not_opened_below_an_anchor(tree: Path, tmp_path: Path) -> None:
    (tree / ".cache").symlink_to(tmp_path / "mine")
    with pytest.raises(UsageError, match=r"'\.cache' is a link"):
        open_folder(".cache/launchverify", create=True)
    assert _names(tmp_path / "mine") == ["victim"]
    (tmp_path / "xdg").symlink_to(tmp_path / "mine")  # the user's: followed
    os.close(open_folder(tmp_path / "xdg" / "launchverify", create=True))
    assert (tmp_path / "mine" / "launchverify").is_dir()
