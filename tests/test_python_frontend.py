"""The Python frontend: no side effects, limits, isolation, exact lines, OpaqueFunction."""

from __future__ import annotations

import json
import os
import sys
from pathlib import Path

import pytest

from launchverify.cli import main
from launchverify.engine import CheckOptions, run_check

HEADER = """\
import os
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
"""


def write(folder: Path, name: str, body: str) -> Path:
    path = folder / name
    path.write_text(HEADER + body)
    return path


def findings(path: Path, *arguments: str, time_limit: float = 10.0
             ) -> list[tuple[str, int, str]]:
    pinned = dict(a.split(":=") for a in arguments)
    report = run_check(CheckOptions(paths=[path], arguments=pinned, workspace=path.parent,
                                    time_limit=time_limit))
    return [(f.code, f.span.line, f.message) for f in report.findings]


def test_side_effects_are_refused(tmp_path: Path) -> None:
    target = tmp_path / "written.txt"
    victim = tmp_path / "victim.txt"
    victim.write_text("keep me")
    body = f"""
import subprocess, socket, shutil

def generate_launch_description():
    for attempt in (
        lambda: subprocess.run(['touch', {str(tmp_path / 'touched')!r}]),
        lambda: open({str(target)!r}, 'w').write('x'),
        lambda: os.remove({str(victim)!r}),
        lambda: socket.create_connection(('127.0.0.1', 9)),
        lambda: os.chdir('/'),
        lambda: os.system('true'),
    ):
        try:
            attempt()
        except PermissionError:
            pass
    os.environ['LV_SET_BY_LAUNCH_FILE'] = '1'
    return LaunchDescription([])
"""
    path = write(tmp_path, "effects.launch.py", body)
    cwd = Path.cwd()
    result = findings(path)
    # every refusal is reported, even when the launch file catches the exception
    assert {code for code, _, _ in result} == {"LV003"} and len(result) == 6
    assert not target.exists() and not (tmp_path / "touched").exists()
    assert victim.read_text() == "keep me"
    assert Path.cwd() == cwd
    assert "LV_SET_BY_LAUNCH_FILE" not in os.environ


def test_refused_side_effect_is_reported(tmp_path: Path) -> None:
    body = """
import subprocess
OUTPUT = subprocess.run(['ros2', 'component', 'types'], capture_output=True)

def generate_launch_description():
    return LaunchDescription([])
"""
    path = write(tmp_path, "runs.launch.py", body)
    [(code, line, message)] = findings(path)
    assert code == "LV003" and line == 8 and "subprocess.run would run" in message


def test_endless_loop_is_stopped(tmp_path: Path) -> None:
    body = """
def generate_launch_description():
    while True:
        pass
"""
    path = write(tmp_path, "loop.launch.py", body)
    [(code, line, message)] = findings(path, time_limit=0.3)
    assert code == "LV002" and "longer than 0.3 s" in message and line in (8, 9)


def test_exception_points_at_the_raising_line(tmp_path: Path) -> None:
    body = """
def generate_launch_description():
    names = {'a': 1}
    return LaunchDescription([Node(package='demo_nodes_cpp', executable=names['b'])])
"""
    path = write(tmp_path, "raises.launch.py", body)
    [(code, line, message)] = findings(path)
    assert (code, line) == ("LV002", 9) and "KeyError" in message


def test_old_keywords_are_rejected_like_the_real_api(tmp_path: Path) -> None:
    body = """
def generate_launch_description():
    return LaunchDescription([Node(package='demo_nodes_cpp', node_executable='talker')])
"""
    [(code, _, message)] = findings(write(tmp_path, "old.launch.py", body))
    assert code == "LV002" and "TypeError" in message


def test_helper_module_lines_and_isolation(tmp_path: Path) -> None:
    (tmp_path / "robot_helpers.py").write_text(
        "from launch_ros.actions import Node\n\n\n"
        "def camera(name):\n"
        "    return Node(package='usb_cam', executable='usb_cam_node_exe', name=name)\n"
    )
    body = """
import sys
sys.path.append(os.path.dirname(__file__))  # ros2 launch does not put it on sys.path
from robot_helpers import camera

def generate_launch_description():
    return LaunchDescription([camera('cam'), camera('cam')])
"""
    path = write(tmp_path, "helpers.launch.py", body)
    result = findings(path)
    assert [(code, line) for code, line, _ in result] == [("LV101", 5)]
    assert "robot_helpers" not in sys.modules
    assert str(tmp_path) not in sys.path
    assert "launch" not in sys.modules or "launchverify" in repr(sys.modules["launch"])


def test_sibling_module_without_sys_path_fails_like_ros2_launch(tmp_path: Path) -> None:
    (tmp_path / "robot_helpers.py").write_text("VALUE = 1\n")
    body = """
from robot_helpers import VALUE

def generate_launch_description():
    return LaunchDescription([])
"""
    [(code, line, message)] = findings(write(tmp_path, "sibling.launch.py", body))
    assert (code, line) == ("LV002", 7) and "ModuleNotFoundError" in message


def test_environment_is_symbolic(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    body = """
def generate_launch_description():
    robot = os.environ['ROBOT_NAME']
    model = os.getenv('ROBOT_MODEL', 'burger')
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name='driver', namespace=robot),
        Node(package='demo_nodes_cpp', executable='talker', name=model),
    ])
"""
    path = write(tmp_path, "env.launch.py", body)
    assert main(["graph", str(path), "--symbolic"]) == 0
    nodes = json.loads(capsys.readouterr().out)["nodes"]
    assert nodes[0]["namespace"] == "/$(env ROBOT_NAME)"
    assert nodes[0]["fqn"] == "/$(env ROBOT_NAME)/driver"
    # os.getenv with a default reads as $(env NAME default): an input, not the default
    assert nodes[1]["name"] == "$(env ROBOT_MODEL burger)"
    # what --env gives, every reading sees
    assert main(["graph", str(path), "--env", "ROBOT_MODEL=waffle", "--env",
                 "ROBOT_NAME=alpha"]) == 0
    nodes = json.loads(capsys.readouterr().out)["nodes"]
    assert [n["fqn"] for n in nodes] == ["/alpha/driver", "/waffle"]


def test_opaque_function_sees_the_arguments(tmp_path: Path) -> None:
    body = """
def setup(context):
    count = int(LaunchConfiguration('count').perform(context))
    return [Node(package='demo_nodes_cpp', executable='talker', name=f'talker_{i}')
            for i in range(count)]

def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('count', default_value='2'),
        OpaqueFunction(function=setup),
        Node(package='demo_nodes_cpp', executable='talker', name='talker_2'),
    ])
"""
    path = write(tmp_path, "opaque.launch.py", body)
    assert findings(path) == []
    assert [(code, line) for code, line, _ in findings(path, "count:=3")] == [("LV101", 16)]


def test_unknown_import_is_opaque_and_reported_once(tmp_path: Path) -> None:
    body = """
import acme_vendor_sdk
from acme_vendor_sdk.tools import helper

def generate_launch_description():
    helper(acme_vendor_sdk.CONFIG)
    return LaunchDescription([])
"""
    result = findings(write(tmp_path, "vendor.launch.py", body))
    assert [(code, line) for code, line, _ in result] == [("LV003", 7)]


def test_syntax_error_and_missing_entry_point(tmp_path: Path) -> None:
    broken = tmp_path / "broken.launch.py"
    broken.write_text("def generate_launch_description(:\n    pass\n")
    [(code, line, _)] = findings(broken)
    assert (code, line) == ("LV001", 1)
    empty = write(tmp_path, "empty.launch.py", "\nVALUE = 1\n")
    [(code, _, message)] = findings(empty)
    assert code == "LV001" and "generate_launch_description" in message


@pytest.mark.parametrize(("key", "runs"), [("slam_toolbox", [True, False]),
                                           ("amcl", [False, True])])
def test_nav2_has_node_params_reads_the_parameter_file(tmp_path: Path, key: str,
                                                       runs: list[bool]) -> None:
    (tmp_path / "params.yaml").write_text(f"{key}:\n  ros__parameters:\n    x: 1\n")
    path = tmp_path / "slam.launch.py"
    path.write_text("""
import os
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition, UnlessCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from nav2_common.launch import HasNodeParams


def generate_launch_description():
    params = LaunchConfiguration('params_file')
    has = HasNodeParams(source_file=params, node_name='slam_toolbox')
    return LaunchDescription([
        DeclareLaunchArgument('params_file', default_value=os.path.join(
            os.path.dirname(__file__), 'params.yaml')),
        Node(package='slam_toolbox', executable='a', name='with_params',
             condition=IfCondition(has)),
        Node(package='slam_toolbox', executable='b', name='without_params',
             condition=UnlessCondition(has)),
    ])
""")
    graph = run_check(CheckOptions(paths=[path], workspace=tmp_path)).graphs[0]
    assert [graph.runs(node.origin) for node in graph.nodes] == runs


def test_findings_stay_in_the_launch_file_that_imports_another(tmp_path: Path) -> None:
    # realsense's rs_multi_camera_launch.py runs rs_launch.launch_setup this way: places
    # in the imported launch file go to the line of the importing file that reached them.
    (tmp_path / "base_launch.py").write_text(HEADER + """
def launch_setup(context):
    return [Node(package='usb_cam', executable='usb_cam_node_exe', name='cam'),
            Node(package='usb_cam', executable='usb_cam_node_exe', name='cam')]

def generate_launch_description():
    return LaunchDescription([OpaqueFunction(function=launch_setup)])
""")
    body = """
import sys
sys.path.append(os.path.dirname(__file__))
import base_launch

def generate_launch_description():
    return LaunchDescription([OpaqueFunction(function=base_launch.launch_setup)])
"""
    path = write(tmp_path, "multi_launch.py", body)
    report = run_check(CheckOptions(paths=[path], workspace=tmp_path))
    assert [(f.code, f.span.file.name, f.span.line) for f in report.findings] == [
        ("LV101", "multi_launch.py", 12)]


def test_a_temporary_file_written_at_run_time_is_an_unknown(tmp_path: Path) -> None:
    # nav2's simulation launch files name a temporary world file that xacro writes when
    # the launch runs, and look at or remove it in an OpaqueFunction: its size needs what
    # only the run has; removing it (the cleanup at shutdown) misses nothing
    body = """
import tempfile

def {verb}(context):
    {statement}
    return []

WORLD = tempfile.mktemp(prefix='nav2_', suffix='.sdf')

def generate_launch_description():
    return LaunchDescription([OpaqueFunction(function={verb})])
"""
    read = body.format(verb="size", statement="os.path.getsize(WORLD)")
    [(code, line, message)] = findings(write(tmp_path, "read.launch.py", read))
    assert (code, line) == ("LV003", 10) and "only exists at run time" in message
    removed = body.format(verb="remove", statement="os.remove(WORLD)")
    assert findings(write(tmp_path, "remove.launch.py", removed)) == []


def test_a_named_temporary_file_is_written_in_the_scratch_folder(tmp_path: Path) -> None:
    # rtabmap's zed examples write a parameter override with NamedTemporaryFile: the write
    # lands in the evaluation's own scratch folder (deleted afterwards), so the evaluation
    # goes on and no message names a random temporary path
    body = """
import tempfile

def generate_launch_description():
    with tempfile.NamedTemporaryFile(mode='w+t', delete=False) as override:
        override.write('/**:\\n  ros__parameters:\\n    rate: 100.0\\n')
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name='talker'),
        Node(package='demo_nodes_cpp', executable='talker', name='talker'),
    ])
"""
    assert [code for code, _, _ in findings(write(tmp_path, "override.launch.py", body))
            ] == ["LV101"]


def test_a_temporary_file_passed_to_an_include_is_read_as_unknown(tmp_path: Path) -> None:
    # rtabmap's zed example writes an override into a NamedTemporaryFile and passes its
    # path to the camera's launch file, whose code opens it: that evaluation has its own
    # scratch folder, so the file is an input there (no message naming a random path)
    camera = """
def setup(context):
    path = LaunchConfiguration('override').perform(context)
    with open(path) as override:
        override.read()
    return [Node(package='demo_nodes_cpp', executable='talker', name='camera'),
            Node(package='demo_nodes_cpp', executable='talker', name='camera')]

def generate_launch_description():
    return LaunchDescription([DeclareLaunchArgument('override'),
                              OpaqueFunction(function=setup)])
"""
    write(tmp_path, "camera.launch.py", camera)
    body = """
import tempfile
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource

def setup(context):
    with tempfile.NamedTemporaryFile(mode='w+t', delete=False) as override:
        override.write('/**:\\n  ros__parameters:\\n    rate: 1\\n')
    return [IncludeLaunchDescription(
        PythonLaunchDescriptionSource(os.path.join(os.path.dirname(__file__),
                                                   'camera.launch.py')),
        launch_arguments={'override': override.name}.items())]

def generate_launch_description():
    return LaunchDescription([OpaqueFunction(function=setup)])
"""
    found = findings(write(tmp_path, "example.launch.py", body))
    assert [code for code, _, _ in found] == ["LV101"], found


def test_a_condition_a_body_evaluates_reads_its_configuration(tmp_path: Path) -> None:
    """``LaunchConfigurationEquals`` judged inside an OpaqueFunction reads ``mode``.

    (The name is built, so that the body's own strings do not count it as mentioned.)
    """
    path = write(tmp_path, "equals.launch.py", """
from launch.conditions import LaunchConfigurationEquals


def setup(context):
    if LaunchConfigurationEquals('mo' + 'de', 'fast').evaluate(context):
        return [Node(package='demo_nodes_cpp', executable='talker', name='fast')]
    return [Node(package='demo_nodes_cpp', executable='talker', name='slow')]


def generate_launch_description():
    return LaunchDescription([DeclareLaunchArgument('mode', default_value='slow'),
                              OpaqueFunction(function=setup)])
""")
    from launchverify.evaluate.runner import evaluate
    from launchverify.workspace.packages import PackageIndex

    graph = evaluate(path, index=PackageIndex(), workspace=tmp_path)
    assert [read.name for read in graph.reads] == ["mode"]
    assert [node.fqn.describe() for node in graph.nodes if node.fqn] == ["/slow"]


def test_the_robots_files_commands_and_host_are_unknowns(tmp_path: Path) -> None:
    # A vendor's helper checks for the robot's configuration file, runs a command and asks
    # the host name while the file loads: on the robot they answer, here they are unknown,
    # and a failure resting on them is no error.
    robot = """
import socket, subprocess, sys

def generate_launch_description():
    out = subprocess.run(['ros2', 'component', 'types'], capture_output=True).stdout
    if out.find('RealSenseNodeFactory') == -1:
        sys.exit('the component is not built')
    host = socket.gethostname()
    if not os.path.exists('/etc/acme/robot.yaml'):
        raise FileNotFoundError('run the acme setup first')
    return LaunchDescription([Node(package='demo_nodes_cpp', executable='talker', name=host)])
"""
    found = findings(write(tmp_path, "robot.launch.py", robot))
    assert [(code, line) for code, line, _ in found] == [("LV003", 10)]
    assert "would run 'ros2 component types'" in found[0][2]
    # the robot has its file: the check passes, and reading it (here by a library's
    # code) gives unknown content; only with it assumed absent would the file fail
    absent = robot.replace("if not os.path.exists", "if os.path.exists")
    found = findings(write(tmp_path, "absent.launch.py", absent))
    assert [(code, line) for code, line, _ in found] == [("LV003", 10), ("LV003", 15)]
    assert "cannot tell whether ros2 launch fails here" in found[1][2]
    assert "/etc/acme/robot.yaml exists on the robot" in found[1][2]


def test_what_each_answer_about_a_robots_file_starts_is_in_the_graph(tmp_path: Path) -> None:
    # Is this a Raspberry Pi? On the robot the file decides; here both answers are
    # possible, so what each starts is in the graph (the other's under an unknown
    # condition), and a value a loop over a vendor's list built is no fact.
    path = write(tmp_path, "board.launch.py", """
import vendor_boards

def generate_launch_description():
    if os.path.exists('/sys/firmware/devicetree/base/model'):
        return LaunchDescription([Node(package='demo_nodes_cpp', executable='talker',
                                       name='pi_' + ''.join(vendor_boards.names()))])
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name='desk'),
        Node(package='demo_nodes_cpp', executable='listener', name='listen')])
""")
    from launchverify.evaluate.runner import evaluate
    from launchverify.workspace.packages import PackageIndex

    graph = evaluate(path, index=PackageIndex(), workspace=tmp_path)
    named = {node.fqn.describe(): node for node in graph.nodes if node.fqn}
    assert {"/desk", "/listen"} <= set(named)  # the other answer's nodes
    assert all("other answers" in (named[n].origin.condition_text() or "")
               for n in ("/desk", "/listen"))
    assert not any(fqn.startswith("/pi_") and fqn != "/pi_" for fqn in named)
    assert [code for code, _, _ in findings(path)] == ["LV003"]  # the module, no error


def test_what_a_helper_finds_in_a_robots_file_is_unknown(tmp_path: Path) -> None:
    # A helper finds its tool where the robot installs it and parses the version file:
    # what ``re`` finds in the unknown content is unknown (not "nothing", whose ``[0]``
    # would fail), so the file loads and its graph is there.
    path = write(tmp_path, "sim.launch.py", """
import re

def tool_version():
    if os.path.isdir('/opt/simulator'):
        with open('/opt/simulator/version.txt') as f:
            return int(re.findall(r'R(\\d+)', f.read())[0])
    return None

def generate_launch_description():
    tool_version()
    return LaunchDescription([Node(package='demo_nodes_cpp', executable='talker',
                                   name='sim_bridge')])
""")
    from launchverify.evaluate.runner import evaluate
    from launchverify.workspace.packages import PackageIndex

    graph = evaluate(path, index=PackageIndex(), workspace=tmp_path)
    assert [node.fqn.describe() for node in graph.nodes if node.fqn] == ["/sim_bridge"]
    assert not findings(path)
    # a failure on known values is still one
    broken = write(tmp_path, "broken.launch.py", path.read_text().replace(
        "    tool_version()\n", "    {}['version']\n    tool_version()\n"))
    assert [code for code, _, _ in findings(broken)] == ["LV002"]


def test_webots_helpers_start_what_they_start(tmp_path: Path) -> None:
    # webots_ros2_driver is modelled (sources or not): the supervisor is a node the file
    # adds itself, the simulator and the driver are processes, the nodes a connection
    # waits for start once it is made.
    path = write(tmp_path, "sim.launch.py", """
from webots_ros2_driver.wait_for_controller_connection import WaitForControllerConnection
from webots_ros2_driver.webots_controller import WebotsController
from webots_ros2_driver.webots_launcher import WebotsLauncher

def generate_launch_description():
    webots = WebotsLauncher(world='/opt/worlds/arena.wbt', ros2_supervisor=True)
    driver = WebotsController(robot_name='rover', namespace='r1')
    odometry = Node(package='demo_nodes_cpp', executable='listener', name='odometry')
    return LaunchDescription([webots, webots._supervisor, driver,
        WaitForControllerConnection(target_driver=driver, nodes_to_start=[odometry])])
""")
    from launchverify.evaluate.runner import evaluate
    from launchverify.workspace.packages import PackageIndex

    graph = evaluate(path, index=PackageIndex(), workspace=tmp_path)
    nodes = {(node.executable_label(), graph.base(node.namespace) if node.namespace else None)
             for node in graph.nodes}
    assert ("ros2_supervisor.py", "/Ros2Supervisor") in {
        (label.rpartition("/")[2], ns) for label, ns in nodes}
    assert "/odometry" in {node.fqn.describe() for node in graph.nodes if node.fqn}
    processes = {graph.base(p.settings.name) for p in graph.processes if p.settings.name}
    assert {"webots", "webots_controller_rover"} <= processes
    assert not findings(path)


def test_what_the_user_types_at_a_prompt_is_unknown(tmp_path: Path) -> None:
    # A vendor's helper asks whether to install its simulator; launchverify's own standard
    # input is not the answer (in CI it may hold a file given with ``check -``).
    path = write(tmp_path, "prompt.launch.py", """
def generate_launch_description():
    if input('Install the simulator? [y/N] ').lower() != 'y':
        raise SystemExit('the simulator is missing')
    return LaunchDescription([Node(package='demo_nodes_cpp', executable='talker')])
""")
    found = findings(path)
    assert [code for code, _, _ in found] == ["LV003"]
    assert "what the user types at the prompt" in found[0][2]


def test_a_variable_the_check_was_not_given_reads_as_unset(tmp_path: Path) -> None:
    # ``NAME in os.environ`` answers no, as a default is read: the branch of a machine
    # that does not set it is the graph's; one given with --env is set.
    path = write(tmp_path, "shared.launch.py", """
def generate_launch_description():
    name = 'shared' if 'SIM_SHARED_FOLDER' in os.environ else 'local'
    return LaunchDescription([Node(package='demo_nodes_cpp', executable='talker', name=name)])
""")
    from launchverify.evaluate.runner import evaluate
    from launchverify.workspace.packages import PackageIndex

    graph = evaluate(path, index=PackageIndex(), workspace=tmp_path)
    assert [node.fqn.describe() for node in graph.nodes] == ["/local"]
    assert not findings(path)
    shown = _graph_names(path, "--env", "SIM_SHARED_FOLDER=/srv")
    assert shown == ["/shared"]


def _graph_names(path: Path, *arguments: str) -> list[str]:
    import contextlib
    import io

    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        main(["graph", str(path), *arguments])
    return [node["fqn"] for node in json.loads(out.getvalue())["nodes"]]


def test_a_class_on_an_unknown_and_a_known_base_answers_as_the_known_one(
        tmp_path: Path) -> None:
    # ``class Params(vendor.Base, dict)`` makes dicts (the vendor's base adds what the
    # class lacks); on the unknown base alone, its instances are unknown values.
    path = write(tmp_path, "bases.launch.py", """
import vendor_config

class Params(vendor_config.Base, dict):
    pass

class Robot(vendor_config.Base):
    pass

def generate_launch_description():
    params = Params()
    params['rate'] = 10
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name='n_' + list(params)[0]),
        Node(package='demo_nodes_cpp', executable='listener', name=str(Robot())),
    ])
""")
    from launchverify.evaluate.runner import evaluate
    from launchverify.workspace.packages import PackageIndex

    graph = evaluate(path, index=PackageIndex(), workspace=tmp_path)
    names = [node.fqn.describe() for node in graph.nodes if node.fqn]
    assert names[0] == "/n_rate" and len(names) == 2 and "Robot" in names[1]


def test_a_configuration_handed_to_unknown_code_may_be_read(tmp_path: Path) -> None:
    # crane_plus: ``loader.use_camera = LaunchConfiguration('use_camera')`` hands the
    # configuration to a vendor's object, whose ``load()`` reads it: no "never used"; an
    # argument nothing hands over stays unused.
    path = write(tmp_path, "handed.launch.py", """
from vendor_description import Loader

def generate_launch_description():
    loader = Loader()
    loader.use_camera = LaunchConfiguration('use_camera')
    loader.configure(gripper=LaunchConfiguration('gripper'))
    loader['arm'] = LaunchConfiguration('arm')
    return LaunchDescription([
        DeclareLaunchArgument('use_camera', default_value='false'),
        DeclareLaunchArgument('gripper', default_value='true'),
        DeclareLaunchArgument('arm', default_value='a'),
        DeclareLaunchArgument('spare', default_value='x'),
        Node(package='demo_nodes_cpp', executable='talker', name='t',
             parameters=[{'robot_description': loader.load()}]),
    ])
""")
    found = [(code, message) for code, _, message in findings(path) if code == "LV202"]
    assert len(found) == 1 and "'spare'" in found[0][1]


def test_json_of_an_unknown_text_is_unknown_and_broken_json_a_fact(tmp_path: Path) -> None:
    body = """
import json

def generate_launch_description():
    cfg = json.loads(os.environ.get('ROBOT_CFG', '{"name": "r"}'))
    return LaunchDescription([Node(package='demo_nodes_cpp', executable='talker',
                                   name=cfg['name'])])
"""
    assert findings(write(tmp_path, "env.launch.py", body)) == []
    broken = body.replace("os.environ.get('ROBOT_CFG', '{\"name\": \"r\"}')", "'{name: r}'")
    [(code, _, message)] = findings(write(tmp_path, "broken.launch.py", broken))
    assert code == "LV002" and "JSONDecodeError" in message


def test_a_missing_file_of_the_workspace_is_a_fact(tmp_path: Path) -> None:
    # The twin: the file would be in the workspace, which launchverify sees.
    body = f"""
def generate_launch_description():
    if not os.path.exists({str(tmp_path / 'config' / 'robot.yaml')!r}):
        raise FileNotFoundError('robot.yaml is missing')
    return LaunchDescription([])
"""
    [(code, line, message)] = findings(write(tmp_path, "local.launch.py", body))
    assert (code, line) == ("LV002", 9) and "robot.yaml is missing" in message


def _helper_workspace(tmp_path: Path, cmake: str) -> Path:
    """A package whose build may install the Python package acme_helpers, and a user."""
    helpers = tmp_path / "acme_common"
    (helpers / "acme_helpers").mkdir(parents=True)
    (helpers / "package.xml").write_text(
        "<package format='3'><name>acme_common</name><version>0.0.0</version>"
        "<description>d</description><maintainer email='a@b.c'>a</maintainer>"
        "<license>MIT</license></package>")
    (helpers / "CMakeLists.txt").write_text(cmake)
    (helpers / "acme_helpers" / "__init__.py").write_text(
        "def robot_name():\n    return 'atlas'\n")
    body = """
from acme_helpers import robot_name

def generate_launch_description():
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name=robot_name()),
        Node(package='demo_nodes_cpp', executable='listener', name='atlas'),
    ])
"""
    return write(tmp_path, "robot.launch.py", body)


def test_a_python_package_a_workspace_build_installs_is_imported(tmp_path: Path) -> None:
    # ament_cmake installs acme_helpers (ament_python_install_package): the helper runs,
    # and the duplicate it makes is found. Without that line nothing installs it: unknown.
    installed = _helper_workspace(tmp_path, "ament_python_install_package(acme_helpers)\n")
    assert [code for code, _, _ in findings(installed)] == ["LV101"]
    (tmp_path / "acme_common" / "CMakeLists.txt").write_text("ament_package()\n")
    codes = [code for code, _, _ in findings(installed)]
    assert "LV101" not in codes and "LV002" not in codes


def test_a_python_package_of_an_installed_prefix_is_imported(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # AMENT_PREFIX_PATH names an install prefix whose site-packages holds the helper.
    site = tmp_path / "prefix" / "lib" / "python3.12" / "site-packages" / "acme_helpers"
    site.mkdir(parents=True)
    (site / "__init__.py").write_text("def robot_name():\n    return 'atlas'\n")
    (tmp_path / "ws").mkdir()
    path = _helper_workspace(tmp_path / "ws", "ament_package()\n")
    monkeypatch.setenv("AMENT_PREFIX_PATH", str(tmp_path / "prefix"))
    codes = [code for code, _, _ in findings(path)]  # (demo_nodes_cpp is not installed)
    assert "LV101" in codes and "LV002" not in codes


def test_the_modules_ablation_leaves_only_launch_and_python(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # bench/ablation.py takes every module but launch, launch_ros and Python's own away:
    # the installed helper is then unknown, so the duplicate it makes is not seen, and no
    # error appears in its place (its yaml import is unknown too, not missing).
    path = _helper_workspace(tmp_path, "ament_python_install_package(acme_helpers)\n")
    source = path.read_text()
    path.write_text(source.replace("from acme_helpers", "import yaml\nfrom acme_helpers"))
    assert [code for code, _, _ in findings(path)] == ["LV101"]
    monkeypatch.setenv("LAUNCHVERIFY_ABLATE", "modules")
    found = findings(path)
    assert [code for code, _, _ in found] == ["LV003", "LV003"]
    assert all("is not modelled and not installed" in message for _, _, message in found)


def test_an_event_handlers_function_is_called_with_an_unknown_event(tmp_path: Path) -> None:
    # OnProcessExit(on_exit=lambda event, context: [...]) and OnProcessIO's on_stdout: the
    # event is only known when it fires; what the function returns is walked.
    body = """
from launch.actions import ExecuteProcess, RegisterEventHandler
from launch.event_handlers import OnProcessExit, OnProcessIO

def generate_launch_description():
    worker = ExecuteProcess(cmd=['sleep', '1'])
    return LaunchDescription([
        worker,
        RegisterEventHandler(OnProcessIO(target_action=worker,
                                         on_stdout=lambda event: print(event.text.decode()))),
        RegisterEventHandler(OnProcessExit(target_action=worker, on_exit=lambda event, context: [
            Node(package='demo_nodes_cpp', executable='talker', name='after_' + str(
                event.returncode))])),
        RegisterEventHandler(OnProcessExit(target_action=worker,
                                           on_exit=lambda event, context: [1 / 0])),
    ])
"""
    path = write(tmp_path, "handlers.launch.py", body)
    found = findings(path)
    assert [(code, line) for code, line, _ in found] == [("LV003", 19)]
    assert "fails here on what only the event gives" in found[0][2]
    report = run_check(CheckOptions(paths=[path], workspace=tmp_path))
    assert [n.name is not None for n in report.graphs[0].nodes] == [True]
