"""pluginlib plugins: what their description files export, and what each one declares.

A node that loads plugins by parameter (nav2's servers, amcl's motion models,
slam_toolbox's solvers) receives the parameters its plugins declare: under the name the
launch gives each plugin (``FollowPath.max_vel_x``), or unprefixed (nav2's behaviours).
A package's ``*.xml`` plugin descriptions name each exported class, its pluginlib type
and base class, and the library it is built into; the library's sources say what it
declares.
"""

from __future__ import annotations

from launchverify.topology.inherited import Lookup
from launchverify.topology.model import PluginContract
from launchverify.topology.plugin_xml import package_descriptions
from launchverify.topology.sources import Target, library_files
from launchverify.workspace.packages import Package


def derives(base: str, loader: str) -> bool:
    """Return whether a description's base class is what a ``ClassLoader<loader>`` loads.

    The loader's argument may be written unqualified (``Layer`` in nav2_costmap_2d).

    Examples:
        >>> derives("nav2_costmap_2d::Layer", "Layer"), derives("a::Layer", "b::Layer")
        (True, False)
    """
    if "::" in loader:
        return base.removeprefix("::") == loader.removeprefix("::")
    return base.rpartition("::")[2] == loader


def plugin_contracts(packages: list[Package], loaders: tuple[str, ...],
                     lookup: Lookup | None = None) -> tuple[PluginContract, ...]:
    """Return what every plugin of these packages that a node's loaders load declares."""
    from launchverify.topology.nodes import target_interface

    out: list[PluginContract] = []
    for package in packages:
        if package.source is None:
            continue
        for plugin in package_descriptions(package.source):
            base = next((loader for loader in loaders if derives(plugin.base, loader)), None)
            if base is None:
                continue
            files, problems = library_files(package, plugin.library)
            interface = target_interface(package.name, Target(plugin.type, plugin.cls, files,
                                                              problems), lookup)
            out.append(PluginContract(plugin.type, plugin.base, interface.parameters,
                                      interface.parameters_open))
    return tuple(out)
