"""Package resolution: workspace sources, install prefixes, install layout to sources."""

from __future__ import annotations

from pathlib import Path

from launchverify.workspace.packages import PackageIndex, find_workspace, scan_sources


def make_package(root: Path, name: str, folder: str | None = None) -> Path:
    path = root / (folder or name)
    path.mkdir(parents=True)
    (path / "package.xml").write_text(
        f'<?xml version="1.0"?>\n<package format="3"><name>{name}</name></package>\n'
    )
    return path


def test_sources_are_found_and_ignored_folders_skipped(tmp_path: Path) -> None:
    make_package(tmp_path / "src", "alpha")
    make_package(tmp_path / "src", "beta", folder="nested/beta_folder")
    make_package(tmp_path / "build", "built")
    ignored = make_package(tmp_path / "src", "ignored")
    (ignored / "COLCON_IGNORE").write_text("")
    names = {name for name, _ in scan_sources(tmp_path)}
    assert names == {"alpha", "beta"}


def test_install_layout_resolves_to_sources(tmp_path: Path) -> None:
    source = make_package(tmp_path, "robot")
    (source / "launch" / "sensors").mkdir(parents=True)
    (source / "launch" / "sensors" / "lidar.launch.xml").write_text("<launch/>")
    (source / "params").mkdir()
    (source / "params" / "driver.yaml").write_text("{}")
    index = PackageIndex([tmp_path])
    package = index.find("robot")
    assert package is not None and package.share == source.resolve()
    share = package.share
    assert index.locate(share / "launch" / "sensors" / "lidar.launch.xml") == (
        source.resolve() / "launch" / "sensors" / "lidar.launch.xml")
    # installed to share/robot/config but kept in params/ in the sources
    assert index.locate(share / "config" / "driver.yaml") == source.resolve() / "params" / (
        "driver.yaml")
    assert index.locate(share / "config" / "missing.yaml") is None


def test_ament_prefix_packages(tmp_path: Path) -> None:
    prefix = tmp_path / "opt"
    marker = prefix / "share" / "ament_index" / "resource_index" / "packages"
    marker.mkdir(parents=True)
    (marker / "demo_nodes_cpp").write_text("")
    (prefix / "share" / "demo_nodes_cpp" / "launch").mkdir(parents=True)
    index = PackageIndex([], [prefix])
    package = index.find("demo_nodes_cpp")
    assert package is not None and package.installed
    assert package.share == prefix.resolve() / "share" / "demo_nodes_cpp"
    assert index.has_install


def test_workspace_install_folder_wins_for_share(tmp_path: Path) -> None:
    make_package(tmp_path / "src", "robot")
    prefix = tmp_path / "install" / "robot"
    marker = prefix / "share" / "ament_index" / "resource_index" / "packages"
    marker.mkdir(parents=True)
    (marker / "robot").write_text("")
    index = PackageIndex([tmp_path])
    package = index.find("robot")
    assert package is not None and package.source is not None and package.installed
    assert package.share == prefix.resolve() / "share" / "robot"


def test_find_workspace(tmp_path: Path) -> None:
    workspace = tmp_path / "ws"
    (workspace / "src").mkdir(parents=True)
    (workspace / "build").mkdir()
    launch = make_package(workspace / "src", "robot") / "launch"
    launch.mkdir()
    assert find_workspace(launch) == workspace.resolve()
    loose = make_package(tmp_path / "loose", "thing") / "launch"
    loose.mkdir()
    assert find_workspace(loose) == (tmp_path / "loose").resolve()


def test_symlinked_repositories_are_followed_once(tmp_path: Path) -> None:
    repos = tmp_path / "repos"
    make_package(repos / "driver_repo", "fast_driver")
    src = tmp_path / "ws" / "src"
    src.mkdir(parents=True)
    (src / "driver_repo").symlink_to(repos / "driver_repo", target_is_directory=True)
    (src / "again").symlink_to(repos, target_is_directory=True)  # the same package twice
    (repos / "loop").symlink_to(repos, target_is_directory=True)  # a cycle
    (src / "everything").symlink_to("/", target_is_directory=True)
    # a link out of the workspace is followed only into folders the user lets it read
    assert list(scan_sources(tmp_path / "ws")) == []
    found = list(scan_sources(tmp_path / "ws", within=[repos]))
    assert [name for name, _ in found] == ["fast_driver"]
    package = PackageIndex([tmp_path / "ws", repos]).find("fast_driver")
    assert package is not None and package.source is not None
    assert (package.source / "package.xml").is_file()
    assert PackageIndex([tmp_path / "ws"]).find("fast_driver") is None


def test_links_inside_the_workspace_are_followed(tmp_path: Path) -> None:
    make_package(tmp_path / "ws" / "vendor" / "driver_repo", "fast_driver")
    (tmp_path / "ws" / "src").mkdir()
    (tmp_path / "ws" / "src" / "driver").symlink_to(tmp_path / "ws" / "vendor",
                                                   target_is_directory=True)
    assert [name for name, _ in scan_sources(tmp_path / "ws" / "src",
                                             within=[tmp_path / "ws"])] == ["fast_driver"]


def test_installed_executables_are_listed(tmp_path: Path) -> None:
    from launchverify.workspace.package_executables import executables
    from launchverify.workspace.packages import Package

    lib = tmp_path / "install" / "lib" / "fast_driver"
    lib.mkdir(parents=True)
    (lib / "driver_node").write_text("#!/bin/sh\n")
    (lib / "driver_node").chmod(0o755)
    (lib / "notes.txt").write_text("not executable\n")
    found = executables(Package("fast_driver", prefix=tmp_path / "install"))
    assert found is not None and found.complete
    assert found.names == {"driver_node"}


def test_cmake_output_name_is_the_installed_name(tmp_path: Path) -> None:
    """teleop_twist_joy installs ``teleop_node`` from the target ``teleop_twist_joy_node``."""
    from launchverify.workspace.package_executables import build_targets, executables
    from launchverify.workspace.packages import Package

    source = make_package(tmp_path, "joy_teleop")
    (source / "CMakeLists.txt").write_text(
        "project(joy_teleop)\n"
        "add_executable(${PROJECT_NAME}_node src/teleop_node.cpp)\n"
        "set_target_properties(${PROJECT_NAME}_node\n"
        "  PROPERTIES OUTPUT_NAME teleop_node PREFIX \"\")\n"
        "add_executable(relay src/relay.cpp)\n"
        "set_property(TARGET relay PROPERTY OUTPUT_NAME ${PROJECT_NAME}_relay)\n"
        "install(TARGETS ${PROJECT_NAME}_node relay DESTINATION lib/${PROJECT_NAME})\n")
    found = executables(Package("joy_teleop", source=source))
    assert found is not None and found.complete
    assert found.names == {"teleop_node", "joy_teleop_relay"}
    targets = build_targets(source, "joy_teleop")
    assert targets is not None
    assert targets.output_names == {"joy_teleop_node": "teleop_node",
                                    "relay": "joy_teleop_relay"}


def test_cmake_variables_lists_and_branches(tmp_path: Path) -> None:
    from launchverify.workspace.package_executables import executables
    from launchverify.workspace.packages import Package

    source = make_package(tmp_path, "tools")
    (source / "CMakeLists.txt").write_text(
        "project(tools)\n"
        "set(NODES a_node b_node)\n"
        "list(APPEND NODES c_node)\n"
        "foreach(n IN LISTS NODES)\n"
        "  add_executable(${n} src/${n}.cpp)\n"
        "endforeach()\n"
        "if(WITH_EXTRA)\n"
        "  install(TARGETS a_node b_node DESTINATION lib/${PROJECT_NAME})\n"
        "else()\n"
        "  install(TARGETS c_node RUNTIME DESTINATION lib/${PROJECT_NAME})\n"
        "endif()\n"
        "install(TARGETS b_node DESTINATION bin)\n")
    found = executables(Package("tools", source=source))
    assert found is not None and found.complete
    assert found.names == {"a_node", "b_node", "c_node"}


def test_a_name_defined_twice_is_the_copy_nearest_to_what_is_checked(tmp_path: Path) -> None:
    """Each repository's own copy wins for its files (an overlay over the other's)."""
    first = make_package(tmp_path / "repo_a", "shared", folder="api/shared")
    second = make_package(tmp_path / "repo_b", "shared", folder="system/shared")
    checked_b = tmp_path / "repo_b" / "launch" / "robot.launch.xml"
    checked_a = tmp_path / "repo_a" / "launch"
    plain = PackageIndex([tmp_path]).find("shared")
    assert plain is not None and plain.source is not None
    scanned_first = plain.source
    assert scanned_first in {first.resolve(), second.resolve()}
    near_b = PackageIndex([tmp_path], near=[checked_b]).find("shared")
    near_a = PackageIndex([tmp_path], near=[checked_a]).find("shared")
    assert near_b is not None and near_b.source == second.resolve()
    assert near_a is not None and near_a.source == first.resolve()
    # the whole workspace checked: both copies are as near, the first scanned stays
    tie = PackageIndex([tmp_path], near=[tmp_path]).find("shared")
    assert tie is not None and tie.source == scanned_first


def test_an_installed_copy_is_as_near_as_its_source(tmp_path: Path) -> None:
    """A repository's emulated install (``share/<name>``, the same manifest) is its copy.

    Of the two, the first scanned stays, as before any preference: the installed one
    holds what the build generates (a ``gz_sim.launch.py`` made from a ``.in``).
    """
    make_package(tmp_path / "repo_a", "shared", folder="api/shared")
    source = make_package(tmp_path / "repo_b", "shared", folder="system/shared")
    installed = tmp_path / "_install" / "repo_b" / "share" / "shared"
    installed.mkdir(parents=True)
    (installed / "package.xml").write_bytes((source / "package.xml").read_bytes())
    index = PackageIndex([tmp_path], near=[tmp_path / "repo_b" / "launch"])
    twins = [f for f in index.sources["shared"] if f in {source.resolve(), installed.resolve()}]
    found = index.find("shared")
    assert found is not None and found.source == twins[0]
    assert twins[0] == installed.resolve()  # '_install' is walked before 'repo_b'
