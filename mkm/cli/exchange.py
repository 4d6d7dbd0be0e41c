"""``mkm import`` and ``mkm export``: measurements in from a table, runs out to a spreadsheet.

Argument parsing only: :mod:`mkm.bench.exchange` does the work.
"""

from __future__ import annotations

import argparse

from mkm.cli.common import (
    add_progress_argument,
    argtype,
    derived_help,
    next_commands,
    parse_within,
    say,
    shared_help,
)
from mkm.core.ranges import parse_fraction, parse_number
from mkm.core.records import EXPORT_FORMATS

IMPORT_EXAMPLE = ("examples: mkm import lab.csv --id lab-muscle-7 --D0 30 --t0 3 --L0 282 "
                  "--eps 12.2%   (header 'Pressure (kPa);Force (N)' read and converted); "
                  "mkm import forcemaps.csv --id dmsp-20 --D0 20 --t0 1.8 --muscle "
                  "\"Festo DMSP-20-300\"   (one run per length)")
EXPORT_EXAMPLE = "example: mkm export mkm-out/demo/runs/<run> --format xlsx --out run.xlsx"

#: when the muscle's id and size are needed: only mkm export's workbook records them
EXPORTED = "required unless the table is a workbook written by mkm export, which holds it"
#: ... and its size and state, which a file's header may declare
DECLARED_ABOVE = (f"{EXPORTED}, or the file declares it above its header (L0 = 300 mm, "
                  "Contraction: 5 %%) or in a TDMS property; one that contradicts the file is "
                  "refused")
#: the braid angle and rubber a lab declares: recorded with each run
DECLARED = ("as the lab declares it, recorded with each run: mkm identify's nominal muscle{} "
            "and the report's prediction; default: none declared, the models' calibrated one")
#: what the rubber's two constants declared together also are
RUBBER_RATIO = " (with the other constant: the ratio it assumes where it fits the rubber)"


def register(subparsers) -> None:
    imp = subparsers.add_parser(
        "import", help="a table of forces measured elsewhere (CSV, TSV, Excel or NI TDMS) as "
        "run folders",
        description="Read the table a lab has (CSV, TSV or semicolon CSV with decimal commas, "
        "every sheet of an .xlsx workbook or every group of an NI .tdms file; a title row above "
        "the header is skipped) and "
        "write one run folder per muscle state (a sheet, or a value of an eps, length, L0 or "
        "run column), status 'imported', that report, calibrate, identify and export read. "
        "Columns are recognised by name and unit (P, Pressure (bar), pressure [kPa], p_psi, "
        "Force (N), F [kgf], load_lbf, t (s), direction, eps, contraction (%), length (mm)) "
        "and converted with pint; what was recognised is printed and recorded in run.json. A "
        "table with a time column (seconds, hh:mm:ss.fff, mm:ss.f or date-times, counted from "
        "its first row) is a time series: stored as samples, its steps the plateaus of a "
        "staircase or quasi-static bins of a ramp (rising and falling apart).",
        epilog=IMPORT_EXAMPLE)
    imp.add_argument("table", nargs="+", action=derived_help(_table_help))
    imp.add_argument("--id", help=f"the muscle's id, naming the run folders ({EXPORTED})")
    imp.add_argument("--D0", type=argtype(parse_number, "--D0", "mm"),
                     help=shared_help("--D0", DECLARED_ABOVE))
    imp.add_argument("--t0", type=argtype(parse_number, "--t0", "mm"),
                     help=shared_help("--t0", DECLARED_ABOVE))
    imp.add_argument("--L0", type=argtype(parse_number, "--L0", "mm"),
                     help=shared_help("--L0", "default: the table's L0 column; without one, "
                                      f"{DECLARED_ABOVE}"))
    imp.add_argument("--eps", type=argtype(parse_fraction),
                     help=shared_help("--eps", "default: the table's eps or length column; "
                                      f"without either, {DECLARED_ABOVE}"))
    for option, name, unit in (("--theta0", "theta0_deg", "DEG"), ("--C10", "C10_MPa", "MPA"),
                               ("--C01", "C01_MPa", "MPA")):
        imp.add_argument(option, dest=name, metavar=unit,
                         type=argtype(parse_within, option, name),
                         help=shared_help(option, DECLARED.format(
                             "" if option == "--theta0" else RUBBER_RATIO)))
    imp.add_argument("--columns", default=None, metavar="ROLE=COLUMN,...",
                     help="which column holds what, where the names do not say: pressure=..., "
                     "force=..., time=..., direction=..., eps=..., length=..., run=...; "
                     "force=A+B adds two load cells' columns (cells in parallel share the "
                     "pull), each in its own unit")
    imp.add_argument("--units", default=None, metavar="ROLE=UNIT,...",
                     help="the unit of a column whose header names none or the wrong one, "
                     "e.g. pressure=kPa,force=lbf (default: bar, N, s, mm, a fraction; a "
                     "time column of row numbers, 1, 2, 3, ..., without a unit is no clock "
                     "unless time=s says it is seconds)")
    imp.add_argument("--sensitivity", default=None, metavar="ROLE=PER_VOLT,...",
                     help="how a channel logged in volts (V or mV) becomes a force or a "
                     "pressure, as the bench's [loadcell] sensitivity_N_per_V: the quantity per "
                     "volt, e.g. force=200N/V (a load-cell amplifier), pressure=2.5bar/V (a "
                     "0.5-4.5 V transducer of 0-10 bar); a bare number is N/V or bar/V; "
                     "load cells summed (--columns force=A+B) each their own in its order, "
                     "force=200N/V+250N/V, or one for all "
                     "(default: none; a column in volts without it is refused)")
    imp.add_argument("--offset-volts", default=None, metavar="ROLE=VOLTS,...",
                     help="what a channel scaled by --sensitivity reads unloaded or at 0 bar, "
                     "subtracted before scaling, as [loadcell] offset_V: e.g. force=0.012, "
                     "pressure=0.5V; summed load cells each theirs, force=10mV+20mV "
                     "(default: 0 V)")
    imp.add_argument("--current-range", default=None, metavar="ROLE=LOW:HIGH,...",
                     action=derived_help(_current_range_help))
    imp.add_argument("--sample-rate", type=argtype(_sample_rate), default=None, metavar="HZ",
                     help="the rate the table's rows were logged at, for a table without a "
                     "time column (or whose time column counts the rows, 1, 2, 3, ...): row k "
                     "at k/HZ seconds, read as a time series, e.g. 100 or 1kHz; recorded in "
                     "run.json (default: none; the rows of a record without time are taken as "
                     "evenly spaced, untimed)")
    imp.add_argument("--sheet", "--group", default=None, metavar="NAME",
                     help="the workbook's sheet, or the TDMS file's group (default: every "
                     "sheet or group with a pressure and a force column, one run each)")
    imp.add_argument("--muscle", default=None, metavar="NAME",
                     help="the muscle to import where the table's muscle column holds several")
    imp.add_argument("--tare", default="auto", metavar="auto|none|linear|N",
                     help="the force's zero: a time series' mean force before its pressure "
                     "rises (or over the vented rest that ends it, where the logging began as "
                     "the pressure rose), a step table's force at the lowest pressure of its "
                     "rising branch (auto, the default; only when that pressure is 0 bar, else "
                     "at the 0 bar rows that end a sweep), none, linear (a time series' "
                     "zero taken at its rests before the rise and after the closing vent, "
                     "joined by a line in time: a load cell that drifted), or a value [N] (or "
                     "with its unit: 0.2kgf)")
    imp.add_argument("--vented", default="auto", metavar="auto|none|BAR",
                     help="what the pressure reads vented, subtracted from a time series (or a "
                     "record without its time): "
                     "detected at its start (auto, the default: up to a sensor's zero error; a "
                     "record held higher is kept, pressurised; one, or a step table, at an "
                     "atmosphere, 0.6-1.1 bar, at its start and its end is refused: an absolute "
                     "sensor's or not, this option says), none, or a value [bar] (or with its "
                     "unit: 1013mbar; subtracted from a step table's pressures too)")
    imp.add_argument("--force-sign", type=int, default=1, metavar="SIGN",
                     action=derived_help(_force_sign_help))
    imp.add_argument("--one-step-per-row", action=derived_help(_one_step_per_row_help,
                                                               argparse._StoreTrueAction))
    imp.add_argument("--join-by-time", default=None, metavar="FILE",
                     help="another table of the same record holding what the table lacks (the "
                     "force, or the pressure), with its own time column: its values "
                     "interpolated linearly at the table's times, compared as moments where "
                     "both times are date-times or clock readings, else as read (seconds); "
                     "the table's rows outside its times are left out")
    imp.add_argument("--join-shift", type=argtype(parse_number, "--join-shift", "s"),
                     default=None, metavar="SECONDS",
                     help="the seconds the --join-by-time file's times are moved later on the "
                     "table's clock: where each logger counts seconds from its own start (no "
                     "date-times), when the file's started after the table's (required then; "
                     "negative: before, 0: one trigger started both); where both hold "
                     "date-times or clock readings, how far its clock runs behind the "
                     "table's (default: none)")
    imp.add_argument("--between-files", type=argtype(parse_number, "--between-files", "s"),
                     default=None, metavar="SECONDS",
                     help="several files whose clocks each restart: the time from one file's "
                     "last sample to the next one's first, e.g. 10s (the settling not logged); "
                     "default: one sample interval, each hold's creep timed from its file's "
                     "start")
    imp.add_argument("--accuracy", default=None, metavar="QUANTITY=BOUND,...",
                     help="the +- bound each force and pressure value keeps (the load cell's "
                     "and the sensor's data sheet, or the table's stated accuracy): a value "
                     "with its unit, a percentage of the value, or their sum, e.g. "
                     "force=0.5N+0.2%%,pressure=0.01bar; each step then carries its "
                     "uncertainty, so mkm report scores E_n and mkm identify judges its fit "
                     "(default: none declared, neither can)")
    imp.add_argument("--tolerance", type=argtype(_tolerances), default=None,
                     metavar="D0=MM,t0=MM[,...]",
                     help="+- tolerances the muscle was made to (D0, t0, L0 [mm], eps, theta0 "
                     "[deg], rubber [%% of C10 and C01]), e.g. D0=0.1,t0=0.05, recorded with "
                     "each run as a bench configuration's [muscle.tolerances]: mkm identify "
                     "draws the tube's into its intervals, mkm report each into its band "
                     "(default: those of [muscle.tolerances], D0 0.3 mm, t0 0.1 mm, L0 1 mm, "
                     "eps 0.004, theta0 1 deg, for any name not given)")
    imp.add_argument("--out", default=None,
                     help="folder to put the run folders in (default: mkm-out/runs)")
    add_progress_argument(imp)
    imp.set_defaults(func=_import)

    exp = subparsers.add_parser(
        "export", help="a run folder as one Excel workbook or three CSV files",
        description="Write a run's steps, samples and metadata (run.json flattened to key, "
        "value) as one .xlsx workbook with three sheets, or as steps.csv, samples.csv and "
        "metadata.csv in a folder; text cells are spreadsheet-safe. mkm import reads the "
        "workbook back. A run imported from a record without time carries the table it came "
        "from: the file as given beside the CSV files (imported_table.csv, its own suffix), "
        "or the workbook's sheet "
        "imported_table as read (mkm import --sheet imported_table reads it again).",
        epilog=EXPORT_EXAMPLE)
    exp.add_argument("run", help="the run folder")
    exp.add_argument("--format", default="xlsx", choices=tuple(EXPORT_FORMATS),
                     help="; ".join(f"{name}: {what}" for name, what in EXPORT_FORMATS.items())
                     + " (default: xlsx)")
    exp.add_argument("--out", default=None,
                     help="the workbook (xlsx) or folder (csv), new or one mkm export wrote "
                     "(nothing else is overwritten); default: mkm-out/export/<run>")
    exp.set_defaults(func=_export)


def _tolerances(text: str):
    from mkm.fem.tolerances import Tolerances  # when given

    return Tolerances.parse(text, Tolerances())


def _sample_rate(text: str) -> float:
    from mkm.bench.exchange import check_sample_rate

    return check_sample_rate(parse_number(text, "--sample-rate", "Hz"))


def _force_sign_help() -> str:
    from mkm.bench.exchange import FORCE_SIGNS

    return (f"{' or '.join(map(str, FORCE_SIGNS))}: -1 negates the table's forces, for a load "
            "cell that reads the muscle's pull negative (a --tare given is as the table reads "
            "it; default: 1, as read)")


def _current_range_help() -> str:
    from mkm.bench.tables import LOOP_MA, LOOP_WORKING_MA

    low, high = LOOP_MA
    return (f"how a {low:g}-{high:g} mA current-loop channel (logged in mA) becomes a pressure "
            f"or a force: the transmitter's range, its reading at {low:g} mA and at {high:g} "
            "mA, linear between, e.g. pressure=0:10bar, force=0:500N; a bare number is bar or "
            f"N; a current outside {LOOP_WORKING_MA[0]:g}-{LOOP_WORKING_MA[1]:g} mA (a broken "
            "loop) is refused (default: none; a column in mA without it is refused)")


def _one_step_per_row_help() -> str:
    from mkm.bench.series import PLATEAU_TOLERANCE_BAR, RECORD_MIN_ROWS

    return ("every row of the table a held pressure, one step each (at its time where there "
            f"is a time column): without it, more than {RECORD_MIN_ROWS} rows whose successive "
            f"pressures lie within {PLATEAU_TOLERANCE_BAR:g} bar are read as a record without "
            "its time (a staircase's plateaus or a ramp's bins), and a time column with "
            "several readings per hold as a time series")


def _table_help() -> str:
    from mkm.bench.tables import table_suffixes_text

    return (f"the table file: {table_suffixes_text()} (LabVIEW's .lvm and a logger's .xls "
            "read as text; .tdms: NI's TDMS file, its channels the columns); several files, or "
            "a pattern in quotes (\"L135/*.csv\", expanded by mkm, its files in name order, "
            "step2 before step10): one record logged a file per pressure step, each with a "
            "time column, imported as one run: ordered by their clock where it continues "
            "from file to file, else in the order given, each file's clock restarting "
            "(--between-files); every file's SHA-256 in run.json")


def _import(args) -> int:
    from mkm.bench.exchange import import_table, parse_accuracy, parse_zero
    from mkm.bench.tables import parse_assignments, parse_scaling, table_files
    from mkm.paths import default_out
    from mkm.progress import progress_bar, summary_line

    lines: list[str] = []
    with progress_bar(1, "import", not args.no_progress, unit="stage") as bar:
        runs = import_table(
            table_files(args.table), args.out or default_out("runs"),
            {"id": args.id, "D0_mm": args.D0, "t0_mm": args.t0, "L0_mm": args.L0,
             "eps": args.eps, "theta0_deg": args.theta0_deg, "C10_MPa": args.C10_MPa,
             "C01_MPa": args.C01_MPa},
            columns=parse_assignments(args.columns, "--columns"),
            units=parse_assignments(args.units, "--units"), sheet=args.sheet,
            tare=parse_zero(args.tare, "--tare", "N"),
            vented=parse_zero(args.vented, "--vented", "bar"),
            select=args.muscle, accuracy=parse_accuracy(args.accuracy),
            force_sign=args.force_sign, one_step_per_row=args.one_step_per_row,
            join=args.join_by_time, join_shift_s=args.join_shift,
            scaling=parse_scaling(args.sensitivity, args.offset_volts, args.current_range),
            sample_rate_hz=args.sample_rate, tolerances=args.tolerance,
            between_files_s=args.between_files, notify=lines.append, bar=bar)
    for line in lines:  # after the import: bad input stays one line
        summary_line("import", line)
    for run in runs:
        summary_line("import", run.line())
    for run in runs:
        print(run.path)
    if runs:
        from mkm.bench.storage import read_meta

        say(args, "note", next_commands([r.path for r in runs],
                                        [read_meta(r.path).muscle.eps for r in runs]))
    return 0


def _export(args) -> int:
    from pathlib import Path

    from mkm.bench.exchange import export_run
    from mkm.bench.folders import one_run_folder
    from mkm.bench.storage import load_run
    from mkm.paths import default_out

    args.run = one_run_folder(args.run)
    name = Path(args.run).name
    out = args.out or default_out("export", name + (".xlsx" if args.format == "xlsx" else ""))
    run = load_run(args.run)  # the status the export records
    print(export_run(args.run, out, args.format))
    if run.meta.recording():
        say(args, "note", f"{name} {run.meta.recording()}: the export holds its record so far "
            f"(status {run.status}); export it again {run.meta.until_ended()}")
    return 0
