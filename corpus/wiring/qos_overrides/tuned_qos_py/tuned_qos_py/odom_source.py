import rclpy
from nav_msgs.msg import Odometry
from rclpy.node import Node
from rclpy.qos import QoSPolicyKind
from rclpy.qos_overriding_options import QoSOverridingOptions


class OdomSource(Node):

    def __init__(self):
        super().__init__('odom_source')
        # reliable (a depth: the default profile) unless the launch overrides reliability
        self.odom = self.create_publisher(
            Odometry, 'odom', 10,
            qos_overriding_options=QoSOverridingOptions([QoSPolicyKind.RELIABILITY]))


def main():
    rclpy.init()
    rclpy.spin(OdomSource())
