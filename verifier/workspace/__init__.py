"""The workspace being checked: its files, its packages and what they install.

Discovery of launch files, the package index (sources, install spaces, ament prefixes),
what a package's build files install and its sources name, and how paths and source
lines are read and shown.
"""
