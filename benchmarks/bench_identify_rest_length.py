"""``mkm identify --params theta0,rubber,L0`` on the Martens and Boblan maps, as a lab reads them.

Run outside the test suite:

    .venv/bin/python benchmarks/bench_identify_rest_length.py [--out FILE.json]

Each Festo muscle of ``martens_boblan_2017_forcemaps.csv`` is imported as the table gives it
(``mkm import``: its longest length is its rest length, 296 mm for the DMSP-20-300, 250 mm for
the DMSP-10-250; the wall the file's third-party 1.8 mm) with the accuracy the published-data
guide declares, and identified on the rest-length run and one other held length with force,
for every such pair (``--search model``): with the thick-wall form, theta0 and one rubber scale
alone (the rest length the table's) and with the rest length fitted (``L0``); with the FE model
(``axisym:mesh=coarse``) and the rest length fitted. Each fit predicts every held length of the
map; the
score is the threshold study's (``bench_threshold_models.py``): the largest error as % of the
muscle's largest force, a slack entry charged for the pull predicted there. Also recorded: the
fitted rest length against Festo's nominal one, the threshold the identified muscle has at the
table's longest length against the measured bracket (the table's last slack entry and its first
force) and the line through its two lowest forces, chi2/nu of the fit, and its wall time.

``--pairs shortened`` fits two shortened lengths instead, the rest-length run left out (the
first shortened length with force and each of the next two), and records the fitted rest
length's interval, whether the fit was ready (within the noise) and whether identify said its
rest length was extrapolated.
"""

from __future__ import annotations

import argparse
import tempfile
import time
from pathlib import Path

import numpy as np
from bench_threshold_models import NOMINAL_LENGTH_MM, read_maps

from mkm.bench.exchange import import_table, parse_accuracy
from mkm.core.records import provenance, write_json_atomic
from mkm.identify import identify
from mkm.identify.fitting import ModelStatic, step_predictions
from mkm.identify.goodness import threshold_row
from mkm.identify.result import REST_EXTRAPOLATED_NOTE
from mkm.identify.runs import load_runs
from mkm.paths import published_table

TABLE = published_table("martens_boblan_2017_forcemaps.csv")
#: as docs/published.md imports them (the id, the maker's diameter, a third party's wall)
MUSCLES = {"Festo DMSP-10-250": ("dmsp-10", "force=0.5N+1%,pressure=0.01bar"),
           "Festo DMSP-20-300": ("dmsp-20", "force=1N+1%,pressure=0.01bar")}
#: (model, what is fitted): the thick-wall form with and without the rest length, the FE
#: model (coarse mesh: within 2e-4 of the fine one's force here) with it
FITS = (("thickwall", "theta0,rubber"), ("thickwall", "theta0,rubber,L0"),
        ("axisym:mesh=coarse", "theta0,rubber,L0"))


def fits_arg(text: str) -> tuple:
    """``MODEL:PARAMS`` pairs separated by ``;`` (a model spec may hold ``:``: the last one
    splits)."""
    return tuple(tuple(fit.rsplit(":", 1)) for fit in text.split(";"))


def imported(force_map, out: Path, ratio: float | None = None) -> list:
    """The map's runs as ``mkm import`` writes them (as identify reads them), by eps; with a
    rubber of C01/C10 ``ratio`` declared (``--C10 0.3 --C01 0.3*ratio``: identify's assumed
    ratio, its scale fitted)."""
    run_id, accuracy = MUSCLES[force_map.muscle]
    rubber = {} if ratio is None else {"C10_MPa": 0.3, "C01_MPa": 0.3 * ratio}
    runs = import_table(TABLE, out, {"id": run_id, "D0_mm": force_map.D0_mm,
                                     "t0_mm": force_map.t0_mm, "L0_mm": None, "eps": None,
                                     **rubber},
                        select=force_map.muscle, accuracy=parse_accuracy(accuracy))
    return sorted(load_runs([run.path for run in runs]), key=lambda run: run.eps)


def score(data, result, force_map, model: str) -> dict:
    """Each held length's largest error as % of the muscle's largest force (a slack step's
    measured 0 N: charged for the pull predicted there)."""
    values, static = result.fit.values, ModelStatic(model, cache_dir=None)
    predicted = step_predictions(static, data, values)
    top = force_map.largest_force_N
    errors = {round(r.eps, 4): float(np.max(np.abs(p - r.steps["force_N_mean"].to_numpy())))
              / top * 100.0 for r, p in zip(data, predicted, strict=True)}
    threshold = threshold_row(data[0], static, values)
    return {"errors": errors, "threshold_bar": threshold["fitted threshold [bar]"]}


def pairs_of(runs: list, which: str) -> list[list]:
    """The pairs of lengths a lab fits: ``rest``, the rest-length run with each other length
    with force (one slack throughout fixes nothing); ``shortened``, the first shortened length
    with force with each of the next two, the rest-length run left out (its rest length then
    extrapolated)."""
    loaded = [r for r in runs[1:] if r.steps["force_N_mean"].max() > 0]
    if which == "rest":
        return [[runs[0], other] for other in loaded]
    return [[loaded[0], other] for other in loaded[1:3]]


def study(out: Path, fits=FITS, ratio: float | None = None, which: str = "rest") -> list[dict]:
    rows = []
    for force_map in read_maps():
        runs = imported(force_map, out / force_map.muscle.replace(" ", "_"), ratio)
        measured = force_map.measured_threshold_bar()
        for pair in pairs_of(runs, which):
            for model, params in fits:
                started = time.perf_counter()
                result = identify([r.path for r in pair], params=params, model=model,
                                  search="model", cache_dir=None)
                seconds = time.perf_counter() - started
                scored = score(runs, result, force_map, model)
                trained = {round(r.eps, 4) for r in pair}
                held = {e: v for e, v in scored["errors"].items() if e not in trained}
                fitted_L0 = result.fit.values.get("L0_mm", force_map.table_L0_mm)
                rows.append({
                    "muscle": force_map.muscle, "model": model,
                    "fitted": params.replace(",", ", "),
                    "trained on eps": ", ".join(f"{r.eps:g}" for r in pair),
                    "L0 mm": round(fitted_L0, 2),
                    **({"L0 95 % CI mm": [round(v, 2) for v in
                                          result.bootstrap["interval"]["L0_mm"]],
                        "ready": not result.goodness.misfit,
                        "extrapolation said": any(n.startswith(REST_EXTRAPOLATED_NOTE)
                                                  for n in result.notes)}
                       if which == "shortened" else {}),
                    **({"t0 mm": round(result.fit.values["t0_mm"], 3)}
                       if "t0_mm" in result.fit.values else {}),
                    "nominal L0 mm": NOMINAL_LENGTH_MM[force_map.muscle],
                    "theta0 deg": round(result.fit.values["theta0_deg"], 3),
                    "rubber x Silastic S": round(result.fit.values["rubber_scale"], 3),
                    "C01/C10": round(result.values["C01_MPa"] / result.values["C10_MPa"], 3),
                    "chi2/nu": round(result.goodness.reduced, 2),
                    "rest curve max err %": round(scored["errors"][0.0], 2),
                    "other trained max err %": round(scored["errors"][max(trained)], 2),
                    "held-out lengths max err %": round(max(held.values()), 2),
                    "worst held-out eps": max(held, key=held.get),
                    "P* at eps 0 bar": round(scored["threshold_bar"], 3),
                    "measured P* bar": round(measured["estimate_bar"], 3),
                    "measured bracket bar": f"{measured['low_bar']:g}-{measured['high_bar']:g}",
                    "seconds": round(seconds, 2)})
                print(rows[-1], flush=True)
    return rows


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="identify_rest_length.json")
    parser.add_argument("--fits", type=fits_arg, default=FITS, metavar="MODEL:PARAMS;...",
                        help="the fits, e.g. 'thickwall:theta0,rubber,L0,t0' (default: the "
                             "three above)")
    parser.add_argument("--C01-over-C10", type=float, default=None, dest="ratio",
                        help="declare a rubber of this C01/C10 on import, the ratio identify "
                             "assumes (default: none declared, Silastic S's)")
    parser.add_argument("--pairs", choices=("rest", "shortened"), default="rest",
                        help="rest: the rest-length run with each other length (default); "
                             "shortened: two shortened lengths, the rest-length run left out")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        rows = study(Path(folder), args.fits, args.ratio, args.pairs)
    write_json_atomic(Path(args.out), {**provenance(), "table": TABLE.name, "rows": rows})
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
