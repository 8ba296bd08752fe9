from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    # the same action object added twice is executed twice; launch raises
    # RuntimeError: ExecuteLocal action 'rviz2-3': executed more than once
    # (the object, not a second node: findings can only point at where it was built)
    rviz = Node(package='rviz2', executable='rviz2', name='rviz2')  # expect: LV002  # expect-not: LV101
    state_publisher = Node(package='robot_state_publisher', executable='robot_state_publisher')
    ld = LaunchDescription()
    ld.add_action(rviz)
    ld.add_action(state_publisher)
    ld.add_action(rviz)  # copy-pasted from another launch file
    return ld
