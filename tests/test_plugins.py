"""pluginlib plugins: what descriptions export, and what each plugin declares."""

from __future__ import annotations

from pathlib import Path

from launchverify.topology.plugin_xml import package_descriptions
from launchverify.topology.plugins import derives, plugin_contracts
from launchverify.workspace.packages import Package

CMAKE = """cmake_minimum_required(VERSION 3.8)
project(demo_controllers)
find_package(ament_cmake REQUIRED)
add_library(demo_controllers SHARED src/follow.cpp)
pluginlib_export_plugin_description_file(demo_core plugins.xml)
ament_package()
"""
PLUGINS = """<library path="demo_controllers">
  <class type="demo_controllers::Follow" base_class_type="demo_core::Controller">
    <description>follows</description>
  </class>
  <class type="demo_controllers::Other" base_class_type="demo_core::Planner"/>
</library>
"""
SOURCE = """#include "demo_core/controller.hpp"
namespace demo_controllers {
class Follow : public demo_core::Controller {
  void configure(const std::string & name) override {
    plugin_name_ = name;
    node->declare_parameter(plugin_name_ + ".gain", 1.5);
    node->declare_parameter("shared_rate", 10.0);
  }
  std::string plugin_name_;
};
}
"""


def _package(root: Path) -> Package:
    folder = root / "demo_controllers"
    (folder / "src").mkdir(parents=True)
    (folder / "package.xml").write_text(
        '<?xml version="1.0"?><package format="3"><name>demo_controllers</name>'
        "<version>0.0.0</version><description>d</description>"
        '<maintainer email="a@b.c">a</maintainer><license>MIT</license></package>\n')
    (folder / "CMakeLists.txt").write_text(CMAKE)
    (folder / "plugins.xml").write_text(PLUGINS)
    (folder / "src" / "follow.cpp").write_text(SOURCE)
    return Package("demo_controllers", source=folder)


def test_descriptions_name_each_class_its_base_and_library(tmp_path: Path) -> None:
    package = _package(tmp_path)
    assert package.source is not None
    found = package_descriptions(package.source)
    assert [(e.library, e.type, e.base) for e in found] == [
        ("demo_controllers", "demo_controllers::Follow", "demo_core::Controller"),
        ("demo_controllers", "demo_controllers::Other", "demo_core::Planner")]


def test_a_loader_gets_what_its_plugins_declare(tmp_path: Path) -> None:
    package = _package(tmp_path)
    (contract,) = plugin_contracts([package], ("demo_core::Controller",))
    assert contract.type == "demo_controllers::Follow"
    assert {p.name for p in contract.parameters} == {"*.gain", "shared_rate"}
    assert plugin_contracts([package], ("other::Base",)) == ()


def test_an_unqualified_loader_matches_by_class_name() -> None:
    assert derives("nav2_costmap_2d::Layer", "Layer")
    assert not derives("nav2_costmap_2d::Layer", "other::Layer")
    assert derives("::a::B", "a::B")
