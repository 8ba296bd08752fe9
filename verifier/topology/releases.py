"""One released package's models across ROS 2 distributions: the checked one's, or a merge.

``bench/interface_models.py`` extracts each package at the branch every distribution is
released from (``models/interfaces/<distro>/<package>.json``). A check for one of those
distributions reads that model. A check for any distribution (none given), or for one no
model is extracted for (iron, kilted), reads what holds for every release: a name is
declared when one release declares it (a name another release takes is no typo), and a
type, a default, a bound, ``read_only`` or ``required`` count only where every release
that declares the name agrees (a bound a value breaks in one release alone is no fact of
the robot's).
"""

from __future__ import annotations

from dataclasses import replace

from launchverify.topology.model import NodeInterface, Parameter

# The distributions models are extracted for, newest last
MODEL_DISTROS = ("humble", "jazzy", "rolling")
# Whose endpoints and node names a check for any distribution takes: the newest LTS
# release's first (what most robots run), then the others
BASE = ("jazzy", "humble", "rolling")


def merged_interfaces(by_distro: dict[str, tuple[NodeInterface, ...]]
                      ) -> tuple[NodeInterface, ...]:
    """Return one interface per executable or component: what every release agrees on.

    Endpoints and node name are the first release's of ``BASE`` that has the target; the
    parameters are merged; the interface is open when one release's is.
    """
    newest = sorted(by_distro, key=lambda d: -BASE.index(d) if d in BASE else -len(BASE))
    keys: dict[tuple[str, str | None], list[NodeInterface]] = {}
    for distro in newest:
        for interface in by_distro[distro]:
            keys.setdefault((interface.executable, interface.component), []).append(interface)
    out = []
    for releases in keys.values():
        last = releases[-1]
        opened = next((r.parameters_open for r in reversed(releases)
                       if r.parameters_open is not None), None)
        out.append(replace(last, parameters=merged_parameters(
            [r.parameters for r in releases]), parameters_open=opened,
            problems=tuple(dict.fromkeys(p for r in releases for p in r.problems)),
            distro=None))
    return tuple(out)


def merged_parameters(releases: list[tuple[Parameter, ...]]) -> tuple[Parameter, ...]:
    """Return each name declared by a release, with only the facts all releases share.

    Examples:
        >>> from launchverify.span import Span
        >>> from pathlib import Path
        >>> at = Span(Path("x.cpp"), 1)
        >>> old = (Parameter("rate", "double", at, 10.0, limits=(("gt", (0,)),)),)
        >>> new = (Parameter("rate", "double", at, 20.0, limits=(("gt", (0,)),)),
        ...        Parameter("mode", "string", at, required=True))
        >>> [(p.name, p.type, p.default, p.limits, p.required)
        ...  for p in merged_parameters([old, new])]
        [('rate', 'double', None, (('gt', (0,)),), False), ('mode', 'string', None, (), False)]
    """
    names: dict[str, list[Parameter]] = {}
    for declared in releases:
        seen: set[str] = set()
        for parameter in declared:
            if parameter.name not in seen:  # one declaration a release (several places)
                names.setdefault(parameter.name, []).append(parameter)
                seen.add(parameter.name)
    out = []
    everywhere = len(releases)
    for found in names.values():
        last = found[-1]
        if len(found) == everywhere and all(_same_facts(p, last) for p in found):
            out.append(last)
            continue
        shared = len(found) == everywhere
        out.append(replace(
            last, type=last.type if all(p.type == last.type for p in found) else None,
            default=_agreed([p.default for p in found]) if shared else None,
            dynamic=any(p.dynamic for p in found),
            required=shared and all(p.required for p in found),
            read_only=shared and all(p.read_only for p in found),
            limits=tuple(limit for limit in last.limits
                         if shared and all(limit in p.limits for p in found))))
    return tuple(out)


def _same_facts(one: Parameter, other: Parameter) -> bool:
    return (one.type, one.default, one.dynamic, one.required, one.read_only, one.limits) == (
        other.type, other.default, other.dynamic, other.required, other.read_only,
        other.limits)


def _agreed(values: list[object]) -> object:
    """Return the value every release gives, ``None`` when they differ."""
    first = values[0]
    return first if all(value == first for value in values) else None
