"""Wall time of `mkm report` with a cold and a warm FE cache, and of `mkm study`.

Run outside the test suite:

    .venv/bin/python benchmarks/bench_report.py [--models eq2,thickwall,axisym,surrogate]
        [--eps 0.122] [--study] [--study-cold]

The report is timed on a fresh simulated run of the paper's prototype at the paper's
eps = 12.2 % (bench API, virtual clock), first with an empty FE cache in a temporary folder,
then again with that cache warm.
Both runs go through the installed `mkm` command, as a user runs it. `--study` times
`mkm study` with the user's cache (mkm.paths.default_cache); `--study-cold` with an empty one
(several minutes: every FE sweep and every surrogate is computed). `mkm demo` is timed too
(warm user cache). Every output goes to a temporary folder.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
import time
from dataclasses import replace
from pathlib import Path

from mkm.bench.config import load_config
from mkm.bench.run import acquire
from mkm.core.records import provenance

MKM = str(Path(sys.executable).with_name("mkm"))


def timed(args: list[str]) -> float:
    start = time.perf_counter()
    subprocess.run([MKM, *args], check=True, stdout=subprocess.DEVNULL)
    return time.perf_counter() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--models", default="eq2,thickwall,axisym,surrogate")
    parser.add_argument("--eps", type=float, default=0.122, help="shortening ratio of the run")
    parser.add_argument("--study", action="store_true", help="also time mkm study (warm)")
    parser.add_argument("--study-cold", action="store_true", help="time mkm study, cold cache")
    args = parser.parse_args()
    results = {"provenance": provenance(), "models": args.models, "eps": args.eps}
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        config = load_config()
        config = replace(config, muscle=replace(config.muscle, eps=args.eps))
        run = acquire(config, out_root=tmp / "runs").path
        for name in ("cold", "warm"):
            results[f"report_{name}_s"] = round(timed(
                ["report", str(run), "--models", args.models, "--out", str(tmp / name),
                 "--cache", str(tmp / "cache"), "--no-progress"]), 2)
        if args.study_cold:
            results["study_cold_s"] = round(timed(
                ["study", "--out", str(tmp / "study"), "--cache", str(tmp / "study-cache"),
                 "--no-progress"]), 1)
        results["demo_s"] = round(timed(["demo", "--out", str(tmp / "demo"), "--no-progress"]),
                                  2)
    if args.study:
        with tempfile.TemporaryDirectory() as tmp:
            results["study_warm_s"] = round(timed(["study", "--out", tmp, "--no-progress"]), 1)
    print(json.dumps(results, indent=1))


if __name__ == "__main__":
    main()
