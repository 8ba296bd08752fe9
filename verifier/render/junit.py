"""``check --format junit``: one JUnit test case per launch file, for CI test reports.

The layout is the one ament_lint's xunit files use and ``colcon test-result`` reads: a
single ``<testsuite name="launchverify">`` root and one ``<testcase
classname="launchverify">`` named by each file's display path. A file with an error or
a warning fails with one ``<failure>`` listing all its findings; a file with only infos
passes and lists them in ``<system-out>``. A file that has findings but was not among
the checked ones (an included file) still gets a test case, so no error goes unreported.
"""

from __future__ import annotations

import os
import re
import xml.etree.ElementTree as ET
from collections.abc import Iterable
from pathlib import Path
from typing import TextIO

from launchverify.engine import Report
from launchverify.findings.fixes import fix_note
from launchverify.render.inert import inert, inert_block
from launchverify.rule import Finding, Severity

# Characters XML 1.0 cannot carry even as character references.
_NOT_XML = re.compile("[^\t\n\r\x20-\ud7ff\ue000-\ufffd\U00010000-\U0010ffff]")


def xml_safe(text: str) -> str:
    r"""Return ``text`` with what XML cannot hold, or a viewer would act on, spelled out.

    Control characters become visible escapes (ESC as ``\x1b``; see ``inert_block``).
    """
    return _NOT_XML.sub(lambda match: ascii(match.group())[1:-1], inert_block(text))


def finding_line(finding: Finding) -> str:
    """Return ``line:col CODE [slug] message`` (with the argument values, when known).

    Callers listing several make each ``inert``: a name's line feed would forge a line.
    """
    span = finding.span
    text = f"{span.line}:{span.column} {finding.code} [{finding.slug}] {finding.message}"
    if finding.witness:
        values = " ".join(f"{k}:={v}" for k, v in sorted(finding.witness.items()))
        text += f" (when: {values})"
    return text + fix_note(finding.fix)


def _unique(paths: Iterable[Path]) -> list[Path]:
    return list(dict.fromkeys(paths))


def case_files(report: Report, checked: list[Path] | None) -> list[Path]:
    """Return the files that become test cases, as canonical paths, in output order."""
    if checked is not None:
        files = _unique(Path(os.path.realpath(path)) for path in checked)
    else:
        files = sorted(report.loaded_files(), key=report.display_path)
    extra = {f.span.file for f in report.findings} - set(files)
    return [*files, *sorted(extra, key=report.display_path)]


def summary(findings: list[Finding]) -> str:
    """Return ``2 errors, 1 warning`` for a file's findings."""
    parts = []
    for severity in Severity:
        count = sum(1 for f in findings if f.severity is severity)
        if count:
            parts.append(f"{count} {severity.value}{'s' if count != 1 else ''}")
    return ", ".join(parts)


def junit_tree(report: Report, checked: list[Path] | None = None) -> ET.Element:
    """Return the ``<testsuite>`` element of a report."""
    by_file: dict[Path, list[Finding]] = {}
    for finding in report.findings:
        by_file.setdefault(finding.span.file, []).append(finding)
    suite = ET.Element("testsuite", name="launchverify")
    failures = 0
    files = case_files(report, checked)
    for path in files:
        case = ET.SubElement(suite, "testcase", classname="launchverify",
                             name=xml_safe(report.display_path(path)), time="0")
        findings = by_file.get(path, [])
        if not findings:
            continue
        listing = "\n".join(xml_safe(inert(finding_line(f))) for f in findings)
        worst = max((f.severity for f in findings), key=lambda s: s.rank)
        if worst is Severity.INFO:
            ET.SubElement(case, "system-out").text = listing
            continue
        failures += 1
        failure = ET.SubElement(case, "failure", message=summary(findings), type=worst.value)
        failure.text = listing
    suite.set("tests", str(len(files)))
    suite.set("failures", str(failures))
    suite.set("errors", "0")
    suite.set("skipped", "0")
    suite.set("time", f"{report.seconds:.3f}")
    return suite


def render_junit(report: Report, out: TextIO, *, checked: list[Path] | None = None) -> None:
    """Write the report as JUnit XML, one test case per checked file (default: all loaded)."""
    suite = junit_tree(report, checked)
    ET.indent(suite)
    out.write('<?xml version="1.0" encoding="UTF-8"?>\n')
    out.write(ET.tostring(suite, encoding="unicode"))
    out.write("\n")
