"""What each launch argument may be: pinned, one of its choices, a switch, or free text.

Two ways to range over arguments (``Mode``):

- ``ANY``: every value ``ros2 launch`` accepts. An argument given on our command line is
  that value; one with ``choices`` is one of them (launch rejects the rest); any other
  argument is any string, or its default when not given. Used to claim that something
  holds for *every* assignment (a condition that can never be true).
- ``SWITCHES``: the combinations of the launch's switches. A switch is an argument with
  ``choices`` or a boolean default (``true``/``false``/``1``/``0``, any case): it takes
  its choices, or the default and its opposite. An argument an include path is computed
  from (``$(find-pkg-share $(var sensor)_launch)``) is one too: it takes its default and
  the values the include was followed for. Every other argument keeps its default
  (or its pinned value). Used to claim that something *can* happen (two nodes collide):
  a namespace or robot-name argument names one robot per launch, and varying it freely
  would make every namespaced node collide with every other one.

An argument without default and without choices that is not pinned is *unconstrained*
in both modes.

Only arguments the user can see are switches: those ``ros2 launch --show-args`` lists for
the root (launch's static discovery, through the includes whose path needs no
configuration). An argument declared only where static discovery does not reach keeps
its default: a witness never asks the user to set what the launch does not expose.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass, field

from launchverify.evaluate.values import BaseReducer, text_of
from launchverify.graph import LaunchGraph
from launchverify.models.booleans import CONDITION_FALSE, CONDITION_TRUE
from launchverify.span import Span


class Mode(enum.Enum):
    """How arguments range (see the module docstring)."""

    ANY = "any"
    SWITCHES = "switches"


_OPPOSITE = {"true": "false", "false": "true", "True": "False", "False": "True",
             "TRUE": "FALSE", "FALSE": "TRUE", "1": "0", "0": "1"}


@dataclass
class ArgumentDomain:
    """Everything known about one launch argument of a root launch."""

    name: str
    pinned: str | None = None
    choices: tuple[str, ...] | None = None
    choices_at: Span | None = None
    defaults: set[str] = field(default_factory=set)  # default texts under the base view
    symbolic_default: bool = False  # some default depends on something unknown
    required: bool = False  # declared somewhere without a default
    exposed: bool = True  # part of the root's interface (see argument_domains)
    candidates: tuple[str, ...] = ()  # values a computed include path was followed for

    @property
    def boolean(self) -> bool:
        """Return whether every default is a boolean the condition rule accepts."""
        return bool(self.defaults) and not self.symbolic_default and all(
            d.strip().lower() in CONDITION_TRUE + CONDITION_FALSE for d in self.defaults)

    @property
    def switch(self) -> bool:
        """Return whether the argument is varied in ``SWITCHES`` mode."""
        return self.pinned is None and self.exposed and (
            self.choices is not None or self.boolean or bool(self.candidates))

    def values(self, mode: Mode) -> tuple[str, ...] | None:
        """Return the finite set of values a given argument takes, or ``None`` (any)."""
        if self.pinned is not None:
            return (self.pinned,)
        if mode is Mode.SWITCHES and not self.exposed and self.defaults \
                and not self.symbolic_default:
            return tuple(sorted(self.defaults))  # not the user's to set: its default
        if self.choices is not None:
            return self.choices
        if mode is Mode.SWITCHES and self.candidates and not self.symbolic_default:
            return tuple(sorted(self.defaults | set(self.candidates)))
        if mode is Mode.SWITCHES and self.boolean:
            values = set(self.defaults)
            values.update(_OPPOSITE.get(d.strip(), "false" if d.strip().lower() in
                                        CONDITION_TRUE else "true") for d in self.defaults)
            return tuple(sorted(values))
        return None

    def describe(self, mode: Mode) -> str:
        """Return the domain as a reader would state it (for unsat cores)."""
        if self.pinned is not None:
            return f"{self.name}:={self.pinned} (command line)"
        values = self.values(mode)
        where = f" (declared at {self.choices_at.short()})" if self.choices_at else ""
        return f"{self.name} is one of {list(values or ())}{where}"


def argument_domains(graph: LaunchGraph) -> dict[str, ArgumentDomain]:
    """Return the domain of every argument declared in an evaluation."""
    base = BaseReducer(graph.inputs())
    out: dict[str, ArgumentDomain] = {}
    for record in graph.arguments:
        domain = out.setdefault(record.name, ArgumentDomain(record.name))
        if record.default is None:
            domain.required = True
        else:
            text = text_of(base.reduce(record.default))
            if text is None:
                domain.symbolic_default = True
            else:
                domain.defaults.add(text)
        if record.choices is not None:
            kept = record.choices if domain.choices is None else tuple(
                c for c in domain.choices if c in record.choices)
            domain.choices = kept
            domain.choices_at = domain.choices_at or record.origin.span
    # The root's interface: what it declares, and what an included file declares where
    # an include on the way passes it by name. A knob only an included file declares, and
    # nothing on the way passes, is that file's own (``ros2 launch --show-args`` lists
    # it, but no user of the root is meant to turn it: autoware's sensing component's
    # launch_pointcloud_container says so in its description).
    listed = {argument.name for argument in graph.root_arguments
              if argument.span.file == graph.root
              or any(argument.name in passed for passed in argument.via_includes)}
    for domain in out.values():
        domain.exposed = domain.name in listed
    for include in graph.includes:
        if include.status == "computed" and include.computed_from in out:
            domain = out[include.computed_from]
            domain.candidates = tuple(sorted({*domain.candidates, *include.candidates}))
    for name, value in graph.pinned.items():
        out.setdefault(name, ArgumentDomain(name)).pinned = value
    return out
