"""Endpoints that wrapper libraries create for a node (tf2_ros, image_transport, nav2...).

Both extractors use these, so C++ and Python nodes describe the same wrapper alike. The
table ``WRAPPERS`` says what constructing a helper class creates, learnt from the
libraries' own sources (nav2_util, nav_2d_utils and nav2_costmap_2d as of nav2 jazzy,
diagnostic_updater): the wrapped ``create_*`` call sits in a library the package does not
contain, so the extractor cannot see it.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from launchverify.span import Span
from launchverify.topology.model import Endpoint, EndpointKind
from launchverify.topology.names import Resolved

TF_TYPE = "tf2_msgs/msg/TFMessage"
IMAGE_TYPE = "sensor_msgs/msg/Image"
CAMERA_INFO_TYPE = "sensor_msgs/msg/CameraInfo"
_TRANSPORTS_NOTE = ("plus {name}/<transport> for each image_transport plugin installed "
                    "(compressed, compressedDepth, theora...)")

# tf2_ros class -> (kind, topic) pairs it creates
TF_CLASSES: dict[str, tuple[tuple[EndpointKind, str], ...]] = {
    "TransformBroadcaster": ((EndpointKind.PUBLISHER, "/tf"),),
    "StaticTransformBroadcaster": ((EndpointKind.PUBLISHER, "/tf_static"),),
    "TransformListener": ((EndpointKind.SUBSCRIPTION, "/tf"),
                          (EndpointKind.SUBSCRIPTION, "/tf_static")),
}


def tf_endpoints(cls: str, span: Span, owner: str | None) -> list[Endpoint]:
    """Return what a tf2_ros broadcaster or listener publishes or subscribes to."""
    return [Endpoint(kind, topic, TF_TYPE, span, via="tf2_ros", owner=owner)
            for kind, topic in TF_CLASSES.get(cls, ())]


def camera_info_name(image: str) -> str:
    """Return the camera-info topic image_transport pairs with an image topic.

    It sits next to the image: ``camera/image_raw`` -> ``camera/camera_info``.
    """
    head, separator, _ = image.rpartition("/")
    return f"{head}/camera_info" if separator else "camera_info"


def image_endpoints(base: Endpoint, camera: bool) -> list[Endpoint]:
    """Return an image_transport endpoint, and its camera-info twin for camera ones."""
    note = _TRANSPORTS_NOTE.format(name=base.name) if base.name is not None else None
    image = Endpoint(base.kind, base.name, IMAGE_TYPE, base.span, base.name_parameter,
                     base.parameter_default, base.qos, "image_transport",
                     base.unresolved_reason, base.owner, note)
    if not camera:
        return [image]
    info_name = camera_info_name(base.name) if base.name is not None else None
    info = Endpoint(base.kind, info_name, CAMERA_INFO_TYPE, base.span,
                    base.name_parameter, base.parameter_default, base.qos,
                    "image_transport", base.unresolved_reason, base.owner,
                    "camera info paired with the image topic")
    return [image, info]


_INTERFACE = re.compile(r"([A-Za-z_]\w*)(?:/|::|\.)(msg|srv|action)(?:/|::|\.)([A-Za-z_]\w*)")


def normalise_type(written: str) -> str | None:
    """Return ``pkg/msg/Name`` for ``pkg::msg::Name`` or ``pkg.msg.Name``, else ``None``."""
    match = _INTERFACE.fullmatch("".join(written.split()).removeprefix("::"))
    return "/".join(match.groups()) if match else None


# --------------------------------------------------------------------------- helper classes

TWIST_NOTE = ("geometry_msgs/msg/Twist, or TwistStamped when the node's parameter "
              "enable_stamped_cmd_vel is true (its default: false up to jazzy, true from "
              "kilted)")
COSTMAP_NOTE = ("published by the costmap node {name} that this node starts in its process; "
                "the topics of its layer plugins (static_layer's map, obstacle_layer's "
                "observation sources...) depend on parameters and are not listed")
NAME = "{name}"  # the name argument, as given
TEMPLATE = "{template}"  # the class's template argument


@dataclass(frozen=True, slots=True)
class Made:
    """One endpoint a helper class creates: ``name`` is a pattern over ``{name}``."""

    kind: EndpointKind
    name: str
    type: str | None  # ``TEMPLATE``: the class's template argument; ``None``: ``note`` says
    note: str | None = None


@dataclass(frozen=True, slots=True)
class Wrapper:
    """What constructing a helper class creates, and where its name argument sits.

    ``name_at`` counts the arguments after the leading node ones (``name_first``: the
    name comes before the node, as in ``nav2_util::ServiceClient(name, node)``).
    ``default`` is the name when that argument is left out; ``parameter`` a node
    parameter that overrides it (``nav_2d_utils::OdomSubscriber``'s ``odom_topic``).
    """

    library: str
    made: tuple[Made, ...]
    name_at: int | None = 0
    name_first: bool = False
    default: str | None = None
    parameter: str | None = None


_PUB, _SUB = EndpointKind.PUBLISHER, EndpointKind.SUBSCRIPTION
_SRV, _CLIENT = EndpointKind.SERVICE, EndpointKind.CLIENT
_ODOM = "nav_msgs/msg/Odometry"
_COSTMAP_MADE = (
    Made(_PUB, "costmap", "nav_msgs/msg/OccupancyGrid", COSTMAP_NOTE),
    Made(_PUB, "costmap_raw", "nav2_msgs/msg/Costmap", COSTMAP_NOTE),
    Made(_PUB, "costmap_updates", "map_msgs/msg/OccupancyGridUpdate", COSTMAP_NOTE),
    Made(_PUB, "costmap_raw_updates", "nav2_msgs/msg/CostmapUpdate", COSTMAP_NOTE),
    Made(_PUB, "published_footprint", "geometry_msgs/msg/PolygonStamped", COSTMAP_NOTE),
    Made(_SUB, "footprint", "geometry_msgs/msg/Polygon", COSTMAP_NOTE),
    Made(_SRV, "get_costmap", "nav2_msgs/srv/GetCostmap", COSTMAP_NOTE),
    Made(_SRV, "get_cost_{name}", "nav2_msgs/srv/GetCost", COSTMAP_NOTE),
    Made(_SRV, "clear_except_{name}", "nav2_msgs/srv/ClearCostmapExceptRegion", COSTMAP_NOTE),
    Made(_SRV, "clear_around_{name}", "nav2_msgs/srv/ClearCostmapAroundRobot", COSTMAP_NOTE),
    Made(_SRV, "clear_around_pose_{name}", "nav2_msgs/srv/ClearCostmapAroundPose",
         COSTMAP_NOTE),
    Made(_SRV, "clear_entirely_{name}", "nav2_msgs/srv/ClearEntireCostmap", COSTMAP_NOTE),
)
COSTMAP_CLASS = "Costmap2DROS"

# class name -> what constructing it creates; the library must appear in the written type
# (after aliases), so that a package's own ``Updater`` or ``ServiceClient`` is not taken
WRAPPERS: dict[str, Wrapper] = {
    "TwistPublisher": Wrapper("nav2_util", (Made(_PUB, NAME, None, TWIST_NOTE),)),
    "TwistSubscriber": Wrapper("nav2_util", (Made(_SUB, NAME, None, TWIST_NOTE),)),
    "SimpleActionServer": Wrapper("nav2_util", (
        Made(EndpointKind.ACTION_SERVER, NAME, TEMPLATE),)),
    "ServiceClient": Wrapper("nav2_util", (Made(_CLIENT, NAME, TEMPLATE),), name_first=True),
    "OdomSmoother": Wrapper("nav2_util", (Made(_SUB, NAME, _ODOM),), name_at=1,
                            default="odom"),
    "OdomSubscriber": Wrapper("nav_2d_utils", (Made(_SUB, NAME, _ODOM),), default="odom",
                              parameter="odom_topic"),
    "CostmapSubscriber": Wrapper("nav2_costmap_2d", (
        Made(_SUB, NAME, "nav2_msgs/msg/Costmap"),
        Made(_SUB, "{name}_updates", "nav2_msgs/msg/CostmapUpdate"))),
    "FootprintSubscriber": Wrapper("nav2_costmap_2d", (
        Made(_SUB, NAME, "geometry_msgs/msg/PolygonStamped"),)),
    COSTMAP_CLASS: Wrapper("nav2_costmap_2d", _COSTMAP_MADE, name_first=True),
    "Updater": Wrapper("diagnostic_updater", (
        Made(_PUB, "/diagnostics", "diagnostic_msgs/msg/DiagnosticArray"),), name_at=None),
}


def wrapper_of(written: str) -> tuple[str, Wrapper] | None:
    """Return the helper class a written type names (``nav2_util::TwistPublisher``)."""
    compact = "".join(written.split())
    bare = re.sub(r"<.*", "", compact)
    cls = bare.rsplit("::", 1)[-1]
    wrapper = WRAPPERS.get(cls)
    if wrapper is None or f"{wrapper.library}::" not in bare:
        return None
    return cls, wrapper


def wrapper_endpoints(cls: str, wrapper: Wrapper, name: Resolved | None, template: str | None,
                      where: Span, owner: str | None, prefix: Resolved | None = None,
                      ) -> list[Endpoint]:
    """Return what one construction of a helper class creates.

    ``name`` is its name argument resolved (``None``: left out); ``template`` its template
    argument's interface type; ``prefix`` the namespace the objects live in relative to
    the node's (a costmap node's), when not the node's own.
    """
    via = wrapper.library
    if wrapper.name_at is None:
        return [Endpoint(m.kind, m.name, m.type, where, via=via, owner=owner, note=m.note)
                for m in wrapper.made]
    if name is None and wrapper.default is not None:
        name = Resolved(wrapper.default)
    if wrapper.parameter is not None and name is not None and name.parameter is None:
        name = Resolved(name.value, wrapper.parameter)
    out = []
    for made in wrapper.made:
        type_ = template if made.type == TEMPLATE else made.type
        note = made.note.format(name=name.value if name and name.value else "?") \
            if made.note else None
        out.append(_made(made, name, prefix, type_, where, owner, via, note))
    return out


def _made(made: Made, name: Resolved | None, prefix: Resolved | None, type_: str | None,
          where: Span, owner: str | None, via: str, note: str | None) -> Endpoint:
    """Return one endpoint of a helper, its name built from the pattern when known."""
    plain = made.name == NAME and prefix is None
    if name is None:
        return Endpoint(made.kind, None, type_, where, via=via, owner=owner, note=note,
                        unresolved_reason="no name argument found")
    if plain and name.known:
        return Endpoint(made.kind, name.value, type_, where, name.parameter,
                        name.value if name.parameter else None, via=via, owner=owner,
                        note=note, unresolved_reason=None if name.value is not None else
                        f"parameter '{name.parameter}' has no default declared in this file")
    if name.value is None or name.parameter is not None:
        reason = name.reason or (f"built from parameter '{name.parameter}'"
                                 if name.parameter else "the name is not known")
        return Endpoint(made.kind, None, type_, where, via=via, owner=owner, note=note,
                        unresolved_reason=reason)
    if prefix is not None and prefix.value is None:
        return Endpoint(made.kind, None, type_, where, via=via, owner=owner, note=note,
                        unresolved_reason=prefix.reason or "its namespace is not known")
    written = made.name.format(name=name.value)
    if prefix is not None and prefix.value:
        written = f"{prefix.value.rstrip('/')}/{written}"
    return Endpoint(made.kind, written, type_, where, via=via, owner=owner, note=note)
