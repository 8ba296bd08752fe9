"""Strings that stand for values only known on the robot.

Python launch code needs real strings (``os.path.join(get_package_share_directory(p), ...)``,
``os.environ['ROBOT']``); where the value is not known statically we hand it a placeholder
such as ``⟨env:ROBOT⟩``. The Python frontend turns placeholders back into symbolic IR
(an environment input, a package's share folder...) when the string reaches an action.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from typing import Any, TypeVar

OPEN, CLOSE = "\u27e8", "\u27e9"
# Inside the brackets, ASCII is written in the Private Use Area: what a launch file does to
# the string (split('_'), replace('-', '_'), upper()) cannot cut a placeholder or change
# its name, and any piece of one still shows that it is a piece of an unknown.
_INSIDE = 0xE000
_WRITE = {code: _INSIDE + code for code in range(128)}
_READ = {_INSIDE + code: code for code in range(128)}
PATTERN = re.compile(OPEN + "([^" + OPEN + CLOSE + "]*)" + CLOSE)
# also escaped, as json.dumps and ascii() write them: what they give still rests on one
_MARK = re.compile("[" + OPEN + CLOSE + chr(_INSIDE) + "-" + chr(_INSIDE + 127) + "]"
                   + r"|\\u27e[89]|\\ue0[0-7][0-9a-f]", re.IGNORECASE)
KINDS = ("env", "pkg", "prefix", "arg", "opaque")


# In the varied world an unknown text holds what a launch file's code may cut it at, so
# that code relying on what it holds (``value.split('_')[1]``) behaves otherwise there;
# each separator is followed by a marked character, so that every piece cut from it is
# still a piece of an unknown (never the plain text ``'/:.-'``).
_VARIED_TEXT = "".join(sep + chr(0xE000 + ord("?")) for sep in " _/:.-,;=") * 3


def placeholder(kind: str, name: str) -> str:
    """Return the placeholder for an unknown value (``kind``: env, pkg, prefix, arg, opaque).

    Handing one to a launch file's code is an assumption about what it holds (counted).
    """
    clean = read(name).replace(OPEN, "<").replace(CLOSE, ">")  # no placeholder inside another
    inside = f"{kind}:{clean}".translate(_WRITE)
    return OPEN + inside + (_VARIED_TEXT if assumed(False, True, clean, text=True) else "") + CLOSE


def read(text: str) -> str:
    """Return text with placeholders' insides readable (``⟨env:ROBOT⟩``).

    Also where a ``repr`` in an error message escaped them (a backslash, ``ue065``).
    """
    return _ESCAPED.sub(lambda m: chr(int(m.group(1), 16)), text).translate(_READ)


_ESCAPED = re.compile(r"\\u(e0[0-7][0-9a-f])")


def parsed(match: re.Match[str]) -> tuple[str, str] | None:
    """Return (kind, name) of a ``PATTERN`` match, or ``None`` for a bracket of the user's."""
    inside = match.group(1)
    kind, colon, name = read(inside).partition(":")
    return (kind, name) if colon and kind in KINDS and inside != read(inside) else None


def environment_variable(name: str, default: str | None = None) -> str:
    """Return the placeholder for a variable of the robot's environment.

    With a default it reads as ``$(env NAME default)`` does: the default when the robot
    does not set it, which launchverify cannot know (environment names hold no ``=``).
    """
    if default is None:
        return placeholder("env", name)
    return EnvironmentText(placeholder("env", f"{name}={default}"), default)


class EnvironmentText(str):
    """A variable of the robot's environment read with a default: unknown, compared as its default.

    ``os.environ.get('ROS_DISTRO', 'humble') == 'humble'`` picks the branch a machine
    without the variable takes, as the base evaluation reads ``$(env NAME default)``, so
    the graph shows what that branch starts (not every branch's nodes). The answer is an
    assumption, though: a failure after it runs again with the other answer (the robot may
    set the variable), and is an error only if it fails there too. The text itself stays
    a placeholder: a name or path built from it is still unknown.
    """

    default: str

    def __new__(cls, text: str, default: str) -> EnvironmentText:
        made = super().__new__(cls, text)
        made.default = default
        return made

    def _answer(self, plain: bool) -> bool:
        # not a branch to explore (the graph shows the default's): only a failure runs again
        return assumed(plain, not plain, read(str(self)).strip(OPEN + CLOSE), text=True)

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, str) or has_placeholder(other):
            return str.__eq__(self, other)
        return self._answer(self.default == other)

    def __ne__(self, other: object) -> bool:
        if not isinstance(other, str) or has_placeholder(other):
            return str.__ne__(self, other)
        return self._answer(self.default != other)

    __hash__ = str.__hash__

    def __reduce__(self) -> tuple[Any, ...]:
        return EnvironmentText, (str(self), self.default)


def _keeping_default(name: str) -> Callable[..., str]:
    """Return ``str.<name>`` for an environment text: the default changes with the text."""
    method = getattr(str, name)

    def kept(self: EnvironmentText, *args: Any) -> str:
        return EnvironmentText(method(str(self), *args), method(self.default, *args))

    kept.__name__ = name
    return kept


# methods after which an environment variable's text still compares as its default would
for _name in ("lower", "upper", "casefold", "strip", "lstrip", "rstrip", "title",
              "capitalize"):
    setattr(EnvironmentText, _name, _keeping_default(_name))


def has_placeholder(text: str) -> bool:
    """Return whether a string carries a value that is not known statically (or a piece)."""
    return _MARK.search(text) is not None


@dataclass
class World:
    """Which way unknown values answer where Python wants a plain answer.

    ``bool``, ``len``, ``int``, a comparison, a loop's length: an unknown value must answer
    something. In the plain world it answers "no", "empty", "zero"; in the varied one,
    "yes", "one". Each answer is counted: an evaluation that gave none rests on no
    assumption, so a failure there is a fact without running it again.
    """

    varied: bool = False
    answers: int = 0  # assumptions made so far
    fixed: int = 0  # of which the varied world cannot vary (an unknown value's type)
    # of which the code could branch on (a truth, a length, a loop, a comparison), not
    # only the text handed out: what it built may differ with another answer
    branches: int = 0
    # what answered, in order, each once (the last few: for a finding's explanation)
    answered: dict[str, None] = field(default_factory=dict)

    def mark(self) -> tuple[int, int]:
        """Return where the counts stand, to ask later what was assumed since."""
        return self.answers, self.fixed


WORLD = World()
_T = TypeVar("_T")
_REMEMBERED = 8


def assumed(plain: _T, varied: _T, what: str = "a value", *, fixed: bool = False,
            text: bool = False) -> _T:
    """Return the answer the unknown ``what`` gives in the current world, and count it.

    ``fixed``: the answer is the same in both worlds (the varied run cannot tell);
    ``text``: only what an unknown text holds, which no code branched on yet.
    """
    WORLD.answers += 1
    WORLD.fixed += fixed
    WORLD.branches += not text
    answered = WORLD.answered
    answered.pop(what, None)
    answered[what] = None
    if len(answered) > _REMEMBERED:
        del answered[next(iter(answered))]
    return varied if WORLD.varied else plain


@contextmanager
def varied_world() -> Iterator[None]:
    """Run a block with every unknown value answering the other way."""
    saved = WORLD.varied
    WORLD.varied = True
    try:
        yield
    finally:
        WORLD.varied = saved


class UnknownMapping(dict):  # type: ignore[type-arg]
    """YAML content only the robot has: any key gives an unknown value, a loop no round."""

    def __missing__(self, key: object) -> object:
        from launchverify.models.launch_api.unknown import Opaque

        return Opaque(f"{key} in a file only the robot has")

    def get(self, key: object, default: object = None) -> object:
        return self[key]

    def __bool__(self) -> bool:
        return assumed(False, True, "the content of a file only the robot has")

    def __contains__(self, key: object) -> bool:
        return assumed(False, True, "the content of a file only the robot has")

    # which keys it holds no run can say (a loop over them runs no round in either world)
    def __iter__(self) -> Iterator[Any]:
        _keys_asked()
        return super().__iter__()

    def __len__(self) -> int:
        _keys_asked()
        return super().__len__()

    def keys(self) -> Any:
        _keys_asked()
        return super().keys()

    def values(self) -> Any:
        _keys_asked()
        return super().values()

    def items(self) -> Any:
        _keys_asked()
        return super().items()


def _keys_asked() -> None:
    assumed(None, None, "which keys a file only the robot has holds", fixed=True)
