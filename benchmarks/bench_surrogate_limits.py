"""What sets a muscle-GP surrogate's worst error on fresh muscles: its threshold-linear form, its
two processes, or the number of muscles they learnt from.

    OPENBLAS_NUM_THREADS=1 .venv/bin/python benchmarks/bench_surrogate_limits.py \
        --kind muscle-gp-range --muscles 60 --draws 10 --seed 20261701 \
        [--fractions 0.35,0.5,0.7,1] [--repeats 1] [--train OTHER.csv]
        [--adaptive K --pool-seed S [--pool 4000]] [--out FILE.json]

Draws ``--draws`` sets of ``--muscles`` fresh muscles (seeds S, S+1, ...): of the practical
range for ``muscle-gp-range`` (sweeps 0-8 bar, :func:`mkm.surrogate.design.build_practical_set`),
of the paper's box otherwise (0-2.5 bar, :func:`mkm.surrogate.design.random_muscles`), solved at
the fine mesh through the dataset cache. Scores each muscle's largest |Err%| (Equation 7 over
its sweep, as ``bench_surrogate_range.py``) for:

- the *form*: each fresh FE sweep's own least-squares threshold line
  (:func:`mkm.surrogate.muscle_gp.muscle_slopes`), the error the form leaves with a perfect
  slope and threshold;
- the kind fitted on each share ``--fractions`` of its shipped training muscles (random subsets,
  seeds 0 .. ``--repeats`` - 1; share 1 is the shipped fit, at the shipped kernels): a learning
  curve; with ``--train``, the kind fitted on all of another FE design as well (for example
  the same recipe with twice the muscles, ``mkm surrogate design ... --out OTHER.csv``);
- with ``--adaptive K``, the kind fitted on its training muscles plus the first K/4, K/2, 3K/4
  and K muscles the shipped fit is least sure of among ``--pool`` random ones (seed
  ``--pool-seed``; :func:`mkm.surrogate.design.adaptive_muscles`, the design's own criterion),
  solved at the fine mesh: whether more muscles where the model doubts itself move the tail;
- for the shipped fit, the share of points within 1, 2 and 3 predictive std in each fifth of the
  points sorted by pressure above the fresh FE threshold (a calibrated std: 68.27, 95.45, 99.73
  in every fifth), and the one factor of the whole std whose 1, 2 and 3 std bands miss the
  normal fractions least on these muscles: how close any rescale of it can come.
"""

from __future__ import annotations

import argparse
import json
import tempfile
import time
from pathlib import Path

import numpy as np
import pandas as pd
from bench_surrogate_range import worst_per_muscle

from mkm.core.records import jsonable, provenance
from mkm.surrogate.coverage import NORMAL_COVERAGE, coverage
from mkm.surrogate.design import (
    DESIGN_PRESSURES,
    EVAL_PRESSURES,
    adaptive_muscles,
    build_practical_set,
    fe_sweeps,
    random_muscles,
)
from mkm.surrogate.kinds import RANGE, make_estimator
from mkm.surrogate.muscle_gp import muscle_slopes
from mkm.surrogate.quiet import quiet_fits
from mkm.surrogate.train import cached_model, kind_files
from mkm.surrogate.training_data import load_training_data

SHARES_OF_PRESSURE = 5
#: Factors of the whole std tried by :func:`best_std_factor`.
STD_FACTORS = np.geomspace(0.5, 2.0, 301)


def fresh_sets(kind: str, muscles: int, seeds, folder: Path) -> list:
    """One :class:`~mkm.surrogate.training_data.TrainingData` of fresh FE sweeps per seed."""
    out = []
    for seed in seeds:
        path = folder / f"fresh_{seed}.csv"
        if kind == RANGE:
            build_practical_set(muscles, seed, path, progress=False)
        else:
            frame, _ = fe_sweeps(random_muscles(muscles, seed), "fine", EVAL_PRESSURES,
                                 progress=False)
            frame.to_csv(path, index=False)
        out.append(load_training_data(path))
    return out


class _Lines:
    """Each fresh sweep's own threshold line, as an estimator of its rows."""

    def __init__(self, data):
        self.data = data

    def predict(self, X):
        d = self.data
        muscles, A, Pstar, _ = muscle_slopes(X[:, 0], d.y, d.groups, d.threshold_pressure_bar)
        which = np.searchsorted(muscles, d.groups)
        slope, threshold = np.nan_to_num(A[which]), np.nan_to_num(Pstar[which], nan=np.inf)
        return slope * np.maximum(X[:, 0] - threshold, 0.0)


def scores(per_draw: list[np.ndarray], target_pct: float) -> dict:
    """Pooled worst, percentiles and muscles above the target, and each draw's worst."""
    errors = np.concatenate(per_draw)
    worst = [float(e.max()) for e in per_draw]
    return {"muscles": int(errors.size), "worst_pct": float(errors.max()),
            "p98_pct": float(np.percentile(errors, 98)),
            "p90_pct": float(np.percentile(errors, 90)), "median_pct": float(np.median(errors)),
            "above_target": int(np.sum(errors > target_pct)), "draw_worst_pct": worst,
            "draws_above_target": int(np.sum(np.array(worst) > target_pct))}


def adaptive_set(kind: str, picks: int, pool: int, seed: int, folder: Path) -> pd.DataFrame:
    """FE sweeps (the kind's design pressures) of the ``picks`` muscles the shipped fit of
    ``kind`` is least sure of among ``pool`` random ones; ``muscle`` is the order picked."""
    path = folder / f"adaptive_{seed}.csv"
    if kind == RANGE:
        return build_practical_set(pool, seed, path, progress=False, adaptive=picks)[0]
    muscles = adaptive_muscles(cached_model(kind).estimator, picks, seed, candidates=pool)
    return fe_sweeps(muscles, "fine", DESIGN_PRESSURES, progress=False)[0]


def with_first(train, picked: pd.DataFrame, n: int, folder: Path):
    """``(X, y, threshold)`` of ``train`` and the first ``n`` muscles of ``picked``."""
    path = folder / f"adaptive_first_{n}.csv"
    picked[picked["muscle"] < n].to_csv(path, index=False)
    extra = load_training_data(path)
    return tuple(np.concatenate([a, b]) for a, b in (
        (train.X, extra.X), (train.y, extra.y),
        (train.threshold_pressure_bar, extra.threshold_pressure_bar)))


def best_std_factor(estimator, sets) -> dict:
    """Within 1/2/3 std as shipped, and at the factor of the whole std (:data:`STD_FACTORS`)
    whose largest miss of the normal fractions is smallest on ``sets``."""
    X = np.concatenate([d.X for d in sets])
    force, std = estimator.predict(X, return_std=True)
    error = np.abs(np.concatenate([d.y for d in sets]) - force)
    keep = (error > 0) | (std > 0)
    ratio = np.sort(error[keep] / std[keep])
    normal = np.array([target for _, target in NORMAL_COVERAGE])
    within = np.array([[np.searchsorted(ratio, n * f, side="right") / ratio.size
                        for n, _ in NORMAL_COVERAGE] for f in STD_FACTORS])
    miss = np.max(np.abs(within - normal), axis=1)
    best = int(np.argmin(miss))
    shipped = [float(np.mean(ratio <= n)) for n, _ in NORMAL_COVERAGE]
    return {"points": int(ratio.size), "shipped_within": shipped,
            "shipped_miss": float(np.max(np.abs(np.array(shipped) - normal))),
            "best_factor": float(STD_FACTORS[best]), "best_within": within[best].tolist(),
            "best_miss": float(miss[best])}


def coverage_by_pressure(estimator, sets) -> list[dict]:
    """Within 1/2/3 std per fifth of the informative points by ``P - P*_FE``."""
    X = np.concatenate([d.X for d in sets])
    y = np.concatenate([d.y for d in sets])
    above = X[:, 0] - np.concatenate([d.threshold_pressure_bar for d in sets])
    force, std = estimator.predict(X, return_std=True)
    error = np.abs(y - force)
    keep = (error > 0) | (std > 0)
    order = np.argsort(above[keep], kind="stable")
    rows = []
    for share in np.array_split(order, SHARES_OF_PRESSURE):
        e, s, x = error[keep][share], std[keep][share], above[keep][share]
        rows.append({"above_threshold_bar": [float(x.min()), float(x.max())], "points": int(e.size),
                     **{f"within_{k}std": coverage(e, s, float(k)) for k in (1, 2, 3)}})
    return rows


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--kind", default="muscle-gp")
    parser.add_argument("--muscles", type=int, default=40)
    parser.add_argument("--draws", type=int, default=8)
    parser.add_argument("--seed", type=int, required=True)
    parser.add_argument("--fractions", default="0.5,0.75,1")
    parser.add_argument("--repeats", type=int, default=1)
    parser.add_argument("--train", default=None, help="another FE design to fit the kind on")
    parser.add_argument("--adaptive", type=int, default=0,
                        help="muscles added where the shipped fit is least sure (default 0)")
    parser.add_argument("--pool", type=int, default=4000)
    parser.add_argument("--pool-seed", type=int, default=None)
    parser.add_argument("--out", default=None)
    args = parser.parse_args()
    fractions = [float(f) for f in args.fractions.split(",")]
    if args.adaptive and (args.adaptive < 4 or args.pool_seed is None):
        parser.error(f"--adaptive {args.adaptive} is invalid: expected at least 4 muscles, "
                     "with --pool-seed")
    target = 1.0 if args.kind == RANGE else 0.25
    seeds = [args.seed + k for k in range(args.draws)]
    train = load_training_data(kind_files(args.kind)[0])
    muscles = np.unique(train.groups)
    result = {"kind": args.kind, "seeds": seeds, "target_pct": target,
              "train": train.summary(), "learning_curve": []}
    with tempfile.TemporaryDirectory() as folder:
        sets = fresh_sets(args.kind, args.muscles, seeds, Path(folder))

        def errors(estimator_of) -> list[np.ndarray]:
            return [worst_per_muscle(estimator_of(d), d) for d in sets]

        result["form"] = scores(errors(_Lines), target)
        print(f"form (each fresh sweep's own line): {result['form']}")
        for fraction in fractions:
            for repeat in range(1 if fraction >= 1 else args.repeats):
                start = time.perf_counter()
                if fraction >= 1:
                    estimator, kept = cached_model(args.kind).estimator, muscles.size
                else:
                    kept_muscles = np.random.default_rng(repeat).permutation(muscles)[
                        : int(round(fraction * muscles.size))]
                    rows, kept = np.isin(train.groups, kept_muscles), kept_muscles.size
                    with quiet_fits():
                        estimator = make_estimator(args.kind, train.inputs).fit(
                            train.X[rows], train.y[rows],
                            threshold_pressure_bar=train.threshold_pressure_bar[rows])
                row = {"fraction": fraction, "repeat": repeat, "training_muscles": int(kept),
                       "fit_s": time.perf_counter() - start,
                       **scores(errors(lambda d, e=estimator: e), target)}
                result["learning_curve"].append(row)
                print(f"{kept} training muscles: {row}")
        if args.train:
            other = load_training_data(args.train)
            start = time.perf_counter()
            with quiet_fits():
                estimator = make_estimator(args.kind, other.inputs).fit(
                    other.X, other.y, threshold_pressure_bar=other.threshold_pressure_bar)
            result["other_design"] = {"train": other.summary(), "training_muscles":
                                      other.n_muscles, "fit_s": time.perf_counter() - start,
                                      **scores(errors(lambda d, e=estimator: e), target)}
            print(f"{other.n_muscles} training muscles of {args.train}: "
                  f"{result['other_design']}")
        if args.adaptive:
            extra = adaptive_set(args.kind, args.adaptive, args.pool, args.pool_seed,
                                 Path(folder))
            result["adaptive"] = {"pool": args.pool, "pool_seed": args.pool_seed, "rows": []}
            for n in range(args.adaptive // 4, args.adaptive + 1, args.adaptive // 4):
                X, y, threshold = with_first(train, extra, n, Path(folder))
                with quiet_fits():
                    estimator = make_estimator(args.kind, train.inputs).fit(
                        X, y, threshold_pressure_bar=threshold)
                row = {"added": n, "training_muscles": int(muscles.size + n),
                       **scores(errors(lambda d, e=estimator: e), target)}
                result["adaptive"]["rows"].append(row)
                print(f"plus {n} adaptive muscles: {row}")
        shipped = cached_model(args.kind).estimator
        if hasattr(shipped, "calibrate_std"):
            result["coverage_by_pressure"] = coverage_by_pressure(shipped, sets)
            for row in result["coverage_by_pressure"]:
                print(f"coverage {row}")
            result["std_factor"] = best_std_factor(shipped, sets)
            print(f"one factor of the std: {result['std_factor']}")
    if args.out:
        with open(args.out, "w", encoding="utf-8") as f:
            json.dump({**result, "provenance": provenance()}, f, indent=2, default=jsonable)


if __name__ == "__main__":
    main()
