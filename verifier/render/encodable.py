r"""Text every output can carry: what cannot be encoded is shown as an escape, never raised on.

Two kinds of text from checked files have no UTF-8 form. A file name whose bytes are not
UTF-8 reaches launchverify through ``surrogateescape`` (the byte ``\xff`` as U+DCFF), and
a Python launch file can build a string holding any lone surrogate (``'\ud800'``).
Written as they are, either ends an output half way with ``UnicodeEncodeError``. Every
format shows them as text instead: an undecodable file-name byte (U+DC80..U+DCFF) as
``\xff``, any other lone surrogate as ``\ud800``. JSON and SARIF carry that text too (the
characters backslash, ``x``, ``f``, ``f``), not a ``\udcff`` JSON escape, which is valid
JSON that many consumers refuse.

The renderers make their text encodable by construction (``inert`` shows surrogates,
``write_json`` for the JSON formats); ``escape_unencodable`` is the last net under the
standard streams, for what a stream's encoding cannot hold besides (``é`` on an ASCII
terminal: ``\xe9``).
"""

from __future__ import annotations

import codecs
import io
import json
import re
from typing import Any, TextIO

ERRORS = "launchverify.escape"  # the codec error handler the standard streams get
_LONE = re.compile("[\ud800-\udfff]")
_NOT_A_BYTE = re.compile("[\ud800-\udc7f\udd00-\udfff]")  # surrogates no file name decodes to


def shown(code: int) -> str:
    r"""Return how one character that cannot be encoded is shown.

    An undecodable byte of a file name as ``\xff`` (what it was); anything else as
    Python writes it: ``\ud800``, ``\xe9``, ``\U0001f600``.
    """
    if 0xDC80 <= code <= 0xDCFF:
        return f"\\x{code - 0xDC00:02x}"
    if code < 0x100:
        return f"\\x{code:02x}"
    return f"\\u{code:04x}" if code < 0x10000 else f"\\U{code:08x}"


# Every lone surrogate and how it is shown, as a ``str.translate`` table.
SURROGATES: dict[int, str] = {code: shown(code) for code in range(0xD800, 0xE000)}


def escape_surrogates(text: str) -> str:
    r"""Return ``text`` with every lone surrogate shown as text (``\xff``, ``\ud800``)."""
    if text.isascii() or _LONE.search(text) is None:  # nearly always: as fast as a scan
        return text
    return text.translate(SURROGATES)


def path_bytes(text: str) -> bytes:
    r"""Return the bytes of a path as the file system holds them (for a URI).

    An undecodable byte goes back to itself (``%FF`` once quoted: the file's real name);
    a lone surrogate that no file name decodes to is shown as text (``\ud800``).
    """
    return _NOT_A_BYTE.sub(lambda match: shown(ord(match.group())), text).encode(
        "utf-8", "surrogateescape")


def without_surrogates(value: Any) -> Any:
    """Return a JSON-ready value with every string (keys too) made encodable."""
    if isinstance(value, str):
        return escape_surrogates(value)
    if isinstance(value, dict):
        return {without_surrogates(key): without_surrogates(item) for key, item in value.items()}
    if isinstance(value, (list, tuple)):
        return [without_surrogates(item) for item in value]
    return value


def json_text(document: Any, *, indent: int | None = 2) -> str:
    r"""Return ``document`` as JSON text (ASCII) in which no lone surrogate is left.

    ``json`` writes a lone surrogate as the escape ``\udcff``; a surrogate pair (a
    character beyond U+FFFF) is written with the same prefix. Only a document whose text
    has one is walked and written again, its surrogates shown (``escape_surrogates``).
    """
    text = json.dumps(document, indent=indent)
    if "\\ud" in text:
        text = json.dumps(without_surrogates(document), indent=indent)
    return text


def write_json(document: Any, out: TextIO, *, indent: int | None = 2) -> None:
    """Write ``document`` as JSON text and a line feed (see ``json_text``)."""
    out.write(json_text(document, indent=indent) + "\n")


def _escape(error: UnicodeError) -> tuple[str, int]:
    """Show what an encoding cannot hold as ``shown`` does (a codec error handler)."""
    if not isinstance(error, UnicodeEncodeError):
        raise error
    text = error.object[error.start:error.end]
    return "".join(shown(ord(character)) for character in text), error.end


codecs.register_error(ERRORS, _escape)


def escape_unencodable(*streams: object) -> None:
    r"""Make text streams show what their encoding cannot hold instead of raising.

    The last net under the renderers, for the standard streams: with
    ``PYTHONIOENCODING=ascii`` a name ``é`` is written ``\xe9``, and a lone surrogate
    that reached a stream past the renderers is shown as they show it. Streams that are
    not plain text files (a test's capture, a ``StringIO``) are left as they are.
    """
    for stream in streams:
        if isinstance(stream, io.TextIOWrapper):
            try:
                stream.reconfigure(errors=ERRORS)
            except (ValueError, OSError):  # closed, or written through a buffer mid-way
                continue
