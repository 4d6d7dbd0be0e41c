"""Prediction bands: how uncertain a model's force is, given the tolerances the muscle is made to.

The tolerances (:class:`mkm.fem.tolerances.Tolerances`, +- bounds, uniform within them) are
propagated by :func:`force_band` to a model's force at given pressures (GUM Supplement 1,
JCGM 101:2008, where it can):

- ``monte-carlo``: a surrogate that takes every toleranced parameter as an input, with every
  draw inside its training box, is evaluated on ``n_draws`` joint draws per pressure in one
  call (20 pressures x 1000 draws in milliseconds: ``benchmarks/bench_uncertainty.py``); the
  standard deviation of the draws is the band; the surrogate's own predictive standard deviation
  is added in quadrature;
- ``linearised``: elsewhere (a physics model, a point outside the surrogate's box), central
  differences over +- one standard uncertainty of each input give the sensitivity coefficients,
  and ``u^2 = sum (dF/dx_i u_i)^2`` (GUM's law of propagation; two predictions per input).

The result goes into a prediction's extras as ``force_u_N`` (see :func:`with_band`), so every
:class:`~mkm.fem.interface.ForceModel` prediction can carry a standard uncertainty.
"""

from __future__ import annotations

import warnings
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from mkm.fem.interface import ForceModel, Prediction
from mkm.fem.tolerances import Tolerances, draws


@dataclass
class Band:
    """A model's force [N] at the pressures, its standard uncertainty [N] and how it was got."""

    force_N: np.ndarray
    force_u_N: np.ndarray
    method: str  # "monte-carlo" | "linearised"
    draws: int = 0  # the Monte Carlo's draws per pressure and their seed
    seed: int | None = None

    def record(self) -> dict:
        """How the band was got, for the provenance of what it judged: the method, and a
        Monte Carlo's draws and seed."""
        return {"method": self.method, **({"draws": self.draws, "seed": self.seed}
                                          if self.method == "monte-carlo" else {})}


def nominal_parameters(model: ForceModel, D0_mm: float, t0_mm: float, eps: float
                       ) -> dict[str, float]:
    """The muscle ``model`` predicts for: the geometry given (``D0_mm``, ``t0_mm`` may be arrays)
    and its own parameters (``L0_mm``, ``theta0_deg``, ``C10_MPa``, ``C01_MPa``, where it has
    them)."""
    from mkm.fem.materials import SILASTIC_S
    from mkm.fem.paper import L0_MM

    params = dict(getattr(model, "parameters", None) or model.params())
    theta = params.get("theta0_deg")
    if theta is None:
        from mkm.fem.calibration import calibrated

        theta = calibrated(model.calibration_key,
                           getattr(model, "calibration", None))["theta0_deg"]
    def given(name: str, default: float) -> float:  # a C01 of 0 (neo-Hookean) is given
        return float(default if params.get(name) is None else params[name])

    return {"D0_mm": np.asarray(D0_mm, dtype=float), "t0_mm": np.asarray(t0_mm, dtype=float),
            "eps": float(eps), "L0_mm": given("L0_mm", L0_MM), "theta0_deg": float(theta),
            "C10_MPa": given("C10_MPa", SILASTIC_S.C10_MPa),
            "C01_MPa": given("C01_MPa", SILASTIC_S.C01_MPa)}


def force_band(model: ForceModel, pressure_bar, D0_mm: float, t0_mm: float, eps: float,
               tolerances: Tolerances, rebuild: Callable[..., ForceModel] | None = None,
               n_draws: int = 1000, seed: int = 0, method: str = "auto",
               predict: Callable[..., Prediction] | None = None) -> Band:
    """The force of ``model`` at ``pressure_bar`` [bar] for the muscle (``D0_mm`` [mm],
    ``t0_mm`` [mm], ``eps``) and its standard uncertainty under ``tolerances``.

    Parameters
    ----------
    rebuild : callable, optional
        ``rebuild(**params)`` returns the model with other ``L0_mm``, ``theta0_deg``,
        ``C10_MPa``, ``C01_MPa`` (a registry spec's ``build``); needed by the linearised method
        for those inputs. Without it they are left out of the band.
    n_draws, seed : int
        Monte Carlo draws per pressure and the seed of their generator.
    method : {"auto", "linearised"}
        ``auto``: Monte Carlo where the model allows it (see the module docstring).
    predict : callable, optional
        ``predict(model, pressure_bar, D0_mm, t0_mm, eps)`` returns a prediction (a cache for
        FE models); default ``model.predict``.

    Returns
    -------
    Band
        ``force_u_N`` is NaN where the nominal force is not valid, or where neither side of a
        linearised difference is.
    """
    pressure = np.atleast_1d(np.asarray(pressure_bar, dtype=float))
    nominal = nominal_parameters(model, D0_mm, t0_mm, eps)
    predict = predict or (lambda m, *args: m.predict(*args))
    base = predict(model, pressure, D0_mm, t0_mm, eps)
    force = np.where(base.valid, base.force_N, np.nan)
    own_std = np.asarray(base.extras.get("force_std_N", np.zeros_like(force)), dtype=float)
    sample = draws(nominal, tolerances, n_draws, np.random.default_rng(seed))
    if method not in ("auto", "linearised"):
        raise ValueError(f"method={method!r} is invalid: expected 'auto' or 'linearised'")
    if method == "auto" and monte_carlo_ready(model, sample):
        spread = _surrogate_spread(model, pressure, sample)
        u = np.sqrt(spread**2 + own_std**2)
        return Band(force, np.where(np.isfinite(force), u, np.nan), "monte-carlo", n_draws,
                    seed)
    contributions = sensitivities(model, pressure, nominal, tolerances, force, rebuild,
                                  predict)
    u2 = own_std**2 + sum(c**2 for c in contributions.values())
    return Band(force, np.sqrt(u2), "linearised")


def sensitivities(model: ForceModel, pressure_bar, nominal: dict, tolerances: Tolerances,
                  force_N, rebuild: Callable[..., ForceModel] | None = None,
                  predict: Callable[..., Prediction] | None = None) -> dict[str, np.ndarray]:
    """``c_i u_i`` [N] per toleranced input: the sensitivity coefficient times the standard
    uncertainty, signed (negative: the force falls as the input grows), by central differences
    over +- u_i (one-sided where one side leaves the model's range: a surrogate's box edge, eps
    below 0). ``nominal`` (:func:`nominal_parameters`) may hold arrays of D0 and t0 (many
    candidates at once); ``force_N`` is the nominal force. Inputs the model cannot vary
    (``rebuild`` missing or refusing) are left out.
    """
    predict = predict or (lambda m, *args: m.predict(*args))
    out = {}
    for name, u_i in tolerances.standard().items():
        shifted = []
        for sign in (1.0, -1.0):
            changed = dict(nominal)
            if name == "rubber_fraction":
                changed["C10_MPa"] = changed["C10_MPa"] * (1 + sign * u_i)
                changed["C01_MPa"] = changed["C01_MPa"] * (1 + sign * u_i)
            else:
                changed[name] = changed[name] + sign * u_i
            shifted.append(_predict_changed(model, pressure_bar, changed, nominal, rebuild,
                                            predict))
        if shifted[0] is None:
            continue
        central = (shifted[0] - shifted[1]) / 2
        one_sided = np.where(np.isfinite(shifted[0]), shifted[0] - force_N,
                             force_N - shifted[1])
        out[name] = np.where(np.isfinite(central), central, one_sided)
    return out


def monte_carlo_ready(model, sample: dict[str, np.ndarray]) -> bool:
    """Whether ``model`` is a surrogate taking every input of ``sample`` with every draw in
    its training box."""
    inputs, box = getattr(model, "inputs", None), getattr(model, "box", None)
    if not inputs or not box or not (hasattr(model, "predictor") or hasattr(model, "estimator")):
        return False
    for name, values in sample.items():
        if name not in inputs:
            return False
        lo, hi = box[name]
        if values.min() < lo or values.max() > hi:
            return False
    return True


def surrogate_draws(model, pressure_bar, sample: dict[str, np.ndarray]) -> np.ndarray:
    """The surrogate's force [N] at every pressure (rows) for every draw (columns) of
    :func:`mkm.fem.tolerances.draws`, in one call of its estimator (the draws must lie in its
    box: :func:`monte_carlo_ready`)."""
    pressure = np.atleast_1d(np.asarray(pressure_bar, dtype=float))
    n = len(next(iter(sample.values())))
    columns = []
    for name in model.inputs:
        if name == "pressure_bar":
            columns.append(np.repeat(pressure, n))
        else:
            columns.append(np.tile(np.broadcast_to(sample[name], n), pressure.size))
    X = np.column_stack(columns)
    predictor = getattr(model, "predictor", None)  # the fitted arrays, without scikit-learn
    force = predictor.predict(X, False) if predictor is not None else model.estimator.predict(X)
    force = force[0] if isinstance(force, tuple) else force
    return np.asarray(force, dtype=float).reshape(pressure.size, n)


def _surrogate_spread(model, pressure: np.ndarray, sample: dict[str, np.ndarray]) -> np.ndarray:
    """Standard deviation over the draws of the surrogate's force, per pressure."""
    force = surrogate_draws(model, pressure, sample)
    lo, hi = model.box["pressure_bar"]
    return np.where((pressure >= lo) & (pressure <= hi), force.std(axis=1, ddof=1), np.nan)


def _predict_changed(model, pressure, changed: dict, nominal: dict, rebuild, predict):
    """The force with ``changed`` inputs (NaN where not valid), or None when ``model`` cannot be
    rebuilt with a changed parameter."""
    varied = [k for k in ("L0_mm", "theta0_deg", "C10_MPa", "C01_MPa")
              if changed[k] != nominal[k]]
    target = model
    if varied:
        if rebuild is None:
            return None
        try:
            target = rebuild(**{k: changed[k] for k in varied})
        except (TypeError, ValueError):
            return None  # the model does not take that parameter (Equation 2 has no rubber)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # a point off the box is answered NaN just below
            out = predict(target, pressure, changed["D0_mm"], changed["t0_mm"],
                          changed["eps"])
    except ValueError:
        return np.full(np.shape(pressure), np.nan)
    return np.where(out.valid, out.force_N, np.nan)


def with_band(prediction: Prediction, band: Band) -> Prediction:
    """``prediction`` with ``force_u_N`` [N] among its extras (how it was got:
    :meth:`Band.record`)."""
    prediction.extras["force_u_N"] = np.broadcast_to(band.force_u_N, prediction.force_N.shape)
    return prediction
