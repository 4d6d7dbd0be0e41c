"""[sim.truth]: a simulated muscle that is not the nominal one, recorded in its simulator settings
only."""

import json
import re

import numpy as np
import pytest

from mkm.bench.config import parse_config
from mkm.bench.run import acquire
from mkm.bench.sim import LSB_V, SimMuscleBench, describe_physics, static_force_table
from mkm.bench.sim_settings import remove_simulator_settings
from mkm.fem.ladder import make_model
from mkm.fem.materials import SILASTIC_S

TRUTH = {"theta0_deg": 30.0, "C10_MPa": 1.3 * SILASTIC_S.C10_MPa,
         "C01_MPa": 1.3 * SILASTIC_S.C01_MPa}


def quiet(config, **sim):
    settings = {"noise_V": 0.0, "monitor_noise_V": 0.0, "hysteresis_fraction": 0.0,
                "creep_fraction": 0.0, "loadcell_offset_V": 0.0, "fe_mesh": "coarse", **sim}
    return config.replace(sim=settings)


def test_a_truth_changes_the_forces_as_the_fe_model_says(config):
    nominal, true = quiet(config), quiet(config, truth=TRUTH)
    m = config.muscle
    fe_nominal = make_model("axisym", mesh="coarse", L0_mm=m.L0_mm)
    fe_true = make_model("axisym", mesh="coarse", L0_mm=m.L0_mm, **TRUTH)
    for c, fe in ((nominal, fe_nominal), (true, fe_true)):
        bench = SimMuscleBench(c)
        bench.set_command_volts(c.regulator.command_volts(2.0))
        for _ in range(100):  # 10 s: the regulator has settled to 1e-10 bar
            volts = bench.step()
        expected = float(fe.predict(2.0, m.D0_mm, m.t0_mm, m.eps).force_N)
        # table interpolation (the FE force is linear in P above the threshold to < 0.1 N over
        # 0.05 bar) plus one ADC step of 0.24 N
        assert volts[0] * c.loadcell.sensitivity_N_per_V == pytest.approx(expected, abs=0.35)
    # the truth is a different muscle: a smaller braid angle pulls harder, by the FE's amount
    p, f_true = static_force_table(true)
    _, f_nominal = static_force_table(nominal)
    assert np.interp(2.0, p, f_true) - np.interp(2.0, p, f_nominal) == pytest.approx(
        float(fe_true.predict(2.0, m.D0_mm, m.t0_mm, m.eps).force_N
              - fe_nominal.predict(2.0, m.D0_mm, m.t0_mm, m.eps).force_N), abs=0.2)
    assert np.interp(2.0, p, f_true) > 1.05 * np.interp(2.0, p, f_nominal)


def test_unset_truth_is_the_nominal_muscle(config):
    p, f = static_force_table(quiet(config))
    p2, f2 = static_force_table(quiet(config, truth={"theta0_deg": None}))
    np.testing.assert_array_equal(f, f2)


@pytest.mark.parametrize("truth, message", [
    ({"theta0_deg": 0.5}, "sim.truth.theta0_deg=0.5 is invalid: expected a braid angle"),
    ({"C10_MPa": -1.0}, "sim.truth.C10_MPa=-1 is invalid"),
    # within the typo bounds but past the braid's locking angle: was refused later, by the FE
    # model, as 'theta0_deg=60 is invalid', which left the reader to guess which of a config's
    # three theta0_deg ([muscle], [muscle.tolerances], [sim.truth]) it was
    ({"theta0_deg": 60.0}, r"^sim.truth.theta0_deg=60 is invalid: expected 0 < theta0 < 54.7 "
                           r"deg \(above the locking angle the muscle cannot pull\)$"),
])
def test_a_bad_truth_is_named(config, truth, message):
    with pytest.raises(ValueError, match=message):
        config.replace(sim={"truth": truth})


def test_a_truth_the_model_does_not_take_is_refused(config):
    with pytest.raises(ValueError, match="sim.truth.C10_MPa is not a parameter of "
                                         "sim.model='eq2': expected some of theta0_deg"):
        config.replace(sim={"model": "eq2", "truth": {"C10_MPa": 0.05}})


def test_the_truth_is_recorded_in_the_simulator_settings(config, tmp_path):
    text = config.text + "\n[sim.truth]\ntheta0_deg = 31.5\n"
    c = parse_config(text, "truth.toml").replace(
        sequence=config.sequence.__dict__, settle=config.settle.__dict__,
        sim={"fe_mesh": "coarse"})
    result = acquire(c, out_root=tmp_path)
    meta = json.loads((result.path / "run.json").read_text(encoding="utf-8"))
    sim = meta["hardware"]["sim"]
    assert sim["truth"] == {"theta0_deg": 31.5, "C10_MPa": None, "C01_MPa": None,
                            "gap_mm": None, "braid": None, "D0_mm": None, "t0_mm": None,
                            "loadcell_gain": None, "loadcell_drift_N_per_min": None,
                            "monitor_gain": None, "monitor_offset_bar": None,
                            "monitor_bow_bar": None,
                            "monitor_hysteresis_bar": None, "monitor_stuck_bar": None,
                            "frame_stiffness_N_per_mm": None, "line_tau_s": None,
                            "mullins_fraction": None, "braid_EA_N": None}
    assert sim["physics"]["instruments"]["monitor_stuck_bar"] is None  # a monitor that reads
    assert sim["physics"]["force_model_params"]["theta0_deg"] == 31.5
    assert "[sim.truth]\ntheta0_deg = 31.5" in (result.path / "config.toml").read_text("utf-8")


def test_a_gap_truth_is_the_thick_wall_muscle_with_that_gap(config):
    m = config.muscle
    pressure, force = static_force_table(quiet(config, model="thickwall",
                                               truth={"gap_mm": 0.8}))
    expected = make_model("thickwall", L0_mm=m.L0_mm, gap_mm=0.8).predict(
        pressure, m.D0_mm, m.t0_mm, m.eps)
    # the table is the model at its pressures: only the table's own arithmetic differs
    np.testing.assert_allclose(force, expected.force_N, rtol=1e-12, atol=1e-12)
    _, gap_free = static_force_table(quiet(config, model="thickwall"))
    assert np.argmax(force > 0) > np.argmax(gap_free > 0)  # the force starts later
    # the FE takes a gap too (a unilateral contact); a rung without one refuses it
    assert config.replace(sim={"truth": {"gap_mm": 0.8}}).sim.truth.gap_mm == 0.8
    with pytest.raises(ValueError, match=r"sim.truth.gap_mm is not a parameter of "
                                         r"sim.model='eq2'"):
        config.replace(sim={"model": "eq2", "truth": {"gap_mm": 0.8}})


def test_a_hold_just_above_the_threshold_reads_the_models_force(config):
    # at eps 0.122 the thick-wall threshold lies between two of the table's 0.05 bar points:
    # a knot there keeps the kink, so the force just above it is the model's, not a line
    # drawn from the grid point below it
    short = quiet(config.replace(muscle={"eps": 0.122}), model="thickwall")
    m = short.muscle
    model = make_model("thickwall", L0_mm=m.L0_mm)
    threshold = float(model.predict(1.0, m.D0_mm, m.t0_mm, m.eps)
                      .extras["threshold_pressure_bar"])
    assert 0.3 < threshold < 0.6 and not np.isclose(threshold % 0.05, 0.0)
    pressure, force = static_force_table(short)
    assert threshold in pressure and force[pressure <= threshold].max() == 0.0
    P = threshold + np.array([0.005, 0.01, 0.02, 0.04])
    exact = model.predict(P, m.D0_mm, m.t0_mm, m.eps).force_N
    # the thick-wall force is close to linear above its threshold: within 1 % of it there
    np.testing.assert_allclose(np.interp(P, pressure, force), exact, rtol=0.01)


def settled(config, pressure_bar: float = 2.0):
    """The bench after 10 s at ``pressure_bar``: (load-cell V, monitor V) and the bench."""
    bench = SimMuscleBench(config)
    bench.set_command_volts(config.regulator.command_volts(pressure_bar))
    for _ in range(100):  # the regulator has settled to 1e-10 bar
        volts = bench.step()
    return volts, bench


def test_a_loadcell_gain_records_every_force_that_much_high(config):
    c = quiet(config, model="thickwall", truth={"loadcell_gain": 1.02})
    volts, bench = settled(c)
    recorded = volts[0] * c.loadcell.sensitivity_N_per_V
    # 2 % of ~760 N is 15 N; one ADC step is 0.24 N
    assert recorded - bench.force_N == pytest.approx(0.02 * bench.force_N,
                                                     abs=LSB_V * c.loadcell.sensitivity_N_per_V)
    # the force itself is the muscle's, at the pressure held: the gain changes the reading only
    _, exact = settled(quiet(config, model="thickwall"))
    assert bench.force_N == pytest.approx(exact.force_N, rel=1e-12)


def test_a_loadcell_drift_moves_the_reading_steadily_with_time(config):
    # 3 N/min: after the 10 s of settled() the cell reads 0.5 N above the force, after 70 s
    # 3.5 N; the force itself is the muscle's
    c = quiet(config, model="thickwall", truth={"loadcell_drift_N_per_min": 3.0})
    volts, bench = settled(c)
    lsb_N = LSB_V * c.loadcell.sensitivity_N_per_V
    recorded = volts[0] * c.loadcell.sensitivity_N_per_V
    assert recorded - bench.force_N == pytest.approx(0.5, abs=lsb_N)
    _, exact = settled(quiet(config, model="thickwall"))
    assert bench.force_N == pytest.approx(exact.force_N, rel=1e-12)
    for _ in range(600):
        volts = bench.step()
    assert volts[0] * c.loadcell.sensitivity_N_per_V - bench.force_N == pytest.approx(
        3.5, abs=lsb_N)


@pytest.mark.parametrize("truth, read", [
    ({"monitor_offset_bar": 0.03}, lambda p: p + 0.03),
    ({"monitor_gain": 1.01}, lambda p: 1.01 * p),
    ({"monitor_gain": 0.99, "monitor_offset_bar": -0.02}, lambda p: 0.99 * p - 0.02),
])
def test_the_monitor_reads_the_true_pressure_through_its_error(config, truth, read):
    c = quiet(config, model="thickwall", truth=truth)
    volts, bench = settled(c)
    recorded_bar = float(c.regulator.monitor_bar(volts[1]))
    lsb_bar = float(c.regulator.monitor_bar(c.regulator.monitor_V_at_zero + LSB_V))
    assert recorded_bar == pytest.approx(read(bench.pressure_bar), abs=lsb_bar)
    # the regulator holds its own sensor at the command: the monitor reads 2 bar, the muscle
    # sees the pressure that makes the sensor read it
    assert recorded_bar == pytest.approx(2.0, abs=lsb_bar)
    assert read(bench.pressure_bar) == pytest.approx(2.0, abs=1e-9)


def bow(p, amplitude_bar, full_scale_bar=4.0):
    """The simulated sensor's non-linearity: zero at both ends of its scale, the amplitude at
    mid-scale."""
    x = p / full_scale_bar
    return amplitude_bar * 4 * x * (1 - x)


@pytest.mark.parametrize("truth, read", [
    ({"monitor_bow_bar": 0.03}, lambda p: p + bow(p, 0.03)),
    # on a rising pressure a sensor with hysteresis reads half of it low
    ({"monitor_gain": 1.01, "monitor_offset_bar": -0.01, "monitor_bow_bar": -0.02,
      "monitor_hysteresis_bar": 0.02}, lambda p: 1.01 * p - 0.01 + bow(p, -0.02) - 0.01),
])
def test_the_monitor_reads_truth_times_gain_plus_offset_plus_bow(config, truth, read):
    c = quiet(config, model="thickwall", truth=truth)
    for pressure in (0.5, 2.0):
        volts, bench = settled(c, pressure)
        recorded_bar = float(c.regulator.monitor_bar(volts[1]))
        lsb_bar = float(c.regulator.monitor_bar(c.regulator.monitor_V_at_zero + LSB_V))
        assert recorded_bar == pytest.approx(read(bench.pressure_bar), abs=lsb_bar)
        # the regulator holds the bowed reading at the command too
        assert read(bench.pressure_bar) == pytest.approx(pressure, abs=1e-9)


@pytest.mark.parametrize("truth", [{"monitor_offset_bar": -0.03}, {"monitor_gain": 0.99},
                                   {"monitor_hysteresis_bar": 0.06}])
def test_a_sensor_reading_low_at_full_scale_pushes_the_muscle_above_it(config, truth):
    # commanded to the regulator's full scale, a sensor that reads low has the regulator deliver
    # more: the muscle pulls with the force of the pressure it really has, not full scale's
    c = quiet(config.replace(regulator={"max_pressure_bar": 4.0}), model="thickwall",
              truth=truth)
    volts, bench = settled(c, 4.0)
    m = c.muscle
    reads = {"monitor_offset_bar": lambda p: p - 0.03, "monitor_gain": lambda p: 0.99 * p,
             "monitor_hysteresis_bar": lambda p: p - 0.03}[next(iter(truth))]
    assert reads(bench.pressure_bar) == pytest.approx(4.0, abs=1e-9)  # 4.03 or 4.04 bar
    expected = float(make_model("thickwall", L0_mm=m.L0_mm).predict(
        bench.pressure_bar, m.D0_mm, m.t0_mm, m.eps).force_N)
    # table interpolation (< 0.1 N) plus one ADC step of 0.24 N; full scale's force is 9-12 N
    # less (about 300 N/bar)
    assert volts[0] * c.loadcell.sensitivity_N_per_V == pytest.approx(expected, abs=0.35)


def test_the_monitors_hysteresis_splits_its_rising_and_falling_readings(config):
    c = quiet(config, model="thickwall", truth={"monitor_hysteresis_bar": 0.02})
    bench = SimMuscleBench(c)
    true_bar = {}
    for branch, command in (("rising", 2.0), ("top", 2.5), ("falling", 2.0)):
        bench.set_command_volts(c.regulator.command_volts(command))
        for _ in range(100):
            volts = bench.step()
        assert float(c.regulator.monitor_bar(volts[1])) == pytest.approx(command, abs=2e-3)
        true_bar[branch] = bench.pressure_bar
    # the monitor reads 2 bar on both branches: rising, the truth is 0.01 bar above it (the
    # sensor reads low); falling, 0.01 bar below
    assert true_bar["rising"] == pytest.approx(2.01, abs=1e-9)
    assert true_bar["falling"] == pytest.approx(1.99, abs=1e-9)


@pytest.mark.parametrize("stuck_bar", [0.0, 0.7])
def test_a_stuck_monitor_reads_its_reading_whatever_the_pressure(config, stuck_bar):
    # its output is frozen; the regulator still holds its own sensor at the command
    c = quiet(config, model="thickwall", truth={"monitor_stuck_bar": stuck_bar})
    lsb_bar = float(c.regulator.monitor_bar(c.regulator.monitor_V_at_zero + LSB_V))
    for pressure in (0.5, 2.0):
        volts, bench = settled(c, pressure)
        assert float(c.regulator.monitor_bar(volts[1])) == pytest.approx(stuck_bar,
                                                                          abs=lsb_bar / 2)
        assert bench.pressure_bar == pytest.approx(pressure, abs=1e-9)


def test_a_bow_beyond_a_tenth_of_full_scale_is_refused(config):
    with pytest.raises(ValueError, match=r"sim\.truth\.monitor_bow_bar=0\.45 is invalid: "
                                         r"expected -0\.4 to 0\.4 bar"):
        config.replace(sim={"truth": {"monitor_bow_bar": 0.45}})


def test_a_true_wall_other_than_the_declared_one_changes_the_force_as_the_model_says(config):
    m = config.muscle
    c = quiet(config, model="thickwall", truth={"t0_mm": m.t0_mm - 0.4})
    assert c.muscle.t0_mm == m.t0_mm  # the declared muscle is unchanged
    pressure, force = static_force_table(c)
    model = make_model("thickwall", L0_mm=m.L0_mm)
    thin = model.predict(pressure, m.D0_mm, m.t0_mm - 0.4, m.eps)
    np.testing.assert_allclose(force, np.maximum(thin.force_N, 0.0), rtol=1e-12, atol=1e-12)
    _, declared = static_force_table(quiet(config, model="thickwall"))
    # D0 is the inner diameter: a thinner wall puts the braid on a smaller circle, the pressure
    # acts on less area (Equation 2's D^2), and the muscle pulls less: 30 N less at 2 bar
    k = np.searchsorted(pressure, 2.0)
    assert declared[k] - force[k] > 20.0
    d0 = quiet(config, model="thickwall", truth={"D0_mm": m.D0_mm + 0.3})
    wide = model.predict(pressure, m.D0_mm + 0.3, m.t0_mm, m.eps)
    np.testing.assert_allclose(static_force_table(d0)[1], np.maximum(wide.force_N, 0.0),
                               rtol=1e-12, atol=1e-12)


def test_a_sliding_braid_truth_is_the_fe_models_sliding_sleeve(config):
    m = config.muscle
    truth = {"braid": "sliding", "theta0_deg": 32.0}
    pressure, force = static_force_table(quiet(config, truth=truth))
    fe = make_model("axisym", mesh="coarse", L0_mm=m.L0_mm, **truth)
    at = pressure[[20, 40, 80]]
    expected = fe.predict(at, m.D0_mm, m.t0_mm, m.eps).force_N
    np.testing.assert_allclose(force[[20, 40, 80]], expected, rtol=1e-9)


@pytest.mark.parametrize("truth, message", [
    ({"braid": "glued"}, "sim.truth.braid='glued' is invalid: expected one of bonded, sliding"),
    ({"loadcell_gain": 1.5}, "sim.truth.loadcell_gain=1.5 is invalid: expected 0.9 to 1.1"),
    ({"monitor_gain": 0.5}, "sim.truth.monitor_gain=0.5 is invalid: expected 0.75 to 1.25"),
    ({"monitor_offset_bar": -1.0}, "sim.truth.monitor_offset_bar=-1 is invalid: expected -0.5 "
                                   "to 0.5 bar"),
    ({"t0_mm": 16.0}, "sim.truth.t0_mm=16 is too thick for D0_mm=30"),
    ({"D0_mm": 0.1}, "sim.truth.D0_mm=0.1 is invalid"),
    ({"monitor_stuck_bar": -0.1}, "sim.truth.monitor_stuck_bar=-0.1 is invalid: expected 0 to "
                                  "10 bar"),
    ({"monitor_stuck_bar": 5.0}, r"sim.truth.monitor_stuck_bar=5 is invalid: expected 0 to 4 "
                                 r"bar \(regulator.full_scale_bar=4\)"),
])
def test_an_out_of_bounds_departure_is_named(config, truth, message):
    with pytest.raises(ValueError, match=message):
        config.replace(sim={"truth": truth})


def test_a_bad_departure_is_one_line_and_exit_2_from_mkm_check(config, tmp_path, capsys):
    from mkm.cli import main

    path = tmp_path / "bad.toml"
    path.write_text(config.text + "\n[sim.truth]\nloadcell_gain = 1.5\n", encoding="utf-8")
    assert main(["check", "--config", str(path)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "sim.truth.loadcell_gain=1.5 is invalid" in err[0]


def test_a_vent_limit_within_the_monitors_zero_error_is_refused(config, tmp_path, capsys):
    # a 10 bar regulator whose monitor is declared within 1 % of full scale may read 0.1 bar
    # on a vented muscle: the packaged vent limit of 0.05 bar would call a vented bench
    # unvented (VENT BY HAND); refused before anything is pressurised
    from mkm.cli import main

    ten_bar = {"full_scale_bar": 10.0, "max_pressure_bar": 6.0, "monitor_accuracy_bar": 0.1}
    path = tmp_path / "ten_bar.toml"
    text = config.text
    for key, value in ten_bar.items():
        text = re.sub(rf"(?m)^{key} = [^\n]*", f"{key} = {value}", text, count=1)
    path.write_text(text, encoding="utf-8")
    assert main(["check", "--config", str(path)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and ("safety.vent_below_bar=0.05 is invalid: a vented muscle's "
                              "monitor may read up to 0.1 bar") in err[0], err
    # the components a data sheet itemises: the zero and half the hysteresis are read at 0 bar
    with pytest.raises(ValueError, match=r"vent_below_bar=0.05 is invalid: .* up to 0.06 bar"):
        config.replace(regulator={"monitor_zero_bar": 0.05, "monitor_hysteresis_bar": 0.02})
    # above it, a monitor 0.077 bar high (within the declared 0.1; numpy seed 2026120572's
    # draw) verifies the vent of a run of that bench
    c = config.replace(regulator=ten_bar, safety={"vent_below_bar": 0.15},
                       sequence={"pressures_bar": (1.0, 2.0), "preconditioning_cycles": 0},
                       sim={"model": "thickwall", "seed": 2026120572,
                            "truth": {"monitor_offset_bar": 0.0771}})
    result = acquire(c, out_root=tmp_path, notify=lambda message: None)
    assert result.status == "complete", result.reason
    meta = json.loads((result.path / "run.json").read_text(encoding="utf-8"))
    assert meta["vent_check"]["verified"] and meta["vent_check"]["below_bar"] == 0.15
    # vented, that monitor settles at its offset: above the packaged 0.05 bar for good
    volts, bench = settled(c, 2.0)
    bench.set_command_volts(0.0)
    for _ in range(300):  # 30 s: the regulator has exhausted the muscle
        volts = bench.step()
    assert bench.pressure_bar == pytest.approx(0.0, abs=1e-6)
    lsb_bar = float(c.regulator.monitor_bar(c.regulator.monitor_V_at_zero + LSB_V))
    assert float(c.regulator.monitor_bar(volts[1])) == pytest.approx(0.0771, abs=lsb_bar)


def test_the_departures_are_stripped_with_the_simulator_settings(config, tmp_path):
    m = config.muscle
    c = config.replace(sim={"model": "thickwall", "truth": {
        "t0_mm": m.t0_mm - 0.3, "loadcell_gain": 1.001, "monitor_offset_bar": 0.02}})
    result = acquire(c, out_root=tmp_path)
    meta = json.loads((result.path / "run.json").read_text(encoding="utf-8"))
    # what a fit reads is the declared muscle; the truth is in the simulator's settings only
    assert meta["muscle"]["t0_mm"] == m.t0_mm
    assert meta["hardware"]["sim"]["truth"]["t0_mm"] == m.t0_mm - 0.3
    assert meta["hardware"]["sim"]["physics"]["instruments"]["loadcell_gain"] == 1.001
    assert meta["hardware"]["sim"]["physics"]["summary"].endswith(
        "departures from the configuration: true t0_mm 2.7 (declared 3), loadcell_gain 1.001, "
        "monitor_offset_bar 0.02")
    remove_simulator_settings(result.path)
    text = (result.path / "run.json").read_text(encoding="utf-8")
    for key in ("loadcell_gain", "monitor_offset_bar", '"truth"'):
        assert key not in text
    assert "[sim" not in (result.path / "config.toml").read_text(encoding="utf-8")


def test_unset_truth_is_the_muscle_the_configuration_declares(config):
    # [muscle] declares a 60 mm tube with a 4 mm wall woven at 18 deg, of a stiff rubber; with
    # no [sim.truth] the simulated muscle is that one. It was the calibrated 33 deg muscle of
    # Silastic S: 1.36 kN/bar at eps 0 where the declared muscle pulls 6.5 kN/bar (Equation 2
    # on the braid's diameter, 68 mm, the FE model's force at eps 0).
    from mkm.fem.eq2 import chou_hannaford

    declared = {"D0_mm": 60.0, "t0_mm": 4.0, "L0_mm": 800.0, "theta0_deg": 18.0,
                "C10_MPa": 0.4, "C01_MPa": 0.1}
    c = quiet(config.replace(muscle=declared, regulator={"max_pressure_bar": 2.0},
                             sequence={"pressures_bar": (1.0, 2.0)}), model="thickwall")
    p, f = static_force_table(c)
    assert np.interp(1.0, p, f) == pytest.approx(float(chou_hannaford(1.0, 68.0, 0.0, 18.0)),
                                                 rel=1e-6) == pytest.approx(6516.8, abs=0.1)
    eps = quiet(c.replace(muscle={"eps": 0.05}), model="thickwall")
    p, f = static_force_table(eps)
    fe = make_model("thickwall", L0_mm=800.0, theta0_deg=18.0, C10_MPa=0.4, C01_MPa=0.1)
    assert np.interp(2.0, p, f) == pytest.approx(
        float(fe.predict(2.0, 60.0, 4.0, 0.05).force_N), rel=1e-6)
    assert describe_physics(eps)["force_model_params"] == fe.params()
    # a truth still departs from the declaration
    true = quiet(c.replace(sim={"truth": {"theta0_deg": 19.0}}), model="thickwall")
    p, f = static_force_table(true)
    assert np.interp(1.0, p, f) == pytest.approx(float(chou_hannaford(1.0, 68.0, 0.0, 19.0)),
                                                 rel=1e-6)


def test_a_frame_that_yields_holds_the_muscle_where_its_pull_leaves_it(config):
    """A frame of 300 N/mm between the muscle's ends: the packaged 30 mm muscle pulls about
    760 N at 2 bar on a rigid one, so it shortens by about 2.5 mm of its 282 mm and pulls
    the thick-wall force at that length, which the model gives at the eps the pull leaves
    (the table interpolates between six lengths: within 0.05 % of the force). At the threshold
    it pulls nothing and the frame gives nothing: the threshold is the rigid frame's."""
    m = config.muscle
    c = quiet(config, model="thickwall", truth={"frame_stiffness_N_per_mm": 300.0})
    pressure, force = static_force_table(c)
    _, rigid = static_force_table(quiet(config, model="thickwall"))
    model = make_model("thickwall", L0_mm=m.L0_mm)
    at = int(np.argmin(np.abs(pressure - 2.0)))
    shortened = m.eps + force[at] / (300.0 * m.L0_mm)
    assert force[at] == pytest.approx(float(model.predict(2.0, m.D0_mm, m.t0_mm, shortened)
                                            .force_N), rel=5e-4)
    assert 2.0 < force[at] / 300.0 < 3.0  # mm
    assert force[at] < 0.97 * rigid[at]
    assert np.argmax(force > 0) == np.argmax(rigid > 0)
    assert "frame_stiffness_N_per_mm 300" in describe_physics(c)["summary"]
    with pytest.raises(ValueError, match=r"^sim.truth.frame_stiffness_N_per_mm=0 is invalid: "
                                         r"expected 1 to 1e\+07 N/mm$"):
        config.replace(sim={"truth": {"frame_stiffness_N_per_mm": 0.0}})


def test_a_braid_whose_fibres_stretch_pulls_as_a_braid_of_longer_fibres(config):
    """Fibres of E A 5e4 N over all strands (a polyester sleeve stretching 2.6 % at the
    packaged muscle's 2 bar): at a held length ``L`` the fibres of length ``b (1 + e)`` set the
    braid, so its share of the pull is Gaylord's ``P (3 L^2 - b'^2) / (4 pi n^2)`` (``b = L0 /
    cos theta0``, ``n`` turns from the rest diameter) and the wall's is the thick-wall one at the
    angle they leave; the fibres' strain is their tension, the pull and the pressure's end load on
    the bore along them, over E A. Solved here by root-finding, the table agrees within its
    cubic spline through six strains (0.05 % of the force: the wall's share bends most near
    rest, where a straight line between the strains is 0.7 % off); the muscle pulls 10 % less
    than with inextensible fibres at 2 bar, four times the strain: the braid's share alone
    falls by ``2 e / (3 cos^2 theta0 - 1)``, 1.6 times it, the rest is the wall's, held further
    contracted. Fibres too soft to hold the pull are refused with a line."""
    from scipy.optimize import brentq

    from mkm.fem.thickwall import braided_tube_elastic_force

    m, EA_N = config.muscle, 5e4
    c = quiet(config, model="thickwall", truth={"theta0_deg": 30.0, "braid_EA_N": EA_N})
    pressure, force = static_force_table(c)
    _, inextensible = static_force_table(quiet(config, model="thickwall",
                                               truth={"theta0_deg": 30.0}))
    rubber = make_model("thickwall", L0_mm=m.L0_mm, theta0_deg=30.0).params()
    theta0 = np.deg2rad(30.0)
    braid_mm = m.D0_mm + 2 * m.t0_mm
    b_mm = m.L0_mm / np.cos(theta0)
    turns = b_mm * np.sin(theta0) / (np.pi * braid_mm)
    L_mm = m.L0_mm * (1 - m.eps)
    wall_mm2 = ((m.D0_mm / 2 + m.t0_mm) ** 2 - (m.D0_mm / 2) ** 2) * m.L0_mm / L_mm

    def pull_N(P_bar, e):
        b = b_mm * (1 + e)
        braid = 0.1 * P_bar * (3 * L_mm**2 - b**2) / (4 * np.pi * turns**2)
        wall = braided_tube_elastic_force(braid_mm * (1 + e) - 2 * m.t0_mm, m.t0_mm,
                                          1 - L_mm / (m.L0_mm * (1 + e)), 30.0,
                                          rubber["C10_MPa"], rubber["C01_MPa"])
        return float(braid + wall)

    def strain_left(e, P_bar):
        b = b_mm * (1 + e)
        cos_t = L_mm / b
        outer_mm2 = (b * np.sqrt(1 - cos_t**2) / (2 * np.pi * turns)) ** 2
        tension_N = (pull_N(P_bar, e) + 0.1 * P_bar * np.pi * (outer_mm2 - wall_mm2)) / cos_t
        return tension_N / EA_N - e

    for P_bar in (1.0, 2.0, 3.0):
        at = int(np.argmin(np.abs(pressure - P_bar)))
        e = brentq(strain_left, 0.0, 0.2, args=(pressure[at],), xtol=1e-14)
        assert force[at] == pytest.approx(pull_N(pressure[at], e), rel=1e-3), P_bar
    at = int(np.argmin(np.abs(pressure - 2.0)))
    e = brentq(strain_left, 0.0, 0.2, args=(2.0,), xtol=1e-14)
    assert 0.02 < e < 0.03
    assert 3.5 * e < 1 - force[at] / inextensible[at] < 4.5 * e
    assert "braid_EA_N 50000" in describe_physics(c)["summary"]
    with pytest.raises(ValueError, match=r"^sim.truth.braid_EA_N=3000 N: the braid's fibres do "
                                         r"not settle under the muscle's pull \(strained past "
                                         r".* at 4 bar, eps 0\): expected fibres stiff enough "
                                         r"to hold it$"):
        static_force_table(quiet(config, model="thickwall", truth={"braid_EA_N": 3000.0}))
    with pytest.raises(ValueError, match=r"^sim.truth.braid_EA_N=10 is invalid: expected 100 "
                                         r"to 1e\+09 N$"):
        config.replace(sim={"truth": {"braid_EA_N": 10.0}})


def test_tubing_lags_the_muscle_behind_the_monitored_pressure_on_a_ramp(config):
    """Tubing of 1 s between the regulator's outlet and the muscle, the command ramped at 0.1
    bar/s: a first-order lag trails a ramp by its rate times its time constant, so from a few
    time constants on the muscle pulls the thick-wall force at 0.1 bar below what the monitor
    reads (within the table's interpolation and one ADC step, 0.35 N), some 30 N less than at
    the monitored pressure. Held, the muscle catches up: the force is the monitor's."""
    c = quiet(config, model="thickwall", truth={"line_tau_s": 1.0})
    pressure, force = static_force_table(c)
    bench = SimMuscleBench(c)
    rate_bar_per_s, rows = 0.1, []
    for k in range(250):  # 25 s at 10 Hz: up to 2.5 bar
        bench.set_command_volts(c.regulator.command_volts(rate_bar_per_s * k * bench.dt))
        cell_V, monitor_V = bench.step()
        rows.append((float(c.regulator.monitor_bar(monitor_V)),
                     cell_V * c.loadcell.sensitivity_N_per_V))
    monitored, read = np.array(rows[150:]).T  # from 15 s (1.5 bar) on
    trailing = np.interp(monitored - rate_bar_per_s * 1.0, pressure, force)
    np.testing.assert_allclose(read, trailing, atol=0.35)
    assert np.min(np.interp(monitored, pressure, force) - read) > 25.0
    for _ in range(100):  # held 10 s at the last command
        cell_V, monitor_V = bench.step()
    held = np.interp(float(c.regulator.monitor_bar(monitor_V)), pressure, force)
    assert cell_V * c.loadcell.sensitivity_N_per_V == pytest.approx(held, abs=0.35)
    assert "line_tau_s 1" in describe_physics(c)["summary"]
    with pytest.raises(ValueError, match=r"^sim.truth.line_tau_s=-0.5 is invalid: "
                                         r"expected 0 to 60 s$"):
        config.replace(sim={"truth": {"line_tau_s": -0.5}})


def test_a_rubber_that_softens_on_its_first_loading_pulls_less_on_its_first_rise(config):
    """Mullins effect of 15 %: above the highest pressure so far the muscle's rubber is 1 /
    0.85 times the truth's, so on its first rise it pulls the thick-wall force of that stiffer
    rubber (less: the wall resists the braid), some 14 N below the truth's at eps 0.1; back
    below that pressure, and on the repeat's rise to it, it pulls the truth's (the
    preconditioned muscle), within the table's interpolation and one ADC step (0.35 N). Above
    the highest pressure it fell from it takes the stiffer rubber back within a tenth of that
    pressure: half way at 2.1 bar after 2 bar, wholly at 2.3."""
    c = quiet(config.replace(muscle={"eps": 0.1}), model="thickwall",
              truth={"mullins_fraction": 0.15})
    m = c.muscle

    def thickwall(P, stiffer=1.0):
        model = make_model("thickwall", L0_mm=m.L0_mm, C10_MPa=stiffer * SILASTIC_S.C10_MPa,
                           C01_MPa=stiffer * SILASTIC_S.C01_MPa)
        return float(model.predict(P, m.D0_mm, m.t0_mm, m.eps).force_N)

    bench = SimMuscleBench(c)

    def hold(pressure_bar):
        bench.set_command_volts(c.regulator.command_volts(pressure_bar))
        for _ in range(100):  # 10 s: settled to 1e-10 bar
            cell_V, _ = bench.step()
        return cell_V * c.loadcell.sensitivity_N_per_V

    first = [hold(1.0), hold(2.0)]
    later = [hold(1.0), hold(0.0), hold(1.0), hold(2.0)]
    np.testing.assert_allclose(first, [thickwall(1.0, 1 / 0.85), thickwall(2.0, 1 / 0.85)],
                               atol=0.35)
    np.testing.assert_allclose(later, [thickwall(1.0), 0.0, thickwall(1.0), thickwall(2.0)],
                               atol=0.35)
    assert thickwall(1.0) - first[0] > 10.0
    beyond = [hold(2.1), hold(2.3)]
    np.testing.assert_allclose(beyond, [(thickwall(2.1) + thickwall(2.1, 1 / 0.85)) / 2,
                                        thickwall(2.3, 1 / 0.85)], atol=0.35)
    assert "mullins_fraction 0.15" in describe_physics(c)["summary"]
    with pytest.raises(ValueError, match=r"^sim.truth.mullins_fraction=0.6 is invalid: "
                                         r"expected 0 to 0.5 \(a fraction of the rubber's "
                                         r"stiffness\)$"):
        config.replace(sim={"truth": {"mullins_fraction": 0.6}})
    with pytest.raises(ValueError, match=r"^sim.truth.mullins_fraction softens the rubber, "
                                         r"which sim.model='eq2' does not have: expected one of "
                                         r".*thickwall"):
        config.replace(sim={"model": "eq2", "truth": {"mullins_fraction": 0.1}})
