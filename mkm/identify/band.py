"""The 95 % prediction band of a force predicted with an identified muscle's calibration.

``mkm fem solve --calibration DIR/calibration.json`` (a file ``mkm identify`` wrote) prints
``band95_N`` beside the force: 1.96 standard deviations of

- the identified parameters' uncertainty: the model's sensitivity to each static parameter
  (braid angle, rubber scale, C01's share where fitted, the wall and diameter where fitted,
  the gap; forward differences of a tenth of a standard deviation) through their bootstrap
  covariance, which already holds the pressure monitor's offset and the load cell's tolerance
  as the runs could not see them;
- each model-form term's and each assumed rubber ratio's end (``terms``: the parameters a refit
  moves to), as the force at the moved parameters less the force: a one-sided term a uniform
  between the two (variance over 3), a symmetric one a standard deviation;
- the load cell's sensitivity tolerance again, on the predicted force itself (uniform within
  the declared +- tolerance: every force the runs measured, so every force the calibration
  predicts, carries the cell's unknown gain);
- the misfit, where calibration.json records one (``band.misfit_rms_N``: the residual the
  model could not explain, :attr:`mkm.identify.goodness.Goodness.discrepancy_rms_N`; the
  covariance is then the widened intervals', by the Birge ratio).

A fitted wall or diameter enters only as the solve's own ``--t0``/``--D0``: the band assumes
the identified muscle's geometry is what is solved (parameters.csv gives the fitted values).

:func:`check_heldout` judges a run the fit did not see against the band
(``benchmarks/bench_identify_coverage.py`` counts the held-out runs inside it).
"""

from __future__ import annotations

import math

import numpy as np

from mkm.identify import fitting

#: the two-sided 95 % normal quantile
Z95 = 1.959964
#: the finite-difference step, in standard deviations of the parameter
STEP_SD = 0.1
#: the band's upper end is the linearisation where the force on the band's ellipse, along the
#: gradient, parts from it by at most this share of the band (:func:`prediction_ends`): a band
#: 2 % wider than a normal one's 1.96 standard deviations holds 97.7 % of it, not 97.5 %
LINEAR_TOLERANCE = 0.02
#: the level of a held-out run's joint statement (:func:`check_heldout`)
RUN_LEVEL = 0.95


def run_noise_z(steps: int, level: float = RUN_LEVEL) -> float:
    """The factor of each step's noise that keeps all ``steps`` steps of a run within it with
    probability at least ``level`` (Sidak: ``level ** (1 / steps)`` per step, two-sided; a lower
    bound for normal errors however they are correlated, the run's shared tare included): 1.96
    for one step, 3.00 for the 19 of the paper's staircase. A run is one statement: judged at
    1.96 per step, an exact prediction of a run whose six slack steps measure only their noise
    would miss 1 - 0.95^6 = 26 % of the time."""
    from scipy.stats import norm

    return float(norm.ppf(0.5 + 0.5 * level ** (1.0 / max(int(steps), 1))))


def identified_entry(calibration) -> tuple[str, dict] | None:
    """``(key, entry)`` of the identified muscle in ``calibration`` (the entry of the static
    model identify confirmed with), or None."""
    return next(((key, entry) for key, entry in calibration.entries.items()
                 if "identified" in entry), None)


def identified_lengths(calibration) -> list[float]:
    """The rest lengths [mm] of the muscle ``calibration`` was identified on (``mkm identify``
    records its runs): the fitted one (``--params L0``), else the runs' declared ones, each
    once; empty for the shipped calibration or one that records none."""
    found = identified_entry(calibration) if calibration is not None else None
    if found is None:
        return []
    record = found[1]["identified"]
    fitted = [float(p["value"]) for p in record.get("parameters", [])
              if p.get("parameter") == "L0_mm" and p.get("status") == "fitted"
              and p.get("value") is not None]
    declared = [(r.get("muscle") or {}).get("L0_mm") for r in record.get("runs", [])]
    return fitted[:1] or list(dict.fromkeys(float(v) for v in declared if v is not None))


def identified_tube(calibration) -> tuple[float, float] | None:
    """``(D0_mm, t0_mm)`` of the tube ``calibration`` was identified on (``mkm identify``
    records its runs, of one tube): a fitted value where identify fitted it, else the runs'
    declared one; None for the shipped calibration or one that records none."""
    found = identified_entry(calibration) if calibration is not None else None
    if found is None:
        return None
    record = found[1]["identified"]
    fitted = {p["parameter"]: float(p["value"]) for p in record.get("parameters", [])
              if p.get("status") == "fitted" and p.get("value") is not None}
    declared = next((r["muscle"] for r in record.get("runs", []) if r.get("muscle")), {})
    tube = [fitted.get(k, declared.get(k)) for k in ("D0_mm", "t0_mm")]
    return None if None in tube else (float(tube[0]), float(tube[1]))


def prediction_band(spec, calibration, force_N, pressure_bar, D0_mm, t0_mm, eps,
                    cache_dir=None):
    """The 95 % half-width [N] of each force ``force_N`` the model of ``spec`` (a
    :class:`mkm.registry.Spec`) predicted with ``calibration`` at the inputs, linearised: the
    band's lower end (:func:`prediction_ends` gives its upper end too, which differs where the
    force is not linear in the parameters); None where the calibration holds no identified
    muscle of this model, or the spec overrides the identified angle or rubber. Its solves are
    kept in the prediction cache ``cache_dir`` (:mod:`mkm.prediction_cache`; None: no
    cache)."""
    ends = _band(spec, calibration, force_N, pressure_bar, D0_mm, t0_mm, eps, cache_dir,
                 upper=False)
    return None if ends is None else ends[0]


def prediction_ends(spec, calibration, force_N, pressure_bar, D0_mm, t0_mm, eps,
                    cache_dir=None):
    """``(below, above)``: how far [N] the 95 % band of each force ``force_N`` reaches below
    and above it (:func:`prediction_band`'s arguments; None where it gives None).

    ``below`` is the linearisation. ``above`` is the most a muscle of the parameters' 95 %
    ellipse pulls (for a force linear in them, its 97.5 % quantile exactly), the terms, the load
    cell and the misfit added as below:

    - near the threshold pressure P*, less than :data:`Z95` standard deviations of P* (its
      sensitivities through the covariance) above the identified P*, or below it, the force is
      ``max(0, A (P - P*))``, not linear in the parameters: the identified muscle's own
      sensitivities say nothing of the muscles that pull where it is slack (a linearised band
      is 0 N below P*), and a step of a tenth of a standard deviation may cross P*. There the
      muscle :data:`Z95` standard deviations of P* lower is solved, through the kink, and the
      one its own gradient points to on the ellipse (one sweep and one per parameter more, and
      one solve per such pressure);
    - elsewhere, the force on the ellipse where the linearisation puts its most (one solve per
      direction, pressures of about one direction sharing it): where it parts from the
      linearised end by more than :data:`LINEAR_TOLERANCE` of the band (near the braid lock
      the force is convex in the braid angle) it is taken, else the linearisation.

    A model that reports no threshold (``threshold_pressure_bar``) has no P* to be near."""
    return _band(spec, calibration, force_N, pressure_bar, D0_mm, t0_mm, eps, cache_dir,
                 upper=True)


def _band(spec, calibration, force_N, pressure_bar, D0_mm, t0_mm, eps, cache_dir, upper):
    """:func:`prediction_ends`, its upper end solved only where ``upper``."""
    found = identified_entry(calibration) if calibration is not None else None
    if found is None or "band" not in found[1]["identified"]:
        return None
    key, entry = found
    if spec.build(calibration).calibration_key != key or {
            "theta0_deg", "C10_MPa", "C01_MPa"} & set(dict(spec.params)):
        return None
    band = entry["identified"]["band"]
    names, covariance = band["parameters"], np.asarray(band["covariance"], dtype=float)
    values = {"c01_fraction": fitting.SILASTIC_C01_FRACTION,
              **fitting.nominal_values(entry["theta0_deg"], entry.get("C10_MPa"),
                                       entry.get("C01_MPa")),
              **dict(zip(names, band["values"], strict=True))}
    inputs = {"D0_mm": D0_mm, "t0_mm": t0_mm}

    def solved(shift: dict, at=pressure_bar) -> tuple[np.ndarray, np.ndarray]:
        # a term's shift names every fitted parameter; the static force takes the static ones,
        # within what a rubber and a gap can be: a shift beyond (the other braid's pull on a
        # natural rubber's small C01 share) is the refit stopped there, as the interval is
        moved = {**values, **{n: values[n] + d for n, d in shift.items()
                              if n in fitting.STATIC_NAMES}}
        moved["c01_fraction"] = float(np.clip(moved["c01_fraction"],
                                              *fitting.TERM_BOUNDS["c01_fraction"]))
        if "gap_mm" in moved:
            moved["gap_mm"] = max(moved["gap_mm"], 0.0)
        geometry = {g: (moved[g] if g in shift or g in names else inputs[g])
                    for g in fitting.GEOMETRY}
        return _solved(spec, calibration, moved, at, geometry["D0_mm"],
                       geometry["t0_mm"], eps, cache_dir)

    def force_at(shift: dict) -> np.ndarray:
        return solved(shift)[0]

    # the force at the band's own (unrounded) values: the differences are taken from it
    base, threshold = solved({})
    steps = [STEP_SD * np.sqrt(max(covariance[k, k], 0.0)) or 1e-6 for k in range(len(names))]
    stepped = [solved({name: step}) for name, step in zip(names, steps, strict=True)]
    G = np.array([(f - base) / step for (f, _), step in zip(stepped, steps, strict=True)]
                 ).reshape(len(names), -1)
    linear = np.einsum("in,ij,jn->n", G, covariance, G) if names else np.zeros(base.size)
    # a term is evaluated where it moves the parameters, not linearised: it may start the
    # force at a step the identified muscle is slack at (a threshold moved)
    others = np.zeros(base.size)
    for term in band.get("terms", ()):
        moved = force_at(term["shift"]) - base
        others = others + moved**2 / (3.0 if term["kind"] == "one-sided" else 1.0)
    tolerance = float(band.get("sensitivity_tolerance", 0.0))
    others = others + (tolerance / np.sqrt(3.0) * np.ravel(force_N)) ** 2
    others = others + float(band.get("misfit_rms_N", 0.0)) ** 2
    shape = np.shape(force_N)
    below = Z95 * np.sqrt(linear + others)
    above = below.copy()
    if not upper:
        return below.reshape(shape), above.reshape(shape)
    # P*'s gradient: the same steps' thresholds (one per sweep, NaN where the braid locks)
    g = np.array([np.nanmean(t) - np.nanmean(threshold) if np.isfinite(t).any() else np.nan
                  for _, t in stepped]) / np.array(steps) if names else np.zeros(0)
    threshold_bar = float(np.nanmean(threshold)) if np.isfinite(threshold).any() else np.nan
    spread = float(np.sqrt(g @ covariance @ g)) if names and np.isfinite(g).all() else 0.0
    pressures = np.asarray(pressure_bar, dtype=float).ravel()
    near = pressures - threshold_bar < Z95 * spread
    linear_end = np.sqrt(linear)
    if names and (far := ~near & (linear_end > 0)).any():
        # the ellipse's point along each pressure's gradient, in standard deviations: pressures
        # whose directions round alike share one solve, each taking its own linear part
        sd = np.sqrt(np.maximum(np.diag(covariance), 0.0))
        directions = (covariance @ G / np.where(linear_end > 0, linear_end, 1.0)).T
        rounded = np.round(directions / np.where(sd > 0, sd, 1.0) * 20) / 20
        for key in np.unique(rounded[far], axis=0):
            at = far & (rounded == key).all(axis=1)
            point = Z95 * directions[at].mean(axis=0)
            moved, _ = solved(dict(zip(names, point, strict=True)), pressures[at])
            curvature = moved - base[at] - G[:, at].T @ point
            end = Z95 * linear_end[at] + curvature
            bent = np.isfinite(end) & (np.abs(curvature) > LINEAR_TOLERANCE * Z95
                                       * linear_end[at])
            above[at] = np.where(bent, np.sqrt(np.maximum(end, 0.0) ** 2
                                               + Z95**2 * others[at]), above[at])
    if spread > 0 and near.any():
        # the muscle Z95 sd of P* lower pulls; the force's own gradient there points to the
        # most the band's ellipse holds
        start = -Z95 * covariance @ g / spread
        first, _ = solved(dict(zip(names, start, strict=True)))
        rise = np.array([(solved(dict(zip(names, start + step * np.eye(len(names))[k],
                                           strict=True)))[0] - first) / step
                         for k, step in enumerate(steps)])
        most = first.copy()
        for i in np.flatnonzero(near):
            reach = float(np.sqrt(max(rise[:, i] @ covariance @ rise[:, i], 0.0)))
            if np.isfinite(reach) and reach > 0:
                point = Z95 * covariance @ rise[:, i] / reach
                most[i] = np.nanmax([first[i], solved(dict(zip(names, point, strict=True)),
                                                      pressures[i:i + 1])[0][0]])
        along = np.maximum(np.nan_to_num(most - base), 0.0)
        above = np.where(near, np.sqrt(along**2 + Z95**2 * others), above)
    return below.reshape(shape), above.reshape(shape)


#: the over-force interlock's ceiling is tabulated every this much [bar], up to
#: :data:`CEILING_TOP` times ``max_pressure_bar`` (a reading beyond 1.1 times it trips the
#: over-pressure limit; the rest is the monitor's accuracy and its gain error)
CEILING_STEP_BAR = 0.05
CEILING_TOP = 1.5


def config_ceiling(config, calibration_file=None):
    """The :class:`mkm.bench.preflight.ForceCeiling` a run of the bench configuration
    ``config`` is held to (:func:`force_ceiling`): of ``calibration_file`` (``mkm acquire
    --calibration``, ``mkm check --calibration``), else of the configuration's
    ``safety.calibration``; None when neither names one. Its errors name the one given."""
    from mkm.fem.calibration import Calibration

    if calibration_file is not None:
        path, given = calibration_file, "--calibration"
    elif config.calibration_path is not None:
        path, given = config.calibration_path, f"config {config.source}: safety.calibration"
    else:
        return None
    try:
        calibration = Calibration.load(path)
    except ValueError as exc:
        raise ValueError(str(exc) if calibration_file is not None else f"{given}: {exc}") \
            from None
    return force_ceiling(calibration, config.muscle, config.regulator.max_pressure_bar, given)


def force_ceiling(calibration, muscle, max_pressure_bar: float, given: str = "--calibration"):
    """The most the muscle ``calibration`` identified (the calibration.json ``mkm identify``
    writes) pulls at ``muscle``'s eps, at pressures up to :data:`CEILING_TOP` x
    ``max_pressure_bar`` [bar]: its identified static force plus the 95 % band's upper
    end (:func:`prediction_ends`: near and below the threshold, that of the muscles that pull
    where the identified one is slack), with the upper end of its friction's interval (the bench's
    :data:`mkm.bench.preflight.FRICTION_FRACTION` where identify fitted none): the
    :class:`mkm.bench.preflight.ForceCeiling` that arms ``mkm acquire``'s over-force
    interlock, with the least it pulls (the static force less the band's lower end).
    ``ValueError`` in one line, naming the file as ``given`` names it, for a calibration that
    holds no identified muscle, or one identified on another tube or rest length than
    ``muscle`` (a :class:`mkm.fem.muscle.Muscle`) declares."""
    from mkm.bench.preflight import FRICTION_FRACTION, ForceCeiling
    from mkm.registry import parse_spec

    found = identified_entry(calibration)
    if found is None or "band" not in found[1]["identified"]:
        raise ValueError(f"{given} {calibration.path} holds no muscle mkm identify "
                         "identified with its prediction band: expected the calibration.json "
                         "of `mkm identify RUNS --out DIR` for this muscle")
    key, entry = found
    record = entry["identified"]
    fitted = {p["parameter"]: p.get("value") for p in record.get("parameters", [])
              if p.get("status") == "fitted"}
    names = [name for name in ("D0_mm", "t0_mm", "L0_mm") if name not in fitted]

    def other(run_muscle: dict) -> list[str]:  # what this run's muscle declares otherwise
        return [name for name in names if name in run_muscle and not math.isclose(
            float(run_muscle[name]), float(getattr(muscle, name)), rel_tol=1e-6)]

    muscles = [r["muscle"] for r in record.get("runs", []) if r.get("muscle")]
    if muscles and all(other(m) for m in muscles):
        differ = other(muscles[0])
        raise ValueError(
            f"{given} {calibration.path} identified a muscle of "
            + ", ".join(f"{name}={muscles[0][name]:g}" for name in differ)
            + "; the configuration declares "
            + ", ".join(f"{name}={getattr(muscle, name):g}" for name in differ)
            + ": expected the identification of the muscle this run holds")
    tube = identified_tube(calibration) or (muscle.D0_mm, muscle.t0_mm)
    L0_mm = fitted.get("L0_mm") or muscle.L0_mm
    spec = parse_spec(key.partition("-")[0]).with_params(**{
        k: v for k, v in entry.get("model_params", {}).items()
        if k not in ("theta0_deg", "C10_MPa", "C01_MPa", "gap_mm", "L0_mm")},
        L0_mm=float(L0_mm))
    pressure_bar = np.arange(0.0, CEILING_TOP * max_pressure_bar + CEILING_STEP_BAR / 2,
                             CEILING_STEP_BAR)
    model = spec.build(calibration)
    predicted = model.predict(pressure_bar, tube[0], tube[1], muscle.eps)
    force = np.asarray(predicted.force_N, dtype=float)
    ends = prediction_ends(spec, calibration, force, pressure_bar, tube[0], tube[1],
                           muscle.eps)
    if ends is None:
        raise ValueError(f"{given} {calibration.path}: no prediction band for its "
                         f"identified model {key}")
    friction = next((p["value"] if p.get("ci_high") is None else p["ci_high"]
                     for p in record.get("parameters", [])
                     if p.get("parameter") == "hysteresis_fraction"
                     and p.get("value") is not None), None)
    # where the model gives no valid force (past its lock) nothing bounds the force, and it
    # pulls none for sure
    below, above = ends
    known = np.asarray(predicted.valid, dtype=bool) & np.isfinite(force + above)
    most = np.where(known, np.maximum(force, 0.0) + above, np.inf)
    least = np.where(known, np.maximum(force - below, 0.0), 0.0)
    return ForceCeiling(tuple(map(float, pressure_bar)), tuple(map(float, most)),
                        tuple(map(float, least)),
                        float(FRICTION_FRACTION if friction is None else friction),
                        f"the muscle identified in {calibration.path} ({key})",
                        fitted.get("theta0_deg"))


def check_heldout(result, run_dir, out_dir) -> dict:
    """A run of the identified muscle the fit did not see (``run_dir``) predicted with the
    calibration the identification ``result`` writes into ``out_dir``: each settled step's mean
    against the identified model's prediction of it (friction and creep along the hold,
    :func:`mkm.identify.procedure.predict_runs`) and the calibration's 95 % band at the step's
    pressure (:func:`prediction_band`, what ``mkm fem solve --calibration`` prints).

    The band is the true force's; a measured step mean carries its own noise too (the hold's
    scatter over root n and the run's tare, as the goodness of fit takes it; an imported
    table's the noise its lab declared), so a step is
    inside when ``|measured - predicted| <= sqrt(band95^2 + (1.96 noise)^2)`` (``inside``),
    and, stricter, within the band alone (``in_band``): a slack step (no force predicted, band
    0) is never in the band alone. A run is inside (``run_inside``) when every step is within
    ``sqrt(band95^2 + (z noise)^2)``, ``z`` the run's joint noise factor
    (:func:`run_noise_z`: 3.00 for 19 steps), so that the noise alone leaves 95 % of the runs
    inside, as the band alone does the true force. Returns the counts, the worst step (its
    error over the run's reach) and the band's median width (a percentage of the force where
    it pulls).
    """
    from mkm.bench.storage import load_run
    from mkm.fem.calibration import Calibration
    from mkm.identify.procedure import predict_runs
    from mkm.identify.runs import load_runs
    from mkm.registry import parse_spec

    files = result.write(out_dir)
    calibration = Calibration.load(files["calibration"])
    (held,) = load_runs([run_dir])
    predicted = predict_runs([run_dir], result.values, model=result.model)[0]["predicted_N"]
    measured = held.steps["force_N_mean"].to_numpy(dtype=float)
    pressure = held.steps["pressure_bar_mean"].to_numpy(dtype=float)
    m = held.muscle
    spec = parse_spec(result.model).with_params(L0_mm=float(m["L0_mm"]))
    band = prediction_band(spec, calibration, predicted, pressure, float(m["D0_mm"]),
                           float(m["t0_mm"]), held.eps)
    if band is None:
        raise RuntimeError(f"{files['calibration']}: no prediction band for {result.model}")
    raw = load_run(run_dir).steps
    raw = raw[raw["settled"].astype(bool)]
    declared = held.declared_noise_N()  # a table's: its single values show none
    noise = declared if declared is not None else np.hypot(
        raw["force_N_std"].to_numpy(dtype=float) / np.sqrt(raw["n"].to_numpy(dtype=float)),
        held.tare_se_N)
    error = np.abs(measured - predicted)
    judged = judge_steps(error, band, noise)
    inside, in_band, reach = judged["inside"], error <= band, judged["run_reach"]
    pulled = (band > 0) & (predicted > 0)  # a step the muscle pulls at, by the prediction
    worst = int(np.argmax(error / np.maximum(reach, 1e-12)))
    ratio = error[pulled] / band[pulled] if pulled.any() else np.full(1, np.nan)
    return {"eps": held.eps, "steps": int(inside.size), "steps_inside": int(inside.sum()),
            "steps_in_band": int(in_band.sum()), "slack_steps": int((~pulled).sum()),
            "run_inside": judged["run_inside"], "run_noise_z": round(judged["z"], 3),
            "run_in_band": bool(in_band.all()),
            "run_in_band_pulled": bool(in_band[pulled].all()),
            "worst_error_over_reach": round(float(error[worst] / reach[worst]), 3),
            "median_error_over_band": round(float(np.median(ratio)), 4),
            "worst_step": {"pressure_bar": round(float(pressure[worst]), 4),
                           "error_N": round(float(error[worst]), 3),
                           "band95_N": round(float(band[worst]), 3),
                           "noise_N": round(float(noise[worst]), 4)},
            "band95_median_percent": round(float(np.median(100 * band[pulled]
                                                            / predicted[pulled]))
                                           if pulled.any() else float("nan"), 2)}


def judge_steps(error, band, noise) -> dict:
    """A run's steps judged against their band and noise: ``inside`` per step (within
    ``sqrt(band^2 + (1.96 noise)^2)``, a step's own 95 %), ``run_reach`` (the band and the
    noise at the run's joint factor ``z``, :func:`run_noise_z` of the number of steps) and
    ``run_inside`` (every step within it)."""
    error, band, noise = (np.asarray(a, dtype=float) for a in (error, band, noise))
    z = run_noise_z(error.size)
    run_reach = np.hypot(band, z * noise)
    return {"inside": error <= np.hypot(band, Z95 * noise), "z": z, "run_reach": run_reach,
            "run_inside": bool((error <= run_reach).all())}


def _solved(spec, calibration, values, pressure_bar, D0_mm, t0_mm, eps, cache_dir=None):
    """The force [N] of the model of ``spec`` at the parameters ``values``, and its threshold
    pressure [bar] (NaN for a model that reports none)."""
    from mkm.prediction_cache import cached_predict

    C10, C01 = fitting.rubber(values)
    gap = {"gap_mm": values["gap_mm"]} if "gap_mm" in values else {}
    model = spec.with_params(theta0_deg=float(values["theta0_deg"]), C10_MPa=C10,
                             C01_MPa=C01, **gap).build(calibration)
    prediction, _ = cached_predict(model, pressure_bar, D0_mm, t0_mm, eps, cache_dir=cache_dir)
    force = np.asarray(prediction.force_N, dtype=float)
    threshold = prediction.extras.get("threshold_pressure_bar")
    return force, (np.full(force.shape, np.nan) if threshold is None
                   else np.asarray(threshold, dtype=float).reshape(force.shape))
