"""Parsers of numbers, fractions and ranges, shared by the command line, grids and bench configs.

Each raises ``ValueError`` with a one-line message naming the bad text and what was expected.
"""

from __future__ import annotations

import math
import re
from functools import cache
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


def parse_number(text: str, name: str, unit: str | None = None,
                 expected: str | None = None) -> float:
    """``text`` as a finite float, in ASCII decimal notation only (:data:`ASCII_DECIMAL`); a
    decimal comma (``12,2``, as a European keyboard types it) is read as a decimal point.

    ``unit``: the unit of the option (``"mm"``, ``"bar"``, ``"deg"``); a number typed with a
    unit (``282mm``, ``1.5in``, ``250kPa``, ``30deg``) is converted into it by pint, and a
    unit of another kind is refused naming both. Without ``unit`` a unit typed is refused with
    a hint. ``expected``: what the message of a text that is no number says is expected
    (default: a number in ``unit``)."""
    expected = expected or (f"a number in {unit}, or one with a unit such as "
                            f"{UNIT_EXAMPLES.get(unit, unit)}" if unit is not None else "")
    wanted = f": expected {expected}" if expected else ""
    cleaned = str(text).strip()
    if cleaned.count(",") == 1 and "." not in cleaned:
        cleaned = cleaned.replace(",", ".")
    with_unit = re.fullmatch(r"([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*([^\W\d_]+|°)",
                             cleaned)
    if with_unit and unit is not None:
        return convert_unit(parse_number(with_unit.group(1), name), with_unit.group(2), unit,
                            f"{name}={text!r}")
    try:
        value = float(cleaned)
    except (TypeError, ValueError):
        hint = (f": expected the number alone, without {with_unit.group(2)!r} (in the unit "
                "the name or --help gives)" if with_unit else wanted)
        raise ValueError(f"{name}={text!r} is not a number{hint}") from None
    if not math.isfinite(value):
        raise ValueError(f"{name}={text!r} is not a finite number{wanted}")
    if not ASCII_DECIMAL.fullmatch(cleaned.strip(" \t\r\n")):
        raise ValueError(f"{name}={text!r} is not a number in ASCII decimal notation: "
                         "expected digits 0-9, one point, an optional exponent (2.5e-1)")
    return value


def convert_unit(value: float, typed: str, unit: str, what: str) -> float:
    """``value`` in the unit ``typed`` (pint's spelling: mm, in, kPa, psi, deg, rad, ...) as a
    number in ``unit``; ``what`` names the text in the one-line ``ValueError``."""
    import pint

    registry = _unit_registry()
    try:
        converted = registry.Quantity(value, typed).to(unit).magnitude
        return float(f"{converted:.12g}")  # 1.5in is 38.1 mm, not 38.099999999999994
    except pint.UndefinedUnitError:
        raise ValueError(f"{what}: {typed!r} is not a unit: expected a number in {unit}, or "
                         f"one with a unit such as {UNIT_EXAMPLES.get(unit, unit)}") from None
    except pint.DimensionalityError:
        raise ValueError(f"{what}: {typed!r} is not a unit of the same kind as {unit}: "
                         f"expected a number in {unit}, or one with a unit such as "
                         f"{UNIT_EXAMPLES.get(unit, unit)}") from None


#: what a unit typed may look like, per unit of an option (for the messages)
UNIT_EXAMPLES = {"mm": "282mm or 1.5in", "bar": "2.5bar or 250kPa", "deg": "30deg",
                 "s": "90s or 2min", "kg": "5kg or 500g", "V": "2V or 500mV",
                 "N": "300N or 0.3kN", "MPa": "0.07MPa or 70kPa"}


@cache
def _unit_registry():
    """pint's registry, built once (a second of parsing definitions)."""
    import pint

    return pint.UnitRegistry()


def parse_seed(text: str, name: str) -> int:
    """``text`` as a random seed: a whole number >= 0 (numpy's generators take no other)."""
    try:
        value = int(str(text).strip())
    except ValueError:
        raise ValueError(f"{name}={text!r} is not a whole number: expected a seed >= 0") from None
    if value < 0:
        raise ValueError(f"{name}={text!r} is invalid: expected a seed >= 0")
    return value


def parse_range(text: str, name: str, unit: str | None = None) -> np.ndarray:
    """``"start:stop:step"``, stop included where the steps reach it (tolerant to round-off),
    never exceeded (``0:8:3`` is 0, 3, 6), as a float array; each
    number may carry a unit when ``unit`` is given (:func:`parse_number`)."""
    parts = text.strip().split(":")
    if len(parts) != 3:
        raise ValueError(f"{name} {text!r} is malformed: expected start:stop:step "
                         "(for example 0:2.5:0.25)")
    start, stop, step = (parse_number(p, name, unit) for p in parts)
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


def decimal_comma_reading(text: str) -> float | None:
    """The number ``text`` is when its comma is a decimal comma (``"1,5"``: 1.5), or None: a
    comma list of two whole numbers reads either way."""
    match = re.fullmatch(r"\s*(\d+),(\d+)\s*", text)
    return None if match is None else float(f"{match[1]}.{match[2]}")


#: How a list option is typed, for the messages (:func:`list_items`).
LIST_FORMS = "a comma list (0,1,2.5) or, with decimal commas, a semicolon list (0,5;1;2,5)"


def list_items(text: str) -> list[str]:
    """The items of a list typed as one word, stripped: separated by semicolons where the text
    holds one, its items then free to hold decimal commas (``0,5;1;1,5``, as Windows writes a
    list where the comma is decimal), else by commas. The one rule of every list option."""
    return [item.strip() for item in str(text).split(";" if ";" in str(text) else ",")]


def parse_numbers(text: str, name: str, unit: str | None = None,
                  expected: str | None = None) -> list[float]:
    """A list option's numbers (:func:`list_items`, each :func:`parse_number`): a bad item is
    one line naming the list and the item."""
    items = list_items(text)
    label = f"{name} {text.strip()!r}: entry" if len(items) > 1 else name
    return [parse_number(item, label, unit, expected) for item in items]


def parse_pressures(text: str, name: str = "--pressures") -> np.ndarray:
    """``"start:stop:step"`` or a list (:func:`list_items`: ``0,1,2.5`` or ``0,5;1;1,5``), in
    bar (a number typed with another unit of pressure, ``250kPa``, converted); gauge
    pressures >= 0."""
    import numpy as np

    text = text.strip()
    if not text:
        raise ValueError(f"{name} is empty: expected start:stop:step or {LIST_FORMS}")
    entries = text.split(":") if ":" in text else list_items(text)
    # '0,100,200kPa': 100 would be read in bar (a zero is zero in every unit)
    number = r"\s*[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?\s*"
    entries = [p.replace(",", ".") for p in entries
               if not re.fullmatch(r"\s*[+-]?0*[.,]?0*\s*", p)]
    if (any(re.fullmatch(number + r"(?:[^\W\d_]+|°)\s*", p) for p in entries)
            and any(re.fullmatch(number, p) for p in entries)):
        raise ValueError(f"{name} {text!r} gives a unit to some entries only: expected every "
                         "entry with its unit (0kPa,100kPa,200kPa) or none (in bar)")
    if ":" in text:
        values = parse_range(text, name, "bar")
    else:
        # '0-8', '0,1,,2': the whole text and the forms it may take
        values = np.array(parse_numbers(text, name, "bar", "start:stop:step (for example "
                                        f"0:8:0.5) or {LIST_FORMS}, in bar"))
    if (values < 0).any():
        raise ValueError(f"{name} {text!r} has a negative pressure "
                         f"{values[values < 0][0]:g} bar: expected gauge pressures >= 0")
    return values


def parse_shortenings(text: str, name: str = "--eps") -> float | np.ndarray:
    """One shortening ratio (:func:`parse_fraction`: ``0.05``, ``5%``), or several:
    ``start:stop:step`` (stop included where the steps reach it) or a list
    (:func:`list_items`), each a fraction or a percentage
    (``0:0.2:0.05``, ``0%:20%:5%``, ``0.05,0.1``, ``0;0,05;0,1``); a float for one, an array for
    several. A comma list that also reads as one value with a decimal comma is refused."""
    import numpy as np

    text = text.strip()
    if ":" in text:
        parts = text.split(":")
        if len(parts) != 3:
            raise ValueError(f"{name} {text!r} is malformed: expected start:stop:step (for "
                             "example 0:0.2:0.05 or 0%:20%:5%)")
        start, stop, step = (parse_fraction(part, name) for part in parts)
        if step <= 0:
            raise ValueError(f"{name} {text!r}: step {step:g} must be > 0")
        if stop < start:
            raise ValueError(f"{name} {text!r}: stop {stop:g} is below start {start:g}")
        count = int(np.floor((stop - start) / step + 1e-9)) + 1
        if count > MAX_RANGE_VALUES:
            raise ValueError(f"{name} {text!r} expands to {count} values: expected at most "
                             f"{MAX_RANGE_VALUES}")
        return np.round(start + step * np.arange(count), 12)
    items = list_items(text)
    if len(items) == 1:
        return parse_fraction(text, name)
    def several() -> np.ndarray:
        return np.array([parse_fraction(item, f"{name} {text!r}: entry") for item in items])

    if ";" in text:  # its commas are decimal commas: one reading
        return several()
    readings = []
    for parse in (lambda: parse_fraction(text, name), several):
        try:
            readings.append(parse())
        except ValueError as exc:
            error = exc
    if len(readings) == 2:
        raise ValueError(f"{name} {text!r} reads as one value with a decimal comma and as a "
                         "list: expected a decimal point (0.1), a list of points (0,0.1) or a "
                         "semicolon list (0;0,1)")
    if not readings:
        raise error
    return readings[0]


def parse_tolerance(text: str, name: str = "--tolerance") -> float:
    """A relative tolerance in (0, 1): a fraction (``0.02``) or a percentage (``2%``). A number
    from 1 to 100 without its sign is told it may be a percentage (:func:`parse_fraction`)."""
    expected = (f"{name} {text.strip()}: expected a fraction in (0, 1) or a percentage in "
                "(0, 100), for example 0.02 or 2%")
    if text.strip().endswith("%"):
        value = _percentage(text.strip(), name, "a percentage in (0, 100), for example 2%")
    else:
        value = parse_fraction(text, name)
    if not 0.0 < value < 1.0:
        raise ValueError(expected)
    return value


def _percentage(text: str, name: str, forms: str) -> float:
    """``text`` (ending in ``%``) as a fraction; ``ValueError`` naming the whole text."""
    try:
        return parse_number(text[:-1], name, expected=forms) / 100.0
    except ValueError:
        raise ValueError(f"{name}={text!r} is not a number followed by %: expected "
                         f"{forms}") from None


def parse_fraction(text: str, name: str = "--eps") -> float:
    """A fraction (``0.05``) or a percentage (``5%``, ``12,2%``); both mean 0.05.

    A fraction must lie in [0, 1): ``12.2`` is a percentage typed without its sign, and the
    message says so (``--eps 12.2: a fraction is expected; did you mean 12.2%?``).
    """
    text = text.strip()
    forms = "a fraction (0.05) or a percentage (5%)"
    if text.endswith("%"):
        value = _percentage(text, name, forms)
        if not 0.0 <= value < 1.0:
            raise ValueError(f"{name} {text}: a percentage in [0, 100) is expected")
        return value
    value = parse_number(text, name, expected=forms)
    if 1.0 <= value < 100.0:
        raise ValueError(f"{name} {text}: a fraction is expected; did you mean {text}%?")
    if not 0.0 <= value < 1.0:
        raise ValueError(f"{name} {text}: a fraction in [0, 1) or a percentage (5%) is "
                         "expected")
    return value
