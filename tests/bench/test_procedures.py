"""bench.procedures: tare, load-cell calibration and the dry-run check on the simulated bench."""

import numpy as np
import pytest

from mkm.bench.procedures import calibrate_loadcell, check, fit_loadcell, tare
from mkm.bench.sim import STANDARD_GRAVITY


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


def test_calibrate_loadcell_refuses_a_mass_beyond_the_cells_capacity(config):
    # 300 kg on the 1961.33 N cell: its reading clips at the 10 V rail (1961 N at 196.133 N/V)
    # and the fit would give 296 N/V, 51 % high, with R^2 0.99994
    with pytest.raises(ValueError) as caught:
        calibrate_loadcell(config, [0.0, 5.0, 300.0], seconds=1.0)
    assert str(caught.value) == ("--masses: 300 kg weighs 2942 N, beyond the load cell's "
                                 "loadcell.capacity_N=1961.33: expected masses up to 200 kg")
    fit = calibrate_loadcell(config, [0.0, 5.0, 190.0], seconds=1.0)  # within: the slope holds
    assert fit["sensitivity_N_per_V"] == pytest.approx(config.loadcell.sensitivity_N_per_V,
                                                       rel=2e-3)


def test_calibrate_loadcell_on_a_stuck_cell_says_so(config):
    # a cell stuck from the start reads 0.0146 V under 0, 5 and 10 kg: the fit's zero slope was
    # said as "volts fall as the mass grows (slope 0 V/N): expected a tension load cell wired
    # with the positive sign", exit 2, as if the wiring were reversed
    from mkm.bench.backend import BenchError

    stuck = config.replace(sim={"faults": {"loadcell_stuck_at_s": 0.0}})
    with pytest.raises(BenchError) as failed:
        calibrate_loadcell(stuck, [0.0, 5.0, 10.0], seconds=1.0)
    assert str(failed.value) == (
        "the load cell read one ADC code, 0.0146 V (+2.9 N at loadcell.offset_V=0 V), under "
        "every mass (0, 5, 10 kg): a stuck, disconnected or railed cell reads so; check its "
        "cable, amplifier and supply; nothing was fitted")


def test_tare_on_the_sim(config):
    from mkm.bench.sequence import TareInvalid

    out = tare(config, seconds=10.0)
    assert out["n"] == 100
    assert out["offset_V"] == pytest.approx(config.sim.loadcell_offset_V, abs=1e-3)  # 5 sigma
    assert out["std_N"] == pytest.approx(0.002 * config.loadcell.sensitivity_N_per_V, rel=0.25)
    assert out["settle_warning"] == ""  # 0.4 N rms: steps settle under the 1.5 N limit
    noisy = tare(config.replace(sim={"noise_V": 0.02}), seconds=10.0)  # inside the tare limit
    assert noisy["settle_warning"].startswith(f"the load cell spreads {noisy['std_N']:.2f} N rms")
    # vented, the monitor reads its zero (the sim's: 0, 1 mbar noise over root 50 readings)
    assert out["monitor_vented_settled"] and abs(out["monitor_vented_bar"]) < 0.002
    assert out["monitor_warning"] == ""
    off = tare(config.replace(sim={"truth": {"monitor_offset_bar": 0.046}}), seconds=10.0)
    assert off["monitor_vented_bar"] == pytest.approx(0.046, abs=0.002)
    assert "vented, beyond the +-0.04 bar" in off["monitor_warning"]
    # the volts it gives, and the setting that takes them: 1 V + 0.046 bar x 4 V / 4 bar
    # the simulated sensor's offset is its truth's, through whatever zero is declared
    assert "zero is off (it gives 1.046 V vented, [regulator] monitor_V_at_zero = 1 V; with " \
        "the muscle open to the air, set monitor_V_at_zero to what it gives (simulated: " \
        "[sim.truth] monitor_offset_bar = 0.046 bar moves any zero declared))" \
        in off["monitor_warning"]
    from mkm.bench.sequence import _zero_said

    real = config.replace(daq={"backend": "ni"}, sim={"truth": {"monitor_offset_bar": 0.046}})
    assert _zero_said(0.046, real) == ("it gives 1.046 V vented, [regulator] monitor_V_at_zero "
                                       "= 1 V; with the muscle open to the air, set "
                                       "monitor_V_at_zero to what it gives")
    with pytest.raises(TareInvalid, match=r"monitor reads \+0\.2\d\d bar with the regulator "
                                          r"vented, beyond safety.vent_below_bar=0.05: it cannot "
                                          r"verify a vent \(its zero is off: it gives 1\.2\d* V "
                                          r"vented, \[regulator\] monitor_V_at_zero = 1 V; with "
                                          r"the muscle open to the air, set monitor_V_at_zero to "
                                          r"what it gives \(simulated: \[sim.truth\] "
                                          r"monitor_offset_bar = 0.2 bar moves any zero "
                                          r"declared\); its wiring"):
        tare(config.replace(sim={"truth": {"monitor_offset_bar": 0.2}}), seconds=10.0)


def test_a_close_that_hangs_ends_the_tare_all_the_same(config, monkeypatch, capsys):
    # the tare read, then the driver hung as the device was closed (the vent written again,
    # the tasks cleared): `mkm tare` never returned. Now the close is waited for CLOSE_WAIT_S
    # and the tare returns, saying so
    import threading

    import mkm.bench.procedures as procedures
    from mkm.bench.run import CLOSE_WAIT_S
    from mkm.bench.sim import SimBackend

    release = threading.Event()

    class Hanging(SimBackend):
        def close(self):
            release.wait(60)  # the test's net; released once the tare returned
            super().close()

    monkeypatch.setattr(procedures, "make_backend", lambda c, clock: Hanging(c))
    try:
        out = tare(config, seconds=2.0)
        still_hung = not release.is_set()
    finally:
        release.set()
    assert still_hung and out["n"] == 20
    assert capsys.readouterr().err.endswith(
        f"mkm tare: closing the device did not return within {CLOSE_WAIT_S:g} s (the driver "
        "hangs): it is let go as this process ends\n")


def test_a_tare_on_one_adc_code_is_refused(config):
    # the load cell is stuck from the start: the tare read one code 20 times, its spread 0 N;
    # it was only warned of, and the run went on with the force limit blind (the stuck-cell
    # interlock needs a tare that strays), marked failed at its end. `mkm tare` refuses it now
    from mkm.bench.sequence import TareInvalid, one_code_noise_V

    stuck = config.replace(sim={"faults": {"loadcell_stuck_at_s": 0.0}})
    with pytest.raises(TareInvalid) as refused:
        tare(stuck, seconds=2.0)
    # the code the sim's cell reads at rest: its 0.015 V offset quantised to 12 steps of 1.22 mV
    assert str(refused.value) == (
        "tare invalid: the load cell read one ADC code, 0.0146 V (+2.9 N at "
        "loadcell.offset_V=0 V), all 20 times: a stuck, disconnected or railed cell reads so, "
        "and the force limit is blind behind it; a live cell's noise moves it (one spreading "
        "0.59 mV rms or more, 0.49 of the 1.22 mV step, shows two codes in all but one tare of "
        "20 readings in 1,000); check the cell's cable, amplifier and supply, and load it by "
        "hand to see its reading move (a live cell quieter than that: lengthen "
        "sequence.tare_s); nothing was pressurised")
    assert tare(config, seconds=2.0)["n"] == 20  # 2 mV of noise (1.6 steps): a live cell
    # the bound: (2 Phi(step / 2 sigma) - 1)^(n - 1) = 1e-3 at sigma = 0.405 mV over 50 readings
    assert one_code_noise_V(50, 20 / 2 ** 14) == pytest.approx(0.405e-3, abs=1e-6)


def test_a_tare_on_one_code_says_a_railed_cell(config):
    # an amplifier driven to its rail reads the input's top code, +2000 N from the zero: said
    # as a cell on one code, at the rail (it was refused as a load on the cell, 100 N off)
    from mkm.bench.sequence import TareInvalid, validate_tare

    top = 10.0 - 20 / 2 ** 14
    with pytest.raises(TareInvalid, match=r"^tare invalid: the load cell read one ADC code, "
                                          r"9\.9988 V \(\+1961\.1 N at loadcell\.offset_V=0 V, "
                                          r"at the input's \+10 V rail\), all 50 times: "):
        validate_tare([top] * 50, config)
    # two readings alike prove little: a live cell as noisy as 487 mV rms reads so once in 1,000
    with pytest.raises(TareInvalid, match=r"one spreading 486\.99 mV rms or more, 399 times the "
                                          r"1\.22 mV step, shows two codes in all but one tare "
                                          r"of 2 readings in 1,000\)"):
        validate_tare([0.0] * 2, config.replace(safety={"tare_min_samples": 2}))


def test_check_lists_device_steps_and_duration(config):
    text, warnings, refusal = check(config)
    assert warnings == [] and refusal == ""
    assert "backend: sim (SIMULATED: no hardware is driven)" in text
    assert "USB-6001 (simulated)" in text and "interlock at 1765.2 N" in text
    assert ("planned steps: 3\n  repeat 1, up: 0.5, 1 bar\n  repeat 1, down: 0.5 bar") in text
    assert "estimated duration: 0.3 to 1.1 min" in text  # 19 s to 68 s


def test_vent_reads_the_monitor_below_the_threshold(config):
    from mkm.bench.procedures import vent

    out = vent(config)
    assert out["vented"] and not out["manual"] and out["stopped"] is None
    assert abs(out["pressure_bar"]) < config.safety.vent_below_bar


def test_vent_with_a_manual_regulator_says_it_cannot_read(config):
    from mkm.bench.procedures import vent

    out = vent(config.replace(regulator={"kind": "manual"}))
    assert out["manual"] and not out["vented"] and out["pressure_bar"] != out["pressure_bar"]


def test_vent_that_does_not_bring_the_pressure_down_says_so(config, monkeypatch):
    # a regulator stuck at 1 bar never reads below 0.05 bar after the vent command
    import mkm.bench.procedures as procedures
    from mkm.bench.backend import BenchError
    from mkm.bench.sim import SimBackend

    class Stuck(SimBackend):
        def start(self):
            super().start()
            self.bench.pressure_bar = 1.0
            self.bench.regulator_stuck = True

    monkeypatch.setattr(procedures, "make_backend", lambda c, clock: Stuck(c))
    with pytest.raises(BenchError, match=r"monitor still reads 1\.00\d bar 2\.\d s after the "
                                         r"vent, above 0\.05 bar \(it no longer fell .*"
                                         r"safety\.vent_timeout_s \(now 2 s, .*\): VENT BY HAND"):
        procedures.vent(config.replace(safety={"vent_timeout_s": 2.0}))


def test_vent_is_not_verified_by_one_noise_spike(config, monkeypatch):
    # a regulator stuck at 1 bar; the monitor's third reading after the vent comes 0.98 V low
    # (one sample of noise, 0.02 bar): that one reading below 0.05 bar verified the vent
    import dataclasses

    import mkm.bench.procedures as procedures
    from mkm.bench.backend import BenchError
    from mkm.bench.sim import SimBackend

    class StuckAndSpiked(SimBackend):
        def start(self):
            super().start()
            self.bench.pressure_bar = 1.0
            self.bench.regulator_stuck = True
            self.reads = 0

        def read(self, n_samples, timeout_s):
            block = super().read(n_samples, timeout_s)
            self.reads += 1
            if self.reads == 3:
                volts = block.volts.copy()
                volts[:, 1] -= 0.98  # 1 V per bar: 1-5 V over 4 bar
                block = dataclasses.replace(block, volts=volts)
            return block

    monkeypatch.setattr(procedures, "make_backend", lambda c, clock: StuckAndSpiked(c))
    with pytest.raises(BenchError, match=r"monitor still reads 1\.00\d bar 2\.\d s after the "
                                         r"vent, above 0\.05 bar \(it no longer fell .*"
                                         r"safety\.vent_timeout_s \(now 2 s, .*\): VENT BY HAND"):
        procedures.vent(config.replace(safety={"vent_timeout_s": 2.0}))


def test_tare_refuses_a_noisy_cell(config):
    from mkm.bench.sequence import TareInvalid

    with pytest.raises(TareInvalid, match="spreads"):
        tare(config.replace(sim={"noise_V": 0.05}), seconds=5.0)


def test_a_tare_that_ends_on_one_code_after_a_small_stray_is_said_so(config):
    # stuck from 0.3 s of a 5 s tare: three readings strayed less than a step (too few to show
    # the cell's noise), then 4.6 s on one code. Not all on one code, so nothing was said, and
    # the stuck-cell interlock stayed disarmed (its tare strayed less than a step): the force
    # limit blind through the run without a word. It is said as a tare on one code is.
    stuck = config.replace(sim={"faults": {"loadcell_stuck_at_s": 0.3}})
    out = tare(stuck, seconds=5.0)
    assert out["std_N"] > 0.0 and out["held_s"] == pytest.approx(4.6)
    assert out["one_code_warning"] == (
        "the tare read the load cell on one ADC code for its last 4.6 s, where it strayed less "
        "than a step before: a stuck or disconnected cell reads so, and hides every force from "
        "the force limit; a cell quieter than one step (1.22 mV) too: load the cell by hand and "
        "see its reading move before any pressure")
    assert tare(config, seconds=5.0)["one_code_warning"] == ""
