"""What a one-file check costs before it reads the file: compiled dataclass code, lazy imports.

Timings live in bench/ (``realrepos.py --startup``); these tests pin the mechanisms.
"""

from __future__ import annotations

import dataclasses
import subprocess
import sys
from pathlib import Path

import pytest

from launchverify.findings.sealed import installation_seal
from launchverify.process import code_cache

CORPUS = Path(__file__).resolve().parent.parent / "corpus"


@pytest.fixture
def cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch):  # type: ignore[no-untyped-def]
    monkeypatch.setattr(sys, "dont_write_bytecode", False)
    monkeypatch.setenv("XDG_STATE_HOME", str(tmp_path / "state"))
    assert installation_seal(create=True) is not None  # as a cached check makes it
    installed = code_cache.install(tmp_path)
    assert installed is not None
    yield installed
    code_cache.uninstall()


def _define() -> type:
    @dataclasses.dataclass(frozen=True)
    class Pose:
        x: float
        y: float = 0.0

    return Pose


def test_compiled_methods_are_kept_between_runs(cache: code_cache.CodeCache,
                                                tmp_path: Path) -> None:
    pose = _define()
    assert pose(1.0) == pose(1.0, 0.0) and repr(pose(2.0)).endswith("Pose(x=2.0, y=0.0)")
    assert cache.added > 0
    cache.save()
    again = code_cache.install(tmp_path)
    assert again is not None and again.known
    second = _define()
    assert again.added == 0  # every text was found compiled
    with pytest.raises(dataclasses.FrozenInstanceError):
        second(1.0).x = 3.0  # type: ignore[misc]


def test_the_code_cache_never_makes_the_installation_secret(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The results cache makes it, where a check may: never in a checked tree, as a state
    folder a pull request names inside its own tree would have it."""
    monkeypatch.setattr(sys, "dont_write_bytecode", False)
    monkeypatch.setenv("XDG_STATE_HOME", str(tmp_path / "state"))
    installed = code_cache.install(tmp_path / "code")
    assert installed is not None
    try:
        _define()
        installed.save()
    finally:
        code_cache.uninstall()
    assert not (tmp_path / "state").exists() and not (tmp_path / "code").exists()


def test_a_broken_or_foreign_file_is_ignored(tmp_path: Path) -> None:
    path = tmp_path / "code.bin"
    for content in (b"", b"something else\n\x00", code_cache._HEADER + b"\n\x00\x01"):
        path.write_bytes(content)
        assert code_cache.CodeCache(path).known == {}


def test_compiled_code_this_installation_did_not_seal_is_never_run(tmp_path: Path) -> None:
    """A code file planted beside launchverify's modules (a virtual environment inside a
    checkout): the text dataclasses asks for maps to code that writes a file; it is not run."""
    import marshal

    from launchverify.findings.sealed import installation_seal

    assert installation_seal(create=True) is not None  # this installation has its secret
    marker = tmp_path / "ran"
    text = "def __create_fn__():\n    pass\n"
    planted = {text: compile(f"open({str(marker)!r}, 'w').close()", "<x>", "exec")}
    path = tmp_path / "code.bin"
    for content in (code_cache._HEADER + b"\n" + marshal.dumps(planted),
                    b"launchverify sealed 1\n" + b"0" * 64 + b"\n" + marshal.dumps(planted)):
        path.write_bytes(content)
        cache = code_cache.CodeCache(path)
        assert cache.known == {}
        cache.exec(text, {}, {})
        assert not marker.exists()


def test_nothing_is_written_where_bytecode_is_not(tmp_path: Path,
                                                  monkeypatch: pytest.MonkeyPatch) -> None:
    target = code_cache.CodeCache(tmp_path / "code.bin")
    target.exec("x = 1", {}, {})
    monkeypatch.setattr(sys, "dont_write_bytecode", True)
    target.save()
    assert not (tmp_path / "code.bin").exists()
    monkeypatch.setattr(sys, "dont_write_bytecode", False)
    unwritable = code_cache.CodeCache(tmp_path / "file" / "code.bin")
    (tmp_path / "file").write_text("a file, not a folder")
    unwritable.exec("x = 1", {}, {})
    unwritable.save()  # quietly nothing
    assert list(tmp_path.iterdir()) == [tmp_path / "file"]


def test_an_xml_check_starts_no_worker_and_no_rich() -> None:
    launch = CORPUS / "naming" / "dds_domains" / "fleet.launch.xml"
    program = (
        "import sys, io\n"
        "from pathlib import Path\n"
        "from launchverify.engine import CheckOptions, run_check\n"
        "from launchverify.render.text import render_text\n"
        f"report = run_check(CheckOptions(paths=[Path({str(launch)!r})]))\n"
        "render_text(report, io.StringIO())\n"
        "print(sorted(m for m in sys.modules if m.startswith(('launchverify.isolation.pool',"
        " 'launchverify.isolation.zygote', 'launchverify.frontends.python', 'rich',"
        " 'importlib.metadata'))))\n")
    out = subprocess.run([sys.executable, "-c", program], capture_output=True, text=True,
                         check=True)
    assert out.stdout.strip() == "[]", out.stdout


def test_the_code_file_lies_outside_the_package_folder() -> None:
    """pip removes only what it installed: a file of ours left in ``launchverify/`` made
    that folder a namespace package shadowing the next (editable) install."""
    import launchverify

    installed = code_cache.install()
    code_cache.uninstall()
    assert installed is not None
    package = Path(launchverify.__file__).resolve().parent
    assert not installed.path.resolve().is_relative_to(package), installed.path
