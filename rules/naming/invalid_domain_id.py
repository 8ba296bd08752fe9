"""LV104 invalid-domain-id."""

from __future__ import annotations

import dataclasses
from collections.abc import Iterator

from launchverify.dds.discovery import DOMAIN
from launchverify.graph import LaunchGraph
from launchverify.rule import Finding, Rule, RuleContext, Severity

HIGHEST = 232  # the last domain whose ports fit the default port mapping (RTPS, 120 peers)
EPHEMERAL = range(102, 215)  # domains whose ports fall in Linux's ephemeral range


class InvalidDomainId(Rule):
    """A `ROS_DOMAIN_ID` the middleware refuses, or one whose ports Linux may take.

    ## What it does
    Reads every `ROS_DOMAIN_ID` the launch sets (`SetEnvironmentVariable`, `<set_env>`, a
    node's `additional_env` or `<env>`) with the value it has under the arguments as
    given. A value that is not a whole number, or above 232, is an error: rcl refuses
    the first (`ROS_DOMAIN_ID is not an integral number`) and the default port mapping
    (7400 + 250 * domain + offsets, 120 participants) runs out of valid ports past 232.
    102 to 214 is a warning: on Linux those domains' ports fall in the ephemeral range
    (32768-60999) that the operating system hands to other programs, so a node may fail
    to bind its port at random.

    ## Why it matters
    Every node of that process fails to start (not a number), refuses to create its
    participant (out of range), or works until another program happens to hold its port.

    ## Example
    ```xml
    <set_env name="ROS_DOMAIN_ID" value="250"/>
    ```

    ## Fix
    Use 0 to 101 (or 215 to 232 on Linux) for robot and fleet domains.
    """

    code = "LV104"
    slug = "invalid-domain-id"
    severity = Severity.ERROR
    message = "ROS_DOMAIN_ID {value!r} {why}"

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        for setting in graph.environment_sets:
            if setting.name != DOMAIN or setting.value is None or \
                    graph.runs(setting.origin) is False:
                continue
            value = graph.base(setting.value)
            if value is None or not value.strip():
                continue  # not known before launch, or empty (domain 0)
            why, severity = judge(value.strip())
            if why is None:
                continue
            finding = self.finding(setting.origin, value=value, why=why)
            yield finding if severity is Severity.ERROR else dataclasses.replace(
                finding, severity=severity)


def judge(value: str) -> tuple[str | None, Severity]:
    """Return what is wrong with a domain id, and how bad it is.

    Examples:
        >>> judge("7")[0] is None, judge("robot")[1].value, judge("233")[1].value
        (True, 'error', 'error')
        >>> judge("150")[1].value
        'warning'
    """
    if not value.isdigit():
        return ("is not a whole number: rcl refuses it and no node of the process "
                "starts"), Severity.ERROR
    number = int(value)
    if number > HIGHEST:
        return (f"is above {HIGHEST}: its ports are out of range for the default port "
                "mapping, and the middleware refuses the domain"), Severity.ERROR
    if number in EPHEMERAL:
        return ("is in 102-214: on Linux its ports overlap the ephemeral range, and "
                "another program may take them"), Severity.WARNING
    return None, Severity.ERROR
