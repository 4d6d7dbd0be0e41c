"""The bench runs one identification reads: one muscle, its settled steps and its time traces.

Only what a real bench records is read: the muscle (``D0_mm``, ``t0_mm``, ``L0_mm``, ``eps``),
``steps.csv`` (which steps settled, their direction and hold window) and ``samples.csv`` (the
pressure and force traces). A simulated run's ``[sim]`` settings are never read: they hold the
truth the identification is tested against.

An imported step table (``mkm import``: one row per step, no samples) is read as one sample per
step, at the step's mean pressure and force, one second apart: the friction play operator
depends on the order of the pressures, not on time, and its holds are not timed, so creep is
not fitted from it (:attr:`RunData.timed`). Nor from an imported ramp, whose steps are bins of
a continuous sweep rather than holds.
"""

from __future__ import annotations

from dataclasses import dataclass, field, fields
from pathlib import Path

import numpy as np
import pandas as pd

from mkm.core.records import file_sha256
from mkm.scoring import slack

#: the tube that must agree between the runs of one muscle family (eps and the length
#: ``L0_mm`` may differ: the same tube and braid cut to several lengths)
SAME_MUSCLE = ("D0_mm", "t0_mm")
SAME_MUSCLE_RTOL = 1e-6
#: holds' true pressures closer than this [bar] share one sweep point, their mean: the rising
#: and the falling hold of one set pressure, whose means differ by the monitor's noise (up to
#: 0.5 mbar for 1 mbar over 50 samples); a hold that far from a threshold between it and the
#: point is off by its slope times that at most
TABLE_KNOT_BAR = 1e-3
#: a vented mean reading of the monitor is its zero within this many standard errors
VENTED_SE_FACTOR = 3.0


@dataclass
class RunData:
    """One run as the fit uses it.

    ``time_s``, ``pressure_bar``, ``force_N``: every sample in time order, the pressure
    denoised where the run held it (see :func:`load_run_data`); ``hold`` is the index of the
    settled step each sample's hold belongs to (-1: not in a settled hold); ``steps`` the
    settled steps (``step``, ``direction``, ``set_pressure_bar``, ``pressure_bar_mean``,
    ``force_N_mean``, ``hold_start_s``, ``end_s``, ``pressure_se_bar``: the standard error of the
    hold's mean pressure, NaN for an imported step; ``force_u_N``, ``pressure_u_bar``: the
    step's standard uncertainties from its budget, NaN where it has none, for an imported run
    the bounds its lab declared); ``tare_se_N`` the standard error of the
    zero the run's forces are measured from (its tare samples' std over their root count);
    the instrument's declared bounds from ``run.json``'s calibration (the defaults of
    :mod:`mkm.bench.config` where a run did not record them: ``instrument_declared`` False).
    """

    path: Path
    muscle: dict
    time_s: np.ndarray
    pressure_bar: np.ndarray
    force_N: np.ndarray
    hold: np.ndarray
    steps: pd.DataFrame
    sha256: dict
    tare_se_N: float = 0.0
    timed: bool = True  # the holds have their real durations (creep can be fitted)
    #: an imported run whose lab declared its accuracy (``mkm import --accuracy``): its steps'
    #: budgets stand for the noise a table's single values cannot show
    declared: bool = False
    #: the pressure monitor's declared +- bounds of its offset [bar] and gain error [fraction]
    #: (:meth:`mkm.bench.config.Regulator.reading_bounds`) and the load cell's sensitivity
    #: tolerance (a fraction), from the run's recorded calibration
    monitor_offset_bound_bar: float = 0.04
    monitor_gain_bound: float = 0.016
    sensitivity_tolerance: float = 0.001
    instrument_declared: bool = True  # False: the run recorded no bounds, defaults taken
    #: False: the run declared no pressure accuracy, its offset bound is the default
    offset_bound_declared: bool = True
    imported: bool = False  # a table or ramp of ``mkm import``: --accuracy declares its bounds
    #: the SHA-256 of the file the run was imported from (``imported_from.sha256``), else None
    table_sha256: str | None = None
    #: the shipped published table (``mkm data``) the run was imported from, by its file name:
    #: measured on another lab's bench, which no one here can stiffen or measure; None otherwise
    published: str | None = None
    #: the monitor's declared zero error [bar] where its data sheet is itemised (``[regulator]
    #: monitor_zero_bar``; None: one accuracy, whose share at zero nobody declared)
    monitor_zero_bound_bar: float | None = None
    #: the monitor's declared hysteresis [bar] (``[regulator] monitor_hysteresis_bar``: the
    #: largest gap between its rising and falling readings; 0 where not declared)
    monitor_hysteresis_bar: float = 0.0
    #: one ADC step of the run's load cell [N] (its recorded sensitivity and device); None for
    #: an imported table, which records no cell
    force_step_N: float | None = None
    #: the monitor's readings while the run was vented to tare the load cell: their mean and
    #: its standard error [bar] (None: no such readings, an imported run or a typed manometer)
    vented_bar: tuple[float, float] | None = None
    #: the tube's declared +- tolerances [mm] (``D0_mm``, ``t0_mm``: run.json's
    #: ``calibration.muscle_tolerances``, :class:`mkm.fem.tolerances.Tolerances` where none)
    geometry_tolerance_mm: dict = field(default_factory=lambda: _tube_tolerances(None))
    #: an imported ramp's pressure rate [bar/s] over each step's bin (its samples' slope, as
    #: the monitor read them); None for a run of held steps
    ramp_rate_bar_per_s: np.ndarray | None = None
    #: what identify notes of the run's record ("" when nothing): a run whose steps were all
    #: done and whose end-of-run vent alone was not verified (:func:`unverified_vent`)
    note: str = ""

    @property
    def name(self) -> str:
        return self.path.name

    @property
    def eps(self) -> float:
        return float(self.muscle["eps"])

    @property
    def held_mm(self) -> float:
        """The length the run held the muscle at, ``L0 (1 - eps)`` [mm]."""
        return float(self.muscle["L0_mm"]) * (1.0 - self.eps)

    @property
    def geometry(self) -> tuple[float, float, float]:
        """``(D0_mm, t0_mm, eps)``: what a force model's predict takes besides the pressure."""
        return float(self.muscle["D0_mm"]), float(self.muscle["t0_mm"]), self.eps

    def true_pressure_bar(self, values: dict) -> np.ndarray:
        """The true pressure [bar] at every sample as the monitor's reading gives it at the
        internal ``values``: less its offset ``pressure_offset_bar``, plus
        ``pressure_hysteresis_bar`` in a rising hold (where it reads low) and less it in a
        falling one, over its gain ``pressure_gain`` (1 unless a sensitivity is taken)."""
        reading = self.pressure_bar - values.get("pressure_offset_bar", 0.0)
        hysteresis = values.get("pressure_hysteresis_bar", 0.0)
        if hysteresis:  # fitted only where declared: most fits have none
            reading = reading + hysteresis * self.branch_sign()
        return reading / values.get("pressure_gain", 1.0)

    def table_pressures(self, values: dict) -> np.ndarray:
        """0 bar and the settled holds' true pressures at ``values`` (:meth:`true_pressure_bar`),
        those within :data:`TABLE_KNOT_BAR` of the next taken as their mean: where a model is
        solved, so that a hold's force is the model's there, not an interpolation across a
        threshold between two set pressures."""
        held = np.unique(np.maximum(self.true_pressure_bar(values)[self.hold >= 0], 0.0))
        group = np.r_[0, np.cumsum(np.diff(held) > TABLE_KNOT_BAR)]
        knots = np.bincount(group, held) / np.bincount(group)
        return np.unique(np.r_[0.0, knots])

    def declared_noise_N(self) -> np.ndarray | None:
        """Each step's noise [N] from the bounds its lab declared (an imported table or ramp,
        ``mkm import --accuracy``): the force's standard uncertainty and the pressure's times
        the force's slope there, the only statement of a single value's noise there is;
        ``None`` for a run with timed holds (their scatter shows it) or no declared bounds."""
        force_u = self.steps["force_u_N"].to_numpy(dtype=float)
        if self.timed or not self.declared or not np.isfinite(force_u).all():
            return None
        pressure_u = np.nan_to_num(self.steps["pressure_u_bar"].to_numpy(dtype=float))
        slopes = branch_slopes(self.steps) if self.binned else step_slopes(self.steps)
        return np.sqrt(force_u**2 + (slopes * pressure_u) ** 2)

    def branch_sign(self) -> np.ndarray:
        """Per sample: +1 in the hold of a rising step, -1 of a falling one, 0 elsewhere (the
        side of a monitor's hysteresis its reading is on)."""
        rising = (self.steps["direction"] == "up").to_numpy()
        sign = np.where(rising, 1.0, -1.0)[np.maximum(self.hold, 0)]
        return np.where(self.hold >= 0, sign, 0.0)

    @property
    def binned(self) -> bool:
        """An imported ramp: its steps are bins of a continuous sweep."""
        return self.ramp_rate_bar_per_s is not None

    def ramp_rate_at_samples(self) -> np.ndarray | float:
        """Per sample: its ramp bin's pressure rate [bar/s] (0 outside the bins), or 0 for a
        run of held steps."""
        if self.ramp_rate_bar_per_s is None:
            return 0.0
        return np.where(self.hold >= 0, self.ramp_rate_bar_per_s[np.maximum(self.hold, 0)], 0.0)

    def step_means(self, force_N: np.ndarray) -> np.ndarray:
        """The mean of a force trace over each settled step's hold [N]."""
        sums = np.bincount(self.hold[self.hold >= 0], weights=force_N[self.hold >= 0],
                           minlength=len(self.steps))
        counts = np.bincount(self.hold[self.hold >= 0], minlength=len(self.steps))
        return sums / np.maximum(counts, 1)


def shown_effects(runs) -> tuple[str, ...]:
    """The ``--params`` groups of what ``runs`` show beyond the muscle: friction in a run with a
    rising and a falling branch, creep in one whose holds have a known duration
    (:attr:`RunData.timed`)."""
    return ((("friction",) if any({"up", "down"} <= set(r.steps["direction"]) for r in runs)
             else ()) + (("creep",) if any(r.timed for r in runs) else ()))


def branch_slopes(steps: pd.DataFrame) -> np.ndarray:
    """dF/dP [N/bar] at each of a ramp's bins, along its own branch (each stretch of one
    direction): a rising and a falling bin lie at pressures a few mbar apart, and
    :func:`step_slopes` taken across the two would divide their friction's difference by
    that."""
    P = steps["pressure_bar_mean"].to_numpy(dtype=float)
    F = steps["force_N_mean"].to_numpy(dtype=float)
    direction = steps["direction"].to_numpy()
    branch = np.r_[0, np.cumsum(direction[1:] != direction[:-1])]
    slopes = np.zeros(P.size)
    for b in np.unique(branch):
        here = np.flatnonzero(branch == b)
        if here.size < 2:
            continue
        order = here[np.argsort(P[here], kind="stable")]
        slopes[order] = np.gradient(F[order], P[order])
    return slopes


def step_slopes(steps: pd.DataFrame) -> np.ndarray:
    """dF/dP [N/bar] at each step, from the run's own step means (both branches' means at each
    distinct pressure)."""
    P = steps["pressure_bar_mean"].to_numpy(dtype=float)
    F = steps["force_N_mean"].to_numpy(dtype=float)
    levels, inverse = np.unique(np.round(P, 3), return_inverse=True)
    if levels.size < 2:
        return np.zeros(P.size)
    mean_P = np.bincount(inverse, P) / np.bincount(inverse)
    mean_F = np.bincount(inverse, F) / np.bincount(inverse)
    return np.gradient(mean_F, mean_P)[inverse]


#: :attr:`RunData.sha256`'s key of the raw samples a reprocessed run was computed from
REPROCESSED_FROM = "reprocessed from samples.csv"


def _traced(run) -> pd.DataFrame:
    """The run's samples with a finite force and pressure."""
    samples = run.samples
    return samples[np.isfinite(samples["force_N"]) & np.isfinite(samples["pressure_bar"])]


def _from_table(run) -> bool:
    """An imported step table without samples: identified from its steps alone."""
    return str(run.status) == "imported" and _traced(run).empty


def measurement_sha256(run) -> dict[str, str]:
    """The SHA-256 of the measurement a run folder (:func:`mkm.bench.storage.load_run`) holds:
    its steps.csv, its samples.csv (none for an imported table: its empty samples.csv is
    every table's), and the raw samples a reprocessed run came from."""
    path = Path(run.path)
    names = ("steps.csv",) if _from_table(run) else ("steps.csv", "samples.csv")
    sha = {name: file_sha256(path / name) for name in names if (path / name).is_file()}
    if source := (run.meta.reprocessed_from or {}).get("samples_sha256"):
        sha[REPROCESSED_FROM] = source  # its raw samples are those of the run it came from
    return sha


def measurement_keys(name: str, sha256: dict[str, str]) -> set[str]:
    """What names the measurement of run ``name`` (its :func:`measurement_sha256`): two runs
    that share a key hold the same one (one table imported twice, a copied run folder, a run
    and its reprocessing)."""
    return {sha256.get("steps.csv", name)} | {
        sha256[k] for k in ("samples.csv", REPROCESSED_FROM) if k in sha256}


def load_run_data(path) -> RunData:
    """A run folder for identification; ``ValueError`` names a run that cannot serve.

    Refused: a run still being recorded, a run whose status is ``failed`` (unless its steps
    were all done and only its end-of-run vent was not verified, :func:`unverified_vent`), a
    run without a settled step, a run without its samples. Within each settled hold the
    regulator has reached the set pressure (the settle criterion), so the hold's samples take
    the hold's mean pressure: the
    monitor's noise would otherwise ratchet the friction model's play operator.
    """
    from mkm.bench.storage import load_run

    run = load_run(path)
    path = Path(path)
    if run.meta.recording():  # its steps so far would be identified as the whole run
        raise ValueError(f"run {path.name} {run.meta.recording()}: expected a run that has "
                         f"ended (identify it {run.meta.until_ended()})")
    note = unverified_vent(run, path.name) if str(run.status) == "failed" else ""
    if run.rows_lost:  # steps whose hold samples are gone would be fitted as forces of zero
        raise ValueError(f"run {path.name}: {run.rows_lost[0]}: expected the whole record to "
                         "identify from")
    steps = run.steps
    settled = steps[steps["settled"].astype(bool)] if len(steps) else steps
    if settled.empty:
        raise ValueError(f"run {path.name} has no settled step: expected at least one step "
                         "with settled = true in steps.csv")
    samples = _traced(run)
    imported = run.meta.imported_from or {}
    if _from_table(run):
        return _from_steps(path, run, settled)
    if samples.empty:
        raise ValueError(f"run {path.name} has no finite sample in samples.csv: expected the "
                         "force and pressure traces")
    samples = samples.sort_values("time_s")
    time_s = samples["time_s"].to_numpy(dtype=float)
    pressure = samples["pressure_bar"].to_numpy(dtype=float).copy()
    hold = np.full(time_s.size, -1)
    settled = settled.reset_index(drop=True).assign(
        hold_start_s=lambda s: s["start_s"] + s["settle_s"])
    pressure_se = np.full(len(settled), np.nan)
    is_ramp = imported.get("shape") == "ramp"
    rate = np.zeros(len(settled))
    for k, step in settled.iterrows():
        inside = (time_s >= step["hold_start_s"] - 1e-9) & (time_s <= step["end_s"] + 1e-9)
        hold[inside] = k
        if inside.sum() > 1:  # the monitor's noise in the hold mean (goodness of fit uses it)
            pressure_se[k] = np.std(pressure[inside], ddof=1) / np.sqrt(inside.sum())
            if is_ramp and np.ptp(time_s[inside]) > 0:
                rate[k] = np.polyfit(time_s[inside], pressure[inside], 1)[0]
        pressure[inside] = step["pressure_bar_mean"]
    settled["pressure_se_bar"] = pressure_se
    if is_ramp:
        _with_turns(pressure, samples["pressure_bar"].to_numpy(dtype=float), hold, settled)
    # the ramp into a hold does not overshoot it (first-order regulator): clip its noise too
    in_step = samples["step"].to_numpy()
    for _, step in settled.iterrows():
        ramp = (in_step == step["step"]) & (time_s < step["hold_start_s"])
        bound = step["pressure_bar_mean"]
        pressure[ramp] = (np.minimum(pressure[ramp], bound) if step["direction"] == "up"
                          else np.maximum(pressure[ramp], bound))
    if not (hold >= 0).any():
        raise ValueError(f"run {path.name}: no sample lies in a settled step's hold window")
    muscle = _muscle(run)
    tare = samples.loc[samples["phase"] == "tare", "force_N"].to_numpy(dtype=float)
    tare_se = float(np.std(tare, ddof=1) / np.sqrt(tare.size)) if tare.size > 1 else 0.0
    sha = measurement_sha256(run)
    return RunData(path=path, muscle=muscle, time_s=time_s, pressure_bar=pressure,
                   force_N=samples["force_N"].to_numpy(dtype=float), hold=hold,
                   steps=_columns(settled, "pressure_se_bar"), sha256=sha, tare_se_N=tare_se,
                   timed=not is_ramp,
                   ramp_rate_bar_per_s=rate if is_ramp else None,
                   vented_bar=_vented(run), note=note, **_instrument(run))


def _with_turns(pressure: np.ndarray, read: np.ndarray, hold: np.ndarray,
                settled: pd.DataFrame) -> None:
    """A ramp's bins, each at its mean pressure, with the pressure it turned at: where the
    sweep turns, the sample of the highest (lowest) reading of the two bins about the turn
    takes that reading, so that the friction model turns there and not at the bins' means,
    below the turn (in place)."""
    direction = settled["direction"].to_numpy()
    for k in np.flatnonzero(direction[1:] != direction[:-1]):
        around = np.flatnonzero((hold == k) | (hold == k + 1))
        pick = np.argmax if direction[k] == "up" else np.argmin
        j = around[pick(read[around])]
        pressure[j] = read[j]


def unverified_vent(run, name: str) -> str:
    """The note under which a failed run's data are used, or ``ValueError`` saying why they are
    refused.

    A run whose steps were all done and whose vent check alone failed holds complete data: the
    vent is a safety matter, said loudly as the run ended (VENT BY HAND), not one of its
    readings. They are used, with a note naming the vent problem, unless the check found an
    instrument not reading what it should (``vent_check.doubted``: the monitor reporting its
    command or stuck, the load cell stuck): that instrument recorded the steps too. A run
    that failed otherwise (an interlock, a fault, a stop before its last step) is refused.
    """
    from mkm.bench.storage import reason_shown
    from mkm.bench.vent import VentCheck

    reason = reason_shown(run.reason) or "no reason"
    check, n = run.meta.vent_check, run.meta.n_steps
    refused = f"run {name} has status failed ({reason})"
    if not n or run.meta.steps_done < n or not isinstance(check, dict) or check.get("verified"):
        raise ValueError(f"{refused}: expected a complete run to identify from")
    doubted = check.get("doubted")
    if doubted is None:  # recorded before the check said which instrument it doubted
        raise ValueError(f"{refused}: all {n} steps were done, but its vent check does not "
                         "say whether it found the monitor or the load cell not reading what "
                         "it should: expected a complete run to identify from, or one whose "
                         "vent check names no such instrument (acquire it again)")
    if doubted:
        raise ValueError(f"{refused}: all {n} steps were done, but its vent check found "
                         f"{doubted} not reading what it should, and {doubted} recorded these "
                         f"steps too: expected a run whose instruments read true; check "
                         f"{doubted} and acquire the run again")
    known = {f.name for f in fields(VentCheck)}
    vent = VentCheck(**{k: v for k, v in check.items() if k in known}).describe()
    return (f"run {name}: all {n} steps done, but its end-of-run vent was not verified "
            f"({vent}); the check doubted neither the monitor nor the load cell, which recorded "
            "the steps, so its data are used")


def _vented(run) -> tuple[float, float] | None:
    """The monitor's zero as the run's tare read it vented, and its standard error [bar]
    (:func:`mkm.bench.sequence.vented_monitor`); None where the tare recorded none (a manual
    regulator, an imported table) or the pressure was still falling."""
    tare = run.meta.tare or {}
    if not tare.get("monitor_vented_settled"):
        return None
    return float(tare["monitor_vented_bar"]), float(tare["monitor_vented_se_bar"])


def _columns(steps: pd.DataFrame, *extra: str) -> pd.DataFrame:
    """The columns of :attr:`RunData.steps`, the budget's NaN where the run recorded none."""
    budget = {c: steps[c] if c in steps else np.nan for c in ("force_u_N", "pressure_u_bar")}
    return steps[["step", "direction", "set_pressure_bar", "pressure_bar_mean", "force_N_mean",
                  "hold_start_s", "end_s", *extra]].assign(**budget)


def _tube_tolerances(tolerances) -> dict[str, float]:
    from mkm.fem.tolerances import Tolerances

    made_to = tolerances if tolerances is not None else Tolerances()
    return {"D0_mm": float(made_to.D0_mm), "t0_mm": float(made_to.t0_mm)}


def _muscle(run) -> dict:
    return run.meta.muscle.record()


def _instrument(run) -> dict:
    """The declared bounds of the run's instrument (its recorded ``loadcell`` and
    ``regulator``), the configuration's defaults where it recorded none (an imported table)."""
    from mkm.bench.budget import Instrument
    from mkm.bench.config import LoadCell, Regulator, from_record

    recorded = {s: run.meta.calibration.get(s) or {} for s in ("loadcell", "regulator")}
    regulator = from_record(Regulator, recorded["regulator"])
    offset, gain = regulator.reading_bounds()
    out = {"monitor_offset_bound_bar": offset, "monitor_gain_bound": gain,
           "monitor_zero_bound_bar": regulator.monitor_components.get("monitor_zero_bar"),
           "monitor_hysteresis_bar": regulator.monitor_components.get("monitor_hysteresis_bar",
                                                                      0.0),
           "sensitivity_tolerance": recorded["loadcell"].get(
               "sensitivity_tolerance_fraction", LoadCell.sensitivity_tolerance_fraction),
           "instrument_declared": ("monitor_accuracy_bar" in recorded["regulator"]
                                   and "max_pressure_bar" in recorded["regulator"]
                                   and "sensitivity_tolerance_fraction" in recorded["loadcell"]),
           "offset_bound_declared": any(key in recorded["regulator"] for key in (
               "monitor_accuracy_bar", "monitor_components")),
           "imported": bool(run.meta.imported_from),
           "table_sha256": (run.meta.imported_from or {}).get("sha256"),
           "published": _published(run),
           "force_step_N": None if run.meta.imported_from else Instrument.from_run(
               run.meta).lsb_N,
           "geometry_tolerance_mm": _tube_tolerances(getattr(run.meta.muscle, "tolerances",
                                                             None))}
    return {**out, **_declared_instrument(run)}


def _published(run) -> str | None:
    """The shipped published table (:func:`mkm.paths.published_tables`) whose SHA-256 the run's
    import recorded (``imported_from.sha256``: ``mkm data copy`` copies it byte for byte), by
    its file name; None for any other run."""
    sha = (run.meta.imported_from or {}).get("sha256")
    if not sha:
        return None
    from mkm.paths import published_tables

    return next((name for name, path in published_tables().items()
                 if file_sha256(path) == sha), None)


def _declared_instrument(run) -> dict:
    """An imported run's instrument from the bounds its lab declared (``mkm import
    --accuracy``): the force's share of the value as the load cell's sensitivity tolerance, the
    pressure's bound as the monitor's offset (its share of the value at the run's top pressure
    where it has no absolute part) and its share as the monitor's gain. A data sheet does not
    say which part of a bound is shared by every value and which is each value's own: the
    intervals take both readings (these drawn as shared, the fit weighed by them as each
    value's own). Empty where none was declared."""
    from mkm.bench.budget import Declared

    declared = (run.meta.imported_from or {}).get("declared_accuracy") or {}
    if not declared:
        return {}
    out: dict = {"declared": True}
    if "force" in declared:
        out["sensitivity_tolerance"] = Declared.from_record(declared["force"]).fraction
        out["instrument_declared"] = True
    if "pressure" in declared:
        bound = Declared.from_record(declared["pressure"])
        top = float(run.steps["pressure_bar_mean"].max()) if len(run.steps) else 0.0
        out["monitor_offset_bound_bar"] = bound.absolute or bound.fraction * top
        out["monitor_gain_bound"] = bound.fraction
        out["offset_bound_declared"] = True
    return out


def vented_zero(runs) -> tuple[float, float] | None:
    """The monitor's offset as the runs' vented readings measure it: ``(centre, half)`` [bar],
    the mean of the runs' vented means and how far the offset may lie from it: what a reading at
    zero cannot show (the declared non-linearity and half the hysteresis: the declared offset
    bound less its zero error), half the runs' spread (the zero drifts between runs) and
    :data:`VENTED_SE_FACTOR` standard errors of the mean. None unless every run read its monitor
    vented and declares its zero error apart (``[regulator] monitor_zero_bar``): with one
    accuracy bound, which share of it the zero holds nobody said."""
    if not runs or any(r.vented_bar is None or r.monitor_zero_bound_bar is None for r in runs):
        return None
    means = np.array([r.vented_bar[0] for r in runs])
    se = np.sqrt(sum(r.vented_bar[1] ** 2 for r in runs)) / len(runs)
    unseen = min(r.monitor_offset_bound_bar - r.monitor_zero_bound_bar for r in runs)
    half = max(unseen, 0.0) + np.ptp(means) / 2 + VENTED_SE_FACTOR * se
    return float(means.mean()), float(half)


def offset_search_bar(runs) -> tuple[float, float]:
    """Where the fit looks for the monitor's offset [bar]: about its vented reading where the
    runs measured it (:func:`vented_zero`), else within the smallest declared bound."""
    zero = vented_zero(runs)
    if zero is not None:
        return zero[0] - zero[1], zero[0] + zero[1]
    bound = min(r.monitor_offset_bound_bar for r in runs)
    return -bound, bound


def vented_beyond_bound(runs) -> str | None:
    """A note when a run's monitor read vented further from 0 than the offset bound it declares
    (beyond :data:`VENTED_SE_FACTOR` standard errors): the declaration or the monitor is wrong."""
    for run in runs:
        if run.vented_bar is None:
            continue
        mean, se = run.vented_bar
        if abs(mean) > run.monitor_offset_bound_bar + VENTED_SE_FACTOR * se:
            return (f"run {run.name}: the pressure monitor read {mean:+.4f} bar vented (the "
                    f"tare), beyond its declared bound +-{run.monitor_offset_bound_bar:g} bar: "
                    "check the monitor's zero and the regulator's accuracy in the configuration")
    return None


def offset_bound_said(runs) -> str:
    """The pressure monitor's offset bound the fit keeps to (the smallest of the runs') as the
    notes say it: declared, or the configuration's default where the run that sets it declared
    none (an imported table without ``--accuracy``, a run whose run.json records no monitor
    accuracy), with how to declare it; or the window about the runs' vented reading."""
    zero = vented_zero(runs)
    if zero is not None:
        return (f"{zero[1]:.2g} bar of its vented reading {zero[0]:+.4f} bar (the runs' tares; "
                "what a reading at zero cannot show, as declared)")
    bound = min(r.monitor_offset_bound_bar for r in runs)
    setting = [r for r in runs if r.monitor_offset_bound_bar == bound]
    if any(r.offset_bound_declared for r in setting):
        return f"its declared bound +-{bound:g} bar"
    why = ("the table declared no pressure accuracy: mkm import ... --accuracy pressure=... "
           "declares it" if any(r.imported for r in setting) else
           "the run's run.json declares no pressure monitor accuracy")
    return f"the default bound +-{bound:g} bar ({why})"


def _from_steps(path: Path, run, settled: pd.DataFrame) -> RunData:
    """An imported step table as one sample per step (see the module docstring)."""
    settled = settled.reset_index(drop=True)
    time_s = np.arange(len(settled), dtype=float)
    steps = settled.assign(hold_start_s=time_s, end_s=time_s)
    return RunData(path=path, muscle=_muscle(run), time_s=time_s,
                   pressure_bar=settled["pressure_bar_mean"].to_numpy(dtype=float),
                   force_N=settled["force_N_mean"].to_numpy(dtype=float),
                   hold=np.arange(len(settled)),
                   steps=_columns(steps),
                   sha256=measurement_sha256(run), timed=False,
                   **_instrument(run))


def load_runs(paths) -> list[RunData]:
    """The runs of one muscle family (:func:`load_run_data` each); ``ValueError`` for runs of
    different tubes (the muscle id and the length may differ, the tube's diameter and wall
    not)."""
    paths = list(paths)
    if not paths:
        raise ValueError("no run folder given: expected at least one RUN_DIR")
    runs = [load_run_data(p) for p in paths]
    first = runs[0]
    for run in runs[1:]:
        for key in SAME_MUSCLE:
            a, b = float(first.muscle[key]), float(run.muscle[key])
            if not np.isclose(a, b, rtol=SAME_MUSCLE_RTOL, atol=0.0):
                # a table imported twice, its tube declared apart (a guide's --t0 and
                # another's): their folders' names differ only by the import's time
                twice = (" (both imported from one file: keep the folders of one import)"
                         if first.table_sha256 and first.table_sha256 == run.table_sha256
                         else "")
                raise ValueError(f"runs {first.name} and {run.name} are of different muscles "
                                 f"({key}={a:g} and {b:g}): expected the runs of one tube (the "
                                 f"length may differ){twice}")
    seen: dict = {}  # a measurement's key (a SHA-256, its values' hash) -> its run
    for run in runs:
        # the same table imported twice (two folders, one measurement), a copied run folder, or
        # a run and its reprocessing (the same raw samples): counted twice, it would halve the
        # intervals and predict each run from its twin
        keys = measurement_keys(run.name, run.sha256)
        twin = next((seen[k] for k in keys if k in seen), None)
        # a table's rows imported twice and declared apart (one guide's --accuracy, another's
        # none): their steps.csv differ in the uncertainties, not in the values (two lengths
        # slack throughout may read alike)
        rows = (pd.util.hash_pandas_object(run.steps[["direction", "pressure_bar_mean",
                                                      "force_N_mean"]], index=False).sum()
                if run.imported and not slack(run.steps) else None)
        if twin is None and rows in seen:
            raise ValueError(f"runs {seen[rows].name} and {run.name} hold the same measurement "
                             "(the same pressures and forces, step by step: one table's rows "
                             "imported twice, declared apart): expected each run once; keep the "
                             "folders of one import")
        if rows is not None:
            seen[rows] = run
        if twin is not None:
            raise ValueError(f"runs {twin.name} and {run.name} hold the same measurement (their "
                             "steps.csv are identical, or one reprocesses the other's samples: "
                             "one table imported twice, a copied run folder, or a run and mkm "
                             "reprocess's folder of it): expected each run once; leave one of "
                             "them out")
        seen.update(dict.fromkeys(keys, run))
    if all(slack(r.steps) for r in runs):
        # a slack muscle (a published map at its shortest length, a bench run past its
        # threshold's reach): every model that predicts slack fits it, and nothing of the
        # muscle can be told from it
        names = ", ".join(r.name for r in runs)
        raise ValueError(f"run{'s' if len(runs) > 1 else ''} {names}: every settled force is "
                         "0 N or less, or within its uncertainty (a slack muscle): nothing to "
                         "identify the muscle from; expected a run whose force rises with the "
                         "pressure")
    return runs
