"""How often identify's F test calls a step table judged by its repeats a misfit: its size
where the model fitted is the truth's (its p-values uniform, below 0.05 in 5 % of the fits) and
its power where the truth has a gap the fitted model has not.

Run outside the test suite:

    OPENBLAS_NUM_THREADS=1 .venv/bin/python benchmarks/bench_repeats_ftest.py \
        [--fits 3000] [--wrong-fits 400] [--gap-mm 0.05] [--seed 2026121163] [--sweeps 3] \
        [--out FILE.json]

Each fit is of two step tables of the thick-wall model (eps 0 and 12.2 %, ``--sweeps`` sweeps
0.5-2.5-0.5 bar each, imported without a declared accuracy: ``repeated_tables`` of
``tests/mkm/test_goodness.py``) at a fresh braid angle (28-36 deg), noise (0.3-3 N) and seed,
the angle and the rubber fitted with the thick-wall model; :func:`mkm.identify.goodness.assess`
judges it by the scatter of its repeats. ``--fits`` fits of tables the thick-wall model made
(the right model: the size), ``--wrong-fits`` of tables of a muscle with a ``--gap-mm`` gap
between tube and braid, which the fitted model has not (a wrong one: the power). Prints, per
model, the share of the overall p-value below 0.05 with its exact (Clopper-Pearson) 95 %
interval, the shares below 0.2 and 0.5, and the misfits identify calls (at
:data:`mkm.identify.goodness.MISFIT_P`).
"""

from __future__ import annotations

import argparse
import json
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
from scipy import stats

from mkm.core.records import provenance, write_atomic
from mkm.identify import goodness

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "mkm"))
from test_goodness import repeated_tables  # noqa: E402  (the tests' tables, not a copy)


def judge(fits: int, gap_mm: float, rng: np.random.Generator, sweeps: int) -> dict:
    """``fits`` fits of fresh tables of a muscle with ``gap_mm``, judged; their p-values'
    shares below 0.05 (with its 95 % interval), 0.2 and 0.5 [%] and the misfits."""
    p_values, misfits, start = [], 0, time.process_time()
    for _ in range(fits):
        seed = int(rng.integers(1 << 31))
        truth = {"theta0_deg": float(rng.uniform(28, 36)), **({"gap_mm": gap_mm} if gap_mm
                                                              else {})}
        noise_N = float(rng.uniform(0.3, 3.0))
        with tempfile.TemporaryDirectory() as folder:
            runs, fit = repeated_tables(Path(folder), truth, cycles=sweeps, noise_N=noise_N,
                                        seed=seed)
            judged = goodness.assess(runs, fit)
        p_values.append(judged.p_value)
        misfits += bool(judged.misfit)
    p = np.array(p_values)
    below = int(np.sum(p < 0.05))
    interval = stats.binomtest(below, fits).proportion_ci(confidence_level=0.95, method="exact")
    return {"truth": f"thick-wall, gap {gap_mm:g} mm" if gap_mm else "thick-wall (the fitted)",
            "fits": fits, "p below 0.05": below,
            "share below 0.05 [%]": round(100 * below / fits, 2),
            "95 % interval low [%]": round(100 * interval.low, 2),
            "95 % interval high [%]": round(100 * interval.high, 2),
            "share below 0.2 [%]": round(100 * float(np.mean(p < 0.2)), 2),
            "share below 0.5 [%]": round(100 * float(np.mean(p < 0.5)), 2),
            "misfits": misfits, "cpu_s": round(time.process_time() - start, 1)}


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--fits", type=int, default=3000, help="fits of the right model")
    parser.add_argument("--wrong-fits", type=int, default=400,
                        help="fits of tables with a gap the fitted model has not")
    parser.add_argument("--gap-mm", type=float, default=0.05,
                        help="the wrong tables' gap between tube and braid [mm]")
    parser.add_argument("--seed", type=int, default=2026121163)
    parser.add_argument("--sweeps", type=int, default=3)
    parser.add_argument("--out", help="also write the rows and the provenance here (JSON)")
    args = parser.parse_args(argv)
    if args.fits < 1 or args.wrong_fits < 0 or not args.gap_mm > 0 or args.sweeps < 1:
        print(f"bench_repeats_ftest.py: error: --fits {args.fits} --wrong-fits "
              f"{args.wrong_fits} --gap-mm {args.gap_mm:g} --sweeps {args.sweeps}: expected at "
              "least 1 fit, no negative count, a gap above 0 mm and at least 1 sweep",
              file=sys.stderr)
        return 2
    right, wrong = (np.random.default_rng(s) for s in np.random.SeedSequence(args.seed).spawn(2))
    rows = [judge(args.fits, 0.0, right, args.sweeps)]
    if args.wrong_fits:
        rows.append(judge(args.wrong_fits, args.gap_mm, wrong, args.sweeps))
    for row in rows:
        print(f"{row['truth']}: {row['fits']} fits of {args.sweeps} sweeps, p below 0.05 in "
              f"{row['share below 0.05 [%]']:.1f} % (95 % interval "
              f"{row['95 % interval low [%]']:.1f}-{row['95 % interval high [%]']:.1f}), below "
              f"0.2 in {row['share below 0.2 [%]']:.1f} %, below 0.5 in "
              f"{row['share below 0.5 [%]']:.1f} %; {row['misfits']} misfit "
              f"({row['cpu_s']:.0f} s CPU)")
    if args.out:
        record = {**provenance(), "seed": args.seed, "sweeps": args.sweeps,
                  "gap_mm": args.gap_mm, "misfit_p": goodness.MISFIT_P, "rows": rows}
        write_atomic(args.out, json.dumps(record, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
