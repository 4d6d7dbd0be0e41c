"""The FE design the default surrogate learns from: muscles spread over the whole box.

A grid spends the FE budget on corners and planes (27 muscles of the paper's 3 x 3 x 3 grid hold
only three values of each input); a space-filling design gives every muscle new values of every
input. :func:`space_filling` places ``n`` muscles in the box :data:`BOX` of the seven muscle
parameters (geometry, length, braid angle, rubber): 16 corners of a 2^(7-3) fractional factorial
[1]_ (every pair of factors balanced, each corner of the box's main effects seen), then a Latin
hypercube [2]_ (``scipy.stats.qmc``, centred-discrepancy optimised) for the rest. Each muscle is one
FE sweep (:data:`DESIGN_PRESSURES`), computed with the dataset builder's cache and workers
(:func:`mkm.fem.batch.run_jobs`). :func:`random_muscles` draws fresh muscles for the
off-grid evaluation the same way. A sub-box where the surrogate needs more muscles than the
box's share (a corner where the end effects change fastest) gets its own space-filling design
(:func:`refinement_muscles`, ``--refine`` and ``--refine-box``), recorded in the sidecar.

References
----------
.. [1] G. E. P. Box, J. S. Hunter, W. G. Hunter, "Statistics for Experimenters", 2nd ed., Wiley,
   2005, ch. 6 (fractional factorials; generators E = ABC, F = BCD, G = ACD).
.. [2] M. D. McKay, R. J. Beckman, W. J. Conover, "A comparison of three methods for selecting
   values of input variables in the analysis of output from a computer code", Technometrics
   21(2), 239-245, 1979, doi:10.2307/1268522.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pandas as pd
from scipy.stats import qmc

from mkm.core.records import package_file, provenance, write_csv_with_sidecar
from mkm.fem.batch import Job, Runner, run_jobs
from mkm.fem.materials import SILASTIC_S
from mkm.surrogate.coverage import rescale_factor
from mkm.surrogate.muscle_predictor import effective_shortening, process_inputs

#: The shipped design dataset (``mkm surrogate design --muscles 96 --out`` this file).
DESIGN_DATASET = package_file("mkm.surrogate", "data", "mkm_design.csv")


#: Parameters of a muscle, in the order of the design's columns.
MUSCLE_PARAMETERS = ("D0_mm", "t0_mm", "eps", "L0_mm", "theta0_deg", "C10_MPa", "C01_MPa")

#: The box the default surrogate covers (issue 13): pressure and the seven muscle parameters;
#: the rubber within +-50 % of Silastic S (the paper's Equation 3).
BOX: dict[str, tuple[float, float]] = {
    "pressure_bar": (0.0, 2.5),
    "D0_mm": (30.0, 50.0),
    "t0_mm": (2.0, 4.0),
    "eps": (0.0, 0.2),
    "L0_mm": (150.0, 400.0),
    "theta0_deg": (28.0, 38.0),
    # rounded as the design's values are, so that its corners lie on the box
    "C10_MPa": (round(0.5 * SILASTIC_S.C10_MPa, 6), round(1.5 * SILASTIC_S.C10_MPa, 6)),
    "C01_MPa": (round(0.5 * SILASTIC_S.C01_MPa, 6), round(1.5 * SILASTIC_S.C01_MPa, 6)),
}

#: Pressures of each FE sweep [bar]: the box's 0-2.5 bar every 0.25 bar (the test pressures),
#: plus 2.75 and 3 bar so that the slope of a muscle with a high threshold is still measured.
DESIGN_PRESSURES = tuple(float(p) for p in np.round(np.arange(0.0, 3.001, 0.25), 2))

#: Pressures of evaluation sweeps [bar]: the paper's test pressures, inside the box.
EVAL_PRESSURES = tuple(float(p) for p in np.round(np.arange(0.0, 2.501, 0.25), 2))

#: Pressures of a sweep over the practical range [bar]: 0-8 bar every 0.5 bar.
PRACTICAL_PRESSURES = tuple(float(p) for p in np.round(np.arange(0.0, 8.001, 0.5), 2))

N_CORNERS = 16  # the 2^(7-3) fractional factorial
MIN_MUSCLES_WITH_CORNERS = 2 * N_CORNERS  # below: corners would be most of the budget


def corners() -> np.ndarray:
    """The 16 corners of the 2^(7-3) resolution IV fractional factorial, in the unit cube.

    Base factors A-D (the geometry) in full factorial, generators E = ABC, F = BCD, G = ACD.
    """
    base = np.array([[(i >> k) & 1 for k in range(4)] for i in range(16)]) * 2 - 1
    a, b, c, d = base.T
    signs = np.column_stack([a, b, c, d, a * b * c, b * c * d, a * c * d])
    return (signs + 1) / 2.0


def _to_box(unit: np.ndarray, box=BOX) -> pd.DataFrame:
    lo = np.array([box[p][0] for p in MUSCLE_PARAMETERS])
    hi = np.array([box[p][1] for p in MUSCLE_PARAMETERS])
    values = np.round(lo + unit * (hi - lo), 6)  # round: the CSV holds them exactly
    return pd.DataFrame(values, columns=list(MUSCLE_PARAMETERS))


def space_filling(n_muscles: int, seed: int = 0, box=BOX) -> pd.DataFrame:
    """``n_muscles`` muscles over ``box``: corners (when ``n >= 32``) then a Latin hypercube.

    Returns one row per muscle with :data:`MUSCLE_PARAMETERS` and ``origin`` (corner or lhs).
    """
    if int(n_muscles) != n_muscles or n_muscles < 1:
        raise ValueError(f"--muscles {n_muscles!r} is invalid: expected an FE budget of at "
                         "least 1 muscle")
    n_muscles = int(n_muscles)
    parts, origin = [], []
    if n_muscles >= MIN_MUSCLES_WITH_CORNERS:
        parts.append(corners())
        origin += ["corner"] * N_CORNERS
    n_lhs = n_muscles - sum(len(p) for p in parts)
    if n_lhs:
        sampler = qmc.LatinHypercube(d=len(MUSCLE_PARAMETERS), optimization="random-cd",
                                     rng=np.random.default_rng(seed))
        parts.append(sampler.random(n_lhs))
        origin += ["lhs"] * n_lhs
    muscles = _to_box(np.vstack(parts), box)
    muscles["origin"] = origin
    return muscles


def parse_sub_box(text: str) -> dict[str, tuple[float, float]]:
    """``"D0_mm=40:50,L0_mm=150:225"``: ranges of some :data:`MUSCLE_PARAMETERS`, each inside
    :data:`BOX` with ``lo < hi``; ``ValueError`` (one line, naming the bad part) otherwise."""
    sub_box = {}
    for part in str(text).split(","):
        name, _, span = part.strip().partition("=")
        bounds = span.split(":")
        if name not in MUSCLE_PARAMETERS or len(bounds) != 2:
            raise ValueError(f"--refine-box part {part.strip()!r} is invalid: expected NAME=LO:HI "
                             f"with NAME one of {', '.join(MUSCLE_PARAMETERS)}")
        try:
            lo, hi = (float(b) for b in bounds)
        except ValueError:
            raise ValueError(f"--refine-box part {part.strip()!r} is invalid: LO and HI must be "
                             "numbers") from None
        box_lo, box_hi = BOX[name]
        if not box_lo <= lo < hi <= box_hi:
            raise ValueError(f"--refine-box {name}={lo:g}:{hi:g} is invalid: expected "
                             f"{box_lo:g} <= LO < HI <= {box_hi:g} (the box)")
        sub_box[name] = (lo, hi)
    return sub_box


def refinement_muscles(n_muscles: int, sub_box: dict, seed: int = 0) -> pd.DataFrame:
    """``n_muscles`` space-filling muscles (:func:`space_filling`) in :data:`BOX` narrowed to
    ``sub_box`` (:func:`parse_sub_box`), origin ``refine``."""
    muscles = space_filling(n_muscles, seed, {**BOX, **sub_box})
    muscles["origin"] = "refine"
    return muscles


def random_muscles(n_muscles: int, seed: int, box=BOX) -> pd.DataFrame:
    """``n_muscles`` muscles drawn uniformly in ``box`` (off-grid evaluation; record ``seed``)."""
    unit = np.random.default_rng(seed).random((int(n_muscles), len(MUSCLE_PARAMETERS)))
    return _to_box(unit, box).assign(origin=f"random seed {seed}")


def fe_jobs(muscles: pd.DataFrame, mesh: str = "fine",
            pressures=DESIGN_PRESSURES) -> list[Job]:
    """One axisym FE job per muscle (the pressure sweep ``pressures``)."""
    return [Job(model="axisym", mesh=mesh, D0_mm=float(m.D0_mm), t0_mm=float(m.t0_mm),
                eps=float(m.eps), L0_mm=float(m.L0_mm), theta0_deg=float(m.theta0_deg),
                pressure_bar=tuple(float(p) for p in pressures), C10_MPa=float(m.C10_MPa),
                C01_MPa=float(m.C01_MPa))
            for m in muscles.itertuples()]


def fe_sweeps(muscles: pd.DataFrame, mesh: str = "fine", pressures=DESIGN_PRESSURES,
              workers: int | None = None, cache_dir=None, progress: bool = True,
              desc: str = "FE sweeps", scheduler: str | None = None,
              runner: Runner | None = None) -> tuple[pd.DataFrame, dict]:
    """The FE rows of every muscle (``muscle`` = its row number in ``muscles``) and the run, on
    ``workers`` local processes, the Dask cluster at ``scheduler`` or an open ``runner``.

    ``progress``: a bar on stderr, when stderr is a terminal (logs and pipes stay clean).
    """
    show = progress and hasattr(sys.stderr, "isatty") and sys.stderr.isatty()
    frame, done = run_jobs(fe_jobs(muscles, mesh, pressures), workers=workers,
                           scheduler=scheduler, runner=runner, cache_dir=cache_dir,
                           progress=show, desc=desc)
    frame.insert(0, "muscle", np.repeat(np.arange(len(muscles)), len(pressures)))
    return frame, done


def adaptive_muscles(estimator, n_muscles: int, seed: int = 0, candidates: int = 2000,
                     pool: pd.DataFrame | None = None, pressure_top_bar: float | None = None,
                     reach_min_bar: float = 1e-3) -> pd.DataFrame:
    """``n_muscles`` muscles where a fitted :class:`~mkm.surrogate.muscle_gp.MuscleThresholdGP` is
    least sure of the force at the top pressure ``pressure_top_bar`` (default: the box's),
    relative to that force, chosen greedily among ``pool`` (default: ``candidates`` random
    muscles of the box): each pick conditions both processes on it (their posterior
    covariance, rank-one update with the fitted noise), so picks spread out instead of piling
    up in one corner. The processes' variance is weighted by the square of the estimator's
    calibrated std factor (``c (log k_A / m_ref)^beta`` times the rescale ``k (k_A eps /
    0.1)^power (theta0 / 30 deg)^angle_power``, 1 for an estimator just fitted): its errors
    grow with the end-effect correction, largest for short muscles at a low braid angle, and so
    do the picks there. The
    threshold's share is taken over at least ``reach_min_bar`` above it (over the practical
    range, one pressure step: a muscle whose threshold nears the top pressure has a force too
    small to say much). Picks from ``pool`` keep its origin, prefixed ``adaptive``."""
    pool = random_muscles(candidates, seed) if pool is None else pool.reset_index(drop=True)
    P_top = BOX["pressure_bar"][1] if pressure_top_bar is None else float(pressure_top_bar)
    values = {"pressure_bar": np.full(len(pool), P_top), **{p: pool[p].to_numpy()
                                                           for p in MUSCLE_PARAMETERS}}
    X = np.column_stack([values[name] for name in estimator.inputs])
    v, z = estimator._muscle(X)
    zs = process_inputs((z - estimator.z_mean_) / estimator.z_scale_, estimator.inputs)
    _, m_A, _, _, _ = estimator._log_k(X)
    calibrated = (estimator._calibrated(m_A) * rescale_factor(
        effective_shortening(v, m_A), v["theta0_deg"], estimator.std_rescale_,
        estimator.std_rescale_power_, estimator.std_rescale_angle_power_)) ** 2
    zero, one = np.zeros(len(pool)), np.ones(len(pool))
    A, gain_A, Pstar, gain_P = estimator._from_logk(v, zero, one, zero, one)
    # the force's relative sensitivity to each process's log k at the top pressure
    reach = np.maximum(P_top - Pstar, reach_min_bar)
    weights = [np.where(A > 0, gain_A / np.maximum(A, 1e-9), 0.0), gain_P / reach]
    covariances, noises = [], []
    for gp, post, z_process in ((estimator.slope_gp_, estimator.slope_posterior_, zs[0]),
                                (estimator.threshold_gp_, estimator.threshold_posterior_,
                                 zs[1])):
        kernel = gp.kernel_.k1  # without the white noise: covariance between muscles
        K_star = kernel(z_process, gp.X_train_)
        V = np.linalg.solve(gp.L_, K_star.T)
        covariances.append((kernel(z_process) - V.T @ V) * post["y_std"] ** 2)
        noises.append(gp.kernel_.k2.noise_level * post["y_std"] ** 2)
    chosen = []
    for _ in range(int(n_muscles)):
        score = calibrated * sum(w**2 * np.diag(C)
                                 for w, C in zip(weights, covariances, strict=True))
        score[chosen] = -np.inf
        pick = int(np.argmax(score))
        chosen.append(pick)
        for C, noise in zip(covariances, noises, strict=True):
            column = C[:, pick].copy()
            C -= np.outer(column, column) / (column[pick] + noise)
    picked = pool.iloc[chosen].reset_index(drop=True)
    picked["origin"] = (f"adaptive seed {seed}" if "origin" not in pool
                        else "adaptive " + picked["origin"])
    return picked


def build_design(n_muscles: int, out, seed: int = 0, mesh: str = "fine",
                 workers: int | None = None, cache_dir=None,
                 progress: bool = True, adaptive: int = 0,
                 scheduler: str | None = None, refine: int = 0,
                 refine_box: dict | None = None) -> tuple[pd.DataFrame, dict]:
    """Compute the design of ``n_muscles`` FE sweeps and write ``out`` (CSV) and ``out.json``;
    with ``refine``, that many more space-filling muscles in the sub-box ``refine_box``
    (:func:`refinement_muscles`); with ``adaptive``, that many more muscles where the default
    surrogate trained on the ones before is least sure (:func:`adaptive_muscles`).

    The sidecar records the box, the seed, the budget, the refinement's sub-box, the muscles
    whose sweep failed (kept in the CSV with ``converged=False``; the loader leaves them out)
    and the FE provenance.
    """
    for flag, count in (("--refine", refine), ("--adaptive", adaptive)):
        if int(count) != count or count < 0:
            raise ValueError(f"{flag} {count!r} is invalid: expected a number of muscles >= 0")
    if refine and not refine_box:
        raise ValueError(f"--refine {refine} needs --refine-box: expected the sub-box of the "
                         "refinement muscles (NAME=LO:HI,...)")
    muscles = space_filling(n_muscles, seed)
    if refine:
        muscles = pd.concat([muscles, refinement_muscles(refine, refine_box, seed)],
                            ignore_index=True)
    with Runner(workers, scheduler) as runner:  # the design and its adaptive muscles: one cluster
        return _build_design(muscles, n_muscles, out, seed, mesh, runner, cache_dir, progress,
                             adaptive, refine_box if refine else None)


def _build_design(muscles, n_muscles, out, seed, mesh, runner, cache_dir, progress, adaptive,
                  refine_box):
    """:func:`build_design` on an open :class:`~mkm.fem.batch.Runner`."""
    frame, done = fe_sweeps(muscles, mesh, runner=runner, cache_dir=cache_dir,
                            progress=progress, desc=f"FE design ({mesh} mesh)")
    if adaptive:
        from mkm.surrogate.kinds import make_estimator
        from mkm.surrogate.quiet import quiet_fits
        from mkm.surrogate.training_data import ALL_INPUTS

        used = frame[frame["converged"]]
        with quiet_fits():
            estimator = make_estimator("muscle-gp", ALL_INPUTS).fit(
                used[list(ALL_INPUTS)].to_numpy(), used["force_N"].to_numpy(),
                threshold_pressure_bar=used["threshold_pressure_bar"].to_numpy())
        muscles = pd.concat([muscles, adaptive_muscles(estimator, adaptive, seed)],
                            ignore_index=True)
        frame, done = fe_sweeps(muscles, mesh, runner=runner, cache_dir=cache_dir,
                                progress=progress, desc=f"FE design + adaptive ({mesh} mesh)")
    frame["origin"] = muscles["origin"].to_numpy()[frame["muscle"].to_numpy()]
    failed = sorted(set(frame.loc[~frame["converged"], "muscle"].tolist()))
    info = {**provenance(),
            "what": "space-filling FE design of the default surrogate (surrogate.design)",
            "design": {"muscles": int(n_muscles), "seed": int(seed), "adaptive": int(adaptive),
                       "refine": int((muscles["origin"] == "refine").sum()),
                       "refine_box": ({k: list(v) for k, v in refine_box.items()}
                                      if refine_box else None),
                       "corners": int((muscles["origin"] == "corner").sum()),
                       "method": "2^(7-3) fractional factorial corners + scipy.stats.qmc "
                                 "LatinHypercube(optimization='random-cd'); refinement: the "
                                 "same in the box narrowed to refine_box, same seed; adaptive: "
                                 "greedy picks of largest calibrated predictive variance"},
            "box": {k: list(v) for k, v in BOX.items()},
            "pressure_bar": list(DESIGN_PRESSURES),
            "model": "axisym", "mesh": mesh, "model_version": done["model_version"],
            "fe_budget_muscles": int(len(muscles)), "jobs_computed": done["computed"],
            "jobs_from_cache": done["cached"], "workers": done["workers"],
            "muscles_with_failed_points": [int(m) for m in failed]}
    write_csv_with_sidecar(out, frame.to_csv(index=False, lineterminator="\n"), info)
    return frame, info


def build_random_set(n_muscles: int, seeds, out, mesh: str = "fine",
                     workers: int | None = None, cache_dir=None,
                     progress: bool = True,
                     scheduler: str | None = None) -> tuple[pd.DataFrame, dict]:
    """FE sweeps (:data:`EVAL_PRESSURES`) of ``n_muscles`` random muscles per seed of ``seeds``
    (:func:`random_muscles`), written to ``out`` and ``out.json`` (seeds, box, provenance)."""
    muscles = pd.concat([random_muscles(n_muscles, seed) for seed in seeds], ignore_index=True)
    frame, done = fe_sweeps(muscles, mesh, EVAL_PRESSURES, workers=workers,
                            cache_dir=cache_dir, progress=progress, desc="FE random muscles",
                            scheduler=scheduler)
    frame["origin"] = muscles["origin"].to_numpy()[frame["muscle"].to_numpy()]
    info = {**provenance(), "what": "random muscles of the box (surrogate.design)",
            "seeds": [int(s) for s in seeds], "muscles_per_seed": int(n_muscles),
            "box": {k: list(v) for k, v in BOX.items()}, "pressure_bar": list(EVAL_PRESSURES),
            "model": "axisym", "mesh": mesh, "model_version": done["model_version"]}
    write_csv_with_sidecar(out, frame.to_csv(index=False, lineterminator="\n"), info)
    return frame, info


def practical_muscles(n_muscles: int, seed: int) -> pd.DataFrame:
    """``n_muscles`` fresh random muscles of the practical range
    (:func:`mkm.fem.sampling.draw_muscles`: log-uniform sizes, coupled wall and length, eps up to
    95 % of the braid lock), one row per muscle with :data:`MUSCLE_PARAMETERS` and ``origin``."""
    from mkm.fem.sampling import draw_muscles

    columns = draw_muscles(int(n_muscles), int(seed)).columns()
    return pd.DataFrame({p: np.round(columns[p], 6) for p in MUSCLE_PARAMETERS}).assign(
        origin=f"practical seed {seed}")


def build_practical_set(n_muscles: int, seed: int, out, mesh: str = "fine",
                        workers: int | None = None, cache_dir=None, progress: bool = True,
                        scheduler: str | None = None,
                        adaptive: int = 0) -> tuple[pd.DataFrame, dict]:
    """FE sweeps (:data:`PRACTICAL_PRESSURES`) of ``n_muscles`` random muscles of the practical
    range (:func:`practical_muscles`), written to ``out`` and ``out.json`` (the draw, its box's
    hull as the dataset's box, provenance): the FE data a surrogate of the whole range learns
    from or is scored on. With ``adaptive``, only that many of the ``n_muscles`` drawn: those
    where the shipped practical-range surrogate (:data:`~mkm.surrogate.kinds.RANGE`) is least
    sure of the force at 8 bar relative to it (:func:`adaptive_muscles`; the sidecar records
    the dataset it was trained on). Muscles whose sweep fails are kept with
    ``converged=False`` (the loader leaves those rows out) and listed in the sidecar."""
    from mkm.fem.limits import PRACTICAL_RANGE
    from mkm.fem.sampling import draw_muscles

    muscles = practical_muscles(n_muscles, seed)
    picked_by = None
    if adaptive:
        from mkm.surrogate.kinds import RANGE
        from mkm.surrogate.train import cached_model

        if not 0 < int(adaptive) <= n_muscles:
            raise ValueError(f"--adaptive {adaptive!r} is invalid: expected 1 to --muscles "
                             f"({n_muscles}) picks among the muscles drawn")
        model = cached_model(RANGE)
        muscles = adaptive_muscles(model.estimator, adaptive, seed, pool=muscles,
                                   pressure_top_bar=PRACTICAL_PRESSURES[-1],
                                   reach_min_bar=PRACTICAL_PRESSURES[1] - PRACTICAL_PRESSURES[0])
        picked_by = {"kind": RANGE, "candidates": int(n_muscles), "picks": int(adaptive),
                     "dataset": {"file": Path(model.metadata["dataset"]["path"]).name,
                                 **{k: model.metadata["dataset"].get(k)
                                    for k in ("sha256", "n_muscles")}}}
    frame, done = fe_sweeps(muscles, mesh, PRACTICAL_PRESSURES, workers=workers,
                            cache_dir=cache_dir, progress=progress,
                            desc="FE muscles of the practical range", scheduler=scheduler)
    frame["origin"] = muscles["origin"].to_numpy()[frame["muscle"].to_numpy()]
    failed = sorted(set(frame.loc[~frame["converged"], "muscle"].tolist()))
    info = {**provenance(), "what": "random muscles of the practical range (surrogate.design)",
            "draw": draw_muscles(0, int(seed)).record() | {"muscles": int(n_muscles)},
            "adaptive": picked_by,
            "box": {k: list(v) for k, v in PRACTICAL_RANGE.hull().items()},
            "pressure_bar": list(PRACTICAL_PRESSURES), "model": "axisym", "mesh": mesh,
            "model_version": done["model_version"], "jobs_computed": done["computed"],
            "jobs_from_cache": done["cached"],
            "muscles_with_failed_points": [int(m) for m in failed]}
    write_csv_with_sidecar(out, frame.to_csv(index=False, lineterminator="\n"), info)
    return frame, info
