"""The report's page: one legend for every picture, cards that explain, whole names."""

from __future__ import annotations

from pathlib import Path

import pytest

from launchverify.cli import main
from launchverify.render import links
from launchverify.render.flow_svg import _fit

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
