"""The NI backend through nidaqmx's real Python code, with the driver layer faked.

As nidaqmx's own unit tests do, ``nidaqmx.utils._select_interpreter`` is patched to return an
autospec of ``nidaqmx._base_interpreter.BaseInterpreter`` (fixture ``fake_driver`` in
conftest.py), so every call nidaqmx would make into the C driver is recorded and can be asserted.
Run these alone with ``pytest -m mocked_hardware``.
"""

import inspect
import re
from importlib.metadata import version

import pytest
from nidaqmx.constants import AcquisitionType, Edge, TerminalConfiguration, VoltageUnits
from nidaqmx.errors import DaqError, DaqNotFoundError, DaqReadError, DaqWriteError

from mkm.bench.backend import (
    AOWriteFailed,
    BenchError,
    BufferOverflow,
    DaqDisconnected,
    DeviceReserved,
    DriverMissing,
    ReadTimeout,
)
from mkm.bench.ni import REVIVE_EVERY_S, REVIVE_WITHIN_S, NIBackend
from mkm.bench.run import acquire
from mkm.bench.storage import load_run

pytestmark = pytest.mark.mocked_hardware

AI, AO = "handle-mkm_ai", "handle-mkm_ao"


@pytest.fixture
def instant_clock(monkeypatch):
    """The NI backend's clock, whose sleeps pass at once: a device lost for good is retried
    until its bound without the test waiting for it, and the bound is counted exactly."""
    from types import SimpleNamespace

    import mkm.bench.ni as ni

    clock = {"t": 0.0}
    monkeypatch.setattr(ni, "time", SimpleNamespace(
        monotonic=lambda: clock["t"], sleep=lambda s: clock.update(t=clock["t"] + s)))
    return clock


def calls(driver, name):
    return [c for c in driver.interpreter.mock_calls if c[0] == name]


def test_tasks_channels_and_clock(config, fake_driver):
    backend = NIBackend(config)
    info = backend.open()
    it = fake_driver.interpreter
    # one AI task with both inputs, differential, +-10 V: never the driver defaults
    assert [c.args for c in calls(fake_driver, "create_ai_voltage_chan")] == [
        (AI, f"Dev1/{ch}", "", TerminalConfiguration.DIFF.value, -10.0, 10.0,
         VoltageUnits.VOLTS.value, "") for ch in ("ai0", "ai1")]
    # hardware clock, 10 Hz, continuous, 10 minutes of buffer (6000 samples)
    it.cfg_samp_clk_timing.assert_called_once_with(
        AI, 10.0, "", Edge.RISING.value, AcquisitionType.CONTINUOUS.value, 6000)
    it.set_buffer_attribute_uint32.assert_called_once_with(AI, 0x186C, 6000)  # input_buf_size
    it.create_ao_voltage_chan.assert_called_once_with(AO, "Dev1/ao0", "", 0.0, 10.0,
                                                      VoltageUnits.VOLTS.value, "")
    # vented at open
    assert calls(fake_driver, "write_analog_scalar_f64")[0].args == (AO, False, 1.0, 0.0)
    # the AO task started (reserved) before its first write, not auto-started by each write
    names = [c[0] for c in it.mock_calls]
    assert names.index("start_task") < names.index("write_analog_scalar_f64")
    assert calls(fake_driver, "start_task")[0].args == (AO,)
    # read back: actual rate, product type, serial number
    assert info.sample_rate_hz == 10.0 and info.product_type == "USB-6001"
    assert info.serial_number == "1F2E3D4" and not info.simulated
    backend.close()


def test_actual_clock_rate_is_recorded(config, fake_driver):
    fake_driver.interpreter.get_timing_attribute_double.return_value = 10.000016
    info = NIBackend(config).open()
    assert info.sample_rate_hz == 10.000016


def test_terminal_config_is_a_setting(config, fake_driver):
    NIBackend(config.replace(daq={"terminal_config": "rse"})).open()
    terminal = {c.args[3] for c in calls(fake_driver, "create_ai_voltage_chan")}
    assert terminal == {TerminalConfiguration.RSE.value}


def test_manual_regulator_has_no_ao(config, fake_driver):
    c = config.replace(regulator={"kind": "manual"})
    fake_driver.n_channels = 1
    NIBackend(c).open()
    assert [c.args[1] for c in calls(fake_driver, "create_ai_voltage_chan")] == ["Dev1/ai0"]
    assert not calls(fake_driver, "create_ao_voltage_chan")


def test_whole_run_writes_commands_and_vents_before_clearing(config, fake_driver, tmp_path):
    result = acquire(config, backend="ni", out_root=tmp_path)
    assert result.status == "complete", result.reason
    run = load_run(result.path)
    assert run.meta["hardware"]["backend"] == "ni" and run.meta["hardware"]["simulated"] is False
    writes = [c.args[3] for c in calls(fake_driver, "write_analog_scalar_f64")]
    # 0.5, 1.0, 0.5 bar over a 4 bar / 10 V regulator; vents (0 V) around them
    assert [w for w in writes if w > 0] == pytest.approx([1.25, 2.5, 1.25])
    assert writes[-1] == 0.0
    names = [c[0] for c in fake_driver.interpreter.mock_calls]
    last_write = max(i for i, n in enumerate(names) if n == "write_analog_scalar_f64")
    clears = [i for i, n in enumerate(names) if n == "clear_task"]
    assert len(clears) == 2 and last_write < min(clears)
    reads = calls(fake_driver, "read_analog_f64")
    assert all(c.args[1] == 1 and c.args[2] == 2.0 for c in reads)  # 1-sample blocks, 2 s
    # every read is a recorded sample, the vent check's after the final vent included (phase
    # vent): one sample each until the monitor read below 0.05 bar (0.1 s of sample time each)
    vent_check = run.meta.vent_check
    assert vent_check["verified"] and vent_check["pressure_bar"] < 0.05
    assert len(reads) == len(run.samples)
    assert (run.samples["phase"] == "vent").sum() == round(vent_check["waited_s"] / 0.1)
    assert [c.args for c in calls(fake_driver, "start_task")] == [(AO,), (AI,)]


@pytest.mark.parametrize("code, error", [
    (-200279, BufferOverflow), (-200361, BufferOverflow), (-200284, ReadTimeout),
    (-50405, DaqDisconnected),
    (-201003, DaqDisconnected), (-200324, DaqDisconnected), (-50103, DeviceReserved),
    (-200022, DeviceReserved),
])
def test_read_error_codes_are_mapped(config, fake_driver, code, error):
    backend = NIBackend(config)
    backend.open()
    backend.start()
    fake_driver.interpreter.read_analog_f64.side_effect = DaqReadError("driver says no", code, 0)
    with pytest.raises(error, match=f"NI-DAQmx error {code}: driver says no"):
        backend.read(1, 2.0)


def test_ao_write_error_is_mapped(config, fake_driver):
    backend = NIBackend(config)
    backend.open()
    fake_driver.interpreter.write_analog_scalar_f64.side_effect = DaqWriteError("bad", -200000, 0)
    with pytest.raises(AOWriteFailed):
        backend.write_command(1.0)


def test_reserved_device_at_open(config, fake_driver):
    fake_driver.interpreter.create_ai_voltage_chan.side_effect = DaqError("in use", -50103)
    backend = NIBackend(config)
    with pytest.raises(DeviceReserved):
        backend.open()
    fake_driver.interpreter.clear_task.assert_called_once_with(AI)  # nothing left reserved


def test_a_device_error_is_said_in_words_with_what_to_do(fake_driver, capsys):
    """`mkm check` on a device another program holds said the driver's words alone ("NI-DAQmx
    error -50103: ..."), and a run's reason began with the error's class ("DeviceReserved:
    ..."): now what failed and what to do, the driver's words in brackets, exit 1; a code mkm
    does not map says where to look."""
    from mkm.cli import main

    fake_driver.interpreter.create_ai_voltage_chan.side_effect = DaqError(
        "The specified resource is reserved.\nTask Name: mkm_ai", -50103)
    assert main(["check", "--backend", "ni"]) == 1
    assert capsys.readouterr().err == (
        "mkm check: error: another program holds the DAQ device (NI MAX's test panel, LabVIEW, "
        "another mkm): close it, then try again (NI-DAQmx error -50103: The specified resource "
        "is reserved.)\n")
    fake_driver.interpreter.create_ai_voltage_chan.side_effect = DaqError("Some fault", -200077)
    assert main(["check", "--backend", "ni"]) == 1
    assert capsys.readouterr().err == (
        "mkm check: error: the DAQ device or its driver failed (NI-DAQmx error -200077: Some "
        "fault): check its USB cable and power, and run its self-test in NI MAX\n")


def test_driver_missing_is_one_clear_message(config, fake_driver):
    fake_driver.interpreter.create_task.side_effect = DaqNotFoundError("no lib")
    with pytest.raises(DriverMissing, match="python -m nidaqmx installdriver.* --backend sim"):
        NIBackend(config).open()


def test_disconnect_mid_run_vents_then_clears(config, fake_driver, tmp_path):
    reads = {"n": 0}
    normal = fake_driver.read

    def read(*args):
        reads["n"] += 1
        if reads["n"] > 30:
            raise DaqReadError("USB transfer aborted", -50405, 0)
        return normal(*args)

    fake_driver.interpreter.read_analog_f64.side_effect = read
    result = acquire(config, backend="ni", out_root=tmp_path)
    assert result.status == "failed"
    assert result.reason.startswith("the DAQ device stopped answering: check its USB cable and "
                                    "power (NI-DAQmx error -50405: USB transfer aborted); ")
    assert len(load_run(result.path).samples) == 30
    mock_calls = fake_driver.interpreter.mock_calls
    first_clear = [c[0] for c in mock_calls].index("clear_task")
    # the vent is the last write before any task is cleared, and the last write of all
    before = [c for c in mock_calls[:first_clear] if c[0] == "write_analog_scalar_f64"]
    assert before[-1].args[3] == 0.0 and max(c.args[3] for c in before) > 0
    assert fake_driver.interpreter.write_analog_scalar_f64.call_args.args[3] == 0.0


def test_overflow_restarts_the_task_and_counts_the_lost_samples(config, fake_driver, tmp_path):
    # The reader falls 6100 samples behind a 6000-sample buffer: the driver reports -200279.
    # Restarting discards all 6100; the backend counts them from the hardware's sample count
    # (total_samp_per_chan_acquired), not from the wall clock (issue 12: it recorded 0).
    reads = {"n": 0}
    normal = fake_driver.read

    def read(*args):
        reads["n"] += 1
        if reads["n"] == 25:
            fake_driver.overflow(6100)
            raise DaqReadError("samples overwritten", -200279, 0)
        return normal(*args)

    fake_driver.interpreter.read_analog_f64.side_effect = read
    result = acquire(config, backend="ni", out_root=tmp_path)
    assert result.status == "complete_with_gaps" and result.exit_code == 3
    run = load_run(result.path)
    (gap,) = run.meta.gaps
    assert gap.lost_samples == 6100 and run.meta.lost_samples == 6100
    assert (gap.start_s, gap.end_s) == (2.4, 612.4)  # samples 24 .. 6123 at 10 Hz
    s = run.samples
    assert s["sample"].iloc[24] == 24 + 6100 and s["flags"].iloc[24] == "gap"
    assert (s["flags"] == "gap").sum() == 1
    assert fake_driver.interpreter.stop_task.call_count == 1
    assert [c.args for c in calls(fake_driver, "start_task")].count((AI,)) == 2


def test_close_alone_writes_0_V_last_before_clearing(config, fake_driver):
    # procedures.session relies on close() alone: the run's shutdown is not there to vent
    backend = NIBackend(config)
    backend.open()
    backend.write_command(6.25)  # 2.5 bar on a 4 bar / 10 V regulator
    backend.close()
    names = [c[0] for c in fake_driver.interpreter.mock_calls]
    writes = calls(fake_driver, "write_analog_scalar_f64")
    assert writes[-1].args[3] == 0.0 and writes[-2].args[3] == 6.25
    last_write = max(i for i, n in enumerate(names) if n == "write_analog_scalar_f64")
    assert last_write < min(i for i, n in enumerate(names) if n == "clear_task")


def test_a_device_simulated_in_ni_max_is_refused(config, fake_driver):
    fake_driver.interpreter.get_device_attribute_bool.return_value = True  # is_simulated
    with pytest.raises(BenchError, match="Dev1 is a simulated USB-6001 \\(NI MAX\\): no "
                                         "hardware would be driven"):
        NIBackend(config).open()
    assert not calls(fake_driver, "create_task")


def test_a_pulled_cable_mid_run_asks_for_a_vent_by_hand(config, fake_driver, tmp_path,
                                                        instant_clock):
    # reads and writes fail alike once the device is gone: the vent cannot be written, so the
    # run cannot claim one (the fake driver used to accept writes after a disconnect)
    reads = {"n": 0}
    normal = fake_driver.read

    def read(*args):
        reads["n"] += 1
        if reads["n"] > 30:
            fake_driver.disconnect()
            return fake_driver.interpreter.read_analog_f64(*args)
        return normal(*args)

    fake_driver.interpreter.read_analog_f64.side_effect = read
    result = acquire(config, backend="ni", out_root=tmp_path)
    assert result.status == "failed" and result.exit_code == 4 and result.manual_vent_required
    assert "vent command failed" in result.reason and "VENT BY HAND" in result.reason


def test_a_pulled_cable_at_the_tare_says_no_pressure_was_applied(config, fake_driver, tmp_path,
                                                                  instant_clock):
    # the device is gone 10 readings into the 2 s tare, nothing above 0 bar ever commanded,
    # and stays gone through its reset: the run ended "VENT BY HAND (the regulator may still
    # hold 0.000977 bar)", exit 4, a muscle never pressurised. It says so, and what it cannot
    # confirm, exit 1
    _lost_after(fake_driver, 10)
    result = acquire(config, backend="ni", out_root=tmp_path)
    assert result.status == "failed" and result.exit_code == 1, result.reason
    assert not result.manual_vent_required and "VENT BY HAND" not in result.reason
    assert re.search(r"; no pressure was applied: this run commanded none above 0 bar \(0 bar "
                     r"was the last command the device took\) and the monitor read at most "
                     r"0\.00\d bar; its vent could not be confirmed \(the device is gone\); see "
                     r"that the regulator reads 0 bar before the next run", result.reason), \
        result.reason
    assert "resetting the device did not bring it back" in result.reason
    run = load_run(result.path)
    assert len(run.samples) == 10 and run.meta.vent_check is None
    assert max(c.args[3] for c in calls(fake_driver, "write_analog_scalar_f64")) == 0.0


def _lost_after(fake_driver, n_reads):
    """Reads work ``n_reads`` times, then the device is gone (reads and writes fail, -50405)."""
    reads = {"n": 0}
    normal = fake_driver.read

    def read(*args):
        reads["n"] += 1
        if reads["n"] > n_reads:
            fake_driver.disconnect()
            return fake_driver.interpreter.read_analog_f64(*args)
        return normal(*args)

    fake_driver.interpreter.read_analog_f64.side_effect = read


def test_a_device_back_after_a_reset_is_vented_and_verified(config, fake_driver, tmp_path):
    # the regulator holds 1.25-2.5 V (0.5-1 bar) when the transfer aborts; the device answers
    # again after DAQmx Reset Device, so a fresh AO task vents it and the monitor confirms
    _lost_after(fake_driver, 30)
    fake_driver.interpreter.reset_device.side_effect = fake_driver.reconnect
    result = acquire(config, backend="ni", out_root=tmp_path)
    assert result.status == "failed" and result.exit_code == 1, result.reason
    assert not result.manual_vent_required and "VENT BY HAND" not in result.reason
    assert "the DAQ device stopped answering" in result.reason
    assert "reset and vented" in result.reason
    fake_driver.interpreter.reset_device.assert_called_once_with("Dev1")
    writes = [c.args[3] for c in calls(fake_driver, "write_analog_scalar_f64")]
    assert writes[-1] == 0.0 and max(writes) > 0
    # the verification is the simulated regulator exhausting, read on the fresh AI task: below
    # safety.vent_below_bar (0.05 bar), as for any vent
    vent_check = load_run(result.path).meta.vent_check
    assert vent_check["verified"] and vent_check["pressure_bar"] < 0.05
    assert fake_driver.bench.target_bar == 0.0


def test_the_samples_after_a_reset_follow_the_runs_on_its_clock(config, fake_driver, tmp_path):
    # the fresh AI task after a reset counts its samples from 0 again: the vent check's rows
    # were recorded as samples 0-8 after sample 29, at 0-0.8 s, under the 0.5 bar command of
    # the samples those indices had named, so samples.csv ran backwards. Now they follow the
    # run's samples (after a gap for the time the device was gone, when it took a sample's)
    _lost_after(fake_driver, 30)
    fake_driver.interpreter.reset_device.side_effect = fake_driver.reconnect
    result = acquire(config, backend="ni", out_root=tmp_path)
    run = load_run(result.path)
    assert run.meta.vent_check["verified"], result.reason
    samples = run.samples
    assert (samples["sample"].diff().dropna() > 0).all()
    assert (samples["time_s"].diff().dropna() > 0).all()
    vent = samples[samples["phase"] == "vent"]
    assert len(vent) > 0 and vent["sample"].min() >= 30
    assert (vent["command_bar"] == 0.0).all()
    assert run.meta.counters["samples"] == len(samples)


def test_a_device_that_stays_lost_asks_for_a_vent_by_hand_within_the_bound(
        config, fake_driver, tmp_path, instant_clock):
    _lost_after(fake_driver, 30)  # and every reset finds the device absent (-200324)
    result = acquire(config, backend="ni", out_root=tmp_path)
    assert result.status == "failed" and result.exit_code == 4 and result.manual_vent_required
    assert "did not bring it back" in result.reason and "VENT BY HAND" in result.reason
    assert 0 < instant_clock["t"] <= REVIVE_WITHIN_S
    # retried every REVIVE_EVERY_S until the bound: attempts at 0, 0.5, ..., 3.0 s
    attempts = fake_driver.interpreter.reset_device.call_count
    assert attempts == int(REVIVE_WITHIN_S / REVIVE_EVERY_S) + 1


# The private hooks below were checked against nidaqmx 1.7.0; pyproject pins nidaqmx>=1.3,<2.
CHECKED_HOOKS = {
    "create_task": ["session_name"],
    "create_ai_voltage_chan": ["task", "physical_channel", "name_to_assign_to_channel",
                               "terminal_config", "min_val", "max_val", "units",
                               "custom_scale_name"],
    "create_ao_voltage_chan": ["task", "physical_channel", "name_to_assign_to_channel",
                               "min_val", "max_val", "units", "custom_scale_name"],
    "cfg_samp_clk_timing": ["task", "rate", "source", "active_edge", "sample_mode",
                            "samps_per_chan"],
    "read_analog_f64": ["task", "num_samps_per_chan", "timeout", "fill_mode", "read_array"],
    "write_analog_scalar_f64": ["task", "auto_start", "timeout", "value"],
    "set_buffer_attribute_uint32": ["task", "attribute", "value"],
    "get_read_attribute_uint64": ["task", "attribute"],
    "start_task": ["task"], "stop_task": ["task"], "clear_task": ["task"],
}


def test_canary_nidaqmx_private_hooks():
    """Fails loudly if nidaqmx moves the hooks the mocked-hardware tests stand on."""
    import nidaqmx.utils
    from nidaqmx._base_interpreter import BaseInterpreter
    from nidaqmx.task import Task

    major, minor = (int(x) for x in version("nidaqmx").split(".")[:2])
    assert (1, 3) <= (major, minor) < (2, 0), "nidaqmx outside the range checked (>=1.3,<2)"
    assert list(inspect.signature(nidaqmx.utils._select_interpreter).parameters) == [
        "grpc_options", "interpreter"]
    assert "utils._select_interpreter(" in inspect.getsource(Task.__init__)
    for name, params in CHECKED_HOOKS.items():
        assert list(inspect.signature(getattr(BaseInterpreter, name)).parameters)[1:] == params


def test_another_device_is_refused(config, fake_driver):
    # the configuration was validated against the USB-6001's capabilities only
    fake_driver.interpreter.get_device_attribute_string.return_value = "USB-6009"
    with pytest.raises(BenchError, match="Dev1 is a USB-6009: the bench settings are validated "
                                         "for a USB-6001 only"):
        NIBackend(config).open()
    assert not calls(fake_driver, "create_task")  # refused before any task was made


def _reads_lost_after(fake_driver, n_reads):
    """Reads work ``n_reads`` times, then fail with -50405 while writes still succeed (the AO
    write reached the device, the monitor cannot be read back); a reset brings reads back."""
    reads = {"n": 0}
    normal = fake_driver.read

    def read(*args):
        reads["n"] += 1
        if reads["n"] > n_reads:
            raise DaqReadError("USB transfer aborted", -50405, 0)
        return normal(*args)

    fake_driver.interpreter.read_analog_f64.side_effect = read

    def reset(device_name):
        reads["n"] = -10**9  # the fresh tasks read again

    fake_driver.interpreter.reset_device.side_effect = reset


def test_a_vent_check_whose_reads_are_lost_resets_the_device_and_verifies(
        config, fake_driver, tmp_path):
    # the read that lost the device stops the run; the vent write succeeds, the vent check's
    # reads fail: without a reset there is no reading, and the run would ask for a vent by hand
    _reads_lost_after(fake_driver, 30)
    result = acquire(config, backend="ni", out_root=tmp_path)
    assert result.status == "failed" and result.exit_code == 1, result.reason
    assert not result.manual_vent_required and "VENT BY HAND" not in result.reason
    assert "the vent check's reads failed" in result.reason
    assert "reset and vented on a fresh task" in result.reason
    fake_driver.interpreter.reset_device.assert_called_once_with("Dev1")
    vent_check = load_run(result.path).meta.vent_check
    assert vent_check["verified"] and vent_check["pressure_bar"] < 0.05  # as for any vent
    assert calls(fake_driver, "write_analog_scalar_f64")[-1].args[3] == 0.0


def test_a_vent_check_whose_reads_stay_lost_asks_for_a_vent_by_hand(
        config, fake_driver, tmp_path, instant_clock):
    _reads_lost_after(fake_driver, 30)
    from nidaqmx.errors import DaqError

    fake_driver.interpreter.reset_device.side_effect = DaqError("device absent", -200324)
    result = acquire(config, backend="ni", out_root=tmp_path)
    assert result.exit_code == 4 and result.manual_vent_required
    assert "the vent check's reads failed" in result.reason
    assert "did not bring it back" in result.reason and "VENT BY HAND" in result.reason
    assert fake_driver.interpreter.reset_device.call_count == \
        int(REVIVE_WITHIN_S / REVIVE_EVERY_S) + 1  # retried until its bound, no longer


def _lost_until_reset(fake_driver):
    """The device a run lost: every call into it fails with -50405 until DAQmx Reset Device."""
    from nidaqmx.errors import DaqError

    fake_driver.disconnect()
    make_channel = fake_driver.interpreter.create_ai_voltage_chan

    def create(*args):
        if fake_driver.disconnected:
            raise DaqError("USB transfer aborted", -50405)

    make_channel.side_effect = create
    fake_driver.interpreter.reset_device.side_effect = fake_driver.reconnect


def test_mkm_vent_resets_a_device_lost_before_it_and_vents(config, fake_driver, instant_clock):
    from mkm.bench.procedures import vent

    _lost_until_reset(fake_driver)
    fake_driver.bench.set_command_volts(6.25)  # the lost run left 2.5 bar commanded
    out = vent(config, backend="ni")
    assert out["vented"] and out["pressure_bar"] < 0.05
    fake_driver.interpreter.reset_device.assert_called_once_with("Dev1")
    assert fake_driver.bench.target_bar == 0.0


def test_mkm_vent_resets_a_device_whose_reads_are_lost_in_the_check(config, fake_driver):
    from mkm.bench.procedures import vent

    _reads_lost_after(fake_driver, 0)
    fake_driver.bench.set_command_volts(6.25)
    out = vent(config, backend="ni")
    assert out["vented"] and out["pressure_bar"] < 0.05
    fake_driver.interpreter.reset_device.assert_called_once_with("Dev1")


def test_a_session_at_open_resets_a_lost_device(config, fake_driver, instant_clock):
    # tare, check and calibrate-loadcell open the device in procedures.session
    from mkm.bench.procedures import tare

    _lost_until_reset(fake_driver)
    out = tare(config, backend="ni", seconds=1.0)
    assert out["device"]["serial_number"] == "1F2E3D4"
    fake_driver.interpreter.reset_device.assert_called_once_with("Dev1")


def test_a_device_absent_at_open_fails_within_the_bound(config, fake_driver, instant_clock):
    from mkm.bench.procedures import vent

    _lost_until_reset(fake_driver)
    fake_driver.interpreter.reset_device.side_effect = fake_driver.reset  # stays absent
    with pytest.raises(DaqDisconnected, match="-50405"):
        vent(config, backend="ni")
    assert 0 < instant_clock["t"] <= REVIVE_WITHIN_S


def test_mkm_vent_finds_the_lock_and_marker_of_the_run_that_lost_the_device(
        config, fake_driver, tmp_path, instant_clock, capsys):
    # the run's lock and marker are keyed by the serial number, which a lost device cannot
    # answer: without the reset, `mkm vent` would key the bench by its name and miss the run
    from nidaqmx.errors import DaqError

    from mkm.bench.procedures import vent
    from mkm.bench.storage import ProcessIdentity
    from mkm.bench.unvented import Marker, bench_folder
    from mkm.core.records import write_json_atomic

    dead = ProcessIdentity(2**22 + 9, "bench-pc", 1.0, None)  # pid above pid_max
    marker = Marker("ni-serial-1F2E3D4", str(tmp_path / "lost-run"), "2026-12-02T10:00:00+00:00",
                    vars(dead), 2.5, "2026-12-02T10:05:00+00:00")
    folder = bench_folder("ni-serial-1F2E3D4")
    folder.mkdir(parents=True)
    write_json_atomic(folder / "dead.json", vars(marker))
    _lost_until_reset(fake_driver)

    def serial(*args):
        if fake_driver.disconnected:
            raise DaqError("USB transfer aborted", -50405)
        return 0x1F2E3D4

    fake_driver.interpreter.get_device_attribute_uint32.side_effect = serial
    notes = []
    out = vent(config, backend="ni", notify=notes.append)
    assert out["vented"]
    assert any(str(tmp_path / "lost-run") in note and "vented now" in note for note in notes)
    assert not (folder / "dead.json").exists()
    assert instant_clock["t"] <= REVIVE_WITHIN_S  # the key and the open share one bound


def _reset_benchmark():
    """benchmarks/bench_ni_reset.py, the hardware measurement of the revive, as a module."""
    import importlib.util
    from pathlib import Path

    path = Path(__file__).parents[2] / "benchmarks" / "bench_ni_reset.py"
    spec = importlib.util.spec_from_file_location("bench_ni_reset", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.mark.parametrize("simulated, product, names, expected", [
    (True, "USB-6001", "Dev1", "is simulated in NI MAX"),
    (False, "USB-6009", "Dev1", "is a USB-6009, not a USB-6001"),
    (False, "USB-6001", "Dev2", "is not connected (NI-DAQmx lists Dev2)"),
])
def test_the_reset_measurement_refuses_without_a_real_usb_6001(fake_driver, capsys, simulated,
                                                               product, names, expected):
    fake_driver.interpreter.get_system_info_attribute_string.return_value = names
    fake_driver.interpreter.get_device_attribute_bool.return_value = simulated
    fake_driver.interpreter.get_device_attribute_string.return_value = product
    assert _reset_benchmark().main(["--device", "Dev1"]) == 2
    err = capsys.readouterr().err
    assert expected in err and "BLOCKED" in err and err.count("\n") == 1
    assert not calls(fake_driver, "create_task") and not calls(fake_driver, "reset_device")


def test_the_reset_measurement_refuses_without_the_driver(fake_driver, capsys):
    fake_driver.interpreter.get_system_info_attribute_string.side_effect = DaqNotFoundError("x")
    assert _reset_benchmark().main(["--device", "Dev1"]) == 2
    assert "NI-DAQmx driver is not installed here" in capsys.readouterr().err


def test_the_reset_measurement_times_revives_and_writes_0_V_only(fake_driver, tmp_path, capsys):
    import json

    fake_driver.interpreter.get_system_info_attribute_string.return_value = "Dev1"
    out = tmp_path / "reset.json"
    assert _reset_benchmark().main(["--device", "Dev1", "--repeats", "3", "--json",
                                    str(out)]) == 0
    record = json.loads(out.read_text())
    assert len(record["live"]["revive_s"]) == len(record["live"]["reset_s"]) == 3
    assert record["device"]["serial_number"] == "1F2E3D4" and record["versions"]["python"]
    assert fake_driver.interpreter.reset_device.call_count == 3 + 3 + 1
    assert {c.args[3] for c in calls(fake_driver, "write_analog_scalar_f64")} == {0.0}
    assert "| revive (reset, fresh tasks, 0 V) | 3 |" in capsys.readouterr().out


def test_a_loss_after_the_key_was_read_still_gets_the_whole_reset_bound(
        config, fake_driver, instant_clock):
    # `mkm vent` reads the key, then may wait up to 30 s for a live run to stop before it opens
    backend = NIBackend(config)
    assert backend.bench_key == "ni-serial-1F2E3D4"
    instant_clock["t"] += 30.0
    _lost_until_reset(fake_driver)
    assert backend.open().serial_number == "1F2E3D4"
    fake_driver.interpreter.reset_device.assert_called_once_with("Dev1")
    backend.close()
