import rclpy
from rcl_interfaces.msg import ParameterDescriptor
from rclpy.node import Node
from rclpy.parameter import Parameter


class SerialDriver(Node):

    def __init__(self):
        super().__init__('serial_driver')
        self.declare_parameter('device', Parameter.Type.STRING)
        self.declare_parameter('baud_rate', 115200)
        self.declare_parameter('timeout', 0.5)
        self.declare_parameter('frame_id', 'serial')
        self.declare_parameter('extra', 0, ParameterDescriptor(dynamic_typing=True))
        self.declare_parameters('filters', [('enabled', True), ('window', 5)])


def main():
    rclpy.init()
    rclpy.spin(SerialDriver())
