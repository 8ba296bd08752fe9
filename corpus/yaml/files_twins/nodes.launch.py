from launch import LaunchDescription  # expect: LV003


def generate_launch_description():
    return LaunchDescription([])
