"""``mkm identify --params theta0,rubber,gap`` on runs the FE model with a gap simulated, blind.

Run outside the test suite:

    .venv/bin/python benchmarks/bench_identify_gap.py [--draws 1] [--seed 0] [--out FILE.json]

Each draw is a muscle with a radial gap between tube and braid: theta0 28-36 deg, rubber
x0.8-1.5 (Silastic S's constants scaled), gap 0.4-1.2 mm, set as the simulated bench's truth
with ``[sim] model = "axisym"`` on the coarse mesh, the simulator's default friction, creep and
noise. Two runs (the paper's staircase at eps 0 and 12.2 %) are acquired, the truth deleted from
them, and the muscle identified from them with the FE model itself searching (``--model
axisym:mesh=coarse --search model``), and with the thick-wall form for comparison (the closed
form leaves out the clamped ends the FE simulated). Prints and records, per draw and model, the
truth and the estimates, the gap's relative error (the issue's target: within 10 %) and the
wall and CPU seconds of the identification (in one process: on a shared machine the CPU time is
the closer to what an idle core takes).
"""

from __future__ import annotations

import argparse
import tempfile
import time
from pathlib import Path

import numpy as np
import pandas as pd

from mkm.bench.config import load_config
from mkm.bench.run import acquire
from mkm.bench.sim_settings import remove_simulator_settings
from mkm.core.records import provenance, write_json_atomic
from mkm.fem.materials import SILASTIC_S
from mkm.identify import identify

EPS = (0.0, 0.122)
MODELS = ("axisym:mesh=coarse", "thickwall")


def simulate(truth: dict, out: Path, seed: int) -> list[Path]:
    """The two blind runs of the FE muscle ``truth``."""
    runs = []
    scale = truth["rubber_scale"]
    for k, eps in enumerate(EPS):
        config = load_config(eps=eps).replace(sim={
            "model": "axisym", "fe_mesh": "coarse", "seed": seed + k,
            "truth": {"theta0_deg": truth["theta0_deg"], "C10_MPa": scale * SILASTIC_S.C10_MPa,
                      "C01_MPa": scale * SILASTIC_S.C01_MPa, "gap_mm": truth["gap_mm"]}})
        result = acquire(config, out_root=out, notify=lambda message: None)
        if result.status != "complete":
            raise RuntimeError(f"simulated run ended {result.status}")
        remove_simulator_settings(result.path)
        runs.append(result.path)
    return runs


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--draws", type=int, default=1)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--out", type=Path, help="write the rows and provenance as JSON here")
    args = parser.parse_args()
    rng = np.random.default_rng(args.seed)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for draw in range(args.draws):
            truth = {"theta0_deg": rng.uniform(28.0, 36.0), "rubber_scale": rng.uniform(0.8, 1.5),
                     "gap_mm": rng.uniform(0.4, 1.2)}
            runs = simulate(truth, Path(tmp) / f"draw{draw}", seed=10 * draw)
            for model in MODELS:
                wall, cpu = time.perf_counter(), time.process_time()
                # in this process (no local cluster), so that its CPU time is all of it
                found = identify(runs, params="theta0,rubber,gap", model=model, search="model",
                                 cache_dir=None, workers=1)
                wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
                values = found.values
                rows.append({
                    "draw": draw, "model": model, "true theta0 deg": truth["theta0_deg"],
                    "theta0 deg": values["theta0_deg"],
                    "true rubber scale": truth["rubber_scale"],
                    "rubber scale": values["C10_MPa"] / SILASTIC_S.C10_MPa,
                    "true gap mm": truth["gap_mm"], "gap mm": values["gap_mm"],
                    "gap error %": 100.0 * (values["gap_mm"] / truth["gap_mm"] - 1.0),
                    "wall s": wall, "cpu s": cpu})
                print(pd.DataFrame(rows[-1:]).to_string(index=False), flush=True)
    if args.out:
        write_json_atomic(args.out, {**provenance(), "seed": args.seed, "rows": rows})


if __name__ == "__main__":
    main()
