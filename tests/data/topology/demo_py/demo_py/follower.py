"""A tf2 follower: listens to frames, broadcasts its own, calls a service of a module it imports."""

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from tf2_ros import TransformBroadcaster
from tf2_ros.buffer import Buffer
from tf2_ros.static_transform_broadcaster import StaticTransformBroadcaster
from tf2_ros.transform_listener import TransformListener

from demo_py.spawner import Spawner


class Follower(Node):
    def __init__(self):
        super().__init__("turtle_follower")  # expect-node-name: turtle_follower
        self.buffer = Buffer()
        self.listener = TransformListener(self.buffer, self)  # expect: subscription /tf tf2_msgs/msg/TFMessage via=tf2_ros ; subscription /tf_static tf2_msgs/msg/TFMessage via=tf2_ros
        self.broadcaster = TransformBroadcaster(self)  # expect: publisher /tf tf2_msgs/msg/TFMessage via=tf2_ros
        self.static = StaticTransformBroadcaster(self)  # expect: publisher /tf_static tf2_msgs/msg/TFMessage via=tf2_ros
        self.cmd = self.create_publisher(Twist, "turtle2/cmd_vel", 1)  # expect: publisher turtle2/cmd_vel geometry_msgs/msg/Twist
        self.spawner = Spawner(self)
        for leader in self.declare_parameter("leaders", ["turtle1/pose"]).value:
            self.create_subscription(Twist, leader, self.on_leader, 1)  # expect: subscription ? geometry_msgs/msg/Twist unresolved


def main():
    rclpy.init()
    rclpy.spin(Follower())
