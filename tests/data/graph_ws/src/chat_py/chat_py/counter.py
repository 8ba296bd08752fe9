"""Counts down on request (an action server) and asks another counter (an action client)."""

import rclpy
from example_interfaces.action import Fibonacci
from rclpy.action import ActionClient, ActionServer
from rclpy.node import Node


class Counter(Node):
    def __init__(self):
        super().__init__("counter")
        self.server = ActionServer(self, Fibonacci, "count", self.execute)
        self.peer = ActionClient(self, Fibonacci, "peer/count")

    def execute(self, goal):
        goal.succeed()
        return Fibonacci.Result()


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Counter())
    rclpy.shutdown()
