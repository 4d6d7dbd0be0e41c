"""The validation report: bench runs against every force model, as one self-contained HTML file.

:func:`build_report` loads runs with :func:`mkm.bench.storage.load_run`, predicts each run's steps
with
the requested models (FE predictions through :mod:`mkm.prediction_cache`), scores them with the
paper's Equation 7 against the measurement and writes ``report.html`` (figures embedded as base64
PNG, inline CSS, no script, no external asset) with the PNGs, CSVs and ``provenance.json``
beside it. The page answers, in this order:

1. the verdict, per run, in one sentence (:mod:`mkm.verdict`: the model to use, how far, how
   fast, consistent or not, and ``auto``'s pick reconciled with it), then how good: a summary
   table (status, eps, every model's largest |Err%|, RMSE and time per force, lost samples, the
   ``auto`` choice);
2. the runs of one muscle together (the paper's Figure 7c/d: eps 0 and 12.2 %, every model);
3. how fast: seconds per predicted force against the largest |Err%| of every model on these runs,
   and the one model ``auto`` picks for each run;
4. per run: the set-up as tables (muscle, hardware, calibration, tare), pressure and force
   against time with the settling and averaging windows, gaps and interlock events, forces with
   each model's uncertainty band, Err% and residuals in N;
5. the surrogate against our FE model on the paper's test muscles (Table 3, Figure 6);
6. provenance, folded, the full JSON in ``provenance.json``.

Each model has one name, its registry label (:attr:`mkm.registry.Spec.display_name`), in every
sentence, table and figure; every table and figure names the provenance entries it was computed
from.
"""

from __future__ import annotations

import dataclasses
import json
import math
import re
import time
import warnings
from dataclasses import dataclass, field
from functools import partial
from pathlib import Path

import numpy as np
import pandas as pd

from mkm.auto import RANGE_SPEC, REFERENCE_SPEC
from mkm.core.records import (
    SPREADSHEET_CSV_ENCODING,
    provenance,
    read_prediction_header,
    save_figure,
    spreadsheet_safe,
    staged_folder,
    write_json_atomic,
)
from mkm.fem.calibration import CalibratedTheta0, Calibration
from mkm.fem.muscle import Muscle, eps_at_rest_length
from mkm.fem.paper import TABLE3_CSV
from mkm.fem.tolerances import Tolerances
from mkm.figures import (
    model_colours,
    overlay_figure,
    report_speed_figure,
    run_figure,
    surrogate_fe_figure,
    time_figure,
)
from mkm.html import (
    esc,
    figure_html,
    html_page,
    mapping_table,
    provenance_details,
    provenance_links,
    table_html,
)
from mkm.identify.page import report_section
from mkm.paths import check_writable, default_out
from mkm.prediction_cache import (
    DEFAULT_CACHE_DIR,
    cached_predict,
    model_origin,
    model_version,
)
from mkm.progress import phase, progress_bar
from mkm.registry import REPORT_MODELS, Spec, entries, parse_spec
from mkm.scoring import evaluation_pressures, predict_steps, score_run, summarise_run
from mkm.uncertainty import force_band, with_band
from mkm.verdict import (
    NO_BUDGET,
    NO_BUDGET_IMPORTED,
    AutoPick,
    advice_command,
    format_seconds,
    friction_explains,
    gives_advice,
    model_label,
    muscle_advice,
    not_carried_over,
    recommend,
    verdict,
)


@dataclass
class _Run:
    """One loaded and scored run, as the sections of the page use it."""

    k: int
    run: object  # bench.storage.Run
    specs: list[Spec]
    #: the models' default angles and rubber (None: the shipped ``fem/calibration.json``)
    calibration: Calibration | None = None
    scored: pd.DataFrame = field(default_factory=pd.DataFrame)
    summary: list[dict] = field(default_factory=list)
    keys: list[str] = field(default_factory=list)
    auto_choices: dict = field(default_factory=dict)  # tolerance -> AutoPick or None
    #: spec text -> the spec whose model answered in its place (:func:`_score`)
    in_place: dict = field(default_factory=dict)
    #: the identify options its advice gives (:func:`_advice_options`), once read, and what
    #: they were read from (the options asked and the run folders): runs alike share them
    advice_options: list[str] | None = None
    advice_from: tuple | None = None
    #: what names its measurement (:func:`_measurement`), once read
    measurement: frozenset[str] | None = None

    @property
    def name(self) -> str:
        return Path(self.run.path).name

    @property
    def meta(self):
        return self.run.meta

    @property
    def muscle(self) -> Muscle:
        return self.meta.muscle

    @property
    def predicted(self) -> Muscle:
        """The muscle the models predict: the run's, with the wall and diameter the
        calibration identified where it identified them on this muscle (its braid angle and
        rubber were fitted together with them: with the declared wall they miss its own runs),
        and the angle and rubber it declares left to the calibration there (each model takes
        its own entry, fitted on this muscle's runs)."""
        if not _identified_muscle(self.calibration, self.muscle):
            return self.muscle
        return dataclasses.replace(self.muscle, **_identified_geometry(
            self.calibration, self.muscle), **dict.fromkeys(DECLARED_MATERIAL))

    @property
    def eps_pct(self) -> float:
        return 100.0 * self.muscle.eps

    @property
    def label(self) -> str:
        return f"run {self.k}, eps = {self.eps_pct:.1f} %"


# --- the report -------------------------------------------------------------------------------


def default_models(calibration: Calibration | None = None) -> list[Spec]:
    """:data:`REPORT_MODELS` less those that cannot take their defaults from ``calibration``
    (a muscle identified with the thick-wall form has no FE entry, which the FE model and the
    surrogate read); each left out is said in a warning naming the reason."""
    specs = [parse_spec(text) for text in REPORT_MODELS]
    if calibration is None:
        return specs
    kept = []
    for spec in specs:
        try:
            reason = missing_angle(spec, calibration)
            if reason is None and spec.name != "surrogate":
                spec.build(calibration).params()
        except ValueError as exc:
            reason = str(exc)
        if reason is not None:
            warnings.warn(f"{spec.text} left out of the report: {reason}; or name the models "
                          "with --models", stacklevel=2)
            continue
        kept.append(spec)
    return kept


def missing_angle(spec: Spec, calibration: Calibration | None) -> str | None:
    """Why ``calibration`` gives ``spec`` no braid angle, with the remedy in the report's
    terms (it has no --theta0: the angle goes into the spec); None when it gives one, the spec
    names its own or the model takes none from it."""
    if calibration is None or "theta0_deg" in dict(spec.params):
        return None
    if spec.name == "surrogate":  # the FE's entry, read without loading (or training) it
        key = "axisym"
    else:
        model = spec.build(calibration)
        model = getattr(model, "static_model", model)  # friction's angle is its static rung's
        if not isinstance(model, CalibratedTheta0) or model.theta0_deg is not None:
            return None
        key = model.calibration_key
    if key in calibration.entries:
        return None
    return calibration.missing(
        key, f"--models {spec.text}{',' if spec.params else ':'}theta0_deg=")


def report_folder(out_dir, run_dirs) -> Path:
    """Where :func:`build_report` writes: ``out_dir``, else ``mkm-out/report/<first run>``."""
    return Path(out_dir) if out_dir else default_out("report", Path(run_dirs[0]).name)


def build_report(run_dirs, models=None, out_dir=None,
                 cache_dir: Path | str | None = DEFAULT_CACHE_DIR,
                 tolerance: float | None = 0.02, surrogate_section: bool = True,
                 progress: bool = False, calibration: Calibration | None = None,
                 notify=None) -> Path:
    """Write ``report.html`` (plus PNGs, CSVs and ``provenance.json``) for bench runs into
    ``out_dir``; return its path.

    Parameters
    ----------
    run_dirs : list of path
        Run folders written by ``mkm acquire`` (real or simulated; aborted ones included).
    models : iterable of str or Spec, optional
        Predictor specs (``eq2``, ``thickwall``, ``axisym:mesh=coarse``, ``surrogate``,
        ``surrogate:path=DIR``), drawn in this order; default :func:`default_models` (those
        of :data:`REPORT_MODELS` the calibration serves).
    out_dir : path, optional
        Output folder (default ``mkm-out/report/<first run folder name>``).
    cache_dir : path or None
        FE prediction cache (None: no cache).
    tolerance : float or None
        Tolerance of the ``auto`` model choice shown per run (a fraction); None leaves it out.
    surrogate_section : bool
        Add the comparison of the default surrogate with the FE model on the test muscles.
    progress : bool
        Progress bar on stderr (shown only when stderr is a terminal).
    calibration : Calibration, optional
        The models' default braid angles and rubber, and the identified muscle shown (None:
        the shipped ``fem/calibration.json``).
    notify : callable, optional
        Called with each line of the first screen's verdict in plain text once the report is
        written (:func:`verdict_lines`): what a terminal shows before the report's path.
    """
    start = time.perf_counter()
    run_dirs = [Path(p) for p in run_dirs]
    if not run_dirs:
        raise ValueError("no run folder given: expected at least one RUN_DIR")
    specs = (default_models(calibration) if models is None
             else [m if isinstance(m, Spec) else parse_spec(m) for m in models])
    for spec in specs if models is not None else ():
        reason = missing_angle(spec, calibration)
        if reason is not None:  # refused before any work
            raise ValueError(f"--models {spec.text}: {reason}")
    out = check_writable(report_folder(out_dir, run_dirs), folder=True)
    try:  # written beside out, moved in whole: a full disk or a Ctrl-C leaves nothing partial
        with staged_folder(out, last="report.html", record="provenance.json",
                           replaces=_files_written(out)) as stage:
            lines = _write_report(run_dirs, specs, stage, cache_dir, tolerance,
                                  surrogate_section, progress, start, calibration)
    except OSError as exc:
        where = exc.filename2 or exc.filename  # the file asked for, not its temporary
        raise ValueError(f"the report was not written ({exc.strerror or type(exc).__name__}"
                         f"{f': {where}' if where else ''}); {out} is as it was") from None
    for line in lines if notify else ():
        notify(line)
    return out / "report.html"


def _files_written(out: Path) -> list[str]:
    """The files the report in ``out`` wrote there (its provenance.json's ``output``), to go
    where this one does not write them again; none when there is no report or it is unread."""
    try:
        files = json.loads((out / "provenance.json").read_text(encoding="utf-8"))["output"]["files"]
    except (OSError, ValueError, KeyError, TypeError):
        return []
    return [f for f in files if isinstance(f, str)] if isinstance(files, list) else []


def _write_report(run_dirs, specs, out: Path, cache_dir, tolerance, surrogate_section,
                  progress, start, calibration: Calibration | None) -> list[str]:
    """Write the report into ``out``; return its verdict in plain text (:func:`verdict_lines`)."""
    from mkm.bench.storage import load_run

    names = {s.text: s.display_name for s in specs}
    colours = model_colours(specs)
    # the calibration the models took their angles and rubber from, named by its content
    prov: dict[str, dict] = {"software": provenance(),
                             "calibration": (calibration or Calibration.shipped()).record()}
    bar = progress_bar(len(run_dirs) * (len(specs) + 1) + int(surrogate_section), "report",
                       progress, unit="task")
    runs, models = [], {}  # one model per spec and rest length for the whole report
    for k, run_dir in enumerate(run_dirs, start=1):
        runs.append(_score(_Run(k, load_run(run_dir), specs, calibration), cache_dir, prov, bar,
                           models))
    in_place = [r.k for r in runs if REFERENCE_SPEC in r.in_place]
    if in_place:
        warnings.warn(f"run{'s' if len(in_place) > 1 else ''} {', '.join(map(str, in_place))}: "
                      f"the default surrogate's box does not cover the muscle; the practical "
                      f"range's ({RANGE_SPEC}) is scored as {REFERENCE_SPEC!r}", stacklevel=2)
    other = _calibration_of_another_muscle(runs)
    if other:
        warnings.warn(other, stacklevel=2)
    summary = pd.DataFrame([{"run": r.name, **row} for r in runs for row in r.summary])
    spreadsheet_safe(summary).to_csv(out / "summary.csv", index=False, float_format="%.6g",
                                     encoding=SPREADSHEET_CSV_ENCODING)

    sections = [_summary_section(runs, summary, names, tolerance),
                _overlay_section(runs, out, names, colours),
                _speed_section(runs, summary, out, names, colours, tolerance)]
    for r in runs:
        sections.append(_run_section(r, out, names, colours, prov))
        bar.update(1)
    sections.append(report_section(run_dirs, out, calibration))
    if surrogate_section:
        sections.append(_surrogate_section(out, prov))
        bar.update(1)
    bar.close()
    prov["output"] = {"files": sorted([p.name for p in out.iterdir()]
                                      + ["provenance.json", "report.html"])}
    write_json_atomic(out / "provenance.json", prov)
    elapsed = time.perf_counter() - start
    intro = (f"<p>Generated {esc(prov['software']['date_utc'])} by "
             f"<code>{esc(prov['software']['command'])}</code> in {elapsed:.1f} s: "
             f"{len(runs)} run(s), {len(specs)} model(s). Err% is the paper's Equation 7, "
             "(F_meas − F_model) / max F_meas over the run, in %; the residual is "
             "F_meas − F_model in N. A point where a model gives no valid number (invalid, out "
             "of its domain, not converged) is drawn as a cross above the axes, never as a "
             "force, and left out of every number. Times are per predicted force.</p>")
    body = intro + "".join(sections) + provenance_details(prov, "provenance.json")
    (out / "report.html").write_text(html_page("McKibben muscle validation report", body),
                                     encoding="utf-8")
    return verdict_lines(runs, names, tolerance)


def verdict_lines(runs: list[_Run], names: dict, tolerance: float | None) -> list[str]:
    """The first screen's verdicts in plain text, as the page says them: each run's sentence,
    then each identify command several of them advise, once, with the runs it concerns."""
    shared = _shared_commands(runs, names, tolerance)
    return ([_verdict(r, names, tolerance, runs, r.k in shared) for r in runs]
            + [said + command for said, command in _advice(runs, shared)])


def _score(r: _Run, cache_dir, prov: dict, bar, models: dict) -> _Run:
    """Predict and score every model on the run's kept steps; record provenance."""
    meta, muscle = r.meta, r.predicted
    run_key = f"run-{r.k}"
    prov[run_key] = {"path": str(r.run.path), "sha256": r.run.sha256(),
                     **{key: meta.get(key) for key in ("provenance", "command", "config_source",
                                                       "config_sha256", "config_overrides")
                        if meta.get(key)}}
    r.keys = [run_key]
    steps = r.run.steps
    if steps.empty:
        bar.update(len(r.specs))
        return r
    frames = []
    built_for = tuple(sorted(muscle.model_parameters().items()))
    for spec in r.specs:
        built = spec
        model = _model(models, spec, built_for, r, bar)
        pred, cached = predict_steps(model, steps, muscle, cache_dir, _pressure_tolerance(meta))
        if spec.text == REFERENCE_SPEC and not pred.valid.all():
            # outside the default's box at a step: the practical range's surrogate answers in
            # its place where it covers every step, under the same name (as auto's reference
            # does)
            wider = parse_spec(RANGE_SPEC)
            try:
                candidate = _model(models, wider, built_for, r, bar)
            except ValueError:  # a muscle parameter it was not trained on either
                candidate = None
            if candidate is not None:
                answer = predict_steps(candidate, steps, muscle, cache_dir,
                                       _pressure_tolerance(meta))
                if answer[0].valid.all():
                    built, model, (pred, cached) = wider, candidate, answer
                    r.in_place[spec.text] = wider.text
        pred, band = _with_band(_held(pred, model, built, r), model, built, r, cache_dir)
        rows = score_run(steps, pred, spec.text)
        frames.append(rows)
        r.summary.append(summarise_run(rows, pred.seconds, cached))
        key = f"model-{spec.text}"
        prov[key] = {"model": model.name, "params": pred.params, "version": model_version(model),
                     **model_origin(model), "band": band.record()}
        r.keys.append(key)
        bar.update(1)
    r.scored = pd.concat(frames, ignore_index=True)
    return r


def _held(pred, model, spec: Spec, r: _Run):
    """``pred`` of a rung with friction and creep (``friction``, whose spec leaves its branch
    and hold free) as the run held it: each settled step's mean over its hold of the force along
    the run's pressure trace, friction and creep carried from step to step, as identify
    predicts its steps (:meth:`mkm.fem.friction.FrictionCreep.history`); a step off that trace
    (not settled, an imported table) on the branch it was measured on. Its rising branch
    scored at every step missed a falling one by twice the friction."""
    from mkm.identify.runs import load_run_data

    given = dict(spec.params)
    if not hasattr(model, "history") or {"direction", "hold_s"} & set(given):
        return pred
    steps = r.run.steps
    down = (steps["direction"] == "down").to_numpy()
    force = np.where(down, pred.extras["force_falling_N"], pred.extras["force_rising_N"])
    try:
        data = load_run_data(r.run.path)
        muscle = r.predicted
        trace = model.history(data.time_s, data.pressure_bar, muscle.D0_mm, muscle.t0_mm,
                              muscle.eps) if data.timed else None
    except ValueError:  # no trace to follow (no settled hold, no valid static force)
        trace = None
    if trace is not None:
        held = dict(zip(data.steps["step"].astype(int), data.step_means(trace), strict=True))
        force = np.array([held.get(int(step), f) for step, f in zip(steps["step"], force,
                                                                     strict=True)])
    return dataclasses.replace(pred, force_N=np.where(np.isfinite(pred.force_N), force,
                                                      pred.force_N))


def _model(models: dict, spec: Spec, built_for: tuple, r: _Run, bar):
    """``spec``'s model of the run's muscle, built once per report (a surrogate loads in about
    a second: once will do)."""
    if (spec, built_for) not in models:
        training = _announce_training(spec, bar)
        models[spec, built_for] = spec.build(r.calibration, r.predicted)
        if training:  # its own estimate was given: the tasks' time left leaves it out
            bar.unpause()
    return models[spec, built_for]


def _with_band(pred, model, spec: Spec, r: _Run, cache_dir):
    """``pred`` with the band of the muscle's tolerances (``force_u_N``, :mod:`mkm.uncertainty`;
    the run's recorded tolerances, else the defaults), FE sweeps through the cache, and the
    band (:class:`mkm.uncertainty.Band`)."""
    muscle = r.predicted
    recorded = (r.meta.get("calibration") or {}).get("muscle_tolerances") or {}
    try:
        tolerances = Tolerances(**{k: v for k, v in recorded.items()
                                   if k in Tolerances.__dataclass_fields__})
    except (TypeError, ValueError):
        tolerances = Tolerances()
    known = entries().get(model.name)

    def predict(m, *args):
        if known is not None and known.expensive:
            return cached_predict(m, *args, cache_dir=cache_dir)[0]
        return m.predict(*args)

    band = force_band(model, pred.pressure_bar, muscle.D0_mm, muscle.t0_mm, muscle.eps,
                      tolerances, predict=predict,
                      rebuild=lambda **params: spec.with_params(**params).build(r.calibration,
                                                                                muscle))
    return with_band(pred, band), band


def _announce_training(spec: Spec, bar) -> bool:
    """Name the one long step of a first report before it starts, training the surrogate, with
    this machine's last time for it (:mod:`mkm.core.durations`); True if it trains."""
    if spec.name != "surrogate" or dict(spec.params).get("path"):
        return False
    from mkm.core.durations import estimate
    from mkm.surrogate.train import is_cached, training_task

    kind = str(dict(spec.params).get("kind", "best"))
    if is_cached(kind):
        return False
    phase("report", f"training the {kind} surrogate on first use, "
                    f"{estimate(training_task(kind))}; cached for every later command",
          not getattr(bar, "disable", False))
    return True


def _pressure_tolerance(meta) -> float:
    """The run's regulator settling tolerance [bar] (0 if not recorded)."""
    settle = (meta.get("sequence") or {}).get("settle", {})
    return float(settle.get("pressure_tolerance_bar", 0.0) or 0.0)


def _plain(text) -> str:
    """``text`` shown literally in a matplotlib title: ``$...$`` in a recorded muscle id would
    otherwise be parsed as mathtext (and crash on bad TeX)."""
    return str(text).replace("$", r"\$")


def _planned_steps(meta) -> str:
    """Steps planned (``RunMeta`` reads it from every run.json schema)."""
    return "an unrecorded number planned" if meta.n_steps is None else str(meta.n_steps)


def _cell(value) -> str:
    """A table cell's text: an absent value (no step has an E_n) is the table's dash, never
    ``None``."""
    return "—" if value is None or (isinstance(value, float) and np.isnan(value)) else str(value)


def _status_html(r: _Run) -> str:
    status = str(r.run.status)
    cls = "ok" if r.run.complete else "bad"
    return f'<span class="{cls}">{esc(status)}</span>'


# --- sections ---------------------------------------------------------------------------------


def _summary_section(runs: list[_Run], summary: pd.DataFrame, names: dict,
                     tolerance: float | None) -> str:
    """The first screen: what the runs are (simulated or measured, past the braid lock), then
    every model's largest |Err%|, RMSE and time per force for every run in one table, the
    model ``auto`` picks for each run, then each run's status."""
    banners = _banners(runs)
    shared = _shared_commands(runs, names, tolerance)
    verdicts = "".join(
        f'<p class="verdict">{esc(_verdict(r, names, tolerance, runs, r.k in shared))}</p>'
        for r in runs) + _advice_lines(runs, shared)
    head = ("<tr><th>run</th><th>model</th><th>largest |Err%|</th><th>RMSE [N]</th>"
            "<th>time per force</th><th>valid steps</th>"
            + (f"<th>auto at {100 * tolerance:g} %</th>" if tolerance else "") + "</tr>")
    rows = []
    for r in runs:
        ordered = sorted(r.summary, key=lambda s: (np.nan_to_num(s["max_abs_err_pct"],
                                                                 nan=np.inf)))
        best = recommend(r.summary, tolerance)[0]  # the verdict's model
        choice = _named_choice(r, names, tolerance) if tolerance else None
        for i, s in enumerate(ordered):
            first = i == 0
            run_cell = (f'<td rowspan="{len(ordered)}"><a href="#run-{r.k}">run {r.k}</a>: '
                        f"{esc(r.name)}{_simulated_badge(r)}<br>eps {r.eps_pct:.1f} %</td>"
                        if first else "")
            strong = best is not None and s["model"] == best["model"]
            name = f"<b>{esc(names[s['model']])}</b>" if strong else esc(names[s["model"]])
            err = "—" if np.isnan(s["max_abs_err_pct"]) else f"{s['max_abs_err_pct']:.2f}"
            rmse = "—" if np.isnan(s["rmse_N"]) else f"{s['rmse_N']:.2f}"
            auto = ""
            if tolerance and first:
                auto = (f'<td rowspan="{len(ordered)}">'
                        f"{esc(choice.name) if choice else '—'}</td>")
            rows.append(f'<tr>{run_cell}<td class="name">{name}</td><td class="num">{err}</td>'
                        f'<td class="num">{rmse}</td>'
                        f'<td class="num">{format_seconds(s["seconds_per_point"])}</td>'
                        f'<td class="num">{s["valid_points"]} / {s["points"]}</td>{auto}</tr>')
    status = "".join(
        f'<tr><td><a href="#run-{r.k}">run {r.k}</a></td><td>{_status_html(r)}</td>'
        f"<td>{len(r.run.steps)} / {esc(_planned_steps(r.meta))}</td>"
        f"<td>{r.meta.lost_samples}</td></tr>" for r in runs)
    keys = [k for r in runs for k in r.keys]
    return ('<h2 id="summary">Summary</h2>' + verdicts + banners
            + '<div class="table"><table class="summary">'
            f"<thead>{head}</thead><tbody>{''.join(rows)}</tbody></table>"
            '<p class="caption">Every model on every run, closest first (largest |Err%|, '
            "Equation 7); in bold, the model the verdict names: the cheapest within the "
            "tolerance against the measurement, else the closest valid at every kept step. "
            "auto: the "
            "cheapest model whose error bound against the FE model at the run's points meets "
            "the tolerance. "
            + provenance_links(dict.fromkeys(keys)) + "</p></div>"
            '<div class="table"><table class="summary"><thead><tr><th>run</th><th>status</th>'
            "<th>steps kept / planned</th><th>lost samples</th></tr></thead>"
            f"<tbody>{status}</tbody></table></div>")


def _simulated(r: _Run) -> bool:
    hardware = r.meta.get("hardware") or {}
    return bool(r.meta.get("simulated") or (isinstance(hardware, dict)
                                            and hardware.get("simulated")))


def _simulated_badge(r: _Run) -> str:
    return ' <span class="bad">SIMULATED</span>' if _simulated(r) else ""


def _past_braid_lock(r: _Run):
    """The braid lock (:func:`mkm.fem.eq2.braid_lock`) a run is held at or past, else None
    (None too where the calibration has no FE angle: no lock known); at the braid angle the
    calibration identified on the run's muscle, which the models take in place of a declared
    one."""
    from mkm.fem.eq2 import braid_lock
    from mkm.identify.band import identified_entry

    found = identified_entry(r.calibration) if _identified_muscle(r.calibration,
                                                                  r.muscle) else None
    try:
        if found and found[1].get("theta0_deg") is not None:
            lock = dataclasses.replace(
                braid_lock(float(found[1]["theta0_deg"])),
                source=f"the braid angle of the muscle identified in {r.calibration.path.name} "
                       f"({found[0]})")
        else:
            lock = braid_lock(r.muscle.theta0_deg, r.calibration)
    except ValueError:
        return None
    return lock if r.muscle.eps >= lock.eps_max else None


def _banners(runs: list[_Run]) -> str:
    """One line per fact the reader must know before any number: simulated runs, runs held past
    the braid lock (where no model is valid)."""
    out = []
    simulated = [r for r in runs if _simulated(r)]
    if simulated:
        which = ", ".join(f"run {r.k}" for r in simulated)
        out.append(f"SIMULATED: {which} came from the simulated bench (a model with noise), "
                   "not from a measurement.")
    for r in runs:
        if lock := _past_braid_lock(r):
            out.append(f"Run {r.k} is held at eps {r.eps_pct:.1f} %, past the braid lock: "
                       f"{lock}. No model is valid there: the braid cannot shorten so far, so "
                       "the muscle pulls little or nothing and every model's number is flagged "
                       "invalid.")
    other = _calibration_of_another_muscle(runs)
    if other:
        out.append(other)
    return "".join(f'<p class="note">{esc(line)}</p>' for line in out)


def _calibration_of_another_muscle(runs: list[_Run]) -> str | None:
    """The line naming the runs whose muscle (D0, t0) is not the one the calibration's
    identified muscle was identified on, or None: its braid angle and rubber are that muscle's,
    so every calibrated model predicts these runs as that muscle's."""
    calibration = runs[0].calibration if runs else None
    muscles = _identified_muscles(calibration)
    others = [r for r in runs if not _identified_on_its_muscle(r)]
    if not others:
        return None
    which = ", ".join(f"{r.k} ({r.muscle.id or 'no id'}, D0 {r.muscle.D0_mm:g} mm, t0 "
                      f"{r.muscle.t0_mm:g} mm)" for r in others)
    identified = ", ".join(f"{i or 'no id'}, D0 {D0:g} mm, t0 {t0:g} mm"
                           for (D0, t0), i in muscles.items())
    return (f"Run{'s' if len(others) > 1 else ''} {which}: the calibration "
            f"{calibration.path} was identified on another muscle ({identified}); its braid "
            "angle and rubber are that muscle's, so every calibrated model predicts "
            f"{'these runs' if len(others) > 1 else 'this run'} as that muscle's. Identify "
            "this muscle's own (mkm identify) or leave --calibration out.")


def _identified_muscles(calibration) -> dict[tuple[float, float], str]:
    """The muscles (D0, t0) -> id the calibration's identification was made on; empty for a
    calibration without that record."""
    return {(m["D0_mm"], m["t0_mm"]): m.get("id", "")
            for m in (r.get("muscle") or {} for r in _identified_runs(calibration))
            if "D0_mm" in m and "t0_mm" in m}


def _identified_on_its_muscle(r: _Run) -> bool:
    """Whether the run's muscle (D0, t0) is one the calibration was identified on (True where
    the calibration records none)."""
    muscles = _identified_muscles(r.calibration)
    return not muscles or any(math.isclose(r.muscle.D0_mm, D0, rel_tol=1e-3) and
                              math.isclose(r.muscle.t0_mm, t0, rel_tol=1e-3)
                              for D0, t0 in muscles)


def _overlay_section(runs: list[_Run], out: Path, names: dict, colours: dict) -> str:
    """The runs of each muscle on one figure (the paper's Figure 7c/d)."""
    groups: dict[tuple, list[_Run]] = {}
    for r in runs:
        if r.scored.empty:
            continue
        m = r.muscle
        groups.setdefault((m.id, m.D0_mm, m.t0_mm, m.L0_mm), []).append(r)
    parts = []
    for i, ((mid, D0, t0, L0), members) in enumerate(groups.items(), start=1):
        if len(members) < 2:
            continue
        members = sorted(members, key=lambda r: r.eps_pct)
        title = (f"{_plain(mid)}: D0 = {D0} mm, t0 = {t0} mm, L0 = {L0} mm; "
                 + ", ".join(f"eps = {r.eps_pct:.1f} %" for r in members))
        fig = overlay_figure([(r.label, r.run.steps, r.scored) for r in members], title,
                             names, colours)
        path = save_figure(fig, out / f"overlay{i}.png")
        keys = dict.fromkeys(k for r in members for k in r.keys)
        parts.append(figure_html(path, "Runs of one muscle together, as the paper's Figure "
                                 "7c/d: measured forces (mean ± std per step; one marker per "
                                 "run) and every model (one line style per run); right: Err% "
                                 "of the up sweeps. " + provenance_links(keys)))
    if not parts:
        return ""
    return '<h2 id="overlay">Runs of one muscle together</h2>' + "".join(parts)


def _speed_section(runs, summary: pd.DataFrame, out: Path, names: dict, colours: dict,
                   tolerance) -> str:
    """Seconds per force against the largest |Err%| on these runs, per model; the auto choice."""
    if summary.empty:
        return ""
    path = save_figure(report_speed_figure(summary, names, colours), out / "speed_accuracy.png")
    table = []
    for model, g in summary.groupby("model", sort=False):
        table.append({"model": names[model], "spec": model,
                      "valid points": int(g["valid_points"].sum()),
                      "of": int(g["points"].sum()),
                      "largest |Err%|": g["max_abs_err_pct"].max(),
                      "largest RMSE [N]": g["rmse_N"].max(),
                      "largest |residual| [N]": g["max_abs_residual_N"].max(),
                      "time per force": format_seconds(g["seconds_per_point"].median()),
                      "timed": "from the FE cache (the original solve)" if g["from_cache"].all()
                      else "in this report"})
    keys = dict.fromkeys(k for r in runs for k in r.keys)
    auto = "".join(_auto_paragraph(r, tolerance) for r in runs) if tolerance else ""
    return ('<h2 id="speed">How fast, how good</h2>'
            + figure_html(path, "Each model's seconds per predicted force (log; a cached FE "
                          "sweep reports the time of its original solve) against its largest "
                          "|Err%| against the measurement, one marker per run. "
                          + provenance_links(keys))
            + table_html(pd.DataFrame(table), "Every model over all runs: the worst of its "
                         "per-run numbers, and the median time per force. "
                         + provenance_links(keys))
            + auto)


def _run_section(r: _Run, out: Path, names: dict, colours: dict, prov: dict) -> str:
    from mkm.bench.storage import reason_shown

    meta, muscle, steps = r.meta, r.muscle, r.run.steps
    parts = [f'<section class="run-head"><h2 id="run-{r.k}">Run {r.k}: {esc(r.name)}</h2>',
             f"<p>status: <b>{_status_html(r)}</b>"]
    n_samples = getattr(r.run, "n_samples", None)
    n_samples = len(r.run.samples) if n_samples is None else n_samples
    imported = meta.get("imported_from") or {}
    recorded = imported.get("recorded_status")
    if recorded and recorded != "complete":  # an exported run cut short, imported back
        why = reason_shown(str(imported.get("recorded_reason") or ""))
        parts.append(f" — recorded as <b>{esc(recorded)}</b>: {esc(why)}")
    if not r.run.complete:
        reason = reason_shown(str(meta.get("reason") or "")) or "not recorded"
        parts.append(f" — reason: {esc(reason)}. Kept: "
                     f"{len(steps)} settled step(s) of {_planned_steps(meta)}, "
                     f"{n_samples} sample(s). Only what was kept is scored below.")
    parts.append("</p>")
    hardware = dict(meta.get("hardware") or {})
    sim = hardware.pop("sim", None) if hardware.get("simulated") else None
    source = "From run.json. " + provenance_links(r.keys[:1])
    identified = {f"{k} identified (the models')": v for k, v in
                  _identified_geometry(r.calibration, muscle).items()}
    replaced = [k for k in DECLARED_MATERIAL if getattr(muscle, k) is not None
                and _identified_muscle(r.calibration, muscle)]
    tables = [mapping_table(muscle.record() | {"eps [%]": r.eps_pct} | identified, "Muscle",
                            source + (" The models predict with the wall, diameter or rest "
                                      "length the calibration identified (eps at it: the held "
                                      "length kept)." if identified else "")
                            + (f" The models take {', '.join(replaced)} from the calibration, "
                               "identified on this muscle, not the declared one(s)."
                               if replaced else "")),
              mapping_table(hardware, "Hardware", source),
              mapping_table(meta.get("calibration") or {}, "Calibration", source),
              mapping_table(meta.get("tare") or {}, "Tare at 0 bar", source)]
    if isinstance(sim, dict):
        tables.append(mapping_table(sim, "Simulated bench", source))
        parts.append(_sim_note(sim, r.specs))
    setup = ('<h3>Set-up</h3><div class="tables">' + "".join(tables) + "</div>")
    unsettled = int((~steps["settled"].astype(bool)).sum()) if len(steps) else 0
    if unsettled:
        parts.append(f'<p class="note">{unsettled} step(s) did not settle before the timeout: '
                     "kept, scored and marked settled = false in the CSV.</p>")
    if r.run.problems:
        parts.append('<p class="note">Loader: ' + esc("; ".join(r.run.problems)) + "</p>")
    for dead in getattr(meta, "unvented_before", None) or []:
        parts.append(f'<p class="note">Before this run, the bench was found left pressurised '
                     f"by run {esc(dead.get('run_path'))} (started {esc(dead.get('started_utc'))},"
                     f" last commanded {esc(dead.get('last_command_bar'))} bar): this run "
                     "vented it first.</p>")
    parts.append("</section>")
    if steps.empty:
        return "".join(parts) + ('<p class="note">No step was kept: nothing to compare.</p>'
                                 + _signals(r, out) + setup)

    stem = f"run{r.k}"
    spreadsheet_safe(r.scored).to_csv(out / f"{stem}_errors.csv", index=False, float_format="%.6g",
                                      encoding=SPREADSHEET_CSV_ENCODING)
    title = f"run {r.k}: {_plain(muscle.id)}, eps = {r.eps_pct:.1f} %"
    fig_path = save_figure(run_figure(steps, r.scored, title, names, colours),
                           out / f"{stem}_force_error.png")
    table = pd.DataFrame([{"model": names[s["model"]], "spec": s["model"],
                           "valid points": s["valid_points"], "of": s["points"],
                           "largest |Err%|": s["max_abs_err_pct"], "RMSE [N]": s["rmse_N"],
                           "largest |residual| [N]": s["max_abs_residual_N"],
                           "worst E_n": s["worst_E_n"], "at step": _cell(s["worst_step"]),
                           "consistent": {True: "yes", False: "no"}.get(s["consistent"], "—"),
                           "time per force": format_seconds(s["seconds_per_point"])}
                          for s in r.summary])
    parts += [
        figure_html(fig_path, "Left: measured force per pressure step (mean ± U at 95.45 %; "
                    + ("filled circles up sweep, open squares down sweep"
                       if (steps["direction"] == "down").any() else "the up sweep only")
                    + ") with each model and, where it has one, its ± 2 u band. Middle: Err% "
                    "(Equation 7). Right: residual in N"
                    + (" (solid up, dashed down). " if (steps["direction"] == "down").any()
                       else ". ") + provenance_links(r.keys)),
        table_html(table, f"Per model (files: {stem}_errors.csv, summary.csv). E_n = "
                   "(F_meas − F_model) / √(U_meas² + (c U_p)² + U_model²) per step, every U "
                   "expanded to 95.45 % (c: the model's newtons per bar); consistent: |E_n| ≤ 1 "
                   "at every valid step. The models have no braid friction and no creep, the "
                   "measurement has both: a model can be inconsistent by them alone. "
                   + provenance_links(r.keys)),
        _budget_section(r, provenance_links(r.keys[:1])),
        _domain_note(r.scored, _pressure_tolerance(meta), names),
        _invalid_note(r.scored, names),
        _signals(r, out),
        setup,
    ]
    return "".join(parts)


def _budget_section(r: _Run, links: str) -> str:
    """The measurement budget of the run's largest-force step, terms ranked by their share."""
    from mkm.bench.budget import Declared, Instrument, declared_step_budget, step_budget

    steps, tare = r.run.steps, r.meta.get("tare") or {}
    declared = (r.meta.get("imported_from") or {}).get("declared_accuracy")
    if "force_U_N" not in steps or not steps["force_U_N"].notna().any():
        return ('<p class="note">This run was recorded without an uncertainty budget'
                + (": import its table again with the instruments' accuracy (mkm import "
                   "--accuracy force=...,pressure=...) to score E_n.</p>"
                   if r.meta.get("imported_from") else ".</p>"))
    s = steps.loc[steps["force_N_mean"].idxmax()]
    if declared:
        budget = declared_step_budget(
            {q: Declared.from_record(b) for q, b in declared.items()}, s,
            r.meta["imported_from"].get("shape") == "staircase")
    else:
        try:
            instrument = Instrument.from_run(r.meta)
        except (TypeError, ValueError, ZeroDivisionError):
            return ('<p class="note">The calibration in run.json is incomplete: the budget\'s '
                    "terms cannot be listed (steps.csv has its totals).</p>")
        budget = step_budget(instrument, float(s["force_N_mean"]),
                             float(s["force_N_std"]), int(s["n"]), float(s["force_drift_N"]),
                             float(tare.get("std_N", np.nan)), int(tare.get("n", 0)),
                             pressure_bar=float(s["pressure_bar_mean"]))
    rows = [{"quantity": q, "term": t.name, "type": t.kind,
             "u": t.u, "share of u² [%]": 100 * share, "from": t.source}
            for q in ("force", "pressure") for t, share in budget.ranked(q)]
    caption = (f"Measurement uncertainty budget of step {int(s['step'])} ({s['set_pressure_bar']:g}"
               f" bar, {s['force_N_mean']:.1f} N, the run's largest force): u in N (force) or "
               f"bar (pressure), ranked, so the first term is the one to improve. Combined: "
               f"U = {budget.force_U_N:.2f} N (k = {budget.k('force'):.3g}) and "
               + (f"{budget.pressure_U_bar:.3f} bar (k = {budget.k('pressure'):.3g}), 95.45 %"
                  if budget.pressure_u_bar > 0 else "the pressure exact (no accuracy declared)")
               + (f"; the hold drifted {budget.drift_N:+.2f} N (creep: the hold mean is the "
                  "measurand)" if np.isfinite(budget.drift_N) else "")
               + (f"; the bounds its lab declared at import ({_declared_text(declared)})"
                  if declared else "")
               + ". Every step's U is in steps.csv (force_U_N, pressure_U_bar). " + links)
    return table_html(pd.DataFrame(rows), caption, formats={"u": ".3g",
                                                            "share of u² [%]": ".1f"})


def _declared_text(declared: dict) -> str:
    """``mkm import --accuracy`` as it was given, from run.json's ``declared_accuracy``."""
    return "--accuracy " + ",".join(f"{q}={b.get('given', '')}" for q, b in declared.items())


def _sim_note(sim: dict, specs) -> str:
    """What the simulated "measurement" is (the simulator's own description in run.json), and
    which report model shares its physics."""
    physics = sim.get("physics") if isinstance(sim.get("physics"), dict) else {}
    source = str(physics.get("force_model") or sim.get("model") or "a force model")
    what = physics.get("summary") or (f"the {source} model with hysteresis "
                                      f"{100 * float(sim.get('hysteresis_fraction', 0)):g} % "
                                      f"and creep {100 * float(sim.get('creep_fraction', 0)):g} %")
    same = [s.text for s in specs if s.name == source.split(":")[0]]
    shared = (f" {', '.join(same)} in this report shares its static physics, so its agreement "
              "on the averaged steps is partly by construction; braid friction and creep are in "
              "no model of the report." if same else " No model in this report is that physics.")
    return ('<p class="note">Simulated run: the "measured" force is the simulated bench\'s '
            f"muscle ({esc(what)}; seed {esc(sim.get('seed'))}), not a real muscle."
            + esc(shared) + "</p>")


def _signals(r: _Run, out: Path) -> str:
    """Pressure and force against time, read in bounded memory (time bins of samples.csv)."""
    from mkm.bench.storage import aggregate_samples

    bins = aggregate_samples(r.run.path)
    if bins.empty:
        return '<p class="note">No samples recorded: no time traces.</p>'
    bins.to_csv(out / f"run{r.k}_signals.csv", index=False, float_format="%.6g")
    gaps = [(float(g["start_s"]), float(g["end_s"])) for g in (r.meta.get("gaps") or [])
            if isinstance(g, dict) and "start_s" in g]
    if not gaps and "gap" in bins:
        gaps = [(t, t + 0.1) for t in bins.loc[bins["gap"] > 0, "time_s"]]
    events = []
    if "interlock" in bins and (bins["interlock"] > 0).any():
        events.append((float(bins.loc[bins["interlock"] > 0, "time_s"].iloc[0]),
                       "force interlock"))
    elif not r.run.complete:
        events.append((float(bins["time_s"].iloc[-1]), str(r.run.status)))
    title = f"run {r.k}: pressure and force against time"
    limit = (r.meta.get("sequence") or {}).get("force_limit_N")
    path = save_figure(time_figure(bins, r.run.steps, title, gaps, events,
                                   float(limit) if limit else None),
                       out / f"run{r.k}_signals.png")
    extra = (f" {len(gaps)} gap(s) in the record (red)." if gaps else " No gap in the record.")
    extra += "".join(f" Event: {esc(label)} at {when:.1f} s (red line)." for when, label in events)
    return (f'<div id="signals-{r.k}">'
            + figure_html(path, "The signals: mean per time bin with its min-max band (file "
                          f"run{r.k}_signals.csv); per step the settling time (yellow, not "
                          "averaged) and the averaging window whose mean ± std is the step's "
                          f"measurement (green).{extra} " + provenance_links(r.keys[:1]))
            + "</div>")


def _domain_note(scored: pd.DataFrame, tolerance_bar: float, names: dict) -> str:
    moved = scored[~np.isclose(scored["pressure_bar"], scored["pressure_meas_bar"])]
    if moved.empty:
        return ""
    items = [f"{esc(names[m])}: {len(g)} point(s), measured "
             f"{', '.join(f'{p:.4f}' for p in g['pressure_meas_bar'])} bar evaluated at "
             f"{', '.join(f'{p:g}' for p in sorted(g['pressure_bar'].unique()))} bar"
             for m, g in moved.groupby("model", sort=False)]
    return ('<p class="note">Measured pressures within the regulator tolerance '
            f"({tolerance_bar:g} bar, the run's settling tolerance) of a model's domain edge "
            "count as in the domain and are evaluated at the edge: " + "; ".join(items)
            + ".</p>")


def _invalid_note(scored: pd.DataFrame, names: dict) -> str:
    bad = scored[~scored["valid"]]
    if bad.empty:
        return ""
    items = [f"{esc(names[m])}: {len(rows)} point(s) at "
             f"{', '.join(f'{p:.2f}' for p in sorted(rows['pressure_bar'].unique()))} bar"
             for m, rows in bad.groupby("model", sort=False)]
    return ('<p class="note">No valid number (invalid, out of domain or not converged), shown '
            "as crosses above the axes and excluded from every number: " + "; ".join(items)
            + ".</p>")


def _auto_pressures(r: _Run) -> np.ndarray:
    """The run's pressures as auto sees them: within the regulator tolerance of the study's top
    pressure counts as that pressure (the domain-edge rule)."""
    from mkm.auto import read_model_errors

    P = evaluation_pressures(r.run.steps)
    top = float(read_model_errors()["pressure_bar"].max())
    tol = _pressure_tolerance(r.meta)
    return np.where((P > top) & (P <= top + tol), top, P)


def _auto_choice(r: _Run, tolerance: float) -> AutoPick | None:
    """What ``auto`` picks for the whole run, or None (chosen once per run: the verdict, the
    summary and the run's section all show it)."""
    from mkm.auto import MODEL_ERRORS_FILE, AutoModel, explain, spec_of
    from mkm.registry import build_spec

    if tolerance not in r.auto_choices:
        choice = None
        # past the braid lock no model answers: auto's pick would be named for no force
        if not r.run.steps.empty and MODEL_ERRORS_FILE.exists() and not _past_braid_lock(r):
            m = r.predicted
            auto = AutoModel(tolerance=tolerance,
                             build=partial(build_spec, calibration=r.calibration),
                             **m.model_parameters())
            try:
                chosen = auto.choose(_auto_pressures(r), m.D0_mm, m.t0_mm, m.eps)
            except ValueError:  # a candidate without a calibration in this command: no choice
                chosen = None
            if chosen is not None:
                used = str(chosen["model_used"][0])
                choice = AutoPick(spec_of(used), model_label(used),
                                  float(np.nanmax(chosen["error_bound_pct"])),
                                  explain(chosen, tolerance, model_label,
                                          gap_mm=auto.resolved_gap_mm()))
        r.auto_choices[tolerance] = choice
    return r.auto_choices[tolerance]


def _named_choice(r: _Run, names: dict, tolerance: float) -> AutoPick | None:
    """:func:`_auto_choice` under the report's name of the model it picks, where it is one of
    the report's (the practical range's surrogate answering as ``surrogate`` included)."""
    choice = _auto_choice(r, tolerance)
    shown = {names[s.text] for s in r.specs}
    if choice is None or choice.name in shown:
        return choice
    match = next((s for s in r.specs
                  if _same_model(choice.spec, r.in_place.get(s.text, s.text))), None)
    if match is not None:
        return AutoPick(choice.spec, names[match.text], choice.bound_pct, choice.explanation)
    if any(name.startswith(f"{choice.name}, ") for name in shown):
        # another of its kind is the report's (`Surrogate, path=...`, a user's own): auto's
        # is named by its spec, not taken for that one
        return AutoPick(choice.spec, f"{choice.name} ({choice.spec})", choice.bound_pct,
                        choice.explanation)
    return choice


def _same_model(a: str, b: str) -> bool:
    """Whether two specs build the same model (``eq2`` and ``eq2:diameter=inner`` do): same
    entry and same parameters once built (the closed forms and the FE model build in
    microseconds; a surrogate spec is compared by its text)."""
    if a == b:
        return True
    try:
        sa, sb = parse_spec(a), parse_spec(b)
        if sa.name != sb.name or sa.name in ("surrogate", "auto"):
            return False
        ma, mb = sa.build(), sb.build()
    except ValueError:
        return False
    return ma.params() == mb.params()


def _verdict(r: _Run, names: dict, tolerance: float | None, runs: list[_Run] = (),
             command_below: bool = False) -> str:
    """The run's verdict sentence (:func:`mkm.verdict.verdict`) with auto's pick and the
    measurement's distance from the report's FE model, if it has one; the identify command it
    suggests takes every run of ``runs`` of the same muscle (one eps alone confounds the braid
    angle and the rubber); ``command_below``: it refers to that command, said once below the
    verdicts (:func:`_advice_lines`)."""
    label = (f"Run {r.k} (eps {r.eps_pct:.1f} %{', simulated' if _simulated(r) else ''})"
             + _cut_short(r))
    choice, same = _auto_pick(r, names, tolerance)
    path, identified, muscle_runs = _advice_arguments(r, runs)
    record = _identified_record(r.calibration)
    fit = {**record, "options": _advice_options(r, runs)} if record else None
    name = r.calibration.path.name if r.calibration else ""
    text = verdict(label, r.summary, names, tolerance, choice, same,
                   _fe_err(r, names), muscle_advice(
                       path, identified, name, muscle_runs, fit, command_below,
                       _advises_rest_length(r), [row["model"] for row in r.summary]),
                   NO_BUDGET_IMPORTED if r.meta.get("imported_from") else NO_BUDGET,
                   _shows_dynamics(r), _ended(r))
    best, within = recommend(r.summary, tolerance)
    if choice is not None or not identified or best is None or within \
            or best.get("consistent") is not False:
        return text
    # no FE model in the report to weigh the run by (a closed form's calibration): a run the
    # identified model misses beyond its noise, unseen by it, is what the calibration lacks
    command = advice_command(path, identified, muscle_runs, _advice_options(r, runs))
    if command is None:
        return text
    said = not_carried_over(identified, name, f"`{command}`", _advises_rest_length(r))
    return f"{text} {said[0].upper()}{said[1:]}."


def _cut_short(r: _Run) -> str:
    """For a run stopped part way, what its verdict is of, said in its label: a model "within
    2 %" over its two lowest steps is no verdict on the muscle's range."""
    kept, planned = len(r.run.steps), r.meta.n_steps
    if r.run.complete or planned is None or not 0 < kept < planned:
        return ""
    top = float(r.run.steps["set_pressure_bar"].max())
    return f", on the {kept} of its {planned} planned steps it kept (to {top:.2f} bar; {_ended(r)})"


def _ended(r: _Run) -> str:
    """How the run ended, as its verdict says it where no step was kept: the terminal shows the
    verdict alone, without the report's status column."""
    from mkm.bench.storage import reason_shown

    reason = reason_shown(str(r.run.reason or ""))
    return f"{r.run.status}: {reason}" if reason else str(r.run.status)


def _fe_err(r: _Run, names: dict) -> tuple[str, float] | None:
    """``(name, largest |Err%|)`` of the report's first FE model on the run: the measurement's
    distance from the FE model; None without one."""
    return next(((names[s["model"]], s["max_abs_err_pct"]) for s in r.summary
                 if parse_spec(s["model"]).entry.family == "FE"
                 and np.isfinite(s["max_abs_err_pct"])), None)


def _shows_dynamics(r: _Run) -> bool:
    """Whether the run can show braid friction or creep: a bench run holds its steps, an
    imported table shows friction only with a rising and a falling branch."""
    return not r.meta.get("imported_from") or (r.run.steps["direction"] == "down").any()


def _auto_pick(r: _Run, names: dict, tolerance: float | None) -> tuple[AutoPick | None, bool]:
    """auto's pick for the run at ``tolerance`` and whether it is the verdict's model."""
    choice = _named_choice(r, names, tolerance) if tolerance and r.summary else None
    best, _ = recommend(r.summary, tolerance)
    return choice, bool(choice and best and _same_model(
        choice.spec, r.in_place.get(best["model"], best["model"])))


def _advice_arguments(r: _Run, runs: list[_Run]) -> tuple[str, list[dict], list[str]]:
    """The run, the calibration's runs and the muscle's runs at hand, as
    :func:`mkm.verdict.muscle_advice` and :func:`mkm.verdict.advice_command` take them; no
    calibration's runs for a run of another muscle (identify refuses two tubes at once: this
    muscle is identified from its own runs)."""
    identified = _identified_runs(r.calibration) if _identified_on_its_muscle(r) else []
    seen, muscle_runs = _measurement(r), []
    for other in runs:
        if other is not r and (not _same_muscle(other.muscle, r.muscle)
                               or _measurement(other) & seen):
            continue  # identify refuses one measurement twice: its twin of r is left out
        seen |= _measurement(other)
        muscle_runs.append(str(other.run.path))
    return str(r.run.path), identified, muscle_runs


def _measurement(r: _Run) -> set[str]:
    """What names the run's measurement (:func:`mkm.identify.runs.measurement_keys`), read
    once."""
    if r.measurement is None:
        from mkm.identify.runs import measurement_keys, measurement_sha256

        r.measurement = frozenset(measurement_keys(r.name, measurement_sha256(r.run)))
    return set(r.measurement)


def _advice_options(r: _Run, runs: list[_Run] = ()) -> list[str]:
    """The options the calibration's identification was asked with, for identifying it again
    with ``r`` and the other runs of ``runs`` it did not see (:func:`mkm.verdict.advice_command`)
    among its runs: a group none of those runs can show (friction and creep of tables with one
    branch and no times) is not advised, as identify would not fit it."""
    if r.advice_options is None:
        from mkm.identify.procedure import options_for_runs, with_group

        options = (_identified_record(r.calibration) or {}).get("options") or []
        identified = _identified_runs(r.calibration)
        paths = [x["path"] for x in identified if "path" in x]
        seen = {x.get("run") for x in identified}
        at_hand = {*_advice_arguments(r, runs)[2], str(r.run.path)}
        unseen = [o for o in [*(o for o in runs if o is not r), r]
                  if str(o.run.path) in at_hand and o.run.path.name not in seen]
        if options and any(_advises_rest_length(o) for o in unseen):
            options = with_group(options, "L0")
        folders = list(dict.fromkeys([*paths, *(str(o.run.path) for o in unseen)]))
        # each run of one muscle asks the same of the same folders: read them once
        r.advice_from = (tuple(options), frozenset(folders))
        r.advice_options = next(
            (o.advice_options for o in runs if o is not r and o.advice_from == r.advice_from),
            None) or (options_for_runs(options, folders) if options and paths
                      else list(options))
    return r.advice_options


def _advises_rest_length(r: _Run) -> bool:
    """Whether the identify advice for ``r`` fits the rest length: a run declared at its rest
    length that the calibration of its shortened runs (at that rest length) does not carry
    over to may be a table's first length already shortened (the DMSP-20-300's published map,
    docs/guide/threshold.md), or a threshold at rest length no model has (the DMSP-10-250's)."""
    identified = _identified_runs(r.calibration)
    return bool(identified) and r.muscle.eps == 0.0 and all(
        float(x.get("muscle", {}).get("L0_mm", -1.0)) == r.muscle.L0_mm for x in identified)


def _shared_commands(runs: list[_Run], names: dict, tolerance: float | None) -> dict[int, str]:
    """The identify command each run's verdict suggests (run number -> command) where several
    verdicts suggest the same one: said once (:func:`_advice_lines`), it keeps the first screen
    for the verdicts rather than the same run paths again and again."""
    commands = {}
    for r in runs:
        command = advice_command(*_advice_arguments(r, runs), _advice_options(r, runs))
        if command and gives_advice(r.summary, names, tolerance,
                                    *_auto_pick(r, names, tolerance), _fe_err(r, names)) \
                and friction_explains(r.summary, tolerance) is None:
            commands[r.k] = command
    said = list(commands.values())
    return {k: c for k, c in commands.items() if said.count(c) > 1}


def _advice_lines(runs: list[_Run], commands: dict[int, str]) -> str:
    """Each identify command of :func:`_shared_commands`, said once, with the runs it
    concerns (:func:`_advice`)."""
    # each argument unbroken: a path wrapped at its hyphen reads as two (mkm- out/runs)
    return "".join(f'<p class="verdict">{esc(said)}<code>'
                   + " ".join(f'<span class="arg">{esc(a)}</span>'
                              for a in re.findall(r'"[^"]*"|\S+', command))
                   + "</code></p>" for said, command in _advice(runs, commands))


def _advice(runs: list[_Run], commands: dict[int, str]) -> list[tuple[str, str]]:
    """For each identify command of ``commands`` (run number -> command), once: the sentence
    that names the runs it concerns, and the command."""
    out = []
    for command in dict.fromkeys(commands.values()):
        concerned = [r for r in runs if commands.get(r.k) == command]
        out.append((f"Runs {', '.join(str(r.k) for r in concerned)}: identify "
                    f"{concerned[0].muscle.id} from its runs here, then give mkm report "
                    "--calibration the calibration.json it writes: ", command))
    return out


def _same_muscle(a: Muscle, b: Muscle) -> bool:
    """One tube: the same id, diameter and wall as run.json records them (its runs may be held
    at other lengths; :func:`_overlay_section` groups by these and the length)."""
    return (a.id, a.D0_mm, a.t0_mm) == (b.id, b.D0_mm, b.t0_mm)


def _identified_record(calibration: Calibration | None) -> dict | None:
    """What ``mkm identify`` recorded of the identification in ``calibration`` (its misfit and
    parameters among it); None for the shipped one or one written by hand."""
    from mkm.identify.band import identified_entry

    found = identified_entry(calibration) if calibration is not None else None
    return found[1]["identified"] if found else None


def _identified_runs(calibration: Calibration | None) -> list[dict]:
    """The runs a calibration was identified on (``mkm identify`` records them in the entry of
    the model it identified with); empty for the shipped one or one written by hand."""
    record = _identified_record(calibration)
    runs = record.get("runs") if record else None
    return [r for r in runs if isinstance(r, dict)] if isinstance(runs, list) else []


#: what a run may declare of its muscle's material that a calibration identified on it replaces
DECLARED_MATERIAL = ("theta0_deg", "C10_MPa", "C01_MPa")


def _identified_muscle(calibration: Calibration | None, muscle: Muscle) -> bool:
    """Whether ``calibration`` was identified (``mkm identify``) on ``muscle`` as run.json
    declares it (its id, diameter, wall and rest length)."""
    from mkm.identify.band import identified_entry

    found = identified_entry(calibration) if calibration is not None else None
    declared = [r.get("muscle") or {} for r in _identified_runs(calibration)]
    return bool(found) and any(m.get("id") == muscle.id and all(
        math.isclose(float(m.get(k, math.nan)), getattr(muscle, k), rel_tol=1e-9)
        for k in ("D0_mm", "t0_mm", "L0_mm")) for m in declared)


def _identified_geometry(calibration: Calibration | None, muscle: Muscle) -> dict[str, float]:
    """The wall, diameter and rest length [mm] ``mkm identify --params t0,D0,L0`` fitted, when
    ``muscle`` (as run.json declares it) is the one it fitted them on (with a fitted rest
    length, the run's ``eps`` at it: its held length kept); empty otherwise."""
    from mkm.identify.band import identified_entry

    if not _identified_muscle(calibration, muscle):
        return {}
    found = identified_entry(calibration)
    fitted = {p["parameter"]: float(p["value"]) for p in found[1]["identified"].get(
        "parameters", []) if p.get("parameter") in ("D0_mm", "t0_mm", "L0_mm")
        and p.get("status") == "fitted"}
    if "L0_mm" in fitted:
        fitted["eps"] = eps_at_rest_length(muscle.L0_mm, muscle.eps, fitted["L0_mm"])
    return fitted


def _auto_paragraph(r: _Run, tolerance: float) -> str:
    """The one model ``--model auto`` uses for this run (the choice only: the fallback FE is
    not solved for it)."""
    choice = _auto_choice(r, tolerance)
    if choice is None:
        return ""
    lines = "<br>".join(esc(line) for line in choice.explanation.splitlines())
    return (f"<p><b>Model choice for run {r.k}</b> (<code>--model auto --tolerance "
            f"{100 * tolerance:g}%</code>, one model for the whole run, each candidate's error "
            f"bound at this run's points and muscle):<br>{lines}.</p>")


def _surrogate_section(out: Path, prov: dict) -> str:
    """The paper's Table 3 and Figure 6 with our numbers: the default surrogate against our FE
    reference of the test muscles (the paper's I, II, III and the surrogate package's off-grid
    ones), computed by :mod:`mkm.surrogate.testset`."""
    head = ("<h2>Surrogate against the FE model on the paper's test muscles I, II, III and "
            "off-grid muscles</h2>")
    from mkm import surrogate
    from mkm.surrogate.testset import FE_REFERENCE, compare_on_test_muscles, read_fe_reference

    if not FE_REFERENCE.exists():
        return head + (f'<p class="note">No FE reference at {esc(FE_REFERENCE)}: build it '
                       "with <code>mkm surrogate reference</code>.</p>")
    model = surrogate.default_model()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # out-of-domain points are flagged per point below
        points, summary = compare_on_test_muscles(model, read_fe_reference())
    points = points.rename(columns={"force_pred_N": "force_N"})
    points["err_pct"] = points["err_pct"].where(points["valid"])
    result = summary.drop(columns=["model", "seconds_all_points"]).rename(columns={
        "max_abs_err_pct": "largest |Err%|", "rmse_N": "RMSE [N]",
        "max_abs_error_N": "largest |error| [N]", "valid_points": "valid points",
        "all_valid": "all points valid"})
    result["muscle"] = result["muscle"].astype(str)
    if TABLE3_CSV.exists():
        paper = pd.read_csv(TABLE3_CSV, comment="#")[["muscle", "max_abs_err_pct"]]
        paper["muscle"] = paper["muscle"].astype(str)
        result = result.merge(paper.rename(columns={"max_abs_err_pct":
                                                    "paper's best net: largest |Err%|"}),
                              on="muscle", how="left")
    points.to_csv(out / "surrogate_vs_fe.csv", index=False, float_format="%.6g")
    result.to_csv(out / "surrogate_vs_fe_summary.csv", index=False, float_format="%.6g")
    seconds = float(summary["seconds_all_points"].iloc[0])
    prov["surrogate"] = {"model": model.name, "params": model.params(),
                         "sha256": model.origin()["sha256"],
                         "trained": model.metadata.get("trained"),
                         # its path as this process found it (a cached model's trainer ran
                         # elsewhere)
                         "dataset": {**(model.metadata.get("dataset") or {}),
                                     **model.origin()["dataset"]},
                         "seconds_per_point": seconds / max(len(points), 1)}
    prov["fe-reference"] = {"file": FE_REFERENCE.name, "header": _reference_header()}
    keys = ["surrogate", "fe-reference"]
    title = f"{parse_spec('surrogate').display_name} against our FE model (the paper's Figure 6)"
    fig_path = save_figure(surrogate_fe_figure(points, title), out / "surrogate_vs_fe.png")
    return head + "".join([
        table_html(result, "The paper's Table 3 with our numbers: largest |Err%| (Equation 7), "
                   "RMSE and largest error of the default surrogate against our FE model "
                   f"(I-III: the paper's muscles; others: off-grid muscles). All {len(points)} "
                   "points predicted in one call: "
                   f"{format_seconds(seconds / max(len(points), 1))} per force (the paper: "
                   "131 ms for 33, 4 ms per force). "
                   + provenance_links(keys)),
        figure_html(fig_path, "FE forces (dots) and the surrogate (lines) per test muscle; "
                    "right: Err% per pressure. " + provenance_links(keys)),
    ])


def _reference_header() -> dict:
    """Metadata of the shipped FE reference (its JSON sidecar or its comment header)."""
    from mkm.surrogate.testset import FE_REFERENCE

    sidecar = FE_REFERENCE.with_suffix(".json")
    if sidecar.exists():
        return json.loads(sidecar.read_text(encoding="utf-8"))
    try:
        return read_prediction_header(FE_REFERENCE)
    except (ValueError, OSError):
        return {}
