from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, EmitEvent, RegisterEventHandler
from launch.events import matches_action
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import LifecycleNode
from launch_ros.event_handlers import OnStateTransition
from launch_ros.events.lifecycle import ChangeState
from lifecycle_msgs.msg import Transition


def generate_launch_description():
    talker = LifecycleNode(package='lifecycle', executable='lifecycle_talker',
                           name='lc_talker', namespace=LaunchConfiguration('ns'),
                           output='screen')
    configure = EmitEvent(event=ChangeState(
        lifecycle_node_matcher=matches_action(talker),
        transition_id=Transition.TRANSITION_CONFIGURE))
    activate = RegisterEventHandler(OnStateTransition(
        target_lifecycle_node=talker, goal_state='inactive',
        entities=[EmitEvent(event=ChangeState(
            lifecycle_node_matcher=matches_action(talker),
            transition_id=Transition.TRANSITION_ACTIVATE))]))
    return LaunchDescription([
        DeclareLaunchArgument('ns', default_value=''),
        activate,
        talker,
        configure,
        LifecycleNode(package='lifecycle', executable='lifecycle_listener',  # expect-not: LV101
                      name='lc_talker', namespace='monitor'),
        LifecycleNode(package='lifecycle', executable='lifecycle_listener',  # expect: LV101
                      name='lc_talker', namespace='/'),
    ])
