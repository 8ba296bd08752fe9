from launch import LaunchDescription
from launch_ros.actions import LifecycleNode


def generate_launch_description():
    # LifecycleNode requires namespace= (keyword-only, no default): TypeError
    driver = LifecycleNode(package='nav2_map_server', executable='map_server',  # expect: LV002
                           name='map_server', parameters=[{'yaml_filename': 'map.yaml'}])
    return LaunchDescription([driver])
