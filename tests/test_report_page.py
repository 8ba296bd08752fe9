"""The report's page: one legend for every picture, cards that explain, whole names.

And one name per node, places that tell files apart, a weight that follows the content.
"""

from __future__ import annotations

import io
import json
import re
from pathlib import Path

import pytest

from launchverify.cli import main
from launchverify.engine import CheckOptions, run_check
from launchverify.render import links
from launchverify.render.flow_svg import _fit
from launchverify.render.graph_out import GraphView
from launchverify.render.html_report import render_html
from launchverify.render.html_text import distinct_tails
from launchverify.render.system_html import roots_to_show

FLEET = Path(__file__).resolve().parent.parent / "corpus" / "realistic" / "fleet_report"


@pytest.fixture(scope="module")
def page(tmp_path_factory: pytest.TempPathFactory) -> str:
    out = tmp_path_factory.mktemp("report") / "report.html"
    links.project_urls.cache_clear()
    main(["report", str(FLEET), "-o", str(out)])
    return out.read_text()


def test_each_legend_is_written_once_for_every_system(page: str) -> None:
    assert page.count('class="flow-section"') > 1  # several computation graphs
    assert page.count('<ul class="legend flow-legend">') == 1
    assert page.count('<ul class="legend">') == 1


def test_a_finding_card_says_why_and_how_to_fix_with_the_docs(page: str) -> None:
    cards = page.split('<article class="finding')[1:]
    assert cards and all('<details class="part about">' in card for card in cards)
    assert "<b>Why it matters:</b>" in cards[0] and "<b>How to fix it:</b>" in cards[0]
    base = links.documentation_base()
    if base is not None:  # from the installed package's metadata
        assert f'href="{base}#lv' in page


def test_a_long_name_keeps_both_ends() -> None:
    components = _fit("/controller_manager/list_hardware_components", 150, 6.0)
    interfaces = _fit("/controller_manager/list_hardware_interfaces", 150, 6.0)
    assert components != interfaces and len(components) <= 25
    assert components.endswith("components") and interfaces.endswith("interfaces")
    assert _fit("/scan", 150, 6.0) == "/scan"


# ------------------------------------------------------------------ one name per node

SERVER = """#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"

class Server : public rclcpp::Node
{
public:
  Server()
  : Node("add_two_ints_server")
  {
    pub_ = create_publisher<std_msgs::msg::String>("status", 10);
  }

private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Server>());
  return 0;
}
"""


def package(folder: Path, name: str, executables: dict[str, str] | None = None) -> Path:
    """Write a package: its manifest, and C++ sources built into ``executables``."""
    folder.mkdir(parents=True)
    (folder / "package.xml").write_text(
        f'<?xml version="1.0"?>\n<package format="3"><name>{name}</name>'
        "<version>0.1.0</version><description>a fixture</description>"
        '<maintainer email="dev@example.com">dev</maintainer><license>MIT</license>'
        "<buildtool_depend>ament_cmake</buildtool_depend><depend>rclcpp</depend>"
        "</package>\n")
    if executables:
        (folder / "src").mkdir()
        lines = [f"cmake_minimum_required(VERSION 3.8)\nproject({name})"]
        for executable, source in executables.items():
            (folder / "src" / f"{executable}.cpp").write_text(source)
            lines.append(f"add_executable({executable} src/{executable}.cpp)\n"
                         f"install(TARGETS {executable} DESTINATION lib/${{PROJECT_NAME}})")
        (folder / "CMakeLists.txt").write_text("\n".join([*lines, "ament_package()"]) + "\n")
    return folder


def report_of(tree: Path, out: Path) -> str:
    links.project_urls.cache_clear()
    main(["report", str(tree), "--workspace", str(tree), "-o", str(out)])
    return out.read_text(encoding="utf-8")


def test_a_node_has_one_name_across_the_page(tmp_path: Path) -> None:
    demo = package(tmp_path / "ws" / "src" / "svc_demo", "svc_demo", {"server": SERVER})
    (demo / "launch").mkdir()
    (demo / "launch" / "svc.launch.xml").write_text(
        '<launch>\n  <node pkg="svc_demo" exec="server"/>\n'
        '  <node pkg="nowhere_pkg" exec="mystery"/>\n</launch>\n')
    page = report_of(tmp_path / "ws", tmp_path / "report.html")
    picture = page[page.index('<svg class="system"'):]
    picture = picture[:picture.index("</svg>")]
    flow = page[page.index('<svg class="flow-svg"'):]
    flow = flow[:flow.index("</svg>")]
    # the launch gives no name, the code does: the picture, the graph and the table agree
    assert 'data-fqn="/add_two_ints_server"' in picture
    assert 'data-fqn="/add_two_ints_server"' in flow
    cell = re.search(r"<td><code>/add_two_ints_server</code>.*?</td>", page, re.S)
    assert cell is not None and cell.group(0).endswith(
        "<small>named by its sources (the launch gives no name)</small></td>")
    assert "unnamed server" not in page
    # nothing knows the other's name: one spelling, wherever it is named
    unnamed = 'data-fqn="&lt;unnamed mystery&gt;"><title>&lt;unnamed mystery&gt;\n'
    assert unnamed in picture and unnamed in flow
    assert "<td><code>&lt;unnamed mystery&gt;</code>" in page


# ------------------------------------------------------------------ the index's places


def test_the_index_tells_files_of_one_name_apart(tmp_path: Path) -> None:
    duplicate = ('<launch>\n  <node pkg="demo_nodes_cpp" exec="talker" name="talker"/>\n'
                 '  <node pkg="demo_nodes_py" exec="talker" name="talker"/>\n</launch>\n')
    for name in ("example_1", "example_5"):
        test = package(tmp_path / "ws" / "src" / name, name) / "test"
        test.mkdir()
        (test / "test_joint_trajectory_controller.launch.xml").write_text(duplicate)
    page = report_of(tmp_path / "ws", tmp_path / "report.html")
    index = page[page.index('<section id="by-rule">'):]
    index = index[:index.index("</section>")]
    places = re.findall(r'<td class="where"><a href="#finding-\d+" title="([^"]*)">'
                        r'<span class="loc">([^<]*)</span>', index)
    assert len(places) == 2
    shown = {text for _, text in places}
    assert shown == {"\u2026/example_1/test/test_joint_trajectory_controller.launch.xml:3",
                     "\u2026/example_5/test/test_joint_trajectory_controller.launch.xml:3"}
    for full, text in places:  # the whole path on hover
        assert full.endswith(text.removeprefix("\u2026/")) and "src/" in full


def test_distinct_tails() -> None:
    tails = distinct_tails(["src/a/launch/robot.launch.xml", "src/b/launch/robot.launch.xml",
                            "src/a/launch/only.launch.xml", "robot.launch.xml",
                            "src\\c\\sim\\robot.launch.xml"])
    assert tails == {"src/a/launch/robot.launch.xml": "\u2026/a/launch/robot.launch.xml",
                     "src/b/launch/robot.launch.xml": "\u2026/b/launch/robot.launch.xml",
                     "src/a/launch/only.launch.xml": "only.launch.xml",
                     "robot.launch.xml": "robot.launch.xml",  # all of the others' ending
                     "src\\c\\sim\\robot.launch.xml": "\u2026/sim/robot.launch.xml"}


# ------------------------------------------------------------------ the page's weight

STACK = [f"server_{i}" for i in range(12)]


def stack_workspace(folder: Path, roots: int) -> Path:
    """Write ``roots`` launch files that each bring up one shared stack, plus a node.

    Twelve servers with twenty parameters each from one file: what most roots of a
    workspace do (every nav2 example starts the same bring-up).
    """
    bringup = package(folder / "src" / "stack_bringup", "stack_bringup")
    (bringup / "launch").mkdir()
    (bringup / "config").mkdir()
    (bringup / "config" / "params.yaml").write_text("".join(
        f"{node}:\n  ros__parameters:\n"
        + "".join(f"    option_{j}: {j * 1.5}\n" for j in range(20)) for node in STACK))
    nodes = "".join(
        f'  <node pkg="stack_bringup" exec="server" name="{node}">\n'
        '    <param from="$(find-pkg-share stack_bringup)/config/params.yaml"/>\n'
        f'    <remap from="cmd" to="/{node}/cmd"/>\n  </node>\n' for node in STACK)
    (bringup / "launch" / "stack.launch.xml").write_text(f"<launch>\n{nodes}</launch>\n")
    for number in range(1, roots + 1):
        (bringup / "launch" / f"demo_{number}.launch.xml").write_text(
            '<launch>\n  <include file="$(find-pkg-share stack_bringup)/launch/'
            'stack.launch.xml"/>\n'
            f'  <node pkg="stack_bringup" exec="client" name="demo_{number}"/>\n</launch>\n')
    return folder


def weigh(folder: Path) -> tuple[str, float]:
    """Return the report of a workspace and its size relative to what it shows.

    What it shows is measured as ``launchverify graph`` would list it: the JSON of
    every distinct node entry of every system (with its parameters, effective values
    and their sources, remaps, conditions), each counted once however many systems
    start it. A ratio, not a timing: the same input always weighs the same.
    """
    with pytest.MonkeyPatch.context() as patch:
        patch.delenv("AMENT_PREFIX_PATH", raising=False)
        patch.chdir(folder)
        report = run_check(CheckOptions(paths=[folder / "src"], workspace=folder))
        out = io.StringIO()
        render_html(report, out)
        entries = {json.dumps(entry, sort_keys=True, default=str)
                   for graph in roots_to_show(report)
                   for entry in GraphView(graph, symbolic=False).document()["nodes"]}
    page = out.getvalue()
    return page, len(page.encode("utf-8")) / sum(len(e.encode("utf-8")) for e in entries)


def test_the_page_weighs_what_it_shows(tmp_path: Path) -> None:
    # one root: the markup around the content (1.86 when each parameter named its file)
    page, ratio = weigh(stack_workspace(tmp_path / "one", 1))
    assert page.count('class="system-section"') == 1
    assert ratio < 1.7, ratio
    # eight roots of the same stack show little more: what they repeat is written once
    # and referred to (11.4 when every root wrote it all again; 3.2 with the pictures,
    # which each root draws)
    page, ratio = weigh(stack_workspace(tmp_path / "eight", 8))
    assert page.count('class="system-section"') == 8
    assert ratio < 4.0, ratio


def test_a_repeated_block_leads_to_its_first_copy(tmp_path: Path) -> None:
    page, _ = weigh(stack_workspace(tmp_path / "ws", 3))
    references = re.findall(r'class="same" data-same="([^"]+)">[^<]*<a href="#([^"]+)">', page)
    assert len(references) >= 2 * len(STACK)  # each server's row in roots 2 and 3
    for ident, href in references:
        written = page.find(f'id="{ident}"')
        assert 0 <= written < page.index(f'data-same="{ident}"')  # written before
        assert f'id="{href}"' in page
    # the first root's rows are whole: every parameter with its value and line
    system = page[page.index('id="system-1"'):page.index('id="system-2"')]
    assert system.count("<code>option_19</code> = <code>28.5</code>") == len(STACK)
