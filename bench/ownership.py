"""One owner per bench: a lock per device, held by a run (or a tare, a calibration, a check)
from before the device is opened until after it is closed.

Two processes driving one regulator is the most dangerous state a bench can be in, so a second
command on a held bench refuses at once, naming the holder's pid, command and start time
(:class:`BenchBusy`). ``mkm vent`` on a held bench does not fight the holder for the device: it
asks the holder to stop (:func:`request_stop`; the run polls :meth:`BenchOwner.stop_request` at
every block, which reads the request on a thread of its own, and stops at that safe point,
venting), waits for the lock, then vents and verifies
itself. The operating system releases the lock when its process dies (``kill -9``), so a dead
holder never blocks the bench: the next command takes the lock and vents first
(:mod:`mkm.bench.unvented`).

The lock (``filelock``, portable to Windows) and two small files live in the bench state
folder (:func:`mkm.bench.unvented.state_dir`), keyed by the physical bench (the backend and the
device's serial number on NI, else its name as NI-DAQmx compares it, case folded):
``<bench>.lock``, ``<bench>.owner`` (who holds it) and ``<bench>.stop`` (a stop request).
"""

from __future__ import annotations

import json
import os
import threading
import time
from pathlib import Path

import filelock

from mkm.bench.backend import BenchError
from mkm.bench.storage import ProcessIdentity
from mkm.bench.unvented import (
    STATE_START_S,
    STATE_WAIT_S,
    Marker,
    StateFolderThread,
    bench_folder,
    find_unvented,
    state_dir,
)
from mkm.core.records import provenance, write_atomic


class BenchBusy(BenchError):
    """Another live process holds the bench."""


class StateFolderBroken(BenchError):
    """The bench state folder cannot be used (read-only, full, a lock that is not a file):
    the bookkeeping fails, the vent must not."""


def _usable_lock(lock_path: Path) -> None:
    """:class:`StateFolderBroken` when ``lock_path`` exists but is not a file (a folder, a
    FIFO): no lock can be taken there, and on Windows taking it would wait instead of fail."""
    if (lock_path.exists() or lock_path.is_symlink()) and not lock_path.is_file():
        raise StateFolderBroken(f"the bench lock {lock_path} is not a file: remove it")


def _paths(bench_key: str, state: Path) -> tuple[Path, Path, Path]:
    base = bench_folder(bench_key, state)
    return (base.with_name(base.name + ".lock"), base.with_name(base.name + ".owner"),
            base.with_name(base.name + ".stop"))


def holder(owner: Path) -> dict | None:
    """What the holder of a bench recorded in its ``owner`` file (pid, command, start), if
    readable."""
    try:
        data = json.loads(owner.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    return data if isinstance(data, dict) else None


def describe_holder(bench_key: str, owner: Path) -> str:
    info = holder(owner)
    if not info:
        return f"bench {bench_key} is held by another process (it left no details)"
    return (f"bench {bench_key} is in use by pid {info.get('pid')} (`mkm {info.get('command')}`"
            f", started {info.get('started_utc')})")


class BenchOwner:
    """The lock of one bench, held in a ``with`` block; :class:`BenchBusy` if someone has it."""

    def __init__(self, bench_key: str, command: str):
        self.bench_key, self.command = bench_key, command
        # resolved now: the state folder's thread may run late, after MKM_STATE_DIR moved
        self.state = state_dir()
        self.lock_path, self.owner_path, self.stop_path = _paths(bench_key, self.state)
        self.lock: filelock.BaseFileLock | None = None
        self._polling = threading.Condition()
        self._poll_thread: threading.Thread | None = None
        self._stop_by: str | None = None  # who asked, as the last read of the stop file found
        self._read_wanted = False  # the loop asked for a read since the last one began
        # the lock is taken and let go by a thread of its own (filelock's are per thread): a
        # state folder that hangs holds it, never the command
        self._state = StateFolderThread("mkm-bench-owner")
        self.problem = ""  # the state folder did not let the bench go in time
        self._hung = False  # the state folder hung, said when found: not waited for again

    def __enter__(self) -> BenchOwner:
        """Take the bench; the state folder is waited for at most :data:`STATE_START_S`
        (:class:`StateFolderBroken` after it: nothing was touched)."""
        done, taken = self._state.call(self._take, STATE_START_S)
        if not done:
            self._hung = True
            self._state.post(self._let_go)  # once it answers: the lock taken meanwhile goes
            self._state.end()
            raise StateFolderBroken(f"the bench state folder {self.lock_path.parent} did not "
                                    f"answer within {STATE_START_S:g} s (it hangs): nothing was "
                                    "touched")
        if isinstance(taken, BaseException):  # not taken: nothing for the thread to keep
            self._state.end()
            raise taken
        return self

    def _take(self) -> BaseException | None:
        """Take the lock and say who holds it (on the state folder's thread); the error."""
        try:
            self.lock_path.parent.mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            return StateFolderBroken(f"the bench state folder {self.lock_path.parent} cannot be "
                                     f"made ({exc.strerror or exc})")
        try:
            _usable_lock(self.lock_path)
        except StateFolderBroken as exc:
            return exc
        lock = filelock.FileLock(self.lock_path, timeout=0)
        try:
            lock.acquire()
        except filelock.Timeout:
            return BenchBusy(describe_holder(self.bench_key, self.owner_path) + ": one command "
                             "per bench at a time (`mkm vent` asks a run to stop)")
        except OSError as exc:
            return StateFolderBroken(f"the bench lock {self.lock_path} cannot be taken "
                                     f"({exc.strerror or exc})")
        self.lock = lock
        try:
            self.stop_path.unlink(missing_ok=True)  # a request to an earlier holder
            me = ProcessIdentity.current()
            write_atomic(self.owner_path, json.dumps(
                {"pid": me.pid, "host": me.host, "command": self.command,
                 "started_utc": provenance()["date_utc"]}))
        except OSError as exc:
            self._let_go()
            return StateFolderBroken(f"the bench state folder {self.lock_path.parent} is not "
                                     f"writable ({exc.strerror or exc})")
        return None

    def dead_runs(self, then: str = "nothing was touched") -> list[tuple[Path, Marker]]:
        """The markers of the runs that died on this bench
        (:func:`mkm.bench.unvented.find_unvented`), read on the state folder's thread and
        waited for at most :data:`STATE_START_S` (not at all when the folder already hangs):
        :class:`StateFolderBroken` after it, its message ending with ``then`` (what the caller
        did); the bench is then let go once the folder answers, or with this process."""
        done, found = self.on_state_folder(lambda: find_unvented(self.bench_key, self.state),
                                           "the runs that died on this bench were looked for")
        if not done:
            raise StateFolderBroken(f"{found}: {then}; the bench is let go once it answers, or "
                                    "as this process ends")
        if isinstance(found, BaseException):  # raised here, as an unbounded search raised it
            raise found
        return found

    @property
    def hung(self) -> bool:
        """The state folder did not answer in time, and was said to hang."""
        return self._hung

    def post(self, update) -> None:
        """``update()`` on the state folder's thread, after those posted before it; never
        waits (its failure is the next wait's to find: :meth:`on_state_folder` runs after it)."""
        self._state.post(update)

    def on_state_folder(self, function, what: str) -> tuple[bool, object]:
        """``function()`` (doing ``what``, said in the past tense) on the state folder's
        thread, after the updates posted before it, waited for at most :data:`STATE_START_S`
        (not at all when the folder already hangs): ``(True, what it returned or raised)``, or
        ``(False, what happened, in words)`` when it did not come back in time (it still runs
        once the folder answers; the bench is let go after it, not waited for again)."""
        # an earlier update never came back (one merely posted, :meth:`post`, is waited for)
        hung = self._hung
        done, out = self._state.call(function, 0.0 if hung else STATE_START_S)
        if done:
            return True, out
        self._hung = True
        within = "" if hung else f" within {STATE_START_S:g} s"
        return False, (f"the bench state folder {self.lock_path.parent} did not answer{within} "
                       f"as {what} (it hangs)")

    def __exit__(self, *exc) -> None:
        """Let the bench go, waiting at most :data:`STATE_WAIT_S` for the state folder: past
        it, :attr:`problem` says so and the lock goes with this process. The state folder's
        thread ends once the lock is let go, on it."""
        if self.lock is None:
            self._state.end()
            return
        if self._hung:  # said as it was found; the lock goes once it answers
            self._state.post(self._let_go)
            self._state.end()
            return
        ticket = self._state.post(self._let_go)
        self._state.end()
        if not self._state.wait(ticket, STATE_WAIT_S):
            self.problem = (f"the bench state folder {self.lock_path.parent} did not let the "
                            f"bench go within {STATE_WAIT_S:g} s (it hangs): not waited for; "
                            "its lock is released as this process ends")

    def _let_go(self) -> None:
        """Remove the owner file and the stop request, release the lock (on the state folder's
        thread)."""
        with self._polling:
            lock, self.lock = self.lock, None
            self._polling.notify()  # the stop request's reader ends
        if lock is None:
            return
        for path in (self.owner_path, self.stop_path):
            try:
                path.unlink(missing_ok=True)
            except OSError:
                pass  # the lock's release below is what matters
        lock.release()

    def stop_request(self) -> str | None:
        """Who asked this holder to stop (``mkm vent``, pid N), or None; never waits.

        Polled by the acquisition loop at every block, so the file is read by a thread of its
        own: a state folder that hangs (a network share) holds that thread, never the loop's
        interlocks. The answer is the last read done; a new read starts when it is."""
        with self._polling:
            if self._poll_thread is None:
                self._poll_thread = threading.Thread(target=self._poll, name="mkm-stop-poll",
                                                     daemon=True)
                self._poll_thread.start()
            self._read_wanted = True
            self._polling.notify()
            return self._stop_by

    def _poll(self) -> None:
        while True:
            with self._polling:
                self._polling.wait_for(lambda: self._read_wanted or self.lock is None)
                if self.lock is None:  # the bench is let go: nobody polls any more
                    return
                self._read_wanted = False
            try:
                by = self.stop_path.read_text(encoding="utf-8").strip() or "a stop request"
            except OSError:
                by = None
            with self._polling:
                self._stop_by = self._stop_by or by


def request_stop(bench_key: str, by: str, state: Path, wait_s: float = 30.0) -> dict | None:
    """Ask the live holder of ``bench_key`` (its lock in the bench state folder ``state``) to
    stop and wait (``wait_s``) until it has let go.

    Returns the holder's record when there was one (None when the bench was free); raises
    :class:`BenchBusy` when it did not let go in time, :class:`StateFolderBroken` when the
    state folder cannot be used (nobody can be asked: the caller vents all the same).
    """
    lock_path, owner_path, stop_path = _paths(bench_key, state)
    if not lock_path.parent.is_dir():
        return None
    _usable_lock(lock_path)
    probe = filelock.FileLock(lock_path, timeout=0)
    try:
        probe.acquire()
    except filelock.Timeout:
        pass
    except OSError as exc:
        raise StateFolderBroken(f"the bench lock {lock_path} cannot be probed "
                                f"({exc.strerror or exc})") from None
    else:
        probe.release()
        return None
    info = holder(owner_path) or {}
    try:
        write_atomic(stop_path, f"{by} (pid {os.getpid()})")
    except OSError as exc:
        raise StateFolderBroken(f"the stop request {stop_path} cannot be written "
                                f"({exc.strerror or exc}): the run holding the bench was not "
                                "asked to stop") from None
    deadline = time.monotonic() + wait_s
    while time.monotonic() < deadline:
        try:
            probe.acquire()
        except filelock.Timeout:
            time.sleep(0.05)
            continue
        probe.release()
        return info
    raise BenchBusy(f"{describe_holder(bench_key, owner_path)} and did not stop within "
                    f"{wait_s:g} s of the request: VENT BY HAND")
