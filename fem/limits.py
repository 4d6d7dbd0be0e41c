"""The one set of limits of a muscle's numbers, and the one check of them.

:data:`LIMITS` are the bounds beyond which a value is a typo, not a muscle (``--D0 1e9`` would
give 3e17 N; ``D0 1e-300`` a zero force). :func:`outside` is the check, for a number or an array
of them; the force-model interface (:func:`mkm.fem.interface.validate_inputs`), reference tables
(:mod:`mkm.fem.calibration`), tolerances and the muscle type (:class:`mkm.fem.muscle.Muscle`:
the bench configuration, the run folder, design) all ask it.
"""

from __future__ import annotations

import math
import re
from typing import Any

#: name -> (low, high, what the value is, unit); both bounds included except :data:`OPEN_ABOVE`
LIMITS: dict[str, tuple[float, float, str, str]] = {
    "pressure_bar": (0.0, 1000.0, "a gauge pressure", "bar"),
    "D0_mm": (1.0, 500.0, "an inner diameter", "mm"),
    "t0_mm": (0.05, 100.0, "a wall thickness", "mm"),
    "L0_mm": (10.0, 3000.0, "a length at rest", "mm"),
    "eps": (0.0, 1.0, "a shortening ratio", "(a fraction)"),
    "theta0_deg": (1.0, 89.0, "a braid angle at rest", "deg"),
    "C10_MPa": (1e-4, 100.0, "a Mooney-Rivlin C10", "MPa"),
    "C01_MPa": (0.0, 100.0, "a Mooney-Rivlin C01", "MPa"),
    "gap_mm": (0.0, 100.0, "a radial gap between tube and braid", "mm"),
}
#: the upper bound of these is excluded (eps = 1 is a muscle of zero length)
OPEN_ABOVE = frozenset({"eps"})
# A muscle id names the run folder and labels figures and reports: no path separators, no
# markup, no spreadsheet formula, no mathtext.
MUSCLE_ID_PATTERN = r"[A-Za-z0-9][A-Za-z0-9._+-]{0,63}"


def limit_text(name: str) -> str:
    """``expected an inner diameter in [1, 500] mm``."""
    low, high, what, unit = LIMITS[name]
    close = ")" if name in OPEN_ABOVE else "]"
    return f"expected {what} in [{low:g}, {high:g}{close} {unit}"


def outside(name: str, values):
    """Where ``values`` (a number, or a numpy or pandas array) lie outside ``LIMITS[name]``:
    a bool of the same shape; NaN counts as outside."""
    low, high = LIMITS[name][:2]
    above = values >= high if name in OPEN_ABOVE else values > high
    return (values < low) | above | (values != values)  # the last: NaN


def check_value(name: str, value: Any, prefix: str = "") -> float:
    """``value`` as a float inside :data:`LIMITS`; ``ValueError`` names it and the range."""
    if isinstance(value, bool):
        raise ValueError(f"{prefix}{name}={value!r} is not a number: {limit_text(name)}")
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{prefix}{name}={value!r} is not a number: {limit_text(name)}") from None
    if not math.isfinite(number) or outside(name, number):
        raise ValueError(f"{prefix}{name}={number:g} is invalid: {limit_text(name)}")
    return number


def check_wall(D0_mm: float, t0_mm: float, prefix: str = "") -> None:
    """A wall thinner than the tube's radius (``t0_mm < D0_mm / 2``)."""
    if not t0_mm < D0_mm / 2:
        raise ValueError(f"{prefix}t0_mm={t0_mm:g} is too thick for D0_mm={D0_mm:g}: expected "
                         f"t0_mm < D0_mm/2 = {D0_mm / 2:g}")


def check_muscle_id(value: Any, where: str = "muscle.id") -> str:
    """``value`` if it is a valid muscle id (:data:`MUSCLE_ID_PATTERN`), else ``ValueError``."""
    if not isinstance(value, str) or not re.fullmatch(MUSCLE_ID_PATTERN, value):
        text = value if isinstance(value, str) else repr(value)
        shown = repr(text if len(text) <= 40 else text[:40] + "...")
        raise ValueError(f"{where}={shown} ({len(text)} characters) is invalid: expected 1 to "
                         "64 letters, digits or . _ + - (it names the run folder and labels "
                         "figures)")
    return value
