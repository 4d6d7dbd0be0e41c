"""Stability map of the axisymmetric FE model: random isometric sweeps over the box, counted by
outcome per mesh and braid.

Run outside the test suite:

    .venv/bin/python benchmarks/bench_stability_map.py [--sweeps 1260] [--seed 20261201]
        [--meshes coarse,medium,fine] [--braids bonded,sliding]
        [--limit fine=60] [--out stability_map.csv]

The box: eps 0-0.3, t0 1-5 mm, D0 20-60 mm, theta0 20-45 deg, L0 100-600 mm (uniform draws,
Silastic S), pressures 0-5 bar. Each muscle is drawn once from the seed, so the first N muscles
are the same on every mesh and braid (``--limit fine=60`` runs the first 60 there only: a
fine-mesh sweep costs about ten medium ones). A sweep is two solves: the grid 0, 0.5, ..., 5 bar,
then three pressures just above its threshold P* (P* + 0.0005, 0.002 and 0.008 bar: the widths
of the band where the held cap inherited the threshold state's corner compression). A sweep is
converged when every point is; otherwise it is counted under the first failed point's reason,
with its numbers stripped. A converged sweep whose force falls with pressure anywhere above P*
(by more than 1e-6 of its largest force) is counted as ``converged, not monotone``: a converged
force that is wrong. Prints the counts per mesh and braid and writes one row per sweep (with
the muscle, P*, the reason, the wall time) to ``--out`` with a provenance JSON beside it.
"""

from __future__ import annotations

import argparse
import collections
import json
import re
import time
from pathlib import Path

import numpy as np

from mkm.core.records import provenance, source_version
from mkm.fem.fe.model import isometric_sweep

BOX = {"eps": (0.0, 0.3), "t0_mm": (1.0, 5.0), "D0_mm": (20.0, 60.0), "theta0_deg": (20.0, 45.0),
       "L0_mm": (100.0, 600.0)}
GRID_BAR = np.linspace(0.0, 5.0, 11)
ABOVE_THRESHOLD_BAR = np.array([0.0005, 0.002, 0.008])


def draw_muscles(n: int, seed: int) -> list[dict[str, float]]:
    """``n`` muscles drawn uniformly from :data:`BOX` (the same first muscles for any ``n``)."""
    rng = np.random.default_rng(seed)
    return [{k: float(rng.uniform(lo, hi)) for k, (lo, hi) in BOX.items()} for _ in range(n)]


def reason_class(failure: str) -> str:
    """A failure reason without its numbers (``at 0.146 bar`` -> ``at # bar``)."""
    return re.sub(r"-?\d+(\.\d+)?(e-?\d+)?", "#", failure)


def run_sweep(muscle: dict, mesh: str, braid: str) -> dict:
    start = time.perf_counter()
    args = (muscle["D0_mm"], muscle["t0_mm"], muscle["eps"], muscle["theta0_deg"],
            muscle["L0_mm"], mesh)
    grid = isometric_sweep(GRID_BAR, *args, braid=braid)
    threshold = float(grid["threshold_pressure_bar"][0])
    P, parts = GRID_BAR, [grid]
    if np.isfinite(threshold) and threshold > 0:
        band = threshold + ABOVE_THRESHOLD_BAR
        parts.append(isometric_sweep(band, *args, braid=braid))
        P = np.concatenate([GRID_BAR, band])
    force = np.concatenate([p["force_N"] for p in parts])
    failure = np.concatenate([p["failure"] for p in parts])
    converged = np.concatenate([p["converged"] for p in parts])
    if converged.all():
        order = np.argsort(P)
        rising = np.diff(force[order])
        monotone = bool(np.all(rising >= -1e-6 * max(np.abs(force).max(), 1.0)))
        outcome = "converged" if monotone else "converged, not monotone"
    else:
        outcome = reason_class(str(failure[np.flatnonzero(~converged)[0]]))
    return {**muscle, "mesh": mesh, "braid": braid, "threshold_pressure_bar": threshold,
            "outcome": outcome, "seconds": time.perf_counter() - start}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sweeps", type=int, default=1260)
    parser.add_argument("--seed", type=int, default=20261201)
    parser.add_argument("--meshes", default="coarse,medium,fine")
    parser.add_argument("--braids", default="bonded,sliding")
    parser.add_argument("--limit", default="", help="mesh=n,...: fewer sweeps on a mesh")
    parser.add_argument("--out", default="stability_map.csv")
    args = parser.parse_args()
    limits = {k: int(v) for k, v in (item.split("=") for item in args.limit.split(",") if item)}
    muscles = draw_muscles(args.sweeps, args.seed)
    rows = []
    for mesh in args.meshes.split(","):
        for braid in args.braids.split(","):
            for muscle in muscles[:limits.get(mesh, args.sweeps)]:
                rows.append(run_sweep(muscle, mesh, braid))
            done = [r for r in rows if r["mesh"] == mesh and r["braid"] == braid]
            counts = collections.Counter(r["outcome"] for r in done)
            seconds = np.median([r["seconds"] for r in done])
            print(f"{mesh} {braid}: {len(done)} sweeps, median {seconds:.2f} s per sweep")
            for outcome, count in counts.most_common():
                print(f"  {count:5d}  {outcome}")
    out = Path(args.out)
    columns = list(rows[0])
    with open(out, "w", encoding="utf-8", newline="\n") as f:
        f.write(",".join(columns) + "\n")
        for r in rows:
            f.write(",".join(json.dumps(r[c]) if isinstance(r[c], str) else f"{r[c]:.6g}"
                             for c in columns) + "\n")
    info = {**provenance(), "code_version": source_version("mkm.fem.fe.model"),
            "seed": args.seed, "sweeps": args.sweeps, "limits": limits, "box": BOX,
            "grid_bar": GRID_BAR.tolist(), "above_threshold_bar": ABOVE_THRESHOLD_BAR.tolist()}
    out.with_suffix(".json").write_text(json.dumps(info, indent=1), encoding="utf-8")
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
