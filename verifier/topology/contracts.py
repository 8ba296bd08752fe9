"""Each launched node's parameter contract: what its code declares, what the launch gives.

The declarations come from the node's interface (``topology.nodes``: the workspace's
sources), the values from ``parameters.effective_parameters``. A contract is judged only
as far as it is known: ``open`` says why the node may accept names it is not seen to
declare (then no name is unknown to it), and a node whose command line sets parameters
itself (``-p``, ``--params-file`` in its arguments) may receive more than the launch's
parameter sources say.
"""

from __future__ import annotations

from dataclasses import dataclass
from fnmatch import fnmatchcase
from typing import TYPE_CHECKING

from launchverify.models.node_parameters import BUILTIN_PARAMETERS
from launchverify.parameters import EffectiveParameters, effective_parameters
from launchverify.suggest import sole_spelling
from launchverify.topology.model import Parameter, PluginContract, soft_open

if TYPE_CHECKING:
    from launchverify.graph import LaunchGraph
    from launchverify.rule import RuleContext
    from launchverify.topology.compose import NodeEndpoints
    from launchverify.topology.wiring import WiringView

_PARAMETER_FLAGS = frozenset({"-p", "--param", "--params-file"})


@dataclass(frozen=True)
class Contract:
    """One launched node, the parameters its code declares and those it receives."""

    composed: NodeEndpoints
    declared: tuple[Parameter, ...]
    received: EffectiveParameters
    open: str | None  # why undeclared names may still be accepted; None: they are not
    command_line: bool  # its command line sets parameters the sources above do not show
    unmatched: str | None  # why file blocks for the node may be missed (its name unknown)

    @property
    def values_known(self) -> bool:
        """Return whether ``received`` holds every value the node gets, as given."""
        return self.received.complete and self.unmatched is None and not self.command_line

    def declarations(self, name: str) -> list[Parameter]:
        """Return the declarations of exactly ``name`` (several files may declare it)."""
        return [p for p in self.declared if p.name == name]

    def accepts(self, name: str) -> bool:
        """Return whether the node or a plugin it may load declares ``name``.

        The ``*`` standing for plugins not known is left out, and so is a plugin's own
        ``*`` (a name its code builds entirely at run time): what they accept is not
        known, and ``open`` says so.
        """
        return any(fnmatchcase(name, p.name) for p in self.declared
                   if p.name != "*" or p.via != "plugins") or any(
            fnmatchcase(name, builtin) for builtin in BUILTIN_PARAMETERS) or any(
            fnmatchcase(name, p.name) for plugin in self.plugins for p in plugin.parameters
            if p.name != "*")

    @property
    def plugins(self) -> tuple[PluginContract, ...]:
        """Return the plugins known to derive from what the node loads."""
        interface = self.composed.interface
        return interface.plugins if interface is not None else ()

    @property
    def typos_only(self) -> bool:
        """Return whether only a misspelling of a known name can be told an error.

        So for a node that accepts undeclared names or loads plugins (``soft_open``), and
        for a released package judged for any distribution (a name another release
        declares is no mistake).
        """
        interface = self.composed.interface
        return self.open is not None or (interface is not None and interface.model is not None
                                         and interface.distro is None)

    def plugin_meant(self, name: str) -> str | None:
        """Return the name a key under a plugin's name misspells, ``None`` if none.

        ``FollowPath.max_vel_xx`` where ``FollowPath.plugin`` names a known plugin whose
        only close name is ``*.max_vel_x``: ``FollowPath.max_vel_x``. A plugin that may
        declare more than is known (its own sources not all read) says nothing.
        """
        prefix, dot, rest = name.rpartition(".")
        winner = self.received.winner(f"{prefix}.plugin") if dot and prefix else None
        chosen = winner.value if winner is not None else None
        plugin = next((p for p in self.plugins if p.type == chosen), None)
        if plugin is None or (plugin.open is not None and not soft_open(plugin.open)):
            return None
        own = frozenset(p.name[2:] for p in plugin.parameters
                        if p.name.startswith("*.") and "*" not in p.name[2:])
        meant = sole_spelling(rest, own)
        return None if meant is None else f"{prefix}.{meant}"

    def static_type(self, name: str) -> Parameter | None:
        """Return the one declaration that fixes ``name``'s type, if they all agree."""
        found = self.declarations(name)
        if not found or any(p.dynamic or p.type is None for p in found):
            return None
        return found[0] if len({p.type for p in found}) == 1 else None

    def concrete_names(self) -> list[str]:
        """Return the declared names without run-time parts (did-you-mean candidates).

        With the names its known plugins declare unprefixed (nav2's behaviours).
        """
        return sorted({p.name for p in self.declared if "*" not in p.name} | {
            p.name for plugin in self.plugins for p in plugin.parameters if "*" not in p.name})


def judged(graph: LaunchGraph, ctx: RuleContext) -> tuple[WiringView, list[Contract]] | None:
    """Return the graph's view and its nodes' contracts for the parameter rules.

    ``None`` when no node that may run has sources here or a shipped model: then there is
    no code to hold the launch to, and nothing is composed.
    """
    from launchverify.topology.wiring import any_view, knows_code

    if not knows_code(graph, ctx):
        return None
    view = any_view(graph, ctx)
    return view, contracts(view)


def contracts(view: WiringView) -> list[Contract]:
    """Return the contract of every node of the view whose code was read (once per view)."""
    kept = view.graph.derived.setdefault("contracts", {})
    found = kept.get(id(view))
    if isinstance(found, list):
        return found
    result = [_contract(view, composed) for composed in view.nodes
              if composed.interface is not None and composed.interface.parameters]
    kept[id(view)] = result
    return result


def _contract(view: WiringView, composed: NodeEndpoints) -> Contract:
    assert composed.interface is not None
    interface = composed.interface
    from launchverify.topology.compose import named_record

    record = named_record(view.graph, composed)
    received = effective_parameters(view.graph, record)
    unmatched = None
    if any(p.file is not None for p in record.parameters) and \
            view.graph.base(record.fqn) is None:
        unmatched = "its parameter files are keyed by node name, which the launch does not give"
    return Contract(composed, interface.parameters, received, interface.parameters_open,
                    _sets_parameters(view, composed), unmatched)


def _sets_parameters(view: WiringView, composed: NodeEndpoints) -> bool:
    """Return whether the node's command line may set parameters (``-p``, a file)."""
    launch = view.graph.launch_of(composed.node)
    if launch is None:
        return False
    words = view.composer.words(launch.arguments + launch.ros_arguments)
    return any(not isinstance(w, str) or w in _PARAMETER_FLAGS for w in words)
