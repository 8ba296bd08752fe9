# nav2's RewrittenYaml loads a file with PyYAML and writes it out again for rcl: a key
# without a value becomes `null`, which rcl takes as text, so only the node that reads the
# file as it is written fails; a list rcl refuses stays refused after the rewrite.
import os

from launch import LaunchDescription
from launch_ros.actions import Node
from nav2_common.launch import RewrittenYaml

HERE = os.path.dirname(__file__)


def generate_launch_description():
    rewritten = RewrittenYaml(source_file=os.path.join(HERE, 'amcl.yaml'),
                              param_rewrites={'use_sim_time': 'false'}, convert_types=True)
    mixed = RewrittenYaml(source_file=os.path.join(HERE, 'mixed.yaml'), param_rewrites={},
                          convert_types=True)
    return LaunchDescription([
        Node(package='nav2_amcl', executable='amcl', name='amcl', parameters=[rewritten]),
        Node(package='nav2_amcl', executable='amcl', name='amcl_raw',
             parameters=[os.path.join(HERE, 'direct.yaml')]),
        Node(package='demo_nodes_cpp', executable='talker', name='talker', parameters=[mixed]),
    ])
