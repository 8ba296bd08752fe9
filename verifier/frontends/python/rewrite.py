"""How a launch file's code is compiled: ``raise``, ``except`` and ``match`` see unknowns.

Python insists that what a ``raise`` raises and what an ``except`` clause names are
exception classes, and a ``match`` statement's patterns read its subject's type at the C
level: none of that asks a value anything, so an unknown value (a vendor's exception
class, a string to Python) cannot answer as the data model's table says it should
(``models/launch_api/data_model.py``). The compiled file asks instead: each of those
places calls a function of the launch file's builtins (``unknown.LAUNCH_BUILTINS``) that turns
an unknown into what the table rules. Lines and columns stay the source's, so every
finding points where it did.
"""

from __future__ import annotations

import ast
from types import CodeType

RAISED, CAUGHT, SUBJECT = ("__launchverify_raised__", "__launchverify_caught__",
                           "__launchverify_subject__")


class _AskingUnknowns(ast.NodeTransformer):
    """Wrap the values of ``raise``, ``except`` and ``match`` in the builtins' calls."""

    def visit_Raise(self, node: ast.Raise) -> ast.Raise:
        self.generic_visit(node)
        if node.exc is not None:
            node.exc = _call(RAISED, node.exc)
        if node.cause is not None:
            node.cause = _call(RAISED, node.cause)
        return node

    def visit_ExceptHandler(self, node: ast.ExceptHandler) -> ast.ExceptHandler:
        self.generic_visit(node)
        if node.type is not None:
            node.type = _call(CAUGHT, node.type)
        return node

    def visit_Match(self, node: ast.Match) -> ast.Match:
        self.generic_visit(node)
        node.subject = _call(SUBJECT, node.subject)
        return node


def _call(function: str, value: ast.expr) -> ast.expr:
    call = ast.Call(func=ast.Name(id=function, ctx=ast.Load()), args=[value], keywords=[])
    return ast.copy_location(call, value)


def compile_launch_file(data: bytes | str, filename: str) -> CodeType:
    """Compile a launch file's source as its code runs under launchverify.

    Raises what ``compile`` raises for invalid source (``SyntaxError``, ``ValueError``...).
    """
    tree = ast.parse(data, filename=filename)
    tree = ast.fix_missing_locations(_AskingUnknowns().visit(tree))
    return compile(tree, filename, "exec", dont_inherit=True)
