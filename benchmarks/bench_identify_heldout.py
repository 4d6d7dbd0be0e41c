"""``mkm identify``'s held-out table against the fit to its own runs, on fresh random muscles.

Run outside the test suite:

    .venv/bin/python benchmarks/bench_identify_heldout.py [--draws 12] [--seed S]

Each draw is a muscle of :func:`bench_identify.draw` on the simulated FE bench; its three runs
(eps 0, 12.2 % and the draw's third eps in 4-10 %) are identified together with the default
parameters, each run held out in turn. One row per run: its largest |Err%| per branch held out
(predicted from the other runs) and fitted (the identification of every run), and whether the
fit to its own run misses it by more than the held-out prediction does. Then how many runs and
branches did, by how much at most, and the largest held-out error among them.
"""

from __future__ import annotations

import argparse
import os
import sys
import tempfile
from pathlib import Path

import numpy as np
from bench_identify import FIT_EPS, acquire_truth, draw

from mkm.identify import identify

BRANCHES = ("rising", "falling")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--draws", type=int, default=12)
    parser.add_argument("--seed", type=int, default=None)
    args = parser.parse_args(argv)
    seed = args.seed if args.seed is not None else int(np.random.SeedSequence().entropy % 2**32)
    print(f"seed {seed}")
    rng = np.random.default_rng(seed)
    runs_larger, branches, larger = 0, 0, []
    with tempfile.TemporaryDirectory() as tmp:
        os.environ["MKM_STATE_DIR"] = str(Path(tmp) / "state")
        for k in range(args.draws):
            truth = draw(rng)
            runs = [acquire_truth(truth, eps, Path(tmp) / f"draw{k}")
                    for eps in (*FIT_EPS, truth["heldout_eps"])]
            for row in identify(runs).checks_table().to_dict(orient="records"):
                held = [row[f"heldout_{b}_pct"] for b in BRANCHES]
                own = [row[f"identified_{b}_pct"] for b in BRANCHES]
                over = [(o - h, h) for o, h in zip(own, held, strict=True) if o > h]
                branches += len(BRANCHES)
                larger += over
                runs_larger += bool(over)
                print(f"draw {k} eps {row['eps']:.3f}: held out {held[0]:.4f}/{held[1]:.4f} %, "
                      f"own fit {own[0]:.4f}/{own[1]:.4f} %"
                      + (" (own fit larger)" if over else ""), flush=True)
    runs = 3 * args.draws
    print(f"over {args.draws} draws: the fit to its own run larger than held out on "
          f"{runs_larger} of {runs} runs ({len(larger)} of {branches} branches)"
          + (f", by at most {max(d for d, _ in larger):.4f} points, where held out "
             f"{max(h for _, h in larger):.4f} % at most" if larger else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
