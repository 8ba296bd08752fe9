from launch import LaunchDescription
from launch.actions import GroupAction
from launch_ros.actions import Node, PushRosNamespace, SetRemap


def generate_launch_description():
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name='front-camera'),  # expect: LV102
        Node(package='demo_nodes_cpp', executable='talker', name='2nd_talker'),  # expect: LV102
        Node(package='demo_nodes_cpp', executable='talker', name='ok_talker',
             namespace='robot 1'),  # expect: LV102
        Node(package='demo_nodes_cpp', executable='talker', name='t3',
             namespace='/robot//arm'),  # expect: LV102
        GroupAction([
            PushRosNamespace('9lives'),  # expect: LV102
        ]),
        # a remap rule's finding points at its tuple, as XML's at its <remap>
        Node(  # expect-not: LV102
            package='demo_nodes_cpp', executable='listener', name='listener',
            remappings=[
                ('chatter', '/robot/2chatter'),  # expect: LV102
                ('~/status', 'status_out'),  # fine: private name
                ('{node}/in', '/out'),
            ],
        ),
        SetRemap(src='scan*', dst='scan_filtered'),  # expect: LV102
    ])
