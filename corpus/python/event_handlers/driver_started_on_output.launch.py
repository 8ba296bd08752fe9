# A driver started by a callback that reads the spawner's output (unknown until it runs),
# and a handler on the driver's exit: the driver is the same action in both, so the
# handler has its target. The handler whose target nothing starts is still reported.
import launch
from launch import LaunchDescription
from launch.actions import ExecuteProcess, RegisterEventHandler
from launch.event_handlers import OnProcessExit, OnProcessIO


def started_once_spawned(event, driver):
    if 'success=True' in event.text.decode():
        return driver
    return None


def generate_launch_description():
    spawner = ExecuteProcess(cmd=['ros2', 'service', 'call', '/spawn', 'std_srvs/srv/Trigger'])
    driver = ExecuteProcess(cmd=['robot_driver'], name='driver')
    forgotten = ExecuteProcess(cmd=['robot_logger'], name='logger')
    return LaunchDescription([
        spawner,
        RegisterEventHandler(OnProcessIO(
            target_action=spawner,
            on_stdout=lambda event: started_once_spawned(event, driver))),
        RegisterEventHandler(OnProcessExit(  # expect-not: LV502
            target_action=driver,
            on_exit=[launch.actions.EmitEvent(event=launch.events.Shutdown())])),
        RegisterEventHandler(OnProcessExit(  # expect: LV502
            target_action=forgotten,
            on_exit=[launch.actions.EmitEvent(event=launch.events.Shutdown())])),
    ])
