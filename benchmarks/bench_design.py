"""Speed of ``mkm design``: the surrogate search of the box and the FE verification.

Run outside the test suite:

    .venv/bin/python benchmarks/bench_design.py [--repeats 20] [--fe-repeats 3]
        [--surrogate surrogate] [--out FILE.json]

- the surrogate search (:func:`mkm.design.box_search`) of the whole training box at the search
  resolution (0.05 mm x 0.01 mm: 80,601 candidates), one requirement and the two-point
  force-stroke spec; the surrogate is loaded once before timing (as within one command); the
  issue's goal is <= 1 s;
- the FE verification (:func:`mkm.design.fe_verification.verify_on_mesh`) of the best 5 designs
  at the converged ``medium`` mesh, one requirement (5 FE sweeps) and the two-point spec (10
  sweeps, one per design and eps); the issue's goal is <= 3 s for 5 designs on this 2-core
  machine;
- the verification as ``mkm design`` does it (:func:`mkm.design.fe_verification.verify`): the
  medium mesh, then the fine one for the designs it met a requirement by less than its error
  (``verified_finer``: how many);
- the chosen design's FE force with its braid 1 deg steeper
  (:func:`mkm.design.fe_verification.steeper_braid_N`), which ``mkm design`` solves after the
  verification where no identified muscle or ``--tolerance`` says how sure its margin is (the
  steeper-braid margin note): one FE solve per requirement on the chosen design's mesh.

Medians, minima and the median CPU time of the process over the repeats: the machine is shared,
and the CPU time (what the work costs without waiting for a core) is the steadier number; the
load average before and after is recorded with them (``load_average_before``, ``_after``).
"""

from __future__ import annotations

import argparse
import json
import os
import time

import numpy as np
from threadpoolctl import threadpool_limits

from mkm.core.records import provenance
from mkm.design import pick, search, verify
from mkm.design.fe_verification import steeper_braid_N, verify_on_mesh

SPECS = {"one point": ["580N@2bar,eps=0.10"],
         "force-stroke": ["300N@2.5bar,eps=0.10", "250N@2.5bar,eps=0.20"]}


def timings(call, repeats: int) -> dict:
    wall, cpu = np.empty(repeats), np.empty(repeats)
    for i in range(repeats):
        start, start_cpu = time.perf_counter(), time.process_time()
        call()
        wall[i], cpu[i] = time.perf_counter() - start, time.process_time() - start_cpu
    return {"median_s": float(np.median(wall)), "min_s": float(np.min(wall)),
            "cpu_median_s": float(np.median(cpu)), "repeats": repeats}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=20)
    parser.add_argument("--fe-repeats", type=int, default=3)
    parser.add_argument("--surrogate", default="surrogate")
    parser.add_argument("--out", help="also write the results as JSON here")
    args = parser.parse_args()
    rows = []
    load_before = os.getloadavg()
    with threadpool_limits(limits=1):
        for name, reqs in SPECS.items():
            found = search(reqs, surrogate=args.surrogate)  # loads the surrogate once
            rows.append({"stage": "surrogate search", "spec": name,
                         "candidates": len(found.candidates),
                         **timings(lambda r=reqs: search(r, surrogate=args.surrogate),
                                   args.repeats)})
            designs = pick(found.feasible, 5, found.constraints)
            designs.insert(0, "rank", np.arange(1, len(designs) + 1))
            rows.append({"stage": "FE verification (medium)", "spec": name,
                         "designs": len(designs),
                         "sweeps": len(designs) * len({r.eps for r in found.requirements}),
                         **timings(lambda d=designs, f=found: verify_on_mesh(
                             d, f.requirements, "medium", f.working_pressure_bar),
                             args.fe_repeats)})
            verified = verify(designs, found.requirements, "medium",
                              found.working_pressure_bar)[0]
            rows.append({"stage": "FE verification (as mkm design)", "spec": name,
                         "designs": len(designs),
                         "verified_finer": int((verified["fe_mesh"] != "medium").sum()),
                         **timings(lambda d=designs, f=found: verify(
                             d, f.requirements, "medium", f.working_pressure_bar),
                             args.fe_repeats)})
            chosen = verified[verified["meets_all"]].iloc[0]
            rows.append({"stage": "FE steeper braid (1 deg)", "spec": name, "designs": 1,
                         "sweeps": len(found.requirements),
                         **timings(lambda c=chosen, f=found: steeper_braid_N(
                             c, f.requirements, None), args.fe_repeats)})
    print(f"{'stage':26s} {'spec':13s} {'size':>14s} {'median s':>9s} {'min s':>7s} "
          f"{'cpu s':>7s}")
    for r in rows:
        size = (f"{r['candidates']} cand." if "candidates" in r
                else f"{r['designs']} des./{r['verified_finer']} finer"
                if "verified_finer" in r else f"{r['designs']} des./{r['sweeps']} sw.")
        print(f"{r['stage']:26s} {r['spec']:13s} {size:>14s} {r['median_s']:9.3f} "
              f"{r['min_s']:7.3f} {r['cpu_median_s']:7.3f}")
    if args.out:
        with open(args.out, "w", encoding="utf-8") as f:
            json.dump({"rows": rows, "surrogate": args.surrogate,
                       "load_average_before": load_before,
                       "load_average_after": os.getloadavg(), **provenance()}, f, indent=2)


if __name__ == "__main__":
    main()
