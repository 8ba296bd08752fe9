"""The report's "Computation graph" part of one system: composed, laid out, drawn.

Composing reads node sources, which ``check`` never does; one package's surprise is
already contained by ``WorkspaceInterfaces``, and anything else going wrong here costs
this part of the page only (said in its place), never the report.
"""

from __future__ import annotations

from launchverify.graph import LaunchGraph
from launchverify.render.flow_model import FlowGraph, build_flow
from launchverify.render.flow_svg import render_flow
from launchverify.render.system_model import SystemModel
from launchverify.topology.compose import InterfaceSource


def computation_graph(model: SystemModel, graph: LaunchGraph, interfaces: InterfaceSource,
                      number: int, anchor: str) -> str:
    """Return the computation graph of system ``number`` (node links: ``#{anchor}-N``)."""
    try:
        flow = build_flow(model, graph, interfaces)
    except Exception as error:  # a bug of ours must not cost the whole report
        flow = FlowGraph({}, {}, [], reason=f"composing the nodes with their sources "
                         f"failed ({type(error).__name__}: {error})")
    return render_flow(flow, number, anchor)
