"""Short bench procedures besides a run: tare, load-cell calibration, dry-run check.

Each opens the device in :func:`session`, which vents and closes it whatever happens.
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager

import numpy as np
from scipy import stats

from bench.backend import Backend, DeviceInfo
from bench.config import BenchConfig
from bench.run import estimate_duration_s, make_backend, make_operator, plan_steps
from bench.sim import STANDARD_GRAVITY


@contextmanager
def session(backend: Backend) -> Iterator[DeviceInfo]:
    """Open ``backend`` (which writes the vent command) and close it (vent again) on exit."""
    info = backend.open()
    try:
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
    """Load-cell offset at 0 bar: mean and spread of ``seconds`` of volts, vented."""
    device = make_backend(config, backend, clock)
    with session(device) as info:
        device.start()
        cell_V = mean_volts(device, config, seconds)[:, 0]
    offset = float(cell_V.mean())
    return {"offset_V": offset, "std_V": float(cell_V.std(ddof=1)), "n": int(cell_V.size),
            "std_N": float(cell_V.std(ddof=1) * config.loadcell.sensitivity_N_per_V),
            "shift_from_config_N": (offset - config.loadcell.offset_V)
            * config.loadcell.sensitivity_N_per_V, "device": info.as_dict()}


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
    ]
    return "\n".join(lines)
