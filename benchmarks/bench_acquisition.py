"""Acquisition figures of the bench package (issues 5 and 12), measured, outside the test suite.

    .venv/bin/python benchmarks/bench_acquisition.py [--trials 5] [--skip-real] [--skip-long]

1. wall time of a one-hour run (sample time) on the virtual clock;
2. settle detection on a step that never settles, 30 min against 60 min (linear: ratio 2);
3. per stop signal (SIGINT, SIGINT twice, SIGTERM, SIGHUP, SIGKILL) on a real-clock
   `mkm acquire` process at a pressurised step: trials, exit status, run status, samples lost
   and the delay from the signal to the vent command (for SIGKILL: to the vent by the next
   `mkm vent`, start-up included);
4. per injected fault on the virtual clock: status, samples lost, exit status and the sample
   time from the fault to the vent command;
5. peak memory of reading a 24 h samples.csv (864,000 rows): whole with pandas against
   `bench.storage.aggregate_samples` (Linux: VmHWM of a fresh process).

Prints a Markdown table per part and one JSON document with every figure and the provenance.
"""

from __future__ import annotations

import argparse
import json
import os
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from mkm.bench.config import load_config
from mkm.bench.run import acquire
from mkm.bench.storage import load_run
from mkm.core.records import provenance

REPO = Path(__file__).resolve().parents[1]
FAST = "[sequence]\npressures_bar = [0.5, 1.0]\ntare_s = 1.0\npreconditioning_cycles = 0\n"
QUIET = {"notify": lambda message: None}


def one_hour_virtual(out: Path) -> dict:
    # 19 steps (0.25..2.5 bar up and down) of ~65 s (settle + 60 s hold), three repeats
    config = load_config().replace(settle={"hold_s": 60.0}, sequence={"repeats": 3})
    start = time.perf_counter()
    result = acquire(config, out_root=out, **QUIET)
    wall = time.perf_counter() - start
    run = load_run(result.path)
    sample_time = float(run.samples["time_s"].iloc[-1])
    return {"status": str(run.status), "sample_time_s": sample_time,
            "samples": len(run.samples), "wall_s": round(wall, 3),
            "wall_per_hour_s": round(wall * 3600.0 / sample_time, 3)}


def never_settling(out: Path) -> dict:
    """One step that never settles, timing out at 30 min and at 60 min (the bound): linear
    settle detection doubles the time, the old quadratic one quadrupled it."""
    walls = {}
    for minutes in (30, 60):
        config = load_config().replace(
            settle={"max_force_std_N": 0.01, "timeout_s": 60.0 * minutes},
            sequence={"pressures_bar": (0.5,), "down_sweep": False, "preconditioning_cycles": 0})
        start = time.perf_counter()
        acquire(config, out_root=out / f"m{minutes}", **QUIET)
        walls[f"{minutes}min_wall_s"] = round(time.perf_counter() - start, 2)
    walls["ratio"] = round(walls["60min_wall_s"] / walls["30min_wall_s"], 2)
    return walls


def _config_file(folder: Path) -> Path:
    text = (REPO / "bench/configs/paper_prototype.toml").read_text()
    head, _, rest = text.partition("[sequence]")
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / "mkm.bench.toml"
    path.write_text(head + FAST + rest[rest.index("[settle]"):])
    return path


def _start(folder: Path, env: dict) -> tuple[subprocess.Popen, Path]:
    config = _config_file(folder)
    proc = subprocess.Popen(
        [sys.executable, "-m", "mkm", "acquire", "--config", str(config), "--clock", "real",
         "--out", str(folder / "runs"), "--no-progress"], cwd=REPO, env=env,
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline:
        runs = list((folder / "runs").glob("*/commands.csv"))
        if runs and ",step\n" in runs[0].read_text():
            return proc, runs[0].parent
        time.sleep(0.02)
    proc.kill()
    raise RuntimeError(f"no pressurised step within 60 s: {proc.communicate()}")


def _lost(run) -> int:
    s = run.samples["sample"].to_numpy()
    return int(s[-1] + 1 - len(s)) if len(s) else 0


def signal_trials(out: Path, trials: int) -> list[dict]:
    rng = np.random.default_rng(0)
    cases = [("SIGINT", 1), ("SIGINT", 2), ("SIGTERM", 1)]
    if hasattr(signal, "SIGHUP"):
        cases.append(("SIGHUP", 1))
    if hasattr(signal, "SIGKILL"):
        cases.append(("SIGKILL", 1))
    rows = []
    for name, times in cases:
        delays, lost, statuses, codes = [], [], set(), set()
        for k in range(trials):
            folder = out / f"{name}x{times}-{k}"
            env = {**os.environ, "MKM_STATE_DIR": str(folder / "state")}
            proc, run_dir = _start(folder, env)
            time.sleep(rng.uniform(0.0, 1.0))  # at a random phase of the 0.1 s sample clock
            sent = time.time()
            for _ in range(times):
                proc.send_signal(getattr(signal, name))
                time.sleep(0.02)
            proc.communicate(timeout=60)
            codes.add(proc.returncode)
            run = load_run(run_dir)
            statuses.add(str(run.status))
            lost.append(_lost(run))
            if name == "SIGKILL":
                subprocess.run([sys.executable, "-m", "mkm", "vent", "--config",
                                str(_config_file(folder))], cwd=REPO, env=env, check=True,
                               capture_output=True)
                delays.append(time.time() - sent)
            else:
                delays.append(run.meta.vented_at_unix_s - sent)
        rows.append({"signal": name + (" twice" if times == 2 else ""), "trials": trials,
                     "exit": sorted(codes), "status": sorted(statuses),
                     "samples_lost": int(sum(lost)),
                     "vent_delay_median_s": round(float(np.median(delays)), 4),
                     "vent_delay_max_s": round(float(np.max(delays)), 4),
                     "vented_by": "next `mkm vent`" if name == "SIGKILL" else "the run itself"})
    return rows


FAULTS = [  # name, [sim] settings, [sim.faults], sequence pressures (default 0.5, 1, 2.5 bar)
    ("stall 5 s < 10 s buffer", {"buffer_s": 10.0}, {"stall_at_s": 4.0, "stall_s": 5.0}, None),
    ("stall 30 s > 10 s buffer", {"buffer_s": 10.0}, {"stall_at_s": 4.0, "stall_s": 30.0},
     None),
    ("load cell NaN at 5 s", {}, {"nan_force_at_s": 5.0}, None),
    ("load cell NaN in the tare", {}, {"nan_force_at_s": 1.0}, None),
    ("load cell stuck from 8 s", {}, {"loadcell_stuck_at_s": 8.0}, None),
    ("regulator stuck from 1 s", {}, {"regulator_stuck_at_s": 1.0}, None),
    ("regulator overshoot 0.3 bar at 2.5 bar", {}, {"overshoot_bar": 0.3}, (2.5,)),
    ("disconnect at 7 s", {}, {"disconnect_at_s": 7.0}, None),
    ("AO write failure at 2 s", {}, {"ao_fail_at_s": 1.0}, None),
    ("10 read timeouts at 5 s", {}, {"read_timeout_at_s": 5.0, "read_timeouts": 10}, None),
    ("load cell noise 50 mV (tare)", {"noise_V": 0.05}, {}, None),
]


def fault_table(out: Path) -> list[dict]:
    base = load_config().replace(
        sequence={"pressures_bar": (0.5, 1.0, 2.5), "tare_s": 2.0, "preconditioning_cycles": 0},
        settle={"min_dwell_s": 3.0, "hold_s": 2.0, "timeout_s": 20.0, "window_s": 2.0})
    rows = []
    for k, (name, sim, faults, pressures) in enumerate(FAULTS):
        config = base.replace(sim={**sim, "faults": faults})
        if pressures:
            config = config.replace(sequence={"pressures_bar": pressures})
        os.environ["MKM_STATE_DIR"] = str(out / f"state{k}")
        result = acquire(config, out_root=out / f"fault{k}", **QUIET)
        run = load_run(result.path)
        s, c = run.samples, run.commands
        # when the run had to stop: the first interlocked sample, else its last sample
        tripped = s[s["flags"].str.contains("interlock")]
        stop_s = float(tripped["time_s"].iloc[0]) if len(tripped) else float(s["time_s"].iloc[-1])
        vents = c[(c["command_bar"] == 0.0) & c["ok"] & (c["time_s"] >= stop_s)]
        stopped = not run.status.finished
        rows.append({"fault": name, "status": str(run.status), "exit": result.exit_code,
                     "samples_lost": run.meta.lost_samples,
                     "stop_to_vent_sample_time_s": round(float(vents["time_s"].iloc[0]) - stop_s,
                                                         2) if stopped and len(vents) else "-",
                     "vented": "by hand (vent failed)" if run.meta.manual_vent_required
                     else "yes",
                     "reason": result.reason.split(";")[0][:80]})
    return rows


def report_memory(out: Path) -> dict:
    """Peak RSS of reading a 24 h run, in a fresh process each."""
    from mkm.bench.storage import SAMPLE_COLUMNS

    n = 24 * 3600 * 10
    path = out / "day"
    path.mkdir()
    rng = np.random.default_rng(0)
    import pandas as pd

    k = np.arange(n)
    frame = pd.DataFrame({"sample": k, "time_s": k / 10, "step": k // 600, "phase": "step",
                          "set_pressure_bar": 1.0, "command_bar": 1.0,
                          "pressure_bar": 1.0 + 0.001 * rng.standard_normal(n),
                          "loadcell_V": 1.0 + 0.002 * rng.standard_normal(n),
                          "monitor_V": 2.0, "force_N": 196.0 + 0.4 * rng.standard_normal(n),
                          "flags": ""})
    frame[list(SAMPLE_COLUMNS)].to_csv(path / "samples.csv", index=False, float_format="%.6g")
    size_mb = (path / "samples.csv").stat().st_size / 1e6
    # peak resident memory of the probe itself: VmHWM is reset by exec (ru_maxrss is not: it
    # would report this process's own peak, the synthetic frame included)
    probe = ("{}\nfor line in open('/proc/self/status'):\n"
             "    if line.startswith('VmHWM:'):\n        print(int(line.split()[1]) / 1024)")
    del frame
    figures = {"rows": n, "file_MB": round(size_mb, 1)}
    for label, code in (("pandas_whole_MB", "import pandas as pd\n"
                         f"pd.read_csv({str(path / 'samples.csv')!r})"),
                        ("aggregate_samples_MB", "from bench.storage import aggregate_samples\n"
                         f"aggregate_samples({str(path)!r})"),
                        ("imports_only_MB", "import pandas, bench.storage")):
        done = subprocess.run([sys.executable, "-c", probe.format(code)], capture_output=True,
                              text=True, check=True, cwd=REPO)
        figures[label] = round(float(done.stdout.split()[-1]), 1)
    return figures


def markdown(rows: list[dict]) -> str:
    keys = list(rows[0])
    lines = ["| " + " | ".join(keys) + " |", "|" + "---|" * len(keys)]
    lines += ["| " + " | ".join(str(r[k]) for k in keys) + " |" for r in rows]
    return "\n".join(lines)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--trials", type=int, default=5, help="trials per signal")
    parser.add_argument("--skip-real", action="store_true", help="skip the signal trials")
    parser.add_argument("--skip-long", action="store_true",
                        help="skip the one-hour, never-settling and 24 h memory figures")
    args = parser.parse_args()
    figures = {}
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        os.environ["MKM_STATE_DIR"] = str(tmp / "state")
        if not args.skip_long:
            figures["one_hour_virtual"] = one_hour_virtual(tmp / "hour")
            figures["never_settling"] = never_settling(tmp / "settle")
            figures["report_memory"] = report_memory(tmp)
        figures["faults"] = fault_table(tmp / "faults")
        print(markdown(figures["faults"]) + "\n")
        if not args.skip_real:
            figures["signals"] = signal_trials(tmp / "signals", args.trials)
            print(markdown(figures["signals"]) + "\n")
    print(json.dumps({**figures, "provenance": provenance()}, indent=2))


if __name__ == "__main__":
    main()
