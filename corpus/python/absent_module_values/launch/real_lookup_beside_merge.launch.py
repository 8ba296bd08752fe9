from launch import LaunchDescription
from launch.actions import OpaqueFunction
from vendor_helpers import load_pipeline


def setup(context):
    # the lookup that fails happens before anything unknown is merged: a fact
    settings = {'rate': 10}
    settings['pipeline']  # expect: LV002
    settings.update(load_pipeline())
    return []


def generate_launch_description():
    return LaunchDescription([OpaqueFunction(function=setup)])
