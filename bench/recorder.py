"""The run's recorder: its folder (:class:`mkm.bench.storage.RunWriter`) and :class:`RunMeta`, kept
true while the run goes (pymeasure's recorder, beside the worker and the procedure).

run.json is written first when the folder is made, rewritten after the tare and at the end;
samples, steps and commands are appended as they happen, by a thread of the recorder's own: the
acquisition loop only queues them, so a disk that hangs (a network share, a dying drive) cannot
stop the loop, and with it every interlock, while the regulator holds its pressure. The thread
syncs them to the disk :data:`SYNC_EVERY_S` after the last sync, whether more rows come or not.
What the disk has not taken yet is held in memory, in order; the loop asks
:meth:`Recorder.stuck` after every block, and rows held while the disk finishes no write for
:data:`DISK_STUCK_S`, a disk trailing by more than that much sample time for as long, or more
than :data:`HELD_ROWS_MAX` rows held, stop the run: vent first, reason "disk not taking the
record".
A write the disk refused is said to the loop at its next block (:meth:`Recorder.raise_failure`)
and in the final reason; the samples it refused are kept and written again, none lost or
written twice. :meth:`Recorder.finish` waits for the disk to take everything held,
then writes the outcome and syncs every file; it never raises, so a full disk cannot hide the
outcome of the vent: it returns what went wrong.
"""

from __future__ import annotations

import collections
import copy
import dataclasses
import threading
import time
from pathlib import Path

from mkm.bench.backend import DeviceInfo, in_words
from mkm.bench.bounded import call_within
from mkm.bench.config import BenchConfig
from mkm.bench.storage import (
    CommandRecord,
    Gap,
    ProcessIdentity,
    RunMeta,
    RunStatus,
    RunWriter,
    Sample,
    StepRecord,
    kept_gaps_path,
    kept_samples_path,
    write_samples,
)
from mkm.bench.unvented import STATE_WAIT_S
from mkm.core.records import provenance, write_json_atomic

# On Windows a file another program holds open cannot be replaced (PermissionError): a virus
# scanner, the search indexer or a cloud-sync client opens a file just written for a moment,
# and run.json is rewritten after the tare and at the end of a run, seconds after its last
# write. Each rewrite tries again for this long before it says so (the tare's on the recorder's
# thread: the loop does not wait for it).
LOCKED_RETRIES, LOCKED_RETRY_S = 10, 0.2
#: Rows held for the disk while it finishes no write for this long [s] (wall time, the disk's
#: own: the samples held meanwhile say nothing of it, the virtual clock acquiring hundreds of
#: times faster than real time and a gap of lost samples jumping their time): it is not taking
#: the record, the run stops. A network share that stalls for seconds is ridden through; what is
#: held meanwhile is in memory, never more than HELD_ROWS_MAX rows (a row is a few hundred bytes in
#: memory: tens of MB, 30 s at the USB-6001's fastest 10 kHz on two inputs).
#: A disk that finishes its writes but trails by more than this much sample time for as long
#: (wall time) takes the record slower than the run acquires it: the run stops too, before
#: the samples held grow to HELD_ROWS_MAX (8 h at 10 Hz) with the record on disk ever further
#: behind.
DISK_STUCK_S = 30.0
HELD_ROWS_MAX = 300_000
#: The rows written are synced to the disk (fsync) by the recorder's thread this long [s] (wall
#: time) after the last sync, at a write or without one (an acquisition that stalls): a crash
#: of the operating system or a power cut loses about this much of the record, not everything
#: since the start (the kernel writes its cache back when it likes: up to 30 s on Linux). At
#: most once this often: a sync costs milliseconds, and the virtual clock writes hundreds of
#: samples a second.
SYNC_EVERY_S = 1.0


class Recorder:
    """Creates the run folder under ``out_root`` and records into it; ``bounds``: more of what
    the run is judged by, recorded with its calibration (the identified muscle's force ceiling)."""

    def __init__(self, out_root: str | Path, config: BenchConfig, info: DeviceInfo,
                 n_steps: int, estimated_duration_s: tuple[float, float],
                 unvented_before: list[dict] | None = None, bounds: dict | None = None):
        m = config.muscle
        prov = provenance()
        settings = config.as_dict()
        process = ProcessIdentity.current()
        self.meta = RunMeta(
            muscle=m,
            hardware=info.as_dict(),
            calibration={"loadcell": settings["loadcell"], "regulator": settings["regulator"],
                         "safety": settings["safety"],
                         "muscle_tolerances": dataclasses.asdict(m.tolerances),
                         **(bounds or {})},
            sequence={**settings["sequence"], "settle": settings["settle"],
                      "force_limit_N": config.force_limit_N, "n_steps": n_steps,
                      "estimated_duration_s": list(estimated_duration_s)},
            config_source=config.recorded_source, config_sha256=config.source_sha256,
            config_overrides=config.overrides,
            command=prov["command"], provenance=prov, started_utc=prov["date_utc"],
            process=process, unvented_before=list(unvented_before or []),
            simulated=bool(info.simulated))
        self.writer = RunWriter(out_root, self.meta, config.effective_text())  # run.json first
        # where the samples the run folder refuses to the end are kept; resolved now, as the
        # run's other state files are
        self.kept_path = kept_samples_path(self.writer.path)
        self.kept = ""  # what became of them there, in words ("" while none is left)
        self.step_rows: list[StepRecord] = []  # steps.csv's rows, in order: the vent check's
        # force per bar (mkm.bench.vent.force_per_bar)
        self._refused = False  # an append of samples failed (the disk)
        # a step's or a command's row the disk refused: the run folder does not hold the whole
        # record, whether the loop was told at its next block or after its last step
        self._rows_lost = False
        # rows taken from the queue and not on disk yet: a block being written, or rows the disk
        # refused, written again first with the next block (samples.csv cut back to its whole
        # rows before, _reopen), and once more at the end (refusals)
        self._unwritten: list[Sample] = []
        self._reopen = False
        self._cond = threading.Condition()
        self._ops: collections.deque = collections.deque()  # (kind, payload), in order
        self._busy = False  # the thread is writing what it took from _ops
        self._unsynced = False  # rows written since the last sync
        self.crashed = ""  # why the recorder's thread failed ("" while it works)
        self._held: collections.deque = collections.deque()  # first time_s of each held block
        self._held_rows = 0
        self.rate_hz = config.daq.sample_rate_hz
        self._failures: list[tuple[str, OSError]] = []  # what the disk refused, in order
        self._told = 0  # failures raised to the loop (raise_failure)
        self.stuck_reason = ""  # set once the disk is found not taking the record
        self.outcome_refused = False  # the final run.json could not be written: it says running
        # the run folder holds the whole record once finish returns: every sample in
        # samples.csv, every file synced, the outcome in run.json
        self.whole = False
        # when the thread last finished a write, or was given one while it had none
        self._done_at = time.monotonic()
        self._synced_at = self._done_at  # when the rows were last synced to the disk
        self._caught_up_at = self._done_at  # when the rows held last spanned DISK_STUCK_S or less
        self._thread = threading.Thread(target=self._write_queued, name="mkm-recorder",
                                        daemon=True)
        self._thread.start()

    @property
    def path(self) -> Path:
        return self.writer.path

    def save(self, books: RunMeta | None = None) -> None:
        """Write run.json: ``books`` (the meta as a queued save took it), else the meta now."""
        self.writer.write_meta(self.meta if books is None else books)

    def _books(self) -> RunMeta:
        """The meta as it is now, for a save queued now: the writer reaches it once the rows
        queued before it are on disk, and the gaps, steps and counts the loop adds meanwhile
        belong to rows queued after it (:meth:`_written_books`)."""
        return copy.deepcopy(self.meta)

    def _written_books(self, books: RunMeta) -> RunMeta:
        """``books`` with the count of the samples on disk, which the writer keeps itself: the
        rows queued before the save, as they are written when it is reached."""
        books.counters["samples"] = self.meta.counters["samples"]
        return books

    # the queue: the loop puts, the thread writes ---------------------------------------------

    def _put(self, kind: str, payload=None) -> None:
        with self._cond:
            if not self._ops and not self._busy:  # the disk is waited for from now
                self._done_at = time.monotonic()
            if kind == "samples":
                self._held.append(payload[0].time_s)
                self._held_rows += len(payload)
            self._ops.append((kind, payload))
            self._cond.notify_all()

    def _write_queued(self) -> None:
        """The recorder's thread: write what is queued, in order; a write the disk refuses is
        kept in ``_failures`` (its samples are kept and written again). Rows written and not
        synced are synced :data:`SYNC_EVERY_S` after the last sync even when nothing more comes
        (an acquisition that stalls: a DAQ that hangs, a loop waiting for a device).

        Should the thread itself fail (memory exhausted, a bug outside a write), :attr:`crashed`
        says why: the loop stops the run at its next block (:meth:`stuck`), nobody waits for
        the thread any more, and :meth:`finish` writes what it held on the caller's thread."""
        try:
            while (op := self._next_op()) is not None:
                self._do(*op)
        except BaseException as exc:
            with self._cond:
                self.crashed = in_words(exc)
                self._busy = False
                self._cond.notify_all()

    def _next_op(self, wait: bool = True) -> tuple[str, object] | None:
        """The next write, taken from the queue (its samples to the rows being written), or a
        sync due; None at ``stop`` (or, without ``wait``, when nothing is queued)."""
        with self._cond:
            while not self._ops:
                due_s = self._synced_at + SYNC_EVERY_S - time.monotonic()
                if self._unsynced and due_s <= 0:
                    break
                if not wait:
                    return None
                self._cond.wait(due_s if self._unsynced else None)
            if self._ops:
                kind, payload = self._ops.popleft()
            else:
                kind, payload = "sync due", None
            if kind == "stop":
                self._cond.notify_all()
                return None
            self._busy = True
            if kind == "samples":  # from the queue to the rows being written
                self._held.popleft()
                self._held_rows -= len(payload)
                self._unwritten.extend(payload)
            return kind, payload

    def _do(self, kind: str, payload) -> None:
        """One write taken by :meth:`_next_op`; what the disk refuses is kept in
        ``_failures``."""
        try:
            what = self._what(kind, payload)
            lost = kind in ("step", "command")  # a row refused is never written again
            try:
                self._write(kind, payload)
                lost = False
                self._unsynced = self._unsynced or kind in ("samples", "step", "command")
                if kind == "sync" or (self._unsynced and
                                      time.monotonic() - self._synced_at >= SYNC_EVERY_S):
                    what = "the rows' sync to the disk"
                    if kind != "sync":
                        self.writer.sync()
                    self._synced_at, self._unsynced = time.monotonic(), False
            except Exception as exc:  # the disk, or a bug: said in the reason, not lost
                failure = exc if isinstance(exc, OSError) else \
                    OSError(in_words(exc))
                with self._cond:
                    self._failures.append((what, failure))
                    self._rows_lost = self._rows_lost or lost
        finally:
            with self._cond:
                self._busy = False
                self._done_at = time.monotonic()
                self._cond.notify_all()

    def _write(self, kind: str, payload) -> None:
        if kind == "samples":  # the payload is in _unwritten already
            self._write_unwritten()
        elif kind == "step":
            self.writer.append_step(payload)
        elif kind == "command":
            self.writer.append_command(payload)
        elif kind == "save":
            self._save_retrying(self._written_books(payload))
        elif kind == "last try":  # the refused rows, with the final record's room given back
            self.writer.release_reserve()
            try:
                self._write_unwritten()
            except OSError:  # said by refusals()
                self._keep_unwritten()
        elif kind == "sync":  # the run's books before a step it may not outlive
            done, books = payload
            try:
                self._save_retrying(self._written_books(books))
                self.writer.sync()
            finally:
                done.set()

    def _write_unwritten(self) -> None:
        """Append the rows held; those the disk refused before go first, after what of them
        reached it (samples.csv cut back to its whole rows: none is lost, none written twice).
        An ``OSError`` keeps them all for the next attempt."""
        try:
            if self._reopen:
                on_disk = self.writer.reopen_samples()
                self._unwritten = [r for r in self._unwritten if r.sample > on_disk]
                self._reopen = False
            if self._unwritten:
                self.writer.append_samples(self._unwritten)
        except OSError:
            self._refused = self._reopen = True
            raise
        self.meta.counters["samples"] += len(self._unwritten)
        self._unwritten = []

    def _keep_unwritten(self) -> None:
        """The samples the run folder refused to the end, written to :attr:`kept_path` instead:
        a run keeps every sample it acquired; :attr:`kept` says where, or why not. Written on a
        thread of its own, waited for :data:`mkm.bench.unvented.STATE_WAIT_S`: a state folder
        that hangs (a roaming profile on a share) must not hold the run's outcome."""
        rows = list(self._unwritten)
        span = f"{rows[0].sample}-{rows[-1].sample}" if len(rows) > 1 else f"{rows[0].sample}"
        # the run's gaps beside them, first: run.json may be refused too, and a kept row after
        # a gap it never held would not continue samples.csv (mkm recover)
        gaps = [dataclasses.asdict(g) for g in self.meta.gaps]

        def keep() -> None:
            if gaps:
                write_json_atomic(kept_gaps_path(self.writer.path), gaps)
            write_samples(self.kept_path, rows)

        returned, exc = call_within(keep, STATE_WAIT_S, "mkm-recorder-keep")
        lost = f"{len(rows)} samples could not be written to the run folder"
        if not returned:
            self.kept = (f"{lost}: samples {span} are being written to {self.kept_path}, which "
                         f"did not answer within {STATE_WAIT_S:g} s (it hangs): kept once it "
                         "answers, lost if this process ends first")
        elif exc is not None:
            self.kept = f"{lost}, nor kept in {self.kept_path} ({in_words(exc)})"
        else:
            self.kept = f"{lost}: samples {span} are kept in {self.kept_path}"

    @staticmethod
    def _what(kind: str, payload) -> str:
        if kind == "samples":
            first, last = payload[0].sample, payload[-1].sample
            return f"samples {first}" if first == last else f"samples {first}-{last}"
        if kind == "step":
            return f"step {payload.step}"
        if kind == "command":
            return f"the {payload.purpose} command of {payload.command_bar:g} bar"
        if kind == "sync due":
            return "the rows' sync to the disk"
        return "run.json"

    def samples(self, rows: list[Sample]) -> None:
        """Queue ``rows`` for samples.csv (never waits for the disk)."""
        if rows:
            self._put("samples", list(rows))

    def step(self, record: StepRecord) -> None:
        self._put("step", record)
        self.step_rows.append(record)
        self.meta.steps_done += 1

    def command(self, record: CommandRecord) -> None:
        self._put("command", record)

    def gap(self, gap: Gap) -> None:
        self.meta.gaps.append(gap)
        self.meta.lost_samples += gap.lost_samples

    def tare(self, tare: dict) -> None:
        self.meta.tare = tare
        self._put("save", self._books())

    def raise_failure(self) -> None:
        """Raise the first write the disk refused that the loop has not been told of."""
        with self._cond:
            if self._told >= len(self._failures):
                return
            exc = self._failures[self._told][1]  # the first: the later ones follow from it
            self._told = len(self._failures)
        raise exc

    def refused(self, exc: BaseException) -> str:
        """What the disk refused in ``exc`` (raised by :meth:`raise_failure`: ``samples 30``,
        ``step 0``), or "" when ``exc`` is none of its refusals."""
        with self._cond:
            return next((what for what, failure in self._failures if exc is failure), "")

    def stuck(self) -> str:
        """Why the disk is not taking the record ("" while it is): samples held while it
        finishes no write for :data:`DISK_STUCK_S`, more than that much sample time held for
        as long (a disk slower than the run), or more than :data:`HELD_ROWS_MAX` rows held."""
        with self._cond:
            held = self.held_rows
            held_s = held / self.rate_hz
            if self.crashed:  # nothing writes them until the end: the run stops now
                self.stuck_reason = (f"the recorder's thread failed ({self.crashed}): {held} "
                                     "samples held in memory, written as the run ends")
                return self.stuck_reason
            now = time.monotonic()
            quiet_s = now - self._done_at
            if held_s <= DISK_STUCK_S:
                self._caught_up_at = now
            behind = now - self._caught_up_at >= DISK_STUCK_S
            if held <= HELD_ROWS_MAX and not (held and quiet_s >= DISK_STUCK_S) and not behind:
                return ""
            unwritten = self._unwritten  # replaced, never emptied in place, by the thread
            oldest_s = unwritten[0].time_s if unwritten else self._held[0]
            what = f"{held} samples ({held_s:g} s, the oldest from {oldest_s:g} s) held in memory"
            self.stuck_reason = (
                f"disk not taking the record: no write finished for {quiet_s:.0f} s, {what}"
                if quiet_s >= DISK_STUCK_S or not behind else
                f"disk not taking the record: slower than the run, {what}, more than "
                f"{DISK_STUCK_S:g} s of samples for {DISK_STUCK_S:g} s")
            return self.stuck_reason

    @property
    def held_rows(self) -> int:
        """Samples queued or refused that the disk has not taken yet."""
        return self._held_rows + len(self._unwritten)

    def wait_written(self, timeout_s: float | None = None) -> bool:
        """Wait until the disk has taken everything queued (at most ``timeout_s``); whether it
        has."""
        with self._cond:  # a thread that failed writes nothing more: not waited for
            return self._cond.wait_for(
                lambda: self.crashed or (not self._ops and not self._busy), timeout_s)

    def mark(self, status: RunStatus, reason: str, timeout_s: float | None = None) -> None:
        """Write the outcome known so far into run.json and sync the rows: the books kept before
        a step that the process may not outlive (a closed Windows console's vent check); waits
        at most ``timeout_s`` for the disk."""
        self.meta.status, self.meta.reason = status, reason
        self.meta.ended_utc = provenance()["date_utc"]
        done = threading.Event()
        self._put("sync", (done, self._books()))
        done.wait(timeout_s)

    def finish(self, status: RunStatus, reason: str) -> list[str]:
        """Record the outcome, sync and close every file; return the problems met (never
        raises: the caller must still be able to say where the run is); :attr:`whole` says
        whether the run folder holds the whole record."""
        self.wait_written()  # everything held, once the disk takes it
        self._put("stop")
        self._thread.join()
        problems = []
        if self.crashed:  # what it held, written here
            problems.append(self._write_rest())
        whole = not self.held_rows and not self._rows_lost
        self.meta.status, self.meta.reason = status, reason
        self.meta.ended_utc = provenance()["date_utc"]
        self.writer.release_reserve()  # a disk that filled mid-run: the room for this record
        try:  # the rows first: run.json's outcome is written once they are on disk
            self.writer.close()
        except Exception as exc:  # noqa: BLE001 - any failure of the close: the outcome still
            whole = False
            problems.append(f"the run's files could not all be synced ({in_words(exc)})")
        else:
            if self._refused:  # rows a full disk refused went out at close: count the disk's
                self.meta.counters["samples"] = self.writer.samples_on_disk(
                    self.meta.counters["samples"])
        try:
            self._save_retrying()
        except PermissionError as exc:
            self.outcome_refused = True
            problems.append(f"run.json could not be written ({in_words(exc)}; "
                            f"tried {LOCKED_RETRIES + 1} times over "
                            f"{LOCKED_RETRIES * LOCKED_RETRY_S:g} s)")
        except OSError as exc:
            self.outcome_refused = True
            problems.append(f"run.json could not be written ({in_words(exc)})")
        self.whole = whole and not self.outcome_refused
        return problems

    def _write_rest(self) -> str:
        """After the recorder's thread failed: write what it left queued, in order, on this
        thread; what became of it, in words."""
        held = self.held_rows
        try:
            while (op := self._next_op(wait=False)) is not None:
                self._do(*op)
            if self._unwritten or self._reopen:
                self._do("last try", None)
        except BaseException as exc:  # never raises: the outcome must still be recorded
            return (f"the recorder's thread failed ({self.crashed}), and so did writing the "
                    f"{self.held_rows} samples it held ({in_words(exc)})")
        if self._unwritten:
            return f"the recorder's thread failed ({self.crashed}), and {self.kept}"
        return (f"the recorder's thread failed ({self.crashed}): the {held} samples it held "
                "were written as the run ended")

    def _save_retrying(self, books: RunMeta | None = None) -> None:
        """:meth:`save`, tried again while another program holds run.json open."""
        for attempt in range(LOCKED_RETRIES + 1):
            try:
                self.save(books)
                return
            except PermissionError:  # held open by another program, mostly briefly
                if attempt == LOCKED_RETRIES:
                    raise
                time.sleep(LOCKED_RETRY_S)

    def refusals(self) -> list[str]:
        """Once everything queued is written: the samples the disk refused tried once more,
        with the room kept for the final record given back; then the writes it refused that
        the loop was not told of, in one phrase (once), and whether their samples reached it
        after all."""
        self.wait_written()
        if self._unwritten or self._reopen:  # on the thread: it may be syncing the files
            self._put("last try")
            self.wait_written()
        with self._cond:
            untold = self._failures[self._told:]
            self._told = len(self._failures)
        if not untold:
            return []
        what, exc = untold[0]
        more = f", and {len(untold) - 1} later write(s)" if len(untold) > 1 else ""
        if any(w.startswith("samples") for w, _ in untold):
            kept = "written again" if not self._unwritten else self.kept
            return [f"the disk refused {what} ({in_words(exc)}){more}; {kept}"]
        return [f"recording failed for {what} ({in_words(exc)}){more}"]
