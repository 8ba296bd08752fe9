"""ROS 2 name rules (rmw/rcl), namespace composition (launch_ros) and launch's truth rules."""

from __future__ import annotations

import math
import re

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from launchverify.models.booleans import (
    InvalidBoolean,
    bool_text,
    condition_truth,
    launch_equals,
    typed_truth,
)
from launchverify.models.ros_names import (
    NAMESPACE_MAX,
    NODE_NAME_MAX,
    make_absolute,
    node_fqn,
    prefix_namespace,
    validate_namespace,
    validate_node_name,
    validate_remap_name,
    validate_topic_name,
)

# --------------------------------------------------------------------------- node names


@pytest.mark.parametrize(
    "name", ["talker", "_hidden", "a1", "A_b_C", "x" * NODE_NAME_MAX, "_1"]
)
def test_valid_node_names(name: str) -> None:
    assert validate_node_name(name) is None


@pytest.mark.parametrize(
    ("name", "fragment"),
    [
        ("", "empty"),
        ("1talker", "start with a number"),
        ("9", "start with a number"),
        ("my-node", "other than alphanumerics"),
        ("my node", "other than alphanumerics"),
        ("/talker", "other than alphanumerics"),
        ("ns/talker", "other than alphanumerics"),
        ("~talker", "other than alphanumerics"),
        ("tälker", "other than alphanumerics"),
        ("talker\n", "other than alphanumerics"),
        ("x" * (NODE_NAME_MAX + 1), f"longer than {NODE_NAME_MAX}"),
    ],
)
def test_invalid_node_names(name: str, fragment: str) -> None:
    reason = validate_node_name(name)
    assert reason is not None
    assert fragment in reason


def test_node_name_max_is_255() -> None:
    assert NODE_NAME_MAX == 255


@given(st.from_regex(r"[A-Za-z_][A-Za-z0-9_]{0,40}", fullmatch=True))
def test_generated_node_names_are_valid(name: str) -> None:
    assert validate_node_name(name) is None


@given(st.text(max_size=12))
def test_node_name_rule(name: str) -> None:
    expected = bool(re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", name)) and len(name) <= 255
    assert (validate_node_name(name) is None) == expected


# --------------------------------------------------------------------------- namespaces


@pytest.mark.parametrize(
    "namespace", ["/", "/robot", "/robot/arm", "/_a/b_1", "/" + "a" * (NAMESPACE_MAX - 1)]
)
def test_valid_namespaces(namespace: str) -> None:
    assert validate_namespace(namespace) is None


@pytest.mark.parametrize(
    ("namespace", "fragment"),
    [
        ("", "empty"),
        ("robot", "absolute"),
        ("robot/", "absolute"),
        ("/robot/", "end with a '/'"),
        ("//", "end with a '/'"),
        ("/a//b", "repeated '/'"),
        ("/1robot", "starts with a number"),
        ("/robot/2arm", "starts with a number"),
        ("/robot-1", "other than alphanumerics"),
        ("/~", "other than alphanumerics"),
        ("/{ns}", "other than alphanumerics"),
        ("/a b", "other than alphanumerics"),
        ("/" + "a" * NAMESPACE_MAX, f"longer than {NAMESPACE_MAX}"),
    ],
)
def test_invalid_namespaces(namespace: str, fragment: str) -> None:
    reason = validate_namespace(namespace)
    assert reason is not None
    assert fragment in reason


def _namespace_reference(namespace: str) -> bool:
    """rmw_validate_namespace: '/' or an absolute full name of [A-Za-z0-9_] tokens."""
    if namespace == "/":
        return True
    if not namespace.startswith("/") or namespace.endswith("/") or "//" in namespace:
        return False
    tokens = namespace[1:].split("/")
    return len(namespace) <= NAMESPACE_MAX and all(
        re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", token) for token in tokens
    )


@given(st.text(alphabet="/ab1_-~", max_size=10))
def test_namespace_rule(namespace: str) -> None:
    assert (validate_namespace(namespace) is None) == _namespace_reference(namespace)


# --------------------------------------------------------------------------- topics


@pytest.mark.parametrize(
    "name",
    ["chatter", "/chatter", "ns/chatter", "/ns/chatter", "~", "~/private", "_a", "a/_b",
     "{node}/cmd", "/{ns}/x_{node}", "a1/b2"],
)
def test_valid_topic_names(name: str) -> None:
    assert validate_topic_name(name) is None


@pytest.mark.parametrize(
    ("name", "fragment"),
    [
        ("", "empty"),
        ("1chatter", "start with a number"),
        ("a/1b", "token that starts with a number"),
        ("/1b", "token that starts with a number"),
        ("a/", "end with a forward slash"),
        ("/", "end with a forward slash"),
        ("~/", "end with a forward slash"),
        ("a~", "'~' must only be the first character"),
        ("/~/a", "'~' must only be the first character"),
        ("~a", "'~' must be followed by '/'"),
        ("a//b", "repeated '/'"),
        ("{a{b}}", "nested"),
        ("{a", "unbalanced '{'"),
        ("a}", "unbalanced '}'"),
        ("{a/b}", "'/' is not allowed inside a substitution"),
        ("{1a}", "must not start with a number"),
        ("chat-ter", "other than alphanumerics"),
        ("chat ter", "other than alphanumerics"),
        ("a\n", "other than alphanumerics"),
    ],
)
def test_invalid_topic_names(name: str, fragment: str) -> None:
    reason = validate_topic_name(name)
    assert reason is not None
    assert fragment in reason


def _topic_reference(name: str) -> bool:
    """rcl_validate_topic_name, restated (with `~` followed by `/` as its message says)."""
    if not name or name[0].isdigit() or name.endswith("/"):
        return False
    in_brace = False
    for index, char in enumerate(name):
        if char.isascii() and char.isalnum():
            if char.isdigit() and in_brace and name[index - 1] == "{":
                return False
        elif char == "_":
            continue
        elif char == "/":
            if in_brace:
                return False
        elif char == "~":
            if index != 0:
                return False
        elif char == "{":
            if in_brace:
                return False
            in_brace = True
        elif char == "}":
            if not in_brace:
                return False
            in_brace = False
        else:
            return False
    if in_brace:
        return False
    if name.startswith("~") and len(name) > 1 and name[1] != "/":
        return False
    return not any(token[:1].isdigit() for token in name.split("/")[1:])


@given(st.text(alphabet="ab1_/~{}-", max_size=10))
@settings(max_examples=300)
def test_topic_rule(name: str) -> None:
    # rcl leaves repeated slashes to full-name validation; the model refuses them at once
    expected = _topic_reference(name) and "//" not in name
    assert (validate_topic_name(name) is None) == expected


@pytest.mark.parametrize(
    "name",
    ["chatter", "/ns/chatter", "rostopic://chatter", "rosservice://~/srv", "__node", "__name",
     "__ns", "rostopic://__node", "__other"],
)
def test_valid_remap_names(name: str) -> None:
    assert validate_remap_name(name) is None


@pytest.mark.parametrize(
    ("name", "fragment"),
    [("a*", "wildcards"), ("/a/**", "wildcards"), ("rostopic://1a", "number"),
     ("rosservice://a/", "forward slash"), ("", "empty"), ("rostopic://", "empty")],
)
def test_invalid_remap_names(name: str, fragment: str) -> None:
    reason = validate_remap_name(name)
    assert reason is not None
    assert fragment in reason


# --------------------------------------------------------------------------- composition


@pytest.mark.parametrize(
    ("base", "namespace", "expected"),
    [
        (None, None, None),
        (None, "foo", "foo"),
        ("/robot", None, "/robot"),
        ("/robot", "foo", "/robot/foo"),
        ("/robot", "/foo", "/foo"),
        ("/", "foo", "/foo"),
        ("/robot", "", "/robot"),
        ("/robot", "foo/", "/robot/foo"),
        ("/robot/", None, "/robot"),
        (None, "foo/", "foo"),
        ("/robot", "/foo/", "/foo"),
        ("/robot", "a/b", "/robot/a/b"),
        ("robot", "foo", "robot/foo"),
        ("/", "/", "/"),
        ("/", None, "/"),
        (None, "/", "/"),
        ("/", "", "/"),
        ("", "foo", "foo"),
        ("", None, ""),
        (None, "", ""),
    ],
)
def test_prefix_namespace(base: str | None, namespace: str | None, expected: str | None) -> None:
    assert prefix_namespace(base, namespace) == expected


def _prefix_reference(base: str | None, namespace: str | None) -> str | None:
    """launch_ros.utilities.prefix_namespace, restated from its documentation."""
    if base is None and namespace is None:
        return None
    if namespace is None:
        combined = base
    elif not base or namespace.startswith("/"):
        combined = namespace
    else:
        combined = ("" if base == "/" else base) + "/" + namespace
    assert combined is not None
    return combined if combined == "/" else combined.rstrip("/")


NAMESPACE_PARTS = st.none() | st.text(alphabet="/ab", max_size=6)


@given(NAMESPACE_PARTS, NAMESPACE_PARTS)
@settings(max_examples=300)
def test_prefix_namespace_matches_launch_ros(base: str | None, namespace: str | None) -> None:
    assert prefix_namespace(base, namespace) == _prefix_reference(base, namespace)


VALID_NAMESPACE = st.lists(st.from_regex(r"[a-z_][a-z0-9_]{0,4}", fullmatch=True),
                           max_size=3).map(lambda tokens: "/" + "/".join(tokens))
RELATIVE = st.lists(st.from_regex(r"[a-z_][a-z0-9_]{0,4}", fullmatch=True),
                    min_size=1, max_size=3).map("/".join)


@given(VALID_NAMESPACE, RELATIVE)
def test_prefixing_valid_namespaces_stays_valid(base: str, relative: str) -> None:
    combined = prefix_namespace(base, relative)
    assert combined is not None
    assert validate_namespace(combined) is None
    assert combined.endswith("/" + relative)
    assert prefix_namespace(base, "/" + relative) == "/" + relative


@pytest.mark.parametrize(
    ("namespace", "expected"),
    [(None, None), ("a", "/a"), ("/a", "/a"), ("", "/"), ("a/b", "/a/b"), ("/", "/")],
)
def test_make_absolute(namespace: str | None, expected: str | None) -> None:
    assert make_absolute(namespace) == expected


@pytest.mark.parametrize(
    ("namespace", "name", "expected"),
    [("", "talker", "/talker"), ("/", "talker", "/talker"), ("/ns", "talker", "/ns/talker"),
     ("/a/b", "c", "/a/b/c")],
)
def test_node_fqn(namespace: str, name: str, expected: str) -> None:
    assert node_fqn(namespace, name) == expected


# --------------------------------------------------------------------------- conditions


@pytest.mark.parametrize(
    ("value", "expected"),
    [("true", True), ("True", True), ("TRUE", True), (" true ", True), ("1", True),
     ("\ttrue\n", True), ("false", False), ("False", False), ("FALSE", False), ("0", False),
     ("  0\n", False)],
)
def test_condition_truth(value: str, expected: bool) -> None:
    assert condition_truth(value) is expected


@pytest.mark.parametrize(
    "value", ["yes", "no", "on", "off", "", " ", "2", "01", "1.0", "tru", "t", "y", "none",
              "'true'", "true false"],
)
def test_condition_truth_refuses(value: str) -> None:
    with pytest.raises(InvalidBoolean) as caught:
        condition_truth(value)
    assert "expected one of [true, 1, false, 0]" in str(caught.value)
    assert repr(value) in str(caught.value)


def test_invalid_boolean_is_a_value_error() -> None:
    assert issubclass(InvalidBoolean, ValueError)


def _case_variants(word: str) -> st.SearchStrategy[str]:
    return st.lists(st.booleans(), min_size=len(word), max_size=len(word)).map(
        lambda flags: "".join(c.upper() if f else c for c, f in zip(word, flags, strict=True))
    )


WHITESPACE = st.text(alphabet=" \t\n", max_size=3)


@given(WHITESPACE, st.sampled_from(["true", "1", "false", "0"]).flatmap(_case_variants),
       WHITESPACE)
def test_condition_truth_ignores_case_and_surrounding_space(
    before: str, word: str, after: str
) -> None:
    assert condition_truth(before + word + after) is (word.lower() in ("true", "1"))


@given(st.text(max_size=8))
def test_condition_truth_accepts_exactly_four_words(value: str) -> None:
    word = value.strip().lower()
    if word in ("true", "1", "false", "0"):
        assert condition_truth(value) is (word in ("true", "1"))
    else:
        with pytest.raises(InvalidBoolean):
            condition_truth(value)


# --------------------------------------------------------------------------- typed truth


@pytest.mark.parametrize(
    ("value", "expected"),
    [("1", True), ("0", False), ("true", True), ("True", True), ("TRUE", True),
     ("false", False), ("False", False), ("FALSE", False), ("yes", True), ("Yes", True),
     ("YES", True), ("no", False), ("No", False), ("on", True), ("On", True), ("ON", True),
     ("off", False), ("Off", False), ("OFF", False)],
)
def test_typed_truth(value: str, expected: bool) -> None:
    assert typed_truth(value) is expected


@pytest.mark.parametrize(
    "value", ["y", "n", "Y", "N", "tRue", "fAlse", "yES", "", "2", "01", "1.0", "null", "~",
              "'true'", "[true]", "{a: 1}", "[1", "maybe"],
)
def test_typed_truth_refuses(value: str) -> None:
    with pytest.raises(InvalidBoolean, match="cannot convert"):
        typed_truth(value)


@given(st.text(max_size=10))
def test_typed_truth_raises_only_invalid_boolean(value: str) -> None:
    try:
        result = typed_truth(value)
    except InvalidBoolean:
        return
    assert isinstance(result, bool)


def test_bool_text() -> None:
    assert (bool_text(True), bool_text(False)) == ("true", "false")


# --------------------------------------------------------------------------- equals


@pytest.mark.parametrize(
    ("left", "right", "expected"),
    [
        # booleans compare as booleans
        ("True", "1", True),
        ("true", "TRUE", True),
        ("0", "false", True),
        ("False", "0", True),
        ("true", "false", False),
        ("1", "false", False),
        # numbers compare as numbers, with isclose
        ("1.0", "1", True),
        ("1e0", "1", True),
        ("0", "0.0", True),
        ("10", "010", True),
        ("2.5", "2.50", True),
        ("0.30000000000000004", "0.3", True),
        ("1", "2", False),
        ("inf", "inf", True),
        ("nan", "nan", False),
        # everything else compares as exact text
        ("a", "a", True),
        ("a", "A", False),
        ("sim", "sim ", False),
        ("yes", "true", False),
        ("", "", True),
        ("", "0", False),
        ("/ns", "/ns", True),
    ],
)
def test_launch_equals(left: str, right: str, expected: bool) -> None:
    assert launch_equals(left, right) is expected
    assert launch_equals(right, left) is expected


@given(st.text(max_size=8), st.text(max_size=8))
def test_launch_equals_is_symmetric(left: str, right: str) -> None:
    assert launch_equals(left, right) == launch_equals(right, left)


def _is_nan(text: str) -> bool:
    try:
        return math.isnan(float(text))
    except ValueError:
        return False


@given(st.one_of(st.text(max_size=8), st.floats().map(str), st.integers().map(str)))
def test_launch_equals_is_reflexive_except_nan(value: str) -> None:
    assert launch_equals(value, value) is not _is_nan(value)


def test_a_name_unknown_here_is_shown_once_under_the_root_namespace() -> None:
    """``/`` and a name from the environment: ``/$(env ROBOT)``, not ``//$(env ROBOT)``."""
    from launchverify.ir.subst import EnvVar, Text
    from launchverify.ir.symbolic import NsPrefix

    assert NsPrefix(Text("/"), EnvVar(Text("ROBOT"))).describe() == "/$(env ROBOT)"
    assert NsPrefix(Text("/fleet"), EnvVar(Text("ROBOT"))).describe() == "/fleet/$(env ROBOT)"
