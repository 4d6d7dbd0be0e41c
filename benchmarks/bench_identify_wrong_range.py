"""What a new user's `mkm identify RUNS` (its defaults) says of fresh muscles across the practical
range on a bench wrong in ways no other benchmark draws: do its 95 % intervals hold the truth,
or does it warn?

Run outside the test suite:

    .venv/bin/python benchmarks/bench_identify_wrong_range.py [--draws 8] [--seed 20261601]
        [--departures gains,...] [--out docs/measured/identify_wrong_range.json]

Each draw is a fresh muscle of ``bench_identify_rubbers.draw`` (inner diameter 8-50 mm, wall
5-15 % of it, length 4-10 diameters, theta0 20-36 deg, C10 0.05-0.5 MPa with C01/C10 0-1.2,
friction 0-4 %, no creep; its runs at 3 or 4 eps up to 70 % of its braid lock on 8 steps up to
8 bar, a load cell sized to its force: ``bench_identify_rubbers.plan``) from its own numpy seed
(``--seed`` plus the draw's index), with one departure (:data:`DEPARTURES`), several of a bench's
errors at once:

- ``gains``: the load cell's gain 1-3 % off (a cell not calibrated on this bench) and the
  pressure monitor's gain 0.5-2 % off its span (twice its declared accuracy and more at the top
  step), each either sign;
- ``rest length``: the rest length the runs declare is 1-3 % shorter than the muscle's (a
  length measured under load, or the first length already shortened): the muscle is
  simulated at its true length and the eps its held length gives, and run.json declares the
  shorter length and the eps the bench computed from it, as a lab records them; with the
  draw's rubber (not Silastic S's ratio);
- ``sliding braid``: a sleeve sliding on the tube (``[sim.truth] braid = "sliding"``) with
  strong braid friction (6-10 %);
- ``frame compliance`` (drawn only when asked for by name: the recorded set's seeds stay
  theirs): the frame, fixtures and load cell yield under the muscle's pull as one spring
  (``[sim.truth] frame_stiffness_N_per_mm``), 0.5-2 mm at the load cell's capacity (a few
  hundred N/mm on the smaller cells, a few thousand on the 1000 kg one): the held length
  shortens by the force over the stiffness;
- ``tubing lag`` and ``tubing lag on ramps`` (drawn only when asked for by name): the muscle
  fills through tubing behind the regulator's outlet, where the monitor reads (``[sim.truth]
  line_tau_s``, a first-order lag of 0.2-2 s); the runs are the staircase of the others, or,
  on ramps, one continuous ramp per eps up to the plan's top pressure and back, reaching it
  in 60-120 s (:func:`mkm.bench.sim.logged_ramp`, as a lab's logger records it), imported
  with the instruments' declared accuracy (the load cell's 0.05 % of its capacity, a 0.25 %
  class transducer's 0.25 % of the monitor's full scale) so that the fit is judged;
- ``first-cycle softening`` and ``first-cycle softening with repeats`` (drawn only when asked
  for by name): the rubber loses 5-20 % of its stiffness once a pressure has been exceeded
  (the Mullins effect, ``[sim.truth] mullins_fraction``; the truth is the preconditioned
  muscle), the runs not preconditioned: the plan's single staircase, or, with repeats, the
  staircase twice (``[sequence] repeats = 2``), whose first rise pulls less than its repeat;
  ``repeats without softening`` (by name), the staircase twice on a rubber that does not
  soften: the control, on which no softening should be named.
- ``no lag on ramps`` (drawn only when asked for by name): no departure, the ramps of ``tubing
  lag on ramps`` on a correct bench, whether identify names a lag that is not there.
- ``stretching fibres`` (drawn only when asked for by name): a braid whose fibres stretch
  0.5-3 % at the plan's top pressure at eps 0 (``[sim.truth] braid_EA_N``, the fibres'
  tension there, the thick-wall force and the pressure's end load on the bore along them,
  over the strain drawn): at a held length the stretched braid is one of a smaller angle and
  a larger diameter, more so the harder it pulls.

The runs are simulated on the FE bench (``sim.model = "axisym"``, the medium mesh), stripped of
the truth and identified by ``identify(runs)``. Every parameter reported with an interval is
judged against the truth as ``bench_identify_rubbers`` judges it (the rubber, where one scale,
against the truth's equivalent scale at Silastic S's ratio over the runs' true lengths and
eps). A draw is ``covered`` when every interval holds the truth, ``warned`` when some miss and
identify printed a misfit line or a warning about the instruments (a creep it cannot tell from
the load cell's gain), ``SILENT`` when some miss without either, ``refused`` or ``crashed`` as
there; ``misfit_line`` and ``instrument_warning`` say whether each was printed at all, and
``frame_check`` the model sweeps the frame check made on a misfit (two per run, the shorter
held length's and the stretched fibres': of the surrogate where the fit searched with it, else
of the FE model), ``fibres`` the stretch of the braid's fibres named, ``braid_refit_sweeps`` and
``braid_refit_seconds`` the sweeps and seconds of the refits without a creep over before the
holds start with each braid (one sweep per run and evaluation, up to 7 evaluations
per braid; 0 where none ran), ``fe_ratio_test`` the FE model's own test of the rubber's ratio
where the surrogate's box cut it (:func:`mkm.identify.procedure.fe_ratio_test`; null where none
ran), whether or not a note gives it.
Prints one row per draw and the counts per departure; ``--out`` writes them (``rows``: one per
draw, with what its verdict names first; ``summary``: per departure), every draw's
parameters, notes and verdict line, the seeds and provenance.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

import numpy as np
from bench_identify_coverage import departures_arg, each_draw, truths, write_record
from bench_identify_rubbers import (
    config_for,
    draw,
    equivalent_scale,
    identified,
    judged,
    plan,
    truth_text,
)

from mkm.bench.exchange import import_table, parse_accuracy
from mkm.bench.run import acquire
from mkm.bench.sim import logged_ramp
from mkm.bench.sim_settings import remove_simulator_settings
from mkm.fem.thickwall import fibre_tension_N

FIRST_SEED = 20261601
DEPARTURES = ("gains", "rest length", "sliding braid", "frame compliance", "tubing lag",
              "tubing lag on ramps", "first-cycle softening",
              "first-cycle softening with repeats", "repeats without softening",
              "no lag on ramps", "stretching fibres")
#: what ``--departures`` draws by default: the recorded results' set
DEFAULT_DEPARTURES = DEPARTURES[:3]
#: the fields of a draw's printed line
COLUMNS = ("seed", "departure", "value", "truth", "verdict", "chi2_per_nu", "misfit_line",
           "instrument_warning", "missed", "far", "seconds", "braid_refit_sweeps",
           "braid_refit_seconds", "message")


def depart(muscle: dict, departure: str) -> dict:
    """``muscle`` with its departure drawn from its own seed (``declared_L0_mm``: the rest
    length the runs declare, where not the true one)."""
    rng = np.random.default_rng([muscle["seed"], DEPARTURES.index(departure)])
    truth = dict(muscle["truth"])
    out = {**muscle, "departure": departure, "truth": truth}
    if departure == "gains":
        truth["loadcell_gain"] = 1.0 + float(rng.choice((-1, 1)) * rng.uniform(0.01, 0.03))
        truth["monitor_gain"] = 1.0 + float(rng.choice((-1, 1)) * rng.uniform(0.005, 0.02))
    elif departure == "rest length":
        out["declared_L0_mm"] = round(muscle["L0_mm"] * (1 - float(rng.uniform(0.01, 0.03))),
                                      2)
    elif departure == "sliding braid":
        truth["braid"] = "sliding"
        out["hysteresis_fraction"] = float(rng.uniform(0.06, 0.10))
    elif departure == "frame compliance":
        out["frame_mm_at_capacity"] = float(rng.uniform(0.5, 2.0))
        truth["frame_stiffness_N_per_mm"] = plan(muscle)["capacity_N"] / out[
            "frame_mm_at_capacity"]
    elif departure.startswith("tubing lag"):
        truth["line_tau_s"] = float(rng.uniform(0.2, 2.0))
    elif departure.startswith("first-cycle softening"):
        truth["mullins_fraction"] = float(rng.uniform(0.05, 0.20))
        out["repeats"] = 2 if departure.endswith("repeats") else 1
    elif departure == "repeats without softening":
        out["repeats"] = 2
    elif departure == "stretching fibres":
        out["fibre_strain_at_top"] = float(rng.uniform(0.005, 0.03))
        truth["braid_EA_N"] = fibre_tension_at_top_N(muscle) / out["fibre_strain_at_top"]
    if departure.endswith("ramps"):
        out["ramp_to_top_s"] = float(rng.uniform(60.0, 120.0))
    return out


def fibre_tension_at_top_N(muscle: dict) -> float:
    """The braid's fibres' total tension [N] at the plan's top pressure at eps 0, were they
    inextensible (:func:`mkm.fem.thickwall.fibre_tension_N` of the thick-wall pull)."""
    runs = plan(muscle)
    return float(fibre_tension_N(runs["eps0_force_N_at_top"], runs["pressures_bar"][-1],
                                 muscle["D0_mm"], muscle["t0_mm"], 0.0,
                                 muscle["truth"]["theta0_deg"]))


def true_eps(muscle: dict, declared_eps: float) -> float:
    """The muscle's eps at the length the bench holds for ``declared_eps`` of the declared rest
    length."""
    declared = muscle.get("declared_L0_mm", muscle["L0_mm"])
    return 1.0 - declared * (1.0 - declared_eps) / muscle["L0_mm"]


def declare(run: Path, L0_mm: float, eps: float) -> None:
    """The rest length and eps run.json declares (the simulated muscle keeps its own)."""
    meta = json.loads((run / "run.json").read_text(encoding="utf-8"))
    meta["muscle"].update(L0_mm=L0_mm, eps=eps)
    (run / "run.json").write_text(json.dumps(meta, indent=2), encoding="utf-8")


def ramp_run(muscle: dict, config, out: Path) -> Path:
    """One continuous ramp of ``config`` to its top pressure and back, as a lab's logger
    records it, imported with the instruments' declared accuracy."""
    top_bar = config.sequence.pressures_bar[-1]
    table = out / f"ramp_{muscle['seed']}_{config.muscle.eps:g}.csv"
    out.mkdir(parents=True, exist_ok=True)
    logged_ramp(config, top_bar, top_bar / muscle["ramp_to_top_s"]).to_csv(table, index=False)
    accuracy = (f"force={0.0005 * config.loadcell.capacity_N:g}N,"
                f"pressure={0.0025 * config.regulator.full_scale_bar:g}bar")
    (imported,) = import_table(table, out, config.muscle.record(),
                               accuracy=parse_accuracy(accuracy))
    return imported.path


def acquire_blind(muscle: dict, declared: dict, out: Path) -> list[Path]:
    """The runs at ``declared``'s eps, each simulated at the muscle's true length and eps and
    declared as ``declared`` says."""
    paths = []
    simulated = {**declared, "eps": [true_eps(muscle, e) for e in declared["eps"]]}
    for k, eps in enumerate(declared["eps"]):
        config = config_for(muscle, simulated, simulated["eps"][k], k)
        if "repeats" in muscle:
            config = config.replace(sequence={"repeats": muscle["repeats"]})
        if "ramp_to_top_s" in muscle:
            paths.append(ramp_run(muscle, config, out))
            continue
        result = acquire(config, out_root=out, notify=lambda message: None)
        if result.status != "complete":
            raise RuntimeError(f"the simulated run at eps {eps:g} ended {result.status}")
        remove_simulator_settings(result.path)
        if "declared_L0_mm" in muscle:
            declare(result.path, muscle["declared_L0_mm"], eps)
        paths.append(result.path)
    return paths


def departure_value(muscle: dict) -> str:
    t = muscle["truth"]
    if muscle["departure"] == "gains":
        return (f"loadcell_gain {t['loadcell_gain']:.4f}, monitor_gain "
                f"{t['monitor_gain']:.4f}")
    if muscle["departure"] == "rest length":
        return (f"declared L0 {muscle['declared_L0_mm']:g} mm "
                f"({100 * (muscle['declared_L0_mm'] / muscle['L0_mm'] - 1):+.2f} %)")
    if muscle["departure"] == "sliding braid":
        return f"sliding, friction {muscle['hysteresis_fraction']:.3f}"
    if "repeats" in muscle:
        return (f"softening {100 * t.get('mullins_fraction', 0.0):.1f} %, "
                f"{muscle['repeats']} staircase{'s' if muscle['repeats'] > 1 else ''} per run")
    ramp = (f", ramps reaching the top in {muscle['ramp_to_top_s']:.0f} s"
            if "ramp_to_top_s" in muscle else "")
    if muscle["departure"] == "no lag on ramps":
        return f"no lag{ramp}"
    if muscle["departure"].startswith("tubing lag"):
        return f"tubing lag {t['line_tau_s']:.2f} s{ramp}"
    if muscle["departure"] == "stretching fibres":
        return (f"fibres of E A {t['braid_EA_N']:.4g} N ({100 * muscle['fibre_strain_at_top']:.2f}"
                " % at the top pressure)")
    return (f"frame {t['frame_stiffness_N_per_mm']:.4g} N/mm ({muscle['frame_mm_at_capacity']:.2f}"
            " mm at the cell's capacity)")


def one(muscle: dict, out: Path) -> dict:
    # the plan a lab makes from what it declares; the truth's lengths and eps follow from it
    declared = plan({**muscle, "L0_mm": muscle.get("declared_L0_mm", muscle["L0_mm"])})
    row = {"seed": muscle["seed"], "departure": muscle["departure"],
           "value": departure_value(muscle), "truth": truth_text(muscle), "muscle": muscle,
           "plan": declared, "verdict": None, "chi2_per_nu": None, "missed": [], "far": [],
           "misfit_line": None, "instrument_warning": None, "message": None, "notes": [],
           "parameters": [], "seconds": None, "braid_refit_sweeps": 0,
           "braid_refit_seconds": 0.0}
    try:
        runs = acquire_blind(muscle, declared, out)
    except Exception as exc:  # the simulator's FE or the bench: no runs, no identification
        row.update(verdict="skipped", message=f"{type(exc).__name__}: {exc}")
        return row
    done = identified(runs, row)
    if done is None:
        return row
    result, seconds, _ = done
    simulated = {**declared, "eps": [true_eps(muscle, e) for e in declared["eps"]]}
    truth = {**truths({**muscle, "departure": muscle["departure"]}, None),
             "rubber_scale": equivalent_scale(muscle, simulated)}
    judged(row, result, muscle, truth, seconds,
           verdict_line=result.summary().splitlines()[-1],
           frame_check=result.goodness.frame_check if result.goodness else None,
           fibres=({k: v for k, v in result.goodness.fibres.items() if k not in ("said", "shift")}
                   if result.goodness and result.goodness.fibres else None),
           softening=next(({k: v for k, v in w.items() if k not in ("said", "verdict")}
                           for w in result.instrument_warnings
                           if w["what"] == "first-cycle softening"), None),
           fe_ratio_test=result.rubber.get("fe_ratio_test"), **braid_refit(result))
    return row


def braid_refit(result) -> dict:
    """What the refits without a creep over before the holds start cost, with each braid: the
    model sweeps (the other braid's FE sweeps, one per run and evaluation, and the search's
    source's where it is the model) and their seconds; 0 where there were none (no such creep,
    or the braid given)."""
    refits = [w["other_braid"] for w in result.instrument_warnings if "other_braid" in w]
    return {"braid_refit_sweeps": sum(r["sweeps"] for r in refits),
            "braid_refit_seconds": round(sum(r["seconds"] for r in refits), 1)}


def summarise(rows: list[dict]) -> list[dict]:
    """Per departure: the draws, and how many were covered, warned, silent, refused, crashed or
    skipped, and printed a misfit line or a warning about the instruments."""
    table = []
    for d in dict.fromkeys(r["departure"] for r in rows):
        mine = [r for r in rows if r["departure"] == d]
        table.append({"departure": d, "draws": len(mine),
                      **{v.lower(): sum(r["verdict"] == v for r in mine)
                         for v in ("covered", "warned", "SILENT", "refused", "crashed",
                                   "skipped")},
                      "misfit_line": sum(r["misfit_line"] is not None for r in mine),
                      "instrument_warning": sum(r["instrument_warning"] is not None
                                                for r in mine),
                      "frame_check_sweeps": sum((r.get("frame_check") or {}).get("sweeps", 0)
                                                for r in mine),
                      "braid_refit_sweeps": sum(r.get("braid_refit_sweeps", 0) for r in mine),
                      "braid_refit_seconds": round(sum(r.get("braid_refit_seconds", 0.0)
                                                       for r in mine), 1),
                      "softening_named": sum(r.get("softening") is not None for r in mine),
                      "fibres_named": sum(r.get("fibres") is not None for r in mine)})
    return table


def table(rows: list[dict]) -> list[dict]:
    """One row per draw: its departure and truth, the verdict, chi2/nu, whether a misfit line
    or a warning about the instruments was printed and what the verdict names first, what
    missed, seconds."""
    return [{"seed": r["seed"], "departure": r["departure"], "value": r["value"],
             "truth": r["truth"], "verdict": r["verdict"],
             "chi2_per_nu": None if r["chi2_per_nu"] is None else float(f"{r['chi2_per_nu']:.3g}"),
             "misfit_line": "yes" if r["misfit_line"] else "no",
             "instrument_warning": "yes" if r["instrument_warning"] else "no",
             "verdict_first": first_said(r.get("verdict_line")),
             "frame_check": frame_check_said(r.get("frame_check")),
             "braid_refit_sweeps": r.get("braid_refit_sweeps", 0),
             "braid_refit_seconds": r.get("braid_refit_seconds", 0.0),
             "softening": softening_said(r.get("softening")),
             "fibres": fibres_said(r.get("fibres")),
             "missed": ", ".join(r["missed"]) or "-", "seconds": r["seconds"]} for r in rows]


def frame_check_said(check: dict | None) -> str:
    """The sweeps the frame check made and of what (the surrogate the fit searched with,
    corrected by the FE model, or the model itself), or '-' where it did not run (no misfit)."""
    if not check:
        return "-"
    model = ("surrogate" if check["model"].endswith("corrected by the FE model")
             else check["model"])
    return f"{check['sweeps']} ({model})"


def softening_said(softening: dict | None) -> str:
    """The first-cycle softening identify named, in % of the rubber's stiffness, and what it
    compared the first rise with (the repeats, or the falling branch), or '-'."""
    if not softening:
        return "-"
    return f"{softening['softened_pct']:g} % (against the {softening['against']})"


def fibres_said(fibres: dict | None) -> str:
    """The stretch of the braid's fibres identify named, in % at the largest tension, and the
    E A it gives, or '-'."""
    if not fibres:
        return "-"
    return f"{100 * fibres['strain_at_largest_tension']:.3g} % (E A {fibres['EA_N']:.3g} N)"


def first_said(verdict: str | None) -> str:
    """What a verdict sends the reader to first (the rest length, the braid, the rubber's
    ratio, the declared tolerances, the surrogate's box; within the noise, the other braid or
    the load cell a creep may be), or '-'."""
    marks = [m for m in ("; first, ", ", but first, ") if m in (verdict or "")]
    if not marks:
        return "-"
    first = verdict.split(marks[0])[1]
    for key, said in (("trails the pressure", "lag"),
                      ("or a yielding frame or stretching fibres", "braid, frame or fibres"),
                      ("a yielding frame or stretching fibres", "frame or fibres"),
                      ("or a braid whose fibres stretch", "braid or fibres"),
                      ("fibres stretch", "fibres"),
                      ("braid (the braid, creep", "braid or frame"),
                      ("frame yielding", "frame"),
                      ("first loading", "softening"),
                      ("braid from a creep", "braid, creep or load cell"),
                      ("load cell", "load cell or creep"),
                      ("rest length", "rest length or gap"), ("braid", "braid"),
                      ("declared tolerances", "declared tolerances"),
                      ("C01/C10 held", "rubber ratio"), ("surrogate's box", "search model")):
        if key in first.split(";")[0]:
            return said
    return first[:40]


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--draws", type=int, default=8, help="draws per departure")
    parser.add_argument("--seed", type=int, default=FIRST_SEED,
                        help="the first draw's numpy seed; the k-th draw's is seed + k")
    parser.add_argument("--departures", default=",".join(DEFAULT_DEPARTURES),
                        help="the departures, comma-separated (default: "
                             f"{', '.join(DEFAULT_DEPARTURES)})")
    parser.add_argument("--out", help="write the table, the draws and provenance as JSON here")
    args = parser.parse_args(argv)
    departures = departures_arg(parser, args.departures, DEPARTURES)
    if args.draws < 1:
        parser.error(f"--draws {args.draws}: expected at least 1")
    rows = each_draw(args.draws, args.seed, departures,
                     lambda seed, departure, out: one(depart(draw(seed), departure), out),
                     COLUMNS)
    summary = summarise(rows)
    print(json.dumps(summary, indent=1))
    if args.out:
        write_record(args.out, seed=args.seed, summary=summary, rows=table(rows), draws=rows,
                     target="every draw covered or warned: no SILENT miss, no crash")
    return 0


if __name__ == "__main__":
    sys.exit(main())
