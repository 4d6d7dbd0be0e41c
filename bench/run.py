"""A bench run: startup, execute, shutdown (pymeasure's procedure lifecycle).

:class:`BenchRun` joins three parts: the procedure (:class:`mkm.bench.sequence.Staircase`: tare,
pre-conditioning, steps), the worker (:class:`mkm.bench.worker.Acquisition`: the acquisition loop
and
its interlocks) and the recorder (:class:`mkm.bench.recorder.Recorder`: the run folder and its
:class:`mkm.bench.storage.RunMeta`). Everything goes to the run folder while it happens.

Safety, in every exit path:

- the run owns its bench for its whole length: a second command on it refuses, ``mkm vent``
  asks it to stop (:mod:`mkm.bench.ownership`); the loop never waits for the bench state
  folder (the marker and the stop request are written and read by threads of their own);
- a bench left pressurised by a run that died without venting is vented first, and said
  (:mod:`mkm.bench.unvented`);
- the pressure command is clamped to ``regulator.max_pressure_bar``; the force and pressure
  interlocks stop the run (:mod:`mkm.bench.worker`), whose loop never waits for the disk
  (:mod:`mkm.bench.recorder` writes behind it; a disk not taking the record stops the run);
- the first Ctrl-C stops at the next block boundary (0.1 s at the default one-sample blocks);
  a second Ctrl-C, SIGTERM, SIGHUP, SIGBREAK or a closed Windows console stop at once
  (:mod:`mkm.bench.signals`); either way, and on any error, ``shutdown`` commands the vent, closes
  the
  device, then records the truth in run.json;
- a device lost mid-run (its vent write failing) is reset and vented on fresh tasks, within
  a few seconds, before a vent by hand is asked for (``revive`` of the NI backend);
- a read of the device that hangs past its timeout with the muscle pressurised (a pressure
  commanded or read: :meth:`mkm.bench.worker.Acquisition.pressurised`) is vented by a
  watchdog thread, and recorded as it hangs (:data:`READ_HANG_MARGIN_S`); so is a command write
  that hangs, and a read of the shutdown that hangs after its vent; the calls before the
  watchdog (the device's serial number, its open, the start of the inputs) are bounded
  (:func:`driver_call`): one that hangs ends the run with its reason;
- every vent is verified (:mod:`mkm.bench.vent`): the monitor (or the operator's manometer
  reading) must fall below ``safety.vent_below_bar`` within ``safety.vent_timeout_s`` (read on
  while still falling, at most :data:`mkm.bench.vent.FALLING_MAX_S`) and stay there, read from
  the zero the tare measured (a zero that drifted low shows as a reading
  settled below it), a monitor found below its command before the vent (by the pressure
  interlock, or in its last reading before a stop, another interlock or a fault) must have
  read more than that before the vent (one stuck at zero reads 0 bar whatever the muscle
  holds), and with a pressure commanded the monitor must fall after the vent; if not, the run
  is ``failed``, asks for a VENT BY HAND and its bench marker stays;
- a closed Windows console leaves seconds before the process is ended: the run vents, writes
  run.json with why it stopped and syncs its rows before the vent check, which stops at the
  grace deadline (:meth:`mkm.bench.signals.StopSignals.grace_deadline`) so the final record
  is written before Windows ends the process.

The exit status of ``mkm acquire`` is :attr:`RunResult.exit_code`: 0 complete, 3 complete with
lost samples, 128 + N after signal N, 2 when the run's storage failed (disk full; also when
the run's record is not whole in its folder, ``Recorder.whole``), 4 when the
vent could not be verified (vent by hand; it wins over every other), 1 otherwise.
"""

from __future__ import annotations

import dataclasses
import math
import queue
import sys
import threading
import time
from contextlib import ExitStack
from dataclasses import dataclass, field
from pathlib import Path

from mkm.bench import backends
from mkm.bench.backend import (
    Backend,
    BenchError,
    DaqDisconnected,
    DriverMissing,
    device_said,
    in_words,
)
from mkm.bench.bounded import call_within
from mkm.bench.config import MONITOR_FAULT, BenchConfig, estimate_duration_s, plan_steps
from mkm.bench.operator import Operator
from mkm.bench.ownership import BenchOwner, StateFolderBroken
from mkm.bench.preflight import ForceCeiling, braid_lock, ceiling_lines, warnings
from mkm.bench.recorder import Recorder
from mkm.bench.sequence import Staircase
from mkm.bench.signals import StopSignal, StopSignals, fatal_trace
from mkm.bench.storage import CommandRecord, RunStatus
from mkm.bench.unvented import STATE_WAIT_S, BenchLease, Marker, vent_unvented
from mkm.bench.vent import (
    ZERO_NOISE_SIGMAS,
    VentCheck,
    VentedZero,
    below_command,
    force_per_bar,
    monitor_unmoved,
    still_pulling,
    verify_vent,
    without_fall,
)
from mkm.bench.wakelock import awake
from mkm.bench.worker import Acquisition, Stop

EXIT_OK, EXIT_FAILED, EXIT_STORAGE, EXIT_GAPS, EXIT_VENT = 0, 1, 2, 3, 4
STATUS_EVERY_S = 10.0  # without a terminal: one status line this often
VENT_WRITES = 3  # a vent write cut or refused is written again at once, this many in all
DISK_NOTICE_S = 2.0  # the final record waits this long for the disk before saying it waits
#: a read of the device still under way this long [s] past its timeout and its block's time
#: hangs (a driver that does not keep its timeout): with a pressure commanded, the watchdog vents
READ_HANG_MARGIN_S = 1.0
#: the watchdog looks at the loop's read this often [s]
WATCH_EVERY_S = 0.1
#: the watchdog waits this long [s] for its vent write (the AO write's own timeout) before it
#: records the write as hung too
WATCHDOG_WRITE_S = 1.0


#: the device's close (the vent written again, the tasks cleared) is waited for this long [s]:
#: the AO write's own timeout and the margin; a driver that hangs there holds no record back
CLOSE_WAIT_S = WATCHDOG_WRITE_S + READ_HANG_MARGIN_S


def close_within(backend: Backend, wait_s: float = CLOSE_WAIT_S) -> str:
    """Close ``backend`` (it writes the vent again) on a thread of its own, waited for
    ``wait_s``: a driver that hangs there must not keep the record from being written. Says
    so when it did not return ("" when it closed); raises what the close raised."""
    returned, exc = call_within(backend.close, wait_s, "mkm-close")
    if not returned:
        return (f"closing the device did not return within {wait_s:g} s (the driver hangs): "
                "it is let go as this process ends")
    if exc is not None:
        raise exc
    return ""


#: the device's open, which writes the vent, is waited for this long [s]: a USB-6001's open (two
#: tasks, the AO started, 0 V written within its 1 s timeout) is expected within a second, one
#: that answers as lost within about 5 (reset and opened again for REVIVE_WITHIN_S, 3 s, then
#: the open); twice that for a slow, loaded bench PC
OPEN_WAIT_S = 10.0


class DriverHangs(BenchError):
    """A call into the driver no watchdog watches yet (the device's serial number, its open, a
    run's start of the inputs) did not return within its bound (:func:`driver_call`): the
    command ends there, the call left behind."""


def driver_call(call, what: str, then: str, wait_s: float | None = None):
    """``call()`` on a thread of its own (:func:`mkm.bench.bounded.call_within`), waited for
    ``wait_s`` [s] (default :data:`OPEN_WAIT_S`): what it returned, or raises what it raised;
    :class:`DriverHangs` past it, saying ``what`` did not return, then ``then``."""
    wait_s = OPEN_WAIT_S if wait_s is None else wait_s
    out = []
    returned, exc = call_within(lambda: out.append(call()), wait_s, "mkm-driver")
    if not returned:
        raise DriverHangs(f"{what} did not return within {wait_s:g} s (the driver hangs): {then}")
    if exc is not None:
        raise exc
    return out[0]


def bench_key_within(backend: Backend, then: str = "") -> str:
    """``backend.bench_key`` waited for :data:`OPEN_WAIT_S` (:func:`driver_call`): an NI
    device's serial number is read through the driver (a lost device reset for up to 3 s, as
    its open) before the device is opened, since the bench's lock, a run holding it and the
    markers of dead runs are keyed by it. ``then`` follows what a hang says."""
    return driver_call(lambda: getattr(backend, "bench_key", "unknown"),
                       "reading the device's serial number (it names the bench)",
                       f"nothing was written to the device, not even the vent{then}")


#: what a command says of an open that hangs (:func:`open_within`)
OPEN_HUNG = "the vent is NOT known to be written (the open writes it)"


def open_within(open_device, then: str = OPEN_HUNG):
    """``open_device()`` (the device's open, which writes the vent) waited for
    :data:`OPEN_WAIT_S` (:func:`driver_call`); the device is not to be closed behind an open
    that hangs: the close would wait behind it in the driver."""
    return driver_call(open_device, "opening the device", then)


class WriteHung(Exception):
    """A vent write that did not return within its bound (:class:`BoundedWrite`)."""


class BoundedWrite:
    """``backend`` whose vent write is made on a thread of its own and waited for the AO
    write's timeout (:data:`WATCHDOG_WRITE_S`) and :data:`READ_HANG_MARGIN_S`, as the watchdog
    waits for a command write: a driver that hung in the open or a vent check may hold its
    writes too. :class:`WriteHung` past it, the write left behind."""

    def __init__(self, backend: Backend):
        self._backend = backend

    def write_command(self, volts: float) -> None:
        returned, exc = call_within(lambda: self._backend.write_command(volts),
                                    WATCHDOG_WRITE_S + READ_HANG_MARGIN_S, "mkm-vent-write")
        if not returned:
            raise WriteHung(f"did not return within {WATCHDOG_WRITE_S + READ_HANG_MARGIN_S:g} "
                            f"s (its timeout {WATCHDOG_WRITE_S:g} s): the driver hangs")
        if exc is not None:
            raise exc

    def __getattr__(self, name):
        return getattr(self._backend, name)


class DeadRunsVentHung(BenchError):
    """The vent written again for the dead runs as a command starts hangs in the driver
    (:func:`vent_dead_runs`): the command ends there, nothing more asked of the device."""


def vent_dead_runs(backend: Backend, found: list, on_state_folder) -> list[Marker]:
    """:func:`mkm.bench.unvented.vent_unvented` right after the device's open, its vent write
    bounded (:class:`BoundedWrite`): :class:`DeadRunsVentHung` when it hangs, the dead runs'
    markers left for the next command to vent and name."""
    try:
        return vent_unvented(BoundedWrite(backend), found, on_state_folder)
    except WriteHung as exc:
        raise DeadRunsVentHung(f"the vent written for the runs that died on this bench {exc}: "
                               "VENT BY HAND; they were not named, and the next command on "
                               "this bench vents first and names them") from None


class StderrNotice:
    """One line for the operator on stderr, ``mkm <command>: <message>`` as every command's
    lines (the default ``notify`` of runs and procedures)."""

    def __init__(self, command: str):
        self.command = command

    def line(self, message: str) -> str:
        return f"mkm {self.command}: {message}"

    def __call__(self, message: str) -> None:
        print(self.line(message), file=sys.stderr, flush=True)


class _Console:
    """What a run writes to the console (progress, notices) without ever waiting for it.

    A console that does not take its output blocks the writer: a terminal paused with Ctrl-S,
    a Windows console with text selected in QuickEdit mode, a pipe nobody reads. Written by the
    acquisition loop, that would stop the loop, and with it every interlock, while the
    regulator holds its pressure. So the loop only queues text (dropped when the queue is
    full, counted in ``dropped``) and a thread of its own writes it to ``stream``; its write
    errors (a closed terminal, a broken pipe) are the console's, not the run's.
    """

    def __init__(self, stream, maxsize: int = 1024):
        self.stream = stream
        self.dropped = 0
        self._queue: queue.Queue = queue.Queue(maxsize)
        self._thread = threading.Thread(target=self._write, name="mkm-console", daemon=True)
        self._thread.start()

    def write(self, text: str) -> int:
        try:
            self._queue.put_nowait(text)
        except queue.Full:
            self.dropped += 1
        return len(text)

    def flush(self) -> None:
        pass  # the thread flushes after every write

    def isatty(self) -> bool:
        try:
            return bool(self.stream.isatty())
        except (AttributeError, ValueError, OSError):
            return False

    def __getattr__(self, name):  # encoding, fileno (tqdm's terminal width): the stream's
        return getattr(self.stream, name)

    def _write(self) -> None:
        while (text := self._queue.get()) is not None:
            try:
                self.stream.write(text)
                self.stream.flush()
            except (OSError, ValueError):
                pass

    def close(self, wait_s: float = 2.0) -> None:
        """Let the queued text out, waiting at most ``wait_s`` for a console that is stuck."""
        try:
            self._queue.put(None, timeout=wait_s)
        except queue.Full:
            return
        self._thread.join(wait_s)


@dataclass
class RunResult:
    """Outcome of a run; ``path`` is None when it failed before its folder was made."""

    path: Path | None
    status: RunStatus
    reason: str
    exit_code: int = EXIT_FAILED
    manual_vent_required: bool = False
    unvented_before: list[Marker] = field(default_factory=list)


def _all_steps(n: int) -> str:
    """``the 1 step`` or ``all 3 steps``: what a complete run did."""
    return "the 1 step" if n == 1 else f"all {n} steps"


def check_out_root(out_root: str | Path) -> Path:
    """``out_root`` as a folder that exists (made if needed) and is writable, or ``ValueError``
    (checked before the device is opened)."""
    import tempfile

    out = Path(out_root)
    if out.exists() and not out.is_dir():
        raise ValueError(f"--out {out} is a file: expected a folder for the run folders")
    try:
        out.mkdir(parents=True, exist_ok=True)
        with tempfile.TemporaryFile(dir=out):
            pass
    except OSError as exc:
        raise ValueError(f"--out {out} is not a writable folder ({exc.strerror or exc})") \
            from None
    return out


class _Progress:
    """Progress on stderr: a tqdm bar when stderr is a terminal, else (a log, a pipe) one status
    line every :data:`STATUS_EVERY_S`. Set and measured pressure, force, a lower bound of the
    time left; SIMULATED in front when no hardware is driven."""

    def __init__(self, config: BenchConfig, n_steps: int, stream=None, command: str = "acquire"):
        self.config, self.n_steps, self.done = config, n_steps, 0
        self.stream = stream or sys.stderr
        self.command = command
        self.label = f"{command} SIMULATED" if config.simulated else command
        self.bar = None
        if self.stream.isatty():
            from tqdm import tqdm

            self.bar = tqdm(total=n_steps, unit="step", desc=self.label, leave=True,
                            file=self.stream)
        self.shown_at = time.monotonic() if self.bar is None else 0.0

    def _status(self, row) -> str:
        st = self.config.settle
        left_s = (self.n_steps - self.done) * (st.min_dwell_s + st.hold_s)
        return (f"{row.phase} {row.set_pressure_bar:.2f} bar, measured {row.pressure_bar:.2f} "
                f"bar, {row.force_N:.1f} N, >= {left_s / 60:.1f} min left")

    def block(self, rows) -> None:
        now = time.monotonic()
        if not rows or now - self.shown_at < (0.25 if self.bar else STATUS_EVERY_S):
            return
        if self.bar is not None:
            self.bar.set_postfix_str(self._status(rows[-1]))
        else:
            simulated = "SIMULATED " if self.config.simulated else ""
            print(f"mkm {self.command}: {simulated}step {self.done}/{self.n_steps}, "
                  f"{self._status(rows[-1])}", file=self.stream, flush=True)
        self.shown_at = now

    def step(self, _step) -> None:
        self.done += 1
        if self.bar is not None:
            self.bar.update(1)

    def close(self) -> None:
        if self.bar is not None:
            self.bar.close()


class _Plot:
    def __init__(self, title: str):
        from mkm.bench.liveplot import LivePlot

        self.plot = LivePlot(title)

    def block(self, rows) -> None:
        if rows:
            self.plot.push(rows[-1].time_s, rows[-1].pressure_bar, rows[-1].force_N)

    def close(self) -> None:
        self.plot.close()


class _ReadWatchdog:
    """Vents a run whose read of the device hangs with the muscle pressurised: a pressure
    commanded, or read above the vent threshold whatever the command
    (:meth:`mkm.bench.worker.Acquisition.pressurised`).

    A read returns within its timeout and its block's time, or raises (the read interlock then
    vents); a driver that does not keep its timeout holds the acquisition loop, every interlock
    with it, while the regulator holds its pressure. A thread of its own looks at the loop's
    read (:attr:`mkm.bench.worker.Acquisition.reading_since`) every :data:`WATCH_EVERY_S`:
    past ``daq.read_timeout_s`` + the block's time + :data:`READ_HANG_MARGIN_S` so pressurised
    it writes the vent (acts first), then keeps the books (so it does for the loop's
    command write, :attr:`mkm.bench.worker.Acquisition.writing`, past the AO write's timeout
    :data:`WATCHDOG_WRITE_S` and the margin): the command's row, the
    bench marker, run.json ``failed`` with why and the vent not verified (a process that never
    comes back is so recorded), a notice; the loop stops the run once the read returns. Once
    the shutdown has written its vent (:meth:`vented`) it vents no more and watches the reads
    of the shutdown (the samples left, the vent check), keeping only the books of each that
    hangs. It watches until :meth:`stop`, past every hang it handled, each once: a hang of the
    loop, then one of the shutdown, are both recorded.
    """

    def __init__(self, run: BenchRun):
        self.run = run
        daq = run.config.daq
        self.limit_s = (daq.read_timeout_s + daq.read_block_samples / daq.sample_rate_hz
                        + READ_HANG_MARGIN_S)
        self._stop, self._vented = threading.Event(), threading.Event()
        self._thread = threading.Thread(target=self._watch, name="mkm-read-watchdog",
                                        daemon=True)
        self._thread.start()

    def vented(self) -> None:
        """The shutdown's vent is written: no vent from here on, and no books of the loop's
        hang (the shutdown keeps them); never waits: a write the hung driver holds would hold
        the shutdown too, and a vent written twice is harmless."""
        self._vented.set()

    def stop(self) -> None:
        """The shutdown's reads are done: the thread ends."""
        self._vented.set()
        self._stop.set()

    def _watch(self) -> None:
        run = self.run
        acq = run.acquisition
        handled = set()  # when each call whose hang was handled began: handled once
        while not self._stop.wait(WATCH_EVERY_S):
            writing = acq.writing
            if writing is not None and writing[0] not in handled and \
                    self._write_hung(acq, writing):
                handled.add(writing[0])
                continue
            since, held = acq.reading_since, acq.held_said()
            if since is None or since in handled or not (acq.pressurised()
                                                         or self._vented.is_set()):
                continue
            hung_s = time.monotonic() - since
            if hung_s < self.limit_s:
                continue
            handled.add(since)
            if self._vented.is_set():  # the shutdown's read, its vent written: books only
                self._after_vent(hung_s)
                continue
            t_s = acq.next_index / acq.rate_hz
            self._trip(acq, t_s, f"read interlock: the read of the device did not return "
                       f"within {hung_s:.1f} s (its timeout {run.config.daq.read_timeout_s:g} "
                       f"s) with {held} after {t_s:g} s: the driver hangs")

    def _trip(self, acq: Acquisition, t_s: float, why: str) -> None:
        """A hang with a pressure held: the loop stops at its next block from now on, whatever
        the vent write does (``why``); the vent is written first, then the books kept, unless
        the shutdown, under way, keeps them."""
        acq.hung = why
        ok, vent = self._vent()  # acts first
        acq.hung_vent = vent
        if not self._vented.is_set():
            self._books(ok, t_s)

    def _write_hung(self, acq: Acquisition, writing: tuple[float, float]) -> bool:
        """Whether the loop's command write hangs past :data:`WATCHDOG_WRITE_S` (the AO write's
        own timeout) and :data:`READ_HANG_MARGIN_S` with a pressure held or asked for: then
        vented, and the books kept, as for a read (the shutdown's vent write included, until
        it is out)."""
        if self._vented.is_set():
            return False
        since, asked_bar = writing
        hung_s = time.monotonic() - since
        if hung_s < WATCHDOG_WRITE_S + READ_HANG_MARGIN_S or not (asked_bar > 0
                                                                 or acq.pressurised()):
            return False
        t_s = acq.next_index / acq.rate_hz
        # the loop also vents a pressure the hung write lets out late
        self._trip(acq, t_s, f"write interlock: the command of {asked_bar:g} bar did not return "
                   f"within {hung_s:.1f} s (its timeout {WATCHDOG_WRITE_S:g} s) with "
                   f"{acq.held_said()} after {t_s:g} s: the driver hangs")
        return True

    def _vent(self) -> tuple[bool, str]:
        """Write the vent on a thread of its own, waited for :data:`WATCHDOG_WRITE_S`: a driver
        that hangs may hold its writes too, and the books must still be kept. Whether it went
        out, and what came of it in words."""
        volts = self.run.config.regulator.command_volts(0.0)
        returned, exc = call_within(lambda: self.run.backend.write_command(volts),
                                    WATCHDOG_WRITE_S, "mkm-watchdog-vent")
        if not returned:
            return False, (f"the watchdog's vent command did not return within "
                           f"{WATCHDOG_WRITE_S:g} s (the driver hangs for it too): VENT BY HAND")
        if exc is not None:
            return False, (f"the watchdog's vent command failed ({in_words(exc)}): "
                           "VENT BY HAND")
        return True, "vented by the watchdog"

    def _after_vent(self, hung_s: float) -> None:
        """A read of the shutdown hangs after its vent: run.json says so, the vent not
        verified (a process that never comes back is so recorded), and a notice (never
        raises)."""
        run, acq = self.run, self.run.acquisition
        hung = (f"a read of the device did not return within {hung_s:.1f} s (its timeout "
                f"{run.config.daq.read_timeout_s:g} s) after the shutdown's vent: the driver "
                "hangs")
        # a read that hung before it returned: the reads after it are said after it
        acq.hung_after_vent = "; ".join(filter(None, [acq.hung_after_vent and
                                                      f"{acq.hung_after_vent}, then returned",
                                                      hung]))
        try:
            run.recorder.meta.manual_vent_required = True
            said = "; ".join(filter(None, [acq.hung_said(), acq.hung_after_vent]))  # the loop's
            run.recorder.mark(RunStatus.FAILED, f"{said}; the vent was commanded, its check "
                              "cannot read the monitor: VENT BY HAND or verify it with `mkm "
                              "vent`", 0.0)
            run.notify(f"{acq.hung_after_vent}: VENT BY HAND or verify it with `mkm vent`; "
                       f"{run.recorder.path} records it")
        except BaseException:  # the shutdown records the run if the read returns
            pass

    def _books(self, ok: bool, t_s: float) -> None:
        """After the watchdog's vent: its row, the marker, run.json, a notice (never raises)."""
        run, acq = self.run, self.run.acquisition
        try:
            run.recorder.command(CommandRecord(t_s, acq.next_index, 0.0, 0.0, ok,
                                               "watchdog vent"))
            if ok and run.lease is not None:
                lease = run.lease
                lease.post(lambda: lease.command(0.0))
            run.recorder.meta.manual_vent_required = True
            said = acq.hung_said()
            run.recorder.mark(RunStatus.FAILED, f"{said}; the vent is not verified until the "
                              "read returns", 0.0)
            run.notify(f"{said}; {run.recorder.path} records it")
        except BaseException:  # the vent went out; the shutdown records the run
            pass


class _Watched:
    """``backend`` whose reads the run's watchdog watches (the vent check's:
    :attr:`mkm.bench.worker.Acquisition.reading_since` set while one is under way)."""

    def __init__(self, backend: Backend, acquisition: Acquisition):
        self._backend, self._acquisition = backend, acquisition

    def read(self, n_samples: int, timeout_s: float):
        self._acquisition.reading_since = time.monotonic()
        try:
            return self._backend.read(n_samples, timeout_s)
        finally:
            self._acquisition.reading_since = None

    def __getattr__(self, name):
        return getattr(self._backend, name)


class BenchRun:
    """One run on ``backend`` with ``config``, recorded under ``out_root``.

    ``operator`` is needed only for a manual regulator. ``progress`` shows a tqdm bar on stderr;
    ``plot`` a live plot in another process. ``handle_signals`` installs the stop handlers of
    :mod:`mkm.bench.signals` (only possible in the main thread). ``notify`` receives one-line
    messages for the operator (a bench found unvented, a stop requested); by default they go
    to stderr as ``mkm <command>: ...``, through the run's console while it runs. ``command``
    is the command the user ran (``acquire``, ``demo``): it names the progress lines, the
    notices and the bench's holder.
    """

    def __init__(self, config: BenchConfig, backend: Backend, out_root: str | Path,
                 operator: Operator | None = None, progress: bool = False, plot: bool = False,
                 handle_signals: bool = True, notify=None, command: str = "acquire",
                 ceiling: ForceCeiling | None = None):
        if not config.regulator.electronic and operator is None:
            raise ValueError("regulator.kind='manual' needs an operator to set the pressure")
        self.config = config
        self.backend = backend
        self.out_root = check_out_root(out_root)
        self.operator = operator
        self.progress = progress
        self.plot = plot
        # the default notices go through the run's console (:class:`_Console`) while it runs
        self.notify = self._say if notify is None else notify
        self._console: _Console | None = None
        self.handle_signals = handle_signals
        self.command = command
        self.ceiling = ceiling  # the identified muscle's most: the over-force interlock's bound
        self.signals = StopSignals()
        self._fatal = ExitStack()  # the fatal-error trace into the run folder (fatal_trace)
        self.steps = plan_steps(config)
        self.recorder: Recorder | None = None
        self.acquisition: Acquisition | None = None
        self.lease: BenchLease | None = None
        self.unvented: list[Marker] = []
        self._dead_runs: list = []  # their markers, found as the bench was taken
        self._observers: list = []
        self.owner: BenchOwner | None = None
        self._stop_by: str | None = None
        self._started = False
        self._watchdog: _ReadWatchdog | None = None
        self.vent_check: VentCheck | None = None
        self._vent_rows_problems: list[str] = []  # the vent check's rows not recorded
        self.storage_failed = False
        self._folder_error: OSError | None = None  # the run folder could not be made
        self._device_hangs = False  # a call of the start-up hangs in the driver
        self._opened = False  # the device's open returned
        self._open_stop = ""  # what came of the open a stop signal was held behind

    def request_stop(self, by: str | None = None) -> None:
        """What the first Ctrl-C does: stop at the next safe point (``by`` says who else asked)."""
        if self.signals.stop_requested_at is None:
            self.signals.stop_requested_at = time.monotonic()
            self._stop_by = by

    def _stop_time(self):
        """When the first stop was asked for (a first Ctrl-C, then a second: the first)."""
        times = [t for t in (self.signals.stop_requested_at, self.signals.signal_at)
                 if t is not None]
        return min(times) if times else None

    def _pending_stop(self) -> Stop | None:
        """The stop to make at this safe point: a first Ctrl-C, or `mkm vent` asking; the
        signal handlers' notices are said here, by the loop."""
        for message in self.signals.said():
            self.notify(message)
        if self.signals.stop_requested_at is None and self.owner is not None:
            by = self.owner.stop_request()
            if by is not None:
                self.notify(f"stopping: {by} asked this run to stop")
                self.request_stop(by)
        if self.signals.stop_requested_at is None:
            return None
        if self._stop_by:
            return Stop(RunStatus.ABORTED, f"stopped by {self._stop_by} at a safe point",
                        say_vent=True)
        return Stop(RunStatus.ABORTED, "stopped by Ctrl-C (SIGINT) at a safe point", "SIGINT", 2,
                    say_vent=True)

    # lifecycle -------------------------------------------------------------------------------

    def execute(self) -> RunResult:
        """Run the whole sequence; the run folder holds the truth whatever happens.

        Raises :class:`mkm.bench.ownership.BenchBusy` (nothing touched) when another process
        holds the bench, :class:`DriverHangs` (nothing touched) when the device's serial number
        that names the bench is not read within :data:`OPEN_WAIT_S`,
        :class:`mkm.bench.ownership.StateFolderBroken` (nothing touched) when the bench state
        folder does not answer as the bench is taken or its dead runs looked for.
        """
        try:
            with BenchOwner(bench_key_within(self.backend, "; VENT BY HAND"), self.command) \
                    as owner, awake():  # Windows must not sleep with the muscle pressurised
                self.owner = owner
                self._dead_runs = owner.dead_runs()  # before the device is opened
                self._console = _Console(sys.stderr)
                try:
                    if self.handle_signals:
                        with self.signals:
                            return self._execute()
                    return self._execute()
                finally:
                    console, self._console = self._console, None
                    console.close()
        finally:  # the run is vented and recorded: a state folder that hangs is not waited for
            if self.owner is not None and self.owner.problem:
                self.notify(self.owner.problem)

    def _say(self, message: str) -> None:
        """The default notice: through the run's console while it runs, else on stderr."""
        console, notice = self._console, StderrNotice(self.command)
        if console is None:
            notice(message)
        else:
            console.write(notice.line(message) + "\n")

    def _execute(self) -> RunResult:
        status, reason, error, exit_code = RunStatus.FAILED, "", None, EXIT_FAILED
        signal_name = signal_number = None
        outcome: BaseException | None = None  # what ended the run early
        late: BaseException | None = None  # a signal that came before they were held
        say_vent = False  # the shutdown says whether its vent went out (the reason does not yet)
        try:
            try:
                self.startup()
                Staircase(self.config, self.acquisition, self.operator, self._on_step,
                          self.notify).run()
                status, reason, exit_code = self._finished()
            except BaseException as exc:
                outcome = exc
            self.signals.hold()  # a further signal must not cut the vent or the record
        except BaseException as exc:  # a signal while the outcome was taken, before the hold
            self.signals.hold()
            late = exc
        # judged with the signals held: a signal can no longer escape as a traceback
        if outcome is None:
            outcome, late = late, None
        if isinstance(outcome, Stop):
            status, reason = outcome.status, outcome.reason
            signal_name, signal_number = outcome.signal_name, outcome.signal_number
            say_vent = outcome.say_vent
        elif isinstance(outcome, StopSignal):
            status, signal_name, signal_number = RunStatus.ABORTED, outcome.name, outcome.signum
            reason, say_vent = f"stopped by {outcome} at once", True
            if self._open_stop:  # held behind the device's open
                reason = f"stopped by {outcome} during the device's open, {self._open_stop}"
                if self._device_hangs:  # nothing is written behind an open that hangs
                    status, say_vent = RunStatus.FAILED, False
        elif isinstance(outcome, KeyboardInterrupt):  # no handlers (not the main thread)
            status, signal_name, signal_number = RunStatus.ABORTED, "SIGINT", 2
            reason, say_vent = "stopped by a second Ctrl-C (SIGINT) at once", True
        elif isinstance(outcome, OSError) and (
                outcome is self._folder_error or
                (self.recorder is not None and self.recorder.refused(outcome))):
            # the run folder's disk: full, gone, read-only; what it refused, when a write
            what = self.recorder.refused(outcome) if self.recorder is not None else ""
            status, exit_code = RunStatus.FAILED, EXIT_STORAGE
            reason = (f"recording failed{f' for {what}' if what else ''} "
                      f"({in_words(outcome)})")
        elif isinstance(outcome, DeadRunsVentHung | DriverHangs):  # said whole; the device is
            # asked no more
            status, reason, self._device_hangs = RunStatus.FAILED, str(outcome), True
        elif isinstance(outcome, DriverMissing):  # what to install, said whole
            status, reason = RunStatus.FAILED, str(outcome)
        elif isinstance(outcome, BenchError | OSError):  # the device, its driver: not the disk
            status, reason = RunStatus.FAILED, device_said(outcome)
        elif outcome is not None:
            status, reason, error = RunStatus.FAILED, in_words(outcome), outcome
        if isinstance(late, StopSignal | KeyboardInterrupt):  # in the record, whatever it ends
            name = late.name if isinstance(late, StopSignal) else "SIGINT"
            if signal_number is None:
                signal_name, signal_number = name, getattr(late, "signum", 2)
            reason = f"{reason}; {name} received meanwhile"
        try:
            status, reason = self.shutdown(status, reason, signal_name, signal_number,
                                           say_vent)
        finally:
            self._fatal.close()
            self.signals.done()
        if signal_number is not None:
            exit_code = 128 + signal_number
        if self.storage_failed:
            exit_code = EXIT_STORAGE
        manual_vent = self.vent_check is not None and not self.vent_check.verified
        if manual_vent:
            exit_code = EXIT_VENT
        if error is not None:  # a bug: its traceback follows, so say first where the run is
            if self.recorder is not None:
                vent = ("VENT THE MUSCLE BY HAND NOW: the vent was not verified" if manual_vent
                        else "vented")
                self.notify(f"the run stopped on an error of mkm ({reason}): {vent}; its "
                            f"samples are recorded, status {status}, in {self.recorder.path}")
            if isinstance(error, ValueError):  # taken for bad input: one line, no traceback
                raise RuntimeError(f"an error of mkm stopped the run: {reason}") from error
            raise error
        return RunResult(self.recorder.path if self.recorder else None, status, reason,
                         exit_code, manual_vent, self.unvented)

    def _finished(self) -> tuple[RunStatus, str, int]:
        meta, n = self.recorder.meta, len(self.steps)
        blind = self.acquisition.one_code_throughout()
        if blind:  # every step done, none measured
            return RunStatus.FAILED, f"{_all_steps(n)} done, but {blind}", EXIT_FAILED
        if not meta.gaps:
            return RunStatus.COMPLETE, f"{_all_steps(n)} done", EXIT_OK
        spans = ", ".join(f"{g.start_s:g}-{g.end_s:g} s" for g in meta.gaps)
        return (RunStatus.COMPLETE_WITH_GAPS, f"{_all_steps(n)} done, but {meta.lost_samples} "
                f"samples were lost in {len(meta.gaps)} gap(s): {spans}", EXIT_GAPS)

    def _open(self):
        """The device's open (it writes the vent command first), bounded (:func:`open_within`);
        a stop signal that comes meanwhile is held until the open returns or its bound passes:
        the shutdown's vent and close would go into the driver beside the open under way (an
        NI device's AO task not yet made: a vent said written that was not). Never closed when
        it hangs."""
        hung = None
        try:
            with self.signals.deferred():
                try:
                    info = open_within(self.backend.open, f"{OPEN_HUNG}; VENT BY HAND")
                except DriverHangs as exc:
                    hung = exc
                    raise
        except StopSignal:
            if hung is None:
                self._opened, self._open_stop = True, "held until it returned"
            else:
                self._device_hangs, self._open_stop = True, f"held until its bound passed: {hung}"
            raise
        self._opened = True
        return info

    def startup(self) -> None:
        info = self._open()
        self.unvented = vent_dead_runs(self.backend, self._dead_runs, self.owner.on_state_folder)
        for marker in self.unvented:
            self.notify(marker.vented_now())
        # a stop signal while the folder is made waits until the run holds its recorder: the
        # shutdown then records why it stopped (a folder whose making it cuts is removed)
        with self.signals.deferred():
            try:
                self.recorder = Recorder(self.out_root, self.config, info, len(self.steps),
                                         estimate_duration_s(self.config),
                                         [m.noted() for m in self.unvented],
                                         self.ceiling.record() if self.ceiling else None)
            except OSError as exc:
                self._folder_error = exc
                raise
        self._fatal.enter_context(fatal_trace(self.recorder.path))
        # the lease is kept from here on: a stop while its first write is waited for still
        # removes the marker at the shutdown
        lease = self.lease = BenchLease(getattr(self.backend, "bench_key", "unknown"),
                                        self.recorder.path, self.recorder.meta.started_utc)
        try:
            lease.started()
        except OSError as exc:  # the state folder, not the run folder: said as such
            lease.post(lease.release)  # whenever it answers: no marker is left
            lease.end()
            self.lease = None
            raise StateFolderBroken(f"the bench marker cannot be written in the bench state "
                                    f"folder ({exc.strerror or exc}): nothing was "
                                    "pressurised") from None
        if self.config.simulated:
            self.notify(f"SIMULATED bench ({self.config.daq.backend}): no hardware is driven; "
                        f"recording into {self.recorder.path}")
        if self.progress:
            self._observers.append(_Progress(self.config, len(self.steps), self._console,
                                              self.command))
        if self.plot:
            self._observers.append(_Plot(self.config.muscle.id))
        self.acquisition = Acquisition(
            self.config, self.backend, self.recorder, stop_requested=self._pending_stop,
            stop_time=self._stop_time, lease=self.lease, observers=self._observers,
            guard=self.signals.deferred, ceiling=self.ceiling)
        self.acquisition.command(0.0, "vent")
        # no watchdog yet: bounded as `mkm vent`'s start of the inputs (the AO write's timeout
        # and the margin, as a command write)
        driver_call(self.backend.start, "starting the device's inputs", "the vent was written "
                    "before it and no pressure commanded; nothing was acquired",
                    WATCHDOG_WRITE_S + READ_HANG_MARGIN_S)
        self._started = True
        if self.config.regulator.electronic:
            self._watchdog = _ReadWatchdog(self)

    def _on_step(self, step) -> None:
        for observer in self._observers:
            if hasattr(observer, "step"):
                observer.step(step)

    def _revive(self, lost: str) -> tuple[bool, str]:
        """The vent after a device loss (``lost`` says what failed): the backend resets the
        device and writes 0 V on a fresh task (bounded); the run's own vent command then
        records it. Whether the device came back, and what happened in one phrase."""
        try:
            self.backend.revive()
        except BaseException as exc:
            return False, (f"{lost}; resetting the device did not bring it back "
                           f"({in_words(exc)})")
        self._started = True  # a fresh AI task runs: the vent is verified as always
        done = f"{lost}: the device was reset and vented on a fresh task"
        if self.acquisition is not None:
            try:
                self.acquisition.restarted()
                self.acquisition.command(0.0, "vent")
            except BaseException as exc:  # 0 V was written by revive(); its record failed
                return True, (f"{done}, but recording that vent failed "
                              f"({in_words(exc)})")
        return True, done

    def _keep_books(self, status: RunStatus, reason: str, problems: list[str], signal_name,
                    signal_number) -> None:
        """A closed Windows console: the process is ended within seconds, so once the vent is
        commanded, run.json says why the run stopped and that the vent is not yet verified
        (``manual_vent_required`` until the check says otherwise), and the rows are synced,
        before the vent check takes what time is left."""
        if self.recorder is None:
            return
        meta = self.recorder.meta
        meta.stop_signal, meta.stop_signal_number = signal_name, signal_number
        meta.manual_vent_required = True
        pending = ("the vent was commanded; its check had not ended when Windows was about to "
                   "end the process: VENT BY HAND or verify it with `mkm vent`")
        # a disk that hangs gets until the grace deadline; the final record says what it did
        self.recorder.mark(status, "; ".join(filter(None, [reason, *problems, pending])),
                           max(self.signals.grace_deadline() - time.monotonic(), 0.0))

    @staticmethod
    def _drain(acq: Acquisition) -> list[str]:
        """After the vent: record the samples acquired before it and not yet read
        (:meth:`Acquisition.drain`); the problem met (never raises: the vent check comes next).
        A device that fails to answer is left to the vent check, which reads it and says so."""
        try:
            acq.drain()
        except BenchError:
            return []
        except BaseException as exc:  # a device half closed by a failed revive, a Ctrl-C
            return [f"the samples acquired before the stop could not be recorded "
                    f"({in_words(exc)})"]
        return []

    def _verify(self, gone: bool = False) -> VentCheck:
        """The vent check (:func:`mkm.bench.vent.verify_vent`), bounded by a closed console's
        grace deadline; never raises. ``gone``: the device is lost for good, nothing to read."""
        below = self.config.safety.vent_below_bar
        if gone:
            return VentCheck(False, float("nan"), below, 0.0, "monitor", "the device is gone",
                             device_lost=True)
        acq, problems = self.acquisition, self._vent_rows_problems

        def record(block) -> None:  # the decay after the vent, on disk (phase "vent")
            problem = acq.record_vent_check(block) if acq is not None and \
                self.recorder is not None else ""
            if problem and problem not in problems:
                problems.append(problem)

        try:
            zero = VentedZero.from_tare(self.recorder.meta.tare, self.config) \
                if self.recorder is not None else None
            backend = _Watched(self.backend, acq) if acq is not None else self.backend
            return verify_vent(backend, self.config, self.operator, started=self._started,
                               deadline=self.signals.grace_deadline, record=record,
                               vented_zero=zero)
        except BaseException as exc:
            return VentCheck(False, float("nan"), below, 0.0, "monitor",
                             in_words(exc))

    def _weighed(self, acq: Acquisition, check: VentCheck) -> VentCheck:
        """The vent check weighed by what the monitor read before the vent: one that read
        nothing of a pressure commanded proves nothing by reading nothing after it
        (:func:`mkm.bench.vent.below_command`), unless, shown working earlier in the run, it
        fell after the vent (a stop as a step from 0 bar begins: the regulator not yet there);
        with a pressure above the vent threshold commanded, a monitor that shows no fall after
        the vent proves nothing either (:func:`mkm.bench.vent.without_fall`)."""
        before = acq.before_vent()
        fell = check
        if check.noise_bar is not None and before is not None and \
                before[1] > self.config.safety.vent_below_bar:
            fell = without_fall(check, *before, check.noise_bar)
        unproven = acq.unproven()
        if unproven is not None and not (acq.shown_moving and fell.verified
                                         and check.first_above_bar is not None):
            judged = below_command(check, *unproven)
            fell = fell if judged.verified else judged
        forces, tare = acq.forces_around_vent(), self.recorder.meta.tare \
            if self.recorder is not None else None
        if forces is not None and tare and before is not None:
            step_N = acq.step_N
            tare_std_N = float(tare["std_N"])
            noise_N = ZERO_NOISE_SIGMAS * tare_std_N + 2 * step_N
            # a cell that strayed more than an ADC step at the tare, or held its code while the
            # monitor rose (a quieter one) or moved as no live cell allows (the interlock of
            # unmoved_cell), and reads one value around the vent is stuck: said
            # as such, the vent still not verified by it
            stuck = (before[0], tare_std_N) if acq.forces_unchanged() and (
                tare_std_N > step_N or acq.one_code_throughout() or acq.unmoved) else None
            fell = still_pulling(fell, *forces, noise_N, max(before[1], acq.pressure_commanded_bar),
                                 stuck, force_per_bar(self.recorder.step_rows, noise_N))
            fell = monitor_unmoved(fell, before[0], *forces, noise_N)
        return fell

    def _write_vent(self, acq: Acquisition | None) -> BaseException | None:
        """Command the vent; what stopped it, or None."""
        try:
            if acq is not None:
                acq.command(0.0, "vent")
            else:
                self.backend.write_command(0.0)
        except BaseException as exc:  # judged by the shutdown
            return exc
        return None

    def shutdown(self, status: RunStatus, reason: str, signal_name=None,
                 signal_number=None, say_vent: bool = False) -> tuple[RunStatus, str]:
        """Vent, verify the vent, close the device, record the outcome. Never raises; returns
        the final status and reason (``failed`` when the vent could not be verified).
        ``say_vent``: ``reason`` (a stop) is followed by ``vented`` once the vent command
        reached the device, and only then: a failed one is said instead."""
        if self._device_hangs:  # before any pressure: a vent or a read would wait behind the
            # call under way in the driver; the close is bounded, and not made behind an open
            try:
                closing = close_within(self.backend) if self._opened else ""
            except BaseException as exc:
                closing = f"closing the device failed ({in_words(exc)})"
            return self._record(status, reason, [closing] if closing else [],
                                lambda problems: problems, signal_name, signal_number)
        problems = []
        acq = self.acquisition
        if self._watchdog is not None:
            # the read came back with an error, or as the watchdog wrote its vent
            problems.extend(part for part in (acq.hung, acq.hung_vent)
                            if part and part not in reason)
        revive = hasattr(self.backend, "revive")  # a device loss is tried once, then said
        gone = False  # lost, and the reset did not bring it back: nothing can be read
        failure = self._write_vent(acq)
        for _ in range(VENT_WRITES - 1):
            if failure is None or (acq is not None and acq.written) or (
                    isinstance(failure, DaqDisconnected) and revive):
                break  # vented, or only its record failed, or a lost device: revived below
            # cut before the device, or refused by it once: the muscle is still pressurised
            if isinstance(failure, KeyboardInterrupt | StopSignal):
                problems.append(f"the vent command was interrupted ({type(failure).__name__}) "
                                "and written again")
            else:
                problems.append(f"vent command failed ({in_words(failure)}), "
                                "tried again")
            failure = self._write_vent(acq)
        if self._watchdog is not None:  # no vent of its own from here on: reads watched
            self._watchdog.vented()
            # a vent write of the shutdown that hung, vented by the watchdog meanwhile
            problems.extend(part for part in (acq.hung, acq.hung_vent)
                            if part and part not in reason and part not in problems)
        # where the reason says "vented": after the failed tries, before what came after
        vented_at = len(problems) if say_vent and (
            failure is None or (acq is not None and acq.written)) else None

        def told(problems: list[str]) -> list[str]:
            if vented_at is None:
                return problems
            return [*problems[:vented_at], "vented", *problems[vented_at:]]

        # the vent command reached the device (a regulator that never got it is no slow one)
        written = failure is None or (acq is not None and acq.written)
        if failure is not None:  # the device may be gone; closing must still happen
            exc = failure
            if acq is not None and acq.written:  # written; only its record failed
                problems.append(f"recording the vent failed ({in_words(exc)})")
            elif isinstance(exc, DaqDisconnected) and revive:
                back, said = self._revive(f"vent command failed ({in_words(exc)})")
                problems.append(said)
                revive, gone, written = False, not back, back
            else:
                problems.append(f"vent command failed ({in_words(exc)})")
        if acq is not None and self._started and not gone:
            problems.extend(self._drain(acq))
        if self.signals.grace_deadline() is not None:
            self._keep_books(status, reason, told(problems), signal_name, signal_number)
        self._vent_rows_problems = problems  # the vent check's rows that failed to record
        self.vent_check = self._verify(gone)
        if self.vent_check.device_lost and revive:
            # the vent was written, but the device was lost before the monitor confirmed it
            back, said = self._revive(f"the vent check's reads failed "
                                      f"({self.vent_check.problem})")
            problems.append(said)
            self.vent_check = self._verify(not back)
        if not written:  # no setting of the check helps a vent never written
            self.vent_check = dataclasses.replace(self.vent_check, timeout_s=None)
        if self._watchdog is not None:  # the shutdown's reads are done
            self._watchdog.stop()
            if acq.hung_after_vent:  # and came back
                problems.append(f"{acq.hung_after_vent}, then returned")
        if not self._started and self.config.regulator.electronic and \
                (acq is None or acq.command_bar == 0.0) and not problems:
            # never started and nothing but vents commanded: there is nothing to verify
            self.vent_check = None
        unpressurised = self._unpressurised(acq)
        if unpressurised:  # a lost device's vent check proves nothing, and nothing needs it
            problems.append(unpressurised)
            self.vent_check = None
        if self.vent_check is not None and acq is not None:
            self.vent_check = self._weighed(acq, self.vent_check)
        if acq is not None and acq.interlock_vent_failed:  # said before: what came of it
            if self.vent_check is None:
                problems.append("nothing verified a vent since: VENT BY HAND")
            elif self.vent_check.verified:
                problems.append(f"the shutdown's vent went through ({self.vent_check.describe()})")
        try:
            closing = close_within(self.backend)
        except BaseException as exc:
            closing = f"closing the device failed ({in_words(exc)})"
        if closing:
            problems.append(closing)
        return self._record(status, reason, problems, told, signal_name, signal_number)

    def _unpressurised(self, acq: Acquisition | None) -> str:
        """What to say of a vent its check could not confirm (the device lost, the monitor's
        wire off) when this run applied no pressure: it asked for none above 0 bar, the
        monitor read none above ``safety.vent_below_bar``, and no run had died on the bench
        (whose pressure this run would have found there); no vent by hand is asked for. ""
        otherwise (a manual regulator's operator reads the vent)."""
        check, below = self.vent_check, self.config.safety.vent_below_bar
        if check is None or check.verified or self._dead_runs or \
                not self.config.regulator.electronic:
            return ""
        # unread, not misread: a monitor that read something wrong (its zero drifted low) may
        # hide a pressure, and an error of mkm proves nothing
        unread = check.device_lost or check.problem.startswith(MONITOR_FAULT) or (
            acq is None and not self._started)
        if not unread:
            return ""
        then = "; see that the regulator reads 0 bar before the next run"
        if acq is None:  # failed before any command of the run's own, the open's vent included
            if self._opened:
                return ""
            return ("no pressure was applied: this run wrote nothing to the device, not even "
                    "the vent (its open failed), so the regulator holds what it held before (no "
                    "run on this bench is marked as having left a pressure)" + then)
        if acq.asked_bar > 0 or acq.highest_bar > below:
            return ""
        read = (f"the monitor read at most {max(acq.highest_bar, 0.0):.3f} bar"
                if math.isfinite(acq.measured_bar) else "nothing was read of the monitor")
        return (f"no pressure was applied: this run commanded none above 0 bar (0 bar was the "
                f"last command the device took) and {read}; its vent could not be confirmed "
                f"({check.problem or check.describe()})" + then)

    def _record(self, status: RunStatus, reason: str, problems: list[str], told,
                signal_name, signal_number) -> tuple[RunStatus, str]:
        """After the vent and the close: the books (observers closed, the bench marker, the
        run folder's final record, the marker let go or kept); ``told(problems)`` places
        ``vented`` among the problems. The final status and reason; never raises."""
        acq = self.acquisition
        for observer in self._observers:
            try:
                observer.close()
            except BaseException:  # a plot window gone: nothing to record
                pass
        for message in self.signals.said():  # after the vent: what the loop did not say
            self.notify(message)
        if self.signals.noted:  # signals during the stop: said, never obeyed mid-vent
            problems.append(f"{', '.join(dict.fromkeys(self.signals.noted))} received while "
                            "stopping: noted, the vent and the record went first")
        marker_problem = self._marker_books(acq)
        if marker_problem:
            problems.append(marker_problem)
        if self.recorder is not None:  # everything held reaches the disk before the outcome
            if not self.recorder.wait_written(DISK_NOTICE_S):
                self.notify(f"vented; the disk of {self.recorder.path} is not taking the record: "
                            f"{self.recorder.held_rows} samples are held in memory until it "
                            "does; mkm waits (signals are noted, not obeyed: killing it, kill -9 "
                            "or the Task Manager, loses them)")
                self.recorder.wait_written()
            problems.extend(self.recorder.refusals())
            if self.recorder.stuck_reason:  # the disk stopped the run
                self.storage_failed = True
        unverified = self.vent_check is not None and not self.vent_check.verified
        if unverified:
            status = RunStatus.FAILED
            held, commanded = self.vent_check.pressure_bar, False  # read after the vent
            if self.vent_check.unfollowed_bar is not None:  # the reading proves nothing
                held, commanded = self.vent_check.unfollowed_bar, True
            elif not held >= 0:  # nothing plausible read by the check, or no pressure
                held, commanded = acq.held_bar() if acq is not None else (0.0, True)
            problems.append(f"{self.vent_check.describe()}: VENT BY HAND (the regulator may "
                            f"still hold {self._held_said(held, commanded)})")
        problems = told(problems)
        if problems:
            reason = "; ".join([reason, *problems]) if reason else "; ".join(problems)
        if self.recorder is not None:
            meta = self.recorder.meta
            meta.stop_signal, meta.stop_signal_number = signal_name, signal_number
            meta.manual_vent_required = unverified
            meta.vent_check = self.vent_check.as_dict() if self.vent_check else None
            for problem in self.recorder.finish(status, reason):
                reason = f"{reason}; {problem}"
            # a sample not in samples.csv, a file not synced, run.json not written: the record
            # is not whole in its folder (a recorder's thread that failed, its rows all written
            # as the run ended, left it whole: said in the reason, the status the run's)
            self.storage_failed = self.storage_failed or not self.recorder.whole
        lease = self.lease
        hung = lease is not None and lease.lagging()  # said above: not waited for again
        refused = self.recorder is not None and self.recorder.outcome_refused
        if refused:  # run.json still says running: the marker keeps the outcome
            reason = f"{reason}; {self._keep_outcome(status, reason, unverified, hung)}"
        if lease is not None and not unverified and not refused:
            done = lease.wait(lease.post(lease.release), 0.0 if hung else STATE_WAIT_S)
            if not done and not hung:
                reason = (f"{reason}; the bench marker {lease.path} is not removed yet (the bench "
                          "state folder does not answer)")
            elif done and lease.error is not None:
                reason = (f"{reason}; the bench marker could not be removed "
                          f"({lease.error.strerror or lease.error})")
        elif lease is not None and unverified:  # kept: the next command vents first, says why
            what, unfollowed = self.vent_check.describe(), self.vent_check.unfollowed_bar
            if "monitor" not in self.vent_check.doubted:  # the check doubted the load cell
                unfollowed = None  # alone: the monitor's readings still stand
            # a failure leaves the marker naming the run and its last command
            done = lease.wait(lease.post(lambda: lease.unverified(what, unfollowed)),
                              0.0 if hung else STATE_WAIT_S)
            if done and lease.error is not None:
                reason = (f"{reason}; the bench marker {lease.path} could not record the vent "
                          f"not verified ({lease.error.strerror or lease.error}): it names the "
                          "run and its last command, and the next command on this bench vents "
                          "first")
        if lease is not None:  # its thread ends after the last update (one that hangs: later)
            lease.end()
        return status, reason

    def _held_said(self, held_bar: float, commanded: bool) -> str:
        """What the regulator may still hold [bar], in words: ``held_bar``, or, when that is a
        command (``commanded``) the monitor read more than before the vent, beyond its declared
        error (an overshoot, a regulator that went on rising), that reading with the command
        beside it: a limit is watched on what is measured."""
        before = self.acquisition.before_vent() if self.acquisition is not None else None
        reg = self.config.regulator
        offset_bar, gain = reg.reading_bounds()
        error_bar = offset_bar + gain * held_bar if reg.monitor_components \
            else reg.monitor_accuracy_bar
        if commanded and before is not None and before[0] > held_bar + error_bar:
            return (f"{before[0]:.3g} bar, as the monitor read before the vent, with "
                    f"{held_bar:.3g} bar commanded")
        return f"{held_bar:.3g} bar"

    def _keep_outcome(self, status: RunStatus, reason: str, unverified: bool,
                      hung: bool) -> str:
        """The final run.json was refused (a full disk, no permission): the bench marker keeps
        the whole record it was to hold (the gaps found since its last write, the vent check,
        the signal...), and the next command on the bench writes it into run.json
        (:func:`mkm.bench.unvented.mend_run`); what became of it, in words."""
        lease, meta = self.lease, self.recorder.meta
        left = "run.json still says running"
        if lease is None:
            return f"{left}: no bench marker could keep the outcome"
        outcome = {**meta.as_dict(), "status": str(status), "reason": reason,
                   "manual_vent_required": unverified}
        done = lease.wait(lease.post(lambda: lease.ended(outcome)),
                          0.0 if hung else STATE_WAIT_S)
        if done and lease.error is None:
            return (f"{left}: the outcome is kept in the bench marker {lease.path}, and the "
                    "next command on this bench writes it there")
        why = (f"could not be written ({lease.error.strerror or lease.error})" if done
               else "is not written yet (the bench state folder does not answer)")
        return (f"{left}: the bench marker {lease.path} that keeps the outcome {why}; the "
                "next command on this bench marks the run killed")

    def _marker_books(self, acq: Acquisition | None) -> str:
        """After the vent: whether the bench marker caught up with the run's commands (the
        lease writes it on a thread of its own, :class:`mkm.bench.unvented.BenchLease`),
        waiting at most :data:`STATE_WAIT_S` for a state folder that hangs; the problem, or
        ""."""
        lease = self.lease
        if lease is None:
            return ""
        if not lease.wait(lease.posted, STATE_WAIT_S):
            return (f"the bench state folder did not take the bench marker {lease.path} within "
                    f"{STATE_WAIT_S:g} s (it hangs): the marker left names this run, and the "
                    "next command on this bench vents first")
        if lease.error is not None:  # the vent went through; the state folder did not
            return (f"the bench marker {lease.path} could not be updated "
                    f"({lease.error.strerror or lease.error})")
        if acq is not None and acq.marker_lagged:
            return ("the bench state folder was slow: pressures were commanded before the bench "
                    "marker recorded them")
        return ""


def make_backend(config: BenchConfig, clock: str = "virtual") -> Backend:
    """The backend of ``config.daq.backend`` (:mod:`mkm.bench.backends`), not yet opened."""
    return backends.entry(config.daq.backend).factory(config, clock)


def make_operator(config: BenchConfig, backend: Backend) -> Operator:
    """The operator's actions: on the simulated bench itself, else asked on the terminal."""
    from mkm.bench.operator import ConsoleOperator, SimOperator

    return SimOperator(backend) if config.simulated else ConsoleOperator()


def with_backend(config: BenchConfig, backend: str | None) -> BenchConfig:
    """``config`` with ``daq.backend`` set to ``backend`` (validated again), if given."""
    if backend is None or backend == config.daq.backend:
        return config
    return config.replace(daq={"backend": backend})


def acquire(config: BenchConfig, backend: str | None = None, clock: str = "virtual",
            out_root: str | Path = "data/experimental", progress: bool = False,
            plot: bool = False, notify=None, allow_past_lock: bool = False,
            command: str = "acquire", ceiling: ForceCeiling | None = None) -> RunResult:
    """Record one run of ``config`` under ``out_root``.

    ``backend`` overrides ``config.daq.backend``. A muscle held past its braid lock is refused
    (``ValueError``) unless ``allow_past_lock``; a load cell the wrong size for the muscle, or
    a muscle outside the practical range, is said (:func:`mkm.bench.preflight.warnings`).
    ``notify`` receives the operator's lines (default: stderr, ``mkm <command>: ...``, with
    ``command`` the command the user ran). ``ceiling``: the most the muscle ``mkm identify``
    identified pulls (:func:`mkm.identify.band.config_ceiling`), which arms the over-force
    interlock (:meth:`mkm.bench.worker.Acquisition.overforce`); required where
    ``safety.calibration`` names one (the bench cannot read an identification itself), and a
    plan whose top step the identified muscle must pull past the force interlock at is
    refused (:func:`mkm.bench.preflight.ceiling_lines`); both ``ValueError``, nothing
    pressurised.
    """
    config = with_backend(config, backend)
    lock = braid_lock(config, ceiling)
    if lock and not allow_past_lock:
        raise ValueError(f"{lock}: pass --allow-past-lock to record it anyway")
    if ceiling is None and config.safety.calibration is not None:
        raise ValueError(f"config {config.source}: safety.calibration="
                         f"{config.safety.calibration!r} arms the over-force interlock: pass "
                         "its ceiling (ceiling=mkm.identify.band.config_ceiling(config)), as "
                         "`mkm acquire` does")
    if ceiling is not None and (refusal := ceiling_lines(config, ceiling)[1]):
        raise ValueError(f"{refusal}; nothing was pressurised")
    for warning in warnings(config):
        (notify or StderrNotice(command))(f"warning: {warning}")
    check_out_root(out_root)  # before the device is opened
    device = make_backend(config, clock)
    operator = None if config.regulator.electronic else make_operator(config, device)
    return BenchRun(config, device, out_root, operator=operator, progress=progress,
                    plot=plot, notify=notify, command=command, ceiling=ceiling).execute()
