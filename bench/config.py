"""Bench configuration: one TOML file, validated into frozen dataclasses with clear errors.

The packaged default ``bench/configs/paper_prototype.toml`` reproduces the paper's prototype on the
simulated bench. Every setting has a unit in its name; a bad value raises ``ValueError`` naming the
``section.key``, the value and what was expected.
"""

from __future__ import annotations

import dataclasses
import re
import tomllib
from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path
from typing import Any

import numpy as np

from mkm.fem.ranges import parse_pressures

DEFAULT_CONFIG = "paper_prototype.toml"


@dataclass(frozen=True)
class DeviceCapabilities:
    """What a DAQ device can do, for validating a configuration before it is run."""

    product: str
    ai_rse: tuple[str, ...]  # single-ended (referenced to AI GND) inputs
    ai_differential: dict[str, str]  # differential input -> the terminal it pairs with
    terminal_configs: tuple[str, ...]
    max_aggregate_rate_hz: float  # over every input of the task (one multiplexed ADC)
    ai_range_V: float  # +- this
    ao: tuple[str, ...]
    ao_range_V: float  # +- this


# NI USB-6001/6002/6003 User Guide (ni.com, "Pinout and Signal Descriptions", "Analog Input"):
# AI 0-7 single-ended (RSE) or four differential channels AI 0-3 paired with AI 4-7 (AI <0,4>,
# <1,5>, <2,6>, <3,7>); no NRSE or pseudo-differential mode; one +-10 V range; two analog
# outputs AO 0-1, +-10 V. NI USB-6001/6002/6003 Specifications: 14-bit ADC, 20 kS/s aggregate
# maximum sample rate on the USB-6001.
USB6001 = DeviceCapabilities(
    product="USB-6001",
    ai_rse=tuple(f"ai{k}" for k in range(8)),
    ai_differential={f"ai{k}": f"ai{k + 4}" for k in range(4)},
    terminal_configs=("differential", "rse"),
    max_aggregate_rate_hz=20_000.0,
    ai_range_V=10.0,
    ao=("ao0", "ao1"),
    ao_range_V=10.0,
)
TERMINAL_CONFIGS = USB6001.terminal_configs
USB6001_RANGE_V = USB6001.ai_range_V
MUSCLE_ID_PATTERN = r"[A-Za-z0-9][A-Za-z0-9._+-]{0,63}"
# Geometry a bench muscle can have (the paper's prototype is D0 30 mm, L0 282 mm); beyond these
# a value is a typo (--D0 1e9 gives 3e17 N), not a muscle.
MAX_D0_MM, MAX_L0_MM = 200.0, 3000.0
MAX_STEPS = 2000  # a 2000-step staircase already takes 5 to 37 hours at the default settle
MAX_SETTLE_TIMEOUT_S = 3600.0
MAX_BUFFER_S = 24 * 3600.0
MAX_BUFFER_VALUES = 20_000_000  # samples x inputs in the driver's host buffer (160 MB)
MAX_BLOCK_S = 1.0  # a stop waits for the block in hand: keep it short


def _positive(name, value):
    if not value > 0:
        raise ValueError(f"{name}={value!r} is invalid: expected a number > 0")


def _fraction(name, value, low=0.0, high=1.0):
    if not low <= value <= high:
        raise ValueError(f"{name}={value!r} is invalid: expected a fraction in [{low}, {high}]")


@dataclass(frozen=True)
class Muscle:
    id: str
    D0_mm: float
    t0_mm: float
    L0_mm: float
    eps: float

    def check(self):
        for name in ("D0_mm", "t0_mm", "L0_mm"):
            _positive(f"muscle.{name}", getattr(self, name))
        if self.t0_mm >= self.D0_mm / 2:
            raise ValueError(f"muscle.t0_mm={self.t0_mm:g} is too thick for D0_mm="
                             f"{self.D0_mm:g}: expected t0_mm < D0_mm/2")
        if not 0.0 <= self.eps < 1.0:
            raise ValueError(f"muscle.eps={self.eps!r} is invalid: expected a shortening ratio "
                             "in [0, 1) (a fraction, 0.122 for 12.2 %)")
        if not re.fullmatch(MUSCLE_ID_PATTERN, self.id):
            shown = self.id if len(self.id) <= 40 else self.id[:40] + "..."
            raise ValueError(f"muscle.id={shown!r} ({len(self.id)} characters) is invalid: "
                             "expected 1 to 64 letters, digits or . _ + - (it names the run "
                             "folder and labels figures)")
        if self.D0_mm > MAX_D0_MM or self.L0_mm > MAX_L0_MM:
            raise ValueError(f"muscle D0_mm={self.D0_mm:g}, L0_mm={self.L0_mm:g} is not a bench "
                             f"muscle: expected D0_mm <= {MAX_D0_MM:g} and L0_mm <= "
                             f"{MAX_L0_MM:g}")


@dataclass(frozen=True)
class Daq:
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
        if self.terminal_config not in TERMINAL_CONFIGS:
            raise ValueError(f"daq.terminal_config={self.terminal_config!r} is invalid: the "
                             f"{USB6001.product} has only {' and '.join(TERMINAL_CONFIGS)} "
                             "inputs (no NRSE or pseudo-differential mode)")
        for name in ("sample_rate_hz", "read_block_samples", "read_timeout_s"):
            _positive(f"daq.{name}", getattr(self, name))
        if self.sample_rate_hz > USB6001.max_aggregate_rate_hz:
            raise ValueError(f"daq.sample_rate_hz={self.sample_rate_hz:g} is invalid: the "
                             f"{USB6001.product} samples at most "
                             f"{USB6001.max_aggregate_rate_hz:g} S/s over all its inputs")
        if not 600.0 <= self.buffer_s <= MAX_BUFFER_S:
            raise ValueError(f"daq.buffer_s={self.buffer_s:g} is invalid: expected 600 s (10 "
                             "minutes of samples, so a stalled reader loses nothing) to "
                             f"{MAX_BUFFER_S:g} s")
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
        if self.read_retries < 0:
            raise ValueError(f"daq.read_retries={self.read_retries} is invalid: expected >= 0")


@dataclass(frozen=True)
class LoadCell:
    capacity_N: float
    sensitivity_N_per_V: float
    offset_V: float = 0.0
    channel: str = "ai0"

    def check(self):
        if self.channel not in USB6001.ai_rse:
            raise ValueError(f"loadcell.channel={self.channel!r} is invalid: the "
                             f"{USB6001.product} has inputs {USB6001.ai_rse[0]} to "
                             f"{USB6001.ai_rse[-1]}")
        if abs(self.offset_V) >= USB6001_RANGE_V:
            raise ValueError(f"loadcell.offset_V={self.offset_V:g} is invalid: expected within "
                             f"the +-{USB6001_RANGE_V:g} V input range")
        _positive("loadcell.capacity_N", self.capacity_N)
        _positive("loadcell.sensitivity_N_per_V", self.sensitivity_N_per_V)
        full_scale_N = self.sensitivity_N_per_V * USB6001_RANGE_V
        if full_scale_N < self.capacity_N * 0.999:
            raise ValueError(
                f"loadcell.sensitivity_N_per_V={self.sensitivity_N_per_V:g} puts the +-10 V rail "
                f"at {full_scale_N:g} N, below capacity_N={self.capacity_N:g}: the cell would clip "
                "before its capacity; expected sensitivity_N_per_V >= capacity_N / 10 V")

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

    @property
    def electronic(self) -> bool:
        return self.kind == "electronic"

    def check(self):
        if self.kind not in ("electronic", "manual"):
            raise ValueError(f"regulator.kind={self.kind!r} is invalid: expected 'electronic' "
                             "or 'manual'")
        _positive("regulator.full_scale_bar", self.full_scale_bar)
        if not 0 < self.max_pressure_bar <= self.full_scale_bar:
            raise ValueError(f"regulator.max_pressure_bar={self.max_pressure_bar:g} is invalid: "
                             f"expected 0 < max <= full_scale_bar={self.full_scale_bar:g}")
        if not self.monitor_V_at_full_scale > self.monitor_V_at_zero:
            raise ValueError("regulator.monitor_V_at_full_scale must exceed monitor_V_at_zero")
        for name in ("monitor_V_at_zero", "monitor_V_at_full_scale"):
            if abs(getattr(self, name)) > USB6001_RANGE_V:
                raise ValueError(f"regulator.{name}={getattr(self, name):g} is invalid: the "
                                 f"{USB6001.product}'s inputs read +-{USB6001_RANGE_V:g} V")
        if self.command_channel not in USB6001.ao:
            raise ValueError(f"regulator.command_channel={self.command_channel!r} is invalid: "
                             f"the {USB6001.product} has outputs {', '.join(USB6001.ao)}")
        if self.monitor_channel not in USB6001.ai_rse:
            raise ValueError(f"regulator.monitor_channel={self.monitor_channel!r} is invalid: "
                             f"the {USB6001.product} has inputs {USB6001.ai_rse[0]} to "
                             f"{USB6001.ai_rse[-1]}")

    def command_volts(self, pressure_bar: float) -> float:
        """AO command [V, 0-10] for ``pressure_bar``, clamped to ``[0, max_pressure_bar]``."""
        clamped = min(max(float(pressure_bar), 0.0), self.max_pressure_bar)
        return clamped / self.full_scale_bar * 10.0

    def monitor_bar(self, volts):
        """Pressure [bar] from the monitor output volts (1-5 V over 0..full scale)."""
        span = self.monitor_V_at_full_scale - self.monitor_V_at_zero
        return (np.asarray(volts) - self.monitor_V_at_zero) / span * self.full_scale_bar


@dataclass(frozen=True)
class Sequence:
    pressures_bar: tuple[float, ...]
    down_sweep: bool = True
    repeats: int = 1
    preconditioning_cycles: int = 0
    preconditioning_hold_s: float = 5.0
    tare_s: float = 5.0

    def check(self):
        if len(self.pressures_bar) == 0:
            raise ValueError("sequence.pressures_bar is empty: expected at least one pressure")
        if self.repeats < 1:
            raise ValueError(f"sequence.repeats={self.repeats} is invalid: expected >= 1")
        if self.preconditioning_cycles < 0:
            raise ValueError(f"sequence.preconditioning_cycles={self.preconditioning_cycles} "
                             "is invalid: expected >= 0")
        _positive("sequence.tare_s", self.tare_s)
        _positive("sequence.preconditioning_hold_s", self.preconditioning_hold_s)


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
        for f in dataclasses.fields(self):
            _positive(f"settle.{f.name}", getattr(self, f.name))
        if self.timeout_s > MAX_SETTLE_TIMEOUT_S:
            raise ValueError(f"settle.timeout_s={self.timeout_s:g} is invalid: expected at most "
                             f"{MAX_SETTLE_TIMEOUT_S:g} s per step")
        if self.timeout_s < self.min_dwell_s:
            raise ValueError(f"settle.timeout_s={self.timeout_s:g} is below min_dwell_s="
                             f"{self.min_dwell_s:g}: expected timeout_s >= min_dwell_s")


@dataclass(frozen=True)
class Safety:
    """Interlocks and the checks a tare must pass before any pressure is commanded.

    The force interlock trips at ``force_limit_fraction`` of the load-cell capacity (or at any
    non-finite force or pressure). The pressure interlock (electronic regulator) trips when the
    measured pressure stays more than ``pressure_tolerance_bar`` from the command for longer
    than ``pressure_follow_s`` (a regulator that does not follow), or exceeds
    ``regulator.max_pressure_bar`` by more than the tolerance (overshoot). The tare needs at
    least ``tare_min_samples`` finite samples, a spread below ``tare_max_std_N`` and an offset
    within ``tare_max_shift_N`` of the configured ``loadcell.offset_V``.
    """

    force_limit_fraction: float = 0.9
    pressure_tolerance_bar: float = 0.15
    pressure_follow_s: float = 5.0
    tare_min_samples: int = 10
    tare_max_std_N: float = 5.0
    tare_max_shift_N: float = 100.0

    def check(self):
        if not 0 < self.force_limit_fraction <= 1:
            raise ValueError(f"safety.force_limit_fraction={self.force_limit_fraction!r} is "
                             "invalid: expected a fraction of the load-cell capacity in (0, 1]")
        for name in ("pressure_tolerance_bar", "pressure_follow_s", "tare_max_std_N",
                     "tare_max_shift_N"):
            _positive(f"safety.{name}", getattr(self, name))
        if self.tare_min_samples < 2:
            raise ValueError(f"safety.tare_min_samples={self.tare_min_samples} is invalid: "
                             "expected >= 2 (a spread needs two samples)")


@dataclass(frozen=True)
class Faults:
    """Faults the simulated bench injects, at sample time [s]; absent means never."""

    disconnect_at_s: float | None = None
    read_timeout_at_s: float | None = None
    read_timeouts: int = 1
    stall_at_s: float | None = None
    stall_s: float = 0.0
    ao_fail_at_s: float | None = None
    nan_force_at_s: float | None = None  # the load-cell input reads NaN from then on
    regulator_stuck_at_s: float | None = None  # the regulator stops following the command
    overshoot_bar: float = 0.0  # the regulator delivers this much above every command

    def check(self):
        if self.overshoot_bar < 0:
            raise ValueError(f"sim.faults.overshoot_bar={self.overshoot_bar:g} is invalid: "
                             "expected >= 0")
        if self.read_timeouts < 1:
            raise ValueError(f"sim.faults.read_timeouts={self.read_timeouts} is invalid: "
                             "expected >= 1")
        if self.stall_s < 0:
            raise ValueError(f"sim.faults.stall_s={self.stall_s:g} is invalid: expected >= 0")


@dataclass(frozen=True)
class Sim:
    """The simulated bench (:mod:`mkm.bench.sim`): the muscle's static force from ``model`` (a
    ``mkm.fem.ladder`` rung; ``axisym`` on the ``fe_mesh`` mesh), braid friction, creep, noise."""

    model: str = "axisym"
    fe_mesh: str = "medium"
    seed: int = 0
    regulator_tau_s: float = 0.4
    regulator_slew_bar_per_s: float = 2.0
    hysteresis_fraction: float = 0.03
    creep_fraction: float = 0.02
    creep_tau_s: float = 30.0
    noise_V: float = 0.002
    loadcell_offset_V: float = 0.015
    monitor_noise_V: float = 0.001
    buffer_s: float | None = None
    faults: Faults = field(default_factory=Faults)

    def check(self):
        from mkm.fem.ladder import model_names

        if self.model not in model_names():
            raise ValueError(f"sim.model={self.model!r} is unknown: expected one of "
                             f"{', '.join(model_names())}")
        if self.fe_mesh not in ("coarse", "medium", "fine"):
            raise ValueError(f"sim.fe_mesh={self.fe_mesh!r} is invalid: expected coarse, medium "
                             "or fine")
        for name in ("regulator_tau_s", "regulator_slew_bar_per_s", "creep_tau_s"):
            _positive(f"sim.{name}", getattr(self, name))
        for name in ("hysteresis_fraction", "creep_fraction"):
            _fraction(f"sim.{name}", getattr(self, name), 0.0, 0.5)
        for name in ("noise_V", "monitor_noise_V"):
            if getattr(self, name) < 0:
                raise ValueError(f"sim.{name}={getattr(self, name)!r} is invalid: expected >= 0")
        if self.buffer_s is not None:
            _positive("sim.buffer_s", self.buffer_s)
        self.faults.check()


@dataclass(frozen=True)
class BenchConfig:
    muscle: Muscle
    loadcell: LoadCell
    daq: Daq = field(default_factory=Daq)
    regulator: Regulator = field(default_factory=Regulator)
    sequence: Sequence = field(default_factory=lambda: Sequence((0.5, 1.0)))
    settle: Settle = field(default_factory=Settle)
    safety: Safety = field(default_factory=Safety)
    sim: Sim = field(default_factory=Sim)
    source: str = ""
    text: str = ""
    overrides: dict[str, Any] = field(default_factory=dict)  # changes made after reading `text`

    @property
    def force_limit_N(self) -> float:
        return self.safety.force_limit_fraction * self.loadcell.capacity_N

    @property
    def ai_channels(self) -> list[str]:
        """Inputs of the AI task: the load cell, and the regulator monitor if electronic."""
        ai = [self.loadcell.channel]
        if self.regulator.electronic:
            ai.append(self.regulator.monitor_channel)
        return ai

    def check(self):
        too_high = [p for p in self.sequence.pressures_bar if p > self.regulator.max_pressure_bar]
        if too_high:
            raise ValueError(f"sequence.pressures_bar has {too_high[0]:g} bar, above "
                             f"regulator.max_pressure_bar={self.regulator.max_pressure_bar:g}: "
                             "expected every planned pressure within the limit")
        self._check_device()
        self._check_duration()

    def _check_device(self):
        """Against the USB-6001's capabilities (:data:`USB6001`)."""
        ai, daq = self.ai_channels, self.daq
        if len(set(ai)) < len(ai):
            raise ValueError(f"loadcell.channel and regulator.monitor_channel are both {ai[0]}: "
                             "expected two different inputs")
        if daq.terminal_config == "differential":
            pairs = USB6001.ai_differential
            for name, channel in zip(("loadcell.channel", "regulator.monitor_channel"), ai,
                                     strict=False):
                if channel not in pairs:
                    raise ValueError(
                        f"{name}={channel!r} cannot be differential on the {USB6001.product}: "
                        f"only {', '.join(pairs)} are (paired with "
                        f"{', '.join(pairs.values())}); use one of those or "
                        "daq.terminal_config = 'rse'")
        aggregate = daq.sample_rate_hz * len(ai)
        if aggregate > USB6001.max_aggregate_rate_hz:
            raise ValueError(f"daq.sample_rate_hz={daq.sample_rate_hz:g} on {len(ai)} inputs is "
                             f"{aggregate:g} S/s: the {USB6001.product} samples at most "
                             f"{USB6001.max_aggregate_rate_hz:g} S/s in aggregate")
        if daq.buffer_samples * len(ai) > MAX_BUFFER_VALUES:
            raise ValueError(f"daq.buffer_s={daq.buffer_s:g} at {daq.sample_rate_hz:g} Hz is "
                             f"{daq.buffer_samples * len(ai)} buffered values: expected at most "
                             f"{MAX_BUFFER_VALUES} (shorten the buffer or the rate)")
        tare_n = int(round(self.sequence.tare_s * daq.sample_rate_hz))
        if tare_n < self.safety.tare_min_samples:
            raise ValueError(f"sequence.tare_s={self.sequence.tare_s:g} at "
                             f"{daq.sample_rate_hz:g} Hz gives {tare_n} tare samples: expected at "
                             f"least safety.tare_min_samples={self.safety.tare_min_samples}")

    def _check_duration(self):
        seq, st = self.sequence, self.settle
        up = len(seq.pressures_bar)
        n = (up + (up - 1 if seq.down_sweep else 0)) * seq.repeats  # as bench.sequence plans
        if n > MAX_STEPS:
            fixed = seq.tare_s + 2 * seq.preconditioning_cycles * seq.preconditioning_hold_s
            short = (fixed + n * (st.min_dwell_s + st.hold_s)) / 86400
            long = (fixed + n * (st.timeout_s + st.hold_s)) / 86400
            raise ValueError(f"the sequence plans {n} steps, {short:.1f} to {long:.1f} "
                             f"days: expected at most {MAX_STEPS} steps (split it into runs)")

    def replace(self, **sections) -> BenchConfig:
        """A copy with some settings changed: ``replace(muscle={"eps": 0.1})``."""
        changes = {name: _replace(getattr(self, name), values)
                   for name, values in sections.items()}
        overrides = {**self.overrides, **{f"{name}.{key}": value for name, values in
                                          sections.items() for key, value in values.items()}}
        new = dataclasses.replace(self, **changes, overrides=overrides)
        for section in changes.values():
            section.check()
        new.check()
        return new

    def as_dict(self) -> dict[str, Any]:
        return {f.name: dataclasses.asdict(getattr(self, f.name))
                for f in dataclasses.fields(self)
                if f.name not in ("source", "text", "overrides")}


def _replace(section, values: dict[str, Any]):
    nested = {k: _replace(getattr(section, k), v) for k, v in values.items()
              if isinstance(v, dict) and dataclasses.is_dataclass(getattr(section, k))}
    return dataclasses.replace(section, **{**values, **nested})


SECTIONS = {"muscle": Muscle, "daq": Daq, "loadcell": LoadCell, "regulator": Regulator,
            "sequence": Sequence, "settle": Settle, "safety": Safety, "sim": Sim}


def _section(cls, table: Any, where: str):
    if not isinstance(table, dict):
        raise ValueError(f"[{where}] must be a table of settings, got {table!r}")
    fields = {f.name: f for f in dataclasses.fields(cls)}
    unknown = sorted(set(table) - set(fields))
    if unknown:
        raise ValueError(f"{where}.{unknown[0]} is not a setting: expected some of "
                         f"{', '.join(fields)}")
    values = {}
    for name, f in fields.items():
        key = f"{where}.{name}"
        if name not in table:
            if f.default is dataclasses.MISSING and f.default_factory is dataclasses.MISSING:
                raise ValueError(f"{key} is missing: it has no default")
            continue
        values[name] = _convert(table[name], f.type, key)
    obj = cls(**values)
    obj.check()
    return obj


def _convert(value, annotation: str, key: str):
    kinds = {"str": str, "float": float, "int": int, "bool": bool}
    if annotation == "Faults":
        return _section(Faults, value, key)
    if annotation == "tuple[float, ...]":
        return _pressures(value, key)
    optional = annotation.endswith(" | None")
    base = annotation.removesuffix(" | None")
    if optional and value is None:
        return None
    expected = kinds[base]
    if expected is float and isinstance(value, int) and not isinstance(value, bool):
        value = float(value)
    if not isinstance(value, expected) or (expected is int and isinstance(value, bool)):
        raise ValueError(f"{key}={value!r} is invalid: expected a {base}")
    if expected is float and not np.isfinite(value):
        raise ValueError(f"{key}={value!r} is not a finite number")
    return value


def _pressures(value, key: str) -> tuple[float, ...]:
    if isinstance(value, str):
        return tuple(float(p) for p in parse_pressures(value))
    if isinstance(value, list) and all(isinstance(v, int | float) for v in value):
        return tuple(float(p) for p in parse_pressures(",".join(str(v) for v in value)))
    raise ValueError(f"{key}={value!r} is invalid: expected 'start:stop:step' or a list of "
                     "numbers [bar]")


def parse_config(text: str, source: str = "<string>") -> BenchConfig:
    """Validate the TOML ``text`` of a bench configuration."""
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise ValueError(f"config {source} is not valid TOML: {exc}") from None
    unknown = sorted(set(data) - set(SECTIONS))
    if unknown:
        raise ValueError(f"config {source}: [{unknown[0]}] is not a section: expected "
                         f"{', '.join(SECTIONS)}")
    for required in ("muscle", "loadcell"):
        if required not in data:
            raise ValueError(f"config {source}: section [{required}] is missing")
    try:
        sections = {name: _section(cls, data[name], name)
                    for name, cls in SECTIONS.items() if name in data}
    except ValueError as exc:
        raise ValueError(f"config {source}: {exc}") from None
    config = BenchConfig(**sections, source=source, text=text)
    try:
        config.check()
    except ValueError as exc:
        raise ValueError(f"config {source}: {exc}") from None
    return config


def load_config(path: str | Path | None = None, eps: float | None = None,
                pressures_bar=None) -> BenchConfig:
    """The configuration in ``path`` (the packaged default when None).

    ``eps`` and ``pressures_bar`` override ``muscle.eps`` and ``sequence.pressures_bar``, as
    ``mkm acquire --eps --pressures`` do; the result is validated again.
    """
    if path is None:
        text = resources.files("mkm.bench").joinpath("configs", DEFAULT_CONFIG).read_text("utf-8")
        config = parse_config(text, f"bench/configs/{DEFAULT_CONFIG}")
    else:
        path = Path(path)
        if not path.is_file():
            raise ValueError(f"config {path} does not exist: expected a TOML file")
        config = parse_config(path.read_text(encoding="utf-8"), str(path))
    changes = {}
    if eps is not None:
        changes["muscle"] = {"eps": float(eps)}
    if pressures_bar is not None:
        changes["sequence"] = {"pressures_bar": tuple(float(p) for p in pressures_bar)}
    return config.replace(**changes) if changes else config

