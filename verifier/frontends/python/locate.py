"""Where a launch file writes the pieces of a call: the keys of a keyword's dict or pairs.

Python values do not know where they were written: the string ``'robot_nam'`` in
``launch_arguments={'robot_nam': 'r1'}.items()`` is just a string. A finding about that
one argument belongs at its key, not at ``IncludeLaunchDescription(`` (ruff points at the
expression; so do we). The models record where each call was made (line and columns);
the file's syntax tree says what is written inside it. Only reading: nothing runs.
"""

from __future__ import annotations

import ast
import functools
from pathlib import Path

from launchverify.span import Span, character_column
from launchverify.workspace.reading import read_file, unsaved

MAX_SOURCE_BYTES = 2 << 20  # a launch file, not a generated blob


Calls = dict[tuple[int, int], ast.Call]
Assignments = dict[str, list[ast.expr]]
Lines = tuple[bytes, ...]
Parsed = tuple[Calls, Assignments, Lines]


class CallLocator:
    """Finds what is written inside a call, by the call's position.

    Parsed files are shared by every locator of a process (an OpaqueFunction's converter
    asks about the same file as the launch file's); each locator looks a file up once.
    """

    def __init__(self) -> None:
        self._files: dict[Path, Parsed] = {}

    def keyword_keys(self, call: Span, keyword: str) -> dict[str, Span]:
        """Return the span of each literal key of ``keyword=`` in the call at ``call``.

        The value may be a dict, ``{...}.items()``, a list or tuple of pairs, or a name
        bound to one of those in the same file. Keys computed at run time are left out.

        Examples:
            >>> import tempfile, textwrap
            >>> folder = Path(tempfile.mkdtemp())
            >>> file = folder / "x.launch.py"
            >>> _ = file.write_text(textwrap.dedent('''
            ...     f(launch_arguments={'a': 1,
            ...                         'bb': 2}.items())
            ... '''))
            >>> spans = CallLocator().keyword_keys(Span(file, 2, 1), "launch_arguments")
            >>> [(k, s.line, s.column) for k, s in spans.items()]
            [('a', 2, 21), ('bb', 3, 21)]
        """
        return self._keys(call.file, self._keyword(call, keyword))

    def keyword_values(self, call: Span) -> dict[str, Span]:
        """Return the span of each keyword argument's value in the call at ``call``.

        Examples:
            >>> import tempfile
            >>> file = Path(tempfile.mkdtemp()) / "x.launch.py"
            >>> _ = file.write_text("Node(package='a',"  + chr(10) + "     name='b')")
            >>> {k: (s.line, s.column) for k, s in CallLocator().keyword_values(
            ...     Span(file, 1, 1)).items()}
            {'package': (1, 14), 'name': (2, 11)}
        """
        node = self._call(call)
        if node is None:
            return {}
        lines = self._parsed(call.file)[2]
        return {k.arg: _span(lines, call.file, k.value) for k in node.keywords
                if k.arg is not None}

    def keyword_items(self, call: Span, keyword: str) -> list[tuple[Span, dict[str, Span]]]:
        """Return each item of the literal list given as ``keyword=``, with its dict keys.

        ``parameters=[path, {'rate': 10}]`` gives the span of ``path``, and of the dict
        with the span of ``'rate'``. A list that is not written out (built at run time)
        gives nothing.
        """
        value = self._bound(call.file, self._keyword(call, keyword))
        if not isinstance(value, (ast.List, ast.Tuple)) or any(
                isinstance(item, ast.Starred) for item in value.elts):
            return []
        lines = self._parsed(call.file)[2]
        return [(_span(lines, call.file, item), self._keys(call.file, item, follow=False))
                for item in value.elts]

    def literal(self, call: Span, text: str, *, position: int | None = None,
                keyword: str | None = None, item: int | None = None,
                items: int | None = None) -> Span | None:
        """Return where ``text`` is written, inside its quotes, as an argument of the call.

        The argument is the call's ``position``-th one or its ``keyword=`` one (``item``:
        an item of the list or tuple written there). Only a plain string literal spelling
        exactly ``text`` (no prefix, escape or implicit concatenation) is located, so that
        a fix can replace it; columns count characters. With ``item``, the list must
        have ``items`` items when given (a value built from more than what is written
        there is not located).

        Examples:
            >>> import tempfile
            >>> file = Path(tempfile.mkdtemp()) / "x.launch.py"
            >>> _ = file.write_text("Node(package='démo', executable=r'talker')")
            >>> where = CallLocator().literal(Span(file, 1, 1), "démo", keyword="package")
            >>> (where.column, where.end_column)
            (15, 19)
            >>> CallLocator().literal(Span(file, 1, 1), "talker", keyword="executable") is None
            True
        """
        node = self._call(call)
        if node is None:
            return None
        value: ast.expr | None = None
        if position is not None and position < len(node.args):
            value = node.args[position]
        elif keyword is not None:
            value = self._keyword(call, keyword)
        if item is not None:
            if not isinstance(value, (ast.List, ast.Tuple)) or not (
                    -len(value.elts) <= item < len(value.elts)) or any(
                    isinstance(entry, ast.Starred) for entry in value.elts) or (
                    items is not None and len(value.elts) != items):
                return None
            value = value.elts[item]
        return self._literal(call.file, value, text)

    def key_literal(self, call: Span, keyword: str, key: str) -> Span | None:
        """Return where a key of the call's ``keyword=`` dict or pairs is written (see above)."""
        value = self._bound(call.file, self._keyword(call, keyword))
        if (isinstance(value, ast.Call) and isinstance(value.func, ast.Attribute)
                and value.func.attr == "items" and not value.args):
            value = self._bound(call.file, value.func.value)
        nodes: list[ast.expr] = []
        if isinstance(value, ast.Dict):
            nodes = [k for k in value.keys if k is not None]
        elif isinstance(value, (ast.List, ast.Tuple)):
            nodes = [entry.elts[0] for entry in value.elts
                     if isinstance(entry, ast.Tuple) and len(entry.elts) == 2]
        found = [node for node in nodes
                 if isinstance(node, ast.Constant) and node.value == key]
        return self._literal(call.file, found[0], key) if len(found) == 1 else None

    def _literal(self, file: Path, node: ast.expr | None, text: str) -> Span | None:
        """Return the span inside the quotes of a plain one-line literal spelling ``text``."""
        if (not isinstance(node, ast.Constant) or node.value != text or not text
                or node.end_lineno != node.lineno or node.end_col_offset is None):
            return None
        lines = self._parsed(file)[2]
        if not 0 < node.lineno <= len(lines) or (node.lineno == 1 and lines[0].startswith(
                b"\xef\xbb\xbf")):  # columns after a byte-order mark are ambiguous
            return None
        line = lines[node.lineno - 1]
        try:
            before = line[:node.col_offset].decode()
            written = line[node.col_offset:node.end_col_offset].decode()
        except UnicodeDecodeError:
            return None
        if len(written) < 2 or written[0] not in "'\"" or written[-1] != written[0] \
                or written[1:-1] != text:
            return None
        column = len(before) + 2  # 1-based, after the opening quote
        return Span(file, node.lineno, column, node.lineno, column + len(text))

    def _keys(self, file: Path, value: ast.expr | None, *, follow: bool = True
              ) -> dict[str, Span]:
        """Return the literal keys of a dict (or ``.items()`` of one) or of a list of pairs.

        ``follow``: a name stands for the value the file binds it to (not for an item of
        a list, whose findings stay at the item).
        """
        if follow:
            value = self._bound(file, value)
        if (isinstance(value, ast.Call) and isinstance(value.func, ast.Attribute)
                and value.func.attr == "items" and not value.args):
            value = value.func.value  # {...}.items()
            if follow:
                value = self._bound(file, value)
        if isinstance(value, ast.Dict):
            return {key.value: _span(self._parsed(file)[2], file, key) for key in value.keys
                    if isinstance(key, ast.Constant) and isinstance(key.value, str)}
        found: dict[str, Span] = {}
        if isinstance(value, (ast.List, ast.Tuple)):
            for item in value.elts:
                if (isinstance(item, ast.Tuple) and len(item.elts) == 2
                        and isinstance(key := item.elts[0], ast.Constant)
                        and isinstance(key.value, str)):
                    found.setdefault(key.value, _span(self._parsed(file)[2], file, key))
        return found

    def _bound(self, file: Path, value: ast.expr | None) -> ast.expr | None:
        """Follow a name to the one value the file binds it to (no guessing among several)."""
        for _ in range(3):
            if not isinstance(value, ast.Name):
                return value
            bound = self._parsed(file)[1].get(value.id, [])
            value = bound[0] if len(bound) == 1 else None
        return None if isinstance(value, ast.Name) else value

    def _keyword(self, call: Span, keyword: str) -> ast.expr | None:
        node = self._call(call)
        return None if node is None else next(
            (k.value for k in node.keywords if k.arg == keyword), None)

    def _call(self, where: Span) -> ast.Call | None:
        return self._parsed(where.file)[0].get((where.line, where.column))

    def _parsed(self, file: Path) -> Parsed:
        found = self._files.get(file)
        if found is None:
            buffered = unsaved(file)
            if buffered is not None:  # an editor's buffer, not the file on disk
                found = _parse(buffered, file)
            else:
                try:
                    stat = file.stat()
                except OSError:
                    found = ({}, {}, ())
                else:
                    found = _index(file, stat.st_mtime_ns, stat.st_size)
            self._files[file] = found
        return found


@functools.lru_cache(maxsize=32)
def _index(file: Path, mtime_ns: int, size: int) -> Parsed:
    """Parse one version of a file; index its calls by position and its simple assignments."""
    if size > MAX_SOURCE_BYTES:
        return {}, {}, ()
    try:
        data = read_file(file)
    except OSError:
        return {}, {}, ()
    return _parse(data, file)


def _parse(data: bytes, file: Path) -> Parsed:
    if len(data) > MAX_SOURCE_BYTES:
        return {}, {}, ()
    try:
        tree = ast.parse(data, filename=str(file))
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return {}, {}, ()
    calls: Calls = {}
    assignments: Assignments = {}
    lines = tuple(data.split(b"\n"))
    for node in ast.walk(tree):
        if isinstance(node, ast.Call):
            calls[(node.lineno, _column(lines, node.lineno, node.col_offset))] = node
        elif isinstance(node, ast.Assign):
            for target in node.targets:
                if isinstance(target, ast.Name):
                    assignments.setdefault(target.id, []).append(node.value)
    return calls, assignments, lines


def _span(lines: tuple[bytes, ...], file: Path, node: ast.expr) -> Span:
    """Return the span of a node (columns 1-based and in characters, as every span)."""
    end = node.end_lineno or node.lineno
    end_column = (_column(lines, end, node.end_col_offset)
                  if node.end_col_offset is not None else None)
    return Span(file, node.lineno, _column(lines, node.lineno, node.col_offset),
                node.end_lineno, end_column)


def _column(lines: tuple[bytes, ...], number: int, offset: int) -> int:
    """Return the 1-based character column of a UTF-8 byte ``offset`` (ast's) in a line."""
    return character_column(lines[number - 1], offset) if 0 < number <= len(lines) \
        else offset + 1
