"""``mkm acquire --calibration``'s over-force ceiling near the threshold and the braid lock, on
sound muscles drawn from the calibration's own distribution.

Run outside the test suite:

    OPENBLAS_NUM_THREADS=1 .venv/bin/python benchmarks/bench_overforce_band.py \
        [--draws 12] [--seed S] [--out FILE.json]

One muscle unknown to the toolkit (``bench_overforce.draw``: the thick-wall closed form) is
identified blind from the packaged staircase at eps 0 and 0.122, as ``bench_overforce`` does.
Its calibration's band is the muscles it holds possible: ``--draws`` sound muscles are drawn
from the identified parameters' normal distribution (the band's values and covariance), each
with the identified friction and creep, and run on a correct simulated bench, watched by that
calibration's ceiling (:func:`mkm.identify.band.force_ceiling`), at each eps of ``EPS_AT``:
where the identified muscle starts to pull at 0.6, 0.9 and 1.0 times ``max_pressure_bar`` (in
the watched half of the pressures, the top step at the threshold) and at 0.85 of the
identified braid lock's eps, where it pulls nothing up to the top step. A sound muscle must
never be stopped. The same muscles with a pressure monitor reading 0.8 of the pressure
(``[sim.truth] monitor_gain``), at the eps where the identified muscle starts to pull at 0.6
times ``max_pressure_bar``, pull more than the ceiling allows by far (1.25 times the pressure
read) and must all be stopped by the over-force interlock. Prints one JSON document: the
identified muscle, each run's status and reason, and the counts.
"""

from __future__ import annotations

import argparse
import os
import tempfile
from pathlib import Path

import numpy as np
from bench_overforce import QUIET, config, draw, emit, stops

from mkm.bench.run import acquire
from mkm.bench.sim_settings import remove_simulator_settings
from mkm.core.records import provenance
from mkm.fem.calibration import Calibration
from mkm.fem.limits import lock_eps
from mkm.fem.thickwall import effective_eps_of_threshold
from mkm.identify import identify
from mkm.identify.band import force_ceiling

#: where each sound run is held: ("threshold", the identified threshold pressure as a share
#: of max_pressure_bar) or ("lock", a share of the identified braid lock's eps)
EPS_AT = (("threshold", 0.6), ("threshold", 0.9), ("threshold", 1.0), ("lock", 0.85))
#: the faulty runs: a monitor reading this share of the pressure, at EPS_AT[0]
MONITOR_GAIN = 0.8


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--draws", type=int, default=12)
    parser.add_argument("--seed", type=int, default=2026120723)
    parser.add_argument("--out", help="write the JSON document here too")
    args = parser.parse_args(argv)
    rng = np.random.default_rng(args.seed)
    record = provenance()  # the code that ran, before any file of it is written
    truth = draw(rng)
    runs, live = [], []
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp)
        os.environ.setdefault("MKM_STATE_DIR", str(out / "state"))
        for j, eps in enumerate((0.0, 0.122)):
            result = acquire(config(truth, eps, j), out_root=out / "fit", **QUIET)
            remove_simulator_settings(result.path)
            runs.append(result.path)
        files = identify(runs, model="thickwall", search="model").write(out / "identified")
        calibration = Calibration.load(files["calibration"])
        entry = calibration.entries["thickwall"]
        band = entry["identified"]["band"]
        identified = dict(zip(band["parameters"], band["values"], strict=True))
        fitted = {p["parameter"]: p["value"] for p in entry["identified"]["parameters"]
                  if p.get("status") == "fitted"}
        base = config(truth, 0.0, 0)
        theta0 = float(entry["theta0_deg"])
        top = base.regulator.max_pressure_bar
        # where the identified muscle starts to pull at each share of the top pressure
        eps_at = [round(float(effective_eps_of_threshold(
            [share * top], [base.muscle.D0_mm], [base.muscle.t0_mm], [theta0],
            [entry["C10_MPa"]], [entry["C01_MPa"]])[0]), 4)
                  if where == "threshold" else round(share * lock_eps(theta0), 4)
                  for where, share in EPS_AT]
        drawn = rng.multivariate_normal(band["values"], band["covariance"], args.draws)
        for k, values in enumerate(drawn):
            muscle = {**identified, **dict(zip(band["parameters"], values, strict=True)),
                      **{n: fitted[n] for n in ("hysteresis_fraction", "creep_fraction")
                         if n in fitted}}
            muscle.setdefault("theta0_deg", entry["theta0_deg"])
            cases = [(eps, {}) for eps in eps_at] + [(eps_at[0], {"monitor_gain": MONITOR_GAIN})]
            for n, (eps, instruments) in enumerate(cases):
                c = config(muscle, eps, 100 + 10 * k + n, **instruments)
                ceiling = force_ceiling(calibration, c.muscle, top)
                result = acquire(c, out_root=out / "live", ceiling=ceiling, **QUIET)
                live.append({"draw": k, "muscle": {n: round(float(v), 5)
                                                   for n, v in muscle.items()},
                             "eps": eps, "instruments": instruments,
                             "status": str(result.status), "reason": result.reason})
    sound = [r for r in live if not r["instruments"]]
    low = [r for r in live if r["instruments"]]
    emit({"provenance": record, "seed": args.seed, "truth": truth,
          "identified": {"band": band, "theta0_deg": entry["theta0_deg"]},
          "eps_at": [{"where": w, "share": s, "eps": e}
                     for (w, s), e in zip(EPS_AT, eps_at, strict=True)],
          "runs": live, "summary": stops(sound, low, "sound", MONITOR_GAIN)}, args.out)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
