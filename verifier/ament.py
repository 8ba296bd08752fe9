"""launchverify as an ament linter: called from a package's tests, run by ``colcon test``.

ament's linters expose ``main_with_errors(argv)`` for a package's ``test/`` to call and
turn into a pytest result; this is the same for launch files:

    from launchverify.ament import main_with_errors

    @pytest.mark.launchverify
    @pytest.mark.linter
    def test_launchverify():
        rc, errors = main_with_errors(argv=[])
        assert rc == 0, ', '.join(errors)

``argv`` takes what ``launchverify check`` takes; without paths it checks the package the
test runs in (the nearest folder with a package.xml). ``--xunit-file FILE`` writes the
JUnit XML ``colcon test-result`` reads, and files listed in
``AMENT_LINT_AUTO_FILE_EXCLUDE`` (a CMake list: ``;``-separated) are left out, as
ament_lint_auto does for its linters.
"""

from __future__ import annotations

import io
import os
from collections.abc import Sequence
from pathlib import Path

from launchverify.workspace.paths import resolved

EXCLUDE_VARIABLE = "AMENT_LINT_AUTO_FILE_EXCLUDE"


def package_root(start: Path) -> Path:
    """Return the nearest folder at or above ``start`` holding a package.xml (else start)."""
    start = resolved(start)
    for folder in (start, *start.parents):
        if (folder / "package.xml").is_file():
            return folder
    return start


def excluded_by_ament() -> list[str]:
    """Return the paths ``AMENT_LINT_AUTO_FILE_EXCLUDE`` names (empty when unset)."""
    raw = os.environ.get(EXCLUDE_VARIABLE, "")
    return [part.strip() for part in raw.replace(os.pathsep, ";").split(";") if part.strip()]


def main_with_errors(argv: Sequence[str] | None = None) -> tuple[int, list[str]]:
    """Check launch files; return the exit status and one line per finding."""
    from launchverify.cli import build_parser, check_options, fails
    from launchverify.config import ConfigError
    from launchverify.engine import UsageError, run_check
    from launchverify.findings.baseline import BaselineError
    from launchverify.process.outputs import write_file
    from launchverify.registry import RegistryError
    from launchverify.render.junit import render_junit

    tokens = list(argv or [])
    if not _has_paths(tokens):
        tokens.insert(0, str(package_root(Path.cwd())))
    try:
        args, extra = build_parser().parse_known_args(["check", *tokens])
    except SystemExit:  # argparse has printed what is wrong
        return 2, ["launchverify: error: invalid arguments"]
    args.targets = [*args.targets, *extra]
    try:
        options, config = check_options(args)
        report = run_check(options)
    except (UsageError, ConfigError, RegistryError, BaselineError) as error:
        return 2, [f"launchverify: error: {error}"]  # a test failure, never a traceback
    if args.xunit_file is not None:  # never through a link (as check's --xunit-file)
        junit = io.StringIO()
        render_junit(report, junit, checked=report.checked)
        try:
            write_file(args.xunit_file, junit.getvalue(), inside=options.paths)
        except UsageError as error:
            return 2, [f"launchverify: error: {error}"]
    errors = [
        f"{report.display_path(f.span.file)}:{f.span.line}:{f.span.column}: "
        f"{f.severity.value} {f.code} [{f.slug}] {f.message}"
        for f in report.findings
    ]
    return (0 if args.exit_zero or not fails(report, args, config) else 1), errors


def main(argv: Sequence[str] | None = None) -> int:
    """Print the findings and return the exit status (for scripts and CMake tests)."""
    status, errors = main_with_errors(argv)
    for line in errors:
        print(line)
    print(f"{len(errors)} finding{'s' if len(errors) != 1 else ''}")
    return status


def _has_paths(tokens: Sequence[str]) -> bool:
    """Return whether ``argv`` names something to check (not only options)."""
    takes_value = {"--workspace", "--select", "--ignore", "--exclude", "--env", "--config",
                   "--baseline", "--format", "-o", "--output", "--color", "--fail-on",
                   "--write-baseline", "--xunit-file"}
    skip = False
    for token in tokens:
        if skip:
            skip = False
            continue
        if token in takes_value:
            skip = True
        elif not token.startswith("-") and ":=" not in token:
            return True
    return False
