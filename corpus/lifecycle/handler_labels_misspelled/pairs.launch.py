"""Labels that exist, but no single event carries them together (LV504), or that rcl never
publishes in their field (LV508)."""
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
    talker = LifecycleNode(package='lifecycle', executable='lifecycle_talker',
                           name='lc_talker', namespace='')
    listener = LifecycleNode(package='lifecycle', executable='lifecycle_listener',
                             name='lc_listener', namespace='')
    return LaunchDescription([
        talker,
        listener,
        change(talker, Transition.TRANSITION_CONFIGURE),
        change(listener, Transition.TRANSITION_CONFIGURE),
        # configure publishes unconfigured -> configuring, then configuring -> inactive:
        # no event goes from 'unconfigured' straight to 'inactive'
        # expect: LV503
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=talker,
            start_state='unconfigured',  # expect: LV504
            goal_state='inactive',
            entities=[change(talker, Transition.TRANSITION_ACTIVATE)])),
        # 'activating' is a state; the transition's label is 'activate'
        # expect: LV503
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=listener, goal_state='inactive',
            transition='activating',  # expect: LV508  # expect-not: LV504
            entities=[change(listener, Transition.TRANSITION_ACTIVATE)])),
        # nothing goes from active to unconfigured in one event; it gates only a log,
        # so the bring-up does not depend on it
        # expect-not: LV503
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=talker, start_state='active',  # expect: LV504
            goal_state='unconfigured',
            entities=[LogInfo(msg='talker cleaned up')])),
        # no transition leaves 'finalized'
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=talker, start_state='finalized',  # expect: LV508  # expect-not: LV504
            entities=[LogInfo(msg='talker gone')])),
        # a matcher of its own: launch_ros ignores the labels
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=talker, goal_state='whatever',  # expect-not: LV504 LV508
            matcher=lambda event: True,
            entities=[LogInfo(msg='talker moved')])),
    ])
