"""What a configuration will ask of the muscle and the load cell, said before a run starts.

- :func:`braid_lock`: whether ``muscle.eps`` shortens the braid past its locking angle, where
  Equation 2 leaves its range and the muscle pulls little or nothing (``mkm acquire`` refuses
  such a run unless told ``--allow-past-lock``; ``mkm check`` warns);
- :func:`loadcell_warning`: whether the muscle's expected force at the highest planned pressure
  (Equation 2, the paper's model) reaches the force interlock, which would stop the run there.
  A warning, not a refusal: the interlock protects the cell.

Both read one braid angle: the muscle's ``theta0_deg`` when the configuration gives it, else
the FE model's calibrated one (:func:`mkm.fem.eq2.braid_lock` says which).
"""

from __future__ import annotations

from mkm.fem.eq2 import BraidLock, chou_hannaford
from mkm.fem.eq2 import braid_lock as fem_braid_lock


def muscle_lock(config) -> BraidLock:
    """The braid lock of the configured muscle, at its own angle or the calibrated one."""
    return fem_braid_lock(config.muscle.theta0_deg)


def braid_lock(config) -> str | None:
    """The message when ``config.muscle.eps`` is at or past the braid lock
    (:func:`mkm.fem.eq2.braid_lock`, the one definition every command uses), else None."""
    lock = muscle_lock(config)
    if config.muscle.eps < lock.eps_max:
        return None
    return (f"eps {config.muscle.eps:g} is past the braid lock, {lock}; the muscle pulls "
            "little or nothing there")


def expected_force_N(config, pressure_bar: float | None = None) -> float:
    """Equation 2's force [N] of the muscle at ``pressure_bar`` (default: the highest planned
    pressure), 0 past the lock."""
    m = config.muscle
    if pressure_bar is None:
        pressure_bar = max(config.sequence.pressures_bar)
    force = chou_hannaford(pressure_bar, m.D0_mm, m.eps, muscle_lock(config).theta0_deg)
    return max(float(force), 0.0)


def loadcell_warning(config) -> str | None:
    """The message when the expected force reaches the force interlock, else None."""
    force, limit = expected_force_N(config), config.force_limit_N
    if force < limit:
        return None
    top = max(config.sequence.pressures_bar)
    return (f"the muscle develops about {force:.0f} N at {top:g} bar (Equation 2), beyond the "
            f"force interlock at {limit:.0f} N ({config.safety.force_limit_fraction:g} x "
            f"loadcell.capacity_N={config.loadcell.capacity_N:g}): the run will stop there; use "
            "a larger load cell")


def warnings(config) -> list[str]:
    """Every preflight message for ``config`` (braid lock, load cell)."""
    return [w for w in (braid_lock(config), loadcell_warning(config)) if w]
