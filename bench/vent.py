"""The verified vent: command 0 bar, then read the regulator's monitor until it says the muscle
is vented.

A vent is only a command until the monitor confirms it: a regulator that sticks keeps its
pressure whatever it is told. :func:`verify_vent` reads the pressure monitor (electronic
regulator) until it is below ``safety.vent_below_bar``, for at most ``safety.vent_timeout_s``
of sample time and wall time (``daq.read_retries`` read timeouts in a row retried, as at 0 bar
in a run), judging only samples acquired after the vent write and only plausible ones (a
live-zero monitor at 0 V, unpowered or unwired, reads -1 bar: a monitor fault, never a vent,
:meth:`mkm.bench.config.Regulator.monitor_fault`); with a manual regulator the
operator vents by hand and types the manometer reading, which must be below the same threshold.
A check with a ``deadline`` (Windows ends a closed console's process within 5 s) stops at it,
unverified, so the run can still be recorded. A monitor that already read below the threshold
when it was found below its command before the vent (:func:`below_command`; by the pressure
interlock, or in its last reading before a stop) verifies nothing: a monitor stuck at zero reads
so whatever the muscle holds.
"""

from __future__ import annotations

import dataclasses
import math
import time
from dataclasses import asdict, dataclass

from mkm.bench.backend import BenchError, BufferOverflow, DaqDisconnected, ReadTimeout


def reading_bar(value: float) -> str:
    """A monitor's reading [bar] as said: three decimals, its noise about 0 said as 0.000."""
    return f"{value:.3f}".replace("-0.000", "0.000")


@dataclass
class VentCheck:
    """What the monitor (or the operator) read after the vent."""

    verified: bool
    pressure_bar: float  # the last reading; NaN when nothing could be read
    below_bar: float
    waited_s: float
    how: str  # "monitor" | "operator"
    problem: str = ""
    device_lost: bool = False  # the monitor's reads failed with the device gone
    # the command [bar] the monitor did not follow before the vent, reading below the
    # threshold already: its readings prove nothing, the muscle may still hold it
    unfollowed_bar: float | None = None

    def as_dict(self) -> dict:
        return asdict(self)

    def describe(self) -> str:
        if self.verified:
            return (f"vent verified: {self.how} read {self.pressure_bar:.3f} bar after "
                    f"{self.waited_s:.1f} s")
        if self.problem:
            return f"the vent could not be verified ({self.problem})"
        return (f"the {self.how} still reads {self.pressure_bar:.3f} bar {self.waited_s:.1f} s "
                f"after the vent, above {self.below_bar:g} bar")


def below_command(check: VentCheck, measured_bar: float, commanded_bar: float) -> VentCheck:
    """``check`` after the monitor read ``measured_bar`` below ``commanded_bar`` before the
    vent (:meth:`mkm.bench.worker.Acquisition.unproven`).

    A monitor that read below the vent threshold then, and reads below it after the vent, has
    shown no fall: a monitor stuck at zero reads so whatever the muscle holds, so the check is
    not verified (a regulator without supply pressure, or a leaking hose, reads so too: a vent
    by hand is asked for all the same). A monitor that read more and then fell below the
    threshold did read the vent: ``check`` stands.
    """
    if not check.verified or check.how != "monitor" or not measured_bar < check.below_bar:
        return check
    return dataclasses.replace(
        check, verified=False, unfollowed_bar=commanded_bar,
        problem=(f"the monitor read {reading_bar(measured_bar)} bar against {commanded_bar:g} bar "
                 "commanded before the vent, so its reading after it proves nothing: stuck near "
                 "zero, a monitor reads so whatever the muscle holds; a regulator without "
                 "supply pressure or a hose that leaks reads the same; check the monitor and "
                 "the supply"))


def verify_vent(backend, config, operator=None, started: bool = True,
                deadline=lambda: None, record=lambda block: None) -> VentCheck:
    """Confirm that the muscle is vented (the vent command already written).

    Parameters
    ----------
    backend : mkm.bench.backend.Backend
        The open backend; read only if ``started`` (its sample clock runs).
    config : mkm.bench.config.BenchConfig
        ``safety.vent_below_bar`` [bar] and ``safety.vent_timeout_s`` [s] bound the check.
    operator : mkm.bench.operator.Operator, optional
        With a manual regulator: vents by hand and reads the manometer.
    deadline : callable, optional
        Returns the ``time.monotonic()`` [s] at which the check gives up unverified, or None
        (asked before every read: a console closed during the check bounds it too).
    record : callable, optional
        Gets every :class:`mkm.bench.backend.Block` the check reads (the run records them:
        the pressure's decay after the vent is on disk); must not raise.
    """
    safety = config.safety
    below, timeout_s = safety.vent_below_bar, safety.vent_timeout_s
    if not config.regulator.electronic:
        if operator is None:
            return VentCheck(False, math.nan, below, 0.0, "operator", "no operator to vent")
        try:
            reading = float(operator.vent())
        except (BenchError, ValueError, TypeError, EOFError, OSError) as exc:
            return VentCheck(False, math.nan, below, 0.0, "operator",
                             f"the operator's reading was not given: {type(exc).__name__}")
        return VentCheck(reading < below, reading, below, 0.0, "operator")
    if not started:
        return VentCheck(False, math.nan, below, 0.0, "monitor", "the acquisition never "
                         "started, so the monitor could not be read")
    rate = config.daq.sample_rate_hz
    n = max(1, int(round(0.1 * rate)))
    start, sample_time_s, pressure = time.monotonic(), 0.0, math.nan
    timeouts, blind_s = 0, 0.0  # read timeouts in a row; the time they waited, in all
    try:  # samples acquired before the vent write say nothing about the vent
        stale = backend.available()
        if stale > 0:
            record(backend.read(stale, config.daq.read_timeout_s))
    except BufferOverflow:
        backend.recover()
    except BenchError as exc:
        return VentCheck(False, pressure, below, 0.0, "monitor", f"{type(exc).__name__}: {exc}",
                         isinstance(exc, DaqDisconnected))
    while True:
        cut, now, read_s = deadline(), time.monotonic(), config.daq.read_timeout_s
        if cut is not None:
            if now >= cut:
                waited = max(now - start, sample_time_s + blind_s)
                return VentCheck(False, pressure, below, waited, "monitor",
                                 f"cut short after {waited:.1f} s: the process is about to be "
                                 "ended (console closed)")
            read_s = min(read_s, max(cut - now, 2 * n / rate))  # a block's time at least
        try:
            block = backend.read(n, read_s)
        except BufferOverflow:
            backend.recover()
            continue
        except ReadTimeout as exc:  # at 0 bar, as in the run: daq.read_retries in a row
            timeouts, blind_s = timeouts + 1, blind_s + read_s
            waited = max(time.monotonic() - start, sample_time_s + blind_s)
            if timeouts > config.daq.read_retries or waited > timeout_s:
                return VentCheck(False, pressure, below, waited, "monitor",
                                 f"{type(exc).__name__}: {exc}")
            continue
        except BenchError as exc:
            return VentCheck(False, pressure, below, time.monotonic() - start, "monitor",
                             f"{type(exc).__name__}: {exc}", isinstance(exc, DaqDisconnected))
        record(block)
        timeouts = 0
        monitor_V = float(block.volts[-1, 1])
        sample_time_s += n / rate
        waited = max(time.monotonic() - start, sample_time_s + blind_s)
        fault = config.regulator.monitor_fault(monitor_V) if math.isfinite(monitor_V) else None
        if fault:  # no reading of a working regulator: nothing is verified by it, and its
            # conversion (0 V: -1 bar) is no pressure: the last plausible reading is kept
            return VentCheck(False, pressure, below, waited, "monitor", fault)
        pressure = float(config.regulator.monitor_bar(monitor_V))
        if pressure < below:
            return VentCheck(True, pressure, below, waited, "monitor")
        if not math.isfinite(pressure):  # a broken input: it verifies nothing
            return VentCheck(False, pressure, below, waited, "monitor",
                             f"the monitor reads {monitor_V!r} V, not a number")
        if waited > timeout_s:
            return VentCheck(False, pressure, below, waited, "monitor")
