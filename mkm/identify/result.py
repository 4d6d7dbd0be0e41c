"""The identified muscle: its table, its calibration file and its record.

``--out DIR`` receives

- ``calibration.json``: the file ``--calibration`` takes. The static model's entry (``axisym``)
  holds the identified ``theta0_deg``, ``C10_MPa``, ``C01_MPa`` and the friction and creep terms
  kept (every model reads its rubber there, the ``friction`` rung its terms), with the runs,
  their hashes, the parameters and their intervals; the closed forms' entries (``eq2-inner``,
  ``eq2-braid``, ``thickwall``) hold their own theta0 fitted to the same runs as
  ``mkm fem calibrate`` fits it, with the identified rubber and terms;
- ``parameters.csv``: ``parameter,value,ci_low,ci_high,unit,status,source``: each fitted
  parameter (``fitted``, with its 95 % interval), what follows from them (``derived``) and what
  the fit took as given (``assumed``, with where from: the rubber's C01/C10 ratio where the runs
  do not separate C10 and C01, the declared wall and diameter where not fitted, the load
  cell's sensitivity tolerance); calibration.json's ``identified`` says the same in
  ``fitted: [...]`` and ``assumed: {name: source}``, with ``band``: the static parameters'
  covariance a prediction band needs (:mod:`mkm.identify.band`);
- ``steps.csv``: every settled step measured, predicted by the nominal model, by the identified
  one and held out;
- ``identification.json``: all of it (candidates, confirmation, correlation, notes, provenance).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pandas as pd

from mkm.core.records import (
    SPREADSHEET_CSV_ENCODING,
    check_output_folder,
    finite_or_null,
    provenance,
    source_version,
    spreadsheet_safe,
    write_json_atomic,
)
from mkm.fem.calibration import (
    calibration_entry,
    check_reference,
    default_target,
    fit_theta0,
    has_slope,
    store_calibration,
)
from mkm.fem.ladder import MODELS
from mkm.fem.options import BRAIDS
from mkm.identify.fitting import (
    GEOMETRY,
    STATIC_NAMES,
    Fit,
    assumed_ratio,
    declared,
    full_parameters,
    geometry,
    rubber,
)
from mkm.identify.goodness import Goodness
from mkm.identify.intervals import robust_covariance
from mkm.identify.runs import offset_bound_said

UNITS = {"theta0_deg": "deg", "C10_MPa": "MPa", "C01_MPa": "MPa", "gap_mm": "mm",
         "t0_mm": "mm", "D0_mm": "mm", "L0_mm": "mm", "pressure_offset_bar": "bar",
         "pressure_hysteresis_bar": "bar", "force_zero_N": "N",
         "rubber_scale": "x Silastic S", "C01_over_C10": "ratio",
         "loadcell_sensitivity_tolerance": "fraction",
         "hysteresis_fraction": "fraction", "creep_fraction": "fraction", "creep_tau_s": "s"}
#: what :meth:`Identification.write` writes into its folder, identification.json its record
OUTPUT_FILES = {"calibration": "calibration.json", "parameters": "parameters.csv",
                "steps": "steps.csv", "identification": "identification.json"}
TERMS = ("hysteresis_fraction", "creep_fraction", "creep_tau_s")
#: the note of runs at one eps that leave theta0 or the rubber wide, which bounds the ready
#: verdict to that eps
ONE_EPS_NOTE = "theta0 and the rubber are partly confounded by runs at one eps"
#: how the note on a rest length fitted from shortened runs alone starts
REST_EXTRAPOLATED_NOTE = "no run is held at the declared rest length"


def closed_forms() -> tuple[str, ...]:
    """The specs of every registered closed form's study variants (``eq2:diameter=inner``,
    ``eq2:diameter=braid``, ``thickwall``)."""
    return tuple(v.spec for e in MODELS.entries() if e.family == "closed form" for v in e.study)


@dataclass
class Identification:
    """What :func:`mkm.identify.procedure.identify` found (see the module docstring)."""

    runs: list
    groups: tuple[str, ...]
    fit: Fit
    bootstrap: dict
    candidates: list[dict]
    confirmation: dict
    checks: list[dict]
    notes: list[str]
    model: str
    searched_with: str
    nominal: dict
    seconds: float
    fe_workers: str = "1 worker (in-process)"  # where the FE sweeps ran
    rubber: dict = field(default_factory=dict)  # whether the runs separate C10 and C01
    files: dict = field(default_factory=dict)
    goodness: Goodness | None = None  # the misfit record (mkm.identify.goodness)
    #: the model-form terms in the intervals (mkm.identify.procedure.model_form_terms)
    model_form: dict = field(default_factory=dict)
    #: the command-line options that fit as asked again (mkm.identify.procedure.command_options)
    options: list[str] = field(default_factory=list)
    #: what the runs cannot tell from an instrument's error, each with its note (``said``) and
    #: the verdict's advice (mkm.identify.procedure.creep_or_gain)
    instrument_warnings: list[dict] = field(default_factory=list)

    @property
    def values(self) -> dict[str, float]:
        """Every parameter as the toolkit names it (fixed and dropped ones at nominal)."""
        return full_parameters(self.fit.values)

    @property
    def dropped(self) -> list[str]:
        """The friction/creep groups asked for that the information criterion dropped."""
        return [g for g in ("friction", "creep") if g in self.groups and not any(
            n in self.fit.names for n in ({"friction": ("hysteresis_fraction",),
                                           "creep": ("creep_fraction",)}[g]))]

    def parameters(self) -> pd.DataFrame:
        """``parameter, value, ci_low, ci_high, unit, status, source``: each fitted parameter
        (status ``fitted``), what follows from them (``derived``) and what the fit took as
        given (``assumed``, with where from); intervals from the bootstrap's replicates."""
        names, draws = list(self.fit.names), self.bootstrap["draws"]
        interval = self.bootstrap["interval"]
        rows = []

        def add(name, value, low=math.nan, high=math.nan, status="fitted", source="the runs"):
            rows.append((name, value, low, high, UNITS.get(name, ""), status, source))

        def replicated(function):
            """A derived parameter's interval: the draws within bounds, widened as the fitted
            ones (the misfit's Birge ratio about the estimate) and moved by each model-form
            term's shift (both ways for a symmetric one)."""
            def interval(shift):
                clipped = {n: np.clip(column + shift.get(n, 0.0), *self.fit.bounds[n])
                           for n, column in zip(names, draws.T, strict=True)}
                values = function({**self.fit.values, **clipped})
                return np.percentile(values, [2.5, 97.5])

            centre = float(function(self.fit.values))
            factor = self.goodness.birge_ratio if self.goodness else 1.0
            base = interval({})
            low, high = (centre + factor * (v - centre) for v in base)
            for term in self.model_form.values():
                if "shift" not in term:
                    continue
                d = term["shift"]
                for shift in ([d] if term["kind"] == "one-sided" else
                              [d, {n: -v for n, v in d.items()}]):
                    moved = interval(shift) - base
                    # and the estimate the term moves to: replicates past a bound (a ratio at
                    # the edge of its search) shift from beyond it
                    there = float(function({**self.fit.values, **{
                        n: float(np.clip(self.fit.values[n] + v, *self.fit.bounds[n]))
                        for n, v in shift.items() if n in self.fit.bounds}}))
                    low, high = (min(low, low + moved[0], there),
                                 max(high, high + moved[1], there))
            return float(low), float(high)

        values = self.values
        for name in names:
            value = self.fit.values[name]
            if name == "rubber_scale" and self.rubber.get("separated"):
                for k, key in enumerate(("C10_MPa", "C01_MPa")):
                    low, high = replicated(lambda v, k=k: rubber(v)[k])
                    # a search bound cuts the replicates (said in a note): the interval
                    # still holds the estimate; widened by a misfit, it stops at 0 (no rubber
                    # constant is negative)
                    add(key, values[key], max(min(low, values[key]), 0.0),
                        max(high, values[key]),
                        source=f"the runs (correlation C10-C01 "
                               f"{self.rubber_correlation():+.2f})")
            elif name == "rubber_scale":
                ratio, said = assumed_ratio(self.fit.values)
                add("rubber_scale", value, *interval[name], source="the runs: one scale on "
                    f"Silastic S's C10 + C01, at {said} ratio (a force-pressure curve carries "
                    "one stiffness)")
                why = (f"{said} ratio: the runs do not separate C10 and C01"
                       + (f" (C01/C10 95 % interval {self.rubber['ratio_ci'][0]:.3g}-"
                          f"{self.rubber['ratio_ci'][1]:.3g}, condition number "
                          f"{self.rubber['condition']:.2g}" + ratio_profile_said(self.rubber)
                          + _box_cut(self.rubber) + ")"
                          if "ratio_ci" in self.rubber else ""))
                add("C01_over_C10", ratio, status="assumed", source=why)
                for key in ("C10_MPa", "C01_MPa"):
                    add(key, values[key], status="derived",
                        source=f"rubber_scale times Silastic S's C10 + C01, at {said} "
                               "ratio")
            elif name == "c01_fraction":
                continue  # reported as C10 and C01 above
            elif name == "log_tau":
                add("creep_tau_s", math.exp(value), *np.exp(interval[name]))
            elif name == "pressure_offset_bar":
                add(name, value, *interval[name], source="nuisance: the monitor's offset within "
                    f"{offset_bound_said(self.runs)} (moves the threshold)")
            elif name == "force_zero_N":
                add(name, value, *interval[name], source="nuisance: what the load cell reads "
                    "when the muscle pulls nothing (a tare left out, a drift), one for every "
                    "run; not part of the muscle's model")
            elif name == "pressure_hysteresis_bar":
                add(name, value, *interval[name], source="nuisance: how far the monitor reads "
                    "low on a rising step and high on a falling one, within half its declared "
                    "hysteresis")
            elif name in GEOMETRY:
                add(name, value, *interval[name], source=f"the runs (declared "
                    f"{float(self.runs[0].muscle[name]):g} mm)")
            elif name == "L0_mm":
                add(name, value, *interval[name], source=f"the runs (declared "
                    f"{float(self.runs[0].muscle[name]):g} mm): each run's eps from its held "
                    "length at this rest length")
            else:
                add(name, value, *interval[name])
        for name, fitted_as in (("theta0_deg", "theta0_deg"), ("C10_MPa", "rubber_scale"),
                                ("C01_MPa", "rubber_scale")):
            if fitted_as not in names:
                add(name, values[name], status="assumed", source=(
                    "the runs' declared muscle (run.json), not fitted"
                    if declared(self.runs, name) is not None else
                    "the calibration's (--calibration, else the shipped one), not fitted: the "
                    "runs declare none"))
        for name in GEOMETRY:
            if name not in names:
                tolerance = max(r.geometry_tolerance_mm.get(name, 0.0) for r in self.runs)
                add(name, float(self.runs[0].muscle[name]), status="assumed",
                    source=f"the runs' declared muscle (run.json), +-{tolerance:g} mm its "
                           "declared tolerance, drawn into every interval")
        where = ("the load cell's declared tolerance (run.json calibration, or mkm import "
                 "--accuracy)"
                 if all(r.instrument_declared for r in self.runs) else
                 "the configuration's default load-cell tolerance (a run declares none)")
        add("loadcell_sensitivity_tolerance", self.sensitivity_tolerance, status="assumed",
            source=f"{where}: invisible to the data, drawn into every interval and prediction "
                   "band")
        return pd.DataFrame(rows, columns=["parameter", "value", "ci_low", "ci_high", "unit",
                                           "status", "source"])

    @property
    def sensitivity_tolerance(self) -> float:
        """The load cell's declared sensitivity tolerance (a fraction; the largest of the
        runs')."""
        return max(r.sensitivity_tolerance for r in self.runs)

    def _geometry_tolerances(self) -> dict[str, float]:
        """The declared wall's and diameter's tolerances drawn into the intervals (those not
        fitted)."""
        out = {n: max(r.geometry_tolerance_mm.get(n, 0.0) for r in self.runs)
               for n in GEOMETRY if n not in self.fit.names}
        return {n: t for n, t in out.items() if t > 0}

    def rubber_correlation(self) -> float:
        """The bootstrap correlation of C10 and C01 (where the runs separate them)."""
        names, draws = list(self.fit.names), self.bootstrap["draws"]
        C10, C01 = rubber({**self.fit.values, **dict(zip(names, draws.T, strict=True))})
        covariance = robust_covariance(np.column_stack([C10, C01]))
        return float(covariance[0, 1] / np.sqrt(covariance[0, 0] * covariance[1, 1]))

    def identified(self) -> dict:
        """What was fitted, what assumed and from what (calibration.json's ``identified``)."""
        table = self.parameters()
        return {"fitted": table.loc[table["status"] == "fitted", "parameter"].tolist(),
                "assumed": dict(zip(table.loc[table["status"] == "assumed", "parameter"],
                                    table.loc[table["status"] == "assumed", "source"],
                                    strict=True))}

    def band(self) -> dict:
        """What a prediction band needs (:func:`mkm.identify.band.prediction_band`): the static
        parameters' values and covariance (the bootstrap's, as its intervals see it:
        :func:`mkm.identify.intervals.robust_covariance`; the monitor's offset and the load
        cell's tolerance inside), the shift of each model-form term and each end of an assumed
        rubber ratio (``terms``: ``kind`` and ``shift``, evaluated by the band at the moved
        parameters), the load cell's tolerance itself, and on a misfit the residual the steps'
        noise does not explain (``misfit_rms_N``), the covariance widened as the intervals are
        (by the Birge ratio)."""
        names = [n for n in STATIC_NAMES if n in self.fit.names]
        index = [self.fit.names.index(n) for n in names]
        birge = self.goodness.birge_ratio if self.goodness else 1.0
        covariance = birge**2 * self.bootstrap["covariance"][np.ix_(index, index)]
        terms = [{"what": term["what"], "kind": term["kind"], "shift": term["shift"]}
                 for term in (*self.model_form.values(),
                              *self.rubber.get("assumed_ratio_terms", {}).values())
                 if "shift" in term]
        misfit = self.goodness.discrepancy_rms_N if self.goodness else 0.0
        return {"parameters": names, "values": [self.fit.values[n] for n in names],
                "covariance": covariance.tolist(), "terms": terms,
                "sensitivity_tolerance": self.sensitivity_tolerance,
                **({"misfit_rms_N": round(misfit, 4)} if misfit > 0 else {})}

    def correlation(self) -> pd.DataFrame:
        names = [{"rubber_scale": "rubber", "log_tau": "creep_tau_s"}.get(n, n)
                 for n in self.fit.names]
        return pd.DataFrame(self.bootstrap["correlation"], index=names, columns=names)

    def steps_frame(self) -> pd.DataFrame:
        frames = []
        for run, check in zip(self.runs, self.checks, strict=True):
            frame = run.steps[["step", "direction", "set_pressure_bar", "pressure_bar_mean",
                               "force_N_mean"]].assign(
                run=run.name, eps=run.eps, nominal_N=check["nominal"],
                identified_N=check["identified"])
            if "heldout" in check:
                frame = frame.assign(heldout_N=check["heldout"])
            frames.append(frame)
        table = pd.concat(frames, ignore_index=True)
        return table[["run", "eps"] + [c for c in table.columns if c not in ("run", "eps")]]

    def checks_table(self) -> pd.DataFrame:
        """Per run: largest |Err%| on each branch, nominal, identified and held out (the run
        alone, and its whole length where :func:`mkm.identify.procedure.held_out_groups` holds
        lengths out)."""
        rows = []
        for check in self.checks:
            row = {"run": check["run"], "eps": check["eps"], "L0_mm": check["L0_mm"]}
            for what in ("heldout", "length_heldout", "nominal", "identified"):
                if f"{what}_err" in check:
                    for branch in ("rising", "falling"):
                        row[f"{what}_{branch}_pct"] = check[f"{what}_err"][branch]
            rows.append(row)
        return pd.DataFrame(rows)

    def _lengths(self) -> str:
        return ", ".join(f"{v:g}" for v in sorted({float(r.muscle["L0_mm"]) for r in self.runs}))

    def predictive_table(self) -> pd.DataFrame:
        """The honest predictive error, the first table shown: each run's largest |Err%| per
        branch when held out (predicted by the FE model from the other runs, and from the
        other lengths where several were fitted). Empty with one run."""
        table = self.checks_table()
        keep = [c for c in table.columns if "heldout" in c]
        return table[["run", "eps", "L0_mm", *keep]] if keep else table.iloc[0:0]

    def record(self) -> dict:
        """Everything, as plain data (identification.json and the calibration's provenance)."""
        params = self.parameters()
        slack = self.bootstrap.get("slack_steps", 0)
        return {
            "runs": [{"run": r.name, "path": str(r.path), "muscle": r.muscle,
                      "settled_steps": len(r.steps), "sha256": r.sha256} for r in self.runs],
            "groups": list(self.groups), "dropped": self.dropped, "options": self.options,
            **self.identified(),
            "parameters": params.to_dict(orient="records"),
            "rubber": self.rubber,
            "interval_method": ("bootstrap over settled steps within each run"
                                + (f" (the {slack} steps where only the load cell's zero moves "
                                   f"the fit, the muscle slack, drawn {slack - 1} of {slack} "
                                   "among themselves)" if slack > 1 else "")
                                + f", {self.bootstrap['replicates']} replicates, linearised at the "
                                f"optimum, percentile 95 %, seed {self.bootstrap['seed']}; the "
                                f"load cell's sensitivity uniform within "
                                f"+-{self.sensitivity_tolerance:g}"
                                + "".join(f"; the declared {n} uniform within +-{t:g} mm"
                                          for n, t in self._geometry_tolerances().items())
                                + "; the pressure monitor's gain uniform within its declared "
                                  "accuracy at the regulator's top pressure"
                                + "".join(f"; {name}'s a profile where it meets a bound of its "
                                          f"search ({p['refits']} refits, chi2 risen by "
                                          f"{p['chi2_rise']:.3g} on the bootstrap's scale)"
                                          for name, p in self.bootstrap.get("profiled",
                                                                            {}).items()
                                          if p.get("widened"))
                                + (f"; widened x{self.goodness.birge_ratio:.3g} by the misfit"
                                   if self.goodness and self.goodness.birge_ratio > 1 else "")
                                + "".join(f"; extended by the model-form term {name} "
                                          f"({term['what']}, {term['kind']})"
                                          for name, term in self.model_form.items()
                                          if "shift" in term)),
            "model_form": self.model_form,
            "correlation": self.correlation().round(4).to_dict(),
            "model_selection": {"criterion": "BIC of the hold residuals",
                                "candidates": self.candidates},
            "searched_with": self.searched_with, "model": self.model,
            "fe_confirmation": self.confirmation, "notes": self.notes,
            "instrument_warnings": self.instrument_warnings,
            "goodness_of_fit": self.goodness.record() if self.goodness else None,
            "leave_one_run_out": self.checks_table().to_dict(orient="records"),
            "band": self.band(),
            "seconds": round(self.seconds, 2), "fe_workers": self.fe_workers,
        }

    def summary(self) -> str:
        """The result as a user reads it on the terminal: the held-out error first."""
        lines = [f"identified from {len(self.runs)} run(s) "
                 f"(eps {', '.join(f'{r.eps:g}' for r in self.runs)}; L0 "
                 f"{self._lengths()} mm), "
                 f"searched with {self.searched_with}, confirmed with {self.model} (FE sweeps on "
                 f"{self.fe_workers}), in {self.seconds:.1f} s"]
        held = self.predictive_table()
        if len(held):
            lines.append("  predictive error, each run predicted from the others "
                         "(largest |Err%| rising/falling):")
            # a run whose held-out fit failed has its steps: no branch is missing
            failed = {c["run"] for c in self.checks if "heldout_failed" in c}
            for row in held.to_dict(orient="records"):
                text = (f"    {row['run']} (eps {row['eps']:g}, L0 {row['L0_mm']:g} mm): "
                        + ("not predicted: the fit to the other runs failed (the note below)"
                           if row["run"] in failed else
                           _branches(row["heldout_rising_pct"], row["heldout_falling_pct"])))
                if "length_heldout_rising_pct" in row and np.isfinite(
                        row["length_heldout_rising_pct"]):
                    text += ("; its length held out "
                             + _branches(row["length_heldout_rising_pct"],
                                         row["length_heldout_falling_pct"]))
                lines.append(text)
        else:
            lines.append("  predictive error: not measured (one run: nothing to hold out)")
        for row in self.parameters().itertuples():
            interval = (f"95 % CI [{row.ci_low:.5g}, {row.ci_high:.5g}]"
                        if np.isfinite(row.ci_low) else f"{row.status:<21}")
            lines.append(f"  {row.parameter:<30} {row.value:10.5g}  {interval} {row.unit}")
        for group in self.dropped:
            lines.append(f"  {group}: not warranted by the data (BIC), dropped")
        if self.goodness is not None and self.goodness.judged:
            g = self.goodness
            declared = [r.name for r in self.runs if r.declared and not r.timed]
            against = ("their noise (the declared accuracy of the imported tables)"
                       if declared else "their own noise")
            if g.repeats:
                against += (f"{' and ' if declared else ', '}the scatter of the tables' "
                            f"repeated steps ({'; '.join(r.said() for r in g.repeats)})")
            lines.append(f"  goodness of fit: chi2/nu = {g.reduced:.3g} over "
                         f"{sum(b.steps for b in g.branches)} settled steps against {against} "
                         f"({'a misfit, see below' if g.misfit else 'within the noise'})"
                         + (f"; not judged on {', '.join(g.left_out)} (no noise: import with "
                            "--accuracy)" if g.left_out else ""))
        elif self.goodness is not None:
            lines.append(self._unjudged_line())
        for check in self.checks_table().to_dict(orient="records"):
            nominal = _branches(check["nominal_rising_pct"], check["nominal_falling_pct"])
            identified = _branches(check["identified_rising_pct"],
                                   check["identified_falling_pct"])
            lines.append(f"  {check['run']}: largest |Err%| rising/falling: nominal {nominal}, "
                         f"identified {identified}")
        lines += [f"  note: {n}" for n in self.notes]
        lines.append(self._verdict_line())
        return "\n".join(lines)

    def _verdict_line(self) -> str:
        """The last line a reader sees: whether the identified muscle can be used."""
        g = self.goodness
        if g is None or not g.judged:
            return ("verdict: not judged (the runs show no noise to judge the fit by): "
                    f"{pulls_late_first(self.groups) if g is not None and g.pulls_late else ''}"
                    "weigh the "
                    "largest |Err%| above against the instruments' accuracy before using "
                    "calibration.json")
        if not g.misfit:
            ready = ("calibration.json is ready for --calibration (mkm report, design, fem "
                     "solve)" + _one_eps_only(self) + _held_lengths_only(self))
            if self.instrument_warnings:
                return (f"verdict: the model follows these runs within their noise (chi2/nu "
                        f"{g.reduced:.3g}), but first, "
                        + "; ".join(w["verdict"] for w in self.instrument_warnings)
                        + f"; {self.instrument_warnings[-1]['ready_if']}, {ready}")
            return (f"verdict: the model follows these runs within their noise (chi2/nu "
                    f"{g.reduced:.3g}): {ready}")
        return (f"verdict: a misfit (chi2/nu {g.reduced:.3g}): the intervals are widened x"
                f"{g.birge_ratio:.3g} and the estimates may be biased; "
                f"{_first(self.rubber, g, self.groups, self.instrument_warnings)}the notes "
                "above name what the runs show "
                "that the fit "
                "lacks: act on them before using calibration.json")

    def _unjudged_line(self) -> str:
        """Without the steps' noise (a table: one value per step) no chi-square says whether
        the model fits: the line gives the largest miss on the fitted runs instead, for the
        reader to weigh against the instruments' accuracy."""
        line = f"  goodness of fit: not judged ({self.goodness.why_not})"
        checks = self.checks_table()
        if not len(checks):
            return line
        misses = checks.reindex(columns=["identified_rising_pct", "identified_falling_pct"]
                                ).astype(float).max(axis=1)
        if not np.isfinite(misses).any():
            return line
        worst = checks.loc[misses.idxmax()]
        return (f"{line}: the identified model misses its own runs by up to "
                f"{misses.max():.2f} % of their largest force (run {worst['run']}, eps "
                f"{worst['eps']:g}); weigh that against the load cell's and the table's accuracy")

    def write(self, out_dir) -> dict[str, Path]:
        """Write the four files into ``out_dir`` (created); return their paths."""
        from mkm.registry import parse_spec

        out = check_output_folder(out_dir, OUTPUT_FILES.values(), OUTPUT_FILES["identification"])
        # the calibration's reference first: runs it refuses leave no file half written
        reference = self._reference()
        out.mkdir(parents=True, exist_ok=True)
        info = provenance()
        # an assumed parameter's interval, a branch without steps: null, not NaN (no JSON)
        record = finite_or_null({**self.record(), "provenance": {
            **info, "code_version": source_version("mkm.identify.procedure", data=False)}})
        files = {key: out / name for key, name in OUTPUT_FILES.items()}
        # plain tables for a spreadsheet (a comment line reads as a row there): their
        # provenance is identification.json's
        for key, frame in (("parameters", self.parameters()), ("steps", self.steps_frame())):
            spreadsheet_safe(frame).to_csv(files[key], index=False, float_format="%.6g",
                                           encoding=SPREADSHEET_CSV_ENCODING)
        write_json_atomic(files["identification"], record)
        files["calibration"].unlink(missing_ok=True)  # one identification per file
        values = self.values
        material = {"C10_MPa": round(values["C10_MPa"], 6), "C01_MPa": round(values["C01_MPa"], 6)}
        terms = {k: round(values[k], 6) for k in TERMS if self._fitted_term(k)}
        static = parse_spec(self.model).with_params(L0_mm=float(self.runs[0].muscle["L0_mm"]))
        gap = {"gap_mm": round(values["gap_mm"], 6)} if "gap_mm" in values else {}
        model = static.build(theta0_deg=values["theta0_deg"], **material, **gap)
        identified = {"runs": record["runs"], "fitted": record["fitted"],
                      "assumed": record["assumed"], "parameters": record["parameters"],
                      "interval_method": record["interval_method"], "dropped": self.dropped,
                      "notes": self.notes, "leave_one_run_out": record["leave_one_run_out"],
                      "misfit": record["goodness_of_fit"], "band": record["band"],
                      "model_form": record["model_form"], "options": record["options"],
                      "instrument_warnings": record["instrument_warnings"]}
        entry = {**_entry(values["theta0_deg"], model, static.entry.module, reference),
                 **material, **gap, **terms, "target": "identify", "identified": identified}
        store_calibration(files["calibration"], model.calibration_key, entry)
        for spec in closed_forms():  # their theta0 fitted again to the runs
            closed = parse_spec(spec).with_params(L0_mm=float(self.runs[0].muscle["L0_mm"]))
            key = closed.build(theta0_deg=30.0).calibration_key
            if key == model.calibration_key:  # the identified model's own entry stays
                continue
            rubber = material if "C10_MPa" in closed.entry.parameters else {}
            target = default_target(closed.build(theta0_deg=30.0))
            used = self.runs if target == "force" else self._rising()
            if not used:
                continue
            fit = fit_theta0(lambda th, s=closed, m=rubber: s.build(theta0_deg=th, **m),
                             self._reference(used), target=target)
            built = closed.build(theta0_deg=fit["theta0_deg"], **rubber)
            entry = calibration_entry(fit, built, ", ".join(r.name for r in used), None,
                                      closed.entry.module)
            store_calibration(files["calibration"], key, {
                **entry, **material, **terms,
                "reference_sha256": {r.name: r.sha256.get("steps.csv") for r in used}})
        self.files = files
        return files

    def _fitted_term(self, key: str) -> bool:
        group = "friction" if key == "hysteresis_fraction" else "creep"
        return group in self.groups  # a dropped term is written as 0: the rung must not add it

    def _rising(self) -> list:
        """The runs whose force rises above its threshold: a closed form's slope is fitted to
        these alone (a run slack at every pressure, as a published table's shortest length
        is, has no slope to fit), judged on what the fit is given (:meth:`_reference`: the
        turning point left out, so a run that pulls at its top step alone has none either)."""
        rising = []
        for run in self.runs:
            try:
                if has_slope(self._reference([run])):
                    rising.append(run)
            except ValueError:  # fewer than two pressures measured both ways
                continue
        return rising

    def _reference(self, runs=None) -> pd.DataFrame:
        """The settled steps of ``runs`` (default: every run) as a calibration reference (both
        branches)."""
        frames = [run.steps.assign(D0_mm=geometry(run, self.fit.values)[0],
                                   t0_mm=geometry(run, self.fit.values)[1], eps=run.eps,
                                   L0_mm=float(run.muscle["L0_mm"]))
                  .rename(columns={"pressure_bar_mean": "pressure_bar",
                                   "force_N_mean": "force_N"}) for run in runs or self.runs]
        table = pd.concat(frames, ignore_index=True)
        return check_reference(table[["pressure_bar", "set_pressure_bar", "D0_mm", "t0_mm",
                                      "eps", "L0_mm", "force_N", "direction"]],
                               "the runs' settled steps")


def _entry(theta0_deg: float, model, module: str, reference: pd.DataFrame) -> dict:
    """The provenance fields every calibration entry has, for the identified model."""
    info = provenance()
    prediction = model.predict(*(reference[c].to_numpy() for c in
                                 ("pressure_bar", "D0_mm", "t0_mm", "eps")))
    residual = prediction.force_N - reference["force_N"].to_numpy()
    return {"theta0_deg": round(float(theta0_deg), 4), "reference": "bench runs (identify)",
            "rmse_N": round(float(np.sqrt(np.mean(residual**2))), 4),
            "max_abs_residual_N": round(float(np.max(np.abs(residual))), 4),
            "model_params": {k: v for k, v in model.params().items() if k != "theta0_deg"},
            "command": info["command"], "date_utc": info["date_utc"],
            "code_version": source_version(module, data=False), "git": info["git"],
            "versions": info["versions"]}


def _one_eps_only(result) -> str:
    """Where the runs are at one eps and leave theta0 or the rubber wide: that the ready
    calibration is of that eps (elsewhere the angle and rubber it traded give other
    forces), and what makes it the muscle's."""
    if not any(note.startswith(ONE_EPS_NOTE) for note in result.notes):
        return ""
    eps = sorted({round(r.eps, 4) for r in result.runs})
    table = result.parameters().set_index("parameter")
    wide = ", ".join(f"{name} {table.at[name, 'ci_low']:.3g} to {table.at[name, 'ci_high']:.3g}"
                     f" {table.at[name, 'unit']}" for name in ("theta0_deg", "rubber_scale")
                     if name in table.index and np.isfinite(table.at[name, "ci_low"]))
    return (f" at eps {', '.join(f'{e:g}' for e in eps)}; at another eps, identify it with "
            f"a run there too: one eps leaves the braid angle and the rubber traded against "
            f"each other (95 % CI {wide})")


def _held_lengths_only(result) -> str:
    """Where the rest length was fitted from shortened runs alone: that the ready calibration
    is of their held lengths, and what makes it the muscle's at its rest length."""
    if not any(note.startswith(REST_EXTRAPOLATED_NOTE) for note in result.notes):
        return ""
    held = sorted(r.held_mm for r in result.runs)
    return (f" at the held lengths {held[0]:.4g}-{held[-1]:.4g} mm; its rest length is "
            "extrapolated (the note on it above): identify with a run held at the rest length "
            "among them before predicting there")


def _branches(rising_pct: float, falling_pct: float) -> str:
    """``0.50/1.20``; a branch without a settled step is said so, not printed as nan (a run
    aborted on its way up has no falling step)."""
    shown = [f"{v:.2f}" if np.isfinite(v) else f"none ({name} step)"
             for v, name in ((rising_pct, "no rising"), (falling_pct, "no falling"))]
    return "/".join(shown)


def ratio_profile_said(rubber: dict) -> str:
    """Where C01's share met a bound of its search and its interval is a profile one
    (:func:`mkm.identify.procedure.profile_at_bounds`) wider than the bootstrap's, or ''."""
    profiled = rubber.get("ratio_profile")
    if not profiled or not profiled.get("widened"):
        return ""
    return (f"; a profile interval: C01's share meets a bound of its search, where the "
            f"bootstrap's collapses, so it was held at {profiled['refits']} values, the rest "
            "refitted")


def _box_cut(rubber: dict) -> str:
    """Where the box searched stopped the ratio's interval (open there), or ''."""
    cut = rubber.get("ratio_box_cut")
    return (f"; open where the {rubber['searched_with']}'s box stopped the search, at C01/C10 "
            + " and ".join(f"{r:.3g}" for r in cut) if cut else "")


def _first(rubber: dict, goodness, groups, cautions=()) -> str:
    """What a misfit's verdict says first: a run declared at its rest length that pulls later
    than the fitted model (a rest length or a gap the runs do not declare: a misfit so large
    that the braid or the rubber's ratio, which barely move the threshold, are read from it
    too: :func:`pulls_late_first`, ``groups`` what was fitted), else :func:`ratio_first`; a
    frame yielding under the muscle's pull before both where it explains the misfit
    (:func:`mkm.identify.procedure.frame_hint`; fibres that stretch in its place, or both
    where the data do not tell them apart), after the other braid where that takes the
    creep's place (it needs no bench to try); a lag between the monitor and the muscle
    before all (``cautions``' :func:`mkm.identify.procedure.lag_hint`): a fit with friction for
    the lag's loop; so does a first rise stiffer than its repeats
    (:func:`mkm.identify.procedure.softening_hint`)."""
    before_all = [c["verdict"] for c in cautions
                  if c["what"] in ("lag between monitor and muscle", "first-cycle softening")]
    if before_all:
        return f"first, {before_all[0]}; then "
    # a braid other than the model's also pulls less the more it pulls (a sliding sleeve named
    # a frame lowering chi2 by 522 where the braid lowered it by 515; named fibres of 0.08 %):
    # the braid is tried without the bench, so first
    braid = next((c["other_braid"]["braid"] for c in cautions
                  if c["what"] == "braid, creep or load cell gain"), None)
    published = (goodness.frame or goodness.fibres or {}).get("published_table")
    if goodness.frame and goodness.fibres:
        lacks = ("a yielding frame or stretching fibres (the data do not tell them apart: "
                 f"about {goodness.frame['stiffness_N_per_mm']:.3g} N/mm or "
                 f"{100 * goodness.fibres['strain_at_largest_tension']:.2g} % at the largest "
                 "tension, the notes above)")
        fix = (_ask_authors("their frame's stiffness and their braid's fibres", "either")
               if published else
               "check the frame's stiffness and measure the fibres, then identify again; then ")
    elif goodness.frame and published:
        lacks = (f"a frame yielding under the muscle's pull on the bench {published} was "
                 f"measured on (about {goodness.frame['stiffness_N_per_mm']:.3g} N/mm: the note "
                 "above)")
        fix = _ask_authors("their frame's stiffness or the held lengths under load", "it")
    elif goodness.frame:
        lacks = (f"a frame yielding under the muscle's pull (about "
                 f"{goodness.frame['stiffness_N_per_mm']:.3g} N/mm: the note above)")
        fix = ("stiffen the frame or measure its stiffness, or measure the muscle's held length "
               "under load, and identify again; then ")
    elif goodness.fibres:
        lacks = ("a braid whose fibres stretch under their tension (about "
                 f"{100 * goodness.fibres['strain_at_largest_tension']:.2g} % at the largest: "
                 "the note above)")
        fix = (_ask_authors("their braid's fibres", "it") if published else
               "measure the braid's fibres or use a stiffer braid, and check the frame's "
               "stiffness, then identify again; then ")
    else:
        return (pulls_late_first(groups) if goodness.pulls_late
                else ratio_first(rubber, goodness.ratio_freed))
    if braid is not None:
        return (f"first, a {braid} braid (the braid, creep or load cell note above) or {lacks} "
                f"may be what the fit lacks: identify again with --braid {braid}; if the misfit "
                f"stays, {fix}")
    return f"first, {lacks} may be what the fit lacks: {fix}"


def _ask_authors(what: str, fitted_with: str) -> str:
    """What a verdict says to do about a frame or fibres of a published table's bench, which
    its reader can neither stiffen nor measure: ask its authors for ``what``."""
    return (f"ask the table's authors for {what}, else predict with the intervals, which hold "
            f"the muscle fitted with {fitted_with}; then ")


def pulls_late_first(groups) -> str:
    """What a verdict says first where a run declared at its rest length pulls later than the
    fitted model, judged or not (a table's fit is not, and its threshold misses as far): the
    ``--params`` that fit its rest length or a gap besides ``groups``, as the note gives them."""
    given = ",".join(groups)
    return ("first, a run declared at its rest length pulls later than the fitted model (the "
            f"note above): fit its rest length (--params {given},L0) or a gap (--params "
            f"{given},gap) and identify again, before reading the braid or the rubber's ratio "
            "from this fit; then ")


def ratio_first(rubber: dict, freed: dict | None = None) -> str:
    """What a misfit's verdict says first when the rubber's ratio was not tested as the runs
    can test it: the runs reject the assumed ratio but one rubber scale at it was kept
    because the braid is in doubt (a braid the model does not have bends the curve as another
    ratio would; the braid given, the ratio is fitted) or the bench's declared tolerances; or
    when the ratio freed (``freed``: :attr:`mkm.identify.goodness.Goodness.ratio_freed`) takes
    the misfit away though the runs do not pin it; else ''."""
    if rubber.get("rejects_silastic_ratio_but_for_declared") and not rubber.get("separated"):
        return (f"first, the runs want a rubber ratio other than {rubber['assumed_from']}, "
                "kept only "
                "because of the bench's declared tolerances (the note on C10 and C01): where "
                "they are known closer, declare them and identify again; then ")
    if rubber.get("separated"):
        return ""
    if rubber.get("rejects_silastic_ratio") and rubber.get("braid_in_doubt"):
        return (f"first, the runs reject {rubber['assumed_from']} rubber ratio, kept only "
                "because the braid is not given: identify again with the muscle's braid ("
                f"{' or '.join(f'--braid {b}' for b in BRAIDS)}) and the ratio is fitted; then ")
    if not (freed and freed["within_noise"]):
        return ""
    low, high = freed["ratio_ci"]
    return (f"first, the rubber's C01/C10 held at {freed['assumed_from']} "
            f"{freed['assumed']:.3g} may be "
            f"what the fit lacks: freed (to {freed['ratio']:.3g}) the model follows these runs "
            f"within their noise (chi2/nu {freed['chi2_per_nu']:.3g}), though they do not pin "
            f"the ratio (95 % interval {low:.3g}-{high:.3g}), so one rubber scale at "
            f"{freed['assumed_from']} ratio is reported, its intervals widened by the misfit "
            "(a bench error that bends the curve, the monitor's gain say, can look the same); "
            "then ")
