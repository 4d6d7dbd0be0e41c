"""The verified vent: command 0 bar, then read the regulator's monitor until it says the muscle
is vented.

A vent is only a command until the monitor confirms it: a regulator that sticks keeps its
pressure whatever it is told. :func:`verify_vent` reads the pressure monitor (electronic
regulator) until it has settled below ``safety.vent_below_bar`` (from the tare's zero,
:class:`VentedZero`, else from the zero the configuration declares), for at most
``safety.vent_timeout_s`` of sample time and wall time (``daq.read_retries`` read timeouts in a
row retried, as at 0 bar in a run), judging only samples acquired after the vent write and only
plausible ones (a live-zero monitor at 0 V, unpowered or unwired, reads -1 bar: a monitor fault,
never a vent, :meth:`mkm.bench.config.Regulator.monitor_fault`); with a manual regulator the
operator vents by hand and types the manometer reading, which must be below the same threshold.
A check with a ``deadline`` (Windows ends a closed console's process within 5 s) stops at it,
unverified, so the run can still be recorded. A monitor that already read below the threshold
when it was found below its command before the vent (:func:`below_command`; by the pressure
interlock, or in its last reading before a stop) verifies nothing: a monitor stuck at zero reads
so whatever the muscle holds; nor, with a pressure commanded as the run stopped, does one that
shows no fall after the vent (:func:`without_fall`).
"""

from __future__ import annotations

import dataclasses
import math
import statistics
import time
from dataclasses import asdict, dataclass

from mkm.bench import backends
from mkm.bench.backend import (
    BenchError,
    BufferOverflow,
    DaqDisconnected,
    ReadTimeout,
    in_words,
)
from mkm.bench.config import MAX_VENT_TIMEOUT_S


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
    # how far [bar] the monitor's first readings after the vent lay above the reading it
    # settled at (the median of the first FIRST_READINGS); None when not judged so
    first_above_bar: float | None = None
    # the noise [bar] a settled reading was judged by: the tare's, or the readings' own
    noise_bar: float | None = None
    # why the check read on past safety.vent_timeout_s ("" when it did not)
    waited_why: str = ""
    # safety.vent_timeout_s [s] of a check that stopped with the monitor above the threshold,
    # no longer falling by more than its noise (None otherwise): the setting a regulator that
    # exhausts slowly needs, named in the message
    timeout_s: float | None = None
    # the instrument the check found not reading what it should ("the monitor", "the load
    # cell", ...; "" when none): it recorded the run's steps too, so their data are in doubt
    doubted: str = ""

    def as_dict(self) -> dict:
        return asdict(self)

    def unproven(self, commanded_bar: float, problem: str,
                 doubted: str = "the monitor") -> VentCheck:
        """This check, not verified: ``problem`` says why its reading proves no vent of
        ``commanded_bar`` (a vent by hand is asked for), ``doubted`` which instrument."""
        return dataclasses.replace(self, verified=False, unfollowed_bar=commanded_bar,
                                   problem=problem, doubted=doubted)

    def describe(self) -> str:
        if self.verified:
            return (f"vent verified: {self.how} read {self.pressure_bar:.3f} bar after "
                    f"{self.waited_s:.1f} s")
        why = f"; {self.waited_why}" if self.waited_why else ""
        if self.problem:
            return f"the vent could not be verified ({self.problem}{why})"
        notes = [self.waited_why] if self.waited_why else []
        if self.timeout_s is not None:
            notes.append(
                f"it no longer fell by more than its noise ({self.noise_bar:.3f} bar) over "
                f"{FALL_SPAN_S:g} s: a regulator that sticks, or one exhausting the muscle with a "
                f"time constant of tens of seconds, which no reading tells apart; for such a "
                f"regulator set safety.vent_timeout_s (now {self.timeout_s:g} s, at most "
                f"{MAX_VENT_TIMEOUT_S:g} s) to the time it takes from the highest pressure to "
                f"below {self.below_bar:g} bar")
        return (f"the {self.how} still reads {self.pressure_bar:.3f} bar {self.waited_s:.1f} s "
                f"after the vent, above {self.below_bar:g} bar"
                + (f" ({'; '.join(notes)})" if notes else ""))


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
    return check.unproven(commanded_bar, (
        f"the monitor read {reading_bar(measured_bar)} bar against {commanded_bar:g} bar "
        "commanded before the vent, so its reading after it proves nothing: stuck near "
        "zero, a monitor reads so whatever the muscle holds; a regulator without "
        "supply pressure or a hose that leaks reads the same; check the monitor and "
        "the supply"))


#: sample time [s] over which the monitor's reading must stay within its noise to count as
#: settled: a muscle exhausting through an ITV-class regulator (tau about 0.4 s) still falls by
#: more than its noise over it until it is within that noise of its vented reading
SETTLED_S = 0.5
#: a monitor still falling at ``safety.vent_timeout_s`` (a regulator slower than its setting
#: foresaw, exhausting the muscle all the same) is read on while it falls, until this long after
#: the vent at most: from 2.5 bar, a regulator of time constant up to about 14 s (below 0.05 bar
#: after 4 time constants); twice the longest ``vent_timeout_s`` a configuration may set
FALLING_MAX_S = 60.0
#: the monitor is still falling when the median of its readings over the last
#: :data:`SETTLED_S` lies below that of its readings this much earlier by more than its noise
FALL_SPAN_S = 2.0
#: the first readings after the vent whose median is the monitor's start of the fall (one
#: noise spike among them moves no median)
FIRST_READINGS = 3
#: readings of a vented monitor stay within this many of its standard deviations at the tare
#: (plus two ADC steps, for a reading quieter than its quantisation) of its vented zero
ZERO_NOISE_SIGMAS = 5.0
#: 1.4826 median absolute deviations are one standard deviation of a normal variable
MAD_SIGMAS = 1.4826


def lsb_bar(config) -> float:
    """One ADC step of the monitor's input [bar]."""
    reg = config.regulator
    return (backends.entry(config.daq.backend).capabilities.ai_lsb_V * reg.full_scale_bar
            / (reg.monitor_V_at_full_scale - reg.monitor_V_at_zero))


def fall_bar(history: list[tuple[float, float]]) -> float:
    """How far [bar] the median reading of ``history`` ((sample time [s], reading [bar]) over
    up to :data:`FALL_SPAN_S` + :data:`SETTLED_S`) fell from its first :data:`SETTLED_S` to its
    last (a noise spike moves neither median); 0 over less than twice :data:`SETTLED_S`."""
    first_s, last_s = history[0][0], history[-1][0]
    if last_s - first_s < 2 * SETTLED_S - 1e-9:
        return 0.0
    earlier = [p for t, p in history if t <= first_s + SETTLED_S + 1e-9]
    later = [p for t, p in history if t > last_s - SETTLED_S - 1e-9]
    return statistics.median(earlier) - statistics.median(later)


def own_noise_bar(readings: list[float], step_bar: float) -> float:
    """How far [bar] a steady reading strays, from the readings themselves (no tare read the
    monitor vented): :data:`ZERO_NOISE_SIGMAS` of their spread plus two ADC steps ``step_bar``.
    The spread comes from the second differences of successive readings, whose standard
    deviation is sqrt(6) times the readings' for white noise: a fall at a steady or slowly
    changing rate (an exhausting muscle) adds almost nothing to them, and their median absolute
    deviation is not moved by a noise spike (three second differences of many)."""
    second = [a - 2 * b + c for a, b, c in zip(readings, readings[1:], readings[2:],
                                              strict=False)]
    if len(second) < 3:
        return 2 * step_bar
    centre = statistics.median(second)
    mad = statistics.median(abs(d - centre) for d in second)
    return ZERO_NOISE_SIGMAS * MAD_SIGMAS * mad / math.sqrt(6.0) + 2 * step_bar


@dataclass(frozen=True)
class VentedZero:
    """What the tare read on the monitor vented: its zero ``zero_bar`` and how far a vented
    reading strays from it, ``noise_bar`` (:meth:`from_tare`)."""

    zero_bar: float
    noise_bar: float

    @classmethod
    def from_tare(cls, tare: dict | None, config) -> VentedZero | None:
        """The zero of a tare of this run (run.json ``tare``), or None when the tare read none."""
        if not tare or not tare.get("monitor_vented_settled"):
            return None
        noise = (ZERO_NOISE_SIGMAS * float(tare.get("monitor_vented_std_bar", 0.0))
                 + 2 * lsb_bar(config))
        return cls(float(tare["monitor_vented_bar"]), noise)


def without_fall(check: VentCheck, before_bar: float, commanded_bar: float, last_bar: float,
                 noise_bar: float) -> VentCheck:
    """``check`` after a run ended with ``commanded_bar`` (above the vent threshold) commanded
    and the monitor reading ``before_bar`` (the median of its last readings, one noise spike
    moves no median), ``last_bar`` the last of them, weighed by the fall it showed after the
    vent.

    A monitor that reads the pressure falls after the vent: its last readings before it, or
    its first after it (a stop as a step begins, the pressure still low before the vent), lie
    above the reading it settles at by more than its noise ``noise_bar``. One frozen near zero
    shows no fall (a noise spike as the run stopped made its last reading look like a
    pressure), so its settled reading verifies nothing. Nor do its first readings after the
    vent lying above its last reading before it: an exhausting muscle does not rise, so that is
    noise (two spikes in a row move the median of the first readings), and the fall they show
    counts only down from ``last_bar`` (plus its noise).
    """
    if not check.verified or check.how != "monitor" or check.first_above_bar is None:
        return check
    # the check's last reading is within the noise of the one it settled at
    first_fall = min(check.first_above_bar, last_bar + noise_bar - check.pressure_bar)
    fall = max(before_bar - check.pressure_bar, first_fall)
    if fall > noise_bar:
        return check
    return check.unproven(commanded_bar, (
        f"the monitor read {reading_bar(before_bar)} bar with {commanded_bar:g} bar "
        f"commanded before the vent and did not fall after it by more than its noise "
        f"({noise_bar:.3f} bar), so its reading proves nothing: stuck near zero, a "
        "monitor reads so whatever the muscle holds; a regulator without supply "
        "pressure or a hose that leaks reads the same; check the monitor and the "
        "supply"))


#: a muscle that vents lets go of its force: a force after the vent above this fraction of the
#: one before it (and above the load cell's noise) is a muscle that still pulls
FORCE_KEPT_FRACTION = 0.5


def force_per_bar(steps, noise_N: float) -> float | None:
    """The muscle's force per bar [N/bar] over the run's steps (``steps.csv``'s rows, in
    order): the median of the slopes between successive steps at different measured pressures
    whose forces are both above the load cell's noise ``noise_N`` (the muscle pulled at both);
    one step across the threshold, or the turn of a sweep, moves no median. None when no two
    such steps were done, or when their median is not positive: a muscle's force rises with its
    pressure, so that is no muscle's slope but the cell's zero drifting under a slack one (forces
    above the noise rising as the pressure falls on a down-sweep below the threshold); the vent
    check then judges the force as without a slope (:func:`still_pulling`)."""
    slopes = []
    for a, b in zip(steps, steps[1:], strict=False):
        dp = b.pressure_bar_mean - a.pressure_bar_mean
        if math.isfinite(dp) and abs(dp) > 0 and a.force_N_mean > noise_N \
                and b.force_N_mean > noise_N:
            slopes.append((b.force_N_mean - a.force_N_mean) / dp)
    per_bar_N = statistics.median(slopes) if slopes else None
    return per_bar_N if per_bar_N is not None and per_bar_N > 0 else None


def still_pulling(check: VentCheck, before_N: float, after_N: float, noise_N: float,
                  commanded_bar: float, stuck_cell: tuple[float, float] | None = None,
                  per_bar_N: float | None = None) -> VentCheck:
    """``check`` weighed by the load cell: the muscle's force (from the tare) ``before_N``
    before the vent and ``after_N`` over the check's settled window.

    A vented muscle is slack: its force falls with its pressure (to a tenth of it or less once
    the monitor has settled below the threshold). One that still pulls more than
    :data:`FORCE_KEPT_FRACTION` of its force before the vent, above the load cell's noise
    ``noise_N``, is still pressurised whatever the monitor reads: a regulator whose monitor
    reports its command (or is stuck) and whose exhaust did not open. A force before the vent
    within the noise tells nothing. Nor does one that no pressure above the muscle's threshold
    need have made: the load cell sees a pressure only by the force it makes, none below the
    threshold (a slack muscle reads the cell's zero, which a warming amplifier moves by newtons
    over a run), ``per_bar_N`` more per bar above it (the run's force per bar,
    :func:`force_per_bar`). A force before the vent not above the noise plus what the vent
    threshold's pressure makes (``per_bar_N`` x ``check.below_bar``) is that of a muscle at
    most that pressure above its threshold, or of a slack one on a zero moved: the cell cannot
    tell it from a vented muscle, so the check stands on the monitor, as it does below the
    threshold. ``stuck_cell``, the monitor's reading [bar] before the vent
    and the load cell's spread [N] at the tare, when every force of both windows was one
    reading although the cell strayed more than an ADC step at the tare: no muscle, slack or
    pulling, holds a live cell's reading to one ADC code, so the cell is stuck or disconnected;
    the vent is still not verified (the force tells nothing), and the check says so.
    """
    if not check.verified or check.how != "monitor" or not before_N > noise_N:
        return check
    if not after_N > max(noise_N, FORCE_KEPT_FRACTION * before_N):
        return check
    if stuck_cell is not None:
        before_bar, tare_std_N = stuck_cell
        return check.unproven(commanded_bar, (
            f"the monitor read {reading_bar(before_bar)} bar before the vent and "
            f"{reading_bar(check.pressure_bar)} bar after it, but the load cell read "
            f"{after_N:.1f} N throughout, every reading the same where it strayed "
            f"{tare_std_N:.2f} N at the tare: a load cell that does not change while the "
            "pressure falls is stuck or disconnected, so it tells neither a slack muscle nor "
            "one that still pulls; check the load cell's cable, amplifier and supply, and "
            "that the muscle hangs slack"), "the load cell")
    if per_bar_N is not None and not before_N > noise_N + per_bar_N * check.below_bar:
        return check
    if per_bar_N is None:  # nothing shows the muscle pulling: a zero moved reads the same
        return check.unproven(commanded_bar, (
            f"the monitor read {reading_bar(check.pressure_bar)} bar, but the load cell still "
            f"reads {after_N:.1f} N against {before_N:.1f} N before the vent (more than "
            f"{FORCE_KEPT_FRACTION:.0%} of it), and the run measured no force per bar (the "
            "muscle pulled at no two successive steps): a muscle that still pulls (a monitor "
            "that reports its command or is stuck, with an exhaust that did not open) reads so, "
            f"and so does a slack one on a load-cell zero moved {before_N:.1f} N since the tare "
            "(an amplifier warming up); look at the muscle: hanging slack, it is vented and the "
            "zero moved (power the amplifier up well before the run); pulling, "
            "check the regulator and the load cell"), "the monitor or the load cell")
    return check.unproven(commanded_bar, (
        f"the monitor read {reading_bar(check.pressure_bar)} bar, but the load cell "
        f"still reads {after_N:.1f} N against {before_N:.1f} N before the vent (more "
        f"than {FORCE_KEPT_FRACTION:.0%} of it): the muscle still pulls, so the "
        "monitor's reading proves nothing: a monitor that reports its command or is "
        "stuck, with an exhaust that did not open (or a load cell stuck); check the "
        "regulator and the load cell"), "the monitor or the load cell")


def monitor_unmoved(check: VentCheck, before_bar: float, before_N: float, after_N: float,
                    noise_N: float) -> VentCheck:
    """``check``, not verified with the monitor still above the threshold, weighed by the load
    cell: the monitor read ``before_bar`` before the vent and no less after it (within its
    noise), while the force fell from ``before_N`` to ``after_N``, below
    :data:`FORCE_KEPT_FRACTION` of it (and ``before_N`` above the cell's noise ``noise_N``).
    The same reading with the muscle's force gone is no pressure held: the monitor no longer
    reads the pressure (its output, wire or input stuck), and neither a regulator that holds
    nor a slow one is the cause. Still not verified: nothing the monitor reads shows the vent.
    """
    noise_bar = check.noise_bar or 0.0
    if check.verified or check.problem or check.how != "monitor" or not before_N > noise_N \
            or not check.pressure_bar >= before_bar - noise_bar \
            or not after_N < FORCE_KEPT_FRACTION * before_N:
        return check
    return dataclasses.replace(check, timeout_s=None, doubted="the monitor", problem=(
        f"the monitor still reads {reading_bar(check.pressure_bar)} bar {check.waited_s:.1f} s "
        f"after the vent, as it read {reading_bar(before_bar)} bar before it, but the load "
        f"cell reads {after_N:.1f} N against {before_N:.1f} N before the vent: the muscle let "
        "go while the monitor did not move, so the monitor no longer reads the pressure (its "
        "output, wire or input stuck); check the monitor"))


def verify_vent(backend, config, operator=None, started: bool = True,
                deadline=lambda: None, record=lambda block: None,
                vented_zero: VentedZero | None = None) -> VentCheck:
    """Confirm that the muscle is vented (the vent command already written).

    Parameters
    ----------
    backend : mkm.bench.backend.Backend
        The open backend; read only if ``started`` (its sample clock runs).
    config : mkm.bench.config.BenchConfig
        ``safety.vent_below_bar`` [bar] and ``safety.vent_timeout_s`` [s] bound the check; a
        monitor still falling at ``vent_timeout_s`` is read on while it falls, at most
        :data:`FALLING_MAX_S` after the vent (said in :attr:`VentCheck.waited_why`).
    operator : mkm.bench.operator.Operator, optional
        With a manual regulator: vents by hand and reads the manometer.
    deadline : callable, optional
        Returns the ``time.monotonic()`` [s] at which the check gives up unverified, or None
        (asked before every read: a console closed during the check bounds it too).
    record : callable, optional
        Gets every :class:`mkm.bench.backend.Block` the check reads (the run records them:
        the pressure's decay after the vent is on disk); must not raise.
    vented_zero : VentedZero, optional
        The monitor's zero read by the run's tare. The reading is then taken from that zero
        when it is below 0 bar. A reading is judged only once it has settled (within the
        monitor's noise over :data:`SETTLED_S`: the zero's, else the readings' own,
        :func:`own_noise_bar`): a monitor whose zero drifted low reads below the threshold
        while the muscle still holds pressure, and shows it only once its reading stops
        falling, below the tare's zero (without one, below 0 bar by more than the zero error
        its configuration declares, :meth:`mkm.bench.config.Regulator.vented_reading_bar`).
        Such a reading verifies nothing.
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
    if vented_zero is not None:  # read from the tare's zero, where it lies below 0 bar
        below = below + min(vented_zero.zero_bar, 0.0)
        zero_bar, zero_error_bar, declared = vented_zero.zero_bar, 0.0, ""
    else:  # no tare read it: 0 bar, within the zero error its configuration declares
        zero_error_bar, declared = config.regulator.vented_reading_bar()
        zero_bar = 0.0
    step_bar = lsb_bar(config)
    # (sample time [s], reading [bar]) over FALL_SPAN_S + SETTLED_S
    recent: list[tuple[float, float]] = []
    waited_why = ""  # why the check reads on past timeout_s
    first: list[float] = []  # the first FIRST_READINGS readings after the vent
    start, sample_time_s, pressure = time.monotonic(), 0.0, math.nan
    timeouts, blind_s = 0, 0.0  # read timeouts in a row; the time they waited, in all
    try:  # samples acquired before the vent write say nothing about the vent
        stale = backend.available()
        if stale > 0:
            record(backend.read(stale, config.daq.read_timeout_s))
    except BufferOverflow:
        backend.recover()
    except BenchError as exc:
        return VentCheck(False, pressure, below, 0.0, "monitor", in_words(exc),
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
            # read on past the timeout while the monitor was falling: its timeouts as well
            if timeouts > config.daq.read_retries or waited > (
                    FALLING_MAX_S if waited_why else timeout_s):
                return VentCheck(False, pressure, below, waited, "monitor",
                                 in_words(exc))
            continue
        except BenchError as exc:
            return VentCheck(False, pressure, below, time.monotonic() - start, "monitor",
                             in_words(exc), isinstance(exc, DaqDisconnected))
        record(block)
        timeouts = 0
        monitor_V = float(block.volts[-1, 1])
        sample_time_s += n / rate
        waited = max(time.monotonic() - start, sample_time_s + blind_s)
        fault = config.regulator.monitor_fault(monitor_V) if math.isfinite(monitor_V) else None
        if fault:  # no reading of a working regulator: nothing is verified by it, and its
            # conversion (0 V: -1 bar) is no pressure: the last plausible reading is kept
            return VentCheck(False, pressure, below, waited, "monitor", fault,
                             doubted="the monitor")
        pressure = float(config.regulator.monitor_bar(monitor_V))
        if not math.isfinite(pressure):  # a broken input: it verifies nothing
            return VentCheck(False, pressure, below, waited, "monitor",
                             f"the monitor reads {monitor_V!r} V, not a number",
                             doubted="the monitor")
        recent = [(t, p) for t, p in recent
                  if t > sample_time_s - FALL_SPAN_S - SETTLED_S - 1e-9]
        recent.append((sample_time_s, pressure))
        if len(first) < FIRST_READINGS:
            first.append(pressure)
        noise_bar = (vented_zero.noise_bar if vented_zero is not None else own_noise_bar(
            [p for t, p in recent if t > sample_time_s - 2 * SETTLED_S - 1e-9], step_bar))
        window = [(t, p) for t, p in recent if t > sample_time_s - SETTLED_S - 1e-9]
        readings = [p for _, p in window]
        settled = (sample_time_s - window[0][0] >= SETTLED_S - 1e-9
                   and max(readings) - min(readings) <= noise_bar)
        if settled and max(readings) < below:  # the whole steady window: no noise dip
            settled_bar = sum(readings) / len(readings)
            if settled_bar < zero_bar - zero_error_bar - noise_bar:
                return VentCheck(False, pressure, below, waited, "monitor", (
                    f"the monitor settled at {reading_bar(pressure)} bar, below the "
                    f"{reading_bar(zero_bar)} bar it read vented at the tare by more than its "
                    f"noise ({noise_bar:.3f} bar): its zero has drifted low, so its reading no "
                    "longer tells what the muscle holds; check the monitor"
                    if vented_zero is not None else
                    f"the monitor settled at {reading_bar(pressure)} bar, below 0 bar by more "
                    f"than the zero error its configuration declares ({zero_error_bar:g} bar, "
                    f"{declared}) and its noise ({noise_bar:.3f} bar): its zero is off low, and "
                    "no tare read it vented, so its reading does not tell what the muscle "
                    "holds; check the monitor"), noise_bar=noise_bar, waited_why=waited_why,
                    doubted="the monitor")
            return VentCheck(True, pressure, below, waited, "monitor",
                             first_above_bar=statistics.median(first) - settled_bar,
                             noise_bar=noise_bar, waited_why=waited_why)
        if waited > timeout_s:
            fell = fall_bar(recent)
            if fell > noise_bar and waited < FALLING_MAX_S:  # exhausting still: read on
                if not waited_why:
                    waited_why = (
                        f"the monitor was still falling at safety.vent_timeout_s="
                        f"{timeout_s:g} s ({reading_bar(fell)} bar over the last "
                        f"{recent[-1][0] - recent[0][0]:.1f} s, more than its noise "
                        f"{noise_bar:.3f} bar): read on while it fell, at most "
                        f"{FALLING_MAX_S:g} s after the vent")
                continue
            if pressure < below:  # never settled: a drift may hide
                return VentCheck(False, pressure, below, waited, "monitor", (
                    f"the monitor read {reading_bar(pressure)} bar but did not settle within "
                    f"{waited:.1f} s, so a drift of its zero cannot be excluded"),
                    waited_why=waited_why, doubted="the monitor")
            return VentCheck(False, pressure, below, waited, "monitor", noise_bar=noise_bar,
                             waited_why=waited_why,
                             timeout_s=None if waited >= FALLING_MAX_S else timeout_s)
