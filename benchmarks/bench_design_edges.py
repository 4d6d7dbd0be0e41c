"""``mkm design``'s edge line on fresh requirements over the practical range: it must appear
exactly when the chosen design sits on an end of a range searched, and name the box searched.

    OPENBLAS_NUM_THREADS=1 .venv/bin/python -P benchmarks/bench_design_edges.py [SEED] [N]

Each requirement is at a muscle of :func:`mkm.fem.sampling.draw_muscles` (1-8 bar, eps up to
60 % of its lock, 0.6-0.95 of its thick-wall force), with each of a D0 (+-30 %), t0 (+-40 %),
L0 (+-30 %) and theta0 (+-3 deg) range of it given half of the time.
:func:`mkm.design.run_design` designs it as ``mkm design`` does (``--top 3``); per
requirement one JSON line gives the ranges of the candidates searched beside the box the
search states, the ends of them the chosen design sits on, and the edge and limit lines (an
infeasible one, its message).
"""

from __future__ import annotations

import json
import sys
import time
import warnings

import numpy as np

from mkm.design import run_design
from mkm.design.box_search import BOX_NAMES
from mkm.design.spec import Requirement
from mkm.fem.limits import PRACTICAL_RANGE, lock_eps
from mkm.fem.sampling import draw_muscles
from mkm.registry import build_spec


def requirement(m, rng) -> tuple[list, dict]:
    """One requirement at muscle ``m`` and the ranges a user gives of it."""
    P = float(np.round(rng.uniform(1.0, 8.0), 2))
    eps = float(np.round(rng.uniform(0.0, 0.6) * lock_eps(m.theta0_deg), 3))
    model = build_spec("thickwall", L0_mm=m.L0_mm, theta0_deg=m.theta0_deg)
    F = float(np.ravel(model.predict([P], m.D0_mm, m.t0_mm, eps).force_N)[0])
    req = [Requirement(round(F * rng.uniform(0.6, 0.95), 1), P, eps)]
    constraints = {}
    for key, value, low, high in (("D0_mm", m.D0_mm, 0.7, 1.3), ("t0_mm", m.t0_mm, 0.6, 1.4),
                                  ("L0_mm", m.L0_mm, 0.7, 1.3)):
        if rng.random() < 0.5:
            lowest, highest = getattr(PRACTICAL_RANGE, key)
            constraints[key] = (round(max(lowest, low * value), 2),
                                round(min(highest, high * value), 2))
    if rng.random() < 0.5:
        constraints["theta0_deg"] = (round(max(15, m.theta0_deg - 3), 1),
                                     round(min(40, m.theta0_deg + 3), 1))
    return req, constraints


def main() -> None:
    seed = int(sys.argv[1]) if len(sys.argv) > 1 else 2026120722
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 10
    rng = np.random.default_rng(seed)
    for i, m in enumerate(draw_muscles(n, seed=seed).muscles):
        req, constraints = requirement(m, rng)
        start = time.perf_counter()
        out = {"i": i, "requirement": req[0].label, "constraints": constraints}
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                result = run_design(req, constraints, top=3, workers=1)
        except ValueError as exc:
            print(json.dumps({**out, "error": str(exc)}), flush=True)
            continue
        s, best = result.search, result.chosen
        searched = {k: (float(s.candidates[k].min()), float(s.candidates[k].max()))
                    for k in BOX_NAMES}
        out.update({"searcher": s.searcher, "s": round(time.perf_counter() - start, 1),
                    "searched": searched,
                    "stated_box": {k: tuple(s.constraints[k]) for k in BOX_NAMES}})
        if best is not None:
            chosen = {k: float(best[k]) for k in BOX_NAMES}
            ends = {k: "low" if np.isclose(chosen[k], low, atol=1e-9) else
                    "high" if np.isclose(chosen[k], high, atol=1e-9) else ""
                    for k, (low, high) in searched.items() if high > low}
            notes = result.notes()
            out.update({"chosen": chosen,
                        "on_end_of_searched": {k: v for k, v in ends.items() if v},
                        "edge_note": [n for n in notes if "edge of the search box" in n],
                        "limit_note": [n for n in notes if "practical range's limit" in n]})
        print(json.dumps(out), flush=True)


if __name__ == "__main__":
    main()
