"""Code actions: a finding's fix as a quick fix, and "suppress this code on this line".

A fix's edits (``rule.Edit``: 1-based span, end exclusive) become one workspace edit; a
safe fix is the preferred action, the one editors apply with a single key. Edits name
the document version they were computed for, so an editor refuses them once the text has
changed.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from lsprotocol import types

from launchverify.lsp.diagnostics import LinesOf, diagnostic, uri_of
from launchverify.lsp.positions import Lines
from launchverify.lsp.suppress import suppression
from launchverify.rule import Applicability, Finding, Fix
from launchverify.span import Span


@dataclass(frozen=True)
class EditStyle:
    """How the client takes workspace edits: versioned document changes, or plain changes."""

    document_changes: bool
    version_of: Callable[[Path], int | None]  # of an open document, else None


def fix_action(finding: Finding, fix: Fix, lines_of: LinesOf,
               style: EditStyle) -> types.CodeAction:
    """Return the quick fix that applies a finding's fix."""
    edits: dict[Path, list[types.TextEdit]] = {}
    for edit in fix.edits:
        lines = lines_of(edit.span.file)
        edits.setdefault(edit.span.file, []).append(
            types.TextEdit(range=_exact(lines, edit.span), new_text=edit.content))
    return types.CodeAction(
        title=f"{finding.code}: {fix.message}",
        kind=types.CodeActionKind.QuickFix,
        diagnostics=[diagnostic(finding, lines_of)],
        edit=workspace_edit(edits, style),
        is_preferred=fix.applicability is Applicability.SAFE,
    )


def suppress_action(finding: Finding, lines_of: LinesOf,
                    style: EditStyle) -> types.CodeAction | None:
    """Return the action writing a suppression comment for the finding's code on its line."""
    path = finding.span.file
    lines = lines_of(path)
    insertion = suppression(path, lines.lines, finding.span.line, finding.code)
    if insertion is None:
        return None
    at = lines.position(insertion.line, insertion.column)
    edit = types.TextEdit(range=types.Range(start=at, end=at), new_text=insertion.text)
    return types.CodeAction(
        title=f"Suppress {finding.code} on this line",
        kind=types.CodeActionKind.QuickFix,
        diagnostics=[diagnostic(finding, lines_of)],
        edit=workspace_edit({path: [edit]}, style),
    )


def workspace_edit(edits: dict[Path, list[types.TextEdit]],
                   style: EditStyle) -> types.WorkspaceEdit:
    """Return edits to files as the client takes them."""
    if not style.document_changes:
        return types.WorkspaceEdit(changes={uri_of(p): e for p, e in edits.items()})
    return types.WorkspaceEdit(document_changes=[
        types.TextDocumentEdit(
            text_document=types.OptionalVersionedTextDocumentIdentifier(
                uri=uri_of(path), version=style.version_of(path)),
            edits=list(file_edits))
        for path, file_edits in edits.items()
    ])


def _exact(lines: Lines, span: Span) -> types.Range:
    """Return an edit's range: its span exactly, empty (an insertion) without an end."""
    start = lines.position(span.line, span.column)
    if span.end_line is None or span.end_column is None:
        return types.Range(start=start, end=start)
    return types.Range(start=start, end=lines.position(span.end_line, span.end_column))
