"""Robust designs: muscles that meet every requirement with a stated probability when they are
built to tolerances (``mkm design --tolerance D0=0.3,t0=0.1,theta0=1,rubber=10% --probability
0.95``).

A muscle built to tolerance has inputs anywhere within the bounds
(:class:`mkm.fem.tolerances.Tolerances`); its force is then uncertain by ``u_tol``, the GUM
propagation of the bounds through the surrogate (:func:`mkm.uncertainty.sensitivities`), and
the surrogate itself by its predictive standard deviation ``s``. Three stages:

1. **Search** (:func:`requirement_margin`): a candidate meets requirement ``k`` with probability
   ``Phi((F - F_k) / sqrt(u_tol^2 + s^2))`` (normal approximation, vectorised over the whole
   box); it is feasible when that is at least the probability asked for at every requirement,
   i.e. when ``F - z_p sqrt(u_tol^2 + s^2) >= F_k`` (``z_p = Phi^-1(p)``).
2. **Monte Carlo** (:func:`monte_carlo`): for every verified design, 4000 joint draws from the
   tolerances through the surrogate (through its linearisation where draws leave its box),
   each with its own surrogate error ``s N(0, 1)``:
   ``probability_r<k>`` (requirement ``k`` met) and ``probability_all`` (all met in the same
   muscle), the numbers designs.csv states. The designs whose ``probability_all`` is below
   the probability asked come after those that hold it (:func:`below_target`): the normal
   approximation is conservative at 95 %, not at 90 % (one uniform bound that dominates
   reaches its 10 % point at 0.80 of its half-width, the normal at 0.74).
3. **Worst corner** (:func:`check_designs`): the FE model at the corner of the tolerance box
   where the force is lowest (each input at its bound, on the side the sensitivity says lowers
   the force; one without a slope there, or that the surrogate does not take, at both bounds,
   the lowest FE force taken): ``r<k>_fe_worst_corner_N``. A corner short of the force is flagged
   (``r<k>:worst_corner_short``), not refused: the corner is rarer than ``1 - p``. A corner the
   FE does not solve (not converged, braid locked) is flagged ``r<k>:worst_corner_unsolved``,
   its reason in ``fe_failure``: never taken for a pass.

``benchmarks/bench_uncertainty.py --design`` checks the stated probability against the FE model
on draws from the tolerances.
"""

from __future__ import annotations

import itertools

import numpy as np
import pandas as pd
from scipy import stats

from mkm.fem.muscle import NUMBERS, Muscle
from mkm.fem.outcomes import classify
from mkm.fem.tolerances import Tolerances, draws
from mkm.registry import parse_spec
from mkm.uncertainty import monte_carlo_ready, nominal_parameters, sensitivities, surrogate_draws

MC_DRAWS = 4000  # the probability to +-0.7 points (binomial sd at 95 %)
#: The Monte Carlo's seed: requirement k draws its built muscles from ``MC_SEED + k`` and the
#: surrogate's noise from ``MC_SEED + 100 + k`` (the same designs give the same probabilities)
MC_SEED = 0
#: The flag of a requirement whose worst corner the FE did not solve (its reason in fe_failure)
WORST_CORNER_UNSOLVED = "worst_corner_unsolved"


def check_probability(probability: float) -> float:
    """``probability`` if it is in (0.5, 1), else ``ValueError`` naming it."""
    if isinstance(probability, bool) or not isinstance(probability, int | float) \
            or not 0.5 < probability < 1.0:
        raise ValueError(f"--probability {probability!r} is invalid: expected a probability "
                         "between 0.5 and 1 (0.95 for 95 %)")
    return float(probability)


def requirement_margin(model, prediction, requirement, D0_mm, t0_mm, tolerances: Tolerances,
                       probability: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The margin [N] a candidate's force must clear ``requirement`` by, for ``probability``;
    and the probability and ``u_tol`` [N] per candidate.

    ``prediction``: the surrogate's prediction at the candidates (``D0_mm``, ``t0_mm`` arrays).
    """
    force = np.asarray(prediction.force_N, dtype=float)
    std = np.asarray(prediction.extras.get("force_std_N", np.zeros_like(force)), dtype=float)
    nominal = nominal_parameters(model, D0_mm, t0_mm, requirement.eps)
    rebuild = getattr(model, "with_parameters", None)
    contributions = sensitivities(model, requirement.pressure_bar, nominal, tolerances, force,
                                  rebuild)
    u_tol = np.sqrt(sum(np.nan_to_num(c) ** 2 for c in contributions.values()))
    u = np.sqrt(u_tol**2 + std**2)
    z = stats.norm.ppf(probability)
    with np.errstate(divide="ignore", invalid="ignore"):
        p = stats.norm.cdf((force - requirement.force_N) / u)
    return z * u, p, u_tol


def describe(tolerances: Tolerances, probability: float) -> str:
    """What the search's margin is, for designs.json and the page."""
    bounds = ", ".join(f"{k}=+-{v:g}" for k, v in vars(tolerances).items() if v > 0)
    z = stats.norm.ppf(probability)
    return (f"{z:.3g} x sqrt(u_tol^2 + surrogate std^2): each requirement met with probability "
            f">= {100 * probability:g} % by muscles built to {bounds} (uniform within them)")


def monte_carlo_record(seed: int = MC_SEED) -> dict:
    """How :func:`check_designs` drew its probabilities, for the designs' record."""
    return {"draws": MC_DRAWS, "seed": seed,
            "streams": "requirement k: the built muscles from seed + k, the surrogate's noise "
                       "from seed + 100 + k (numpy default_rng)"}


def check_designs(designs: pd.DataFrame, requirements, models: dict,
                  tolerances: Tolerances, probability: float, mesh: str, cache_dir=None,
                  seed: int = MC_SEED) -> pd.DataFrame:
    """``designs`` with the Monte Carlo probabilities (:func:`monte_carlo`) and the FE at the
    worst corner.

    ``models``: the search's surrogates by ``(L0, theta0, rubber)``. Adds
    ``probability_r<k>``, ``probability_all``, ``r<k>_fe_worst_corner_N`` (NaN where the FE
    gives no valid force there) and the flags ``r<k>:worst_corner_short``,
    ``r<k>:worst_corner_unsolved`` (its reason added to ``fe_failure``) and
    ``all:probability_below_target``.
    """
    from mkm.prediction_cache import cached_predict

    chances = monte_carlo(designs, requirements, models, tolerances, seed)
    rows = []
    for index, d in designs.iterrows():
        model = models[(float(d["L0_mm"]), float(d["theta0_deg"]), d["rubber"])]
        out, flags = {}, [f for f in str(d.get("flags", "") or "").split(";") if f]
        failures = [f for f in [str(d.get("fe_failure", "") or "")] if f]
        for k, req in enumerate(requirements, start=1):
            out[f"probability_r{k}"] = chances.loc[index, f"probability_r{k}"]
            nominal = {name: float(v) for name, v in nominal_parameters(
                model, d["D0_mm"], d["t0_mm"], req.eps).items()}
            force, reason = _worst_corner_force(model, d.get("fe_mesh", mesh), nominal, req,
                                                tolerances, cache_dir, cached_predict)
            out[f"r{k}_fe_worst_corner_N"] = force
            if np.isnan(force):  # never a pass: whether the corner holds is unknown
                flags.append(f"r{k}:{WORST_CORNER_UNSOLVED}")
                failures.append(f"r{k} worst corner: {reason}")
            elif force < req.force_N:
                flags.append(f"r{k}:worst_corner_short")
        out["probability_all"] = chances.loc[index, "probability_all"]
        if not out["probability_all"] >= probability:
            flags.append("all:probability_below_target")
        out["flags"] = ";".join(flags)
        out["fe_failure"] = "; ".join(failures)
        rows.append(out)
    extra = pd.DataFrame(rows, index=designs.index)
    return pd.concat([designs.drop(columns=["flags", "fe_failure"], errors="ignore"), extra],
                     axis=1)


def monte_carlo(designs: pd.DataFrame, requirements, models: dict, tolerances: Tolerances,
                seed: int = MC_SEED) -> pd.DataFrame:
    """Per design (``designs``' index): ``probability_r<k>`` and ``probability_all``, the share
    of :data:`MC_DRAWS` joint draws from the tolerances, each with its own surrogate error,
    that meet requirement ``k`` and every requirement in the same muscle."""
    rows = []
    for _, d in designs.iterrows():
        model = models[(float(d["L0_mm"]), float(d["theta0_deg"]), d["rubber"])]
        out, met_all = {}, None
        for k, req in enumerate(requirements, start=1):
            nominal = nominal_parameters(model, d["D0_mm"], d["t0_mm"], req.eps)
            nominal = {name: float(v) for name, v in nominal.items()}
            sample = draws(nominal, tolerances, MC_DRAWS, np.random.default_rng(seed + k))
            pred = model.predict(req.pressure_bar, d["D0_mm"], d["t0_mm"], req.eps)
            std = float(np.ravel(pred.extras.get("force_std_N", [0.0]))[0])
            if monte_carlo_ready(model, sample):
                force = surrogate_draws(model, req.pressure_bar, sample)[0]
            else:  # draws off the surrogate's box: its linearisation carries the same draws
                force = _linear_draws(model, req, nominal, sample, tolerances,
                                      float(np.ravel(pred.force_N)[0]))
            noise = np.random.default_rng(seed + 100 + k).standard_normal(MC_DRAWS)
            met = force + std * noise >= req.force_N
            out[f"probability_r{k}"] = float(met.mean())
            met_all = met if met_all is None else met_all & met
        out["probability_all"] = float(met_all.mean()) if met_all is not None else np.nan
        rows.append(out)
    return pd.DataFrame(rows, index=designs.index)


def below_target(designs: pd.DataFrame, requirements, models: dict, tolerances: Tolerances,
                 probability: float, seed: int = 0) -> frozenset:
    """The ``rank`` of each design whose Monte Carlo ``probability_all`` (:func:`monte_carlo`)
    is below ``probability``: the FE verification places them after those that hold it."""
    chances = monte_carlo(designs, requirements, models, tolerances, seed)
    return frozenset(designs.loc[~(chances["probability_all"] >= probability), "rank"])


def _linear_draws(model, req, nominal, sample, tolerances, force_N) -> np.ndarray:
    """``F + sum_i (dF/dx_i) (x_i - x_i,nominal)`` for every draw (the GUM linearisation)."""
    contributions = sensitivities(model, req.pressure_bar, nominal, tolerances, force_N,
                                  getattr(model, "with_parameters", None))
    u = tolerances.standard()
    force = np.full(MC_DRAWS, force_N)
    for name, c in contributions.items():
        c = float(np.ravel(c)[0])
        if name == "rubber_fraction":
            deviation = sample["C10_MPa"] / nominal["C10_MPa"] - 1.0
        else:
            deviation = sample[name] - nominal[name]
        force = force + c / u[name] * deviation
    return force


def _worst_corner_force(model, mesh, nominal, req, tolerances, cache_dir,
                        cached_predict) -> tuple[float, str]:
    """The FE force at the corner of the tolerance box that lowers the force most, and why it is
    NaN where the FE gave no valid force there (else ""). Each input goes to the bound the
    surrogate's sensitivity says lowers the force; an input it shows no slope for (the rubber
    and the length at eps 0, where the braid holds the tube's shape) or cannot vary goes to
    both bounds, and the FE's lowest force of those corners is the worst."""
    force = float(np.ravel(model.predict(req.pressure_bar, nominal["D0_mm"], nominal["t0_mm"],
                                         req.eps).force_N)[0])
    signs = sensitivities(model, req.pressure_bar, nominal, tolerances, force,
                          getattr(model, "with_parameters", None))
    bounds = vars(tolerances)
    corner = dict(nominal)
    for name, c in signs.items():
        corner = _moved(corner, name, -np.sign(float(np.ravel(c)[0])) * bounds[name])
    undecided = [name for name, bound in bounds.items()
                 if bound > 0 and not np.ravel(signs.get(name, [0.0]))[0]]
    forces = []
    for sides in itertools.product((-1.0, 1.0), repeat=len(undecided)):
        muscle_at = dict(corner)
        for name, side in zip(undecided, sides, strict=True):
            muscle_at = _moved(muscle_at, name, side * bounds[name])
        found, reason = _fe_force(muscle_at, mesh, req, cache_dir, cached_predict)
        if not np.isfinite(found):  # never a pass: whether that corner holds is unknown
            return np.nan, reason
        forces.append(found)
    return min(forces), ""


def _moved(muscle: dict, name: str, step: float) -> dict:
    """``muscle`` with the toleranced input ``name`` moved by ``step`` (the rubber: C10 and C01
    by that fraction), eps no lower than 0."""
    out = dict(muscle)
    if name == "rubber_fraction":
        out["C10_MPa"] *= 1 + step
        out["C01_MPa"] *= 1 + step
    else:
        out[name] = out[name] + step
    out["eps"] = max(out["eps"], 0.0)
    return out


def _fe_force(corner: dict, mesh, req, cache_dir, cached_predict) -> tuple[float, str]:
    """The FE force of the muscle ``corner`` at the requirement's pressure, and why it is NaN
    where the FE gave no valid force (else "")."""
    muscle = Muscle(**{k: corner.get(k) for k in NUMBERS})
    fe = parse_spec(f"axisym:mesh={mesh}").build(muscle=muscle)
    pred, _ = cached_predict(fe, req.pressure_bar, muscle.D0_mm, muscle.t0_mm, muscle.eps,
                             cache_dir=cache_dir)
    force = float(np.ravel(np.where(pred.valid, pred.force_N, np.nan))[0])
    if np.isfinite(force):
        return force, ""
    outcome = str(classify(pred)[0])  # the one classification: braid locks, not converged...
    outcome = "the FE gave a NaN force" if outcome == "ok" else outcome
    failure = str(np.ravel(pred.extras.get("failure", [""]))[0])
    return np.nan, outcome if failure in ("", "nan") else f"{outcome}: {failure}"
