"""``launchverify run``: real processes through start-up, events, timers, respawn, shutdown.

The processes are corpus/executor/nodes/worker.py, a stand-in for a node that prints,
crashes, finishes or ignores signals on cue. Every test checks the order of events the
supervisor recorded and that no process (nor a child of one) survives the run.
"""

from __future__ import annotations

import os
import shutil
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest

from launchverify.cli import main

CORPUS = Path(__file__).resolve().parent.parent / "corpus" / "executor"
WORKER = CORPUS / "nodes" / "worker.py"


@pytest.fixture(autouse=True)
def _no_ros(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)
    monkeypatch.setattr(shutil, "which", _which_without_ros2)


_real_which = shutil.which


def _which_without_ros2(name: str, *args: object, **kwargs: object) -> str | None:
    return None if name == "ros2" else _real_which(name)  # type: ignore[arg-type]


def events_of(log_dir: Path) -> list[str]:
    """Return the events of the only run under ``log_dir`` (without their times)."""
    (run,) = log_dir.glob("launchverify-*")
    return [line.split(maxsplit=1)[1] for line in
            (run / "events.log").read_text().splitlines()]


def pids(events: list[str]) -> list[int]:
    return [int(e.split()[2]) for e in events if e.startswith("start ")]


def alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    # a zombie is dead for our purpose; /proc tells
    status = Path(f"/proc/{pid}/status")
    return not status.exists() or "zombie" not in status.read_text()


def run(capsys: pytest.CaptureFixture[str], tmp_path: Path, launch: Path,
        *argv: str) -> tuple[int, list[str], str]:
    code = main(["run", str(launch), "--log-dir", str(tmp_path), *argv])
    out = capsys.readouterr().out
    events = events_of(tmp_path) if any(tmp_path.glob("launchverify-*")) else []
    return code, events, out


def test_start_up_handlers_timers_and_shutdown_in_order(
        capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    code, events, out = run(capsys, tmp_path, CORPUS / "events" / "events.launch.py")
    assert code == 0
    starts = [e.split()[1] for e in events if e.startswith("start ")]
    assert starts == ["python3-1", "python3-2", "python3-3"]
    # the second worker starts from the first one's start handler, after it
    assert events.index("handler process_start events.launch.py:19") < events.index(
        next(e for e in events if e.startswith("start python3-3")))
    # 'short' finishes on its own, its exit handler logs; the timer shuts down after
    exit_short = events.index("exit python3-2 0")
    shutdown = events.index("shutdown timer")
    assert exit_short < shutdown
    assert "[INFO] [launch.user]: short finished" in out
    assert out.index("short finished") < out.index("short complete") < out.index("timer fired")
    after = events[shutdown:]
    assert {"signal python3-1 SIGINT", "signal python3-3 SIGINT"} <= set(after)
    assert not any(alive(pid) for pid in pids(events))
    assert "[python3-1] ready first" in out


def test_respawn_until_the_retries_run_out(capsys: pytest.CaptureFixture[str],
                                           tmp_path: Path) -> None:
    launch = tmp_path / "respawn.launch.xml"
    launch.write_text((CORPUS / "respawn" / "respawn.launch.xml").read_text()
                      .replace("$(dirname)", str(CORPUS / "respawn"))
                      .replace('period="1.5"', 'period="4.0"')  # three lives, even on a busy CI
                      .replace("<log message=\"stopping\"/>",
                               "<log message=\"stopping\"/><shutdown reason=\"enough\"/>"))
    code, events, _ = run(capsys, tmp_path / "logs", launch)
    flaky = [e for e in events if "flaky" in e]
    assert flaky == ["start flaky-1 " + flaky[0].split()[2], "exit flaky-1 3", "respawn flaky-1",
                     flaky[3], "exit flaky-1 3", "respawn flaky-1", flaky[6], "exit flaky-1 3"]
    assert code == 1  # the crashes are failures, respawned or not
    assert "shutdown enough" in events
    assert not any(e.startswith("start late") for e in events)  # the timer's process: cancelled
    assert not any(alive(pid) for pid in pids(events))


def test_a_process_ignoring_signals_is_killed_on_time_with_its_children(
        capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    started = time.monotonic()
    code, events, out = run(capsys, tmp_path, CORPUS / "stubborn" / "stubborn.launch.xml")
    elapsed = time.monotonic() - started
    stubborn = [e for e in events if "stubborn-1" in e and not e.startswith("start")]
    assert stubborn == ["signal stubborn-1 SIGINT", "signal stubborn-1 SIGTERM",
                        "signal stubborn-1 SIGKILL", "exit stubborn-1 -9"]
    assert events.index("exit quitter-1 0") < events.index("shutdown Shutdown action")
    assert elapsed < 0.3 + 0.5 + 0.5 + 3.0  # quitter's life + sigterm + sigkill + start-up
    child = int(next(line.split()[3] for line in out.splitlines()
                     if line.startswith("[stubborn-1] child")))
    assert not alive(child)  # the whole process group went
    assert not any(alive(pid) for pid in pids(events))
    assert code == 0  # stopped by the shutdown: not a failure
    assert "[polite-1] ready" not in out  # output="log": stdout only in the log file
    assert "[polite-1] to stderr polite" in out  # ...stderr on the screen too
    (folder,) = tmp_path.glob("launchverify-*")
    assert "ready polite" in (folder / "polite-1.log").read_text()


def test_fifty_processes_survive_a_crash_and_stop_within_sigterm_timeout(
        capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    started = time.monotonic()
    code, events, _ = run(capsys, tmp_path, CORPUS / "fleet" / "fleet.launch.py")
    elapsed = time.monotonic() - started
    starts = [e for e in events if e.startswith("start ")]
    assert len(starts) == 51  # fifty, and worker7 once more
    assert "respawn worker7-1" in events
    shutdown = events.index("shutdown done")
    exits = [e for e in events[shutdown:] if e.startswith("exit ")]
    assert len(exits) == 50 and all(e.endswith(" 0") for e in exits)
    assert not any(e.startswith("signal") and "SIGTERM" in e for e in events)
    assert elapsed < 6.0 + 2.0 + 3.0  # the timer, sigterm_timeout, start-up
    assert not any(alive(pid) for pid in pids(events))
    assert code == 1  # worker7 crashed once


def install_prefix(tmp_path: Path) -> Path:
    """Write an install prefix with package fake_robot whose 'worker' is worker.py."""
    prefix = tmp_path / "install"
    lib = prefix / "lib" / "fake_robot"
    lib.mkdir(parents=True)
    (lib / "worker").symlink_to(WORKER)
    marker = prefix / "share" / "ament_index" / "resource_index" / "packages"
    marker.mkdir(parents=True)
    (marker / "fake_robot").write_text("")
    share = prefix / "share" / "fake_robot"
    share.mkdir(parents=True)
    (share / "package.xml").write_text(
        "<package format='3'><name>fake_robot</name><version>0.0.0</version>"
        "<description>x</description><maintainer email='a@b.c'>a</maintainer>"
        "<license>MIT</license></package>")
    return prefix


def test_node_command_lines_are_built_as_launch_ros_builds_them(
        capsys: pytest.CaptureFixture[str], tmp_path: Path,
        monkeypatch: pytest.MonkeyPatch) -> None:
    prefix = install_prefix(tmp_path)
    monkeypatch.setenv("AMENT_PREFIX_PATH", str(prefix))
    launch = CORPUS / "nodes_cmdline" / "robot.launch.xml"
    assert main(["run", str(launch), "--dry-run", "--log-dir", str(tmp_path / "logs")]) == 0
    plan = capsys.readouterr().out
    assert not (tmp_path / "logs").exists()  # a dry run starts and writes nothing
    expected = (f"start worker: {prefix}/lib/fake_robot/worker talker --finish-after 0.2 "
                "--ros-args --log-level debug --ros-args -r __node:=talker "
                "-r __ns:=/robot1 -p use_sim_time:=false --params-file ")
    assert expected in plan
    assert "-r /tf:=tf -r chatter:=chat" in plan
    assert "env ROBOT_ID=7" in plan
    assert "rate: 10" in plan and "frame: base_link" in plan and "/**:" in plan
    code, _, out = run(capsys, tmp_path / "logs", launch)
    assert code == 0
    line = next(x for x in out.splitlines() if x.startswith("[worker-1] ready talker"))
    assert "--ros-args -r __node:=talker -r __ns:=/robot1" in line
    params = Path(line.split("--params-file ")[1].split()[0])
    assert params.read_text().startswith("/**:\n  ros__parameters:\n    rate: 10")


REWRITTEN = """\
import os
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from nav2_common.launch import RewrittenYaml


def generate_launch_description():
    params = RewrittenYaml(
        source_file=os.path.join(os.path.dirname(__file__), 'params.yaml'),
        root_key=LaunchConfiguration('namespace'),
        param_rewrites={'use_sim_time': LaunchConfiguration('use_sim_time'),
                        'talker.ros__parameters.rate': '20'},
        convert_types=True)
    return LaunchDescription([
        DeclareLaunchArgument('namespace', default_value='robot1'),
        DeclareLaunchArgument('use_sim_time', default_value='true'),
        Node(package='fake_robot', executable='worker', name='talker', namespace='robot1',
             arguments=['talker', '--finish-after', '0.2'], parameters=[params],
             output='screen'),
    ])
"""


def test_a_rewritten_parameter_file_is_written_as_nav2_writes_it(
        capsys: pytest.CaptureFixture[str], tmp_path: Path,
        monkeypatch: pytest.MonkeyPatch) -> None:
    """RewrittenYaml: the node gets the file with the launch's values, under its root key."""
    monkeypatch.setenv("AMENT_PREFIX_PATH", str(install_prefix(tmp_path)))
    launch = tmp_path / "nav.launch.py"
    launch.write_text(REWRITTEN)
    (tmp_path / "params.yaml").write_text(
        "talker:\n  ros__parameters:\n    use_sim_time: false\n    rate: 10\n")
    assert main(["run", str(launch), "--dry-run", "--log-dir", str(tmp_path / "logs")]) == 0
    expected = "robot1:\n  talker:\n    ros__parameters:\n      use_sim_time: true\n" \
        "      rate: 20\n"
    plan = "\n".join(line.strip() for line in capsys.readouterr().out.splitlines())
    assert "\n".join(line.strip() for line in expected.splitlines()) in plan, plan
    code, _, out = run(capsys, tmp_path / "logs", launch)
    assert code == 0
    line = next(x for x in out.splitlines() if x.startswith("[worker-1] ready talker"))
    assert Path(line.split("--params-file ")[1].split()[0]).read_text() == expected


SPAWNER = """\
import os
from launch import LaunchDescription
from launch_ros.actions import Node
from nav2_common.launch import RewrittenYaml


def generate_launch_description():
    controllers = RewrittenYaml(
        source_file=os.path.join(os.path.dirname(__file__), 'controllers.yaml'),
        param_rewrites={'wheel_separation': '0.5'}, convert_types=True)
    return LaunchDescription([
        Node(package='fake_robot', executable='worker', name='spawner', output='screen',
             arguments=['spawner', '--finish-after', '0.2', '--param-file', controllers],
             parameters=[{'use_sim_time': True}]),
    ])
"""


def test_a_dry_run_says_which_parameter_files_the_run_would_write_and_where(
        capsys: pytest.CaptureFixture[str], tmp_path: Path,
        monkeypatch: pytest.MonkeyPatch) -> None:
    """A spawner's --param-file and parameters: the files are the run's, in its folder."""
    monkeypatch.setenv("AMENT_PREFIX_PATH", str(install_prefix(tmp_path)))
    launch = tmp_path / "spawn.launch.py"
    launch.write_text(SPAWNER)
    (tmp_path / "controllers.yaml").write_text(
        "diff_drive_controller:\n  ros__parameters:\n    wheel_separation: 0.4\n")
    logs = tmp_path / "logs"
    assert main(["run", str(launch), "--dry-run", "--log-dir", str(logs)]) == 0
    plan = capsys.readouterr().out
    assert not logs.exists()  # nothing written
    folder = f"{logs}/launchverify-<start time>-<pid>"
    # the rewritten file, as the run writes it: not its source, nor a folder of this process
    assert f"--param-file '{folder}/params/params_1.yaml'" in plan
    assert f"would write {folder}/params/params_1.yaml first:" in plan
    assert "wheel_separation: 0.5" in plan
    assert f"--params-file '{folder}/params/params_2.yaml'" in plan
    assert f"would write {folder}/params/params_2.yaml first:" in plan
    assert f"note: the run makes its folder {folder} when it starts" in plan
    assert "  writes " not in plan
    code, _, out = run(capsys, logs, launch)
    assert code == 0
    line = next(x for x in out.splitlines() if x.startswith("[worker-1] ready spawner"))
    (run_folder,) = logs.glob("launchverify-*")
    given = Path(line.split("--param-file ")[1].split()[0])
    assert given == run_folder / "params" / "params_1.yaml"
    assert "wheel_separation: 0.5" in given.read_text()
    assert Path(line.split("--params-file ")[1].split()[0]).read_text().startswith(
        "/**:\n  ros__parameters:\n    use_sim_time: true")


def test_lifecycle_without_ros2_says_so(capsys: pytest.CaptureFixture[str],
                                        tmp_path: Path) -> None:
    launch = tmp_path / "lc.launch.py"
    launch.write_text(f"""
from launch import LaunchDescription
from launch.actions import EmitEvent, ExecuteProcess, TimerAction
from launch.events import Shutdown, matches_action
from launch_ros.actions import LifecycleNode
from launch_ros.events.lifecycle import ChangeState
from lifecycle_msgs.msg import Transition


def generate_launch_description():
    node = LifecycleNode(executable='{sys.executable}', name='talker', namespace='',
                         arguments=['{WORKER}', 'talker'])
    return LaunchDescription([
        node,
        EmitEvent(event=ChangeState(lifecycle_node_matcher=matches_action(node),
                                    transition_id=Transition.TRANSITION_CONFIGURE)),
        TimerAction(period=0.5, actions=[EmitEvent(event=Shutdown())]),
    ])
""")
    code, events, out = run(capsys, tmp_path / "logs", launch)
    assert code == 0
    assert "lifecycle transitions are not performed: the ROS 2 command line" in out
    assert "lifecycle /talker configure not performed" in events


def test_errors_found_by_the_check_refuse_the_start(capsys: pytest.CaptureFixture[str],
                                                    tmp_path: Path) -> None:
    launch = tmp_path / "dup.launch.xml"
    launch.write_text(f"""<launch>
  <executable cmd="python3 {WORKER} a --finish-after 0.1" name="a"/>
  <node exec="{sys.executable}" name="twin" args="{WORKER} b --finish-after 0.1"/>
  <node exec="{sys.executable}" name="twin" args="{WORKER} c --finish-after 0.1"/>
</launch>
""")
    assert main(["run", str(launch), "--log-dir", str(tmp_path / "logs")]) == 1
    err = capsys.readouterr().err
    assert "LV101" in err and "not started" in err
    assert not (tmp_path / "logs").exists()
    code, events, _ = run(capsys, tmp_path / "logs", launch, "--force")
    assert code == 0 and len(pids(events)) == 3


def test_ctrl_c_stops_everything(tmp_path: Path) -> None:
    """SIGINT to ``launchverify run`` (as Ctrl-C sends it) stops every process group."""
    launch = CORPUS / "stubborn" / "stubborn.launch.xml"
    text = launch.read_text().replace("$(dirname)", str(launch.parent)).replace(
        ' on_exit="shutdown"', "").replace("--finish-after 0.3", "")
    copy = tmp_path / "stubborn.launch.xml"
    copy.write_text(text)
    command = [str(Path(sys.executable).parent / "launchverify"), "run", str(copy),
               "--log-dir", str(tmp_path / "logs")]
    child = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                             text=True)
    lines: list[str] = []
    ready = threading.Event()  # the stubborn worker ignores signals from now on

    def read() -> None:
        assert child.stdout is not None
        for line in child.stdout:
            lines.append(line)
            if line.startswith("[stubborn-1] ready"):
                ready.set()

    reader = threading.Thread(target=read, daemon=True)
    reader.start()
    assert ready.wait(timeout=20)
    child.send_signal(signal.SIGINT)
    child.wait(timeout=20)
    reader.join(timeout=20)
    out = "".join(lines)
    events = events_of(tmp_path / "logs")
    assert "shutdown SIGINT received" in events
    assert "signal stubborn-1 SIGKILL" in events
    grandchild = int(next(line.split()[3] for line in out.splitlines()
                          if line.startswith("[stubborn-1] child")))
    assert not alive(grandchild)
    assert not any(alive(pid) for pid in pids(events))


def test_on_shutdown_handlers_run_and_io_callbacks_are_announced(
        capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    launch = tmp_path / "io.launch.py"
    launch.write_text(f"""
from launch import LaunchDescription
from launch.actions import (EmitEvent, ExecuteProcess, LogInfo, RegisterEventHandler,
                            TimerAction)
from launch.event_handlers import OnProcessIO, OnShutdown
from launch.events import Shutdown


def generate_launch_description():
    worker = ExecuteProcess(cmd=['python3', '{WORKER}', 'w'], output='screen')
    return LaunchDescription([
        worker,
        RegisterEventHandler(OnProcessIO(target_action=worker,
                                         on_stdout=lambda event: None)),
        RegisterEventHandler(OnShutdown(on_shutdown=[
            LogInfo(msg='cleaning up'),
            ExecuteProcess(cmd=['python3', '{WORKER}', 'never']),
        ])),
        TimerAction(period=0.4, actions=[EmitEvent(event=Shutdown(reason='test'))]),
    ])
""")
    code, events, out = run(capsys, tmp_path / "logs", launch)
    assert code == 0
    assert "OnProcessIO callbacks are Python functions" in out
    assert events.index("shutdown test") < events.index("handler shutdown io.launch.py:15")
    assert out.index("shutdown requested: test") < out.index("cleaning up")
    assert len(pids(events)) == 1  # no process starts once shutdown began


def test_a_missing_executable_is_a_clear_error(capsys: pytest.CaptureFixture[str],
                                               tmp_path: Path) -> None:
    launch = tmp_path / "missing.launch.xml"
    launch.write_text('<launch><node pkg="demo_nodes_cpp" exec="talker" name="t"/></launch>')
    assert main(["run", str(launch), "--log-dir", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert "executable 'talker' of package 'demo_nodes_cpp' not found" in err
    assert "Traceback" not in err


def test_engine_ros2_needs_ros2(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    launch = tmp_path / "ok.launch.xml"
    launch.write_text(f'<launch><executable cmd="python3 {WORKER} a"/></launch>')
    assert main(["run", str(launch), "--engine", "ros2"]) == 2
    assert "--engine ros2 needs the ROS 2 command line" in capsys.readouterr().err


def test_nothing_survives_launchverify_being_killed(tmp_path: Path) -> None:
    """SIGKILL to launchverify itself: its guard kills every process group it started."""
    launch = tmp_path / "two.launch.xml"
    launch.write_text(f"""<launch>
  <executable cmd="python3 {WORKER} a --spawn-child" name="a" output="screen"/>
  <executable cmd="python3 {WORKER} b --ignore-signals" name="b" output="screen"/>
</launch>
""")
    command = [str(Path(sys.executable).parent / "launchverify"), "run", str(launch),
               "--log-dir", str(tmp_path / "logs")]
    child = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                             text=True)
    assert child.stdout is not None
    lines = []
    for line in child.stdout:
        lines.append(line)
        if sum("] ready " in x for x in lines) == 2 and any("] child " in x for x in lines):
            break
    child.kill()
    child.wait(timeout=10)
    events = events_of(tmp_path / "logs")
    grandchild = int(next(x.split()[3] for x in lines if "] child " in x))
    deadline = time.monotonic() + 5
    while time.monotonic() < deadline and any(alive(p) for p in [*pids(events), grandchild]):
        time.sleep(0.05)
    assert not any(alive(p) for p in [*pids(events), grandchild])


def test_dry_run_shows_missing_executables_instead_of_failing(
        capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    launch = tmp_path / "missing.launch.xml"
    launch.write_text('<launch><node pkg="demo_nodes_cpp" exec="talker" name="t"/></launch>')
    assert main(["run", str(launch), "--dry-run"]) == 0
    out = capsys.readouterr().out
    assert "start talker: '<lib/demo_nodes_cpp/talker: not found>' --ros-args" in out
    assert "note: executable 'talker' of package 'demo_nodes_cpp' not found" in out


def test_commands_and_the_environment_are_resolved_when_the_launch_runs(
        capsys: pytest.CaptureFixture[str], tmp_path: Path,
        monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("WORKER_NAME", "from-env")
    launch = tmp_path / "cmd.launch.xml"
    launch.write_text(f"""<launch>
  <executable cmd="python3 {WORKER} $(env WORKER_NAME) --finish-after 0.1" name="w"
              output="screen"/>
  <node exec="{sys.executable}" name="described" output="screen"
        args="{WORKER} described --finish-after 0.1">
    <param name="robot_description"
           value="$(command '{sys.executable} -c &quot;print(42)&quot;')"/>
  </node>
</launch>
""")
    assert main(["run", str(launch), "--dry-run"]) == 0
    plan = capsys.readouterr().out
    assert "robot_description: <output of $(command" in plan  # a dry run runs nothing
    code, _, out = run(capsys, tmp_path / "logs", launch)
    assert code == 0
    assert "[w-1] ready from-env" in out
    line = next(x for x in out.splitlines() if "] ready described" in x)
    params = Path(line.split("--params-file ")[1].split()[0])
    assert "robot_description: 42" in params.read_text()


@pytest.fixture
def ros2_calls(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """Put a ``ros2`` on the path that records its arguments (a line per call) and succeeds;
    return the file it records to."""
    folder = tmp_path / "bin"
    folder.mkdir()
    script = folder / "ros2"
    calls = tmp_path / "ros2.calls"
    script.write_text(f"#!{sys.executable}\nimport sys\n"
                      f"open({str(calls)!r}, 'a').write(' '.join(sys.argv[1:]) + '\\n')\n")
    script.chmod(0o755)
    monkeypatch.setattr(shutil, "which",
                        lambda name, *a, **k: str(script) if name == "ros2" else _real_which(name))
    return calls


def test_lifecycle_transitions_go_through_ros2_when_it_is_there(
        capsys: pytest.CaptureFixture[str], tmp_path: Path, ros2_calls: Path) -> None:
    launch = tmp_path / "lc.launch.py"
    launch.write_text(f"""
from launch import LaunchDescription
from launch.actions import EmitEvent, TimerAction
from launch.events import Shutdown, matches_action
from launch_ros.actions import LifecycleNode
from launch_ros.events.lifecycle import ChangeState
from lifecycle_msgs.msg import Transition


def generate_launch_description():
    talker = LifecycleNode(executable='{sys.executable}', name='talker', namespace='robot',
                           arguments=['{WORKER}', 'talker'])
    auto = LifecycleNode(executable='{sys.executable}', name='auto', namespace='',
                         arguments=['{WORKER}', 'auto'], autostart=True)
    return LaunchDescription([
        talker, auto,
        EmitEvent(event=ChangeState(lifecycle_node_matcher=matches_action(talker),
                                    transition_id=Transition.TRANSITION_CONFIGURE)),
        TimerAction(period=1.0, actions=[EmitEvent(event=Shutdown())]),
    ])
""")
    code, events, _ = run(capsys, tmp_path / "logs", launch)
    assert code == 0
    calls = sorted(ros2_calls.read_text().splitlines())
    assert calls == ["lifecycle set /auto activate", "lifecycle set /auto configure",
                     "lifecycle set /robot/talker configure"]
    assert events.index("lifecycle /auto configure") < events.index("lifecycle /auto activate")


def test_engine_ros2_hands_the_file_and_arguments_over(
        capsys: pytest.CaptureFixture[str], tmp_path: Path, ros2_calls: Path) -> None:
    launch = tmp_path / "ok.launch.xml"
    launch.write_text(f'<launch><arg name="robot" default="r1"/>'
                      f'<executable cmd="python3 {WORKER} $(var robot)"/></launch>')
    assert main(["run", str(launch), "robot:=r2", "--engine", "ros2"]) == 0
    assert ros2_calls.read_text() == f"launch {launch} robot:=r2\n"


def test_composable_nodes_are_loaded_through_ros2(
        capsys: pytest.CaptureFixture[str], tmp_path: Path, ros2_calls: Path) -> None:
    (tmp_path / "params.yaml").write_text("/perception/camera:\n  ros__parameters:\n    fps: 30\n")
    launch = tmp_path / "container.launch.xml"
    launch.write_text(f"""<launch>
  <node_container exec="{sys.executable}" name="container"
                  namespace="perception" args="{WORKER} container" output="screen">
    <composable_node pkg="usb_cam" plugin="usb_cam::UsbCamNode" name="camera"
                     namespace="perception">
      <param from="{tmp_path / 'params.yaml'}"/>
      <param name="frame_id" value="cam"/>
      <remap from="image" to="image_raw"/>
    </composable_node>
  </node_container>
  <timer period="1.0"><shutdown/></timer>
</launch>
""")
    code, events, _ = run(capsys, tmp_path / "logs", launch)
    assert code == 0
    assert ros2_calls.read_text().splitlines() == [
        "component load /perception/container usb_cam usb_cam::UsbCamNode --node-name camera "
        "--node-namespace /perception --remap-rule image:=image_raw --parameter fps:=30 "
        "--parameter frame_id:=cam"]
    assert "component usb_cam/usb_cam::UsbCamNode loaded into /perception/container" in events


GUARDED = """<launch>
  <arg name="use_mock_hardware" default="{default}"/>
  <arg name="mock" default="$(var use_mock_hardware)"/>
  <node pkg="demo_nodes_cpp" exec="talker" name="driver"/>
  <node pkg="demo_nodes_cpp" exec="listener" name="driver" if="$(var {guard})"/>
</launch>
"""


@pytest.mark.parametrize(("default", "guard", "given", "verdict"), [
    # the duplicate needs use_mock_hardware:=true: started, and said
    ("false", "use_mock_hardware", [], "started, 1 elsewhere"),
    ("false", "mock", [], "started, 1 elsewhere"),  # a default that is another's value
    ("true", "use_mock_hardware", [], "refused"),  # it holds by default
    ("true", "mock", [], "refused"),
    ("false", "use_mock_hardware", ["use_mock_hardware:=true"], "refused"),  # as given
    ("false", "mock", ["mock:=true"], "refused"),  # a default overridden
    ("true", "use_mock_hardware", ["use_mock_hardware:=false"], "started"),
])
def test_run_refuses_only_errors_that_hold_for_the_arguments_given(
        default: str, guard: str, given: list[str], verdict: str, tmp_path: Path,
        capsys: pytest.CaptureFixture[str]) -> None:
    launch = tmp_path / "robot.launch.xml"
    launch.write_text(GUARDED.format(default=default, guard=guard))
    started = verdict.startswith("started")
    assert main(["run", str(launch), "--dry-run", *given]) == (0 if started else 1)
    out, err = capsys.readouterr()
    note = ("1 error(s) hold only for other argument values; `launchverify check "
            f"{launch}` lists them")
    assert (note in err) is verdict.endswith("elsewhere")
    if started:
        assert "start talker:" in out and "not started" not in err and "LV101" not in err
    else:
        assert out == "" and "LV101" in err and "not started" in err
    assert main(["check", str(launch), *given]) == (0 if verdict == "started" else 1)
    capsys.readouterr()


def test_run_judges_python_launch_arguments_too(tmp_path: Path,
                                                capsys: pytest.CaptureFixture[str]) -> None:
    launch = tmp_path / "robot.launch.py"
    launch.write_text('''from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('use_mock_hardware', default_value='false'),
        Node(package='demo_nodes_cpp', executable='talker', name='driver'),
        Node(package='demo_nodes_cpp', executable='listener', name='driver',
             condition=IfCondition(LaunchConfiguration('use_mock_hardware'))),
    ])
''')
    assert main(["run", str(launch), "--dry-run"]) == 0
    assert "1 error(s) hold only for other argument values" in capsys.readouterr().err
    assert main(["run", str(launch), "--dry-run", "use_mock_hardware:=true"]) == 1
    assert "not started" in capsys.readouterr().err


def test_a_dry_run_of_ros2_launch_shows_the_handover_and_runs_nothing(
        capsys: pytest.CaptureFixture[str], tmp_path: Path, ros2_calls: Path) -> None:
    launch = tmp_path / "ok.launch.xml"
    launch.write_text(f'<launch><arg name="robot" default="r1"/>'
                      f'<executable cmd="python3 {WORKER} $(var robot)"/></launch>')
    assert main(["run", str(launch), "robot:=r2", "--dry-run", "--engine", "ros2"]) == 0
    out = capsys.readouterr().out.splitlines()
    assert not ros2_calls.exists()
    assert out[0] == f"run {tmp_path / 'bin' / 'ros2'} launch {launch} robot:=r2"
    assert any(line.endswith(f"{WORKER} r2") for line in out)  # as the check evaluated it
    assert out[-1].startswith("note: ros2 launch evaluates the file itself")


def test_a_dry_run_of_ros2_launch_decides_as_the_run_does(
        capsys: pytest.CaptureFixture[str], tmp_path: Path,
        monkeypatch: pytest.MonkeyPatch) -> None:
    """Without ros2 it is refused as the run is; a condition known only at run time is
    ros2 launch's to decide, so it is said, not refused."""
    launch = tmp_path / "later.launch.xml"
    launch.write_text(f'<launch><executable cmd="python3 {WORKER} a" '
                      'if="$(env LV_TEST_FLAG_UNSET)"/></launch>')
    monkeypatch.delenv("LV_TEST_FLAG_UNSET", raising=False)
    assert main(["run", str(launch), "--dry-run", "--engine", "ros2"]) == 2
    assert "--engine ros2 needs the ROS 2 command line" in capsys.readouterr().err
    monkeypatch.setattr(shutil, "which", lambda name, *a, **k: "/opt/ros/bin/ros2"
                        if name == "ros2" else _real_which(name))
    assert main(["run", str(launch), "--dry-run", "--engine", "ros2"]) == 0
    out = capsys.readouterr().out.splitlines()
    assert out[0] == f"run /opt/ros/bin/ros2 launch {launch}"
    assert out[1].startswith("note: what it starts is known only when it runs: conditions "
                             "not known before run time")
    assert main(["run", str(launch), "--dry-run"]) == 2  # the embedded engine decides now


def test_ros2_launch_gets_the_file_by_a_path_it_cannot_read_as_an_option(
        capsys: pytest.CaptureFixture[str], tmp_path: Path, ros2_calls: Path,
        monkeypatch: pytest.MonkeyPatch) -> None:
    (tmp_path / "--help.launch.xml").write_text(
        f'<launch><executable cmd="python3 {WORKER} a"/></launch>')
    monkeypatch.chdir(tmp_path)
    assert main(["run", "--engine", "ros2", "--", "--help.launch.xml"]) == 0
    assert ros2_calls.read_text() == f"launch {tmp_path / '--help.launch.xml'}\n"
