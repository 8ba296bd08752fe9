from launch import LaunchDescription
from launch_ros.actions import Node

SUPPORTED = ('burger', 'waffle')


def check_model(model):
    if model not in SUPPORTED:
        raise RuntimeError(f'unsupported robot model {model!r}')  # expect: LV002
    return model


def generate_launch_description():
    model = check_model('waffle_pi')
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name=f'{model}_driver'),
    ])
