"""Speed of the surrogates: prediction latency and training time.

Run outside the test suite:

    .venv/bin/python benchmarks/bench_surrogate.py [--dataset data/mkm_dataset.csv]
        [--repeats 200] [--grid-seeds 10] [--skip-grid] [--out FILE.json]

- the 33 test points of the paper (muscles I, II, III, 11 pressures each) in one ``predict``
  call, as a caller sees it (validation, domain check, features, estimator): median, 90th
  percentile, minimum and median CPU time over ``--repeats`` calls; the issue's goal is
  <= 0.5 ms median (the paper: 131 ms);
- single-point latency (one pressure of muscle I);
- training time of each named kind on the whole dataset (one fit, BLAS on one thread);
- wall time of the whole 27-net grid over ``--grid-seeds`` splits, both variants, on 2 cores.
"""

from __future__ import annotations

import argparse
import json
import time
import warnings

import numpy as np
from threadpoolctl import threadpool_limits

from fem.records import provenance
from surrogate.estimators import KINDS, make_estimator
from surrogate.model import SurrogateForceModel
from surrogate.testset import PAPER_MUSCLES, test_points
from surrogate.training_data import DEFAULT_DATASET, load_training_data


def timings(call, repeats: int) -> tuple[np.ndarray, np.ndarray]:
    """Wall and CPU seconds of ``repeats`` calls. On a shared machine the CPU time (what the
    call itself costs, without waiting for a core) is the steadier of the two."""
    call()  # warm caches (first call imports and allocates)
    wall, cpu = np.empty(repeats), np.empty(repeats)
    for i in range(repeats):
        start, start_cpu = time.perf_counter(), time.process_time()
        call()
        wall[i], cpu[i] = time.perf_counter() - start, time.process_time() - start_cpu
    return wall, cpu


def bench_kind(kind: str, data, repeats: int) -> dict:
    with threadpool_limits(limits=1), warnings.catch_warnings():
        warnings.simplefilter("ignore")
        start = time.perf_counter()
        estimator = make_estimator(kind).fit(data.X, data.y)
        fit_s = time.perf_counter() - start
    model = SurrogateForceModel(estimator, data.domain(), kind)
    points = test_points(PAPER_MUSCLES)
    inputs = [points[c].to_numpy() for c in ("pressure_bar", "D0_mm", "t0_mm", "eps")]
    batch, batch_cpu = timings(lambda: model.predict(*inputs), repeats)
    one = [x[1:2] for x in inputs]
    single, _ = timings(lambda: model.predict(*one), repeats)
    return {"kind": kind, "fit_s": fit_s, "points": len(points),
            "predict_33_median_s": float(np.median(batch)),
            "predict_33_p90_s": float(np.percentile(batch, 90)),
            "predict_33_min_s": float(np.min(batch)),
            "predict_33_cpu_median_s": float(np.median(batch_cpu)),
            "single_point_median_s": float(np.median(single))}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--dataset", default=str(DEFAULT_DATASET))
    parser.add_argument("--repeats", type=int, default=200)
    parser.add_argument("--grid-seeds", type=int, default=10)
    parser.add_argument("--skip-grid", action="store_true")
    parser.add_argument("--out", help="also write the results as JSON here")
    args = parser.parse_args()
    data = load_training_data(args.dataset)
    rows = [bench_kind(kind, data, args.repeats) for kind in KINDS]
    print(f"{'kind':18s} {'fit s':>8s} {'33 pts ms':>10s} {'p90 ms':>8s} {'min ms':>8s} "
          f"{'cpu ms':>8s} {'1 pt ms':>8s}")
    for r in rows:
        print(f"{r['kind']:18s} {r['fit_s']:8.3f} {1e3 * r['predict_33_median_s']:10.3f} "
              f"{1e3 * r['predict_33_p90_s']:8.3f} {1e3 * r['predict_33_min_s']:8.3f} "
              f"{1e3 * r['predict_33_cpu_median_s']:8.3f} "
              f"{1e3 * r['single_point_median_s']:8.3f}")
    result = {"dataset": args.dataset, "dataset_sha256": data.sha256, "kinds": rows,
              **provenance()}
    if not args.skip_grid:
        from surrogate.paper_grid import run_paper_grid

        start = time.perf_counter()
        runs = run_paper_grid(args.dataset, seeds=args.grid_seeds, jobs=2)
        result["grid"] = {"seeds": args.grid_seeds, "jobs": 2, "fits": int(len(runs) * 6),
                          "wall_s": time.perf_counter() - start,
                          "sum_fit_s_of_refits": float(runs["fit_seconds"].sum())}
        print(f"27-net grid, 2 variants, {args.grid_seeds} splits (5-fold CV + refit each), "
              f"2 jobs: {result['grid']['wall_s']:.0f} s")
    if args.out:
        with open(args.out, "w", encoding="utf-8") as f:
            json.dump(result, f, indent=2)


if __name__ == "__main__":
    main()
