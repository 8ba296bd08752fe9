import rclpy
from nav_msgs.msg import Odometry
from rclpy.node import Node


class OdomConsumer(Node):

    def __init__(self):
        super().__init__('odom_consumer')
        self.odom = self.create_subscription(Odometry, 'odom', self.take, 10)  # reliable

    def take(self, message):
        pass


def main():
    rclpy.init()
    rclpy.spin(OdomConsumer())
