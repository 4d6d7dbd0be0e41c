"""Training surrogates: one kind, every kind, and the cached default surrogate.

Every trained surrogate carries its metrics: held-out RMSE over repeated 80/20 splits (the
same seeds for every kind) and, when the FE reference exists, its errors on the test muscles.
"""

from __future__ import annotations

import hashlib
import json
import warnings
from pathlib import Path

import platformdirs
from sklearn.exceptions import ConvergenceWarning
from threadpoolctl import threadpool_limits

from fem.records import file_sha256, provenance, source_version
from surrogate.estimators import BEST, make_estimator
from surrogate.model import SurrogateForceModel
from surrogate.training_data import DEFAULT_DATASET, load_training_data
from surrogate.validation import split_scores, summarise

SEEDS = tuple(range(10))  # shared by every kind, recorded in the metadata
CACHE_DIR = Path(platformdirs.user_cache_dir("mkm-bench")) / "surrogate"


def train_surrogate(kind: str = "best", dataset=DEFAULT_DATASET, seeds=SEEDS,
                    random_state: int = 0) -> SurrogateForceModel:
    """Fit ``kind`` on the whole dataset; metrics from refits on the 80/20 splits ``seeds``."""
    resolved = BEST if kind == "best" else kind
    data = load_training_data(dataset)
    estimator = make_estimator(resolved, random_state=random_state)
    with threadpool_limits(limits=1), warnings.catch_warnings():
        # ~100 rows: BLAS threads only contend (see estimators.py). A Gaussian process length
        # scale at its bound means an input it finds irrelevant, a noise level at its bound
        # noise-free FE data: expected here, not worth a warning per fit.
        warnings.filterwarnings("ignore", message="The optimal value found for dimension",
                                category=ConvergenceWarning)
        # fitrnet, which the nets copy, also stops at its IterationLimit without a warning
        warnings.filterwarnings("ignore", message="lbfgs failed to converge",
                                category=ConvergenceWarning)
        splits = [split_scores(estimator, data.X, data.y, seed, cv_folds=0) for seed in seeds]
        estimator.fit(data.X, data.y)
    metrics = {"split_seeds": list(seeds),
               "rmse_test_N": summarise([s["rmse_test_N"] for s in splits]) if splits else None,
               "max_abs_test_N": (summarise([s["max_abs_test_N"] for s in splits])
                                  if splits else None)}
    metadata = {"kind_requested": kind, "random_state": random_state,
                "dataset": data.summary(), "metrics": metrics, "trained": provenance()}
    model = SurrogateForceModel(estimator, data.domain(), resolved, metadata)
    metrics["test_muscles"] = _test_muscle_metrics(model)
    return model


def _test_muscle_metrics(model: SurrogateForceModel):
    from surrogate.testset import FE_REFERENCE, compare_on_test_muscles, read_fe_reference

    if not FE_REFERENCE.is_file():
        return None
    _, summary = compare_on_test_muscles(model, read_fe_reference())
    return summary.drop(columns=["model"]).to_dict(orient="records")


def cache_key(dataset=DEFAULT_DATASET, kind: str = BEST, seeds=SEEDS) -> str:
    """Hash of what a trained surrogate depends on: the data, the source of the surrogate and of
    every physics module it calls (materials and calibration included), library versions."""
    parts = {"dataset": file_sha256(dataset), "kind": kind, "seeds": list(seeds),
             "versions": provenance()["versions"],
             "code": source_version("surrogate.train", "surrogate.io")}
    return hashlib.sha256(json.dumps(parts, sort_keys=True).encode()).hexdigest()[:16]


def cached_model(kind: str = "best", dataset=DEFAULT_DATASET, cache_dir=None,
                 seeds=SEEDS) -> SurrogateForceModel:
    """Surrogate ``kind`` trained on ``dataset``, as a fitted ForceModel: the one surrogate cache.

    Trained on first use and kept under ``cache_dir`` (default: the user's cache folder) as
    ``<kind>-<key>`` (:func:`cache_key`), so a fresh install needs no manual step and a changed
    dataset, code or library retrains it. ``seeds``: the 80/20 splits whose refits give the
    held-out metrics (``()``: none, fit only).
    """
    from surrogate.io import load_model, save_model

    if not Path(dataset).is_file():
        load_training_data(dataset)  # raises the ValueError that says what is missing
    cache_dir = Path(cache_dir) if cache_dir is not None else CACHE_DIR
    directory = cache_dir / f"{kind}-{cache_key(dataset, kind, seeds)}"
    if (directory / "metadata.json").is_file():
        with warnings.catch_warnings():
            warnings.simplefilter("error")  # a stale cache entry is retrained, never trusted
            try:
                return load_model(directory)
            except (Warning, ValueError):
                pass
    model = train_surrogate(kind, dataset, seeds=seeds)
    try:
        save_model(model, directory)
    except OSError:  # another process saved the same model first: theirs is as good
        pass
    return model


def default_model(dataset=DEFAULT_DATASET, cache_dir=None) -> SurrogateForceModel:
    """The default (``best``) surrogate trained on ``dataset`` (see :func:`cached_model`)."""
    return cached_model("best", dataset, cache_dir)
