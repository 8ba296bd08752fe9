# The OpaqueFunction runs only with rosbag:=<a bag>; evaluated with the default it fails,
# but that is not what ros2 launch does by default: not judged (LV003), not an error.
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration, PythonExpression


def play(context):
    bag = LaunchConfiguration('rosbag').perform(context)
    assert bag != 'None', f'rosbag {bag} does not exist'  # expect: LV003  # expect-not: LV002
    return []


def generate_launch_description():
    has_bag = PythonExpression(["'", LaunchConfiguration('rosbag'), "' != 'None'"])
    return LaunchDescription([
        DeclareLaunchArgument('rosbag', default_value='None'),
        OpaqueFunction(function=play, condition=IfCondition(has_bag)),
    ])
