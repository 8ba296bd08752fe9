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

from launchverify.span import Span

MAX_SOURCE_BYTES = 2 << 20  # a launch file, not a generated blob


Calls = dict[tuple[int, int], ast.Call]
Assignments = dict[str, list[ast.expr]]


class CallLocator:
    """Finds the keys written in a keyword argument of a call, by the call's position.

    Every locator of a process shares the parsed files (an OpaqueFunction's converter
    asks about the same file as the launch file's).
    """

    def __init__(self) -> None:
        self._assignments: dict[Path, Assignments] = {}

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
        node = self._call(call)
        if node is None:
            return {}
        value = next((k.value for k in node.keywords if k.arg == keyword), None)
        return {} if value is None else self._keys(call.file, value, depth=0)

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
        return {k.arg: _span(call.file, k.value) for k in node.keywords if k.arg is not None}

    def keyword_items(self, call: Span, keyword: str) -> list[tuple[Span, dict[str, Span]]]:
        """Return each item of the literal list given as ``keyword=``, with its dict keys.

        ``parameters=[path, {'rate': 10}]`` gives the span of ``path``, and of the dict
        with the span of ``'rate'``. A list that is not written out (built at run time)
        gives nothing.
        """
        node = self._call(call)
        value = None if node is None else next(
            (k.value for k in node.keywords if k.arg == keyword), None)
        if isinstance(value, ast.Name):
            bound = self._assignments.get(call.file, {}).get(value.id, [])
            value = bound[0] if len(bound) == 1 else None
        if not isinstance(value, (ast.List, ast.Tuple)):
            return []
        if any(isinstance(item, ast.Starred) for item in value.elts):
            return []
        return [(_span(call.file, item), self._keys(call.file, item, depth=3))
                for item in value.elts]

    def _keys(self, file: Path, value: ast.expr, depth: int) -> dict[str, Span]:
        if (isinstance(value, ast.Call) and isinstance(value.func, ast.Attribute)
                and value.func.attr == "items" and not value.args):
            value = value.func.value  # {...}.items()
        if isinstance(value, ast.Dict):
            return {key.value: _span(file, key) for key in value.keys
                    if isinstance(key, ast.Constant) and isinstance(key.value, str)}
        if isinstance(value, (ast.List, ast.Tuple)):
            found: dict[str, Span] = {}
            for item in value.elts:
                if (isinstance(item, ast.Tuple) and len(item.elts) == 2
                        and isinstance(key := item.elts[0], ast.Constant)
                        and isinstance(key.value, str)):
                    found.setdefault(key.value, _span(file, key))
            return found
        if isinstance(value, ast.Name) and depth < 3:
            bound = self._assignments.get(file, {}).get(value.id, [])
            if len(bound) == 1:  # one binding in the file: no guessing which one ran
                return self._keys(file, bound[0], depth + 1)
        return {}

    def _call(self, where: Span) -> ast.Call | None:
        try:
            stat = where.file.stat()
        except OSError:
            return None
        calls, assignments = _index(where.file, stat.st_mtime_ns, stat.st_size)
        self._assignments[where.file] = assignments
        return calls.get((where.line, where.column))


@functools.lru_cache(maxsize=32)
def _index(file: Path, mtime_ns: int, size: int) -> tuple[Calls, Assignments]:
    """Parse one version of a file; index its calls by position and its simple assignments."""
    if size > MAX_SOURCE_BYTES:
        return {}, {}
    try:
        tree = ast.parse(file.read_bytes(), filename=str(file))
    except (OSError, SyntaxError, ValueError, RecursionError, MemoryError):
        return {}, {}
    calls: Calls = {}
    assignments: Assignments = {}
    for node in ast.walk(tree):
        if isinstance(node, ast.Call):
            calls[(node.lineno, node.col_offset + 1)] = node
        elif isinstance(node, ast.Assign):
            for target in node.targets:
                if isinstance(target, ast.Name):
                    assignments.setdefault(target.id, []).append(node.value)
    return calls, assignments


def _span(file: Path, node: ast.expr) -> Span:
    """Return the span of a node (columns 1-based, as every span)."""
    end_column = node.end_col_offset + 1 if node.end_col_offset is not None else None
    return Span(file, node.lineno, node.col_offset + 1, node.end_lineno, end_column)
