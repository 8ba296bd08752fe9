"""Parameters declared by generate_parameter_library: its YAML, read without building.

A package names its definitions in ``CMakeLists.txt``
(``generate_parameter_library(my_params src/my_params.yaml)``, then ``#include
"my_params.hpp"``) or ``setup.py`` (``generate_parameter_module("my_params", "...yaml")``,
then ``import``). The YAML nests parameter names under one top-level key; a mapping with
a ``type`` is a parameter: its ``default_value`` (none: required, the generated listener
throws at start; ``type: none`` is documentation, never required), ``read_only``, and
``validation`` (``bounds<>``, ``gt<>``, ``one_of<>``).
``__map_<other>`` keys stand for names taken from another parameter's values at run time.
"""

from __future__ import annotations

import re
from pathlib import Path

import yaml

from launchverify.frontends.yaml_reader import compose, span_of
from launchverify.topology.model import FileInterfaces, Parameter
from launchverify.workspace.reading import Unreadable, read_file

VIA = "generate_parameter_library"
MAX_DEFINITION_BYTES = 1_000_000
_CMAKE = re.compile(r"generate_parameter_library\s*\(\s*([\w${}.-]+)\s+([^\s)]+)")
_SETUP = re.compile(r"generate_parameter_module\s*\(\s*['\"]([\w.]+)['\"]\s*,\s*['\"]([^'\"]+)")
_TYPES = {"bool": "bool", "int": "integer", "double": "double", "string": "string",
          "bool_array": "bool_array", "int_array": "integer_array",
          "double_array": "double_array", "string_array": "string_array"}
_LIMITS = ("bounds", "gt", "gt_eq", "lt", "lt_eq", "one_of")


def parameter_libraries(source: Path) -> dict[str, Path]:
    """Return each generated header (or module) name of a package and its YAML file."""
    found: dict[str, Path] = {}
    for build_file, pattern in (("CMakeLists.txt", _CMAKE), ("setup.py", _SETUP)):
        try:
            written = read_file(source / build_file).decode("utf-8", "replace")
        except (Unreadable, OSError):
            continue
        for name, path in pattern.findall(written):
            path = re.sub(r"\$\{(?:CMAKE_CURRENT_SOURCE_DIR|PROJECT_SOURCE_DIR)\}/?", "", path)
            definition = source / path
            if "$" not in name and "$" not in path and _inside(definition, source):
                found[name.rpartition(".")[2]] = definition
    return found


def _inside(path: Path, source: Path) -> bool:
    """Return whether a definition lies in its package (a build file names no other file)."""
    from launchverify.workspace.paths import resolved

    return resolved(path).is_relative_to(resolved(source))


def definitions(path: Path) -> tuple[Parameter, ...]:
    """Return the parameters one definition file declares (none when it cannot be read)."""
    try:
        data = read_file(path, prefix=MAX_DEFINITION_BYTES)
        root = compose(data.decode("utf-8", "replace"))
    except (Unreadable, OSError, yaml.YAMLError):
        return ()
    if not isinstance(root, yaml.MappingNode):
        return ()
    found: list[Parameter] = []
    for _, body in root.value:  # the top-level key names the generated namespace
        if isinstance(body, yaml.MappingNode):
            _walk(path, body, "", found)
    return tuple(found)


def _walk(path: Path, node: yaml.MappingNode, prefix: str, found: list[Parameter]) -> None:
    fields = {key.value: value for key, value in node.value if isinstance(key, yaml.ScalarNode)}
    if "type" in fields and isinstance(fields["type"], yaml.ScalarNode):
        found.append(_parameter(path, prefix, node, fields))
        return
    for key, value in node.value:
        if not isinstance(key, yaml.ScalarNode) or not isinstance(value, yaml.MappingNode):
            continue
        part = "*" if str(key.value).startswith("__map_") else str(key.value)
        _walk(path, value, f"{prefix}.{part}" if prefix else part, found)


def _parameter(path: Path, name: str, node: yaml.MappingNode,
               fields: dict[str, yaml.Node]) -> Parameter:
    written = str(fields["type"].value)
    kind = _TYPES.get(written, "string" if written.startswith("string_fixed") else None)
    default = fields.get("default_value")
    value = _plain(default) if default is not None else None
    limits = _limits(fields.get("validation"))
    read_only = _plain(fields["read_only"]) is True if "read_only" in fields else False
    # ``type: none`` is documentation only: nothing is generated, so nothing is required
    return Parameter(name, kind, span_of(path, node), value, dynamic=kind is None,
                     required=default is None and written != "none", read_only=read_only,
                     limits=limits, via=VIA)


def _limits(node: yaml.Node | None) -> tuple[tuple[str, tuple[object, ...]], ...]:
    """Return the checks of a ``validation`` mapping this reader judges, with arguments."""
    if not isinstance(node, yaml.MappingNode):
        return ()
    found = []
    for key, value in node.value:
        check = str(key.value).removesuffix("<>").rpartition("::")[2]
        arguments = _plain(value)
        if check in _LIMITS and isinstance(arguments, list):
            found.append((check, tuple(arguments)))
    return tuple(found)


def _plain(node: yaml.Node) -> object:
    """Return a YAML node as Python data (scalars typed as YAML types them)."""
    try:
        return yaml.safe_load(yaml.serialize(node))
    except yaml.YAMLError:
        return None


def used_definitions(results: list[FileInterfaces],
                     generated: dict[str, Path]) -> list[FileInterfaces]:
    """Return the definitions of the generated parameter libraries these files include.

    ``generated`` maps each library's header name to its definition file
    (``parameter_libraries``).
    """
    used = {re.split(r"[/.]", i.removesuffix(".hpp").removesuffix(".h"))[-1]
            for r in results for i in r.includes}
    return [FileInterfaces(path, parameters=definitions(path))
            for name, path in sorted(generated.items()) if name in used]

