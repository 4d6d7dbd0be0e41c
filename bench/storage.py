"""Run folders: writing them while a run goes, and loading them back as pandas objects.

One folder per run, named ``<UTC time>_<muscle id>``::

    run.json      metadata; written atomically at start (status "running") and at the end
                  ("complete", "aborted" or "failed", with the reason)
    config.toml   the bench configuration as given
    samples.csv   one row per sample, appended and flushed after every block read
    steps.csv     one row per pressure step, appended when the step ends
    commands.csv  every regulator command written, with whether the write succeeded

Rows are flushed to the operating system after every block, so a run killed at any moment keeps
every sample read before its last block. ``fsync`` (which costs milliseconds) runs only for
run.json and at close: it guards against power loss, not against a dying process.
"""

from __future__ import annotations

import datetime
import json
import math
import os
import tempfile
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import pandas as pd

SAMPLE_COLUMNS = ("sample", "time_s", "step", "phase", "set_pressure_bar", "command_bar",
                  "pressure_bar", "loadcell_V", "monitor_V", "force_N", "flags")
STEP_COLUMNS = ("step", "direction", "repeat", "set_pressure_bar", "pressure_bar_mean",
                "force_N_mean", "force_N_std", "n", "settled", "settle_s", "start_s", "end_s")
COMMAND_COLUMNS = ("time_s", "sample", "command_bar", "command_V", "ok", "purpose")
STATUSES = ("running", "complete", "aborted", "failed")


def run_folder_name(muscle_id: str, when: datetime.datetime | None = None) -> str:
    when = when or datetime.datetime.now(datetime.UTC)
    return f"{when:%Y%m%dT%H%M%SZ}_{muscle_id}"


def _number(value) -> str:
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return ""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return f"{value:.6g}"
    return str(value)


def write_json_atomic(path: Path, data: dict[str, Any]) -> None:
    """Write ``data`` so that ``path`` always holds either the old or the new complete file."""
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    try:
        os.chmod(tmp, 0o644)  # mkstemp makes it private; a run record is for everyone to read
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            json.dump(data, f, indent=2, default=str)
            f.write("\n")
            f.flush()
            os.fsync(f.fileno())
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


class RunWriter:
    """Creates a run folder and appends to its files as the run goes."""

    def __init__(self, root: str | Path, muscle_id: str, config_text: str):
        root = Path(root)
        root.mkdir(parents=True, exist_ok=True)
        name = run_folder_name(muscle_id)
        path, k = root / name, 1
        while True:
            try:
                path.mkdir()
                break
            except FileExistsError:
                k += 1
                path = root / f"{name}-{k}"
        self.path = path
        (path / "config.toml").write_text(config_text, encoding="utf-8")
        self._files = {}
        for name, columns in (("samples", SAMPLE_COLUMNS), ("steps", STEP_COLUMNS),
                              ("commands", COMMAND_COLUMNS)):
            f = open(path / f"{name}.csv", "w", encoding="utf-8", newline="")
            f.write(",".join(columns) + "\n")
            f.flush()
            self._files[name] = f

    def write_meta(self, meta: dict[str, Any]) -> None:
        write_json_atomic(self.path / "run.json", meta)

    def _append(self, name: str, rows: list[tuple]) -> None:
        f = self._files[name]
        f.write("".join(",".join(_number(v) for v in row) + "\n" for row in rows))
        f.flush()

    def append_samples(self, rows: list[tuple]) -> None:
        """Rows in :data:`SAMPLE_COLUMNS` order; flushed before returning."""
        self._append("samples", rows)

    def append_step(self, row: dict[str, Any]) -> None:
        self._append("steps", [tuple(row[c] for c in STEP_COLUMNS)])

    def append_command(self, row: tuple) -> None:
        self._append("commands", [row])

    def close(self) -> None:
        for f in self._files.values():
            if not f.closed:
                f.flush()
                os.fsync(f.fileno())
                f.close()


@dataclass
class Run:
    """A run folder loaded back: metadata, samples and steps, and whether it is complete.

    ``status`` is the one in ``run.json`` ("complete", "aborted", "failed"), "running" while the
    recording process is alive, or "incomplete" when the run stopped without closing its record
    (killed, power lost). ``problems`` lists what the loader had to repair or could not read.
    """

    path: Path
    meta: dict[str, Any]
    samples: pd.DataFrame
    steps: pd.DataFrame
    status: str
    commands: pd.DataFrame = field(default_factory=pd.DataFrame)
    problems: list[str] = field(default_factory=list)

    @property
    def complete(self) -> bool:
        return self.status == "complete"

    @property
    def reason(self) -> str:
        return self.meta.get("reason", "")


def _read_csv(path: Path, columns: tuple[str, ...], problems: list[str]) -> pd.DataFrame:
    if not path.is_file():
        problems.append(f"{path.name} is missing")
        return pd.DataFrame(columns=list(columns))
    text = path.read_text(encoding="utf-8")
    if text and not text.endswith("\n"):
        # The process died in the middle of a row: that row was never flushed whole.
        text = text[: text.rfind("\n") + 1]
        problems.append(f"{path.name}: dropped a partial last row")
    if not text.startswith(",".join(columns)):
        raise ValueError(f"{path} is corrupt: expected a header starting "
                         f"{','.join(columns[:3])}...")
    from io import StringIO

    try:
        df = pd.read_csv(StringIO(text), keep_default_na=True, dtype={"flags": "string"}
                         if "flags" in columns else None)
    except (pd.errors.ParserError, ValueError) as exc:
        raise ValueError(f"{path} is corrupt: {exc}") from None
    if "flags" in df:
        df["flags"] = df["flags"].fillna("")
    if "settled" in df:
        df["settled"] = df["settled"].astype(str).str.lower().eq("true")
    if "ok" in df:
        df["ok"] = df["ok"].astype(str).str.lower().eq("true")
    return df


def _process_alive(meta: dict[str, Any]) -> bool:
    import socket

    pid, host = meta.get("pid"), meta.get("host")
    if not pid or host != socket.gethostname():
        return False
    try:
        os.kill(int(pid), 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


def load_run(path: str | Path) -> Run:
    """Load the run folder ``path``.

    Raises ``ValueError`` with a clear message when ``path`` is not a run folder or ``run.json``
    cannot be read. A run that did not finish loads with ``complete`` False, status
    "incomplete" (or "running" if its process is still alive), every flushed sample, and the
    reason in ``problems``.
    """
    path = Path(path)
    meta_path = path / "run.json"
    if not meta_path.is_file():
        raise ValueError(f"{path} is not a run folder: run.json is missing")
    try:
        meta = json.loads(meta_path.read_text(encoding="utf-8"))
    except (json.JSONDecodeError, UnicodeDecodeError) as exc:
        raise ValueError(f"{meta_path} is corrupt (not valid JSON: {exc})") from None
    if not isinstance(meta, dict) or meta.get("status") not in STATUSES:
        raise ValueError(f"{meta_path} is corrupt: expected a 'status' among "
                         f"{', '.join(STATUSES)}")
    problems: list[str] = []
    samples = _read_csv(path / "samples.csv", SAMPLE_COLUMNS, problems)
    steps = _read_csv(path / "steps.csv", STEP_COLUMNS, problems)
    commands = _read_csv(path / "commands.csv", COMMAND_COLUMNS, problems)
    status = meta["status"]
    if status == "running" and not _process_alive(meta):
        status = "incomplete"
        problems.append("the run stopped without closing its record (killed or crashed): "
                        f"{len(samples)} samples were flushed before it stopped")
    return Run(path=path, meta=meta, samples=samples, steps=steps, status=status,
               commands=commands, problems=problems)
