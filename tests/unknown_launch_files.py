"""Hypothesis strategies: Python launch files drawing values from a module, ``vendor``.

Each place of the launch API (``PLACES``) is a snippet reading ``vendor.v<N>`` and a
strategy for a valid concrete value there. A drawn file is checked twice
(``tests/test_metamorphic_unknowns.py``): with ``vendor`` absent, and with a stand-in
``vendor.py`` beside it that holds the drawn values.
"""

from __future__ import annotations

from dataclasses import dataclass

from hypothesis import strategies as st

_NAMES = st.text(alphabet="abcdefghij", min_size=1, max_size=6)

# snippet (``{n}``: the place's number; statements in generate_launch_description, which
# appends to ``out``), and the strategy of a valid value for ``vendor.v{n}`` (as source)
PLACES: dict[str, tuple[str, st.SearchStrategy[str]]] = {
    "argument default": (
        "out.append(DeclareLaunchArgument('a{n}', default_value=vendor.v{n}))",
        _NAMES.map(repr)),
    "choices": (
        "out.append(DeclareLaunchArgument('c{n}', choices=vendor.v{n}, default_value='a'))",
        st.lists(_NAMES, max_size=3).map(lambda names: repr(["a", *names]))),
    "appended choices": (
        "m{n} = vendor.v{n}\n    m{n}.append('a')\n"
        "    out.append(DeclareLaunchArgument('d{n}', choices=m{n}, default_value='a'))",
        st.lists(_NAMES, max_size=3).map(repr)),
    "comprehension choices": (
        "out.append(DeclareLaunchArgument('e{n}', choices=[c for c in vendor.v{n}] + ['a'],"
        " default_value='a'))",
        st.lists(_NAMES, max_size=3).map(repr)),
    "condition": (
        "out.append(Node(package='demo_nodes_cpp', executable='talker', name='k{n}',"
        " condition=IfCondition(vendor.v{n})))",
        st.sampled_from(["'true'", "'false'"])),
    "expression condition": (
        "out.append(Node(package='demo_nodes_cpp', executable='talker', name='p{n}',"
        " condition=IfCondition(PythonExpression([vendor.v{n}, ' == 1']))))",
        st.sampled_from(["'0'", "'1'"])),
    "node name": (
        "out.append(Node(package='demo_nodes_cpp', executable='talker', name=vendor.v{n}))",
        _NAMES.map(lambda name: repr(f"named_{{n}}_{name}"))),
    "namespace": (
        "out.append(Node(package='demo_nodes_cpp', executable='talker', name='s{n}',"
        " namespace=vendor.v{n}))",
        _NAMES.map(repr)),
    "joined package": (
        "out.append(Node(package=vendor.v{n} + '_cpp', executable='talker', name='j{n}'))",
        st.just("'demo_nodes'")),
    "package share": (
        "out.append(LogInfo(msg=FindPackageShare(vendor.v{n})))",
        st.just("'demo_nodes_cpp'")),
    "parameter": (
        "out.append(Node(package='demo_nodes_cpp', executable='talker', name='q{n}',"
        " parameters=[{{'p': vendor.v{n}}}]))",
        st.one_of(st.integers(-5, 5).map(repr), _NAMES.map(repr))),
    "remap": (
        "out.append(Node(package='demo_nodes_cpp', executable='talker', name='r{n}',"
        " remappings=[(vendor.v{n}, '/b')]))",
        _NAMES.map(lambda name: repr(f"/{name}"))),
    "include argument": (
        "out.append(IncludeLaunchDescription(PythonLaunchDescriptionSource(EMPTY),"
        " launch_arguments={{'x': vendor.v{n}}}.items()))",
        _NAMES.map(repr)),
    "opaque function": (
        "out.append(OpaqueFunction(function=lambda context: [LogInfo(msg=vendor.v{n})]))",
        _NAMES.map(repr)),
    "loop": (
        "for item in vendor.v{n}:\n        out.append(LogInfo(msg=item))",
        st.lists(_NAMES, max_size=3).map(repr)),
    "exception": (
        "try:\n        got = vendor.v{n}()\n    except KeyError:\n        got = 'none'\n"
        "    out.append(LogInfo(msg=got))",
        _NAMES.map(lambda name: f"lambda: {name!r}")),
}

HEADER = """\
import os

import vendor
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription, LogInfo
from launch.actions import OpaqueFunction
from launch.conditions import IfCondition
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import PythonExpression
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare

EMPTY = os.path.join(os.path.dirname(__file__), 'empty.launch.py')


def generate_launch_description():
    out = []
"""


@dataclass(frozen=True)
class Drawn:
    """A launch file and the stand-in module that gives its unknowns valid values."""

    launch_file: str
    stand_in: str


@st.composite
def launch_files(draw: st.DrawFn) -> Drawn:
    """Draw a launch file reading ``vendor`` at some places, and a stand-in for it."""
    chosen = draw(st.lists(st.sampled_from(sorted(PLACES)), min_size=1, max_size=5))
    body, values = [], []
    for n, place in enumerate(chosen):
        snippet, value = PLACES[place]
        body.append("    " + snippet.format(n=n) + f"  # {place}\n")
        values.append(f"v{n} = {draw(value).replace('{n}', str(n))}\n")
    return Drawn(HEADER + "".join(body) + "    return LaunchDescription(out)\n",
                 "".join(values))
