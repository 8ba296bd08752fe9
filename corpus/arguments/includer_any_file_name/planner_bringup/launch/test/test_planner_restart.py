"""A pytest module that builds launch descriptions inside its tests: not a launch file.

Its ``generate_launch_description`` functions are nested in test functions, so ros2 launch
could not run this file; discovery must not pick it up (no LV001 here).
"""

import launch
import launch.actions


def test_restart_twice():
    def generate_launch_description():
        return launch.LaunchDescription([launch.actions.LogInfo(msg='restart')])

    service = launch.LaunchService()
    service.include_launch_description(generate_launch_description())
    assert service.run() == 0
