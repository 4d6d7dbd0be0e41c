"""Short bench procedures besides a run: tare, load-cell calibration, dry-run check, vent.

Each opens the device in :func:`session`, which owns the bench for the duration
(:mod:`mkm.bench.ownership`: a live run on it makes them refuse), vents and closes it whatever
happens, and first vents a bench left pressurised by a run that died without venting
(:mod:`mkm.bench.unvented`), saying which run it was. :func:`vent` on a bench a live run holds
asks that run to stop (it vents itself) and then vents and verifies.
"""

from __future__ import annotations

import math
import threading
import time
from collections.abc import Iterator
from contextlib import contextmanager

import numpy as np
from scipy import stats

from mkm.bench.backend import (
    AOWriteFailed,
    Backend,
    BenchError,
    DaqDisconnected,
    DeviceInfo,
    in_words,
)
from mkm.bench.budget import budget_table, expected_budget
from mkm.bench.config import BenchConfig, estimate_duration_s, plan_steps
from mkm.bench.ownership import BenchOwner, StateFolderBroken, request_stop
from mkm.bench.preflight import ForceCeiling, ceiling_lines, expected_force_N, warnings
from mkm.bench.run import (
    OPEN_HUNG,
    READ_HANG_MARGIN_S,
    VENT_WRITES,
    WATCH_EVERY_S,
    WATCHDOG_WRITE_S,
    BoundedWrite,
    DriverHangs,
    StderrNotice,
    WriteHung,
    bench_key_within,
    close_within,
    driver_call,
    make_backend,
    make_operator,
    open_within,
    vent_dead_runs,
    with_backend,
)
from mkm.bench.sequence import (
    TareInvalid,
    check_vented_monitor,
    monitor_zero_warning,
    one_code_warning,
    rest_warning,
    settle_warning,
    shift_warning,
    validate_tare,
    vented_monitor,
)
from mkm.bench.sim import STANDARD_GRAVITY
from mkm.bench.unvented import (
    STATE_START_S,
    StateFolderThread,
    mark_vent,
    state_dir,
    vent_marker,
    vent_unvented,
)
from mkm.bench.vent import VentCheck, reading_bar, verify_vent

MAX_SECONDS = 600.0  # a tare or a calibration mass is averaged for at most this long
STOP_WAIT_S = 30.0  # `mkm vent` waits this long for a run it asked to stop


@contextmanager
def session(backend: Backend, command: str, notify=None) -> Iterator[DeviceInfo]:
    """Own the bench (``command`` names what for), open ``backend`` (which writes the vent
    command; a lost NI device is reset and opened again first), vent and report a bench a dead
    run left pressurised, and close (vent again) on exit. ``notify`` receives the operator's
    lines (default: stderr, ``mkm <command>: ...``). A serial number that names the bench
    that hangs (:func:`mkm.bench.run.bench_key_within`), an open that hangs
    (:func:`mkm.bench.run.open_within`) or a vent written for dead runs that hangs
    (:func:`mkm.bench.run.vent_dead_runs`) ends the command."""
    notify = notify or StderrNotice(command)
    owner = BenchOwner(bench_key_within(backend, "; VENT BY HAND"), command)
    try:
        with owner:
            dead_runs = owner.dead_runs()  # before the device is opened
            # never closed when it hangs or is interrupted
            info = _open_said(backend.open, notify, f"{OPEN_HUNG}; VENT BY HAND")
            try:
                for marker in vent_dead_runs(backend, dead_runs, owner.on_state_folder):
                    notify(marker.vented_now())
                yield info
            finally:
                closing = close_within(backend)  # a driver that hangs there holds no one
                if closing:
                    notify(closing)
    finally:  # vented and closed: a state folder that hangs is not waited for
        if owner.problem:
            notify(owner.problem)


def _open_said(open_device, notify, then: str = OPEN_HUNG):
    """:func:`mkm.bench.run.open_within`; a Ctrl-C while the open is under way in the driver
    (these commands take no stop signals of their own) is said to ``notify`` as it goes: the
    vent the open writes is not known to be written, and nothing is to be written or closed
    behind the open."""
    try:
        return open_within(open_device, then)
    except KeyboardInterrupt:
        notify(f"interrupted during the device's open: {OPEN_HUNG}; VENT BY HAND")
        raise


def _seconds(seconds: float) -> float:
    if not 0 < seconds <= MAX_SECONDS:
        raise ValueError(f"seconds={seconds!r} is invalid: expected a duration in (0, "
                         f"{MAX_SECONDS:g}] s")
    return float(seconds)


def mean_volts(backend: Backend, config: BenchConfig, seconds: float) -> np.ndarray:
    """Read ``seconds`` of samples; return them (samples x inputs) in volts."""
    n = max(2, int(round(seconds * config.daq.sample_rate_hz)))
    block = backend.read(n, timeout_s=seconds + config.daq.read_timeout_s)
    return block.volts


def tare(config: BenchConfig, backend: str | None = None, clock: str = "virtual",
         seconds: float = 5.0) -> dict:
    """Load-cell offset at 0 bar: mean and spread of ``seconds`` of volts, vented; checked by
    :func:`mkm.bench.sequence.validate_tare` (``TareInvalid`` when it would stop a run)."""
    seconds = _seconds(seconds)
    config = with_backend(config, backend)
    device = make_backend(config, clock)
    with session(device, "tare") as info:
        volts = _read_vented(device, config, seconds)
    out = at_rest(volts, config)
    return {**out, "shift_from_config_N": out["shift_N"], "device": info.as_dict()}


def _read_vented(device: Backend, config: BenchConfig, seconds: float) -> np.ndarray:
    """``seconds`` of every input, read vented in a session's open device, each driver call
    bounded (:class:`_Bounded`)."""
    bounded = _Bounded(device, config.daq.sample_rate_hz)
    bounded.start()
    return mean_volts(bounded, config, seconds)


#: the warnings of :func:`at_rest`, by their keys
AT_REST_WARNINGS = ("settle_warning", "one_code_warning", "rest_warning", "shift_warning",
                    "monitor_warning")


def at_rest(volts: np.ndarray, config: BenchConfig) -> dict:
    """What a run's tare finds in ``volts`` read vented (the load cell's first, the monitor's
    second): :func:`mkm.bench.sequence.validate_tare`, the monitor's vented zero, and the
    warnings :data:`AT_REST_WARNINGS` ("" where none); ``TareInvalid`` where it would stop the
    run."""
    out = validate_tare(volts[:, 0], config)
    if config.regulator.electronic:
        out.update(vented_monitor(config.regulator.monitor_bar(volts[:, 1])))
        check_vented_monitor(out, config)  # as a run's tare: it would stop the run
    return {**out, "settle_warning": settle_warning(out["std_N"], config),
            "one_code_warning": one_code_warning(out, config),
            "rest_warning": rest_warning(out, config),
            "shift_warning": shift_warning(out, config),
            "monitor_warning": monitor_zero_warning(out, config)}


def vent(config: BenchConfig, backend: str | None = None, clock: str = "virtual",
         notify=None, stop_wait_s: float = STOP_WAIT_S) -> dict:
    """Command 0 bar and verify it (:func:`mkm.bench.vent.verify_vent`), then do the
    bookkeeping.

    A live run holding the bench is asked to stop first (it vents itself at its next safe
    point), then the bench is vented and verified here. The bench state folder (lock, stop
    request, markers of dead runs) is bookkeeping: when it cannot be used (read-only, full, a
    lock that is not a file) the vent goes ahead without it and the problem is returned in
    ``bookkeeping`` instead of stopping the vent. Returns ``pressure_bar`` (the last reading;
    NaN with a manual regulator, to be vented by hand), ``vented``, ``waited_s``, ``manual``,
    ``stopped`` (the holder asked to stop, or None) and ``bookkeeping`` (problems met, after
    the vent). A device lost (at open, on the vent write or on the check's reads) is reset and
    vented on fresh tasks first (NI: ``open`` and ``revive``, within a few seconds). Raises
    :class:`BenchError` when the device cannot be opened, its open does not return within
    :data:`mkm.bench.run.OPEN_WAIT_S` (the driver hangs; so for its serial number, read before
    it, :func:`mkm.bench.run.bench_key_within`) or the device stays lost, when the
    pressure stays above ``safety.vent_below_bar`` for ``safety.vent_timeout_s``, or a live
    holder does not let go.
    """
    notify = notify or StderrNotice("vent")
    config = with_backend(config, backend)
    device = make_backend(config, clock)
    # needed before the vent: a run holding the bench is asked to stop (its tasks hold the
    # device) and the lock is keyed by it; a driver that hangs there ends the command
    key = bench_key_within(device)
    bookkeeping: list[str] = []
    stopped, answered = _ask_to_stop(key, stop_wait_s, bookkeeping)
    if stopped:
        notify(f"asked the run holding the bench (pid {stopped.get('pid')}, `mkm "
               f"{stopped.get('command')}`, started {stopped.get('started_utc')}) to stop; it "
               "stopped")
    owner = BenchOwner(key, "vent")
    try:
        if answered:  # a state folder that hangs is not waited for again: the vent goes first
            owner.__enter__()
    except StateFolderBroken as exc:  # vent without the lock: venting twice is harmless
        bookkeeping.append(str(exc))
    open_hung = False
    try:
        # the open writes the vent (a lost device is reset first); a driver that hangs there
        # leaves the user staring at nothing: bounded, then said
        try:
            _open_said(lambda: _refused_again(device.open, notify), notify)
        except (DriverHangs, KeyboardInterrupt):
            open_hung = True
            raise
        if config.regulator.electronic:  # marked once the vent is out, never waited for: a
            # process killed during the check leaves the bench marked
            owner.post(lambda: mark_vent(key, "vent", "", owner.state))
        check = _vent_and_verify(device, config, notify)
        unproven = []
        if answered:
            problems, dead = _mend_dead_runs(device, owner, notify)
            bookkeeping.extend(problems)
            unproven = [m for m in dead if m.unfollowed_bar is not None]
        if check is not None:  # marked or not, before the bench is let go
            bookkeeping.extend(_mark(owner, key, check))
    finally:
        try:
            # a close would wait behind an open under way in the driver
            closing = "" if open_hung else close_within(device)
            if closing:
                bookkeeping.append(closing)
        finally:
            owner.__exit__()
            if owner.problem:
                bookkeeping.append(owner.problem)
    if not config.regulator.electronic:
        return {"pressure_bar": float("nan"), "vented": False, "waited_s": 0.0,
                "manual": True, "stopped": stopped, "bookkeeping": bookkeeping}
    if not check.verified:
        raise BenchError(f"{check.describe()}: VENT BY HAND and check the regulator"
                         + "".join(f"; {p}" for p in bookkeeping))
    if unproven:  # a monitor that run's check doubted: its low reading now proves nothing
        found = unproven[0].vent_unverified or (f"the monitor did not follow the "
                                                f"{unproven[0].unfollowed_bar:g} bar commanded")
        raise BenchError(
            f"the vent went out, but the monitor's {reading_bar(check.pressure_bar)} bar does not "
            f"verify it: in run {unproven[0].run_path} {found}; check the muscle and the monitor"
            + "".join(f"; {p}" for p in bookkeeping))
    return {"pressure_bar": check.pressure_bar, "vented": True, "waited_s": check.waited_s,
            "manual": False, "stopped": stopped, "bookkeeping": bookkeeping}


def _refused_again(write, notify) -> None:
    """``write()`` (a vent command, or the open that writes it), written again at once when
    the device refuses it (an AO write error), :data:`mkm.bench.run.VENT_WRITES` times in all
    as a run's shutdown does; each refusal said. Raises the last refusal."""
    for attempt in range(1, VENT_WRITES + 1):
        try:
            write()
            return
        except AOWriteFailed as exc:
            if attempt == VENT_WRITES:
                raise
            notify(f"vent command failed ({in_words(exc)}), tried again")


def _mark(owner: BenchOwner, key: str, check: VentCheck) -> list[str]:
    """After the check: the bench's marker removed (a verified vent) or saying what the check
    found (:func:`mkm.bench.unvented.mark_vent`), on the owner's state folder thread (bounded:
    a state folder that hangs is said, not waited for; one already said to hang is not said
    again); the problems met."""
    said = owner.hung
    if check.verified:
        done, out = owner.on_state_folder(
            lambda: vent_marker(key, "vent", owner.state).unlink(missing_ok=True),
            "the bench's marker was removed after the verified vent")
    else:
        what = check.describe()
        done, out = owner.on_state_folder(lambda: mark_vent(key, "vent", what, owner.state),
                                          "the bench was marked with its vent not verified")
    if not done:
        return [] if said else [str(out)]
    if isinstance(out, OSError):
        return [f"the bench state folder {owner.state} could not "
                + ("remove the bench's marker" if check.verified else "record the vent not "
                   "verified") + f" ({out.strerror or out}): the next command on this bench "
                + ("names this vent as not verified" if check.verified else "is not told")]
    if isinstance(out, BaseException):
        raise out
    return []


def _ask_to_stop(key: str, stop_wait_s: float, bookkeeping: list[str]
                 ) -> tuple[dict | None, bool]:
    """Ask a live holder of the bench to stop (:func:`mkm.bench.ownership.request_stop`), on a
    thread of its own: a state folder that hangs does not keep the vent from going out. The
    holder that stopped (or None), and whether the state folder answered within
    ``stop_wait_s`` + :data:`mkm.bench.unvented.STATE_START_S` (a problem in ``bookkeeping``
    when not); :class:`mkm.bench.ownership.BenchBusy` when a holder did not let go."""
    state = state_dir()  # resolved now: the thread may run late, after MKM_STATE_DIR moved
    asking = StateFolderThread("mkm-vent-ask")
    done, answer = asking.call(lambda: request_stop(key, "`mkm vent`", state, stop_wait_s),
                               stop_wait_s + STATE_START_S)
    asking.end()  # once the state folder has answered
    if not done:
        bookkeeping.append(f"the bench state folder {state} did not answer within "
                           f"{stop_wait_s + STATE_START_S:g} s (it hangs): no run holding the "
                           "bench was asked to stop, the bench was vented without its lock "
                           "and the markers of dead runs were not looked for")
        return None, False
    if isinstance(answer, StateFolderBroken | OSError):
        bookkeeping.append(str(answer))
        return None, True
    if isinstance(answer, BaseException):
        raise answer
    return answer, True


def _vent_and_verify(device: Backend, config: BenchConfig, notify):
    """Write 0 bar and, with an electronic regulator, verify it; a device lost on the write or
    on the check's reads is reset and vented on fresh tasks once (``revive``, NI only), and
    the vent checked again; a write the device refuses is written again
    (:func:`_refused_again`, said to ``notify``). The check (None with a manual regulator)."""
    revive = getattr(device, "revive", None)
    try:
        _refused_again(lambda: device.write_command(0.0), notify)
        started = False
    except DaqDisconnected:
        if revive is None:
            raise
        revive()  # raises when the device stays lost: VENT BY HAND
        revive, started = None, True
    if not config.regulator.electronic:
        return None
    check = _watched_check(device, config, start=not started)
    if check.device_lost and revive is not None:
        revive()
        check = _watched_check(device, config)
    return check


class _Timed:
    """``backend`` whose call to the driver under way is known: :attr:`calling` holds when it
    began, how long it may take (a read: its timeout, its block's time and
    :data:`mkm.bench.run.READ_HANG_MARGIN_S`; the count of samples waiting: the margin; the
    start of the inputs: the AO write's timeout, :data:`mkm.bench.run.WATCHDOG_WRITE_S`, and
    the margin, as a command write) and what it is, in words; None between calls."""

    def __init__(self, backend: Backend, rate_hz: float):
        self._backend, self._rate_hz = backend, rate_hz
        self.calling: tuple[float, float, str] | None = None

    def read(self, n_samples: int, timeout_s: float):
        self.calling = (time.monotonic(),
                        timeout_s + n_samples / self._rate_hz + READ_HANG_MARGIN_S,
                        f"a read of the device did not return within {{:.1f}} s (its timeout "
                        f"{timeout_s:g} s)")
        try:
            return self._backend.read(n_samples, timeout_s)
        finally:
            self.calling = None

    def start(self) -> None:
        self.calling = (time.monotonic(), WATCHDOG_WRITE_S + READ_HANG_MARGIN_S,
                        "starting the device's inputs did not return within {:.1f} s")
        try:
            self._backend.start()
        finally:
            self.calling = None

    def available(self) -> int:
        self.calling = (time.monotonic(), READ_HANG_MARGIN_S, "the device did not say how many "
                        "samples wait within {:.1f} s")
        try:
            return self._backend.available()
        finally:
            self.calling = None

    def __getattr__(self, name):
        return getattr(self._backend, name)


class _Bounded:
    """``backend`` whose start of the inputs, reads and count of samples waiting each return
    within the bound a run's watchdog gives them (as :class:`_Timed`'s), or end the command
    (:class:`mkm.bench.run.DriverHangs`, the call left behind): a tare or a load-cell
    calibration, at 0 bar, has no watchdog, and a driver that hangs held it, nothing said."""

    THEN = "nothing was pressurised, and nothing is measured"

    def __init__(self, backend: Backend, rate_hz: float):
        self._backend, self._rate_hz = backend, rate_hz

    def start(self) -> None:
        driver_call(self._backend.start, "starting the device's inputs", self.THEN,
                    WATCHDOG_WRITE_S + READ_HANG_MARGIN_S)

    def read(self, n_samples: int, timeout_s: float):
        return driver_call(lambda: self._backend.read(n_samples, timeout_s),
                           f"a read of the device (its timeout {timeout_s:g} s)", self.THEN,
                           timeout_s + n_samples / self._rate_hz + READ_HANG_MARGIN_S)

    def available(self) -> int:
        return driver_call(self._backend.available, "the count of samples waiting",
                           self.THEN, READ_HANG_MARGIN_S)

    def __getattr__(self, name):
        return getattr(self._backend, name)


def _watched_check(device: Backend, config: BenchConfig, start: bool = False) -> VentCheck:
    """:func:`mkm.bench.vent.verify_vent` on a thread of its own, its reads (and, with
    ``start``, the start of the inputs before them) watched as a run's watchdog watches them: a
    call that hangs (a driver that does not keep its timeout) ends the check unverified, the
    call left behind."""
    timed, out = _Timed(device, config.daq.sample_rate_hz), []

    def check() -> None:
        try:
            if start:
                timed.start()
            out.append(verify_vent(timed, config))
        except BaseException as exc:  # raised by the caller
            out.append(exc)

    begun = time.monotonic()
    thread = threading.Thread(target=check, name="mkm-vent-check", daemon=True)
    thread.start()
    while thread.is_alive():
        thread.join(WATCH_EVERY_S)
        calling = timed.calling
        if thread.is_alive() and calling is not None:
            hung_s = time.monotonic() - calling[0]
            if hung_s > calling[1]:
                return VentCheck(
                    False, math.nan, config.safety.vent_below_bar, time.monotonic() - begun,
                    "monitor", f"{calling[2].format(hung_s)} during the vent check: the driver "
                    "hangs; the vent was commanded, its check cannot read the monitor")
    if isinstance(out[0], BaseException):
        raise out[0]
    return out[0]


def _mend_dead_runs(device: Backend, owner: BenchOwner, notify
                    ) -> tuple[list[str], list]:
    """After the vent: name the runs that died without venting on this bench and mend their
    folders; the problems met (a state folder that cannot be read or written, or hangs; the
    vent written again for them, bounded by :class:`mkm.bench.run.BoundedWrite`, that hangs)
    and the dead runs' markers."""
    try:
        markers = vent_unvented(BoundedWrite(device),
                                owner.dead_runs("the bench was vented, the runs that died on "
                                                "it were not named"),
                                owner.on_state_folder)
    except WriteHung as exc:  # their markers stay: the next command vents first, names them
        return [f"the vent written again for the runs that died on this bench {exc}; they were "
                "not named, their folders not mended, and the next command on this bench "
                "vents first and names them"], []
    except StateFolderBroken as exc:
        return [str(exc)], []
    except OSError as exc:
        return [f"the markers of dead runs in the bench state folder could not be handled "
                f"({exc.strerror or exc})"], []
    for marker in markers:
        notify(marker.vented_now())
    return [], markers


def loadcell_table(fit: dict, config: BenchConfig | None = None,
                   record: dict | None = None) -> str:
    """The ``[loadcell]`` table to paste into a bench configuration, from a fit
    (:func:`fit_loadcell`): the configured channel and capacity, the fitted sensitivity and
    offset (6 significant digits), as TOML. With ``record`` (:func:`mkm.core.records.provenance`)
    its first lines are comments saying how it was fitted: the command, date, code, the masses
    and volts and the fit's quality. Pasted into the configuration, they go with it into every
    run folder's config.toml, where run.json holds the numbers alone."""
    import tomlkit

    table = tomlkit.table()
    if record is not None:
        where = (f" from volts measured on the {fit['measured_on']}" if "measured_on" in fit
                 else " from volts measured elsewhere")
        code = ", ".join(f"{k} {v}" for k, v in (("mkm-bench",
                                                   record["versions"].get("mkm-bench")),
                                                  ("git", record.get("git"))) if v)
        for line in (f"fitted {record['date_utc']}{where} by: {record['command']} ({code})",
                     f"masses [kg] {', '.join(f'{m:g}' for m in fit['mass_kg'])}; volts [V] "
                     f"{', '.join(f'{v:.6g}' for v in fit['volts'])}",
                     f"R^2 {fit['r_squared']:.6f}, largest residual "
                     f"{fit['max_abs_residual_N']:.3f} N"):
            table.add(tomlkit.comment(line))
    if config is not None:
        table["channel"] = config.loadcell.channel
        table["capacity_N"] = config.loadcell.capacity_N
    table["sensitivity_N_per_V"] = float(f"{fit['sensitivity_N_per_V']:.6g}")
    table["offset_V"] = float(f"{fit['offset_V']:.6g}")
    document = tomlkit.document()
    document["loadcell"] = table
    return tomlkit.dumps(document).rstrip("\n")


def refused_fit(fit: dict, config: BenchConfig) -> str | None:
    """Why ``config`` with the fitted sensitivity and offset (:func:`loadcell_table`'s block
    pasted in) is refused, or None if it is taken: a cell whose ``+-10 V`` rail the fitted
    sensitivity puts below its capacity clips before it."""
    from dataclasses import replace

    cell = replace(config.loadcell, sensitivity_N_per_V=float(f"{fit['sensitivity_N_per_V']:.6g}"),
                   offset_V=float(f"{fit['offset_V']:.6g}"))
    try:
        replace(config, loadcell=cell).check()
    except ValueError as exc:
        return str(exc)
    return None


def fit_loadcell(mass_kg, volts) -> dict:
    """Least-squares load-cell calibration from known masses and the mean volts under each.

    The cell is linear: ``volts = force_N / sensitivity_N_per_V + offset_V`` with
    ``force_N = mass_kg * g`` (standard gravity). Returns the sensitivity [N/V], the offset [V],
    the masses and volts fitted, R^2, the standard error of the sensitivity, its 95 % interval's
    half-width as a fraction of it (Student's t on n - 2 degrees of freedom; NaN with two
    masses, which leave no residual to judge it by) and the largest residual in newtons.
    """
    m = np.asarray(mass_kg, dtype=float)
    v = np.asarray(volts, dtype=float)
    if m.shape != v.shape or m.ndim != 1:
        raise ValueError(f"got {m.size} masses and {v.size} voltages: expected one voltage "
                         "per mass")
    if np.unique(m).size < 2:
        raise ValueError("need at least two different masses to fit a sensitivity")
    force = m * STANDARD_GRAVITY
    fit = stats.linregress(force, v)
    if fit.slope <= 0:
        raise ValueError(f"volts fall as the mass grows (slope {fit.slope:.3g} V/N): "
                         "expected a tension load cell wired with the positive sign")
    sensitivity = 1.0 / fit.slope
    residual_N = (v - (fit.intercept + fit.slope * force)) * sensitivity
    stderr = float(fit.stderr / fit.slope**2) if m.size > 2 else float("nan")
    return {"sensitivity_N_per_V": float(sensitivity), "offset_V": float(fit.intercept),
            "mass_kg": m.tolist(), "volts": v.tolist(), "r_squared": float(fit.rvalue**2),
            "sensitivity_stderr_N_per_V": stderr,
            "sensitivity_U95_fraction": float(stats.t.ppf(0.975, m.size - 2) * stderr
                                              / sensitivity) if m.size > 2 else float("nan"),
            "max_abs_residual_N": float(np.abs(residual_N).max()), "n_points": int(m.size)}


def check_masses(config: BenchConfig, mass_kg) -> None:
    """``ValueError`` for a mass heavier than the load cell's capacity: it overloads the cell,
    and its reading clipped at the rail would bend the fitted sensitivity without a word."""
    heaviest, capacity_N = max(mass_kg), config.loadcell.capacity_N
    if heaviest * STANDARD_GRAVITY > capacity_N:
        raise ValueError(f"--masses: {heaviest:g} kg weighs {heaviest * STANDARD_GRAVITY:.0f} N, "
                         f"beyond the load cell's loadcell.capacity_N={capacity_N:g}: expected "
                         f"masses up to {capacity_N / STANDARD_GRAVITY:.4g} kg")


def calibrate_loadcell(config: BenchConfig, mass_kg, backend: str | None = None,
                       clock: str = "virtual", seconds: float = 3.0) -> dict:
    """Hang each mass in turn (the operator does), average the volts, fit the calibration."""
    seconds = _seconds(seconds)
    check_masses(config, mass_kg)
    config = with_backend(config, backend)
    device = make_backend(config, clock)
    operator = make_operator(config, device)
    volts, codes = [], set()
    with session(device, "calibrate-loadcell"):
        bounded = _Bounded(device, config.daq.sample_rate_hz)
        bounded.start()
        for mass in mass_kg:
            operator.hang_mass(float(mass))
            while bounded.available() > 0:  # discard what came while the mass was being hung
                bounded.read(bounded.available(), config.daq.read_timeout_s)
            cell_V = mean_volts(bounded, config, seconds)[:, 0]
            codes.update(cell_V.tolist())
            volts.append(float(cell_V.mean()))
        operator.hang_mass(0.0)
    if len(codes) == 1:  # no slope to fit: not a cell wired the wrong way round
        cell, masses = config.loadcell, ", ".join(f"{m:g}" for m in mass_kg)
        raise BenchError(f"the load cell read one ADC code, {volts[0]:.4f} V "
                         f"({float(cell.force_N(volts[0])):+.1f} N at loadcell.offset_V="
                         f"{cell.offset_V:g} V), under every mass ({masses} kg): a stuck, "
                         "disconnected or railed cell reads so; check its cable, amplifier and "
                         "supply; nothing was fitted")
    bench = f"{config.daq.backend} bench" + (f" (SIMULATED, seed {config.sim.seed})"
                                               if config.simulated else "")
    return {**fit_loadcell(mass_kg, volts), "measured_on": bench}


def check(config: BenchConfig, backend: str | None = None, clock: str = "virtual",
          ceiling: ForceCeiling | None = None) -> tuple[str, list[str], str]:
    """Dry run: device information, limits, the bench read at rest, vented, as a run's tare
    reads it (``sequence.tare_s``: :func:`at_rest`), the planned steps, the estimated duration
    and the expected uncertainty budget (:func:`expected_budget_lines`); with the identified
    muscle's ``ceiling``, the force each step is held to
    (:func:`mkm.bench.preflight.ceiling_lines`); the warnings of
    :func:`mkm.bench.preflight.warnings` (braid lock, load cell) and of the reading at rest; and
    why a run's tare would refuse the bench as it is, or its plan must trip ("" when
    neither)."""
    config = with_backend(config, backend)
    device = make_backend(config, clock)
    with session(device, "check") as info:
        volts = _read_vented(device, config, config.sequence.tare_s)
    try:
        rest, refusal = at_rest(volts, config), ""
    except TareInvalid as exc:
        rest, refusal = {}, f"{exc}; `mkm acquire` would stop at its tare"
    shortest, longest = estimate_duration_s(config)
    m, cell, reg = config.muscle, config.loadcell, config.regulator
    lines = [
        f"config: {config.source}",
        f"backend: {config.daq.backend}"
        f"{' (SIMULATED: no hardware is driven)' if config.simulated else ''}",
        f"device: {info.product_type}, serial {info.serial_number}, "
        f"{info.sample_rate_hz:g} Hz, AI {', '.join(info.channels['ai'])} "
        f"({info.channels['terminal_config']}, +-10 V), AO {info.channels['ao'] or 'none'}",
        f"muscle: {m.id}, D0 {m.D0_mm:g} mm, t0 {m.t0_mm:g} mm, L0 {m.L0_mm:g} mm, "
        f"eps {m.eps:g}",
        f"regulator: {reg.kind}, commands clamped to {reg.max_pressure_bar:g} bar",
        f"load cell: capacity {cell.capacity_N:g} N, {cell.sensitivity_N_per_V:g} N/V, "
        f"interlock at {config.force_limit_N:g} N",
        *_rest_lines(rest, config),
        f"sequence: tare {config.sequence.tare_s:g} s, "
        f"{config.sequence.preconditioning_cycles} pre-conditioning cycle(s), "
        f"{config.sequence.repeats} repeat(s)",
        *_plan_lines(plan_steps(config)),
        f"estimated duration: {shortest / 60:.1f} to {longest / 60:.1f} min (at most "
        f"sequence.max_duration_h = {config.sequence.max_duration_h:g} h)",
        *expected_budget_lines(config),
    ]
    if ceiling is not None:
        held, must_trip = ceiling_lines(config, ceiling)
        lines += held
        refusal = refusal or (must_trip and f"{must_trip}; `mkm acquire` refuses this plan")
    found = [rest[key] for key in AT_REST_WARNINGS if rest.get(key)]
    return "\n".join(lines), [*warnings(config, rest.get("std_N"), ceiling), *found], refusal


def _rest_lines(rest: dict, config: BenchConfig) -> list[str]:
    """The reading at rest (:func:`at_rest`) in words, or none when the tare refused it."""
    if not rest:
        return []
    monitor = (f", the pressure monitor {rest['monitor_vented_bar']:+.4f} bar"
               if "monitor_vented_bar" in rest else "")
    return [f"at rest, vented ({config.sequence.tare_s:g} s, as a run's tare): the load cell "
            f"{rest['shift_N']:+.2f} N from loadcell.offset_V, spread {rest['std_N']:.2f} N "
            f"rms{monitor}"]


def _plan_lines(steps) -> list[str]:
    """The planned staircase in words: each sweep's pressures in order, per repeat."""
    sweeps: dict[tuple[int, str], list[str]] = {}
    for s in steps:
        sweeps.setdefault((s.repeat, s.direction), []).append(f"{s.set_pressure_bar:g}")
    lines = [f"planned steps: {sum(len(v) for v in sweeps.values())}"]
    for (repeat, direction), pressures in sweeps.items():
        lines.append(f"  repeat {repeat + 1}, {direction}: {', '.join(pressures)} bar")
    return lines


def expected_budget_lines(config: BenchConfig) -> list[str]:
    """The uncertainty budget a run of ``config`` can have at each planned pressure (forces
    from Equation 2 on the braid's diameter, :func:`mkm.bench.preflight.expected_force_N`; data
    terms at the settle and tare limits), and its terms at the top."""
    pressures = sorted(set(config.sequence.pressures_bar))
    budgets = [(p, force, expected_budget(config, force, p))
               for p, force in ((p, expected_force_N(config, p)) for p in pressures)]
    lines = ["expected uncertainty (U at 95.45 %; forces by Equation 2 on the braid's diameter, "
             "the FE model's at eps 0; hold scatter, drift and tare at their settle and safety "
             "limits, so at most this):",
             f"{'P [bar]':>8} {'F [N]':>8} {'U(F) [N]':>9} {'U(F) [%]':>9} {'U(P) [bar]':>10}"
             "  largest term"]
    for p, force, b in budgets:
        top = b.ranked("force")[0][0].name
        share = 100 * b.force_U_N / force if force > 0 else float("nan")
        lines.append(f"{p:>8g} {force:>8.1f} {b.force_U_N:>9.2f} {share:>9.2f} "
                     f"{b.pressure_U_bar:>10.3f}  {top}")
    p, _, top = budgets[-1]
    lines.append(f"force budget at {p:g} bar, terms ranked by their share of the variance:")
    lines.extend(budget_table(top, "force"))
    lines.append(f"pressure budget at {p:g} bar:")
    lines.extend(budget_table(top, "pressure"))
    return lines
