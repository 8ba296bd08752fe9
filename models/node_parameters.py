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
    # ros2_control's: a controller is a node the manager makes (its own parameters are
    # controller_interface's, in LIBRARY_PARAMETERS)
    "controller_interface::ControllerInterface",
    "controller_interface::ChainableControllerInterface",
})
# Base classes by prefix that declare no parameters on the node deriving from them
NO_PARAMETERS = ("std::", "boost::", "rclcpp::", "rclcpp_lifecycle::", "rclpy.",
                 "enable_shared_from_this", "object")
# Constants of released libraries that name parameters (``bond::msg::Constants::...``)
NAME_CONSTANTS = {
    "bond::msg::Constants::DISABLE_HEARTBEAT_TIMEOUT_PARAM": "bond_disable_heartbeat_timeout",
}
# Released libraries that declare parameters on the node they are given, by the first part
# of their headers' paths: the names they may declare (``None``: any name). A library not
# listed is taken to declare none.
LIBRARY_PARAMETERS: dict[str, tuple[str, ...] | None] = {
    "image_transport": ("*.*",),  # <topic>.<transport>.<option>
    "point_cloud_transport": ("*.*",),
    "diagnostic_updater": ("diagnostic_updater.*",),
    "nav2_util": None,  # declare_parameter_if_not_declared, introspection_mode, bond_*
    "nav2_ros_common": None,
    "nav2_costmap_2d": None,
    "nav2_core": None,
    # ControllerInterfaceBase::init (controller_interface_base.cpp): humble declares
    # update_rate; jazzy and rolling also is_async and thread_priority. The spawner reads
    # type and fallback_controllers from the controller's own block of its parameter
    # files (controller_manager_services.set_controller_parameters_from_param_files)
    "controller_interface": ("update_rate", "is_async", "thread_priority", "type",
                             "fallback_controllers"),
}
