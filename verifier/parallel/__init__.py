"""Work shared with forked processes.

The rules of a large check (``fanout``), and a computation that runs beside the check
(``forked``: the includers scan). Python launch files run in confined workers of their
own (``launchverify.isolation``).
"""
