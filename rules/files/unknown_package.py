"""LV303 unknown-package."""

from __future__ import annotations

import dataclasses
from collections.abc import Iterator

from rapidfuzz.distance import Levenshtein

from launchverify.graph import LaunchGraph, PackageRef
from launchverify.models.known_packages import is_released, released_packages
from launchverify.rule import Finding, Rule, RuleContext, Severity, rename
from launchverify.suggest import closest_package, typos


class UnknownPackage(Rule):
    """A package named in the launch exists nowhere.

    ## What it does
    Looks up every package a launch file names (`pkg=`, `package=`, `$(find-pkg-share)`,
    `FindPackageShare`, `get_package_share_directory`, `$(find-pkg-prefix)`,
    `$(exec-in-pkg)`) in the workspace and, when ROS 2 is installed, in
    `AMENT_PREFIX_PATH`, including packages used only under a condition false by default.
    With an installation, a package found nowhere is an error.

    Without one, a package missing from the workspace may still be installed where the
    launch runs, so it is weighed against the packages ROS 2 distributions release:

    - a released package (`nav2_bringup`, `rviz2`) is a dependency to install: quiet;
    - a package that the launch file's own package declares in its `package.xml`
      (`<exec_depend>`...) comes from elsewhere (a `.repos` file, another overlay):
      quiet;
    - an unreleased package within one or two edits of a workspace package, or one edit
      of a released package, is a typo: an error (not one that differs only in its
      numbers, `example_1` beside `example_10`: a sibling that is not here; nor one that
      differs from a released package in its first word only, a vendor's prefix:
      neobotix's `neo_gz_worlds` beside LeoRover's `leo_gz_worlds`); two edits
      from a released package only is a warning (a package built from source outside
      the workspace may have that name: `kobuki_node` beside the released `kobuki_core`);
    - another unreleased package whose name is close to a workspace package's (shares
      most words, whole or shortened) is a warning: nothing declares it, and a renamed or
      mistyped package is likely;
    - any other is an info: nothing declares it, but its name is like nothing here, so
      it is most likely an outside dependency (an optional demo's driver, a vendor's
      package) that `package.xml` should declare. Loose launch files, outside any
      package, are not judged.

    A warning or info is given once per file and package (its first use), errors at every
    use.
    The message names the package most likely meant: a typo's target, else the one
    workspace package whose name shares the most words, whole or shortened
    (`acme_simulation` for `acme_sim`, `acme_navigation2_bringup` for `acme_nav2_bringup`).
    It names none when no package is that close, or when two are equally close.

    ## Why it matters
    ros2 launch stops with `PackageNotFoundError` when it reaches the reference.

    ## Example
    ```xml
    <node pkg="demo_node_cpp" exec="talker"/>  <!-- error: did you mean demo_nodes_cpp? -->
    <!-- warning when the workspace has acme_simulation and no acme_sim; an info for
         vendor_lidar_driver, like nothing in the workspace -->
    <include file="$(find-pkg-share acme_sim)/launch/world.launch.xml"/>
    ```

    ## Fix
    Correct the package name, or add the package to the workspace. A package installed
    apart from the workspace is found through `AMENT_PREFIX_PATH` or `package-paths`.

    Autofix: renames the package to the one the message names, where the name is written
    as plain text; safe for a typo with exactly one candidate, unsafe for a typo with
    several or for a package that is only named alike.
    """

    code = "LV303"
    slug = "unknown-package"
    severity = Severity.ERROR
    message = "package {name!r} is {where}{hint}"
    outside = " (an outside dependency? package.xml does not declare it)"

    def __init__(self) -> None:
        # one check's suggestions: every graph asks again, and installed packages are many
        self._typos: dict[str, tuple[str | None, bool]] = {}
        self._closest: dict[str, str | None] = {}

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        installed = ctx.packages is not None and ctx.packages.has_install
        local = frozenset(ctx.packages.names() if ctx.packages is not None else ())
        seen: set[object] = set()
        warned: set[tuple[str, object]] = set()  # a missing dependency: once per file
        for ref in graph.packages:
            key = (ref.name, ref.origin.span)
            if ref.found or key in seen:
                continue
            seen.add(key)
            finding = self._judge(ref, local, installed, ctx)
            if finding is None:
                continue
            if finding.severity is not Severity.ERROR:
                if (ref.name, ref.origin.span.file) in warned:
                    continue
                warned.add((ref.name, ref.origin.span.file))
            yield finding

    def _judge(self, ref: PackageRef, local: frozenset[str], installed: bool,
               ctx: RuleContext) -> Finding | None:
        """Report a package found nowhere: an error when surely wrong, else a warning."""
        if not installed and is_released(ref.name):
            return None  # a dependency to install, not a mistake
        typo, unique = self._typo(ref.name, local)
        if not installed and typo is None and not local:
            return None  # loose launch files: no workspace to miss it from
        if (not installed and ctx.packages is not None
                and ctx.packages.declares(ref.origin.span.file, ref.name)):
            return None  # a declared dependency from elsewhere (.repos): not here yet
        # two edits from a released package only: a package built from source outside the
        # workspace may well have that name (kobuki_node beside the released kobuki_core)
        sure = typo is not None and (typo in local or _one_edit(ref.name, typo))
        hint = typo or self._closest_package(ref.name, local)
        where = ("neither in the workspace nor installed" if installed
                 else "not in the workspace and not a released ROS 2 package")
        fix = None if hint is None else rename(ref.written, ref.name, hint,
                                               unique=sure and unique)
        finding = self.finding(ref.origin, name=ref.name, where=where,
                               hint=f" (did you mean {hint!r}?)" if hint else "", fix=fix)
        if installed or sure:
            return finding
        if hint is None:
            return dataclasses.replace(finding, severity=Severity.INFO,
                                       message=finding.message + self.outside)
        return dataclasses.replace(finding, severity=Severity.WARNING)

    def _typo(self, name: str, local: frozenset[str]) -> tuple[str | None, bool]:
        """Return the package ``name`` misspells, if any, and whether it is the only one."""
        if name not in self._typos:
            # a released name that differs in its first word only is another vendor's
            # package: neobotix's neo_gz_worlds beside LeoRover's leo_gz_worlds
            close = typos(name, local) or [c for c in typos(name, released_packages())
                                           if not _vendor_twin(name, c)]
            # numbered siblings (example_1 beside example_10, ur5 beside ur10) are other
            # packages, not misspellings
            close = [c for c in close if _digitless(c) != _digitless(name)]
            self._typos[name] = (close[0] if close else None, len(close) == 1)
        return self._typos[name]

    def _closest_package(self, name: str, local: frozenset[str]) -> str | None:
        """Return the workspace package most likely meant (asked only when reported)."""
        if name not in self._closest:
            self._closest[name] = closest_package(name, local)
        return self._closest[name]


def _one_edit(name: str, other: str) -> bool:
    """Return whether two names are one insertion, deletion or substitution apart."""
    return Levenshtein.distance(name, other, score_cutoff=1) <= 1


def _vendor_twin(name: str, other: str) -> bool:
    """Return whether two names differ in their first word (a vendor's prefix) only.

    (Numbers aside: ``neo_teleop2`` beside ``leo_teleop``.)
    """
    first, _, rest = name.partition("_")
    other_first, _, other_rest = other.partition("_")
    return bool(rest) and first != other_first and _digitless(rest) == _digitless(other_rest)


def _digitless(name: str) -> str:
    return "".join(c for c in name if not c.isdigit())
