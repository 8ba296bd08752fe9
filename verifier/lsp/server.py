"""The language server's wiring: protocol messages to checks, diagnostics and answers.

Documents are checked when opened or saved, and after a pause in typing
(``schedule.py``); diagnostics go to every file a check decided, cleared where nothing
is left. Requests (code actions, hover, definitions) are answered from what the last
checks found. A failure of ours is logged to the client (``window/logMessage``) and the
server goes on: a bug must not cost the editor its diagnostics for the session.
"""

from __future__ import annotations

import contextlib
import functools
import logging
import os
import sys
import traceback
from collections.abc import Callable
from pathlib import Path
from typing import Any, TypeVar

from lsprotocol import types
from pygls.lsp.server import LanguageServer
from pygls.uris import to_fs_path

from launchverify import __version__
from launchverify.engine import canonical
from launchverify.lsp.actions import EditStyle, fix_action, suppress_action
from launchverify.lsp.checking import check_documents
from launchverify.lsp.diagnostics import diagnostic, location, uri_of
from launchverify.lsp.hover import finding_text, join, reference_text
from launchverify.lsp.lookup import reference_at
from launchverify.lsp.positions import UTF16, Lines
from launchverify.lsp.results import Results
from launchverify.lsp.schedule import DEBOUNCE, Scheduler, in_thread
from launchverify.workspace.paths import relative_file

R = TypeVar("R")


class Session:
    """One editor's session: its documents, the findings published, what to check next."""

    def __init__(self, server: LanguageServer) -> None:
        self.server = server
        self.results = Results()
        self.published: dict[Path, list[types.Diagnostic]] = {}
        self.scheduler = Scheduler(self.check)
        self.shut_down = False
        self._said: set[str] = set()

    # ------------------------------------------------------------------ documents

    def path_of(self, uri: str) -> Path | None:
        """Return the file a ``file:`` URI names (``None`` for other schemes)."""
        if not uri.startswith("file:"):
            return None
        path = to_fs_path(uri)
        return canonical(Path(path)) if path else None

    def open_documents(self) -> dict[Path, tuple[str, str, int | None]]:
        """Return each open file's URI, text and version."""
        out = {}
        for uri, document in self.server.workspace.text_documents.items():
            path = self.path_of(uri)
            if path is not None:
                out[path] = (uri, document.source, document.version)
        return out

    def folders(self) -> list[Path]:
        """Return the editor's workspace folders (the innermost first)."""
        uris = [folder.uri for folder in self.server.workspace.folders.values()]
        if self.server.workspace.root_uri:
            uris.append(self.server.workspace.root_uri)
        paths = {p for p in (self.path_of(uri) for uri in uris) if p is not None}
        return sorted(paths, key=lambda p: len(p.parts), reverse=True)

    def display(self, path: Path) -> str:
        """Return a path as the user thinks of it: relative to its workspace folder."""
        folder = next((f for f in self.folders() if path.is_relative_to(f)), None)
        return relative_file(path, folder) if folder is not None else str(path)

    @property
    def encoding(self) -> str:
        """Return how the client counts characters (UTF-16 unless it chose otherwise)."""
        chosen = self.server.workspace.position_encoding
        return str(getattr(chosen, "value", chosen) or UTF16)

    def lines_of(self, path: Path) -> Lines:
        """Return a file's lines as checked, with how its spans and the client count."""
        return Lines(self.results.lines_of(path), self.encoding)

    def version_of(self, path: Path) -> int | None:
        """Return the version of an open document (``None`` when it is not open)."""
        opened = self.open_documents().get(path)
        return opened[2] if opened is not None else None

    def current(self, path: Path) -> bool:
        """Return whether the findings of a file were found in the text the editor has now."""
        opened = self.open_documents().get(path)
        if opened is None:
            return True
        return tuple(opened[1].splitlines()) == tuple(self.results.lines_of(path))

    # ------------------------------------------------------------------ checking

    async def check(self, paths: frozenset[Path]) -> None:
        """Check what the documents affect; publish what changed."""
        opened = self.open_documents()
        buffers = {path: text.encode("utf-8") for path, (_, text, _) in opened.items()}
        folders = self.folders()
        try:
            checked = await in_thread(lambda: check_documents(paths, buffers, folders))
        except Exception:
            self.log_error("checking failed", traceback.format_exc())
            return
        for problem in checked.problems:
            self.say(problem)
        uris = {path: uri for path, (uri, _, _) in self.open_documents().items()}
        for path in self.results.update(checked):
            self.publish(path, uris.get(path) or uri_of(path), always=path in paths)

    def publish(self, path: Path, uri: str, *, always: bool = False) -> None:
        """Send a file's diagnostics when they changed (or ``always``: a checked document).

        ``uri``: the one the editor opened the file with, if it did (a symbolic link).
        """
        diagnostics = [diagnostic(f, self.lines_of) for f in self.results.findings[path]]
        if not always and self.published.get(path, []) == diagnostics:
            return
        self.published[path] = diagnostics
        self.server.text_document_publish_diagnostics(
            types.PublishDiagnosticsParams(uri=uri, diagnostics=diagnostics))

    # ------------------------------------------------------------------ messages

    def say(self, message: str) -> None:
        """Show a problem of the set-up (a broken configuration) once per session."""
        if message not in self._said:
            self._said.add(message)
            self.server.window_show_message(types.ShowMessageParams(
                type=types.MessageType.Error, message=f"launchverify: {message}"))

    def log_error(self, what: str, details: str) -> None:
        """Log an internal error to the client; the server goes on."""
        self.server.window_log_message(types.LogMessageParams(
            type=types.MessageType.Error,
            message=f"launchverify {__version__}: internal error, {what}:\n{details}"))

    def guarded(self, handler: Callable[..., R]) -> Callable[..., R | None]:
        """Wrap a handler: an exception is logged, and the request gets no answer (None)."""
        @functools.wraps(handler)
        def run(*args: Any) -> R | None:
            try:
                return handler(*args)
            except Exception:
                self.log_error(f"in {handler.__name__}", traceback.format_exc())
                return None
        return run

    # ------------------------------------------------------------------ requests

    def code_actions(self, params: types.CodeActionParams) -> list[types.CodeAction] | None:
        """Return quick fixes for the findings in a range, and suppressions."""
        only = params.context.only
        if only and not any(types.CodeActionKind.QuickFix.value.startswith(kind)
                            for kind in only):
            return None
        path = self.path_of(params.text_document.uri)
        if path is None or not self.current(path):
            return None  # the text moved on since the check: edits would land wrong
        capabilities = self.server.client_capabilities.workspace
        changes = bool(capabilities and capabilities.workspace_edit
                       and capabilities.workspace_edit.document_changes)
        style = EditStyle(changes, self.version_of)
        lines = self.lines_of(path)
        out = []
        for finding in self.results.findings.get(path, []):
            if not _overlap(lines.range(finding.span), params.range):
                continue
            if finding.fix is not None:
                out.append(fix_action(finding, finding.fix, self.lines_of, style))
            suppress = suppress_action(finding, self.lines_of, style)
            if suppress is not None:
                out.append(suppress)
        return out

    def hover(self, params: types.HoverParams) -> types.Hover | None:
        """Return the findings under the cursor with their rules, or the argument there."""
        path = self.path_of(params.text_document.uri)
        if path is None:
            return None
        lines = self.lines_of(path)
        texts: list[str | None] = [
            finding_text(f, self.display) for f in self.results.findings.get(path, [])
            if _inside(params.position, lines.range(f.span))]
        line, column = lines.column(params.position)
        reference = reference_at(self.results.graphs_with(path), path, lines.lines, line,
                                 column)
        if reference is not None:
            texts.append(reference_text(reference, self.display))
        text = join(texts)
        if text is None:
            return None
        return types.Hover(contents=types.MarkupContent(kind=types.MarkupKind.Markdown,
                                                        value=text))

    def definition(self, params: types.DefinitionParams) -> list[types.Location] | None:
        """Return where the argument, include or parameter file under the cursor is."""
        path = self.path_of(params.text_document.uri)
        if path is None:
            return None
        lines = self.lines_of(path)
        line, column = lines.column(params.position)
        reference = reference_at(self.results.graphs_with(path), path, lines.lines, line,
                                 column)
        if reference is None:
            return None
        if reference.file is not None:
            start = types.Position(line=0, character=0)
            return [types.Location(uri=uri_of(reference.file),
                                   range=types.Range(start=start, end=start))]
        return [location(span, self.lines_of) for span in reference.targets()] or None


def _inside(position: types.Position, where: types.Range) -> bool:
    at = (position.line, position.character)
    return (where.start.line, where.start.character) <= at <= (where.end.line,
                                                                 where.end.character)


def _overlap(first: types.Range, second: types.Range) -> bool:
    def key(p: types.Position) -> tuple[int, int]:
        return p.line, p.character

    return key(first.start) <= key(second.end) and key(second.start) <= key(first.end)


def build_server() -> tuple[LanguageServer, Session]:
    """Return a server with every feature registered, and its session."""
    server = LanguageServer("launchverify", __version__,
                            text_document_sync_kind=types.TextDocumentSyncKind.Incremental)
    session = Session(server)

    def request(uri: str, delay: float) -> None:
        path = session.path_of(uri)
        if path is not None and not session.shut_down:
            session.scheduler.request(path, delay)

    @server.feature(types.TEXT_DOCUMENT_DID_OPEN)
    def did_open(params: types.DidOpenTextDocumentParams) -> None:
        request(params.text_document.uri, 0.0)

    @server.feature(types.TEXT_DOCUMENT_DID_CHANGE)
    def did_change(params: types.DidChangeTextDocumentParams) -> None:
        request(params.text_document.uri, DEBOUNCE)

    @server.feature(types.TEXT_DOCUMENT_DID_SAVE)
    def did_save(params: types.DidSaveTextDocumentParams) -> None:
        request(params.text_document.uri, 0.0)

    @server.feature(types.TEXT_DOCUMENT_DID_CLOSE)
    def did_close(params: types.DidCloseTextDocumentParams) -> None:
        request(params.text_document.uri, 0.0)  # the file on disk counts again

    @server.feature(types.SHUTDOWN)
    def shutdown(params: None) -> None:
        session.shut_down = True
        session.scheduler.cancel()

    server.feature(types.TEXT_DOCUMENT_CODE_ACTION, types.CodeActionOptions(
        code_action_kinds=[types.CodeActionKind.QuickFix]))(
            session.guarded(session.code_actions))
    server.feature(types.TEXT_DOCUMENT_HOVER)(session.guarded(session.hover))
    server.feature(types.TEXT_DOCUMENT_DEFINITION)(session.guarded(session.definition))
    return server, session


def run(address: tuple[str, int] | None) -> int:
    """Serve one client until it says ``exit`` (0 after ``shutdown``, else 1)."""
    logging.basicConfig(level=logging.WARNING, stream=sys.stderr,
                        format="launchverify lsp: %(levelname)s: %(message)s")
    _load_rules()
    server, session = build_server()
    if address is not None:
        with contextlib.suppress(SystemExit):  # pygls ends a TCP session with sys.exit
            server.start_tcp(*address)
    else:
        # The protocol owns standard output: anything else printed in this process (or a
        # process it forks) goes to standard error instead of corrupting a message.
        protocol = os.fdopen(os.dup(sys.stdout.fileno()), "wb")
        os.dup2(sys.stderr.fileno(), sys.stdout.fileno())
        server.start_io(sys.stdin.buffer, protocol)
    return 0 if session.shut_down else 1


def _load_rules() -> None:
    """Import every rule before serving: checks fork, and must not fork mid-import."""
    from launchverify.registry import all_rules

    all_rules()
