"""ROS 2 naming rules: validity (rmw/rcl), namespace composition (launch_ros), expansion.

Each validator returns ``None`` for a valid name or the reason it is invalid, worded like
rmw's messages so users recognise them.
"""

from __future__ import annotations

import functools
import re

NODE_NAME_MAX = 255
NAMESPACE_MAX = 245
TOPIC_MAX = 247
_NODE_CHARS = re.compile(r"[A-Za-z0-9_]*")
_NS_CHARS = re.compile(r"[A-Za-z0-9_/]*")
_TOPIC_CHARS = re.compile(r"[A-Za-z0-9_/~{}]*")


def validate_node_name(name: str) -> str | None:
    """Return why ``name`` is not a valid node name, or ``None``.

    Examples:
        >>> validate_node_name("talker") is None
        True
        >>> validate_node_name("my-node")
        "node name must not contain characters other than alphanumerics or '_'"
    """
    if not name:
        return "node name must not be empty"
    if not _NODE_CHARS.fullmatch(name):
        return "node name must not contain characters other than alphanumerics or '_'"
    if name[0].isdigit():
        return "node name must not start with a number"
    if len(name) > NODE_NAME_MAX:
        return f"node name must not be longer than {NODE_NAME_MAX} characters"
    return None


def validate_namespace(namespace: str) -> str | None:
    """Return why an absolute ``namespace`` is invalid, or ``None`` (rmw rules)."""
    if not namespace:
        return "namespace must not be empty"
    if not namespace.startswith("/"):
        return "namespace must be absolute, it must lead with a '/'"
    if namespace == "/":
        return None
    if namespace.endswith("/"):
        return "namespace must not end with a '/', unless only a '/'"
    if "//" in namespace:
        return "namespace must not contain repeated '/'"
    if not _NS_CHARS.fullmatch(namespace):
        return "namespace must not contain characters other than alphanumerics, '_', or '/'"
    if any(token[:1].isdigit() for token in namespace.split("/")):
        return "namespace must not have a token that starts with a number"
    if len(namespace) > NAMESPACE_MAX:
        return f"namespace must not be longer than {NAMESPACE_MAX} characters"
    return None


def validate_topic_name(name: str) -> str | None:
    """Return why a topic or service name (relative, private or absolute) is invalid."""
    if not name:
        return "topic name must not be empty"
    if not _TOPIC_CHARS.fullmatch(name):
        return "topic name must not contain characters other than alphanumerics, '_', '~', '{', '}', or '/'"  # noqa: E501
    if name[0].isdigit():
        return "topic name must not start with a number"
    if name.endswith("/"):
        return "topic name must not end with a forward slash"
    if "~" in name[1:]:
        return "'~' must only be the first character"
    if name.startswith("~") and len(name) > 1 and name[1] != "/":
        return "'~' must be followed by '/' or stand alone"
    if "//" in name:
        return "topic name must not contain repeated '/'"
    depth = 0
    for index, char in enumerate(name):
        if char == "{":
            if depth:
                return "substitutions in topic names must not be nested"
            depth = 1
            if index + 1 < len(name) and name[index + 1].isdigit():
                return "substitution in topic name must not start with a number"
        elif char == "}":
            if not depth:
                return "unbalanced '}' in topic name"
            depth = 0
        elif char == "/" and depth:
            return "'/' is not allowed inside a substitution"
    if depth:
        return "unbalanced '{' in topic name"
    if any(token[:1].isdigit() for token in name.split("/")[1:]):
        return "topic name must not have a token that starts with a number"
    return None


def validate_remap_name(name: str) -> str | None:
    """Return why one side of a remap rule is invalid.

    ``rostopic://`` prefixes are allowed, and a ``node_name:`` prefix that limits the rule
    to one node of the process (``talker:chatter:=news``).
    """
    for prefix in ("rostopic://", "rosservice://"):
        if name.startswith(prefix):
            name = name[len(prefix):]
            break
    else:
        node, colon, rest = name.partition(":")
        if colon:
            problem = validate_node_name(node)
            if problem is not None:
                return f"node name before ':' is invalid: {problem}"
            name = rest
    if name in ("__node", "__name", "__ns"):
        return None
    if "*" in name:
        return "wildcards are not implemented in remap rules"
    return validate_topic_name(name)


def prefix_namespace(base: str | None, namespace: str | None) -> str | None:
    """Compose a pushed namespace with a node's own, as launch_ros does.

    Examples:
        >>> prefix_namespace("/robot", "arm")
        '/robot/arm'
        >>> prefix_namespace("/robot", "/abs")
        '/abs'
        >>> prefix_namespace(None, None) is None
        True
    """
    if base is None and namespace is None:
        return None
    if namespace is None:
        result = base or ""
        if base is None:
            return None
    elif not base or namespace.startswith("/"):
        result = namespace
    else:
        result = ("" if base == "/" else base) + "/" + namespace
    return result if result == "/" else result.rstrip("/")


def make_absolute(namespace: str | None) -> str | None:
    """Prefix ``/`` unless already absolute (``None`` stays ``None``)."""
    if namespace is None:
        return None
    return namespace if namespace.startswith("/") else "/" + namespace


def node_fqn(namespace: str, name: str) -> str:
    """Return the fully qualified name of a node."""
    return "/" + name if namespace in ("", "/") else namespace + "/" + name


def expand_topic_name(name: str, namespace: str, node_name: str) -> str:
    """Expand a topic or service name as rcl does before matching remap rules.

    Examples:
        >>> expand_topic_name("chatter", "/robot1", "talker")
        '/robot1/chatter'
        >>> expand_topic_name("~/status", "/", "talker"), expand_topic_name("/tf", "/ns", "x")
        ('/talker/status', '/tf')
    """
    base = "" if namespace in ("", "/") else namespace.rstrip("/")
    if name.startswith("/"):
        return name
    if name == "~" or name.startswith("~/"):
        return f"{base}/{node_name}{name[1:]}"
    return f"{base}/{name}"


def node_key_matches(key: str, fqn: str) -> bool:
    """Return whether a parameter file's node key applies to the node ``fqn``.

    As rclcpp matches them: the key gets a leading ``/``, ``/**`` stands for any number of
    tokens (none included) and ``/*`` for exactly one, and the whole name must match, so
    ``controller`` does not match ``/robot1/controller``.

    Examples:
        >>> node_key_matches("/**", "/robot1/amcl"), node_key_matches("amcl", "/amcl")
        (True, True)
        >>> node_key_matches("/*/amcl", "/robot1/amcl"), node_key_matches("amcl", "/r/amcl")
        (True, False)
    """
    if "*" not in key:  # the common case, and keys are many in a fleet
        return (key if key.startswith("/") else "/" + key) == fqn
    return _key_pattern(key).fullmatch(fqn) is not None


@functools.cache
def _key_pattern(key: str) -> re.Pattern[str]:
    absolute = key if key.startswith("/") else "/" + key
    pattern = ""
    for token in absolute.split("/")[1:]:
        if token == "**":
            pattern += r"(/\w+)*"
        elif token == "*":
            pattern += r"/\w+"
        else:
            pattern += "/" + re.escape(token)
    return re.compile(pattern or "/")
