"""mkm acquire --calibration: the identified muscle bounds what the load cell may read.

A pressure monitor reading low by its gain (a 5 bar regulator's monitor read on the 4 bar
scale declared: 0.8 of the pressure, its zero right, so the tare sees nothing) makes its
regulator deliver 1.25 times every command, which the over-pressure limit, watching that same
monitor, never sees: the packaged staircase completed holding 3.125 bar at its 2.5 bar step. The
muscle ``mkm identify`` found is the load cell's witness: its force, with its 95 % band and its
friction, bounds what each measured pressure can pull.

The simulated muscle is the thick-wall closed form (as identify's fast tests make it), so the
identified muscle is known exactly: ``CALIBRATION`` is what ``mkm identify`` wrote for two blind
runs of it at eps 0 and 0.122 (band and intervals rounded; seed 0), without the provenance.
"""

from __future__ import annotations

import dataclasses
import json
import re
from pathlib import Path

import numpy as np
import pytest

from mkm.bench.config import load_config
from mkm.bench.run import acquire
from mkm.bench.storage import load_run
from mkm.fem.calibration import Calibration
from mkm.fem.materials import SILASTIC_S
from mkm.identify.band import force_ceiling

TRUTH = {"theta0_deg": 33.0, "rubber_scale": 1.1, "hysteresis_fraction": 0.05,
         "creep_fraction": 0.03}
MUSCLE = {"D0_mm": 30.0, "t0_mm": 3.0, "L0_mm": 282.0, "id": "paper-prototype"}
CALIBRATION = {"thickwall": {
    "theta0_deg": 33.0003, "C10_MPa": 0.076338, "C01_MPa": 0.069078,
    "hysteresis_fraction": 0.049985, "creep_fraction": 0.029886, "creep_tau_s": 29.97579,
    "model_params": {"C10_MPa": 0.076338, "C01_MPa": 0.069078, "L0_mm": 282.0},
    "target": "identify",
    "identified": {
        "runs": [{"run": f"run-eps-{eps}", "path": f"runs/run-eps-{eps}",
                  "muscle": {**MUSCLE, "eps": eps}} for eps in (0.0, 0.122)],
        "parameters": [
            {"parameter": "theta0_deg", "value": 33.0003, "ci_low": 32.767,
             "ci_high": 33.248, "status": "fitted"},
            {"parameter": "rubber_scale", "value": 1.09997, "ci_low": 1.0606,
             "ci_high": 1.1405, "status": "fitted"},
            {"parameter": "hysteresis_fraction", "value": 0.049985, "ci_low": 0.04929,
             "ci_high": 0.05067, "status": "fitted"},
            {"parameter": "D0_mm", "value": 30.0, "status": "assumed"},
            {"parameter": "t0_mm", "value": 3.0, "status": "assumed"}],
        "band": {"parameters": ["theta0_deg", "rubber_scale"], "values": [33.0003, 1.09997],
                 "covariance": [[0.015019, -0.00047164], [-0.00047164, 0.00041543]],
                 "sensitivity_tolerance": 0.001,
                 "terms": [{"kind": "one-sided", "shift": {"c01_fraction": -0.47504,
                                                           "rubber_scale": -0.10803}},
                           {"kind": "one-sided", "shift": {"c01_fraction": 0.12496,
                                                           "rubber_scale": 0.032442}}]}}}}


def sim_config(eps: float, seed: int = 0, **truth):
    """The packaged bench holding the thick-wall muscle ``TRUTH`` at ``eps`` (its instruments
    other than declared by ``truth``: ``[sim.truth]``)."""
    scale = TRUTH["rubber_scale"]
    return load_config(eps=eps).replace(sim={
        "model": "thickwall", "seed": seed,
        "hysteresis_fraction": TRUTH["hysteresis_fraction"],
        "creep_fraction": TRUTH["creep_fraction"],
        "truth": {"theta0_deg": TRUTH["theta0_deg"], "C10_MPa": scale * SILASTIC_S.C10_MPa,
                  "C01_MPa": scale * SILASTIC_S.C01_MPa, **truth}})


@pytest.fixture
def calibration(tmp_path) -> Path:
    path = tmp_path / "identified" / "calibration.json"
    path.parent.mkdir()
    path.write_text(json.dumps(CALIBRATION), encoding="utf-8")
    return path


def record(config, calibration: Path, out: Path):
    ceiling = force_ceiling(Calibration.load(calibration), config.muscle,
                            config.regulator.max_pressure_bar)
    return acquire(config, out_root=out, notify=lambda m: None, ceiling=ceiling)


@pytest.mark.parametrize("eps", [0.0, 0.122])
def test_a_monitor_reading_low_by_its_gain_is_stopped_by_the_identified_muscle(
        calibration, tmp_path, eps):
    config = sim_config(eps, monitor_gain=0.8)
    unwatched = acquire(config, out_root=tmp_path / "unwatched", notify=lambda m: None)
    assert unwatched.status == "complete"  # the over-pressure limit sees nothing
    held = load_run(unwatched.path).samples["pressure_bar"] / 0.8  # the sensor's gain alone
    assert held.max() > 3.1  # 3.125 bar held at the 2.5 bar step, 2.5 bar the limit
    result = record(config, calibration, tmp_path / "watched")
    run = load_run(result.path)
    assert result.status == "failed" and result.exit_code == 1, result.reason
    found = re.match(
        r"over-force interlock: the load cell read (\d+\.\d) N at [\d.]+ s with the monitor "
        r"reading (\d\.\d{3}) bar, more than the muscle pulls there: the muscle identified in "
        + re.escape(str(calibration)) + r" \(thickwall\) pulls at most (\d+\.\d) N at eps "
        + f"{eps:g}" + r" \(at [\d.]+ bar, the reading at its accuracy, with its 95 % band and "
        r"5\.07 % for the braid's friction\), and the load cell's accuracy is [\d.]+ N: the "
        r"pressure monitor reads low \(a gain or zero error; .*\), or the load cell reads high; "
        r"check the monitor against a reference gauge", result.reason)
    assert found, result.reason
    read_N, reading_bar, most_N = map(float, found.groups())
    assert read_N > most_N
    # judged from half the 2.5 bar limit up, in pre-conditioning's rise: the muscle never
    # held more than the limit's 2.5 bar
    assert 1.25 <= reading_bar < 1.4
    assert (run.samples["pressure_bar"] / 0.8).max() < 2.5
    assert run.meta.vent_check["verified"]
    assert run.commands["purpose"].iloc[-1] == "vent"
    assert run.meta.calibration["force_ceiling"] == {
        "source": f"the muscle identified in {calibration} (thickwall)",
        "friction_fraction": 0.05067}


@pytest.mark.parametrize("eps, truth", [
    (0.0, {}), (0.122, {}), (0.2, {}), (0.3, {}),
    # instruments off by what the configuration declares they may be: no over-force
    (0.0, {"monitor_gain": 1.0 - 0.016}), (0.0, {"monitor_offset_bar": -0.04}),
    (0.0, {"loadcell_gain": 1.001}), (0.122, {"frame_stiffness_N_per_mm": 300.0})])
def test_the_identified_muscle_on_a_correct_bench_never_trips(calibration, tmp_path, eps,
                                                              truth):
    # the packaged staircase: pre-conditioning to 2.5 bar, up and down (the falling branch
    # holds the braid's friction), each hold creeping 3 %
    result = record(sim_config(eps, **truth), calibration, tmp_path)
    assert result.status == "complete", result.reason


def test_repeats_and_another_noise_draw_never_trip(calibration, tmp_path):
    config = sim_config(0.05, seed=7).replace(sequence={"repeats": 2})
    result = record(config, calibration, tmp_path)
    assert result.status == "complete", result.reason
    steps = load_run(result.path).steps
    assert (steps["repeat"] == 1).any() and (steps["direction"] == "down").any()


def test_the_ceiling_holds_the_identified_force_and_its_band(calibration):
    config = sim_config(0.0)
    ceiling = force_ceiling(Calibration.load(calibration), config.muscle, 2.5)
    assert ceiling.pressure_bar[0] == 0.0 and ceiling.pressure_bar[-1] == pytest.approx(3.75)
    assert ceiling.friction_fraction == 0.05067  # the friction's interval, upper end
    from mkm.fem.ladder import make_model

    truth = make_model("thickwall", theta0_deg=33.0, L0_mm=282.0,
                       C10_MPa=1.1 * SILASTIC_S.C10_MPa, C01_MPa=1.1 * SILASTIC_S.C01_MPa)
    at = np.array([1.0, 2.5])
    true_N = truth.predict(at, 30.0, 3.0, 0.0).force_N
    most_N = np.interp(at, ceiling.pressure_bar, ceiling.force_N)
    # above the truth, by the band: a few % of the force, not the declared tolerances' 20 %
    assert np.all(most_N > true_N) and np.all(most_N < 1.05 * true_N), (most_N, true_N)


def test_acquire_takes_the_calibration_and_refuses_another_muscles(calibration, tmp_path,
                                                                  mkm_run):
    other = json.loads(calibration.read_text())
    for run in other["thickwall"]["identified"]["runs"]:
        run["muscle"]["t0_mm"] = 2.5
    wrong = tmp_path / "wrong.json"
    wrong.write_text(json.dumps(other))
    code, out, err = mkm_run(["acquire", "--backend", "sim", "--calibration", str(wrong),
                              "--out", str(tmp_path / "runs")])
    assert (code, out) == (2, "")
    assert err == (f"mkm acquire: error: --calibration {wrong} identified a muscle of "
                   "t0_mm=2.5; the configuration declares t0_mm=3: expected the "
                   "identification of the muscle this run holds\n")
    shipped = Path(__file__).parents[2] / "fem" / "calibration.json"
    code, out, err = mkm_run(["acquire", "--backend", "sim", "--calibration", str(shipped),
                              "--out", str(tmp_path / "runs")])
    assert (code, out) == (2, "")
    assert err == (f"mkm acquire: error: --calibration {shipped} holds no muscle mkm identify "
                   "identified with its prediction band: expected the calibration.json of "
                   "`mkm identify RUNS --out DIR` for this muscle\n")
    assert not (tmp_path / "runs").exists() or not list((tmp_path / "runs").iterdir())


def test_a_muscle_identified_over_several_lengths_bounds_a_run_of_any_of_them(tmp_path):
    # the runs of one tube at two lengths: a run of the second length is that muscle too
    both = json.loads(json.dumps(CALIBRATION))
    both["thickwall"]["identified"]["runs"][0]["muscle"]["L0_mm"] = 150.0
    path = tmp_path / "calibration.json"
    path.write_text(json.dumps(both))
    config = sim_config(0.0)
    ceiling = force_ceiling(Calibration.load(path), config.muscle, 2.5)
    assert np.interp(2.5, ceiling.pressure_bar, ceiling.force_N) > 0
    with pytest.raises(ValueError, match="identified a muscle of L0_mm=150; the "
                       "configuration declares L0_mm=200: expected"):
        force_ceiling(Calibration.load(path), dataclasses.replace(config.muscle, L0_mm=200.0),
                      2.5)
