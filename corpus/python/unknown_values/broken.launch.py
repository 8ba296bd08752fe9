# The buggy twin: a failure that happens on every machine is still an error.
from launch import LaunchDescription


def generate_launch_description():
    model, plugin, media = ['model_path', 'plugin_path']  # expect: LV002
    return LaunchDescription([])
