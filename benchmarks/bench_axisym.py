"""Speed of the axisymmetric FE model: one 11-pressure isometric sweep per mesh level.

Run outside the test suite:

    .venv/bin/python benchmarks/bench_axisym.py [--levels coarse,medium,fine] [--repeats 3]
        [--eps 0.05,0.2] [--braids bonded,sliding]

Muscle I (D0 35 mm, t0 2.5 mm, L0 282 mm) at the calibrated theta0, pressures 0 to 2.5 bar in
0.25 bar steps, as `mkm fem solve` runs it. For each level and eps it reports the median wall
time of the sweep, the unknowns, the Newton iterations (threshold search + pressure ramp) and
where the time goes: mesh and operator set-up, tangent assembly, sparse LU (SuperLU) and the
rest (Python, residual checks), with the number of assemblies and factorisations (counts do not
depend on the machine's load). The split is measured by wrapping those three functions with
timers in this script only. Goal (issue 11): medium <= 0.15 s and fine <= 1 s per sweep on the
project's 2-core machine, forces unchanged to 1e-6 relative. The machine is shared, so compare
the Newton iteration counts too: 62-69 (medium) and 75-78 (fine) before the thick-wall start of
the threshold search and the chord convergence check, 24-29 after. The LU column is SuperLU's
factorisation only; the pressure ramp's symmetric permutation (:class:`mkm.fem.fe.newton.OrderedLU`)
counts as "rest". Goal for the sliding braid: no more than twice the bonded one's time on the
fine mesh (its one sleeve tension is a dense row of the tangent, numbered last).
"""

from __future__ import annotations

import argparse
import json
import time

import numpy as np

import mkm.fem.fe.model
import mkm.fem.fe.newton
from mkm.core.records import provenance

PRESSURES_BAR = np.arange(0.0, 2.51, 0.25)
MUSCLE_I = {"D0_mm": 35.0, "t0_mm": 2.5, "L0_mm": 282.0}


class Timers:
    """Wall time spent inside wrapped functions, by name."""

    def __init__(self):
        self.seconds: dict[str, float] = {}
        self.calls: dict[str, int] = {}

    def wrap(self, name, func):
        def timed(*args, **kwargs):
            self.calls[name] = self.calls.get(name, 0) + 1
            start = time.perf_counter()
            try:
                return func(*args, **kwargs)
            finally:
                self.seconds[name] = self.seconds.get(name, 0.0) + time.perf_counter() - start

        return timed


def bench_sweep(level: str, eps: float, theta0_deg: float, braid: str = "bonded") -> dict:
    timers = Timers()
    half = mkm.fem.fe.model.HalfMuscle
    init, assemble, splu = half.__init__, half._assemble, mkm.fem.fe.newton.splu
    half.__init__ = timers.wrap("setup", init)
    half._assemble = timers.wrap("assembly", assemble)
    mkm.fem.fe.newton.splu = timers.wrap("lu", splu)
    try:
        start = time.perf_counter()
        out = mkm.fem.fe.model.isometric_sweep(
            PRESSURES_BAR, MUSCLE_I["D0_mm"], MUSCLE_I["t0_mm"], eps, theta0_deg, MUSCLE_I["L0_mm"],
            level, braid=braid)
        total = time.perf_counter() - start
    finally:
        half.__init__, half._assemble = init, assemble
        mkm.fem.fe.newton.splu = splu
    below = out["force_N"] == 0
    threshold_iterations = int(out["iterations"][below].max()) if below.any() else 0
    t = timers.seconds
    return {"mesh": level, "braid": braid, "eps": eps, "dofs": int(out["dofs"][0]),
            "seconds": total,
            "iterations": threshold_iterations + int(out["iterations"][~below].sum()),
            "setup_s": t.get("setup", 0.0), "assembly_s": t.get("assembly", 0.0),
            "lu_s": t.get("lu", 0.0), "assemblies": timers.calls.get("assembly", 0),
            "factorisations": timers.calls.get("lu", 0),
            "other_s": total - sum(t.get(k, 0.0) for k in ("setup", "assembly", "lu")),
            "converged": bool(out["converged"].all()), "force_2p5bar_N": out["force_N"][-1]}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--levels", default="coarse,medium,fine")
    parser.add_argument("--eps", default="0.05,0.2")
    parser.add_argument("--braids", default="bonded")
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    theta0 = mkm.fem.fe.model.Axisym().params()["theta0_deg"]
    rows = []
    for level in args.levels.split(","):
        for eps in (float(e) for e in args.eps.split(",")):
            for braid in args.braids.split(","):
                runs = [bench_sweep(level, eps, theta0, braid) for _ in range(args.repeats)]
                median = sorted(runs, key=lambda r: r["seconds"])[len(runs) // 2]
                rows.append(median)
    info = provenance()
    print(f"# muscle I, 11 pressures 0-2.5 bar, theta0 {theta0} deg, median of {args.repeats}; "
          f"{info['date_utc']}, {info['machine']}, {json.dumps(info['versions'])}")
    print("mesh,braid,eps,dofs,seconds,iterations,assemblies,factorisations,setup_s,assembly_s,lu_s,"
          "other_s,converged,force_2p5bar_N")
    for r in rows:
        print(f"{r['mesh']},{r['braid']},{r['eps']:g},{r['dofs']},{r['seconds']:.3f},{r['iterations']},"
              f"{r['assemblies']},{r['factorisations']},"
              f"{r['setup_s']:.3f},{r['assembly_s']:.3f},{r['lu_s']:.3f},{r['other_s']:.3f},"
              f"{r['converged']},{r['force_2p5bar_N']:.2f}")


if __name__ == "__main__":
    main()
