"""The FE meshes' bound at the scale of a call (:mod:`mkm.mesh_errors`), by hand on a
threshold-linear force, and the shipped table near the braid lock."""

import json

import numpy as np
import pandas as pd
import pytest

from mkm.core.records import sidecar_path
from mkm.fem.limits import lock_eps
from mkm.fem.sampling import LOCK_FRACTION, draw_muscles
from mkm.mesh_errors import (
    MAX_END_RESOLUTION,
    MESH_ERRORS_FILE,
    MIN_REGION_MUSCLES,
    MIN_SCALE_N,
    NEAR_LOCK_RANGE,
    PRESSURES_BAR,
    SAFETY,
    SLENDERNESS_REACH,
    end_resolution,
    mesh_model,
    near_lock_seed,
    point_bound_pct,
)
from mkm.registry import build_spec

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


def test_mesh_model_is_the_largest_over_the_muscles_as_slender_times_the_safety(tmp_path):
    # 40 stout muscles of L0/t0 25-1000, their errors growing with it (a mesh's elements flatten
    # as the wall gets longer and thinner), and the shipped table's slender thin tube (5.8
    # bending lengths at the clamp on the coarse mesh, 2.9 on the medium), beyond the end zone
    # the coarse bound is claimed for. A muscle's a and b: the largest over those at most 1.5
    # times as slender, at least the 30 least slender, times SAFETY.
    path = tmp_path / "mesh_errors.csv"
    L0 = np.linspace(50.0, 1000.0, 40)
    t0 = np.where(L0 < 500.0, 2.0, 1.0)
    slender = L0 / t0
    rows = [{"D0_mm": 40.0, "t0_mm": t, "L0_mm": length, "mesh": mesh,
             "shift_per_threshold": 2e-6 * s, "relative_error": 1e-6 * s, "fe_failed": False}
            for t, length, s in zip(t0, L0, slender, strict=True) for mesh in ("coarse", "medium")]
    rows += [{"D0_mm": 40.0, "t0_mm": 2.0, "L0_mm": 300.0, "mesh": "coarse",
              "shift_per_threshold": np.nan, "relative_error": np.nan, "fe_failed": True},
             {"D0_mm": 5.361, "t0_mm": 0.5815, "L0_mm": 839.3, "mesh": "coarse",
              "shift_per_threshold": 0.017, "relative_error": 0.072, "fe_failed": False},
             {"D0_mm": 5.361, "t0_mm": 0.5815, "L0_mm": 839.3, "mesh": "medium",
              "shift_per_threshold": 0.0022, "relative_error": 0.0032, "fe_failed": False}]
    pd.DataFrame(rows).to_csv(path, index=False)
    model = mesh_model(str(path))
    for mesh in ("coarse", "medium"):  # the slender tube: only the medium mesh resolves its end
        assert len(model[mesh].slenderness) == 40 + (mesh == "medium")
    ordered = np.sort(slender)
    for L0_mm, t0_mm in ((300.0, 2.0), (900.0, 1.0), (50.0, 2.0)):
        limit = max(SLENDERNESS_REACH * L0_mm / t0_mm, ordered[MIN_REGION_MUSCLES - 1])
        largest = ordered[ordered <= limit].max()
        a, b = model["coarse"].coefficients(L0_mm, t0_mm)
        assert (a, b) == pytest.approx((SAFETY * 2e-6 * largest, SAFETY * 1e-6 * largest))
    assert model["medium"].largest == pytest.approx((SAFETY * 0.0022, SAFETY * 0.0032))
    assert model["coarse"].largest == pytest.approx((SAFETY * 2e-3, SAFETY * 1e-3))
    assert mesh_model(str(tmp_path / "absent.csv")) == {}


def test_the_shipped_bound_is_smaller_for_a_stout_wall_than_for_a_long_thin_one():
    # the paper's muscle (L0/t0 about 100) against a 0.6 mm wall 800 mm long: the medium mesh's
    # largest relative error over the range (0.32 %, such a wall) is not the stout wall's
    for mesh, bound in mesh_model().items():
        stout = bound.coefficients(282.0, 2.5)
        thin = bound.coefficients(800.0, 0.6)
        assert thin == pytest.approx(bound.largest)
        assert stout[0] < thin[0] / 3 and stout[1] < thin[1] / 3, mesh


def test_the_shipped_table_measured_near_the_braid_lock():
    # A mesh shifts the threshold most near the braid lock, where a draw of the whole range
    # puts few muscles: the shipped a and b come from a table with its recorded share drawn
    # there, eps at 85-95 % of each muscle's lock. Half of such muscles pull below 8 bar (30 of
    # a draw of 60): at least a quarter must be scored, or the share measured little.
    table = pd.read_csv(MESH_ERRORS_FILE)
    info = json.loads(sidecar_path(MESH_ERRORS_FILE).read_text())
    muscles = table.drop_duplicates("muscle")
    near = muscles[muscles["draw"] == "near lock"]
    assert info["near_lock_draw"]["seed"] == near_lock_seed(info["draw"]["seed"])
    assert len(near) == info["near_lock_draw"]["muscles"] == round(
        info["near_lock_share"] * len(muscles)) > 0
    eps_per_lock = near["eps"] / lock_eps(near["theta0_deg"])
    low, high = NEAR_LOCK_RANGE.eps_per_lock
    assert eps_per_lock.between(low, high * LOCK_FRACTION).all()
    pulling = table[(table["draw"] == "near lock") & ~table["fe_failed"].astype(bool)
                    & (table["threshold_bar"] < PRESSURES_BAR[-1])]
    assert pulling["muscle"].nunique() >= len(near) // 4


@pytest.mark.slow  # the fine mesh
def test_a_muscle_near_the_lock_within_the_shipped_bound():
    # Call 36 of benchmarks/bench_auto.py --range practical --calls 80 --seed 20261206: eps at
    # 0.89 of the lock, a 0.51 mm wall 932 mm long, the fine threshold at 6.374 bar. The medium
    # mesh puts it at 6.394 (0.31 % off) and the coarse at 6.430 (0.89 %), so the sweep's error
    # (1.22 % and 3.46 % of its largest force) is mostly the threshold's shift: each must be
    # within the bound auto states from the shipped table.
    muscle = draw_muscles(80, 20261206).muscles[36]
    assert muscle.eps / lock_eps(muscle.theta0_deg) > NEAR_LOCK_RANGE.eps_per_lock[0]
    P = np.array(PRESSURES_BAR[1:])  # the benchmark's sweep, 0.5-8 bar
    rubber = {k: getattr(muscle, k) for k in ("L0_mm", "theta0_deg", "C10_MPa", "C01_MPa")}
    geometry = (muscle.D0_mm, muscle.t0_mm, muscle.eps)
    fine = np.ravel(build_spec("axisym:mesh=fine", **rubber).predict(P, *geometry).force_N)
    for mesh, bound_of in mesh_model().items():
        a, b = bound_of.coefficients(muscle.L0_mm, muscle.t0_mm)
        if end_resolution(muscle.D0_mm, muscle.t0_mm, muscle.L0_mm, mesh) > MAX_END_RESOLUTION:
            continue  # the coarse mesh here (4.03): no bound claimed, auto does not use it
        pred = build_spec(f"axisym:mesh={mesh}", **rubber).predict(P, *geometry)
        force = np.ravel(pred.force_N)
        error_pct = 100 * np.max(np.abs(force - fine)) / max(np.max(fine), MIN_SCALE_N)
        bound = point_bound_pct(force, P, np.ravel(pred.extras["threshold_pressure_bar"]),
                                np.tile(geometry, (len(P), 1)), a, b)
        assert error_pct <= bound.max(), mesh
