"""pluginlib's plugin description files: the classes each exports, read without running.

One reader for every use: the ros2_control controllers a package exports (their types a
controller manager is given), the plugins a server's loaders may load (nav2's), and
whether a controller type is exported at all.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from lxml import etree

from launchverify.workspace.reading import Unreadable, read_text

_PLUGIN_XML_BYTES = 256 * 1024


@dataclass(frozen=True, slots=True)
class Exported:
    """One class a plugin description exports."""

    library: str  # the CMake target (``path="libfoo"`` -> ``foo``)
    type: str  # its pluginlib name (``name``, else ``type``), as a parameter chooses it
    cls: str  # the C++ class
    base: str  # base_class_type, without spaces

    @property
    def controller(self) -> bool:
        """Return whether it is a ros2_control controller (a controller_interface base)."""
        return self.base.startswith("controller_interface::")


def descriptions(path: Path) -> list[Exported] | None:
    """Return the classes one description file exports; ``None`` when it is no XML."""
    try:
        code = read_text(path, prefix=_PLUGIN_XML_BYTES)
        root = etree.fromstring(code.encode(), etree.XMLParser(resolve_entities=False,
                                                                no_network=True))
    except (Unreadable, OSError, etree.XMLSyntaxError, ValueError):
        return None
    found: list[Exported] = []
    libraries = [root] if root.tag == "library" else root.findall("library")
    for library in libraries:
        name = Path(library.get("path", "")).name.removeprefix("lib")
        for cls in library.findall("class"):
            kind, base = cls.get("type"), cls.get("base_class_type")
            if kind and base and name:
                found.append(Exported(name, cls.get("name") or kind, kind,
                                      "".join(base.split())))
    return found


def package_descriptions(source: Path) -> list[Exported]:
    """Return what the description files at a package's root export (in file order)."""
    return [exported for path in sorted(source.glob("*.xml")) if path.name != "package.xml"
            for exported in descriptions(path) or ()]
