"""Command lines as ros2 launch builds them, and the executables they name.

A node's command is launch_ros's: the executable, its ``arguments``, ``--ros-args`` with
its ``ros_arguments``, then ``--ros-args`` with ``-r __node:=NAME``, ``-r __ns:=NS``, the
parameters in the order they reach the node (``-p name:=value`` for ``SetParameter``,
``--params-file`` for files; inline dictionaries written to a parameter file under
``/**``) and the remaps (``-r from:=to``, ``SetRemap`` rules first). Executables come
from ``lib/<package>/<executable>`` of an install prefix (``AMENT_PREFIX_PATH``) or of the
workspace's ``install/`` folder (merged or isolated layout).
"""

from __future__ import annotations

import os
import shutil
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path

import yaml

from launchverify.evaluate.values import file_source
from launchverify.graph import LaunchGraph, LaunchRecord, NodeRecord, ParamRecord
from launchverify.ir.subst import Concat, Sub, Text
from launchverify.ir.symbolic import CommandOutput
from launchverify.models import rewritten_yaml
from launchverify.models.parameter_values import typed_parameter


class CommandError(Exception):
    """A process that cannot be started as written (unknown value, missing executable)."""


@dataclass
class Command:
    """A process ready to start: argv, working folder, environment changes, files to write."""

    argv: list[str]
    cwd: str | None = None
    env: dict[str, str | None] = field(default_factory=dict)  # None: unset
    replace_env: dict[str, str] | None = None
    files: dict[Path, str] = field(default_factory=dict)  # parameter files to write first
    shell: bool = False


def install_prefixes(workspace: Path | None) -> list[Path]:
    """Return where executables are looked for: AMENT_PREFIX_PATH, then the workspace."""
    prefixes = [Path(p) for p in os.environ.get("AMENT_PREFIX_PATH", "").split(os.pathsep)
                if p]
    if workspace is not None and (workspace / "install").is_dir():
        install = workspace / "install"
        prefixes.append(install)
        prefixes.extend(sorted(p for p in install.iterdir() if p.is_dir()))
    return prefixes


def find_executable(package: str, executable: str, prefixes: Iterable[Path]) -> Path:
    """Return ``lib/<package>/<executable>`` from the first prefix that has it."""
    for prefix in prefixes:
        candidate = prefix / "lib" / package / executable
        if candidate.is_file() and os.access(candidate, os.X_OK):
            return candidate
    raise CommandError(f"executable '{executable}' of package '{package}' not found in "
                       "any install prefix (AMENT_PREFIX_PATH or the workspace's install/; "
                       "build and source the workspace first)")


class CommandBuilder:
    """Builds the commands of one graph's processes under its arguments."""

    def __init__(self, graph: LaunchGraph, prefixes: list[Path], params_dir: Path, *,
                 strict: bool = True) -> None:
        self.graph = graph
        self.strict = strict  # False (dry runs): a missing executable is shown, not fatal
        self.missing: list[str] = []
        self.prefixes = prefixes
        self.params_dir = params_dir
        self.counter = 0
        self.pending_files: dict[Path, str] = {}

    def text(self, sub: Sub | None, what: str) -> str:
        """Return a value, or fail when it depends on something unknown before run time.

        ``$(command ...)`` parts are run now, as launch runs them when the action
        executes (in a dry run they are shown instead).
        """
        if sub is None:
            return ""
        value = self.graph.base(sub)
        if value is not None:
            return value
        value = self.materialize(self.graph.reduced(sub))
        if value is None:
            if not self.strict:
                return sub.describe()
            raise CommandError(f"{what} is not known before run time ({sub.describe()})")
        return value

    def materialize(self, sub: Sub) -> str | None:
        """Return a reduced value's text, running the commands it holds (``None``: no)."""
        if isinstance(sub, Text):
            return sub.text
        if isinstance(sub, Concat):
            texts = []
            for part in sub.parts:
                text = self.materialize(part)
                if text is None:
                    return None
                texts.append(text)
            return "".join(texts)
        if isinstance(sub, CommandOutput) and self.strict:
            command = self.materialize(sub.command)
            on_stderr = "fail" if sub.on_stderr is None else self.materialize(sub.on_stderr)
            return None if command is None else run_command(command, on_stderr or "fail")
        return None

    def build(self, launch: LaunchRecord) -> Command:
        """Return the command of one process."""
        settings = launch.settings
        if launch.node is not None:
            argv = self.node_argv(launch, launch.node)
        else:
            argv = [self.text(part, "a command word") for part in launch.cmd]
            if not argv or not argv[0]:
                raise CommandError("empty command")
            if not settings.shell:
                argv[0] = self.program(argv[0])
        if settings.prefix is not None:
            prefix = self.text(settings.prefix, "the prefix")
            argv = [*prefix.split(), *argv] if prefix.strip() else argv
        command = Command(argv, shell=settings.shell, files=dict(self.pending_files))
        self.pending_files.clear()
        if settings.cwd is not None:
            command.cwd = self.text(settings.cwd, "the working folder")
        for name, value in settings.env:
            command.env[name] = None if value is None else self.text(value, f"${name}")
        if settings.replace_env is not None:
            command.replace_env = {self.text(k, "an environment name"): self.text(v, "a value")
                                   for k, v in settings.replace_env}
        return command

    def program(self, word: str) -> str:
        """Return a command's program as a path (PATH lookup for bare names)."""
        if os.sep in word:
            return word
        found = shutil.which(word)
        if found is None:
            error = f"program '{word}' not found on PATH"
            if self.strict:
                raise CommandError(error)
            self.missing.append(error)
            return word
        return found

    def node_argv(self, launch: LaunchRecord, node: NodeRecord) -> list[str]:
        """Return a node's argv as launch_ros builds it."""
        executable = self.text(node.executable, "the executable")
        if node.package is not None:
            package = self.text(node.package, "the package")
            try:
                program = str(find_executable(package, executable, self.prefixes))
            except CommandError as error:
                if self.strict:
                    raise
                self.missing.append(str(error))
                program = f"<lib/{package}/{executable}: not found>"
        else:
            program = self.program(executable)
        # a RewrittenYaml given as an argument (a spawner's --param-file) is the file it writes
        argv = [program, *(self.parameter_file(a) if rewritten_yaml.rewrite_of(a) is not None
                           else self.text(a, "an argument") for a in launch.arguments)]
        if launch.ros_arguments:
            argv += ["--ros-args", *(self.text(a, "a ROS argument") for a in launch.ros_arguments)]
        argv.append("--ros-args")
        if node.name is not None:
            argv += ["-r", f"__node:={self.text(node.name, 'the node name')}"]
        if node.namespace is not None:
            namespace = self.text(node.namespace, "the namespace")
            if namespace:
                argv += ["-r", f"__ns:={namespace}"]
        argv += self.parameter_arguments(node.parameters)
        for remap in node.remappings:
            argv += ["-r", f"{self.text(remap.src, 'a remap')}:={self.text(remap.dst, 'a remap')}"]
        return argv

    def parameter_arguments(self, parameters: tuple[ParamRecord, ...]) -> list[str]:
        """Return ``-p``/``--params-file`` arguments; inline values go to a written file."""
        out: list[str] = []
        inline: dict[str, object] = {}

        def flush() -> None:
            if not inline:
                return
            document = {"/**": {"ros__parameters": _nest(inline)}}
            out.extend(["--params-file", self.written(document)])
            inline.clear()

        for param in parameters:
            if param.file is not None:
                flush()
                out.extend(["--params-file", self.parameter_file(param.file)])
            elif param.name is not None:
                name = self.text(param.name, "a parameter name")
                value = self.value(param.value, param.value_type)
                if param.scope:  # SetParameter: launch_ros passes -p name:=value
                    flush()
                    out.extend(["-p", f"{name}:={yaml_value(value)}"])
                else:
                    inline[name] = value
        flush()
        return out

    def written(self, document: object) -> str:
        """Return where a parameter file the launch makes is written (before the start)."""
        self.counter += 1
        path = self.params_dir / f"params_{self.counter}.yaml"
        self.pending_files[path] = yaml.safe_dump(document, sort_keys=False)
        return str(path)

    def parameter_file(self, file: Sub) -> str:
        """Return the path of a parameter file; one ``RewrittenYaml`` makes, written."""
        path = str(Path(self.text(file_source(file), "a parameter file")).absolute())
        rewrite = rewritten_yaml.rewrite_of(file)
        if rewrite is None:
            return path
        if not rewrite.exact:
            if not self.strict:
                return path  # (a dry run shows the source)
            raise CommandError(f"{rewrite.describe()}: launchverify does not follow what it "
                               "rewrites (key_rewrites, or a key that is not text)")
        rewrites = {key: self.text(value, f"the value RewrittenYaml gives {key}")
                    for key, value in rewrite.params}
        replaced = {key: self.text(value, f"the value RewrittenYaml gives for {key}")
                    for key, value in rewrite.values}
        root = None if rewrite.root_key is None else self.text(rewrite.root_key, "a root key")
        try:
            document = yaml.safe_load(Path(path).read_text(encoding="utf-8"))
            rewritten = rewritten_yaml.rewrite_document(document, rewrites, replaced, root,
                                                        rewrite.convert)
        except (OSError, ValueError, TypeError, AttributeError, IndexError, KeyError,
                yaml.YAMLError) as error:
            raise CommandError(f"{rewrite.describe()} cannot be rewritten: {error}") from error
        return self.written(rewritten)

    def value(self, value: object, value_type: str | None) -> object:
        """Return a parameter value as the node receives it."""
        if isinstance(value, Sub):
            return typed_parameter(self.text(value, "a parameter value"), value_type)
        if isinstance(value, tuple):
            return [self.value(v, value_type) for v in value]
        return value


def _nest(flat: dict[str, object]) -> dict[str, object]:
    """Turn ``a.b: 1`` into ``a: {b: 1}``, as parameter files write namespaced names."""
    out: dict[str, object] = {}
    for name, value in flat.items():
        parts = name.split(".")
        here = out
        for part in parts[:-1]:
            child = here.setdefault(part, {})
            if not isinstance(child, dict):
                here[name] = value
                break
            here = child
        else:
            here[parts[-1]] = value
    return out


def yaml_value(value: object) -> str:
    """Return a value as one line of YAML (``-p name:=VALUE``)."""
    text = yaml.safe_dump(value, default_flow_style=True, width=1 << 20).strip()
    return text.removesuffix("...").strip()


def run_command(command: str, on_stderr: str) -> str:
    """Run a ``$(command ...)`` as launch does: its stdout, unstripped; failures raise."""
    import shlex
    import subprocess

    try:
        done = subprocess.run(shlex.split(command), capture_output=True, text=True,
                              timeout=120, check=False)
    except (OSError, ValueError, subprocess.TimeoutExpired) as error:
        raise CommandError(f"$(command {command}) failed: {error}") from error
    if done.returncode != 0:
        raise CommandError(f"$(command {command}) exited with {done.returncode}: "
                           f"{done.stderr.strip()[:500]}")
    if done.stderr and on_stderr == "fail":
        raise CommandError(f"$(command {command}) wrote to stderr: {done.stderr.strip()[:500]}")
    return done.stdout
