"""bench.reprocess: a new calibration applied to a run's raw volts gives the forces it implies."""

import json
from pathlib import Path

import numpy as np
import pytest

from mkm.bench.reprocess import reprocess
from mkm.bench.run import acquire
from mkm.bench.storage import load_run
from mkm.cli import main
from mkm.core.records import file_sha256


@pytest.fixture
def source(config, tmp_path):
    return load_run(acquire(config, out_root=tmp_path / "runs", notify=lambda m: None).path)


def test_forces_follow_the_new_sensitivity(config, source, tmp_path):
    # the cell was really 10 % more sensitive in N/V than configured: every tared force
    # scales by exactly 1.1, the volts and everything else stay
    new = config.replace(loadcell={"sensitivity_N_per_V": 196.133 * 1.1})
    out = load_run(reprocess(source.path, new, tmp_path / "new"))
    a, b = source.samples, out.samples
    np.testing.assert_array_equal(a["loadcell_V"], b["loadcell_V"])
    step = a["phase"] != "tare"
    np.testing.assert_allclose(b["force_N"][step], 1.1 * a["force_N"][step], rtol=2e-5)
    np.testing.assert_allclose(out.steps["force_N_mean"], 1.1 * source.steps["force_N_mean"],
                               rtol=2e-5)
    np.testing.assert_allclose(out.steps["force_N_std"], 1.1 * source.steps["force_N_std"],
                               rtol=1e-3)
    assert list(out.steps["n"]) == list(source.steps["n"])
    # from the CSV's volts (6 significant digits, 1e-8 V here; the ADC step is 1.2e-3 V)
    assert out.meta.tare["offset_V"] == pytest.approx(source.meta.tare["offset_V"], rel=1e-5)
    assert out.meta.calibration["loadcell"]["sensitivity_N_per_V"] == pytest.approx(215.7463)
    prov = out.meta.reprocessed_from
    assert prov["path"] == str(source.path.resolve())
    assert prov["samples_sha256"] == file_sha256(source.path / "samples.csv")
    assert prov["calibration"]["loadcell"]["sensitivity_N_per_V"] == 196.133
    assert out.commands.equals(source.commands)


def test_reprocess_command_prints_the_new_folder(config, source, tmp_path, capsys):
    toml = tmp_path / "new.toml"
    toml.write_text(config.text.replace("sensitivity_N_per_V = 196.133",
                                        "sensitivity_N_per_V = 200.0"))
    assert main(["reprocess", str(source.path), "--config", str(toml), "--out",
                 str(tmp_path / "new")]) == 0
    path = capsys.readouterr().out.strip()
    meta = json.loads((tmp_path / "new" / path.split("/")[-1] / "run.json").read_text())
    assert meta["calibration"]["loadcell"]["sensitivity_N_per_V"] == 200.0
    assert meta["reprocessed_from"]["path"] == str(source.path.resolve())
    assert main(["reprocess", str(tmp_path), "--config", str(toml)]) == 2  # not a run folder


def test_the_source_of_a_reprocessed_run_is_recorded_by_its_absolute_path(
        config, source, tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(source.path.parent)
    toml = tmp_path / "new.toml"
    toml.write_text(config.text)
    assert main(["reprocess", source.path.name, "--config", str(toml), "--out",
                 str(tmp_path / "new")]) == 0
    (folder,) = (tmp_path / "new").iterdir()
    recorded = json.loads((folder / "run.json").read_text())["reprocessed_from"]["path"]
    assert Path(recorded).is_absolute() and Path(recorded) == source.path.resolve()


def test_a_loadcell_only_file_recalibrates_and_the_folder_says_reprocessed(source, tmp_path,
                                                                           capsys):
    toml = tmp_path / "cell.toml"
    toml.write_text("[loadcell]\nsensitivity_N_per_V = 200.0\ncapacity_N = 1961.33\n")
    assert main(["reprocess", str(source.path), "--config", str(toml), "--out",
                 str(tmp_path / "new")]) == 0
    path = capsys.readouterr().out.strip()
    assert path.endswith("-reprocessed-SIMULATED")
    out = load_run(path)
    assert out.meta.calibration["loadcell"]["sensitivity_N_per_V"] == 200.0
    # everything but the cell is the run's own configuration, kept in its config.toml
    kept = (out.path / "config.toml").read_text()
    assert "sensitivity_N_per_V = 200.0" in kept and kept.count("[loadcell]") == 1
    assert out.meta.muscle == source.meta.muscle
    np.testing.assert_allclose(out.steps["force_N_mean"],
                               source.steps["force_N_mean"] * 200.0 / 196.133, rtol=2e-5)


def test_a_run_folder_that_does_not_exist_is_named_so(config, tmp_path, capsys):
    # was: "the run's config .../config.toml does not exist", as if --config were at fault
    toml = tmp_path / "new.toml"
    toml.write_text(config.text)
    assert main(["reprocess", str(tmp_path / "nothere"), "--config", str(toml)]) == 2
    assert capsys.readouterr().err == f"mkm reprocess: error: {tmp_path / 'nothere'}: no such " \
        "folder: expected a run folder of mkm acquire or mkm import (it holds run.json)\n"


@pytest.mark.parametrize("damage, message", [
    ("steps", r"steps\.csv is missing: expected the whole record to reprocess"),
    ("samples", r"samples\.csv holds 50 samples, run\.json counted \d+: \d+ lost: expected the "
                r"whole record to reprocess"),
])
def test_a_source_that_lost_rows_is_refused(damage, message, config, source, tmp_path):
    # the copy was a complete run with 0 steps (or steps of no samples) and not a word of it
    if damage == "steps":
        (source.path / "steps.csv").unlink()
    else:
        lines = (source.path / "samples.csv").read_text().splitlines(keepends=True)
        (source.path / "samples.csv").write_text("".join(lines[:51]))
    with pytest.raises(ValueError, match=message):
        reprocess(source.path, config, out_root=tmp_path / "again")
    assert not (tmp_path / "again").exists()


def test_a_reprocessed_run_hashes_the_configuration_it_applied(config, source, tmp_path):
    # was: reprocessed_from named the file given (config_source) without its sha256, where
    # run.json hashes its own configuration file: an edited new.toml was not told apart
    toml = tmp_path / "cell.toml"
    toml.write_text("[loadcell]\nsensitivity_N_per_V = 200.0\ncapacity_N = 1961.33\n")
    assert main(["reprocess", str(source.path), "--config", str(toml), "--out",
                 str(tmp_path / "new")]) == 0
    (folder,) = (tmp_path / "new").iterdir()
    recorded = json.loads((folder / "run.json").read_text())["reprocessed_from"]
    assert recorded["config_source"].endswith(f" + {toml}")
    assert recorded["config_sha256"] == file_sha256(toml)
    assert recorded["config_overrides"] == {}


def test_a_tare_the_new_settings_refuse_is_said_in_one_line(config, source, tmp_path, capsys):
    # the run's tare spreads 0.4 N (2 mV of noise); a configuration allowing 0.1 N refuses it:
    # `mkm reprocess` ended in a traceback of TareInvalid, exit 1
    toml = tmp_path / "tight.toml"
    toml.write_text(config.text.replace("tare_max_std_N = 5.0", "tare_max_std_N = 0.1"))
    assert main(["reprocess", str(source.path), "--config", str(toml), "--out",
                 str(tmp_path / "new")]) == 2
    err = capsys.readouterr().err
    assert err.startswith(f"mkm reprocess: error: run {source.path}: its tare is invalid with "
                          "these settings (the load cell spreads 0.")
    assert err.endswith(" N rms at 0 bar, above safety.tare_max_std_N=0.1 (a loose wire, "
                        "vibration, or a load on the cell)): nothing reprocessed\n")
    assert not (tmp_path / "new").exists()


def test_a_recorded_tare_on_one_code_is_reprocessed(config, tmp_path):
    # the checks of a cell stuck in the tare guard the pressure to come; a recorded run's tare
    # is its offset whatever the cell did after it: a tare on one ADC code is taken again
    stuck = config.replace(sim={"faults": {"loadcell_stuck_at_s": 0.0}})
    run = load_run(acquire(stuck, out_root=tmp_path / "runs", notify=lambda m: None).path)
    assert run.meta.status == "failed" and "one ADC code" in run.meta.reason
    out = load_run(reprocess(run.path, config, tmp_path / "new"))
    assert out.meta.tare["offset_V"] == pytest.approx(run.samples["loadcell_V"].iloc[0])
    assert out.meta.tare["std_V"] == 0.0
