"""Runs that ended without venting (``kill -9``, power loss), noticed by the next command.

While a run may pressurise the muscle it holds a marker file for its bench (backend and device
name) in the user's state folder (``MKM_STATE_DIR``, else
``platformdirs.user_state_dir("mkm-bench")``: ``~/.local/state/mkm-bench`` on Linux,
``%LOCALAPPDATA%\\mkm-bench`` on Windows): the run folder, the recording process
(:class:`mkm.bench.storage.ProcessIdentity`: pid, start time, boot time), and the last commanded
pressure, rewritten at every command by a thread of the run (:class:`BenchLease`: a state folder
that hangs never holds the acquisition loop) before the pressure is written to the device, so a
kill between the two still finds it (unless the state folder takes longer than
:data:`mkm.bench.worker.MARKER_WAIT_S`: the pressure then goes out ahead of its marker). A clean
shutdown that vented removes it. Every command that
opens a bench (``acquire``, ``check``, ``tare``, ``calibrate-loadcell``, ``vent``) first looks for
markers of that bench whose process is dead (on the bench owner's thread, at most
:data:`STATE_START_S`: :meth:`mkm.bench.ownership.BenchOwner.dead_runs`): it vents (opening the
device writes the vent command) and says which run it was, when it started, and what pressure it
left commanded, then mends its folder and removes its marker within the same bound. One file
per run, so concurrent runs never lock or overwrite each other's marker, nor does a later run of
the same process. ``mkm vent``, which has no run folder, leaves a marker of its own when it
has not verified its vent yet (:func:`mark_vent`).
"""

from __future__ import annotations

import datetime
import json
import queue
import re
import threading
from collections.abc import Callable
from dataclasses import asdict, dataclass, fields
from pathlib import Path

from mkm.bench.signals import FATAL_TRACE_FILE, fatal_error
from mkm.bench.storage import (
    OUTCOME_FIELDS,
    ProcessIdentity,
    RunStatus,
    kept_outcome,
    outcome_written,
)
from mkm.core.home import user_state
from mkm.core.records import write_json_atomic


def state_dir() -> Path:
    """Folder of the bench markers (:func:`mkm.core.home.user_state`: ``MKM_STATE_DIR`` overrides
    the platform's state folder)."""
    return user_state()


def bench_folder_name(bench_key: str) -> str:
    """``bench_key`` as a file name of the state folder: case folded, as NI-DAQmx compares
    device names (:func:`mkm.bench.devices.device_key`), so one device has one lock on every
    file system, case-sensitive or not."""
    return re.sub(r"[^a-z0-9._-]", "_", bench_key.strip().casefold())


def bench_folder(bench_key: str, state: Path | None = None) -> Path:
    """Where ``bench_key``'s markers lie, beside its lock, owner and stop files: in the bench
    state folder ``state`` (None: :func:`state_dir` now)."""
    return (state_dir() if state is None else state) / "benches" / bench_folder_name(bench_key)


@dataclass
class Marker:
    """A run that holds (or held) a bench."""

    bench: str
    run_path: str
    started_utc: str
    process: dict
    last_command_bar: float = 0.0
    last_command_utc: str = ""
    # the run ended with its vent commanded but not verified: what the check found
    vent_unverified: str = ""
    # the pressure its monitor did not follow before the vent: that monitor's readings prove no
    # vent (None: it followed, or no such interlock)
    unfollowed_bar: float | None = None
    # the run's final record (run.json's content: its status, reason, ended_utc,
    # manual_vent_required, gaps, vent check, signal...) when its run.json refused it (a full
    # disk, no permission): the finder writes it there
    outcome: dict | None = None
    # the command that left it without a run folder (``vent``: its check not verified);
    # ``run_path`` is then ""
    command: str = ""
    mended: str = ""  # what the finder did to the run folder (not written in the marker)

    def describe(self) -> str:
        run = (f"`mkm {self.command}`" if self.command and not self.run_path
               else f"run {self.run_path}") + (f" (started {self.started_utc}, "
                                              f"pid {self.process['pid']})")
        at = self.last_command_utc or self.started_utc
        if self.outcome:
            return (f"{run} ended {self.outcome['status']} at {self.outcome['ended_utc']}, but "
                    f"its run.json refused that record: {self.outcome['reason']}")
        if self.last_command_bar > 0:
            return (f"{run} ended without venting; its last commanded pressure was "
                    f"{self.last_command_bar:g} bar at {at}")
        if self.vent_unverified:
            return (f"{run} vented (0 bar commanded at {at}) but its vent was not verified: "
                    f"{self.vent_unverified}")
        if self.last_command_utc:
            return (f"{run} ended after its vent (0 bar commanded at {at}) before the vent "
                    "was verified")
        return f"{run} ended before any pressure was commanded"

    def vented_now(self) -> str:
        """What the command that found the marker says once it vented (and mended the run)."""
        return f"{self.describe()}: vented now{f'; {self.mended}' if self.mended else ''}"

    def record(self) -> dict:
        """The marker as written in the state folder."""
        data = asdict(self)
        del data["mended"]
        return data

    def noted(self) -> dict:
        """The marker as the run that found it records it (``unvented_before``): its outcome
        by its status, reason, end and manual vent (the rest is the dead run's own run.json's),
        and what was mended."""
        data = asdict(self)
        if self.outcome:
            data["outcome"] = {k: self.outcome.get(k) for k in OUTCOME_FIELDS}
        return data


#: The end of a command waits this long [s] for the bench state folder, then goes on without it
#: (the vent and the record are done by then).
STATE_WAIT_S = 2.0
#: A command's start, with nothing pressurised yet, waits this long [s] for the bench state
#: folder, then refuses: a state folder that takes longer hangs (a network share).
STATE_START_S = 10.0


_END = object()  # queued by StateFolderThread.end: the thread ends there


class StateFolderThread:
    """Updates of the bench state folder, made in order by a thread of their own.

    A state folder that hangs (a roaming profile on a network share) then holds that thread,
    never its caller: the acquisition loop, its interlocks and its vents, or the end of a
    command, which waits for an update (:meth:`wait`) only as long as it chooses.

    The thread ends where its owner says it is done (:meth:`end`, after its last update), never
    when idle: a bench's lock is held on it for a whole run, and filelock's locks belong to the
    thread that took them, so the update that releases the lock runs on that thread, before it
    ends. An update posted after the end keeps the thread (or starts another).
    """

    def __init__(self, name: str):
        self._name = name
        self._updates: queue.Queue = queue.Queue()
        self._done = threading.Condition()
        self._posted = self._written = 0  # updates posted, updates done (written or failed)
        self.error: OSError | None = None  # the last update's failure (None once one succeeds)
        self._thread: threading.Thread | None = None

    def post(self, update: Callable[[], None]) -> int:
        """Queue ``update`` for the thread; its ticket."""
        with self._done:  # the thread cannot end between this check and the queueing
            if self._thread is None:
                self._thread = threading.Thread(target=self._run, name=self._name,
                                                daemon=True)
                self._thread.start()
            self._posted += 1
            self._updates.put(update)
            return self._posted

    def end(self) -> None:
        """The owner is done: the thread ends once the updates posted before are (a state
        folder that hangs keeps it until it answers). Never waits."""
        with self._done:
            if self._thread is not None:
                self._updates.put(_END)

    def wait(self, ticket: int, timeout_s: float | None) -> bool:
        """Whether the update ``ticket`` (and every one before it) is done within
        ``timeout_s``; :attr:`error` says if it failed."""
        with self._done:
            return self._done.wait_for(lambda: self._written >= ticket, timeout_s)

    def call(self, function: Callable[[], object], timeout_s: float | None
             ) -> tuple[bool, object]:
        """``function()`` on the thread, waited for at most ``timeout_s``: ``(True, what it
        returned or the exception it raised)``, or ``(False, None)`` when it did not come back
        in time (it still runs, in order, once the folder answers)."""
        out: list = []

        def run() -> None:
            try:
                out.append(function())
            except Exception as exc:  # the caller's to raise or to say
                out.append(exc)

        if not self.wait(self.post(run), timeout_s):
            return False, None
        return True, out[0]

    @property
    def posted(self) -> int:
        """The ticket of the last update posted (0 before any)."""
        return self._posted

    def lagging(self) -> bool:
        """An update posted is not done yet: the state folder is slow or hangs."""
        return self._written < self._posted

    def _run(self) -> None:
        while True:
            update = self._updates.get()
            if update is _END:
                with self._done:
                    if self._updates.empty():  # nothing posted since the end: done
                        self._thread = None
                        return
                continue
            try:
                update()
                error = None
            except OSError as exc:
                error = exc
            except Exception as exc:  # a bug: said as the update's failure, the thread goes on
                error = OSError(f"{type(exc).__name__}: {exc}")
            with self._done:
                self._written += 1
                self.error = error
                self._done.notify_all()


class BenchLease(StateFolderThread):
    """The marker of one running run; :meth:`command` records each commanded pressure.

    The acquisition loop never writes it itself: it posts each update (:meth:`post`) to the
    lease's thread, which writes them in order (:meth:`command`, :meth:`unverified`,
    :meth:`release`); :meth:`wait` tells the loop whether an update is on disk yet. The first
    write is posted as the lease is made; :meth:`started` waits for it, before anything is
    pressurised.
    """

    def __init__(self, bench_key: str, run_path: Path, started_utc: str):
        super().__init__("mkm-bench-marker")
        me = ProcessIdentity.current()
        # absolute: the next command may run from another folder
        self.marker = Marker(bench_key, str(Path(run_path).resolve()), started_utc, asdict(me))
        folder = bench_folder(bench_key)
        # one per run: a marker a run leaves (its vent not verified, its record refused) stays
        # beside those of the later runs of the same process until that process has ended
        self.path = folder / (f"{me.pid}-{int((me.started_unix_s or 0.0) * 1000)}-"
                              f"{bench_folder_name(Path(run_path).name)}.json")

        def first() -> None:
            folder.mkdir(parents=True, exist_ok=True)
            self._write()

        self.post(first)

    def started(self) -> None:
        """Wait for the first write, at most :data:`STATE_START_S`: ``TimeoutError`` after
        it, its ``OSError`` if it failed."""
        if not self.wait(1, STATE_START_S):
            raise TimeoutError(f"no answer within {STATE_START_S:g} s: it hangs")
        if self.error is not None:
            raise self.error

    def _write(self) -> None:
        write_json_atomic(self.path, self.marker.record())

    def command(self, pressure_bar: float) -> None:
        if pressure_bar == self.marker.last_command_bar:
            return
        self.marker.last_command_bar = float(pressure_bar)
        self.marker.last_command_utc = datetime.datetime.now(datetime.UTC).isoformat(
            timespec="seconds")
        self._write()

    def unverified(self, what: str, unfollowed_bar: float | None = None) -> None:
        """The run ends with its vent not verified (``what`` the check found; the pressure its
        monitor did not follow, when that is why): the marker stays, and says so to the
        command that finds it."""
        self.marker.vent_unverified = what
        self.marker.unfollowed_bar = unfollowed_bar
        self._write()

    def ended(self, outcome: dict) -> None:
        """The run's run.json refused its final record ``outcome`` (what run.json would hold):
        the marker stays and keeps it, for the next command on the bench to write
        (:func:`mend_run`)."""
        self.marker.outcome = outcome
        self._write()

    def release(self) -> None:
        self.path.unlink(missing_ok=True)


def vent_marker(bench_key: str, command: str, state: Path) -> Path:
    """Where ``command`` (a command without a run folder: ``vent``) of this process marks
    ``bench_key`` in the bench state folder ``state`` (:func:`mark_vent`)."""
    me = ProcessIdentity.current()
    return bench_folder(bench_key, state) / (f"{me.pid}-{int((me.started_unix_s or 0.0) * 1000)}"
                                             f"-{bench_folder_name(command)}.json")


def mark_vent(bench_key: str, command: str, what: str, state: Path) -> None:
    """Mark ``bench_key`` in the bench state folder ``state`` as vented by ``command`` (a
    command without a run folder: ``vent``), its vent not verified: its check under way
    (``what`` "") or what the check found. Once this process has ended, the next command on
    the bench vents first and says so (:func:`find_unvented`); a verified vent removes the
    marker (:func:`vent_marker`). Raises the folder's ``OSError``."""
    now = datetime.datetime.now(datetime.UTC).isoformat(timespec="seconds")
    marker = Marker(bench_key, "", now, asdict(ProcessIdentity.current()), last_command_utc=now,
                    vent_unverified=what, command=command)
    path = vent_marker(bench_key, command, state)
    path.parent.mkdir(parents=True, exist_ok=True)
    write_json_atomic(path, marker.record())


def find_unvented(bench_key: str, state: Path | None = None) -> list[tuple[Path, Marker]]:
    """Markers of ``bench_key`` left by processes that are gone, in the bench state folder
    ``state`` (None: :func:`state_dir` now)."""
    folder = bench_folder(bench_key, state)
    found = []
    for path in sorted(folder.glob("*.json")) if folder.is_dir() else []:
        try:
            data = json.loads(path.read_text(encoding="utf-8"))
            known = {f.name for f in fields(Marker)} - {"mended"}
            marker = Marker(**{k: v for k, v in data.items() if k in known})  # a later version's
            alive = ProcessIdentity(**marker.process).alive()
        except (OSError, ValueError, TypeError, KeyError, AttributeError):
            continue  # unreadable: not ours to judge (written by another version?)
        if not alive:
            marker.outcome = _outcome(marker.outcome)
            found.append((path, marker))
    return found


def _outcome(kept) -> dict | None:
    """The final record a marker kept (:meth:`BenchLease.ended`), its outcome checked
    (:func:`mkm.bench.storage.kept_outcome`), or None when it holds none that a run ends with
    (the run is then mended as killed)."""
    try:
        return kept_outcome(kept, "the bench marker's outcome")
    except ValueError:
        return None


def vent_unvented(backend, found: list[tuple[Path, Marker]], on_state_folder
                  ) -> list[Marker]:
    """Vent a bench left pressurised by a dead run, before anything else happens on it.

    ``found``: the dead runs' markers, looked for by the bench's owner before the device was
    opened (:meth:`mkm.bench.ownership.BenchOwner.dead_runs`, bounded: a state folder that
    hangs refuses the command untouched). Call it right after ``backend.open()`` (which
    already wrote the vent): the vent is written again here, explicitly, and only once it
    succeeded are the dead runs' folders mended and their markers removed, by
    ``on_state_folder`` (:meth:`mkm.bench.ownership.BenchOwner.on_state_folder`: a thread
    waited for within a bound, so a state folder or a run folder that hangs holds that thread,
    never the command; each marker's ``mended`` then says what is left to do). Returns those
    markers for the caller to report; an ``OSError`` of the state folder is raised.
    """
    if not found:
        return []
    backend.write_command(0.0)

    def forget() -> list[str]:
        mended = []
        for path, marker in found:
            said, done = mend_run(marker)
            mended.append(said)
            if done:
                path.unlink(missing_ok=True)
        return mended

    done, mended = on_state_folder(forget, "the dead runs' folders were mended and their "
                                   "markers removed")
    if isinstance(mended, BaseException):
        raise mended
    if not done:
        mended = [f"{mended}: not yet done, done once it answers (the bench is let go after "
                  "it, or as this process ends)"] * len(found)
    for (_, marker), said in zip(found, mended, strict=True):
        marker.mended = said
    return [marker for _, marker in found]


def mend_run(marker: Marker) -> tuple[str, bool]:
    """Make the run folder of a dead run tell the truth, once its bench is vented: a run.json
    still ``running`` becomes ``killed``, with the sample count of the rows on disk and the time
    of death as far as known (samples.csv's last write), or takes the final record the marker
    kept when the run's own final write was refused (its outcome alone when the record is not
    this run's or not valid: :func:`mkm.bench.storage.outcome_written`), counting the rows on
    disk. Returns what was done, in words, and whether the marker is done with: one whose kept
    record run.json refuses again stays, for the next command to write."""
    from mkm.bench.storage import ended_on_disk, read_meta, write_final_record
    from mkm.core.records import provenance

    if not marker.run_path:  # left by a command without a run folder
        return "", True
    path = Path(marker.run_path)
    if not path.is_absolute():
        return f"its folder {path} is not an absolute path: not mended", True
    try:
        meta = read_meta(path)
    except (ValueError, OSError) as exc:
        return f"its run.json could not be read ({str(exc)[:200]}): not mended", True
    if meta.status != RunStatus.RUNNING:
        return "", True  # it recorded its own end
    if not meta.process or meta.process.pid != marker.process.get("pid"):
        return "its run.json names another process: not mended", True
    samples, died = ended_on_disk(path)
    died = died or marker.last_command_utc
    outcome, whole = marker.outcome, False
    fatal = fatal_error(path)  # the trace faulthandler wrote as the process died
    trace = (f"; its process died of a fatal error ({fatal}): the trace of the thread that "
             f"faulted is in {path / FATAL_TRACE_FILE}") if fatal else ""
    if outcome:
        try:
            meta, whole = outcome_written(meta, outcome, "the run's record its bench marker kept")
        except ValueError:  # not one run.json could hold: mended as killed
            outcome = None
    meta.counters["samples"] = samples
    if outcome:
        meta.ended_utc = meta.ended_utc or died or None
        meta.reason = (f"{meta.reason}; this outcome was refused by run.json as the run "
                       f"ended, kept in its bench marker and written by the next command "
                       f"at {provenance()['date_utc']}")
    else:
        meta.status = RunStatus.KILLED
        meta.ended_utc = died or None
        how = (f"of a fatal error ({fatal})" if fatal
               else "without closing the record (killed or power lost)")
        meta.reason = (f"its process (pid {marker.process.get('pid')}) died {how}, at about "
                       f"{died or 'an unknown time'}; its last commanded pressure was "
                       f"{marker.last_command_bar:g} bar; vented by the next command at "
                       f"{provenance()['date_utc']}"
                       + (f"; the trace of the thread that faulted is in {path / FATAL_TRACE_FILE}"
                          if fatal else ""))
    try:
        write_final_record(path, meta)
    except OSError as exc:
        kept = "; its bench marker keeps the outcome for the next command" if outcome else ""
        return (f"its run.json could not be rewritten ({exc.strerror or exc}): not mended{kept}",
                not outcome)
    alone = "" if whole or not outcome else (" (its marker kept the outcome alone, not the "
                                              "whole record)")
    return (f"run.json mended: status {meta.status}, {samples} samples on disk{alone}{trace}",
            True)
