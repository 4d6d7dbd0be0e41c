"""How far the recorder's writer thread trails the acquisition loop, and what a held row costs
in memory: the figures behind :data:`mkm.bench.recorder.DISK_STUCK_S` and
:data:`mkm.bench.recorder.HELD_ROWS_MAX`.

    .venv/bin/python -P benchmarks/bench_recorder_lag.py [--blocks 1,10] [--repeats 20]
        [--out FILE]

Runs the paper's staircase on the simulated bench's virtual clock (hundreds of times faster
than real time: the hardest case for the writer, a good disk under it) ``--repeats`` times per
read block size, and records the most samples held for the disk at any moment (queued or being
written), in rows and in seconds of samples; then the memory of 100 000 held rows
(``tracemalloc``). A run stops when the disk finishes no write for ``DISK_STUCK_S`` (30 s of
wall time), however many samples are held: the held span says how far a healthy writer trails.
How far it trails depends on the threads' scheduling, so on the machine's load: the table gives
the range over the repeats. Prints a Markdown table; ``--out``
also writes it, every run and the provenance as JSON.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import tempfile
import time
import tracemalloc

from mkm.bench import recorder
from mkm.bench.config import load_config
from mkm.bench.run import acquire
from mkm.bench.storage import Sample
from mkm.core.records import provenance, write_atomic


def lag(block: int) -> dict:
    """The paper's run with reads of ``block`` samples; the most held for the disk."""
    most = {"rows": 0}
    put = recorder.Recorder._put

    def watched(self, kind, payload=None):
        put(self, kind, payload)
        most["rows"] = max(most["rows"], self.held_rows)

    recorder.Recorder._put = watched
    try:
        config = load_config().replace(daq={"read_block_samples": block})
        start = time.perf_counter()
        with tempfile.TemporaryDirectory() as out:
            result = acquire(config, out_root=out, notify=lambda message: None)
        wall_s = time.perf_counter() - start
    finally:
        recorder.Recorder._put = put
    rate = config.daq.sample_rate_hz
    return {"block": block, "status": str(result.status), "rows": most["rows"],
            "held_s": most["rows"] / rate, "wall_s": wall_s}


def bytes_per_row(n: int = 100_000) -> float:
    tracemalloc.start()
    rows = [Sample(k, k / 10, 3, "step", 1.0, 1.0, 1.0 + k * 1e-6, 0.5 + k * 1e-6,
                   2.0 + k * 1e-6, 100.0 + k * 1e-3, "") for k in range(n)]
    used, _ = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    return used / len(rows)


def summary(runs: list[dict]) -> list[dict]:
    """One row per read block size: the range of the most held over its repeats."""
    rows = []
    for block in dict.fromkeys(r["block"] for r in runs):
        mine = [r for r in runs if r["block"] == block]
        held = [r["rows"] for r in mine]
        rows.append({"read block [samples]": block, "runs": len(mine),
                     "complete": sum(r["status"] == "complete" for r in mine),
                     "most held, least [rows]": min(held), "most held, most [rows]": max(held),
                     "most held, most [s of samples]": max(r["held_s"] for r in mine),
                     "run wall time, median [s]": round(
                         statistics.median(r["wall_s"] for r in mine), 2)})
    return rows


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--blocks", default="1,10", help="read block sizes [samples]")
    parser.add_argument("--repeats", type=int, default=1, help="runs per block size")
    parser.add_argument("--out", help="also write the table, every run and the provenance "
                                      "here (JSON)")
    args = parser.parse_args(argv)
    os.environ.setdefault("MKM_STATE_DIR", tempfile.mkdtemp())  # no markers in the user's
    load = os.getloadavg() if hasattr(os, "getloadavg") else None  # not on Windows
    runs = [lag(int(block)) for block in args.blocks.split(",") for _ in range(args.repeats)]
    rows = summary(runs)
    keys = list(rows[0])
    print("| " + " | ".join(keys) + " |")
    print("|" + "---|" * len(keys))
    for row in rows:
        print("| " + " | ".join(str(row[k]) for k in keys) + " |")
    per_row = bytes_per_row()
    print(f"\nA held row in memory: {per_row:.0f} bytes (tracemalloc, 100 000 rows); "
          f"DISK_STUCK_S {recorder.DISK_STUCK_S:g} s, HELD_ROWS_MAX {recorder.HELD_ROWS_MAX}")
    if args.out:
        record = {**provenance(), "repeats": args.repeats, "load_average_before": load,
                  "bytes_per_held_row": round(per_row), "disk_stuck_s": recorder.DISK_STUCK_S,
                  "held_rows_max": recorder.HELD_ROWS_MAX, "rows": rows, "runs": runs}
        write_atomic(args.out, json.dumps(record, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
