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
from pathlib import Path
from typing import TYPE_CHECKING, Any

from launchverify.own_code import package_folders
from launchverify.workspace.paths import resolved

if TYPE_CHECKING:
    from launchverify.workspace.packages import PackageIndex

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
    # other processes: tracing, memory
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
# Signals, even to itself (a worker that wants to end, ends by exiting): the process is
# killed (SIGSYS), so that a C-level raise() cannot fail silently and go on.
_KILLED = ("kill", "tkill", "tgkill", "rt_sigqueueinfo", "rt_tgsigqueueinfo",
           "pidfd_send_signal")
# Without Landlock: every change to the file system.
_WRITES = ("rename", "renameat", "renameat2", "link", "linkat", "symlink", "symlinkat",
           "unlink", "unlinkat", "mkdir", "mkdirat", "rmdir", "truncate", "ftruncate", "creat")
_WRITE_FLAGS = (os.O_WRONLY, os.O_RDWR, os.O_CREAT, os.O_TRUNC, os.O_APPEND)
_PR_SET_DUMPABLE = 4
_PR_SET_NO_NEW_PRIVS = 38
_PR_SET_SECCOMP = 22
_SECCOMP_MODE_FILTER = 2


WITHOUT_LANDLOCK = "LAUNCHVERIFY_WITHOUT_LANDLOCK"  # =1: confine as where Landlock is missing


class Confinement:
    """The confinement of a check's workers, prepared once in the zygote.

    Building the seccomp filter and loading the Landlock bindings costs milliseconds;
    done here, before any fork, each worker only applies them.
    """

    def __init__(self, limits: Limits, *, landlock: bool = True) -> None:
        self.limits = limits
        self.missing: dict[str, str] = {}
        if landlock:
            self.landlock = _landlock_module(self.missing)
        else:  # the fallback of kernels without it, on purpose (its tests)
            self.missing["Landlock"] = f"turned off by {WITHOUT_LANDLOCK}"
            self.landlock = None
        self.seccomp = _seccomp_filter(self.missing, writes_too=self.landlock is None)
        self.prctl = _prctl()
        self.program = _compiled(self.seccomp, self.prctl)

    def apply(self, scratch: str, readable: Iterable[str]) -> Protections:
        """Confine this process for good; return which layers took effect.

        ``readable``: existing folders (and files), none beneath another (``outermost``).
        """
        protections = Protections(missing=dict(self.missing))
        self._limits(protections)
        if self.landlock is not None:
            self._landlock(self.landlock, scratch, readable, protections)
        if self.seccomp is not None:
            try:
                if self.program is None or not self.program.load():
                    self.seccomp.load()
                protections.active.append(
                    "seccomp" if self.landlock is not None else "seccomp (no file writes)")
            except Exception as error:
                protections.missing["seccomp"] = _reason(error)
        return protections

    def _limits(self, protections: Protections) -> None:
        if resource is None:
            protections.missing["resource limits"] = "not a POSIX system"
            return
        limits = self.limits
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
        if self.prctl is not None:  # no core dump and no ptrace attach, whatever the pattern
            self.prctl(_PR_SET_DUMPABLE, 0, 0, 0, 0)
        if failed:
            protections.missing["some resource limits"] = ", ".join(failed)
        protections.active.append("resource limits")

    def _landlock(self, landlock: Any, scratch: str, readable: Iterable[str],
                  protections: Protections) -> None:
        try:
            files = landlock.FSAccess.READ_FILE | landlock.FSAccess.EXECUTE
            folders = files | landlock.FSAccess.READ_DIR
            ruleset = landlock.Ruleset()
            for path in readable:  # a rule on a file may hold only rights on files
                ruleset.allow(path, rules=folders if os.path.isdir(path) else files)  # noqa: PTH112
            for device in (os.devnull, "/dev/urandom"):
                if os.path.exists(device):  # noqa: PTH110
                    ruleset.allow(device, rules=landlock.FSAccess.READ_FILE
                                  | landlock.FSAccess.WRITE_FILE)
            ruleset.allow(scratch)
            ruleset.apply()
        except Exception as error:
            protections.missing["Landlock"] = _reason(error)
            return
        protections.active.append(f"Landlock (ABI {landlock.landlock_abi_version()})")


def outermost(folders: Iterable[str]) -> list[str]:
    """Return the existing folders (resolved) not beneath another one (one rule each)."""
    kept: list[str] = []
    for folder in sorted({os.path.realpath(f) for f in folders if os.path.exists(f)}):  # noqa: PTH110
        if not any(folder == k or folder.startswith(k.rstrip("/") + "/") for k in kept):
            kept.append(folder)
    return kept


def _landlock_module(missing: dict[str, str]) -> Any:
    if not sys.platform.startswith("linux"):
        missing["Landlock"] = "not Linux"
        return None
    try:
        import landlock
        from landlock import plumbing

        landlock.landlock_abi_version()  # raises where the kernel lacks Landlock
        for warm in (plumbing.get_add_rule, plumbing.get_restrict_self, plumbing.get_prctl):
            warm()
    except ImportError:
        missing["Landlock"] = "the 'landlock' package is not installed"
        return None
    except Exception as error:
        missing["Landlock"] = _reason(error)
        return None
    return landlock


def _seccomp_filter(missing: dict[str, str], *, writes_too: bool) -> Any:
    if not sys.platform.startswith("linux"):
        missing["seccomp"] = "not Linux"
        return None
    try:
        seccomp = _seccomp_module()
        refuse = seccomp.ERRNO(errno.EPERM)
        rules = seccomp.SyscallFilter(seccomp.ALLOW)
        for name in _DENIED + (_WRITES if writes_too else ()):
            _add(rules, refuse, name)
        for name in _KILLED:
            _add(rules, seccomp.KILL_PROCESS, name)
        _add(rules, seccomp.ERRNO(errno.ENOSYS), "clone3")  # glibc falls back to clone
        _add(rules, seccomp.ERRNO(errno.ENOSYS), "openat2")
        _add(rules, refuse, "prlimit64", seccomp.Arg(2, seccomp.NE, 0))
        if writes_too:
            for flag in _WRITE_FLAGS:
                _add(rules, refuse, "open", seccomp.Arg(1, seccomp.MASKED_EQ, flag, flag))
                _add(rules, refuse, "openat", seccomp.Arg(2, seccomp.MASKED_EQ, flag, flag))
    except ImportError:
        missing["seccomp"] = "libseccomp or the 'pyseccomp' package is missing"
        return None
    except Exception as error:
        missing["seccomp"] = _reason(error)
        return None
    return rules


class _Program:
    """A seccomp filter compiled once by libseccomp, loaded by each worker in microseconds.

    (libseccomp compiles the filter again on every ``seccomp_load``: a millisecond or two
    and hundreds of page faults per worker.) Loading is what libseccomp itself does:
    no new privileges, then ``PR_SET_SECCOMP`` with the program.
    """

    def __init__(self, code: bytes, prctl: Any) -> None:
        import ctypes

        class Program(ctypes.Structure):
            _fields_ = [("len", ctypes.c_ushort), ("filter", ctypes.c_void_p)]

        self.buffer = ctypes.create_string_buffer(code, len(code))
        self.program = Program(len(code) // 8, ctypes.addressof(self.buffer))
        self.reference = ctypes.byref(self.program)
        self.prctl = prctl

    def load(self) -> bool:
        """Install the filter in this process; ``False`` if the kernel refused."""
        if self.prctl(_PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0:
            return False
        return bool(self.prctl(_PR_SET_SECCOMP, _SECCOMP_MODE_FILTER, self.reference, 0, 0)
                    == 0)


def _compiled(rules: Any, prctl: Any) -> _Program | None:
    """Return the filter as a loadable program, or ``None`` (then libseccomp loads it)."""
    if rules is None or prctl is None:
        return None
    try:
        read, write = os.pipe()
        try:
            with os.fdopen(write, "wb", closefd=False) as handle:
                rules.export_bpf(handle)
            os.close(write)
            write = -1
            code = b""
            while chunk := os.read(read, 65536):
                code += chunk
        finally:
            os.close(read)
            if write >= 0:
                os.close(write)
    except Exception:
        return None
    return _Program(code, prctl) if code and len(code) % 8 == 0 else None


def _prctl() -> Any:
    if not sys.platform.startswith("linux"):
        return None
    try:
        import ctypes

        prctl = ctypes.CDLL(None, use_errno=True).prctl
    except (OSError, AttributeError):
        return None
    # every argument a full word: prctl reads unsigned longs, and checks unused ones are 0
    prctl.argtypes = (ctypes.c_int, ctypes.c_ulong, ctypes.c_void_p, ctypes.c_ulong,
                      ctypes.c_ulong)
    prctl.restype = ctypes.c_int
    return prctl


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
    try:  # (a plain descriptor: each worker reads this, and file objects cost faults)
        fd = os.open("/proc/self/statm", os.O_RDONLY)
        try:
            pages = int(os.read(fd, 256).split()[0])
        finally:
            os.close(fd)
        return pages * os.sysconf("SC_PAGE_SIZE")
    except (OSError, ValueError, IndexError):
        return 0


def readable_folders(index: PackageIndex, workspace: Path) -> tuple[str, ...]:
    """Return the folders a worker may read: the workspace, packages, Python, system libraries.

    Everything else (home folders, ``/proc``, ``/etc``) stays unreadable where Landlock
    is available, so a launch file cannot copy secrets into its findings.
    """
    folders = {str(workspace)}
    folders.update(str(folder) for folder in (*index.workspaces, *index.prefixes))
    folders.update(str(folder) for found in index.sources.values() for folder in found)
    prefixes = (sys.prefix, sys.base_prefix, sys.exec_prefix, sys.base_exec_prefix)
    folders.update(prefixes)
    # Python's own folders: beneath a prefix, site-packages-like, or on PYTHONPATH (a ROS
    # installation's); not the folder launchverify was started in.
    python_path = os.environ.get("PYTHONPATH", "").split(os.pathsep)
    folders.update(entry for entry in sys.path if entry and (
        entry in python_path or entry.endswith(("site-packages", "dist-packages"))
        or any(entry.startswith(prefix + os.sep) for prefix in prefixes)))
    # launchverify's own packages where Python finds them (a module a model imports late
    # is read there), and their real folders: a strict editable install links each
    # module of its tree into the checkout
    folders.update(package_folders())
    folders.update(str(resolved(Path(folder, "__init__.py")).parent)
                   for folder in package_folders())
    folders.update(("/usr/lib", "/usr/lib64", "/lib", "/lib64", "/usr/share/zoneinfo",
                    "/etc/ld.so.cache", "/etc/localtime"))
    return tuple(outermost(folders))


def beneath(folder: str, folders: Iterable[str]) -> bool:
    """Return whether ``folder`` is one of ``folders`` or inside one of them (real paths)."""
    return any(folder == f or folder.startswith(f.rstrip("/") + "/") for f in folders)
