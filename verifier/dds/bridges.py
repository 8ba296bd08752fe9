"""What domain_bridge carries between DDS domains, read from its configuration.

``domain_bridge`` (its executable, started as a node or a plain process, or through its
own ``domain_bridge.launch.xml`` with ``config``, ``from_domain`` and ``to_domain``)
takes YAML files: ``from_domain`` and ``to_domain``, then ``topics`` by name, each with
its ``type`` and optionally its own domains, ``remap`` (the name it publishes under),
``reversed`` and ``bidirectional``. ``--from``/``--to`` override every topic's domains.
Names resolve against ``/``. A key may repeat (the project's own example bridges
``chatter`` five ways), so the file is read as a node tree, not a dict. A bridge whose
files are not known or cannot be read may carry anything (``None``).
"""

from __future__ import annotations

import os
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path

import yaml

from launchverify.dds.discovery import domain_number
from launchverify.frontends.yaml_reader import YamlLoadError, compose, span_of
from launchverify.graph import LaunchGraph, Origin
from launchverify.ir.subst import Sub
from launchverify.ir.symbolic import ExecutablePath
from launchverify.span import Span
from launchverify.workspace.reading import Unreadable, read_text

MAX_CONFIG_BYTES = 1_000_000
PACKAGE = "domain_bridge"
LAUNCH_FILE = "domain_bridge.launch.xml"
# options of the executable, each followed by its value (process_cmd_line_arguments.hpp)
VALUED_OPTIONS = ("--from", "--to", "--mode", "--wait-for-subscription",
                  "--wait-for-publisher", "--auto-remove")


@dataclass(frozen=True, slots=True)
class Crossing:
    """One topic a bridge forwards: read under ``topic`` in one domain, written in another.

    ``published`` is the name it writes under (``remap``, else ``topic``); ``span`` is the
    topic's entry in the configuration, ``origin`` where the bridge is launched.
    """

    topic: str
    type: str | None
    source: str
    target: str
    published: str = ""
    span: Span | None = None
    origin: Origin | None = None

    @property
    def reads(self) -> str:
        """Return the fully qualified name the bridge subscribes to."""
        return absolute(self.topic)

    @property
    def writes(self) -> str:
        """Return the fully qualified name the bridge publishes under."""
        return absolute(self.published or self.topic)

    def leaves(self, domain: str | None) -> bool:
        """Return whether it reads in ``domain`` (compared as rcl reads domains)."""
        return domain_number(self.source) == domain_number(domain)

    def enters(self, domain: str | None) -> bool:
        """Return whether it writes in ``domain``."""
        return domain_number(self.target) == domain_number(domain)


@dataclass(frozen=True, slots=True)
class _Bridge:
    """One bridge as launched: its words (configs and options), where it is launched."""

    words: tuple[str | None, ...]
    origin: Origin


def crossings(graph: LaunchGraph) -> list[Crossing] | None:
    """Return what every bridge of the launch forwards, ``None`` when one is not known."""
    kept = graph.derived.setdefault("bridges", {})
    if "crossings" in kept:
        known = kept["crossings"]
        return known if isinstance(known, list) else None
    found: list[Crossing] | None = []
    for bridge in _bridges(graph):
        read = _read(bridge)
        if read is None or found is None:
            found = None
            break
        found.extend(read)
    kept["crossings"] = found
    return found


def runs_bridge(graph: LaunchGraph, origin: Origin) -> bool:
    """Return whether the node or process launched at ``origin`` is a known bridge.

    Known: every bridge's configuration was read. Such a bridge publishes only what it
    carries across domains, which the rules ask about by domain: it is no node or
    process that may publish anything.
    """
    if crossings(graph) is None:
        return False
    kept = graph.derived.setdefault("bridges", {})
    launched = kept.get("origins")
    if not isinstance(launched, set):
        launched = kept["origins"] = {id(bridge.origin) for bridge in _bridges(graph)}
    return id(origin) in launched


def feeding(bridges: Sequence[Crossing], name: str) -> list[Crossing]:
    """Return the crossings that publish ``name`` (a fully qualified name)."""
    return [c for c in bridges if c.writes == name]


def message_type(name: str) -> str:
    """Return a message type as ``pkg/msg/Type`` (the bridge also takes ``pkg/Type``).

    Examples:
        >>> message_type("std_msgs/String"), message_type("std_msgs::msg::String")
        ('std_msgs/msg/String', 'std_msgs/msg/String')
    """
    parts = name.strip().replace("::", "/").split("/")
    return "/".join(parts if len(parts) != 2 else [parts[0], "msg", parts[1]])


def absolute(name: str) -> str:
    """Return a bridge's topic name resolved against ``/``."""
    return "/" + name.strip().lstrip("~").strip("/")


def _bridges(graph: LaunchGraph) -> Iterator[_Bridge]:
    """Yield every domain_bridge the launch may start, with its command words."""
    for launch in graph.launches:
        if graph.runs(launch.origin) is False:
            continue
        node = launch.node
        if node is not None:
            if graph.base(node.package) == PACKAGE and graph.base(node.executable) == PACKAGE:
                yield _Bridge(tuple(graph.base(a) for a in launch.arguments), launch.origin)
        elif launch.cmd and _is_bridge(graph, launch.cmd[0]):
            words = [graph.base(w) for w in launch.cmd[1:]]
            yield _Bridge(tuple(p for w in words for p in (w.split() if w else [w])),
                          launch.origin)
    for include in graph.includes:
        if include.status != "loaded" and graph.runs(include.origin) is not False and \
                _names_bridge_launch(include.location.describe()):
            given = {name: graph.base(value) for name, value, _ in include.arguments}
            passed: list[str | None] = []
            for option, argument in (("--from", "from_domain"), ("--to", "to_domain")):
                if given.get(argument):
                    passed += [option, given[argument]]
            passed.append(given.get("config"))
            yield _Bridge(tuple(passed), include.origin)


def _names_bridge_launch(written: str) -> bool:
    """Return whether an include's path is domain_bridge's own launch file.

    Examples:
        >>> tail = "/launch/domain_bridge.launch.xml"
        >>> _names_bridge_launch("<share folder of domain_bridge>" + tail)
        True
        >>> _names_bridge_launch("<share folder of my_domain_bridge>" + tail)
        False
    """
    share = (f"<share folder of {PACKAGE}>", f"$(find-pkg-share {PACKAGE})")
    return written.endswith(f"/launch/{LAUNCH_FILE}") and any(
        written.startswith(prefix) or f"/share/{PACKAGE}/" in written for prefix in share)


def _is_bridge(graph: LaunchGraph, word: Sub) -> bool:
    """Return whether a command's first word runs the domain_bridge executable."""
    if isinstance(word, ExecutablePath):
        return word.package == PACKAGE and word.executable == PACKAGE
    text = graph.base(word)
    return text is not None and Path(text.split()[0] if text.split() else "").name == PACKAGE


def _read(bridge: _Bridge) -> list[Crossing] | None:
    """Return what one bridge forwards, from its files and options."""
    configs: list[str] = []
    overrides: dict[str, str] = {}
    words = iter(bridge.words)
    for word in words:
        if word is None:
            return None
        if word in VALUED_OPTIONS:
            value = next(words, None)
            if value is None:
                return None
            overrides[word] = value
        elif word and not word.startswith("--ros-args"):
            configs.append(word)
    if not configs:
        return None
    found: list[Crossing] = []
    for config in configs:
        read = read_config(Path(os.path.normpath(config)), bridge.origin)
        if read is None:
            return None
        found.extend(read)
    source, target = overrides.get("--from"), overrides.get("--to")
    return [Crossing(c.topic, c.type, source or c.source, target or c.target, c.published,
                     c.span, c.origin) for c in found]


def read_config(path: Path, origin: Origin | None = None) -> list[Crossing] | None:
    """Return the topics one configuration file forwards (``None``: not readable)."""
    try:
        root = compose(read_text(path, prefix=MAX_CONFIG_BYTES))
    except (Unreadable, OSError, YamlLoadError, ValueError):
        return None
    return parse(root, path, origin)


def parse(root: yaml.Node | None, path: Path, origin: Origin | None = None
          ) -> list[Crossing] | None:
    """Return the topics a configuration forwards (``None`` when it is not one).

    Examples:
        >>> from launchverify.frontends.yaml_reader import compose
        >>> text = '''from_domain: 7
        ... to_domain: 0
        ... topics:
        ...   battery: {type: sensor_msgs/msg/BatteryState}
        ...   cmd: {type: std_msgs/msg/String, bidirectional: true}
        ...   cmd: {type: std_msgs/msg/String, reversed: true, remap: cmd_in}'''
        >>> found = parse(compose(text), Path("bridge.yaml"))
        >>> [(c.source, c.target, c.writes) for c in found]
        [('7', '0', '/battery'), ('7', '0', '/cmd'), ('0', '7', '/cmd'), ('0', '7', '/cmd_in')]
    """
    document = _pairs(root)
    if document is None:
        return None
    topics_node = document.get("topics")
    topics = _entries(topics_node) if topics_node is not None else []
    if topics is None:
        return None  # not a mapping: the bridge refuses to start
    found: list[Crossing] = []
    for key, options_node in topics:
        options = _pairs(options_node)
        if options is None:
            return None
        source = _scalar(options.get("from_domain", document.get("from_domain")))
        target = _scalar(options.get("to_domain", document.get("to_domain")))
        if source is None or target is None:
            return None  # the bridge refuses to start without both
        if _flag(options.get("reversed")):
            source, target = target, source
        crossing = Crossing(key, _scalar(options.get("type")), source, target,
                            _scalar(options.get("remap")) or "", span_of(path, options_node),
                            origin)
        found.append(crossing)
        if _flag(options.get("bidirectional")):
            found.append(Crossing(crossing.topic, crossing.type, target, source,
                                  crossing.published, crossing.span, origin))
    return found


def _entries(node: yaml.Node | None) -> list[tuple[str, yaml.Node]] | None:
    """Return a mapping's entries in order, repeated keys included."""
    if not isinstance(node, yaml.MappingNode):
        return None
    entries = []
    for key, value in node.value:
        text = _scalar(key)
        if text is None:
            return None
        entries.append((text, value))
    return entries


def _pairs(node: yaml.Node | None) -> dict[str, yaml.Node] | None:
    """Return a mapping's entries by key (the last of a repeated key wins)."""
    entries = _entries(node)
    return None if entries is None else dict(entries)


def _scalar(node: yaml.Node | None) -> str | None:
    return str(node.value) if isinstance(node, yaml.ScalarNode) else None


def _flag(node: yaml.Node | None) -> bool:
    """Return a YAML boolean as yaml-cpp's ``as<bool>`` reads it."""
    value = _scalar(node)
    return value is not None and value.lower() in ("true", "yes", "on", "y")
