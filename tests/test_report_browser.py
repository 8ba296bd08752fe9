"""The HTML report in a real browser: headless Chromium loads it, runs it, draws it.

Skipped when Chromium is not installed, unless the CI environment variable is set (CI
installs it, so its absence there is a failure). Chromium is driven from the command line
(``--dump-dom``, ``--screenshot``) with its network features off: it must not try to
reach anything, and the report needs nothing.
"""

from __future__ import annotations

import os
import re
import shutil
import struct
import subprocess
from pathlib import Path

import pytest
from flow_workspace import write_workspace

from launchverify.engine import CheckOptions, run_check
from launchverify.render.html_report import render_html
from launchverify.topology.compose import WorkspaceInterfaces
from launchverify.workspace.packages import PackageIndex

CORPUS = Path(__file__).resolve().parent.parent / "corpus"
FLEET = CORPUS / "realistic" / "fleet_report"
ESCAPING = CORPUS / "realistic" / "report_escaping"
TIMEOUT = 60  # seconds for one Chromium run (a run takes about one)
QUIET_FLAGS = ("--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
               "--no-first-run", "--disable-background-networking",
               "--disable-component-update", "--disable-sync", "--hide-scrollbars",
               "--disable-extensions", "--mute-audio")


@pytest.fixture(scope="module")
def chromium() -> str:
    found = shutil.which("chromium") or shutil.which("chromium-browser")
    if found is None and Path("/usr/bin/chromium").exists():
        found = "/usr/bin/chromium"
    if found is None:
        if os.environ.get("CI"):
            pytest.fail("CI is set but chromium is not installed (.ci/run installs it)")
        pytest.skip("chromium is not installed (apt-get install chromium); set CI to require it")
    return found


@pytest.fixture(scope="module")
def pages(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    folder = tmp_path_factory.mktemp("report")
    with pytest.MonkeyPatch.context() as patch:
        patch.delenv("AMENT_PREFIX_PATH", raising=False)
        out = {}
        for name, tree in (("fleet", FLEET), ("escaping", ESCAPING)):
            report = run_check(CheckOptions(paths=[tree], workspace=tree))
            path = folder / f"{name}.html"
            with path.open("w", encoding="utf-8") as handle:
                render_html(report, handle)
            out[name] = path
        fleet = write_workspace(folder / "fleet_ws", robots=9)
        report = run_check(CheckOptions(paths=[fleet], workspace=folder / "fleet_ws"))
        out["flow"] = folder / "flow.html"
        with out["flow"].open("w", encoding="utf-8") as handle:
            render_html(report, handle, interfaces=WorkspaceInterfaces(
                PackageIndex.from_environment([folder / "fleet_ws"], [])))
        return out


def browse(chromium: str, profile: Path, *arguments: str) -> str:
    """Run Chromium once with a fresh profile; return what it prints on stdout."""
    profile.mkdir(parents=True, exist_ok=True)
    done = subprocess.run(
        [chromium, *QUIET_FLAGS, f"--user-data-dir={profile}", *arguments],
        capture_output=True, text=True, timeout=TIMEOUT, check=False)
    assert done.returncode == 0, done.stderr[-2000:]
    return done.stdout


def dump_dom(chromium: str, profile: Path, url: str, *extra: str) -> str:
    dom = browse(chromium, profile, *extra, "--dump-dom", url)
    assert "</html>" in dom, dom[:500]
    return dom


def png_size(path: Path) -> tuple[int, int]:
    header = path.read_bytes()[:24]
    assert header[:8] == b"\x89PNG\r\n\x1a\n" and header[12:16] == b"IHDR"
    width, height = struct.unpack(">II", header[16:24])
    return width, height


def test_fleet_report_in_the_browser(chromium: str, pages: dict[str, Path],
                                     tmp_path: Path) -> None:
    dom = dump_dom(chromium, tmp_path / "profile", pages["fleet"].as_uri())
    # the summary: findings by severity, files, nodes
    assert '<span class="value">4</span><span class="label">findings' in dom
    assert '<span class="value">4</span><span class="label">errors' in dom
    assert re.search(r"<b>20\d</b> nodes", dom)
    for code in ("LV101", "LV204", "LV402", "LV505"):
        assert f'id="rule-{code}"' in dom
        assert f'<code class="code">{code}</code>' in dom
    # the picture: nodes by namespace, lifecycle states, managers, containers
    assert dom.count("<svg") == 1
    for fqn in ("/robot3/amcl", "/robot1/sensors/front_lidar", "/fleet/map_server",
                "/robot6/lifecycle_manager_navigation", "/robot2/perception/perception_container",
                "/robot5/perception/camera/front_camera"):
        assert f'data-fqn="{fqn}"' in dom
    for state in ("active", "inactive", "unconfigured"):
        assert f'<span class="chip st-{state}">{state}</span>' in dom
    assert 'class="bad">does not complete' in dom
    # without a fragment the node table stays collapsed
    assert '<details class="nodes">' in dom


def test_link_into_node_table_opens_it(chromium: str, pages: dict[str, Path],
                                       tmp_path: Path) -> None:
    dom = dump_dom(chromium, tmp_path / "profile", pages["fleet"].as_uri() + "#sys1-node-40")
    assert '<details class="nodes" open="">' in dom


def _cells(table: str, row: str) -> list[str]:
    """Return the cells of a node's row but the first (its name), without their ids."""
    found = re.search(rf'<tr id="{row}">(.*?)</tr>', table, re.S)
    assert found is not None, row
    cells = re.findall(r"<td\b[^>]*>.*?</td>", found.group(1), re.S)
    return [re.sub(r' id="[^"]*"', "", cell) for cell in cells[1:]]


def test_repeated_rows_are_filled_in(chromium: str, pages: dict[str, Path],
                                     tmp_path: Path) -> None:
    # six robots start the same nodes: a row seen before is written as a reference to
    # it, which the script fills with a copy when the table opens
    source = pages["fleet"].read_text(encoding="utf-8")
    references = re.findall(r'<tr id="(sys1-node-\d+)"><td>(?:(?!</tr>).)*?'
                            r'<td colspan="6" class="same" data-same="([^"]+)">', source, re.S)
    assert len(references) > 50
    dom = dump_dom(chromium, tmp_path / "profile", pages["fleet"].as_uri() + "#sys1-node-40")
    table = dom[dom.index('<details class="nodes" open="">'):]
    table = table[:table.index("</details>")]
    assert 'class="same"' not in table
    for row, first in references:
        cells = _cells(table, row)
        assert len(cells) == 6 and cells == _cells(table, first)
    # as many as when every row was written whole
    assert table.count("max_particles</code> = <code>2000") == 4


def test_policy_lets_only_the_report_script_run(chromium: str, pages: dict[str, Path],
                                                tmp_path: Path) -> None:
    # a script slipped into the page (as if escaping had failed) is refused
    page = pages["fleet"].read_text(encoding="utf-8").replace(
        "</body>", "<script>document.title='PWNED'</script></body>")
    copy = tmp_path / "injected.html"
    copy.write_text(page, encoding="utf-8")
    dom = dump_dom(chromium, tmp_path / "profile", copy.as_uri())
    assert "<title>launchverify report</title>" in dom


def test_reads_without_javascript(chromium: str, pages: dict[str, Path],
                                  tmp_path: Path) -> None:
    # --dump-dom needs JavaScript itself; a policy forbidding every script of the page
    # leaves the browser's own reading working. The probe proves the page's scripts stop.
    page = pages["fleet"].read_text(encoding="utf-8").replace(
        "<head>", "<head><meta http-equiv=\"Content-Security-Policy\" "
        "content=\"script-src 'none'\">", 1).replace(
        "</body>", "<script>document.title='SCRIPTS RAN'</script></body>")
    copy = tmp_path / "no-script.html"
    copy.write_text(page, encoding="utf-8")
    dom = dump_dom(chromium, tmp_path / "profile", copy.as_uri() + "#sys1-node-40")
    assert "<title>launchverify report</title>" in dom
    assert 'data-fqn="/robot3/amcl"' in dom and 'id="finding-4"' in dom
    assert 'id="sys1-node-40"' in dom and "max_particles" in dom


def test_escaped_payloads_never_run(chromium: str, pages: dict[str, Path],
                                    tmp_path: Path) -> None:
    source = pages["escaping"].read_text(encoding="utf-8")
    assert "<script>document.title" not in source and "<img" not in source
    dom = dump_dom(chromium, tmp_path / "profile", pages["escaping"].as_uri())
    title = re.search(r"<title>(.*?)</title>", dom, re.S)
    assert title is not None and title.group(1) == "launchverify report"
    scripts = re.findall(r"<script\b[^>]*>(.*?)</script>", dom, re.S)
    assert len(scripts) == 1 and "PWNED" not in scripts[0] and "alert" not in scripts[0]
    assert "<img" not in dom
    # the text is there, shown as text
    assert "&lt;script&gt;document.title='PWNED'&lt;/script&gt;" in dom


def test_screenshot(chromium: str, pages: dict[str, Path], tmp_path: Path) -> None:
    shot = tmp_path / "fleet.png"
    browse(chromium, tmp_path / "profile", f"--screenshot={shot}", "--window-size=1400,2000",
           pages["fleet"].as_uri())
    assert shot.is_file()
    assert png_size(shot) == (1400, 2000)
    assert shot.stat().st_size > 60_000  # a drawn page, not a blank one


def _lit(dom: str) -> set[str]:
    """Return the names of the computation graph's nodes the filter keeps."""
    return set(re.findall(r'class="fnode[^"]* on"[^>]*data-fqn="([^"]*)"', dom))


def test_filter_narrows_the_computation_graph(chromium: str, pages: dict[str, Path],
                                              tmp_path: Path) -> None:
    source = pages["flow"].read_text(encoding="utf-8")
    dom = dump_dom(chromium, tmp_path / "plain", pages["flow"].as_uri())
    assert '<svg class="flow-svg" id="flow1-svg"' in dom  # nothing filtered
    box = re.search(r'<input type="search" class="flow-filter"[^>]*>', dom)
    assert box is not None and "hidden" not in box.group(0)  # the script shows it
    suggestions = re.search(r'<datalist id="flow1-names">(.*?)</datalist>', dom, re.S)
    assert suggestions is not None  # and lists every node's name, once, in order
    names = re.findall(r'<option value="([^"]*)">', suggestions.group(1))
    assert len(names) == 201 and names == sorted(set(names))
    page = tmp_path / "filtered.html"
    page.write_text(source.replace('class="flow-filter" ',
                                   'class="flow-filter" value="/robot3/localizer" '),
                    encoding="utf-8")
    dom = dump_dom(chromium, tmp_path / "profile", page.as_uri())
    assert '<svg class="flow-svg focus" id="flow1-svg"' in dom
    # what it reads from (map, filtered scan, imu, odometry; its reset service's caller)
    # and who reads what it publishes (the planner reads its pose); not the co-readers
    assert _lit(dom) == {"/robot3/localizer", "/map_server", "/robot3/front_filter",
                         "/robot3/imu", "/robot3/base_driver", "/robot3/behavior",
                         "/robot3/planner"}
    assert "1 node matches" in dom
    view = re.search(r'id="flow1-svg"[^>]* viewBox="([^"]+)" data-box="([^"]+)"', dom)
    assert view is not None and view.group(1) != view.group(2)  # cropped to them
    # a part of a name: every robot's localizer
    page.write_text(source.replace('class="flow-filter" ', 'class="flow-filter" '
                                   'value="localizer" '), encoding="utf-8")
    dom = dump_dom(chromium, tmp_path / "profile", page.as_uri())
    assert "9 nodes match" in dom and "/robot9/planner" in _lit(dom)
