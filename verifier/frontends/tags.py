"""Every tag of the ROS 2 XML and YAML launch frontends, turned into IR actions.

One handler per tag, registered by name like launch's ``@expose_action``. Handlers read
exactly the attributes the real ``parse`` methods read (launch, launch_ros, and the newer
tags of kilted/rolling), so anything left unread is reported as launch would refuse it.
"""

from __future__ import annotations

import contextlib
import re
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import TypedDict

from launchverify.frontends.entity import Entity, Scalar
from launchverify.frontends.reader import EntityReader, MissingAttribute
from launchverify.frontends.subst_parser import SUBSTITUTIONS
from launchverify.ir import actions as a
from launchverify.ir import subst as s
from launchverify.ir.conditions import Condition
from launchverify.models import distros
from launchverify.models.launch_api import ros_gz
from launchverify.problems import Problem, ProblemKind, ProblemSink
from launchverify.span import Span

Handler = Callable[["TagParser", Entity], a.Action | None]


class Common(TypedDict):
    """What every action is built with."""

    span: Span
    condition: Condition | None
    attr_spans: dict[str, Span]


class NodeFields(Common):
    """What ``<node>`` and its variants are built with."""

    executable: s.Sub
    package: s.Sub | None
    name: s.Sub | None
    namespace: s.Sub | None
    exec_name: s.Sub | None
    arguments: tuple[s.Sub, ...]
    ros_arguments: tuple[s.Sub, ...]
    parameters: tuple[a.ParamEntry, ...]
    remappings: tuple[a.Remap, ...]
    process: a.ProcessOptions
TAGS: dict[str, Handler] = {}

# Close misspellings and ROS 1 tags users carry over, named in the error message.
TAG_HINTS = {
    "prepend_env": "use <append_env prepend='true'>",
    "rosparam": "ROS 1 tag; use <param from='file.yaml'> in a node",
    "machine": "ROS 1 tag; not supported by ROS 2 launch",
    "test": "ROS 1 tag; use launch_testing",
    "composable_node": "only allowed inside <node_container> or <load_composable_node>",
    "push_namespace": "use <push_ros_namespace>",
    "pop_ros_namespace": "namespaces end with the enclosing <group>; there is no pop",
    "gzserver": "ros_gz_sim's tag is <gz_server>",
    "gz_bridge": "ros_gz_bridge's tag is <ros_gz_bridge>",
    "ros_gz_spawn_model": "ros_gz_sim's tag is <gz_spawn_model>",
}


# Tags that launch extensions of other packages add; not modelled, so they are opaque.
# (ros_gz's tags are modelled below: `<gz_server>`, `<gz_spawn_model>`, `<ros_gz_bridge>`.)
EXTENSION_TAGS = {
    "trace": "tracetools_launch",
}


def tag(*names: str) -> Callable[[Handler], Handler]:
    """Register a handler for one or more tag names."""

    def register(handler: Handler) -> Handler:
        for name in names:
            if name in TAGS:
                raise ValueError(f"tag {name} registered twice")
            TAGS[name] = handler
        return handler

    return register


class TagParser(EntityReader):
    """Turns the entity tree of one file into IR actions."""

    def __init__(self, path: Path, sink: ProblemSink) -> None:
        super().__init__(path, sink)

    def launch_file(self, root: Entity, fmt: str) -> a.LaunchFile:
        """Convert the root entity; the root must be ``launch``."""
        if root.tag != "launch":
            self.sink.parse(f"expected `launch` as the root, found `{root.tag}`", root.span)
            return a.LaunchFile(path=self.path, format=fmt, actions=(), span=root.span)
        deprecated = self.plain(root, "deprecated")
        actions = self.actions(root.children())
        # no ``finish(root)``: launch reads ``deprecated`` from the root and checks no
        # other attribute there (``<launch version="0.1">`` loads), only each action's
        return a.LaunchFile(
            path=self.path, format=fmt, actions=actions, span=root.span, deprecated=deprecated
        )

    def actions(self, entities: list[Entity]) -> tuple[a.Action, ...]:
        """Convert a list of child entities, skipping the ones that cannot be read."""
        out = []
        for entity in entities:
            action = self.action(entity)
            if action is not None:
                out.append(action)
        return tuple(out)

    def action(self, entity: Entity) -> a.Action | None:
        """Convert one entity through its tag handler."""
        handler = TAGS.get(entity.tag)
        if handler is None and entity.tag in EXTENSION_TAGS:
            package = EXTENSION_TAGS[entity.tag]
            self.sink.unmodeled(
                f"`{entity.tag}` is a launch extension of {package}; what it starts is not "
                "modelled", entity.span)
            return a.OpaqueAction(span=entity.span, description=f"<{entity.tag}>")
        if handler is None:
            hint = TAG_HINTS.get(entity.tag)
            extra = f"; {hint}" if hint else ""
            self.sink.parse(
                f"unknown tag `{entity.tag}` (ros2 launch: Unrecognized entity){extra}",
                entity.span,
            )
            return None
        try:
            action = handler(self, entity)
        except MissingAttribute:
            return None
        self.finish(entity)
        return action

    def common(self, entity: Entity) -> Common:
        """Return the keyword arguments every action takes: span, condition, spans."""
        return {
            "span": entity.span,
            "condition": self.condition(entity),
            "attr_spans": self.spans(entity),
        }

    def pairs(self, entity: Entity, nested: str, first: str = "name",
              second: str = "value") -> tuple[tuple[s.Sub, s.Sub], ...]:
        """Read nested ``<keep name value>``-like entities as pairs."""
        out = []
        for item in entity.get_nested(nested) or []:
            try:
                out.append((self.req(item, first), self.req(item, second)))
            except MissingAttribute:
                continue
            finally:
                self.finish(item)
        return tuple(out)

    # ------------------------------------------------------------------ node pieces

    def process_options(self, entity: Entity) -> a.ProcessOptions:
        """Read the attributes shared by ``executable`` and ``node``."""
        on_exit: tuple[a.Action, ...] = ()
        on_exit_attr = entity.get("on_exit")
        if on_exit_attr is not None:
            if on_exit_attr.value == "shutdown":
                on_exit = (a.Shutdown(span=on_exit_attr.span),)
            else:
                self.sink.parse(
                    f"`on_exit` only accepts `shutdown`, got {on_exit_attr.value!r}",
                    on_exit_attr.span,
                )
        return a.ProcessOptions(
            name=self.sub(entity, "name") if entity.tag == "executable" else None,
            cwd=self.sub(entity, "cwd"),
            prefix=self.sub(entity, "launch-prefix"),
            output=self.sub(entity, "output"),
            respawn=self.sub_or_bool(entity, "respawn") or False,
            respawn_delay=self.number(entity, "respawn_delay", float, minimum=0.0),
            respawn_max_retries=_integer(self.number(entity, "respawn_max_retries", int)),
            sigterm_timeout=self.number(entity, "sigterm_timeout", float, minimum=0.0),
            sigkill_timeout=self.number(entity, "sigkill_timeout", float, minimum=0.0),
            shell=self.flag(entity, "shell") or False,
            emulate_tty=self.flag(entity, "emulate_tty"),
            additional_env=self.pairs(entity, "env"),
            on_exit=on_exit,
        )

    def remaps(self, entity: Entity) -> tuple[a.Remap, ...]:
        """Read nested ``<remap from to>``."""
        out = []
        for item in entity.get_nested("remap") or []:
            with contextlib.suppress(MissingAttribute):
                out.append(a.Remap(src=self.req(item, "from"), dst=self.req(item, "to"),
                                   span=item.span))
            self.finish(item)
        return tuple(out)

    def parameters(self, entity: Entity) -> tuple[a.ParamEntry, ...]:
        """Read nested ``<param>``: files (``from``) and named values, nesting allowed."""
        out: list[a.ParamEntry] = []
        for item in entity.get_nested("param") or []:
            source = self.sub(item, "from")
            if source is not None:
                allow = self.sub_or_bool(item, "allow_substs")
                if item.get("name") is not None:
                    self.sink.parse("`name` and `from` cannot be used together", item.span)
                out.append(a.ParamFile(path=source, span=item.span, allow_substs=allow or False))
                self.finish(item)
                continue
            items = self.param_items(item, prefix=())
            if items:
                out.append(a.ParamDict(items=tuple(items), span=item.span))
        return tuple(out)

    def param_items(self, item: Entity, prefix: tuple[s.Sub, ...]) -> list[a.ParamItem]:
        """Flatten one named ``<param>`` (with nested ``<param>`` children) into items."""
        try:
            name = self.req(item, "name")
        except MissingAttribute:
            return []
        value_type = self.plain(item, "type")
        nested = item.get_nested("param")
        attr = item.get("value")
        full = s.concat(_dotted((*prefix, name)))
        out: list[a.ParamItem] = []
        if attr is not None and nested:
            self.sink.parse("nested parameters and `value` are mutually exclusive", item.span)
        if nested:
            for child in nested:
                out.extend(self.param_items(child, (*prefix, name)))
        elif attr is not None:
            out.append(a.ParamItem(name=full, value=self.param_value(item, attr.value, value_type),
                                   span=item.span))
        else:
            self.sink.parse(f"parameter {full.describe()!r} needs `value` or nested parameters",
                            item.span)
        self.finish(item)
        return out

    def param_value(self, item: Entity, raw: Scalar | list[Scalar],
                    value_type: str | None) -> a.ParamValue:
        """Read a parameter value: substituted text, ``value-sep`` lists, YAML literals."""
        span = item.attrs["value"].span
        if isinstance(raw, str):
            separator = self.plain(item, "value-sep")
            if separator is not None:
                parts = raw.split(separator) if separator else [raw]
                return a.ParamValue(
                    value=tuple(self.parse_text(p, span) for p in parts), value_type=value_type
                )
            written = item.attrs["value"].value_at  # a fix can rename a name read here
            return a.ParamValue(value=self.parse_text(raw, span, written), value_type=value_type)
        if isinstance(raw, list):
            return a.ParamValue(
                value=tuple(self.parse_text(x, span) if isinstance(x, str) else x for x in raw),
                value_type=value_type,
            )
        return a.ParamValue(value=raw, value_type=value_type)

    def node_fields(self, entity: Entity) -> NodeFields:
        """Read everything ``<node>`` and its variants share."""
        if "node-name" in entity.attrs:  # refused here, so no spelling to suggest
            entity.read.add("node-name")
            self.sink.parse(
                "`node-name` is read by the parser but Node() has no such argument; use `name`",
                entity.attrs["node-name"].span,
            )
        return {
            **self.common(entity),
            "executable": self.req(entity, "exec"),
            "package": self.sub(entity, "pkg"),
            "name": self.sub(entity, "name"),
            "namespace": self.sub(entity, "namespace"),
            "exec_name": self.sub(entity, "exec_name"),
            "arguments": self.cmdline(entity, "args"),
            "ros_arguments": self.cmdline(entity, "ros_args"),
            "parameters": self.parameters(entity),
            "remappings": self.remaps(entity),
            "process": self.process_options(entity),
        }

    def composable_nodes(self, entity: Entity, *, required: bool) -> tuple[a.ComposableNode, ...]:
        """Read nested ``<composable_node>`` (and ``<composable_lifecycle_node>``)."""
        out = []
        found = False
        for nested_tag, lifecycle in (("composable_node", False),
                                      ("composable_lifecycle_node", True)):
            for item in entity.get_nested(nested_tag) or []:
                found = True
                node = self.composable_node(item, lifecycle)
                if node is not None:
                    out.append(node)
        if required and not found:
            self.sink.parse(f"`{entity.tag}` requires nested `composable_node`", entity.span)
        return tuple(out)

    def composable_node(self, item: Entity, lifecycle: bool) -> a.ComposableNode | None:
        """Read one composable node description."""
        if lifecycle and (why := distros.missing("the <composable_lifecycle_node> tag")):
            self.sink.parse(f"unknown tag `composable_lifecycle_node`: {why}", item.span)
        try:
            node = a.ComposableNode(
                package=self.req(item, "pkg"),
                plugin=self.req(item, "plugin"),
                name=self.req(item, "name"),
                namespace=self.sub(item, "namespace"),
                condition=self.condition(item),
                parameters=self.parameters(item),
                remappings=self.remaps(item),
                extra_arguments=tuple(
                    a.ParamItem(name=n, value=a.ParamValue(value=v), span=item.span)
                    for n, v in self.pairs(item, "extra_arg")
                ),
                lifecycle=lifecycle,
                autostart=(self.sub_or_bool(item, "autostart") or False) if lifecycle else False,
                span=item.span,
                attr_spans=self.spans(item),
            )
        except MissingAttribute:
            node = None
        self.finish(item)
        return node


def _integer(value: float | int | None) -> int | None:
    return None if value is None else int(value)


def _dotted(names: tuple[s.Sub, ...]) -> list[s.Sub]:
    out: list[s.Sub] = []
    for index, name in enumerate(names):
        if index:
            out.append(s.Text("."))
        out.append(name)
    return out


# ---------------------------------------------------------------------- launch


@tag("arg")
def _arg(p: TagParser, e: Entity) -> a.Action:
    name = p.plain(e, "name", required=True)
    assert name is not None
    choices = None
    for item in e.get_nested("choice") or []:
        value = p.plain(item, "value", required=False)
        p.finish(item)
        if value is not None:
            choices = (*(choices or ()), value)
    return a.DeclareArgument(
        **p.common(e),
        name=name,
        default=p.sub(e, "default"),
        description=p.plain(e, "description"),
        choices=choices,
    )


@tag("let")
def _let(p: TagParser, e: Entity) -> a.Action:
    return a.SetConfig(**p.common(e), name=p.req(e, "name"), value=p.req(e, "value"))


@tag("include")
def _include(p: TagParser, e: Entity) -> a.Action:
    arguments = []
    for nested in ("arg", "let"):
        for item in e.get_nested(nested) or []:
            with contextlib.suppress(MissingAttribute):
                arguments.append(a.IncludeArg(name=p.req(item, "name"),
                                              value=p.req(item, "value"), span=item.span))
            p.finish(item)
    arguments.sort(key=lambda arg: (arg.span.line, arg.span.column))
    return a.Include(**p.common(e), path=p.req(e, "file"), arguments=tuple(arguments))


@tag("group")
def _group(p: TagParser, e: Entity) -> a.Action:
    common = p.common(e)
    scoped = p.flag(e, "scoped")
    forwarding = p.flag(e, "forwarding")
    keep = p.pairs(e, "keep")
    children = [c for c in e.children() if c.tag != "keep"]
    return a.Group(
        **common,
        actions=p.actions(children),
        scoped=True if scoped is None else scoped,
        forwarding=True if forwarding is None else forwarding,
        keep=keep,
    )


@tag("reset")
def _reset(p: TagParser, e: Entity) -> a.Action:
    return a.ResetConfigs(**p.common(e), keep=p.pairs(e, "keep"))


@tag("executable")
def _executable(p: TagParser, e: Entity) -> a.Action:
    common = p.common(e)
    cmd = p.cmdline(e, "cmd", required=True)
    return a.ExecuteProcess(**common, cmd=cmd, process=p.process_options(e))


@tag("set_env")
def _set_env(p: TagParser, e: Entity) -> a.Action:
    return a.SetEnv(**p.common(e), name=p.req(e, "name"), value=p.req(e, "value"))


@tag("unset_env")
def _unset_env(p: TagParser, e: Entity) -> a.Action:
    return a.UnsetEnv(**p.common(e), name=p.req(e, "name"))


@tag("append_env")
def _append_env(p: TagParser, e: Entity) -> a.Action:
    return a.AppendEnv(
        **p.common(e),
        name=p.req(e, "name"),
        value=p.req(e, "value"),
        prepend=p.sub_or_bool(e, "prepend") or False,
        separator=p.sub(e, "separator"),
    )


@tag("reset_env")
def _reset_env(p: TagParser, e: Entity) -> a.Action:
    return a.ResetEnv(**p.common(e))


@tag("log", "log_info", "log_warning", "log_debug", "log_error")
def _log(p: TagParser, e: Entity) -> a.Action:
    level = e.tag[4:] if e.tag != "log" else (p.plain(e, "level") or "info")
    return a.Log(**p.common(e), message=p.req(e, "message"), level=level)


@tag("timer", "ros_timer")
def _timer(p: TagParser, e: Entity) -> a.Action:
    common = p.common(e)
    period = p.typed(e, "period", float)
    if period is None:
        p.sink.parse(f"`{e.tag}` requires the attribute `period`", e.span)
        raise MissingAttribute("period")
    period_sub = (
        p.parse_text(period, e.attrs["period"].span) if isinstance(period, str)
        else s.Text(str(period))
    )
    cancel = p.sub_or_bool(e, "cancel_on_shutdown")
    return a.Timer(
        **common,
        period=period_sub,
        actions=p.actions(e.children()),
        cancel_on_shutdown=True if cancel is None else cancel,
        ros_time=e.tag == "ros_timer",
    )


@tag("shutdown")
def _shutdown(p: TagParser, e: Entity) -> a.Action:
    return a.Shutdown(**p.common(e), reason=p.sub(e, "reason"))


@tag("for")
def _for(p: TagParser, e: Entity) -> a.Action:
    common = p.common(e)
    return a.ForLoop(
        **common,
        length=p.req(e, "len"),
        name=p.plain(e, "name") or "",
        actions=p.actions(e.children()),
    )


@tag("for_each")
def _for_each(p: TagParser, e: Entity) -> a.Action:
    common = p.common(e)
    return a.ForEach(**common, values=p.req(e, "values"), actions=p.actions(e.children()))


# ---------------------------------------------------------------------- launch_ros


@tag("node")
def _node(p: TagParser, e: Entity) -> a.Action:
    return a.Node(**p.node_fields(e))


@tag("lifecycle_node")
def _lifecycle_node(p: TagParser, e: Entity) -> a.Action:
    if why := distros.missing("the <lifecycle_node> tag"):
        p.sink.parse(f"unknown tag `lifecycle_node`: {why}; use a Python launch file's "
                     "LifecycleNode", e.span)
    fields = p.node_fields(e)
    if fields["name"] is None:
        p.sink.parse("`lifecycle_node` requires the attribute `name`", e.span)
    if fields["namespace"] is None:
        p.sink.parse("`lifecycle_node` requires the attribute `namespace`", e.span)
    return a.LifecycleNode(**fields, autostart=p.sub_or_bool(e, "autostart") or False)


@tag("node_container")
def _node_container(p: TagParser, e: Entity) -> a.Action:
    fields = p.node_fields(e)
    return a.ComposableNodeContainer(
        **fields,
        composable_nodes=p.composable_nodes(e, required=False),
    )


@tag("load_composable_node")
def _load_composable_node(p: TagParser, e: Entity) -> a.Action:
    common = p.common(e)
    return a.LoadComposableNodes(
        **common,
        target=p.req(e, "target"),
        composable_nodes=p.composable_nodes(e, required=True),
    )


@tag("push_ros_namespace", "push-ros-namespace")
def _push_ros_namespace(p: TagParser, e: Entity) -> a.Action:
    return a.PushNamespace(**p.common(e), namespace=p.req(e, "namespace"))


@tag("set_remap")
def _set_remap(p: TagParser, e: Entity) -> a.Action:
    return a.SetRemap(**p.common(e), src=p.req(e, "from"), dst=p.req(e, "to"))


@tag("set_parameter")
def _set_parameter(p: TagParser, e: Entity) -> a.Action:
    common = p.common(e)
    name = p.req(e, "name")
    raw = e.get("value")
    if raw is None:
        p.sink.parse("`set_parameter` requires the attribute `value`", e.span)
        raise MissingAttribute("value")
    value = p.param_value(e, raw.value, None)
    return a.SetParameter(**common, name=name, value=value)


@tag("set_parameters_from_file")
def _set_parameters_from_file(p: TagParser, e: Entity) -> a.Action:
    return a.SetParametersFromFile(**p.common(e), filename=p.req(e, "filename"))


@tag("set_use_sim_time")
def _set_use_sim_time(p: TagParser, e: Entity) -> a.Action:
    common = p.common(e)
    value = p.sub_or_bool(e, "value")
    if value is None:
        p.sink.parse("`set_use_sim_time` requires the attribute `value`", e.span)
        raise MissingAttribute("value")
    return a.SetUseSimTime(**common, value=value)


@tag("set_ros_log_dir")
def _set_ros_log_dir(p: TagParser, e: Entity) -> a.Action:
    return a.SetRosLogDir(**p.common(e), new_log_dir=p.req(e, "new_log_dir"))


# ---------------------------------------------------------------------- ros_gz (jazzy on)
# The tags ros_gz_sim and ros_gz_bridge expose; what they start is modelled in
# models/launch_api/ros_gz.py, shared with the Python actions.


def _ros_gz(p: TagParser, e: Entity, package: str) -> ros_gz.Written:
    """Report the tag where the checked distribution lacks it; return where it is written."""
    if why := ros_gz.missing(f"the <{e.tag}> tag of {package}"):
        p.sink.parse(f"unknown tag `{e.tag}` (ros2 launch: Unrecognized entity): {why}",
                     e.span)
    common = p.common(e)
    return ros_gz.Written(common["span"], common["condition"], common["attr_spans"])


def _flag(p: TagParser, e: Entity, name: str, default: bool) -> ros_gz.Flag:
    """Read a boolean attribute the action coerces when it runs (substitutions allowed)."""
    value = p.sub(e, name)
    return default if value is None else value


def _text(p: TagParser, e: Entity, name: str, default: str) -> s.Sub:
    """Read a text attribute, or the default the action's constructor has."""
    value = p.sub(e, name)
    return s.Text(default) if value is None else value


@tag("gz_server")
def _gz_server(p: TagParser, e: Entity) -> a.Action:
    where = _ros_gz(p, e, "ros_gz_sim")
    values = {name: a.ParamValue(value=_text(p, e, name, ""))
              for name in ("world_sdf_file", "world_sdf_string")}
    return ros_gz.gz_server(
        where, container_name=_text(p, e, "container_name", ros_gz.DEFAULT_CONTAINER),
        create_own_container=_flag(p, e, "create_own_container", False),
        use_composition=_flag(p, e, "use_composition", False),
        parameters=(ros_gz.param_dict(values, e.span),))


@tag("gz_spawn_model")
def _gz_spawn_model(p: TagParser, e: Entity) -> a.Action:
    where = _ros_gz(p, e, "ros_gz_sim")
    return ros_gz.gz_spawn_model(where, {name: p.sub(e, name)
                                         for name in ros_gz.SPAWN_ARGUMENTS})


# Attributes of <topic> and <service> under <ros_gz_bridge>: required, then optional (with
# the type launch reads them as).
_BRIDGE_ENTRIES: dict[str, tuple[tuple[str, ...], tuple[tuple[str, type], ...]]] = {
    "topic": (("ros_topic_name", "ros_type_name", "gz_topic_name", "gz_type_name"),
              (("direction", str), ("lazy", str), ("publisher_queue", int),
               ("subscriber_queue", int))),
    "service": (("service_name", "ros_type_name", "gz_req_type_name", "gz_rep_type_name"), ()),
}


def _bridge_entries(p: TagParser, e: Entity) -> dict[str, a.ParamValue]:
    """Read nested ``<topic>``/``<service>`` as ``bridges.bridge_N.*`` and ``bridge_names``."""
    out: dict[str, a.ParamValue] = {}
    names: list[str] = []
    for nested, (required, optional) in _BRIDGE_ENTRIES.items():
        for item in e.get_nested(nested) or []:
            key = f"bridge_{len(names)}"
            names.append(key)
            for name in required:
                with contextlib.suppress(MissingAttribute):
                    out[f"bridges.{key}.{name}"] = a.ParamValue(value=p.req(item, name))
            for name, kind in optional:
                value = p.sub(item, name) if kind is str else p.number(item, name, kind)
                if value is not None:
                    out[f"bridges.{key}.{name}"] = a.ParamValue(value=value)
            p.finish(item)
    if names:
        out["bridge_names"] = a.ParamValue(value=tuple(sorted(names)), value_type="str")
    return out


@tag("ros_gz_bridge")
def _ros_gz_bridge(p: TagParser, e: Entity) -> a.Action:
    where = _ros_gz(p, e, "ros_gz_bridge")
    bridge_name = p.req(e, "bridge_name")
    values = {"config_file": a.ParamValue(value=_text(p, e, "config_file", ""))}
    bridge_params = p.sub(e, "bridge_params")
    if bridge_params is not None:
        problem = ros_gz.bridge_params_problem(bridge_params)
        if problem is not None:
            p.sink.unmodeled(problem, e.attrs["bridge_params"].span)
        elif isinstance(bridge_params, s.Text):
            values.update((k, a.ParamValue(value=v))
                          for k, v in ros_gz.bridge_param_pairs(bridge_params.text).items())
    values.update(_bridge_entries(p, e))
    return ros_gz.ros_gz_bridge(
        where, bridge_name=bridge_name, namespace=_text(p, e, "namespace", ""),
        container_name=_text(p, e, "container_name", ros_gz.DEFAULT_CONTAINER),
        create_own_container=_flag(p, e, "create_own_container", False),
        use_composition=_flag(p, e, "use_composition", False),
        use_respawn=_flag(p, e, "use_respawn", False), log_level=_text(p, e, "log_level", "info"),
        parameters=(ros_gz.param_dict(values, e.span),))


# ---------------------------------------------------------------------- ROS 1 files

ROS1_MESSAGE = "ROS 1 launch file: not checked (ros2 launch cannot read it)"
# Tags of roslaunch (ROS 1). Any other tag with a handler above exists only in ROS 2.
_ROS1_TAGS = frozenset({"launch", "node", "machine", "include", "remap", "env", "param",
                        "rosparam", "group", "test", "arg"})
# Substitutions only roslaunch has; those it shares with ROS 2 prove nothing either way.
_ROS1_SUBSTITUTIONS = frozenset({"find", "arg", "optenv"})
_SHARED_SUBSTITUTIONS = frozenset({"env", "eval", "anon", "dirname"})
_DECISIVE = frozenset({"$(find)", "$(arg)"})
_SUBSTITUTION_NAME = re.compile(r"\$\(\s*([\w-]+)")


def ros1_launch_file(root: Entity, path: Path) -> Problem | None:
    """Return the info for an XML file written for roslaunch (ROS 1), else ``None``.

    The rule of recognition. The root must be ``<launch>``. ROS 1 signals, each counted
    once per kind:

    - the substitutions ``$(find ...)`` and ``$(arg ...)`` (decisive on their own) and
      ``$(optenv ...)``;
    - the tags ``<rosparam>``, ``<machine>`` and ``<test>``;
    - ``<node type=...>`` without ``exec``;
    - ``<arg value=...>`` without ``default`` outside an ``<include>`` (a ROS 1 constant);
    - ``<param>``, ``<remap>`` or ``<env>`` directly inside ``<launch>`` or ``<group>``
      (one kind per tag);
    - ``ns=`` on ``<node>``, ``<group>`` or ``<include>``;
    - a file name ending in ``.launch``.

    The file is ROS 1 when it has a decisive signal or two signals of different kinds, and
    no ROS 2 spelling at all: a tag only ROS 2 has (``<let>``, ``<executable>``,
    ``<set_parameter>``...), ``<node exec=...>`` or ``<node namespace=...>``, or a
    substitution only ROS 2 has (``$(var)``, ``$(find-pkg-share)``...). A ROS 2 file with a
    ROS 1 leftover, or a file ported halfway, keeps its parse errors.

    Only a file checked on its own gets this single info instead of its parse errors:
    ``ros2 launch`` cannot include it, so through an include its errors stay.
    """
    if root.tag != "launch":
        return None
    ros1: dict[str, Span] = {}
    if path.name.lower().endswith(".launch"):
        ros1[".launch file name"] = root.span
    for entity, parent in _walk(root, None):
        for kind, span in _ros1_signals(entity, parent):
            ros1.setdefault(kind, span)
        if _ros2_spelling(entity):
            return None
    if not (_DECISIVE & ros1.keys() or len(ros1) >= 2):
        return None
    seen = sorted(ros1.items(), key=lambda item: (item[1].line, item[1].column))
    evidence = ", ".join(f"{kind} (line {span.line})" for kind, span in seen[:3])
    return Problem(ProblemKind.UNMODELED, f"{ROS1_MESSAGE}; seen: {evidence}", root.span)


def _walk(entity: Entity, parent: str | None) -> Iterator[tuple[Entity, str | None]]:
    yield entity, parent
    for child in entity.child_list or []:
        yield from _walk(child, entity.tag)


def _substitution_names(entity: Entity) -> Iterator[tuple[str, Span]]:
    for attr in entity.attrs.values():
        if isinstance(attr.value, str):
            for match in _SUBSTITUTION_NAME.finditer(attr.value):
                yield match.group(1), attr.span


def _ros1_signals(entity: Entity, parent: str | None) -> Iterator[tuple[str, Span]]:
    for name, span in _substitution_names(entity):
        if name in _ROS1_SUBSTITUTIONS:
            yield f"$({name})", span
    attrs = entity.attrs
    if entity.tag in ("rosparam", "machine", "test"):
        yield f"<{entity.tag}>", entity.span
    if entity.tag == "node" and "type" in attrs and "exec" not in attrs:
        yield "<node type=>", attrs["type"].span
    if entity.tag == "arg" and parent != "include" and "value" in attrs \
            and "default" not in attrs:
        yield "<arg value=>", attrs["value"].span
    if entity.tag in ("param", "remap", "env") and parent in ("launch", "group"):
        yield f"<{entity.tag}> outside a node", entity.span
    if entity.tag in ("node", "group", "include") and "ns" in attrs:
        yield "ns=", attrs["ns"].span


def _ros2_spelling(entity: Entity) -> bool:
    if entity.tag in TAGS and entity.tag not in _ROS1_TAGS:
        return True
    if entity.tag == "node" and ("exec" in entity.attrs or "namespace" in entity.attrs):
        return True
    return any(name in SUBSTITUTIONS and name not in _SHARED_SUBSTITUTIONS
               for name, _ in _substitution_names(entity))
