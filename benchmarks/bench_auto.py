"""The promise of ``auto`` on fresh random calls of the box, sweeps and single points, and what
it saves.

Run outside the test suite:

    .venv/bin/python benchmarks/bench_auto.py [--calls 200] [--seed S] [--range practical]
        [--tolerances 0.005,0.01,0.02,0.05] [--out FILE.json]

Draws ``--calls`` muscles uniformly in the default surrogate's box (D0, t0, eps, L0, theta0 and
the rubber scale; seed printed and recorded), each one call: half of them the muscle's sweep
0.25-2.5 bar, a quarter a single pressure of that sweep, a quarter a single pressure just above
the muscle's threshold ``P*`` (``P* + 0.01-0.1`` bar, the fine mesh's ``P*``), where a small
shift of the threshold is a large part of the force. At each call and tolerance, ``auto`` (one
model for the call) answers; the truth is the fine FE mesh at the same pressures, and the error
is Equation 7 at the scale of the call: over a sweep, relative to its largest force; at a single
point, relative to the force there (at least 1 N). Prints per tolerance and kind of call: the
share within the tolerance (target >= 99 %), the worst error, which models answered, and the
seconds auto took against the fine FE's; per model that answered, how many of its calls erred
beyond the bound auto stated for the call (its largest ``error_bound_pct``), and the call of the
largest error / bound. With ``--range practical`` the muscles are those of
the practical range (:func:`mkm.fem.sampling.draw_muscles`), sweeps 0.5-8 bar: mostly outside
the surrogate's box, where the FE meshes answer. FE solves go through the prediction cache
(``MKM_CACHE_DIR``), so a second run only times auto.
"""

from __future__ import annotations

import argparse
import json
import time
import warnings
from collections import Counter

import numpy as np

from mkm.auto import MIN_SCALE_N
from mkm.core.records import jsonable, provenance
from mkm.prediction_cache import DEFAULT_CACHE_DIR, cached_predict
from mkm.registry import build_spec
from mkm.surrogate import kinds
from mkm.surrogate.design import BOX

SWEEP_BAR = np.round(np.arange(0.25, 2.501, 0.25), 2)
PRACTICAL_SWEEP_BAR = np.round(np.arange(0.5, 8.001, 0.5), 2)
KINDS = ("sweep", "sweep", "point", "near threshold")
ABOVE_THRESHOLD_BAR = (0.01, 0.1)


def draw(rng: np.random.Generator) -> tuple[dict, tuple, float, float]:
    """A muscle of the box: its parameters, its geometry (D0, t0, eps), one pressure of the
    sweep and a step above the threshold [bar]."""
    scale = rng.uniform(0.5, 1.5)
    muscle = {"L0_mm": rng.uniform(*BOX["L0_mm"]), "theta0_deg": rng.uniform(*BOX["theta0_deg"]),
              "C10_MPa": 0.0694 * scale, "C01_MPa": 0.0628 * scale}
    geometry = tuple(rng.uniform(*BOX[k]) for k in ("D0_mm", "t0_mm", "eps"))
    return muscle, geometry, float(rng.choice(SWEEP_BAR)), float(rng.uniform(*ABOVE_THRESHOLD_BAR))


def draw_practical(n: int, seed: int, rng: np.random.Generator) -> list:
    """``n`` muscles of the practical range (:func:`mkm.fem.sampling.draw_muscles`, ``seed``),
    as :func:`draw` gives them, pressures from :data:`PRACTICAL_SWEEP_BAR`."""
    from mkm.fem.sampling import draw_muscles

    out = []
    for m in draw_muscles(n, seed).muscles:
        muscle = {"L0_mm": m.L0_mm, "theta0_deg": m.theta0_deg, "C10_MPa": m.C10_MPa,
                  "C01_MPa": m.C01_MPa}
        out.append((muscle, (m.D0_mm, m.t0_mm, m.eps), float(rng.choice(PRACTICAL_SWEEP_BAR)),
                    float(rng.uniform(*ABOVE_THRESHOLD_BAR))))
    return out


def calls(points, sweep_bar=SWEEP_BAR, top_bar=BOX["pressure_bar"][1]):
    """Per muscle: its kind of call, the pressures asked and the fine FE's forces there (None
    where the fine FE failed)."""
    out = []
    for k, (muscle, (D0, t0, eps), P, step) in enumerate(points):
        kind = KINDS[k % len(KINDS)]
        fine, _ = cached_predict(build_spec("axisym:mesh=fine", **muscle), sweep_bar, D0, t0,
                                 eps, cache_dir=DEFAULT_CACHE_DIR)
        threshold = float(np.ravel(fine.extras["threshold_pressure_bar"])[0])
        if kind == "near threshold" and threshold + step <= top_bar:
            pressures = np.array([round(threshold + step, 4)])
            fine, _ = cached_predict(build_spec("axisym:mesh=fine", **muscle), pressures, D0,
                                     t0, eps, cache_dir=DEFAULT_CACHE_DIR)
        elif kind == "sweep":
            pressures = np.asarray(sweep_bar)
        else:
            kind, pressures = "point", np.array([P])
            fine, _ = cached_predict(build_spec("axisym:mesh=fine", **muscle), pressures, D0,
                                     t0, eps, cache_dir=DEFAULT_CACHE_DIR)
        truth = np.ravel(fine.force_N) if fine.valid.all() else None
        out.append((kind, muscle, (D0, t0, eps), pressures, truth, fine.seconds))
    return out


def bound_check(rows) -> dict:
    """Per model that answered: its calls, how many erred beyond the bound auto stated for them
    (its largest ``error_bound_pct`` over the call), the largest error / bound and that call."""
    out = {}
    for model in sorted({r[3] for r in rows}):
        mine = [r for r in rows if r[3] == model]
        ratio = [r[1] / r[2] if r[2] > 0 else (np.inf if r[1] > 0 else 0.0) for r in mine]
        k = int(np.argmax(ratio))
        kind, err, bound, _, call = mine[k]
        out[model] = {"calls": len(mine), "exceeded": int(sum(r[1] > r[2] for r in mine)),
                      "worst_ratio": float(ratio[k]),
                      "worst": {"kind": kind, "err_pct": err, "bound_pct": bound, **call}}
    return out


def reference_check(todo) -> dict:
    """Per reference surrogate (the default one in its box, the practical range's outside):
    over every call with a truth, the factor of its std its error needed, ``max |R - truth| /
    max s`` on the call's scale (auto states ``STD_FACTOR`` of it as the surrogate's bound and
    adds it to a closed form's distance from ``R``): its quantiles, the largest and its call."""
    from mkm.auto import RANGE_SPEC, RANGE_STD_FACTOR, STD_FACTOR, AutoModel

    needed = {}
    for kind, muscle, (D0, t0, eps), pressures, truth, _ in todo:
        if truth is None:
            continue
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            ref = AutoModel(build=build_spec, **muscle).reference(
                pressures, np.full(pressures.shape, D0), np.full(pressures.shape, t0),
                np.full(pressures.shape, eps))
        if ref is None:
            continue
        R, s, spec, _ = ref
        err = np.max(np.abs(R - truth)) / max(float(np.max(np.abs(truth))), MIN_SCALE_N)
        std = np.max(s) / max(float(np.max(np.abs(R))), MIN_SCALE_N)
        # no force and no std (the muscle below its threshold) is no error: 0 of 0
        needed.setdefault(spec, []).append((float(err / std) if std > 0 else
                                            (np.inf if err > 0 else 0.0), kind,
                                            {"D0_mm": D0, "t0_mm": t0, "eps": eps, **muscle}))
    out = {}
    for spec, rows in needed.items():
        k = np.array([r[0] for r in rows])
        worst = rows[int(np.argmax(k))]
        factor = RANGE_STD_FACTOR if spec == RANGE_SPEC else STD_FACTOR
        out[spec] = {"calls": int(k.size), "std_factor": factor,
                     "within_std_factor": float(np.mean(k <= factor)),
                     "within_3_std": float(np.mean(k <= 3.0)),
                     **{f"q{q:g}": float(np.quantile(k, q / 100)) for q in (50, 90, 95, 99)},
                     "largest": float(k.max()), "largest_call": {"kind": worst[1], **worst[2]}}
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--calls", type=int, default=200)
    parser.add_argument("--seed", type=int, default=None)
    parser.add_argument("--tolerances", default="0.005,0.01,0.02,0.05")
    parser.add_argument("--range", choices=tuple(kinds.RANGES), default="box",
                        help="practical: muscles of the practical range (draw_muscles, the "
                        "seed), sweeps 0.5-8 bar: outside the surrogate's box the FE meshes "
                        "answer at their bound on the scale of the call")
    parser.add_argument("--out", default=None)
    args = parser.parse_args()
    seed = args.seed if args.seed is not None else int(np.random.SeedSequence().entropy % 2**32)
    print(f"seed {seed}")
    rng = np.random.default_rng(seed)
    tolerances = [float(t) for t in args.tolerances.split(",")]
    if args.range == "practical":
        todo = calls(draw_practical(args.calls, seed, rng), PRACTICAL_SWEEP_BAR,
                     float(PRACTICAL_SWEEP_BAR[-1]))
    else:
        todo = calls([draw(rng) for _ in range(args.calls)])
    references = reference_check(todo)
    for spec, check in references.items():
        print(f"reference {spec}: over {check['calls']} calls its error was within "
              f"{check['std_factor']:g} std (the factor auto uses) in "
              f"{100 * check['within_std_factor']:.1f} % of them, within 3 std in "
              f"{100 * check['within_3_std']:.1f} %; factor of the std needed: median "
              f"{check['q50']:.3g}, 90 % "
              f"{check['q90']:.3g}, 95 % {check['q95']:.3g}, 99 % {check['q99']:.3g}, largest "
              f"{check['largest']:.3g} ({check['largest_call']})")
    results = {}
    for tol in tolerances:
        rows, used, seconds, failed = [], Counter(), [], 0
        for kind, muscle, (D0, t0, eps), pressures, truth, _ in todo:
            if truth is None:
                failed += 1  # no truth to judge against: counted, not scored
                continue
            start = time.perf_counter()
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                pred = build_spec(f"auto:tolerance={tol}", **muscle).predict(pressures, D0,
                                                                              t0, eps)
            seconds.append(time.perf_counter() - start)
            scale = max(float(np.max(np.abs(truth))), MIN_SCALE_N)
            error = 100 * float(np.max(np.abs(np.ravel(pred.force_N) - truth))) / scale
            model = str(np.ravel(pred.extras["model_used"])[0])
            rows.append((kind, error, float(np.max(pred.extras["error_bound_pct"])), model,
                         {"D0_mm": D0, "t0_mm": t0, "eps": eps, **muscle,
                          "pressures_bar": [float(p) for p in pressures]}))
            used[model] += 1
        errors = np.array([r[1] for r in rows])
        by_kind = {}
        for kind in dict.fromkeys(r[0] for r in rows):
            e = np.array([r[1] for r in rows if r[0] == kind])
            by_kind[kind] = {"calls": int(e.size), "within": float(np.mean(e <= 100 * tol)),
                             "worst_err_pct": float(e.max())}
        within = float(np.mean(errors <= 100 * tol))
        results[tol] = {"calls": len(errors), "no_fe_truth": failed, "within": within,
                        "worst_err_pct": float(errors.max()), "by_kind": by_kind,
                        "bound_by_model": bound_check(rows),
                        "used": dict(used), "auto_s_median": float(np.median(seconds)),
                        "fine_fe_s_median": float(np.median([c[5] for c in todo]))}
        per_kind = "; ".join(f"{k} {100 * v['within']:.1f} % of {v['calls']} (worst "
                          f"{v['worst_err_pct']:.3f} %)" for k, v in by_kind.items())
        print(f"tolerance {100 * tol:g} %: {100 * within:.1f} % of {len(errors)} calls within "
              f"(target >= 99 %), worst {errors.max():.3f} %: {per_kind}; used {dict(used)}; auto "
              f"{np.median(seconds):.3g} s per call (median)")
        for model, check in results[tol]["bound_by_model"].items():
            print(f"  {model}: {check['exceeded']} of {check['calls']} calls above the bound "
                  f"stated, largest error / bound {check['worst_ratio']:.3g} "
                  f"({check['worst']['kind']}: {check['worst']['err_pct']:.3g} % against "
                  f"{check['worst']['bound_pct']:.3g} %)")
    if args.out:
        with open(args.out, "w", encoding="utf-8") as f:
            json.dump({"seed": seed, "calls": args.calls, "range": args.range,
                       "kinds": list(KINDS), "reference_std_factor": references,
                       "above_threshold_bar": list(ABOVE_THRESHOLD_BAR), "results": results,
                       "provenance": provenance()}, f, indent=2, default=jsonable)


if __name__ == "__main__":
    main()
