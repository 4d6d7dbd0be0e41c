"""The table reader: layouts labs use, headers in common spellings, units converted by pint."""

from __future__ import annotations

import re
import zipfile

import numpy as np
import pandas as pd
import pytest

from mkm.bench.tables import (
    Recognition,
    check_channel_times,
    column_values,
    counts_rows,
    directions,
    parse_assignments,
    parse_header,
    parse_scaling,
    parse_unit,
    plain_number,
    read_tables,
    recognise,
    unread_time_columns,
)

# Units by their definitions (not by the code under test): the international pound is
# 0.45359237 kg, standard gravity 9.80665 m/s^2, the inch 0.0254 m.
LBF_N = 0.45359237 * 9.80665
KGF_N = 9.80665
PSI_BAR = LBF_N / 0.0254**2 / 1e5


@pytest.mark.parametrize("header, name, unit", [
    ("P", "p", None), ("Pressure (bar)", "pressure", "bar"), ("pressure [kPa]", "pressure", "kPa"),
    ("p_psi", "p", "psi"), ("Force (N)", "force", "N"), ("F [kgf]", "f", "kgf"),
    ("load_lbf", "load", "lbf"), ("time", "time", None), ("t (s)", "t", "s"),
    ("direction", "direction", None), ("eps", "eps", None), ("contraction (%)", "contraction", "%"),
    ("length (mm)", "length", "mm"), ("pressure_bar_mean", "pressure", "bar"),
    ("force_N_mean", "force", "N"), ("force_N_std", "force std", "N"),
    ("set_pressure_bar", "set pressure", "bar"), ("Time in s", "time", "s"),
    ("zero_entry", "zero entry", None), ("Pressure, bar", "pressure", "bar"),
    ("eps (%", "eps (%", None),  # a bracket left open: no unit, and no traceback
    ("Force, kN", "force", "kN"), ("Date&Time", "date time", None),
    # 'min' after a force's or a pressure's name is their minimum, no minute; after a time's
    # name it is the minute
    ("F_min", "f min", None), ("Kraft_min", "kraft min", None), ("p_min", "p min", None),
    ("t_min", "t", "min"), ("Zeit_min", "zeit", "min"),
    # an Arduino sketch's header naming the call it logs: was a time in seconds
    ("millis()", "millis", "ms"), ("micros()", "micros", "us"),
    # a clock's zone or origin in its brackets: refused as no unit of time
    ("Time (UTC)", "time", None), ("Zeit (MEZ)", "zeit", None), ("Time [UTC+01:00]", "time", None),
    ("Timestamp (ms since epoch)", "timestamp", "ms"), ("t (s since 1970-01-01)", "t", "s"),
    ("Zeit [ms seit Start]", "zeit", "ms"), ("F (N since tare)", "f", "N since tare"),
])
def test_headers_in_common_spellings(header, name, unit):
    assert parse_header(header) == (name, unit)


@pytest.mark.parametrize("text", ["(%", "N/0", "bar(", "**"])
def test_text_pint_cannot_parse_is_no_unit(text):
    assert parse_unit(text) is None  # not a traceback from pint's parser


def test_a_column_named_with_a_comma_in_its_header():
    assert parse_assignments("force=Kraft, gemessen,pressure=Druck", "--columns") == {
        "force": "Kraft, gemessen", "pressure": "Druck"}
    assert parse_assignments("pressure=kPa, force = lbf", "--units") == {
        "pressure": "kPa", "force": "lbf"}
    with pytest.raises(ValueError, match="--columns item 'weight=F' is invalid"):
        parse_assignments("pressure=P,weight=F", "--columns")


@pytest.mark.parametrize("text, option, message", [
    ("force=N,force=kN", "--units", "--units gives force twice (force=N, force=kN): expected one "
     "value per role"),
    ("pressure=P,force=F,pressure=Druck", "--columns", "--columns gives pressure twice "
     "(pressure=P, pressure=Druck)"),
])
def test_a_role_given_twice_is_refused(text, option, message):
    with pytest.raises(ValueError) as caught:
        parse_assignments(text, option)
    assert message in str(caught.value)


def _one(tmp_path, text, name="lab.csv"):
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    (table,) = read_tables(path)
    return table, recognise(table)


def test_units_converted_by_their_definitions(tmp_path):
    path = tmp_path / "a.csv"
    path.write_text("p_psi,F [kgf],load_lbf,pressure [kPa]\n10,2,3,150\n20,4,6,250\n")
    (table,) = read_tables(path)
    # two columns claim the pressure (and two the force): the reader does not guess
    with pytest.raises(ValueError, match="two pressure columns, 'p_psi' and 'pressure"):
        recognise(table, {"force": "F [kgf]"})
    found = recognise(table, {"pressure": "p_psi", "force": "F [kgf]"})
    np.testing.assert_allclose(column_values(table, found["pressure"]),
                               [10 * PSI_BAR, 20 * PSI_BAR], rtol=1e-12)
    np.testing.assert_allclose(column_values(table, found["force"]), [2 * KGF_N, 4 * KGF_N],
                               rtol=1e-12)
    table, found = _one(tmp_path, "pressure [kPa];load_lbf\n150;3\n250;6\n", "b.csv")
    np.testing.assert_allclose(column_values(table, found["pressure"]), [1.5, 2.5], rtol=1e-12)
    np.testing.assert_allclose(column_values(table, found["force"]), [3 * LBF_N, 6 * LBF_N],
                               rtol=1e-12)


def test_a_column_named_without_its_unit_is_found(tmp_path):
    # was: "--columns pressure='Kanal 1': lab.csv has no such column: it has 'Kanal 1 [bar]'"
    table, _ = _one(tmp_path, "Kanal 1 [bar];Kanal 2 (kN);Kanal 2 [V]\n0;0,5;1\n2;1,5;2\n")
    found = recognise(table, {"pressure": "Kanal 1", "force": "Kanal 2 (kN)"})
    assert (found["pressure"].header, found["pressure"].unit) == ("Kanal 1 [bar]", "bar")
    np.testing.assert_allclose(column_values(table, found["pressure"]), [0.0, 2.0])
    # two headers of that name (with two units): which one is not guessed
    with pytest.raises(ValueError, match=re.escape(
            "--columns force='Kanal 2': lab.csv has 2 columns of that name, 'Kanal 2 (kN)', "
            "'Kanal 2 [V]': expected one; name it with its unit")):
        recognise(table, {"pressure": "Kanal 1", "force": "Kanal 2"})


def test_two_columns_of_one_name_are_refused_not_the_first_taken(tmp_path):
    # a logger that repeats a header: --columns force='Force (N)' took column B and dropped
    # column C without a word, after the error had said to choose one that way
    path = tmp_path / "dup.csv"
    path.write_text("P (bar),Force (N),Force (N)\n0,0,0\n1,100,101\n", encoding="utf-8")
    (table,) = read_tables(path)
    with pytest.raises(ValueError, match=re.escape(
            "--columns force='Force (N)': dup.csv has 2 columns named 'Force (N)' (B, C): "
            "expected one column of that name; rename the others in the file")):
        recognise(table, {"force": "Force (N)"})
    with pytest.raises(ValueError, match=re.escape(
            "dup.csv: 2 columns named 'Force (N)' (B, C), each a force column: expected one; "
            "rename the others in the file")):
        recognise(table)


def test_unit_spellings_pint_reads_otherwise(tmp_path):
    # [-] is dimensionless; MPA/mpa a megapascal (pint: millipascal), KN a kilonewton (pint:
    # knot), kp a kilopond (pint: kilopoise); all-caps MBAR, MM and S as a lab means them
    table, found = _one(tmp_path, "T [S],P [mpa],F [KN],eps [-],L [MM]\n0,0.25,0.5,0.1,250\n"
                        "1,0.5,1,0.1,250\n")
    np.testing.assert_allclose(column_values(table, found["pressure"]), [2.5, 5.0], rtol=1e-12)
    np.testing.assert_allclose(column_values(table, found["force"]), [500, 1000], rtol=1e-12)
    np.testing.assert_allclose(column_values(table, found["eps"]), [0.1, 0.1], rtol=1e-12)
    np.testing.assert_allclose(column_values(table, found["length"]), [250, 250], rtol=1e-12)
    np.testing.assert_allclose(column_values(table, found["time"]), [0, 1], rtol=1e-12)
    table, found = _one(tmp_path, "p [barg];F [kp]\n1,5;2\n2,5;4\n", "b.csv")
    np.testing.assert_allclose(column_values(table, found["pressure"]), [1.5, 2.5], rtol=1e-12)
    np.testing.assert_allclose(column_values(table, found["force"]), [2 * KGF_N, 4 * KGF_N],
                               rtol=1e-12)
    table, found = _one(tmp_path, "P [MBAR],F [N]\n500,1\n1500,2\n", "c.csv")
    np.testing.assert_allclose(column_values(table, found["pressure"]), [0.5, 1.5], rtol=1e-12)
    # a logger writing in capitals: MSEC was a megasecond, each 100 ms sample 1e8 s apart
    table, found = _one(tmp_path, "TIME (MSEC),PRESSURE (PSIG),FORCE (LBF)\n0,1,1\n100,2,2\n",
                        "d.csv")
    np.testing.assert_allclose(column_values(table, found["time"]), [0.0, 0.1], rtol=1e-12)
    np.testing.assert_allclose(column_values(table, found["pressure"]), [PSI_BAR, 2 * PSI_BAR],
                               rtol=1e-12)
    # ... and H an hour: was pint's henry, refused as "not a unit of time" (TIME_H: no time)
    for header in ("TIME (H)", "TIME_H"):
        table, found = _one(tmp_path, f"{header},PRESSURE (BAR),FORCE (N)\n0,1,1\n0.5,2,2\n",
                            "e.csv")
        assert found["time"].header == header
        np.testing.assert_allclose(column_values(table, found["time"]), [0.0, 1800.0],
                                   rtol=1e-12)


def test_a_mega_or_milli_prefix_in_a_header_of_capitals_is_not_guessed(tmp_path):
    # 'FORCE (MN)' of a logger writing in capitals was read as meganewtons, a lab's
    # millinewtons a million times too large (refused only as beyond any load cell)
    text = "PRESSURE (BAR),FORCE (MN)\n1,500\n2,1000\n"
    with pytest.raises(ValueError, match=re.escape(
            "lab.csv: column 'FORCE (MN)': 'MN' written in capitals may be 'mN' (millinewton) "
            "or 'MN' (meganewton), a million apart: not guessed: expected --units force=mN (or "
            "force=MN)")):
        _one(tmp_path, text)
    path = tmp_path / "given.csv"
    path.write_text(text, encoding="utf-8")
    (table,) = read_tables(path)
    found = recognise(table, units={"force": "mN"})
    np.testing.assert_allclose(column_values(table, found["force"]), [0.5, 1.0], rtol=1e-12)
    # a header in mixed case says its prefix; capitals labs use for one prefix are read so
    table, found = _one(tmp_path, "Pressure (bar),Force (MN)\n1,5e-4\n2,1e-3\n", "mega.csv")
    np.testing.assert_allclose(column_values(table, found["force"]), [500, 1000], rtol=1e-12)
    table, found = _one(tmp_path, "P [bar],F [mN]\n1,500\n2,1000\n", "milli.csv")
    np.testing.assert_allclose(column_values(table, found["force"]), [0.5, 1.0], rtol=1e-12)
    table, found = _one(tmp_path, "PRESSURE (MPA),FORCE (N)\n0.1,5\n0.2,10\n", "mpa.csv")
    np.testing.assert_allclose(column_values(table, found["pressure"]), [1.0, 2.0], rtol=1e-12)


@pytest.mark.parametrize("header", ["Zeit [sek]", "Zeit [Sek.]", "Time (sec.)", "Zeit_sek"])
def test_seconds_as_german_and_abbreviated_headers_write_them(header, tmp_path):
    # 'Zeit [sek]' was refused: "'sek' is not a unit of time (expected one like s)"
    table, found = _one(tmp_path, f"{header};Druck [bar];Kraft [N]\n0,5;1;10\n1,5;2;20\n")
    assert found["time"].header == header
    np.testing.assert_allclose(column_values(table, found["time"]), [0.5, 1.5])
    table, found = _one(tmp_path, "Zeit [msek];Druck [bar];Kraft [N]\n500;1;10\n1500;2;20\n",
                        "ms.csv")
    np.testing.assert_allclose(column_values(table, found["time"]), [0.5, 1.5])


def test_pounds_in_capitals_name_the_option_that_reads_them_as_a_force(tmp_path):
    # 'Force (LBS)' was refused as "not a unit of force" with no word of --units force=lbf,
    # which 'Force (lbs)' names
    for header in ("Force (lbs)", "Force (LBS)"):
        with pytest.raises(ValueError, match=r"is not a unit of force .*--units force=lbf"):
            _one(tmp_path, f"Pressure (psi),{header}\n10,1\n20,2\n")


def test_milli_units_in_capitals_are_not_mega(tmp_path):
    # pint reads MV, MA and MMHG as a megavolt, a megaampere and a megametre of mercury: a load
    # cell amplifier's millivolts scaled a billion times too large, a 4-20 mA loop refused
    path = tmp_path / "lab.csv"
    path.write_text("PRESSURE (MMHG),FORCE (MV)\n750.06,0\n1500.12,1000\n")
    (table,) = read_tables(path)
    found = recognise(table, scaling=parse_scaling("force=200N/V", None))
    # the conventional millimetre of mercury: 13595.1 kg/m^3 * 9.80665 m/s^2 * 1 mm
    np.testing.assert_allclose(column_values(table, found["pressure"]),
                               np.array([750.06, 1500.12]) * 13595.1 * 9.80665e-3 / 1e5,
                               rtol=1e-6)
    np.testing.assert_allclose(column_values(table, found["force"]), [0.0, 200.0])
    path.write_text("P (MA),F (N)\n4,0\n12,100\n")
    (table,) = read_tables(path)
    found = recognise(table, scaling=parse_scaling(None, None, "pressure=0:10bar"))
    np.testing.assert_allclose(column_values(table, found["pressure"]), [0.0, 5.0])
    with pytest.raises(ValueError, match=r"'KG' is not a unit of force .*--units force=kgf"):
        _one(tmp_path, "P (bar),F (KG)\n1,10\n", "kg.csv")


# the technical atmosphere is 1 kgf/cm^2; the conventional inch of mercury the pressure of an
# inch of mercury of 13595.1 kg/m^3 under standard gravity (3386.389 Pa)
AT_BAR = KGF_N / 0.01**2 / 1e5
INHG_BAR = 0.0254 * 13595.1 * 9.80665 / 1e5


@pytest.mark.parametrize("header, cells, bar_per_unit", [
    ("Druck [at]", ("1,5", "2,5"), AT_BAR), ("Druck (atü)", ("1,5", "2,5"), AT_BAR),
    ("Druck", ("1.5 at", "2.5 at"), AT_BAR), ("Pressure [inHg]", ("1,5", "2,5"), INHG_BAR),
    ("Pressure (in Hg)", ("1,5", "2,5"), INHG_BAR), ("p [in. Hg]", ("1,5", "2,5"), INHG_BAR),
    ("Pressure", ("1,5 in Hg", "2,5 in Hg"), INHG_BAR),
    ("P", ("1,5 in. Hg", "2,5 in. Hg"), INHG_BAR),
])
def test_technical_atmospheres_and_inches_of_mercury(header, cells, bar_per_unit, tmp_path):
    # were refused: 'at' read as the English word ("'at' is not a unit of pressure"), 'in Hg'
    # as an inch times mercury's density
    assert AT_BAR == pytest.approx(0.980665, rel=1e-15)
    assert INHG_BAR * 1e5 == pytest.approx(3386.389, abs=5e-4)
    table, found = _one(tmp_path, f"{header};F (N)\n{cells[0]};2\n{cells[1]};4\n")
    np.testing.assert_allclose(column_values(table, found["pressure"]),
                               [1.5 * bar_per_unit, 2.5 * bar_per_unit], rtol=1e-12)


@pytest.mark.parametrize("header, bar_per_unit", [
    ("Druck [kgf/cm2]", AT_BAR), ("p (N/mm2)", 10.0), ("Pressure [lbf/in2]", PSI_BAR),
    ("Druck [kgf/cm²]", AT_BAR), ("p [N/mm^2]", 10.0),
    # the kilopond per square centimetre of a German gauge: was "'kp/cm²' is not a unit of
    # pressure" (kp alone read as kilopond, not within a unit)
    ("Druck [kp/cm²]", AT_BAR), ("Druck [kp/cm2]", AT_BAR), ("Kraft [kp]", None),
])
def test_an_area_written_with_its_exponent_as_a_digit(header, bar_per_unit, tmp_path):
    # a gauge's kgf/cm2: was "'kgf/cm2' is not a unit of pressure" (pint reads cm2 as no unit)
    if bar_per_unit is None:  # kp alone, as before: a force
        table, found = _one(tmp_path, f"P (bar);{header}\n1,5;2\n2,5;4\n")
        np.testing.assert_allclose(column_values(table, found["force"]), [2 * 9.80665,
                                                                         4 * 9.80665])
        return
    table, found = _one(tmp_path, f"{header};F (N)\n1,5;2\n2,5;4\n")
    np.testing.assert_allclose(column_values(table, found["pressure"]),
                               [1.5 * bar_per_unit, 2.5 * bar_per_unit], rtol=1e-12)


def test_a_gauge_in_kilograms_per_area_is_told_its_force_unit(tmp_path):
    # a gauge's dial in kg/cm² means kilogram-force: said, as a load cell's kg is
    with pytest.raises(ValueError, match=re.escape(
            "'kg/cm²' is not a unit of pressure (expected one like bar); if the gauge shows "
            "kilograms of weight per area, give --units pressure=kgf/cm²")):
        _one(tmp_path, "Druck [kg/cm²];F (N)\n1,5;2\n2,5;4\n")


def test_at_as_a_word_of_a_header_is_no_unit():
    # 'at' is a unit in brackets or a cell, a word in a header's name
    assert parse_header("Force at peak") == ("force peak", None)
    assert parse_header("P at") == ("p", None)


@pytest.mark.parametrize("header, bar_per_unit", [
    ("Pressure [bar(g)]", 1.0), ("Pressure (bar g)", 1.0), ("Druck [bar(ü)]", 1.0),
    ("Pressure (kPa (g))", 0.01), ("p [psi gauge]", PSI_BAR), ("p_psig", PSI_BAR),
    # the unit after the name, its mark alone in brackets: was "no pressure column among
    # 'P bar(g)'" (the name read as 'p bar', the unit as 'g')
    ("P bar(g)", 1.0), ("Druck bar (ü)", 1.0), ("p kPa (g)", 0.01), ("Pressure psi(g)", PSI_BAR),
    # German and French gauges say relative (Relativdruck, pression relative): was "'bar rel'
    # is not a unit of pressure"
    ("Druck [bar rel]", 1.0), ("Druck [bar(rel)]", 1.0), ("p [bar rel.]", 1.0),
    ("Druck [kPa relativ]", 0.01), ("Pression (bar relatif)", 1.0), ("P bar(rel)", 1.0),
])
def test_a_pressure_marked_gauge_is_read_in_its_unit(header, bar_per_unit, tmp_path):
    # bar(g) was "no pressure column among 'Pressure [bar(g)]'", bar g "not a unit of pressure"
    table, found = _one(tmp_path, f"{header};F (N)\n1,5;2\n2,5;4\n")
    assert found["pressure"].header == header
    np.testing.assert_allclose(column_values(table, found["pressure"]),
                               [1.5 * bar_per_unit, 2.5 * bar_per_unit], rtol=1e-12)


@pytest.mark.parametrize("header, unit", [
    ("Druck [bar(a)]", "bar(a)"), ("p [psia]", "psia"), ("Pressure (bar abs)", "bar abs"),
    ("P [kPa (absolute)]", "kPa (absolute)"), ("P bar(a)", "bar(a)"), ("p psi (abs)", "psi(abs)"),
    ("Druck [ata]", "ata"),
])
def test_a_pressure_marked_absolute_is_refused_saying_why(header, unit, tmp_path):
    # was "'bar(a)' is not a unit of pressure (expected one like bar)": a lab's gauge reads
    # absolute pressure 1 bar above what the muscle feels
    with pytest.raises(ValueError, match=re.escape(
            f"column {header!r}: {unit!r} is an absolute pressure: expected a gauge pressure, "
            "above the atmosphere as the regulator sets it (bar, bar(g), kPa, psi)")):
        _one(tmp_path, f"{header};F (N)\n1,5;2\n2,5;4\n")


@pytest.mark.parametrize("header", ["Absolutdruck [bar]", "p_abs [bar]", "Druck abs. [kPa]",
                                    "Pressure absolute (psi)"])
def test_a_pressure_named_absolute_is_refused_saying_why(header, tmp_path):
    # was: 'Absolutdruck [bar]' read as a gauge pressure, every step 1 bar too high, and the
    # others "no pressure column" (then named with --columns, read the same)
    with pytest.raises(ValueError, match=re.escape(
            f"lab.csv: column {header!r} is an absolute pressure (its name says so): expected "
            "a gauge pressure, above the atmosphere as the regulator sets it (bar, bar(g), kPa, "
            "psi)")):
        _one(tmp_path, f"{header};F (N)\n1,5;2\n2,5;4\n")


def test_semicolons_decimal_commas_and_a_title_row(tmp_path):
    table, found = _one(tmp_path, "Messung Muskel 7; 02.11.2026\n\nDruck (bar);Kraft (N);"
                        "Kürzung (%)\n0,5;12,25;12,2\n1,0;40,5;12,2\n")
    assert (table.separator, table.decimal, table.title_rows, table.header_row) == (";", ",", 1, 3)
    np.testing.assert_allclose(column_values(table, found["pressure"]), [0.5, 1.0])
    np.testing.assert_allclose(column_values(table, found["force"]), [12.25, 40.5])
    assert "eps" not in found  # "Kürzung" is not a spelling the reader knows: --columns
    found = recognise(table, {"eps": "Kürzung (%)"})
    np.testing.assert_allclose(column_values(table, found["eps"]), [0.122, 0.122])


@pytest.mark.parametrize("header, role", [
    ("Zugkraft [N]", "force"), ("Messkraft (kN)", "force"), ("Druckkraft [N]", "force"),
    ("Luftdruck [bar]", "pressure"), ("Betriebsdruck (kPa)", "pressure"),
    ("Pression (bar)", "pressure"), ("Effort [N]", "force"), ("Kontraktion (%)", "eps"),
    ("Verkürzung [%]", "eps"), ("Ruhelänge [mm]", "L0"), ("Länge [mm]", "length"),
    ("Minderdruck [bar]", "pressure"),
])
def test_a_compound_or_translated_header_names_its_role(header, role, tmp_path):
    # 'Zugkraft' was left unread: a German table names its force by its kind of pull
    other = "Zeit [s]" if role != "time" else "Kraft [N]"
    table, found = _one(tmp_path, f"{header};{other}\n1;2\n")
    assert found[role].header == header
    # the unit read from the header, converted as any other: 1 kN is 1000 N, 1 kPa 0.01 bar
    scale = {"Messkraft (kN)": 1000.0, "Betriebsdruck (kPa)": 0.01, "Kontraktion (%)": 0.01,
             "Verkürzung [%]": 0.01}.get(header, 1.0)
    np.testing.assert_allclose(column_values(table, found[role]), [scale])


@pytest.mark.parametrize("header, role", [
    ("Pressione", "pressure"), ("Presión", "pressure"), ("Pressão", "pressure"),
    ("Druk", "pressure"), ("Forza", "force"), ("Fuerza", "force"), ("Força", "force"),
    ("Kracht", "force"), ("Tempo", "time"), ("Tiempo", "time"), ("Tijd", "time")])
def test_italian_spanish_portuguese_and_dutch_names_are_read(header, role, tmp_path):
    # an Italian, Spanish, Portuguese or Dutch lab's columns: without a unit they were no
    # column ("no pressure or force column"), and a time column by its unit only named, the
    # record read untimed
    other = {"time": "Forza", "pressure": "Tempo", "force": "Tempo"}[role]
    table, found = _one(tmp_path, f"{header};{other}\n1;2\n")
    assert found[role].header == header
    np.testing.assert_allclose(column_values(table, found[role]), [1.0])


@pytest.mark.parametrize("other", ["T [°C]", "P [W]", "F [Hz]"])
def test_a_symbol_of_another_quantity_is_no_reading(other, tmp_path):
    # a temperature logged beside the record as 'T [°C]' was a second time column (the table
    # refused), and alone was refused as a time in °C; a power 'P [W]' a second pressure
    table, found = _one(tmp_path, f"Zeit [s];Druck [bar];Kraft [N];{other}\n0;1;100;22\n"
                        "1;2;210;23\n")
    assert {role: c.header for role, c in found.items()} == {
        "time": "Zeit [s]", "pressure": "Druck [bar]", "force": "Kraft [N]"}
    # a unit a reading may be mistaken in keeps its column, so its option is named
    with pytest.raises(ValueError, match=r"'kg' is not a unit of force .*--units force=kgf"):
        _one(tmp_path, "P [bar];F [kg]\n1;10\n", "kg.csv")


def test_a_german_benchs_actual_reading_beside_its_set_point(tmp_path):
    # was: "no pressure column among 'Druck_Soll [bar]', 'Druck_Ist [bar]', ...": Ist (the
    # actual value) is the reading, Soll (the set point) is left out
    table, found = _one(tmp_path, "Druck_Soll [bar];Druck_Ist [bar];Kraft Istwert [N]\n"
                        "1;0,98;100\n2;2,01;201\n")
    assert found["pressure"].header == "Druck_Ist [bar]"
    assert found["force"].header == "Kraft Istwert [N]"
    np.testing.assert_allclose(column_values(table, found["pressure"]), [0.98, 2.01])


@pytest.mark.parametrize("header", ["Solldruck [bar];Istdruck [bar];Sollkraft [N];Kraft [N]",
                                    "p_set [bar];p_act [bar];F_set [N];F_act [N]"])
def test_a_set_point_compound_or_abbreviation_is_left_out(header, tmp_path):
    # was: "two pressure columns, 'Solldruck [bar]' and 'Istdruck [bar]'" (a regulator's set
    # point and its reading, one word each), and "no pressure column" for p_set and p_act
    table, found = _one(tmp_path, f"{header}\n1;0,98;100;99\n2;2,01;200;201\n")
    headers = header.split(";")
    assert (found["pressure"].header, found["force"].header) == (headers[1], headers[3])
    np.testing.assert_allclose(column_values(table, found["pressure"]), [0.98, 2.01])
    np.testing.assert_allclose(column_values(table, found["force"]), [99.0, 201.0])


def test_a_german_direction_column(tmp_path):
    # was: 'Richtung' not recognised, its auf/ab left out unsaid
    table, found = _one(tmp_path, "Druck [bar];Kraft [N];Richtung\n0;0;auf\n2;200;Auf\n"
                        "2;210;ab\n0;0;Entlastung\n")
    assert found["direction"].header == "Richtung"
    assert directions(table, found["direction"]) == ["up", "up", "down", "down"]



@pytest.mark.parametrize("up, down", [("load", "Unload"), ("Increase", "decrease"),
                                      ("ascending", "descending"), ("inc", "dec"), ("up", "dn"),
                                      ("Belasten", "Entlasten"), ("aufwärts", "Abwärts")])
def test_direction_words_as_labs_write_them(up, down, tmp_path):
    # 'load'/'unload' was refused: "'load' is not a direction", and the file had to be edited
    table, found = _one(tmp_path, f"Druck [bar];Kraft [N];Richtung\n0;0;{up}\n2;200;{up}\n"
                        f"2;210;{down}\n0;0;{down}\n")
    assert directions(table, found["direction"]) == ["up", "up", "down", "down"]


def test_a_french_direction_column(tmp_path):
    # was: 'Sens' not recognised, its montée/descente left out unsaid
    table, found = _one(tmp_path, "Pression (bar);Effort (N);Sens\n0;0;montée\n2;200;Montée\n"
                        "2;210;descente\n0;0;Décharge\n")
    assert found["direction"].header == "Sens"
    assert directions(table, found["direction"]) == ["up", "up", "down", "down"]


def test_quoted_decimal_commas_in_a_comma_separated_file(tmp_path):
    # a lab's export with ',' between fields keeps its decimal commas quoted
    table, found = _one(tmp_path, 'Pressure [bar],Force [N]\n"0,0","0"\n"0,5","12,25"\n'
                        '"1,5","50,125"\n')
    assert (table.separator, table.decimal) == (",", ",")
    np.testing.assert_allclose(column_values(table, found["pressure"]), [0.0, 0.5, 1.5])
    np.testing.assert_allclose(column_values(table, found["force"]), [0.0, 12.25, 50.125])
    # beside decimal points, a quoted comma groups thousands: not a decimal comma
    table, _ = _one(tmp_path, 'P [bar],F [N]\n0.5,"1,250"\n1.5,300.5\n', "points.csv")
    assert table.decimal == "."
    # every comma three digits from the end: either reading fits, so neither is guessed
    with pytest.raises(ValueError, match=r"ambiguous.csv: numbers such as '1,500' in a "
                       "comma-separated file could be decimal commas or thousands"):
        _one(tmp_path, 'P [bar],F [N]\n1,"1,500"\n2,"2,250"\n', "ambiguous.csv")


@pytest.mark.parametrize("text, decimal", [
    ("P [bar];F [N]\n1,5;1.25\n2,5;12.634\n", ","),
    ("P [bar];F [N]\n1,5;1,25\n2,5; 12,5 \n", ","),
    ("P [bar],F [N]\n1.5,1e3\n2.5,+.5\n", "."),
    ("P [bar],F [N]\n1.5,1e3\n2.5,1_000\n3.5,2\n", "."),  # Python's float reads '1_000'
])
def test_a_column_of_plain_numbers_reads_as_cell_by_cell(text, decimal, tmp_path):
    # a whole column of plain numbers is read at numpy's speed (a 1 kHz record has 600000
    # rows); every number reads as it does alone, and a cell that is not one is named
    table, found = _one(tmp_path, text)
    assert table.decimal == decimal
    cells = [plain_number(row[1], decimal) for row in table.rows]
    if None in cells:
        with pytest.raises(ValueError, match=r"cell B3 \(column 'F \[N\]'\): '1_000' is not "
                           "a number"):
            column_values(table, found["force"])
    else:
        np.testing.assert_array_equal(column_values(table, found["force"]), cells)


def test_thousands_grouped_beside_a_decimal_mark(tmp_path):
    # a force column formatted with thousands (a Festo DMSP-20 pulls 1500 N), as German and
    # English spreadsheets export it; unambiguous beside the decimal mark
    table, found = _one(tmp_path, "Druck [bar];Kraft [N]\n1;1.234,5\n2;12.634,25 N\n", "de.csv")
    assert table.decimal == ","
    np.testing.assert_allclose(column_values(table, found["force"]), [1234.5, 12634.25])
    table, found = _one(tmp_path, 'P [bar],F [N]\n0.5,250.5\n1,"1,234.5"\n', "en.csv")
    np.testing.assert_allclose(column_values(table, found["force"]), [250.5, 1234.5])


def test_points_grouping_thousands_beside_decimal_commas_are_told_from_decimal_points(
        tmp_path):
    # a German export of pressures in Pa grouped by points ('250.000' beside '125.000,5'):
    # '250.000' was read as 250 Pa, a decimal point, every such pressure 1000 times too low
    table, found = _one(tmp_path, "Druck [Pa];Kraft [N]\n0;0\n50.000;209,79\n"
                        "125.000,5;1.048,96\n250.000;839,17\n", "de.csv")
    np.testing.assert_allclose(column_values(table, found["pressure"]),
                               [0.0, 0.5, 1.250005, 2.5], rtol=1e-15)
    # a column whose every number with a point could be either: neither is guessed
    table, found = _one(tmp_path, "Druck [Pa];Kraft [N]\n0;0\n50.000;209,79\n"
                        "250.000;1.048,96\n", "ambiguous.csv")
    with pytest.raises(ValueError, match=re.escape(
            "ambiguous.csv, cell A3 (column 'Druck [Pa]'): '50.000' in a table of decimal "
            "commas could be 50000 with its thousands grouped or 50 with a decimal point, as "
            "could every number of the column with a point: expected the file saved without "
            "thousands separators")):
        column_values(table, found["pressure"])
    # beside a decimal point written as such ('1.25'), '12.634' is one too
    table, found = _one(tmp_path, "P [bar];F [N]\n1,5;1.25\n2,5;12.634\n", "mixed.csv")
    np.testing.assert_allclose(column_values(table, found["force"]), [1.25, 12.634])

@pytest.mark.parametrize("mark", ["'", "\u2019", "\u2009", "\u202f", "\u00a0"])
def test_thousands_grouped_by_an_apostrophe_or_a_space(mark, tmp_path):
    # a Swiss spreadsheet's 1'234.5, a French one's 1 234,5 (a thin or no-break space): were
    # "'1'234.5' is not a number"
    table, found = _one(tmp_path, f"P [bar];F [N]\n1.5;250.5\n2.5;1{mark}234.5\n"
                        f"3;12{mark}634{mark}000.25 N\n", "ch.csv")
    np.testing.assert_allclose(column_values(table, found["force"]),
                               [250.5, 1234.5, 12634000.25], rtol=1e-15)
    table, found = _one(tmp_path, f"P [bar];F [N]\n1;250,5\n2;1{mark}234,5\n", "fr.csv")
    assert table.decimal == ","
    np.testing.assert_allclose(column_values(table, found["force"]), [250.5, 1234.5],
                               rtol=1e-15)
    # a mark that groups no three digits is no grouping: the cell is named
    with pytest.raises(ValueError, match=re.escape(f"{'1' + mark + '23.5'!r} is not a number")):
        table, found = _one(tmp_path, f"P [bar];F [N]\n1.5;250.5\n2;1{mark}23.5\n", "bad.csv")
        column_values(table, found["force"])


@pytest.mark.parametrize("header", ["unix_time", "Unix timestamp", "epoch", "Epoch time [s]",
                                    "POSIX time"])
def test_a_unix_time_column_is_the_time(header, tmp_path):
    # a logger's seconds since 1970 under its own name: was left unread, its record taken as
    # rows evenly spaced in time
    table, found = _one(tmp_path, f"{header},P [bar],F [N]\n1765011600.0,0,1\n"
                        "1765011600.1,0.5,2\n")
    assert found["time"].header == header
    np.testing.assert_allclose(np.diff(column_values(table, found["time"])), [0.1], rtol=1e-6)


def test_a_unix_time_column_of_whole_seconds_is_no_row_counter(tmp_path):
    # a 1 Hz logger's seconds since 1970 step by 1 as a row counter carried on does: its name
    # says they are seconds
    table, found = _one(tmp_path, "unix_time,P [bar],F [N]\n1765011600,0,1\n"
                        "1765011601,0.5,2\n1765011602,1,3\n")
    assert not counts_rows(table, found["time"])
    table, found = _one(tmp_path, "Zeitpunkt,P [bar],F [N]\n1765011600,0,1\n"
                        "1765011601,0.5,2\n1765011602,1,3\n", "counter.csv")
    assert counts_rows(table, found["time"])


def test_a_quoted_comment_over_two_lines_is_one_cell(tmp_path):
    # Excel writes a cell holding a line break (Alt+Enter in a comment) quoted over two lines:
    # was "cell A4 (column 'P [bar]'): 'Anschluss' is not a number"
    table, found = _one(tmp_path, 'P [bar];F [N];Kommentar\r\n0;3;genullt\r\n'
                        '0,5;213;"Leck am\nAnschluss; nachgezogen"\r\n1;423;\r\n1;4;"5"" hose"\r\n')
    np.testing.assert_allclose(column_values(table, found["pressure"]), [0, 0.5, 1, 1])
    assert table.rows[1][2] == "Leck am\nAnschluss; nachgezogen"
    assert table.row_numbers == [2, 3, 5, 6]
    # a quote that never closes, or that opens no cell, is no line break: each line a row
    table, found = _one(tmp_path, 'P [bar];F [N];Kommentar\n0;3;"offen\n1;423;\n', "open.csv")
    np.testing.assert_allclose(column_values(table, found["force"]), [3, 423])
    table, found = _one(tmp_path, 'P [bar],F [N],note\n0,3,5" hose\n1,423,6" hose\n',
                        "inch.csv")
    np.testing.assert_allclose(column_values(table, found["force"]), [3, 423])


def test_a_channels_own_time_column_is_the_time(tmp_path):
    # SignalExpress's text export: each channel beside its own time, 'Time - Pressure': were
    # left unread, the record taken as rows evenly spaced, its holds' times lost
    text = ("Time - Pressure\tPressure (bar)\tTime - Force\tForce (N)\n"
            "0.0\t0\t0.0\t1\n0.1\t0.5\t0.1\t2\n0.2\t1\t0.2\t3\n")
    table, found = _one(tmp_path, text, "sigex.txt")
    assert found["time"].header == "Time - Pressure"
    np.testing.assert_allclose(column_values(table, found["time"]), [0, 0.1, 0.2])
    # channels on clocks of their own are not one time: named, for --columns to choose
    table, found = _one(tmp_path, text.replace("0.1\t2", "0.15\t2"), "apart.txt")
    assert "time" not in found
    assert unread_time_columns(table, found) == ["Time - Pressure", "Time - Force"]


@pytest.mark.parametrize("suffix, how", [
    (".tdm", "NI's TDM file: open it in Excel with NI's TDM importer and save it as .xlsx"),
    (".tdms_index", "the index NI's software writes beside a TDMS file (no samples): import "
     "the .tdms file itself"),
    (".dxd", "DEWESoft's data file: export it from DEWESoft as CSV or Excel"),
    # a lab's LibreOffice sheet: was "unknown table format '.ods'"
    (".ods", "a LibreOffice (OpenDocument) spreadsheet: save it as .xlsx (File > Save As, "
     "Excel 2007-365) or as CSV"),
])
def test_a_loggers_binary_file_names_how_to_export_it(suffix, how, tmp_path):
    # was "unknown table format '.dxd': expected .csv, ...", not saying how to get one
    path = tmp_path / f"log{suffix}"
    path.write_bytes(b"TDSm\x00binary")
    with pytest.raises(ValueError, match=re.escape(
            f"log{suffix} is {how}: mkm reads .csv, .tsv, .txt, .lvm, .xls, .xlsx, .xlsm or "
            ".tdms")):
        read_tables(path)


def test_rows_of_separators_only_are_blank(tmp_path):
    # a spreadsheet's export: empty rows as ";;", between the data and after it
    table, found = _one(tmp_path, "Druck (bar);Kraft (N);Notiz\n0,5;12,25;\n;;\n1,0;40,5;ok\n"
                        ";;\n ; ; \n")
    np.testing.assert_allclose(column_values(table, found["force"]), [12.25, 40.5])
    assert table.row_numbers == [2, 4]  # a bad cell is still named by its row in the file


@pytest.mark.parametrize("end", [b"\x1a", b"\x00" * 512, b"\r\n\x1a"])
def test_an_end_of_file_mark_or_nul_padding_is_no_row(end, tmp_path):
    # a DOS program's Ctrl-Z and a logger's preallocated NULs after the last line: read as a
    # row skipped for a blank cell, or as a bad cell ('40,5\x1a'), that no editor shows
    path = tmp_path / "lab.csv"
    path.write_bytes(b"Druck [bar];Kraft [N]\r\n0,5;12,25\r\n1,0;40,5" + end)
    (table,) = read_tables(path)
    assert table.rows == [["0,5", "12,25"], ["1,0", "40,5"]]


def test_excels_unicode_text_is_utf16(tmp_path):
    # Excel's "Unicode Text (*.txt)": UTF-16 with a byte-order mark, tab separated
    path = tmp_path / "export.txt"
    path.write_bytes("Druck [bar]\tKraft [N]\r\n0\t0\r\n1,5\t150,5\r\n".encode("utf-16"))
    (table,) = read_tables(path)
    found = recognise(table)
    assert (table.separator, table.decimal) == ("\t", ",")
    np.testing.assert_allclose(column_values(table, found["pressure"]), [0.0, 1.5])
    np.testing.assert_allclose(column_values(table, found["force"]), [0.0, 150.5])


@pytest.mark.parametrize("encoding", ["utf-16-le", "utf-16-be"])
def test_utf16_without_a_byte_order_mark_is_read(encoding, tmp_path):
    # was: "export.txt has no row of numbers" (read as Latin-1, a NUL between every letter)
    path = tmp_path / "export.txt"
    path.write_bytes("Druck [bar]\tKraft [N]\r\n0\t0\r\n1,5\t150,5\r\n".encode(encoding))
    (table,) = read_tables(path)
    found = recognise(table)
    np.testing.assert_allclose(column_values(table, found["pressure"]), [0.0, 1.5])
    np.testing.assert_allclose(column_values(table, found["force"]), [0.0, 150.5])


@pytest.mark.parametrize("text, row", [
    ("Pressure (bar);Force (N)\ntare;1,5\n0;1,5\n1;100\n", "row 2 ('tare', '1,5')"),
    ("Run 7\n\nP (bar);F (N)\nZero;0,8\n0,5;40\n1;95\n", "row 4 ('Zero', '0,8')"),
])
def test_a_labelled_row_under_the_header_is_named(text, row, tmp_path):
    # was: that row read as the header, "no pressure or force column among 'tare', '1,5'"
    path = tmp_path / "lab.csv"
    path.write_text(text)
    header = "'Pressure (bar)', 'Force (N)'" if "Pressure" in text else "'P (bar)', 'F (N)'"
    with pytest.raises(ValueError) as info:
        read_tables(path)
    assert str(info.value).startswith(f"lab.csv, {row} lies between the header (row "
                                      f"{1 if 'Pressure' in text else 3}: {header}) and the "
                                      "rows of numbers: expected every row under the header")


LABVIEW_LVM = (
    "LabVIEW Measurement\t\nWriter_Version\t2\nSeparator\tTab\nDecimal_Separator\t.\n"
    "***End_of_Header***\t\n\t\nChannels\t2\t\nSamples\t3\t3\t\n"
    "Date\t2026/12/05\t2026/12/05\t\nY_Unit_Label\tkPa\tkN\t\nX_Dimension\tTime\tTime\t\n"
    "X0\t0.0000000000000000E+0\t0.0000000000000000E+0\t\nDelta_X\t0.100000\t0.100000\t\n"
    "***End_of_Header***\t\nX_Value\tDruck\tKraft\tComment\n"
    "0.000000\t0.000000\t0.035000\t\n0.100000\t250.000000\t2.730000\t\n"
    "0.200000\t800.000000\t8.660000\t\n")


#: a LabChart (ADInstruments) text export of 3 samples at 10 Hz, its time column included
LABCHART_TXT = (
    "Interval=\t0.1 s\nExcelDateTime=\t4.6361586805555557e+04\t05.12.2026 14:05:00,000000\n"
    "TimeFormat=\tStartOfBlock\nDateFormat=\t\nChannelTitle=\tDruck\tKraft\n"
    "Range=\t10.000 V\t2.000 V\nUnitName=\tkPa\tN\nTopValue=\t1000\t2000\n"
    "BottomValue=\t0\t-2000\n0.000\t0.0\t3.0\n0.100\t250.0\t253.0\n0.200\t800.0\t803.0\n")


@pytest.mark.parametrize("timed", [True, False])
def test_a_labchart_text_export_is_read_by_its_channel_titles_and_units(timed, tmp_path):
    # its header block's TopValue= and BottomValue= rows hold numbers: taken for the first
    # rows of data, under 'UnitName=;kPa;N' as the header ("no pressure or force column")
    text = LABCHART_TXT
    if not timed:  # exported without its time column, decimal commas on a German PC
        text = "\n".join(line.split("\t", 1)[1].replace(".", ",") if line[0].isdigit() else line
                         for line in text.splitlines()) + "\n"
    table, found = _one(tmp_path, text, "labchart.txt")
    assert table.header == ["Time [s]"] * timed + ["Druck [kPa]", "Kraft [N]"]
    assert table.header_row == 5 and table.row_numbers == [10, 11, 12]
    np.testing.assert_allclose(column_values(table, found["pressure"]), [0.0, 2.5, 8.0])
    np.testing.assert_allclose(column_values(table, found["force"]), [3.0, 253.0, 803.0])
    if timed:
        np.testing.assert_allclose(column_values(table, found["time"]), [0.0, 0.1, 0.2])
    else:
        assert "time" not in found and table.decimal == ","
    # its header's sampling interval, as written and in seconds: the rows' times without one
    assert table.interval == ("Interval= 0.1 s", pytest.approx(0.1, rel=1e-15))
    # a record stopped and started again: a second block, its header block under the rows
    block = "".join(text.splitlines(keepends=True)[:9])
    with pytest.raises(ValueError, match=re.escape(
            "two.txt, row 13 ('Interval='): a second block of the LabChart export begins")):
        _one(tmp_path, text + block + text.splitlines(keepends=True)[-1], "two.txt")


@pytest.mark.parametrize("name, text, header, title_rows, force", [
    # a logger's header block with a measuring range: two numbers in a labelled row
    ("logger.csv", "Gerät;HBM QuantumX\r\nMessbereich [bar];0;10\r\nAbtastrate [Hz];10\r\n"
     "\r\nZeit [s];Druck [bar];Kraft [N]\r\n0,0;0,0;3,0\r\n0,1;2,5;253,0\r\n0,2;8;803\r\n",
     ["Zeit [s]", "Druck [bar]", "Kraft [N]"], 3, [3.0, 253.0, 803.0]),
    # LabVIEW's measurement file: 'Samples', 'X0', 'Delta_X' hold two numbers each
    ("run 7.lvm", LABVIEW_LVM, ["Time [s]", "Druck [kPa]", "Kraft [kN]", "Comment"], 13,
     [35.0, 2730.0, 8660.0]),
])
def test_a_header_block_with_rows_of_numbers_is_skipped(name, text, header, title_rows, force,
                                                         tmp_path):
    # was: the row above 'Messbereich [bar];0;10' read as the header ("no pressure or force
    # column among 'Gerät', 'HBM QuantumX'"), 'Samples 3 3' under 'Channels 2' refused as a
    # labelled row, and '.lvm' an unknown table format
    table, found = _one(tmp_path, text, name)
    assert table.header == header and table.title_rows == title_rows
    assert len(table.rows) == 3
    np.testing.assert_allclose(column_values(table, found["force"]), force)
    np.testing.assert_allclose(column_values(table, found["time"]), [0.0, 0.1, 0.2])
    np.testing.assert_allclose(column_values(table, found["pressure"]), [0.0, 2.5, 8.0])


def test_a_text_xls_is_read_and_a_binary_workbook_under_another_name_is_named(tmp_path):
    # was: "unknown table format '.xls'" for the tab-separated text LabVIEW's Write To
    # Spreadsheet File saves as .xls, and "has no row of numbers" for an .xlsx renamed .csv
    table, found = _one(tmp_path, "Zeit [s]\tDruck [bar]\tKraft [N]\r\n0\t0\t3\r\n"
                        "0.1\t2.5\t253\r\n", "run 7.xls")
    np.testing.assert_allclose(column_values(table, found["force"]), [3.0, 253.0])
    old = tmp_path / "old.xls"
    old.write_bytes(b"\xd0\xcf\x11\xe0\xa1\xb1\x1a\xe1" + bytes(504))
    with pytest.raises(ValueError, match=re.escape(
            "old.xls is an Excel 97-2003 workbook: expected an .xlsx workbook or a CSV table; "
            "open it in Excel and save it as .xlsx")):
        read_tables(old)
    renamed = tmp_path / "book.csv"
    with zipfile.ZipFile(renamed, "w") as archive:
        archive.writestr("xl/workbook.xml", "<workbook/>")
    with pytest.raises(ValueError, match=re.escape(
            "book.csv is a zip archive (an .xlsx workbook?) under a .csv name: expected a text "
            "table; if it is a workbook, rename it to .xlsx")):
        read_tables(renamed)


def test_a_labview_x_column_of_another_dimension_and_a_named_unit_are_as_written(tmp_path):
    # the .lvm above: X_Value is the time and Druck, Kraft take Y_Unit_Label's kPa and kN (was:
    # read in s-less bar and N, one step per sample, 250 'bar' refused); not so here
    table, found = _one(tmp_path, LABVIEW_LVM.replace("X_Dimension\tTime\tTime",
                                                      "X_Dimension\tPoints\tPoints")
                        .replace("Druck\t", "Druck [bar]\t"), "b.lvm")
    assert table.header[:2] == ["X_Value", "Druck [bar]"] and "time" not in found


def test_a_labview_file_with_an_x_column_per_channel_gives_each_channel_its_unit(tmp_path):
    # X_Columns Multi: an X_Value before each channel. Y_Unit_Label's units went to the columns
    # by position: the second X_Value took 'kN' and Kraft none, its kN read as N, unsaid
    text = (LABVIEW_LVM.replace("X_Value\tDruck\tKraft\tComment",
                                "X_Value\tDruck\tX_Value\tKraft\tComment")
            .replace("0.000000\t0.000000\t0.035000", "0.000000\t0.000000\t0.000000\t0.035000")
            .replace("0.100000\t250.000000\t2.730000", "0.100000\t250.000000\t0.100000\t2.730000")
            .replace("0.200000\t800.000000\t8.660000", "0.200000\t800.000000\t0.200000\t8.660000"))
    table, found = _one(tmp_path, text, "multi.lvm")
    assert table.header[:4] == ["Time [s]", "Druck [kPa]", "X_Value", "Kraft [kN]"]
    np.testing.assert_allclose(column_values(table, found["force"]), [35.0, 2730.0, 8660.0])
    np.testing.assert_allclose(column_values(table, found["pressure"]), [0.0, 2.5, 8.0])
    check_channel_times(table, found)  # one time per row: nothing to say
    # the force sampled at half the rate, its x column other times on each row: its readings
    # were paired row by row with the pressure read at another time, unsaid
    path = tmp_path / "rates.lvm"
    path.write_text(text.replace("0.100000\t2.730000", "0.200000\t2.730000")
                    .replace("0.200000\t8.660000", "0.400000\t8.660000"), encoding="utf-8")
    table, found = _one(tmp_path, path.read_text(encoding="utf-8"), "rates.lvm")
    with pytest.raises(ValueError) as info:
        check_channel_times(table, found)
    assert str(info.value) == (
        "rates.lvm, cell C17 (column 'X_Value'): '0.200000' beside '0.100000' of the time "
        "column 'Time [s]': its channel was sampled at other times: expected one time per "
        "row; save the channels with one x column (X_Columns One), or each to a file of its "
        "own and join them with --join-by-time")


TDMS_CSV = ("Root Name,bench 3\nRoot Author,jdoe\nGroup Name,Untitled\n"
            "Channel Name,Time,Pressure,Load\nunit_string,s,MPa,kN\nwf_increment,0.1,0.1,0.1\n"
            "Time,Pressure,Load\n0.0,0.0,0.012\n0.1,0.25,0.45\n0.2,0.6,1.2\n")


@pytest.mark.parametrize("label", ["unit_string", "Unit String", "Units", "Einheit"])
def test_a_header_blocks_row_of_units_gives_the_columns_their_units(label, tmp_path):
    # a TDMS file exported to CSV with its channel properties above the names: the units row
    # was skipped as a title, so 0.6 MPa was read as 0.6 bar and 1.2 kN as 1.2 N, unsaid
    table, found = _one(tmp_path, TDMS_CSV.replace("unit_string", label), "export.csv")
    assert table.header == ["Time [s]", "Pressure [MPa]", "Load [kN]"]
    np.testing.assert_allclose(column_values(table, found["pressure"]), [0.0, 2.5, 6.0])
    np.testing.assert_allclose(column_values(table, found["force"]), [12.0, 450.0, 1200.0])


def test_a_header_blocks_units_that_fit_no_column_are_refused(tmp_path):
    # two units for three columns: which is whose cannot be told
    path = tmp_path / "export.csv"
    path.write_text(TDMS_CSV.replace("unit_string,s,MPa,kN", "Unit,MPa,kN"))
    with pytest.raises(ValueError) as info:
        read_tables(path)
    assert str(info.value) == (
        "export.csv, row 5 ('Unit', 'MPa', 'kN') gives 2 units for the 3 columns 'Time', "
        "'Pressure', 'Load': expected one per column, in their order; or put each unit in its "
        "column's name ('Pressure [bar]')")


def test_a_tdms_channel_path_names_its_column(tmp_path):
    # npTDMS's as_dataframe().to_csv(): each column the channel's path in the file, after the
    # frame's index; was "no pressure or force column among "/'Untitled'/'Time'", ..."
    table, found = _one(tmp_path, ",/'Untitled'/'Time',/'Untitled'/'Pressure [kPa]',"
                        "/'Untitled'/'Force'\n0,0.0,0.0,1.5\n1,0.1,150.0,12.25\n", "tdms.csv")
    assert {role: column.header for role, column in found.items()} == {
        "time": "/'Untitled'/'Time'", "pressure": "/'Untitled'/'Pressure [kPa]'",
        "force": "/'Untitled'/'Force'"}
    np.testing.assert_allclose(column_values(table, found["pressure"]), [0.0, 1.5])
    np.testing.assert_allclose(column_values(table, found["force"]), [1.5, 12.25])


def _lvm_segment(x0: float, rows: str, units: str = "kPa\tkN") -> str:
    """One segment of LabVIEW's measurement file: its channel header, heading and rows."""
    return (f"Channels\t2\t\nSamples\t2\t2\t\nDate\t2026/12/05\t2026/12/05\t\n"
            f"Y_Unit_Label\t{units}\t\nX_Dimension\tTime\tTime\t\nX0\t{x0:.16E}\t{x0:.16E}\t\n"
            "Delta_X\t0.100000\t0.100000\t\n***End_of_Header***\t\nX_Value\tDruck\tKraft\t"
            f"Comment\n{rows}")


LVM_FILE_HEADER = ("LabVIEW Measurement\t\nWriter_Version\t2\nSeparator\tTab\n"
                   "Decimal_Separator\t.\n***End_of_Header***\t\n\t\n")


def test_a_labview_file_of_several_segments_is_one_table(tmp_path):
    # Write To Measurement File's one header per segment: the second segment's channel header
    # was read as rows ("cell B14 ...: '2026/12/05' is not a number"), the import refused
    text = (LVM_FILE_HEADER + _lvm_segment(0.0, "0.0\t0.0\t0.035\n0.1\t250.0\t2.73\n") + "\n"
            + _lvm_segment(0.2, "0.2\t800.0\t8.66\n0.3\t500.0\t5.5\n"))
    table, found = _one(tmp_path, text, "segments.lvm")
    assert table.header[:3] == ["Time [s]", "Druck [kPa]", "Kraft [kN]"]
    np.testing.assert_allclose(column_values(table, found["time"]), [0.0, 0.1, 0.2, 0.3])
    np.testing.assert_allclose(column_values(table, found["pressure"]), [0.0, 2.5, 8.0, 5.0])
    assert table.row_numbers == [16, 17, 28, 29]  # each row's line in the file, as written
    # a segment whose channels changed units cannot be one column
    path = tmp_path / "changed.lvm"
    path.write_text(text.replace("Y_Unit_Label\tkPa\tkN\t\nX_Dimension\tTime\tTime\t\n"
                                 "X0\t2.0", "Y_Unit_Label\tbar\tkN\t\nX_Dimension\tTime\tTime"
                                 "\t\nX0\t2.0"), encoding="utf-8")
    with pytest.raises(ValueError) as info:
        read_tables(path)
    assert str(info.value) == ("changed.lvm, row 22: a segment's channel units ('bar', 'kN') "
                               "differ from the first segment's ('kPa', 'kN'): expected one "
                               "unit per channel; save the segments as files of their own")


@pytest.mark.parametrize("header, scale", [("millis", 1e-3), ("micros", 1e-6)])
def test_an_arduino_clock_column_is_the_time_in_its_unit(header, scale, tmp_path):
    # an Arduino logger's millis() (or micros()) beside its readings: was left out unsaid, the
    # record's rows taken as evenly spaced
    table, found = _one(tmp_path, f"{header},pressure_bar,force_N\n123456,0,0\n123556,1,100\n"
                        "123756,2,210\n")
    assert found["time"].header == header
    np.testing.assert_allclose(column_values(table, found["time"]),
                               np.array([123456, 123556, 123756]) * scale)


def test_channels_named_by_number_are_recognised_by_their_units(tmp_path):
    # a DAQ's channels as it names them ('AI 1 [bar]', 'AI 2 [N]'): was "no pressure or force
    # column among ..."; one column per unit's quantity is unambiguous
    table, found = _one(tmp_path, "Time [s];AI 1 [bar];AI 2 [kN]\n0;0;0\n0,1;1,5;0,25\n")
    assert (found["pressure"].header, found["force"].header) == ("AI 1 [bar]", "AI 2 [kN]")
    np.testing.assert_allclose(column_values(table, found["force"]), [0.0, 250.0])
    # two pressure channels: which is the muscle's is not known, so none is taken
    path = tmp_path / "two.csv"
    path.write_text("AI 1 [bar];AI 2 [bar];AI 3 [N]\n0;0;0\n1;6;100\n")
    (table,) = read_tables(path)
    assert "pressure" not in recognise(table) and recognise(table)["force"].header == "AI 3 [N]"
    # nor a set point, which is no reading
    path.write_text("p_set [bar];AI 3 [N]\n0;0\n1;100\n")
    (table,) = read_tables(path)
    assert "pressure" not in recognise(table)


def test_a_windows_1252_header_with_an_umlaut(tmp_path):
    path = tmp_path / "lab.csv"
    path.write_bytes("Länge [mm];Druck [bar];Kraft [N]\r\n250;1,5;150,5\r\n".encode("cp1252"))
    (table,) = read_tables(path)
    found = recognise(table)
    assert found["length"].header == "Länge [mm]"  # as "laenge" is
    np.testing.assert_allclose(column_values(table, found["length"]), [250.0])


def test_a_windows_1252_header_keeps_its_dashes_and_per_mille(tmp_path):
    # Excel's CSV on a German Windows is code page 1252: its en dash (0x96) and per mille
    # (0x89) were read as Latin-1's control characters, so the header shown and recorded was
    # not the file's, and --columns naming it as Excel shows it found no such column
    path = tmp_path / "lab.csv"
    header = ("Zeit [s];Druck – Ist [bar];Kraft „gemessen“ [N];Dehnung [‰];Weg [µm];"
              "Temperatur [°C]")
    path.write_bytes(f"{header}\r\n0;1,5;150,5;0,5;10;22\r\n".encode("cp1252"))
    (table,) = read_tables(path)
    assert table.header == header.split(";")
    found = recognise(table, columns={"pressure": "Druck – Ist [bar]",
                                      "force": "Kraft „gemessen“ [N]"})
    np.testing.assert_allclose(column_values(table, found["pressure"]), [1.5])
    np.testing.assert_allclose(column_values(table, found["force"]), [150.5])
    # a byte code page 1252 leaves undefined (0x81) is read as Latin-1 reads it, not refused
    path.write_bytes(b"Druck [bar];Kraft [N];Notiz\r\n1,5;150,5;\x81\r\n")
    (table,) = read_tables(path)
    assert table.rows == [["1,5", "150,5", "\x81"]]


def test_a_loggers_units_row_under_the_names(tmp_path):
    table, found = _one(tmp_path, "Messung 7\nZeit;Druck;Kraft\ns;[kPa];(N)\n0;0;1,5\n"
                        "0,1;150;12,25\n")
    assert table.header == ["Zeit [s]", "Druck [kPa]", "Kraft [N]"]
    assert (table.header_row, table.title_rows) == (2, 1)
    np.testing.assert_allclose(column_values(table, found["pressure"]), [0.0, 1.5])
    np.testing.assert_allclose(column_values(table, found["force"]), [1.5, 12.25])
    # a column without a unit under empty brackets (a row counter's '[]') takes none
    table, found = _one(tmp_path, "Nr.;Zeit;Druck;Kraft\n[];[s];[kPa];[N]\n1;0;0;1,5\n"
                        "2;0,1;150;12,25\n", "n.csv")
    assert table.header == ["Nr.", "Zeit [s]", "Druck [kPa]", "Kraft [N]"]
    np.testing.assert_allclose(column_values(table, found["pressure"]), [0.0, 1.5])
    # one header of names that pint also reads (P: poise, F: farad) is not a units row
    table, found = _one(tmp_path, "Messung 7;x\nP;F\n1;2\n3;4\n", "b.csv")
    assert table.header == ["P", "F"] and set(found) == {"pressure", "force"}


def test_a_units_row_under_names_that_hold_their_units(tmp_path):
    # German Excel's export names each column with its unit and writes the units
    # row under them ('Zeit [s]' over 's'): the header became 'Zeit [s] [s]', no clock's name,
    # so a 10 Hz record was binned as rows without time (its holds untimed)
    text = "Zeit [s];Druck [bar];Kraft [N];Temp [°C]\ns;bar;N;°C\n0;0;1,5;22\n0,1;1,5;12,25;22\n"
    table, found = _one(tmp_path, text)
    assert table.header == ["Zeit [s]", "Druck [bar]", "Kraft [N]", "Temp [°C]"]
    assert set(found) >= {"time", "pressure", "force"}
    np.testing.assert_allclose(column_values(table, found["time"]), [0.0, 0.1])
    # the same unit spelled otherwise is the same unit; two units for one column are refused
    table, found = _one(tmp_path, "Zeit;Druck (kPa);Kraft\n[s];[kPa];[N]\n0;0;1,5\n"
                        "0,1;150;12,25\n", "k.csv")
    assert table.header == ["Zeit [s]", "Druck (kPa)", "Kraft [N]"]
    np.testing.assert_allclose(column_values(table, found["pressure"]), [0.0, 1.5])
    path = tmp_path / "two.csv"
    path.write_text("Zeit [s];Druck [bar];Kraft [kN]\ns;bar;N\n0;0;1,5\n0,1;1,5;12,25\n",
                    encoding="utf-8")
    with pytest.raises(ValueError) as raised:
        read_tables(path)
    assert str(raised.value) == ("two.csv, row 2: column 'Kraft [kN]' names its unit, and the "
                                 "row of units under the names gives it 'N': expected one unit "
                                 "per column; correct the name or the units row")


@pytest.mark.parametrize("units", ["# s, kPa, kN", "#s,kPa,kN", "#,s,kPa,kN", "# [s],[kPa],[kN]"])
def test_a_units_row_marked_as_a_comment_is_the_units_row(units, tmp_path):
    # a logger marks its units row with '#' so that other readers skip it: it was dropped as
    # a comment, and the kPa and kN read as bar and N
    table, found = _one(tmp_path, f"Zeit,Druck,Kraft\n{units}\n0,0,0.0015\n0.1,150,0.01225\n")
    assert table.header == ["Zeit [s]", "Druck [kPa]", "Kraft [kN]"]
    assert table.header_row == 1 and table.row_numbers == [3, 4]
    np.testing.assert_allclose(column_values(table, found["pressure"]), [0.0, 1.5])
    np.testing.assert_allclose(column_values(table, found["force"]), [1.5, 12.25])


@pytest.mark.parametrize("comment", ["# Messung 7, Prüfstand 2", "# s, kPa", "# 0, 0, 0"])
def test_a_comment_under_the_names_that_is_no_units_row_stays_a_comment(comment, tmp_path):
    # words, fewer units than names, or numbers: a comment, as before
    table, found = _one(tmp_path, f"Zeit,Druck,Kraft\n{comment}\n0,0,1.5\n0.1,1.5,12.25\n")
    assert table.header == ["Zeit", "Druck", "Kraft"] and table.row_numbers == [3, 4]
    np.testing.assert_allclose(column_values(table, found["force"]), [1.5, 12.25])


def test_a_units_row_with_a_temperature_and_a_displacement_is_read(tmp_path):
    # a US logger's units row under its names, with a temperature in °F and a displacement in
    # inches beside the readings: was no units row (°F and in are no role's units), so the
    # units became the header and no pressure or force column was found
    table, found = _one(tmp_path, "Time,Pressure,Force,Temperature,Displacement\n"
                        "s,psi,lbf,°F,in\n0,14.5,10,72.5,0.01\n0.1,29,20,72.5,0.02\n")
    assert table.header == ["Time [s]", "Pressure [psi]", "Force [lbf]", "Temperature [°F]",
                            "Displacement [in]"]
    np.testing.assert_allclose(column_values(table, found["pressure"]),
                               [14.5 * PSI_BAR, 29 * PSI_BAR])
    np.testing.assert_allclose(column_values(table, found["force"]), [10 * LBF_N, 20 * LBF_N])


def test_tab_separated_with_units_overridden(tmp_path):
    table, found = _one(tmp_path, "P\tF\n100\t10\n200\t20\n", "lab.tsv")
    assert table.separator == "\t"
    found = recognise(table, units={"pressure": "kPa", "force": "lbf"})
    np.testing.assert_allclose(column_values(table, found["pressure"]), [1.0, 2.0])
    np.testing.assert_allclose(column_values(table, found["force"]), [10 * LBF_N, 20 * LBF_N])


def test_every_sheet_or_one(tmp_path):
    path = tmp_path / "book.xlsx"
    with pd.ExcelWriter(path) as book:
        pd.DataFrame({"P (bar)": [0.5, 1.0], "F (N)": [1.0, 2.0]}).to_excel(book, sheet_name="eps0",
                                                                           index=False)
        pd.DataFrame({"note": ["nothing here"]}).to_excel(book, sheet_name="notes", index=False,
                                                         startrow=2)
        pd.DataFrame({"P (bar)": [0.5], "F (N)": [3.0]}).to_excel(book, sheet_name="eps12",
                                                                  index=False)
    tables = read_tables(path, None)
    assert [t.sheet for t in tables] == ["eps0", "eps12"]  # a sheet without numbers is no table
    (table,) = read_tables(path, "eps12")
    assert column_values(table, recognise(table)["force"]).tolist() == [3.0]
    with pytest.raises(ValueError, match="--sheet 'x': book.xlsx has no such sheet"):
        read_tables(path, "x")


@pytest.mark.parametrize("header", ["Kontraktion [%]", "Kontraktion", "eps [-]"])
@pytest.mark.parametrize("force", [150.5, "150,5"])  # a text cell of a decimal comma beside
def test_a_workbook_cell_formatted_as_a_percentage_is_read_as_shown(header, force, tmp_path):
    # Excel stores 12.2 % typed into a cell as 0.122, formatted '0.0%': under 'Kontraktion [%]'
    # it was read as 0.122 %, an eps of 0.00122, unsaid
    import openpyxl

    book = openpyxl.Workbook()
    sheet = book.active
    sheet.append(["Druck [bar]", "Kraft [N]", header])
    for fraction in (0.0, 0.122):
        sheet.append([2, force, fraction])
        sheet.cell(sheet.max_row, 3).number_format = "0.0%"
    path = tmp_path / "book.xlsx"
    book.save(path)
    (table,) = read_tables(path)
    found = recognise(table)
    np.testing.assert_allclose(column_values(table, found["eps"]), [0.0, 0.122], rtol=1e-12)
    np.testing.assert_allclose(column_values(table, found["force"]), [150.5, 150.5])


def test_a_workbooks_numbers_stored_as_text_with_decimal_commas(tmp_path):
    path = tmp_path / "book.xlsx"
    pd.DataFrame({"Druck [bar]": ["0", "1,5", "2,75"], "Kraft [N]": [0.0, 150.5, "300,25"]}
                 ).to_excel(path, index=False)
    (table,) = read_tables(path)
    found = recognise(table)
    assert table.decimal == ","
    np.testing.assert_allclose(column_values(table, found["pressure"]), [0.0, 1.5, 2.75])
    np.testing.assert_allclose(column_values(table, found["force"]), [0.0, 150.5, 300.25])


@pytest.mark.parametrize("text, message", [
    ("", "lab.csv is empty"),
    ("P,F\n", "has no row of numbers"),
    ("P,F\n1,2\n1,abc\n", "lab.csv, cell B3 (column 'F'): 'abc' is not a number"),
    # a German Excel sheet's failed formula was 'not a number', the cell's error
    # not said
    ("P;F\n1;2\n1;#WERT!\n", "lab.csv, cell B3 (column 'F'): '#WERT!' is a spreadsheet's "
     "error value (a formula that failed there: Excel's #VALUE!, #DIV/0!, #REF!, in German "
     "#WERT!, #BEZUG!): correct the formula, or delete its row"),
    # one in a row's first cell was a '#' comment, the row left out without a word
    ("P,F\n1,2\n#DIV/0!,3\n2,4\n", "lab.csv, cell A3 (column 'P'): '#DIV/0!' is a "
     "spreadsheet's error value"),
    ("P,F\n1,2\n1,#NUM!\n", "'#NUM!' is a spreadsheet's error value"),
    ("P,F\n1,2\n1,nan\n", "lab.csv, cell B3 (column 'F'): 'nan' is not a finite number"),
    ("P,F\n1 bar,2\n150 kPa,2\n", "mixed units in column 'P': 'bar' in cell A2, 'kPa' in cell A3"),
    ("P (bar),F\n1,2\n150 kPa,2\n", "mixed units in column 'P (bar)': 'bar' in the header, "
     "'kPa' in cell A3"),
    ("P [kg],F\n1,2\n", "'kg' is not a unit of pressure"),
])
def test_bad_cells_are_named(tmp_path, text, message):
    path = tmp_path / "lab.csv"
    path.write_text(text)
    with pytest.raises(ValueError, match=message.replace("(", r"\(").replace(")", r"\)")):
        (table,) = read_tables(path)
        found = recognise(table)
        for column in found.values():
            column_values(table, column)


def test_units_written_in_the_cells(tmp_path):
    table, found = _one(tmp_path, "P,F\n150 kPa,2 lbf\n250 kPa,4 lbf\n")
    np.testing.assert_allclose(column_values(table, found["pressure"]), [1.5, 2.5])
    np.testing.assert_allclose(column_values(table, found["force"]), [2 * LBF_N, 4 * LBF_N])


def test_a_formula_without_a_saved_value_is_named_as_a_formula(tmp_path):
    import openpyxl

    # openpyxl (as pandas, or a lab's script) writes a formula without the value a spreadsheet
    # would save with it
    book = openpyxl.Workbook()
    book.active.title = "eps0"
    for row in (["P (bar)", "F (N)"], [1.0, 150.0], [2.0, "=B2*2"]):
        book.active.append(row)
    path = tmp_path / "book.xlsx"
    book.save(path)
    (table,) = read_tables(path)
    found = recognise(table)
    assert column_values(table, found["pressure"]).tolist() == [1.0, 2.0]
    with pytest.raises(ValueError) as caught:
        column_values(table, found["force"])
    assert str(caught.value) == (
        "book.xlsx, sheet 'eps0', cell B3 (column 'F (N)'): holds the formula '=B2*2' without "
        "a value saved: open and save the workbook in Excel (or LibreOffice) to compute it, or "
        "export it as CSV")


def test_numbers_in_scientific_notation(tmp_path):
    # '1e2' was read as 1 with the unit 'e2', which pint does not know: 'not a number'
    table, found = _one(tmp_path, "P,F\n0.5,5E1\n1,1e2\n1.5,1.5e2 N\n2,2.0e+02\n2.5,2.5E2N\n")
    np.testing.assert_allclose(column_values(table, found["force"]),
                               [50.0, 100.0, 150.0, 200.0, 250.0])
    table, found = _one(tmp_path, "P,F\n1,2.5E-1 kN\n2,5e-1 kN\n")
    np.testing.assert_allclose(column_values(table, found["force"]), [250.0, 500.0])


@pytest.mark.parametrize("cells, seconds", [
    # an English-language Excel's times of day: 12-hour clock, past noon and past midnight
    (["11:59:59.5 AM", "12:00:00.5 PM", "12:00:01 PM"], [0.0, 1.0, 1.5]),
    (["11:59:59 PM", "12:00:00 AM", "12:00:01 a.m."], [0.0, 1.0, 2.0]),
    # its date-times, month first (Excel's m/d/yyyy h:mm too), and day first where a day > 12
    (["12/5/2026 11:59:59.750 PM", "12/6/2026 12:00:00.250 AM"], [0.0, 0.5]),
    (["12/5/2026 23:59", "12/6/2026 0:01"], [0.0, 120.0]),
    (["31/1/2026 23:59:59", "1/2/2026 00:00:01"], [0.0, 2.0]),
    # ISO 8601's basic format, and its zone after a space or named UTC, as loggers write them
    (["20261206T090000.000Z", "20261206T090001.250Z"], [0.0, 1.25]),
    (["2026-12-06 09:00:00.000 +01:00", "2026-12-06 08:00:01.500 Z"], [0.0, 1.5]),
    (["2026-12-06 09:00:00 UTC", "2026-12-06 10:00:02 +0100"], [0.0, 2.0]),
    # German Excel's date-time as it shows it, saved to CSV so, without seconds
    (["06.12.2026 23:59", "07.12.2026 00:01"], [0.0, 120.0]),
    # BenchLink's milliseconds after a third colon, in a date-time and a time of day
    (["12/6/2026 14:05:00:900", "12/6/2026 14:05:01:150"], [0.0, 0.25]),
    (["23:59:59:900", "00:00:00:100"], [0.0, 0.2]),
    # a logger's date year first with slashes
    (["2026/12/05 23:59:59.75", "2026/12/06 00:00:00.25", "2026/12/6 00:00:01"],
     [0.0, 0.5, 1.25]),
])
def test_times_of_day_and_date_times_as_excel_and_loggers_write_them(cells, seconds, tmp_path):
    # were: "cell A2 (column 'Time'): '11:59:59.5 AM' is not a number", "'20261206T090000.000Z'
    # is not a time"
    rows = "".join(f"{c};{k};{k}\n" for k, c in enumerate(cells))
    table, found = _one(tmp_path, f"Time;P [bar];F [N]\n{rows}")
    np.testing.assert_allclose(column_values(table, found["time"]), seconds, atol=1e-9)


def test_a_date_and_time_column_is_the_clock(tmp_path):
    # 'Date&Time' was no time's name: the record was read untimed, its clock left out
    table, found = _one(tmp_path, "Date&Time,Druck [bar],Kraft [N]\n2026/12/05 14:05:00.0,0,0\n"
                        "2026/12/05 14:05:00.5,1,100\n")
    assert found["time"].header == "Date&Time"
    np.testing.assert_allclose(column_values(table, found["time"]), [0.0, 0.5], atol=1e-9)


def test_a_time_cell_that_is_no_time_is_named_as_such(tmp_path):
    # was: "'13:61 PM' is not a number", for a column of times
    table, found = _one(tmp_path, "Time;P [bar];F [N]\n13:61 PM;0;1\n")
    with pytest.raises(ValueError) as info:
        column_values(table, found["time"])
    assert str(info.value).startswith("lab.csv, cell A2 (column 'Time'): '13:61 PM' is not a "
                                      "time: expected seconds")


def test_an_evaluation_block_under_its_own_title_is_no_data(tmp_path):
    # a lab sheet's results under the measurements, a title row above them: 'Peak;2;549,4'
    # holds two numbers, so the block was read as steps ("'Peak' is not a number")
    table, found = _one(tmp_path, "Druck [bar];Kraft [N]\n0;0\n1;214,5\n2;549,4\n\nAuswertung\n"
                        "Peak;2;549,4\nHysterese [N];5,5\n")
    np.testing.assert_allclose(column_values(table, found["force"]), [0.0, 214.5, 549.4])
    assert table.footer_skipped == ["A6 ('Auswertung')", "A7 ('Peak')", "A8 ('Hysterese [N]')"]
    # a table's rows labelled by text under a blank row, with no title, stay its rows
    table, found = _one(tmp_path, "Richtung;Druck [bar];Kraft [N]\nauf;0;0\nauf;2;549,4\n\n"
                        "ab;1;220\nab;0;0,5\n", "branches.csv")
    np.testing.assert_allclose(column_values(table, found["force"]), [0.0, 549.4, 220.0, 0.5])


def test_a_loggers_closing_notes_under_a_blank_row_are_no_data(tmp_path):
    # was: "cell A8 (column 'Druck [bar]'): 'Anzahl Werte' is not a number"
    notes = "\nAnzahl Werte;3\nMessdauer [s];120,5\nMessung beendet;14:05:00\nPrüfer;Müller\n"
    table, found = _one(tmp_path, f"Druck [bar];Kraft [N]\n0;2\n1;102\n2;203\n{notes}")
    np.testing.assert_allclose(column_values(table, found["force"]), [2.0, 102.0, 203.0])
    assert table.footer_skipped == ["A6 ('Anzahl Werte')", "A7 ('Messdauer [s]')",
                                    "A8 ('Messung beendet')", "A9 ('Prüfer')"]
    assert Recognition(table, found).line().endswith(
        "4 row(s) of notes under the table skipped: A6 ('Anzahl Werte'), A7 ('Messdauer [s]'), "
        "A8 ('Messung beendet'), ...")
    # with no blank row above it, such a row is read with the data, and named there
    table, found = _one(tmp_path, "Druck [bar];Kraft [N]\n0;2\n1;102\nAnzahl Werte;2\n", "b.csv")
    with pytest.raises(ValueError, match=r"cell A4 \(column 'Druck \[bar\]'\): 'Anzahl Werte' "
                                         "is not a number"):
        column_values(table, found["pressure"])


@pytest.mark.parametrize("text", [
    # a comment typed in a column without a header, beside some rows
    "P (bar);F (N)\r\n0;1,5;ok\r\n0,5;40,2\r\n1;80,1;Riss?\r\n",
    # a row missing its force
    "P (bar);F (N)\r\n0;1,5\r\n0,5\r\n1;80,1\r\n",
])
def test_a_semicolon_table_with_a_ragged_row_keeps_its_separator(text, tmp_path):
    # its decimal commas split as many lines into as many fields as its semicolons: the comma
    # was taken for the separator ("no pressure or force column among '0;1', '5;ok'")
    table, found = _one(tmp_path, text, "ragged.csv")
    assert table.separator == ";" and table.decimal == ","
    assert table.header[:2] == ["P (bar)", "F (N)"] and set(found) == {"pressure", "force"}
