"""The design search's margin takes auto's factor of each surrogate kind (no model is trained:
the margin depends only on the kind and the prediction's std)."""

from types import SimpleNamespace

import numpy as np
import pytest

from mkm.auto import RANGE_STD_FACTOR, STD_FACTOR
from mkm.design.box_search import std_factor, surrogate_uncertainty
from mkm.surrogate import kinds

STD_N = np.array([2.0, 10.0, 40.0])


def _surrogate(kind):
    margin = SimpleNamespace(within_2std=0.95, worst_abs_error_N=None)
    return SimpleNamespace(kind=kind, error_margin=lambda: margin)


@pytest.mark.parametrize("kind, factor", [(kinds.RANGE, 6.0), (kinds.BEST, 3.0)])
def test_a_range_surrogate_design_takes_autos_wider_margin(kind, factor):
    # the practical range's std is heavy-tailed per call: auto bounds it by 6 std, and the
    # design searched with 3 (its own number) where the same surrogate answered
    assert (RANGE_STD_FACTOR, STD_FACTOR) == (6.0, 3.0)
    prediction = SimpleNamespace(force_N=np.array([100.0, 300.0, 900.0]),
                                 extras={"force_std_N": STD_N})
    margin, told = surrogate_uncertainty(_surrogate(kind), prediction, 250.0)
    np.testing.assert_allclose(margin, factor * STD_N)
    assert told == (f"{factor:g} x the surrogate's predictive standard deviation; held-out "
                    "muscles within 2 std: 95 %")
    assert std_factor(_surrogate(kind)) == factor
