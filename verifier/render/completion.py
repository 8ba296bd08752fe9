"""Shell completion scripts, written from the command line's own parser.

``launchverify completion bash|zsh|fish`` prints a script that completes subcommands,
each subcommand's options, the values of options with choices (``--format``,
``--distro``...), rule codes after ``--select``/``--ignore`` and ``explain``, and paths
everywhere else. Generated from ``build_parser()``: a new option completes without
touching this module.
"""

from __future__ import annotations

import argparse
from dataclasses import dataclass, field

RULE_OPTIONS = ("--select", "--ignore")


@dataclass
class Command:
    """What completes after one subcommand."""

    name: str
    help: str
    options: list[str] = field(default_factory=list)
    choices: dict[str, list[str]] = field(default_factory=dict)  # option -> its values
    flags: set[str] = field(default_factory=set)  # options that take no value


def commands_of(parser: argparse.ArgumentParser) -> list[Command]:
    """Return the subcommands of a parser with their options."""
    found: list[Command] = []
    for action in parser._actions:  # argparse exposes subparsers only this way
        if not isinstance(action, argparse._SubParsersAction):
            continue
        helps = {choice.dest: choice.help or "" for choice in action._choices_actions}
        for name, sub in action.choices.items():
            command = Command(name, helps.get(name, ""))
            for option in sub._actions:
                if not option.option_strings:
                    continue
                command.options.extend(option.option_strings)
                if option.nargs == 0:
                    command.flags.update(option.option_strings)
                if option.choices:
                    for string in option.option_strings:
                        command.choices[string] = [str(c) for c in option.choices]
            found.append(command)
    return found


def completion_script(shell: str, parser: argparse.ArgumentParser, codes: list[str]) -> str:
    """Return the completion script of a shell."""
    commands = commands_of(parser)
    if shell == "fish":
        return _fish(commands, codes)
    script = _bash(commands, codes)
    if shell == "zsh":  # zsh runs bash completions through bashcompinit
        return "autoload -U +X bashcompinit && bashcompinit\n" + script
    return script


def _bash(commands: list[Command], codes: list[str]) -> str:
    cases = []
    for command in commands:
        values = []
        for option, choices in sorted(command.choices.items()):
            values.append(f'            {option}) COMPREPLY=($(compgen -W "{" ".join(choices)}" '
                          '-- "$cur")); return;;')
        for option in RULE_OPTIONS:
            if option in command.options:
                values.append(f'            {option}) COMPREPLY=($(compgen -W "$codes" -- "$cur"'
                              ')); return;;')
        cases.append(
            f"        {command.name})\n"
            f'            case "$prev" in\n' + "\n".join(values) + ("\n" if values else "")
            + "            esac\n"
            f'            options="{" ".join(command.options)}";;')
    names = " ".join(c.name for c in commands)
    return f"""# launchverify completion for bash (eval "$(launchverify completion bash)")
_launchverify() {{
    local cur prev command options codes
    cur="${{COMP_WORDS[COMP_CWORD]}}"
    prev="${{COMP_WORDS[COMP_CWORD-1]}}"
    command="${{COMP_WORDS[1]}}"
    codes="{" ".join(codes)}"
    if [ "$COMP_CWORD" -eq 1 ]; then
        COMPREPLY=($(compgen -W "{names} --version --help" -- "$cur")); return
    fi
    if [ "$command" = explain ]; then COMPREPLY=($(compgen -W "$codes" -- "$cur")); return; fi
    case "$command" in
{chr(10).join(cases)}
    esac
    if [[ "$cur" == -* ]]; then
        COMPREPLY=($(compgen -W "$options" -- "$cur"))
    else
        COMPREPLY=($(compgen -f -- "$cur"))
    fi
}}
complete -o filenames -F _launchverify launchverify
"""


def _fish(commands: list[Command], codes: list[str]) -> str:
    names = " ".join(c.name for c in commands)
    lines = ["# launchverify completion for fish (launchverify completion fish | source)",
             f"complete -c launchverify -n __fish_use_subcommand -f -a '{names}'"]
    for command in commands:
        when = f"__fish_seen_subcommand_from {command.name}"
        lines.append(f"complete -c launchverify -n '__fish_use_subcommand' -a {command.name} "
                     f"-d {_quote(command.help)}")
        for option in command.options:
            if not option.startswith("--"):
                continue
            long = option[2:]
            extra = ""
            if option in command.choices:
                extra = f" -x -a '{' '.join(command.choices[option])}'"
            elif option in RULE_OPTIONS:
                extra = f" -x -a '{' '.join(codes)}'"
            elif option not in command.flags:
                extra = " -r"
            lines.append(f"complete -c launchverify -n '{when}' -l {long}{extra}")
        if command.name == "explain":
            lines.append(f"complete -c launchverify -n '{when}' -f -a '{' '.join(codes)}'")
    return "\n".join(lines) + "\n"


def _quote(text: str) -> str:
    return "'" + text.replace("\\", "\\\\").replace("'", "\\'") + "'"
