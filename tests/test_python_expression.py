"""The side-effect-free ``$(eval)`` model against Python's own ``eval``.

launch runs ``str(eval(text, {}, {**vars(math), 'math': math}))``. The model must give the
same text for what launch files really write, report Python's own error when Python would
raise, and refuse (never run) anything outside its subset, quickly and without side effects.
"""

from __future__ import annotations

import math
import subprocess
import sys
import time
import tracemalloc
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from launchverify.models.python_expression import (
    MAX_SIZE,
    ExpressionError,
    Unsupported,
    evaluate_expression,
)

MATH_LOCALS = {**vars(math), "math": math}


def python_eval(text: str) -> str:
    """What launch's PythonExpression computes (only ever called on harmless text)."""
    return str(eval(text, {}, dict(MATH_LOCALS)))


# --------------------------------------------------------------------------- agreement


REAL_EXPRESSIONS = [
    # comparisons on substituted strings
    "'sim' == 'sim'",
    "'sim' == 'real'",
    "'a' != 'b'",
    "'True' == 'true'",
    "'True'.lower() == 'true'",
    "'  Sim '.strip().lower() == 'sim'",
    "'TRUE'.lower()",
    "'ab'.upper()",
    "'a,b,c'.split(',')",
    "'robot_1'.replace('_', '/')",
    "'camera_front'.startswith('camera')",
    "'x.yaml'.endswith('.yaml')",
    "'/'.join(['a', 'b'])",
    "'7'.isdigit()",
    "'3'.zfill(3)",
    # boolean logic
    "True and False",
    "True or False",
    "not True",
    "not False and True",
    "'' or 'default'",
    "'set' and 'used'",
    "0 or ''",
    "not ''",
    # ordering and membership
    "1 < 2",
    "3 >= 3",
    "1 < 2 < 3",
    "3 > 2 > 2",
    "2 == 2.0",
    "'a' in 'abc'",
    "'x' not in ['a', 'b']",
    "'b' in ('a', 'b')",
    "'k' in {'k': 1}",
    "None is None",
    "None is not None",
    # arithmetic
    "1 + 2 * 3",
    "(1 + 2) * 3",
    "7 / 2",
    "7 // 2",
    "-7 // 2",
    "7 % 3",
    "2 ** 10",
    "10 ** -2",
    "-5",
    "+5",
    "0.1 + 0.2",
    "0.5 == 1 / 2",
    "abs(-3)",
    "round(2.567, 2)",
    "round(2.5)",
    "max(1, 5, 3)",
    "min([4, 2])",
    "True + True",
    # math, with and without the module name
    "math.pi",
    "pi",
    "2 * pi",
    "e",
    "inf",
    "math.sqrt(16)",
    "math.radians(180)",
    "math.cos(0)",
    "math.floor(2.5)",
    "math.ceil(2.1)",
    "math.degrees(pi / 2)",
    "sqrt(2)",
    # conditional expressions
    "'yes' if True else 'no'",
    "1 if 0 else 2",
    "'a' if 'x' == 'y' else 'b'",
    "1 if 0 else 2 if 1 else 3",
    # conversions and containers
    "len('abc')",
    "len([1, 2, 3]) > 2",
    "int('3')",
    "int('3') + 1",
    "float('1.5')",
    "float('inf')",
    "str(5) + 'm'",
    "str(True).lower()",
    "bool('')",
    "bool('false')",
    "'%s_%d' % ('robot', 1)",
    "'x' * 3",
    "[1, 2][0]",
    "'abc'[1:]",
    "'abc'[::-1]",
    "{'a': 1}['a']",
    "(1, 2)",
    "[1, 'a']",
    "{1}",
    "sorted([3, 1, 2])",
    "any([False, True])",
    "all([])",
    "tuple([1])",
    "list('ab')",
    "None",
    "True",
    "'a' 'b'",
    "  1 + 1  ",
]


@pytest.mark.parametrize("text", REAL_EXPRESSIONS)
def test_matches_python(text: str) -> None:
    assert evaluate_expression(text) == python_eval(text.strip())


def test_docstring_examples() -> None:
    assert evaluate_expression("'a' + 'b' == 'ab'") == "True"
    assert evaluate_expression("pi > 3") == "True"


def test_explicit_math_module_only() -> None:
    assert evaluate_expression("math.pi", modules=["math"]) == str(math.pi)


def test_without_modules_math_names_are_undefined() -> None:
    with pytest.raises(ExpressionError, match="NameError"):
        evaluate_expression("pi", modules=[])
    assert evaluate_expression("1 + 1", modules=[]) == "2"


@pytest.mark.parametrize("module", ["os", "subprocess", "numpy"])
def test_other_modules_are_not_modelled(module: str) -> None:
    with pytest.raises(Unsupported):
        evaluate_expression("1", modules=[module])


# --------------------------------------------------------------------------- Python errors


ERRORS = [
    ("os.path.exists('/x')", "NameError: name 'os' is not defined"),
    ("undefined_name", "NameError: name 'undefined_name' is not defined"),
    ("1 / 0", "ZeroDivisionError"),
    ("5 % 0", "ZeroDivisionError"),
    ("int('x')", "ValueError"),
    ("float('abc')", "ValueError"),
    ("'a' + 1", "TypeError"),
    ("'a' < 1", "TypeError"),
    ("[1][5]", "IndexError"),
    ("{}['k']", "KeyError"),
    ("math.nope", "AttributeError"),
    ("math.exp(1000)", "OverflowError"),
    ("1 +", "SyntaxError"),
    ("", "SyntaxError"),
    ("x = 1", "SyntaxError"),
    ("'unterminated", "SyntaxError"),
    ("1\x00", "SyntaxError"),
]


@pytest.mark.parametrize(("text", "message"), ERRORS, ids=[e[0] for e in ERRORS])
def test_python_errors_are_reported_as_python_reports_them(text: str, message: str) -> None:
    with pytest.raises(ExpressionError) as caught:
        evaluate_expression(text)
    assert str(caught.value).startswith(message)
    if "\x00" not in text:  # eval itself names the same exception
        with pytest.raises(Exception) as python_error:
            python_eval(text)
        assert str(caught.value).startswith(type(python_error.value).__name__)


# --------------------------------------------------------------------------- hostile input


HOSTILE = [
    "__import__('os').system('touch {marker}')",
    "__import__('subprocess').call(['touch', '{marker}'])",
    "open('{marker}', 'w')",
    "eval(\"open('{marker}', 'w')\")",
    "exec(\"open('{marker}', 'w')\")",
    "globals()",
    "getattr(1, 'real')",
    "().__class__",
    "().__class__.__bases__",
    "().__class__.__bases__[0].__subclasses__()",
    "''.__class__.__mro__[1].__subclasses__()",
    "(1).__class__",
    "str.__class__",
    "math.__class__.__init__.__globals__",
    "math.__getattr__('pi')",
    "math.sys",
    "'{0.__class__}'.format(1)",
    "str.format('{0.__class__}', 1)",
    "'{}'.format",
    "f'{1}'",
    "lambda: 1",
    "(lambda: 1)()",
    "(lambda: __import__('os').system('touch {marker}'))()",
    "[x for x in 'abc']",
    "{x for x in 'abc'}",
    "{x: 1 for x in 'abc'}",
    "(x for x in 'abc')",
    "' '.join(str(i) for i in [1])",
    "(y := 1)",
    "~1",
    "1 << 100000000",
    "9**9**9",
    "10**10**10",
    "2.0 ** 2000",
    "'a'*10**9",
    "'a' * 10**5 * 10**5",
    "[0]*10**9",
    "('a' * 1000) * 1000",
    "'a'.ljust(10**9)",
    "sorted([1], key=lambda x: x)",
    "max(*[1, 2])",
    "dict(**{'a': 1})",
    "-" * 400 + "1",
    "+".join(["1"] * 1000),
]


@pytest.mark.parametrize("template", HOSTILE, ids=range(len(HOSTILE)))
def test_hostile_input_is_refused_quickly_and_runs_nothing(template: str, tmp_path: Path) -> None:
    marker = tmp_path / "lv_pwned"
    text = template.replace("{marker}", str(marker))
    # run, each would take minutes or gigabytes: refused, it takes this process's CPU
    # for a moment (CPU, not the wall clock, which other processes' load stretches)
    start = time.process_time()
    with pytest.raises((Unsupported, ExpressionError)):
        evaluate_expression(text)
    assert time.process_time() - start < 1.0
    assert not marker.exists()


def test_touch_tmp_lv_pwned_does_not_run(tmp_path: Path) -> None:
    target = tmp_path / "lv_pwned"  # the test's own: a shared /tmp path races other runs
    with pytest.raises((Unsupported, ExpressionError)):
        evaluate_expression(f"__import__('os').system('touch {target}')")
    assert not target.exists()


@pytest.mark.parametrize("text", ["math.__class__", "math.__dict__", "math.__doc__"])
def test_dunder_attributes_of_math_are_refused(text: str) -> None:
    with pytest.raises((Unsupported, ExpressionError)):
        evaluate_expression(text)


@pytest.mark.parametrize("text", ["-" * 100_000 + "1", "not " * 50_000 + "1", "'\ud800'"],
                         ids=["deep-minus", "deep-not", "surrogate"])
def test_parser_failures_stay_inside_the_model(text: str) -> None:
    with pytest.raises((Unsupported, ExpressionError)):
        evaluate_expression(text)


@pytest.mark.parametrize("text", ["len(range(3))", "isinstance(1, int)", "sum([1, 2])",
                                  "hex(255)"])
def test_unmodelled_builtins_are_unsupported_not_name_errors(text: str) -> None:
    try:
        result = evaluate_expression(text)
    except Unsupported:
        return
    assert result == python_eval(text)


def _peak_bytes(text: str) -> int:
    tracemalloc.start()
    try:
        with pytest.raises((Unsupported, ExpressionError)):
            evaluate_expression(text)
        return tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()


@pytest.mark.parametrize(
    "text",
    ["10**8 * 'a'", "'a'.zfill(10**8)", "'%0100000000d' % 1",
     "'x'.join(['a' * 100000] * 1000)"],
)
def test_large_results_are_refused_before_they_are_built(text: str) -> None:
    assert _peak_bytes(text) < 32 * 1024 * 1024


def test_large_non_string_results_are_refused() -> None:
    try:
        result = evaluate_expression("[[0] * 1000] * 1000")
    except Unsupported:
        return
    assert len(result) <= MAX_SIZE


def _finishes_within(text: str, seconds: float) -> bool:
    code = (
        "from launchverify.models.python_expression import evaluate_expression\n"
        "try:\n"
        f"    evaluate_expression({text!r})\n"
        "except Exception:\n"
        "    pass\n"
    )
    try:
        done = subprocess.run([sys.executable, "-c", code], check=False, timeout=seconds,
                              capture_output=True, text=True)
    except subprocess.TimeoutExpired:
        return False
    if done.returncode != 0:  # not the bug under test: must not count as the expected failure
        raise RuntimeError(done.stderr)
    return True


@pytest.mark.parametrize("text", ["math.factorial(10**7)", "((((10**64)**64)**64)**64)**64"])
def test_expensive_expressions_finish_quickly(text: str) -> None:
    assert _finishes_within(text, seconds=2.0), f"{text} still running after 2 s"


# --------------------------------------------------------------------------- property


def _small_int_expressions() -> st.SearchStrategy[str]:
    leaf = st.integers(-20, 20).map(lambda i: f"({i})")

    def extend(inner: st.SearchStrategy[str]) -> st.SearchStrategy[str]:
        binary = st.sampled_from(["+", "-", "*", "/", "//", "%"])
        compare = st.sampled_from(["==", "!=", "<", "<=", ">", ">="])
        return st.one_of(
            st.tuples(inner, binary, inner).map(lambda t: f"({t[0]} {t[1]} {t[2]})"),
            st.tuples(inner, compare, inner).map(lambda t: f"({t[0]} {t[1]} {t[2]})"),
            st.tuples(inner, compare, inner, compare, inner).map(
                lambda t: f"({t[0]} {t[1]} {t[2]} {t[3]} {t[4]})"
            ),
            st.tuples(inner, st.integers(0, 4)).map(lambda t: f"({t[0]} ** {t[1]})"),
            st.tuples(inner, st.sampled_from(["and", "or"]), inner).map(
                lambda t: f"({t[0]} {t[1]} {t[2]})"
            ),
            inner.map(lambda x: f"(not {x})"),
            inner.map(lambda x: f"(-{x})"),
            st.tuples(inner, inner, inner).map(lambda t: f"({t[0]} if {t[1]} else {t[2]})"),
        )

    return st.recursive(leaf, extend, max_leaves=10)


def _outcome_of_python(text: str) -> tuple[str, str]:
    try:
        return ("value", python_eval(text))
    except Exception as error:
        return ("error", type(error).__name__)


def _outcome_of_model(text: str) -> tuple[str, str]:
    try:
        return ("value", evaluate_expression(text))
    except ExpressionError as error:
        return ("error", str(error).split(":")[0])


@given(_small_int_expressions())
@settings(max_examples=300, deadline=None)
def test_small_integer_expressions_match_python(text: str) -> None:
    assert _outcome_of_model(text) == _outcome_of_python(text)
