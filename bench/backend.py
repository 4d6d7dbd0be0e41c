"""The acquisition backend protocol and its error types.

A backend is the transport between the run and the bench hardware (pymeasure's adapter/driver
split): it opens one analog-input task holding every input and one analog-output channel for the
regulator command, reads blocks of raw volts on a hardware clock, writes the command, and closes.
:class:`mkm.bench.ni.NIBackend` talks to an NI USB-6001 through nidaqmx;
:class:`mkm.bench.sim.SimBackend` is a simulated bench with the same signature. The run
(``mkm.bench.run``) only sees this protocol, so the real bench and the simulation share one code
path; :mod:`mkm.bench.backends` is the one list of backends.

Failures are raised as :class:`BenchError` subclasses with one-line messages (the NI backend maps
NI-DAQmx status codes to them); :func:`in_words` says one to the user, with what to do.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Protocol

if TYPE_CHECKING:  # annotations only: the backend registry is read by `mkm --help`
    import numpy as np


#: The clocks a backend's factory takes (``--clock``), which matter to a simulated one only:
#: ``virtual``, sample k at k / rate s and reads returning at once; ``real``, reads waiting
#: until their samples' times have passed, as the hardware clock does.
CLOCKS = ("virtual", "real")


class BenchError(RuntimeError):
    """A failure of the bench hardware (or of its simulation); the message is one line."""


class DriverMissing(BenchError):
    """NI-DAQmx is not installed (always the case on Linux for the USB-6001)."""


class DaqDisconnected(BenchError):
    """The device went away (USB unplugged, powered off)."""


class ReadTimeout(BenchError):
    """The requested samples did not arrive within the read timeout."""


class BufferOverflow(BenchError):
    """The reader fell behind and the driver overwrote unread samples: data were lost.

    ``lost_samples`` is the number of samples per input lost (everything unread: restarting the
    task discards the buffer), when the backend knows it.
    """

    def __init__(self, message: str, lost_samples: int | None = None):
        super().__init__(message)
        self.lost_samples = lost_samples


class AOWriteFailed(BenchError):
    """The regulator command could not be written."""


class DeviceReserved(BenchError):
    """Another task or program holds the device."""


#: What an error of the device means and what to do, by its class (first match).
ERROR_WORDS: dict[type[BenchError], str] = {
    DaqDisconnected: "the DAQ device stopped answering: check its USB cable and power",
    ReadTimeout: "the DAQ device sent no samples in time: check its USB cable and power",
    BufferOverflow: "samples were lost, read from the DAQ device too late: close other "
                    "programs that load the PC",
    AOWriteFailed: "the regulator command did not reach the DAQ device: check its USB cable "
                   "and power",
    DeviceReserved: "another program holds the DAQ device (NI MAX's test panel, LabVIEW, "
                    "another mkm): close it, then try again",
}


def in_words(exc: BaseException) -> str:
    """``exc`` as the user reads it, one line: an error of the device in words, with what to
    do (:data:`ERROR_WORDS`) and the driver's own words in brackets; another
    :class:`BenchError` by its message (written for the user); an operating system's error by
    its description and the file it names; any other (an error of mkm's own) by its class and
    message, which say where to look."""
    text = " ".join(str(exc).split())  # one line, whatever the driver's message holds
    words = next((w for cls, w in ERROR_WORDS.items() if isinstance(exc, cls)), None)
    if words is not None:
        return f"{words} ({text})" if text else words
    if isinstance(exc, BenchError) and text:
        return text
    if isinstance(exc, OSError):
        where = exc.filename2 or exc.filename
        said = exc.strerror or text or "the system gave no description"
        return f"{said}: {where}" if where else said
    return f"{type(exc).__name__}: {text}" if text else type(exc).__name__


def device_said(exc: BaseException) -> str:
    """:func:`in_words` of an error raised while the device was driven: an operating system's
    error naming no file (a crash inside the driver's DLL, a USB stack's I/O error) said as the
    device's; one naming a file is that file's."""
    if isinstance(exc, OSError) and not (exc.filename or exc.filename2):
        return (f"the DAQ device or its driver failed ({in_words(exc)}): check its USB cable and "
                "power")
    return in_words(exc)


@dataclass(frozen=True)
class DeviceCapabilities:
    """What a DAQ device can do, for validating a configuration before it is run.

    Each backend of :mod:`mkm.bench.backends` declares the capabilities of its device.
    """

    product: str
    ai_rse: tuple[str, ...]  # single-ended (referenced to AI GND) inputs
    ai_differential: dict[str, str]  # differential input -> the terminal it pairs with
    terminal_configs: tuple[str, ...]
    max_aggregate_rate_hz: float  # over every input of the task (one multiplexed ADC)
    ai_range_V: float  # +- this
    ao: tuple[str, ...]
    ao_range_V: float  # +- this
    ai_bits: int  # ADC resolution

    @property
    def ai_lsb_V(self) -> float:
        """One step of the ADC [V] over the input range (+-10 V at 14 bits: 1.22 mV)."""
        return 2 * self.ai_range_V / 2**self.ai_bits


@dataclass
class DeviceInfo:
    """What the backend found when it opened the device; recorded in ``run.json``."""

    backend: str
    simulated: bool
    product_type: str
    serial_number: str
    sample_rate_hz: float
    channels: dict[str, Any]
    extra: dict[str, Any] = field(default_factory=dict)

    def as_dict(self) -> dict[str, Any]:
        return {"backend": self.backend, "simulated": self.simulated,
                "product_type": self.product_type, "serial_number": self.serial_number,
                "sample_rate_hz": self.sample_rate_hz, "channels": self.channels, **self.extra}


@dataclass
class Block:
    """Samples read in one call: ``volts[k, c]`` is sample ``first_index + k`` of input ``c``.

    Inputs are in the order of ``DeviceInfo.channels["ai"]``. The sample index counts periods of
    the hardware clock since start; after a buffer overflow it jumps by the samples lost.
    """

    first_index: int
    volts: np.ndarray


class Backend(Protocol):
    """Transport to the bench: one AI task with every input, one AO command, a hardware clock.

    ``bench_key`` names the physical bench (backend and device: ``ni-serial-1F2E3D4``,
    ``sim-Dev1``) for the locks and markers of :mod:`mkm.bench.ownership` and
    :mod:`mkm.bench.unvented`, which fold its case as NI-DAQmx compares device names.
    """

    bench_key: str

    def open(self) -> DeviceInfo:
        """Reserve the device, create the tasks (not started) and write the vent command."""

    def start(self) -> None:
        """Start the sample clock; sample 0 is the first sample after this call."""

    def read(self, n_samples: int, timeout_s: float) -> Block:
        """Block until ``n_samples`` per input are available and return them."""

    def available(self) -> int:
        """Samples per input acquired and not yet read."""

    def recover(self) -> int:
        """Restart acquisition after a :class:`BufferOverflow`; return the next sample index."""

    def write_command(self, volts: float) -> None:
        """Write the regulator command voltage on the AO channel (no-op without AO)."""

    def close(self) -> None:
        """Write the vent command, then stop and clear every task. Safe to call twice."""
