"""The one classification of a prediction's points (mkm.fem.outcomes): a physical limit the
model names is its own outcome, never a solver's failure."""

import numpy as np
import pytest

from mkm.fem.interface import Prediction
from mkm.fem.outcomes import BRAID_LOCKS, OUTCOMES, PHYSICAL_LIMITS, classify


def sweep(force, converged, limit=None, valid=None):
    P = np.arange(len(force), dtype=float)
    extras = {} if limit is None else {"limit": np.array(limit, dtype=object)}
    return Prediction(model="m", params={}, pressure_bar=P, D0_mm=P * 0 + 30, t0_mm=P * 0 + 2,
                      eps=P * 0 + 0.2, force_N=np.array(force, dtype=float),
                      valid=np.array(converged if valid is None else valid, dtype=bool),
                      converged=np.array(converged, dtype=bool), seconds=0.0, extras=extras)


def test_a_named_braid_lock_is_its_own_outcome_and_a_stall_is_not_converged():
    # three points no state was found at: the first two where the model says the braid locks
    # before eps (no state of the muscle exists), the third a solve that failed
    pred = sweep([np.nan, np.nan, np.nan, 10.0], [False, False, False, True],
                 limit=[BRAID_LOCKS, BRAID_LOCKS, "", ""])
    assert classify(pred).tolist() == [BRAID_LOCKS, BRAID_LOCKS, "not converged", "ok"]


def test_without_a_limit_extra_an_unsolved_point_is_not_converged():
    pred = sweep([np.nan, 10.0], [False, True])
    assert classify(pred).tolist() == ["not converged", "ok"]


def test_a_missing_name_read_back_as_nan_is_no_limit():
    # a table read back (CSV) holds an empty name as NaN
    pred = sweep([np.nan, 10.0], [False, True], limit=[np.nan, np.nan])
    assert classify(pred).tolist() == ["not converged", "ok"]


def test_a_limit_outside_the_vocabulary_is_refused():
    pred = sweep([np.nan], [False], limit=["the rubber tears"])
    with pytest.raises(ValueError, match=r"limit='the rubber tears' is not a physical limit: "
                                         r"expected one of braid locks"):
        classify(pred)


def test_every_physical_limit_is_an_outcome_with_a_colour():
    from mkm.figures import STABILITY_CLASSES

    assert set(PHYSICAL_LIMITS) <= set(OUTCOMES)
    assert set(STABILITY_CLASSES) == set(OUTCOMES)
