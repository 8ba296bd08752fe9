"""Partial evaluation of substitutions: as concrete as the launch files allow.

``Reducer.reduce`` turns an expression into ``Text`` when everything it depends on is
known, and otherwise into a residual expression whose leaves are inputs (``Arg``,
``EnvInput``) or unknowns. Operators follow launch's rules exactly (boolean coercion,
``equals``, ``prefix_namespace``, ``os.path.join``); leaves are looked up by subclasses:
``walker.ScopeReducer`` during evaluation, ``BaseReducer`` for the default-argument view.
"""

from __future__ import annotations

import functools
import os
from collections.abc import Callable

import yaml

from launchverify.ir import subst as s
from launchverify.ir.symbolic import (
    Arg,
    CommandOutput,
    EnvInput,
    ExecutablePath,
    Guard,
    NsPrefix,
    Opaque,
    PackageFolder,
    Select,
    StrEquals,
    Truthy,
    Unknown,
    Unset,
)
from launchverify.models import booleans
from launchverify.models.python_expression import (
    ExpressionError,
    Unsupported,
    evaluate_expression,
)
from launchverify.models.rewritten_yaml import HELPER as REWRITTEN_YAML
from launchverify.models.rewritten_yaml import rewrite_of
from launchverify.models.ros_names import make_absolute, prefix_namespace
from launchverify.span import Span

_SAFE_LOADER = getattr(yaml, "CSafeLoader", yaml.SafeLoader)


def text_of(sub: s.Sub | None) -> str | None:
    """Return the text of a concrete value, or ``None`` when it is symbolic.

    A YAML file ``RewrittenYaml`` rewrites without moving its keys under a root key is
    named by its source's path, as it stands for it (its readers follow what it rewrites:
    ``parameters.py``); one with a root key is named only where a file is expected
    (``file_source``).
    """
    if type(sub) is s.Text:
        return sub.text
    rewrite = rewrite_of(sub)
    if rewrite is not None and rewrite.root_key is None:
        return text_of(rewrite.source)
    return sub.text if isinstance(sub, s.Text) else None


def file_source(sub: s.Sub) -> s.Sub:
    """Return the file a parameter file value reads: a ``RewrittenYaml``'s source.

    What the rewrite does, the file's readers apply (``parameters.py``).
    """
    rewrite = rewrite_of(sub)
    return sub if rewrite is None else rewrite.source


def is_unset(sub: s.Sub) -> bool:
    """Return whether a value may be unset on some path."""
    return _summary(sub)[0]


# What launch performs whole: every part of these is performed when they are (``$(if)``
# performs its condition, then one branch).
_STRICT_PARTS = (s.Concat, s.PythonExpr, s.NotSub, s.AndSub, s.OrSub, s.AnySub, s.AllSub,
                 s.EqualsSub, s.NotEqualsSub, s.StringJoin, s.PathJoin, s.AsBool, NsPrefix,
                 CommandOutput)


def performs_unset(sub: s.Sub) -> bool | None:
    """Return whether performing a value reads a configuration nobody set (launch raises).

    ``True`` when an unset read is a part launch performs whatever the path; ``None`` when
    only some path, branch or argument value reaches one (a ``Select`` with an unset
    branch, an ``$(if)``'s branch, the default of an argument the user may give).

    Examples:
        >>> performs_unset(s.Concat((Unset("cfg"), s.Text(".yaml"))))
        True
        >>> performs_unset(s.Text("a.yaml"))
        False
    """
    if not is_unset(sub):
        return False
    return True if unset_read(sub) is not None else None


def unset_read(sub: s.Sub) -> Unset | None:
    """Return an unset configuration that performing ``sub`` surely reads, if any."""
    stack = [sub]
    while stack:
        item = stack.pop()
        if isinstance(item, Unset):
            return item
        if isinstance(item, s.IfElse):
            stack.append(item.condition)
        elif isinstance(item, _STRICT_PARTS):
            stack.extend(reversed(item.children()))
    return None


def argument_names(sub: s.Sub) -> frozenset[str]:
    """Return the names of the launch arguments a value is (or includes)."""
    return _summary(sub)[1]


def is_literal(sub: s.Sub) -> bool:
    """Return whether a condition is written without any input (``if="true"``)."""
    return _summary(sub)[2]


_LITERAL_PARTS = (s.Text, s.Concat, s.PythonExpr, s.NotSub, s.AndSub, s.OrSub, s.AnySub,
                  s.AllSub, s.EqualsSub, s.NotEqualsSub, s.IfElse)
_Summary = tuple[bool, frozenset[str], bool]  # may be unset; its arguments; literal
_SUMMARIES: dict[int, tuple[s.Sub, bool, frozenset[str], bool]] = {}  # by id, object kept
MAX_SUMMARIES = 200_000
_NO_NAMES: frozenset[str] = frozenset()


def _summary(sub: s.Sub) -> _Summary:
    """Return what ``is_unset``, ``argument_names`` and ``is_literal`` ask, each part once.

    A configuration assigned under a condition wraps its previous value in a ``Select``:
    the chains grow long (a root of autoware_launch declares the same argument in dozens
    of files), and walking a whole chain at each declaration was a tenth of evaluating.
    The summary of a new link reuses its tail's; an included file's conditions, asked
    again by every root, are summarised once.
    """
    known = _SUMMARIES.get(id(sub))
    if known is not None and known[0] is sub:
        return known[1:]
    if len(_SUMMARIES) >= MAX_SUMMARIES:
        _SUMMARIES.clear()
    stack: list[tuple[s.Sub, bool]] = [(sub, False)]
    while stack:
        item, expanded = stack.pop()
        if _summarised(item):
            continue
        children = item.children()
        if not expanded:
            stack.append((item, True))
            stack.extend((child, False) for child in children if not _summarised(child))
            continue
        unset = isinstance(item, Unset)
        names = frozenset((item.name,)) if isinstance(item, Arg) else _NO_NAMES
        literal = isinstance(item, _LITERAL_PARTS)
        for child in children:
            _, child_unset, child_names, child_literal = _SUMMARIES[id(child)]
            unset = unset or child_unset
            literal = literal and child_literal
            if child_names and not child_names <= names:
                names = child_names if not names else names | child_names
        _SUMMARIES[id(item)] = (item, unset, names, literal)
    return _SUMMARIES[id(sub)][1:]


def _summarised(sub: s.Sub) -> bool:
    known = _SUMMARIES.get(id(sub))
    return known is not None and known[0] is sub


class Reducer:
    """Reduce expressions; subclasses say what configurations and the environment hold."""

    def __init__(self) -> None:
        self._in_guards = 0  # evaluating a guard (see ``guard``)
        self._dispatch: dict[type, Callable[[s.Sub], s.Sub]] = {
            s.Text: lambda x: x,
            s.Concat: self._concat,
            s.LaunchConfig: self._config,
            s.EnvVar: self._env,
            s.PythonExpr: self._eval,
            s.Command: self._command,
            s.FindExecutable: lambda x: Unknown(f"{x.describe()} on the PATH"),
            s.FindPackageShare: self._pkg_share,
            s.FindPackagePrefix: self._pkg_prefix,
            s.ExecutableInPackage: self._exec_in_pkg,
            s.ThisLaunchFile: lambda x: self.this_file(False),
            s.ThisLaunchFileDir: lambda x: self.this_file(True),
            s.LaunchLogDir: lambda x: Unknown("the launch log folder"),
            s.AnonName: self._anon,
            s.NotSub: self._not,
            s.AndSub: self._and,
            s.OrSub: self._or,
            s.AnySub: self._any,
            s.AllSub: self._all,
            s.EqualsSub: self._equals,
            s.NotEqualsSub: self._not_equals,
            s.IfElse: self._if_else,
            s.FileContent: self._file_content,
            s.RosParameter: self._ros_parameter,
            s.ForEachVar: self._for_var,
            s.ForLoopIndex: self._loop_index,
            s.StringJoin: self._string_join,
            s.PathJoin: self._path_join,
            s.LocalSub: lambda x: Unknown(f"event value {x.describe()}"),
            s.Opaque: lambda x: Unknown(x.describe()),
            s.PackageLookup: lambda x: (PackageFolder(x.description, x.package)
                                        if isinstance(x, s.PackageLookup) else x),
            s.Raises: self._raises,
            s.Rewritten: self._rewritten,
            s.AsBool: self._as_bool,
            Arg: lambda x: self.arg(x) if isinstance(x, Arg) else x,
            EnvInput: lambda x: self.env_input(x) if isinstance(x, EnvInput) else x,
            Unknown: lambda x: x,
            CommandOutput: lambda x: x,
            ExecutablePath: lambda x: x,
            PackageFolder: lambda x: x,
            Unset: lambda x: x,
            Select: self._select,
            NsPrefix: self._ns_prefix,
        }

    # ------------------------------------------------------------------ public

    def reduce(self, sub: s.Sub) -> s.Sub:
        """Return ``sub`` evaluated as far as possible."""
        return self._dispatch[type(sub)](sub)

    def text(self, sub: s.Sub | None) -> str | None:
        """Reduce and return the text, or ``None`` when symbolic (or absent)."""
        return None if sub is None else text_of(self.reduce(sub))

    def truth(self, sub: s.Sub) -> bool | None:
        """Apply the condition rule to ``sub``; ``None`` when it is not known."""
        value = text_of(self.reduce(sub))
        if value is None:
            return None
        try:
            return booleans.condition_truth(value)
        except booleans.InvalidBoolean as error:
            self.fail(str(error), rule="LV207")
            return None

    def guard(self, guard: Guard) -> bool | None:
        """Return whether a guard holds, or ``None`` when unknown.

        A guard is a condition launch evaluated where it is written: an ``$(eval)`` in it
        is probed there (``probe``), not again wherever a value that depends on it is read.
        """
        self._in_guards += 1
        try:
            return self._guard(guard)
        finally:
            self._in_guards -= 1

    def _guard(self, guard: Guard) -> bool | None:
        if isinstance(guard, Truthy):
            value = self.truth(guard.expression)
            return None if value is None else value != guard.negate
        if isinstance(guard, StrEquals):
            left = self.reduce(guard.left)
            if guard.right is None:
                result: bool | None = performs_unset(left)
            else:
                left_text, right_text = text_of(left), self.text(guard.right)
                result = None if left_text is None or right_text is None else (
                    left_text == right_text
                )
            return None if result is None else result != guard.negate
        return None

    # ------------------------------------------------------------------ hooks

    def config(self, name: str, default: s.Sub | None, where: Span | None = None,
               written: Span | None = None) -> s.Sub:
        """Return the value of a launch configuration (read at ``where``, if known).

        ``written``: where the name itself is written verbatim (for fixes), if known.
        """
        raise NotImplementedError

    def environment(self, name: str, default: s.Sub | None) -> s.Sub:
        """Return the value of an environment variable."""
        return EnvInput(name, None if default is None else self.reduce(default))

    def package_share(self, name: str, written: Span | None = None) -> s.Sub:
        """Return the share folder of a package (its name written verbatim at ``written``)."""
        return Unknown(f"share folder of {name}")

    def package_prefix(self, name: str, written: Span | None = None) -> s.Sub:
        """Return the install prefix of a package."""
        return Unknown(f"install prefix of {name}")

    def executable_path(self, executable: str, package: str,
                        written: Span | None = None) -> s.Sub:
        """Return the path of an executable of a package."""
        return ExecutablePath(f"path of {executable} in {package}", executable, package)

    def this_file(self, directory: bool) -> s.Sub:
        """Return the current launch file (or its folder)."""
        return Unknown("current launch file")

    def anon(self, name: str) -> s.Sub:
        """Return the anonymous name for ``name`` in the current scope."""
        return Unknown(f"anonymous name {name}")

    def file_content(self, path: str) -> s.Sub:
        """Return the content of a file."""
        return Unknown(f"content of {path}")

    def ros_parameter(self, name: str, default: s.Sub | None) -> s.Sub:
        """Return the value of a SetParameter in scope."""
        return Unknown(f"parameter {name}") if default is None else self.reduce(default)

    def loop_variable(self, name: str, default: s.Sub | None, index: bool) -> s.Sub:
        """Return the value of a for-loop variable or index."""
        return Unknown(f"loop variable {name}")

    def arg(self, sub: Arg) -> s.Sub:
        """Return the value of a launch-argument input (kept symbolic by default)."""
        return sub

    def env_input(self, sub: EnvInput) -> s.Sub:
        """Return the value of a machine environment variable (kept symbolic)."""
        return sub

    def probe(self, residual: s.Sub) -> None:
        """Look at a residual expression under the default arguments (hook)."""

    def fail(self, message: str, rule: str | None = None) -> None:
        """Record that launch would raise while evaluating the current action.

        ``rule``: the rule that names this failure, when one does (see ``Problem.rule``).
        """

    def unmodeled(self, message: str) -> None:
        """Record that a construct is not modelled."""

    # ------------------------------------------------------------------ structure

    def _concat(self, sub: s.Sub) -> s.Sub:
        assert isinstance(sub, s.Concat)
        return s.concat([self.reduce(p) for p in sub.parts])

    def _name(self, sub: s.Sub) -> str | None:
        return text_of(self.reduce(sub))

    def _config(self, sub: s.Sub) -> s.Sub:
        assert isinstance(sub, s.LaunchConfig)
        name = self._name(sub.name)
        if name is None:
            return Unknown(f"configuration named by {sub.name.describe()}")
        return self.config(name, sub.default, sub.where, s.written_at(sub.name))

    def _env(self, sub: s.Sub) -> s.Sub:
        assert isinstance(sub, s.EnvVar)
        name = self._name(sub.name)
        if name is None:
            return Unknown(f"environment variable named by {sub.name.describe()}")
        return self.environment(name, sub.default)

    def _eval(self, sub: s.Sub) -> s.Sub:
        assert isinstance(sub, s.PythonExpr)
        expression = self.reduce(sub.expression)
        modules = None if sub.modules is None else self.reduce(sub.modules)
        text = text_of(expression)
        module_text = text_of(modules) if modules is not None else "math"
        if text is None or module_text is None:
            residual = s.PythonExpr(expression, modules)
            if not self._in_guards:  # a guard's $(eval) is its condition's, judged there
                self.probe(residual)
            return residual
        names = [m.strip() for m in module_text.split(",") if m.strip()]
        try:
            return s.Text(evaluate_expression(text, names))
        except ExpressionError as error:
            self.fail(f"$(eval) raises {error}")
        except Unsupported as error:
            self.unmodeled(f"{error}: {text!r}")
        return Unknown(f"value of $(eval {text!r})")

    def _raises(self, sub: s.Sub) -> s.Sub:
        """Launch raises performing this value: a failure where it is evaluated."""
        assert isinstance(sub, s.Raises)
        self.fail(f"ros2 launch raises {sub.error}")
        return Unknown(f"a value launch rejects ({sub.error})")

    def _command(self, sub: s.Sub) -> s.Sub:
        """A command's output: never run statically, but kept runnable for ``run``."""
        assert isinstance(sub, s.Command)
        on_stderr = None if sub.on_stderr is None else self.reduce(sub.on_stderr)
        return CommandOutput(f"output of {sub.describe()}", self.reduce(sub.command), on_stderr)

    def _pkg_share(self, sub: s.Sub) -> s.Sub:
        assert isinstance(sub, s.FindPackageShare)
        name = self._name(sub.package)
        return (Unknown(sub.describe()) if name is None
                else self.package_share(name, s.written_at(sub.package)))

    def _pkg_prefix(self, sub: s.Sub) -> s.Sub:
        assert isinstance(sub, s.FindPackagePrefix)
        name = self._name(sub.package)
        return (Unknown(sub.describe()) if name is None
                else self.package_prefix(name, s.written_at(sub.package)))

    def _exec_in_pkg(self, sub: s.Sub) -> s.Sub:
        assert isinstance(sub, s.ExecutableInPackage)
        executable, package = self._name(sub.executable), self._name(sub.package)
        if executable is None or package is None:
            return Unknown(sub.describe())
        return self.executable_path(executable, package, s.written_at(sub.package))

    def _anon(self, sub: s.Sub) -> s.Sub:
        assert isinstance(sub, s.AnonName)
        name = self._name(sub.name)
        return Unknown(sub.describe()) if name is None else self.anon(name)

    def _bool_op(self, values: list[s.Sub], combine: Callable[[list[bool]], bool],
                 rebuild: Callable[[list[s.Sub]], s.Sub]) -> s.Sub:
        """Apply a boolean substitution: concrete when every operand is known."""
        texts = [text_of(v) for v in values]
        if any(t is None for t in texts):
            return rebuild(values)
        try:
            flags = [booleans.typed_truth(t) for t in texts if t is not None]
        except booleans.InvalidBoolean as error:
            self.fail(str(error))
            return Unknown(f"failed {rebuild(values).describe()}")
        return s.Text(booleans.bool_text(combine(flags)))

    def _not(self, sub: s.Sub) -> s.Sub:
        assert isinstance(sub, s.NotSub)
        return self._bool_op([self.reduce(sub.value)], lambda f: not f[0],
                             lambda v: s.NotSub(v[0]))

    def _and(self, sub: s.Sub) -> s.Sub:
        assert isinstance(sub, s.AndSub)
        return self._bool_op([self.reduce(sub.left), self.reduce(sub.right)], all,
                             lambda v: s.AndSub(v[0], v[1]))

    def _or(self, sub: s.Sub) -> s.Sub:
        assert isinstance(sub, s.OrSub)
        return self._bool_op([self.reduce(sub.left), self.reduce(sub.right)], any,
                             lambda v: s.OrSub(v[0], v[1]))

    def _any(self, sub: s.Sub) -> s.Sub:
        assert isinstance(sub, s.AnySub)
        return self._bool_op([self.reduce(a) for a in sub.args], any,
                             lambda v: s.AnySub(tuple(v)))

    def _all(self, sub: s.Sub) -> s.Sub:
        assert isinstance(sub, s.AllSub)
        return self._bool_op([self.reduce(a) for a in sub.args], all,
                             lambda v: s.AllSub(tuple(v)))

    def _equals(self, sub: s.Sub) -> s.Sub:
        assert isinstance(sub, s.EqualsSub)
        left, right = self.reduce(sub.left), self.reduce(sub.right)
        lt, rt = text_of(left), text_of(right)
        if lt is None or rt is None:
            return s.EqualsSub(left, right)
        return s.Text(booleans.bool_text(booleans.launch_equals(lt, rt)))

    def _not_equals(self, sub: s.Sub) -> s.Sub:
        assert isinstance(sub, s.NotEqualsSub)
        left, right = self.reduce(sub.left), self.reduce(sub.right)
        lt, rt = text_of(left), text_of(right)
        if lt is None or rt is None:
            return s.NotEqualsSub(left, right)
        return s.Text(booleans.bool_text(not booleans.launch_equals(lt, rt)))

    def _if_else(self, sub: s.Sub) -> s.Sub:
        assert isinstance(sub, s.IfElse)
        condition = self.reduce(sub.condition)
        chosen = self._bool_op([condition], lambda f: f[0], lambda v: v[0])
        if isinstance(chosen, s.Text):
            return self.reduce(sub.if_value if chosen.text == "true" else sub.else_value)
        if isinstance(chosen, Unknown):
            return chosen
        return s.IfElse(condition, self.reduce(sub.if_value), self.reduce(sub.else_value))

    def _file_content(self, sub: s.Sub) -> s.Sub:
        assert isinstance(sub, s.FileContent)
        path = self._name(sub.path)
        return Unknown(sub.describe()) if path is None else self.file_content(path)

    def _ros_parameter(self, sub: s.Sub) -> s.Sub:
        assert isinstance(sub, s.RosParameter)
        name = self._name(sub.name)
        return Unknown(sub.describe()) if name is None else self.ros_parameter(name, sub.default)

    def _for_var(self, sub: s.Sub) -> s.Sub:
        assert isinstance(sub, s.ForEachVar)
        name = self._name(sub.name)
        if name is None:
            return Unknown(sub.describe())
        return self.loop_variable(name, sub.default, index=False)

    def _loop_index(self, sub: s.Sub) -> s.Sub:
        assert isinstance(sub, s.ForLoopIndex)
        name = self._name(sub.name)
        return Unknown(sub.describe()) if name is None else self.loop_variable(name, None, True)

    def _string_join(self, sub: s.Sub) -> s.Sub:
        assert isinstance(sub, s.StringJoin)
        delimiter = self.reduce(sub.delimiter)
        parts = [self.reduce(p) for p in sub.parts]
        texts = [text_of(p) for p in parts]
        delimiter_text = text_of(delimiter)
        if delimiter_text is None or any(t is None for t in texts):
            return s.StringJoin(delimiter, tuple(parts))
        return s.Text(delimiter_text.join(t for t in texts if t is not None))

    def _path_join(self, sub: s.Sub) -> s.Sub:
        assert isinstance(sub, s.PathJoin)
        parts = [self.reduce(p) for p in sub.parts]
        texts = [text_of(p) for p in parts]
        if any(t is None for t in texts):
            return s.PathJoin(tuple(parts))
        joined = os.path.join(*(t for t in texts if t is not None)) if texts else ""  # noqa: PTH118
        return s.Text(joined)

    def _rewritten(self, sub: s.Sub) -> s.Sub:
        """A rewritten file stands for its source, with what ``RewrittenYaml`` rewrites.

        The parameters it rewrites, the root key its content moves under (an empty one
        moves nothing) and whether it rewrites more stay with it: the file's readers
        apply them (``parameters.py``). A file rewritten twice keeps both rewrites, later
        ones winning; under a root key first, the second is not followed.
        """
        assert isinstance(sub, s.Rewritten)
        inputs = [self.reduce(item) for item in sub.inputs]
        if sub.description == "HasNodeParams" and len(inputs) == 2:
            return self._has_node_params(sub, inputs[0], text_of(inputs[1]))
        source = self.reduce(sub.source)
        if sub.description != REWRITTEN_YAML:
            return source
        root = None if sub.root_key is None else self.reduce(sub.root_key)
        if root is not None and text_of(root) == "":
            root = None
        params = tuple((key, self.reduce(value)) for key, value in sub.params)
        values = tuple((key, self.reduce(value)) for key, value in sub.values)
        exact = sub.exact
        inner = rewrite_of(source)
        if inner is not None:  # a rewritten file, rewritten again
            exact = exact and inner.exact and inner.root_key is None \
                and inner.convert == sub.convert
            params, values = inner.params + params, inner.values + values
            source = inner.source
        if root is None and not params and not values and exact:
            return source
        return s.Rewritten(source, (), REWRITTEN_YAML, root, params, values, exact,
                           sub.convert)

    def _has_node_params(self, sub: s.Rewritten, path: s.Sub, node: str | None) -> s.Sub:
        """nav2's HasNodeParams: 'True' when the YAML file has a top-level key ``node``."""
        name = text_of(path)
        content = self.file_content(name) if name is not None else None
        text = text_of(content) if content is not None else None
        unknown = s.Rewritten(sub.source, (path, s.Text(node or "")), sub.description)
        if text is None or node is None:
            return unknown  # the base view may read the file later
        keys = top_level_keys(text)
        if keys is None:
            return unknown
        return s.Text("True" if node in keys else "False")

    def _as_bool(self, sub: s.Sub) -> s.Sub:
        assert isinstance(sub, s.AsBool)
        value = self.reduce(sub.value)
        text = text_of(value)
        if text is None:
            return s.AsBool(value)
        return s.Text("True" if text.strip().lower() in ("true", "1", "yes", "on") else "False")

    def _select(self, sub: s.Sub) -> s.Sub:
        assert isinstance(sub, Select)
        remaining = []
        for guard in sub.guards:
            verdict = self.guard(guard)
            if verdict is False:
                return self.reduce(sub.otherwise)
            if verdict is None:
                remaining.append(guard)
        if not remaining:
            return self.reduce(sub.then)
        then, otherwise = self.reduce(sub.then), self.reduce(sub.otherwise)
        if then == otherwise:
            return then
        return Select(tuple(remaining), then, otherwise)

    def _ns_prefix(self, sub: s.Sub) -> s.Sub:
        assert isinstance(sub, NsPrefix)
        base = None if sub.base is None else self.reduce(sub.base)
        result = ns_prefix(base, self.reduce(sub.ns), absolute=sub.absolute)
        assert result is not None  # ns is never None here
        return result


def ns_prefix(base: s.Sub | None, ns: s.Sub | None, *, absolute: bool = True) -> s.Sub | None:
    """Compose namespaces like ``make_absolute(prefix_namespace(base, ns))``, symbolically.

    ``None`` stands for "no namespace" on either side, as in launch_ros.
    """

    def finish(text: str | None) -> s.Sub | None:
        if text is None:
            return None
        return s.Text(text if not absolute else make_absolute(text) or "/")

    base_text = None if base is None else text_of(base)
    if ns is None:
        if base is None or base_text is not None:
            return finish(prefix_namespace(base_text, None))
        return base
    ns_text = text_of(ns)
    if ns_text is not None and (ns_text.startswith("/") or base is None or base_text is not None):
        return finish(prefix_namespace(base_text, ns_text))
    leading = ns.parts[0] if isinstance(ns, s.Concat) else ns
    if isinstance(leading, s.Text) and leading.text.startswith("/"):
        return ns  # an absolute namespace ignores the base
    return NsPrefix(base, ns, absolute)


class BaseReducer(Reducer):
    """Reduces residual values under the default arguments (the base evaluation).

    ``pinned`` holds values for inputs: ``name`` for arguments, ``env:NAME`` for
    environment variables. Inputs with neither a pinned value nor a default stay symbolic.
    """

    def __init__(self, pinned: dict[str, str] | None = None,
                 read: Callable[[str], str | None] | None = None, *,
                 environment_defaults: bool = True) -> None:
        super().__init__()
        self.pinned = pinned or {}
        self.read = read
        # an unset variable reads as its default: true only if the robot does not set it
        self.environment_defaults = environment_defaults

    def file_content(self, path: str) -> s.Sub:
        text = self.read(path) if self.read is not None else None
        return Unknown(f"content of {path}") if text is None else s.Text(text)

    def config(self, name: str, default: s.Sub | None, where: Span | None = None,
               written: Span | None = None) -> s.Sub:
        return Unknown(f"configuration {name}")

    def arg(self, sub: Arg) -> s.Sub:
        if sub.name in self.pinned:
            return s.Text(self.pinned[sub.name])
        return sub if sub.default is None else self.reduce(sub.default)

    def env_input(self, sub: EnvInput) -> s.Sub:
        key = "env:" + sub.name
        if key in self.pinned:
            return s.Text(self.pinned[key])
        if sub.default is None or not self.environment_defaults:
            return sub
        return self.reduce(sub.default)


def machine_dependent(sub: s.Sub) -> bool:
    """Return whether a value depends on an environment variable not given with ``--env``.

    (Given ones are substituted; what remains is an input of the robot's machine, which
    the machine running the check cannot speak for.)
    """
    return any(isinstance(part, EnvInput) for part in s.walk(sub))


def describe_value(sub: s.Sub | None) -> str | None:
    """Return text for output: the text of concrete values, the expression otherwise."""
    if sub is None:
        return None
    return sub.text if isinstance(sub, s.Text) else sub.describe()


__all__ = [
    "BaseReducer",
    "Opaque",
    "Reducer",
    "argument_names",
    "describe_value",
    "is_literal",
    "is_unset",
    "machine_dependent",
    "ns_prefix",
    "performs_unset",
    "text_of",
    "unset_read",
]


@functools.lru_cache(maxsize=64)
def top_level_keys(text: str) -> frozenset[object] | None:
    """Return a YAML document's top-level keys (empty: not a mapping; ``None``: not YAML).

    nav2 launch files ask this of one large parameter file for every server: parsed once
    per content, with libyaml when PyYAML has it.
    """
    try:
        data = yaml.load(text, Loader=_SAFE_LOADER)
    except yaml.YAMLError:
        return None
    return frozenset(data) if isinstance(data, dict) else frozenset()
