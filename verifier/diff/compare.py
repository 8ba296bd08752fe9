"""Two snapshots compared launch by launch: what a change does to the launched system.

Launch files pair by path (following the renames git saw). Within a pair, nodes pair by
fully qualified name; a node gone and a node new with the same package and executable
are one node renamed (or moved to another namespace). Paired nodes compare the value
each parameter ends up with (and where it is given), their parameter files, remappings
and what they run. Includes compare by target, the computation graph by name (what
appears, goes, or loses an end), nodes that start only for other argument values by
their condition and wiring as written, arguments by name, lifecycle managers by the
nodes they bring up, findings by fingerprint, then by where they are (``_findings``).
The result is plain data, documented in docs/output.md.
"""

from __future__ import annotations

import bisect
from collections.abc import Callable
from typing import Any

from launchverify.diff.snapshot import Launch, Snapshot

Data = dict[str, Any]


def compare(base: Snapshot, head: Snapshot, renamed: dict[str, str]) -> Data:
    """Return what differs between the two sides (``renamed``: base path -> head path)."""
    back = {new: old for old, new in renamed.items()}
    launches: list[Data] = []
    unseen: list[Data] = []  # read changed files, and nothing seen of it changed
    unchanged = 0
    paired_base: set[str] = set()
    for file in sorted(head.launches):
        before_file = back.get(file, file)
        before = base.launches.get(before_file)
        if before is None and file in base.launches:
            before, before_file = base.launches[file], file
        if before is not None:
            paired_base.add(before_file)
        found = compare_launch(before, head.launches[file])
        if found is None:
            unchanged += 1
        elif found["status"] == "inputs":
            unseen.append({"file": file, "inputs_changed": found["inputs_changed"]})
        else:
            launches.append({"file": file, "base_file": before_file if before else None,
                             **found})
    for file in sorted(set(base.launches) - paired_base):
        found = compare_launch(base.launches[file], None)
        if found is not None:
            launches.append({"file": file, "base_file": file, **found})
    introduced, fixed, changed = _findings(base, head, renamed)
    return {"launches": launches, "unchanged": unchanged, "inputs_only": unseen,
            "findings": {"introduced": introduced, "fixed": fixed, "changed": changed},
            "summary": _summary(launches, introduced, fixed, changed)}


Key = Callable[[Data, str], tuple[str, ...] | None]  # a finding, its anchor -> its key
# How findings without a twin fingerprint pair, in turn: the same message at the same
# line text (another occurrence number: an identical finding came or went before it);
# the same message (an edited line that keeps its mistake); the same line text and
# severity (the same finding, its message changed: a remap whose first rule now names
# another target). Each within one rule and file (renames followed).
_PAIRINGS: tuple[Key, ...] = (
    lambda finding, anchor: (finding["message"], anchor),
    lambda finding, anchor: (finding["message"],),
    lambda finding, anchor: (anchor, finding["severity"]) if anchor else None,
)


def _findings(base: Snapshot, head: Snapshot, renamed: dict[str, str]
              ) -> tuple[list[Data], list[Data], list[Data]]:
    """Return the findings only the head side has, only the base side has, and changed.

    Fingerprints pair most (they hold no line number). The others pair by what they
    still share (``_PAIRINGS``), each with the candidate nearest its line; one paired
    with another message is ``changed`` (the head side's, its ``base`` the other's),
    not one finding introduced and one fixed.
    """
    only_base = [f for f in base.findings if f not in head.findings]
    only_head = [f for f in head.findings if f not in base.findings]
    pairs: list[tuple[str, str]] = []  # base fingerprint, head fingerprint
    for key in _PAIRINGS:
        candidates: dict[tuple[str, ...], tuple[list[int], list[str]]] = {}
        for print_ in only_base:
            finding = base.findings[print_]
            found = key(finding, base.anchors.get(print_, ""))
            if found is not None:
                lines, prints = candidates.setdefault(
                    (finding["code"], renamed.get(finding["file"]) or finding["file"],
                     *found), ([], []))
                at = bisect.bisect(lines, finding["line"])
                lines.insert(at, finding["line"])
                prints.insert(at, print_)
        left = []
        for print_ in only_head:
            finding = head.findings[print_]
            found = key(finding, head.anchors.get(print_, ""))
            bucket = None if found is None else candidates.get(
                (finding["code"], finding["file"], *found))
            if not bucket or not bucket[0]:
                left.append(print_)
                continue
            pairs.append((_nearest(bucket, finding["line"]), print_))
        paired = {was for was, _ in pairs}
        only_base = [print_ for print_ in only_base if print_ not in paired]
        only_head = left
    twin = {now: was for was, now in pairs}
    changed = [finding | {"fingerprint": now, "base": {
                   key: base.findings[twin[now]][key] for key in ("file", "line", "message")}
                   | {"fingerprint": twin[now]}}
               for now, finding in head.findings.items()
               if now in twin and base.findings[twin[now]]["message"] != finding["message"]]
    return ([head.findings[f] | {"fingerprint": f} for f in only_head],
            [base.findings[f] | {"fingerprint": f} for f in only_base], changed)


def _nearest(bucket: tuple[list[int], list[str]], line: int) -> str:
    """Take the candidate nearest a line out of a bucket (lines sorted) and return it."""
    lines, prints = bucket
    at = bisect.bisect(lines, line)
    if at == len(lines) or (at > 0 and line - lines[at - 1] <= lines[at] - line):
        at -= 1
    del lines[at]
    return prints.pop(at)


def compare_launch(before: Launch | None, after: Launch | None) -> Data | None:
    """Return how one launch file's system changed (``None``: it did not)."""
    status = "added" if before is None else "removed" if after is None else "changed"
    old = before or Launch("")
    new = after or Launch("")
    nodes, pairs = _nodes(old.nodes, new.nodes)
    parameters, files, remappings, executables = [], [], [], []
    for was, now in pairs:
        parameters += _parameters(was, now)
        files += _listed(was, now, "parameter_files")
        remappings += _listed(was, now, "remappings")
        if (was["package"], was["executable"]) != (now["package"], now["executable"]):
            executables.append({"node": now["label"],
                                "base": f"{was['package']}/{was['executable']}",
                                "head": f"{now['package']}/{now['executable']}",
                                "file": now["file"], "line": now["line"]})
    arguments = _arguments(old.arguments, new.arguments)
    lifecycle = [{"manager": name, "base": old.managers.get(name),
                  "head": new.managers.get(name)}
                 for name in sorted(set(old.managers) | set(new.managers))
                 if old.managers.get(name) != new.managers.get(name)]
    dormant: list[Data] = [
        {"node": key, "base": old.dormant.get(key), "head": new.dormant.get(key),
         "witness": new.witnesses.get(key) or old.witnesses.get(key)}
        for key in sorted(set(old.dormant) | set(new.dormant))
        if old.dormant.get(key) != new.dormant.get(key)]
    for key in sorted(set(old.dormant_wiring) & set(new.dormant_wiring)):
        was, now = old.dormant_wiring[key], new.dormant_wiring[key]
        node, _, condition = key.partition(" when ")
        for part in ("parameters", "remappings"):
            added = [item for item in now[part] if item not in was[part]]
            removed = [item for item in was[part] if item not in now[part]]
            if added or removed:
                dormant.append({"node": node, "when": condition,
                                "witness": new.witnesses.get(node), part: {
                                    "added": added, "removed": removed}})
    inputs = _inputs(old.inputs, new.inputs) if before and after else []
    includes = [{"include": name, "base": old.includes.get(name),
                 "head": new.includes.get(name)}
                for name in sorted(set(old.includes) | set(new.includes))
                if old.includes.get(name) != new.includes.get(name)]
    graph = _graph(old.endpoints, new.endpoints)
    found: Data = {"status": status, "inputs_changed": inputs, "nodes": nodes,
                   "includes": includes, "graph": graph,
                   "conditional": dormant,
                   "parameters": parameters, "parameter_files": files,
                   "remappings": remappings, "executables": executables,
                   "arguments": arguments, "lifecycle": lifecycle,
                   "stops": {"base": old.stopped, "head": new.stopped}}
    if status == "changed" and not (any(nodes.values()) or includes or graph or dormant
                                    or parameters
                                    or files
                                    or remappings
                                    or executables or any(arguments.values()) or lifecycle
                                    or old.stopped != new.stopped):
        if not inputs:
            return None
        found["status"] = "inputs"  # files it reads changed; what it starts did not, as seen
    return found


_ENDS = {"topic": ("publishers", "subscribers"), "service": ("servers", "clients"),
         "action": ("servers", "clients")}


def _graph(old: dict[str, Data], new: dict[str, Data]) -> list[Data]:
    """Return the topics, services and actions that appear, go, lose or find an end.

    An end lost is a name that had nodes on both ends and now has none on one (a topic
    whose last publisher went), an end found the reverse; a type changed is said too.
    Which nodes are on an end otherwise is left to the nodes' own changes.
    """
    out = []
    for name in sorted(set(old) | set(new)):
        was, now = old.get(name), new.get(name)
        if was is None or now is None:
            out.append({"name": name, "change": "added" if was is None else "removed",
                        "base": was, "head": now})
            continue
        ends = _ENDS[name.split(" ", 1)[0]]
        if _connected(was, ends) != _connected(now, ends):
            out.append({"name": name, "base": was, "head": now,
                        "change": "end lost" if _connected(was, ends) else "end found"})
        elif was["type"] != now["type"]:
            out.append({"name": name, "change": "type", "base": was, "head": now})
    return out


def _connected(entry: Data, ends: tuple[str, str]) -> bool:
    return all(entry[end] for end in ends)


def _inputs(old: dict[str, str] | None, new: dict[str, str] | None) -> list[str] | None:
    """Return the files a launch reads that differ between the sides (None: not known)."""
    if old is None or new is None:
        return None
    return sorted(name for name in set(old) | set(new) if old.get(name) != new.get(name))


def _nodes(old: dict[str, Data], new: dict[str, Data]
           ) -> tuple[Data, list[tuple[Data, Data]]]:
    """Return nodes added, removed and renamed, and every pair of one node's two sides."""
    pairs = [(old[name], new[name]) for name in new if name in old]
    gone = [old[name] for name in old if name not in new]
    came = [new[name] for name in new if name not in old]
    renamed = []
    for node in list(came):
        twin = next((g for g in gone if (g["package"], g["executable"])
                     == (node["package"], node["executable"])), None)
        if twin is not None:
            gone.remove(twin)
            came.remove(node)
            pairs.append((twin, node))
            renamed.append({"base": twin["fqn"], "head": node["fqn"],
                            "package": node["package"], "executable": node["executable"],
                            "file": node["file"], "line": node["line"]})
    return ({"added": [_brief(n) for n in came], "removed": [_brief(n) for n in gone],
             "renamed": renamed}, pairs)


def _brief(node: Data) -> Data:
    return {key: node[key] for key in ("fqn", "package", "executable", "condition", "file",
                                       "line")}


def _parameters(was: Data, now: Data) -> list[Data]:
    """Return the parameters whose value (or presence) differs between a node's sides."""
    out = []
    for name in sorted(set(was["parameters"]) | set(now["parameters"])):
        before, after = was["parameters"].get(name), now["parameters"].get(name)
        if before is not None and after is not None and _same(before, after):
            continue
        out.append({"node": now["label"], "name": name, "base": before, "head": after})
    return out


def _same(before: Data, after: Data) -> bool:
    """Return whether a parameter gets the same value (an unknown one by the same expression)."""
    if before["value"] is None or after["value"] is None:
        return (before["value"], before.get("expression")) == (after["value"],
                                                               after.get("expression"))
    return bool(before["value"] == after["value"]
                and type(before["value"]) is type(after["value"]))


def _listed(was: Data, now: Data, key: str) -> list[Data]:
    """Return what a node's list (remappings, parameter files) gained and lost."""
    added = [r for r in now[key] if r not in was[key]]
    removed = [r for r in was[key] if r not in now[key]]
    if not added and not removed:
        return []
    return [{"node": now["label"], "added": added, "removed": removed, "file": now["file"],
             "line": now["line"]}]


def _arguments(old: dict[str, Data], new: dict[str, Data]) -> Data:
    return {
        "added": [{"name": n, **new[n]} for n in new if n not in old],
        "removed": [{"name": n, **old[n]} for n in old if n not in new],
        "changed": [{"name": n, "base": old[n]["default"], "head": new[n]["default"],
                     "file": new[n]["file"], "line": new[n]["line"]}
                    for n in new if n in old and old[n]["default"] != new[n]["default"]],
    }


def _summary(launches: list[Data], introduced: list[Data], fixed: list[Data],
             changed: list[Data]) -> Data:
    def count(key: str, part: str | None = None) -> int:
        return sum(len(launch[key][part] if part else launch[key]) for launch in launches)

    return {
        "launches_changed": len(launches),
        "nodes_added": count("nodes", "added"), "nodes_removed": count("nodes", "removed"),
        "nodes_renamed": count("nodes", "renamed"), "conditional_changed": count("conditional"),
        "includes_changed": count("includes"), "graph_changed": count("graph"),
        "parameters_changed": count("parameters"),
        "parameter_files_changed": count("parameter_files"),
        "remappings_changed": count("remappings"),
        "executables_changed": count("executables"),
        "arguments_changed": sum(len(launch["arguments"][part]) for launch in launches
                                 for part in ("added", "removed", "changed")),
        "lifecycle_changed": count("lifecycle"),
        "findings_introduced": len(introduced), "findings_fixed": len(fixed),
        "findings_changed": len(changed),
        "errors_introduced": sum(f["severity"] == "error" for f in introduced),
    }
