"""Topics, services and actions in ``launchverify graph``: launch graph composed with sources.

``tests/data/graph_ws`` is a small workspace (a C++ and a Python package, with launch
files); each case runs ``graph --format json`` on one of its launch files and compares the
topics, services and actions with who publishes, subscribes, serves and calls.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

from launchverify.cli import main
from launchverify.topology.resolve import UnknownRule, expand, node_identity, parse_rule, resolve

WORKSPACE = Path(__file__).parent / "data" / "graph_ws"
LAUNCH = WORKSPACE / "src" / "chat_cpp" / "launch"

Summary = dict[str, dict[str, dict[str, list[str]]]]


def _graph(capsys: pytest.CaptureFixture[str], launch: str, *extra: str) -> dict[str, Any]:
    code = main(["graph", str(LAUNCH / launch), "--workspace", str(WORKSPACE), *extra])
    out = capsys.readouterr().out
    assert code == 0, out
    document: dict[str, Any] = json.loads(out)
    return document


def _summary(document: dict[str, Any]) -> Summary:
    """Each section: name -> role -> sorted node names (only roles with someone in them)."""
    roles = {"topics": ("publishers", "subscribers"), "services": ("servers", "clients"),
             "actions": ("servers", "clients")}
    return {section: {entry["name"]: {role: sorted(e["node"] for e in entry[role])
                                      for role in roles[section] if entry[role]}
                      for entry in document[section]}
            for section in roles}


TALKER = {"/talker/status": {"publishers": ["/talker"]}, "/tf": {"publishers": ["/talker"]}}

CASES: list[tuple[str, tuple[str, ...], Summary]] = [
    ("pair.launch.xml", (), {"topics": {
        "/chatter": {"publishers": ["/talker"], "subscribers": ["/listener"]}, **TALKER}}),
    # talker remaps the relative name, listener the absolute one: both reach /conversation
    ("remapped_pair.launch.xml", (), {"topics": {
        "/conversation": {"publishers": ["/talker"], "subscribers": ["/listener"]},
        **TALKER}}),
    # a pushed namespace makes chatter /robot1/chatter; robot2's relative remap source
    # matches its resolved name /robot2/chatter
    ("namespaced.launch.xml", (), {"topics": {
        "/robot1/chatter": {"publishers": ["/robot1/talker"],
                            "subscribers": ["/robot1/listener"]},
        "/robot1/talker/status": {"publishers": ["/robot1/talker"]},
        "/robot2/talker/status": {"publishers": ["/robot2/talker"]},
        "/shared": {"publishers": ["/robot2/talker"]},
        "/tf": {"publishers": ["/robot1/talker", "/robot2/talker"]}}}),
    # the topic parameter: set by the launch for /tuned, the sources' default for /plain
    ("tuned.launch.xml", (), {
        "topics": {"/news": {"subscribers": ["/tuned"]},
                   "/chatter": {"subscribers": ["/plain"]},
                   "/tf": {"subscribers": ["/plain", "/tuned"]},
                   "/tf_static": {"subscribers": ["/plain", "/tuned"]}},
        "services": {"/box/echo/reset": {"clients": ["/plain", "/tuned"]}}}),
    # set_remap listener:chatter:=/heard applies to the listener only
    ("node_specific.launch.xml", (), {"topics": {
        "/chatter": {"publishers": ["/talker"]}, "/heard": {"subscribers": ["/listener"]},
        **TALKER}}),
    # a component in a container: its private service is under its own name
    ("container.launch.xml", (), {
        "topics": {"/chatter": {"publishers": ["/talker"], "subscribers": ["/echo"]},
                   "/out": {"publishers": ["/echo"], "subscribers": ["/tuned"]},
                   "/talker/status": {"publishers": ["/talker"]},
                   "/tf": {"publishers": ["/talker"], "subscribers": ["/tuned"]},
                   "/tf_static": {"subscribers": ["/tuned"]}},
        "services": {"/echo/reset": {"servers": ["/echo"]},
                     "/box/echo/reset": {"clients": ["/tuned"]}}}),
    ("actions.launch.py", (), {"actions": {
        "/left/count": {"servers": ["/left/counter"]},
        "/right/count": {"servers": ["/right/counter"], "clients": ["/left/counter"]},
        "/right/peer/count": {"clients": ["/right/counter"]}}}),
    ("ros_arguments.launch.py", (), {"topics": {"/first": {"publishers": ["/talker"]},
                                                **TALKER}}),
    ("arguments_remap.launch.py", (), {"topics": {"/zeroth": {"publishers": ["/talker"]},
                                                  **TALKER}}),
    # the listener is off under the defaults ...
    ("conditional.launch.xml", (), {"topics": {"/chatter": {"publishers": ["/talker"]},
                                               **TALKER}}),
    # ... on when asked, and present (with its condition) in the symbolic view
    ("conditional.launch.xml", ("with_listener:=true",), {"topics": {
        "/chatter": {"publishers": ["/talker"], "subscribers": ["/listener"]}, **TALKER}}),
    ("conditional.launch.xml", ("--symbolic",), {"topics": {
        "/chatter": {"publishers": ["/talker"], "subscribers": ["/listener"]}, **TALKER}}),
    # a namespace only the user gives: relative and private names stay unknown, /tf does not
    # a remap whose target only the user gives: chatter unknown, the rest unaffected
    ("symbolic_remap.launch.xml", (), {"topics": TALKER}),
    ("symbolic_remap.launch.xml", ("to:=/said",), {"topics": {
        "/said": {"publishers": ["/talker"]}, **TALKER}}),
    ("symbolic_namespace.launch.xml", (),
     {"topics": {"/tf": {"publishers": ["/$(var robot)/talker"]}}}),
]


@pytest.mark.parametrize(("launch", "extra", "expected"), CASES,
                         ids=[f"{c[0]}{' ' + ' '.join(c[1]) if c[1] else ''}" for c in CASES])
def test_graph_lists_who_talks_to_whom(capsys: pytest.CaptureFixture[str], launch: str,
                                       extra: tuple[str, ...], expected: Summary) -> None:
    summary = _summary(_graph(capsys, launch, *extra))
    for section in ("topics", "services", "actions"):
        assert summary[section] == expected.get(section, {}), section


def test_topic_entries_say_type_source_launch_and_condition(
        capsys: pytest.CaptureFixture[str]) -> None:
    document = _graph(capsys, "conditional.launch.xml", "--symbolic")
    chatter = next(t for t in document["topics"] if t["name"] == "/chatter")
    assert chatter["type"] == "std_msgs/msg/String"
    assert chatter["types"] == ["std_msgs/msg/String"]
    assert chatter["condition"] is None  # the talker publishes whatever the arguments
    listener = chatter["subscribers"][0]
    assert listener["condition"] == "$(var with_listener)"
    assert listener["source"].endswith("chat_cpp/src/listener.cpp:11")
    assert listener["launch"].endswith("conditional.launch.xml:4")
    assert (listener["package"], listener["executable"]) == ("chat_cpp", "listener")


def test_parameter_value_says_where_it_comes_from(capsys: pytest.CaptureFixture[str]) -> None:
    document = _graph(capsys, "tuned.launch.xml")
    ends = {e["node"]: e for t in document["topics"] for e in t["subscribers"]
            if e["parameter"] == "topic"}
    assert ends["/tuned"]["value_from"] == "launch"
    assert ends["/plain"]["value_from"] == "default"


def test_remapped_endpoint_names_its_rule(capsys: pytest.CaptureFixture[str]) -> None:
    document = _graph(capsys, "remapped_pair.launch.xml")
    conversation = next(t for t in document["topics"] if t["name"] == "/conversation")
    assert conversation["publishers"][0]["remapped_by"].endswith("remapped_pair.launch.xml:3")


def test_unknown_namespace_leaves_names_unresolved_with_reasons(
        capsys: pytest.CaptureFixture[str]) -> None:
    document = _graph(capsys, "symbolic_namespace.launch.xml")
    interface = document["nodes"][0]["interface"]
    assert interface["found"] and interface["endpoints"] == 3
    unresolved = {u["written"]: u["reason"] for u in interface["unresolved"]}
    assert set(unresolved) == {"chatter", "~/status"}
    assert all("namespace is not known before launch" in r for r in unresolved.values())


def test_unknown_remap_side_says_which_rule(capsys: pytest.CaptureFixture[str]) -> None:
    document = _graph(capsys, "symbolic_remap.launch.xml")
    [unresolved] = document["nodes"][0]["interface"]["unresolved"]
    assert unresolved["written"] == "chatter"
    assert "$(var to)" in unresolved["reason"]
    assert "symbolic_remap.launch.xml:4" in unresolved["reason"]


def test_sources_that_cannot_be_read_are_said_so(monkeypatch: pytest.MonkeyPatch,
                                                 capsys: pytest.CaptureFixture[str]) -> None:
    from launchverify.topology import nodes

    def broken(*arguments: object) -> list[object]:
        raise ValueError("surprise")

    monkeypatch.setattr(nodes, "package_interfaces", broken)
    document = _graph(capsys, "pair.launch.xml")
    assert document["topics"] == []
    notes = {n["interface"]["note"] for n in document["nodes"]}
    assert notes == {"the sources of chat_cpp could not be read: ValueError: surprise"}


def test_package_without_sources_is_said_so(capsys: pytest.CaptureFixture[str]) -> None:
    document = _graph(capsys, "actions.launch.py")
    talker = next(n for n in document["nodes"] if n["package"] == "demo_nodes_cpp")
    assert talker["interface"]["found"] is False
    assert "is not found" in talker["interface"]["note"]
    container = _graph(capsys, "container.launch.xml")["nodes"]
    box = next(n for n in container if n["kind"] == "node_container")
    assert box["interface"]["found"] is False


def test_text_format_lists_topics(capsys: pytest.CaptureFixture[str]) -> None:
    main(["graph", str(LAUNCH / "symbolic_namespace.launch.xml"), "--workspace",
          str(WORKSPACE), "--format", "text"])
    out = capsys.readouterr().out
    assert ("topics:\n    /tf  tf2_msgs/msg/TFMessage\n"
            "        publishers: /$(var robot)/talker\n") in out
    assert "not resolved:" in out and "namespace is not known" in out


def _modules_check_imports(*argv: str) -> str:
    """Return the source-reading modules ``check`` imports (in a fresh interpreter)."""
    code = ("import sys\n"
            "from launchverify.cli import main\n"
            f"main(['check', *{list(argv)!r}])\n"
            "print(sorted(m for m in sys.modules if m.startswith(('tree_sitter', "
            "'launchverify.topology.compose', 'launchverify.topology.files'))), "
            "file=sys.stderr)\n")
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                            check=False)
    return result.stderr.strip().splitlines()[-1]


def test_check_reads_sources_only_for_the_rules_that_compose(tmp_path: Path) -> None:
    """``check`` reads sources only for the rules that compose nodes with their code (the
    wiring rules LV6, the node contracts LV405-LV408), and only when a launched
    node's package has sources in the workspace."""
    pair = str(LAUNCH / "pair.launch.xml")
    assert _modules_check_imports(pair, "--workspace", str(WORKSPACE), "--ignore",
                                  "LV6,LV405,LV406,LV407,LV408") == "[]"
    released = tmp_path / "released.launch.xml"
    released.write_text('<launch><node pkg="demo_nodes_cpp" exec="talker"/></launch>')
    assert _modules_check_imports(str(released), "--workspace", str(tmp_path)) == "[]"
    assert "tree_sitter" in _modules_check_imports(pair, "--workspace", str(WORKSPACE))


def test_workspace_without_sources_gives_empty_lists(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    launch = tmp_path / "only.launch.xml"
    launch.write_text('<launch><node pkg="demo_nodes_cpp" exec="talker" name="t"/></launch>')
    code = main(["graph", str(launch), "--workspace", str(tmp_path)])
    document = json.loads(capsys.readouterr().out)
    assert code == 0
    assert (document["topics"], document["services"], document["actions"]) == ([], [], [])


# ------------------------------------------------------------ name resolution (§6.2, §7)

RESOLVE_CASES: list[tuple[str, str, str | None, list[tuple[str, str]], bool, str | None]] = [
    # name, namespace, node name, rules (launch order), service, expected
    ("chatter", "/", "talker", [], False, "/chatter"),
    ("chatter", "/robot1", "talker", [], False, "/robot1/chatter"),
    ("/chatter", "/robot1", "talker", [], False, "/chatter"),
    ("~/status", "/robot1", "talker", [], False, "/robot1/talker/status"),
    ("~", "/", "talker", [], False, "/talker"),
    ("{node}/out", "/ns", "cam", [], False, "/ns/cam/out"),
    # the trap: a rule written relative in a namespaced group matches the resolved name
    ("chatter", "/ns", "talker", [("chatter", "/x")], False, "/x"),
    ("/ns/chatter", "/ns", "talker", [("chatter", "/x")], False, "/x"),
    ("chatter", "/ns", "talker", [("/chatter", "/x")], False, "/ns/chatter"),
    # the replacement is expanded too: relative, private
    ("chatter", "/ns", "talker", [("chatter", "talk")], False, "/ns/talk"),
    ("chatter", "/ns", "talker", [("chatter", "~/talk")], False, "/ns/talker/talk"),
    ("~/status", "/", "talker", [("~/status", "/health")], False, "/health"),
    # first match wins, no chaining
    ("a", "/", "n", [("a", "b"), ("a", "c")], False, "/b"),
    ("a", "/", "n", [("a", "b"), ("b", "c")], False, "/b"),
    # node-specific rules
    ("chatter", "/", "talker", [("listener:chatter", "/heard")], False, "/chatter"),
    ("chatter", "/", "listener", [("listener:chatter", "/heard")], False, "/heard"),
    # rostopic:// and rosservice:// limit a rule to topics or services
    ("add", "/", "n", [("rostopic://add", "/sum")], True, "/add"),
    ("add", "/", "n", [("rosservice://add", "/sum")], True, "/sum"),
    ("add", "/", "n", [("rosservice://add", "/sum")], False, "/add"),
    # special rules do not rename topics
    ("chatter", "/", "n", [("__node", "other")], False, "/chatter"),
    # unknowns
    ("~/status", "/", None, [], False, None),
    ("chatter", "/", None, [("listener:chatter", "/heard")], False, None),
    ("{robot}/x", "/", "n", [], False, None),
    ("bad name", "/", "n", [], False, None),
]


@pytest.mark.parametrize(("name", "namespace", "node", "rules", "service", "expected"),
                         RESOLVE_CASES)
def test_resolve(name: str, namespace: str, node: str | None, rules: list[tuple[str, str]],
                 service: bool, expected: str | None) -> None:
    result = resolve(name, namespace, node, [parse_rule(s, d) for s, d in rules],
                     service=service)
    assert result.name == expected
    assert (result.reason is None) == (expected is not None)


def test_unknown_rule_blocks_only_what_it_may_match() -> None:
    unknown_target = UnknownRule("chatter:=$(var to)", None, "chatter")
    assert resolve("chatter", "/", "n", [unknown_target]).name is None
    assert resolve("other", "/", "n", [unknown_target]).name == "/other"
    unknown_source = UnknownRule("$(var from):=x")
    reason = resolve("other", "/", "n", [unknown_source]).reason
    assert reason is not None and "$(var from)" in reason
    for_another = UnknownRule("camera:$(var from):=x", "camera")
    assert resolve("other", "/", "n", [for_another]).name == "/other"


def test_node_identity_takes_special_rules_only_when_launch_leaves_them() -> None:
    rules = [parse_rule("__node", "renamed"), parse_rule("__ns", "/moved")]
    assert node_identity("talker", "/", rules, False, False)[:2] == ("renamed", "/moved")
    assert node_identity("talker", "/", rules, True, True)[:2] == ("talker", "/")
    name, _, reason = node_identity("talker", "/", [UnknownRule("$(var a):=b")], False, True)
    assert name is None and reason is not None


def test_expand_reports_an_unknown_namespace_substitution_as_unknown() -> None:
    assert expand("{ns}/x", "/robot", "n").name == "/robot/x"
    assert expand("{namespace}/x", "/", "n").name == "/x"


def test_remap_rules_are_read_only_inside_ros_args_sections() -> None:
    from launchverify.ir.symbolic import Arg
    from launchverify.topology.compose import _remap_rules
    from launchverify.topology.resolve import Rule

    unknown = Arg("level")
    rules, why = _remap_rules(["-r", "a:=b", "--ros-args", "--log-level", unknown, "-r",
                               "c:=d", "--", "-r", "e:=f"], False, "x.py:1")
    assert [(r.src, r.dst) for r in rules if isinstance(r, Rule)] == [("c", "d")]
    assert why is None
    rules, why = _remap_rules(["-r", unknown, "-r", "e:=f"], True, "x.py:1")
    assert rules == [] and why is not None and "remap rule" in why
    rules, why = _remap_rules(["-r", "a:=b", unknown], True, "x.py:1")
    assert len(rules) == 1 and why is not None  # the unknown word could be -r
