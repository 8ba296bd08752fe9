"""Nodes, composable nodes and their remaps and parameters, as launch_ros builds them.

``NodeBuilder`` works for the walker: it resolves a node's package, name and namespace,
collects the remap rules and parameter sources in the order ROS 2 applies them (scope
first, then the node's own), checks parameter files, and evaluates parameter files loaded
with ``allow_substs`` in the node's scope.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import TYPE_CHECKING

from launchverify.evaluate.reducers import Ctx, ScopeReducer
from launchverify.evaluate.scope import GLOBAL_PARAMS, ROS_NAMESPACE, ROS_REMAPS
from launchverify.evaluate.values import file_source, machine_dependent, ns_prefix, text_of
from launchverify.graph import (
    FileRef,
    LaunchRecord,
    NodeRecord,
    Origin,
    ParamRecord,
    RemapRecord,
)
from launchverify.ir import actions as a
from launchverify.ir import subst as s
from launchverify.models import booleans
from launchverify.problems import ProblemKind
from launchverify.span import Span

if TYPE_CHECKING:
    from launchverify.evaluate.walker import Walker


class NodeBuilder:
    """Evaluates Node-like actions for a walker and records them in its graph."""

    def __init__(self, walker: Walker) -> None:
        self.walker = walker
        # each SetParameter in scope becomes one record, shared by the nodes it reaches
        self._scope_records: dict[int, tuple[object, ParamRecord]] = {}

    def run_node(self, action: a.Node, ctx: Ctx) -> NodeRecord:
        """Execute a Node-like action as launch_ros does and record it."""
        reducer = self.walker.reducer.at(ctx, action.at("pkg"))
        package = None if action.package is None else reducer.reduce(action.package)
        package_name = text_of(package)
        if package_name is not None:
            self.walker.record_package(package_name, ctx.origin(action.at("pkg")),
                                       self.walker.index.find(package_name) is not None,
                                       "node", s.written_at(action.package))
        executable = self.walker.reducer.at(ctx, action.at("exec")).reduce(action.executable)
        reducer = self.walker.reducer.at(ctx, action.at("name"))
        name = None if action.name is None else reducer.reduce(action.name)
        if name is not None:
            self.walker.record_name("node name", name, ctx.origin(action.at("name")))
        reducer = self.walker.reducer.at(ctx, action.at("namespace"))
        own_ns = None if action.namespace is None else reducer.reduce(action.namespace)
        namespace = ns_prefix(self.pushed_namespace(reducer), own_ns)
        if namespace is not None and own_ns is not None:  # a pushed one is checked at its push
            self.walker.record_name("namespace", namespace, ctx.origin(action.at("namespace")))
        fqn = None
        if name is not None:  # without any namespace, a node is in "/"
            fqn = ns_prefix(namespace if namespace is not None else s.Text("/"), name)
        reducer = self.walker.reducer.at(ctx, action.span)
        arguments = tuple(reducer.reduce(argument) for argument in action.arguments)
        ros_arguments = tuple(reducer.reduce(argument) for argument in action.ros_arguments)
        exec_name = action.exec_name
        if exec_name is not None:
            reducer.reduce(exec_name)
        remaps = (*self.scope_remaps(ctx), *self.own_remaps(action.remappings, ctx))
        params = (*self.scope_params(ctx),
                  *self.own_params(action.parameters, ctx, empty_is_none=True))
        settings = self.walker.visit_process_options(action.process, action.span, ctx, action)
        autostart = None
        if isinstance(action, a.LifecycleNode):
            autostart = self.autostart(action.autostart, reducer)
        record = NodeRecord(
            kind=action.kind, origin=ctx.origin(action.span), package=package,
            executable=executable, name=name, namespace=namespace, fqn=fqn,
            remappings=remaps, parameters=params, deferred=ctx.deferred,
            execution=self.walker.execution, autostart=autostart,
            executable_written=s.written_at(action.executable),
        )
        self.walker.graph.nodes.append(record)
        self.walker.graph.launches.append(LaunchRecord(
            record.origin, self.walker.execution, settings, node=record, arguments=arguments,
            ros_arguments=ros_arguments))
        return record

    def run_composable(self, node: a.ComposableNode, container: s.Sub | None, ctx: Ctx) -> None:
        """Record a composable node loaded into a container."""
        inner = self.walker.apply_condition(node.condition, node.span, ctx)
        if inner is None:
            return
        reducer = self.walker.reducer.at(inner, node.span)
        package = reducer.reduce(node.package)
        package_name = text_of(package)
        if package_name is not None:
            found = self.walker.index.find(package_name) is not None
            self.walker.record_package(package_name, inner.origin(node.at("pkg")), found,
                                       "composable node", s.written_at(node.package))
        plugin = reducer.reduce(node.plugin)
        name = None if node.name is None else reducer.reduce(node.name)
        if name is not None:
            self.walker.record_name("node name", name, inner.origin(node.at("name")))
        own_ns = None if node.namespace is None else reducer.reduce(node.namespace)
        namespace = ns_prefix(self.pushed_namespace(reducer), own_ns)
        if namespace is not None and own_ns is not None:
            self.walker.record_name("namespace", namespace, inner.origin(node.at("namespace")))
        fqn = None
        if name is not None:
            fqn = ns_prefix(namespace if namespace is not None else s.Text("/"), name)
        for item in node.extra_arguments:
            reducer.reduce(item.name)
            if isinstance(item.value.value, s.Sub):
                reducer.reduce(item.value.value)
        self.walker.graph.nodes.append(NodeRecord(
            kind="composable_lifecycle_node" if node.lifecycle else "composable_node",
            origin=inner.origin(node.span), package=package, executable=plugin, name=name,
            namespace=namespace, fqn=fqn,
            remappings=(*self.scope_remaps(inner), *self.own_remaps(node.remappings, inner)),
            parameters=(*self.scope_params(inner), *self.own_params(node.parameters, inner)),
            container=container, deferred=inner.deferred, execution=self.walker.execution,
            autostart=self.autostart(node.autostart, reducer) if node.lifecycle else None,
        ))

    @staticmethod
    def autostart(value: s.Sub | bool, reducer: ScopeReducer) -> s.Sub | None:
        """Return a lifecycle node's ``autostart`` (``None`` when it is plainly off)."""
        if isinstance(value, bool):
            return s.Text("true") if value else None
        return reducer.reduce(value)

    def scope_remaps(self, ctx: Ctx) -> list[RemapRecord]:
        """Return the SetRemap rules in scope (they come before the node's own)."""
        return [RemapRecord(r.src, r.dst, r.origin, scope=True)
                for r in self.walker.scopes.shared(ROS_REMAPS)]

    def own_remaps(self, remaps: tuple[a.Remap, ...], ctx: Ctx) -> list[RemapRecord]:
        """Evaluate a node's own remap rules."""
        out = []
        for remap in remaps:
            reducer = self.walker.reducer.at(ctx, remap.span)
            src, dst = reducer.reduce(remap.src), reducer.reduce(remap.dst)
            origin = Origin(remap.span, ctx.chain, ctx.path, call=remap.call)
            self.walker.record_name("remap", src, origin)
            self.walker.record_name("remap", dst, origin)
            out.append(RemapRecord(src, dst, origin))
        return out

    def pushed_namespace(self, reducer: ScopeReducer) -> s.Sub | None:
        """Return the namespace pushed around the node, as the current path decides it."""
        pushed = self.walker.scopes.get(ROS_NAMESPACE)
        return None if pushed is None else reducer.decided(pushed)

    def scope_params(self, ctx: Ctx) -> list[ParamRecord]:
        """Return SetParameter/SetParametersFromFile values in scope (they come first)."""
        records = []
        for param in self.walker.scopes.shared(GLOBAL_PARAMS):
            known = self._scope_records.get(id(param))
            if known is None or known[0] is not param:
                known = self._scope_records[id(param)] = (param, ParamRecord(
                    param.origin, file=param.file, name=param.name, value=param.value,
                    scope=True, value_type=param.value_type, source=param.source))
            records.append(known[1])
        return records

    def own_params(self, entries: tuple[a.ParamEntry, ...], ctx: Ctx,
                   empty_is_none: bool = False) -> list[ParamRecord]:
        """Evaluate a node's own parameters: files are checked, values reduced.

        ``empty_is_none``: an empty path names no file (a process node's placeholder,
        ``default=''``): launch_ros skips it and starts the node without it, where a
        composable node's loader opens it and fails.
        """
        out = []
        for entry in entries:
            reducer = self.walker.reducer.at(ctx, entry.span)
            if isinstance(entry, a.ParamFile):
                location = reducer.reduce(entry.path)
                self.check_file(file_source(location), ctx.origin(entry.span),
                                "parameter file", ctx, entry.path, empty_is_none)
                out.append(ParamRecord(ctx.origin(entry.span), file=location,
                                       source=self.read_param_file(location)))
                if self.allows_substitutions(entry, ctx):
                    self.substitute_param_file(file_source(location), entry.span, ctx)
                continue
            for item in entry.items:
                value = item.value.value
                if isinstance(value, s.Sub):
                    value = reducer.reduce(value)
                elif isinstance(value, tuple):
                    value = tuple(reducer.reduce(v) if isinstance(v, s.Sub) else v for v in value)
                out.append(ParamRecord(ctx.origin(item.span), name=reducer.reduce(item.name),
                                       value=value, value_type=item.value.value_type))
        return out

    def allows_substitutions(self, entry: a.ParamFile, ctx: Ctx) -> bool:
        """Return whether a parameter file is read with ``allow_substs`` true."""
        flag = entry.allow_substs
        if isinstance(flag, bool):
            return flag
        value = self.walker.reducer.at(ctx, entry.span).text(flag)
        try:
            return value is not None and booleans.typed_truth(value)
        except booleans.InvalidBoolean:
            return False

    def substitute_param_file(self, location: s.Sub, span: Span, ctx: Ctx) -> None:
        """Evaluate the ``$(...)`` in a parameter file loaded with ``allow_substs``.

        launch performs them in the node's context, so their reads count like any other;
        they are pointed at their line of the parameter file.
        """
        text = text_of(location) or self.walker.graph.base(location)
        located = None if text is None else self.walker.index.locate(Path(text))
        if located is None or not self.walker.loader.within(located, self.walker.workspace):
            self.walker.mark_incomplete()  # its reads are unknown
            return
        for line in self.walker.loader.substitutions(located):
            if line.expression is None:
                self.walker.problem(ProblemKind.EVALUATION,
                                    "invalid substitution in parameter file loaded with "
                                    f"allow_substs: {line.error}", line.where, ctx,
                                    with_defaults=text_of(location) is None)
                continue
            self.walker.reducer.at(ctx, line.where).reduce(line.expression)

    def read_param_file(self, location: s.Sub) -> Path | None:
        """Read a parameter file of the workspace into the graph; return where it is.

        A file ``RewrittenYaml`` rewrites is read as its source (its readers apply it).
        """
        location = file_source(location)
        text = text_of(location) or self.walker.graph.base(location)
        if not text or not Path(text).is_absolute():
            return None
        located = self.walker.index.locate(Path(os.path.normpath(text)))  # "launch/../config"
        if located is None or not self.walker.loader.within(located, self.walker.workspace):
            return None
        if located not in self.walker.graph.param_files:
            self.walker.graph.param_files[located] = self.walker.loader.param_file(located)
        return located

    def check_file(self, location: s.Sub, origin: Origin, what: str, ctx: Ctx,
                   expression: s.Sub | None = None, empty_is_none: bool = False) -> None:
        """Record whether a file the launch needs exists (when its path is known).

        ``expression``: the path as written, to locate the file's name in it (for a fix).
        ``empty_is_none``: an empty path means no file, not a missing one.
        """
        text = text_of(location)
        if text is None and machine_dependent(location):
            return  # the robot's environment decides; not a claim to make here
        if text is None:
            text = self.walker.graph.base(location)
        if text is None:
            return
        if not text.strip():
            if empty_is_none:
                return
            empty = FileRef(text, origin, False, what, "the path is empty")
            self.walker.graph.file_refs.append(empty)
            return
        path = Path(text)
        if not path.is_absolute():
            beside = ctx.file.parent / path
            note = ("relative paths are resolved against the folder ros2 launch is started "
                    "from, not the launch file")
            self.walker.graph.file_refs.append(FileRef(text, origin, beside.is_file(), what, note))
            return
        located = self.walker.index.locate(path)
        if located is not None:
            self.walker.graph.file_refs.append(FileRef(text, origin, True, what))
        elif self.walker.in_workspace(path):
            written = None if expression is None else s.tail_at(expression, path.name)
            self.walker.graph.file_refs.append(FileRef(text, origin, False, what,
                                                       written=written))
