"""The run's procedure: tare at 0 bar, pre-conditioning cycles, the pressure staircase.

At each step the pressure is set, the reading is judged steady over the last ``settle.window_s``
once per second of data (:func:`settle_reached`), then held ``settle.hold_s`` and averaged, with
the step's uncertainty budget (:mod:`mkm.bench.budget`). Only
a window's worth of samples is kept while waiting and running sums while holding, so a step
costs time and memory linear in its length, whatever ``settle.timeout_s``.

The tare must pass :func:`validate_tare` before any pressure is commanded: enough samples, a
finite mean, a spread and a shift from the configured offset within ``[safety]`` limits.
"""

from __future__ import annotations

import math
from collections import deque
from statistics import NormalDist

import numpy as np

from mkm.bench import backends
from mkm.bench.backend import BenchError
from mkm.bench.budget import Instrument, step_budget
from mkm.bench.config import BenchConfig, Step, plan_steps
from mkm.bench.preflight import LIMIT_SHARE, lowest_step, percent
from mkm.bench.storage import StepRecord
from mkm.bench.worker import STUCK_CELL_S, UNMOVED_CELL_STEPS, Acquisition


def settle_reached(t_s: np.ndarray, force_N: np.ndarray, pressure_bar: np.ndarray,
                   set_pressure_bar: float, config: BenchConfig) -> bool:
    """Whether the last ``settle.window_s`` of a step is steady.

    Steady means: the force's least-squares slope and its standard deviation are below the
    thresholds and, when the pressure is measured (``pressure_bar`` not NaN), the window's mean
    pressure is within tolerance of the set pressure.
    """
    st = config.settle
    window = t_s >= t_s[-1] - st.window_s
    t, f, p = t_s[window], force_N[window], pressure_bar[window]
    if t.size < 3 or t[-1] - t[0] < 0.5 * st.window_s:
        return False
    slope = np.polyfit(t - t[0], f, 1)[0]
    if abs(slope) > st.max_force_slope_N_per_s or np.std(f) > st.max_force_std_N:
        return False
    measured = p[np.isfinite(p)]
    return measured.size == 0 or abs(measured.mean() - set_pressure_bar) <= \
        st.pressure_tolerance_bar


def settle_warning(tare_std_N: float, config: BenchConfig) -> str:
    """What a load cell noisier at rest than ``settle.max_force_std_N`` does to a run (no step
    can settle: each waits ``settle.timeout_s`` and is recorded unsettled), or "". The limit it
    asks for is three times the spread; where that lets more than
    :data:`~mkm.bench.preflight.LIMIT_SHARE` of the force at the lowest planned step into a
    step, the cell is too noisy for the muscle, and it asks for a cell instead."""
    st = config.settle
    if not tare_std_N > st.max_force_std_N:
        return ""
    said = (f"the load cell spreads {tare_std_N:.2f} N rms at 0 bar, above "
            f"settle.max_force_std_N={st.max_force_std_N:g}: no step can settle, each will wait "
            f"settle.timeout_s={st.timeout_s:g} s and be recorded settled = false; ")
    low_bar, force_N = lowest_step(config)
    if force_N > 0 and 3 * tare_std_N > LIMIT_SHARE * force_N:
        return (said + f"a limit this cell can settle under, about {3 * tare_std_N:.2g} N, is "
                f"{percent(3 * tare_std_N / force_N)} % of the {force_N:.2g} N the muscle pulls "
                f"at the lowest step, {low_bar:g} bar: the cell is too noisy for this muscle, use "
                "a quieter or smaller one (Ctrl-C stops the run at a safe point, vented)")
    return (said + f"for this cell set [settle] max_force_std_N to about {3 * tare_std_N:.2g} "
            "(Ctrl-C stops the run at a safe point, vented)")


#: the halves of a vented reading differ by more than this many standard errors: still falling
VENTED_HALVES_SE = 4.0


def vented_monitor(monitor_bar) -> dict:
    """The pressure monitor's zero as the tare reads it, vented: ``monitor_vented_bar``, the mean
    of the tare's second half (the first lets a muscle still deflating empty), its standard
    error ``monitor_vented_se_bar`` and standard deviation ``monitor_vented_std_bar`` (a single
    reading's spread: the vent check's, :class:`mkm.bench.vent.VentedZero`), and
    ``monitor_vented_settled``, False when the halves
    differ by more than :data:`VENTED_HALVES_SE` standard errors (the pressure still falling:
    no zero). Empty with fewer than 4 finite readings."""
    p = np.asarray(monitor_bar, dtype=float)
    p = p[np.isfinite(p)]
    if p.size < 4:
        return {}
    first, second = p[: p.size // 2], p[p.size // 2:]
    se = float(second.std(ddof=1) / np.sqrt(second.size))
    apart = math.hypot(first.std(ddof=1) / np.sqrt(first.size), se)
    settled = bool(abs(first.mean() - second.mean()) <= VENTED_HALVES_SE * max(apart, 1e-12))
    return {"monitor_vented_bar": float(second.mean()), "monitor_vented_se_bar": se,
            "monitor_vented_std_bar": float(second.std(ddof=1)),
            "monitor_vented_settled": settled}


def monitor_zero_warning(tare: dict, config: BenchConfig) -> str:
    """What a monitor reading vented further from 0 than its declared offset bound
    (:meth:`mkm.bench.config.Regulator.reading_bounds`, beyond 3 standard errors) means, or
    ""."""
    if not tare.get("monitor_vented_settled"):
        return ""
    mean, se = tare["monitor_vented_bar"], tare["monitor_vented_se_bar"]
    bound = config.regulator.reading_bounds()[0]
    if abs(mean) <= bound + 3.0 * se:
        return ""
    return (f"the pressure monitor reads {mean:+.4f} bar vented, beyond the +-{bound:g} bar its "
            "configuration declares ([regulator] monitor_accuracy_bar or its components): its "
            f"zero is off ({_zero_said(mean, config)}), or the muscle is not open to the air; "
            "every pressure of this run is read from that zero")


def monitor_low_bar(tare: dict) -> float:
    """How far below 0 bar the monitor reads vented [bar]: its settled zero where more than 3
    standard errors below 0 (a pressure the over-pressure limit adds to every reading), else
    0."""
    mean, se = tare.get("monitor_vented_bar"), tare.get("monitor_vented_se_bar", 0.0)
    if not tare.get("monitor_vented_settled") or mean is None or not mean < -3.0 * se:
        return 0.0
    return -float(mean)


class TareInvalid(BenchError):
    """The tare at 0 bar is not usable: the run must not start."""


def check_vented_monitor(tare: dict, config: BenchConfig) -> None:
    """:class:`TareInvalid` when the monitor reads, vented, further from 0 than
    ``safety.vent_below_bar``: no vent of the run could be verified by it (reading high, every
    vent check would fail with the muscle empty; reading low, it would pass with the muscle
    holding that much)."""
    mean = tare.get("monitor_vented_bar")
    below = config.safety.vent_below_bar
    if mean is not None and abs(mean) > below:
        raise TareInvalid(f"tare invalid: the pressure monitor reads {mean:+.3f} bar with the "
                          f"regulator vented, beyond safety.vent_below_bar={below:g}: it cannot "
                          f"verify a vent (its zero is off: {_zero_said(mean, config)}; its "
                          "wiring or scaling is wrong, or the muscle is not open to the air); "
                          "nothing was pressurised")


def _zero_said(vented_bar: float, config: BenchConfig) -> str:
    """The volts the monitor gives vented against the configured zero's, and the setting that
    takes them, for a muscle known open to the air."""
    regulator = config.regulator
    said = (f"it gives {float(regulator.monitor_volts(vented_bar)):.4g} V vented, "
            f"[regulator] monitor_V_at_zero = {regulator.monitor_V_at_zero:g} V; with the "
            "muscle open to the air, set monitor_V_at_zero to what it gives")
    offset = config.sim.truth.monitor_offset_bar if config.simulated else None
    # the simulated sensor reads its truth through the declared scaling: no zero declared
    # takes its offset away
    return said + (f" (simulated: [sim.truth] monitor_offset_bar = {offset:g} bar moves any "
                   "zero declared)" if offset else "")


def validate_tare(cell_V, config: BenchConfig, pressure_to_follow: bool = True) -> dict:
    """The tare of load-cell volts ``cell_V`` read at 0 bar, or :class:`TareInvalid` saying why.

    ``pressure_to_follow``: the tare comes before pressure (a run's, ``mkm tare``'s, ``mkm
    check``'s), so a cell that reads one code or sticks, behind which the force limit would be
    blind, is refused; False for a recorded run's tare (``mkm reprocess``), whose offset is
    taken again whatever the cell did after it.

    Returns ``offset_V`` (mean), ``std_V``, ``n``, ``std_N``, ``shift_N`` (offset minus the
    configured ``loadcell.offset_V``, in newtons), ``drift_N`` (the forces' straight-line trend,
    first to last sample) and ``at_rest`` (:func:`rest_warning` says what its absence means).
    """
    cell, safety = config.loadcell, config.safety
    v = np.asarray(cell_V, dtype=float)
    if v.size < safety.tare_min_samples:
        raise TareInvalid(f"tare invalid: {v.size} samples, expected at least "
                          f"safety.tare_min_samples={safety.tare_min_samples}")
    if not np.isfinite(v).all():
        raise TareInvalid(f"tare invalid: {int((~np.isfinite(v)).sum())} of {v.size} load-cell "
                          "samples are not numbers (a broken input)")
    step_V = backends.entry(config.daq.backend).capabilities.ai_lsb_V
    if pressure_to_follow and v.max() == v.min():
        raise TareInvalid(one_code_refusal(float(v[0]), v.size, config))
    offset, std = float(v.mean()), float(v.std(ddof=1))
    std_N = std * cell.sensitivity_N_per_V
    shift_N = (offset - cell.offset_V) * cell.sensitivity_N_per_V
    if std_N > safety.tare_max_std_N:
        raise TareInvalid(f"tare invalid: the load cell spreads {std_N:.2f} N rms at 0 bar, "
                          f"above safety.tare_max_std_N={safety.tare_max_std_N:g} (a loose "
                          "wire, vibration, or a load on the cell)")
    if abs(shift_N) > safety.tare_max_shift_N:
        raise TareInvalid(f"tare invalid: the offset is {shift_N:+.1f} N from loadcell.offset_V"
                          f"={cell.offset_V:g} V, beyond safety.tare_max_shift_N="
                          f"{safety.tare_max_shift_N:g} (a load on the cell, or the wrong "
                          "calibration)")
    _, intervals, stray_V = held_tail(v)
    held_s = intervals / config.daq.sample_rate_hz
    if pressure_to_follow and stray_V > step_V and held_s >= STUCK_CELL_S - 1e-9:
        raise TareInvalid(f"tare invalid: the load cell read {v[-1]:.4f} V unchanged for the "
                          f"last {held_s:.1f} s of the tare, where it strayed "
                          f"{stray_V * cell.sensitivity_N_per_V:.2f} N before: a stuck or "
                          "disconnected load cell, behind which the force limit is not watched; "
                          "check its cable, amplifier and supply; nothing was pressurised")
    drift_N, at_rest = _tare_drift(v * cell.sensitivity_N_per_V, config)
    return {"offset_V": offset, "std_V": std, "n": int(v.size), "std_N": std_N,
            "shift_N": shift_N, "config_offset_V": cell.offset_V, "drift_N": drift_N,
            "at_rest": at_rest, "held_s": held_s, "stray_V": stray_V}


#: a live load cell's tare is refused as one on a single ADC code at most this often, for a cell
#: as noisy as :func:`one_code_noise_V` says (a tare again costs seconds; a stuck cell passed,
#: the force limit is blind)
ONE_CODE_ODDS = 1e-3


def one_code_noise_V(n: int, step_V: float, odds: float = ONE_CODE_ODDS) -> float:
    """The rms noise [V] from which a live cell's ``n`` readings all lie on one ADC code of
    ``step_V`` with probability at most ``odds``.

    With Gaussian noise of spread sigma, a reading falls on a code with probability ``p_k``,
    the largest ``2 Phi(step / 2 sigma) - 1`` (the cell's mean at the code's centre); all ``n``
    on one code has probability ``sum p_k^n <= max p_k^(n - 1)``. So sigma at which that bound
    is ``odds``: 0.40 mV (a third of the USB-6001's 1.22 mV step) over 50 readings, 0.59 mV
    over 20."""
    p = odds ** (1.0 / (n - 1))
    return step_V / (2.0 * NormalDist().inv_cdf((1.0 + p) / 2.0))


def one_code_refusal(cell_V: float, n: int, config: BenchConfig) -> str:
    """Why a tare whose ``n`` load-cell readings all read ``cell_V`` [V] is refused: a stuck,
    disconnected or railed cell reads so, and the force limit is blind behind it (neither the
    force nor the stuck-cell interlock can tell it from a slack muscle)."""
    cell = config.loadcell
    caps = backends.entry(config.daq.backend).capabilities
    step_V = caps.ai_lsb_V
    quiet_V = one_code_noise_V(n, step_V)
    rail = (f", at the input's {math.copysign(caps.ai_range_V, cell_V):+g} V rail"
            if abs(cell_V) >= caps.ai_range_V - 2 * step_V else "")
    return (f"tare invalid: the load cell read one ADC code, {cell_V:.4f} V "
            f"({float(cell.force_N(cell_V)):+.1f} N at loadcell.offset_V={cell.offset_V:g} V"
            f"{rail}), all {n} times: a stuck, disconnected or railed cell reads so, and the "
            "force limit is blind behind it; a live cell's noise moves it (one spreading "
            f"{quiet_V * 1e3:.2f} mV rms or more, {_share(quiet_V / step_V)} the "
            f"{step_V * 1e3:.2f} mV step, shows two codes in all but one tare of {n} readings "
            f"in {1 / ONE_CODE_ODDS:,.0f}); check the cell's cable, amplifier and supply, and "
            "load it by hand to see its reading move (a live cell quieter than that: lengthen "
            "sequence.tare_s); nothing was pressurised")


def _share(ratio: float) -> str:
    """``ratio`` of a whole in words: "0.49 of", "399 times"."""
    return f"{ratio:.2g} of" if ratio < 1 else f"{ratio:.3g} times"


def held_tail(cell_V) -> tuple[float, int, float]:
    """The code the load-cell readings ``cell_V`` [V] end on, how many sample intervals it has
    been held (0 when the last two readings differ), and the readings' spread [V] before it
    (their standard deviation; all the readings' with fewer than two before it): a live cell's
    noise, which a cell that stuck early in a tare no longer shows in the tare's whole spread.
    The stuck-cell rule of :data:`mkm.bench.worker.STUCK_CELL_S`, held from the tare into the
    run."""
    v = np.asarray(cell_V, dtype=float)
    changed = np.flatnonzero(v != v[-1])
    first = int(changed[-1] + 1) if changed.size else 0
    before = v[:first] if first >= 2 else v
    return float(v[-1]), int(v.size - 1 - first), float(before.std(ddof=1)) \
        if before.size > 1 else 0.0


def _tare_drift(force_N: np.ndarray, config: BenchConfig) -> tuple[float, bool]:
    """The straight-line trend of the tare's forces, first to last sample [N], and whether the
    load cell was at rest: a trend within 4 standard errors of none (a resting cell's noise
    goes beyond it in one tare of 20 samples in 1,200, by Student's t with 18 degrees of
    freedom; of 50, in 4,600), or within the zero drift the uncertainty budget allows over a run
    (``loadcell.zero_drift_fraction_fs`` of the capacity). A muscle still relaxing, or touched,
    moves its zero while the tare averages it."""
    cell = config.loadcell
    n = force_N.size
    t = np.arange(n) / config.daq.sample_rate_hz
    (slope, _), residual = np.polyfit(t, force_N, 1, full=True)[:2]
    spread = float(np.sum((t - t.mean()) ** 2))
    se = math.sqrt(float(residual[0]) / (n - 2) / spread) if residual.size and n > 2 else 0.0
    drift_N = float(slope * t[-1])
    bound_N = cell.zero_drift_fraction_fs * cell.capacity_N
    return drift_N, bool(abs(slope) <= 4.0 * se or abs(drift_N) <= bound_N)


def rest_warning(tare: dict, config: BenchConfig) -> str:
    """What a tare that did not see the load cell at rest means (its zero moved while it was
    averaged), or ""."""
    if tare.get("at_rest", True):
        return ""
    cell = config.loadcell
    drift_N, n = tare["drift_N"], tare["n"]
    return (f"the tare did not see the load cell at rest: its force moved {drift_N:+.2f} N "
            f"over the {n / config.daq.sample_rate_hz:g} s of the tare, beyond noise and the "
            f"zero drift of {cell.zero_drift_fraction_fs * cell.capacity_N:.2g} N the "
            f"uncertainty budget allows (loadcell.zero_drift_fraction_fs): the zero it "
            f"measured, and every force from it, may be off by about {abs(drift_N) / 2:.2g} N; "
            "let the muscle rest vented and tare again (or lengthen sequence.tare_s)")


def shift_warning(tare: dict, config: BenchConfig) -> str:
    """What a tare whose zero lies more than :data:`~mkm.bench.preflight.LIMIT_SHARE` of the
    force at the lowest planned step (:func:`~mkm.bench.preflight.lowest_step`) from
    ``loadcell.offset_V`` means (``safety.tare_max_shift_N``, a bound for the cell, lets it
    pass): a load left on the cell at the tare is taken off every force, and the force limit
    does not see it; or the configured zero is not the cell's. Or ""."""
    low_bar, force_N = lowest_step(config)
    shift_N, cell = tare["shift_N"], config.loadcell
    if force_N <= 0 or not abs(shift_N) > LIMIT_SHARE * force_N:
        return ""
    return (f"the tare's zero is {shift_N:+.2f} N from loadcell.offset_V={cell.offset_V:g} V, "
            f"{percent(abs(shift_N) / force_N)} % of the {force_N:.2g} N the muscle pulls at the "
            f"lowest step, {low_bar:g} bar (safety.tare_max_shift_N="
            f"{config.safety.tare_max_shift_N:g} lets it pass): a load left on the cell at the "
            "tare (the muscle not hanging free, a fixture resting on the cell) is taken off every "
            "force, and the force limit does not see it; remove it and tare again, or, if the "
            f"cell hung unloaded, set loadcell.offset_V to its zero, {tare['offset_V']:.4f} V")


def one_code_warning(tare: dict, config: BenchConfig) -> str:
    """What a tare whose last :data:`mkm.bench.worker.STUCK_CELL_S` lay on one ADC code
    (``held_s``) after readings that strayed less than a step (else :func:`validate_tare`
    refuses it, as it refuses a tare all on one code) means: a stuck or disconnected cell reads
    so, and the force limit is blind behind it (the stuck-cell interlock needs a tare that
    strays); a cell quieter than one step reads so too. Else what a tare whose readings strayed
    less than a step (``stray_V``) means: that interlock is off for the run. Or ""."""
    step_V = backends.entry(config.daq.backend).capabilities.ai_lsb_V
    held_s = tare.get("held_s", 0.0)
    step_mV = step_V * 1e3
    if not held_s >= STUCK_CELL_S - 1e-9:
        stray_V = tare.get("stray_V", math.inf)
        if stray_V > step_V:
            return ""
        cell = config.loadcell
        return (f"the load cell spreads {stray_V * 1e3:.2f} mV rms at 0 bar "
                f"({stray_V * cell.sensitivity_N_per_V:.2f} N), less than one ADC step "
                f"({step_mV:.2f} mV): one code held {STUCK_CELL_S:g} s cannot tell it stuck from "
                "quiet, so a cell that sticks is found only once the pressure rises or falls by "
                f"what must move the muscle's force {UNMOVED_CELL_STEPS} ADC steps (never where it "
                "stays slack), the force limit blind meanwhile")
    read = (f"on one ADC code for its last {held_s:.1f} s, where it strayed less than a step "
            "before")
    return (f"the tare read the load cell {read}: a stuck or disconnected cell reads so, and "
            f"hides every force from the force limit; a cell quieter than one step "
            f"({step_mV:.2f} mV) too: load the cell by hand and see its reading move before any "
            "pressure")


class HoldStats:
    """Running mean, spread and straight-line trend (Welford's updates) of a hold's samples.

    Memory does not grow with the hold; :meth:`record` turns them into the step's row of
    ``steps.csv``, with its uncertainty budget (:func:`mkm.bench.budget.step_budget`).
    """

    def __init__(self):
        self.n, self.mean, self.m2 = 0, 0.0, 0.0
        self.t_mean, self.t_m2, self.tf_c = 0.0, 0.0, 0.0
        self.t_first, self.t_last = math.nan, math.nan
        self.p_sum, self.p_n = 0.0, 0

    def add(self, time_s: float, force_N: float, pressure_bar: float) -> None:
        if self.n == 0:
            self.t_first = time_s
        self.t_last = time_s
        t = time_s - self.t_first  # from the hold's start: no cancellation over long runs
        self.n += 1
        delta, dt = force_N - self.mean, t - self.t_mean
        self.mean += delta / self.n
        self.t_mean += dt / self.n
        self.m2 += delta * (force_N - self.mean)
        self.t_m2 += dt * (t - self.t_mean)
        self.tf_c += dt * (force_N - self.mean)
        if math.isfinite(pressure_bar):
            self.p_sum += pressure_bar
            self.p_n += 1

    @property
    def std(self) -> float:
        return math.sqrt(self.m2 / (self.n - 1)) if self.n > 1 else math.nan

    @property
    def drift_N(self) -> float:
        """Change of the least-squares line from the first to the last sample [N]."""
        if self.n < 3 or self.t_m2 <= 0:
            return math.nan
        return self.tf_c / self.t_m2 * (self.t_last - self.t_first)

    @property
    def pressure_mean(self) -> float:
        return self.p_sum / self.p_n if self.p_n else math.nan

    def record(self, step: Step, instrument: Instrument, tare: dict | None, settled: bool,
               settle_s: float, start_s: float, end_s: float) -> StepRecord:
        """The step's row of ``steps.csv`` (``tare``: the run's tare, with ``std_N`` and ``n``)."""
        force = self.mean if self.n else math.nan
        tare = tare or {}
        budget = step_budget(instrument, force, self.std, self.n, self.drift_N,
                             float(tare.get("std_N", math.nan)), int(tare.get("n", 0)),
                             pressure_bar=self.pressure_mean)
        return StepRecord(step.step, step.direction, step.repeat, step.set_pressure_bar,
                          self.pressure_mean, force, self.std, self.n, bool(settled),
                          float(settle_s), start_s, end_s, self.drift_N,
                          **budget.columns())


class Staircase:
    """The procedure of one run: tare, pre-conditioning, steps, through ``acquisition``."""

    def __init__(self, config: BenchConfig, acquisition: Acquisition, operator=None,
                 on_step=lambda step: None, notify=lambda message: None):
        self.config = config
        self.acq = acquisition
        self.operator = operator
        self.on_step = on_step
        self.notify = notify
        self.steps = plan_steps(config)
        self.instrument = Instrument.from_config(config)

    def run(self) -> None:
        self.tare()
        seq = self.config.sequence
        top = max(seq.pressures_bar)
        for _ in range(seq.preconditioning_cycles):
            for pressure in (top, 0.0):
                self.acq.set_pressure(pressure, "precondition", self.operator)
                self.acq.acquire_for(seq.preconditioning_hold_s, "precondition", -1, pressure)
        for step in self.steps:
            self.run_step(step)

    def tare(self) -> None:
        self.acq.set_pressure(0.0, "vent", self.operator)
        volts: list[float] = []
        monitor: list[float] = []
        self.acq.acquire_for(self.config.sequence.tare_s, "tare", -1, 0.0, volts, monitor)
        tare = validate_tare(volts, self.config)
        if self.config.regulator.electronic:  # a manual regulator's readings are typed
            tare.update(vented_monitor(monitor))
            check_vented_monitor(tare, self.config)
            self.acq.monitor_low_bar = monitor_low_bar(tare)
        held_V, intervals, stray_V = held_tail(volts)
        self.acq.set_tare(tare["offset_V"], stray_V)
        self.acq.held_since_tare(held_V, intervals)
        self.acq.recorder.tare({**tare, "duration_s": self.config.sequence.tare_s})
        for warning in (one_code_warning(tare, self.config), rest_warning(tare, self.config),
                        shift_warning(tare, self.config),
                        settle_warning(tare["std_N"], self.config),
                        monitor_zero_warning(tare, self.config)):
            if warning:
                self.notify(f"warning: {warning}")

    def run_step(self, step: Step) -> None:
        acq, st = self.acq, self.config.settle
        acq.set_pressure(step.set_pressure_bar, "step", self.operator)
        rate = self.config.daq.sample_rate_hz
        window: deque = deque(maxlen=int(math.ceil(st.window_s * rate)) + 2)
        hold = HoldStats()
        start_s = acq.next_index / rate
        settle_s, settled, next_check, elapsed = None, False, st.min_dwell_s, 0.0
        while True:
            for row in acq.read_block("step", step.step, step.set_pressure_bar):
                elapsed = row.time_s - start_s
                if settle_s is None:
                    window.append((elapsed, row.force_N, row.pressure_bar))
                elif elapsed > settle_s:
                    hold.add(row.time_s, row.force_N, row.pressure_bar)
            if settle_s is None and elapsed >= next_check:
                next_check = elapsed + 1.0  # judge once per second of data: cheap and enough
                t, f, p = (np.array(c) for c in zip(*window, strict=True))
                settled = settle_reached(t, f, p, step.set_pressure_bar, self.config)
                if settled or elapsed >= st.timeout_s:
                    settle_s = elapsed
            if settle_s is not None and elapsed - settle_s >= st.hold_s:
                break
        acq.recorder.step(hold.record(step, self.instrument, acq.recorder.meta.tare, settled,
                                      settle_s, start_s, start_s + elapsed))
        self.on_step(step)
