"""The report's "Computation graph" part of one system: composed, laid out, drawn.

Composing reads node sources, which ``check`` never does; one package's surprise is
already contained by ``WorkspaceInterfaces``, and anything else going wrong here costs
this part of the page only (said in its place), never the report.
"""

from __future__ import annotations

from launchverify.graph import LaunchGraph
from launchverify.render.flow_model import Composition, FlowGraph, assemble, compose_view
from launchverify.render.flow_svg import render_flow
from launchverify.render.html_shared import Shared
from launchverify.render.system_model import SystemModel
from launchverify.topology.compose import InterfaceSource


def compose_system(graph: LaunchGraph, interfaces: InterfaceSource) -> Composition:
    """Return the nodes of one root composed with their sources (never raises).

    Composed once per section: the picture takes the names the sources give unnamed
    nodes from it, the computation graph everything else.
    """
    try:
        return compose_view(graph, interfaces)
    except Exception as error:  # a bug of ours must not cost the whole report
        return Composition([], _failed(error))


def computation_graph(model: SystemModel, composition: Composition, number: int,
                      anchor: str, shared: Shared | None = None) -> str:
    """Return the computation graph of system ``number`` (node links: ``#{anchor}-N``).

    ``shared``: what earlier systems drew; a graph one of them drew is linked to.
    """
    if composition.reason is not None:
        flow = FlowGraph({}, {}, [], reason=composition.reason)
    else:
        try:
            flow = assemble(model.nodes, composition.nodes)
        except Exception as error:  # likewise
            flow = FlowGraph({}, {}, [], reason=_failed(error))
    return render_flow(flow, number, anchor, shared)


def _failed(error: Exception) -> str:
    return f"composing the nodes with their sources failed ({type(error).__name__}: {error})"
