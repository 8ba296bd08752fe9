"""A detector ported from ROS 1, where it read its input through a private node handle."""

import rclpy
from rclpy.node import Node
from sensor_msgs.msg import Image
from vision_msgs.msg import Detection2DArray


class Detector(Node):

    def __init__(self):
        super().__init__('detector')
        self.detections = self.create_publisher(Detection2DArray, 'detections', 10)
        self.images = self.create_subscription(Image, '~/image_raw', self.on_image, 10)

    def on_image(self, image):
        self.detections.publish(Detection2DArray(header=image.header))


def main():
    rclpy.init()
    rclpy.spin(Detector())
    rclpy.shutdown()
