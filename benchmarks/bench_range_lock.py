"""``muscle-gp-range``'s processes near the braid lock: other inputs and targets, scored on the
shipped muscles nothing fitted on (no FE).

    OPENBLAS_NUM_THREADS=1 .venv/bin/python -P benchmarks/bench_range_lock.py \
        [--train surrogate/data/mkm_range_design.csv] [--variants shipped,lock-input,...] \
        [--restarts 1] [--out FILE.json]

Over the practical range the slope falls to zero and the threshold diverges as the effective
shortening reaches the braid lock (:func:`mkm.fem.limits.lock_eps` ``L``): learnt as ``log k``
(``k eps`` the effective shortening), a small error of ``log k`` is a relative error of
``(k eps / L) / (1 - k eps / L)`` times larger of the threshold (9 times at 90 % of the lock).
Each variant fits the two processes of the shipped kind (:func:`mkm.surrogate.gp.
fit_gaussian_process`, the inputs of :func:`mkm.surrogate.range_gp.range_muscle_values`) on
``--train`` with another input or target, and prints per shipped set (the range's calibration
and held-out sets, the check set of ``tests/surrogate``) the worst, median and 90th percentile
of each muscle's largest error over its sweep in % of its largest FE force (Err% of
``benchmarks/bench_surrogate_range.py``) and how many muscles are above 1 %:

- ``shipped``: ``log k`` over the shipped inputs (reproduces the kind's forces);
- ``lock-input``: the same with ``log(1 - eps / L)`` as a further input of both processes;
- ``lock-power``: the target ``log k'`` with ``d_eff = d^k'``, ``d = 1 - eps / L`` the
  distance to the lock and ``d_eff = 1 - e / L`` the effective one (``k' = k`` as eps -> 0):
  the effective shortening never reaches the lock, and a relative error of ``d_eff`` (of the
  threshold near the lock) is ``|log d_eff|`` times that of ``k'`` (2.3 at 90 % of the lock);
- ``lock-power-input``: both;
- ``lock-distance``: the target ``log(d_eff / d)``, ``lock-distance-input`` with the input.
"""

from __future__ import annotations

import argparse
import json
import time

import numpy as np
from threadpoolctl import threadpool_limits

from mkm.core.records import jsonable, package_file, provenance
from mkm.fem.limits import lock_eps
from mkm.fem.thickwall import effective_eps_of_slope, effective_eps_of_threshold
from mkm.surrogate.features import braid_slope_N_per_bar, thickwall_threshold_bar
from mkm.surrogate.gp import fit_gaussian_process, posterior_mean_std
from mkm.surrogate.muscle_gp import muscle_slopes
from mkm.surrogate.muscle_predictor import process_inputs
from mkm.surrogate.range_gp import range_muscle_values
from mkm.surrogate.training_data import load_training_data

SETS = {"calibration": package_file("mkm.surrogate", "data", "mkm_range_std_calibration.csv"),
        "held-out": package_file("mkm.surrogate", "data", "mkm_range_std_holdout.csv"),
        "check": "tests/surrogate/data/range_check.csv"}
#: name -> (target, with log(1 - eps / L) as an input)
VARIANTS = {"shipped": ("log-k", False), "lock-input": ("log-k", True),
            "lock-power": ("lock-power", False), "lock-power-input": ("lock-power", True),
            "lock-distance": ("lock-distance", False),
            "lock-distance-input": ("lock-distance", True)}


def muscles_of(data):
    """Per muscle of ``data``: its FE slope and threshold (:func:`muscle_slopes`), its values
    and its rows."""
    muscles, A, Pstar, _ = muscle_slopes(data.X[:, 0], data.y, data.groups,
                                         data.threshold_pressure_bar)
    first = np.array([np.flatnonzero(data.groups == m)[0] for m in muscles])
    v, z = range_muscle_values(data.X[first], data.inputs, data.fixed)
    return muscles, A, Pstar, v, z


def process_columns(v, z, z_mean, z_scale, inputs, lock_input):
    """The slope's and the threshold's inputs, standardised, with ``log(1 - eps / L)``."""
    slope, threshold = process_inputs((z - z_mean) / z_scale, inputs)
    if not lock_input:
        return slope, threshold
    distance = np.log(np.maximum(1.0 - v["eps"] / lock_eps(v["theta0_deg"]), 1e-6))
    return (np.column_stack([slope, distance]), np.column_stack([threshold, distance]))


def target_of(v, e, target):
    eps, L = v["eps"], lock_eps(v["theta0_deg"])
    with np.errstate(divide="ignore", invalid="ignore"):
        if target == "log-k":
            return np.log(e / eps)
        if target == "lock-power":
            return np.log(np.log1p(-e / L) / np.log1p(-eps / L))
        return np.log1p(-e / L) - np.log1p(-eps / L)


def shortening_of(v, m, target):
    """The effective shortening at the target ``m``, kept short of the lock as the kind does."""
    eps, L = v["eps"], lock_eps(v["theta0_deg"])
    if target == "log-k":
        e = eps * np.exp(m)
    elif target == "lock-power":
        e = -L * np.expm1(np.exp(m) * np.log1p(-eps / L))
    else:
        e = L - (L - eps) * np.exp(m)
    return np.minimum(e, 0.999 * L)


def fit(data, target, lock_input, restarts):
    """``(z_mean, z_scale, slope posterior, threshold posterior)`` of one variant."""
    _, A, Pstar, v, z = muscles_of(data)
    e_A = effective_eps_of_slope(A, v["D0_mm"], v["t0_mm"], v["theta0_deg"])
    e_P = effective_eps_of_threshold(Pstar, v["D0_mm"], v["t0_mm"], v["theta0_deg"],
                                     v["C10_MPa"], v["C01_MPa"])
    z_mean, z_scale = z.mean(axis=0), np.where(z.std(axis=0) > 0, z.std(axis=0), 1.0)
    columns = process_columns(v, z, z_mean, z_scale, data.inputs, lock_input)
    posteriors = []
    with threadpool_limits(limits=1):
        for Z, e in zip(columns, (e_A, e_P), strict=True):
            t = target_of(v, e, target)
            ok = (v["eps"] > 0) & np.isfinite(t)
            posteriors.append(fit_gaussian_process(Z[ok], t[ok], 0, restarts)[1])
    return z_mean, z_scale, *posteriors


def errors_pct(fitted, data, target, lock_input):
    """Each muscle's largest |F - F_FE| over its sweep in % of its largest FE force."""
    z_mean, z_scale, slope, threshold = fitted
    muscles, _, _, v, z = muscles_of(data)
    columns = process_columns(v, z, z_mean, z_scale, data.inputs, lock_input)
    e_A, e_P = (shortening_of(v, posterior_mean_std(post, Z)[0], target)
                for post, Z in zip((slope, threshold), columns, strict=True))
    # the kind's slope and threshold at these shortenings (a target may give a lengthening)
    A = np.maximum(braid_slope_N_per_bar(v["D0_mm"], v["t0_mm"], e_A, v["theta0_deg"]), 0.0)
    Pstar = np.maximum(np.nan_to_num(thickwall_threshold_bar(
        v["D0_mm"], v["t0_mm"], e_P, v["theta0_deg"], v["C10_MPa"], v["C01_MPa"])), 0.0)
    out = []
    for k, m in enumerate(muscles):
        rows = data.groups == m
        top = float(np.max(np.abs(data.y[rows])))
        if top > 0:
            force = A[k] * np.maximum(data.X[rows, 0] - Pstar[k], 0.0)
            out.append(100.0 * float(np.max(np.abs(force - data.y[rows]))) / top)
    return np.array(out)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--train", default=str(package_file("mkm.surrogate", "data",
                                                            "mkm_range_design.csv")))
    parser.add_argument("--variants", default=",".join(VARIANTS))
    parser.add_argument("--restarts", type=int, default=1)
    parser.add_argument("--out", default=None)
    args = parser.parse_args()
    names = args.variants.split(",")
    unknown = [n for n in names if n not in VARIANTS]
    if unknown:
        parser.error(f"--variants {unknown[0]!r} is invalid: expected some of "
                     f"{', '.join(VARIANTS)}")
    train = load_training_data(args.train)
    sets = {name: load_training_data(path) for name, path in SETS.items()}
    results = {"train": train.summary(), "restarts": args.restarts, "variants": {}}
    for name in names:
        target, lock_input = VARIANTS[name]
        start = time.perf_counter()
        fitted = fit(train, target, lock_input, args.restarts)
        row = {"fit_seconds": time.perf_counter() - start}
        pooled = []
        for label, data in sets.items():
            e = errors_pct(fitted, data, target, lock_input)
            pooled.append(e)
            row[label] = summary(e)
        row["pooled"] = summary(np.concatenate(pooled))
        results["variants"][name] = row
        print(f"{name}: " + "; ".join(
            f"{label} {s['muscles']} muscles worst {s['worst_pct']:.2f} % median "
            f"{s['median_pct']:.3f} % p90 {s['p90_pct']:.2f} % above 1 %: {s['above_1pct']}"
            for label, s in row.items() if label != "fit_seconds"), flush=True)
    if args.out:
        with open(args.out, "w", encoding="utf-8") as f:
            json.dump({**results, "provenance": provenance()}, f, indent=2, default=jsonable)


def summary(errors) -> dict:
    return {"muscles": int(errors.size), "worst_pct": float(errors.max()),
            "median_pct": float(np.median(errors)),
            "p90_pct": float(np.percentile(errors, 90)), "above_1pct": int((errors > 1).sum())}


if __name__ == "__main__":
    main()
