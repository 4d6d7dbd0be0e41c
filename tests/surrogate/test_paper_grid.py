import pandas as pd
import pytest

from mkm.surrogate.paper_grid import run_paper_grid


@pytest.mark.slow  # joblib worker processes
def test_paper_grid_does_not_depend_on_the_workers(thickwall_dataset):
    # Every fit runs on one BLAS thread, in-process or in a joblib worker: the same splits and
    # initialisations give the same nets, bit for bit (Table 2 net #1, 1 x 25 ReLU, one split).
    kwargs = {"dataset": thickwall_dataset, "seeds": 1, "variants": ("paper",), "nets": [1]}
    serial = run_paper_grid(jobs=1, **kwargs).drop(columns="fit_seconds")
    parallel = run_paper_grid(jobs=2, **kwargs).drop(columns="fit_seconds")
    pd.testing.assert_frame_equal(serial, parallel)
    assert serial["rmse_test_N"].iloc[0] > 0
