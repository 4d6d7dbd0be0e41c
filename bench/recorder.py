"""The run's recorder: its folder (:class:`mkm.bench.storage.RunWriter`) and :class:`RunMeta`, kept
true while the run goes (pymeasure's recorder, beside the worker and the procedure).

run.json is written first when the folder is made, rewritten after the tare and at the end;
samples, steps and commands are appended as they happen. :meth:`Recorder.finish` writes the
outcome and syncs every file; it never raises, so a full disk cannot hide the outcome of the
vent: it returns what went wrong.
"""

from __future__ import annotations

import dataclasses
import time
from pathlib import Path

from mkm.bench.backend import DeviceInfo
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
)
from mkm.core.records import provenance

# On Windows a file another program holds open cannot be replaced (PermissionError): a virus
# scanner, the search indexer or a cloud-sync client opens a file just written for a moment,
# and run.json is rewritten at the end of a run seconds after its last write. The final record
# tries again for this long before it says so.
LOCKED_RETRIES, LOCKED_RETRY_S = 10, 0.2

class Recorder:
    """Creates the run folder under ``out_root`` and records into it."""

    def __init__(self, out_root: str | Path, config: BenchConfig, info: DeviceInfo,
                 n_steps: int, estimated_duration_s: tuple[float, float],
                 unvented_before: list[dict] | None = None):
        m = config.muscle
        prov = provenance()
        settings = config.as_dict()
        process = ProcessIdentity.current()
        self.meta = RunMeta(
            muscle=m,
            hardware=info.as_dict(),
            calibration={"loadcell": settings["loadcell"], "regulator": settings["regulator"],
                         "safety": settings["safety"],
                         "muscle_tolerances": dataclasses.asdict(m.tolerances)},
            sequence={**settings["sequence"], "settle": settings["settle"],
                      "force_limit_N": config.force_limit_N, "n_steps": n_steps,
                      "estimated_duration_s": list(estimated_duration_s)},
            config_source=config.source, config_overrides=config.overrides,
            command=prov["command"], provenance=prov, started_utc=prov["date_utc"],
            process=process, unvented_before=list(unvented_before or []),
            simulated=bool(info.simulated))
        self.writer = RunWriter(out_root, self.meta, config.effective_text())  # run.json first
        self._refused = False  # an append of samples failed (the disk)

    @property
    def path(self) -> Path:
        return self.writer.path

    def save(self) -> None:
        self.writer.write_meta(self.meta)

    def samples(self, rows: list[Sample]) -> None:
        try:
            self.writer.append_samples(rows)
        except OSError:
            self._refused = True  # buffered rows may still reach the disk at close
            raise
        self.meta.counters["samples"] += len(rows)

    def step(self, record: StepRecord) -> None:
        self.writer.append_step(record)
        self.meta.steps_done += 1

    def command(self, record: CommandRecord) -> None:
        self.writer.append_command(record)

    def gap(self, gap: Gap) -> None:
        self.meta.gaps.append(gap)
        self.meta.lost_samples += gap.lost_samples

    def tare(self, tare: dict) -> None:
        self.meta.tare = tare
        self.save()

    def mark(self, status: RunStatus, reason: str) -> None:
        """Write the outcome known so far into run.json and sync the rows: the books kept before
        a step that the process may not outlive (a closed Windows console's vent check)."""
        self.meta.status, self.meta.reason = status, reason
        self.meta.ended_utc = provenance()["date_utc"]
        self.save()
        self.writer.sync()

    def finish(self, status: RunStatus, reason: str) -> list[str]:
        """Record the outcome, sync and close every file; return the problems met (never
        raises: the caller must still be able to say where the run is)."""
        self.meta.status, self.meta.reason = status, reason
        self.meta.ended_utc = provenance()["date_utc"]
        problems = []
        self.writer.release_reserve()  # a disk that filled mid-run: the room for this record
        try:  # the rows first: run.json's outcome is written once they are on disk
            self.writer.close()
        except OSError as exc:
            problems.append(f"the run's files could not all be synced ({exc})")
        else:
            if self._refused:  # rows a full disk refused went out at close: count the disk's
                self.meta.counters["samples"] = self.writer.samples_on_disk(
                    self.meta.counters["samples"])
        for attempt in range(LOCKED_RETRIES + 1):
            try:
                self.save()
                break
            except PermissionError as exc:  # held open by another program, mostly briefly
                if attempt == LOCKED_RETRIES:
                    problems.append(f"run.json could not be written ({type(exc).__name__}: "
                                    f"{exc}; tried {LOCKED_RETRIES + 1} times over "
                                    f"{LOCKED_RETRIES * LOCKED_RETRY_S:g} s)")
                else:
                    time.sleep(LOCKED_RETRY_S)
            except OSError as exc:
                problems.append(f"run.json could not be written ({type(exc).__name__}: {exc})")
                break
        return problems
