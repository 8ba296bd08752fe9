"""Findings as LSP diagnostics: range, severity, code with its documentation, related places.

The message is the one every reporter prints, with the argument values that make the
finding happen (``when: use_sim:=true``); related places and the include chain that
reached the file become related information, the nearest includer first.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from lsprotocol import types
from pygls.uris import from_fs_path

from launchverify.lsp.positions import Lines
from launchverify.registry import rule_of
from launchverify.render.links import documentation_base, help_uri
from launchverify.render.sarif import message_text
from launchverify.rule import Finding, Severity
from launchverify.span import Span

SOURCE = "launchverify"
INCLUDED_FROM = "included from here"
SEVERITIES = {
    Severity.ERROR: types.DiagnosticSeverity.Error,
    Severity.WARNING: types.DiagnosticSeverity.Warning,
    Severity.INFO: types.DiagnosticSeverity.Information,
}

LinesOf = Callable[[Path], Lines]


def uri_of(path: Path) -> str:
    """Return the ``file:`` URI of a path."""
    return from_fs_path(str(path)) or path.as_uri()


def location(span: Span, lines_of: LinesOf) -> types.Location:
    """Return the LSP location of a span."""
    return types.Location(uri=uri_of(span.file), range=lines_of(span.file).range(span))


def diagnostic(finding: Finding, lines_of: LinesOf) -> types.Diagnostic:
    """Return the diagnostic of one finding."""
    rule = rule_of(finding.code)
    href = help_uri(rule, documentation_base()) if rule is not None else None
    related = [types.DiagnosticRelatedInformation(location=location(r.span, lines_of),
                                                  message=r.message)
               for r in finding.related]
    related += [types.DiagnosticRelatedInformation(location=location(span, lines_of),
                                                   message=INCLUDED_FROM)
                for span in reversed(finding.chain)]
    return types.Diagnostic(
        range=lines_of(finding.span.file).range(finding.span),
        message=message_text(finding),
        severity=SEVERITIES[finding.severity],
        code=finding.code,
        code_description=types.CodeDescription(href=href) if href else None,
        source=SOURCE,
        related_information=related or None,
        data={"slug": finding.slug},
    )
