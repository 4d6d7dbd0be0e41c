"""Issue 20: a bench that proves it vented and owns its hardware. One test (or a few) per
finding; each failed before the fix.
"""

import dataclasses
import errno
import json
import math
import re
import signal
import threading
import time
from pathlib import Path

import pandas as pd
import pytest

from mkm.bench.config import load_config
from mkm.bench.ownership import BenchBusy, BenchOwner
from mkm.bench.run import BenchRun, acquire
from mkm.bench.sim import SimBackend
from mkm.bench.storage import RunWriter, load_run
from mkm.bench.unvented import BenchLease, bench_folder

QUIET = {"notify": lambda m: None}


# 1. the vent is verified -------------------------------------------------------------------

def test_a_stuck_regulator_fails_the_run_and_asks_for_a_vent_by_hand(config, tmp_path):
    # stuck from 4 s, at the 0.5 bar step: the 1.0 bar command is not followed, the interlock
    # vents, and the monitor still reads ~0.5 bar 10 s (safety.vent_timeout_s) later
    c = config.replace(sim={"faults": {"regulator_stuck_at_s": 4.0}})
    result = acquire(c, out_root=tmp_path, **QUIET)
    run = load_run(result.path)
    assert result.status == "failed" and result.exit_code == 4 and result.manual_vent_required
    assert "monitor still reads 0.49" in result.reason and "VENT BY HAND" in result.reason
    check = run.meta.vent_check
    assert not check["verified"] and check["pressure_bar"] == pytest.approx(0.5, abs=0.02)
    assert check["waited_s"] > c.safety.vent_timeout_s
    assert check["doubted"] == ""  # the monitor read the pressure the valve held
    assert run.meta.manual_vent_required
    (marker,) = bench_folder("sim-Dev1").glob("*.json")  # the bench stays marked
    assert json.loads(marker.read_text())["run_path"] == str(run.path)


def _stopped_at(config, tmp_path, sample: int):
    """A run of ``config`` on the simulator that Ctrl-C stops at ``sample``; its result and
    backend."""
    backend = SimBackend(config)
    read = backend.read

    def stopped(n, timeout):
        block = read(n, timeout)
        if block.first_index == sample:
            run.request_stop()
        return block

    backend.read = stopped
    run = BenchRun(config, backend, tmp_path, handle_signals=False, **QUIET)
    return run.execute(), backend


def test_a_regulator_slower_than_the_vent_timeout_is_read_on_while_it_falls(config, tmp_path):
    # A regulator of time constant 2.5 s, stopped at 2.5 bar (15 s into the step): it exhausts
    # the muscle below 0.05 bar 2.5 ln(2.5 / 0.05) = 9.8 s after the vent, but its reading was
    # not yet steady at safety.vent_timeout_s = 10 s: VENT BY HAND (exit 4) on a bench that
    # vented. Still falling at the timeout, the monitor is read on while it falls.
    c = config.replace(sequence={"pressures_bar": (2.5,)}, sim={"regulator_tau_s": 2.5})
    result, backend = _stopped_at(c, tmp_path, 170)
    assert result.status == "aborted" and result.exit_code == 130, result.reason
    check = load_run(result.path).meta.vent_check
    held = 2.5 * (1 - math.exp(-15.1 / 2.5))  # the pressure the vent found
    assert check["verified"]
    # steady once its fall over vent.SETTLED_S (0.5 s) is within its noise (noise_bar): at
    # 2.5 ln(held (1 - exp(-0.5 / 2.5)) / noise) = 10.7 s, within a 0.1 s read and the noise
    steady_s = 2.5 * math.log(held * (1 - math.exp(-0.5 / 2.5)) / check["noise_bar"])
    assert check["waited_s"] == pytest.approx(steady_s, abs=0.3)
    assert check["waited_s"] > c.safety.vent_timeout_s
    assert "still falling at safety.vent_timeout_s=10 s" in check["waited_why"]
    assert "at most 60 s after the vent" in check["waited_why"]
    assert backend.bench.pressure_bar < c.safety.vent_below_bar  # the truth: vented


def test_a_read_timeout_while_the_check_reads_on_is_retried_as_before_it(config, tmp_path):
    # the same slow regulator; one read times out 10.3 s after the vent, as the check reads on
    # past safety.vent_timeout_s: it ended the check (VENT BY HAND) where a timeout before the
    # 10 s was retried (daq.read_retries)
    c = config.replace(sequence={"pressures_bar": (2.5,)}, sim={
        "regulator_tau_s": 2.5, "faults": {"read_timeout_at_s": 17.1 + 10.3}})
    result, backend = _stopped_at(c, tmp_path, 170)
    assert result.status == "aborted" and result.exit_code == 130, result.reason
    check = load_run(result.path).meta.vent_check
    assert check["verified"] and "still falling" in check["waited_why"]
    assert backend.bench.pressure_bar < c.safety.vent_below_bar  # the truth: vented

def test_a_regulator_still_falling_at_the_hard_maximum_asks_for_a_vent_by_hand(config,
                                                                              tmp_path):
    # time constant 20 s: the 2.5 bar step ends unsettled at 22 s, near 2.5 (1 - exp(-1.1)) =
    # 1.7 bar, and 60 s after the vent the monitor still falls (by 10 % in 2 s, more than its
    # noise) at 1.7 exp(-3) = 0.08 bar, above 0.05 bar: the check reads on no longer
    c = config.replace(sequence={"pressures_bar": (2.5,)}, sim={"regulator_tau_s": 20.0})
    result = acquire(c, out_root=tmp_path, **QUIET)
    assert result.status == "failed" and result.exit_code == 4 and result.manual_vent_required
    assert "still falling at safety.vent_timeout_s=10 s" in result.reason
    assert "at most 60 s after the vent" in result.reason and "VENT BY HAND" in result.reason
    run = load_run(result.path)
    check = run.meta.vent_check
    assert not check["verified"] and check["waited_s"] == pytest.approx(60.0, abs=0.15)
    before = run.samples.pressure_bar[run.samples.phase != "vent"].iloc[-1]
    # the exhaust from the reading the vent found, within the monitor's noise and ADC steps
    assert check["pressure_bar"] == pytest.approx(before * math.exp(-check["waited_s"] / 20),
                                                  abs=0.005)



def test_a_regulator_too_slow_to_show_its_fall_is_told_which_setting_covers_it(config,
                                                                                monkeypatch):
    # `mkm vent` on a muscle left at 0.2 bar, a regulator of time constant 20 s: still falling
    # at safety.vent_timeout_s = 10 s (0.2 exp(-0.5) = 0.12 bar), read on until its fall over
    # 2 s, 9.5 % of the reading, is within its noise (at 0.11 bar, 11.8 s), above 0.05 bar: VENT BY
    # HAND, the message as a stuck regulator's, naming no setting. Now it names
    # safety.vent_timeout_s and its value; set to 30 s, past 20 ln(0.2 / 0.05) = 27.7 s, it
    # verifies the vent.
    import mkm.bench.procedures as procedures
    from mkm.bench.backend import BenchError

    class Held(SimBackend):
        def start(self):
            super().start()
            self.bench.pressure_bar = 0.2  # left by a run: the vent exhausts it

    monkeypatch.setattr(procedures, "make_backend", lambda c, clock: Held(c))
    slow = config.replace(sim={"regulator_tau_s": 20.0})
    with pytest.raises(BenchError) as caught:
        procedures.vent(slow, notify=lambda m: None)
    message = str(caught.value)
    reading = re.search(r"the monitor still reads ([0-9.]+) bar ([0-9.]+) s after the vent, "
                        r"above 0.05 bar", message)
    assert reading, message
    assert float(reading.group(1)) == pytest.approx(0.2 * math.exp(-float(reading.group(2)) / 20),
                                                    abs=0.005)  # its noise and ADC steps
    assert ("a regulator that sticks, or one exhausting the muscle with a time constant of tens "
            "of seconds, which no reading tells apart; for such a regulator set "
            "safety.vent_timeout_s (now 10 s, at most 30 s) to the time it takes from the "
            "highest pressure to below 0.05 bar") in message
    assert "VENT BY HAND" in message
    out = procedures.vent(slow.replace(safety={"vent_timeout_s": 30.0}), notify=lambda m: None)
    assert out["vented"] and out["pressure_bar"] < 0.05
    # the exhaust takes 27.7 s, then a steady 0.5 s, within the monitor's noise
    assert out["waited_s"] == pytest.approx(20 * math.log(0.2 / 0.05) + 0.5, abs=1.5)


def test_the_cli_says_vent_by_hand_with_its_own_exit_status(tmp_path, mkm_cli):
    text = load_config().text.replace("monitor_noise_V = 0.001",
                                      "monitor_noise_V = 0.001\n[sim.faults]\n"
                                      "regulator_stuck_at_s = 8.0")
    (tmp_path / "stuck.toml").write_text(text)
    code, out, err = mkm_cli(["acquire", "--config", str(tmp_path / "stuck.toml"),
                              "--pressures", "0.5,1", "--out", str(tmp_path / "runs"),
                              "--no-progress"])
    assert code == 4 and "VENT THE MUSCLE BY HAND NOW" in err
    assert out.strip().endswith("-SIMULATED")


def test_a_manual_vent_is_confirmed_by_the_operators_reading(config, tmp_path):
    class StillPressurised:
        def set_pressure(self, pressure_bar):
            return pressure_bar

        def vent(self):
            return 0.3  # the manometer still reads 0.3 bar

    c = config.replace(regulator={"kind": "manual"})
    result = BenchRun(c, SimBackend(c), tmp_path, operator=StillPressurised(),
                      handle_signals=False, **QUIET).execute()
    assert result.status == "failed" and result.exit_code == 4
    assert "operator still reads 0.300 bar" in result.reason


def _frozen_at(backend, at_sample: int, reading_bar: float = 0.0):
    """From sample ``at_sample`` on, ``backend``'s monitor reads ``reading_bar`` whatever the
    pressure (a monitor that followed, then froze)."""
    read = backend.read

    def freezing(n, timeout):
        if backend._index >= at_sample:
            backend.bench.monitor_stuck_bar = reading_bar
        return read(n, timeout)

    backend.read = freezing
    return backend


@pytest.mark.parametrize("frozen", ["from the start", "at 4 s, having followed 0.5 bar"])
def test_a_monitor_frozen_at_zero_does_not_verify_the_vent(config, tmp_path, frozen):
    # The monitor reads 0 bar whatever the pressure while the regulator delivers the command:
    # the follow interlock trips 0.000 bar against 0.5 bar and vents, and the vent check used to
    # read the same stuck 0 bar and call the vent verified (exit 1, marker removed) while the
    # muscle still held the 0.5 bar falling by one sample of the regulator's exhaust
    if frozen == "from the start":
        c = config.replace(sim={"truth": {"monitor_stuck_bar": 0.0}})
        backend = SimBackend(c)
    else:
        c = config
        backend = _frozen_at(SimBackend(c), 40)
    result = BenchRun(c, backend, tmp_path, handle_signals=False, **QUIET).execute()
    run = load_run(result.path)
    assert "pressure interlock: the regulator does not follow" in result.reason
    assert result.status == "failed" and result.exit_code == 4 and result.manual_vent_required
    assert "against 0.5 bar commanded before the vent, so its reading after it proves nothing" \
        in result.reason
    assert result.reason.endswith("check the monitor and the supply): VENT BY HAND (the "
                                  "regulator may still hold 0.5 bar)")
    check = run.meta.vent_check
    assert not check["verified"] and check["pressure_bar"] < c.safety.vent_below_bar
    assert check["unfollowed_bar"] == 0.5 and run.meta.manual_vent_required
    # the truth: six 0.1 s samples after the vent (the check waits for a reading steady over
    # vent.SETTLED_S), exhausting with tau 0.4 s from 0.5 bar, the muscle still held
    # 0.5 exp(-0.6/0.4) = 0.11 bar while the monitor read 0
    assert backend.bench.pressure_bar == pytest.approx(0.5 * math.exp(-1.5), abs=1e-3)
    (marker,) = bench_folder("sim-Dev1").glob("*.json")  # the bench stays marked
    assert "proves nothing" in json.loads(marker.read_text())["vent_unverified"]


@pytest.mark.parametrize("stop", ["Ctrl-C", "mkm vent asking"])
def test_a_stop_before_the_follow_interlock_trips_does_not_verify_with_a_frozen_monitor(
        config, tmp_path, stop):
    # the monitor reads 0 bar whatever the pressure; the run is stopped at 4.5 s, 2.5 s into
    # the 0.5 bar step, before the follow interlock's 5 s: the vent check read the same 0 bar
    # and called the vent verified (exit 130, marker removed) while the muscle held 0.39 bar
    c = config.replace(sim={"truth": {"monitor_stuck_bar": 0.0}})
    backend = SimBackend(c)
    read = backend.read

    def stopped_at_45(n, timeout):
        block = read(n, timeout)
        if block.first_index == 45:
            run.request_stop(None if stop == "Ctrl-C" else "mkm vent (pid 1)")
        return block

    backend.read = stopped_at_45
    run = BenchRun(c, backend, tmp_path, handle_signals=False, **QUIET)
    result = run.execute()
    assert "pressure interlock" not in result.reason  # the stop came first
    assert result.status == "failed" and result.exit_code == 4 and result.manual_vent_required
    assert "0.5 bar commanded before the vent, so its reading after it proves nothing" \
        in result.reason
    assert result.reason.endswith("VENT BY HAND (the regulator may still hold 0.5 bar)")
    check = load_run(result.path).meta.vent_check
    assert not check["verified"] and check["unfollowed_bar"] == 0.5
    # the truth: six 0.1 s samples of exhaust (tau 0.4 s) after the vent from 0.5 bar, the
    # check waiting for a reading steady over vent.SETTLED_S
    assert backend.bench.pressure_bar == pytest.approx(0.5 * math.exp(-1.5), abs=1e-3)
    (marker,) = bench_folder("sim-Dev1").glob("*.json")  # the bench stays marked, unproven
    assert json.loads(marker.read_text())["unfollowed_bar"] == 0.5


def test_a_stop_with_a_following_monitor_verifies_the_vent(config, tmp_path):
    # the same stop with a monitor that reads the 0.5 bar: its fall after the vent verifies it
    backend = SimBackend(config)
    read = backend.read

    def stopped_at_45(n, timeout):
        block = read(n, timeout)
        if block.first_index == 45:
            run.request_stop()
        return block

    backend.read = stopped_at_45
    run = BenchRun(config, backend, tmp_path, handle_signals=False, **QUIET)
    result = run.execute()
    assert result.status == "aborted" and result.exit_code == 130, result.reason
    check = load_run(result.path).meta.vent_check
    assert check["verified"] and check["unfollowed_bar"] is None


@pytest.mark.parametrize("stop", [None, "Ctrl-C"])
def test_a_monitor_frozen_within_the_tolerance_of_its_step_verifies_no_vent(config, tmp_path,
                                                                            stop):
    # The monitor reads 0 bar whatever the pressure; the one step, 0.12 bar, is within the
    # follow interlock's 0.15 bar of it, so nothing tripped: the run ended complete (exit 0),
    # or stopped by Ctrl-C 2.5 s into the step (exit 130), its vent "verified" by the frozen
    # 0 bar while the muscle held 0.12 bar. A working monitor moves with its command: this one
    # never moves, is a monitor fault after pressure_follow_s, and verifies no vent.
    c = config.replace(sequence={"pressures_bar": (0.12,), "down_sweep": False},
                       sim={"truth": {"monitor_stuck_bar": 0.0}})
    backend = SimBackend(c)
    read, write, at_vent = backend.read, backend.write_command, []

    def stopped_at_45(n, timeout):
        block = read(n, timeout)
        if stop and block.first_index == 45:
            run.request_stop()
        return block

    def vent_noted(volts):
        if volts == 0.0 and backend._index > 20:
            at_vent.append(backend.bench.pressure_bar)
        write(volts)

    backend.read, backend.write_command = stopped_at_45, vent_noted
    run = BenchRun(c, backend, tmp_path, handle_signals=False, **QUIET)
    result = run.execute()
    assert result.status == "failed" and result.exit_code == 4 and result.manual_vent_required
    assert ("pressure interlock: the monitor does not move with the command" in result.reason) \
        == (stop is None)
    assert "0.12 bar commanded before the vent, so its reading after it proves nothing" \
        in result.reason
    assert result.reason.endswith("VENT BY HAND (the regulator may still hold 0.12 bar)")
    check = load_run(result.path).meta.vent_check
    assert not check["verified"] and check["unfollowed_bar"] == 0.12
    # the truth: the muscle held 0.12 bar as the vent went out (2.5 s or more at tau 0.4 s);
    # the frozen 0 bar verified it after one 0.1 s sample, with 0.12 exp(-0.25) = 0.093 bar
    # left, above the 0.05 bar a verified vent claims
    assert at_vent[0] == pytest.approx(0.12, abs=1e-3)
    (marker,) = bench_folder("sim-Dev1").glob("*.json")  # the bench stays marked
    assert json.loads(marker.read_text())["unfollowed_bar"] == 0.12


def test_a_monitor_frozen_at_zero_is_caught_as_pre_conditioning_leaves_its_top(config,
                                                                               tmp_path):
    # Frozen at 0 bar: pre-conditioning held 1 bar from 2 s for exactly pressure_follow_s (5 s)
    # and went back to 0 bar, which the frozen reading matches, before any sample was 5 s past
    # the command: neither interlock tripped, and the run went on to trip 5 s into its first
    # step (at 17 s). The command's return judges the monitor on the time it had: 7 s.
    c = config.replace(sequence={"preconditioning_cycles": 1},
                       sim={"truth": {"monitor_stuck_bar": 0.0}})
    result = acquire(c, out_root=tmp_path, **QUIET)
    assert result.status == "failed" and result.exit_code == 4, result.reason
    assert re.match(r"pressure interlock: the monitor does not move with the command: "
                    r"0\.00\d bar measured against 1 bar commanded from 2 s to 7 s, after "
                    r"0\.00\d bar under 0 bar \(a working regulator's monitor moves more than "
                    r"half the change within 5 s\): a monitor fault \(stuck\), or a regulator "
                    r"without supply; vented; ", result.reason), result.reason
    run = load_run(result.path)
    tripped = run.samples[run.samples["flags"].str.contains("interlock")]
    assert tripped["time_s"].iloc[0] == pytest.approx(7.0) and (run.samples["step"] < 0).all()
    assert run.meta.vent_check["unfollowed_bar"] == 1.0  # its reading verifies no vent
    assert result.reason.endswith("VENT BY HAND (the regulator may still hold 1 bar)")
    # a working monitor under the same pre-conditioning: no fault
    assert acquire(config.replace(sequence={"preconditioning_cycles": 1}), out_root=tmp_path,
                   **QUIET).status == "complete"
    # a regulator of time constant 8 s moves its monitor 0.46 bar of the 1 bar in those 5 s,
    # less than half, more than the tolerance: moving, so no monitor fault; it is too slow for
    # the follow interlock on its way back down instead
    slow = acquire(config.replace(sequence={"preconditioning_cycles": 1},
                                  sim={"regulator_tau_s": 8.0}), out_root=tmp_path, **QUIET)
    assert slow.reason.startswith("pressure interlock: the regulator does not follow: "), \
        slow.reason


@pytest.mark.parametrize("truth", [{}, {"monitor_gain": 0.9, "monitor_offset_bar": -0.04,
                                        "monitor_hysteresis_bar": 0.1}])
def test_a_monitor_that_moves_with_small_steps_is_no_monitor_fault(config, tmp_path, truth):
    # steps 0.06 bar apart, just above the 0.05 bar vent threshold the move is judged from,
    # read by a good sensor and by one 10 % low, 0.04 bar low, with 0.1 bar of hysteresis
    c = config.replace(sequence={"pressures_bar": (0.06, 0.12, 0.18)},
                       sim={"truth": truth})
    result = acquire(c, out_root=tmp_path, **QUIET)
    assert result.status == "complete" and result.exit_code == 0, result.reason
    assert load_run(result.path).meta.vent_check["verified"]


@pytest.mark.parametrize("preconditioned", [True, False])
def test_a_stop_as_a_step_from_0_bar_begins_is_judged_by_whether_the_monitor_moved(
        config, tmp_path, preconditioned):
    # A slow regulator (tau 1.5 s): Ctrl-C at the first sample of a 0.5 bar step from a vented
    # muscle, which the monitor reads 0.5 (1 - exp(-0.1/1.5)) = 0.032 bar, below 0.05 bar and
    # 0.47 bar below the command. After a pre-conditioning cycle the monitor has moved with a
    # command (to 1 bar and back), and now rose above its reading at 0 bar by more than its
    # noise: it is moving with the step, and its fall after the vent verifies it (it used to
    # say VENT BY HAND, exit 4). As the run's first pressure no command has shown it works: a
    # reading that rose a little then fell is all a monitor whose output lost its gain gives
    # too, so a vent by hand is still asked for.
    cycles = {"preconditioning_cycles": 1, "preconditioning_hold_s": 10.0} if preconditioned \
        else {}
    c = config.replace(sequence=cycles, sim={"regulator_tau_s": 1.5})
    first = 20 + (200 if preconditioned else 0)  # after the tare's 2 s and the cycle's 20 s
    result, backend = _stopped_at(c, tmp_path, first)
    samples = load_run(result.path).samples
    (at_stop,) = samples.pressure_bar[samples["sample"] == first]
    assert at_stop == pytest.approx(0.5 * (1 - math.exp(-0.1 / 1.5)), abs=0.005)
    check = load_run(result.path).meta.vent_check
    if preconditioned:
        assert result.status == "aborted" and result.exit_code == 130, result.reason
        assert check["verified"] and check["unfollowed_bar"] is None
    else:
        assert result.status == "failed" and result.exit_code == 4
        assert not check["verified"] and check["unfollowed_bar"] == 0.5
    assert backend.bench.pressure_bar < c.safety.vent_below_bar  # the truth: vented


@pytest.mark.parametrize("spike_V", [0.3, 0.06])
def test_a_noise_spike_as_a_frozen_monitor_stops_verifies_no_vent(config, tmp_path, spike_V):
    # The monitor reads 0 bar whatever the pressure; one sample of noise (+0.3 V, or +0.06 V,
    # 0.06 bar: just above the 0.05 bar threshold) comes as Ctrl-C stops the run 2.5 s into the
    # 0.5 bar step. Its last reading was above the threshold, which passed for a monitor that
    # read the pressure, and the frozen 0 bar after the vent verified the vent (exit 130) with
    # 0.11 bar in the muscle. A monitor that reads the pressure falls after the vent; this one
    # shows no fall.
    c = config.replace(sim={"truth": {"monitor_stuck_bar": 0.0}})
    backend = SimBackend(c)
    read = backend.read

    def spike_and_stop_at_45(n, timeout):
        block = read(n, timeout)
        if block.first_index == 45:
            run.request_stop()
            volts = block.volts.copy()
            volts[:, 1] += spike_V  # 1 V per bar: 1-5 V over 4 bar
            block = dataclasses.replace(block, volts=volts)
        return block

    backend.read = spike_and_stop_at_45
    run = BenchRun(c, backend, tmp_path, handle_signals=False, **QUIET)
    result = run.execute()
    assert result.status == "failed" and result.exit_code == 4 and result.manual_vent_required
    assert "with 0.5 bar commanded before the vent and did not fall after it" in result.reason
    assert result.reason.endswith("VENT BY HAND (the regulator may still hold 0.5 bar)")
    run_ = load_run(result.path)
    (spiked,) = run_.samples.pressure_bar[run_.samples["sample"] == 45]
    assert spiked == pytest.approx(spike_V, abs=0.003)  # the reading the stop came with
    check = run_.meta.vent_check
    assert not check["verified"] and check["unfollowed_bar"] == 0.5
    # the truth: six 0.1 s samples of exhaust (tau 0.4 s) from 0.5 bar as the check settled
    assert backend.bench.pressure_bar == pytest.approx(0.5 * math.exp(-1.5), abs=1e-3)


def test_two_noise_spikes_as_the_vent_check_begins_are_no_fall(config, tmp_path):
    # The monitor moved with the pre-conditioning cycle (to 1 bar and back), then froze at
    # 0 bar as the 0.5 bar step began (sample 120); Ctrl-C 2.5 s into the step, before the
    # follow interlock's 5 s. The vent check's first two readings are noise spikes (+0.3 V,
    # 0.3 bar): their median with the third was taken for the monitor's fall after the vent,
    # and the frozen 0 bar verified it (exit 130) with 0.11 bar in the muscle. Readings after
    # a vent cannot start above the monitor's last reading before it: this one read 0 bar.
    c = config.replace(sequence={"preconditioning_cycles": 1, "preconditioning_hold_s": 5.0})
    backend = _frozen_at(SimBackend(c), 120)
    read, after_stop = backend.read, []

    def stop_then_spikes(n, timeout):
        block = read(n, timeout)
        if after_stop:
            after_stop.append(block.first_index)
            if len(after_stop) <= 3:  # the stop's block, then the vent check's first two
                volts = block.volts.copy()
                volts[:, 1] += 0.3  # 1 V per bar: 1-5 V over 4 bar
                block = dataclasses.replace(block, volts=volts)
        elif block.first_index == 145:
            run.request_stop()
            after_stop.append(block.first_index)
        return block

    backend.read = stop_then_spikes
    run = BenchRun(c, backend, tmp_path, handle_signals=False, **QUIET)
    result = run.execute()
    assert result.status == "failed" and result.exit_code == 4 and result.manual_vent_required
    assert "against 0.5 bar commanded before the vent, so its reading after it proves " \
        "nothing" in result.reason
    run_ = load_run(result.path)
    vent_rows = run_.samples[run_.samples.phase == "vent"]
    assert list(vent_rows.pressure_bar[:2]) == pytest.approx([0.3, 0.3], abs=0.003)
    check = run_.meta.vent_check
    assert not check["verified"] and check["unfollowed_bar"] == 0.5
    # the truth: 2.5 s into the step (tau 0.4 s) the muscle held 0.5 bar; eight 0.1 s samples
    # of exhaust as the check read the two spikes, then six steady readings (vent.SETTLED_S),
    # leave 0.5 exp(-2) = 0.068 bar, above the 0.05 bar a verified vent claims
    assert backend.bench.pressure_bar == pytest.approx(0.5 * math.exp(-2.0), abs=2e-3)


def _monitor_reports_its_command_valve_sticks(backend, config, at_sample: int) -> None:
    """``backend``'s regulator made one whose monitor output reports its setpoint, not the
    pressure, and whose valve stops moving from sample ``at_sample`` on."""
    bench, reg = backend.bench, config.regulator
    step, read = bench.step, backend.read
    span_V = reg.monitor_V_at_full_scale - reg.monitor_V_at_zero

    def reporting_its_command():
        cell_V, _ = step()
        return cell_V, reg.monitor_V_at_zero + bench.command_bar / reg.full_scale_bar * span_V

    def valve_stuck(n, timeout):
        if backend._index >= at_sample:
            bench.regulator_stuck = True
        return read(n, timeout)

    bench.step, backend.read = reporting_its_command, valve_stuck


def test_a_monitor_that_reports_its_command_verifies_no_vent_the_load_cell_denies(config,
                                                                                   tmp_path):
    # The regulator's monitor output reports its setpoint, not the pressure (it reads "OK"
    # whatever the valve does), and from 15 s its valve no longer moves: at the end of the run
    # the vent is commanded, the monitor reads 0.000 bar at once, and the vent was verified
    # (exit 0, marker removed) with the muscle at 0.55 bar pulling 215 N. A vented muscle lets
    # go of its force: the load cell still reading it verifies no vent.
    backend = SimBackend(config)
    bench = backend.bench
    _monitor_reports_its_command_valve_sticks(backend, config, at_sample=150)
    result = BenchRun(config, backend, tmp_path, handle_signals=False, **QUIET).execute()
    assert result.status == "failed" and result.exit_code == 4 and result.manual_vent_required
    assert "but the load cell still reads" in result.reason
    assert "stuck or disconnected" not in result.reason  # a live cell: its noise is there
    assert result.reason.endswith("VENT BY HAND (the regulator may still hold 0.5 bar)")
    run = load_run(result.path)
    check = run.meta.vent_check
    assert not check["verified"] and check["pressure_bar"] == 0.0 and check["unfollowed_bar"] == 0.5
    assert check["doubted"] == "the monitor or the load cell"  # they recorded the steps too
    forces = re.search(r"still reads ([0-9.]+) N against ([0-9.]+) N before", result.reason)
    after_N, before_N = float(forces.group(1)), float(forces.group(2))
    assert after_N == pytest.approx(before_N, rel=0.02)  # nothing let go: creep alone
    # the truth: the pressure the valve stuck at, above the 0.5 bar step (falling from 1 bar)
    assert bench.pressure_bar > 0.5 and bench.force_N == pytest.approx(after_N, abs=2.0)
    (marker,) = bench_folder("sim-Dev1").glob("*.json")  # the bench stays marked
    assert json.loads(marker.read_text())["unfollowed_bar"] == 0.5


def _drifting(drift_N_per_min: float):
    """eps 12.2 % (the muscle pulls from about 0.45 bar), 0.25 to 0.75 bar and back, 30 s
    holds (a run of about 170 s), on a load cell whose zero drifts ``drift_N_per_min``."""
    return load_config(eps=0.122).replace(
        sequence={"pressures_bar": (0.25, 0.5, 0.75), "tare_s": 2.0,
                  "preconditioning_cycles": 0},
        settle={"min_dwell_s": 3.0, "hold_s": 30.0, "timeout_s": 20.0, "window_s": 2.0},
        sim={"truth": {"loadcell_drift_N_per_min": drift_N_per_min}})


def test_a_muscle_that_trips_the_force_interlock_as_it_rises_verifies_its_vent(tmp_path):
    # A 60 mm tube with a 4 mm wall at 18 deg on the example's 1961 N cell: pre-conditioning's
    # first 0.1 s towards 2 bar makes about 1100 N, the next reading clips at the cell's rail
    # and the interlock vents. The vent check weighed the load cell after the vent (the
    # muscle's last tens of newtons as the regulator exhausts it) against the median of the
    # half second before it, the tare's readings, not yet taken from the tare's zero (the
    # amplifier's offset, 9.8 N here): "the muscle still pulls ... VENT BY HAND", exit 4, on a
    # vented bench. From the tare's zero those readings are the muscle at rest, within the
    # cell's noise, which tells nothing: the monitor verifies the vent.
    c = load_config().replace(
        muscle={"D0_mm": 60.0, "t0_mm": 4.0, "L0_mm": 800.0, "theta0_deg": 18.0},
        regulator={"max_pressure_bar": 2.0}, sequence={"pressures_bar": (1.0, 2.0)},
        sim={"fe_mesh": "coarse", "loadcell_offset_V": 0.05, "truth": {"theta0_deg": 18.0}})
    backend = SimBackend(c)
    result = BenchRun(c, backend, tmp_path, handle_signals=False, **QUIET).execute()
    assert result.status == "aborted" and result.exit_code == 1, result.reason
    assert result.reason.startswith("force interlock: ") and result.reason.endswith("; vented")
    assert not result.manual_vent_required
    run = load_run(result.path)
    assert run.meta.vent_check["verified"] and run.steps.empty  # no step was reached
    tare = run.samples[run.samples["phase"] == "tare"]
    assert tare["force_N"].median() == pytest.approx(0.05 * 196.133, abs=1.0)  # as recorded
    assert backend.bench.pressure_bar < c.safety.vent_below_bar  # the truth: vented


def test_a_slack_muscle_on_a_drifting_load_cell_zero_verifies_its_vent(tmp_path):
    # The load cell's amplifier warms up: its zero drifts 1.3 N/min from the start. The run
    # ends on 0.25 bar, below the muscle's threshold: slack, the cell reads its zero, moved by
    # then. The vent check read about the same force after the vent as before it and said "the
    # muscle still pulls ... VENT BY HAND" (exit 4, run failed) of a muscle that held no
    # pressure making any force. A force no pressure above the threshold need have made tells
    # nothing: the vent is verified.
    c = _drifting(1.3)
    backend = SimBackend(c)
    result = BenchRun(c, backend, tmp_path, handle_signals=False, **QUIET).execute()
    assert result.status == "complete" and result.exit_code == 0, result.reason
    assert not result.manual_vent_required
    run = load_run(result.path)
    assert run.meta.vent_check["verified"]
    last = run.steps.iloc[-1]
    assert last.set_pressure_bar == 0.25
    # slack: the last hold reads the zero's drift since the start, 1.3 N/min at the hold's
    # middle time, within five times the spread of the tare's mean (0.35 N over its 20
    # samples: 0.08 N; the hold's 300 samples add little to it)
    middle_s = (last.start_s + last.end_s) / 2
    assert last.force_N_mean == pytest.approx(1.3 * middle_s / 60.0, abs=0.4)
    assert last.force_N_mean > 3.0  # above the cell's noise (5 x 0.35 N + 2 ADC steps)
    assert backend.bench.pressure_bar < c.safety.vent_below_bar  # the truth: vented


def test_a_muscle_held_by_a_stuck_valve_on_a_drifting_load_cell_is_still_caught(tmp_path):
    # The same drifting cell, with a regulator whose monitor reports its command and whose
    # valve sticks at 10 s into the 0.75 bar step: the muscle holds 0.75 bar, 0.3 bar above its
    # threshold, to the end and after the vent, pulling about 57 N on top of the zero's 3.5 N.
    # That is far more than the 0.05 bar above the threshold makes (about 10 N): VENT BY HAND.
    c = _drifting(1.3)
    backend = SimBackend(c)
    bench = backend.bench
    _monitor_reports_its_command_valve_sticks(backend, c, at_sample=900)
    result = BenchRun(c, backend, tmp_path, handle_signals=False, **QUIET).execute()
    assert result.status == "failed" and result.exit_code == 4 and result.manual_vent_required
    forces = re.search(r"still reads ([0-9.]+) N against ([0-9.]+) N before", result.reason)
    assert forces, result.reason
    assert float(forces.group(2)) > 50.0, result.reason  # 0.75 bar's force, not the drift
    assert bench.pressure_bar == pytest.approx(0.75, abs=0.01)  # the truth: still held


def test_a_load_cell_stuck_at_its_reading_is_said_so_the_vent_still_unverified(config,
                                                                                tmp_path):
    # The load cell's input holds its reading from 12 s (on the 1.0 bar step: its cable or
    # amplifier failed so). The regulator vents (the run stops on the stuck cell: below), the
    # monitor falls to 0 bar, and the check called it a muscle that still pulls, with a
    # monitor reporting its command and an exhaust that did not open: the regulator to check.
    # Every force read one ADC code where the tare's strayed 0.35 N (2 mV rms at 196.133 N/V,
    # 0.39 N: 1.6 ADC steps), which no live cell does: it is said to be the load cell, still
    # VENT BY HAND (the force proves nothing).
    c = config.replace(sim={"faults": {"loadcell_stuck_at_s": 12.0}})
    backend = SimBackend(c)
    result = BenchRun(c, backend, tmp_path, handle_signals=False, **QUIET).execute()
    assert result.status == "failed" and result.exit_code == 4 and result.manual_vent_required
    run = load_run(result.path)
    forces = run.samples["force_N"][run.samples["sample"] >= 120]
    assert forces.nunique() == 1  # the fault: one reading from 12 s on
    reason = re.search(r"the monitor read ([0-9.]+) bar before the vent and ([0-9.]+) bar after "
                       r"it, but the load cell read ([0-9.]+) N throughout, every reading the "
                       r"same where it strayed ([0-9.]+) N at the tare: a load cell that does "
                       r"not change while the pressure falls is stuck or disconnected",
                       result.reason)
    assert reason, result.reason
    before_bar, after_bar, held_N, tare_std_N = map(float, reason.groups())
    assert before_bar == pytest.approx(1.0, abs=0.02)  # the step it stuck on
    assert after_bar < c.safety.vent_below_bar
    assert held_N == pytest.approx(forces.iloc[0], abs=0.05)
    # the tare's spread is the cell's noise: 2 mV rms at 196.133 N/V, quantised
    assert tare_std_N == pytest.approx(0.002 * 196.133, rel=0.25)
    assert "check the load cell's cable, amplifier and supply" in result.reason
    assert "a monitor that reports its command" not in result.reason
    assert backend.bench.pressure_bar < c.safety.vent_below_bar  # the truth: vented
    assert not run.meta.vent_check["verified"]
    assert run.meta.vent_check["doubted"] == "the load cell"


def test_a_load_cell_stuck_mid_run_stops_the_run_within_two_seconds(config, tmp_path):
    # The load cell's input holds its reading from 12 s: the run went on to its end, every
    # step "settled" at once on one force (steps.csv full of it), the force interlock blind
    # behind it, until the vent check found the cell unchanged. A live cell strays at every
    # reading (0.35 N at the tare, 1.6 ADC steps): one code held STUCK_CELL_S (2 s, 20
    # readings) stops the run there, vented, failed, with why.
    from mkm.bench.worker import STUCK_CELL_S

    c = config.replace(sim={"faults": {"loadcell_stuck_at_s": 12.0}})
    result = acquire(c, out_root=tmp_path, **QUIET)
    assert result.status == "failed" and result.exit_code == 4, result.reason
    assert re.match(r"force interlock: the load cell read [0-9.]+ V \([0-9.]+ N\) unchanged for "
                    r"2\.0 s, where it strayed 0\.[0-9]+ N at the tare: a stuck or disconnected "
                    r"load cell, behind which the force limit is not watched; check its cable, "
                    r"amplifier and supply; vented", result.reason), result.reason
    run = load_run(result.path)
    tripped = run.samples[run.samples["flags"].str.contains("interlock")]
    # the sample 12 s in holds the code, then 20 readings: 2 s later, to a sample
    assert tripped["time_s"].iloc[0] == pytest.approx(12.0 + STUCK_CELL_S, abs=0.11)
    assert run.meta.steps_done < len(c.sequence.pressures_bar) + 1  # not every step


def test_a_load_cell_stuck_during_the_tare_is_no_tare(config, tmp_path):
    # The load cell's input holds its reading from 2 s of a 5 s tare: its last 2.9 s (30
    # readings) on one code, where the tare's first 2 s strayed 0.3 N. The tare passed, the
    # pre-conditioning commanded 2.5 bar, and the stuck-cell interlock, counting from the
    # tare's end, tripped 2 s later at 2.1 bar, the force limit blind meanwhile. No live cell
    # holds one code that long (STUCK_CELL_S): the tare is invalid, nothing pressurised.
    from mkm.bench.sim import SimBackend

    c = config.replace(sequence={"tare_s": 5.0, "preconditioning_cycles": 1},
                       sim={"faults": {"loadcell_stuck_at_s": 2.0}})
    backend = SimBackend(c)
    result = BenchRun(c, backend, tmp_path, handle_signals=False, **QUIET).execute()
    assert result.status == "failed" and result.exit_code == 1, result.reason
    assert re.fullmatch(r"tare invalid: the load cell read [0-9.]+ V unchanged for "
                        r"the last 2\.9 s of the tare, where it strayed 0\.[0-9]+ N before: a "
                        r"stuck or disconnected load cell, behind which the force limit is not "
                        r"watched; check its cable, amplifier and supply; nothing was "
                        r"pressurised", result.reason), result.reason
    assert max(volts for _, volts in backend.commands) == 0.0  # the regulator got vents only
    run = load_run(result.path)
    assert len(run.samples) >= 50 and not run.meta.manual_vent_required  # the tare's, kept


def test_a_load_cell_stuck_early_in_the_tare_is_no_tare_either(config, tmp_path):
    # Stuck from 1 s of a 5 s tare, on a code near the tare's mean: its last 3.9 s on one code
    # pulled the whole tare's spread below one ADC step (1.22 mV), which disarmed the stuck-cell
    # interlock and said nothing (not all on one code): the run recorded one force through all
    # its steps, complete, exit 0, the force limit blind. The spread that shows a live cell is
    # that of the readings before the held code (0.41 N here, 2 mV of noise): the tare is invalid.
    from mkm.bench.sim import SimBackend

    c = config.replace(sequence={"tare_s": 5.0}, sim={"faults": {"loadcell_stuck_at_s": 1.0}})
    backend = SimBackend(c)
    result = BenchRun(c, backend, tmp_path, handle_signals=False, **QUIET).execute()
    assert result.status == "failed" and result.exit_code == 1, result.reason
    said = re.fullmatch(r"tare invalid: the load cell read [0-9.]+ V unchanged for "
                        r"the last 3\.9 s of the tare, where it strayed ([0-9.]+) N before: a "
                        r"stuck .*; nothing was pressurised", result.reason)
    assert said, result.reason
    # the readings before it: 2 mV rms of noise at 196.133 N/V (0.39 N), quantised, over 10
    assert float(said.group(1)) == pytest.approx(0.002 * 196.133, rel=0.4)
    tare = load_run(result.path).samples.query("phase == 'tare'")["loadcell_V"]
    assert len(tare) == 50 and tare.std() < 1.22e-3  # the whole tare's spread: below a step
    assert max(volts for _, volts in backend.commands) == 0.0


def test_a_load_cell_on_one_code_at_the_tare_stops_the_run_before_any_pressure(config,
                                                                                tmp_path):
    # Stuck from the start: the tare on one code was only warned of, and the run went on, the
    # stuck-cell interlock disarmed: 1.0 bar into the muscle with the force limit blind, the
    # run marked failed only at its end. The tare refuses it: nothing pressurised, the
    # regulator vented and verified, every sample kept, run.json saying why.
    c = config.replace(sim={"faults": {"loadcell_stuck_at_s": 0.0}})
    backend = SimBackend(c)
    result = BenchRun(c, backend, tmp_path, handle_signals=False, **QUIET).execute()
    assert result.status == "failed" and result.exit_code == 1, result.reason
    assert re.fullmatch(r"tare invalid: the load cell read one ADC code, 0\.0146 V "
                        r"\(\+2\.9 N at loadcell\.offset_V=0 V\), all 20 times: a stuck, .*"
                        r"; nothing was pressurised", result.reason), result.reason
    assert max(volts for _, volts in backend.commands) == 0.0
    run = load_run(result.path)
    assert run.meta.status == "failed" and run.meta.reason == result.reason
    assert (run.samples["phase"] == "tare").sum() == 20 and run.meta.vent_check["verified"]
    assert not result.manual_vent_required and not list(bench_folder("sim-Dev1").glob("*.json"))


def _tripped(run):
    """The first sample of ``run`` an interlock tripped on."""
    return run.samples[run.samples["flags"].str.contains("interlock")].iloc[0]


def _truth_N(c, pressure_bar: float) -> float:
    """The simulated muscle's static force [N] at ``pressure_bar`` (its FE table)."""
    import numpy as np

    from mkm.bench.sim import static_force_table

    return float(np.interp(pressure_bar, *static_force_table(c)))


STEP_N = 20 / 2 ** 14 * 196.133  # one ADC step of the USB-6001 through the paper's cell
#: what the quiet-cell interlock's reason says the bound took of the packaged muscle, whose
#: braid angle and rubber are not declared (:func:`mkm.bench.preflight.bound_assumes`)
BOUND_TAKES = (r"; the bound takes theta0 32\.99 \+- 1 deg \(the FE model's calibrated theta0 "
               r"\(axisym\): \[muscle\] declares none\) and Silastic S's rubber \(\[muscle\] "
               r"declares none\); a muscle with a steeper braid or a stiffer rubber is slack to "
               r"a higher pressure: if the cell is sound, declare the muscle's theta0_deg and "
               r"C10_MPa in \[muscle\] or widen \[muscle.tolerances\] theta0_deg")


def test_a_live_cell_on_a_muscle_slack_beyond_its_declaration_names_what_the_bound_took(
        tmp_path):
    # A muscle the toolkit does not know yet (bench_overforce.py's draw 7: a braid of 35.6 deg,
    # a rubber 1.48 times Silastic S) held at eps 0.218 on a sound, quiet cell: it is slack
    # from 1.5 bar down, so the cell holds its code while the monitor falls to 0.9 bar, where
    # the bound, taking the FE model's calibrated 32.99 +- 1 deg and Silastic S for the
    # undeclared braid and rubber, makes the force move 1.6 N. The stop is kept (a stuck cell
    # reads the same); its reason said only "check its cable" and now names what the bound
    # took and how to widen it, which lets the same run complete.
    from mkm.fem.materials import SILASTIC_S

    c = load_config(eps=0.2184).replace(sim={
        "model": "thickwall", "seed": 79, "hysteresis_fraction": 0.0773,
        "creep_fraction": 0.00215,
        "truth": {"theta0_deg": 35.578, "C10_MPa": 1.4824 * SILASTIC_S.C10_MPa,
                  "C01_MPa": 1.4824 * SILASTIC_S.C01_MPa}})
    result = acquire(c, out_root=tmp_path / "declared", **QUIET)
    assert result.status == "failed", result.reason
    assert re.fullmatch(
        r"force interlock: the load cell read [0-9.]+ V \(-0\.\d\d N\) unchanged from [0-9.]+ s "
        r"while the monitor fell from 1\.50 to 0\.90 bar, which moves the muscle's force by "
        r"1\.6 N or more at eps 0\.2184 \(\d+ ADC steps of 0\.24 N\): a stuck or disconnected "
        r"load cell, behind which the force limit is not watched; check its cable, amplifier "
        r"and supply" + BOUND_TAKES + "; vented", result.reason), result.reason
    widened = c.replace(muscle={"tolerances": {"theta0_deg": 4.0}})
    assert acquire(widened, out_root=tmp_path / "widened", **QUIET).status == "complete"


def test_a_quiet_load_cell_on_one_code_from_the_tare_is_stopped_as_the_pressure_rises(
        config, tmp_path):
    # A cell quieter than a step (0.3 mV rms) that sticks 1.5 s into a 2 s tare: its tare shows
    # two codes, strays less than a step (one code held 2 s cannot tell it stuck) and holds its
    # code only 0.5 s, so it passes. It recorded one force at every step up to 1.0 bar, the
    # force limit blind, and was failed only at the run's end. At eps 0 the muscle pulls from
    # its first millibars: the rise that must move its force 4 ADC steps stops the run there.
    from mkm.bench.worker import UNMOVED_CELL_STEPS

    c = config.replace(sim={"noise_V": 0.0003, "faults": {"loadcell_stuck_at_s": 1.5}})
    result = acquire(c, out_root=tmp_path, **QUIET)
    assert result.status == "failed" and result.exit_code == 1, result.reason
    said = re.fullmatch(r"force interlock: the load cell read 0\.0146 V \(-0\.0\d N\) unchanged "
                        r"from 1\.[0-9] s while the monitor rose from 0\.00 to (0\.[0-9]+) bar, "
                        r"which moves the muscle's force by ([0-9.]+) N or more at eps 0 "
                        r"\((\d+) ADC steps of 0\.24 N\): a stuck or disconnected load cell, "
                        r"behind which the force limit is not watched; check its cable, "
                        r"amplifier and supply" + BOUND_TAKES + "; vented", result.reason)
    assert said, result.reason
    high_bar, rise_N, steps = float(said[1]), float(said[2]), int(said[3])
    assert steps >= UNMOVED_CELL_STEPS and rise_N == pytest.approx(steps * STEP_N, abs=STEP_N)
    run = load_run(result.path)
    assert run.meta.steps_done == 0 and run.meta.vent_check["verified"]  # before the first step
    # the muscle pulled what the interlock said, and more: a live cell would have moved
    assert _truth_N(c, high_bar) > rise_N
    assert _tripped(run)["pressure_bar"] < c.sequence.pressures_bar[0]
    assert run.samples.query("phase == 'tare'")["loadcell_V"].nunique() == 2


def test_a_quiet_load_cell_stuck_at_the_top_stops_as_the_pressure_falls(config, tmp_path):
    # the quiet cell sticks at 9 s, at 353.8 N on the 1.0 bar step: the pressure fell to 0.5
    # bar and vented, the run went to its end, and the vent check blamed the regulator (`the
    # muscle still pulls ... a monitor that reports its command`). A force held on one code
    # while the pressure falls by what must move it is a stuck cell too: stopped there, and the
    # vent check names the cell
    c = config.replace(sim={"noise_V": 0.0003, "faults": {"loadcell_stuck_at_s": 9.0}})
    result = acquire(c, out_root=tmp_path, **QUIET)
    assert result.status == "failed" and result.exit_code == 4, result.reason
    said = re.match(r"force interlock: the load cell read 1\.8188 V \(\+353\.84 N\) unchanged "
                    r"from 9 s while the monitor fell from 1\.00 to (0\.[0-9]+) bar, which "
                    r"moves the muscle's force by ([0-9.]+) N or more at eps 0 ", result.reason)
    assert said, result.reason
    # 352 N (353.8 N less its zero's doubt) x (0.9 / 1.1 x 0.944 / (low + 0.04 + 0.016 low) - 1)
    # reaches 4 ADC steps below 0.72 bar (1.0 bar read 0.056 bar low by its accuracy)
    assert 0.6 < float(said[1]) < 0.72
    assert ("a load cell that does not change while the pressure falls is stuck or "
            "disconnected") in result.reason
    assert "a monitor that reports its command" not in result.reason
    run = load_run(result.path)
    assert run.meta.vent_check["doubted"] == "the load cell"
    assert _tripped(run)["step"] == 2  # on the way down, before the 0.5 bar step was held


def test_a_quiet_load_cell_stuck_under_a_manual_regulator_stops_at_the_pressure_typed(
        config, tmp_path):
    # with a hand regulator the pressure is the manometer's reading the operator types: the
    # 0.5 bar typed for the first step is the rise that must move the muscle's force
    c = config.replace(regulator={"kind": "manual"},
                       sim={"noise_V": 0.0003, "faults": {"loadcell_stuck_at_s": 1.5}})
    result = acquire(c, out_root=tmp_path, **QUIET)
    assert result.status == "failed" and result.exit_code == 1, result.reason
    assert re.match(r"force interlock: the load cell read 0\.0146 V \(-0\.0\d N\) unchanged from "
                    r"1\.\d s while the manometer's reading rose from 0\.00 to 0\.50 bar, which "
                    r"moves the muscle's force by ([0-9.]+) N or more at eps 0 ", result.reason)
    assert acquire(c.replace(sim={"faults": {"loadcell_stuck_at_s": None}}), out_root=tmp_path,
                   **QUIET).status == "complete"  # the live cell: no trip


def test_a_quiet_load_cell_under_a_hand_regulator_turned_slowly_is_not_called_stuck(
        tmp_path, monkeypatch):
    # The operator turns the hand regulator and types the manometer's reading once it settles,
    # as asked: the samples acquired meanwhile are read after it (the operator's). At eps 0.2
    # the muscle pulls nothing below its threshold, so the quiet live cell held its code over
    # the turn's first samples, which were judged at the 2.5 bar typed: `the load cell read
    # 0.0146 V (-0.01 N) unchanged from 1.3 s while the manometer's reading rose from 0.00 to
    # 2.50 bar, which moves the muscle's force by 67.0 N or more`, a live cell failed as stuck.
    # Their pressure lies anywhere between the two readings: the interlock judges the
    # samples after; a stuck cell is still stopped there
    from mkm.bench.sim import MANOMETER_RESOLUTION_BAR

    def settled(self, pressure_bar):
        self.bench.target_bar = pressure_bar
        for _ in range(300):  # the operator waits for the manometer, 30 s at most
            if abs(self.bench.pressure_bar - pressure_bar) < MANOMETER_RESOLUTION_BAR / 2:
                break
            self._acquire(1)
        return round(pressure_bar / MANOMETER_RESOLUTION_BAR) * MANOMETER_RESOLUTION_BAR

    monkeypatch.setattr(SimBackend, "set_manual_pressure", settled)
    c = load_config().replace(muscle={"eps": 0.2}, regulator={"kind": "manual"},
                              sim={"noise_V": 0.0003})
    live = acquire(c, out_root=tmp_path, **QUIET)
    assert live.status == "complete", live.reason
    run = load_run(live.path)
    assert (run.samples["phase"] == "operator").sum() > 100  # the turns' samples
    assert run.samples.query("phase == 'tare'")["loadcell_V"].nunique() <= 2  # quiet
    stuck = acquire(c.replace(sim={"faults": {"loadcell_stuck_at_s": 1.5}}), out_root=tmp_path,
                    **QUIET)
    assert stuck.status == "failed" and re.match(
        r"force interlock: the load cell read 0\.0146 V \(-0\.01 N\) unchanged from 1\.3 s "
        r"while the manometer's reading rose from 0\.00 to 2\.50 bar, which moves the muscle's "
        r"force by 67\.0 N or more at eps 0\.2 ", stuck.reason), stuck.reason


def test_a_quiet_load_cell_under_a_hand_regulator_read_before_it_settles_is_told_so(tmp_path):
    # The simulated operator types the manometer's reading as the regulator is turned, the
    # pressure still rising behind it (a real operator who types early does the same): at eps
    # 0.2 the muscle pulls nothing as its pressure nears the threshold, and the quiet live cell,
    # on one code, is judged at the reading typed. Not judging the samples after a reading
    # typed (for pressure_follow_s) would blind the interlock through pre-conditioning's hold,
    # as long: a cell stuck at 1.5 s was found at 1.25 bar in the staircase, not at 2.5 bar. The
    # trip stands, and its reason names the early reading beside the stuck cell
    c = load_config().replace(muscle={"eps": 0.2}, regulator={"kind": "manual"},
                              sim={"noise_V": 0.0003})
    live = acquire(c, out_root=tmp_path, **QUIET)
    assert live.status == "failed" and re.match(
        r"force interlock: the load cell read 0\.0146 V \(-0\.04 N\) unchanged from 3\.8 s "
        r"while the manometer's reading rose from 0\.00 to 2\.50 bar, which moves the muscle's "
        r"force by 67\.0 N or more at eps 0\.2 .*: a stuck or disconnected load cell, .*; check "
        r"its cable, amplifier and supply, or whether a reading was typed before the manometer "
        r"settled \(the pressure still on its way, the muscle below it\): type each once it "
        r"holds still" + BOUND_TAKES + "; vented", live.reason), live.reason
    electronic = acquire(c.replace(regulator={"kind": "electronic"},
                                   sim={"faults": {"loadcell_stuck_at_s": 1.5}}),
                         out_root=tmp_path, **QUIET)
    assert "force interlock: the load cell read" in electronic.reason
    assert "typed" not in electronic.reason  # an electronic regulator has no reading typed


def test_a_quiet_load_cell_on_one_code_under_a_slack_muscle_trips_nothing(config, tmp_path):
    # At eps 0.25 the muscle is slack up to 2.48 bar (its FE force), the thick-wall model at
    # the declared tolerances' weakest says so too: the steps at 0.5 and 1.0 bar read the
    # cell's zero. A quiet live cell is no stuck one there (complete); a stuck one is not
    # tripped either (nothing the data can show), and is failed at the end as before: one code
    # from before the first pressure to the end measured nothing.
    c = config.replace(muscle={"eps": 0.25}, sim={"noise_V": 0.0003})
    assert _truth_N(c, 1.0) == 0.0
    live = acquire(c, out_root=tmp_path, **QUIET)
    assert live.status == "complete", live.reason
    stuck = acquire(c.replace(sim={"faults": {"loadcell_stuck_at_s": 1.5}}), out_root=tmp_path,
                    **QUIET)
    assert stuck.status == "failed" and stuck.exit_code == 1, stuck.reason
    assert re.fullmatch(r"all 3 steps done, but the load cell read one ADC code \(0\.0[0-9]+ V\) "
                        r"from before the first pressure to the end, while the monitor read up "
                        r"to 1\.0[0-9] bar: a stuck or disconnected cell, or a muscle that never "
                        r"pulled one ADC step \(0\.24 N\); its forces measure nothing, and the "
                        r"force limit was blind", stuck.reason), stuck.reason
    for path in (live.path, stuck.path):
        assert not load_run(path).samples["flags"].str.contains("interlock").any()


def test_a_quiet_load_cell_on_one_code_under_a_hand_regulator_and_a_slack_muscle_fails(
        tmp_path):
    # as above with a hand regulator: the cell stuck from the tare read one code to the end
    # while the manometer's reading went up to 2.5 bar, and the run ended complete, exit 0
    # (the check asked for a pressure commanded, which a hand regulator never has)
    c = load_config().replace(muscle={"eps": 0.25}, regulator={"kind": "manual"},
                              sim={"noise_V": 0.0003})
    assert acquire(c, out_root=tmp_path, **QUIET).status == "complete"  # live, quiet
    stuck = acquire(c.replace(sim={"faults": {"loadcell_stuck_at_s": 1.5}}), out_root=tmp_path,
                    **QUIET)
    assert stuck.status == "failed" and stuck.exit_code == 1, stuck.reason
    assert re.fullmatch(r"all 19 steps done, but the load cell read one ADC code \(0\.0146 V\) "
                        r"from before the first pressure to the end, while the manometer's "
                        r"reading was up to 2\.50 bar: a stuck or disconnected cell, or a muscle "
                        r"that never pulled one ADC step \(0\.24 N\); its forces measure "
                        r"nothing, and the force limit was blind", stuck.reason), stuck.reason


def test_the_force_bounds_of_a_rise_hold_the_simulated_muscle(config):
    # what the stuck-cell interlock of a quiet cell takes the muscle to pull at least and at most
    # (preflight.force_bounds_N) holds the simulated FE muscle at every eps it pulls at, with
    # the sure half's margin: the weakest thick-wall force or more where that gives 2 N or more
    import numpy as np

    from mkm.bench.preflight import SURE_FRACTION, force_bounds_N
    from mkm.bench.sim import static_force_table

    for eps in (0.0, 0.05, 0.1, 0.15, 0.18, 0.2, 0.22, 0.25, 0.3):
        c = config.replace(muscle={"eps": eps})
        pressure_bar, least_N, most_N = force_bounds_N(c)
        truth_N = np.interp(pressure_bar, *static_force_table(c))
        assert (truth_N <= most_N + 1e-9).all(), eps
        weakest = least_N / SURE_FRACTION
        pulls = weakest >= 2.0
        assert (truth_N[pulls] >= weakest[pulls]).all(), eps


def test_a_quiet_load_cell_stuck_mid_run_under_a_slack_muscle_stops_as_it_must_pull(config,
                                                                                      tmp_path):
    # 0.8 mV rms of noise: the tare spreads 0.72 mV, less than the 1.22 mV step. Stuck at 4 s,
    # in the 0.25 bar step at eps 0.18 (the muscle slack), it read -0.04 N at 1.5 bar, where
    # the muscle pulls 82 N, and the run was failed only at its end, the force limit blind
    # through 1.5 bar. The rise from 0.25 bar past the muscle's threshold (0.81 bar) stops it
    # as soon as its force must have moved 4 ADC steps, before the 1.5 bar step is reached.
    from mkm.bench.worker import UNMOVED_CELL_STEPS

    c = config.replace(muscle={"eps": 0.18}, sequence={"pressures_bar": (0.25, 1.5)},
                       sim={"noise_V": 0.0008})
    live = acquire(c, out_root=tmp_path, **QUIET)
    assert live.status == "complete", live.reason  # no false trip on the live cell
    assert load_run(live.path).steps["force_N_mean"].iloc[1] == pytest.approx(82, abs=2)
    notes: list[str] = []
    stuck = acquire(c.replace(sim={"faults": {"loadcell_stuck_at_s": 4.0}}), out_root=tmp_path,
                    notify=notes.append)
    assert stuck.status == "failed" and stuck.exit_code == 1, stuck.reason
    # said at the tare, before any pressure
    assert re.fullmatch(r"warning: the load cell spreads 0\.[67]\d mV rms at 0 bar \(0\.1\d N\), "
                        r"less than one ADC step \(1\.22 mV\): one code held 2 s cannot tell it "
                        r"stuck from quiet, so a cell that sticks is found only once the "
                        r"pressure rises or falls by what must move the muscle's force 4 ADC "
                        r"steps \(never where it stays slack\), the force limit blind meanwhile",
                        notes[1]), notes
    said = re.fullmatch(r"force interlock: the load cell read 0\.0146 V \(-0\.04 N\) unchanged "
                        r"from 3\.8 s while the monitor rose from 0\.2[45] to ([01]\.[0-9]+) bar, "
                        r"which moves the muscle's force by ([0-9.]+) N or more at eps 0\.18 "
                        r"\((\d+) ADC steps of 0\.24 N\): a stuck or disconnected load cell, .*; "
                        r"vented", stuck.reason)
    assert said, stuck.reason
    high_bar, rise_N = float(said[1]), float(said[2])
    assert int(said[3]) >= UNMOVED_CELL_STEPS
    assert 0.81 < high_bar < 1.5 and _truth_N(c, high_bar) > rise_N  # past the threshold
    run = load_run(stuck.path)
    assert run.meta.tare["std_V"] < 20 / 2 ** 14  # less than a step
    assert run.meta.steps_done == 1 and _tripped(run)["step"] == 1  # in the rise to 1.5 bar


def test_a_quiet_load_cell_stuck_under_a_pulling_muscle_stops_as_the_pressure_rises(config,
                                                                                     tmp_path):
    # the same quiet cell stuck at 6 s, at 184.6 N in the 0.5 bar step: it read 184.6 N through
    # the 1.0 bar step, the vent check the first to name it. The force it read as it stuck is
    # the muscle's at 0.5 bar: one that grows at least in proportion to its pressure has moved
    # 4 ADC steps by about 0.73 bar (the monitor's accuracy, 0.04 bar, and the braid's friction
    # taken off): stopped there; the vent check still names the cell
    c = config.replace(sim={"noise_V": 0.0008, "faults": {"loadcell_stuck_at_s": 6.0}})
    result = acquire(c, out_root=tmp_path, **QUIET)
    assert result.status == "failed" and result.exit_code == 4, result.reason
    said = re.match(r"force interlock: the load cell read 0\.9558 V \(\+184\.56 N\) unchanged "
                    r"from 5\.9 s while the monitor rose from 0\.50 to (0\.[0-9]+) bar, which "
                    r"moves the muscle's force by ([0-9.]+) N or more at eps 0 ", result.reason)
    assert said, result.reason
    high_bar = float(said[1])
    # 184.6 N less its zero's doubt (1.6 N), times 0.95 x high / peak - 1 >= 4 steps (creep
    # taken off), with the peak since the vent, 0.50 bar, raised by the monitor's accuracy (0.04
    # + 0.016 x 0.50) and high lowered by its own: 0.64 bar, the medians of the rise's samples
    # up to 0.07 bar behind (0.72 to 0.80 bar with the friction taken off both ends)
    assert 0.64 < high_bar < 0.72
    assert ("a load cell that does not change while the pressure falls is stuck or "
            "disconnected") in result.reason
    run = load_run(result.path)
    assert run.meta.vent_check["doubted"] == "the load cell"
    assert run.meta.steps_done == 1 and _tripped(run)["step"] == 1


def test_a_quiet_load_cell_stuck_on_the_way_up_stops_before_the_next_step(config, tmp_path):
    # The packaged staircase (pre-conditioning to 2.5 bar and back to 0, steps of 0.25 bar, a
    # down-sweep): the quiet cell sticks at 50 s, at 366 N on the 1.0 bar step. The force read
    # times the pressures' ratio, friction taken off both ends (0.9 / 1.1), needed about a fifth
    # more pressure: it tripped on the 1.5 bar step at 1.41 bar, 14.5 s later, the force limit
    # blind over 156 N of the muscle's rise. Risen from the vent to its peak, 1.0 bar, the
    # muscle's force is held by its friction at most at what that peak pulled up, so a
    # pressure above the peak pulls it up again (creep's 5 % taken off): stopped in the rise to
    # 1.25 bar, under 6 s after it stuck
    c = load_config().replace(sim={"noise_V": 0.0008, "faults": {"loadcell_stuck_at_s": 50.0}})
    result = acquire(c, out_root=tmp_path, **QUIET)
    said = re.match(r"force interlock: the load cell read 1\.8811 V \(\+366\.02 N\) unchanged "
                    r"from 50 s while the monitor rose from 1\.00 to (1\.[0-9]+) bar, which "
                    r"moves the muscle's force by ([0-9.]+) N or more at eps 0 ", result.reason)
    assert said, result.reason
    high_bar, rise_N = float(said[1]), float(said[2])
    # 364 N (366 N less its zero's doubt) x (0.95 x (high - 0.04 - 0.016 high) / 1.056 - 1)
    # reaches 4 ADC steps at 1.17 bar
    assert 1.17 <= high_bar < 1.25 and _truth_N(c, high_bar) - _truth_N(c, 1.0) > rise_N
    run = load_run(result.path)
    tripped = _tripped(run)
    assert tripped["step"] == 4 and tripped["set_pressure_bar"] == 1.25
    assert tripped["time_s"] - 50.0 < 6.0


def test_a_load_cell_stuck_late_in_the_tare_trips_two_seconds_after_it_stuck(config,
                                                                             tmp_path):
    # Stuck from 4 s of a 5 s tare (1 s of it on one code): the interlock counted its 2 s from
    # the tare's end, so the pre-conditioning's 2.5 bar rose to 2.1 bar with the force limit
    # blind until 7.0 s. It counts from where the code was first read: 6.0 s.
    from mkm.bench.worker import STUCK_CELL_S

    # (at eps 0.28, slack up to 2.5 bar: the pre-conditioning's rise moves no force, and the
    # interlock of a quiet cell has nothing to trip on)
    c = config.replace(muscle={"eps": 0.28}, sequence={"tare_s": 5.0, "preconditioning_cycles": 1},
                       sim={"faults": {"loadcell_stuck_at_s": 4.0}})
    result = acquire(c, out_root=tmp_path, **QUIET)
    assert result.status == "failed" and re.match(
        r"force interlock: the load cell read [0-9.]+ V \([0-9.-]+ N\) unchanged for 2\.0 s",
        result.reason), result.reason
    run = load_run(result.path)
    tripped = run.samples[run.samples["flags"].str.contains("interlock")]
    assert tripped["time_s"].iloc[0] == pytest.approx(4.0 + STUCK_CELL_S, abs=0.11)


def test_a_monitor_frozen_above_the_threshold_is_named_by_the_load_cell(config, tmp_path):
    # The monitor's output freezes at its reading from 20 s (on the last step, 0.5 bar). The
    # vent empties the muscle, its force falls from 194 N to nothing, and the check, the
    # monitor still at 0.5 bar, blamed the regulator: "a regulator that sticks, or one
    # exhausting ... set safety.vent_timeout_s". The same reading with the force gone is no
    # pressure held: the monitor is named, still VENT BY HAND, and no setting is offered.
    backend = SimBackend(config)
    bench, read = backend.bench, backend.read

    def frozen_from_20_s(n, timeout):
        if backend._index >= 200 and bench.monitor_stuck_bar is None:
            bench.monitor_stuck_bar = bench.sensor_bar(bench.pressure_bar)
        return read(n, timeout)

    backend.read = frozen_from_20_s
    result = BenchRun(config, backend, tmp_path, handle_signals=False, **QUIET).execute()
    assert result.status == "failed" and result.exit_code == 4 and result.manual_vent_required
    said = re.search(r"the monitor still reads ([0-9.]+) bar [0-9.]+ s after the vent, as it "
                     r"read ([0-9.]+) bar before it, but the load cell reads (-?[0-9.]+) N "
                     r"against ([0-9.]+) N before the vent: the muscle let go while the monitor "
                     r"did not move, so the monitor no longer reads the pressure \(its output, "
                     r"wire or input stuck\); check the monitor", result.reason)
    assert said, result.reason
    after_bar, before_bar, after_N, before_N = map(float, said.groups())
    assert after_bar == pytest.approx(before_bar, abs=0.01)
    assert before_bar == pytest.approx(0.5, abs=0.02)  # the last step's, when it froze
    assert abs(after_N) < 1.0 < 150.0 < before_N  # slack after; 0.5 bar's force before
    assert "safety.vent_timeout_s" not in result.reason
    assert load_run(result.path).meta.vent_check["doubted"] == "the monitor"
    assert bench.pressure_bar < config.safety.vent_below_bar  # the truth: vented


class _Supply(SimBackend):
    """A regulator whose pressure cannot pass ``ceiling_bar`` (its supply) and, while
    pressurised, cannot fall below ``floor_bar`` (an exhaust that only opens fully at 0)."""

    def __init__(self, config, ceiling_bar=10.0, floor_bar=0.0):
        super().__init__(config)
        set_command = self.bench.set_command_volts

        def limited(volts):
            set_command(volts)
            if self.bench.target_bar > 0:
                self.bench.target_bar = min(max(self.bench.target_bar, floor_bar), ceiling_bar)

        self.bench.set_command_volts = limited


@pytest.mark.parametrize("supply, read_bar", [({"ceiling_bar": 0.3}, 0.3),
                                              ({"floor_bar": 0.8}, 0.8)])
def test_a_monitor_that_read_pressure_before_the_vent_verifies_it(config, tmp_path, supply,
                                                                  read_bar):
    # the interlock tripped on a pressure off its command that the monitor did read: below it
    # (a supply of 0.3 bar for 0.5 bar commanded) or above it (a regulator that holds at least
    # 0.8 bar while pressurised); the monitor's fall after the vent verifies the vent
    backend = _Supply(config, **supply)
    result = BenchRun(config, backend, tmp_path, handle_signals=False, **QUIET).execute()
    assert "pressure interlock: the regulator does not follow" in result.reason
    assert result.status == "aborted" and result.exit_code == 1, result.reason
    assert not result.manual_vent_required and "VENT BY HAND" not in result.reason
    check = load_run(result.path).meta.vent_check
    assert check["verified"] and check["unfollowed_bar"] is None
    # the pressure the regulator delivered, within the monitor's 1 mV noise and 1.2 mV steps
    measured = re.search(r"([0-9.]+) bar measured against 0\.5 bar commanded", result.reason)
    assert float(measured.group(1)) == pytest.approx(read_bar, abs=0.005)
    assert backend.bench.pressure_bar < config.safety.vent_below_bar  # the truth: vented


def test_a_monitor_reading_below_a_zero_command_is_judged_by_its_reading(config, tmp_path):
    # a sensor 0.08 bar low trips a 0.05 bar tolerance during the tare, 0 bar commanded: it
    # is judged by its reading, not as a monitor that read nothing of a pressure ("may still
    # hold 0 bar"); with no tare done, that reading is 0.08 bar below the zero its
    # configuration declares, beyond the declared 0.04 bar: the tare would have refused it
    # (beyond vent_below_bar), and a vent it reads proves nothing (0.04 bar read with 0.12 bar
    # held)
    c = config.replace(sequence={"tare_s": 8.0}, safety={"pressure_tolerance_bar": 0.05},
                       sim={"truth": {"monitor_offset_bar": -0.08}})
    result = acquire(c, out_root=tmp_path, **QUIET)
    assert "against 0 bar commanded for more than 5 s" in result.reason
    assert "below 0 bar by more than the zero error its configuration declares" in result.reason
    assert "read nothing" not in result.reason and "proves nothing" not in result.reason
    assert result.status == "failed" and result.exit_code == 4, result.reason
    check = load_run(result.path).meta.vent_check
    assert not check["verified"] and check["unfollowed_bar"] is None


def test_a_monitor_whose_zero_drifted_low_after_the_tare_verifies_no_vent(config, tmp_path):
    # The tare reads the monitor's zero at 0.000 bar; then its input's ground shifts by
    # -0.09 V (-0.09 bar), within the follow interlock's 0.15 bar of every command. The vent
    # check took its first reading below 0.05 bar (0.022 bar) as a verified vent, exit 0, while
    # the muscle held 0.11 bar; the reading then settles at -0.09 bar, below the tare's zero:
    # a drifted zero, so the reading tells nothing of the muscle
    backend = SimBackend(config)
    read = backend.read

    def ground_shifted(n, timeout):
        block = read(n, timeout)
        if block.first_index < 20:  # the tare's 2 s read the true zero
            return block
        volts = block.volts.copy()
        volts[:, 1] -= 0.09  # 1 V per bar: 1-5 V over 4 bar
        return dataclasses.replace(block, volts=volts)

    backend.read = ground_shifted
    result = BenchRun(config, backend, tmp_path, handle_signals=False, **QUIET).execute()
    run = load_run(result.path)
    assert result.status == "failed" and result.exit_code == 4 and result.manual_vent_required
    assert abs(run.meta.tare["monitor_vented_bar"]) < 0.002
    assert "below the 0.000 bar it read vented at the tare by more than its noise" in result.reason
    assert result.reason.endswith("VENT BY HAND (the regulator may still hold 0.5 bar)")
    check = run.meta.vent_check
    # it settles at the shifted zero, within the monitor's 1 mV noise and 1.2 mV steps
    assert not check["verified"] and check["pressure_bar"] == pytest.approx(-0.09, abs=0.005)
    # the truth when the first reading fell below 0.05 bar: 0.05 + 0.09 = 0.14 bar or less,
    # more than 0.05 bar (the reading at a sample is the pressure it read plus the shift)
    vent_rows = [r for r in run.samples.itertuples() if r.phase == "vent"]
    first = next(k for k, r in enumerate(vent_rows) if r.pressure_bar < 0.05)
    held = 0.5 * math.exp(-(first + 1) * 0.1 / 0.4)  # from the 0.5 bar step, tau 0.4 s
    assert vent_rows[first].pressure_bar == pytest.approx(held - 0.09, abs=0.005)
    assert held > 0.1


def test_mkm_vent_does_not_verify_with_a_monitor_read_low(config, monkeypatch):
    # `mkm vent` has no tare: the check took three readings in a row below 0.05 bar as a
    # verified vent. The muscle holds 0.5 bar and the monitor's input reads 0.09 bar low (its
    # ground shifted): it read below 0.05 bar from 0.14 bar in the muscle, and the third
    # reading verified the vent with 0.5 exp(-0.7/0.4) = 0.087 bar held. Without a tare its
    # reading must settle too, and not below the zero its configuration declares by more than
    # the declared zero error (0.04 bar) and its noise.
    import mkm.bench.procedures as procedures
    from mkm.bench.backend import BenchError

    class HeldAndShifted(SimBackend):
        def start(self):
            super().start()
            self.bench.pressure_bar = 0.5  # left by a run: the vent exhausts it

        def read(self, n_samples, timeout_s):
            block = super().read(n_samples, timeout_s)
            volts = block.volts.copy()
            volts[:, 1] -= 0.09  # 1 V per bar: 1-5 V over 4 bar
            return dataclasses.replace(block, volts=volts)

    backends = []
    monkeypatch.setattr(procedures, "make_backend",
                        lambda c, clock: backends.append(HeldAndShifted(c)) or backends[0])
    with pytest.raises(BenchError, match=r"the monitor settled at -0\.0[89]\d bar, below 0 bar "
                                         r"by more than the zero error its configuration "
                                         r"declares \(0\.04 bar, regulator\.monitor_accuracy_bar"
                                         r"\) .*its zero is off low.*VENT BY HAND"):
        procedures.vent(config)
    # the truth: vented by now (the reading settled), but nothing read could tell it
    assert backends[0].bench.pressure_bar < config.safety.vent_below_bar


def test_a_run_whose_tare_read_no_zero_still_asks_for_a_fall_after_the_vent(config, tmp_path):
    # The tare reads the monitor still falling (0.005 bar a sample: no settled zero), then the
    # monitor freezes at 0 bar whatever the pressure; one sample of noise (+0.06 V, 0.06 bar,
    # just above the 0.05 bar threshold) comes as Ctrl-C stops the run 2.5 s into the 0.5 bar
    # step. Without the tare's zero no fall was asked for: the frozen 0 bar verified the vent
    # (exit 130) with 0.11 bar in the muscle. The readings' own noise judges the fall instead.
    backend = SimBackend(config)
    read = backend.read

    def falling_tare_frozen_then_spike(n, timeout):
        block = read(n, timeout)
        volts = block.volts.copy()
        if block.first_index < 20:  # the tare's 2 s: 0.1 bar falling to 0
            volts[:, 1] += 0.1 - 0.005 * block.first_index  # 1 V per bar: 1-5 V over 4 bar
        else:
            volts[:, 1] = 1.0  # frozen at 0 bar
        if block.first_index == 45:
            run.request_stop()
            volts[:, 1] += 0.06
        return dataclasses.replace(block, volts=volts)

    backend.read = falling_tare_frozen_then_spike
    run = BenchRun(config, backend, tmp_path, handle_signals=False, **QUIET)
    result = run.execute()
    run_ = load_run(result.path)
    assert run_.meta.tare["monitor_vented_settled"] is False
    assert result.status == "failed" and result.exit_code == 4 and result.manual_vent_required
    assert "with 0.5 bar commanded before the vent and did not fall after it" in result.reason
    assert result.reason.endswith("VENT BY HAND (the regulator may still hold 0.5 bar)")
    assert not run_.meta.vent_check["verified"]
    # the truth: six 0.1 s samples of exhaust (tau 0.4 s) from 0.5 bar as the check settled
    assert backend.bench.pressure_bar == pytest.approx(0.5 * math.exp(-1.5), abs=1e-3)


def test_the_vent_check_reads_from_a_zero_below_0_bar(config, tmp_path):
    # the monitor's input reads 0.04 bar low from the start (the tare's zero: -0.04 bar), and
    # the regulator's exhaust leaves 0.08 bar in the muscle once it was pressurised: the monitor
    # reads 0.04 bar, below 0.05 bar, which verified the vent; from its zero that is 0.08 bar
    backend = SimBackend(config)
    read, set_command = backend.read, backend.bench.set_command_volts

    def shifted(n, timeout):
        block = read(n, timeout)
        volts = block.volts.copy()
        volts[:, 1] -= 0.04  # 1 V per bar: 1-5 V over 4 bar
        return dataclasses.replace(block, volts=volts)

    def exhaust_left_open(volts):
        set_command(volts)
        if backend._index >= 20:  # after the tare's 2 s
            backend.bench.target_bar = max(backend.bench.target_bar, 0.08)

    backend.read, backend.bench.set_command_volts = shifted, exhaust_left_open
    result = BenchRun(config, backend, tmp_path, handle_signals=False, **QUIET).execute()
    run = load_run(result.path)
    assert run.meta.tare["monitor_vented_bar"] == pytest.approx(-0.04, abs=0.003)
    assert result.status == "failed" and result.exit_code == 4, result.reason
    check = run.meta.vent_check
    # 0.05 bar from the -0.04 bar zero; the reading 0.08 - 0.04 bar, within noise and a step
    assert not check["verified"] and check["below_bar"] == pytest.approx(0.01, abs=0.003)
    assert check["pressure_bar"] == pytest.approx(0.04, abs=0.005)
    assert backend.bench.pressure_bar == pytest.approx(0.08, abs=1e-3)  # the truth


def test_below_command_weighs_a_verified_check_by_what_the_monitor_read_before_it():
    from mkm.bench.vent import VentCheck, below_command

    verified = VentCheck(True, 0.01, 0.05, 0.3, "monitor")
    assert below_command(verified, 0.3, 0.5) is verified  # it read pressure, then fell
    judged = below_command(verified, 0.0, 0.5)
    assert not judged.verified and judged.unfollowed_bar == 0.5
    assert judged.pressure_bar == 0.01  # the reading is kept as read
    assert "proves nothing" in judged.describe()
    unverified = VentCheck(False, 0.4, 0.05, 10.1, "monitor")
    assert below_command(unverified, 0.0, 0.5) is unverified  # said as it is
    operator = VentCheck(True, 0.0, 0.05, 0.0, "operator")
    assert below_command(operator, 0.0, 0.5) is operator  # a manometer read by the operator


def test_force_per_bar_is_the_muscles_slope_where_it_pulls():
    from mkm.bench.storage import StepRecord
    from mkm.bench.vent import force_per_bar

    # F = 190 N/bar (p - 0.45 bar) above the threshold, the cell's zero (0 N) below it; the
    # steps up to 1 bar and down, repeated at the top: the slopes where both steps pull are
    # 190 N/bar, the one across the threshold (9.5 N over 0.25 bar) and none from the repeat
    def row(k, p, force):
        return StepRecord(k, "up", 0, p, p, force, 0.35, 50, True, 4.0, 9.0 * k, 9.0 * k + 9.0)

    pressures = (0.25, 0.5, 0.75, 1.0, 1.0, 0.75, 0.5, 0.25)
    steps = [row(k, p, 190.0 * max(p - 0.45, 0.0)) for k, p in enumerate(pressures)]
    assert force_per_bar(steps, 2.2) == pytest.approx(190.0)
    assert force_per_bar(steps[:2], 2.2) is None  # 9.5 N at 0.5 bar, nothing above it


def test_force_per_bar_is_never_negative_on_a_zero_drifting_under_a_slack_muscle():
    from mkm.bench.storage import StepRecord
    from mkm.bench.vent import force_per_bar

    # a slack down-sweep below the 0.45 bar threshold while the cell's zero drifts up 0.5 N a
    # step, above the 2.2 N noise: the slopes are 0.5 N / -0.1 bar = -5 N/bar, and were
    # returned as the muscle's force per bar. A muscle's force never falls as its pressure
    # rises: none is found
    def row(k, p, force):
        return StepRecord(k, "down", 0, p, p, force, 0.35, 50, True, 4.0, 9.0 * k, 9.0 * k + 9.0)

    steps = [row(k, p, 3.0 + 0.5 * k) for k, p in enumerate((0.4, 0.3, 0.2, 0.1))]
    assert force_per_bar(steps, 2.2) is None
    flat = [row(k, p, 3.0) for k, p in enumerate((0.4, 0.3, 0.2))]  # a zero slope: none either
    assert force_per_bar(flat, 2.2) is None


def test_a_force_kept_with_no_force_per_bar_says_the_zero_may_have_moved_and_what_to_do():
    # A slack muscle (below its threshold at every step: no force per bar) on a load-cell zero
    # drifting 4 N/min reads 3.7 N before the vent and 4.0 N after: no check can tell it from
    # a muscle a stuck exhaust holds, so VENT BY HAND stays. The message said only "the muscle
    # still pulls ... check the regulator and the load cell", of a muscle never seen pulling:
    # it names the zero moved as the other cause and what to look at.
    from mkm.bench.vent import VentCheck, still_pulling

    verified = VentCheck(True, 0.005, 0.05, 1.8, "monitor")
    judged = still_pulling(verified, 3.7, 4.0, 2.2, 0.25)
    assert not judged.verified and judged.unfollowed_bar == 0.25
    assert judged.doubted == "the monitor or the load cell"
    assert judged.problem == (
        "the monitor read 0.005 bar, but the load cell still reads 4.0 N against 3.7 N before "
        "the vent (more than 50% of it), and the run measured no force per bar (the muscle "
        "pulled at no two successive steps): a muscle that still pulls (a monitor that reports "
        "its command or is stuck, with an exhaust that did not open) reads so, and so does a "
        "slack one on a load-cell zero moved 3.7 N since the tare (an amplifier warming up); "
        "look at the muscle: hanging slack, it is vented and the zero moved (power the amplifier "
        "up well before the run); pulling, check the regulator and the load "
        "cell")


def test_a_force_kept_after_the_vent_is_judged_by_what_the_threshold_pressure_makes():
    from mkm.bench.vent import VentCheck, still_pulling

    # a load cell of noise 2.2 N on a muscle of 190 N/bar, the vent threshold 0.05 bar: 9.5 N
    # is what 0.05 bar above the muscle's threshold makes, 11.7 N with the noise
    verified = VentCheck(True, 0.003, 0.05, 1.8, "monitor")
    slack = still_pulling(verified, 11.5, 11.6, 2.2, 0.25, per_bar_N=190.0)
    assert slack is verified  # a slack muscle on a zero moved by 11.5 N, or one barely pulling
    pulls = still_pulling(verified, 12.0, 11.9, 2.2, 0.25, per_bar_N=190.0)
    assert not pulls.verified and "the muscle still pulls" in pulls.problem
    # with no force per bar from the run, any force above the noise is the muscle's
    assert not still_pulling(verified, 3.8, 4.3, 2.2, 0.25).verified
    # a muscle that let go (the force fell below half of it) verifies, whatever the slope
    assert still_pulling(verified, 214.6, 3.0, 2.2, 0.5, per_bar_N=190.0) is verified


# 2. one owner per bench --------------------------------------------------------------------

def test_a_second_command_on_a_held_bench_refuses_with_the_holder(config, tmp_path, mkm_cli):
    import os

    with BenchOwner("sim-Dev1", "acquire"):
        with pytest.raises(BenchBusy, match=rf"bench sim-Dev1 is in use by pid {os.getpid()} "
                                            r"\(`mkm acquire`, started 20"):
            acquire(config, out_root=tmp_path, **QUIET)
        for argv in (["tare", "--backend", "sim"],
                     ["calibrate-loadcell", "--masses", "0,1", "--backend", "sim"],
                     ["acquire", "--out", str(tmp_path), "--no-progress"], ["check"]):
            code, _, err = mkm_cli(argv)
            assert code == 1 and f"in use by pid {os.getpid()}" in err, argv
    assert not list(tmp_path.glob("*_*"))  # nothing recorded, nothing opened


class _Slow(SimBackend):
    """Virtual clock, but each read after the first step's command takes 20 ms of wall time,
    so another thread can act while the run is pressurised."""

    def __init__(self, config, pressurised):
        super().__init__(config)
        self.pressurised = pressurised

    def read(self, n_samples, timeout_s):
        if any(volts > 0 for _, volts in self.commands):
            self.pressurised.set()
            time.sleep(0.02)
        return super().read(n_samples, timeout_s)


def test_vent_during_a_run_asks_the_run_to_stop(config, tmp_path, mkm_cli):
    pressurised, results = threading.Event(), []
    run = BenchRun(config, _Slow(config, pressurised), tmp_path, handle_signals=False, **QUIET)
    worker = threading.Thread(target=lambda: results.append(run.execute()))
    worker.start()
    assert pressurised.wait(30)
    code, out, err = mkm_cli(["vent", "--backend", "sim"])
    worker.join(30)
    (result,) = results
    assert result.status == "aborted" and "stopped by `mkm vent`" in result.reason
    assert result.exit_code == 0 or result.exit_code == 1
    assert code == 0 and out.startswith("vented: ") and "asked the run holding the bench" in err
    assert load_run(result.path).meta.vent_check["verified"]


# 3. interlocks a configuration cannot switch off ---------------------------------------------

@pytest.mark.parametrize("section, values, message", [
    ("safety", {"pressure_tolerance_bar": 100.0}, r"safety\.pressure_tolerance_bar=100 is "
     r"invalid: expected 0 to 0\.4 bar \(a tenth of regulator\.full_scale_bar=4\)"),
    ("safety", {"pressure_follow_s": 1e9}, r"safety\.pressure_follow_s=1e\+09 is invalid: "
     r"expected 1 to 10 s"),
    ("safety", {"tare_max_std_N": 1e9}, r"safety\.tare_max_std_N=1e\+09 is invalid: expected 0 "
     r"to 19\.6133 N \(1 % of loadcell\.capacity_N=1961\.33\)"),
    ("loadcell", {"capacity_N": 1e300, "sensitivity_N_per_V": 1e300},
     r"loadcell\.capacity_N=1e\+300 is invalid: expected 0 to 100000 N"),
    ("muscle", {"D0_mm": 1e-300}, r"muscle\.D0_mm=1e-300 is invalid"),
    ("muscle", {"L0_mm": 1e-9}, r"muscle\.L0_mm=1e-09 is invalid"),
])
def test_interlocks_and_geometry_are_bounded(section, values, message):
    with pytest.raises(ValueError, match=message):
        load_config().replace(**{section: values})


def test_a_cell_the_muscle_overloads_is_a_warning_from_check(tmp_path, mkm_cli):
    text = load_config().text.replace("capacity_N = 1961.33", "capacity_N = 300") \
        .replace("sensitivity_N_per_V = 196.133", "sensitivity_N_per_V = 30") \
        .replace("tare_max_std_N = 5.0", "tare_max_std_N = 2.0") \
        .replace("tare_max_shift_N = 100.0", "tare_max_shift_N = 20.0")
    (tmp_path / "small.toml").write_text(text)
    code, out, err = mkm_cli(["check", "--config", str(tmp_path / "small.toml")])
    # Equation 2 on the braid's diameter at the strongest muscle of the default tolerances
    # (D0 30.3, t0 3.1: 36.5 mm; the FE model's calibrated 33.0 deg less 1 deg; eps 0): 1079 N
    # at 2.5 bar against an interlock at 270 N, reached from 0.75 bar on
    assert code == 0 and "warning" not in out
    assert err.count("mkm check: warning:") == 1
    assert "may develop 1079 N at 2.5 bar (Equation 2 on the braid's diameter, at its declared " \
        "tolerances' strongest), beyond the force interlock at 270 N (0.9 x " \
        "loadcell.capacity_N=300) from 0.75 bar: pre-conditioning to 2.5 bar stops the run " \
        "before its first step; use a load cell of at least 1199 N" in err


def test_a_thick_walled_tube_that_overloads_its_cell_is_warned_of(tmp_path, mkm_cli):
    """A 5 mm tube with a 0.8 mm wall at 38 deg up to 8 bar on a 50 N cell (interlock 45 N):
    the FE model's force at eps 0 is Equation 2 on the braid's diameter, 62 N at 8 bar, which
    pre-conditioning reaches before any step; Equation 2 on the inner diameter says 36 N, and
    check called the bench ready while acquire stopped at the interlock."""
    from mkm.bench.preflight import expected_force_N
    from mkm.fem import Axisym
    from mkm.fem.eq2 import chou_hannaford

    tiny = load_config().replace(
        muscle={"id": "tiny", "D0_mm": 5.0, "t0_mm": 0.8, "L0_mm": 50.0, "theta0_deg": 38.0},
        loadcell={"capacity_N": 50.0, "sensitivity_N_per_V": 5.0},
        regulator={"max_pressure_bar": 8.0, "full_scale_bar": 10.0,
                   "monitor_accuracy_bar": 0.1},
        safety={"tare_max_std_N": 0.2, "tare_max_shift_N": 2.0, "vent_below_bar": 0.15},
        settle={"max_force_std_N": 0.06, "max_force_slope_N_per_s": 0.04},
        sequence={"pressures_bar": tuple(0.5 * k for k in range(1, 17))})
    fe_N = float(Axisym(mesh="coarse", theta0_deg=38.0, L0_mm=50.0)
                 .predict([8.0], 5.0, 0.8, 0.0).force_N[0])
    assert expected_force_N(tiny, 8.0) == pytest.approx(fe_N, rel=1e-6) == pytest.approx(62.31,
                                                                                     abs=0.01)
    assert float(chou_hannaford(8.0, 5.0, 0.0, 38.0)) < tiny.force_limit_N < fe_N
    (tmp_path / "tiny.toml").write_text(tiny.effective_text())
    code, _, err = mkm_cli(["check", "--config", str(tmp_path / "tiny.toml")])
    # at the default tolerances' strongest: D0 5.3, t0 0.9 (a 7.1 mm braid), 37 deg, eps 0
    assert float(chou_hannaford(8.0, 7.1, 0.0, 37.0)) == pytest.approx(79.9, abs=0.05)
    assert code == 0 and "may develop 80 N at 8 bar (Equation 2 on the braid's diameter" in err
    assert "beyond the force interlock at 45 N (0.9 x loadcell.capacity_N=50) from 5 bar: " \
        "pre-conditioning to 8 bar stops the run before its first step; use a load cell of at " \
        "least 89 N" in err
    code, _, err = mkm_cli(["check", "--config", str(tmp_path / "tiny.toml"), "--pressures",
                            "0.5:4:0.5"])
    assert code == 0 and "warning" not in err  # 40 N at most at 4 bar, 40 % of the capacity


def test_a_cell_far_larger_than_the_muscle_is_a_warning_from_check(tmp_path, mkm_cli):
    """The same 5 mm tube on the packaged 1961 N cell: its largest force, 62.3 N at 8 bar, is
    3.2 % of the capacity, below the tenth under which a cell is the wrong size (its noise, ADC
    step, non-linearity and zero drift are fractions of its capacity); check called it ready
    without a word while its expected uncertainty reached tens of % of the force at the lowest
    steps. The cell that suits it: from what the interlock needs (88.8 N, the strongest muscle
    over 0.9) to ten times the force."""
    tiny = load_config().replace(
        muscle={"id": "tiny", "D0_mm": 5.0, "t0_mm": 0.8, "L0_mm": 50.0, "theta0_deg": 38.0},
        regulator={"max_pressure_bar": 8.0, "full_scale_bar": 10.0,
                   "monitor_accuracy_bar": 0.1},
        safety={"vent_below_bar": 0.15},
        sequence={"pressures_bar": tuple(0.5 * k for k in range(1, 17))})
    (tmp_path / "tiny.toml").write_text(tiny.effective_text())
    code, out, err = mkm_cli(["check", "--config", str(tmp_path / "tiny.toml")])
    # and the packaged settle and noise limits, sized for the 30 mm muscle (preflight's own),
    # and the simulated amplifier's zero, 2.93 N from the configured one, read at rest
    assert code == 0 and err.count("mkm check: warning:") == 3
    assert err.count("warning: the settle and noise limits are sized for a stronger muscle") == 1
    assert err.count("warning: the tare's zero is +2.93 N from loadcell.offset_V=0 V, 75 % of "
                     "the 3.9 N the muscle pulls at the lowest step, 0.5 bar") == 1
    # at 0.5 bar, Equation 2 on the 6.6 mm braid: 3.89 N (62.3 N / 16), one ADC step of 0.24 N
    # (1.22 mV x 196 N/V) 6.1 % of it, the non-linearity's 0.98 N (0.05 % of 1961 N) 25 %
    assert "the muscle develops at most about 62.3 N at 8 bar (Equation 2 on the braid's " \
        "diameter at eps 0), 3.2 % of loadcell.capacity_N=1961.33: the cell's noise, ADC step " \
        "and data-sheet errors, fractions of its capacity, weigh on every force (`mkm check`'s " \
        "expected uncertainty): at the lowest step, 0.5 bar, the muscle pulls about 3.9 N, of " \
        "which one ADC step (0.24 N) is 6.1 % and the cell's non-linearity (0.98 N) 25 %; a " \
        "cell of 88.8 to 623 N capacity (9.1 to 64 kg) suits this muscle" in err
    lowest = next(line.split() for line in out.splitlines() if line.split()[:1] == ["0.5"])
    assert float(lowest[3]) > 20.0  # U(F) [%] at 0.5 bar
    # a run at eps 20 % of the same muscle on a cell that suits it at eps 0: no word
    fitting = tiny.replace(muscle={"eps": 0.2}, loadcell={"capacity_N": 200.0,
                                                         "sensitivity_N_per_V": 20.0},
                           safety={"tare_max_std_N": 0.2, "tare_max_shift_N": 20.0},
                           settle={"max_force_std_N": 0.06, "max_force_slope_N_per_s": 0.04})
    (tmp_path / "fits.toml").write_text(fitting.effective_text())
    code, _, err = mkm_cli(["check", "--config", str(tmp_path / "fits.toml")])
    assert code == 0 and "warning" not in err


#: The newcomer's small muscle: the packaged example with a 5 mm tube, a 0.8 mm wall, 60 mm long,
#: to 4 bar (docs/guide/bench.md), every other setting the packaged one
SMALL = {"muscle": {"id": "small", "D0_mm": 5.0, "t0_mm": 0.8, "L0_mm": 60.0},
         "regulator": {"max_pressure_bar": 4.0},
         "sequence": {"pressures_bar": tuple(0.5 * k for k in range(1, 9))}}


def _limits_said(err: str) -> str:
    """The settle and noise limits' warning in ``err`` (one line), or ""."""
    lines = [line for line in err.splitlines() if "settle and noise limits" in line]
    assert len(lines) <= 1
    return lines[0] if lines else ""


def test_settle_limits_sized_for_a_stronger_muscle_are_a_warning_from_check_and_acquire(
        tmp_path, mkm_cli):
    """A 5 mm muscle kept the 30 mm muscle's settle and noise limits, and check said nothing:
    the 1.5 N scatter a step may settle with is 23 % of the 6.4 N it pulls at 0.5 bar. Each
    limit is named with its share and the value taking the share the packaged example's takes
    of its muscle's force at its lowest step; the packaged example itself, at the paper's two
    eps, is not warned."""
    from mkm.bench.preflight import muscle_lock
    from mkm.fem.eq2 import chou_hannaford

    small = load_config().replace(**SMALL)
    theta0 = muscle_lock(small).theta0_deg
    # Equation 2 on the braid's diameter (D0 + 2 t0) at eps 0: the small muscle at 0.5 bar,
    # the packaged one at 0.25 bar
    force_N = float(chou_hannaford(0.5, 6.6, 0.0, theta0))
    packaged_N = float(chou_hannaford(0.25, 36.0, 0.0, theta0))
    assert force_N == pytest.approx(6.41, abs=0.01) and packaged_N == pytest.approx(95.3, abs=0.1)
    assert round(100 * 1.5 / force_N) == 23 and round(100 * 5.0 / force_N) == 78
    # the packaged limits scaled by the forces: 1.5 N, 1 N/s and 5 N x 6.41 / 95.3
    assert [f"{v * force_N / packaged_N:.2g}" for v in (1.5, 1.0, 5.0)] == ["0.1", "0.067", "0.34"]
    said = ("the settle and noise limits are sized for a stronger muscle: at its lowest step, "
            "0.5 bar, this one pulls about 6.4 N (Equation 2 on the braid's diameter at eps 0), "
            "and these limits pass more than 10 % of it into a step: "
            "settle.max_force_std_N=1.5 passes 23 % (a hold scattering 1.5 N rms), "
            "settle.max_force_slope_N_per_s=1 78 % (5 N of trend over the hold) and "
            "safety.tare_max_std_N=5 78 % (a tare, taken off every force, scattering 5 N rms); "
            "set settle.max_force_std_N to about 0.1, settle.max_force_slope_N_per_s to about "
            "0.067 and safety.tare_max_std_N to about 0.34 (the share the packaged example's "
            "take of the 95 N its muscle pulls at 0.25 bar)")
    (tmp_path / "small.toml").write_text(small.effective_text())
    code, _, err = mkm_cli(["check", "--config", str(tmp_path / "small.toml")])
    # check reads the packaged cell at rest, 0.38 N rms (the simulator's 2 mV x 196 N/V): it
    # cannot meet the values it gives (a hold settles under 3 x 0.38 N, a tare passes under 1.5
    # x), which it said nothing of
    cell = re.escape("; but this load cell spreads 0.38 N rms at rest: it settles under no "
                     "settle.max_force_std_N below about 1.1 N (3 times it, 18 % of that force) "
                     "and passes no tare under a safety.tare_max_std_N below about 0.57 N (1.5 "
                     "times it, 8.9 % of that force), too noisy for this muscle: use a quieter or "
                     "smaller cell")
    assert code == 0 and re.fullmatch(re.escape(f"mkm check: warning: {said}") + cell,
                                      _limits_said(err)), _limits_said(err)
    notes = []  # acquire says it before the device is opened
    result = acquire(small.replace(sequence={"pressures_bar": (0.5,), "down_sweep": False,
                                             "preconditioning_cycles": 0}),
                     out_root=tmp_path / "runs", notify=notes.append)
    assert result.status == "complete"
    assert notes.index(f"warning: {said}") < next(i for i, n in enumerate(notes)
                                                  if "recording into" in n)
    for eps in ("0", "0.122"):  # the paper's two tests on the packaged example: no word
        code, _, err = mkm_cli(["check", "--eps", eps])
        assert code == 0 and "warning" not in err


def test_a_tare_zero_shifted_by_a_share_of_a_small_muscles_force_is_said(tmp_path, mkm_cli):
    # The packaged cell's amplifier reads 0.015 V unloaded against the configured 0 V: 2.93 N,
    # which tare_max_shift_N = 100 N lets pass, as it lets a load left on the cell of up to 100
    # N: the small muscle pulls 6.4 N at its lowest step, and such a load, taken off every
    # force, passed unsaid. A zero more than a tenth of that force from the configured one is
    # said by mkm tare, check and acquire's tare; the packaged muscle's 95 N takes it silently
    from mkm.bench.procedures import tare

    said = ("warning: the tare's zero is +2.93 N from loadcell.offset_V=0 V, 46 % of the 6.4 N "
            "the muscle pulls at the lowest step, 0.5 bar (safety.tare_max_shift_N=100 lets it "
            "pass): a load left on the cell at the tare (the muscle not hanging free, a fixture "
            "resting on the cell) is taken off every force, and the force limit does not see it; "
            "remove it and tare again, or, if the cell hung unloaded, set loadcell.offset_V to "
            "its zero, 0.0149 V")
    small = load_config().replace(**SMALL)
    (tmp_path / "small.toml").write_text(small.effective_text())
    for command in ("tare", "check"):
        code, _, err = mkm_cli([command, "--config", str(tmp_path / "small.toml")])
        assert code == 0 and f"mkm {command}: {said}" in err.splitlines(), err
    notes: list[str] = []
    result = acquire(small.replace(sequence={"pressures_bar": (0.5,), "down_sweep": False}),
                     out_root=tmp_path / "runs", notify=notes.append)
    assert result.status == "complete" and said in notes
    assert tare(load_config())["shift_warning"] == ""  # 2.93 N of the packaged muscle's 95 N
    zeroed = small.replace(loadcell={"offset_V": 0.0149})  # as it says: nothing more
    assert tare(zeroed)["shift_warning"] == ""


def test_a_five_mm_muscle_set_as_the_warnings_say_meets_the_accuracy_check_predicts(
        tmp_path, mkm_cli):
    """The small muscle with the limits the warning gives and a cell from the range the
    load-cell warning gives (the paper's 10 kg TCA10, 98 N): check warns of nothing, and its
    simulated runs settle every step with the true force within the expected uncertainty
    check states (an upper bound: the limits' worst, 0.12 N at 0.5 bar; the simulated cell,
    linear and exact within its declared gain, errs 0.01 N there)."""
    from mkm.bench.budget import expected_budget
    from mkm.bench.coverage import simulated_run_steps
    from mkm.bench.preflight import expected_force_N

    small = load_config().replace(**SMALL)
    (tmp_path / "small.toml").write_text(small.effective_text())
    _, _, err = mkm_cli(["check", "--config", str(tmp_path / "small.toml")])
    to_set = dict(re.findall(r"(\w+\.\w+) to about ([\d.]+)", _limits_said(err)))
    low, high = map(float, re.search(r"a cell of ([\d.]+) to ([\d.]+) N capacity", err).groups())
    assert low < 98.0665 < high
    settle = {k.split(".")[1]: float(v) for k, v in to_set.items() if k.startswith("settle.")}
    fitted = small.replace(loadcell={"capacity_N": 98.0665, "sensitivity_N_per_V": 9.80665},
                           settle=settle, safety={"tare_max_std_N": float(
                               to_set["safety.tare_max_std_N"]), "tare_max_shift_N": 5.0})
    (tmp_path / "fitted.toml").write_text(fitted.effective_text())
    code, _, err = mkm_cli(["check", "--config", str(tmp_path / "fitted.toml")])
    assert code == 0 and "warning" not in err
    steps = pd.concat([simulated_run_steps(fitted, seed, tmp_path / "runs") for seed in (0, 1)])
    assert len(steps) == 30 and steps["settled"].all()
    forces = {p: expected_force_N(fitted, p) for p in fitted.sequence.pressures_bar}
    predicted = {p: expected_budget(fitted, f, p).force_U_N for p, f in forces.items()}
    assert max(predicted[p] / f for p, f in forces.items()) < 0.02  # 1.8 % at 0.5 bar, the most
    predicted_N = steps["set_pressure_bar"].map(predicted)
    assert ((steps["force_N_mean"] - steps["force_true_N"]).abs() <= predicted_N).all()
    assert (steps["force_U_N"] <= predicted_N).all()


def test_a_1000_kg_cell_on_a_five_mm_muscle_names_its_adc_step_and_the_cell_to_use(
        tmp_path, mkm_cli):
    """A 1000 kg cell (9807 N, 981 N/V) on the small muscle: one ADC step, 1.22 mV x 981 N/V =
    1.2 N, is 19 % of the 6.4 N at 0.5 bar, and its noise at rest (the simulator's 2 mV, 2 N
    rms) is above the 1.5 N settle limit: the tare asked for a limit of 5.7 N, 89 % of the
    force, where the cell is what is wrong."""
    from mkm.bench.procedures import tare

    big = load_config().replace(**SMALL, loadcell={"capacity_N": 9806.65,
                                                   "sensitivity_N_per_V": 980.665})
    (tmp_path / "big.toml").write_text(big.effective_text())
    code, _, err = mkm_cli(["check", "--config", str(tmp_path / "big.toml")])
    assert code == 0
    assert "0.52 % of loadcell.capacity_N=9806.65: the cell's noise, ADC step and data-sheet " \
        "errors, fractions of its capacity, weigh on every force (`mkm check`'s expected " \
        "uncertainty): at the lowest step, 0.5 bar, the muscle pulls about 6.4 N, of which one " \
        "ADC step (1.2 N) is 19 % and the cell's non-linearity (4.9 N) 77 %; a cell of 72.6 to " \
        "513 N capacity (7.4 to 52 kg) suits this muscle" in err
    out = tare(big, seconds=5.0)
    share = 100 * 3 * out["std_N"] / 6.41
    assert out["std_N"] == pytest.approx(0.002 * 980.665, rel=0.25) and share > 10
    assert out["settle_warning"].startswith(f"the load cell spreads {out['std_N']:.2f} N rms")
    assert f"a limit this cell can settle under, about {3 * out['std_N']:.2g} N, is " \
        f"{share:.0f} % of the 6.4 N the muscle pulls at the lowest step, 0.5 bar: the cell is " \
        "too noisy for this muscle, use a quieter or smaller one" in out["settle_warning"]
    assert "set [settle] max_force_std_N" not in out["settle_warning"]


def test_a_muscle_outside_the_practical_range_is_a_warning_from_check_and_acquire(
        tmp_path, mkm_cli):
    # a braid woven at 45 deg, past the practical range's 40: check called it ready without a
    # word, where fem solve and design say every model extrapolates there
    steep = load_config().replace(muscle={"theta0_deg": 45.0},
                                  sequence={"pressures_bar": (0.5,), "preconditioning_cycles": 0})
    (tmp_path / "steep.toml").write_text(steep.effective_text())
    said = ("the muscle lies outside the practical range every model is validated over "
            "(theta0_deg=45 outside [15, 40]): its runs are recorded all the same, but every "
            "model's force for them (the report's, identify's, the simulated bench's) is an "
            "extrapolation (`mkm models` states the range)")
    code, _, err = mkm_cli(["check", "--config", str(tmp_path / "steep.toml")])
    assert code == 0 and f"mkm check: warning: {said}\n" in err
    notes = []
    result = acquire(steep, out_root=tmp_path / "runs", notify=notes.append)
    assert result.status == "complete" and f"warning: {said}" in notes
    code, _, err = mkm_cli(["check", "--config", str(tmp_path / "steep.toml"), "--pressures",
                            "9"])
    assert code == 2  # beyond the regulator: refused before any warning


def test_a_muscle_that_pulls_nothing_at_its_eps_is_a_warning_from_check_and_acquire(
        tmp_path, mkm_cli):
    # a 10 mm tube with a 1.5 mm wall at eps 0.28, up to 6 bar: check forecast
    # 2.1 to 25.3 N (Equation 2, which has no threshold) and said ready, and the simulated run
    # (the FE model) read the load cell's zero at all 23 steps
    from mkm.bench.preflight import thickwall_force_N

    m10 = load_config().replace(
        muscle={"D0_mm": 10.0, "t0_mm": 1.5, "L0_mm": 250.0, "eps": 0.28},
        regulator={"max_pressure_bar": 6.0, "full_scale_bar": 10.0},
        sequence={"pressures_bar": (2.0, 4.0, 6.0), "preconditioning_cycles": 0})
    (tmp_path / "m10.toml").write_text(m10.effective_text())
    # the thick-wall model at the FE model's calibrated angle: 1.6 N of 298 N at eps 0
    at_rest, pulled = (thickwall_force_N(m10, 6.0, e) for e in (0.0, 0.28))
    assert pulled < 0.01 * at_rest and thickwall_force_N(m10, 6.0, 0.277) > 0.01 * at_rest
    said = (f"at eps 0.28 the muscle pulls at most {pulled:.2g} N up to 6 bar, under 1 % of the "
            f"{at_rest:.0f} N it pulls at its rest length (the thick-wall model, whose wall "
            "holds the braid below a threshold pressure; Equation 2's forecast above has "
            "none): every step would read about the load cell's zero; it pulls more than that "
            "at 6 bar below eps 0.278, at a higher pressure or with a thinner wall")
    code, _, err = mkm_cli(["check", "--config", str(tmp_path / "m10.toml")])
    assert code == 0 and f"mkm check: warning: {said}\n" in err
    notes = []
    result = acquire(m10, out_root=tmp_path / "runs", notify=notes.append)
    assert result.status == "complete" and f"warning: {said}" in notes
    # and so the simulated muscle (the FE model) does: every step within the cell's noise of 0
    steps = load_run(result.path).steps
    assert (steps["force_N_mean"].abs() < 3 * steps["force_N_std"] + 0.1).all()
    # at eps 0.25 it pulls, about 10 % of its force at rest at 6 bar: no word
    code, _, err = mkm_cli(["check", "--config", str(tmp_path / "m10.toml"), "--eps", "0.25"])
    assert code == 0 and "pulls at most" not in err
    # the run: the report scored the models against its largest reading, a tenth of a newton
    # of noise ('103.85 % off ... points to the muscle: identify it'), and identify called its
    # fit ready, every interval its search box; neither has a force to go by
    import pandas as pd

    from mkm.registry import parse_specs
    from mkm.report import build_report

    build_report([result.path], parse_specs("thickwall"), out_dir=tmp_path / "report",
                 cache_dir=None, tolerance=None, surrogate_section=False)
    summary = pd.read_csv(tmp_path / "report" / "summary.csv")
    assert summary["max_abs_err_pct"].isna().all() and summary["valid_points"].gt(0).all()
    code, _, err = mkm_cli(["identify", str(result.path), "--model", "thickwall", "--search",
                            "model", "--out", str(tmp_path / "id")])
    assert code == 2 and ("every settled force is 0 N or less, or within its uncertainty (a "
                          "slack muscle)") in err, err


# 4. bounded runs ---------------------------------------------------------------------------

@pytest.mark.parametrize("section, values, message", [
    ("sequence", {"tare_s": 1e9}, r"sequence\.tare_s=1e\+09 is invalid: expected 0 to 600 s"),
    ("sequence", {"preconditioning_hold_s": 1e9}, r"preconditioning_hold_s=1e\+09 is invalid"),
    ("sequence", {"preconditioning_cycles": 10**6}, r"preconditioning_cycles=1000000 is "
     r"invalid: expected 0 to 100"),
    ("settle", {"hold_s": 1e9}, r"settle\.hold_s=1e\+09 is invalid: expected 0 to 3600 s"),
    ("sim", {"buffer_s": 0.01}, r"sim\.buffer_s=0\.01 is invalid: expected 1 to 86400 s"),
    ("sim", {"faults": {"stall_s": 1e8}}, r"sim\.faults\.stall_s=1e\+08 is invalid: expected 0 "
     r"to 3600 s"),
    ("settle", {"timeout_s": 3600.0}, r"may take up to 19\.0 h .*: expected at most "
     r"sequence\.max_duration_h=4 h"),
])
def test_every_duration_and_count_is_bounded(section, values, message):
    with pytest.raises(ValueError, match=message):
        load_config().replace(**{section: values})


def test_a_longer_plan_needs_a_larger_max_duration():
    config = load_config().replace(settle={"timeout_s": 600.0},
                                   sequence={"max_duration_h": 4.0})  # 19 x 605 s: 3.2 h
    assert config.sequence.max_duration_h == 4.0
    with pytest.raises(ValueError, match=r"max_duration_h=100 is invalid: expected 0 to 48 h"):
        load_config().replace(sequence={"max_duration_h": 100.0})


# 5. writes that cannot lie -----------------------------------------------------------------

def test_a_full_disk_at_the_final_write_is_exit_2_and_said(tmp_path, mkm_cli, monkeypatch):
    write = RunWriter.write_meta

    def full_at_the_end(self, meta):
        if meta.status != "running":
            raise OSError(errno.ENOSPC, "No space left on device")
        write(self, meta)

    monkeypatch.setattr(RunWriter, "write_meta", full_at_the_end)
    code, out, err = mkm_cli(["acquire", "--pressures", "0.5", "--out", str(tmp_path),
                              "--no-progress"])
    assert code == 2
    assert "run.json could not be written (No space left on device)" in err
    assert load_run(Path(out.strip())).status == "running"  # this process: still alive


@pytest.mark.parametrize("refusal", [OSError(errno.ENOSPC, "No space left on device"),
                                     PermissionError(errno.EACCES, "Permission denied")])
def test_a_final_record_refused_for_good_is_kept_in_the_marker_and_written_next(
        config, tmp_path, monkeypatch, refusal):
    # the disk refuses run.json's final write for good (full, or no permission): the run
    # vented and said so on stderr, but run.json said `running` for ever and its marker was
    # removed, so nothing ever wrote the outcome. Now the bench marker keeps it, and the next
    # command on the bench writes it into run.json once the run's process has ended
    from mkm.bench import procedures, recorder

    monkeypatch.setattr(recorder, "LOCKED_RETRY_S", 0.0)
    write, refusing = RunWriter.write_meta, [True]

    def refused_at_the_end(self, meta):
        if meta.status != "running" and refusing:
            raise refusal
        write(self, meta)

    monkeypatch.setattr(RunWriter, "write_meta", refused_at_the_end)
    result = acquire(config, out_root=tmp_path, **QUIET)
    assert result.status == "complete" and result.exit_code == 2
    assert f"run.json could not be written ({refusal.strerror}" in result.reason
    assert result.reason.endswith("run.json still says running: the outcome is kept in the "
                                  f"bench marker {next(bench_folder('sim-Dev1').glob('*.json'))}, "
                                  "and the next command on this bench writes it there")
    assert load_run(result.path).status == "running"  # this process: still alive
    (path,) = bench_folder("sim-Dev1").glob("*.json")
    marker = json.loads(path.read_text())
    assert marker["outcome"]["status"] == "complete"
    assert marker["outcome"]["reason"].startswith("all 3 steps done; run.json could not be")
    for written in (path, result.path / "run.json"):  # as if its process had ended
        data = json.loads(written.read_text())
        data["process"]["started_unix_s"] -= 100.0
        written.write_text(json.dumps(data))
    # the next command finds the disk still refusing run.json: the marker, which alone keeps
    # the outcome, was removed all the same; now it stays for the command after
    from mkm.bench import storage

    write_json = storage.write_json_atomic

    def still_refused(path, data):
        if path.name == "run.json" and refusing:
            raise refusal
        write_json(path, data)

    monkeypatch.setattr(storage, "write_json_atomic", still_refused)  # a dead run's final record
    notes = []
    assert procedures.vent(config, notify=notes.append)["vented"]
    (said,) = notes
    assert said.endswith(f"vented now; its run.json could not be rewritten ({refusal.strerror}): "
                         "not mended; its bench marker keeps the outcome for the next command")
    assert path.is_file() and load_run(result.path).status == "incomplete"
    refusing.clear()  # the disk takes writes again
    notes = []
    assert procedures.vent(config, notify=notes.append)["vented"]
    (said,) = notes
    assert f"run {result.path.resolve()} (started " in said
    assert ", but its run.json refused that record: all 3 steps done; " in said
    assert said.endswith("vented now; run.json mended: status complete, 225 samples on disk")
    run = load_run(result.path)
    assert run.status == "complete" and not run.meta.manual_vent_required
    assert run.reason.startswith(marker["outcome"]["reason"])
    assert "; this outcome was refused by run.json as the run ended, kept in its bench marker " \
        "and written by the next command at " in run.reason
    # the run's 203, the check's 22: 0.5 bar exhausting with tau 0.4 s falls by less than the
    # monitor's noise over vent.SETTLED_S from 2.2 s on
    assert run.meta.counters["samples"] == len(run.samples) == 225
    assert not list(bench_folder("sim-Dev1").glob("*.json"))


def test_a_full_disk_at_the_start_leaves_no_folder_and_says_so(tmp_path, mkm_cli, monkeypatch):
    def full(self, meta):
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(RunWriter, "write_meta", full)
    code, out, err = mkm_cli(["acquire", "--pressures", "0.5", "--out", str(tmp_path / "runs"),
                              "--no-progress"])
    assert code == 2 and out == ""
    assert "recording failed (No space left on device)" in err
    assert list((tmp_path / "runs").iterdir()) == []


def test_a_full_state_folder_is_named_not_taken_for_a_failed_vent(config, tmp_path,
                                                                  monkeypatch):
    command = BenchLease.command

    def full_at_zero(self, pressure_bar):
        if pressure_bar == 0.0:
            raise OSError(errno.ENOSPC, "No space left on device")
        command(self, pressure_bar)

    monkeypatch.setattr(BenchLease, "command", full_at_zero)
    result = acquire(config, out_root=tmp_path, **QUIET)
    run = load_run(result.path)
    assert "vent command failed" not in result.reason
    assert "could not be updated (No space left on device)" in result.reason
    assert run.commands["ok"].all() and run.meta.vent_check["verified"]


# 7. spreadsheet-safe outputs, ids validated when loaded ------------------------------------

def test_formula_cells_are_neutralised():
    import pandas as pd

    from mkm.core.records import spreadsheet_safe

    frame = pd.DataFrame({"run": ["=HYPERLINK(1)", "+1", "-cmd", "@x", "\tx", "ok"],
                          "force_N": [-1.0, 2.0, 3.0, 4.0, 5.0, 6.0]})
    safe = spreadsheet_safe(frame)
    assert list(safe["run"]) == ["'=HYPERLINK(1)", "'+1", "'-cmd", "'@x", "'\tx", "ok"]
    assert list(safe["force_N"]) == list(frame["force_N"])  # numbers untouched


@pytest.mark.parametrize("edit, message", [
    (("flags", "=cmd|' /C calc'!A0"), r"samples\.csv is corrupt: flags="),
    (("id", "<img src=x onerror=alert(1)>"), r"muscle\.id=.*is invalid"),
    (("id", "a/b"), r"muscle\.id='a/b' .* is invalid"),
])
def test_hostile_cells_and_ids_are_refused_when_loaded(config, tmp_path, edit, message):
    path = acquire(config, out_root=tmp_path, **QUIET).path
    key, value = edit
    if key == "flags":
        lines = (path / "samples.csv").read_text().splitlines()
        lines[1] = lines[1] + value.replace(",", "")
        (path / "samples.csv").write_text("\n".join(lines) + "\n")
    else:
        meta = json.loads((path / "run.json").read_text())
        meta["muscle"]["id"] = value
        (path / "run.json").write_text(json.dumps(meta))
    with pytest.raises(ValueError, match=message):
        load_run(path).samples  # noqa: B018 (the samples are read on first use)


# 9. the small ones -------------------------------------------------------------------------

def test_a_killed_runs_sample_count_comes_from_samples_csv(config, tmp_path):
    path = acquire(config, out_root=tmp_path, **QUIET).path
    meta = json.loads((path / "run.json").read_text())
    meta["status"], meta["counters"]["samples"] = "running", 20  # the last rewrite's count
    meta["process"]["pid"] = 2**22 + 5  # dead
    (path / "run.json").write_text(json.dumps(meta))
    run = load_run(path)
    assert run.meta.counters["samples"] == len(run.samples) > 20
    assert any("samples counted from samples.csv" in p for p in run.problems)


def test_stop_to_vent_counts_from_the_first_stop_request(config, tmp_path):
    run = BenchRun(config, SimBackend(config), tmp_path, handle_signals=False, **QUIET)
    run.signals.stop_requested_at, run.signals.signal_at = 10.0, 12.5  # Ctrl-C, then again
    assert run._stop_time() == 10.0


@pytest.mark.parametrize("held", [1, 10, 11])
def test_run_json_held_open_at_the_end_is_tried_again(config, tmp_path, monkeypatch, held):
    # Windows: a virus scanner or the indexer holding run.json for a moment made the final
    # record fail once and for all: a complete run stayed 'running' with the tare's counters
    import os

    from mkm.bench import recorder

    monkeypatch.setattr(recorder, "LOCKED_RETRY_S", 0.0)
    replace, finishing, refused = os.replace, [], []

    def held_open(source, target):
        if finishing and str(target).endswith("run.json") and len(refused) < held:
            refused.append(target)
            raise PermissionError(13, "The process cannot access the file because it is "
                                  "being used by another process", str(target))
        return replace(source, target)

    finish = recorder.Recorder.finish

    def finishing_now(self, *args):
        finishing.append(1)
        return finish(self, *args)

    monkeypatch.setattr(os, "replace", held_open)
    monkeypatch.setattr(recorder.Recorder, "finish", finishing_now)
    result = acquire(config, out_root=tmp_path, notify=lambda m: None)
    meta = json.loads((result.path / "run.json").read_text(encoding="utf-8"))
    rows = len((result.path / "samples.csv").read_text(encoding="utf-8").splitlines()) - 1
    if held <= recorder.LOCKED_RETRIES:
        assert result.exit_code == 0 and result.status == "complete"
        assert meta["status"] == "complete" and meta["counters"]["samples"] == rows
    else:  # held for good: said, exit 2, the samples on disk
        assert result.exit_code == 2 and meta["status"] == "running"
        assert "run.json could not be written (The process " \
               "cannot access the file" in result.reason and "tried 11 times over 0 s" \
               in result.reason
        # the rows on disk: the run's 203 and the vent check's 22 (a reading steady over
        # vent.SETTLED_S)
        assert rows == 225 and meta["counters"]["samples"] == 20  # run.json: the tare's
    assert len(refused) == held


def test_a_disk_that_fills_mid_run_still_gets_the_final_record(config, tmp_path, monkeypatch):
    # the disk fills during the first step: run.json's final write was refused as well, so the
    # run stayed 'running' with the tare's counters (and a real disk cut the last row of
    # samples.csv in half); the room a run keeps in its folder is given back for that record.
    # The disk here is full while the folder holds at least what it held when it filled.
    from mkm.bench import storage
    from mkm.bench.storage import RunWriter

    def folder_bytes(path):
        return sum(p.stat().st_size for p in Path(path).iterdir() if p.is_file())

    full_at, append, write_json = [], RunWriter.append_samples, storage.write_json_atomic

    def samples_until_full(self, rows):
        if rows[-1].sample >= 40 or full_at:
            full_at.append(full_at[0] if full_at else folder_bytes(self.path))
            raise OSError(errno.ENOSPC, "No space left on device")
        append(self, rows)

    def json_on_a_full_disk(path, data):
        if full_at and folder_bytes(Path(path).parent) >= full_at[0]:
            raise OSError(errno.ENOSPC, "No space left on device", str(path))
        return write_json(path, data)

    monkeypatch.setattr(RunWriter, "append_samples", samples_until_full)
    monkeypatch.setattr(storage, "write_json_atomic", json_on_a_full_disk)
    result = acquire(config, out_root=tmp_path / "runs", notify=lambda m: None)
    assert result.status == "failed" and result.exit_code == 2
    assert result.reason.startswith("recording failed for samples 40 (No "
                                    "space left")
    meta = json.loads((result.path / "run.json").read_text(encoding="utf-8"))
    assert meta["status"] == "failed" and meta["reason"] == result.reason
    assert meta["vent_check"]["verified"]
    rows = (result.path / "samples.csv").read_text(encoding="utf-8").splitlines()[1:]
    assert meta["counters"]["samples"] == len(rows) == 40  # samples 0-39, the rest refused
    assert sorted(p.name for p in result.path.iterdir()) == [
        "commands.csv", "config.toml", "run.json", "samples.csv", "steps.csv"]


def test_rows_a_full_disk_refused_and_that_went_out_at_close_are_counted(config, tmp_path,
                                                                       monkeypatch):
    # a row refused by a full disk stays in the file's buffer and reaches the disk at close
    # once the reserve is given back (seen on a 320 KiB tmpfs: 700 rows, run.json said 699);
    # modelled here by an append that writes its row, then fails
    from mkm.bench.storage import RunWriter

    append = RunWriter.append_samples

    def written_then_refused(self, rows):
        append(self, rows)
        if rows[-1].sample >= 40:
            raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(RunWriter, "append_samples", written_then_refused)
    result = acquire(config, out_root=tmp_path / "runs", notify=lambda m: None)
    meta = json.loads((result.path / "run.json").read_text(encoding="utf-8"))
    rows = (result.path / "samples.csv").read_text(encoding="utf-8").splitlines()[1:]
    assert meta["status"] == "failed" and result.exit_code == 2
    assert int(rows[-1].split(",")[0]) == len(rows) - 1  # every row whole, none twice
    assert meta["counters"]["samples"] == len(rows) > 40


# 2. `mkm vent`'s own reads are watched ------------------------------------------------------

def test_a_read_that_hangs_in_mkm_vents_check_ends_unverified_and_marks_the_bench(
        config, monkeypatch):
    # `mkm vent` writes the vent as it opens the device; its check's third read then hangs (the
    # driver does not keep its 0.5 s timeout). The command sat in that read for as long as it
    # hung, nothing said. Now the read is given its timeout, its block and READ_HANG_MARGIN_S,
    # then the vent is said not verified while the read still hangs, the bench is marked, the
    # command exits 1, and the next command on the bench names the unverified vent.
    import mkm.bench.procedures as procedures
    from mkm.bench.backend import BenchError

    c = config.replace(daq={"read_timeout_s": 0.5})
    release, reads, backends = threading.Event(), [], []

    class Hanging(SimBackend):
        def read(self, n_samples, timeout_s):
            reads.append(n_samples)
            if len(reads) == 3:
                release.wait(60)  # the test's net; released once the command returned
            return super().read(n_samples, timeout_s)

    make_backend = procedures.make_backend
    monkeypatch.setattr(procedures, "make_backend",
                        lambda c, clock: backends.append(Hanging(c)) or backends[-1])
    try:
        with pytest.raises(BenchError) as caught:
            procedures.vent(c, notify=lambda m: None)
        still_hung = not release.is_set() and len(reads) == 3
    finally:
        release.set()
    assert still_hung  # the command did not wait for the read
    message = str(caught.value)
    hung_s = float(re.search(r"did not return within ([0-9.]+) s", message).group(1))
    assert hung_s >= 0.5 + 0.1 + 1.0  # its timeout, a block (1 sample at 10 Hz), the margin
    assert message.startswith("the vent could not be verified (a read of the device did not "
                              "return within")
    assert ("(its timeout 0.5 s) during the vent check: the driver hangs; the vent was "
            "commanded, its check cannot read the monitor): VENT BY HAND") in message
    assert backends[0].commands[0][1] == 0.0  # the vent went out first, at open
    (path,) = bench_folder("sim-Dev1").glob("*.json")  # the bench is marked
    data = json.loads(path.read_text())
    assert data["command"] == "vent" and data["run_path"] == ""
    assert "did not return within" in data["vent_unverified"]
    data["process"]["started_unix_s"] -= 100.0  # as if its process had ended
    path.unlink()  # under another name than this process's next `mkm vent` marks
    path.with_name("dead-vent.json").write_text(json.dumps(data))
    notes = []
    monkeypatch.setattr(procedures, "make_backend", make_backend)  # a driver that answers
    assert procedures.vent(config, notify=notes.append)["vented"]
    (said,) = [n for n in notes if "not verified" in n]
    assert said.startswith(f"`mkm vent` (started {data['started_utc']}, pid "
                           f"{data['process']['pid']}) vented (0 bar commanded at ")
    assert "during the vent check: the driver hangs" in said and said.endswith("vented now")
    assert not list(bench_folder("sim-Dev1").glob("*.json"))  # removed once vented


def _dead_run_lease() -> BenchLease:
    """The marker of a run that died on the simulated bench with 1.5 bar commanded."""
    lease = BenchLease("sim-Dev1", Path("/nonexistent/run"), "2026-12-01T10:00:00+00:00")
    lease.started()
    lease.end()
    lease.command(1.5)
    data = json.loads(lease.path.read_text())
    data["process"]["started_unix_s"] -= 100.0  # as if its process had died
    lease.path.write_text(json.dumps(data))
    return lease


def test_the_vent_written_again_for_dead_runs_after_a_hung_check_is_bounded(config,
                                                                            monkeypatch):
    # a run died on the bench; `mkm vent` vents, its check's read hangs (watched, said), then it
    # writes the vent again for the dead run, and the driver hangs for that write too: the
    # command sat in it, nothing said. Now the write is given the AO write's timeout and the
    # margin, then said; the dead run is left marked, for the next command to vent and name.
    import mkm.bench.procedures as procedures
    from mkm.bench.backend import BenchError

    lease = _dead_run_lease()
    c = config.replace(daq={"read_timeout_s": 0.5})
    release, reads, writes, hanging = threading.Event(), [], [], set()

    class Hanging(SimBackend):
        def read(self, n_samples, timeout_s):
            reads.append(n_samples)
            if len(reads) >= 3:
                release.wait(60)  # the test's net; released once the command returned
            return super().read(n_samples, timeout_s)

        def write_command(self, volts):
            writes.append(volts)
            if len(reads) >= 3:  # the driver hangs for every call once the check's read hung
                hanging.add(n := len(writes))
                release.wait(60)
                hanging.discard(n)
            super().write_command(volts)

    monkeypatch.setattr(procedures, "make_backend", lambda c, clock: Hanging(c))
    try:
        with pytest.raises(BenchError) as caught:
            procedures.vent(c, notify=lambda m: None)
        hung = set(hanging)
    finally:
        release.set()
    assert 3 in hung  # the dead run's vent (at open, before the check, then it) left hanging
    message = str(caught.value)
    assert "during the vent check: the driver hangs" in message
    assert ("the vent written again for the runs that died on this bench did not return "
            "within 2 s (its timeout 1 s): the driver hangs; they were not named, their folders "
            "not mended, and the next command on this bench vents first and names them"
            ) in message
    assert lease.path.exists()  # the dead run stays marked


def test_the_vent_written_at_start_up_for_dead_runs_is_bounded(config, monkeypatch):
    # a run died on the bench; `mkm tare` opens the device (which writes the vent) and writes
    # the vent again for the dead run before anything else, and the driver hangs in that write:
    # the command sat in it, nothing said. Now the write is given the AO write's timeout and the
    # margin, then the command ends in one line; the dead run is left marked for the next.
    import mkm.bench.procedures as procedures
    from mkm.bench.backend import BenchError

    lease = _dead_run_lease()
    release, hung = threading.Event(), []
    monkeypatch.setattr(procedures, "make_backend",
                        lambda c, clock: _hanging_after_open(release, hung)(c))
    try:
        with pytest.raises(BenchError) as caught:
            procedures.tare(config, seconds=0.5)
        still_hung = list(hung)
    finally:
        release.set()
    assert still_hung == [0.0]
    assert str(caught.value) == DEAD_RUNS_VENT_HUNG
    assert lease.path.exists()  # the dead run stays marked


DEAD_RUNS_VENT_HUNG = (
    "the vent written for the runs that died on this bench did not return within 2 s (its "
    "timeout 1 s): the driver hangs: VENT BY HAND; they were not named, and the next command on "
    "this bench vents first and names them")


def _hanging_after_open(release: threading.Event, hung: list) -> type:
    """A simulated backend whose first write after its open (the vent written again for the
    dead runs) hangs until ``release``; the volts it was asked for go into ``hung``, then
    ``"returned"`` once it returns."""

    class Hanging(SimBackend):
        opened = False

        def open(self):
            info = super().open()
            self.opened = True
            return info

        def write_command(self, volts):
            if self.opened and not hung:
                hung.append(volts)
                release.wait(10)  # the test's net; released once the command returned
                hung.append("returned")
            super().write_command(volts)

    return Hanging


def test_the_vent_written_at_a_runs_start_up_for_dead_runs_is_bounded(config, tmp_path,
                                                                       monkeypatch):
    # as for `mkm tare`, at `mkm acquire`'s start-up: the driver hangs in the vent written
    # again for a dead run, and the run sat in it, nothing said. Now the run is refused in one
    # line after the same bound, before its folder is made; the dead run is left marked.
    import mkm.bench.run as run

    lease = _dead_run_lease()
    release, hung = threading.Event(), []
    monkeypatch.setattr(run, "make_backend",
                        lambda c, clock: _hanging_after_open(release, hung)(c))
    try:
        result = acquire(config, out_root=tmp_path / "runs", **QUIET)
        still_hung = list(hung)
    finally:
        release.set()
    assert still_hung == [0.0]
    assert (result.path, result.status, result.exit_code) == (None, "failed", 1)
    assert result.reason == DEAD_RUNS_VENT_HUNG
    assert not list((tmp_path / "runs").iterdir())  # no run folder
    assert lease.path.exists()  # the dead run stays marked


@pytest.mark.parametrize("call, said, bound_s", [
    # the check's first call to the driver asks how many samples wait (those acquired before
    # the vent, which prove nothing): READ_HANG_MARGIN_S
    ("available", "the device did not say how many samples wait within", 1.0),
    # the vent went out with the open; the check then starts the inputs' task (the monitor's
    # clock): the AO write's timeout and READ_HANG_MARGIN_S
    ("start", "starting the device's inputs did not return within", 2.0)])
def test_a_call_of_the_vent_check_that_hangs_in_mkm_vent_ends_it_unverified(config, monkeypatch,
                                                                           call, said, bound_s):
    # the driver hangs in a call of `mkm vent`'s check, watched by nothing: the command sat in
    # it, nothing said. Now the call is watched as the check's reads are, then the vent is said
    # not verified and the bench stays marked.
    import mkm.bench.procedures as procedures
    from mkm.bench.backend import BenchError

    release, backends = threading.Event(), []

    def hangs(method):
        def hung(self, *args):
            release.wait(60)  # the test's net; released once the command returned
            return method(self, *args)
        return hung

    Hanging = type("Hanging", (SimBackend,), {call: hangs(getattr(SimBackend, call))})
    monkeypatch.setattr(procedures, "make_backend",
                        lambda c, clock: backends.append(Hanging(c)) or backends[-1])
    try:
        with pytest.raises(BenchError) as caught:
            procedures.vent(config, notify=lambda m: None)
        still_hung = not release.is_set()
    finally:
        release.set()
    assert still_hung
    assert backends[0].commands[0][1] == 0.0  # the vent went out first, at open
    hung_s = float(re.search(re.escape(said) + r" ([0-9.]+) s during the vent check: the driver "
                             r"hangs; the vent was commanded, its check cannot read the "
                             r"monitor\): VENT BY HAND", str(caught.value)).group(1))
    assert hung_s >= bound_s
    (marker,) = bench_folder("sim-Dev1").glob("*.json")  # the bench is marked
    assert said in json.loads(marker.read_text())["vent_unverified"]


@pytest.mark.parametrize("refusals", [1, 3])
def test_a_vent_write_mkm_vent_is_refused_is_written_again(config, monkeypatch, refusals):
    # the device refuses `mkm vent`'s vent write (an AO write error), as it opens: the command
    # gave up at once, VENT BY HAND, where a run's shutdown writes it again, three times in
    # all. Now so does `mkm vent`, and says so; refused three times, VENT BY HAND.
    import mkm.bench.procedures as procedures
    from mkm.bench.backend import AOWriteFailed, BenchError

    refused, backends = [], []

    class Refusing(SimBackend):
        def write_command(self, volts):
            if len(refused) < refusals:
                refused.append(volts)
                raise AOWriteFailed("AO write refused")
            super().write_command(volts)

        def start(self):
            super().start()
            self.bench.pressure_bar = 0.5  # left by a run: the vent exhausts it

    monkeypatch.setattr(procedures, "make_backend",
                        lambda c, clock: backends.append(Refusing(c)) or backends[-1])
    notes = []
    if refusals == 3:
        with pytest.raises(BenchError, match="AO write refused"):
            procedures.vent(config, notify=notes.append)  # the command line: VENT BY HAND
    else:
        assert procedures.vent(config, notify=notes.append)["vented"]
        assert backends[0].bench.pressure_bar < config.safety.vent_below_bar  # the truth
    assert refused == [0.0] * refusals
    assert notes == ["vent command failed (the regulator command did not reach the DAQ device: "
                     "check its USB cable and power (AO write refused)), tried again"] * (
        min(refusals, 2))


def test_mkm_vent_killed_during_its_check_leaves_the_bench_marked(config, monkeypatch):
    # `mkm vent` killed (kill -9, the Task Manager) while its check reads the monitor left no
    # trace: the next command said nothing of a vent never verified. Now the bench is marked
    # once the vent is out, the marker removed once the vent is verified; the marker as the
    # kill would leave it is named by the next command.
    import mkm.bench.procedures as procedures

    seen, backends = {}, []

    class Watched(SimBackend):
        def read(self, n_samples, timeout_s):
            if "marker" not in seen:  # the check's first read: the marker is posted before it
                deadline = time.monotonic() + 60  # the test's net
                while time.monotonic() < deadline and "marker" not in seen:
                    for path in bench_folder("sim-Dev1").glob("*.json"):
                        seen["marker"] = (path, path.read_text())
            return super().read(n_samples, timeout_s)

    make_backend = procedures.make_backend
    monkeypatch.setattr(procedures, "make_backend",
                        lambda c, clock: backends.append(Watched(c)) or backends[-1])
    assert procedures.vent(config, notify=lambda m: None)["vented"]
    assert not list(bench_folder("sim-Dev1").glob("*.json"))  # verified: removed
    path, text = seen["marker"]  # what a kill during the check leaves
    data = json.loads(text)
    assert data["command"] == "vent" and data["vent_unverified"] == ""
    data["process"]["started_unix_s"] -= 100.0  # as if its process had been killed
    path.with_name("dead-vent.json").write_text(json.dumps(data))  # not this process's name
    notes = []
    monkeypatch.setattr(procedures, "make_backend", make_backend)
    assert procedures.vent(config, notify=notes.append)["vented"]
    assert notes == [f"`mkm vent` (started {data['started_utc']}, pid {data['process']['pid']}) "
                     f"ended after its vent (0 bar commanded at {data['last_command_utc']}) "
                     "before the vent was verified: vented now"]


def _open_hangs(release, closed):
    """A simulated device whose open hangs in the driver until ``release`` (the test's net:
    10 s), each close recorded in ``closed``."""

    class Hanging(SimBackend):
        def open(self):
            release.wait(10)
            return super().open()

        def close(self):
            closed.append(True)
            super().close()

    return Hanging


def test_an_open_that_hangs_in_mkm_vent_says_the_vent_was_not_written(mkm_cli, monkeypatch,
                                                                       tmp_path):
    # `mkm vent` opens the device, which writes the vent; the driver hangs in the open. The
    # command sat in it, nothing said, for as long as it hung. Now the open is waited for
    # OPEN_WAIT_S, then one line says the vent is not known to be written: VENT BY HAND, exit 1;
    # the device is not closed behind the open under way (a close would wait behind it).
    release, closed = threading.Event(), []
    code, out, err, still_hung, _ = _command_on(_open_hangs(release, closed), release,
                                                ["vent"], mkm_cli, monkeypatch, tmp_path)
    assert still_hung and code == 1 and out == "" and not closed
    assert err.splitlines()[-1] == (
        "mkm vent: error: opening the device did not return within 0.2 s (the driver hangs): "
        "the vent is NOT known to be written (the open writes it); VENT BY HAND")
    assert not list(bench_folder("sim-Dev1").glob("*.json"))  # no vent to name: not marked


@pytest.mark.parametrize("command", [["acquire", "--clock", "virtual"], ["tare"], ["check"],
                                     ["calibrate-loadcell", "--masses", "0,5"]])
def test_an_open_that_hangs_ends_every_command_in_one_line(mkm_cli, monkeypatch, tmp_path,
                                                           command):
    # `mkm vent` bounds its open; `mkm acquire`, `tare`, `check` and `calibrate-loadcell` sat
    # in an open the driver hangs in, nothing said, as long as it hung. Now each waits
    # OPEN_WAIT_S, then ends in one line, exit 1: the vent is not known to be written, VENT BY
    # HAND; the device is not closed behind the open, no run folder is made, and a run that
    # died on the bench stays marked for the next command.

    lease = _dead_run_lease()
    release, closed = threading.Event(), []
    code, out, err, still_hung, out_root = _command_on(_open_hangs(release, closed), release,
                                                       command, mkm_cli, monkeypatch, tmp_path)
    assert still_hung and code == 1 and out == "" and not closed
    simulated = "SIMULATED " if command[0] == "acquire" else ""  # a run says it in its line
    assert err.splitlines()[-1] == (
        f"mkm {command[0]}: error: {simulated}opening the device did not return within 0.2 s "
        "(the driver hangs): the vent is NOT known to be written (the open writes it); VENT BY "
        "HAND")
    assert not out_root.exists() or not list(out_root.iterdir())  # no run folder
    assert lease.path.exists()  # the dead run stays marked


def _command_on(backend_class, release, command, mkm_cli, monkeypatch, tmp_path):
    """``mkm COMMAND --backend sim`` on a ``backend_class`` whose driver hangs until
    ``release`` (set once the command returned), ``OPEN_WAIT_S`` 0.2 s: its exit status,
    stdout, stderr, whether the driver still hung as it returned, and the folder of a run."""
    import mkm.bench.procedures as procedures
    import mkm.bench.run as run

    for module in (run, procedures):
        monkeypatch.setattr(module, "make_backend", lambda c, clock: backend_class(c))
    monkeypatch.setattr(run, "OPEN_WAIT_S", 0.2)  # the bound itself: 10 s
    out_root = tmp_path / "runs"
    try:
        code, out, err = mkm_cli([*command, "--backend", "sim", *(
            ["--out", str(out_root)] if command[0] == "acquire" else [])])
        still_hung = not release.is_set()
    finally:
        release.set()
    return code, out, err, still_hung, out_root


@pytest.mark.parametrize("command", [["vent"], ["acquire", "--clock", "virtual"], ["tare"],
                                     ["check"], ["calibrate-loadcell", "--masses", "0,5"]])
def test_a_serial_number_that_hangs_ends_every_command_in_one_line(mkm_cli, monkeypatch,
                                                                  tmp_path, command):
    # every command reads the device's serial number, which names the bench (its lock, a run
    # holding it, the markers of dead runs), before it opens the device; on NI that goes
    # through the driver, and a driver that hangs there held the command, `mkm vent`
    # included, nothing said. It cannot come after the vent: `mkm vent` must first ask a run
    # holding the bench to stop (its tasks hold the device). Now it is waited for OPEN_WAIT_S,
    # then the command ends in one line, VENT BY HAND, exit 1; the device is not opened, no run
    # folder is made, and a run that died on the bench stays marked.

    lease = _dead_run_lease()
    release, opened = threading.Event(), []

    class Hanging(SimBackend):
        @property
        def bench_key(self):
            release.wait(10)  # the test's net; released once the command returned
            return self._key

        @bench_key.setter
        def bench_key(self, key):
            self._key = key

        def open(self):
            opened.append(True)
            return super().open()

    code, out, err, still_hung, out_root = _command_on(Hanging, release, command, mkm_cli,
                                                       monkeypatch, tmp_path)
    assert still_hung and code == 1 and out == "" and not opened
    assert err.splitlines()[-1] == (
        f"mkm {command[0]}: error: reading the device's serial number (it names the bench) did "
        "not return within 0.2 s (the driver hangs): nothing was written to the device, not "
        "even the vent; VENT BY HAND")
    assert not out_root.exists() or not list(out_root.iterdir())  # no run folder
    assert lease.path.exists()  # the dead run stays marked


def test_a_start_of_the_inputs_that_hangs_ends_the_run_with_its_reason(config, tmp_path,
                                                                       monkeypatch):
    # a run opens the device (which vents), makes its folder, writes the vent again and starts
    # the inputs; the watchdog comes after. The driver hung in the start: the run sat in it,
    # nothing said, its run.json `running`. Now the start is waited for 2 s (the AO write's
    # timeout and the margin, as `mkm vent`'s), then the run ends failed, exit 1, its reason
    # in run.json and no sample lost (none yet); nothing else is asked of the device but its
    # bounded close, and the bench marker is let go: no pressure was ever commanded.
    import mkm.bench.run as run

    release, calls = threading.Event(), []

    class Hanging(SimBackend):
        def start(self):
            calls.append("start")
            release.wait(10)  # the test's net; released once the run returned
            super().start()

        def write_command(self, volts):
            calls.append(volts)
            super().write_command(volts)

        def read(self, n_samples, timeout_s):
            calls.append("read")
            return super().read(n_samples, timeout_s)

    monkeypatch.setattr(run, "make_backend", lambda c, clock: Hanging(c))
    try:
        result = acquire(config, out_root=tmp_path / "runs", **QUIET)
        still_hung = not release.is_set()
    finally:
        release.set()
    reason = ("starting the device's inputs did not return within 2 s (the driver hangs): the "
              "vent was written before it and no pressure commanded; nothing was acquired")
    assert still_hung and (result.status, result.exit_code) == ("failed", 1)
    assert result.reason == reason and not result.manual_vent_required
    assert calls[calls.index("start"):] == ["start", 0.0]  # then only the close's vent
    saved = load_run(result.path)
    assert (saved.meta.status, saved.meta.reason) == ("failed", reason)
    assert saved.n_samples == 0 and saved.meta.counters["samples"] == 0 and not saved.problems
    assert saved.commands["command_bar"].tolist() == [0.0]  # the vent before the start
    assert not list(bench_folder("sim-Dev1").glob("*.json"))  # nothing pressurised: let go


@pytest.mark.parametrize("command, hangs, said", [
    ("tare", "read", "a read of the device (its timeout 1 s) did not return within 2.5 s"),
    ("calibrate_loadcell", "start", "starting the device's inputs did not return within 2 s"),
])
def test_a_call_that_hangs_in_a_tare_or_a_calibration_ends_it_in_one_line(
        config, monkeypatch, command, hangs, said):
    # `mkm tare` and `mkm calibrate-loadcell` start the inputs and read them with no watchdog:
    # a driver that hung there held the command, nothing said. Now each call is given the bound
    # a run's watchdog gives it (a read: its timeout, its block's time and 1 s; the start: the
    # AO write's timeout and 1 s), then the command ends in one line; the device is closed
    # (bounded) and the bench let go.
    import mkm.bench.procedures as procedures
    from mkm.bench.backend import BenchError

    release = threading.Event()

    class Hanging(SimBackend):
        def start(self):
            if hangs == "start":
                release.wait(10)  # the test's net; released once the command returned
            super().start()

        def read(self, n_samples, timeout_s):
            if hangs == "read":
                release.wait(10)
            return super().read(n_samples, timeout_s)

    monkeypatch.setattr(procedures, "make_backend", lambda c, clock: Hanging(c))
    c = config.replace(daq={"read_timeout_s": 0.5})
    args = (c, [0.0, 5.0]) if command == "calibrate_loadcell" else (c,)
    try:
        with pytest.raises(BenchError) as caught:
            getattr(procedures, command)(*args, seconds=0.5)
        still_hung = not release.is_set()
    finally:
        release.set()
    assert still_hung and str(caught.value) == (
        f"{said} (the driver hangs): nothing was pressurised, and nothing is measured")
    assert not list(bench_folder("sim-Dev1").glob("*"))  # the bench let go


def test_a_vent_refused_with_its_own_vent_by_hand_says_it_once(monkeypatch, mkm_cli):
    # a vent check that failed ends its reason with "VENT BY HAND and check the regulator";
    # the command added "; VENT BY HAND" again
    import mkm.bench.procedures as procedures
    from mkm.bench.backend import BenchError

    def refused(config, **kwargs):
        raise BenchError("the monitor still reads 0.5 bar after 10 s: VENT BY HAND and check "
                         "the regulator")

    monkeypatch.setattr(procedures, "vent", refused)
    code, out, err = mkm_cli(["vent", "--backend", "sim"])
    assert code == 1 and err.count("VENT BY HAND") == 1, err
    assert err.rstrip().endswith("VENT BY HAND and check the regulator")


@pytest.mark.slow  # sends a signal to this process
@pytest.mark.skipif(not hasattr(signal, "pthread_kill"),
                    reason="a signal to the main thread, while it waits, needs pthread_kill")
@pytest.mark.parametrize("command", [["vent"], ["tare"]])
def test_a_ctrl_c_during_the_devices_open_says_the_vent_is_not_known(mkm_cli, monkeypatch,
                                                                     tmp_path, command):
    # Ctrl-C while `mkm vent` waited for the device's open (the driver still in it): the close
    # wrote the vent and cleared the tasks beside the open under way (on NI, no AO task yet),
    # and the command said only "interrupted". Now nothing is written behind the open, and a
    # line says the vent is not known to be written, VENT BY HAND, before "interrupted" (130)
    main, release, closed = threading.main_thread().ident, threading.Event(), []

    class Interrupted(SimBackend):
        def open(self):
            signal.pthread_kill(main, signal.SIGINT)  # to the thread waiting for the open
            release.wait(10)  # the test's net; released once the command returned
            return super().open()

        def close(self):
            closed.append(True)
            super().close()

    code, out, err, still_hung, _ = _command_on(Interrupted, release, command, mkm_cli,
                                                monkeypatch, tmp_path)
    assert still_hung and code == 130 and out == "" and not closed
    assert err.splitlines()[-2:] == [
        f"mkm {command[0]}: interrupted during the device's open: the vent is NOT known to be "
        "written (the open writes it); VENT BY HAND", f"mkm {command[0]}: interrupted"]
