"""Prediction bands: how uncertain a model's force is, given the tolerances the muscle is made to.

A muscle is made to tolerances: D0, t0 and L0 by the tube's maker, eps read from the threaded
rod's scale, theta0 fitted (its spread across fits), the rubber's constants from one material
test. :class:`Tolerances` holds them as +- bounds; each input is taken as uniformly distributed
within its bound (a part made to tolerance lies anywhere inside it; standard uncertainty
bound / sqrt 3), independent of the others, except C10 and C01, which come from one fit and move
together (``rubber_fraction`` scales both).

:func:`force_band` propagates them to a model's force at given pressures (GUM Supplement 1,
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

import math
import re
import warnings
from collections.abc import Callable
from dataclasses import asdict, dataclass, fields

import numpy as np

from mkm.fem.interface import ForceModel, Prediction
from mkm.fem.muscle import LIMITS

SQRT3 = math.sqrt(3.0)
#: what ``--tolerance`` calls each field
SHORT_NAMES = {"D0": "D0_mm", "t0": "t0_mm", "L0": "L0_mm", "eps": "eps",
               "theta0": "theta0_deg", "rubber": "rubber_fraction"}
MAX_RUBBER_FRACTION = 0.5


@dataclass(frozen=True)
class Tolerances:
    """+- bounds of a muscle's inputs (uniform within them).

    Parameters
    ----------
    D0_mm : float
        Inner diameter [mm]; default 0.3 (an extruded silicone tube's +-1 % at 30 mm).
    t0_mm : float
        Wall thickness [mm]; default 0.1.
    L0_mm : float
        Length at rest [mm]; default 1.0 (cut to length with a rule).
    eps : float
        Shortening ratio (a fraction); default 0.004 (the threaded rod's scale read to 1 mm on
        282 mm).
    theta0_deg : float
        Braid angle at rest [deg]; default 1.0 (the spread of a fitted braid angle).
    rubber_fraction : float
        C10 and C01 together, a fraction of their value; default 0 (the calibrated rubber).
    """

    D0_mm: float = 0.3
    t0_mm: float = 0.1
    L0_mm: float = 1.0
    eps: float = 0.004
    theta0_deg: float = 1.0
    rubber_fraction: float = 0.0

    def __post_init__(self):
        for f in fields(self):
            value = getattr(self, f.name)
            high = MAX_RUBBER_FRACTION if f.name == "rubber_fraction" else \
                0.5 * LIMITS[f.name][1] if f.name != "eps" else 0.5
            if isinstance(value, bool) or not isinstance(value, int | float) \
                    or not 0.0 <= value <= high:
                raise ValueError(f"tolerance {f.name}={value!r} is invalid: expected a +- bound "
                                 f"from 0 to {high:g}")

    @classmethod
    def parse(cls, text: str, base: Tolerances | None = None) -> Tolerances:
        """``D0=0.3,t0=0.1,theta0=1,rubber=10%`` (mm, mm, deg, a percentage or a fraction);
        names not given keep ``base``'s value (default: none, 0)."""
        values = asdict(base) if base is not None else {f.name: 0.0 for f in fields(cls)}
        for item in filter(None, (part.strip() for part in str(text).split(","))):
            name, sep, value = item.partition("=")
            key = SHORT_NAMES.get(name.strip())
            if not sep or key is None:
                raise ValueError(f"tolerance {item[:40]!r} is invalid: expected NAME=VALUE with "
                                 f"NAME one of {', '.join(SHORT_NAMES)}")
            match = re.fullmatch(r"\s*([0-9.eE+-]+)\s*(%?)\s*", value)
            try:
                number = float(match.group(1)) if match else math.nan
            except ValueError:
                number = math.nan
            if not math.isfinite(number):
                raise ValueError(f"tolerance {item[:40]!r} is invalid: expected a number")
            if match.group(2):
                if key != "rubber_fraction":
                    raise ValueError(f"tolerance {item[:40]!r} is invalid: only rubber takes a "
                                     "percentage")
                number /= 100.0
            values[key] = number
        return cls(**values)

    def standard(self) -> dict[str, float]:
        """Standard uncertainties (bound / sqrt 3) of the inputs with a non-zero bound."""
        return {k: v / SQRT3 for k, v in asdict(self).items() if v > 0}


def draws(nominal: dict[str, float], tolerances: Tolerances, n: int,
          rng: np.random.Generator) -> dict[str, np.ndarray]:
    """``n`` joint draws of the muscle's inputs (``D0_mm, t0_mm, L0_mm, eps, theta0_deg,
    C10_MPa, C01_MPa``) around ``nominal``, uniform within the bounds, clipped to
    :data:`mkm.fem.muscle.LIMITS` (eps at 0 stays at 0 or above)."""
    bounds = asdict(tolerances)
    out = {}
    for name in ("D0_mm", "t0_mm", "L0_mm", "eps", "theta0_deg"):
        low, high = LIMITS[name][:2]
        # a muscle at eps = 0 cannot be stretched by the rod: draws stay physical
        out[name] = np.clip(nominal[name] + bounds[name] * rng.uniform(-1.0, 1.0, n), low,
                            high if name != "eps" else 0.99)
    factor = 1.0 + bounds["rubber_fraction"] * rng.uniform(-1.0, 1.0, n)
    out["C10_MPa"] = nominal["C10_MPa"] * factor
    out["C01_MPa"] = nominal["C01_MPa"] * factor
    return out


@dataclass
class Band:
    """A model's force [N] at the pressures, its standard uncertainty [N] and how it was got."""

    force_N: np.ndarray
    force_u_N: np.ndarray
    method: str  # "monte-carlo" | "linearised"


def nominal_parameters(model: ForceModel, D0_mm: float, t0_mm: float, eps: float
                       ) -> dict[str, float]:
    """The muscle ``model`` predicts for: the geometry given and its own parameters
    (``L0_mm``, ``theta0_deg``, ``C10_MPa``, ``C01_MPa``, where it has them)."""
    from mkm.fem.materials import SILASTIC_S
    from mkm.fem.paper import L0_MM

    params = dict(getattr(model, "parameters", None) or model.params())
    theta = params.get("theta0_deg")
    if theta is None:
        from mkm.fem.calibration import calibrated

        theta = calibrated(model.calibration_key)["theta0_deg"]
    return {"D0_mm": float(D0_mm), "t0_mm": float(t0_mm), "eps": float(eps),
            "L0_mm": float(params.get("L0_mm") or L0_MM), "theta0_deg": float(theta),
            "C10_MPa": float(params.get("C10_MPa") or SILASTIC_S.C10_MPa),
            "C01_MPa": float(params.get("C01_MPa") or SILASTIC_S.C01_MPa)}


def force_band(model: ForceModel, pressure_bar, D0_mm: float, t0_mm: float, eps: float,
               tolerances: Tolerances, rebuild: Callable[..., ForceModel] | None = None,
               n_draws: int = 1000, seed: int = 0, method: str = "auto") -> Band:
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

    Returns
    -------
    Band
        ``force_u_N`` is NaN where the nominal force is not valid, or where neither side of a
        linearised difference is.
    """
    pressure = np.atleast_1d(np.asarray(pressure_bar, dtype=float))
    nominal = nominal_parameters(model, D0_mm, t0_mm, eps)
    base = model.predict(pressure, D0_mm, t0_mm, eps)
    force = np.where(base.valid, base.force_N, np.nan)
    own_std = np.asarray(base.extras.get("force_std_N", np.zeros_like(force)), dtype=float)
    sample = draws(nominal, tolerances, n_draws, np.random.default_rng(seed))
    if method not in ("auto", "linearised"):
        raise ValueError(f"method={method!r} is invalid: expected 'auto' or 'linearised'")
    if method == "auto" and _monte_carlo_ready(model, sample):
        spread = _surrogate_spread(model, pressure, sample)
        u = np.sqrt(spread**2 + own_std**2)
        return Band(force, np.where(np.isfinite(force), u, np.nan), "monte-carlo")
    u2 = own_std**2
    for name, u_i in tolerances.standard().items():
        shifted = []
        for sign in (1.0, -1.0):
            changed = dict(nominal)
            if name == "rubber_fraction":
                changed["C10_MPa"] *= 1 + sign * u_i
                changed["C01_MPa"] *= 1 + sign * u_i
            else:
                changed[name] += sign * u_i
            shifted.append(_predict_changed(model, pressure, changed, nominal, rebuild))
        if shifted[0] is None:
            continue
        # (dF/dx u)^2, central over +-u; one-sided where one side leaves the model's range
        # (a surrogate's box edge, eps below 0)
        central = (shifted[0] - shifted[1]) / 2
        one_sided = np.where(np.isfinite(shifted[0]), shifted[0] - force, force - shifted[1])
        u2 = u2 + np.where(np.isfinite(central), central, one_sided) ** 2
    return Band(force, np.sqrt(u2), "linearised")


def _monte_carlo_ready(model, sample: dict[str, np.ndarray]) -> bool:
    inputs, box = getattr(model, "inputs", None), getattr(model, "box", None)
    if not inputs or not box or not hasattr(model, "estimator"):
        return False
    for name, values in sample.items():
        if name not in inputs:
            return False
        lo, hi = box[name]
        if values.min() < lo or values.max() > hi:
            return False
    return True


def _surrogate_spread(model, pressure: np.ndarray, sample: dict[str, np.ndarray]) -> np.ndarray:
    """Standard deviation over the draws of the surrogate's force, per pressure (one call)."""
    n = len(next(iter(sample.values())))
    columns = []
    for name in model.inputs:
        if name == "pressure_bar":
            columns.append(np.repeat(pressure, n))
        else:
            columns.append(np.tile(sample[name], pressure.size))
    X = np.column_stack(columns)
    force = np.asarray(model.estimator.predict(X), dtype=float).reshape(pressure.size, n)
    lo, hi = model.box["pressure_bar"]
    return np.where((pressure >= lo) & (pressure <= hi), force.std(axis=1, ddof=1), np.nan)


def _predict_changed(model, pressure, changed: dict, nominal: dict, rebuild):
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
            out = target.predict(pressure, changed["D0_mm"], changed["t0_mm"], changed["eps"])
    except ValueError:
        return np.full(pressure.shape, np.nan)
    return np.where(out.valid, out.force_N, np.nan)


def with_band(prediction: Prediction, band: Band) -> Prediction:
    """``prediction`` with ``force_u_N`` [N] (and the method) among its extras."""
    prediction.extras["force_u_N"] = np.broadcast_to(band.force_u_N, prediction.force_N.shape)
    return prediction
