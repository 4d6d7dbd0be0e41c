"""A fitted surrogate as a project force model that knows its domain.

The force-model contract is ``predict(pressure_bar, D0_mm, t0_mm, eps)``; the other muscle
parameters (``L0_mm``, ``theta0_deg``, ``C10_MPa``, ``C01_MPa``) are constructor parameters, as
for the FE model. For each of them a surrogate either takes it as an input (its training data
varied it; outside the training box every point is flagged) or records the one value its data
held: asking for another value is refused with a ``ValueError`` naming both, never answered.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass, replace
from functools import cache
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
from threadpoolctl import ThreadpoolController

from mkm.core.records import recorded_path
from mkm.fem.interface import INPUTS, Domain, ForceModel, Prediction
from mkm.fem.limits import PRACTICAL_RANGE, check_value, lock_eps, past_lock_text
from mkm.fem.materials import SILASTIC_S
from mkm.fem.paper import L0_MM
from mkm.surrogate.kinds import RANGE
from mkm.surrogate.training_data import PARAMETERS

if TYPE_CHECKING:
    from mkm.fem.calibration import Calibration

# Relative slack of "the same value" for a recorded parameter (a CSV round trip keeps ~1e-15).
SAME_VALUE_RTOL = 1e-9


#: why a point whose predictive std exceeds any force the muscle can develop has no answer
UNINFORMED = "without an answer: its std exceeds any force the muscle can develop there"


def uninformed_text(std_N: float, ceiling_N: float) -> str:
    """The reason column of such a point: :data:`UNINFORMED`, with both forces."""
    return (f"{UNINFORMED} (std {std_N:.3g} N, Equation 2 on the braid at rest {ceiling_N:.4g} "
            "N)")


class OutOfDomainWarning(UserWarning):
    """A surrogate was asked for points outside the box it was trained on."""


@dataclass(frozen=True)
class ErrorMargin:
    """What training measured of a surrogate's errors on muscles it did not see.

    Attributes
    ----------
    worst_abs_error_N : float or None
        Largest absolute error [N] recorded at training: the worst split of the muscle-held-out
        refits and the worst test muscle; None when neither was measured.
    within_1std, within_2std : float or None
        Median over the muscle-held-out splits of the fraction of held-out points within 1 and
        2 predictive standard deviations [fraction]; None for a surrogate without a std or
        without splits.
    measured_on : str
        Where the figures come from, for a reader (``"10 muscle-held-out splits, 5 test
        muscles"``); empty when nothing was measured.
    """

    worst_abs_error_N: float | None
    within_1std: float | None
    within_2std: float | None
    measured_on: str


def default_parameters(calibration: Calibration | None = None,
                       theta0_deg: float | None = None) -> dict[str, float]:
    """Muscle parameters used when the caller gives none: the paper's length, the calibrated
    braid angle of the FE model in ``calibration`` (None: the shipped ``fem/calibration.json``)
    and its rubber (an identified muscle's, else Silastic S). With ``theta0_deg`` given, a
    calibration without the FE's entry gives the nominal rubber, as for the physics models."""
    from mkm.fem.calibration import calibrated

    try:
        entry = calibrated("axisym", calibration)
    except ValueError:
        if theta0_deg is None:
            raise
        entry = {}
    return {"L0_mm": float(L0_MM),
            "theta0_deg": float(entry["theta0_deg"] if theta0_deg is None else theta0_deg),
            "C10_MPa": float(entry.get("C10_MPa", SILASTIC_S.C10_MPa)),
            "C01_MPa": float(entry.get("C01_MPa", SILASTIC_S.C01_MPa))}


class SurrogateForceModel(ForceModel):
    """A fitted estimator of the force [N] over ``inputs`` and the box it claims.

    Outside ``box`` the estimator's number is kept but the point gets ``valid=False`` and
    ``in_domain=False`` and an :class:`OutOfDomainWarning` is issued: a surrogate never
    extrapolates silently. Extras: ``in_domain`` always, ``force_std_N`` (predictive standard
    deviation [N]) when the estimator has one.

    Parameters
    ----------
    estimator : fitted scikit-learn regressor or None
        Of ``X`` with the columns ``inputs``; None: ``load_estimator`` gives it on first use
        of :attr:`estimator`.
    kind : str
        The estimator's kind (:mod:`mkm.surrogate.kinds`).
    inputs : sequence of str
        ``pressure_bar, D0_mm, t0_mm, eps`` and the muscle parameters the estimator takes.
    fixed : dict
        The recorded value of each muscle parameter it does not take.
    box : dict
        ``name: (low, high)`` of every input: the training box.
    metadata : dict, optional
        Training data hash and provenance, metrics, versions (see ``mkm.surrogate.io``).
    L0_mm, theta0_deg, C10_MPa, C01_MPa : float, optional
        The muscle's length [mm], braid angle at rest [deg] and rubber [MPa]. Default:
        :func:`default_parameters` (the braid angle of ``calibration``). A value
        other than the recorded one of a parameter the estimator does not take raises
        ``ValueError`` (here for a given value, at ``predict`` for a default).
    predictor : object, optional
        Predicts from the estimator's fitted arrays without scikit-learn (``predict(X,
        return_std)``, ``has_std``; see :class:`mkm.surrogate.kinds.Kind`): predictions go
        through it, the same numbers as the estimator's.
    load_estimator : callable, optional
        ``() -> estimator``, when ``estimator`` is None.
    calibration : Calibration, optional
        Where the default muscle parameters come from (None: the shipped one).
    data_file : path, optional
        Where its training data lies on this machine (the file trained on, or found unchanged
        where it was loaded): saving records it relative to the model's folder, never as
        given.
    """

    def __init__(self, estimator, kind: str, inputs, fixed: dict, box: dict,
                 metadata: dict | None = None, L0_mm: float | None = None,
                 theta0_deg: float | None = None, C10_MPa: float | None = None,
                 C01_MPa: float | None = None, *, predictor=None, load_estimator=None,
                 calibration: Calibration | None = None, data_file=None):
        if estimator is None and load_estimator is None:
            raise ValueError("SurrogateForceModel needs an estimator or load_estimator")
        self._estimator = estimator
        self._load_estimator = load_estimator
        self.predictor = predictor
        self.calibration = calibration
        self.data_file = None if data_file is None else Path(data_file)
        self.kind = kind
        self.inputs = tuple(inputs)
        self.fixed = dict(fixed)
        self.box = {k: tuple(float(x) for x in v) for k, v in box.items()}
        self.metadata = metadata or {}
        self.name = f"surrogate-{kind}"
        self.domain = Domain(**{name: self.box[name] for name in INPUTS})
        # a value outside LIMITS is a typo (C10_MPa=-1), refused as the physics models do;
        # one inside them but outside the box is a muscle, flagged where it is predicted
        self._given = {name: None if value is None else check_value(name, value)
                       for name, value in (("L0_mm", L0_mm), ("theta0_deg", theta0_deg),
                                           ("C10_MPa", C10_MPa), ("C01_MPa", C01_MPa))}
        self._resolve({k: v for k, v in self._given.items() if v is not None})  # refuse now
        self._fast_predict = (predictor.predict if predictor is not None
                              else _validated_predictor(self.estimator))

    @property
    def estimator(self):
        """The fitted estimator (read from its model file on first use if not given)."""
        if self._estimator is None:
            self._estimator = self._load_estimator()
        return self._estimator

    @property
    def parameters(self) -> dict[str, float]:
        """The muscle parameters predictions are for, defaults resolved now (its calibration
        gives the default braid angle, as for the physics models)."""
        given = {k: v for k, v in self._given.items() if v is not None}
        missing = [k for k in PARAMETERS if k not in given]
        if missing:
            defaults = default_parameters(self.calibration, given.get("theta0_deg"))
            given.update({k: defaults[k] for k in missing})
        return self._resolve(given)

    def _resolve(self, given: dict) -> dict[str, float]:
        resolved = {}
        for name, value in given.items():
            if not np.isfinite(value):
                raise ValueError(f"{name}={value!r} is not a finite number")
            recorded = self.fixed.get(name)
            if recorded is not None and not np.isclose(value, recorded, rtol=SAME_VALUE_RTOL,
                                                       atol=0.0):
                source = ("" if self._given.get(name) is not None else
                          f" (the default of the calibration {self.calibration.path})"
                          if self.calibration is not None and not self.calibration.is_shipped
                          else " (the default)")
                raise ValueError(f"{self.name} was trained at {name}={recorded:g} only: "
                                 f"{name}={value:g}{source} refused; give {name}={recorded:g}, "
                                 f"or use a surrogate trained on a design that varies {name} "
                                 "(the default surrogate)")
            resolved[name] = float(value)
        return resolved

    def with_parameters(self, calibration: Calibration | None = None,
                        **parameters) -> SurrogateForceModel:
        """The same fitted surrogate for another muscle (``L0_mm=..., theta0_deg=...``), its
        defaults from ``calibration`` (None: this one's)."""
        unknown = sorted(set(parameters) - set(PARAMETERS))
        if unknown:
            raise ValueError(f"{self.name} takes no parameter {', '.join(unknown)}: expected "
                             f"some of {', '.join(PARAMETERS)}")
        merged = {**self._given, **{k: v for k, v in parameters.items() if v is not None}}
        return SurrogateForceModel(self._estimator, self.kind, self.inputs, self.fixed,
                                   self.box, self.metadata, **merged, predictor=self.predictor,
                                   load_estimator=self._load_estimator,
                                   calibration=calibration or self.calibration,
                                   data_file=self.data_file)

    def params(self):
        dataset = self.metadata.get("dataset", {})
        try:
            parameters = self.parameters
        except ValueError as exc:  # provenance of a refused surrogate says why
            parameters = {"refused": str(exc)}
        return {"kind": self.kind, **parameters, "dataset_sha256": dataset.get("sha256"),
                "inputs": list(self.inputs), "box": {k: list(v) for k, v in self.box.items()}}

    def origin(self) -> dict:
        """What a record of what it computed names it by: its model file's sha256 (None before
        it is saved), its training's provenance and seed, and its dataset's path and sha256.
        The path is that of :attr:`data_file` as this process names it
        (:func:`~mkm.core.records.recorded_path`) where it is known (the file trained on, or
        found with the recorded sha256: a model reused from the cache was trained from another
        folder, whose path means nothing here), else the one recorded at training."""
        dataset = _mapping(self.metadata.get("dataset"))
        path = (recorded_path(self.data_file) if self.data_file is not None
                else dataset.get("path"))
        return {"sha256": self.metadata.get("sha256"), "trained": self.metadata.get("trained"),
                "random_state": self.metadata.get("random_state"),
                "dataset": {"path": path, "sha256": dataset.get("sha256")}}

    def error_margin(self) -> ErrorMargin:
        """The errors on muscles held out of training that training recorded (its metadata's
        ``metrics``: the muscle-held-out splits and the test muscles)."""
        metrics = _mapping(self.metadata.get("metrics"))
        held_out = _mapping(metrics.get("muscle_held_out"))
        worst, sources = [], []
        split_worst = _number(_mapping(held_out.get("max_abs_test_N")).get("max"))
        if split_worst is not None:
            worst.append(split_worst)
            sources.append(f"{_mapping(held_out['max_abs_test_N']).get('n', 'its')} "
                           "muscle-held-out splits")
        tests = metrics.get("test_muscles")  # a dict says why they were not evaluated
        errors = [e for e in (_number(_mapping(m).get("max_abs_error_N"))
                              for m in (tests if isinstance(tests, list) else [])) if e is not None]
        if errors:
            worst.append(max(errors))
            sources.append(f"{len(errors)} test muscles")
        return ErrorMargin(max(worst) if worst else None,
                           _number(_mapping(held_out.get("within_1std")).get("median")),
                           _number(_mapping(held_out.get("within_2std")).get("median")),
                           ", ".join(sources))

    @property
    def has_std(self) -> bool:
        """True when the estimator gives a predictive standard deviation."""
        if self.predictor is not None:
            return self.predictor.has_std
        from sklearn.gaussian_process import GaussianProcessRegressor
        from sklearn.pipeline import Pipeline

        from mkm.surrogate import muscle_gp

        final = self.estimator[-1] if isinstance(self.estimator, Pipeline) else self.estimator
        return isinstance(final, GaussianProcessRegressor | muscle_gp.MuscleThresholdGP)

    def answered(self, prediction: Prediction) -> Prediction:
        """``prediction`` with no number where it has no answer: a point outside the training
        box keeps ``valid=False`` and gets NaN for ``force_N`` (an empty cell in a CSV) and
        ``force_std_N``, and the extra ``reason`` names what lies outside (``eps=0.25 not in
        [0, 0.2]``; empty where the point is answered). The estimator's number there is an
        extrapolation that a table or a script would take for a prediction."""
        unanswered = ~np.asarray(prediction.valid, dtype=bool)
        outside = self.parameters_outside()
        reason = np.full(prediction.force_N.shape, "", dtype=object)
        inputs = {name: np.broadcast_to(getattr(prediction, name), reason.shape)
                  for name in INPUTS}
        locked = np.broadcast_to(self._past_lock(inputs["eps"], self.parameters), reason.shape)
        std = prediction.extras.get("force_std_N")
        in_domain = np.broadcast_to(prediction.extras.get("in_domain", False), reason.shape)
        ceiling = self._ceiling_N(inputs["pressure_bar"], inputs["D0_mm"], inputs["t0_mm"])
        for index in np.ndindex(reason.shape):  # a scalar prediction's index is ()
            if not unanswered[index]:
                continue
            if (std is not None and in_domain[index]
                    and float(std[index]) > ceiling[index] > 0):
                reason[index] = uninformed_text(float(std[index]), float(ceiling[index]))
                continue
            parts = []
            for name, values in inputs.items():
                lo, hi = self.box[name]
                slack = 1e-9 * max(abs(lo), abs(hi), 1.0)  # as Domain.contains allows
                if not lo - slack <= float(values[index]) <= hi + slack:
                    parts.append(f"{name}={float(values[index]):g} not in [{lo:g}, {hi:g}]")
            said = [past_lock_text(self.parameters["theta0_deg"])] if locked[index] else []
            if parts + outside or not said:
                said.append("outside the training domain: " + "; ".join(parts + outside))
            reason[index] = "; ".join(said)
        extras = {**prediction.extras, "reason": reason}
        if "force_std_N" in extras:
            extras["force_std_N"] = np.where(unanswered, np.nan, extras["force_std_N"])
        return replace(prediction, force_N=np.where(unanswered, np.nan, prediction.force_N),
                       extras=extras)

    def parameters_outside(self, parameters=None) -> list[str]:
        """The muscle parameters outside the training box, as ``name=value not in [lo, hi]``."""
        parameters = parameters or self.parameters
        out = []
        for name in self.inputs[len(INPUTS):]:
            lo, hi = self.box[name]
            value = parameters[name]
            slack = 1e-9 * max(abs(lo), abs(hi), 1.0)
            if not lo - slack <= value <= hi + slack:
                out.append(f"{name}={value:g} not in [{lo:g}, {hi:g}]")
        return out

    def _ceiling_N(self, P, D0, t0) -> np.ndarray:
        """More than any force the muscle can develop at ``P`` [N]: Equation 2 on the braid's
        diameter at rest (no rubber, no shortening); infinite without a braid angle."""
        theta0 = self.parameters.get("theta0_deg")
        if theta0 is None:
            return np.full(np.shape(P), np.inf)
        from mkm.fem.eq2 import chou_hannaford

        return chou_hannaford(P, np.asarray(D0) + 2 * np.asarray(t0), 0.0, float(theta0))

    def _past_lock(self, eps, parameters) -> np.ndarray:
        """Where ``eps`` is at or past the braid lock of the muscle's angle: no muscle was
        trained there (the practical range's eps box reaches the lock of its lowest angle, far
        past that of a steeper one, where the estimator would extrapolate a number)."""
        theta0 = parameters.get("theta0_deg")
        if theta0 is None:
            return np.zeros(np.shape(eps), dtype=bool)
        return np.asarray(eps, dtype=float) >= lock_eps(float(theta0))

    def _range_hint(self, P, D0, t0, eps, parameters) -> str:
        """Where every point lies in the practical range and this is not the range's kind: the
        spec that answers there (empty otherwise)."""
        if self.kind == RANGE:
            return ""
        P, D0, t0, eps = (a.ravel() for a in np.broadcast_arrays(
            *(np.asarray(a, dtype=float) for a in (P, D0, t0, eps))))
        fixed = {name: parameters.get(name) for name in PARAMETERS}
        if (not np.all(np.isfinite(P))
                or any(PRACTICAL_RANGE.violations(pressure_bar=p) for p in (P.min(), P.max()))
                or any(PRACTICAL_RANGE.violations(D0_mm=d, t0_mm=t, eps=e, **fixed)
                       for d, t, e in set(zip(D0, t0, eps, strict=True)))):
            return ""
        return (f"; these points lie in the practical range, where the spec "
                f"surrogate:kind={RANGE} (or auto) answers")

    def _forces(self, P, D0, t0, eps):
        parameters = self.parameters  # refuses a recorded parameter at another value
        in_box = self.domain.contains(P, D0, t0, eps)
        locked = self._past_lock(eps, parameters)
        inside = in_box & ~locked
        outside = self.parameters_outside(parameters)
        if outside:
            inside = np.zeros(P.shape, dtype=bool)
        if not inside.all():
            n_out = int((~inside).sum())
            why = "; ".join(
                _inputs_outside(self.domain, (P, D0, t0, eps)) + outside
                + ([past_lock_text(parameters["theta0_deg"])] if locked.any() else []))
            warnings.warn(f"{n_out} of {inside.size} points lie outside the training domain "
                          f"({why}): flagged valid=False, in_domain=False"
                          + self._range_hint(P, D0, t0, eps, parameters),
                          OutOfDomainWarning, stacklevel=3)
        columns = [np.ravel(a) for a in (P, D0, t0, eps)]
        columns += [np.full(P.size, parameters[n]) for n in self.inputs[len(INPUTS):]]
        X = np.column_stack(columns)
        out = {"valid": inside, "in_domain": inside, "converged": np.ones(P.shape, dtype=bool)}
        if self._fast_predict is not None:  # numpy on a few points: no thread pool wakes up
            result = self._fast_predict(X, self.has_std)
        else:
            from sklearn import config_context

            # validate_inputs has checked the inputs; with matrices this small BLAS threads
            # only contend (a GP's few points took several times as long threaded on a busy
            # machine as on one thread)
            with config_context(assume_finite=True), _blas().limit(limits=1):
                result = self.estimator.predict(X, **({"return_std": True} if self.has_std
                                                      else {}))
        force, std = result if isinstance(result, tuple) else (result, None)
        out["force_N"] = np.asarray(force).reshape(P.shape)
        if std is not None:
            out["force_std_N"] = np.asarray(std).reshape(P.shape)
            # a std beyond any force the muscle can pull: the estimator knows nothing there
            # (no FE muscle of its training reached that state: a thick wall locks its braid
            # short of Equation 2's eps_max), whatever its mean
            ceiling = self._ceiling_N(P, D0, t0)
            uninformed = inside & (ceiling > 0) & (out["force_std_N"] > ceiling)
            if uninformed.any():
                warnings.warn(f"{int(uninformed.sum())} of {inside.size} points: "
                              f"{UNINFORMED}: flagged valid=False", OutOfDomainWarning,
                              stacklevel=3)
                out["valid"] = inside & ~uninformed
        return out


@cache
def _blas() -> ThreadpoolController:
    """One controller per process: building it scans the loaded libraries (3 ms)."""
    return ThreadpoolController()


def _validated_predictor(estimator):
    """``(X, return_std) -> force[, std]`` without scikit-learn's per-call checks (which cost
    more than the arithmetic) for the threshold-linear estimators; None for the others.
    ``ForceModel.predict`` has validated the inputs already."""
    from sklearn.pipeline import Pipeline
    from sklearn.preprocessing import FunctionTransformer

    # modules, not names, imported: the code version reads this file, and resolving a name
    # would load the module (and scikit-learn) where only the predictor is needed
    from mkm.surrogate import muscle_gp, threshold_linear

    if isinstance(estimator, muscle_gp.MuscleThresholdGP):
        return estimator.predict_validated
    if not (isinstance(estimator, Pipeline) and len(estimator.steps) == 2):
        return None
    features, final = estimator[0], estimator[-1]
    if not (isinstance(features, FunctionTransformer)
            and isinstance(final, threshold_linear.ThresholdLinearRegressor)):
        return None
    kw_args = features.kw_args or {}
    return lambda X, _std=False: final.predict_validated(features.func(X, **kw_args))


def _mapping(value) -> dict:
    return value if isinstance(value, dict) else {}


def _number(value) -> float | None:
    """``value`` as a float if it is a finite number, else None (metrics a model does not have)."""
    if isinstance(value, int | float) and not isinstance(value, bool) and np.isfinite(value):
        return float(value)
    return None


def _inputs_outside(domain: Domain, values) -> list[str]:
    """The inputs outside ``domain``, each as ``name=value not in [lo, hi]`` (``name=a-b``: the
    span of its values outside), with the slack :meth:`Domain.contains` allows. The inputs are
    validated non-negative, so the hyphen reads as a span."""
    out = []
    for name, value in zip(INPUTS, values, strict=True):
        lo, hi = getattr(domain, name)
        value = np.asarray(value, dtype=float).ravel()
        slack = 1e-9 * max(abs(lo), abs(hi) if np.isfinite(hi) else 0.0, 1.0)
        beyond = value[(value < lo - slack) | (value > hi + slack)]
        if beyond.size:
            low, high = float(beyond.min()), float(beyond.max())
            shown = f"{low:g}" if low == high else f"{low:g}-{high:g}"
            out.append(f"{name}={shown} not in [{lo:g}, {hi:g}]")
    return out
