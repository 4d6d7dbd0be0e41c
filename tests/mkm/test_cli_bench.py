"""The bench subcommands of `mkm`: output contract and one-line errors."""

import json
import re
import tomllib
from pathlib import Path

import pytest

from mkm.bench.config import load_config, parse_config
from mkm.bench.storage import load_run
from mkm.cli import main


@pytest.fixture(autouse=True)
def _bench_state(tmp_path, monkeypatch):
    """Bench markers (bench.unvented) of these runs go to the test's own folder."""
    monkeypatch.setenv("MKM_STATE_DIR", str(tmp_path / "mkm-state"))


def test_acquire_prints_the_run_folder_last(tmp_path, capsys):
    rc = main(["acquire", "--pressures", "0.5,1", "--eps", "12.2%", "--out", str(tmp_path),
               "--no-progress"])
    captured = capsys.readouterr()
    out = captured.out.strip().splitlines()
    assert rc == 0
    run = load_run(Path(out[-1]))
    assert run.complete and run.meta["muscle"]["eps"] == pytest.approx(0.122)
    # and what to type next, on stderr
    assert captured.err.strip().splitlines()[-1] == (
        f"mkm acquire: note: next: mkm report {out[-1]} scores every model against the "
        "measurement; mkm identify with runs of this muscle at two eps or more fits its braid "
        "angle and rubber")
    assert list(run.steps["set_pressure_bar"]) == [0.5, 1.0, 0.5]
    assert run.meta["config_overrides"]["muscle.eps"] == pytest.approx(0.122)


def test_run_json_names_a_packaged_config_by_its_package_name_and_a_users_by_its_path(
        tmp_path, capsys):
    # was: the packaged example by its install path, a folder of one machine (a site-packages
    # under the user's folder on Windows); the file's sha256 says which text it was
    import hashlib

    from mkm.bench.config import copy_example_config, example_config

    own = copy_example_config(tmp_path / "my bench.toml")
    own.write_text(own.read_text(encoding="utf-8") + "# edited\n", encoding="utf-8")
    recorded = []
    for config in ([], ["--config", str(own)]):
        assert main(["acquire", *config, "--pressures", "0.5", "--out", str(tmp_path / "runs"),
                     "--no-progress"]) == 0
        meta = load_run(Path(capsys.readouterr().out.strip().splitlines()[-1])).meta
        recorded.append((meta["config_source"], meta["config_sha256"]))
    assert recorded == [
        ("mkm.bench/configs/paper_prototype.toml",
         hashlib.sha256(example_config().read_bytes()).hexdigest()),
        (str(own), hashlib.sha256(own.read_bytes()).hexdigest())]


@pytest.mark.parametrize("argv, message", [
    (["acquire", "--pressures", "0:4:1"], "above regulator.max_pressure_bar=2.5"),
    (["acquire", "--config", "/nope.toml"], "config /nope.toml does not exist"),
])
def test_bad_values_are_one_line(argv, message, capsys):
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.startswith("mkm acquire: error:") and message in err and err.count("\n") == 1


@pytest.mark.parametrize("argv, message", [
    (["calibrate-loadcell", "--masses", "0,-1"], "negative mass"),
    # was: the device opened, the mass hung and read, then "need at least two different masses"
    (["calibrate-loadcell", "--masses", "5"], "mkm calibrate-loadcell: error: --masses '5' holds "
     "one mass: expected at least two different masses for a sensitivity (0,5,10,20)\n"),
    (["calibrate-loadcell", "--masses", "5,5kg"], "--masses '5,5kg' holds one mass"),
    (["tare", "--seconds", "0"], "expected a duration > 0 s"),
    # the flag named as typed, the fix suggested; a decimal comma is a decimal point
    (["acquire", "--eps", "12.2"], "mkm acquire: error: --eps 12.2: a fraction is expected; "
     "did you mean 12.2%?\n"),
    (["check", "--eps", "12,2"], "mkm check: error: --eps 12,2: a fraction is expected; "
     "did you mean 12,2%?\n"),
])
def test_bad_arguments_are_one_line(argv, message, capsys):
    with pytest.raises(SystemExit) as exit_info:
        main(argv)
    err = capsys.readouterr().err
    assert exit_info.value.code == 2
    assert err.startswith("mkm ") and message in err and err.count("\n") == 1


def test_ni_without_driver_is_one_clear_line(tmp_path, capsys):
    # what to install and the simulator, in words: the line began with the class of the
    # error, `DriverMissing:`, which names nothing a lab engineer can act on
    said = ("NI-DAQmx, NI's driver of the USB-6001, is not installed: on Windows type 'python -m "
            "nidaqmx installdriver' (it downloads NI's installer; or get NI-DAQmx from ni.com), "
            "then restart the PC (NI does not support the USB-6001 on Linux); without the bench, "
            "--backend sim runs the simulated one")
    rc = main(["acquire", "--backend", "ni", "--out", str(tmp_path)])
    err = capsys.readouterr().err
    assert rc == 1 and err == f"mkm acquire: error: {said}\n"
    assert [p.name for p in tmp_path.iterdir()] == ["mkm-state"]  # nothing was recorded
    for command in ("check", "tare"):
        assert main([command, "--backend", "ni"]) == 1
        assert capsys.readouterr().err == f"mkm {command}: error: {said}\n"


def test_check_without_the_device_exits_as_getting_started_says(capsys):
    # getting started said exit 2 for a device check cannot take; a device it cannot reach or
    # use is a hardware failure, exit 1, as every bench command (a bad configuration: exit 2)
    rc = main(["check", "--backend", "ni"])
    err = capsys.readouterr().err
    assert rc == 1 and err.startswith("mkm check: error: NI-DAQmx, NI's driver of the USB-6001, "
                                      "is not installed")
    text = " ".join((Path(__file__).parents[2] / "docs" / "getting-started.md")
                    .read_text(encoding="utf-8").split())
    assert ("a configuration it cannot take is one `mkm check: error:` line per bad value (every "
            "one at once) and exit 2, a "
            "device it cannot reach or use (no NI-DAQmx, no such device, another product) one "
            "such line and exit 1") in text


def test_calibrate_loadcell_prints_the_toml_block(capsys):
    assert main(["calibrate-loadcell", "--masses", "0,10", "--volts", "0.01,0.51"]) == 0
    captured = capsys.readouterr()
    # stdout is the [loadcell] block alone: 10 kg = 98.0665 N over 0.5 V, offset 0.01 V
    block = tomllib.loads(captured.out)["loadcell"]
    assert block["sensitivity_N_per_V"] == pytest.approx(196.133, rel=1e-6)
    assert block["offset_V"] == pytest.approx(0.01, abs=1e-9)
    assert block["channel"] == "ai0" and block["capacity_N"] == 1961.33
    # the fit goes to stderr in one line, for the operator (no JSON dump)
    assert "R^2 1.000000" in captured.err and "over 2 masses" in captured.err
    assert captured.err.count("\n") == 1 and "{" not in captured.err
    # pasted into a config, it is a valid [loadcell] section
    text = load_config().text
    head, _, rest = text.partition("[loadcell]")
    rest = rest[rest.index("[regulator]"):]
    config = parse_config(head + captured.out + "\n" + rest)
    assert config.loadcell.sensitivity_N_per_V == pytest.approx(196.133, rel=1e-6)


def test_calibrate_loadcell_takes_semicolon_lists_with_decimal_commas(capsys):
    # masses and volts typed as a decimal-comma locale writes them: 0.5 kg = 4.903 N over
    # 0.025 V is 196.13 N/V, the fit of the same numbers typed with points
    assert main(["calibrate-loadcell", "--masses", "0;0,5;1", "--volts",
                 "0,01;0,035;0,06"]) == 0
    commas = capsys.readouterr().out
    assert main(["calibrate-loadcell", "--masses", "0,0.5,1", "--volts", "0.01,0.035,0.06"]) == 0
    points = capsys.readouterr().out
    block = tomllib.loads(commas)["loadcell"]
    assert block["sensitivity_N_per_V"] == pytest.approx(0.5 * 9.80665 / 0.025, rel=1e-6)
    assert block["offset_V"] == pytest.approx(0.01, abs=1e-9)
    assert block == tomllib.loads(points)["loadcell"]


def test_calibrate_loadcell_says_how_sure_its_sensitivity_is(capsys):
    # was: the fit's standard error computed and never shown, so a user could not judge the
    # sensitivity_tolerance_fraction the budget takes (0.1 %) against three masses of 0-2 kg
    import numpy as np
    from scipy import stats

    masses, volts = [0.0, 1.0, 2.0], [0.01, 0.06, 0.1105]
    assert main(["calibrate-loadcell", "--masses", "0,1,2", "--volts", "0.01,0.06,0.1105"]) == 0
    err = capsys.readouterr().err
    # the straight line's own covariance: the slope's sd from numpy, then 1/slope's
    force = np.array(masses) * 9.80665
    (slope, _), cov = np.polyfit(force, volts, 1, cov="unscaled")
    residual = np.array(volts) - np.polyval([slope, _], force)
    sd = np.sqrt(cov[0, 0] * residual @ residual / (len(masses) - 2))
    half = stats.t.ppf(0.975, 1) * sd / slope  # the fraction of the sensitivity 1/slope
    assert f"({f'+-{100 * half:.2g}'} % at 95 %)" in err
    assert (f"warning: the fitted sensitivity's 95 % interval, +-{100 * half:.2g} %, is wider than "
            "loadcell.sensitivity_tolerance_fraction = 0.001 declares: declare at least "
            f"{half:.2g} there, or calibrate again with more masses") in err
    assert main(["calibrate-loadcell", "--masses", "0,10", "--volts", "0.01,0.51"]) == 0
    err = capsys.readouterr().err
    assert "(no interval from two masses: hang three or more to judge it)" in err
    assert "warning" not in err


def test_calibrate_loadcell_says_how_its_block_was_fitted(capsys):
    # was: the block alone, pasted into the config and copied into every run folder with no
    # word of when, by which command and code, from which masses and volts, nor how well
    from mkm.core.records import command_line, provenance

    assert main(["calibrate-loadcell", "--backend", "sim", "--masses", "0,5,10"]) == 0
    lines = capsys.readouterr().out.splitlines()
    record = provenance()
    assert lines[1].startswith(f"# fitted {record['date_utc'][:10]}")
    assert lines[1].endswith(f" from volts measured on the sim bench (SIMULATED, seed 0) by: "
                             f"{command_line()} (mkm-bench {record['versions']['mkm-bench']}"
                             + (f", git {record['git']})" if record["git"] else ")"))
    assert lines[2].startswith("# masses [kg] 0, 5, 10; volts [V] ")
    assert lines[3].startswith("# R^2 0.9999")  # the simulated cell: linear, with noise
    assert main(["calibrate-loadcell", "--masses", "0,10", "--volts", "0.01,0.51"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert " from volts measured elsewhere by: " in lines[1]
    assert lines[2:4] == ["# masses [kg] 0, 10; volts [V] 0.01, 0.51",
                          "# R^2 1.000000, largest residual 0.000 N"]


def test_calibrate_loadcell_says_when_its_block_would_be_refused(capsys):
    """The packaged example's cell reads its capacity, 1961.33 N, at the +-10 V rail: a fit 1 %
    less sensitive (10 kg over 0.505 V: 194.19 N/V, the rail at 1941.9 N; the simulated bench's
    1 kg calibration gives such a fit) printed a block that `mkm check` then refused, unsaid."""
    assert main(["calibrate-loadcell", "--masses", "0,10", "--volts", "0.01,0.515"]) == 0
    captured = capsys.readouterr()
    block = tomllib.loads(captured.out)["loadcell"]  # stdout stays the block alone
    assert block["sensitivity_N_per_V"] == pytest.approx(98.0665 / 0.505, rel=1e-6)
    (warning,) = [line for line in captured.err.splitlines() if "warning" in line]
    assert warning.startswith("mkm calibrate-loadcell: warning: this [loadcell] pasted into the "
                              "config is refused: loadcell.sensitivity_N_per_V=194.191 puts the "
                              "+-10 V rail at 1941.91 N, below capacity_N=1961.33")
    text = load_config().text
    head, _, rest = text.partition("[loadcell]")
    with pytest.raises(ValueError, match="below capacity_N=1961.33"):
        parse_config(head + captured.out + "\n" + rest[rest.index("[regulator]"):])


def test_calibrate_loadcell_volts_of_a_mass_beyond_capacity_are_refused(capsys):
    assert main(["calibrate-loadcell", "--masses", "0,10,300", "--volts", "0.01,0.51,10"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "300 kg weighs 2942 N, beyond the load cell's " \
        "loadcell.capacity_N=1961.33: expected masses up to 200 kg" in err


def test_check_prints_the_plan(capsys):
    assert main(["check", "--pressures", "1,2"]) == 0
    out = capsys.readouterr().out
    assert "planned steps: 3\n  repeat 1, up: 1, 2 bar\n  repeat 1, down: 1 bar" in out
    assert "," not in out.split("planned steps")[1].split("estimated")[0].replace(", ", "")


def test_a_staircase_that_reads_as_a_decimal_comma_says_which_steps_it_is(capsys):
    # '1,2' is the steps 1 and 2 bar, as in every mkm command; a lab that writes 1.2 bar as
    # '1,2' learns it before the muscle is pressurised
    assert main(["check", "--pressures", "1,2"]) == 0
    captured = capsys.readouterr()
    assert "up: 1, 2 bar" in captured.out
    assert captured.err.splitlines()[0] == ("mkm check: note: --pressures '1,2' is two steps, "
                                            "1 and 2 bar; for one step at 1.2 bar write 1.2")
    assert main(["check", "--pressures", "0.5,1"]) == 0
    assert "note" not in capsys.readouterr().err
    assert main(["check", "--pressures", "1,x"]) == 2
    assert capsys.readouterr().err.count("\n") == 1


def test_aborted_run_report_states_steps_planned_and_done(tmp_path):
    # Issue 10: the writer stored a count, the reader expected a list, so every aborted run's
    # report said "of an unrecorded number planned". Interlock at 20 % of the 1961 N cell
    # (392 N): the prototype reaches it on the way to 2.5 bar, after the first steps.
    from mkm.bench.run import acquire
    from mkm.report import build_report

    config = load_config(pressures_bar=[0.5, 1.0, 2.5]).replace(
        sequence={"preconditioning_cycles": 0}, safety={"force_limit_fraction": 0.2})
    result = acquire(config, out_root=tmp_path / "runs")
    run = load_run(result.path)
    assert result.status == "aborted" and run.meta.n_steps == 5
    done = run.meta.steps_done
    assert done == len(run.steps) == 2  # 0.5 and 1.0 bar held; 2.5 bar tripped on its way
    html = build_report([result.path], ["eq2"], out_dir=tmp_path / "report",
                        cache_dir=None, tolerance=None, surrogate_section=False
                        ).read_text(encoding="utf-8")
    assert f"{done} settled step(s) of 5" in html
    assert "unrecorded" not in html


@pytest.mark.parametrize("out, message", [("file.txt", "is a file: expected a folder"),
                                          ("file.txt/runs", "is not a writable folder")])
def test_bad_out_is_one_line_before_the_device_opens(tmp_path, capsys, out, message):
    (tmp_path / "file.txt").write_text("x")
    assert main(["acquire", "--out", str(tmp_path / out), "--no-progress"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and f"--out {tmp_path / out} {message}" in err
    assert not (tmp_path / "mkm-state").exists()  # no bench was opened


@pytest.mark.parametrize("setting, message", [
    ("[loadcell]\nchannel = 'ai9'", "the USB-6001 has inputs ai0 to ai7"),
    ("[regulator]\nmonitor_channel = 'ai5'", "cannot be differential on the USB-6001"),
    ("[daq]\nterminal_config = 'nrse'", "no NRSE or pseudo-differential mode"),
    ("[daq]\nsample_rate_hz = 1e6", "samples at most 20000 S/s"),
])
def test_check_rejects_what_the_device_cannot_run(tmp_path, capsys, setting, message):
    text = load_config().text
    section, line = setting.split("\n")
    text = text.replace(f"{section}\n", f"{section}\n{line}\n", 1)
    key = line.split(" =")[0]
    # drop the packaged value of the same key, which now follows the new line
    lines = text.splitlines()
    first = next(i for i, s in enumerate(lines) if s.startswith(f"{key} ="))
    lines = [s for i, s in enumerate(lines) if i == first or not s.startswith(f"{key} =")]
    config = tmp_path / "bad.toml"
    config.write_text("\n".join(lines) + "\n")
    assert main(["check", "--config", str(config)]) == 2
    err = capsys.readouterr().err
    assert err.startswith("mkm check: error: config ") and message in err and err.count("\n") == 1


@pytest.mark.parametrize("line, said", [
    ("D0mm = 30.0", "muscle.D0mm is not a field of a muscle: expected some of C01_MPa, C10_MPa, "
                    "D0_mm, L0_mm, eps, gap_mm, id, t0_mm, theta0_deg"),
    ("", "muscle.D0_mm is missing: expected the muscle's inner diameter")])
def test_check_names_a_misspelt_muscle_key(tmp_path, capsys, line, said):
    # [muscle] D0mm = 10 was said as 'muscle.D0_mm is missing: expected the
    # muscle's  inner diameter', the key written not named
    config = tmp_path / "lab.toml"
    config.write_text(load_config().text.replace("D0_mm = 30.0", line, 1), encoding="utf-8")
    assert main(["check", "--config", str(config)]) == 2
    assert capsys.readouterr().err == f"mkm check: error: config {config}: {said}\n"


def test_check_warns_past_the_braid_lock(tmp_path, capsys):
    # its last line said to run `mkm acquire` with the same options, which refuses
    # a muscle past its braid lock: the command it names is the one that runs
    assert main(["check", "--eps", "0.4"]) == 0
    err = capsys.readouterr().err
    assert "mkm check: warning: eps 0.4 is past the braid lock" in err
    assert "locking angle 54.7" in err
    assert err.splitlines()[-1] == ("mkm check: ready: the simulated device answered (no "
                                    "hardware driven) and the configuration holds; read the 1 "
                                    "warning(s) above, then `mkm acquire` with the same options "
                                    "and --allow-past-lock, without which it refuses a muscle "
                                    "past its braid lock")
    out = str(tmp_path / "runs")
    assert main(["acquire", "--eps", "0.4", "--out", out, "--no-progress"]) == 2
    assert main(["acquire", "--eps", "0.4", "--out", out, "--no-progress",
                 "--allow-past-lock"]) == 0


def test_check_ends_with_a_verdict(capsys):
    # the budget table was the last thing printed: nothing said the check had passed
    assert main(["check"]) == 0
    captured = capsys.readouterr()
    assert captured.err.splitlines() == ["mkm check: ready: the simulated device answered (no "
                                         "hardware driven) and the configuration holds; `mkm "
                                         "acquire` with the same options runs the steps above"]


def test_check_reads_the_bench_at_rest_as_a_runs_tare_does(tmp_path, capsys):
    # a pressure monitor 0.08 bar off its zero: `mkm check` said "ready" (it read nothing),
    # and `mkm acquire` then refused at its tare. check reads the bench vented for the tare's
    # time: its reading is in the plan, what the tare would refuse is its last line, exit 1
    config = tmp_path / "lab.toml"
    config.write_text(load_config().text + "\n[sim.truth]\nmonitor_offset_bar = 0.08\n")
    assert main(["check", "--config", str(config)]) == 1
    captured = capsys.readouterr()
    last = captured.err.splitlines()[-1]
    assert last.startswith("mkm check: error: tare invalid: the pressure monitor reads +0.08")
    assert "beyond safety.vent_below_bar=0.05: it cannot verify a vent (its zero is off: it " \
        "gives 1.08 V vented, [regulator] monitor_V_at_zero = 1 V" in last
    assert last.endswith("; `mkm acquire` would stop at its tare: fix this first")
    assert "ready" not in captured.err
    # 0.046 bar off: within what a vent check takes, beyond the monitor's declared 0.04 bar
    config.write_text(load_config().text + "\n[sim.truth]\nmonitor_offset_bar = 0.046\n")
    assert main(["check", "--config", str(config)]) == 0
    captured = capsys.readouterr()
    assert "at rest, vented (5 s, as a run's tare): the load cell " in captured.out
    assert ", the pressure monitor +0.04" in captured.out
    assert "mkm check: warning: the pressure monitor reads +0.04" in captured.err
    assert captured.err.splitlines()[-1].startswith("mkm check: ready: ")


@pytest.mark.parametrize("argv, message", [
    (["acquire", "--pressures", "0:1e12:1"], "--pressures"),
    (["acquire", "--pressures", "0.001:2.5:0.001"], "4999 steps, 0.5 to 3.8 days: expected at "
     "most 2000 steps"),
])
def test_huge_sequences_are_one_line(argv, message, capsys):
    with pytest.raises(SystemExit) as exit_info:
        rc = main(argv)
        raise SystemExit(rc)
    assert exit_info.value.code == 2
    err = capsys.readouterr().err
    assert message in err and err.count("\n") == 1


def _edited_run(tmp_path, **muscle):
    from mkm.bench.run import acquire
    from mkm.core.records import write_json_atomic

    config = load_config(pressures_bar=[0.5, 1.0]).replace(sequence={"preconditioning_cycles": 0})
    path = acquire(config, out_root=tmp_path / "runs", notify=lambda m: None).path
    meta = json.loads((path / "run.json").read_text())
    meta["muscle"].update(muscle)
    for key in [k for k, v in muscle.items() if v is None]:
        del meta["muscle"][key]
    write_json_atomic(path / "run.json", meta)
    return path


def test_report_on_run_json_without_D0_is_one_line(tmp_path, capsys):
    path = _edited_run(tmp_path, D0_mm=None)
    assert main(["report", str(path), "--models", "eq2", "--out", str(tmp_path / "r"),
                 "--no-cache", "--no-progress"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "muscle.D0_mm is missing" in err


def test_report_refuses_a_recorded_id_that_is_not_an_id(tmp_path, capsys):
    # ids are validated when loaded, not only when configured (issue 20): "$...$" made
    # matplotlib parse mathtext, "/" and markup named folders
    path = _edited_run(tmp_path, id="odd$\\frac{1}$id")
    assert main(["report", str(path), "--models", "eq2", "--out", str(tmp_path / "r"),
                 "--no-cache", "--no-progress"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "muscle.id='odd$\\\\frac{1}$id'" in err


def test_report_says_a_run_ended_without_venting(tmp_path):
    # what kill -9 leaves: run.json "running" from a dead process, no final vent in commands.csv
    from mkm.bench.run import acquire
    from mkm.core.records import write_json_atomic
    from mkm.report import build_report

    config = load_config(pressures_bar=[0.5, 1.0]).replace(sequence={"preconditioning_cycles": 0})
    path = acquire(config, out_root=tmp_path / "runs", notify=lambda m: None).path
    meta = json.loads((path / "run.json").read_text())
    meta["status"] = "running"
    meta["process"]["pid"] = 2**22 + 99  # above pid_max: dead
    write_json_atomic(path / "run.json", meta)
    commands = (path / "commands.csv").read_text().splitlines()
    kept = [line for line in commands if not line.endswith(",vent")] + [""]
    (path / "commands.csv").write_text("\n".join([commands[0], *kept[1:]]))
    html = build_report([path], ["eq2"], out_dir=tmp_path / "r", cache_dir=None,
                        tolerance=None, surrogate_section=False).read_text(encoding="utf-8")
    assert "incomplete" in html
    assert "ended without venting: the last commanded pressure was 0.5 bar" in html


def test_report_says_a_run_vented_a_dead_one_first(tmp_path):
    import socket

    from mkm.bench.run import acquire
    from mkm.bench.storage import ProcessIdentity
    from mkm.bench.unvented import Marker, bench_folder
    from mkm.core.records import write_json_atomic
    from mkm.report import build_report

    dead = ProcessIdentity(2**22 + 7, socket.gethostname(), 1.0, None)
    marker = Marker("sim-Dev1", "old/run", "2026-12-01T10:00:00+00:00", vars(dead), 2.5)
    bench_folder("sim-Dev1").mkdir(parents=True)
    write_json_atomic(bench_folder("sim-Dev1") / "dead.json", vars(marker))
    config = load_config(pressures_bar=[0.5]).replace(sequence={"preconditioning_cycles": 0})
    path = acquire(config, out_root=tmp_path / "runs", notify=lambda m: None).path
    html = build_report([path], ["eq2"], out_dir=tmp_path / "r", cache_dir=None,
                        tolerance=None, surrogate_section=False).read_text(encoding="utf-8")
    assert ("the bench was found left pressurised by run old/run (started "
            "2026-12-01T10:00:00+00:00, last commanded 2.5 bar): this run vented it first") in html


def test_a_run_still_being_recorded_is_not_identified_and_its_export_says_so(tmp_path, capsys):
    """A second PC (or window) on the run folder while `mkm acquire` records it: `mkm
    identify` fitted the steps so far and said `calibration.json is ready`, and `mkm export`
    wrote them without a word, as if the run were whole."""
    import json

    from mkm.bench.run import acquire
    from mkm.bench.storage import ProcessIdentity

    config = load_config(pressures_bar=[0.5, 1.0]).replace(sequence={"preconditioning_cycles": 0})
    path = acquire(config, out_root=tmp_path / "runs", notify=lambda m: None).path
    meta = json.loads((path / "run.json").read_text(encoding="utf-8"))
    # as run.json reads while its recorder (this process: alive) is at work
    meta.update(status="running", reason="", process=vars(ProcessIdentity.current()))
    (path / "run.json").write_text(json.dumps(meta), encoding="utf-8")
    capsys.readouterr()
    pid = ProcessIdentity.current().pid
    assert main(["identify", str(path), "--out", str(tmp_path / "id")]) == 2
    assert capsys.readouterr().err == (
        f"mkm identify: error: run {path.name} is still being recorded (pid {pid}): expected a "
        "run that has ended (identify it once its mkm acquire has ended)\n")
    assert not (tmp_path / "id").exists()
    assert main(["export", str(path), "--out", str(tmp_path / "run.xlsx")]) == 0
    captured = capsys.readouterr()
    assert captured.out == f"{tmp_path / 'run.xlsx'}\n"
    assert captured.err == (
        f"mkm export: note: {path.name} is still being recorded (pid {pid}): the export holds "
        "its record so far (status running); export it again once its mkm acquire has ended\n")
    # the run folder on a share, recorded by another bench PC: its process cannot be seen from
    # here, and identify fitted the steps so far, export said nothing
    meta["process"].update(host="BENCH-PC-A", pid=2**22 + 7)
    (path / "run.json").write_text(json.dumps(meta), encoding="utf-8")
    elsewhere = (f"{path.name} may still be recorded on BENCH-PC-A (its run.json says running, "
                 "and this PC cannot see that PC's processes)")
    then = ("once its mkm acquire on BENCH-PC-A has ended (a run that stopped there without "
            "closing its record is closed by the next mkm command on that bench there, such as "
            "mkm vent on BENCH-PC-A; if that PC runs mkm no more, by mkm close RUN_DIR --reason "
            "TEXT here)")
    assert main(["identify", str(path), "--out", str(tmp_path / "id")]) == 2
    assert capsys.readouterr().err == (
        f"mkm identify: error: run {elsewhere}: expected a run that has ended (identify it "
        f"{then})\n")
    assert not (tmp_path / "id").exists()
    assert main(["export", str(path), "--out", str(tmp_path / "run.xlsx")]) == 0
    assert capsys.readouterr().err == (
        f"mkm export: note: {elsewhere}: the export holds its record so far (status "
        f"incomplete); export it again {then}\n")


def test_a_run_dead_on_a_pc_gone_is_closed_by_hand_then_identified(tmp_path, capsys):
    """A run folder on a share whose bench PC broke mid-run: its run.json says running, and
    `mkm identify` refused it ("may still be recorded on BENCH-PC-A"), naming only the next mkm
    command there. `mkm close RUN --reason` closes it here, every sample kept, and identify
    takes it."""
    import datetime
    import os

    from mkm.bench.run import acquire
    from mkm.bench.storage import STILL_WRITTEN_S
    from mkm.cli import build_parser
    from mkm.identify.runs import load_run_data

    config = load_config(pressures_bar=[0.5, 1.0]).replace(sequence={"preconditioning_cycles": 0})
    path = acquire(config, out_root=tmp_path / "runs", notify=lambda m: None).path
    rows = len(load_run(path).samples)
    meta = json.loads((path / "run.json").read_text(encoding="utf-8"))
    meta.update(status="running", reason="", ended_utc=None)
    meta["process"].update(host="BENCH-PC-A", pid=2**22 + 7)
    (path / "run.json").write_text(json.dumps(meta), encoding="utf-8")
    with pytest.raises(ValueError, match="if that PC runs mkm no more, by mkm close RUN_DIR "
                       "--reason TEXT here"):
        load_run_data(path)
    assert main(["close", str(path), "--reason", "BENCH-PC-A broke"]) == 2  # written just now
    assert "may still record it" in capsys.readouterr().err
    old = (datetime.datetime.now(datetime.UTC) - datetime.timedelta(minutes=6)).timestamp()
    for file in path.iterdir():
        os.utime(file, (old, old))
    samples = (path / "samples.csv").read_bytes()
    assert main(["close", str(path), "--reason", "BENCH-PC-A broke"]) == 0
    captured = capsys.readouterr()
    assert captured.out == f"{path}\n"
    assert captured.err.splitlines()[0] == (f"mkm close: note: run {path.name} closed: status "
                                            f"killed, {rows} samples kept as they are on disk")
    assert (path / "samples.csv").read_bytes() == samples
    assert json.loads((path / "run.json").read_text(encoding="utf-8"))["closed"]["reason"] == \
        "BENCH-PC-A broke"
    assert len(load_run_data(path).time_s) == rows
    # its --help says the wait the refusal holds to
    help_text = build_parser()._subparsers._group_actions[0].choices["close"].description
    assert f"within the last {STILL_WRITTEN_S / 60:g} minutes" in help_text


def test_demo_on_a_held_simulated_bench_is_one_line(tmp_path, capsys):
    """`mkm demo` while another command holds the simulated bench (another `mkm acquire
    --backend sim`, another demo) said so in a BenchBusy traceback; now one line, exit 1, and
    no run folder written."""
    import os

    from mkm.bench.ownership import BenchOwner

    with BenchOwner("sim-Dev1", "acquire"):
        rc = main(["demo", "--out", str(tmp_path / "demo"), "--no-progress"])
    err = capsys.readouterr().err
    assert rc == 1
    assert err.startswith("mkm demo: error: bench sim-Dev1 is in use by pid "
                          f"{os.getpid()} (`mkm acquire`, started 20")
    assert err.count("\n") == 1 and "Traceback" not in err
    assert not list((tmp_path / "demo").glob("runs/*"))


def test_the_demo_s_bench_lines_name_mkm_demo(tmp_path, capsys, monkeypatch):
    """Under `mkm demo` the simulated bench's notices and status lines said `mkm acquire: ...`,
    a command the user never typed; they name `mkm demo` now, as its other lines do."""
    import mkm.bench.run as run
    from mkm.demo import run_demo

    real_execute = run.BenchRun.execute

    def with_status_lines(self):  # the demo shows its progress on a terminal only
        self.progress = True
        return real_execute(self)

    monkeypatch.setattr(run, "STATUS_EVERY_S", 0.0)  # a status line each block: stderr is no TTY
    monkeypatch.setattr(run.BenchRun, "execute", with_status_lines)
    run_demo(tmp_path / "demo", progress=False, models=["eq2"], tolerance=None,
             surrogate_section=False, cache_dir=None)
    err = capsys.readouterr().err
    assert "mkm acquire" not in err
    assert err.count("mkm demo: SIMULATED bench (sim): no hardware is driven; recording into ") == 2
    assert re.search(r"^mkm demo: SIMULATED step \d+/\d+, ", err, re.M), err
