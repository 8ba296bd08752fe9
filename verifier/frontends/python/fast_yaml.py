"""PyYAML's loading functions backed by libyaml in workers, where both read alike.

Launch files, and our models of the libraries they call (``moveit_configs_utils``), load
parameter files with ``yaml.safe_load``, which PyYAML runs in pure Python: a MoveIt
robot's configuration took 60-100 ms of every worker that evaluated a MoveIt launch
file. Where PyYAML was built with libyaml, the functions installed here parse with it
and build values with the same Python constructor and resolver.

The two parsers do not accept the same documents: libyaml takes tabs, ``|#`` and some
lone ``!`` and ``?`` that PyYAML refuses (or reads otherwise), and Unicode line and
byte-order marks differ. ros2 launch runs PyYAML's own, so a document holding any of
those characters outside its comments, or anything unprintable, is read by it; on the
rest (about four parameter files in five) hundreds of thousands of generated documents
read the same, and ``tests/test_fast_yaml.py`` keeps generating them. A document libyaml
refuses is read again by PyYAML, whose error is the one launch gives. A loader class of
the user's own keeps its own parser.
"""

from __future__ import annotations

import io
import re
from collections.abc import Callable
from typing import Any

import yaml

_installed: list[bool] = []
_MISSING: Any = object()
# PyYAML's own (typed loosely: called without a loader, they raise PyYAML's own error)
_LOAD: Callable[..., Any] = yaml.load
_LOAD_ALL: Callable[..., Any] = yaml.load_all
# What libyaml says of a document it cannot read (then the pure-Python loader reads it,
# and says what launch would say). Anything else, the time limit's interruption included,
# is the caller's, as it would be from the pure-Python loader.
_REFUSED = (yaml.YAMLError, UnicodeError)
# Where the two parsers were seen to disagree (see the module's docstring).
_DISAGREEING = "\t!?|>%@`\\"
_COMMENT = re.compile(r"(?:^| )#")
_QUOTE = r"""(?:"[^"\\]*"|'[^']*')"""
_ITEM = rf"(?:{_QUOTE}|[\w./+-]+)"
_QUOTED_LINE = re.compile(  # a line whose quotes all open and close on it
    rf" *(?:- )*(?:[\w./-]+: *)?(?:{_QUOTE}|\[ *(?:{_ITEM} *(?:, *{_ITEM} *)*)?\]) *")
MAX_READ = 8 * 1024 * 1024  # characters or bytes of a stream parsed at once
_BYTE_ORDER_MARKS = (b"\xff\xfe", b"\xfe\xff", b"\xef\xbb\xbf")


def install() -> None:
    """Replace PyYAML's module-level loading functions in this process (once)."""
    if _installed or not getattr(yaml, "__with_libyaml__", False):
        return
    for name, function in replacements().items():
        setattr(yaml, name, function)
    _installed.append(True)


def replacements() -> dict[str, Callable[..., Any]]:
    """Return the functions ``install`` puts in ``yaml`` (name -> function)."""
    twins = {getattr(yaml, name): getattr(yaml, "C" + name)
             for name in ("BaseLoader", "SafeLoader", "FullLoader", "Loader", "UnsafeLoader")
             if hasattr(yaml, name) and hasattr(yaml, "C" + name)}

    def reading(original: Callable[..., Any],
                collect: Callable[[Any], Any]) -> Callable[..., Any]:
        """Return ``original`` (``yaml.load`` or ``load_all``) reading with libyaml."""

        def read(stream: Any, Loader: Any = _MISSING) -> Any:
            twin = twins.get(Loader) if isinstance(Loader, type) else None
            if twin is None:  # a loader of the user's own, or none given (PyYAML's error)
                return original(stream) if Loader is _MISSING else original(stream, Loader)
            text = _text(stream)
            if _alike(text):
                try:
                    return collect(original(text, twin))
                except _REFUSED:
                    pass
            return original(_again(text, stream), Loader)

        return read

    load = reading(_LOAD, lambda value: value)
    # every document read at once: a failure part way is then PyYAML's, from the start
    load_all = reading(_LOAD_ALL, lambda documents: iter(list(documents)))
    out: dict[str, Callable[..., Any]] = {"load": load, "load_all": load_all}
    for prefix, loader in (("safe", "SafeLoader"), ("full", "FullLoader"),
                           ("unsafe", "UnsafeLoader")):
        if hasattr(yaml, loader):
            out[f"{prefix}_load"] = _with(load, getattr(yaml, loader))
            out[f"{prefix}_load_all"] = _with(load_all, getattr(yaml, loader))
    return out


def _with(function: Callable[[Any, Any], Any], loader: Any) -> Callable[[Any], Any]:
    def bound(stream: Any) -> Any:
        return function(stream, loader)

    return bound


def _text(stream: Any) -> Any:
    """Return what a stream holds (a string or bytes stay as they are).

    Read once, so that the pure-Python loader can start again from the beginning; at
    most ``MAX_READ``: a longer stream (``/dev/urandom``...) is left to PyYAML, which
    reads it a piece at a time, after what was read (``_Rest``).
    """
    read = getattr(stream, "read", None)
    if not callable(read):
        return stream
    head = read(MAX_READ + 1)
    return head if len(head) <= MAX_READ else _Rest(head, stream)


class _Rest:
    """A stream read too far to parse at once: what was read, then the rest of it."""

    def __init__(self, head: Any, stream: Any) -> None:
        self.head = head
        self.stream = stream
        if hasattr(stream, "name"):  # PyYAML names the stream in its errors
            self.name = stream.name

    def read(self, size: int = -1) -> Any:
        if not self.head:
            return self.stream.read(size)
        if size is None or size < 0:
            out, self.head = self.head + self.stream.read(), self.head[:0]
            return out
        out, self.head = self.head[:size], self.head[size:]
        return out


def _alike(text: Any) -> bool:
    """Return whether both parsers read this text alike (as far as we have seen)."""
    if isinstance(text, bytes):
        if text.startswith(_BYTE_ORDER_MARKS):
            return False
        try:
            text = text.decode("utf-8")
        except UnicodeDecodeError:
            return False
    if not isinstance(text, str) or not text.replace("\n", "").replace("\r", "").isprintable():
        return False
    code = _without_comments(text)
    return not any(character in code for character in _DISAGREEING)


def _without_comments(text: str) -> str:
    """Return the text without what both parsers surely read as comments.

    A ``#`` at the start of a line or after a space starts a comment, unless it is inside
    a quoted or block scalar. A block scalar's header (``|``, ``>``) is kept, so its text
    is read by PyYAML anyway. Quotes are understood on lines that hold a whole quoted
    value (``key: "text"``, ``- 'text'``, ``key: ["a", "b"]``); after any other quote, a
    quoted scalar may run on across lines, so nothing more is removed.
    """
    kept: list[str] = []
    quoted = False
    for line in text.splitlines():
        start = _COMMENT.search(line)
        code = line if quoted or start is None else line[:start.start()]
        if not quoted and ("'" in code or '"' in code) and not _QUOTED_LINE.fullmatch(code):
            code, quoted = line, True  # (the "comment" may be inside the quotes)
        kept.append(code)
    return "\n".join(kept)


def _again(text: Any, stream: Any) -> Any:
    """Return what to give the pure-Python loader: the stream as it was given.

    A stream's content is given as a stream again, under the same name, so that an error
    names the place as it would have (``"<file>"`` or the file's name, not a string).
    """
    if stream is text or not isinstance(text, (str, bytes)):
        return text  # (a _Rest is a stream already)
    again = io.StringIO(text) if isinstance(text, str) else io.BytesIO(text)
    if hasattr(stream, "name"):
        again.name = stream.name
    return again
