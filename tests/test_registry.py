"""Meta-tests: every rule is registered, documented, and exercised by the corpus."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from corpus_markers import read_markers

from launchverify.registry import RegistryError, all_rules, resolve, select
from launchverify.rules import BUILTIN

ROOT = Path(__file__).resolve().parent.parent
HEADINGS = ("## What it does", "## Why it matters", "## Example", "## Fix")


def corpus_codes() -> set[str]:
    codes: set[str] = set()
    for tree in (ROOT / "corpus").glob("*/*"):
        codes |= {code for (_, _, code) in read_markers(tree).expected}
    return codes


def test_builtin_is_sorted_and_unique() -> None:
    codes = [rule.code for rule in BUILTIN]
    assert codes == sorted(codes)
    assert len(set(codes)) == len(codes)
    assert len({rule.slug for rule in BUILTIN}) == len(BUILTIN)


@pytest.mark.parametrize("rule", BUILTIN, ids=lambda r: r.code)
def test_rule_metadata(rule: type) -> None:
    assert re.fullmatch(r"LV\d{3}", rule.code)
    assert re.fullmatch(r"[a-z]+(-[a-z]+)*", rule.slug)
    doc = rule.documentation()
    for heading in HEADINGS:
        assert heading in doc, f"{rule.code} docstring lacks {heading!r}"
    assert len(doc.splitlines()[0]) <= 99


# LV005 reports launchverify's own bugs: tests/test_isolation.py makes rules fail on purpose.
@pytest.mark.parametrize("rule", [r for r in BUILTIN if r.code != "LV005"],
                         ids=lambda r: r.code)
def test_rule_is_exercised_by_the_corpus(rule: type) -> None:
    assert rule.code in corpus_codes(), f"no corpus fixture expects {rule.code}"


def test_every_rule_module_is_listed() -> None:
    listed = {rule.__module__ for rule in BUILTIN}
    modules = {
        "launchverify.rules." + ".".join(path.relative_to(ROOT / "rules").with_suffix("").parts)
        for path in (ROOT / "rules").rglob("*.py")
        if path.name != "__init__.py"
    }
    assert modules == listed


def test_resolve_accepts_codes_slugs_and_prefixes() -> None:
    assert [r.code for r in resolve("LV101")] == ["LV101"]
    assert [r.code for r in resolve("duplicate-node-name")] == ["LV101"]
    assert {r.code for r in resolve("LV3")} >= {"LV301", "LV302", "LV303"}
    with pytest.raises(RegistryError):
        resolve("LV999")


def test_select_and_ignore() -> None:
    chosen = {r.code for r in select(["LV1", "LV201"], ["LV102"])}
    assert chosen == {"LV101", "LV103", "LV104", "LV201"}
    assert len(select(None, None)) == len(all_rules())


def test_plugin_rules_come_from_entry_points(tmp_path: Path,
                                            monkeypatch: pytest.MonkeyPatch) -> None:
    from launchverify.process import distributions

    (tmp_path / "acme_rules.py").write_text(
        "from launchverify.rule import Rule, Severity\n\n\n"
        "class NoTalker(Rule):\n"
        '    """No talkers.\n\n    ## What it does\n    x\n"""\n\n'
        '    code = "LV901"\n    slug = "no-talker"\n    severity = Severity.WARNING\n'
        '    message = "talker"\n\n    def check(self, graph, ctx):\n        return iter(())\n\n\n'
        "RULES = [NoTalker]\n")
    for name, group in (("acme_rules-1.0.dist-info", "launchverify.rules"),
                        ("shadowed-1.0.dist-info", "other.group")):
        (tmp_path / name).mkdir()
        (tmp_path / name / "entry_points.txt").write_text(
            f"[console_scripts]\nacme = acme_rules:main\n\n[{group}]\nacme = acme_rules:RULES\n")
    monkeypatch.setattr("sys.path", [str(tmp_path), *__import__("sys").path])
    distributions.distributions.cache_clear()
    all_rules.cache_clear()
    try:
        codes = [rule.code for rule in all_rules()]
    finally:
        distributions.distributions.cache_clear()
        all_rules.cache_clear()
    assert codes.count("LV901") == 1 and codes == sorted(codes)
