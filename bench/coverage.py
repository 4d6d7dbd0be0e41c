"""Does the k = 2 interval of :mod:`mkm.bench.budget` cover the truth? Checked on simulated runs.

The simulated bench (:mod:`mkm.bench.sim`) knows the force on its cell at every sample: the
model's static force with braid friction and creep (the measurand, see
:mod:`mkm.bench.budget`). :func:`simulated_coverage` records whole runs through the normal run
code, one per seed, and compares every settled step's recorded force with the mean true force
over the same hold samples: covered when ``|F_meas - F_true| <= force_U_N``.

The simulated load cell is ideal: its sensitivity is exact, it is linear and its zero does not
drift. The runs are therefore recorded with the data-sheet terms at zero
(``loadcell.sensitivity_tolerance_fraction``, ``nonlinearity_fraction_fs``,
``zero_drift_fraction_fs``), so what is checked is what the data decide: noise, quantisation,
tare and drift. The data-sheet terms are rectangular bounds; a k = 2 interval covers a
rectangular error always, so with them on the coverage can only rise.
"""

from __future__ import annotations

import tempfile
from pathlib import Path

import numpy as np
import pandas as pd

from mkm.bench.run import BenchRun
from mkm.bench.sim import SimBackend
from mkm.bench.storage import load_run

IDEAL_CELL = {"sensitivity_tolerance_fraction": 0.0, "nonlinearity_fraction_fs": 0.0,
              "zero_drift_fraction_fs": 0.0}


def _recorded(backend: SimBackend) -> list[float]:
    """Make ``backend`` keep the true force of every sample it takes; return that list."""
    bench, truth = backend.bench, []
    step = bench.step

    def recording_step():
        volts = step()
        truth.append(bench.force_N)
        return volts

    bench.step = recording_step
    return truth


def simulated_run_steps(config, seed: int, out_root: str | Path) -> pd.DataFrame:
    """The steps of one simulated run of ``config`` with ``sim.seed = seed``, each with
    ``force_true_N`` (mean true force over its hold samples) and ``covered``."""
    config = config.replace(loadcell=IDEAL_CELL, sim={"seed": int(seed)})
    backend = SimBackend(config)
    truth_list = _recorded(backend)
    result = BenchRun(config, backend, out_root, handle_signals=False,
                      notify=lambda message: None).execute()
    if not result.status.finished:
        raise RuntimeError(f"simulated run {seed} did not finish: {result.reason}")
    truth = np.asarray(truth_list)
    steps = load_run(result.path).steps.copy()
    rate = config.daq.sample_rate_hz
    true_means = []
    for s in steps.itertuples():
        # the hold: samples after start_s + settle_s up to end_s (as bench.sequence averages)
        first = round((s.start_s + s.settle_s) * rate) + 1
        last = round(s.end_s * rate)
        if last + 1 - first != s.n:
            raise RuntimeError(f"step {s.step}: {last + 1 - first} true samples in the hold, "
                               f"{s.n} recorded")
        true_means.append(float(truth[first:last + 1].mean()))
    steps["force_true_N"] = true_means
    steps["seed"] = seed
    steps["covered"] = (steps["force_N_mean"] - steps["force_true_N"]).abs() <= steps["force_U_N"]
    return steps


def simulated_coverage(config, seeds, out_root: str | Path | None = None) -> pd.DataFrame:
    """Every settled step of one simulated run per seed (see :func:`simulated_run_steps`)."""
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(out_root) if out_root is not None else Path(tmp)
        frames = [simulated_run_steps(config, seed, root) for seed in seeds]
    steps = pd.concat(frames, ignore_index=True)
    return steps[steps["settled"]].reset_index(drop=True)
