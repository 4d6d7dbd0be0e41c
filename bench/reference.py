"""A measurement as a calibration reference: a CSV table, or the settled steps of a run folder.

:func:`calibration_reference` is what ``mkm fem calibrate --reference`` reads (a CSV, a run
folder, or a folder of them as other commands take runs): the table
:func:`mkm.fem.calibration.check_reference` checks (``pressure_bar, D0_mm, t0_mm, eps,
force_N``, optional ``L0_mm`` and ``direction``), with its name and the SHA-256 of the file
read, for the calibration's provenance.
"""

from __future__ import annotations

import hashlib
from pathlib import Path

import pandas as pd

from mkm.bench.folders import PATTERN_CHARACTERS, is_run_folder, run_folders
from mkm.bench.storage import load_run
from mkm.bench.tables import plain_number, read_tables
from mkm.core.records import file_sha256
from mkm.fem.calibration import REFERENCE_COLUMNS, check_reference


def calibration_reference(path) -> tuple[pd.DataFrame, str, str | None]:
    """The reference table at ``path``, its name and the SHA-256 of the file read.

    A run folder gives its settled steps: the measured mean pressure and force of each step,
    its direction, and the muscle from run.json. A folder of run folders, or a pattern, gives
    theirs together, one sweep per muscle state (the name says how many runs; the SHA-256 is
    that of their steps.csv files' names and SHA-256 in order).
    """
    text = str(path)
    path = Path(path)
    if any(c in text for c in PATTERN_CHARACTERS) or (path.is_dir() and not is_run_folder(path)):
        runs = run_folders([text])
        if len(runs) > 1:
            frames, shas = zip(*(_run_steps(run) for run in runs), strict=True)
            reference = check_reference(pd.concat(frames, ignore_index=True),
                                        f"{len(runs)} runs in {text} (settled steps)")
            listed = "".join(f"{run.name} {sha}\n" for run, sha in zip(runs, shas, strict=True))
            return reference, f"{len(runs)} runs in {text}", hashlib.sha256(
                listed.encode()).hexdigest()
        path = runs[0]
    if not path.is_dir():
        sha = file_sha256(path) if path.is_file() else None
        frame = _table(path)
        missing = [c for c in REFERENCE_COLUMNS if c not in frame.columns]
        if missing:
            # a lab's own table of pressure and force: its run folder is the reference
            raise ValueError(f"{path} lacks columns {missing}: expected a reference table with "
                             f"{', '.join(REFERENCE_COLUMNS)} (optional L0_mm, direction), or "
                             "a run folder; a lab's table of pressures and forces becomes one "
                             f"with mkm import \"{path}\" --id ... --D0 ... --t0 ...")
        return check_reference(frame, str(path)), path.name, sha
    frame, sha = _run_steps(path)
    reference = check_reference(frame, f"run {path} (settled steps of steps.csv)")
    return reference, f"run {path.name}", sha


def _table(path: Path) -> pd.DataFrame:
    """A reference table as a lab's spreadsheet saves it (:func:`mkm.bench.tables.read_tables`:
    separator ``,``, ``;`` or tab, decimal commas, CRLF, ``#`` comments, or an ``.xlsx``), its
    number cells read as every imported table's are, for
    :func:`mkm.fem.calibration.check_reference`."""
    table = read_tables(path)[0]

    def cell_value(cell):
        number = plain_number(cell, table.decimal)
        return cell if number is None else number

    return pd.DataFrame([[cell_value(cell) for cell in row] for row in table.rows],
                        columns=table.header)


def _run_steps(path: Path) -> tuple[pd.DataFrame, str]:
    """A run folder's settled steps as reference rows, and the SHA-256 of its steps.csv."""
    run = load_run(path)
    if "steps.csv is missing" in run.problems:
        raise ValueError(f"run {path} has no steps.csv: expected its settled steps as the "
                         "reference")
    steps = run.steps[run.steps["settled"]]
    muscle = run.meta.muscle
    frame = pd.DataFrame({"pressure_bar": steps["pressure_bar_mean"],
                          "set_pressure_bar": steps["set_pressure_bar"],
                          "force_N": steps["force_N_mean"], "direction": steps["direction"],
                          "D0_mm": muscle.D0_mm, "t0_mm": muscle.t0_mm, "eps": muscle.eps,
                          "L0_mm": muscle.L0_mm})
    return frame, file_sha256(path / "steps.csv")
