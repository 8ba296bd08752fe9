"""A listener with its topic in a parameter, and names that stay unknown."""

import rclpy
from rclpy.node import Node
from rclpy.qos import qos_profile_sensor_data
from sensor_msgs.msg import LaserScan
from std_msgs.msg import String as Text
import std_srvs.srv

STATUS = "status"


class Listener(Node):
    def __init__(self, suffix):
        super().__init__("listener")  # expect-node-name: listener
        self.declare_parameter("topic", "chatter")
        topic = self.get_parameter("topic").get_parameter_value().string_value
        self.sub = self.create_subscription(Text, topic, self.on_text, 10)  # expect: subscription chatter std_msgs/msg/String param=topic
        self.scan_topic = self.declare_parameter("scan_topic", "/scan").value
        self.scan = self.create_subscription(  # expect: subscription /scan sensor_msgs/msg/LaserScan param=scan_topic
            LaserScan, self.scan_topic, self.on_scan, qos_profile_sensor_data)
        self.status = self.create_publisher(msg_type=Text, topic=STATUS, qos_profile=1)  # expect: publisher status std_msgs/msg/String
        self.reset = self.create_service(std_srvs.srv.Empty, "~/reset", self.on_reset)  # expect: service ~/reset std_srvs/srv/Empty
        self.named = self.create_publisher(Text, f"{self.get_name()}/echo", 10)  # expect: publisher ? std_msgs/msg/String unresolved
        self.suffixed = self.create_publisher(Text, "out_" + suffix, 10)  # expect: publisher ? std_msgs/msg/String unresolved

    def on_text(self, msg):
        self.get_logger().info(msg.data)

    def on_scan(self, msg):
        pass

    def on_reset(self, request, response):
        return response


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Listener("x"))
    rclpy.shutdown()
