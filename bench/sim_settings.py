"""Settings of the simulated bench (:mod:`mkm.bench.sim`): the ``[sim]``, ``[sim.faults]`` and
``[sim.truth]`` tables of a bench configuration.

Every time and count is bounded, so no setting can make a simulated run endless: a reader stall
of at most an hour, a driver buffer of one second to a day, faults at most a day into the run.
"""

from __future__ import annotations

import dataclasses
import json
import re
from dataclasses import dataclass, field
from pathlib import Path

from mkm.bench.settings import positive, within

MAX_SIM_TIME_S = 24 * 3600.0  # a fault time, a stall, a buffer: beyond a day is not a test
MAX_STALL_S = 3600.0
MIN_SIM_BUFFER_S = 1.0  # at least ten 0.1 s blocks: below, every read overflows and none ends
MAX_READ_TIMEOUTS = 1000


@dataclass(frozen=True)
class Faults:
    """Faults the simulated bench injects, at sample time [s]; absent means never."""

    disconnect_at_s: float | None = None
    read_timeout_at_s: float | None = None
    read_timeouts: int = 1
    stall_at_s: float | None = None
    stall_s: float = 0.0
    ao_fail_at_s: float | None = None
    nan_force_at_s: float | None = None  # the load-cell input reads NaN from then on
    # the load-cell input holds the value it read then, whatever the force (a cell whose cable
    # or amplifier failed so), from then on
    loadcell_stuck_at_s: float | None = None
    regulator_stuck_at_s: float | None = None  # the regulator stops following the command
    overshoot_bar: float = 0.0  # the regulator delivers this much above every command
    monitor_lost_at_s: float | None = None  # the monitor input reads 0 V from then on

    def check(self):
        for f in dataclasses.fields(self):
            value = getattr(self, f.name)
            if f.name.endswith("_at_s") and value is not None:
                within(f"sim.faults.{f.name}", value, 0.0, MAX_SIM_TIME_S, "s")
        within("sim.faults.overshoot_bar", self.overshoot_bar, 0.0, 10.0, "bar")
        within("sim.faults.read_timeouts", self.read_timeouts, 1, MAX_READ_TIMEOUTS)
        within("sim.faults.stall_s", self.stall_s, 0.0, MAX_STALL_S, "s")


@dataclass(frozen=True)
class Truth:
    """The simulated muscle and instruments as they are, where they differ from what the
    configuration declares.

    The muscle: its braid angle, rubber, gap between tube and braid (a model that takes
    ``gap_mm``: ``thickwall``, ``axisym``), braid (``bonded`` or ``sliding``, a model that takes
    ``braid``: ``axisym``) and its true geometry ``D0_mm``, ``t0_mm`` (``[muscle]`` keeps the
    declared one, which is what a fit reads). The instruments: ``loadcell_gain``, the cell's true
    output per newton over the configured one (1.02 records forces 2 % high);
    ``loadcell_drift_N_per_min``, its zero moving steadily from the start of acquisition (a
    strain-gauge amplifier warming up: what the tare took away comes back over the run);
    ``monitor_gain``, ``monitor_offset_bar``, ``monitor_bow_bar`` and ``monitor_hysteresis_bar``,
    the regulator's pressure sensor: the monitor reads ``monitor_gain * P + monitor_offset_bar +
    monitor_bow_bar * 4 x (1 - x)`` for a true pressure ``P`` (``x = P /
    regulator.full_scale_bar``: a bow, zero at both ends of the sensor's range, largest at
    mid-scale), less half ``monitor_hysteresis_bar`` on a rising pressure and plus half on a
    falling one (a play operator: the two branches ``monitor_hysteresis_bar`` apart); the
    regulator holds that reading at the command, as an ITV does with its own sensor.
    ``monitor_stuck_bar``: the monitor output is frozen at this reading whatever the pressure
    (its output stage, wire or input stuck), while the regulator still holds its own sensor at
    the command. The frame: ``frame_stiffness_N_per_mm``, the frame, fixtures and load cell
    between the muscle's ends as one spring of that stiffness: the held length shortens by
    ``F / k`` under the muscle's pull ``F`` (its eps grows by ``F / (k L0)``; a real frame is
    never rigid, and the force falls steeply with eps). The tubing: ``line_tau_s``, the time
    constant of the first-order lag between the regulator's outlet, where its sensor and the
    monitor read, and the muscle, which fills through its tubing: on a ramp of ``r`` bar/s the
    muscle's pressure trails the monitor's by ``r * line_tau_s``. The rubber:
    ``mullins_fraction``, the share of its stiffness it loses once a pressure has been exceeded
    (the Mullins effect: a fresh or rested muscle is stiffer on its first rise to a new highest
    pressure than on every later loading to it): the truth's rubber is the preconditioned
    one, and above every pressure the muscle has fallen from in the run (on its first rise,
    above none) it is the one of a rubber ``1 / (1 - mullins_fraction)`` times as stiff; each
    run starts rested, and nothing recovers within it. The braid: ``braid_EA_N``, its
    tensile stiffness along its fibres, ``E A`` summed over its strands (a lab measures one
    strand's force over its strain on a tensile tester and multiplies by the strands it
    counts): the fibres' total tension over it is their strain, which lengthens every fibre
    by that fraction, so at a held length the braid is one of longer fibres (a smaller angle
    to the axis, a larger diameter: the force of a muscle further contracted); polyester and
    nylon sleeves stretch 0.5-3 % at a muscle's top force, where the models take them as
    inextensible.

    Unset (None): the declared value (``[muscle]``'s angle, rubber and gap where it gives
    them, else the calibrated angle, Silastic S, no gap; a bonded braid, the declared
    geometry, exact instruments: :func:`mkm.bench.sim.muscle_params`). With ``[sim]``'s
    ``hysteresis_fraction``, ``creep_fraction`` and ``creep_tau_s`` this is the truth that
    ``mkm identify`` must find blind: it is recorded in the run's simulator settings only
    (:func:`remove_simulator_settings` deletes it).
    """

    theta0_deg: float | None = None
    C10_MPa: float | None = None
    C01_MPa: float | None = None
    gap_mm: float | None = None
    braid: str | None = None
    D0_mm: float | None = None
    t0_mm: float | None = None
    loadcell_gain: float | None = None
    loadcell_drift_N_per_min: float | None = None
    monitor_gain: float | None = None
    monitor_offset_bar: float | None = None
    monitor_bow_bar: float | None = None
    monitor_hysteresis_bar: float | None = None
    monitor_stuck_bar: float | None = None
    frame_stiffness_N_per_mm: float | None = None
    line_tau_s: float | None = None
    mullins_fraction: float | None = None
    braid_EA_N: float | None = None

    def check(self):
        from mkm.fem.limits import check_theta0, check_value

        for name in MODEL_FIELDS + GEOMETRY_FIELDS:
            if name != "braid" and getattr(self, name) is not None:
                check_value(name, getattr(self, name), prefix="sim.truth.")
        if self.theta0_deg is not None:
            check_theta0(self.theta0_deg, prefix="sim.truth.")
        for name, (low, high, unit, _) in INSTRUMENT_BOUNDS.items():
            if getattr(self, name) is not None:
                within(f"sim.truth.{name}", getattr(self, name), low, high, unit)
        if self.frame_stiffness_N_per_mm is not None:
            within("sim.truth.frame_stiffness_N_per_mm", self.frame_stiffness_N_per_mm,
                   *FRAME_STIFFNESS_BOUNDS_N_PER_MM, "N/mm")
        if self.line_tau_s is not None:
            within("sim.truth.line_tau_s", self.line_tau_s, *LINE_TAU_BOUNDS_S, "s")
        if self.mullins_fraction is not None:
            within("sim.truth.mullins_fraction", self.mullins_fraction, *MULLINS_BOUNDS,
                   "(a fraction of the rubber's stiffness)")
        if self.braid_EA_N is not None:
            within("sim.truth.braid_EA_N", self.braid_EA_N, *BRAID_EA_BOUNDS_N, "N")

    def model_params(self) -> dict[str, float | str]:
        """The set values the force model takes (angle, rubber, gap, braid)."""
        return {name: (getattr(self, name) if name == "braid" else float(getattr(self, name)))
                for name in MODEL_FIELDS if getattr(self, name) is not None}

    def geometry(self, muscle) -> tuple[float, float]:
        """The true ``(D0_mm, t0_mm)``: the set ones, else ``muscle``'s declared ones."""
        return (float(self.D0_mm if self.D0_mm is not None else muscle.D0_mm),
                float(self.t0_mm if self.t0_mm is not None else muscle.t0_mm))

    def instrument(self, name: str) -> float | None:
        """An instrument's truth, the exact instrument's when unset (gain 1, offset 0, a
        monitor not stuck: None)."""
        value = getattr(self, name)
        return float(value) if value is not None else INSTRUMENT_BOUNDS[name][3]


#: a frame stiffness the simulator takes [N/mm]: from one that gives 1 mm under 1 N to about
#: a steel block's
FRAME_STIFFNESS_BOUNDS_N_PER_MM = (1.0, 1e7)
#: a tubing lag the simulator takes [s]: none to a muscle filled through a long thin line
LINE_TAU_BOUNDS_S = (0.0, 60.0)
#: a first loading's softening the simulator takes: none to half the rubber's stiffness (filled
#: rubbers lose up to some 40 % on their first cycle, silicones less)
MULLINS_BOUNDS = (0.0, 0.5)
#: a braid's fibre stiffness the simulator takes [N]: a few thin nylon strands (a 1 % strain
#: under 1 N) to steel wire's
BRAID_EA_BOUNDS_N = (100.0, 1e9)
#: the truths the force model takes; the true geometry; the instruments' truths: their bounds
#: and unit, and the exact instrument's value
MODEL_FIELDS = ("theta0_deg", "C10_MPa", "C01_MPa", "gap_mm", "braid")
GEOMETRY_FIELDS = ("D0_mm", "t0_mm")
INSTRUMENT_BOUNDS = {
    "loadcell_gain": (0.9, 1.1, "(a cell 10 % off its calibration is broken)", 1.0),
    "loadcell_drift_N_per_min": (-10.0, 10.0, "N/min", 0.0),
    # a sensor 10 % off is broken; 0.8: a 5 bar regulator's monitor read on a 4 bar scale
    "monitor_gain": (0.75, 1.25, "(a sensor reading 0.8 of the pressure: a 5 bar regulator's "
                     "monitor read on a 4 bar one's scale)", 1.0),
    "monitor_offset_bar": (-0.5, 0.5, "bar", 0.0),
    "monitor_bow_bar": (-0.5, 0.5, "bar", 0.0),  # and a tenth of full scale
    "monitor_hysteresis_bar": (0.0, 0.5, "bar", 0.0),
    "monitor_stuck_bar": (0.0, 10.0, "bar", None),  # and within full scale
}
@dataclass(frozen=True)
class Sim:
    """The simulated bench (:mod:`mkm.bench.sim`): the muscle's static force from ``model`` (a
    ``mkm.fem.ladder`` rung; ``axisym`` on the ``fe_mesh`` mesh), braid friction, creep, noise."""

    model: str = "axisym"
    fe_mesh: str = "medium"
    seed: int = 0
    regulator_tau_s: float = 0.4
    regulator_slew_bar_per_s: float = 2.0
    hysteresis_fraction: float = 0.03
    creep_fraction: float = 0.02
    creep_tau_s: float = 30.0
    noise_V: float = 0.002
    loadcell_offset_V: float = 0.015
    monitor_noise_V: float = 0.001
    buffer_s: float | None = None
    faults: Faults = field(default_factory=Faults)
    truth: Truth = field(default_factory=Truth)

    def check(self):
        from mkm.fem.ladder import entry, static_names
        from mkm.fem.options import MESH_LEVELS

        if self.model not in static_names():
            raise ValueError(f"sim.model={self.model[:40]!r} is unknown: expected one of "
                             f"{', '.join(static_names())}")
        if self.fe_mesh not in MESH_LEVELS:
            raise ValueError(f"sim.fe_mesh={self.fe_mesh[:40]!r} is invalid: expected one of "
                             f"{', '.join(MESH_LEVELS)}")
        within("sim.seed", self.seed, 0, 2**63 - 1)
        within("sim.regulator_tau_s", self.regulator_tau_s, 1e-3, 60.0, "s")
        within("sim.regulator_slew_bar_per_s", self.regulator_slew_bar_per_s, 1e-3, 1000.0,
               "bar/s")
        within("sim.creep_tau_s", self.creep_tau_s, 1e-3, 1e5, "s")
        for name in ("hysteresis_fraction", "creep_fraction"):
            within(f"sim.{name}", getattr(self, name), 0.0, 0.5, "(a fraction)")
        for name in ("noise_V", "monitor_noise_V"):
            within(f"sim.{name}", getattr(self, name), 0.0, 10.0, "V (the input range)")
        within("sim.loadcell_offset_V", self.loadcell_offset_V, -10.0, 10.0, "V")
        if self.buffer_s is not None:
            positive("sim.buffer_s", self.buffer_s)
            within("sim.buffer_s", self.buffer_s, MIN_SIM_BUFFER_S, MAX_SIM_TIME_S, "s")
        self.faults.check()
        self.truth.check()
        declared = entry(self.model).parameters
        refused = [k for k in self.truth.model_params() if k not in declared]
        if refused:
            raise ValueError(f"sim.truth.{refused[0]} is not a parameter of sim.model="
                             f"{self.model!r}: expected some of "
                             f"{', '.join(k for k in declared if k in MODEL_FIELDS) or 'none'}")
        if self.truth.mullins_fraction and "C10_MPa" not in declared:
            rubbers = [n for n in static_names() if "C10_MPa" in entry(n).parameters]
            raise ValueError(f"sim.truth.mullins_fraction softens the rubber, which "
                             f"sim.model={self.model!r} does not have: expected one of "
                             f"{', '.join(rubbers)}")
        if self.truth.braid is not None:
            choices = declared["braid"].options()
            if self.truth.braid not in choices:
                raise ValueError(f"sim.truth.braid={self.truth.braid[:40]!r} is invalid: "
                                 f"expected one of {', '.join(choices)}")


def sim_of(truth: dict, seed: int, model: str = "thickwall", **departures) -> dict:
    """The ``[sim]`` table of a bench holding the muscle ``truth``, given in identify's
    parameters: ``theta0_deg``, ``rubber_scale`` (Silastic S's constants times it) and, where
    given, ``hysteresis_fraction`` and ``creep_fraction`` (else the simulator's defaults);
    ``departures`` are further ``[sim.truth]`` values (instruments, gap, frame). A blind test
    draws ``truth`` and compares what identify fits with it."""
    from mkm.fem.materials import SILASTIC_S

    scale = truth["rubber_scale"]
    friction = {name: truth[name] for name in ("hysteresis_fraction", "creep_fraction")
                if name in truth}
    return {"model": model, "seed": seed, **friction,
            "truth": {"theta0_deg": truth["theta0_deg"], "C10_MPa": scale * SILASTIC_S.C10_MPa,
                      "C01_MPa": scale * SILASTIC_S.C01_MPa, **departures}}


def remove_simulator_settings(run_dir) -> None:
    """Delete a simulated run's ``[sim]`` settings, its truth among them, from its run.json
    (the simulator's record and ``sim.*`` overrides) and its config.toml: what is left is what a
    real bench records, for identification tested blind."""
    run_dir = Path(run_dir)
    meta = json.loads((run_dir / "run.json").read_text(encoding="utf-8"))
    meta.get("hardware", {}).pop("sim", None)
    meta["config_overrides"] = {k: v for k, v in (meta.get("config_overrides") or {}).items()
                                if not k.startswith("sim")}
    (run_dir / "run.json").write_text(json.dumps(meta, indent=2), encoding="utf-8")
    config = run_dir / "config.toml"
    text = config.read_text(encoding="utf-8")
    # every [sim] and [sim.*] table, up to the next other table or the end
    config.write_text(re.sub(r"(?ms)^\[sim(\.[^\]]*)?\][^\n]*\n.*?(?=^\[(?!sim[.\]])|\Z)",
                             "", text), encoding="utf-8")
