# Values from a module that is not installed here (gazebo_ros's `scripts` helper) are
# unknown: unpacking, paths, arithmetic, comparisons and loops on them give more unknowns,
# never an exception blamed on the launch file.
import os
from pathlib import Path

import gazebo_helpers  # expect: LV003
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    model, plugin, media = gazebo_helpers.get_paths()  # expect-not: LV002
    first, *rest = gazebo_helpers.values()  # expect-not: LV002
    world = Path(gazebo_helpers.share) / 'worlds' / 'empty.world'  # expect-not: LV002
    config = os.path.join(gazebo_helpers.share, 'config')  # expect-not: LV002
    if gazebo_helpers.count > 3:  # expect-not: LV002
        model += os.pathsep + str(media)
    for plugin_path in gazebo_helpers.plugins():  # expect-not: LV002
        raise RuntimeError(plugin_path)
    label = f'{gazebo_helpers.name:>10}'  # expect-not: LV002
    return LaunchDescription([
        Node(package='gazebo_ros', executable='spawn_entity.py', name='spawner',
             arguments=['-file', str(world), '-x', label, config]),
    ])
