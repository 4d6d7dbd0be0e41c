"""Typed settings from TOML tables (read by :mod:`mkm.core.toml_text`) and the checks settings
share.

:func:`typed_section` fills a frozen dataclass from one table: unknown keys, missing required
keys and wrong types are named with their ``section.key``; the dataclass's own ``check()`` then
validates the values.
"""

from __future__ import annotations

import dataclasses
import math
import re
import typing
import unicodedata
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

from mkm.core.ranges import parse_pressures


class PathText(str):
    """The type of a setting that names a file or folder: :func:`typed_section` refuses one
    holding a control character (:func:`path_text`), what a Windows path in ``"..."`` becomes
    where its backslashes happen to be valid escapes, which would be read without a word. The
    value is kept as a ``str``."""


#: a control character as TOML's "..." writes it, and what it is called
_ESCAPES = {"\t": ("\\t", "a tab"), "\n": ("\\n", "a new line"),
            "\r": ("\\r", "a carriage return"), "\b": ("\\b", "a backspace"),
            "\f": ("\\f", "a form feed")}


class Problems:
    """The bad values of a configuration, gathered so that one check names every one (a line
    each) rather than the first: a user fixing them one run at a time met the next only after
    the last was mended."""

    def __init__(self):
        self.lines: list[str] = []

    @contextmanager
    def check(self) -> Iterator[None]:
        """Run one check (of one setting, or of settings that depend on each other): its
        ``ValueError`` is kept and the checks after it still run."""
        try:
            yield
        except ValueError as exc:
            self.lines += [line for line in str(exc).splitlines() if line not in self.lines]

    def raise_any(self, prefix: str = "") -> None:
        """One ``ValueError`` of every line kept, each after ``prefix``; nothing when none."""
        if self.lines:
            raise ValueError("\n".join(prefix + line for line in self.lines))


def positive(name: str, value) -> None:
    if not value > 0:
        raise ValueError(f"{name}={value!r} is invalid: expected a number > 0")


def within(name: str, value, low, high, unit: str = "", why: str = "") -> None:
    """``low <= value <= high`` or ``ValueError`` naming the setting, the range and why."""
    if not low <= value <= high:
        shown = f"{value:g}" if isinstance(value, float) else repr(value)
        raise ValueError(f"{name}={shown} is invalid: expected {low:g} to {high:g}"
                         f"{' ' + unit if unit else ''}{f' ({why})' if why else ''}")


def typed_section(cls, table: Any, where: str):
    """An instance of the dataclass ``cls`` from the TOML ``table`` at ``where``, checked.

    Field types: ``str``, ``float``, ``int``, ``bool``, ``X | None``, ``tuple[float, ...]``
    (pressures: ``'start:stop:step'`` or a list) and nested dataclasses (sub-tables).
    """
    if not isinstance(table, dict):
        raise ValueError(f"[{where}] must be a table of settings, got {_short(table)}")
    fields = {f.name: f for f in dataclasses.fields(cls)}
    problems = Problems()
    for name in sorted(set(table) - set(fields)):
        shown = name if len(name) <= 40 else name[:40] + "..."
        problems.lines.append(f"{where}.{shown} is not a setting: expected some of "
                              f"{', '.join(fields)}")
    hints = typing.get_type_hints(cls)
    values, bad = {}, []
    for name, f in fields.items():
        key = f"{where}.{name}"
        with problems.check():
            if name not in table:
                if f.default is dataclasses.MISSING and f.default_factory is dataclasses.MISSING:
                    bad.append(name)
                    raise ValueError(f"{key} is missing: it has no default")
                continue
            try:
                values[name] = _convert(table[name], hints[name], key)
            except ValueError:
                bad.append(name)
                raise
    if bad and all(_has_default(fields[name]) for name in bad):
        problems.lines += _checked_without(cls, values, bad, where)
    problems.raise_any()
    try:
        obj = cls(**values)  # a type that checks itself when made (the tolerances)
    except ValueError as exc:
        raise ValueError(f"[{where}] {exc}") from None
    if hasattr(obj, "check"):
        obj.check()
    return obj


def _has_default(f: dataclasses.Field) -> bool:
    return f.default is not dataclasses.MISSING or f.default_factory is not dataclasses.MISSING


def _checked_without(cls, values: dict[str, Any], bad: list[str], where: str) -> list[str]:
    """The problems ``cls``'s own checks find in ``values``, its ``bad`` settings (of a wrong
    type) left at their defaults, so that one check names every bad value of a section; a
    problem naming a bad setting is left out: it would be about a default the file does not
    hold."""
    try:
        obj = cls(**values)
    except ValueError as exc:
        found = [f"[{where}] {line}" for line in str(exc).splitlines()]
    else:
        try:
            if hasattr(obj, "check"):
                obj.check()
            found = []
        except ValueError as exc:
            found = str(exc).splitlines()
    named = re.compile(r"\b(?:" + "|".join(map(re.escape, bad)) + r")\b")
    return [line for line in found if not named.search(line)]


#: a TOML value's type as a lab engineer reads it (not Python's name: "a int")
_KINDS = {int: "a whole number", float: "a number", str: "a text in quotes",
          bool: "true or false"}


def _short(value, n: int = 60) -> str:
    text = repr(value)
    return text if len(text) <= n else text[:n] + "..."


def _convert(value, annotation, key: str):
    if dataclasses.is_dataclass(annotation):
        return typed_section(annotation, value, key)
    if annotation == tuple[float, ...]:
        return _pressures(value, key)
    args = typing.get_args(annotation)
    if type(None) in args:
        if value is None:
            return None
        (annotation,) = [a for a in args if a is not type(None)]
    if annotation is PathText:
        if isinstance(value, str):
            path_text(value, key)
        annotation = str
    if annotation is float and isinstance(value, int) and not isinstance(value, bool):
        try:
            value = float(value)
        except OverflowError:
            raise ValueError(f"{key}={_short(value)} is not a finite number") from None
    if not isinstance(value, annotation) or (annotation is int and isinstance(value, bool)):
        raise ValueError(f"{key}={_short(value)} is invalid: expected "
                         f"{_KINDS.get(annotation, annotation.__name__)}")
    if annotation is float and not math.isfinite(value):
        raise ValueError(f"{key}={value!r} is not a finite number")
    return value


def path_text(value: str, key: str) -> str:
    """``value``, the path the setting ``key`` names, or a one-line ``ValueError`` where it
    holds a control character, with the single-quoted form to type: TOML reads
    ``"C:\\temp\\new"`` as C:, a tab, emp, a new line, ew."""
    controls = [c for c in dict.fromkeys(value) if unicodedata.category(c) == "Cc"]
    if not controls:
        return value
    typed = "".join(_ESCAPES[c][0] if c in _ESCAPES
                    else f"\\u{ord(c):04X}" if unicodedata.category(c) == "Cc" else c
                    for c in value)
    named = [f"{_ESCAPES[c][1]} ({_ESCAPES[c][0]})" if c in _ESCAPES
             else f"the control character U+{ord(c):04X}" for c in controls]
    said = ", ".join(named[:-1]) + " and " + named[-1] if len(named) > 1 else named[0]
    name = key.rpartition(".")[2]
    fixed = f"'{typed}'" if "'" not in typed else f'"{typed.replace(chr(92), "/")}"'
    raise ValueError(f'{key} = "{_shorter(typed)}" reads as a path with {said} in it: in '
                     f'"..." a \\ begins an escape; write a Windows path in single quotes, '
                     f"{name} = {fixed}, or with / for \\")


def _shorter(text: str, n: int = 200) -> str:
    return text if len(text) <= n else text[:n] + "..."


def _pressures(value, key: str) -> tuple[float, ...]:
    if isinstance(value, str):
        return tuple(float(p) for p in parse_pressures(value, key))
    if isinstance(value, list) and all(isinstance(v, int | float) and not isinstance(v, bool)
                                       for v in value):
        return tuple(float(p) for p in parse_pressures(",".join(str(v) for v in value), key))
    raise ValueError(f"{key}={_short(value)} is invalid: expected 'start:stop:step' or a list "
                     "of numbers [bar]")
