# Values of the vendor's where models check what they are given: a node's parameters, a
# transition id, a configuration's name, a locals mapping, a type to convert to. Each is
# unknown, none a failure (LV002, or an LV003 that stops the evaluation), and the real
# mistake after them is still found.
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, EmitEvent, OpaqueFunction
from launch.events import matches_action
from launch.substitutions import LaunchConfiguration
from launch.utilities import perform_typed_substitution
from launch_ros.actions import LifecycleNode, Node
from launch_ros.events.lifecycle import ChangeState
import vendor_helpers


def setup(context):
    context.extend_locals(vendor_helpers.extras())
    name = context.locals.robot_name  # expect-not: LV002
    mode = context.launch_configurations[vendor_helpers.MODE_ARGUMENT]  # expect-not: LV002
    rate = perform_typed_substitution(context, vendor_helpers.RATE, float)  # expect-not: LV002
    flag = perform_typed_substitution(context, LaunchConfiguration('x', default='1'),
                                      vendor_helpers.Flag)  # expect-not: LV002
    return [Node(package='demo_nodes_cpp', executable='listener', name=name,
                 parameters=[{'mode': mode, 'rate': rate, 'flag': flag}])]


def generate_launch_description():
    driver = LifecycleNode(package='demo_nodes_cpp', executable='talker', name='driver',
                           namespace='')
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker',
             parameters=vendor_helpers.parameters()),  # expect-not: LV002
        driver,
        EmitEvent(event=ChangeState(lifecycle_node_matcher=matches_action(driver),  # expect-not: LV002
                                    transition_id=vendor_helpers.CONFIGURE)),
        OpaqueFunction(function=setup),  # expect-not: LV201
        DeclareLaunchArgument('robot_name', default_value='r1'),  # an entry point
        Node(package='demo_nodes_cpp', executable='talker', name=LaunchConfiguration('robot_name'),
             namespace=LaunchConfiguration('robot_id')),  # expect: LV201
    ])
