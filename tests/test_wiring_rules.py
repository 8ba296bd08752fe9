"""The wiring rules (LV602-LV604) and what the configuration tells them.

Their findings are in the corpus (corpus/wiring/); here: the configuration keys, and a
type mismatch whose other end does not come from the workspace's sources.
"""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path

import pytest

from launchverify.cli import main
from launchverify.config import Config, ConfigError, load_config
from launchverify.engine import CheckOptions, build_index, canonical, run_check
from launchverify.evaluate.runner import evaluate
from launchverify.rule import RuleContext, Severity
from launchverify.rules.wiring.type_mismatch import TypeMismatch
from launchverify.topology.compose import WorkspaceInterfaces
from launchverify.topology.model import NodeInterface
from launchverify.topology.wiring import view_of

WIRING = Path(__file__).resolve().parent.parent / "corpus" / "wiring"
PEERS = WIRING / "missing_peer"
VELOCITY = WIRING / "velocity_commands"


@pytest.fixture(autouse=True)
def _no_ros(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)


def findings(tree: Path, launch: str, config: Config | None = None) -> list[tuple[str, str]]:
    """Return (code, severity) of the LV6 findings on one launch file of a corpus tree."""
    file = next(tree.rglob(launch))
    report = run_check(CheckOptions(paths=[file], workspace=tree, select=["LV6"],
                                    config=config or Config()))
    return sorted((f.code, f.severity.value) for f in report.findings)


def test_external_names_silence_what_is_fed_from_outside() -> None:
    assert findings(PEERS, "fleet.launch.xml") == [("LV602", "info")]
    assert findings(PEERS, "fleet.launch.xml", Config(external_names=["/robot1/scan"])) == []
    assert findings(PEERS, "fleet.launch.xml", Config(external_names=["scan"])) == []
    assert findings(PEERS, "fleet.launch.xml", Config(external_names=["/scan"])) == [
        ("LV602", "info")]  # a leading slash anchors the glob at the root


def test_external_names_do_not_hide_a_close_miss_they_do_not_name() -> None:
    config = Config(external_names=["/robot2/*"])
    assert findings(PEERS, "namespace_one_side.launch.xml", config) == [("LV602", "warning")]


def test_single_writer_topics_replace_the_default() -> None:
    assert findings(VELOCITY, "two_sources.launch.xml") == [("LV604", "warning")]
    assert findings(VELOCITY, "two_sources.launch.xml", Config(single_writer_topics=[])) == []
    assert findings(VELOCITY, "two_sources.launch.xml",
                    Config(single_writer_topics=["/joy_vel"])) == []
    assert findings(VELOCITY, "muxed.launch.xml",
                    Config(single_writer_topics=["cmd_vel*"])) == []  # one writer each


def test_configuration_file_reaches_the_rules(tmp_path: Path,
                                              capsys: pytest.CaptureFixture[str]) -> None:
    config = tmp_path / "launchverify.toml"
    config.write_text('external-names = ["/robot1/scan"]\nsingle-writer-topics = []\n')
    launches = [str(next(PEERS.rglob("fleet.launch.xml"))),
                str(next(VELOCITY.rglob("two_sources.launch.xml")))]
    for launch, workspace in zip(launches, (PEERS, VELOCITY), strict=True):
        main(["check", launch, "--workspace", str(workspace), "--select", "LV6",
              "--format", "json", "--config", str(config)])
        assert json.loads(capsys.readouterr().out)["findings"] == []


@pytest.mark.parametrize(("text", "message"), [
    ("external-names = 3", "external-names must be a list of strings"),
    ('external-names = ["/a b"]', "external-names must be a list of name globs"),
    ('single-writer-topics = [""]', "single-writer-topics must be a list of name globs"),
])
def test_bad_name_globs_are_a_clear_error(tmp_path: Path, text: str, message: str) -> None:
    path = tmp_path / "launchverify.toml"
    path.write_text(text)
    with pytest.raises(ConfigError, match=message):
        load_config(path)


def test_name_globs_are_read(tmp_path: Path) -> None:
    path = tmp_path / "pyproject.toml"
    path.write_text('[tool.launchverify]\nexternal-names = "/gps/*"\n'
                    'single-writer-topics = ["*cmd_vel", "/arm/command"]\n')
    config = load_config(path)
    assert config.external_names == ["/gps/*"]
    assert config.single_writer_topics == ["*cmd_vel", "/arm/command"]
    assert Config().single_writer_topics is None  # unset: the rule's own default


class ModelledInterfaces:
    """The workspace's interfaces, except one executable given by a model (no sources)."""

    def __init__(self, workspace: WorkspaceInterfaces, modelled: str) -> None:
        self.workspace = workspace
        self.modelled = modelled

    def interface(self, package: str, executable: str,
                  component: bool) -> tuple[NodeInterface | None, str | None]:
        found, note = self.workspace.interface(package, executable, component)
        if found is not None and executable == self.modelled:
            return dataclasses.replace(found, sources=()), None
        return found, note


@pytest.mark.parametrize(("modelled", "severity"), [
    (None, Severity.ERROR), ("teleop", Severity.WARNING), ("base_controller",
                                                            Severity.WARNING)])
def test_a_type_mismatch_is_an_error_only_between_ends_read_from_sources(
        modelled: str | None, severity: Severity) -> None:
    launch = canonical(next(VELOCITY.rglob("jazzy_migration.launch.xml")))
    workspace, index = build_index([launch], VELOCITY)
    graph = evaluate(launch, index=index, workspace=workspace)
    reader = WorkspaceInterfaces(index)
    view_of(graph, reader if modelled is None else ModelledInterfaces(reader, modelled))
    found = list(TypeMismatch().check(graph, RuleContext(packages=index)))
    assert [f.severity for f in found] == [severity]
