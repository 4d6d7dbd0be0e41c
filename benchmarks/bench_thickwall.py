"""Speed of the closed-form rungs: points per second of `thickwall` (and `eq2` for scale).

Run outside the test suite:

    .venv/bin/python benchmarks/bench_thickwall.py [--points 1000000] [--repeats 7] [--seed 0]

Inputs are drawn uniformly over the paper's dataset box (P 0-2.5 bar, D0 30-50 mm, t0 2-4 mm,
eps 0-20 %) with a fixed seed. For each model it reports the median wall time of ``predict`` on
the whole batch (validation and broadcasting included, as a caller sees it), the points per
second, and the latency of a one-point call (what a 10 Hz simulated bench pays per sample).
The issue asks for at least 1e5 points per second from `thickwall`.
"""

from __future__ import annotations

import argparse
import json
import time

import numpy as np

from mkm.core.records import provenance
from mkm.fem.ladder import make_model

BOX = {"pressure_bar": (0.0, 2.5), "D0_mm": (30.0, 50.0), "t0_mm": (2.0, 4.0), "eps": (0.0, 0.2)}


def sample_inputs(n: int, seed: int) -> list[np.ndarray]:
    rng = np.random.default_rng(seed)
    return [rng.uniform(lo, hi, n) for lo, hi in BOX.values()]


def median_seconds(call, repeats: int) -> float:
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        call()
        times.append(time.perf_counter() - start)
    return float(np.median(times))


def bench(model_name: str, points: int, repeats: int, seed: int) -> dict:
    model = make_model(model_name)
    inputs = sample_inputs(points, seed)
    batch = median_seconds(lambda: model.predict(*inputs), repeats)
    one = [x[:1] for x in inputs]
    single = median_seconds(lambda: model.predict(*one), max(repeats, 200))
    valid = float(model.predict(*inputs).valid.mean())
    return {"model": model_name, "points": points, "batch_s": batch,
            "points_per_s": points / batch, "single_point_s": single, "valid_fraction": valid}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=1_000_000)
    parser.add_argument("--repeats", type=int, default=7)
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args()
    rows = [bench(name, args.points, args.repeats, args.seed) for name in ("thickwall", "eq2")]
    info = provenance()
    print(f"# seed {args.seed}, {args.repeats} repeats, median; {info['date_utc']}, "
          f"{info['machine']}, {json.dumps(info['versions'])}")
    print("model,points,batch_s,points_per_s,single_point_s,valid_fraction")
    for r in rows:
        print(f"{r['model']},{r['points']},{r['batch_s']:.4f},{r['points_per_s']:.3g},"
              f"{r['single_point_s']:.2e},{r['valid_fraction']:.3f}")


if __name__ == "__main__":
    main()
