"""Python launch files are code: they run only in confined worker processes.

launchverify never runs a launch file's code in its own process. ``pool.IsolatedPython``
sends each Python launch file to a fresh worker forked from a ``zygote``; the worker
confines itself (``confine``: seccomp, Landlock, resource limits), arms the audit hook,
evaluates the file and sends its IR back as plain data (``channel``, ``codec``), which
launchverify validates before the evaluator sees it. The threat model is in
docs/design.md.
"""
