"""The language server, driven over its protocol: JSON-RPC with Content-Length framing.

A small client starts ``python -m launchverify lsp`` with pipes and reads its messages in
a thread; every wait has a time limit. One server serves the module's tests, each in a
workspace of its own (a git root, which the server takes as the workspace when the editor
names no folder).
"""

from __future__ import annotations

import contextlib
import json
import os
import queue
import socket
import subprocess
import sys
import textwrap
import threading
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest

pytest.importorskip("pygls")

TIMEOUT = 30.0  # seconds for anything to arrive (a loaded CI machine; usually well under 1)

Message = dict[str, Any]

# The server with a bug planted in it: checking a file named explode.launch.xml fails.
BOOT = textwrap.dedent("""
    import sys
    import launchverify.lsp.server as server
    check_documents = server.check_documents

    def exploding(paths, buffers, folders):
        if any(path.name == "explode.launch.xml" for path in paths):
            raise RuntimeError("planted bug")
        return check_documents(paths, buffers, folders)

    server.check_documents = exploding
    from launchverify.cli import main
    sys.exit(main(["lsp"]))
""")


class Client:
    """Speaks LSP to a server over a pair of byte streams."""

    def __init__(self, reader: Any, writer: Any) -> None:
        self.writer = writer
        self.incoming: queue.Queue[Message | None] = queue.Queue()
        self.held: list[Message] = []  # arrived while waiting for something else
        self.last_id = 0
        threading.Thread(target=self._read, args=(reader,), daemon=True).start()

    def _read(self, stream: Any) -> None:
        while True:
            length = None
            while True:
                try:
                    line = stream.readline()
                except OSError:  # the server went away (a socket reset)
                    line = b""
                if not line:
                    self.incoming.put(None)
                    return
                if not line.strip():
                    break
                name, _, value = line.decode("ascii").partition(":")
                if name.strip().lower() == "content-length":
                    length = int(value)
            assert length is not None, "a message without Content-Length"
            self.incoming.put(json.loads(stream.read(length)))

    def send(self, message: Message) -> None:
        body = json.dumps({"jsonrpc": "2.0", **message}).encode("utf-8")
        self.writer.write(b"Content-Length: %d\r\n\r\n%s" % (len(body), body))
        self.writer.flush()

    def notify(self, method: str, params: Any = None) -> None:
        self.send({"method": method, "params": params})

    def request(self, method: str, params: Any = None) -> Any:
        self.last_id += 1
        number = self.last_id
        self.send({"id": number, "method": method, "params": params})
        answer = self.wait(lambda m: m.get("id") == number and "method" not in m)
        assert "error" not in answer, answer
        return answer.get("result")

    def wait(self, matches: Callable[[Message], bool], timeout: float = TIMEOUT) -> Message:
        for message in self.held:
            if matches(message):
                self.held.remove(message)
                return message
        deadline = time.monotonic() + timeout
        while True:
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                raise AssertionError(f"nothing matching arrived in {timeout}s; "
                                     f"held: {json.dumps(self.held)[:2000]}")
            try:
                message = self.incoming.get(timeout=remaining)
            except queue.Empty:
                continue
            if message is None:
                raise AssertionError("the server closed its output")
            if matches(message):
                return message
            self.held.append(message)

    def diagnostics(self, path: Path, until: Callable[[list[Message]], bool] = lambda d: True
                    ) -> list[Message]:
        """Wait for diagnostics of a file that satisfy ``until``; return them."""
        uri = path.as_uri()

        def matches(message: Message) -> bool:
            return (message.get("method") == "textDocument/publishDiagnostics"
                    and message["params"]["uri"] == uri
                    and until(message["params"]["diagnostics"]))

        found: list[Message] = self.wait(matches)["params"]["diagnostics"]
        return found

    def initialize(self, root: Path | None = None) -> Any:
        result = self.request("initialize", {
            "processId": os.getpid(), "rootUri": root.as_uri() if root else None,
            "capabilities": {"workspace": {"workspaceEdit": {"documentChanges": True}}}})
        self.notify("initialized", {})
        return result

    def open(self, path: Path, text: str | None = None) -> None:
        self.notify("textDocument/didOpen", {"textDocument": {
            "uri": path.as_uri(), "languageId": "xml", "version": 1,
            "text": path.read_text() if text is None else text}})

    def change(self, path: Path, text: str, version: int) -> None:
        self.notify("textDocument/didChange", {
            "textDocument": {"uri": path.as_uri(), "version": version},
            "contentChanges": [{"text": text}]})

    def at(self, method: str, path: Path, line: int, character: int) -> Any:
        return self.request(method, {"textDocument": {"uri": path.as_uri()},
                                     "position": {"line": line, "character": character}})


def start(*command: str) -> subprocess.Popen[bytes]:
    return subprocess.Popen([sys.executable, *command], stdin=subprocess.PIPE,
                            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)


def stop(client: Client, process: subprocess.Popen[bytes]) -> int:
    assert client.request("shutdown") is None
    client.notify("exit")
    assert process.stdin is not None
    process.stdin.close()
    return process.wait(timeout=TIMEOUT)


@pytest.fixture(scope="module")
def client() -> Iterator[Client]:
    process = start("-c", BOOT)
    client = Client(process.stdout, process.stdin)
    capabilities = client.initialize()["capabilities"]
    assert capabilities["hoverProvider"] and capabilities["definitionProvider"]
    assert capabilities["codeActionProvider"]["codeActionKinds"] == ["quickfix"]
    yield client
    try:
        assert stop(client, process) == 0
    finally:
        process.kill()


ROBOT = """\
<launch>
  <arg name="robot" default="r1" description="the robot's name"/>
  <arg name="use_sim_time" default="false"/>
  <node pkg="demo_nodes_cpp" exec="talker" name="talker" if="$(var use_sim_tme)"/>
  <include file="$(find-pkg-share demo_pkg)/launch/part.launch.xml"/>
</launch>
"""
PART = """\
<launch>
  <node pkg="demo_nodes_cpp" exec="listener" name="listener" namespace="$(var robot)"/>
</launch>
"""
TYPO = (3, ROBOT.splitlines()[3].index('if="'))  # 0-based line and character of the read


def workspace(root: Path, files: dict[str, str]) -> Path:
    (root / ".git").mkdir(parents=True)
    package = root / "demo_pkg"
    (package / "launch").mkdir(parents=True)
    (package / "package.xml").write_text(
        '<?xml version="1.0"?>\n<package format="3"><name>demo_pkg</name><version>0.0.0'
        '</version><description>d</description><maintainer email="a@b.c">a</maintainer>'
        "<license>MIT</license></package>\n")
    for name, text in files.items():
        (package / "launch" / name).write_text(text)
    return package / "launch"


def codes(diagnostics: list[Message]) -> set[str]:
    return {d["code"] for d in diagnostics}


def test_open_publishes_the_planted_bug_and_a_fix_clears_it(client: Client,
                                                             tmp_path: Path) -> None:
    launch = workspace(tmp_path, {"robot.launch.xml": ROBOT, "part.launch.xml": PART})
    robot = launch / "robot.launch.xml"
    client.open(robot)
    found = client.diagnostics(robot)
    typo = next(d for d in found if d["code"] == "LV201")
    line, character = TYPO
    assert typo["range"] == {"start": {"line": line, "character": character},
                             "end": {"line": line, "character": character + 23}}
    assert typo["severity"] == 1 and typo["source"] == "launchverify"
    assert "did you mean 'use_sim_time'" in typo["message"]
    assert typo["codeDescription"]["href"].endswith("#lv201-undeclared-argument")
    # An unsaved edit is what is checked: fixing the typo in the buffer clears it.
    client.change(robot, ROBOT.replace("use_sim_tme", "use_sim_time"), 2)
    assert client.diagnostics(robot, lambda d: "LV201" not in codes(d)) == []
    assert "use_sim_tme" in robot.read_text()  # the file itself is never written


def test_change_to_an_included_file_updates_its_includer(client: Client,
                                                         tmp_path: Path) -> None:
    launch = workspace(tmp_path, {"robot.launch.xml": ROBOT, "part.launch.xml": PART})
    robot, part = launch / "robot.launch.xml", launch / "part.launch.xml"
    client.open(robot)
    assert "LV208" not in codes(client.diagnostics(robot))
    client.open(part)
    client.diagnostics(part)
    required = PART.replace("<launch>\n", '<launch>\n  <arg name="arm"/>\n')
    client.change(part, required, 2)
    found = client.diagnostics(robot, lambda d: "LV208" in codes(d))
    missing = next(d for d in found if d["code"] == "LV208")
    assert missing["range"]["start"]["line"] == 4  # the include that does not pass it
    client.change(part, PART, 3)
    client.diagnostics(robot, lambda d: "LV208" not in codes(d))


def test_code_actions_offer_the_fix_and_a_suppression(client: Client, tmp_path: Path) -> None:
    launch = workspace(tmp_path, {"robot.launch.xml": ROBOT, "part.launch.xml": PART})
    robot = launch / "robot.launch.xml"
    client.open(robot)
    typo = next(d for d in client.diagnostics(robot) if d["code"] == "LV201")
    actions = client.request("textDocument/codeAction", {
        "textDocument": {"uri": robot.as_uri()}, "range": typo["range"],
        "context": {"diagnostics": [typo]}})
    fix = next(a for a in actions
               if a["title"] == "LV201: replace 'use_sim_tme' with 'use_sim_time'")
    assert fix["kind"] == "quickfix" and fix["isPreferred"] is True
    assert fix["diagnostics"][0]["code"] == "LV201"
    (change,) = fix["edit"]["documentChanges"]
    assert change["textDocument"] == {"uri": robot.as_uri(), "version": 1}
    column = ROBOT.splitlines()[3].index("use_sim_tme")  # only the misspelt name changes
    assert change["edits"] == [{"range": {"start": {"line": 3, "character": column},
                                          "end": {"line": 3, "character": column + 11}},
                                "newText": "use_sim_time"}]
    suppress = next(a for a in actions if a["title"] == "Suppress LV201 on this line")
    (edit,) = suppress["edit"]["documentChanges"][0]["edits"]
    end = len(ROBOT.splitlines()[3])
    assert edit == {"range": {"start": {"line": 3, "character": end},
                              "end": {"line": 3, "character": end}},
                    "newText": " <!-- launchverify: ignore[LV201] -->"}
    assert "isPreferred" not in suppress or not suppress["isPreferred"]


def test_hover_explains_the_finding_and_the_argument(client: Client, tmp_path: Path) -> None:
    launch = workspace(tmp_path, {"robot.launch.xml": ROBOT, "part.launch.xml": PART})
    robot, part = launch / "robot.launch.xml", launch / "part.launch.xml"
    client.open(robot)
    client.diagnostics(robot)
    text = client.at("textDocument/hover", robot, TYPO[0], TYPO[1] + 5)["contents"]["value"]
    assert "**LV201** `undeclared-argument`" in text
    assert "**Why it matters:**" in text and "**Fix:** Correct the name" in text
    client.open(part)
    client.diagnostics(part)
    character = PART.splitlines()[1].index("$(var robot)") + 3
    text = client.at("textDocument/hover", part, 1, character)["contents"]["value"]
    assert "launch argument `robot`" in text and "the robot's name" in text
    assert "**Default:** `r1`" in text


def test_definition_of_an_argument_and_of_an_include(client: Client, tmp_path: Path) -> None:
    launch = workspace(tmp_path, {"robot.launch.xml": ROBOT, "part.launch.xml": PART})
    robot, part = launch / "robot.launch.xml", launch / "part.launch.xml"
    client.open(part)
    client.diagnostics(part)
    character = PART.splitlines()[1].index("$(var robot)") + 7
    (declared,) = client.at("textDocument/definition", part, 1, character)
    assert declared["uri"] == robot.as_uri()  # only the includer declares it
    assert declared["range"]["start"] == {"line": 1, "character": 2}
    client.open(robot)
    client.diagnostics(robot)
    (included,) = client.at("textDocument/definition", robot, 4, 10)
    assert included["uri"] == part.as_uri()
    assert client.at("textDocument/definition", robot, 0, 1) is None


LOADS_PARAMETERS = """\
<launch>
  <node pkg="demo_nodes_cpp" exec="talker" name="talker">
    <param from="$(find-pkg-share demo_pkg)/config/params.yaml"/>
  </node>
</launch>
"""


def test_a_parameter_file_is_checked_through_the_launch_files_loading_it(
        client: Client, tmp_path: Path) -> None:
    launch = workspace(tmp_path, {"robot.launch.xml": LOADS_PARAMETERS})
    parameters = launch.parent / "config" / "params.yaml"
    parameters.parent.mkdir()
    parameters.write_text("talker:\n  ros__parameters:\n    rate: 10\n")
    client.open(parameters)
    assert client.diagnostics(parameters) == []
    client.change(parameters, "talkr:\n  ros__parameters:\n    rate: 10\n", 2)
    stale = next(d for d in client.diagnostics(parameters, bool)
                 if d["code"] == "LV402")
    assert stale["range"]["start"] == {"line": 0, "character": 0}
    robot = launch / "robot.launch.xml"
    client.open(robot)
    client.diagnostics(robot)
    (loaded,) = client.at("textDocument/definition", robot, 2, 20)
    assert loaded["uri"] == parameters.as_uri()


PYTHON = """\
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('robot', default_value='r1'),
        Node(package='demo_nodes_cpp', executable='talker', name='é',
             namespace=LaunchConfiguration('robot')),
        Node(package='demo_nodes_cpp', executable='talker', name='b',
             namespace=LaunchConfiguration('robt')),
    ])
"""


def test_python_launch_file(client: Client, tmp_path: Path) -> None:
    launch = workspace(tmp_path, {"bringup.launch.py": PYTHON})
    bringup = launch / "bringup.launch.py"
    client.open(bringup)
    typo = next(d for d in client.diagnostics(bringup) if d["code"] == "LV201")
    start = PYTHON.splitlines()[12].index("LaunchConfiguration")
    assert typo["range"]["start"] == {"line": 12, "character": start}
    # Python spans count bytes: the 'é' on line 10 must not shift the range (UTF-16 here).
    character = PYTHON.splitlines()[10].index("LaunchConfiguration") + 3
    (declared,) = client.at("textDocument/definition", bringup, 10, character)
    assert declared["range"]["start"] == {"line": 8, "character": 8}


def test_a_file_that_does_not_parse_is_a_diagnostic(client: Client, tmp_path: Path) -> None:
    launch = workspace(tmp_path, {"broken.launch.xml": "<launch>\n  <node pkg=\n"})
    broken = launch / "broken.launch.xml"
    client.open(broken)
    assert "LV001" in codes(client.diagnostics(broken))
    client.open(launch / "missing.launch.xml", "<launch/>")  # not on disk: not checked
    client.at("textDocument/hover", broken, 0, 0)  # and the server still answers


def test_an_internal_error_is_logged_and_the_server_goes_on(client: Client,
                                                            tmp_path: Path) -> None:
    launch = workspace(tmp_path, {"explode.launch.xml": PART, "part.launch.xml": PART})
    client.open(launch / "explode.launch.xml")
    logged = client.wait(lambda m: m.get("method") == "window/logMessage")["params"]
    assert logged["type"] == 1 and "planted bug" in logged["message"]
    client.open(launch / "part.launch.xml")
    client.diagnostics(launch / "part.launch.xml")


def _serve_on_a_free_port() -> tuple[subprocess.Popen[bytes], socket.socket]:
    """Start ``launchverify lsp --tcp`` on a port free a moment ago; connect to it.

    The port is free when chosen, not when the server binds it: another process (a
    parallel test, another run on the machine) may take it meanwhile. Then the server
    exits and another port is tried; and the connection is made only once the server
    itself holds the listening socket, never to whoever else listens there.
    """
    for _attempt in range(5):
        with socket.socket() as probe:
            probe.bind(("127.0.0.1", 0))
            port = probe.getsockname()[1]
        process = start("-m", "launchverify", "lsp", "--tcp", f"127.0.0.1:{port}")
        deadline = time.monotonic() + TIMEOUT
        while process.poll() is None and time.monotonic() < deadline:
            if _listens(process.pid, port):
                return process, socket.create_connection(("127.0.0.1", port), timeout=1)
            time.sleep(0.05)
        process.kill()
        process.wait(timeout=TIMEOUT)
    raise AssertionError("the language server listened on none of five free ports")


def _listens(pid: int, port: int) -> bool:
    """Whether process ``pid`` holds the socket listening on 127.0.0.1:``port``.

    Read from ``/proc`` (Linux); elsewhere whoever listens is taken for the server.
    """
    table = Path("/proc/net/tcp")
    if not table.exists():
        with socket.socket() as attempt:
            return attempt.connect_ex(("127.0.0.1", port)) == 0
    listening = {fields[9] for fields in map(str.split, table.read_text().splitlines()[1:])
                 if fields[1] == f"0100007F:{port:04X}" and fields[3] == "0A"}
    held = set()
    with contextlib.suppress(OSError):
        for fd in Path(f"/proc/{pid}/fd").iterdir():
            with contextlib.suppress(OSError):
                held.add(str(fd.readlink()))
    return any(f"socket:[{inode}]" in held for inode in listening)


def test_editor_folder_is_the_workspace_and_tcp_transport(tmp_path: Path) -> None:
    # Two repositories side by side: only with the editor's folder as the workspace does
    # one find the other's package.
    top = tmp_path / "ws"
    (top / "other" / ".git").mkdir(parents=True)
    (top / "other" / "package.xml").write_text(
        '<?xml version="1.0"?>\n<package format="3"><name>other_pkg</name></package>\n')
    (top / "other" / "part.launch.xml").write_text("<launch/>\n")
    launch = workspace(top / "mine", {"robot.launch.xml": (
        '<launch>\n  <include file="$(find-pkg-share other_pkg)/part.launch.xml"/>\n'
        "</launch>\n")})
    robot = launch / "robot.launch.xml"
    process, connection = _serve_on_a_free_port()
    try:
        with connection:
            stream = connection.makefile("rwb")
            client = Client(stream, stream)
            client.initialize(top)
            client.open(robot)
            assert "LV303" not in codes(client.diagnostics(robot))
            assert client.request("shutdown") is None
            client.notify("exit")
            assert process.wait(timeout=TIMEOUT) == 0
    finally:
        process.kill()
        process.wait(timeout=TIMEOUT)


def test_exit_without_shutdown_is_status_1(tmp_path: Path) -> None:
    process = start("-m", "launchverify", "lsp")
    client = Client(process.stdout, process.stdin)
    client.initialize(tmp_path)
    client.notify("exit")
    assert process.stdin is not None
    process.stdin.close()
    assert process.wait(timeout=TIMEOUT) == 1


def test_without_pygls_the_command_says_what_to_install() -> None:
    block = "import sys; sys.modules['pygls'] = None; from launchverify.cli import main; " \
            "sys.exit(main(['lsp']))"
    done = subprocess.run([sys.executable, "-c", block], capture_output=True, text=True,
                          timeout=TIMEOUT, check=False)
    assert done.returncode == 2
    assert "pip install 'pygls>=2,<3'" in done.stderr
    assert "Traceback" not in done.stderr


def test_a_check_does_not_import_pygls(tmp_path: Path) -> None:
    launch = workspace(tmp_path, {"part.launch.xml": PART})
    program = ("import sys; from launchverify.cli import main; "
               f"main(['check', '-q', {str(launch)!r}]); print(sorted("
               "m for m in sys.modules if m.split('.')[0] in ('pygls', 'lsprotocol')))")
    done = subprocess.run([sys.executable, "-c", program], capture_output=True, text=True,
                          timeout=TIMEOUT, check=False)
    assert done.stdout.strip().splitlines()[-1] == "[]", done.stderr


def test_bad_tcp_address_is_a_usage_error() -> None:
    done = subprocess.run([sys.executable, "-m", "launchverify", "lsp", "--tcp", "nowhere"],
                          capture_output=True, text=True, timeout=TIMEOUT, check=False)
    assert done.returncode == 2 and "HOST:PORT" in done.stderr and "Traceback" not in \
        done.stderr


# ---------------------------------------------------------------------- conversions


def _finding(path: Path, line: int, column: int, end: int, **extra: Any) -> Any:
    from launchverify.rule import Finding, Severity
    from launchverify.span import Span

    return Finding("LV201", "undeclared-argument", Severity.ERROR, "read but never declared",
                   Span(path, line, column, line, end), **extra)


def _lines(*texts: str) -> Any:
    from launchverify.lsp.positions import Lines

    return Lines(texts)


def test_positions_count_utf16_units() -> None:
    from launchverify.lsp.positions import UTF8, UTF32, Lines
    from launchverify.span import Span

    line = "a='é😀', b=x"  # é: 2 UTF-8 bytes, 1 UTF-16 unit; 😀: 4 bytes, 2 units
    column = line.index("b") + 1  # characters, as every span counts
    lines = _lines(line)
    assert lines.position(1, column).character == column  # one more unit for 😀
    assert lines.position(1, column).character == line.index("b") + 1
    assert lines.column(lines.position(1, column)) == (1, column)
    byte_column = len(line[: line.index("b")].encode()) + 1
    assert Lines((line,), encoding=UTF8).position(1, column).character == byte_column - 1
    assert Lines((line,), encoding=UTF32).position(1, column).character == column - 1
    without_end = lines.range(Span(Path("f.xml"), 1, 3))
    assert (without_end.start.character, without_end.end.character) == (2, len(line) + 1)
    beyond = lines.position(5, 1)  # the text changed since: the end, never an error
    assert (beyond.line, beyond.character) == (1, 0)


def test_diagnostic_carries_code_related_places_and_the_include_chain(tmp_path: Path) -> None:
    from launchverify.lsp.diagnostics import diagnostic
    from launchverify.rule import Related
    from launchverify.span import Span

    child, top = tmp_path / "child.launch.xml", tmp_path / "top.launch.xml"
    finding = _finding(child, 2, 5, 9, related=(Related(Span(child, 1, 3), "declared here"),),
                       chain=(Span(top, 4, 3, 4, 10),), witness={"sim": "true"})
    lines = {child: _lines("<launch>", "  <x y='1'/>"), top: _lines(*["<launch/>"] * 5)}
    result = diagnostic(finding, lines.__getitem__)
    assert (result.code, result.source, result.severity) == ("LV201", "launchverify", 1)
    assert result.message == "read but never declared (when: sim:=true)"
    assert (result.range.start.line, result.range.start.character) == (1, 4)
    assert (result.range.end.line, result.range.end.character) == (1, 8)
    assert result.related_information is not None
    declared, included = result.related_information
    assert declared.message == "declared here" and declared.location.uri == child.as_uri()
    assert included.message == "included from here" and included.location.uri == top.as_uri()
    assert included.location.range.start.line == 3


def test_fix_becomes_a_quick_fix_with_a_workspace_edit(tmp_path: Path) -> None:
    from launchverify.lsp.actions import EditStyle, fix_action
    from launchverify.rule import Applicability, Edit, Fix
    from launchverify.span import Span

    robot, other = tmp_path / "robot.launch.py", tmp_path / "other.launch.xml"
    text = "x = LaunchConfiguration('é', 'use_sim_tme')"
    start = text.index("use_sim_tme") + 1  # characters, in Python files too
    rename = Edit(Span(robot, 1, start, 1, start + len("use_sim_tme")), "use_sim_time")
    insert = Edit(Span(other, 2, 1, 2, 1), '<arg name="use_sim_time"/>\n')
    fix = Fix("rename to 'use_sim_time'", (rename, insert), Applicability.UNSAFE)
    finding = _finding(robot, 1, 5, 10, fix=fix)
    lines = {robot: _lines(text), other: _lines("<launch>", "</launch>")}
    versioned = fix_action(finding, fix, lines.__getitem__,
                           EditStyle(True, {robot: 7}.get))
    assert versioned.title == "LV201: rename to 'use_sim_time'" and not versioned.is_preferred
    assert versioned.kind == "quickfix" and versioned.diagnostics is not None
    assert versioned.edit is not None and versioned.edit.document_changes is not None
    first, second = versioned.edit.document_changes
    assert (first.text_document.uri, first.text_document.version) == (robot.as_uri(), 7)
    (edit,) = first.edits
    column = text.index("use_sim_tme")  # characters: the é counts once
    assert (edit.range.start.character, edit.range.end.character) == (column, column + 11)
    assert edit.new_text == "use_sim_time"
    (added,) = second.edits
    assert second.text_document.version is None  # not open: no version to check
    assert added.range.start == added.range.end and added.range.start.line == 1
    plain = fix_action(finding, Fix("rename", (rename,)), lines.__getitem__,
                       EditStyle(False, {}.get))
    assert plain.is_preferred and plain.edit is not None and plain.edit.changes is not None
    assert list(plain.edit.changes) == [robot.as_uri()]


@pytest.mark.parametrize(("name", "lines", "line", "expected"), [
    ("a.py", ["x = f(", "    a=1,  # noqa", ")"], 2, (2, 17, "  # launchverify: ignore[LV201]")),
    ("a.py", ['x = """', 'text', '"""'], 1, None),  # a comment would go into the string
    ("a.py", ["y = 2 \\", "  + 3"], 1, None),
    ("a.xml", ["<launch>", '  <node pkg="a"', '        name="b"/>'], 2,
     (2, 1, "  <!-- launchverify: ignore[LV201] -->\n")),  # above a tag over several lines
    ("a.xml", ["<launch>", '  <node pkg="a"', '        name="b"/>'], 3, None),
    ("a.xml", ['<arg name="x"/> <!-- launchverify: ignore[LV202] -->'], 1,
     (1, 48, ", LV201")),  # added before the "]"
    ("a.yaml", ["launch:", "- node:", "    cmd: |", "      a"], 4, None),
    ("a.yaml", ["launch:", "- arg: {name: x}"], 2, (2, 17, "  # launchverify: ignore[LV201]")),
    ("a.yaml", ["- arg: {name: x}  # launchverify: ignore[LV201]"], 1, None),
])
def test_suppression_comment_in_each_format(name: str, lines: list[str], line: int,
                                            expected: tuple[int, int, str] | None) -> None:
    from launchverify.lsp.suppress import suppression

    found = suppression(Path(name), lines, line, "LV201")
    assert (None if found is None else (found.line, found.column, found.text)) == expected


def test_variable_references_use_the_frontend_grammar() -> None:
    from launchverify.frontends.subst_parser import variable_references

    line = r'<x a="$(var robot)/$(var $(var arm))" b="\$(var no)" c="$(var half'
    assert [name for name, _, _ in variable_references(line)] == ["robot", "arm"]
