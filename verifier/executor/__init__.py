"""``launchverify run``: start a verified launch with ros2 launch's run-time semantics.

``plan.py`` turns an evaluated graph into what to start (commands built as launch_ros
builds them, in ``command.py``), ``supervisor.py`` runs it: processes in their own
process groups, event handlers, timers, respawn, output, and ros2 launch's shutdown
(SIGINT, then SIGTERM after ``sigterm_timeout``, then SIGKILL after ``sigkill_timeout``).
"""
