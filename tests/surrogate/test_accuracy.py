"""Accuracy of the default surrogate against our FE, on the shipped dataset and reference."""

import pytest

from surrogate.testset import FE_REFERENCE, PAPER_MUSCLES, read_fe_reference
from surrogate.train import train_surrogate
from surrogate.training_data import DEFAULT_DATASET

pytestmark = pytest.mark.skipif(
    not (DEFAULT_DATASET.is_file() and FE_REFERENCE.is_file()),
    reason="needs data/mkm_dataset.csv (mkm fem dataset) and data/reference/fe_test_muscles.csv "
           "(mkm surrogate reference)")


@pytest.fixture(scope="module")
def best():
    return train_surrogate("best")


def test_reference_is_our_fe_model():
    header = FE_REFERENCE.read_text().splitlines()[1]
    assert header == '# model: "axisym"'
    assert len(read_fe_reference()) == 55


def test_default_surrogate_on_the_test_muscles(best):
    # The goal is <= 2 % largest |Err%| (Equation 7) on each of muscles I, II, III (the
    # paper reached 6.55, 7.92, 9.34 %). Measured: 0.27, 0.22, 0.09 % (IV 0.33, V 0.06 %). The
    # pin, 1 %, is 3x the worst measured value: room for FE re-runs (solver tolerances move the
    # forces by far less), yet it fails if the surrogate loses its structure.
    summary = {row["muscle"]: row for row in best.metadata["metrics"]["test_muscles"]}
    for muscle in (*PAPER_MUSCLES, "IV", "V"):
        assert summary[muscle]["max_abs_err_pct"] <= 1.0, muscle
        assert summary[muscle]["all_valid"]


def test_default_surrogate_held_out_rmse(best):
    # The paper's best net reached 7.30 N on its one split; ours must beat it on every one of
    # the 10 repeated 80/20 splits, not only in the median. Measured: 0.18-0.26 N; the pin,
    # 1 N, is 4x that and still 7x below the paper.
    assert best.metadata["metrics"]["rmse_test_N"]["max"] < 1.0
