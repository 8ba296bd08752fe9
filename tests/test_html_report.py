"""The HTML report's structure, without a browser: self-contained, escaped, complete."""

from __future__ import annotations

import io
import re
from html.parser import HTMLParser
from pathlib import Path

import pytest

from launchverify.engine import CheckOptions, Report, run_check
from launchverify.render import links
from launchverify.render.graph_out import GraphView
from launchverify.render.html_report import render_html

CORPUS = Path(__file__).resolve().parent.parent / "corpus"
FLEET = CORPUS / "realistic" / "fleet_report"
ESCAPING = CORPUS / "realistic" / "report_escaping"
PAYLOAD = "<script>document.title='PWNED'</script>"
VOID = {"meta", "br", "img", "input", "link", "hr", "wbr", "col", "source"}


def check(*trees: Path) -> Report:
    return run_check(CheckOptions(paths=list(trees), workspace=trees[0]))


def render(report: Report) -> str:
    out = io.StringIO()
    render_html(report, out)
    return out.getvalue()


@pytest.fixture(autouse=True)
def _no_ros(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)


@pytest.fixture(scope="module")
def fleet() -> tuple[Report, str]:
    report = check(FLEET)
    return report, render(report)


@pytest.fixture(scope="module")
def escaping() -> str:
    return render(check(ESCAPING))


class Balance(HTMLParser):
    """Checks that every element is closed in order (SVG children self-close)."""

    def __init__(self) -> None:
        super().__init__()
        self.stack: list[str] = []
        self.errors: list[str] = []
        self.tags: list[tuple[str, dict[str, str | None]]] = []

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        self.tags.append((tag, dict(attrs)))
        if tag not in VOID:
            self.stack.append(tag)

    def handle_startendtag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        self.tags.append((tag, dict(attrs)))

    def handle_endtag(self, tag: str) -> None:
        if not self.stack or self.stack[-1] != tag:
            self.errors.append(f"</{tag}> closes {self.stack[-1:]}")
            return
        self.stack.pop()


def parse(page: str) -> Balance:
    parser = Balance()
    parser.feed(page)
    parser.close()
    return parser


def test_well_formed(fleet: tuple[Report, str], escaping: str) -> None:
    for page in (fleet[1], escaping):
        parsed = parse(page)
        assert parsed.errors == []
        assert parsed.stack == []


def test_self_contained(fleet: tuple[Report, str]) -> None:
    page = fleet[1]
    tags = parse(page).tags
    docs = links.documentation_base()  # the only way out: a link the reader follows
    for tag, attrs in tags:
        for name in ("src", "href", "action", "srcset", "data"):
            value = (attrs.get(name) or "").strip()
            if tag == "a" and name == "href" and docs and value.startswith(docs + "#"):
                continue
            assert not re.match(r"(?i)^([a-z][a-z0-9+.-]*:|//)", value), (tag, name, value)
    assert not [t for t, _ in tags if t in ("link", "iframe", "img", "object", "embed")]
    assert [a.get("src") for t, a in tags if t == "script"] == [None]
    assert "@import" not in page and "url(" not in page


def test_summary_and_every_finding(fleet: tuple[Report, str]) -> None:
    report, page = fleet
    assert len(report.findings) == 4
    assert f'<span class="value">{report.files}</span><span class="label">files read' in page
    assert '<span class="value">4</span><span class="label">findings' in page
    for index, finding in enumerate(report.findings, 1):
        article = re.search(rf'<article [^>]*id="finding-{index}">(.*?)</article>', page, re.S)
        assert article is not None
        body = article.group(1)
        assert finding.code in body and finding.slug in body
        assert finding.severity.value in body
        assert finding.message.replace("'", "&#x27;") in body
        assert "<mark>" in body  # the code frame marks the span
        assert f'href="#finding-{index}"' in page  # the index by rule links to it
        assert f'id="rule-{finding.code}"' in page
    lv505 = next(f for f in report.findings if f.code == "LV505")
    assert lv505.chain  # reached through two includes: the chain is listed
    assert page.count('<ol class="chain">') == sum(1 for f in report.findings if f.chain)


def test_picture_names_every_node(fleet: tuple[Report, str]) -> None:
    report, page = fleet
    root = next(g for g in report.graphs if not g.included_elsewhere)
    nodes = GraphView(root, symbolic=False).document()["nodes"]
    assert len(nodes) >= 200
    svg = page[page.index("<svg"): page.index("</svg>")]
    for node in nodes:
        assert f'data-fqn="{node["fqn"]}"' in svg
    assert svg.count('class="node') >= len(nodes)
    assert "/robot3/amcl" in page
    # one section: the included files are not shown as systems of their own
    assert page.count('class="system-section"') == 1


def test_node_boxes_do_not_overlap(fleet: tuple[Report, str]) -> None:
    svg = fleet[1][fleet[1].index("<svg"): fleet[1].index("</svg>")]
    boxes = [tuple(float(v) for v in m) for m in re.findall(
        r'<a href="#[^"]+" class="node[^"]*" data-fqn="[^"]*"><title>[^<]*</title>'
        r'<rect x="([\d.]+)" y="([\d.]+)" width="([\d.]+)" height="([\d.]+)"', svg)]
    assert len(boxes) >= 200
    boxes.sort(key=lambda b: (b[0], b[1]))
    for i, (x, y, w, h) in enumerate(boxes):
        for x2, y2, w2, h2 in boxes[i + 1:]:
            if x2 >= x + w:
                break
            assert y2 >= y + h or y >= y2 + h2, ((x, y, w, h), (x2, y2, w2, h2))
    width = re.search(r'<svg class="system"[^>]* width="(\d+)"', svg)
    assert width is not None and int(width.group(1)) <= 1400


def test_lifecycle_and_containers(fleet: tuple[Report, str]) -> None:
    page = fleet[1]
    assert "/robot6/lifecycle_manager_navigation" in page
    assert page.count('class="bad">does not complete') == 1
    assert page.count('class="ok">completes') == 12
    assert 'class="chip st-active">active' in page
    assert 'class="node container' in page and "12 comp." in page
    # robot6's manager never brings its nodes up: they rest unconfigured
    assert 'class="st-unconfigured"' in page
    # the parameters each node receives, with where they come from
    assert "max_particles</code> = <code>2000" in page
    assert "cmd_vel</code> \u2192 <code>cmd_vel_nav" in page


def test_include_tree(fleet: tuple[Report, str]) -> None:
    page = fleet[1]
    tree = page[page.index('<details class="includes"'):]
    tree = tree[: tree.index("</details>")]
    assert tree.count("robot.launch.xml</code>") == 6
    assert tree.count("navigation.launch.xml</code>") == 6
    assert "robot_name:=robot4" in tree


def test_escaping(escaping: str) -> None:
    assert PAYLOAD not in escaping
    assert "&lt;script&gt;document.title=&#x27;PWNED&#x27;&lt;/script&gt;" in escaping
    assert "<img" not in escaping and "</svg><script" not in escaping
    scripts = re.findall(r"<script\b[^>]*>(.*?)</script>", escaping, re.S)
    assert len(scripts) == 1 and "PWNED" not in scripts[0]
    assert "r&amp;d.launch.xml" in escaping  # a file name
    assert 'chatter_&quot;quoted&quot;' in escaping  # a remap, in the node table
    assert parse(escaping).errors == []


def test_trace_witness_and_several_roots() -> None:
    report = check(CORPUS / "lifecycle" / "activate_at_start")
    page = render(report)
    assert page.count('<ol class="trace">') == sum(1 for f in report.findings if f.trace) > 0
    assert "the launch starts" in page
    assert page.count('class="system-section"') == 3  # .py, .xml and .yaml roots
    assert "processes" in page
    report = check(CORPUS / "conditions" / "path_sensitive_duplicates")
    page = render(report)
    assert '<ul class="witness"><li><code>use_sim:=true</code>' in page
    assert "first started here" in page


def test_empty_report() -> None:
    page = render(Report([], 0, 0.0, {}))
    assert "No findings." in page
    assert parse(page).errors == []


def test_one_legend_and_places_that_tell_files_apart() -> None:
    html = render(check(CORPUS / "naming" / "scoped_namespaces_clean",
                        CORPUS / "naming" / "duplicate_same_scope"))
    assert html.count('<ul class="legend">') == 1
    assert html.count('<section class="system-section"') >= 2
    places = re.findall(r'<span class="loc" title="([^"]*)">([^<]*)</span>', html)
    assert places
    for full, shown in places:
        tail = shown.removeprefix("\u2026/")
        assert full.endswith(tail) and tail.count("/") == min(2, full.count("/"))
