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
from pathlib import Path

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


def check_writable(out: str | os.PathLike) -> Path:
    """``out``, a folder or file a command will write, if a file can be made where it goes
    (in ``out`` when it is a folder that exists, else in the nearest folder above it that
    exists); else ``ValueError``. Called before a long computation: a read-only place is said
    before the work, not after it, when the work would be lost."""
    import tempfile

    out = Path(out)
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
