"""Steps from a time series another lab recorded: a pressure staircase or a continuous ramp.

A lab's record is pressure and force sampled in time. Before any step is taken from it:

- :func:`vented_offset`: the pressure the record reads while the muscle is vented (its first
  samples, before the pressure starts to rise); a gauge that reads above zero at rest is
  detected (:mod:`mkm.bench.exchange` takes it as the record's zero up to a sensor's zero
  error);
- :func:`tare`: the force's zero (a load cell is rarely at 0 N when the muscle is slack) is
  the mean force of the rest before the pressure rises, that rest ended where a fit in time
  puts the rise's start (:func:`rise_start`): the pressure's level there, not a band of
  pressure, tells it, since on a ramp the first 0.03 bar already pull; :func:`end_rest` finds
  the record's closing rest the same way, whose force tells a drifted zero: only its settled
  part (:func:`settled_start`), since a vent's tail still pulls as the rest begins.

Then :func:`shape` tells a staircase (the pressure held on plateaus most of the time) from a
ramp, and the steps are taken:

- :func:`staircase_steps`: each plateau is a step, its settling judged by the bench's own test
  (:func:`mkm.bench.sequence.settle_reached`, with the packaged configuration's ``[settle]``
  criteria) and its hold averaged by the bench's :class:`mkm.bench.sequence.HoldStats`, up to
  where the pressure leaves its level at the plateau's end (:func:`_held_stop`); a plateau
  that never settles is averaged over its second half and recorded ``settled = false``;
- :func:`untimed_staircase_steps`: the plateaus of a staircase recorded without its time (its
  rows the clock), each averaged over its second half;
- :func:`ramp_steps`: quasi-static points, the samples binned by pressure on each branch apart
  (:func:`branches`: rising and falling, each cycle of a repeated ramp its own), each bin a
  step with its samples' mean; a branch's bins follow each other in time, as the holds of a
  staircase do.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from mkm.bench.sequence import HoldStats, settle_reached
from mkm.bench.storage import StepRecord

#: a plateau: the pressure within this of its median [bar] ...
PLATEAU_TOLERANCE_BAR = 0.03
#: ... for at least this long [s]
PLATEAU_MIN_S = 2.0
#: a staircase holds its plateaus at least this share of the record's time
STAIRCASE_SHARE = 0.5
#: a vented reading at least this far above zero is reported [bar]
VENTED_THRESHOLD_BAR = 0.02
#: quasi-static bins of a ramp: this many over its pressure range, at least this wide [bar]
RAMP_BINS = 20
RAMP_MIN_BIN_BAR = 0.02
#: ... widened by these factors in turn until this share of the samples at most is in no bin
#: (a bin of one sample is left out: a slow logger on a fast sweep, 1 Hz at 0.2 bar/s, has one
#: sample per bin, and its bins of two by chance alone were kept)
RAMP_WIDENING = (1.0, 1.5, 2.0, 3.0, 4.0, 6.0)
RAMP_LEFT_OUT_SHARE = 0.1
#: the fit of the rise's start looks this far above the rest [bar]
RISE_WINDOW_BAR = 0.05
#: a tare from fewer samples than this is said to be short
SHORT_REST_SAMPLES = 10
#: a rest's force has settled where its least-squares trend to the rest's end lies within
#: this many standard errors of none (a vent's tail pulls the most at the rest's start, and a
#: test of the halves' means misses the tail a trend shows); a rest of noise alone shows such a
#: trend by chance once in 80, and is then trimmed, not misread
SETTLED_TREND_SE = 2.5
#: a ramp turns (up to down, or back) where the pressure comes back this share of its range
TURN_SHARE = 0.1
#: a table without time of more rows than this, its successive readings within a plateau's
#: band, is a record sampled in time, read with its rows for its clock (a step table steps from
#: row to row)
RECORD_MIN_ROWS = 4 * RAMP_BINS
#: a plateau of such a record holds at least this many rows (its time unknown: a second at 10 Hz)
RECORD_PLATEAU_ROWS = 10


@dataclass
class Plateau:
    """Samples ``start`` to ``stop`` (exclusive) held near ``level_bar``."""

    start: int
    stop: int
    level_bar: float


def plateaus(time_s: np.ndarray, pressure_bar: np.ndarray,
             tolerance_bar: float = PLATEAU_TOLERANCE_BAR,
             min_s: float = PLATEAU_MIN_S) -> list[Plateau]:
    """Runs of consecutive samples within ``tolerance_bar`` of their running median, lasting at
    least ``min_s`` s, settled (:func:`_settled`)."""
    out, start = [], 0
    n = pressure_bar.size
    while start < n:
        stop = start + 1
        level = pressure_bar[start]
        while stop < n and abs(pressure_bar[stop] - level) <= tolerance_bar:
            stop += 1
            if (stop - start) % 16 == 0:  # a running median: noise does not drag the level
                level = float(np.median(pressure_bar[start:stop]))
        held = stop
        if not _settled(time_s[start:stop], pressure_bar[start:stop], tolerance_bar):
            # a rest and the slow ramp after it: the rest is the part before the kink
            held = start + max(_kink(time_s[start:stop], pressure_bar[start:stop]), 1)
            held = held if _settled(time_s[start:held], pressure_bar[start:held],
                                    tolerance_bar) else start + 1
        if time_s[held - 1] - time_s[start] >= min_s:
            out.append(Plateau(start, held, float(np.median(pressure_bar[start:held]))))
            stop = held
        # a run too short: the next starts where it left its band (a start inside it would
        # leave the band there too, or, on a ramp, find the plateau at most a band later),
        # so that each sample is scanned once: a 1 kHz ramp took minutes sample by sample
        start = stop
    return out


def _settled(t: np.ndarray, p: np.ndarray, tolerance_bar: float) -> bool:
    """Whether a run held in its band is a plateau, not a slow ramp: the trend of its middle
    half (a plateau has settled by then and leaves its band only at the end; a ramp keeps its
    rate) is within 4 standard errors of none, or carried over the whole run stays within half
    ``tolerance_bar``. A ramp of 0.002-0.02 bar/s stays 2-15 s in a 0.03 bar band that moves
    with its running median."""
    middle = slice(t.size // 4, 3 * t.size // 4)
    tt, pp = t[middle], p[middle]
    if tt.size < 4 or np.ptp(tt) <= 0:
        return True
    tt = tt - tt[0]
    (slope, _), residual = np.polyfit(tt, pp, 1, full=True)[:2]
    spread = float(np.sum((tt - tt.mean()) ** 2))
    se = math.sqrt(float(residual[0]) / (tt.size - 2) / spread) if residual.size else 0.0
    return abs(slope) <= 4.0 * se or abs(slope) * (t[-1] - t[0]) <= 0.5 * tolerance_bar


def one_reading_per_step(time_s: np.ndarray) -> bool:
    """Whether a record with times is a step table: its readings :data:`PLATEAU_MIN_S` or more
    apart (the median), too sparse for any hold to be a plateau (a logger writing each hold's
    mean, with its time)."""
    return time_s.size >= 2 and float(np.median(np.diff(time_s))) >= PLATEAU_MIN_S


def sampled_without_time(pressure_bar: np.ndarray) -> bool:
    """Whether a table without a time column is a record sampled in time, not one row per held
    pressure: more than :data:`RECORD_MIN_ROWS` rows whose successive readings lie (the median)
    within :data:`PLATEAU_TOLERANCE_BAR` of each other. A step table steps from row to row by
    its pressure step; a 10 Hz record of a slow ramp moves a few thousandths of a bar, and its
    rows as steps would be thousands of one-row steps for identify to fit."""
    return pressure_bar.size > RECORD_MIN_ROWS and float(
        np.median(np.abs(np.diff(pressure_bar)))) <= PLATEAU_TOLERANCE_BAR


def branches(pressure_bar: np.ndarray) -> list[tuple[int, int, str]]:
    """The record as monotone branches ``(start, stop, direction)``, stop exclusive: it turns
    where the pressure comes back :data:`TURN_SHARE` of its range from the branch's extreme
    (less is noise), so a record of several cycles has a rising and a falling branch each."""
    n = pressure_bar.size
    turn = TURN_SHARE * float(np.ptp(pressure_bar)) if n else 0.0
    out, start, direction, extreme = [], 0, "up", 0
    for k in range(1, n):
        rise = pressure_bar[k] - pressure_bar[extreme]
        if (rise > 0) if direction == "up" else (rise < 0):  # further along the branch
            extreme = k
        elif abs(rise) > turn:
            out.append((start, extreme + 1, direction))
            start, direction = extreme + 1, "down" if direction == "up" else "up"
            part = pressure_bar[start:k + 1]
            extreme = start + int(np.argmin(part) if direction == "down" else np.argmax(part))
    out.append((start, n, direction))
    return out


def rising_end(pressure_bar: np.ndarray) -> int:
    """Index after the last sample of the first rising branch (its highest pressure)."""
    return branches(pressure_bar)[0][1]


def vented_offset(time_s: np.ndarray, pressure_bar: np.ndarray, min_s: float = 0.5) -> float:
    """The pressure the record reads vented [bar]: the median of its first plateau (``min_s``
    or longer) when that plateau starts the record and is its lowest level, else 0 (the record
    starts pressurised); a sensor's zero error either side of zero, so below it too."""
    found = plateaus(time_s, pressure_bar, min_s=min_s)
    if not found or found[0].start != 0:
        return 0.0
    level = found[0].level_bar
    if level > np.percentile(pressure_bar, 5) + PLATEAU_TOLERANCE_BAR:
        return 0.0
    return level if abs(level) >= VENTED_THRESHOLD_BAR else 0.0


@dataclass
class Tare:
    """The force's zero of a record: ``force_N`` the mean force of the samples ``rest``
    (``std_N`` its standard error, NaN from one sample) at the pressure ``pressure_bar``."""

    force_N: float
    std_N: float
    pressure_bar: float
    rest: slice
    #: False: the force still trends to the rest's end (:func:`settled_start` found no start)
    settled: bool = True


def rise_start(time_s: np.ndarray, pressure_bar: np.ndarray) -> int:
    """Index of the first sample after the rest that starts the record: the kink of a level
    followed by a line in time, fitted by least squares to the samples up to the first that
    stands :data:`RISE_WINDOW_BAR` (or 10 noise widths) above the rising branch's lowest
    pressure; the kink's own sample counts as rising. 1 or more: a record that starts rising
    keeps its first sample as its rest."""
    p = pressure_bar[:rising_end(pressure_bar)]
    if p.size < 4:
        return 1
    step = np.diff(p)
    # the noise from successive differences: a ramp's slope only shifts their median
    noise = 1.4826 * float(np.median(np.abs(step - np.median(step)))) / math.sqrt(2.0)
    above = np.flatnonzero(p > p.min() + max(10.0 * noise, RISE_WINDOW_BAR))
    w = int(above[0]) + 1 if above.size else p.size
    return max(_kink(time_s[:w], p[:w], rising=True), 1)


def _kink(t: np.ndarray, p: np.ndarray, rising: bool = False) -> int:
    """Index of the kink of the level followed by a line (rising, if ``rising``) that fits
    ``p(t)`` best by least squares: 1 to n - 3 (a level of one sample at least, a line of
    three), 0 when none fits (fewer than 4 samples)."""
    w = t.size
    if w < 4:
        return 0
    t = t - t[0]
    m = np.arange(w, 0, -1)  # samples from j on

    def tail(x):
        return np.cumsum(x[::-1])[::-1]

    s1, s2, sp, stp = tail(t), tail(t * t), tail(p), tail(t * p)
    # the line's regressor x_i = max(t_i - t_j, 0) for a kink at sample j
    sx = s1 - m * t
    sxx = s2 - 2.0 * t * s1 + m * t * t - sx * sx / w
    sxp = stp - t * sp - sx * sp[0] / w
    with np.errstate(divide="ignore", invalid="ignore"):
        explained = np.where((sxx > 0) & ((sxp > 0) if rising else True), sxp * sxp / sxx,
                             -np.inf)
    explained[0] = explained[-2:] = -np.inf
    return int(np.argmax(explained))


def tare(time_s: np.ndarray, pressure_bar: np.ndarray, force_N: np.ndarray) -> Tare:
    """The force's zero (module docstring): the samples before :func:`rise_start`."""
    rest = slice(0, rise_start(time_s, pressure_bar))
    f = force_N[rest]
    std = float(f.std(ddof=1)) / math.sqrt(f.size) if f.size > 1 else math.nan
    return Tare(float(f.mean()), std, float(np.median(pressure_bar[rest])), rest)


def end_rest(time_s: np.ndarray, pressure_bar: np.ndarray, force_N: np.ndarray) -> Tare:
    """The rest that ends the record, found as :func:`tare` finds the one that starts it, on
    the record read backwards, from where its force has settled (:func:`settled_start`; its
    second half, ``settled`` False, where it never does): its mean force is the zero read after
    the run (a load cell that drifted, or a muscle that did not come back, reads another)."""
    n = pressure_bar.size
    back = tare(time_s[-1] - time_s[::-1], pressure_bar[::-1], force_N[::-1])
    first = n - back.rest.stop
    start = settled_start(time_s[first:], force_N[first:])
    settled = start is not None
    first += start if settled else (n - first) // 2
    f = force_N[first:]
    std = float(f.std(ddof=1)) / math.sqrt(f.size) if f.size > 1 else math.nan
    return Tare(float(f.mean()), std, float(np.median(pressure_bar[first:])), slice(first, n),
                settled)


#: a zero that steps (:func:`zero_step`) is judged over this many samples either side
ZERO_STEP_SAMPLES = 5
#: ... the pressure's medians either side within this [bar]: held, the step not the muscle's
ZERO_STEP_HELD_BAR = 0.01
#: ... and shows in the logged force over this many samples at most: a display's or
#: amplifier's moving average of N readings turns the tare's step into a line over N samples
ZERO_STEP_SMEAR_SAMPLES = 10


@dataclass(frozen=True)
class ZeroStep:
    """Where a record's zero stepped (:func:`zero_step`): the samples from ``start`` to
    ``first`` - 1 read it part way (a filter's average of readings either side of the tare;
    none where it steps from one sample to the next), ``first`` on read the new zero."""
    start: int
    first: int
    step_N: float


def zero_step(pressure_bar: np.ndarray, force_N: np.ndarray, within: slice, drift_N: float,
              spread_N: float) -> ZeroStep | None:
    """Where a record's zero stepped within ``within``: the force's median over
    :data:`ZERO_STEP_SAMPLES` samples differs from the median of those before it (next to
    them, or up to :data:`ZERO_STEP_SMEAR_SAMPLES` samples on) in the sense of ``drift_N``
    (the closing rest's zero less the starting one's), by the drift (within a tenth of it and
    4 of its standard errors) and 20 times the noise of a sample's difference from the next
    or more (``spread_N``, the load cell's spread at rest), while the pressure holds (every
    such median between the two within :data:`ZERO_STEP_HELD_BAR`): a load cell zeroed again
    mid-record, its tare pressed with the muscle pulling. The nearest such windows are taken;
    the samples between them that read neither zero are the step's spread, at most
    :data:`ZERO_STEP_SMEAR_SAMPLES`. A drift in time shows no such step, and a ramp's turn
    through its friction no held pressure. None where there is none."""
    w = ZERO_STEP_SAMPLES
    if not math.isfinite(spread_N) or not drift_N:
        return None
    windows = np.lib.stride_tricks.sliding_window_view
    f = np.median(windows(force_N, w), axis=1)  # f[k]: the median of samples k to k + w - 1
    p = np.median(windows(pressure_bar, w), axis=1)
    sign = math.copysign(1.0, drift_N)
    # the standard error of the difference of two medians of w samples (1.25 a mean's)
    se = 1.25 * spread_N * math.sqrt(2.0 / w)
    for gap in range(ZERO_STEP_SMEAR_SAMPLES + 1):
        # the windows before (from k - w) and after (from k + gap) the step
        start, stop = max(within.start or 0, w), min(within.stop, force_N.size - w + 1) - gap
        if stop <= start:
            return None
        k = np.arange(start, stop)
        steps = f[k + gap] - f[k - w]
        between = windows(p, w + gap + 1)[k - w]  # every window's median from one to the other
        held = np.ptp(between, axis=1) <= ZERO_STEP_HELD_BAR
        along = np.where(held, steps * sign, -np.inf)
        best = int(np.argmax(along))
        step = float(steps[best])
        # a step that large is no noise
        if (along[best] < 20.0 * math.sqrt(2.0) * spread_N
                or abs(step - drift_N) > 0.1 * abs(drift_N) + 4.0 * se):
            continue
        lo, hi = int(k[best]) - w, int(k[best]) + gap + w
        # each sample's way from the zero before to the one after, along the step; off either
        # beyond its noise and a hundredth of the step (a filter's tail)
        moved = (force_N[lo:hi] - f[lo]) * math.copysign(1.0, step)
        off = 4.0 * spread_N + 0.01 * abs(step)
        left = int(np.argmax(moved > off))  # the first sample off the zero before
        below = np.flatnonzero(moved < abs(step) - off)
        first = max(int(below[-1]) + 1 if below.size else 0, left)
        return ZeroStep(lo + left, lo + first, step)
    return None


def settled_start(time_s: np.ndarray, force_N: np.ndarray) -> int | None:
    """The first sample of a rest from which its force's least-squares trend to the end lies
    within :data:`SETTLED_TREND_SE` standard errors of none, leaving
    :data:`SHORT_REST_SAMPLES` samples or more (a shorter rest judged whole); None where none
    does (still moving). A rest of fewer than 3 samples shows no trend: 0."""
    n = time_s.size
    if n < 3:
        return 0
    t, f = time_s - time_s[0], force_N - force_N.mean()  # centred: sums without cancellation

    def tail(x):
        return np.cumsum(x[::-1])[::-1]

    m = np.arange(n, 0, -1, dtype=float)  # samples from k on
    st, stt, sf, sff, stf = tail(t), tail(t * t), tail(f), tail(f * f), tail(t * f)
    sxx = stt - st * st / m
    sxy = stf - st * sf / m
    syy = sff - sf * sf / m
    with np.errstate(divide="ignore", invalid="ignore"):
        slope = sxy / sxx
        rss = np.maximum(syy - sxy * slope, 0.0)
        se = np.sqrt(rss / (m - 2.0) / sxx)
        flat = np.abs(slope) <= SETTLED_TREND_SE * se
    candidates = np.flatnonzero(flat[:min(max(n - SHORT_REST_SAMPLES, 0), n - 3) + 1])
    return int(candidates[0]) if candidates.size else None


def held_plateaus(time_s: np.ndarray, pressure_bar: np.ndarray,
                  min_s: float = PLATEAU_MIN_S) -> list[Plateau]:
    """The plateaus above the vented level: the holds of a staircase."""
    low = float(pressure_bar.min()) + PLATEAU_TOLERANCE_BAR
    return [q for q in plateaus(time_s, pressure_bar, min_s=min_s) if q.level_bar > low]


def shape(time_s: np.ndarray, pressure_bar: np.ndarray,
          held: list[Plateau] | None = None) -> str:
    """``"staircase"`` when plateaus above the vented level (``held``, else
    :func:`held_plateaus`) hold at least :data:`STAIRCASE_SHARE` of the pressurised time, there
    are two or more, and they step by more than twice :data:`PLATEAU_TOLERANCE_BAR` (the median
    step), else ``"ramp"``."""
    pressurised = pressure_bar > float(pressure_bar.min()) + PLATEAU_TOLERANCE_BAR
    if not pressurised.any():
        return "ramp"
    held = held_plateaus(time_s, pressure_bar) if held is None else held
    dt = np.diff(time_s, append=time_s[-1])
    held_s = sum(float(dt[q.start:q.stop].sum()) for q in held)
    # a staircase steps from level to level; a slow ramp's stretches that passed for plateaus
    # follow each other a band apart
    steps_bar = np.abs(np.diff([q.level_bar for q in held]))
    return "staircase" if len(held) >= 2 and held_s >= STAIRCASE_SHARE * float(
        dt[pressurised].sum()) and np.median(steps_bar) > 2 * PLATEAU_TOLERANCE_BAR else "ramp"


def directions(pressure_bar: np.ndarray, held: list[Plateau]) -> list[str]:
    """Each plateau's branch: ``"up"`` where it lies above the plateau before it or the record
    was vented between them (a staircase after a pre-conditioning cycle rises from its vent,
    as the braid's friction does), else ``"down"``."""
    vented = float(pressure_bar.min()) + PLATEAU_TOLERANCE_BAR  # held_plateaus' vented level
    out, previous, stop = [], 0.0, 0
    for q in held:
        between = pressure_bar[stop:q.start]
        rose = q.level_bar >= previous or (between.size > 0 and between.min() <= vented)
        out.append("up" if rose else "down")
        previous, stop = q.level_bar, q.stop
    return out


#: a load cell spreading more than ``settle.max_force_std_N`` at rest has the settle test's
#: force limits scaled to this many times its spread, the limit the bench asks for such a cell
#: (:func:`mkm.bench.sequence.settle_warning`)
SETTLE_SPREADS = 3.0


def settle_for_cell(config, rest_std_N: float):
    """``config`` (a :class:`mkm.bench.config.BenchConfig`) with its ``[settle]`` force limits
    scaled to the record's load cell, and the factor (1.0: unchanged). A cell spreading
    ``rest_std_N`` [N] at rest beyond ``settle.max_force_std_N`` (a 10 kN cell's 3 N under a
    60 mm muscle) would leave every hold unsettled under the packaged limits: its spread limit
    becomes :data:`SETTLE_SPREADS` times that spread, and its slope limit grows by the same
    factor, as the slope a window's noise alone makes grows with the noise."""
    st = config.settle
    if not rest_std_N > st.max_force_std_N:  # NaN too: no rest to read the cell's spread from
        return config, 1.0
    factor = SETTLE_SPREADS * rest_std_N / st.max_force_std_N
    return config.replace(settle={
        "max_force_std_N": st.max_force_std_N * factor,
        "max_force_slope_N_per_s": st.max_force_slope_N_per_s * factor}), factor


def staircase_steps(time_s, pressure_bar, force_N, settle_config,
                    held: list[Plateau] | None = None,
                    unread: slice = slice(0, 0)) -> tuple[list[StepRecord], np.ndarray]:
    """The steps of a staircase (module docstring) and each sample's step (-1: between
    steps). ``settle_config``: a :class:`mkm.bench.config.BenchConfig` whose ``[settle]``
    judges the plateaus; ``held``: its :func:`held_plateaus`, if found already; ``unread``:
    samples in no hold's mean (a zero stepping through them, :func:`zero_step`)."""
    held = held_plateaus(time_s, pressure_bar) if held is None else held
    step_of = np.full(time_s.size, -1)
    records = []
    repeats: dict[tuple[str, float], int] = {}
    for k, (q, direction) in enumerate(zip(held, directions(pressure_bar, held), strict=True)):
        stop = q.start + _held_stop(pressure_bar[q.start:q.stop], q.level_bar)
        t, f, p = time_s[q.start:stop], force_N[q.start:stop], pressure_bar[q.start:stop]
        settle_at, settled = _settle_index(t, f, p, q.level_bar, settle_config)
        hold = HoldStats()
        for j in range(settle_at, t.size):
            if not unread.start <= q.start + j < unread.stop:
                hold.add(float(t[j]), float(f[j]), float(p[j]))
        key = (direction, round(q.level_bar, 2))
        repeats[key] = repeats.get(key, -1) + 1
        step_of[q.start:stop] = k
        records.append(StepRecord(
            k, direction, repeats[key], round(q.level_bar, 4), hold.pressure_mean, hold.mean,
            hold.std, hold.n, settled, float(t[settle_at] - t[0]), float(t[0]), float(t[-1]),
            hold.drift_N))
    return records, step_of


def unsettled_note(pressure_bar: np.ndarray, held: list[Plateau], steps: list[StepRecord],
                   settle_config) -> str:
    """What a staircase's steps that did not settle mean for the user (``""``: each settled):
    ``mkm identify`` fits settled steps alone. One held before the record first vents between
    two plateaus, with settled steps after, is a pre-conditioning cycle's top (a short hold
    before the staircase starts from its vent): left out as it should be; any other is a
    measured step lost, and a longer hold keeps it."""
    vented = float(pressure_bar.min()) + PLATEAU_TOLERANCE_BAR
    first_vent = next((j for j, (a, b) in enumerate(zip(held, held[1:], strict=False))
                       if b.start > a.stop and pressure_bar[a.stop:b.start].min() <= vented),
                      None)
    later_settled = first_vent is not None and any(s.settled for s in steps[first_vent + 1:])
    said = []
    for k, step in enumerate(steps):
        if step.settled:
            continue
        held_s = step.end_s - step.start_s
        if later_settled and k <= first_vent:
            said.append(f"step {k} at {step.set_pressure_bar:.3g} bar, held {held_s:.3g} s "
                        "before the record vents and its staircase starts: a pre-conditioning "
                        "cycle's top, not a step of the measurement: nothing to do")
        else:
            said.append(f"step {k} at {step.set_pressure_bar:.3g} bar, held {held_s:.3g} s: "
                        "its force did not settle within the hold; to fit it, hold each step "
                        f"longer than the bench's settle.min_dwell_s "
                        f"({settle_config.settle.min_dwell_s:g} s) and until the force is "
                        "steady")
    if not said:
        return ""
    return (f"{len(said)} step(s) did not settle (the bench's settle test), kept in steps.csv "
            "with settled = false and left out by mkm identify, which fits settled holds "
            "alone: " + "; ".join(said))
#: a hold ends before the trailing samples of its plateau whose pressure lies this many robust
#: standard deviations of the plateau's pressure from its level, and :data:`DEPARTURE_FLOOR_BAR`
#: at least: the next step's rise, within the plateau's band, pulls a steep muscle's force with
#: it (0.02 bar of a 60 mm muscle's 4 kN/bar: 90 N on a 3 N cell)
DEPARTURE_SIGMAS = 4.0
DEPARTURE_FLOOR_BAR = 0.005


def _held_stop(p: np.ndarray, level_bar: float) -> int:
    """How many of a plateau's samples (its pressures ``p``, held at ``level_bar``) the hold
    keeps: all but the trailing ones that leave the level (:data:`DEPARTURE_SIGMAS`), never
    more than half of them."""
    away = np.abs(p - level_bar)
    bound = max(DEPARTURE_SIGMAS * 1.4826 * float(np.median(away)), DEPARTURE_FLOOR_BAR)
    stop = p.size
    while stop > p.size // 2 + 1 and away[stop - 1] > bound:
        stop -= 1
    return stop


def untimed_staircase_steps(pressure_bar, force_N, held: list[Plateau],
                            unread: slice = slice(0, 0)) -> list[StepRecord]:
    """The steps of a staircase recorded without its time (its rows the clock: ``held`` found
    with :data:`RECORD_PLATEAU_ROWS`). Without time the bench's settle test cannot judge a
    plateau: each is averaged over its second half, as a plateau that never settles is, its
    start and end times unknown (NaN); the rows ``unread`` in no mean."""
    records = []
    repeats: dict[tuple[str, float], int] = {}
    for k, (q, direction) in enumerate(zip(held, directions(pressure_bar, held), strict=True)):
        hold = HoldStats()
        for j in range((q.start + q.stop) // 2, q.stop):
            if not unread.start <= j < unread.stop:
                hold.add(float(j), float(force_N[j]), float(pressure_bar[j]))
        key = (direction, round(q.level_bar, 2))
        repeats[key] = repeats.get(key, -1) + 1
        records.append(StepRecord(
            k, direction, repeats[key], round(q.level_bar, 4), hold.pressure_mean, hold.mean,
            hold.std, hold.n, True, math.nan, math.nan, math.nan, hold.drift_N))
    return records


def _settle_index(t, f, p, level_bar, config) -> tuple[int, bool]:
    """The first sample of the hold: where the bench's settle test first passes, judged once
    per second of data after ``settle.min_dwell_s`` (or the plateau's half, if that is
    shorter); the second half of the plateau when it never passes."""
    start = min(config.settle.min_dwell_s, 0.5 * (t[-1] - t[0]))
    check = t[0] + start
    for j in range(1, t.size):
        if t[j] < check:
            continue
        if settle_reached(t[:j + 1], f[:j + 1], p[:j + 1], level_bar, config):
            return j, True
        check = t[j] + 1.0
    return t.size // 2, False


def ramp_steps(time_s, pressure_bar, force_N) -> tuple[list[StepRecord], np.ndarray, float]:
    """The quasi-static points of a ramp (module docstring), each sample's step (-1: none),
    and the bin width [bar]: a twentieth of the pressure's range, or wider
    (:data:`RAMP_WIDENING`) where that leaves more than :data:`RAMP_LEFT_OUT_SHARE` of the
    samples in bins of one."""
    low, high = float(pressure_bar.min()), float(pressure_bar.max())
    base = max((high - low) / RAMP_BINS, RAMP_MIN_BIN_BAR)
    for factor in RAMP_WIDENING:
        records, step_of = _ramp_bins(time_s, pressure_bar, force_N, low, base * factor)
        if np.mean(step_of < 0) <= RAMP_LEFT_OUT_SHARE:
            break
    return records, step_of, base * factor


def _ramp_bins(time_s, pressure_bar, force_N, low: float,
               width: float) -> tuple[list[StepRecord], np.ndarray]:
    """:func:`ramp_steps`'s points in bins of ``width`` [bar] from ``low``, and each sample's
    step (-1: in a bin of one)."""
    # a twentieth of the range: 20 bins, not 21 for the rounding of the division
    bins = max(math.ceil((float(pressure_bar.max()) - low) / width - 1e-9), 1)
    step_of = np.full(time_s.size, -1)
    records: list[StepRecord] = []
    repeats = {"up": 0, "down": 0}
    for start, stop, direction in branches(pressure_bar):
        part = slice(start, stop)
        repeat = repeats[direction]
        repeats[direction] += 1
        p = pressure_bar[part]
        if p.size == 0:
            continue
        index = np.floor((p - low) / width).clip(0, bins - 1).astype(int)
        # each bin one stretch of time: a sample the noise drops back a bin stays in this one
        index = np.maximum.accumulate(index) if direction == "up" else \
            np.minimum.accumulate(index)
        offset = part.start
        for b in (np.unique(index) if direction == "up" else np.unique(index)[::-1]):
            members = np.flatnonzero(index == b) + offset
            if members.size < 2:
                continue
            hold = HoldStats()
            for j in members:
                hold.add(float(time_s[j]), float(force_N[j]), float(pressure_bar[j]))
            k = len(records)
            step_of[members] = k
            records.append(StepRecord(
                k, direction, repeat, round(low + (b + 0.5) * width, 4), hold.pressure_mean,
                hold.mean, hold.std, hold.n, True, 0.0, float(time_s[members[0]]),
                float(time_s[members[-1]]), math.nan))
    return records, step_of
