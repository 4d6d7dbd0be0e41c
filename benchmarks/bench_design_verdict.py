"""``mkm design``'s verdict on fresh random requirements, checked on the fine mesh.

    OPENBLAS_NUM_THREADS=1 .venv/bin/python -P benchmarks/bench_design_verdict.py \
        --specs 24 --seed S [--range practical] [--out FILE.json]

Each spec is one or two requirements (a force-stroke pair: the same pressure at two
shortenings) at a muscle drawn at random: in the default surrogate's box (D0 30-50 mm, t0 2-4 mm,
0.5-2.5 bar, eps 0-0.2, the default L0 and braid angle), or with ``--range practical`` a muscle
of :func:`mkm.fem.sampling.draw_muscles` (its D0 +-30 % as the design's range, its L0 and
braid angle fixed, 1-8 bar, eps up to 70 % of its lock). The force asked is the thick-wall
closed form's at the drawn muscle times 0.6-0.95 (feasible, mostly, and not trivially).
:func:`mkm.design.run_design` designs it as ``mkm design`` does; the chosen design (the best
the FE confirms on its ``fe_mesh``) is then solved on the fine mesh at every requirement. The
promise: the chosen design meets every requirement on the fine mesh too, and its force on the
verifying mesh lies within that mesh's stated error (:func:`mkm.mesh_errors.point_error_N`) of
the fine mesh's. Prints per spec the outcome, the margins and the ratio of the mesh's error to
its bound; ``broken`` counts the specs that break it.
"""

from __future__ import annotations

import argparse
import json
import time
import warnings

import numpy as np

from mkm.core.records import jsonable, provenance
from mkm.design import run_design
from mkm.design.fe_verification import fe_model
from mkm.design.spec import Requirement
from mkm.fem.limits import lock_eps
from mkm.mesh_errors import point_error_N
from mkm.registry import build_spec


def draw_box(rng: np.random.Generator) -> tuple[dict, dict, tuple]:
    """A muscle of the default box, the design's constraints (none: the default box) and the
    requirements' pressure and shortenings."""
    muscle = {"D0_mm": rng.uniform(30, 50), "t0_mm": rng.uniform(2, 4)}
    P = float(np.round(rng.uniform(0.5, 2.5), 2))
    return muscle, {}, (P, float(np.round(rng.uniform(0.0, 0.2), 3)))


def draw_practical(m, rng: np.random.Generator) -> tuple[dict, dict, tuple]:
    """A muscle of the practical range (``m``), its D0 +-30 % as the design's range, its
    length and braid angle fixed."""
    muscle = {"D0_mm": m.D0_mm, "t0_mm": m.t0_mm, "L0_mm": m.L0_mm, "theta0_deg": m.theta0_deg}
    D0 = (max(5.0, 0.7 * m.D0_mm), min(60.0, 1.3 * m.D0_mm))
    constraints = {"D0_mm": D0, "L0_mm": float(m.L0_mm), "theta0_deg": float(m.theta0_deg)}
    P = float(np.round(rng.uniform(1.0, 8.0), 2))
    eps = float(np.round(rng.uniform(0.0, 0.7) * lock_eps(m.theta0_deg), 3))
    return muscle, constraints, (P, eps)


def requirements_for(muscle: dict, P: float, eps: float, rng: np.random.Generator) -> list:
    """One requirement at (P, eps), and on every other spec a second at a larger shortening
    (a force-stroke pair), each at 0.6-0.95 of the thick-wall force of ``muscle`` there."""
    params = {k: muscle[k] for k in ("L0_mm", "theta0_deg") if k in muscle}
    model = build_spec("thickwall", **params)
    shortenings = [eps] if rng.random() < 0.5 else [eps, float(np.round(1.5 * eps + 0.02, 3))]
    out = []
    for e in shortenings:
        force = float(np.ravel(model.predict([P], muscle["D0_mm"], muscle["t0_mm"],
                                             e).force_N)[0])
        if np.isfinite(force) and force > 1.0:
            out.append(Requirement(round(force * rng.uniform(0.6, 0.95), 1), P, e))
    return out


def check(result, requirements) -> dict:
    """The chosen design on the fine mesh: its force and margin per requirement, and the
    verifying mesh's distance from it over its stated bound."""
    best = result.chosen
    if best is None:
        return {"outcome": "no design met every requirement"}
    mesh = str(best["fe_mesh"])
    model = fe_model("fine", best["L0_mm"], best["theta0_deg"], best["rubber"])
    rows = []
    for k, r in enumerate(requirements, start=1):
        pred = model.predict([r.pressure_bar], best["D0_mm"], best["t0_mm"], r.eps)
        fine = float(np.ravel(pred.force_N)[0]) if bool(np.ravel(pred.valid)[0]) else np.nan
        mesh_force = float(best[f"r{k}_fe_N"])
        bound = point_error_N(mesh, mesh_force, r.pressure_bar, float(best[f"r{k}_threshold_bar"]),
                              best["D0_mm"], best["t0_mm"], best["L0_mm"])
        err = abs(mesh_force - fine)
        # the fine mesh's own bound is 0: its sweep and this one point differ by the solver's
        # tolerance alone (the ramp's path), far below 1e-6 of the force
        bound = max(bound, 1e-6 * abs(fine))
        rows.append({"requirement": r.label, "mesh": mesh, "mesh_force_N": mesh_force,
                     "fine_force_N": fine, "fine_margin_pct": 100 * (fine - r.force_N) / r.force_N,
                     "mesh_margin_pct": float(best[f"r{k}_fe_margin_pct"]),
                     "bound_N": bound, "err_N": err,
                     "ratio": err / bound if bound > 0 else (np.inf if err > 0 else 0.0),
                     "fine_meets": bool(np.isfinite(fine) and fine >= r.force_N)})
    broken = any(not r["fine_meets"] or r["ratio"] > 1 for r in rows)
    return {"outcome": "broken" if broken else "held", "chosen": {
        k: best[k] for k in ("D0_mm", "t0_mm", "L0_mm", "theta0_deg", "rubber", "flags")},
        "requirements": rows}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--specs", type=int, default=24)
    parser.add_argument("--seed", type=int, default=None)
    parser.add_argument("--range", choices=("box", "practical"), default="box")
    parser.add_argument("--out", default=None)
    args = parser.parse_args()
    seed = args.seed if args.seed is not None else int(np.random.SeedSequence().entropy % 2**32)
    print(f"seed {seed}")
    rng = np.random.default_rng(seed)
    if args.range == "practical":
        from mkm.fem.sampling import draw_muscles

        # more muscles than specs: a draw whose force is below its threshold asks for nothing
        muscles = iter(draw_muscles(4 * args.specs, seed).muscles)
    rows = []
    while len(rows) < args.specs:
        muscle, constraints, (P, eps) = (draw_practical(next(muscles), rng)
                                         if args.range == "practical" else draw_box(rng))
        requirements = requirements_for(muscle, P, eps, rng)
        if not requirements:
            continue
        labels = [r.label for r in requirements]
        start = time.perf_counter()
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                result = run_design(requirements, constraints)
                row = check(result, requirements)
        except ValueError as error:  # infeasible or refused: said, not a broken promise
            row = {"outcome": "refused", "message": str(error)}
        row.update({"muscle": muscle, "constraints": constraints, "asked": labels,
                    "seconds": time.perf_counter() - start})
        rows.append(row)
        worst = max((r["ratio"] for r in row.get("requirements", [])), default=np.nan)
        margin = min((r["fine_margin_pct"] for r in row.get("requirements", [])),
                     default=np.nan)
        print(f"{row['outcome']:>8}: {', '.join(labels)} {constraints or ''}; fine margin "
              f"{margin:.3g} %, mesh error / bound {worst:.3g}"
              + (f" ({row['requirements'][0]['mesh']})" if "requirements" in row else "")
              + (f"; {row['message'][:160]}" if "message" in row else ""), flush=True)
    outcomes = {k: sum(r["outcome"] == k for r in rows) for k in dict.fromkeys(
        r["outcome"] for r in rows)}
    ratios = [q["ratio"] for r in rows for q in r.get("requirements", [])]
    margins = [q["fine_margin_pct"] for r in rows for q in r.get("requirements", [])]
    summary = {"outcomes": outcomes, "broken": outcomes.get("broken", 0),
               "largest_ratio": max(ratios, default=None),
               "smallest_fine_margin_pct": min(margins, default=None)}
    print(json.dumps(summary, default=jsonable))
    if args.out:
        with open(args.out, "w", encoding="utf-8") as f:
            json.dump({"seed": seed, "specs": args.specs, "range": args.range, **summary,
                       "rows": rows, "provenance": provenance()}, f, indent=2, default=jsonable)


if __name__ == "__main__":
    main()
