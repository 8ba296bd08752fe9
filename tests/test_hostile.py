"""Hostile launch trees: a pull request's files cannot touch the machine or the verdict.

One workspace holds every attack below beside two sentinel files with a known finding
(LV101 in XML and in Python); one ``launchverify check`` runs over all of it, as CI would
on a pull request. Then, for each attack: nothing outside the check changed (canary
files, a listener on 127.0.0.1 that must see no connection, wrapper programs on PATH that
log any call, no scratch folder left behind), its own file has a finding, and the
sentinels' findings are still there; the exit status and the JSON come from launchverify.
"""

from __future__ import annotations

import hashlib
import json
import os
import re
import socket
import subprocess
import sys
import threading
import time
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

import pytest

SECRET = "LV-TOP-SECRET-7f3a"  # in a file outside the workspace and in the environment
TIME_LIMIT = 1.0  # seconds per evaluation (lowered for the test)
WALL_LIMIT = 90.0  # the whole check, with every attack (on a busy 2-core machine)

PY_HEADER = """\
import os, sys
from launch import LaunchDescription
from launch.actions import OpaqueFunction
from launch_ros.actions import Node
CANARY = {canary!r}
PORT = {port}
"""

PY_END = """
def generate_launch_description():
    return LaunchDescription([Node(package='demo_nodes_cpp', executable='talker')])
"""

# name -> (file name, content); Python ones get PY_HEADER and, unless they define their
# own, PY_END. {canary} is a folder outside the workspace: anything in it is a side effect.
ATTACKS: dict[str, tuple[str, str]] = {
    # code that runs outside the audit hook's reach
    "thread": ("thread.launch.py", """
import threading
threading.Thread(target=lambda: os.system(f"touch {CANARY}/thread")).start()
"""),
    "atexit": ("atexit.launch.py", """
import atexit
atexit.register(lambda: open(CANARY + '/atexit', 'w').write('x'))
"""),
    "del": ("del.launch.py", """
class Evil:
    def __del__(self):
        open(CANARY + '/del', 'w').write('x')
KEEP = Evil()
"""),
    "finalize": ("finalize.launch.py", """
import weakref
class Thing: pass
THING = Thing()
weakref.finalize(THING, lambda: os.system(f"touch {CANARY}/finalize"))
"""),
    "exception-str": ("exception_str.launch.py", """
class Loud(Exception):
    def __str__(self):
        os.system(f"touch {CANARY}/exception_str")
        return 'loud'

def generate_launch_description():
    raise Loud()
"""),
    "fspath": ("fspath.launch.py", """
class Path:
    def __fspath__(self):
        os.system(f"touch {CANARY}/fspath")
        return '/tmp/x.yaml'

def setup(context):
    return [Node(package='demo_nodes_cpp', executable='talker', parameters=[Path()])]

def generate_launch_description():
    return LaunchDescription([OpaqueFunction(function=setup)])
"""),
    "sandbox-reset": ("sandbox_reset.launch.py", """
for name, module in list(sys.modules.items()):
    if name.startswith('launchverify') and name.endswith('sandbox'):
        getattr(module, '_armed', []).clear()
        getattr(module, '_scratch', []).clear()
open(CANARY + '/sandbox_reset', 'w').write('x')
"""),
    # effects Python does not announce
    "mkfifo": ("mkfifo.launch.py", """
try:
    os.mkfifo(CANARY + '/fifo')
except OSError:
    pass
"""),
    "mknod": ("mknod.launch.py", """
import stat
try:
    os.mknod(CANARY + '/node', stat.S_IFREG | 0o600)
except OSError:
    pass
"""),
    "sqlite": ("sqlite.launch.py", """
import sqlite3
sqlite3.connect(CANARY + '/db.sqlite').execute('create table t (x)')
"""),
    "fork-exec": ("fork_exec.launch.py", """
import _posixsubprocess
ARGS = [[b'/usr/bin/touch', (CANARY + '/fork_exec').encode()], [b'/usr/bin/touch'], True,
        (), None, None, -1, -1, -1, -1, -1, -1, *os.pipe(), False, False]
for tail in ([-1, None, None, None, -1, None, False],   # 3.11: 23 arguments
             [None, None, None, -1, None, False],       # 3.10
             [-1, None, None, None, -1, None, False, False]):
    try:
        _posixsubprocess.fork_exec(*ARGS, *tail)
        break
    except TypeError:
        continue
"""),
    "replace-from-scratch": ("replace.launch.py", """
import tempfile
fd, name = tempfile.mkstemp()
os.write(fd, b'x')
os.close(fd)
os.replace(name, CANARY + '/replaced')
"""),
    "link-into-scratch": ("link.launch.py", """
import tempfile
os.link(CANARY + '/keep.txt', tempfile.gettempdir() + '/linked')
open(tempfile.gettempdir() + '/linked', 'w').write('changed')
"""),
    "setrlimit": ("setrlimit.launch.py", """
import resource
resource.setrlimit(resource.RLIMIT_AS, (resource.RLIM_INFINITY, resource.RLIM_INFINITY))
"""),
    "memory": ("memory.launch.py", """
BLOB = 'a' * (50 * 1024 ** 3)
"""),
    "setitimer": ("setitimer.launch.py", """
import signal
signal.setitimer(signal.ITIMER_REAL, 0)
signal.signal(signal.SIGALRM, signal.SIG_IGN)
while True:
    pass
"""),
    "catch-everything": ("catch.launch.py", """
while True:
    try:
        while True:
            pass
    except BaseException:
        pass
"""),
    "loop-in-c": ("c_loop.launch.py", """
import collections, itertools
collections.deque(itertools.count(), maxlen=0)
"""),
    "sigalrm-default": ("sigalrm.launch.py", """
import signal
signal.signal(signal.SIGALRM, signal.SIG_DFL)
while True:
    pass
"""),
    # the verdict forged or lost
    "exit-0": ("exit0.launch.py", """
os._exit(0)
"""),
    "forged-output": ("forged.launch.py", """
os.write(1, b'{"findings": [], "summary": {"errors": 0, "forged": true}}')
os.write(2, b'forged on stderr')
os._exit(0)
"""),
    "forged-frames": ("frames.launch.py", """
for fd in range(3, 64):
    try:
        os.write(fd, b'\\x00\\x00\\x00\\x00\\x00\\x00\\x00\\x10{"op":"loaded"}')
    except OSError:
        pass
"""),
    "sorted": ("sorted.launch.py", """
import builtins
builtins.sorted = lambda *args, **kwargs: []
builtins.len = lambda *args: 0
"""),
    "patch-launchverify": ("patch_lv.launch.py", """
for name, module in list(sys.modules.items()):
    if name.startswith('launchverify'):
        for attribute in ('run_rules', 'run_check', 'evaluate', 'load_launch_file'):
            if hasattr(module, attribute):
                setattr(module, attribute, lambda *a, **k: [])
"""),
    "patch-libraries": ("patch_libs.launch.py", """
import yaml, lxml.etree, launch_ros.actions
yaml.compose = lambda *a, **k: None
yaml.safe_load = lambda *a, **k: {}
lxml.etree.fromstring = lambda *a, **k: None
os.getenv = lambda *a, **k: 'patched'
launch_ros.actions.Node.__init__ = lambda self, *a, **k: None
"""),
    "misattributed": ("misattributed.launch.py", """
def generate_launch_description():
    exec(compile("raise ValueError('blamed on the sentinel')", SENTINEL_PY, "exec"))
"""),
    # one file ending the whole check
    "keyboard-interrupt": ("interrupt.launch.py", """
raise KeyboardInterrupt
"""),
    "system-exit": ("system_exit.launch.py", """
raise SystemExit(0)
"""),
    "recursion": ("recursion.launch.py", """
sys.setrecursionlimit(10 ** 6)
def down(n):
    return down(n + 1) + 1
down(0)
"""),
    "segfault": ("segfault.launch.py", """
import faulthandler
faulthandler._sigsegv()
"""),
    "sigkill-self": ("sigkill.launch.py", """
import signal
os.kill(os.getpid(), signal.SIGKILL)
"""),
    "kill-parent": ("kill_parent.launch.py", """
import signal
for target in (os.getppid(), -1):
    try:
        os.kill(target, signal.SIGKILL)
    except OSError:
        pass
try:
    os.killpg(0, signal.SIGKILL)
except OSError:
    pass
"""),
    "audit-hook": ("audit_hook.launch.py", """
try:
    sys.addaudithook(lambda event, args: None)
except Exception:
    pass
os.system(f"touch {CANARY}/audit_hook")
"""),
    "opaque-loop": ("opaque_loop.launch.py", """
def setup(context):
    while True:
        pass

def generate_launch_description():
    return LaunchDescription([OpaqueFunction(function=setup)])
"""),
    "opaque-exit": ("opaque_exit.launch.py", """
def setup(context):
    os._exit(3)

def generate_launch_description():
    return LaunchDescription([OpaqueFunction(function=setup),
                              OpaqueFunction(function=setup)])
"""),
    "huge-integer": ("huge_int.launch.py", """
def generate_launch_description():
    return LaunchDescription([Node(package='demo_nodes_cpp', executable='talker',
                                   parameters=[{'x': 10 ** 5000}])])
"""),
    "deep-description": ("deep.launch.py", """
from launch.actions import GroupAction
def generate_launch_description():
    inner = Node(package='demo_nodes_cpp', executable='talker')
    for _ in range(3000):
        inner = GroupAction([inner])
    return LaunchDescription([inner])
"""),
    # the machine: processes, network, files, secrets
    "processes": ("processes.launch.py", """
import subprocess, ctypes
for attempt in (lambda: subprocess.run(['touch', CANARY + '/subprocess']),
                lambda: os.system(f"touch {CANARY}/system"),
                lambda: os.fork(),
                lambda: ctypes.CDLL(None).system(f"touch {CANARY}/ctypes".encode()),
                lambda: os.posix_spawn('/usr/bin/touch', ['touch', CANARY + '/spawn'], {})):
    try:
        attempt()
    except BaseException:
        pass
"""),
    "network": ("network.launch.py", """
import socket, urllib.request
for attempt in (lambda: socket.create_connection(('127.0.0.1', PORT), timeout=1),
                lambda: urllib.request.urlopen(f'http://127.0.0.1:{PORT}/', timeout=1)):
    try:
        attempt()
    except BaseException:
        pass
"""),
    "files": ("files.launch.py", """
import shutil
for attempt in (lambda: open(CANARY + '/written', 'w').write('x'),
                lambda: open(CANARY + '/keep.txt', 'a').write('x'),
                lambda: os.truncate(CANARY + '/keep.txt', 0),
                lambda: os.chmod(CANARY + '/keep.txt', 0o777),
                lambda: os.remove(CANARY + '/keep.txt'),
                lambda: os.symlink('/etc/passwd', CANARY + '/symlink'),
                lambda: os.mkdir(CANARY + '/folder'),
                lambda: shutil.rmtree(CANARY)):
    try:
        attempt()
    except BaseException:
        pass
"""),
    "secrets": ("secrets.launch.py", """
def read(path):
    try:
        return open(path).read()
    except BaseException as error:
        return type(error).__name__

def generate_launch_description():
    found = read(SECRET_FILE) + read('/proc/self/environ') + str(dict(os.environ))
    import posix
    found += str(getattr(posix, 'environ', {}))
    return LaunchDescription([Node(package='demo_nodes_cpp', executable='talker',
                                   name='n' + found.encode().hex()[:4000])])
"""),
    "print-flood": ("flood.launch.py", """
for _ in range(2000):
    print('x' * 50000)
    sys.stderr.write('y' * 50000)
"""),
    # data files that end checks or hang them
    "xml-long-integer": ("long_int.launch.xml",
                         '<launch><arg name="n" default="' + "9" * 5000 + '"/></launch>'),
    "yaml-long-integer": ("long_int.launch.yaml",
                          "launch:\n- arg:\n    name: n\n    default: " + "9" * 5000 + "\n"),
    "yaml-deep-nesting": ("deep.launch.yaml", "launch: " + "[" * 100_000),
    "xml-cdata-comments": ("cdata.launch.xml", "<launch><![CDATA[" + "<!--" * 1_000_000
                           + "]]></launch>"),
    "param-long-integer": ("param_long.launch.xml", """<launch>
<node pkg="demo_nodes_cpp" exec="talker" name="param_long">
  <param from="{workspace}/params/long.yaml"/>
</node></launch>"""),
    "param-recursive-alias": ("param_recursive.launch.xml", """<launch>
<node pkg="demo_nodes_cpp" exec="talker" name="param_recursive">
  <param from="{workspace}/params/recursive.yaml"/>
</node></launch>"""),
    "param-alias-bomb": ("param_bomb.launch.xml", """<launch>
<node pkg="demo_nodes_cpp" exec="talker" name="param_bomb">
  <param from="{workspace}/params/bomb.yaml"/>
</node></launch>"""),
}

# Attacks with nothing to report: the attempt has no effect on anything and the file is
# otherwise a correct launch file (its own worker's launchverify patched; a valid XML file
# whose CDATA would make a quadratic scan hang; prints that go nowhere).
INERT = frozenset({"patch-launchverify", "xml-cdata-comments", "print-flood"})
# Attacks on a parameter file: the finding is on that file.
PARAMETER_FILES = {"param-long-integer": "long.yaml", "param-recursive-alias": "recursive.yaml",
                   "param-alias-bomb": "bomb.yaml"}
SPECIAL = ("fifo", "package-fifo", "dev-zero", "symlink-loop")  # made in the file system

SENTINEL_XML = """<launch>
  <node pkg="demo_nodes_cpp" exec="talker" name="twin"/>
  <node pkg="demo_nodes_cpp" exec="listener" name="twin"/>
</launch>
"""
SENTINEL_PY = """\
from launch import LaunchDescription
from launch_ros.actions import Node

def generate_launch_description():
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name='pytwin'),
        Node(package='demo_nodes_cpp', executable='listener', name='pytwin'),
    ])
"""


def _alias_bomb() -> str:
    """Nine levels of mappings, each naming the one below nine times: 9**9 parameters."""
    text = "a0: &a0 {" + ", ".join(f"k{i}: x" for i in range(9)) + "}\n"
    for level in range(1, 10):
        below = ", ".join(f"k{i}: *a{level - 1}" for i in range(9))
        text += f"a{level}: &a{level} {{{below}}}\n"
    return "node:\n  ros__parameters:\n" + "".join("    " + line + "\n"
                                                  for line in text.splitlines())


@dataclass
class Outcome:
    """What one check of the hostile workspace produced, and what happened around it."""

    root: Path
    workspace: Path
    canary: Path
    status: int
    stdout: str
    stderr: str
    seconds: float
    report: dict[str, object] | None
    connections: list[str]
    before: dict[str, str]
    after: dict[str, str]
    calls: str
    scratch_left: list[str]

    def findings_in(self, name: str) -> list[dict[str, object]]:
        findings = self.report["findings"] if self.report else []
        assert isinstance(findings, list)
        return [f for f in findings if Path(str(f["file"])).name == name]


def _snapshot(root: Path, skip: Path) -> dict[str, str]:
    """Return every file and folder below ``root`` with a digest of its content."""
    state: dict[str, str] = {}
    for current, dirs, files in os.walk(root):
        if Path(current) == skip:
            dirs[:] = []
            continue
        for name in dirs:
            state[str(Path(current) / name)] = "dir"
        for name in files:
            path = Path(current) / name
            try:
                if path.is_symlink() or not path.is_file():
                    state[str(path)] = "special"
                    continue
                info = path.stat()
                state[str(path)] = f"{oct(info.st_mode)} " + hashlib.sha256(
                    path.read_bytes()).hexdigest()
            except OSError as error:
                state[str(path)] = f"error {error.errno}"
    return state


def _listener() -> tuple[socket.socket, list[str]]:
    server = socket.socket()
    server.bind(("127.0.0.1", 0))
    server.listen(16)
    seen: list[str] = []

    def accept() -> None:
        while True:
            try:
                connection, address = server.accept()
            except OSError:
                return
            seen.append(str(address))
            connection.close()

    threading.Thread(target=accept, daemon=True).start()
    return server, seen


def _wrappers(folder: Path, log: Path) -> None:
    folder.mkdir()
    for name in ("sh", "bash", "touch", "true", "ls", "id", "echo", "python3", "curl",
                 "ros2", "ldconfig", "gcc", "cc"):
        script = folder / name
        script.write_text(f"#!/bin/sh\necho \"{name} $*\" >> {log}\n")
        script.chmod(0o755)


def _build(root: Path, port: int) -> tuple[Path, Path]:
    workspace = root / "ws"
    canary = root / "canary"
    (workspace / "params").mkdir(parents=True)
    canary.mkdir()
    (canary / "keep.txt").write_text("keep me")
    (root / "secret.txt").write_text(SECRET)
    sentinel_py = workspace / "sentinel.launch.py"
    (workspace / "sentinel.launch.xml").write_text(SENTINEL_XML)
    sentinel_py.write_text(SENTINEL_PY)
    (workspace / "params" / "long.yaml").write_text(
        "node:\n  ros__parameters:\n    n: " + "7" * 5000 + "\n")
    (workspace / "params" / "recursive.yaml").write_text(
        "node: &a\n  ros__parameters:\n    inner: *a\n")
    (workspace / "params" / "bomb.yaml").write_text(_alias_bomb())
    for name, (filename, content) in ATTACKS.items():
        path = workspace / filename
        if filename.endswith(".py"):
            header = PY_HEADER.format(canary=str(canary), port=port)
            header += f"SENTINEL_PY = {str(sentinel_py)!r}\n"
            header += f"SECRET_FILE = {str(root / 'secret.txt')!r}\n"
            body = content if "def generate_launch_description" in content \
                else content + PY_END
            path.write_text(header + body)
        else:
            path.write_text(content.replace("{workspace}", str(workspace)))
        assert name
    os.mkfifo(workspace / "fifo.launch.xml")
    (workspace / "pkg_fifo").mkdir()
    os.mkfifo(workspace / "pkg_fifo" / "package.xml")
    (workspace / "zero.launch.xml").symlink_to("/dev/zero")
    (workspace / "loop.launch.xml").symlink_to(workspace / "loop2.launch.xml")
    (workspace / "loop2.launch.xml").symlink_to(workspace / "loop.launch.xml")
    return workspace, canary


@pytest.fixture(scope="module")
def outcome(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Outcome]:
    root = tmp_path_factory.mktemp("hostile")
    server, connections = _listener()
    port = server.getsockname()[1]
    workspace, canary = _build(root, port)
    scratch = root / "tmp"
    scratch.mkdir()
    log = root / "calls.log"
    _wrappers(root / "bin", log)
    env = {**os.environ, "PATH": f"{root / 'bin'}:{os.environ.get('PATH', '')}",
           "TMPDIR": str(scratch), "LV_TEST_SECRET": SECRET}
    env.pop("LAUNCHVERIFY_DEBUG_WORKERS", None)
    before = _snapshot(root, scratch)
    start = time.perf_counter()
    done = subprocess.run(
        [sys.executable, "-m", "launchverify", "check", str(workspace), "--format", "json",
         "--workspace", str(workspace), "--time-limit", str(TIME_LIMIT), "-j", "2",
         "--exclude", "loop*.launch.xml"],
        capture_output=True, text=True, env=env, cwd=root, timeout=WALL_LIMIT * 2,
        check=False)
    seconds = time.perf_counter() - start
    time.sleep(0.2)  # anything a stray process would do, it has done by now
    server.close()
    try:
        report = json.loads(done.stdout)
    except ValueError:
        report = None
    yield Outcome(root, workspace, canary, done.returncode, done.stdout, done.stderr,
                  seconds, report, connections, before, _snapshot(root, scratch),
                  log.read_text() if log.exists() else "",
                  sorted(p.name for p in scratch.iterdir()))


# --------------------------------------------------------------------------- the check


def test_the_verdict_comes_from_launchverify(outcome: Outcome) -> None:
    assert outcome.report is not None, outcome.stdout[:2000] + outcome.stderr[-2000:]
    assert outcome.status == 1, outcome.stderr[-2000:]
    assert "\"forged\": true" not in outcome.stdout and "forged on stderr" not in outcome.stderr
    assert set(outcome.report) == {"tool", "workspace", "findings", "not_judged", "summary"}
    assert outcome.stdout.count('"tool"') == 1


def test_sentinels_keep_their_findings(outcome: Outcome) -> None:
    for name in ("sentinel.launch.xml", "sentinel.launch.py"):
        found = outcome.findings_in(name)
        assert [f["code"] for f in found] == ["LV101"], found


def test_bounded_time(outcome: Outcome) -> None:
    assert outcome.seconds < WALL_LIMIT


def test_no_side_effects(outcome: Outcome) -> None:
    assert outcome.after == outcome.before
    assert (outcome.canary / "keep.txt").read_text() == "keep me"
    assert not outcome.connections
    assert not outcome.calls
    assert not outcome.scratch_left  # every worker's scratch folder was removed


def test_no_secret_reaches_the_report(outcome: Outcome) -> None:
    shown = outcome.stdout + outcome.stderr
    assert SECRET not in shown
    assert SECRET.encode().hex() not in shown


def test_no_process_survives(outcome: Outcome) -> None:
    mine = subprocess.run(["ps", "-eo", "pid,args"], capture_output=True, text=True,
                          check=False).stdout
    assert str(outcome.workspace) not in mine


@pytest.mark.parametrize("name", sorted(ATTACKS))
def test_each_attack_has_a_finding_on_its_own_file(outcome: Outcome, name: str) -> None:
    filename = PARAMETER_FILES.get(name, ATTACKS[name][0])
    found = outcome.findings_in(filename)
    assert found or name in INERT, f"{name}: no finding on {filename}"
    assert all(f["code"] != "LV005" for f in found), found


@pytest.mark.parametrize("name", SPECIAL)
def test_special_files_are_findings_not_hangs(outcome: Outcome, name: str) -> None:
    filename = {"fifo": "fifo.launch.xml", "package-fifo": "package.xml",
                "dev-zero": "zero.launch.xml", "symlink-loop": "loop.launch.xml"}[name]
    if name == "package-fifo":  # scanned for packages, not a launch file: skipped quietly
        assert outcome.report is not None
        return
    if name == "symlink-loop":  # excluded on the command line: applying it must not fail
        assert not outcome.findings_in(filename)
        return
    [finding] = outcome.findings_in(filename)
    if name == "dev-zero":  # a link into /dev: never opened
        assert finding["code"] == "LV003" and "/dev/zero is outside" in str(finding["message"])
        return
    assert finding["code"] == "LV001" and "not a regular file" in str(finding["message"])


def test_without_landlock_nothing_is_written_either(outcome: Outcome,
                                                    monkeypatch: pytest.MonkeyPatch) -> None:
    """The fallback where the kernel has no Landlock: seccomp refuses every write."""
    from launchverify.engine import CheckOptions, run_check

    monkeypatch.setenv("LAUNCHVERIFY_WITHOUT_LANDLOCK", "1")
    monkeypatch.setenv("TMPDIR", str(outcome.root / "tmp"))
    before = _snapshot(outcome.root, outcome.root / "tmp")
    report = run_check(CheckOptions(paths=[outcome.workspace], workspace=outcome.workspace,
                                    time_limit=TIME_LIMIT, jobs=2,
                                    exclude=[str(outcome.workspace / "loop*.launch.xml")]))
    assert report.protections is not None
    assert "seccomp (no file writes)" in report.protections
    assert "Landlock (turned off by LAUNCHVERIFY_WITHOUT_LANDLOCK)" in report.protections
    assert _snapshot(outcome.root, outcome.root / "tmp") == before
    for name in ("sentinel.launch.xml", "sentinel.launch.py"):
        assert [f.code for f in report.findings if f.span.file.name == name] == ["LV101"], [
            f.message for f in report.findings if f.span.file.name == name]


@pytest.mark.parametrize("landlock", [True, False])
def test_a_file_that_disarms_the_sandbox_costs_only_itself(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch, landlock: bool) -> None:
    """The next file in its worker is evaluated as in a fresh one (``isolation/reuse``).

    One worker takes both files in turn; the next would otherwise make its own scratch
    folder, which seccomp alone refuses.
    """
    from launchverify.engine import CheckOptions, run_check

    if not landlock:
        monkeypatch.setenv("LAUNCHVERIFY_WITHOUT_LANDLOCK", "1")
    canary = tmp_path / "canary"
    canary.mkdir()
    workspace = tmp_path / "ws"
    workspace.mkdir()
    _, attack = ATTACKS["sandbox-reset"]
    (workspace / "a_reset.launch.py").write_text(
        PY_HEADER.format(canary=str(canary), port=0) + attack + PY_END)
    (workspace / "b_sentinel.launch.py").write_text(SENTINEL_PY)
    report = run_check(CheckOptions(paths=[workspace], workspace=workspace, jobs=1,
                                    time_limit=TIME_LIMIT))
    assert [f.code for f in report.findings if f.span.file.name == "b_sentinel.launch.py"
            ] == ["LV101"], [f.message for f in report.findings]
    assert not list(canary.iterdir())


# --------------------------------------------------------------------------- the terminal

# Names and source lines that would act on a reviewer's terminal if printed raw: erase and
# move (CSI), the clipboard (OSC 52), the window title, a forged finding line, a bidi
# override, C1 controls, NUL.
FORGED = "src/evil.launch.py:1:1: error LV999 [forged] all clear"
TERMINAL_ATTACKS = {
    "names.launch.py": (
        "from launch import LaunchDescription\n"
        "from launch_ros.actions import Node\n"
        f"NAME = 'cam\\x1b[2K\\x1b[1A\\x1b]52;c;ZXZpbA==\\x07\\x1b]0;title\\x07\\n{FORGED}'\n"
        "def generate_launch_description():\n"
        "    return LaunchDescription([\n"
        "        Node(package='demo_nodes_cpp', executable='talker', name=NAME),\n"
        "        Node(package='demo_nodes_cpp', executable='listener', name=NAME),\n"
        "    ])\n"),
    "bidi.launch.py": (
        "from launch import LaunchDescription\n"
        "from launch_ros.actions import Node\n"
        "NAME = 'ok\\u202e\\u2066gnp\\x85\\x9b31m\\x00'\n"
        "def generate_launch_description():\n"
        "    return LaunchDescription([\n"
        "        Node(package='demo_nodes_cpp', executable='talker', name=NAME),\n"
        "        Node(package='demo_nodes_cpp', executable='listener', name=NAME),\n"
        "    ])\n"),
    # control characters in the source itself: a parse error's code frame shows the line
    "frame.launch.xml": "<launch>\n<node name=\"x\x1b[31mred\x1b]52;c;eA==\x07\" <\n",
}


def _terminal_workspace(root: Path) -> Path:
    workspace = root / "ws"
    workspace.mkdir()
    (workspace / "sentinel.launch.xml").write_text(SENTINEL_XML)
    for name, content in TERMINAL_ATTACKS.items():
        (workspace / name).write_text(content)
    (workspace / "binary.launch.xml").write_bytes(
        b"<launch>\x00\x1b[2J\x1b]52;c;eA==\x07\xff\xfe<node\n" * 3)
    return workspace


def _raw_controls(text: str) -> list[str]:
    """Return the characters in ``text`` a terminal would act on (tab and LF aside)."""
    bidi = {0x061C, 0x200E, 0x200F, *range(0x202A, 0x202F), *range(0x2066, 0x206A)}
    return sorted({repr(c) for c in text
                   if (ord(c) < 0x20 and c not in "\t\n") or 0x7F <= ord(c) < 0xA0
                   or ord(c) in bidi})


@pytest.mark.parametrize("output", ["text", "github", "junit", "html", "graph"])
def test_nothing_from_a_checked_file_acts_on_the_terminal(tmp_path: Path, output: str) -> None:
    workspace = _terminal_workspace(tmp_path)
    base = [sys.executable, "-m", "launchverify"]
    command = {
        "text": [*base, "check", str(workspace), "--color", "always", "--explain"],
        "github": [*base, "check", str(workspace), "--format", "github"],
        "junit": [*base, "check", str(workspace), "--format", "junit"],
        "html": [*base, "report", str(workspace), "-o", str(tmp_path / "report.html")],
        "graph": [*base, "graph", str(workspace / "names.launch.py"), "--format", "text"],
    }[output]
    done = subprocess.run(command, capture_output=True, text=True, cwd=tmp_path,
                          timeout=120, check=False, errors="surrogateescape")
    shown = done.stdout + done.stderr
    if output == "html":
        shown += (tmp_path / "report.html").read_text(errors="surrogateescape")
    if output == "text":  # colours are launchverify's own: the only ESC allowed
        shown = re.sub(r"\x1b\[[0-9;]*m", "", shown)
    assert done.returncode in (0, 1), shown[-2000:]
    assert not _raw_controls(shown), _raw_controls(shown)
    if output != "html":  # there a line feed is a space
        assert not any(line.startswith(FORGED) for line in shown.splitlines())
    if output != "graph":
        assert "twin" in shown  # the sentinel's finding is still there
        assert "names.launch.py" in shown and "bidi.launch.py" in shown
    assert "\\x1b" in shown or "\\u001b" in shown or output == "html"


def test_json_keeps_names_exact(tmp_path: Path) -> None:
    workspace = _terminal_workspace(tmp_path)
    done = subprocess.run([sys.executable, "-m", "launchverify", "check", str(workspace),
                           "--format", "json"], capture_output=True, text=True, cwd=tmp_path,
                          timeout=120, check=False)
    report = json.loads(done.stdout)
    messages = " ".join(f["message"] for f in report["findings"])
    assert "\x1b]52;c;ZXZpbA==\x07" in messages and "\u202e" in messages


# --------------------------------------------------------------------------- configuration

READS_OUTSIDE = """\
from launch import LaunchDescription
from launch_ros.actions import Node

def generate_launch_description():
    try:
        name = open({secret!r}).read().strip()
    except Exception:
        name = 'unread'
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name=name),
        Node(package='demo_nodes_cpp', executable='listener', name=name),
    ])
"""


def _widening_workspace(root: Path) -> tuple[Path, Path]:
    outside = root / "vault"
    outside.mkdir()
    (outside / "secret.txt").write_text(SECRET)
    workspace = root / "ws"
    workspace.mkdir()
    (workspace / ".git").mkdir()  # the workspace's root, as a clone has it
    (workspace / "launchverify.toml").write_text(
        f'package-paths = ["{outside}", "/etc"]\nworkspace = "{root}"\n')
    (workspace / "reads.launch.py").write_text(
        READS_OUTSIDE.format(secret=str(outside / "secret.txt")))
    return workspace, outside


def _check(workspace: Path, *extra: str, env: dict[str, str] | None = None
           ) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "launchverify", "check", str(workspace),
                           "--no-cache", *extra], capture_output=True, text=True,
                          cwd=workspace.parent, timeout=120, check=False,
                          env={**os.environ, **(env or {})})


def test_a_configuration_in_the_checked_tree_widens_nothing(tmp_path: Path) -> None:
    workspace, _ = _widening_workspace(tmp_path)
    done = _check(workspace)
    assert SECRET not in done.stdout + done.stderr
    assert "secret.txt is outside the workspace" in done.stdout  # read as an unknown
    assert "names package path" in done.stderr and "not read" in done.stderr
    assert "names workspace" in done.stderr


@pytest.mark.parametrize("how", ["option", "variable"])
def test_the_user_confirms_a_folder_outside(tmp_path: Path, how: str) -> None:
    workspace, outside = _widening_workspace(tmp_path)
    if how == "option":
        done = _check(workspace, "--package-path", str(outside))
    else:
        done = _check(workspace, env={"LAUNCHVERIFY_PACKAGE_PATH": str(outside)})
    assert SECRET in done.stdout  # the user's own decision: the file may be read
    assert "'/etc', outside the workspace: not read" in done.stderr


def test_a_configuration_of_the_user_is_trusted(tmp_path: Path) -> None:
    workspace, outside = _widening_workspace(tmp_path)
    mine = tmp_path / "mine.toml"
    (workspace / "launchverify.toml").rename(mine)
    mine.write_text(f'package-paths = ["{outside}"]\n')
    done = _check(workspace, "--config", str(mine))
    assert SECRET in done.stdout and "not read" not in done.stderr


# --------------------------------------------------------------------------- links and paths


def _linking_workspace(root: Path) -> Path:
    """A workspace whose files point out of it: links, absolute includes, /proc."""
    vault = root / "vault"
    (vault / "pkg_out" / "launch").mkdir(parents=True)
    (vault / "secret.launch.xml").write_text(f"<launch>\n<{SECRET}\n")
    (vault / "pkg_out" / "package.xml").write_text(
        "<package format='3'><name>pkg_out</name></package>")
    (vault / "pkg_out" / "launch" / "x.launch.xml").write_text(f"<launch>\n<{SECRET}\n")
    workspace = root / "ws"
    workspace.mkdir()
    (workspace / ".git").mkdir()
    (workspace / "sentinel.launch.xml").write_text(SENTINEL_XML)
    (workspace / "everything").symlink_to("/")
    (workspace / "proc").symlink_to("/proc")
    (workspace / "vendor").symlink_to(vault)
    (workspace / "linked.launch.xml").symlink_to(vault / "secret.launch.xml")
    (workspace / "includes.launch.xml").write_text(
        "<launch>\n"
        '  <include file="/proc/self/environ"/>\n'
        f'  <include file="{vault / "secret.launch.xml"}"/>\n'
        '  <include file="$(find-pkg-share pkg_out)/launch/x.launch.xml"/>\n'
        "</launch>\n")
    (workspace / "includes.launch.py").write_text(
        "from launch import LaunchDescription\n"
        "from launch.actions import IncludeLaunchDescription\n"
        "from launch.launch_description_sources import AnyLaunchDescriptionSource\n"
        "def generate_launch_description():\n"
        "    return LaunchDescription([IncludeLaunchDescription(\n"
        "        AnyLaunchDescriptionSource('/proc/self/environ'))])\n")
    (workspace / "params.launch.xml").write_text(
        "<launch>\n"
        '  <node pkg="demo_nodes_cpp" exec="talker" name="p">\n'
        f'    <param from="{vault / "secret.launch.xml"}"/>\n'
        "  </node>\n</launch>\n")
    return workspace


@pytest.mark.parametrize("output", ["text", "json"])
def test_nothing_outside_the_workspace_is_read_or_walked(tmp_path: Path, output: str) -> None:
    workspace = _linking_workspace(tmp_path)
    start = time.perf_counter()
    done = subprocess.run([sys.executable, "-m", "launchverify", "check", str(workspace),
                           "--format", output, "--explain", "--no-cache"] if output == "text"
                          else [sys.executable, "-m", "launchverify", "check", str(workspace),
                                "--format", output],
                          capture_output=True, text=True, cwd=tmp_path, timeout=120,
                          check=False, env={**os.environ, "LV_TEST_SECRET": SECRET})
    assert time.perf_counter() - start < 30  # no walk of the machine through a link
    shown = done.stdout + done.stderr
    assert SECRET not in shown, shown[-3000:]
    assert "LV_TEST_SECRET" not in shown
    assert done.returncode == 1, shown[-2000:]
    assert "twin" in shown  # the sentinel's finding
    assert "outside the workspace and its packages: not read" in shown
    assert "pkg_out" in shown  # a package found only through the link: not found


# --------------------------------------------------------------------------- budgets


def test_one_file_cannot_flood_the_verdict(tmp_path: Path) -> None:
    """A node name of 5 MB, twice: the finding quotes a bounded part of it."""
    workspace = tmp_path / "ws"
    workspace.mkdir()
    (workspace / "sentinel.launch.xml").write_text(SENTINEL_XML)
    (workspace / "huge.launch.py").write_text(
        "from launch import LaunchDescription\n"
        "from launch_ros.actions import Node\n"
        "NAME = 'n' * 5_000_000\n"
        "def generate_launch_description():\n"
        "    return LaunchDescription([\n"
        "        Node(package='demo_nodes_cpp', executable='talker', name=NAME),\n"
        "        Node(package='demo_nodes_cpp', executable='listener', name=NAME),\n"
        "    ])\n")
    for output in ("json", "text"):
        done = subprocess.run([sys.executable, "-m", "launchverify", "check", str(workspace),
                               "--format", output], capture_output=True, text=True,
                              cwd=tmp_path, timeout=120, check=False)
        assert done.returncode == 1, done.stderr[-2000:]
        assert len(done.stdout) < 100_000
        assert "more characters)" in done.stdout and "twin" in done.stdout


def test_a_description_too_large_is_not_checked_and_the_rest_is(tmp_path: Path) -> None:
    """100,000 parameters: past the bound of what one file may send, an info, and the
    sentinel's finding is still there."""
    from launchverify.engine import CheckOptions, run_check

    (tmp_path / "sentinel.launch.xml").write_text(SENTINEL_XML)
    (tmp_path / "big.launch.py").write_text(
        "from launch import LaunchDescription\n"
        "from launch_ros.actions import Node\n"
        "def generate_launch_description():\n"
        "    params = {f'p{i}': i for i in range(100_000)}\n"
        "    return LaunchDescription([Node(package='demo_nodes_cpp', executable='talker',\n"
        "                                   parameters=[params])])\n")
    report = run_check(CheckOptions(paths=[tmp_path], workspace=tmp_path))
    found = {(f.code, f.span.file.name) for f in report.findings}
    assert ("LV101", "sentinel.launch.xml") in found
    [big] = [f for f in report.findings if f.span.file.name == "big.launch.py"]
    assert big.code == "LV003" and "250,000 parts" in big.message
