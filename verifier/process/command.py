"""The ``launchverify`` command as a process of its own (also ``python -m launchverify``).

A process that ends when its command does can skip what a library must keep doing: the
cycle collector is paused from the first import (what a check builds lives until the
end; the collector walking it again and again was a third of a large check, and a tenth
of a one-file check went to collections during the imports), and the process leaves
without freeing its objects (freeing a large check's objects one by one took 0.4 s of a
3 s check of the fleet bench). ``cli.main`` turns the collector back on for the commands
that run long (``LONG_RUNNING``). The methods ``dataclasses`` generates are compiled once
and kept between runs (``code_cache``).
"""

import gc
import os
import sys
import threading

LONG_RUNNING = frozenset({"lsp", "run"})  # commands that serve or supervise until stopped


def run() -> None:
    """Run the command line, then exit at once (its output flushed)."""
    command = next((arg for arg in sys.argv[1:] if not arg.startswith("-")), None)
    if command not in LONG_RUNNING:
        gc.disable()
    from launchverify.process.code_cache import install

    code = install()
    from launchverify.render.encodable import escape_unencodable

    escape_unencodable(sys.stdout, sys.stderr)  # the last net: what no encoding holds is shown
    from launchverify.cli import main

    status = main()
    if code is not None:
        code.save()
    try:
        sys.stdout.flush()
        sys.stderr.flush()
    except OSError:  # a stream closed after main's end (main handles `check | head` itself)
        raise SystemExit(status) from None
    if threading.active_count() > 1 or sys.getprofile() or sys.gettrace():
        raise SystemExit(status)  # a thread left running; a profiler or coverage writes at exit
    os._exit(status)
