"""Hostile trials of issue 20, per finding: a seeded corpus of hostile inputs run through an
installed `mkm` as subprocesses, each outcome classified, outside the test suite.

    .venv/bin/python benchmarks/bench_hostile.py [--mkm PATH] [--seed 0] [--folders 30]
        [--configs 70] [--models 26] [--only 1,6] [--timeout 60] [--cache DIR] [--json FILE]

`--mkm` names the `mkm` of another environment (for example an older checkout's venv): every
input is built from that environment's own packaged bench configuration, its own recorded run
and its own trained model folder, so the same seed gives the same hostile edits to both. Per
finding (the numbers of issue 20):

1. stuck regulator ([sim.faults] regulator_stuck_at_s within the run): bad when the regulator
   is stuck above 0.1 bar (read from samples.csv at the fault's time) and the run exits 0 or
   says nothing of a vent by hand;
2. a second `acquire`, `tare`, `calibrate-loadcell` or `vent` while a real-clock run holds the
   bench (same state folder): bad when a second acquisition, tare or calibration exits 0, or
   when `vent` exits 0 without a word about the run;
3. configurations that switch an interlock off (tolerances, follow time, tare spread, force
   limit above the cell), absurd geometry or cell capacity, a cell the muscle overloads,
   through `mkm check`: bad when accepted (exit 0) without a warning;
4. runs without end (huge durations, counts, a tiny buffer, a long stall) through `mkm check`,
   and a few through `mkm acquire` (20 s): bad when accepted without a warning, or still running;
5. a full disk (RLIMIT_FSIZE: a write past the limit fails with EFBIG) during `mkm acquire`:
   bad when a write had to fail and the exit status is 0, or the folder has no run.json, or
   run.json says `running` after the process ended;
6. hostile run folders through `mkm report`, `mkm reprocess`, `mkm fem calibrate --reference`,
   hostile config files through `mkm check`, hostile model folders through `mkm fem solve
   --model surrogate:path=DIR`: bad on a traceback, a hang or death by a signal;
7. formula cells and hostile muscle ids or folder names through `mkm report` and `mkm
   reprocess`: bad when an output CSV cell starts with = + - @ (not a number) or a folder named
   after a hostile id is created;
8. a trained model folder's metadata.json edited (box widened, kind, inputs): bad when a point
   outside the trained box is predicted with valid and in_domain true;
9. SIGKILL during a run (the sample counter the environment's loader reports against the rows
   of samples.csv), SIGINT twice (exit status 130), SIGINT during start-up (no traceback),
   `MKM_OUT=X mkm report RUN` (the report under X/report/, not in X itself).

Every trial: a traceback, a hang (--timeout) or death by a signal is bad whatever the category.
Prints one Markdown table (per finding: trials, bad outcomes, outcome counts), the run time, and
with --json every trial with its outcome.
"""

from __future__ import annotations

import argparse
import csv
import json
import os
import random
import re
import resource
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from collections import Counter
from dataclasses import asdict, dataclass, field
from pathlib import Path

FORMULA_START = ("=", "+", "-", "@", "\t", "\r")
FINDINGS = {1: "vent not verified (stuck regulator)", 2: "two processes on one bench",
            3: "interlocks, geometry, capacity", 4: "runs without end", 5: "full disk",
            6: "tracebacks (run folders, configs, model folders)", 7: "formulas and ids",
            8: "model metadata tampering", 9: "signals, counters, MKM_OUT"}
FAST = {("sequence", "tare_s"): "1.0", ("sequence", "preconditioning_cycles"): "0",
        ("sequence", "pressures_bar"): "[0.5, 1.0, 1.5]"}


@dataclass
class Result:
    finding: int
    name: str
    outcome: str
    bad: bool
    seconds: float
    code: int | None = None
    detail: str = ""


@dataclass
class Proc:
    code: int | None
    out: str
    err: str
    seconds: float
    hung: bool = False

    @property
    def traceback(self) -> bool:
        return "Traceback (most recent call last)" in self.err

    def basic(self) -> tuple[str, bool] | None:
        """The outcome that is bad in every category, else None."""
        if self.hung:
            return "hang", True
        if self.traceback:
            return "traceback", True
        if self.code is not None and self.code < 0:
            return f"killed by signal {-self.code}", True
        return None

    def refusal(self) -> str:
        # one prefix for every error: "mkm <command>: error:"
        lines = [line for line in self.err.splitlines()
                 if re.match(r"mkm( [a-z-]+)*: error:", line)]
        if self.code == 0:
            return "exit 0"
        if self.code == 2 and len(lines) == 1:
            return "refused (exit 2, one line)"
        return f"exit {self.code}" + (" with an error line" if lines else "")


def set_key(text: str, section: str, key: str, value: str) -> str:
    """``text`` with ``key = value`` in ``[section]`` (replaced, or added to the section, or in a
    new section at the end)."""
    lines = text.splitlines()
    header = f"[{section}]"
    if header not in (line.strip() for line in lines):
        return text.rstrip("\n") + f"\n\n{header}\n{key} = {value}\n"
    start = next(i for i, line in enumerate(lines) if line.strip() == header)
    end = next((i for i in range(start + 1, len(lines)) if lines[i].startswith("[")),
               len(lines))
    for i in range(start + 1, end):
        if lines[i].split("=")[0].strip() == key:
            lines[i] = f"{key} = {value}"
            return "\n".join(lines) + "\n"
    lines.insert(start + 1, f"{key} = {value}")
    return "\n".join(lines) + "\n"


def edit_config(text: str, edits: dict) -> str:
    for (section, key), value in edits.items():
        text = set_key(text, section, key, value)
    return text


def formula_cells(folder: Path) -> list[str]:
    """Text cells of every CSV under ``folder`` that a spreadsheet would run as a formula."""
    found = []
    for path in folder.rglob("*.csv"):
        try:
            rows = csv.reader(path.read_text(encoding="utf-8", errors="replace").splitlines())
            for row in rows:
                for cell in row:
                    if cell.startswith(FORMULA_START):
                        try:
                            float(cell)
                        except ValueError:
                            found.append(f"{path.name}: {cell[:40]}")
        except (OSError, csv.Error):
            continue
    return found


class Env:
    """One installed ``mkm``: its interpreter, packaged configuration and scratch folders."""

    def __init__(self, mkm: str, root: Path, timeout: float, cache: Path):
        self.mkm = str(Path(mkm).absolute())
        self.python = str(Path(self.mkm).with_name("python"))
        self.root = root
        self.timeout = timeout
        self.cwd = root / "cwd"
        self.cwd.mkdir()
        self.env = {**os.environ, "MKM_CACHE_DIR": str(cache),
                    "MKM_STATE_DIR": str(root / "state"), "MKM_OUT": str(root / "mkm-out"),
                    "MPLBACKEND": "Agg"}
        self.env.pop("DISPLAY", None)
        self.env.pop("WAYLAND_DISPLAY", None)
        self._n = 0
        # the environment's own example, on a closed-form simulated muscle (no FE tabulation)
        text = self.snippet(
            "import importlib.resources as r\n"
            "for p in ('mkm.bench', 'bench'):\n"
            "    try:\n"
            "        print(r.files(p).joinpath('configs/paper_prototype.toml').read_text(),"
            " end='')\n"
            "        break\n"
            "    except ModuleNotFoundError:\n"
            "        pass\n")
        self.base_text = set_key(text, "sim", "model", '"thickwall"')
        self.fast_text = edit_config(self.base_text, FAST)
        self.base_config = self.write("base.toml", self.base_text)
        self.fast_config = self.write("fast.toml", self.fast_text)

    def fresh(self, name: str) -> Path:
        self._n += 1
        folder = self.root / f"t{self._n:04d}-{name}"
        folder.mkdir()
        return folder

    def write(self, name: str, text: str | bytes) -> Path:
        path = self.root / name
        if isinstance(text, bytes):
            path.write_bytes(text)
        else:
            path.write_text(text, encoding="utf-8")
        return path

    def snippet(self, code: str, *args: str) -> str:
        proc = subprocess.run([self.python, "-c", code, *args], capture_output=True, text=True,
                              cwd=self.cwd, env=self.env, timeout=120)
        if proc.returncode:
            raise RuntimeError(proc.stderr[-2000:])
        return proc.stdout

    def run(self, argv, state: Path | None = None, timeout: float | None = None,
            extra_env: dict | None = None, fsize: int | None = None) -> Proc:
        env = {**self.env, **(extra_env or {})}
        if state is not None:
            env["MKM_STATE_DIR"] = str(state)

        def limit():
            if fsize is not None:
                signal.signal(signal.SIGXFSZ, signal.SIG_IGN)  # EFBIG instead of a core dump
                resource.setrlimit(resource.RLIMIT_FSIZE, (fsize, fsize))

        start = time.perf_counter()
        proc = subprocess.Popen([self.mkm, *map(str, argv)], cwd=self.cwd, env=env,
                                stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE, text=True, errors="replace",
                                start_new_session=True, preexec_fn=limit)
        try:
            out, err = proc.communicate(timeout=timeout or self.timeout)
            hung = False
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            out, err = proc.communicate()
            hung = True
        return Proc(None if hung else proc.returncode, out, err,
                    time.perf_counter() - start, hung)

    def start(self, argv, state: Path) -> subprocess.Popen:
        env = {**self.env, "MKM_STATE_DIR": str(state)}
        return subprocess.Popen([self.mkm, *map(str, argv)], cwd=self.cwd, env=env,
                                stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE, text=True, errors="replace",
                                start_new_session=True)


def run_folder(out: Path) -> Path | None:
    found = sorted(p for p in out.glob("*") if p.is_dir()) if out.is_dir() else []
    return found[0] if found else None


def pressurised(out: Path, proc: subprocess.Popen, limit_s: float = 60.0) -> Path | None:
    """The run folder once the run has commanded its first step, else None."""
    deadline = time.monotonic() + limit_s
    while time.monotonic() < deadline and proc.poll() is None:
        folder = run_folder(out)
        commands = folder / "commands.csv" if folder else None
        if commands and commands.exists() and ",step" in commands.read_text(errors="replace"):
            return folder
        time.sleep(0.02)
    return None


def stop(proc: subprocess.Popen) -> Proc:
    start = time.perf_counter()
    if proc.poll() is None:
        proc.send_signal(signal.SIGINT)
    try:
        out, err = proc.communicate(timeout=30)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        out, err = proc.communicate()
    return Proc(proc.returncode, out, err, time.perf_counter() - start)


def acquire_args(config: Path, out: Path, *extra) -> list:
    return ["acquire", "--config", config, "--out", out, "--no-progress", *extra]


# 1 ------------------------------------------------------------------------------------------

def finding_1(env: Env, rng: random.Random, n: int = 12) -> list[Result]:
    import pandas as pd

    results = []
    for k in range(n):
        stuck_s = round(rng.uniform(3.0, 45.0), 1)
        edits = {("sim.faults", "regulator_stuck_at_s"): repr(stuck_s)}
        if k % 3 == 2:
            edits[("sim.faults", "overshoot_bar")] = repr(round(rng.uniform(0.0, 0.1), 3))
        config = env.write(f"stuck{k}.toml", edit_config(env.fast_text, edits))
        t = env.fresh("stuck")
        proc = env.run(acquire_args(config, t / "runs"), state=t / "state")
        name = f"regulator stuck at {stuck_s:g} s"
        basic = proc.basic()
        folder = run_folder(t / "runs")
        held = 0.0
        if folder and (folder / "samples.csv").exists():
            samples = pd.read_csv(folder / "samples.csv")
            at = samples[samples["time_s"] >= stuck_s].head(1)
            held = float(at["pressure_bar"].iloc[0]) if len(at) else 0.0
        by_hand = "by hand" in proc.err.lower()
        if basic:
            outcome, bad = basic
        elif held > 0.1 and (proc.code == 0 or not by_hand):
            outcome, bad = "vent not verified", True
        elif held > 0.1:
            outcome, bad = "vent by hand asked", False
        else:
            outcome, bad = f"stuck near 0 bar, {proc.refusal()}", False
        results.append(Result(1, name, outcome, bad, proc.seconds, proc.code,
                              f"held {held:.2f} bar"))
    return results


# 2 ------------------------------------------------------------------------------------------

def finding_2(env: Env, rng: random.Random) -> list[Result]:
    results = []
    one_step = env.write("one_step.toml", set_key(env.fast_text, "sequence", "pressures_bar",
                                                  "[0.5]"))
    seconds = ["--seconds", "1"]
    second = [("acquire, same --out", lambda t: acquire_args(env.fast_config, t / "runs")),
              ("acquire, other --out", lambda t: acquire_args(env.fast_config, t / "other")),
              ("acquire real clock", lambda t: acquire_args(one_step, t / "other", "--clock",
                                                            "real")),
              ("tare", lambda t: ["tare", "--config", env.fast_config, *seconds]),
              ("calibrate-loadcell", lambda t: ["calibrate-loadcell", "--config",
                                                env.fast_config, "--masses", "0,1", *seconds]),
              ("vent", lambda t: ["vent", "--config", env.fast_config])]
    for name, argv in second:
        t = env.fresh("owner")
        first = env.start(acquire_args(env.fast_config, t / "runs", "--clock", "real"),
                          t / "state")
        if pressurised(t / "runs", first) is None:
            stop(first)
            results.append(Result(2, name, "first run never pressurised", False, 0.0))
            continue
        time.sleep(rng.uniform(0.0, 0.5))
        proc = env.run(argv(t), state=t / "state", timeout=40)
        first_alive = first.poll() is None
        stop(first)
        basic = proc.basic()
        if basic:
            outcome, bad = basic
        elif name == "vent":
            said = any(w in proc.err.lower() for w in ("run", "in use", "held"))
            bad = proc.code == 0 and not said
            outcome = "vented silently under a live run" if bad else \
                f"{proc.refusal()}, the run {'kept' if first_alive else 'asked to stop'}"
        else:
            bad = proc.code == 0
            outcome = "second process ran on the held bench" if bad else proc.refusal()
        results.append(Result(2, name, outcome, bad, proc.seconds, proc.code))
    return results


# 3 and 4 ------------------------------------------------------------------------------------

SMALL_CELL = {("loadcell", "capacity_N"): "300", ("loadcell", "sensitivity_N_per_V"): "30",
              ("safety", "tare_max_std_N"): "2.0", ("safety", "tare_max_shift_N"): "20.0"}
INTERLOCKS = [  # (section, key): absurd values; every one outside physical bounds
    (("safety", "pressure_tolerance_bar"), ["4.5", "10", "100", "1e9", "inf"]),
    (("safety", "pressure_follow_s"), ["600", "3600", "1e9", "inf"]),
    (("safety", "tare_max_std_N"), ["200", "1e4", "1e9", "inf"]),
    (("safety", "tare_max_shift_N"), ["1e4", "1e9", "inf"]),
    (("safety", "force_limit_fraction"), ["1.5", "10", "1e9"]),
    (("safety", "vent_below_bar"), ["2", "10", "1e9"]),
    (("safety", "vent_timeout_s"), ["1e6", "1e9"]),
    (("muscle", "D0_mm"), ["1e-300", "1e-9", "0.001", "1e9"]),
    (("muscle", "L0_mm"), ["1e-9", "1e-300", "1e9"]),
    (("muscle", "t0_mm"), ["1e-300", "1e6", "20"]),
    (("loadcell", "capacity_N"), ["1e300", "1e9"]),
    (("regulator", "max_pressure_bar"), ["100", "1e9"]),
    (("regulator", "full_scale_bar"), ["1e9"]),
]
CELLS = [("300 N cell", SMALL_CELL),
         ("100 N cell", {**SMALL_CELL, ("loadcell", "capacity_N"): "100",
                         ("loadcell", "sensitivity_N_per_V"): "10",
                         ("safety", "tare_max_shift_N"): "10.0"}),
         ("500 N cell", {**SMALL_CELL, ("loadcell", "capacity_N"): "500",
                         ("loadcell", "sensitivity_N_per_V"): "50"})]
ENDLESS = [
    (("sequence", "tare_s"), ["1e6", "1e9"]),
    (("sequence", "preconditioning_hold_s"), ["1e6", "1e9"]),
    (("sequence", "preconditioning_cycles"), ["1000000", "1000000000"]),
    (("sequence", "repeats"), ["1000000", "1000000000"]),
    (("sequence", "pressures_bar"), ['"0.0001:2.5:0.0001"', '"0.001:2.5:0.00001"']),
    (("settle", "hold_s"), ["1e6", "1e9"]),
    (("settle", "timeout_s"), ["1e6", "1e9"]),
    (("settle", "min_dwell_s"), ["1e6", "1e9"]),
    (("settle", "window_s"), ["1e6", "1e9"]),
    (("sim", "buffer_s"), ["0.01", "1e-6"]),
    (("sim.faults", "stall_s"), ["1e8", "1e12"]),
    (("sequence", "max_duration_h"), ["1e6", "inf"]),
]


def _with_cell(edits: dict, key: tuple, value: str) -> dict:
    """A capacity with the sensitivity that keeps it 10 V full scale (the edit tested is the
    capacity, not a mismatch with the sensitivity)."""
    edits = {key: value}
    if key == ("loadcell", "capacity_N"):
        edits[("loadcell", "sensitivity_N_per_V")] = repr(float(value) / 10.0)
    if key == ("sim.faults", "stall_s"):
        edits[("sim.faults", "stall_at_s")] = "5.0"
    return edits


def config_trials(env: Env, rng: random.Random, finding: int, n: int) -> list[Result]:
    table = INTERLOCKS if finding == 3 else ENDLESS
    pairs = [(key, value) for key, values in table for value in values]
    cases = [(f"{s}.{k} = {v}", _with_cell({}, (s, k), v)) for (s, k), v in pairs]
    if finding == 3:
        cases += [(name, edits) for name, edits in CELLS]
    rng.shuffle(cases)
    while len(cases) < n:  # pairs of absurd settings
        (a, ea), (b, eb) = rng.sample(cases[:len(pairs)], 2)
        cases.append((f"{a}; {b}", {**ea, **eb}))
    results = []
    for k, (name, edits) in enumerate(cases[:n]):
        config = env.write(f"c{finding}-{k}.toml", edit_config(env.base_text, edits))
        t = env.fresh("check")
        proc = env.run(["check", "--config", config], state=t / "state")
        basic = proc.basic()
        warned = "warning" in proc.err.lower()
        if basic:
            outcome, bad = basic
        elif proc.code == 0 and not warned:
            outcome, bad = "accepted without a warning", True
        else:
            outcome, bad = ("accepted with a warning" if proc.code == 0 else proc.refusal()), \
                False
        results.append(Result(finding, name, outcome, bad, proc.seconds, proc.code,
                              proc.err.strip().splitlines()[-1][:160] if proc.err.strip()
                              else ""))
    return results


def endless_acquisitions(env: Env, rng: random.Random) -> list[Result]:
    cases = [{("settle", "hold_s"): "1e9"}, {("sequence", "tare_s"): "1e9"},
             {("sim.faults", "stall_s"): "1e8", ("sim.faults", "stall_at_s"): "3.0"}]
    results = []
    for k, edits in enumerate(cases):
        config = env.write(f"endless{k}.toml", edit_config(env.fast_text, edits))
        t = env.fresh("endless")
        proc = env.run(acquire_args(config, t / "runs"), state=t / "state", timeout=20)
        name = "acquire " + ", ".join(f"{s}.{key} = {v}" for (s, key), v in edits.items())
        if proc.hung:
            size = sum(p.stat().st_size for p in (t / "runs").rglob("*") if p.is_file())
            outcome, bad = f"still running after 20 s ({size / 1e6:.0f} MB written)", True
        else:
            basic = proc.basic()
            outcome, bad = basic or (("ran to the end", True) if proc.code == 0
                                     else (proc.refusal(), False))
        results.append(Result(4, name, outcome, bad, proc.seconds, proc.code))
    return results


# 5 ------------------------------------------------------------------------------------------

def finding_5(env: Env, rng: random.Random, sizes: dict, n: int = 10) -> list[Result]:
    largest = max(sizes.values())
    limits = sorted({int(200 * (2 * largest / 200) ** (k / (n - 1)) * rng.uniform(0.9, 1.0))
                     for k in range(n)})
    results = []
    for limit in limits:
        t = env.fresh("disk")
        proc = env.run(acquire_args(env.fast_config, t / "runs"), state=t / "state",
                       fsize=limit)
        must_fail = largest > limit
        folder = run_folder(t / "runs")
        status = None
        if folder and (folder / "run.json").exists():
            try:
                status = json.loads((folder / "run.json").read_text()).get("status")
            except (ValueError, AttributeError):
                status = "unreadable"
        basic = proc.basic()
        if basic:
            outcome, bad = basic
        elif folder is not None and status is None:
            outcome, bad = "folder without run.json", True
        elif status == "running":
            outcome, bad = f"run.json left running, {proc.refusal()}", True
        elif must_fail and proc.code == 0:
            outcome, bad = "a write failed, exit 0", True
        else:
            outcome, bad = (proc.refusal() if proc.code else "complete"), False
        results.append(Result(5, f"files limited to {limit} bytes", outcome, bad, proc.seconds,
                              proc.code, f"run.json status {status}"))
    return results


# 6 and 7: hostile run folders ---------------------------------------------------------------

def _csv_edit(name: str, column: str, value: str, row: int | None = None):
    def edit(folder: Path, rng: random.Random):
        path = folder / name
        lines = path.read_text().splitlines()
        header = lines[0].split(",")
        col = header.index(column) if column in header else 0
        k = row if row is not None else rng.randrange(1, len(lines))
        cells = lines[k].split(",")
        cells[col] = value
        lines[k] = ",".join(cells)
        path.write_text("\n".join(lines) + "\n")
    return edit


def _json_edit(*path_keys, value):
    def edit(folder: Path, rng: random.Random):
        meta = json.loads((folder / "run.json").read_text())
        target = meta
        for key in path_keys[:-1]:
            target = target[key]
        target[path_keys[-1]] = value() if callable(value) else value
        (folder / "run.json").write_text(json.dumps(meta))
    return edit


def _write(name: str, content: str | bytes):
    def edit(folder: Path, rng: random.Random):
        path = folder / name
        if isinstance(content, bytes):
            path.write_bytes(content)
        else:
            path.write_text(content)
    return edit


def _remove(name: str):
    def edit(folder: Path, rng: random.Random):
        (folder / name).unlink()
    return edit


def _deep(n: int) -> str:
    return "[" * n + "]" * n


NUMERIC = ["time_s", "pressure_bar", "loadcell_V", "force_N", "step", "sample"]
STEP_NUMERIC = ["pressure_bar_mean", "force_N_mean", "n", "set_pressure_bar", "settle_s"]
FOLDER_EDITS = [
    ("samples.csv missing", _remove("samples.csv")),
    ("steps.csv missing", _remove("steps.csv")),
    ("commands.csv missing", _remove("commands.csv")),
    ("run.json missing", _remove("run.json")),
    ("config.toml missing", _remove("config.toml")),
    *[(f"text in samples.csv {c}", _csv_edit("samples.csv", c, "abc")) for c in NUMERIC],
    *[(f"text in steps.csv {c}", _csv_edit("steps.csv", c, "x1")) for c in STEP_NUMERIC],
    ("steps.csv settled = maybe", _csv_edit("steps.csv", "settled", "maybe", row=1)),
    ("force 1e308 in samples.csv", _csv_edit("samples.csv", "force_N", "1e308")),
    ("force 1e308 in steps.csv", _csv_edit("steps.csv", "force_N_mean", "1e308", row=1)),
    ("force -inf in steps.csv", _csv_edit("steps.csv", "force_N_mean", "-inf", row=2)),
    ("nan pressure in steps.csv", _csv_edit("steps.csv", "pressure_bar_mean", "nan", row=1)),
    ("run.json nested 100000 deep", _write("run.json", _deep(100_000))),
    ("run.json gaps nested 100000 deep", _write("run.json", '{"gaps": ' + _deep(100_000) + "}")),
    ("run.json a list", _write("run.json", "[1, 2, 3]")),
    ("run.json empty", _write("run.json", "")),
    ("run.json invalid UTF-8", _write("run.json", b"\xff\xfe{\x00")),
    ("gaps a string", _json_edit("gaps", value="soon")),
    ("gaps a list of strings", _json_edit("gaps", value=["a", "b"])),
    ("gaps [[1]]", _json_edit("gaps", value=[[1]])),
    ("gaps of dicts", _json_edit("gaps", value=[{"start": "x"}])),
    ("process a string", _json_edit("process", value="pid")),
    ("process pid a string", _json_edit("process", "pid", value="abc")),
    ("process pid 1e30", _json_edit("process", "pid", value=10**30)),
    ("hardware a list", _json_edit("hardware", value=[1])),
    ("hardware sim a number", _json_edit("hardware", "sim", value=7)),
    ("sequence a number", _json_edit("sequence", value=3)),
    ("sequence pressures text", _json_edit("sequence", "pressures_bar", value="lots")),
    ("muscle id with /", _json_edit("muscle", "id", value="../../escape/x")),
    ("muscle id 100000 characters", _json_edit("muscle", "id", value="m" * 100_000)),
    ("muscle missing", _json_edit("muscle", value=None)),
    ("muscle D0 text", _json_edit("muscle", "D0_mm", value="thirty")),
    ("muscle D0 negative", _json_edit("muscle", "D0_mm", value=-30.0)),
    ("muscle eps 1e308", _json_edit("muscle", "eps", value=1e308)),
    ("status a list", _json_edit("status", value=["complete"])),
    ("status unknown", _json_edit("status", value="exploded")),
    ("counters a string", _json_edit("counters", value="many")),
    ("tare a list", _json_edit("tare", value=[0.0])),
    ("calibration a string", _json_edit("calibration", value="none")),
    ("schema_version 999", _json_edit("schema_version", value=999)),
    ("schema_version text", _json_edit("schema_version", value="two")),
    ("samples.csv empty", _write("samples.csv", "")),
    ("steps.csv header only", _write("steps.csv", "step,direction\n")),
    ("samples.csv binary", _write("samples.csv", bytes(range(256)) * 4)),
    ("steps.csv a 1 MB cell", _csv_edit("steps.csv", "direction", "u" * 1_000_000, row=1)),
    ("steps.csv duplicated header", lambda f, r: (f / "steps.csv").write_text(
        (f / "steps.csv").read_text().replace("force_N_mean", "pressure_bar_mean", 1))),
]
FORMULA_EDITS = [  # (name, edit of the folder, new folder name or None, command)
    ("folder named =HYPERLINK(1)", None, "=HYPERLINK(1)", "report"),
    ("folder named @SUM(1)", None, "@SUM(1)", "report"),
    ("muscle id =HYPERLINK(1)", _json_edit("muscle", "id", value="=HYPERLINK(1)"), None,
     "report"),
    ("flags =cmd|' /C calc'!A0", _csv_edit("samples.csv", "flags", "=cmd|' /C calc'!A0", 1),
     None, "reprocess"),
    ("flags +cmd", _csv_edit("samples.csv", "flags", "+cmd|x", 2), None, "reprocess"),
    ("flags @SUM", _csv_edit("samples.csv", "flags", "@SUM(A1)", 3), None, "reprocess"),
    ("muscle id <img src=x onerror=alert(1)>",
     _json_edit("muscle", "id", value="<img src=x onerror=alert(1)>"), None, "reprocess"),
    ("muscle id =1+1", _json_edit("muscle", "id", value="=1+1"), None, "reprocess"),
    ("muscle id -2+3", _json_edit("muscle", "id", value="-2+3"), None, "reprocess"),
    ("steps.csv direction =1+1", _csv_edit("steps.csv", "direction", "=1+1", 1), None,
     "reprocess"),
]


def _commands(env: Env, folder: Path, t: Path) -> dict:
    return {"report": ["report", folder, "--models", "eq2", "--out", t / "report",
                       "--no-progress"],
            "reprocess": ["reprocess", folder, "--config", env.base_config, "--out", t / "rp"],
            "fem calibrate": ["fem", "calibrate", "--model", "eq2", "--reference", folder]}


def hostile_folders(env: Env, rng: random.Random, base: Path, n: int) -> list[Result]:
    edits = list(FOLDER_EDITS)
    rng.shuffle(edits)
    results = []
    for k in range(n):
        name, edit = edits[k % len(edits)]
        t = env.fresh("folder")
        folder = t / base.name
        shutil.copytree(base, folder)
        edit(folder, rng)
        for command, argv in _commands(env, folder, t).items():
            proc = env.run(argv, state=t / "state")
            outcome, bad = proc.basic() or (proc.refusal(), False)
            results.append(Result(6, f"{name} | {command}", outcome, bad, proc.seconds,
                                  proc.code))
    return results


def finding_7(env: Env, rng: random.Random, base: Path) -> list[Result]:
    results = []
    for name, edit, rename, command in FORMULA_EDITS:
        t = env.fresh("formula")
        folder = t / "in" / (rename or base.name)
        shutil.copytree(base, folder)
        if edit:
            edit(folder, rng)
        out = t / "out"
        argv = _commands(env, folder, out)[command]
        out.mkdir()
        proc = env.run(argv, state=t / "state")
        leaked = formula_cells(out)
        hostile_dirs = [p.name for p in out.rglob("*") if p.is_dir()
                        and any(s in p.name for s in ("<img", "=", "@SUM", "+cmd"))]
        basic = proc.basic()
        if basic:
            outcome, bad = basic
        elif leaked:
            outcome, bad = f"formula in {leaked[0]}", True
        elif hostile_dirs:
            outcome, bad = f"folder {hostile_dirs[0][:40]!r} created", True
        else:
            outcome, bad = (proc.refusal() if proc.code else "written, neutralised"), False
        results.append(Result(7, f"{name} | {command}", outcome, bad, proc.seconds, proc.code))
    return results


# 6 (configs and model folders) and 8 ---------------------------------------------------------

def hostile_configs(env: Env) -> list[Result]:
    device = next(line for line in env.base_text.splitlines() if line.startswith("device ="))
    cases = [
        ("500-deep inline table", "[muscle]\nid = " + "{a = " * 500 + "1" + "}" * 500 + "\n"),
        ("100000-character device name", env.base_text.replace(
            device, f'device = "{"D" * 100_000}"')),
        ("empty file", ""),
        ("binary bytes", bytes(range(256))),
        ("invalid UTF-8", b"[muscle]\nid = \"\xff\xfe\"\n"),
        ("[[muscle]] array of tables", env.base_text.replace("[muscle]", "[[muscle]]")),
        ("duplicated key", env.base_text.replace("[muscle]", "[muscle]\nD0_mm = 30.0")),
        ("muscle id 100000 characters", set_key(env.base_text, "muscle", "id",
                                                f'"{"m" * 100_000}"')),
        ("muscle id with /", set_key(env.base_text, "muscle", "id", '"../../x"')),
        ("daq a string", env.base_text.replace("[daq]", "daq = 'x'\n[daq0]")),
    ]
    results = []
    for k, (name, text) in enumerate(cases):
        path = env.write(f"hostile{k}.toml", text)
        t = env.fresh("config")
        proc = env.run(["check", "--config", path], state=t / "state")
        outcome, bad = proc.basic() or (proc.refusal(), False)
        results.append(Result(6, f"config: {name}", outcome, bad, proc.seconds, proc.code))
    t = env.fresh("config")
    for name, path in (("a folder", t), ("a missing file", t / "none.toml")):
        proc = env.run(["check", "--config", path], state=t / "state")
        outcome, bad = proc.basic() or (proc.refusal(), False)
        results.append(Result(6, f"config: {name}", outcome, bad, proc.seconds, proc.code))
    return results


def _meta_edit(change):
    def edit(folder: Path, rng: random.Random):
        path = folder / "metadata.json"
        meta = json.loads(path.read_text())
        meta = change(meta)
        path.write_text(json.dumps(meta) if not isinstance(meta, str) else meta)
    return edit


def _set(meta, keys, value):
    target = meta
    for key in keys[:-1]:
        target = target.setdefault(key, {}) if isinstance(target, dict) else target
    if isinstance(target, dict):
        target[keys[-1]] = value
    return meta


MODEL_EDITS = [
    ("metadata.json a list", _meta_edit(lambda m: [m])),
    ("checks a string", _meta_edit(lambda m: _set(m, ["checks"], "all good"))),
    ("checks a list of numbers", _meta_edit(lambda m: _set(m, ["checks"], [1, 2]))),
    ("metadata.json nested 100000 deep", _meta_edit(lambda m: _deep(100_000))),
    ("metadata.json not JSON", _meta_edit(lambda m: "{kind: physics")),
    ("metadata.json empty", _meta_edit(lambda m: "")),
    ("metadata.json missing", lambda f, r: (f / "metadata.json").unlink()),
    ("estimator file missing", lambda f, r: [p.unlink() for p in f.glob("*.skops")]),
    ("estimator file garbage", lambda f, r: [p.write_bytes(b"PK\x03\x04" + bytes(300))
                                             for p in f.glob("*.skops")]),
    ("estimator file empty", lambda f, r: [p.write_bytes(b"") for p in f.glob("*.skops")]),
    ("kind a number", _meta_edit(lambda m: _set(m, ["kind"], 7))),
    ("kind unknown", _meta_edit(lambda m: _set(m, ["kind"], "oracle"))),
    ("box a list", _meta_edit(lambda m: _set(m, ["box"], [1, 2]))),
    ("box bounds text", _meta_edit(lambda m: _set(m, ["box", "D0_mm"], ["a", "b"]))),
    ("inputs a string", _meta_edit(lambda m: _set(m, ["inputs"], "D0_mm"))),
    ("fixed a list", _meta_edit(lambda m: _set(m, ["fixed"], [1]))),
    ("sha256 a number", _meta_edit(lambda m: _set(m, ["sha256"], 12))),
    ("dataset a string", _meta_edit(lambda m: _set(m, ["dataset"], "x"))),
    ("metrics nested", _meta_edit(lambda m: _set(m, ["metrics"], {"a": {"b": {"c": []}}}))),
    ("random_state text", _meta_edit(lambda m: _set(m, ["random_state"], "zero"))),
    ("an empty folder", lambda f, r: [p.unlink() for p in f.iterdir()]),
]
WIDENED = [  # (name, edit, D0 mm, pressures bar) of a point outside the trained box
    ("box D0 widened to 1..1000 mm", _meta_edit(lambda m: _set(m, ["box", "D0_mm"], [1, 1000])),
     500, "1,2"),
    ("box D0 widened, dataset box too", _meta_edit(lambda m: _set(
        _set(m, ["box", "D0_mm"], [1, 1000]), ["dataset", "box", "D0_mm"], [1, 1000])),
     500, "1,2"),
    ("box pressure widened to 0..10 bar", _meta_edit(
        lambda m: _set(m, ["box", "pressure_bar"], [0, 10])), 35, "8,10"),
    ("box D0 widened to 0..100 mm", _meta_edit(lambda m: _set(m, ["box", "D0_mm"], [0, 100])),
     80, "1,2"),
    ("box removed", _meta_edit(lambda m: {k: v for k, v in m.items() if k != "box"}), 500,
     "1,2"),
]


def _predicts_outside(out: str) -> bool:
    rows = list(csv.DictReader(out.splitlines()))
    return any(r.get("valid") == "True" and r.get("in_domain", "True") == "True" for r in rows)


def model_trials(env: Env, rng: random.Random, model: Path, n: int) -> list[Result]:
    results = []
    edits = [(6, name, edit, 35, "1,2") for name, edit in MODEL_EDITS]
    edits = edits[:max(0, n - len(WIDENED))] + [(8, *w) for w in WIDENED]
    for finding, name, edit, D0, pressures in edits:
        t = env.fresh("model")
        folder = t / "model"
        shutil.copytree(model, folder)
        edit(folder, rng)
        proc = env.run(["fem", "solve", "--model", f"surrogate:path={folder}", "--D0", D0,
                        "--t0", "2.5", "--eps", "0.05", "--pressures", pressures],
                       state=t / "state")
        basic = proc.basic()
        if basic:
            outcome, bad = basic
        elif finding == 8 and proc.code == 0 and _predicts_outside(proc.out):
            outcome, bad = "valid and in_domain outside the trained box", True
        else:
            outcome, bad = (proc.refusal() if proc.code else "predicted"), False
        results.append(Result(finding, f"model: {name}", outcome, bad, proc.seconds,
                              proc.code))
    return results


# 9 ------------------------------------------------------------------------------------------

COUNTER = (
    "import sys\n"
    "try:\n"
    "    from mkm.bench.storage import load_run\n"
    "except ImportError:\n"
    "    from bench.storage import load_run\n"
    "meta = load_run(sys.argv[1]).meta\n"
    "counters = meta['counters'] if isinstance(meta, dict) else meta.counters\n"
    "print(counters['samples'])\n")


def finding_9(env: Env, rng: random.Random, base: Path, n: int = 4) -> list[Result]:
    results = []
    for _ in range(n):  # SIGKILL: the sample counter the loader reports
        t = env.fresh("kill")
        proc = env.start(acquire_args(env.fast_config, t / "runs", "--clock", "real"),
                         t / "state")
        folder = pressurised(t / "runs", proc)
        time.sleep(rng.uniform(0.1, 2.0))
        os.killpg(proc.pid, signal.SIGKILL)
        proc.communicate()
        if folder is None:
            results.append(Result(9, "SIGKILL", "never pressurised", False, 0.0))
            continue
        rows = len((folder / "samples.csv").read_text().splitlines()) - 1
        try:
            counted = int(env.snippet(COUNTER, str(folder)))
            bad = counted != rows
            outcome = f"counter {counted} against {rows} rows" if bad else "counter = rows"
        except RuntimeError as exc:
            bad, outcome = True, f"loader failed: {str(exc).strip().splitlines()[-1][:80]}"
        results.append(Result(9, "SIGKILL during a run", outcome, bad, 0.0))
        env.run(["vent", "--config", env.fast_config], state=t / "state")
    for _ in range(n):  # SIGINT twice
        t = env.fresh("sigint2")
        proc = env.start(acquire_args(env.fast_config, t / "runs", "--clock", "real"),
                         t / "state")
        pressurised(t / "runs", proc)
        time.sleep(rng.uniform(0.0, 1.0))
        gap = rng.uniform(0.005, 0.08)
        proc.send_signal(signal.SIGINT)
        time.sleep(gap)
        if proc.poll() is None:
            proc.send_signal(signal.SIGINT)
        out = stop(proc)
        basic = out.basic()
        outcome, bad = basic or ((f"exit {out.code}", out.code != 130))
        results.append(Result(9, f"SIGINT twice, {gap * 1e3:.0f} ms apart", outcome, bad,
                              out.seconds, out.code))
    for _ in range(n):  # SIGINT during start-up
        t = env.fresh("sigint-start")
        proc = env.start(acquire_args(env.fast_config, t / "runs"), t / "state")
        delay = rng.uniform(0.05, 0.8)
        time.sleep(delay)
        out = stop(proc)
        outcome, bad = out.basic() or (f"exit {out.code}", False)
        results.append(Result(9, f"SIGINT {delay:.2f} s after start", outcome, bad,
                              out.seconds, out.code))
    t = env.fresh("mkm-out")
    proc = env.run(["report", base, "--models", "eq2", "--no-progress"], state=t / "state",
                   extra_env={"MKM_OUT": str(t / "X")})
    basic = proc.basic()
    if basic:
        outcome, bad = basic
    elif (t / "X" / "report.html").exists():
        outcome, bad = "written into MKM_OUT itself", True
    else:
        outcome, bad = ("under MKM_OUT/report/" if (t / "X" / "report").is_dir()
                        else proc.refusal()), False
    results.append(Result(9, "MKM_OUT=X mkm report RUN", outcome, bad, proc.seconds,
                          proc.code))
    return results


# the whole corpus ---------------------------------------------------------------------------

def record_base(env: Env) -> tuple[Path, dict]:
    t = env.fresh("base")
    proc = env.run(acquire_args(env.fast_config, t / "runs"), state=t / "state")
    folder = run_folder(t / "runs")
    if proc.code != 0 or folder is None:
        raise RuntimeError(f"the base run failed: {proc.err[-2000:]}")
    # a first report trains the report's surrogate into the cache (minutes): not a trial
    proc = env.run(["report", folder, "--models", "eq2", "--out", t / "report",
                    "--no-progress"], state=t / "state", timeout=1200)
    if proc.code != 0:
        raise RuntimeError(f"the base report failed: {proc.err[-2000:]}")
    return folder, {p.name: p.stat().st_size for p in folder.iterdir()}


def train_model(env: Env) -> Path:
    out = env.root / "model"
    proc = env.run(["surrogate", "train", "--kind", "physics", "--splits", "0", "--out", out,
                    "--no-progress"], timeout=600)
    if proc.code != 0:
        raise RuntimeError(f"training failed: {proc.err[-2000:]}")
    return out


def run_all(env: Env, seed: int, only: set[int], folders: int, configs: int,
            models: int) -> list[Result]:
    results: list[Result] = []

    def rng(finding):
        return random.Random(f"{seed}-{finding}")

    base, sizes = record_base(env)
    steps = [
        (1, lambda: finding_1(env, rng(1))),
        (2, lambda: finding_2(env, rng(2))),
        (3, lambda: config_trials(env, rng(3), 3, configs * 6 // 10)),
        (4, lambda: config_trials(env, rng(4), 4, configs - configs * 6 // 10)
         + endless_acquisitions(env, rng(4))),
        (5, lambda: finding_5(env, rng(5), sizes)),
        (6, lambda: hostile_folders(env, rng(6), base, folders) + hostile_configs(env)),
        (7, lambda: finding_7(env, rng(7), base)),
        (8, lambda: model_trials(env, rng(8), train_model(env), models)),
        (9, lambda: finding_9(env, rng(9), base)),
    ]
    for finding, step in steps:
        if finding in only:
            start = time.perf_counter()
            found = step()
            results += found
            print(f"finding {finding}: {len(found)} trials, {sum(r.bad for r in found)} bad, "
                  f"{time.perf_counter() - start:.0f} s", file=sys.stderr, flush=True)
    return results


def table(results: list[Result]) -> str:
    lines = ["| # | finding | trials | bad | outcomes (bad ones starred) |",
             "|---|---|---|---|---|"]
    by = {}
    for r in results:
        by.setdefault(r.finding, []).append(r)
    for finding, rows in sorted(by.items()):
        counts = Counter((r.outcome.split(" (")[0] if not r.bad else "*" + r.outcome[:60])
                         for r in rows)
        shown = "; ".join(f"{o} x{c}" for o, c in counts.most_common(6))
        lines.append(f"| {finding} | {FINDINGS[finding]} | {len(rows)} | "
                     f"{sum(r.bad for r in rows)} | {shown} |")
    lines.append(f"| | all | {len(results)} | {sum(r.bad for r in results)} | |")
    return "\n".join(lines)


@dataclass
class Report:
    mkm: str
    seed: int
    seconds: float
    results: list[Result] = field(default_factory=list)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--mkm", default=str(Path(sys.executable).with_name("mkm")),
                        help="the mkm to try (default: this interpreter's)")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--folders", type=int, default=30,
                        help="hostile run folders, each through three commands (default 30)")
    parser.add_argument("--configs", type=int, default=70,
                        help="altered configurations of findings 3 and 4 (default 70)")
    parser.add_argument("--models", type=int, default=26,
                        help="tampered model folders of findings 6 and 8 (default 26)")
    parser.add_argument("--only", default="1,2,3,4,5,6,7,8,9",
                        help="comma list of findings to try")
    parser.add_argument("--timeout", type=float, default=60.0,
                        help="seconds before a command counts as a hang (default 60)")
    parser.add_argument("--json", help="write every trial with its outcome here")
    parser.add_argument("--keep", action="store_true", help="keep the scratch folder")
    parser.add_argument("--cache", help="MKM_CACHE_DIR of the trials, kept between runs (one "
                        "per environment; default: in the scratch folder)")
    args = parser.parse_args(argv)
    only = {int(x) for x in args.only.split(",")}
    root = Path(tempfile.mkdtemp(prefix="mkm-hostile-"))
    start = time.perf_counter()
    try:
        env = Env(args.mkm, root, args.timeout, Path(args.cache) if args.cache
                  else root / "cache")
        results = run_all(env, args.seed, only, args.folders, args.configs, args.models)
    finally:
        if not args.keep:
            shutil.rmtree(root, ignore_errors=True)
    seconds = time.perf_counter() - start
    print(table(results))
    print(f"\n{args.mkm}, seed {args.seed}: {len(results)} trials in {seconds:.0f} s")
    if args.json:
        from mkm.core.records import provenance

        report = Report(args.mkm, args.seed, round(seconds, 1), results)
        Path(args.json).write_text(json.dumps({**asdict(report), "provenance": provenance()},
                                              indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
