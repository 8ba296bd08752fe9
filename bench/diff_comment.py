"""Picture the pull-request comment `launchverify diff --format markdown` writes.

Builds a small repository with one commit and a change of each kind a reviewer asks
about (a parameter changed in a parameter file the change does not touch otherwise, a
node renamed, a remapping removed, an argument's default changed, a node that starts
only under an argument, a new error), runs `launchverify diff --format markdown` on it,
renders the Markdown as a pull-request comment would show it (CommonMark with tables and
HTML, through markdown-it, which rich brings along; GitHub's own renderer may differ in
details) and takes a screenshot with headless Chromium:

    python bench/diff_comment.py --out docs/diff-comment.png

Standard library, markdown-it and a `chromium` on PATH.
"""

from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

PACKAGE = ("<package format='3'><name>demo_bringup</name><version>0.1.0</version>"
           "<description>demo</description><maintainer email='a@b.c'>a</maintainer>"
           "<license>MIT</license></package>\n")
PARAMS = """\
controller:
  ros__parameters:
    max_velocity: 0.5
    frame: base_link
"""
BRINGUP = """\
<launch>
  <arg name="use_sim" default="false"/>
  <arg name="rate" default="10"/>
  <node pkg="demo_nodes_cpp" exec="talker" name="controller">
    <param from="$(find-pkg-share demo_bringup)/config/controller.yaml"/>
    <param name="rate" value="$(var rate)"/>
    <remap from="chatter" to="/cmd_vel"/>
  </node>
  <node pkg="demo_nodes_cpp" exec="listener" name="base_driver">
    <remap from="chatter" to="/cmd_vel"/>
  </node>
  <node pkg="demo_nodes_cpp" exec="talker" name="odometry"/>
</launch>
"""
CHANGED = {
    "config/controller.yaml": ("max_velocity: 0.5", "max_velocity: 1.5"),
    "launch/bringup.launch.xml": None,
}
STYLE = """
body { font: 14px/1.5 -apple-system, 'Segoe UI', 'Noto Sans', Helvetica, Arial, sans-serif;
       color: #1f2328; background: #fff; margin: 0; padding: 16px; }
.comment { border: 1px solid #d0d7de; border-radius: 6px; max-width: 860px; }
.head { background: #f6f8fa; border-bottom: 1px solid #d0d7de; padding: 8px 16px;
        border-radius: 6px 6px 0 0; color: #59636e; }
.head b { color: #1f2328; }
.body { padding: 4px 16px 8px; }
h3 { font-size: 1.25em; margin: 16px 0 8px; }
code { font: 12px ui-monospace, SFMono-Regular, Menlo, monospace; background: #eff1f3;
       padding: .2em .4em; border-radius: 6px; }
table { border-collapse: collapse; margin: 8px 0; }
th, td { border: 1px solid #d0d7de; padding: 6px 13px; }
tr:nth-child(2n) td { background: #f6f8fa; }
details { margin: 8px 0; } summary { cursor: pointer; }
ul { padding-left: 2em; margin: 4px 0; }
"""


def build(root: Path) -> None:
    """Write the repository: a base commit, then the change in the working tree."""
    def git(*arguments: str) -> None:
        subprocess.run(["git", "-C", str(root), *arguments], check=True, capture_output=True,
                       env={**os.environ, "GIT_AUTHOR_NAME": "a", "GIT_AUTHOR_EMAIL": "a@b",
                            "GIT_COMMITTER_NAME": "a", "GIT_COMMITTER_EMAIL": "a@b"})

    package = root / "demo_bringup"
    (package / "launch").mkdir(parents=True)
    (package / "config").mkdir()
    (package / "package.xml").write_text(PACKAGE)
    (package / "config" / "controller.yaml").write_text(PARAMS)
    (package / "launch" / "bringup.launch.xml").write_text(BRINGUP)
    git("init", "-q", "-b", "main")
    git("add", "-A")
    git("commit", "-q", "-m", "base")
    (package / "config" / "controller.yaml").write_text(
        PARAMS.replace("max_velocity: 0.5", "max_velocity: 1.5"))
    changed = (BRINGUP
               .replace('name="base_driver">\n    <remap from="chatter" to="/cmd_vel"/>',
                        'name="base_driver">')
               .replace('name="odometry"/>', 'name="odometry_filtered"/>\n'
                        '  <node pkg="demo_nodes_cpp" exec="listener" name="sim_bridge" '
                        'if="$(var use_sim)"/>\n'
                        '  <node pkg="demo_nodes_cpp" exec="talker" name="controller"/>')
               .replace('name="rate" default="10"', 'name="rate" default="20"'))
    (package / "launch" / "bringup.launch.xml").write_text(changed)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", type=Path, default=Path("docs/diff-comment.png"))
    parser.add_argument("--markdown", type=Path, help="also keep the Markdown here")
    args = parser.parse_args()
    from markdown_it import MarkdownIt

    folder = Path(tempfile.mkdtemp(prefix="lv-diff-comment-"))
    try:
        repository = folder / "repo"
        repository.mkdir()
        build(repository)
        launchverify = Path(sys.executable).with_name("launchverify")
        done = subprocess.run([str(launchverify), "diff", "--format", "markdown"],
                              cwd=repository, capture_output=True, text=True, check=False)
        if done.returncode not in (0, 1):
            raise SystemExit(done.stderr)
        markdown = done.stdout
        if args.markdown:
            args.markdown.write_text(markdown)
        body = MarkdownIt("commonmark", {"html": True}).enable("table").render(markdown)
        page = folder / "comment.html"
        page.write_text(f"<!doctype html><meta charset='utf-8'><style>{STYLE}</style>"
                        "<div class='comment'><div class='head'><b>github-actions</b> "
                        f"commented</div><div class='body'>{body}</div></div>")
        # the first <details> open, as a reviewer would click it
        page.write_text(page.read_text().replace("<details>", "<details open>", 1))
        subprocess.run(["chromium", "--headless", "--no-sandbox", "--disable-gpu",
                        "--hide-scrollbars", f"--screenshot={args.out.resolve()}",
                        "--window-size=900,570", page.as_uri()], check=True,
                       capture_output=True)
        print(f"wrote {args.out}")
        return 0
    finally:
        shutil.rmtree(folder, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
