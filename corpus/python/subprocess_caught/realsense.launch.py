import subprocess

from launch import LaunchDescription
from launch_ros.actions import ComposableNodeContainer, Node
from launch_ros.descriptions import ComposableNode


def components_available():
    try:
        out = subprocess.check_output(['ros2', 'component', 'types'])  # expect: LV003
    except (subprocess.CalledProcessError, OSError):
        return False
    return b'realsense2_camera::RealSenseNodeFactory' in out


def generate_launch_description():
    if components_available():
        camera = ComposableNodeContainer(
            name='camera_container', namespace='camera', package='rclcpp_components',
            executable='component_container',
            composable_node_descriptions=[ComposableNode(
                package='realsense2_camera', plugin='realsense2_camera::RealSenseNodeFactory',
                name='camera', namespace='camera')])
    else:
        camera = Node(package='realsense2_camera', executable='realsense2_camera_node',
                      name='camera', namespace='camera')
    return LaunchDescription([camera])
