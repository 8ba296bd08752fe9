"""Python launch files are code: they run only in confined worker processes.

launchverify never runs a launch file's code in its own process. ``pool.IsolatedPython``
sends each Python launch file to a worker forked from a ``zygote`` (which may take
further files of the same repository: ``reuse``); the worker
confines itself (``confine``: seccomp, Landlock, resource limits), arms the audit hook,
evaluates the file and sends its IR back as plain data (``channel``, ``codec``), which
launchverify validates before the evaluator sees it. The threat model is in
docs/design.md.
"""
