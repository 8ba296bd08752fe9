"""The Python actions behind the tags: the same nodes, the same checks."""

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition, UnlessCondition
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution, ThisLaunchFileDir
from ros_gz_bridge.actions import RosGzBridge
from ros_gz_sim.actions import GzServer, GzSpawnModel


def generate_launch_description():
    config = PathJoinSubstitution([ThisLaunchFileDir(), 'clock.yaml'])
    use_sim_gui = LaunchConfiguration('gui')
    return LaunchDescription([
        DeclareLaunchArgument('gui', default_value='false'),
        DeclareLaunchArgument('robot', default_value='robot1'),
        # the ros_gz_sim.launch.py way: one container, the bridge loaded into it
        GzServer(world_sdf_file='empty.sdf', container_name='sim_container',
                 create_own_container=True, use_composition=True),
        RosGzBridge(bridge_name='clock_bridge', config_file=config,
                    container_name='sim_container', use_composition='True'),
        # a second bridge of that name, standalone: both are /clock_bridge
        RosGzBridge(bridge_name='clock_bridge', config_file=config),  # expect: LV101
        # twins: in the robot's namespace; under conditions that exclude each other
        RosGzBridge(bridge_name='clock_bridge', config_file=config,  # expect-not: LV101
                    namespace=LaunchConfiguration('robot')),
        RosGzBridge(bridge_name='gui_bridge', config_file=config,
                    condition=IfCondition(use_sim_gui)),
        RosGzBridge(bridge_name='gui_bridge', config_file=config,  # expect-not: LV101
                    condition=UnlessCondition(use_sim_gui),
                    extra_bridge_params={'expand_gz_topic_names': True}),
        GzSpawnModel(world='empty', file=PathJoinSubstitution([ThisLaunchFileDir(), 'robot.sdf']),
                     entity_name=LaunchConfiguration('robot')),
    ])
