"""The held-out run's judgement (mkm.identify.band.judge_steps): one statement per run, at 95 %.

Regression: bench_identify_coverage.py --departures in-family --seed 2026120503 held 16 of its
first 20 held-out runs inside (80 %, target >= 90 %): every miss a slack step at eps 18 %
(predicted 0 N, band 0) whose mean was 1.1-1.5 times its own 95 % noise reach. Judged at 1.96
noise per step, a run with six such steps misses 1 - 0.95^6 = 26 % of the time however exact
the prediction (a simulated run at eps 0.18, theta0 35 deg: 5.0 % of 360 slack steps outside
1.96, 21.7 % of 60 runs with one outside).
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.stats import norm

from mkm.identify.band import Z95, judge_steps, run_noise_z


def test_the_runs_noise_factor_is_sidaks():
    assert run_noise_z(1) == pytest.approx(Z95, abs=1e-6)
    # 19 steps: each at 0.95 ** (1 / 19) = 99.73 %, two-sided
    assert run_noise_z(19) == pytest.approx(norm.ppf(0.5 + 0.5 * 0.95 ** (1 / 19)), rel=1e-9)
    assert run_noise_z(19) == pytest.approx(3.0004, abs=1e-3)


def test_an_exact_prediction_leaves_95_percent_of_runs_inside():
    # the paper's staircase at eps 18 %: 19 steps, six slack (band 0) judged by their noise
    # alone, the others pulling with a band of 3 % of 100 N; each step's mean off by its hold's
    # scatter (0.057 N, independent) plus the run's tare (0.055 N, shared): the figures of the
    # simulated bench (0.4 N rms over 50 samples each). The prediction is exact, so the runs
    # inside must be >= 95 % (Sidak's bound holds for correlated normals): 0.95 - 3 standard
    # errors of 4000 runs (0.0034) is the floor: 98.5 % are; at 1.96 per step 79.0 % were.
    rng = np.random.default_rng(20261205)
    runs, hold, tare = 4000, 0.057, 0.055
    band = np.r_[np.zeros(6), np.full(13, 3.0)]
    noise = np.full(19, np.hypot(hold, tare))
    inside = [judge_steps(np.abs(rng.normal(0, hold, 19) + rng.normal(0, tare)), band,
                          noise)["run_inside"] for _ in range(runs)]
    assert np.mean(inside) >= 0.95 - 3 * np.sqrt(0.05 * 0.95 / runs)
    # and a step is still judged at its own 95 %: the per-step verdict is 1.96 noise
    step = judge_steps([0.9, 1.1], [0.0, 0.0], [0.5, 0.5])
    assert step["inside"].tolist() == [True, False]
    assert step["run_inside"]  # 1.1 N within 2.24 x 0.5 N: the factor of a two-step run


def test_a_gross_miss_is_still_outside():
    # a slack step measuring 0.4 N against 0.08 N of noise (5 sigma, the size of a threshold
    # 0.01 bar off at 40 N/bar) stays outside the run's reach of 3.0 x 0.08 N
    judged = judge_steps(np.r_[0.4, np.zeros(18)], np.zeros(19), np.full(19, 0.08))
    assert not judged["run_inside"]
    assert judged["run_reach"][0] == pytest.approx(3.0004 * 0.08, rel=1e-3)
