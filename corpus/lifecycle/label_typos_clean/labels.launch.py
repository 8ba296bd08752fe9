"""The twin of label_typos_misspelled: every label written as rcl publishes it.

Lower-case states, transition states as start states, a goal that only a shutdown
reaches: each handler can fire, so LV508 stays quiet.
"""
from launch import LaunchDescription
from launch.actions import EmitEvent, LogInfo, RegisterEventHandler
from launch.events import matches_action
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
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=camera, entities=[LogInfo(msg='activating')],
            goal_state='activating')),  # expect-not: LV508
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=camera, entities=[LogInfo(msg='active')],
            goal_state='active')),  # expect-not: LV508
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=camera, entities=[LogInfo(msg='cleaned up')],
            start_state='cleaningup',  # expect-not: LV508
            goal_state='unconfigured')),
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=camera, entities=[LogInfo(msg='shutting down')],
            start_state='inactive',  # expect-not: LV508
            goal_state='shuttingdown')),
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=camera, entities=[LogInfo(msg='gone')],
            goal_state='finalized')),  # expect-not: LV508
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=camera, entities=[LogInfo(msg='failed')],
            goal_state='errorprocessing')),  # expect-not: LV508
    ])
