"""The FE meshes' bound at the scale of a call (:mod:`mkm.mesh_errors`), by hand on a
threshold-linear force."""

import numpy as np
import pandas as pd
import pytest

from mkm.mesh_errors import SAFETY, mesh_model, point_bound_pct

A_N_PER_BAR, P_STAR_BAR = 100.0, 0.4
GEOMETRY = (35.0, 2.5, 0.1)


def force(P):
    return A_N_PER_BAR * np.maximum(np.asarray(P) - P_STAR_BAR, 0.0)


def test_a_single_point_above_the_threshold_has_a_larger_bound_than_the_sweep():
    # error a P* A + b F: 0.0075 x 0.4 x 100 + 0.001 F newtons. At 0.41 bar (F 1 N) that is
    # 0.301 N, relative to the force there; over the sweep 0.5-2.5 bar, relative to its largest
    # force less its own error (210 - 0.51 N).
    a, b = 0.0075, 0.001
    P = np.array([0.5, 1.5, 2.5])
    sweep = point_bound_pct(force(P), P, np.full(3, P_STAR_BAR), np.tile(GEOMETRY, (3, 1)), a, b)
    error = a * P_STAR_BAR * A_N_PER_BAR + b * force(P)
    np.testing.assert_allclose(sweep, 100 * error / (210.0 - error[-1]))
    single = point_bound_pct(force([0.41]), [0.41], [P_STAR_BAR], [GEOMETRY], a, b)
    assert single[0] == pytest.approx(100 * 0.301 / 1.0)  # the scale never below 1 N
    assert single[0] > 10 * sweep.max()


def test_zero_force_points_far_below_or_near_the_threshold():
    # Below the threshold by more than a P* (0.003 bar): both meshes say 0 N, bound 0. Within it
    # the fine force may have started: the muscle's slope from its points above; with none, no
    # bound.
    a, b = 0.0075, 0.001
    P = np.array([0.2, 0.399, 1.4])
    bound = point_bound_pct(force(P), P, np.full(3, P_STAR_BAR), np.tile(GEOMETRY, (3, 1)), a, b)
    assert bound[0] == 0.0
    shift_N = a * P_STAR_BAR * A_N_PER_BAR
    assert bound[1] == pytest.approx(100 * shift_N / (100.0 - shift_N - b * 100.0))
    alone = point_bound_pct([0.0], [0.399], [P_STAR_BAR], [GEOMETRY], a, b)
    assert np.isinf(alone[0])


def test_mesh_model_is_the_largest_over_the_muscles_times_the_safety(tmp_path):
    path = tmp_path / "mesh_errors.csv"
    pd.DataFrame([
        {"mesh": "coarse", "shift_per_threshold": 0.002, "relative_error": 0.001,
         "fe_failed": False},
        {"mesh": "coarse", "shift_per_threshold": 0.004, "relative_error": 0.0005,
         "fe_failed": False},
        {"mesh": "coarse", "shift_per_threshold": np.nan, "relative_error": np.nan,
         "fe_failed": True},
        {"mesh": "medium", "shift_per_threshold": 0.001, "relative_error": 0.0002,
         "fe_failed": False}]).to_csv(path, index=False)
    model = mesh_model(str(path))
    assert model["coarse"] == pytest.approx((SAFETY * 0.004, SAFETY * 0.001))
    assert model["medium"] == pytest.approx((SAFETY * 0.001, SAFETY * 0.0002))
    assert mesh_model(str(tmp_path / "absent.csv")) == {}
