"""How long the published DMSP-10-250 takes through the command line: ``mkm import``, ``mkm
identify`` and ``mkm report`` as a user types them, whole-process wall times against issue 34's
targets.

    .venv/bin/python benchmarks/bench_published_commands.py [--repeats 3] [--json FILE]

The Festo DMSP-10-250 of Martens and Boblan's force maps (``mkm data copy
martens_boblan_2017_forcemaps.csv``): a 10 mm muscle at up to 6.5 bar, outside the default
surrogate's box (D0 30-50 mm, 0-2.5 bar). The commands are published.md's "With the
instruments' accuracy": the import with an assumed accuracy (:data:`IMPORT`), ``mkm identify``
on the lengths at eps 0.064 and 0.184 with the default params and models (the practical
range's surrogate searching, the FE model confirming), and ``mkm report`` on the four lengths
with force with the default models, without and with that identification's calibration.

The benchmark's caches are a folder of its own (``MKM_CACHE_DIR``), empty at the start: the first
``mkm identify`` is timed once as a user's first use (it trains the surrogates it needs, which
are kept). Each command then runs once untimed, then ``--repeats`` times as a new
process (the ``mkm`` script of this environment), each with the caches of what was solved
emptied first (the predictions and the FE batch's finished jobs, :data:`SOLVED_CACHES`): a
first identification or report of these runs, as a user runs it then. Prints the median,
the fastest and the slowest wall time (with the median CPU time of the process, user and
system: what a shared machine changes least), against the targets (``mkm report`` on four
imported 10 mm runs at 6 bar <= 60 s, ``mkm identify`` on two <= 30 s), and the load average
before and after (the machine may be shared: record on an idle one).
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from bench_published import ACCURACY, MUSCLES
from bench_published import ACCURACY_EPS as IDENTIFY_EPS

from mkm.core.home import CACHE_ENV

TABLE = "martens_boblan_2017_forcemaps.csv"
#: the import of published.md's "With the instruments' accuracy" (after ``--out``)
IMPORT = ["--id", "dmsp-10", "--D0", "10", "--t0", f"{MUSCLES['Festo DMSP-10-250'][2]:g}",
          "--muscle", "Festo DMSP-10-250", "--accuracy", ACCURACY]
#: the caches of what was solved (the predictions and the FE batch's finished jobs), emptied
#: before each timed run; the trained surrogates are kept
SOLVED_CACHES = ("predictions", "dataset")
#: issue 34's targets [s]
TARGETS = {"identify": 30.0, "report": 60.0}


def mkm_script() -> str:
    return str(Path(sys.executable).parent / ("mkm.exe" if os.name == "nt" else "mkm"))


def mkm(argv, cwd: Path) -> list[str]:
    """``mkm argv`` as a new process in ``cwd``, its caches in ``cwd / "cache"``; its stdout
    lines."""
    quiet = [] if argv[0] == "data" else ["--no-progress"]
    done = subprocess.run([mkm_script(), *argv, *quiet], cwd=cwd, capture_output=True,
                          text=True, env={**os.environ, CACHE_ENV: str(cwd / "cache")})
    if done.returncode != 0:
        raise SystemExit(f"mkm {' '.join(argv)} failed ({done.returncode}): "
                         f"{done.stderr.strip()}")
    return done.stdout.splitlines()


def _children_cpu_s() -> float:
    """The CPU time [s] the benchmark's ended child processes used (user and system)."""
    import resource

    used = resource.getrusage(resource.RUSAGE_CHILDREN)
    return used.ru_utime + used.ru_stime


def timed(argv, cwd: Path, repeats: int) -> tuple[list[float], list[float]]:
    """Wall times and CPU times [s] of ``repeats`` runs of ``mkm argv`` after one untimed run,
    each into a folder of its own (``--out``)."""
    times, cpu = [], []
    for k in range(repeats + 1):
        for solved in SOLVED_CACHES:
            shutil.rmtree(cwd / "cache" / solved, ignore_errors=True)
        start, start_cpu = time.perf_counter(), _children_cpu_s()
        mkm([*argv, "--out", f"timed-{argv[0]}-{len(argv)}-{k}"], cwd)
        if k:
            times.append(time.perf_counter() - start)
            cpu.append(_children_cpu_s() - start_cpu)
    return times, cpu


def load_averages() -> tuple[float, float, float] | None:
    """The machine's load averages over 1, 5 and 15 minutes (None where the OS keeps none)."""
    return os.getloadavg() if hasattr(os, "getloadavg") else None


def load_average() -> float | None:
    """The last minute's load average (None where the OS keeps none)."""
    loads = load_averages()
    return None if loads is None else loads[0]


def row(label: str, measured: tuple[list[float], list[float]], target: float | None,
        load: float | None) -> dict:
    """One command's row of the record (printed as it is made): its wall times' median, fastest
    and slowest and its median CPU time [s], against ``target``."""
    times, cpu = measured
    median = statistics.median(times)
    met = "" if target is None else ("yes" if median <= target else "no")
    verdict = "" if target is None else (f"  target <= {target:g} s: "
                                         f"{'met' if median <= target else 'NOT met'}")
    print(f"  {label:40s} median {median:.1f} s [{min(times):.1f}-{max(times):.1f}], "
          f"CPU {statistics.median(cpu):.1f} s{verdict}", flush=True)
    return {"command": label, "runs": len(times), "median_s": round(median, 2),
            "fastest_s": round(min(times), 2), "slowest_s": round(max(times), 2),
            "median_cpu_s": round(statistics.median(cpu), 2),
            "load_average_before": None if load is None else round(load, 2),
            "target_s": "" if target is None else f"<= {target:g}", "met": met}


def measure(work: Path, repeats: int) -> list[dict]:
    from mkm.bench.storage import load_run, read_meta

    mkm(["data", "copy", TABLE], work)
    commands = {"mkm import (5 lengths)": (["import", TABLE, *IMPORT], None)}
    runs = [Path(line) for line in mkm(["import", TABLE, *IMPORT, "--out", "runs"], work)
            if (work / line).is_dir()]
    eps = {run: read_meta(work / run).muscle.eps for run in runs}
    two = [str(r) for r in runs if any(abs(eps[r] - e) < 1e-9 for e in IDENTIFY_EPS)]
    pulling = [str(r) for r in runs if (load_run(work / r).steps["force_N_mean"] > 0).any()]
    if len(two) != 2 or len(pulling) != 4:
        raise SystemExit(f"expected two lengths at eps {IDENTIFY_EPS} and four with force, "
                         f"got {two} and {pulling}")
    load = load_average()
    start, start_cpu = time.perf_counter(), _children_cpu_s()
    mkm(["identify", *two, "--out", "id"], work)
    first = [time.perf_counter() - start], [_children_cpu_s() - start_cpu]
    rows = [row("mkm identify (2 lengths), first use", first, TARGETS["identify"], load)]
    commands.update({
        "mkm identify (2 lengths)": (["identify", *two], TARGETS["identify"]),
        "mkm report (4 lengths)": (["report", *pulling], TARGETS["report"]),
        "mkm report (4 lengths) --calibration": (
            ["report", *pulling, "--calibration", "id/calibration.json"], TARGETS["report"])})
    for label, (argv, target) in commands.items():
        load = load_average()
        rows.append(row(label, timed(argv, work, repeats), target, load))
    return rows


def main(argv=None) -> dict:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--json", type=Path)
    args = parser.parse_args(argv)
    load_before = load_averages()
    print(f"load average before: {load_before}, {os.cpu_count()} CPUs; median of "
          f"{args.repeats} runs")
    with tempfile.TemporaryDirectory() as work:
        rows = measure(Path(work), args.repeats)
    load_after = load_averages()
    print(f"load average after: {load_after}")
    from mkm.core.records import provenance

    record = {**provenance(), "repeats": args.repeats, "load_average_before": load_before,
              "load_average_after": load_after, "rows": rows}
    if args.json:
        args.json.write_text(json.dumps(record, indent=2) + "\n", encoding="utf-8")
    return record


if __name__ == "__main__":
    main()
