"""Does the expanded interval of :mod:`mkm.bench.budget` cover the truth? Checked on simulated
runs.

The simulated bench (:mod:`mkm.bench.sim`) knows the force on its cell and the pressure in the
muscle at every sample: the model's static force with braid friction and creep (the measurand,
see :mod:`mkm.bench.budget`). :func:`simulated_coverage` records whole runs through the normal
run code, one per seed, and compares every settled step's recorded force and pressure with the
mean true ones over the same hold samples: covered when ``|F_meas - F_true| <= force_U_N`` (and
``|P_meas - P_true| <= pressure_U_bar``).

Each run's instruments are drawn within the data sheet the configuration declares
(:func:`instrument_draw`): the load cell's gain uniform within
``loadcell.sensitivity_tolerance_fraction``; the pressure monitor from what ``[regulator]``
declares of its error (:data:`mkm.bench.config.MONITOR_COMPONENTS`):

- its components: each drawn uniformly within its own bound, independent: the offset within
  ``monitor_zero_bar``, the gain within ``1 +- monitor_span_fraction``, the bow's amplitude
  (``[sim.truth] monitor_bow_bar``, a non-linearity zero at both ends of the sensor's scale)
  within ``monitor_nonlinearity_bar``, the difference between rising and falling readings
  within ``0..monitor_hysteresis_bar``; a component not declared is not drawn (exact). Each
  then reaches its bound somewhere: the zero everywhere, the span at the top of the range,
  the bow at mid-scale (2 bar on a 4 bar sensor), the hysteresis on every branch;
- ``monitor_accuracy_bar`` alone: a linear sensor (an offset and a gain) that meets the bound
  over the whole range, uniform over every such sensor: its error at 0 bar and its error at
  ``regulator.max_pressure_bar`` each uniform within the bound, independent, and the error in
  between on the line joining them (a bound over the range is met at every pressure when it is
  met at both ends). At either end the error is then uniform within the bound, as the budget's
  rectangular term says; in between it is the mean of two such errors, weighted by the position
  in the range, more often small: the budget's interval, right at the ends, covers more there.

The simulated cell is linear and its zero does not drift, so those two data-sheet terms
(``nonlinearity_fraction_fs``, ``zero_drift_fraction_fs``) are set to zero: they would have
nothing to cover.
"""

from __future__ import annotations

import tempfile
from pathlib import Path

import numpy as np
import pandas as pd

from mkm.bench.run import BenchRun
from mkm.bench.sim import SimBackend
from mkm.bench.storage import load_run

#: the data-sheet terms the simulated cell has no error for
LINEAR_CELL = {"nonlinearity_fraction_fs": 0.0, "zero_drift_fraction_fs": 0.0}


def instrument_draw(config, seed: int) -> dict:
    """``[sim.truth]``'s instrument errors for run ``seed``, uniform within the data sheet of
    ``config`` (see the module docstring)."""
    rng = np.random.default_rng([int(seed), 0x1A57])
    tolerance = config.loadcell.sensitivity_tolerance_fraction
    gain = 1.0 + float(rng.uniform(-tolerance, tolerance))
    components = config.regulator.monitor_components
    if components:
        # the truth each declared component stands for, and the interval it is drawn from
        drawn = {"monitor_zero_bar": ("monitor_offset_bar", -1.0, 0.0),
                 "monitor_span_fraction": ("monitor_gain", -1.0, 1.0),
                 "monitor_nonlinearity_bar": ("monitor_bow_bar", -1.0, 0.0),
                 "monitor_hysteresis_bar": ("monitor_hysteresis_bar", 0.0, 0.0)}
        truth = {}
        for name, bound in components.items():
            key, low, shift = drawn[name]
            truth[key] = shift + float(rng.uniform(low * bound, bound))
        return {"loadcell_gain": gain, **truth}
    accuracy = config.regulator.monitor_accuracy_bar
    at_zero, at_full_scale = rng.uniform(-accuracy, accuracy, size=2)
    return {"loadcell_gain": gain, "monitor_offset_bar": float(at_zero),
            "monitor_gain": 1.0 + float(at_full_scale - at_zero)
            / config.regulator.max_pressure_bar}


def _recorded(backend: SimBackend) -> list[tuple[float, float]]:
    """Make ``backend`` keep the true force and pressure of every sample it takes; return that
    list."""
    bench, truth = backend.bench, []
    step = bench.step

    def recording_step():
        volts = step()
        truth.append((bench.force_N, bench.pressure_bar))
        return volts

    bench.step = recording_step
    return truth


def simulated_run_steps(config, seed: int, out_root: str | Path) -> pd.DataFrame:
    """The steps of one simulated run of ``config`` with ``sim.seed = seed`` and its instruments
    drawn (:func:`instrument_draw`), each step with ``force_true_N`` and ``pressure_true_bar``
    (the means over its hold samples), ``covered`` (the force) and ``pressure_covered``."""
    truth = {**config.sim.truth.__dict__, **instrument_draw(config, seed)}
    config = config.replace(loadcell=LINEAR_CELL, sim={"seed": int(seed), "truth": truth})
    backend = SimBackend(config)
    truth_list = _recorded(backend)
    result = BenchRun(config, backend, out_root, handle_signals=False,
                      notify=lambda message: None).execute()
    if not result.status.finished:
        raise RuntimeError(f"simulated run {seed} did not finish: {result.reason}")
    true_force, true_pressure = np.asarray(truth_list).T
    steps = load_run(result.path).steps.copy()
    rate = config.daq.sample_rate_hz
    true_means, true_pressures = [], []
    for s in steps.itertuples():
        # the hold: samples after start_s + settle_s up to end_s (as bench.sequence averages)
        first = round((s.start_s + s.settle_s) * rate) + 1
        last = round(s.end_s * rate)
        if last + 1 - first != s.n:
            raise RuntimeError(f"step {s.step}: {last + 1 - first} true samples in the hold, "
                               f"{s.n} recorded")
        true_means.append(float(true_force[first:last + 1].mean()))
        true_pressures.append(float(true_pressure[first:last + 1].mean()))
    steps["force_true_N"] = true_means
    steps["pressure_true_bar"] = true_pressures
    steps["seed"] = seed
    for key, value in instrument_draw(config, seed).items():
        steps[key] = value
    steps["covered"] = (steps["force_N_mean"] - steps["force_true_N"]).abs() <= steps["force_U_N"]
    steps["pressure_covered"] = ((steps["pressure_bar_mean"] - steps["pressure_true_bar"]).abs()
                                 <= steps["pressure_U_bar"])
    return steps


def simulated_coverage(config, seeds, out_root: str | Path | None = None) -> pd.DataFrame:
    """Every settled step of one simulated run per seed (see :func:`simulated_run_steps`)."""
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(out_root) if out_root is not None else Path(tmp)
        frames = [simulated_run_steps(config, seed, root) for seed in seeds]
    steps = pd.concat(frames, ignore_index=True)
    return steps[steps["settled"]].reset_index(drop=True)
