"""The NI USB-6001 backend: the :class:`mkm.bench.backend.Backend` protocol over nidaqmx.

The only module that imports ``nidaqmx`` (inside methods, so the package imports without it).
One AI task holds every input (the USB-6001 has one multiplexed ADC): the load cell and, with an
electronic regulator, its monitor output, each with an explicit terminal configuration and the
+-10 V range (never the driver defaults). The task runs continuously on the hardware sample clock
with a buffer of ``daq.buffer_s`` (>= 10 min) and is read in small blocks by the run's plain loop.
A second task writes the regulator command on AO0, on demand, started at open so the channel is
reserved until close. ``close`` writes the vent command before clearing the tasks: the
USB-6001's AO keeps its last value when a task is closed, and through a lost USB transfer:
:meth:`NIBackend.revive` resets a lost device and vents it on fresh tasks, and ``open`` resets
a device that answers as lost before giving up. A device NI MAX
simulates is refused: it would drive nothing while the run says it drove the bench.

The NI-DAQmx status codes (turned into :mod:`mkm.bench.backend` errors) live here; a missing driver
(always the case on Linux) becomes :class:`~mkm.bench.backend.DriverMissing` with what to do.
"""

from __future__ import annotations

import time
from contextlib import contextmanager, suppress

import numpy as np

from mkm.bench.backend import (
    AOWriteFailed,
    BenchError,
    Block,
    BufferOverflow,
    DaqDisconnected,
    DeviceInfo,
    DeviceReserved,
    DriverMissing,
    ReadTimeout,
)
from mkm.bench.devices import USB6001, device_key

USB6001_RANGE_V = USB6001.ai_range_V

# NI-DAQmx status codes (nidaqmx.error_codes.DAQmxErrors) and what they mean for a run.
NI_ERROR_CODES: dict[int, type[BenchError]] = {
    -200279: BufferOverflow,  # SAMPLES_NO_LONGER_AVAILABLE: the buffer was overwritten
    -200361: BufferOverflow,  # ONBOARD_MEMORY_OVERFLOW: USB-600x FIFO full, samples lost
    -200284: ReadTimeout,  # SAMPLES_NOT_YET_AVAILABLE: timeout elapsed
    -50405: DaqDisconnected,  # PAL_TRANSFER_ABORTED: USB transfer aborted, device gone
    -201003: DaqDisconnected,  # DEV_CANNOT_BE_ACCESSED
    -200324: DaqDisconnected,  # DEV_ABSENT_OR_UNAVAILABLE
    -50103: DeviceReserved,  # PAL_RESOURCE_RESERVED
    -200022: DeviceReserved,  # RESOURCE_ALREADY_RESERVED by another task
}


def error_for_code(code: int, message: str, default: type[BenchError] = BenchError) -> BenchError:
    """The :class:`BenchError` for an NI-DAQmx status ``code``; ``default`` for unmapped codes."""
    cls = NI_ERROR_CODES.get(int(code), default)
    first_line = message.strip().splitlines()[0] if message.strip() else "no description"
    said = f"NI-DAQmx error {code}: {first_line}"
    if cls is BenchError:  # what its code means is NI's to say: where to look
        said = (f"the DAQ device or its driver failed ({said}): check its USB cable and power, "
                "and run its self-test in NI MAX")
    return cls(said)


DRIVER_MISSING = ("NI-DAQmx, NI's driver of the USB-6001, is not installed: on Windows type "
                  "'python -m nidaqmx installdriver' (it downloads NI's installer; or get "
                  "NI-DAQmx from ni.com), then restart the PC (NI does not support the USB-6001 "
                  "on Linux); without the bench, --backend sim runs the simulated one")
TERMINAL_CONFIG_NAMES = {"differential": "DIFF", "rse": "RSE"}  # what the USB-6001 has
VENT_V = 0.0  # an ITV-class regulator exhausts at 0 V command
#: A device lost mid-run is reset and given fresh tasks for at most this long [s], every
#: REVIVE_EVERY_S, before the vent is declared impossible: the operator must hear within seconds.
REVIVE_WITHIN_S = 3.0
REVIVE_EVERY_S = 0.5


@contextmanager
def daq_errors(default: type[BenchError] = BenchError):
    """Translate nidaqmx exceptions into :mod:`mkm.bench.backend` errors with one-line messages."""
    import nidaqmx.errors

    try:
        yield
    except nidaqmx.errors.DaqNotFoundError:
        raise DriverMissing(DRIVER_MISSING) from None
    except nidaqmx.errors.DaqNotSupportedError as exc:
        raise DriverMissing(f"NI-DAQmx is not supported here ({exc}): use --backend sim") from None
    except nidaqmx.errors.DaqError as exc:
        raise error_for_code(exc.error_code, str(exc), default) from exc


class NIBackend:
    """NI USB-6001 bench: AI task (load cell [+ regulator monitor]) and AO command task.

    Parameters
    ----------
    config : mkm.bench.config.BenchConfig
        The bench settings (``daq``, ``loadcell``, ``regulator``).
    """

    def __init__(self, config):
        self.config = config
        self.device = config.daq.device.strip()
        self._bench_key: str | None = None
        self.rate_hz = config.daq.sample_rate_hz
        self.ai_task = None
        self.ao_task = None
        self._reader = None
        self._writer = None
        self._index = 0
        self._base = 0  # hardware index of the current task start's first sample
        self._started_at: float | None = None
        self._serial_opened: str | None = None
        self._lost_deadline: float | None = None

    @property
    def bench_key(self) -> str:
        """The physical device: ``ni-serial-<serial number>`` as the driver reads it (one key
        whatever NI MAX calls the device and however the name is written), else the name as
        NI-DAQmx compares it (driver or device missing: nothing can be driven anyway)."""
        if self._bench_key is None:
            try:
                self._bench_key = f"ni-serial-{self._serial()}"
            except BenchError:
                self._bench_key = f"ni-{device_key(self.device)}"
        return self._bench_key

    def _serial(self) -> str:
        try:
            import nidaqmx.system
        except ImportError:
            raise DriverMissing(DRIVER_MISSING) from None

        def read() -> str:
            with daq_errors():
                return f"{int(nidaqmx.system.Device(self.device).serial_num):X}"

        return self._reset_while_lost(read)

    def _reset_while_lost(self, attempt):
        """``attempt()``, and while the device answers as lost (-50405, -200324, -201003: a run
        lost it, or a USB glitch) DAQmx Reset Device and again, every :data:`REVIVE_EVERY_S`
        until :data:`REVIVE_WITHIN_S` after the first loss met (a device that stays lost for the
        bench key is not waited for again by the open): `mkm vent` after a loss must still
        reach the regulator the run left pressurised, and the run's lock and marker."""
        while True:
            try:
                result = attempt()
            except DaqDisconnected:
                if self._lost_deadline is None:
                    self._lost_deadline = time.monotonic() + REVIVE_WITHIN_S
                if time.monotonic() + REVIVE_EVERY_S > self._lost_deadline:
                    raise
            else:
                self._lost_deadline = None  # answered: a later loss gets the whole bound
                return result
            time.sleep(REVIVE_EVERY_S)
            with suppress(BenchError):  # a device still absent: the next attempt says so
                self._reset_device()

    @property
    def ai_channels(self) -> list[str]:
        return self.config.ai_channels

    def open(self) -> DeviceInfo:
        """Open the device and vent it; a device that answers as lost is reset and opened
        again within the bound (:meth:`_reset_while_lost`)."""
        return self._reset_while_lost(self._open)

    def _reset_device(self) -> str:
        """DAQmx Reset Device (aborts every task on it); the serial number it answers with."""
        import nidaqmx.system

        with daq_errors():
            device = nidaqmx.system.Device(self.device)
            device.reset_device()
            return f"{int(device.serial_num):X}"

    def _open(self) -> DeviceInfo:
        import nidaqmx.system

        daq = self.config.daq
        try:
            with daq_errors():
                dev = nidaqmx.system.Device(self.device)
                product, serial = str(dev.product_type), f"{int(dev.serial_num):X}"
                simulated = dev.is_simulated is True
            if simulated:
                raise BenchError(f"device {self.device} is a simulated {product} (NI MAX): no "
                                 "hardware would be driven; run with --backend sim to simulate")
            if product != USB6001.product:
                raise BenchError(f"device {self.device} is a {product}: the bench settings are "
                                 f"validated for a {USB6001.product} only "
                                 "(mkm.bench.devices.USB6001)")
            self._serial_opened = serial
            with daq_errors():
                self._make_tasks()
                self.write_command(VENT_V)
                actual_rate = float(self.ai_task.timing.samp_clk_rate)
        except BaseException:
            with suppress(BenchError):  # the error that stopped opening is the one to report
                self.close()
            raise
        channels = {"ai": self.ai_channels, "ai_range_V": [-USB6001_RANGE_V, USB6001_RANGE_V],
                    "terminal_config": daq.terminal_config,
                    "ao": self.config.regulator.command_channel if self._writer else None,
                    "buffer_samples": daq.buffer_samples}
        return DeviceInfo(backend="ni", simulated=False, product_type=product,
                          serial_number=serial, sample_rate_hz=actual_rate, channels=channels,
                          extra={"device": self.device, "nidaqmx": _nidaqmx_version()})

    def _make_tasks(self) -> None:
        """The AI task (every input, hardware clock) and, with an electronic regulator, the AO
        task, started so that AO0 stays reserved."""
        import nidaqmx
        from nidaqmx.constants import AcquisitionType, TerminalConfiguration
        from nidaqmx.stream_readers import AnalogMultiChannelReader
        from nidaqmx.stream_writers import AnalogSingleChannelWriter

        daq = self.config.daq
        terminal = getattr(TerminalConfiguration, TERMINAL_CONFIG_NAMES[daq.terminal_config])
        self.ai_task = nidaqmx.Task("mkm_ai")
        for channel in self.ai_channels:
            self.ai_task.ai_channels.add_ai_voltage_chan(
                f"{self.device}/{channel}", terminal_config=terminal,
                min_val=-USB6001_RANGE_V, max_val=USB6001_RANGE_V)
        self.ai_task.timing.cfg_samp_clk_timing(
            self.rate_hz, sample_mode=AcquisitionType.CONTINUOUS,
            samps_per_chan=daq.buffer_samples)
        self.ai_task.in_stream.input_buf_size = daq.buffer_samples
        self._reader = AnalogMultiChannelReader(self.ai_task.in_stream)
        if self.config.regulator.electronic:
            self.ao_task = nidaqmx.Task("mkm_ao")
            self.ao_task.ao_channels.add_ao_voltage_chan(
                f"{self.device}/{self.config.regulator.command_channel}",
                min_val=0.0, max_val=10.0)
            # started once: the channel stays reserved for the whole run (an
            # auto-started task would release it after every write, to NI MAX's
            # test panel or another program)
            self.ao_task.start()
            self._writer = AnalogSingleChannelWriter(self.ao_task.out_stream,
                                                     auto_start=False)

    def start(self) -> None:
        with daq_errors():
            self.ai_task.start()
        self._started_at = time.monotonic()
        self._index = self._base = 0

    def read(self, n_samples: int, timeout_s: float) -> Block:
        data = np.empty((len(self.ai_channels), n_samples))
        with daq_errors():
            read = self._reader.read_many_sample(data, n_samples, timeout=timeout_s)
        block = Block(self._index, data[:, :read].T.copy())
        self._index += read
        return block

    def available(self) -> int:
        with daq_errors():
            return int(self.ai_task.in_stream.avail_samp_per_chan)

    def recover(self) -> int:
        """Restart after an overflow; return the index of the next sample (the lost ones skipped).

        Restarting discards the buffer, so everything acquired and unread is lost: the hardware
        had acquired ``total_samp_per_chan_acquired`` samples when the task stopped, and the
        clock runs on while it restarts (counted from the time the restart took).
        """
        with daq_errors():
            acquired = int(self.ai_task.in_stream.total_samp_per_chan_acquired)
            stopped_at = time.monotonic()
            self.ai_task.stop()
            self.ai_task.start()
        restart_samples = int((time.monotonic() - stopped_at) * self.rate_hz)
        self._base = max(self._index, self._base + acquired + restart_samples)
        self._index = self._base
        return self._index

    def write_command(self, volts: float) -> None:
        if self._writer is None:
            return
        with daq_errors(AOWriteFailed):
            self._writer.write_one_sample(float(volts), timeout=1.0)

    def revive(self, within_s: float = REVIVE_WITHIN_S) -> None:
        """After a device loss (-50405, -200324, the device gone): reset the device, make fresh
        tasks, write the vent command and restart the AI task, retried every
        :data:`REVIVE_EVERY_S` for at most ``within_s`` [s] of wall time.

        A USB-6001 keeps its last AO value through a lost transfer, so the regulator holds the
        run's pressure until a task on a live device writes 0 V (DAQmx Reset Device aborts the
        dead tasks; NI-DAQmx Help, "DAQmx Reset Device"). The serial number must be the one
        opened: another device under the same name is not the bench. Raises the last
        :class:`BenchError` when the device stays lost; the vent is then still to be verified.
        """
        deadline = time.monotonic() + within_s
        while True:
            self._drop_tasks()
            try:
                serial = self._reset_device()
                if self._serial_opened is not None and serial != self._serial_opened:
                    raise BenchError(f"device {self.device} came back as serial {serial}, not "
                                     f"the bench's {self._serial_opened}")
                with daq_errors():
                    self._make_tasks()
                self.write_command(VENT_V)
                self.start()
                return
            except BenchError as exc:
                last = exc
            if time.monotonic() + REVIVE_EVERY_S > deadline:
                raise last
            time.sleep(REVIVE_EVERY_S)

    def _drop_tasks(self) -> None:
        """Clear the tasks of a lost device; their handles are dead, so errors say nothing."""
        for name in ("ai_task", "ao_task"):
            task = getattr(self, name)
            if task is not None:
                with suppress(Exception):
                    task.close()
            setattr(self, name, None)
        self._writer = self._reader = None

    def close(self) -> None:
        """Vent first, then clear the AI and AO tasks; every step is tried, the first error wins."""
        errors = []
        if self._writer is not None:
            try:
                self.write_command(VENT_V)
            except BaseException as exc:
                errors.append(exc)
        for name in ("ai_task", "ao_task"):
            task = getattr(self, name)
            if task is None:
                continue
            try:
                with daq_errors():
                    task.close()
            except BaseException as exc:
                errors.append(exc)
            setattr(self, name, None)
        self._writer = self._reader = None
        if errors:
            raise errors[0]


def _nidaqmx_version() -> str:
    from importlib.metadata import version

    return version("nidaqmx")

