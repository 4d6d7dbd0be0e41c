"""The acquisition worker: reads blocks, turns volts into samples, records them, commands the
regulator, and trips the interlocks (pymeasure's worker, beside the procedure in
:mod:`mkm.bench.sequence` and the recorder in :mod:`mkm.bench.recorder`).

Interlocks, checked on every sample; each stops the run (:class:`Stop`, status ``aborted``)
after commanding the vent, which goes out as soon as the block holding the tripping sample is
read: before that block is written to samples.csv, shown or plotted (a slow or full disk
cannot delay it, nor take the interlock's reason from the run; the loop never waits for the
disk, :mod:`mkm.bench.recorder` writes behind it):

- force: ``|force| >= safety.force_limit_fraction x capacity``, a reading within 2 LSB of a rail
  (clipped), or a non-finite force (``abs(nan) >= limit`` is False, so NaN is tested apart);
- pressure (electronic regulator): a non-finite measured pressure; a monitor reading no
  working regulator gives (a live-zero output at 0 V: unpowered, wire off); a pressure more
  than the tolerance away from the command it was acquired under, without moving more than
  the tolerance towards it, for longer than ``safety.pressure_follow_s`` (a regulator that
  does not follow). The window is the measured pressure's: a new command does not restart it
  (a stuck regulator trips ``pressure_follow_s`` after it stops following, whatever is
  commanded meanwhile), a working regulator's step response restarts it as it moves; samples
  read late after a stall are judged against their own command; a monitor that does not move
  with its command (frozen within the tolerance of it): once the command is more than
  ``safety.vent_below_bar`` from the one it last moved with, the reading must move more than
  half that change towards it within ``safety.pressure_follow_s``;
- over-pressure, on the measured pressure (the monitor's, raised by what it read below 0 bar
  vented at the tare, or the manometer reading the operator typed with a manual regulator)
  whatever the tolerance: above
  ``regulator.max_pressure_bar`` by more than :data:`OVERPRESSURE_MARGIN_FRACTION` of it for
  longer than :data:`OVERPRESSURE_HOLD_S`, or by more than :data:`OVERPRESSURE_HARD_FRACTION`
  of it at once (a regulator that overshoots); the run is ``failed``, not ``aborted``;
- over-force, where the run was given the muscle ``mkm identify`` identified (a
  :class:`~mkm.bench.preflight.ForceCeiling`; electronic regulator, after the tare, a pressure
  commanded): the load cell is the monitor's independent witness (:meth:`Acquisition.overforce`),
  as a monitor that reads low hides from the over-pressure limit the pressure its regulator
  delivers; the run is ``failed``.

- disk: the run folder's disk finishing no write for ``recorder.DISK_STUCK_S`` with samples
  held, or trailing by more than that much sample time for as long (they are written when it
  returns); the run is ``failed``.

- reading: a read that times out while the muscle may hold pressure
  (:meth:`Acquisition.pressurised`: a pressure commanded, or a reading above
  ``safety.vent_below_bar``; vented, ``daq.read_retries`` timeouts in a row are retried); the
  run is ``failed``.

If the interlock's own vent write fails, the reason says so and asks for a vent by hand.
"""

from __future__ import annotations

import math
import statistics
import time
from collections import deque
from contextlib import nullcontext

import numpy as np

from mkm.bench import backends
from mkm.bench.backend import Backend, BenchError, BufferOverflow, ReadTimeout, in_words
from mkm.bench.config import BenchConfig
from mkm.bench.ownership import StateFolderBroken
from mkm.bench.preflight import (
    CREEP_FRACTION,
    FRICTION_FRACTION,
    OVERFORCE_FROM_FRACTION,
    ForceCeiling,
    adc_step_N,
    bound_assumes,
    force_bounds_N,
)
from mkm.bench.recorder import Recorder
from mkm.bench.signals import StopSignal
from mkm.bench.storage import CommandRecord, Gap, RunStatus, Sample
from mkm.bench.vent import SETTLED_S, ZERO_NOISE_SIGMAS

RAIL_MARGIN_V = 2e-3  # within 2 LSB (1.22 mV each) of the +-10 V rails: the reading is clipped
# The muscle's limit is max_pressure_bar. A regulator at its command reads within its accuracy
# class (about 1 % of its full scale, at most about 2 % of max_pressure_bar on the paper's 4 bar
# regulator at 2.5 bar) plus monitor noise, so 2 % above the limit held for a second is an
# overshoot, not noise; 10 % above it is never a reading of a working regulator at the limit.
OVERPRESSURE_MARGIN_FRACTION = 0.02
OVERPRESSURE_HOLD_S = 1.0  # a step's transient settles within the regulator's time constant
OVERPRESSURE_HARD_FRACTION = 0.10
#: The bench marker takes milliseconds on a local disk; a state folder slower than this [s] hangs
#: (a network share), and the loop goes on without it rather than leave the interlocks unwatched.
MARKER_WAIT_S = 0.5
#: a load cell whose input holds one ADC code this long [s] of sample time, where its tare
#: strayed more than a step, is stuck or disconnected: no live cell's noise stays on one code
#: (twenty readings at 10 Hz; one step of noise keeps two readings on one code at most a third
#: of the time), and behind it the force limit is not watched
STUCK_CELL_S = 2.0
#: a load cell held on one code while the measured pressure rose or fell by what must move the
#: muscle's force this many ADC steps (:func:`mkm.bench.preflight.force_bounds_N`) is stuck or
#: disconnected, however quiet: a force that moves one step moves any cell's code; the rest is
#: margin for the bounds
UNMOVED_CELL_STEPS = 4


class Stop(Exception):
    """Leave the sequence at a safe point with this status and reason; ``say_vent``: the
    shutdown adds whether its vent went out (an interlock's reason says its own)."""

    def __init__(self, status: RunStatus, reason: str, signal_name: str | None = None,
                 signal_number: int | None = None, say_vent: bool = False):
        super().__init__(reason)
        self.status, self.reason = status, reason
        self.signal_name, self.signal_number = signal_name, signal_number
        self.say_vent = say_vent


def _with_signal(tripped: Stop, sig: StopSignal) -> Stop:
    """The interlock's stop ``tripped`` with the signal that arrived during its vent: its
    reason stays the run's, the signal sets the exit status."""
    stop = Stop(tripped.status, f"{tripped.reason}; {sig} received meanwhile", sig.name,
                sig.signum)
    stop.__cause__ = tripped.__cause__
    return stop


class Acquisition:
    """The acquisition loop on ``backend`` with ``config``, recording into ``recorder``.

    ``stop_requested`` returns the :class:`Stop` to raise at this safe point (a first Ctrl-C, a
    ``mkm vent`` asking) or None; ``stop_time`` the ``time.monotonic()`` of the first request;
    ``observers`` get every block (``block(samples)``) for progress and plots.
    ``lease`` (a :class:`mkm.bench.unvented.BenchLease`) learns every commanded pressure.
    ``guard`` makes the context that a block's read and its recording share (the run's
    :meth:`mkm.bench.signals.StopSignals.deferred`: no signal between the two loses the block).
    ``ceiling``: the most the identified muscle pulls (None: no over-force interlock).
    """

    def __init__(self, config: BenchConfig, backend: Backend, recorder: Recorder,
                 stop_requested=lambda: None, stop_time=lambda: None, lease=None,
                 observers=(), guard=nullcontext, ceiling: ForceCeiling | None = None):
        self.config = config
        self.ceiling = ceiling
        self.guard = guard
        self.backend = backend
        self.recorder = recorder
        self.stop_requested = stop_requested
        self.stop_time = stop_time
        self.lease = lease
        self.observers = list(observers)
        self.rate_hz = config.daq.sample_rate_hz
        self.cell = config.loadcell
        self.step_N = adc_step_N(config)  # one ADC step of the load cell's input [N]
        self.electronic = config.regulator.electronic
        self.tare_offset_V = config.loadcell.offset_V
        # the load cell's spread at the tare [V] (0 before it): above one ADC step, a reading
        # held on one code for STUCK_CELL_S is a stuck cell (_stuck_cell)
        self.tare_std_V = 0.0
        # how far below 0 bar the monitor read vented at the tare [bar]: every reading is that
        # much under the pressure the over-pressure limit watches (a reading above 0 vented is
        # not taken off: the limit is never loosened)
        self.monitor_low_bar = 0.0
        self._held_cell: tuple[float, float] | None = None  # (the code held [V], since [s])
        # the load cell's last code [V] and since when it has read it [s], the first sample
        # acquired under a pressure commanded or set by hand [s], and the highest plausible
        # pressure measured [bar]: a cell on one code from before any pressure to the end,
        # while the muscle was pressurised, measured nothing (:meth:`one_code_throughout`); so
        # did one on one code from any time to the end while the monitor rose more than the
        # vent threshold: the lowest plausible reading since the code was first read, and the
        # largest rise since (rise, from, to) [bar]
        self._same_cell: tuple[float, float] | None = None
        self._same_low_bar = math.inf
        self._same_rise = (0.0, math.nan, math.nan)
        self._pressure_from_s: float | None = None
        # the last three plausible readings [bar] since the load cell's code was first read
        # (their median: one glitch moves none), the lowest and the highest of those medians
        # with when each was read [s], and the muscle's force bounds over pressure (built
        # once, as first needed): :meth:`unmoved_cell`
        self._last3_bar: deque = deque(maxlen=3)
        self._held_low = self._held_high = (math.nan, math.nan)
        self._force_bounds: tuple | None = None
        # the highest plausible pressure read [bar] since the muscle was last vented (the
        # median of the last three readings at or below safety.vent_below_bar), and that peak
        # as the load cell's code was first read (None until it is known): unmoved_cell
        self._vented3_bar: deque = deque(maxlen=3)
        self._peak_bar = 0.0
        self._peak_at_code: float | None = None
        self.unmoved = ""  # why unmoved_cell found the load cell stuck ("" while it did not)
        # the over-force interlock (:meth:`overforce`): the tare taken, the last three
        # plausible readings [bar] and finite forces [N], the command of the last sample [bar]
        # and when a command last fell [s]
        self._tared = False
        self._over3_bar: deque = deque(maxlen=3)
        self._over3_N: deque = deque(maxlen=3)
        self._last_commanded_bar = 0.0
        self._fell_s = -math.inf
        self.highest_bar = 0.0
        self.command_bar = 0.0
        self.pressure_commanded_bar = 0.0  # the last pressure above 0 bar written
        # the highest pressure a write was asked for [bar]: one that failed may still have
        # reached the device
        self.asked_bar = 0.0
        # the commands written, by the device's sample clock when each was issued (index, bar),
        # and the command before the oldest kept: the command each sample was acquired under
        self._issued: list[tuple[int, float]] = []
        self._issued_before_bar = 0.0
        self.manometer_bar = math.nan
        self.measured_bar = math.nan  # the last plausible pressure read (see held_bar)
        self.next_index = 0
        # added to the device's sample indices: its clock restarts at 0 on a fresh task after a
        # loss (:meth:`restarted`), the run's indices go on
        self._offset = 0
        self._read_at = time.monotonic()  # when a block was last read
        # when the loop's read under way began (None between reads): the run's watchdog vents a
        # read that hangs past its timeout with a pressure commanded, and says why here
        self.reading_since: float | None = None
        # (when, pressure [bar]) of the loop's command write under way (None between writes):
        # the watchdog vents one that hangs past its timeout, as it does a read
        self.writing: tuple[float, float] | None = None
        self.hung = ""  # why the read (or a command write) hung ("" while none did)
        self.hung_after_vent = ""  # why a read of the shutdown, after its vent, hung
        self.hung_vent = ""  # what the watchdog's vent did, once written
        self.vented = False  # the last command written was a successful vent
        self.written = False  # the last command asked for reached the device
        self.marker_lagged = False  # a pressure went out before its bench marker was written
        self.interlock_vent_failed = False  # the shutdown says what became of the muscle
        # (measured, commanded) [bar] when the follow or stuck-monitor interlock tripped with
        # the pressure below a pressure commanded: the vent check weighs the monitor's readings
        # by it
        self.below_command: tuple[float, float] | None = None
        # (measured, commanded) [bar] of the last plausible sample acquired under a pressure
        # commanded (see :meth:`unproven`)
        self._pressurised: tuple[float, float] | None = None
        self._pending_flags: list[str] = []
        self._reading = ("tare", -1, 0.0)  # phase, step and set pressure of the last block asked
        # the measured pressure has been off its command, and not moved towards it by more than
        # the tolerance, since then; the pressure it had then
        self._off_since_s: float | None = None
        self._off_from_bar = 0.0
        self._over_since_s: float | None = None  # pressure above the limit's margin since then
        # (command, reading) [bar] when the monitor last moved with its command, and since when
        # the command has been too far from that one for a frozen monitor to pass (see _unmoved)
        self._moved: tuple[float, float] | None = None
        self._unmoved_since_s: float | None = None
        # the last command it has not moved with since then, and its reading under it [bar]
        self._unmoved_under = (0.0, 0.0)
        # the monitor moved with a command this run (more than half a change larger than the
        # vent threshold, see _unmoved): its fall after a vent as a step begins is then no
        # output that lost its gain
        self.shown_moving = False
        # the last plausible readings of the run's blocks [bar], and the last one's command
        self._recent_bar: deque = deque(maxlen=int(round(SETTLED_S * self.rate_hz)) + 1)
        self._recent_command_bar = 0.0
        # the last finite forces [N] before the vent, and of the vent check's samples
        self._recent_N: deque = deque(maxlen=self._recent_bar.maxlen)
        self._vent_N: deque = deque(maxlen=self._recent_bar.maxlen)

    # one block -------------------------------------------------------------------------------

    def read_block(self, phase: str, step: int, set_bar: float) -> list[Sample]:
        """Read one block (retrying timeouts, recovering overflows), record it, check it."""
        daq = self.config.daq
        self._reading = (phase, step, set_bar)
        timeouts = 0
        trips: list[tuple[str, RunStatus]] = []
        tripped: Stop | None = None
        while True:
            try:
                with self.guard():
                    self.reading_since = time.monotonic()
                    try:
                        block = self.backend.read(daq.read_block_samples, daq.read_timeout_s)
                    finally:
                        self.reading_since = None
                    first = self._first(block)
                    rows = [self._sample(first + k, volts, phase, step, set_bar, trips)
                            for k, volts in enumerate(block.volts)]
                    self.next_index = first + len(block.volts)
                    if trips:  # acts first, keeps books after: the vent before the rows
                        tripped = self._vent_for(*trips[0])
                    elif self.hung:  # vented by the watchdog as the read hung: the run stops
                        tripped = Stop(RunStatus.FAILED, self.hung_said())
                    self.recorder.samples(rows)  # queued: the disk is never waited for here
                    if tripped is None:
                        stuck = self.recorder.stuck()
                        if stuck:  # the samples held in memory are kept; the run stops
                            tripped = self._vent_for(stuck, RunStatus.FAILED)
                        else:
                            self.recorder.raise_failure()
                break
            except StopSignal as sig:  # held through the block; the interlock's reason stays
                if tripped is None:
                    raise
                stop = _with_signal(tripped, sig)
                raise stop from stop.__cause__
            except ReadTimeout as exc:
                timeouts += 1
                self.recorder.meta.counters["read_timeouts"] += 1
                if self.electronic and self.pressurised():
                    # pressurised and blind: no interlock can act until a reading comes; a
                    # signal during its vent is held until the vent is out, and added to it
                    try:
                        with self.guard():
                            tripped = self._vent_for(
                                self.hung_said() or
                                f"read interlock: no reading within {daq.read_timeout_s:g} s "
                                f"with {self.held_said()} at "
                                f"{self.next_index / self.rate_hz:g} s ({exc})",
                                RunStatus.FAILED)
                    except StopSignal as sig:
                        if tripped is None:
                            raise
                        stop = _with_signal(tripped, sig)
                        raise stop from stop.__cause__
                    raise tripped from tripped.__cause__
                if timeouts > daq.read_retries:
                    raise
                self._pending_flags.append("timeout")
            except BufferOverflow as exc:
                self._overflowed(exc)
        for observer in self.observers:
            observer.block(rows)
        if tripped is not None:
            raise tripped
        stop = self.stop_requested()
        if stop is not None:
            raise stop
        return rows

    def _overflowed(self, exc: BufferOverflow) -> None:
        """Restart after a buffer overflow and record the gap of the samples lost."""
        resumed = self.backend.recover() + self._offset
        lost = resumed - self.next_index
        self.recorder.gap(Gap(self.next_index - 1, lost, self.next_index / self.rate_hz,
                              resumed / self.rate_hz, str(exc)))
        self._pending_flags.append("gap")
        self.next_index = resumed

    def drain(self) -> None:
        """Record the samples the device already holds: acquired before the stop, unread (the
        block a signal or an interlock cut, a reader that fell behind). Called after the vent,
        before the vent check, which reads past them. Reads only what is there; no interlock
        is judged (the vent is commanded), so none is flagged."""
        waiting = self.backend.available()
        if waiting <= 0:
            return
        self.reading_since = time.monotonic()  # watched as the loop's reads are
        try:
            block = self.backend.read(waiting, self.config.daq.read_timeout_s)
        except BufferOverflow as exc:
            self._overflowed(exc)
            return
        finally:
            self.reading_since = None
        phase, step, set_bar, first = *self._reading, self._first(block)
        self.recorder.samples([self._sample(first + k, volts, phase, step, set_bar)
                               for k, volts in enumerate(block.volts)])
        self.next_index = first + len(block.volts)

    def record_vent_check(self, block) -> str:
        """Record a block the vent check read (phase ``vent``, step -1, set 0 bar): the
        pressure's decay after the vent. Samples skipped since the last read (an overflow the
        check recovered from) are a gap. No interlock is judged (the vent is commanded). The
        problem met, or "" (never raises: the check goes on)."""
        try:
            first = self._first(block)
            if first > self.next_index:
                lost = first - self.next_index
                self.recorder.gap(Gap(self.next_index - 1, lost, self.next_index / self.rate_hz,
                                      first / self.rate_hz, "samples lost during the vent check"))
                self._pending_flags.append("gap")
            rows = [self._sample(first + k, volts, "vent", -1, 0.0)
                    for k, volts in enumerate(block.volts)]
            self.next_index = first + len(block.volts)
            self.recorder.samples(rows)
        except Exception as exc:
            return (f"the samples of the vent check could not be recorded "
                    f"({in_words(exc)})")
        return ""

    def _first(self, block) -> int:
        """The run's index of ``block``'s first sample (the device's, after a restart offset);
        the block is noted as read now."""
        self._read_at = time.monotonic()
        return block.first_index + self._offset

    def restarted(self) -> None:
        """The device was lost, reset and given a fresh AI task (``revive``): its sample clock
        restarts at 0. The samples acquired since the last read are lost with it (a gap, of
        the time since that read: a lower bound), the device's indices from now on follow the
        run's, and what the fresh task reads was acquired after the revive's vent."""
        lost = int((time.monotonic() - self._read_at) * self.rate_hz)
        if lost > 0:
            self.recorder.gap(Gap(self.next_index - 1, lost, self.next_index / self.rate_hz,
                                  (self.next_index + lost) / self.rate_hz,
                                  "the device was lost and reset: the samples acquired "
                                  "meanwhile went with it"))
            self._pending_flags.append("gap")
            self.next_index += lost
        self._offset = self.next_index
        self._reading = ("vent", -1, 0.0)

    def _sample(self, index: int, volts, phase: str, step: int, set_bar: float,
                trips: list[tuple[str, RunStatus]] | None = None) -> Sample:
        """The sample of ``volts``; its interlocks are judged (their trips added to ``trips``)
        unless ``trips`` is None."""
        reg = self.config.regulator
        cell_V = float(volts[0])
        monitor_V = float(volts[1]) if self.electronic else math.nan
        pressure = float(reg.monitor_bar(monitor_V)) if self.electronic else self.manometer_bar
        force = (cell_V - self.tare_offset_V) * self.cell.sensitivity_N_per_V
        commanded = self._commanded_at(index) if self.electronic else math.nan
        if math.isfinite(cell_V) and (self._same_cell is None or self._same_cell[0] != cell_V):
            self._same_cell = (cell_V, index / self.rate_hz)
            self._same_low_bar, self._same_rise = math.inf, (0.0, math.nan, math.nan)
            self._held_low = self._held_high = (math.nan, math.nan)
            self._last3_bar.clear()  # the readings since the code was first read
            self._peak_at_code = None
        plausible = math.isfinite(pressure) and not (self.electronic
                                                     and reg.monitor_fault(monitor_V))
        # a hand regulator's samples acquired while the operator turned it, read after the
        # reading typed: their pressure lies anywhere between that reading and the one before,
        # so the stuck-cell interlock of a quiet cell takes them at neither, only the peak
        # since the vent as high as the new one
        if plausible and phase == "operator":
            self._peak_bar = max(self._peak_bar, pressure)
        elif plausible:
            self._last3_bar.append(pressure)
            if len(self._last3_bar) == 3:
                median = statistics.median(self._last3_bar)
                if not median >= self._held_low[0]:  # NaN: the first
                    self._held_low = (median, index / self.rate_hz)
                if not median <= self._held_high[0]:
                    self._held_high = (median, index / self.rate_hz)
            self._vented3_bar.append(pressure)
            vented = statistics.median(self._vented3_bar) <= self.config.safety.vent_below_bar
            self._peak_bar = pressure if vented else max(self._peak_bar, pressure)
        if plausible:
            self._same_low_bar = min(self._same_low_bar, pressure)
            if pressure - self._same_low_bar > self._same_rise[0]:
                self._same_rise = (pressure - self._same_low_bar, self._same_low_bar, pressure)
            self.measured_bar = pressure
            self.highest_bar = max(self.highest_bar, pressure)
            if phase != "vent":  # the vent check's come after the vent
                self._recent_bar.append(pressure)
                self._recent_command_bar = commanded
                if commanded > 0:
                    self._pressurised = (pressure, commanded)
        if self._peak_at_code is None and self._same_cell is not None:
            self._peak_at_code = self._peak_bar
        pressure_set_bar = commanded if self.electronic else self.manometer_bar
        if self._pressure_from_s is None and pressure_set_bar > 0:
            self._pressure_from_s = index / self.rate_hz
        if math.isfinite(force):
            (self._vent_N if phase == "vent" else self._recent_N).append(force)
        flags, self._pending_flags = self._pending_flags, []
        if not math.isfinite(force) or (self.electronic and not math.isfinite(pressure)):
            flags.append("nonfinite")
        elif abs(cell_V) >= 10.0 - RAIL_MARGIN_V:
            flags.append("clipped")
            self.recorder.meta.counters["clipped_samples"] += 1
        t_s = index / self.rate_hz
        if trips is not None:
            # the measured pressure is the monitor's, or the operator's manometer reading: a
            # hand regulator turned past the limit is as over-pressured as an electronic one
            over = (self._overpressure(t_s, pressure)
                    or self.overforce(t_s, pressure if plausible else math.nan, force, commanded))
            fault = over or self._stuck_cell(t_s, cell_V, force) or self.unmoved_cell(force)
            trip = fault or self._interlock(index, force, pressure, cell_V, monitor_V, flags)
            if trip:
                flags.append("interlock")
                trips.append((trip, RunStatus.FAILED if fault else RunStatus.ABORTED))
        return Sample(index, index / self.rate_hz, step, phase, set_bar, commanded, pressure,
                      cell_V, monitor_V, force, "|".join(flags))

    def held_since_tare(self, cell_V: float, intervals: int) -> None:
        """The tare ended on the code ``cell_V`` [V], held for ``intervals`` sample intervals:
        the stuck-cell interlock counts from where the code was first read, not from the
        tare's end (a cell that stuck during the tare trips :data:`STUCK_CELL_S` after it
        stuck)."""
        self._held_cell = (cell_V, (self.next_index - 1 - intervals) / self.rate_hz)

    def _stuck_cell(self, t_s: float, cell_V: float, force: float) -> str | None:
        """The load cell's input has held one code (``cell_V``) for :data:`STUCK_CELL_S`
        where its tare strayed more than an ADC step: stuck or disconnected (its message), or
        None."""
        step_V = backends.entry(self.config.daq.backend).capabilities.ai_lsb_V
        if not self.tare_std_V > step_V or not math.isfinite(cell_V):
            return None
        if self._held_cell is None or self._held_cell[0] != cell_V:
            self._held_cell = (cell_V, t_s)
            return None
        if t_s - self._held_cell[1] < STUCK_CELL_S - 1e-9:
            return None
        return (f"force interlock: the load cell read {cell_V:.4f} V ({force:.1f} N) unchanged "
                f"for {t_s - self._held_cell[1]:.1f} s, where it strayed "
                f"{self.tare_std_V * self.cell.sensitivity_N_per_V:.2f} N at the tare: a stuck "
                "or disconnected load cell, behind which the force limit is not watched; check "
                "its cable, amplifier and supply")

    def unmoved_cell(self, force: float) -> str | None:
        """The load cell has held one code while the pressure, read as medians of three, rose
        or fell between a low and a high that must move the muscle's force
        :data:`UNMOVED_CELL_STEPS` ADC steps or more: stuck or disconnected (its message), or
        None. Each pressure is taken the monitor's accuracy towards the other; the force
        differs between them by at least the larger of

        - the force the muscle surely pulls at the high pressure less the most it could pull
          at the low one (:func:`mkm.bench.preflight.force_bounds_N`): a muscle slack over the
          span (its eps, its threshold) makes no force to move;
        - the force read, less what its zero may be off (the tare's noise, two ADC steps and
          the zero drift a run allows), times the pressures' ratio less one, the braid's
          friction taken off both ends: at a fixed length the force grows at least in
          proportion to the pressure (above a threshold, none below it), and a live cell
          that held its code read that force at the low pressure too;
        - that force times the ratio of the high pressure to the highest read since the muscle
          was last vented until the code was first read, less one, what creep may take off
          the high end (:data:`mkm.bench.preflight.CREEP_FRACTION`) taken off: the braid's
          friction holds a force at most at what the highest pressure since the vent pulled
          up, so a force above the most the muscle pulls at the vent threshold was pulled up
          to there, and a pressure above that peak pulls it up again, the friction on both
          ends the same (a rise above the run's peak so far, as an up-sweep's; after a fall
          only the two bounds above hold).

        It needs no noise at the tare, so it watches a cell quieter than a step, which
        :meth:`_stuck_cell` cannot tell from a stuck one."""
        if self._same_cell is None or len(self._last3_bar) < 3:
            return None
        (low, low_s), (high, high_s) = self._held_low, self._held_high
        if not high > low:
            return None
        offset_bar, gain = self.config.regulator.reading_bounds()
        high_bar, low_bar = high - offset_bar - gain * high, low + offset_bar + gain * low
        pressure_bar, least_N, most_N = self._bounds()
        rise_N = (float(np.interp(high_bar, pressure_bar, least_N))
                  - float(np.interp(low_bar, pressure_bar, most_N)))
        step_N = self.step_N
        held_N = force - (ZERO_NOISE_SIGMAS * self.tare_std_V * self.cell.sensitivity_N_per_V
                          + 2 * step_N
                          + self.cell.zero_drift_fraction_fs * self.cell.capacity_N)
        if held_N > 0 and low_bar > 0:
            sure = (1.0 - FRICTION_FRACTION) / (1.0 + FRICTION_FRACTION)
            rise_N = max(rise_N, held_N * (sure * high_bar / low_bar - 1.0))
        vented_bar = self.config.safety.vent_below_bar
        vented_bar += offset_bar + gain * vented_bar
        peak = self._peak_at_code + self.monitor_low_bar  # a zero read low lowers the peak
        peak_bar = peak + offset_bar + gain * peak
        if held_N > float(np.interp(vented_bar, pressure_bar, most_N)) and peak_bar > 0:
            rise_N = max(rise_N, held_N * ((1.0 - CREEP_FRACTION) * high_bar / peak_bar - 1.0))
        if not rise_N >= UNMOVED_CELL_STEPS * step_N:
            return None
        read = "the monitor" if self.electronic else "the manometer's reading"
        cell_V, since_s = self._same_cell
        span = (f"rose from {round(low, 2) + 0.0:.2f} to {high:.2f}" if low_s < high_s else
                f"fell from {high:.2f} to {round(low, 2) + 0.0:.2f}")
        self.unmoved = (f"force interlock: the load cell read {cell_V:.4f} V ({force:+.2f} N) "
                        f"unchanged from {since_s:g} s while {read} {span} bar, which moves "
                        f"the muscle's force by {rise_N:.1f} N or more at eps "
                        f"{self.config.muscle.eps:g} ({rise_N / step_N:.0f} ADC steps of "
                        f"{step_N:.2f} N): a stuck or disconnected load cell, behind which the "
                        "force limit is not watched; check its cable, amplifier and supply"
                        + ("" if self.electronic else
                           ", or whether a reading was typed before the manometer settled (the "
                           "pressure still on its way, the muscle below it): type each once it "
                           "holds still")
                        + f"; {bound_assumes(self.config)}")
        return self.unmoved

    def _bounds(self) -> tuple:
        """The muscle's force bounds over pressure (:func:`force_bounds_N`), built once."""
        if self._force_bounds is None:
            self._force_bounds = force_bounds_N(self.config)
        return self._force_bounds

    def _commanded_at(self, index: int) -> float:
        """The command [bar] sample ``index`` was acquired under: the last one issued at or
        before it by the device's clock (samples read late, after a stall or at a stop, were
        acquired before a command the reader wrote meanwhile)."""
        bar = self._issued_before_bar
        for at, value in self._issued:
            if at > index:
                break
            bar = value
        return bar

    def _clock_index(self) -> int:
        """The device's sample clock now, as a sample index: the samples acquired, read or
        waiting in its buffer (a command written now acts from this sample on). Where the
        device cannot say (lost, not started), the samples read: the reader's position, a
        lower bound."""
        try:
            return self.next_index + max(int(self.backend.available()), 0)
        except BenchError:
            return self.next_index

    def _interlock(self, index, force, pressure, cell_V, monitor_V, flags) -> str | None:
        """The interlock sample ``index`` trips (its message), or None. The regulator is
        judged against the command the sample was acquired under (samples read late, after a
        stall, were acquired before a command the reader wrote meanwhile), and gets
        ``pressure_follow_s`` from the last sample at which its pressure was on the command or
        had moved more than the tolerance towards it."""
        t_s = index / self.rate_hz
        limit = self.config.force_limit_N
        safety = self.config.safety
        if "nonfinite" in flags:
            what = "force" if not math.isfinite(force) else "pressure"
            return (f"{what} interlock: the {what} reading is not a number (load cell "
                    f"{cell_V!r} V, monitor {monitor_V!r} V) at {t_s:g} s: a broken input or "
                    "calibration")
        if abs(force) >= limit or "clipped" in flags:
            return (f"force interlock: {force:.1f} N reached the limit {limit:.1f} N "
                    f"({safety.force_limit_fraction:g} x capacity {self.cell.capacity_N:g} N)")
        if not self.electronic:
            return None
        fault = self.config.regulator.monitor_fault(monitor_V)
        if fault:
            return f"pressure interlock: {fault} at {t_s:g} s"
        commanded = self._commanded_at(index)
        tolerance = safety.pressure_tolerance_bar
        if abs(pressure - commanded) <= tolerance:
            self._off_since_s = None
        elif self._off_since_s is None or (
                (pressure - self._off_from_bar) * math.copysign(1.0, commanded
                                                                - self._off_from_bar)
                > tolerance):
            # off the command, first or after moving more than the tolerance towards it (a
            # working regulator's step response or a ramp it lags): the window starts here. A
            # new command does not restart it: a stuck regulator's pressure does not move
            self._off_since_s, self._off_from_bar = t_s, pressure
        elif t_s - self._off_since_s > safety.pressure_follow_s:
            self._tripped_below(pressure, commanded)
            return (f"pressure interlock: the regulator does not follow: {pressure:.3f} bar "
                    f"measured against {commanded:g} bar commanded for more than "
                    f"{safety.pressure_follow_s:g} s (tolerance {tolerance:g} bar; the "
                    f"pressure has not moved towards the command since "
                    f"{self._off_since_s:g} s)")
        return self._unmoved(t_s, pressure, commanded)

    def _tripped_below(self, pressure: float, commanded: float) -> None:
        """Keep :attr:`below_command` for an interlock tripping at ``pressure`` below the
        positive pressure ``commanded`` (the first such trip only)."""
        if 0 < commanded and pressure < commanded and self.below_command is None:
            self.below_command = (pressure, commanded)

    def _unmoved(self, t_s: float, pressure: float, commanded: float) -> str | None:
        """The stuck-monitor interlock's message for this sample, or None.

        A monitor frozen within the follow tolerance of its commands (near 0 bar at a step of
        0.1 bar, a tolerance of 0.15 bar) never trips the follow interlock, and its frozen
        reading would verify the vent. A working regulator's monitor reads the pressure the
        regulator holds at its command, so it moves with the command: once the command is more
        than ``safety.vent_below_bar`` from the one under which the monitor last moved with it
        (a smaller change leaves the muscle below the vent threshold), the reading must move
        more than half that change towards it within ``safety.pressure_follow_s``. A reading
        off the command by more than the tolerance is the follow interlock's."""
        safety = self.config.safety
        if self._moved is None:
            self._moved = (commanded, pressure)
            return None
        moved_command, moved_bar = self._moved
        change = commanded - moved_command
        if abs(change) <= safety.vent_below_bar:
            since, (held, last_bar) = self._unmoved_since_s, self._unmoved_under
            towards_bar = (last_bar - moved_bar) * math.copysign(1.0, held - moved_command)
            if since is not None and t_s - since >= safety.pressure_follow_s - 1e-9 and \
                    towards_bar <= safety.pressure_tolerance_bar:
                # the command came back to the reading before the next sample could judge it
                # (pre-conditioning's top held as long as pressure_follow_s, then 0 bar): the
                # monitor had that long under it and did not move (a slow regulator's, moving
                # more than the tolerance, is the follow interlock's)
                self._tripped_below(pressure, held)
                return self._unmoved_said(pressure, held, f"from {since:g} s to {t_s:g} s",
                                          moved_bar, moved_command)
            self._unmoved_since_s = None
            if commanded == moved_command:  # the reading the next change is judged from
                self._moved = (commanded, pressure)
            return None
        if (pressure - moved_bar) * math.copysign(1.0, change) > abs(change) / 2:
            self._moved, self._unmoved_since_s = (commanded, pressure), None
            self.shown_moving = True
            return None
        if self._unmoved_since_s is None:
            self._unmoved_since_s = t_s
        self._unmoved_under = (commanded, pressure)
        if (t_s - self._unmoved_since_s > safety.pressure_follow_s
                and abs(pressure - commanded) <= safety.pressure_tolerance_bar):
            self._tripped_below(pressure, commanded)
            return self._unmoved_said(pressure, commanded, f"since {self._unmoved_since_s:g} s",
                                      moved_bar, moved_command)
        return None

    def _unmoved_said(self, pressure: float, commanded: float, span: str, moved_bar: float,
                      moved_command: float) -> str:
        """The stuck-monitor interlock's message: ``pressure`` [bar] read against ``commanded``
        over ``span`` (since when, or from when to when), after ``moved_bar`` under
        ``moved_command``."""
        follow_s = self.config.safety.pressure_follow_s
        return (f"pressure interlock: the monitor does not move with the command: "
                f"{pressure:.3f} bar measured against {commanded:g} bar commanded {span}, after "
                f"{moved_bar:.3f} bar under {moved_command:g} bar (a working regulator's monitor "
                f"moves more than half the change within {follow_s:g} s): a monitor fault "
                "(stuck), or a regulator without supply")

    def _overpressure(self, t_s: float, reading: float) -> str | None:
        """The over-pressure interlock's message for this monitor ``reading`` [bar] (plus
        :attr:`monitor_low_bar`), or None."""
        limit = self.config.regulator.max_pressure_bar
        soft, hard = OVERPRESSURE_MARGIN_FRACTION * limit, OVERPRESSURE_HARD_FRACTION * limit
        pressure = reading + self.monitor_low_bar
        if not pressure > limit + soft:  # NaN is the non-finite interlock's
            self._over_since_s = None
            return None
        if self._over_since_s is None:
            self._over_since_s = t_s
        said = f"{pressure:.3f} bar measured" + (
            f" ({reading:.3f} bar read, the monitor reading {-self.monitor_low_bar:+.4f} bar "
            "vented at the tare)" if self.monitor_low_bar > 0 else "")
        if pressure > limit + hard:
            return (f"over-pressure interlock: {said} at {t_s:g} s, above "
                    f"max_pressure_bar {limit:g} + {hard:.3g} bar (regulator overshoot)")
        if t_s - self._over_since_s > OVERPRESSURE_HOLD_S:
            return (f"over-pressure interlock: {said} at {t_s:g} s, above "
                    f"max_pressure_bar {limit:g} + {soft:.3g} bar for more than "
                    f"{OVERPRESSURE_HOLD_S:g} s (regulator overshoot)")
        return None

    def overforce(self, t_s: float, pressure: float, force: float, commanded: float) -> str | None:
        """The over-force interlock's message, or None: the load cell, an instrument the
        regulator does not close its loop on, read more force than the identified muscle
        (:attr:`ceiling`) pulls at the measured pressure. The regulator holds its monitor's
        reading at the command, so a monitor that reads low (a gain or zero error) delivers more
        pressure than it reads, unseen by the over-pressure limit, and the muscle pulls the
        force of the pressure it holds. Judged, on medians of three (one glitch moves none),
        where the force read, less the load cell's accuracy (the tare's noise, two ADC steps,
        its zero drift, non-linearity and sensitivity tolerance), exceeds the ceiling's force at
        the reading taken its accuracy high, plus the identified friction (which a falling
        pressure leaves in the force), but no more than the ceiling at the highest reading
        since the muscle was last vented, also taken its accuracy high (the braid holds a force
        at most at what that peak pulled up; creep and a yielding frame only take force off),
        times ``1 + safety.overforce_margin_fraction`` (:meth:`ForceCeiling.most_N`).
        Only with an electronic regulator, after the tare (forces before it are from the
        configured zero), under a pressure commanded, at a reading from
        :data:`~mkm.bench.preflight.OVERFORCE_FROM_FRACTION` of ``max_pressure_bar`` up, and
        not within ``safety.pressure_follow_s`` of a command that fell: a muscle exhausts
        through its tube behind the regulator's sensor, and holds more than the reading
        meanwhile (on a rise it lags below it, which only lowers the force)."""
        ceiling = self.ceiling
        if ceiling is None or not self.electronic:
            return None
        if commanded < self._last_commanded_bar:
            self._fell_s = t_s
        self._last_commanded_bar = commanded
        if not (self._tared and commanded > 0 and math.isfinite(pressure)
                and math.isfinite(force)):
            self._over3_bar.clear()  # medians of consecutive samples judged only
            self._over3_N.clear()
            return None
        self._over3_bar.append(pressure)
        self._over3_N.append(force)
        if (len(self._over3_bar) < 3
                or t_s - self._fell_s < self.config.safety.pressure_follow_s - 1e-9):
            return None
        reading, force_N = statistics.median(self._over3_bar), statistics.median(self._over3_N)
        measured = reading + self.monitor_low_bar
        if measured < OVERFORCE_FROM_FRACTION * self.config.regulator.max_pressure_bar:
            return None
        most, where = ceiling.most_N(self.config, measured, self._peak_bar + self.monitor_low_bar)
        cell = self.cell
        accuracy_N = (ZERO_NOISE_SIGMAS * self.tare_std_V * cell.sensitivity_N_per_V
                      + 2 * self.step_N
                      + (cell.zero_drift_fraction_fs + cell.nonlinearity_fraction_fs)
                      * cell.capacity_N + cell.sensitivity_tolerance_fraction * abs(force_N))
        if not force_N - accuracy_N > most:
            return None
        return (f"over-force interlock: the load cell read {force_N:.1f} N at {t_s:g} s with "
                f"the monitor reading {measured:.3f} bar, more than the muscle pulls there: "
                f"{ceiling.source} pulls at most {most:.1f} N at eps "
                f"{self.config.muscle.eps:g} ({where}), and the load cell's accuracy is "
                f"{accuracy_N:.1f} N: the pressure monitor reads low (a gain or zero error; the "
                "regulator holds that reading at the command and delivers more, which the "
                "over-pressure limit does not see), or the load cell reads high; check the "
                "monitor against a reference gauge and the load cell with a known mass")

    def _vent_for(self, message: str, status: RunStatus) -> Stop:
        """Command the interlock's vent now; the :class:`Stop` that says so, to raise once the
        tripping block is recorded."""
        try:
            self.command(0.0, "interlock vent")
        except Exception as exc:
            if self.written:  # the vent went out; only its record (or marker) failed
                stop = Stop(status, f"{message}; vented, but recording the interlock's vent "
                            f"failed ({in_words(exc)})")
            else:  # the shutdown vents again and says whether that was verified
                self.interlock_vent_failed = True
                stop = Stop(status, f"{message}; the interlock's vent command failed "
                            f"({in_words(exc)})")
            stop.__cause__ = exc
            return stop
        return Stop(status, f"{message}; vented")

    def unproven(self) -> tuple[float, float] | None:
        """(measured, commanded) [bar] by which the vent check weighs the monitor's readings
        (:func:`mkm.bench.vent.below_command`): the follow interlock's, or, when a stop, another
        interlock or a fault ended the run first, the last plausible reading acquired under a
        pressure commanded if it was below that command by more than the tolerance, or below it
        without having moved with it yet (a monitor frozen near zero reads so from the first
        sample; the run may end before the follow or stuck-monitor interlock trips). None: the
        monitor followed its command."""
        if self.below_command is not None:
            return self.below_command
        if self._pressurised is None:
            return None
        measured, commanded = self._pressurised
        if commanded - measured > self.config.safety.pressure_tolerance_bar or (
                self._unmoved_since_s is not None and measured < commanded):
            return measured, commanded
        return None

    def before_vent(self) -> tuple[float, float, float] | None:
        """(reading, command, last reading) [bar] as the run stopped: the median of the
        monitor's last plausible readings (over :data:`mkm.bench.vent.SETTLED_S`; one noise
        spike moves no median), the command the last was acquired under, and that last
        reading; None before any."""
        if not self._recent_bar:
            return None
        return (statistics.median(self._recent_bar), self._recent_command_bar,
                self._recent_bar[-1])

    def set_tare(self, offset_V: float, std_V: float) -> None:
        """Take forces from the tare's zero ``offset_V`` [V] on; the forces read before it (the
        tare's, against the configuration's offset) are taken from it too, so that the vent
        check weighs the muscle's force, not the amplifier's offset, before a vent that comes
        within :data:`mkm.bench.vent.SETTLED_S` of the tare. ``std_V``: the cell's spread at the
        tare [V]."""
        shift_N = (offset_V - self.tare_offset_V) * self.cell.sensitivity_N_per_V
        self._recent_N = deque((force - shift_N for force in self._recent_N),
                               maxlen=self._recent_N.maxlen)
        self.tare_offset_V, self.tare_std_V = offset_V, std_V
        self._tared = True
        self._bounds()  # built before any pressure, not in the rise they judge

    def pressurised(self) -> bool:
        """Whether the muscle may hold pressure: a pressure commanded, or, whatever the
        command, the last plausible reading above ``safety.vent_below_bar`` (a vent the
        regulator has not exhausted yet, or does not follow). The read interlock and the
        run's watchdog watch a blind run by it: what is measured, not only what is
        commanded."""
        return self.command_bar > 0 or self.measured_bar > self.config.safety.vent_below_bar

    def held_said(self) -> str:
        """The pressure :meth:`pressurised` found, in words: the command, and the last reading
        where it is above the vent threshold and, with a pressure commanded, above it by more
        than ``safety.pressure_tolerance_bar`` (one at its command says nothing more; with 0
        bar commanded the reading is why the muscle is held pressurised)."""
        safety = self.config.safety
        above = self.command_bar + safety.pressure_tolerance_bar if self.command_bar > 0 else 0.0
        read = (f" and {self.measured_bar:.3f} bar last read"
                if self.measured_bar > max(safety.vent_below_bar, above) else "")
        return f"{self.command_bar:g} bar commanded{read}"

    def hung_said(self) -> str:
        """Why the read hung and what the watchdog's vent did, or ""."""
        return "; ".join(filter(None, [self.hung, self.hung_vent]))

    def forces_around_vent(self) -> tuple[float, float] | None:
        """(before, after) [N]: the median force over the last
        :data:`mkm.bench.vent.SETTLED_S` before the vent, and over the vent check's last
        samples (its settled window, once it verified); None before either."""
        if not self._recent_N or not self._vent_N:
            return None
        return statistics.median(self._recent_N), statistics.median(self._vent_N)

    def one_code_throughout(self) -> str:
        """What a load cell that read one ADC code from before the run's first pressure to
        its end, while the monitor read a pressure above ``safety.vent_below_bar``, or from a
        later time to its end while the monitor rose by more than that, means (its forces
        from then measure nothing: no muscle that pulls more as its pressure rises, nor one
        that lets go at the vent, holds a live cell to one code; a slack one with a cell
        quieter than a step may), or "" (a cell that moved, a regulator never commanded or
        set to a pressure)."""
        below = self.config.safety.vent_below_bar
        if self._same_cell is None or self._pressure_from_s is None:
            return ""
        same, since_s = self._same_cell
        step_N = self.step_N
        blind = "its forces measure nothing, and the force limit was blind"
        read = "the monitor" if self.electronic else "the manometer's reading"
        up_to = "the monitor read" if self.electronic else "the manometer's reading was"
        if since_s <= self._pressure_from_s:
            if not self.highest_bar > below:
                return ""
            return (f"the load cell read one ADC code ({same:.4f} V) from before the first "
                    f"pressure to the end, while {up_to} up to {self.highest_bar:.2f} "
                    f"bar: a stuck or disconnected cell, or a muscle that never pulled one ADC "
                    f"step ({step_N:.2f} N); {blind}")
        rise, low, high = self._same_rise
        if not rise > below:
            return ""
        force_N = (same - self.tare_offset_V) * self.cell.sensitivity_N_per_V
        return (f"the load cell read one ADC code ({same:.4f} V, {force_N:+.2f} N) from "
                f"{since_s:g} s to the end, the vent included, "
                f"while {read} rose from {low:.2f} to {high:.2f} bar: a stuck or "
                f"disconnected cell, or a muscle that pulled not one ADC step ({step_N:.2f} N) "
                f"more as its pressure rose; from {since_s:g} s {blind}")

    def forces_unchanged(self) -> bool:
        """Every force of :meth:`forces_around_vent`'s two windows is the same reading (a load
        cell stuck, or a muscle steady within one ADC step)."""
        forces = [*self._recent_N, *self._vent_N]
        return bool(self._recent_N) and bool(self._vent_N) and min(forces) == max(forces)

    def held_bar(self) -> tuple[float, bool]:
        """The pressure [bar] the regulator may still hold when its vent is not verified, and
        whether it is a command: its command while the vent was not written, else the last
        plausible pressure measured, or, read below 0 bar (a zero drifted low), the last
        pressure commanded (a lost monitor's 0 V converts to -1 bar, which is no pressure at
        all)."""
        if not self.vented:
            return self.command_bar, True
        if self.measured_bar >= 0:
            return self.measured_bar, False
        return self.pressure_commanded_bar, True

    # commands --------------------------------------------------------------------------------

    def set_pressure(self, pressure_bar: float, purpose: str, operator=None) -> None:
        if self.electronic:
            self.command(pressure_bar, purpose)
            return
        self.manometer_bar = operator.set_pressure(pressure_bar)
        # Samples acquired while the operator was busy belong to no step.
        while self.backend.available() > 0:
            self.read_block("operator", -1, pressure_bar)

    def command(self, pressure_bar: float, purpose: str) -> None:
        """Write the clamped pressure command and log it (also when the write fails).

        The write comes first; the log row after it carries the time the command was issued:
        the device's sample clock just after the write (:meth:`_clock_index`), not the reader's
        position, which lags it by the samples waiting in the buffer (a stalled reader, a stop
        that cut a block)."""
        reg = self.config.regulator
        clamped = min(max(pressure_bar, 0.0), reg.max_pressure_bar)
        volts = reg.command_volts(clamped)
        ok = self.written = False
        self.asked_bar = max(self.asked_bar, clamped)
        if self.lease is not None and clamped > 0:
            self._mark(clamped)
        # a stop signal is held until the write and its books are done: one raised as the
        # write returns left a pressure on the device that the books called a failed write
        with self.guard():
            # watched until the device's clock is read after the write (a driver call too)
            self.writing = (time.monotonic(), clamped)
            try:
                self.backend.write_command(volts)
                ok = self.written = True
                self.command_bar = clamped
                if clamped > 0:
                    self.pressure_commanded_bar = clamped
                self.vented = clamped == 0.0
                meta = self.recorder.meta
                stopped_at = self.stop_time()
                if clamped == 0.0 and stopped_at is not None and meta.stop_to_vent_s is None:
                    meta.stop_to_vent_s = time.monotonic() - stopped_at
                    meta.vented_at_unix_s = time.time()
            finally:
                try:
                    issued = self._clock_index()
                finally:
                    self.writing = None
                if ok:
                    self._issued.append((issued, clamped))
                    # the oldest still needed: every sample to be read was acquired after it
                    while len(self._issued) > 1 and self._issued[1][0] <= self.next_index:
                        self._issued_before_bar = self._issued.pop(0)[1]
                self.recorder.meta.last_command_bar = self.command_bar
                if ok and self.lease is not None and clamped == 0.0:
                    lease = self.lease  # after the vent, never waited for: the shutdown checks it
                    lease.post(lambda: lease.command(0.0))
                self.recorder.command(CommandRecord(issued / self.rate_hz, issued, clamped, volts,
                                                    ok, purpose))
        if ok and clamped > 0 and self.hung:
            # a pressure that went out after the watchdog's vent (its write hung): vented again
            # at once; the run stops at its next block
            self.command(0.0, "vent")

    def _mark(self, pressure_bar: float) -> None:
        """The bench marker learns ``pressure_bar`` before it is written to the device, so a
        kill between the two still finds it; a pressure the marker cannot record is not
        commanded. The marker is written by the lease's thread: a state folder that takes more
        than :data:`MARKER_WAIT_S` (it hangs) is not waited for again until it catches up, and
        the pressure goes out ahead of its marker (the marker written at the run's start
        already makes the next command vent a run killed meanwhile); said at the end."""
        lease = self.lease
        behind = self.marker_lagged and lease.lagging()  # found slow, not caught up since
        ticket = lease.post(lambda: lease.command(pressure_bar))
        # an update queued before it (a vent's, never waited for) is waited for with it: a
        # state folder that takes milliseconds is not slow, however soon the pressure follows
        if behind or not lease.wait(ticket, MARKER_WAIT_S):
            self.marker_lagged = True
            return
        if lease.error is not None:
            raise StateFolderBroken(f"the bench marker {lease.path} in the bench state folder "
                                    f"could not be written ({lease.error.strerror or lease.error})"
                                    f": {pressure_bar:g} bar not commanded")

    def acquire_for(self, duration_s: float, phase: str, step: int, set_bar: float,
                    cell_volts: list | None = None, monitor_bar: list | None = None) -> None:
        """Read for ``duration_s`` of sample time; collect the load-cell volts and the monitor's
        readings if asked."""
        end_index = self.next_index + int(round(duration_s * self.rate_hz))
        while self.next_index < end_index:
            for row in self.read_block(phase, step, set_bar):
                if cell_volts is not None:
                    cell_volts.append(row.loadcell_V)
                if monitor_bar is not None:
                    monitor_bar.append(row.pressure_bar)
