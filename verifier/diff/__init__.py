"""``launchverify diff``: what a change does to the launched system, for its reviewer.

Both sides are evaluated from their own trees (``sides``), each into a snapshot of what
its launch files start (``snapshot``); the snapshots are compared launch by launch
(``compare``) and the differences written for people, programs and pull requests
(``render``). ``command`` ties them to the command line.
"""
