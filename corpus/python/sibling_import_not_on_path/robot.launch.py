from launch import LaunchDescription

# ros2 launch loads this file with SourceFileLoader and never adds its folder to
# sys.path: this import fails on the robot (ModuleNotFoundError)
from common import make_nodes  # expect: LV002


def generate_launch_description():
    return LaunchDescription(make_nodes('r1'))
