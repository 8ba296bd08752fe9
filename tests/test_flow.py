"""The report's computation graph: model, layout and picture, on a 201-node fleet with sources.

``flow_workspace.write_workspace`` generates the fleet (9 robots of 22 nodes and three
fleet nodes, C++ and Python sources); small hand-made graphs test the layout's rules.
"""

from __future__ import annotations

import io
import os
import re
import subprocess
import sys
import time
from pathlib import Path

import pytest
from flow_workspace import NODES_PER_ROBOT, write_workspace

from launchverify.cli import main
from launchverify.engine import CheckOptions, Report, run_check
from launchverify.render import flow_model
from launchverify.render.flow_layout import MAX_ROWS, FlowLayout, layout
from launchverify.render.flow_model import FlowEdge, FlowGraph, FlowNode, FlowTopic, build_flow
from launchverify.render.flow_svg import render_flow
from launchverify.render.html_report import render_html
from launchverify.render.system_html import roots_to_show
from launchverify.render.system_model import build_model
from launchverify.topology.compose import Composer, WorkspaceInterfaces
from launchverify.workspace.packages import PackageIndex

CORPUS = Path(__file__).resolve().parent.parent / "corpus"
WIRING = CORPUS / "wiring" / "unused_remap"
ROBOTS = 9


@pytest.fixture(autouse=True)
def _no_ros(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)


@pytest.fixture(scope="module")
def fleet(tmp_path_factory: pytest.TempPathFactory) -> tuple[Report, Path]:
    folder = tmp_path_factory.mktemp("fleet")
    root = write_workspace(folder, ROBOTS)
    return run_check(CheckOptions(paths=[root], workspace=folder)), folder


def _flow(report: Report, folder: Path) -> FlowGraph:
    graph = roots_to_show(report)[0]
    index = PackageIndex.from_environment([folder], [])
    return build_flow(build_model(report, graph, {}), graph, WorkspaceInterfaces(index))


@pytest.fixture(scope="module")
def flow(fleet: tuple[Report, Path]) -> FlowGraph:
    return _flow(*fleet)


def _key(flow: FlowGraph, fqn: str) -> str:
    return next(n.key for n in flow.nodes.values() if n.fqn == fqn)


def _topic(flow: FlowGraph, name: str, namespace: str | None = None) -> FlowTopic:
    """Return the element of a topic (in ``namespace``: its copy there)."""
    return next(t for t in flow.topics.values() if name in t.names
                and (t.ref is None if namespace is None else t.namespace == namespace))


# ------------------------------------------------------------------ the model


def test_every_node_and_the_wiring(flow: FlowGraph) -> None:
    assert len(flow.nodes) == ROBOTS * NODES_PER_ROBOT + 3 >= 200
    assert flow.reason is None
    edges = set(flow.edges)
    scan = _topic(flow, "/robot4/front/scan")
    assert scan.namespace == "/robot4" and scan.types == ["sensor_msgs/msg/LaserScan"]
    assert FlowEdge(_key(flow, "/robot4/front_lidar"), scan.key, "topics") in edges
    assert FlowEdge(scan.key, _key(flow, "/robot4/front_filter"), "topics") in edges
    # services and actions: client -> element -> server
    reset = _topic(flow, "/robot2/localizer/reset")
    assert reset.section == "services"
    assert FlowEdge(_key(flow, "/robot2/behavior"), reset.key, "services") in edges
    assert FlowEdge(reset.key, _key(flow, "/robot2/localizer"), "services") in edges
    navigate = _topic(flow, "/robot7/navigate_to_pose")
    assert navigate.section == "actions"
    assert navigate.sources == [_key(flow, "/robot7/behavior")]
    assert navigate.sinks == [_key(flow, "/robot7/planner")]


def test_arrows_stay_in_their_namespace(flow: FlowGraph) -> None:
    for edge in flow.edges:
        assert flow.namespace_of(edge.source) == flow.namespace_of(edge.target), edge
    # /map lives with its publisher in /; each robot reads a copy of it in its own box
    original = _topic(flow, "/map")
    assert original.namespace == "/" and original.ref is None
    assert len(original.sinks) == 2 * ROBOTS + 1  # localizer and planner, fleet_manager
    copies = [t for t in flow.topics.values() if t.ref == original.key]
    assert sorted(c.namespace for c in copies) == sorted(f"/robot{i}"
                                                         for i in range(1, ROBOTS + 1))
    assert all(c.sources == original.sources for c in copies)


def test_tf_is_one_element_with_hidden_arrows(flow: FlowGraph) -> None:
    pairs = [t for t in flow.topics.values() if t.tf and t.ref is None]
    assert len(pairs) == 1
    tf = pairs[0]
    assert tf.names == ["/tf", "/tf_static"] and tf.label == "tf + tf_static"
    assert not any(t.names == ["/tf_static"] for t in flow.topics.values())
    tf_edges = [e for e in flow.edges if e.tf]
    assert tf_edges and all(e.section == "topics" for e in tf_edges)
    # 5 broadcasters and 3 listeners per robot
    assert len(tf.sources) == 5 * ROBOTS and len(tf.sinks) == 3 * ROBOTS


def test_marks(flow: FlowGraph) -> None:
    assert _topic(flow, "/robot1/cmd_vel_teleop").missing == "publisher"
    assert _topic(flow, "/robot1/diagnostics").missing == "subscriber"
    assert _topic(flow, "/robot1/cmd_vel").missing is None
    assert _topic(flow, "/map_server/load_map").missing is None  # a service nobody calls
    camera = flow.nodes[_key(flow, "/robot5/left_camera")]
    assert camera.condition == "$(var use_cameras)" and camera.known
    rviz = flow.nodes[_key(flow, "/rviz2")]
    assert not rviz.known and rviz.note is not None
    assert rviz.note.startswith("package rviz2 is not found")
    assert flow.known() == len(flow.nodes) - 1


# ------------------------------------------------------------------ the layout


def _overlap(a: tuple[float, float, float, float], b: tuple[float, float, float, float]) -> bool:
    return a[0] < b[0] + b[2] and b[0] < a[0] + a[2] and a[1] < b[1] + b[3] and \
        b[1] < a[1] + a[3]


def test_layout_of_two_hundred_nodes(flow: FlowGraph) -> None:
    started = time.process_time()  # CPU time: a loaded machine stretches wall time alone
    placed = layout(flow)
    html = render_flow(flow, 1, "sys1-node")
    elapsed = time.process_time() - started
    assert elapsed < 3.0  # about 0.1 s here
    assert len(html) < 600_000
    assert set(placed.boxes) == set(flow.nodes) | set(flow.topics)
    clusters = [(c.x, c.y, c.width, c.height) for c in placed.clusters]
    for i, one in enumerate(clusters):
        assert not any(_overlap(one, other) for other in clusters[i + 1:])
    for cluster in placed.clusters:
        boxes = sorted((placed.boxes[k].x, placed.boxes[k].y, placed.boxes[k].width,
                        placed.boxes[k].height) for k in cluster.members())
        for x, y, w, h in boxes:
            assert cluster.x <= x and x + w <= cluster.x + cluster.width + 0.01
            assert cluster.y <= y and y + h <= cluster.y + cluster.height + 0.01
        for i, one in enumerate(boxes):
            assert not any(_overlap(one, other) for other in boxes[i + 1:]), one
    assert placed.height < 4000 and placed.width < 2600


def test_data_flows_left_to_right(flow: FlowGraph) -> None:
    placed = layout(flow)
    chain = ["/robot3/front_lidar", "/robot3/front_filter", "/robot3/localizer",
             "/robot3/planner", "/robot3/controller", "/robot3/velocity_mux",
             "/robot3/base_driver"]
    xs = [placed.boxes[_key(flow, fqn)].x for fqn in chain]
    assert xs == sorted(xs) and len(set(xs)) == len(xs)


def test_same_input_same_bytes(fleet: tuple[Report, Path], flow: FlowGraph) -> None:
    again = _flow(*fleet)
    assert render_flow(again, 1, "a") == render_flow(flow, 1, "a")
    # a second check of the same tree, rendered whole: only the timing differs
    report = run_check(CheckOptions(paths=fleet[0].checked, workspace=fleet[1]))
    pages = []
    for one in (fleet[0], report):
        out = io.StringIO()
        render_html(one, out, interfaces=WorkspaceInterfaces(
            PackageIndex.from_environment([fleet[1]], [])))
        pages.append(re.sub(r'<span class="value">[\d.]+</span><span class="label">seconds',
                            "", out.getvalue()))
    assert pages[0] == pages[1]


def test_same_bytes_under_other_hash_seeds(tmp_path: Path) -> None:
    root = write_workspace(tmp_path / "ws", robots=3)
    sections = []
    for seed in ("1", "2"):
        out = tmp_path / f"report{seed}.html"
        env = {**os.environ, "PYTHONHASHSEED": seed}
        env.pop("AMENT_PREFIX_PATH", None)
        done = subprocess.run([sys.executable, "-m", "launchverify", "report", str(root),
                               "--workspace", str(tmp_path / "ws"), "-o", str(out)],
                              capture_output=True, text=True, env=env, check=False)
        assert done.returncode == 0, done.stderr
        page = out.read_text(encoding="utf-8")
        sections.append(page[page.index('<details class="flow-section"'):
                             page.index('<details class="nodes"')])
    assert sections[0] == sections[1] and "<svg" in sections[0]


def _graph(nodes: list[str], topics: dict[str, tuple[list[str], list[str]]]) -> FlowGraph:
    """Return a graph in ``/`` from node names and topic -> (publishers, subscribers)."""
    flow_nodes = {f"n{i}": FlowNode(f"n{i}", i, f"/{name}", "/", "pkg/exe", "node", None,
                                    True) for i, name in enumerate(nodes)}
    key = {f"/{name}": f"n{i}" for i, name in enumerate(nodes)}
    flow_topics, edges = {}, []
    for number, (name, (pubs, subs)) in enumerate(topics.items()):
        topic = FlowTopic(f"t{number}", "topics", [name], "/", [],
                          [key[p] for p in pubs], [key[s] for s in subs])
        flow_topics[topic.key] = topic
        edges += [FlowEdge(key[p], topic.key, "topics") for p in pubs]
        edges += [FlowEdge(topic.key, key[s], "topics") for s in subs]
    return FlowGraph(flow_nodes, flow_topics, edges)


def _x(placed: FlowLayout, key: str) -> float:
    return placed.boxes[key].x


def test_a_cycle_is_cut_where_it_returns() -> None:
    # sensor -> /a -> filter -> /b -> base -> /odom -> filter: the loop is odom's
    flow = _graph(["base", "filter", "sensor"], {
        "/a": (["/sensor"], ["/filter"]), "/b": (["/filter"], ["/base"]),
        "/odom": (["/base"], ["/filter"])})
    placed = layout(flow)
    assert _x(placed, "n2") < _x(placed, "t0") < _x(placed, "n1") < _x(placed, "t1") \
        < _x(placed, "n0") < _x(placed, "t2")


def test_unpublished_topic_sits_next_to_its_reader() -> None:
    flow = _graph(["a", "b", "c", "reader"], {
        "/ab": (["/a"], ["/b"]), "/bc": (["/b"], ["/c"]), "/cr": (["/c"], ["/reader"]),
        "/teleop": ([], ["/reader"])})
    placed = layout(flow)
    assert _x(placed, "t3") == _x(placed, "t2")  # same column as /cr, not column 0


def test_tall_columns_wrap_and_loose_elements_form_a_grid() -> None:
    readers = [f"r{i}" for i in range(MAX_ROWS * 2 + 3)]
    loose = [f"lone{i}" for i in range(7)]
    flow = _graph(["hub", *readers, *loose], {"/all": (["/hub"], [f"/{r}" for r in readers])})
    placed = layout(flow)
    cluster = placed.clusters[0]
    assert len(cluster.columns) == 2 + 3  # hub, /all, readers in three columns
    assert max(len(c) for c in cluster.columns) <= MAX_ROWS
    assert sorted(cluster.grid) == sorted(n.key for n in flow.nodes.values()
                                          if n.fqn.startswith("/lone"))
    bottom = max(placed.boxes[k].y for column in cluster.columns for k in column)
    assert all(placed.boxes[k].y > bottom for k in cluster.grid)


# ------------------------------------------------------------------ the picture


def test_picture(flow: FlowGraph) -> None:
    html = render_flow(flow, 2, "sys2-node")
    assert html.count("<svg") == 1 and 'id="flow2-svg"' in html
    for node in flow.nodes.values():
        assert f'data-fqn="{node.fqn}"' in html
        assert f'href="#sys2-node-{node.index}"' in html
    assert html.count('class="fedge') == len(flow.edges)
    camera = re.search(r'class="fnode cond"[^>]*data-fqn="/robot5/left_camera"><title>'
                       r"([^<]*)</title>", html)
    assert camera is not None and "when $(var use_cameras)" in camera.group(1)
    assert re.search(r'class="fnode unknown"[^>]*data-fqn="/rviz2"><title>[^<]*'
                     "interface not known: package rviz2 is not found", html)
    assert 'class="ftopic s-topics m-publisher"' in html  # cmd_vel_teleop
    assert 'class="ftopic s-topics m-subscriber"' in html  # diagnostics
    assert 'class="ftopic s-actions"' in html and 'class="fedge e-actions"' in html
    assert 'class="fedge e-services"' in html
    assert 'class="fedge e-topics e-tf"' in html and 'class="tf-toggle"' in html
    assert "url(" not in html  # no markers: the page refers to nothing
    # the filter's suggestions are the script's to list (the box needs it anyway)
    assert "<datalist" not in html and 'list="flow2-names"' in html


def test_without_tree_sitter(fleet: tuple[Report, Path], monkeypatch: pytest.MonkeyPatch,
                             ) -> None:
    monkeypatch.setitem(sys.modules, "tree_sitter_cpp", None)  # import fails
    flow = _flow(*fleet)
    assert flow.reason is not None and "tree_sitter_cpp is missing" in flow.reason
    html = render_flow(flow, 1, "x")
    assert "Not drawn: reading node sources needs the tree-sitter packages" in html
    assert "<svg" not in html


def test_without_any_sources(fleet: tuple[Report, Path]) -> None:
    report = fleet[0]
    graph = roots_to_show(report)[0]
    empty = PackageIndex.from_environment([], [])
    flow = build_flow(build_model(report, graph, {}), graph, WorkspaceInterfaces(empty))
    assert flow.reason is not None and flow.reason.startswith(
        "no launched node has its sources in the workspace")
    assert "<svg" not in render_flow(flow, 1, "x")


def test_a_failure_costs_only_this_part(fleet: tuple[Report, Path],
                                        monkeypatch: pytest.MonkeyPatch) -> None:
    def broken(self: Composer) -> None:
        raise RuntimeError("boom")

    monkeypatch.setattr(Composer, "compose", broken)
    out = io.StringIO()
    render_html(fleet[0], out, interfaces=WorkspaceInterfaces(
        PackageIndex.from_environment([fleet[1]], [])))
    page = out.getvalue()
    assert "Not drawn: composing the nodes with their sources failed (RuntimeError: boom)" \
        in page
    assert 'class="system-section"' in page and "</html>" in page


def test_parsers_present_here() -> None:
    assert flow_model.parsers_missing() is None


# ------------------------------------------------------------------ the command


def test_report_command_draws_the_wiring_demo(tmp_path: Path,
                                              capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "report.html"
    code = main(["report", str(WIRING), "--workspace", str(WIRING), "-o", str(out)])
    assert code == 0, capsys.readouterr().err
    page = out.read_text(encoding="utf-8")
    section = page[page.index('<details class="flow-section"'):]
    section = section[:section.index("</details>")]
    assert "Computation graph: 2 nodes, 3 topics, 1 without sources" in section
    # relay reads /sensors/imu (remapped; nobody publishes it) and writes imu_out, /status
    assert re.search(r'class="ftopic s-topics m-publisher"[^>]*><title>topic /sensors/imu\n',
                     section)
    assert 'data-fqn="/robot1/relay"' in section
    for name in ("/robot1/imu_out", "/status"):
        assert f"<title>topic {name}\n" in section
    assert 'class="fnode unknown" data-key="n1" data-fqn="/listener"' in section
    assert section.count('class="fedge e-topics"') == 3
