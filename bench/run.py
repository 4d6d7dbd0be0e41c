"""A bench run: startup, execute, shutdown (pymeasure's procedure lifecycle).

:class:`BenchRun` joins three parts: the procedure (:class:`mkm.bench.sequence.Staircase`: tare,
pre-conditioning, steps), the worker (:class:`mkm.bench.worker.Acquisition`: the acquisition loop
and
its interlocks) and the recorder (:class:`mkm.bench.recorder.Recorder`: the run folder and its
:class:`mkm.bench.storage.RunMeta`). Everything goes to the run folder while it happens.

Safety, in every exit path:

- a bench left pressurised by a run that died without venting is vented first, and said
  (:mod:`mkm.bench.unvented`);
- the pressure command is clamped to ``regulator.max_pressure_bar``; the force and pressure
  interlocks stop the run (:mod:`mkm.bench.worker`);
- the first Ctrl-C stops at the next block boundary (0.1 s at the default one-sample blocks);
  a second Ctrl-C, SIGTERM, SIGHUP, SIGBREAK or a closed Windows console stop at once
  (:mod:`mkm.bench.signals`); either way, and on any error, ``shutdown`` commands the vent, closes
  the
  device, then records the truth in run.json. A failed vent asks for a vent by hand.

The exit status of ``mkm acquire`` is :attr:`RunResult.exit_code`: 0 complete, 3 complete with
lost samples, 128 + N after signal N, 2 when the run's storage failed (disk full), 1 otherwise.
"""

from __future__ import annotations

import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

from mkm.bench.backend import Backend, BenchError
from mkm.bench.config import BenchConfig
from mkm.bench.operator import Operator
from mkm.bench.recorder import Recorder
from mkm.bench.sequence import Staircase, estimate_duration_s, plan_steps
from mkm.bench.signals import StopSignal, StopSignals
from mkm.bench.storage import RunStatus
from mkm.bench.unvented import BenchLease, Marker, vent_unvented
from mkm.bench.worker import Acquisition, Stop

EXIT_OK, EXIT_FAILED, EXIT_STORAGE, EXIT_GAPS = 0, 1, 2, 3


def notify_stderr(message: str) -> None:
    """One line for the operator on stderr (the default ``notify`` of runs and procedures)."""
    print(f"mkm: {message}", file=sys.stderr, flush=True)


@dataclass
class RunResult:
    """Outcome of a run; ``path`` is None when it failed before its folder was made."""

    path: Path | None
    status: RunStatus
    reason: str
    exit_code: int = EXIT_FAILED
    manual_vent_required: bool = False
    unvented_before: list[Marker] = field(default_factory=list)


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
    """tqdm bar on stderr: set and measured pressure, force, a lower bound of the time left."""

    def __init__(self, config: BenchConfig, n_steps: int):
        from tqdm import tqdm

        self.config, self.n_steps, self.done = config, n_steps, 0
        self.bar = tqdm(total=n_steps, unit="step", desc="acquire", leave=True)
        self.shown_at = 0.0

    def block(self, rows) -> None:
        if not rows or time.monotonic() - self.shown_at < 0.25:
            return
        row, st = rows[-1], self.config.settle
        left_s = (self.n_steps - self.done) * (st.min_dwell_s + st.hold_s)
        self.bar.set_postfix_str(f"{row.phase} {row.set_pressure_bar:.2f} bar, measured "
                                 f"{row.pressure_bar:.2f} bar, {row.force_N:.1f} N, "
                                 f">= {left_s / 60:.1f} min left")
        self.shown_at = time.monotonic()

    def step(self, _step) -> None:
        self.done += 1
        self.bar.update(1)

    def close(self) -> None:
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


class BenchRun:
    """One run on ``backend`` with ``config``, recorded under ``out_root``.

    ``operator`` is needed only for a manual regulator. ``progress`` shows a tqdm bar on stderr;
    ``plot`` a live plot in another process. ``handle_signals`` installs the stop handlers of
    :mod:`mkm.bench.signals` (only possible in the main thread). ``notify`` receives one-line
    messages for the operator (a bench found unvented, a stop requested).
    """

    def __init__(self, config: BenchConfig, backend: Backend, out_root: str | Path,
                 operator: Operator | None = None, progress: bool = False, plot: bool = False,
                 handle_signals: bool = True, notify=notify_stderr):
        if not config.regulator.electronic and operator is None:
            raise ValueError("regulator.kind='manual' needs an operator to set the pressure")
        self.config = config
        self.backend = backend
        self.out_root = check_out_root(out_root)
        self.operator = operator
        self.progress = progress
        self.plot = plot
        self.notify = notify
        self.handle_signals = handle_signals
        self.signals = StopSignals(on_first_interrupt=lambda: self.notify(
            "stopping at the next safe point (Ctrl-C again to vent now)"))
        self.steps = plan_steps(config)
        self.recorder: Recorder | None = None
        self.acquisition: Acquisition | None = None
        self.lease: BenchLease | None = None
        self.unvented: list[Marker] = []
        self._observers: list = []

    def request_stop(self) -> None:
        """What the first Ctrl-C does: stop at the next safe point."""
        if self.signals.stop_requested_at is None:
            self.signals.stop_requested_at = time.monotonic()

    def _stop_time(self):
        return self.signals.signal_at or self.signals.stop_requested_at

    # lifecycle -------------------------------------------------------------------------------

    def execute(self) -> RunResult:
        """Run the whole sequence; the run folder holds the truth whatever happens."""
        if self.handle_signals:
            with self.signals:
                return self._execute()
        return self._execute()

    def _execute(self) -> RunResult:
        status, reason, error, exit_code = RunStatus.FAILED, "", None, EXIT_FAILED
        signal_name = signal_number = None
        try:
            self.startup()
            Staircase(self.config, self.acquisition, self.operator, self._on_step).run()
            status, reason, exit_code = self._finished()
        except Stop as stop:
            status, reason = stop.status, stop.reason
            signal_name, signal_number = stop.signal_name, stop.signal_number
        except StopSignal as sig:
            status, signal_name, signal_number = RunStatus.ABORTED, sig.name, sig.signum
            reason = f"stopped by {sig}: vented at once"
        except KeyboardInterrupt:  # the handlers were not installed (not the main thread)
            status, signal_name, signal_number = RunStatus.ABORTED, "SIGINT", 2
            reason = "stopped by a second Ctrl-C (SIGINT): vented at once"
        except BenchError as exc:
            reason = f"{type(exc).__name__}: {exc}"
        except OSError as exc:  # the run folder's disk: full, gone, read-only
            reason, exit_code = f"recording failed ({type(exc).__name__}: {exc})", EXIT_STORAGE
        except BaseException as exc:
            reason, error = f"{type(exc).__name__}: {exc}", exc
        finally:
            self.signals.hold()  # a further signal must not cut the vent or the record
            reason = self.shutdown(status, reason, signal_name, signal_number)
            self.signals.done()
        if signal_number is not None:
            exit_code = 128 + signal_number
        if error is not None:
            raise error
        meta = self.recorder.meta if self.recorder else None
        return RunResult(self.recorder.path if self.recorder else None, status, reason,
                         exit_code, bool(meta and meta.manual_vent_required), self.unvented)

    def _finished(self) -> tuple[RunStatus, str, int]:
        meta, n = self.recorder.meta, len(self.steps)
        if not meta.gaps:
            return RunStatus.COMPLETE, f"all {n} steps done", EXIT_OK
        spans = ", ".join(f"{g.start_s:g}-{g.end_s:g} s" for g in meta.gaps)
        return (RunStatus.COMPLETE_WITH_GAPS, f"all {n} steps done, but {meta.lost_samples} "
                f"samples were lost in {len(meta.gaps)} gap(s): {spans}", EXIT_GAPS)

    def startup(self) -> None:
        info = self.backend.open()  # writes the vent command first
        self.unvented = vent_unvented(self.backend)
        for marker in self.unvented:
            self.notify(f"{marker.describe()}: vented now")
        self.recorder = Recorder(self.out_root, self.config, info, len(self.steps),
                                 estimate_duration_s(self.config),
                                 [vars(m) for m in self.unvented])
        self.lease = BenchLease(getattr(self.backend, "bench_key", "unknown"),
                                self.recorder.path, self.recorder.meta.started_utc)
        if self.progress:
            self._observers.append(_Progress(self.config, len(self.steps)))
        if self.plot:
            self._observers.append(_Plot(self.config.muscle.id))
        self.acquisition = Acquisition(
            self.config, self.backend, self.recorder,
            stop_requested=lambda: self.signals.stop_requested_at, stop_time=self._stop_time,
            lease=self.lease, observers=self._observers)
        self.acquisition.command(0.0, "vent")
        self.backend.start()

    def _on_step(self, step) -> None:
        for observer in self._observers:
            if hasattr(observer, "step"):
                observer.step(step)

    def shutdown(self, status: RunStatus, reason: str, signal_name=None,
                 signal_number=None) -> str:
        """Vent, close the device, record the outcome. Never raises; returns the final reason."""
        problems = []
        acq = self.acquisition
        vented = False
        try:
            if acq is not None:
                acq.command(0.0, "vent")
            else:
                self.backend.write_command(0.0)
            vented = True
        except BaseException as exc:  # the device may be gone; closing must still happen
            problems.append(f"vent command failed ({type(exc).__name__}: {exc})")
            vented = acq is not None and acq.vented  # the command was written, only its log failed
        if self.operator is not None and not self.config.regulator.electronic:
            try:
                self.operator.vent()
            except BaseException as exc:
                problems.append(f"operator vent not confirmed ({type(exc).__name__})")
        try:
            self.backend.close()
        except BaseException as exc:
            problems.append(f"closing the device failed ({type(exc).__name__}: {exc})")
        for observer in self._observers:
            observer.close()
        last_bar = acq.command_bar if acq is not None else 0.0
        if not vented and self.config.regulator.electronic:
            problems.append(f"VENT BY HAND: the regulator may still hold {last_bar:g} bar")
        if problems:
            reason = "; ".join([reason, *problems]) if reason else "; ".join(problems)
        if self.recorder is not None:
            meta = self.recorder.meta
            meta.stop_signal, meta.stop_signal_number = signal_name, signal_number
            meta.manual_vent_required = not vented and self.config.regulator.electronic
            for problem in self.recorder.finish(status, reason):
                reason = f"{reason}; {problem}"
        if self.lease is not None and (vented or not self.config.regulator.electronic):
            self.lease.release()  # else the marker stays: the next command on it vents first
        return reason


def make_backend(config: BenchConfig, backend: str = "sim", clock: str = "virtual") -> Backend:
    """The simulated (``sim``) or NI (``ni``) backend for ``config``."""
    if backend == "sim":
        from mkm.bench.sim import SimBackend

        return SimBackend(config, clock=clock)
    if backend == "ni":
        from mkm.bench.ni import NIBackend

        return NIBackend(config)
    raise ValueError(f"backend={backend!r} is invalid: expected 'sim' or 'ni'")


def make_operator(backend: Backend) -> Operator:
    from mkm.bench.operator import ConsoleOperator, SimOperator
    from mkm.bench.sim import SimBackend

    return SimOperator(backend) if isinstance(backend, SimBackend) else ConsoleOperator()


def acquire(config: BenchConfig, backend: str = "sim", clock: str = "virtual",
            out_root: str | Path = "data/experimental", progress: bool = False,
            plot: bool = False, notify=notify_stderr) -> RunResult:
    """Record one run of ``config`` on the ``backend`` ("sim" or "ni") under ``out_root``."""
    check_out_root(out_root)  # before the device is opened
    device = make_backend(config, backend, clock)
    operator = None if config.regulator.electronic else make_operator(device)
    return BenchRun(config, device, out_root, operator=operator, progress=progress,
                    plot=plot, notify=notify).execute()
