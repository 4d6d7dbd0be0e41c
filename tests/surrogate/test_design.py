import numpy as np
import pandas as pd
import pytest

from mkm.fem.materials import SILASTIC_S
from mkm.surrogate.design import (
    BOX,
    DESIGN_DATASET,
    MUSCLE_PARAMETERS,
    corners,
    parse_sub_box,
    random_muscles,
    refinement_muscles,
    space_filling,
)
from mkm.surrogate.training_data import load_training_data


def test_box_is_the_issues():
    assert BOX["pressure_bar"] == (0.0, 2.5) and BOX["L0_mm"] == (150.0, 400.0)
    assert BOX["theta0_deg"] == (28.0, 38.0)
    assert BOX["C10_MPa"] == pytest.approx((0.5 * SILASTIC_S.C10_MPa, 1.5 * SILASTIC_S.C10_MPa))


def test_corners_are_an_orthogonal_fractional_factorial():
    # 2^(7-3) resolution IV: every column balanced, every pair of columns orthogonal, and the
    # 16 runs distinct corners of the box.
    signs = corners() * 2 - 1
    assert signs.shape == (16, 7) and set(np.unique(signs)) == {-1.0, 1.0}
    np.testing.assert_array_equal(signs.sum(axis=0), 0)
    np.testing.assert_array_equal(signs.T @ signs, 16 * np.eye(7))
    assert len({tuple(r) for r in signs}) == 16


def test_space_filling_is_a_latin_hypercube_beside_the_corners():
    muscles = space_filling(48, seed=3)
    assert list(muscles["origin"]).count("corner") == 16
    lhs = muscles[muscles["origin"] == "lhs"]
    for name in MUSCLE_PARAMETERS:
        lo, hi = BOX[name]
        assert muscles[name].between(lo, hi).all()
        # one point in each of the 32 strata of every input (rounding to 6 digits aside)
        strata = np.floor((lhs[name] - lo) / (hi - lo) * 32 - 1e-6).clip(0, 31)
        assert sorted(strata.astype(int)) == list(range(32)), name
    np.testing.assert_array_equal(space_filling(48, seed=3)[list(MUSCLE_PARAMETERS)],
                                  muscles[list(MUSCLE_PARAMETERS)])  # seeded


def test_small_budget_has_no_corners():
    assert set(space_filling(8)["origin"]) == {"lhs"}


def test_random_muscles_follow_their_seed():
    a, b = random_muscles(5, seed=1), random_muscles(5, seed=1)
    np.testing.assert_array_equal(a[list(MUSCLE_PARAMETERS)], b[list(MUSCLE_PARAMETERS)])
    assert not np.allclose(random_muscles(5, seed=2)["D0_mm"], a["D0_mm"])


def test_sub_box_is_parsed_inside_the_box():
    assert parse_sub_box("D0_mm=40:50, eps=0:0.08") == {"D0_mm": (40.0, 50.0), "eps": (0.0, 0.08)}
    for bad, says in (("D0_mm=40:60", "30 <= LO < HI <= 50"), ("eps=0.1:0.05", "LO < HI"),
                      ("P=0:1", "NAME one of"), ("L0_mm=150", "NAME=LO:HI"),
                      ("L0_mm=a:200", "numbers")):
        with pytest.raises(ValueError, match=says):
            parse_sub_box(bad)


def test_refinement_fills_its_sub_box_only():
    sub_box = {"D0_mm": (40.0, 50.0), "L0_mm": (150.0, 225.0)}
    muscles = refinement_muscles(12, sub_box, seed=2)
    assert set(muscles["origin"]) == {"refine"} and len(muscles) == 12
    for name in MUSCLE_PARAMETERS:
        lo, hi = sub_box.get(name, BOX[name])
        assert muscles[name].between(lo, hi).all(), name
        # a Latin hypercube of the sub-box: one muscle in each of its 12 strata
        strata = np.floor((muscles[name] - lo) / (hi - lo) * 12 - 1e-6).clip(0, 11)
        assert sorted(strata.astype(int)) == list(range(12)), name


@pytest.mark.skipif(not DESIGN_DATASET.is_file(), reason="no shipped design")
def test_shipped_design_is_what_the_sidecar_says():
    data = load_training_data(DESIGN_DATASET)
    info = data.provenance
    n, extra = info["design"]["muscles"], info["design"]["adaptive"]
    refine, sub_box = info["design"]["refine"], info["design"]["refine_box"]
    assert info["fe_budget_muscles"] == n + refine + extra and info["mesh"] == "fine"
    assert data.inputs == ("pressure_bar", *MUSCLE_PARAMETERS)
    # the muscles of the seeded space-filling design and of its refinement are all in, every
    # one the FE solved (rows of failed points are dropped; the sidecar lists such muscles),
    # then the adaptive
    failed = info["muscles_with_failed_points"]
    assert data.n_muscles == n + refine + extra - len(failed)
    expected = space_filling(n, info["design"]["seed"])
    if refine:
        expected = pd.concat([expected, refinement_muscles(refine, parse_sub_box(",".join(
            f"{k}={lo}:{hi}" for k, (lo, hi) in sub_box.items())), info["design"]["seed"])])
    n += refine
    first = np.array([np.flatnonzero(data.groups == g)[0] for g in np.unique(data.groups)])
    got = {tuple(r) for r in data.X[first, 1:]}
    want = {tuple(r) for r in expected[list(MUSCLE_PARAMETERS)].to_numpy()}
    assert len(want - got) <= len(failed) and len(got - want) == extra - sum(
        f >= n for f in failed)


@pytest.mark.skipif(not DESIGN_DATASET.is_file(), reason="no shipped design")
def test_a_training_set_is_recorded_by_a_path_of_no_machine(tmp_path, monkeypatch):
    # a model file and every result nesting its training set (train.path) named the checkout
    # that trained it: /work/main/surrogate/data/mkm_design.csv
    monkeypatch.chdir(tmp_path)
    assert load_training_data(DESIGN_DATASET).summary()["path"] == DESIGN_DATASET.name
    (tmp_path / "sets").mkdir()
    for suffix in (".csv", ".json"):
        copy = (tmp_path / "sets" / DESIGN_DATASET.name).with_suffix(suffix)
        copy.write_bytes(DESIGN_DATASET.with_suffix(suffix).read_bytes())
    assert load_training_data(tmp_path / "sets" / DESIGN_DATASET.name).path == \
        f"sets/{DESIGN_DATASET.name}"


@pytest.mark.slow  # GP fits
def test_adaptive_muscles_go_where_the_surrogate_is_unsure():
    # Trained on the space-filling muscles only, the picks have a larger predictive std of the
    # force at 2.5 bar than the candidates on average, and are distinct.
    from mkm.surrogate.design import adaptive_muscles
    from mkm.surrogate.kinds import make_estimator
    from mkm.surrogate.training_data import ALL_INPUTS

    data = load_training_data(DESIGN_DATASET)
    estimator = make_estimator("muscle-gp", data.inputs).fit(
        data.X, data.y, threshold_pressure_bar=data.threshold_pressure_bar)
    picks = adaptive_muscles(estimator, 5, seed=1, candidates=300)
    assert len(picks.drop_duplicates()) == 5
    pool = random_muscles(300, 1)

    def relative_std(muscles):
        X = np.column_stack([np.full(len(muscles), 2.5)] + [muscles[p] for p in ALL_INPUTS[1:]])
        force, std = estimator.predict(X, return_std=True)
        return std / np.maximum(force, 1.0)

    assert relative_std(picks).mean() > 2 * relative_std(pool).mean()
    # from a given pool (the practical range's draw, weighed at its top pressure): picks of it,
    # named after it
    from mkm.surrogate.design import practical_muscles

    practical = practical_muscles(100, 2)
    chosen = adaptive_muscles(estimator, 3, pool=practical, pressure_top_bar=8.0,
                              reach_min_bar=0.5)
    assert set(chosen["origin"]) == {"adaptive practical seed 2"}
    drawn = {tuple(r) for r in practical[list(MUSCLE_PARAMETERS)].to_numpy()}
    assert {tuple(r) for r in chosen[list(MUSCLE_PARAMETERS)].to_numpy()} <= drawn
    assert len(chosen.drop_duplicates()) == 3


def test_practical_adaptive_picks_at_most_the_muscles_drawn(tmp_path):
    from mkm.surrogate.design import build_practical_set

    with pytest.raises(ValueError, match="--adaptive 6 is invalid"):
        build_practical_set(5, 1, tmp_path / "a.csv", adaptive=6)


def test_practical_muscles_lie_in_the_practical_range_and_follow_their_seed():
    from mkm.fem.limits import PRACTICAL_RANGE
    from mkm.surrogate.design import practical_muscles

    muscles = practical_muscles(50, 4)
    assert muscles.equals(practical_muscles(50, 4))
    assert not muscles.equals(practical_muscles(50, 5))
    assert set(muscles["origin"]) == {"practical seed 4"}
    for m in muscles.itertuples():
        # rounded to 6 decimals as the CSV holds them: the upper bounds hold to that precision
        values = {p: getattr(m, p) for p in ("D0_mm", "t0_mm", "L0_mm", "theta0_deg",
                                             "C10_MPa", "C01_MPa", "eps")}
        assert PRACTICAL_RANGE.violations(**{k: v * (1 - 1e-6) if k in ("t0_mm", "eps", "C01_MPa")
                                             else v for k, v in values.items()}) == [], values
