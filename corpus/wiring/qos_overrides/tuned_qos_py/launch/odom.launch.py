from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        # an inline override makes the reliable source best effort: the consumer gets nothing
        Node(package='tuned_qos_py', executable='odom_source', name='wheel_odom',
             remappings=[('odom', '/wheel/odom')],
             parameters=[{'qos_overrides': {'/wheel/odom': {'publisher': {
                 'reliability': 'best_effort'}}}}]),
        Node(package='tuned_qos_py', executable='odom_consumer', name='wheel_consumer',  # expect: LV605
             remappings=[('odom', '/wheel/odom')]),
        # keyed by the name before the remap: the source stays reliable
        Node(package='tuned_qos_py', executable='odom_source', name='visual_odom',
             remappings=[('odom', '/visual/odom')],
             parameters=[{'qos_overrides./odom.publisher.reliability': 'best_effort'}]),
        Node(package='tuned_qos_py', executable='odom_consumer', name='visual_consumer',  # expect-not: LV605
             remappings=[('odom', '/visual/odom')]),
    ])
