"""What a new user's `mkm identify RUNS` (its defaults) says of muscles across the practical range,
rubbers nobody published among them: do its 95 % intervals hold the truth, or does it warn?

Run outside the test suite:

    .venv/bin/python benchmarks/bench_identify_rubbers.py [--draws 12] [--seed 20261206]
        [--out docs/measured/identify_rubbers.json] [--declare-rubber FACTOR]

``--declare-rubber 0.8``: each muscle's configuration declares its rubber as a lab that knows
its ratio does, at 0.8 times the true constants (a data sheet's), so that identify assumes the
true ratio and fits the scale; the rubber is then judged against the scale at that ratio.

Each draw is a fresh muscle from its own numpy seed (``--seed`` plus the draw's index, recorded
per draw), across the practical range (``mkm models``): inner diameter 8-50 mm, wall 0.05-0.15
of it (at least 0.5 mm), length 4-10 diameters (at least 50 mm), braid angle 20-36 deg, C10
0.05-0.5 MPa with C01/C10 0-1.2 (natural rubber, chloroprene, stiff silicones as well as
Silastic-like ones), braid friction 0-4 %, no creep. Its runs are at 3 or 4 shortenings from 0
to 70 % of its braid lock. The pressures (:func:`plan`) are 8 steps up to the top one, set by
the thick-wall closed form at the truth: twice the pressure at which the shortest run starts to
pull (at least 1 bar, at most 8 bar, and at most what makes 70 % of a 1000 kg load cell's
capacity at eps 0); where the shortest run would not pull within it, its eps is lowered to the
largest that pulls at half of it. The load cell is the smallest of a catalogue's
(:data:`CELLS_N`) whose capacity holds the eps 0 force at the top step with a margin; the
regulator's full scale is 4 bar up to 4 bar, else 9 bar (a 0.9 MPa ITV), its monitor accurate
to 1 % of it (the vent check at 2 %). The runs are simulated on the FE bench
(``sim.model = "axisym"``, the medium mesh: identify's own, so that no mesh error reads as a
misfit, and a draw takes seconds either way; the simulator's noise), stripped of the truth
and identified by ``identify(runs)``: the default parameters, the surrogate search, the FE
confirmation. A run the simulator cannot make (its FE
fails, the bench refuses the plan) skips the draw, with why.

Every parameter reported with an interval is judged against the truth as
``bench_identify_coverage.judge`` does (the rubber, where one scale, against the truth's
equivalent scale at Silastic S's ratio over these runs, :func:`equivalent_scale`, and the true
C01/C10 against the ratio interval the note prints). A draw is ``covered`` when every interval
holds the truth, ``warned`` when some miss and identify printed a misfit line or a warning
about the instruments (``bench_identify_coverage.instrument_warning``), ``SILENT`` when some
miss without either, ``refused`` when identify raised ``ValueError`` (its message recorded),
``crashed`` on any other exception (a defect). Prints one row per draw; ``--out`` writes the
summary, one row per draw (truth, verdict, chi2/nu, seconds), every draw's parameters, notes
and plan, and provenance.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import sys
import tempfile
import time
import traceback
import warnings
from pathlib import Path

import numpy as np
from bench_identify_coverage import instrument_warning, judge, truths, write_record

from mkm.bench.config import load_config
from mkm.bench.run import acquire
from mkm.bench.sim_settings import remove_simulator_settings
from mkm.fem.limits import lock_eps
from mkm.fem.materials import SILASTIC_S
from mkm.identify import identify
from mkm.registry import parse_spec

FIRST_SEED = 20261206
#: load cells a lab buys (10 kg to 1000 kg), amplified to +-10 V [N]
CELLS_N = (98.0665, 196.133, 490.3325, 980.665, 1961.33, 4903.325, 9806.65)
#: the share of the cell's capacity the eps 0 force may reach at the top step (the interlock
#: trips at 90 %, and the truth's force is not the closed form's)
CELL_MARGIN = 0.7
STEPS = 8
#: the simulated bench's FE mesh (``--mesh``)
FE_MESH = "medium"
#: the runs' eps as fractions of the braid lock (3 or 4 runs)
EPS_PER_LOCK = {3: (0.0, 0.35, 0.7), 4: (0.0, 0.23, 0.47, 0.7)}


def draw(seed: int) -> dict:
    """A muscle of the practical range: geometry, the truth (``[sim.truth]``), friction."""
    rng = np.random.default_rng(seed)
    D0 = float(rng.uniform(8.0, 50.0))
    t0 = max(0.5, float(rng.uniform(0.05, 0.15)) * D0)
    L0 = max(50.0, float(rng.uniform(4.0, 10.0)) * D0)
    C10 = float(rng.uniform(0.05, 0.5))
    ratio = float(rng.uniform(0.0, 1.2))
    truth = {"theta0_deg": float(rng.uniform(20.0, 36.0)), "C10_MPa": C10,
             "C01_MPa": ratio * C10}
    return {"seed": seed, "D0_mm": round(D0, 2), "t0_mm": round(t0, 2), "L0_mm": round(L0, 1),
            "truth": truth, "hysteresis_fraction": float(rng.uniform(0.0, 0.04)),
            "creep_fraction": 0.0, "runs": int(rng.choice((3, 4)))}


def _force(muscle: dict, pressure_bar, eps: float):
    t = muscle["truth"]
    model = parse_spec("thickwall").with_params(
        L0_mm=muscle["L0_mm"], theta0_deg=t["theta0_deg"], C10_MPa=t["C10_MPa"],
        C01_MPa=t["C01_MPa"]).build()
    prediction = model.predict(np.asarray(pressure_bar, float), muscle["D0_mm"],
                               muscle["t0_mm"], eps)
    return np.where(prediction.valid, prediction.force_N, np.nan)


def _threshold(muscle: dict, eps: float, grid) -> float:
    """The lowest pressure of ``grid`` at which the muscle at ``eps`` pulls (inf: none)."""
    force = _force(muscle, grid, eps)
    pulling = np.flatnonzero(np.nan_to_num(force) > 0.0)
    return float(grid[pulling[0]]) if pulling.size else math.inf


def plan(muscle: dict) -> dict:
    """The runs' eps, the pressures and the instruments (see the module docstring)."""
    lock = float(lock_eps(muscle["truth"]["theta0_deg"]))
    eps = [round(f * lock, 4) for f in EPS_PER_LOCK[muscle["runs"]]]
    grid = np.linspace(0.01, 8.0, 800)
    at_zero = np.nan_to_num(_force(muscle, grid, 0.0))
    within_cell = grid[at_zero <= CELL_MARGIN * CELLS_N[-1]]
    top_bar = float(within_cell[-1]) if within_cell.size else float(grid[0])
    notes = []
    threshold = _threshold(muscle, eps[-1], grid)
    p_max = min(top_bar, max(1.0, 2.0 * threshold))
    if threshold > p_max / 2:  # the shortest run would pull on fewer than half the steps
        pulls = [e for e in np.linspace(eps[-1], 0.0, 60)
                 if _threshold(muscle, e, grid) <= p_max / 2]
        low = round(float(pulls[0]), 4)
        notes.append(f"eps {eps[-1]:g} would pull only from {threshold:.3g} bar; lowered to "
                     f"{low:g} ({low / lock:.2f} of the lock)")
        fractions = np.asarray(EPS_PER_LOCK[muscle["runs"]]) / EPS_PER_LOCK[muscle["runs"]][-1]
        eps = [round(float(f * low), 4) for f in fractions]
    p_max = math.floor(p_max * 20) / 20  # to 0.05 bar
    pressures = [round(p_max * (k + 1) / STEPS, 3) for k in range(STEPS)]
    force_N = float(np.nan_to_num(_force(muscle, p_max, 0.0)))
    cell = next((c for c in CELLS_N if force_N <= CELL_MARGIN * c), CELLS_N[-1])
    full_scale = 4.0 if p_max <= 4.0 else 9.0
    return {"eps": eps, "pressures_bar": pressures, "lock_eps": round(lock, 4),
            "eps0_force_N_at_top": round(force_N, 1), "capacity_N": cell,
            "full_scale_bar": full_scale, "notes": notes}


def equivalent_scale(muscle: dict, runs_plan: dict) -> float:
    """The scale on Silastic S's C10 + C01, at the assumed ratio (the rubber the muscle declares,
    else Silastic S's), whose force, by the thick-wall closed form, is closest to the true
    rubber's over the runs' eps and pressures: what a one-scale report at the assumed ratio
    can at best be."""
    from scipy.optimize import minimize_scalar

    pressures = np.asarray(runs_plan["pressures_bar"])

    def force(C10, C01):
        other = {**muscle, "truth": {**muscle["truth"], "C10_MPa": C10, "C01_MPa": C01}}
        return np.concatenate([np.nan_to_num(_force(other, pressures, e))
                               for e in runs_plan["eps"]])

    t, declared = muscle["truth"], muscle.get("declared", {})
    true = force(t["C10_MPa"], t["C01_MPa"])
    total = SILASTIC_S.C10_MPa + SILASTIC_S.C01_MPa
    share = (declared["C01_MPa"] / (declared["C10_MPa"] + declared["C01_MPa"]) if declared
             else SILASTIC_S.C01_MPa / total)
    def misfit(s):
        return float(np.sum((force(s * total * (1 - share), s * total * share) - true) ** 2))

    # a grid first: a scale whose muscle pulls nothing at any step is a plateau a bracketing
    # search can wander along to its bound
    grid = np.geomspace(0.05, 10.0, 61)
    k = int(np.argmin([misfit(s) for s in grid]))
    best = minimize_scalar(misfit, bounds=(grid[max(k - 1, 0)], grid[min(k + 1, grid.size - 1)]),
                           method="bounded", options={"xatol": 1e-6})
    return float(best.x)


def config_for(muscle: dict, runs_plan: dict, eps: float, k: int):
    cell, fs = runs_plan["capacity_N"], runs_plan["full_scale_bar"]
    return load_config(eps=eps).replace(
        muscle={"id": f"rubber-{muscle['seed']}", "D0_mm": muscle["D0_mm"],
                "t0_mm": muscle["t0_mm"], "L0_mm": muscle["L0_mm"],
                **muscle.get("declared", {})},
        loadcell={"capacity_N": cell, "sensitivity_N_per_V": cell / 10.0},
        regulator={"max_pressure_bar": runs_plan["pressures_bar"][-1], "full_scale_bar": fs,
                   "monitor_accuracy_bar": 0.01 * fs},
        # the packaged limits are a 200 kg cell's: a tenth and a hundredth of the capacity
        # the vent check above the monitor's declared zero error (1 % of its full scale)
        safety={"tare_max_shift_N": min(100.0, 0.1 * cell),
                "tare_max_std_N": min(5.0, 0.01 * cell), "vent_below_bar": 0.02 * fs},
        sequence={"pressures_bar": tuple(runs_plan["pressures_bar"]),
                  "preconditioning_cycles": 0},
        sim={"model": "axisym", "fe_mesh": FE_MESH, "seed": muscle["seed"] + 1000 * k,
             "hysteresis_fraction": muscle["hysteresis_fraction"],
             "creep_fraction": muscle["creep_fraction"], "truth": muscle["truth"]})


def acquire_blind(muscle: dict, runs_plan: dict, out: Path) -> list[Path]:
    paths = []
    for k, eps in enumerate(runs_plan["eps"]):
        result = acquire(config_for(muscle, runs_plan, eps, k), out_root=out,
                         notify=lambda message: None)
        if result.status != "complete":
            raise RuntimeError(f"the simulated run at eps {eps:g} ended {result.status}")
        remove_simulator_settings(result.path)
        paths.append(result.path)
    return paths


def truth_text(muscle: dict) -> str:
    t = muscle["truth"]
    return (f"D0 {muscle['D0_mm']:g}, t0 {muscle['t0_mm']:g}, L0 {muscle['L0_mm']:g} mm, "
            f"theta0 {t['theta0_deg']:.1f}, C10 {t['C10_MPa']:.3f}, "
            f"C01/C10 {t['C01_MPa'] / t['C10_MPa']:.2f}, friction "
            f"{muscle['hysteresis_fraction']:.3f}")


def one(muscle: dict, out: Path) -> dict:
    runs_plan = plan(muscle)
    row = {"seed": muscle["seed"], "truth": truth_text(muscle), "muscle": muscle,
           "plan": runs_plan, "verdict": None, "chi2_per_nu": None, "missed": [], "far": [],
           "misfit_line": None, "instrument_warning": None, "message": None, "notes": [],
           "parameters": [], "rubber_separated": None, "seconds": None}
    start = time.perf_counter()
    try:
        runs = acquire_blind(muscle, runs_plan, out)
    except Exception as exc:  # the simulator's FE or the bench: no runs, no identification
        row.update(verdict="skipped", message=f"{type(exc).__name__}: {exc}")
        return row
    row["acquire_seconds"] = round(time.perf_counter() - start, 1)
    done = identified(runs, row)
    if done is None:
        return row
    result, seconds, caught = done
    truth = {**truths({**muscle, "departure": "practical range"}, None),
             "rubber_scale": equivalent_scale(muscle, runs_plan)}
    return judged(row, result, muscle, truth, seconds,
                  rubber_separated=bool(result.rubber.get("separated")),
                  warnings=sorted({str(w.message) for w in caught}))


def identified(runs, row: dict):
    """identify with its defaults on ``runs``: its result, seconds and the warnings it gave;
    None where it refused (in one line, as the command would) or failed (a defect), ``row``
    saying so."""
    start = time.perf_counter()
    try:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            result = identify(runs)
    except ValueError as exc:  # refused in one line, as the command would
        row.update(verdict="refused", message=str(exc),
                   seconds=round(time.perf_counter() - start, 1))
        return None
    except Exception as exc:  # a defect
        row.update(verdict="crashed", message=f"{type(exc).__name__}: {exc}",
                   traceback=traceback.format_exc(),
                   seconds=round(time.perf_counter() - start, 1))
        return None
    return result, time.perf_counter() - start, caught


def judged(row: dict, result, muscle: dict, truth: dict, seconds: float, **extra) -> dict:
    """``row`` with the identification ``result`` judged against ``truth``: covered (every
    interval holds it), warned (one misses, the misfit line or a warning about the instruments
    said) or SILENT; and ``extra``."""
    parameters = judge(result, muscle, None, truth)
    missed = [p["parameter"] for p in parameters if not p["covered"]]
    misfit = result.goodness.line() if result.goodness else None
    instrument = instrument_warning(result)
    row.update(verdict="covered" if not missed else "warned" if misfit or instrument
               else "SILENT",
               chi2_per_nu=result.goodness.reduced if result.goodness else None,
               missed=missed, far=[p["parameter"] for p in parameters if p["far"]],
               misfit_line=misfit, instrument_warning=instrument, notes=result.notes,
               parameters=parameters,
               seconds=round(seconds, 1), **extra)
    return row


def summarise(rows: list[dict]) -> dict:
    """The verdicts' counts, and the misses' extremes: the lowest and highest braid angle and
    C01/C10 among the draws that missed (warned or silent)."""
    verdicts = ("covered", "warned", "SILENT", "refused", "crashed", "skipped")
    missed = [r for r in rows if r["verdict"] in ("warned", "SILENT")]
    out = {v.lower(): sum(r["verdict"] == v for r in rows) for v in verdicts}
    out["draws"] = len(rows)
    # a misfit line printed on a covered draw: intervals widened, and a user told to check the
    # instruments of a bench that has nothing wrong
    out["covered_with_misfit_line"] = sum(r["verdict"] == "covered" and r["misfit_line"]
                                          is not None for r in rows)
    out["instrument_warning"] = sum(r.get("instrument_warning") is not None for r in rows)
    if missed:
        theta = [r["muscle"]["truth"]["theta0_deg"] for r in missed]
        ratio = [r["muscle"]["truth"]["C01_MPa"] / r["muscle"]["truth"]["C10_MPa"]
                 for r in missed]
        out["missed_theta0_deg"] = [round(min(theta), 2), round(max(theta), 2)]
        out["missed_C01_per_C10"] = [round(min(ratio), 3), round(max(ratio), 3)]
    return out


def table(rows: list[dict]) -> list[dict]:
    return [{"seed": r["seed"], "truth": r["truth"],
             "eps": ", ".join(f"{e:g}" for e in r["plan"]["eps"]),
             "top_bar": r["plan"]["pressures_bar"][-1], "verdict": r["verdict"],
             "chi2_per_nu": None if r["chi2_per_nu"] is None else round(r["chi2_per_nu"], 3),
             "misfit_line": "yes" if r["misfit_line"] else "no",
             "instrument_warning": "yes" if r.get("instrument_warning") else "no",
             "missed": ", ".join(r["missed"]) or "-", "seconds": r["seconds"]} for r in rows]


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--draws", type=int, default=12)
    parser.add_argument("--seed", type=int, default=FIRST_SEED,
                        help="the first draw's numpy seed; the k-th draw's is seed + k")
    parser.add_argument("--out", help="write the summary, the draws and provenance as JSON here")
    parser.add_argument("--declare-rubber", type=float, default=None, metavar="FACTOR",
                        help="each muscle's [muscle] declares the true rubber times FACTOR (its "
                             "ratio the truth's, its stiffness a data sheet's: 0.8 is 20 %% "
                             "soft), the ratio identify assumes")
    args = parser.parse_args(argv)
    if args.draws < 1:
        parser.error(f"--draws {args.draws}: expected at least 1")
    rows = []
    print("seed,truth,eps,top_bar,verdict,chi2_per_nu,missed,far,seconds,message")
    with tempfile.TemporaryDirectory() as tmp:
        # the simulated bench's ownership markers stay here (another user's runs block nothing)
        os.environ["MKM_STATE_DIR"] = str(Path(tmp) / "state")
        for k in range(args.draws):
            muscle = draw(args.seed + k)
            if args.declare_rubber is not None:
                muscle["declared"] = {n: args.declare_rubber * muscle["truth"][n]
                                      for n in ("C10_MPa", "C01_MPa")}
            row = one(muscle, Path(tmp) / f"draw{k}")
            rows.append(row)
            chi2 = row["chi2_per_nu"]
            print(f"{row['seed']},{row['truth']},{'|'.join(f'{e:g}' for e in row['plan']['eps'])},"
                  f"{row['plan']['pressures_bar'][-1]:g},{row['verdict']},"
                  f"{'' if chi2 is None else f'{chi2:.3g}'},{'|'.join(row['missed']) or '-'},"
                  f"{'|'.join(row['far']) or '-'},{row['seconds']},{row['message'] or ''}",
                  flush=True)
    summary = summarise(rows)
    print(json.dumps(summary, indent=1))
    if args.out:
        write_record(args.out, seed=args.seed, summary=summary, rows=table(rows),
                     declare_rubber=args.declare_rubber, draws=rows,
                     target="every draw covered or warned: no SILENT miss, no crash")
    return 0


if __name__ == "__main__":
    sys.exit(main())
