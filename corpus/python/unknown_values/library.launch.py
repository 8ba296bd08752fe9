# A failure inside an installed library is no verdict: launchverify's copy of it is not
# the robot's (usb_cam's helper module fails under pydantic 2, works under pydantic 1).
import yaml
from launch import LaunchDescription


def generate_launch_description():
    settings = yaml.safe_load('{camera: [')  # expect: LV003
    return LaunchDescription([])
