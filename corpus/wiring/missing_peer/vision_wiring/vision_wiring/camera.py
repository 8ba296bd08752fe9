"""A camera: publishes image_raw."""

import rclpy
from rclpy.node import Node
from sensor_msgs.msg import Image


class Camera(Node):

    def __init__(self):
        super().__init__('camera')
        self.publisher = self.create_publisher(Image, 'image_raw', 10)


def main():
    rclpy.init()
    rclpy.spin(Camera())
    rclpy.shutdown()
