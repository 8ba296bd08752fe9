"""Regenerate models/interfaces/: node interfaces of released packages, extracted from git.

For each repository of ``SOURCES`` this exports the C++/Python sources and build files of
one branch from a local git repository (a clone or a bare mirror) into a temporary folder,
runs launchverify's extractor on the packages listed, writes each package's model
(extracted names and types only, with the repository, branch and commit) and deletes the
exported sources. Nothing fetched is kept or committed.

    python bench/interface_models.py --git-root /work/.mirror            # every package
    python bench/interface_models.py --git-root ~/src --only nav2_amcl joy

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
from dataclasses import dataclass
from pathlib import Path

from launchverify import __version__
from launchverify.topology.nodes import package_interfaces
from launchverify.topology.shipped import ModelSource, dump_model, model_document
from launchverify.workspace.packages import Package, PackageIndex, scan_sources

OUTPUT = Path(__file__).resolve().parent.parent / "models" / "interfaces"
_KEEP = (".cpp", ".cc", ".cxx", ".hpp", ".hh", ".hxx", ".h", ".ipp", ".py", ".xml",
         ".cmake", ".cfg", ".txt", ".yaml")  # .yaml: generate_parameter_library definitions


@dataclass(frozen=True)
class Source:
    """Packages of one repository, extracted at one branch."""

    repository: str  # owner/name on GitHub
    branch: str
    packages: tuple[str, ...]


# Branches: jazzy where the repository has one, else the branch jazzy is released from
# (rolling / ros2); teleop_twist_joy and teleop_twist_keyboard at the newest branch the
# mirror holds.
NAV2 = ("nav2_amcl", "nav2_controller", "nav2_planner", "nav2_bt_navigator", "nav2_behaviors",
        "nav2_smoother", "nav2_velocity_smoother", "nav2_collision_monitor", "nav2_map_server",
        "nav2_lifecycle_manager", "nav2_waypoint_follower", "nav2_route", "nav2_costmap_2d")
SOURCES = (
    Source("ros/robot_state_publisher", "rolling", ("robot_state_publisher",)),
    Source("ros/joint_state_publisher", "ros2", ("joint_state_publisher",
                                                 "joint_state_publisher_gui")),
    Source("ros-drivers/joystick_drivers", "ros2", ("joy",)),
    Source("ros2/teleop_twist_joy", "foxy", ("teleop_twist_joy",)),
    Source("ros2/teleop_twist_keyboard", "dashing", ("teleop_twist_keyboard",)),
    Source("ros-teleop/twist_mux", "rolling", ("twist_mux",)),
    Source("SteveMacenski/slam_toolbox", "ros2", ("slam_toolbox",)),
    Source("cra-ros-pkg/robot_localization", "ros2", ("robot_localization",)),
    Source("ros-perception/pointcloud_to_laserscan", "rolling", ("pointcloud_to_laserscan",)),
    Source("ros-perception/image_pipeline", "rolling", ("image_proc", "depth_image_proc")),
    Source("ros2/geometry2", "jazzy", ("tf2_ros",)),
    Source("ros-navigation/navigation2", "jazzy", NAV2),
    Source("ros-controls/ros2_control", "jazzy", ("controller_manager",)),
    Source("ros-controls/ros2_controllers", "jazzy", (
        "joint_state_broadcaster", "diff_drive_controller", "joint_trajectory_controller",
        "forward_command_controller", "position_controllers", "velocity_controllers",
        "effort_controllers", "imu_sensor_broadcaster", "force_torque_sensor_broadcaster",
        "tricycle_controller", "ackermann_steering_controller", "gripper_controllers")),
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


def generate(root: Path, output: Path, only: set[str]) -> dict[str, float]:
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
        with tempfile.TemporaryDirectory(prefix="lv-models-") as temporary:
            tree = Path(temporary)
            commit = export(git, source.branch, tree)
            found = {name: folder for name, folder in scan_sources(tree)}
            lookup = PackageIndex([tree]).lookup()  # base classes in sibling packages
            for package in packages:
                folder = found.get(package)
                if folder is None:
                    print(f"skipped {package}: not in {source.repository} {source.branch}",
                          file=sys.stderr)
                    continue
                started = time.perf_counter()
                interfaces = [i for i in package_interfaces(Package(package, source=folder),
                                                            lookup)
                              if not _test_only(i.sources, folder)]
                timings[package] = time.perf_counter() - started
                where = folder.relative_to(tree).as_posix() if folder != tree else ""
                model = ModelSource(f"https://github.com/{source.repository}", source.branch,
                                    commit, where)
                document = model_document(package, interfaces, model, folder,
                                          f"launchverify {__version__}")
                (output / f"{package}.json").write_text(dump_model(document), encoding="utf-8")
                count = sum(len(i["endpoints"]) for i in document["interfaces"])
                print(f"{package:<32} {len(interfaces):>3} targets {count:>4} endpoints "
                      f"{timings[package]:6.2f} s  ({source.branch} {commit[:12]})")
    return timings


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--git-root", type=Path, required=True,
                        help="folder holding the repositories' git directories")
    parser.add_argument("--only", nargs="*", default=[], help="packages to regenerate")
    parser.add_argument("--output", type=Path, default=OUTPUT)
    parser.add_argument("--timings", type=Path, help="write the extraction times as JSON")
    args = parser.parse_args()
    args.output.mkdir(parents=True, exist_ok=True)
    timings = generate(args.git_root, args.output, set(args.only))
    total = sum(timings.values())
    print(f"{len(timings)} packages extracted in {total:.2f} s")
    if args.timings:
        args.timings.write_text(json.dumps({"packages": timings, "total": total}, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
