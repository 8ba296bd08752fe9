"""Each node's activation waits for the other to be active: neither ever is."""
from launch import LaunchDescription
from launch.actions import EmitEvent, RegisterEventHandler
from launch.events import matches_action
from launch_ros.actions import LifecycleNode
from launch_ros.event_handlers import OnStateTransition
from launch_ros.events.lifecycle import ChangeState
from lifecycle_msgs.msg import Transition


def change(node, transition):
    return EmitEvent(event=ChangeState(lifecycle_node_matcher=matches_action(node),
                                       transition_id=transition))


def generate_launch_description():
    camera = LifecycleNode(package='usb_cam', executable='driver', name='camera',
                           namespace='sensors')
    detector = LifecycleNode(package='perception', executable='detector', name='detector',
                             namespace='perception')
    return LaunchDescription([
        camera,
        detector,
        change(camera, Transition.TRANSITION_CONFIGURE),
        change(detector, Transition.TRANSITION_CONFIGURE),
        # expect: LV503
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=camera, goal_state='active',
            entities=[change(detector, Transition.TRANSITION_ACTIVATE)])),
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=detector, goal_state='active',
            entities=[change(camera, Transition.TRANSITION_ACTIVATE)])),
    ])
