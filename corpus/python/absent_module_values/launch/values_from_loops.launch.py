# A name built by a loop over a vendor's list: empty only because launchverify assumed the
# list empty, so it is no invalid name; the vendor's exception class is caught or not
# by an assumption, and a class built on the vendor's makes unknown values. The evaluation
# goes on past them: a real duplicate is still found.
from launch import LaunchDescription
from launch_ros.actions import Node
import acme_fleet


class Robot(acme_fleet.Base):
    def frame(self):
        return self.prefix + '_base'


def generate_launch_description():
    name = '_'.join(part for part in acme_fleet.name_parts())
    try:
        mode = acme_fleet.load_mode()
    except acme_fleet.ConfigError:
        mode = 'sim'
    nodes = [
        Node(package='demo_nodes_cpp', executable='talker', name=name),  # expect-not: LV102
        Node(package='demo_nodes_cpp', executable='listener', name=Robot().frame()),  # expect-not: LV102
        Node(package='demo_nodes_cpp', executable='talker', name='talker', namespace=mode),
        Node(package='demo_nodes_cpp', executable='talker', name='fixed'),
        Node(package='demo_nodes_cpp', executable='listener', name='fixed'),  # expect: LV101
    ]
    return LaunchDescription(nodes)
