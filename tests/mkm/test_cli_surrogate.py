import pandas as pd

from mkm.cli import main


def test_grid_small_run(thickwall_dataset, tmp_path, capsys):
    # Net #10 (1 x 25 tanh), one split, both variants, on both cores.
    out = tmp_path / "grid"
    assert main(["surrogate", "grid", "--dataset", str(thickwall_dataset), "--seeds", "1",
                 "--nets", "10", "--jobs", "2", "--out", str(out)]) == 0
    table = pd.read_csv(out / "paper_grid.csv").set_index("variant")
    assert list(table["paper_valid_N"]) == [421.37, 421.37]  # Table 2 beside ours
    assert (out / "paper_grid.md").exists() and (out / "paper_grid.png").exists()
    # The paper's failure and its fix: tanh with the response in N predicts about the mean
    # (forces spread over ~500 N, RMSE of the mean ~500 N); standardising the response fixes
    # it (measured: ~300 N against ~10 N; the 5x factor leaves room for other seeds).
    assert table.loc["paper", "rmse_test_median_N"] > 100.0
    assert table.loc["standardised", "rmse_test_median_N"] < 0.2 * table.loc[
        "paper", "rmse_test_median_N"]


def test_train_predict_test(thickwall_dataset, tmp_path, capsys):
    model = tmp_path / "models" / "physics"
    assert main(["surrogate", "train", "--dataset", str(thickwall_dataset), "--kind",
                 "physics", "--out", str(model)]) == 0
    assert "held-out RMSE" in capsys.readouterr().err
    assert main(["surrogate", "predict", "--model", str(model), "--D0", "35", "--t0", "2.5",
                 "--eps", "5%", "--pressures", "0:3:0.5"]) == 0
    captured = capsys.readouterr()
    assert '# model: "surrogate-physics"' in captured.out
    lines = [line for line in captured.out.splitlines() if not line.startswith("#")]
    assert lines[0] == "pressure_bar,D0_mm,t0_mm,eps,force_N,valid,converged,in_domain"
    assert lines[-1].startswith("3,35,2.5,0.05,") and lines[-1].endswith(",False,True,False")
    assert captured.err.startswith("mkm: warning: 1 of 7 points lie outside the training")

    reference = tmp_path / "ref.csv"
    assert main(["surrogate", "reference", "--model", "thickwall", "--out",
                 str(reference)]) == 0
    assert main(["surrogate", "test", "--model", str(model), "--reference", str(reference),
                 "--out", str(tmp_path / "test")]) == 0
    summary = pd.read_csv(tmp_path / "test" / "test_muscles.csv")
    assert len(summary) == 5 and summary["max_abs_err_pct"].max() < 1e-3


def test_bad_kind_is_a_one_line_error(thickwall_dataset, capsys):
    assert main(["surrogate", "train", "--dataset", str(thickwall_dataset), "--kind",
                 "forest"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("mkm: error: unknown surrogate kind 'forest'") and err.count("\n") == 1


def test_missing_dataset_is_a_one_line_error(tmp_path, capsys):
    assert main(["surrogate", "train", "--dataset", str(tmp_path / "no.csv")]) == 2
    assert "does not exist" in capsys.readouterr().err
