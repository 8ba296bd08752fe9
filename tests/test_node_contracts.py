"""Node contracts read from code: parameter declarations and QoS, without building.

Each case is a snippet of a node's code and what the extractor must read from it (the
traps as much as the bugs: a helper forwarding a name declares nothing, a declaration in
a ``try`` is optional, a descriptor from elsewhere may allow any type).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from launchverify.topology.cpp import extract as extract_cpp
from launchverify.topology.generated_parameters import definitions, parameter_libraries
from launchverify.topology.model import Parameter
from launchverify.topology.python import extract as extract_python
from launchverify.topology.qos import (
    Overriding,
    Qos,
    incompatible,
    overridden,
    overriding_of,
    qos_of,
)


def _cpp(body: str) -> dict[str, Parameter]:
    code = ("class N : public rclcpp::Node {\n public:\n  N() : Node(\"n\") {\n"
            f"{body}\n  }}\n}};\n")
    return {p.name: p for p in extract_cpp(Path("n.cpp"), code.encode()).parameters}


CPP_CASES = [
    # body, name, (type, default, dynamic, required)
    ('declare_parameter("speed", 0.5);', "speed", ("double", 0.5, False, False)),
    ('declare_parameter("count", 4);', "count", ("integer", 4, False, False)),
    ('declare_parameter("on", true);', "on", ("bool", True, False, False)),
    ('declare_parameter("frame", std::string("base"));', "frame", ("string", None, False, False)),
    ('declare_parameter<double>("gain", 1);', "gain", ("double", 1, False, False)),
    ('declare_parameter<std::string>("port");', "port", ("string", None, False, True)),
    ('declare_parameter("port", rclcpp::PARAMETER_STRING);', "port",
     ("string", None, False, False)),  # declared unset: the code may check for it
    ('declare_parameter("v", std::vector<double>{1.0, 2.0});', "v",
     ("double_array", None, False, False)),
    ('declare_parameter("neg", -2.5);', "neg", ("double", -2.5, False, False)),
    ('declare_parameter("x", 1.0, make_descriptor());', "x", ("double", 1.0, True, False)),
    ('rcl_interfaces::msg::ParameterDescriptor d; d.dynamic_typing = true;\n'
     'declare_parameter("y", 1.0, d);', "y", ("double", 1.0, True, False)),
    ('try { declare_parameter<int>("maybe"); } catch (...) {}', "maybe",
     ("integer", None, False, False)),
    ('nav2::declare_parameter_if_not_declared(node, "rate", rclcpp::ParameterValue(2.0));',
     "rate", ("double", 2.0, False, False)),
    ('declare_parameter(plugin_name_ + ".max_vel", 0.5);', "*.max_vel",
     ("double", 0.5, False, False)),
    # controller_manager's: a name formatted at run time keeps its literal parts
    ('const std::string p = fmt::format(FMT_COMPILE("{}.type"), name);\n'
     'declare_parameter(p, rclcpp::ParameterType::PARAMETER_STRING);', "*.type",
     ("string", None, False, False)),
    ('declare_parameter(fmt::format("{}.{}.gain", a, b), 1.0);', "*.*.gain",
     ("double", 1.0, False, False)),
]


@pytest.mark.parametrize(("body", "name", "expected"), CPP_CASES)
def test_cpp_declarations(body: str, name: str, expected: tuple[object, ...]) -> None:
    found = _cpp(body)
    assert name in found, sorted(found)
    parameter = found[name]
    assert (parameter.type, parameter.default, parameter.dynamic, parameter.required) == expected


def test_a_helper_forwarding_its_argument_declares_nothing() -> None:
    code = (b"template<typename T> T get_or(const std::string & name, const T & value) {\n"
            b"  return node_->declare_parameter(name, value);\n}\n")
    assert extract_cpp(Path("h.hpp"), code).parameters == ()


def test_a_helper_forwarding_its_argument_through_a_descriptor_declares_nothing() -> None:
    """nav2_util: ``descriptor.name = name; declare_parameter(descriptor.name, ...)``."""
    code = (b"void add_parameter(const std::string & name, const rclcpp::ParameterValue & v) {\n"
            b"  auto descriptor = rcl_interfaces::msg::ParameterDescriptor();\n"
            b"  descriptor.name = name;\n"
            b"  declare_parameter(descriptor.name, v, descriptor);\n}\n")
    assert extract_cpp(Path("h.hpp"), code).parameters == ()


def test_a_local_reused_across_functions_takes_its_own_functions_value() -> None:
    code = (b"void A::load(const std::string & c) {\n"
            b'  const std::string param_name = c + ".type";\n'
            b"  declare_parameter(param_name, rclcpp::ParameterType::PARAMETER_STRING);\n}\n"
            b"void A::files(const std::string & c) {\n"
            b'  const std::string param_name = c + ".params_file";\n'
            b"  declare_parameter(param_name, std::vector<std::string>{});\n}\n")
    assert sorted(p.name for p in extract_cpp(Path("a.cpp"), code).parameters) == [
        "*.params_file", "*.type"]


def test_descriptor_ranges_become_bounds() -> None:
    found = _cpp('rcl_interfaces::msg::ParameterDescriptor d;\n'
                 'rcl_interfaces::msg::FloatingPointRange r;\n'
                 'r.set__from_value(0.0).set__to_value(1.0);\n'
                 'd.floating_point_range.push_back(r);\n'
                 'declare_parameter("ratio", 0.5, d);')
    assert found["ratio"].limits == (("bounds", (0.0, 1.0)),)


def test_options_that_accept_undeclared_parameters_are_read() -> None:
    code = (b"auto o = rclcpp::NodeOptions()"
            b".automatically_declare_parameters_from_overrides(true);\n"
            b'auto n = std::make_shared<rclcpp::Node>("n", o);\n')
    assert extract_cpp(Path("m.cpp"), code).undeclared is not None
    closed = b"auto o = rclcpp::NodeOptions().allow_undeclared_parameters(false);\n"
    assert extract_cpp(Path("m.cpp"), closed).undeclared is None


def test_python_declarations() -> None:
    code = b"""
from rcl_interfaces.msg import ParameterDescriptor
from rclpy.node import Node
from rclpy.parameter import Parameter

class Driver(Node):
    def __init__(self):
        super().__init__('driver')
        self.declare_parameter('baud', 115200)
        self.declare_parameter('port', Parameter.Type.STRING)
        self.declare_parameter('any', 0, ParameterDescriptor(dynamic_typing=True))
        self.declare_parameter('loose')
        self.declare_parameters('filters', [('enabled', True), ('window', 5.0)])
        self.declare_parameter(f'{self.get_name()}.rate', 1.0)
"""
    result = extract_python(Path("d.py"), code)
    found = {p.name: (p.type, p.default, p.dynamic, p.required) for p in result.parameters}
    assert found == {"baud": ("integer", 115200, False, False),
                     "port": ("string", None, False, False),
                     "any": ("integer", 0, True, False), "loose": (None, None, True, False),
                     "filters.enabled": ("bool", True, False, False),
                     "filters.window": ("double", 5.0, False, False),
                     "*.rate": ("double", 1.0, False, False)}
    assert not result.declarations_missed
    assert result.bases == (("Driver", "rclpy.node.Node"),)


def test_generate_parameter_library_definitions(tmp_path: Path) -> None:
    (tmp_path / "CMakeLists.txt").write_text(
        "generate_parameter_library(limiter_parameters src/limiter.yaml)\n")
    (tmp_path / "src").mkdir()
    (tmp_path / "src" / "limiter.yaml").write_text(
        "limiter:\n"
        "  speed: {type: double, default_value: 1.0, validation: {bounds<>: [0.0, 2.0]}}\n"
        "  mode: {type: string, default_value: a, validation: {one_of<>: [[a, b]]}}\n"
        "  topic: {type: string}\n"
        "  gains:\n    __map_joints:\n      p: {type: double, default_value: 0.0}\n")
    libraries = parameter_libraries(tmp_path)
    assert libraries == {"limiter_parameters": tmp_path / "src" / "limiter.yaml"}
    found = {p.name: p for p in definitions(libraries["limiter_parameters"])}
    assert found["speed"].limits == (("bounds", (0.0, 2.0)),)
    assert found["mode"].limits == (("one_of", (["a", "b"],)),)
    assert found["topic"].required and found["topic"].type == "string"
    assert "gains.*.p" in found and not found["gains.*.p"].required


QOS_CASES = [
    (["rclcpp::SensorDataQoS()"], ("best_effort", "volatile")),
    (["10"], ("reliable", "volatile")),
    (["rclcpp::QoS(1).transient_local()"], ("reliable", "transient_local")),
    (["rclcpp::QoS(rclcpp::KeepLast(5))", "qos.best_effort()"], ("best_effort", "volatile")),
    (["rclcpp::SystemDefaultsQoS()"], (None, None)),
    (["QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)"],
     ("reliable", "transient_local")),
    (["rclpy.qos.qos_profile_sensor_data"], ("best_effort", "volatile")),
    (["QoSProfile(depth=1, reliability=policy)"], (None, None)),  # from a variable
    (["rclcpp::QoS(1)", "qos.best_effort()", "qos.reliable()"], (None, "volatile")),
]


@pytest.mark.parametrize(("texts", "expected"), QOS_CASES)
def test_qos_profiles(texts: list[str], expected: tuple[str | None, str | None]) -> None:
    found = qos_of(texts)
    assert found is not None and (found.reliability, found.durability) == expected


def test_unknown_profiles_and_compatibility() -> None:
    assert qos_of(["make_qos()"]) is None and qos_of([]) is None
    best, reliable = Qos("best_effort", "volatile"), Qos("reliable", "volatile")
    latched = Qos("reliable", "transient_local")
    assert incompatible(best, reliable) and not incompatible(reliable, best)
    assert incompatible(reliable, latched) and not incompatible(latched, reliable)
    assert incompatible(Qos(None, None), reliable) is None


OVERRIDING_CASES = [
    (["options", "options.qos_overriding_options = rclcpp::QosOverridingOptions("
      "{rclcpp::QosPolicyKind::Reliability})"], Overriding(frozenset({"reliability"}))),
    (["rclcpp::QosOverridingOptions::with_default_policies()"],
     Overriding(frozenset({"history", "depth", "reliability"}))),
    (['QosOverridingOptions({QosPolicyKind::Reliability}, nullptr, "fast")'],
     Overriding(frozenset({"reliability"}), "fast")),
    (["QosOverridingOptions({QosPolicyKind::Durability}, check, id_)"],
     Overriding(frozenset({"durability"}), None)),  # an id from a variable
    (['o.qos_overriding_options = {{QosPolicyKind::LivelinessLeaseDuration}, nullptr, "x"}'],
     Overriding(frozenset({"liveliness_lease_duration"}), "x")),
    (["o.qos_overriding_options = {QosPolicyKind::Depth, QosPolicyKind::Durability, "
      "QosPolicyKind::History}"], Overriding(frozenset({"depth", "durability", "history"}))),
    (["QoSOverridingOptions.with_default_policies(\n  # entity_id='x',\n)"],
     Overriding(frozenset({"history", "depth", "reliability"}))),  # a comment is no id
    (["rclcpp::QosOverridingOptions(kinds)"], Overriding(None)),  # a list not spelt out
    (["QoSOverridingOptions([QoSPolicyKind.RELIABILITY, QoSPolicyKind.DURABILITY], "
      "entity_id='a')"], Overriding(frozenset({"reliability", "durability"}), "a")),
    (["QoSOverridingOptions.with_default_policies(entity_id=name)"],
     Overriding(frozenset({"history", "depth", "reliability"}), None)),
    (["rclcpp::QosOverridingOptions()"], None),  # the default: nothing opens
    (["QoSOverridingOptions([])"], None),
    (["rclcpp::PublisherOptions()"], None),
]


@pytest.mark.parametrize(("texts", "expected"), OVERRIDING_CASES)
def test_overriding_options(texts: list[str], expected: Overriding | None) -> None:
    assert overriding_of(texts) == expected


def test_options_argument_opens_the_endpoint() -> None:
    """The options (third argument, or fourth after a callback) carry the opt-in."""
    code = (
        "void f(rclcpp::Node * node) {\n"
        "  rclcpp::PublisherOptions options;\n"
        "  options.qos_overriding_options = rclcpp::QosOverridingOptions::"
        "with_default_policies();\n"
        "  node->create_publisher<std_msgs::msg::String>(\"a\", rclcpp::SensorDataQoS(),"
        " options);\n"
        "  node->create_subscription<std_msgs::msg::String>(\"b\", 10, cb, options);\n"
        "  node->create_publisher<std_msgs::msg::String>(\"c\", 10);\n}\n")
    found = {e.name: e.profile for e in extract_cpp(Path("n.cpp"), code.encode()).endpoints}
    assert found["a"] is not None and found["a"].overriding is not None
    assert found["a"].reliability == "best_effort"
    assert found["b"] is not None and found["b"].overriding is not None
    assert found["c"] is not None and found["c"].overriding is None
    lambda_built = (
        "static const auto kOpts = [] {\n  rclcpp::PublisherOptions options;\n"
        "  options.qos_overriding_options = {rclcpp::QosPolicyKind::Reliability};\n"
        "  return options;\n}();\n"
        "void g(rclcpp::Node * node) {\n"
        "  node->create_publisher<std_msgs::msg::String>(\"d\", 10, kOpts);\n}\n")
    [end] = extract_cpp(Path("n.cpp"), lambda_built.encode()).endpoints
    assert end.profile == Qos("reliable", "volatile", Overriding(frozenset({"reliability"})))
    python = ("self.create_publisher(String, 'a', make_qos(), "
              "qos_overriding_options=QoSOverridingOptions([QoSPolicyKind.DURABILITY]))\n")
    [end] = extract_python(Path("n.py"), python.encode()).endpoints
    assert end.profile == Qos(None, None, Overriding(frozenset({"durability"})))


class _Given:
    def __init__(self, value: object) -> None:
        self.value = value


class _Received:
    """What a node receives, as ``EffectiveParameters`` answers it."""

    def __init__(self, values: dict[str, object], complete: bool = True) -> None:
        self.values = {name: [_Given(value)] for name, value in values.items()}
        self.complete = complete
        self.fqn = "/n"

    def winner(self, name: str) -> _Given | None:
        found = self.values.get(name)
        return found[-1] if found else None


OVERRIDE_CASES = [
    # policies, id, what the node receives, (reliability, durability) after
    ({"reliability"}, "", {"qos_overrides./s.publisher.reliability": "reliable"},
     ("reliable", "volatile")),
    ({"reliability"}, "", {"qos_overrides./s.publisher.durability": "transient_local"},
     ("best_effort", "volatile")),  # durability is not opened
    ({"reliability"}, "", {"qos_overrides./scan.publisher.reliability": "reliable"},
     ("best_effort", "volatile")),  # another topic's
    ({"reliability"}, "", {"qos_overrides./s.publisher.reliability": None},
     (None, "volatile")),  # not known before launch
    ({"reliability"}, "", {"qos_overrides./s.publisher.reliability": "system_default"},
     (None, "volatile")),
    ({"reliability"}, "", {"qos_overrides./s.publisher.reliability": "RELIABLE"},
     (None, "volatile")),  # rclcpp throws: the endpoint is never made
    ({"reliability"}, "x", {"qos_overrides./s.publisher.reliability": "reliable"},
     ("best_effort", "volatile")),  # its parameters are publisher_x.*
    ({"reliability"}, "x", {"qos_overrides./s.publisher_x.reliability": "reliable"},
     ("reliable", "volatile")),
    ({"reliability"}, None, {"qos_overrides./s.publisher_x.reliability": "reliable"},
     (None, "volatile")),  # an id not known here: it may be this one
    (None, "", {"qos_overrides./s.publisher.reliability": "reliable"},
     (None, "volatile")),  # a list not read: it may or may not be opened
]


@pytest.mark.parametrize(("policies", "entity", "received", "expected"), OVERRIDE_CASES)
def test_overrides_applied(policies: set[str] | None, entity: str | None,
                           received: dict[str, object],
                           expected: tuple[str | None, str | None]) -> None:
    opened = Overriding(None if policies is None else frozenset(policies), entity)
    profile = Qos("best_effort", "volatile", opened)
    found, _ = overridden(profile, "/s", "publisher", _Received(received))  # type: ignore[arg-type]
    assert (found.reliability, found.durability) == expected


def test_overrides_case_and_unread_sources() -> None:
    profile = Qos("best_effort", "volatile", Overriding(frozenset({"reliability"})))
    given = _Received({"qos_overrides./s.publisher.reliability": "RELIABLE"})
    found, settled = overridden(profile, "/s", "publisher", given, python=True)  # type: ignore[arg-type]
    assert found.reliability == "reliable" and [n for n, _ in settled] == [
        "qos_overrides./s.publisher.reliability"]  # rclpy reads any case
    found, _ = overridden(profile, "/s", "publisher", _Received({}, complete=False))  # type: ignore[arg-type]
    assert found.reliability is None and found.durability == "volatile"


def test_build_files_name_no_file_outside_their_package(tmp_path: Path) -> None:
    """A pull request's CMakeLists.txt or #include cannot make the reader open a secret."""
    from launchverify.workspace.packages import PackageIndex

    secret = tmp_path / "secret.yaml"
    secret.write_text("leak:\n  token: {type: string, default_value: hunter2}\n")
    package = tmp_path / "ws" / "pkg"
    (package / "include" / "pkg").mkdir(parents=True)
    (package / "package.xml").write_text(
        "<package format='3'><name>pkg</name><version>0.0.0</version><description>d"
        "</description><maintainer email='a@b.c'>m</maintainer><license>MIT</license>"
        "</package>")
    (package / "CMakeLists.txt").write_text(
        "generate_parameter_library(leak ../../secret.yaml)\n"
        f"generate_parameter_library(abs {secret})\n")
    assert parameter_libraries(package) == {}
    index = PackageIndex([tmp_path / "ws"])
    assert index.header("pkg/../../../secret.yaml") is None
    (package / "include" / "pkg" / "base.hpp").write_text("// a header\n")
    assert index.header("pkg/base.hpp") == package / "include" / "pkg" / "base.hpp"


def _package(root: Path, name: str, files: dict[str, str]) -> Path:
    folder = root / name
    for relative, text in files.items():
        (folder / relative).parent.mkdir(parents=True, exist_ok=True)
        (folder / relative).write_text(text)
    (folder / "package.xml").write_text(
        f"<package format='3'><name>{name}</name><version>0.0.0</version><description>d"
        "</description><maintainer email='a@b.c'>m</maintainer><license>MIT</license>"
        "</package>")
    return folder


def test_a_base_class_in_a_sibling_package_declares_on_the_node(tmp_path: Path) -> None:
    """rtabmap's nodes derive from ``CommonDataSubscriber`` (another package): what its code
    declares is the node's; a base whose code is nowhere leaves the node open."""
    from launchverify.topology.nodes import package_interfaces
    from launchverify.workspace.packages import Package, PackageIndex

    _package(tmp_path, "sync", {
        "include/sync/subscriber.hpp": "namespace sync { class Subscriber {\n public:\n"
                                       "  void setup(rclcpp::Node & node);\n}; }\n",
        "src/subscriber.cpp": '#include "sync/subscriber.hpp"\nnamespace sync {\n'
                              "void Subscriber::setup(rclcpp::Node & node) {\n"
                              '  node.declare_parameter("approx_sync", true);\n}\n}\n'})
    node = ('#include "sync/subscriber.hpp"\n#include "rclcpp/rclcpp.hpp"\n'
            "class Viz : public rclcpp::Node, public {base} {{\n public:\n"
            '  Viz() : Node("viz") {{ declare_parameter("rate", 1.0); }}\n}};\n'
            "int main() {{ return 0; }}\n")
    cmake = ("cmake_minimum_required(VERSION 3.8)\nproject(viz)\n"
             "add_executable(viz src/viz.cpp)\ninstall(TARGETS viz DESTINATION lib/viz)\n")
    for base, declared, open_ in (("sync::Subscriber", {"rate", "approx_sync"}, None),
                                  ("other::Mixin", {"rate"}, "other::Mixin")):
        folder = _package(tmp_path / base.replace("::", "_"), "viz",
                          {"CMakeLists.txt": cmake, "src/viz.cpp": node.format(base=base)})
        index = PackageIndex([tmp_path / base.replace("::", "_"), tmp_path / "sync"])
        interface = next(i for i in package_interfaces(Package("viz", source=folder),
                                                       index.lookup())
                         if i.executable == "viz")
        assert {p.name for p in interface.parameters} == declared
        if open_ is None:
            assert interface.parameters_open is None
        else:
            assert interface.parameters_open is not None and "Mixin" in \
                interface.parameters_open
