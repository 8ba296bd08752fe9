"""Parsing source files with tree-sitter, imported only when extraction runs.

tree-sitter parses code that does not compile here (missing headers, macros, a newer
standard) into a tree with error nodes instead of failing; we read what it recovered.
"""

from __future__ import annotations

from functools import lru_cache
from typing import TYPE_CHECKING

from launchverify.span import Span

if TYPE_CHECKING:
    from pathlib import Path

    from tree_sitter import Node, Parser, Tree


@lru_cache(maxsize=2)
def _parser(language: str) -> Parser:
    import tree_sitter

    if language == "cpp":
        import tree_sitter_cpp as grammar
    else:
        import tree_sitter_python as grammar  # type: ignore[no-redef]
    return tree_sitter.Parser(tree_sitter.Language(grammar.language()))


def parse(language: str, data: bytes) -> Tree:
    """Return the syntax tree of ``data`` in ``language`` (``cpp`` or ``python``)."""
    return _parser(language).parse(data)


def text(node: Node | None) -> str:
    """Return a node's source text."""
    if node is None or node.text is None:
        return ""
    return node.text.decode("utf-8", "replace")


def span(file: Path, node: Node) -> Span:
    """Return the 1-based span of a node (columns count bytes, as tree-sitter does)."""
    return Span(file, node.start_point[0] + 1, node.start_point[1] + 1,
                node.end_point[0] + 1, node.end_point[1] + 1)


def walk(node: Node) -> list[Node]:
    """Return every named node below ``node`` (itself included), in source order."""
    out: list[Node] = []
    stack = [node]
    while stack:
        current = stack.pop()
        out.append(current)
        stack.extend(reversed(current.named_children))
    return out


def short(code: str, limit: int = 60) -> str:
    """Return code on one line, cut to ``limit`` characters, for messages."""
    flat = " ".join(code.split())
    return flat if len(flat) <= limit else flat[: limit - 1] + "…"


def damaged(root: Node) -> bool:
    """Return whether the parser had to skip code (an error node, a missing token).

    A missing ``;`` alone does not count: ``RCLCPP_COMPONENTS_REGISTER_NODE(x)`` and other
    macros are written without one, and the tree around them is whole.
    """
    stack = [root]
    while stack:
        node = stack.pop()
        if node.type == "ERROR" or (node.is_missing and node.type != ";"):
            return True
        stack.extend(child for child in node.children if child.has_error)
    return False
