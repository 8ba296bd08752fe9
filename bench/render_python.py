"""Render a generated launch tree (``generate.El``) as a Python launch file.

The output is written the way people write Python launch files: ``DeclareLaunchArgument``,
``Node(...)`` with parameter dicts and files, ``PathJoinSubstitution([FindPackageShare(..),
...])``, ``IncludeLaunchDescription`` with ``launch_arguments={...}.items()``, conditions
from ``launch.conditions``, each file a ``generate_launch_description()``. It means the
same as the XML rendering of the tree, so the benchmark's tree stays clean whatever
format a file is written in.

Only the substitutions the generator uses are translated: ``$(var)``,
``$(find-pkg-share)``, ``$(dirname)``, ``$(eval)`` and ``$(equals)`` in conditions.
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING, Union

if TYPE_CHECKING:
    from generate import El

# Where each name the rendering may use is imported from.
IMPORTS: dict[str, str] = {
    "LaunchDescription": "launch",
    "DeclareLaunchArgument": "launch.actions",
    "ExecuteProcess": "launch.actions",
    "GroupAction": "launch.actions",
    "IncludeLaunchDescription": "launch.actions",
    "LogInfo": "launch.actions",
    "SetLaunchConfiguration": "launch.actions",
    "IfCondition": "launch.conditions",
    "UnlessCondition": "launch.conditions",
    "LaunchConfigurationEquals": "launch.conditions",
    "AnyLaunchDescriptionSource": "launch.launch_description_sources",
    "PythonLaunchDescriptionSource": "launch.launch_description_sources",
    "LaunchConfiguration": "launch.substitutions",
    "PathJoinSubstitution": "launch.substitutions",
    "PythonExpression": "launch.substitutions",
    "ThisLaunchFileDir": "launch.substitutions",
    "Node": "launch_ros.actions",
    "PushRosNamespace": "launch_ros.actions",
    "SetParameter": "launch_ros.actions",
    "SetRemap": "launch_ros.actions",
    "FindPackageShare": "launch_ros.substitutions",
}

# A parsed substitution string: literal text and ``(name, [argument parts...])`` calls.
Part = Union[str, "Call"]
Call = tuple[str, list[list[Part]]]

_NUMBER = re.compile(r"^-?[0-9]+(\.[0-9]+)?$")


def parse(text: str) -> list[Part]:
    """Split ``text`` into literal text and (nested) ``$(...)`` calls."""
    parts, end = _parse(text, 0, None)
    if end != len(text):
        raise ValueError(f"unbalanced substitution in {text!r}")
    return parts


def _parse(text: str, i: int, stop: str | None) -> tuple[list[Part], int]:
    parts: list[Part] = []
    literal = ""
    while i < len(text):
        if stop is not None and text[i] in stop:
            break
        if text.startswith("$(", i):
            if literal:
                parts.append(literal)
                literal = ""
            call, i = _call(text, i + 2)
            parts.append(call)
            continue
        literal += text[i]
        i += 1
    if literal:
        parts.append(literal)
    return parts, i


def _call(text: str, i: int) -> tuple[Call, int]:
    name = re.match(r"[a-z-]+", text[i:])
    if name is None:
        raise ValueError(f"bad substitution in {text!r}")
    i += name.end()
    args: list[list[Part]] = []
    while True:
        while i < len(text) and text[i] == " ":
            i += 1
        if i >= len(text):
            raise ValueError(f"unterminated substitution in {text!r}")
        if text[i] == ")":
            return (name.group(), args), i + 1
        if text[i] in "'\"":
            quote = text[i]
            arg, i = _parse(text, i + 1, quote)
            i += 1  # the closing quote
        else:
            arg, i = _parse(text, i, " )")
        args.append(arg)


class PythonWriter:
    """Turn one file's element tree into Python source, collecting the imports it needs."""

    def __init__(self) -> None:
        self.used: set[str] = set()

    def name(self, name: str) -> str:
        self.used.add(name)
        return name

    # ---- substitutions

    def sub(self, text: str | bool) -> str:
        """Return a Python expression for an attribute value (a ``SomeSubstitutionsType``)."""
        if isinstance(text, bool):
            return repr("true" if text else "false")
        if not text:
            return "''"
        path = self.path(text)
        if path is not None:
            return path
        return self.parts(parse(text))

    def path(self, text: str) -> str | None:
        """Render ``$(find-pkg-share p)/a/b`` and ``$(dirname)/a`` as a path join."""
        match = re.fullmatch(r"\$\((find-pkg-share ([a-z0-9_]+)|dirname)\)/([^$]+)", text)
        if match is None:
            return None
        if match.group(2):
            head = f"{self.name('FindPackageShare')}({match.group(2)!r})"
        else:
            head = f"{self.name('ThisLaunchFileDir')}()"
        tail = ", ".join(repr(segment) for segment in match.group(3).split("/"))
        return f"{self.name('PathJoinSubstitution')}([{head}, {tail}])"

    def parts(self, parts: list[Part]) -> str:
        rendered = [self.part(p) for p in parts]
        if len(rendered) == 1:
            return rendered[0]
        return "[" + ", ".join(rendered) + "]"

    def part(self, part: Part) -> str:
        if isinstance(part, str):
            return repr(part)
        name, args = part
        if name == "var":
            return f"{self.name('LaunchConfiguration')}({self.parts(args[0])})"
        if name == "find-pkg-share":
            return f"{self.name('FindPackageShare')}({self.parts(args[0])})"
        if name == "dirname":
            return f"{self.name('ThisLaunchFileDir')}()"
        if name == "eval":
            items = [self.part(p) for p in args[0]]
            return f"{self.name('PythonExpression')}([{', '.join(items)}])"
        raise ValueError(f"no Python rendering for $({name})")

    def condition(self, attrs: dict[str, str | bool]) -> str | None:
        if "if" in attrs:
            parts = parse(str(attrs["if"]))
            equals = _equals_of_var(parts)
            if equals is not None:
                return f"{self.name('LaunchConfigurationEquals')}({equals[0]!r}, {equals[1]!r})"
            return f"{self.name('IfCondition')}({self.parts(parts)})"
        if "unless" in attrs:
            return f"{self.name('UnlessCondition')}({self.sub(attrs['unless'])})"
        return None

    def words(self, text: str) -> str:
        """Return a list expression of a command line's words (each may hold substitutions)."""
        words: list[list[Part]] = [[]]
        for part in parse(text):
            if not isinstance(part, str):
                words[-1].append(part)
                continue
            pieces = part.split(" ")
            for index, piece in enumerate(pieces):
                if index:
                    words.append([])
                if piece:
                    words[-1].append(piece)
        return "[" + ", ".join(self.parts(word) for word in words if word) + "]"

    # ---- actions

    def actions(self, elements: list[El], indent: int) -> list[str]:
        out: list[str] = []
        for el in elements:
            if el.comment:
                out.append(" " * indent + f"# {el.comment}")
            lines = self.action(el, indent).split("\n")
            lines[-1] += ","
            out.extend(lines)
        return out

    def action(self, el: El, indent: int) -> str:
        pad = " " * indent
        attrs = el.attrs
        keywords: list[str] = []
        if el.tag == "arg":
            keywords.append(repr(attrs["name"]))
            if "default" in attrs:
                keywords.append(f"default_value={self.sub(attrs['default'])}")
            if "description" in attrs:
                keywords.append(f"description={attrs['description']!r}")
            if el.kids:
                keywords.append(f"choices={[str(k.attrs['value']) for k in el.kids]!r}")
            return self.call(pad, "DeclareLaunchArgument", keywords)
        if el.tag == "let":
            return self.call(pad, "SetLaunchConfiguration",
                             [repr(attrs["name"]), self.sub(attrs["value"])])
        if el.tag == "push_ros_namespace":
            return self.call(pad, "PushRosNamespace", [self.sub(attrs["namespace"])])
        if el.tag == "set_remap":
            return self.call(pad, "SetRemap", [f"src={self.sub(attrs['from'])}",
                                               f"dst={self.sub(attrs['to'])}"])
        if el.tag == "set_parameter":
            return self.call(pad, "SetParameter", [f"name={attrs['name']!r}",
                                                   f"value={self.sub(attrs['value'])}"])
        if el.tag == "log":
            return self.call(pad, "LogInfo", [f"msg={self.sub(attrs['message'])}"])
        if el.tag == "executable":
            keywords = [f"cmd={self.words(str(attrs['cmd']))}"]
            if "output" in attrs:
                keywords.append(f"output={attrs['output']!r}")
            return self.call(pad, "ExecuteProcess", self.conditioned(keywords, attrs))
        if el.tag == "group":
            body = "\n".join(self.actions(el.kids, indent + 8))
            keywords = [f"[\n{body}\n{pad}    ]"]
            return self.call(pad, "GroupAction", self.conditioned(keywords, attrs))
        if el.tag == "include":
            return self.include(el, pad)
        if el.tag == "node":
            return self.node(el, pad)
        raise ValueError(f"no Python rendering for <{el.tag}>")

    def conditioned(self, keywords: list[str], attrs: dict[str, str | bool]) -> list[str]:
        condition = self.condition(attrs)
        return [*keywords, f"condition={condition}"] if condition else keywords

    def call(self, pad: str, callee: str, arguments: list[str]) -> str:
        self.name(callee)
        one_line = f"{pad}{callee}({', '.join(arguments)})"
        if len(one_line) <= 96 and "\n" not in one_line:
            return one_line
        inner = "".join(f"{pad}    {argument},\n" for argument in arguments)
        return f"{pad}{callee}(\n{inner}{pad})"

    def include(self, el: El, pad: str) -> str:
        target = str(el.attrs["file"])
        source = ("PythonLaunchDescriptionSource" if target.endswith(".py")
                  else "AnyLaunchDescriptionSource")
        keywords = [f"{self.name(source)}({self.sub(target)})"]
        if el.kids:
            items = ", ".join(f"{k.attrs['name']!r}: {self.sub(k.attrs['value'])}"
                              for k in el.kids)
            keywords.append(f"launch_arguments={{{items}}}.items()")
        return self.call(pad, "IncludeLaunchDescription", keywords)

    def node(self, el: El, pad: str) -> str:
        attrs = el.attrs
        keywords = [f"package={attrs['pkg']!r}", f"executable={attrs['exec']!r}",
                    f"name={attrs['name']!r}"]
        if "namespace" in attrs:
            keywords.append(f"namespace={self.sub(attrs['namespace'])}")
        if "output" in attrs:
            keywords.append(f"output={attrs['output']!r}")
        if attrs.get("respawn"):
            keywords.append("respawn=True")
        if "respawn_delay" in attrs:
            keywords.append(f"respawn_delay={attrs['respawn_delay']}")
        if "args" in attrs:
            keywords.append(f"arguments={self.words(str(attrs['args']))}")
        if "ros_args" in attrs:
            keywords.append(f"ros_arguments={self.words(str(attrs['ros_args']))}")
        parameters = self.parameters([k for k in el.kids if k.tag == "param"])
        if parameters:
            keywords.append(f"parameters=[{', '.join(parameters)}]")
        remaps = [f"({self.sub(k.attrs['from'])}, {self.sub(k.attrs['to'])})"
                  for k in el.kids if k.tag == "remap"]
        if remaps:
            keywords.append(f"remappings=[{', '.join(remaps)}]")
        return self.call(pad, "Node", self.conditioned(keywords, attrs))

    def parameters(self, params: list[El]) -> list[str]:
        """Return the ``parameters=[...]`` items: files as paths, values as dicts, in order."""
        items: list[str] = []
        pending: list[str] = []
        for param in params:
            if "from" in param.attrs:
                if pending:
                    items.append("{" + ", ".join(pending) + "}")
                    pending = []
                items.append(self.sub(param.attrs["from"]))
            else:
                pending.append(f"{param.attrs['name']!r}: {self.value(param)}")
        if pending:
            items.append("{" + ", ".join(pending) + "}")
        return items

    def value(self, param: El) -> str:
        if param.kids:
            return "{" + ", ".join(f"{k.attrs['name']!r}: {self.value(k)}"
                                   for k in param.kids) + "}"
        value = param.attrs["value"]
        if isinstance(value, bool) or value in ("true", "false"):
            return repr(value in (True, "true"))
        if _NUMBER.match(str(value)):
            return str(value)
        return self.sub(value)

    # ---- whole file

    def file(self, root: El, comment: str) -> str:
        body = "\n".join(self.actions(root.kids, 8))
        self.used.add("LaunchDescription")
        by_module: dict[str, list[str]] = {}
        for name in sorted(self.used):
            by_module.setdefault(IMPORTS[name], []).append(name)
        imports = [f"from {module} import {', '.join(names)}"
                   for module, names in sorted(by_module.items())]
        return (f'"""{comment}."""\n\n' + "\n".join(imports) + "\n\n\n"
                "def generate_launch_description():\n"
                "    return LaunchDescription([\n"
                f"{body}\n"
                "    ])\n")


def _equals_of_var(parts: list[Part]) -> tuple[str, str] | None:
    """Return (argument, value) for ``$(equals $(var a) value)``, the common case."""
    if len(parts) != 1 or isinstance(parts[0], str) or parts[0][0] != "equals":
        return None
    left, right = parts[0][1]
    if (len(left) == 1 and not isinstance(left[0], str) and left[0][0] == "var"
            and len(right) == 1 and isinstance(right[0], str)):
        name = left[0][1][0]
        if len(name) == 1 and isinstance(name[0], str):
            return name[0], right[0]
    return None


def render_python(root: El, comment: str) -> str:
    """Return the Python launch file for ``root`` (a ``<launch>`` element)."""
    return PythonWriter().file(root, comment)
