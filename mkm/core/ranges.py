"""Parsers of numbers, fractions and ranges, shared by the command line, grids and bench configs.

Each raises ``ValueError`` with a one-line message naming the bad text and what was expected.
"""

from __future__ import annotations

import math
import re
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # numpy is imported where arrays are made: `mkm --help` starts without it
    import numpy as np

#: Most values a range may expand to: a staircase or a grid axis of more is a typo, not a plan
#: (``0:1e12:1`` would allocate terabytes).
MAX_RANGE_VALUES = 10_000


#: A number as an instrument file or a person writes it: ASCII digits, one decimal point, an
#: optional exponent. ``float()`` also takes Arabic-Indic or full-width digits and ``0.2_5``,
#: which no bench setting is meant to be.
ASCII_DECIMAL = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?", re.ASCII)


def parse_number(text: str, name: str) -> float:
    """``text`` as a finite float, in ASCII decimal notation only (:data:`ASCII_DECIMAL`); a
    decimal comma (``12,2``, as a European keyboard types it) is read as a decimal point."""
    cleaned = str(text).strip()
    if cleaned.count(",") == 1 and "." not in cleaned:
        cleaned = cleaned.replace(",", ".")
    try:
        value = float(cleaned)
    except (TypeError, ValueError):
        with_unit = re.fullmatch(r"\s*[-+]?[\d.]+(?:[eE][-+]?\d+)?\s*([^\W\d_]+)\s*", cleaned)
        hint = (f": expected the number alone, without {with_unit.group(1)!r} (in the unit "
                "the name or --help gives)" if with_unit else "")
        raise ValueError(f"{name}={text!r} is not a number{hint}") from None
    if not math.isfinite(value):
        raise ValueError(f"{name}={text!r} is not a finite number")
    if not ASCII_DECIMAL.fullmatch(cleaned.strip(" \t\r\n")):
        raise ValueError(f"{name}={text!r} is not a number in ASCII decimal notation: "
                         "expected digits 0-9, one point, an optional exponent (2.5e-1)")
    return value


def parse_seed(text: str, name: str) -> int:
    """``text`` as a random seed: a whole number >= 0 (numpy's generators take no other)."""
    try:
        value = int(str(text).strip())
    except ValueError:
        raise ValueError(f"{name}={text!r} is not a whole number: expected a seed >= 0") from None
    if value < 0:
        raise ValueError(f"{name}={text!r} is invalid: expected a seed >= 0")
    return value


def parse_range(text: str, name: str) -> np.ndarray:
    """``"start:stop:step"``, stop included (tolerant to round-off), as a float array."""
    parts = text.strip().split(":")
    if len(parts) != 3:
        raise ValueError(f"{name} {text!r} is malformed: expected start:stop:step "
                         "(for example 0:2.5:0.25)")
    start, stop, step = (parse_number(p, name) for p in parts)
    if step <= 0:
        raise ValueError(f"{name} {text!r}: step {step:g} must be > 0")
    if stop < start:
        raise ValueError(f"{name} {text!r}: stop {stop:g} is below start {start:g}")
    import numpy as np

    count = np.floor((stop - start) / step + 1e-9) + 1
    if count > MAX_RANGE_VALUES:
        raise ValueError(f"{name} {text!r} expands to {count:.3g} values: expected at most "
                         f"{MAX_RANGE_VALUES}")
    return np.round(start + step * np.arange(int(count)), 12)


def parse_pressures(text: str, name: str = "--pressures") -> np.ndarray:
    """``"start:stop:step"`` or a comma list, in bar; gauge pressures >= 0."""
    import numpy as np

    text = text.strip()
    if ":" in text:
        values = parse_range(text, name)
    else:
        if not text:
            raise ValueError(f"{name} is empty: expected start:stop:step or a comma list")
        parts = text.split(",")
        label = f"{name} {text!r}: entry" if len(parts) > 1 else name
        try:
            values = np.array([parse_number(p, label) for p in parts])
        except ValueError as exc:  # '0-8', '0,1,,2': the whole text and the forms it may take
            raise ValueError(str(exc) if "expected" in str(exc) else
                             f"{exc}: expected start:stop:step (for example 0:8:0.5) or a comma "
                             "list (0,1,2.5), in bar") from None
    if (values < 0).any():
        raise ValueError(f"{name} {text!r} has a negative pressure "
                         f"{values[values < 0][0]:g} bar: expected gauge pressures >= 0")
    return values


def parse_fraction(text: str, name: str = "--eps") -> float:
    """A fraction (``0.05``) or a percentage (``5%``, ``12,2%``); both mean 0.05.

    A fraction must lie in [0, 1): ``12.2`` is a percentage typed without its sign, and the
    message says so (``--eps 12.2: a fraction is expected; did you mean 12.2%?``).
    """
    text = text.strip()
    if text.endswith("%"):
        value = parse_number(text[:-1], name) / 100.0
        if not 0.0 <= value < 1.0:
            raise ValueError(f"{name} {text}: a percentage in [0, 100) is expected")
        return value
    value = parse_number(text, name)
    if 1.0 <= value < 100.0:
        raise ValueError(f"{name} {text}: a fraction is expected; did you mean {text}%?")
    if not 0.0 <= value < 1.0:
        raise ValueError(f"{name} {text}: a fraction in [0, 1) or a percentage (5%) is "
                         "expected")
    return value
