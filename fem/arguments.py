"""Parsers for command-line values shared by every ``mkm`` subcommand.

Each raises ``ValueError`` with a one-line message naming the bad text and what was expected.
"""

from __future__ import annotations

import numpy as np


def parse_number(text: str, name: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise ValueError(f"{name}={text!r} is not a number") from None
    if not np.isfinite(value):
        raise ValueError(f"{name}={text!r} is not a finite number")
    return value


def parse_pressures(text: str) -> np.ndarray:
    """``"start:stop:step"`` (stop included, tolerant to round-off) or a comma list, in bar."""
    text = text.strip()
    if ":" in text:
        parts = text.split(":")
        if len(parts) != 3:
            raise ValueError(f"--pressures {text!r} is malformed: expected start:stop:step "
                             "(for example 0:2.5:0.25) or a comma list")
        start, stop, step = (parse_number(p, "--pressures") for p in parts)
        if step <= 0:
            raise ValueError(f"--pressures {text!r}: step {step:g} must be > 0")
        if stop < start:
            raise ValueError(f"--pressures {text!r}: stop {stop:g} is below start {start:g}")
        n = int(np.floor((stop - start) / step + 1e-9)) + 1
        values = start + step * np.arange(n)
        values = np.round(values, 12)
    else:
        if not text:
            raise ValueError("--pressures is empty: expected start:stop:step or a comma list")
        values = np.array([parse_number(p, "--pressures") for p in text.split(",")])
    if (values < 0).any():
        raise ValueError(f"--pressures {text!r} has a negative pressure "
                         f"{values[values < 0][0]:g} bar: expected gauge pressures >= 0")
    return values


def parse_fraction(text: str, name: str = "--eps") -> float:
    """A fraction (``0.05``) or a percentage (``5%``); both mean 0.05."""
    text = text.strip()
    if text.endswith("%"):
        return parse_number(text[:-1], name) / 100.0
    return parse_number(text, name)
