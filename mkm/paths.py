"""Where commands write by default: the one place every default output folder and cache comes from.

- Outputs (reports, studies, datasets, run folders of ``mkm acquire``) go under
  :func:`output_root`, ``./mkm-out`` in the folder the command runs from (or the folder named by
  the ``MKM_OUT`` environment variable), one subfolder per command: nothing lands among the
  project's shipped files, and the path is printed at the end of every command.
- Caches (FE predictions, trained surrogates, dataset jobs) go under :func:`cache_root`, the
  user's cache folder of the operating system (:func:`mkm.core.home.user_cache`:
  ``~/.cache/mkm-bench`` on Linux, ``%LOCALAPPDATA%\\mkm-bench\\mkm-bench\\Cache`` on Windows),
  where the libraries keep theirs too (``mkm.surrogate.train``, ``mkm.fem.dataset.build``), so a
  second
  run from any folder is fast.

Replacing a file shipped inside a package (the study table, the FE dataset, the FE reference,
the calibration) always takes an explicit flag of the command that writes it.
"""

from __future__ import annotations

import os
import re
from pathlib import Path, PureWindowsPath

from mkm.core.home import user_cache

OUT_ENV = "MKM_OUT"
DEFAULT_OUT_ROOT = "mkm-out"


def output_root() -> Path:
    """``$MKM_OUT`` if set, else ``./mkm-out`` (relative to the working directory)."""
    return Path(os.environ.get(OUT_ENV) or DEFAULT_OUT_ROOT)


def default_out(*parts: str) -> Path:
    """Default output of a command: ``output_root() / parts`` (``default_out("report")``)."""
    return output_root().joinpath(*parts)


def cache_root() -> Path:
    """The user's cache folder for this toolkit (created on first write, not here)."""
    return user_cache()


def default_cache(*parts: str) -> Path:
    """A cache subfolder: ``cache_root() / parts`` (``default_cache("predictions")``)."""
    return cache_root().joinpath(*parts)


class CacheFolder(os.PathLike):
    """A cache subfolder named once and resolved at each use (``Path(folder)``, ``str(folder)``),
    so a default argument follows ``MKM_CACHE_DIR`` set after import (the tests' own cache)."""

    def __init__(self, *parts: str):
        self.parts = parts

    def __fspath__(self) -> str:
        return str(default_cache(*self.parts))

    __str__ = __fspath__

    def __repr__(self) -> str:
        return f"CacheFolder{self.parts!r}"


#: The package holding measurements published by other labs (``mkm data``): shipped with the
#: wheel, so the documented ``mkm import`` of them works without the source tree.
PUBLISHED_PACKAGE = "mkm.data.published"


def published_tables() -> dict[str, Path]:
    """The shipped published measurements, by file name (``martens_boblan_2017_forcemaps.csv``)."""
    from importlib.resources import files

    folder = files(PUBLISHED_PACKAGE)
    # resolved: a strict editable install links each file, and mkm import refuses links
    return {p.name: Path(str(p)).resolve() for p in sorted(folder.iterdir(), key=lambda p: p.name)
            if p.name.endswith(".csv")}


def published_table(name: str) -> Path:
    """The shipped file ``name`` (as :func:`published_tables` names it); ``ValueError`` naming
    the shipped ones for any other name."""
    tables = published_tables()
    if name not in tables:
        raise ValueError(f"{name!r} is not a shipped published table: expected one of "
                         f"{', '.join(tables)} (mkm data list)")
    return tables[name]


def copy_published_table(name: str, to: str | os.PathLike | None = None) -> Path:
    """Copy the shipped table ``name`` byte for byte (its SHA-256 is its provenance, recorded by
    ``mkm import``) to ``to``: a file name, an existing folder (the file keeps its name there),
    or None (the working folder). An existing file is kept: the same bytes already (a script
    run again) is that copy, another file a ``ValueError``."""
    import filecmp
    import shutil

    source = published_table(name)
    target = Path(name) if to is None else Path(to)
    if target.is_dir():
        target = target / name
    elif str(to).endswith(("/", os.sep)):  # "sub/": a folder meant, which Path would drop
        raise ValueError(f"TO {str(to)!r}: no such folder: expected an existing folder (make "
                         f"it first) or a file name ending in {source.suffix}")
    elif target.suffix.lower() != source.suffix.lower():
        # mkm import reads a table by its suffix: a copy named "maps" or "newdir" is no table
        raise ValueError(f"TO {str(to)!r} is neither an existing folder nor a file name ending "
                         f"in {source.suffix}: expected one of them (mkm import reads the table "
                         "by its suffix)")
    if target.is_file() and filecmp.cmp(source, target, shallow=False):
        return target
    if target.exists():
        raise ValueError(f"{target} exists: kept as it is; name a new file for {name}")
    if not target.parent.is_dir():
        raise ValueError(f"TO {str(to)!r}: no such folder {str(target.parent)!r}: expected the "
                         "file in an existing folder (make it first)")
    shutil.copyfile(source, target)
    return target


# characters that split or change an argument in cmd, PowerShell or a POSIX shell
_SHELL_SPECIAL = re.compile(r"[\s&|<>^;()'`$%!,{}\[\]*?#]")


def command_argument(path: str | os.PathLike) -> str:
    """``path`` as one argument of a command the user may copy: in double quotes (which cmd,
    PowerShell and bash all read as one argument) where it holds a space or a character a shell
    treats specially (``C:\\Users\\Lab PC\\mkm-out\\runs\\R``), else as it is."""
    text = str(path)
    return f'"{text}"' if not text or _SHELL_SPECIAL.search(text) else text


# what Windows refuses in a file or folder name: these characters (":" opens an NTFS alternate
# data stream), a trailing dot or space (silently dropped), a device name with any extension
_WINDOWS_FORBIDDEN = re.compile(r'[<>:"|?*\x00-\x1f]')
_WINDOWS_DEVICE = re.compile(r"(CON|PRN|AUX|NUL|COM[1-9]|LPT[1-9])(\..*)?", re.IGNORECASE)


def windows_name_problem(name: str) -> str | None:
    """Why Windows cannot make a file or folder named ``name`` (one path component), or None."""
    if name in (".", ".."):
        return None
    bad = _WINDOWS_FORBIDDEN.search(name)
    if bad:
        return f"{bad.group()!r} in {name!r}"
    if name.endswith((".", " ")):
        return f"{name!r} ends in {name[-1]!r}"
    if _WINDOWS_DEVICE.fullmatch(name.rstrip(" ")):
        return f"{name!r} is a device name"
    return None


#: whether this system is Windows (where a backslash separates folders)
WINDOWS = os.name == "nt"


def check_path_name(path: str | os.PathLike, flag: str = "--out") -> str:
    """``path`` if every folder and file name in it is one Windows can make, else ``ValueError``
    naming the value and the rule: checked on every system, so a command line or run folder
    that works here works on a lab's Windows PC too. An absolute Windows path (``C:\\...``, a
    ``\\\\server\\share``) keeps its anchor; ``a:b`` is a name with a colon, not a drive. Elsewhere
    a Windows path (a drive letter, a backslash) is refused too: it would name one file here."""
    text = os.fspath(path)
    windows = PureWindowsPath(text)
    names = windows.parts[1:] if windows.root else re.split(r"[\\/]", text)
    problem = next(filter(None, map(windows_name_problem, names)), None)
    if problem:
        raise ValueError(f"{flag} {text!r} is not a path Windows can make ({problem}): expected "
                         'folder and file names without < > : " | ? * or control characters, '
                         "not ending in a dot or space, and not CON, PRN, AUX, NUL, COM1-9 or "
                         "LPT1-9 (with or without an extension)")
    if not WINDOWS and (re.match(r"[A-Za-z]:", text) or "\\" in text):
        # here a backslash is part of a name: "C:\\Users\\lab\\out" would be one file in the
        # working folder
        raise ValueError(f"{flag} {text!r} is a Windows path: expected a path of this system, "
                         "folders separated by / (such as mkm-out/runs or /home/lab/mkm-out)")
    return text


def check_writable(out: str | os.PathLike, folder: bool = False) -> Path:
    """``out``, a folder (``folder``) or file a command will write, if a file can be made where
    it goes (in ``out`` when it is a folder that exists, else in the nearest folder above it that
    exists); else ``ValueError``. Called before a long computation: a read-only place, or a file
    where the command makes a folder, is said before the work, not after it, when the work
    would be lost."""
    import tempfile

    out = Path(out)
    if folder and out.exists() and not out.is_dir():
        raise ValueError(f"{out} is a file: expected --out to name a folder (new or one the "
                         "command wrote before); nothing was computed or written")
    place = out if out.is_dir() else out.parent
    while not place.exists() and place != place.parent:
        place = place.parent
    if not place.is_dir():
        return out  # a file where a folder goes: the writer's own check names it
    try:
        with tempfile.TemporaryFile(dir=place):
            pass
    except OSError as exc:
        where = "" if place == out else f": {place} is not writable for this user"
        raise ValueError(f"{out} cannot be written{where} ({exc.strerror or exc}): expected "
                         "--out in a folder this user can write to; nothing was computed or "
                         "written") from None
    return out
