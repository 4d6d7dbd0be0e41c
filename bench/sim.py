"""The simulated bench: the :class:`mkm.bench.backend.Backend` protocol over a physical model.

Like ``ophyd.sim``, the simulated device has the real one's signature plus a seed and a clock, so
the whole acquisition code runs unchanged on it. Every sample ``k`` (at ``k / rate`` s) advances

- the regulator: a first-order lag (time constant ``regulator_tau_s``) towards the commanded
  pressure, rate-limited to ``regulator_slew_bar_per_s``, with a 1-5 V monitor output;
- the muscle: the static force of a physics model (``sim.model``, a ``mkm.fem.ladder`` rung; by
  default the axisymmetric FE model ``axisym``, at the braid angle and rubber of ``[sim.truth]``
  where set, else the nominal ones, which is none of the closed forms a report
  compares, tabulated over pressure once per muscle, so a sample costs an interpolation) put
  through two effects no static model of the ladder has, defined once in
  :mod:`mkm.fem.friction` (the ``friction`` rung predicts them):

  * hysteresis, a play operator of half-width ``hysteresis_fraction`` times the force: rising
    pressure reads low, falling high, as Coulomb friction between braid threads does
    (Davis & Caldwell 2006 report loops of several % of the force; 3 % is the default);
  * creep, stress relaxation of the silicone at fixed length: ``creep_fraction`` of the force
    lost with time constant ``creep_tau_s`` (2 % over 30 s by default, the order of
    silicone-rubber relaxation over a minute); it makes settle detection meaningful;

- the load cell: force over sensitivity plus offset and Gaussian noise, clipped at the +-10 V rails
  and quantised to the USB-6001's 14 bits over +-10 V (1 LSB = 1.22 mV).

``[sim.truth]`` (:class:`mkm.bench.sim_settings.Truth`) makes the bench wrong the way real ones
are, unknown to the configuration: the muscle's true geometry, braid and rubber, a load cell whose
output per newton is ``loadcell_gain`` times the configured one and whose zero drifts by
``loadcell_drift_N_per_min`` from the start of acquisition, a regulator sensor reading
``monitor_gain * P + monitor_offset_bar`` plus a bow ``monitor_bow_bar * 4 x (1 - x)`` (``x`` the
pressure over the sensor's full scale) and a hysteresis ``monitor_hysteresis_bar`` between its
rising and falling readings (the regulator holds that reading at the command, so the monitor
reads the command while the true pressure is off by the sensor's error), or a monitor output
frozen at ``monitor_stuck_bar`` whatever the pressure (the regulator still regulating on its own
sensor). A frame of stiffness ``frame_stiffness_N_per_mm`` lets the muscle shorten by ``F / k``
under its own pull: the static force is the model's at the length that pull leaves it. Tubing
between the regulator's outlet (where its sensor and the monitor read) and the muscle lags the
muscle's pressure behind the outlet's by a first-order lag of ``line_tau_s``: on a ramp the force
trails the monitored pressure, a loop between the branches that is not friction. A rubber that
softens on its first loading (``mullins_fraction``, the Mullins effect) pulls the force of a
stiffer rubber while its pressure rises above every pressure it has fallen from in the run
(taking it over within :data:`MULLINS_BAND` of that pressure above it), and the truth's at and
below them: a staircase's first rise pulls less than its repeats at the same pressure, and from
its top on the muscle is the preconditioned one. A braid whose fibres stretch (``braid_EA_N``,
their tensile stiffness summed over the strands) is, at each pressure, the braid of fibres
longer by their tension over it: at the held length its angle is smaller and its diameter
larger, the force of a muscle further contracted.

A force model that leaves its validity range (Equation 2 beyond eps_max) or predicts a negative
force gives zero, and so does creep recovery after a pressure drop: the braid goes slack and a
muscle cannot push. The clock is ``virtual`` (reads
return at once, a one-hour run takes seconds) or ``real`` (reads wait for the sample times).
Faults from ``[sim.faults]`` fire at sample time: disconnect, read timeouts, a reader stall (the
clock runs on and samples pile up in the buffer: a stall shorter than the buffer delays the
reading and every later command, a longer one overflows it and loses the samples), an AO write
failure, a load-cell input reading NaN or holding one value (``loadcell_stuck_at_s``: its cable
or amplifier failed), a regulator that stops following, an overshoot, a monitor input that reads
0 V (``monitor_lost_at_s``: regulator unpowered, wire off).
:func:`describe_physics` says what the simulated muscle is (recorded in run.json);
:func:`logged_ramp` is a lab's logger record of a continuous ramp on it (for ``mkm import``).
"""

from __future__ import annotations

import functools
import math
import time
from collections import deque

import numpy as np

from mkm.bench.backend import (
    CLOCKS,
    AOWriteFailed,
    Block,
    BufferOverflow,
    DaqDisconnected,
    DeviceInfo,
    ReadTimeout,
)
from mkm.bench.devices import USB6001
from mkm.bench.sim_settings import INSTRUMENT_BOUNDS, MODEL_FIELDS
from mkm.fem.friction import advance

USB6001_RANGE_V = USB6001.ai_range_V

LSB_V = USB6001.ai_lsb_V  # USB-6001: 14 bits over +-10 V = 1.22 mV
STANDARD_GRAVITY = 9.80665  # m/s^2, for masses hung on the load cell
#: a rubber softened up to a pressure takes its first loading's stiffness back over this
#: share of that pressure above it (the fresh and softened curves meet, as in Ogden and
#: Roxburgh's model): a staircase a few mbar above its preconditioning pulls as preconditioned
MULLINS_BAND = 0.1
MANOMETER_RESOLUTION_BAR = 0.05  # smallest division of a 2.5 bar class-1 dial (paper's NUOVA FIMA)


def quantize_volts(volts: float) -> float:
    """Clip to the +-10 V rails and round to the ADC's 14-bit step (NaN stays NaN)."""
    if math.isnan(volts):
        return volts
    clipped = min(max(volts, -USB6001_RANGE_V), USB6001_RANGE_V - LSB_V)
    return round(clipped / LSB_V) * LSB_V


def static_force_table(config, n: int = 81, first_loading: bool = False,
                       ) -> tuple[np.ndarray, np.ndarray]:
    """Pressures [bar] over the regulator's range and the model's static force [N] at them
    (``first_loading``: the rubber's before it softened, :func:`first_loading_params`).

    Computed once per muscle and model in a process (an FE sweep takes about a second); a
    sample then costs one linear interpolation (``n`` points over full scale, 0.05 bar on a
    4 bar regulator: the FE force is smooth above its threshold, which is a knot of its own).
    The table reaches the highest pressure the
    regulator can deliver: a sensor reading low (offset, gain, bow, hysteresis) or an overshoot
    puts the muscle above full scale, and an interpolation clamped at full scale would hold its
    force there.
    """
    m, s, fs = config.muscle, config.sim, config.regulator.full_scale_bar
    mesh = s.fe_mesh if s.model == "axisym" else None
    top = max(fs, highest_pressure_bar(config))
    params = first_loading_params(config) if first_loading else muscle_params(config)
    return _table(s.model, mesh, m.L0_mm, tuple(sorted(params.items())),
                  *s.truth.geometry(m), m.eps, top, math.ceil((n - 1) * top / fs) + 1,
                  s.truth.frame_stiffness_N_per_mm, s.truth.braid_EA_N)


def muscle_params(config) -> dict[str, float | str]:
    """What the simulated muscle's force model is built with besides its length: the braid
    angle, rubber and gap ``[muscle]`` declares, those the model takes, with ``[sim.truth]``'s
    where set (the muscle as it is, departing from its declaration); the model's calibrated
    ones where neither says."""
    from mkm.fem.ladder import entry

    taken = entry(config.sim.model).parameters
    declared = {k: v for k, v in config.muscle.model_parameters().items()
                if k in MODEL_FIELDS and k in taken}
    return {**declared, **config.sim.truth.model_params()}


def first_loading_params(config) -> dict[str, float | str]:
    """:func:`muscle_params` with the rubber of the muscle before its first loading softened
    it: ``1 / (1 - mullins_fraction)`` times the truth's C10 and C01 (the model's own where
    nothing sets them)."""
    s, m = config.sim, config.muscle
    params = muscle_params(config)
    mesh = s.fe_mesh if s.model == "axisym" else None
    rubber = _model(s.model, mesh, m.L0_mm, params).params()
    stiffer = 1.0 / (1.0 - s.truth.mullins_fraction)
    return {**params, **{k: stiffer * float(rubber[k]) for k in ("C10_MPa", "C01_MPa")}}


def highest_pressure_bar(config) -> float:
    """The true pressure [bar] at the regulator's full-scale command on a rising branch: what
    its sensor reads as full scale, plus the overshoot fault."""
    t, fs = config.sim.truth, config.regulator.full_scale_bar
    return (sensor_inverse_bar(t, fs, fs + t.instrument("monitor_hysteresis_bar") / 2)
            + config.sim.faults.overshoot_bar)


def sensor_inverse_bar(truth, full_scale_bar: float, reading_bar: float) -> float:
    """The pressure [bar] that the regulator's sensor (``truth``'s gain, offset and bow, without
    its hysteresis) reads as ``reading_bar``: the root of the quadratic ``(g + b) P - b P^2 / FS
    = reading - offset`` (``b = 4 bow / FS``) next to the linear sensor's, in the form that
    stays exact as the bow goes to zero."""
    gain = truth.instrument("monitor_gain")
    b = 4.0 * truth.instrument("monitor_bow_bar") / full_scale_bar
    c = reading_bar - truth.instrument("monitor_offset_bar")
    if b == 0:
        return c / gain
    slope = gain + b
    return 2.0 * c / (slope + math.sqrt(max(slope**2 - 4.0 * b * c / full_scale_bar, 0.0)))


@functools.lru_cache(maxsize=32)
def _table(model_name, mesh, L0_mm, truth, D0_mm, t0_mm, eps, top_bar, n, stiffness_N_per_mm,
           braid_EA_N=None):
    model = _model(model_name, mesh, L0_mm, dict(truth))
    pressure_bar = np.linspace(0.0, top_bar, n)
    prediction = model.predict(pressure_bar, D0_mm, t0_mm, eps)

    def force_at(held_eps, rigid_N=None):
        """The static force [N] at each pressure with the muscle held at ``held_eps``."""
        if rigid_N is None:
            p = model.predict(pressure_bar, D0_mm, t0_mm, held_eps)
            rigid_N = np.where(p.valid, p.force_N, 0.0)
        if braid_EA_N is None:
            return rigid_N
        return _fibres_stretched(model, pressure_bar, D0_mm, t0_mm, held_eps, braid_EA_N,
                                 rigid_N)

    force = force_at(eps, np.where(prediction.valid, prediction.force_N, 0.0))
    if stiffness_N_per_mm is not None:
        force = _on_frame(force_at, eps, L0_mm, stiffness_N_per_mm, force)
    # the force starts at the threshold with a kink: a knot there, or a hold just above it
    # would read a force interpolated across the kink
    threshold = np.asarray(prediction.extras.get("threshold_pressure_bar", np.nan), dtype=float)
    threshold = threshold[np.isfinite(threshold)]
    if threshold.size and 0.0 < threshold[0] < top_bar and threshold[0] not in pressure_bar:
        at = np.searchsorted(pressure_bar, threshold[0])
        pressure_bar = np.insert(pressure_bar, at, threshold[0])
        force = np.insert(force, at, 0.0)
    pressure_bar.flags.writeable = False
    force = np.maximum(force, 0.0)
    force.flags.writeable = False
    return pressure_bar, force


def _on_frame(force_at, eps, L0_mm, stiffness_N_per_mm, held_N, lengths: int = 6):
    """The static force [N] of a muscle held by a frame of ``stiffness_N_per_mm``: its length
    shortens by ``F / k``, so the force at each pressure solves ``F = F_static(P, eps + F /
    (k L0))``. ``held_N`` is the force at ``eps`` (a rigid frame's); ``force_at(eps)`` gives
    it at ``lengths - 1`` more eps up to where that force would put it, interpolated linearly
    in eps between them. The static force falls with eps, so the root is unique in
    ``[0, held_N]``: found by bisection. At the threshold there is no pull and no shortening:
    the threshold stays the rigid frame's."""
    per_N = 1.0 / (stiffness_N_per_mm * L0_mm)  # eps per newton
    grid = np.linspace(eps, eps + float(np.max(held_N)) * per_N, lengths)
    forces = [held_N] + [force_at(e) for e in grid[1:]]
    table = np.maximum(np.array(forces), 0.0)  # (eps, pressure)
    low, high = np.zeros_like(held_N), np.asarray(held_N, dtype=float).copy()
    columns = np.arange(held_N.size)
    for _ in range(60):  # the bracket halves each time: to 1e-18 of the largest force
        middle = 0.5 * (low + high)
        at = np.clip((eps + middle * per_N - grid[0]) / (grid[1] - grid[0]), 0.0,
                     lengths - 1.0) if grid[-1] > grid[0] else np.zeros_like(middle)
        static = _between(table, at, columns)
        pulls_more = static > middle
        low, high = np.where(pulls_more, middle, low), np.where(pulls_more, high, middle)
    return 0.5 * (low + high)


def _between(table, at, columns):
    """``table``'s rows (one per grid point) interpolated linearly at the fractional row
    ``at`` of each column."""
    k = np.minimum(at.astype(int), table.shape[0] - 2)
    return table[k, columns] + (at - k) * (table[k + 1, columns] - table[k, columns])


def _fibres_stretched(model, pressure_bar, D0_mm, t0_mm, eps, braid_EA_N, rigid_N,
                      strains: int = 6, iterations: int = 100):
    """The static force [N] of a muscle held at ``eps`` whose braid's fibres stretch by their
    total tension over ``braid_EA_N`` (``rigid_N``: the force of inextensible ones).

    The model is evaluated as the braid of longer fibres
    (:func:`mkm.fem.thickwall.stretched_braid`) and the fibres' tension is the pull and the
    pressure's end load along them (:func:`mkm.fem.thickwall.fibre_tension_N`). The strain
    solves ``e = T(e) / EA`` at each pressure: the model at ``strains`` strains up to twice the
    inextensible fibres' ``T(0) / EA``, interpolated between them, iterated from ``T(0) / EA``.
    The fibres' tension grows with their length about as ``1 + e``, so the iteration contracts
    by about ``e`` a step; where it does not settle within the strains tabulated, no braid holds
    the pull and a ValueError says so."""
    from scipy.interpolate import CubicSpline

    from mkm.fem.thickwall import fibre_tension_N, stretched_braid

    theta0_deg = float(model.params()["theta0_deg"])

    def strain_of(strain, force_N):
        return fibre_tension_N(force_N, pressure_bar, D0_mm, t0_mm, eps, theta0_deg,
                               strain) / braid_EA_N

    strain = strain_of(0.0, rigid_N)
    grid = np.linspace(0.0, 2.0 * float(np.max(strain)), strains)
    if grid[-1] == 0:  # no tension anywhere
        return rigid_N
    table = [rigid_N]
    for e in grid[1:]:
        D0_at_mm, eps_at = stretched_braid(D0_mm, t0_mm, eps, e)
        p = model.predict(pressure_bar, D0_at_mm, t0_mm, eps_at)
        table.append(np.where(p.valid, p.force_N, 0.0))
    # the wall's share bends with the strain, most near rest: a cubic spline through the
    # strains, where straight lines between them are off by most of a percent of the force
    between = CubicSpline(grid, np.array(table), axis=0)
    columns = np.arange(strain.size)
    for _ in range(iterations):
        force = between(strain)[columns, columns]
        settled = strain_of(strain, force)
        step, strain = np.max(np.abs(settled - strain)), settled
        if np.max(strain) > grid[-1] or step <= 1e-12 + 1e-9 * np.max(strain):
            break
    if np.max(strain) > grid[-1] or step > 1e-12 + 1e-9 * np.max(strain):
        worst = int(np.argmax(strain))
        raise ValueError(
            f"sim.truth.braid_EA_N={braid_EA_N:g} N: the braid's fibres do not settle under the "
            f"muscle's pull (strained past {min(strain[worst], grid[-1]):.3g} at "
            f"{pressure_bar[worst]:.3g} bar, eps {eps:.3g}): expected fibres stiff enough to "
            "hold it")
    return between(strain)[columns, columns]


def _model(model_name, mesh, L0_mm, truth):
    """The static model of the simulated muscle: the rung at the ``[sim.truth]`` values."""
    from mkm.fem.ladder import make_model

    return make_model(model_name, L0_mm=L0_mm, **({"mesh": mesh} if mesh else {}), **truth)


def describe_physics(config) -> dict:
    """What the simulated muscle is, for run.json and the report: the model and its parameters,
    and the effects added to it."""
    s, m = config.sim, config.muscle
    mesh = s.fe_mesh if s.model == "axisym" else None
    model = _model(s.model, mesh, m.L0_mm, muscle_params(config))
    geometry = dict(zip(("D0_mm", "t0_mm"), s.truth.geometry(m), strict=True))
    departures = [f"true {k} {v:g} (declared {getattr(m, k):g})" for k, v in geometry.items()
                  if v != getattr(m, k)]
    departures += [f"{k} {getattr(s.truth, k):g}" for k in (*INSTRUMENT_BOUNDS,
                                                            "frame_stiffness_N_per_mm",
                                                            "line_tau_s", "mullins_fraction",
                                                            "braid_EA_N")
                   if getattr(s.truth, k) is not None]
    return {
        "force_model": s.model, "force_model_params": model.params(),
        "table": f"{s.model} tabulated at 81 pressures over 0-{config.regulator.full_scale_bar:g}"
                 " bar, linearly interpolated",
        "friction": f"braid friction as a play operator of half-width {s.hysteresis_fraction:g}"
                    " x force (rising and falling branches apart)",
        "creep": f"{s.creep_fraction:g} of the force relaxed with tau {s.creep_tau_s:g} s",
        "noise": f"load-cell noise {s.noise_V * 1e3:g} mV rms, 14-bit quantisation",
        "true_geometry": geometry,
        "instruments": {name: s.truth.instrument(name) for name in INSTRUMENT_BOUNDS},
        "summary": f"the {s.model} model's force{f' ({mesh} mesh)' if mesh else ''} with "
                   f"{100 * s.hysteresis_fraction:g} % braid friction (rising and falling "
                   f"branches apart), {100 * s.creep_fraction:g} % creep and load-cell noise"
                   + (f"; departures from the configuration: {', '.join(departures)}"
                      if departures else ""),
    }


class SimMuscleBench:
    """Regulator, muscle and load cell advanced one sample at a time (pure physics, no I/O)."""

    def __init__(self, config):
        self.config = config
        s = config.sim
        self.dt = 1.0 / config.daq.sample_rate_hz
        self.table_p, self.table_F = static_force_table(config)
        # the rubber before it softened, above the highest pressure the muscle has seen
        self.first_p, self.first_F = (static_force_table(config, first_loading=True)
                                      if s.truth.mullins_fraction else (None, None))
        self.highest_bar = 0.0  # the muscle's highest pressure so far
        self.softened_bar = 0.0  # the highest it has fallen from: its rubber softened up to it
        self.lag = 1.0 - math.exp(-self.dt / s.regulator_tau_s)
        self.max_step_bar = s.regulator_slew_bar_per_s * self.dt
        self.relax = 1.0 - math.exp(-self.dt / s.creep_tau_s)
        # the tubing's lag from the outlet to the muscle (none: the muscle at the outlet)
        self.line_tau_s = s.truth.line_tau_s or 0.0
        self.line_decay = math.exp(-self.dt / self.line_tau_s) if self.line_tau_s > 0 else 0.0
        self.rng = np.random.default_rng(s.seed)
        self.loadcell_gain = s.truth.instrument("loadcell_gain")
        self.loadcell_drift_N_per_min = s.truth.instrument("loadcell_drift_N_per_min")
        self.elapsed_s = 0.0  # since the first sample: the cell's zero drifts with it
        self.monitor_gain = s.truth.instrument("monitor_gain")
        self.monitor_offset_bar = s.truth.instrument("monitor_offset_bar")
        self.monitor_bow_bar = s.truth.instrument("monitor_bow_bar")
        self.monitor_hysteresis_bar = s.truth.instrument("monitor_hysteresis_bar")
        self.monitor_stuck_bar = s.truth.instrument("monitor_stuck_bar")  # None: it reads
        # the sensor's play operator: its output stays within half the hysteresis of the
        # pressure, so a rising pressure reads that much low and a falling one high
        self.monitor_played_bar = 0.0
        self.monitor_branch = -1.0  # -1 rising, +1 falling: the side the regulator expects
        self.command_bar = 0.0
        self._noise = np.empty(0)
        self._next_noise = 0
        self.target_bar = 0.0
        self.pressure_bar = 0.0  # at the regulator's outlet, where its sensor reads
        self.muscle_pressure_bar = 0.0  # inside the muscle, behind its tubing
        self.hysteretic_N = 0.0
        self.relaxed_N = 0.0
        self.external_force_N = 0.0
        self.force_N = 0.0  # true force on the cell at the last sample
        self.regulator_stuck = False  # fault: the regulator no longer follows its command
        self.loadcell_broken = False  # fault: the load-cell input reads NaN
        self.loadcell_stuck = False  # fault: the load-cell input holds one value
        self._stuck_cell_V: float | None = None  # the value it holds
        self.monitor_lost = False  # fault: the monitor input reads 0 V (unpowered, wire off)

    def set_command_volts(self, volts: float) -> None:
        r = self.config.regulator
        command_bar = min(max(volts, 0.0), 10.0) / 10.0 * r.full_scale_bar
        if command_bar != self.command_bar:
            self.monitor_branch = -1.0 if command_bar > self.command_bar else 1.0
        self.command_bar = command_bar
        # the regulator holds its own sensor's reading at the command (a zero command vents)
        self.target_bar = (max(self.sensor_inverse_bar(
            command_bar - self.monitor_branch * self.monitor_hysteresis_bar / 2), 0.0)
            if command_bar > 0 else 0.0)
        if self.target_bar > 0:
            self.target_bar += self.config.sim.faults.overshoot_bar

    def sensor_bar(self, pressure_bar: float) -> float:
        """The regulator sensor's reading of ``pressure_bar`` without its hysteresis: gain,
        offset and bow."""
        x = pressure_bar / self.config.regulator.full_scale_bar
        return (self.monitor_gain * pressure_bar + self.monitor_offset_bar
                + self.monitor_bow_bar * 4.0 * x * (1.0 - x))

    def sensor_inverse_bar(self, reading_bar: float) -> float:
        """The pressure whose :meth:`sensor_bar` is ``reading_bar``."""
        return sensor_inverse_bar(self.config.sim.truth, self.config.regulator.full_scale_bar,
                                  reading_bar)

    def _normal(self) -> float:
        if self._next_noise >= self._noise.size:
            self._noise = self.rng.standard_normal(4096)
            self._next_noise = 0
        self._next_noise += 1
        return float(self._noise[self._next_noise - 1])

    def step(self) -> tuple[float, float]:
        """Advance one sample; return (load-cell volts, monitor volts) as the ADC reads them."""
        s, r, cell = self.config.sim, self.config.regulator, self.config.loadcell
        outlet_bar = self.pressure_bar
        if not self.regulator_stuck:
            change = (self.target_bar - self.pressure_bar) * self.lag
            self.pressure_bar += min(max(change, -self.max_step_bar), self.max_step_bar)
        if self.line_tau_s > 0:
            # the lag's exact answer to an outlet pressure linear between samples: a ramp is
            # trailed by its rate times tau, not by the sample-and-hold's (0.95 tau at 10 Hz
            # and 1 s)
            trail_bar = self.line_tau_s * (self.pressure_bar - outlet_bar) / self.dt
            self.muscle_pressure_bar = self.pressure_bar - trail_bar + self.line_decay * (
                self.muscle_pressure_bar - outlet_bar + trail_bar)
        else:
            self.muscle_pressure_bar = self.pressure_bar
        static = float(np.interp(self.muscle_pressure_bar, self.table_p, self.table_F))
        if self.first_F is not None:
            if self.muscle_pressure_bar < self.highest_bar:
                self.softened_bar = self.highest_bar
            self.highest_bar = max(self.highest_bar, self.muscle_pressure_bar)
            above_bar = self.muscle_pressure_bar - self.softened_bar
            if above_bar > 0:  # loading its rubber afresh
                fresh = float(np.interp(self.muscle_pressure_bar, self.first_p, self.first_F))
                share = (min(above_bar / (MULLINS_BAND * self.softened_bar), 1.0)
                         if self.softened_bar > 0 else 1.0)
                static += share * (fresh - static)
        self.hysteretic_N, self.relaxed_N = advance(
            self.hysteretic_N, self.relaxed_N, static, s.hysteresis_fraction, s.creep_fraction,
            self.relax)
        # a slack muscle (force relaxing below zero after a pressure drop) cannot push
        force = max(self.hysteretic_N - self.relaxed_N, 0.0) + self.external_force_N
        self.force_N = force  # the truth a measurement of this sample is judged against
        self.elapsed_s += self.dt
        drift_N = self.loadcell_drift_N_per_min * self.elapsed_s / 60.0
        cell_V = ((self.loadcell_gain * force + drift_N) / cell.sensitivity_N_per_V
                  + s.loadcell_offset_V + s.noise_V * self._normal())
        span = r.monitor_V_at_full_scale - r.monitor_V_at_zero
        half = self.monitor_hysteresis_bar / 2
        self.monitor_played_bar = min(max(self.monitor_played_bar, self.pressure_bar - half),
                                      self.pressure_bar + half)
        sensed_bar = self.sensor_bar(self.pressure_bar) + self.monitor_played_bar \
            - self.pressure_bar
        if self.monitor_stuck_bar is not None:  # its output no longer follows its sensor
            sensed_bar = self.monitor_stuck_bar
        monitor_V = (r.monitor_V_at_zero + sensed_bar / r.full_scale_bar * span
                     + s.monitor_noise_V * self._normal())
        if self.monitor_lost:
            monitor_V = 0.0
        if self.loadcell_broken:
            return math.nan, quantize_volts(monitor_V)
        if self.loadcell_stuck:
            if self._stuck_cell_V is None:
                self._stuck_cell_V = quantize_volts(cell_V)
            return self._stuck_cell_V, quantize_volts(monitor_V)
        return quantize_volts(cell_V), quantize_volts(monitor_V)


class SimBackend:
    """Simulated NI USB-6001 bench with the :class:`mkm.bench.backend.Backend` interface.

    Parameters
    ----------
    config : mkm.bench.config.BenchConfig
        The bench settings; ``config.sim`` (:class:`mkm.bench.sim_settings.Sim`) holds the
        physics, seed and faults.
    clock : {"virtual", "real"}
        ``virtual``: sample k is at k / rate s and reads return at once; ``real``: reads wait
        until the samples' times have passed, as the hardware clock does.
    """

    def __init__(self, config, clock: str = "virtual"):
        if clock not in CLOCKS:
            raise ValueError(f"clock={clock!r} is invalid: expected one of {', '.join(CLOCKS)}")
        self.config = config
        self.clock = clock
        self.bench_key = f"sim-{config.daq.device.strip()}"  # the lock folds the case
        self.rate_hz = config.daq.sample_rate_hz
        buffer_s = config.sim.buffer_s or config.daq.buffer_s
        self.buffer_samples = int(round(buffer_s * self.rate_hz))
        self.bench = SimMuscleBench(config)
        self.commands: list[tuple[int, float]] = []  # (hardware sample index, volts) per write
        self.closed = False
        self._fifo: deque = deque()  # acquired, not yet read (the driver's buffer)
        self._head = 0  # index of the next sample the hardware clock will take
        self._started_at: float | None = None
        self._faults = config.sim.faults
        self._timeouts_left = self._faults.read_timeouts
        self._ao_failed = False
        self._stalled = False
        self._overflow: BufferOverflow | None = None  # found while writing, raised at the next read

    @property
    def _index(self) -> int:
        """Index of the next sample to be read."""
        return self._head - len(self._fifo)

    @property
    def _channels(self) -> list[str]:
        return self.config.ai_channels

    def _now_s(self) -> float:
        return self._index / self.rate_hz

    def _due(self, at_s: float | None) -> bool:
        return at_s is not None and self._now_s() >= at_s

    def open(self) -> DeviceInfo:
        self.write_command(0.0)
        regulator = self.config.regulator
        channels = {"ai": self._channels, "ai_range_V": [-10.0, 10.0],
                    "terminal_config": self.config.daq.terminal_config,
                    "ao": regulator.command_channel if regulator.electronic else None}
        sim = {**self.config.as_dict()["sim"], "physics": describe_physics(self.config)}
        return DeviceInfo(backend="sim", simulated=True, product_type="USB-6001 (simulated)",
                          serial_number=f"SIM-{self.config.sim.seed}",
                          sample_rate_hz=self.rate_hz, channels=channels,
                          extra={"clock": self.clock, "sim": sim})

    def start(self) -> None:
        self._started_at = time.monotonic()

    def _acquire(self, n: int) -> None:
        """The hardware clock takes ``n`` samples into the buffer (faults fire at their time)."""
        f = self._faults
        for _ in range(n):
            t_s = self._head / self.rate_hz
            if f.nan_force_at_s is not None and t_s >= f.nan_force_at_s:
                self.bench.loadcell_broken = True
            if f.loadcell_stuck_at_s is not None and t_s >= f.loadcell_stuck_at_s:
                self.bench.loadcell_stuck = True
            if f.regulator_stuck_at_s is not None and t_s >= f.regulator_stuck_at_s:
                self.bench.regulator_stuck = True
            if f.monitor_lost_at_s is not None and t_s >= f.monitor_lost_at_s:
                self.bench.monitor_lost = True
            self._fifo.append(self.bench.step())
            self._head += 1
        if len(self._fifo) > self.buffer_samples:
            lost = len(self._fifo)
            self._fifo.clear()  # the driver overwrote unread samples; restarting discards all
            raise BufferOverflow(f"the reader fell {lost} samples behind, more than the "
                                 f"{self.buffer_samples}-sample buffer", lost_samples=lost)

    def _catch_up(self) -> None:
        """Real clock: acquire every sample whose time has passed."""
        due = int((time.monotonic() - self._started_at) * self.rate_hz)
        if due > self._head:
            self._acquire(due - self._head)

    def read(self, n_samples: int, timeout_s: float) -> Block:
        if self._started_at is None:
            raise RuntimeError("read before start")
        faults = self._faults
        if self._overflow is not None:
            exc, self._overflow = self._overflow, None
            raise exc
        if self._due(faults.disconnect_at_s):
            raise DaqDisconnected(f"simulated disconnect at {faults.disconnect_at_s:g} s")
        if self._due(faults.read_timeout_at_s) and self._timeouts_left > 0:
            self._timeouts_left -= 1
            raise ReadTimeout(f"simulated read timeout at {self._now_s():g} s")
        if self._due(faults.stall_at_s) and not self._stalled:
            # The reader stalls: the clock runs on, samples pile up in the buffer (and overflow
            # it if the stall is longer), commands written afterwards reach the regulator late.
            self._stalled = True
            if self.clock == "real":
                time.sleep(faults.stall_s)
            else:
                self._acquire(int(round(faults.stall_s * self.rate_hz)))
        if self.clock == "real":
            self._wait_for(n_samples, timeout_s)
        elif len(self._fifo) < n_samples:
            self._acquire(n_samples - len(self._fifo))
        first = self._index
        rows = [self._fifo.popleft() for _ in range(n_samples)]
        volts = np.array(rows, dtype=float).reshape(n_samples, 2)
        if not self.config.regulator.electronic:
            volts = volts[:, :1]
        return Block(first, volts)

    def available(self) -> int:
        if self._started_at is None:
            return 0
        if self.clock == "real":
            try:
                self._catch_up()
            except BufferOverflow as exc:
                self._overflow = exc
                return 1  # something to read: the read reports the overflow
        return len(self._fifo)

    def _wait_for(self, n_samples: int, timeout_s: float) -> None:
        self._catch_up()
        missing = n_samples - len(self._fifo)
        if missing <= 0:
            return
        wait = (self._head + missing) / self.rate_hz - (
            time.monotonic() - self._started_at)
        if wait > timeout_s:
            time.sleep(timeout_s)
            raise ReadTimeout(f"samples not available within {timeout_s:g} s")
        if wait > 0:
            time.sleep(wait)
        self._acquire(max(0, n_samples - len(self._fifo)))

    def recover(self) -> int:
        # Restarting the task discards the buffer (already emptied at the overflow): reading
        # resumes at the hardware clock's head, the physics having run on meanwhile.
        return self._index

    def write_command(self, volts: float) -> None:
        if self._due(self._faults.disconnect_at_s):
            raise DaqDisconnected(f"simulated disconnect at {self._faults.disconnect_at_s:g} s")
        if self._due(self._faults.ao_fail_at_s) and not self._ao_failed:
            self._ao_failed = True
            raise AOWriteFailed(f"simulated AO write failure at {self._now_s():g} s")
        if not self.config.regulator.electronic:
            return
        if self.clock == "real" and self._started_at is not None:
            try:  # the command lands at the hardware's present, not at the reader's
                self._catch_up()
            except BufferOverflow as exc:  # the reader learns it at its next read, as on NI
                self._overflow = exc
        self.bench.set_command_volts(volts)
        self.commands.append((self._head, float(volts)))

    def close(self) -> None:
        if self.closed:
            return
        self.closed = True
        self.write_command(0.0)

    # Operator actions on the simulated bench (manual regulator, calibration masses).

    def set_manual_pressure(self, pressure_bar: float) -> float:
        """Turn the hand regulator to ``pressure_bar``; return the manometer reading [bar]."""
        self.bench.target_bar = pressure_bar
        return round(pressure_bar / MANOMETER_RESOLUTION_BAR) * MANOMETER_RESOLUTION_BAR

    def hang_mass(self, mass_kg: float) -> None:
        """Hang ``mass_kg`` on the load cell (for ``mkm calibrate-loadcell``)."""
        self.bench.external_force_N = mass_kg * STANDARD_GRAVITY


def logged_ramp(config, top_bar: float, rate_bar_per_s: float, rest_s: float = 5.0):
    """What a lab's logger records of the simulated bench under a continuous ramp: vented
    ``rest_s``, the command ramped at ``rate_bar_per_s`` up to ``top_bar`` and back to 0,
    vented ``rest_s`` again, one row per sample (``config.daq.sample_rate_hz``) of the time,
    the monitor's pressure and the load cell's force as read (its offset in it: ``mkm
    import`` tares it on the rest), a table for :func:`mkm.bench.exchange.import_table`."""
    import pandas as pd

    bench, r = SimMuscleBench(config), config.regulator
    rise_s = top_bar / rate_bar_per_s
    n = int(round((2 * rest_s + 2 * rise_s) / bench.dt))
    time_s = np.arange(n) * bench.dt
    commanded = np.interp(time_s, [0.0, rest_s, rest_s + rise_s, rest_s + 2 * rise_s],
                          [0.0, 0.0, top_bar, 0.0])
    volts = np.empty((n, 2))
    for k in range(n):
        bench.set_command_volts(r.command_volts(commanded[k]))
        volts[k] = bench.step()
    return pd.DataFrame({"t (s)": time_s, "P (bar)": r.monitor_bar(volts[:, 1]),
                         "F (N)": volts[:, 0] * config.loadcell.sensitivity_N_per_V})
