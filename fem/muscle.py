"""The muscle: one description of a McKibben muscle and one set of limits for every package.

A muscle is its tube (inner diameter ``D0_mm``, wall ``t0_mm``), its length at rest ``L0_mm``,
its braid angle at rest ``theta0_deg`` and its rubber (Mooney-Rivlin ``C10_MPa``, ``C01_MPa``);
the shortening ratio ``eps`` (a fraction) is where it is held. ``None`` for the angle or the
rubber means "the model's default" (the calibrated angle, Silastic S).

:data:`LIMITS` are the bounds beyond which a value is a typo, not a muscle (``--D0 1e9`` would
give 3e17 N; ``D0 1e-300`` a zero force). The force-model interface checks its arrays against
them (:func:`mkm.fem.interface.validate_inputs`), the bench configuration, the run folder and
design check their muscles with :func:`check_muscle`: one validator, one set of limits.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass
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


def limit_text(name: str) -> str:
    """``expected an inner diameter in [1, 500] mm``."""
    low, high, what, unit = LIMITS[name]
    close = ")" if name in OPEN_ABOVE else "]"
    return f"expected {what} in [{low:g}, {high:g}{close} {unit}"


def check_value(name: str, value: Any, prefix: str = "") -> float:
    """``value`` as a float inside :data:`LIMITS`; ``ValueError`` names it and the range."""
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{prefix}{name}={value!r} is not a number: {limit_text(name)}") from None
    low, high = LIMITS[name][:2]
    above = number >= high if name in OPEN_ABOVE else number > high
    if not math.isfinite(number) or number < low or above:
        raise ValueError(f"{prefix}{name}={number:g} is invalid: {limit_text(name)}")
    return number


def check_wall(D0_mm: float, t0_mm: float, prefix: str = "") -> None:
    """A wall thinner than the tube's radius (``t0_mm < D0_mm / 2``)."""
    if not t0_mm < D0_mm / 2:
        raise ValueError(f"{prefix}t0_mm={t0_mm:g} is too thick for D0_mm={D0_mm:g}: expected "
                         f"t0_mm < D0_mm/2 = {D0_mm / 2:g}")


@dataclass(frozen=True)
class Muscle:
    """A McKibben muscle (see the module docstring); checked when made.

    Parameters
    ----------
    D0_mm, t0_mm : float
        Inner diameter and wall thickness of the tube at rest [mm].
    L0_mm : float
        Length at rest [mm]; default 282 (the paper's prototype).
    eps : float
        Shortening ratio at which it is held (a fraction).
    theta0_deg : float or None
        Braid angle at rest [deg]; None: the model's calibrated angle.
    C10_MPa, C01_MPa : float or None
        Mooney-Rivlin constants of the rubber [MPa]; None: Silastic S.
    """

    D0_mm: float
    t0_mm: float
    L0_mm: float = 282.0
    eps: float = 0.0
    theta0_deg: float | None = None
    C10_MPa: float | None = None
    C01_MPa: float | None = None

    def __post_init__(self):
        check_muscle(self)
        for name, value in asdict(self).items():  # numbers from TOML or text: floats
            if value is not None:
                object.__setattr__(self, name, float(value))

    def as_dict(self) -> dict[str, float | None]:
        return asdict(self)

    def model_params(self) -> dict[str, float]:
        """The parameters a force model takes (``L0_mm``, and the angle and rubber if set)."""
        keys = ("L0_mm", "theta0_deg", "C10_MPa", "C01_MPa")
        return {k: getattr(self, k) for k in keys if getattr(self, k) is not None}


def check_muscle(muscle, prefix: str = "") -> None:
    """Check every set field of ``muscle`` (a :class:`Muscle` or any object with some of its
    attributes: a bench configuration's muscle, a run's metadata) against :data:`LIMITS`."""
    for name in ("D0_mm", "t0_mm", "L0_mm", "eps", "theta0_deg", "C10_MPa", "C01_MPa"):
        value = getattr(muscle, name, None)
        if value is not None:
            check_value(name, value, prefix)
    D0, t0 = getattr(muscle, "D0_mm", None), getattr(muscle, "t0_mm", None)
    if D0 is not None and t0 is not None:
        check_wall(float(D0), float(t0), prefix)
