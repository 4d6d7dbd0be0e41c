"""bench.sim: the simulated bench's physics, measured against its own definitions."""

import math

import numpy as np
import pytest

from mkm.bench.sim import LSB_V, SimBackend, SimMuscleBench, quantize_volts, static_force_table
from mkm.fem.ladder import make_model


def quiet(config, **sim):
    """The config with the named sim settings changed (noise, hysteresis, creep off by default)."""
    settings = {"noise_V": 0.0, "monitor_noise_V": 0.0, "hysteresis_fraction": 0.0,
                "creep_fraction": 0.0, "loadcell_offset_V": 0.0, **sim}
    return config.replace(sim=settings)


def run_for(bench, seconds):
    return np.array([bench.step() for _ in range(int(round(seconds / bench.dt)))])


def test_quantization_and_rails():
    assert LSB_V == pytest.approx(1.2207e-3, rel=1e-4)  # USB-6001: 20 V / 2^14
    for v in (0.0123456, -3.3333, 7.77777):
        q = quantize_volts(v)
        assert abs(q - v) <= LSB_V / 2 + 1e-12
        assert q / LSB_V == pytest.approx(round(q / LSB_V), abs=1e-9)
    assert quantize_volts(25.0) == pytest.approx(10.0 - LSB_V)
    assert quantize_volts(-25.0) == -10.0


def test_force_table_is_the_registry_model(config):
    p, f = static_force_table(config)
    m = config.muscle
    expected = make_model(config.sim.model, L0_mm=m.L0_mm).predict(2.0, m.D0_mm, m.t0_mm, m.eps)
    assert np.interp(2.0, p, f) == pytest.approx(float(expected.force_N), rel=1e-3)


def test_regulator_first_order_lag(config):
    # A 0.5 bar step with a slew limit that does not bind: after one time constant the pressure
    # has covered 1 - 1/e of the step (the discrete update is the exact exponential).
    c = quiet(config, regulator_tau_s=0.5, regulator_slew_bar_per_s=100.0)
    bench = SimMuscleBench(c)
    bench.set_command_volts(c.regulator.command_volts(0.5))
    run_for(bench, 0.5)
    assert bench.pressure_bar == pytest.approx(0.5 * (1 - math.exp(-1)), rel=1e-9)


def test_regulator_slew_limit_and_monitor(config):
    c = quiet(config, regulator_tau_s=0.1, regulator_slew_bar_per_s=1.0)
    bench = SimMuscleBench(c)
    bench.set_command_volts(c.regulator.command_volts(2.5))
    volts = run_for(bench, 1.0)
    assert bench.pressure_bar == pytest.approx(1.0, abs=1e-9)  # 1 bar/s for 1 s
    # monitor: 1 V at 0 bar to 5 V at 4 bar full scale, quantized
    assert volts[-1, 1] == pytest.approx(1.0 + 4.0 * 1.0 / 4.0, abs=LSB_V)


def test_static_force_without_hysteresis_or_creep(config):
    c = quiet(config)
    bench = SimMuscleBench(c)
    bench.set_command_volts(c.regulator.command_volts(1.5))
    volts = run_for(bench, 10.0)
    expected = np.interp(1.5, bench.table_p, bench.table_F)
    # one LSB of force resolution: 1.22 mV x 196 N/V = 0.24 N
    assert volts[-1, 0] * c.loadcell.sensitivity_N_per_V == pytest.approx(
        expected, abs=LSB_V * c.loadcell.sensitivity_N_per_V)


def test_hysteresis_loop_width(config):
    # Play operator of half-width h: going up the force is (1 - h) F, coming down (1 + h) F.
    h = 0.03
    c = quiet(config, hysteresis_fraction=h)
    bench = SimMuscleBench(c)
    reached = []
    for target in (1.0, 2.5, 1.0):
        bench.set_command_volts(c.regulator.command_volts(target))
        run_for(bench, 10.0)
        reached.append(bench.hysteretic_N)
    static = np.interp(1.0, bench.table_p, bench.table_F)
    assert reached[0] == pytest.approx((1 - h) * static, rel=1e-6)
    assert reached[2] == pytest.approx((1 + h) * static, rel=1e-6)


def test_creep_relaxes_by_its_fraction(config):
    c = quiet(config, creep_fraction=0.02, creep_tau_s=30.0)
    bench = SimMuscleBench(c)
    bench.set_command_volts(c.regulator.command_volts(2.0))
    run_for(bench, 300.0)  # ten time constants: fully relaxed to 1e-4
    static = np.interp(2.0, bench.table_p, bench.table_F)
    assert bench.hysteretic_N - bench.relaxed_N == pytest.approx(0.98 * static, rel=1e-3)


def test_noise_level_and_seed(config):
    c = config.replace(sim={"noise_V": 0.002, "loadcell_offset_V": 0.015})
    a = run_for(SimMuscleBench(c), 200.0)[:, 0]
    b = run_for(SimMuscleBench(c), 200.0)[:, 0]
    other = run_for(SimMuscleBench(c.replace(sim={"seed": 1})), 200.0)[:, 0]
    np.testing.assert_array_equal(a, b)
    assert not np.array_equal(a, other)
    # 2000 samples: the sample std is within 5 % of sigma with > 99 % probability; the
    # quantization adds LSB^2/12 in variance (0.35 mV rms), combined below.
    sigma = math.hypot(0.002, LSB_V / math.sqrt(12))
    assert a.std() == pytest.approx(sigma, rel=0.05)
    assert a.mean() == pytest.approx(0.015, abs=3 * sigma / math.sqrt(a.size))


def test_backend_reads_blocks_with_indices(config):
    sim = SimBackend(config)
    info = sim.open()
    assert info.simulated and info.channels["ai"] == ["ai0", "ai1"]
    sim.start()
    first, second = sim.read(3, 1.0), sim.read(2, 1.0)
    assert (first.first_index, second.first_index) == (0, 3)
    assert first.volts.shape == (3, 2)
    sim.close()
    assert sim.commands[0] == (0, 0.0) and sim.commands[-1] == (5, 0.0)  # vent at open and close


def test_real_clock_paces_reads(config):
    import time

    sim = SimBackend(config, clock="real")
    sim.open()
    sim.start()
    start = time.monotonic()
    sim.read(3, 2.0)
    # 3 samples at 10 Hz end at 0.3 s; the sleep is never shorter, and a read that waited for
    # something else than its samples would wait out its 2 s timeout (the bound leaves a loaded
    # machine's scheduling its room)
    assert 0.29 <= time.monotonic() - start < 1.9


def test_unknown_clock_is_refused(config):
    with pytest.raises(ValueError, match="clock='wall' is invalid: expected one of virtual, "
                                         "real"):
        SimBackend(config, clock="wall")


def test_the_clock_choices_of_every_bench_command_are_the_backends(monkeypatch):
    # --clock offered a list of its own ('virtual', 'real'), apart from the clocks the
    # simulated bench takes: a clock added to CLOCKS is offered by every bench command
    import argparse

    from mkm.bench import backend
    from mkm.cli import build_parser

    monkeypatch.setattr(backend, "CLOCKS", (*backend.CLOCKS, "toy"))

    commands = [sub for action in build_parser()._actions
                if isinstance(action, argparse._SubParsersAction)
                for sub in action.choices.values()]
    offered = [a.choices for sub in commands for a in sub._actions if "--clock" in a.option_strings]
    assert len(offered) >= 3 and all(tuple(c) == backend.CLOCKS for c in offered)



def test_slack_muscle_does_not_push(config):
    # After a long hold at 2.5 bar the relaxed part is ~2 % of ~1000 N; venting leaves it
    # recovering, which must not read as a compressive force on a slack muscle.
    c = quiet(config, creep_fraction=0.02, hysteresis_fraction=0.03)
    bench = SimMuscleBench(c)
    bench.set_command_volts(c.regulator.command_volts(2.5))
    run_for(bench, 60.0)
    bench.set_command_volts(0.0)
    volts = run_for(bench, 30.0)[:, 0]
    assert bench.relaxed_N > 1.0 and volts.min() == 0.0


def test_real_clock_overflow_found_while_writing_is_reported_by_the_next_read(config):
    # the reader fell 2 s behind a 1 s buffer; the command write must not fail for it
    import time

    from mkm.bench.backend import BufferOverflow

    c = config.replace(sim={"buffer_s": 1.0})
    sim = SimBackend(c, clock="real")
    sim.open()
    sim.start()
    sim._started_at -= 2.0  # as if the reader had stalled for 2 s
    sim.write_command(2.5)  # goes through
    assert sim.commands[-1][1] == 2.5 and sim.commands[-1][0] >= 20
    with pytest.raises(BufferOverflow):
        sim.read(1, 1.0)
    assert sim.recover() >= 20
    start = time.monotonic()
    # the next sample is there at once: a read short of its 1 s timeout
    assert sim.read(1, 1.0).first_index >= 20 and time.monotonic() - start < 0.9


def test_the_default_simulated_muscle_is_the_fe_model_and_says_so(config):
    # issue 15: a "measurement" from a closed form made that closed form win by construction
    info = SimBackend(config).open()
    physics = info.extra["sim"]["physics"]
    assert config.sim.model == "axisym" and physics["force_model"] == "axisym"
    assert physics["force_model_params"]["mesh"] == "medium"
    assert "braid friction" in physics["summary"] and "creep" in physics["summary"]
    # and it is not the thick-wall closed form: 4.3 % apart at 2 bar for the prototype (eps 0)
    p, f = static_force_table(config)
    m = config.muscle
    thick = make_model("thickwall", L0_mm=m.L0_mm).predict(2.0, m.D0_mm, m.t0_mm, m.eps)
    assert abs(np.interp(2.0, p, f) / float(thick.force_N) - 1) > 0.02
