r"""Text from checked files, made inert before it reaches a terminal or a text report.

Names, values and source lines come from files a pull request wrote. Raw, they could move
a reviewer's cursor, erase lines, set the clipboard (OSC 52) or a window title, forge
extra finding lines, or reorder what is shown (bidi overrides). Every such character is
shown visibly instead, as git and ruff do: ``\x1b``, ``\u202e``. Text that has no
UTF-8 form is shown too (``encodable``): an undecodable file-name byte as ``\xff``, a
lone surrogate as ``\ud800``; written raw, it would end the output half way.

Machine formats (JSON, SARIF, the language server) keep values exact: their encoders
escape what they must (``encodable.write_json`` for lone surrogates).
"""

from __future__ import annotations

from typing import TextIO

from launchverify.render.encodable import SURROGATES

# Bidi embeddings, overrides, isolates and marks; line and paragraph separators (they
# break a line on some terminals and editors).
_INVISIBLE = (0x061C, 0x200E, 0x200F, *range(0x202A, 0x202F), *range(0x2066, 0x206A),
              0x2028, 0x2029)


def _escape(code: int) -> str:
    return f"\\x{code:02x}" if code < 0x100 else f"\\u{code:04x}"


def _table(*, escape_newlines: bool) -> dict[int, str]:
    codes = [*range(0x20), 0x7F, *range(0x80, 0xA0), *_INVISIBLE]
    kept = {0x09} if escape_newlines else {0x09, 0x0A}  # tabs are expanded by the renderers
    return {**{code: _escape(code) for code in codes if code not in kept}, **SURROGATES}


_IN_LINE = _table(escape_newlines=True)
_IN_TEXT = _table(escape_newlines=False)


def inert(text: str) -> str:
    r"""Return text for one line of human output: every control character shown visibly.

    Line breaks are escaped too, so a name cannot forge another finding line; lone
    surrogates are shown (``\xff``, ``\ud800``), so the text can always be encoded.
    """
    return text.translate(_IN_LINE)


def inert_block(text: str) -> str:
    """Return text of several lines for human output: like ``inert``, line feeds kept."""
    return text.translate(_IN_TEXT)


class InertWriter:
    """A text stream for plain-text dumps written a line per ``write`` (or ``print``).

    Each write is made ``inert``, its final line feed kept (the graph and node
    interfaces listings print names from checked files).
    """

    def __init__(self, out: TextIO) -> None:
        self.out = out

    def write(self, text: str) -> int:
        """Write ``text`` with its control characters shown visibly."""
        if text.endswith("\n"):
            return self.out.write(inert(text[:-1]) + "\n")
        return self.out.write(inert(text))

    def flush(self) -> None:
        """Flush the stream below."""
        self.out.flush()
