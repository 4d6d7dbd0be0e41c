"""The ``mkm`` command line: one module per command group, each only parses arguments and calls
one library function.

Bad input (a ``ValueError`` from the library or a malformed argument) prints one line
``mkm <command>: error: ...`` and exits with status 2, without a traceback.
"""

from __future__ import annotations

import argparse
import difflib
import errno
import io
import os
import re
import sys
import warnings

from mkm.cli import (
    bench,
    data,
    demo,
    design,
    exchange,
    fem,
    identify,
    models,
    surrogate,
    validation,
)
from mkm.cli.common import command_name, error_line, remember_command, say
from mkm.core.records import HeldOpen


class _Version(argparse.Action):
    """``--version``: the installed version, read only when asked (it costs a metadata scan)."""

    def __init__(self, option_strings, dest=argparse.SUPPRESS, **kwargs):
        super().__init__(option_strings, dest, nargs=0, help="show the version and exit",
                         **kwargs)

    def __call__(self, parser, namespace, values, option_string=None):
        from mkm import __version__

        parser.exit(0, f"mkm {__version__}\n")


class _Parser(argparse.ArgumentParser):
    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        # "-5%" and "-1,0" are values (reported as bad values), not unknown options; argparse
        # only treats plain negative numbers so and has no public setting for it
        self._negative_number_matcher = re.compile(r"^-\.?\d")

    def parse_known_args(self, args=None, namespace=None):
        # the words this parser was given, for its error's hint (a subcommand's parser is
        # given its own words by argparse, through this method)
        self.typed = list(sys.argv[1:] if args is None else args)
        namespace, rest = super().parse_known_args(args, namespace)
        if rest and not getattr(namespace, "_mkm_split_list", None):  # the innermost's words
            first = next((k for k in reversed(range(len(self.typed)))
                          if self.typed[k:k + len(rest)] == rest), len(self.typed))
            namespace._mkm_split_list = self._list_split(first, alike=True)
        remember_command(namespace, self.prog)
        return namespace, rest

    def error(self, message):  # one line, no usage dump
        option = re.match(r"(?:argument )?(--[\w-]+)", message)
        typed = getattr(self, "typed", [])
        # an option's bad value followed by words the command takes no positional for
        split = (self._list_split(typed.index(option[1]) + 2)
                 if option and option[1] in typed
                 and all(a.option_strings for a in self._actions) else "")
        self.exit(2, error_line(self.prog, message + self._commands_expected(message)
                                + self._runs_expected(message) + _did_you_mean(message))
                  + split + "\n")

    def _list_split(self, at: int, alike: bool = False) -> str:
        """Where the words typed from ``at`` on follow the value of an option that takes a
        comma list (``--masses 0 5 10``): that list as one quoted word. PowerShell passes an
        unquoted comma list (``0,5,10``) to a program as separate words, which argparse then
        refuses as arguments nobody takes (or takes the first alone). ``alike``: only where
        each word is of the value's kind, a number's or a name's (``--eps 0 extra`` is a stray
        word, not a list)."""
        typed = getattr(self, "typed", [])
        words = []
        for word in typed[at:]:
            if word.startswith("-") and not self._negative_number_matcher.match(word):
                break
            words.append(word)
        action = self._option_string_actions.get(typed[at - 2]) if 2 <= at <= len(typed) \
            else None
        if not words or action is None or typed[at - 1].startswith("-") or not (
                "," in str(action.metavar or "") or "comma" in str(action.help or "")):
            return ""
        numeric = re.compile(r"[+-]?\.?\d")
        if alike and any(bool(numeric.match(w)) != bool(numeric.match(typed[at - 1]))
                         for w in words):
            return ""
        listed = ",".join([typed[at - 1], *words])
        return (f"; a comma list is one word: {typed[at - 2]} \"{listed}\" (PowerShell passes "
                "an unquoted one as separate words: quote it)")

    def _runs_expected(self, message: str) -> str:
        """For a command typed without its run folders (``mkm report``): what they are, and
        the runs mkm's own folders here hold (``mkm acquire``'s, ``mkm demo``'s), as a line to
        type: argparse names only the metavar."""
        missing = message.partition("the following arguments are required: ")[2].split(", ")
        action = next((a for a in self._actions if not a.option_strings
                       and (a.metavar or a.dest) in missing
                       and (a.metavar == "RUN_DIR" or a.dest == "run")), None)
        if action is None:
            return ""
        from mkm.bench.folders import runs_inside
        from mkm.paths import default_out

        several = action.nargs == "+"
        said = (': expected run folders, as `mkm acquire` or `mkm import` prints them last, a '
                'folder of them or a pattern ("runs/*")' if several else
                ": expected a run folder, as `mkm acquire` or `mkm import` prints it last")
        if len(missing) > 1:  # `mkm reprocess` without its --config either: no line to type
            return said
        for folder in (default_out("runs"), default_out("demo", "runs")):
            runs = runs_inside(folder) if folder.is_dir() else []
            if runs:
                named = str(folder if several else runs[-1])
                named = f'"{named}"' if " " in named else named  # as every shell takes it
                return (f"{said}; {folder} holds {len(runs)}: `{self.prog} {named}`"
                        f"{'' if several else ' (the newest)'}")
        return f"{said}; none is in {default_out('runs')}: `mkm demo` records two"

    def _commands_expected(self, message: str) -> str:
        """For a group typed without its command (``mkm data``): the commands it takes, from
        its own subparsers, and where each is described."""
        for action in self._actions:
            if isinstance(action, argparse._SubParsersAction) and \
                    message.endswith(f"required: {action.metavar}"):
                return (f": expected one of {', '.join(action.choices)} (`{self.prog} --help` "
                        "says what each does)")
        return ""


def _did_you_mean(message: str) -> str:
    """For a value not among an argument's choices (``mkm idenitfy``): the closest choice, if
    one is close (:func:`difflib.get_close_matches`' default cutoff), read from argparse's
    message (its choices quoted or not, as Python versions write them)."""
    said = re.search(r"invalid choice: '([^']*)' \(choose from (.*)\)$", message)
    if not said:
        return ""
    choices = [c.strip().strip("'") for c in said[2].split(",")]
    close = difflib.get_close_matches(said[1], choices, n=1)
    return f": did you mean '{close[0]}'?" if close else ""


def _notes(args):
    """Warnings as a user reads them: one line, no source path (the library's own words), each
    said once (a note a model gives for every run of a report is one fact)."""
    said: set[str] = set()

    def show(message, category, filename, lineno, file=None, line=None) -> None:
        if str(message) not in said:
            said.add(str(message))
            say(args, "note", message)

    return show


#: the arguments naming a file or folder a command writes (by dest), as their messages name them
WRITTEN = {"out": "--out", "example": "--example", "to": "TO"}


def _check_written_names(args) -> None:
    """``ValueError`` for a path a command writes (``--out``, ``$MKM_OUT`` where its default
    goes, ``mkm check --example FILE``, ``mkm data copy NAME TO``) that names a file or folder
    Windows cannot make: said on every system, before any work."""
    from mkm.paths import OUT_ENV, check_path_name

    if hasattr(args, "out") and os.environ.get(OUT_ENV):
        check_path_name(os.environ[OUT_ENV], OUT_ENV)
    for dest, flag in WRITTEN.items():
        value = getattr(args, dest, None)
        if isinstance(value, str) and value != "-":  # "-": stdout
            check_path_name(value, flag)
            suffix = getattr(args, "written_files", {}).get(dest)
            if suffix:
                _check_file_name(value, flag, suffix)


def _check_file_name(value: str, flag: str, suffix: str) -> None:
    """``ValueError`` for a path where a command writes one file (``--out`` of ``fem solve``,
    ``mkm check --example FILE``...) that names a folder: ``results/`` (the slash would be
    dropped and a file ``results`` written), an existing folder, or a name without a suffix
    (``results``: the other commands' ``--out`` is a folder; this one would be a file that no
    spreadsheet or editor opens by its name)."""
    from pathlib import Path

    path = Path(value)
    folder = value.endswith(("/", os.sep)) or path.is_dir()
    if not folder and path.suffix:
        return
    why = ("is a folder" if path.is_dir() else "ends in a folder separator" if folder
           else "has no file suffix")
    example = path / f"result{suffix}" if folder else path.with_suffix(suffix)
    raise ValueError(f"{flag} {value!r} {why}: this command writes one file: expected a file "
                     f"name ending in {suffix}, such as {example}")


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog="mkm", description="McKibben muscle bench toolkit: acquire forces, "
                     "predict them with physics and surrogate models, validate.",
                     epilog="new here: `mkm demo` records two simulated bench runs and writes "
                     "their validation report (a few seconds, no hardware); your bench: `mkm "
                     "check --example bench.toml`, set its [daq] and [loadcell], then `mkm "
                     "check --config bench.toml`; forces measured elsewhere: `mkm import "
                     "--help`")
    parser.add_argument("--version", action=_Version)
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND",
                                parser_class=_Parser)
    for group in (demo, bench, exchange, data, fem, surrogate, validation, design, identify,
                  models):
        group.register(sub)
    return parser


def main(argv: list[str] | None = None) -> int:
    from mkm.cli.common import has_display

    if not has_display():  # the one place the backend is chosen: files only, no window
        os.environ.setdefault("MPLBACKEND", "Agg")
    # Windows writes a redirected stdout (`mkm report ... > log.txt`, a pipe) in the ANSI code
    # page: a path it cannot encode (C:\Users\Łukasz\...) is escaped, as on stderr, instead of
    # failing the command after its work is done
    for stream in (sys.stdout, sys.stderr):
        if isinstance(stream, io.TextIOWrapper):
            stream.reconfigure(errors="backslashreplace")
    parser = build_parser()
    if not (sys.argv[1:] if argv is None else argv):  # `mkm` alone: the help, not an error
        parser.print_help()
        return 0
    args, rest = parser.parse_known_args(argv)
    if rest:  # named by the command they were given to, not by mkm alone
        name = command_name(args)
        parser.exit(2, error_line(name, f"unrecognized arguments: {' '.join(rest)}: expected "
                                  f"the arguments of `{name} --help`")
                    + getattr(args, "_mkm_split_list", "") + "\n")
    try:
        _check_written_names(args)  # every command that writes: one check of the names
        with warnings.catch_warnings():
            warnings.showwarning = _notes(args)
            return int(args.func(args) or 0)
    except ValueError as exc:
        say(args, "error", exc)
        return 2
    except BrokenPipeError:  # `mkm ... | head`: the reader left, which is not an error
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 0
    except OSError as exc:  # a path the command cannot use (--out naming a folder, a file...)
        path = exc.filename2 or exc.filename  # an atomic write's target, not its temporary
        if isinstance(exc, HeldOpen):  # on Windows: one line, both causes, not "read-only"
            say(args, "error", f"{exc}; the command's files there are as they were")
        elif path and exc.errno in (errno.EACCES, errno.EPERM, errno.EROFS):
            say(args, "error", f"{path} cannot be written ({exc.strerror}): expected a folder "
                "this user can write to (not read-only); the command's files there are as "
                "they were")
        else:
            say(args, "error", f"{path}: {exc.strerror or exc}: expected a path this command "
                "can use (a file's name where it writes a file, a folder's where a folder)"
                if path else exc)
        return 2
    except KeyboardInterrupt:
        print(f"{command_name(args)}: interrupted", file=sys.stderr)
        return 130


if __name__ == "__main__":
    sys.exit(main())
