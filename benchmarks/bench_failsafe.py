"""Hostile trials of issue 35, per finding: seeded hostile cases run through an installed `mkm`
as subprocesses (the harness of `bench_hostile.py`), each outcome classified.

    .venv/bin/python benchmarks/bench_failsafe.py [--mkm PATH] [--seed 0] [--only 1,2]
        [--timeout 60] [--json FILE]

`--mkm` names the `mkm` of another environment (an older checkout's venv, for the "before"
column); inputs are built from that environment's own packaged configuration. Per finding:

1. `mkm vent` with a broken bench state folder (the lock a folder or a pipe, the benches
   folder a file, the state folder a file): bad when nothing says it vented (no `vented:` on
   stdout), or a traceback;
2. a regulator overshooting at max_pressure_bar ([sim.faults] overshoot_bar, full scales and
   tolerances the configuration accepts): bad when the run exits 0 while the measured pressure
   stayed above max_pressure_bar + 2 % for more than 1 s, or exceeded it by 10 %;
3. a second `acquire` on the device a real-clock run holds, the name written another way
   (case, trailing space): bad when it runs (exit 0);
4. SIGKILL during a real-clock run, then `mkm vent`: bad when run.json still says `running`
   or its sample counter differs from the rows of samples.csv;
5. `mkm export` and `mkm reprocess` of a run without content (header-only, missing, a pipe,
   a link to /dev/zero, no finite force nor load-cell volt): bad on exit 0;
6. `mkm import` of hostile tables (0 bytes, text or random bytes named .xlsx, an XML DTD, a
   decompression bomb, a link to /etc/passwd) and `mkm report` on a full disk
   (RLIMIT_FSIZE): bad on exit 0, a traceback, a file's content in the message, a report folder
   with files but no report.html;
7. settings that fail every run or numbers that are not ASCII decimals, through `mkm check`;
   a run.json with a repeated key through `mkm export`: bad on exit 0;
8. `mkm vent`, `tare`, `calibrate-loadcell` without `--backend` and `--config`: bad on exit 0;
9. the regulator's monitor lost (0 V) during a run or before `mkm vent`: bad when the vent is
   called verified (exit 0, or run.json's vent_check verified);
10. a closed Windows console during a real-clock run (a process of that environment's Python
   calling the console handler from another thread, as Windows does), the regulator venting or
   stuck at pressure: bad when the handler is released (Windows ends the process) later than
   4.5 s after the event, or run.json then still says `running` or calls a stuck vent verified.

A traceback, a hang or death by a signal is bad in every category. Prints one Markdown table.
"""

from __future__ import annotations

import argparse
import json
import os
import random
import shutil
import signal
import sys
import tempfile
import time
import zipfile
from collections import Counter
from pathlib import Path

from bench_hostile import Env, Result, acquire_args, edit_config, pressurised, run_folder

FINDINGS = {1: "vent with a broken state folder", 2: "over-pressure on the measured pressure",
            3: "one lock per device", 4: "a killed run's folder mended",
            5: "no success without content", 6: "guarded readers",
            7: "settings, numbers, run.json keys", 8: "hardware commands name their backend",
            9: "a lost monitor is no vent", 10: "a closed console recorded in time"}


def _outcome(proc, good: str, bad_when: bool, bad: str) -> tuple[str, bool]:
    basic = proc.basic()
    if basic:
        return basic
    return (bad, True) if bad_when else (good, False)


# 1 ------------------------------------------------------------------------------------------

def finding_1(env: Env, rng: random.Random, n: int = 8) -> list[Result]:
    def lock_folder(state):
        benches = state / "benches"
        benches.mkdir(parents=True)
        for name in ("sim-Dev1.lock", "sim-dev1.lock"):
            (benches / name).mkdir()

    def lock_fifo(state):
        benches = state / "benches"
        benches.mkdir(parents=True)
        for name in ("sim-Dev1.lock", "sim-dev1.lock"):
            os.mkfifo(benches / name)

    def benches_file(state):
        state.mkdir(parents=True)
        (state / "benches").write_text("not a folder")

    def state_file(state):
        state.parent.mkdir(parents=True, exist_ok=True)
        state.write_text("not a folder")

    cases = [("lock is a folder", lock_folder), ("lock is a pipe", lock_fifo),
             ("benches is a file", benches_file), ("state folder is a file", state_file)]
    results = []
    for k in range(n):
        name, make = cases[k % len(cases)] if k < len(cases) else rng.choice(cases)
        t = env.fresh("vent-state")
        make(t / "state")
        proc = env.run(["vent", "--config", env.fast_config], state=t / "state")
        outcome, bad = _outcome(proc, f"vented, exit {proc.code}",
                                not proc.out.startswith("vented:"), "no vent")
        results.append(Result(1, name, outcome, bad, proc.seconds, proc.code))
    return results


# 2 ------------------------------------------------------------------------------------------

def finding_2(env: Env, rng: random.Random, n: int = 8) -> list[Result]:
    import pandas as pd

    results = []
    for k in range(n):
        full_scale = rng.choice([4.0, 6.0, 10.0])
        tolerance = round(0.1 * full_scale, 2)  # the largest the configuration accepts
        overshoot = round(rng.uniform(0.06, 1.0), 2)
        edits = {("regulator", "full_scale_bar"): repr(full_scale),
                 ("safety", "pressure_tolerance_bar"): repr(tolerance),
                 ("sequence", "pressures_bar"): "[2.5]",
                 ("sim.faults", "overshoot_bar"): repr(overshoot)}
        config = env.write(f"over{k}.toml", edit_config(env.fast_text, edits))
        t = env.fresh("over")
        proc = env.run(acquire_args(config, t / "runs"), state=t / "state")
        folder = run_folder(t / "runs")
        over_s, peak = 0.0, 0.0
        if folder and (folder / "samples.csv").exists():
            s = pd.read_csv(folder / "samples.csv")
            over_s = float((s["pressure_bar"] > 2.55).sum()) / 10.0  # 10 Hz samples
            peak = float(s["pressure_bar"].max())
        outcome, bad = _outcome(proc, f"stopped, exit {proc.code}",
                                proc.code == 0 and (over_s > 1.05 or peak > 2.75),
                                f"exit 0, {peak:.2f} bar held {over_s:.1f} s")
        results.append(Result(2, f"overshoot {overshoot:g} bar, full scale {full_scale:g}",
                              outcome, bad, proc.seconds, proc.code, f"peak {peak:.2f} bar"))
    return results


# 3 ------------------------------------------------------------------------------------------

def finding_3(env: Env, rng: random.Random) -> list[Result]:
    results = []
    for device in ("dev1", "DEV1", "Dev1 ", "dEv1"):
        t = env.fresh("lock")
        first = env.start(acquire_args(env.fast_config, t / "runs", "--clock", "real"),
                          t / "state")
        if pressurised(t / "runs", first) is None:
            first.kill()
            first.communicate()
            results.append(Result(3, repr(device), "first run never pressurised", False, 0.0))
            continue
        other = env.write(f"device-{len(device)}-{device.strip()}.toml",
                          edit_config(env.fast_text, {("daq", "device"): f'"{device}"'}))
        proc = env.run(acquire_args(other, t / "other"), state=t / "state")
        os.killpg(first.pid, signal.SIGINT)
        first.communicate()
        outcome, bad = _outcome(proc, f"refused, exit {proc.code}", proc.code == 0,
                                "ran beside the holder")
        results.append(Result(3, f"device {device!r} while 'Dev1' runs", outcome, bad,
                              proc.seconds, proc.code))
    return results


# 4 ------------------------------------------------------------------------------------------

def finding_4(env: Env, rng: random.Random, n: int = 4) -> list[Result]:
    results = []
    for _ in range(n):
        t = env.fresh("kill")
        proc = env.start(acquire_args(env.fast_config, Path("runs-" + t.name), "--clock",
                                      "real"), t / "state")  # relative --out, as typed
        folder = pressurised(env.cwd / ("runs-" + t.name), proc)
        time.sleep(rng.uniform(0.1, 2.0))
        os.killpg(proc.pid, signal.SIGKILL)
        proc.communicate()
        if folder is None:
            results.append(Result(4, "SIGKILL", "never pressurised", False, 0.0))
            continue
        vent = env.run(["vent", "--config", env.fast_config], state=t / "state")
        meta = json.loads((folder / "run.json").read_text())
        rows = len((folder / "samples.csv").read_text().splitlines()) - 1
        counted = meta.get("counters", {}).get("samples")
        bad = meta["status"] == "running" or counted != rows
        outcome = (f"run.json {meta['status']}, counter {counted} against {rows} rows"
                   if bad else f"mended: {meta['status']}, counter = rows")
        basic = vent.basic()
        if basic:
            outcome, bad = basic
        results.append(Result(4, "SIGKILL, then mkm vent", outcome, bad, vent.seconds,
                              vent.code))
    return results


# 5 ------------------------------------------------------------------------------------------

def _damage(folder: Path, how: str) -> None:
    samples = folder / "samples.csv"
    lines = samples.read_text().splitlines()
    if how == "header only":
        samples.write_text(lines[0] + "\n")
    elif how == "missing":
        samples.unlink()
    elif how == "a pipe":
        samples.unlink()
        os.mkfifo(samples)
    elif how == "link to /dev/zero":
        samples.unlink()
        samples.symlink_to("/dev/zero")
    else:  # no finite force, and no raw volts to recompute one from
        header = lines[0].split(",")
        rows = [r.split(",") for r in lines[1:]]
        for r in rows:
            for column in ("force_N", "loadcell_V"):
                r[header.index(column)] = ""
        samples.write_text("\n".join([lines[0], *(",".join(r) for r in rows)]) + "\n")


def finding_5(env: Env, rng: random.Random) -> list[Result]:
    results = []
    base_runs = env.fresh("base5")
    env.run(acquire_args(env.fast_config, base_runs))
    base = run_folder(base_runs)
    loadcell = env.write("loadcell.toml", '[loadcell]\nchannel = "ai0"\ncapacity_N = 1961.33\n'
                         "sensitivity_N_per_V = 200.0\noffset_V = 0.0\n")
    for how in ("header only", "missing", "a pipe", "link to /dev/zero", "no finite force"):
        for command in ("export", "reprocess"):
            t = env.fresh("content")
            folder = t / base.name
            shutil.copytree(base, folder)
            _damage(folder, how)
            argv = (["export", folder, "--out", t / "out.xlsx"] if command == "export" else
                    ["reprocess", folder, "--config", loadcell, "--out", t / "re"])
            proc = env.run(argv, timeout=30)
            outcome, bad = _outcome(proc, proc.refusal(), proc.code == 0, "written, exit 0")
            results.append(Result(5, f"{command}, samples.csv {how}", outcome, bad,
                                  proc.seconds, proc.code))
    return results


# 6 ------------------------------------------------------------------------------------------

DTD = (b'<?xml version="1.0"?><!DOCTYPE lolz [<!ENTITY lol "lol"><!ENTITY lol2 "&lol;&lol;'
       b'&lol;&lol;&lol;&lol;&lol;&lol;">]><worksheet xmlns="http://schemas.openxmlformats.org'
       b'/spreadsheetml/2006/main"><sheetData><row r="1"><c r="A1" t="inlineStr"><is><t>'
       b"&lol2;</t></is></c></row></sheetData></worksheet>")


def _workbook(env: Env, path: Path, sheet: bytes | None = None, pad: int = 0) -> None:
    env.snippet("import sys, pandas as pd\n"
                "pd.DataFrame({'pressure_bar': [0.5, 1.0], 'force_N': [10.0, 20.0]})"
                ".to_excel(sys.argv[1], index=False)\n", str(path))
    with zipfile.ZipFile(path) as old:
        members = {m.filename: old.read(m) for m in old.infolist()}
    if sheet is not None:
        members["xl/worksheets/sheet1.xml"] = sheet
    if pad:
        members["xl/media/pad.bin"] = b"\0" * pad
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as new:
        for name, data in members.items():
            new.writestr(name, data)


def finding_6(env: Env, rng: random.Random) -> list[Result]:
    results = []
    muscle = ["--id", "lab-7", "--D0", "30", "--t0", "3", "--L0", "282", "--eps", "0.1"]
    cases = {
        "0-byte .csv": lambda p: p.write_bytes(b""),
        "text named .xlsx": lambda p: p.write_text("pressure_bar,force_N\n1,2\n"),
        "random bytes named .xlsx": lambda p: p.write_bytes(rng.randbytes(20_000)),
        "xlsx with an entity DTD": lambda p: _workbook(env, p, DTD),
        "xlsx expanding to 300 MB": lambda p: _workbook(env, p, pad=300_000_000),
        "link to /etc/passwd": lambda p: p.symlink_to("/etc/passwd"),
    }
    for name, make in cases.items():
        t = env.fresh("import")
        suffix = ".csv" if "csv" in name or "passwd" in name else ".xlsx"
        table = t / f"table{suffix}"
        make(table)
        proc = env.run(["import", table, *muscle, "--out", t / "runs"])
        leaked = "root:" in proc.err
        outcome, bad = _outcome(proc, proc.refusal(), proc.code == 0 or leaked,
                                "file content printed" if leaked else "imported, exit 0")
        results.append(Result(6, f"import {name}", outcome, bad, proc.seconds, proc.code))
    base_runs = env.fresh("base6")
    env.run(acquire_args(env.fast_config, base_runs))
    base = run_folder(base_runs)
    # once without a limit: the surrogate the report compares is trained into the cache
    env.run(["report", base, "--models", "eq2", "--out", env.fresh("warm") / "report",
             "--no-progress"], timeout=600)
    for limit in (20_000, 200_000, 2_000_000):
        t = env.fresh("report-full")
        out = t / "report"
        proc = env.run(["report", base, "--models", "eq2", "--tolerance", "0.02", "--out", out,
                        "--no-progress"], fsize=limit)
        partial = out.is_dir() and any(out.iterdir()) and not (out / "report.html").exists()
        stray = [p.name for p in t.iterdir() if "partial" in p.name]
        outcome, bad = _outcome(proc, proc.refusal(), partial or bool(stray),
                                "partial files left")
        results.append(Result(6, f"report, disk full at {limit // 1000} kB", outcome, bad,
                              proc.seconds, proc.code))
    return results


# 7 ------------------------------------------------------------------------------------------

def finding_7(env: Env, rng: random.Random) -> list[Result]:
    results = []
    edits = [("safety", "vent_timeout_s", "1e-320"), ("safety", "pressure_follow_s", "1e-320"),
             ("safety", "force_limit_fraction", "1e-320"), ("safety", "vent_timeout_s", "0.1"),
             ("daq", "read_timeout_s", "60.0"), ("sequence", "pressures_bar", '"\u0660.\u0665"'),
             ("sequence", "pressures_bar", '"\uff10.\uff15"'),
             ("sequence", "pressures_bar", '"0.2_5"')]
    for k, (section, key, value) in enumerate(edits):
        changes = {(section, key): value}
        if key == "read_timeout_s":
            changes[("daq", "read_retries")] = "100"
        config = env.write(f"floor{k}.toml", edit_config(env.fast_text, changes))
        proc = env.run(["check", "--config", config])
        outcome, bad = _outcome(proc, proc.refusal(), proc.code == 0, "accepted, exit 0")
        results.append(Result(7, f"{section}.{key} = {value}", outcome, bad, proc.seconds,
                              proc.code))
    t = env.fresh("dupkey")
    env.run(acquire_args(env.fast_config, t / "runs"))
    folder = run_folder(t / "runs")
    text = (folder / "run.json").read_text()
    (folder / "run.json").write_text(text.replace('"status": "', '"status": "running", '
                                                  '"status": "', 1))
    proc = env.run(["export", folder, "--out", t / "out.xlsx"])
    outcome, bad = _outcome(proc, proc.refusal(), proc.code == 0, "accepted, exit 0")
    results.append(Result(7, "run.json with status twice", outcome, bad, proc.seconds,
                          proc.code))
    return results


# 8 ------------------------------------------------------------------------------------------

def finding_8(env: Env, rng: random.Random) -> list[Result]:
    results = []
    for argv in (["vent"], ["tare", "--seconds", "1"],
                 ["calibrate-loadcell", "--masses", "0,1", "--seconds", "1"]):
        t = env.fresh("nobackend")
        proc = env.run(argv, state=t / "state")
        outcome, bad = _outcome(proc, proc.refusal(), proc.code == 0,
                                "ran on the simulated bench, exit 0")
        results.append(Result(8, f"mkm {argv[0]} without --backend or --config", outcome,
                              bad, proc.seconds, proc.code))
    return results


# 9 ------------------------------------------------------------------------------------------

def finding_9(env: Env, rng: random.Random, n: int = 5) -> list[Result]:
    results = []
    for k in range(n):
        lost = round(rng.uniform(1.5, 20.0), 1)
        config = env.write(f"lost{k}.toml", edit_config(
            env.fast_text, {("sim.faults", "monitor_lost_at_s"): repr(lost)}))
        t = env.fresh("lost")
        proc = env.run(acquire_args(config, t / "runs"), state=t / "state")
        folder = run_folder(t / "runs")
        verified = False
        if folder and (folder / "run.json").exists():
            check = json.loads((folder / "run.json").read_text()).get("vent_check") or {}
            verified = bool(check.get("verified"))
        refused = "monitor_lost_at_s is not a setting" in proc.err
        outcome, bad = _outcome(proc, f"not verified, exit {proc.code}",
                                verified or proc.code == 0, "vent called verified")
        if refused:  # a version without the fault cannot be tried on it
            outcome, bad = "fault unknown to this version", False
        results.append(Result(9, f"monitor lost at {lost:g} s", outcome, bad, proc.seconds,
                              proc.code))
    config = env.write("lost-now.toml", edit_config(
        env.fast_text, {("sim.faults", "monitor_lost_at_s"): "0.0"}))
    proc = env.run(["vent", "--config", config])
    refused = "monitor_lost_at_s is not a setting" in proc.err
    outcome, bad = _outcome(proc, f"not verified, exit {proc.code}", proc.code == 0,
                            "vent called verified")
    if refused:
        outcome, bad = "fault unknown to this version", False
    results.append(Result(9, "mkm vent, monitor at 0 V", outcome, bad, proc.seconds,
                          proc.code))
    return results


CONSOLE_CLOSE = """
import json, sys, threading, time
from mkm.bench import signals
from mkm.bench.config import load_config
from mkm.bench.run import BenchRun, make_backend

event_at_s, stuck, out = float(sys.argv[1]), sys.argv[2] == "stuck", sys.argv[3]
faults = {"regulator_stuck_at_s": event_at_s - 0.1} if stuck else {}
config = load_config().replace(
    sequence={"pressures_bar": (0.5, 1.0), "tare_s": 1.0, "preconditioning_cycles": 0},
    sim={"faults": faults})
run = BenchRun(config, make_backend(config, "real"), out, notify=lambda m: None)
seen = {}

def close():
    while run.acquisition is None or run.acquisition.next_index < event_at_s * 10:
        time.sleep(0.005)
    start = time.monotonic()
    run.signals.on_console_event(signals.CTRL_CLOSE_EVENT)
    seen["released_s"] = time.monotonic() - start
    seen["meta"] = json.loads((run.recorder.path / "run.json").read_text())

closer = threading.Thread(target=close, daemon=True)
closer.start()
run.execute()
closer.join(15)
print(json.dumps({"released_s": seen["released_s"], "status": seen["meta"]["status"],
                  "verified": bool((seen["meta"].get("vent_check") or {}).get("verified"))}))
"""


def finding_10(env: Env, rng: random.Random, n: int = 4) -> list[Result]:
    results = []
    for k in range(n):
        regulator = ("venting", "stuck")[k % 2]
        event_at_s = round(1.0 + rng.uniform(0.5, 2.5), 2)  # in the first step (0.5 bar)
        t = env.fresh("console")
        start = time.perf_counter()
        try:
            seen = json.loads(env.snippet(CONSOLE_CLOSE, str(event_at_s), regulator,
                                          str(t / "runs")).splitlines()[-1])
        except (RuntimeError, ValueError, IndexError) as exc:
            results.append(Result(10, f"console closed at {event_at_s:g} s, {regulator}",
                                  f"no outcome ({str(exc).strip().splitlines()[-1][:60]})",
                                  True, time.perf_counter() - start))
            continue
        late = seen["released_s"] > 4.5
        bad = late or seen["status"] == "running" or (regulator == "stuck" and seen["verified"])
        outcome = (f"{'late' if late else 'recorded'}: {seen['status']}"
                   f"{', verified' if seen['verified'] else ''}")
        results.append(Result(10, f"console closed at {event_at_s:g} s, regulator {regulator}",
                              outcome, bad, time.perf_counter() - start, None,
                              f"released {seen['released_s']:.2f} s after the event"))
    return results


STEPS = {1: finding_1, 2: finding_2, 3: finding_3, 4: finding_4, 5: finding_5, 6: finding_6,
         7: finding_7, 8: finding_8, 9: finding_9, 10: finding_10}


def summary(results: list[Result]) -> list[dict]:
    """One row per finding: its trials, the bad ones, the commonest outcomes (bad ones starred)."""
    by: dict[int, list[Result]] = {}
    for r in results:
        by.setdefault(r.finding, []).append(r)
    rows = []
    for finding, found in sorted(by.items()):
        counts = Counter(("*" if r.bad else "") + r.outcome[:50] for r in found)
        rows.append({"#": finding, "finding": FINDINGS[finding], "trials": len(found),
                     "bad": sum(r.bad for r in found),
                     "outcomes": "; ".join(f"{o} x{c}" for o, c in counts.most_common(5))})
    return rows


def table(results: list[Result]) -> str:
    lines = ["| # | finding | trials | bad | outcomes (bad ones starred) |",
             "|---|---|---|---|---|"]
    lines += [f"| {r['#']} | {r['finding']} | {r['trials']} | {r['bad']} | {r['outcomes']} |"
              for r in summary(results)]
    lines.append(f"| | all | {len(results)} | {sum(r.bad for r in results)} | |")
    return "\n".join(lines)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--mkm", default=str(Path(sys.executable).with_name("mkm")),
                        help="the mkm to try (default: this interpreter's)")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--only", default=",".join(map(str, STEPS)),
                        help="comma list of findings to try")
    parser.add_argument("--timeout", type=float, default=60.0,
                        help="seconds before a command counts as a hang (default 60)")
    parser.add_argument("--json", help="write every trial with its outcome here")
    args = parser.parse_args(argv)
    root = Path(tempfile.mkdtemp(prefix="mkm-failsafe-"))
    start = time.perf_counter()
    results: list[Result] = []
    try:
        env = Env(args.mkm, root, args.timeout, root / "cache")
        for finding in (int(x) for x in args.only.split(",")):
            began = time.perf_counter()
            found = STEPS[finding](env, random.Random(f"{args.seed}-{finding}"))
            results += found
            print(f"finding {finding}: {len(found)} trials, {sum(r.bad for r in found)} bad, "
                  f"{time.perf_counter() - began:.0f} s", file=sys.stderr, flush=True)
    finally:
        shutil.rmtree(root, ignore_errors=True)
    seconds = time.perf_counter() - start
    print(table(results))
    print(f"\n{args.mkm}, seed {args.seed}: {len(results)} trials in {seconds:.0f} s")
    if args.json:  # the summary as "rows" (the docs' table), every trial with its outcome
        from dataclasses import asdict

        from mkm.core.records import provenance, write_atomic

        record = {**provenance(), "seed": args.seed, "total_s": round(seconds, 1),
                  "rows": summary(results), "trials": [asdict(r) for r in results]}
        write_atomic(args.json, json.dumps(record, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
