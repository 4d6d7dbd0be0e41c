"""The bench subcommands of `mkm`: output contract and one-line errors."""

from pathlib import Path

import pytest

from bench.storage import load_run
from mkm.cli import main


def test_acquire_prints_the_run_folder_last(tmp_path, capsys):
    rc = main(["acquire", "--pressures", "0.5,1", "--eps", "12.2%", "--out", str(tmp_path),
               "--no-progress"])
    out = capsys.readouterr().out.strip().splitlines()
    assert rc == 0
    run = load_run(Path(out[-1]))
    assert run.complete and run.meta["muscle"]["eps"] == pytest.approx(0.122)
    assert list(run.steps["set_pressure_bar"]) == [0.5, 1.0, 0.5]
    assert run.meta["config_overrides"]["muscle.eps"] == pytest.approx(0.122)


@pytest.mark.parametrize("argv, message", [
    (["acquire", "--eps", "1.2"], "muscle.eps=1.2 is invalid"),
    (["acquire", "--pressures", "0:4:1"], "above regulator.max_pressure_bar=2.5"),
    (["acquire", "--config", "/nope.toml"], "config /nope.toml does not exist"),
])
def test_bad_values_are_one_line(argv, message, capsys):
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.startswith("mkm: error:") and message in err and err.count("\n") == 1


@pytest.mark.parametrize("argv, message", [
    (["calibrate-loadcell", "--masses", "0,-1"], "negative mass"),
    (["tare", "--seconds", "0"], "expected a duration > 0 s"),
])
def test_bad_arguments_are_one_line(argv, message, capsys):
    with pytest.raises(SystemExit) as exit_info:
        main(argv)
    err = capsys.readouterr().err
    assert exit_info.value.code == 2
    assert err.startswith("mkm ") and message in err and err.count("\n") == 1


def test_ni_without_driver_is_one_clear_line(tmp_path, capsys):
    rc = main(["acquire", "--backend", "ni", "--out", str(tmp_path)])
    err = capsys.readouterr().err
    assert rc == 1 and err.count("\n") == 1
    assert "install NI-DAQmx" in err and "--backend sim" in err
    assert list(tmp_path.iterdir()) == []  # nothing was recorded


def test_calibrate_loadcell_from_given_volts(capsys):
    assert main(["calibrate-loadcell", "--masses", "0,10", "--volts", "0.0,0.5"]) == 0
    # 10 kg = 98.0665 N over 0.5 V
    assert "sensitivity_N_per_V = 196.1330" in capsys.readouterr().out


def test_check_prints_the_plan(capsys):
    assert main(["check", "--pressures", "1,2"]) == 0
    assert "0,up,0,1\n1,up,0,2\n2,down,0,1" in capsys.readouterr().out
