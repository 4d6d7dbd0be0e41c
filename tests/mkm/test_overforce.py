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
from mkm.bench.preflight import braid_lock
from mkm.bench.run import acquire
from mkm.bench.sim_settings import sim_of
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
    return load_config(eps=eps).replace(sim=sim_of(TRUTH, seed, **truth))


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


def test_a_run_past_the_identified_muscles_braid_lock_is_refused(calibration, tmp_path,
                                                                 mkm_run):
    # a muscle identified at 37.6 deg locks at eps 0.271; the configuration declares no angle,
    # and the FE model's calibrated 32.99 deg locks at 0.311: a run at eps 0.28 was accepted
    steep = json.loads(calibration.read_text())
    entry = steep["thickwall"]
    entry["theta0_deg"] = 37.6
    next(p for p in entry["identified"]["parameters"]
         if p["parameter"] == "theta0_deg").update(value=37.6, ci_low=37.4, ci_high=37.8)
    path = calibration.parent / "steep.json"
    path.write_text(json.dumps(steep), encoding="utf-8")
    argv = ["acquire", "--backend", "sim", "--eps", "0.28", "--out", str(tmp_path / "runs")]
    code, out, err = mkm_run([*argv, "--calibration", str(path)])
    assert (code, out) == (2, "")
    assert err == ("mkm acquire: error: eps 0.28 is past the braid lock, eps_max 0.271 (the "
                   "braid reaches its locking angle 54.7 deg from theta0 37.60 deg, the braid "
                   f"angle of the muscle identified in {path} (thickwall)); the muscle pulls "
                   "little or nothing there: pass --allow-past-lock to record it anyway\n")
    assert not (tmp_path / "runs").exists() or not list((tmp_path / "runs").iterdir())
    config = load_config(eps=0.28)
    assert braid_lock(config) is None  # at the calibrated angle it is short of the lock
    assert braid_lock(config, force_ceiling(Calibration.load(path), config.muscle,
                                            config.regulator.max_pressure_bar))


def test_a_run_past_the_identified_lock_has_the_reports_banner(calibration, tmp_path,
                                                              mkm_run):
    # recorded past the identified lock with --allow-past-lock, the report's banner was
    # silent: it took the lock at the FE model's calibrated angle (eps_max 0.311)
    steep = json.loads(calibration.read_text())
    steep["thickwall"]["theta0_deg"] = 37.6
    path = calibration.parent / "steep.json"
    path.write_text(json.dumps(steep), encoding="utf-8")
    runs = tmp_path / "runs"
    code, _, _ = mkm_run(["acquire", "--backend", "sim", "--eps", "0.28", "--pressures",
                          "0,0.5", "--out", str(runs), "--calibration", str(path),
                          "--allow-past-lock"])
    assert code == 0
    code, out, err = mkm_run(["report", str(next(runs.iterdir())), "--models", "thickwall",
                              "--calibration", str(path), "--out", str(tmp_path / "report")])
    assert code == 0, err
    html = (tmp_path / "report" / "report.html").read_text(encoding="utf-8")
    assert ("Run 1 is held at eps 28.0 %, past the braid lock: eps_max 0.271 (the braid "
            "reaches its locking angle 54.7 deg from theta0 37.60 deg, the braid angle of the "
            "muscle identified in steep.json (thickwall))") in html
    # the identified muscle's section ended the report in a traceback ("thickwall gives no
    # valid force for run ..."): the run is said not compared there
    assert re.search(r"Run 1 \([^)]*, eps = 28\.0 %\): not compared, thickwall gives no valid "
                     r"force for run", html)


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


def config_file(tmp_path, calibration: Path, margin: float = 0.0, monitor_gain: float = 1.0,
                **replaced) -> Path:
    """The packaged example as a lab edits it: the thick-wall muscle ``TRUTH`` simulated, its
    identification named by ``[safety] calibration`` from the file's folder, a pressure
    monitor reading ``monitor_gain`` of the pressure; ``replaced``: lines of the example
    replaced (its text: the new text)."""
    text = (Path(__file__).parents[2] / "bench/configs/paper_prototype.toml").read_text()
    scale = TRUTH["rubber_scale"]
    changes = {
        "overforce_margin_fraction = 0.0":
            f'calibration = "identified/{calibration.name}"\n'
            f"overforce_margin_fraction = {margin}",
        'model = "axisym"': 'model = "thickwall"',
        "hysteresis_fraction = 0.03": f"hysteresis_fraction = {TRUTH['hysteresis_fraction']}",
        "creep_fraction = 0.02": f"creep_fraction = {TRUTH['creep_fraction']}", **replaced}
    for old, new in changes.items():
        assert text.count(old) == 1, old
        text = text.replace(old, new)
    text += (f"\n[sim.truth]\ntheta0_deg = {TRUTH['theta0_deg']}\n"
             f"C10_MPa = {scale * SILASTIC_S.C10_MPa}\nC01_MPa = {scale * SILASTIC_S.C01_MPa}\n"
             f"monitor_gain = {monitor_gain}\n")
    path = tmp_path / "lab" / "bench.toml"
    (path.parent / "identified").mkdir(parents=True)
    (path.parent / "identified" / calibration.name).write_bytes(calibration.read_bytes())
    path.write_text(text, encoding="utf-8")
    return path


@pytest.mark.parametrize("margin", [0.0, 0.1])
def test_the_configurations_calibration_arms_the_interlock_at_any_margin(calibration, tmp_path,
                                                                        mkm_run, margin):
    # a lab that always runs with its identified muscle names it once, in [safety]; the
    # widest margin still stops a monitor reading 0.8 of the pressure (1.25 times the force)
    config = config_file(tmp_path, calibration, margin, monitor_gain=0.8)
    code, out, err = mkm_run(["acquire", "--config", str(config), "--out",
                              str(tmp_path / "runs"), "--no-progress"])
    assert code == 1, err
    run = load_run(Path(out.splitlines()[-1]))
    assert run.status == "failed" and run.reason.startswith(
        "over-force interlock: the load cell read "), run.reason
    said = config.parent / "identified" / calibration.name
    assert f"the muscle identified in {said} (thickwall)" in run.reason
    assert (", plus safety.overforce_margin_fraction=0.1" in run.reason) == (margin > 0)
    assert run.meta.vent_check["verified"]
    # on a correct bench the same configuration completes
    correct = config_file(tmp_path / "correct", calibration, margin)
    code, out, err = mkm_run(["acquire", "--config", str(correct), "--out",
                              str(tmp_path / "runs"), "--no-progress"])
    assert code == 0, err


@pytest.mark.parametrize("line, said", [
    ("overforce_margin_fraction = 0.0", "overforce_margin_fraction = 0.2"),
    ("overforce_margin_fraction = 0.0", "overforce_margin_fraction = -0.01")])
def test_a_margin_out_of_bounds_is_one_line(tmp_path, mkm_run, line, said):
    text = (Path(__file__).parents[2] / "bench/configs/paper_prototype.toml").read_text()
    config = tmp_path / "bench.toml"
    config.write_text(text.replace(line, said))
    value = said.split(" = ")[1]
    code, out, err = mkm_run(["check", "--config", str(config)])
    assert (code, out) == (2, "")
    assert err == (f"mkm check: error: config {config}: safety.overforce_margin_fraction={value} "
                   "is invalid: expected 0 to 0.1 (a fraction of the identified force) (a wider "
                   "margin hides a pressure monitor reading 0.8 of the pressure, the fault the "
                   "over-force interlock is for)\n")


def test_a_missing_calibration_of_the_configuration_is_one_line(tmp_path, mkm_run,
                                                                calibration):
    config = config_file(tmp_path, calibration)
    (config.parent / "identified" / calibration.name).unlink()
    for command in (["check"], ["acquire", "--out", str(tmp_path / "runs")]):
        code, out, err = mkm_run([*command, "--config", str(config)])
        assert (code, out) == (2, "")
        assert err.startswith(f"mkm {command[0]}: error: config {config}: safety.calibration: "
                              f"calibration {config.parent / 'identified' / calibration.name}: "
                              "cannot read it: No such file or directory"), err
        assert err.count("\n") == 1
    assert not (tmp_path / "runs").exists() or not list((tmp_path / "runs").iterdir())


def test_the_python_api_refuses_a_configuration_calibration_it_was_not_given(calibration,
                                                                             tmp_path):
    from mkm.bench.config import load_config as load
    from mkm.identify.band import config_ceiling

    config = load(config_file(tmp_path, calibration))
    with pytest.raises(ValueError, match=r"safety.calibration='identified/calibration.json' "
                       r"arms the over-force interlock: pass its ceiling"):
        acquire(config, out_root=tmp_path / "runs", notify=lambda m: None)
    result = acquire(config, out_root=tmp_path / "runs", notify=lambda m: None,
                     ceiling=config_ceiling(config))
    assert result.status == "complete", result.reason


def test_check_says_each_steps_ceiling_and_refuses_a_plan_that_must_trip(calibration, tmp_path,
                                                                         mkm_run):
    from mkm.fem.ladder import make_model

    config = config_file(tmp_path, calibration)
    code, out, err = mkm_run(["check", "--config", str(config)])
    assert code == 0, err
    rows = {}
    for line in out[out.index("over-force ceiling: "):].splitlines()[2:21]:
        step, bar, *rest = line.split()
        most = float(rest.pop(0)) if rest[0][0].isdigit() else None
        rows[int(step)] = (float(bar), most, " ".join(rest))
    truth = make_model("thickwall", theta0_deg=33.0, L0_mm=282.0,
                       C10_MPa=1.1 * SILASTIC_S.C10_MPa, C01_MPa=1.1 * SILASTIC_S.C01_MPa)
    for step, (bar, most, said) in rows.items():
        if bar < 1.25:  # half max_pressure_bar: not watched
            assert most is None and said.endswith("not watched"), said
            continue
        # the true force at the reading taken its accuracy high (0.04 bar, and as much again
        # at 2.5 bar as a gain), above it by the band (a few %, not the tolerances' 20 %), and,
        # falling, the friction's upper end
        high_bar = bar + 0.04 + 0.04 / 2.5 * bar
        true_N = float(truth.predict(high_bar, 30.0, 3.0, 0.0).force_N)
        friction = 1.05067 if said.startswith("down") else 1.0
        assert 1.0 < most / friction / true_N < 1.05, (step, most, true_N)
    # a step held falling keeps the friction's 5.07 % over the same pressure held rising
    assert rows[14][0] == rows[4][0] == 1.25
    assert rows[14][1] / rows[4][1] == pytest.approx(1.05067, abs=2e-4)
    top = float(truth.predict(2.5 - 0.04 - 0.04, 30.0, 3.0, 0.0).force_N)
    least = re.search(r"the top step, 2.5 bar: the muscle identified pulls at least (\d+) N on "
                      r"its rise, under the force interlock at 1765 N\n", out)
    # below what the muscle pulls rising at the reading taken its accuracy low
    assert 0.9 * (1 - 0.05067) * top < float(least.group(1)) < (1 - 0.05067) * top
    # a 900 N cell's interlock at 810 N: the rise to 2.5 bar must trip it
    small = config_file(tmp_path / "small", calibration, **{
        "capacity_N = 1961.33": "capacity_N = 900.0",
        "sensitivity_N_per_V = 196.133": "sensitivity_N_per_V = 90.0",
        "tare_max_shift_N = 100.0": "tare_max_shift_N = 50.0"})
    code, out, err = mkm_run(["check", "--config", str(small)])
    refused = (f"the muscle identified pulls at least {least.group(1)} N on the rise to the top "
               "step, 2.5 bar (the muscle identified in "
               f"{small.parent / 'identified' / calibration.name} (thickwall): its force less its "
               "95 % band and friction, at the reading at its accuracy), at or beyond the force "
               "interlock at 810 N (0.9 x loadcell.capacity_N=900): the run must stop there; "
               "lower the top pressure to 2 bar or less, or use a larger load cell")
    assert code == 1 and err.endswith(
        f"mkm check: error: {refused}; `mkm acquire` refuses this plan: fix this first\n"), err
    code, out, err = mkm_run(["acquire", "--config", str(small), "--out",
                              str(tmp_path / "runs")])
    assert (code, out) == (2, "")
    assert err.endswith(f"mkm acquire: error: {refused}; nothing was pressurised\n"), err
    assert not (tmp_path / "runs").exists() or not list((tmp_path / "runs").iterdir())
    # the top pressure offered is one the muscle surely pulls less than 810 N at: its band's
    # upper end at the reading taken its accuracy high; the run to it completes (offered from
    # the band's lower end, 2.35 bar, the run tripped the force interlock at 810.3 N)
    code, out, err = mkm_run(["check", "--config", str(small), "--pressures", "0.25:2:0.25"])
    assert code == 0, err
    code, out, err = mkm_run(["acquire", "--config", str(small), "--pressures", "0.25:2:0.25",
                              "--out", str(tmp_path / "runs"), "--no-progress"])
    run = load_run(Path(out.splitlines()[-1]))
    assert (code, run.status) == (0, "complete"), run.reason
    assert run.samples["force_N"].max() < 810.0


def test_the_ceiling_below_the_identified_threshold_holds_the_muscles_that_pull_there(
        tmp_path):
    # a rubber identified to +-5 % (1 sd), no term: at eps 0.24 the identified muscle is slack
    # up to 1.75 bar, where a muscle of the interval 1.96 sd softer pulls already; the ceiling
    # took the linearised band, 0 N at every slack step (its steps stiffer, slack too), and a
    # sound muscle pulling a few newtons there read more than it
    rubber = json.loads(json.dumps(CALIBRATION))
    entry = rubber["thickwall"]
    sd = 0.05 * 1.09997
    entry["identified"]["band"] = {"parameters": ["rubber_scale"], "values": [1.09997],
                                   "covariance": [[sd**2]]}
    path = tmp_path / "calibration.json"
    path.write_text(json.dumps(rubber), encoding="utf-8")
    config = sim_config(0.24)
    ceiling = force_ceiling(Calibration.load(path), config.muscle, 2.5)
    from mkm.fem.ladder import make_model

    def force(scale):
        return make_model("thickwall", theta0_deg=33.0003, L0_mm=282.0,
                          C10_MPa=scale * SILASTIC_S.C10_MPa,
                          C01_MPa=scale * SILASTIC_S.C01_MPa).predict(
            np.array(ceiling.pressure_bar), 30.0, 3.0, 0.24)

    identified, softer = force(1.09997), force(1.09997 - 1.959964 * sd)
    slack = (identified.force_N == 0) & (softer.force_N > 0)
    assert slack.sum() >= 2, softer.force_N[identified.force_N == 0]
    np.testing.assert_allclose(np.array(ceiling.force_N)[slack], softer.force_N[slack],
                               rtol=1e-3)
    assert np.all(np.array(ceiling.least_N)[slack] == 0.0)
