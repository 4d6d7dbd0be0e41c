"""Measurements in and out of run folders: another lab's table in, a run out to a spreadsheet.

- :func:`import_table`: the table a lab has (CSV, TSV, semicolon CSV with decimal commas, or an
  ``.xlsx`` workbook, every sheet or one; columns found by name and unit by
  :mod:`mkm.bench.tables`, converted by pint) becomes run folders with status ``imported``: one
  per muscle state (a sheet, or a value of an eps, length, L0 or run-id column), all of one
  muscle id. A step table (one row per held pressure) gives the steps as they are (a record
  whose time column was left out, :func:`mkm.bench.series.sampled_without_time`, is read as a
  time series with its rows for its clock, the table kept whole in its run folder); a time
  series (a ``time`` column) is stored as samples and its steps derived
  (:mod:`mkm.bench.series`: a staircase's plateaus as the bench judges them, or a ramp's
  quasi-static bins per branch), its force zeroed at its mean before the pressure rises and a
  vented pressure reading off zero, up to a sensor's zero error (:data:`VENTED_AUTO_MAX_BAR`),
  taken as the record's zero. ``imported_from`` in run.json records the source file's name and
  SHA-256, the sheet, the columns and units recognised, the shape, the tare and the vented
  reading. ``mkm report``, ``mkm fem calibrate --reference``, ``mkm identify`` and
  ``mkm export`` read these runs like any other.
- :func:`export_run`: a run folder as one Excel workbook (sheets ``steps``, ``samples``,
  ``metadata``) or as three CSV files, every text cell spreadsheet-safe. The workbook imports
  back to the run it was: steps, samples, calibration and tare. A run that keeps the table it
  was imported from (:data:`TABLE_COPY`) takes it along: the file as given beside the CSV
  files, the table as read in a sheet of its own, which ``mkm import --sheet`` reads again.
"""

from __future__ import annotations

import datetime
import itertools
import json
import math
import re
import shutil
from dataclasses import asdict, dataclass, replace
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
import pandas as pd

from mkm.bench import series
from mkm.bench.config import MAX_CAPACITY_N
from mkm.bench.sim_settings import INSTRUMENT_BOUNDS
from mkm.bench.storage import (
    RunMeta,
    RunStatus,
    RunWriter,
    Sample,
    StepRecord,
    load_run,
    muscle_from_dict,
)
from mkm.bench.tables import (
    CLOCK_ORIGIN_S,
    SUMMED_ROLES,
    UNIX_TIME_S,
    VOLTS_ROLES,
    Recognition,
    Scaling,
    by_unit_columns,
    check_channel_times,
    column_text,
    counts_rows,
    current_header,
    declared_state,
    directions,
    flags,
    join_by_time,
    join_files,
    key_values,
    marked_gauge,
    numbers_as_read,
    parse_header,
    read_tables,
    recognise,
    require_time_order,
    several_forces,
    sheet_names,
    taken_columns,
    timed_rows,
    unread_columns,
    unread_time_columns,
    volts_header,
    weighed_columns,
    with_milliseconds,
    without_blank_rows,
    without_repeated_rows,
    without_summary_block,
    without_summary_rows,
)
from mkm.core.ranges import parse_number
from mkm.core.records import (
    EXPORT_FORMATS,
    SPREADSHEET_CSV_ENCODING,
    file_sha256,
    provenance,
    spreadsheet_safe,
    spreadsheet_safe_text,
)
from mkm.fem.limits import PRACTICAL_RANGE, check_value, outside

if TYPE_CHECKING:
    from mkm.bench.budget import Declared
    from mkm.fem.tolerances import Tolerances

REQUIRED_ROLES = ("pressure", "force")
#: what to know choosing among columns that each hold a role by their unit
SEVERAL_BY_UNIT = {"pressure": "the sensor at the muscle, not one upstream of the regulator"}
#: columns whose values split one table into runs (one muscle state each)
SPLIT_ROLES = ("run", "eps", "length", "L0")
EXCEL_MAX_ROWS = 1_048_575  # below the header row
#: the sheets of mkm's own export: its steps sheet is the table, its metadata the muscle
EXPORT_SHEETS = ("steps", "samples", "metadata")
#: ``--tare`` and ``--vented``: found in the data (auto), none, or a value given
ZERO_CHOICES = ("auto", "none")
#: a step table's closing 0 bar rows said to read another zero than its opening one beyond this
#: [N]: two ADC steps of a bench's load cell, the slack steps' floor identify uses for a table
#: (:data:`mkm.identify.goodness.ZERO_FLOOR_N`), where no force accuracy is declared
TABLE_ZERO_DRIFT_N = 0.5
#: ... and one beyond this share of its largest force may be a load cell zeroed again at a
#: row (:func:`_table_zero_drift`), its tare pressed with the muscle pulling
TABLE_ZERO_STEP_SHARE = 0.05
#: ``--tare linear``: a time series' zero taken at its rests before the rise and after the vent
#: that ends it, joined by a line in time (a load cell that drifted through the record)
LINEAR_TARE = "linear"
#: the name (and the table's suffix) of the copy of a table kept in the run folder where its
#: rows are no run folder's samples (a record without time, binned), or of mkm export's
#: workbook that carried that table in its sheet of this name
TABLE_COPY = "imported_table"
#: ``--force-sign``: the table's forces as read (a muscle's pull positive), or negated (a load
#: cell wired to read tension negative)
FORCE_SIGNS = (1, -1)

#: what a lab may declare of its muscle beyond its size: the braid angle and the rubber
DECLARED = ("theta0_deg", "C10_MPa", "C01_MPa")


#: What a given zero may be [its unit], and why. A vented pressure sensor reads its offset: at
#: most the half bar the simulator allows a sensor's offset below zero (more is a broken
#: sensor), and above zero up to the top of the practical range (an absolute sensor reads
#: 1.013 bar vented; 8 bar vented is no offset of a muscle's sensor). A tare is a load cell's
#: reading: within the largest cell a bench configuration accepts.
ZERO_LIMITS = {"--tare": (-MAX_CAPACITY_N, MAX_CAPACITY_N,
                          "the largest load cell a bench takes"),
               "--vented": (-INSTRUMENT_BOUNDS["monitor_offset_bar"][1],
                            PRACTICAL_RANGE.pressure_bar[1],
                            "a pressure sensor's offset below zero, the practical range above")}


#: the largest vented reading ``--vented auto`` subtracts [bar]: a gauge's zero error, at most
#: the offset a pressure sensor may have (as :data:`ZERO_LIMITS`). A record held higher at its
#: start was pressurised when the logging began, or its sensor reads absolute pressure (the
#: ambient 0.5-1.05 bar): the data cannot tell these apart, and a pressure column is a gauge
#: pressure, so its readings are kept and the option that says otherwise is named
VENTED_AUTO_MAX_BAR = INSTRUMENT_BOUNDS["monitor_offset_bar"][1]
#: what an absolute sensor reads vented [bar]: the atmosphere from a high-pressure day at sea
#: level (1.05 bar) to a lab 4000 m up (0.62 bar). A record held within it at its start, its
#: lowest level, that ends there too is refused unless ``--vented`` says which it is: read as
#: gauge, a muscle tared nowhere pulls from the atmosphere up, and identify then blames its
#: length
ATMOSPHERE_BAR = (0.6, 1.1)


#: a pressure sensor's zero error where a table declares no pressure accuracy, as a fraction of
#: the span: 1 % of full scale, the class of a proportional regulator's readback (Festo VPPM,
#: SMC ITV), of a sensor spanning the practical range
GAUGE_ZERO_ERROR_OF_SPAN = 0.01


def _below_zero_bound(pressure: np.ndarray, declared: Declared | None):
    """How far below 0 bar each reading of a step table may lie and still be a vented row
    [bar], and that bound in words: the declared pressure accuracy at the reading, else a
    gauge's zero error (:data:`GAUGE_ZERO_ERROR_OF_SPAN` of the practical range)."""
    if declared is not None:
        at = " at that reading" if declared.fraction else ""
        noise = series.PLATEAU_TOLERANCE_BAR  # a reading's noise, whatever its accuracy
        return (np.maximum(declared.absolute + declared.fraction * np.abs(pressure), noise),
                lambda bound: (f"the declared pressure accuracy, +-{bound:.3g} bar{at}"
                               if bound > noise else f"a reading's noise, +-{noise:g} bar")
                + f" (--accuracy pressure={declared.text})")
    top = PRACTICAL_RANGE.pressure_bar[1]
    return (np.full(pressure.shape, GAUGE_ZERO_ERROR_OF_SPAN * top),
            lambda bound: f"a gauge's zero error, +-{bound:g} bar where no pressure accuracy "
            f"is declared ({100 * GAUGE_ZERO_ERROR_OF_SPAN:g} % of the practical range's "
            f"{top:g} bar)")


#: what a given zero may look like typed with its unit (for the messages)
ZERO_EXAMPLES = {"N": "1.5N or 0.2kgf", "bar": "0.02bar or 1013mbar"}


def parse_zero(text: str | float | None, option: str, unit: str) -> str | float:
    """``auto``, ``none`` (``--tare``: or ``linear``) or a number within :data:`ZERO_LIMITS`,
    typed as the other options' (``--tare 3.2``, ``1,5``, ``0.2kgf``; ``--vented 0.6``,
    ``1013mbar``)."""
    choices = (*ZERO_CHOICES, LINEAR_TARE) if option == "--tare" else ZERO_CHOICES
    if text is None or text in choices:
        return text or "auto"
    value = parse_number(str(text), option, unit, f"{', '.join(choices)} or a number in "
                         f"{unit}, or one with a unit such as {ZERO_EXAMPLES[unit]}")
    low, high, why = ZERO_LIMITS.get(option, (-math.inf, math.inf, ""))
    if not low <= value <= high:
        raise ValueError(f"{option} {text!r} is invalid: expected a number in [{low:g}, "
                         f"{high:g}] {unit} ({why})")
    return value


#: the largest bound ``--accuracy`` takes for each quantity [its unit], and why: beyond it the
#: value says nothing (a fraction of 100 %) or the table is not a measurement of a braided muscle
ACCURACY_LIMITS = {"force": (MAX_CAPACITY_N, "the largest load cell a bench takes"),
                   "pressure": (PRACTICAL_RANGE.pressure_bar[1], "the practical range's top")}
_BOUND_PART = re.compile(r"^(?P<number>\d*[.,]?\d+(?:[eE][+-]?\d+)?)\s*(?P<unit>.*)$")


def parse_accuracy(text: str | None) -> dict[str, Declared]:
    """``--accuracy force=0.5N+0.2%,pressure=0.01bar`` -> quantity -> :class:`Declared`: each
    bound a sum of parts, a number with a unit of the quantity (converted by pint; a bare number
    is N or bar) or a percentage of the value; ``ValueError`` naming a bad item."""
    from mkm.bench.budget import DECLARED_QUANTITIES, Declared
    from mkm.bench.tables import parse_assignments, parse_unit, registry

    out = {}
    for quantity, given in parse_assignments(text, "--accuracy", DECLARED_QUANTITIES).items():
        unit, (largest, why) = DECLARED_QUANTITIES[quantity], ACCURACY_LIMITS[quantity]
        expected = (f"expected a +- bound such as {quantity}=0.5{unit}, {quantity}=1% (of each "
                    f"value) or their sum {quantity}=0.5{unit}+1%")
        absolute = fraction = 0.0
        for part in given.split("+"):
            match = _BOUND_PART.match(part.strip())
            if not match:
                raise ValueError(f"--accuracy {quantity}={given} is invalid: {expected}")
            number = float(match["number"].replace(",", "."))
            written = match["unit"].strip()
            if written == "%":
                fraction += number / 100.0
                continue
            if written.lower().replace(" ", "") in ("%fs", "%offullscale", "%f.s."):
                raise ValueError(f"--accuracy {quantity}={given}: a share of full scale is a "
                                 f"bound in {unit} (0.1 % of a 500 {unit} range: 0.5{unit}): "
                                 f"{expected}")
            found = parse_unit(written) if written else registry().Unit(unit)
            if found is None or found.dimensionality != registry().Unit(unit).dimensionality:
                raise ValueError(f"--accuracy {quantity}={given}: {written!r} is not a unit of "
                                 f"{quantity}: {expected}")
            absolute += float(registry().Quantity(number, found).to(unit).magnitude)
        if not (absolute > 0 or fraction > 0):
            raise ValueError(f"--accuracy {quantity}={given}: a bound of 0 claims exact values: "
                             f"{expected}")
        if fraction >= 1 or absolute > largest:
            raise ValueError(f"--accuracy {quantity}={given} is invalid: expected less than "
                             f"100 % and at most {largest:g} {unit} ({why})")
        out[quantity] = Declared(absolute, fraction, given)
    return out


@dataclass
class ImportedRun:
    """One run folder written by :func:`import_table` and what was done to make it."""

    path: Path
    state: str  # the muscle state: "eps 0.0473", "sheet 'B'"
    shape: str  # "steps", "staircase" or "ramp"
    n_steps: int
    notes: list[str]
    #: the steps on the rising branches and on the falling ones
    branches: tuple[int, int] = (0, 0)

    def line(self) -> str:
        made = {"steps": "one table row each", "staircase": "the plateaus of a staircase",
                "ramp": "quasi-static bins of a ramp",
                "export": "the exported run's own, with its samples"}[self.shape]
        up, down = self.branches
        # both branches kept: said, so a loading and an unloading sweep are seen apart
        apart = f" ({up} rising, {down} falling)" if up and down else ""
        return f"{self.state}: {self.n_steps} step(s){apart}, {made}" + "".join(
            f"; {n}" for n in self.notes)


def check_sample_rate(rate_hz: float) -> float:
    """``rate_hz`` if it is a rate rows can be logged at, finite and above 0 Hz, its period
    ``1 / rate_hz`` a number too; ``ValueError`` naming it otherwise."""
    if not (math.isfinite(rate_hz) and rate_hz > 0 and math.isfinite(1.0 / rate_hz)):
        raise ValueError(f"--sample-rate {rate_hz:g} Hz is invalid: expected the rate the "
                         "table's rows were logged at, a finite number > 0 Hz (100, 1kHz)")
    return rate_hz


def import_table(path: str | Path | list[str | Path], out_root: str | Path, muscle: dict, *,
                 columns: dict[str, str] | None = None, units: dict[str, str] | None = None,
                 sheet: str | None = None, tare: str | float = "auto",
                 vented: str | float = "auto", select: str | None = None,
                 accuracy: dict[str, Declared] | None = None, force_sign: int = 1,
                 one_step_per_row: bool = False, join: str | Path | None = None,
                 join_shift_s: float | None = None, scaling: dict[str, Scaling] | None = None,
                 sample_rate_hz: float | None = None, tolerances: Tolerances | None = None,
                 between_files_s: float | None = None, notify=lambda line: None,
                 bar=None) -> list[ImportedRun]:
    """Run folders (status ``imported``) under ``out_root`` from the table ``path`` (see the
    module docstring).

    Parameters
    ----------
    path : path or list of paths
        The table; several files: one record logged a file per pressure step, each with a time
        column, read as one table (:func:`mkm.bench.tables.join_files`: ordered by their clock
        where it continues, else in the order given), every file's SHA-256 recorded.
    muscle : dict
        ``id``, ``D0_mm``, ``t0_mm`` and, unless the table has them, ``L0_mm`` and ``eps``
        (``None``: take them from the table); optionally :data:`DECLARED`, the braid angle and
        rubber the lab declares (recorded with each run: identify's nominal muscle, the
        report's prediction).
    columns, units : dict, optional
        Role -> column header, role -> unit: the reader's guesses overridden.
    sheet : str, optional
        The workbook's sheet to read (default: every sheet holding pressure and force).
    tare : "auto", "none" or float
        The force's zero [N]: a step table's force at the lowest pressure of its rising
        branch, a time series' mean force before its pressure rises (``auto``; only when that
        pressure is 0 bar, else the 0 bar rows or the vented rest that end the table), none,
        or this value.
    vented : "auto", "none" or float
        The pressure read vented [bar], subtracted from a time series' pressures: detected
        (``auto``), none, or this value (subtracted from a step table's too).
    select : str, optional
        The muscle to import where the table's muscle column holds several.
    accuracy : dict, optional
        Quantity -> :class:`mkm.bench.budget.Declared`: the +- bounds the lab declares for its
        forces and pressures (:func:`parse_accuracy`). Each step then carries its uncertainty
        budget (:func:`mkm.bench.budget.declared_budget`), so ``mkm report`` scores E_n and
        ``mkm identify`` judges its fit; without it neither can.
    force_sign : 1 or -1
        -1: the table's forces negated (a load cell that reads the muscle's pull negative); a
        ``tare`` given is as the table reads it.
    one_step_per_row : bool
        Every row a step, at its time where the table has one: a fine step table of more
        than :data:`mkm.bench.series.RECORD_MIN_ROWS` rows is otherwise read as a record
        without its time (:func:`mkm.bench.series.sampled_without_time`), and a time column as
        a time series.
    join : path, optional
        Another table of the same record holding what ``path``'s tables lack (the force, or
        the pressure, with its time), joined to each by time
        (:func:`mkm.bench.tables.join_by_time`).
    join_shift_s : float, optional
        The seconds ``join``'s times are moved later on the table's clock: where each counts
        from its own start, when its logger started after the table's (required then);
        where both are date-times or clock readings, how far its clock runs behind.
    scaling : dict, optional
        Role -> :class:`mkm.bench.tables.Scaling`, or of summed load cells
        :class:`mkm.bench.tables.SummedScaling`, or of a 4-20 mA channel
        :class:`mkm.bench.tables.CurrentLoop`: how a channel logged in volts or mA becomes a
        pressure or a force (:func:`mkm.bench.tables.parse_scaling`); a channel in volts or
        mA without one is refused.
    sample_rate_hz : float, optional
        The rate the table's rows were logged at [Hz], for a table without a clock (or with a
        row counter, :func:`mkm.bench.tables.counts_rows`): row ``k`` at ``k / sample_rate_hz``
        seconds (:func:`mkm.bench.tables.timed_rows`), a time series; refused for a table with
        a time column, for ``mkm export``'s workbook and with ``join``. A LabChart export
        without its time column is timed so by its header's ``Interval=``, a LabVIEW
        measurement file by its ``Delta_X`` (a rate given must agree with it).
    between_files_s : float, optional
        Several files whose clocks each restart: the seconds from one file's last sample to
        the next one's first (default: one sample interval, each hold's creep timed from its
        file's start).
    tolerances : mkm.fem.tolerances.Tolerances, optional
        The +- tolerances the muscle was made to, recorded with each run as a bench run records
        its configuration's ``[muscle.tolerances]`` (``calibration.muscle_tolerances``): what
        ``mkm identify`` draws into its intervals and ``mkm report`` into its bands (default:
        none recorded, :class:`~mkm.fem.tolerances.Tolerances`' defaults taken).
    notify : callable
        Receives the line of what was recognised in each table.
    bar : optional
        A progress bar with tqdm's ``total``, ``update`` and ``set_postfix_str``
        (:func:`mkm.progress.progress_bar` on the command line): one unit per stage (reading the
        file, recognising each table, finding each run's steps, writing each run folder), its
        total growing as the stages become known, the stage named before it starts (a record
        of 600,000 rows takes 15 s, more on a busy machine).

    Raises ``ValueError`` naming the file and the cell of what cannot be imported; nothing is
    written then.
    """
    paths = [Path(p) for p in path] if isinstance(path, list | tuple) else [Path(path)]
    path, several = paths[0], len(paths) > 1
    bar = _Stages(bar)
    if between_files_s is not None and not several:
        raise ValueError(f"--between-files {between_files_s:g} s: one file, {path.name}: "
                         "expected the option with the several files of one record")
    if several and sheet is not None:
        raise ValueError(f"--sheet {sheet!r} with {len(paths)} files: expected one table in "
                         "each file of a record logged as several files")
    if join_shift_s is not None and join is None:
        raise ValueError(f"--join-shift {join_shift_s:g} s: no --join-by-time FILE: expected it "
                         "with the file whose times it moves")
    if sample_rate_hz is not None:
        check_sample_rate(sample_rate_hz)
        if join is not None:
            raise ValueError(f"--sample-rate {sample_rate_hz:g} Hz with --join-by-time "
                             f"{Path(join).name}: expected a time column in both tables to "
                             "join by, and --sample-rate only for a table without one")
    if force_sign not in FORCE_SIGNS:
        raise ValueError(f"--force-sign {force_sign!r} is invalid: expected one of "
                         f"{', '.join(map(str, FORCE_SIGNS))}")
    muscle = dict(muscle)
    tare, vented = parse_zero(tare, "--tare", "N"), parse_zero(vented, "--vented", "bar")
    exported = not several and sheet is None and set(EXPORT_SHEETS) <= set(sheet_names(path))
    if exported and sample_rate_hz is not None:  # its samples have their times
        raise ValueError(f"--sample-rate {sample_rate_hz:g} Hz: {path.name} is a run mkm "
                         "export wrote, its samples timed: expected the option only for a "
                         "table without a clock")
    if exported:  # mkm export's own
        known = key_values(path, "metadata")
        for key in ("id", "D0_mm", "t0_mm", "L0_mm", "eps", *DECLARED):
            if muscle.get(key) is None and f"muscle.{key}" in known:
                muscle[key] = known[f"muscle.{key}"]
        sheet = "steps"
        if tare == "auto":  # its forces were zeroed when it was recorded or imported
            tare = "none"
    bar.start(f"reading {path.name}" + (f" and {len(paths) - 1} more" if several else ""))
    joined = join_files(paths, columns, units, scaling, between_files_s) if several else None
    tables = [joined.table] if joined else read_tables(path, sheet)
    bar.done(len(tables))
    names = [t.sheet for t in tables]
    other = _join_table(join, scaling) if join is not None else None
    prepared, skipped = [], []
    for table in tables:
        bar.start(f"recognising {table.name}")
        table, found = ((table, dict(joined.found)) if joined else
                        with_milliseconds(table, recognise(table, columns, units, scaling)))
        # a logger's row numbers under a clock's name: read as seconds, a 1 Hz clock the file
        # does not say
        counter = found.pop("time").header if counts_rows(table, found.get("time")) else None
        rate_hz, rate_from = sample_rate_hz, "--sample-rate"
        if "time" not in found and table.interval is not None:
            # a LabChart export or a LabVIEW measurement file saved without its time column:
            # its header states the rate
            written, interval_s = table.interval
            rate_from = f"the header's {written}"
            if rate_hz is not None and not math.isclose(rate_hz * interval_s, 1.0,
                                                        rel_tol=1e-9):
                raise ValueError(f"--sample-rate {rate_hz:g} Hz: {table.name}'s header states "
                                 f"{written}, {1.0 / interval_s:g} Hz: expected the "
                                 "rate its rows were logged at; without --sample-rate the "
                                 "header's is taken")
            rate_hz = 1.0 / interval_s
        if rate_hz is not None:
            if "time" in found:  # two clocks that may disagree: the file's is not overridden
                raise ValueError(f"--sample-rate {rate_hz:g} Hz: {table.name} has a "
                                 f"time column, {found['time'].header!r}: expected the option "
                                 "only for a table without one (its rows logged evenly at that "
                                 "rate)")
            table, found["time"] = timed_rows(table, rate_hz)
        missing = [r for r in REQUIRED_ROLES if r not in found]
        if other is not None:
            if counter:
                raise ValueError(f"--join-by-time {Path(join).name}: {table.name}'s column "
                                 f"{counter!r} counts the rows (whole numbers stepping by 1, no "
                                 "unit), no clock to join by: expected a time column in both "
                                 "tables; if it is seconds, --units time=s reads it so")
            if not missing:
                raise ValueError(f"--join-by-time {Path(join).name}: {table.name} holds a "
                                 "pressure and a force column itself: expected the other table "
                                 "to give the one it lacks")
            table, found = join_by_time(table, found, *other, missing, join_shift_s)
            table.joined["sha256"] = file_sha256(join)
            missing = []
        if missing and len(tables) > 1 and not any(
                len(by_unit_columns(table, r, found)) > 1 for r in missing):
            # a sheet of notes or of the lab's results beside the measurements: named below
            skipped.append(f"{table.sheet!r} ({_lacks(table, missing)})")
            continue
        for role in missing:
            if len(by_unit := by_unit_columns(table, role, found)) > 1:
                shown = [repr(table.header[k]) for k in by_unit]
                what = (f": {several_forces([table.header[k] for k in by_unit])}"
                        if role in SUMMED_ROLES else f", chosen with --columns {role}=COLUMN "
                        f"({SEVERAL_BY_UNIT[role]})")
                raise ValueError(f"{table.name}: no column is named a {role}, and "
                                 f"{len(shown)} hold one by their unit, "
                                 f"{', '.join(shown[:-1])} and {shown[-1]}: which is the "
                                 f"muscle's is not guessed: expected one{what}")
        if missing:
            in_volts = [h for h in table.header if h and volts_header(h)]
            in_mA = [h for h in table.header if h and current_header(h)]
            raise ValueError(f"{table.name}: no {' or '.join(missing)} column among "
                             f"{', '.join(repr(h) for h in table.header if h) or 'no header'}: "
                             f"name it with --columns {missing[0]}=COLUMN (and --units "
                             f"{missing[0]}=UNIT"
                             + (f"; a channel in volts, {in_volts[0]!r}, with --sensitivity "
                                f"{missing[0]}={VOLTS_ROLES[missing[0]][0]}" if in_volts
                                else "")
                             + (f"; a 4-20 mA channel, {in_mA[0]!r}, with --current-range "
                                f"{missing[0]}=LOW:HIGH" if in_mA else "") + ")"
                             + "".join((f"; {h!r} names {why}, not taken by its unit"
                                        if parse_header(h)[1] else
                                        f"; by its name, {h!r} is {why}, no reading")
                                       + f": --columns {missing[0]}={h!r} reads it"
                                       for h, why in unread_columns(table, missing[0])[:1])
                             + "".join(f"; {h!r} holds a mass: a scale's, or a load cell "
                                       "showing the weight it holds, is read with --columns "
                                       f"force={h!r} --units force={weight}"
                                       for h, weight in weighed_columns(table)[:1]
                                       if "force" in missing))
        table = without_summary_rows(table)
        if "time" in found:
            table = without_summary_block(table, found["time"])
        table = without_blank_rows(table, [found[r] for r in (*REQUIRED_ROLES, "time")
                                           if r in found])
        if "time" in found:  # a step table's rows may repeat a step; a record's are samples
            table = without_repeated_rows(table, [found[r] for r in ("time", *REQUIRED_ROLES)])
            check_channel_times(table, found)
        recognition = Recognition(table, found, [h for k, h in enumerate(table.header) if h and
                                                 k not in taken_columns(found)], counter,
                                  rate_hz, None if rate_hz is None else rate_from)
        # without a time column every row is a step, or a record's rows are taken as evenly
        # spaced (or timed by --sample-rate): a clock by a name the reader does not know is
        # left out, and named (an export's steps have times)
        unread = [] if exported or ("time" in found and rate_hz is None) else \
            unread_time_columns(table, found)
        if rate_hz is not None:
            read_as = timed_by = f"the rows timed at {rate_hz:g} Hz ({rate_from})"
        else:
            read_as = ("its rows are taken as evenly spaced in time" if (unread or counter) and
                       not one_step_per_row and
                       series.sampled_without_time(recognition.values("pressure"))
                       else "every row is a step")
            timed_by = (f"{read_as}; if it is seconds, --units time=s reads it as a 1 Hz "
                        "clock, and --sample-rate HZ times the rows at another rate")
        notify(f"{table.name}: {recognition.line()}"
               + (f"; column {counter!r} counts the rows (whole numbers stepping by 1, no "
                  f"unit), no clock: {timed_by}" if counter else "")
               + "".join(f"; column {header!r} holds times but is not read as the time "
                         f"column: {read_as}; if it is the record's clock, --columns "
                         f"time={header!r}"
                         + (" without --sample-rate" if sample_rate_hz is not None else "")
                         + " reads the table as a time series"
                         for header in unread[:1]))
        prepared.append(recognition)
        bar.done()
    part = tables[0].part  # a workbook's sheets, a TDMS file's groups
    if not prepared:  # each sheet's lack named, and how to name a column the reader missed
        raise ValueError(f"{path.name}: no {part} holds a pressure and a force column ({part}s "
                         f"{', '.join(skipped or map(repr, names))}): name them with --columns "
                         f"pressure=COLUMN,force=COLUMN (and --units; --{part} NAME reads one "
                         f"{part})")
    if skipped:
        notify(f"{path.name}: {part}s without a pressure and a force column skipped: "
               f"{', '.join(skipped)}")
    for role, scale in (scaling or {}).items():  # given for no column: it would be ignored
        if not any(r.columns[role].scale or role in r.table.joined.get("columns", {})
                   for r in prepared):
            raise ValueError(f"{scale.option} {role}={scale.text}: "
                             f"{prepared[0].table.name}'s {role} column "
                             f"{prepared[0].columns[role].header!r} is not logged in "
                             f"{scale.reads}: expected it only for {scale.channel}")
    groups = []
    for recognition in prepared:
        groups += _groups(recognition, select, several_sheets=len(prepared) > 1)
    muscles = [_muscle(muscle, g) for g in groups]  # every run checked before any is written
    sha = None if joined else file_sha256(path)
    bar.more(2 * len(groups))
    built = []
    for g, (m, override, (header_notes, header_record)) in zip(groups, muscles, strict=True):
        bar.start(f"finding the steps of {g.state}")
        built.append(_build(path, sha, g, m, tare, vented, accuracy or {}, override,
                            force_sign, one_step_per_row))
        built[-1][3][:0] = header_notes  # where the muscle came from, said first
        if header_record:
            built[-1][0].imported_from["declared_in_header"] = header_record
        if joined:  # each file named with its SHA-256, and how they were joined said first
            imported = built[-1][0].imported_from
            del imported["sha256"]
            imported.update(file=tables[0].source.name, files=joined.files,
                            clock=joined.clock, between_files_s=between_files_s)
            built[-1][3].insert(0, joined.note)
            if joined.origin_s is not None:
                built[-1][3].insert(1, _counted_from(
                    joined.found["time"].header, joined.origin_s,
                    f"the first row of {joined.files[0]['file']}", imported))
            if apart := _files_apart(built[-1][1], joined.files):
                built[-1][3].append(apart)
        bar.done()
    shared = [k for k, g in enumerate(groups) if not {"eps", "length"} & set(g.columns)]
    if len(prepared) > 1 and len(shared) > 1 and muscle.get("eps") is not None:
        # a workbook of one sheet per state, its sheets told apart by their names alone
        for k in shared:
            built[k][3].append(f"eps {float(muscle['eps']):g} from --eps for each of the "
                               f"{len(shared)} {part}s without an eps or length column: if "
                               f"they hold different states, import each with --{part} NAME "
                               "and its --eps")
    if exported and len(built) == 1 and not accuracy:
        built = [_restored(path, known, *built[0])]
    from mkm.bench.run import check_out_root

    check_out_root(out_root)
    out, muscles = [], [b[0].muscle for b in built]
    for g, (meta, steps, samples, notes, shape) in zip(groups, built, strict=True):
        if tolerances is not None:
            meta = replace(meta, muscle=replace(meta.muscle, tolerances=tolerances),
                           calibration={**meta.calibration,
                                        "muscle_tolerances": asdict(tolerances)})
        label = _folder_label(meta.muscle, muscles)
        bar.start(f"writing the run folder of {g.state}")
        writer = RunWriter(out_root, meta, f"# imported from {tables[0].source.name}: no bench "
                           "configuration\n", label)
        writer.append_samples(samples)
        for step in steps:
            writer.append_step(step)
        writer.close()
        if copy := meta.imported_from.get("table_copy"):
            shutil.copyfile(path, writer.path / copy)
        rising = sum(s.direction == "up" for s in steps)
        out.append(ImportedRun(writer.path, g.state, shape, len(steps), notes,
                               (rising, len(steps) - rising)))
        bar.done()
    bar.end()
    return out


#: two steps of one branch at one pressure, in two of a record's files, whose forces lie this
#: share of the larger apart are said: a muscle's cycles repeat far closer, another length or
#: another muscle does not ...
FILES_APART_SHARE = 0.25
#: ... where the larger pulls this share of the record's largest step force at least (a slack
#: muscle's steps read the load cell's noise, any share of it apart)
FILES_APART_FLOOR = 0.1


def _files_apart(steps: list[StepRecord], files: list[dict]) -> str:
    """The note on the steps of several files (:func:`mkm.bench.tables.join_files`) whose
    forces at one pressure, on one branch, lie :data:`FILES_APART_SHARE` apart or more in two
    files (the larger pair said; above :data:`FILES_APART_FLOOR`): files of two muscle states no
    column tells apart, or ``""``.
    A step's file is the one whose span on the run's clock holds its start."""
    starts = np.array([f["placed_at_s"] for f in files])
    floor = FILES_APART_FLOOR * max((abs(s.force_N_mean) for s in steps), default=0.0)

    def file_of(step: StepRecord) -> str:
        return files[max(int(np.searchsorted(starts, step.start_s, side="right")) - 1, 0)]["file"]

    worst = None
    for a, b in itertools.combinations(steps, 2):
        larger = max(abs(a.force_N_mean), abs(b.force_N_mean))
        if (a.direction != b.direction or not larger > floor
                or abs(a.pressure_bar_mean - b.pressure_bar_mean) > series.PLATEAU_TOLERANCE_BAR
                or file_of(a) == file_of(b)):
            continue
        share = abs(a.force_N_mean - b.force_N_mean) / larger
        if share >= FILES_APART_SHARE and (worst is None or share > worst[0]):
            worst = (share, a, b)
    if worst is None:
        return ""
    share, a, b = worst
    branch = "rising" if a.direction == "up" else "falling"
    return (f"{branch} at {a.pressure_bar_mean:.3g} bar, {file_of(a)} reads "
            f"{a.force_N_mean:.4g} N and {file_of(b)} {b.force_N_mean:.4g} N, "
            f"{100 * share:.0f} % apart, where a muscle's cycles repeat far closer: if the files "
            "hold two lengths or two muscles, import each one's files as a run of its own, with "
            "its --eps (or --id)")


def _lacks(table, missing: list[str]) -> str:
    """What a sheet skipped lacks, in words: ``neither``, or ``no force column`` and the
    columns of that unit whose names make them no reading (a statistic, ``'F max (N)'``, or
    the supply pressure)."""
    if len(missing) > 1:
        return "neither"
    named = unread_columns(table, missing[0])
    return f"no {missing[0]} column" + "".join(f"; {h!r} is {why}, no reading"
                                               for h, why in named[:1])


def _join_table(path: str | Path, scaling=None):
    """The table of ``--join-by-time`` and its columns: a text table, or the one sheet of a
    workbook holding a time column (``scaling``: its channels logged in volts)."""
    tables = read_tables(path)
    timed = [(t, found) for t in tables if "time" in (found := recognise(t, scaling=scaling))]
    if len(tables) > 1 and len(timed) != 1:
        raise ValueError(f"--join-by-time {Path(path).name}: {len(timed)} of its sheets hold a "
                         f"time column: expected one (sheets "
                         f"{', '.join(repr(t.sheet) for t in tables)}); save it alone")
    table, found = with_milliseconds(*timed[0] if timed else
                                     (tables[0], recognise(tables[0], scaling=scaling)))
    if counts_rows(table, found.get("time")):  # read as seconds, a 1 Hz clock it does not say
        header = found["time"].header
        raise ValueError(f"--join-by-time {Path(path).name}: its column {header!r} counts the "
                         "rows (whole numbers stepping by 1, no unit), no clock to join by: "
                         f"expected a time column in both tables; if it is seconds, name its "
                         f"unit in the header ('{header} [s]')")
    return table, found


class _Stages:
    """:func:`import_table`'s stages on a tqdm-like ``bar`` (None: none shown). A stage
    finished is counted as the next one is named: a status line, printed as the count goes up
    (:class:`mkm.progress.StatusLine`), names the stage running, not the one just finished."""

    def __init__(self, bar):
        self.bar, self.finished = bar, 0
        if bar is not None:
            bar.total = 1  # reading the file: the rest is known once it is read

    def start(self, doing: str) -> None:
        if self.bar is not None:
            self.bar.set_postfix_str(doing)
            self._count()

    def more(self, stages: int) -> None:
        if self.bar is not None:
            self.bar.total += stages

    def done(self, more: int = 0) -> None:
        """One stage finished, ``more`` now known to follow."""
        self.more(more)
        self.finished += 1

    def end(self) -> None:
        """Every stage finished: counted, none named."""
        if self.bar is not None:
            self.bar.set_postfix_str("")
            self._count()

    def _count(self) -> None:
        if self.finished:
            self.bar.update(self.finished)
            self.finished = 0


def _restored(path: Path, known: dict, meta, steps, samples, notes, shape):
    """mkm export's workbook as the run it was: its steps as recorded (set pressures, holds,
    uncertainty budgets), its samples, its calibration, tare, hardware, sequence (the settling
    tolerance the report scores with) and whether it was simulated (from ``known``, its
    metadata sheet), each sheet checked as a run folder's files are
    (:func:`mkm.bench.storage.checked_rows`)."""
    from mkm.bench.storage import SAMPLE_COLUMNS, STEP_COLUMNS, checked_rows

    sheets = {name: pd.read_excel(path, sheet_name=name, dtype={
        c: "string" for c in ("direction", "phase", "flags")}) for name in ("steps", "samples")}
    recorded = sheets["steps"]
    if not set(STEP_COLUMNS) <= set(recorded.columns) or len(recorded) != len(steps):
        return meta, steps, samples, notes, shape  # edited since: read as any table
    where = f"{path.name}, sheet"
    steps = [StepRecord(*row) for row in checked_rows(
        recorded[list(STEP_COLUMNS)].copy(), f"{where} 'steps'").astype(object).itertuples(
        index=False)]
    rows = sheets["samples"]
    if set(SAMPLE_COLUMNS) <= set(rows.columns) and len(rows):
        samples = [Sample(*row) for row in checked_rows(
            rows[list(SAMPLE_COLUMNS)].copy(), f"{where} 'samples'").astype(object).itertuples(
            index=False)]
        notes.insert(0, f"{len(samples)} samples")
        shape = "export"
        meta.reason = (f"imported from {path.name}: mkm export's workbook, its steps and "
                       "samples as recorded")
    for part in ("calibration", "tare", "hardware", "sequence"):
        restored = _unflattened(known, part)
        if restored:
            setattr(meta, part, restored)
    # a simulated run stays one: read back as a measurement, its report would not say it
    meta.simulated = _cell_value(known.get("simulated")) is True
    status, reason = known.get("status"), known.get("reason")
    if status and status != "complete":  # a run cut short stays marked with why
        meta.reason += f"; recorded as {status}: {reason or 'no reason recorded'}"
    meta.imported_from = {**meta.imported_from, "shape": shape,
                          "restored": "steps, samples, calibration, tare, hardware and sequence of "
                          "mkm export",
                          "recorded_status": status, "recorded_reason": reason}
    if TABLE_COPY in sheet_names(path):  # the table the exported run came from, carried on
        meta.imported_from.update(table_copy=TABLE_COPY + path.suffix.lower(),
                                  table_copy_sheet=TABLE_COPY)
    meta.counters["samples"] = len(samples)
    return meta, steps, samples, notes, shape


def _unflattened(known: dict, part: str) -> dict:
    """The ``part.`` keys of mkm export's metadata sheet (:func:`_flatten`) as run.json held
    them: nested, each cell's number, bool, list or text back."""
    out: dict = {}
    for key, cell in known.items():
        if not key.startswith(f"{part}."):
            continue
        node, *path = key.split(".")[1:][::-1]
        target = out
        for name in reversed(path):
            target = target.setdefault(name, {})
        target[node] = _cell_value(cell)
    return out


def _cell_value(cell):
    if cell is None or cell == "":
        return None
    if isinstance(cell, str):
        if cell[:1] == "'" and spreadsheet_safe_text(cell[1:]) == cell:
            # the export's guard against a formula (a negative number written as text starts
            # like one), not part of the value
            cell = cell[1:]
        if cell in ("True", "False"):
            return cell == "True"
        try:
            return json.loads(cell)
        except ValueError:
            return cell
    return cell


def _folder_label(muscle, muscles) -> str:
    """What tells one run of a table from the others in its folder's name (not the second it
    was written in): its eps, and its rest length where the table holds several; empty for a
    table of one run."""
    if len(muscles) < 2:
        return ""
    several_L0 = len({m.L0_mm for m in muscles}) > 1
    return f"{f'L0{muscle.L0_mm:g}mm-' if several_L0 else ''}eps{muscle.eps:.4g}"


@dataclass
class _Group:
    """The rows of one muscle state in one table."""

    recognition: Recognition
    rows: np.ndarray
    state: str
    key: dict

    @property
    def table(self):
        return self.recognition.table

    @property
    def columns(self):
        return self.recognition.columns

    def values(self, role: str, optional: bool = False) -> np.ndarray:
        return self.recognition.values(role, optional)[self.rows]

    def cell(self, k: int, role: str) -> str:
        return self.table.ref(int(self.rows[k]), self.columns[role].index)

    def where(self, k: int, role: str) -> str:
        return self.table.where(int(self.rows[k]), self.columns[role].index)

    @property
    def named(self) -> str:
        """``lab.csv`` for a file of one state, else ``lab.csv (eps 0.1)``: the file named
        once."""
        name = self.table.source.name
        return name if self.state == name else f"{name} ({self.state})"


def _groups(recognition: Recognition, select: str | None, several_sheets: bool) -> list[_Group]:
    """The table's rows split into muscle states (see :data:`SPLIT_ROLES`)."""
    table, found = recognition.table, recognition.columns
    n = len(table.rows)
    keep = np.ones(n, dtype=bool)
    if "muscle" in found:
        names = column_text(table, found["muscle"])
        distinct = list(dict.fromkeys(names))
        if select is None and len(distinct) > 1:
            raise ValueError(f"{table.name}: column {found['muscle'].header!r} holds "
                             f"{len(distinct)} muscles ({', '.join(map(repr, distinct))}): "
                             "choose one with --muscle NAME")
        if select is not None:
            if select not in distinct:
                raise ValueError(f"--muscle {select!r}: {table.name} has no such muscle in "
                                 f"column {found['muscle'].header!r}: it has "
                                 f"{', '.join(map(repr, distinct))}")
            keep = np.array([v == select for v in names])
    elif select is not None:
        raise ValueError(f"--muscle {select!r}: {table.name} has no muscle column")
    keys = [[] for _ in range(n)]
    labels = []
    for role in SPLIT_ROLES:
        if role not in found:
            continue
        if role == "run":
            values = column_text(table, found[role])
        else:
            values = [f"{v:.6g}" for v in recognition.values(role)]
        labels.append(role)
        for k in range(n):
            keys[k].append(values[k])
    order = list(dict.fromkeys(tuple(k) for k, kept in zip(keys, keep, strict=True) if kept))
    groups = []
    for key in order:
        rows = np.flatnonzero([tuple(k) == key and kept for k, kept in zip(keys, keep,
                                                                           strict=True)])
        parts = [f"{label} {value}{' mm' if label in ('length', 'L0') else ''}"
                 for label, value in zip(labels, key, strict=True)]
        if several_sheets or (table.sheet and not parts):
            parts.insert(0, f"{table.part} {table.sheet!r}")
        groups.append(_Group(recognition, rows, ", ".join(parts) or table.source.name,
                             dict(zip(labels, key, strict=True))))
    if not groups:
        raise ValueError(f"{table.name} has no row to import" + "".join(
            f" (the file is damaged or cut short: npTDMS: {warned})"
            for warned in table.read_warnings[:1]))
    return groups


def _single(group: _Group, role: str) -> float:
    values = group.values(role)
    if role in ("length", "L0"):
        bad = np.flatnonzero(~(np.isfinite(values) & (values > 0)))
        if bad.size:
            raise ValueError(f"{group.where(int(bad[0]), role)} (column "
                             f"{group.columns[role].header!r}): {values[bad[0]]:g} mm is not a "
                             "length: expected a finite length > 0 mm")
    return float(values[0])


#: what a file's header may declare (:data:`mkm.bench.tables.DECLARED_STATE`): the muscle's
#: key it gives, the option that gives it too, and the columns that give it instead (a held
#: length gives eps with the rest length)
HEADER_STATES = (("L0", "L0_mm", "--L0", ("L0",)), ("D0", "D0_mm", "--D0", ()),
                 ("t0", "t0_mm", "--t0", ()), ("eps", "eps", "--eps", ("eps", "length")),
                 ("length", "eps", "--eps", ("eps", "length")))


def _shown(key: str, value: float) -> str:
    """``eps 0.05``, ``L0 300 mm``: a muscle's value as the messages say it."""
    return f"eps {value:.4g}" if key == "eps" else f"{key.removesuffix('_mm')} {value:g} mm"


def _header_states(given: dict, group: _Group) -> tuple[dict, list[str], dict]:
    """``given`` with what the file's header declares of the muscle (its comment or title
    lines, a TDMS file's properties: :func:`mkm.bench.tables.declared_state`) where no option
    and no column gives it; the notes of the values so taken; and the record of each statement
    (taken, or agreeing with the option). An option that contradicts its header beyond the
    header's rounding (``Contraction: 5 %`` holds 4.5-5.5 %) is refused naming both."""
    stated = declared_state(group.table.preamble)
    values, notes, record, source = dict(given), [], {}, {}
    for role, key, option, columns in HEADER_STATES:
        if role not in stated or any(c in group.columns for c in columns):
            continue
        said = stated[role]
        value, half = float(said.value), said.half_step
        how = f"the file's {said.text!r} ({said.where})"
        if role == "length":  # a held length gives eps with the rest length
            if values.get("L0_mm") is None:
                continue
            rest = float(values["L0_mm"])
            value, half = (rest - value) / rest, half / rest
            how += f" at L0 {rest:g} mm"
        entry = {"text": said.text, "at": said.where, key: value}
        if values.get(key) is None:
            values[key], source[key] = value, how
            notes.append(f"{_shown(key, value)} from {how}")
            record[role] = {**entry, "taken": True}
        elif replace(said, value=value, half_step=half).agrees(float(values[key])):
            record[role] = {**entry, "taken": False}
        else:
            by = source.get(key, f"{option} {float(values[key]):g}")
            raise ValueError(f"{group.named}: {by} contradicts {how}, {_shown(key, value)}: "
                             f"expected one of them; without {option} the file's is used")
    return values, notes, record


def _muscle(given: dict, group: _Group):
    """The muscle of one state: what its header declares where nothing else gives it
    (:func:`_header_states`), the table's L0 and eps (or length) over the ones given, but
    ``--L0`` over the table's L0 where its held lengths give eps anew; what was overridden (a
    note, or None), and the header's statements (their notes and record)."""
    where = f"{group.named}: "
    given, header_notes, header_record = _header_states(given, group)
    values = dict(given)
    override = None
    if "L0" in group.columns:
        table_L0 = _single(group, "L0")
        values["L0_mm"] = table_L0
        if (given.get("L0_mm") is not None and "length" in group.columns
                and not math.isclose(float(given["L0_mm"]), table_L0, rel_tol=1e-9)):
            # a catalogue muscle's nominal length over the table's longest: the held lengths
            # are measured, their eps follows from the rest length
            values["L0_mm"] = float(given["L0_mm"])
            override = (f"L0 {values['L0_mm']:g} mm from --L0 over the table's "
                        f"{table_L0:g} mm (column {group.columns['L0'].header!r})")
    if "eps" in group.columns and override is None:
        values["eps"] = _single(group, "eps")
        column = group.columns["eps"]
        if column.unit is None and 1 <= values["eps"] < 100:
            raise ValueError(f"{where}column {column.header!r}: eps {values['eps']:g} is not "
                             "a fraction: expected a shortening ratio in [0, 1); if the "
                             "column is a percentage, give --units eps=%")
    elif "length" in group.columns:
        length = _single(group, "length")
        if values.get("L0_mm") is None:
            raise ValueError(f"{where}a length column but no L0: give --L0 (the length at rest, "
                             "mm) or an L0 column, so that eps = (L0 - L) / L0")
        values["eps"] = (float(values["L0_mm"]) - length) / float(values["L0_mm"])
        if values["eps"] < 0:
            raise ValueError(f"{where}length {length:g} mm is above L0 = {values['L0_mm']:g} "
                             "mm: expected a held length at most the length at rest")
        if override is not None:  # the eps the run gets, not the state's (the table's) eps
            override += (f": eps {values['eps']:.4g} from the held length {length:g} mm "
                         f"(column {group.columns['length'].header!r})")
    # an option the table's own column would silently override is a conflict, said
    for key, option, roles in (("L0_mm", "--L0", ("L0",)), ("eps", "--eps", ("eps", "length"))):
        column = next((group.columns[r] for r in roles if r in group.columns), None)
        if column is not None and given.get(key) is not None and not math.isclose(
                float(given[key]), float(values[key]), rel_tol=1e-9, abs_tol=1e-12):
            other = (" (--L0 replaces the table's L0 where a length column gives eps anew)"
                     if key == "L0_mm" else "")
            raise ValueError(f"{where}{option} {float(given[key]):g} conflicts with the "
                             f"table's {key} {float(values[key]):g} (column "
                             f"{column.header!r}): expected one of them; without {option} "
                             f"the table's is used{other}")
    for key, option in (("id", "--id"), ("D0_mm", "--D0"), ("t0_mm", "--t0"),
                        ("L0_mm", "--L0"), ("eps", "--eps")):
        if values.get(key) is None:
            # the muscle's id and sizes come from mkm export's workbook only, never a column
            source = ("a table's columns give none; mkm export's workbook carries it"
                      if key in ("id", "D0_mm", "t0_mm") else
                      f"the table has no {'eps or length' if key == 'eps' else key} column")
            raise ValueError(f"{where}no {key}: give {option} ({source}"
                             f"{_look_alike(group, key)})")
    try:
        values = {k: (v if k == "id" else float(v)) for k, v in values.items()
                  if v is not None}
    except (TypeError, ValueError):
        raise ValueError(f"{where}the muscle {values} has a value that is not a number") from None
    return muscle_from_dict(values, where.rstrip(": ")), override, (header_notes, header_record)


#: header stems of the columns a table may hold the tube's size in under another name
SIZE_STEMS = {"D0_mm": ("d0", "diameter", "inner diameter"), "t0_mm": ("t0", "wall", "thickness")}


def _look_alike(group: _Group, key: str) -> str:
    """``; its column 'D0_nominal_mm' holds 20`` for a column left unrecognised whose name
    reads as ``key`` (a catalogue's nominal diameter): the value to check and give."""
    table = group.table
    for k, header in enumerate(table.header):
        name = str(header or "").strip().lower()
        if header in group.recognition.ignored and name.startswith(SIZE_STEMS.get(key, ())):
            return f"; its column {header!r} holds {table.rows[int(group.rows[0])][k]}"
    return ""


def _closing_rest(clock, pressure, force, rest) -> series.Tare | None:
    """The vented rest that ends a record where it is a surer zero than ``rest``, the one
    before its rise: that one of fewer than :data:`mkm.bench.series.SHORT_REST_SAMPLES`
    samples (the logging began as the pressure rose: they already pull) or held pressurised,
    this one vented and of that many samples or more where settled; else None. One whose
    force still falls (``settled`` False) is returned, for the caller to say why it is no
    zero."""
    if rest.rest.stop >= series.SHORT_REST_SAMPLES and \
            rest.pressure_bar <= series.VENTED_THRESHOLD_BAR:
        return None
    end = series.end_rest(clock, pressure, force)
    if (end.rest.start <= rest.rest.stop or end.pressure_bar > series.VENTED_THRESHOLD_BAR
            or (end.settled and end.rest.stop - end.rest.start < series.SHORT_REST_SAMPLES)):
        return None
    return end


def _rest_spread_N(force, *rests) -> float:
    """The load cell's spread at rest [N], a standard deviation: the smaller of the vented
    rests ``rests`` (:class:`mkm.bench.series.Tare`, or None) of
    :data:`~mkm.bench.series.SHORT_REST_SAMPLES` samples or more; NaN without one."""
    spreads = [float(np.std(force[r.rest], ddof=1)) for r in rests
               if r is not None and r.rest.stop - r.rest.start >= series.SHORT_REST_SAMPLES
               and r.pressure_bar <= series.VENTED_THRESHOLD_BAR]
    return min(spreads, default=math.nan)


def _zero_drift(group: _Group, time_s, pressure, force, rest, handling):
    """The note (if any) of a record that ends vented at another zero than it started: the
    drift recorded as ``zero_drift_N`` (end less start), said when it is beyond 4 standard
    errors of the two rests' means. Where the force steps by that drift within a hold
    (:func:`mkm.bench.series.zero_step`: the load cell zeroed again mid-record), each sample is
    tared at the zero it was logged with, the start's before the step and the end's from it on,
    the samples a filter spread the step over at a zero linear across them. ``time_s`` None: a
    record without time, its rows the clock. (notes, the zero at every sample or None, the
    samples it stepped through: in no step's mean)."""
    clock = np.arange(force.size, dtype=float) if time_s is None else time_s
    end = series.end_rest(clock, pressure, force)
    if (end.rest.start <= rest.rest.stop or end.pressure_bar > series.VENTED_THRESHOLD_BAR
            or not (math.isfinite(end.std_N) and math.isfinite(rest.std_N))):
        return [], None, slice(0, 0)
    drift = end.force_N - rest.force_N
    handling["zero_drift_N"] = drift
    noise = 4.0 * math.hypot(end.std_N, rest.std_N)
    if abs(drift) <= noise:
        return [], None, slice(0, 0)
    stepped = series.zero_step(pressure, force, slice(rest.rest.stop, end.rest.start), drift,
                               _rest_spread_N(force, rest, end))
    if stepped is None:
        linear = (f"--tare {LINEAR_TARE}" if time_s is not None else
                  f"--sample-rate HZ (the rate its rows were logged at) with --tare {LINEAR_TARE}")
        return [f"the force vented at the end reads {drift:+.3g} N from the zero at the start "
                f"(beyond the rests' noise, {noise:.2g} N): a load cell that drifted, or a "
                "muscle that did not come back; every step keeps the start's zero: where the "
                f"cell drifted (the muscle vented pulls nothing), {linear} takes the zero "
                "linearly in time between the two rests"], None, slice(0, 0)
    k, step = stepped.first, stepped.step_N
    held_bar = float(np.median(pressure[stepped.start:k + series.ZERO_STEP_SAMPLES]))
    cell = group.cell(k, "force")
    spread = k - stepped.start
    recorded = {"cell": cell, "step_N": step, "pressure_bar": held_bar,
                "spread_samples": spread}
    if time_s is None:
        at, there = f"at cell {cell}", f"before cell {cell}"
    else:
        recorded = {"at_s": float(time_s[k]), **recorded}
        at, there = f"at {time_s[k]:.4g} s (cell {cell})", f"to {time_s[k]:.4g} s"
    if spread:
        from_cell = group.cell(stepped.start, "force")
        at = (f"over {spread + 1} samples from cell {from_cell} to cell {cell}"
              if time_s is None else
              f"over {time_s[k] - time_s[stepped.start - 1]:.3g} s from "
              f"{time_s[stepped.start - 1]:.4g} s to {time_s[k]:.4g} s (cells {from_cell} to "
              f"{cell})")
    handling["zero_step"] = recorded
    closing = (f"the mean force of the {end.rest.stop - end.rest.start} sample(s) of the vented "
               "rest that ends the record")
    handling["tare"] += f", {there}; from there ({cell}) {closing}, {end.force_N:.4g} N"
    zero = np.where(np.arange(force.size) < k, rest.force_N, end.force_N)
    # a moving average of N readings reads the new zero's share (j + 1) / N at its j-th sample
    share = np.arange(1, spread + 1) / (spread + 1)
    zero[stepped.start:k] = rest.force_N + share * (end.force_N - rest.force_N)
    smeared = (f"; the {spread} sample(s) between read it part way (a display's or "
               "amplifier's average over readings either side of the tare): tared at a zero "
               "linear across them, in no step's mean" if spread else "")
    return [f"tare {rest.force_N:.4g} N subtracted {there}, {end.force_N:.4g} N from "
            f"there ({closing}): the force steps by {step:+.4g} N {at} "
            f"while the pressure holds at {held_bar:.3g} bar, as far as the force vented at the "
            "end reads from the zero at the start: the load cell zeroed again there (its tare "
            "pressed with the muscle pulling), each sample tared at the zero it was logged "
            f"with{smeared}; --tare {rest.force_N:.4g} keeps the start's zero throughout"], zero, \
        slice(stepped.start, k)


def _table_zero_drift(group: _Group, pressure, force, zero: float, closing_rows, declared,
                      handling):
    """The note (if any) of a step table tared at its 0 bar rising row(s) whose falling branch
    ends at 0 bar reading another force: the difference recorded as ``zero_drift_N``, said when
    beyond :data:`TABLE_ZERO_DRIFT_N` or twice the declared force accuracy's absolute part (a
    table has no noise to judge it by). Where it is beyond :data:`TABLE_ZERO_STEP_SHARE` of the
    largest force, the table as read has a force that moves against its pressure from one row
    to the next or a pressurised row pulling less than nothing, and one pressurised row, its
    force and those after it tared at the closing rows' zero, leaves every force following its
    pressure from row to row, with the least travel of the force up and down by the drift or
    more (a row tared at another zero moves it there and back), the load cell was zeroed again
    at that row: the rows from it on are tared at the closing zero. (notes, the zero at every
    row or None)."""
    if closing_rows is None or not closing_rows.any():
        return [], None
    closing = float(np.mean(force[closing_rows]))
    drift = closing - zero
    handling["zero_drift_N"] = drift
    floor = max(TABLE_ZERO_DRIFT_N, 2.0 * declared.absolute if declared else 0.0)
    if abs(drift) <= floor:
        return [], None
    said = (f"the 0 bar row(s) that end the falling branch read {drift:+.3g} N from the zero "
            f"at the start (beyond {floor:.2g} N)")

    def rises(zeros) -> bool:
        # from each row to the next the force follows the pressure up or down
        return not np.any(np.sign(np.diff(pressure)) * np.diff(force - zeros) < -floor)

    def travel(k) -> float:
        # a row tared at the wrong zero moves the force there and back again
        return float(np.abs(np.diff(force - np.where(start < k, zero, closing))).sum())

    start = np.arange(force.size)
    fits = sorted((k for k in range(1, force.size) if pressure[k] > series.VENTED_THRESHOLD_BAR
                   and rises(np.where(start < k, zero, closing))), key=travel)
    if (abs(drift) <= TABLE_ZERO_STEP_SHARE * float(np.max(np.abs(force - zero))) or not fits
            or (len(fits) > 1 and travel(fits[1]) < travel(fits[0]) + abs(drift))
            or (rises(np.full(force.size, zero)) and not np.any(
                force[pressure > series.VENTED_THRESHOLD_BAR] - zero < -floor))):
        return [f"{said}: a load cell that drifted, or a muscle that did not come back; every "
                "step keeps the start's zero (a table's rows have no time to spread a drift "
                "over: --tare N sets another zero)"], None
    k = fits[0]
    cell = group.cell(k, "force")
    handling["zero_step"] = {"cell": cell, "step_N": drift, "pressure_bar": float(pressure[k])}
    handling["tare"] += f", before cell {cell}; from there the closing row(s)' {closing:.4g} N"
    return [f"tare {zero:.4g} N subtracted before cell {cell}, {closing:.4g} N from there: "
            f"{said}, and with the rows from {cell} ({pressure[k]:.3g} bar) on tared at theirs "
            "every force follows its pressure from row to row, the least up and down of any "
            "row's: the load cell zeroed again there "
            "(its tare pressed with the muscle pulling), each row tared at the zero it was "
            f"logged with; --tare {zero:.4g} keeps the start's zero throughout"], \
        np.where(start < k, zero, closing)


def _zeros_between_steps(group: _Group, pressure, force, zero: float, declared, handling):
    """The note and the zero at every row of a step table vented between its pressurised steps
    (a 0 bar row, or two where the sweep turns, with steps before and after it): the load cell's
    zero read there, by a lab that vents to read or press its tare between steps, each such run
    of rows read as the zero of the rows from it to the next (its force's mean), the rows
    before the first tared at the 0 bar rows the table starts with (``zero`` where it starts
    pressurised); the closing 0 bar rows keep the zero before them, their difference
    ``zero_drift_N``. Each zero, its cells and its change from the one before in
    ``zeros_between_steps``; a change beyond the declared force accuracy (or
    :data:`TABLE_ZERO_DRIFT_N` where none is declared) is warned of, as is the closing rows'
    difference beyond it. (notes, the start's zero, the zero at every row), or ``None`` where
    no 0 bar row lies between steps."""
    vented = pressure <= series.VENTED_THRESHOLD_BAR
    pressurised = np.flatnonzero(~vented)
    if not pressurised.size:
        return None
    row = np.arange(pressure.size)
    between = vented & (row > pressurised[0]) & (row < pressurised[-1])
    if not between.any():
        return None
    lead = vented & (row < pressurised[0])
    zero = float(np.mean(force[lead])) if lead.any() else zero  # the start's rows alone
    firsts = np.flatnonzero(between & ~np.r_[False, between[:-1]])
    ends = np.flatnonzero(between & ~np.r_[between[1:], False]) + 1
    closing = np.flatnonzero(vented & (row > pressurised[-1]))
    zeros, recorded, warned = np.full(force.size, zero), [], []
    before = zero

    def cells(first: int, end: int) -> str:
        return group.cell(first, "force") + ("" if end - first == 1 else
                                             f" to {group.cell(end - 1, 'force')}")

    def beyond(read: float, change_N: float) -> bool:
        bound = (declared.absolute + declared.fraction * abs(read) if declared else
                 TABLE_ZERO_DRIFT_N)
        return abs(change_N) > bound * (1.0 + 1e-9)  # a change of the bound as written is within

    for first, end in zip(firsts, ends, strict=True):
        read = float(np.mean(force[first:end]))
        zeros[first:] = read
        recorded.append({"cells": cells(first, end), "zero_N": read,
                         "change_N": read - before, "beyond_accuracy": beyond(read, read - before)})
        if recorded[-1]["beyond_accuracy"]:
            warned.append(f"{read - before:+.3g} N at {recorded[-1]['cells']}")
        before = read
    handling["zeros_between_steps"] = recorded
    if closing.size:
        read = float(np.mean(force[closing]))
        handling["zero_drift_N"] = read - before
        if beyond(read, read - before):
            warned.append(f"{read - before:+.3g} N at {cells(closing[0], closing[-1] + 1)}, the "
                          "closing 0 bar row(s), kept as read")
    handling["tare"] += (", the start's rows alone; from each 0 bar row between steps on, the "
                         "force that row reads")
    accuracy = (f"the declared force accuracy (--accuracy force={declared.text})" if declared
                else f"{TABLE_ZERO_DRIFT_N:g} N (no force accuracy declared: --accuracy "
                "force=...)")
    said = ", ".join(f"{r['zero_N']:.4g} N at {r['cells']}" for r in recorded)
    return ([f"tare {zero:.4g} N subtracted, and from each 0 bar row between steps on the zero "
             f"it reads, {said}: a load cell whose zero was read, or pressed again, vented "
             f"between steps, each row tared at the zero read last before it; --tare "
             f"{zero:.4g} keeps the start's zero throughout"]
            + ([f"warning: the zero moved beyond {accuracy}, by {', '.join(warned)}: a load "
                "cell drifting that much drifts within a step too, where no 0 bar row reads "
                "it, or a muscle that did not come back reads so vented"] if warned else []),
            zero, zeros)


def _linear_tare(group: _Group, time_s, pressure, force, rest, handling):
    """``--tare linear``: the zero of a time series whose load cell drifted, the mean force of
    its rest before the rise and of the vented rest that ends it, joined by a line in time
    (each at its rest's mean time). Returns the start's zero [N] and the zero at every sample;
    ``ValueError`` where the record lacks a clock or either rest."""
    if time_s is None:
        raise ValueError(f"{group.named}: --tare {LINEAR_TARE} needs a time column: expected a "
                         "time series, or --tare auto, none or a value")
    end = series.end_rest(time_s, pressure, force)
    if (rest.pressure_bar > series.VENTED_THRESHOLD_BAR or end.rest.start <= rest.rest.stop
            or end.pressure_bar > series.VENTED_THRESHOLD_BAR or not end.settled):
        raise ValueError(f"{group.named}: --tare {LINEAR_TARE} needs a vented rest before the "
                         "pressure rises and a settled vented rest that ends the record: "
                         "expected a record that starts and ends vented, or --tare auto, none "
                         "or a value")
    t_start = float(np.mean(time_s[rest.rest]))
    t_end = float(np.mean(time_s[end.rest]))
    slope = (end.force_N - rest.force_N) / (t_end - t_start)
    handling["tare_std_N"] = rest.std_N
    handling["zero_drift_N"] = end.force_N - rest.force_N
    handling["tare"] = (f"linear in time: {rest.force_N:.4g} N at {t_start:.4g} s (the rest "
                        f"before the pressure rises) to {end.force_N:.4g} N at {t_end:.4g} s "
                        "(the vented rest that ends the record), a drift of "
                        f"{end.force_N - rest.force_N:+.3g} N")
    return rest.force_N, rest.force_N + slope * (np.asarray(time_s) - t_start)


def _counted_from(header: str, origin_s: float, row: str, handling) -> str:
    """The note of a time column counted from its first reading ``origin_s`` (that of
    ``row``), far from 0 (:data:`~mkm.bench.tables.CLOCK_ORIGIN_S`): recorded as
    ``time_origin_s``, and where it is Unix time as ``record_started_utc``, its moment in ISO
    form."""
    handling["time_origin_s"] = origin_s
    said = f"{header!r} counted from {row}, {origin_s:.13g} s"
    if not UNIX_TIME_S[0] <= origin_s <= UNIX_TIME_S[1]:
        return said
    moment = datetime.datetime.fromtimestamp(origin_s, datetime.UTC)
    handling["record_started_utc"] = moment.isoformat(timespec="milliseconds")
    return f"{said} (Unix time, {moment:%Y-%m-%d %H:%M:%S} UTC)"


def _reading(force_N: float, force: np.ndarray) -> str:
    """What a table or record without a 0 bar reading reads where its rising branch starts,
    ``force_N``: one within 1 % of its largest force of 0 N is named as a load cell zeroed
    there, pressurised, may read it (every force then low by the pull it was zeroed at)."""
    said = f"reading {force_N:.4g} N"
    if abs(force_N) > 0.01 * float(np.nanmax(np.abs(force))):
        return said
    return (f"{said}: a load cell zeroed there with the muscle pressurised, every force then "
            "low by its pull there (--tare minus that pull restores them), or a muscle slack "
            "there")


def _never_rises(pressure_bar: np.ndarray) -> bool:
    """Whether a record's pressures stay within two plateau bands: a vented gauge's noise, or
    one hold; no steps to find."""
    return bool(np.ptp(pressure_bar) <= 2 * series.PLATEAU_TOLERANCE_BAR)


def _refuse_atmosphere(group: _Group, held_bar: float, end_bar: float, what: str):
    """Refuse a ``what`` (a record, a table) that starts at an atmosphere's reading
    (:data:`ATMOSPHERE_BAR`), its lowest level, and ends there too (``end_bar``): an absolute
    sensor's, or a muscle kept pressurised throughout, which its pressures cannot tell
    apart."""
    low, high = ATMOSPHERE_BAR
    if not low <= held_bar <= high or abs(end_bar - held_bar) > series.PLATEAU_TOLERANCE_BAR:
        return
    header = group.columns["pressure"].header
    raise ValueError(f"{group.named}: the {what} starts and ends held at {held_bar:.3f} bar "
                     f"({header!r}) and reads no lower: the atmosphere an absolute sensor "
                     f"reads vented ({low:g}-{high:g} bar), or a muscle kept pressurised from "
                     "start to end, which the pressures cannot tell apart: expected --vented "
                     f"{held_bar:.3f}bar (an absolute sensor: subtracted, the force tared at "
                     "the rest) or --vented none (a gauge: kept as read)")


def _build(path: Path, sha: str, group: _Group, muscle, tare, vented, accuracy,
           override=None, force_sign=1, one_step_per_row=False):
    """The run record, steps, samples, notes and shape of one muscle state (``override``: what
    an option replaced of the table, said first)."""
    table, found = group.table, group.columns
    pressure, force = group.values("pressure"), force_sign * group.values("force")
    for k in np.flatnonzero(np.abs(force) > MAX_CAPACITY_N)[:1]:  # no load cell reads it
        raise ValueError(f"{group.where(int(k), 'force')} (column "
                         f"{found['force'].header!r}): {force_sign * force[k]:g} N is beyond "
                         f"the largest load cell a bench takes ({MAX_CAPACITY_N:g} N): "
                         "expected a force reading (a logger's overload value, or a unit "
                         "--units force=... gives)")
    notes, handling = ([override], {"L0": override}) if override else ([], {})
    handling["force_sign"] = force_sign
    handling["one_step_per_row"] = one_step_per_row
    if force_sign < 0:
        notes.append("forces negated (--force-sign -1)")
    notes += filter(None, [PRACTICAL_RANGE.length_note(muscle.D0_mm, muscle.L0_mm),
                           PRACTICAL_RANGE.lock_note(muscle.eps)])
    timed = "time" in found
    if timed:
        time_s = group.values("time")
        require_time_order(time_s, found["time"].header, lambda k: group.where(k, "time"))
        if abs(time_s[0]) >= CLOCK_ORIGIN_S:
            origin = float(time_s[0])
            time_s = np.round(time_s - origin, 6)  # a float's digits at Unix time's 1.8e9 s
            notes.append(_counted_from(found["time"].header, origin, "its first row",
                                       handling))
    # a record whose time column was left out (its rows evenly spaced in time) is read as a
    # time series is, its rows the clock
    record = not (timed or one_step_per_row) and series.sampled_without_time(pressure)
    step_times = None
    if timed and one_step_per_row:  # a step table, its pressures as written
        step_times, timed = time_s, False
        handling["steps_from"] = "one row per step (--one-step-per-row), at its time"
    if timed or record:
        if vented == "auto":
            offset = (series.vented_offset(time_s, pressure) if timed else
                      series.vented_offset(np.arange(pressure.size, dtype=float), pressure,
                                           min_s=series.RECORD_PLATEAU_ROWS))
        else:
            offset = 0.0 if vented == "none" else float(vented)
        if vented == "auto" and offset < -VENTED_AUTO_MAX_BAR:
            offset = 0.0  # below a sensor's zero error: refused below as a reading < 0 bar
        if vented == "auto" and offset > VENTED_AUTO_MAX_BAR:
            held = handling["held_at_start_bar"] = offset
            offset = 0.0
            unit = found["pressure"].unit
            if not (marked_gauge(unit) or _never_rises(pressure)):  # one hold: said below
                # its last samples, not a closing rest: a record may stop as a ramp comes down
                _refuse_atmosphere(group, held, float(np.median(
                    pressure[-series.RECORD_PLATEAU_ROWS:])), "record")
            notes.append(f"the record starts held at {held:.3g} bar, more than a gauge's zero "
                         f"error ({VENTED_AUTO_MAX_BAR:g} bar): kept as the gauge pressure "
                         + (f"its unit {unit!r} says (the muscle pressurised when the logging "
                            f"began; --vented {held:.3f}bar would take it as the zero)"
                            if marked_gauge(unit) else
                            "its column holds (the muscle pressurised when the logging began); "
                            "if the sensor reads absolute pressure, import again with --vented "
                            f"{held:.3f}bar"))
        handling["vented_reading_bar"] = offset
        handling["vented"] = ("detected" if vented == "auto" else
                              "none" if vented == "none" else "given")
        pressure = pressure - offset
        if offset:
            notes.append(f"vented reading {offset:.3g} bar {handling['vented']}: subtracted")
    if timed and series.one_reading_per_step(time_s):
        step_times, timed = time_s, False
        apart = float(np.median(np.diff(time_s)))
        handling["steps_from"] = f"one row per step, its readings {apart:.3g} s apart (median)"
        notes.append(f"one reading every {apart:.3g} s: each row a step at its time (a time "
                     "series has several readings per hold)")
        if series.sampled_without_time(pressure):  # a logger's milliseconds read as seconds?
            rate_hz = group.recognition.sample_rate_hz
            notes[-1] += (f"; {pressure.size} rows whose successive pressures lie within "
                          f"{series.PLATEAU_TOLERANCE_BAR:g} bar, as a record's samples do: "
                          + (f"if they were logged faster than {rate_hz:g} Hz, import again "
                             "with the --sample-rate they were" if rate_hz else
                             f"if {found['time'].header!r} is in milliseconds, import again "
                             "with --units time=ms"))
    # a gauge's noise around its vented zero is not a vacuum (a bench run's vented step reads
    # -0.0001 bar too); a step table's pressures are as written (less a --vented given), so
    # its vented rows read the gauge's zero error, taken as 0 bar up to its bound
    step_table = not (timed or record)
    if step_table and not isinstance(vented, str):  # an absolute sensor's table
        pressure = pressure - vented
        handling["vented_reading_bar"], handling["vented"] = float(vented), "given"
        notes.append(f"vented reading {vented:g} bar given: subtracted")
    elif (step_table and vented == "auto" and pressure.size > 1
          and not marked_gauge(found["pressure"].unit)
          and pressure[0] <= pressure.min() + series.PLATEAU_TOLERANCE_BAR):
        _refuse_atmosphere(group, float(pressure[0]), float(pressure[-1]), "table")
    below = _below_zero_bound(pressure, accuracy.get("pressure")) if step_table else None
    noise = (pressure < 0) & (pressure >= -(below[0] if below else
                                            series.PLATEAU_TOLERANCE_BAR))
    if below and np.any(noise & (pressure < -series.PLATEAU_TOLERANCE_BAR)):
        rows = np.flatnonzero(noise)
        lowest = int(rows[np.argmin(pressure[rows])])
        cells = [group.cell(int(k), "pressure") for k in rows]
        handling["below_zero_bound_bar"] = float(below[0][lowest])
        notes.append(f"{rows.size} row(s) reading down to {pressure[lowest]:g} bar "
                     f"({', '.join(cells[:5])}{', ...' if len(cells) > 5 else ''}) taken as "
                     f"vented, 0 bar: within {below[1](below[0][lowest])}"
                     + ("" if "pressure" in accuracy else
                        "; --accuracy pressure=... declares the sensor's"))
    pressure = np.where(noise, 0.0, pressure)
    handling["readings_below_zero_set_to_0"] = int(noise.sum())
    top_bar = float(pressure.max())
    # a gauge's noise about a hold at the range's top is no unit read wrong: kPa or psi read
    # as bar lie 10 times and more beyond it
    declared = accuracy.get("pressure")
    noise_bar = max(series.PLATEAU_TOLERANCE_BAR, 0.0 if declared is None else
                    declared.absolute + declared.fraction * top_bar)
    if top_bar > PRACTICAL_RANGE.pressure_bar[1] + noise_bar:
        # kPa or psi read as bar pass as a bar 10-100 times: under a header without a unit,
        # or one whose unit is wrong (a logger's channel set up in bar that records kPa)
        column = found["pressure"]
        read = (f"read as bar since {column.header!r} names no unit" if column.unit is None
                else f"read in {column.unit} as its cells say" if column.in_cells
                else f"read in {column.unit} as {column.header!r} says")
        notes.append(f"pressures up to {top_bar:g} bar, {read}: above the "
                     f"{PRACTICAL_RANGE.pressure_bar[1]:g} bar of any braided muscle; "
                     + _other_pressure_units(top_bar, column.unit))
    # the first bad cell named (a record's every sample checked at once)
    for k in np.flatnonzero(outside("pressure_bar", pressure))[:1]:
        p = pressure[k]
        if p < 0 and below:
            raise ValueError(f"{group.where(k, 'pressure')} (column "
                             f"{found['pressure'].header!r}): {p:g} bar is below 0 by more "
                             f"than {below[1](below[0][k])}: expected a gauge pressure >= "
                             f"{-below[0][k]:.3g} bar; if the sensor's accuracy is wider, "
                             f"declare it: --accuracy pressure={-p:g}bar")
        if p < 0:
            raise ValueError(f"{group.where(k, 'pressure')} (column "
                             f"{found['pressure'].header!r}): {p:g} bar is below 0: expected a "
                             "gauge pressure >= 0 (--vented sets a vented reading to subtract)")
        try:
            check_value("pressure_bar", p, f"{group.where(k, 'pressure')}: ")
        except ValueError as exc:  # beyond any gauge: a unit read as bar, as the note says
            raise ValueError(f"{exc}; {_other_pressure_units(top_bar, found['pressure'].unit)}"
                             ) from None
    if (timed or record) and _never_rises(pressure):
        # a gauge's noise binned by pressure would make steps of nothing
        what = "samples" if timed else "rows"
        read = pressure + handling.get("vented_reading_bar", 0.0)  # as the file holds them
        level = float(np.median(read))
        span = (f"its {pressure.size} {what} read {read.min():.3g} to {read.max():.3g} bar, "
                f"within {2 * series.PLATEAU_TOLERANCE_BAR:g} bar of each other")
        if level > 2 * series.PLATEAU_TOLERANCE_BAR:  # a hold, not a vented gauge
            raise ValueError(f"{group.named}: the pressure is held at {level:.3g} bar "
                             f"throughout ({span}): one hold, no sweep to find steps in: "
                             "expected a record of the pressure rising; where each pressure "
                             "step was logged to a file of its own, import the files together "
                             "as one run: mkm import \"FOLDER/*.csv\" (or each file named)")
        raise ValueError(f"{group.named}: the pressure never rises: {span} (a vented "
                         f"gauge's noise): expected a record of the muscle pressurised; is "
                         f"{found['pressure'].header!r} its pressure?")
    closing = closing_rows = None
    if timed or record:  # zeroed at the rest before its rise, not at one noisy row at 0 bar
        clock = time_s if timed else np.arange(pressure.size, dtype=float)
        rest = series.tare(clock, pressure, force)
        zero, zero_at = rest.force_N, rest.pressure_bar
        handling["tare_at_bar"] = zero_at
        zero_rows = rest.rest
        if tare == "auto":
            closing = _closing_rest(clock, pressure, force, rest)
        if closing is not None and not closing.settled:  # a vent's tail: still pulling
            notes.append("the vented rest that ends the record still falls (its force's trend "
                         f"beyond {series.SETTLED_TREND_SE:g} standard errors to its end): not "
                         "taken as the zero; a longer rest after the vent, or --tare N, gives "
                         "one")
            closing = None
    else:
        order = (np.array(directions(table, found["direction"]))[group.rows]
                 if "direction" in found else _inferred(pressure))
        up = order == "up"
        zero_at = float(pressure[up].min()) if up.any() else math.nan
        zero = float(np.mean(force[up & (pressure == zero_at)])) if up.any() else 0.0
        # a sweep that starts pressurised and ends vented reads the zero where it ends
        vented_rows = ~up & (pressure <= series.VENTED_THRESHOLD_BAR)
        if tare == "auto" and not zero_at <= series.VENTED_THRESHOLD_BAR and vented_rows.any():
            closing_rows = vented_rows
    drift: list[str] = []
    line, unread = None, slice(0, 0)
    if tare == "none":
        zero, handling["tare"] = 0.0, "none"
    elif tare == LINEAR_TARE:
        zero, line = _linear_tare(group, time_s if timed else None, pressure, force,
                                  rest if timed else None, handling)
    elif closing_rows is not None:
        zero = float(np.mean(force[closing_rows]))
        handling["tare"] = (f"mean force of the {int(closing_rows.sum())} row(s) at 0 bar where "
                            f"the falling branch ends: the rising branch starts at {zero_at:g} "
                            "bar")
    elif closing is not None:
        zero, zero_rows = closing.force_N, closing.rest
        handling["tare_at_bar"], handling["tare_std_N"] = closing.pressure_bar, closing.std_N
        what = "sample" if timed else "row"
        handling["tare"] = (
            f"mean force of the {closing.rest.stop - closing.rest.start} {what}(s) of the "
            "vented rest that ends the record"
            + (f" (from {time_s[closing.rest.start]:.4g} s, where its force has settled)"
               if timed else " (where its force has settled)") + ": "
            + (f"it starts held at {zero_at:.3g} bar" if zero_at > series.VENTED_THRESHOLD_BAR
               else f"only {rest.rest.stop} {what}(s) before the pressure rises"))
    elif tare == "auto" and not timed and not zero_at <= series.VENTED_THRESHOLD_BAR:
        lowest, zero = zero, 0.0
        handling["tare"] = "none: the table has no 0 bar row"
        # a load cell's offset would stay in every force unsaid, unless the table marks where
        # the muscle is slack (its zero: a published map's 0 N entries)
        if not ("slack" in found and flags(table, found["slack"])[group.rows].any()):
            notes.append(f"no tare: the table has no 0 bar row (its rising branch starts at "
                         f"{zero_at:g} bar, {_reading(lowest, force)}): its forces as given; "
                         "--tare N gives one")
    elif tare == "auto" and not zero_at <= series.VENTED_THRESHOLD_BAR:
        # the force of a record that starts pressurised is the muscle's pull, not the zero
        zero, handling["tare"] = 0.0, (f"none: the record has no 0 bar reading (its rising "
                                       f"branch starts at {zero_at:g} bar)")
        notes.append(f"no tare: {handling['tare'][6:-1]}, {_reading(rest.force_N, force)}); "
                     "--tare N gives one")
    elif tare == "auto" and timed:
        n = rest.rest.stop
        rises_s = time_s[min(n, time_s.size - 1)] - time_s[0]
        handling["tare"] = (f"mean force of the {n} sample(s) before the pressure rises "
                            f"(at {rises_s:.4g} s)")
        handling["tare_std_N"] = rest.std_N
        if n < series.SHORT_REST_SAMPLES:
            notes.append(f"tare from only {n} sample(s): the pressure rises {rises_s:.3g} s "
                         "into the record; a vented rest of a second or more before it, or "
                         "--tare N, gives a surer zero")
        drift, line, unread = _zero_drift(group, time_s, pressure, force, rest, handling)
    elif tare == "auto" and record:
        handling["tare"] = f"mean force of the {rest.rest.stop} row(s) before the pressure rises"
        handling["tare_std_N"] = rest.std_N
        drift, line, unread = _zero_drift(group, None, pressure, force, rest, handling)
    elif tare == "auto":
        handling["tare"] = "force at the lowest pressure of the rising branch"
        between = _zeros_between_steps(group, pressure, force, zero, accuracy.get("force"),
                                       handling)
        if between is not None:
            drift, zero, line = between
        else:
            drift, line = _table_zero_drift(
                group, pressure, force, zero, ~up & (pressure <= series.VENTED_THRESHOLD_BAR)
                if zero_at <= series.VENTED_THRESHOLD_BAR else None, accuracy.get("force"),
                handling)
    else:
        zero, handling["tare"] = force_sign * float(tare), "given"
        if zero >= float(np.nanmax(force)):  # every force <= 0: a muscle that never pulled
            pull = ("largest", "below") if force_sign > 0 else ("smallest", "above")
            raise ValueError(f"{table.name}: --tare {float(tare):g} N is not {pull[1]} the "
                             f"{pull[0]} force of the table, "
                             f"{force_sign * float(np.nanmax(force)):g} N: expected the force "
                             "read at 0 bar")
    handling["tare_N"] = zero
    if line is not None:
        force = force - line
        if not {"zero_step", "zeros_between_steps"} & handling.keys():  # their notes say each
            notes.append(f"tare {zero:.4g} N at the start subtracted, then {handling['tare']}")
    elif zero:
        force = force - zero
        notes.append(f"tare {zero:.4g} N subtracted ({handling['tare']})")
    notes.extend(drift)
    samples: list[Sample] = []
    if timed:
        held = series.held_plateaus(time_s, pressure)
        shape = series.shape(time_s, pressure, held)
        if shape == "staircase":
            from mkm.bench.config import load_config

            spread_N = _rest_spread_N(force, rest, closing)
            config, factor = series.settle_for_cell(load_config(), spread_N)
            steps, step_of = series.staircase_steps(time_s, pressure, force, config, held,
                                                    unread)
            handling["steps_from"] = ("plateaus judged by the bench's settle test "
                                      "(packaged [settle] criteria), averaged by HoldStats")
            if factor > 1.0:
                st = config.settle
                handling["settle_scaled"] = {
                    "rest_std_N": spread_N, "factor": factor,
                    "max_force_std_N": st.max_force_std_N,
                    "max_force_slope_N_per_s": st.max_force_slope_N_per_s}
                handling["steps_from"] += (f", its force limits x{factor:.3g} for the load "
                                           "cell's spread at rest")
                notes.append(f"the load cell spreads {spread_N:.3g} N at rest: each hold judged "
                             f"settled within {st.max_force_std_N:.3g} N and "
                             f"{st.max_force_slope_N_per_s:.3g} N/s, the bench's [settle] "
                             f"limits x{factor:.3g}, as the bench asks for such a cell")
            if unsettled := series.unsettled_note(pressure, held, steps, config):
                notes.append(unsettled)
        else:
            steps, step_of, width = series.ramp_steps(time_s, pressure, force)
            handling["steps_from"] = (f"quasi-static bins of {width:.3g} bar, rising and "
                                      "falling branches apart")
            twentieth = max(float(np.ptp(pressure)) / series.RAMP_BINS,
                            series.RAMP_MIN_BIN_BAR)
            if steps and width > twentieth * (1.0 + 1e-9):
                apart = float(np.median(np.abs(np.diff(pressure))[step_of[1:] >= 0]))
                notes.append(f"bins of {width:.3g} bar, {width / twentieth:g} times a "
                             f"twentieth of its range: its samples lie {apart:.2g} bar apart "
                             "on the sweeps (the median), and narrower bins would hold one "
                             "each, left out")
        if not steps:
            apart = float(np.median(np.diff(time_s))) if time_s.size > 1 else math.nan
            raise ValueError(f"{group.named}: no step found in the time series (pressure "
                             f"{pressure.min():g}-{pressure.max():g} bar, {time_s.size} samples "
                             f"{apart:.3g} s apart): expected plateaus held "
                             f"{series.PLATEAU_MIN_S:g} s or more, or a ramp; if each row is a "
                             "held pressure, import again with --one-step-per-row")
        tare_rows = np.zeros(pressure.size, dtype=bool)
        tare_rows[zero_rows] = True
        samples = [Sample(k, float(t), int(s), "tare" if tare_rows[k] else "step", math.nan,
                          math.nan, float(p), math.nan, math.nan, float(f), "")
                   for k, (t, s, p, f) in enumerate(zip(time_s, step_of, pressure, force,
                                                        strict=True))]
        notes.insert(0, f"{len(samples)} samples")
    elif record:
        # a record whose clock the table left out, its rows the clock: a staircase's plateaus,
        # or a ramp's rows binned (by pressure, each branch apart); every row kept in the run
        # folder as the table it came in
        rows = np.arange(pressure.size, dtype=float)
        held = series.held_plateaus(rows, pressure, min_s=series.RECORD_PLATEAU_ROWS)
        shape = series.shape(rows, pressure, held)
        apart = float(np.median(np.abs(np.diff(pressure))))
        what = (f"a record without time ({pressure.size} rows, successive readings "
                f"{apart:.2g} bar apart, the median)")
        if shape == "staircase":
            steps = series.untimed_staircase_steps(pressure, force, held, unread)
            handling["steps_from"] = (f"{what}: plateaus of {series.RECORD_PLATEAU_ROWS} rows "
                                      "or more, each averaged over its second half")
            done = f"its {len(steps)} plateaus averaged over their second halves"
        else:
            steps, _, width = series.ramp_steps(rows, pressure, force)
            steps = [s._replace(start_s=math.nan, end_s=math.nan) for s in steps]
            handling["steps_from"] = (f"{what}: quasi-static bins of {width:.3g} bar, rising "
                                      "and falling branches apart")
            done = f"binned by {width:.3g} bar on each branch"
        handling["table_copy"] = TABLE_COPY + path.suffix.lower()
        notes.insert(0, f"{pressure.size} rows of a record without time (successive readings "
                     f"{apart:.2g} bar apart): {done}, every row kept in "
                     f"{handling['table_copy']}; if each row is a held pressure, import again "
                     "with --one-step-per-row; if its rows were logged at a known rate, "
                     "--sample-rate HZ times them")
    else:
        shape = "steps"
        std = group.values("force_std", optional=True) if "force_std" in found else \
            np.full(pressure.size, math.nan)
        repeats: dict[tuple[str, float], int] = {}
        steps = []
        at = step_times if step_times is not None else np.full(pressure.size, math.nan)
        for k, (p, f, s, d) in enumerate(zip(pressure, force, std, order, strict=True)):
            key = (d, round(float(p), 3))
            repeats[key] = repeats.get(key, -1) + 1
            steps.append(StepRecord(k, d, repeats[key], float(p), float(p), float(f), float(s),
                                    1, True, math.nan, float(at[k]), float(at[k])))
    if accuracy:
        steps = _with_budget(steps, accuracy, shape)
        handling["declared_accuracy"] = {q: b.record() for q, b in accuracy.items()}
        if "pressure" not in accuracy:
            notes.append("no pressure accuracy declared: the pressures counted as exact")
    if "slack" in found:
        slack = int(flags(table, found["slack"])[group.rows].sum())
        handling["slack_rows"] = slack
        if slack:
            notes.append(f"{slack} slack row(s) ({found['slack'].header}): kept at their force")
    if not np.any(force != 0):
        notes.append("every force is 0 N: no model error can be scored against this run")
    elif weak := _far_below_a_pull(pressure, force, muscle, found["force"]):
        notes.append(weak)
    elif np.ptp(pressure) > 0 and np.ptp(force) > 0 and (
            -np.polyfit(pressure, force, 1)[0] * np.ptp(pressure) > 0.5 * np.ptp(force)):
        # a muscle pulls harder the higher its pressure: a force that falls with it (the line
        # through it falls by more than half the forces' spread: a slack muscle's forces, all
        # alike, fall by round-off) is a load cell read with the opposite sign (compression
        # positive), which every model would score as wrong
        low, high = int(np.argmin(pressure)), int(np.argmax(pressure))
        notes.append(f"the force falls as the pressure rises ({force[low]:.4g} N at "
                     f"{pressure[low]:g} bar, {force[high]:.4g} N at {pressure[high]:g} bar): "
                     "a muscle pulls harder with pressure; "
                     + ("--force-sign -1 negated them: import again without it" if force_sign < 0
                        else "if the load cell reads the pull negative, import again with "
                        "--force-sign -1"))
    now = datetime.datetime.now(datetime.UTC).isoformat(timespec="seconds")
    prov = provenance()
    imported = {"file": path.name, "sha256": sha, "shape": shape, "state": group.state,
                "split_by": group.key,
                **group.recognition.describe(), **handling}
    meta = RunMeta(
        muscle=muscle, status=RunStatus.IMPORTED,
        reason=f"imported from {group.named}: measured elsewhere, "
        + ("samples and steps derived from them" if timed else "one row per step, no samples"),
        hardware={"backend": "import"}, sequence={"n_steps": len(steps)},
        steps_done=len(steps), command=prov["command"], provenance=prov, started_utc=now,
        ended_utc=now, imported_from=imported, counters={
            "samples": len(samples), "read_timeouts": 0, "clipped_samples": 0})
    return meta, steps, samples, notes, shape


#: the units a lab's pressures are written in that read as bar pass as a bar 10-100 times
MISREAD_PRESSURE_UNITS = ("kPa", "psi")
#: a logger's millibar read as bar, a thousand times: named where none of those brings the
#: readings within the range
MISREAD_PRESSURE_UNITS_THEN = ("mbar",)


def _other_pressure_units(top_bar: float, unit: str | None) -> str:
    """What the note on pressures above the practical range suggests: each unit of
    :data:`MISREAD_PRESSURE_UNITS` other than the column's (``None``: bar) in which its
    largest reading lies within the range (a psi column is not told it may be psi)."""
    from mkm.bench.tables import parse_unit, registry

    def in_bar(name: str | None) -> float:
        found = parse_unit(name) if name else None
        return float(registry().Quantity(1.0, found or registry().Unit("bar")).to(
            "bar").magnitude)

    written = top_bar / in_bar(unit)  # the largest reading as the table writes it

    def fitting(units) -> list[str]:
        return [u for u in units if not math.isclose(in_bar(u), in_bar(unit))
                and written * in_bar(u) <= PRACTICAL_RANGE.pressure_bar[1]]

    fits = fitting(MISREAD_PRESSURE_UNITS) or (
        fitting(MISREAD_PRESSURE_UNITS_THEN) if math.isclose(in_bar(unit), 1.0) else [])
    if not fits:
        return "check the column's unit (--units pressure=UNIT)"
    return (f"if they are {' or '.join(fits)}, import again with --units pressure={fits[0]}"
            + "".join(f" (or {u})" for u in fits[1:]))


#: how far below Equation 2's force at the top pressure a table's largest force must lie to be
#: questioned: a muscle's friction, a softer rubber or a braid angle off take tens of per cent,
#: a load cell's kN read as N a thousandth
FAR_BELOW_A_PULL = 0.01


def _far_below_a_pull(pressure, force, muscle, column) -> str:
    """The note (or "") on forces under :data:`FAR_BELOW_A_PULL` of the force Equation 2 gives
    the muscle at the table's top pressure: a load cell's kN read as N."""
    from mkm.fem.ladder import make_model

    top = int(np.argmax(pressure))
    ideal = make_model("eq2").predict(float(pressure[top]), muscle.D0_mm, muscle.t0_mm,
                                      muscle.eps)
    largest = float(np.max(np.abs(force)))
    if not (bool(np.all(ideal.valid)) and largest < FAR_BELOW_A_PULL * float(ideal.force_N)):
        return ""
    read = (f"read as N since {column.header!r} names no unit" if column.unit is None
            else f"read in {column.unit} as its cells say" if column.in_cells
            else f"read in {column.unit} as {column.header!r} says")
    return (f"forces up to {largest:.3g} N at {pressure[top]:g} bar, {read}: under "
            f"{100 * FAR_BELOW_A_PULL:g} % of the {float(ideal.force_N):.3g} N Equation 2 gives "
            "this muscle there; if they are kN, import again with --units force=kN (else check "
            "the muscle's --D0, --t0 and --eps)")


def _with_budget(steps: list[StepRecord], accuracy: dict[str, Declared],
                 shape: str) -> list[StepRecord]:
    """``steps`` with the budget of the bounds the lab declared."""
    from mkm.bench.budget import declared_step_budget

    return [s._replace(**declared_step_budget(accuracy, s, shape == "staircase").columns())
            for s in steps]


def _inferred(pressure: np.ndarray) -> np.ndarray:
    """Each row's direction: the branch it lies on (:func:`mkm.bench.series.branches`: the
    sweep turns where the pressure comes back a tenth of its range from the branch's extreme),
    the first up. A table of several cycles has a rising branch in each, not only in the
    first; a pressure written twice where the sweep turns (``1, 0, 0, 1``) ends one branch and
    starts the next; a reading's noise (a record sampled without its time) turns none."""
    out = np.empty(pressure.size, dtype=object)
    for start, stop, direction in series.branches(pressure):
        out[start:stop] = direction
    return out.astype(str)


def export_run(run_dir: str | Path, out: str | Path, fmt: str = "xlsx") -> Path:
    """The run ``run_dir`` as ``out`` (a ``.xlsx`` workbook) or, with ``fmt="csv"``, as the
    folder ``out`` holding ``steps.csv``, ``samples.csv`` and ``metadata.csv``; with the table
    the run was imported from where it keeps one (:data:`TABLE_COPY`): the file as it came,
    beside the CSV files, or the table as ``mkm import`` read it, the workbook's sheet
    ``imported_table``."""
    if fmt not in EXPORT_FORMATS:
        raise ValueError(f"--format {fmt!r} is invalid: expected {' or '.join(EXPORT_FORMATS)}")
    out = Path(out)
    _check_export_target(out, fmt)
    run = load_run(run_dir)
    run.require_content("sheet")
    samples = run.samples
    if fmt == "xlsx" and len(samples) > EXCEL_MAX_ROWS:
        raise ValueError(f"{run.path.name} has {len(samples)} samples: a worksheet holds at "
                         f"most {EXCEL_MAX_ROWS}; use --format csv")
    # the loader's status and problems: a dead run's record still says "running", a copy cut
    # short still says every sample is there
    # and the export's own record: a workbook travels without its run folder
    exported = {"source": str(run.path), "sha256": run.sha256(), **provenance()}
    copy = (run.meta.imported_from or {}).get("table_copy")
    if copy and not (run.path / copy).is_file():
        raise ValueError(f"{run.path.name}: the table it was imported from, {copy}, is missing "
                         "from the run folder: expected the copy mkm import keeps there (import "
                         "the table again)")
    if copy:
        exported["imported_table"] = (copy if fmt == "csv" else
                                      f"sheet {TABLE_COPY!r}: the table as mkm import read it")
    metadata = pd.DataFrame(_flatten({**run.meta.as_dict(), "status": str(run.status),
                                      "problems": run.problems, "exported": exported}),
                            columns=["key", "value"])
    sheets = {"steps": run.steps, "samples": samples, "metadata": metadata}
    if copy and fmt == "xlsx":
        (table,) = read_tables(run.path / copy, run.meta.imported_from.get(
            "table_copy_sheet", run.meta.imported_from.get("sheet")))
        if len(table.rows) > EXCEL_MAX_ROWS:
            raise ValueError(f"{run.path.name}: its imported table has {len(table.rows)} rows: "
                             f"a worksheet holds at most {EXCEL_MAX_ROWS}; use --format csv")
        sheets[TABLE_COPY] = pd.DataFrame(numbers_as_read(table), columns=table.header)
    sheets = {name: spreadsheet_safe(frame) for name, frame in sheets.items()}
    if fmt == "xlsx":
        out.parent.mkdir(parents=True, exist_ok=True)
        with pd.ExcelWriter(out, engine="openpyxl") as book:
            for name, frame in sheets.items():
                frame.to_excel(book, sheet_name=name, index=False)
        return out
    out.mkdir(parents=True, exist_ok=True)
    for name, frame in sheets.items():
        frame.to_csv(out / f"{name}.csv", index=False, float_format="%.10g",
                     encoding=SPREADSHEET_CSV_ENCODING)
    for stale in out.glob(f"{TABLE_COPY}.*"):  # an earlier export's: not this run's table
        stale.unlink()
    if copy:
        shutil.copyfile(run.path / copy, out / copy)
    return out


def _check_export_target(out: Path, fmt: str) -> None:
    """``ValueError`` unless ``out`` can take the export: a workbook named ``.xlsx`` that is
    new or one mkm export wrote (never a lab's own table), or a folder for the CSV files."""
    if fmt == "csv":
        if out.exists() and not out.is_dir():
            raise ValueError(f"--out {out} is a file: expected a folder for steps.csv, "
                             "samples.csv and metadata.csv (--format csv)")
        held = [f"{name}.csv" for name in EXPORT_SHEETS if (out / f"{name}.csv").exists()]
        if held and not _an_export_folder(out):
            what = ("is a run folder" if (out / "run.json").exists() else
                    f"holds {', '.join(held)} that mkm export did not write")
            raise ValueError(f"--out {out} {what}: expected a new folder, or one mkm export "
                             "wrote (nothing is overwritten)")
        return
    if out.suffix.lower() != ".xlsx":
        raise ValueError(f"--out {out}: expected a workbook name ending in .xlsx (or --format "
                         "csv and a folder)")
    if out.is_dir():
        raise ValueError(f"--out {out} is a folder: expected a workbook name ending in .xlsx")
    if out.exists() and set(sheet_names(out)) - {TABLE_COPY} != set(EXPORT_SHEETS):
        raise ValueError(f"--out {out} exists and is not a workbook mkm export wrote: expected "
                         "a new name (nothing is overwritten)")


def _an_export_folder(folder: Path) -> bool:
    """Whether ``folder`` holds a CSV export of mkm export's own (its metadata.csv of keys and
    values beside the steps), not a run folder nor a lab's own tables of those names."""
    if (folder / "run.json").exists() or not (folder / "metadata.csv").is_file():
        return False
    try:
        with open(folder / "metadata.csv", encoding="utf-8-sig", newline="") as f:
            first = f.readline().strip()
    except (OSError, UnicodeDecodeError):
        return False
    return first == "key,value"


def _flatten(data, prefix: str = "") -> list[tuple[str, str]]:
    """``run.json`` as ``(dotted.key, value)`` rows: one cell per value."""
    rows = []
    if isinstance(data, dict):
        for key, value in data.items():
            rows += _flatten(value, f"{prefix}{key}.")
    elif isinstance(data, list) and data and all(isinstance(v, dict) for v in data):
        for k, value in enumerate(data):
            rows += _flatten(value, f"{prefix}{k}.")
    else:
        value = json.dumps(data) if isinstance(data, list) else data
        rows.append((prefix.rstrip("."), "" if value is None else str(value)))
    return rows
