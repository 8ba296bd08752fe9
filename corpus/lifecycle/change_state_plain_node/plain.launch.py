"""ChangeState aimed at a plain Node: it has no lifecycle services, launch drops the event."""
from launch import LaunchDescription
from launch.actions import EmitEvent
from launch.events import matches_action
from launch_ros.actions import LifecycleNode, Node
from launch_ros.events.lifecycle import ChangeState
from lifecycle_msgs.msg import Transition


def generate_launch_description():
    driver = Node(package='demo_nodes_cpp', executable='talker', name='lidar')
    camera = LifecycleNode(package='usb_cam', executable='driver', name='camera',
                           namespace='')
    return LaunchDescription([
        driver,
        camera,
        EmitEvent(event=ChangeState(  # expect: LV504
            lifecycle_node_matcher=matches_action(driver),
            transition_id=Transition.TRANSITION_CONFIGURE)),
        EmitEvent(event=ChangeState(  # expect-not: LV504
            lifecycle_node_matcher=matches_action(camera),
            transition_id=Transition.TRANSITION_CONFIGURE)),
    ])
