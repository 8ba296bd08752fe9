"""Python findings point at the expression that causes them (line and column)."""

from __future__ import annotations

from pathlib import Path

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from launchverify.engine import CheckOptions, run_check
from launchverify.frontends.python.locate import CallLocator
from launchverify.rule import IN_CALL
from launchverify.span import Span

TREE = Path(__file__).resolve().parent.parent / "corpus" / "python" / "finding_locations"


def test_findings_point_at_the_expression_and_name_the_call() -> None:
    report = run_check(CheckOptions(paths=[TREE], workspace=TREE))
    found = {(f.code, f.span.line, f.span.column, f.span.end_column): f for f in report.findings}
    # LaunchConfiguration('frame') in the Node's parameters dict, not `Node(` on line 21
    read = found[("LV201", 27, 29, 57)]
    assert [(r.message, r.span.line, r.span.column) for r in read.related] == [
        (IN_CALL, 21, 9)]
    # the key of a dict bound to a name and passed as launch_arguments=robot_arguments.items()
    assert ("LV204", 17, 9, 22) in found
    # the first item of a pair in a list of pairs
    pair = found[("LV204", 38, 18, 28)]
    assert [(r.message, r.span.line) for r in pair.related] == [(IN_CALL, 34)]
    assert len(report.findings) == 3


def test_a_suppression_on_the_call_still_covers_a_finding_inside_it(tmp_path: Path) -> None:
    launch = tmp_path / "talker.launch.py"
    launch.write_text(
        "from launch import LaunchDescription\n"
        "from launch.actions import DeclareLaunchArgument\n"
        "from launch.substitutions import LaunchConfiguration\n"
        "from launch_ros.actions import Node\n\n\n"
        "def generate_launch_description():\n"
        "    return LaunchDescription([\n"
        "        DeclareLaunchArgument('name', default_value='talker'),\n"
        "        Node(package='demo_nodes_cpp', executable='talker',"
        " name=LaunchConfiguration('name'),  # launchverify: ignore[LV201]\n"
        "             parameters=[{'rate': LaunchConfiguration('rate')}]),\n"
        "    ])\n")
    report = run_check(CheckOptions(paths=[launch], workspace=tmp_path))
    assert not [f for f in report.findings if f.code in ("LV201", "LV004")]


def test_parameters_point_at_their_list_item_and_dict_key(tmp_path: Path) -> None:
    launch = tmp_path / "params.launch.py"
    launch.write_text(
        "import os\n"
        "from launch import LaunchDescription\n"
        "from launch_ros.actions import Node\n\n\n"
        "def generate_launch_description():\n"
        "    here = os.path.dirname(__file__)\n"
        "    return LaunchDescription([\n"
        "        Node(package='demo_nodes_cpp', executable='talker', name='talker',\n"
        "             parameters=[\n"
        "                 os.path.join(here, 'missing.yaml'),\n"
        "                 {'rate': 10},\n"
        "                 {'rate': 'fast'},\n"
        "             ]),\n"
        "    ])\n")
    report = run_check(CheckOptions(paths=[launch], workspace=tmp_path))
    where = {f.code: (f.span.line, f.span.column) for f in report.findings}
    assert where["LV302"] == (11, 18)  # the path item, not `Node(` on line 9
    assert where["LV403"] == (13, 19)  # the key whose value disagrees


@settings(max_examples=40, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(keys=st.lists(st.from_regex(r"[a-z_][a-z0-9_/.]{0,12}", fullmatch=True),
                     min_size=1, max_size=6, unique=True),
       indent=st.integers(min_value=0, max_value=12), as_pairs=st.booleans())
def test_located_keys_are_where_the_text_says(tmp_path: Path, keys: list[str], indent: int,
                                               as_pairs: bool) -> None:
    """Whatever the layout, each key's span covers exactly its quoted text."""
    pad = " " * (4 + indent)  # inside a function, as launch files write it
    items = ",\n".join(f"{pad}    ('{k}', '1')" if as_pairs else f"{pad}    '{k}': '1'"
                       for k in keys)
    opening, closing = ("[", "]") if as_pairs else ("{", "}")
    source = (f"def g():\n{pad}f(\n{pad}  launch_arguments={opening}\n{items}\n"
              f"{pad}  {closing})\n")
    file = tmp_path / "keys.launch.py"
    file.write_text(source)
    lines = source.splitlines()
    found = CallLocator().keyword_keys(Span(file, 2, len(pad) + 1), "launch_arguments")
    assert set(found) == set(keys)
    for key, span in found.items():
        assert span.end_column is not None
        assert lines[span.line - 1][span.column - 1:span.end_column - 1] == f"'{key}'"


def test_remappings_point_at_their_tuple(tmp_path: Path) -> None:
    """Each rule of ``remappings=[...]`` is at its pair, as XML's ``<remap>`` at its tag."""
    launch = tmp_path / "remaps.launch.py"
    launch.write_text(
        "from launch import LaunchDescription\n"
        "from launch_ros.actions import Node\n\n\n"
        "def generate_launch_description():\n"
        "    rules = [('scan', 'a'), ('/scan', 'b')]\n"
        "    return LaunchDescription([\n"
        "        Node(package='demo_nodes_cpp', executable='listener', name='a',\n"
        "             remappings=[('cmd_vel', 'x'),\n"
        "                         ('cmd_vel', 'y')]),\n"
        "        Node(package='demo_nodes_cpp', executable='listener', name='b',\n"
        "             remappings=rules),\n"
        "        Node(package='demo_nodes_cpp', executable='listener', name='c',\n"
        "             remappings=list(reversed(rules))),\n"
        "    ])\n")
    report = run_check(CheckOptions(paths=[launch], workspace=tmp_path))
    found = sorted((f.span.line, f.span.column, f.span.end_column,
                    [(r.message, r.span.line) for r in f.related])
                   for f in report.findings if f.code == "LV103")
    assert found == [
        (6, 29, 43, [("/scan -> /a wins", 6), (IN_CALL, 11)]),  # in the list bound to rules
        (10, 26, 42, [("/cmd_vel -> /x wins", 9), (IN_CALL, 8)]),  # the tuple in the call
        (13, 9, 47, [("/scan -> /b wins", 13)]),  # built at run time: the call (to 14:47)
    ]


def test_a_suppression_on_the_call_still_covers_a_remap_inside_it(tmp_path: Path) -> None:
    launch = tmp_path / "remaps.launch.py"
    launch.write_text(
        "from launch import LaunchDescription\n"
        "from launch_ros.actions import Node\n\n\n"
        "def generate_launch_description():\n"
        "    return LaunchDescription([\n"
        "        Node(package='demo_nodes_cpp', executable='listener',"
        "  # launchverify: ignore[LV103]\n"
        "             remappings=[('cmd_vel', 'x'), ('cmd_vel', 'y')]),\n"
        "    ])\n")
    report = run_check(CheckOptions(paths=[launch], workspace=tmp_path))
    assert not [f for f in report.findings if f.code in ("LV103", "LV004")]
