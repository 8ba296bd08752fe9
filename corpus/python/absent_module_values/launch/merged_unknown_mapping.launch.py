from launch import LaunchDescription
from launch.actions import OpaqueFunction
from vendor_helpers import load_pipeline


def setup(context):
    # what the vendor's mapping holds is merged in: any key may be there on the robot
    settings = {'rate': 10}
    settings.update(load_pipeline())
    stages = settings.get('pipeline', {}).get('stages', [])
    if not stages:
        raise RuntimeError('no pipeline stages')  # expect-not: LV002
    merged = {**load_pipeline(), 'rate': 10}
    merged['controller_names']  # expect-not: LV002
    return []


def generate_launch_description():
    return LaunchDescription([OpaqueFunction(function=setup)])
