"""bench.procedures: tare, load-cell calibration and the dry-run check on the simulated bench."""

import numpy as np
import pytest

from bench.procedures import calibrate_loadcell, check, fit_loadcell, tare
from bench.sim import STANDARD_GRAVITY


def test_fit_loadcell_recovers_a_linear_cell():
    mass = np.array([0.0, 1.0, 2.0, 5.0, 10.0])
    volts = 0.012 + mass * STANDARD_GRAVITY / 196.133
    fit = fit_loadcell(mass, volts)
    assert fit["sensitivity_N_per_V"] == pytest.approx(196.133, rel=1e-9)
    assert fit["offset_V"] == pytest.approx(0.012, abs=1e-12)
    assert fit["r_squared"] == pytest.approx(1.0) and fit["max_abs_residual_N"] < 1e-9


def test_fit_loadcell_bad_input():
    with pytest.raises(ValueError, match="one voltage per mass"):
        fit_loadcell([0, 1], [0.1])
    with pytest.raises(ValueError, match="two different masses"):
        fit_loadcell([1, 1], [0.1, 0.1])
    with pytest.raises(ValueError, match="volts fall as the mass grows"):
        fit_loadcell([0, 1], [0.1, 0.0])


def test_calibrate_loadcell_on_the_sim(config):
    fit = calibrate_loadcell(config, [0.0, 5.0, 10.0, 20.0], seconds=5.0)
    # 50 samples per mass with 2 mV noise: the mean is good to 0.3 mV (1 sigma); over a 20 kg
    # (196 N = 1 V) span that is 0.03 % of the slope, so 0.2 % is > 5 sigma
    assert fit["sensitivity_N_per_V"] == pytest.approx(config.loadcell.sensitivity_N_per_V,
                                                       rel=2e-3)
    assert fit["offset_V"] == pytest.approx(config.sim.loadcell_offset_V, abs=1.5e-3)


def test_tare_on_the_sim(config):
    out = tare(config, seconds=10.0)
    assert out["n"] == 100
    assert out["offset_V"] == pytest.approx(config.sim.loadcell_offset_V, abs=1e-3)  # 5 sigma
    assert out["std_N"] == pytest.approx(0.002 * config.loadcell.sensitivity_N_per_V, rel=0.25)


def test_check_lists_device_steps_and_duration(config):
    text = check(config)
    assert "USB-6001 (simulated)" in text and "interlock at 1765.2 N" in text
    assert "0,up,0,0.5\n1,up,0,1\n2,down,0,0.5" in text
    assert "estimated duration: 0.3 to 1.1 min" in text  # 19 s to 68 s
