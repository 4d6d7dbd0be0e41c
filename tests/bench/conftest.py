"""Shared fixtures of the bench tests: a short sequence, and the NI driver layer faked.

The short sequence keeps every simulated run to a few hundred samples (virtual clock), so the
whole bench suite stays within its 60 s budget.
"""

from __future__ import annotations

from unittest import mock

import numpy as np
import pytest

from mkm.bench.config import load_config
from mkm.bench.sim import SimMuscleBench


@pytest.fixture(autouse=True)
def _bench_state(tmp_path, monkeypatch):
    """Every test gets its own folder of bench markers (bench.unvented)."""
    monkeypatch.setenv("MKM_STATE_DIR", str(tmp_path / "mkm-state"))


@pytest.fixture(autouse=True)
def _signals_as_a_fresh_process_has_them():
    """The signals a run handles, as a command started from a terminal has them: delivered
    (not blocked in this thread's mask) with their default actions, restored after the test.
    A suite started in the background by a shell without job control (`make test &`, a CI
    runner's script) inherits SIGINT and SIGQUIT ignored (POSIX): a Ctrl-C the tests send this
    process then ended a command with 1, not 130, and a SIGQUIT never reached the run."""
    import signal
    import threading

    from mkm.bench.signals import BACKGROUND_SIGNALS, ENDING_SIGNALS, STOP_SIGNALS

    if threading.current_thread() is not threading.main_thread():
        yield
        return
    handled = (*STOP_SIGNALS, *ENDING_SIGNALS, *BACKGROUND_SIGNALS)
    before = {s: signal.getsignal(s) for s in handled}
    mask = (signal.pthread_sigmask(signal.SIG_UNBLOCK, handled)
            if hasattr(signal, "pthread_sigmask") else None)
    for s in handled:
        signal.signal(s, signal.default_int_handler if s == signal.SIGINT else signal.SIG_DFL)
    yield
    for s, handler in before.items():
        if handler is not None:
            signal.signal(s, handler)
    if mask is not None:
        signal.pthread_sigmask(signal.SIG_SETMASK, mask)


SHORT = {
    "sequence": {"pressures_bar": (0.5, 1.0), "tare_s": 2.0, "preconditioning_cycles": 0},
    "settle": {"min_dwell_s": 3.0, "hold_s": 2.0, "timeout_s": 20.0, "window_s": 2.0},
}


@pytest.fixture
def config():
    """The packaged paper prototype with a short staircase: 0.5, 1.0 bar up, 0.5 down."""
    return load_config().replace(**SHORT)


class FakeDriver:
    """The NI-DAQmx driver layer (``BaseInterpreter``) faked, fed by the simulated bench.

    Reads come from a :class:`mkm.bench.sim.SimMuscleBench`, AO writes go to its regulator, so a
    whole
    run goes through nidaqmx's real Python code and gives physically meaningful data.
    """

    def __init__(self, interpreter, config, actual_rate_hz=10.0):
        from nidaqmx.constants import FillMode

        self.interpreter = interpreter
        self.bench = SimMuscleBench(config)
        self.n_channels = 2 if config.regulator.electronic else 1
        self.fill_mode = FillMode.GROUP_BY_CHANNEL.value
        interpreter.create_task.side_effect = lambda name: (f"handle-{name}", True)
        interpreter.get_task_attribute_string.side_effect = lambda handle, attr: handle
        interpreter.read_analog_f64.side_effect = self.read
        interpreter.write_analog_scalar_f64.side_effect = self.write
        interpreter.get_read_attribute_uint32.side_effect = self.read_attribute
        interpreter.get_read_attribute_uint64.side_effect = self.read_attribute_64
        interpreter.start_task.side_effect = self.start
        interpreter.reset_device.side_effect = self.reset
        interpreter.get_timing_attribute_double.return_value = actual_rate_hz
        interpreter.get_device_attribute_string.return_value = "USB-6001"
        interpreter.get_device_attribute_uint32.return_value = 0x1F2E3D4
        interpreter.get_device_attribute_bool.return_value = False  # is_simulated
        interpreter.driver_version = (25, 0, 0)
        self.acquired = 0  # samples the "hardware" took since the task started
        self.overflow_behind = 0  # an overflow: the hardware ran this far ahead of the reader
        self.disconnected = False  # once the device is gone, every write fails as on USB

    def disconnect(self):
        """The USB cable is pulled: reads and writes fail with -50405 from now on."""
        from nidaqmx.errors import DaqReadError

        self.disconnected = True
        self.interpreter.read_analog_f64.side_effect = DaqReadError("USB transfer aborted",
                                                                    -50405, 0)

    def reset(self, device_name):
        """DAQmx Reset Device: a device that is gone is absent (-200324)."""
        from nidaqmx.errors import DaqError

        if self.disconnected:
            raise DaqError("device absent or unavailable", -200324)

    def reconnect(self, device_name=None):
        """The device is back (what ``reset_device`` finds after a glitch): reads and writes work
        again, on the bench as it was left (the regulator still at its last command)."""
        self.disconnected = False
        self.interpreter.read_analog_f64.side_effect = self.read

    def start(self, handle):
        self.acquired = 0  # the count restarts with the task

    def overflow(self, behind_samples):
        """The reader fell ``behind_samples`` behind: the hardware acquired them, unread."""
        for _ in range(behind_samples):
            self.bench.step()
        self.acquired += behind_samples

    def read_attribute_64(self, handle, attribute):
        assert attribute == 0x192A  # total_samp_per_chan_acquired
        return self.acquired

    def read_attribute(self, handle, attribute):
        return {0x217B: self.n_channels, 0x1223: 0}[attribute]  # num_chans, avail_samp_per_chan

    def read(self, handle, n_samples, timeout, fill_mode, data):
        assert fill_mode == self.fill_mode
        samples = np.array([self.bench.step() for _ in range(n_samples)])
        data[:, :] = samples[:, : self.n_channels].T
        self.acquired += n_samples
        return data, n_samples

    def write(self, handle, auto_start, timeout, value):
        if self.disconnected:
            from nidaqmx.errors import DaqWriteError

            raise DaqWriteError("USB transfer aborted", -50405, 0)
        self.bench.set_command_volts(value)
        return 1


@pytest.fixture(scope="session")
def _interpreter():
    from nidaqmx._base_interpreter import BaseInterpreter

    return mock.create_autospec(BaseInterpreter, instance=True)  # 0.3 s: made once


@pytest.fixture
def fake_driver(config, _interpreter):
    """Patch ``nidaqmx.utils._select_interpreter`` as nidaqmx's own unit tests do."""
    interpreter = _interpreter
    interpreter.reset_mock(return_value=True, side_effect=True)
    driver = FakeDriver(interpreter, config)
    with mock.patch("nidaqmx.utils._select_interpreter", return_value=interpreter):
        yield driver


@pytest.fixture
def ctrl_c_run(config, tmp_path):
    """``ctrl_c_run(vent_failures) -> (BenchRun, failed)``: a simulated run that Ctrl-C stops at
    sample 45 (0.5 bar commanded), whose vent writes from there fail ``vent_failures`` times
    (None: every one; an AO write error; ``failed`` lists them); not yet executed."""
    from mkm.bench.backend import AOWriteFailed
    from mkm.bench.run import BenchRun
    from mkm.bench.sim import SimBackend

    def make(vent_failures: int | None):
        backend = SimBackend(config)
        write, read, failed = backend.write_command, backend.read, []

        def vent_fails(volts):
            if volts == 0.0 and backend._index >= 45 and (
                    vent_failures is None or len(failed) < vent_failures):
                failed.append(volts)
                raise AOWriteFailed("simulated AO write failure")
            write(volts)

        def ctrl_c_at_45(n, timeout):
            block = read(n, timeout)
            if block.first_index == 45:
                run.request_stop()  # what the first SIGINT does
            return block

        backend.write_command, backend.read = vent_fails, ctrl_c_at_45
        run = BenchRun(config, backend, tmp_path, handle_signals=False, notify=lambda m: None)
        return run, failed

    return make


@pytest.fixture
def mkm_cli(capsys):
    """``mkm_cli(argv) -> (exit status, stdout, stderr)`` of ``mkm argv`` run in-process."""
    from mkm.cli import main

    def run(argv):
        try:
            code = main(argv)
        except SystemExit as exc:  # argparse --help and errors leave through parser.exit
            code = exc.code
        out, err = capsys.readouterr()
        return code, out, err

    return run


class RunEvents(list):
    """The events :func:`run_events` records, in order."""

    def after_the_stop(self, stop: tuple) -> list[tuple]:
        """What the run did from the stop ``stop`` (an event a test put in) to its first
        vent write, that write left out; every event when none came."""
        rest = self[self.index(stop) + 1:]
        return rest[:rest.index(("AO", 0.0))] if ("AO", 0.0) in rest else rest


@pytest.fixture
def run_events(monkeypatch) -> RunEvents:
    """What the run's own thread does to the device and to its books, in order, as the run
    does it: each read (``("read", first sample)``), each AO write (``("AO", volts)``) and each
    call of its recorder (``("books", name)``: a block queued, a command's or a step's row,
    run.json marked or finished), appended once the call returned; a test puts in the signal
    it raises. The recorder's own thread (the rows it writes behind the loop) is left out:
    "acts first, keeps books after" is the order of the run's loop, which no clock decides."""
    import threading

    from mkm.bench.recorder import Recorder
    from mkm.bench.sim import SimBackend

    events = RunEvents()
    main = threading.main_thread()

    def spy(cls, name, said):
        original = getattr(cls, name)

        def called(self, *args, **kwargs):
            out = original(self, *args, **kwargs)
            if threading.current_thread() is main:
                events.append(said(out, *args))
            return out

        monkeypatch.setattr(cls, name, called)

    spy(SimBackend, "read", lambda block, *args: ("read", block.first_index))
    spy(SimBackend, "write_command", lambda out, volts: ("AO", float(volts)))
    for name in ("samples", "command", "step", "gap", "tare", "mark", "finish"):
        spy(Recorder, name, lambda out, *args, name=name: ("books", name))
    return events
