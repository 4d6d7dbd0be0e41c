"""The report's "identified muscle" section, shown when the calibration given holds one.

``mkm report RUN... --calibration DIR/calibration.json`` (a file ``mkm identify`` wrote) shows
the parameters with their intervals and what the runs could not tell; for each run of the report
the measured rising and falling steps with both branches the identified muscle predicts, the
hysteresis width per step, and the residuals before (the nominal model: the angle and rubber
the runs declare, else the shipped calibration's, no friction or creep) and after
identification; the identified muscle's threshold pressure at each run's eps against the
measured one
(:func:`mkm.identify.goodness.threshold_row`). The held-out check of the identification's own
runs comes first: the honest predictive error. Without an identified muscle in the
calibration, the section is empty.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd

from mkm.core.records import save_figure
from mkm.fem.calibration import Calibration
from mkm.fem.friction import DEFAULTS
from mkm.fem.materials import SILASTIC_S
from mkm.html import esc, figure_html, table_html
from mkm.identify import fitting
from mkm.identify.band import identified_entry
from mkm.identify.goodness import threshold_row
from mkm.identify.runs import load_run_data


def report_section(run_dirs, out: Path, calibration: Calibration | None = None) -> str:
    """The section's HTML (empty without an identified muscle in ``calibration``, default the
    shipped one); figures go into ``out``."""
    calibration = calibration or Calibration.shipped()
    found = identified_entry(calibration)
    if found is None:
        return ""
    key, entry = found
    ident = entry["identified"]
    parts = ['<h2 id="identified">Identified muscle</h2>',
             f"<p>From <code>{esc(calibration.path)}</code>, written by "
             f"<code>{esc(entry.get('command', ''))}</code> ({esc(entry.get('date_utc', ''))}) "
             f"from {len(ident.get('runs', []))} run(s): "
             f"{esc(', '.join(r['run'] for r in ident.get('runs', [])))}. Intervals: "
             f"{esc(ident.get('interval_method', 'not recorded'))}.</p>"]
    held = pd.DataFrame(ident.get("leave_one_run_out", []))
    columns = [f"{what}_{branch}_pct" for what in ("heldout", "length_heldout")
               for branch in ("rising", "falling") if f"{what}_{branch}_pct" in held]
    if columns:
        parts.append(table_html(held[["run", "eps", *(["L0_mm"] if "L0_mm" in held else []),
                                      *columns]],
                                "Predictive error first: each of the identification's runs "
                                "predicted by the FE model from the others (largest |Err%| "
                                "per branch; length_heldout: its whole length held out)."))
    else:
        parts.append('<p class="note">Predictive error not measured: one run, nothing to '
                     "hold out.</p>")
    table = pd.DataFrame(ident.get("parameters", []))
    table = table[[c for c in ("parameter", "value", "ci_low", "ci_high", "unit", "status",
                               "source") if c in table]].rename(columns={
        "ci_low": "95 % CI low", "ci_high": "95 % CI high"})
    parts.append(table_html(table, "Identified parameters (parameters.csv): fitted, derived "
                            "and assumed, with where each comes from.", digits=5))
    notes = list(ident.get("notes", [])) + [f"{g}: not warranted by the data (BIC), dropped"
                                             for g in ident.get("dropped", [])]
    if notes:
        parts.append('<p class="note">' + "<br>".join(esc(n) for n in notes) + "</p>")

    spec = key + (f":mesh={entry['model_params']['mesh']}"
                  if "mesh" in entry.get("model_params", {}) else "")
    fitted = {row["parameter"]: row["value"] for row in ident.get("parameters", [])
              if row.get("status", "fitted") == "fitted"}
    identified = fitting.internal_values({
        "theta0_deg": entry["theta0_deg"], "C10_MPa": entry.get("C10_MPa", SILASTIC_S.C10_MPa),
        "C01_MPa": entry.get("C01_MPa", SILASTIC_S.C01_MPa),
        **{k: entry.get(k, DEFAULTS[k]) for k in DEFAULTS},
        **({"gap_mm": entry["gap_mm"]} if "gap_mm" in entry else {}),
        **{k: fitted[k] for k in fitting.OPTIONAL if k in fitted and k != "gap_mm"}})
    rows, thresholds = [], []
    runs = [load_run_data(p) for p in run_dirs]
    static = fitting.ModelStatic(spec)
    nominal = fitting.nominal_muscle(static.spec, runs, Calibration.shipped())
    for k, run in enumerate(runs, start=1):
        try:
            after = fitting.step_predictions(static, [run], identified)[0]
            before = fitting.step_predictions(static, [run], nominal)[0]
        except fitting.NoValidForce as exc:
            # past the identified muscle's braid lock: no branch to draw, no threshold
            parts.append(f'<p class="note">Run {k} ({esc(run.name)}, eps = '
                         f"{100 * run.eps:.1f} %): not compared, {esc(str(exc))}.</p>")
            continue
        path = save_figure(_figure(run, before, after, k), Path(out) / f"identified_run{k}.png")
        parts.append(figure_html(path, f"Run {k} ({esc(run.name)}, eps = {100 * run.eps:.1f} %)."
                                 " Left: measured steps (filled up, open down) and the branches "
                                 "the identified muscle predicts. Middle: hysteresis width per "
                                 "pressure (falling minus rising). Right: residual measured "
                                 "minus model, nominal and identified."))
        thresholds.append(threshold_row(run, static, identified))
        scale = float(np.max(run.steps["force_N_mean"]))
        for label, predicted in (("nominal", before), ("identified", after)):
            # a run without force (slack all the way) has no Err%
            err = (100 * (run.steps["force_N_mean"].to_numpy() - predicted) / scale
                   if scale > 0 else np.full(len(predicted), np.nan))
            up = run.steps["direction"].to_numpy() == "up"
            rows.append({"run": run.name, "model": label,
                         "largest |Err%| rising": np.max(np.abs(err[up])) if up.any() else np.nan,
                         "largest |Err%| falling": (np.max(np.abs(err[~up])) if (~up).any()
                                                    else np.nan)})
    parts.append(table_html(pd.DataFrame(rows), "Before and after identification: largest "
                            "|Err%| (Equation 7) on each branch, the static model "
                            f"{esc(spec)} with friction and creep."))
    parts.append(table_html(pd.DataFrame(thresholds), "Threshold pressure at each run's eps: "
                            "the identified static model's (the pressure below which the held "
                            "muscle pulls nothing) against the measured one, the zero of the "
                            "least-squares line through the run's settled steps above its "
                            "noise floor.", digits=3))
    return "".join(parts)


def _figure(run, before, after, k: int):
    from matplotlib.figure import Figure

    steps = run.steps.assign(before=before, after=after)
    up, down = steps[steps["direction"] == "up"], steps[steps["direction"] == "down"]
    fig = Figure(figsize=(12, 3.6), layout="constrained")
    loop, width, resid = fig.subplots(1, 3)
    loop.plot(up["pressure_bar_mean"], up["force_N_mean"], "o", color="k", label="measured up")
    loop.plot(down["pressure_bar_mean"], down["force_N_mean"], "s", mfc="none", color="k",
              label="measured down")
    loop.plot(up["pressure_bar_mean"], up["after"], "-", color="tab:brown", label="rising")
    loop.plot(down["pressure_bar_mean"], down["after"], "--", color="tab:brown",
              label="falling")
    loop.set(xlabel="pressure [bar]", ylabel="force [N]", title=f"run {k}: loop")
    loop.legend(fontsize=8)
    both = up.merge(down, on="set_pressure_bar", suffixes=("_up", "_down"))
    width.plot(both["set_pressure_bar"], both["force_N_mean_down"] - both["force_N_mean_up"],
               "o", color="k", label="measured")
    width.plot(both["set_pressure_bar"], both["after_down"] - both["after_up"], "-",
               color="tab:brown", label="identified")
    width.set(xlabel="pressure [bar]", ylabel="falling - rising [N]", title="hysteresis width")
    width.legend(fontsize=8)
    for label, column, colour in (("nominal", "before", "tab:gray"),
                                  ("identified", "after", "tab:brown")):
        resid.plot(steps["pressure_bar_mean"], steps["force_N_mean"] - steps[column], "o",
                   color=colour, label=label)
    resid.axhline(0.0, color="k", lw=0.5)
    resid.set(xlabel="pressure [bar]", ylabel="measured - model [N]", title="residuals")
    resid.legend(fontsize=8)
    return fig
