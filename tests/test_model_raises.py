"""Every ``raise`` in the launch API's models, classified: an error rests only on facts.

A model that raises on a value launchverify cannot know (an absent vendor module's,
``unknown.Opaque``) reports the launch file's failure (LV002) on no fact. The model sweep
(``tests/test_model_sweep.py``) feeds unknowns to every parameter, by example; this test
covers every ``raise`` by construction (issue 43). It reads the models' source, and each
``raise`` must be in ``RAISES`` with its kind, so that a new model's validation is
classified the day it lands. One that judges a value the launch file gave (``VALIDATES``,
and ``FILE``) must follow a guard that asks whether the value is unknown (``GUARDS``): in
its own function, or in every function that calls it (``callers``, all of them checked).
"""

from __future__ import annotations

import ast
import enum
import functools
from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass
from pathlib import Path

import pytest

from launchverify.frontends.python.convert import placeholder_sub
from launchverify.ir import subst as s
from launchverify.models.launch_api.unknown import Opaque, UnknownInstance

ROOT = Path(__file__).resolve().parent.parent
MODELS = ROOT / "models" / "launch_api"
# Not models of launch: data_model.py is a table (a raise there is a probe's text),
# unknown.py is the unknown value itself (its raises are Python's protocols: an
# AttributeError for a dunder or for launchverify's own probe, StopAsyncIteration ending a
# loop, the launch file's own exception passed on) and placeholders.py marks and counts
# unknowns (it raises nothing). tests/test_data_model.py covers what they do.
INFRASTRUCTURE = frozenset({"data_model.py", "unknown.py", "placeholders.py"})
# Where the callers of a raise's function are looked for: all of launchverify's source.
PACKAGES = ("verifier", "models", "rules")


class Kind(enum.Enum):
    """Why a raise is no error resting on an unknown."""

    VALIDATES = "judges a value the launch file gave: only after a guard for unknowns"
    FILE = "a file the launch names is missing where launchverify sees the files"
    PLUMBING = "launchverify's own contract: no value of a launch file reaches it"
    MIRRORS = "the real library raises the same on any value: its presence decides"


@dataclass(frozen=True)
class Entry:
    """One function's raises of one exception: their kind, and why."""

    kind: Kind
    reason: str
    guard: str = ""  # VALIDATES, FILE: the guard (a name in GUARDS) before each raise
    callers: tuple[str, ...] = ()  # the guard is there instead: every caller, before its call
    count: int = 1


def _name(node: ast.AST) -> str:
    if isinstance(node, ast.Name):
        return node.id
    return node.attr if isinstance(node, ast.Attribute) else ""


def _called(name: str) -> Callable[[ast.Call], bool]:
    return lambda call: _name(call.func) == name


def _instance_of(*names: str) -> Callable[[ast.Call], bool]:
    def test(call: ast.Call) -> bool:
        kinds = call.args[1:2]
        if kinds and isinstance(kinds[0], ast.Tuple):
            kinds = kinds[0].elts
        return _name(call.func) == "isinstance" and any(_name(k) in names for k in kinds)
    return test


# What asks whether a value is unknown; test_guards_let_unknowns_through backs the claims.
GUARDS: dict[str, Callable[[ast.Call], bool]] = {
    "_unknown": _called("_unknown"),  # base._unknown: an Opaque (or an unknown instance)
    "has_placeholder": _called("has_placeholder"),  # text holding a piece of an unknown
    "Opaque": _instance_of("Opaque", "UnknownInstance"),
    "str": _instance_of("str"),  # every unknown is a str (Opaque derives from it)
    "callable": _called("callable"),  # every unknown is callable (Opaque.__call__)
    "Text": _instance_of("Text"),  # an IR text is known (an unknown converts to s.Opaque)
}

V, F, P, M = Kind.VALIDATES, Kind.FILE, Kind.PLUMBING, Kind.MIRRORS
RAISES: dict[str, Entry] = {
    # ---------------------------------------------------------------- base
    "base:unmodelled_attribute:missing": Entry(
        P, "Python's attribute protocol: a dunder, launchverify's or a library's getattr "
        "probe, a read outside an evaluation; the launch file's read gets an unknown"),
    "base:Substitution.perform:TypeError": Entry(
        V, "a context that is none (a vendor's context performs to an unknown)", "_unknown"),
    "base:Condition.evaluate:TypeError": Entry(
        V, "a context that is none (a vendor's context: an unknown truth)", "_unknown"),
    "base:check_substitutions:TypeError": Entry(
        V, "what launch cannot normalize to substitutions (a bool, a number...)", "_unknown",
        count=3),
    # ---------------------------------------------------------------- context
    "context:LaunchContext.perform_substitution:RuntimeError": Entry(
        P, "every context made in an evaluation gets its performer (the frontend's, or "
        "runtime.context_tools for one the launch file makes): only outside one it lacks it"),
    "context:LaunchContext.evaluate_condition:RuntimeError": Entry(
        P, "as perform_substitution: the evaluator is launchverify's to give"),
    "context:_AttributeDict.__getattr__:AttributeError": Entry(
        V, "a name context.locals lacks (a vendor's name, or locals a vendor's mapping "
        "extended, may be there: unknown)", "_unknown"),
    "context:_AttributeDict.__setattr__:AttributeError": Entry(
        M, "launch's locals are read-only: the assignment, not its value, raises"),
    "context:RecordingDict.__getitem__:MissingConfiguration": Entry(
        V, "a configuration nobody set (a name holding an unknown may be any: unknown)",
        "has_placeholder"),
    "context:normalize_to_list_of_substitutions.one:TypeError": Entry(
        V, "an item launch cannot normalize", "_unknown"),
    "context:_extract_type:ValueError": Entry(
        V, "a type launch does not convert to (a vendor's type: the result is unknown)",
        "_unknown", callers=("context:coerce_to_type", "context:perform_typed_substitution")),
    "context:coerce_to_type.as_yaml:ValueError": Entry(
        V, "text YAML cannot read as an allowed value", "has_placeholder",
        callers=("context:coerce_to_type",), count=2),
    "context:coerce_to_type:ValueError": Entry(
        V, "text that is not the type asked for", "has_placeholder", count=2),
    "context:perform_typed_substitution:TypeError": Entry(
        V, "a scalar that is not the type asked for", "_unknown"),
    # ---------------------------------------------------------------- helpers, moveit
    "helpers:process_file:FileNotFoundError": Entry(
        F, "xacro's input: an absolute path in the workspace that does not exist; a "
        "path holding an unknown never is one", "has_placeholder"),
    "moveit:load_xacro:FileNotFoundError": Entry(
        F, "as process_file, after the package index's lookup", "has_placeholder"),
    "moveit:_require:FileNotFoundError": Entry(
        F, "a configuration file MoveIt loads: as load_xacro", "has_placeholder"),
    "moveit:MoveItConfigsBuilder.planning_pipelines:RuntimeError": Entry(
        V, "a default pipeline none of the pipelines is (a vendor's name may be one)",
        "has_placeholder"),
    # ---------------------------------------------------------------- launch_actions
    "launch_actions:DeclareLaunchArgument.__init__:TypeError": Entry(
        V, "a name that is no str", "str"),
    "launch_actions:DeclareLaunchArgument.__init__:RuntimeError": Entry(
        V, "empty choices (a vendor's list may hold some)", "_unknown"),
    "launch_actions:OpaqueFunction.__init__:TypeError": Entry(
        V, "a function that cannot be called", "callable"),
    "launch_actions:ForEach.call:ValueError": Entry(
        V, "an input value that is no mapping (one holding an unknown: an unknown entity)",
        "has_placeholder"),
    "launch_actions:ExecuteProcess._cached:RuntimeError": Entry(
        V, "output read from a process that does not cache it", "_unknown"),
    "launch_actions:RegisterEventHandler._called:raise": Entry(
        P, "passes on launchverify's time limit, which no value raises"),
    # ---------------------------------------------------------------- launch_events, ros
    "launch_events:OnStateTransition.__init__:RuntimeError": Entry(
        V, "a target that is no LifecycleNode (a vendor's node may be one)", "_unknown"),
    "launch_events:ChangeState.__init__:ValueError": Entry(
        V, "a transition id out of range (a vendor's id may be any)", "_unknown"),
    "launch_ros:Node.__init__:TypeError": Entry(
        V, "parameters that are no list (a vendor's list: unknown parameters)", "_unknown"),
    "launch_ros:Node.node_name:RuntimeError": Entry(
        M, "launch_ros knows the name only once the node runs: reading it raises"),
    "launch_ros:LifecycleNode.__init__:TypeError": Entry(
        M, "the distribution lacks the keyword: given at all, whatever its value, it raises"),
    "launch_ros:LifecycleTransition.__init__:ImportError": Entry(
        M, "the distribution lacks the class, whatever its arguments"),
    "launch_ros:LifecycleTransition.__init__:ValueError": Entry(
        V, "no node names or no transition ids (a vendor's list: unknown items)", "_unknown"),
    "launch_substitutions:TextSubstitution.__init__:TypeError": Entry(
        V, "a text that is no str", "str"),
    "launch_substitutions:IfElseSubstitution.__init__:RuntimeError": Entry(
        V, "neither value given", "_unknown"),
    "ros_gz:bridge_param_pairs:ValueError": Entry(
        V, "bridge_params that are not 'key': 'value' pairs, read only from a known text",
        "Text", callers=("ros_gz:bridge_params_problem", "ros_gz:RosGzBridge._parameters",
                         "verifier.frontends.tags:_ros_gz_bridge")),
    "ros_gz:_RosGzAction.__init__:ImportError": Entry(
        M, "the distribution lacks the module (before jazzy), whatever the arguments"),
    # ---------------------------------------------------------------- runtime
    "runtime:active:RuntimeError": Entry(
        P, "a model used outside an evaluation: launchverify's own code, never a launch's"),
}


@dataclass(frozen=True)
class Function:
    """A function of launchverify's source, its key ``module:qualname``."""

    key: str
    node: ast.AST  # a module's own statements are those of ``module:<module>``

    @functools.cached_property
    def own(self) -> list[ast.AST]:
        """Return the nodes of its body, not those of the functions it defines."""
        out, pending = [], list(ast.iter_child_nodes(self.node))
        while pending:
            node = pending.pop()
            if not isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                out.append(node)
                pending.extend(ast.iter_child_nodes(node))
        return out

    def guarded(self, guard: str, before: ast.stmt | ast.expr) -> bool:
        """Return whether the guard is called in its body before ``before``."""
        where = (before.lineno, before.col_offset)
        return any(isinstance(n, ast.Call) and GUARDS[guard](n)
                   and (n.lineno, n.col_offset) < where for n in self.own)


def _module(path: Path) -> str:
    if path.parent == MODELS:
        return path.stem
    return ".".join(path.relative_to(ROOT).with_suffix("").parts)


def sources() -> dict[Path, str]:
    """Return the text of every Python file of launchverify's source."""
    return {path: path.read_text(encoding="utf-8") for folder in PACKAGES
            for path in sorted((ROOT / folder).rglob("*.py"))}


def functions(path: Path, text: str) -> Iterator[Function]:
    """Yield the functions and methods of a file, nested ones too, and the file itself."""
    def walk(node: ast.AST, prefix: str) -> Iterator[Function]:
        for child in ast.iter_child_nodes(node):
            if isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
                name = f"{prefix}.{child.name}" if prefix else child.name
                if not isinstance(child, ast.ClassDef):
                    yield Function(f"{_module(path)}:{name}", child)
                yield from walk(child, name)
            else:
                yield from walk(child, prefix)
    tree = ast.parse(text, str(path))
    yield Function(f"{_module(path)}:<module>", tree)
    yield from walk(tree, "")


def _raised(node: ast.Raise) -> str:
    """Return the raised exception's name (``raise`` alone: ``raise``, a variable: its name)."""
    if node.exc is None:
        return "raise"
    exc = node.exc.func if isinstance(node.exc, ast.Call) else node.exc
    return _name(exc) or ast.unparse(exc)


def _called_name(key: str) -> str:
    """Return the name a raise's function is called by (``m:C.f:E``: ``f``)."""
    return key.split(":")[1].rpartition(".")[2]


def check(texts: Mapping[Path, str], table: Mapping[str, Entry]) -> dict[str, list[str]]:
    """Return what is wrong, by failure: ``unclassified``, ``stale``, ``unguarded``."""
    called = {_called_name(key) for key, entry in table.items() if entry.callers}
    every = [f for path, text in texts.items()
             if path.parent == MODELS or any(name in text for name in called)
             for f in functions(path, text)]
    models = {_module(path) for path in texts
              if path.parent == MODELS and path.name not in INFRASTRUCTURE}
    found: dict[str, list[tuple[Function, ast.Raise]]] = {}
    for function in every:
        if function.key.partition(":")[0] not in models:
            continue  # launchverify's other source: only its calls are looked at
        for node in function.own:
            if isinstance(node, ast.Raise):
                key = f"{function.key}:{_raised(node)}"
                found.setdefault(key, []).append((function, node))
    problems: dict[str, list[str]] = {"unclassified": [], "stale": [], "unguarded": []}
    for key, raises in sorted(found.items()):
        entry = table.get(key)
        if entry is None or len(raises) > entry.count:
            lines = ", ".join(str(node.lineno) for _, node in raises)
            problems["unclassified"].append(f"{key} (line {lines}): add it to RAISES")
    for key, entry in table.items():
        if len(found.get(key, ())) < entry.count:
            problems["stale"].append(f"{key}: {entry.count} raise(s) listed, "
                                     f"{len(found.get(key, ()))} found")
    for key, entry in table.items():
        if entry.kind in (Kind.VALIDATES, Kind.FILE) and key in found:
            problems["unguarded"] += _unguarded(key, entry, found[key], every)
    return problems


def _unguarded(key: str, entry: Entry, raises: list[tuple[Function, ast.Raise]],
               every: list[Function]) -> list[str]:
    if not entry.callers:
        return [f"{key} (line {node.lineno}): no {entry.guard} guard before it"
                for function, node in raises if not function.guarded(entry.guard, node)]
    name = _called_name(key)
    out = []
    for function in every:
        for node in function.own:
            if not (isinstance(node, ast.Call) and _name(node.func) == name):
                continue
            if function.key not in entry.callers:
                out.append(f"{key}: {function.key} calls it (line {node.lineno}), not a "
                           "guarded caller")
            elif not function.guarded(entry.guard, node):
                out.append(f"{key}: {function.key} calls it (line {node.lineno}) before a "
                           f"{entry.guard} guard")
    missing = set(entry.callers) - {f.key for f in every}
    out += [f"{key}: caller {caller} not found" for caller in sorted(missing)]
    return out


@pytest.fixture(scope="module")
def problems() -> dict[str, list[str]]:
    return check(sources(), RAISES)


def test_every_raise_is_classified(problems: dict[str, list[str]]) -> None:
    assert not problems["unclassified"], "\n".join(problems["unclassified"])


def test_every_entry_names_a_raise(problems: dict[str, list[str]]) -> None:
    assert not problems["stale"], "\n".join(problems["stale"])


def test_validations_ask_for_unknowns_first(problems: dict[str, list[str]]) -> None:
    assert not problems["unguarded"], "\n".join(problems["unguarded"])


def test_table_is_well_formed() -> None:
    for key, entry in RAISES.items():
        assert entry.reason, key
        checked = entry.kind in (Kind.VALIDATES, Kind.FILE)
        assert (entry.guard in GUARDS) if checked else not (entry.guard or entry.callers), key


def test_guards_let_unknowns_through() -> None:
    """What the ``str``, ``callable`` and ``Text`` guards rely on."""
    assert issubclass(UnknownInstance, Opaque)
    assert issubclass(Opaque, str)
    assert callable(Opaque("vendor.value"))
    assert not isinstance(placeholder_sub(str(Opaque("vendor.value"))), s.Text)
    assert not isinstance(placeholder_sub(f"x{Opaque('vendor.value')}"), s.Text)


MUTATIONS = [  # (file, text, replacement, the failure it must give)
    ("launch_events.py", "if not _unknown(transition_id) and transition_id",
     "if transition_id", "unguarded"),
    ("context.py", "    if _unknown(data_type) or has_placeholder(value):",
     "    if False:", "unguarded"),
    ("launch_ros.py", "        self.autostart = False",
     "        raise ValueError\n        self.autostart = False", "unclassified"),
    ("runtime.py", '        raise RuntimeError("launch API models', '        print("', "stale"),
]


@pytest.mark.parametrize(("file", "text", "replacement", "failure"), MUTATIONS)
def test_each_failure_is_caught(file: str, text: str, replacement: str, failure: str) -> None:
    texts = sources()
    path = MODELS / file
    assert texts[path].count(text) == 1
    texts[path] = texts[path].replace(text, replacement)
    assert check(texts, RAISES)[failure]
