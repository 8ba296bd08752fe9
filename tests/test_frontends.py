"""XML and YAML frontends: spans, one IR class per tag, problems for the unknown and hostile.

Every file is written into pytest's ``tmp_path``. A frontend records problems and never
raises; hostile inputs (bad encodings, deep nesting, alias and entity bombs, external
entities, huge files) must end in a PARSE problem within seconds and read nothing else.
"""

from __future__ import annotations

import json
import time
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from launchverify.engine import CheckOptions, run_check
from launchverify.frontends import LoadedFile, launch_format, load_launch_file
from launchverify.frontends.tags import TAGS, TagParser
from launchverify.frontends.xml_reader import read_xml
from launchverify.frontends.yaml_reader import read_yaml
from launchverify.ir import actions as a
from launchverify.ir import subst as s
from launchverify.models import distros
from launchverify.problems import ProblemKind, ProblemSink
from launchverify.rule import Severity
from launchverify.span import Span

# Guards against hangs, not benchmarks: an expansion that runs away spends CPU time, which
# a loaded machine (a parallel test run) does not stretch; a read that blocks spends
# none, and the generous wall-clock bound catches it.
TIME_LIMIT = 5.0  # CPU seconds
WALL_LIMIT = 60.0


def _within_limits(start: tuple[float, float]) -> bool:
    return (time.process_time() - start[0] < TIME_LIMIT
            and time.perf_counter() - start[1] < WALL_LIMIT)


def load(tmp_path: Path, name: str, content: str | bytes) -> LoadedFile:
    path = tmp_path / name
    path.write_bytes(content.encode() if isinstance(content, str) else content)
    return load_launch_file(path)


def parse_problems(loaded: LoadedFile) -> list[str]:
    return [p.message for p in loaded.problems if p.kind is ProblemKind.PARSE]


def at(span: Span) -> tuple[int, int]:
    return (span.line, span.column)


# --------------------------------------------------------------------------- XML spans


XML_SPANS = """\
<launch>
  <arg name="x" default="1"/> <arg name="y"/>
  <node pkg='p' exec = "e" name="n">
    <param name="a" value="1"/>
    <remap from="a" to="b"/>
  </node>
  <group><log message="m"/></group>
</launch>
"""


def test_xml_element_and_attribute_spans(tmp_path: Path) -> None:
    loaded = load(tmp_path, "spans.launch.xml", XML_SPANS)
    assert loaded.problems == []
    assert loaded.launch is not None
    assert at(loaded.launch.span) == (1, 1)
    first, second, node, group = loaded.launch.actions
    assert isinstance(first, a.DeclareArgument)
    assert at(first.span) == (2, 3)
    assert at(first.at("name")) == (2, 8)
    assert at(first.at("default")) == (2, 17)
    # a second element on the same line
    assert isinstance(second, a.DeclareArgument)
    assert second.name == "y"
    assert at(second.span) == (2, 31)
    assert at(second.at("name")) == (2, 36)
    # single quotes and spaces around `=`
    assert isinstance(node, a.Node)
    assert at(node.span) == (3, 3)
    assert at(node.at("pkg")) == (3, 9)
    assert at(node.at("exec")) == (3, 17)
    assert at(node.at("name")) == (3, 28)
    assert at(node.parameters[0].span) == (4, 5)
    assert at(node.remappings[0].span) == (5, 5)
    assert isinstance(group, a.Group)
    assert at(group.span) == (7, 3)
    (log,) = group.actions
    assert isinstance(log, a.Log)
    assert at(log.span) == (7, 10)
    assert at(log.at("message")) == (7, 15)


def test_xml_attribute_span_covers_name_to_closing_quote(tmp_path: Path) -> None:
    loaded = load(tmp_path, "end.launch.xml", '<launch>\n  <arg name="x" default="1"/>\n</launch>')
    assert loaded.launch is not None
    span = loaded.launch.actions[0].at("default")
    assert (span.line, span.column, span.end_line, span.end_column) == (2, 17, 2, 28)


def test_xml_same_tag_twice_on_one_line(tmp_path: Path) -> None:
    text = '<launch>\n<log message="a"/><log message="b"/><log_info message="c"/>\n</launch>'
    loaded = load(tmp_path, "twice.launch.xml", text)
    assert loaded.launch is not None
    spans = [(at(x.span), at(x.at("message"))) for x in loaded.launch.actions]
    assert spans == [((2, 1), (2, 6)), ((2, 19), (2, 24)), ((2, 37), (2, 47))]


def test_xml_problem_span_points_at_the_attribute(tmp_path: Path) -> None:
    text = '<launch>\n  <node pkg="p" exec="e" bogus="1"/>\n</launch>'
    loaded = load(tmp_path, "attr.launch.xml", text)
    (problem,) = loaded.problems
    assert problem.kind is ProblemKind.PARSE
    assert "unexpected attribute `bogus`" in problem.message
    assert at(problem.span) == (2, 26)


MULTILINE = """\
<launch>
  <node pkg="p"
        exec="e"
   name="n"/>
</launch>
"""


def test_xml_multiline_start_tag_spans(tmp_path: Path) -> None:
    loaded = load(tmp_path, "multi.launch.xml", MULTILINE)
    assert loaded.launch is not None
    (node,) = loaded.launch.actions
    assert at(node.span) == (2, 3)
    assert at(node.at("pkg")) == (2, 9)
    assert at(node.at("exec")) == (3, 9)
    assert at(node.at("name")) == (4, 4)


def test_xml_multiline_start_tag_attribute_on_last_line(tmp_path: Path) -> None:
    loaded = load(tmp_path, "multi.launch.xml", MULTILINE)
    assert loaded.launch is not None
    assert at(loaded.launch.actions[0].at("name")) == (4, 4)


def test_xml_span_skips_commented_out_tag_on_same_line(tmp_path: Path) -> None:
    text = '<launch>\n<!-- <node pkg="old" exec="x"/> --><node pkg="p" exec="e"/>\n</launch>'
    loaded = load(tmp_path, "comment.launch.xml", text)
    assert loaded.launch is not None
    (node,) = loaded.launch.actions
    assert at(node.span) == (2, 36)
    assert at(node.at("pkg")) == (2, 42)


def test_xml_attribute_span_ignores_text_inside_other_values(tmp_path: Path) -> None:
    text = "<launch>\n<node pkg=\"p\" exec=\"e\" args=\"a name='b'\" name=\"n\"/>\n</launch>"
    loaded = load(tmp_path, "value.launch.xml", text)
    assert loaded.launch is not None
    assert at(loaded.launch.actions[0].at("name")) == (2, 42)


# --------------------------------------------------------------------------- YAML spans


YAML_SPANS = """\
launch:
- arg: {name: x, default: '1'}
- node:
    pkg: p
    exec: e
    name: n
    param:
    - {name: a, value: 1}
    remap:
    - {from: a, to: b}
- group:
    children:
    - log: {message: m}
"""


def test_yaml_spans_are_keys(tmp_path: Path) -> None:
    loaded = load(tmp_path, "spans.launch.yaml", YAML_SPANS)
    assert loaded.problems == []
    assert loaded.launch is not None
    assert at(loaded.launch.span) == (1, 1)
    arg, node, group = loaded.launch.actions
    assert isinstance(arg, a.DeclareArgument)
    assert at(arg.span) == (2, 3)
    assert at(arg.at("name")) == (2, 9)
    assert at(arg.at("default")) == (2, 18)
    assert isinstance(node, a.Node)
    assert at(node.span) == (3, 3)
    assert at(node.at("pkg")) == (4, 5)
    assert at(node.at("exec")) == (5, 5)
    assert at(node.at("name")) == (6, 5)
    assert at(node.parameters[0].span) == (8, 7)
    assert at(node.remappings[0].span) == (10, 7)
    assert isinstance(group, a.Group)
    assert at(group.span) == (11, 3)
    (log,) = group.actions
    assert at(log.span) == (13, 7)
    assert at(log.at("message")) == (13, 13)


def test_yaml_problem_span_points_at_the_key(tmp_path: Path) -> None:
    loaded = load(tmp_path, "attr.launch.yaml", "launch:\n- node: {pkg: a, exec: b, bogus: 1}\n")
    (problem,) = loaded.problems
    assert "unexpected attribute `bogus`" in problem.message
    assert at(problem.span) == (2, 27)


def test_yaml_syntax_error_position_is_one_based(tmp_path: Path) -> None:
    loaded = load(tmp_path, "bad.launch.yaml", "launch:\n- node: {pkg: a\n")
    (problem,) = loaded.problems
    assert problem.kind is ProblemKind.PARSE
    assert problem.message.startswith("invalid YAML")
    assert problem.span.line >= 2


def test_read_yaml_and_read_xml_directly(tmp_path: Path) -> None:
    sink = ProblemSink()
    root = read_yaml(tmp_path / "x.launch.yaml", b"launch:\n- arg: {name: x}\n", sink)
    assert root is not None
    assert root.tag == "launch"
    assert at(root.span) == (1, 1)
    (child,) = root.children()
    assert child.tag == "arg"
    assert at(child.attrs["name"].span) == (2, 9)
    xml_root = read_xml(tmp_path / "x.launch.xml", b'<launch>\n <arg name="x"/></launch>', sink)
    assert xml_root is not None
    (xml_child,) = xml_root.children()
    assert at(xml_child.span) == (2, 2)
    assert at(xml_child.attrs["name"].span) == (2, 7)
    assert sink.problems == []


# --------------------------------------------------------------------------- every tag

# tag -> (IR class, attributes, nested entities); minimal and valid for launch.
TAG_EXAMPLES: dict[str, tuple[type[a.Action], dict[str, str], dict[str, list[dict[str, str]]]]] = {
    "arg": (a.DeclareArgument, {"name": "x"}, {}),
    "let": (a.SetConfig, {"name": "x", "value": "1"}, {}),
    "include": (a.Include, {"file": "other.launch.xml"}, {}),
    "group": (a.Group, {}, {}),
    "reset": (a.ResetConfigs, {}, {}),
    "executable": (a.ExecuteProcess, {"cmd": "ls -l"}, {}),
    "set_env": (a.SetEnv, {"name": "A", "value": "1"}, {}),
    "unset_env": (a.UnsetEnv, {"name": "A"}, {}),
    "append_env": (a.AppendEnv, {"name": "A", "value": "1"}, {}),
    "reset_env": (a.ResetEnv, {}, {}),
    "log": (a.Log, {"message": "hi"}, {}),
    "log_info": (a.Log, {"message": "hi"}, {}),
    "log_warning": (a.Log, {"message": "hi"}, {}),
    "log_debug": (a.Log, {"message": "hi"}, {}),
    "log_error": (a.Log, {"message": "hi"}, {}),
    "timer": (a.Timer, {"period": "1.5"}, {}),
    "ros_timer": (a.Timer, {"period": "1.5"}, {}),
    "shutdown": (a.Shutdown, {}, {}),
    "for": (a.ForLoop, {"len": "2", "name": "i"}, {}),
    "for_each": (a.ForEach, {"values": "a;b"}, {}),
    "node": (a.Node, {"pkg": "p", "exec": "e"}, {}),
    "lifecycle_node": (
        a.LifecycleNode, {"pkg": "p", "exec": "e", "name": "n", "namespace": "ns"}, {}
    ),
    "node_container": (
        a.ComposableNodeContainer,
        {"pkg": "rclcpp_components", "exec": "component_container", "name": "c",
         "namespace": "/"},
        {},
    ),
    "load_composable_node": (
        a.LoadComposableNodes,
        {"target": "c"},
        {"composable_node": [{"pkg": "p", "plugin": "p::Q", "name": "q"}]},
    ),
    "push_ros_namespace": (a.PushNamespace, {"namespace": "ns"}, {}),
    "push-ros-namespace": (a.PushNamespace, {"namespace": "ns"}, {}),
    "set_remap": (a.SetRemap, {"from": "a", "to": "b"}, {}),
    "set_parameter": (a.SetParameter, {"name": "a", "value": "1"}, {}),
    "set_parameters_from_file": (a.SetParametersFromFile, {"filename": "p.yaml"}, {}),
    "set_use_sim_time": (a.SetUseSimTime, {"value": "true"}, {}),
    "set_ros_log_dir": (a.SetRosLogDir, {"new_log_dir": "/tmp/logs"}, {}),
    # ros_gz's launch extensions: what each starts, in the scope it runs in
    "gz_server": (a.Group, {}, {}),
    "gz_spawn_model": (a.Group, {}, {}),
    "ros_gz_bridge": (a.Group, {"bridge_name": "b"}, {}),
}


def test_every_registered_tag_has_an_example() -> None:
    assert set(TAG_EXAMPLES) == set(TAGS)


def _xml_for(tag: str) -> str:
    _, attrs, nested = TAG_EXAMPLES[tag]
    attributes = "".join(f' {k}="{v}"' for k, v in attrs.items())
    inner = "".join(
        "<" + name + "".join(f' {k}="{v}"' for k, v in item.items()) + "/>"
        for name, items in nested.items()
        for item in items
    )
    return f"<launch>\n  <{tag}{attributes}>{inner}</{tag}>\n</launch>\n"


def _yaml_for(tag: str) -> str:
    _, attrs, nested = TAG_EXAMPLES[tag]
    body: dict[str, object] = {**attrs, **nested}
    return f"launch:\n- {tag}: {json.dumps(body)}\n"


@pytest.mark.parametrize("fmt", ["xml", "yaml"])
@pytest.mark.parametrize("tag", sorted(TAG_EXAMPLES))
def test_tag_produces_its_ir_class(tag: str, fmt: str, tmp_path: Path) -> None:
    text = _xml_for(tag) if fmt == "xml" else _yaml_for(tag)
    loaded = load(tmp_path, f"t.launch.{fmt}", text)
    assert loaded.format == fmt
    assert loaded.problems == [], text
    assert loaded.launch is not None
    (action,) = loaded.launch.actions
    assert type(action) is TAG_EXAMPLES[tag][0]
    assert at(action.span) == (2, 3)


@pytest.mark.parametrize("fmt", ["xml", "yaml"])
def test_tag_details(fmt: str, tmp_path: Path) -> None:
    def only(tag: str) -> a.Action:
        loaded = load(tmp_path, f"{tag}.launch.{fmt}",
                      _xml_for(tag) if fmt == "xml" else _yaml_for(tag))
        assert loaded.launch is not None
        return loaded.launch.actions[0]

    for tag, level in [("log", "info"), ("log_info", "info"), ("log_warning", "warning"),
                       ("log_debug", "debug"), ("log_error", "error")]:
        log = only(tag)
        assert isinstance(log, a.Log)
        assert log.level == level
        assert log.message == s.Text("hi")
    timer, ros_timer = only("timer"), only("ros_timer")
    assert isinstance(timer, a.Timer)
    assert isinstance(ros_timer, a.Timer)
    assert (timer.ros_time, ros_timer.ros_time) == (False, True)
    executable = only("executable")
    assert isinstance(executable, a.ExecuteProcess)
    assert executable.cmd == (s.Text("ls"), s.Text("-l"))
    load_nodes = only("load_composable_node")
    assert isinstance(load_nodes, a.LoadComposableNodes)
    assert [n.plugin for n in load_nodes.composable_nodes] == [s.Text("p::Q")]
    arg = only("arg")
    assert isinstance(arg, a.DeclareArgument)
    assert arg.name == "x"


def test_tag_parser_directly(tmp_path: Path) -> None:
    path = tmp_path / "direct.launch.xml"
    sink = ProblemSink()
    root = read_xml(path, b'<launch><let name="a" value="$(var b)"/></launch>', sink)
    assert root is not None
    launch = TagParser(path, sink).launch_file(root, "xml")
    (let,) = launch.actions
    assert isinstance(let, a.SetConfig)
    assert let.value == s.LaunchConfig(s.Text("b"))
    assert sink.problems == []


# --------------------------------------------------------------------------- refused content


REFUSED = [
    ("xml", "<launch><bogus/></launch>", "unknown tag `bogus`"),
    ("xml", "<launch><rosparam/></launch>", "ROS 1 tag"),
    ("xml", '<launch><node pkg="p" exec="e" bogus="1"/></launch>',
     "unexpected attribute `bogus` in `node`"),
    ("xml", '<launch><node pkg="p" exec="e"><bogus/></node></launch>',
     "unexpected nested tag `bogus` in `node`"),
    ("xml", "<launch><arg/></launch>", "`arg` requires the attribute `name`"),
    ("xml", '<launch><node pkg="p"/></launch>', "`node` requires the attribute `exec`"),
    ("xml", '<launch><node pkg="p" exec="e" if="1" unless="0"/></launch>',
     "cannot be used together"),
    ("xml", '<launch><log message="$(arg x)"/></launch>', "ROS 2 uses $(var)"),
    ("xml", '<launch><log message="$(var  x)"/></launch>', "exactly one space"),
    ("xml", "<robot/>", "expected `launch` as the root"),
    ("xml", "<launch><node></launch>", "invalid XML"),
    ("yaml", "launch:\n- bogus: {}\n", "unknown tag `bogus`"),
    ("yaml", "launch:\n- node: {pkg: p, exec: e, bogus: 1}\n",
     "unexpected attribute `bogus` in `node`"),
    ("yaml", "launch:\n- node: {pkg: p, exec: e, pkg: q}\n", "duplicate key `pkg`"),
    ("yaml", "launch:\n- node: {pkg: p, exec: 1}\n", "must be str, got int"),
    ("yaml", "launch:\n- arg: {}\n", "`arg` requires the attribute `name`"),
    ("yaml", "launch:\n- node: {pkg: p, exec: e, children: [{log: {message: m}}]}\n",
     "does not take children"),
    ("yaml", "launch:\n- 5\n", "each child must be a mapping"),
    ("yaml", "launch: 5\n", "must hold a mapping"),
    ("yaml", "robot: []\n", "expected `launch` as the root"),
    ("yaml", "launch: []\nother: []\n", "one root key"),
    ("yaml", "launch: [\n", "invalid YAML"),
]


def test_the_roots_other_attributes_are_ignored_as_launch_ignores_them(tmp_path: Path) -> None:
    # launch's parser reads ``deprecated`` from the root and checks nothing else there
    # (LeoRover's files: ``<launch version="0.1.1">``); an action's attributes it checks.
    path = tmp_path / "root.launch.xml"
    sink = ProblemSink()
    root = read_xml(path, b'<launch version="0.1.1"><node pkg="p" exec="e" bogus="1"/>'
                          b'</launch>', sink)
    assert root is not None
    TagParser(path, sink).launch_file(root, "xml")
    assert [p.message for p in sink.problems] == [
        "unexpected attribute `bogus` in `node` (ros2 launch refuses it)"]


@pytest.mark.parametrize(("fmt", "text", "fragment"), REFUSED, ids=[r[2] for r in REFUSED])
def test_refused_content_is_a_parse_problem(
    fmt: str, text: str, fragment: str, tmp_path: Path
) -> None:
    loaded = load(tmp_path, f"r.launch.{fmt}", text)
    messages = parse_problems(loaded)
    assert any(fragment in m for m in messages), messages


SPELLINGS = [
    ("xml", '<launch><node pkg="p" exec="e" nmae="x"/></launch>',
     ["unexpected attribute `nmae` in `node` (ros2 launch refuses it); did you mean `name`?"]),
    ("yaml", "launch:\n- node: {pkg: p, exec: e, nmae: x}\n",
     ["unexpected attribute `nmae` in `node` (ros2 launch refuses it); did you mean `name`?"]),
    ("xml", '<launch><arg name="a" defualt="1"/></launch>',
     ["unexpected attribute `defualt` in `arg` (ros2 launch refuses it); "
      "did you mean `default`?"]),
    ("xml", '<launch><node pkg="p" exec="e"><parm name="a" value="1"/></node></launch>',
     ["unexpected nested tag `parm` in `node` (ros2 launch refuses it); "
      "did you mean `param`?"]),
    # in YAML a list of mappings and an attribute are both keys: either may be meant
    ("yaml", "launch:\n- node: {pkg: p, exec: e, parm: [{name: a, value: 1}]}\n",
     ["unexpected key `parm` in `node` (ros2 launch refuses it); did you mean `param`?"]),
    ("xml", '<launch><node pkg="p" exec="e" name="n" colour="red"/></launch>',
     ["unexpected attribute `colour` in `node` (ros2 launch refuses it)"]),
    # a name already written is not suggested again
    ("xml", '<launch><node pkg="p" exec="e" name="n" nmae="m"/></launch>',
     ["unexpected attribute `nmae` in `node` (ros2 launch refuses it)"]),
    # `node-name` is refused with its own message, never suggested
    ("xml", '<launch><node pkg="p" exec="e" node_name="n"/></launch>',
     ["unexpected attribute `node_name` in `node` (ros2 launch refuses it)"]),
    # launch stops at the attribute missing: the others are not reported, a misspelt one
    # is named
    ("xml", '<launch><node pkg="p" exce="e" nmae="x"/></launch>',
     ["`node` requires the attribute `exec`; `exce` may misspell it"]),
    ("xml", '<launch><node pkg="p" exec="e"><remap form="a" to="b"/></node></launch>',
     ["`remap` requires the attribute `from`; `form` may misspell it"]),
    ("yaml", "launch:\n- node: {pkg: p, exec: e, remap: [{form: a, to: b}]}\n",
     ["`remap` requires the attribute `from`; `form` may misspell it"]),
]


@pytest.mark.parametrize(("fmt", "text", "expected"), SPELLINGS,
                         ids=[f"{r[0]}-{r[1]}" for r in SPELLINGS])
def test_an_unexpected_name_suggests_the_one_it_misspells(
    fmt: str, text: str, expected: list[str], tmp_path: Path
) -> None:
    assert parse_problems(load(tmp_path, f"r.launch.{fmt}", text)) == expected


def test_missing_file_is_a_parse_problem(tmp_path: Path) -> None:
    loaded = load_launch_file(tmp_path / "absent.launch.xml")
    assert loaded.launch is None
    (problem,) = loaded.problems
    assert problem.kind is ProblemKind.PARSE
    assert "cannot read file" in problem.message


def test_python_launch_file_is_unmodeled(tmp_path: Path) -> None:
    loaded = load(tmp_path, "x.launch.py", "raise SystemExit('must not run')\n")
    assert loaded.format == "python"
    assert loaded.launch is None
    assert [p.kind for p in loaded.problems] == [ProblemKind.UNMODELED]


@pytest.mark.parametrize(
    ("name", "data", "expected"),
    [("a.launch.xml", None, "xml"), ("a.launch.yaml", None, "yaml"), ("a.yml", None, "yaml"),
     ("a.launch.py", None, "python"), ("A.LAUNCH.XML", None, "xml"),
     ("a.launch", b"  <launch/>", "xml"), ("a.launch", b"launch: []", "yaml"),
     ("a.launch", None, "yaml")],
)
def test_launch_format(name: str, data: bytes | None, expected: str) -> None:
    assert launch_format(Path(name), data) == expected


def test_sniffed_launch_suffix_is_read(tmp_path: Path) -> None:
    loaded = load(tmp_path, "legacy.launch", '<launch><arg name="x"/></launch>')
    assert loaded.format == "xml"
    assert loaded.launch is not None
    assert len(loaded.launch.actions) == 1


# --------------------------------------------------------------------------- ros_gz tags


def only_group(tmp_path: Path, body: str, name: str = "gz.launch.xml") -> a.Group:
    loaded = load(tmp_path, name, f"<launch>\n  {body}\n</launch>\n")
    assert parse_problems(loaded) == []
    assert loaded.launch is not None
    (group,) = loaded.launch.actions
    assert isinstance(group, a.Group)
    assert not group.scoped  # what an action's execute returns runs in its own scope
    return group


def params(entries: tuple[a.ParamEntry, ...]) -> dict[str, object]:
    out: dict[str, object] = {}
    for entry in entries:
        assert isinstance(entry, a.ParamDict)
        for item in entry.items:
            assert isinstance(item.name, s.Text)
            out[item.name.text] = item.value.value
    return out


def test_gz_server_starts_gzserver_with_its_world(tmp_path: Path) -> None:
    group = only_group(tmp_path, '<gz_server world_sdf_file="$(var w)" if="$(var sim)"/>')
    assert group.condition is not None and group.condition.describe() == "if $(var sim)"
    plugins, resources, node = group.actions
    assert isinstance(plugins, a.SetEnv) and plugins.name == s.Text("GZ_SIM_SYSTEM_PLUGIN_PATH")
    assert isinstance(resources, a.SetEnv) and resources.name == s.Text("GZ_SIM_RESOURCE_PATH")
    assert type(node) is a.Node
    assert (node.package, node.executable, node.name) == (
        s.Text("ros_gz_sim"), s.Text("gzserver"), None)  # its code calls it gzserver
    assert node.condition is None
    assert params(node.parameters) == {"world_sdf_file": s.LaunchConfig(s.Text("w")),
                                       "world_sdf_string": s.Text("")}


def test_gz_server_composed_in_its_own_container(tmp_path: Path) -> None:
    group = only_group(tmp_path, '<gz_server use_composition="True" container_name="c" '
                                 'create_own_container="true"/>')
    container = group.actions[-1]
    assert isinstance(container, a.ComposableNodeContainer)
    assert (container.package, container.executable, container.name, container.namespace) == (
        s.Text("rclcpp_components"), s.Text("component_container"), s.Text("c"), s.Text(""))
    (component,) = container.composable_nodes
    assert (component.plugin, component.name) == (s.Text("ros_gz_sim::GzServer"),
                                                  s.Text("gz_server"))
    assert [item.name for item in component.extra_arguments] == [
        s.Text("use_intra_process_comms")]


def test_composition_from_an_argument_conditions_each_setup(tmp_path: Path) -> None:
    group = only_group(tmp_path, '<ros_gz_bridge bridge_name="b" '
                                 'use_composition="$(var comp)" container_name="sim"/>')
    node, load_nodes = group.actions
    assert isinstance(node, a.Node) and node.condition is not None
    assert node.condition.describe() == "if $(not $(var comp))"
    assert isinstance(load_nodes, a.LoadComposableNodes) and load_nodes.condition is not None
    assert load_nodes.condition.describe() == "if $(var comp)"
    assert load_nodes.target == s.Text("sim")
    group = only_group(tmp_path, '<ros_gz_bridge bridge_name="b" use_composition="$(var c)" '
                                 'create_own_container="$(var own)"/>')
    assert [x.condition.describe() for x in group.actions if x.condition is not None] == [
        "if $(not $(var c))", "if $(and $(var c) $(var own))",
        "if $(and $(var c) $(not $(var own)))"]
    assert [type(x) for x in group.actions] == [
        a.Node, a.ComposableNodeContainer, a.LoadComposableNodes]


def test_ros_gz_bridge_node_and_parameters(tmp_path: Path) -> None:
    group = only_group(tmp_path, """<ros_gz_bridge bridge_name="clock" namespace="r1"
        config_file="/c.yaml" use_respawn="true" log_level="debug"
        bridge_params="{'qos.depth': '5', 'x': 'y'}">
      <topic ros_topic_name="/clock" gz_topic_name="/clock" ros_type_name="rosgraph_msgs/msg/Clock"
             gz_type_name="gz.msgs.Clock" publisher_queue="7"/>
      <service service_name="/s" ros_type_name="a/srv/B" gz_req_type_name="gz.msgs.A"
               gz_rep_type_name="gz.msgs.B"/>
    </ros_gz_bridge>""")
    (node,) = group.actions
    assert isinstance(node, a.Node)
    assert (node.package, node.executable, node.name, node.namespace) == (
        s.Text("ros_gz_bridge"), s.Text("bridge_node"), s.Text("clock"), s.Text("r1"))
    assert node.arguments == (s.Text("--ros-args"), s.Text("--log-level"), s.Text("debug"))
    assert (node.process.respawn, node.process.respawn_delay) == (True, 2.0)
    assert params(node.parameters) == {
        "config_file": s.Text("/c.yaml"), "qos.depth": "5", "x": "y",
        "bridges.bridge_0.ros_topic_name": s.Text("/clock"),
        "bridges.bridge_0.ros_type_name": s.Text("rosgraph_msgs/msg/Clock"),
        "bridges.bridge_0.gz_topic_name": s.Text("/clock"),
        "bridges.bridge_0.gz_type_name": s.Text("gz.msgs.Clock"),
        "bridges.bridge_0.publisher_queue": 7,
        "bridges.bridge_1.service_name": s.Text("/s"),
        "bridges.bridge_1.ros_type_name": s.Text("a/srv/B"),
        "bridges.bridge_1.gz_req_type_name": s.Text("gz.msgs.A"),
        "bridges.bridge_1.gz_rep_type_name": s.Text("gz.msgs.B"),
        "bridge_names": ("bridge_0", "bridge_1"),
    }


def test_gz_spawn_model_sets_its_include_arguments(tmp_path: Path) -> None:
    group = only_group(tmp_path, '<gz_spawn_model file="/m.sdf" x="1" roll="0.5"/>')
    *sets, create = group.actions
    assert all(isinstance(x, a.SetConfig) for x in sets)
    given = {x.name: x.value for x in sets if isinstance(x, a.SetConfig)}
    assert given[s.Text("file")] == s.Text("/m.sdf")
    assert given[s.Text("roll")] == s.Text("0.5")
    assert given[s.Text("topic")] == s.Text("")  # omitted: empty (ros_gz#909)
    assert isinstance(create, a.Node)
    assert (create.package, create.executable, create.name) == (
        s.Text("ros_gz_sim"), s.Text("create"), None)
    values = params(create.parameters)
    assert values["string"] == s.LaunchConfig(s.Text("model_string"))
    # the included file reads R, not the roll the action passes
    assert values["R"] == s.LaunchConfig(s.Text("R"), s.Text("0.0"))


@pytest.mark.parametrize(("text", "fragment"), [
    ('<ros_gz_bridge config_file="/c.yaml"/>', "requires the attribute `bridge_name`"),
    ('<ros_gz_bridge bridge_name="b" config="/c.yaml"/>', "unexpected attribute `config`"),
    ('<ros_gz_bridge bridge_name="b"><topic ros_topic_name="/a"/></ros_gz_bridge>',
     "`topic` requires the attribute `ros_type_name`"),
    ('<gz_server world="empty.sdf"/>', "unexpected attribute `world`"),
    ("<gzserver/>", "ros_gz_sim's tag is <gz_server>"),
])
def test_ros_gz_tags_refuse_what_their_parse_refuses(text: str, fragment: str,
                                                     tmp_path: Path) -> None:
    loaded = load(tmp_path, "bad.launch.xml", f"<launch>{text}</launch>")
    assert any(fragment in m for m in parse_problems(loaded)), parse_problems(loaded)


@pytest.mark.parametrize("value", ["a:b:c", "$(var extra)"])
def test_bridge_params_not_read_here_are_unknown(value: str, tmp_path: Path) -> None:
    loaded = load(tmp_path, "p.launch.xml",
                  f'<launch><ros_gz_bridge bridge_name="b" bridge_params="{value}"/></launch>')
    (problem,) = loaded.problems
    assert problem.kind is ProblemKind.UNMODELED
    assert "the bridge parameters it adds are unknown" in problem.message


@pytest.mark.parametrize(("distro", "known"), [("humble", False), ("iron", False),
                                               ("jazzy", True), ("rolling", True)])
def test_ros_gz_tags_exist_from_jazzy(distro: str, known: bool, tmp_path: Path) -> None:
    with distros.checking(distro):
        loaded = load(tmp_path, "d.launch.xml", '<launch><gz_server/></launch>')
    messages = parse_problems(loaded)
    assert (messages == []) is known, messages
    if not known:
        assert f"not in {distro} (since jazzy)" in messages[0]


ROS_GZ_PYTHON = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from ros_gz_bridge.actions import RosGzBridge
from ros_gz_sim.actions import GzServer, GzSpawnModel


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('comp', default_value='false'),
        GzServer(world_sdf_file='empty.sdf', use_composition=LaunchConfiguration('comp'),
                 create_own_container=True),
        RosGzBridge(bridge_name='bridge', config_file='/c.yaml', namespace='r1',
                    use_composition=LaunchConfiguration('comp'), bridge_params="'a': 'b'",
                    extra_bridge_params={'expand_gz_topic_names': True}),
        GzSpawnModel(world='empty', file='/m.sdf', entity_name='robot'),
    ])
"""


def _python_nodes(tmp_path: Path, *arguments: str, distro: str | None = None
                  ) -> tuple[list[tuple[str | None, str | None, str | None]], list[str]]:
    path = tmp_path / "gz.launch.py"
    path.write_text(ROS_GZ_PYTHON)
    report = run_check(CheckOptions(paths=[path], workspace=tmp_path, distro=distro,
                                    arguments=dict(a.split(":=") for a in arguments)))
    codes = [f.code for f in report.findings if f.code != "LV003"]
    if not report.graphs:
        return [], codes
    graph = report.graphs[0]
    nodes = [(graph.base(n.fqn) if n.fqn is not None else None, graph.base(n.package),
              graph.base(n.executable)) for n in graph.nodes
             if graph.runs(n.origin) is not False]
    return nodes, codes


def test_python_actions_start_the_same_nodes(tmp_path: Path) -> None:
    nodes, codes = _python_nodes(tmp_path)
    assert codes == []
    assert nodes == [(None, "ros_gz_sim", "gzserver"),
                     ("/r1/bridge", "ros_gz_bridge", "bridge_node"),
                     (None, "ros_gz_sim", "create")]
    nodes, codes = _python_nodes(tmp_path, "comp:=true")
    assert codes == []
    assert nodes == [("/ros_gz_container", "rclcpp_components", "component_container"),
                     ("/gz_server", "ros_gz_sim", "ros_gz_sim::GzServer"),
                     ("/r1/bridge", "ros_gz_bridge", "ros_gz_bridge::RosGzBridge"),
                     (None, "ros_gz_sim", "create")]


def test_python_actions_are_missing_before_jazzy(tmp_path: Path) -> None:
    _, codes = _python_nodes(tmp_path, distro="humble")
    assert codes == ["LV002"]


HUMBLE_SPAWNERS = """\
from controller_manager.launch_utils import generate_load_controller_launch_description

def generate_launch_description():
    return generate_load_controller_launch_description(
        controller_name='arm_controller',
        controller_type='joint_trajectory_controller/JointTrajectoryController',
        controller_params_file='/opt/robot/arm_controller.yaml')
"""


@pytest.mark.parametrize(("distro", "expected"), [
    (None, []), ("humble", []), ("iron", []), ("jazzy", ["LV002"]), ("rolling", ["LV002"])])
def test_controller_spawner_helpers_take_each_distros_arguments(
        tmp_path: Path, distro: str | None, expected: list[str]) -> None:
    # PAL's TIAGo passes controller_type, which humble and iron take and jazzy dropped: with
    # no distribution given, the call may be right; for jazzy it raises as launch does.
    path = tmp_path / "arm.launch.py"
    path.write_text(HUMBLE_SPAWNERS)
    report = run_check(CheckOptions(paths=[path], workspace=tmp_path, distro=distro))
    assert [f.code for f in report.findings if f.severity is Severity.ERROR] == expected


# --------------------------------------------------------------------------- hostile input


def _passwd_lines() -> list[str]:
    try:
        text = Path("/etc/passwd").read_text(errors="replace")
    except OSError:
        return []
    return [line for line in text.splitlines() if len(line) > 8]


BOMB = """<?xml version="1.0"?>
<!DOCTYPE launch [
 <!ENTITY a "aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa">
 <!ENTITY b "&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;">
 <!ENTITY c "&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;">
 <!ENTITY d "&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;">
 <!ENTITY e "&d;&d;&d;&d;&d;&d;&d;&d;&d;&d;&d;&d;&d;&d;&d;&d;&d;&d;&d;&d;&d;&d;&d;&d;&d;">
 <!ENTITY f "&e;&e;&e;&e;&e;&e;&e;&e;&e;&e;&e;&e;&e;&e;&e;&e;&e;&e;&e;&e;&e;&e;&e;&e;&e;">
]>
<launch><log message="&f;"/></launch>
"""

EXTERNAL = """<?xml version="1.0"?>
<!DOCTYPE launch [<!ENTITY x SYSTEM "file:///etc/passwd">]>
<launch><log message="&x;"/></launch>
"""

PARAMETER_ENTITY = """<?xml version="1.0"?>
<!DOCTYPE launch [<!ENTITY % p SYSTEM "file:///etc/passwd"> %p;]>
<launch/>
"""


def _alias_bomb(levels: int = 8, fan_out: int = 9) -> str:
    """Each level repeats the previous one ``fan_out`` times: 9**8 nodes once expanded."""
    text = "launch:\n- group:\n    children: &a0 ["
    text += ", ".join(["{log: {message: x}}"] * fan_out) + "]\n"
    for level in range(1, levels):
        child = f"{{group: {{children: *a{level - 1}}}}}"
        text += f"- group:\n    children: &a{level} [" + ", ".join([child] * fan_out) + "]\n"
    return text


BIG = 10 * 1000 * 1000 + 1  # the default --max-file-size, plus one

HOSTILE: list[tuple[str, str, bytes]] = [
    ("invalid-utf8-xml", "x.launch.xml", b'<launch><arg name="\xff\xfe"/></launch>'),
    ("binary-xml", "x.launch.xml", bytes(range(256)) * 40),
    ("binary-yaml", "x.launch.yaml", bytes(range(256)) * 40),
    ("binary-sniffed", "x.launch", bytes(range(256)) * 40),
    ("nul-yaml", "x.launch.yaml", b"launch:\x00 []\n"),
    ("empty-xml", "x.launch.xml", b""),
    ("empty-yaml", "x.launch.yaml", b""),
    ("empty-sniffed", "x.launch", b""),
    ("blank-yaml", "x.launch.yaml", b"\n\n  \n"),
    ("deep-xml", "x.launch.xml",
     b"<launch>" + b"<group>" * 10_000 + b"</group>" * 10_000 + b"</launch>"),
    ("deep-yaml", "x.launch.yaml", b"launch: " + b"[" * 10_000 + b"]" * 10_000),
    ("deep-yaml-mappings", "x.launch.yaml", b"launch: " + b"{a: " * 10_000 + b"1" + b"}" * 10_000),
    ("recursive-alias", "x.launch.yaml", b"launch: &a [*a]\n"),
    ("alias-bomb", "x.launch.yaml", _alias_bomb().encode()),
    ("big-xml", "x.launch.xml", b"<launch>" + b" " * BIG + b"</launch>"),
    ("big-yaml", "x.launch.yaml", b"launch: []\n" + b"#" * BIG),
    ("entity-bomb", "x.launch.xml", BOMB.encode()),
    ("external-entity", "x.launch.xml", EXTERNAL.encode()),
    ("parameter-entity", "x.launch.xml", PARAMETER_ENTITY.encode()),
    ("python-tag-yaml", "x.launch.yaml",
     b'launch: !!python/object/apply:os.system ["touch lv_pwned_yaml"]\n'),
    ("two-documents", "x.launch.yaml", b"launch: []\n---\nlaunch: []\n"),
    ("unclosed-xml", "x.launch.xml", b"<launch><group>"),
]


@pytest.mark.parametrize(("name", "data"), [(h[1], h[2]) for h in HOSTILE],
                         ids=[h[0] for h in HOSTILE])
def test_hostile_input_is_a_parse_problem(
    name: str, data: bytes, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    start = time.process_time(), time.perf_counter()
    loaded = load(tmp_path, name, data)
    assert _within_limits(start)
    assert parse_problems(loaded), loaded.problems
    assert not (tmp_path / "lv_pwned_yaml").exists()
    shown = " ".join(p.message for p in loaded.problems) + repr(loaded.launch)
    for line in _passwd_lines():
        assert line not in shown


@pytest.mark.parametrize(
    "text",
    [
        '<?xml version="1.0"?>\n<!DOCTYPE launch SYSTEM "file:///etc/passwd">\n'
        '<launch><log message="&x;"/></launch>\n',
        '<?xml version="1.0"?>\n<!DOCTYPE launch SYSTEM "file:///etc/passwd">\n'
        '<launch><log message="a"/></launch>\n',
        '<launch xmlns:xi="http://www.w3.org/2001/XInclude">'
        '<xi:include href="/etc/passwd" parse="text"/></launch>',
    ],
    ids=["doctype-entity-ref", "doctype", "xinclude"],
)
def test_external_documents_are_never_read(text: str, tmp_path: Path) -> None:
    start = time.process_time(), time.perf_counter()
    loaded = load(tmp_path, "x.launch.xml", text)
    assert _within_limits(start)
    shown = " ".join(p.message for p in loaded.problems) + repr(loaded.launch)
    for line in _passwd_lines():
        assert line not in shown


@pytest.mark.parametrize(
    "data",
    [b'launch:\n- arg: {name: "\xff\xfe"}\n', b"launch: []\n# \xc3\x28\n"],
    ids=["in-value", "in-comment"],
)
def test_invalid_utf8_yaml_is_a_parse_problem(data: bytes, tmp_path: Path) -> None:
    loaded = load(tmp_path, "x.launch.yaml", data)
    assert parse_problems(loaded)


@pytest.mark.parametrize(
    "text",
    ["launch: &a [{group: *a}]\n", "launch: &a [{group: {children: *a}}]\n",
     "launch: &a [{timer: {period: 1, children: *a}}]\n"],
    ids=["group-value", "children", "timer-children"],
)
def test_recursive_alias_through_children_is_a_parse_problem(
    text: str, tmp_path: Path
) -> None:
    loaded = load(tmp_path, "x.launch.yaml", text)
    assert parse_problems(loaded)


@pytest.mark.parametrize("depth", [100, 250])
def test_xml_nesting_just_under_the_parser_limit_loads(depth: int, tmp_path: Path) -> None:
    text = "<launch>" + "<group>" * depth + "</group>" * depth + "</launch>"
    loaded = load(tmp_path, "x.launch.xml", text)
    assert loaded.problems == []
    assert loaded.launch is not None
    action: a.Action = loaded.launch.actions[0]
    for _ in range(depth - 1):
        assert isinstance(action, a.Group)
        action = action.actions[0]
    assert isinstance(action, a.Group)


@given(data=st.binary(max_size=300), suffix=st.sampled_from([".xml", ".yaml", ""]))
@settings(max_examples=150, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture])
def test_random_bytes_never_raise(data: bytes, suffix: str, tmp_path: Path) -> None:
    path = tmp_path / f"fuzz.launch{suffix}"
    path.write_bytes(data)
    loaded = load_launch_file(path)
    assert loaded.launch is not None or parse_problems(loaded)


YAML_PIECES = st.sampled_from(
    ["launch:", "\n", "- ", "  ", "{", "}", "[", "]", ", ", ": ", "&a ", "*a", "node",
     "group", "children", "pkg", "exec", "p", "'$(var x)'", "1", "~", "!!str ", "\"",
     "param", "name", "value"]
)


@given(text=st.lists(YAML_PIECES, max_size=30).map("".join))
@settings(max_examples=200, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture])
def test_yaml_like_text_never_raises(text: str, tmp_path: Path) -> None:
    path = tmp_path / "fuzz.launch.yaml"
    path.write_text(text)
    load_launch_file(path)
