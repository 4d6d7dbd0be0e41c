"""Stability map over the practical range: fresh random muscles, every physics model, each sweep
counted by outcome, every failure with its reason.

Run outside the test suite:

    .venv/bin/python benchmarks/bench_stability_map.py [--muscles 60] [--seed N]
        [--models SPEC,...] [--limit SPEC=n;...]
        [--out docs/measured/stability_map.json]

The muscles are drawn by :func:`mkm.fem.sampling.draw_muscles` from
:data:`mkm.fem.limits.PRACTICAL_RANGE` (the seed is a fresh one unless given, and recorded:
``--seed`` draws the same muscles again); each keeps its own length, braid angle and rubber.
Each model (a registry spec; default every physics variant the study scores but the fine mesh:
Equation 2 on both diameters, thick-wall, the FE coarse and medium meshes and the sliding braid)
predicts each muscle's isometric sweep over the range's pressures
(0 to its top in 0.5 bar steps) and, for a model with a threshold P*, three pressures just above
it (P* + 0.0005, 0.002 and 0.008 bar: the band where the held cap inherits the threshold
state's corner compression). A sweep's outcome is the first non-``ok`` status of its points by
the one classification every consumer uses (:func:`mkm.fem.outcomes.classify`: a physical
limit the model names, ``braid locks`` where the braid reaches its locking angle before the
held shortening; not converged, a failure of the solver; invalid by the model's own limit,
negative force, force falling with pressure by more than
:data:`mkm.fem.outcomes.FORCE_NOISE_N`), with the reason the model gave and its numbers
stripped; a model that refuses the muscle outright is ``refused`` with its message.

Writes ``--out``, a JSON (provenance, the draw's seed and box, the range stated, and under
``rows`` the counts per model, outcome and reason: the table the docs show), and beside it a
CSV of one row per muscle and model (the muscle and its eps as a fraction of the braid lock,
P*, the outcome, the reason, the first failing pressure, the largest force, the wall time);
prints the counts.
"""

from __future__ import annotations

import argparse
import collections
import re
import time
from pathlib import Path

import numpy as np
import pandas as pd

from mkm.core.records import provenance, source_version, write_json_atomic
from mkm.fem import ladder
from mkm.fem.limits import PRACTICAL_RANGE, lock_eps, range_text
from mkm.fem.outcomes import classify
from mkm.fem.sampling import draw_muscles
from mkm.registry import parse_spec


def default_models() -> str:
    """Every physics variant the study scores (the registry's), the fine mesh left out: a
    fine sweep costs several medium ones (``--models`` adds it)."""
    return ",".join(v.spec for entry in ladder.MODELS.entries() for v in entry.study
                    if "mesh=fine" not in v.spec)

STEP_BAR = 0.5
ABOVE_THRESHOLD_BAR = np.array([0.0005, 0.002, 0.008])


def reason_class(failure: str) -> str:
    """A failure reason without its numbers (``at 0.146 bar`` -> ``at # bar``)."""
    return re.sub(r"-?\d+(\.\d+)?(e-?\d+)?", "#", failure)


def grid_bar() -> np.ndarray:
    low, high = PRACTICAL_RANGE.pressure_bar
    return np.arange(low, high + STEP_BAR / 2, STEP_BAR)


def run_sweep(spec: str, muscle) -> dict:
    """One muscle's sweep by one model: its outcome, reason and cost."""
    start = time.perf_counter()
    row = {"threshold_pressure_bar": np.nan, "outcome": "ok", "reason": "",
           "first_failing_pressure_bar": np.nan, "largest_force_N": np.nan}
    try:
        model = parse_spec(spec).build(muscle=muscle)
        parts = [model.predict_muscle(muscle, grid_bar())]
        threshold = float(np.ravel(parts[0].extras.get("threshold_pressure_bar", [np.nan]))[0])
        if np.isfinite(threshold) and 0 < threshold < PRACTICAL_RANGE.pressure_bar[1]:
            parts.append(model.predict_muscle(muscle, threshold + ABOVE_THRESHOLD_BAR))
    except ValueError as exc:  # the model refuses the muscle: its own limit, stated
        return {**row, "outcome": "refused", "reason": str(exc),
                "seconds": time.perf_counter() - start}
    row["threshold_pressure_bar"] = threshold
    P = np.concatenate([np.ravel(p.pressure_bar) for p in parts])
    force = np.concatenate([np.ravel(p.force_N) for p in parts])
    status = np.concatenate([classify(p) for p in parts])
    messages = np.concatenate([np.ravel(p.extras.get("failure", np.full(p.force_N.size, "")))
                               for p in parts]).astype(str)
    row["largest_force_N"] = float(np.nanmax(force)) if np.isfinite(force).any() else np.nan
    bad = np.flatnonzero(status != "ok")
    if bad.size:
        first = bad[np.argmin(P[bad])]
        row.update(outcome=str(status[first]), reason=reason_class(messages[first]),
                   first_failing_pressure_bar=float(P[first]))
    return {**row, "seconds": time.perf_counter() - start}


def counts_table(frame: pd.DataFrame) -> pd.DataFrame:
    """Per model: sweeps, and how many per outcome and reason."""
    rows = []
    for model, g in frame.groupby("model", sort=False):
        reasons = g["reason"].fillna("")
        outcomes = collections.Counter(zip(g["outcome"], reasons, strict=True))
        for (outcome, reason), count in outcomes.most_common():
            these = g[(g["outcome"] == outcome) & (reasons == reason)]
            rows.append({"model": model, "sweeps": len(g), "outcome": outcome,
                         "count": count, "reason": reason,
                         # where the failures lie: how close to the braid lock
                         "smallest eps/lock": (float(f"{these['eps_per_lock'].min():.3g}")
                                               if outcome != "ok" else None),
                         "median seconds per sweep": float(f"{g['seconds'].median():.3g}")})
    return pd.DataFrame(rows)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--muscles", type=int, default=60)
    parser.add_argument("--seed", type=int, default=None,
                        help="draw these muscles again (default: a fresh seed, recorded)")
    parser.add_argument("--models", default=default_models(),
                        help="registry specs, comma separated")
    parser.add_argument("--limit", default="", help="spec=n;...: the first n muscles only")
    parser.add_argument("--out", default="stability_map.json")
    args = parser.parse_args()
    limits = {k: int(v) for k, v in (item.rsplit("=", 1) for item in args.limit.split(";")
                                     if item)}
    draw = draw_muscles(args.muscles, args.seed)
    rows = []
    for spec in args.models.split(","):
        for i, muscle in enumerate(draw.muscles[:limits.get(spec, args.muscles)]):
            rows.append({"muscle": i, **{k: v for k, v in muscle.record().items() if k != "id"},
                         "eps_per_lock": muscle.eps / float(lock_eps(muscle.theta0_deg)),
                         "model": spec, **run_sweep(spec, muscle)})
        done = pd.DataFrame([r for r in rows if r["model"] == spec])
        print(f"{spec}: {len(done)} sweeps, median {done['seconds'].median():.3f} s per sweep")
        for (outcome, reason), n in collections.Counter(
                zip(done["outcome"], done["reason"], strict=True)).most_common():
            print(f"  {n:5d}  {outcome}{': ' + reason if reason else ''}")
    frame = pd.DataFrame(rows)
    out = Path(args.out)
    out.parent.mkdir(parents=True, exist_ok=True)
    frame.to_csv(out.with_suffix(".csv"), index=False, float_format="%.6g",
                 lineterminator="\n")
    info = {**provenance(), "code_version": source_version("mkm.fem.fe.model"),
            "seed": draw.seed, "draw": draw.record(), "range": range_text(),
            "models": args.models.split(","),
            "limits": limits, "grid_bar": grid_bar().tolist(),
            "above_threshold_bar": ABOVE_THRESHOLD_BAR.tolist(),
            "rows": counts_table(frame).to_dict(orient="records")}
    write_json_atomic(out, info)
    print(f"wrote {out} (seed {draw.seed})")


if __name__ == "__main__":
    main()
