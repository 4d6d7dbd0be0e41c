"""How fast the command line answers: whole-process wall times of quick commands, and what
``mkm --help`` imports.

    .venv/bin/python benchmarks/bench_startup.py [--repeats 9] [--json FILE]

Each command runs ``--repeats`` times as a new process (the ``mkm`` script of this environment,
as a user types it); prints the median and the fastest, against the issue's targets: ``mkm
--help`` <= 0.3 s, ``mkm fem solve --model eq2`` <= 0.5 s, ``mkm fem solve --model surrogate``
(one sweep, the model already trained: one untimed run first) <= 0.6 s and below the FE model's
time on the same sweep. Then the largest cumulative imports of ``mkm --help``
(``python -X importtime``) and whether pandas, scipy, matplotlib, numpy or the FE model are among
them. Prints the load average before and after (the machine may be shared).
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

MUSCLE = ["--D0", "35", "--t0", "2.5", "--eps", "0.05"]
COMMANDS = {
    "mkm --help": (["--help"], 0.3),
    "mkm models": (["models"], None),
    "mkm fem solve --model eq2": (["fem", "solve", "--model", "eq2", *MUSCLE], 0.5),
    "mkm fem solve --model surrogate": (["fem", "solve", "--model", "surrogate", *MUSCLE], 0.6),
    "mkm fem solve --model axisym": (["fem", "solve", "--model", "axisym", *MUSCLE], None),
}
HEAVY = ("numpy", "pandas", "scipy", "matplotlib", "sklearn", "skfem", "mkm.fem.fe", "dask")


def mkm_script() -> str:
    return str(Path(sys.executable).parent / ("mkm.exe" if os.name == "nt" else "mkm"))


def timed(argv, repeats: int) -> list[float]:
    subprocess.run([mkm_script(), *argv], check=True, capture_output=True)  # caches warm
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        subprocess.run([mkm_script(), *argv], check=True, capture_output=True)
        times.append(time.perf_counter() - start)
    return times


def help_imports(top: int = 8) -> dict:
    done = subprocess.run([sys.executable, "-X", "importtime", mkm_script(), "--help"],
                          capture_output=True, text=True, check=True)
    rows = []
    for line in done.stderr.splitlines():
        if line.startswith("import time:") and "|" in line:
            _, cumulative, name = (part.strip() for part in line.split("|"))
            if cumulative.isdigit():
                rows.append((int(cumulative), name))
    names = {name for _, name in rows}
    return {"largest_cumulative_us": sorted(rows, reverse=True)[:top],
            "heavy_imported": [m for m in HEAVY if m in names]}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=9)
    parser.add_argument("--json", type=Path)
    args = parser.parse_args()
    load_before = os.getloadavg()
    print(f"load average before: {load_before[0]:.2f} (1 min), {os.cpu_count()} CPUs; "
          f"median of {args.repeats} runs")
    results = {}
    for label, (argv, target) in COMMANDS.items():
        times = timed(argv, args.repeats)
        median = statistics.median(times)
        results[label] = {"median_s": median, "min_s": min(times), "target_s": target}
        verdict = "" if target is None else (f"  target <= {target} s: "
                                             f"{'met' if median <= target else 'NOT met'}")
        print(f"  {label:34s} median {median:.3f} s, fastest {min(times):.3f} s{verdict}")
    surrogate = results["mkm fem solve --model surrogate"]["median_s"]
    fe = results["mkm fem solve --model axisym"]["median_s"]
    print(f"  surrogate / FE model: {surrogate / fe:.2f}")
    imports = help_imports()
    results["help_imports"] = imports
    print("mkm --help, largest cumulative imports [ms]: " + ", ".join(
        f"{name} {us / 1e3:.0f}" for us, name in imports["largest_cumulative_us"]))
    print(f"  heavy libraries imported by mkm --help: {imports['heavy_imported'] or 'none'}")
    load_after = os.getloadavg()
    print(f"load average after: {load_after[0]:.2f} (1 min)")
    if args.json:
        from mkm.core.records import provenance

        rows = [{"command": label, "median_s": round(r["median_s"], 3),
                 "fastest_s": round(r["min_s"], 3),
                 "target_s": "" if r["target_s"] is None else f"<= {r['target_s']}"}
                for label, r in results.items() if label in COMMANDS]
        rows.append({"command": "surrogate / FE model (medians)",
                     "median_s": round(surrogate / fe, 3), "fastest_s": "", "target_s": "< 1"})
        args.json.write_text(json.dumps({**provenance(), "load_average_before": load_before,
                                         "load_average_after": load_after, **results,
                                         "rows": rows}, indent=2) + "\n")


if __name__ == "__main__":
    main()
