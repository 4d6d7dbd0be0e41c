"""The tolerances a McKibben muscle is made to, and draws from them.

A muscle is made to tolerances: D0, t0 and L0 by the tube's maker, eps read from the threaded
rod's scale, theta0 fitted (its spread across fits), the rubber's constants from one material
test. :class:`Tolerances` holds them as +- bounds; each input is taken as uniformly distributed
within its bound (a part made to tolerance lies anywhere inside it; standard uncertainty
bound / sqrt 3), independent of the others, except C10 and C01, which come from one fit and move
together (``rubber_fraction`` scales both). The bench configuration's ``[muscle]`` section takes
its defaults from here; :mod:`mkm.uncertainty` propagates them to a model's force.
"""

from __future__ import annotations

import math
import re
from dataclasses import asdict, dataclass, fields

import numpy as np

from mkm.fem.limits import LIMITS

SQRT3 = math.sqrt(3.0)
#: what ``--tolerance`` calls each field
SHORT_NAMES = {"D0": "D0_mm", "t0": "t0_mm", "L0": "L0_mm", "eps": "eps",
               "theta0": "theta0_deg", "rubber": "rubber_fraction"}
MAX_RUBBER_FRACTION = 0.5


@dataclass(frozen=True)
class Tolerances:
    """+- bounds of a muscle's inputs (uniform within them).

    Parameters
    ----------
    D0_mm : float
        Inner diameter [mm]; default 0.3 (an extruded silicone tube's +-1 % at 30 mm).
    t0_mm : float
        Wall thickness [mm]; default 0.1.
    L0_mm : float
        Length at rest [mm]; default 1.0 (cut to length with a rule).
    eps : float
        Shortening ratio (a fraction); default 0.004 (the threaded rod's scale read to 1 mm on
        282 mm).
    theta0_deg : float
        Braid angle at rest [deg]; default 1.0 (the spread of a fitted braid angle).
    rubber_fraction : float
        C10 and C01 together, a fraction of their value; default 0 (the calibrated rubber).
    """

    D0_mm: float = 0.3
    t0_mm: float = 0.1
    L0_mm: float = 1.0
    eps: float = 0.004
    theta0_deg: float = 1.0
    rubber_fraction: float = 0.0

    def __post_init__(self):
        for f in fields(self):
            value = getattr(self, f.name)
            high = MAX_RUBBER_FRACTION if f.name == "rubber_fraction" else \
                0.5 * LIMITS[f.name][1] if f.name != "eps" else 0.5
            if isinstance(value, bool) or not isinstance(value, int | float) \
                    or not 0.0 <= value <= high:
                raise ValueError(f"tolerance {f.name}={value!r} is invalid: expected a +- bound "
                                 f"from 0 to {high:g}")

    @classmethod
    def parse(cls, text: str, base: Tolerances | None = None) -> Tolerances:
        """``D0=0.3,t0=0.1,theta0=1,rubber=10%`` (mm, mm, deg, a percentage or a fraction);
        names not given keep ``base``'s value (default: none, 0)."""
        values = asdict(base) if base is not None else {f.name: 0.0 for f in fields(cls)}
        for item in filter(None, (part.strip() for part in str(text).split(","))):
            name, sep, value = item.partition("=")
            key = SHORT_NAMES.get(name.strip())
            if not sep or key is None:
                raise ValueError(f"tolerance {item[:40]!r} is invalid: expected NAME=VALUE with "
                                 f"NAME one of {', '.join(SHORT_NAMES)}")
            match = re.fullmatch(r"\s*([0-9.eE+-]+)\s*(%?)\s*", value)
            try:
                number = float(match.group(1)) if match else math.nan
            except ValueError:
                number = math.nan
            if not math.isfinite(number):
                raise ValueError(f"tolerance {item[:40]!r} is invalid: expected a number")
            if match.group(2):
                if key != "rubber_fraction":
                    raise ValueError(f"tolerance {item[:40]!r} is invalid: only rubber takes a "
                                     "percentage")
                number /= 100.0
            values[key] = number
        return cls(**values)

    def standard(self) -> dict[str, float]:
        """Standard uncertainties (bound / sqrt 3) of the inputs with a non-zero bound."""
        return {k: v / SQRT3 for k, v in asdict(self).items() if v > 0}


def draws(nominal: dict[str, float], tolerances: Tolerances, n: int,
          rng: np.random.Generator) -> dict[str, np.ndarray]:
    """``n`` joint draws of the muscle's inputs (``D0_mm, t0_mm, L0_mm, eps, theta0_deg,
    C10_MPa, C01_MPa``) around ``nominal``, uniform within the bounds, clipped to
    :data:`mkm.fem.limits.LIMITS` (eps at 0 stays at 0 or above)."""
    bounds = asdict(tolerances)
    out = {}
    for name in ("D0_mm", "t0_mm", "L0_mm", "eps", "theta0_deg"):
        low, high = LIMITS[name][:2]
        # a muscle at eps = 0 cannot be stretched by the rod: draws stay physical
        out[name] = np.clip(nominal[name] + bounds[name] * rng.uniform(-1.0, 1.0, n), low,
                            high if name != "eps" else 0.99)
    factor = 1.0 + bounds["rubber_fraction"] * rng.uniform(-1.0, 1.0, n)
    out["C10_MPa"] = nominal["C10_MPa"] * factor
    out["C01_MPa"] = nominal["C01_MPa"] * factor
    return out
