"""Paths into a package that is not built: show what the user can open.

``$(find-pkg-share pkg)/config/x.yaml`` stands for the package's sources when it is not
built, where CMake may install ``bringup/config`` as ``share/pkg/config``: the folder
``pkg/config`` does not exist. Messages name the installed file and the source folder,
and the did-you-mean looks there.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from launchverify.cli import main

PACKAGE_XML = """<?xml version="1.0"?>
<package format="3"><name>demo_bringup</name><version>0.0.1</version>
<description>d</description><maintainer email="a@b.c">a</maintainer><license>MIT</license>
<buildtool_depend>ament_cmake</buildtool_depend>
<export><build_type>ament_cmake</build_type></export></package>
"""
CMAKE = """cmake_minimum_required(VERSION 3.8)
project(demo_bringup)
find_package(ament_cmake REQUIRED)
install(DIRECTORY bringup/launch bringup/config DESTINATION share/${PROJECT_NAME})
ament_package()
"""
LAUNCH = """<launch>
  <node pkg="demo_nodes_cpp" exec="talker" name="driver">
    <param from="$(find-pkg-share demo_bringup)/config/{name}"/>
  </node>
</launch>
"""


def _package(root: Path, name: str) -> Path:
    package = root / "demo_bringup"
    (package / "bringup" / "launch").mkdir(parents=True)
    (package / "bringup" / "config").mkdir()
    (package / "package.xml").write_text(PACKAGE_XML)
    (package / "CMakeLists.txt").write_text(CMAKE)
    (package / "bringup" / "config" / "driver.yaml").write_text(
        "driver:\n  ros__parameters:\n    rate: 10.0\n")
    launch = package / "bringup" / "launch" / "driver.launch.xml"
    launch.write_text(LAUNCH.replace("{name}", name))
    (root / ".git").mkdir()
    return launch


def test_a_missing_file_is_named_as_installed_with_the_folder_to_open(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    launch = _package(tmp_path, "drivr.yaml")
    assert main(["check", str(launch), "--format", "json", "--no-cache"]) == 1
    [finding] = [f for f in json.loads(capsys.readouterr().out)["findings"]
                 if f["code"] == "LV302"]
    assert finding["message"].startswith(
        "parameter file 'share/demo_bringup/config/drivr.yaml' does not exist (config/ "
        "would be installed from ")
    assert "demo_bringup/bringup/config; did you mean 'driver.yaml'?)" in finding["message"]
    assert finding["fix"]["applicability"] == "safe"
    assert finding["fix"]["edits"][0]["content"] == "driver.yaml"


def test_the_correct_file_is_found_through_the_install_layout(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    launch = _package(tmp_path, "driver.yaml")
    assert main(["check", str(launch), "--format", "json", "--no-cache"]) == 0
    capsys.readouterr()
    assert main(["run", str(launch), "--dry-run", "--log-dir", str(tmp_path / "log")]) == 0
    out = capsys.readouterr().out
    assert "config/driver.yaml: not built here, installed from " in out
    assert "demo_bringup/bringup/config/driver.yaml" in out
