"""Braid friction and rubber creep around any static force model: the rung the bench shows.

No static model of the ladder has friction or time: their force is one number per pressure. A
real muscle's rising and falling sweeps differ (the braid's threads rub on each other and on the
tube) and its force relaxes during a hold (the silicone creeps). :class:`FrictionCreep` wraps a
static rung with the two smallest models that reproduce both, as the simulated bench
(:mod:`mkm.bench.sim`) defines them, sample by sample (:func:`advance`):

- friction: a play operator whose band is proportional to the force, as Coulomb friction between
  braid threads is (Davis & Caldwell 2006): the force stays inside
  ``[F_static (1 - h), F_static (1 + h)]``, so a rising branch reads ``F_static (1 - h)`` and a
  falling one ``F_static (1 + h)`` (``h``: ``hysteresis_fraction``);
- creep: one relaxation mode, a lag of time constant ``tau`` (``creep_tau_s``) towards losing
  ``c`` (``creep_fraction``) of the force: after a hold of ``t`` s from an unrelaxed start the
  force is ``F (1 - c (1 - exp(-t / tau)))``.

A force that relaxes below zero (after a pressure drop) is zero: a slack muscle cannot push.
The three parameters default to the muscle's identified values in the calibration file in
effect (``mkm identify`` writes them into the static model's entry), else to no friction and no
creep: without identified values the rung is its static model.
"""

from __future__ import annotations

import math

import numpy as np

from mkm.fem.calibration import Calibration, calibrated
from mkm.fem.interface import ForceModel

DIRECTIONS = ("rising", "falling", "mean")
#: the three parameters, as the calibration file and ``mkm identify`` name them
PARAMETERS = ("hysteresis_fraction", "creep_fraction", "creep_tau_s")
DEFAULTS = {"hysteresis_fraction": 0.0, "creep_fraction": 0.0, "creep_tau_s": 30.0}


def advance(hysteretic_N: float, relaxed_N: float, static_N: float, hysteresis_fraction: float,
            creep_fraction: float, relax: float) -> tuple[float, float]:
    """One sample of friction and creep: the new play-operator force and relaxed force [N].

    ``relax`` is ``1 - exp(-dt / creep_tau_s)`` for a sample of ``dt`` s. The muscle pulls
    ``max(hysteretic - relaxed, 0)``.
    """
    h = hysteresis_fraction
    hysteretic = min(max(hysteretic_N, static_N * (1.0 - h)), static_N * (1.0 + h))
    return hysteretic, relaxed_N + (creep_fraction * hysteretic - relaxed_N) * relax


def force_history(time_s, static_N, hysteresis_fraction: float, creep_fraction: float,
                  creep_tau_s: float) -> np.ndarray:
    """The force [N] of a muscle whose static force goes through ``static_N`` at ``time_s`` [s].

    Starts unloaded and unrelaxed before the first sample; each sample goes through
    :func:`advance` with the time since the one before (the first: as long as the second's), as
    the simulated bench does.
    """
    time_s = np.asarray(time_s, dtype=float)
    static = np.asarray(static_N, dtype=float)
    if time_s.shape != static.shape or time_s.ndim != 1:
        raise ValueError(f"time_s {time_s.shape} and static_N {static.shape}: expected two "
                         "1-D arrays of the same length")
    if np.any(np.diff(time_s) < 0):
        raise ValueError("time_s goes backwards: expected the samples in time order")
    dt = np.diff(time_s, prepend=2 * time_s[:1] - time_s[1:2] if time_s.size > 1 else time_s)
    relax = (-np.expm1(-dt / creep_tau_s)).tolist()
    h, c = float(hysteresis_fraction), float(creep_fraction)
    low, high = (static * (1.0 - h)).tolist(), (static * (1.0 + h)).tolist()
    out = []
    hysteretic = relaxed = 0.0
    # advance() inlined, its min/max as comparisons (the same floats, half the time): this loop
    # runs over every sample of a run in each fit evaluation
    for lo, hi, r in zip(low, high, relax, strict=True):
        if hysteretic < lo:
            hysteretic = lo
        if hysteretic > hi:
            hysteretic = hi
        relaxed += (c * hysteretic - relaxed) * r
        out.append(hysteretic - relaxed)
    return np.maximum(np.array(out, dtype=float), 0.0)


def branch_factors(hysteresis_fraction: float, creep_fraction: float, creep_tau_s: float,
                   hold_s: float) -> dict[str, float]:
    """Force over static force on each branch after a hold of ``hold_s`` s from unrelaxed."""
    kept = 1.0 - creep_fraction * (1.0 if math.isinf(hold_s)
                                   else -math.expm1(-hold_s / creep_tau_s))
    h = hysteresis_fraction
    return {"rising": (1.0 - h) * kept, "falling": (1.0 + h) * kept, "mean": kept}


class FrictionCreep(ForceModel):
    """A static force model with braid friction and one creep mode (see the module docstring).

    ``predict(P, D0, t0, eps)`` has no direction and no time, so both are parameters: the force
    is the ``direction`` branch (``rising``, ``falling``, or ``mean``: the static force, between
    them) after a hold of ``hold_s`` s; the extras ``force_rising_N`` and ``force_falling_N``
    hold both branches at once. :meth:`history` gives a whole time trace (branches and
    relaxation as they happen, turning points included).

    Parameters
    ----------
    static : str
        The wrapped rung of the ladder (``axisym``, ``thickwall``, ``eq2``); default ``axisym``.
    direction : {"rising", "falling", "mean"}
        The branch ``force_N`` holds; default ``rising`` (a staircase measured upwards).
    hold_s : float
        Time held at the pressure [s], from an unrelaxed start; default 0 (no relaxation yet);
        ``inf``: relaxed.
    hysteresis_fraction, creep_fraction : float, optional
        Half-width of the friction band and share of the force creep relaxes (fractions).
        Default: the static model's calibration entry, else 0.
    creep_tau_s : float, optional
        Creep time constant [s]; default the calibration entry's, else 30.
    mesh, theta0_deg, L0_mm, C10_MPa, C01_MPa, calibration
        Passed to the static model (those it takes); the calibration also holds the friction
        and creep terms.
    """

    name = "friction"

    def __init__(self, static: str = "axisym", direction: str = "rising", hold_s: float = 0.0,
                 hysteresis_fraction: float | None = None, creep_fraction: float | None = None,
                 creep_tau_s: float | None = None, calibration: Calibration | None = None,
                 **static_params):
        from mkm.fem.ladder import make_model

        if static == self.name:
            raise ValueError("friction:static=friction is invalid: expected a static rung")
        if direction not in DIRECTIONS:
            raise ValueError(f"direction={direction!r} is invalid: expected one of "
                             f"{', '.join(DIRECTIONS)}")
        if not hold_s >= 0:
            raise ValueError(f"hold_s={hold_s!r} is invalid: expected a time >= 0 s")
        self.static_model = make_model(static, calibration=calibration, **static_params)
        self.calibration = calibration
        self.static, self.direction, self.hold_s = static, direction, float(hold_s)
        self._given = {"hysteresis_fraction": hysteresis_fraction,
                       "creep_fraction": creep_fraction, "creep_tau_s": creep_tau_s}
        for key, value in self._given.items():
            if value is not None:
                _check(key, value)
        self.domain = self.static_model.domain
        self.has_threshold = self.static_model.has_threshold

    @property
    def calibration_key(self) -> str:
        return self.static_model.calibration_key

    @property
    def terms(self) -> dict[str, float]:
        """The friction and creep parameters in effect (given, else calibrated, else none)."""
        entry = {}
        if any(v is None for v in self._given.values()):
            try:
                entry = calibrated(self.calibration_key, self.calibration)
            except ValueError:  # no entry for the static model: no identified friction
                entry = {}
        return {k: float(v if v is not None else entry.get(k, DEFAULTS[k]))
                for k, v in self._given.items()}

    def params(self):
        return {"static": self.static, "direction": self.direction, "hold_s": self.hold_s,
                **self.terms, **self.static_model.params()}

    def _forces(self, P, D0, t0, eps):
        static = self.static_model.predict(P, D0, t0, eps)
        factors = branch_factors(**self.terms, hold_s=self.hold_s)
        force = np.asarray(static.force_N)
        return {**static.extras, "force_N": force * factors[self.direction],
                "valid": static.valid, "converged": static.converged,
                "force_rising_N": force * factors["rising"],
                "force_falling_N": force * factors["falling"]}

    def history(self, time_s, pressure_bar, D0_mm: float, t0_mm: float, eps: float,
                table_bar: float = 0.05) -> np.ndarray:
        """Force [N] along a pressure trace ``pressure_bar`` at ``time_s`` [s] (1-D arrays).

        The static model is computed on a grid of ``table_bar`` over the trace's range and
        interpolated (as the simulated bench tabulates it). Raises ``ValueError`` where the
        static model has no valid force.
        """
        pressure = np.clip(np.asarray(pressure_bar, dtype=float), 0.0, None)
        grid = np.arange(0.0, pressure.max() + 2 * table_bar, table_bar)
        static = self.static_model.predict(grid, D0_mm, t0_mm, eps)
        if not static.valid.all():
            raise ValueError(f"{self.static} has no valid force at some pressure in "
                             f"0-{grid[-1]:g} bar for D0_mm={D0_mm:g}, t0_mm={t0_mm:g}, "
                             f"eps={eps:g}")
        return force_history(time_s, np.interp(pressure, grid, static.force_N), **self.terms)


def _check(name: str, value: float) -> None:
    low, high = (1e-3, 1e5) if name == "creep_tau_s" else (0.0, 0.5)
    if not low <= value <= high:
        unit = "s" if name == "creep_tau_s" else "(a fraction)"
        raise ValueError(f"{name}={value:g} is invalid: expected {low:g} to {high:g} {unit}")
