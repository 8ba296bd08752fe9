"""Handler labels rcl never publishes in their field (LV508), next to a pair it publishes
but never in one event (LV504).

launch_ros compares each label with the event's by ==: none of these handlers ever fires.
They only log, so the bring-up itself does not wait on them (no LV503).
"""
from launch import LaunchDescription
from launch.actions import EmitEvent, LogInfo, RegisterEventHandler
from launch.events import matches_action
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import LifecycleNode
from launch_ros.event_handlers import OnStateTransition
from launch_ros.events.lifecycle import ChangeState
from lifecycle_msgs.msg import Transition


def change(node, transition):
    return EmitEvent(event=ChangeState(lifecycle_node_matcher=matches_action(node),
                                       transition_id=transition))


def generate_launch_description():
    camera = LifecycleNode(package='lifecycle', executable='lifecycle_talker',
                           name='camera', namespace='')
    return LaunchDescription([
        camera,
        change(camera, Transition.TRANSITION_CONFIGURE),
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=camera,
            start_state='configuring', goal_state='inactive',  # expect-not: LV508 LV504
            entities=[change(camera, Transition.TRANSITION_ACTIVATE)])),
        # a word for the state, not its label: 'active'
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=camera, entities=[LogInfo(msg='up')],
            goal_state='activated')),  # expect: LV508
        # the constant's name, not its label: 'inactive'
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=camera, entities=[LogInfo(msg='idle')],
            goal_state='PRIMARY_STATE_INACTIVE')),  # expect: LV508
        # rcl writes 'cleaningup' in one word
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=camera, entities=[LogInfo(msg='cleaned')],
            start_state='cleaning_up')),  # expect: LV508
        # no node is ever in 'unknown'
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=camera, entities=[LogInfo(msg='lost')],
            goal_state='unknown')),  # expect: LV508
        # a substitution is compared unperformed: it equals no label
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=camera, entities=[LogInfo(msg='chosen')],
            # expect: LV508
            goal_state=LaunchConfiguration('camera_state', default='active'))),
        # both labels are rcl's, but activate goes inactive -> activating -> active
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=camera, entities=[LogInfo(msg='two steps')],
            start_state='inactive',  # expect: LV504
            goal_state='active')),  # expect-not: LV508
    ])
