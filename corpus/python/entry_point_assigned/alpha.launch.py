import functools

from fleet_tools.launch_utils import robot_launch

# ros2 launch only needs a callable named generate_launch_description
generate_launch_description = functools.partial(
    robot_launch, 'alpha', sensors=('lidar', 'camera', 'lidar'))
