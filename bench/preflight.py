"""What a configuration will ask of the muscle and the load cell, said before a run starts.

- :func:`braid_lock`: whether ``muscle.eps`` shortens the braid past its locking angle, where
  Equation 2 leaves its range and the muscle pulls little or nothing (``mkm acquire`` refuses
  such a run unless told ``--allow-past-lock``; ``mkm check`` warns);
- :func:`loadcell_warning`: whether the muscle's force at the highest planned pressure may reach
  the force interlock, which stops the run there: pre-conditioning goes to that pressure first,
  so before any step is recorded. The force is bounded from above by Equation 2 on the braid's
  diameter ``D0 + 2 (t0 + gap)`` (the FE model's force at eps 0; above it at any eps, where the
  rubber takes its share) at the strongest muscle the declared tolerances allow: the paper's
  form on the inner diameter ``D0`` is (1 + 2 t0 / D0)^2 lower, 1.7 times on a 5 mm tube with a
  0.8 mm wall. A warning, not a refusal: the interlock protects the cell. So is a cell the
  muscle's largest force uses less than a tenth of (:func:`oversized_warning`);
- :func:`limits_warning`: whether a settle or noise limit in newtons (``[settle]
  max_force_std_N``, ``max_force_slope_N_per_s``, ``[safety] tare_max_std_N``) lets more than
  :data:`LIMIT_SHARE` of the force the muscle pulls at its lowest planned step into a step's
  force, with the values that take the share the packaged example's take of its muscle's;
- :func:`slack_warning`: whether the muscle pulls at its eps at all up to the highest planned
  pressure (the thick-wall model's threshold, which Equation 2 has not: a share of its force at
  its rest length, :data:`SLACK_FRACTION`);
- :func:`practical_range_warning`: whether the declared muscle or the planned pressures leave the
  practical range, where every model's force is an extrapolation.

The first two read one braid angle: the muscle's ``theta0_deg`` when the configuration gives
it, else the FE model's calibrated one (:func:`mkm.fem.eq2.braid_lock` says which).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from mkm.bench import backends
from mkm.bench.config import MIN_FORCE_LIMIT_FRACTION, load_config, plan_steps
from mkm.fem.eq2 import BraidLock, chou_hannaford
from mkm.fem.eq2 import braid_lock as fem_braid_lock
from mkm.fem.limits import LIMITS, PRACTICAL_RANGE
from mkm.fem.tolerances import Tolerances


def muscle_lock(config, ceiling: ForceCeiling | None = None) -> BraidLock:
    """The braid lock of the configured muscle, at its own angle, else at the angle identified
    in the calibration that arms the over-force interlock (``ceiling``), else at the calibrated
    one."""
    if config.muscle.theta0_deg is None and ceiling is not None and ceiling.theta0_deg:
        return replace(fem_braid_lock(ceiling.theta0_deg),
                       source=f"the braid angle of {ceiling.source}")
    return fem_braid_lock(config.muscle.theta0_deg)


def braid_lock(config, ceiling: ForceCeiling | None = None) -> str | None:
    """The message when ``config.muscle.eps`` is at or past the braid lock
    (:func:`mkm.fem.eq2.braid_lock`, the one definition every command uses; at the identified
    angle with ``ceiling``: :func:`muscle_lock`), else None."""
    lock = muscle_lock(config, ceiling)
    if config.muscle.eps < lock.eps_max:
        return None
    return (f"eps {config.muscle.eps:g} is past the braid lock, {lock}; the muscle pulls "
            "little or nothing there")


def expected_force_N(config, pressure_bar: float | None = None, strongest: bool = False,
                     eps: float | None = None) -> float:
    """Equation 2's force [N] on the braid's diameter ``D0 + 2 (t0 + gap)`` at ``pressure_bar``
    (default: the highest planned pressure) and ``eps`` (default the muscle's), 0 past the
    lock: the FE model's force at eps 0, an upper bound of it at any eps. ``strongest``: at the
    muscle's declared tolerances' strongest (``D0`` and ``t0`` at their upper bounds,
    ``theta0`` and ``eps`` at their lower ones)."""
    m, lock = config.muscle, muscle_lock(config)
    if pressure_bar is None:
        pressure_bar = max(config.sequence.pressures_bar)
    eps = m.eps if eps is None else eps
    tol = m.tolerances if strongest else Tolerances(0.0, 0.0, 0.0, 0.0, 0.0)
    braid_mm = m.D0_mm + tol.D0_mm + 2 * (m.t0_mm + tol.t0_mm + (m.gap_mm or 0.0))
    theta0 = max(lock.theta0_deg - tol.theta0_deg, LIMITS["theta0_deg"][0])
    force = chou_hannaford(pressure_bar, braid_mm, max(eps - tol.eps, 0.0), theta0)
    return max(float(force), 0.0)


def loadcell_warning(config) -> str | None:
    """The message when the muscle's force may reach the force interlock (how much, from which
    planned step, that pre-conditioning stops the run before its first step, and the capacity
    a cell needs), or when its largest force, at eps 0 and the bench's highest pressure, stays below
    :data:`~mkm.bench.config.MIN_FORCE_LIMIT_FRACTION` of the cell's capacity (the noise, the
    ADC step and the data sheet's errors of a cell are fractions of its capacity: the cell is
    the wrong size); else None."""
    force, limit = expected_force_N(config, strongest=True), config.force_limit_N
    if force < limit:
        return oversized_warning(config)
    seq, top = config.sequence, max(config.sequence.pressures_bar)
    first = min(p for p in seq.pressures_bar if expected_force_N(config, p, True) >= limit)
    where = (f"pre-conditioning to {top:g} bar stops the run before its first step"
             if seq.preconditioning_cycles else
             f"the run stops at its first step at {first:g} bar")
    return (f"the muscle may develop {force:.0f} N at {top:g} bar (Equation 2 on the braid's "
            f"diameter, at its declared tolerances' strongest), beyond the force interlock at "
            f"{limit:.0f} N ({config.safety.force_limit_fraction:g} x loadcell.capacity_N="
            f"{config.loadcell.capacity_N:g}) from {first:g} bar: {where}; use a load cell of "
            f"at least {force / config.safety.force_limit_fraction:.0f} N")


def oversized_warning(config) -> str | None:
    """The message when the muscle's largest force, Equation 2 on the braid's diameter at eps 0
    and the bench's highest pressure (``regulator.max_pressure_bar``: the cell serves every run
    of the muscle, whatever its eps and staircase), is below a tenth of the load cell's
    capacity, else None. It names what one ADC step and the data sheet's non-linearity take of
    the force at the lowest planned step (:func:`lowest_step`)."""
    cell, top = config.loadcell, config.regulator.max_pressure_bar
    largest_N = expected_force_N(config, top, eps=0.0)
    if largest_N >= MIN_FORCE_LIMIT_FRACTION * cell.capacity_N or largest_N <= 0:
        return None
    low_N = expected_force_N(config, top, True, 0.0) / config.safety.force_limit_fraction
    high_N = largest_N / MIN_FORCE_LIMIT_FRACTION
    low_bar, force_N = lowest_step(config)
    step_N = adc_step_N(config)
    linearity_N = cell.nonlinearity_fraction_fs * cell.capacity_N
    return (f"the muscle develops at most about {largest_N:.3g} N at {top:g} bar (Equation 2 on "
            f"the braid's diameter at eps 0), {100 * largest_N / cell.capacity_N:.2g} % of "
            f"loadcell.capacity_N={cell.capacity_N:g}: the cell's noise, ADC step and data-sheet "
            f"errors, fractions of its capacity, weigh on every force (`mkm check`'s expected "
            f"uncertainty): at the lowest step, {low_bar:g} bar, the muscle pulls about "
            f"{force_N:.2g} N, of which one ADC step ({step_N:.2g} N) is "
            f"{percent(step_N / force_N)} % and the cell's non-linearity ({linearity_N:.2g} N) "
            f"{percent(linearity_N / force_N)} %; a cell of {low_N:.3g} to {high_N:.3g} N "
            f"capacity ({low_N / G_N_PER_KG:.2g} to {high_N / G_N_PER_KG:.2g} kg) suits this "
            "muscle")


def adc_step_N(config) -> float:
    """One ADC step of the configured backend's input through the load cell [N]."""
    return (backends.entry(config.daq.backend).capabilities.ai_lsb_V
            * config.loadcell.sensitivity_N_per_V)


#: Standard gravity [N/kg]: load cells are sold by the mass they weigh
G_N_PER_KG = 9.80665
#: A settle or noise limit in newtons that lets more than this share of the force the muscle
#: pulls at its lowest planned step into a step's force is sized for a stronger muscle: the
#: packaged example's limits take at most 5.2 % of its muscle's (95 N at 0.25 bar), about
#: half of it.
LIMIT_SHARE = 0.1
#: The limits that bound a step's force: the setting, and what it lets into the force [N]
#: from its value (a hold's or a tare's scatter; a trend over the hold, judged settled)
FORCE_LIMITS = (
    ("settle.max_force_std_N", lambda c, v: v, "a hold scattering {:.2g} N rms"),
    ("settle.max_force_slope_N_per_s", lambda c, v: v * c.settle.hold_s,
     "{:.2g} N of trend over the hold"),
    ("safety.tare_max_std_N", lambda c, v: v, "a tare, taken off every force, scattering "
     "{:.2g} N rms"),
)


def lowest_step(config) -> tuple[float, float]:
    """The lowest planned pressure above 0 bar [bar] and the force [N] the muscle pulls there
    at its rest length (Equation 2 on the braid's diameter, the thick-wall model's force at eps
    0): the force the settle and noise limits and the load cell are judged against, at eps 0 as
    the cell is, so every run of the muscle on one configuration says the same (at eps > 0 the
    steps near the threshold pull a small share of any muscle's force). A 0 bar step reads the
    cell's zero, no pull; a plan of 0 bar alone gives ``(0.0, 0.0)``."""
    low_bar = min((p for p in config.sequence.pressures_bar if p > 0), default=0.0)
    return low_bar, expected_force_N(config, low_bar, eps=0.0)


def _limit(config, name: str, allowed) -> tuple[float, float]:
    """The value of the limit ``name`` (``section.key``) in ``config`` and what it lets into a
    step's force [N]."""
    section, key = name.split(".")
    value = getattr(getattr(config, section), key)
    return value, allowed(config, value)


#: The limits on the load cell's scatter, what a cell that fails one does, and the multiple of
#: the cell's spread at rest below which it fails it: a hold settles under three times it
#: (:func:`mkm.bench.sequence.settle_warning` asks for as much); a tare of 20 readings or more
#: spreads within a sixth of it (the sample spread's relative error, 1 / sqrt(2 (n - 1))), so
#: half as much again passes it
SPREAD_LIMITS = {"settle.max_force_std_N": ("settles under no", 3.0),
                 "safety.tare_max_std_N": ("passes no tare under a", 1.5)}


def limits_warning(config, rest_std_N: float | None = None) -> str | None:
    """The message when a limit of :data:`FORCE_LIMITS` lets more than :data:`LIMIT_SHARE` of
    the force at the lowest planned step (:func:`lowest_step`) into a step's force, naming each
    such limit, its value, its share and a value to set: the share the packaged example's
    takes of its muscle's force at its lowest step. A warning, not a scaled default: a value
    the configuration states is the one its runs use and record. ``rest_std_N``: the load
    cell's spread read at rest [N] (``mkm check``'s); a value to set of :data:`SPREAD_LIMITS`
    below its multiple of it is one this cell cannot meet (no step would settle, or no tare
    pass), and the message says the cell is too noisy for the muscle."""
    low_bar, force_N = lowest_step(config)
    if force_N <= 0:
        return None
    loose = [(name, allowed, what, *_limit(config, name, allowed))
             for name, allowed, what in FORCE_LIMITS]
    loose = [limit for limit in loose if limit[-1] > LIMIT_SHARE * force_N]
    if not loose:
        return None
    packaged = load_config()
    packaged_bar, packaged_N = lowest_step(packaged)
    said, to_set, unmet = [], [], []
    for name, allowed, what, value, allowed_N in loose:
        share = _limit(packaged, name, allowed)[1] / packaged_N
        passes = "" if said else "passes "
        said.append(f"{name}={value:g} {passes}{percent(allowed_N / force_N)} % "
                    f"({what.format(allowed_N)})")
        suggested = value * share * force_N / allowed_N
        to_set.append(f"{name} to about {suggested:.2g}")
        fails, sigmas = SPREAD_LIMITS.get(name, ("", 0.0))
        if rest_std_N is not None and suggested < sigmas * rest_std_N:
            floor_N = sigmas * rest_std_N
            unmet.append(f"{fails} {name} below about {floor_N:.2g} N ({sigmas:g} times it, "
                         f"{percent(floor_N / force_N)} % of that force)")
    cell = (f"; but this load cell spreads {rest_std_N:.2g} N rms at rest: it "
            f"{_listed(unmet)}, too noisy for this muscle: use a quieter or smaller cell"
            if unmet else "")
    return (f"the settle and noise limits are sized for a stronger muscle: at its lowest step, "
            f"{low_bar:g} bar, this one pulls about {force_N:.2g} N (Equation 2 on the braid's "
            f"diameter at eps 0), and these limits pass more than {100 * LIMIT_SHARE:g} % of it "
            f"into a step: {_listed(said)}; set {_listed(to_set)} (the share the packaged "
            f"example's take of the {packaged_N:.0f} N its muscle pulls at {packaged_bar:g} bar)"
            f"{cell}")


def percent(share: float) -> str:
    """``share`` in percent to two digits, without an exponent (``1.6``, ``23``, ``130``)."""
    return f"{100 * share:.0f}" if share >= 0.1 else f"{100 * share:.2g}"


def _listed(items: list[str]) -> str:
    """``a``, ``a and b``, ``a, b and c``."""
    return items[0] if len(items) == 1 else f"{', '.join(items[:-1])} and {items[-1]}"


def practical_range_warning(config) -> str | None:
    """The message when the declared muscle or the highest planned pressure lies outside the
    practical range every model is validated over (:data:`mkm.fem.limits.PRACTICAL_RANGE`),
    else None: the run records it all the same, every model's force for it extrapolates."""
    m = config.muscle
    numbers = {k: getattr(m, k) for k in ("D0_mm", "t0_mm", "L0_mm", "theta0_deg", "C10_MPa",
                                          "C01_MPa") if getattr(m, k) is not None}
    outside = PRACTICAL_RANGE.violations(pressure_bar=max(config.sequence.pressures_bar),
                                         **numbers)
    if not outside:
        return None
    return (f"the muscle lies outside the practical range every model is validated over "
            f"({'; '.join(outside)}): its runs are recorded all the same, but every model's "
            "force for them (the report's, identify's, the simulated bench's) is an "
            "extrapolation (`mkm models` states the range)")


def thickwall_force_N(config, pressure_bar: float, eps: float) -> float:
    """The thick-wall model's force [N] of the configured muscle at ``pressure_bar`` and
    ``eps``, at the braid angle the other checks read (:func:`muscle_lock`): a closed form
    whose wall holds the braid below a threshold pressure, which Equation 2 has not."""
    return float(_thickwall_N(config, float(pressure_bar), eps))


def _thickwall_N(config, pressure_bar, eps: float, side: int = 0):
    """:func:`thickwall_force_N` over an array of pressures; ``side`` +1 at the declared
    tolerances' strongest muscle (``D0`` up, ``t0``, ``theta0`` and ``eps`` down), -1 at
    their weakest, 0 as declared. Where the model gives no force (past the lock), 0."""
    from mkm.fem.ladder import make_model  # the models' registry: only where asked

    m, tol = config.muscle, config.muscle.tolerances
    theta0 = max(muscle_lock(config).theta0_deg - side * tol.theta0_deg, LIMITS["theta0_deg"][0])
    model = make_model("thickwall", muscle=m, theta0_deg=theta0)
    prediction = model.predict(pressure_bar, m.D0_mm + side * tol.D0_mm,
                               m.t0_mm - side * tol.t0_mm, max(eps - side * tol.eps, 0.0))
    force = np.where(prediction.valid, prediction.force_N, 0.0)
    return np.maximum(np.nan_to_num(force, nan=0.0), 0.0)


#: The share of the thick-wall model's force at the declared tolerances' weakest muscle that the
#: muscle surely pulls: the FE model (the simulated muscle) pulls that force or more on the
#: paper's prototype at eps 0 to 0.3 wherever it gives 2 N or more, and at most the model's
#: force at their strongest (both held by ``tests/bench/test_safety.py``); the half is left for
#: a rubber or braid beyond the declaration and for the braid's friction.
SURE_FRACTION = 0.5
#: Braid friction: a force held as the pressure falls reads up to this share above the static
#: one (Davis & Caldwell 2006 report loops of several %; the simulator's play is 3 %).
FRICTION_FRACTION = 0.1
#: Creep: a muscle's force loses at most this share of itself as the rubber relaxes: silicone
#: relaxes by a few % over a minute's hold (identify's
#: :data:`~mkm.identify.procedure.UNTIMED_CREEP_FRACTION`, 3 %; the simulator's 2 %).
CREEP_FRACTION = 0.05



#: the over-force interlock judges readings from this fraction of ``max_pressure_bar`` up: a
#: monitor reading low hides over-pressure only near the limit (one reading 0.8 of the pressure
#: hides it from 0.8 of the limit), and one that reads less than half the pressure its
#: regulator holds (frozen near 0 bar) is the follow and stuck-monitor interlocks'; below it a
#: load cell's zero drifting beyond its data sheet is no over-pressure
OVERFORCE_FROM_FRACTION = 0.5


@dataclass(frozen=True)
class ForceCeiling:
    """The most an identified muscle pulls at the run's eps: ``force_N`` [N] at each of
    ``pressure_bar`` [bar] (its static force plus its 95 % prediction band's upper end), the
    least ``least_N`` [N] (its static force less the band's lower end, at least 0), the
    braid's friction's upper end ``friction_fraction`` (a falling pressure leaves that share of
    the static force in, a rising one takes it off), and ``source``, what it was identified in
    (said where it trips). Built by the application from a calibration of ``mkm identify``
    (:func:`mkm.identify.band.force_ceiling`); the over-force interlock's bound
    (:meth:`most_N`, :meth:`mkm.bench.worker.Acquisition.overforce`)."""

    pressure_bar: tuple[float, ...]
    force_N: tuple[float, ...]
    least_N: tuple[float, ...]
    friction_fraction: float
    source: str
    theta0_deg: float | None = None  # the identified braid angle, where identify fitted it

    def record(self) -> dict:
        """What run.json's ``calibration`` records of it (``force_ceiling``)."""
        return {"force_ceiling": {"source": self.source,
                                  "friction_fraction": self.friction_fraction}}

    def most_N(self, config, reading_bar: float, peak_bar: float) -> tuple[float, str]:
        """The most [N] the load cell may read at the monitor's ``reading_bar`` [bar], the
        highest reading since the muscle was last vented being ``peak_bar``, and where that
        bound comes from: the ceiling at the reading taken its declared accuracy high
        (``[regulator]``) with the friction, but no more than the ceiling at the peak so taken
        (the braid holds a force at most at what that pressure pulled up), times ``1 +
        safety.overforce_margin_fraction``."""
        offset_bar, gain = config.regulator.reading_bounds()
        high_bar = reading_bar + offset_bar + gain * reading_bar
        friction = self.friction_fraction
        most = (1.0 + friction) * self.most_rising_N(config, reading_bar)
        where = (f"at {high_bar:.3f} bar, the reading at its accuracy, with its 95 % band and "
                 f"{100 * friction:.3g} % for the braid's friction")
        rise = self.most_rising_N(config, peak_bar)
        if rise < most:
            peak_bar = peak_bar + offset_bar + gain * peak_bar
            most, where = rise, (f"at {peak_bar:.3f} bar, the highest reading since the vent "
                                 "at its accuracy, with its 95 % band: the braid holds no more "
                                 "than that pressure pulled")
        margin = config.safety.overforce_margin_fraction
        if margin > 0:
            most *= 1.0 + margin
            where += f", plus safety.overforce_margin_fraction={margin:g}"
        return most, where

    def most_rising_N(self, config, reading_bar: float) -> float:
        """The most [N] the muscle pulls on a rise to the monitor's ``reading_bar`` [bar], and
        held at any pressure after it (the braid holds no more than that pressure pulled): the
        ceiling at the reading taken its declared accuracy high."""
        offset_bar, gain = config.regulator.reading_bounds()
        high_bar = reading_bar + offset_bar + gain * reading_bar
        return float(np.interp(high_bar, self.pressure_bar, self.force_N))

    def least_rising_N(self, config, reading_bar: float) -> float:
        """The least [N] the muscle pulls on a rise to the monitor's ``reading_bar`` [bar]: the
        ceiling's least at the reading taken its declared accuracy low, the friction taken
        off."""
        offset_bar, gain = config.regulator.reading_bounds()
        low_bar = max(reading_bar - offset_bar - gain * reading_bar, 0.0)
        return ((1.0 - self.friction_fraction)
                * float(np.interp(low_bar, self.pressure_bar, self.least_N)))


def ceiling_lines(config, ceiling: ForceCeiling) -> tuple[list[str], str]:
    """What the over-force interlock holds each planned step of ``config`` to
    (:meth:`ForceCeiling.most_N`, at the step's pressure read as commanded, the peak since
    the vent the highest step since a step below ``safety.vent_below_bar``), below the force
    interlock's limit, in lines for ``mkm check``; and why the plan must trip ("" when it need
    not): the identified muscle pulls at least the force interlock's limit on the rise to the
    top step (:meth:`ForceCeiling.least_rising_N`), which pre-conditioning or the staircase
    reaches first."""
    limit_N, top = config.force_limit_N, max(config.sequence.pressures_bar)
    watched_bar = OVERFORCE_FROM_FRACTION * config.regulator.max_pressure_bar
    lines = [f"over-force ceiling: {ceiling.source} at eps {config.muscle.eps:g}, its 95 % band "
             f"and {100 * ceiling.friction_fraction:.3g} % friction, at the reading taken its "
             "accuracy high; rising, no more than at the highest reading since the vent (the "
             "braid holds no more than that pressure pulled); watched from "
             f"{watched_bar:g} bar ({OVERFORCE_FROM_FRACTION:g} x regulator.max_pressure_bar), "
             f"the force interlock at {limit_N:.0f} N above it:",
             f"{'step':>6} {'P [bar]':>8} {'most [N]':>9}  held by"]
    peak = 0.0  # pre-conditioning, if any, ends vented
    for s in plan_steps(config):
        below = s.set_pressure_bar <= config.safety.vent_below_bar
        peak = s.set_pressure_bar if below else max(peak, s.set_pressure_bar)
        if s.set_pressure_bar < watched_bar:
            most, by = "", "not watched"
        else:
            most_N, where = ceiling.most_N(config, s.set_pressure_bar, peak)
            by = "the peak since the vent" if "highest reading" in where else \
                "the reading with the friction"
            if not most_N < limit_N:
                most_N, by = limit_N, "the force interlock"
            most = f"{most_N:.1f}"
        lines.append(f"{s.step:>6} {s.set_pressure_bar:>8g} {most:>9}  {s.direction}, {by}")
    least_N = ceiling.least_rising_N(config, top)
    if least_N >= limit_N:
        return lines, (f"the muscle identified pulls at least {least_N:.0f} N on the rise to the "
                       f"top step, {top:g} bar ({ceiling.source}: its force less its 95 % band "
                       f"and friction, at the reading at its accuracy), at or beyond the force "
                       f"interlock at {limit_N:.0f} N ({config.safety.force_limit_fraction:g} x "
                       f"loadcell.capacity_N={config.loadcell.capacity_N:g}): the run must stop "
                       f"there; lower the top pressure to {_below(ceiling, config):g} bar or "
                       "less, or use a larger load cell")
    lines.append(f"the top step, {top:g} bar: the muscle identified pulls at least "
                 f"{least_N:.0f} N on its rise, under the force interlock at {limit_N:.0f} N")
    return lines, ""


def _below(ceiling: ForceCeiling, config) -> float:
    """The highest pressure [bar], to 0.05 bar, on the rise to which the identified muscle
    surely pulls less than the force interlock's limit (:meth:`ForceCeiling.most_rising_N`:
    a run whose muscle may pull the limit there may trip as well)."""
    grid = np.arange(0.0, config.regulator.max_pressure_bar + 1e-9, 0.05)
    under = [p for p in grid if ceiling.most_rising_N(config, p) < config.force_limit_N]
    return float(round(max(under), 2)) if under else 0.0


def force_bounds_N(config, n: int = 1001) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """What the configured muscle at its eps pulls at least and at most [N] at ``n``
    pressures [bar] from 0 to 1.1 x ``regulator.max_pressure_bar`` (the over-pressure
    interlock's hard bound): the thick-wall model at the declared tolerances' weakest muscle
    times :data:`SURE_FRACTION`, and at their strongest one plus :data:`FRICTION_FRACTION`. The
    force at a fixed length rises with the pressure, from the threshold on (none below it, at
    the lower bound's eps past the lock none at all), so the forces at ``low`` and ``high``
    differ by ``least(high) - most(low)`` or more, whichever came first: the stuck-cell
    interlock of a quiet load cell (:meth:`mkm.bench.worker.Acquisition.unmoved_cell`)."""
    pressure_bar = np.linspace(0.0, 1.1 * config.regulator.max_pressure_bar, n)
    eps = config.muscle.eps
    least = SURE_FRACTION * _thickwall_N(config, pressure_bar, eps, -1)
    most = (1.0 + FRICTION_FRACTION) * _thickwall_N(config, pressure_bar, eps, +1)
    return pressure_bar, least, most


def bound_assumes(config) -> str:
    """What :func:`force_bounds_N`'s lower bound takes of the muscle's braid and rubber, and how
    to widen it: a muscle with a steeper braid or a stiffer rubber is slack to a higher
    pressure, and a live load cell then holds its code where the bound says the force moves."""
    m, tol = config.muscle, config.muscle.tolerances
    lock = muscle_lock(config)
    angle = (f"theta0 {lock.theta0_deg:.4g} +- {tol.theta0_deg:g} deg"
             + ("" if m.theta0_deg is not None else f" ({lock.source}: [muscle] declares none)"))
    rubber = ("its declared rubber" if m.C10_MPa is not None
              else "Silastic S's rubber ([muscle] declares none)")
    return (f"the bound takes {angle} and {rubber}; a muscle with a steeper braid or a stiffer "
            "rubber is slack to a higher pressure: if the cell is sound, declare the muscle's "
            "theta0_deg and C10_MPa in [muscle] or widen [muscle.tolerances] theta0_deg")


#: A muscle pulling less than this share of its force at its rest length, at the highest planned
#: pressure, is slack there: the thick-wall model and the FE model part by about as much near
#: the threshold (a 10 mm tube with a 1.5 mm wall at eps 0.28 and 6 bar: 1.6 N and none, of
#: 590 N at eps 0)
SLACK_FRACTION = 0.01


def slack_warning(config) -> str | None:
    """The message when the muscle at its eps pulls less than :data:`SLACK_FRACTION` of its
    force at its rest length up to the highest planned pressure, by :func:`thickwall_force_N`
    (its threshold lies at or above that pressure: every step would read about the load cell's
    zero), with the largest eps at which it pulls more there, else None. Past the braid lock
    :func:`braid_lock` says it."""
    m, top = config.muscle, max(config.sequence.pressures_bar)
    if braid_lock(config):
        return None
    least = SLACK_FRACTION * thickwall_force_N(config, top, 0.0)
    force = thickwall_force_N(config, top, m.eps)
    if not force < least:  # a force the model gives none for (NaN) is not said slack
        return None
    low, high = 0.0, m.eps
    if least <= 0.0:
        reach = "at no eps, not even at its rest length"
    else:
        while high - low > 1e-4:  # the largest eps it pulls at, to a tenth of a per mille
            middle = (low + high) / 2
            low, high = (middle, high) if thickwall_force_N(config, top, middle) >= least \
                else (low, middle)
        reach = f"below eps {low:.3f}"
    return (f"at eps {m.eps:g} the muscle pulls at most {force:.2g} N up to {top:g} bar, under "
            f"{100 * SLACK_FRACTION:g} % of the {least / SLACK_FRACTION:.0f} N it pulls at its "
            "rest length (the thick-wall model, whose wall holds the braid below a threshold "
            "pressure; Equation 2's forecast above has none): every step would read about the "
            f"load cell's zero; it pulls more than that at {top:g} bar {reach}, at a higher "
            "pressure or with a thinner wall")


def warnings(config, rest_std_N: float | None = None,
             ceiling: ForceCeiling | None = None) -> list[str]:
    """Every preflight message for ``config`` (braid lock, at the identified angle with
    ``ceiling``; a slack muscle, load cell, settle and noise limits, practical range);
    ``rest_std_N``: the load cell's spread read at rest [N], where known
    (:func:`limits_warning`)."""
    return [w for w in (braid_lock(config, ceiling), slack_warning(config),
                        loadcell_warning(config),
                        limits_warning(config, rest_std_N), practical_range_warning(config))
            if w]
