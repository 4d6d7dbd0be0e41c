import re

import numpy as np
import pandas as pd
import pytest

from mkm.core.records import read_prediction_header
from mkm.fem.ladder import make_model
from mkm.fem.paper import equation7_err_pct
from mkm.surrogate.testset import (
    TEST_MUSCLES,
    build_fe_reference,
    compare_on_test_muscles,
    read_fe_reference,
    run_test,
)


def test_percentage_error_is_equation_7():
    # (F_num - F_pred) / max(F_num) over the sweep, in %: hand-computed.
    np.testing.assert_allclose(equation7_err_pct([0.0, 100.0, 200.0], [0.0, 90.0, 210.0]),
                               [0.0, 5.0, -5.0])


def test_paper_muscles_are_the_papers():
    assert TEST_MUSCLES["I"] == (35.0, 2.5, 0.05)
    assert TEST_MUSCLES["II"] == (40.0, 3.0, 0.15)
    assert TEST_MUSCLES["III"] == (45.0, 3.5, 0.20)


@pytest.fixture(scope="module")
def thickwall_reference(tmp_path_factory):
    path = tmp_path_factory.mktemp("ref") / "fe_test_muscles.csv"
    build_fe_reference(make_model("thickwall"), path)
    return path


def test_reference_has_provenance_and_every_sweep(thickwall_reference):
    # a plain CSV; the provenance is in the JSON sidecar
    assert thickwall_reference.read_text().startswith("muscle,pressure_bar,")
    header = read_prediction_header(thickwall_reference)
    assert header["what"].startswith("FE reference") and header["model"] == "thickwall"
    assert {"params", "calibration", "versions"} <= set(header)
    table = read_fe_reference(thickwall_reference)
    assert len(table) == 11 * len(TEST_MUSCLES)
    assert list(table.groupby("muscle", sort=False).size()) == [11] * len(TEST_MUSCLES)


def test_model_against_itself_has_zero_error(thickwall_reference, tmp_path):
    model = make_model("thickwall")
    points, summary = compare_on_test_muscles(model, read_fe_reference(thickwall_reference))
    # the CSV keeps 6 significant digits: up to 5e-6 relative per force, 1e-3 % is that bound
    assert summary["max_abs_err_pct"].max() < 1e-3
    summary = run_test({"thickwall": model}, tmp_path, thickwall_reference)
    for name in ("test_muscles.csv", "test_muscles_points.csv", "test_muscles.md"):
        assert (tmp_path / name).stat().st_size > 0
    table = (tmp_path / "test_muscles.md").read_text()
    assert "| paper, 3 x 100 ReLU (its FE) | 6.55 | 7.92 | 9.34 |" in table
    # provenance beside each CSV (was none): the reference read, the model and its code
    from mkm.core.records import file_sha256, source_version

    for name in ("test_muscles.csv", "test_muscles_points.csv"):
        info = read_prediction_header(tmp_path / name)
        assert info["reference_sha256"] == file_sha256(thickwall_reference)
        assert info["models"]["thickwall"]["version"] == source_version("mkm.fem.thickwall")
        assert info["models"]["thickwall"]["params"] == model.params()
        assert {"date_utc", "command", "versions"} <= set(info)


def test_eq2_error_on_muscle_III_is_what_equation_7_says(thickwall_reference):
    # Equation 2 has no threshold: it over-predicts the thick-wall force. Check one muscle's
    # Err% against a direct computation from the two models' forces.
    reference = read_fe_reference(thickwall_reference)
    _, summary = compare_on_test_muscles(make_model("eq2"), reference)
    sweep = reference[reference["muscle"] == "III"]
    eq2 = make_model("eq2").predict(sweep["pressure_bar"], 45.0, 3.5, 0.2).force_N
    expected = np.max(np.abs(100 * (sweep["force_N"] - eq2) / sweep["force_N"].max()))
    got = summary.set_index("muscle").loc["III", "max_abs_err_pct"]
    assert got == pytest.approx(expected, rel=1e-9)


def test_points_a_model_disowns_are_not_scored(thickwall_reference):
    """`mkm surrogate test` of a surrogate trained on a smaller box scored the test muscles at
    the points it flags valid=False (outside its domain), its extrapolations: 5.73 % on muscle
    III from 11 disowned points. Only the points a model answers are scored now; a muscle it
    answers nowhere has no error."""
    from mkm.fem.thickwall import ThickWall

    class Narrow(ThickWall):  # thickwall 100 N off, disowned, beyond D0 44 mm
        def _forces(self, P, D0, t0, eps):
            out = super()._forces(P, D0, t0, eps)
            wide = D0 > 44.0
            out["force_N"] = np.where(wide, out["force_N"] + 100.0, out["force_N"])
            out["valid"] = out["valid"] & ~wide
            return out

    points, summary = compare_on_test_muscles(Narrow(), read_fe_reference(thickwall_reference))
    by = summary.set_index("muscle")
    assert by.loc["III", ["max_abs_err_pct", "rmse_N", "max_abs_error_N"]].isna().all()
    assert by.loc["III", "valid_points"] == "0/11" and not by.loc["III", "all_valid"]
    assert by.loc["I", "valid_points"] == "11/11" and by.loc["I", "max_abs_err_pct"] < 1e-3
    assert points.loc[points["muscle"] == "III", "err_pct"].isna().all()
    assert summary["max_abs_err_pct"].max() < 1e-3  # the self-reference where it answers


def test_reference_without_its_columns_is_named(thickwall_reference, tmp_path):
    # Excel's ';' export reads as one column: `mkm surrogate test --reference` ended in a
    # KeyError traceback naming 'converged'
    table = pd.read_csv(thickwall_reference, comment="#")
    path = tmp_path / "semicolons.csv"
    table.to_csv(path, index=False, sep=";", lineterminator="\r\n")
    with pytest.raises(ValueError, match=re.escape(
            f"FE reference {str(path)!r} lacks column(s) muscle, pressure_bar, D0_mm, t0_mm, "
            "eps, force_N: expected a CSV with columns muscle,pressure_bar,D0_mm,t0_mm,eps,"
            "force_N (as `mkm surrogate reference` writes it)")):
        read_fe_reference(path)
    # published forces carry no solver flags: read as they are, every point kept
    table.drop(columns=["converged", "valid"]).to_csv(path, index=False)
    assert read_fe_reference(path)["force_N"].tolist() == table["force_N"].tolist()


def test_reference_with_failed_points_is_refused(thickwall_reference, tmp_path):
    table = pd.read_csv(thickwall_reference, comment="#")
    table.loc[3, "converged"] = False
    table.to_csv(tmp_path / "bad.csv", index=False)
    with pytest.raises(ValueError, match="1 unconverged or invalid point"):
        read_fe_reference(tmp_path / "bad.csv")
