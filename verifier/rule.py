"""Rules and findings: what a rule module defines and what it yields.

A rule is a class with a code (``LV101``), a slug (``duplicate-node-name``), a severity, a
message template and a docstring with four headings (What it does / Why it matters /
Example / Fix) that ``launchverify explain`` prints. ``check`` looks at one launch graph and
yields findings built with ``self.finding(...)``: a rule cannot mislabel itself.
"""

from __future__ import annotations

import enum
from collections.abc import Hashable, Iterable, Iterator, Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, ClassVar

from launchverify.findings.trace import Step
from launchverify.span import Span

if TYPE_CHECKING:  # a finding read back from the cache needs none of these
    from launchverify.graph import LaunchGraph, Origin
    from launchverify.ir.symbolic import PathCondition
    from launchverify.workspace.interfaces import Interfaces
    from launchverify.workspace.packages import PackageIndex


class Severity(enum.Enum):
    """How bad a finding is; ``error`` fails ``launchverify check``."""

    ERROR = "error"
    WARNING = "warning"
    INFO = "info"

    @property
    def rank(self) -> int:
        """Return 2 for errors, 1 for warnings, 0 for infos."""
        return {"error": 2, "warning": 1, "info": 0}[self.value]


@dataclass(frozen=True, slots=True)
class Related:
    """Another place that explains a finding (the first definition, the declaration...)."""

    span: Span
    message: str


IN_CALL = "in this call"  # the related call around a finding's expression


class Applicability(enum.Enum):
    """Whether ``--fix`` applies a fix on its own (safe) or only with ``--unsafe-fixes``."""

    SAFE = "safe"
    UNSAFE = "unsafe"


@dataclass(frozen=True, slots=True)
class Edit:
    """Replace the text from ``span``'s start to its end (exclusive) with ``content``.

    The span must carry its end; an empty span (start == end) inserts.
    """

    span: Span
    content: str


@dataclass(frozen=True, slots=True)
class Fix:
    """How to mend a finding: edits to the user's files, said in a few words."""

    message: str  # "rename to 'use_sim_time'"
    edits: tuple[Edit, ...]
    applicability: Applicability = Applicability.SAFE


def rename(written: Span | None, old: str, new: str, *, unique: bool) -> Fix | None:
    """Return the fix that replaces ``old``, written verbatim at ``written``, with ``new``.

    Safe when ``new`` is the only candidate (``unique``), else unsafe. ``None`` when the
    place is unknown or is not exactly ``old``'s width on one line: a fix replaces exactly
    the text it names, or is not offered.

    Examples:
        >>> from pathlib import Path
        >>> fix = rename(Span(Path("a.xml"), 3, 12, 3, 17), "talkr", "talker", unique=True)
        >>> fix.message, fix.applicability.value, fix.edits[0].content
        ("replace 'talkr' with 'talker'", 'safe', 'talker')
        >>> rename(Span(Path("a.xml"), 3, 12), "talkr", "talker", unique=True) is None
        True
    """
    if (written is None or written.end_line != written.line or written.end_column is None
            or written.end_column - written.column != len(old) or not old or old == new):
        return None
    return Fix(f"replace {old!r} with {new!r}", (Edit(written, new),),
               Applicability.SAFE if unique else Applicability.UNSAFE)


@dataclass(frozen=True, slots=True)
class Finding:
    """One reported problem, with everything reporters need."""

    code: str
    slug: str
    severity: Severity
    message: str
    span: Span
    related: tuple[Related, ...] = ()
    chain: tuple[Span, ...] = ()
    witness: Mapping[str, str] | None = None
    trace: tuple[Step, ...] = ()  # how the launch gets there (lifecycle rules)
    fix: Fix | None = field(default=None, compare=False)
    # the path condition of where it is (not shown: dead code is dropped by the engine)
    path: PathCondition = field(default=(), compare=False, repr=False)

    def key(self) -> tuple[object, ...]:
        """Return what makes two findings the same (for de-duplication across roots)."""
        return (self.code, str(self.span.file), self.span.line, self.span.column, self.message)

    def sort_key(self) -> tuple[object, ...]:
        """Return the order reporters use: file, line, column, code."""
        return (str(self.span.file), self.span.line, self.span.column, self.code, self.message)


def _no_interfaces() -> Interfaces:
    from launchverify.workspace.interfaces import Interfaces

    return Interfaces()


@dataclass
class RuleContext:
    """What a rule may use besides the graph.

    ``settled`` lets a rule marked ``every_context`` remember, across the graphs of one
    check, places where some evaluation already shows the finding does not hold (it
    would be voted out anyway), so that the other graphs need not ask again.
    """

    packages: PackageIndex | None = None
    interfaces: Interfaces = field(default_factory=_no_interfaces)  # of every checked root
    # What the check's configuration says for rules (``engine.rule_options``): name globs
    # under ``external-names`` and ``single-writer-topics``.
    options: dict[str, object] = field(default_factory=dict)
    settled: dict[str, Settled] = field(default_factory=dict)
    memo: dict[str, dict[object, object]] = field(default_factory=dict)

    def settled_for(self, code: str) -> Settled:
        """Return the places a rule has settled (created on first use)."""
        return self.settled.setdefault(code, Settled())

    def memo_for(self, code: str) -> dict[object, object]:
        """Return what a rule gathers across graphs for its ``finish`` (created on first use)."""
        return self.memo.setdefault(code, {})


class Settled:
    """The places a rule marked ``every_context`` found settled, across graphs.

    Skipping a settled place makes one graph's findings depend on the graphs judged
    before it; ``log`` makes that dependency visible, per graph: the places the graph
    settled, and those it skipped because another graph had (a result kept between
    checks is valid only while the places it skipped are still settled by some graph).
    """

    def __init__(self, places: Iterable[object] = ()) -> None:
        self.places = set(places)
        self.log: tuple[set[object], set[object]] | None = None  # (settled, relied on)

    def __contains__(self, place: object) -> bool:
        if place not in self.places:
            return False
        if self.log is not None:
            self.log[1].add(place)
        return True

    def add(self, place: object) -> None:
        """Record that some evaluation shows the finding cannot stand at ``place``."""
        self.places.add(place)
        if self.log is not None:
            self.log[0].add(place)


class Poll:
    """Claims of absence put to every evaluation that can judge them.

    A file evaluated alone may lack what an includer supplies (a manager's node started by
    a sibling include), and an includer may be too incomplete to say anything. A rule asks
    each complete evaluation a question (a place, in words that do not depend on the
    context) and records its answer: a finding, or ``None`` when all is well there. A claim
    is kept when every answer to its question makes it; the shortest include chain wins.
    """

    def __init__(self, ctx: RuleContext, code: str) -> None:
        self.answers = ctx.memo_for(code)

    def answer(self, question: Hashable, finding: Finding | None) -> None:
        """Record one evaluation's answer to a question."""
        answers = self.answers.setdefault(question, [])
        assert isinstance(answers, list)
        answers.append(finding)

    def outcome(self) -> Iterator[Finding]:
        """Yield the claims every evaluation that was asked agrees on."""
        for answers in self.answers.values():
            assert isinstance(answers, list)
            if answers and all(isinstance(a, Finding) for a in answers):
                yield min(answers, key=lambda f: len(f.chain))


class Rule:
    """Base class of every rule module's rule."""

    code: ClassVar[str]
    slug: ClassVar[str]
    severity: ClassVar[Severity]
    message: ClassVar[str]

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        """Yield the findings of this rule on one launch graph."""
        raise NotImplementedError

    def finish(self, ctx: RuleContext) -> Iterator[Finding]:
        """Yield findings that need every graph of the check (after ``check`` saw them all)."""
        return iter(())

    def finding(
        self,
        origin: Origin | Span,
        *,
        related: tuple[Related, ...] = (),
        witness: Mapping[str, str] | None = None,
        trace: tuple[Step, ...] = (),
        fix: Fix | None = None,
        **values: object,
    ) -> Finding:
        """Build a finding from the message template at a record's origin (or a span)."""
        span, chain, path = ((origin, (), ()) if isinstance(origin, Span)
                             else (origin.span, origin.chain, origin.path))
        if not isinstance(origin, Span) and origin.call is not None:
            related = (*related, Related(origin.call, IN_CALL))
        return Finding(
            code=self.code,
            slug=self.slug,
            severity=self.severity,
            message=self.message.format(**values),
            span=span,
            related=related,
            chain=chain,
            witness=witness,
            trace=trace,
            fix=fix,
            path=path,
        )

    @classmethod
    def documentation(cls) -> str:
        """Return the rule's documentation (its docstring, dedented)."""
        import inspect

        return inspect.cleandoc(cls.__doc__ or "")

    @classmethod
    def summary(cls) -> str:
        """Return the first line of the documentation."""
        return cls.documentation().split("\n", 1)[0].strip()

    @classmethod
    def section(cls, heading: str) -> str:
        """Return one ``## heading`` section of the documentation ('' when absent)."""
        text = cls.documentation()
        marker = f"## {heading}"
        start = text.find(marker)
        if start < 0:
            return ""
        body = text[start + len(marker):]
        end = body.find("\n## ")
        return (body if end < 0 else body[:end]).strip()

    @classmethod
    def lead(cls, heading: str) -> str:
        """Return the first paragraph of a section on one line (a short why or fix)."""
        return " ".join(cls.section(heading).split("\n\n", 1)[0].split())


class GatheringRule(Rule):
    """A rule that judges across graphs: each graph tells what it knows, then one verdict.

    ``gather`` depends on its graph alone (what it returns is kept with the graph's other
    results, and may come from another process or an earlier check); ``conclude`` judges
    what every graph gathered, in the order of the check's graphs.
    """

    def gather(self, graph: LaunchGraph, ctx: RuleContext) -> object:
        """Return what this graph tells the rule (picklable)."""
        raise NotImplementedError

    def conclude(self, gathered: list[object], ctx: RuleContext) -> Iterator[Finding]:
        """Yield the findings every graph's contribution together shows."""
        raise NotImplementedError

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        gathered = ctx.memo_for(self.code).setdefault("gathered", [])
        assert isinstance(gathered, list)
        gathered.append(self.gather(graph, ctx))
        return iter(())

    def finish(self, ctx: RuleContext) -> Iterator[Finding]:
        gathered = ctx.memo_for(self.code).get("gathered", [])
        assert isinstance(gathered, list)
        return self.conclude(gathered, ctx)


class PollingRule(Rule):
    """A rule whose claims of absence are polled across every evaluation (see ``Poll``).

    Subclasses yield ``(question, finding or None)`` from ``answers`` and may still yield
    findings that need no poll from ``direct``.
    """

    def answers(self, graph: LaunchGraph, ctx: RuleContext
                ) -> Iterator[tuple[Hashable, Finding | None]]:
        """Yield this evaluation's answer to each question it can judge."""
        raise NotImplementedError

    def direct(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        """Yield findings that hold in this evaluation whatever the others say."""
        return iter(())

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        poll = Poll(ctx, self.code)
        for question, finding in self.answers(graph, ctx):
            poll.answer(question, finding)
        yield from self.direct(graph, ctx)

    def finish(self, ctx: RuleContext) -> Iterator[Finding]:
        return Poll(ctx, self.code).outcome()
