"""The force-model interface shared by every predictor of the project.

A force model is "pressures and geometry in, forces out": :meth:`ForceModel.predict` takes the
supply pressure in bar, the tube's inner diameter ``D0_mm`` and wall thickness ``t0_mm`` in mm and
the shortening ratio ``eps`` (a fraction), broadcasts them with numpy, and returns a
:class:`Prediction` holding the force in N with a per-point validity flag. The report, the dataset
builder and the speed/accuracy study loop over any list of models through this interface only.

Subclasses implement :meth:`ForceModel._forces` on already validated, broadcast float arrays;
input validation, broadcasting and timing live here, once.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, ClassVar

import numpy as np

from mkm.fem.limits import LIMITS, check_wall, limit_text, outside

if TYPE_CHECKING:
    import pandas as pd

    from mkm.fem.muscle import Muscle

INPUTS = ("pressure_bar", "D0_mm", "t0_mm", "eps")
MAX_PRESSURE_BAR = LIMITS["pressure_bar"][1]
MAX_D0_MM = LIMITS["D0_mm"][1]


@dataclass(frozen=True)
class Domain:
    """Closed box of inputs a model claims to be valid on (``(low, high)`` per input)."""

    pressure_bar: tuple[float, float] = (0.0, np.inf)
    D0_mm: tuple[float, float] = (0.0, np.inf)
    t0_mm: tuple[float, float] = (0.0, np.inf)
    eps: tuple[float, float] = (0.0, 1.0)

    def contains(self, pressure_bar, D0_mm, t0_mm, eps, rtol: float = 1e-9) -> np.ndarray:
        """Boolean array, True where every input lies inside the box (with round-off slack)."""
        inside = True
        for name, value in zip(INPUTS, (pressure_bar, D0_mm, t0_mm, eps), strict=True):
            lo, hi = getattr(self, name)
            slack = rtol * max(abs(lo), abs(hi) if np.isfinite(hi) else 0.0, 1.0)
            inside = inside & (np.asarray(value) >= lo - slack) & (np.asarray(value) <= hi + slack)
        return np.asarray(inside, dtype=bool)

    def as_dict(self) -> dict[str, list[float]]:
        return {name: [float(v) for v in getattr(self, name)] for name in INPUTS}


@dataclass
class Prediction:
    """Forces of one model call, broadcast to a common shape.

    ``force_N`` is NaN where the model could not produce a number (a solve that did not converge);
    where the model produced a number outside its own validity (Equation 2 beyond eps_max) the
    number is kept and ``valid`` is False. Consumers must honour ``valid``.
    """

    model: str
    params: dict[str, Any]
    pressure_bar: np.ndarray
    D0_mm: np.ndarray
    t0_mm: np.ndarray
    eps: np.ndarray
    force_N: np.ndarray
    valid: np.ndarray
    converged: np.ndarray
    seconds: float
    extras: dict[str, np.ndarray] = field(default_factory=dict)

    def columns(self) -> dict[str, np.ndarray]:
        """One array per column, one value per point: the inputs, ``force_N``, ``valid``,
        ``converged`` and the extras."""
        columns = {name: np.ravel(getattr(self, name)) for name in INPUTS}
        columns["force_N"] = np.ravel(self.force_N)
        columns["valid"] = np.ravel(self.valid)
        columns["converged"] = np.ravel(self.converged)
        for key, value in self.extras.items():
            columns[key] = np.ravel(np.broadcast_to(value, self.force_N.shape))
        return columns

    def to_frame(self) -> pd.DataFrame:
        """One row per point (:meth:`columns`)."""
        import pandas as pd  # here, not at import: the command line starts without pandas

        return pd.DataFrame(self.columns())


def validate_inputs(pressure_bar, D0_mm, t0_mm, eps) -> tuple[np.ndarray, ...]:
    """Broadcast the four inputs to float arrays, raising ``ValueError`` on unphysical values.

    Messages name the bad value and what was expected, so the CLI can print them as they are.
    """
    try:
        values = [np.asarray(v, dtype=float) for v in (pressure_bar, D0_mm, t0_mm, eps)]
    except (TypeError, ValueError) as exc:
        raise ValueError(f"inputs must be numbers: {exc}") from None
    try:
        arrays = np.broadcast_arrays(*values)
    except ValueError as exc:
        raise ValueError(f"inputs do not broadcast to a common shape: {exc}") from None
    P, D0, t0, e = (np.array(a) for a in arrays)
    for name, a in zip(INPUTS, (P, D0, t0, e), strict=True):
        bad = ~np.isfinite(a)
        if bad.any():
            raise ValueError(f"{name}={a[bad].flat[0]:g} is not a finite number")
    for name, a in zip(INPUTS, (P, D0, t0, e), strict=True):
        _check(a, outside(name, a), name, limit_text(name))
    bad = t0 >= D0 / 2
    if bad.any():
        i = np.flatnonzero(bad.ravel())[0]
        check_wall(float(D0.flat[i]), float(t0.flat[i]))
    return P, D0, t0, e


def _check(values: np.ndarray, bad: np.ndarray, name: str, expected: str) -> None:
    if bad.any():
        raise ValueError(f"{name}={values[bad].flat[0]:g} is invalid: {expected}")


class ForceModel:
    """Base class of every force predictor (closed-form, FE, surrogate).

    Subclasses set ``name`` and ``domain``, store their parameters in ``__init__`` and implement
    :meth:`_forces`. ``params()`` returns what a result needs for its provenance.
    """

    name: ClassVar[str] = "abstract"
    domain: Domain = Domain()
    #: The model has a threshold pressure (a wall to stretch before the held muscle pulls):
    #: its theta0 is calibrated on the force slope by default (fem.calibration)
    has_threshold: ClassVar[bool] = False

    def params(self) -> dict[str, Any]:
        return {}

    @property
    def calibration_key(self) -> str:
        """Entry of ``fem/calibration.json`` holding this model's default theta0."""
        return self.name

    def predict(self, pressure_bar, D0_mm, t0_mm, eps) -> Prediction:
        """Forces [N] for pressures [bar] and geometry (``D0_mm``, ``t0_mm``, ``eps`` fraction)."""
        P, D0, t0, e = validate_inputs(pressure_bar, D0_mm, t0_mm, eps)
        start = time.perf_counter()
        out = self._forces(P, D0, t0, e)
        seconds = time.perf_counter() - start
        force = np.asarray(out.pop("force_N"), dtype=float).reshape(P.shape)
        converged = np.asarray(out.pop("converged", np.isfinite(force)), dtype=bool)
        converged = np.broadcast_to(converged, P.shape).copy()
        valid = np.asarray(out.pop("valid", True), dtype=bool)
        valid = np.broadcast_to(valid, P.shape) & converged & np.isfinite(force)
        extras = {k: np.broadcast_to(np.asarray(v), P.shape).copy() for k, v in out.items()}
        return Prediction(
            model=self.name, params=self.params(), pressure_bar=P, D0_mm=D0, t0_mm=t0, eps=e,
            force_N=force, valid=valid, converged=converged, seconds=seconds, extras=extras,
        )

    def predict_muscle(self, muscle: Muscle, pressure_bar) -> Prediction:
        """Forces [N] of ``muscle`` held at its ``eps``, at ``pressure_bar`` [bar].

        The model must be this muscle's (``make_model(name, muscle=muscle)``): a length, angle or
        rubber the muscle knows and the model was built with another is refused, not silently
        predicted for another muscle.
        """
        params = self.params()
        for key, value in muscle.model_parameters().items():
            built = params.get(key)
            if isinstance(built, int | float) and not np.isclose(built, value, rtol=1e-12,
                                                                  atol=0.0):
                raise ValueError(f"{key}={value:g} of the muscle differs from the {self.name} "
                                 f"model's {key}={built:g}: expected a model built for this "
                                 "muscle (make_model(..., muscle=muscle))")
        return self.predict(pressure_bar, muscle.D0_mm, muscle.t0_mm, muscle.eps)

    def _forces(self, P, D0, t0, eps) -> dict[str, np.ndarray]:
        """Return at least ``{"force_N": ...}``; optionally ``valid``, ``converged`` and extras."""
        raise NotImplementedError

    def __repr__(self) -> str:
        args = ", ".join(f"{k}={v!r}" for k, v in self.params().items())
        return f"{type(self).__name__}({args})"
