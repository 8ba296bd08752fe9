"""ros2_control's executables, as launch files name them (controller_manager, humble on)."""

from __future__ import annotations

SPAWNER = ("controller_manager", "spawner")  # asks a manager to load controllers
CONTROL_NODE = ("controller_manager", "ros2_control_node")  # the manager's process
MANAGER_NAME = "controller_manager"  # ros2_control_node's node name, the spawner's default
