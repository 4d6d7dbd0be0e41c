"""Tables labs keep: read any common layout and recognise what each column holds, in what unit.

- :func:`read_tables`: a ``.csv``/``.tsv``/``.txt`` file (separator ``,``, ``;`` or tab, decimal
  commas detected, ``#`` comment lines and title rows above the header skipped), an ``.xlsx``
  workbook (every sheet, or one named) or an NI ``.tdms`` file (every group, or one named: its
  channels the columns) as :class:`RawTable` s of text and number cells, each cell keeping its
  place in the file so that a bad one can be named (``lab.csv, cell B7``).
- :func:`parse_header`: a header such as ``Pressure (bar)``, ``pressure [kPa]``, ``p_psi``,
  ``F [kgf]``, ``load_lbf``, ``t (s)`` or ``contraction (%)`` as a name and a unit.
- :func:`recognise`: which column holds each :data:`ROLES` entry (the name matched against the
  role's spellings, or a German compound's ending, the unit checked to have the role's
  dimension), ``--columns`` and ``--units`` overriding.
- :func:`column_values`: a recognised column's cells as numbers in the toolkit's unit
  (bar, N, s, mm, fraction), converted by pint; a time column of clock readings
  (``hh:mm:ss.fff``, ``2:05:00 PM``), stopwatch readings (``mm:ss.f``) or date-times as
  seconds from its first row.

Nothing in a table can run code: cells are read as text and numbers only (openpyxl reads a
workbook's cached values; a formula's text is read only to name it where no value was saved;
npTDMS reads a TDMS file's numbers, texts and properties, no pickle).
"""

from __future__ import annotations

import csv
import datetime
import glob
import io
import itertools
import logging
import math
import re
from dataclasses import dataclass, field, replace
from functools import cache
from pathlib import Path

import numpy as np

from mkm.bench.series import PLATEAU_TOLERANCE_BAR
from mkm.core.guards import table_file
from mkm.core.records import file_sha256
from mkm.core.toml_text import TEXT_END_PADDING, saved_text

#: the largest table read (rows below the header, over all sheets)
MAX_ROWS = 2_000_000
SEPARATORS = (",", ";", "\t")
#: text tables read; ``.lvm`` is LabVIEW's measurement file (tab separated under a header block)
#: and ``.xls`` the tab-separated text LabVIEW's Write To Spreadsheet File and loggers name so
#: (an Excel 97-2003 workbook is refused, naming what to save it as)
TEXT_SUFFIXES = (".csv", ".tsv", ".txt", ".lvm", ".xls")
#: how a binary file that is no text table starts: an Excel 97-2003 workbook (OLE2), and a
#: zip archive (an .xlsx saved or renamed under a text table's name)
_OLE2_MAGIC = b"\xd0\xcf\x11\xe0\xa1\xb1\x1a\xe1"
_ZIP_MAGIC = b"PK\x03\x04"
#: workbooks read, every sheet a table
WORKBOOK_SUFFIXES = (".xlsx", ".xlsm")
#: NI's TDMS files (LabVIEW, SignalExpress, FlexLogger, DAQmx logging), every group a table
TDMS_SUFFIXES = (".tdms",)
#: the channel properties that give a TDMS channel its unit, the first that reads as one taken:
#: ``unit_string`` (LabVIEW, DAQmx, FlexLogger), NI's ``NI_UnitDescription`` (SignalExpress)
TDMS_UNIT_PROPERTIES = ("unit_string", "NI_UnitDescription")
#: a TDMS waveform's time axis: its sampling interval [s], and its first sample's time [s]
TDMS_WAVEFORM = ("wf_increment", "wf_start_offset")
#: the longest text of a TDMS file's or group's property, or of npTDMS's warning, kept
TDMS_PROPERTY_CHARS = 200
#: npTDMS's warnings on a damaged file kept (the first, each once)
TDMS_WARNINGS_KEPT = 5


#: loggers' own binary files and other programs' spreadsheets, and how each becomes a table
#: mkm reads
LOGGER_FILES = {
    ".tdm": "NI's TDM file: open it in Excel with NI's TDM importer and save it as .xlsx",
    ".tdms_index": "the index NI's software writes beside a TDMS file (no samples): import the "
                   ".tdms file itself",
    ".dxd": "DEWESoft's data file: export it from DEWESoft as CSV or Excel",
    ".d7d": "DEWESoft's data file: export it from DEWESoft as CSV or Excel",
    ".mf4": "an ASAM MDF file: export it as CSV from the logger's software (or asammdf)",
    ".ods": "a LibreOffice (OpenDocument) spreadsheet: save it as .xlsx (File > Save As, Excel "
            "2007-365) or as CSV",
    ".numbers": "an Apple Numbers spreadsheet: export it as .xlsx or CSV (File > Export To)",
}


def table_suffixes_text() -> str:
    """The files :func:`read_tables` reads, in words: ``.csv, .tsv, ... or .tdms``."""
    *first, last = (*TEXT_SUFFIXES, *WORKBOOK_SUFFIXES, *TDMS_SUFFIXES)
    return f"{', '.join(first)} or {last}"
#: words of a header that say which reading of a quantity it is (German Ist: the actual
#: value, beside the Soll, the set one), dropped from its name
STAT_WORDS = {"mean", "avg", "average", "measured", "meas", "value", "actual", "act", "ist",
              "istwert", "gemessen", "mittelwert"}
#: how a German one-word compound naming a set point starts (Solldruck, Sollkraft): no reading,
#: left out as Druck_Soll is
SET_POINT_PREFIX = "soll"


@dataclass(frozen=True)
class Role:
    """What a column may hold: the spellings of its name, its unit (``None``: text or flags)."""

    names: tuple[str, ...]
    unit: str | None = None  # the toolkit's unit; "" is a dimensionless fraction
    #: endings of one-word compounds that name it too (German: Zugkraft, Luftdruck)
    endings: tuple[str, ...] = ()

    def matches(self, name: str) -> bool:
        return name in self.names or (bool(self.endings) and " " not in name
                                      and name.endswith(self.endings)
                                      and not name.startswith(SET_POINT_PREFIX)
                                      and not _statistic_compound(name)
                                      and not supply(name))


#: the roles a column may take by its unit alone, where no column's name says it
BY_UNIT_ROLES = ("pressure", "force")
#: the words of a column's name that make it a set point, no reading (p_set, Druck_Soll)
SET_POINT_WORDS = {"soll", "sollwert", "set", "setpoint", "target", "command", "cmd"}


def _set_point(name: str) -> bool:
    return name.startswith(SET_POINT_PREFIX) or bool(SET_POINT_WORDS & set(name.split()))


#: the words of a column's name that make it a statistic of a quantity, no reading of it (a
#: results sheet's 'F max (N)', 'Peak force'): not taken by its unit alone (a mean is a hold's
#: reading, as a step table gives it, and a total the sum of load cells sharing the pull)
STATISTIC_WORDS = {"min", "max", "minimum", "maximum", "peak", "spitze", "std", "stdev", "sd",
                   "count", "anzahl", "range", "maximal", "maximale", "minimal", "minimale",
                   "maxi", "mini", "spitzenwert", "höchstwert", "hoechstwert", "maximalwert",
                   "minimalwert"}
#: how a one-word compound naming a statistic of a force or a pressure starts or ends
#: (German Maximalkraft, Höchstkraft, Spitzendruck, Mindestdruck, Kraftspitze,
#: Druckmaximum; English maxforce; Fmax, pmin), longest first: no reading, as 'F max' is none
STATISTIC_PREFIXES = ("maximal", "minimal", "hoechst", "spitzen", "mindest", "höchst", "peak",
                      "max", "min")
STATISTIC_SUFFIXES = ("maximum", "minimum", "spitze", "max", "min", "peak")


def _statistic_compound(word: str) -> bool:
    """Whether one word is a statistic's prefix or suffix joined to the name of a force or a
    pressure (``maximalkraft``, ``höchstzugkraft``, ``fmax``): a short prefix (``max``,
    ``min``) or a suffix to the name itself, so that ``minderdruck`` stays a pressure."""
    def reading(rest: str, compound: bool) -> bool:
        return any(rest in ROLES[r].names or (compound and ROLES[r].endings and rest.endswith(
            ROLES[r].endings)) for r in BY_UNIT_ROLES)

    prefix = next((p for p in STATISTIC_PREFIXES if word.startswith(p)), None)
    suffix = next((p for p in STATISTIC_SUFFIXES if word.endswith(p)), None)
    return bool(prefix and reading(word[len(prefix):], len(prefix) > 3)
                or suffix and reading(word[:-len(suffix)], False))


#: the words of a pressure column's name that make it the supply's, upstream of the regulator
#: (a logger's channel beside the muscle's: 'Versorgungsdruck', 'Supply pressure'), no reading
#: of the muscle's pressure
SUPPLY_WORDS = {"supply", "inlet", "versorgung", "versorgungsdruck", "vordruck", "eingangsdruck",
                "netzdruck", "speisedruck", "zuluftdruck", "systemdruck"}


def supply(name: str) -> bool:
    """Whether a column's name (as :func:`parse_header` gives it) names the supply pressure
    upstream of the regulator (:data:`SUPPLY_WORDS`)."""
    return bool(SUPPLY_WORDS & set(name.split()))


def statistic(name: str) -> bool:
    """Whether a column's name (as :func:`parse_header` gives it) names a statistic: a word of
    :data:`STATISTIC_WORDS`, or one word compounding a statistic with a force or a pressure
    (:func:`_statistic_compound`)."""
    words = name.split()
    return bool(STATISTIC_WORDS & set(words)) or (len(words) == 1
                                                  and _statistic_compound(words[0]))
#: the names of a clock whose unit the name says: an Arduino logger's millis() and micros()
CLOCK_NAMES = {"millis": "ms", "micros": "us"}
#: the count after which an Arduino's micros() and millis() start from 0 again (an unsigned
#: 32-bit counter of microseconds or milliseconds: 4294.967296 s, about 71.6 min, and 49.7 days)
CLOCK_WRAP = 2**32
#: the names of a clock of seconds since 1970, as loggers name it
EPOCH_NAMES = ("unix time", "unix timestamp", "epoch", "epoch time", "posix time")
#: every column a lab's table may have -> the names it goes by (lower case, words joined by one
#: space) and the toolkit's unit
ROLES = {
    "pressure": Role(("p", "pressure", "pres", "druck", "pression", "pressione", "presión",
                      "presion", "pressão", "pressao", "druk"), "bar", ("druck",)),
    "force": Role(("f", "force", "load", "kraft", "tension", "effort", "forza", "fuerza",
                   "força", "forca", "kracht"), "N", ("kraft",)),
    "time": Role(("t", "time", "zeit", "elapsed", "elapsed time", "timestamp", "time stamp",
                  "datetime", "date time", "date and time", "uhrzeit", "zeitstempel",
                  "datum zeit", "datum uhrzeit", "datum und uhrzeit", "datum und zeit",
                  "relative time", "time since start", "runtime", "run time", "test time",
                  "messzeit", "laufzeit", "prüfzeit", "pruefzeit", "versuchszeit",
                  "zeitpunkt", "messzeitpunkt",
                  "relative zeit", "zeit seit start", "temps", "temps écoulé",
                  "tempo", "tiempo", "tijd",
                  "temps ecoule", "horodatage", "time 1 default sample rate",
                  "zeit 1 standardmessrate",
                  *EPOCH_NAMES, *CLOCK_NAMES), "s"),
    "direction": Role(("direction", "dir", "branch", "sweep", "richtung", "sens")),
    "force_std": Role(("force std", "std", "force sd", "sd", "force stdev", "std force"), "N"),
    "eps": Role(("eps", "epsilon", "contraction", "shortening", "strain",
                 "shortening ratio", "contraction ratio", "kontraktion", "verkürzung",
                 "verkuerzung"), ""),
    "length": Role(("l", "length", "held length", "laenge", "länge"), "mm"),
    "L0": Role(("l0", "rest length", "initial length", "length at rest", "ruhelänge",
                "ruhelaenge", "ausgangslänge", "ausgangslaenge"), "mm"),
    "run": Role(("run", "run id", "test", "trial", "series")),
    "muscle": Role(("muscle", "muscle id", "actuator", "specimen")),
    "slack": Role(("zero entry", "slack")),
}
#: the direction words a table may use (English, German, French) -> the run folder's ``up``/``down``
DIRECTION_WORDS = {"up": "up", "rising": "up", "increasing": "up", "loading": "up",
                   "load": "up", "increase": "up", "inc": "up", "ascending": "up",
                   "down": "down", "falling": "down", "decreasing": "down", "unloading": "down",
                   "unload": "down", "decrease": "down", "dec": "down", "descending": "down",
                   "dn": "down",
                   "auf": "up", "steigend": "up", "belastung": "up", "belasten": "up",
                   "aufwärts": "up", "aufwaerts": "up",
                   "ab": "down", "fallend": "down", "entlastung": "down", "entlasten": "down",
                   "abwärts": "down", "abwaerts": "down",
                   "montée": "up", "montee": "up", "charge": "up",
                   "descente": "down", "décharge": "down", "decharge": "down"}


@dataclass
class RawTable:
    """One table as read: ``header`` and ``rows`` of cells (text or numbers), with the file row
    of each (1-based, as a spreadsheet shows it)."""

    source: Path
    sheet: str | None
    header: list[str]
    header_row: int
    rows: list[list]
    row_numbers: list[int]
    title_rows: int = 0
    separator: str | None = None
    decimal: str = "."
    #: the first blank cell of each row :func:`without_blank_rows` left out (``B7``)
    blanks_skipped: list[str] = field(default_factory=list)
    #: the first overload mark of each row :func:`without_blank_rows` left out (``C7 ('OVL')``)
    overloads_skipped: list[str] = field(default_factory=list)
    #: the first cell of each row :func:`without_repeated_rows` left out (``A12``)
    repeats_skipped: list[str] = field(default_factory=list)
    #: the time cell of each row sharing the row above's time with other readings, kept as
    #: samples of their own (a clock coarser than the sampling)
    times_shared: list[str] = field(default_factory=list)
    #: the cell naming the statistic of each row :func:`without_summary_rows` left out
    summaries_skipped: list[str] = field(default_factory=list)
    #: the first cell of each row of the notes under the table, after a blank row (no data)
    footer_skipped: list[str] = field(default_factory=list)
    #: the block of rows under a record's samples that :func:`without_summary_block` left
    #: out as their summary: its rows' time cells, their span as said and why
    block_skipped: dict = field(default_factory=dict)
    #: what :func:`join_by_time` joined to it: the other table, its columns, the times' origin
    joined: dict = field(default_factory=dict)
    #: the sampling interval its header block states, as written (LabChart's ``Interval=
    #: 0.01 s``, a LabVIEW measurement file's ``Delta_X 0.010000``), and in seconds: its rows'
    #: times where it has no time column
    interval: tuple[str, float] | None = None
    #: what a TDMS file says of itself (``file``), of the group (``group``) and of its
    #: waveforms' time axis (``waveform``): their properties, kept in the run folder
    properties: dict = field(default_factory=dict)
    #: what the reader warned of while reading a damaged file (npTDMS: a segment cut short)
    read_warnings: list[str] = field(default_factory=list)
    #: a LabVIEW measurement file's segments that timed its rows (:func:`_lvm_times`): how
    #: many, what told their starts, their Delta_X as written, the time between them unlogged
    lvm_segments: dict = field(default_factory=dict)
    #: each row's file where several files were joined into this table (:func:`join_files`);
    #: empty for one file
    row_files: list[str] = field(default_factory=list)
    #: the lines above the header row (comments and titles), as written, each with its line:
    #: what the file says of the record (a held length, the muscle); a TDMS file's properties
    #: as ``name: value``, each with where it is; several files' with their file's name
    preamble: list[tuple[int | str, str]] = field(default_factory=list)

    @property
    def part(self) -> str:
        """What the file calls the part of it this table is: a workbook's sheet, a TDMS
        file's group."""
        return "group" if self.source.suffix.lower() in TDMS_SUFFIXES else "sheet"

    @property
    def name(self) -> str:
        return (f"{self.source.name}, {self.part} {self.sheet!r}" if self.sheet
                else self.source.name)

    def cell(self, k: int, column: int) -> str:
        """The spreadsheet reference of data row ``k``'s cell in ``column`` (``B7``)."""
        return f"{_column_letters(column)}{self.row_numbers[k]}"

    def where(self, k: int, column: int) -> str:
        """Data row ``k``'s cell in ``column`` with its file: ``lab.csv, cell B7``; of a
        table joined from several files, the row's own file (``step4.csv, cell B7``)."""
        name = self.row_files[k] if self.row_files else self.name
        return f"{name}, cell {self.cell(k, column)}"

    def ref(self, k: int, column: int) -> str:
        """Data row ``k``'s cell in ``column`` as the lists of skipped rows name it: ``B7``,
        and where several files were joined, its file too (``step4.csv B7``)."""
        return (f"{self.row_files[k]} " if self.row_files else "") + self.cell(k, column)

    def kept(self, keep) -> RawTable:
        """The table of the data rows ``keep`` (indices, in order)."""
        return replace(self, rows=[self.rows[k] for k in keep],
                       row_numbers=[self.row_numbers[k] for k in keep],
                       row_files=[self.row_files[k] for k in keep] if self.row_files else [])

    def describe(self) -> dict:
        """What the reader found, for the run folder's provenance."""
        return {"sheet": self.sheet, "header_row": self.header_row,
                "title_rows": self.title_rows, "separator": self.separator,
                "decimal": self.decimal, "rows": len(self.rows),
                "rows_skipped_for_a_blank_cell": self.blanks_skipped,
                "rows_skipped_for_an_overload": self.overloads_skipped,
                "rows_skipped_as_repeats": self.repeats_skipped,
                "rows_sharing_a_time_kept": self.times_shared,
                "summary_rows_skipped": self.summaries_skipped,
                "footer_rows_skipped": self.footer_skipped,
                **({"summary_block_skipped": self.block_skipped} if self.block_skipped
                   else {}),
                **({"joined_by_time": self.joined} if self.joined else {}),
                **({"tdms_properties": self.properties} if self.properties else {}),
                **({"read_warnings": self.read_warnings} if self.read_warnings else {}),
                **({"lvm_segments": self.lvm_segments} if self.lvm_segments else {})}


def _column_letters(index: int) -> str:
    letters = ""
    index += 1
    while index:
        index, rest = divmod(index - 1, 26)
        letters = chr(ord("A") + rest) + letters
    return letters


# --- reading ----------------------------------------------------------------------------------

_NUMBER = re.compile(r"^[+-]?(\d+([.,]\d*)?|[.,]\d+)([eE][+-]?\d+)?$")
# a unit of two words is one pint or LAB_UNITS reads as one ('in Hg', 'in. Hg', 'bar g')
_NUMBER_AND_UNIT = tuple(re.compile(rf"^(?P<number>[-+.,\deE]+{lazy})\s*"
                                    r"(?P<unit>[A-Za-z%°µ][\w%°µ/^]*(?:\.?\s+[A-Za-z]\w*)?)?$")
                         for lazy in ("", "?"))
_COMMA_DECIMAL = re.compile(r"^[+-]?\d*,\d+([eE][+-]?\d+)?$")
_POINT_DECIMAL = re.compile(r"^[+-]?\d*\.\d+([eE][+-]?\d+)?$")
_THOUSANDS = re.compile(r"^[+-]?\d{1,3}(,\d{3})+$")
#: a number with thousands grouped and a decimal mark ('1.234,5', '1,234.5'): unambiguous where
#: the table's decimal mark is known (a grouped number without one is not: '1.234')
_GROUPED = {",": re.compile(r"^(?P<number>[+-]?\d{1,3}(\.\d{3})+,\d+)(?P<rest>.*)$"),
            ".": re.compile(r"^(?P<number>[+-]?\d{1,3}(,\d{3})+\.\d+)(?P<rest>.*)$")}

#: marks that group a number's thousands and are no decimal mark anywhere: an apostrophe (Swiss
#: 1'234.5, typeset 1’234.5) and a thin, narrow no-break or no-break space (French 1 234,5)
_GROUP_MARKS = "'\u2019\u2009\u202f\u00a0"
_MARK_GROUPED = re.compile(rf"^(?P<sign>[+-]?)(?P<digits>\d{{1,3}}(?:[{_GROUP_MARKS}]\d{{3}})+)"
                           rf"(?![\d{_GROUP_MARKS}])")


def _ungrouped(text: str) -> str:
    """``text`` with the marks of :data:`_GROUP_MARKS` dropped from a leading number grouped
    by threes (``1'234.5`` -> ``1234.5``); any other text as it is."""
    match = _MARK_GROUPED.match(text)
    if not match:
        return text
    return (match["sign"] + re.sub(f"[{_GROUP_MARKS}]", "", match["digits"])
            + text[match.end():])


def read_tables(path: str | Path, sheet: str | None = None) -> list[RawTable]:
    """The tables in ``path``: one for a text file, one per sheet of a workbook (or the sheet
    named ``sheet``); ``ValueError`` naming the file when it cannot be read."""
    path = Path(path)
    if not path.exists():
        raise ValueError(f"{path}: no such file: expected a table ({table_suffixes_text()})")
    path = table_file(path)  # before any parser: links, empty files, bombs, DTDs refused
    suffix = path.suffix.lower()
    if suffix in WORKBOOK_SUFFIXES:
        return _read_workbook(path, sheet)
    if suffix in TDMS_SUFFIXES:
        return _read_tdms(path, sheet)
    if suffix in LOGGER_FILES:
        raise ValueError(f"{path.name} is {LOGGER_FILES[suffix]}: mkm reads "
                         f"{table_suffixes_text()}")
    if suffix not in TEXT_SUFFIXES:
        raise ValueError(f"{path}: unknown table format {suffix!r}: expected "
                         f"{table_suffixes_text()}")
    if sheet is not None:
        raise ValueError(f"--sheet {sheet!r}: {path.name} is a text table, it has no sheets")
    try:
        data = path.read_bytes()
    except OSError as exc:
        raise ValueError(f"{path} cannot be read ({exc.strerror or exc})") from None
    if data.startswith(_OLE2_MAGIC):
        raise ValueError(f"{path.name} is an Excel 97-2003 workbook: expected an .xlsx "
                         "workbook or a CSV table; open it in Excel and save it as .xlsx")
    if data.startswith(_ZIP_MAGIC):
        raise ValueError(f"{path.name} is a zip archive (an .xlsx workbook?) under a "
                         f"{suffix} name: expected a text table; if it is a workbook, rename "
                         "it to .xlsx")
    try:
        text = saved_text(data)  # Excel's "Unicode Text" is UTF-16
    except UnicodeDecodeError:
        text = _windows_text(data.rstrip(TEXT_END_PADDING.encode()))
    return [_text_table(path, text)]


def _windows_text(data: bytes) -> str:
    """A text table that is no UTF-8: Windows' code page 1252, as Excel and loggers on a
    Western European Windows save it (its ‰, €, – and curly quotes are no Latin-1 control
    characters), else Latin-1, which decodes any byte."""
    try:
        return data.decode("cp1252")
    except UnicodeDecodeError:  # the five bytes code page 1252 leaves undefined
        return data.decode("latin-1")


def _text_table(path: Path, text: str) -> RawTable:
    numbered = [(k + 1, line) for k, line in enumerate(text.splitlines()) if line.strip()]
    lines = [(n, line) for n, line in numbered if not _comment(line)]
    if not lines:
        raise ValueError(f"{path} is empty: expected a header row and one row per step or "
                         "sample")
    lines = _with_quoted_line_breaks(lines)
    separator = _separator([line for _, line in lines])
    lines = _with_commented_units(numbered, lines, separator)
    # a row of separators only (";;;", as a spreadsheet exports its empty rows) is blank too
    parsed = [(n + j, cells) for n, line in lines
              for j, cells in enumerate(_cells(line, separator)) if any(c.strip() for c in cells)]
    interval, segments = None, {}
    if path.suffix.lower() == ".lvm":
        interval = _lvm_interval(parsed)
        times, segments = _lvm_times(parsed)
        parsed = _without_later_lvm_headers(path, parsed)
        if times:  # the x column LabVIEW would have written (X_Columns One)
            heading = max(n for n, _ in parsed if n < min(times))
            parsed = [(n, [repr(times[n]), *cells] if n in times else
                       ["X_Value", *cells] if n == heading else cells)
                      for n, cells in parsed]
    interval = interval or _labchart_interval(parsed)
    parsed = _labchart_header(path, parsed)
    decimal = _decimal(path, separator, [_ungrouped(c.strip()) for _, cells in parsed[1:200]
                                         for c in cells])
    table = _with_header(path, None, [n for n, _ in parsed], [c for _, c in parsed], separator,
                         decimal)
    # its comment lines too, where a lab notes what the columns do not hold
    table = replace(table, preamble=[(n, line.strip()) for n, line in numbered
                                     if n < table.header_row])
    if path.suffix.lower() == ".lvm":
        table = replace(_without_empty_x_column(table), lvm_segments=segments)
    return replace(table, interval=interval) if interval else table


def _without_empty_x_column(table: RawTable) -> RawTable:
    """A LabVIEW measurement file written with an empty time column (LabVIEW's ``X_Value``
    heading over blank cells), that column left out: its rows are timed by the channel
    header's ``Delta_X``, not skipped each for a blank time."""
    if not table.header or table.header[0] not in ("X_Value", "Time [s]") or any(
            str(row[0]).strip() for row in table.rows if row):
        return table
    return replace(table, header=table.header[1:], rows=[row[1:] for row in table.rows])


def _comment(line: str) -> bool:
    """A '#' comment line; not one whose first cell is a spreadsheet's error value (a row of
    a sheet saved as CSV, said where it is read)."""
    text = line.lstrip()
    return text.startswith("#") and not _ERROR_FIRST.match(text)


def _with_commented_units(numbered: list[tuple[int, str]], lines: list[tuple[int, str]],
                          separator: str) -> list[tuple[int, str]]:
    """``lines`` with each comment line that is the units row under a row of names (``# s, bar,
    kN``, marked so that other readers skip it) put back without its ``#``: its cells, as many
    as the names (a first empty one, ``#,s,bar``, the mark's own), units
    (:func:`_units_row`). Any other comment stays one."""
    kept = dict(lines)
    out = list(lines)
    for (above, _), (number, line) in zip(numbered, numbered[1:], strict=False):
        if above not in kept or not _comment(line):
            continue
        names = _filled(_cells(kept[above], separator)[0])
        units = _filled(_cells(line.lstrip()[1:], separator)[0])
        if len(units) == len(names) + 1 and not units[0]:
            units = units[1:]
        if len(units) == len(names) and not any(_is_number(c) for c in names) \
                and _units_row(units):
            out.append((number, separator.join(units)))
    return sorted(out)


def _filled(cells: list[str]) -> list[str]:
    """``cells`` stripped, without the empty ones at the end (a separator ending the line)."""
    cells = [c.strip() for c in cells]
    while cells and not cells[-1]:
        cells.pop()
    return cells


#: the most lines a quoted cell spans (a comment of a few lines): a quote that does not close
#: within them is a stray one, and each line stays a row
QUOTED_LINES_MAX = 10
#: a quoted cell left open at the line's end: its quote opens the cell (5" in a comment is no
#: quoting)
_OPEN_QUOTE = re.compile(r'(?:^|[,;\t])\s*"[^"]*$')


#: the rows a LabChart text export's header block starts with, at most (``Interval=``,
#: ``ExcelDateTime=``, ``TimeFormat=``, ``DateFormat=``, ``ChannelTitle=``, ``Range=``,
#: ``UnitName=``, ``TopValue=``, ``BottomValue=``)
LABCHART_BLOCK_MAX = 20


def _labchart_block(parsed: list[tuple[int, list[str]]]) -> dict[str, int]:
    """A LabChart text export's header block, each label (lower case, ``channeltitle=``) ->
    its row's index in ``parsed``; empty for any other table."""
    block = {}
    for k, (_, cells) in enumerate(parsed[:LABCHART_BLOCK_MAX]):
        label = cells[0].strip() if cells else ""
        if not label.endswith("=") or len(label) < 2:
            break
        block[label.lower()] = k
    return block if "channeltitle=" in block and len(block) < len(parsed) else {}


#: a LabChart header block's ``Interval=`` cell: a number and its unit of time (``0.01 s``,
#: ``0,01 s`` where the PC writes decimal commas, ``1 ms``)
_INTERVAL = re.compile(r"(?P<number>\d+(?:[.,]\d*)?(?:[eE][+-]?\d+)?)\s*(?P<unit>\S*)")


def _labchart_interval(parsed: list[tuple[int, list[str]]]) -> tuple[str, float] | None:
    """The sampling interval a LabChart text export's header block states (``Interval=`` and
    ``0.01 s``), as written and in seconds; None where it has none or one that is no
    positive time."""
    block = _labchart_block(parsed)
    if "interval=" not in block:
        return None
    cells = parsed[block["interval="]][1]
    text = cells[1].strip() if len(cells) > 1 else ""
    match = _INTERVAL.fullmatch(text)
    unit = parse_unit(match["unit"] or "s") if match else None
    if unit is None or unit.dimensionality != registry().Unit("s").dimensionality:
        return None
    seconds = float(match["number"].replace(",", ".")) * (1 * unit).to("s").magnitude
    return (f"Interval= {text}", seconds) if math.isfinite(seconds) and seconds > 0 else None


@dataclass(frozen=True)
class _LvmSegment:
    """A LabVIEW measurement file's segment: its channel header's first ``X0`` and
    ``Delta_X`` (as written), its start as ``Date`` and ``Time`` give it (a datetime, or
    None), and its data rows' indices in the file's parsed rows."""
    x0: str
    delta_x: str
    moment: datetime.datetime | None
    rows: range


def _lvm_segments(parsed: list[tuple[int, list[str]]]) -> list[_LvmSegment] | None:
    """The segments of a LabVIEW measurement file whose channel headers each state a time
    axis (``X_Dimension`` Time, one ``Delta_X`` for every channel); None where any does not."""
    heads, block = [], None
    for k, (_, cells) in enumerate(parsed):
        label = cells[0].strip() if cells else ""
        values = [c.strip() for c in cells[1:] if c.strip()]
        if label == "Channels":
            block = {"at": k}
        elif block is not None and label == "***End_of_Header***":
            heads.append((block, k + 2))  # after its heading
            block = None
        elif block is not None and values:
            block[label] = values
    out = []
    for (block, first), (after, _) in zip(heads, [*heads[1:], ({"at": len(parsed)}, 0)],
                                          strict=True):
        deltas = set(block.get("Delta_X", []))
        if {d.lower() for d in block.get("X_Dimension", [])} != {"time"} or len(deltas) != 1 \
                or "X0" not in block:
            return None
        moment = _lvm_moment(block.get("Date", [""])[0], block.get("Time", [""])[0])
        out.append(_LvmSegment(block["X0"][0], deltas.pop(), moment, range(first, after["at"])))
    return out or None


def _lvm_moment(day: str, clock: str) -> datetime.datetime | None:
    """A LabVIEW measurement file's ``Date`` (``2026/12/05``) and ``Time`` (``09:15:00.1234567
    890123``, its seconds to any number of digits) as one datetime; None where either is none."""
    try:
        hours, minutes, seconds = clock.split(":")
        return datetime.datetime.strptime(day, "%Y/%m/%d") + datetime.timedelta(
            hours=int(hours), minutes=int(minutes), seconds=float(seconds))
    except ValueError:
        return None


def _lvm_interval(parsed: list[tuple[int, list[str]]]) -> tuple[str, float] | None:
    """The sampling interval a LabVIEW measurement file's channel headers state (``Delta_X``,
    one cell per channel, all alike, where ``X_Dimension`` is time), as written and in
    seconds, where its rows follow on from each other: one segment, or segments each starting
    one interval after the last row of the one before (:func:`_lvm_starts`). None where it has
    none, segments whose times the rows alone do not tell (:func:`_lvm_times` gives them) or
    one that is no positive time."""
    segments = _lvm_segments(parsed)
    if not segments or len({s.delta_x for s in segments}) != 1:
        return None
    seconds = plain_number(segments[0].delta_x, ".")
    if seconds is None or not (math.isfinite(seconds) and seconds > 0):
        return None
    starts = _lvm_starts(segments)
    if len(segments) > 1 and (starts is None or any(
            abs(later - start - seconds * len(a.rows)) > 0.5 * seconds
            for a, start, later in zip(segments, starts, starts[1:], strict=False))):
        return None
    return f"Delta_X {segments[0].delta_x}", seconds


def _lvm_starts(segments: list[_LvmSegment]) -> list[float] | None:
    """Each segment's first sample [s] from the first's: by its ``X0`` where they differ,
    else by its ``Date`` and ``Time`` (each segment's X0 alike from its own start); None where
    neither tells."""
    x0 = [plain_number(s.x0, ".") for s in segments]
    if None not in x0 and len(set(x0)) > 1:
        return [x - x0[0] for x in x0]
    if any(s.moment is None for s in segments):
        return None
    return [(s.moment - segments[0].moment).total_seconds() for s in segments]


def _lvm_times(parsed: list[tuple[int, list[str]]]) -> tuple[dict[int, float], dict]:
    """A LabVIEW measurement file written without its x values (no ``X_Value`` heading) in
    segments that do not follow on from each other (a pause between two writes): each data
    row's time [s], by file row, its segment's start (:func:`_lvm_starts`) and ``Delta_X``
    per row before it in the segment, and what timed them (:attr:`RawTable.lvm_segments`).
    Empty where its rows are evenly spaced (:func:`_lvm_interval`), it has an x column or
    its segments' starts are not told."""
    segments = _lvm_segments(parsed)
    if not segments or len(segments) < 2 or _lvm_interval(parsed) is not None or any(
            cells and cells[0].strip() == "X_Value" for _, cells in parsed):
        return {}, {}
    starts = _lvm_starts(segments)
    steps = [plain_number(s.delta_x, ".") for s in segments]
    if starts is None or any(s is None or not (math.isfinite(s) and s > 0) for s in steps):
        return {}, {}  # a record without time, as its rows are
    ends = [start + step * len(s.rows) for s, start, step in zip(segments, starts, steps,
                                                                  strict=True)]
    x0 = {s.x0 for s in segments}
    return {parsed[k][0]: start + step * j
            for segment, start, step in zip(segments, starts, steps, strict=True)
            for j, k in enumerate(segment.rows)}, {
        "count": len(segments), "starts_from": "X0" if len(x0) > 1 else "Date and Time",
        "delta_x": ", ".join(dict.fromkeys(s.delta_x for s in segments)),
        "unlogged_s": float(sum(b - a for a, b in zip(ends, starts[1:], strict=False)))}


def _labchart_header(path: Path,
                     parsed: list[tuple[int, list[str]]]) -> list[tuple[int, list[str]]]:
    """A LabChart (ADInstruments) text export's rows with its header block, each row a label
    ending in ``=`` and a cell per channel, made one header: each channel's ``ChannelTitle=``
    with its ``UnitName=`` (``Druck [bar]``), after ``Time [s]`` where the rows start with
    their time (seconds from the block's start; ``Time`` where it is a time of day), on the
    line of ``ChannelTitle=``. Its ``TopValue=`` and ``BottomValue=`` rows hold numbers, and
    were otherwise the first rows of data. Any other table as it is; ``ValueError`` naming
    the row where a second block's header begins (a record stopped and started again)."""
    block = _labchart_block(parsed)
    if not block:
        return parsed
    number, titles = parsed[block["channeltitle="]]
    names = _filled(titles[1:])
    units = _filled(parsed[block["unitname="]][1][1:]) if "unitname=" in block else []
    header = [f"{name} [{unit}]" if name and unit else name
              for name, unit in zip(names, units + [""] * len(names), strict=False)]
    first = _filled(parsed[len(block)][1])
    if len(first) > len(names):  # each row's time before its channels
        header.insert(0, "Time [s]" if _is_number(first[0]) else "Time")
    label = parsed[0][1][0].strip()
    again = next((n for n, cells in parsed[len(block):] if cells and cells[0].strip() == label),
                 None)
    if again is not None:
        raise ValueError(f"{path.name}, row {again} ({label!r}): a second block of the LabChart "
                         "export begins (the record stopped and started again): expected one "
                         "block per file; export each block as a file of its own and import "
                         "each")
    return [(number, header), *parsed[len(block):]]


def _with_quoted_line_breaks(lines: list[tuple[int, str]]) -> list[tuple[int, str]]:
    """``lines`` (file row, text) with a line whose quotes do not pair up joined to the next
    ones until they do: a quoted cell holding a line break (a comment written with Alt+Enter,
    which Excel writes over two lines), numbered by its first line."""
    out, k = [], 0
    while k < len(lines):
        number, line = lines[k]
        end = k
        if line.count('"') % 2 and _OPEN_QUOTE.search(line):
            end = next((j for j in range(k + 1, min(k + QUOTED_LINES_MAX, len(lines)))
                        if sum(text.count('"') for _, text in lines[k:j + 1]) % 2 == 0), k)
        out.append((number, "\n".join(text for _, text in lines[k:end + 1])))
        k = end + 1
    return out


def _cells(line: str, separator: str) -> list[list[str]]:
    """A line's cells (one row), or the rows of its lines, one after the other, where it
    joined lines whose quote, with this separator, opens no cell."""
    try:
        (cells,) = csv.reader(io.StringIO(line, newline=""), delimiter=separator)
        return [cells]
    except (csv.Error, ValueError):  # a line break outside quotes, or two records
        return [next(csv.reader([part], delimiter=separator), [])
                for part in line.split("\n")]


def _without_later_lvm_headers(path: Path, parsed: list[tuple[int, list[str]]]):
    """LabVIEW's measurement file written with one header per segment, each segment's rows
    under its own channel header (``Channels`` ... ``***End_of_Header***``, then the heading):
    the headers after the first segment's rows left out, so the segments are one table;
    ``ValueError`` where a segment's channel units differ from the first's."""
    def label(cells):
        return cells[0].strip() if cells else ""

    def units(cells):
        return [c.strip() for c in cells[1:] if c.strip()]

    heading = next((k for k, (_, cells) in enumerate(parsed)
                    if label(cells) == "X_Value" or (k and label(parsed[k - 1][1])
                                                     == "***End_of_Header***"
                                                     and label(cells) != "Channels")), None)
    first_units = next((units(cells) for _, cells in parsed[:heading or 0]
                        if label(cells) == "Y_Unit_Label"), None)
    if heading is None:
        return parsed
    out, inside = parsed[:heading + 1], False
    for n, cells in parsed[heading + 1:]:
        if label(cells) == "Channels":
            inside = True
        if not inside:
            out.append((n, cells))
            continue
        if label(cells) == "Y_Unit_Label" and units(cells) != first_units:
            raise ValueError(f"{path.name}, row {n}: a segment's channel units "
                             f"({', '.join(map(repr, units(cells)))}) differ from the first "
                             f"segment's ({', '.join(map(repr, first_units or []))}): expected "
                             "one unit per channel; save the segments as files of their own")
        # the block ends at the segment's heading, the first segment's own
        inside = [c.strip() for c in cells] != [c.strip() for c in parsed[heading][1]]
    return out


def _decimal(path: Path, separator: str, cells: list[str]) -> str:
    """The decimal mark of a text table's number cells. In a ``,``-separated file a number
    holding a comma was quoted (``"1,5"``): a decimal comma, unless other cells have decimal
    points (then the commas group thousands) or every such cell could be either
    (``"1,500"``: refused, naming it)."""
    cells = [_number_part(c) for c in cells]
    commas = [c for c in cells if _COMMA_DECIMAL.match(c) or _GROUPED[","].match(c)]
    if separator != ",":
        return "," if commas else "."
    if not commas or any(_POINT_DECIMAL.match(c) for c in cells):
        return "."
    if all(_THOUSANDS.match(c) for c in commas):
        raise ValueError(f"{path.name}: numbers such as {commas[0]!r} in a comma-separated file "
                         "could be decimal commas or thousands: expected the file saved with "
                         "';' as separator, or its numbers without thousands separators")
    return ","


def _number_part(text: str) -> str:
    """A cell's number where a unit follows it (``'1,25 bar'`` -> ``'1,25'``), so that its
    decimal mark is seen as a bare number's; any other cell as it is."""
    match = _NUMBER_AND_UNIT[0].match(text)
    if match and match["unit"] and parse_unit(match["unit"]) is not None:
        return match["number"]
    return text


def _separator(lines: list[str]) -> str:
    """The separator that splits the most lines into the same number (>= 2) of fields; where
    two do so alike (a row with a comment in a column without a header, a row missing its last
    cell), the one that splits more lines at all, then a semicolon before a tab before a comma
    (a semicolon table's decimal commas split its numbers into as many fields by chance)."""
    best, score = ",", (-1, -1, -1)
    for rank, sep in enumerate(_SEPARATOR_PREFERENCE):
        # a quoted cell's line break is no row's end: a space serves as well for counting
        counts = [len(next(csv.reader([line.replace("\n", " ")], delimiter=sep)))
                  for line in lines[:200]]
        common = max(set(counts), key=counts.count)
        agree = counts.count(common) if common >= 2 else 0
        this = (agree, sum(c >= 2 for c in counts), -rank)
        if this > score:
            best, score = sep, this
    return best


#: the separators in the order a tie between them is decided (:func:`_separator`)
_SEPARATOR_PREFERENCE = (";", "\t", ",")


def sheet_names(path: str | Path) -> list[str]:
    """The sheets of the workbook ``path`` (empty for a text table)."""
    import openpyxl

    path = Path(path)
    if path.suffix.lower() not in WORKBOOK_SUFFIXES:
        return []
    try:
        book = openpyxl.load_workbook(path, read_only=True)
    except Exception:  # read_tables says what is wrong with it
        return []
    try:
        return list(book.sheetnames)
    finally:
        book.close()


def key_values(path: str | Path, sheet: str) -> dict[str, object]:
    """A sheet of two columns (key, value) as a dict, the header row left out."""
    import openpyxl

    book = openpyxl.load_workbook(path, read_only=True, data_only=True)
    try:
        rows = list(book[sheet].iter_rows(values_only=True))
    finally:
        book.close()
    return {str(r[0]): r[1] for r in rows[1:] if len(r) > 1 and r[0] is not None}


def _read_workbook(path: Path, sheet: str | None) -> list[RawTable]:
    import openpyxl

    try:
        book = openpyxl.load_workbook(path, read_only=True, data_only=True)
    except Exception as exc:  # openpyxl raises many kinds for a file that is not a workbook
        raise ValueError(f"{path} cannot be read as a workbook ({type(exc).__name__}: "
                         f"{str(exc)[:120]})") from None
    try:
        names = book.sheetnames
        if sheet is not None and sheet not in names:
            raise ValueError(f"--sheet {sheet!r}: {path.name} has no such sheet: it has "
                             f"{', '.join(map(repr, names))}")
        # a chart sheet (a lab's plot of its measurements) holds no cells
        charts = {chart.title for chart in book.chartsheets}
        if sheet in charts:
            raise ValueError(f"--sheet {sheet!r}: {path.name}'s sheet {sheet!r} is a chart, no "
                             "table: expected the sheet of its measurements (sheets "
                             f"{', '.join(repr(n) for n in names if n not in charts)})")
        tables, problems = [], []
        for name in [sheet] if sheet is not None else [n for n in names if n not in charts]:
            numbers, rows, percent = [], [], []
            for n, row in enumerate(book[name].iter_rows(), start=1):
                cells = []
                for cell in row:
                    value = getattr(cell, "value", None)
                    if type(value) in (int, float) and "%" in (
                            getattr(cell, "number_format", None) or ""):
                        percent.append((len(rows), len(cells)))
                    cells.append("" if value is None else value)
                if any(str(c).strip() for c in cells):
                    numbers.append(n)
                    rows.append(cells)
                if len(rows) > MAX_ROWS:
                    raise ValueError(f"{path}, sheet {name!r} has more than {MAX_ROWS} rows")
            # numbers a German Excel stored as text ("1,5", "1,25 bar") have a decimal comma
            decimal = "," if any(
                isinstance(c, str) and _COMMA_DECIMAL.match(_number_part(_ungrouped(c.strip())))
                for cells in rows[:50] for c in cells) else "."
            try:
                tables.append(_in_percent_as_shown(
                    _with_header(path, name, numbers, rows, None, decimal),
                    {(numbers[k], j) for k, j in percent}))
            except ValueError as exc:  # a sheet of notes: skipped unless it was asked for
                if sheet is not None:
                    raise
                problems.append(str(exc))
    finally:
        book.close()
    if not tables:
        raise ValueError(problems[0] if len(problems) == 1 else
                         f"{path.name}: no sheet holds a table ({'; '.join(problems)[:300]})")
    return tables


def _read_tdms(path: Path, group: str | None) -> list[RawTable]:
    """Each group of the TDMS file ``path`` that holds samples (or the group named ``group``)
    as a table of its channels (:func:`_tdms_table`)."""
    from nptdms import TdmsFile

    kept = _Kept()
    loggers = [logging.getLogger(name) for name in list(logging.root.manager.loggerDict)
               if name.split(".")[0] == "nptdms"]
    for logger in loggers:
        logger.addFilter(kept)
    try:
        # read through the file opened here: npTDMS then reads no index file lying beside it
        with open(path, "rb") as f, TdmsFile.open(f) as tdms:
            names = [g.name for g in tdms.groups()]
            file_properties = _tdms_properties(tdms.properties)
            groups = [(g.name, _tdms_properties(g.properties),
                       [(c.name, dict(c.properties), len(c),
                         c[:] if len(c) <= MAX_ROWS else None) for c in g.channels()])
                      for g in tdms.groups() if group in (None, g.name)]
    except Exception as exc:  # npTDMS raises many kinds for a file that is no TDMS file
        raise ValueError(f"{path} cannot be read as a TDMS file ({type(exc).__name__}: "
                         f"{str(exc)[:120]}): expected a .tdms file as LabVIEW, SignalExpress "
                         "or FlexLogger writes it") from None
    finally:
        for logger in loggers:
            logger.removeFilter(kept)
    if group is not None and group not in names:
        raise ValueError(f"--group {group!r}: {path.name} has no such group: it has "
                         f"{', '.join(map(repr, names)) or 'none'}")
    tables = [_tdms_table(path, name, {"file": file_properties, "group": properties}, channels)
              for name, properties, channels in groups
              if group is not None or any(n for *_, n, _ in channels)]
    if not tables:
        raise ValueError(f"{path.name} holds no samples" + "".join(
            f" (the file is damaged or cut short: npTDMS: {warned})" for warned in kept.lines[:1])
            + ": expected a group of channels (time, pressure, force) with their values")
    for table in tables:
        table.read_warnings = list(dict.fromkeys(kept.lines))[:TDMS_WARNINGS_KEPT]
    return tables


class _Kept(logging.Filter):
    """npTDMS's warnings on a damaged file (its last segment cut short, a chunk read in
    part), kept for the table's record instead of printed."""

    def __init__(self):
        super().__init__()
        self.lines: list[str] = []

    def filter(self, record: logging.LogRecord) -> bool:
        self.lines.append(record.getMessage()[:TDMS_PROPERTY_CHARS])
        return False


def _tdms_table(path: Path, group: str, properties: dict, channels: list) -> RawTable:
    """A TDMS group as a table: a column per channel (``name, properties, length, values``),
    its unit from the first of :data:`TDMS_UNIT_PROPERTIES` that reads as one, after a
    ``Time [s]`` column where the channels are waveforms (:data:`TDMS_WAVEFORM`) and none is
    named a time; a channel
    shorter than the others ends in blank cells. Row 1 is the header, sample ``k`` row
    ``k + 2``, as the group reads once exported to a sheet."""
    where = f"{path.name}, group {group!r}"
    rows = max((n for *_, n, _ in channels), default=0)
    if rows > MAX_ROWS:
        raise ValueError(f"{where} has a channel of {rows} samples: expected at most {MAX_ROWS}")
    if not rows:
        raise ValueError(f"{where} holds no samples: expected channels (time, pressure, force) "
                         "with their values")
    header, columns = [], []
    for name, props, _, values in channels:
        units = [str(props[key]).strip() for key in TDMS_UNIT_PROPERTIES
                 if str(props.get(key, "")).strip()]
        unit = next((u for u in units if parse_unit(u) is not None), units[0] if units else "")
        header.append(f"{name} [{unit}]" if unit and parse_header(name)[1] is None else name)
        columns.append(_tdms_cells(values))
    timings = {name: (tuple(_plain_float(props.get(key, 0.0)) for key in TDMS_WAVEFORM), props)
               for name, props, *_ in channels if TDMS_WAVEFORM[0] in props}
    table_properties = dict(properties)
    if timings:
        first, ((increment_s, start_s), props) = next(iter(timings.items()))
        if other := next((n for n, (t, _) in timings.items() if t != (increment_s, start_s)),
                         None):
            step_s, from_s = timings[other][0]
            raise ValueError(f"{where}: channel {other!r} is sampled every {step_s:g} s from "
                             f"{from_s:g} s, channel {first!r} every {increment_s:g} s from "
                             f"{start_s:g} s (wf_increment, wf_start_offset): expected one time "
                             "per row; log them at one rate, or export each to a table of its "
                             "own and join them with --join-by-time")
        if not (math.isfinite(increment_s) and increment_s > 0 and math.isfinite(start_s)):
            raise ValueError(f"{where}: channel {first!r}'s wf_increment {increment_s:g} s from "
                             f"wf_start_offset {start_s:g} s: expected a positive sampling "
                             "interval in seconds")
        # a channel of the times (LabVIEW's Write To TDMS of a waveform's t beside its Y) is
        # the clock itself
        if not any(ROLES["time"].matches(parse_header(h)[0]) for h in header):
            header.insert(0, "Time [s]")
            columns.insert(0, (start_s + increment_s * np.arange(rows)).tolist())
            table_properties["waveform"] = _tdms_properties(
                {key: value for key, value in props.items() if key.startswith("wf_")})
    cells = [list(row) for row in itertools.zip_longest(*columns, fillvalue="")]
    return RawTable(path, group, header, 1, cells, list(range(2, rows + 2)),
                    properties=table_properties,
                    preamble=_tdms_statements(properties, channels))


def _plain_float(value) -> float:
    """``value`` as a float, NaN where it is none (a property written as text)."""
    try:
        return float(value)
    except (TypeError, ValueError):
        return math.nan


def _tdms_cells(values: np.ndarray) -> list:
    """A TDMS channel's values as cells: numbers, a date-time as ISO text, a missing reading
    (NaN, NaT) blank as an empty cell is, any other value as text."""
    kind = values.dtype.kind
    if kind == "f":
        return ["" if math.isnan(v) else v for v in values.tolist()]
    if kind in "iub":
        return values.astype(np.int64 if kind == "b" else values.dtype).tolist()
    if kind == "M":
        return ["" if text == "NaT" else text
                for text in np.datetime_as_string(values, unit="us").tolist()]
    return ["" if v is None else str(v) for v in values.tolist()]


def _tdms_properties(properties) -> dict:
    """A TDMS object's properties as run.json keeps them: numbers and flags as they are, a
    time as ISO text, anything else as text of at most :data:`TDMS_PROPERTY_CHARS`."""
    out = {}
    for key, value in properties.items():
        if isinstance(value, np.datetime64):
            value = np.datetime_as_string(value, unit="us")
        elif isinstance(value, np.generic):
            value = value.item()
        if not isinstance(value, (bool, int, float)) or (
                isinstance(value, float) and not math.isfinite(value)):
            value = str(value)[:TDMS_PROPERTY_CHARS]
        out[str(key)[:TDMS_PROPERTY_CHARS]] = value
    return out


def _in_percent_as_shown(table: RawTable, cells: set[tuple[int, int]]) -> RawTable:
    """``table`` with the numbers of the cells formatted as a percentage (file row, column)
    that lie under a header in % as the cells show them: Excel stores 12.2 % as 0.122, which
    under ``Kontraktion [%]`` would read 0.122 %. Under any other header the number stored is
    the value (a fraction under one without a unit or in ``[-]``)."""
    if not cells:
        return table
    in_percent = {j for j, header in enumerate(table.header)
                  if (unit := parse_header(header)[1]) is not None
                  and str(parse_unit(unit)) == "percent"}
    at = {n: i for i, n in enumerate(table.row_numbers)}
    for n, j in cells:
        if j in in_percent and n in at:
            table.rows[at[n]][j] *= 100
    return table


def numbers_as_read(table: RawTable) -> list[list]:
    """``table``'s rows, each cell that is a plain number (``'1,5'`` in a table of decimal
    commas) as that number and the others as written: a sheet that reads as the table did."""
    out = []
    for row in table.rows:
        cells = []
        for cell in row:
            value, unit = _number(cell, table.decimal) if isinstance(cell, str) else (None, None)
            cells.append(value if value is not None and unit is None else cell)
        out.append(cells)
    return out


def _is_number(cell) -> bool:
    """A number, possibly with a decimal comma or a unit after it."""
    return _number(cell, ",")[0] is not None


def _units_row(cells: list[str]) -> bool:
    """Whether a header row holds units only (``s``, ``[kPa]``, ``(N)``, ``%``, ``-``, and a
    logged temperature's ``°C`` or a displacement's ``in``), of the roles' quantities in all
    its cells or in two of them at least; names such as ``P`` or ``F`` are not (pint: poise,
    farad)."""
    # an empty pair of brackets, '[]', is a column without a unit (a row counter's)
    units = [_row_unit(c.strip("[]() ")) for c in cells if c.strip("[]() ")]
    roles = sum(any(_fits(u, role) for role in ROLES.values()) for u in units)
    return bool(units) and all(u is not None for u in units) and roles >= min(2, len(units))


def _row_unit(text: str):
    """A cell of a units row as a unit: as :func:`parse_unit` reads it, or a word a header's
    name holds as English that a row of units means as a unit (``in``: the inch)."""
    found = parse_unit(text)
    if found is None and text.lower() in NOT_UNITS:
        try:
            found = registry().Unit(text.lower())
        except Exception:  # pint's parser raises many kinds ('of', 'to')
            return None
    return found


def _refuse_a_labelled_row(where, numbers, rows, first_data) -> None:
    """``ValueError`` when the row taken for the header holds a number under a row of names
    alone ("Pressure (bar);Force (N)" over "tare;1,5"): a row of the lab's own between the
    header and the numbers, which would be read as the header, the real one as a title."""
    def shown(cells) -> str:
        return ", ".join(repr(str(c).strip()) for c in cells if str(c).strip())

    names = next((k for k in range(first_data - 1, -1, -1)
                  if not any(_is_number(c) for c in rows[k])), None)
    if names is None:
        return
    k = names + 1
    raise ValueError(f"{where}, row {numbers[k]} ({shown(rows[k])}) lies between the header "
                     f"(row {numbers[names]}: {shown(rows[names])}) and the rows of numbers: "
                     "expected every row under the header to hold a number per column; delete "
                     "that row (a force read at 0 bar is a row '0;FORCE', or --tare FORCE)")


def _preamble_row(rows: list[list], k: int) -> bool:
    """Whether row ``k``, holding two numbers, is a line of a logger's header block, not data:
    text labels it (LabVIEW's ``Samples 2610 2610``, ``Messbereich [bar];0;10``), a row without
    any number (the block's end, the column names) comes within the next two rows, and rows of
    numbers follow further on."""
    first = next((c for c in rows[k] if str(c).strip()), "")
    if _is_number(first):
        return False
    ends = [j for j in range(k + 1, min(k + 3, len(rows)))
            if not any(_is_number(c) for c in rows[j])]
    return bool(ends) and any(sum(_is_number(c) for c in cells) >= 2
                              for cells in rows[ends[0] + 1:])


def _with_header(path, sheet, numbers, rows, separator, decimal) -> RawTable:
    """The header is the row above the first row with two numbers (a date-time or a clock
    reading counts as one: a logger's record of one channel and its time) that is not a line
    of a header block (:func:`_preamble_row`); rows above it are titles."""
    first_data = next((k for k, cells in enumerate(rows)
                       if sum(_is_number(c) or _clock(c) is not None for c in cells) >= 2
                       and not _preamble_row(rows, k)), None)
    where = f"{path.name}, sheet {sheet!r}" if sheet else path.name
    if first_data is None:
        raise ValueError(f"{where} has no row of numbers: expected a header row and one row "
                         "per step or sample")
    if first_data == 0:
        raise ValueError(f"{where} has no header row: expected column names above the numbers "
                         "(pressure, force, ...)")
    header_index = first_data - 1
    if any(_is_number(c) for c in rows[header_index]):
        _refuse_a_labelled_row(where, numbers, rows, first_data)
    width = max(len(r) for r in rows[first_data:])
    header = [str(c).strip() for c in rows[header_index]] + [""] * width
    if header_index > 0 and _units_row(header):
        # a logger's two header rows, names over units ("Druck" over "kPa"): one header
        names = [str(c).strip() for c in rows[header_index - 1]] + [""] * width
        header = [_named_with_unit(where, numbers[header_index], n, u)
                  for n, u in zip(names, header, strict=False)]
        header_index -= 1
    header = _labview_header(header, rows[:header_index])
    header = _block_units(where, header, rows[:header_index], numbers)
    end = _footer_start(numbers, rows, first_data)
    data = [list(r) + [""] * (width - len(r)) for r in rows[first_data:end]]
    if len(data) > MAX_ROWS:
        raise ValueError(f"{where} has {len(data)} rows: expected at most {MAX_ROWS}")
    return RawTable(path, sheet, header[:width], numbers[header_index], data,
                    numbers[first_data:end], header_index, separator, decimal,
                    footer_skipped=[f"A{numbers[k]} ({str(rows[k][0]).strip()[:40]!r})"
                                    for k in range(end, len(rows))],
                    preamble=[(numbers[k], " ".join(str(c).strip() for c in rows[k]
                                                    if str(c).strip()))
                              for k in range(header_index)])


def _named_with_unit(where: str, row: int, name: str, unit: str) -> str:
    """A column's name over its cell of a units row as one header: ``Druck`` over ``kPa`` is
    ``Druck [kPa]``; a name that holds the same unit keeps it (German Excel's ``Druck [bar]``
    over ``bar``). ``ValueError`` where the two units differ: which one the column holds
    cannot be told, and a factor of 10 or 1000 would go unseen."""
    written = unit.strip("[]() ")
    if not (name and written):
        return name or unit
    in_name = parse_header(name)[1]
    named, given = (parse_unit(in_name) if in_name else None), parse_unit(written)
    if named is None or given is None:
        return f"{name} [{written}]"
    if str(named) != str(given):
        raise ValueError(f"{where}, row {row}: column {name!r} names its unit, and the row of "
                         f"units under the names gives it {written!r}: expected one unit per "
                         "column; correct the name or the units row")
    return name


def _footer_start(numbers: list[int], rows: list[list], first_data: int) -> int:
    """Where the notes under a table begin (``len(rows)``: none): the rows after the last blank
    row that each hold fewer than two numbers, labelled by text (``Anzahl Werte;2610``,
    ``Messung beendet;14:05:00``), as a logger writes a closing block, or that follow a title
    row of text alone, each labelled by text (a sheet's results); a row of numbers, or none
    blank above them, keeps them in the table, where a bad cell is named."""
    def labelled(row) -> bool:
        return not _is_number(next((c for c in row if str(c).strip()), ""))

    end = len(rows)
    while end > first_data + 1 and sum(_is_number(c) for c in rows[end - 1]) < 2 \
            and labelled(rows[end - 1]):
        end -= 1
    # the block stands apart: a blank row (left out on reading) lies just above it
    if end < len(rows) and numbers[end] - numbers[end - 1] > 1:
        return end
    # or a block of results under its own title ('Auswertung', then 'Peak;2;549,4'): after the
    # last blank row, a row of text alone, then rows each labelled by text, whatever numbers
    # they hold (a table's own rows under a blank row hold numbers from their first row on)
    title = next((k for k in range(len(rows) - 1, first_data, -1)
                  if numbers[k] - numbers[k - 1] > 1), None)
    if title is not None and not any(_is_number(c) for c in rows[title]) \
            and all(labelled(row) for row in rows[title:]):
        return title
    return len(rows)


def _labview_header(header: list[str], titles: list[list]) -> list[str]:
    """A LabVIEW measurement file's column names with what its channel header says: each
    channel's unit (``Y_Unit_Label``, in the channels' order: an x column before each, as
    ``X_Columns Multi`` writes them, takes none; a file written with ``X_Columns No`` has
    none) after its name, and its first x column (``X_Value``) named ``Time [s]`` where the
    channels' ``X_Dimension`` is time; any other header as it is."""
    block = {str(row[0]).strip(): [str(c).strip() for c in row[1:]] for row in titles if row}
    if "Y_Unit_Label" not in block or not header:
        return header
    out = list(header)
    if out[0] == "X_Value" and {d.lower() for d in block.get("X_Dimension", []) if d} == {
            "time"}:
        out[0] = "Time [s]"
    channels = [k for k in range(len(out)) if header[k] != "X_Value"]
    for k, unit in zip(channels, block["Y_Unit_Label"], strict=False):
        if out[k] and unit and parse_header(out[k])[1] is None:
            out[k] = f"{out[k]} [{unit}]"
    return out


#: the first cell of a header block's row of units, one per column (a TDMS file exported with
#: its channel properties, ``unit_string``; a logger's ``Unit`` or ``Einheit``)
UNIT_ROW_LABELS = ("unit", "units", "unit string", "unit_string", "einheit", "einheiten",
                   "unité", "unités")


def _block_units(where: str, header: list[str], titles: list[list],
                 numbers: list[int]) -> list[str]:
    """The column names with the units a header block's row of units gives them (a row
    labelled as :data:`UNIT_ROW_LABELS` whose other cells are units), in the columns' order;
    a name that holds its unit keeps it. ``ValueError`` where the units are not one per
    column: which is whose cannot be told, and a unit left out would be read as bar or N."""
    for k, row in enumerate(titles):
        cells = [str(c).strip() for c in row]
        units = cells[1:]
        while units and not units[-1]:
            units.pop()
        if (not cells or cells[0].lower().rstrip(":") not in UNIT_ROW_LABELS or not units
                or not all(parse_unit(u) is not None for u in units if u)):
            continue
        named = [j for j, name in enumerate(header) if name]
        if len(units) != len(named):
            shown = ", ".join(repr(c) for c in cells if c)
            raise ValueError(f"{where}, row {numbers[k]} ({shown}) gives {len(units)} units for "
                             f"the {len(named)} columns "
                             f"{', '.join(repr(header[j]) for j in named)}: expected one per "
                             "column, in their order; or put each unit in its column's name "
                             "('Pressure [bar]')")
        out = list(header)
        for j, unit in zip(named, units, strict=True):
            if unit and parse_header(out[j])[1] is None:
                out[j] = f"{out[j]} [{unit}]"
        return out
    return header


# --- recognising ------------------------------------------------------------------------------

# the unit may hold one parenthesis of its own: "Pressure [bar(g)]"
_BRACKETED = re.compile(r"^(?P<name>.*?)\s*[(\[{](?P<unit>[^)\]}(]*(?:\([^)]*\))?[^)\]}]*)"
                        r"[)\]}]\s*$")
#: "Force, N": a unit after a comma; "Date&Time", as a logger may name its clock
_WORDS = re.compile(r"[\s_\-./:,&]+")
#: a header's name ending in a pressure unit, and the mark that may follow it in brackets
_MARKED_UNIT = re.compile(r"^(?P<name>.*?\S)[\s_,]+(?P<unit>m?bar|[km]?pa|psi)\s*$",
                          re.IGNORECASE)
_PRESSURE_MARK = re.compile(r"g|gauge|ü|rel\.?|relativ|relative|relatif|a|abs|absolute",
                            re.IGNORECASE)


@cache
def registry(case_sensitive: bool = True):
    """A pint unit registry (made once each: parsing its definitions takes a fraction of a
    second); the case-insensitive one reads ``KGF`` or ``n`` where a header shouts or
    whispers."""
    import pint

    return pint.UnitRegistry(case_sensitive=case_sensitive)


#: words of a header that pint would read as a unit but a header means as English
NOT_UNITS = {"in", "at", "of", "per", "to", "a"}


#: unit spellings of lab headers that pint reads otherwise (any case, spaces as one) -> what a
#: lab means: ``[-]`` dimensionless, ``MPA``/``mpa`` not millipascal, ``KN`` not knot, ``kp``
#: the kilopond not the kilopoise, ``MBAR`` not megabar, ``MM``/``S``/``MS`` not megamolar or
#: siemens, ``at`` the technical atmosphere (a word where a header's name holds it, see
#: :data:`NOT_UNITS`), ``in Hg`` an inch of mercury (not an inch times mercury's density), the
#: gauge suffixes (the toolkit's pressures are gauge pressures), the seconds written
#: ``sec.``, German ``sek``, ``Sek.`` and ``msek`` (pint reads none), ``MSEC``, ``MV``, ``MA``
#: and ``MMHG`` a millisecond, millivolt, milliampere and millimetre of mercury (pint: mega),
#: ``H`` an hour (pint: the henry, which no bench logs),
#: and ``LBS`` and ``KG`` (pint reads ``lbs`` and ``kg`` alone): a load cell's pounds or
#: kilograms, refused as a mass naming ``--units force=lbf`` or ``kgf``
LAB_UNITS = {"-": "dimensionless", "bar": "bar", "mbar": "mbar", "barg": "bar", "pa": "Pa",
             "kpa": "kPa", "mpa": "MPa", "psi": "psi", "psig": "psi", "at": "technical_atmosphere",
             "in hg": "inch_Hg", "in. hg": "inch_Hg", "inch hg": "inch_Hg", "mm hg": "mmHg",
             "n": "N", "kn": "kN", "dan": "daN", "kp": "kgf", "kilopond": "kgf", "kgf": "kgf",
             "lbf": "lbf", "mm": "mm", "cm": "cm", "s": "s", "ms": "ms", "min": "min",
             "sek": "s", "sek.": "s", "sec.": "s", "sekunden": "s", "msek": "ms", "lbs": "lb",
             "msec": "ms", "usec": "us", "µsec": "us", "mv": "mV", "ma": "mA", "mmhg": "mmHg",
             "kg": "kg", "h": "hour"}


#: a pressure unit marked gauge as labs write it: bar g, bar(g), kPa (g), psi gauge, bar(ü),
#: atü (German technical atmospheres above the atmosphere), bar rel, bar relativ, bar relatif
#: (German and French: relative to the atmosphere)
_GAUGE = re.compile(r"(?P<unit>m?bar|[km]?pa|psi|at)\s*"
                    r"(?:\(\s*(?:g|gauge|ü|rel\.?|relativ|relative|relatif)\s*\)"
                    r"|(?:g|gauge|ü|rel\.?|relativ|relative|relatif))", re.IGNORECASE)
#: the same marked absolute (bar a, bar(a), psia, bar abs, ata): refused, with why
_ABSOLUTE = re.compile(r"(?:m?bar|[km]?pa|psi|at)\s*"
                       r"(?:\(\s*(?:a|abs|absolute)\s*\)|(?:a|abs|absolute))", re.IGNORECASE)


def marked_gauge(unit: str | None) -> bool:
    """Whether a pressure unit as written is marked gauge (``barg``, ``bar(g)``, ``psi gauge``):
    the lab says its sensor reads gauge pressure."""
    return bool(_GAUGE.fullmatch((unit or "").strip()))


#: a length squared or cubed written with its exponent as a digit (cm2, mm2, in2)
_AREA_DIGIT = re.compile(r"(?<![A-Za-z])(mm|cm|m|in|ft)([23])(?![\w])")


#: the kilopond within a unit (kp/cm²), as LAB_UNITS reads it alone
_KILOPOND = re.compile(r"(?<![A-Za-z])kp(?![A-Za-z])", re.IGNORECASE)


def parse_unit(text: str):
    """``text`` as a pint unit, or ``None`` if it is not one (:data:`LAB_UNITS` first, then
    case as written, then any case)."""
    text = text.strip()
    if gauge := _GAUGE.fullmatch(text):  # the toolkit's pressures are gauge pressures
        text = gauge.group("unit")
    if (spelled := " ".join(text.lower().split())) in LAB_UNITS:
        return registry().Unit(LAB_UNITS[spelled])
    if not text or text.lower() in NOT_UNITS or not re.search(r"[A-Za-z%°µ]", text):
        return None
    text = _AREA_DIGIT.sub(r"\1**\2", text)  # kgf/cm2: pint reads no 'cm2'
    text = _KILOPOND.sub("kgf", text)  # kp/cm²: pint's kp would be a kilopoise
    for case_sensitive in (True, False):
        try:
            return registry(case_sensitive).Unit(text)
        except Exception:  # pint's parser raises many kinds: "(%" TokenError, "N/0" division
            continue
    return None


def _fits(unit, role: Role) -> bool:
    return (unit is not None and role.unit is not None
            and unit.dimensionality == registry().Unit(role.unit or "dimensionless").dimensionality)


def unread_time_columns(table: RawTable, found: dict[str, Column]) -> list[str]:
    """The headers of ``table`` that no role took and whose unit is one of time (``Zeit seit
    Beginn [s]``) or whose first cell is a clock reading or a date-time (``Messung am``): a
    record's clock by a name the reader does not know, or a hold's duration; or that are a
    channel's own time (:func:`_channel_times`)."""
    taken = taken_columns(found)
    channels = set(_channel_times(table, taken))
    return [header for index, header in enumerate(table.header) if header and index not in taken
            and (index in channels or _first_a_time(table, index)
                 or (unit := parse_header(header)[1]) is not None
                 and (clock_format(unit) or _fits(parse_unit(unit), ROLES["time"])))]


def _first_a_time(table: RawTable, index: int) -> bool:
    """Whether the first filled cell of a column is a clock reading or a date-time."""
    first = next((row[index] for row in table.rows if str(row[index]).strip()), None)
    return first is not None and not isinstance(first, int | float) and _clock(first) is not None


#: the first word of a channel's own time column's name (``Time - Pressure``, as
#: SignalExpress exports each channel beside its time)
CHANNEL_TIME_WORDS = ("time", "zeit", "temps")


def _channel_times(table: RawTable, taken: set[int]) -> list[int]:
    """The columns no role took named as a channel's own time (:data:`CHANNEL_TIME_WORDS`, then
    the channel's name)."""
    out = []
    for index, header in enumerate(table.header):
        words = parse_header(header)[0].split() if header else []
        if index not in taken and len(words) > 1 and words[0] in CHANNEL_TIME_WORDS:
            out.append(index)
    return out


#: a TDMS channel's path, as npTDMS names a data frame's columns: ``/'Group'/'Channel'``
_TDMS_PATH = re.compile(r"/'[^']*'/'(?P<channel>[^']+)'")


def parse_header(text: str) -> tuple[str, str | None]:
    """A column header as its name (lower case, words joined by one space, statistics words
    such as ``mean`` dropped) and its unit as written (``None`` when it names none).

    ``Pressure (bar)`` -> ``("pressure", "bar")``; ``p_psi`` -> ``("p", "psi")``;
    ``force_N_mean`` -> ``("force", "N")``; ``eps`` -> ``("eps", None)``;
    ``/'Untitled'/'Pressure [kPa]'`` (a TDMS channel's path) -> ``("pressure", "kPa")``.
    """
    text = str(text).strip()
    if channel := _TDMS_PATH.fullmatch(text):  # npTDMS's "/'Group'/'Channel'": the channel
        text = channel.group("channel").strip()
    match = _BRACKETED.match(text)
    if match and match.group("name").strip():
        name, unit = match.group("name"), match.group("unit").strip()
        if not unit and (call := name.strip().lower()) in CLOCK_NAMES:  # an Arduino's millis()
            return call, CLOCK_NAMES[call]
        # a pressure unit written after the name with its gauge or absolute mark in brackets
        # ("P bar(g)", "Druck bar(ü)", "p kPa (a)"): the unit is the two together
        marked = _MARKED_UNIT.match(name)
        if marked and _PRESSURE_MARK.fullmatch(unit):
            return (_name(_WORDS.split(marked.group("name"))),
                    f"{marked.group('unit')}({unit})")
        return _name(_WORDS.split(name)), _without_origin(unit) or None
    words = [w for w in _WORDS.split(text) if w]
    if len(words) == 1 and words[0].lower() in CLOCK_NAMES:
        return words[0].lower(), CLOCK_NAMES[words[0].lower()]
    for k, word in enumerate(words[1:], start=1):
        unit = None if word.lower() in NOT_UNITS else parse_unit(word)
        if unit is None or not any(_fits(unit, r) for r in ROLES.values()):
            continue
        rest = _name(words[:k] + words[k + 1:])
        named = next((r for r in ROLES.values() if r.matches(rest)), None)
        # F_min, Kraft_min: a statistic of the quantity the rest names ('min' a minute only
        # where the rest names a time, t_min)
        if word.lower() in STATISTIC_WORDS and named is not None and not _fits(unit, named):
            continue
        return rest, word
    return _name(words), None


#: what a time column's brackets may say besides its unit: the zone its clock reads
#: (``Time (UTC)``, ``Zeit (MEZ)``), or the origin it counts from (``ms since epoch``)
_ZONE_NAME = re.compile(r"(?:utc|gmt|z|local(?: time)?|lokal(?:zeit)?|cet|cest|mez|mesz)"
                        r"(?:\s*[+-]\s*\d{1,2}(?::?\d\d)?)?", re.IGNORECASE)
_SINCE = re.compile(r"^(?P<unit>\S+)\s+(?:since|seit|depuis|from)\b.*$", re.IGNORECASE)


def _without_origin(unit: str) -> str:
    """A header's bracketed unit without what it says of a clock besides: a time zone is no
    unit (its date-times are read as moments either way, its numbers as seconds), and ``ms
    since epoch`` counts in ms (every time is counted from the first row)."""
    if _ZONE_NAME.fullmatch(unit.strip()):
        return ""
    since = _SINCE.match(unit.strip())
    if since and (counted := parse_unit(since["unit"])) is not None and \
            counted.dimensionality == registry().Unit("s").dimensionality:
        return since["unit"]
    return unit


def _name(words) -> str:
    return " ".join(w.lower() for w in words
                    if w and w.lower() not in STAT_WORDS and w.lower() not in NOT_UNITS)


@dataclass
class Column:
    """A recognised column: its index and header, its unit as read and the toolkit's."""

    role: str
    index: int
    header: str
    unit: str | None = None  # as the table (or --units) says; None: the toolkit's own
    given: bool = False  # named by --columns
    #: a time column of spreadsheet date-times saved as numbers (:func:`_excel_serial_days`)
    excel_days: bool = False
    #: ``unit`` is the one its cells are written with ('0,5 at'), its header naming none
    in_cells: bool = False
    #: the columns this one adds up (``--columns force=A+B``: load cells sharing the pull),
    #: each in its own unit; ``index`` is the first's
    parts: tuple[Column, ...] = ()
    #: how its volts or milliamperes become the role's unit (a channel logged in volts:
    #: ``--sensitivity``; a 4-20 mA transmitter's: ``--current-range``)
    scale: Scaling | SummedScaling | CurrentLoop | None = None
    #: a time column of whole seconds: the column of its milliseconds beside it (index,
    #: header), joined to each time cell by :func:`with_milliseconds`
    milliseconds: tuple[int, str] | None = None

    @property
    def indices(self) -> tuple[int, ...]:
        """The table's columns this one reads: its own (and its milliseconds'), or those it
        adds up."""
        return (tuple(p.index for p in self.parts) or (self.index,)) + (
            (self.milliseconds[0],) if self.milliseconds else ())

    def describe(self) -> dict:
        role_unit = ROLES[self.role].unit
        unit = EXCEL_DAYS if self.excel_days else self.unit
        return {"column": self.header, "unit": unit if unit is not None else role_unit,
                "converted_to": role_unit if role_unit else ("fraction" if role_unit == ""
                                                             else None),
                **({"sum_of": [p.describe() for p in self.parts]} if self.parts else {}),
                **({"milliseconds_column": self.milliseconds[1]} if self.milliseconds
                   else {}),
                **({"scaling": self.scale.describe()} if self.scale else {})}


#: the roles a channel logged in volts or milliamperes may hold (a load-cell amplifier's
#: output, a 0-10 V or a 4-20 mA pressure transducer), one in volts scaled as the bench
#: scales its load cell, ``[loadcell]`` ``sensitivity_N_per_V`` and ``offset_V``: (volts -
#: offset) * sensitivity; each with its scaling's placeholder and where its offset is read
VOLTS_ROLES = {"pressure": ("BAR_PER_V", "at 0 bar"), "force": ("N_PER_V", "unloaded")}


@dataclass(frozen=True)
class Scaling:
    """A channel logged in volts as its role's quantity: ``(volts - offset_V) *
    sensitivity_per_V`` (in the role's unit per volt), as typed (``text``)."""

    sensitivity_per_V: float
    offset_V: float
    text: str
    option = "--sensitivity"
    reads = "V"  # the unit it scales from; what a column logged in it is said to be
    channel = "a channel logged in V or mV"

    def describe(self) -> dict:
        return {"sensitivity_per_V": self.sensitivity_per_V, "offset_V": self.offset_V}

    def shown(self, target: str) -> str:
        return f"{self.sensitivity_per_V:g} {target}/V from {self.offset_V:g} V"

    def values(self, volts: np.ndarray) -> np.ndarray:
        return (volts - self.offset_V) * self.sensitivity_per_V


@dataclass(frozen=True)
class SummedScaling:
    """The :class:`Scaling` of each load cell summed (``--columns force=A+B``), in the order
    of the sum, as typed (``text``)."""

    parts: tuple[Scaling, ...]
    text: str
    option, reads, channel = Scaling.option, Scaling.reads, Scaling.channel

    def describe(self) -> dict:
        return {"sensitivity_per_V": [p.sensitivity_per_V for p in self.parts],
                "offset_V": [p.offset_V for p in self.parts]}

    def shown(self, target: str) -> str:
        return " + ".join(p.shown(target) for p in self.parts)


#: where a summed load cells' sensitivities or offsets part (``200N/V+210N/V``), not an
#: exponent's sign (``2e+2N/V``)
_SUM_SPLIT = re.compile(r"(?<![eE])\+")

#: a current loop's span: its transmitter's range from 4 mA (the low end) to 20 mA (the high)
LOOP_MA = (4.0, 20.0)
#: the currents a working loop reads (NAMUR NE 43): below, a broken wire or a transmitter
#: signalling a fault; above, a fault or a short
LOOP_WORKING_MA = (3.8, 20.5)


@dataclass(frozen=True)
class CurrentLoop:
    """A 4-20 mA transmitter's channel as its role's quantity: ``low`` at 4 mA, ``high`` at
    20 mA, linear between (in the role's unit), as typed (``text``)."""

    low: float
    high: float
    text: str
    option = "--current-range"
    reads = "mA"
    channel = "a 4-20 mA channel logged in mA or A"

    def describe(self) -> dict:
        return {"range": [self.low, self.high], "at_mA": list(LOOP_MA)}

    def shown(self, target: str) -> str:
        return (f"{LOOP_MA[0]:g} mA = {self.low:g} {target}, {LOOP_MA[1]:g} mA = "
                f"{self.high:g} {target}")

    def values(self, current_mA: np.ndarray) -> np.ndarray:
        span = LOOP_MA[1] - LOOP_MA[0]
        return self.low + (current_mA - LOOP_MA[0]) * (self.high - self.low) / span


_SCALE_PART = re.compile(r"^(?P<number>[+-]?(?:\d+[.,]?\d*|[.,]\d+)(?:[eE][+-]?\d+)?)\s*"
                         r"(?P<unit>.*)$")


def _volts(unit) -> bool:
    return unit is not None and unit.dimensionality == registry().Unit("V").dimensionality


def _reads(unit, scale) -> bool:
    """Whether a column in ``unit`` (a pint unit or None) is what ``scale`` converts."""
    return unit is not None and unit.dimensionality == registry().Unit(scale.reads).dimensionality


def _current(unit) -> bool:
    return unit is not None and unit.dimensionality == registry().Unit("mA").dimensionality


def current_header(header: str) -> bool:
    """Whether a header names a unit of electric current (``AI2 [mA]``)."""
    unit = parse_header(header)[1]
    return unit is not None and _current(parse_unit(unit))


def volts_header(header: str) -> bool:
    """Whether a header names a unit of voltage (``AI0 [V]``, ``Kraft (mV)``)."""
    unit = parse_header(header)[1]
    return unit is not None and _volts(parse_unit(unit))


def parse_scaling(sensitivity: str | None, offset: str | None,
                  current_range: str | None = None
                  ) -> dict[str, Scaling | SummedScaling | CurrentLoop]:
    """``--sensitivity force=200N/V,pressure=2.5bar/V`` and ``--offset-volts
    force=0.012,pressure=0.5V`` -> role -> :class:`Scaling`: a sensitivity in any unit of the
    role per volt (a bare number: N/V, bar/V), positive; an offset in volts (default 0 V);
    summed load cells' each (``force=200N/V+210N/V``: :class:`SummedScaling`, one per column
    of ``--columns force=A+B`` in its order; one alone is shared); ``--current-range
    pressure=0:10bar`` -> role -> :class:`CurrentLoop`; ``ValueError`` naming a bad item or a
    role given both."""
    given = parse_assignments(sensitivity, "--sensitivity", VOLTS_ROLES)
    offsets = parse_assignments(offset, "--offset-volts", VOLTS_ROLES)
    loops = parse_assignments(current_range, "--current-range", VOLTS_ROLES)
    for role in loops.keys() & given.keys():
        raise ValueError(f"--current-range {role}={loops[role]} and --sensitivity "
                         f"{role}={given[role]}: expected one, --current-range for a 4-20 mA "
                         "channel, --sensitivity for one in volts")
    for role in offsets.keys() - given.keys():
        raise ValueError(f"--offset-volts {role}={offsets[role]}: no --sensitivity {role}=...: "
                         f"expected both for a channel logged in volts")
    out: dict[str, Scaling | SummedScaling | CurrentLoop] = {}
    for role, text in given.items():
        # load cells summed (--columns force=A+B) may each have their own: 200N/V+210N/V
        texts = _SUM_SPLIT.split(text) if role in SUMMED_ROLES else [text]
        written = _SUM_SPLIT.split(offsets[role]) if role in offsets and role in SUMMED_ROLES \
            else [offsets.get(role)]
        if len(texts) > 1 and len(written) > 1 and len(written) != len(texts):
            raise ValueError(f"--sensitivity {role}={text} and --offset-volts "
                             f"{role}={offsets[role]}: {len(texts)} sensitivities and "
                             f"{len(written)} offsets: expected one of each per column added")
        n = max(len(texts), len(written))
        parts = tuple(_scaling(role, texts[k % len(texts)].strip(),
                               None if written[k % len(written)] is None
                               else written[k % len(written)].strip()) for k in range(n))
        out[role] = parts[0] if n == 1 else SummedScaling(parts, text)
    for role, text in loops.items():
        out[role] = _current_loop(role, text)
    return out


def _scaling(role: str, text: str, written: str | None) -> Scaling:
    """One channel's ``--sensitivity`` ``text`` and ``--offset-volts`` ``written`` (None:
    0 V) -> :class:`Scaling`."""
    per = f"{ROLES[role].unit}/V"
    match = _SCALE_PART.match(text.strip())
    unit = parse_unit(match["unit"]) if match and match["unit"].strip() else \
        registry().Unit(per) if match else None
    if unit is None or unit.dimensionality != registry().Unit(per).dimensionality:
        raise ValueError(f"--sensitivity {role}={text} is invalid: expected the {role} per "
                         f"volt, e.g. {role}=200{per}" if role == "force" else
                         f"--sensitivity {role}={text} is invalid: expected the {role} per "
                         f"volt, e.g. {role}=2.5{per}")
    value = float(registry().Quantity(float(match["number"].replace(",", ".")), unit)
                  .to(per).magnitude)
    if not (math.isfinite(value) and value > 0):
        raise ValueError(f"--sensitivity {role}={text} is invalid: expected a {role} per "
                         "volt above 0 (--force-sign -1 reads a load cell wired to read "
                         "the pull negative)")
    offset_V = 0.0
    if written is not None:
        match = _SCALE_PART.match(written.strip())
        unit = parse_unit(match["unit"]) if match and match["unit"].strip() else \
            registry().Unit("V") if match else None
        if not _volts(unit):
            raise ValueError(f"--offset-volts {role}={written} is invalid: expected the "
                             f"volts the channel reads {VOLTS_ROLES[role][1]}, e.g. "
                             f"{role}=0.012 or {role}=12mV")
        offset_V = float(registry().Quantity(float(match["number"].replace(",", ".")),
                                             unit).to("V").magnitude)
    return Scaling(value, offset_V, text)


def _current_loop(role: str, text: str) -> CurrentLoop:
    """``--current-range ROLE=LOW:HIGH[UNIT]`` (each end may carry its unit; a bare number is
    in the role's unit) -> :class:`CurrentLoop`."""
    unit_of = ROLES[role].unit
    example = "pressure=0:10bar" if role == "pressure" else "force=0:500N"
    ends = [_SCALE_PART.match(part.strip()) for part in text.split(":")]
    units = [parse_unit(m["unit"]) if m and m["unit"].strip() else None for m in ends
             if m is not None]
    if (len(ends) != 2 or not all(ends) or len(units) != 2
            or any(m["unit"].strip() and u is None for m, u in zip(ends, units, strict=True))):
        raise ValueError(f"--current-range {role}={text} is invalid: expected the "
                         f"transmitter's {role} at 4 mA and at 20 mA, LOW:HIGH, e.g. {example}")
    default = next((u for u in reversed(units) if u is not None), registry().Unit(unit_of))
    low, high = (registry().Quantity(float(m["number"].replace(",", ".")), u or default)
                 for m, u in zip(ends, units, strict=True))
    if not all(_fits(q.units, ROLES[role]) for q in (low, high)):
        raise ValueError(f"--current-range {role}={text} is invalid: expected a {role} at each "
                         f"end, e.g. {example}")
    low, high = (float(q.to(unit_of).magnitude) for q in (low, high))
    if not (math.isfinite(low) and math.isfinite(high) and high > low):
        raise ValueError(f"--current-range {role}={text} is invalid: expected the {role} at "
                         f"4 mA below the one at 20 mA, e.g. {example}")
    return CurrentLoop(low, high, text)


#: the roles whose columns ``--columns ROLE=A+B`` adds up: load cells in parallel share the
#: muscle's pull (pressures, times or lengths added make no reading)
SUMMED_ROLES = ("force",)


def taken_columns(found: dict[str, Column]) -> set[int]:
    """The table's columns the recognised ``found`` read (the parts of a sum each)."""
    return {k for c in found.values() for k in c.indices}


def several_forces(headers: list[str]) -> str:
    """What to do with several force columns: choose one, or add them (``A+B``)."""
    return ("choose one with --columns force=COLUMN (load cells in series each read the whole "
            f"force), or add them with --columns force='{'+'.join(headers)}' (cells in parallel "
            "share it)")


def parse_assignments(text: str | None, option: str, roles=ROLES) -> dict[str, str]:
    """``pressure=P [bar],force=F`` (``--columns``, ``--units``) -> ``{"pressure": "P [bar]",
    "force": "F"}``; ``ValueError`` naming a bad item or a role given twice. ``roles``: the
    names the option takes (default the columns' :data:`ROLES`)."""
    out = {}
    # an item ends at a comma before the next NAME=, so a header may hold commas itself
    # ("force=Kraft, gemessen,pressure=Druck")
    items = re.split(r",(?=\s*[A-Za-z_]\w*\s*=)", text or "")
    for item in filter(None, (i.strip() for i in items)):
        role, sep, value = item.partition("=")
        role = role.strip()
        if not sep or role not in roles or not value.strip():
            raise ValueError(f"{option} item {item!r} is invalid: expected ROLE=VALUE with ROLE "
                             f"one of {', '.join(roles)}")
        if role in out:
            raise ValueError(f"{option} gives {role} twice ({role}={out[role]}, {item}): "
                             "expected one value per role")
        out[role] = value.strip()
    return out


def recognise(table: RawTable, columns: dict[str, str] | None = None,
              units: dict[str, str] | None = None,
              scaling: dict[str, Scaling] | None = None) -> dict[str, Column]:
    """The column of each role found in ``table`` (see the module docstring).

    ``columns`` names a role's column outright, ``units`` its unit, ``scaling`` how a channel
    logged in volts becomes its role's quantity. ``ValueError``: a named column missing, two
    columns claiming one role, a unit of the wrong dimension, a channel in volts without a
    scaling or a scaling for one not in volts.
    """
    columns, units = columns or {}, units or {}
    found: dict[str, Column] = {}
    headers = table.header
    for role, given in columns.items():
        named = [given] if given in headers or "+" not in given else \
            [part.strip() for part in given.split("+")]
        if len(named) > 1 and not all(named):
            raise ValueError(f"--columns {role}={given!r}: a sum names a column on each side "
                             "of each '+': expected COLUMN+COLUMN")
        if len(named) > 1 and role not in SUMMED_ROLES:
            raise ValueError(f"--columns {role}={given!r}: only {' and '.join(SUMMED_ROLES)} "
                             f"columns add up (load cells sharing the pull): expected one "
                             f"{role} column")
        parts = []
        for header in named:
            if header not in headers:
                header = _header_named(table, role, header)
            if headers.count(header) > 1:  # the first would be taken, the others dropped unsaid
                raise ValueError(f"--columns {role}={header!r}: {table.name} has "
                                 f"{_same_name(headers, header)}: expected one column of that "
                                 "name; rename the others in the file")
            parts.append(Column(role, headers.index(header), header, parse_header(header)[1],
                                True))
        if len({p.index for p in parts}) < len(parts):
            raise ValueError(f"--columns {role}={given!r} names one column twice: expected "
                             "each column added once")
        found[role] = parts[0] if len(parts) == 1 else Column(
            role, parts[0].index, " + ".join(p.header for p in parts), ROLES[role].unit,
            True, parts=tuple(parts))
    taken = taken_columns(found)
    for index, header in enumerate(headers):
        if index in taken or not header:
            continue
        name, unit = parse_header(header)
        absolute = _absolute_name(name)
        if "pressure" not in columns and absolute is not None and \
                ROLES["pressure"].matches(absolute):
            # its name says what a unit's mark says ('kPa abs'): read as gauge, 1 bar too high
            raise ValueError(f"{table.name}: column {header!r} is an absolute pressure (its "
                             "name says so): expected a gauge pressure, above the atmosphere "
                             "as the regulator sets it (bar, bar(g), kPa, psi)")
        role = next((r for r, spec in ROLES.items() if spec.matches(name)), None)
        if role is None or role in columns or _symbol_of_another(name, unit):
            continue
        if role in found and header == found[role].header:
            raise ValueError(f"{table.name}: {_same_name(headers, header)}, each a {role} "
                             "column: expected one; rename the others in the file")
        if role in found:
            raise ValueError(f"{table.name}: two {role} columns, {found[role].header!r} and "
                             f"{header!r}: " + (several_forces([found[role].header, header])
                                                if role in SUMMED_ROLES else
                                                f"choose one with --columns {role}=COLUMN"))
        found[role] = Column(role, index, header, unit)
    for role in BY_UNIT_ROLES:
        # a DAQ's channel by its number ('AI 1 [bar]'): the one column whose unit is of the
        # role's quantity (two, a set point beside a reading, are for --columns to tell)
        by_unit = [] if role in found else by_unit_columns(table, role, found)
        if len(by_unit) == 1:
            index = by_unit[0]
            found[role] = Column(role, index, headers[index], parse_header(headers[index])[1])
    if "time" not in found:
        # each channel beside its own time: one clock where they read alike row by row (one
        # such column alone may be a hold's duration, 'Time held (s)': named, not taken)
        channels = _channel_times(table, taken_columns(found))
        if len(channels) > 1 and all(row[k] == row[channels[0]] for row in table.rows
                                     for k in channels):
            header = headers[channels[0]]
            found["time"] = Column("time", channels[0], header, parse_header(header)[1])
    for role, unit in units.items():
        if role not in found:
            raise ValueError(f"--units {role}={unit}: {table.name} has no {role} column "
                             f"(found {_listed(c.header for c in found.values())})")
        for column in found[role].parts or (found[role],):
            column.unit = unit
    for column in [p for c in found.values() for p in c.parts or (c,)]:
        if column.unit is None and ROLES[column.role].unit is not None:
            # the unit the first cell is written with ('0,5 at'), as the line and run.json
            # say it; column_values reads every cell's and refuses mixed ones
            first = next((row[column.index] for row in table.rows
                          if str(row[column.index]).strip()), None)
            written = _number(first, table.decimal)[1] if isinstance(first, str) else None
            if written is not None:
                column.unit, column.in_cells = written, True
    for role, scale in (scaling or {}).items():
        if role in found:
            column = found[role]
            if not all(_reads(parse_unit(p.unit) if p.unit else None, scale)
                       for p in column.parts or (column,)):
                written = (f"is in {column.unit!r}" if column.unit else
                           f"names no unit (read in {ROLES[role].unit})")
                kind = "volts" if scale.reads == "V" else "a current"
                what = "a scaling" if scale.reads == "V" else "a range"
                raise ValueError(f"{scale.option} {role}={scale.text}: column "
                                 f"{column.header!r} {written}, not {kind}: expected {what} "
                                 f"only for {scale.channel}")
            parts = column.parts or (column,)
            each = getattr(scale, "parts", None)
            if each is not None and len(each) != len(parts):
                raise ValueError(f"--sensitivity {role}={scale.text}: {len(each)} "
                                 f"sensitivities for {len(parts)} column(s), "
                                 f"{column.header!r}: expected one per column added "
                                 f"(--columns {role}=A+B), in its order, or one for all")
            for k, part in enumerate(parts):
                part.scale = each[k] if each is not None else scale
            column.scale = scale
    for column in [p for c in found.values() for p in c.parts or (c,)]:
        if column.role not in units and not column.in_cells:
            _refuse_mega_or_milli(table, column)
        _check_unit(table, column)
    if "time" in found and found["time"].unit is None:
        found["time"].excel_days = _excel_serial_days(table, found["time"])
    return found


#: the quantities a one-letter name stands for beside the roles' (T a temperature, P a
#: power, F or f a frequency), by a unit of each
OTHER_SYMBOL_UNITS = ("K", "W", "Hz")


def _symbol_of_another(name: str, unit: str | None) -> bool:
    """Whether a one-letter name is the symbol of another quantity, which its unit says (``T
    [°C]`` a temperature, not a time; ``P [W]`` a power; ``F [Hz]`` a frequency): a column
    to leave, not a reading written in the wrong unit, which is refused naming it."""
    parsed = parse_unit(unit) if len(name) == 1 and unit is not None else None
    return parsed is not None and any(
        parsed.dimensionality == registry().Unit(other).dimensionality
        for other in OTHER_SYMBOL_UNITS)


def by_unit_columns(table: RawTable, role: str, found: dict[str, Column]) -> list[int]:
    """The columns no role took whose unit is of ``role``'s quantity, set points left out: the
    ones that may hold it where no column's name says it."""
    taken = taken_columns(found)
    return [index for index, header in enumerate(table.header)
            if header and index not in taken and not _set_point(parse_header(header)[0])
            and not statistic(parse_header(header)[0]) and not supply(parse_header(header)[0])
            and (unit := parse_header(header)[1]) is not None
            and (parsed := parse_unit(unit)) is not None and _fits(parsed, ROLES[role])]


def unread_columns(table: RawTable, role: str) -> list[tuple[str, str]]:
    """The headers whose unit is of ``role``'s quantity but whose name makes them no reading
    of the muscle's, which :func:`by_unit_columns` leaves out, each with why in words: a
    statistic (:data:`STATISTIC_WORDS`) or the supply pressure (:data:`SUPPLY_WORDS`)."""
    out = []
    for header in table.header:
        name, unit = parse_header(header) if header else ("", None)
        why = ("a statistic" if statistic(name) else
               "the supply pressure, upstream of the regulator" if supply(name) else None)
        # without a unit, a statistic of the role's quantity by its name (F_min, p max)
        of_role = ROLES[role].matches(" ".join(w for w in name.split()
                                               if w not in STATISTIC_WORDS))
        if why and (unit is None and of_role or unit is not None
                    and (parsed := parse_unit(unit)) is not None and _fits(parsed, ROLES[role])):
            out.append((header, why))
    return out


#: how a time column of spreadsheet serial dates is said (the line, run.json)
EXCEL_DAYS = "Excel serial days"
#: the serial dates (days since 30 Dec 1899) a time column without a unit is taken to hold:
#: 1954-10-03 to Excel's last day, 9999-12-31
EXCEL_SERIAL_DAYS = (20_000.0, 2_958_465.0)


def _excel_serial_days(table: RawTable, column: Column) -> bool:
    """Whether the numbers of a time column without a unit are a spreadsheet's date-times
    saved as numbers (46361.5868 is 5 Dec 2026 14:05): each within :data:`EXCEL_SERIAL_DAYS`
    and all within a day of the first. As seconds they would be a record of less than a second
    taken hours into a clock's count, which no muscle's hold is."""
    raw = [row[column.index] for row in table.rows]
    if len(raw) < 3 or _clock(raw[0]) is not None:
        return False
    values = _plain_numbers(raw, table.decimal)
    low, high = EXCEL_SERIAL_DAYS
    return bool(values is not None and values.min() >= low and values.max() <= high
                and np.ptp(values) < 1.0)


#: the fewest rows a time column must have to be told a row counter
ROW_COUNTER_MIN_ROWS = 3


def counts_rows(table: RawTable, column: Column | None) -> bool:
    """Whether a time column is a logger's row counter, no clock: whole numbers stepping by
    exactly 1 (from 0, 1 or a count carried on, 100000) under a header without a unit that
    names no clock of seconds since 1970, neither named by ``--columns`` nor given one by
    ``--units``. Read as seconds they would be a 1 Hz clock, which the file does not say (a
    100 Hz record would last a hundred times as long)."""
    if column is None or column.unit is not None or column.given or column.excel_days \
            or column.parts or len(table.rows) < ROW_COUNTER_MIN_ROWS \
            or parse_header(column.header)[0] in EPOCH_NAMES:
        return False
    raw = [row[column.index] for row in table.rows]
    values = _plain_numbers(raw, table.decimal)
    rows = np.arange(len(raw))
    if values is None:  # a blank cell, a summary row's label ('Max'): the rows of numbers
        read = [plain_number(cell, table.decimal) for cell in raw]
        rows = np.flatnonzero([v is not None for v in read])
        values = np.array([read[k] for k in rows], dtype=float)
    # each number its row's: a whole number on the first row, one more on each row below
    if 2 * rows.size <= len(raw) or rows.size < ROW_COUNTER_MIN_ROWS:
        return False
    start = values[0] - rows[0]
    return bool(start >= 0 and start == round(start) and np.all(values - rows == start))


#: the names of a column holding a clock's milliseconds beside a time column of whole
#: seconds, as some data loggers write their time ('Date&Time' and 'ms')
MILLISECOND_NAMES = ("ms", "msec", "millisecond", "milliseconds", "millisekunden")
#: a clock reading's whole seconds, nothing after them that is part of the time (14:05:00 in
#: '05.12.2026 14:05:00' or '2:05:00 PM', not 14:05:00.250 or 14:05:00:250)
_WHOLE_SECONDS = re.compile(r"(?<![\d:])(\d{1,2}:\d{2}:\d{2})(?![\d.,:])")


def with_milliseconds(table: RawTable,
                      found: dict[str, Column]) -> tuple[RawTable, dict[str, Column]]:
    """``table`` and ``found`` with a time column of whole seconds (clock readings or
    date-times, ``05.12.2026 14:05:00``) and the column of milliseconds beside it (named
    :data:`MILLISECOND_NAMES`, without a unit) joined: each time cell holds its row's
    milliseconds (``05.12.2026 14:05:00.250``), and the time column names both. Read apart,
    the rows of one second would share its time. Any other table as it is; ``ValueError``
    naming a row's milliseconds that are no whole number from 0 to 999."""
    time = found.get("time")
    if time is None or time.parts or time.milliseconds or not table.rows:
        return table, found
    taken = taken_columns(found)
    beside = [k for k in (time.index + 1, time.index - 1)
              if 0 <= k < len(table.header) and k not in taken and table.header[k]
              and parse_header(table.header[k]) in ((n, None) for n in MILLISECOND_NAMES)]
    if not beside:
        return table, found
    cells = [row[time.index] for row in table.rows]
    whole = [isinstance(c, datetime.datetime) and not c.microsecond
             or isinstance(c, str) and len(_WHOLE_SECONDS.findall(c)) == 1 for c in cells]
    # rows whose time is no clock reading (a blank cell, a summary row's 'Max') are left to
    # the checks that skip or refuse them
    if not whole[0] or not all(
            w or not isinstance(c, (str, datetime.datetime)) or ":" not in str(c)
            for c, w in zip(cells, whole, strict=True)):
        return table, found
    index = beside[0]
    rows = []
    for k, (row, cell, joined) in enumerate(zip(table.rows, cells, whole, strict=True)):
        if joined:
            ms = plain_number(row[index], table.decimal)
            if ms is None or ms != int(ms) or not 0 <= ms <= 999:
                raise ValueError(f"{table.where(k, index)} (column "
                                 f"{table.header[index]!r}): {_shown(row[index])} is not the "
                                 f"milliseconds of its time {_shown(cell)}: expected a whole "
                                 "number from 0 to 999")
            cell = (cell + datetime.timedelta(milliseconds=int(ms))
                    if isinstance(cell, datetime.datetime) else
                    _WHOLE_SECONDS.sub(lambda m, ms=int(ms): f"{m[1]}.{ms:03d}", cell))
        rows.append([*row[:time.index], cell, *row[time.index + 1:]])
    return (replace(table, rows=rows),
            {**found, "time": replace(time, milliseconds=(index, table.header[index]))})


def timed_rows(table: RawTable, rate_hz: float) -> tuple[RawTable, Column]:
    """``table`` with a time column of its own, row ``k`` at ``k / rate_hz`` seconds, and that
    column: a logger's rows written at the rate the lab states (``--sample-rate``) without
    their clock, or with a row counter (:func:`counts_rows`)."""
    header = f"rows at {rate_hz:g} Hz"
    rows = [[*row, k / rate_hz] for k, row in enumerate(table.rows)]
    return (replace(table, header=[*table.header, header], rows=rows),
            Column("time", len(table.header), header, "s", given=True))


def _header_named(table: RawTable, role: str, given: str) -> str:
    """The header ``--columns ROLE=given`` names where no header is ``given`` itself: the one
    whose name without its unit is ``given`` (``Kanal 1`` for ``Kanal 1 [bar]``)."""
    name = given.strip().casefold()
    named = [h for h in table.header if h and name and (
        (match := _BRACKETED.match(str(h).strip())) and match.group("name").strip().casefold()
        == name)]
    if len(named) > 1:
        raise ValueError(f"--columns {role}={given!r}: {table.name} has {len(named)} columns "
                         f"of that name, {_listed(named)}: expected one; name it with its unit")
    if not named:
        raise ValueError(f"--columns {role}={given!r}: {table.name} has no such column: "
                         f"it has {_listed(table.header)}")
    return named[0]


#: the words of a header's name that mark an absolute pressure, and a German compound's start
_ABSOLUTE_WORDS, _ABSOLUTE_PREFIX = {"abs", "absolute", "absolut"}, "absolut"


def _absolute_name(name: str) -> str | None:
    """``name`` (as :func:`parse_header` gives it) without the mark of an absolute pressure
    (``druck abs``, ``p abs``, ``absolutdruck``), or None where it has none."""
    words = name.split()
    if any(w in _ABSOLUTE_WORDS for w in words):
        return " ".join(w for w in words if w not in _ABSOLUTE_WORDS)
    if len(words) == 1 and name.startswith(_ABSOLUTE_PREFIX) and name != _ABSOLUTE_PREFIX:
        return name[len(_ABSOLUTE_PREFIX):]
    return None


#: what a time column's header may name in place of a unit: the format of its clock readings
#: or date-times (``Time (hh:mm:ss)``, ``Zeit [hh:mm:ss.fff]``, ``dd.mm.yyyy hh:mm:ss``)
_CLOCK_FORMAT = re.compile(r"^(?:(?:[dmy]{1,4}[./-][dmy]{1,4}[./-][dmy]{1,4}[ t])?h{1,2}:m{1,2}"
                           r":s{1,2}(?:[.,][fsz0]{1,6})?|m{1,2}:s{1,2}[.,][fsz0]{1,6})$",
                           re.IGNORECASE)


def clock_format(unit: str | None) -> bool:
    """Whether a time column's unit as written is the format of clock readings
    (``hh:mm:ss``), not a unit: its cells are read as clock readings or date-times."""
    return unit is not None and bool(_CLOCK_FORMAT.match(unit.strip()))


def _check_unit(table: RawTable, column: Column) -> None:
    role = ROLES[column.role]
    if column.unit is None:
        return
    if column.role == "time" and clock_format(column.unit):
        return  # its cells are clock readings: column_values reads them as seconds
    if role.unit is None:
        raise ValueError(f"{table.name}: column {column.header!r} ({column.role}) takes no "
                         f"unit, got {column.unit!r}")
    if column.role in VOLTS_ROLES and column.scale is None and _volts(parse_unit(column.unit)):
        placeholder, zero = VOLTS_ROLES[column.role]
        raise ValueError(f"{table.name}: column {column.header!r} is logged in volts "
                         f"({column.unit!r}): expected a {column.role} unit like {role.unit}, "
                         f"or the channel's scaling: --sensitivity {column.role}={placeholder} "
                         f"(and --offset-volts {column.role}=V, what it reads {zero})")
    if column.role in VOLTS_ROLES and column.scale is None and _current(parse_unit(column.unit)):
        example = "0:10bar" if column.role == "pressure" else "0:500N"
        raise ValueError(f"{table.name}: column {column.header!r} is a current loop's "
                         f"({column.unit!r}): expected a {column.role} unit like {role.unit}, "
                         f"or the transmitter's range: --current-range {column.role}={example} "
                         f"(its {column.role} at 4 mA and at 20 mA)")
    if column.scale is not None:
        return  # its volts or milliamperes scaled to the role's unit
    if column.role == "pressure" and _ABSOLUTE.fullmatch(column.unit.strip()):
        raise ValueError(f"{table.name}: column {column.header!r}: {column.unit!r} is an "
                         "absolute pressure: expected a gauge pressure, above the atmosphere as "
                         "the regulator sets it (bar, bar(g), kPa, psi)")
    unit = parse_unit(column.unit)
    if not _fits(unit, role):
        # a load cell's display in kg or lb shows a mass for the force it weighs
        weighed = (column.role == "force" and unit is not None
                   and unit.dimensionality == registry().Unit("kg").dimensionality)
        hint = (f"; if the load cell shows the weight it holds, give --units force="
                f"{_weight_unit(unit)}" if weighed else "")
        # a gauge's dial in kg/cm² shows kilograms of weight per area, as at and kgf/cm² do
        if (column.role == "pressure" and unit is not None
                and unit.dimensionality == registry().Unit("kg/cm**2").dimensionality):
            per_area = re.sub(r"^\s*kg\b", "kgf", column.unit.strip())
            if not _fits(parse_unit(per_area), role):
                per_area = "kgf/cm²"
            hint = ("; if the gauge shows kilograms of weight per area, give --units "
                    f"pressure={per_area}")
        raise ValueError(f"{table.name}: column {column.header!r}: {column.unit!r} is not a "
                         f"unit of {column.role} (expected one like "
                         f"{role.unit or 'percent'}){hint}")


def _refuse_mega_or_milli(table: RawTable, column: Column) -> None:
    """``ValueError`` for a header written in capitals whose unit's ``M`` may be mega or milli
    (``FORCE (MN)``: a meganewton as pint reads it, a millinewton as a lab writing in capitals
    may mean it), a million apart: not guessed. A header in mixed case says its prefix
    (``Force (MN)`` mega, ``F [mN]`` milli), and :data:`LAB_UNITS` reads the capitals labs
    use for one of them (``MPA``, ``MBAR``, ``MSEC``)."""
    text = (column.unit or "").strip()
    if not text.startswith("M") or " ".join(text.lower().split()) in LAB_UNITS \
            or column.header != column.header.upper():
        return
    milli_text = "m" + text[1:]
    mega, milli = parse_unit(text), parse_unit(milli_text)
    if mega is None or milli is None or mega == milli \
            or mega.dimensionality != milli.dimensionality:
        return
    raise ValueError(f"{table.name}: column {column.header!r}: {text!r} written in capitals "
                     f"may be {milli_text!r} ({milli}) or {text!r} ({mega}), a million apart: "
                     f"not guessed: expected --units {column.role}={milli_text} (or "
                     f"{column.role}={text})")


def weighed_columns(table: RawTable) -> list[tuple[str, str]]:
    """The headers whose unit is a mass (``Weight (kg)``: a scale, or a load cell's display in
    kg, shows the mass whose weight it holds), each with the force unit of that weight."""
    out = []
    for header in table.header:
        unit = parse_unit(parse_header(header)[1] or "") if header else None
        if unit is not None and unit.dimensionality == registry().Unit("kg").dimensionality:
            out.append((header, _weight_unit(unit)))
    return out


def _weight_unit(mass) -> str:
    """The force unit of the weight of ``mass``, a pint unit of mass: ``kgf`` for kg, ``gf``
    for g, ``lbf`` for lb (or lbs)."""
    name = f"{mass:~}" + "f"
    force = parse_unit(name)
    return name if force is not None and _fits(force, ROLES["force"]) else "kgf (g: gf, lb: lbf)"


def _same_name(headers, header: str) -> str:
    """``2 columns named 'F (N)' (B, C)``."""
    letters = [_column_letters(i) for i, h in enumerate(headers) if h == header]
    return f"{len(letters)} columns named {header!r} ({', '.join(letters)})"


def _listed(headers) -> str:
    shown = [repr(str(h)) for h in headers if str(h)]
    return ", ".join(shown) if shown else "no named column"


def column_values(table: RawTable, column: Column, optional: bool = False) -> np.ndarray:
    """The cells of ``column`` as numbers in the toolkit's unit (pint converts); ``ValueError``
    naming the first cell that is text, not finite, or carries a unit other cells do not
    (``optional``: an empty cell is NaN, a value not known); a sum's parts each so, added."""
    if column.parts:
        return sum(column_values(table, part, optional) for part in column.parts)
    role = ROLES[column.role]
    raw = [row[column.index] for row in table.rows]
    if column.role == "time":
        if clock_format(column.unit) and raw and _clock(raw[0]) is None:
            raise ValueError(f"{table.where(0, column.index)} (column "
                             f"{column.header!r}): {_shown(raw[0])} is not a clock reading "
                             f"as the header's {column.unit!r} says: expected times such as "
                             "09:05:00.250, or a header naming the unit of its numbers "
                             "(Time [s])")
        elapsed = _elapsed_s(table, column, raw)
        if elapsed is not None:
            return elapsed
        if column.excel_days:  # counted from the first row, as a clock is
            days = _plain_numbers(raw, table.decimal)
            return (days - days[0]) * _DAY_S
        if raw and str(raw[0]).strip() and _number(raw[0], table.decimal)[0] is None:
            raise ValueError(f"{table.where(0, column.index)} (column "
                             f"{column.header!r}): {_shown(raw[0])} is not a time: expected "
                             "seconds (or the unit in the header: Time [ms]), minutes and "
                             "seconds (05:03.2), a time of day (14:05:00.250, 2:05:00 PM) or a "
                             "date-time (2026-12-05 14:05:00, 05.12.2026 14:05:00, 12/5/2026 "
                             "2:05:00 PM)")
    plain = _plain_numbers(raw, table.decimal)
    values = plain if plain is not None else np.empty(len(raw))
    inline: dict[str, int] = {}
    grouped = plain is None and _points_group(table, column, raw)
    for k, cell in enumerate(raw if plain is None else ()):
        if optional and str(cell).strip() == "":
            values[k] = math.nan
            continue
        if grouped and _POINT_GROUPED.match(str(cell).strip()):
            cell = str(cell).strip().replace(".", "")
        number, unit = _number(cell, table.decimal)
        if number is None:
            formula = _formula(table, k, column.index) if cell == "" else None
            again = str(cell).strip() == column.header.strip()
            why = (f"holds the formula {_shown(formula)} without a value saved: open and save "
                   "the workbook in Excel (or LibreOffice) to compute it, or export it as CSV"
                   if formula else
                   f"{_shown(cell)} is the header again, a second record in the file (a "
                   "logger that appended another session): expected one header; split the "
                   "file there and import each" if again else
                   f"{_shown(cell)} is a spreadsheet's error value (a formula that failed "
                   "there: Excel's #VALUE!, #DIV/0!, #REF!, in German #WERT!, #BEZUG!): "
                   "correct the formula, or delete its row"
                   if _SPREADSHEET_ERROR.fullmatch(str(cell).strip()) else
                   f"{_shown(cell)} is not a number")
            raise ValueError(f"{table.where(k, column.index)} (column "
                             f"{column.header!r}): {why}")
        if not math.isfinite(number):
            raise ValueError(f"{table.where(k, column.index)} (column "
                             f"{column.header!r}): {_shown(cell)} is not a finite number")
        if unit is not None:
            inline.setdefault(unit, k)
        values[k] = number
    unit = column.unit
    if inline:
        if len(inline) > 1 or (unit is not None and unit not in inline):
            (u1, k1), (u2, k2) = sorted({**({unit: -1} if unit and unit not in inline else {}),
                                         **inline}.items(), key=lambda kv: kv[1])[:2]
            where1 = "the header" if k1 < 0 else f"cell {table.ref(k1, column.index)}"
            raise ValueError(f"{table.name}: mixed units in column {column.header!r}: {u1!r} "
                             f"in {where1}, {u2!r} in cell {table.ref(k2, column.index)}: "
                             "expected one unit per column")
        unit = next(iter(inline))
        _check_unit(table, replace(column, unit=unit))
    if column.scale is not None:  # volts as the bench scales its load cell's, or a loop's mA
        read = (values * parse_unit(unit)).to(column.scale.reads).magnitude
        if isinstance(column.scale, CurrentLoop):
            _check_loop(table, column, read)
        return column.scale.values(read)
    if unit is not None and role.unit is not None:
        values = (values * parse_unit(unit)).to(role.unit or "dimensionless").magnitude
    if column.role != "time":
        return values
    clock = CLOCK_NAMES.get(parse_header(column.header)[0])
    if clock is not None:  # an Arduino's micros() or millis(): its 32-bit counter overflows
        values = _carried_on(values, float((CLOCK_WRAP * parse_unit(clock)).to("s").magnitude))
    return _carried_on(values, _DAY_S)


#: a number grouped by points with no decimal mark ('250.000'): beside decimal commas, its
#: thousands grouped or a decimal point (a column another program wrote)
_POINT_GROUPED = re.compile(r"^[+-]?[1-9]\d{0,2}(\.\d{3})+$")


def _points_group(table: RawTable, column: Column, raw: list) -> bool:
    """Whether the points of a decimal-comma table's column group thousands ('250.000' beside
    '1.048,96' or '12,5' in the column); False where it has none so written, or points that
    are decimal points ('1.25'); ``ValueError`` naming the first such cell where every one
    of the column's numbers with a point could be either."""
    if table.decimal != ",":
        return False
    texts = [str(c).strip() for c in raw]
    first = next((k for k, t in enumerate(texts) if _POINT_GROUPED.match(t)), None)
    if first is None:
        return False
    if any(_COMMA_DECIMAL.match(t) or _GROUPED[","].match(t) for t in texts):
        return True
    if any("." in t and not _POINT_GROUPED.match(t) for t in texts):
        return False
    cell = texts[first]
    raise ValueError(f"{table.where(first, column.index)} (column {column.header!r}): "
                     f"{cell!r} in a table of decimal commas could be "
                     f"{float(cell.replace('.', '')):g} with its thousands grouped or "
                     f"{float(cell):g} with a decimal point, as could every number of the "
                     "column with a point: expected the file saved without thousands "
                     "separators (Excel: Format Cells, Number, no 1000 separator)")


def _carried_on(seconds: np.ndarray, period_s: float) -> np.ndarray:
    """A time column whose count restarts each ``period_s`` (seconds since midnight, a logger's
    time of day as a number; an Arduino's micros(), every ~71.6 min), every reading within one
    period, carried on across each restart, as a clock reading's are: a step back that lands
    one sampling interval (or two) past the period's end. Any other step back stays one,
    refused where the time is read."""
    if seconds.size < 3 or seconds.min() < 0 or seconds.max() >= period_s:
        return seconds
    step = np.diff(seconds)
    forward = step[step > 0]
    if not forward.size:
        return seconds
    across = step + period_s  # the time from the period's last reading to the first after it
    wrapped = (step < 0) & (across > 0) & (across <= 2 * float(np.median(forward)))
    return seconds + period_s * np.cumsum(np.r_[0.0, wrapped]) if wrapped.any() else seconds


def _check_loop(table: RawTable, column: Column, current_mA: np.ndarray) -> None:
    """``ValueError`` naming the first cell of a 4-20 mA channel outside the currents a working
    loop reads (:data:`LOOP_WORKING_MA`): a broken wire or a transmitter in fault reads no
    pressure or force, and scaled it would read as one."""
    low, high = LOOP_WORKING_MA
    outside = np.flatnonzero((current_mA < low) | (current_mA > high))
    if outside.size:
        k = int(outside[0])
        more = f" ({outside.size - 1} more row(s) too)" if outside.size > 1 else ""
        raise ValueError(f"{table.where(k, column.index)} (column "
                         f"{column.header!r}): {current_mA[k]:g} mA is outside the "
                         f"{low:g}-{high:g} mA a working 4-20 mA loop reads{more}: a broken "
                         "wire or a transmitter signalling a fault, its reading no "
                         f"{column.role}: expected the rows of a working loop (leave those "
                         "rows out of the file)")


def _plain_numbers(raw: list, decimal: str) -> np.ndarray | None:
    """A column whose every cell is a plain finite number (a workbook's numbers, or text such as
    ``1.5``, ``1,5`` with decimal commas) read at numpy's speed; ``None``: read it cell by cell
    (a unit, a thousands' mark, text, a blank, a non-finite value), which names a bad cell."""
    if all(type(c) is float or type(c) is int for c in raw):
        values = np.asarray(raw, dtype=float)
    # float() reads '1_000'; beside decimal commas '1.234' groups thousands
    elif all(type(c) is str and "_" not in c and (decimal == "." or "." not in c)
             for c in raw):
        text = np.asarray(raw, dtype=str)
        try:
            values = (np.char.replace(text, ",", ".") if decimal == "," else text).astype(float)
        except ValueError:
            return None
    else:
        return None
    return values if values.size and np.isfinite(values).all() else None


_CLOCK = re.compile(r"^(?P<h>\d{1,3}):(?P<m>\d{2}):(?P<s>\d{2}(?:[.,]\d*)?)$")
_DAY_S = 86400.0
#: a stopwatch's minutes and seconds, as a spreadsheet's ``mm:ss.0`` shows an elapsed time
#: (05:03.2); the seconds' fraction tells it from a clock's ``hh:mm``
_STOPWATCH = re.compile(r"^(?P<m>\d{1,4}):(?P<s>[0-5]\d[.,]\d+)$")
_HOUR_S = 3600.0


#: a time of day on a 12-hour clock, as an English-language Excel writes it (2:05:00 PM)
_CLOCK_12H = re.compile(r"^(?P<h>\d{1,2}):(?P<m>\d{2})(?::(?P<s>\d{2}(?:[.,]\d*)?))?\s*"
                        r"(?P<half>[AaPp])\.?[Mm]\.?$")
#: a date written with slashes, day and month in either order (12/5/2026 or 5/12/2026), and a
#: time of day after it (24-hour, or 12-hour with AM/PM)
_SLASHED = re.compile(r"^(?P<a>\d{1,2})/(?P<b>\d{1,2})/(?P<y>\d{4})\s+(?P<clock>\S.*)$")


def _time_of_day_s(text: str) -> float | None:
    """``hh:mm:ss[.fff]`` or ``h:mm[:ss[.fff]] AM/PM`` as seconds from midnight, else None."""
    match = _CLOCK.match(text)
    if match:
        return (int(match["h"]) * 3600.0 + int(match["m"]) * 60.0
                + float(match["s"].replace(",", ".")))
    match = _CLOCK_12H.match(text)
    if match and 1 <= int(match["h"]) <= 12:
        hour = int(match["h"]) % 12 + (12 if match["half"] in "Pp" else 0)
        return (hour * 3600.0 + int(match["m"]) * 60.0
                + float((match["s"] or "0").replace(",", ".")))
    return None


def _slashed_s(text: str, day_first: bool) -> float | None:
    """A slashed date-time (month first, or day first) as seconds since 1970, else None."""
    match = _SLASHED.match(text)
    if not match:
        return None
    month, day = (int(match["b"]), int(match["a"])) if day_first else (int(match["a"]),
                                                                        int(match["b"]))
    if ":" not in match["clock"]:
        return None
    clock = _time_of_day_s(match["clock"].strip())
    clock = clock if clock is not None else (
        _time_of_day_s(match["clock"].strip() + ":00") if match["clock"].count(":") == 1
        else None)  # Excel's 'm/d/yyyy h:mm'
    try:
        date = datetime.datetime(int(match["y"]), month, day)
    except ValueError:
        return None
    return None if clock is None else _epoch_s(date) + clock


def _day_first(raw: list) -> bool:
    """Whether a column's slashed dates put the day first: one of them starts above 12."""
    return any(int(m["a"]) > 12 for m in (_SLASHED.match(str(c).strip()) for c in raw) if m)


def _clock(cell, day_first: bool = False) -> tuple[str, float] | None:
    """A cell holding a time of day (``hh:mm:ss[.fff]``, ``2:05:00 PM``, a workbook's time), a
    duration (a workbook's time delta), a stopwatch reading (``mm:ss.f``) or a date-time (ISO,
    ``dd.mm.yyyy hh:mm:ss``, or slashed ``m/d/yyyy h:mm:ss AM``, ``d/m/yyyy`` with
    ``day_first``), as its kind and seconds; ``None`` for any other cell."""
    if isinstance(cell, datetime.datetime):
        return "date-time", _epoch_s(cell)
    if isinstance(cell, datetime.time):
        return "clock", cell.hour * 3600.0 + cell.minute * 60.0 + cell.second \
            + cell.microsecond / 1e6
    if isinstance(cell, datetime.timedelta):
        return "duration", cell.total_seconds()
    text = _COLON_MILLISECONDS.sub(r"\g<clock>.\g<ms>", str(cell).strip())
    if ":" not in text and not _ISO_BASIC.match(text):
        return None
    of_day = _time_of_day_s(text)
    if of_day is not None:
        return "clock", of_day
    stopwatch = _STOPWATCH.match(text)
    if stopwatch:
        return "stopwatch reading", int(stopwatch["m"]) * 60.0 + float(
            stopwatch["s"].replace(",", "."))
    slashed = _slashed_s(text, day_first)
    if slashed is not None:
        return "date-time", slashed
    text = _YEAR_FIRST_SLASHED.sub(lambda m: f"{m['y']}-{int(m['m']):02d}-{int(m['d']):02d}",
                                   text)
    iso = _ISO_ZONE.sub(lambda m: "+00:00" if m["zone"].upper() in ("UTC", "GMT")
                        else m["zone"], text)
    for parse in (lambda t: datetime.datetime.fromisoformat(iso.replace(",", ".")),
                  lambda t: datetime.datetime.strptime(t, "%d.%m.%Y %H:%M:%S"),
                  lambda t: datetime.datetime.strptime(t, "%d.%m.%Y %H:%M:%S.%f"),
                  # German Excel's date-time as it shows it, saved to CSV so: no seconds
                  lambda t: datetime.datetime.strptime(t, "%d.%m.%Y %H:%M")):
        try:
            return "date-time", _epoch_s(parse(text.replace(",", ".")))
        except ValueError:
            continue
    return None


#: a clock's milliseconds after a third colon, as Keysight's BenchLink Data Logger writes them
#: (``12/6/2026 14:05:00:123``): read as after a decimal mark
_COLON_MILLISECONDS = re.compile(r"(?P<clock>\d{1,2}:\d{2}:\d{2}):(?P<ms>\d{3})$")
#: a date written year first with slashes (2026/12/05 14:05:00.1, as some loggers write
#: it): read as ISO 8601's 2026-12-05
_YEAR_FIRST_SLASHED = re.compile(r"^(?P<y>\d{4})/(?P<m>\d{1,2})/(?P<d>\d{1,2})(?=[ T])")
#: ISO 8601's basic format, without separators (20261206T090000.250Z)
_ISO_BASIC = re.compile(r"^\d{8}T\d{6}")
#: a date-time's zone written after a space, or named (' +01:00', ' Z', ' UTC'): ISO 8601
#: writes it joined
_ISO_ZONE = re.compile(r"(?<=\d)\s+(?P<zone>[+-]\d{2}:?\d{2}|Z|UTC|GMT)$", re.IGNORECASE)


def _epoch_s(moment: datetime.datetime) -> float:
    # naive arithmetic: the machine's time zone and its summer time play no part
    if moment.tzinfo is not None:
        moment = moment.astimezone(datetime.UTC).replace(tzinfo=None)
    return (moment - datetime.datetime(1970, 1, 1)).total_seconds()


def _elapsed_s(table: RawTable, column: Column, raw: list) -> np.ndarray | None:
    """A time column of clock readings or date-times as seconds from its first row (``None``:
    the column holds numbers); ``ValueError`` naming a cell that is neither, or of a kind
    other than the first's."""
    day_first = _day_first(raw)
    if not raw or _clock(raw[0], day_first) is None:
        return None
    kinds = [_clock(cell, day_first) for cell in raw]
    values = np.empty(len(raw))
    for k, (cell, reading) in enumerate(zip(raw, kinds, strict=True)):
        if reading is None or reading[0] != kinds[0][0]:
            raise ValueError(f"{table.where(k, column.index)} (column "
                             f"{column.header!r}): {_shown(cell)} is not a {kinds[0][0]} as "
                             f"the first row's {_shown(raw[0])}: expected one kind of time "
                             "per column")
        values[k] = reading[1]
    if kinds[0][0] == "clock":
        # a time of day restarts at midnight: a step back of more than half a day is the next day
        values += _DAY_S * np.cumsum(np.r_[0.0, np.diff(values) < -_DAY_S / 2])
    elif kinds[0][0] == "stopwatch reading":
        # mm:ss.0 shows the minutes of the hour: a step back of more than half an hour is the
        # next hour
        values += _HOUR_S * np.cumsum(np.r_[0.0, np.diff(values) < -_HOUR_S / 2])
    return values - values[0]


def require_time_order(times: np.ndarray, header: str, where) -> None:
    """``ValueError``, one line, where the time column ``header`` of ``times`` [s] goes back;
    ``where(k)`` names row ``k``'s cell."""
    back = np.flatnonzero(np.diff(times) < 0)
    if back.size:
        k = int(back[0]) + 1
        raise ValueError(backwards_message(where(k), header, times[k - 1] - times[k],
                                           newest_first=back.size == times.size - 1,
                                           swapped=_swapped_rows(times)))


def _swapped_rows(times: np.ndarray) -> int:
    """How many rows are out of place where sorting the times alone mends them: sorted, the
    steps are the log's own (none under half the median step, none over twice it); 0 where
    sorting leaves repeats or gaps (a logger restarted, files joined in the wrong order)."""
    steps = np.diff(np.sort(times))
    typical = float(np.median(steps)) if steps.size else 0.0
    if typical <= 0.0 or steps.min() < 0.5 * typical or steps.max() > 2.0 * typical:
        return 0
    return int(np.count_nonzero(np.argsort(times, kind="stable") != np.arange(times.size)))


def backwards_message(where: str, header: str, jump_s: float,
                      newest_first: bool = False, swapped: int = 0) -> str:
    """The one line of a time column that goes back by ``jump_s`` [s] at ``where`` (a table
    and its cell); an hour back is named as a clock put back (summer time's end), a column
    whose every row goes back (``newest_first``) as a logger's newest-first export, and
    ``swapped`` rows that sorting puts in step as rows out of order."""
    if newest_first:
        return (f"{where} (column {header!r}): every row is earlier than the one above it, the "
                "newest first, as some loggers export: expected the samples oldest first; sort "
                "the file by its time, ascending")
    dst = (" by an hour: a local clock put back at the end of summer time? give the times with "
           "their zone (+02:00, +01:00)" if abs(jump_s - 3600.0) <= 60.0 else
           f" by {jump_s:.4g} s")
    order = (f"; {swapped} rows are out of order, and sorted by time they follow the log's "
             "own step: sort the file by its time, ascending" if swapped else "")
    return (f"{where} (column {header!r}): the time goes backwards{dst}: expected samples in "
            f"time order{order}")


#: a date-time's time zone at its end: ``Z``, ``+01:00``, ``-0500`` or ``UTC``
_ZONE = re.compile(r"(?:\dZ|[+-]\d\d:?\d\d|\bUTC)$", re.IGNORECASE)


def _time_origin(table: RawTable, column: Column) -> tuple[str, float] | None:
    """The kind and moment [s] of a time column's first row where its cells are clock readings
    or date-times (``("date-time", seconds since 1970)``); None for a column of numbers
    counted from any start."""
    raw = [row[column.index] for row in table.rows]
    if not raw:
        return None
    if column.excel_days:
        return "date-time", float(_plain_numbers(raw[:1], table.decimal)[0]) * _DAY_S
    reading = _clock(raw[0], _day_first(raw))
    return reading if reading is not None and reading[0] in ("date-time", "clock") else None


def _own_start(times: np.ndarray, origin) -> bool:
    """Whether a time column counts from its own start: clock readings or date-times (read
    from their first row), or seconds whose first reading is 0 or one sampling interval."""
    if origin is not None:
        return True
    return times.size > 1 and 0.0 <= times[0] <= max(float(np.median(np.diff(times))), 0.0)


def join_by_time(table: RawTable, found: dict[str, Column], other: RawTable,
                 other_found: dict[str, Column], roles: list[str],
                 shift_s: float | None = None) -> tuple[RawTable, dict[str, Column]]:
    """``table`` with the columns of ``roles`` from ``other``, another table of the same
    record, each interpolated linearly at ``table``'s times (in the toolkit's unit), and
    ``found`` with them: the times compared as moments where both are date-times or clock
    readings of one kind, else as read (seconds; clock readings from their first row).
    ``shift_s`` [s] moves ``other``'s times later on ``table``'s clock: where two loggers each
    count from their own start, the seconds ``other``'s started after ``table``'s (required
    then: as read they would be joined as if started together); where both are moments, a
    clock that runs behind the other's. ``table``'s rows outside ``other``'s times are left
    out (nothing extrapolated); ``ValueError`` naming what is missing, a time that goes
    backwards, or tables whose times do not overlap."""
    for where, columns, what in ((table, found, ("time",)), (other, other_found,
                                                               ("time", *roles))):
        absent = [r for r in what if r not in columns]
        if absent:
            named = ", ".join(repr(h) for h in where.header if h) or "no header"
            raise ValueError(f"--join-by-time {other.source.name}: {where.name} has no "
                             f"{' or '.join(absent)} "
                             f"column among {named}: expected a time column in both tables and "
                             f"the {' and '.join(roles)} in {other.name}")
    times = column_values(table, found["time"])
    other_times = column_values(other, other_found["time"])
    column = other_found["time"]
    require_time_order(other_times, column.header,
                       lambda k: f"{other.name}, cell {other.cell(k, column.index)}")
    origins = (_time_origin(table, found["time"]), _time_origin(other, other_found["time"]))
    if None not in origins and origins[0][0] == origins[1][0] == "date-time":
        firsts = [str(t.rows[0][f["time"].index]).strip() if t.rows else ""
                  for t, f in ((table, found), (other, other_found))]
        zoned = [bool(_ZONE.search(first)) for first in firsts]
        if zoned[0] != zoned[1]:  # one read as UTC, the other in its zone: hours apart
            (with_zone, plain) = (0, 1) if zoned[0] else (1, 0)
            names = (table.name, other.name)
            raise ValueError(f"--join-by-time {other.source.name}: {names[with_zone]}'s "
                             f"date-times carry a time zone ({firsts[with_zone]!r}) and "
                             f"{names[plain]}'s none ({firsts[plain]!r}), which is read as "
                             "UTC: expected both with their zone or both without")
    given = (f", {other.name}'s moved {shift_s:+.4g} s (--join-shift)"
             if shift_s is not None else "")
    if None not in origins and origins[0][0] == origins[1][0]:
        shift = origins[1][1] - origins[0][1]  # the other's first row, on this table's clock
        how = (f"as {origins[0][0]}s, {other.name} starting {shift:+.4g} s from {table.name}"
               + given)
    else:  # seconds as written, clock readings from their first row
        if shift_s is None and _own_start(times, origins[0]) and \
                _own_start(other_times, origins[1]):
            raise ValueError(
                f"--join-by-time {other.source.name}: {table.name}'s times and {other.name}'s "
                f"each count seconds from their own start ({times[0]:.4g} s and "
                f"{other_times[0]:.4g} s in their first rows): when one logger started after "
                f"the other is not in the files: expected --join-shift SECONDS, the seconds "
                f"{other.name}'s logger started after {table.name}'s (negative: before; 0: one "
                "trigger started both)")
        shift = 0.0
        how = "their times as read" + (given or ", in seconds")
    shift += shift_s or 0.0
    other_times = other_times + shift
    inside = (times >= other_times[0]) & (times <= other_times[-1])
    if not inside.any():
        raise ValueError(f"--join-by-time {other.source.name}: {table.name}'s times "
                         f"({times[0]:.4g}-{times[-1]:.4g} s) and {other.name}'s "
                         f"({other_times[0]:.4g}-{other_times[-1]:.4g} s, {how}) do not "
                         "overlap: expected two tables of one record")
    kept = np.flatnonzero(inside)
    header, rows = list(table.header), [list(table.rows[k]) for k in kept]
    found = dict(found)
    joined = {}
    for role in roles:
        column = other_found[role]
        values = np.interp(times[kept], other_times, column_values(other, column))
        name = f"{column.header} ({other.source.name})"
        found[role] = Column(role, len(header), name, ROLES[role].unit, given=True)
        header.append(name)
        for row, value in zip(rows, values, strict=True):
            row.append(float(value))
        joined[role] = column.header
    how += f", linearly; {kept.size} of {times.size} rows within its times"
    return replace(table.kept(kept), header=header, rows=rows,
                   joined={"file": other.source.name, "columns": joined, "how": how,
                           "shift_s": shift, "rows_outside": int(times.size - kept.size)}), found


#: what a spreadsheet's summary row under the measurements is called (mean, sum, extremes,
#: spread), in English, German and French: such a row is no step
SUMMARY_WORDS = {"mean", "average", "avg", "sum", "total", "min", "max", "minimum", "maximum",
                 "std", "stdev", "std dev", "standard deviation", "median", "mittelwert",
                 "mittel", "durchschnitt", "summe", "gesamt", "standardabweichung", "stabw",
                 "moyenne", "somme", "écart-type", "ecart-type", "écart type", "médiane",
                 "std abw", "stdabw", "mw", "ø", "moy", "anzahl", "count"}


def _summary_word(cell: str) -> str:
    """A cell as :data:`SUMMARY_WORDS` spells it: lower case, its abbreviating dots and a
    trailing colon dropped (``Std.Abw.``, ``Std. Dev.``, ``Max:``)."""
    return re.sub(r"[\s.]+", " ", cell.strip().rstrip(":").lower()).strip()


def without_summary_rows(table: RawTable) -> RawTable:
    """``table`` without its summary rows (a cell reading ``Mean``, ``Mittelwert``, ``Summe``,
    ``Max``, ... alone: :data:`SUMMARY_WORDS`), which a spreadsheet puts under the measurements
    and which are no measurement; the cell naming each in ``summaries_skipped``. Such a label
    leads its row, or stands where the steps hold numbers (an index, a pressure): after the
    numbers in a column of text, a lab's comments, the word is a comment on its row ('Max'
    beside the top step)."""
    def word(cell) -> bool:
        return isinstance(cell, str) and _summary_word(cell) in SUMMARY_WORDS

    labelled = {k for k, row in enumerate(table.rows) if any(map(word, row))}
    numbered: dict[int, bool] = {}  # a column holding a number in a row of no such word

    def steps_number(column: int) -> bool:
        if column not in numbered:
            numbered[column] = any(_is_number(row[column]) for k, row in enumerate(table.rows)
                                   if k not in labelled and column < len(row))
        return numbered[column]

    named = {}
    for k in sorted(labelled):
        lead = next((j for j, cell in enumerate(table.rows[k]) if str(cell).strip()), None)
        for column, cell in enumerate(table.rows[k]):
            if word(cell) and (column == lead or steps_number(column)):
                named[k] = f"{table.ref(k, column)} ({cell.strip()!r})"
                break
    if not named:
        return table
    keep = [k for k in range(len(table.rows)) if k not in named]
    return replace(table.kept(keep), summaries_skipped=list(named.values()))


#: the most rows under a record's samples that :func:`without_summary_block` reads as their
#: summary (a few rows of means per pressure, or of totals) ...
SUMMARY_BLOCK_MAX_ROWS = 20
#: ... and at most this share of the rows above them
SUMMARY_BLOCK_SHARE = 0.1
#: the rows above such a block whose times give the samples' step
SUMMARY_BLOCK_CONTEXT_ROWS = 200
#: a block whose times step within this share of the samples' median step steps as they do
SUMMARY_BLOCK_STEP_SHARE = 0.1


def without_summary_block(table: RawTable, time: Column) -> RawTable:
    """``table`` without the block of rows under a record's samples that summarises them (a
    few rows of means per pressure, a row of totals, as LabVIEW and Excel exports write them
    under the samples without a header of their own): the rows from a break (a blank row
    above, or other cells filled than in the row above; the last under which ``time`` goes
    back, the rows above it in time order) to the end, no more than
    :data:`SUMMARY_BLOCK_MAX_ROWS` and :data:`SUMMARY_BLOCK_SHARE` of the rows above, whose
    times do not step as the samples' do (step numbers, pressures, a hold's time); their time
    cells and why in ``block_skipped``. ``ValueError`` naming the block
    where its times step as the samples' do: a second record appended under a blank row,
    whose samples are not dropped. A time that goes back anywhere else is left to
    :func:`require_time_order`."""
    rows, numbers = table.rows, table.row_numbers

    def filled(k: int) -> list[bool]:
        return [bool(str(c).strip()) for c in rows[k]]

    # a block of a few rows under many: the breaks in the last rows, a tenth of them at most
    first = max(1, len(rows) - SUMMARY_BLOCK_MAX_ROWS,
                math.ceil(len(rows) / (1.0 + SUMMARY_BLOCK_SHARE)))
    breaks = [k for k in range(first, len(rows))
              if numbers[k] - numbers[k - 1] > 1 or filled(k) != filled(k - 1)]
    if not breaks:
        return table
    above = max(0, breaks[0] - SUMMARY_BLOCK_CONTEXT_ROWS)
    try:  # the samples above and the block, counted from the first of them
        times = column_values(table.kept(range(above, len(rows))), time, optional=True)
    except ValueError:
        return table  # the bad cell is named where the record's time is read

    def summary(k: int) -> bool:  # rows in time order above k, and k on going back
        block, samples = times[k - above:], times[:k - above]
        return samples.size >= 2 and not np.any(np.diff(samples) < 0) and bool(
            block[0] < samples[-1] or np.any(np.diff(block) < 0))

    # the last break under which the block goes back: a pause's samples above it stay
    k = next((k for k in reversed(breaks) if summary(k)), None)
    if k is None:
        return table
    block, samples = times[k - above:], times[:k - above]
    n = len(rows) - k
    header = time.header
    cells = [table.ref(j, time.index) for j in range(k, len(rows))]
    span = cells[0] if n == 1 else f"{cells[0]} to {cells[-1]}"
    apart = ("under a blank row" if numbers[k] - numbers[k - 1] > 1 else
             "its cells filled in other columns than the samples'")
    step_s = float(np.median(np.diff(samples)))
    block_step_s = float(np.median(np.diff(block))) if n > 1 else math.nan
    if abs(block_step_s - step_s) <= SUMMARY_BLOCK_STEP_SHARE * step_s:
        raise ValueError(f"{table.name}, rows {span} ({apart}): their {header!r} goes back "
                         f"to {_shown(rows[k][time.index])} after "
                         f"{_shown(rows[k - 1][time.index])} and steps by {block_step_s:.3g} "
                         "s, as the samples above do: a second record appended to the file? "
                         "expected one record per file; split the file there and import each, "
                         "or delete those rows where they are no samples")
    why = (f"{apart}, {header!r} going back to {_shown(rows[k][time.index])} there"
           + (f" and stepping by {block_step_s:.3g} s" if n > 1 else "")
           + f", where the {k} samples above step by {step_s:.3g} s")
    return replace(table.kept(range(k)), block_skipped={"rows": cells, "span": span,
                                                        "why": why})


#: a spreadsheet's error values, a formula that failed, saved into a CSV as their text: Excel's
#: in English, German and French (#N/A and #NV, a lookup that found nothing: :data:`NO_READING`)
SPREADSHEET_ERRORS = ("#VALUE!", "#DIV/0!", "#REF!", "#NAME?", "#NUM!", "#NULL!", "#SPILL!",
                      "#CALC!", "#N/A", "#WERT!", "#BEZUG!", "#ZAHL!", "#ÜBERLAUF!", "#NV",
                      "#VALEUR!", "#NOMBRE!", "#NOM?", "#NUL!")
_SPREADSHEET_ERROR = re.compile("|".join(map(re.escape, SPREADSHEET_ERRORS)), re.IGNORECASE)
#: a line starting with one, a cell of its own: a row, not a '#' comment
_ERROR_FIRST = re.compile(rf"(?:{_SPREADSHEET_ERROR.pattern})(?=$|[\s;,|])", re.IGNORECASE)
#: what a cell reads where a logger or a spreadsheet has no reading: LabVIEW's NaN for a
#: sample its read lost, a spreadsheet's #N/A (German #NV) for a lookup that found none, a
#: table's n/a or null, a German lab sheet's k.A. (keine Angabe) or n.a.; and a logger's dashes
#: ('-', '---')
NO_READING = ("nan", "#n/a", "#nv", "n/a", "null", "k.a.", "k. a.", "n.a.")
_DASHES = re.compile(r"^-+$")
#: what a logger writes where a channel read beyond its range (OVL, -OVL, OL, Over, Overload,
#: Overrange, or SCPI's number :data:`SCPI_OVERLOAD`): no reading either, and said apart,
#: since the cell or its range was too small
_OVERLOAD = re.compile(r"^[+-]?\s*(?:ovl|ol|over|overload|overrange|over range|overflow)$",
                       re.IGNORECASE)


#: SCPI's overload value (+-9.9E37; 9.91E37 its not-a-number), which Keysight's and other
#: instruments' loggers write as a reading over range: no force or pressure is near it
SCPI_OVERLOAD = 9.9e37


def _overload(cell) -> bool:
    if isinstance(cell, str):
        if _OVERLOAD.match(cell.strip()):
            return True
        try:
            cell = float(cell.strip().replace(",", "."))
        except ValueError:
            return False
    return isinstance(cell, int | float) and not isinstance(cell, bool) and \
        abs(cell) >= SCPI_OVERLOAD


def _no_reading(cell) -> bool:
    text = str(cell).strip()
    return (text == "" or text.lower() in NO_READING or bool(_DASHES.match(text))
            or _overload(text))


def without_blank_rows(table: RawTable, columns: list[Column]) -> RawTable:
    """``table`` without the rows whose cell in one of ``columns`` is blank or reads as
    :data:`NO_READING` (a lab sheet's stray empty cell, a logger's lost sample: that row's
    reading is not known, and no value is made up for it), the first such cell of each in
    ``blanks_skipped`` (with what it reads, where it is not empty), or a logger's overload mark
    (``OVL``: the reading beyond the channel's range), the first in ``overloads_skipped``. A
    workbook cell read empty that holds a formula stays, for :func:`column_values` to name."""
    columns = [p for c in columns for p in c.parts or (c,)]
    marked: dict[int, list[tuple[int, bool]]] = {}  # row -> (column, overload) in their order
    for c in columns:
        raw = [row[c.index] for row in table.rows]
        values = _plain_numbers(raw, table.decimal)  # a column of numbers read at numpy's speed
        rows = (np.flatnonzero(np.abs(values) >= SCPI_OVERLOAD).tolist() if values is not None
                else [k for k, cell in enumerate(raw) if _no_reading(cell)])
        for k in rows:
            marked.setdefault(k, []).append((c.index, _overload(raw[k])))
    blank = {k: next((i for i, over in marks if over), marks[0][0])
             for k, marks in sorted(marked.items())}
    formulas = _formulas(table, [(k, c.index) for k in blank for c in columns])
    skipped = [k for k in blank if not any((k, c.index) in formulas for c in columns)]
    if not skipped:
        return table
    keep = [k for k in range(len(table.rows)) if k not in set(skipped)]

    def named(k: int) -> str:
        text = str(table.rows[k][blank[k]]).strip()
        return table.ref(k, blank[k]) + (f" ({text!r})" if text else "")

    over = [k for k in skipped if _overload(table.rows[k][blank[k]])]
    return replace(table.kept(keep),
                   blanks_skipped=[named(k) for k in skipped if k not in set(over)],
                   overloads_skipped=[named(k) for k in over])


def check_channel_times(table: RawTable, found: dict[str, Column]) -> None:
    """``ValueError`` where a LabVIEW file's x column of a channel (``X_Value`` beside the
    time column, as ``X_Columns Multi`` writes one per channel) reads another time than the
    time column on a row: its channel was sampled at other times, and row by row its readings
    would be paired with the wrong pressures."""
    if "time" not in found:
        return
    time = found["time"].index
    for index, header in enumerate(table.header):
        if header != "X_Value" or index == time:
            continue
        for k, row in enumerate(table.rows):
            x, t = (plain_number(row[i], table.decimal) for i in (index, time))
            if x is not None and t is not None and not math.isclose(x, t, rel_tol=1e-9,
                                                                    abs_tol=1e-9):
                raise ValueError(
                    f"{table.where(k, index)} (column 'X_Value'): "
                    f"{_shown(row[index])} beside {_shown(row[time])} of the time column "
                    f"{found['time'].header!r}: its channel was sampled at other times: "
                    "expected one time per row; save the channels with one x column "
                    "(X_Columns One), or each to a file of its own and join them with "
                    "--join-by-time")


def without_repeated_rows(table: RawTable, columns: list[Column]) -> RawTable:
    """``table`` without the rows that repeat an earlier row in every one of ``columns``, the
    time first (its time and readings: a logger that wrote a sample twice, or rows pasted
    twice, one by one or as a block), each named in ``repeats_skipped`` (``A12``; ``A52 as
    A2`` where the row it repeats is not the one above): counted twice, a sample would halve
    the standard errors of its hold, not add a reading. Where some rows share their time with
    an earlier row but not their readings (a clock coarser than the sampling, whole seconds at
    10 Hz), alike rows may be samples of their own: none is skipped, each named in
    ``times_shared``."""
    indices = [p.index for c in columns for p in c.parts or (c,)]
    rows = table.rows

    def alike(k: int, j: int) -> bool:
        return all(str(rows[k][i]).strip() == str(rows[j][i]).strip() for i in indices)

    first_of_time: dict[str, int] = {}
    same_time, skipped = [], []
    for k, row in enumerate(rows):
        j = first_of_time.setdefault(str(row[indices[0]]).strip(), k)
        if j < k:  # its time read before: by the row above, or a row further up
            same_time.append(k)
            repeated = next((i for i in (k - 1, j) if alike(k, i)), None)
            if repeated is not None:
                skipped.append((k, repeated))
    if len(skipped) < len(same_time):
        return replace(table, times_shared=[table.ref(k, indices[0]) for k in same_time])
    if not skipped:
        return table
    gone = {k for k, _ in skipped}
    keep = [k for k in range(len(rows)) if k not in gone]
    # a repeat of the row above is named alone; one of a row further up, with it
    return replace(table.kept(keep), repeats_skipped=[
        table.ref(k, indices[0]) + ("" if k - j == 1 else f" as {table.ref(j, indices[0])}")
        for k, j in skipped])


def _formula(table: RawTable, k: int, column: int) -> str | None:
    """The formula in a workbook cell read empty: openpyxl reads the value a spreadsheet saved
    with it, and a workbook written by a program other than a spreadsheet has none."""
    return _formulas(table, [(k, column)]).get((k, column))


def _formulas(table: RawTable, cells: list[tuple[int, int]]) -> dict[tuple[int, int], str]:
    """The formulas of those of ``cells`` (data row, column) that hold one, the workbook read
    once; none in a text table."""
    if table.source.suffix.lower() not in WORKBOOK_SUFFIXES or not cells:
        return {}
    import openpyxl

    book = openpyxl.load_workbook(table.source, read_only=True, data_only=False)
    try:
        sheet = book[table.sheet]
        found = {}
        for k, column in cells:
            cell = sheet[table.cell(k, column)]
            if cell.data_type == "f":
                found[k, column] = cell.value
        return found
    finally:
        book.close()


def plain_number(cell, decimal: str) -> float | None:
    """A cell that is a number alone (no unit after it) as a float, read as every column is
    (decimal mark ``decimal``, thousands' marks dropped); None otherwise."""
    number, unit = _number(cell, decimal)
    return number if unit is None else None


def _number(cell, decimal: str) -> tuple[float | None, str | None]:
    """A cell as a number and the unit written after it (``'2,5 bar'`` -> 2.5, ``'bar'``)."""
    if isinstance(cell, bool):
        return None, None
    if isinstance(cell, int | float):
        return float(cell), None
    text = _ungrouped(str(cell).strip())
    if text.lower().lstrip("+-") in ("nan", "inf", "infinity"):
        return float(text), None
    grouped = _GROUPED[decimal].match(text)
    if grouped:  # '1.234,5' (decimal comma) or '1,234.5': the thousands' marks dropped
        text = grouped["number"].replace("," if decimal == "." else ".", "") + grouped["rest"]
    # the longest number first: the shortest would read '1e9' as 1 'e9' ('2 E' is 2 E, though)
    for pattern in _NUMBER_AND_UNIT:
        match = pattern.match(text)
        if match and _NUMBER.match(match.group("number")):
            number, unit = match.group("number"), match.group("unit")
            break
    else:
        return None, None
    if decimal == ",":
        number = number.replace(",", ".")
    try:
        value = float(number)
    except ValueError:
        return None, None
    if unit is not None and parse_unit(unit) is None:
        return None, None
    return value, unit


def _shown(cell) -> str:
    text = repr(cell if isinstance(cell, str) else str(cell))
    return text if len(text) <= 40 else text[:40] + "...'"


def column_text(table: RawTable, column: Column) -> list[str]:
    """The cells of ``column`` as stripped text (numbers without a trailing ``.0``)."""
    out = []
    for row in table.rows:
        cell = row[column.index]
        if isinstance(cell, float) and cell.is_integer():
            cell = int(cell)
        out.append(str(cell).strip())
    return out


def directions(table: RawTable, column: Column) -> list[str]:
    """The direction column as ``up``/``down`` (:data:`DIRECTION_WORDS`); ``ValueError``
    naming the first cell that is neither."""
    out = []
    for k, value in enumerate(column_text(table, column)):
        word = DIRECTION_WORDS.get(value.lower())
        if word is None:
            raise ValueError(f"{table.where(k, column.index)} (column "
                             f"{column.header!r}): {_shown(value)} is not a direction: expected "
                             f"one of {', '.join(DIRECTION_WORDS)}")
        out.append(word)
    return out


def flags(table: RawTable, column: Column) -> np.ndarray:
    """A flag column (1/0, true/false, yes/no) as booleans; ``ValueError`` naming a bad cell."""
    words = {"1": True, "0": False, "true": True, "false": False, "yes": True, "no": False,
             "": False}
    out = np.zeros(len(table.rows), dtype=bool)
    for k, value in enumerate(column_text(table, column)):
        if value.lower() not in words:
            raise ValueError(f"{table.where(k, column.index)} (column "
                             f"{column.header!r}): {_shown(value)} is not a flag: expected 1 or 0")
        out[k] = words[value.lower()]
    return out


@dataclass
class Recognition:
    """What was recognised in one table: for the one-line summary and the provenance."""

    table: RawTable
    columns: dict[str, Column]
    ignored: list[str] = field(default_factory=list)
    #: the header of a time column read as a row counter (:func:`counts_rows`), no clock
    row_counter: str | None = None
    #: the rate its rows were logged at, as the lab states it (:func:`timed_rows`) [Hz]
    sample_rate_hz: float | None = None
    #: who states that rate: ``--sample-rate``, or the file's header (LabChart's
    #: ``Interval=``)
    sample_rate_from: str | None = None
    _values: dict = field(default_factory=dict, repr=False)

    def values(self, role: str, optional: bool = False) -> np.ndarray:
        """:func:`column_values` of the role's column, read once (a table split into many
        runs is read per run)."""
        if (role, optional) not in self._values:
            self._values[role, optional] = column_values(self.table, self.columns[role],
                                                         optional)
        return self._values[role, optional]

    def line(self) -> str:
        """``P_bar -> pressure [bar], F [kgf] -> force [kgf -> N], ...; decimal comma``."""
        parts = []
        for role, column in self.columns.items():
            d = column.describe()
            unit, target = d["unit"], d["converted_to"]
            if unit == "":
                unit = "fraction"
            if column.parts:  # each part in its own unit
                units = [p["unit"] for p in d["sum_of"]]
                unit = " + ".join(units) if len(set(units)) > 1 else units[0]
            shown = (f" [{unit} -> {target}]" if target and unit != target
                     else f" [{unit}]" if unit else "")
            if column.scale:
                shown = f"{shown[:-1]}: {column.scale.shown(target)}]"
            header = " + ".join([repr(p.header) for p in column.parts or (column,)]
                                + ([repr(column.milliseconds[1])] if column.milliseconds
                                   else []))
            parts.append(f"{header} -> {role}{shown}")
        extras = []
        if self.table.decimal == ",":
            extras.append("decimal comma")
        if self.table.title_rows:
            extras.append(f"{self.table.title_rows} title row(s) skipped")
        if footer := self.table.footer_skipped:
            extras.append(f"{len(footer)} row(s) of notes under the table skipped: "
                          + ", ".join(footer[:3]) + (", ..." if len(footer) > 3 else ""))
        if block := self.table.block_skipped:
            extras.append(f"{len(block['rows'])} row(s) under the samples skipped as their "
                          f"summary, no samples: {block['span']} ({block['why']})")
        if summaries := self.table.summaries_skipped:
            extras.append(f"{len(summaries)} summary row(s) skipped: "
                          + ", ".join(summaries[:3]) + (", ..." if len(summaries) > 3 else ""))
        if joined := self.table.joined:
            extras.append(f"{', '.join(map(repr, joined['columns'].values()))} of "
                          f"{joined['file']} joined by time ({joined['how']})")
        if skipped := self.table.blanks_skipped:
            extras.append(f"{len(skipped)} row(s) with a blank cell skipped: "
                          + ", ".join(skipped[:5]) + (", ..." if len(skipped) > 5 else ""))
        if repeats := self.table.repeats_skipped:
            above = ("the row above (its time and readings)"
                     if not any(" as " in r for r in repeats) else
                     "an earlier row (its time and readings: rows pasted twice)")
            extras.append(f"{len(repeats)} row(s) repeating {above} skipped: "
                          + ", ".join(repeats[:5])
                          + (", ..." if len(repeats) > 5 else ""))
        if shared := self.table.times_shared:
            extras.append(f"{len(shared)} row(s) with the time of the row above but other "
                          "readings (a clock coarser than the sampling) kept as samples: "
                          + ", ".join(shared[:5]) + (", ..." if len(shared) > 5 else ""))
        if self.sample_rate_from and self.sample_rate_from != "--sample-rate":
            extras.append(f"rows at {self.sample_rate_hz:g} Hz by {self.sample_rate_from}")
        if over := self.table.overloads_skipped:
            extras.append(f"{len(over)} row(s) with an overload mark skipped: "
                          + ", ".join(over[:5]) + (", ..." if len(over) > 5 else "")
                          + ": the channel read beyond its range there")
        if lvm := self.table.lvm_segments:
            extras.append(f"'Time [s]' from its {lvm['count']} segments' {lvm['starts_from']} "
                          f"and Delta_X {lvm['delta_x']}, {lvm['unlogged_s']:.4g} s between "
                          "them unlogged")
        if wave := self.table.properties.get("waveform"):
            extras.append(f"'Time [s]' from the channels' wf_increment, {wave['wf_increment']:g} "
                          "s")
        if warned := self.table.read_warnings:
            extras.append("the file is damaged or cut short, read as far as it goes (npTDMS: "
                          + "; ".join(warned[:2]) + ("; ..." if len(warned) > 2 else "") + ")")
        return ", ".join(parts) + (f"; {', '.join(extras)}" if extras else "")

    def describe(self) -> dict:
        return {**self.table.describe(),
                "columns": {role: c.describe() for role, c in self.columns.items()},
                "ignored_columns": self.ignored,
                **({"row_counter_column": self.row_counter} if self.row_counter else {}),
                **({"sample_rate_hz": self.sample_rate_hz,
                    "sample_rate_from": self.sample_rate_from} if self.sample_rate_hz else {})}


#: the characters that make a table argument a file-name pattern the toolkit expands itself
#: (the Windows shell passes ``*.csv`` on as typed)
PATTERN_CHARACTERS = "*?["


def _natural_key(path: Path) -> list:
    """A path's sort key, folder by folder, with the numbers in names by value: ``step2``
    before ``step10``."""
    return [[int(part) if part.isdigit() else part.lower() for part in re.split(r"(\d+)", name)]
            for name in path.parts]


def table_files(given: list[str | Path]) -> list[Path]:
    """The files a list of table arguments names: a path as given, a pattern (``*``, ``?``,
    ``[...]``, in its folders too) its matches in name order, numbers by value (``step2``
    before ``step10``); ``ValueError`` for a pattern matching nothing or a file named twice."""
    files: list[Path] = []
    for item in given:
        path = Path(item)
        if path.exists() or not any(c in str(item) for c in PATTERN_CHARACTERS):
            files.append(path)
            continue
        matches = sorted((Path(p) for p in glob.glob(str(item)) if Path(p).is_file()),
                         key=_natural_key)
        if not matches:
            raise ValueError(f"{item}: no file matches this pattern: expected one or more "
                             f"tables ({table_suffixes_text()})")
        files += matches
    seen: set[Path] = set()
    for path in files:
        if path.resolve() in seen:
            raise ValueError(f"{path}: named twice: expected each file of the run once")
        seen.add(path.resolve())
    return files


_DECLARED_NUMBER = r"(?P<value>[-+]?\d+(?:[.,]\d+)?)"
_LENGTH_UNITS = r"mm|cm|m"


def _statement(name: str, units: str | None) -> re.Pattern:
    """A header line's statement of one quantity: its name, its unit in brackets or after an
    underscore (``L0 [mm]: 300``, a TDMS property's ``L0_mm: 300``) or after the value
    (``L0 = 300 mm``); ``units`` None: a value of no unit (an id)."""
    if units is None:
        return re.compile(rf"(?:{name})\s*[:=]?\s*(?P<value>[A-Za-z][\w.-]*?\d[\w.-]*)"
                          r"(?=[\s,;)]|$)", re.IGNORECASE)
    return re.compile(rf"(?:{name})(?:\s*[\[(]\s*(?P<before>{units})\s*[\])]|_(?P<suffix>{units})"
                      rf"\b)?\s*[:=]?\s*{_DECLARED_NUMBER}(?:\s*(?P<after>{units})(?![\w%]))?",
                      re.IGNORECASE)


#: what a file's comment or title lines (or a TDMS file's properties) declare of the muscle,
#: each a pattern whose groups are the value and its unit: a rest length, a held length
#: (``L = 135 mm``, not ``LM8``), an eps (``Contraction: 5 %``; a number without ``%`` a
#: fraction, below 1), the tube's inner diameter and wall, the muscle's id (one holding a
#: digit, ``LM-8``: not ``muscle pressure``); a length without its unit is no statement
DECLARED_STATE = {
    "L0": _statement(r"\bL_?0|\b(?:rest(?:ing)?|initial|nominal|free)\s+length"
                     r"|\bruhel(?:ä|ae)nge|\bausgangsl(?:ä|ae)nge", _LENGTH_UNITS),
    "length": _statement(r"\b(?:held\s+|fixed\s+|clamped\s+)?length|\bl(?:ä|ae)nge"
                         r"|\bL(?:_?held)?(?=\s*[:=])", _LENGTH_UNITS),
    "eps": _statement(r"\beps(?:ilon)?|ε|\bstrain|\bcontraction|\bkontraktion", "%"),
    "D0": _statement(r"\bD_?0|\b(?:inner|inside|internal)\s+diameter|\binnendurchmesser",
                     _LENGTH_UNITS),
    "t0": _statement(r"\bt_?0|\bwall\s+thickness|\bwandst(?:ä|ae)rke", _LENGTH_UNITS),
    "muscle": _statement(r"\b(?:muscle|muskel)(?:\s+id)?", None),
}
_TO_MM = {"mm": 1.0, "cm": 10.0, "m": 1000.0}


@dataclass(frozen=True)
class Stated:
    """One quantity a file's header declares (:func:`declared_state`)."""

    value: object  # mm, a fraction, or the id
    text: str  # as written: 'Contraction: 5 %'
    at: int | str  # its line, or where else in the file (a TDMS property)
    #: half a unit of its last digit as written, in ``value``'s unit: 'L0 = 300 mm' holds any
    #: length within 0.5 mm of 300
    half_step: float = 0.0

    @property
    def where(self) -> str:
        return f"line {self.at}" if isinstance(self.at, int) else str(self.at)

    def agrees(self, value: float) -> bool:
        """Whether ``value`` rounds to this one as written (or lies within 1e-9 of it: a TDMS
        property's float)."""
        return abs(value - float(self.value)) <= max(self.half_step,
                                                     1e-9 * abs(float(self.value)), 1e-12)


def declared_state(preamble: list[tuple[int | str, str]]) -> dict[str, Stated]:
    """What a file's lines above its header declare of the muscle's state
    (:data:`DECLARED_STATE`): role -> :class:`Stated`, each role's first."""
    found: dict[str, Stated] = {}
    for at, line in preamble:
        taken: list[tuple[int, int]] = []
        for role, pattern in DECLARED_STATE.items():
            for match in pattern.finditer(line):
                if role in found or any(a < match.end() and match.start() < b
                                        for a, b in taken):
                    continue  # a rest length is no held length
                text = match.group("value")
                if role == "muscle":
                    found[role] = Stated(text, match.group(0).strip(), at)
                    taken.append(match.span())
                    continue
                unit = next((u for u in (match.group(g) for g in ("before", "suffix", "after"))
                             if u), None)
                value = float(text.replace(",", "."))
                digits = len(re.split(r"[.,]", text)[1]) if re.search(r"[.,]", text) else 0
                half = 0.5 * 10.0 ** -digits
                if role == "eps":
                    scale = 0.01 if unit else 1.0
                    if not 0 <= value * scale < 1:
                        continue  # '5' of no unit: a percentage or a fraction, not guessed
                elif unit is None:
                    continue
                else:
                    scale = _TO_MM[unit.lower()]
                taken.append(match.span())
                found[role] = Stated(value * scale, match.group(0).strip(), at, half * scale)
    return found


def _tdms_statements(properties: dict, channels: list) -> list[tuple[str, str]]:
    """A TDMS group's file, group and channel properties as header lines
    (:func:`declared_state`), each ``name: value`` and where it is: NI's way to store what a
    lab writes above a table's header."""
    owners = [("the file", properties.get("file", {})), (None, properties.get("group", {})),
              *((f"channel {name!r}", props) for name, props, *_ in channels)]
    lines = []
    for owner, props in owners:
        for key, value in props.items():
            if isinstance(value, float):
                value = f"{value:.15g}"
            lines.append((f"the property {key!r} of {owner or 'its group'}", f"{key}: {value}"))
    return lines


def _check_declared_states(read: list[tuple[Path, RawTable, dict]]) -> None:
    """``ValueError`` where two files' headers declare different muscle states (a held length,
    a rest length, an eps, a tube or a muscle id): one run of one state cannot hold both."""
    declared = [(path.name, declared_state(table.preamble)) for path, table, _ in read]
    for role in DECLARED_STATE:
        said = [(name, state[role]) for name, state in declared if role in state]
        for name, stated in said[1:]:
            first, stated0 = said[0]
            same = (stated.value == stated0.value if role == "muscle" else
                    math.isclose(stated.value, stated0.value, rel_tol=1e-6, abs_tol=1e-9))
            if not same:
                what = ("import each muscle's files as a run of its own, with its --id"
                        if role in ("muscle", "D0", "t0") else "import each state's files as "
                        "a run of its own, with its --eps" + (" and --L0" if role == "L0"
                                                              else ""))
                raise ValueError(f"{name}: its header declares {stated.text!r} "
                                 f"({stated.where}), {first}'s {stated0.text!r} "
                                 f"({stated0.where}): two muscle states, which one run cannot "
                                 "hold: expected the files of one muscle at one length; "
                                 f"{what}")


#: a time column whose first reading is this far from 0 s (Unix time, seconds since 1970) is
#: counted from its first row: a run folder's times stay within its cells' bound
#: (:data:`mkm.bench.storage.MAX_CELL_MAGNITUDE`) and keep their milliseconds in 10 digits
CLOCK_ORIGIN_S = 1e6
#: such a first reading is said as the moment it is in Unix time between these [s] (2001 and
#: 2100)
UNIX_TIME_S = (1e9, 4.1e9)


@dataclass
class JoinedFiles:
    """Several files of one record read as one table (:func:`join_files`)."""

    table: RawTable
    found: dict[str, Column]
    #: each file in the order joined: its name, SHA-256, rows, clock span as read [s] and
    #: where on the joined clock its first row lies [s]
    files: list[dict]
    #: ``continues`` (the files ordered by their shared clock) or ``restarts`` (in the order
    #: given, one after another)
    clock: str
    #: how they were joined, in words
    note: str
    #: the first reading of a continuing clock far from 0 s (:data:`CLOCK_ORIGIN_S`: Unix
    #: time), from which the joined times count; None for any other clock
    origin_s: float | None = None


def _file_clock(table: RawTable, found: dict[str, Column]):
    """A file's times [s] as read and, for clock readings or date-times, the moment [s] of its
    first row (None: seconds counted from any start)."""
    times = column_values(table, found["time"])
    require_time_order(times, found["time"].header,
                       lambda k: table.where(k, found["time"].index))
    origin = _time_origin(table, found["time"])
    return times, (origin[1] if origin else None)


def join_files(paths: list[Path], columns=None, units=None, scaling=None,
               between_files_s: float | None = None) -> JoinedFiles:
    """One table of the files ``paths``, each one table with a time column, logged as one
    record (one file per pressure step): the same columns in the same units in each, their
    rows one after another.

    Where the clock continues from file to file (their spans do not overlap: seconds of one
    clock, or clock readings and date-times), the files are ordered by it and keep its times,
    the time between files as logged. Where each file's clock restarts (seconds from 0 or one
    sample in), they are joined in the order given, each file's first row placed
    ``between_files_s`` after the last row of the one before (default: one sample interval of
    that file, the step taken as the file begins, so each hold's creep is timed from its
    file's start). ``ValueError`` in one line for what cannot be one record: a file of other
    columns or units, or of another muscle; clocks that overlap without each restarting; a
    time that goes back within a file; ``between_files_s`` for a clock that continues."""
    if between_files_s is not None and not (math.isfinite(between_files_s)
                                            and between_files_s > 0):
        raise ValueError(f"--between-files {between_files_s:g} s: expected the time from one "
                         "file's last sample to the next one's first, above 0 s")
    read = []
    for path in paths:
        tables = read_tables(path)
        if len(tables) != 1:
            raise ValueError(f"{path.name}: {len(tables)} {tables[0].part}s: expected one table "
                             "in each file of a record logged as several files")
        table, found = with_milliseconds(tables[0], recognise(tables[0], columns, units,
                                                              scaling))
        if "time" not in found or counts_rows(table, found["time"]):
            raise ValueError(f"{path.name}: no time column: expected one in each of the "
                             f"{len(paths)} files, to order them and keep the time between "
                             "them; import a file without one alone")
        table = without_summary_block(table, found["time"])
        for role in ("pressure", "force"):  # a bad cell named in its own file
            if role in found:
                column_values(table, found[role])
        read.append((path, table, found))
    pressures = [column_values(table, found["pressure"]) if "pressure" in found else None
                 for _, table, found in read]
    first_path, first, first_found = read[0]
    shape = {r: (c.header, c.describe()["unit"]) for r, c in first_found.items()}
    for path, _table, found in read[1:]:
        other = {r: (c.header, c.describe()["unit"]) for r, c in found.items()}
        for role in dict.fromkeys([*shape, *other]):
            if shape.get(role) != other.get(role):
                said = [f"{name}: " + (f"{v[0]!r} [{v[1]}]" if v else "none")
                        for name, v in ((first_path.name, shape.get(role)),
                                        (path.name, other.get(role)))]
                raise ValueError(f"{path.name}: its {role} column differs from the first "
                                 f"file's ({'; '.join(said)}): expected the same columns in "
                                 "the same units in every file of one run")
    if "muscle" in first_found:
        named = {p.name: sorted(set(column_text(t, f["muscle"]))) for p, t, f in read}
        first_named = named[first_path.name]
        for name, muscles in named.items():
            if muscles != first_named:
                raise ValueError(f"{name}: muscle {', '.join(map(repr, muscles))} in column "
                                 f"{first_found['muscle'].header!r}, {first_path.name}: "
                                 f"{', '.join(map(repr, first_named))}: expected the files of "
                                 "one muscle's run")
    _check_declared_states(read)
    clocks = []
    for path, table, found in read:
        if not table.rows:
            raise ValueError(f"{path.name} has no row to import")
        times, origin = _file_clock(table, found)
        clocks.append((times, origin))
    start = [(origin or 0.0) + times[0] for times, origin in clocks]
    end = [(origin or 0.0) + times[-1] for times, origin in clocks]
    by_clock = sorted(range(len(read)), key=lambda k: start[k])
    overlap = next(((a, b) for a, b in itertools.pairwise(by_clock) if start[b] <= end[a]),
                   None)
    origin_s = None
    if overlap is None:
        if between_files_s is not None:
            raise ValueError(f"--between-files {between_files_s:g} s: the files' clock "
                             "continues from one to the next, its times give the time between "
                             "them: expected the option only for files whose clocks each "
                             "restart")
        order, clock = by_clock, "continues"
        placed = [start[k] - start[by_clock[0]] for k in order]
        if all(origin is None for _, origin in clocks) and \
                abs(start[by_clock[0]]) >= CLOCK_ORIGIN_S:
            origin_s = start[by_clock[0]]
        shift = [(clocks[k][1] or 0.0) - start[by_clock[0]] for k in order]
    elif all(origin is None and _own_start(times, None) for times, origin in clocks):
        order, clock = list(range(len(read))), "restarts"
        placed, shift = [], []
        for k in order:
            times, at = clocks[k][0], 0.0
            if k:
                before = clocks[k - 1][0]
                gap = between_files_s if between_files_s is not None else (
                    float(np.median(np.diff(before))) if before.size > 1 else 0.0)
                at = placed[-1] + before[-1] - before[0] + gap
            placed.append(at)
            shift.append(at - times[0])
    else:
        a, b = overlap
        raise ValueError(f"{read[b][0].name}: its clock ({_span(start[b], end[b], clocks[b][1])}) "
                         f"overlaps {read[a][0].name}'s ({_span(start[a], end[a], clocks[a][1])}), "
                         "and not every file's clock starts at 0: expected the files of one "
                         "run, one after another on one clock or each counting from its own "
                         "start")
    rows, numbers, row_files, files = [], [], [], []
    index = first_found["time"].index
    for j, k in enumerate(order):
        path, table, found = read[k]
        times = clocks[k][0]
        joined_s = times + shift[j]
        if origin_s is not None:  # to the microsecond, a float's digits at Unix time
            joined_s = np.round(joined_s, 6)
        elif clock == "restarts":
            # each file placed by a sum of its times and the intervals before it: rounded to the
            # times a clock that went on would have logged (49.199999999999996 s is 49.2 s),
            # else the settle test's once-a-second check, due at 49.2 s, passes that sample by
            joined_s = np.round(joined_s, JOIN_TIME_DECIMALS)
        for row, t in zip(table.rows, joined_s, strict=True):
            row = list(row)
            row[index] = float(t)
            rows.append(row)
        numbers += table.row_numbers
        row_files += [path.name] * len(table.rows)
        files.append({"file": path.name, "sha256": file_sha256(path), "rows": len(table.rows),
                      **_file_span(times, origin_s), "placed_at_s": float(placed[j])})
    names = [f["file"] for f in files]
    gaps = [placed[j + 1] - (placed[j] + clocks[order[j]][0][-1] - clocks[order[j]][0][0])
            for j in range(len(order) - 1)]
    if origin_s is not None:
        gaps = [round(g, 6) for g in gaps]
    # the level a hold keeps across each join (a logger rolling its file mid-hold), or None
    held = [_held_across(pressures[a], pressures[b]) for a, b in itertools.pairwise(order)]
    for j, (gap, level) in enumerate(zip(gaps, held, strict=True), start=1):
        files[j]["join"] = {"gap_s": float(gap), "within_hold_bar": level}
    within = [j for j, level in enumerate(held) if level is not None]
    if clock == "continues":
        # a join a few samples late within a hold: the samples the logger lost, named
        lost = [j for j in range(len(gaps))
                if gaps[j] > JOIN_LATE_INTERVALS * _interval_s(clocks[order[j]][0])]
        note = (f"{len(files)} files joined on their clock, which continues from one to the "
                f"next: ordered by it, {names[0]} first, the time between files as logged "
                f"({min(gaps):.3g}-{max(gaps):.3g} s)"
                + "".join(f"; {names[j + 1]} begins {gaps[j]:.3g} s after {names[j]}'s last "
                          "sample" + (f", within the hold at {held[j]:.3g} bar: that much of "
                                      "it not logged" if held[j] is not None else "")
                          for j in lost[:JOIN_GAPS_SAID])
                + (f" (and {len(lost) - JOIN_GAPS_SAID} more such gaps)"
                   if len(lost) > JOIN_GAPS_SAID else "")
                + (f"; {len(within) - len(set(within) & set(lost))} join(s) within a hold, "
                   "the clock on by one sample: one hold" if set(within) - set(lost) else ""))
    else:
        steps = len(within) < len(held)
        note = (f"{len(files)} files joined in the order given ({names[0]} first), each "
                "file's clock restarting at its start: "
                + (f"each placed {between_files_s:g} s (--between-files) after the one before"
                   if between_files_s is not None else
                   "the time between them unknown, each placed one sample after the one "
                   "before" + (", its step taken as the file begins: each hold's creep timed "
                               "from its file's start" if steps else "")
                   + "; --between-files SECONDS gives the time from one file's last sample to "
                   "the next one's first")
                + (f"; {len(within)} of the {len(held)} joins within a hold (the pressure at "
                   "one level across each, as a logger that rolls its file every few minutes "
                   f"writes it: {', '.join(names[j + 1] for j in within[:JOIN_GAPS_SAID])}"
                   + (", ..." if len(within) > JOIN_GAPS_SAID else "")
                   + "), each joined as one hold"
                   + (f", the {between_files_s:g} s of --between-files put into it"
                      if between_files_s is not None else
                      ", any time lost between the files unknown") if within else ""))
    source = first_path.with_name(f"{first_path.name} and {len(files) - 1} more")
    # every file's header lines, each named with its file (they agree: checked above)
    preamble = [(f"{path.name}, " + (f"line {at}" if isinstance(at, int) else str(at)), line)
                for path, table, _ in read for at, line in table.preamble]
    blocks = [(path.name, table.block_skipped) for path, table, _ in read
              if table.block_skipped]
    block = {"rows": [f"{name} {cell}" for name, b in blocks for cell in b["rows"]],
             "span": ", ".join(f"{name} {b['span']}" for name, b in blocks),
             "why": "; ".join(f"{name}: {b['why']}" for name, b in blocks)} if blocks else {}
    table = replace(first, source=source, rows=rows, row_numbers=numbers, row_files=row_files,
                    preamble=preamble, block_skipped=block)
    found = {**first_found, "time": Column("time", index, first_found["time"].header, "s")}
    return JoinedFiles(table, found, files, clock, note, origin_s)


def _file_span(times: np.ndarray, origin_s: float | None) -> dict:
    """A joined file's first and last time as read, or counted from ``origin_s`` (the joined
    clock's first reading, :attr:`JoinedFiles.origin_s`) to the microsecond, a float's digits
    at Unix time's 1.8e9 s, with its first reading's moment where that is Unix time."""
    if origin_s is None:
        return {"clock_as_read_s": [float(times[0]), float(times[-1])]}
    span = {"clock_s": [round(float(t) - origin_s, 6) for t in (times[0], times[-1])]}
    if UNIX_TIME_S[0] <= times[0] <= UNIX_TIME_S[1]:
        span["first_row_utc"] = datetime.datetime.fromtimestamp(
            float(times[0]), datetime.UTC).isoformat(timespec="milliseconds")
    return span


#: the samples at each side of a join whose pressures judge whether it falls within a hold
JOIN_SAMPLES = 5
#: a join of a continuing clock later than this many sampling intervals is said: samples lost
JOIN_LATE_INTERVALS = 2.0
#: the joins named in the note (the others counted)
JOIN_GAPS_SAID = 3
#: the decimals [s] of the times of files whose clocks restart, placed one after another (a
#: nanosecond: below any logger's resolution, above the sums' rounding error)
JOIN_TIME_DECIMALS = 9


def _interval_s(times: np.ndarray) -> float:
    """A file's sampling interval [s]: its times' median step (0 for one sample)."""
    return float(np.median(np.diff(times))) if times.size > 1 else 0.0


def _held_across(before: np.ndarray | None, after: np.ndarray | None) -> float | None:
    """The pressure [bar] a hold keeps across the join of two files (``before``'s pressures,
    then ``after``'s): the last and the first :data:`JOIN_SAMPLES` readings each within a
    staircase's plateau band (:data:`mkm.bench.series.PLATEAU_TOLERANCE_BAR`) of their median,
    the two medians within it of each other (a logger that rolled its file mid-hold); None
    where the pressure steps at the join (a file per step) or moves (a ramp), or a file has too
    few readings."""
    if before is None or after is None:
        return None
    last, first = before[np.isfinite(before)][-JOIN_SAMPLES:], \
        after[np.isfinite(after)][:JOIN_SAMPLES]
    if last.size < JOIN_SAMPLES or first.size < JOIN_SAMPLES:
        return None
    a, b = float(np.median(last)), float(np.median(first))
    if (np.max(np.abs(last - a)) > PLATEAU_TOLERANCE_BAR or np.max(np.abs(first - b))
            > PLATEAU_TOLERANCE_BAR or abs(a - b) > PLATEAU_TOLERANCE_BAR):
        return None
    return round((a + b) / 2, 6)


def _span(first_s: float, last_s: float, origin) -> str:
    if origin is None:
        return f"{first_s:g}-{last_s:g} s"
    moment = datetime.datetime(1970, 1, 1) + datetime.timedelta(seconds=first_s)
    shown = moment.isoformat(sep=" ") if first_s >= _DAY_S else moment.time().isoformat()
    return f"from {shown}, {last_s - first_s:g} s"
