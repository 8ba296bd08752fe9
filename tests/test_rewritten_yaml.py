"""nav2's ``RewrittenYaml``: nodes get the file as it is rewritten, not as it is written.

Leaf keys and dotted paths take the launch's values, paths through ``ros__parameters``
are added, a root key moves every block under it; what is rewritten beyond that
(``key_rewrites``) leaves the node's parameters unknown instead of the source's.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from launchverify.cli import main
from launchverify.engine import CheckOptions, run_check

PARAMS = """\
amcl:
  ros__parameters:
    use_sim_time: false
    alpha1: 0.2
    scan_topic: scan
planner_server:
  ros__parameters:
    use_sim_time: false
    GridBased:
      use_sim_time: false
      tolerance: 0.5
"""

LAUNCH = """\
import os
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node, PushRosNamespace
from nav2_common.launch import RewrittenYaml

HERE = os.path.dirname(__file__)


def generate_launch_description():
    namespace = LaunchConfiguration('namespace')
    configured = RewrittenYaml(
        source_file={source},
        root_key=namespace,
        param_rewrites={{'use_sim_time': LaunchConfiguration('use_sim_time'),
                         'amcl.ros__parameters.alpha1': '0.7',
                         'planner_server.ros__parameters.expected_planner_frequency': '20'}},
        {extra}convert_types={convert})
    return LaunchDescription([
        DeclareLaunchArgument('namespace', default_value=''),
        DeclareLaunchArgument('use_sim_time', default_value='true'),
        GroupAction([
            PushRosNamespace(namespace),
            Node(package='nav2_amcl', executable='amcl', name='amcl', parameters=[configured]),
            Node(package='nav2_planner', executable='planner_server', name='planner_server',
                 parameters=[configured]),
        ]),
    ])
"""
SOURCE = "os.path.join(HERE, 'params.yaml')"


def _parameters(tmp_path: Path, capsys: pytest.CaptureFixture[str], *arguments: str,
                source: str = SOURCE, extra: str = "", convert: str = "True"
                ) -> dict[str, dict[str, object]]:
    (tmp_path / "params.yaml").write_text(PARAMS)
    launch = tmp_path / "nav.launch.py"
    launch.write_text(LAUNCH.format(source=source, extra=extra, convert=convert))
    assert main(["graph", str(launch), "--workspace", str(tmp_path), *arguments]) == 0
    nodes = json.loads(capsys.readouterr().out)["nodes"]
    return {node["fqn"]: {name: (entry["value"], Path(entry["from"]).name)
                          for name, entry in node["effective_parameters"].items()}
            for node in nodes}


def test_rewrites_are_what_the_nodes_get(tmp_path: Path,
                                         capsys: pytest.CaptureFixture[str]) -> None:
    assert _parameters(tmp_path, capsys) == {
        "/amcl": {"use_sim_time": (True, "nav.launch.py:13"),  # a leaf key
                  "alpha1": (0.7, "nav.launch.py:13"),  # a dotted path
                  "scan_topic": ("scan", "params.yaml:5")},
        "/planner_server": {"use_sim_time": (True, "nav.launch.py:13"),
                            "GridBased.use_sim_time": (True, "nav.launch.py:13"),  # nested
                            "GridBased.tolerance": (0.5, "params.yaml:11"),
                            "expected_planner_frequency": (20, "nav.launch.py:13")}}  # added


def test_a_root_key_moves_the_blocks_under_it(tmp_path: Path,
                                              capsys: pytest.CaptureFixture[str]) -> None:
    found = _parameters(tmp_path, capsys, "namespace:=robot1", "use_sim_time:=false")
    assert set(found) == {"/robot1/amcl", "/robot1/planner_server"}
    assert found["/robot1/amcl"]["use_sim_time"] == (False, "nav.launch.py:13")
    assert found["/robot1/amcl"]["scan_topic"] == ("scan", "params.yaml:5")


def test_a_file_rewritten_twice_keeps_both_rewrites(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    inner = ("RewrittenYaml(source_file=os.path.join(HERE, 'params.yaml'), "
             "param_rewrites={'scan_topic': 'base_scan', 'alpha1': '0.1'}, convert_types=True)")
    found = _parameters(tmp_path, capsys, source=inner)["/amcl"]
    assert found["scan_topic"] == ("base_scan", "nav.launch.py:13")
    assert found["alpha1"] == (0.7, "nav.launch.py:13")  # the later rewrite wins


def test_what_is_not_followed_leaves_the_values_unknown(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    found = _parameters(tmp_path, capsys, extra="key_rewrites={'scan': 'base_scan'}, ")
    assert found == {"/amcl": {}, "/planner_server": {}}  # not the source's values
    unknown = _parameters(tmp_path, capsys, convert="LaunchConfiguration('convert')")
    assert unknown == {"/amcl": {}, "/planner_server": {}}  # the values' types


def test_value_rewrites_replace_values_by_their_text(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """nav2 marks values to replace (``enabled: KEEPOUT_ZONE_ENABLED``)."""
    found = _parameters(tmp_path, capsys, extra="value_rewrites={'scan': 'base_scan'}, ")
    assert found["/amcl"]["scan_topic"] == ("base_scan", "nav.launch.py:13")
    assert found["/amcl"]["alpha1"] == (0.7, "nav.launch.py:13")


SPAWNED = """\
import os
from launch import LaunchDescription
from launch_ros.actions import Node
from nav2_common.launch import RewrittenYaml


def generate_launch_description():
    types = RewrittenYaml(source_file=os.path.join(os.path.dirname(__file__), 'types.yaml'),
                          root_key='{root}', param_rewrites={{}})
    return LaunchDescription([
        Node(package='controller_manager', executable='ros2_control_node', namespace='robot1'),
        Node(package='controller_manager', executable='spawner', namespace='robot1',
             arguments=['arm_controller', '-c', '/robot1/controller_manager'],
             parameters=[types]),
    ])
"""


@pytest.mark.parametrize(("root", "codes"), [("robot1", []), ("robot2", ["LV507"])])
def test_a_spawners_file_under_a_root_key_gives_types_there(
        tmp_path: Path, root: str, codes: list[str]) -> None:
    """The spawner reads the type under the controller's own name, namespace included."""
    (tmp_path / "types.yaml").write_text(
        "arm_controller:\n  ros__parameters:\n"
        "    type: joint_trajectory_controller/JointTrajectoryController\n")
    (tmp_path / "arm.launch.py").write_text(SPAWNED.format(root=root))
    report = run_check(CheckOptions(paths=[tmp_path], workspace=tmp_path))
    assert [f.code for f in report.findings if f.code.startswith("LV5")] == codes, [
        f.message for f in report.findings]
