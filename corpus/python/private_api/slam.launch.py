# Launch files reach into the launch API beyond what they build: rtabmap_ros's
# rtabmap.launch.py evaluates conditions through their private `_predicate_func` in an
# OpaqueFunction; others call `evaluate`, `perform` and getters (`node_package`,
# `variable_name`). The models compute them as launch does: the odometry node's name comes
# out equal to the driver's only when every value is right (LV101), and none raises
# AttributeError (which would be an LV002 on the line that reads it).
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.conditions import IfCondition, UnlessCondition
from launch.substitutions import LaunchConfiguration, PythonExpression
from launch_ros.actions import Node


def launch_setup(context, *args, **kwargs):
    camera = LaunchConfiguration('camera')
    stereo = IfCondition(PythonExpression(["'", camera, "' == 'stereo'"]))._predicate_func(context)  # expect-not: LV002
    with_depth = UnlessCondition(LaunchConfiguration('no_depth')).evaluate(context)  # expect-not: LV002
    robot = LaunchConfiguration('robot')
    prefix = robot.perform(context)
    argument = robot.variable_name[0].perform(context)  # expect-not: LV002
    driver = Node(package='rtabmap_odom', executable='rgbd_odometry',
                  name=f"{prefix}_{'stereo' if stereo else 'rgbd'}_odometry")
    mode = ('stereo' if stereo else 'mono') if with_depth else 'none'
    odometry = Node(  # expect: LV101
        package=driver.node_package,  # expect-not: LV002
        executable=driver.node_executable,
        name=f'{context.launch_configurations[argument]}_{mode}_odometry')
    return [driver, odometry]


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('camera', default_value='stereo'),
        DeclareLaunchArgument('no_depth', default_value='false'),
        DeclareLaunchArgument('robot', default_value='rover'),
        OpaqueFunction(function=launch_setup),
    ])
