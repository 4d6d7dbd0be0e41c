"""What a new user's `mkm identify RUNS` (its defaults) says on the simulated FE bench made wrong
one way at a time, at or beyond the declared tolerances: do its 95 % intervals hold the truth,
or does it warn?

Run outside the test suite:

    .venv/bin/python benchmarks/bench_identify_wrong_bench.py [--draws 6] [--seed 20261240]
        [--departures loadcell gain,...] [--params GROUPS]
        [--out docs/measured/identify_wrong_bench.json]

Each draw is a fresh muscle (theta0 30-36 deg, rubber x0.8-1.2 on Silastic S, braid friction
0-6 %, creep 0-3 %, tau 30 s) on the default simulated bench (the FE model, medium mesh, the
simulator's noise) with one departure (:data:`DEPARTURES`), drawn from its own numpy seed
(``--seed`` plus the draw's index, recorded per draw): the load cell's gain 2 % off (either
sign; 20 times its declared tolerance), the cell's zero left in the forces (the tare left out:
an amplifier offset of 0.01-0.05 V, 2-10 N, added to every recorded force; or each run its
own, the eps 0 run's 0.5-3 N beyond the other's, either sign: runs tared apart), the cell's zero
drifting 0.5-2 N/min from the start (either sign: 2-7 N by the end of a run), the pressure monitor
0.02-0.04 bar off (within its declared 0.04 bar) or its gain 1 % off (either sign), a rubber whose
C01/C10 is not Silastic S's (0-0.3 or 1.8-2.5, the same small-strain stiffness), a braid angle
within 0.4 deg of the surrogate box's edge (28 or 38 deg, either side), a radial gap of 0.3-1 mm
between tube and braid, strong braid friction (8-12 %) with strong creep (4-6 %), and creep of
2-4 % with another time constant than the simulator's default 30 s (5-10 s or 90-300 s, the
holds lasting about 10 s). Two runs (eps 0 and 12.2 %) are acquired, stripped of the truth and
identified by ``identify(runs)`` (a run the bench's own checks failed is kept: identify's
refusal is then the draw's verdict, ``refused``): the default parameters (or ``--params``:
what a user who read the notes would fit, the load cell's zero say), the surrogate search, the
FE confirmation.

Every parameter reported with an interval is judged against the truth as
``bench_identify_coverage.judge`` does (the rubber, where one scale, against the truth's
equivalent scale at the assumed ratio; the monitor's offset against the true offset, not judged
under a gain). A draw is ``covered`` when every interval holds the truth, ``warned`` when some
miss and identify printed a misfit line or a warning about the instruments
(``bench_identify_coverage.instrument_warning``), ``SILENT`` when some miss without either.
Prints one row per draw; ``--out`` writes the draws x departures table, every draw's
parameters and notes, the seeds and provenance.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np
import pandas as pd
from bench_identify_coverage import (
    departures_arg,
    each_draw,
    instrument_warning,
    judge,
    write_record,
)

from mkm.bench.config import load_config
from mkm.bench.run import acquire
from mkm.bench.sim_settings import remove_simulator_settings
from mkm.fem.materials import SILASTIC_S
from mkm.identify import identify
from mkm.surrogate.design import BOX

FIT_EPS = (0.0, 0.122)
DEPARTURES = ("loadcell gain", "loadcell offset", "loadcell drift", "monitor offset",
              "monitor gain", "rubber ratio", "theta0 at box edge", "gap", "friction and creep",
              "creep time", "loadcell offset per run")
#: what ``--departures`` draws by default: the recorded results' set (a departure added to it
#: would give every later draw another seed), the drift and the zero per run asked for by name
DEFAULT_DEPARTURES = tuple(d for d in DEPARTURES
                           if d not in ("loadcell drift", "loadcell offset per run"))
FIRST_SEED = 20261240
#: the fields of a draw's printed line
COLUMNS = ("seed", "departure", "value", "verdict", "chi2_per_nu", "missed", "far", "seconds")


def draw(seed: int, departure: str, config) -> dict:
    """A muscle and its one departure (``truth``: the ``[sim.truth]`` table;
    ``loadcell_offset_N``: the zero left in every recorded force)."""
    rng = np.random.default_rng(seed)
    scale = float(rng.uniform(0.8, 1.2))
    truth = {"theta0_deg": float(rng.uniform(30.0, 36.0)), "C10_MPa": scale * SILASTIC_S.C10_MPa,
             "C01_MPa": scale * SILASTIC_S.C01_MPa}
    muscle = {"departure": departure, "seed": seed, "truth": truth, "loadcell_offset_N": 0.0,
              "hysteresis_fraction": float(rng.uniform(0.0, 0.06)),
              "creep_fraction": float(rng.uniform(0.0, 0.03))}
    sign = float(rng.choice((-1.0, 1.0)))
    if departure == "loadcell gain":
        truth["loadcell_gain"] = 1.0 + sign * 0.02
    elif departure in ("loadcell offset", "loadcell offset per run"):
        muscle["loadcell_offset_N"] = (sign * float(rng.uniform(0.01, 0.05))
                                       * config.loadcell.sensitivity_N_per_V)
        if departure == "loadcell offset per run":
            muscle["eps0_zero_apart_N"] = (float(rng.choice((-1.0, 1.0)))
                                           * float(rng.uniform(0.5, 3.0)))
    elif departure == "loadcell drift":
        truth["loadcell_drift_N_per_min"] = sign * float(rng.uniform(0.5, 2.0))
    elif departure == "monitor offset":
        truth["monitor_offset_bar"] = sign * float(rng.uniform(0.02, 0.04))
    elif departure == "monitor gain":
        truth["monitor_gain"] = 1.0 + sign * 0.01
    elif departure == "rubber ratio":
        ratio = float(rng.uniform(0.0, 0.3) if sign < 0 else rng.uniform(1.8, 2.5))
        stiffness = scale * (SILASTIC_S.C10_MPa + SILASTIC_S.C01_MPa)
        truth.update(C10_MPa=stiffness / (1 + ratio), C01_MPa=stiffness * ratio / (1 + ratio))
    elif departure == "theta0 at box edge":
        edge = BOX["theta0_deg"][0 if sign < 0 else 1]
        truth["theta0_deg"] = edge + float(rng.uniform(-0.4, 0.4))
    elif departure == "gap":
        truth["gap_mm"] = float(rng.uniform(0.3, 1.0))
    elif departure == "friction and creep":
        muscle.update(hysteresis_fraction=float(rng.uniform(0.08, 0.12)),
                      creep_fraction=float(rng.uniform(0.04, 0.06)))
    elif departure == "creep time":
        muscle.update(creep_fraction=float(rng.uniform(0.02, 0.04)),
                      creep_tau_s=float(rng.uniform(5.0, 10.0) if sign < 0
                                        else rng.uniform(90.0, 300.0)))
    return muscle


def leave_zero_in(run: Path, offset_N: float) -> None:
    """The run as recorded without a tare: every force (the tare's samples, each hold, the steps'
    means) carries the cell's zero ``offset_N``."""
    for name, column in (("samples.csv", "force_N"), ("steps.csv", "force_N_mean")):
        table = pd.read_csv(run / name)
        table[column] = table[column] + offset_N
        table.to_csv(run / name, index=False)


def acquire_blind(muscle: dict, eps: float, out: Path) -> Path:
    config = load_config(eps=eps).replace(sim={
        "hysteresis_fraction": muscle["hysteresis_fraction"],
        "creep_fraction": muscle["creep_fraction"],
        "creep_tau_s": muscle.get("creep_tau_s", 30.0), "seed": muscle["seed"] + int(1000 * eps),
        "truth": muscle["truth"]})
    # a run the bench's checks fail is kept: what identify says of it is the draw's verdict
    result = acquire(config, out_root=out, notify=lambda message: None)
    remove_simulator_settings(result.path)
    offset_N = muscle["loadcell_offset_N"] + (muscle.get("eps0_zero_apart_N", 0.0) if eps == 0
                                               else 0.0)
    if offset_N:
        leave_zero_in(result.path, offset_N)
    return result.path


def departure_value(muscle: dict) -> str:
    t = muscle["truth"]
    d = muscle["departure"]
    if d == "loadcell offset":
        return f"{muscle['loadcell_offset_N']:+.2f} N"
    if d == "loadcell offset per run":
        return (f"{muscle['loadcell_offset_N']:+.2f} N, at eps 0 "
                f"{muscle['eps0_zero_apart_N']:+.2f} N more")
    if d == "rubber ratio":
        return f"C01/C10 {t['C01_MPa'] / t['C10_MPa']:.3g}"
    if d == "creep time":
        return f"creep {muscle['creep_fraction']:.3f}, tau {muscle['creep_tau_s']:.3g} s"
    if d == "friction and creep":
        return f"friction {muscle['hysteresis_fraction']:.3f}, creep {muscle['creep_fraction']:.3f}"
    key = {"loadcell gain": "loadcell_gain", "loadcell drift": "loadcell_drift_N_per_min",
           "monitor offset": "monitor_offset_bar",
           "monitor gain": "monitor_gain", "theta0 at box edge": "theta0_deg",
           "gap": "gap_mm"}[d]
    return f"{key} {t[key]:.4g}"


def one(muscle: dict, out: Path, config, params: str | None = None) -> dict:
    runs = [acquire_blind(muscle, eps, out) for eps in FIT_EPS]
    start = time.perf_counter()
    try:
        result = identify(runs, params=params)
    except ValueError as exc:  # refused in one line, as the command would
        return {"departure": muscle["departure"], "seed": muscle["seed"],
                "value": departure_value(muscle), "verdict": "refused", "chi2_per_nu": None,
                "missed": [], "far": [], "misfit_line": None, "instrument_warning": None,
                "zero_line": None,
                "refused": str(exc), "notes": [], "parameters": [], "muscle": muscle,
                "seconds": round(time.perf_counter() - start, 1)}
    seconds = time.perf_counter() - start
    parameters = judge(result, muscle, config)
    missed = [p["parameter"] for p in parameters if not p["covered"]]
    far = [p["parameter"] for p in parameters if p["far"]]
    misfit = result.goodness.line() if result.goodness else None
    zero = result.goodness.zero_line() if result.goodness else None
    instrument = instrument_warning(result)
    verdict = "covered" if not missed else "warned" if misfit or instrument else "SILENT"
    return {"departure": muscle["departure"], "seed": muscle["seed"],
            "value": departure_value(muscle), "verdict": verdict,
            "chi2_per_nu": result.goodness.reduced if result.goodness else None,
            "missed": missed, "far": far, "misfit_line": misfit,
            "instrument_warning": instrument, "zero_line": zero,
            "notes": result.notes,
            "parameters": parameters, "muscle": muscle, "seconds": round(seconds, 1)}


def grid(rows: list[dict], departures) -> list[dict]:
    """Draws x departures: per departure how many draws were covered, missed with a misfit
    line, missed silently, and how many printed a misfit line and the load cell's zero line
    (:meth:`mkm.identify.goodness.Goodness.zero_line`); each cell the verdict (``+m``:
    covered, and a misfit line printed), the departure's value, chi2/nu and what missed."""
    table = []
    for d in departures:
        mine = [r for r in rows if r["departure"] == d]
        cells = {}
        for k, r in enumerate(mine):
            mark = "+m" if r["misfit_line"] and not r["missed"] else ""
            missed = f"; missed {', '.join(r['missed'])}" if r["missed"] else ""
            fit = ("identify refused the runs" if r["verdict"] == "refused"
                   else f"chi2/nu {r['chi2_per_nu']:.3g}")
            cells[f"draw {k}"] = f"{r['verdict']}{mark} ({r['value']}, {fit}{missed})"
        table.append({"departure": d, "covered": sum(r["verdict"] == "covered" for r in mine),
                      "warned": sum(r["verdict"] == "warned" for r in mine),
                      "silent": sum(r["verdict"] == "SILENT" for r in mine),
                      "refused": sum(r["verdict"] == "refused" for r in mine),
                      "misfit_line": sum(r["misfit_line"] is not None for r in mine),
                      "zero_line": sum(r["zero_line"] is not None for r in mine), **cells})
    return table


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--draws", type=int, default=6, help="draws per departure")
    parser.add_argument("--seed", type=int, default=FIRST_SEED,
                        help="the first draw's numpy seed; the k-th draw's is seed + k")
    parser.add_argument("--departures", default=",".join(DEFAULT_DEPARTURES),
                        help="the departures, comma-separated (default all but loadcell drift)")
    parser.add_argument("--params", default=None,
                        help="what identify fits (mkm identify's --params; default its own)")
    parser.add_argument("--out", help="write the table, the draws and provenance as JSON here")
    args = parser.parse_args(argv)
    departures = departures_arg(parser, args.departures, DEPARTURES)
    config = load_config()
    rows = each_draw(args.draws, args.seed, departures,
                     lambda seed, departure, out: one(draw(seed, departure, config), out, config,
                                                      args.params),
                     COLUMNS)
    table = grid(rows, departures)
    print(pd.DataFrame(table)[["departure", "covered", "warned", "silent", "refused",
                               "misfit_line", "zero_line"]].to_string(index=False))
    if args.out:
        write_record(args.out, seed=args.seed, params=args.params, rows=table, draws=rows,
                     target="every draw covered or warned: no SILENT miss")
    return 0


if __name__ == "__main__":
    sys.exit(main())
