"""Measurements in and out of run folders: another bench's table in, a run out to a spreadsheet.

- :func:`import_table`: a CSV or Excel table of forces measured elsewhere (another bench, a
  spreadsheet; one row per step: pressure, force, optionally the sweep direction and the force's
  standard deviation) becomes a run folder with status ``imported``, the muscle as the user
  gives it, and the source file's name and SHA-256 in ``imported_from``. It has no samples and
  no commands (the table holds none); ``mkm report``, ``mkm fem calibrate --reference`` and
  ``mkm identify`` read it like any run.
- :func:`export_run`: a run folder as one Excel workbook (sheets ``steps``, ``samples``,
  ``metadata``) or as three CSV files, every text cell spreadsheet-safe.

Tables are read with pandas' readers (``openpyxl`` for ``.xlsx``); nothing in them can run code.
"""

from __future__ import annotations

import datetime
import json
import math
from pathlib import Path

import numpy as np
import pandas as pd

from mkm.bench.storage import (
    DIRECTIONS,
    MAX_CELL_MAGNITUDE,
    RunMeta,
    RunStatus,
    RunWriter,
    StepRecord,
    load_run,
)
from mkm.core.records import file_sha256, provenance, spreadsheet_safe
from mkm.fem.limits import check_value
from mkm.fem.muscle import Muscle

#: what a table column may hold -> the names looked for when ``--columns`` does not say
COLUMN_ROLES = {"pressure": ("pressure_bar", "pressure", "p_bar", "p"),
                "force": ("force_N", "force", "f_n", "f"),
                "direction": ("direction", "dir", "branch"),
                "force_std": ("force_std_N", "force_N_std", "std_N", "force_std")}
REQUIRED_ROLES = ("pressure", "force")
MAX_ROWS = 100_000
EXCEL_MAX_ROWS = 1_048_575  # below the header row


def read_table(path: str | Path) -> pd.DataFrame:
    """The table in ``path`` (``.csv``, ``.xlsx``: the first sheet); ``ValueError`` otherwise."""
    path = Path(path)
    if not path.is_file():
        raise ValueError(f"{path}: no such file: expected a CSV or .xlsx table")
    suffix = path.suffix.lower()
    if suffix not in (".xlsx", ".xlsm", ".csv", ".txt"):
        raise ValueError(f"{path}: unknown table format {suffix!r}: expected .csv or .xlsx")
    try:
        if suffix in (".xlsx", ".xlsm"):
            table = pd.read_excel(path, sheet_name=0, engine="openpyxl")
        else:
            table = pd.read_csv(path, sep=None, engine="python")  # , or ; as exported
    except (OSError, UnicodeDecodeError, pd.errors.ParserError, pd.errors.EmptyDataError,
            KeyError, TypeError, ValueError) as exc:
        raise ValueError(f"{path} cannot be read as a table ({type(exc).__name__}: "
                         f"{str(exc)[:120]})") from None
    if len(table) > MAX_ROWS:
        raise ValueError(f"{path} has {len(table)} rows: expected one row per step (at most "
                         f"{MAX_ROWS})")
    return table


def parse_columns(text: str | None) -> dict[str, str]:
    """``pressure=P [bar],force=F`` -> ``{"pressure": "P [bar]", "force": "F"}``."""
    out = {}
    for item in filter(None, (i.strip() for i in (text or "").split(","))):
        role, sep, column = item.partition("=")
        role = role.strip()
        if not sep or role not in COLUMN_ROLES or not column.strip():
            raise ValueError(f"--columns item {item!r} is invalid: expected ROLE=COLUMN with ROLE "
                             f"one of {', '.join(COLUMN_ROLES)}")
        out[role] = column.strip()
    return out


def _pick(table: pd.DataFrame, columns: dict[str, str]) -> dict[str, str]:
    """The table column of each role: as given, else the first known name (any case)."""
    by_lower = {str(c).strip().lower(): c for c in table.columns}
    chosen = {}
    for role, names in COLUMN_ROLES.items():
        if role in columns:
            if columns[role] not in table.columns:
                raise ValueError(f"--columns {role}={columns[role]!r}: no such column: the "
                                 f"table has {', '.join(map(str, table.columns))}")
            chosen[role] = columns[role]
            continue
        found = next((by_lower[n.lower()] for n in names if n.lower() in by_lower), None)
        if found is not None:
            chosen[role] = found
    missing = [r for r in REQUIRED_ROLES if r not in chosen]
    if missing:
        raise ValueError(f"no {' or '.join(missing)} column found among "
                         f"{', '.join(map(str, table.columns))}: name it with --columns "
                         "pressure=COLUMN,force=COLUMN")
    return chosen


def _numbers(table: pd.DataFrame, column: str, role: str) -> np.ndarray:
    values = pd.to_numeric(table[column], errors="coerce").to_numpy(dtype=float)
    bad = ~np.isfinite(values) | (np.abs(values) > MAX_CELL_MAGNITUDE)
    if bad.any():
        row = int(np.flatnonzero(bad)[0])
        raise ValueError(f"{role} column {column!r}, row {row + 2}: {table[column].iloc[row]!r} "
                         "is not a finite number")
    return values


def _directions(table: pd.DataFrame, column: str | None, pressure: np.ndarray) -> list[str]:
    """The sweep of each row: as given, else up to the highest pressure and down after it."""
    if column is None:
        top = int(np.argmax(pressure))
        return ["up" if k <= top else "down" for k in range(len(pressure))]
    values = [str(v).strip().lower() for v in table[column]]
    for row, value in enumerate(values):
        if value not in DIRECTIONS:
            raise ValueError(f"direction column {column!r}, row {row + 2}: {value!r} is "
                             f"invalid: expected {' or '.join(DIRECTIONS)}")
    return values


def import_table(path: str | Path, muscle: Muscle, out_root: str | Path,
                 columns: dict[str, str] | None = None) -> Path:
    """A run folder (status ``imported``) under ``out_root`` from the table ``path``; returns
    its path. ``muscle``: the muscle measured (id, D0_mm, t0_mm, L0_mm, eps)."""
    path = Path(path)
    table = read_table(path)
    if table.empty:
        raise ValueError(f"{path} has no rows: expected one row per step")
    chosen = _pick(table, columns or {})
    pressure = _numbers(table, chosen["pressure"], "pressure")
    for value in pressure:
        check_value("pressure_bar", value, f"{path.name}: ")
    force = _numbers(table, chosen["force"], "force")
    std = (_numbers(table, chosen["force_std"], "force_std") if "force_std" in chosen
           else np.full(len(table), math.nan))
    directions = _directions(table, chosen.get("direction"), pressure)
    now = datetime.datetime.now(datetime.UTC).isoformat(timespec="seconds")
    prov = provenance()
    meta = RunMeta(
        muscle=muscle, status=RunStatus.IMPORTED,
        reason=f"imported from {path.name}: measured elsewhere, no samples or commands",
        hardware={"backend": "import"}, sequence={"n_steps": len(table)},
        steps_done=len(table), command=prov["command"], provenance=prov, started_utc=now,
        ended_utc=now, imported_from={"file": path.name, "sha256": file_sha256(path),
                                      "columns": {r: str(c) for r, c in chosen.items()}})
    writer = RunWriter(out_root, meta, f"# imported from {path.name}: no bench configuration\n")
    repeats: dict[tuple[str, float], int] = {}
    for k, (p, f, s, d) in enumerate(zip(pressure, force, std, directions, strict=True)):
        key = (d, round(float(p), 3))
        repeats[key] = repeats.get(key, 0) + 1
        writer.append_step(StepRecord(k, d, repeats[key] - 1, float(p), float(p), float(f),
                                      float(s), 1, True, math.nan, math.nan, math.nan))
    writer.close()
    return writer.path


def export_run(run_dir: str | Path, out: str | Path, fmt: str = "xlsx") -> Path:
    """The run ``run_dir`` as ``out`` (a ``.xlsx`` workbook) or, with ``fmt="csv"``, as the
    folder ``out`` holding ``steps.csv``, ``samples.csv`` and ``metadata.csv``."""
    if fmt not in ("xlsx", "csv"):
        raise ValueError(f"--format {fmt!r} is invalid: expected xlsx or csv")
    run = load_run(run_dir)
    samples = run.samples
    if fmt == "xlsx" and len(samples) > EXCEL_MAX_ROWS:
        raise ValueError(f"{run.path.name} has {len(samples)} samples: a worksheet holds at "
                         f"most {EXCEL_MAX_ROWS}; use --format csv")
    metadata = pd.DataFrame(_flatten(run.meta.as_dict()), columns=["key", "value"])
    sheets = {"steps": run.steps, "samples": samples, "metadata": metadata}
    sheets = {name: spreadsheet_safe(frame) for name, frame in sheets.items()}
    out = Path(out)
    if fmt == "xlsx":
        out.parent.mkdir(parents=True, exist_ok=True)
        with pd.ExcelWriter(out, engine="openpyxl") as book:
            for name, frame in sheets.items():
                frame.to_excel(book, sheet_name=name, index=False)
        return out
    out.mkdir(parents=True, exist_ok=True)
    for name, frame in sheets.items():
        frame.to_csv(out / f"{name}.csv", index=False, float_format="%.10g")
    return out


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
