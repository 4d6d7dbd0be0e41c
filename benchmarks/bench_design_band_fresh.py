"""The band ``mkm design`` states on a chosen design's force, both ends, against the true
muscle's force on fresh random points.

    OPENBLAS_NUM_THREADS=1 .venv/bin/python benchmarks/bench_design_band_fresh.py \
        [--points 400] [--seed S] [--out FILE.json]

Per point, a true muscle is drawn (theta0 20-35 deg, its rubber 1-5 x Silastic S, L0 150-300
mm), how well an identification knows it (one standard deviation of 0.2-2 deg and 3-20 % of
the rubber, log-uniform, correlated by -0.8 to 0.8) and the identified muscle, drawn from the
truth by that covariance as an identification's estimate lies from the truth it was measured
on; then a design's tube (D0 10-40 mm, t0 0.5 mm to 0.15 D0, at most 3 mm) and a requirement
(eps up to 0.85 of the identified braid's lock, the pressure from 0.5 bar below the identified
muscle's threshold to 8 bar). The band design states about the identified muscle's FE force
(:func:`mkm.design.fe_verification.identified_ends_N`: ``band95_N`` below it, the
linearisation; ``band95_above_N`` above it, :func:`mkm.identify.band.prediction_ends`) is held
against the true muscle's FE force (the same medium mesh; 0 N where it is slack or its braid
locks): inside, below or above it. For a force linear in the parameters 95 % of the points
lie inside, 2.5 % on either side; ``linear`` counts the same against the linearised band
alone (``band95_N`` on both sides). A point the identified muscle's FE gives no force at
(its braid locked) is no design's and is skipped, counted. Each point's generator is seeded
by ``(seed, point)``: a point is the same in any run of the same seed.
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path
from tempfile import TemporaryDirectory

import numpy as np
from bench_design_band import MESH, calibration_of, force_N, sampling_error

from mkm.core.records import jsonable, provenance
from mkm.design.fe_verification import fe_model, identified_ends_N
from mkm.design.spec import Requirement
from mkm.fem.limits import lock_eps

#: the two-sided band's nominal share inside
NOMINAL = 0.95


def draw_point(seed: int, point: int) -> dict:
    """The true and the identified muscle (as :data:`bench_design_band.MUSCLES`' entries), the
    tube and the requirement's eps share of the lock and pressure draw of point ``point``."""
    rng = np.random.default_rng([seed, point])
    theta0, scale = rng.uniform(20.0, 35.0), float(np.exp(rng.uniform(0.0, np.log(5.0))))
    sd_theta0 = float(np.exp(rng.uniform(np.log(0.2), np.log(2.0))))
    sd_rubber = scale * float(np.exp(rng.uniform(np.log(0.03), np.log(0.2))))
    rho = rng.uniform(-0.8, 0.8)
    covariance = np.array([[sd_theta0**2, rho * sd_theta0 * sd_rubber],
                           [rho * sd_theta0 * sd_rubber, sd_rubber**2]])
    # a rubber estimated below zero (beyond 5 sd) is no rubber
    found = rng.multivariate_normal([theta0, scale], covariance)
    L0 = rng.uniform(150.0, 300.0)
    D0 = rng.uniform(10.0, 40.0)
    t0 = rng.uniform(0.5, min(3.0, 0.15 * D0))
    identified = {"theta0_deg": float(found[0]), "rubber_scale": max(float(found[1]), 1e-3),
                  "sd_theta0": sd_theta0, "sd_rubber": sd_rubber, "rho": float(rho),
                  "L0_mm": float(L0)}
    truth = {"theta0_deg": float(theta0), "rubber_scale": scale, "L0_mm": float(L0)}
    return {"truth": truth, "identified": identified, "D0_mm": float(D0), "t0_mm": float(t0),
            "eps_share": float(rng.uniform(0.0, 0.85)), "pressure_share": float(rng.uniform())}


def judged(seed: int, point: int, folder: Path) -> dict:
    """Point ``point``: its draw, the band stated at it and where the true force lies."""
    drawn = draw_point(seed, point)
    identified, truth = drawn["identified"], drawn["truth"]
    D0, t0 = drawn["D0_mm"], drawn["t0_mm"]
    calibration = calibration_of(identified, folder)
    nominal = fe_model(MESH, identified["L0_mm"], identified["theta0_deg"], "calibrated",
                       calibration)
    eps = float(round(drawn["eps_share"] * lock_eps(identified["theta0_deg"]), 4))
    at_one = nominal.predict(np.array([1.0]), D0, t0, eps)
    out = {"point": point, "D0_mm": round(D0, 3), "t0_mm": round(t0, 3),
           "L0_mm": round(identified["L0_mm"], 2), "eps": eps,
           "identified": {k: round(v, 4) for k, v in identified.items() if k != "L0_mm"},
           "truth": {k: round(v, 4) for k, v in truth.items() if k != "L0_mm"}}
    threshold = float(at_one.extras["threshold_pressure_bar"][0])
    if not bool(np.ravel(at_one.valid)[0]) or not np.isfinite(threshold):
        return {**out, "skipped": "the identified muscle's FE gives no force"}
    low = max(0.05, threshold - 0.5)
    P = float(round(low + drawn["pressure_share"] * (8.0 - low), 3))
    prediction = nominal.predict(np.array([P]), D0, t0, eps)
    F = float(np.ravel(prediction.force_N)[0])
    if not bool(np.ravel(prediction.valid)[0]) or not np.isfinite(F):
        return {**out, "pressure_bar": P, "skipped": "the identified muscle's FE gives no force"}
    row = {"D0_mm": D0, "t0_mm": t0, "L0_mm": identified["L0_mm"],
           "theta0_deg": identified["theta0_deg"], "rubber": "calibrated", "fe_mesh": MESH,
           "r1_fe_N": F}
    # the band is of the row's force; a requirement asks more than nothing
    ((below, above),) = identified_ends_N(row, [Requirement(max(F, 1e-6), P, eps)],
                                          calibration)
    true = force_N(truth, truth["theta0_deg"], truth["rubber_scale"], P, D0, t0, eps)
    side = "below" if true < F - below else "above" if true > F + above else "inside"
    linear = "below" if true < F - below else "above" if true > F + below else "inside"
    return {**out, "pressure_bar": P, "threshold_bar": round(threshold, 3),
            "force_N": round(F, 3), "band95_N": round(below, 3),
            "band95_above_N": round(above, 3), "true_force_N": round(true, 3),
            "side": side, "linear": linear}


def summary(rows: list[dict]) -> dict:
    """The shares inside and on either side of the band, and of the linearised band, with
    the sampling error of a share of :data:`NOMINAL` over the points judged."""
    done = [r for r in rows if "side" in r]
    n = len(done)

    def shares(key):
        return {side: sum(r[key] == side for r in done) for side in ("inside", "below", "above")}

    return {"points": len(rows), "judged": n, "skipped": len(rows) - n,
            "slack": sum(r["force_N"] == 0 for r in done),
            "band": shares("side"), "linear": shares("linear"),
            "inside_pct": round(100 * shares("side")["inside"] / n, 1) if n else None,
            "linear_inside_pct": round(100 * shares("linear")["inside"] / n, 1) if n else None,
            # twice the standard error of a 95 % share over n points
            "sampling_error_pct": round(100 * sampling_error(NOMINAL, n), 1) if n else None}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=400)
    parser.add_argument("--seed", type=int, default=2026120741)
    parser.add_argument("--out")
    args = parser.parse_args()
    rows, record = [], provenance()
    start = time.process_time()
    with TemporaryDirectory() as tmp:
        for point in range(args.points):
            folder = Path(tmp) / str(point)
            folder.mkdir()
            rows.append(judged(args.seed, point, folder))
            print(json.dumps(rows[-1]), flush=True)
            if args.out and (point % 20 == 19 or point == args.points - 1):
                # a run stopped keeps the points it finished
                with open(args.out, "w", encoding="utf-8") as f:
                    json.dump({"points": args.points, "seed": args.seed, "mesh": MESH,
                               "nominal_inside": NOMINAL, "summary": summary(rows),
                               "cpu_s": round(time.process_time() - start, 1),
                               "rows": rows, "provenance": record},
                              f, indent=2, default=jsonable)
    print(json.dumps(summary(rows)))


if __name__ == "__main__":
    main()
