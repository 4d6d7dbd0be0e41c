"""Short bench procedures besides a run: tare, load-cell calibration, dry-run check, vent.

Each opens the device in :func:`session`, which vents and closes it whatever happens, and first
vents a bench left pressurised by a run that died without venting (:mod:`mkm.bench.unvented`),
saying which run it was.
"""

from __future__ import annotations

import time
from collections.abc import Iterator
from contextlib import contextmanager

import numpy as np
from scipy import stats

from mkm.bench.backend import Backend, BenchError, DeviceInfo
from mkm.bench.config import BenchConfig
from mkm.bench.run import make_backend, make_operator, notify_stderr
from mkm.bench.sequence import estimate_duration_s, plan_steps, validate_tare
from mkm.bench.sim import STANDARD_GRAVITY
from mkm.bench.unvented import vent_unvented

VENTED_BELOW_BAR = 0.05  # `mkm vent` waits for the monitor to read below this
VENT_WAIT_S = 10.0


@contextmanager
def session(backend: Backend, notify=notify_stderr) -> Iterator[DeviceInfo]:
    """Open ``backend`` (which writes the vent command), vent and report a bench a dead run left
    pressurised, and close (vent again) on exit."""
    info = backend.open()
    try:
        for marker in vent_unvented(backend):
            notify(f"{marker.describe()}: vented now")
        yield info
    finally:
        backend.close()


def mean_volts(backend: Backend, config: BenchConfig, seconds: float) -> np.ndarray:
    """Read ``seconds`` of samples; return them (samples x inputs) in volts."""
    n = max(2, int(round(seconds * config.daq.sample_rate_hz)))
    block = backend.read(n, timeout_s=seconds + config.daq.read_timeout_s)
    return block.volts


def tare(config: BenchConfig, backend: str = "sim", clock: str = "virtual",
         seconds: float = 5.0) -> dict:
    """Load-cell offset at 0 bar: mean and spread of ``seconds`` of volts, vented; checked by
    :func:`mkm.bench.sequence.validate_tare` (``TareInvalid`` when it would stop a run)."""
    device = make_backend(config, backend, clock)
    with session(device) as info:
        device.start()
        cell_V = mean_volts(device, config, seconds)[:, 0]
    out = validate_tare(cell_V, config)
    return {**out, "shift_from_config_N": out["shift_N"], "device": info.as_dict()}


def vent(config: BenchConfig, backend: str = "sim", clock: str = "virtual",
         below_bar: float = VENTED_BELOW_BAR, wait_s: float = VENT_WAIT_S) -> dict:
    """Command 0 bar and wait until the regulator's monitor reads below ``below_bar``.

    Returns ``pressure_bar`` (the last reading; NaN without a monitor: a manual regulator, to
    be vented by hand), ``vented`` and ``waited_s``. Raises :class:`BenchError` when the device
    cannot be opened or the pressure stays above ``below_bar`` for ``wait_s``.
    """
    device = make_backend(config, backend, clock)
    with session(device):
        device.write_command(0.0)
        if not config.regulator.electronic:
            return {"pressure_bar": float("nan"), "vented": False, "waited_s": 0.0,
                    "manual": True}
        device.start()
        start = time.monotonic()
        rate = config.daq.sample_rate_hz
        block = max(1, int(round(0.2 * rate)))
        sample_time_s, pressure = 0.0, float("nan")
        while True:
            volts = device.read(block, config.daq.read_timeout_s).volts
            pressure = float(config.regulator.monitor_bar(volts[-1, 1]))
            sample_time_s += block / rate
            waited = max(time.monotonic() - start, sample_time_s)
            if pressure < below_bar:
                return {"pressure_bar": pressure, "vented": True, "waited_s": waited,
                        "manual": False}
            if waited > wait_s:
                raise BenchError(f"the regulator still reads {pressure:.3f} bar {wait_s:g} s "
                                 "after the vent command: VENT BY HAND and check the regulator")


def fit_loadcell(mass_kg, volts) -> dict:
    """Least-squares load-cell calibration from known masses and the mean volts under each.

    The cell is linear: ``volts = force_N / sensitivity_N_per_V + offset_V`` with
    ``force_N = mass_kg * g`` (standard gravity). Returns the sensitivity [N/V], the offset [V],
    R^2, the standard error of the sensitivity and the largest residual in newtons.
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
    return {"sensitivity_N_per_V": float(sensitivity), "offset_V": float(fit.intercept),
            "r_squared": float(fit.rvalue**2),
            "sensitivity_stderr_N_per_V": float(fit.stderr / fit.slope**2)
            if m.size > 2 else float("nan"),
            "max_abs_residual_N": float(np.abs(residual_N).max()), "n_points": int(m.size)}


def calibrate_loadcell(config: BenchConfig, mass_kg, backend: str = "sim",
                       clock: str = "virtual", seconds: float = 3.0) -> dict:
    """Hang each mass in turn (the operator does), average the volts, fit the calibration."""
    device = make_backend(config, backend, clock)
    operator = make_operator(device)
    volts = []
    with session(device):
        device.start()
        for mass in mass_kg:
            operator.hang_mass(float(mass))
            while device.available() > 0:  # discard what came while the mass was being hung
                device.read(device.available(), config.daq.read_timeout_s)
            volts.append(float(mean_volts(device, config, seconds)[:, 0].mean()))
        operator.hang_mass(0.0)
    return {**fit_loadcell(mass_kg, volts), "mass_kg": list(map(float, mass_kg)),
            "volts": volts}


def check(config: BenchConfig, backend: str = "sim", clock: str = "virtual") -> str:
    """Dry run: device information, limits, the planned steps and the estimated duration."""
    device = make_backend(config, backend, clock)
    with session(device) as info:
        pass
    shortest, longest = estimate_duration_s(config)
    warnings = braid_lock_warnings(config)
    m, cell, reg = config.muscle, config.loadcell, config.regulator
    lines = [
        f"config: {config.source}",
        f"device: {info.product_type}, serial {info.serial_number}, "
        f"{info.sample_rate_hz:g} Hz, AI {', '.join(info.channels['ai'])} "
        f"({info.channels['terminal_config']}, +-10 V), AO {info.channels['ao'] or 'none'}",
        f"muscle: {m.id}, D0 {m.D0_mm:g} mm, t0 {m.t0_mm:g} mm, L0 {m.L0_mm:g} mm, "
        f"eps {m.eps:g}",
        f"regulator: {reg.kind}, commands clamped to {reg.max_pressure_bar:g} bar",
        f"load cell: capacity {cell.capacity_N:g} N, {cell.sensitivity_N_per_V:g} N/V, "
        f"interlock at {config.force_limit_N:g} N",
        f"sequence: tare {config.sequence.tare_s:g} s, "
        f"{config.sequence.preconditioning_cycles} pre-conditioning cycle(s), "
        f"{config.sequence.repeats} repeat(s)",
        "step,direction,repeat,set_pressure_bar",
        *(f"{s.step},{s.direction},{s.repeat},{s.set_pressure_bar:g}" for s in plan_steps(config)),
        f"estimated duration: {shortest / 60:.1f} to {longest / 60:.1f} min",
        *warnings,
    ]
    return "\n".join(lines)


def braid_lock_warnings(config: BenchConfig) -> list[str]:
    """A warning when ``muscle.eps`` shortens the braid past its locking angle (54.7 deg), where
    Equation 2 leaves its range and the muscle pulls little or nothing."""
    from mkm.fem.calibration import calibrated
    from mkm.fem.eq2 import LOCKING_ANGLE_DEG, Eq2, chou_hannaford_eps_max

    theta0 = float(calibrated(Eq2().calibration_key)["theta0_deg"])
    eps_max = float(chou_hannaford_eps_max(theta0))
    if config.muscle.eps < eps_max:
        return []
    return [f"warning: eps {config.muscle.eps:g} is past the braid lock: at theta0 "
            f"{theta0:.1f} deg the braid reaches its locking angle {LOCKING_ANGLE_DEG:.1f} deg at "
            f"eps {eps_max:.3f}; the muscle pulls little or nothing there"]
