"""bench.worker: the interlocks no NaN disarms, the pressure interlock, vents that fail (issue 12).

Every run here is on the virtual-clock simulated bench with faults injected at sample time; the
short staircase tares for 2 s (samples 0-19) and commands 0.5 bar at 2.0 s.
"""

import errno
import math
import re

import numpy as np
import pytest

from mkm.bench.run import acquire
from mkm.bench.storage import load_run


def record(config, tmp_path, **faults):
    if faults:
        config = config.replace(sim={"faults": faults})
    result = acquire(config, out_root=tmp_path, notify=lambda m: None)
    return result, load_run(result.path)


def assert_vented_last(run):
    last = run.commands.iloc[-1]
    assert last["purpose"] == "vent" and last["ok"] and last["command_bar"] == 0.0


def test_nan_force_trips_the_interlock(config, tmp_path):
    # abs(nan) >= limit is False: before issue 12 a NaN force never tripped anything
    result, run = record(config, tmp_path, nan_force_at_s=5.0)
    assert result.status == "aborted" and result.exit_code == 1
    assert "force interlock: the force reading is not a number" in result.reason
    s = run.samples[run.samples["phase"] != "vent"]  # before the vent check's reads
    assert s["force_N"].iloc[-1] != s["force_N"].iloc[-1]  # the NaN sample is recorded
    assert s["time_s"].iloc[-1] == pytest.approx(5.0) and s["flags"].iloc[-1] == \
        "nonfinite|interlock"
    assert "interlock vent" in set(run.commands["purpose"])
    assert_vented_last(run)


def test_nan_during_the_tare_stops_before_any_pressure(config, tmp_path):
    # A NaN tare used to make every force NaN and the run "complete" with nothing interlocked.
    result, run = record(config, tmp_path, nan_force_at_s=1.0)
    # the NaN sample itself trips the interlock during the tare: no pressure is ever commanded
    assert result.status == "aborted" and "not a number" in result.reason
    assert (run.commands["command_bar"] == 0.0).all()
    assert run.meta.tare is None


def test_noisy_tare_refuses_to_start(config, tmp_path):
    # 50 mV of noise x 196 N/V = 9.8 N rms, above safety.tare_max_std_N = 5 N
    result, run = record(config.replace(sim={"noise_V": 0.05}), tmp_path)
    assert result.status == "failed" and "tare invalid: the load cell spreads" \
        in result.reason
    assert (run.commands["command_bar"] == 0.0).all() and run.steps.empty


def test_shifted_tare_refuses_to_start(config, tmp_path):
    # a 1 V offset (196 N, a load hanging on the cell) against loadcell.offset_V = 0
    result, _ = record(config.replace(sim={"loadcell_offset_V": 1.0}), tmp_path)
    assert result.status == "failed" and "beyond safety.tare_max_shift_N=100" in result.reason


def test_regulator_that_does_not_follow_trips_the_pressure_interlock(config, tmp_path):
    # stuck at 0 bar from 1 s: the 0.5 bar command at 2.0 s is never followed; 0.5 bar is
    # beyond the 0.15 bar tolerance at once, the interlock trips after 5 s of it. Its monitor
    # reads 0 bar before the vent as a monitor stuck at zero would: the vent is not verified
    result, run = record(config, tmp_path, regulator_stuck_at_s=1.0)
    assert result.status == "failed" and result.exit_code == 4
    assert "pressure interlock: the regulator does not follow" in result.reason
    assert "0.5 bar commanded for more than 5 s" in result.reason
    assert "so its reading after it proves nothing" in result.reason
    tripped = run.samples[run.samples["flags"].str.contains("interlock")]
    assert tripped["time_s"].iloc[0] == pytest.approx(2.0 + 5.1, abs=0.051)
    assert_vented_last(run)


def test_regulator_overshoot_trips_the_pressure_interlock(config, tmp_path):
    # 0.3 bar over every command: at a 2.5 bar step it heads for 2.8 > 2.5 + 10 % (2.75 bar),
    # the hard margin, tripped at the first sample over, before the following check (5 s)
    c = config.replace(sequence={"pressures_bar": (2.5,)})
    result, run = record(c, tmp_path, overshoot_bar=0.3)
    assert result.status == "failed" and "(regulator overshoot)" in result.reason
    tripped = run.samples[run.samples["flags"].str.contains("interlock")]
    assert tripped["pressure_bar"].iloc[0] > 2.75
    acquired = run.samples[run.samples["phase"] != "vent"]  # before the vent check's reads
    assert (acquired["pressure_bar"].iloc[:-1] <= 2.75).all()  # the first sample over
    assert_vented_last(run)


def test_failed_interlock_vent_is_named(config, tmp_path):
    # The paper's +-98 N cell trips on the way to 0.5 bar; the AO fails at the interlock's vent.
    c = config.replace(loadcell={"capacity_N": 98.0665, "sensitivity_N_per_V": 9.80665},
                       safety={"tare_max_std_N": 0.5, "tare_max_shift_N": 9.0})
    result, run = record(c, tmp_path, ao_fail_at_s=2.05)
    assert result.status == "aborted"
    assert "force interlock" in result.reason
    assert ("the interlock's vent command failed (the regulator command did not reach the DAQ "
            "device") in result.reason
    # the shutdown's vent went through and was verified: no VENT BY HAND for a vented bench
    assert "the shutdown's vent went through (vent verified: monitor read " in result.reason
    assert "VENT BY HAND" not in result.reason
    failed = run.commands[~run.commands["ok"]]
    assert list(failed["purpose"]) == ["interlock vent"]
    assert_vented_last(run)  # the shutdown's vent, tried again, went through
    assert not run.meta.manual_vent_required


def test_failed_final_vent_asks_for_a_vent_by_hand(config, tmp_path):
    result, run = record(config, tmp_path, disconnect_at_s=7.0)
    assert result.status == "failed" and result.manual_vent_required
    assert "vent command failed (the DAQ device stopped answering" in result.reason
    assert "VENT BY HAND (the regulator may still hold 0.5 bar)" in result.reason
    assert result.exit_code == 4  # the vent was not verified
    assert run.meta.manual_vent_required and "vented by hand" in run.unvented


def test_a_vent_by_hand_names_the_pressure_measured_above_its_command(config, tmp_path):
    # a regulator delivering 0.1 bar above every command (within the follow tolerance), the
    # device lost at 7 s on the 0.5 bar step: the vent never went out. VENT BY HAND said the
    # regulator may still hold 0.5 bar, the command, while its monitor read 0.6: the limits
    # are watched on what is measured. Now it names the monitor's reading, the command beside
    # (a reading within the monitor's declared error, 0.04 bar, of its command is not named)
    result, run = record(config, tmp_path, disconnect_at_s=7.0, overshoot_bar=0.1)
    assert result.exit_code == 4
    assert "vent command failed (the DAQ device stopped answering" in result.reason
    before = run.samples[run.samples["phase"] != "vent"]
    # the monitor's median over the last 0.5 s (5 samples at 10 Hz) before the vent
    read = before["pressure_bar"].iloc[-5:].median()
    assert read == pytest.approx(0.6, abs=0.01)  # 0.5 bar commanded, 0.1 bar overshoot
    assert result.reason.endswith(f"VENT BY HAND (the regulator may still hold {read:.3g} bar, "
                                  "as the monitor read before the vent, with 0.5 bar "
                                  "commanded)")
    # the bench stays marked: the next command on it vents first and says why
    import json

    from mkm.bench.unvented import bench_folder

    (marker,) = [json.loads(p.read_text()) for p in bench_folder("sim-Dev1").glob("*.json")]
    assert marker["run_path"] == str(run.path) and marker["last_command_bar"] == 0.5


def test_stall_shorter_than_the_buffer_delays_but_loses_nothing(config, tmp_path):
    # A 5 s stall with a 10 s buffer at 1.0 s: the samples wait in the buffer, none is lost, and
    # the hardware is at 6.0 s when the reader resumes at 1.0 s; the 0.5 bar command, written
    # when the reader reaches 2.0 s (the virtual reader catches up instantly), lands at 6.0 s,
    # and commands.csv says so; the samples acquired before it were acquired at 0 bar
    from mkm.bench.run import BenchRun
    from mkm.bench.sim import SimBackend

    c = config.replace(sim={"buffer_s": 10.0, "faults": {"stall_at_s": 1.0, "stall_s": 5.0}})
    backend = SimBackend(c)
    result = BenchRun(c, backend, tmp_path, handle_signals=False, notify=lambda m: None
                      ).execute()
    run = load_run(result.path)
    assert result.status == "complete" and run.meta.lost_samples == 0
    np.testing.assert_array_equal(run.samples["sample"], np.arange(len(run.samples)))
    written = run.commands[run.commands.purpose == "step"].iloc[0]
    applied = [k for k, volts in backend.commands if volts > 0][0]
    assert (written["sample"], applied) == (60, 60) and written["time_s"] == 6.0
    s = run.samples
    assert set(s["command_bar"].iloc[:60]) == {0.0} and s["command_bar"].iloc[60] == 0.5


def test_stall_longer_than_the_buffer_loses_the_samples(config, tmp_path):
    c = config.replace(sim={"buffer_s": 10.0})
    result, run = record(c, tmp_path, stall_at_s=1.0, stall_s=11.0)
    assert result.status == "complete_with_gaps" and run.meta.lost_samples == 110
    assert math.isclose(run.meta.gaps[0].end_s - run.meta.gaps[0].start_s, 11.0)


def test_samples_waiting_in_the_buffer_at_a_stop_are_recorded(config, tmp_path):
    # A 5 s stall at 3.0 s (0.5 bar commanded): samples 30-79 wait in the buffer; the first,
    # a NaN force, trips the interlock. The 49 behind it were acquired before the stop: they
    # are recorded (before the fix the vent check read and dropped them), no interlock judged.
    result, run = record(config, tmp_path, stall_at_s=3.0, stall_s=5.0, nan_force_at_s=3.0)
    assert result.status == "aborted" and "force interlock" in result.reason
    assert run.meta.counters["samples"] == len(run.samples) and run.meta.lost_samples == 0
    s = run.samples[run.samples["phase"] != "vent"]  # then the vent check's reads
    np.testing.assert_array_equal(s["sample"], np.arange(80))
    assert list(s["flags"].iloc[29:]) == ["", "nonfinite|interlock"] + ["nonfinite"] * 49
    assert set(s["phase"].iloc[30:]) == {"step"} and set(s["step"].iloc[30:]) == {0}
    # acquired under the 0.5 bar command: the vent was issued when the hardware was at 8.0 s
    assert set(s["command_bar"].iloc[20:]) == {0.5}
    vent = run.commands[run.commands["purpose"] == "interlock vent"].iloc[0]
    assert vent["sample"] == 80 and vent["time_s"] == 8.0
    assert_vented_last(run)


@pytest.mark.parametrize("faults", [
    {"nan_force_at_s": 5.0},  # the reader keeps up: the vent at the sample that tripped it
    {"stall_at_s": 3.0, "stall_s": 5.0, "nan_force_at_s": 3.0},  # 49 samples waiting
])
def test_the_vent_is_recorded_at_the_time_it_was_issued(config, tmp_path, faults):
    # A safety log says when the vent was commanded: commands.csv's time of the interlock's
    # vent is the simulated device's sample clock at its write (the sample from which the
    # regulator has it), to the clock's resolution (one sample, 0.1 s at 10 Hz), however far
    # behind the reader is
    from mkm.bench.run import BenchRun
    from mkm.bench.sim import SimBackend

    c = config.replace(sim={"faults": faults})
    backend = SimBackend(c)
    result = BenchRun(c, backend, tmp_path, handle_signals=False, notify=lambda m: None
                      ).execute()
    run = load_run(result.path)
    assert result.status == "aborted" and "force interlock" in result.reason
    vent = run.commands[run.commands["purpose"] == "interlock vent"].iloc[0]
    pressurised = [k for k, volts in backend.commands if volts > 0][-1]
    issued = [k for k, volts in backend.commands if k > pressurised and volts == 0][0]
    assert vent["sample"] == issued
    assert vent["time_s"] == pytest.approx(issued / 10.0, abs=0.1)
    # after every sample acquired before it: the regulator vented at or after the trip
    tripped = run.samples[run.samples["flags"].str.contains("interlock")]["time_s"].iloc[0]
    assert vent["time_s"] >= tripped


def test_a_cell_noisier_than_the_settle_limit_is_said_at_the_tare(config, tmp_path):
    # 20 mV of noise x 196 N/V: some 3-4 N rms at rest, inside safety.tare_max_std_N = 5 N,
    # above settle.max_force_std_N = 1.5 N, so no step can settle; said once the tare is taken
    said = []
    result = acquire(config.replace(sim={"noise_V": 0.02}), out_root=tmp_path,
                     notify=said.append)
    warning = [m for m in said if "above settle.max_force_std_N=1.5: no step can settle" in m]
    assert len(warning) == 1
    spread, advice = map(float, re.search(r"spreads ([\d.]+) N rms.*to about ([\d.]+)",
                                          warning[0]).groups())
    assert spread == pytest.approx(load_run(result.path).meta.tare["std_N"], abs=0.005)
    assert advice == pytest.approx(3 * spread, rel=0.05)
    assert not load_run(result.path).steps["settled"].any()
    quiet = []
    acquire(config, out_root=tmp_path, notify=quiet.append)  # the default cell settles
    assert not any("settle.max_force_std_N" in m for m in quiet)


def test_the_tare_reads_the_monitors_zero_and_says_one_beyond_its_bound(config, tmp_path):
    # vented, the true pressure is 0: the monitor reads its offset, within its 1 mV (1 mbar)
    # noise over root 25 readings of the tare's second half
    small = config.replace(sequence={"pressures_bar": (0.5,), "down_sweep": False,
                                     "preconditioning_cycles": 0})
    said = []
    run = load_run(acquire(small.replace(sim={"truth": {"monitor_offset_bar": 0.046}}),
                           out_root=tmp_path, notify=said.append).path)
    tare = run.meta.tare
    assert tare["monitor_vented_settled"]
    assert 0.0001 < tare["monitor_vented_se_bar"] < 0.0004
    # the simulated monitor's default hysteresis: half of it below on a falling branch
    assert tare["monitor_vented_bar"] == pytest.approx(0.046, abs=0.002)
    warning = [m for m in said if "vented, beyond the +-0.04 bar" in m]
    assert len(warning) == 1 and re.search(r"reads \+0\.04[4-8]\d* bar", warning[0])
    quiet = []
    run = load_run(acquire(small, out_root=tmp_path, notify=quiet.append).path)
    assert abs(run.meta.tare["monitor_vented_bar"]) < 0.003
    assert not any("vented, beyond" in m for m in quiet)


def test_a_monitor_that_cannot_verify_a_vent_stops_the_run_at_the_tare(config, tmp_path):
    # 0.2 bar high vented: every vent check of the run would fail with the muscle empty (and
    # 0.08 bar low, pass with it holding 0.08 bar; lower, the 1-5 V output is a fault below
    # 0.9 V): refused before any pressure
    for offset in (0.2, -0.08):
        bad = config.replace(sim={"truth": {"monitor_offset_bar": offset}})
        result = acquire(bad, out_root=tmp_path, notify=lambda message: None)
        run = load_run(result.path)
        assert result.status == "failed" and "tare invalid: the pressure monitor reads" in \
            result.reason and "beyond safety.vent_below_bar=0.05" in result.reason
        assert (run.commands["command_bar"] == 0).all()  # never pressurised
        assert (run.samples["phase"] == "tare").any()  # the tare's samples are kept


def test_a_pressure_still_falling_at_the_tare_gives_no_zero():
    from mkm.bench.sequence import vented_monitor

    rng = np.random.default_rng(0)
    noise = rng.normal(0.0, 0.001, 50)
    at_rest = vented_monitor(0.01 + noise)
    assert at_rest["monitor_vented_settled"]
    assert at_rest["monitor_vented_bar"] == pytest.approx(0.01, abs=0.001)
    # a muscle emptying through the vent (time constant 2 s, 10 Hz) during the tare
    falling = vented_monitor(0.01 + 0.3 * np.exp(-np.arange(50) / 20.0) + noise)
    assert not falling["monitor_vented_settled"]
    assert vented_monitor([0.0, np.nan, 0.0]) == {}


def test_samples_read_late_are_judged_against_the_command_they_were_acquired_under(config,
                                                                                   tmp_path):
    # A 6 s stall at 1.0 s: the 0.5 bar command, written when the reader reaches 2.0 s, acts
    # at 7.0 s; the samples 2.0-6.9 s, read after it, were acquired at 0 bar under the vent.
    # Judged against the newest command they were "0.5 bar off for more than 5 s" and tripped
    # the follow interlock on a regulator that followed every command
    c = config.replace(sim={"buffer_s": 10.0})
    result, run = record(c, tmp_path, stall_at_s=1.0, stall_s=6.0)
    assert result.status == "complete", result.reason
    s = run.samples
    assert not s["flags"].str.contains("interlock").any()
    late = s[s["command_bar"] < s["set_pressure_bar"]]  # acquired before their step's command
    assert len(late) > 0 and (abs(late["pressure_bar"] - late["command_bar"]) < 0.15).all()


def test_a_regulator_that_stops_following_after_a_stall_still_trips(config, tmp_path):
    # the same stall, with the regulator stuck from 4 s: judged against the commands the
    # samples were acquired under, it trips 5 s after the first command it did not follow
    c = config.replace(sim={"buffer_s": 10.0})
    result, run = record(c, tmp_path, stall_at_s=1.0, stall_s=6.0, regulator_stuck_at_s=1.0)
    assert result.status == "failed" and result.manual_vent_required, result.reason  # at 0 bar
    assert "pressure interlock: the regulator does not follow" in result.reason
    assert_vented_last(run)


def _order_of_writes(monkeypatch):
    """Every AO write (volts) and every samples.csv append (last sample index), in order."""
    from mkm.bench.sim import SimBackend
    from mkm.bench.storage import RunWriter

    events: list[tuple[str, float]] = []
    write, append = SimBackend.write_command, RunWriter.append_samples

    def spy_write(self, volts):
        write(self, volts)
        events.append(("AO", float(volts)))

    def spy_append(self, rows):
        append(self, rows)
        events.append(("samples", rows[-1].sample))

    monkeypatch.setattr(SimBackend, "write_command", spy_write)
    monkeypatch.setattr(RunWriter, "append_samples", spy_append)
    return events


@pytest.mark.parametrize("block", [1, 5])
def test_an_interlock_vents_before_its_block_is_written(config, tmp_path, monkeypatch, block):
    # acts first, keeps books after: the NaN force at 5.0 s (sample 50) trips the interlock;
    # its vent goes out before that block is written to samples.csv (by the recorder's thread,
    # which may still be writing the blocks before it)
    events = _order_of_writes(monkeypatch)
    c = config.replace(daq={"read_block_samples": block})
    result, run = record(c, tmp_path, nan_force_at_s=5.0)
    assert "force interlock: the force reading is not a number" in result.reason
    tripped = next(i for i, e in enumerate(events) if e[0] == "samples" and e[1] >= 50)
    assert events[tripped] == ("samples", 50 + block - 1)  # the block holding sample 50
    vent = events.index(("AO", 0.0), events.index(("AO", 1.25)))  # the first after 0.5 bar
    assert vent < tripped  # the interlock's vent, then the rows
    assert run.meta.counters["samples"] == len(run.samples)
    assert (run.samples["phase"] != "vent").sum() == events[tripped][1] + 1
    vent = run.commands[run.commands["purpose"] == "interlock vent"].iloc[0]
    assert vent["sample"] == events[tripped][1] + 1  # issued just after the block's last sample


def test_a_disk_that_fails_the_tripping_block_keeps_the_interlocks_reason(config, tmp_path,
                                                                            monkeypatch):
    # the NaN sample's block cannot be written (disk full): the run still vents first and says
    # the interlock, then the disk, not a bare "recording failed"; samples 50 on are kept
    # outside the run folder, whose record is not whole: exit 2, a failed disk's
    from mkm.bench.storage import RunWriter

    events = _order_of_writes(monkeypatch)
    append = RunWriter.append_samples

    def full_at_50(self, rows):
        if rows[-1].sample >= 50:
            raise OSError(errno.ENOSPC, "No space left on device")
        append(self, rows)

    monkeypatch.setattr(RunWriter, "append_samples", full_at_50)
    result, run = record(config, tmp_path, nan_force_at_s=5.0)
    assert result.status == "aborted" and result.exit_code == 2
    assert result.reason.startswith("force interlock: the force reading is not a number")
    assert "; vented; the disk refused samples 50 (No space left on device), and " \
           in result.reason
    assert ("AO", 0.0) in events
    assert run.meta.counters["samples"] == len(run.samples) == 50  # samples 0-49 kept
    assert run.commands["purpose"].iloc[-2:].tolist() == ["interlock vent", "vent"]


def test_an_interlock_vent_whose_record_fails_is_not_called_a_failed_vent(config, tmp_path,
                                                                          monkeypatch):
    # the vent went out, only its row of commands.csv met a full disk: the run must not say
    # that the vent command failed and ask for a vent by hand while the regulator is vented
    from mkm.bench.storage import RunWriter

    events = _order_of_writes(monkeypatch)
    append = RunWriter.append_command

    def full_for_the_interlock(self, row):
        if row.purpose == "interlock vent":
            raise OSError(errno.ENOSPC, "No space left on device")
        append(self, row)

    monkeypatch.setattr(RunWriter, "append_command", full_for_the_interlock)
    result, run = record(config, tmp_path, nan_force_at_s=5.0)
    # commands.csv lacks the vent's row: the record is not whole in its folder, exit 2
    assert result.status == "aborted" and result.exit_code == 2
    assert "vent command failed" not in result.reason and "VENT BY HAND" not in result.reason
    assert "; vented; recording failed for the interlock vent command of 0 bar (No space " \
           "left on device)" in result.reason
    assert not result.manual_vent_required and run.meta.vent_check["verified"]
    # the vent before the tripping block's rows (the recorder's thread may still be writing
    # the blocks before it)
    vent = events.index(("AO", 0.0), events.index(("AO", 1.25)))  # the first after 0.5 bar
    assert vent < events.index(("samples", 50))


def test_a_shutdown_vent_that_fails_after_an_interlock_vent_is_called_failed(config, tmp_path,
                                                                            monkeypatch):
    # the interlock vented; the shutdown's own vent write then fails: that is a failed write,
    # not "recording the vent failed" (which an earlier successful vent used to make it)
    from mkm.bench.backend import AOWriteFailed
    from mkm.bench.sim import SimBackend

    write, zeros = SimBackend.write_command, []

    def second_vent_fails(self, volts):
        if volts == 0.0 and self._started_at is not None:
            zeros.append(volts)
            if len(zeros) == 3:  # the tare's, the interlock's went out; the shutdown's fails
                raise AOWriteFailed("simulated AO write failure")
        write(self, volts)

    monkeypatch.setattr(SimBackend, "write_command", second_vent_fails)
    result, run = record(config, tmp_path, nan_force_at_s=5.0)
    assert "recording the vent failed" not in result.reason
    assert ("; vent command failed (the regulator command did not reach the DAQ device: check its "
            "USB cable and power (simulated AO write failure)), tried again") in result.reason
    assert run.commands["purpose"].iloc[-3:].tolist() == ["interlock vent", "vent", "vent"]
    assert run.commands["ok"].iloc[-3:].tolist() == [True, False, True]


@pytest.mark.parametrize("stuck_s", [6.0, 8.0, 10.5, 16.0])
def test_a_stuck_regulator_trips_within_the_follow_time_whatever_is_commanded(tmp_path, stuck_s):
    # The paper's sequence: pre-conditioning to 2.5 bar at 5 s and back to 0 at 10 s, held 5 s
    # each (pressure_follow_s), then the staircase from 15 s. The window used to restart at each
    # new command: stuck from 6 s (rising towards 2.5 bar), it tripped only at 20.1 s, and
    # pre-conditioning could never trip it. Now it trips pressure_follow_s (and a block) after
    # the first sample, from the moment it sticks, at which its pressure is off the command
    from mkm.bench.config import load_config

    c = load_config()
    result, run = record(c, tmp_path, regulator_stuck_at_s=stuck_s)
    assert result.status in ("aborted", "failed"), result.reason
    assert "pressure interlock: the regulator does not follow" in result.reason
    s = run.samples
    tol, follow = c.safety.pressure_tolerance_bar, c.safety.pressure_follow_s
    block_s = c.daq.read_block_samples / c.daq.sample_rate_hz
    failing = s[(s["time_s"] >= stuck_s - 1e-9)
                & ((s["pressure_bar"] - s["command_bar"]).abs() > tol)]
    tripped = s[s["flags"].str.contains("interlock")]["time_s"].iloc[0]
    assert tripped - failing["time_s"].iloc[0] <= follow + 1 / c.daq.sample_rate_hz + block_s
    assert "interlock vent" in set(run.commands["purpose"])


def test_a_healthy_regulator_never_trips_the_follow_interlock_on_the_papers_sequence(tmp_path):
    # every step response of the simulator's regulator (0.4 s lag, 2 bar/s slew), the 2.5 bar
    # pre-conditioning steps included, and a sensor with the truth's hysteresis and bow
    from mkm.bench.config import load_config

    for truth in ({}, {"monitor_hysteresis_bar": 0.05, "monitor_bow_bar": 0.03}):
        c = load_config().replace(sim={"truth": truth})
        result, run = record(c, tmp_path)
        assert result.status == "complete", result.reason
        assert not run.samples["flags"].str.contains("interlock").any()


@pytest.mark.parametrize("faults", [{}, {"regulator_stuck_at_s": 4.0}])
def test_the_vent_checks_own_samples_are_recorded(config, tmp_path, faults):
    # the samples read after the vent, while the monitor was watched for it, were dropped: the
    # pressure's decay (or a stuck regulator's pressure that did not decay) was not on disk
    result, run = record(config, tmp_path, **faults)
    s, check = run.samples, run.meta.vent_check
    vent = s[s["phase"] == "vent"]
    assert len(vent) > 0 and (vent["step"] == -1).all() and (vent["command_bar"] == 0.0).all()
    assert vent["sample"].iloc[0] >= run.commands["sample"].iloc[-1]  # after the final vent
    assert vent["pressure_bar"].iloc[-1] == pytest.approx(check["pressure_bar"], abs=1e-6)
    assert vent["time_s"].iloc[-1] - vent["time_s"].iloc[0] == pytest.approx(
        check["waited_s"] - 0.1, abs=0.051)
    assert list(s["sample"]) == list(range(len(s)))  # no sample missing, none twice
    assert run.meta.counters["samples"] == len(s)
    if faults:  # the stuck regulator's pressure, held for the whole check, is on disk
        assert not check["verified"] and (vent["pressure_bar"] > 0.15).all()
    else:
        assert check["verified"] and vent["pressure_bar"].is_monotonic_decreasing


def test_an_interlock_whose_block_the_disk_refuses_once_keeps_its_samples_and_reason(
        config, tmp_path, monkeypatch):
    # the NaN force at 5.0 s (sample 50) trips the interlock; SIGTERM arrives while that block
    # is read (held to the block's end), and the disk refuses the block once (EIO): the block,
    # its interlock flag with it, was lost, and the reason did not say so. Now the block is
    # written again after it, and the reason keeps the interlock, the disk and the signal
    import signal

    from mkm.bench.run import BenchRun
    from mkm.bench.sim import SimBackend
    from mkm.bench.storage import RunWriter

    append, refused = RunWriter.append_samples, []

    def refuses_once(self, rows):
        if any(r.sample == 50 for r in rows) and not refused:
            refused.append(rows[0].sample)
            raise OSError(errno.EIO, "Input/output error")
        append(self, rows)

    monkeypatch.setattr(RunWriter, "append_samples", refuses_once)
    c = config.replace(sim={"faults": {"nan_force_at_s": 5.0}})
    backend = SimBackend(c)
    read = backend.read

    def signalled_at_50(n, timeout):
        block = read(n, timeout)
        if block.first_index == 50:
            signal.raise_signal(signal.SIGTERM)  # its handler runs before read returns
        return block

    backend.read = signalled_at_50
    result = BenchRun(c, backend, tmp_path, handle_signals=True, notify=lambda m: None).execute()
    run = load_run(result.path)
    assert refused == [50]
    assert result.status == "aborted" and result.exit_code == 128 + signal.SIGTERM
    assert result.reason.startswith("force interlock: the force reading is not a number")
    assert "; vented; SIGTERM received meanwhile" in result.reason
    assert "the disk refused samples 50 (Input/output error); written " \
           "again" in result.reason
    assert run.meta.reason == result.reason and run.meta.stop_signal == "SIGTERM"
    s = run.samples
    assert list(s["sample"]) == list(range(len(s)))  # none lost, none twice
    assert s.loc[s["sample"] == 50, "flags"].tolist() == ["nonfinite|interlock"]
    assert run.meta.counters["samples"] == len(s)
    assert_vented_last(run)
    assert run.meta.vent_check["verified"]
