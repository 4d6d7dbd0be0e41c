"""``mkm import`` and ``mkm export``: measurements in from a table, runs out to a spreadsheet.

Argument parsing only: :mod:`mkm.bench.exchange` does the work.
"""

from __future__ import annotations

from mkm.cli.common import add_muscle_arguments

IMPORT_EXAMPLE = ("example: mkm import lab.xlsx --id lab-muscle-7 --D0 30 --t0 3 --L0 282 "
                  "--eps 12.2% --columns pressure=P_bar,force=F_N")
EXPORT_EXAMPLE = "example: mkm export mkm-out/demo/runs/<run> --format xlsx --out run.xlsx"


def register(subparsers) -> None:
    imp = subparsers.add_parser(
        "import", help="a table of forces measured elsewhere (CSV or Excel) as a run folder",
        description="Read a CSV or .xlsx table (one row per step: pressure [bar], force [N], "
        "optionally direction up/down and the force's standard deviation [N]) and write a run "
        "folder with status 'imported' that report, calibrate and identify read. Columns are "
        "found by name (pressure_bar, force_N, direction, force_std_N, any case) or named "
        "with --columns.", epilog=IMPORT_EXAMPLE)
    imp.add_argument("table", help="the CSV or .xlsx file")
    imp.add_argument("--id", required=True, help="the muscle's id (names the run folder)")
    add_muscle_arguments(imp, length=True)
    imp.add_argument("--columns", default=None, metavar="ROLE=COLUMN,...",
                     help="which column holds what: pressure=..., force=..., direction=..., "
                     "force_std=...")
    imp.add_argument("--out", default=None,
                     help="folder to put the run folder in (default: mkm-out/runs)")
    imp.set_defaults(func=_import)

    exp = subparsers.add_parser(
        "export", help="a run folder as one Excel workbook or three CSV files",
        description="Write a run's steps, samples and metadata (run.json flattened to key, "
        "value) as one .xlsx workbook with three sheets, or as steps.csv, samples.csv and "
        "metadata.csv in a folder; text cells are spreadsheet-safe.", epilog=EXPORT_EXAMPLE)
    exp.add_argument("run", help="the run folder")
    exp.add_argument("--format", default="xlsx", choices=("xlsx", "csv"))
    exp.add_argument("--out", default=None,
                     help="the workbook (xlsx) or folder (csv); default: mkm-out/export/<run>")
    exp.set_defaults(func=_export)


def _import(args) -> int:
    from mkm.bench.exchange import import_table, parse_columns
    from mkm.bench.storage import muscle_from_dict
    from mkm.paths import default_out
    from mkm.progress import summary_line

    muscle = muscle_from_dict({"id": args.id, "D0_mm": args.D0, "t0_mm": args.t0,
                                  "L0_mm": args.L0, "eps": args.eps}, "the muscle")
    path = import_table(args.table, muscle, args.out or default_out("runs"),
                        parse_columns(args.columns))
    summary_line("import", f"{args.table} as an imported run")
    print(path)
    return 0


def _export(args) -> int:
    from pathlib import Path

    from mkm.bench.exchange import export_run
    from mkm.paths import default_out

    name = Path(args.run).name
    out = args.out or default_out("export", name + (".xlsx" if args.format == "xlsx" else ""))
    print(export_run(args.run, out, args.format))
    return 0
