"""A listener whose topic is a parameter; it also asks the echo component to reset."""

import rclpy
from rclpy.node import Node
from std_msgs.msg import String
from std_srvs.srv import Empty
from tf2_ros.buffer import Buffer
from tf2_ros.transform_listener import TransformListener


class TunedListener(Node):
    def __init__(self):
        super().__init__("tuned_listener")
        topic = self.declare_parameter("topic", "chatter").value
        self.heard = self.create_subscription(String, topic, self.on_text, 10)
        self.reset = self.create_client(Empty, "/box/echo/reset")
        self.buffer = Buffer()
        self.frames = TransformListener(self.buffer, self)

    def on_text(self, msg):
        self.get_logger().info(msg.data)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(TunedListener())
    rclpy.shutdown()
