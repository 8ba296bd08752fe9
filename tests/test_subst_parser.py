"""The ``$(...)`` grammar of the XML/YAML frontends, checked against ros2/launch's grammar.lark.

Tables pin the accepted language (one space between arguments, quoting, escapes, nesting)
and the refusals (unknown names with ROS 1 hints, arity, unclosed constructs); properties
check plain text, robustness on arbitrary input, and that ``describe()`` reads back.
"""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from launchverify.frontends.subst_parser import (
    MAX_DEPTH,
    SubstitutionSyntaxError,
    parse_substitution,
    unescape,
)
from launchverify.ir import subst as s

T = s.Text
LC = s.LaunchConfig


# --------------------------------------------------------------------------- accepted


VALID = [
    ("", s.EMPTY),
    ("plain text", T("plain text")),
    ("$(var a)", LC(T("a"))),
    ("$(var a b)", LC(T("a"), T("b"))),
    ("prefix/$(var ns)/suffix", s.Concat((T("prefix/"), LC(T("ns")), T("/suffix")))),
    ("$(var a) $(env B c)", s.Concat((LC(T("a")), T(" "), s.EnvVar(T("B"), T("c"))))),
    ("$(var a)$(var b)", s.Concat((LC(T("a")), LC(T("b"))))),
    # quoted arguments keep their spaces and still parse nested substitutions
    ("$(var 'a b')", LC(T("a b"))),
    ('$(var "a b")', LC(T("a b"))),
    ("$(var 'a $(var b)')", LC(s.Concat((T("a "), LC(T("b")))))),
    ('$(var "x $(env HOME) y")', LC(s.Concat((T("x "), s.EnvVar(T("HOME")), T(" y"))))),
    ("$(var '')", LC(s.EMPTY)),
    ('$(var "")', LC(s.EMPTY)),
    ("$(var a '')", LC(T("a"), s.EMPTY)),
    ('$(var "it\'s")', LC(T("it's"))),
    ("$(var 'say \"hi\"')", LC(T('say "hi"'))),
    (r"$(var 'x\'y')", LC(T("x'y"))),
    ("$(eval '1 + 2 == 3')", s.PythonExpr(T("1 + 2 == 3"))),
    ("$(eval \"'$(var a)' == 'b'\")",
     s.PythonExpr(s.Concat((T("'"), LC(T("a")), T("' == 'b'"))))),
    # unquoted arguments mix text and nested substitutions
    ("$(var a$(var b))", LC(s.Concat((T("a"), LC(T("b")))))),
    ("$(var $(var a)_suffix)", LC(s.Concat((LC(T("a")), T("_suffix"))))),
    ("$(var a\\ b)", LC(T("a b"))),
    # backslash escapes are removed; an escaped `$(` is literal
    (r"\$(var a)", T("$(var a)")),
    (r"cost \$(5)", T("cost $(5)")),
    (r"a\b", T("ab")),
    (r"a\\b", T("a\\b")),
    ("\\", T("\\")),
    ("trailing\\", T("trailing\\")),
    (r"$(var 'a\$(b')", LC(T("a$(b"))),
    # `$` not followed by `(` is literal, and so are parentheses and quotes outside
    ("$", T("$")),
    ("$$", T("$$")),
    ("a$b", T("a$b")),
    ("5$ (var a)", T("5$ (var a)")),
    ("a)b(c", T("a)b(c")),
    ("it's \"quoted\"", T("it's \"quoted\"")),
    ("$(var a)b)", s.Concat((LC(T("a")), T("b)")))),
    # every name of the table
    ("$(env HOME)", s.EnvVar(T("HOME"))),
    ("$(command 'ls -l' warn)", s.Command(T("ls -l"), T("warn"))),
    ("$(find-exec ls)", s.FindExecutable(T("ls"))),
    ("$(find-pkg-share pkg)/launch/x.py",
     s.Concat((s.FindPackageShare(T("pkg")), T("/launch/x.py")))),
    ("$(find-pkg-prefix pkg)", s.FindPackagePrefix(T("pkg"))),
    ("$(exec-in-pkg talker demo)", s.ExecutableInPackage(T("talker"), T("demo"))),
    ("$(filename)", s.ThisLaunchFile()),
    ("$(dirname)", s.ThisLaunchFileDir()),
    ("$(log_dir)", s.LaunchLogDir()),
    ("$(launch_log_dir)", s.LaunchLogDir()),
    ("$(anon node)", s.AnonName(T("node"))),
    ("$(not $(var a))", s.NotSub(LC(T("a")))),
    ("$(and a b)", s.AndSub(T("a"), T("b"))),
    ("$(or a b)", s.OrSub(T("a"), T("b"))),
    ("$(any)", s.AnySub(())),
    ("$(any a b c)", s.AnySub((T("a"), T("b"), T("c")))),
    ("$(all a)", s.AllSub((T("a"),))),
    ("$(equals $(var a) sim)", s.EqualsSub(LC(T("a")), T("sim"))),
    ("$(not-equals a b)", s.NotEqualsSub(T("a"), T("b"))),
    ("$(if c x y)", s.IfElse(T("c"), T("x"), T("y"))),
    ("$(if c x)", s.IfElse(T("c"), T("x"), s.EMPTY)),
    ("$(file-content f.txt)", s.FileContent(T("f.txt"))),
    ("$(param use_sim_time false)", s.RosParameter(T("use_sim_time"), T("false"))),
    ("$(for-var i)", s.ForEachVar(T("i"))),
    ("$(index i)", s.ForLoopIndex(T("i"))),
    ("$(string-join , a b)", s.StringJoin(T(","), (T("a"), T("b")))),
]


@pytest.mark.parametrize(("text", "expected"), VALID, ids=[v[0] or "<empty>" for v in VALID])
def test_parses(text: str, expected: s.Sub) -> None:
    assert parse_substitution(text) == expected


def test_nesting_up_to_the_limit_is_accepted() -> None:
    depth = MAX_DEPTH
    text = "$(var " * depth + "x" + ")" * depth
    result = parse_substitution(text)
    for _ in range(depth):
        assert isinstance(result, s.LaunchConfig)
        result = result.name
    assert result == T("x")


# --------------------------------------------------------------------------- refused


INVALID = [
    # exactly one space between arguments
    ("$(var  a)", "exactly one space", 6),
    ("$(var a )", "exactly one space", 8),
    ("$(var a  b)", "exactly one space", 8),
    ("$(var\ta)", "unexpected '\\t'", 5),
    # unknown names; ROS 1 spellings get a hint
    ("$(bogus x)", "unknown substitution $(bogus)", 0),
    ("$(Var a)", "unknown substitution $(Var)", 0),
    ("$(arg a)", "ROS 2 uses $(var)", 0),
    ("$(find pkg)", "ROS 2 uses $(find-pkg-share)", 0),
    ("$(optenv X)", "ROS 2 uses $(env NAME default)", 0),
    ("x $(arg a)", "unknown substitution $(arg)", 2),
    # arity
    ("$(var)", "expects 1 to 2 argument(s), got 0", 0),
    ("$(var a b c)", "expects 1 to 2 argument(s), got 3", 0),
    ("$(exec-in-pkg a)", "expects 2 argument(s), got 1", 0),
    ("$(filename x)", "expects 0 argument(s), got 1", 0),
    ("$(string-join a)", "expects at least 2 argument(s), got 1", 0),
    ("$(not)", "expects 1 argument(s), got 0", 0),
    ("$(var $(var))", "$(var) expects", 6),
    # unclosed substitutions and quotes
    ("$(var a", "unclosed substitution $(var", 0),
    ("ab $(var a", "unclosed substitution $(var", 3),
    ("$(var", "unclosed substitution $(var", 0),
    ("$(var 'a)", "unclosed quote", 6),
    ('$(var "a)', "unclosed quote", 6),
    ("$(var 'a $(var b)", "unclosed quote", 6),
    # malformed
    ("$(", "expected a substitution name", 2),
    ("$()", "expected a substitution name", 2),
    ("$( var a)", "expected a substitution name", 2),
    ("$(1var a)", "expected a substitution name", 2),
    ("$(var 'a'b)", "quoted argument must stand alone", 9),
    ("$(var a(b)", "unexpected '('", 7),
    ("$(var a'b)", "unexpected \"'\"", 7),
]


@pytest.mark.parametrize(("text", "fragment", "offset"), INVALID, ids=[v[0] for v in INVALID])
def test_refuses(text: str, fragment: str, offset: int) -> None:
    with pytest.raises(SubstitutionSyntaxError) as caught:
        parse_substitution(text)
    assert fragment in str(caught.value)
    assert caught.value.offset == offset


def test_unknown_name_without_ros1_spelling_has_no_hint() -> None:
    with pytest.raises(SubstitutionSyntaxError) as caught:
        parse_substitution("$(bogus x)")
    assert "ROS 1" not in str(caught.value)


def test_syntax_error_is_a_value_error() -> None:
    assert issubclass(SubstitutionSyntaxError, ValueError)


def test_nesting_beyond_the_limit_is_an_error_not_a_crash() -> None:
    depth = MAX_DEPTH + 5
    with pytest.raises(SubstitutionSyntaxError, match="nested too deeply"):
        parse_substitution("$(var " * depth + "x" + ")" * depth)
    with pytest.raises(SubstitutionSyntaxError):
        parse_substitution("$(var " * 10_000)


# --------------------------------------------------------------------------- unescape


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("", ""),
        ("plain", "plain"),
        (r"a\,b", "a,b"),
        (r"\$(var a)", "$(var a)"),
        (r"a\\b", "a\\b"),
        ("x\\", "x\\"),
        ("\\", "\\"),
        (r"\\\\", "\\\\"),
        ("$(var a)", "$(var a)"),
    ],
)
def test_unescape(text: str, expected: str) -> None:
    assert unescape(text) == expected


# --------------------------------------------------------------------------- properties


@given(st.text(alphabet=st.characters(blacklist_characters="$\\")))
@settings(max_examples=200, deadline=None)
def test_text_without_dollar_or_backslash_is_itself(text: str) -> None:
    assert parse_substitution(text) == T(text)


GRAMMAR_PIECES = st.sampled_from(
    ["$(", "$", "(", ")", " ", "  ", "'", '"', "\\", "var", "env", "eval", "if", "any",
     "string-join", "exec-in-pkg", "arg", "a", "x y", "\t", "\n", "é", "\x00"]
)
ANY_TEXT = st.one_of(st.text(), st.lists(GRAMMAR_PIECES, max_size=20).map("".join))


@given(ANY_TEXT)
@settings(max_examples=200, deadline=None)
def test_arbitrary_text_parses_or_raises_syntax_error(text: str) -> None:
    try:
        result = parse_substitution(text)
    except SubstitutionSyntaxError as error:
        assert 0 <= error.offset <= len(text)
    else:
        assert isinstance(result, s.Sub)


@given(ANY_TEXT)
@settings(max_examples=200, deadline=None)
def test_unescape_never_grows_text(text: str) -> None:
    assert len(unescape(text)) <= len(text)


IDENT = st.from_regex(r"[A-Za-z_][A-Za-z0-9_]{0,7}", fullmatch=True)


def _expressions() -> st.SearchStrategy[s.Sub]:
    """Trees of Text / LaunchConfig / EnvVar / NotSub / EqualsSub with identifier texts.

    Empty text is included (it is spelt ``''``). Texts needing quotes (spaces, quotes,
    ``$``...) are left out: a quoted argument holding a substitution whose own argument
    needs quotes has no spelling in the grammar (see the test below).
    """
    leaf = st.one_of(IDENT.map(T), st.just(s.EMPTY))

    def extend(inner: st.SearchStrategy[s.Sub]) -> st.SearchStrategy[s.Sub]:
        optional = st.none() | inner
        return st.one_of(
            st.builds(s.LaunchConfig, inner, optional),
            st.builds(s.EnvVar, inner, optional),
            st.builds(s.NotSub, inner),
            st.builds(s.EqualsSub, inner, inner),
            st.lists(inner, min_size=2, max_size=3).map(s.concat),
        )

    return st.recursive(leaf, extend, max_leaves=12)


@given(_expressions())
@settings(max_examples=200, deadline=None)
def test_describe_reads_back(expression: s.Sub) -> None:
    expected = s.concat([expression])
    assert parse_substitution(expression.describe()) == expected


@pytest.mark.parametrize(
    "expression",
    [
        s.LaunchConfig(s.Concat((T("a b"), s.LaunchConfig(T("c d"))))),
        s.LaunchConfig(s.Concat((T(" "), s.LaunchConfig(s.EMPTY)))),
    ],
)
def test_nested_quoted_arguments_have_no_spelling(expression: s.Sub) -> None:
    # The grammar cannot quote inside a quoted argument; describe() gives display text.
    with pytest.raises(SubstitutionSyntaxError):
        parse_substitution(expression.describe())


def test_describe_escapes_top_level_text() -> None:
    expression = s.concat([T("C:\\dir$("), s.LaunchConfig(T("a"))])
    assert parse_substitution(expression.describe()) == expression
