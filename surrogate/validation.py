"""Accuracy over repeated 80/20 splits shared by every model (one split misleads: the same
configuration's held-out RMSE varies several-fold from seed to seed)."""

from __future__ import annotations

import time

import numpy as np
from sklearn.base import clone
from sklearn.model_selection import KFold, cross_val_predict, train_test_split

TEST_SIZE = 0.2  # the paper's 80/20 split
CV_FOLDS = 5  # Regression Learner's default cross-validation


def rmse(a, b) -> float:
    """Root mean squared error (the paper's Equation 6) [unit of the inputs]."""
    return float(np.sqrt(np.mean((np.asarray(a) - np.asarray(b)) ** 2)))


def split_scores(estimator, X, y, seed: int, cv_folds: int = CV_FOLDS) -> dict:
    """Scores of ``estimator`` on the 80/20 split ``seed`` [N].

    ``rmse_train_N``: refit on the training part, on itself (resubstitution);
    ``rmse_cv_N``: ``cv_folds``-fold cross-validation on the training part, pooled over folds
    (Regression Learner's "validation"), skipped when ``cv_folds`` is 0;
    ``rmse_test_N`` and ``max_abs_test_N``: the refit on the held-out 20 %.
    """
    X_train, X_test, y_train, y_test = train_test_split(X, y, test_size=TEST_SIZE,
                                                        random_state=seed)
    scores = {"seed": seed}
    if cv_folds:
        folds = KFold(cv_folds, shuffle=True, random_state=seed)
        scores["rmse_cv_N"] = rmse(cross_val_predict(clone(estimator), X_train, y_train,
                                                     cv=folds), y_train)
    start = time.perf_counter()
    fitted = clone(estimator).fit(X_train, y_train)
    scores["fit_seconds"] = time.perf_counter() - start
    scores["rmse_train_N"] = rmse(fitted.predict(X_train), y_train)
    residual = fitted.predict(X_test) - y_test
    scores["rmse_test_N"] = rmse(residual, 0.0)
    scores["max_abs_test_N"] = float(np.max(np.abs(residual)))
    final = fitted[-1] if hasattr(fitted, "steps") else fitted
    final = getattr(final, "regressor_", final)
    final = final[-1] if hasattr(final, "steps") else final
    if hasattr(final, "n_iter_"):
        scores["n_iter"] = int(final.n_iter_)
    return scores


def summarise(values) -> dict:
    """Median and spread (10th-90th percentile, min, max) of repeated-split scores."""
    v = np.asarray(values, dtype=float)
    return {"median": float(np.median(v)), "p10": float(np.percentile(v, 10)),
            "p90": float(np.percentile(v, 90)), "min": float(v.min()), "max": float(v.max()),
            "n": int(v.size)}
