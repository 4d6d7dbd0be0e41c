"""fem.friction: braid friction and creep around a static rung, as the simulated bench defines
them."""

import json
import math

import numpy as np
import pytest

from mkm.bench.config import load_config
from mkm.bench.sim import SimMuscleBench
from mkm.fem.calibration import Calibration
from mkm.fem.friction import FrictionCreep, branch_factors, force_history
from mkm.fem.ladder import make_model

D0, T0 = 30.0, 3.0


def test_history_is_the_simulated_bench_sample_for_sample():
    config = load_config().replace(sim={"model": "thickwall", "noise_V": 0.0,
                                        "monitor_noise_V": 0.0, "hysteresis_fraction": 0.05,
                                        "creep_fraction": 0.03, "creep_tau_s": 20.0})
    bench = SimMuscleBench(config)
    times, pressures, forces = [], [], []
    for k, target in enumerate((1.0, 2.0, 2.5, 1.5, 0.5, 1.2)):
        bench.set_command_volts(config.regulator.command_volts(target))
        for j in range(150):
            bench.step()
            times.append((150 * k + j) * bench.dt)
            pressures.append(bench.pressure_bar)
            forces.append(max(bench.hysteretic_N - bench.relaxed_N, 0.0))
    static = np.interp(pressures, bench.table_p, bench.table_F)
    got = force_history(times, static, 0.05, 0.03, 20.0)
    # the same recursion on the same static force: equal to round-off
    np.testing.assert_allclose(got, forces, rtol=1e-12, atol=1e-9)


def test_branches_and_relaxation_match_the_closed_forms():
    model = FrictionCreep(static="thickwall", hysteresis_fraction=0.04, creep_fraction=0.02,
                          creep_tau_s=30.0, hold_s=10.0)
    static = make_model("thickwall").predict(2.0, D0, T0, 0.1).force_N
    pred = model.predict(2.0, D0, T0, 0.1)
    kept = 1 - 0.02 * (1 - math.exp(-10.0 / 30.0))
    assert pred.force_N == pytest.approx(0.96 * kept * static, rel=1e-12)
    assert pred.extras["force_falling_N"] == pytest.approx(1.04 * kept * static, rel=1e-12)
    # the history of a ramp to 2 bar held 10 s: the rising branch, relaxed as the closed form
    # says (the ramp's own 0.1 s adds under 0.1 % of the 2 % creep)
    t = np.arange(0.0, 10.05, 0.1)
    trace = model.history(t, np.minimum(t * 20.0, 2.0), D0, T0, 0.1, table_bar=0.01)
    assert trace[-1] == pytest.approx(float(pred.force_N), rel=1e-4)
    assert branch_factors(0.04, 0.02, 30.0, math.inf)["mean"] == pytest.approx(0.98)


def test_without_terms_the_rung_is_its_static_model():
    static = make_model("thickwall", theta0_deg=31.0).predict([0.5, 2.0], D0, T0, 0.0)
    wrapped = FrictionCreep(static="thickwall", theta0_deg=31.0, hysteresis_fraction=0.0,
                            creep_fraction=0.0).predict([0.5, 2.0], D0, T0, 0.0)
    np.testing.assert_array_equal(wrapped.force_N, static.force_N)


def test_terms_default_to_the_calibration_given(tmp_path):
    path = tmp_path / "calibration.json"
    path.write_text(json.dumps({"thickwall": {"theta0_deg": 31.0, "hysteresis_fraction": 0.05,
                                              "creep_fraction": 0.01, "creep_tau_s": 12.0}}))
    calibration = Calibration.load(path)
    model = FrictionCreep(static="thickwall", direction="falling", calibration=calibration)
    assert model.terms == {"hysteresis_fraction": 0.05, "creep_fraction": 0.01,
                           "creep_tau_s": 12.0}
    force = float(model.predict(2.0, D0, T0, 0.0).force_N)
    static = float(make_model("thickwall", calibration).predict(2.0, D0, T0, 0.0).force_N)
    assert force == pytest.approx(1.05 * static, rel=1e-12)
    assert FrictionCreep(static="thickwall").terms["hysteresis_fraction"] == 0.0  # shipped


@pytest.mark.parametrize("params, message", [
    ({"hysteresis_fraction": 0.7}, "hysteresis_fraction=0.7 is invalid: expected 0 to 0.5"),
    ({"creep_tau_s": 0.0}, "creep_tau_s=0 is invalid: expected 0.001 to 100000 s"),
    ({"direction": "up"}, "direction='up' is invalid: expected one of rising, falling, mean"),
    ({"hold_s": -1.0}, "hold_s=-1.0 is invalid"),
])
def test_bad_parameters_are_named(params, message):
    with pytest.raises(ValueError, match=message):
        FrictionCreep(static="thickwall", **params)
