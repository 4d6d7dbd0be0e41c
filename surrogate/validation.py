"""Honest errors: muscles held out whole, repeated splits, scikit-learn metrics.

A row held out of a sweep whose other pressures were trained on says little: the surrogate has
seen that muscle. :func:`muscle_split_scores` holds out whole muscles
(``sklearn.model_selection.GroupShuffleSplit`` with one group per FE sweep) and scores the refit
on them: RMSE and largest error (``sklearn.metrics``), the worst muscle's largest |Err%| (the
paper's Equation 7) and, for a surrogate with a predictive std, the fraction of held-out points
within 1 and 2 std. :func:`split_scores` is the paper's own 80/20 split by row (its 27-net
study). One split misleads (the same configuration's held-out RMSE varies several-fold from seed
to seed): :func:`summarise` gives the median and spread over many.
"""

from __future__ import annotations

import inspect
import time

import numpy as np

from mkm.fem.paper import equation7_err_pct
from mkm.surrogate.coverage import coverage

# scikit-learn is imported by the functions that use it: loading a saved surrogate reads
# MUSCLE_SPLITS (the cache's key) and must not wait for scikit-learn to load.
TEST_SIZE = 0.2  # the paper's 80/20 split
CV_FOLDS = 5  # Regression Learner's default cross-validation
MUSCLE_SPLITS = 10  # muscle-held-out splits of a trained surrogate's metrics


def rmse(a, b) -> float:
    """Root mean squared error (the paper's Equation 6) [unit of the inputs]; broadcast."""
    from sklearn.metrics import root_mean_squared_error

    a, b = np.broadcast_arrays(np.asarray(a, dtype=float), np.asarray(b, dtype=float))
    return float(root_mean_squared_error(a.ravel(), b.ravel()))


def fit_params(estimator, threshold_pressure_bar) -> dict:
    """The FE threshold for estimators whose ``fit`` takes it (the per-muscle slope models)."""
    if threshold_pressure_bar is None:
        return {}
    if "threshold_pressure_bar" in inspect.signature(estimator.fit).parameters:
        return {"threshold_pressure_bar": threshold_pressure_bar}
    return {}


def predict_with_std(estimator, X):
    """``(force, std or None)`` of a fitted estimator."""
    try:
        force, std = estimator.predict(X, return_std=True)
    except TypeError:  # no predictive std
        return estimator.predict(X), None
    return force, std


def std_coverage(estimator, X, y) -> dict[str, float]:
    """Share of the points of ``(X, y)`` within 1, 2 and 3 of ``estimator``'s predictive std
    (``within_1std``, ...): 68.27, 95.45 and 99.73 % for a calibrated one."""
    force, std = predict_with_std(estimator, X)
    return {f"within_{k}std": coverage(y - force, std, float(k)) for k in (1, 2, 3)}


def worst_err_pct(y_true, y_pred, groups) -> float:
    """Largest |Err%| (Equation 7, per muscle sweep) over the muscles in ``groups``."""
    worst = 0.0
    for g in np.unique(groups):
        rows = groups == g
        if np.max(np.abs(y_true[rows]), initial=0.0) > 0:
            worst = max(worst, float(np.max(np.abs(equation7_err_pct(y_true[rows],
                                                                     y_pred[rows])))))
    return worst


def held_out_scores(y_true, y_pred, std, groups) -> dict:
    """Scores of predictions on held-out muscles [N, %]."""
    from sklearn.metrics import max_error

    scores = {"rmse_test_N": rmse(y_true, y_pred), "max_abs_test_N": float(max_error(y_true,
                                                                                   y_pred)),
              "worst_err_pct": worst_err_pct(y_true, y_pred, groups)}
    if std is not None:
        scores["within_1std"] = coverage(y_true - y_pred, std, 1.0)
        scores["within_2std"] = coverage(y_true - y_pred, std, 2.0)
    return scores


def muscle_splits(groups, n_splits: int = MUSCLE_SPLITS, seed: int = 0):
    """Train/test row indices of ``n_splits`` splits holding out 20 % of the muscles each."""
    from sklearn.model_selection import GroupShuffleSplit

    splitter = GroupShuffleSplit(n_splits=n_splits, test_size=TEST_SIZE, random_state=seed)
    return list(splitter.split(np.zeros(len(groups)), groups=groups))


def muscle_split_scores(estimator, X, y, groups, threshold_pressure_bar=None,
                        n_splits: int = MUSCLE_SPLITS, seed: int = 0, scored=None,
                        post_fit=None, progress=None, only=None) -> dict:
    """Refit ``estimator`` on each muscle-held-out split and score it on the held-out muscles.

    ``scored``: rows that may be scored (default all; the rows inside the box, where a sweep
    goes beyond it to measure slopes). Returns ``{"splits": [scores per split], "summary":
    {score: summarise(...)}, "points": (y_true, y_pred, std) of every held-out point pooled}``;
    the coverage scores also hold ``pooled``, over every held-out point of every split.
    ``post_fit``: called with each refit model (the std calibration of the trained model);
    ``progress``: called after each split (a progress bar's ``update``); ``only``: the indices
    of the splits to refit (default all; a check of a few splits of a stored result).
    """
    from sklearn.base import clone

    scored = np.ones(len(y), dtype=bool) if scored is None else np.asarray(scored, dtype=bool)
    rows, pooled = [], []
    for k, (train, test) in enumerate(muscle_splits(groups, n_splits, seed)):
        if only is not None and k not in only:
            continue
        test = test[scored[test]]
        model = clone(estimator)
        start = time.perf_counter()
        threshold = (None if threshold_pressure_bar is None
                     else threshold_pressure_bar[train])
        model.fit(X[train], y[train], **fit_params(model, threshold))
        if post_fit is not None:
            post_fit(model)
        fit_seconds = time.perf_counter() - start
        force, std = predict_with_std(model, X[test])
        rows.append({"split": k, "fit_seconds": fit_seconds, "n_test_muscles":
                     int(np.unique(groups[test]).size),
                     **held_out_scores(y[test], force, std, groups[test])})
        pooled.append((y[test], force, std))
        if progress is not None:
            progress()
    keys = [k for k in rows[0] if k not in ("split", "n_test_muscles")]
    summary = {key: summarise([r[key] for r in rows]) for key in keys}
    std_all = (None if pooled[0][2] is None else np.concatenate([p[2] for p in pooled]))
    if std_all is not None:
        error = np.concatenate([p[0] - p[1] for p in pooled])
        summary["within_1std"]["pooled"] = coverage(error, std_all, 1.0)
        summary["within_2std"]["pooled"] = coverage(error, std_all, 2.0)
    return {"splits": rows, "summary": summary,
            "points": (np.concatenate([p[0] for p in pooled]),
                       np.concatenate([p[1] for p in pooled]), std_all)}


def split_scores(estimator, X, y, seed: int, cv_folds: int = CV_FOLDS) -> dict:
    """Scores of ``estimator`` on the paper's 80/20 split by row ``seed`` [N].

    ``rmse_train_N``: refit on the training part, on itself (resubstitution);
    ``rmse_cv_N``: ``cv_folds``-fold cross-validation on the training part, pooled over folds
    (Regression Learner's "validation"), skipped when ``cv_folds`` is 0;
    ``rmse_test_N`` and ``max_abs_test_N``: the refit on the held-out 20 %.
    """
    from sklearn.base import clone
    from sklearn.metrics import max_error
    from sklearn.model_selection import KFold, cross_val_predict, train_test_split

    X_train, X_test, y_train, y_test = train_test_split(X, y, test_size=TEST_SIZE,
                                                        random_state=seed)
    scores = {"seed": seed}
    if cv_folds:
        folds = KFold(cv_folds, shuffle=True, random_state=seed)
        scores["rmse_cv_N"] = rmse(y_train, cross_val_predict(clone(estimator), X_train,
                                                              y_train, cv=folds))
    start = time.perf_counter()
    fitted = clone(estimator).fit(X_train, y_train)
    scores["fit_seconds"] = time.perf_counter() - start
    scores["rmse_train_N"] = rmse(y_train, fitted.predict(X_train))
    predicted = fitted.predict(X_test)
    scores["rmse_test_N"] = rmse(y_test, predicted)
    scores["max_abs_test_N"] = float(max_error(y_test, predicted))
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
