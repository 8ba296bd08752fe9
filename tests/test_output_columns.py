"""Columns count characters in every format, whatever the file's language.

Python places code by UTF-8 bytes (``ast``, code positions, tracebacks); XML and YAML
spans, code frames, fixes and editors count characters. A line with ``é`` or an emoji
before a finding once put the caret several columns to the right.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from launchverify.cli import main

LAUNCH = """\
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name='talker'),
        ['é😀', Node(package='demo_nodes_cpp', executable='talker', name='talker')][1],
        Node(package='demo_nodes_cpp', executable='talker', name='lé'),
    ])
"""
RAISES = LAUNCH.replace("    ])", "        ['ü', 1 / 0][0],\n    ])")


@pytest.fixture
def launch(tmp_path: Path) -> Path:
    path = tmp_path / "unicode.launch.py"
    path.write_text(LAUNCH, encoding="utf-8")
    return path


def _findings(launch: Path, capsys: pytest.CaptureFixture[str]) -> dict[str, dict]:
    main(["check", str(launch), "--format", "json", "--no-cache"])
    return {f["code"]: f for f in json.loads(capsys.readouterr().out)["findings"]}


def test_python_columns_count_characters(launch: Path,
                                         capsys: pytest.CaptureFixture[str]) -> None:
    found = _findings(launch, capsys)
    lines = LAUNCH.splitlines()
    duplicate = found["LV101"]
    assert lines[duplicate["line"] - 1][duplicate["column"] - 1:].startswith("Node(")
    invalid = found["LV102"]
    line = lines[invalid["line"] - 1]
    start, end = invalid["column"] - 1, invalid["end_column"] - 1
    assert line[start:end] in ("'lé'", "lé")


def test_a_traceback_column_counts_characters(tmp_path: Path,
                                              capsys: pytest.CaptureFixture[str]) -> None:
    path = tmp_path / "raises.launch.py"
    path.write_text(RAISES, encoding="utf-8")
    raised = _findings(path, capsys)["LV002"]
    line = RAISES.splitlines()[raised["line"] - 1]
    assert line[raised["column"] - 1:].startswith("1 / 0")


def test_the_caret_is_under_the_call(launch: Path,
                                     capsys: pytest.CaptureFixture[str]) -> None:
    main(["check", str(launch), "--no-cache", "--color", "never", "--select", "LV101"])
    out = capsys.readouterr().out.splitlines()
    source = next(i for i, text in enumerate(out) if "'é😀', Node(" in text)
    code, caret = out[source].split(" | ", 1)[1], out[source + 1].split(" | ", 1)[1]
    assert code[caret.index("^"):].startswith("Node(")
