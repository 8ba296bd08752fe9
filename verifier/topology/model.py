"""What a node's code creates: endpoints and the interface of one executable or component.

Names are kept as written in the code (relative, ``~/private`` or absolute): resolving them
against a namespace and remaps belongs to the launch graph, not to the sources.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from enum import Enum
from pathlib import Path

from launchverify.span import Span
from launchverify.topology.names import Resolved
from launchverify.topology.qos import Qos


class EndpointKind(str, Enum):
    """What an endpoint does on the ROS graph."""

    PUBLISHER = "publisher"
    SUBSCRIPTION = "subscription"
    SERVICE = "service"
    CLIENT = "client"
    ACTION_SERVER = "action_server"
    ACTION_CLIENT = "action_client"


@dataclass(frozen=True, slots=True)
class Endpoint:
    """One publisher, subscription, service, client or action end a node's code creates.

    ``name`` is the name as written, ``None`` when it is not known before run time; then
    ``unresolved_reason`` says why. When the name comes from a parameter,
    ``name_parameter`` is that parameter and ``name`` its default (when one is declared).
    ``via`` names the wrapper that creates it (``image_transport``, ``message_filters``,
    ``tf2_ros``); ``type`` is normalised (``sensor_msgs/msg/LaserScan``) when known.
    """

    kind: EndpointKind
    name: str | None
    type: str | None
    span: Span
    name_parameter: str | None = None
    parameter_default: str | None = None
    qos: str | None = None
    via: str | None = None
    unresolved_reason: str | None = None
    owner: str | None = None  # the class whose code creates it, when inside one
    note: str | None = None
    type_written: str | None = None  # the type as written, when ``type`` is not known
    profile: Qos | None = None  # reliability and durability, when the code shows them

    def at(self, file: Path) -> Endpoint:
        """Return the same endpoint located in ``file`` (a cached result reused)."""
        return replace(self, span=replace(self.span, file=file))


@dataclass(frozen=True, slots=True)
class Parameter:
    """One parameter a node's code declares (``declare_parameter``, a generated library).

    ``name`` is relative to the node; ``*`` stands for a part built at run time
    (``*.plugin`` for ``plugin_name + ".plugin"``). ``type`` is rcl's name (``double``,
    ``string_array``), ``None`` when not known; ``dynamic`` when the descriptor allows any
    type. ``required``: typed with no default in a form that throws at start unless a value
    is given (rclcpp's ``declare_parameter<T>(name)``, a generated definition).
    ``limits`` are the checks a value must pass, as generate_parameter_library names them:
    ``("bounds", (low, high))`` inclusive, ``("gt", (x,))``, ``("gt_eq", ...)``,
    ``("lt", ...)``, ``("lt_eq", ...)``, ``("one_of", ([a, b],))``.
    """

    name: str
    type: str | None
    span: Span
    default: object = None
    dynamic: bool = False
    required: bool = False
    read_only: bool = False
    limits: tuple[tuple[str, tuple[object, ...]], ...] = ()
    via: str | None = None  # generate_parameter_library, when declared by its YAML
    owner: str | None = None  # the class whose code declares it, when inside one

    def at(self, file: Path) -> Parameter:
        """Return the same declaration located in ``file``."""
        return replace(self, span=replace(self.span, file=file))


LOADS_PLUGINS = "it loads plugins chosen by parameters, whose own are not read"
# How the readers say a node takes undeclared parameters (C++ NodeOptions, rclpy's Node)
CPP_UNDECLARED = "its NodeOptions set "
PYTHON_UNDECLARED = "its Node is built with "


def soft_open(reason: str | None) -> bool:
    """Return whether a node is open only in ways that still let a misspelling be told.

    It accepts undeclared parameters (NodeOptions, rclpy's Node arguments), or loads
    plugins: every name it and its known plugins read is seen, so a name one edit from
    one of them, and none of them itself, is a typo; another name may be a plugin's own.
    """
    return reason == LOADS_PLUGINS or (reason or "").startswith(
        (CPP_UNDECLARED, PYTHON_UNDECLARED))


@dataclass(frozen=True, slots=True)
class PluginContract:
    """The parameters one pluginlib plugin declares on the node that loads it.

    ``type`` is its pluginlib name (``dwb_core::DWBLocalPlanner``), ``base`` the class it
    derives from; names are as declared (``*.max_vel_x`` for ``plugin_name + ".max_vel_x"``,
    plain names for plugins that declare them unprefixed, as nav2's behaviours do).
    ``open`` says why it may declare more (``None``: it does not).
    """

    type: str
    base: str
    parameters: tuple[Parameter, ...]
    open: str | None = None


@dataclass(frozen=True, slots=True)
class NodeName:
    """A default node name given in code (``rclcpp::Node("talker")``, ``super().__init__``).

    ``name`` is ``None`` when the code computes it: then no other name in the same sources
    can be taken for the node's name.
    """

    name: str | None
    span: Span
    owner: str | None = None

    def at(self, file: Path) -> NodeName:
        """Return the same name located in ``file``."""
        return replace(self, span=replace(self.span, file=file))


@dataclass(frozen=True, slots=True)
class MemberInit:
    """An object built with a node whose type is declared in another file.

    ``cartesian_broadcaster_(*this)`` in a ``.cpp`` whose header declares the member a
    ``tf2_ros::StaticTransformBroadcaster`` (``member``), or ``new ImuSubscriber(this,
    "imu")`` where a header's ``typedef`` says what ``ImuSubscriber`` is (``written``):
    what it creates is known once the files of the whole executable are read together.
    """

    member: str | None
    written: str | None
    span: Span
    owner: str | None
    node_arguments: int  # leading node arguments (``this``, ``*this``, ``node``)
    arguments: int
    values: tuple[Resolved, ...]  # the first arguments after them, resolved

    @property
    def name(self) -> Resolved | None:
        """Return the first argument after the node ones: most wrappers' name."""
        return self.values[0] if self.values else None

    def at(self, file: Path) -> MemberInit:
        """Return the same initialiser located in ``file``."""
        return replace(self, span=replace(self.span, file=file))


@dataclass(frozen=True, slots=True)
class FileInterfaces:
    """What one source file creates; ``problem`` says why a file could not be read."""

    file: Path
    endpoints: tuple[Endpoint, ...] = ()
    node_names: tuple[NodeName, ...] = ()
    problem: str | None = None
    partial: bool = False  # the parser recovered from syntax errors
    aliases: tuple[tuple[str, str], ...] = ()  # C++ type aliases, for other files' types
    members: tuple[tuple[str, str], ...] = ()  # ``Class::member`` -> its written type
    inits: tuple[MemberInit, ...] = ()  # initialisers of members declared elsewhere
    classes: tuple[tuple[str, tuple[str, ...]], ...] = ()  # class -> bases and member types
    instantiated: tuple[str, ...] = ()  # classes the file's code builds (make_shared, new)
    loaders: tuple[str, ...] = ()  # base classes of the pluginlib plugins the file loads
    parameters: tuple[Parameter, ...] = ()
    undeclared: str | None = None  # why the node may accept parameters it never declares
    bases: tuple[tuple[str, str], ...] = ()  # (class, base class as written), for parameters
    declarations_missed: bool = False  # the text declares parameters the reader did not see
    includes: tuple[str, ...] = ()  # ``#include`` paths as written

    def at(self, file: Path) -> FileInterfaces:
        """Return the same result for another file with identical content."""
        if file == self.file:
            return self
        return FileInterfaces(file, tuple(e.at(file) for e in self.endpoints),
                              tuple(n.at(file) for n in self.node_names),
                              self.problem, self.partial, self.aliases, self.members,
                              tuple(i.at(file) for i in self.inits), self.classes,
                              self.instantiated, self.loaders,
                              tuple(p.at(file) for p in self.parameters), self.undeclared,
                              self.bases, self.declarations_missed, self.includes)


@dataclass(frozen=True, slots=True)
class NodeInterface:
    """The endpoints of one executable (or component plugin) of a package.

    ``sources`` are the files read; ``problems`` say what could not be read or mapped, so
    an empty ``endpoints`` never passes for "creates nothing" when it is incomplete.
    ``model`` says where an interface shipped as a model (``topology.shipped``) was
    extracted from; ``None`` for one read from the workspace's sources. ``node_name_at``
    is where the code gives ``node_name`` (a model's records it when extracted with it).
    """

    package: str
    executable: str
    component: str | None
    node_name: str | None
    endpoints: tuple[Endpoint, ...]
    sources: tuple[Path, ...]
    problems: tuple[str, ...] = ()
    model: str | None = None
    parameters: tuple[Parameter, ...] = ()
    # why ``parameters`` may not be every name the node accepts (``None``: they are)
    parameters_open: str | None = "its parameter declarations were not read"
    # the node option that declares any parameter given (then types are not fixed by code)
    parameters_undeclared: str | None = None
    # the one ROS 2 distribution a shipped model's parameters are of (``None``: any)
    distro: str | None = None
    node_name_at: Span | None = None
    # base classes of the pluginlib plugins it loads, and the plugins known to derive from
    # them (a released package's model lists its repository's)
    loaders: tuple[str, ...] = ()
    plugins: tuple[PluginContract, ...] = ()
