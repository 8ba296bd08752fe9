"""Check that a Python launch file and its XML twin give launchverify the same graph.

Generates the benchmark tree twice from one seed: as ``generate.py`` writes it (about a
third of the files in Python), and with every Python file written as XML instead (the
element trees are the same: rendering Python draws no random numbers). Then runs
``launchverify graph --format json`` on every file of both trees and compares the nodes
(names, namespaces, parameters as the node receives them, remappings). Source lines,
condition text and the tree's folder are left out: they differ by construction.

    python bench/twins.py [--files 200] [--seed 1]

It prints the files whose nodes differ and exits 1 if any do. Each file costs one
``launchverify graph`` process per twin (~0.3 s a file in all).
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
from pathlib import Path

import generate

LAUNCHVERIFY = Path(sys.executable).with_name("launchverify")


def nodes_of(path: Path, root: Path) -> list[str]:
    """Return the nodes of one launch file (default arguments) as comparable text."""
    result = subprocess.run([str(LAUNCHVERIFY), "graph", str(path), "--format", "json"],
                            capture_output=True, text=True, check=False)
    document = json.loads(result.stdout)
    out = []
    for node in document["nodes"]:
        for key in ("file", "line", "condition"):
            node.pop(key, None)
        for parameter in node["parameters"]:
            if "file" in parameter:
                parameter["file"] = str(Path(parameter["file"]).relative_to(root))
        out.append(json.dumps(node, sort_keys=True))
    return sorted(out)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--files", type=int, default=200)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args(argv)
    with tempfile.TemporaryDirectory() as scratch:
        as_written, as_xml = Path(scratch, "mixed"), Path(scratch, "xml")
        mixed = generate.generate(as_written, args.files, args.seed)
        written_names = [lf.filename for lf in mixed.files]  # before the patch below
        generate.render_python = lambda root, comment: generate.render_xml(root, False, comment)
        generate.LaunchFile.filename = property(  # type: ignore[assignment]
            lambda lf: f"{lf.stem}.launch.{'xml' if lf.fmt == 'py' else lf.fmt}")
        xml = generate.generate(as_xml, args.files, args.seed)
        differ = 0
        for left, right, name in zip(mixed.files, xml.files, written_names, strict=True):
            folder = Path("src", left.package.name, "launch")
            ours = nodes_of(as_written / folder / name, as_written)
            theirs = nodes_of(as_xml / folder / right.filename, as_xml)
            if ours != theirs:
                differ += 1
                print(f"{folder / name}: nodes differ")
                for line in sorted(set(ours) ^ set(theirs))[:4]:
                    print(f"  {'python' if line in ours else 'xml   '} {line[:300]}")
    python = sum(lf.fmt == "py" for lf in mixed.files)
    print(f"{len(mixed.files)} files ({python} Python): {differ} with different nodes")
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
