"""Endpoints that wrapper libraries create for a node (tf2_ros, image_transport).

Both extractors use these, so C++ and Python nodes describe the same wrapper alike.
"""

from __future__ import annotations

import re

from launchverify.span import Span
from launchverify.topology.model import Endpoint, EndpointKind

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
