"""The Gaussian processes' shipped hyperparameters (surrogate/data/gp_kernels.json): a process
fitted at recorded hyperparameters is the process the optimiser finds, looked up by what its
optimum depends on, and the shipped file is that of today's datasets."""

import json

import numpy as np
import pytest

from mkm.core.records import file_sha256
from mkm.surrogate.gp import KEY_DIGITS, fit_gaussian_process, kernel_key, recording_kernels
from mkm.surrogate.train import KERNELS_PATH, cached_model, kind_files


def _points(n=40, seed=3):
    rng = np.random.default_rng(seed)
    Z = rng.uniform(-1.0, 1.0, (n, 3))
    return Z, np.sin(2.0 * Z[:, 0]) + Z[:, 1] ** 2 + 0.01 * rng.standard_normal(n)


def test_a_process_fitted_at_recorded_hyperparameters_is_the_searched_one():
    Z, y = _points()
    with recording_kernels() as found:
        searched, post = fit_gaussian_process(Z, y, random_state=0, restarts=0)
    assert searched.optimizer is not None and list(found) == [kernel_key(Z, y, 0, 0)]
    reused, again = fit_gaussian_process(Z, y, random_state=0, restarts=0, kernels=found)
    assert reused.optimizer is None  # no search
    for name in post:  # the same numbers, bit for bit
        assert np.array_equal(post[name], again[name]), name
    # another seed (or number of restarts) is another search: nothing to reuse
    assert kernel_key(Z, y, 0, 1) not in found
    other, _ = fit_gaussian_process(Z, y, random_state=1, restarts=0, kernels=found)
    assert other.optimizer is not None


def test_a_recording_searches_whatever_is_known():
    Z, y = _points()
    with recording_kernels() as first:
        fit_gaussian_process(Z, y, random_state=0, restarts=0)
    wrong = {key: [0.0] * len(theta) for key, theta in first.items()}
    with recording_kernels() as second:
        gp, _ = fit_gaussian_process(Z, y, random_state=0, restarts=0, kernels=wrong)
    assert gp.optimizer is not None and second == first


def test_the_key_reads_the_points_to_eight_significant_digits():
    Z, y = _points()
    key = kernel_key(Z, y, 0, 1)
    # another platform's last bits of a log or a root search: the same optimum
    assert kernel_key(Z * (1 + 4 * np.finfo(float).eps), y, 0, 1) == key
    moved = Z.copy()
    moved[7, 1] *= 1 + 10.0 ** (2 - KEY_DIGITS)
    assert kernel_key(moved, y, 0, 1) != key
    assert kernel_key(Z, y[::-1], 0, 1) != key


def test_the_shipped_kernels_are_those_of_todays_datasets():
    # a changed dataset (or inputs a kind builds differently) makes the first training search
    # again: regenerate with tools/record_gp_kernels.py
    shipped = json.loads(KERNELS_PATH.read_text(encoding="utf-8"))
    assert shipped["provenance"]["command"] == "tools/record_gp_kernels.py"
    for kind, record in shipped["kinds"].items():
        dataset = kind_files(kind)[0]
        assert (record["dataset"], record["sha256"]) == (dataset.name, file_sha256(dataset))
        assert record["processes"] == 2


@pytest.mark.slow  # the default surrogate (shared by the session)
def test_the_default_surrogate_is_fitted_at_the_shipped_kernels():
    source = cached_model("best").metadata["gp_kernels_from"]
    assert source["path"] == KERNELS_PATH.name and source["processes"] == 2
    assert source["sha256"] == file_sha256(KERNELS_PATH)
