"""``mkm acquire --calibration``'s over-force interlock on fresh random truths of the simulated
bench: no trip on a correct bench, a trip on a monitor reading low by its gain.

Run outside the test suite:

    .venv/bin/python benchmarks/bench_overforce.py [--draws 16] [--seed S] [--out FILE.json]

Each draw is a muscle unknown to the toolkit, simulated with the thick-wall closed form (as
identify's fast tests make it): theta0 28-38 deg, rubber x0.6-1.5 (Silastic S's constants
scaled), braid friction 0-8 %, creep 0-4 %. Two blind runs of it (the packaged staircase at eps
0 and 12.2 %) are identified (``search="model"``); the calibration it writes then watches five
live runs of the same muscle on a correct bench (eps 0, 0.1 twice over, 0.2, 0.3 and one drawn
in 0-0.3, each up and down with creep), which must all complete, and one whose pressure monitor
reads 0.8 of the pressure (``[sim.truth] monitor_gain``), which must stop. Prints one JSON
document: per draw the truth, every live run's status and reason, and the provenance; the
summary counts the correct runs stopped, by any interlock and by the over-force one.
"""

from __future__ import annotations

import argparse
import json
import os
import tempfile
from pathlib import Path

import numpy as np

from mkm.bench.config import load_config
from mkm.bench.run import acquire
from mkm.bench.sim_settings import remove_simulator_settings, sim_of
from mkm.core.records import jsonable, provenance
from mkm.fem.calibration import Calibration
from mkm.identify import identify
from mkm.identify.band import force_ceiling

QUIET = {"notify": lambda message: None}


def draw(rng) -> dict:
    return {"theta0_deg": rng.uniform(28.0, 38.0), "rubber_scale": rng.uniform(0.6, 1.5),
            "hysteresis_fraction": rng.uniform(0.0, 0.08),
            "creep_fraction": rng.uniform(0.0, 0.04)}


def config(truth: dict, eps: float, seed: int, **instruments):
    return load_config(eps=eps).replace(sim=sim_of(truth, seed, **instruments))


def one(truth: dict, rng, out: Path, k: int) -> dict:
    runs = []
    for j, eps in enumerate((0.0, 0.122)):
        result = acquire(config(truth, eps, 10 * k + j), out_root=out / "fit", **QUIET)
        remove_simulator_settings(result.path)
        runs.append(result.path)
    files = identify(runs, model="thickwall", search="model").write(out / "identified")
    calibration = Calibration.load(files["calibration"])
    live = []
    cases = [(0.0, {}, {}), (0.1, {"repeats": 2}, {}), (0.2, {}, {}), (0.3, {}, {}),
             (float(rng.uniform(0.0, 0.3)), {}, {}), (0.0, {}, {"monitor_gain": 0.8})]
    for n, (eps, sequence, instruments) in enumerate(cases):
        c = config(truth, eps, 10 * k + 5 + n, **instruments)
        if sequence:
            c = c.replace(sequence=sequence)
        ceiling = force_ceiling(calibration, c.muscle, c.regulator.max_pressure_bar)
        result = acquire(c, out_root=out / "live", ceiling=ceiling, **QUIET)
        live.append({"eps": eps, "sequence": sequence, "instruments": instruments,
                     "status": str(result.status), "reason": result.reason})
    return {"truth": truth, "live": live}


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--draws", type=int, default=16)
    parser.add_argument("--seed", type=int, default=20261207)
    parser.add_argument("--out", help="write the JSON document here too")
    args = parser.parse_args(argv)
    rng = np.random.default_rng(args.seed)
    draws = []
    with tempfile.TemporaryDirectory() as tmp:
        os.environ.setdefault("MKM_STATE_DIR", str(Path(tmp) / "state"))
        for k in range(args.draws):
            draws.append(one(draw(rng), rng, Path(tmp) / str(k), k))
    correct = [r for d in draws for r in d["live"] if not r["instruments"]]
    low = [r for d in draws for r in d["live"] if r["instruments"]]
    emit({"provenance": provenance(), "seed": args.seed, "draws": draws,
          "summary": stops(correct, low, "correct", 0.8)}, args.out)
    return 0


def stops(sound: list[dict], low: list[dict], name: str, gain: float) -> dict:
    """The counts of the runs on correct benches (``sound``, called ``name``) and of those
    with a monitor reading ``gain`` of the pressure (``low``): how many stopped, and how many
    by the over-force interlock."""
    def interlocked(runs):
        return sum(r["reason"].startswith("over-force interlock") for r in runs)

    return {f"{name}_runs": len(sound),
            f"{name}_runs_stopped": sum(r["status"] != "complete" for r in sound),
            f"{name}_runs_stopped_by_the_over_force_interlock": interlocked(sound),
            f"monitor_gain_{gain:g}_runs": len(low),
            f"monitor_gain_{gain:g}_stopped_by_the_over_force_interlock": interlocked(low)}


def emit(document: dict, out: str | None) -> None:
    """Print the benchmark's JSON ``document``, and write it to ``out`` where given."""
    text = json.dumps(document, indent=1, default=jsonable)
    print(text)
    if out:
        Path(out).write_text(text + "\n", encoding="utf-8")


if __name__ == "__main__":
    raise SystemExit(main())
