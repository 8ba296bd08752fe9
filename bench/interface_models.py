"""Regenerate models/interfaces/: node interfaces of released packages, extracted from git.

For each repository of ``SOURCES`` and each distribution of ``MODEL_DISTROS`` (humble,
jazzy, rolling), this exports the C++/Python sources and build files of the branch that
distribution is released from, out of a local git repository (a clone or a bare mirror),
into a temporary folder, runs launchverify's extractor on the packages listed, writes each
package's model to ``models/interfaces/<distro>/<package>.json`` (extracted names, types,
defaults, bounds and endpoints only, with the repository, branch and commit) and deletes
the exported sources. Nothing fetched is kept or committed.

    python bench/interface_models.py --git-root /work/.mirror            # every package
    python bench/interface_models.py --git-root ~/src --only nav2_amcl joy --distro humble

A repository ``owner/name`` is looked for below ``--git-root`` as ``owner+name/repo``,
``owner+name``, ``name.git`` or ``name`` (a work tree's ``.git`` or a bare repository).
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, replace
from pathlib import Path

from launchverify import __version__
from launchverify.topology.inherited import Lookup
from launchverify.topology.model import NodeInterface, PluginContract
from launchverify.topology.nodes import package_interfaces
from launchverify.topology.plugins import plugin_contracts
from launchverify.topology.releases import MODEL_DISTROS
from launchverify.topology.shipped import ModelSource, dump_model, model_document
from launchverify.workspace.packages import Package, PackageIndex, scan_sources

OUTPUT = Path(__file__).resolve().parent.parent / "models" / "interfaces"
_KEEP = (".cpp", ".cc", ".cxx", ".hpp", ".hh", ".hxx", ".h", ".ipp", ".py", ".xml",
         ".cmake", ".cfg", ".txt", ".yaml")  # .yaml: generate_parameter_library definitions


@dataclass(frozen=True)
class Source:
    """Packages of one repository, and the branch each distribution is released from."""

    repository: str  # owner/name on GitHub
    branches: dict[str, str]  # distro -> branch
    packages: tuple[str, ...]


def released(humble: str, jazzy: str, rolling: str) -> dict[str, str]:
    """Return the branch of each distribution."""
    return {"humble": humble, "jazzy": jazzy, "rolling": rolling}


def one_branch(branch: str) -> dict[str, str]:
    """Return a repository whose one ROS 2 branch every distribution is released from."""
    return released(branch, branch, branch)


# Each distribution's release branch where the repository has one; else the branch it is
# released from (rolling / ros2 / a repository's only ROS 2 branch; teleop_twist_joy and
# teleop_twist_keyboard at the newest branch the mirror holds).
NAV2 = ("nav2_amcl", "nav2_controller", "nav2_planner", "nav2_bt_navigator", "nav2_behaviors",
        "nav2_smoother", "nav2_velocity_smoother", "nav2_collision_monitor", "nav2_map_server",
        "nav2_lifecycle_manager", "nav2_waypoint_follower", "nav2_route", "nav2_costmap_2d",
        "opennav_docking", "opennav_following", "nav2_loopback_sim")
CONTROLLERS = (
    "joint_state_broadcaster", "diff_drive_controller", "joint_trajectory_controller",
    "forward_command_controller", "position_controllers", "velocity_controllers",
    "effort_controllers", "imu_sensor_broadcaster", "force_torque_sensor_broadcaster",
    "tricycle_controller", "ackermann_steering_controller", "gripper_controllers",
    "admittance_controller", "bicycle_steering_controller", "tricycle_steering_controller",
    "steering_controllers_library", "pid_controller", "range_sensor_broadcaster",
    "pose_broadcaster", "gpio_controllers", "parallel_gripper_controller",
    "mecanum_drive_controller", "omni_wheel_drive_controller", "chained_filter_controller",
    "motion_primitives_controllers", "gps_sensor_broadcaster", "battery_state_broadcaster",
    "magnetometer_broadcaster", "state_interfaces_broadcaster")
SOURCES = (
    Source("ros/robot_state_publisher", released("humble", "rolling", "rolling"),
           ("robot_state_publisher",)),
    Source("ros/joint_state_publisher", one_branch("ros2"), ("joint_state_publisher",
                                                             "joint_state_publisher_gui")),
    Source("ros-drivers/joystick_drivers", one_branch("ros2"), ("joy",)),
    Source("ros2/teleop_twist_joy", one_branch("foxy"), ("teleop_twist_joy",)),
    Source("ros2/teleop_twist_keyboard", one_branch("dashing"), ("teleop_twist_keyboard",)),
    Source("ros-teleop/twist_mux", one_branch("rolling"), ("twist_mux",)),
    Source("SteveMacenski/slam_toolbox", released("humble", "ros2", "ros2"), ("slam_toolbox",)),
    Source("cra-ros-pkg/robot_localization", one_branch("ros2"), ("robot_localization",)),
    Source("ros-perception/pointcloud_to_laserscan", released("humble", "rolling", "rolling"),
           ("pointcloud_to_laserscan",)),
    Source("ros-perception/image_pipeline", released("humble", "rolling", "rolling"),
           ("image_proc", "depth_image_proc", "stereo_image_proc", "image_rotate",
            "image_view", "image_publisher", "camera_calibration")),
    Source("ros2/geometry2", released("humble", "jazzy", "rolling"), ("tf2_ros",)),
    Source("ros-navigation/navigation2", released("humble", "jazzy", "main"), NAV2),
    Source("ros-controls/ros2_control", released("humble", "jazzy", "master"),
           ("controller_manager",)),
    Source("ros-controls/ros2_controllers", released("humble", "jazzy", "master"),
           CONTROLLERS),
    Source("IntelRealSense/realsense-ros", one_branch("ros2-master"), ("realsense2_camera",)),
)


def git_dir(root: Path, repository: str) -> Path | None:
    """Return the git directory of ``owner/name`` below ``root``, ``None`` when absent."""
    owner, name = repository.split("/")
    for candidate in (root / f"{owner}+{name}" / "repo", root / f"{owner}+{name}",
                      root / f"{name}.git", root / name):
        for folder in (candidate / ".git", candidate):
            if (folder / "HEAD").is_file() and (folder / "objects").is_dir():
                return folder
    return None


def export(git: Path, branch: str, into: Path) -> str:
    """Write the branch's sources and build files into ``into``; return its commit.

    Blobs the repository lacks (large files left out of a mirror) are skipped.
    """
    commit = subprocess.run(["git", f"--git-dir={git}", "rev-parse", f"{branch}^{{commit}}"],
                            check=True, capture_output=True, text=True).stdout.strip()
    listing = subprocess.run(["git", f"--git-dir={git}", "ls-tree", "-r", "-z", commit],
                             check=True, capture_output=True).stdout.decode()
    wanted: list[tuple[str, str]] = []
    for entry in filter(None, listing.split("\0")):
        meta, path = entry.split("\t", 1)
        _, kind, sha = meta.split()
        if kind == "blob" and path.endswith(_KEEP):
            wanted.append((sha, path))
    batch = subprocess.run(["git", f"--git-dir={git}", "cat-file", "--batch"],
                           input="".join(f"{sha}\n" for sha, _ in wanted).encode(),
                           check=True, capture_output=True).stdout
    offset = 0
    for _, path in wanted:
        header_end = batch.index(b"\n", offset)
        header = batch[offset:header_end].split()
        offset = header_end + 1
        if header[-1] == b"missing":
            continue
        size = int(header[2])
        target = into / path
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_bytes(batch[offset: offset + size])
        offset += size + 1
    return commit


def _test_only(sources: tuple[Path, ...], folder: Path) -> bool:
    """Return whether an executable is built from tests only (not one a launch starts)."""
    parts = [p.relative_to(folder).parts for p in sources if p.is_relative_to(folder)]
    return bool(parts) and all("test" in p[:-1] or "tests" in p[:-1] for p in parts)


def generate(root: Path, output: Path, only: set[str],
             distros: tuple[str, ...] = MODEL_DISTROS) -> dict[str, float]:
    """Write the models of ``SOURCES`` (or of the packages in ``only``); return timings."""
    timings: dict[str, float] = {}
    for source in SOURCES:
        packages = [p for p in source.packages if not only or p in only]
        if not packages:
            continue
        git = git_dir(root, source.repository)
        if git is None:
            print(f"skipped {source.repository}: no git repository below {root}",
                  file=sys.stderr)
            continue
        for distro in distros:
            branch = source.branches[distro]
            with tempfile.TemporaryDirectory(prefix="lv-models-") as temporary:
                timings.update(_extract(git, source, distro, branch, packages,
                                        Path(temporary), output / distro))
    return timings


def _extract(git: Path, source: Source, distro: str, branch: str, packages: list[str],
             tree: Path, output: Path) -> dict[str, float]:
    """Write one distribution's models of one repository's packages; return timings."""
    timings: dict[str, float] = {}
    commit = export(git, branch, tree)
    found = {name: folder for name, folder in scan_sources(tree)}
    lookup = PackageIndex([tree]).lookup()  # base classes in sibling packages
    repository = [Package(name, source=folder) for name, folder in sorted(found.items())]
    plugins: dict[tuple[str, ...], tuple[PluginContract, ...]] = {}
    output.mkdir(parents=True, exist_ok=True)
    for package in packages:
        folder = found.get(package)
        if folder is None:
            print(f"skipped {package}: not in {source.repository} {branch} ({distro})",
                  file=sys.stderr)
            continue
        started = time.perf_counter()
        interfaces = [with_plugins(i, repository, lookup, plugins)
                      for i in package_interfaces(Package(package, source=folder), lookup)
                      if not _test_only(i.sources, folder)]
        if not interfaces:  # a library other packages' nodes use: no node of its own
            print(f"skipped {package}: no executable or component in {branch} ({distro})",
                  file=sys.stderr)
            continue
        key = f"{distro}/{package}"
        timings[key] = time.perf_counter() - started
        where = folder.relative_to(tree).as_posix() if folder != tree else ""
        model = ModelSource(f"https://github.com/{source.repository}", branch, commit, where)
        document = model_document(package, interfaces, model, folder,
                                  f"launchverify {__version__}", tree)
        (output / f"{package}.json").write_text(dump_model(document), encoding="utf-8")
        count = sum(len(i["endpoints"]) for i in document["interfaces"])
        closed = sum(1 for i in document["interfaces"] if i["parameters_open"] is None)
        print(f"{key:<40} {len(interfaces):>3} targets {closed:>3} closed {count:>4} endpoints "
              f"{timings[key]:6.2f} s  ({branch} {commit[:12]})")
    return timings


def with_plugins(interface: NodeInterface, repository: list[Package], lookup: Lookup,
                 known: dict[tuple[str, ...], tuple[PluginContract, ...]]) -> NodeInterface:
    """Return an interface with what its repository's plugins for its loaders declare."""
    if not interface.loaders:
        return interface
    if interface.loaders not in known:
        known[interface.loaders] = plugin_contracts(repository, interface.loaders, lookup)
    return replace(interface, plugins=known[interface.loaders])


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--git-root", type=Path, required=True,
                        help="folder holding the repositories' git directories")
    parser.add_argument("--only", nargs="*", default=[], help="packages to regenerate")
    parser.add_argument("--distro", nargs="*", choices=MODEL_DISTROS, default=MODEL_DISTROS,
                        help="distributions to extract (default: all)")
    parser.add_argument("--output", type=Path, default=OUTPUT)
    parser.add_argument("--timings", type=Path, help="write the extraction times as JSON")
    args = parser.parse_args()
    args.output.mkdir(parents=True, exist_ok=True)
    timings = generate(args.git_root, args.output, set(args.only), tuple(args.distro))
    total = sum(timings.values())
    print(f"{len(timings)} packages extracted in {total:.2f} s")
    if args.timings:
        args.timings.write_text(json.dumps({"packages": timings, "total": total}, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
