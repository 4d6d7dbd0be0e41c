"""The default surrogate's muscle-held-out refits, written to the file training reuses
(``surrogate/data/muscle_held_out.json``, :data:`mkm.surrogate.train.HELD_OUT_FILE`).

    OPENBLAS_NUM_THREADS=1 .venv/bin/python benchmarks/bench_held_out.py [--check]

Training the default surrogate refits it on 10 splits that hold out whole muscles (its
``muscle_held_out`` metrics, about 80 % of its training time). The file keeps every split's
scores and their summary with a key of what they depend on (dataset, kind, splits, libraries,
model and training code, std sets: :func:`mkm.surrogate.train.held_out_key`); training reuses
them while the key matches and refits otherwise. Run this after a change of any of those, so a
first use trains in seconds again. ``--check``: refit every split and compare with the file
instead of writing it (exit 1 on a difference).
"""

from __future__ import annotations

import argparse
import json
import sys

from mkm.core.records import jsonable, write_json_atomic
from mkm.surrogate.train import HELD_OUT_FILE, compute_held_out

# the scores a refit reproduces exactly (the fit's wall time is the machine's)
TIMING = "fit_seconds"


def comparable(result: dict) -> list[dict]:
    return [{k: v for k, v in row.items() if k != TIMING} for row in result["splits"]]


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true",
                        help="refit and compare with the shipped file, write nothing")
    args = parser.parse_args(argv)
    result = json.loads(json.dumps(compute_held_out(), default=jsonable))
    if args.check:
        shipped = json.loads(HELD_OUT_FILE.read_text(encoding="utf-8"))
        same = (shipped["key"] == result["key"]
                and comparable(shipped) == comparable(result))
        print(f"{HELD_OUT_FILE}: {'matches' if same else 'differs from'} a fresh refit")
        return 0 if same else 1
    write_json_atomic(HELD_OUT_FILE, result)
    print(HELD_OUT_FILE)
    return 0


if __name__ == "__main__":
    sys.exit(main())
