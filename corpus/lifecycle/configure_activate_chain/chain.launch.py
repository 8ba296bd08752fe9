"""Configure at launch, activate when the node reaches 'inactive': the usual chain."""
from launch import LaunchDescription
from launch.actions import EmitEvent, RegisterEventHandler
from launch.events import matches_action
from launch_ros.actions import LifecycleNode
from launch_ros.event_handlers import OnStateTransition
from launch_ros.events.lifecycle import ChangeState
from lifecycle_msgs.msg import Transition


def generate_launch_description():
    talker = LifecycleNode(package='lifecycle', executable='lifecycle_talker',
                           name='lc_talker', namespace='')
    configure = EmitEvent(event=ChangeState(  # expect-not: LV504
        lifecycle_node_matcher=matches_action(talker),
        transition_id=Transition.TRANSITION_CONFIGURE))
    # expect-not: LV503
    activate_when_inactive = RegisterEventHandler(OnStateTransition(
        target_lifecycle_node=talker, start_state='configuring', goal_state='inactive',
        entities=[EmitEvent(event=ChangeState(  # expect-not: LV504
            lifecycle_node_matcher=matches_action(talker),
            transition_id=Transition.TRANSITION_ACTIVATE))]))
    listener = LifecycleNode(package='lifecycle', executable='lifecycle_listener',
                             name='listener', namespace='')
    # expect-not: LV503
    start_listener_when_active = RegisterEventHandler(OnStateTransition(
        target_lifecycle_node=talker, goal_state='active',
        entities=[listener,
                  EmitEvent(event=ChangeState(  # expect-not: LV504
                      lifecycle_node_matcher=matches_action(listener),
                      transition_id=Transition.TRANSITION_CONFIGURE))]))
    return LaunchDescription([activate_when_inactive, start_listener_when_active, talker,
                              configure])
