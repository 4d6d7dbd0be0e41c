"""A closed Windows console during a run, on the real-clock simulated bench: from the event to
the vent command, to run.json saying why the run stopped, and to the record being final (the
handler released, when Windows ends the process), against the 5 s Windows allows.

    .venv/bin/python -P benchmarks/bench_console_close.py [--trials 5] [--seed 0] [--json FILE]

Each trial runs a short staircase in this process (the main thread, as `mkm acquire` does) and,
from another thread at a random sample time within the first pressure step, calls the console
handler with ``CTRL_CLOSE_EVENT`` as Windows does on the thread it makes for the event
(:meth:`mkm.bench.signals.StopSignals.on_console_event`; the ``SetConsoleCtrlHandler``
registration itself is Windows-only and tested with a mocked kernel32 in
tests/bench/test_signals.py). Two regulators: one that exhausts (the vent is verified in well
under a second), one stuck at pressure from just before the event (``[sim.faults]
regulator_stuck_at_s``: the check would wait ``vent_timeout_s``, 10 s, and is cut at the grace
deadline). A trial is bad when the handler is released after 4.5 s
(:data:`mkm.bench.signals.CONSOLE_HOLD_S`), or run.json at that moment still says ``running``,
or calls a stuck vent verified. Prints a Markdown table (medians and maxima per regulator).
"""

from __future__ import annotations

import argparse
import json
import os
import random
import statistics
import sys
import tempfile
import threading
import time
from pathlib import Path

from mkm.bench import signals
from mkm.bench.config import load_config
from mkm.bench.recorder import Recorder
from mkm.bench.run import BenchRun, make_backend

SHORT = {"sequence": {"pressures_bar": (0.5, 1.0), "tare_s": 1.0,
                      "preconditioning_cycles": 0},
         "settle": {"min_dwell_s": 3.0, "hold_s": 2.0, "timeout_s": 20.0, "window_s": 2.0}}
TARE_END_S = 1.0  # the first step (0.5 bar) is commanded when the tare ends


def one_trial(regulator: str, event_at_s: float, out: Path) -> dict:
    """One run closed at sample time ``event_at_s``; the times from the event [s]."""
    faults = {"regulator_stuck_at_s": event_at_s - 0.1} if regulator == "stuck" else {}
    config = load_config().replace(**SHORT, sim={"faults": faults})
    run = BenchRun(config, make_backend(config, "real"), out, notify=lambda message: None)
    marks: list[float] = []
    mark = Recorder.mark

    def timed_mark(self, status, reason, *wait):
        mark(self, status, reason, *wait)
        marks.append(time.monotonic())

    seen: dict = {}

    def windows_closes_the_console():
        rate = config.daq.sample_rate_hz
        while run.acquisition is None or run.acquisition.next_index < event_at_s * rate:
            time.sleep(0.005)
        seen["event"], seen["event_unix"] = time.monotonic(), time.time()
        run.signals.on_console_event(signals.CTRL_CLOSE_EVENT)
        seen["released"] = time.monotonic()
        # Windows ends the process now: the run folder says all it will ever say
        seen["meta"] = json.loads((run.recorder.path / "run.json").read_text(encoding="utf-8"))

    Recorder.mark = timed_mark
    try:
        closer = threading.Thread(target=windows_closes_the_console, daemon=True)
        closer.start()
        run.execute()
        closer.join(10.0)
    finally:
        Recorder.mark = mark
    meta = seen["meta"]
    recorded_s = seen["released"] - seen["event"]
    check = meta.get("vent_check") or {}
    bad = (recorded_s > signals.CONSOLE_HOLD_S or meta["status"] == "running"
           or (regulator == "stuck" and bool(check.get("verified"))))
    return {"regulator": regulator, "event_at_s": round(event_at_s, 2),
            "to_vent_s": meta["vented_at_unix_s"] - seen["event_unix"],
            "to_marked_s": marks[0] - seen["event"] if marks else None,
            "to_recorded_s": recorded_s, "status": meta["status"],
            "verified": bool(check.get("verified")), "bad": bad}


def summary(trials: list[dict]) -> list[dict]:
    rows = []
    for regulator in ("exhausts", "stuck"):
        found = [t for t in trials if t["regulator"] == regulator]
        if not found:
            continue

        def stat(key, how, found=found):
            values = [t[key] for t in found if t[key] is not None]
            return round(how(values), 3) if values else None

        statuses = sorted({f"{t['status']}{', verified' if t['verified'] else ''}"
                           for t in found})
        rows.append({"regulator": regulator, "trials": len(found),
                     "bad": sum(t["bad"] for t in found),
                     "to vent, median [s]": stat("to_vent_s", statistics.median),
                     "to vent, max [s]": stat("to_vent_s", max),
                     "to run.json marked, median [s]": stat("to_marked_s", statistics.median),
                     "to recorded, median [s]": stat("to_recorded_s", statistics.median),
                     "to recorded, max [s]": stat("to_recorded_s", max),
                     "run.json at release": "; ".join(statuses)})
    return rows


def table(rows: list[dict]) -> str:
    keys = list(rows[0])
    lines = ["| " + " | ".join(keys) + " |", "|" + "---|" * len(keys)]
    lines += ["| " + " | ".join("" if r[k] is None else str(r[k]) for k in keys) + " |"
              for r in rows]
    return "\n".join(lines)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--trials", type=int, default=5, help="per regulator (default 5)")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--json", help="write the summary and every trial here")
    args = parser.parse_args(argv)
    rng = random.Random(args.seed)
    trials = []
    start = time.perf_counter()
    with tempfile.TemporaryDirectory(prefix="mkm-console-") as tmp:
        # its trials' bench markers (a stuck regulator's unverified vents) in a state folder of
        # their own, not the user's, where every later run would report them
        os.environ["MKM_STATE_DIR"] = str(Path(tmp) / "state")
        for regulator in ("exhausts", "stuck"):
            for k in range(args.trials):
                # within the first step: 0.5 bar commanded at 1 s, the regulator rising
                event_at_s = TARE_END_S + rng.uniform(0.5, 2.5)
                trials.append(one_trial(regulator, event_at_s, Path(tmp) / f"{regulator}{k}"))
                print(f"{regulator} {k}: {trials[-1]}", file=sys.stderr, flush=True)
    seconds = time.perf_counter() - start
    rows = summary(trials)
    print(table(rows))
    print(f"\nseed {args.seed}: {len(trials)} trials in {seconds:.0f} s; Windows ends the "
          f"process {signals.CONSOLE_HOLD_S:g} s after the event at the latest (held)")
    if args.json:
        from mkm.core.records import provenance, write_atomic

        record = {**provenance(), "seed": args.seed, "total_s": round(seconds, 1),
                  "hold_s": signals.CONSOLE_HOLD_S, "record_s": signals.CONSOLE_RECORD_S,
                  "rows": rows, "trials": trials}
        write_atomic(args.json, json.dumps(record, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
