"""DDS domains, discovery ranges and domain_bridge: what keeps nodes apart, what joins them.

The corpus fixtures (``corpus/naming/dds_domains``, ``corpus/wiring/dds_domains``) hold
the rule-level pairs; these cases pin the pieces: rcl's reading of the discovery
variables per distribution, the bridge's reading of its YAML and command line, and what
``graph`` shows.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given
from hypothesis import strategies as st

from launchverify.cli import main
from launchverify.dds.bridges import parse, read_config
from launchverify.dds.discovery import CALLER, Discovery, effective_range
from launchverify.frontends.yaml_reader import compose
from launchverify.models import distros

FLEET = Path(__file__).resolve().parent.parent / "corpus" / "wiring" / "dds_domains"


def _graph(capsys: pytest.CaptureFixture[str], launch: Path, *extra: str) -> dict[str, Any]:
    code = main(["graph", str(launch), "--workspace", str(launch.parents[2]), *extra])
    out = capsys.readouterr().out
    assert code == 0, out
    document: dict[str, Any] = json.loads(out)
    return document


@pytest.mark.parametrize(("distro", "given", "localhost_only", "expected"), [
    (None, "", "", "SUBNET"),
    (None, "OFF", "", "OFF"),
    (None, "OFF", "1", "LOCALHOST"),      # ROS_LOCALHOST_ONLY=1 prevails (rcl init.c)
    (None, "OFF", "0", "OFF"),
    (None, "Off", "", "LOCALHOST"),       # rcl compares exactly and falls back to localhost
    (None, "SYSTEM_DEFAULT", "", "SYSTEM_DEFAULT"),
    ("jazzy", "OFF", CALLER, "OFF"),      # the caller's ROS_LOCALHOST_ONLY: taken as unset
    ("humble", "OFF", "", "SUBNET"),      # humble reads no ROS_AUTOMATIC_DISCOVERY_RANGE
    ("humble", "", "1", "LOCALHOST"),
    (None, CALLER, "", CALLER),
    (None, None, "", None),               # set from what is not known before launch
])
def test_effective_range(distro: str | None, given: str | None, localhost_only: str | None,
                         expected: str | None) -> None:
    with distros.checking(distro):
        assert effective_range(given, localhost_only) == expected


def test_only_facts_keep_nodes_apart() -> None:
    seven, zero = Discovery("7", "SUBNET", process=1), Discovery("0", "SUBNET", process=2)
    assert seven.meets(zero) is False
    assert seven.meets(Discovery("07", "SUBNET", process=3)) is True
    caller = Discovery(CALLER, "SUBNET", process=4, domain_source=CALLER)
    assert caller.meets(seven) is None                       # the caller may export 7
    assert caller.meets(zero) is None
    assert caller.meets(zero, assume_default=True) is True   # a warning may assume 0
    assert caller.meets(seven, assume_default=True) is False
    assert Discovery("3", "OFF", process=5).meets(Discovery("3", "SUBNET", process=6)) is False
    # one process (a container and its components) is one participant: off or not
    assert Discovery("3", "OFF", process=5).meets(Discovery("3", "SUBNET", process=5)) is True
    assert Discovery(None, "SUBNET", process=7).meets(seven) is None


@given(st.integers(0, 232), st.integers(0, 232))
def test_domains_compare_as_numbers(first: int, second: int) -> None:
    one = Discovery(str(first), "SUBNET", process=1)
    other = Discovery(f"{second:03d}", "SUBNET", process=2)
    assert one.meets(other) is (first == second)


def test_bridge_reads_every_entry_of_a_repeated_key(tmp_path: Path) -> None:
    config = tmp_path / "bridge.yaml"
    config.write_text("from_domain: 2\nto_domain: 3\ntopics:\n"
                      "  chatter: {type: example_interfaces/msg/String}\n"
                      "  chatter: {type: example_interfaces/msg/String, to_domain: 4}\n"
                      "  chatter: {type: example_interfaces/msg/String, reversed: True}\n"
                      "  chatter: {type: example_interfaces/msg/String, remap: chitter}\n")
    found = read_config(config)
    assert found is not None
    assert [(c.source, c.target, c.writes, c.span.line if c.span else 0) for c in found] == [
        ("2", "3", "/chatter", 4), ("2", "4", "/chatter", 5), ("3", "2", "/chatter", 6),
        ("2", "3", "/chitter", 7)]


@pytest.mark.parametrize("text", [
    "topics:\n  a: {type: std_msgs/msg/String, to_domain: 1}\n",   # no from_domain: refused
    "from_domain: 1\nto_domain: 2\ntopics:\n  - a: {type: std_msgs/msg/String}\n",
    "from_domain: 1\nto_domain: 2\ntopics:\n  a: std_msgs/msg/String\n",
    "- not a configuration\n",
])
def test_a_configuration_the_bridge_refuses_carries_nothing_known(text: str) -> None:
    assert parse(compose(text), Path("bridge.yaml")) is None


def test_an_unreadable_configuration_may_carry_anything(tmp_path: Path) -> None:
    assert read_config(tmp_path / "absent.yaml") is None
    (tmp_path / "broken.yaml").write_text("topics: [\n")
    assert read_config(tmp_path / "broken.yaml") is None


def test_graph_shows_domains_and_bridges(capsys: pytest.CaptureFixture[str]) -> None:
    launch = FLEET / "fleet_wiring" / "launch" / "station_remapped.launch.xml"
    document = _graph(capsys, launch)
    domains = {n["executable"]: n["dds"] for n in document["nodes"]}
    assert domains["battery_monitor"] == {"domain": "7", "discovery_range": CALLER,
                                          "localhost_only": CALLER}
    assert domains["fleet_dashboard"]["domain"] == "0"
    # --from 7 on the command line overrides the file's from_domain: 3
    assert [(b["topic"], b["published_as"], b["from_domain"], b["to_domain"], b["line"])
            for b in document["bridges"]] == [
        ("/fleet/battery", "/station/robot7_battery", "7", "0", 6),
        ("/fleet/battery", "/fleet/battery", "7", "9", 9)]


def test_the_callers_environment_given_on_the_command_line(
        capsys: pytest.CaptureFixture[str]) -> None:
    launch = FLEET / "fleet_wiring" / "launch" / "station_remapped.launch.xml"
    document = _graph(capsys, launch, "--env", "ROS_DOMAIN_ID=4",
                      "--env", "ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST")
    bridge = next(n for n in document["nodes"] if n["package"] == "domain_bridge")
    assert bridge["dds"]["domain"] == "4"
    assert bridge["dds"]["discovery_range"] == "LOCALHOST"


def test_a_bridge_through_its_own_launch_file(tmp_path: Path,
                                              capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / "bridge.yaml").write_text(
        "from_domain: 5\ntopics:\n  scan: {type: sensor_msgs/msg/LaserScan, to_domain: 0}\n")
    launch = tmp_path / "pkg" / "launch" / "station.launch.xml"
    launch.parent.mkdir(parents=True)
    launch.write_text(
        '<launch>\n  <include file="$(find-pkg-share domain_bridge)/launch/'
        'domain_bridge.launch.xml">\n'
        f'    <arg name="config" value="{tmp_path / "bridge.yaml"}"/>\n'
        '    <arg name="to_domain" value="2"/>\n  </include>\n</launch>\n')
    code = main(["graph", str(launch), "--workspace", str(tmp_path)])
    document = json.loads(capsys.readouterr().out)
    assert code == 0
    assert document["includes"][0]["arguments"]["config"] == str(tmp_path / "bridge.yaml")
    assert [(b["topic"], b["from_domain"], b["to_domain"]) for b in document["bridges"]] == [
        ("/scan", "5", "2")]


def test_the_report_draws_a_box_per_domain(tmp_path: Path) -> None:
    launch = FLEET / "fleet_wiring" / "launch" / "station_bridged.launch.xml"
    page = tmp_path / "report.html"
    assert main(["report", str(launch), "--workspace", str(launch.parents[2]),
                 "-o", str(page)]) in (0, 1)
    boxes = [title for title in ("DDS domain 0", "DDS domain 7", "DDS domain: the caller")
             if f"<title>{title}" in page.read_text()]
    assert boxes == ["DDS domain 0", "DDS domain 7", "DDS domain: the caller"]
    single = FLEET.parent.parent / "naming" / "duplicate_same_scope" / "dup.launch.xml"
    assert main(["report", str(single), "-o", str(page)]) in (0, 1)
    assert "DDS domain" not in page.read_text()


def test_graph_text_shows_domains_and_bridges(capsys: pytest.CaptureFixture[str]) -> None:
    launch = FLEET / "fleet_wiring" / "launch" / "station_remapped.launch.xml"
    assert main(["graph", str(launch), "--workspace", str(launch.parents[2]),
                 "--format", "text"]) == 0
    out = capsys.readouterr().out
    assert f"dds domain 7, discovery range {CALLER}" in out
    assert ("/fleet/battery as /station/robot7_battery [sensor_msgs/msg/BatteryState]  "
            "domain 7 -> 0") in out
