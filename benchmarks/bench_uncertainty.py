"""Coverage of the step budget on simulated runs, and the speed of prediction bands.

Run outside the test suite:

    .venv/bin/python benchmarks/bench_uncertainty.py [--runs 100] [--eps 0 0.122]
        [--out docs/measured/budget_coverage.json]

1. Coverage (mkm.bench.coverage): ``--runs`` simulated runs of the paper's prototype per eps (19
   settled steps each; the simulator's noise, 14-bit quantisation, braid friction and creep on;
   seeds 0..runs-1, or from ``--first-seed``), each with its instruments drawn within the data
   sheet the config declares (:func:`mkm.bench.coverage.instrument_draw`), every step's 95.45 %
   interval (k per quantity) against the mean true force and pressure over its hold. Twice
   (``--monitor``): with the packaged config, whose ``[regulator]`` declares only
   ``monitor_accuracy_bar`` (the monitor a linear sensor meeting it over the range), and with the
   monitor's error declared as components (:data:`COMPONENTS`, drawn each within its bound: offset,
   gain, a bow, a hysteresis). Target: 95 +- 3 % pooled, force and pressure, and per set pressure
   (over-covered at 0.25-0.5 bar with the components, 98-99 %: docs/guide/uncertainty.md says why).
   Printed: coverage of force and pressure, the pooled steps, the spread of the normalised error
   (F_meas - F_true) / u (1 if u is the error's standard deviation), the force's k range, and the
   pressure's coverage per set pressure. The runs of one seed share their instruments' errors, so
   the coverage's spread is that of ``--runs`` draws, not of the steps.
2. Bands (mkm.uncertainty): the default surrogate's Monte Carlo band at 20 pressures x 1000
   draws (inside its box: D0 40 mm, t0 3 mm, eps 0.1), best of 5 calls; target <= 0.5 s.

3. Robust design (``--design``, mkm.design with ``--tolerance``): the best design for
   580 N at 2 bar, eps 0.10 built to D0 +-0.3 mm, t0 +-0.1 mm, theta0 +-1 deg, rubber +-10 %
   at 95 %; its stated probability (Monte Carlo over the surrogate) against the fraction of
   ``--fe-draws`` muscles drawn from the same tolerances that the FE model (axisym, medium
   mesh) finds meeting the requirement. Target: within +-5 points, >= 50 draws.

Prints one CSV block per part and the provenance (versions, command, date) as JSON.
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

import numpy as np
import pandas as pd

from mkm.bench.config import load_config
from mkm.bench.coverage import simulated_coverage
from mkm.core.records import jsonable, provenance

#: The monitor's error declared as components: the packaged 0.04 bar itemised, an illustration
#: and not a data sheet: the worst case of their sum at the top of the range, 0.016 + 0.004 x
#: 2.5 + 0.008 + 0.012 / 2 = 0.04 bar, is the single bound (0.4 % of the 4 bar scale for the
#: zero, 0.4 % of the reading for the span, 0.2 % and 0.3 % of full scale for the non-linearity
#: and the hysteresis), so the two declarations compare.
COMPONENTS = {"monitor_zero_bar": 0.016, "monitor_span_fraction": 0.004,
              "monitor_nonlinearity_bar": 0.008, "monitor_hysteresis_bar": 0.012}
#: --monitor: what [regulator] declares of the monitor's error
MONITOR_FORMS = {"accuracy": {}, "components": COMPONENTS}


def coverage(runs: int, eps_values, forms, out: str | None = None,
             first_seed: int = 0) -> None:
    print("monitor,eps,runs,steps,force_covered_percent,pressure_covered_percent,z_std,z_mean,"
          "k_force_min,k_force_max,k_pressure,seconds")
    rows, summaries, by_set = [], {}, {}
    for form in forms:
        pooled = []
        for eps in eps_values:
            config = load_config(eps=eps)
            if MONITOR_FORMS[form]:
                config = config.replace(regulator=MONITOR_FORMS[form])
            start = time.perf_counter()
            steps = simulated_coverage(config, range(first_seed, first_seed + runs))
            seconds = time.perf_counter() - start
            z = (steps["force_N_mean"] - steps["force_true_N"]) / steps["force_u_N"]
            k_force = steps["force_U_N"] / steps["force_u_N"]
            k_pressure = steps["pressure_U_bar"] / steps["pressure_u_bar"]
            pooled.append(steps)
            row = {"monitor": form, "eps": eps, "runs": runs, "steps": len(steps),
                   "force_covered_percent": round(100 * steps["covered"].mean(), 2),
                   "pressure_covered_percent": round(100 * steps["pressure_covered"].mean(), 2),
                   "z_std": round(float(z.std()), 3), "z_mean": round(float(z.mean()), 3),
                   "k_force_min": round(float(k_force.min()), 3),
                   "k_force_max": round(float(k_force.max()), 3),
                   "k_pressure": round(float(k_pressure.median()), 3),
                   "seconds": round(seconds, 1)}
            rows.append(row)
            print(",".join(str(v) for v in row.values()))
        steps = pd.concat(pooled, ignore_index=True)
        by_pressure = steps.groupby(steps["set_pressure_bar"].round(3))["pressure_covered"]
        by_set[form] = {f"{p:g}": round(100 * v, 1) for p, v in by_pressure.mean().items()}
        summaries[form] = {
            "declared": {**({"monitor_accuracy_bar": config.regulator.monitor_accuracy_bar}
                            if not MONITOR_FORMS[form] else {}), **MONITOR_FORMS[form]},
            "runs": runs * len(pooled), "steps": len(steps),
            "force_covered_percent": round(100 * steps["covered"].mean(), 2),
            "pressure_covered_percent": round(100 * steps["pressure_covered"].mean(), 2),
            "pressure_covered_percent_by_set_pressure_bar": by_set[form],
            "seeds": f"{first_seed}..{first_seed + runs - 1} per eps"}
        print(f"all, {form}: {json.dumps(summaries[form])}")
    table = [{"set_pressure_bar": float(p), **{f"pressure_covered_percent_{form}": by_set[form][p]
                                               for form in forms}}
             for p in by_set[forms[0]]]
    if out:
        Path(out).write_text(json.dumps({
            **provenance(), "rows": rows, "all": summaries, "by_set_pressure": table,
            "target": "force and pressure coverage 95 +- 3 %, pooled and per set pressure"},
            indent=1, default=jsonable), encoding="utf-8")


def band_speed() -> None:
    from mkm.fem.tolerances import Tolerances
    from mkm.registry import build_spec
    from mkm.uncertainty import force_band

    model = build_spec("surrogate")
    pressure = np.linspace(0.125, 2.5, 20)
    tolerances = Tolerances()
    times = []
    for _ in range(5):
        start = time.perf_counter()
        band = force_band(model, pressure, 40.0, 3.0, 0.1, tolerances, n_draws=1000)
        times.append(time.perf_counter() - start)
    print("model,method,pressures,draws,best_s,median_s,u_at_2.5bar_N,force_at_2.5bar_N")
    print(f"{model.name},{band.method},{pressure.size},1000,{min(times):.4f},"
          f"{float(np.median(times)):.4f},{band.force_u_N[-1]:.2f},{band.force_N[-1]:.1f}")


def design_check(fe_draws: int, seed: int = 7) -> None:
    from mkm.design import run_design
    from mkm.fem.tolerances import Tolerances, draws
    from mkm.registry import parse_spec
    from mkm.uncertainty import nominal_parameters

    tolerances = Tolerances.parse("D0=0.3,t0=0.1,theta0=1,rubber=10%")
    requirement = "580N@2bar,eps=0.10"
    start = time.perf_counter()
    result = run_design([requirement], top=3, tolerances=tolerances, probability=0.95)
    seconds = time.perf_counter() - start
    req = result.search.requirements[0]
    print("rank,D0_mm,t0_mm,stated_probability,fe_draws,fe_fraction_met,binomial_sd,"
          "difference_points,design_s,fe_check_s")
    for _, d in result.designs.iterrows():
        model = result.search.models[(float(d["L0_mm"]), float(d["theta0_deg"]), d["rubber"])]
        nominal = {k: float(v) for k, v in nominal_parameters(
            model, d["D0_mm"], d["t0_mm"], req.eps).items()}
        sample = draws(nominal, tolerances, fe_draws, np.random.default_rng(seed))
        start_fe = time.perf_counter()
        met = []
        for i in range(fe_draws):
            fe = parse_spec("axisym:mesh=medium").build(
                L0_mm=sample["L0_mm"][i], theta0_deg=sample["theta0_deg"][i],
                C10_MPa=sample["C10_MPa"][i], C01_MPa=sample["C01_MPa"][i])
            pred = fe.predict(req.pressure_bar, sample["D0_mm"][i], sample["t0_mm"][i],
                              sample["eps"][i])
            met.append(bool(pred.valid.ravel()[0]) and float(pred.force_N.ravel()[0])
                       >= req.force_N)
        fraction = float(np.mean(met))
        stated = float(d["probability_all"])
        sd = np.sqrt(stated * (1 - stated) / fe_draws)
        print(f"{int(d['rank'])},{d['D0_mm']:.2f},{d['t0_mm']:.2f},{100 * stated:.1f},"
              f"{fe_draws},{100 * fraction:.1f},{100 * sd:.1f},"
              f"{100 * (fraction - stated):+.1f},{seconds:.1f},"
              f"{time.perf_counter() - start_fe:.1f}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=100, help="simulated runs per eps")
    parser.add_argument("--first-seed", type=int, default=0,
                        help="the coverage runs' seeds: FIRST_SEED .. FIRST_SEED + runs - 1")
    parser.add_argument("--out", help="write the coverage table and provenance as JSON here")
    parser.add_argument("--eps", type=float, nargs="+", default=[0.0])
    parser.add_argument("--monitor", nargs="+", choices=list(MONITOR_FORMS),
                        default=list(MONITOR_FORMS), help="what [regulator] declares of the "
                        "pressure monitor's error: its accuracy alone (the packaged config) "
                        "and/or components (COMPONENTS); default both")
    parser.add_argument("--no-bands", action="store_true", help="skip the band timing")
    parser.add_argument("--design", action="store_true", help="check a robust design's "
                        "stated probability with the FE model")
    parser.add_argument("--fe-draws", type=int, default=100)
    parser.add_argument("--no-coverage", action="store_true", help="skip the coverage runs")
    args = parser.parse_args()
    if not args.no_coverage:
        coverage(args.runs, args.eps, args.monitor, args.out, args.first_seed)
    if not args.no_bands:
        band_speed()
    if args.design:
        design_check(args.fe_draws)
    print(json.dumps(provenance(), indent=1, default=str))


if __name__ == "__main__":
    main()
