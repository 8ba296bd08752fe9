"""No lifecycle node at all: the ChangeState still goes nowhere."""
from launch import LaunchDescription
from launch.actions import EmitEvent
from launch.events import matches_action
from launch_ros.actions import Node
from launch_ros.events.lifecycle import ChangeState
from lifecycle_msgs.msg import Transition


def generate_launch_description():
    driver = Node(package='demo_nodes_cpp', executable='talker', name='lidar')
    return LaunchDescription([
        driver,
        EmitEvent(event=ChangeState(  # expect: LV504
            lifecycle_node_matcher=matches_action(driver),
            transition_id=Transition.TRANSITION_CONFIGURE)),
    ])
