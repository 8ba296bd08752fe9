"""launchverify: a formal verifier and static analyser for ROS 2 launch files."""

__version__ = "0.1.0"
