"""Guards for files read from places a user or another program can write: run folders,
calibration files, tables to import.

Each raises ``ValueError`` with one line naming the file and what was expected, and never
quotes the file's content (a symbolic link to a system file would otherwise print it):

- :func:`regular_file`: a regular file reached without a symbolic link (a FIFO blocks, a device
  never ends, a link may lead anywhere);
- :func:`table_file`: a table to import, checked before any parser sees it: not empty, of a
  bounded size, and an ``.xlsx`` a zip archive whose members, as its central directory declares
  them, decompress to a bounded size (``zipfile`` stops every member at its declared size, so
  the check bounds what a reader can inflate) and hold no XML document type declaration (the
  entity-expansion attacks need one; a spreadsheet never has one).
"""

from __future__ import annotations

import os
import stat
import zipfile
from pathlib import Path

MAX_TABLE_BYTES = 50_000_000  # a table of 100,000 steps is a few MB
MAX_XLSX_UNCOMPRESSED_BYTES = 200_000_000  # what 100,000 rows of a few cells expand to, x10
XLSX_SUFFIXES = (".xlsx", ".xlsm")
_DTD_MARKERS = (b"<!DOCTYPE", b"<!ENTITY")
_CHUNK = 1 << 20


def _shown(path: Path) -> str:
    text = str(path)
    return text if len(text) <= 200 else text[:200] + "..."


def regular_file(path: str | os.PathLike, what: str = "") -> Path:
    """``path`` if it is a regular file and not a symbolic link, else ``ValueError``; ``what``
    prefixes the message (``"table "``)."""
    path = Path(path)
    try:
        info = path.lstat()
    except FileNotFoundError:
        raise ValueError(f"{what}{_shown(path)} does not exist") from None
    except OSError as exc:
        raise ValueError(f"{what}{_shown(path)} cannot be read ({exc.strerror or exc})") from None
    if stat.S_ISLNK(info.st_mode):
        raise ValueError(f"{what}{_shown(path)} is a symbolic link: refused (copy the file it "
                         "points to in its place)")
    if not stat.S_ISREG(info.st_mode):
        raise ValueError(f"{what}{_shown(path)} is not a regular file (a folder, a device or a "
                         "pipe): expected a file")
    return path


def table_file(path: str | os.PathLike) -> Path:
    """``path`` checked as a table to import (see the module): returned, or ``ValueError``."""
    path = regular_file(path, "table ")
    size = path.stat().st_size
    if size == 0:
        raise ValueError(f"{_shown(path)} is empty (0 bytes): expected a CSV or .xlsx table")
    if size > MAX_TABLE_BYTES:
        raise ValueError(f"{_shown(path)} is {size} bytes: expected a table of at most "
                         f"{MAX_TABLE_BYTES}")
    if path.suffix.lower() in XLSX_SUFFIXES:
        _check_workbook(path)
    return path


def _check_workbook(path: Path) -> None:
    if not zipfile.is_zipfile(path):
        raise ValueError(f"{_shown(path)} is not an Excel workbook (an .xlsx is a zip archive; "
                         "this file is not one): expected a CSV or .xlsx table")
    try:
        with zipfile.ZipFile(path) as archive:
            members = archive.infolist()
            total = sum(m.file_size for m in members)
            if total > MAX_XLSX_UNCOMPRESSED_BYTES:
                raise ValueError(f"{_shown(path)} expands to {total} bytes: expected a workbook "
                                 f"of at most {MAX_XLSX_UNCOMPRESSED_BYTES} uncompressed "
                                 "(a decompression bomb is refused before it is opened)")
            for member in members:
                if member.filename.lower().endswith((".xml", ".rels", ".vml")) and \
                        _has_dtd(archive, member):
                    raise ValueError(f"{_shown(path)}: {member.filename[:80]} holds an XML "
                                     "document type declaration (entity definitions): refused, "
                                     "no spreadsheet needs one")
    except (zipfile.BadZipFile, zipfile.LargeZipFile, NotImplementedError, EOFError) as exc:
        raise ValueError(f"{_shown(path)} is a damaged workbook ({type(exc).__name__}): "
                         "expected a CSV or .xlsx table") from None
    except OSError as exc:
        raise ValueError(f"{_shown(path)} cannot be read ({exc.strerror or exc})") from None


def _has_dtd(archive: zipfile.ZipFile, member: zipfile.ZipInfo) -> bool:
    """Whether ``member`` holds ``<!DOCTYPE`` or ``<!ENTITY``, read in chunks (a marker cut
    between two chunks is found by keeping the tail of the previous one)."""
    tail = b""
    with archive.open(member) as stream:
        while chunk := stream.read(_CHUNK):
            window = (tail + chunk).upper()
            if any(marker in window for marker in _DTD_MARKERS):
                return True
            tail = chunk[-16:]
    return False
