"""A surrogate of the whole practical range against issue 34's targets, on fresh muscles.

Run outside the test suite:

    .venv/bin/mkm surrogate design --range practical --muscles 600 --seed S0 --out TRAIN.csv
    .venv/bin/python benchmarks/bench_surrogate_range.py --train TRAIN.csv [--kind muscle-gp]
        [--muscles 60] [--box-muscles 40] [--seed S] [--draws N] [--seeds S1 S2 ...]
        [--pool-with FE.csv ...] [--out FILE.json]
    .venv/bin/python benchmarks/bench_surrogate_range.py --kind muscle-gp-range [...]

Fits ``--kind`` on the FE sweeps of ``--train`` (one BLAS thread), or without ``--train`` takes
the kind as shipped (trained on its own dataset with its std calibrated, through the one
surrogate cache: :func:`mkm.surrogate.train.cached_model`), then draws ``--muscles``
fresh muscles of the practical range (:func:`mkm.surrogate.design.practical_muscles`, seed
printed and recorded; sweeps 0-8 bar) and ``--box-muscles`` fresh muscles of the paper's box
(:func:`mkm.surrogate.design.random_muscles`, sweeps 0-2.5 bar), solves them at the fine mesh
(through the dataset cache) and prints per set the worst and median of each muscle's largest
|Err%| (Equation 7 over its sweep; muscles without force and those whose FE failed are counted
and left out) and, for a kind with a std, the share of points within 1, 2 and 3 std (a
calibrated std: 68.27, 95.45, 99.73 %). ``--draws N`` draws the practical range N times (seeds
S, S+1, ...; the box once, seed S) and adds the errors and coverage pooled over the draws (the
points of one muscle share its errors: coverage moves several points between draws of 60);
``--seeds`` names the draws' seeds instead (the box drawn once, with the first) and
``--pool-with`` adds FE sets of the practical range made before (a check set), each scored
alone and pooled with the draws. Each set records its ``--worst`` muscles (default 10): the
inputs, FE force, force and std at each one's worst point, the error in std there, eps over the
braid lock, and ``auto_bound_pct``, the bound ``auto`` states for the surrogate over a call of
the muscle's sweep (its std factor, :data:`mkm.auto.RANGE_STD_FACTOR` for the practical range's
kind, times its largest std over the sweep, in % of its largest force there): where that bound
exceeds a tolerance, ``auto`` does not answer with the surrogate.
Targets: over the range worst <= 1 %, median <= 0.2 %; in the box worst <= 0.25 %.
"""

from __future__ import annotations

import argparse
import json
import tempfile
import time
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pandas as pd

from mkm.auto import MIN_SCALE_N, RANGE_STD_FACTOR, STD_FACTOR
from mkm.core.records import jsonable, package_file, provenance, recorded_path
from mkm.fem.limits import lock_eps
from mkm.surrogate import kinds
from mkm.surrogate.design import EVAL_PRESSURES, build_practical_set, fe_sweeps, random_muscles
from mkm.surrogate.features import columns_of
from mkm.surrogate.kinds import make_estimator
from mkm.surrogate.quiet import quiet_fits
from mkm.surrogate.train import cached_model
from mkm.surrogate.training_data import load_training_data


def dataset_path(path) -> str:
    """``path`` as the record names it: a dataset shipped with mkm as ``surrogate/data/NAME``,
    wherever mkm is installed or the benchmark runs; another file by
    :func:`~mkm.core.records.recorded_path`."""
    if Path(path).resolve().parent == package_file("mkm.surrogate", "data"):
        return f"surrogate/data/{Path(path).name}"
    return recorded_path(path)


def worst_muscles(estimator, data, factor: float, n: int) -> list[dict]:
    """The ``n`` muscles of largest error (each one's largest |F - F_FE| over its sweep, in % of
    its largest FE force): its group ``muscle``, inputs, FE force, force and std at that point,
    the error in std there and ``auto``'s bound for the surrogate over the sweep (``factor``
    times the largest std, in % of the largest force, at least :data:`mkm.auto.MIN_SCALE_N`)."""
    if n <= 0:
        return []
    has_std = hasattr(estimator, "calibrate_std")
    force, std = (estimator.predict(data.X, return_std=True) if has_std
                  else (estimator.predict(data.X), None))
    values = columns_of(data.X, tuple(data.inputs), data.fixed)
    rows = []
    for g in np.unique(data.groups):
        these = np.flatnonzero(data.groups == g)
        top = float(np.max(np.abs(data.y[these])))
        if top <= 0:
            continue
        miss = np.abs(force[these] - data.y[these])
        at = these[np.argmax(miss)]
        row = {"muscle": int(g), **{name: float(values[name][at]) for name in values}}
        row.update(eps_per_lock=float(values["eps"][at] / lock_eps(values["theta0_deg"][at])),
                   fe_force_N=float(data.y[at]), force_N=float(force[at]),
                   err_pct=100.0 * float(miss.max()) / top)
        if std is not None:
            largest = max(float(np.max(np.abs(force[these]))), MIN_SCALE_N)
            row.update(force_std_N=float(std[at]),
                       err_in_std=float(miss.max() / std[at]) if std[at] > 0 else None,
                       auto_bound_pct=100.0 * factor * float(np.max(std[these])) / largest)
        rows.append(row)
    return sorted(rows, key=lambda r: -r["err_pct"])[:n]


def worst_per_muscle(estimator, data) -> np.ndarray:
    """Each muscle's largest |F - F_FE| over its sweep, in % of its largest FE force."""
    force = estimator.predict(data.X)
    out = []
    for g in np.unique(data.groups):
        rows = data.groups == g
        top = float(np.max(np.abs(data.y[rows])))
        if top > 0:
            out.append(100.0 * float(np.max(np.abs(force[rows] - data.y[rows]))) / top)
    return np.array(out)


def std_coverage(estimator, data) -> dict | None:
    """Share of the points within 1, 2 and 3 predictive std of the FE (None without a std)."""
    from mkm.surrogate.validation import std_coverage as within

    if not hasattr(estimator, "calibrate_std"):
        return None
    return within(estimator, data.X, data.y)


def summary(label: str, estimator, data, drawn: int, factor: float, worst: int) -> dict:
    """Worst, median and 90th percentile of each muscle's largest error, the coverage and the
    ``worst`` muscles (:func:`worst_muscles`; pooled, each with ``set``, its part's index) of
    ``data`` (a :class:`~mkm.surrogate.training_data.TrainingData` or a list of them, pooled)."""
    parts = data if isinstance(data, list) else [data]
    errors = np.concatenate([worst_per_muscle(estimator, d) for d in parts])
    pooled = SimpleNamespace(X=np.concatenate([d.X for d in parts]),
                             y=np.concatenate([d.y for d in parts]))
    row = {"muscles_drawn": drawn, "muscles_scored": int(errors.size),
           "worst_pct": float(errors.max()), "median_pct": float(np.median(errors)),
           "p90_pct": float(np.percentile(errors, 90)),
           "std_coverage": std_coverage(estimator, pooled),
           "worst_muscles": sorted(({**m, "set": k} if len(parts) > 1 else m
                                    for k, d in enumerate(parts)
                                    for m in worst_muscles(estimator, d, factor, worst)),
                                   key=lambda m: -m["err_pct"])[:worst]}
    cover = row["std_coverage"]
    within = ("" if cover is None else ", within 1/2/3 std " + " / ".join(
        f"{100 * cover[f'within_{k}std']:.1f}" for k in (1, 2, 3)) + " % of the points")
    print(f"{label}: {errors.size} of {drawn} muscles scored: worst {row['worst_pct']:.3f} %, "
          f"median {row['median_pct']:.3f} %, 90th percentile {row['p90_pct']:.3f} %{within}")
    return row


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--train", default=None,
                        help="FE sweeps to fit (CSV with sidecar); default: the kind as shipped")
    parser.add_argument("--kind", default="muscle-gp")
    parser.add_argument("--muscles", type=int, default=60)
    parser.add_argument("--box-muscles", type=int, default=40,
                        help="fresh muscles of the paper's box (default 40; 0: none)")
    parser.add_argument("--seed", type=int, default=None)
    parser.add_argument("--draws", type=int, default=1,
                        help="draws of --muscles over the practical range, seeds S, S+1, ... "
                        "(default 1); errors and coverage pooled over them as well")
    parser.add_argument("--seeds", type=int, nargs="+", default=None,
                        help="the practical range's draws by seed, instead of --seed/--draws")
    parser.add_argument("--pool-with", nargs="+", default=[], metavar="FE_CSV",
                        help="FE sets of the practical range (CSV with sidecar) scored alone "
                        "and pooled with the draws")
    parser.add_argument("--worst", type=int, default=10,
                        help="muscles of largest error recorded per set (default 10)")
    parser.add_argument("--out", default=None)
    args = parser.parse_args()
    if args.worst < 0:
        parser.error(f"--worst {args.worst} is invalid: expected 0 or more muscles")
    if args.box_muscles < 0 or args.muscles < 1:
        parser.error(f"--muscles {args.muscles} --box-muscles {args.box_muscles} are invalid: "
                     "expected at least 1 muscle of the range and 0 or more of the box")
    if args.draws < 1:
        parser.error(f"--draws {args.draws} is invalid: expected at least 1")
    if args.seeds is not None and (args.seed is not None or args.draws != 1):
        parser.error("--seeds names every draw: expected it without --seed and --draws")
    pooled_sets = []
    for path in args.pool_with:  # before the FE, so a bad file costs nothing
        try:
            pooled_sets.append((Path(path), load_training_data(path),
                                int(pd.read_csv(path, usecols=["muscle"])["muscle"].nunique())))
        except (OSError, ValueError) as error:
            parser.error(f"--pool-with {path} is not an FE set: {error}")
    seed = (args.seeds[0] if args.seeds else args.seed if args.seed is not None
            else int(np.random.SeedSequence().entropy % 2**32))
    draw_seeds = args.seeds or [seed + k for k in range(args.draws)]
    print(f"seed {seed}")
    start = time.perf_counter()
    if args.train is None:
        model = cached_model(args.kind)
        estimator, train = model.estimator, dict(model.metadata["dataset"])
        # a cached model names the file as the checkout that trained it saw it: name the file
        # this process trained or found it as, a shipped one by its place in the source tree
        train["path"] = dataset_path(model.data_file or train["path"])
        print(f"{args.kind} as shipped ({train['n_muscles']} muscles), loaded or trained in "
              f"{time.perf_counter() - start:.0f} s")
    else:
        data = load_training_data(args.train)
        with quiet_fits():
            estimator = make_estimator(args.kind, data.inputs).fit(
                data.X, data.y, threshold_pressure_bar=data.threshold_pressure_bar)
        train = data.summary()
        print(f"{args.kind} fitted on {data.n_muscles} muscles in "
              f"{time.perf_counter() - start:.0f} s")
    results = {"seed": seed, "kind": args.kind, "train": train, "draw_seeds": draw_seeds}
    # the factor auto bounds this kind with (mkm.design.box_search.std_factor, by kind)
    factor = RANGE_STD_FACTOR if args.kind == kinds.RANGE else STD_FACTOR
    scored = {"factor": factor, "worst": args.worst}
    with tempfile.TemporaryDirectory() as folder:
        draws = []
        for k, draw_seed in enumerate(draw_seeds):
            practical = Path(folder) / f"practical_{k}.csv"
            build_practical_set(args.muscles, draw_seed, practical, progress=False)
            draws.append(load_training_data(practical))
        several = len(draw_seeds) > 1
        results["practical_range"] = summary(
            "practical range" + (f", seed {seed}" if several else ""), estimator,
            draws[0], args.muscles, **scored)
        if several:
            results["practical_range_draws"] = [results["practical_range"]] + [
                summary(f"practical range, seed {s}", estimator, d, args.muscles, **scored)
                for s, d in zip(draw_seeds[1:], draws[1:], strict=True)]
        if pooled_sets:
            results["pool_with"] = [
                {"file": path.name, **summary(path.name, estimator, data, drawn, **scored)}
                for path, data, drawn in pooled_sets]
        if several or pooled_sets:
            results["practical_range_pooled"] = summary(
                f"practical range, {len(draw_seeds)} draws"
                + "".join(f" and {path.name}" for path, _, _ in pooled_sets) + " pooled",
                estimator, draws + [data for _, data, _ in pooled_sets],
                args.muscles * len(draw_seeds) + sum(drawn for _, _, drawn in pooled_sets),
                **scored)
        if args.box_muscles:
            box = random_muscles(args.box_muscles, seed)
            frame, _ = fe_sweeps(box, "fine", EVAL_PRESSURES, progress=False)
            path = Path(folder) / "box.csv"
            frame.to_csv(path, index=False)
            results["paper_box"] = summary(
                "paper's box", estimator, load_training_data(path), args.box_muscles, **scored)
    if args.out:
        with open(args.out, "w", encoding="utf-8") as f:
            json.dump({**results, "provenance": provenance()}, f, indent=2, default=jsonable)


if __name__ == "__main__":
    main()
