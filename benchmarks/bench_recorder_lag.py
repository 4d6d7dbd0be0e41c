"""How far the recorder's writer thread trails the acquisition loop, and what a held row costs
in memory: the figures behind :data:`mkm.bench.recorder.DISK_STUCK_S` and
:data:`mkm.bench.recorder.HELD_ROWS_MAX`.

    .venv/bin/python -P benchmarks/bench_recorder_lag.py [--blocks 1,10]

Runs the paper's staircase on the simulated bench's virtual clock (hundreds of times faster
than real time: the hardest case for the writer, a good disk under it) once per read block
size, and records the most samples held for the disk at any moment (queued or being written),
in rows and in seconds of samples; then the memory of 100 000 held rows (``tracemalloc``).
A held span near ``DISK_STUCK_S`` (30 s) would stop a healthy run: the table says the margin.
Prints a Markdown table.
"""

from __future__ import annotations

import argparse
import os
import tempfile
import time
import tracemalloc

from mkm.bench import recorder
from mkm.bench.config import load_config
from mkm.bench.run import acquire
from mkm.bench.storage import Sample


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


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--blocks", default="1,10", help="read block sizes [samples]")
    args = parser.parse_args()
    os.environ.setdefault("MKM_STATE_DIR", tempfile.mkdtemp())  # no markers in the user's
    print("| read block [samples] | status | most held [rows] | most held [s of samples] | "
          "run wall time [s] |")
    print("|---|---|---|---|---|")
    for block in (int(b) for b in args.blocks.split(",")):
        r = lag(block)
        print(f"| {r['block']} | {r['status']} | {r['rows']} | {r['held_s']:.1f} | "
              f"{r['wall_s']:.1f} |")
    print(f"\nA held row in memory: {bytes_per_row():.0f} bytes (tracemalloc, 100 000 rows); "
          f"DISK_STUCK_S {recorder.DISK_STUCK_S:g} s, HELD_ROWS_MAX {recorder.HELD_ROWS_MAX}")


if __name__ == "__main__":
    main()
