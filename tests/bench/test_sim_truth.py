"""[sim.truth]: a simulated muscle that is not the nominal one, recorded in its simulator settings
only."""

import json

import numpy as np
import pytest

from mkm.bench.config import parse_config
from mkm.bench.run import acquire
from mkm.bench.sim import SimMuscleBench, static_force_table
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
                            "gap_mm": None}
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
