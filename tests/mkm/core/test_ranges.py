"""The one parser of numbers, fractions and ranges (mkm/core/ranges.py)."""

import numpy as np
import pytest

from mkm.core.ranges import (
    MAX_RANGE_VALUES,
    list_items,
    parse_fraction,
    parse_number,
    parse_numbers,
    parse_pressures,
    parse_range,
    parse_shortenings,
    parse_tolerance,
)


def test_range_includes_its_stop_despite_round_off():
    # 0.1 steps do not add up exactly in binary: 0 + 7 * 0.1 = 0.7000000000000001
    values = parse_range("0:0.7:0.1", "x")
    assert len(values) == 8 and values[-1] == 0.7
    np.testing.assert_array_equal(parse_range("0:2.5:0.25", "p"), np.arange(11) * 0.25)


def test_pressures_as_range_or_comma_list():
    np.testing.assert_array_equal(parse_pressures("0:1:0.5"), [0.0, 0.5, 1.0])
    np.testing.assert_array_equal(parse_pressures(" 2.5, 0 ,1"), [2.5, 0.0, 1.0])
    # a list as German Windows writes it, its comma decimal: 'entry='5;1' is not a number'
    np.testing.assert_array_equal(parse_pressures("0,5; 1;1,5 ;2,5"), [0.5, 1.0, 1.5, 2.5])


def test_a_list_splits_on_semicolons_where_it_holds_one_else_on_commas():
    # the one rule of every list option: a semicolon list keeps its decimal commas in its items
    assert list_items(" 0,5; 1;1,5 ") == ["0,5", "1", "1,5"]
    assert list_items("paper, standardised") == ["paper", "standardised"]
    assert list_items("eq2;axisym:mesh=coarse,theta0=20") == ["eq2", "axisym:mesh=coarse,theta0=20"]
    assert parse_numbers("0;0,5;1", "--masses", "kg") == [0.0, 0.5, 1.0]
    assert parse_numbers("0,0.5,1", "--masses", "kg") == [0.0, 0.5, 1.0]
    assert parse_numbers("500g;1,5kg", "--masses", "kg") == [0.5, 1.5]


def test_fraction_or_percentage_mean_the_same():
    assert parse_fraction("5%") == parse_fraction("0.05") == pytest.approx(0.05, rel=1e-15)
    # a decimal comma, as a European keyboard types it
    assert parse_fraction("12,2%") == parse_fraction("0,122") == pytest.approx(0.122)
    assert parse_number("35,5", "--D0") == 35.5


@pytest.mark.parametrize(("parse", "text", "expected"), [
    (parse_fraction, "%", "a fraction (0.05) or a percentage (5%)"),
    (parse_fraction, "abc%", "a fraction (0.05) or a percentage (5%)"),
    (parse_tolerance, " 2 %% ", "a percentage in (0, 100), for example 2%"),
])
def test_a_percentage_that_is_no_number_is_named_whole(parse, text, expected):
    # was: "--eps='' is not a number": the value shown without its '%'
    name = "--eps" if parse is parse_fraction else "--tolerance"
    with pytest.raises(ValueError) as info:
        parse(text)
    assert str(info.value) == (f"{name}={text.strip()!r} is not a number followed by %: "
                               f"expected {expected}")


@pytest.mark.parametrize("text", ["0", "0%", "200%", "-1%", "100%"])
def test_a_tolerance_outside_zero_to_one_is_named_with_one_range(text):
    # '--tolerance 0%' was read as 0 and refused as '--tolerance 0: expected a fraction in
    # (0, 1)', while '200%' was told 'a percentage in [0, 100)': two ranges, neither the one
    with pytest.raises(ValueError) as info:
        parse_tolerance(text)
    assert str(info.value) == (f"--tolerance {text}: expected a fraction in (0, 1) or a "
                               "percentage in (0, 100), for example 0.02 or 2%")


def test_a_tolerance_is_a_fraction_or_a_percentage():
    assert parse_tolerance("2%") == parse_tolerance("0.02") == pytest.approx(0.02, rel=1e-15)
    with pytest.raises(ValueError, match=r"--tolerance 2: a fraction is expected; did you "
                                         r"mean 2%\?"):
        parse_tolerance("2")


def test_a_number_typed_with_a_unit_is_converted_into_the_options():
    """``--L0 282mm`` used to be refused ("expected the number alone"); every option that
    names its unit now converts a unit typed (pint), and refuses one of another kind."""
    assert parse_number("282mm", "--L0", "mm") == 282.0
    assert parse_number("1.5in", "--D0", "mm") == 38.1  # 25.4 mm per inch, exactly
    assert parse_number("12,5 mm", "--D0", "mm") == 12.5
    assert parse_number("30deg", "--theta0", "deg") == parse_number("30°", "--theta0", "deg")
    np.testing.assert_allclose(parse_pressures("0:250kPa:50kPa"), [0, 0.5, 1, 1.5, 2, 2.5])
    np.testing.assert_allclose(parse_pressures("0,1bar,100psi"), [0, 1, 6.894757], rtol=1e-6)
    with pytest.raises(ValueError, match=r"^--L0='282kg': 'kg' is not a unit of the same kind "
                       r"as mm: expected a number in mm, or one with a unit such as 282mm"):
        parse_number("282kg", "--L0", "mm")
    with pytest.raises(ValueError, match=r"^--L0='282zz': 'zz' is not a unit: expected"):
        parse_number("282zz", "--L0", "mm")


@pytest.mark.parametrize(("call", "message"), [
    (lambda: parse_number("abc", "--D0"), "^--D0='abc' is not a number$"),
    # an option with a unit says what it takes (was: "--D0='abc' is not a number" alone)
    (lambda: parse_number("abc", "--D0", "mm"), r"^--D0='abc' is not a number: expected a "
     r"number in mm, or one with a unit such as 282mm or 1\.5in$"),
    (lambda: parse_number("2..5", "--pressure", "bar"), r"^--pressure='2\.\.5' is not a number: "
     r"expected a number in bar, or one with a unit such as 2\.5bar or 250kPa$"),
    # a design spec's force said "such as N", the unit for its own example
    (lambda: parse_number("abc", "force_N", "N"), r"^force_N='abc' is not a number: expected a "
     r"number in N, or one with a unit such as 300N or 0\.3kN$"),
    (lambda: parse_number("abc", "--C10", "MPa"), r"such as 0\.07MPa or 70kPa$"),
    (lambda: parse_number("inf", "--D0"), "^--D0='inf' is not a finite number$"),
    (lambda: parse_range("0:2.5", "p"), "malformed: expected start:stop:step"),
    (lambda: parse_range("0:1:0", "p"), "step 0 must be > 0"),
    (lambda: parse_range("2:1:0.5", "p"), "stop 1 is below start 2"),
    (lambda: parse_range("0:1e12:1", "p"), f"expected at most {MAX_RANGE_VALUES}"),
    (lambda: parse_pressures(""), "--pressures is empty"),
    (lambda: parse_pressures("1,-0.5"), "negative pressure -0.5 bar"),
    # 0 and 100 would be bar: a unit on the last entry alone made a 100 bar step
    (lambda: parse_pressures("0,100,200kPa"), r"^--pressures '0,100,200kPa' gives a unit to "
     r"some entries only: expected every entry with its unit \(0kPa,100kPa,200kPa\) or none"),
    (lambda: parse_pressures("0:250kPa:50"), "gives a unit to some entries only"),
    (lambda: parse_pressures("0.5,1,2psi"), "gives a unit to some entries only"),
    # a mistyped sweep names the whole text and the two forms it may take
    (lambda: parse_pressures("0-8"), r"^--pressures='0-8' is not a number: expected "
     r"start:stop:step \(for example 0:8:0\.5\) or a comma list \(0,1,2\.5\) or, with "
     r"decimal commas, a semicolon list \(0,5;1;2,5\), in bar$"),
    # a decimal comma in a semicolon list is a number of the unit check as much as 0.5 is
    (lambda: parse_pressures("0,5;250kPa"), "gives a unit to some entries only"),
    (lambda: parse_pressures("0,1,,2"), r"^--pressures '0,1,,2': entry='' is not a number: "
     "expected start:stop:step"),
    (lambda: parse_fraction("five%"), r"^--eps='five%' is not a number followed by %: "
     r"expected a fraction \(0\.05\) or a percentage \(5%\)$"),
    (lambda: parse_fraction("0.1,L0=200", "--require: eps"), r"^--require: eps='0\.1,L0=200' "
     r"is not a number: expected a fraction \(0\.05\) or a percentage \(5%\)$"),
    # a unit typed after the number: said, not only refused
    (lambda: parse_number("282mm", "--L0"), "--L0='282mm' is not a number: expected the "
                                           "number alone, without 'mm'"),
    (lambda: parse_fraction("12.2"), "^--eps 12.2: a fraction is expected; did you mean 12.2%"),
    (lambda: parse_fraction("2", "--tolerance"), "^--tolerance 2: a fraction is expected; "
     "did you mean 2%"),
    (lambda: parse_fraction("150%"), r"^--eps 150%: a percentage in \[0, 100\) is expected$"),
    (lambda: parse_number("1,2,3", "--D0"), "^--D0='1,2,3' is not a number$"),
])
def test_bad_text_gives_one_line_naming_it(call, message):
    with pytest.raises(ValueError, match=message) as info:
        call()
    assert "\n" not in str(info.value)


@pytest.mark.parametrize("text, expected", [
    ("5%", 0.05), ("0.05", 0.05), ("0,05", 0.05), ("12,5%", 0.125),  # one, as parse_fraction
    ("0:0.2:0.05", [0.0, 0.05, 0.1, 0.15, 0.2]), ("0%:20%:10%", [0.0, 0.1, 0.2]),
    ("0.05,0.1", [0.05, 0.1]), ("5%,10%", [0.05, 0.1]), ("0,0.1", [0.0, 0.1]),
    ("0;0,05;0,1", [0.0, 0.05, 0.1]), ("0,5%;12,5%", [0.005, 0.125])])
def test_several_shortenings_are_a_range_or_a_list(text, expected):
    got = parse_shortenings(text)
    assert np.ndim(got) == np.ndim(expected)
    np.testing.assert_allclose(got, expected, rtol=0, atol=1e-12)


@pytest.mark.parametrize("text, message", [
    ("0,5%", "reads as one value with a decimal comma and as a list"),  # 0.005 or 0 and 5 %
    ("0.2:0.1:0.05", "stop 0.1 is below start 0.2"),
    ("0:0.2", "expected start:stop:step"),
    ("0.05,12", "did you mean 12%?"),
    ("0:50:10", "did you mean 50%?")])
def test_shortenings_that_do_not_read_are_named(text, message):
    with pytest.raises(ValueError, match="--eps") as info:
        parse_shortenings(text)
    assert message in str(info.value)
