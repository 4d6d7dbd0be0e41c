"""Do `mkm identify`'s 95 % intervals cover the truth, or does it warn, when the bench is wrong the
way real ones are?

Run outside the test suite:

    .venv/bin/python benchmarks/bench_identify_coverage.py [--draws 27] [--seed 32]
        [--departures in-family,...] [--out docs/measured/identify_coverage.json]

Each draw is a muscle unknown to the toolkit (theta0 30-36 deg, rubber x0.7-1.3 on Silastic S,
braid friction 0-6 %, creep 0-3 %) with one departure from what the fit assumes, cycling
through :data:`DEPARTURES`, each at a magnitude drawn uniformly within the tolerance the
configuration declares: the monitor's offset or gain within ``regulator.monitor_accuracy_bar``
(the gain reaching it at ``max_pressure_bar``), the load cell's gain within
``loadcell.sensitivity_tolerance_fraction``, the true wall and diameter within
``[muscle.tolerances]``; a rubber whose C01/C10 ratio is not Silastic S's (C01 = 0, C01 = 2 C10;
the same small-strain stiffness C10 + C01); a sliding braid under a bonded fit; and in-family
draws. Two runs are acquired (eps 0 and 12.2 %), the truth is stripped from them, and
`identify` fits them the fast way the unit tests do: simulated and fitted with the thick-wall
closed form (``search="model"``), or, for the sliding braid, simulated with the FE model's
sliding sleeve and fitted with its bonded braid (coarse mesh).

For every reported parameter: does its interval cover the truth? A draw whose misses all come
with a misfit line or a warning about the instruments (:func:`instrument_warning`) is warned; a
miss without either is silent. Target: no silent miss.

A third run of the same muscle and departure, at eps 6 % or 18 % (:data:`HELDOUT_EPS`, draw by
draw), is predicted with the calibration identify wrote and judged against its band
(:func:`mkm.identify.band.check_heldout`: a step inside when within the band and 1.96 times its
own noise, a run when every settled step is within the band and the run's joint noise factor,
3.00 for 19 steps, :func:`mkm.identify.band.run_noise_z`). Target: held-out runs inside in
>= 90 % of the draws.

With ``--tables ACCURACY`` every run reaches identify as a lab's step table would: its settled
steps' means and directions only, written to a CSV and read by ``mkm import --accuracy
ACCURACY`` (the data sheet's bounds of the configured instrument: ``force=1N+0.1%,
pressure=0.04bar`` for the packaged load cell and regulator), so the fit is weighed and judged
by the declared bounds instead of the holds' noise, and creep is not fitted (no times).

Prints one row per draw and the summary; ``--out`` writes them with the seeds and provenance.
"""

from __future__ import annotations

import argparse
import itertools
import json
import math
import os
import tempfile
import time
from pathlib import Path

import numpy as np

from mkm.bench.config import load_config
from mkm.bench.run import acquire
from mkm.bench.sim_settings import remove_simulator_settings
from mkm.core.records import jsonable, provenance
from mkm.fem.materials import SILASTIC_S
from mkm.identify import identify
from mkm.identify.band import check_heldout

FIT_EPS = (0.0, 0.122)
#: the held-out run's eps, alternating draw by draw: inside the fitted span and beyond it
HELDOUT_EPS = (0.06, 0.18)
DEPARTURES = ("in-family", "monitor offset", "monitor gain", "loadcell gain", "rubber C01=0",
              "rubber C01=2C10", "sliding braid", "true t0", "true D0")
FE = "axisym:mesh=coarse"


def draw(rng: np.random.Generator, departure: str, config) -> dict:
    """A muscle and its one departure (``truth``: the ``[sim.truth]`` table)."""
    scale = float(rng.uniform(0.7, 1.3))
    truth = {"theta0_deg": float(rng.uniform(30.0, 36.0)), "C10_MPa": scale * SILASTIC_S.C10_MPa,
             "C01_MPa": scale * SILASTIC_S.C01_MPa}
    accuracy = config.regulator.monitor_accuracy_bar
    tol = config.muscle.tolerances
    sign = float(rng.choice((-1.0, 1.0)))
    stiffness = scale * (SILASTIC_S.C10_MPa + SILASTIC_S.C01_MPa)
    if departure == "monitor offset":
        truth["monitor_offset_bar"] = sign * float(rng.uniform(0.25, 1.0)) * accuracy
    elif departure == "monitor gain":
        truth["monitor_gain"] = 1.0 + sign * float(rng.uniform(0.25, 1.0)) * accuracy \
            / config.regulator.max_pressure_bar
    elif departure == "loadcell gain":
        truth["loadcell_gain"] = 1.0 + sign * float(rng.uniform(0.25, 1.0)) \
            * config.loadcell.sensitivity_tolerance_fraction
    elif departure == "rubber C01=0":
        truth.update(C10_MPa=stiffness, C01_MPa=0.0)
    elif departure == "rubber C01=2C10":
        truth.update(C10_MPa=stiffness / 3, C01_MPa=2 * stiffness / 3)
    elif departure == "sliding braid":
        truth["braid"] = "sliding"
    elif departure == "true t0":
        truth["t0_mm"] = config.muscle.t0_mm + sign * float(rng.uniform(0.25, 1.0)) * tol.t0_mm
    elif departure == "true D0":
        truth["D0_mm"] = config.muscle.D0_mm + sign * float(rng.uniform(0.25, 1.0)) * tol.D0_mm
    return {"departure": departure, "truth": truth,
            "hysteresis_fraction": float(rng.uniform(0.0, 0.06)),
            "creep_fraction": float(rng.uniform(0.0, 0.03)), "seed": int(rng.integers(2**31))}


def acquire_blind(muscle: dict, eps: float, out: Path) -> Path:
    sliding = muscle["departure"] == "sliding braid"
    config = load_config(eps=eps).replace(sim={
        "model": "axisym" if sliding else "thickwall", "fe_mesh": "coarse",
        "hysteresis_fraction": muscle["hysteresis_fraction"],
        "creep_fraction": muscle["creep_fraction"], "seed": muscle["seed"] + int(1000 * eps),
        "truth": muscle["truth"]})
    result = acquire(config, out_root=out, notify=lambda message: None)
    if result.status != "complete":
        raise RuntimeError(f"simulated run at eps {eps:g} ended {result.status}")
    remove_simulator_settings(result.path)
    return result.path


def equivalent_scale(muscle: dict, config) -> float:
    """The scale on Silastic S (its C01/C10 ratio) whose static force, by the thick-wall
    closed form the rubber draws are fitted with, is closest to the true rubber's over both
    runs' eps and pressures: what a one-scale report at the assumed ratio can at best be."""
    from scipy.optimize import minimize_scalar

    from mkm.registry import parse_spec

    t, m = muscle["truth"], config.muscle
    spec = parse_spec("thickwall").with_params(L0_mm=m.L0_mm, theta0_deg=t["theta0_deg"])
    P = np.linspace(0.0, config.regulator.max_pressure_bar, 61)

    def force(C10, C01):
        model = spec.with_params(C10_MPa=C10, C01_MPa=C01).build()
        return np.concatenate([model.predict(P, m.D0_mm, m.t0_mm, e).force_N for e in FIT_EPS])

    true = force(t["C10_MPa"], t["C01_MPa"])
    best = minimize_scalar(lambda s: float(np.sum((force(s * SILASTIC_S.C10_MPa,
                                                         s * SILASTIC_S.C01_MPa) - true) ** 2)),
                           bounds=(0.2, 3.0), method="bounded", options={"xatol": 1e-6})
    return float(best.x)


def truths(muscle: dict, config) -> dict[str, float]:
    """The true values of what identify may report (the rubber as a scale on Silastic S: the
    true one where the truth has Silastic S's ratio, else :func:`equivalent_scale`; C10 and
    C01 apart; the monitor's offset only where the truth has one: a gain has no single
    offset; the load cell's zero left in the forces, where it does not drift and is one for
    every run)."""
    t = muscle["truth"]
    scale = (t["C10_MPa"] + t["C01_MPa"]) / (SILASTIC_S.C10_MPa + SILASTIC_S.C01_MPa)
    if muscle["departure"].startswith("rubber"):
        scale = equivalent_scale(muscle, config)
    out = {"theta0_deg": t["theta0_deg"], "C10_MPa": t["C10_MPa"], "C01_MPa": t["C01_MPa"],
           "rubber_scale": scale,
           "hysteresis_fraction": muscle["hysteresis_fraction"],
           "creep_fraction": muscle["creep_fraction"],
           "creep_tau_s": muscle.get("creep_tau_s", 30.0)}
    if "monitor_gain" not in t:
        out["pressure_offset_bar"] = t.get("monitor_offset_bar", 0.0)
    # a drift has no single zero, nor have runs tared apart
    if "loadcell_drift_N_per_min" not in t and "eps0_zero_apart_N" not in muscle:
        out["force_zero_N"] = muscle.get("loadcell_offset_N", 0.0)
    return out


def judge(result, muscle: dict, config, truth: dict | None = None) -> list[dict]:
    """Each parameter identify reports with an interval against the truth (``truth``, default
    :func:`truths`), and the rubber's
    ratio against what identify claims of it: measured (C10 and C01 apart, judged above), or
    assumed at Silastic S's with the runs' 95 % interval of C01/C10 beside it (the
    ``C01_over_C10`` row's source), which must then hold the true ratio (a true ratio outside
    it, with the ratio assumed, is a miss: the written C10 and C01 are wrong and nothing says
    so). ``far``: the truth outside by more than the interval's half-width."""
    truth = truths(muscle, config) if truth is None else truth
    rows = []
    for row in result.parameters().to_dict(orient="records"):
        name = row["parameter"]
        if row["status"] != "fitted" or name not in truth:
            continue
        if name == "creep_tau_s" and muscle["creep_fraction"] < 0.005:
            continue  # no creep to time: tau is not a property of this muscle
        value = truth[name]
        low, high = row["ci_low"], row["ci_high"]
        half = (high - low) / 2
        outside = max(low - value, value - high, 0.0)
        rows.append({**row, "truth": value, "covered": bool(outside == 0.0),
                     "far": bool(outside > half)})
    if not result.rubber.get("separated") and "ratio_ci" in result.rubber:
        t = muscle["truth"]
        ratio = t["C01_MPa"] / t["C10_MPa"] if t["C10_MPa"] > 0 else math.inf
        low, high = result.rubber["ratio_ci"]
        assumed = result.rubber.get("assumed_C01_over_C10",
                                    SILASTIC_S.C01_MPa / SILASTIC_S.C10_MPa)
        exact = math.isclose(ratio, assumed, rel_tol=1e-6)
        outside = 0.0 if exact else max(low - ratio, ratio - high, 0.0)
        rows.append({"parameter": "C01_over_C10", "value": assumed, "ci_low": low,
                     "ci_high": high, "status": "assumed", "truth": ratio,
                     "covered": bool(outside == 0.0), "far": bool(outside > (high - low) / 2)})
    return rows


def as_table(run: Path, accuracy: str) -> Path:
    """The run as a lab's step table (the settled steps' means and directions) imported with
    the declared ``accuracy``."""

    from mkm.bench.exchange import import_table, parse_accuracy
    from mkm.bench.storage import load_run

    recorded = load_run(run)
    steps = recorded.steps[recorded.steps["settled"].astype(bool)]
    table = run.parent / f"{run.name}.csv"
    steps.rename(columns={"pressure_bar_mean": "pressure_bar", "force_N_mean": "force_N"})[
        ["pressure_bar", "force_N", "direction"]].to_csv(table, index=False)
    (imported,) = import_table(table, run.parent / "tables", recorded.meta.muscle.record(),
                               tare="none", accuracy=parse_accuracy(accuracy))
    return imported.path


def one(muscle: dict, out: Path, config, heldout_eps: float, tables: str | None = None) -> dict:
    start = time.perf_counter()
    runs = [acquire_blind(muscle, eps, out) for eps in (*FIT_EPS, heldout_eps)]
    if tables:
        runs = [as_table(run, tables) for run in runs]
    sliding = muscle["departure"] == "sliding braid"
    result = identify(runs[:-1], model=FE if sliding else "thickwall", search="model", seed=0)
    predicted = check_heldout(result, runs[-1], out / "identified")
    misfit = result.goodness.line() if result.goodness else None
    instrument = instrument_warning(result)
    parameters = judge(result, muscle, config)
    missed = [p["parameter"] for p in parameters if not p["covered"]]
    far = [p["parameter"] for p in parameters if p["far"]]
    return {"departure": muscle["departure"],
            "departure_values": {k: v for k, v in muscle["truth"].items()
                                 if k not in ("theta0_deg", "C10_MPa", "C01_MPa")
                                 or muscle["departure"].startswith("rubber")},
            "seed": muscle["seed"], "parameters": parameters, "missed": missed, "far": far,
            "rubber_separated": bool(result.rubber.get("separated")),
            "chi2_per_nu": result.goodness.reduced if result.goodness else None,
            "misfit_line": misfit, "instrument_warning": instrument,
            "silent_miss": bool(missed and not (misfit or instrument)),
            "silent_far_miss": bool(far and not (misfit or instrument)),
            "heldout": predicted, "notes": result.notes,
            "seconds": round(time.perf_counter() - start, 1)}


def instrument_warning(result) -> str | None:
    """What identify said the runs cannot tell from an instrument's error (its notes of
    identification.json's ``instrument_warnings``: a creep over before the holds start, which
    is the load cell reading low), or None: a warning the user reads, as a misfit line is."""
    return "; ".join(w["said"] for w in result.instrument_warnings) or None


def warned(row: dict) -> bool:
    """Whether identify warned of the draw: a misfit line or a warning about the instruments."""
    return row["misfit_line"] is not None or row.get("instrument_warning") is not None


def _values(row: dict, sep: str = ";") -> str:
    return sep.join(f"{a}={b:.5g}" if isinstance(b, float) else f"{a}={b}"
                    for a, b in row["departure_values"].items())


def _silent(row: dict) -> str:
    return "SILENT-FAR" if row["silent_far_miss"] else "SILENT" if row["silent_miss"] else "no"


def _heldout(row: dict) -> str:
    h = row["heldout"]
    return f"{h['eps']:g},{h['steps_inside']}/{h['steps']}"


def summarise(rows: list[dict], departures, seed: int) -> dict:
    """Per parameter: coverage, covered or warned, silent and far silent misses; per
    departure: draws, warned, silent misses; and how many draws honest 95 % intervals miss
    by chance (``chance_silent_draws``: the expected number of draws with at least one of
    their judged parameters outside, each at 5 %, the warned draws left out)."""
    names = sorted({p["parameter"] for r in rows for p in r["parameters"]})
    per_parameter = {}
    for name in names:
        judged = [(p["covered"], p["far"], warned(r)) for r in rows
                  for p in r["parameters"] if p["parameter"] == name]
        per_parameter[name] = {
            "draws": len(judged),
            "covered_percent": round(100 * np.mean([c for c, _, _ in judged]), 1),
            "covered_or_warned_percent": round(100 * np.mean([c or w for c, _, w in judged]), 1),
            "silent_misses": sum(not c and not w for c, _, w in judged),
            "silent_far_misses": sum(f and not w for _, f, w in judged)}
    by_departure = {d: {"draws": sum(r["departure"] == d for r in rows),
                        "warned": sum(r["departure"] == d and warned(r) for r in rows),
                        "silent_misses": sum(r["departure"] == d and r["silent_miss"]
                                             for r in rows),
                        "silent_far_misses": sum(r["departure"] == d and r["silent_far_miss"]
                                                 for r in rows)} for d in departures}
    unwarned = [r for r in rows if not warned(r)]
    chance = sum(1 - 0.95 ** sum(p["status"] == "fitted" for p in r["parameters"])
                 for r in unwarned)
    held = [r["heldout"] for r in rows]
    steps = sum(h["steps"] for h in held)
    heldout = {
        "runs": len(held),
        "runs_inside_percent": round(100 * np.mean([h["run_inside"] for h in held]), 1),
        "runs_in_band_alone_percent": round(100 * np.mean([h["run_in_band"] for h in held]), 1),
        "runs_in_band_alone_pulled_steps_percent":
            round(100 * np.mean([h["run_in_band_pulled"] for h in held]), 1),
        "steps": steps,
        "steps_inside_percent": round(100 * sum(h["steps_inside"] for h in held) / steps, 1),
        "steps_in_band_alone_percent": round(100 * sum(h["steps_in_band"] for h in held)
                                             / steps, 1),
        "median_error_over_band": round(float(np.median([h["median_error_over_band"]
                                                         for h in held])), 4),
        "band95_median_percent": round(float(np.median([h["band95_median_percent"]
                                                        for h in held])), 2),
        "runs_inside_percent_by_eps": {
            f"{e:g}": round(100 * np.mean([h["run_inside"] for h in held if h["eps"] == e]), 1)
            for e in sorted({h["eps"] for h in held})}}
    return {"draws": len(rows), "silent_misses": sum(r["silent_miss"] for r in rows),
            "heldout_in_band": heldout,
            "silent_far_misses": sum(r["silent_far_miss"] for r in rows),
            "chance_silent_draws": round(chance, 1),
            "parameter_judgements_unwarned": sum(len(r["parameters"]) for r in unwarned),
            "by_departure": by_departure,
            "draws_with_misfit_line": sum(r["misfit_line"] is not None for r in rows),
            "draws_with_instrument_warning": sum(r.get("instrument_warning") is not None
                                                 for r in rows),
            "per_parameter": per_parameter, "seed": seed}


#: how a draw's line prints a field of its row (any other: as it is)
PRINTED = {"chi2_per_nu": lambda v: "" if v is None else f"{v:.3g}",
           "misfit_line": lambda v: "yes" if v else "no",
           "instrument_warning": lambda v: "yes" if v else "no",
           "missed": lambda v: "|".join(v) or "-",
           "far": lambda v: "|".join(v) or "-", "message": lambda v: v or ""}


def each_draw(draws: int, seed: int, departures, run, columns) -> list[dict]:
    """The rows of ``draws`` rounds over ``departures``, the k-th draw's seed ``seed + k``, in a
    temporary folder: ``run(seed, departure, out)`` identifies one draw into ``out`` and
    returns its row, printed as it comes as a line of its ``columns`` (:data:`PRINTED`)."""
    print(",".join(columns))
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        # the simulated bench's ownership markers stay here (another user's runs block nothing)
        os.environ["MKM_STATE_DIR"] = str(Path(tmp) / "state")
        for k, (_, departure) in enumerate(itertools.product(range(draws), departures)):
            row = run(seed + k, departure, Path(tmp) / f"draw{k}")
            rows.append(row)
            print(",".join(PRINTED.get(c, str)(row[c]) for c in columns), flush=True)
    return rows


def departures_arg(parser, given: str, known) -> list[str]:
    """The comma-separated ``--departures`` ``given``, each one of ``known``; else the parser's
    one-line error naming them."""
    departures = [d.strip() for d in given.split(",") if d.strip()]
    if not departures or any(d not in known for d in departures):
        parser.error(f"--departures {given!r}: expected some of {','.join(known)}")
    return departures


def write_record(path, **fields) -> None:
    """The benchmark's record at ``path``: provenance, then ``fields`` in their order (JSON)."""
    Path(path).write_text(json.dumps({**provenance(), **fields}, indent=1, default=jsonable),
                          encoding="utf-8")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--draws", type=int, default=3 * len(DEPARTURES))
    parser.add_argument("--seed", type=int, default=32)
    parser.add_argument("--departures", default=",".join(DEPARTURES),
                        help="the departures to cycle through (default all)")
    parser.add_argument("--tables", metavar="ACCURACY", help="identify from the runs' step "
                        "tables imported with this --accuracy (see the module docstring)")
    parser.add_argument("--out", help="write the rows and provenance as JSON here")
    args = parser.parse_args(argv)
    departures = departures_arg(parser, args.departures, DEPARTURES)
    rng = np.random.default_rng(args.seed)
    config = load_config()
    rows = []
    print("draw,departure,departure_values,chi2_per_nu,misfit,missed,far,silent_miss,"
          "heldout_eps,heldout_steps_inside,heldout_worst_error_over_reach,seconds")
    with tempfile.TemporaryDirectory() as tmp:
        os.environ["MKM_STATE_DIR"] = str(Path(tmp) / "state")
        for k in range(args.draws):
            muscle = draw(rng, departures[k % len(departures)], config)
            row = one(muscle, Path(tmp) / f"draw{k}", config,
                      HELDOUT_EPS[k % len(HELDOUT_EPS)], args.tables)
            rows.append({"draw": k, **row})
            print(f"{k},{row['departure']},{_values(row)},{row['chi2_per_nu']:.3g},"
                  f"{'yes' if row['misfit_line'] else 'no'},{'|'.join(row['missed']) or '-'},"
                  f"{'|'.join(row['far']) or '-'},{_silent(row)},{_heldout(row)},"
                  f"{row['heldout']['worst_error_over_reach']},{row['seconds']}", flush=True)
    summary = summarise(rows, departures, args.seed)
    print(json.dumps(summary, indent=1))
    if args.out:
        table = [{"draw": r["draw"], "departure": r["departure"],
                  "departure_values": _values(r, ", "),
                  "chi2_per_nu": round(r["chi2_per_nu"], 3),
                  "misfit_line": "yes" if r["misfit_line"] else "no",
                  "rubber": "apart" if r["rubber_separated"] else "one scale",
                  "missed": ", ".join(r["missed"]) or "-",
                  "far": ", ".join(r["far"]) or "-", "silent_miss": _silent(r),
                  "heldout_eps": r["heldout"]["eps"],
                  "heldout_steps_inside": f"{r['heldout']['steps_inside']}/"
                                          f"{r['heldout']['steps']}",
                  "heldout_band95_percent": r["heldout"]["band95_median_percent"],
                  "heldout_error_over_band": r["heldout"]["median_error_over_band"],
                  "seconds": r["seconds"]} for r in rows]
        write_record(
            args.out, tables_accuracy=args.tables, rows=table, summary=summary, draws=rows,
            targets="every parameter's 95 % interval covers the truth in >= 90 % of the "
                    "draws or a misfit line was printed; silent misses: 0 beyond what "
                    "chance explains (chance_silent_draws; none far: truth outside by "
                    "more than the interval's half-width); held-out runs inside their "
                    "printed band in >= 90 % of cases")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
