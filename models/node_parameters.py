"""Parameters every node has without declaring them: rclcpp's and rclpy's own.

Names as patterns (``*`` for any part): ``qos_overrides.*`` are declared for publishers
and subscriptions built with QoS overriding options.
"""

from __future__ import annotations

BUILTIN_PARAMETERS = ("use_sim_time", "start_type_description_service", "qos_overrides.*",
                      "start_parameter_services", "start_parameter_event_publisher")
# Base classes whose own declarations are these (a node class deriving from another one
# that the sources do not show may declare anything)
NODE_BASES = frozenset({
    "Node", "LifecycleNode", "rclcpp::Node", "rclcpp_lifecycle::LifecycleNode",
    "rclpy.node.Node", "rclpy.lifecycle.Node", "rclpy.lifecycle.LifecycleNode",
    "rclpy.lifecycle.node.LifecycleNode",
})
