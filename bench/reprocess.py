"""Recompute a run's forces from its raw volts with another load-cell calibration.

``samples.csv`` keeps the raw ``loadcell_V`` of every sample, so a run recorded with a wrong or
outdated calibration is not lost: :func:`reprocess` writes a new run folder in which the tare
offset is the mean of the run's own tare samples again (checked by
:func:`mkm.bench.sequence.validate_tare` with the new settings), every ``force_N`` is
``(loadcell_V - offset) x sensitivity`` with the new ``[loadcell]`` and ``[safety]`` sections,
and every step's hold average and uncertainty budget are taken again over the same hold window
(the samples after ``start_s + settle_s`` up to ``end_s``). The samples are streamed, so memory
does not grow with the run. ``run.json`` gets ``reprocessed_from``: the source folder, the
SHA-256 of its run.json and samples.csv, the calibration it had, and the configuration applied
(``config_source``, the SHA-256 of the file given, ``config_sha256``, and ``config_overrides``,
as ``run.json`` records its own).
"""

from __future__ import annotations

import dataclasses
import re
from pathlib import Path

import numpy as np

from mkm.bench.budget import Instrument
from mkm.bench.config import BenchConfig, Step, config_from_tables
from mkm.bench.sequence import HoldStats, TareInvalid, validate_tare
from mkm.bench.storage import (
    CommandRecord,
    ProcessIdentity,
    RunStatus,
    RunWriter,
    Sample,
    iter_samples,
    load_run,
    read_meta,
)
from mkm.core.guards import regular_file
from mkm.core.records import file_sha256, provenance
from mkm.core.toml_text import read_toml_file


def overlay_config(run_dir: str | Path, path: str | Path) -> BenchConfig:
    """The run's own configuration (its ``config.toml``) with every section of the TOML file
    ``path`` laid over it: a file holding only ``[loadcell]`` recalibrates and changes nothing
    else. The text kept is the run's, its replaced sections swapped for the file's."""
    read_meta(run_dir)  # a folder that is none is named so, not as a missing config.toml
    run_text, run_data = read_toml_file(regular_file(Path(run_dir) / "config.toml",
                                                     "the run's config "), "the run's config ")
    new_text, new_data = read_toml_file(path, "config ")
    if not new_data:
        raise ValueError(f"config {path}: no section: expected at least [loadcell]")
    merged = {**run_data, **new_data}
    text = _swap_sections(run_text, new_text, set(new_data))
    config = config_from_tables(merged, text, f"{Path(run_dir).name}/config.toml + {path}")
    return dataclasses.replace(config, source_sha256=file_sha256(path))


def _swap_sections(base: str, new: str, names: set[str]) -> str:
    """``base`` with its top-level tables in ``names`` replaced by those of ``new`` (appended
    where ``base`` has none)."""
    def split(text: str) -> list[tuple[str, str]]:
        parts, name, lines = [], "", []
        for line in text.splitlines(keepends=True):
            header = re.match(r"^\s*\[([A-Za-z_][\w.]*)\]\s*(#.*)?$", line)
            if header:
                parts.append((name, "".join(lines)))
                name, lines = header.group(1).split(".")[0], []
            lines.append(line)
        parts.append((name, "".join(lines)))
        return parts

    replacement = {n: "" for n in names}
    for name, chunk in split(new):
        if name in names:
            replacement[name] += chunk
    out = []
    for name, chunk in split(base):
        if name in names:
            out.append(replacement.pop(name, ""))
        else:
            out.append(chunk)
    out += [chunk for chunk in replacement.values() if chunk]
    return "".join(part if part.endswith("\n") else part + "\n" for part in out if part)


def reprocess(run_dir: str | Path, config: BenchConfig, out_root: str | Path | None = None
              ) -> Path:
    """Write a copy of the run ``run_dir`` recalibrated with ``config.loadcell``; return it."""
    source = load_run(run_dir)
    # the copy would be a complete run with steps or samples missing and not a word of it
    if "steps.csv is missing" in source.problems or source.rows_lost:
        gone = source.rows_lost[0] if source.rows_lost else "steps.csv is missing"
        raise ValueError(f"run {source.path}: {gone}: expected the whole record to reprocess")
    cell = config.loadcell
    out_root = Path(out_root) if out_root is not None else source.path.parent
    samples_csv = source.path / "samples.csv"
    if not samples_csv.is_file():
        raise ValueError(f"run {source.path} has no samples.csv: expected the raw volts to "
                         "reprocess")
    regular_file(samples_csv, f"run {source.path.name}: ")
    # pass 1: the tare, from the run's own samples at 0 bar; and what there is to reprocess
    tare_V, rows, finite = [], 0, 0
    for chunk in iter_samples(source.path):
        tare_V.extend(chunk.loc[chunk["phase"] == "tare", "loadcell_V"].tolist())
        rows += len(chunk)
        finite += int(np.isfinite(chunk["loadcell_V"].to_numpy(float)).sum())
    if not finite:
        raise ValueError(f"run {source.path} has {rows} samples and not one finite load-cell "
                         "reading: nothing to reprocess")
    try:
        tare = validate_tare(tare_V, config, pressure_to_follow=False) if tare_V else None
    except TareInvalid as exc:  # the settings given refuse it: bad input, one line
        why = str(exc).removeprefix("tare invalid: ").removesuffix("; nothing was pressurised")
        raise ValueError(f"run {source.path}: its tare is invalid with these settings ({why}): "
                         "nothing reprocessed") from None
    offset_V = tare["offset_V"] if tare else cell.offset_V
    steps = source.steps
    windows = {int(s.step): (float(s.start_s) + float(s.settle_s), float(s.end_s))
               for s in steps.itertuples()}
    holds = {k: HoldStats() for k in windows}
    meta = dataclasses.replace(source.meta)
    prov = provenance()
    settings = config.as_dict()
    meta.reprocessed_from = {
        # absolute: a path relative to where the command ran says nothing once elsewhere
        "path": str(source.path.resolve()),
        "run_json_sha256": file_sha256(source.path / "run.json"),
        "samples_sha256": file_sha256(samples_csv),
        "calibration": source.meta.calibration, "tare": source.meta.tare,
        # the file laid over the run's config.toml, named and hashed as run.json names its own
        "config_source": config.source, "config_sha256": config.source_sha256,
        "config_overrides": config.overrides, "date_utc": prov["date_utc"]}
    meta.calibration = {**meta.calibration, "loadcell": settings["loadcell"],
                        "safety": settings["safety"]}
    meta.tare = {**tare, "duration_s": source.meta.sequence.get("tare_s")} if tare else None
    meta.provenance, meta.command = prov, prov["command"]
    # run.json first, "running" from this process until every file is written
    writer = RunWriter(out_root, dataclasses.replace(
        meta, status=RunStatus.RUNNING, process=ProcessIdentity.current()),
        config.effective_text())
    # pass 2: every sample again, forces from the raw volts
    for chunk in iter_samples(source.path):
        during_tare = (chunk["phase"] == "tare").to_numpy()
        volts = chunk["loadcell_V"].to_numpy(float)
        force = (volts - np.where(during_tare, cell.offset_V, offset_V)) * \
            cell.sensitivity_N_per_V
        chunk = chunk.assign(force_N=force)
        writer.append_samples([Sample(*row) for row in chunk.itertuples(index=False)])
        in_step = chunk[chunk["phase"] == "step"]
        for k, group in in_step.groupby("step"):
            if int(k) not in windows:
                continue
            start, end = windows[int(k)]
            t = group["time_s"].to_numpy(float)
            inside = (t > start + 1e-9) & (t <= end + 1e-9)
            for row in group[inside].itertuples(index=False):
                holds[int(k)].add(float(row.time_s), float(row.force_N), float(row.pressure_bar))
    instrument = Instrument.from_config(config)
    for s in steps.itertuples():
        hold = holds[int(s.step)]
        row = hold.record(Step(int(s.step), s.direction, int(s.repeat), float(s.set_pressure_bar)),
                          instrument, tare, bool(s.settled), float(s.settle_s), float(s.start_s),
                          float(s.end_s))
        # the pressures were not recomputed: keep the recorded mean
        writer.append_step(row._replace(pressure_bar_mean=float(s.pressure_bar_mean)))
    for c in source.commands.itertuples(index=False):
        writer.append_command(CommandRecord(*c))
    writer.write_meta(meta)
    writer.close()
    return writer.path
