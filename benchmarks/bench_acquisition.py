"""Acquisition figures of the bench package (issue 5), measured, outside the test suite.

    .venv/bin/python benchmarks/bench_acquisition.py [--skip-real]

1. wall time of a one-hour run (sample time) on the virtual clock (goal <= 5 s);
2. samples lost in a 2-minute real-clock run and the reader's largest backlog (goal 0 lost);
3. time from SIGINT to the vent command of a real-clock `mkm acquire` process (goal < 0.2 s).

Prints one JSON document with the figures, the settings and the provenance.
"""

from __future__ import annotations

import argparse
import json
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from bench.config import load_config
from bench.run import BenchRun, acquire
from bench.sim import SimBackend
from bench.storage import load_run
from fem.records import provenance

REPO = Path(__file__).resolve().parents[1]


def one_hour_virtual(out: Path) -> dict:
    # 19 steps (0.25..2.5 bar up and down) of ~65 s (settle + 60 s hold), three repeats
    config = load_config().replace(settle={"hold_s": 60.0}, sequence={"repeats": 3})
    start = time.perf_counter()
    result = acquire(config, out_root=out)
    wall = time.perf_counter() - start
    run = load_run(result.path)
    return {"status": run.status, "sample_time_s": float(run.samples["time_s"].iloc[-1]),
            "samples": len(run.samples), "wall_s": round(wall, 3),
            "wall_per_hour_s": round(wall * 3600.0 / float(run.samples["time_s"].iloc[-1]), 3)}


def two_minutes_real(out: Path) -> dict:
    config = load_config().replace(sequence={"pressures_bar": (0.5, 1.0, 1.5), "tare_s": 5.0},
                                   settle={"hold_s": 20.0, "min_dwell_s": 4.0})
    backend = SimBackend(config, clock="real")
    backlog = []
    read = backend.read

    def watched_read(n, timeout_s):
        backlog.append(backend.available())
        return read(n, timeout_s)

    backend.read = watched_read
    start = time.perf_counter()
    result = BenchRun(config, backend, out, handle_sigint=False).execute()
    wall = time.perf_counter() - start
    run = load_run(result.path)
    expected = int(run.samples["sample"].iloc[-1]) + 1
    return {"status": run.status, "wall_s": round(wall, 1), "samples": len(run.samples),
            "samples_lost": expected - len(run.samples),
            "gaps": len(run.meta["counters"]["gaps"]),
            "largest_backlog_samples": int(max(backlog))}


def sigint_to_vent(out: Path, repeats: int = 5) -> dict:
    rng = np.random.default_rng(0)
    delays = []
    for k in range(repeats):
        folder = out / f"sigint{k}"
        proc = subprocess.Popen(
            [sys.executable, "-m", "mkm", "acquire", "--clock", "real", "--out",
             str(folder), "--no-progress"], cwd=REPO, stdout=subprocess.PIPE,
            stderr=subprocess.DEVNULL, text=True)
        while not list(folder.glob("*/samples.csv")):
            time.sleep(0.05)
        time.sleep(3.0 + rng.uniform(0, 1))  # at a random phase of the 0.1 s sample clock
        sent = time.time()
        proc.send_signal(signal.SIGINT)
        stdout, _ = proc.communicate(timeout=30)
        meta = load_run(Path(stdout.strip().splitlines()[-1])).meta
        delays.append(meta["vented_at_unix_s"] - sent)
    return {"repeats": repeats, "median_s": round(float(np.median(delays)), 4),
            "max_s": round(float(np.max(delays)), 4)}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--skip-real", action="store_true",
                        help="skip the 2-minute real-clock run")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        figures = {"one_hour_virtual": one_hour_virtual(tmp / "hour"),
                   "sigint_to_vent": sigint_to_vent(tmp)}
        if not args.skip_real:
            figures["two_minutes_real"] = two_minutes_real(tmp / "real")
    print(json.dumps({**figures, "provenance": provenance()}, indent=2))


if __name__ == "__main__":
    main()
