"""The promise of ``auto`` at fresh random points of the box, and what it saves.

Run outside the test suite:

    .venv/bin/python benchmarks/bench_auto.py [--points 200] [--seed S]
        [--tolerances 0.005,0.01,0.02,0.05] [--out FILE.json]

Draws ``--points`` muscles uniformly in the default surrogate's box (D0, t0, eps, L0, theta0 and
the rubber scale; seed printed and recorded) and one pressure each in 0.25-2.5 bar. At each
point and tolerance, ``auto`` (one model for the point) answers; the truth is the fine FE mesh at
the muscle's own sweep 0.25-2.5 bar (its largest force is Equation 7's scale). Prints per
tolerance: the share of points within the tolerance (target >= 99 %), the worst true error, which
models answered, and the seconds auto took against the fine FE's (the cost saved). FE sweeps go
through the prediction cache (``MKM_CACHE_DIR``), so a second run only times auto.
"""

from __future__ import annotations

import argparse
import json
import time
import warnings
from collections import Counter

import numpy as np

from mkm.core.records import jsonable, provenance
from mkm.prediction_cache import DEFAULT_CACHE_DIR, cached_predict
from mkm.registry import build_spec
from mkm.surrogate.design import BOX

SWEEP_BAR = np.round(np.arange(0.25, 2.501, 0.25), 2)


def draw(rng: np.random.Generator) -> tuple[dict, tuple, float]:
    """A muscle of the box: its parameters, its geometry (D0, t0, eps) and one pressure."""
    scale = rng.uniform(0.5, 1.5)
    muscle = {"L0_mm": rng.uniform(*BOX["L0_mm"]), "theta0_deg": rng.uniform(*BOX["theta0_deg"]),
              "C10_MPa": 0.0694 * scale, "C01_MPa": 0.0628 * scale}
    geometry = tuple(rng.uniform(*BOX[k]) for k in ("D0_mm", "t0_mm", "eps"))
    return muscle, geometry, float(rng.choice(SWEEP_BAR))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=200)
    parser.add_argument("--seed", type=int, default=None)
    parser.add_argument("--tolerances", default="0.005,0.01,0.02,0.05")
    parser.add_argument("--out", default=None)
    args = parser.parse_args()
    seed = args.seed if args.seed is not None else int(np.random.SeedSequence().entropy % 2**32)
    print(f"seed {seed}")
    rng = np.random.default_rng(seed)
    tolerances = [float(t) for t in args.tolerances.split(",")]
    points = [draw(rng) for _ in range(args.points)]
    truth, fe_seconds = [], []
    for muscle, (D0, t0, eps), _ in points:
        fine, _ = cached_predict(build_spec("axisym:mesh=fine", **muscle), SWEEP_BAR, D0, t0,
                                 eps, cache_dir=DEFAULT_CACHE_DIR)
        truth.append(fine)
        fe_seconds.append(fine.seconds)
    results = {}
    for tol in tolerances:
        errors, used, seconds, failed = [], Counter(), [], 0
        for (muscle, (D0, t0, eps), P), fine in zip(points, truth, strict=True):
            if not fine.valid.all():
                failed += 1  # no truth to judge against: counted, not scored
                continue
            start = time.perf_counter()
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                pred = build_spec(f"auto:tolerance={tol}", **muscle).predict(P, D0, t0, eps)
            seconds.append(time.perf_counter() - start)
            F = float(fine.force_N[SWEEP_BAR == P][0])
            errors.append(100 * abs(float(pred.force_N) - F) / np.nanmax(fine.force_N))
            used[str(pred.extras["model_used"].item())] += 1
        errors = np.array(errors)
        within = float(np.mean(errors <= 100 * tol))
        results[tol] = {"points": len(errors), "no_fe_truth": failed, "within": within,
                        "worst_err_pct": float(errors.max()), "used": dict(used),
                        "auto_s_median": float(np.median(seconds)),
                        "fine_fe_s_median": float(np.median(fe_seconds))}
        print(f"tolerance {100 * tol:g} %: {100 * within:.1f} % of {len(errors)} points within "
              f"(target >= 99 %), worst {errors.max():.3f} %; used {dict(used)}; auto "
              f"{np.median(seconds):.3g} s per point against the fine FE's "
              f"{np.median(fe_seconds):.3g} s per sweep (median)")
    if args.out:
        with open(args.out, "w", encoding="utf-8") as f:
            json.dump({"seed": seed, "points": args.points, "results": results,
                       "provenance": provenance()}, f, indent=2, default=jsonable)


if __name__ == "__main__":
    main()
