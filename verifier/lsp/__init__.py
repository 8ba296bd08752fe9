"""The language server, ``launchverify lsp``: findings in the editor as you type.

It speaks the Language Server Protocol through pygls, an optional dependency (the
``lsp`` extra: ``pip install '.[lsp]'`` in a clone). Nothing here imports pygls at module
level: the command line imports this package only for ``lsp``, and ``serve`` says clearly
when pygls is missing instead of failing with a traceback.
"""

from __future__ import annotations

from launchverify.engine import UsageError

INSTALL_HINT = "pip install 'pygls>=2,<3' (the [lsp] extra of launchverify)"


def serve(tcp: str | None = None) -> int:
    """Run the server on standard input and output, or on ``HOST:PORT``; return the status.

    Raises:
        UsageError: when pygls is not installed, or ``tcp`` is not ``HOST:PORT``.
    """
    address = parse_address(tcp) if tcp is not None else None
    try:
        from launchverify.lsp.server import run
    except ImportError as error:
        if (error.name or "").partition(".")[0] not in ("pygls", "lsprotocol"):
            raise
        raise UsageError(f"the language server needs pygls: {INSTALL_HINT}") from None
    return run(address)


def parse_address(text: str) -> tuple[str, int]:
    """Return ``(host, port)`` from ``HOST:PORT`` (``[::1]:PORT`` for IPv6)."""
    host, colon, port = text.rpartition(":")
    host = host.removeprefix("[").removesuffix("]")
    if not colon or not host or not port.isdigit() or not 0 < int(port) < 65536:
        raise UsageError(f"--tcp {text!r}: expected HOST:PORT, such as 127.0.0.1:2087")
    return host, int(port)
