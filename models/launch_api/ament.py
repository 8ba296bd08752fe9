"""Models of ``ament_index_python.packages``."""

from __future__ import annotations

from pathlib import Path

from launchverify.models.launch_api.base import caller_span
from launchverify.models.launch_api.placeholders import placeholder
from launchverify.models.launch_api.runtime import active


class PackageNotFoundError(KeyError):
    """``ament_index_python.packages.PackageNotFoundError``."""


def get_package_share_directory(package_name: str, print_warning: bool = True) -> str:
    """Return the share folder; unknown packages get a placeholder (they may be installed)."""
    runtime = active()
    runtime.packages_seen.add(package_name)
    runtime.lookups.append((package_name, caller_span()))
    package = runtime.index.find(package_name)
    if package is None:
        return placeholder("pkg", package_name)
    return str(package.share)


def get_package_share_path(package_name: str, print_warning: bool = True) -> Path:
    """``get_package_share_path``: the share folder as a ``Path``."""
    return Path(get_package_share_directory(package_name))


def get_package_prefix(package_name: str) -> str:
    """Return the install prefix, or a placeholder when only sources are known."""
    runtime = active()
    runtime.packages_seen.add(package_name)
    runtime.lookups.append((package_name, caller_span()))
    package = runtime.index.find(package_name)
    if package is None or package.prefix is None:
        return placeholder("prefix", package_name)
    return str(package.prefix)


def get_packages_with_prefixes() -> dict[str, str]:
    """Return every known package with its prefix (sources stand in for prefixes)."""
    runtime = active()
    out = {}
    for name in runtime.index.names():
        package = runtime.index.find(name)
        if package is not None:
            out[name] = str(package.prefix or package.source)
    return out


def get_package_xml_path(package_name: str) -> str:
    """Return the package.xml of a package."""
    share = get_package_share_directory(package_name)
    return share + "/package.xml"


def has_resource(resource_type: str, resource_name: str) -> bool:
    """``ament_index_python.resources.has_resource``: packages the analysis knows of."""
    if resource_type != "packages":
        return False
    from launchverify.models.known_packages import is_released

    return active().index.find(resource_name) is not None or is_released(resource_name)


def get_resource(resource_type: str, resource_name: str) -> tuple[str, str]:
    """``ament_index_python.resources.get_resource``: content unknown statically."""
    return "", get_package_prefix(resource_name)
