"""An error reported with a module absent is reported with any valid stand-in present.

With ``vendor`` absent its values are unknown; an error may rest only on facts, so it must
still be there once a stand-in module gives those values valid concrete contents
(``tests/unknown_launch_files.py`` draws both). The examples below are the false errors
issue 43 named (each was reported with the module absent and not with it present).
"""

from __future__ import annotations

from pathlib import Path

from hypothesis import HealthCheck, example, given, settings
from unknown_launch_files import HEADER, Drawn, launch_files

from launchverify.engine import CheckOptions, run_check
from launchverify.rule import Severity

PACKAGE_XML = """<?xml version="1.0"?>
<package format="3"><name>meta_pkg</name><version>0.0.0</version>
<description>d</description><maintainer email="a@b.c">a</maintainer><license>MIT</license>
<exec_depend>demo_nodes_cpp</exec_depend></package>
"""


def _errors(root: Path, drawn: Drawn, *, stand_in: bool) -> set[tuple[str, str, int]]:
    launch = root / "launch"
    launch.mkdir(parents=True, exist_ok=True)
    (root / "package.xml").write_text(PACKAGE_XML)
    (launch / "empty.launch.py").write_text(
        "from launch import LaunchDescription\n\n\n"
        "def generate_launch_description():\n    return LaunchDescription([])\n")
    (launch / "x.launch.py").write_text(drawn.launch_file)
    module = launch / "vendor.py"
    if stand_in:
        module.write_text(drawn.stand_in)
    else:
        module.unlink(missing_ok=True)
    report = run_check(CheckOptions(paths=[launch / "x.launch.py"], workspace=root))
    return {(f.code, f.span.file.name, f.span.line) for f in report.findings
            if f.severity is Severity.ERROR}


def _case(body: str, stand_in: str) -> Drawn:
    return Drawn(HEADER + body + "    return LaunchDescription(out)\n", stand_in)


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                 HealthCheck.function_scoped_fixture])
@given(drawn=launch_files())
@example(drawn=_case("    out.append(DeclareLaunchArgument('model', choices=vendor.v0, "
                     "default_value='a'))\n", "v0 = ['a', 'b']\n"))
@example(drawn=_case("    m = vendor.v0\n    m.append('')\n    out.append(DeclareLaunchArgument("
                     "'model', choices=m, default_value=''))\n", "v0 = ['a']\n"))
@example(drawn=_case("    out.append(DeclareLaunchArgument('model', choices=[m for m in "
                     "vendor.v0], default_value='a'))\n", "v0 = ['a']\n"))
@example(drawn=_case("    out.append(Node(package=vendor.v0 + '_cpp', executable='talker'))\n"
                     "    out.append(LogInfo(msg=FindPackageShare(vendor.v0 + '_cpp')))\n",
                     "v0 = 'demo_nodes'\n"))
@example(drawn=_case("    out.append(Node(package='demo_nodes_cpp', executable='talker', "
                     "condition=IfCondition(PythonExpression([vendor.v0, ' == 1']))))\n",
                     "v0 = '1'\n"))
def test_an_error_with_the_module_absent_stays_with_it_present(
        tmp_path: Path, drawn: Drawn) -> None:
    root = tmp_path / "meta_pkg"
    absent = _errors(root, drawn, stand_in=False)
    present = _errors(root, drawn, stand_in=True)
    assert absent <= present, (f"errors only while vendor is absent: {absent - present}\n"
                               f"{drawn.launch_file}\n# vendor.py\n{drawn.stand_in}")
