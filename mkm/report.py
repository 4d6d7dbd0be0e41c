"""The validation report: bench runs against every force model, as one self-contained HTML file.

:func:`build_report` loads runs with :func:`bench.storage.load_run`, predicts each run's steps with
the requested models (FE predictions through :mod:`mkm.prediction_cache`), scores them with the
paper's Equation 7 against the measurement, compares the surrogate with our FE model on the
paper's test muscles I, II and III, and writes ``report.html`` (figures embedded as base64 PNG,
inline CSS, no external asset) with the PNGs and CSVs beside it. Every table and figure names
the provenance entries (models and their parameters, data, versions) it was computed from.
"""

from __future__ import annotations

import json
import time
import warnings
from pathlib import Path

import numpy as np
import pandas as pd

from fem.interface import ForceModel, Prediction
from fem.paper import L0_MM, TABLE3_CSV, equation7_err_pct
from fem.records import provenance
from mkm.figures import run_figure, surrogate_fe_figure
from mkm.html import (
    esc,
    figure_html,
    flatten,
    html_page,
    kv_html,
    provenance_links,
    save_figure,
    table_html,
)
from mkm.paths import default_out
from mkm.prediction_cache import DEFAULT_CACHE_DIR, cached_predict, model_version
from mkm.registry import Spec, parse_spec

DEFAULT_MODELS = ("eq2", "thickwall", "axisym", "surrogate")
CACHED_MODELS = ("axisym",)  # seconds per sweep; the closed forms and surrogates take microseconds


def predict_steps(model: ForceModel, steps: pd.DataFrame, muscle: dict, cache_dir,
                  pressure_tolerance_bar: float = 0.0) -> tuple[Prediction, bool]:
    """Model forces at each step's measured mean pressure (through the cache for FE models).

    A measured pressure within ``pressure_tolerance_bar`` (the regulator's settling tolerance)
    outside a model's pressure domain is evaluated at the domain's edge: 2.5001 bar measured at
    the 2.5 bar step is the 2.5 bar the surrogate was trained to, not an extrapolation.
    """
    pressure = domain_pressures(model, evaluation_pressures(steps), pressure_tolerance_bar)
    args = (pressure, muscle["D0_mm"], muscle["t0_mm"], muscle["eps"])
    if model.name in CACHED_MODELS:
        return cached_predict(model, *args, cache_dir=cache_dir)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # out-of-domain points are flagged in the report itself
        return model.predict(*args), False


def domain_pressures(model: ForceModel, pressure_bar: np.ndarray,
                     tolerance_bar: float) -> np.ndarray:
    """``pressure_bar`` with values within ``tolerance_bar`` of the model's pressure domain
    moved onto its edge (models without a ``domain`` are left alone)."""
    domain = getattr(model, "domain", None)
    if domain is None or tolerance_bar <= 0:
        return pressure_bar
    lo, hi = domain.pressure_bar
    near = (pressure_bar >= lo - tolerance_bar) & (pressure_bar <= hi + tolerance_bar)
    return np.where(near, np.clip(pressure_bar, lo, hi), pressure_bar)


def evaluation_pressures(steps: pd.DataFrame) -> np.ndarray:
    """Measured mean pressure per step (set pressure where none was measured), floored at 0 bar:
    a mean of -0.003 bar at the vented step is sensor noise, not a vacuum."""
    measured = steps["pressure_bar_mean"].fillna(steps["set_pressure_bar"])
    return np.maximum(measured.to_numpy(dtype=float), 0.0)


def score_run(steps: pd.DataFrame, prediction: Prediction, label: str) -> pd.DataFrame:
    """One row per step: measurement, the model's force, validity and Err% (Equation 7)."""
    scale = float(np.nanmax(steps["force_N_mean"].to_numpy(dtype=float)))
    valid = np.ravel(prediction.valid)
    force = np.where(valid, np.ravel(prediction.force_N), np.nan)
    rows = pd.DataFrame({
        "model": label, "step": steps["step"].to_numpy(), "direction": steps["direction"],
        "set_pressure_bar": steps["set_pressure_bar"].to_numpy(),
        "pressure_bar": np.ravel(prediction.pressure_bar),
        "force_meas_N": steps["force_N_mean"].to_numpy(),
        "force_meas_std_N": steps["force_N_std"].to_numpy(),
        "force_N": force, "valid": valid, "settled": steps["settled"].to_numpy(),
    })
    rows["err_pct"] = equation7_err_pct(rows["force_meas_N"], rows["force_N"], scale)
    for key, value in prediction.extras.items():
        rows[key] = np.ravel(value)
    return rows


def summarise(scored: pd.DataFrame, seconds: float, cached: bool) -> dict:
    """Numbers per model and run: points, valid points, largest |Err%|, RMSE [N] and largest
    |residual| [N] over the valid points, seconds per predicted force, from the cache (1/0)."""
    ok = scored[scored["valid"]]
    residual = ok["force_meas_N"] - ok["force_N"]
    return {
        "model": scored["model"].iloc[0],
        "points": len(scored), "valid_points": len(ok),
        "max_abs_err_pct": float(ok["err_pct"].abs().max()) if len(ok) else np.nan,
        "rmse_N": float(np.sqrt(np.mean(residual**2))) if len(ok) else np.nan,
        "max_abs_residual_N": float(residual.abs().max()) if len(ok) else np.nan,
        "seconds_per_point": seconds / max(len(scored), 1),
        "from_cache": int(cached),
    }


# --- the report -------------------------------------------------------------------------------


def build_report(run_dirs, models=DEFAULT_MODELS, out_dir=None,
                 cache_dir: Path | str | None = DEFAULT_CACHE_DIR,
                 tolerance: float | None = 0.02, surrogate_section: bool = True,
                 progress: bool = False) -> Path:
    """Write ``report.html`` (plus PNGs and CSVs) for bench runs into ``out_dir``; return its path.

    Parameters
    ----------
    run_dirs : list of path
        Run folders written by ``mkm acquire`` (real or simulated; aborted ones included).
    models : iterable of str
        Model specs (``eq2``, ``thickwall``, ``axisym:mesh=coarse``, ``surrogate`` or
        ``surrogate:PATH``), drawn in this order.
    out_dir : path, optional
        Output folder (default ``reports/<first run folder name>``).
    cache_dir : path or None
        FE prediction cache (None: no cache).
    tolerance : float or None
        Tolerance of the ``auto`` model choice shown per run (a fraction); None leaves the
        choice out.
    surrogate_section : bool
        Add the comparison of the default surrogate with the FE model on the test muscles.
    """
    from bench.storage import load_run

    start = time.perf_counter()
    run_dirs = [Path(p) for p in run_dirs]
    if not run_dirs:
        raise ValueError("no run folder given: expected at least one RUN_DIR")
    specs = [m if isinstance(m, Spec) else parse_spec(m) for m in models]
    out = Path(out_dir) if out_dir else default_out("report", run_dirs[0].name)
    out.mkdir(parents=True, exist_ok=True)
    prov: dict[str, dict] = {"software": provenance()}
    sections, summaries, notes = [], [], []

    for k, run_dir in enumerate(run_dirs, start=1):
        run = load_run(run_dir)
        sections.append(_run_section(k, run, specs, out, cache_dir, tolerance, prov,
                                     summaries, notes))

    if surrogate_section:
        sections.append(_surrogate_section(out, prov))
    summary = pd.DataFrame(summaries)
    summary.to_csv(out / "summary.csv", index=False)
    elapsed = time.perf_counter() - start
    intro = (f"<p>Generated {esc(prov['software']['date_utc'])} by "
             f"<code>{esc(prov['software']['command'])}</code> in {elapsed:.1f} s. "
             f"{len(run_dirs)} run(s); models: {esc(', '.join(s.text for s in specs))}. "
             "Err% is the paper's Equation 7, (F_meas − F_model) / max F_meas over the run, "
             "in %; points where a model is invalid or outside its domain are drawn as grey "
             "crosses and left out of every number.</p>")
    body = intro + "".join(sections) + _provenance_section(prov)
    path = out / "report.html"
    path.write_text(html_page("McKibben muscle validation report", body), encoding="utf-8")
    return path


def _run_section(k, run, specs, out, cache_dir, tolerance, prov, summaries, notes) -> str:
    meta = run.meta
    muscle = meta.get("muscle", {})
    run_key = f"run-{k}"
    prov[run_key] = {"path": str(run.path), **{key: meta.get(key) for key in
                                                ("provenance", "versions", "command")
                                                if key in meta}}
    status = str(run.status)
    steps = run.steps
    head = [f'<section class="run-head"><h2>Run {k}: {esc(Path(run.path).name)}</h2>',
            f'<p><span class="status status-{"complete" if run.complete else "other"}">'
            f"status: {esc(status)}</span>"]
    if not run.complete:
        head.append(f" — reason: {esc(meta.get('reason') or 'not recorded')}. Kept: "
                    f"{len(steps)} settled step(s) of {_planned_steps(meta)}, "
                    f"{len(run.samples)} sample(s). Only what was kept is scored below.")
    head.append("</p>")
    hardware = meta.get("hardware", {})
    head.append(kv_html({
        "muscle": f"{muscle.get('id', '?')}: D0 = {muscle.get('D0_mm')} mm, "
                  f"t0 = {muscle.get('t0_mm')} mm, L0 = {muscle.get('L0_mm')} mm",
        "shortening ratio eps": f"{100 * float(muscle.get('eps', np.nan)):.1f} %",
        "hardware": ", ".join(f"{a}={b}" for a, b in hardware.items()
                              if not isinstance(b, dict | list)),
        "calibration": flatten(meta.get("calibration", {})),
        "tare": flatten(meta.get("tare", {})),
    }))
    sim = hardware.get("sim") if hardware.get("simulated") else None
    if isinstance(sim, dict):
        head.append(f'<p class="note">Simulated run: the "measured" force is the '
                    f"{esc(sim.get('model', '?'))} model's, with hysteresis "
                    f"{100 * float(sim.get('hysteresis_fraction', 0)):g} %, creep "
                    f"{100 * float(sim.get('creep_fraction', 0)):g} % and load-cell noise "
                    f"(seed {esc(sim.get('seed'))}): agreement with that model is by "
                    "construction, not evidence about a real muscle.</p>")
    unsettled = int((~steps["settled"].astype(bool)).sum()) if len(steps) else 0
    if unsettled:
        head.append(f'<p class="note">{unsettled} step(s) did not settle before the timeout: '
                    "kept, scored and marked settled = false in the CSV.</p>")
    if run.problems:
        head.append('<p class="note">Loader: ' + esc("; ".join(run.problems)) + "</p>")
    head.append("</section>")
    if steps.empty:
        return "".join(head) + '<p class="note">No step was kept: nothing to compare.</p>'

    scored, keys = [], [run_key]
    for spec in specs:
        model = spec.build(L0_mm=float(muscle.get("L0_mm", L0_MM)))
        pred, cached = predict_steps(model, steps, muscle, cache_dir,
                                     _pressure_tolerance(meta))
        rows = score_run(steps, pred, spec.text)
        scored.append(rows)
        summaries.append({"run": Path(run.path).name, **summarise(rows, pred.seconds, cached)})
        key = f"model-{spec.text}"
        prov[key] = {"model": model.name, "params": pred.params, "version": model_version(model)}
        keys.append(key)
    scored = pd.concat(scored, ignore_index=True)
    stem = f"run{k}"
    scored.to_csv(out / f"{stem}_errors.csv", index=False, float_format="%.6g")
    fig_path = save_figure(run_figure(steps, scored, f"run {k}: {muscle.get('id', '')}, "
                                      f"eps = {100 * float(muscle.get('eps', 0)):.1f} %"),
                           out / f"{stem}_force_error.png")
    run_summary = pd.DataFrame([s for s in summaries if s["run"] == Path(run.path).name])
    parts = head + [
        figure_html(fig_path, "Left: measured force per pressure step (mean ± std; filled "
                    "circles up sweep, open squares down sweep) with each model on the same "
                    "axes. Right: Err% per pressure step of each model against the "
                    "measurement (solid up, dashed down). " + provenance_links(keys)),
        table_html(run_summary.drop(columns="run"),
                   f"Summary per model (files: {stem}_errors.csv, summary.csv). "
                   + provenance_links(keys)),
        _invalid_note(scored),
        _auto_paragraph(steps, muscle, tolerance) if tolerance else "",
    ]
    return "".join(parts)


def _pressure_tolerance(meta: dict) -> float:
    """The run's regulator settling tolerance [bar] (0 if not recorded)."""
    settle = meta.get("sequence", {}).get("settle", {})
    return float(settle.get("pressure_tolerance_bar", 0.0) or 0.0)


def _planned_steps(meta: dict) -> str:
    sequence = meta.get("sequence", {})
    for key in ("n_steps", "planned_steps"):
        if key in sequence:
            return str(sequence[key])
    steps = sequence.get("steps")
    return str(len(steps)) if isinstance(steps, list) else "an unrecorded number planned"


def _invalid_note(scored: pd.DataFrame) -> str:
    bad = scored[~scored["valid"]]
    if bad.empty:
        return ""
    items = [f"{esc(m)}: {len(rows)} point(s) at "
             f"{', '.join(f'{p:.2f}' for p in sorted(rows['pressure_bar'].unique()))} bar"
             for m, rows in bad.groupby("model", sort=False)]
    return ('<p class="note">No valid number (invalid, out of domain or not converged), shown '
            "as crosses and excluded from the summary: " + "; ".join(items) + ".</p>")


def _auto_paragraph(steps, muscle, tolerance) -> str:
    """What ``--model auto`` would use for this run's points (the choice only: the fallback FE is
    not solved for it)."""
    from mkm.auto import MODEL_ERRORS_FILE, AutoModel, explain

    if not MODEL_ERRORS_FILE.exists():
        return ('<p class="note">Model choice: no study table (fem/model_errors.csv); run '
                "<code>mkm study</code>.</p>")
    choice = AutoModel(tolerance=tolerance).choose(evaluation_pressures(steps), muscle["D0_mm"],
                                                  muscle["t0_mm"], muscle["eps"])
    lines = "<br>".join(esc(line) for line in explain(choice, tolerance).splitlines())
    return (f"<p><b>Model choice for this scene</b> (<code>--model auto --tolerance "
            f"{100 * tolerance:g}%</code>, from the study table fem/model_errors.csv):<br>"
            f"{lines}.</p>")


def _surrogate_section(out: Path, prov: dict) -> str:
    """The paper's Table 3 and Figure 6 with our numbers: the default surrogate against our FE
    reference of the test muscles (the paper's I, II, III and the surrogate package's off-grid
    ones), computed by :mod:`surrogate.testset`."""
    head = "<h2>Surrogate against the FE model on the paper's test muscles I, II, III</h2>"
    import surrogate
    from surrogate.testset import FE_REFERENCE, compare_on_test_muscles, read_fe_reference

    if not FE_REFERENCE.exists():
        return head + (f'<p class="note">No FE reference at {esc(FE_REFERENCE)}: build it '
                       "with the surrogate package's reference command.</p>")
    model = surrogate.default_model()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # out-of-domain points are flagged per point below
        points, summary = compare_on_test_muscles(model, read_fe_reference())
    points = points.rename(columns={"force_pred_N": "force_N"})
    points["err_pct"] = points["err_pct"].where(points["valid"])
    result = summary.drop(columns=["model", "seconds_all_points"]).rename(columns={
        "max_abs_err_pct": "largest |Err%|", "rmse_N": "RMSE [N]",
        "max_abs_error_N": "largest |error| [N]", "all_valid": "all points valid"})
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
                         "trained": model.metadata.get("trained"),
                         "dataset": model.metadata.get("dataset"),
                         f"seconds_{len(points)}_points": seconds}
    prov["fe-reference"] = {"file": FE_REFERENCE.name, "header": _comment_header(FE_REFERENCE)}
    keys = ["surrogate", "fe-reference"]
    fig_path = save_figure(surrogate_fe_figure(points, f"{model.name} against our FE model "
                                               "(the paper's Figure 6)"),
                           out / "surrogate_vs_fe.png")
    return head + "".join([
        table_html(result, "The paper's Table 3 with our numbers: largest |Err%| (Equation 7), "
                   "RMSE and largest error of the default surrogate against our FE model "
                   f"(I-III: the paper's muscles; others: off-grid muscles). All {len(points)} "
                   f"points predicted in one call in {1e3 * seconds:.2f} ms (the paper: 131 ms "
                   "for 33). " + provenance_links(keys)),
        figure_html(fig_path, "FE forces (dots) and the surrogate (lines) per test muscle; "
                    "right: Err% per pressure. " + provenance_links(keys)),
    ])


def _comment_header(path: Path) -> list[str]:
    lines = []
    with open(path, encoding="utf-8") as f:
        for line in f:
            if not line.startswith("#"):
                break
            lines.append(line[1:].strip())
    return lines


def _provenance_section(prov: dict) -> str:
    items = "".join(f'<h3 id="prov-{esc(k)}">{esc(k)}</h3><pre>'
                    f"{esc(json.dumps(v, indent=1, default=str))}</pre>" for k, v in prov.items())
    return "<h2>Provenance</h2>" + items
