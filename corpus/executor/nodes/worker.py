#!/usr/bin/env python3
"""A stand-in for a ROS node in the executor's tests: prints, waits, crashes or hangs on cue.

    worker.py NAME [--crash-after S [--crash-once]] [--exit-code C] [--finish-after S]
              [--ignore-signals] [--spawn-child] [ROS arguments...]

It prints ``ready NAME <argv>`` at once, exits 0 on SIGINT/SIGTERM (unless told to
ignore them), and with ``--spawn-child`` starts a grandchild that prints its pid, so
tests can check that whole process groups are stopped. ``--crash-once`` crashes only the
first start under one parent (a respawned worker then keeps running).
"""

import signal
import sys

# Signal handlers first, before the slower imports: a launch stopped while this worker is
# still starting (a respawn just before a shutdown, on a loaded machine) must still see a
# clean exit, not Python's KeyboardInterrupt (exit code 1).
ARGV = sys.argv[1:]
NAME = ARGV[0] if ARGV else "worker"
if "--ignore-signals" in ARGV:
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_IGN)
else:
    def bye(number, frame):
        print(f"bye {NAME} {signal.Signals(number).name}", flush=True)
        sys.exit(0)
    signal.signal(signal.SIGINT, bye)
    signal.signal(signal.SIGTERM, bye)

import os  # noqa: E402
import subprocess  # noqa: E402
import tempfile  # noqa: E402
import time  # noqa: E402


def main() -> None:
    argv, name = ARGV, NAME

    def option(flag, default=None):
        return argv[argv.index(flag) + 1] if flag in argv else default

    crash_after = option("--crash-after")
    if crash_after is not None and "--crash-once" in argv:
        marker = os.path.join(tempfile.gettempdir(), f"worker-{os.getppid()}-{name}.crashed")
        if os.path.exists(marker):
            crash_after = None
            os.remove(marker)  # no stale marker for a later parent with the same pid
        else:
            open(marker, "w").close()
    finish_after = option("--finish-after")
    code = int(option("--exit-code", "1"))
    if "--spawn-child" in argv:
        child = subprocess.Popen([sys.executable, "-c", "import time; time.sleep(600)"])
        print(f"child {name} {child.pid}", flush=True)
    print(f"ready {name} {os.getpid()} {' '.join(argv[1:])}", flush=True)
    print(f"to stderr {name}", file=sys.stderr, flush=True)
    started = time.monotonic()
    while True:
        elapsed = time.monotonic() - started
        if crash_after is not None and elapsed >= float(crash_after):
            print(f"crash {name}", flush=True)
            os._exit(code)
        if finish_after is not None and elapsed >= float(finish_after):
            print(f"done {name}", flush=True)
            return
        time.sleep(0.02)


if __name__ == "__main__":
    main()
