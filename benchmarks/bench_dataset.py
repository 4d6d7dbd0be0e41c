"""Wall time of a dataset build with 1, 2, ... workers, each from an empty cache (the speed-up).

    .venv/bin/python benchmarks/bench_dataset.py --model axisym --workers 1 2

Each run starts from a fresh temporary cache, so every job is computed; the time includes the
start-up of the local Dask cluster, as a user sees it. Prints one line per worker count and the
speed-up against the first; ``--json FILE`` also writes them with provenance.
"""

from __future__ import annotations

import argparse
import json
import tempfile
from pathlib import Path

from mkm.core.records import provenance
from mkm.fem.dataset import build_dataset


def bench(grid: str, model: str, mesh: str | None, workers: list[int]) -> list[dict]:
    results = []
    for n in workers:
        with tempfile.TemporaryDirectory(prefix="mkm-bench-dataset-") as tmp:
            run = build_dataset(grid, model, mesh=mesh, out=None, workers=n,
                                cache_dir=Path(tmp), progress=False)
        assert run.jobs_computed == run.jobs_total  # a fresh cache: every job computed
        results.append({"workers": n, "where": run.workers, "jobs": run.jobs_total,
                        "rows": len(run.frame), "wall_seconds": run.wall_seconds,
                        "job_seconds_sum": float(run.frame.groupby(
                            ["D0_mm", "t0_mm", "eps", "L0_mm", "theta0_deg"])["seconds"]
                            .first().sum()),
                        "points_not_converged": run.points_not_converged})
    return results


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--grid", default="paper")
    parser.add_argument("--model", default="axisym")
    parser.add_argument("--mesh")
    parser.add_argument("--workers", type=int, nargs="+", default=[1, 2])
    parser.add_argument("--json", type=Path, help="also write the results here")
    args = parser.parse_args()
    results = bench(args.grid, args.model, args.mesh, args.workers)
    base = results[0]["wall_seconds"]
    print(f"grid {args.grid}, model {args.model}, mesh {args.mesh or 'default'}")
    print("workers,wall_s,sum_of_job_solve_s,speedup,points_not_converged")
    for r in results:
        print(f"{r['workers']},{r['wall_seconds']:.1f},{r['job_seconds_sum']:.1f},"
              f"{base / r['wall_seconds']:.2f},{r['points_not_converged']}")
    if args.json:
        args.json.write_text(json.dumps({**provenance(), "grid": args.grid, "model": args.model,
                                         "mesh": args.mesh, "results": results}, indent=2))


if __name__ == "__main__":  # the guard lets Dask spawn worker processes from this script
    main()
