from launch import LaunchDescription
from launch_ros.actions import Node

# launch files must not have side effects: the evaluation refuses to write this file
with open('/tmp/launchverify_corpus_must_not_exist.yaml', 'w') as out:  # expect: LV003
    out.write('talker:\n  ros__parameters:\n    rate: 5\n')


def generate_launch_description():
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name='talker',
             parameters=['/tmp/launchverify_corpus_must_not_exist.yaml']),
    ])
