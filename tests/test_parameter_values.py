"""Parameter values are typed as launch_ros types them (YAML rules, forced types, plain str)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from launchverify.cli import main
from launchverify.models.parameter_values import typed_parameter


@pytest.mark.parametrize(("text", "value_type", "expected"), [
    ("5", None, 5),
    ("2.5", None, 2.5),
    ("true", None, True),
    ("True", None, True),
    ("yes", None, True),  # PyYAML 1.1 booleans, as launch_ros reads them
    ("", None, ""),
    ("base_link", None, "base_link"),
    ("[1, 2]", None, (1, 2)),
    ("['a', 'b']", None, ("a", "b")),
    ("[1, 'a']", None, "[1, 'a']"),  # mixed list: launch_ros refuses, the text is kept
    ("{a: 1}", None, "{a: 1}"),  # a mapping is refused too
    ("~", None, "~"),  # null
    ("5", "str", "5"),
    ("5", "int", 5),
    ("5", "float", 5.0),
    ("abc", "int", "abc"),
    ("true", "bool", True),
    ("1", "bool", "1"),
    ("0x10", None, 16),
])
def test_typed_parameter(text: str, value_type: str | None, expected: object) -> None:
    value = typed_parameter(text, value_type)
    assert value == expected and type(value) is type(expected)


PYTHON = """\
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node, SetParameter
from launch_ros.parameter_descriptions import ParameterValue


def generate_launch_description():
    rate = LaunchConfiguration('rate')
    return LaunchDescription([
        DeclareLaunchArgument('rate', default_value='5'),
        SetParameter(name='use_sim_time', value='true'),
        Node(package='demo_nodes_cpp', executable='talker', parameters=[{
            'plain': '5',
            'from_argument': rate,
            'forced': ParameterValue(rate, value_type=str),
            'wrapped': ParameterValue('7'),
            'words': ['1', '2'],
            'number': 3,
        }]),
    ])
"""

XML = """\
<launch>
  <arg name="rate" default="5"/>
  <set_parameter name="use_sim_time" value="true"/>
  <node pkg="demo_nodes_cpp" exec="talker">
    <param name="plain" value="5"/>
    <param name="from_argument" value="$(var rate)"/>
    <param name="forced" value="$(var rate)" type="str"/>
    <param name="listed" value="1,2" value-sep=","/>
  </node>
</launch>
"""


def parameters(path: Path, capsys: pytest.CaptureFixture[str]) -> dict[str, object]:
    assert main(["graph", str(path)]) == 0
    node = json.loads(capsys.readouterr().out)["nodes"][0]
    return {p["name"]: p["value"] for p in node["parameters"]}


def test_python_values(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """Checked against launch_ros (rolling) with the oracle, except ``words``: launch_ros
    dumps that list as a Python tuple, which the oracle cannot read back."""
    path = tmp_path / "types.launch.py"
    path.write_text(PYTHON)
    assert parameters(path, capsys) == {
        "use_sim_time": "true",  # a plain str given to SetParameter stays a string
        "plain": "5", "from_argument": 5, "forced": "5", "wrapped": "7",
        "words": ["1", "2"], "number": 3,
    }


def test_frontend_values(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = tmp_path / "types.launch.xml"
    path.write_text(XML)
    assert parameters(path, capsys) == {
        "use_sim_time": True, "plain": 5, "from_argument": 5, "forced": "5", "listed": [1, 2],
    }
