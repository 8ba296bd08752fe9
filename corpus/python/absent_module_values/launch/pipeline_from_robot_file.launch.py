import yaml
from launch import LaunchDescription
from launch.actions import OpaqueFunction
from vendor_helpers import config_file_path


def stages_of(data):
    merged = {}
    for key, value in data.items():
        if isinstance(value, dict):
            merged.update(value.get('ros__parameters', {}))
    return merged.get('pipeline', {}).get('stages', [])


def setup(context):
    # the vendor's helper names the file: its content is unknown, and so are its keys
    with open(config_file_path(context)) as f:
        data = yaml.safe_load(f) or {}
    if not stages_of(data):
        raise RuntimeError('no pipeline stages declared')  # expect-not: LV002
    return []


def generate_launch_description():
    return LaunchDescription([OpaqueFunction(function=setup)])
