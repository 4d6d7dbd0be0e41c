"""Text files a user edits on Windows, and the TOML in them: the one reader of every TOML the
toolkit reads (a bench configuration, a run folder's ``config.toml``, a dataset grid) and of the
tables a lab saves.

:func:`saved_text` decodes a file as a Windows program may have saved it; :func:`read_toml`
parses TOML text and turns any malformed text, including nesting deep enough to exhaust the
parser's recursion, into one ``ValueError`` that says what a Windows user's line needs
(:func:`toml_hint`); :func:`read_toml_file` reads a file so, naming one that is not there with
where Windows put it (:func:`saved_as_hint`, :func:`separator_hint`).
"""

from __future__ import annotations

import os
import re
import tomllib
from pathlib import Path
from typing import Any

MAX_TEXT_CHARS = 1_000_000  # a bench configuration is a few kB; beyond this it is not one

#: the byte-order marks of UTF-16, which Notepad's "Unicode", Excel's "Unicode Text" and
#: Windows PowerShell 5's ``>`` write
UTF16_BOMS = (b"\xff\xfe", b"\xfe\xff")
#: what may follow the last line: a DOS program's end-of-file mark (Ctrl-Z) and a logger's
#: file written into space filled with NULs beforehand
TEXT_END_PADDING = "\x00\x1a"


def saved_text(data: bytes) -> str:
    """The text of a file as a Windows program may have saved it: UTF-16 with its byte-order
    mark, or without one (a logger's, a script's: a NUL in its first two bytes), else UTF-8
    with or without its byte-order mark; a trailing Ctrl-Z or NUL padding is no text.
    ``UnicodeDecodeError`` for bytes that are none of them (a Windows code page)."""
    if data.startswith(UTF16_BOMS):
        text = data.decode("utf-16", errors="replace")
    elif b"\x00" in data[:2]:
        text = data.decode("utf-16-le" if data[1:2] == b"\x00" else "utf-16-be",
                           errors="replace")
    else:
        text = data.rstrip(TEXT_END_PADDING.encode()).decode("utf-8-sig")
    return text.rstrip(TEXT_END_PADDING)


def separator_hint(argument: str) -> str:
    """What a Windows path typed on another system needs ("runs\\R": one name here)."""
    if os.sep != "/" or "\\" not in argument:
        return ""
    posix = argument.replace("\\", "/")
    return f"; on this system folders are separated by /: {posix!r}?"


def saved_as_hint(path: Path) -> str:
    """Where Windows put the file ``path`` names, when it names none: Notepad saves
    ``bench.toml`` as ``bench.toml.txt`` unless its type is "All files", and Explorer hides the
    extension, so that file shows as ``bench.toml`` and a name typed from it lacks ``.toml``."""
    for other, why in ((path.with_name(path.name + ".txt"),
                        "Notepad added .txt: rename it, or save with type 'All files'"),
                       (path.with_name(path.name + ".toml"),
                        "Explorer hides the extension: type it too")):
        if path.suffix != other.suffix and other.is_file():
            return f"; {other} is there ({why})"
    return ""


def toml_hint(text: str, exc: tomllib.TOMLDecodeError) -> str:
    """What the line tomllib refused needs, where its message names the parser's complaint
    only: a Windows path in a "..." string (each backslash begins an escape), a decimal comma,
    a word without quotes, Python's ``True``. ``""`` when none of them is the cause."""
    message = str(exc)
    at = re.search(r"\(at line (\d+), column \d+\)$", message)
    lines = text.splitlines()
    if at is None or int(at[1]) > len(lines):
        return ""
    line = lines[int(at[1]) - 1]
    key, _, value = (part.strip() for part in line.partition("="))
    value = value.split("#")[0].strip()
    if message.startswith(("Unescaped '\\'", "Invalid hex value", "Escaped character")):
        typed = next((m[1] for m in re.finditer(r'"((?:[^"\\]|\\.)*)"', line)
                      if "\\" in m[1]), None)
        if typed is not None:
            fixed = f"'{typed}'" if "'" not in typed else f'"{typed.replace(chr(92), "/")}"'
            return (f"; a \\ in \"...\" begins an escape (\\n, \\t, \\U...): write a Windows "
                    f"path in single quotes, {key} = {fixed}, or with / for \\")
    if message.startswith("Expected newline") and re.fullmatch(r"[+-]?\d+,\d+", value):
        return f"; a decimal comma: TOML numbers take a point, {key} = {value.replace(',', '.')}"
    if message.startswith("Invalid value") and re.fullmatch(r"[A-Za-z_][\w.+-]*", value):
        if value.lower() in ("true", "false"):
            return f"; TOML's true and false are lower case: {key} = {value.lower()}"
        return f'; a text value goes in quotes: {key} = "{value}"'
    return ""


def read_toml(text: str, source: str) -> dict[str, Any]:
    """The tables of the TOML ``text`` read from ``source``, or one-line ``ValueError``."""
    if len(text) > MAX_TEXT_CHARS:
        raise ValueError(f"{source} has {len(text)} characters: expected a TOML file of at most "
                         f"{MAX_TEXT_CHARS}")
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise ValueError(f"{source} is not valid TOML: {exc}{toml_hint(text, exc)}") from None
    except RecursionError:
        raise ValueError(f"{source} is not valid TOML: nested too deeply") from None


def read_toml_file(path: str | Path, what: str = "",
                   expected: str = "a TOML file") -> tuple[str, dict[str, Any]]:
    """The text of the TOML file ``path`` and its tables (:func:`read_toml`); ``what`` prefixes
    the messages (``"config "``), ``expected`` says what a missing one should have been."""
    path = Path(path)
    shown = str(path) if len(str(path)) <= 200 else str(path)[:200] + "..."
    try:
        if path.is_dir():
            raise ValueError(f"{what}{shown} is a folder: expected {expected}")
        if not path.is_file():
            raise ValueError(f"{what}{shown} does not exist: expected {expected}"
                             f"{separator_hint(str(path)) or saved_as_hint(path)}")
        if path.stat().st_size > MAX_TEXT_CHARS * 4:
            raise ValueError(f"{what}{shown} is {path.stat().st_size} bytes: expected a TOML "
                             f"file of at most {MAX_TEXT_CHARS} characters")
        # Notepad's BOM, its "Unicode" (UTF-16), a DOS editor's Ctrl-Z at the end
        text = saved_text(path.read_bytes())
    except OSError as exc:
        raise ValueError(f"{what}{shown} cannot be read ({exc.strerror or exc})") from None
    except UnicodeDecodeError as exc:
        raise ValueError(f"{what}{shown} is not UTF-8 text (byte {exc.start + 1} is not, as "
                         "a Windows code page saves an accented letter): save it as UTF-8 "
                         "(Notepad: File, Save as, Encoding UTF-8)") from None
    return text, read_toml(text, f"{what}{path}")
