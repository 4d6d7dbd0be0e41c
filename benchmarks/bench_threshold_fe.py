"""The threshold study's gap model with the FE's tube-braid contact instead of the closed form.

The model-selection study (``bench_threshold_models.py``) fits the thick-wall closed form, a
mid-section model: with a gap its clamped ends are left out, while the FE model (``axisym``)
holds the tube's ends at their rest radius, so next to each cap the tube never reaches the
braid. Does that change the picture on the Martens and Boblan maps? Here the baseline and the
gap model (gap inside the nominal braid) are fitted with the FE model (coarse mesh: with a gap
its forces are the fine mesh's to 2e-5, ``tests/fem/fe/test_contact.py``) on each muscle's
default pair of held lengths, started from the closed form's fit, and scored as the study
scores them (largest error as % of the muscle's largest force on the rest-length curve and on
the other held lengths, the threshold at the table's longest length against the measured one),
each map read with the table's longest length and, where it differs, Festo's nominal length as
the rest length (as the study reads them).

    .venv/bin/python benchmarks/bench_threshold_fe.py [--out FILE.json] [--muscles DMSP-10-250]

writes FILE.json (rows: one per muscle, reading and model, closed form and FE side by side;
provenance; the seconds each FE fit took).
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

import numpy as np
import pandas as pd
from bench_threshold_models import (
    CANDIDATES,
    EXTRAS,
    Physics,
    fit_candidate,
    read_maps,
    score,
)

from mkm.core.records import provenance, write_json_atomic
from mkm.fem.fe.model import isometric_sweep
from mkm.fem.materials import SILASTIC_S, MooneyRivlin

ROOT = Path(__file__).resolve().parents[1]
DEFAULT_OUT = ROOT / "docs" / "measured" / "threshold_fe.json"
MESH = "coarse"
MODELS = ("thick-wall (baseline)", "gap, braid nominal")


def fe_physics(L0_mm: float) -> Physics:
    """The FE model of a muscle of rest length ``L0_mm`` as the study's :class:`Physics`."""

    def sweep(P, eps, D0_mm, t0_mm, theta0_deg, rubber_scale, gap_inside_mm=0.0):
        material = MooneyRivlin(rubber_scale * SILASTIC_S.C10_MPa,
                                rubber_scale * SILASTIC_S.C01_MPa)
        return isometric_sweep(P, D0_mm - 2.0 * gap_inside_mm, t0_mm, eps, theta0_deg,
                               L0_mm=L0_mm, mesh=MESH, material=material,
                               gap_mm=gap_inside_mm)

    def force(P, eps, D0_mm, t0_mm, **params):
        P, eps = np.broadcast_arrays(np.asarray(P, dtype=float), np.asarray(eps, dtype=float))
        out = np.full(P.shape, np.nan)
        for level in np.unique(eps):
            here = eps == level
            result = sweep(P[here], float(level), D0_mm, t0_mm, **params)
            out[here] = np.where(result["converged"], result["force_N"], np.nan)
        return out

    def threshold(D0_mm, t0_mm, params, eps=0.0):
        result = sweep([0.0], float(eps), D0_mm, t0_mm, **params)
        return float(result["threshold_pressure_bar"][0])

    return Physics(force, threshold)


def study(muscles) -> list[dict]:
    rows = []
    maps = [m for m in read_maps() if any(name in m.muscle for name in muscles)]
    readings = [r for m in maps for r in (m, m.at_nominal_length())
                if r is m or r.rest_length_mm != m.table_L0_mm]  # the nominal one if another
    for force_map in readings:
        pair = force_map.held[:2]
        train = force_map.rows[np.isin(force_map.rows["eps"], pair)]
        measured = force_map.measured_threshold_bar()
        physics = fe_physics(force_map.rest_length_mm)
        for candidate in (c for c in CANDIDATES if c.name in MODELS):
            closed = fit_candidate(candidate, force_map, train)
            names = ["theta0_deg", "rubber_scale", *candidate.extras]
            # from the closed form's fit, and from the extras' own start (a gap the ends
            # might want larger)
            starts = [[closed.params[n] for n in names]]
            if candidate.extras:
                starts.append([closed.params[n] for n in names[:2]]
                              + [EXTRAS[e][0] for e in candidate.extras])
            start = time.perf_counter()
            fe = fit_candidate(candidate, force_map, train, physics, starts)
            seconds = time.perf_counter() - start
            for label, fit, how in (("closed form", closed, None), (f"FE ({MESH})", fe, physics)):
                scores = score(fit, force_map, pair, how) if how else score(fit, force_map, pair)
                rows.append({
                    "muscle": force_map.muscle, "rest length": force_map.reading,
                    "model": candidate.name, "physics": label,
                    "trained on eps": ", ".join(f"{e:g}" for e in pair),
                    "theta0 deg": fit.params.get("theta0_deg"),
                    "rubber x Silastic S": fit.params.get("rubber_scale"),
                    "gap mm": fit.params.get("gap_inside_mm", 0.0),
                    "rest curve max err %": scores.get("rest_max_err_pct"),
                    "other lengths max err %": scores.get("other_max_err_pct"),
                    "P* at the longest length bar": scores.get("threshold_eps0_bar"),
                    "measured P* bar": measured["estimate_bar"],
                    "measured bracket bar": f"{measured['low_bar']:g}-{measured['high_bar']:g}",
                    "converged": fit.converged,
                    "fit seconds": seconds if how else None})
    return rows


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=DEFAULT_OUT)
    parser.add_argument("--muscles", default="DMSP-10-250,DMSP-20-300",
                        help="comma list of muscles (a part of their name)")
    args = parser.parse_args()
    rows = study(args.muscles.split(","))
    print(pd.DataFrame(rows).to_string(index=False))
    try:
        shown = args.out.resolve().relative_to(ROOT).as_posix()
    except ValueError:
        shown = str(args.out)
    write_json_atomic(args.out, {**provenance(), "command": (
        f"benchmarks/bench_threshold_fe.py --out {shown} --muscles {args.muscles}"),
        "mesh": MESH, "rows": rows})


if __name__ == "__main__":
    main()
