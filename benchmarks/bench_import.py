"""How long ``mkm import`` takes on a lab's long time series: whole-process wall times.

    .venv/bin/python benchmarks/bench_import.py [--seconds 60,600] [--rate-hz 1000]
        [--repeats 3] [--json FILE]

Each record is a 1 kHz (``--rate-hz``) logger's file of a held 10 mm muscle: vented 5 s, then
ramps of 0.11 bar/s up to 6 bar and back, 120 s a cycle, noise 0.005 bar and 0.3 N, as a CSV of
time, pressure and force. Each is imported ``--repeats`` times as a new process (the ``mkm``
script of this environment); prints the median and range per record and per 100000 samples, and
the load average before and after (the machine may be shared).
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import pandas as pd


def record(seconds: float, rate_hz: float, path: Path, seed: int = 3) -> int:
    rng = np.random.default_rng(seed)
    t = np.arange(0.0, seconds, 1.0 / rate_hz)
    p = np.interp(t % 120.0, [0, 5, 60, 115, 120], [0, 0, 6, 0, 0])
    force = 80.0 * np.maximum(p - 0.4, 0.0) + 5.0 + rng.normal(0, 0.3, t.size)
    pd.DataFrame({"t (s)": t, "p (bar)": p + rng.normal(0, 0.005, t.size),
                  "F (N)": force}).to_csv(path, index=False)
    return t.size


def mkm_script() -> str:
    return str(Path(sys.executable).parent / ("mkm.exe" if os.name == "nt" else "mkm"))


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", default="60,600")
    parser.add_argument("--rate-hz", type=float, default=1000.0)
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--json", type=Path, default=None)
    args = parser.parse_args(argv)
    out = {"rate_hz": args.rate_hz, "repeats": args.repeats,
           "load_before": os.getloadavg() if hasattr(os, "getloadavg") else None, "records": []}
    with tempfile.TemporaryDirectory() as tmp:
        for seconds in (float(s) for s in args.seconds.split(",")):
            path = Path(tmp) / f"ramp_{seconds:g}s.csv"
            n = record(seconds, args.rate_hz, path)
            times = []
            for k in range(args.repeats):
                start = time.perf_counter()
                subprocess.run([mkm_script(), "import", str(path), "--id", "bench", "--D0", "10",
                                "--t0", "1.5", "--eps", "0.05", "--L0", "250", "--out",
                                str(Path(tmp) / f"runs{k}")], check=True, capture_output=True)
                times.append(time.perf_counter() - start)
            row = {"seconds_recorded": seconds, "samples": n, "median_s": statistics.median(times),
                   "min_s": min(times), "max_s": max(times),
                   "median_s_per_100k_samples": statistics.median(times) * 1e5 / n}
            out["records"].append(row)
            print(f"{seconds:g} s at {args.rate_hz:g} Hz ({n} samples): median "
                  f"{row['median_s']:.1f} s [{row['min_s']:.1f}-{row['max_s']:.1f}], "
                  f"{row['median_s_per_100k_samples']:.1f} s per 100000 samples")
    out["load_after"] = os.getloadavg() if hasattr(os, "getloadavg") else None
    print(f"load average before {out['load_before']}, after {out['load_after']}")
    if args.json:
        args.json.write_text(json.dumps(out, indent=1))


if __name__ == "__main__":
    main()
