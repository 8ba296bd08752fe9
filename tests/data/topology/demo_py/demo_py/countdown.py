"""An action server and client, and message_filters subscribers."""

import message_filters
import rclpy
from action_tutorials_interfaces.action import Fibonacci
from rclpy.action import ActionClient, ActionServer
from rclpy.node import Node
from sensor_msgs.msg import CameraInfo, Image


class Countdown(Node):
    def __init__(self):
        super().__init__("countdown")  # expect-node-name: countdown
        self.server = ActionServer(self, Fibonacci, "fibonacci", self.execute)  # expect: action_server fibonacci action_tutorials_interfaces/action/Fibonacci
        self.client = ActionClient(self, Fibonacci, action_name="/other/fibonacci")  # expect: action_client /other/fibonacci action_tutorials_interfaces/action/Fibonacci
        image = message_filters.Subscriber(self, Image, "camera/image")  # expect: subscription camera/image sensor_msgs/msg/Image via=message_filters
        info = message_filters.Subscriber(self, CameraInfo, "camera/camera_info")  # expect: subscription camera/camera_info sensor_msgs/msg/CameraInfo via=message_filters
        self.sync = message_filters.TimeSynchronizer([image, info], 10)

    def execute(self, goal_handle):
        return Fibonacci.Result()


def main():
    rclpy.init()
    rclpy.spin(Countdown())
