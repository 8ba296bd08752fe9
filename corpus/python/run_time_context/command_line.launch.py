# A launch file that checks its own command line (rosbag2's benchmark): it sees what
# ros2 launch leaves in sys.argv, never launchverify's command line.
import sys

from launch import LaunchDescription


def generate_launch_description():
    if sys.argv[:2] != ['ros2', 'launch']:
        raise RuntimeError(f'not run by ros2 launch: {sys.argv}')  # expect-not: LV002
    return LaunchDescription([])
