from launch import LaunchDescription

# robot_helpers.py lives in another package's launch folder; a.launch.py puts that folder
# on sys.path, but only in its own ros2 launch process: not for this file
from robot_helpers import drivers  # expect: LV003


def generate_launch_description():
    return LaunchDescription([*drivers('beta'), *drivers('beta')])
