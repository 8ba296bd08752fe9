"""A diff written out: text for a terminal, JSON, Markdown for a pull request, annotations.

Names and values come from the files a pull request wrote. In text they are made inert
(``render.inert``); in Markdown each sits in a code span that it cannot leave (its
backticks fenced by longer runs, line breaks and table bars neutralised, its length
bounded), so a value cannot add links, images, mentions or HTML to a comment; in the
GitHub format they are escaped as the runner unescapes them.
"""

from __future__ import annotations

import html
import io
import json
import re
from collections.abc import Iterator
from typing import Any, TextIO

from launchverify.render.github import escape_data, escape_property
from launchverify.render.inert import inert

Data = dict[str, Any]
MAX_VALUE = 120  # characters of one value shown in text and Markdown
_COLOURS = {"+": "\x1b[32m", "-": "\x1b[31m", "~": "\x1b[33m", "!": "\x1b[1;31m",
            "?": "\x1b[2m"}
_RESET = "\x1b[0m"
_MARKS = {"+": "\N{HEAVY PLUS SIGN}", "-": "\N{HEAVY MINUS SIGN}",
          "~": "\N{PENCIL}\N{VARIATION SELECTOR-16}", "!": "\N{NO ENTRY}",
          "?": "\N{WHITE QUESTION MARK ORNAMENT}"}


def render_json(diff: Data, out: TextIO) -> None:
    """Write the diff as JSON (docs/output.md)."""
    json.dump(diff, out, indent=2, sort_keys=False)
    out.write("\n")


# ------------------------------------------------------------------ one change per line


Change = tuple[str, str, str | None, int | None]  # mark, sentence, file, line


def changes(launch: Data) -> Iterator[Change]:
    """Yield a launch's changes: a mark, a sentence, and its place on the head side.

    Marks: ``+`` added, ``-`` removed, ``~`` changed, ``!`` broken (a topic's last
    publisher gone, the launch stopping at an error).
    """
    for part in (_nodes, _includes, _graph, _conditional, _wiring, _arguments, _others):
        yield from part(launch)


def _nodes(launch: Data) -> Iterator[Change]:
    nodes = launch["nodes"]
    for mark, group in (("+", nodes["added"]), ("-", nodes["removed"])):
        for node in group:
            yield mark, f"node {_v(node['fqn'])} ({_v(node['package'])}/" \
                f"{_v(node['executable'])}){_when(node)}", node["file"], node["line"]
    for node in nodes["renamed"]:
        yield "~", f"node {_v(node['base'])} is now {_v(node['head'])} " \
            f"({_v(node['package'])}/{_v(node['executable'])})", node["file"], node["line"]


def _includes(launch: Data) -> Iterator[Change]:
    for change in launch["includes"]:
        before, after = change["base"], change["head"]
        if before is None:
            yield "+", f"includes {_v(change['include'])}" + (
                f" ({after})" if after != "loaded" else ""), None, None
        elif after is None:
            yield "-", f"no longer includes {_v(change['include'])}", None, None
        else:
            yield "~", f"include {_v(change['include'])}: {before} -> {after}", None, None


def _graph(launch: Data) -> Iterator[Change]:
    for change in launch["graph"]:
        kind, name = change["name"].split(" ", 1)
        before, after = change["base"], change["head"]
        first, second = ("publishers", "subscribers") if kind == "topic" else \
            ("servers", "clients")
        if change["change"] == "added":
            yield "+", f"{kind} {_v(name)} ({_v(after['type'])}){_ends(after, first, second)}", \
                None, None
        elif change["change"] == "removed":
            yield "-", f"{kind} {_v(name)}{_ends(before, first, second)}", None, None
        elif change["change"] == "type":
            yield "~", f"{kind} {_v(name)}: type {_v(before['type'])} -> " \
                f"{_v(after['type'])}", None, None
        elif change["change"] == "end lost":
            lost = first if not after[first] and before[first] else second
            yield "!", f"{kind} {_v(name)} lost its last {lost[:-1]} " \
                f"({_list(before[lost])}){_ends(after, first, second)}", None, None
        else:
            yield "+", f"{kind} {_v(name)} is now connected{_ends(after, first, second)}", \
                None, None


def _conditional(launch: Data) -> Iterator[Change]:
    for change in launch["conditional"]:
        node = _v(change["node"])
        if "when" in change:  # a node that starts for other values, wired otherwise now
            part = "parameters" if "parameters" in change else "remappings"
            when = f"as with {_assigned(change['witness'])}" if change.get("witness") \
                else f"when {change['when']}"
            yield "~", f"node {node} ({_v(when)}): {part} {_gained(change[part])}", None, None
            continue
        before, after = change["base"], change["head"]
        example = f" (as with {_v(_assigned(change['witness']))})" \
            if change.get("witness") else ""
        if before is None:
            yield "+", f"node {node} starts when {_v(after)}{example}", None, None
        elif after is None:
            yield "-", f"node {node} no longer starts when {_v(before)}{example}", None, None
        else:
            yield "~", f"node {node} starts when {_v(after)} (was when {_v(before)})" \
                f"{example}", None, None


def _wiring(launch: Data) -> Iterator[Change]:
    """What paired nodes run and are given: executables, parameters, files, remappings."""
    for change in launch["executables"]:
        yield "~", f"node {_v(change['node'])} runs {_v(change['head'])} (was " \
            f"{_v(change['base'])})", change["file"], change["line"]
    for change in launch["parameters"]:
        before, after = change["base"], change["head"]
        file, _, line = (after or before)["from"].rpartition(":")
        moved = before is not None and after is not None and before["from"] != after["from"]
        yield "~", f"{_v(change['node'])}: {_v(change['name'])} {_given(before, moved)} -> " \
            f"{_given(after, moved)}", file or None, int(line) if line.isdigit() else None
    for key, verb in (("parameter_files", "parameter files"), ("remappings", "remaps")):
        for change in launch[key]:
            yield "~", f"{_v(change['node'])} {verb} {_gained(change)}", change["file"], \
                change["line"]


def _arguments(launch: Data) -> Iterator[Change]:
    arguments = launch["arguments"]
    for argument in arguments["added"]:
        yield "+", f"argument {_v(argument['name'])} (default {_v(argument['default'])})", \
            argument["file"], argument["line"]
    for argument in arguments["removed"]:
        yield "-", f"argument {_v(argument['name'])}", argument["file"], argument["line"]
    for argument in arguments["changed"]:
        yield "~", f"argument {_v(argument['name'])}: default {_v(argument['base'])} -> " \
            f"{_v(argument['head'])}", argument["file"], argument["line"]


def _others(launch: Data) -> Iterator[Change]:
    """Lifecycle managers' node lists, and whether the launch stops at an error."""
    for manager in launch["lifecycle"]:
        yield "~", f"lifecycle manager {_v(manager['manager'])} brings up " \
            f"{_list(manager['head'])} (was {_list(manager['base'])})", None, None
    stops = launch["stops"]
    if stops["base"] != stops["head"]:
        yield ("!", "the launch now stops at an error", None, None) if stops["head"] else \
            ("~", "the launch no longer stops at an error", None, None)


def _gained(change: Data) -> str:
    """Return what a list gained and lost: ``+ a, - b``."""
    return ", ".join([f"+ {_v(item)}" for item in change["added"]]
                     + [f"- {_v(item)}" for item in change["removed"]])


def _ends(ends: Data, first: str, second: str) -> str:
    """Return who is on each end of a name, briefly."""
    return f": {first} {_list(ends[first])}, {second} {_list(ends[second])}"


def _v(value: object) -> str:
    """Return a value to show, cut to ``MAX_VALUE`` characters at a word's end with ``…``.

    A value with no space in its second half (a long path or name) is cut inside it.
    """
    text = "(unknown)" if value is None else str(value)
    if len(text) <= MAX_VALUE:
        return text
    end = text.rfind(" ", 0, MAX_VALUE)  # the ellipsis takes the space's place
    if end < MAX_VALUE // 2:
        end = MAX_VALUE - 1
    return text[:end].rstrip(" ,;:") + "…"


def _when(node: Data) -> str:
    return f" when {_v(node['condition'])}" if node.get("condition") else ""


def _given(given: Data | None, where: bool = False) -> str:
    """Return a parameter's value (and where it is set, when the two sides differ there)."""
    if given is None:
        return "(not set)"
    value = given["value"]
    shown = json.dumps(value) if value is not None else given.get("expression", "(unknown)")
    return f"{_v(shown)} (at {given['from']})" if where else _v(shown)


def _list(names: list[str] | None) -> str:
    return "(none)" if names is None else "[" + ", ".join(_v(n) for n in names) + "]"


# ------------------------------------------------------------------ text


def render_text(diff: Data, out: TextIO, *, colour: bool = False) -> None:
    """Write the diff for a terminal, one change per line."""
    def paint(mark: str, text: str) -> str:
        return f"{_COLOURS[mark]}{text}{_RESET}" if colour else text

    out.write(inert(f"launchverify diff: {_side(diff['base'])} -> {_side(diff['head'])}")
              + "\n")
    for launch in diff["launches"]:
        title = launch["file"]
        if launch["status"] != "changed":
            title += f" ({launch['status']})"
        elif launch["base_file"] not in (None, launch["file"]):
            title += f" (was {launch['base_file']})"
        out.write("\n" + inert(title) + "\n")
        for mark, sentence, file, line in changes(launch):
            place = f"  {file}:{line}" if file and line else ""
            out.write("  " + paint(mark, inert(f"{mark} {sentence}")) + inert(place) + "\n")
    if diff["inputs_only"]:
        out.write("\n" + paint("?", inert(_unseen(diff["inputs_only"]))) + "\n")
    findings = diff["findings"]
    if _any_finding(findings):
        out.write("\nfindings: " + _counted(findings) + "\n")
        for mark, group in (("+", findings["introduced"]), ("-", findings["fixed"]),
                            ("~", findings.get("changed", []))):
            for finding in group:
                text = f"{mark} {finding['severity']} {finding['code']} {finding['file']}:" \
                       f"{finding['line']} {finding['message']}{_was(finding)}"
                out.write("  " + paint("!" if mark == "+" and finding["severity"] == "error"
                                       else mark, inert(text)) + "\n")
    for assignment in diff.get("assignments", []):
        out.write("\n" + inert(f"under {_given_values(assignment)}, besides:") + "\n")
        if not assignment["launches"]:
            out.write("  nothing more\n")
        for launch in assignment["launches"]:
            out.write("  " + inert(launch["file"]) + "\n")
            for change in launch["changes"]:
                place = f"  {change['file']}:{change['line']}" if change["file"] and \
                    change["line"] else ""
                out.write("    " + paint(change["mark"], inert(f"{change['mark']} "
                                                           f"{change['change']}"))
                          + inert(place) + "\n")
    summary = diff["summary"]
    out.write(f"\n{summary['launches_changed']} launch file(s) changed, "
              f"{diff['unchanged']} unchanged ({diff['seconds']['total']:.1f} s)\n")


def _unseen(launches: list[Data]) -> str:
    files = sorted({name for launch in launches for name in launch["inputs_changed"]})
    return (f"{len(launches)} launch file(s) read changed files ({', '.join(files)}) with "
            "no change seen in what they start: "
            + ", ".join(launch["file"] for launch in launches))


def _side(side: Data) -> str:
    commit = side.get("commit")
    return f"{side['label']} ({commit[:10]})" if commit and commit != side["label"] \
        else side["label"]


def _counted(findings: Data) -> str:
    errors = sum(f["severity"] == "error" for f in findings["introduced"])
    changed = len(findings.get("changed", []))
    return (f"{len(findings['introduced'])} introduced"
            + (f" ({errors} error{'s' if errors != 1 else ''})" if errors else "")
            + f", {len(findings['fixed'])} fixed"
            + (f", {changed} changed" if changed else ""))


def _any_finding(findings: Data) -> bool:
    return bool(findings["introduced"] or findings["fixed"] or findings.get("changed"))


def _was(finding: Data) -> str:
    """Return what a changed finding said on the base side (and where, if elsewhere)."""
    before = finding.get("base")
    if before is None:
        return ""
    moved = (before["file"], before["line"]) != (finding["file"], finding["line"])
    return f" (was: {before['message']}" + (
        f" at {before['file']}:{before['line']})" if moved else ")")


# ------------------------------------------------------------------ Markdown


def code(text: object, *, table: bool = False) -> str:
    """Return a value as a Markdown code span it cannot leave (``table``: in a cell)."""
    shown = inert(_v(text))
    if table:
        shown = shown.replace("|", "\\|")
    longest = max((len(run) for run in re.findall(r"`+", shown)), default=0)
    fence = "`" * (longest + 1)
    pad = " " if shown.startswith("`") or shown.endswith("`") or longest else ""
    return f"{fence}{pad}{shown}{pad}{fence}"


MAX_COMMENT = 60_000  # characters: GitHub refuses a comment over 65,536


def render_markdown(diff: Data, out: TextIO, *, max_items: int = 50) -> None:
    """Write the diff for a pull-request comment: a summary table, details folded.

    Sized for a comment: with fewer items shown (each list says how many more) until it
    fits in ``MAX_COMMENT`` characters, and cut at a line as a last resort.
    """
    while True:
        written = io.StringIO()
        _markdown(diff, written, max_items)
        text = written.getvalue()
        if len(text) <= MAX_COMMENT or max_items == 1:
            break
        max_items = max(1, max_items // 2)
    if len(text) > MAX_COMMENT:
        text = text[:text.rfind("\n", 0, MAX_COMMENT - 200) + 1] + \
            "\n…cut here: the whole diff is in `--format json`.\n"
    out.write(text)


def _markdown(diff: Data, out: TextIO, max_items: int) -> None:
    summary = diff["summary"]
    out.write(f"### launchverify diff: {code(_side(diff['base']))} → "
              f"{code(_side(diff['head']))}\n\n")
    if not diff["launches"] and not _any_finding(diff["findings"]):
        out.write(f"No change in what the {diff['unchanged'] + len(diff['inputs_only'])} "
                  "launch file(s) start, as far as launchverify sees.\n")
        if diff["inputs_only"]:
            out.write(f"\n{_MARKS['?']} {code(_unseen(diff['inputs_only']))}\n")
        return
    if diff["launches"]:
        out.write("| launch file | nodes | parameters | remappings | arguments | other |\n"
                  "|---|---|---|---|---|---|\n")
        for launch in diff["launches"][:max_items]:
            nodes = launch["nodes"]
            node_counts = " ".join(part for part in (
                f"+{len(nodes['added'])}" if nodes["added"] else "",
                f"\N{MINUS SIGN}{len(nodes['removed'])}" if nodes["removed"] else "",
                f"~{len(nodes['renamed'])}" if nodes["renamed"] else "") if part)
            arguments = sum(len(launch["arguments"][k]) for k in ("added", "removed",
                                                                  "changed"))
            other = ", ".join(f"{count} {word}" for word, count in (
                ("includes", len(launch["includes"])),
                ("graph", len(launch["graph"])),
                ("conditional", len(launch["conditional"])),
                ("parameter files", len(launch["parameter_files"])),
                ("executables", len(launch["executables"])),
                ("lifecycle", len(launch["lifecycle"]))) if count)

            name = code(launch["file"], table=True) + (f" ({launch['status']})"
                                           if launch["status"] != "changed" else "")
            out.write(f"| {name} | {node_counts} | {len(launch['parameters']) or ''} | "
                      f"{len(launch['remappings']) or ''} | {arguments or ''} | {other} |\n")
        if len(diff["launches"]) > max_items:
            out.write(f"\n…and {len(diff['launches']) - max_items} more launch files.\n")
        out.write(f"\n{summary['launches_changed']} launch file(s) changed, "
                  f"{diff['unchanged']} unchanged.\n")
    if diff["inputs_only"]:
        out.write(f"\n{_MARKS['?']} {code(_unseen(diff['inputs_only']))}\n")
    findings = diff["findings"]
    if _any_finding(findings):
        out.write(f"\n**Findings**: {_counted(findings)}\n")
        shown = 0
        for mark, group in ((_MARKS["+"], findings["introduced"]),
                            (_MARKS["-"], findings["fixed"]),
                            (_MARKS["~"], findings.get("changed", []))):
            for finding in group:
                if shown == max_items:
                    break
                shown += 1
                alarm = group is findings["introduced"] and finding["severity"] == "error"
                was = f" (was {code(finding['base']['message'])})" if "base" in finding \
                    else ""
                out.write(f"- {_MARKS['!'] if alarm else mark} {finding['severity']} "
                          f"{code(finding['code'])} "
                          f"{code(finding['file'] + ':' + str(finding['line']))} "
                          f"{code(finding['message'])}{was}\n")
        total = len(findings["introduced"]) + len(findings["fixed"]) + \
            len(findings.get("changed", []))
        if total > shown:
            out.write(f"- …and {total - shown} more\n")
    for launch in diff["launches"][:max_items]:
        found = list(changes(launch))
        out.write(f"\n<details><summary><code>{html.escape(inert(_v(launch['file'])))}"
                  f"</code>: {len(found)} change"
                  f"{'s' if len(found) != 1 else ''}</summary>\n\n")
        for mark, sentence, file, line in found[:max_items]:
            place = f" at {code(f'{file}:{line}')}" if file and line else ""
            out.write(f"- {_MARKS[mark]} {code(sentence)}{place}\n")
        if len(found) > max_items:
            out.write(f"- …and {len(found) - max_items} more\n")
        out.write("\n</details>\n")
    for assignment in diff.get("assignments", []):
        more = [(launch["file"], change) for launch in assignment["launches"]
                for change in launch["changes"]]
        out.write(f"\n<details><summary>under <code>"
                  f"{html.escape(inert(_v(_given_values(assignment))))}</code>: "
                  f"{len(more)} more change{'s' if len(more) != 1 else ''}</summary>\n\n")
        for file, change in more[:max_items]:
            place = f" at {code(change['file'] + ':' + str(change['line']))}" \
                if change["file"] and change["line"] else f" in {code(file)}"
            out.write(f"- {_MARKS[change['mark']]} {code(change['change'])}{place}\n")
        if len(more) > max_items:
            out.write(f"- …and {len(more) - max_items} more\n")
        out.write("\n</details>\n")


def _given_values(assignment: Data) -> str:
    return _assigned(assignment["arguments"])


def _assigned(values: dict[str, str]) -> str:
    """Return argument values as given on a command line: ``a:=1 b:=2``."""
    return " ".join(f"{k}:={v}" for k, v in sorted(values.items()))


# ------------------------------------------------------------------ GitHub annotations


def render_github(diff: Data, out: TextIO) -> None:
    """Write a workflow command per change on a line of the head side, per new finding."""
    for launch in diff["launches"]:
        for mark, sentence, file, line in changes(launch):
            if file is None or line is None or mark == "-":
                continue  # (what is gone has no line on the head side)
            out.write(f"::notice file={escape_property(file)},line={line},"
                      f"title={escape_property('launchverify diff')}::"
                      f"{escape_data(sentence)}\n")
    for finding in diff["findings"]["introduced"]:
        command = {"error": "error", "warning": "warning"}.get(finding["severity"], "notice")
        out.write(f"::{command} file={escape_property(finding['file'])},"
                  f"line={finding['line']},title={escape_property(finding['code'])}::"
                  f"{escape_data('new: ' + finding['message'])}\n")
