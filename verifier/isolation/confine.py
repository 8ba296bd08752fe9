"""Operating-system confinement of a worker process, applied before any user code runs.

Layers, strongest first; each is applied when the system has it and its absence is said:

- **seccomp** (libseccomp through ``pyseccomp``): no new processes or threads, no sockets,
  no signals to other processes, no tracing or reading other processes, no raising of the
  limits below, no mounts, namespaces, kernel modules, clocks, keyrings, persistent IPC
  objects or io_uring, no changes to file ownership, modes or times;
- **Landlock** (``landlock``): files are read only beneath the folders the evaluation needs
  (the workspace, package folders, the Python installation, system libraries) and written
  only beneath the worker's scratch folder. Without Landlock, seccomp refuses every write
  instead (no file can be created or changed, not even a temporary one);
- **resource limits** (``resource``): address space, CPU time, file size, open files, no
  processes, no core dumps. seccomp makes them final.

The audit hook of ``frontends.python.sandbox`` stays in front of all this: it turns what
Python announces into clear messages ("os.system is not allowed"), while the kernel
enforces what Python does not announce.
"""

from __future__ import annotations

import contextlib
import errno
import os
import sys
from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import Any

try:
    import resource
except ImportError:  # pragma: no cover - not POSIX
    resource = None  # type: ignore[assignment]


@dataclass(frozen=True)
class Limits:
    """What one worker may use."""

    seconds: float = 10.0  # per request (a file's evaluation, one OpaqueFunction call)
    memory: int = 2 * 1024 ** 3  # bytes of address space beyond the worker's start
    cpu_seconds: int = 120  # over the worker's life
    file_size: int = 64 * 1024 ** 2  # the largest file it may write (in its scratch folder)
    open_files: int = 256


@dataclass
class Protections:
    """Which layers are active in a worker, and why the others are not."""

    active: list[str] = field(default_factory=list)
    missing: dict[str, str] = field(default_factory=dict)

    def describe(self) -> str:
        """Return one line for the user."""
        text = "active: " + (", ".join(self.active) or "none")
        if self.missing:
            text += "; unavailable: " + "; ".join(f"{k} ({v})" for k, v in self.missing.items())
        return text


_DENIED = (
    # new processes and threads
    "fork", "vfork", "clone", "execve", "execveat",
    # networking
    "socket", "socketpair", "connect", "bind", "listen", "accept", "accept4",
    # other processes: signals, tracing, memory
    "kill", "tkill", "rt_sigqueueinfo", "rt_tgsigqueueinfo", "pidfd_send_signal",
    "pidfd_open", "pidfd_getfd", "ptrace", "process_vm_readv", "process_vm_writev", "kcmp",
    "process_madvise", "process_mrelease", "migrate_pages", "move_pages",
    # limits, scheduling, sessions
    "setrlimit", "setpriority", "sched_setaffinity", "sched_setscheduler", "sched_setparam",
    "sched_setattr", "ioprio_set", "setsid", "setpgid",
    # the system
    "mount", "umount2", "pivot_root", "chroot", "unshare", "setns", "swapon", "swapoff",
    "reboot", "kexec_load", "kexec_file_load", "init_module", "finit_module",
    "delete_module", "sethostname", "setdomainname", "settimeofday", "clock_settime",
    "clock_adjtime", "adjtimex", "acct", "quotactl", "quotactl_fd", "syslog", "iopl",
    "ioperm", "vhangup", "bpf", "perf_event_open", "userfaultfd", "keyctl", "add_key",
    "request_key", "fanotify_init", "name_to_handle_at", "open_by_handle_at", "personality",
    "io_uring_setup", "io_uring_enter", "io_uring_register", "fsopen", "fsmount", "fsconfig",
    "fspick", "move_mount", "open_tree", "mount_setattr", "uselib", "lookup_dcookie",
    # objects that outlive the process
    "mq_open", "mq_unlink", "msgget", "semget", "shmget", "mknod", "mknodat",
    # file metadata (Landlock does not cover it)
    "chmod", "fchmod", "fchmodat", "fchmodat2", "chown", "fchown", "lchown", "fchownat",
    "utime", "utimes", "utimensat", "futimesat", "setxattr", "lsetxattr", "fsetxattr",
    "removexattr", "lremovexattr", "fremovexattr",
)
# Without Landlock: every change to the file system.
_WRITES = ("rename", "renameat", "renameat2", "link", "linkat", "symlink", "symlinkat",
           "unlink", "unlinkat", "mkdir", "mkdirat", "rmdir", "truncate", "ftruncate", "creat")
_WRITE_FLAGS = (os.O_WRONLY, os.O_RDWR, os.O_CREAT, os.O_TRUNC, os.O_APPEND)


def confine(scratch: str, readable: Iterable[str], limits: Limits) -> Protections:
    """Confine this process for good; return which layers took effect."""
    protections = Protections()
    _set_limits(limits, protections)
    landlocked = _landlock(scratch, readable, protections)
    _seccomp(protections, writes_too=not landlocked)
    return protections


def _set_limits(limits: Limits, protections: Protections) -> None:
    if resource is None:
        protections.missing["resource limits"] = "not a POSIX system"
        return
    wanted = [
        ("RLIMIT_AS", _address_space() + limits.memory),
        ("RLIMIT_CPU", limits.cpu_seconds),
        ("RLIMIT_FSIZE", limits.file_size),
        ("RLIMIT_NOFILE", limits.open_files),
        ("RLIMIT_NPROC", 0),
        ("RLIMIT_CORE", 0),
        ("RLIMIT_MSGQUEUE", 0),
    ]
    failed = []
    for name, value in wanted:
        which = getattr(resource, name, None)
        if which is None:
            continue
        try:
            _, hard = resource.getrlimit(which)
            if hard != resource.RLIM_INFINITY:
                value = min(value, hard)
            resource.setrlimit(which, (value, value))
        except (ValueError, OSError):
            failed.append(name)
    _not_dumpable()
    if failed:
        protections.missing["some resource limits"] = ", ".join(failed)
    protections.active.append("resource limits")


def _not_dumpable() -> None:
    """No core dump and no ptrace attach, whatever the core pattern (``PR_SET_DUMPABLE``)."""
    if not sys.platform.startswith("linux"):
        return
    try:
        import ctypes

        ctypes.CDLL(None, use_errno=True).prctl(4, 0, 0, 0, 0)
    except (OSError, AttributeError):
        pass


def _landlock(scratch: str, readable: Iterable[str], protections: Protections) -> bool:
    if not sys.platform.startswith("linux"):
        protections.missing["Landlock"] = "not Linux"
        return False
    try:
        import landlock

        version = landlock.landlock_abi_version()
        read = landlock.FSAccess.READ_FILE | landlock.FSAccess.READ_DIR \
            | landlock.FSAccess.EXECUTE
        ruleset = landlock.Ruleset()
        for folder in sorted(set(readable)):
            if os.path.exists(folder):  # noqa: PTH110
                ruleset.allow(folder, rules=read)
        for device in (os.devnull, "/dev/urandom"):
            if os.path.exists(device):  # noqa: PTH110
                ruleset.allow(device, rules=landlock.FSAccess.READ_FILE
                              | landlock.FSAccess.WRITE_FILE)
        ruleset.allow(scratch)
        ruleset.apply()
    except ImportError:
        protections.missing["Landlock"] = "the 'landlock' package is not installed"
        return False
    except Exception as error:  # the kernel lacks it, or a container forbids it
        protections.missing["Landlock"] = _reason(error)
        return False
    protections.active.append(f"Landlock (ABI {version})")
    return True


def _seccomp(protections: Protections, *, writes_too: bool) -> None:
    if not sys.platform.startswith("linux"):
        protections.missing["seccomp"] = "not Linux"
        return
    try:
        seccomp = _seccomp_module()
        refuse = seccomp.ERRNO(errno.EPERM)
        rules = seccomp.SyscallFilter(seccomp.ALLOW)
        names = _DENIED + (_WRITES if writes_too else ())
        for name in names:
            _add(rules, refuse, name)
        _add(rules, seccomp.ERRNO(errno.ENOSYS), "clone3")  # glibc falls back to clone
        _add(rules, seccomp.ERRNO(errno.ENOSYS), "openat2")
        _add(rules, refuse, "tgkill", seccomp.Arg(0, seccomp.NE, os.getpid()))
        _add(rules, refuse, "prlimit64", seccomp.Arg(2, seccomp.NE, 0))
        if writes_too:
            for flag in _WRITE_FLAGS:
                _add(rules, refuse, "open", seccomp.Arg(1, seccomp.MASKED_EQ, flag, flag))
                _add(rules, refuse, "openat", seccomp.Arg(2, seccomp.MASKED_EQ, flag, flag))
        rules.load()
    except ImportError:
        protections.missing["seccomp"] = "libseccomp or the 'pyseccomp' package is missing"
        return
    except Exception as error:  # a container that forbids seccomp, an old kernel
        protections.missing["seccomp"] = _reason(error)
        return
    protections.active.append("seccomp" + ("" if not writes_too else " (no file writes)"))


def _seccomp_module() -> Any:
    try:
        import seccomp  # libseccomp's own bindings, where the system has them
    except ImportError:
        import pyseccomp as seccomp
    return seccomp


def _add(rules: object, action: object, name: str, *conditions: object) -> None:
    # a system call this architecture does not have is skipped
    with contextlib.suppress(RuntimeError, ValueError, OSError):
        rules.add_rule(action, name, *conditions)  # type: ignore[attr-defined]


def _reason(error: BaseException) -> str:
    text = str(error).splitlines()[0] if str(error) else type(error).__name__
    return text[:120]


def _address_space() -> int:
    try:
        with open("/proc/self/statm", "rb") as handle:  # noqa: PTH123
            pages = int(handle.read().split()[0])
        return pages * os.sysconf("SC_PAGE_SIZE")
    except (OSError, ValueError, IndexError):
        return 0


def prepare() -> None:
    """Load what confinement needs while the process may still read anything.

    ``pyseccomp`` looks libseccomp up with ``ldconfig`` when imported: done once in the
    launchverify process, before any worker exists.
    """
    if not sys.platform.startswith("linux"):
        return
    with contextlib.suppress(ImportError, OSError):
        _seccomp_module()
    with contextlib.suppress(ImportError):
        import landlock  # noqa: F401
