"""bench.config: the packaged default reproduces the paper's prototype; bad values are named."""

import pytest

from mkm.bench.config import load_config, parse_config


def test_default_is_the_papers_prototype():
    c = load_config()
    # Antonelli et al. 2025, section 4: D0 30 mm, t0 3 mm, working length 282 mm.
    assert (c.muscle.D0_mm, c.muscle.t0_mm, c.muscle.L0_mm) == (30.0, 3.0, 282.0)
    assert c.daq.sample_rate_hz == 10.0
    assert c.daq.buffer_samples >= 6000  # at least 10 minutes at 10 Hz
    assert c.sequence.pressures_bar[-1] == 2.5
    assert c.regulator.max_pressure_bar == 2.5


def test_default_load_cell_holds_the_prototypes_force():
    # The model force at 2.5 bar must stay below the interlock, or the default run could not
    # finish; the paper's +-98 N TCA10 would not (see test_run.py::test_interlock_...).
    from mkm.fem.ladder import make_model

    c = load_config()
    force = make_model(c.sim.model).predict(2.5, c.muscle.D0_mm, c.muscle.t0_mm, 0.0).force_N
    assert float(force) * 1.03 < c.force_limit_N  # 3 %: the simulated hysteresis on the way down


def test_overrides_are_validated_and_recorded():
    c = load_config(eps=0.122, pressures_bar=[0.5, 1.0])
    assert c.muscle.eps == 0.122
    assert c.sequence.pressures_bar == (0.5, 1.0)
    assert c.overrides == {"muscle.eps": 0.122, "sequence.pressures_bar": (0.5, 1.0)}
    # named as the option typed, with the setting it overrides
    with pytest.raises(ValueError, match=r"^--eps: muscle\.eps=1\.5 is invalid"):
        load_config(eps=1.5)
    with pytest.raises(ValueError, match=r"^--pressures: sequence\.pressures_bar has 3 bar, "
                       "above regulator.max_pressure_bar=2.5"):
        load_config(pressures_bar=[1.0, 3.0])


def test_a_staircase_given_falling_is_refused():
    # its steps would be labelled up while the pressure falls, and down while it rises
    with pytest.raises(ValueError, match=r"^--pressures: sequence\.pressures_bar goes from 2 "
                       "to 1 bar: "
                       "expected the rising staircase"):
        load_config(pressures_bar=[2.0, 1.0, 0.5])
    with pytest.raises(ValueError, match="goes from 1 to 1 bar"):
        load_config(pressures_bar=[0.5, 1.0, 1.0])
    assert load_config(pressures_bar=[0.5, 1.0]).sequence.pressures_bar == (0.5, 1.0)


def test_an_override_is_in_the_text_a_run_folder_keeps(tmp_path):
    """eps is in one place: what config.toml says is what run.json says (issue 30: --eps 0.122
    left config.toml at eps = 0.0)."""
    import json
    import tomllib
    from dataclasses import replace

    from mkm.bench.run import acquire

    c = load_config(eps=0.122)
    assert tomllib.loads(c.effective_text())["muscle"]["eps"] == 0.122
    assert "# shortening ratio (fraction), set by the threaded rod" in c.effective_text()
    c = replace(c, sequence=replace(c.sequence, pressures_bar=(0.5,), preconditioning_cycles=0))
    run = acquire(c, out_root=tmp_path)
    folder = tomllib.loads((run.path / "config.toml").read_text(encoding="utf-8"))
    recorded = json.loads((run.path / "run.json").read_text(encoding="utf-8"))
    assert folder["muscle"]["eps"] == recorded["muscle"]["eps"] == 0.122


def test_a_known_braid_angle_and_rubber_are_the_muscles_own():
    from mkm.bench.preflight import braid_lock, expected_force_N
    from mkm.fem.eq2 import chou_hannaford, chou_hannaford_eps_max

    c = parse_config(with_settings("[muscle]\ntheta0_deg = 25.0\nC10_MPa = 0.1\nC01_MPa = 0.05"))
    assert (c.muscle.theta0_deg, c.muscle.C10_MPa, c.muscle.C01_MPa) == (25.0, 0.1, 0.05)
    # both preflight checks read the muscle's own angle: the lock at 25 deg is eps 0.363
    assert braid_lock(c.replace(muscle={"eps": 0.3})) is None
    eps_max = float(chou_hannaford_eps_max(25.0))
    assert f"{eps_max:.3f}" in braid_lock(c.replace(muscle={"eps": 0.37}))
    # on the braid's diameter D0 + 2 t0, the FE model's force at eps 0
    assert expected_force_N(c, 2.0) == pytest.approx(float(chou_hannaford(2.0, 36.0, 0.0, 25.0)))
    with pytest.raises(ValueError, match=r"muscle\.theta0_deg=95 is invalid"):
        parse_config(with_settings("[muscle]\ntheta0_deg = 95"))
    # past the locking angle, though within the typo bounds: named where it is, as the others
    with pytest.raises(ValueError, match=r": muscle\.theta0_deg=60 is invalid: expected 0 < "
                                         r"theta0 < 54\.7 deg"):
        parse_config(with_settings("[muscle]\ntheta0_deg = 60"))
    with pytest.raises(ValueError, match=r"muscle\.D0_tolerance_mm is not a field of a muscle"):
        parse_config(with_settings("[muscle]\nD0_tolerance_mm = 0.3"))


BASE = """
[muscle]
id = "m1"
D0_mm = 30
t0_mm = 3
L0_mm = 282
eps = 0
[loadcell]
capacity_N = 1000
sensitivity_N_per_V = 100
[daq]
backend = "sim"
"""


def with_settings(extra: str, base: str = BASE) -> str:
    """``base`` with the ``[section]`` lines of ``extra`` merged into its own tables."""
    text = base
    for block in extra.strip().split("\n["):
        header, _, lines = ("[" + block.lstrip("[")).partition("\n")
        if f"\n{header}\n" in text:
            text = text.replace(f"\n{header}\n", f"\n{header}\n{lines}\n", 1)
        else:
            text += f"{header}\n{lines}\n"
    return text


def test_minimal_config_takes_defaults():
    c = parse_config(BASE)
    assert c.daq.terminal_config == "differential"
    assert c.muscle.D0_mm == 30.0 and isinstance(c.muscle.D0_mm, float)


def test_the_muscles_eps_is_written_as_the_command_line_takes_it():
    # `eps = "12.2%"`, as --eps 12.2% is typed, was refused: 'expected a number'
    assert parse_config(BASE.replace("eps = 0", 'eps = "12.2%"')).muscle.eps == pytest.approx(
        0.122, abs=1e-15)
    with pytest.raises(ValueError, match=r": muscle\.eps 12\.2: a fraction is expected; did "
                                         r"you mean 12\.2%\?$"):
        parse_config(BASE.replace("eps = 0", 'eps = "12.2"'))


@pytest.mark.parametrize("extra, message", [
    ("[daq]\nterminal_config = 'default'", r"daq\.terminal_config='default' is invalid"),
    ("[daq]\nbuffer_s = 60", r"daq\.buffer_s=60 is invalid: expected 600 s"),
    ("[daq]\nsample_rate = 10", r"daq\.sample_rate is not a setting"),
    ("[regulator]\nkind = 'pneumatic'", r"regulator\.kind='pneumatic' is invalid"),
    ("[regulator]\nmax_pressure_bar = 5", r"regulator\.max_pressure_bar=5 is invalid"),
    # the setting is named, not the --pressures flag of the command line
    ("[sequence]\npressures_bar = '0:2:-1'",
     r": sequence\.pressures_bar '0:2:-1': step -1 must be > 0"),
    ("[sequence]\npressures_bar = [0.5, -1]",
     r": sequence\.pressures_bar '0\.5,-1' has a negative pressure -1 bar"),
    ("[sequence]\npressures_bar = 'abc'", r"is not a number"),
    ("[sequence]\npressures_bar = [1, 'x']", r"expected 'start:stop:step' or a list"),
    ("[sequence]\npressures_bar = [1]\nrepeats = 0", r"sequence\.repeats=0 is invalid"),
    ("[settle]\ntimeout_s = 1", r"settle\.timeout_s=1 is below min_dwell_s"),
    ("[safety]\nforce_limit_fraction = 1.5", r"force_limit_fraction=1\.5 is invalid"),
    ("[sim]\nmodel = 'nope'", r"sim\.model='nope' is unknown"),
    ("[sim]\nseed = 1.5", r"sim\.seed=1\.5 is invalid: expected a whole number$"),
    ("[sequence]\npressures_bar = [1]\ndown_sweep = 'yes'",
     r"sequence\.down_sweep='yes' is invalid: expected true or false$"),
    ("[sim.faults]\nread_timeouts = 0", r"sim\.faults\.read_timeouts=0 is invalid"),
    ("[extra]\na = 1", r"\[extra\] is not a section"),
])
def test_bad_settings_are_named(extra, message):
    with pytest.raises(ValueError, match=message):
        parse_config(with_settings(extra))


def test_load_cell_that_clips_before_capacity_is_refused():
    text = BASE.replace("sensitivity_N_per_V = 100", "sensitivity_N_per_V = 50")
    with pytest.raises(ValueError, match="below capacity_N=1000"):
        parse_config(text)


def test_a_config_that_is_a_folder_is_named_so(tmp_path, mkm_cli):
    # `--config mkm-out` (a folder, where a file was meant) said it did not exist
    code, out, err = mkm_cli(["acquire", "--config", str(tmp_path), "--out", str(tmp_path / "r")])
    assert code == 2 and out == "" and not (tmp_path / "r").exists()
    assert err.strip().splitlines() == [f"mkm acquire: error: config {tmp_path} is a folder: "
                                        "expected a TOML file"]


def test_missing_section_and_file_and_bad_toml():
    with pytest.raises(ValueError, match=r"section \[loadcell\] is missing"):
        parse_config(BASE.split("[loadcell]")[0])
    with pytest.raises(ValueError, match="does not exist"):
        load_config("/nonexistent/bench.toml")
    with pytest.raises(ValueError, match="is not valid TOML"):
        parse_config("[muscle\n")


def test_a_config_saved_by_windows_programs_is_read_as_it_was_written(tmp_path, mkm_cli):
    """The packaged example edited on the bench PC: saved by Notepad as "Unicode" (UTF-16 LE
    with its byte-order mark, CRLF), as Windows PowerShell 5's `>` writes it, was 'cannot be
    read as UTF-8 text ('utf-8' codec can't decode byte 0xff in position 0: ...)'; with a DOS
    editor's Ctrl-Z after the last line, 'not valid TOML: Invalid statement (at line 107,
    column 1)', a character nobody sees."""
    from mkm.bench.config import example_config

    text = example_config().read_text("utf-8").replace('D0_mm = 30.0', 'D0_mm = 25.0')
    windows = text.replace("\n", "\r\n")
    saved = {"unicode.toml": windows.encode("utf-16"),
             "ctrl-z.toml": windows.encode() + b"\x1a",
             "bom.toml": b"\xef\xbb\xbf" + windows.encode()}
    for name, data in saved.items():
        (tmp_path / name).write_bytes(data)
        config = load_config(tmp_path / name)
        assert config.muscle.D0_mm == 25.0, name
        assert config.daq.backend == "sim" and config.sequence.pressures_bar[-1] == 2.5, name
    # bytes that are no UTF-8 nor UTF-16 (Notepad's "ANSI": a code page's ü) are named as such
    (tmp_path / "ansi.toml").write_bytes(text.replace("paper-prototype", "Müller").encode(
        "cp1252"))
    code, out, err = mkm_cli(["check", "--config", str(tmp_path / "ansi.toml")])
    at = text.encode().index(b"paper-prototype") + 2
    assert code == 2 and out == ""
    assert err.strip().splitlines() == [
        f"mkm check: error: config {tmp_path / 'ansi.toml'} is not UTF-8 text (byte {at} is "
        "not, as a Windows code page saves an accented letter): save it as UTF-8 (Notepad: "
        "File, Save as, Encoding UTF-8)"]


def test_a_config_path_typed_with_backslashes_on_another_system_says_the_separator(
        tmp_path, mkm_cli, monkeypatch):
    """`mkm check --config "Müller Versuch 1\\bench.toml"`, pasted from the bench PC: 'does
    not exist', where `mkm report` of a run folder so typed says the separator here."""
    folder = tmp_path / "Müller Versuch 1"
    folder.mkdir()
    from mkm.bench.config import copy_example_config

    copy_example_config(folder / "bench.toml")
    monkeypatch.chdir(tmp_path)
    code, out, err = mkm_cli(["check", "--config", "Müller Versuch 1\\bench.toml"])
    assert code == 2 and out == ""
    assert err.strip().splitlines() == [
        "mkm check: error: config Müller Versuch 1\\bench.toml does not exist: expected a "
        "TOML file; on this system folders are separated by /: 'Müller Versuch 1/bench.toml'?"]
    code, out, err = mkm_cli(["check", "--config", "Müller Versuch 1/bench.toml"])
    assert code == 0, err


def test_a_config_notepad_saved_with_txt_or_named_without_toml_says_the_file_there(
        tmp_path, mkm_cli, monkeypatch):
    """Notepad saves `bench.toml` as `bench.toml.txt` unless its type is 'All files', and
    Explorer shows that file as `bench.toml`: `--config bench.toml` said 'does not exist'
    alone; a name typed as Explorer shows it, `bench` for `bench.toml`, likewise."""
    from mkm.bench.config import copy_example_config

    monkeypatch.chdir(tmp_path)
    copy_example_config(tmp_path / "notepad.toml.txt")
    copy_example_config(tmp_path / "bench.toml")
    code, out, err = mkm_cli(["check", "--config", "notepad.toml"])
    assert code == 2 and out == ""
    assert err.strip().splitlines() == [
        "mkm check: error: config notepad.toml does not exist: expected a TOML file; "
        "notepad.toml.txt is there (Notepad added .txt: rename it, or save with type 'All "
        "files')"]
    code, out, err = mkm_cli(["check", "--config", "bench"])
    assert code == 2 and err.strip().splitlines() == [
        "mkm check: error: config bench does not exist: expected a TOML file; bench.toml is "
        "there (Explorer hides the extension: type it too)"]
    code, out, err = mkm_cli(["check", "--config", "other.toml"])  # nothing near: as it was
    assert code == 2 and err.strip().splitlines() == [
        "mkm check: error: config other.toml does not exist: expected a TOML file"]


@pytest.mark.parametrize(("edited", "said"), [
    # a Windows path typed as Explorer shows it: tomllib's 'Invalid hex value' (\U) and
    # 'Unescaped '\' in a string' (\l) named neither the path nor the quotes it needs
    ('id = "paper-prototype"\nout = "C:\\Users\\lab\\runs"',
     "Invalid hex value (at line 8, column 12); a \\ in \"...\" begins an escape (\\n, \\t, "
     "\\U...): write a Windows path in single quotes, out = 'C:\\Users\\lab\\runs', or with / "
     "for \\"),
    ('id = "D:\\lab\\m7"',
     "Unescaped '\\' in a string (at line 7, column 11); a \\ in \"...\" begins an escape (\\n, "
     "\\t, \\U...): write a Windows path in single quotes, id = 'D:\\lab\\m7', or with / for \\"),
    # German Windows' decimal comma: 'Expected newline or end of document after a statement'
    ('id = "paper-prototype"\nD0_mm = 30,5',
     "Expected newline or end of document after a statement (at line 8, column 11); a decimal "
     "comma: TOML numbers take a point, D0_mm = 30.5"),
    # a word without quotes, Python's True: 'Invalid value'
    ('id = paper-prototype', "Invalid value (at line 7, column 6); a text value goes in quotes: "
     'id = "paper-prototype"'),
    ('id = "paper-prototype"\nflag = True', "Invalid value (at line 8, column 8); TOML's true "
     "and false are lower case: flag = true"),
    # any other fault is tomllib's message alone
    ('id = "paper-prototype"\nD0_mm = 30.5.1', "Expected newline or end of document after a "
     "statement (at line 8, column 13)"),
])
def test_a_toml_line_windows_users_type_says_what_it_needs(tmp_path, mkm_cli, edited, said):
    from mkm.bench.config import example_config

    text = example_config().read_text("utf-8").replace('id = "paper-prototype"', edited, 1)
    (tmp_path / "bench.toml").write_bytes(b"\xef\xbb\xbf" + text.replace("\n", "\r\n").encode())
    code, out, err = mkm_cli(["check", "--config", str(tmp_path / "bench.toml")])
    assert code == 2 and out == ""
    assert err.strip().splitlines() == [
        f"mkm check: error: config {tmp_path / 'bench.toml'} is not valid TOML: {said}"]


def _path_settings(cls, where: str) -> list[str]:
    """Every setting of ``cls`` (a section of the configuration) typed as a path, found from
    the types, nested sections included."""
    import dataclasses
    import typing

    from mkm.bench.settings import PathText

    found = []
    for name, hint in typing.get_type_hints(cls).items():
        if dataclasses.is_dataclass(hint):
            found += _path_settings(hint, f"{where}.{name}")
        elif PathText in (hint, *typing.get_args(hint)):
            found.append(f"{where}.{name}")
    return found


def _config_path_settings() -> list[str]:
    from mkm.bench.config import SECTIONS

    return [key for section, read in SECTIONS.items() if isinstance(read, type)
            for key in _path_settings(read, section)]


def test_the_configuration_has_path_settings_and_the_calibration_is_one():
    # the search below must find something to test: the over-force calibration is a path
    assert "safety.calibration" in _config_path_settings()


@pytest.mark.parametrize("key", _config_path_settings())
@pytest.mark.parametrize(("typed", "said"), [
    # TOML reads each \t, \n as an escape: C:, a tab, emp, a new line, ew, without a word
    ("C:\\temp\\new", "a tab (\\t) and a new line (\\n)"),
    ("D:\\bench\\results\\fits", "a backspace (\\b), a carriage return (\\r) and a form "
     "feed (\\f)"),
])
def test_a_windows_path_whose_backslashes_are_escapes_is_refused_with_the_form_to_type(
        tmp_path, mkm_cli, key, typed, said):
    from mkm.bench.config import example_config

    section, _, name = key.rpartition(".")
    text = example_config().read_text("utf-8").replace(
        f"[{section}]\n", f'[{section}]\n{name} = "{typed}"\n', 1)
    (tmp_path / "bench.toml").write_text(text, encoding="utf-8")
    code, out, err = mkm_cli(["check", "--config", str(tmp_path / "bench.toml")])
    assert code == 2 and out == ""
    assert err.strip().splitlines()[-1] == (
        f"mkm check: error: config {tmp_path / 'bench.toml'}: {key} = \"{typed}\" reads as a "
        f"path with {said} in it: in \"...\" a \\ begins an escape; write a Windows path in "
        f"single quotes, {name} = '{typed}', or with / for \\")
    # the form it offers is read as typed
    fixed = text.replace(f'{name} = "{typed}"', f"{name} = '{typed}'")
    read = parse_config(fixed)
    for part in key.split("."):
        read = getattr(read, part)
    assert read == typed


def test_command_is_clamped_and_monitor_scaled():
    r = load_config().regulator
    assert r.command_volts(1.0) == pytest.approx(2.5)  # 0-10 V over 0-4 bar full scale
    assert r.command_volts(9.0) == pytest.approx(2.5 / 4.0 * 10.0)  # clamped to 2.5 bar
    assert r.command_volts(-1.0) == 0.0
    assert r.monitor_bar(1.0) == pytest.approx(0.0)  # 1-5 V monitor over 0-4 bar
    assert r.monitor_bar(5.0) == pytest.approx(4.0)


# Settings a USB-6001 cannot run (NI USB-6001/6002/6003 User Guide and Specifications): each
# passed `mkm check` and started acquiring before issue 12.
DEVICE_IMPOSSIBLE = [
    ("[loadcell]\nchannel = 'ai9'", r"loadcell\.channel='ai9' is invalid: the USB-6001 has "
     r"inputs ai0 to ai7"),
    ("[regulator]\ncommand_channel = 'ao2'", r"command_channel='ao2' is invalid: the USB-6001 "
     r"has outputs ao0, ao1"),
    ("[regulator]\nmonitor_channel = 'ai5'", r"monitor_channel='ai5' cannot be differential on "
     r"the USB-6001: only ai0, ai1, ai2, ai3 are \(paired with ai4, ai5, ai6, ai7\)"),
    ("[regulator]\nmonitor_channel = 'ai0'", r"are both ai0: expected two different inputs"),
    ("[daq]\nterminal_config = 'nrse'", r"the USB-6001 has only differential and rse inputs"),
    ("[daq]\nterminal_config = 'pseudodifferential'", r"no NRSE or pseudo-differential mode"),
    ("[daq]\nsample_rate_hz = 1e6", r"samples at most 20000 S/s"),
    ("[daq]\nsample_rate_hz = 15000", r"15000 on 2 inputs is 30000 S/s: .* 20000 S/s in "
     r"aggregate"),
    ("[daq]\nbuffer_s = 1e9", r"daq\.buffer_s=1e\+09 is invalid: expected 600 s .* to 86400 s"),
    ("[daq]\nsample_rate_hz = 10000\nbuffer_s = 3600", r"72000000 buffered values"),
    ("[regulator]\nmonitor_V_at_full_scale = 15", r"monitor_V_at_full_scale=15 is invalid: the "
     r"USB-6001's inputs read \+-10 V"),
    ("[daq]\nread_block_samples = 100", r"read_block_samples=100 is 10 s of samples at 10 Hz: "
     r"expected blocks of at most 1 s"),
    ("[daq]\nread_timeout_s = 0.001", r"read_timeout_s=0.001 is too short for blocks of 0.1 s"),
]


@pytest.mark.parametrize("extra, message", DEVICE_IMPOSSIBLE,
                         ids=[e.split("\n")[1] for e, _ in DEVICE_IMPOSSIBLE])
def test_device_impossible_settings_are_refused(extra, message):
    with pytest.raises(ValueError, match=message):
        parse_config(with_settings(extra))


def test_rse_allows_every_input():
    c = parse_config(with_settings("[daq]\nterminal_config = 'rse'\n[regulator]\n"
                                   "monitor_channel = 'ai7'"))
    assert c.ai_channels == ["ai0", "ai7"]


# "m1." names a folder "..._m1." that Windows makes as "..._m1"
@pytest.mark.parametrize("muscle_id", ["x" * 300, "a\nb", "a\tb", "a b", "$F_{max}$", "../up",
                                       "", "m1."])
def test_muscle_ids_that_cannot_name_a_folder_or_a_label(muscle_id):
    text = BASE.replace('id = "m1"', f"id = {muscle_id!r}".replace("'", '"')
                        .replace("\n", "\\n").replace("\t", "\\t"))
    with pytest.raises(ValueError, match=r"muscle\.id=.* is invalid: expected 1 to 64 ASCII "
                       r"letters"):
        parse_config(text)


@pytest.mark.parametrize("muscle_id", ["Müller-Muskel", "_m1", "µm-tube"])
def test_a_refused_muscle_id_is_told_what_the_pattern_allows(muscle_id):
    """The message names the rule of ``MUSCLE_ID_PATTERN``: ASCII letters (an umlaut is refused
    though it is a letter) and a first character that is a letter or digit."""
    from mkm.fem.limits import check_muscle_id

    with pytest.raises(ValueError) as info:
        check_muscle_id(muscle_id)
    assert str(info.value) == (
        f"muscle.id={muscle_id!r} ({len(muscle_id)} characters) is invalid: expected 1 to 64 "
        "ASCII letters (no accents), digits or . _ + -, starting with a letter or digit and not "
        "ending in '.' (it names the run folder and labels figures)")


def test_a_refused_device_name_says_ascii():
    with pytest.raises(ValueError, match=r"daq\.device='Gerät1' \(6 characters\) is invalid: "
                       r"expected a device name of 1 to 64 ASCII letters \(no accents\), "
                       r"digits, spaces or _ \. -, starting with a letter, digit or _"):
        parse_config(with_settings('[daq]\ndevice = "Gerät1"'))


@pytest.mark.parametrize("name, value, message", [
    ("D0_mm", 1e9, r"muscle\.D0_mm=1e\+09 is invalid: expected an inner diameter in \[1, 500\] mm"),
    ("D0_mm", 1e-300, r"muscle\.D0_mm=1e-300 is invalid"),
    ("L0_mm", 1e-9, r"muscle\.L0_mm=1e-09 is invalid: expected a length at rest in \[10, 3000\]"),
    ("t0_mm", 20.0, r"muscle\.t0_mm=20 is too thick for D0_mm=30"),
])
def test_geometry_is_in_the_muscle_types_limits(name, value, message):
    # --D0 1e9 gave 3e17 N; issue 20: D0 1e-300 mm and L0 1e-9 mm were accepted
    with pytest.raises(ValueError, match=message):
        load_config().replace(muscle={name: value})


def test_huge_staircases_are_refused_with_their_duration():
    # 0.0001:2.5:0.0001 bar is 25,000 pressures, 50,000 steps up and down: 5 to 37 days
    with pytest.raises(ValueError, match=r"plans 49999 steps, 5\.2 to 37\.6 days: "
                                         r"expected at most 2000 steps"):
        load_config(pressures_bar=[k * 1e-4 for k in range(1, 25001)])


def test_settle_timeout_and_tare_are_bounded():
    with pytest.raises(ValueError, match=r"settle\.timeout_s=1e\+06 is invalid: expected at "
                                         r"most 3600 s"):
        load_config().replace(settle={"timeout_s": 1e6})
    # below one sample period, or a tiny rate: a tare of no samples gave NaN forces
    with pytest.raises(ValueError, match=r"tare_s=0.05 at 10 Hz gives 0 tare samples"):
        load_config().replace(sequence={"tare_s": 0.05})
    with pytest.raises(ValueError, match=r"tare_s=0.5 at 10 Hz gives 5 tare samples: expected "
                                         r"at least safety.tare_min_samples=10"):
        load_config().replace(sequence={"tare_s": 0.5})
    with pytest.raises(ValueError, match=r"read_block_samples=1 is 10 s of samples at 0.1 Hz"):
        load_config().replace(daq={"sample_rate_hz": 0.1, "read_timeout_s": 30.0,
                                   "buffer_s": 6000.0})


def test_a_monitor_without_a_live_zero_is_refused_on_a_real_bench(tmp_path, mkm_cli):
    # 0-10 V over 0-4 bar: a lost monitor (wire off, 0 V) read 0 bar, a verified vent
    text = load_config().text
    zero10 = (text.replace("monitor_V_at_zero = 1.0", "monitor_V_at_zero = 0.0")
              .replace("monitor_V_at_full_scale = 5.0", "monitor_V_at_full_scale = 10.0"))
    assert zero10 != text
    path = tmp_path / "zero10.toml"
    path.write_text(zero10)
    sim = load_config(path)  # the simulator may model such a sensor
    with pytest.raises(ValueError, match=r"^regulator\.monitor_V_at_zero=0 is invalid on a "
                       r"real bench: a lost monitor .* would pass for a vent"):
        sim.replace(daq={"backend": "ni"})
    for command in ("check", "acquire"):
        code, out, err = mkm_cli([command, "--config", str(path), "--backend", "ni",
                                  "--out", str(tmp_path / "r")] if command == "acquire" else
                                 [command, "--config", str(path), "--backend", "ni"])
        assert code == 2 and not (tmp_path / "r").exists()
        (line,) = err.strip().splitlines()
        assert line.startswith(f"mkm {command}: error: regulator.monitor_V_at_zero=0 is invalid")
    live = load_config().replace(daq={"backend": "ni"})  # 1-5 V: accepted
    assert live.regulator.monitor_V_at_zero == 1.0


def test_a_force_limit_and_tare_shift_beyond_the_capacity_together_are_refused(tmp_path,
                                                                                 mkm_cli):
    # force_limit_fraction 0.98 and tare_max_shift_N 100 on the packaged 1961 N cell, each
    # within its bounds: a 100 N load on the cell as the tare read it is its zero, and the
    # force interlock let it carry 1922 + 100 N before tripping, 2022 N, beyond its capacity
    config = tmp_path / "bench.toml"
    config.write_text(load_config().effective_text().replace(
        "force_limit_fraction = 0.9", "force_limit_fraction = 0.98"), encoding="utf-8")
    code, out, err = mkm_cli(["check", "--config", str(config)])
    assert code == 2 and out == ""
    assert err.splitlines() == [
        f"mkm check: error: config {config}: safety.force_limit_fraction=0.98 and "
        "safety.tare_max_shift_N=100 are invalid together: a load the tare takes as the zero is "
        "not seen by the force interlock, which lets the load cell carry up to 2022 N before it "
        "trips, beyond loadcell.capacity_N=1961.33: expected force_limit_fraction x capacity + "
        "tare_max_shift_N within the capacity"]
    # 0.949 x 1961.33 + 100 = 1961.3 N: within
    config.write_text(load_config().effective_text().replace(
        "force_limit_fraction = 0.9", "force_limit_fraction = 0.949"), encoding="utf-8")
    assert mkm_cli(["check", "--config", str(config)])[0] == 0


def test_every_bad_value_is_named_at_once(tmp_path, mkm_cli):
    """A 490 N load cell failed on safety.tare_max_std_N (5 N, above 1 % of 490 N), and once
    that was mended on tare_max_shift_N (100 N, above 10 %): every bad value is named in one
    go now, a line each, whether checked against another section, within one or by type."""
    config = tmp_path / "bench.toml"
    config.write_text(BASE.replace("capacity_N = 1000", "capacity_N = 490").replace(
        "sensitivity_N_per_V = 100", "sensitivity_N_per_V = 49"), encoding="utf-8")
    code, out, err = mkm_cli(["check", "--config", str(config)])
    assert code == 2 and out == ""
    assert err.splitlines() == [
        f"mkm check: error: config {config}: safety.tare_max_std_N=5 is invalid: expected 0 to "
        "4.9 N (1 % of loadcell.capacity_N=490)",
        f"mkm check: error: config {config}: safety.tare_max_shift_N=100 is invalid: expected "
        "0 to 49 N (10 % of loadcell.capacity_N=490)"]
    # two values of one section, and a value of another, each said once
    text = with_settings("[settle]\nwindow_s = -1\nhold_s = 0\n[daq]\nbuffer_s = 60\n"
                         "[sim]\nseed = 1.5")
    with pytest.raises(ValueError) as info:
        parse_config(text, "lab.toml")
    assert str(info.value).splitlines() == [
        "config lab.toml: daq.buffer_s=60 is invalid: expected 600 s (10 minutes of samples, "
        "so a stalled reader loses nothing) to 86400 s",
        "config lab.toml: settle.window_s=-1.0 is invalid: expected a number > 0",
        "config lab.toml: settle.hold_s=0.0 is invalid: expected a number > 0",
        "config lab.toml: sim.seed=1.5 is invalid: expected a whole number"]


def test_every_bad_value_of_the_muscle_is_named_at_once():
    """[muscle] and its tolerances name every bad value, a line each: muscle.eps = "2 bar"
    beside muscle.tolerances.t0_mm = "abc" (a fresh draw, seed 2026120728), and
    several bad numbers of the muscle itself."""
    text = BASE.replace('id = "m1"', 'id = "a/b"').replace("D0_mm = 30", 'D0_mm = "x"').replace(
        "t0_mm = 3", "t0_mm = -1").replace("L0_mm = 282", "L0_mm = 1e9").replace(
        "eps = 0", 'eps = "2 bar"\n[muscle.tolerances]\nt0_mm = "abc"')
    with pytest.raises(ValueError) as info:
        parse_config(text, "lab.toml")
    lines = str(info.value).splitlines()
    assert [line.split("=")[0].split(" ")[2] for line in lines] == [
        "muscle.tolerances.t0_mm", "muscle.id", "muscle.eps", "muscle.D0_mm", "muscle.t0_mm",
        "muscle.L0_mm"]
    assert lines[2] == ("config lab.toml: muscle.eps='2 bar' is not a number: expected the "
                        "number alone, without 'bar' (in the unit the name or --help gives)")
    assert lines[4] == ("config lab.toml: muscle.t0_mm=-1 is invalid: expected a wall "
                        "thickness in [0.05, 100] mm")
    # a misspelt key is named as no field, not as a missing D0_mm too
    with pytest.raises(ValueError) as info:
        parse_config(BASE.replace("D0_mm = 30", "D0mm = 30"), "lab.toml")
    (line,) = str(info.value).splitlines()
    assert line.startswith("config lab.toml: muscle.D0mm is not a field of a muscle")


def test_a_sections_other_values_are_checked_beside_a_value_of_the_wrong_type():
    """buffer_s = "ten" hid read_retries = 1000 of the same [daq] (and nonlinearity 0.5 of
    [loadcell] hid nothing only because offset_V was a number): the section's own checks
    stopped at the type error. They run now with the mistyped value at its default, and say
    every other bad value; none is said about the default the file does not hold."""
    text = with_settings('[daq]\nbuffer_s = "ten"\nread_retries = 1000\n[loadcell]\n'
                         'offset_V = "x"\nnonlinearity_fraction_fs = 0.5\n'
                         '[regulator]\nfull_scale_bar = "4"\nmax_pressure_bar = 5')
    with pytest.raises(ValueError) as info:
        parse_config(text, "lab.toml")
    assert str(info.value).splitlines() == [
        "config lab.toml: daq.buffer_s='ten' is invalid: expected a number",
        "config lab.toml: daq.read_retries=1000 is invalid: expected 0 to 100",
        # 2 s x (1000 + 1) retries
        "config lab.toml: daq.read_timeout_s=2 with read_retries=1000 lets a run go 2002 s "
        "without a reading: expected at most 60 s in all",
        "config lab.toml: loadcell.offset_V='x' is invalid: expected a number",
        "config lab.toml: loadcell.nonlinearity_fraction_fs=0.5 is invalid: expected 0 to 0.05 "
        "(a fraction) (a data-sheet bound beyond 5 % is not a load cell)",
        # max_pressure_bar is checked against full_scale_bar: not against its default 4 bar
        "config lab.toml: regulator.full_scale_bar='4' is invalid: expected a number"]


def test_a_gap_wider_than_the_tubes_radius_is_refused():
    """[sim.truth] gap_mm = 30 around a 40 mm tube was simulated: a braid 106 mm wide around a
    46 mm tube. The gap is bounded by the tube's outer radius, the true tube's for the
    simulated truth, the declared one's for the muscle."""
    from mkm.fem.muscle import Muscle

    text = with_settings("[sim.truth]\ngap_mm = 30\nD0_mm = 40")
    with pytest.raises(ValueError) as info:
        parse_config(text, "lab.toml")
    # outer radius 40/2 + 3 = 23 mm
    assert str(info.value) == (
        "config lab.toml: sim.truth.gap_mm=30 is too wide for D0_mm=40, t0_mm=3: expected "
        "gap_mm < D0_mm/2 + t0_mm = 23 mm (the tube's outer radius: a braid more than twice "
        "the tube's width is no muscle's sleeve)")
    assert parse_config(with_settings("[sim.truth]\ngap_mm = 22.9\nD0_mm = 40")
                        ).sim.truth.gap_mm == 22.9
    with pytest.raises(ValueError, match=r"^config lab\.toml: muscle\.gap_mm=18 is too wide "
                                         r"for D0_mm=30, t0_mm=3: expected gap_mm < D0_mm/2 "
                                         r"\+ t0_mm = 18 mm"):
        parse_config(with_settings("[muscle]\ngap_mm = 18"), "lab.toml")
    assert Muscle(30.0, 3.0, gap_mm=0.5).gap_mm == 0.5
