"""Workers load YAML with libyaml: the same values and errors as PyYAML's pure loaders."""

from __future__ import annotations

import datetime
import io
from pathlib import Path
from typing import Any

import pytest
import yaml
from hypothesis import given, settings
from hypothesis import strategies as st

from launchverify.engine import CheckOptions, run_check
from launchverify.frontends.python import fast_yaml

pytestmark = pytest.mark.skipif(not yaml.__with_libyaml__, reason="PyYAML without libyaml")

FAST = fast_yaml.replacements()

DOCUMENTS = {
    "parameters": "controller_server:\n  ros__parameters:\n    use_sim_time: true\n"
                  "    rate: 20.0\n    plugins: [\"FollowPath\"]\n",
    "yaml 1.1 scalars": "a: yes\nb: off\nc: 012\nd: 0x1F\ne: 1:20\nf: .inf\ng: ~\nh: 1e3\n",
    "anchors and merges": "base: &b {x: 1, y: 2}\nderived:\n  <<: *b\n  y: 3\nlist: [*b, *b]\n",
    "tags": "a: !!str 12\nb: !!float 1\nc: !!binary aGVsbG8=\nd: 2001-12-14t21:59:43.10-05:00\n",
    "block scalars": "literal: |\n  line one\n  line two\nfolded: >-\n  folded\n  text\n",
    "quoted": "a: \"tab\\there \\u00e9\"\nb: 'it''s'\nc: \"\\x41\"\n",
    "empty": "",
    "comment only": "# nothing here\n",
    "unicode": "name: caf\u00e9\nemoji: \"\\U0001F916\"\n",
    "set and omap": "s: !!set {a, b}\no: !!omap [x: 1, y: 2]\n",
}

MALFORMED = {
    "unclosed flow": "a: [1, 2\n",
    "bad indentation": "a:\n  b: 1\n c: 2\n",
    "tab indentation": "a:\n\tb: 1\n",
    "undefined alias": "a: *nowhere\n",
    "duplicate anchor use before definition": "a: *x\nb: &x 1\n",
    "unknown tag": "a: !!python/object:os.system ls\n",
    "two documents for one": "a: 1\n---\nb: 2\n",
    "bad escape": "a: \"\\q\"\n",
}


# Documents libyaml reads otherwise than PyYAML: launch runs PyYAML's, so do we.
DISAGREEING = {
    "a tab after a colon": "key:\tvalue\n",
    "a tab in a flow sequence": "a: [1,\t2]\n",
    "an empty non-specific tag": "!",
    "a comment glued to a block scalar header": "|#\n",
}


def _outcome(function: Any, *arguments: Any) -> tuple[str, Any]:
    try:
        return "value", function(*arguments)
    except Exception as error:  # compare the kind and the words
        return type(error).__name__, str(error)


@pytest.mark.parametrize("name", sorted(DOCUMENTS))
def test_documents_give_the_same_values(name: str) -> None:
    text = DOCUMENTS[name]
    assert _outcome(FAST["safe_load"], text) == _outcome(yaml.safe_load, text)
    assert _outcome(FAST["full_load"], text) == _outcome(yaml.full_load, text)
    assert (_outcome(lambda t: list(FAST["safe_load_all"](t)), text)
            == _outcome(lambda t: list(yaml.safe_load_all(t)), text))


@pytest.mark.parametrize("name", sorted(MALFORMED))
def test_malformed_documents_give_the_same_errors(name: str) -> None:
    """libyaml's refusal is not what the user sees: the pure loader's own error is."""
    text = MALFORMED[name]
    expected = _outcome(yaml.safe_load, text)
    assert expected[0] != "value"
    assert _outcome(FAST["safe_load"], text) == expected


@pytest.mark.parametrize("name", sorted(DISAGREEING))
def test_where_the_parsers_disagree_pyyamls_reading_is_kept(name: str) -> None:
    text = DISAGREEING[name]
    expected = _outcome(yaml.safe_load, text)
    assert _outcome(lambda t: yaml.load(t, Loader=yaml.CSafeLoader), text) != expected
    assert _outcome(FAST["safe_load"], text) == expected
    assert _outcome(FAST["safe_load"], io.BytesIO(text.encode())) == _outcome(
        yaml.safe_load, io.BytesIO(text.encode()))


# What libyaml may read, though it holds characters where the parsers disagree: they
# are in comments.
IN_COMMENTS = {
    "a comment": "range: 0.0  # motion added ==> maxDistance_? default: 0.0 | none\n",
    "a comment after a quoted value": 'planners: "RRT,PRM"  # which? -> both\n',
    "a comment after a flow list": 'joints: ["j1", j2]  # order? as the URDF\n',
    "a comment line": "# it's the robot's `config`: 100% tested!\na: 1\n",
}
# Where a "#" is not a comment: read by PyYAML whatever it holds.
NOT_COMMENTS = {
    "inside a quoted value": 'a: "x # y?"\n',
    "inside a quoted value over two lines": 'a: "one\n  two # ?"\n',
    "inside single quotes with an escape": "a: 'it''s # ?\n  more'\n",
    "after an apostrophe in a plain value": "a: it's\nb: 'multi\n  line # ?'\n",
    "inside a block scalar": "a: |\n  x # ?\n",
    "after a carriage return": "a: 1 # c\rb: ?\n",
}


@pytest.mark.parametrize("name", sorted(IN_COMMENTS))
def test_what_comments_hold_does_not_matter(name: str) -> None:
    text = IN_COMMENTS[name]
    assert fast_yaml._alike(text)
    assert FAST["safe_load"](text) == yaml.safe_load(text)


@pytest.mark.parametrize("name", sorted(NOT_COMMENTS))
def test_a_hash_inside_a_value_is_not_taken_for_a_comment(name: str) -> None:
    assert not fast_yaml._alike(NOT_COMMENTS[name])


def test_streams_are_read_as_pyyaml_reads_them() -> None:
    text = DOCUMENTS["parameters"]
    expected = yaml.safe_load(text)
    assert FAST["safe_load"](io.StringIO(text)) == expected
    assert FAST["safe_load"](io.BytesIO(text.encode("utf-16"))) == expected  # its BOM read
    assert FAST["load"](io.StringIO(text), yaml.SafeLoader) == expected
    documents = "a: 1\n---\nb: 2\n"
    assert list(FAST["load_all"](io.StringIO(documents), Loader=yaml.SafeLoader)) == [
        {"a": 1}, {"b": 2}]


def test_a_stream_libyaml_refuses_is_read_again_from_its_start() -> None:
    stream = io.StringIO(MALFORMED["unclosed flow"])
    with pytest.raises(yaml.YAMLError) as fast:
        FAST["safe_load"](stream)
    with pytest.raises(yaml.YAMLError) as pure:
        yaml.safe_load(io.StringIO(MALFORMED["unclosed flow"]))
    assert str(fast.value) == str(pure.value)


class Endless(io.RawIOBase):
    """A stream that never ends (``/dev/zero``): PyYAML refuses its first piece.

    (Read to more than a megabyte, it says so: reading it whole would never end.)
    """

    def __init__(self) -> None:
        self.given = 0

    def readable(self) -> bool:
        return True

    def readinto(self, buffer: Any) -> int:
        self.given += len(buffer)
        if self.given > 1 << 20:
            raise RuntimeError("read without end")
        buffer[:] = bytes(len(buffer))
        return len(buffer)


def test_a_stream_is_read_only_so_far(monkeypatch: pytest.MonkeyPatch) -> None:
    """Beyond ``MAX_READ`` PyYAML reads on from where reading stopped (no endless read)."""
    monkeypatch.setattr(fast_yaml, "MAX_READ", 16)
    load = fast_yaml.replacements()["safe_load"]
    text = DOCUMENTS["parameters"]
    assert load(io.StringIO(text)) == yaml.safe_load(text)
    assert load(io.BytesIO(text.encode())) == yaml.safe_load(text)
    assert _outcome(load, Endless()) == _outcome(yaml.safe_load, Endless())


def test_pyyamls_own_errors_and_loaders_are_kept() -> None:
    with pytest.raises(TypeError) as fast:
        FAST["load"]("a: 1")
    with pytest.raises(TypeError) as pure:
        yaml.load("a: 1")  # type: ignore[call-arg]
    assert str(fast.value) == str(pure.value)

    class Shouting(yaml.SafeLoader):
        """A loader of the user's own: its constructors must run."""

    Shouting.add_constructor("tag:yaml.org,2002:str",
                             lambda loader, node: loader.construct_scalar(node).upper())
    assert FAST["load"]("a: b", Loader=Shouting) == {"A": "B"}


YAML_VALUES = st.recursive(
    st.none() | st.booleans() | st.integers(-2**70, 2**70)
    | st.floats(allow_nan=False) | st.text(max_size=20)
    | st.dates() | st.datetimes(timezones=st.none() | st.just(datetime.timezone.utc)),
    lambda inner: st.lists(inner, max_size=4) | st.dictionaries(st.text(max_size=8), inner,
                                                                max_size=4),
    max_leaves=12,
)


@settings(max_examples=150, deadline=None)
@given(YAML_VALUES, st.sampled_from([None, True, False]))
def test_dumped_values_read_back_the_same(value: object, flow: bool | None) -> None:
    text = yaml.safe_dump(value, default_flow_style=flow, allow_unicode=True)
    assert _outcome(FAST["safe_load"], text) == _outcome(yaml.safe_load, text)


@settings(max_examples=150, deadline=None)
@given(st.text(alphabet=st.sampled_from(list("ab:-[]{},&*!?|>%@'\"#\n\r \t012.~\\\u2028\ufeff")),
               max_size=30))
def test_any_text_gives_the_same_outcome(text: str) -> None:
    assert _outcome(FAST["safe_load"], text) == _outcome(yaml.safe_load, text)


def test_workers_load_yaml_with_libyaml(tmp_path: Path) -> None:
    """The zygote installs the loaders before any worker exists (fails without it)."""
    (tmp_path / "params.yaml").write_text("talker:\n  ros__parameters:\n    rate: 5\n")
    (tmp_path / "y.launch.py").write_text(
        "import os\n\nimport yaml\nfrom launch import LaunchDescription\n"
        "from launch_ros.actions import Node\n\n\ndef generate_launch_description():\n"
        "    with open(os.path.join(os.path.dirname(__file__), 'params.yaml')) as f:\n"
        "        rate = yaml.safe_load(f)['talker']['ros__parameters']['rate']\n"
        "    loader = yaml.safe_load_all.__module__.rsplit('.', 1)[-1]\n"
        "    return LaunchDescription([Node(package='demo_nodes_cpp', executable='talker',\n"
        "                                   name=f'{loader}_{rate}')])\n")
    report = run_check(CheckOptions(paths=[tmp_path], workspace=tmp_path))
    names = [node.name.describe() for graph in report.graphs for node in graph.nodes
             if node.name is not None]
    assert names == ["fast_yaml_5"]
