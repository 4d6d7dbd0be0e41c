"""A bench run: startup, execute, shutdown (pymeasure's procedure lifecycle).

:func:`acquire` tares the load cell at 0 bar, runs the pre-conditioning cycles and the pressure
staircase (up, optionally down, repeated), waits at each step until the reading has settled, then
holds and averages. Everything goes to a run folder (``bench.storage``) while it happens.

Safety, in every exit path:

- the pressure command is clamped to ``regulator.max_pressure_bar``;
- a force beyond ``safety.force_limit_fraction`` of the load-cell capacity stops the staircase
  (interlock: vent, status "aborted");
- the first Ctrl-C stops at the next block boundary (at most one block, 0.1 s at the default
  one-sample blocks), the second stops at once; either way, and on any error, ``shutdown`` runs in
  ``finally``: it commands the vent, then closes the device, then records the truth in run.json.
"""

from __future__ import annotations

import math
import os
import signal
import socket
import sys
import threading
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from bench.backend import Backend, BenchError, BufferOverflow, ReadTimeout
from bench.config import BenchConfig
from bench.operator import Operator
from bench.storage import RunWriter
from fem.records import provenance

PHASES = ("tare", "precondition", "step", "operator", "vent")


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


def estimate_duration_s(config: BenchConfig) -> tuple[float, float]:
    """Shortest and longest run time [s]: every step settling at min dwell, or timing out."""
    seq, st = config.sequence, config.settle
    fixed = seq.tare_s + 2 * seq.preconditioning_cycles * seq.preconditioning_hold_s
    n = len(plan_steps(config))
    return fixed + n * (st.min_dwell_s + st.hold_s), fixed + n * (st.timeout_s + st.hold_s)


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


class _Stop(Exception):
    """Leave the sequence at a safe point with this status and reason."""

    def __init__(self, status: str, reason: str):
        super().__init__(reason)
        self.status, self.reason = status, reason


@dataclass
class RunResult:
    """Outcome of a run; ``path`` is None when it failed before its folder was made."""

    path: Path | None
    status: str
    reason: str


class BenchRun:
    """One run on ``backend`` with ``config``, recorded under ``out_root``.

    ``operator`` is needed only for a manual regulator. ``progress`` shows a tqdm bar on stderr;
    ``plot`` a live plot in another process. ``handle_sigint`` installs the two-stage Ctrl-C
    handler (only possible in the main thread).
    """

    def __init__(self, config: BenchConfig, backend: Backend, out_root: str | Path,
                 operator: Operator | None = None, progress: bool = False, plot: bool = False,
                 handle_sigint: bool = True):
        if not config.regulator.electronic and operator is None:
            raise ValueError("regulator.kind='manual' needs an operator to set the pressure")
        self.config = config
        self.backend = backend
        self.out_root = Path(out_root)
        self.operator = operator
        self.progress = progress
        self.plot = plot
        self.handle_sigint = handle_sigint and threading.current_thread() is threading.main_thread()
        self.steps = plan_steps(config)
        self.rate_hz = config.daq.sample_rate_hz
        self.cell = config.loadcell
        self.tare_offset_V = config.loadcell.offset_V
        self.command_bar = 0.0
        self.manometer_bar = math.nan
        self.next_index = 0
        self.stop_requested_at: float | None = None
        self.counters = {"samples": 0, "read_timeouts": 0, "gaps": [], "clipped_samples": 0}
        self._pending_flags: list[str] = []
        self._bar = None
        self._shown_at = 0.0
        self._steps_done = 0
        self._plot = None
        self.writer: RunWriter | None = None
        self.meta: dict = {}

    # lifecycle -------------------------------------------------------------------------------

    def execute(self) -> RunResult:
        """Run the whole sequence; the run folder holds the truth whatever happens."""
        status, reason, error = "failed", "", None
        old_handler = None
        try:
            if self.handle_sigint:
                old_handler = signal.signal(signal.SIGINT, self._on_sigint)
            self.startup()
            self._sequence()
            status, reason = "complete", f"all {len(self.steps)} steps done"
        except _Stop as stop:
            status, reason = stop.status, stop.reason
        except KeyboardInterrupt:
            status, reason = "aborted", "stopped by a second Ctrl-C: vented at once"
        except BenchError as exc:
            status, reason = "failed", f"{type(exc).__name__}: {exc}"
        except BaseException as exc:
            status, reason, error = "failed", f"{type(exc).__name__}: {exc}", exc
        finally:
            if old_handler is not None:  # a further Ctrl-C must not cut the vent or the record
                signal.signal(signal.SIGINT, signal.SIG_IGN)
            reason = self.shutdown(status, reason)
            if old_handler is not None:
                signal.signal(signal.SIGINT, old_handler)
        if error is not None:
            raise error
        return RunResult(self.writer.path if self.writer else None, status, reason)

    def startup(self) -> None:
        info = self.backend.open()
        self.writer = RunWriter(self.out_root, self.config.muscle.id, self.config.text)
        m = self.config.muscle
        prov = provenance()
        self.meta = {
            "status": "running", "reason": "",
            "muscle": {"id": m.id, "D0_mm": m.D0_mm, "t0_mm": m.t0_mm, "L0_mm": m.L0_mm,
                       "eps": m.eps},
            "hardware": info.as_dict(),
            "calibration": {"loadcell": self.config.as_dict()["loadcell"],
                            "regulator": self.config.as_dict()["regulator"]},
            "tare": None,
            "sequence": {**self.config.as_dict()["sequence"],
                         "settle": self.config.as_dict()["settle"],
                         "force_limit_N": self.config.force_limit_N,
                         "steps": len(self.steps),
                         "estimated_duration_s": list(estimate_duration_s(self.config))},
            "config_source": self.config.source, "config_overrides": self.config.overrides,
            "command": prov["command"], "provenance": prov,
            "started_utc": prov["date_utc"], "ended_utc": None,
            "pid": os.getpid(), "host": socket.gethostname(),
        }
        self.writer.write_meta(self.meta)
        if self.progress:
            from tqdm import tqdm

            self._bar = tqdm(total=len(self.steps), unit="step", desc="acquire", leave=True)
        if self.plot:
            from bench.liveplot import LivePlot

            self._plot = LivePlot(self.config.muscle.id)
        self._command(0.0, "vent")
        self.backend.start()

    def shutdown(self, status: str, reason: str) -> str:
        """Vent, close the device, record the outcome. Never raises; returns the final reason."""
        problems = []
        try:
            self._command(0.0, "vent")
        except BaseException as exc:  # the device may be gone; closing must still happen
            problems.append(f"vent command failed ({type(exc).__name__}: {exc})")
        if self.operator is not None and not self.config.regulator.electronic:
            try:
                self.operator.vent()
            except BaseException as exc:
                problems.append(f"operator vent not confirmed ({type(exc).__name__})")
        try:
            self.backend.close()
        except BaseException as exc:
            problems.append(f"closing the device failed ({type(exc).__name__}: {exc})")
        if self._bar is not None:
            self._bar.close()
        if self._plot is not None:
            self._plot.close()
        if problems:
            reason = "; ".join([reason, *problems]) if reason else "; ".join(problems)
        if self.writer is not None:
            self.meta.update(status=status, reason=reason, counters=self.counters,
                             ended_utc=provenance()["date_utc"])
            self.writer.write_meta(self.meta)
            self.writer.close()
        return reason

    # the sequence ----------------------------------------------------------------------------

    def _sequence(self) -> None:
        self._tare()
        seq = self.config.sequence
        top = max(seq.pressures_bar)
        for _ in range(seq.preconditioning_cycles):
            for pressure in (top, 0.0):
                self._set_pressure(pressure, "precondition")
                self._acquire_for(seq.preconditioning_hold_s, "precondition", -1, pressure)
        for step in self.steps:
            self._run_step(step)

    def _tare(self) -> None:
        self._set_pressure(0.0, "vent")
        volts = []
        self._acquire_for(self.config.sequence.tare_s, "tare", -1, 0.0, volts)
        cell_V = np.array(volts)
        self.tare_offset_V = float(cell_V.mean())
        self.meta["tare"] = {
            "offset_V": self.tare_offset_V, "std_V": float(cell_V.std(ddof=1)),
            "n": int(cell_V.size), "duration_s": self.config.sequence.tare_s,
            "config_offset_V": self.cell.offset_V,
            "shift_N": (self.tare_offset_V - self.cell.offset_V) * self.cell.sensitivity_N_per_V,
        }
        self.writer.write_meta(self.meta)

    def _run_step(self, step: Step) -> None:
        self._set_pressure(step.set_pressure_bar, "step")
        st = self.config.settle
        t, f, p = [], [], []
        start_s = self.next_index / self.rate_hz
        settle_s, settled, next_check = None, False, st.min_dwell_s
        while True:
            rows = self._read_block("step", step.step, step.set_pressure_bar)
            for row in rows:
                t.append(row[1] - start_s)
                p.append(row[6])
                f.append(row[9])
            elapsed = t[-1] if t else 0.0
            if settle_s is None and elapsed >= next_check:
                next_check = elapsed + 1.0  # judge once per second of data: cheap and enough
                settled = settle_reached(np.array(t), np.array(f), np.array(p),
                                         step.set_pressure_bar, self.config)
                if settled or elapsed >= st.timeout_s:
                    settle_s = elapsed
            if settle_s is not None and elapsed - settle_s >= st.hold_s:
                break
        t_arr, f_arr, p_arr = np.array(t), np.array(f), np.array(p)
        hold = t_arr > settle_s
        self.writer.append_step({
            "step": step.step, "direction": step.direction, "repeat": step.repeat,
            "set_pressure_bar": step.set_pressure_bar,
            "pressure_bar_mean": float(np.nanmean(p_arr[hold])) if np.isfinite(
                p_arr[hold]).any() else math.nan,
            "force_N_mean": float(f_arr[hold].mean()),
            "force_N_std": float(f_arr[hold].std(ddof=1)) if hold.sum() > 1 else math.nan,
            "n": int(hold.sum()), "settled": bool(settled), "settle_s": float(settle_s),
            "start_s": start_s, "end_s": start_s + float(t_arr[-1]),
        })
        self._steps_done += 1
        if self._bar is not None:
            self._bar.update(1)

    def _acquire_for(self, duration_s: float, phase: str, step: int, set_bar: float,
                     cell_volts: list | None = None) -> None:
        end_index = self.next_index + int(round(duration_s * self.rate_hz))
        while self.next_index < end_index:
            for row in self._read_block(phase, step, set_bar):
                if cell_volts is not None:
                    cell_volts.append(row[7])

    # one block -------------------------------------------------------------------------------

    def _read_block(self, phase: str, step: int, set_bar: float) -> list[tuple]:
        daq = self.config.daq
        timeouts = 0
        while True:
            try:
                block = self.backend.read(daq.read_block_samples, daq.read_timeout_s)
                break
            except ReadTimeout:
                timeouts += 1
                self.counters["read_timeouts"] += 1
                if timeouts > daq.read_retries:
                    raise
                self._pending_flags.append("timeout")
            except BufferOverflow as exc:
                resumed = self.backend.recover()
                lost = resumed - self.next_index
                self.counters["gaps"].append({"after_sample": self.next_index - 1,
                                              "lost_samples": lost, "message": str(exc)})
                self._pending_flags.append("gap")
        electronic = self.config.regulator.electronic
        rows = []
        limit = self.config.force_limit_N
        interlock = None
        for k, volts in enumerate(block.volts):
            index = block.first_index + k
            cell_V = float(volts[0])
            monitor_V = float(volts[1]) if electronic else math.nan
            pressure = float(self.config.regulator.monitor_bar(monitor_V)) if electronic \
                else self.manometer_bar
            force = (cell_V - self.tare_offset_V) * self.cell.sensitivity_N_per_V
            flags = self._pending_flags
            self._pending_flags = []
            if abs(cell_V) >= 10.0 - 2e-3:  # within 2 LSB of a rail: the reading is clipped
                flags.append("clipped")
                self.counters["clipped_samples"] += 1
            if abs(force) >= limit or "clipped" in flags:
                flags.append("interlock")
                interlock = force
            rows.append((index, index / self.rate_hz, step, phase, set_bar,
                         self.command_bar if electronic else math.nan, pressure, cell_V,
                         monitor_V, force, "|".join(flags)))
        self.writer.append_samples(rows)
        self.next_index = block.first_index + len(block.volts)
        self.counters["samples"] += len(rows)
        if self._plot is not None and rows:
            self._plot.push(rows[-1][1], rows[-1][6], rows[-1][9])
        if self._bar is not None and rows and time.monotonic() - self._shown_at > 0.25:
            self._show_progress(rows[-1])
        if interlock is not None:
            self._command(0.0, "interlock vent")
            raise _Stop("aborted", f"force interlock: {interlock:.1f} N reached the limit "
                        f"{limit:.1f} N ({self.config.safety.force_limit_fraction:g} x capacity "
                        f"{self.cell.capacity_N:g} N); vented")
        if self.stop_requested_at is not None:
            raise _Stop("aborted", "stopped by Ctrl-C at a safe point; vented")
        return rows

    def _show_progress(self, row: tuple) -> None:
        """Set and measured pressure, current force, and a lower bound of the time left."""
        st = self.config.settle
        left_s = (len(self.steps) - self._steps_done) * (st.min_dwell_s + st.hold_s)
        self._bar.set_postfix_str(f"{row[3]} {row[4]:.2f} bar, measured {row[6]:.2f} bar, "
                                  f"{row[9]:.1f} N, >= {left_s / 60:.1f} min left")
        self._shown_at = time.monotonic()

    # commands --------------------------------------------------------------------------------

    def _set_pressure(self, pressure_bar: float, purpose: str) -> None:
        if self.config.regulator.electronic:
            self._command(pressure_bar, purpose)
        else:
            self.manometer_bar = self.operator.set_pressure(pressure_bar)
            # Samples acquired while the operator was busy belong to no step.
            while self.backend.available() > 0:
                self._read_block("operator", -1, pressure_bar)

    def _command(self, pressure_bar: float, purpose: str) -> None:
        """Write the clamped pressure command and log it (also when the write fails)."""
        reg = self.config.regulator
        clamped = min(max(pressure_bar, 0.0), reg.max_pressure_bar)
        volts = reg.command_volts(clamped)
        t_s = self.next_index / self.rate_hz
        ok = False
        try:
            self.backend.write_command(volts)
            ok = True
            self.command_bar = clamped
            if purpose.endswith("vent") and self.stop_requested_at is not None and \
                    "stop_to_vent_s" not in self.meta:
                self.meta["stop_to_vent_s"] = time.monotonic() - self.stop_requested_at
                self.meta["vented_at_unix_s"] = time.time()
        finally:
            if self.writer is not None:
                self.writer.append_command((t_s, self.next_index, clamped, volts, ok, purpose))

    def _on_sigint(self, signum, frame) -> None:
        if self.stop_requested_at is None:
            self.stop_requested_at = time.monotonic()
            print("\nmkm: stopping at the next safe point (Ctrl-C again to vent now)",
                  file=sys.stderr, flush=True)
            return
        raise KeyboardInterrupt


def make_backend(config: BenchConfig, backend: str = "sim", clock: str = "virtual") -> Backend:
    """The simulated (``sim``) or NI (``ni``) backend for ``config``."""
    if backend == "sim":
        from bench.sim import SimBackend

        return SimBackend(config, clock=clock)
    if backend == "ni":
        from bench.ni import NIBackend

        return NIBackend(config)
    raise ValueError(f"backend={backend!r} is invalid: expected 'sim' or 'ni'")


def make_operator(backend: Backend) -> Operator:
    from bench.operator import ConsoleOperator, SimOperator
    from bench.sim import SimBackend

    return SimOperator(backend) if isinstance(backend, SimBackend) else ConsoleOperator()


def acquire(config: BenchConfig, backend: str = "sim", clock: str = "virtual",
            out_root: str | Path = "data/experimental", progress: bool = False,
            plot: bool = False) -> RunResult:
    """Record one run of ``config`` on the ``backend`` ("sim" or "ni") under ``out_root``."""
    device = make_backend(config, backend, clock)
    operator = None if config.regulator.electronic else make_operator(device)
    return BenchRun(config, device, out_root, operator=operator, progress=progress,
                    plot=plot).execute()
