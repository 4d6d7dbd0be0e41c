"""Signals that must never leave the muscle pressurised: every one of them vents at once.

The USB-6001's analog output keeps its last value after the process ends, so an electronic
regulator holds the last commanded pressure until something commands it again. While a run
goes, :class:`StopSignals` handles:

- the first ``SIGINT`` (Ctrl-C): stop at the next block boundary (a safe point);
- a second ``SIGINT``, ``SIGTERM`` (kill, service stop), ``SIGHUP`` (terminal or SSH session
  closed; POSIX), ``SIGBREAK`` (Ctrl-Break; Windows), and every other signal that would end
  the process while it keeps its default action (:data:`ENDING_SIGNAL_NAMES`: ``SIGQUIT`` from
  Ctrl-\\, ``SIGUSR1``, ``SIGALRM``, ``SIGXCPU``, ``SIGABRT``, ``SIGTRAP``, ``SIGSYS`` sent
  with kill, ...; POSIX; and :data:`REALTIME_SIGNALS`):
  raise :class:`StopSignal` at once, which unwinds to the run's shutdown: vent, close the
  device, record. The exit status is 128 + N. Once it is raised, a further signal is only
  noted (the run's reason names it): nothing cuts the vent or the record;
- ``SIGTSTP`` (Ctrl-Z; POSIX) is refused and said (:data:`SUSPEND_SIGNAL`): a suspended run
  would hold its pressure with no interlock watching; ``SIGTTOU`` and ``SIGTTIN``, which stop a
  run in the background that writes to or reads from its terminal, are ignored
  (:data:`BACKGROUND_SIGNALS`);
- on Windows, closing the console window arrives as a console control event
  (``CTRL_CLOSE_EVENT``, ``SetConsoleCtrlHandler``), not as a signal, on a thread Windows makes
  for it: the handler turns it into ``SIGBREAK`` in the main thread and holds the process until
  the run has vented and recorded. Windows ends the process when the handler returns and at the
  latest 5 s after the event, so the run's shutdown has a grace deadline
  (:meth:`StopSignals.grace_deadline`): vent, write run.json with why it stopped, sync the rows,
  verify the vent with what time is left, close the device, record. ``CTRL_LOGOFF_EVENT`` and
  ``CTRL_SHUTDOWN_EVENT`` are handled the same, but Windows sends them to services only: an
  interactive console program is ended at log-off without notice (its bench marker then makes
  the next command vent, :mod:`mkm.bench.unvented`).

A fault in a driver or an extension (``SIGSEGV``, ``SIGBUS``, ``SIGFPE``, ``SIGILL``) ends the
process whatever a handler does; while a run goes, :func:`fatal_trace` has :mod:`faulthandler`
write the faulting thread's trace into the run folder as it ends, and the next command on the bench,
which vents first, names the error and the file (:func:`fatal_error`).

Only the signals this platform has are touched (``hasattr(signal, name)``), and the console
handler is installed only on Windows (:data:`WINDOWS`).
"""

from __future__ import annotations

import faulthandler
import signal
import sys
import threading
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path

STOP_SIGNAL_NAMES = ("SIGINT", "SIGTERM", "SIGHUP", "SIGBREAK")
STOP_SIGNALS = tuple(getattr(signal, n) for n in STOP_SIGNAL_NAMES if hasattr(signal, n))
#: the other signals whose default action ends the process (Ctrl-\ sends SIGQUIT; SIGABRT,
#: SIGTRAP and SIGSYS sent with kill; POSIX: Windows has SIGABRT, but its kill ends a process
#: with no signal to handle): stop signals too while they keep that default (one a profiler or
#: a test timer handles is left to it; faulthandler's dump of SIGABRT, which Python sees as the
#: default, is not). An abort() still ends the process once the handler returns (C's abort
#: restores the default and raises again), the bench marker making the next command vent.
#: SIGSEGV, SIGBUS, SIGFPE and SIGILL are left alone: raised by a fault, the faulting
#: instruction would run again after a handler, in a loop that holds the pressure.
ENDING_SIGNAL_NAMES = ("SIGQUIT", "SIGUSR1", "SIGUSR2", "SIGALRM", "SIGXCPU", "SIGVTALRM",
                       "SIGPROF", "SIGPWR", "SIGSTKFLT", "SIGIO", "SIGABRT", "SIGTRAP", "SIGSYS",
                       "SIGEMT")
#: the real-time signals (POSIX; Linux: ``kill -s RTMIN+1``), whose default action ends the
#: process too: stop signals as well
REALTIME_SIGNALS = (tuple(range(signal.SIGRTMIN, signal.SIGRTMAX + 1))
                    if hasattr(signal, "SIGRTMIN") else ())
ENDING_SIGNALS = (*(getattr(signal, n) for n in ENDING_SIGNAL_NAMES if hasattr(signal, n)),
                  *REALTIME_SIGNALS)
#: Ctrl-Z (POSIX): a run it suspended would hold its pressure with no interlock watching, for as
#: long as it stays suspended; refused while a run goes, and said
SUSPEND_SIGNAL = getattr(signal, "SIGTSTP", None)
#: a run in the background that writes to (or reads from) its terminal is stopped by these
#: (POSIX; ``stty tostop``): ignored while a run goes, its lines are written (its reads fail)
BACKGROUND_SIGNALS = tuple(getattr(signal, n) for n in ("SIGTTOU", "SIGTTIN")
                           if hasattr(signal, n))

#: the file of a run folder that faulthandler writes the trace of a fatal error into
#: (:func:`fatal_trace`), removed when the run ends without one
FATAL_TRACE_FILE = "fatal-error.txt"
#: the fatal signals by the words faulthandler heads their trace with
FATAL_WORDS = {"Segmentation fault": "SIGSEGV", "Bus error": "SIGBUS",
               "Floating point exception": "SIGFPE", "Illegal instruction": "SIGILL",
               "Aborted": "SIGABRT"}

#: what the first Ctrl-C and a refused Ctrl-Z say (:meth:`StopSignals.said`)
FIRST_INTERRUPT = "stopping at the next safe point (Ctrl-C again to vent now)"
SUSPEND_REFUSED = ("Ctrl-Z does not suspend a run: suspended, it would hold the regulator's "
                   "pressure with no interlock watching; Ctrl-C stops it at a safe point, vented")

# Windows console control events (wincon.h) and how long Windows waits for the handler.
CTRL_C_EVENT, CTRL_BREAK_EVENT, CTRL_CLOSE_EVENT = 0, 1, 2
CTRL_LOGOFF_EVENT, CTRL_SHUTDOWN_EVENT = 5, 6
CONSOLE_EVENTS = {CTRL_CLOSE_EVENT: "console closed", CTRL_LOGOFF_EVENT: "log-off",
                  CTRL_SHUTDOWN_EVENT: "system shutdown"}
CONSOLE_HOLD_S = 4.5  # Windows kills the process 5 s after CTRL_CLOSE_EVENT
#: Of the hold, what the last steps keep back [s]: closing the device and writing run.json with
#: its files synced take milliseconds on the bench PC; half a second leaves room for a slow disk.
CONSOLE_RECORD_S = 0.5
WINDOWS = sys.platform == "win32"
#: Set by the ``mkm`` console entry point, which exits once the command returns: a run's stop
#: signals then stay ignored after it is recorded, since a signal there would end the process
#: with 128 + N while run.json says how the run really ended. In-process callers keep theirs.
LINGER = False


def signal_name(signum: int) -> str:
    """The signal's name as ``kill -l`` gives it (``SIGTERM``; ``SIGRTMIN+1`` for a real-time
    signal, which has none of its own)."""
    try:
        return signal.Signals(signum).name
    except ValueError:
        return f"SIGRTMIN+{signum - signal.SIGRTMIN}"


class StopSignal(BaseException):
    """A signal that stops the run at once (a ``BaseException``: nothing may swallow it)."""

    def __init__(self, signum: int, detail: str = ""):
        self.signum = int(signum)
        self.name = signal_name(signum)
        self.detail = detail
        super().__init__(f"{self.name} ({detail})" if detail else self.name)

    @property
    def exit_code(self) -> int:
        return 128 + self.signum


class StopSignals:
    """Install the stop handlers for the duration of a ``with`` block (main thread only).

    ``stop_requested_at`` is the ``time.monotonic()`` of the first Ctrl-C (None before), and
    ``signal_at`` that of the stop signal raised. Once a stop signal has been raised (or held
    for the end of a block), and after :meth:`hold`, a further signal is only noted in
    ``noted``: nothing interrupts the vent and the record; :meth:`done` releases a held Windows
    console handler.
    ``linger`` (default :data:`LINGER`): the stop signals stay ignored after the block.
    """

    def __init__(self, interrupt_main: Callable[[int], None] | None = None,
                 linger: bool | None = None):
        self.linger = LINGER if linger is None else linger
        # what the handlers have to say to the operator, said by the run (:meth:`said`): a
        # handler never writes, since the write it interrupted may hold the lock its own would
        # wait for, in the one thread that runs the interlocks
        self.notices: list[str] = []
        self.stop_requested_at: float | None = None
        self.signal_at: float | None = None
        self.console_event: str | None = None
        self.console_event_at: float | None = None
        self._previous: dict[int, object] = {}
        self._finished = threading.Event()
        self._console_callback = None
        self._interrupt_main = interrupt_main
        self.active = False
        self._deferring = False
        self._deferred: StopSignal | None = None
        # set as the first stop signal is raised (or held for a block's end), and by hold():
        # the stop has begun, and every later signal is noted here, never raised
        self.stopping = False
        self.noted: list[str] = []

    def __enter__(self) -> StopSignals:
        if threading.current_thread() is not threading.main_thread():
            return self  # signal handlers can only be installed in the main thread
        for signum in STOP_SIGNALS:
            self._previous[signum] = signal.signal(signum, self._handle)
        for signum in ENDING_SIGNALS:
            if signal.getsignal(signum) == signal.SIG_DFL:
                self._previous[signum] = signal.signal(signum, self._handle)
        if SUSPEND_SIGNAL is not None and signal.getsignal(SUSPEND_SIGNAL) == signal.SIG_DFL:
            self._previous[SUSPEND_SIGNAL] = signal.signal(SUSPEND_SIGNAL, self._refuse_suspend)
        for signum in BACKGROUND_SIGNALS:
            if signal.getsignal(signum) == signal.SIG_DFL:
                self._previous[signum] = signal.signal(signum, signal.SIG_IGN)
        if WINDOWS:
            self._install_console_handler()
        self.active = True
        return self

    def __exit__(self, *exc) -> None:
        self.done()
        for signum, handler in self._previous.items():
            signal.signal(signum, signal.SIG_IGN if self.linger else handler)
        self._previous.clear()
        if self._console_callback is not None:
            import ctypes

            ctypes.windll.kernel32.SetConsoleCtrlHandler(self._console_callback, False)
            self._console_callback = None
        self.active = False

    def _refuse_suspend(self, signum, frame) -> None:
        self.notices.append(SUSPEND_REFUSED)

    def said(self) -> Iterator[str]:
        """The handlers' notices not yet said, oldest first (taken from the list one at a
        time: a handler may add one meanwhile)."""
        while self.notices:
            yield self.notices.pop(0)

    def _handle(self, signum, frame) -> None:
        if self.stopping:  # a stop is under way: this one cannot cut its vent or its record
            self.noted.append(signal_name(signum))
            return
        now = time.monotonic()
        if signum == signal.SIGINT and self.stop_requested_at is None:
            self.stop_requested_at = now
            self.notices.append(FIRST_INTERRUPT)
            return
        self.signal_at = now
        detail = "second Ctrl-C" if signum == signal.SIGINT else (self.console_event or "")
        self.stopping = True  # from here on, a further signal is only noted
        if self._deferring:
            self._deferred = StopSignal(signum, detail)
            return
        raise StopSignal(signum, detail)

    @contextmanager
    def deferred(self) -> Iterator[None]:
        """Hold a stop signal that arrives inside until the block ends, then raise it.

        For a block read from the device and its recording: a signal raised between the two
        would lose samples the device no longer holds. The delay is the block's own: a DAQmx
        read blocks in C, where no Python handler runs anyway. Inside another such block it
        holds nothing of its own: the outer one raises at its end.
        """
        if self._deferring:
            yield
            return
        self._deferring = True
        try:
            yield
        finally:
            self._deferring = False
            stop, self._deferred = self._deferred, None
            if stop is not None:
                raise stop

    def hold(self) -> None:
        """From now on a stop signal is only noted (the shutdown must not be cut)."""
        self.stopping = True

    def done(self) -> None:
        self._finished.set()

    def grace_deadline(self) -> float | None:
        """The ``time.monotonic()`` by which the vent check must end so that the run is
        recorded before Windows ends the process (a console closed); None without a console
        event: nothing bounds the shutdown then."""
        if self.console_event_at is None:
            return None
        return self.console_event_at + CONSOLE_HOLD_S - CONSOLE_RECORD_S

    # Windows console control events ----------------------------------------------------------

    def on_console_event(self, event: int) -> bool:
        """Handle one console control event; True means handled (Windows then ends the process
        when this returns, so it returns only once the run has vented and recorded)."""
        if event not in CONSOLE_EVENTS:
            return False  # Ctrl-C and Ctrl-Break: Python raises SIGINT and SIGBREAK itself
        self.console_event_at = time.monotonic()
        self.console_event = CONSOLE_EVENTS[event]
        interrupt = self._interrupt_main
        if interrupt is None:
            import _thread

            interrupt = _thread.interrupt_main
        interrupt(getattr(signal, "SIGBREAK", signal.SIGTERM))
        self._finished.wait(CONSOLE_HOLD_S)
        return True

    def _install_console_handler(self) -> None:
        import ctypes
        from ctypes import wintypes

        handler_type = ctypes.WINFUNCTYPE(wintypes.BOOL, wintypes.DWORD)
        self._console_callback = handler_type(lambda event: bool(self.on_console_event(event)))
        if not ctypes.windll.kernel32.SetConsoleCtrlHandler(self._console_callback, True):
            self._console_callback = None


def _keep_python_handlers() -> None:
    """Give the signals faulthandler also takes (SIGABRT) back to the Python handler the run
    installed: faulthandler's would dump and end the process where a stop signal vents."""
    for signum in ENDING_SIGNALS:
        handler = signal.getsignal(signum)
        if callable(handler):
            signal.signal(signum, handler)


@contextmanager
def fatal_trace(folder: Path) -> Iterator[None]:
    """While the block runs, a fatal error (SIGSEGV, SIGBUS, SIGFPE, SIGILL, which a fault in a
    driver or an extension raises and no handler survives) writes the Python trace of the
    thread that faulted into ``folder``/:data:`FATAL_TRACE_FILE` (:mod:`faulthandler`) as the
    process ends (not every thread's: walking the other threads' frames while they run
    faulted again on half the test's runs, the process then dying of SIGSEGV);
    the next command on the bench vents and names it (:func:`fatal_error`). The file is
    removed after a block that ended without one; faulthandler is given back as it was (to
    stderr where it was on). Main thread only; a folder that refuses the file is run without."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    path = Path(folder) / FATAL_TRACE_FILE
    try:
        file = open(path, "w", encoding="utf-8")  # held open for the block: faulthandler's
    except OSError:
        yield
        return
    enabled = faulthandler.is_enabled()
    faulthandler.enable(file, all_threads=False)
    _keep_python_handlers()
    try:
        yield
    finally:
        faulthandler.disable()
        stderr = sys.__stderr__
        if enabled and stderr is not None:
            try:
                faulthandler.enable(stderr, all_threads=True)
            except (ValueError, OSError, AttributeError):  # no file descriptor of its own
                pass
        _keep_python_handlers()
        file.close()
        try:
            if path.stat().st_size == 0:
                path.unlink()
        except OSError:
            pass


def fatal_error(folder: Path) -> str:
    """What the fatal error that ended a run's process was, from the trace
    :func:`fatal_trace` left in its ``folder`` (``Segmentation fault, SIGSEGV``), or "" when it
    left none."""
    path = Path(folder) / FATAL_TRACE_FILE
    try:
        with open(path, encoding="utf-8", errors="replace") as file:
            first = file.readline(200).strip()
    except OSError:
        return ""
    if not first:
        return ""
    words = first.removeprefix("Fatal Python error: ")
    name = FATAL_WORDS.get(words)
    return f"{words}, {name}" if name else words

