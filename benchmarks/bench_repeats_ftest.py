"""How often identify's F test calls a step table judged by its repeats a misfit when the model
fitted is the truth's: its p-values should be uniform, below 0.05 in 5 % of the fits.

Run outside the test suite:

    OPENBLAS_NUM_THREADS=1 .venv/bin/python benchmarks/bench_repeats_ftest.py \
        [--fits 200] [--seed 2026121161] [--sweeps 3]

Each fit is of two step tables of the thick-wall model (eps 0 and 12.2 %, ``--sweeps`` sweeps
0.5-2.5-0.5 bar each, imported without a declared accuracy: ``repeated_tables`` of
``tests/mkm/test_goodness.py``) at a fresh braid angle (28-36 deg), noise (0.3-3 N) and seed,
the angle and the rubber fitted with the thick-wall model; :func:`mkm.identify.goodness.assess`
judges it by the scatter of its repeats. Prints the misfits and the shares of the overall
p-value below 0.05, 0.2 and 0.5.
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from mkm.identify import goodness

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "mkm"))
from test_goodness import repeated_tables  # noqa: E402  (the tests' tables, not a copy)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--fits", type=int, default=200)
    parser.add_argument("--seed", type=int, default=2026121161)
    parser.add_argument("--sweeps", type=int, default=3)
    args = parser.parse_args()
    rng = np.random.default_rng(args.seed)
    p_values, misfits, start = [], 0, time.process_time()
    for _ in range(args.fits):
        seed = int(rng.integers(1 << 31))
        theta0_deg, noise_N = float(rng.uniform(28, 36)), float(rng.uniform(0.3, 3.0))
        with tempfile.TemporaryDirectory() as folder:
            runs, fit = repeated_tables(Path(folder), {"theta0_deg": theta0_deg},
                                        cycles=args.sweeps, noise_N=noise_N, seed=seed)
            judged = goodness.assess(runs, fit)
        p_values.append(judged.p_value)
        misfits += bool(judged.misfit)
    p = np.array(p_values)
    print(f"seed {args.seed}, {args.fits} fits of {args.sweeps} sweeps: {misfits} misfit; "
          f"p below 0.05 in {100 * np.mean(p < 0.05):.1f} %, below 0.2 in "
          f"{100 * np.mean(p < 0.2):.1f} %, below 0.5 in {100 * np.mean(p < 0.5):.1f} % "
          f"({time.process_time() - start:.0f} s CPU)")


if __name__ == "__main__":
    main()
