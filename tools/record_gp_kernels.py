"""Record the optimised hyperparameters of the Gaussian processes the shipped kinds fit on their
own datasets into ``surrogate/data/gp_kernels.json`` (:data:`mkm.surrogate.gp.KERNELS_FILE`).

    OPENBLAS_NUM_THREADS=1 .venv/bin/python -P tools/record_gp_kernels.py [--kinds K ...]

The optimiser of a process's marginal likelihood is most of a first training (seconds for the
default surrogate, about a minute for the practical-range one). Training looks each process up
by what its optimum depends on (:func:`mkm.surrogate.gp.kernel_key`: its points and targets, the
kernel, the optimiser's settings) and, where this file holds it, fits the process at those
hyperparameters without the search: the same process. Run this after a change of a kind's
dataset or of how it builds its processes' inputs (training still works without it: it
searches). Default kinds: every registered kind whose estimator fits these processes.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from mkm.core.records import command_line, file_sha256, provenance, write_json_atomic
from mkm.surrogate.gp import KERNELS_FILE, recording_kernels
from mkm.surrogate.kinds import entry, names
from mkm.surrogate.train import kind_files, train_surrogate

# the checkout's file (an editable install links it; the installed path may not exist yet)
OUT = Path(__file__).resolve().parents[1] / "surrogate" / "data" / KERNELS_FILE


def gp_kinds() -> list[str]:
    """The registered kinds that fit :func:`mkm.surrogate.gp.fit_gaussian_process` processes
    (their estimators are built on :mod:`mkm.surrogate.muscle_gp`)."""
    return [k for k in names(include_families=False)
            if "mkm.surrogate.muscle_gp" in entry(k).modules]


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--kinds", nargs="+", default=None,
                        help="kinds to record (default: every kind fitting such processes)")
    args = parser.parse_args(argv)
    kinds = args.kinds or gp_kinds()
    record = {"provenance": {**provenance(), "command": command_line()}, "kinds": {},
              "kernels": {}}
    for kind in kinds:
        with recording_kernels() as found:
            train_surrogate(kind, splits=0)
        dataset = kind_files(kind)[0]
        record["kinds"][kind] = {"dataset": dataset.name, "sha256": file_sha256(dataset),
                                 "processes": len(found)}
        record["kernels"].update(found)
        print(f"{kind}: {len(found)} processes recorded")
    write_json_atomic(OUT, record)
    print(f"wrote {OUT}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
