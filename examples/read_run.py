"""Read a run folder with pandas

A run folder (written by `mkm acquire`, format in the user guide's "Run folders" page) is plain
CSV plus `run.json`. `mkm.bench.storage.load_run` reads it back with its metadata and status;
the CSVs also open as they are in pandas or a spreadsheet.

This example takes the shipped simulated run of the paper's prototype at eps 12.2 %, recomputes
each pressure step's force from the raw samples (a step's average is its last `n` samples, the
hold after settling) and compares the rising and falling branches: braid friction makes the
falling branch carry more force at the same pressure.
"""

from pathlib import Path

import numpy as np
import pandas as pd

from mkm.bench.storage import load_run

ROOT = Path(__file__).resolve().parent.parent
RUN = ROOT / "data" / "experimental" / "20261123T084037Z_paper-prototype"

run = load_run(RUN)
print(f"{run.path.name}: status {run.status}, muscle {run.meta.muscle}, "
      f"{run.n_samples} samples, {len(run.steps)} steps")

samples = pd.read_csv(RUN / "samples.csv")  # a plain CSV: what load_run reads, typed
steps = run.steps
held = samples[samples["phase"] == "step"].groupby("step", group_keys=False)
recomputed = pd.Series({k: g["force_N"].tail(int(steps.loc[steps["step"] == k, "n"].iloc[0]))
                        .mean() for k, g in held})
steps = steps.assign(force_N_recomputed=steps["step"].map(recomputed))
print(steps[["step", "direction", "set_pressure_bar", "force_N_mean", "force_N_recomputed"]]
      .to_string(index=False))

branches = steps.pivot_table(index="set_pressure_bar", columns="direction",
                             values="force_N_mean").dropna()
branches["down_minus_up_N"] = branches["down"] - branches["up"]
print(branches.round(2).to_string())

worst = (steps["force_N_recomputed"] - steps["force_N_mean"]).abs().max()
print(f"largest difference between steps.csv and the samples: {worst:.2e} N")
# both files keep 6 significant digits: half a unit in the 6th digit of each value
assert np.allclose(steps["force_N_recomputed"], steps["force_N_mean"], rtol=5e-6, atol=1e-5)
