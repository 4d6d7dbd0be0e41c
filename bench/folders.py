"""Run folders named on a command line: patterns and parent folders expanded by mkm itself.

Windows ``cmd`` and PowerShell hand ``mkm-out/runs/*`` to a program as it is typed (only a POSIX
shell expands it), so every command that takes run folders passes its arguments through
:func:`run_folders`: the same line works in ``cmd``, PowerShell and bash.
"""

from __future__ import annotations

import glob
import re
from pathlib import Path

from mkm.bench.tables import TEXT_SUFFIXES, WORKBOOK_SUFFIXES
from mkm.core.toml_text import separator_hint as _separator_hint

TABLE_SUFFIXES = (*TEXT_SUFFIXES, *WORKBOOK_SUFFIXES)
RUN_RECORD = "run.json"
PATTERN_CHARACTERS = ("*", "?")


def is_run_folder(path: Path) -> bool:
    return (path / RUN_RECORD).is_file()


# <UTC time>_<muscle id>[-k][-reprocessed|-imported][-SIMULATED] (mkm.bench.storage's names)
_NAME = re.compile(r"^(?P<stem>.*?)(?:-(?P<k>\d+))?"
                   r"(?P<tail>(?:-reprocessed|-imported)?(?:-SIMULATED)?)$")


def run_order(path: Path) -> tuple:
    """Sort key of run folders: by start time, the folders of one second in the order they
    were made (``X_m``, ``X_m-2``, ..., ``X_m-10``), which their names alone do not give: by
    name ``-2`` comes before the first and ``-10`` before ``-2``."""
    found = _NAME.match(path.name)
    return (found["stem"], int(found["k"] or 1), found["tail"], str(path))


def runs_inside(folder: Path) -> list[Path]:
    """The run folders directly inside ``folder``, oldest first (:func:`run_order`)."""
    return sorted((p for p in folder.iterdir() if p.is_dir() and is_run_folder(p)),
                  key=run_order)


def run_folders(arguments) -> list[Path]:
    """The run folders ``arguments`` name, in order, each once.

    An argument with ``*`` or ``?`` is a pattern (:func:`glob.glob`; ``[`` and ``]`` are
    themselves, as in a folder's name), its matches oldest first; a
    folder that is not a run folder but holds run folders stands for them, and a run's
    ``run.json`` for its folder; anything else is passed on as it is (the loader says what is
    wrong with it). ``ValueError`` for a pattern or folder that names no run folder, and for
    another file.
    """
    out: list[Path] = []
    for argument in map(str, arguments):
        if any(c in argument for c in PATTERN_CHARACTERS):
            # only * and ? are patterns: a [ is itself (a Windows folder "Messung [2]"), as
            # glob.escape writes it
            matches = sorted((Path(m) for m in glob.glob(argument.replace("[", "[[]"))),
                             key=run_order)
            found = []
            for match in matches:
                if is_run_folder(match):
                    found.append(match)
                elif match.is_dir():
                    found += runs_inside(match)
            if not found:
                raise ValueError(f"{argument} matches no run folder ({len(matches)} match(es) "
                                 f"without {RUN_RECORD}): expected run folders of mkm acquire "
                                 f"or mkm import{_separator_hint(argument)}")
            out += found
            continue
        path = Path(argument)
        if path.is_dir() and not is_run_folder(path):
            inside = runs_inside(path)
            if not inside:
                raise ValueError(f"{path} is not a run folder ({RUN_RECORD} is missing) and "
                                 "holds none: expected a run folder or a folder of them")
            out += inside
        elif not path.exists() and _separator_hint(argument):
            raise ValueError(f"{argument}: no such folder{_separator_hint(argument)}")
        elif path.is_file() and path.name == RUN_RECORD:
            out.append(path.parent)  # a run's record stands for its folder
        elif path.is_file() and path.suffix.lower() in TABLE_SUFFIXES:
            # a lab's table given where its run is expected: it becomes one by mkm import
            raise ValueError(f"{path} is a table, not a run folder: expected run folders; "
                             f"import it first (mkm import \"{path}\" --id ... --D0 ... "
                             "--t0 ...) and pass the run folder that prints")
        elif path.is_file():
            # a shell's * passes every file beside the run folders (a README): say how to
            # let mkm expand the pattern instead
            raise ValueError(f"{path} is a file, not a run folder: expected run folders; to "
                             f"pass a folder's runs, quote the pattern (\"{path.parent / '*'}\") "
                             "or name the folder, and mkm takes only its run folders")
        else:
            out.append(path)
    return list(dict.fromkeys(out))


def one_run_folder(argument) -> Path:
    """The single run folder ``argument`` names (a pattern must match exactly one)."""
    found = run_folders([argument])
    if len(found) != 1:
        raise ValueError(f"{argument} names {len(found)} run folders: expected one")
    return found[0]
