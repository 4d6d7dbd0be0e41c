"""Fresh random muscles from the practical range (:data:`mkm.fem.limits.PRACTICAL_RANGE`).

:func:`draw_muscles` is how benchmarks, the stability map and surrogate validation get muscles
nobody chose: each draw records its seed, so a table of results names the muscles it was
measured on and can be measured again.

How a muscle is drawn (every number inside the box and its coupled constraints, by
construction, never by rejection):

- ``D0_mm`` log-uniform over the box (a 6 mm tube is as much a muscle as a 60 mm one);
- ``t0_mm`` log-uniform from the thinnest wall to ``min(t0 high, t0_per_D0_max * D0)``;
- ``L0_mm`` log-uniform from ``max(L0 low, L0_per_D0_min * D0)`` to the longest;
- ``theta0_deg`` uniform; ``eps`` uniform from the box's lowest to ``lock_fraction`` of its
  highest fraction of the braid lock at that angle (at the lock itself the force is zero and
  every model's answer there is "no force", not a test);
- ``C10_MPa`` log-uniform (soft silicone to chloroprene spans a factor 20), ``C01_MPa`` the
  C10 times a ratio uniform over ``C01_per_C10``.

The muscles come from one ``(n, 7)`` block of uniforms read row by row, so the first ``k``
muscles of a draw of ``n`` are the draw of ``k`` with the same seed.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from mkm.fem.limits import PRACTICAL_RANGE, PracticalRange, lock_eps
from mkm.fem.muscle import NUMBERS, Muscle

#: the largest eps drawn, as a fraction of the box's top of the braid lock
LOCK_FRACTION = 0.95


@dataclass(frozen=True)
class Draw:
    """Muscles drawn from a box, with what it takes to draw them again.

    Attributes
    ----------
    seed : int
        The seed of :func:`numpy.random.default_rng` they were drawn with.
    box : PracticalRange
        The box they were drawn from.
    lock_fraction : float
        The largest eps drawn, as a fraction of the box's top of the braid lock.
    muscles : tuple of Muscle
        The muscles, in the order drawn.
    """

    seed: int
    box: PracticalRange
    lock_fraction: float
    muscles: tuple[Muscle, ...]

    def record(self) -> dict[str, Any]:
        """What an output records of the draw (its provenance): the seed, the count, the box."""
        return {"seed": self.seed, "muscles": len(self.muscles),
                "lock_fraction": self.lock_fraction,
                "box": {name: list(getattr(self.box, name)) for name in self.box.INTERVALS}
                | {"t0_per_D0_max": self.box.t0_per_D0_max,
                   "L0_per_D0_min": self.box.L0_per_D0_min}}

    def columns(self) -> dict[str, np.ndarray]:
        """The muscles as one array per number (:data:`mkm.fem.muscle.NUMBERS`)."""
        return {name: np.array([getattr(m, name) for m in self.muscles], dtype=float)
                for name in NUMBERS}


def _log_uniform(u, low, high):
    return np.exp(np.log(low) + u * (np.log(high) - np.log(low)))


def draw_muscles(n: int, seed: int | None = None, box: PracticalRange = PRACTICAL_RANGE,
                 lock_fraction: float = LOCK_FRACTION) -> Draw:
    """``n`` fresh random muscles from ``box`` (see the module docstring for how).

    Parameters
    ----------
    n : int
        How many muscles.
    seed : int, optional
        Seed of the draw; None: a fresh one from the operating system, recorded in the result.
    box : PracticalRange
        Where to draw from; default the practical range.
    lock_fraction : float
        The largest eps drawn as a fraction of the box's top of the braid lock, in (0, 1].

    Returns
    -------
    Draw
        The muscles and their seed.
    """
    if isinstance(n, bool) or not isinstance(n, int | np.integer) or n < 0:
        raise ValueError(f"n={n!r} is invalid: expected a count of muscles >= 0")
    if not 0.0 < lock_fraction <= 1.0:
        raise ValueError(f"lock_fraction={lock_fraction!r} is invalid: expected in (0, 1]")
    if seed is None:
        seed = int(np.random.SeedSequence().entropy % 2**63)
    u = np.random.default_rng(seed).random((int(n), 7))
    D0 = _log_uniform(u[:, 0], *box.D0_mm)
    t0_high = np.minimum(box.t0_mm[1], box.t0_per_D0_max * D0)
    if np.any(t0_high < box.t0_mm[0]):
        raise ValueError(f"box={box!r} is invalid: no wall fits the thinnest tube")
    t0 = _log_uniform(u[:, 1], box.t0_mm[0], t0_high)
    L0_low = np.maximum(box.L0_mm[0], box.L0_per_D0_min * D0)
    if np.any(L0_low > box.L0_mm[1]):
        raise ValueError(f"box={box!r} is invalid: the widest tube is longer than the longest "
                         "muscle")
    L0 = _log_uniform(u[:, 2], L0_low, box.L0_mm[1])
    theta0 = box.theta0_deg[0] + u[:, 3] * (box.theta0_deg[1] - box.theta0_deg[0])
    lock = lock_eps(theta0)
    low, high = box.eps_per_lock[0], box.eps_per_lock[1] * lock_fraction
    eps = (low + u[:, 4] * (high - low)) * lock
    C10 = _log_uniform(u[:, 5], *box.C10_MPa)
    ratio = box.C01_per_C10[0] + u[:, 6] * (box.C01_per_C10[1] - box.C01_per_C10[0])
    muscles = tuple(Muscle(D0_mm=float(d), t0_mm=float(t), L0_mm=float(length), eps=float(e),
                           theta0_deg=float(a), C10_MPa=float(c), C01_MPa=float(c * r))
                    for d, t, length, e, a, c, r in zip(D0, t0, L0, eps, theta0, C10, ratio,
                                                        strict=True))
    return Draw(int(seed), box, float(lock_fraction), muscles)
