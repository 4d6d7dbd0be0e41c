"""Dataset grids (fem/dataset/grid.py): Table 1 of the paper, TOML parsing and its errors."""

import re

import pandas as pd
import pytest

from mkm.cli import main
from mkm.fem.calibration import calibrated
from mkm.fem.dataset.build import make_jobs
from mkm.fem.dataset.grid import load_grid, parse_grid

GRID = """
pressure_bar = "0:2:1"
D0_mm = [30, 40]
t0_mm = 2.5
eps = [0.0, 0.1]
L0_mm = 282
"""


def test_paper_grid_is_table_1_of_the_paper():
    # Antonelli et al. 2025, Table 1: 6 pressures x 3 D0 x 3 t0 x 3 eps, L0 = 282 mm
    grid = load_grid("paper")
    assert grid.pressure_bar == (0.0, 0.5, 1.0, 1.5, 2.0, 2.5)
    assert grid.D0_mm == (30.0, 40.0, 50.0)
    assert grid.t0_mm == (2.0, 3.0, 4.0)
    assert grid.eps == (0.0, 0.1, 0.2)
    assert grid.L0_mm == (282.0,)
    jobs = make_jobs(grid, "eq2")
    assert len(jobs) == 27
    assert sum(len(job.pressure_bar) for job in jobs) == 162
    # theta0 is left out of the grid: each job carries the model's calibrated angle
    assert {job.theta0_deg for job in jobs} == {calibrated("eq2-inner")["theta0_deg"]}


def test_grid_range_includes_its_stop():
    grid = parse_grid('pressure_bar = "0:2.5:0.25"\nD0_mm = 35\nt0_mm = 2.5\neps = 0.05', "g")
    assert len(grid.pressure_bar) == 11 and grid.pressure_bar[-1] == 2.5
    assert grid.theta0_deg == (None,) and grid.L0_mm == (None,)


@pytest.mark.parametrize("text, message", [
    ("D0 = [30]", "unknown key 'D0': expected some of pressure_bar, D0_mm"),
    ("D0_mm = []", "D0_mm is an empty list: expected at least one value"),
    ("t0_mm = -2", "t0_mm=-2 is negative: expected values >= 0"),
    ("t0_mm = 15", "t0_mm=15 is too thick for D0_mm=30: expected t0_mm < D0_mm/2 = 15"),
    ("eps = [0, 10, 20]", r"eps=10 is invalid: expected a shortening ratio in \[0, 1\)"),
    ('pressure_bar = "0:2.5"', "pressure_bar '0:2.5' is malformed: expected start:stop:step"),
    ('pressure_bar = "2:0:0.5"', "stop 0 is below start 2"),
    ('D0_mm = ["30"]', "D0_mm='30' is not a number"),
    ("D0_mm = [30, 30]", "D0_mm lists 30 twice"),
    ("theta0_deg = 60", "theta0_deg=60 is invalid: expected theta0_deg < 54.7356"),
    # below LIMITS (fem/limits.py) a value is a typo: 0.5 deg gave Equation 2 1.3 MN at 1 bar
    ("theta0_deg = 0.5", r"theta0_deg=0.5 is invalid: expected a braid angle at rest in \[1, 89\]"),
    ("L0_mm = 0", r"L0_mm=0 is invalid: expected a length at rest in \[10, 3000\] mm"),
    ("L0_mm = 5", r"L0_mm=5 is invalid: expected a length at rest in \[10, 3000\] mm"),
])
def test_bad_grid_gives_clear_error(text, message):
    base = {"pressure_bar": "pressure_bar = [0, 1]", "D0_mm": "D0_mm = 30", "t0_mm": "t0_mm = 2",
            "eps": "eps = 0.1"}
    key = text.split("=")[0].strip()
    lines = [text] + [line for k, line in base.items() if k != key]
    with pytest.raises(ValueError, match=f"^grid bad.toml: .*{message}"):
        parse_grid("\n".join(lines), "bad.toml")


def test_missing_grid_key_is_named():
    with pytest.raises(ValueError, match="missing key 'eps': expected pressure_bar, D0_mm"):
        parse_grid("pressure_bar = 1\nD0_mm = 30\nt0_mm = 2", "g")


def test_bad_grid_file_on_the_command_line(tmp_path, capsys):
    bad = tmp_path / "bad.toml"
    bad.write_text(GRID.replace("t0_mm", "t_mm"))
    code = main(["fem", "dataset", "--grid", str(bad), "--model", "eq2", "--out",
                 str(tmp_path / "d.csv"), "--cache", str(tmp_path / "cache")])
    err = capsys.readouterr().err
    assert code == 2
    assert err == f"mkm fem dataset: error: grid {bad}: unknown key 't_mm': expected some of " \
                  "pressure_bar, " \
                  "D0_mm, t0_mm, eps, L0_mm, theta0_deg\n"
    assert not (tmp_path / "d.csv").exists()


def test_a_calibration_without_the_models_angle_names_the_grid_not_theta0(tmp_path):
    # fem dataset has no --theta0 (the error said "or pass --theta0 29.2"): the angle of a
    # model the calibration has no entry for is the grid's theta0_deg
    import json

    from mkm.fem.calibration import Calibration

    lab = tmp_path / "calibration.json"
    lab.write_text(json.dumps({"thickwall": {"theta0_deg": 29.2, "identified": {},
                                             "command": "mkm identify r1 r2 --out id20"}}))
    with pytest.raises(ValueError, match=r"^no calibrated theta0 for model 'axisym' in .*"
                       r"or pass --grid FILE with theta0_deg = 29\.2 \(the thickwall fit's "):
        make_jobs(parse_grid(GRID, "g"), "axisym", calibration=Calibration.load(lab))
    jobs = make_jobs(parse_grid(GRID + "theta0_deg = 29.2\n", "g"), "axisym",
                     calibration=Calibration.load(lab))
    assert {job.theta0_deg for job in jobs} == {29.2}


def test_a_grid_saved_by_a_windows_editor_is_read_or_named(tmp_path):
    # a BOM (Notepad's "UTF-8 with BOM") was "not valid TOML ... line 1, column 1"; a file in
    # the ANSI code page was the decoder's words alone, neither grid nor what was expected
    bom = tmp_path / "bom.toml"
    bom.write_bytes(b"\xef\xbb\xbf" + GRID.encode())
    assert load_grid(bom).D0_mm == (30.0, 40.0)
    ansi = tmp_path / "ansi.toml"
    ansi.write_bytes(GRID.encode() + b"# theta0 30\xb0\n")
    with pytest.raises(ValueError, match=rf"^grid {re.escape(str(ansi))} is not UTF-8 text "
                       r"\(byte 94 is not, as a Windows code page saves an accented letter\): "
                       r"save it as UTF-8 \(Notepad: File, Save as, Encoding UTF-8\)$"):
        load_grid(ansi)


@pytest.mark.parametrize(("name", "data", "said"), [
    ("comma.toml", GRID.replace("t0_mm = 2.5", "t0_mm = 2,5").encode(),
     "is not valid TOML: Expected newline or end of document after a statement (at line 4, "
     "column 10); a decimal comma: TOML numbers take a point, t0_mm = 2.5"),
    ("word.toml", GRID.replace("t0_mm = 2.5", "t0_mm = two").encode(),
     "is not valid TOML: Invalid value (at line 4, column 9); a text value goes in quotes: "
     't0_mm = "two"'),
    ("unicode.toml", GRID.replace("t0_mm = 2.5", "t0_mm = 2,5").encode("utf-16"),
     "is not valid TOML: Expected newline or end of document after a statement (at line 4, "
     "column 10); a decimal comma: TOML numbers take a point, t0_mm = 2.5"),
    ("missing.toml", None, "does not exist: expected 'paper' or the path of a grid TOML file; "
     "{path}.txt is there (Notepad added .txt: rename it, or save with type 'All files')"),
], ids=["decimal-comma", "word", "utf-16", "notepad-txt"])
def test_load_grid_in_python_says_what_the_command_line_says(tmp_path, capsys, name, data,
                                                             said):
    # load_grid said tomllib's words alone ('grid comma.toml: not valid TOML: Expected newline
    # ...'), read no UTF-16 and named no Notepad .txt, where `mkm fem dataset --grid` did: one
    # reader for both
    path = tmp_path / name
    if data is None:
        path.with_name(name + ".txt").write_bytes(GRID.encode())
    else:
        path.write_bytes(data)
    message = f"grid {path} {said.format(path=path)}"
    with pytest.raises(ValueError) as caught:
        load_grid(path)
    assert str(caught.value) == message
    assert main(["fem", "dataset", "--grid", str(path), "--model", "eq2", "--out",
                 str(tmp_path / "d.csv"), "--cache", str(tmp_path / "cache")]) == 2
    assert capsys.readouterr().err == f"mkm fem dataset: error: {message}\n"


def test_a_grid_file_notepad_saved_as_unicode_or_with_a_decimal_comma_on_the_command_line(
        tmp_path, capsys):
    # Notepad's "Unicode" (UTF-16) was 'cannot be read as UTF-8 text ('utf-8' codec can't
    # decode byte 0xff ...)', a decimal comma tomllib's 'Expected newline or end of document
    # after a statement' alone, where a bench configuration so saved or typed is read or said
    unicode = tmp_path / "unicode.toml"
    unicode.write_bytes(GRID.replace("\n", "\r\n").encode("utf-16"))
    out = tmp_path / "d.csv"
    assert main(["fem", "dataset", "--grid", str(unicode), "--model", "eq2", "--out", str(out),
                 "--cache", str(tmp_path / "cache"), "--no-progress"]) == 0
    assert len(pd.read_csv(out)) == 3 * 2 * 2  # the grid's pressures x D0 x eps
    comma = tmp_path / "comma.toml"
    comma.write_text(GRID.replace("t0_mm = 2.5", "t0_mm = 2,5"), encoding="utf-8")
    capsys.readouterr()
    assert main(["fem", "dataset", "--grid", str(comma), "--model", "eq2", "--out",
                 str(tmp_path / "e.csv"), "--cache", str(tmp_path / "cache")]) == 2
    assert capsys.readouterr().err == (
        f"mkm fem dataset: error: grid {comma} is not valid TOML: Expected newline or end of "
        f"document after a statement (at line 4, column 10); a decimal comma: TOML "
        "numbers take a point, t0_mm = 2.5\n")
