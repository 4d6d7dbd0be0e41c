"""A fitted surrogate as a project force model, flagging every point outside its training box."""

from __future__ import annotations

import warnings
from functools import cache

import numpy as np
from sklearn import config_context
from sklearn.gaussian_process import GaussianProcessRegressor
from sklearn.pipeline import Pipeline
from sklearn.preprocessing import FunctionTransformer
from threadpoolctl import ThreadpoolController

from fem.interface import Domain, ForceModel
from surrogate.estimators import ThresholdLinearRegressor


class OutOfDomainWarning(UserWarning):
    """A surrogate was asked for points outside the box it was trained on."""


class SurrogateForceModel(ForceModel):
    """A fitted estimator of ``[pressure_bar, D0_mm, t0_mm, eps] -> force_N`` and its domain.

    Outside ``domain`` (the box of the training inputs) the estimator's number is kept but the
    point gets ``valid=False`` and ``in_domain=False`` and an :class:`OutOfDomainWarning` is
    issued: a surrogate never extrapolates silently. Extras: ``in_domain`` always,
    ``force_std_N`` (predictive standard deviation [N]) when the estimator has one.

    Parameters
    ----------
    estimator : fitted scikit-learn regressor
    domain : fem.interface.Domain
        Training box.
    kind : str
        The estimator's kind (``surrogate.estimators.make_estimator``).
    metadata : dict, optional
        Training data hash and provenance, metrics, versions (see ``surrogate.io``).
    """

    domain: Domain

    def __init__(self, estimator, domain: Domain, kind: str, metadata: dict | None = None):
        self.estimator = estimator
        self.domain = domain
        self.kind = kind
        self.metadata = metadata or {}
        self.name = f"surrogate-{kind}"
        self._fast_predict = _validated_predictor(estimator)

    def params(self):
        dataset = self.metadata.get("dataset", {})
        return {"kind": self.kind, "dataset_sha256": dataset.get("sha256"),
                "domain": self.domain.as_dict()}

    @property
    def has_std(self) -> bool:
        """True when the estimator gives a predictive standard deviation (a Gaussian process)."""
        final = self.estimator[-1] if isinstance(self.estimator, Pipeline) else self.estimator
        return isinstance(final, GaussianProcessRegressor)

    def _forces(self, P, D0, t0, eps):
        inside = self.domain.contains(P, D0, t0, eps)
        if not inside.all():
            n_out = int((~inside).sum())
            warnings.warn(f"{n_out} of {inside.size} points lie outside the training domain "
                          f"{_describe(self.domain)}: flagged valid=False, in_domain=False",
                          OutOfDomainWarning, stacklevel=3)
        X = np.column_stack([np.ravel(a) for a in (P, D0, t0, eps)])
        out = {"valid": inside, "in_domain": inside, "converged": np.ones(P.shape, dtype=bool)}
        if self._fast_predict is not None:
            force = self._fast_predict(X)
        else:
            # validate_inputs has checked the inputs; with matrices this small BLAS threads only
            # contend (a GP's 33 points took 8 ms threaded on a busy machine, 1.2 ms on one)
            with config_context(assume_finite=True), _blas().limit(limits=1):
                if self.has_std:
                    force, std = self.estimator.predict(X, return_std=True)
                    out["force_std_N"] = std.reshape(P.shape)
                else:
                    force = self.estimator.predict(X)
        out["force_N"] = force.reshape(P.shape)
        return out


@cache
def _blas() -> ThreadpoolController:
    """One controller per process: building it scans the loaded libraries (3 ms)."""
    return ThreadpoolController()


def _validated_predictor(estimator):
    """``X -> force`` without scikit-learn's per-call checks for the physics pipeline (features
    then :class:`ThresholdLinearRegressor`), whose checks cost twice its arithmetic; None for
    other estimators. ``ForceModel.predict`` has validated the inputs already."""
    if not (isinstance(estimator, Pipeline) and len(estimator.steps) == 2):
        return None
    features, final = estimator[0], estimator[-1]
    if not (isinstance(features, FunctionTransformer) and isinstance(final,
                                                                    ThresholdLinearRegressor)):
        return None
    kw_args = features.kw_args or {}
    return lambda X: final.predict_validated(features.func(X, **kw_args))


def _describe(domain: Domain) -> str:
    return ", ".join(f"{name} in [{lo:g}, {hi:g}]" for name, (lo, hi) in domain.as_dict().items())
