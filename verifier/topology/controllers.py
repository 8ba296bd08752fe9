"""ros2_control's controllers as nodes of the computation graph.

Controllers are nodes no launch file starts: a ``spawner`` asks the controller manager to
load them, and they run in the manager's process, each a node named after the controller
in the manager's namespace. ``with_controllers`` adds them after their spawner: their type
from the spawner's ``--controller-type`` or ``--param-file``, else the manager's
``<name>.type`` parameter; their interface from the type's model. A controller whose type
or interface is not known is a node whose endpoints are not known, never one that has none.
"""

from __future__ import annotations

import re
import shlex
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import TYPE_CHECKING

from launchverify.graph import NodeRecord, ParamRecord
from launchverify.ir.subst import Sub, Text
from launchverify.models.rewritten_yaml import rewrite_of, rooted
from launchverify.models.ros2_control import CONTROL_NODE, MANAGER_NAME, SPAWNER
from launchverify.models.ros_names import node_fqn, node_key_matches
from launchverify.parameters import effective_parameters
from launchverify.span import Span
from launchverify.topology.compose import (
    ComposedEndpoint,
    Composer,
    NodeEndpoints,
    Spawn,
    WorkspaceInterfaces,
    _Identity,
    _remap_rules,
    named_record,
)
from launchverify.topology.model import Endpoint, EndpointKind, NodeInterface
from launchverify.topology.resolve import Rule, RuleLike, UnknownRule

SPAWNER_FILES = "<the spawner's parameter files>"

if TYPE_CHECKING:
    from launchverify.frontends.param_file import FileParameter, ParamFile
    from launchverify.parameters import Contribution


@dataclass(frozen=True, slots=True)
class Written:
    """Where a controller's type is written literally; ``exact``: just its text (for a fix)."""

    at: Span
    exact: bool


def with_controllers(composer: Composer, composed: list[NodeEndpoints]) -> list[NodeEndpoints]:
    """Return ``composed`` with the controllers each spawner loads right after it."""
    if not any((c.package, c.executable) == SPAWNER for c in composed):
        return composed
    return Spawners(composer).with_controllers(composed)


class Spawners:
    """The spawners of one composed view, and the controllers they load."""

    def __init__(self, composer: Composer) -> None:
        self.composer = composer

    def with_controllers(self, composed: list[NodeEndpoints]) -> list[NodeEndpoints]:
        """Return ``composed`` with each spawner's controllers right after it.

        A spawner whose command line is known becomes a node that calls its manager's
        services (when the manager is launched here); one that is not stays a node whose
        endpoints are not known.
        """
        managers = {c.fqn: c for c in composed
                    if (c.package, c.executable) == CONTROL_NODE and c.fqn is not None}
        out: list[NodeEndpoints] = []
        for entry in composed:
            if (entry.package, entry.executable) != SPAWNER:
                out.append(entry)
                continue
            spawner, controllers = self.spawned(entry, managers)
            out.append(spawner)
            out.extend(controllers)
        return out

    def spawned(self, entry: NodeEndpoints, managers: dict[str, NodeEndpoints],
                ) -> tuple[NodeEndpoints, list[NodeEndpoints]]:
        """Return a spawner as known from its command line, and the controllers it loads."""
        node = entry.node
        launch = self.composer.graph.launch_of(node)
        call = parse_spawner(self.spawner_words(launch.arguments) if launch is not None
                             else [])
        namespace = self.composer.text(node.namespace) if node.namespace is not None else "/"
        manager = call.manager_fqn(namespace)
        host = managers.get(manager) if manager is not None else None
        controllers = [self.controller(node, name, call, manager, host)
                       for name in call.controllers]
        unknown = call.unknown or (None if manager is not None else
                                   "the controller manager's name is not known before launch")
        if unknown is not None:
            return replace(entry, note=f"a ros2_control spawner: {unknown}"), controllers
        return self.spawner(entry, call, manager or "", host is not None), controllers

    def spawner_words(self, arguments: tuple[Sub, ...]) -> list[str | Sub]:
        """Return a spawner's words: split, but a ``--controller-ros-args`` value kept whole.

        That value is one word holding the controller's own ROS arguments
        (``"-r ~/cmd_vel:=/cmd_vel"``).
        """
        words: list[str | Sub] = []
        for argument in arguments:
            if words and words[-1] == "--controller-ros-args":
                text = self.composer.text(argument)
                words.append(argument if text is None else text)
                continue
            words.extend(self.composer.words((argument,)))
        return words

    def spawner(self, entry: NodeEndpoints, call: SpawnerCall, manager: str,
                served: bool) -> NodeEndpoints:
        """Return a spawner as the client of its manager's services.

        Only when the manager is launched here: one that runs elsewhere (a simulator's
        plugin) serves them unbeknown to us, and a client nobody seems to serve would be
        a false claim.
        """
        node = entry.node
        span = node.origin.span
        services = call.services() if served else []
        endpoints = tuple(Endpoint(EndpointKind.CLIENT, f"{manager}/{service}",
                                   f"controller_manager_msgs/srv/{_pascal(service)}", span)
                          for service in services)
        interface = NodeInterface(SPAWNER[0], SPAWNER[1], None, None, endpoints, ())
        name = self.composer.text(node.name) if node.name is not None else (
            f"spawner_{call.controllers[0]}" if call.controllers else None)
        namespace = self.composer.text(node.namespace) if node.namespace is not None else "/"
        fqn = node_fqn(namespace, name) if name is not None and namespace is not None else None
        loads = ", ".join(call.controllers) or "no controller"
        return NodeEndpoints(node, entry.package, entry.executable, interface,
                             tuple(ComposedEndpoint(node, e, e.name) for e in endpoints),
                             note=f"a ros2_control spawner: asks {manager} to load {loads}",
                             fqn=fqn)

    def controller(self, spawner: NodeRecord, name: str, call: SpawnerCall,
                   manager: str | None, host: NodeEndpoints | None) -> NodeEndpoints:
        """Return one controller: a node of its manager's process, named after it.

        Its interface is its type's (``diff_drive_controller/DiffDriveController``), the
        type being what the spawner's ``--controller-type`` or ``--param-file``, else the
        manager's parameters, say. It runs when its spawner does (its place and
        condition are the spawner's).
        """
        namespace = None if manager is None else manager.rpartition("/")[0] or "/"
        fqn = None if namespace is None else node_fqn(namespace, name)
        kind, reason, undefined, written = self.controller_type(spawner, name, fqn, call, host)
        undefined = undefined and call.unknown is None  # an option not understood may give it
        spawn = Spawn(spawner, name, manager, undefined,
                      self.defined(host) if undefined and host is not None else (), kind,
                      written.at if written is not None and call.unknown is None else None,
                      written is not None and written.exact)
        package = kind.partition("/")[0] if kind is not None and "/" in kind else None
        parameters = tuple(p for p in host.node.parameters
                           if p.file is not None or p.scope) if host is not None else ()
        if call.param_files or spawner.parameters or call.unknown is not None:
            # the spawner loads more into the controller: not followed here, so what the
            # controller receives is not all known (a file that cannot be read says so)
            parameters += (ParamRecord(spawner.origin, file=Text(SPAWNER_FILES)),)
        record = replace(spawner, kind="node", package=_text(package), executable=_text(kind),
                         name=Text(name), namespace=_text(namespace), fqn=_text(fqn),
                         remappings=(), parameters=parameters, container=None,
                         executable_written=None, autostart=None)
        what = f"controller {name} loaded by a spawner"
        if namespace is None:
            return NodeEndpoints(record, package, kind, None, fqn=fqn, spawn=spawn, note=(
                f"{what}: its controller manager's name is not known before launch"))
        if kind is None or package is None:
            return NodeEndpoints(record, package, kind, None, fqn=fqn, spawn=spawn,
                                 note=f"{what}: {reason or f'its type {kind} names no package'}")
        interface, note = self.composer.source.interface(package, kind, False)
        if interface is None:
            return NodeEndpoints(record, package, kind, None, fqn=fqn, spawn=spawn,
                                 note=f"{what} ({kind}): {note}")
        identity = _Identity(name, namespace, rules=self.controller_rules(call, host))
        endpoints = tuple(self.composer.endpoint(record, e, identity) for e in interface.endpoints)
        return NodeEndpoints(record, package, kind, interface, endpoints, fqn=fqn, spawn=spawn,
                             note=f"{what} ({kind})" + (f"; {note}" if note else ""))

    def controller_type(self, spawner: NodeRecord, name: str, fqn: str | None,
                        call: SpawnerCall, host: NodeEndpoints | None,
                        ) -> tuple[str | None, str | None, bool, Written | None]:
        """Return a controller's type (``package/Class``), or ``None`` and why not.

        The third item is ``True`` when the type is surely given nowhere: every source
        was read, and the manager will refuse to load the controller. The fourth says
        where the type is written literally (``None``: not so, a launch argument gives it).

        As the spawner and the manager decide it: ``--controller-type``, else a
        ``type`` for the controller in the spawner's ``--param-file`` (it sets the
        manager's ``<name>.type``), else the manager's own ``<name>.type`` parameter.
        Since 2025 the spawner also reads the files of its own ``--params-file`` ROS
        arguments (launch's ``parameters=`` on the spawner) as ``--param-file``s.
        """
        if call.controller_type is not None:
            given = self.word(call.controller_type)
            return given, None if given is not None else (
                "its --controller-type is not known before launch"), False, (
                None if given is None else self.type_argument(spawner, given))
        for file in call.param_files:
            text = self.word(file)
            if text is None:
                return None, "the spawner's --param-file is not known before launch", False, None
            loaded = self.parameter_file(text)
            if loaded is None:
                return (None, f"the spawner's --param-file {text} could not be read", False,
                        None)
            found = _type_in(loaded, name, fqn)
            if found is not None:
                return str(found.value), None, False, _in_file(found)
        own, unknown = self.own_parameter_files(spawner)
        for loaded in own:
            found = _type_in(loaded, name, fqn)
            if found is not None:
                return str(found.value), None, False, _in_file(found)
        if unknown is not None:
            return None, unknown, False, None
        if host is None:
            return None, ("its controller manager is not started by this launch and the "
                          "spawner's --param-file does not give its type"), False, None
        graph = self.composer.graph
        effective = effective_parameters(graph, named_record(graph, host))
        winner = effective.winner(f"{name}.type")
        if winner is not None:
            if isinstance(winner.value, str) and winner.value:
                # a source not read may give another type (for LV509, no fact then)
                return winner.value, None, False, self.type_parameter(
                    host, name, winner) if effective.complete else None
            return (None, f"the manager's parameter {name}.type is not known before launch",
                    False, None)
        if not effective.complete:
            return None, ("a parameter source of its controller manager could not be read: "
                          "it may give the type"), False, None
        return None, (f"neither the controller manager's parameters nor the spawner's "
                      f"--param-file give {name}.type"), True, None

    def type_argument(self, spawner: NodeRecord, given: str) -> Written | None:
        """Return where a spawner's ``--controller-type`` is written literally, if it is.

        The last ``-t``/``--controller-type`` of its arguments wins, as in the spawner; a
        value from a launch argument (or any expression) is not written literally.
        """
        launch = self.composer.graph.launch_of(spawner)
        found: Written | None = None
        previous: str | None = None
        for argument in launch.arguments if launch is not None else ():
            if previous == "--controller-ros-args":  # one word, whatever it holds
                previous = None
                continue
            literal = isinstance(argument, Text) and argument.where is not None
            words = _located(argument) if isinstance(argument, Text) and literal else [
                (w, None) for w in self.composer.words((argument,))]
            for word, at in words:
                if not isinstance(word, str):
                    previous = None
                    continue
                option, equals, value = word.partition("=")
                if previous in ("-t", "--controller-type"):
                    found = None if not literal or word != given else _written(
                        at, 0, word, spawner.origin.span)
                elif equals and option in ("-t", "--controller-type"):
                    found = None if not literal or value != given else _written(
                        at, len(option) + 1, value, spawner.origin.span)
                previous = word
        return found

    def type_parameter(self, host: NodeEndpoints, name: str,
                       winner: Contribution) -> Written | None:
        """Return where the manager's ``<name>.type`` is written literally, if it is.

        In a parameter file as it is (not a value ``RewrittenYaml`` puts there), or as a
        literal of the launch (``parameters=[{'arm.type': '...'}]``).
        """
        if winner.layer == "file":
            return None if winner.value_span is None else Written(winner.value_span, True)
        for param in host.node.parameters:
            if param.origin.span != winner.span or param.name is None or \
                    self.composer.text(param.name) != f"{name}.type":
                continue
            value = param.value
            if isinstance(value, Text):
                return Written(value.where, True) if value.where is not None else Written(
                    winner.span, False)
            if isinstance(value, str):
                return Written(winner.span, False)
        return None

    def own_parameter_files(self, spawner: NodeRecord) -> tuple[list[ParamFile], str | None]:
        """Return the parameter files launch gives the spawner node, and why not all.

        launch_ros passes them (and a file of its inline values) as ``--params-file``; a
        value that could be a controller's type, or a file not read, leaves it unknown.
        """
        found: list[ParamFile] = []
        graph = self.composer.graph
        for param in spawner.parameters:
            if param.file is not None:
                loaded = None if param.source is None else graph.param_files.get(param.source)
                if loaded is None or not loaded.readable:
                    return found, "a parameter file of the spawner could not be read"
                rewrite = rewrite_of(param.file)
                if rewrite is not None and rewrite.root_key is not None:
                    root = graph.base(rewrite.root_key)
                    if root is None:
                        return found, "a parameter file of the spawner moves under a key " \
                            "not known before launch"
                    loaded = replace(loaded, blocks=[replace(block, key=rooted(block.key, root))
                                                     for block in loaded.blocks])
                found.append(loaded)
            elif param.name is None or (self.composer.text(param.name) or "type") \
                    .rpartition(".")[2] == "type":
                return found, "the spawner's own parameters may give the type"
        return found, None

    def defined(self, host: NodeEndpoints) -> tuple[str, ...]:
        """Return the controllers a manager's parameters give a type (for did-you-mean)."""
        graph = self.composer.graph
        effective = effective_parameters(graph, named_record(graph, host))
        return tuple(sorted(name[:-len(".type")] for name in effective.values
                            if name.endswith(".type") and name.count(".") == 1))

    def word(self, value: str | Sub) -> str | None:
        """Return a command-line word when known."""
        return value if isinstance(value, str) else self.composer.text(value)

    def parameter_file(self, text: str) -> ParamFile | None:
        """Return a parameter file the evaluation read, else one read from the workspace."""
        loaded = self.composer.graph.param_files.get(Path(text))
        if loaded is not None:
            return loaded if loaded.readable else None
        if isinstance(self.composer.source, WorkspaceInterfaces):
            return self.composer.source.parameter_file(text)
        return None

    def controller_rules(self, call: SpawnerCall, host: NodeEndpoints | None,
                         ) -> list[RuleLike]:
        """Return the remap rules a controller node gets, in the order rcl applies them.

        Its own (``--controller-ros-args``), then the manager process's command line
        (launch's ``remappings``, ``-r`` rules): global arguments reach every node of a
        process. The manager drops ``__node``/``__ns`` ones: the controller keeps its name.
        """
        rules: list[RuleLike] = []
        if call.ros_args:
            where = "a spawner's --controller-ros-args"
            words = self.composer.words(tuple(Text(a) if isinstance(a, str) else a
                                     for a in call.ros_args))
            found, unknown = _remap_rules(words, True, where)
            rules.extend(found)
            if unknown is not None:
                rules.append(UnknownRule(unknown))
        if host is not None:
            given, reason = self.composer.ros_argument_rules(host.node)
            rules.extend(given)
            if reason is not None:
                rules.append(UnknownRule(reason))
            rules.extend(self.composer.remap_rules(host.node))
        return [r for r in rules if not (isinstance(r, Rule) and r.src in ("__node", "__ns"))]


# ``spawner`` options (controller_manager, humble to rolling) and what they take
_SPAWNER_VALUED = frozenset({
    "-c", "--controller-manager", "-p", "--param-file", "-n", "--namespace", "-t",
    "--controller-type", "--controller-manager-timeout", "--switch-timeout",
    "--service-call-timeout", "--controller-ros-args"})
_SPAWNER_FLAGS = frozenset({"--load-only", "--stopped", "--inactive", "-u",
                            "--unload-on-kill", "--activate-as-group", "--switch-asap",
                            "--no-switch-asap", "-h", "--help"})
_SPAWNER_LISTS = frozenset({"--fallback_controllers", "--fallback-controllers"})


@dataclass
class SpawnerCall:
    """What a ``controller_manager spawner`` command line asks for."""

    controllers: list[str] = field(default_factory=list)
    manager: str | Sub = MANAGER_NAME
    namespace: str | Sub | None = None  # ``-n``: the manager's namespace (deprecated)
    param_files: list[str | Sub] = field(default_factory=list)
    controller_type: str | Sub | None = None
    ros_args: list[str | Sub] = field(default_factory=list)
    load_only: bool = False
    inactive: bool = False
    unload: bool = False
    unknown: str | None = None  # why not everything it asks for is known

    def manager_fqn(self, namespace: str | None) -> str | None:
        """Return the manager's fully qualified name, as the spawner makes it.

        A relative ``--controller-manager`` is taken in ``--namespace``, else in the
        spawner's own namespace.
        """
        if not isinstance(self.manager, str) or not self.manager.strip("/"):
            return None
        if self.manager.startswith("/"):
            return "/" + self.manager.strip("/")
        base = self.namespace if self.namespace is not None else namespace
        if not isinstance(base, str):
            return None
        base = "/" + base.strip("/")
        return node_fqn(base, self.manager.strip("/"))

    def services(self) -> list[str]:
        """Return the manager's services the spawner calls."""
        found = ["list_controllers", "load_controller"]
        if not self.load_only:
            found.append("configure_controller")
            if not self.inactive:
                found.append("switch_controller")
        if self.unload:
            found.append("unload_controller")
        return found


def parse_spawner(words: list[str | Sub]) -> SpawnerCall:
    """Return what a spawner's arguments ask for (``unknown`` says what is not known).

    Examples:
        >>> call = parse_spawner(["jsb", "diff", "--param-file", "/c.yaml", "-c", "/cm"])
        >>> call.controllers, call.param_files, call.manager_fqn("/")
        (['jsb', 'diff'], ['/c.yaml'], '/cm')
        >>> parse_spawner(["arm", "--controller-manager-timeout", "50"]).manager_fqn("/r1")
        '/r1/controller_manager'
    """
    call = SpawnerCall()
    index = 0
    while index < len(words):
        word = words[index]
        index += 1
        if not isinstance(word, str):  # a controller's name, or an option: not known
            call.unknown = "an argument is not known before launch"
            continue
        if word == "--ros-args":  # the spawner's own ROS arguments from here on
            break
        option, equals, inline = word.partition("=")
        if word in _SPAWNER_FLAGS:
            call.load_only |= word == "--load-only"
            call.inactive |= word in ("--inactive", "--stopped")
            call.unload |= word in ("-u", "--unload-on-kill")
        elif word in _SPAWNER_VALUED or (equals and option in _SPAWNER_VALUED):
            if equals:
                value: str | Sub = inline
            elif index < len(words):
                value = words[index]
                index += 1
            else:
                call.unknown = f"{word} has no value"
                break
            _set_option(call, option if equals else word, value)
        elif word in _SPAWNER_LISTS:
            while index < len(words) and isinstance(words[index], str) \
                    and not str(words[index]).startswith("-"):
                index += 1
        elif word.startswith("-"):
            call.unknown = f"option {word} is not one launchverify knows"
        else:
            call.controllers.append(word)
    return call


def _set_option(call: SpawnerCall, option: str, value: str | Sub) -> None:
    if option in ("-c", "--controller-manager"):
        call.manager = value
    elif option in ("-n", "--namespace"):
        call.namespace = value
    elif option in ("-p", "--param-file"):
        call.param_files.append(value)
    elif option in ("-t", "--controller-type"):
        call.controller_type = value
    elif option == "--controller-ros-args":
        call.ros_args.append(value)


def _type_in(loaded: ParamFile, name: str, fqn: str | None) -> FileParameter | None:
    """Return the ``type`` a parameter file gives a controller (its own key before ``/**``).

    The spawner looks for the controller's name (with or without its namespace), then
    for a wildcard key.
    """
    own: FileParameter | None = None
    wildcard: FileParameter | None = None
    for block in loaded.blocks:
        parameter = block.parameters.get("type")
        if parameter is None or not isinstance(parameter.value, str) or not parameter.value:
            continue
        if block.key.strip("/") == name or (fqn is not None and block.key == fqn):
            own = parameter
        elif fqn is not None and node_key_matches(block.key, fqn):
            wildcard = parameter
    return own or wildcard


def _in_file(parameter: FileParameter) -> Written:
    """Return where a parameter file writes a type: its value, else its key."""
    if parameter.value_span is not None:
        return Written(parameter.value_span, True)
    return Written(parameter.span, False)


def _located(argument: Text) -> list[tuple[str, Span | None]]:
    """Return the words of a literal argument, each with where it is written.

    A word is located only when the argument lies on one line and the word holds no
    quote or backslash (what shlex would change); launch splits the argument as shlex.
    """
    where = argument.where
    try:
        words = shlex.split(argument.text)
    except ValueError:
        return [(argument.text, None)]
    if where is None or where.end_line not in (None, where.line):
        return [(word, None) for word in words]
    plain = list(re.finditer(r"\S+", argument.text))
    if [m.group() for m in plain] != words:  # quotes or escapes: places not known
        return [(word, None) for word in words]
    return [(m.group(), Span(where.file, where.line, where.column + m.start(), where.line,
                             where.column + m.end())) for m in plain]


def _written(at: Span | None, offset: int, word: str, otherwise: Span) -> Written:
    """Return the place of ``word`` starting ``offset`` characters into a located word.

    ``otherwise`` (the spawner) when the word's place is not known.
    """
    if at is None:
        return Written(otherwise, False)
    return Written(Span(at.file, at.line, at.column + offset, at.line,
                        at.column + offset + len(word)), True)


def _text(value: str | None) -> Sub | None:
    return None if value is None else Text(value)


def _pascal(snake: str) -> str:
    """Return ``ListControllers`` for ``list_controllers`` (a service type's name)."""
    return "".join(part.capitalize() for part in snake.split("_"))
