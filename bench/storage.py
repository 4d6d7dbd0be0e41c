"""The run folder contract: one module writes it and reads it back.

One folder per run, named ``<UTC time>_<muscle id>``:

- ``run.json``: :class:`RunMeta`, written atomically at start (status ``running``) and at the
  end (a :class:`RunStatus`, with the reason); ``schema_version`` says which layout it has
  (files without it are version 1 and still load);
- ``config.toml``: the bench configuration as given;
- ``samples.csv``: one :class:`Sample` per row, appended and flushed after every block read;
- ``steps.csv``: one :class:`StepRecord` per pressure step, appended when the step ends;
- ``commands.csv``: one :class:`CommandRecord` per regulator command, with whether the write
  succeeded.

Rows are flushed to the operating system as they are appended (a run's by the thread of
:class:`mkm.bench.recorder.Recorder`, a few blocks behind its loop at most while the disk takes
them), so a run killed at any moment keeps every sample appended. ``fsync`` (which costs
milliseconds) runs for run.json, for the rows a second after the last sync whether more come
or not (:data:`mkm.bench.recorder.SYNC_EVERY_S`), and at close: it guards against a crash of
the operating system or a power cut, not against a dying process.

:func:`load_run` reads a folder back (samples loaded on first use); :func:`aggregate_samples`
streams ``samples.csv`` into time bins with bounded memory, for long runs (a 24 h run at 10 Hz
is 864,000 rows).
"""

from __future__ import annotations

import dataclasses
import datetime
import enum
import errno
import functools
import io
import json
import math
import os
import socket
import tempfile
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, NamedTuple

import numpy as np
import pandas as pd

from mkm.bench.signals import FATAL_TRACE_FILE, fatal_error
from mkm.core.guards import regular_file
from mkm.core.home import user_state
from mkm.core.records import (
    file_sha256,
    finite_or_null,
    one_argument,
    spreadsheet_safe_text,
    write_json_atomic,
)
from mkm.fem.muscle import Muscle
from mkm.fem.tolerances import Tolerances

SCHEMA_VERSION = 2
# Room kept on the run folder's disk while a run records, given back for its final record: a
# disk that fills mid-run would otherwise leave run.json 'running' (its final write refused)
# and the last row of samples.csv cut in half (its buffered tail refused at close).
RESERVE_NAME, RESERVE_BYTES = ".space-reserve", 256 * 1024
class RunStatus(enum.StrEnum):
    """Status of a run in ``run.json`` (a ``str``: ``RunStatus.COMPLETE == "complete"``)."""

    RUNNING = "running"
    COMPLETE = "complete"
    COMPLETE_WITH_GAPS = "complete_with_gaps"  # every step done, but samples were lost
    ABORTED = "aborted"  # stopped on purpose: interlock, signal, operator
    FAILED = "failed"  # stopped by an error: device, storage, tare
    INCOMPLETE = "incomplete"  # never written: the loader's verdict on a dead "running" record
    KILLED = "killed"  # its process died mid-run: written by the next command that found it,
    # or by mkm close (close_by_hand)
    IMPORTED = "imported"  # measured elsewhere (another bench, a spreadsheet): mkm import

    @property
    def finished(self) -> bool:
        return self in (RunStatus.COMPLETE, RunStatus.COMPLETE_WITH_GAPS, RunStatus.IMPORTED)


WRITTEN_STATUSES = tuple(s for s in RunStatus if s is not RunStatus.INCOMPLETE)
PHASES = ("tare", "precondition", "step", "operator", "vent")  # vent: its check's reads
DIRECTIONS = ("up", "down")
FLAGS = ("gap", "timeout", "clipped", "interlock", "nonfinite")


class Sample(NamedTuple):
    """One row of ``samples.csv``: one sample of every input on the hardware clock."""

    sample: int  # index on the hardware sample clock since start
    time_s: float  # sample / rate
    step: int  # -1 outside the staircase
    phase: str  # one of PHASES
    set_pressure_bar: float
    command_bar: float  # NaN with a manual regulator
    pressure_bar: float  # regulator monitor, or the typed manometer reading (manual)
    loadcell_V: float
    monitor_V: float
    force_N: float  # (loadcell_V - tare offset) * sensitivity
    flags: str  # FLAGS joined by "|"


class StepRecord(NamedTuple):
    """One row of ``steps.csv``: a pressure step, its hold average and how it settled."""

    step: int
    direction: str
    repeat: int
    set_pressure_bar: float
    pressure_bar_mean: float
    force_N_mean: float
    force_N_std: float
    n: int  # samples averaged in the hold
    settled: bool  # False: the settle timeout expired
    settle_s: float  # time from the step's start to the start of the hold
    start_s: float
    end_s: float
    # the hold's trend from first to last sample, and the budget of mkm.bench.budget (U at 95.45 %)
    force_drift_N: float = math.nan
    force_u_N: float = math.nan
    force_U_N: float = math.nan
    pressure_u_bar: float = math.nan
    pressure_U_bar: float = math.nan


class CommandRecord(NamedTuple):
    """One row of ``commands.csv``: a regulator command and whether the write succeeded.

    ``sample`` and ``time_s`` say when it was issued, by the device's sample clock just after
    the write (the samples acquired by then, read or waiting in the buffer): the command acts
    from that sample on. Only where the device could not say (lost) is it the samples read.
    """

    time_s: float
    sample: int
    command_bar: float
    command_V: float
    ok: bool
    purpose: str


SAMPLE_COLUMNS = Sample._fields
STEP_COLUMNS = StepRecord._fields
# steps.csv before the uncertainty budget: still read, the budget columns empty
STEP_COLUMNS_UNBUDGETED = STEP_COLUMNS[:STEP_COLUMNS.index("force_drift_N")]
COMMAND_COLUMNS = CommandRecord._fields
TIME_COLUMNS = {"time_s", "settle_s", "start_s", "end_s"}  # written with 10 digits: 0.1 s at 1e8 s


@dataclass(frozen=True)
class ProcessIdentity:
    """The process that records a run: pid plus its start time and the machine's boot time, so a
    pid reused after the recorder died (or after a reboot) does not make the run look alive."""

    pid: int
    host: str
    started_unix_s: float | None = None
    boot_unix_s: float | None = None

    @classmethod
    def current(cls) -> ProcessIdentity:
        """This process (the pid alone if the system does not say when it started)."""
        import psutil

        try:
            return cls(os.getpid(), socket.gethostname(), psutil.Process().create_time(),
                       psutil.boot_time())
        except (psutil.Error, OSError):
            return cls(os.getpid(), socket.gethostname())

    def alive(self) -> bool:
        """Whether this process still runs (False when it runs on another host: unknowable).

        The system clock may be set while it runs (an NTP step, a hand correction, a virtual
        machine resumed): the boot time the system gives moves with it, and so, on Linux, does
        the start time of every process (counted from the boot), while Windows keeps the start
        times it stamped. So the same process is the pid started at the recorded time, or, both
        moved alike, started as long after its boot as recorded; a process of the pid started
        another time (the pid reused, or reused after a reboot) is not it."""
        import psutil

        if self.host != socket.gethostname() or not psutil.pid_exists(self.pid):
            return False
        boot_moved_s = None if self.boot_unix_s is None else \
            psutil.boot_time() - self.boot_unix_s
        if self.started_unix_s is None:  # a version-1 record: the pid is all there is
            return boot_moved_s is None or abs(boot_moved_s) <= 2.0  # else rebooted since
        try:
            started = psutil.Process(self.pid).create_time()
        except psutil.NoSuchProcess:
            return False
        except psutil.AccessDenied:
            return boot_moved_s is None or abs(boot_moved_s) <= 2.0
        moved_s = started - self.started_unix_s
        return abs(moved_s) < 1.0 or (boot_moved_s is not None
                                      and abs(moved_s - boot_moved_s) < 1.0)


@dataclass
class Gap:
    """Samples lost to a buffer overflow: ``lost_samples`` after sample ``after_sample``."""

    after_sample: int
    lost_samples: int
    start_s: float  # time of the first lost sample
    end_s: float  # time of the first sample after the gap
    message: str = ""


@dataclass
class RunMeta:
    """Everything ``run.json`` holds. :meth:`as_dict` writes it, :meth:`from_dict` reads it.

    ``sequence`` holds the configured sequence and settle criteria plus ``n_steps`` (steps
    planned); ``steps_done`` counts the steps finished. ``config_source`` names the
    configuration file (the packaged example by its name in the package, a user's file by its
    path as given) and ``config_sha256`` hashes its bytes. ``stop_signal`` names the signal that
    stopped the run (``SIGTERM``...), ``stop_signal_number`` its number (exit status 128 + N).
    ``manual_vent_required`` is True when the final vent could not be verified (the command
    failed, the monitor did not fall below the threshold, or it read below it already when the
    pressure interlock found it below its command: ``vent_check`` says what was read): the
    operator must vent by hand. ``simulated`` is True for a run on a simulated bench (its
    folder name ends in ``-SIMULATED``). ``unvented_before`` lists earlier runs on this bench
    found ended without venting (and vented) when this run started. ``lost_samples`` totals
    the ``gaps``. ``closed`` says who closed by hand the record of a run whose ``mkm acquire``
    stopped without closing it (:func:`close_by_hand`): ``reason``, ``by`` (the user), ``on``
    (the PC), ``utc``.
    """

    muscle: Muscle
    status: RunStatus = RunStatus.RUNNING
    reason: str = ""
    schema_version: int = SCHEMA_VERSION
    hardware: dict[str, Any] = field(default_factory=dict)
    calibration: dict[str, Any] = field(default_factory=dict)
    tare: dict[str, Any] | None = None
    sequence: dict[str, Any] = field(default_factory=dict)
    steps_done: int = 0
    config_source: str = ""
    config_sha256: str | None = None
    config_overrides: dict[str, Any] = field(default_factory=dict)
    command: str = ""
    provenance: dict[str, Any] = field(default_factory=dict)
    started_utc: str = ""
    ended_utc: str | None = None
    process: ProcessIdentity | None = None
    counters: dict[str, int] = field(default_factory=lambda: {
        "samples": 0, "read_timeouts": 0, "clipped_samples": 0})
    gaps: list[Gap] = field(default_factory=list)
    lost_samples: int = 0
    stop_signal: str | None = None
    stop_signal_number: int | None = None
    stop_to_vent_s: float | None = None
    vented_at_unix_s: float | None = None
    last_command_bar: float = 0.0
    manual_vent_required: bool = False
    vent_check: dict[str, Any] | None = None
    unvented_before: list[dict[str, Any]] = field(default_factory=list)
    reprocessed_from: dict[str, Any] | None = None
    imported_from: dict[str, Any] | None = None
    simulated: bool = False
    closed: dict[str, Any] | None = None

    @property
    def n_steps(self) -> int | None:
        return self.sequence.get("n_steps")

    def recording(self) -> str:
        """``"is still being recorded (pid N)"`` for a run whose ``mkm acquire`` still runs on
        this machine, what is known of one whose record another PC holds open (a run folder on
        a share: that PC's processes cannot be seen from here), else ``""``: its files hold what
        was on disk a moment ago."""
        if self.status != RunStatus.RUNNING or not self.process:
            return ""
        if self.process.alive():
            return f"is still being recorded (pid {self.process.pid})"
        if self.recorded_on():
            return (f"may still be recorded on {self.recorded_on()} (its run.json says running, "
                    "and this PC cannot see that PC's processes)")
        return ""

    def recorded_on(self) -> str:
        """The other PC whose ``mkm acquire`` wrote this run's record, or ``""`` (this PC's)."""
        host = self.process.host if self.process else ""
        return host if host and host.casefold() != socket.gethostname().casefold() else ""

    def until_ended(self) -> str:
        """When a run that :meth:`recording` holds has its whole record: ``"once its mkm
        acquire has ended"``, with where and how when another PC holds it."""
        if not self.recorded_on():
            return "once its mkm acquire has ended"
        return (f"once its mkm acquire on {self.recorded_on()} has ended (a run that stopped "
                "there without closing its record is closed by the next mkm command on that "
                f"bench there, such as mkm vent on {self.recorded_on()}; if that PC runs mkm no "
                "more, by mkm close RUN_DIR --reason TEXT here)")

    def as_dict(self) -> dict[str, Any]:
        """run.json's content: strict JSON, so nothing read (a vent check on a lost device or
        monitor, NaN) is ``null``, which jq, a browser and a spreadsheet's JSON import read."""
        data = dataclasses.asdict(self)
        data["muscle"] = self.muscle.record()
        data["status"] = str(self.status)
        del data["schema_version"]
        return finite_or_null({"schema_version": SCHEMA_VERSION, **data})

    # A read-only mapping view, for code that shows run.json generically (provenance dumps).
    def get(self, key: str, default: Any = None) -> Any:
        return self.as_dict().get(key, default)

    def __getitem__(self, key: str) -> Any:
        return self.as_dict()[key]

    def __contains__(self, key: str) -> bool:
        return key in self.as_dict()

    @classmethod
    def from_dict(cls, data: Any, where: str = "run.json") -> RunMeta:
        """Validate ``data`` (a parsed run.json of any schema version) into a :class:`RunMeta`.

        Raises ``ValueError`` naming the missing or bad field.
        """
        if not isinstance(data, dict):
            raise ValueError(f"{where} is corrupt: expected a JSON object")
        data = dict(data)
        version = data.pop("schema_version", 1)
        if version not in (1, SCHEMA_VERSION):
            raise ValueError(f"{where} has schema_version {version!r}: expected 1 or "
                             f"{SCHEMA_VERSION} (a newer mkm wrote it?)")
        if not isinstance(data.get("status"), str) or data["status"] not in WRITTEN_STATUSES:
            raise ValueError(f"{where} is corrupt: expected a 'status' among "
                             f"{', '.join(WRITTEN_STATUSES)}, got {_shown(data.get('status'))}")
        if version == 1:
            try:
                data = _upgrade_v1(data)
            except (TypeError, ValueError, KeyError, AttributeError) as exc:
                raise ValueError(f"{where} is corrupt: its version-1 layout does not upgrade "
                                 f"({type(exc).__name__})") from None
        known = {f.name for f in dataclasses.fields(cls)}
        values = {k: v for k, v in data.items() if k in known}
        _check_fields(values, where)
        values["status"] = RunStatus(values["status"])
        tolerances = (data.get("calibration") or {}).get("muscle_tolerances")
        values["muscle"] = muscle_from_dict(data.get("muscle"), where, tolerances)
        if values.get("process") is not None:
            values["process"] = _record(ProcessIdentity, values["process"], f"{where}: process")
        values["gaps"] = [_record(Gap, g, f"{where}: gaps[{k}]")
                          for k, g in enumerate(values.get("gaps") or [])]
        if "simulated" not in data:  # recorded in the hardware section before
            values["simulated"] = bool((data.get("hardware") or {}).get("simulated"))
        values["schema_version"] = version  # as read; as_dict() writes the current layout
        return cls(**values)


def muscle_from_dict(data: Any, where: str, tolerances: Any = None) -> Muscle:
    """The run's muscle (:class:`mkm.fem.muscle.Muscle`): ``run.json``'s ``muscle`` with its
    ``id``, and the tolerances recorded with the run's calibration (the defaults where they are
    not, or not usable)."""
    if not isinstance(data, dict):
        raise ValueError(f"{where} has no 'muscle' object: expected id, D0_mm, t0_mm, L0_mm, eps")
    if "id" not in data:
        raise ValueError(f"{where}: muscle.id is missing: expected the muscle's id")
    try:
        made_to = Tolerances(**tolerances) if isinstance(tolerances, dict) else Tolerances()
    except (TypeError, ValueError):
        made_to = Tolerances()
    return Muscle.from_dict(data, f"{where}: muscle", tolerances=made_to)


def _shown(value: Any, n: int = 60) -> str:
    text = repr(value)
    return text if len(text) <= n else text[:n] + "..."


#: The most of a run's ``reason`` a summary shows (a report, a loader's problem, a refusal):
#: a reason written by hand or by another tool may be any length; run.json keeps it whole.
REASON_SHOWN_CHARS = 200


def reason_shown(reason: str) -> str:
    """``reason`` as a summary shows it: its first line, at most :data:`REASON_SHOWN_CHARS`
    characters, with ``... (in full in run.json)`` where it is cut."""
    text = reason.strip()
    first = text.splitlines()[0] if text else ""
    shown = first if len(first) <= REASON_SHOWN_CHARS else first[:REASON_SHOWN_CHARS].rstrip()
    return shown if shown == text else f"{shown}... (in full in run.json)"


# The JSON type each field of run.json must have (None allowed where the field is optional).
_FIELD_TYPES: dict[str, tuple[type, ...]] = {
    "reason": (str,), "hardware": (dict,), "calibration": (dict,), "tare": (dict, type(None)),
    "sequence": (dict,), "steps_done": (int,), "config_source": (str,),
    "config_sha256": (str, type(None)),
    "config_overrides": (dict,), "command": (str,), "provenance": (dict,),
    "started_utc": (str,), "ended_utc": (str, type(None)), "process": (dict, type(None)),
    "counters": (dict,), "gaps": (list,), "lost_samples": (int,),
    "stop_signal": (str, type(None)), "stop_signal_number": (int, type(None)),
    "stop_to_vent_s": (float, int, type(None)), "vented_at_unix_s": (float, int, type(None)),
    "last_command_bar": (float, int), "manual_vent_required": (bool,),
    "vent_check": (dict, type(None)), "unvented_before": (list,),
    "reprocessed_from": (dict, type(None)), "imported_from": (dict, type(None)),
    "simulated": (bool,), "closed": (dict, type(None)),
}
# Numbers other code reads from the nested objects: section -> key -> (low, high)
_NESTED_NUMBERS = {
    "sequence": {"n_steps": (0, 10**6), "force_limit_N": (0.0, 1e7), "tare_s": (0.0, 1e6)},
    "hardware": {"sample_rate_hz": (1e-6, 1e6)},
}


def _check_fields(values: dict[str, Any], where: str) -> None:
    """Every known field of run.json with the JSON type it must have, and the nested numbers
    other tools read within bounds (``ValueError`` naming the first that is not)."""
    for name, types in _FIELD_TYPES.items():
        if name not in values:
            continue
        value = values[name]
        if isinstance(value, bool) and bool not in types:
            ok = False
        else:
            ok = isinstance(value, types)
        if not ok:
            kinds = " or ".join("null" if t is type(None) else t.__name__ for t in types)
            raise ValueError(f"{where}: {name}={_shown(value)} is invalid: expected {kinds}")
        if isinstance(value, float) and not math.isfinite(value):
            raise ValueError(f"{where}: {name}={value!r} is not a finite number")
    for section, keys in _NESTED_NUMBERS.items():
        table = values.get(section) or {}
        for key, (low, high) in keys.items():
            value = table.get(key)
            if value is None:
                continue
            if isinstance(value, bool) or not isinstance(value, int | float) \
                    or not low <= value <= high:
                raise ValueError(f"{where}: {section}.{key}={_shown(value)} is invalid: expected "
                                 f"a number in [{low:g}, {high:g}]")
    settle = (values.get("sequence") or {}).get("settle", {})
    if not isinstance(settle, dict):
        raise ValueError(f"{where}: sequence.settle={_shown(settle)} is invalid: expected an "
                         "object")
    for entry in values.get("unvented_before") or []:
        if not isinstance(entry, dict):
            raise ValueError(f"{where}: unvented_before holds {_shown(entry)}: expected "
                             "objects (the runs found unvented)")
    steps_done = values.get("steps_done", 0)
    if isinstance(steps_done, int) and not isinstance(steps_done, bool) and steps_done < 0:
        raise ValueError(f"{where}: steps_done={steps_done} is invalid: expected a count >= 0")
    counters = values.get("counters") or {}
    for key, value in counters.items():
        if isinstance(value, bool) or not isinstance(value, int) or value < 0:
            raise ValueError(f"{where}: counters.{str(key)[:40]}={_shown(value)} is invalid: "
                             "expected a count >= 0")


#: The statuses a run's own end writes: those its bench marker keeps when run.json refused them.
ENDED_STATUSES = (RunStatus.COMPLETE, RunStatus.COMPLETE_WITH_GAPS, RunStatus.ABORTED,
                  RunStatus.FAILED)
#: A run's outcome in run.json: all a bench marker of an older version keeps of its record.
OUTCOME_FIELDS = ("status", "reason", "ended_utc", "manual_vent_required")


def kept_outcome(data: Any, where: str) -> dict[str, Any]:
    """A run's final record kept outside its run.json (its bench marker, when run.json refused
    it), its outcome checked as run.json's fields are: a status a run ends with
    (:data:`ENDED_STATUSES`), its reason, end and manual vent (``ValueError`` naming the first
    that is not). The rest is checked where it is written (:func:`outcome_written`); a marker of
    an older version keeps those fields alone (:data:`OUTCOME_FIELDS`)."""
    if not isinstance(data, dict):
        raise ValueError(f"{where}={_shown(data)} is invalid: expected an object")
    if data.get("status") not in ENDED_STATUSES:
        raise ValueError(f"{where}: status={_shown(data.get('status'))} is invalid: expected "
                         f"one a run ends with: {', '.join(ENDED_STATUSES)}")
    outcome = {"status": data["status"], "reason": data.get("reason"),
               "ended_utc": data.get("ended_utc"),
               "manual_vent_required": data.get("manual_vent_required", False)}
    _check_fields(outcome, where)
    return {**data, **outcome}


def outcome_written(meta: RunMeta, kept: dict[str, Any], where: str) -> tuple[RunMeta, bool]:
    """``meta`` (a run.json still ``running``) with the final record ``kept`` for it
    (:func:`kept_outcome`) laid over it, read as run.json is (:meth:`RunMeta.from_dict`): the
    whole record when it is this run's (its start and process id) and valid, else its
    outcome's four fields alone; and whether it was whole."""
    record = meta.as_dict()
    process = kept.get("process")
    if kept.get("started_utc") == record["started_utc"] and isinstance(process, dict) and \
            meta.process is not None and process.get("pid") == meta.process.pid:
        try:
            return RunMeta.from_dict({**record, **kept}, where), True
        except ValueError:  # edited by hand: its outcome alone
            pass
    return RunMeta.from_dict({**record, **{k: kept[k] for k in OUTCOME_FIELDS}}, where), False


def _record(cls, data: Any, where: str):
    """``cls(**data)`` for a small record of run.json, its fields' types checked."""
    if not isinstance(data, dict):
        raise ValueError(f"{where}={_shown(data)} is invalid: expected an object")
    fields = {f.name: f for f in dataclasses.fields(cls)}
    unknown = sorted(set(data) - set(fields))
    missing = [n for n, f in fields.items() if n not in data
               and f.default is dataclasses.MISSING]
    if unknown or missing:
        raise ValueError(f"{where} is invalid: expected the fields {', '.join(fields)}")
    for name, value in data.items():
        kind = str(fields[name].type)
        if kind == "str":
            ok = isinstance(value, str)
        else:  # int and float fields, some optional
            ok = (value is None and "None" in kind) or (
                isinstance(value, int | float) and not isinstance(value, bool)
                and math.isfinite(value) and (not kind.startswith("int") or
                                              isinstance(value, int)))
        if not ok:
            raise ValueError(f"{where}.{name}={_shown(value)} is invalid: expected {kind}")
    return cls(**data)


def _upgrade_v1(data: dict[str, Any]) -> dict[str, Any]:
    """Version 1 (no schema_version): pid/host at the top, gaps inside counters, the planned
    step count as ``sequence.steps``."""
    data = dict(data)
    if "pid" in data:
        data["process"] = {"pid": data.pop("pid"), "host": data.pop("host", "")}
    sequence = dict(data.get("sequence") or {})
    if isinstance(sequence.get("steps"), int):
        sequence["n_steps"] = sequence.pop("steps")
    data["sequence"] = sequence
    counters = dict(data.get("counters") or {})
    rate = float((data.get("hardware") or {}).get("sample_rate_hz") or 10.0)
    gaps = []
    for g in counters.pop("gaps", []):
        first = int(g["after_sample"]) + 1
        gaps.append({"after_sample": int(g["after_sample"]),
                     "lost_samples": int(g["lost_samples"]), "start_s": first / rate,
                     "end_s": (first + int(g["lost_samples"])) / rate,
                     "message": g.get("message", "")})
    data["counters"] = counters
    data["gaps"] = gaps
    data["lost_samples"] = sum(g["lost_samples"] for g in gaps)
    return data


SIMULATED_SUFFIX = "-SIMULATED"
REPROCESSED_SUFFIX = "-reprocessed"
IMPORTED_SUFFIX = "-imported"


def run_folder_name(muscle_id: str, when: datetime.datetime | None = None, k: int = 1,
                    simulated: bool = False, origin: str = "", label: str = "") -> str:
    """``<UTC time>_<muscle id>[-label][-k][-reprocessed|-imported][-SIMULATED]``: the
    ``k``-th folder of that second; ``label`` tells apart the runs one command writes (an
    imported table's lengths: ``eps0.064``); ``origin`` is ``"reprocessed"``, ``"imported"``
    or empty (acquired)."""
    when = when or datetime.datetime.now(datetime.UTC)
    return (f"{when:%Y%m%dT%H%M%SZ}_{muscle_id}{f'-{label}' if label else ''}"
            f"{f'-{k}' if k > 1 else ''}"
            f"{f'-{origin}' if origin else ''}{SIMULATED_SUFFIX if simulated else ''}")


def _cell(value, column: str) -> str:
    if type(value) is float:  # most cells: checked first (a record's samples are millions)
        return "" if value != value else (f"{value:.10g}" if column in TIME_COLUMNS
                                          else f"{value:.6g}")
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return ""
    if isinstance(value, bool | np.bool_):
        return "true" if value else "false"
    if isinstance(value, float | np.floating):
        return f"{value:.10g}" if column in TIME_COLUMNS else f"{value:.6g}"
    if isinstance(value, str):
        return _safe_text(value)
    return str(value)


# a sample's phase and a step's direction repeat: each judged once
_safe_text = functools.lru_cache(maxsize=256)(spreadsheet_safe_text)


class RunWriter:
    """Creates a run folder and appends records to its files as the run goes.

    The folder is made with its run.json first (``meta``), then config.toml and the CSV
    headers; if any of that fails (a full disk) the folder is removed again and the
    ``OSError`` raised, so no folder exists without its run.json. ``label`` goes into the
    folder's name (:func:`run_folder_name`).
    """

    def __init__(self, root: str | Path, meta: RunMeta, config_text: str, label: str = ""):
        import shutil

        root = Path(root)
        root.mkdir(parents=True, exist_ok=True)
        when, k = datetime.datetime.now(datetime.UTC), 1
        while True:
            origin = ("reprocessed" if meta.reprocessed_from else
                      "imported" if meta.imported_from else "")
            path = root / run_folder_name(meta.muscle.id, when, k, meta.simulated, origin,
                                          label)
            try:
                path.mkdir()
                break
            except FileExistsError:
                k += 1
        self.path = path
        self._files = {}
        try:
            self.write_meta(meta)
            (path / "config.toml").write_text(config_text, encoding="utf-8")
            for name, columns in (("samples", SAMPLE_COLUMNS), ("steps", STEP_COLUMNS),
                                  ("commands", COMMAND_COLUMNS)):
                f = open(path / f"{name}.csv", "w", encoding="utf-8", newline="")
                self._files[name] = (f, columns)
                f.write(",".join(columns) + "\n")
                f.flush()
            with open(path / RESERVE_NAME, "wb") as f:  # the final record's room
                f.write(os.urandom(RESERVE_BYTES))  # not zeros: a compressing disk keeps them
                f.flush()
                os.fsync(f.fileno())
        except BaseException:  # a full disk, or a stop signal while the folder is made: no
            # half-made folder is left to pass for a run that died while it recorded
            for f, _ in self._files.values():
                try:
                    f.close()
                except OSError:
                    pass
            shutil.rmtree(path, ignore_errors=True)
            raise

    def write_meta(self, meta: RunMeta) -> None:
        write_json_atomic(self.path / "run.json", meta.as_dict())

    def samples_on_disk(self, otherwise: int) -> int:
        """The whole rows of samples.csv on disk (``otherwise`` where it is gone)."""
        path = self.path / "samples.csv"
        try:
            size = _whole_rows_bytes(path)
            with open(path, "rb") as f:
                rows = -1  # the header
                while size > 0:
                    chunk = f.read(min(size, 1 << 20))
                    if not chunk:
                        break
                    rows, size = rows + chunk.count(b"\n"), size - len(chunk)
        except OSError:
            return otherwise
        return max(rows, 0)

    def reopen_samples(self) -> int:
        """After an append of samples the disk refused: samples.csv closed (what its buffer
        still held is dropped), cut back to its last whole row, opened again; the index of the
        last sample it holds (-1 for none), after which the refused rows are written again."""
        f, columns = self._files["samples"]
        try:
            f.close()
        except OSError:
            pass  # the buffer the disk refused: dropped, the rows are written again
        path = self.path / "samples.csv"
        whole = _whole_rows_bytes(path)
        with open(path, "r+b") as raw:
            raw.truncate(whole)
            raw.seek(max(0, whole - 4096))
            lines = raw.read().splitlines()
        self._files["samples"] = (open(path, "a", encoding="utf-8", newline=""), columns)
        try:
            return int(lines[-1].split(b",")[0]) if len(lines) > 1 or whole > 4096 else -1
        except (IndexError, ValueError):  # the header alone
            return -1

    def release_reserve(self) -> None:
        """Give back the room kept for the final record (:data:`RESERVE_BYTES`)."""
        release_reserve(self.path)

    def _append(self, name: str, rows) -> None:
        f, columns = self._files[name]
        f.write("".join(",".join(_cell(v, c) for v, c in zip(row, columns, strict=True)) + "\n"
                        for row in rows))
        f.flush()
        self._check_linked(f, name)

    def _check_linked(self, f, name: str) -> None:
        """``FileNotFoundError`` when ``f`` was deleted under the run (its folder removed): on
        POSIX the writes of an open file then go on into a file no one can read, so the run
        would record nothing while it pressurises the muscle."""
        if os.fstat(f.fileno()).st_nlink == 0:
            raise FileNotFoundError(errno.ENOENT, f"{name}.csv was deleted while recording (its "
                                    "rows went with it): the run folder was removed",
                                    str(self.path))

    def append_samples(self, rows: list[Sample]) -> None:
        """Flushed to the operating system before returning."""
        self._append("samples", rows)

    def append_step(self, row: StepRecord) -> None:
        self._append("steps", [row])

    def append_command(self, row: CommandRecord) -> None:
        self._append("commands", [row])

    def sync(self) -> None:
        """Sync every open file to disk, leaving it open (rows kept through a power cut)."""
        for f, _ in self._files.values():
            if not f.closed:
                f.flush()
                os.fsync(f.fileno())

    def close(self) -> None:
        """Sync every file to disk and close it; every file is tried, the first error raised."""
        errors = []
        for f, _ in self._files.values():
            if f.closed:
                continue
            try:
                f.flush()
                os.fsync(f.fileno())
            except OSError as exc:
                errors.append(exc)
            finally:
                try:
                    f.close()
                except OSError as exc:  # the buffered tail could not be written (disk full)
                    errors.append(exc)
        self.release_reserve()
        if errors:
            raise errors[0]


def write_samples(path: Path, rows: list[Sample]) -> None:
    """``rows`` alone in a CSV of samples.csv's columns at ``path`` (its folder made), synced to
    the disk: the samples a run folder refused, kept elsewhere."""
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w", encoding="utf-8", newline="") as f:
        f.write(",".join(SAMPLE_COLUMNS) + "\n")
        f.write("".join(",".join(_cell(v, c) for v, c in zip(row, SAMPLE_COLUMNS, strict=True))
                        + "\n" for row in rows))
        f.flush()
        os.fsync(f.fileno())


def kept_samples_path(run_dir: Path) -> Path:
    """Where the samples the run folder ``run_dir`` refused to the end are kept
    (:func:`write_samples`): the user state folder, local and kept across restarts, under the
    run folder's name."""
    return user_state("unwritten", f"{Path(run_dir).name}-samples.csv")


def kept_gaps_path(run_dir: Path) -> Path:
    """Where the gaps of the run folder ``run_dir`` are kept beside its kept samples
    (:func:`kept_samples_path`): a run.json refused at the end never held those found after its
    last write, and without them kept rows after a gap do not continue samples.csv."""
    return user_state("unwritten", f"{Path(run_dir).name}-gaps.json")


def _kept_gaps(run_dir: Path) -> list[Gap]:
    """The gaps kept beside the run's kept samples (:func:`kept_gaps_path`); none when no file.
    ``ValueError`` when it cannot be read."""
    kept = kept_gaps_path(run_dir)
    if not kept.is_file():
        return []
    try:
        data = json.loads(kept.read_text(encoding="utf-8"))
    except (OSError, ValueError) as exc:
        raise ValueError(f"{kept} cannot be read ({str(exc)[:200]}): expected the gaps a run "
                         "kept beside its samples; nothing joined") from None
    if not isinstance(data, list):
        raise ValueError(f"{kept} holds {_shown(data)}: expected the list of gaps a run kept "
                         "beside its samples; nothing joined")
    return [_record(Gap, g, f"{kept}: [{k}]") for k, g in enumerate(data)]


def _kept_elsewhere(path: Path) -> list[str]:
    """The samples of the run folder ``path`` kept in the state folder
    (:func:`kept_samples_path`) that samples.csv does not hold (past its last row: they follow
    it), in words."""
    kept = kept_samples_path(path)
    if not kept.is_file():
        return []
    try:
        sample = _read_csv(kept, SAMPLE_COLUMNS, [])["sample"]
        last = _last_row(path / "samples.csv")[:1]
        sample = sample[sample > int(last[0])] if last else sample
    except (OSError, ValueError) as exc:
        return [f"samples this run's folder refused are kept in {kept}, which cannot be read "
                f"({str(exc)[:200]})"]
    if sample.empty:  # appended to samples.csv already
        return []
    span = f"{sample.iloc[0]}-{sample.iloc[-1]}" if len(sample) > 1 else f"{sample.iloc[0]}"
    return [f"samples {span} ({len(sample)}) are not in samples.csv: the run folder refused "
            f"them, and they are kept in {kept} (`mkm recover {one_argument(path)}` joins them to "
            "samples.csv once the folder takes writes again)"]


def join_kept_samples(run_dir: str | Path) -> tuple[str, bool]:
    """Join the samples the run folder ``run_dir`` refused to the end, kept in the state folder
    (:func:`kept_samples_path`), back into its samples.csv once the folder takes writes again,
    and count them in run.json (its reason then says so; a run.json still ``running`` keeps its
    reason for the outcome the bench marker holds). What was done, in words, and whether
    run.json took the count.

    ``ValueError`` (nothing changed) when nothing is kept, the run still records, the folder or
    samples.csv still refuses writes, or the kept rows do not continue samples.csv's last
    sample (after a gap recorded there). The gaps kept beside them (:func:`kept_gaps_path`)
    that run.json does not hold are recorded in it, as any gap. The kept rows are written as
    they are, after samples.csv's last whole row; those it holds already are left out; the kept
    files stay. Asked again after run.json refused the count, it counts them then, and records
    the gaps it did not hold.
    """
    path = Path(run_dir)
    meta = read_meta(path)
    kept, samples_csv = kept_samples_path(path), path / "samples.csv"
    if not kept.is_file():
        raise ValueError(f"{path}: no samples of this run are kept in {kept}: nothing to join")
    if meta.recording():
        raise ValueError(f"{path} {meta.recording()}: expected a run that has ended")
    if not samples_csv.is_file():
        raise ValueError(f"{samples_csv} is missing: expected the run's samples.csv to join "
                         f"the kept samples of {kept} to")
    recorded = {g.after_sample for g in meta.gaps}
    added = [g for g in _kept_gaps(path) if g.after_sample not in recorded]
    if added:  # found after run.json's last write: it never held them
        meta.gaps = sorted([*meta.gaps, *added], key=lambda g: g.after_sample)
        meta.lost_samples = sum(g.lost_samples for g in meta.gaps)
    gaps = (f", and the {len(added)} gap(s) kept beside them "
            f"({sum(g.lost_samples for g in added)} samples lost) recorded" if added else "")
    header, *rows = kept.read_bytes().splitlines(keepends=True)
    if header.rstrip(b"\r\n") != ",".join(SAMPLE_COLUMNS).encode():
        raise ValueError(f"{kept} does not start with samples.csv's header: expected the rows "
                         "a run kept there")
    rows = [r if r.endswith(b"\n") else r + b"\n" for r in rows]
    try:
        numbers = [int(r.split(b",", 1)[0]) for r in rows]
    except ValueError:
        raise ValueError(f"{kept} holds a row without a sample number: expected the rows a run "
                         "kept there") from None
    last = _last_row(samples_csv)
    last_sample = int(last[0]) if last else -1
    new = [(n, r) for n, r in zip(numbers, rows, strict=True) if n > last_sample]
    if not new and numbers:  # joined before: a run.json that refused the count (and the
        # gaps, written with it) takes them now
        held = Run(path, meta, pd.DataFrame(), meta.status).n_samples
        if held != meta.counters.get("samples") or added:
            return _count_joined(path, meta, held, f"the samples kept in {kept} are all in "
                                 f"{samples_csv} already, joined before{gaps}",
                                 f"samples {numbers[0]}-{numbers[-1]} ({len(numbers)}) kept in "
                                 f"{kept} were joined to samples.csv{gaps}")
    if not new:
        raise ValueError(f"the samples kept in {kept} are all in {samples_csv} already (its "
                         f"last sample is {last_sample}): nothing to join; the kept file may "
                         "be deleted")
    lost = sum(g.lost_samples for g in meta.gaps if g.after_sample == last_sample)
    if new[0][0] != last_sample + 1 + lost:
        raise ValueError(f"the samples kept in {kept} begin at sample {new[0][0]}, but "
                         f"{samples_csv} ends at sample {last_sample}: expected this run's "
                         f"kept rows, from sample {last_sample + 1 + lost}; nothing joined")
    try:
        with tempfile.TemporaryFile(dir=path):  # the folder, not only the file, takes writes
            pass
        with open(samples_csv, "r+b") as f:
            f.truncate(_whole_rows_bytes(samples_csv))  # a half row a killed writer left
            f.seek(0, os.SEEK_END)
            f.write(b"".join(r for _, r in new))
            f.flush()
            os.fsync(f.fileno())
    except OSError as exc:
        raise ValueError(f"{path} still refuses writes ({exc.strerror or exc}): nothing "
                         f"joined, the samples stay kept in {kept}; expected a run folder this "
                         "user can write to again") from None
    span = f"samples {new[0][0]}-{new[-1][0]} ({len(new)})"
    return _count_joined(path, meta, Run(path, meta, pd.DataFrame(), meta.status).n_samples,
                         f"{span} kept in {kept} were joined to {samples_csv}{gaps}",
                         f"{span} kept in {kept} were joined to samples.csv{gaps}")


def _count_joined(path: Path, meta: RunMeta, held: int, done: str, said: str
                  ) -> tuple[str, bool]:
    """run.json of the run folder ``path`` counts the ``held`` samples of samples.csv, its
    reason followed by ``said`` (once; a run.json still ``running`` keeps its reason for the
    outcome the bench marker holds): :func:`join_kept_samples`' words (``done`` what was
    done) and whether run.json took the count."""
    meta.counters["samples"] = held
    if meta.status != RunStatus.RUNNING and said not in meta.reason:
        meta.reason = f"{meta.reason}; {said}"
    try:
        write_json_atomic(path / "run.json", meta.as_dict())
    except OSError as exc:
        return (f"{done}, but run.json could not count them ({exc.strerror or exc}): "
                f"samples.csv holds {held} samples"), False
    return f"{done}; run.json counts {held} samples", True


def ended_on_disk(path: Path) -> tuple[int, str | None]:
    """What the folder ``path`` of a run whose process died holds: its samples, counted from
    samples.csv's whole rows (run.json's counter is from its last rewrite), and when
    samples.csv was last written (UTC, to the second; None without it), the end as far as
    known."""
    samples = load_run(path).meta.counters["samples"]
    csv = path / "samples.csv"
    return samples, (datetime.datetime.fromtimestamp(csv.stat().st_mtime, datetime.UTC)
                     .isoformat(timespec="seconds") if csv.is_file() else None)


def write_final_record(path: Path, meta: RunMeta) -> None:
    """``meta``, the final record of the dead run in ``path``, into its run.json (the room its
    recorder kept for it given back first); raises the ``OSError``."""
    release_reserve(path)
    write_json_atomic(path / "run.json", meta.as_dict())


#: A run whose samples.csv or run.json changed less than this long ago [s], by this PC's clock
#: (or, a share's clock ahead, later), may still be recorded: :func:`close_by_hand` refuses it.
#: A recording run writes samples.csv every block, a second or so apart; the margin covers a
#: share's cached times and two PCs' clocks minutes apart.
STILL_WRITTEN_S = 300.0


def close_by_hand(run_dir: str | Path, reason: str, now: datetime.datetime | None = None) -> str:
    """Close the record of a run whose ``mkm acquire`` stopped without closing it (its run.json
    says ``running``), for a user who knows it is dead: recorded on a PC that will run mkm no
    more (broken, reinstalled), whose next command would close it (:func:`mkm.bench.unvented.
    mend_run`). Its run.json becomes ``killed``, as that command writes it, with the samples
    counted from samples.csv, the end at samples.csv's last write, ``reason`` first in its
    reason and ``closed`` saying why, by whom, on which PC and when; no other file is touched.
    Returns what was done, in words.

    ``ValueError`` (nothing changed) when the run is not ``running``, its process runs on this
    PC, its files were written less than :data:`STILL_WRITTEN_S` ago, or ``reason`` is empty;
    the ``OSError`` of a run.json that refuses the write.
    """
    import getpass

    path = Path(run_dir)
    reason = " ".join(str(reason).split())
    if not reason:
        raise ValueError("--reason is empty: expected why the run is closed by hand (for "
                         "example \"BENCH-PC-A broke during the run\")")
    meta = read_meta(path)
    if meta.status != RunStatus.RUNNING:
        raise ValueError(f"run {path.name} is closed already (status {meta.status}): expected a "
                         "run whose run.json says running")
    if meta.process and meta.process.alive():
        raise ValueError(f"run {path.name} is still being recorded on this PC (pid "
                         f"{meta.process.pid}): stop it (Ctrl-C in its window, or mkm vent on "
                         "its bench asks it to stop) and it closes its record itself")
    now = now or datetime.datetime.now(datetime.UTC)
    for name in ("samples.csv", "run.json"):
        if (path / name).is_file():
            written = datetime.datetime.fromtimestamp((path / name).stat().st_mtime,
                                                      datetime.UTC)
            if (now - written).total_seconds() < STILL_WRITTEN_S:
                still = written + datetime.timedelta(seconds=STILL_WRITTEN_S)
                raise ValueError(
                    f"run {path.name}'s {name} was written at {written:%Y-%m-%dT%H:%M:%S}Z, "
                    f"less than {STILL_WRITTEN_S / 60:g} min ago: its mkm acquire on "
                    f"{meta.recorded_on() or 'this PC'} may still record it: expected files "
                    f"still for that long (close it from {still:%H:%M:%S} UTC on)")
    samples, died = ended_on_disk(path)
    try:
        user = getpass.getuser()
    except (OSError, KeyError, ImportError):  # no user name in the environment
        user = "an unknown user"
    host, at = socket.gethostname(), now.isoformat(timespec="seconds")
    pid = meta.process.pid if meta.process else "unknown"
    recorder = meta.process.host if meta.process else "an unknown PC"
    meta.status, meta.ended_utc = RunStatus.KILLED, died
    meta.counters["samples"] = samples
    meta.closed = {"reason": reason, "by": user, "on": host, "utc": at}
    meta.reason = (f"{reason} (closed by hand with mkm close by {user} on {host} at {at}); its "
                   f"mkm acquire (pid {pid} on {recorder}) stopped without closing its record, "
                   f"its last samples written at about {died or 'an unknown time'}")
    write_final_record(path, meta)
    unvented = _unvented(_read_csv(path / "commands.csv", COMMAND_COLUMNS, []))
    vent = (f"; {unvented}: vent that bench (mkm vent on {recorder}, or by hand)" if unvented
            else "")
    return (f"run {path.name} closed: status killed, {samples} samples kept as they are on "
            f"disk{vent}")


def release_reserve(path: Path) -> None:
    """Delete the room a run kept in its folder ``path`` for its final record, if there."""
    try:
        (Path(path) / RESERVE_NAME).unlink(missing_ok=True)
    except OSError:
        pass


# --- reading ----------------------------------------------------------------------------------


def _whole_rows_bytes(path: Path) -> int:
    """Size of ``path`` up to and including its last newline (a killed writer may leave half a
    row after it)."""
    size = path.stat().st_size
    with open(path, "rb") as f:
        pos = size
        while pos > 0:
            start = max(0, pos - 65536)
            f.seek(start)
            chunk = f.read(pos - start)
            k = chunk.rfind(b"\n")
            if k >= 0:
                return start + k + 1
            pos = start
    return 0


class _Prefix(io.RawIOBase):
    """The first ``limit`` bytes of a binary file, as a readable stream."""

    def __init__(self, f, limit: int):
        self._f, self._left = f, limit

    def readable(self) -> bool:
        return True

    def readinto(self, buffer) -> int:
        n = min(len(buffer), self._left)
        data = self._f.read(n)
        buffer[: len(data)] = data
        self._left -= len(data)
        return len(data)


# Earlier layouts a file may have: its columns missing there are read as empty
OLDER_COLUMNS = {"steps.csv": (STEP_COLUMNS_UNBUDGETED,)}


def _open_rows(path: Path, columns: tuple[str, ...], problems: list[str]):
    """A text stream over the whole rows of ``path``, its header checked (the current one or an
    earlier layout of :data:`OLDER_COLUMNS`), and the columns it has."""
    whole = _whole_rows_bytes(path)
    if whole < path.stat().st_size:
        problems.append(f"{path.name}: dropped a partial last row")
    raw = open(path, "rb")
    # utf-8-sig: a file saved again on Windows (Excel's "CSV UTF-8") starts with a BOM
    stream = io.TextIOWrapper(io.BufferedReader(_Prefix(raw, whole)), encoding="utf-8-sig",
                              newline="")
    try:
        header = stream.readline().rstrip("\r\n")
    except UnicodeDecodeError:
        header = None  # not text: refused below as any other header
    layouts = (columns, *OLDER_COLUMNS.get(path.name, ()))
    found = next((c for c in layouts if header == ",".join(c)), None)
    if found is None:
        stream.close()
        raw.close()
        raise ValueError(f"{path} is corrupt: expected the header {','.join(columns[:3])}...")
    return stream, raw, found


DTYPES = {"flags": "string", "phase": "string", "direction": "string", "purpose": "string"}


def _read_csv(path: Path, columns: tuple[str, ...], problems: list[str],
              chunksize: int | None = None):
    if path.is_symlink() or (path.exists() and not path.is_file()):
        regular_file(path, "run folder file ")  # refused with its reason
    if not path.is_file():
        problems.append(f"{path.name} is missing")
        empty = pd.DataFrame(columns=list(columns))
        return iter([empty]) if chunksize else empty
    stream, raw, found = _open_rows(path, columns, problems)
    dtypes = {c: t for c, t in DTYPES.items() if c in columns}

    def frames():
        try:
            reader = pd.read_csv(stream, names=list(found), header=None, dtype=dtypes,
                                 chunksize=chunksize or 200_000)
            while True:
                try:
                    df = next(reader)
                except StopIteration:
                    return
                except (pd.errors.ParserError, ValueError) as exc:
                    first = (str(exc).strip().splitlines() or [type(exc).__name__])[0]
                    raise ValueError(f"{path} is corrupt: {first}") from None
                yield checked_rows(df, path).reindex(columns=list(columns))
        finally:
            stream.close()
            raw.close()

    if chunksize:
        return frames()
    parts = list(frames())
    return pd.concat(parts, ignore_index=True) if parts else pd.DataFrame(columns=list(columns))


def checked_rows(df: pd.DataFrame, path: Path | str) -> pd.DataFrame:
    """``df`` (rows of a run folder's CSV, or of mkm export's sheet) typed, its text columns
    within their fixed vocabulary and its numbers within bounds; ``ValueError`` naming
    ``path`` and the first bad cell otherwise."""
    if "flags" in df:
        df["flags"] = df["flags"].fillna("")
    for column in ("settled", "ok"):
        if column in df:
            df[column] = df[column].astype(str).str.lower().eq("true")
    # Text columns hold a fixed vocabulary; anything else (a tampered "=cmd") is refused, so no
    # spreadsheet formula can pass through into a report's CSV.
    for column, allowed in (("direction", DIRECTIONS), ("phase", PHASES)):
        if column in df:
            bad = ~df[column].isin(allowed)
            if bad.any():
                raise ValueError(f"{path} is corrupt: {column}={df[column][bad].iloc[0]!r}, "
                                 f"expected one of {', '.join(allowed)}")
    if "purpose" in df:
        bad = ~df["purpose"].str.fullmatch(r"[a-z ]+").fillna(False).astype(bool)
        if bad.any():
            raise ValueError(f"{path} is corrupt: purpose={_shown(df['purpose'][bad].iloc[0])}, "
                             "expected lowercase words")
    if "flags" in df:
        tokens = df["flags"].str.split("|").explode()
        bad = ~(tokens.isin(FLAGS) | tokens.eq(""))
        if bad.any():
            raise ValueError(f"{path} is corrupt: flags={_shown(tokens[bad].iloc[0])}, expected "
                             f"some of {', '.join(FLAGS)} joined by |")
    for column in df.columns:
        if column in DTYPES or column in ("settled", "ok"):
            continue
        try:
            values = pd.to_numeric(df[column], errors="raise")
        except (ValueError, TypeError):
            raise ValueError(f"{path} is corrupt: {column} holds text, expected numbers") \
                from None
        magnitude = values.abs()
        if (magnitude > MAX_CELL_MAGNITUDE).any():  # NaN (a broken input) is recorded as such
            raise ValueError(f"{path} is corrupt: {column}="
                             f"{float(values[magnitude > MAX_CELL_MAGNITUDE].iloc[0])!r} is beyond "
                             f"+-{MAX_CELL_MAGNITUDE:g} (no bench reading is)")
        df[column] = values
    return df


MAX_CELL_MAGNITUDE = 1e9  # larger than any index, time [s], pressure [bar], force [N] or volt


@dataclass
class Run:
    """A run folder loaded back.

    ``status`` is the one in ``run.json``, except that a ``running`` record whose process is dead
    (killed, power lost) loads as ``incomplete``. ``problems`` lists what the loader had to repair
    or could not read; ``unvented`` describes a run that ended without its vent (None if it did
    vent). ``samples`` is read on first use (whole); :func:`aggregate_samples` streams instead.
    """

    path: Path
    meta: RunMeta
    steps: pd.DataFrame
    status: RunStatus
    commands: pd.DataFrame = field(default_factory=pd.DataFrame)
    problems: list[str] = field(default_factory=list)
    unvented: str | None = None
    #: the rows its files lost against its closed record (also in ``problems``)
    rows_lost: list[str] = field(default_factory=list)
    _samples: pd.DataFrame | None = None

    @property
    def samples(self) -> pd.DataFrame:
        if self._samples is None:
            self._samples = _read_csv(self.path / "samples.csv", SAMPLE_COLUMNS, [])
        return self._samples

    @property
    def n_samples(self) -> int:
        """Samples in samples.csv (counted without loading them)."""
        path = self.path / "samples.csv"
        if self._samples is not None or not path.is_file():
            return len(self.samples)
        whole = _whole_rows_bytes(path)
        with open(path, "rb") as f:
            count = 0
            while whole > 0:
                chunk = f.read(min(1 << 20, whole))
                whole -= len(chunk)
                count += chunk.count(b"\n")
        return max(count - 1, 0)

    @property
    def complete(self) -> bool:
        """Every planned step done and nothing lost (an imported table counts as complete)."""
        return self.status in (RunStatus.COMPLETE, RunStatus.IMPORTED)

    @property
    def reason(self) -> str:
        return self.meta.reason

    def sha256(self) -> dict[str, str]:
        """The SHA-256 of each file of the run there is (its record, steps, samples and an
        imported table's copy), by name: what a file computed from the run names it by."""
        copy = (self.meta.imported_from or {}).get("table_copy")
        names = ("run.json", "steps.csv", "samples.csv", *([copy] if copy else []))
        return {name: file_sha256(self.path / name) for name in names
                if (self.path / name).is_file()}

    def require_content(self, what: str) -> None:
        """``ValueError`` (one line naming ``what`` would be written) unless the run holds a
        measurement: a finite force in its samples, or, imported, in its steps."""
        if self.status == RunStatus.IMPORTED:
            forces, where = self.steps.get("force_N_mean", pd.Series(dtype=float)), "steps"
        else:
            regular_file(self.path / "samples.csv", f"run {self.path.name}: ")
            forces, where = self.samples["force_N"], "samples"
        if len(forces) == 0:
            raise ValueError(f"run {self.path} has no {where}: no {what} is written from it")
        if not np.isfinite(pd.to_numeric(forces, errors="coerce").to_numpy(float)).any():
            raise ValueError(f"run {self.path} has {len(forces)} {where} and not one finite "
                             f"force: no {what} is written from it")


MAX_RUN_JSON_BYTES = 10_000_000


def read_meta(path: str | Path) -> RunMeta:
    """The :class:`RunMeta` of the run folder ``path`` (``ValueError`` when it cannot be read)."""
    path = Path(path)
    meta_path = path / "run.json"
    try:
        is_file = meta_path.is_file()
    except OSError as exc:
        raise ValueError(f"{str(path)[:200]} cannot be read as a run folder "
                         f"({exc.strerror or exc})") from None
    if not is_file:
        expected = "expected a run folder of mkm acquire or mkm import (it holds run.json)"
        if not path.exists():
            raise ValueError(f"{path}: no such folder: {expected}")
        raise ValueError(f"{path} is not a run folder: run.json is missing: {expected}")
    regular_file(meta_path, "run folder file ")
    if meta_path.stat().st_size > MAX_RUN_JSON_BYTES:
        raise ValueError(f"{meta_path} is {meta_path.stat().st_size} bytes: expected a run "
                         f"record of at most {MAX_RUN_JSON_BYTES}")
    try:
        text = meta_path.read_text(encoding="utf-8-sig")  # a BOM: Windows editors
    except OSError as exc:  # no permission, a file held locked: a read, not a write, failed
        raise ValueError(f"{meta_path} cannot be read ({exc.strerror or exc}): expected a run "
                         "record this user can read") from None
    except UnicodeDecodeError as exc:
        raise ValueError(f"{meta_path} is corrupt (not valid JSON: {exc})") from None
    try:
        data = json.loads(text, object_pairs_hook=_unique_keys)
    except json.JSONDecodeError as exc:
        raise ValueError(f"{meta_path} is corrupt (not valid JSON: {exc})") from None
    except RecursionError:
        raise ValueError(f"{meta_path} is corrupt (nested too deeply)") from None
    return RunMeta.from_dict(data, str(meta_path))


def _unique_keys(pairs: list[tuple[str, Any]]) -> dict[str, Any]:
    """A JSON object, refused (``JSONDecodeError``-like ``ValueError``) when a key repeats:
    which one a reader keeps differs between readers, so the record would not be one truth."""
    data = dict(pairs)
    if len(data) != len(pairs):
        seen: set[str] = set()
        key = next(k for k, _ in pairs if k in seen or seen.add(k))
        raise json.JSONDecodeError(f"the key {_shown(key, 40)} appears twice", "", 0)
    return data


def load_run(path: str | Path) -> Run:
    """Load the run folder ``path``.

    Raises ``ValueError`` with a clear message when ``path`` is not a run folder or ``run.json``
    cannot be read. A run that did not finish loads with ``complete`` False, status
    ``incomplete`` (or ``running`` if its process is still alive), and the reason in
    ``problems``.
    """
    path = Path(path)
    meta = read_meta(path)
    problems: list[str] = []
    steps = _read_csv(path / "steps.csv", STEP_COLUMNS, problems)
    commands = _read_csv(path / "commands.csv", COMMAND_COLUMNS, problems)
    # partial-row and missing-file problems of samples.csv, without reading it
    samples_csv = path / "samples.csv"
    if samples_csv.is_symlink() or (samples_csv.exists() and not samples_csv.is_file()):
        regular_file(samples_csv, "run folder file ")  # a link or a pipe: refused
    if not samples_csv.is_file():
        problems.append("samples.csv is missing")
    else:
        _open_rows(samples_csv, SAMPLE_COLUMNS, problems)[1].close()
    if meta.schema_version == 1:  # version 1 did not count the steps done
        meta.steps_done = len(steps)
    status = meta.status
    unvented = None
    if status == RunStatus.RUNNING and not (meta.process and meta.process.alive()):
        status = RunStatus.INCOMPLETE
        fatal = fatal_error(path)  # the trace faulthandler wrote as the process died
        if fatal:
            problems.append(f"the run's process died of a fatal error ({fatal}) without closing "
                            "its record: the trace of the thread that faulted is in "
                            f"{path / FATAL_TRACE_FILE}")
        elif meta.recorded_on():  # a run folder on a share: its processes are another PC's
            problems.append(f"the run's record is open, written by mkm acquire on "
                            f"{meta.recorded_on()}: this PC cannot tell whether it still records "
                            "there or stopped without closing its record (killed or crashed)")
        else:
            problems.append("the run stopped without closing its record (killed or crashed)")
        # run.json's counter is from its last rewrite; the rows on disk are the truth
        written = Run(path, meta, steps, status).n_samples if samples_csv.is_file() else 0
        if written != meta.counters.get("samples"):
            problems.append(f"samples counted from samples.csv: {written} (run.json said "
                            f"{meta.counters.get('samples')})")
            meta.counters["samples"] = written
        unvented = _unvented(commands)
        if unvented:
            problems.append(unvented)
    elif status == RunStatus.KILLED:
        problems.append(reason_shown(meta.reason))
        unvented = _unvented(commands)
    elif meta.manual_vent_required:
        unvented = "the final vent command failed: the muscle had to be vented by hand"
        problems.append(unvented)
    lost = ([] if status == RunStatus.INCOMPLETE
            else _rows_lost(Run(path, meta, steps, status), samples_csv))
    return Run(path=path, meta=meta, steps=steps, status=status, commands=commands,
               problems=problems + lost + _kept_elsewhere(path), unvented=unvented,
               rows_lost=lost)


def _rows_lost(run: Run, samples_csv: Path) -> list[str]:
    """Rows a closed record counted that its files no longer hold (a copy cut short, a file
    emptied): the run's numbers would be computed from part of it, so the loss is named."""
    lost = []
    counted = run.meta.counters.get("samples")
    if isinstance(counted, int) and samples_csv.is_file():
        held = run.n_samples
        if held < counted:
            lost.append(f"samples.csv holds {held} samples, run.json counted {counted}: "
                        f"{counted - held} lost")
    if (run.path / "steps.csv").is_file() and len(run.steps) < run.meta.steps_done:
        lost.append(f"steps.csv holds {len(run.steps)} steps, run.json counted "
                    f"{run.meta.steps_done} done: {run.meta.steps_done - len(run.steps)} lost")
    return lost


def _unvented(commands: pd.DataFrame) -> str | None:
    """What a dead run left commanded, when its last successful command was not a vent."""
    done = commands[commands["ok"]] if len(commands) else commands
    if done.empty:
        return None
    last = done.iloc[-1]
    if float(last["command_bar"]) == 0.0:
        return None
    return (f"it ended without venting: the last commanded pressure was "
            f"{float(last['command_bar']):g} bar (at {float(last['time_s']):g} s)")


def iter_samples(run_dir: str | Path, chunksize: int = 100_000):
    """``samples.csv`` of the run folder ``run_dir`` as DataFrames of ``chunksize`` rows (whole
    rows only), for passes over long runs in bounded memory."""
    return _read_csv(Path(run_dir) / "samples.csv", SAMPLE_COLUMNS, [], chunksize=chunksize)


def aggregate_samples(path: str | Path, bin_s: float | None = None,
                      max_bins: int = 4000, chunksize: int = 100_000) -> pd.DataFrame:
    """Time bins of ``samples.csv`` in one streamed pass (memory bounded by the chunk and the bin
    count, not by the run's length).

    One row per non-empty bin of ``bin_s`` seconds (default: the run's duration over
    ``max_bins``, at least one sample period): ``time_s`` (bin start), ``n``, ``step`` (last in
    the bin), ``pressure_bar_{min,mean,max}``, ``force_N_{min,mean,max}``, and counts of the
    ``gap``, ``interlock`` and ``timeout`` flags.
    """
    path = Path(path)
    csv = path / "samples.csv" if path.is_dir() else path
    if bin_s is None:
        last = _last_time_s(csv)
        bin_s = max(last / max_bins, 1e-9) if last > 0 else 1.0
    if not bin_s > 0:
        raise ValueError(f"bin_s={bin_s!r} is invalid: expected a duration > 0 s")
    parts = []
    for chunk in _read_csv(csv, SAMPLE_COLUMNS, [], chunksize=chunksize):
        if chunk.empty:
            continue
        time_s = chunk["time_s"].to_numpy(float)
        bins = np.floor(time_s / bin_s)
        bad = ~(np.isfinite(bins) & (time_s >= 0) & (bins < 2**62))  # a bin is an int64
        if bad.any():
            raise ValueError(f"{csv}: time_s={float(time_s[bad][0])!r} is invalid: expected finite "
                             "times >= 0 s from the run's start")
        b = bins.astype(np.int64)
        flags = chunk["flags"].fillna("")
        frame = pd.DataFrame({"bin": b, "step": chunk["step"],
                              "p": chunk["pressure_bar"], "f": chunk["force_N"],
                              "gap": flags.str.contains("gap").astype(int),
                              "interlock": flags.str.contains("interlock").astype(int),
                              "timeout": flags.str.contains("timeout").astype(int)})
        g = frame.groupby("bin")
        parts.append(pd.DataFrame({
            "n": g.size(), "step": g["step"].last(),
            "p_sum": g["p"].sum(), "p_n": g["p"].count(), "p_min": g["p"].min(),
            "p_max": g["p"].max(), "f_sum": g["f"].sum(), "f_n": g["f"].count(),
            "f_min": g["f"].min(), "f_max": g["f"].max(), "gap": g["gap"].sum(),
            "interlock": g["interlock"].sum(), "timeout": g["timeout"].sum()}))
    if not parts:
        return pd.DataFrame(columns=["time_s", "n", "step", "pressure_bar_min",
                                     "pressure_bar_mean", "pressure_bar_max", "force_N_min",
                                     "force_N_mean", "force_N_max", "gap", "interlock",
                                     "timeout"])
    # a bin split across two chunks is merged here
    all_bins = pd.concat(parts).groupby(level=0)
    merged = all_bins.agg({"n": "sum", "step": "last", "p_sum": "sum", "p_n": "sum",
                           "p_min": "min", "p_max": "max", "f_sum": "sum", "f_n": "sum",
                           "f_min": "min", "f_max": "max", "gap": "sum", "interlock": "sum",
                           "timeout": "sum"})
    with np.errstate(invalid="ignore", divide="ignore"):
        out = pd.DataFrame({
            "time_s": merged.index.to_numpy() * bin_s, "n": merged["n"].to_numpy(),
            "step": merged["step"].to_numpy(),
            "pressure_bar_min": merged["p_min"].to_numpy(),
            "pressure_bar_mean": (merged["p_sum"] / merged["p_n"]).to_numpy(),
            "pressure_bar_max": merged["p_max"].to_numpy(),
            "force_N_min": merged["f_min"].to_numpy(),
            "force_N_mean": (merged["f_sum"] / merged["f_n"]).to_numpy(),
            "force_N_max": merged["f_max"].to_numpy(),
            "gap": merged["gap"].to_numpy(), "interlock": merged["interlock"].to_numpy(),
            "timeout": merged["timeout"].to_numpy()})
    return out


def _last_row(csv: Path) -> list[bytes]:
    """The cells of samples.csv's last whole row; [] without one (a missing samples.csv reads
    as no samples: load_run names it)."""
    if not csv.is_file():
        return []
    whole = _whole_rows_bytes(csv)
    with open(csv, "rb") as f:
        f.seek(max(0, whole - 4096))
        lines = f.read(whole - max(0, whole - 4096)).splitlines()
    return lines[-1].split(b",") if len(lines) >= 2 else []


def _last_time_s(csv: Path) -> float:
    try:
        return float(_last_row(csv)[1])
    except (IndexError, ValueError):
        return 0.0
