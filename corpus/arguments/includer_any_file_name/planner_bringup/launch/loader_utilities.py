"""Helpers shared by the planner's launch files: not a launch file itself.

A launch file is a module with a top-level ``generate_launch_description()``, such as::

    def generate_launch_description():
        return LaunchDescription([])

This module only mentions it in text, so discovery must leave it alone (no LV001 here).
"""

from .planner_names import PLANNER_NAMESPACE  # a relative import: fails outside the package


def planner_topic(name: str) -> str:
    return f'/{PLANNER_NAMESPACE}/{name}'
