"""Bench configuration: one TOML file, validated into frozen dataclasses with clear errors.

The packaged default ``bench/configs/paper_prototype.toml`` reproduces the paper's prototype on the
simulated bench. Every setting has a unit in its name and bounds a physical bench can have: the
muscle is checked against the one muscle type's limits (:mod:`mkm.fem.muscle`), every safety
setting within a fraction of what it guards (so no configuration switches an interlock off),
every time and count bounded, and the whole run's planned duration bounded by
``sequence.max_duration_h``. The device settings are checked against the capabilities of the
configured backend (``[daq] backend``, one of :mod:`mkm.bench.backends`). A bad value raises
``ValueError`` naming the ``section.key``, the value and what was expected. The simulator's own
``[sim]`` settings are in :mod:`mkm.bench.sim_settings`; TOML reading in
:mod:`mkm.core.toml_text`, typed sections in :mod:`mkm.bench.settings`.
"""

from __future__ import annotations

import dataclasses
import hashlib
import re
from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path
from typing import Any

import numpy as np

from mkm.bench import backends
from mkm.bench.settings import PathText, Problems, positive, typed_section, within
from mkm.bench.sim_settings import Sim
from mkm.core.ranges import parse_fraction
from mkm.core.records import file_sha256, write_atomic
from mkm.core.toml_text import read_toml, read_toml_file
from mkm.fem.limits import LIMITS, check_gap, check_muscle_id, check_wall
from mkm.fem.muscle import Muscle
from mkm.fem.tolerances import Tolerances

DEFAULT_CONFIG = "paper_prototype.toml"
PACKAGED_CONFIG = f"mkm.bench/configs/{DEFAULT_CONFIG}"  # as a record names it
DEVICE_PATTERN = r"[A-Za-z0-9_][A-Za-z0-9 _.-]{0,63}"  # NI MAX names: Dev1, cDAQ1Mod1
MAX_STEPS = 2000  # a 2000-step staircase already takes 5 to 37 hours at the default settle
MAX_STEP_S = 3600.0  # a settle timeout, a hold, a window: at most an hour each
MAX_TARE_S = 600.0
MAX_PRECONDITIONING_CYCLES = 100
MAX_DURATION_H = 48.0  # the largest planned run sequence.max_duration_h may allow
MAX_BUFFER_S = 24 * 3600.0
MAX_BUFFER_VALUES = 20_000_000  # samples x inputs in the driver's host buffer (160 MB)
MAX_BLOCK_S = 1.0  # a stop waits for the block in hand: keep it short
MAX_READ_TIMEOUT_S = 60.0
MAX_READ_RETRIES = 100
MAX_SILENCE_S = 60.0  # read_timeout_s x (read_retries + 1): longest a run goes without a reading
MAX_CAPACITY_N = 1e5  # a 10 t load cell; a McKibben bench needs far less
# Interlocks within physical bounds: a tolerance of at most a tenth of the regulator's range, a
# follow time of seconds, tare limits a small part of the cell's capacity.
MAX_TOLERANCE_FRACTION = 0.1
MAX_FOLLOW_S = 10.0
# Floors that let a normal run pass: a regulator needs about a second to follow a step and to
# exhaust the muscle (the paper's ITV class: 0.1 s response, then the muscle's volume through
# its exhaust), so shorter follow or vent times fail every run; a force limit below a tenth of
# the capacity means a load cell of the wrong size (its noise and drift are fractions of it).
MIN_FOLLOW_S = 1.0
MIN_VENT_TIMEOUT_S = 2.0
MIN_FORCE_LIMIT_FRACTION = 0.1
MAX_TARE_STD_FRACTION = 0.01
MAX_TARE_SHIFT_FRACTION = 0.1
MAX_VENT_BELOW_BAR = 0.2
MAX_VENT_TIMEOUT_S = 30.0
MAX_DATASHEET_FRACTION = 0.05
#: The over-force interlock is there for a pressure monitor that reads low by its gain: one
#: reading 0.8 of the pressure (a 5 bar regulator's monitor read on a 4 bar scale) makes the
#: muscle pull about 1.25 times the identified force, which the ceiling's band and friction
#: (5-10 %) already take part of; a margin above a tenth would let that through
MAX_OVERFORCE_MARGIN_FRACTION = 0.1
MAX_PATH_CHARS = 4096  # PATH_MAX on Linux; Windows' long paths are shorter
MONITOR_FAULT = "monitor fault:"  # how :meth:`Regulator.monitor_fault` begins
MONITOR_MARGIN_FRACTION = 0.025  # 0.1 V of a 4 V span: noise and offset of a working output
#: The pressure reading's error as ``[regulator]`` declares it, name: (unit, what it is).
#: Either one +- bound at every pressure (``monitor_accuracy_bar``, alone), or the components a
#: pressure sensor's data sheet itemises, each a +- bound (those declared replace the single
#: one in the budget): the zero (offset) error; the span (gain) error, a fraction of the
#: reading; the non-linearity, the largest departure from the line through the zero and
#: full-scale readings; the hysteresis, the largest difference between the readings of one
#: pressure approached rising and falling (so +- half of it on either branch). Repeatability is
#: left out: a random error of each approach, which no simulated truth stands for.
MONITOR_COMPONENTS = {"monitor_accuracy_bar": ("bar", "reading accuracy"),
                      "monitor_zero_bar": ("bar", "zero error"),
                      "monitor_span_fraction": ("fraction", "span error"),
                      "monitor_nonlinearity_bar": ("bar", "non-linearity"),
                      "monitor_hysteresis_bar": ("bar", "hysteresis")}


def from_record(cls, values: dict[str, Any]):
    """Section ``cls`` from what a run recorded of it: known keys only, defaults for the rest
    (a run that predates a setting)."""
    known = {f.name for f in dataclasses.fields(cls)}
    return cls(**{k: v for k, v in values.items() if k in known})


def read_muscle(table: Any, where: str = "muscle") -> Muscle:
    """The bench's muscle from its ``[muscle]`` table: the one muscle type
    (:class:`mkm.fem.muscle.Muscle`, checked against its limits), with an ``id`` (it names the
    run folder) and the +- tolerances of ``[muscle.tolerances]`` (defaults and meaning:
    :class:`mkm.fem.tolerances.Tolerances`), which the report propagates to every model's
    prediction."""
    if not isinstance(table, dict):
        raise ValueError(f"[{where}] must be a table of settings, got {str(table)[:60]}")
    table, problems = dict(table), Problems()
    tolerances = Tolerances()
    with problems.check():
        tolerances = typed_section(Tolerances, table.pop("tolerances", {}),
                                   f"{where}.tolerances")
    with problems.check():
        check_muscle_id(table.get("id"), f"{where}.id")
    if isinstance(table.get("eps"), str):  # "12.2%", as --eps takes it
        with problems.check():
            table["eps"] = parse_fraction(table["eps"], f"{where}.eps")
        if isinstance(table["eps"], str):  # said: the muscle's other values are checked too
            table["eps"] = 0.0
    muscle = None
    with problems.check():
        muscle = Muscle.from_dict(table, where, tolerances=tolerances)
    problems.raise_any()
    return muscle


@dataclass(frozen=True)
class Daq:
    """The acquisition device: which backend drives it (``sim`` or ``ni``, no default: a
    configuration says whether it drives hardware) and how it samples."""

    backend: str
    device: str = "Dev1"
    terminal_config: str = "differential"
    sample_rate_hz: float = 10.0
    buffer_s: float = 600.0
    read_block_samples: int = 1
    read_timeout_s: float = 2.0
    read_retries: int = 2

    @property
    def buffer_samples(self) -> int:
        return int(round(self.buffer_s * self.sample_rate_hz))

    def check(self):
        problems = Problems()
        with problems.check():
            backends.entry(self.backend)  # one line naming the choices
        with problems.check():
            if not re.fullmatch(DEVICE_PATTERN, self.device):
                shown = self.device if len(self.device) <= 40 else self.device[:40] + "..."
                raise ValueError(f"daq.device={shown!r} ({len(self.device)} characters) is "
                                 "invalid: expected a device name of 1 to 64 ASCII letters (no "
                                 "accents), digits, spaces or _ . -, starting with a letter, "
                                 "digit or _ (as NI MAX shows it: Dev1)")
        with problems.check():
            if not 600.0 <= self.buffer_s <= MAX_BUFFER_S:
                raise ValueError(f"daq.buffer_s={self.buffer_s:g} is invalid: expected 600 s (10 "
                                 "minutes of samples, so a stalled reader loses nothing) to "
                                 f"{MAX_BUFFER_S:g} s")
        with problems.check():
            within("daq.read_retries", self.read_retries, 0, MAX_READ_RETRIES)
        with problems.check():
            for name in ("sample_rate_hz", "read_block_samples", "read_timeout_s"):
                positive(f"daq.{name}", getattr(self, name))
            self._check_reads()
        problems.raise_any()

    def _check_reads(self):
        """The blocks read, their timeout and retries, of a positive rate, block and timeout."""
        block_s = self.read_block_samples / self.sample_rate_hz
        if block_s > MAX_BLOCK_S:
            raise ValueError(f"daq.read_block_samples={self.read_block_samples} is "
                             f"{block_s:g} s of samples at {self.sample_rate_hz:g} Hz: expected "
                             f"blocks of at most {MAX_BLOCK_S:g} s (a stop waits for the block "
                             "in hand)")
        if self.read_timeout_s < 2 * block_s or self.read_timeout_s < 0.1:
            raise ValueError(f"daq.read_timeout_s={self.read_timeout_s:g} is too short for "
                             f"blocks of {block_s:g} s: every read would time out; expected at "
                             f"least {max(2 * block_s, 0.1):g} s (twice the block, >= 0.1 s)")
        within("daq.read_timeout_s", self.read_timeout_s, 0.1, MAX_READ_TIMEOUT_S, "s")
        silence_s = self.read_timeout_s * (self.read_retries + 1)
        if silence_s > MAX_SILENCE_S:
            raise ValueError(f"daq.read_timeout_s={self.read_timeout_s:g} with read_retries="
                             f"{self.read_retries} lets a run go {silence_s:g} s without a "
                             f"reading: expected at most {MAX_SILENCE_S:g} s in all")


@dataclass(frozen=True)
class LoadCell:
    """The load cell and its data sheet's error bounds (half-widths, for the uncertainty budget
    of :mod:`mkm.bench.budget`): ``sensitivity_tolerance_fraction`` of the reading (the paper's
    TCA10: <= 0.1 %), ``nonlinearity_fraction_fs`` and ``zero_drift_fraction_fs`` (over a run) of
    the capacity (typical S-beam data sheets: 0.05 % and 0.02 %; set your cell's)."""

    capacity_N: float
    sensitivity_N_per_V: float
    offset_V: float = 0.0
    channel: str = "ai0"
    sensitivity_tolerance_fraction: float = 0.001
    nonlinearity_fraction_fs: float = 0.0005
    zero_drift_fraction_fs: float = 0.0002

    def check(self):
        problems = Problems()
        with problems.check():
            positive("loadcell.capacity_N", self.capacity_N)
            within("loadcell.capacity_N", self.capacity_N, 0.0, MAX_CAPACITY_N, "N")
        with problems.check():
            positive("loadcell.sensitivity_N_per_V", self.sensitivity_N_per_V)
        for name in ("sensitivity_tolerance_fraction", "nonlinearity_fraction_fs",
                     "zero_drift_fraction_fs"):
            with problems.check():
                within(f"loadcell.{name}", getattr(self, name), 0.0, MAX_DATASHEET_FRACTION,
                       "(a fraction)", "a data-sheet bound beyond 5 % is not a load cell")
        problems.raise_any()

    def force_N(self, volts):
        """Force [N] from load-cell volts with this calibration."""
        return (np.asarray(volts) - self.offset_V) * self.sensitivity_N_per_V


@dataclass(frozen=True)
class Regulator:
    kind: str = "electronic"
    max_pressure_bar: float = 2.5
    full_scale_bar: float = 4.0
    command_channel: str = "ao0"
    monitor_channel: str = "ai1"
    monitor_V_at_zero: float = 1.0
    monitor_V_at_full_scale: float = 5.0
    monitor_accuracy_bar: float = 0.04  # +- bound of the pressure reading: 1 % of an ITV's 4 bar
    # the reading's error as a data sheet itemises it (None: not declared; see MONITOR_COMPONENTS)
    monitor_zero_bar: float | None = None
    monitor_span_fraction: float | None = None
    monitor_nonlinearity_bar: float | None = None
    monitor_hysteresis_bar: float | None = None

    @property
    def electronic(self) -> bool:
        return self.kind == "electronic"

    def check(self):
        problems = Problems()
        with problems.check():
            if self.kind not in ("electronic", "manual"):
                raise ValueError(f"regulator.kind={self.kind[:40]!r} is invalid: expected "
                                 "'electronic' or 'manual'")
        with problems.check():
            if not self.monitor_V_at_full_scale > self.monitor_V_at_zero:
                raise ValueError("regulator.monitor_V_at_full_scale must exceed "
                                 "monitor_V_at_zero")
        with problems.check():  # the bounds below are fractions of the full scale
            positive("regulator.full_scale_bar", self.full_scale_bar)
            within("regulator.full_scale_bar", self.full_scale_bar, 0.0,
                   LIMITS["pressure_bar"][1], "bar")
        problems.raise_any()
        with problems.check():
            if not 0 < self.max_pressure_bar <= self.full_scale_bar:
                raise ValueError(f"regulator.max_pressure_bar={self.max_pressure_bar:g} is "
                                 f"invalid: expected 0 < max <= full_scale_bar="
                                 f"{self.full_scale_bar:g}")
        for name, (unit, _) in MONITOR_COMPONENTS.items():
            value = getattr(self, name)
            if name == "monitor_accuracy_bar" or value is not None:
                high = (MAX_DATASHEET_FRACTION if unit == "fraction"
                        else MAX_TOLERANCE_FRACTION * self.full_scale_bar)
                with problems.check():
                    within(f"regulator.{name}", value, 0.0, high,
                           "(a fraction of the reading)" if unit == "fraction" else "bar",
                           "a sensor 5 % off is broken" if unit == "fraction" else
                           f"a tenth of regulator.full_scale_bar={self.full_scale_bar:g}")
        problems.raise_any()

    @property
    def monitor_components(self) -> dict[str, float]:
        """The components of the reading's error the configuration declares (name: bound), empty
        when it declares only ``monitor_accuracy_bar``."""
        return {name: float(getattr(self, name)) for name in MONITOR_COMPONENTS
                if name != "monitor_accuracy_bar" and getattr(self, name) is not None}

    def reading_bounds(self) -> tuple[float, float]:
        """The +- bounds of the reading's offset [bar] and of its gain error [fraction] (what an
        identification fits as a nuisance or carries as a shared term). With components: the
        zero error plus what no straight line carries (the non-linearity, half the hysteresis)
        as the offset, the span error as the gain; with the one accuracy, the whole bound as
        either (the gain's reached at ``max_pressure_bar``). A component not declared is 0."""
        parts = self.monitor_components
        if not parts:
            return self.monitor_accuracy_bar, self.monitor_accuracy_bar / self.max_pressure_bar
        offset = (parts.get("monitor_zero_bar", 0.0) + parts.get("monitor_nonlinearity_bar", 0.0)
                  + parts.get("monitor_hysteresis_bar", 0.0) / 2)
        return offset, parts.get("monitor_span_fraction", 0.0)

    def vented_reading_bar(self) -> tuple[float, str]:
        """How far from 0 bar [bar] the monitor may read on a vented muscle, as declared (its
        zero error), and the settings that declare it."""
        parts = self.monitor_components
        if not parts:
            return self.monitor_accuracy_bar, "regulator.monitor_accuracy_bar"
        return (parts.get("monitor_zero_bar", 0.0) + parts.get("monitor_hysteresis_bar", 0.0) / 2,
                "regulator.monitor_zero_bar + monitor_hysteresis_bar / 2")

    def command_volts(self, pressure_bar: float) -> float:
        """AO command [V, 0-10] for ``pressure_bar``, clamped to ``[0, max_pressure_bar]``."""
        clamped = min(max(float(pressure_bar), 0.0), self.max_pressure_bar)
        return clamped / self.full_scale_bar * 10.0

    def monitor_bar(self, volts):
        """Pressure [bar] from the monitor output volts (1-5 V over 0..full scale)."""
        span = self.monitor_V_at_full_scale - self.monitor_V_at_zero
        return (np.asarray(volts) - self.monitor_V_at_zero) / span * self.full_scale_bar

    def monitor_volts(self, pressure_bar):
        """The monitor output [V] that reads ``pressure_bar`` (:meth:`monitor_bar`'s inverse)."""
        span = self.monitor_V_at_full_scale - self.monitor_V_at_zero
        return self.monitor_V_at_zero + np.asarray(pressure_bar) / self.full_scale_bar * span

    def monitor_fault(self, volts: float) -> str | None:
        """What is wrong with a monitor reading no working regulator gives, or None.

        A live-zero output (1-5 V) reads near 0 V only when the regulator is unpowered or its
        wire is off, which would convert to a negative pressure and pass for a vent; readings
        beyond :data:`MONITOR_MARGIN_FRACTION` of the span outside the output's range (0.9 V,
        5.1 V for 1-5 V) are a fault of the monitor, not a pressure."""
        span = self.monitor_V_at_full_scale - self.monitor_V_at_zero
        low = self.monitor_V_at_zero - MONITOR_MARGIN_FRACTION * span
        high = self.monitor_V_at_full_scale + MONITOR_MARGIN_FRACTION * span
        if low <= volts <= high:
            return None
        return (f"{MONITOR_FAULT} the monitor reads {volts:.3f} V, outside its "
                f"{self.monitor_V_at_zero:g}-{self.monitor_V_at_full_scale:g} V output "
                f"(below {low:.3g} V: regulator unpowered or wire off)" if volts < low else
                f"{MONITOR_FAULT} the monitor reads {volts:.3f} V, above its "
                f"{self.monitor_V_at_full_scale:g} V full scale")



@dataclass(frozen=True)
class Sequence:
    pressures_bar: tuple[float, ...]
    down_sweep: bool = True
    repeats: int = 1
    preconditioning_cycles: int = 0
    preconditioning_hold_s: float = 5.0
    tare_s: float = 5.0
    max_duration_h: float = 4.0  # a run planned longer than this is refused

    def check(self):
        problems = Problems()
        with problems.check():
            if len(self.pressures_bar) == 0:
                raise ValueError("sequence.pressures_bar is empty: expected at least one "
                                 "pressure")
            pressures = self.pressures_bar
            # the steps are labelled up in the order given and down in reverse: a falling list
            # would record its falling branch as the rising one
            for low, high in zip(pressures[:-1], pressures[1:], strict=True):
                if not high > low:
                    raise ValueError(f"sequence.pressures_bar goes from {low:g} to {high:g} "
                                     "bar: expected the rising staircase, each pressure above "
                                     "the one before (down_sweep adds the falling branch, "
                                     "repeats the cycles)")
        with problems.check():
            within("sequence.repeats", self.repeats, 1, MAX_STEPS)
        with problems.check():
            within("sequence.preconditioning_cycles", self.preconditioning_cycles, 0,
                   MAX_PRECONDITIONING_CYCLES)
        for name, high, unit in (("tare_s", MAX_TARE_S, "s"),
                                 ("preconditioning_hold_s", MAX_STEP_S, "s"),
                                 ("max_duration_h", MAX_DURATION_H, "h")):
            with problems.check():
                positive(f"sequence.{name}", getattr(self, name))
                within(f"sequence.{name}", getattr(self, name), 0.0, high, unit)
        problems.raise_any()


@dataclass(frozen=True)
class Settle:
    min_dwell_s: float = 4.0
    timeout_s: float = 60.0
    window_s: float = 3.0
    pressure_tolerance_bar: float = 0.03
    max_force_slope_N_per_s: float = 1.0
    max_force_std_N: float = 1.5
    hold_s: float = 5.0

    def check(self):
        problems = Problems()
        for f in dataclasses.fields(self):
            with problems.check():
                positive(f"settle.{f.name}", getattr(self, f.name))
        problems.raise_any()  # the bounds below compare positive times
        with problems.check():
            if self.timeout_s > MAX_STEP_S:
                raise ValueError(f"settle.timeout_s={self.timeout_s:g} is invalid: expected at "
                                 f"most {MAX_STEP_S:g} s per step")
            if self.timeout_s < self.min_dwell_s:
                raise ValueError(f"settle.timeout_s={self.timeout_s:g} is below min_dwell_s="
                                 f"{self.min_dwell_s:g}: expected timeout_s >= min_dwell_s")
        with problems.check():
            within("settle.window_s", self.window_s, 0.0, MAX_STEP_S, "s")
        with problems.check():
            within("settle.hold_s", self.hold_s, 0.0, MAX_STEP_S, "s")
        problems.raise_any()


@dataclass(frozen=True)
class Safety:
    """Interlocks, the checks a tare must pass before any pressure is commanded, and the vent.

    The force interlock trips at ``force_limit_fraction`` of the load-cell capacity (or at any
    non-finite force or pressure). The pressure interlock (electronic regulator) trips when the
    measured pressure stays more than ``pressure_tolerance_bar`` from its command, without
    moving more than that towards it, for longer than ``pressure_follow_s`` (a regulator that
    does not follow; a new command does not restart the window), or exceeds
    ``regulator.max_pressure_bar`` by more than the tolerance (overshoot). The tare needs at
    least ``tare_min_samples`` finite samples, a spread below ``tare_max_std_N`` and an offset
    within ``tare_max_shift_N`` of the configured ``loadcell.offset_V``. A vent is verified: the
    monitor must read below ``vent_below_bar`` within ``vent_timeout_s`` (read on while it is
    still falling then: :data:`mkm.bench.vent.FALLING_MAX_S`).

    The over-force interlock is armed by ``calibration``, the ``calibration.json`` of ``mkm
    identify`` for the muscle held (a path relative to the configuration's folder; ``mkm
    acquire --calibration`` names one instead): the load cell may read no more than the
    identified muscle pulls at the measured pressure (with its prediction band and friction),
    times ``1 + overforce_margin_fraction`` (:meth:`mkm.bench.preflight.ForceCeiling.most_N`).
    The margin is bounded by :data:`MAX_OVERFORCE_MARGIN_FRACTION`.

    Every limit is bounded by what it guards (checked with the other sections by
    :meth:`BenchConfig.check`): the tolerance by a tenth of the regulator's full scale, the
    follow time by 10 s, the tare spread by 1 % and the shift by 10 % of the cell's capacity.
    """

    force_limit_fraction: float = 0.9
    pressure_tolerance_bar: float = 0.15
    pressure_follow_s: float = 5.0
    tare_min_samples: int = 10
    tare_max_std_N: float = 5.0
    tare_max_shift_N: float = 100.0
    vent_below_bar: float = 0.05
    vent_timeout_s: float = 10.0
    calibration: PathText | None = None
    overforce_margin_fraction: float = 0.0

    def check(self):
        problems = Problems()
        with problems.check():
            if self.calibration is not None and not 0 < len(self.calibration) <= MAX_PATH_CHARS:
                raise ValueError(f"safety.calibration={self.calibration[:60]!r} is invalid: "
                                 "expected the path of the calibration.json `mkm identify` "
                                 "wrote for this muscle")
        with problems.check():
            within("safety.overforce_margin_fraction", self.overforce_margin_fraction, 0.0,
                   MAX_OVERFORCE_MARGIN_FRACTION, "(a fraction of the identified force)",
                   "a wider margin hides a pressure monitor reading 0.8 of the pressure, the "
                   "fault the over-force interlock is for")
        with problems.check():
            within("safety.force_limit_fraction", self.force_limit_fraction,
                   MIN_FORCE_LIMIT_FRACTION, 1.0, "(a fraction of the load-cell capacity)",
                   "below a tenth of its capacity the load cell is the wrong size")
        bounds = {"pressure_follow_s": (MIN_FOLLOW_S, MAX_FOLLOW_S, "s", "a regulator needs "
                                        "about a second to follow; one that has not followed "
                                        f"by {MAX_FOLLOW_S:g} s is stuck"),
                  "vent_below_bar": (0.0, MAX_VENT_BELOW_BAR, "bar", ""),
                  "vent_timeout_s": (MIN_VENT_TIMEOUT_S, MAX_VENT_TIMEOUT_S, "s",
                                     "a regulator needs seconds to exhaust the muscle")}
        for name in ("pressure_tolerance_bar", "pressure_follow_s", "tare_max_std_N",
                     "tare_max_shift_N", "vent_below_bar", "vent_timeout_s"):
            with problems.check():
                positive(f"safety.{name}", getattr(self, name))
                if name in bounds:
                    within(f"safety.{name}", getattr(self, name), *bounds[name])
        with problems.check():
            within("safety.tare_min_samples", self.tare_min_samples, 2, 100_000,
                   why="a spread needs two samples")
        problems.raise_any()


@dataclass(frozen=True)
class BenchConfig:
    muscle: Muscle
    loadcell: LoadCell
    daq: Daq
    regulator: Regulator = field(default_factory=Regulator)
    sequence: Sequence = field(default_factory=lambda: Sequence((0.5, 1.0)))
    settle: Settle = field(default_factory=Settle)
    safety: Safety = field(default_factory=Safety)
    sim: Sim = field(default_factory=Sim)
    source: str = ""
    text: str = ""
    overrides: dict[str, Any] = field(default_factory=dict)  # changes made after reading `text`
    #: how a record names the file: a packaged example by its name in the package (its
    #: install path names one machine's folders), a user's file by its path as given
    recorded_source: str = ""
    source_sha256: str | None = None  # of the file's bytes, as read

    @property
    def force_limit_N(self) -> float:
        return self.safety.force_limit_fraction * self.loadcell.capacity_N

    @property
    def calibration_path(self) -> Path | None:
        """``safety.calibration`` as a path: a relative one from the folder of the
        configuration file (where it was written, not where a command is started), from the
        working folder for a configuration given as text; None when not set."""
        if self.safety.calibration is None:
            return None
        path = Path(self.safety.calibration).expanduser()
        if path.is_absolute() or self.source_sha256 is None or \
                self.recorded_source == PACKAGED_CONFIG:
            return path
        return Path(self.source).parent / path

    @property
    def simulated(self) -> bool:
        """Whether the configured backend drives no hardware."""
        return backends.entry(self.daq.backend).simulated

    @property
    def ai_channels(self) -> list[str]:
        """Inputs of the AI task: the load cell, and the regulator monitor if electronic."""
        ai = [self.loadcell.channel]
        if self.regulator.electronic:
            ai.append(self.regulator.monitor_channel)
        return ai

    def check(self):
        """Every setting checked against the others (the sections checked themselves): one
        ``ValueError`` naming each bad value on a line of its own."""
        problems = Problems()
        with problems.check():
            too_high = [p for p in self.sequence.pressures_bar
                        if p > self.regulator.max_pressure_bar]
            if too_high:
                raise ValueError(f"sequence.pressures_bar has {too_high[0]:g} bar, above "
                                 "regulator.max_pressure_bar="
                                 f"{self.regulator.max_pressure_bar:g}: expected every planned "
                                 "pressure within the limit")
        self._check_interlocks(problems)
        with problems.check():  # the true tube, then the braid around it
            check_wall(*self.sim.truth.geometry(self.muscle), prefix="sim.truth.")
            if self.sim.truth.gap_mm is not None:
                check_gap(*self.sim.truth.geometry(self.muscle), self.sim.truth.gap_mm,
                          prefix="sim.truth.")
        fs = self.regulator.full_scale_bar
        with problems.check():
            if self.sim.truth.monitor_bow_bar is not None:
                # within a tenth of full scale the bowed sensor still reads a higher pressure
                # higher: its slope is at least gain - 4 bow / full scale >= 0.9 - 0.4
                within("sim.truth.monitor_bow_bar", self.sim.truth.monitor_bow_bar,
                       -MAX_TOLERANCE_FRACTION * fs, MAX_TOLERANCE_FRACTION * fs, "bar",
                       f"a tenth of regulator.full_scale_bar={fs:g}")
        with problems.check():
            if self.sim.truth.monitor_stuck_bar is not None:  # a reading the monitor can give
                within("sim.truth.monitor_stuck_bar", self.sim.truth.monitor_stuck_bar, 0.0,
                       fs, "bar", f"regulator.full_scale_bar={fs:g}")
        self._check_device(problems)
        with problems.check():
            self._check_duration()
        problems.raise_any()

    def _check_interlocks(self, problems: Problems):
        """Safety limits within what they guard: none can be set so wide it never trips."""
        s, reg, capacity = self.safety, self.regulator, self.loadcell.capacity_N
        with problems.check():
            within("safety.pressure_tolerance_bar", s.pressure_tolerance_bar, 0.0,
                   MAX_TOLERANCE_FRACTION * reg.full_scale_bar, "bar",
                   f"a tenth of regulator.full_scale_bar={reg.full_scale_bar:g}")
        with problems.check():
            within("safety.tare_max_std_N", s.tare_max_std_N, 0.0,
                   MAX_TARE_STD_FRACTION * capacity, "N",
                   f"1 % of loadcell.capacity_N={capacity:g}")
        with problems.check():
            within("safety.tare_max_shift_N", s.tare_max_shift_N, 0.0,
                   MAX_TARE_SHIFT_FRACTION * capacity, "N",
                   f"10 % of loadcell.capacity_N={capacity:g}")
        with problems.check():
            within("settle.pressure_tolerance_bar", self.settle.pressure_tolerance_bar, 0.0,
                   MAX_TOLERANCE_FRACTION * reg.full_scale_bar, "bar",
                   f"a tenth of regulator.full_scale_bar={reg.full_scale_bar:g}")
        with problems.check():
            # a load on the cell as the tare reads it, within tare_max_shift_N, is its zero: the
            # force interlock sees what comes on top of it, so the two together must stay
            # within the capacity the interlock guards
            carried_N = s.force_limit_fraction * capacity + s.tare_max_shift_N
            valid = (MIN_FORCE_LIMIT_FRACTION <= s.force_limit_fraction <= 1
                     and 0 <= s.tare_max_shift_N <= MAX_TARE_SHIFT_FRACTION * capacity)
            if valid and carried_N > capacity * (1 + 1e-12):  # each said alone otherwise
                raise ValueError(
                    f"safety.force_limit_fraction={s.force_limit_fraction:g} and "
                    f"safety.tare_max_shift_N={s.tare_max_shift_N:g} are invalid together: a load "
                    f"the tare takes as the zero is not seen by the force interlock, which lets "
                    f"the load cell carry up to {carried_N:.4g} N before it trips, beyond "
                    f"loadcell.capacity_N={capacity:g}: expected force_limit_fraction x capacity "
                    "+ tare_max_shift_N within the capacity")
        with problems.check():
            if reg.electronic:
                # a vent is verified by the monitor, which may read its zero error at 0 bar: a
                # limit within it fails the check of a vented muscle (VENT BY HAND, a false alarm)
                zero, declared = reg.vented_reading_bar()
                if s.vent_below_bar <= zero:
                    raise ValueError(f"safety.vent_below_bar={s.vent_below_bar:g} is invalid: "
                                     f"a vented muscle's monitor may read up to {zero:g} bar "
                                     f"({declared}), so the vent check could fail on a vented "
                                     f"bench: expected more than {zero:g} bar (at most "
                                     f"{MAX_VENT_BELOW_BAR:g})")

    def _check_device(self, problems: Problems):
        """Against the capabilities of the configured backend's device."""
        caps = backends.entry(self.daq.backend).capabilities
        ai, daq, cell, reg = self.ai_channels, self.daq, self.loadcell, self.regulator
        with problems.check():
            if daq.terminal_config not in caps.terminal_configs:
                raise ValueError(f"daq.terminal_config={daq.terminal_config[:40]!r} is invalid: "
                                 f"the {caps.product} has only "
                                 f"{' and '.join(caps.terminal_configs)} inputs (no NRSE or "
                                 "pseudo-differential mode)")
        aggregate = daq.sample_rate_hz * len(ai)
        with problems.check():  # the rate, over every input, then the buffer it fills
            if daq.sample_rate_hz > caps.max_aggregate_rate_hz:
                raise ValueError(f"daq.sample_rate_hz={daq.sample_rate_hz:g} is invalid: the "
                                 f"{caps.product} samples at most "
                                 f"{caps.max_aggregate_rate_hz:g} S/s over all its inputs")
            if aggregate > caps.max_aggregate_rate_hz:
                raise ValueError(f"daq.sample_rate_hz={daq.sample_rate_hz:g} on {len(ai)} "
                                 f"inputs is {aggregate:g} S/s: the {caps.product} samples at "
                                 f"most {caps.max_aggregate_rate_hz:g} S/s in aggregate")
            if daq.buffer_samples * len(ai) > MAX_BUFFER_VALUES:
                raise ValueError(f"daq.buffer_s={daq.buffer_s:g} at {daq.sample_rate_hz:g} Hz "
                                 f"is {daq.buffer_samples * len(ai)} buffered values: expected "
                                 f"at most {MAX_BUFFER_VALUES} (shorten the buffer or the rate)")
        with problems.check():  # each input, then the two as a pair
            for name, channel in (("loadcell.channel", cell.channel),
                                  ("regulator.monitor_channel", reg.monitor_channel)):
                if channel not in caps.ai_rse:
                    raise ValueError(f"{name}={channel[:40]!r} is invalid: the {caps.product} has "
                                     f"inputs {caps.ai_rse[0]} to {caps.ai_rse[-1]}")
            if len(set(ai)) < len(ai):
                raise ValueError("loadcell.channel and regulator.monitor_channel are both "
                                 f"{ai[0]}: expected two different inputs")
            if daq.terminal_config == "differential":
                pairs = caps.ai_differential
                for name, channel in zip(("loadcell.channel", "regulator.monitor_channel"), ai,
                                         strict=False):
                    if channel not in pairs:
                        raise ValueError(
                            f"{name}={channel!r} cannot be differential on the {caps.product}: "
                            f"only {', '.join(pairs)} are (paired with "
                            f"{', '.join(pairs.values())}); use one of those or "
                            "daq.terminal_config = 'rse'")
        with problems.check():
            if reg.command_channel not in caps.ao:
                raise ValueError(f"regulator.command_channel={reg.command_channel[:40]!r} is "
                                 f"invalid: the {caps.product} has outputs {', '.join(caps.ao)}")
        with problems.check():
            if reg.electronic and not backends.entry(self.daq.backend).simulated \
                    and reg.monitor_fault(0.0) is None:
                # a monitor without a live zero: its lost wire (0 V) reads a plausible pressure
                least = (MONITOR_MARGIN_FRACTION / (1 + MONITOR_MARGIN_FRACTION)
                         * reg.monitor_V_at_full_scale)
                raise ValueError(
                    f"regulator.monitor_V_at_zero={reg.monitor_V_at_zero:g} is invalid on a real "
                    f"bench: a lost monitor (unpowered, wire off) reads 0 V, which this output "
                    f"gives at {float(reg.monitor_bar(0.0)):.3g} bar and would pass for a vent; "
                    f"expected a live-zero output (1-5 V: monitor_V_at_zero above "
                    f"{least:.3g} V, so that 0 V is a monitor fault)")
        with problems.check():
            for name in ("monitor_V_at_zero", "monitor_V_at_full_scale"):
                if abs(getattr(reg, name)) > caps.ai_range_V:
                    raise ValueError(f"regulator.{name}={getattr(reg, name):g} is invalid: the "
                                     f"{caps.product}'s inputs read +-{caps.ai_range_V:g} V")
        with problems.check():
            if abs(cell.offset_V) >= caps.ai_range_V:
                raise ValueError(f"loadcell.offset_V={cell.offset_V:g} is invalid: expected within "
                                 f"the +-{caps.ai_range_V:g} V input range")
        full_scale_N = cell.sensitivity_N_per_V * caps.ai_range_V
        with problems.check():
            if full_scale_N < cell.capacity_N * 0.999:
                raise ValueError(
                    f"loadcell.sensitivity_N_per_V={cell.sensitivity_N_per_V:g} puts the "
                    f"+-{caps.ai_range_V:g} V rail at {full_scale_N:g} N, below capacity_N="
                    f"{cell.capacity_N:g}: the cell would clip before its capacity; expected "
                    f"sensitivity_N_per_V >= capacity_N / {caps.ai_range_V:g} V")
        tare_n = int(round(self.sequence.tare_s * daq.sample_rate_hz))
        with problems.check():
            if tare_n < self.safety.tare_min_samples:
                raise ValueError(f"sequence.tare_s={self.sequence.tare_s:g} at "
                                 f"{daq.sample_rate_hz:g} Hz gives {tare_n} tare samples: "
                                 "expected at least safety.tare_min_samples="
                                 f"{self.safety.tare_min_samples}")

    def _check_duration(self):
        seq, st = self.sequence, self.settle
        n = step_count(self)
        short, long = estimate_duration_s(self)
        if n > MAX_STEPS:
            raise ValueError(f"the sequence plans {n} steps, {short / 86400:.1f} to "
                             f"{long / 86400:.1f} days: expected at most {MAX_STEPS} steps "
                             "(split it into runs)")
        if long > seq.max_duration_h * 3600:
            raise ValueError(f"the sequence may take up to {long / 3600:.1f} h ({n} steps timing "
                             f"out after settle.timeout_s={st.timeout_s:g} s, plus tare and "
                             "pre-conditioning): expected at most sequence.max_duration_h="
                             f"{seq.max_duration_h:g} h (raise it, up to {MAX_DURATION_H:g} h, or "
                             "split the run)")

    def replace(self, **sections) -> BenchConfig:
        """A copy with some settings changed: ``replace(muscle={"eps": 0.1})``, recorded in
        ``overrides`` (and in :meth:`effective_text`)."""
        changes = {}
        for name, values in sections.items():
            try:
                changes[name] = _replace(getattr(self, name), values)
            except ValueError as exc:  # the muscle checks itself when made
                raise ValueError(f"{name}.{exc}") from None
        overrides = {**self.overrides, **{f"{name}.{key}": value for name, values in
                                          sections.items() for key, value in values.items()}}
        new = dataclasses.replace(self, **changes, overrides=overrides)
        for section in changes.values():
            if hasattr(section, "check"):
                section.check()
        new.check()
        return new

    def effective_text(self) -> str:
        """The configuration's text with its overrides written in, comments kept: what a run
        folder's ``config.toml`` holds, so that it says what run.json says."""
        if not self.overrides:
            return self.text
        import tomlkit

        document = tomlkit.parse(self.text) if self.text else tomlkit.document()
        for setting, value in self.overrides.items():
            section, _, key = setting.partition(".")
            _set_toml(document.setdefault(section, tomlkit.table()), {key: value})
        return tomlkit.dumps(document)

    def as_dict(self) -> dict[str, Any]:
        return {f.name: dataclasses.asdict(getattr(self, f.name))
                for f in dataclasses.fields(self)
                if f.name not in ("source", "text", "overrides", "recorded_source",
                                  "source_sha256")}


def _set_toml(table, values: dict[str, Any]) -> None:
    """Write ``values`` into the TOML ``table`` (a sub-table for a dict; None, which TOML
    cannot hold, removes the key: the setting's default)."""
    import tomlkit

    for key, value in values.items():
        if isinstance(value, dict):
            _set_toml(table.setdefault(key, tomlkit.table()), value)
        elif value is None:
            table.pop(key, None)
        else:
            table[key] = list(value) if isinstance(value, tuple) else value


def _replace(section, values: dict[str, Any]):
    nested = {k: _replace(getattr(section, k), v) for k, v in values.items()
              if isinstance(v, dict) and dataclasses.is_dataclass(getattr(section, k))}
    return dataclasses.replace(section, **{**values, **nested})


SECTIONS = {"muscle": read_muscle, "daq": Daq, "loadcell": LoadCell, "regulator": Regulator,
            "sequence": Sequence, "settle": Settle, "safety": Safety, "sim": Sim}
REQUIRED = ("muscle", "loadcell", "daq")


def parse_config(text: str, source: str = "<string>") -> BenchConfig:
    """Validate the TOML ``text`` of a bench configuration."""
    return config_from_tables(read_toml(text, f"config {source}"), text, source)


def config_from_tables(data: dict[str, Any], text: str, source: str) -> BenchConfig:
    """Validate the tables ``data`` (read from ``text``, named ``source``) into a config."""
    unknown = sorted(set(data) - set(SECTIONS))
    if unknown:
        raise ValueError(f"config {source}: [{unknown[0][:40]}] is not a section: expected "
                         f"{', '.join(SECTIONS)}")
    for required in REQUIRED:
        if required not in data:
            raise ValueError(f"config {source}: section [{required}] is missing"
                             + (_BACKEND_CHOICE if required == "daq" else ""))
    if isinstance(data["daq"], dict) and "backend" not in data["daq"]:
        raise ValueError(f"config {source}: daq.backend is missing" + _BACKEND_CHOICE)
    problems, sections = Problems(), {}
    for name, read in SECTIONS.items():
        if name in data:
            with problems.check():
                sections[name] = (read(data[name], name) if read is read_muscle
                                  else typed_section(read, data[name], name))
    problems.raise_any(f"config {source}: ")  # the settings between sections need them all
    with problems.check():
        config = BenchConfig(**sections, source=source, recorded_source=source, text=text)
        config.check()
    problems.raise_any(f"config {source}: ")
    return config


def _backend_choice() -> str:
    return (": expected [daq] backend = " + " or ".join(f"'{e.name}' ({e.label})"
                                                       for e in backends.BACKENDS.entries())
            + ", so the configuration says whether it drives hardware")


_BACKEND_CHOICE = _backend_choice()


def example_config():
    """The packaged example configuration (the paper's prototype on the simulated bench), the
    file to copy and edit (:func:`copy_example_config`)."""
    return resources.files("mkm.bench").joinpath("configs", DEFAULT_CONFIG)


def copy_example_config(path: str | Path) -> Path:
    """Write the packaged example into ``path`` (UTF-8, whatever the console's encoding: a
    redirection in Windows PowerShell would write UTF-16) and return it; an existing file is
    never overwritten."""
    path = Path(path)
    if path.exists():
        raise ValueError(f"{path} exists: kept as it is; name a new file for the example")
    if not path.parent.is_dir():
        raise ValueError(f"--example {str(path)!r}: no such folder {str(path.parent)!r}: "
                         "expected the file in an existing folder (make it first)")
    return write_atomic(path, example_config().read_text("utf-8"))


def load_config(path: str | Path | None = None, eps: float | None = None,
                pressures_bar=None, backend: str | None = None) -> BenchConfig:
    """The configuration in ``path`` (the packaged default when None).

    ``eps``, ``pressures_bar`` and ``backend`` override ``muscle.eps``,
    ``sequence.pressures_bar`` and ``daq.backend``, as ``mkm acquire --eps --pressures
    --backend`` do; the result is validated again.
    """
    if path is None:
        example = example_config()
        config = dataclasses.replace(
            parse_config(example.read_text("utf-8"), f"the packaged example {example}"),
            recorded_source=PACKAGED_CONFIG,
            source_sha256=hashlib.sha256(example.read_bytes()).hexdigest())
    else:
        text, data = read_toml_file(Path(path), "config ")
        config = dataclasses.replace(config_from_tables(data, text, str(path)),
                                     source_sha256=file_sha256(path))
    changes: dict[str, dict] = {}
    if eps is not None:
        changes["muscle"] = {"eps": float(eps)}
    if pressures_bar is not None:
        changes["sequence"] = {"pressures_bar": tuple(float(p) for p in pressures_bar)}
    if backend is not None and backend != config.daq.backend:
        changes["daq"] = {"backend": backend}
    try:
        return config.replace(**changes) if changes else config
    except ValueError as exc:
        # a value the command line gave is named as typed there, not as a setting of the file
        message = str(exc)
        for key, flag, given in (("sequence.pressures_bar", "--pressures", pressures_bar),
                                 ("muscle.eps", "--eps", eps)):
            if given is not None and message.startswith(key):
                raise ValueError(f"{flag}: {message}") from None
        raise


@dataclass(frozen=True)
class Step:
    """One planned pressure step of the staircase."""

    step: int
    direction: str  # "up" | "down"
    repeat: int
    set_pressure_bar: float


def plan_steps(config: BenchConfig) -> list[Step]:
    """The staircase: pressures up, then (optionally) down without repeating the top; x repeats."""
    seq = config.sequence
    up = list(seq.pressures_bar)
    down = up[-2::-1] if seq.down_sweep else []
    steps = []
    for repeat in range(seq.repeats):
        for direction, pressures in (("up", up), ("down", down)):
            for p in pressures:
                steps.append(Step(len(steps), direction, repeat, p))
    return steps


def step_count(config: BenchConfig) -> int:
    """``len(plan_steps(config))`` without making the steps (a configuration is checked for
    the size of its staircase before any is made)."""
    seq = config.sequence
    up = len(seq.pressures_bar)
    return (up + (up - 1 if seq.down_sweep else 0)) * seq.repeats


def estimate_duration_s(config: BenchConfig) -> tuple[float, float]:
    """Shortest and longest run time [s]: every step settling at min dwell, or timing out."""
    seq, st = config.sequence, config.settle
    fixed = seq.tare_s + 2 * seq.preconditioning_cycles * seq.preconditioning_hold_s
    n = step_count(config)
    return fixed + n * (st.min_dwell_s + st.hold_s), fixed + n * (st.timeout_s + st.hold_s)
