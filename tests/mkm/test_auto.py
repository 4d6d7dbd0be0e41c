"""The auto model picks the cheapest model whose study error meets the tolerance (fem/auto.py)."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from mkm.auto import AutoModel, error_bounds, explain, read_model_errors
from mkm.fem.ladder import make_model
from mkm.registry import build_spec

PRESSURES = (0.0, 1.25, 2.5)
MUSCLES = {"M1": (35.0, 2.5, 0.05), "M2": (40.0, 3.0, 0.15)}
# Equation 2 with theta0 = 50 deg: eps_max = 1 - 1/(sqrt(3) cos 50 deg) = 0.102, so it is
# invalid at M2 (eps 0.15) whatever the table says about its error.
EQ2 = "eq2:theta0_deg=50"
# |Err%| per predictor at pressures 0, 1.25, 2.5 (same for both muscles); costs in s per force
TABLE = {"eq2-inner": (EQ2, (5.0, 5.0, 5.0), 1e-6),
         "thickwall": ("thickwall", (1.0, 1.0, 3.0), 1e-5),
         # the fallback: the coarse mesh keeps the test fast; its spec is what auto builds
         "axisym-fine": ("axisym:mesh=coarse", (0.0, 0.0, 0.0), 0.1)}


def auto(**params) -> AutoModel:
    return AutoModel(build=build_spec, **params)


@pytest.fixture(scope="module")
def table_path(tmp_path_factory):
    rows = [{"predictor": name, "family": "x", "spec": spec, "muscle": m,
             "role": "test", "D0_mm": d, "t0_mm": t, "eps": e, "pressure_bar": p,
             "force_ref_N": 100.0, "force_N": 100.0, "valid": True, "err_pct": err,
             "seconds_per_point": cost}
            for name, (spec, errs, cost) in TABLE.items()
            for m, (d, t, e) in MUSCLES.items() for p, err in zip(PRESSURES, errs, strict=True)]
    path = tmp_path_factory.mktemp("auto") / "model_errors.csv"
    path.write_text(pd.DataFrame(rows).to_csv(index=False))  # hand-made study table
    return str(path)


def test_error_bound_is_the_worst_of_the_bracketing_study_points(table_path):
    table = read_model_errors(table_path)
    # M1 at 1.0 bar: bracket 0..1.25 -> 1 %; at 2.0 bar: bracket 1.25..2.5 -> 3 %
    bound = error_bounds(table, "thickwall", [1.0, 2.0, 1.25], 35.0, 2.5, 0.05)
    np.testing.assert_allclose(bound, [1.0, 3.0, 1.0])
    # 3 bar is beyond the study's pressures; D0 80 mm is far from every study muscle
    assert np.isnan(error_bounds(table, "thickwall", [3.0], 35.0, 2.5, 0.05)).all()
    assert np.isnan(error_bounds(table, "thickwall", [1.0], 80.0, 2.5, 0.05)).all()


def test_picks_the_cheapest_model_meeting_the_tolerance(table_path):
    P = np.array([1.0, 1.0])
    loose = auto(tolerance=0.10, table=table_path).predict(P, 35.0, 2.5, 0.05)
    assert set(loose.extras["model_used"]) == {"eq2-inner"}  # 5 % <= 10 %, and cheapest
    np.testing.assert_allclose(loose.force_N, make_model("eq2", theta0_deg=50.0).predict(
        P, 35.0, 2.5, 0.05).force_N)
    tight = auto(tolerance=0.02, table=table_path).predict(P, 35.0, 2.5, 0.05)
    assert set(tight.extras["model_used"]) == {"thickwall"}  # eq2's 5 % > 2 %
    np.testing.assert_allclose(tight.extras["error_bound_pct"], 1.0)
    np.testing.assert_allclose(tight.force_N, make_model("thickwall").predict(
        P, 35.0, 2.5, 0.05).force_N)
    assert tight.valid.all()


def test_an_invalid_cheap_model_is_skipped(table_path):
    pred = auto(tolerance=0.10, table=table_path).predict([1.0], 40.0, 3.0, 0.15)
    assert pred.extras["model_used"].tolist() == ["thickwall"]  # eq2 beyond its eps_max


def test_falls_back_to_the_fe_model_per_point(table_path):
    # 2.0 bar: thickwall's bound is 3 % > 2 %; D0 80 mm: no study muscle near
    P, D0 = np.array([1.0, 2.0, 1.0]), np.array([35.0, 35.0, 80.0])
    pred = auto(tolerance=0.02, table=table_path, per_point=True).predict(P, D0, 2.5, 0.05)
    assert pred.extras["model_used"].tolist() == ["thickwall", "axisym-fine", "axisym-fine"]
    assert np.isnan(pred.extras["error_bound_pct"][1:]).all()
    fe = make_model("axisym", mesh="coarse").predict(P[1:], D0[1:], 2.5, 0.05)
    np.testing.assert_allclose(pred.force_N[1:], fe.force_N)
    text = explain(pred)
    assert "auto: thickwall for 1 of 3 points" in text and "<= 2%" in text
    assert "auto: axisym-fine for 2 of 3 points" in text


def test_one_model_for_the_whole_sweep_by_default(table_path):
    # muscle M1 over 1 and 2 bar: thickwall meets 2 % at 1 bar (bound 1 %) but not at 2 bar
    # (3 %), so the sweep as a whole goes to the FE model; at 5 % Equation 2 (bound 5 % at every
    # pressure) is the cheapest that holds over the whole sweep
    P = np.array([1.0, 2.0])
    tight = auto(tolerance=0.02, table=table_path).predict(P, 35.0, 2.5, 0.05)
    assert tight.extras["model_used"].tolist() == ["axisym-fine", "axisym-fine"]
    loose = auto(tolerance=0.035, table=table_path).predict(P, 35.0, 2.5, 0.05)
    assert loose.extras["model_used"].tolist() == ["thickwall", "thickwall"]  # 3 % <= 3.5 %
    np.testing.assert_allclose(loose.extras["error_bound_pct"], [1.0, 3.0])
    # eq2 qualifies by its bound at M1 and M2, but is invalid at M2's eps: the sweep over both
    # muscles cannot use it, not even at M1
    both = auto(tolerance=0.10, table=table_path).predict([1.0, 1.0], [35.0, 40.0],
                                                               [2.5, 3.0], [0.05, 0.15])
    assert both.extras["model_used"].tolist() == ["thickwall", "thickwall"]
    assert "per_point" in both.params and both.params["per_point"] is False


def test_bad_tolerance_and_missing_table_are_clear_errors(table_path, tmp_path):
    with pytest.raises(ValueError, match=r"tolerance=1\.5 is invalid"):
        auto(tolerance=1.5, table=table_path).predict(1.0, 35.0, 2.5, 0.05)
    with pytest.raises(ValueError, match="run `mkm study`"):
        auto(table=str(tmp_path / "none.csv")).predict(1.0, 35.0, 2.5, 0.05)


@pytest.mark.slow  # solves the fine mesh
def test_cli_solve_auto_says_what_it_used(capsys):
    """`mkm fem solve --model auto` on the committed study table (fem/model_errors.csv)."""
    from io import StringIO

    from mkm.cli import main

    code = main(["fem", "solve", "--model", "auto", "--tolerance", "2%", "--D0", "35", "--t0",
                 "2.5", "--eps", "0.05"])
    out, err = capsys.readouterr()
    assert code == 0
    rows = pd.read_csv(StringIO(out), comment="#")
    assert len(rows) == 11 and rows["valid"].all()
    candidates = set(read_model_errors()["predictor"])
    assert set(rows["model_used"]) <= candidates
    chosen = rows[rows["model_used"] != "axisym-fine"]
    assert (chosen["error_bound_pct"] <= 2.0).all()
    counts = [int(line.split(" for ")[1].split(" of ")[0]) for line in err.splitlines()
              if line.startswith("auto: ")]
    assert sum(counts) == 11
