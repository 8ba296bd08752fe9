"""Two parties drive one node: autostart configures it, and so does the manager."""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition, UnlessCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import LifecycleNode, Node


def generate_launch_description():
    manage = LaunchConfiguration('use_manager')
    return LaunchDescription([
        DeclareLaunchArgument('use_manager', default_value='true'),
        LifecycleNode(package='nav2_controller', executable='controller_server',
                      name='controller_server', namespace='', autostart=True),
        Node(package='nav2_lifecycle_manager', executable='lifecycle_manager',  # expect: LV504
             name='lifecycle_manager_navigation',
             parameters=[{'autostart': True, 'node_names': ['controller_server']}]),
        # one party or the other, never both: fine
        LifecycleNode(package='nav2_planner', executable='planner_server',
                      name='planner_server', namespace='', autostart=True,
                      condition=UnlessCondition(manage)),
        Node(package='nav2_lifecycle_manager', executable='lifecycle_manager',  # expect-not: LV504
             name='lifecycle_manager_planning', condition=IfCondition(manage),
             parameters=[{'autostart': True, 'node_names': ['planner_server']}]),
        LifecycleNode(package='nav2_planner', executable='planner_server',
                      name='planner_server', namespace='', condition=IfCondition(manage)),
    ])
