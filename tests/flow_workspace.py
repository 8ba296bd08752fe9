"""A generated fleet workspace with node sources: the computation graph at scale.

``write_workspace(folder, robots)`` writes a colcon-like ``src/`` with four packages whose
nodes are real C++ (rclcpp, rclcpp_action, tf2_ros) and Python (rclpy) sources, and a
``fleet.launch.xml`` that starts ``robots`` robots of 22 nodes each (one include per
robot, in its own namespace) plus fleet-wide nodes in ``/``: 9 robots make 201 nodes.

A robot's nodes are wired as a real stack: three lidars and two cameras feed filters and
a detector, a localizer reads the scans and the fleet's ``/map``, a planner serves a
``navigate_to_pose`` action the behaviour node calls, the controller's command goes
through a multiplexer to the base driver; every robot broadcasts and listens to tf.
Cameras start only with ``use_cameras`` (a conditional node), a teleop topic is read but
never published and a diagnostics topic published but never read, and one fleet node is
from a released package (no sources here). Deterministic: no randomness at all.

Used by the tests (tests/test_flow.py) and by ``bench/flow_report.py``.
"""

from __future__ import annotations

from pathlib import Path

# executable -> (language, default node name, endpoints: (kind, type, name))
Spec = tuple[str, str, list[tuple[str, str, str]]]
SCAN, IMAGE, IMU = "sensor_msgs/msg/LaserScan", "sensor_msgs/msg/Image", "sensor_msgs/msg/Imu"
ODOM, TWIST, PATH = "nav_msgs/msg/Odometry", "geometry_msgs/msg/Twist", "nav_msgs/msg/Path"
POSE, MAP = "geometry_msgs/msg/PoseWithCovarianceStamped", "nav_msgs/msg/OccupancyGrid"
OBJECTS, BATTERY = "vision_msgs/msg/Detection2DArray", "sensor_msgs/msg/BatteryState"
DIAG, TRIGGER = "diagnostic_msgs/msg/DiagnosticArray", "std_srvs/srv/Trigger"
NAVIGATE, LOAD_MAP = "nav2_msgs/action/NavigateToPose", "nav2_msgs/srv/LoadMap"

PACKAGES: dict[str, dict[str, Spec]] = {
    "fleet_sensors": {
        "lidar_driver": ("cpp", "lidar_driver", [("pub", SCAN, "scan"), ("tf", "", "")]),
        "camera_driver": ("cpp", "camera_driver", [("pub", IMAGE, "image_raw")]),
        "imu_driver": ("cpp", "imu_driver", [("pub", IMU, "imu/data")]),
    },
    "fleet_perception": {
        "scan_filter": ("cpp", "scan_filter", [("sub", SCAN, "scan"),
                                               ("pub", SCAN, "scan_filtered")]),
        "obstacle_detector": ("cpp", "obstacle_detector", [
            ("sub", SCAN, "front/scan_filtered"), ("sub", SCAN, "rear/scan_filtered"),
            ("sub", SCAN, "top/scan_filtered"), ("pub", OBJECTS, "obstacles"),
            ("listen", "", "")]),
        "camera_processor": ("cpp", "camera_processor", [
            ("sub", IMAGE, "image_raw"), ("pub", OBJECTS, "detections")]),
        "fusion": ("cpp", "fusion", [
            ("sub", OBJECTS, "obstacles"), ("sub", OBJECTS, "left_camera/detections"),
            ("sub", OBJECTS, "right_camera/detections"), ("pub", OBJECTS, "tracked_objects")]),
    },
    "fleet_nav": {
        "localizer": ("cpp", "localizer", [
            ("sub", SCAN, "front/scan_filtered"), ("sub", MAP, "/map"), ("sub", IMU, "imu/data"),
            ("sub", ODOM, "odom"), ("pub", POSE, "pose"), ("srv", TRIGGER, "~/reset"),
            ("tf", "", ""), ("listen", "", "")]),
        "planner": ("cpp", "planner", [
            ("sub", MAP, "/map"), ("sub", POSE, "pose"), ("sub", OBJECTS, "tracked_objects"),
            ("pub", PATH, "plan"), ("action_server", NAVIGATE, "navigate_to_pose"),
            ("listen", "", "")]),
        "controller": ("cpp", "controller", [
            ("sub", PATH, "plan"), ("sub", ODOM, "odom"), ("pub", TWIST, "cmd_vel_nav")]),
        "velocity_mux": ("cpp", "velocity_mux", [
            ("sub", TWIST, "cmd_vel_nav"), ("sub", TWIST, "cmd_vel_teleop"),
            ("pub", TWIST, "cmd_vel")]),
        "behavior": ("cpp", "behavior", [
            ("action_client", NAVIGATE, "navigate_to_pose"), ("client", TRIGGER,
                                                              "localizer/reset"),
            ("sub", BATTERY, "battery")]),
    },
    "fleet_base": {
        "base_driver": ("python", "base_driver", [
            ("sub", TWIST, "cmd_vel"), ("pub", ODOM, "odom"), ("tf", "", "")]),
        "battery_monitor": ("python", "battery_monitor", [("pub", BATTERY, "battery")]),
        "diagnostics": ("python", "diagnostics", [
            ("sub", BATTERY, "battery"), ("pub", DIAG, "diagnostics")]),
    },
    "fleet_core": {
        "map_server": ("cpp", "map_server", [
            ("pub", MAP, "map"), ("srv", LOAD_MAP, "~/load_map")]),
        "fleet_manager": ("cpp", "fleet_manager", [("sub", MAP, "/map")]),
    },
}

# One robot: (package, executable, name, remaps, condition)
ROBOT: list[tuple[str, str, str, list[tuple[str, str]], str | None]] = [
    *[("fleet_sensors", "lidar_driver", f"{side}_lidar", [("scan", f"{side}/scan")], None)
      for side in ("front", "rear", "top")],
    *[("fleet_sensors", "camera_driver", f"{side}_camera",
       [("image_raw", f"{side}_camera/image_raw")], "use_cameras")
      for side in ("left", "right")],
    ("fleet_sensors", "imu_driver", "imu", [], None),
    ("fleet_sensors", "imu_driver", "imu_backup", [("imu/data", "imu_backup/data")], None),
    *[("fleet_perception", "scan_filter", f"{side}_filter",
       [("scan", f"{side}/scan"), ("scan_filtered", f"{side}/scan_filtered")], None)
      for side in ("front", "rear", "top")],
    ("fleet_perception", "obstacle_detector", "obstacle_detector", [], None),
    *[("fleet_perception", "camera_processor", f"{side}_processor",
       [("image_raw", f"{side}_camera/image_raw"),
        ("detections", f"{side}_camera/detections")], "use_cameras")
      for side in ("left", "right")],
    ("fleet_perception", "fusion", "fusion", [], None),
    ("fleet_nav", "localizer", "localizer", [], None),
    ("fleet_nav", "planner", "planner", [], None),
    ("fleet_nav", "controller", "controller", [], None),
    ("fleet_nav", "velocity_mux", "velocity_mux", [], None),
    ("fleet_nav", "behavior", "behavior", [], None),
    ("fleet_base", "base_driver", "base_driver", [], None),
    ("fleet_base", "battery_monitor", "battery_monitor", [], None),
    ("fleet_base", "diagnostics", "diagnostics", [], None),
]
NODES_PER_ROBOT = len(ROBOT)
FLEET_NODES = 3  # map_server, fleet_manager and a released rviz2


def write_workspace(folder: Path, robots: int = 9) -> Path:
    """Write the workspace below ``folder``; return the root launch file."""
    for package, executables in PACKAGES.items():
        _package(folder / "src" / package, package, executables)
    launch = folder / "src" / "fleet_core" / "launch"
    launch.mkdir(parents=True, exist_ok=True)
    (launch / "robot.launch.xml").write_text(_robot_launch(), encoding="utf-8")
    root = launch / "fleet.launch.xml"
    root.write_text(_fleet_launch(robots), encoding="utf-8")
    return root


def _robot_launch() -> str:
    lines = ['<launch>', '  <arg name="use_cameras" default="true"/>']
    for package, executable, name, remaps, condition in ROBOT:
        when = f' if="$(var {condition})"' if condition else ""
        inner = "".join(f'\n    <remap from="{a}" to="{b}"/>' for a, b in remaps)
        close = f"{inner}\n  </node>" if inner else ""
        lines.append(f'  <node pkg="{package}" exec="{executable}" name="{name}"{when}'
                     + (f">{close}" if close else "/>"))
    lines.append("</launch>")
    return "\n".join(lines) + "\n"


def _fleet_launch(robots: int) -> str:
    lines = ["<launch>",
             '  <node pkg="fleet_core" exec="map_server" name="map_server"/>',
             '  <node pkg="fleet_core" exec="fleet_manager" name="fleet_manager"/>',
             '  <node pkg="rviz2" exec="rviz2" name="rviz2"/>']
    for index in range(1, robots + 1):
        lines += ["  <group>",
                  f'    <push_ros_namespace namespace="robot{index}"/>',
                  '    <include file="$(dirname)/robot.launch.xml"/>',
                  "  </group>"]
    lines.append("</launch>")
    return "\n".join(lines) + "\n"


def _package(folder: Path, name: str, executables: dict[str, Spec]) -> None:
    python = any(language == "python" for language, _, _ in executables.values())
    cpp = [e for e, (language, _, _) in executables.items() if language == "cpp"]
    folder.mkdir(parents=True, exist_ok=True)
    build = "ament_cmake" if cpp else "ament_python"
    (folder / "package.xml").write_text(
        '<?xml version="1.0"?>\n<package format="3">\n'
        f"  <name>{name}</name>\n  <version>0.1.0</version>\n"
        "  <description>Generated fleet package (tests/flow_workspace.py).</description>\n"
        '  <maintainer email="dev@example.com">dev</maintainer>\n'
        "  <license>Apache-2.0</license>\n"
        f"  <buildtool_depend>{build}</buildtool_depend>\n"
        f"  <export><build_type>{build}</build_type></export>\n</package>\n",
        encoding="utf-8")
    if cpp:
        (folder / "src").mkdir(exist_ok=True)
        for executable in cpp:
            _, node_name, endpoints = executables[executable]
            (folder / "src" / f"{executable}.cpp").write_text(
                _cpp(executable, node_name, endpoints), encoding="utf-8")
        targets = "".join(f"add_executable({e} src/{e}.cpp)\n" for e in cpp)
        (folder / "CMakeLists.txt").write_text(
            f"cmake_minimum_required(VERSION 3.8)\nproject({name})\n"
            "find_package(ament_cmake REQUIRED)\nfind_package(rclcpp REQUIRED)\n"
            f"{targets}install(TARGETS {' '.join(cpp)} DESTINATION lib/${{PROJECT_NAME}})\n"
            "install(DIRECTORY launch DESTINATION share/${PROJECT_NAME} OPTIONAL)\n"
            "ament_package()\n", encoding="utf-8")
    if python:
        scripts = [e for e, (language, _, _) in executables.items() if language == "python"]
        module = folder / name
        module.mkdir(exist_ok=True)
        (module / "__init__.py").write_text("", encoding="utf-8")
        for executable in scripts:
            _, node_name, endpoints = executables[executable]
            (module / f"{executable}.py").write_text(_python(node_name, endpoints),
                                                     encoding="utf-8")
        (folder / "resource").mkdir(exist_ok=True)
        (folder / "resource" / name).write_text("", encoding="utf-8")
        entries = "".join(f'            "{e} = {name}.{e}:main",\n' for e in scripts)
        (folder / "setup.py").write_text(
            f'from setuptools import setup\n\npackage_name = "{name}"\n\nsetup(\n'
            '    name=package_name,\n    version="0.1.0",\n    packages=[package_name],\n'
            "    entry_points={\n        \"console_scripts\": [\n"
            f"{entries}        ],\n    }},\n)\n", encoding="utf-8")


def _cpp_type(written: str) -> str:
    return written.replace("/", "::")


def _cpp(executable: str, node_name: str, endpoints: list[tuple[str, str, str]]) -> str:
    cls = "".join(part.title() for part in executable.split("_"))
    members, body = [], []
    for number, (kind, kind_type, name) in enumerate(endpoints):
        cpp_type = _cpp_type(kind_type)
        member = f"e{number}_"
        if kind == "pub":
            body.append(f'    {member} = create_publisher<{cpp_type}>("{name}", 10);')
            members.append(f"  rclcpp::Publisher<{cpp_type}>::SharedPtr {member};")
        elif kind == "sub":
            body.append(f'    {member} = create_subscription<{cpp_type}>(\n      "{name}", 10, '
                        f"[](const {cpp_type}::ConstSharedPtr) {{}});")
            members.append(f"  rclcpp::Subscription<{cpp_type}>::SharedPtr {member};")
        elif kind == "srv":
            body.append(f'    {member} = create_service<{cpp_type}>(\n      "{name}", '
                        f"[](const std::shared_ptr<{cpp_type}::Request>,\n"
                        f"      std::shared_ptr<{cpp_type}::Response>) {{}});")
            members.append(f"  rclcpp::Service<{cpp_type}>::SharedPtr {member};")
        elif kind == "client":
            body.append(f'    {member} = create_client<{cpp_type}>("{name}");')
            members.append(f"  rclcpp::Client<{cpp_type}>::SharedPtr {member};")
        elif kind == "action_server":
            body.append(f"    {member} = rclcpp_action::create_server<{cpp_type}>(\n"
                        f'      this, "{name}", nullptr, nullptr, nullptr);')
            members.append(f"  rclcpp_action::Server<{cpp_type}>::SharedPtr {member};")
        elif kind == "action_client":
            body.append(f'    {member} = rclcpp_action::create_client<{cpp_type}>(this, '
                        f'"{name}");')
            members.append(f"  rclcpp_action::Client<{cpp_type}>::SharedPtr {member};")
        elif kind == "tf":
            body.append(f"    {member} = std::make_unique<tf2_ros::TransformBroadcaster>"
                        "(*this);")
            members.append(f"  std::unique_ptr<tf2_ros::TransformBroadcaster> {member};")
        elif kind == "listen":
            body.append(f"    {member} = std::make_unique<tf2_ros::Buffer>(get_clock());")
            body.append("    listener_ = std::make_shared<tf2_ros::TransformListener>"
                        f"(*{member});")
            members.append(f"  std::unique_ptr<tf2_ros::Buffer> {member};")
            members.append("  std::shared_ptr<tf2_ros::TransformListener> listener_;")
    return (f"// {executable}: generated by tests/flow_workspace.py\n"
            '#include <memory>\n\n#include "rclcpp/rclcpp.hpp"\n'
            '#include "rclcpp_action/rclcpp_action.hpp"\n'
            '#include "tf2_ros/transform_broadcaster.h"\n'
            '#include "tf2_ros/transform_listener.h"\n\n'
            f"class {cls} : public rclcpp::Node\n{{\npublic:\n  {cls}()\n"
            f'  : Node("{node_name}")\n  {{\n' + "\n".join(body) + "\n  }\n\nprivate:\n"
            + "\n".join(members) + "\n};\n\n"
            "int main(int argc, char ** argv)\n{\n  rclcpp::init(argc, argv);\n"
            f"  rclcpp::spin(std::make_shared<{cls}>());\n  rclcpp::shutdown();\n"
            "  return 0;\n}\n")


def _python(node_name: str, endpoints: list[tuple[str, str, str]]) -> str:
    imports = {"import rclpy", "from rclpy.node import Node"}
    body = []
    for kind, kind_type, name in endpoints:
        if kind in ("pub", "sub"):
            package, _, message = kind_type.split("/")
            imports.add(f"from {package}.msg import {message}")
            if kind == "pub":
                body.append(f'        self.create_publisher({message}, "{name}", 10)')
            else:
                body.append(f'        self.create_subscription({message}, "{name}", '
                            "self.on_message, 10)")
        elif kind == "tf":
            imports.add("from tf2_ros import TransformBroadcaster")
            body.append("        self.frames = TransformBroadcaster(self)")
    cls = "".join(part.title() for part in node_name.split("_"))
    return ("\n".join(sorted(imports)) + "\n\n\n"
            f"class {cls}(Node):\n    def __init__(self):\n"
            f'        super().__init__("{node_name}")\n' + "\n".join(body) + "\n\n"
            "    def on_message(self, message):\n        pass\n\n\n"
            "def main(args=None):\n    rclpy.init(args=args)\n"
            f"    rclpy.spin({cls}())\n    rclpy.shutdown()\n")
