"""What ``mkm design`` says of a chosen design's band with an identified muscle (no model is
trained or solved: the note is built from the verified forces and the band's two ends)."""

from types import SimpleNamespace

import pandas as pd
import pytest

from mkm.design.result import DesignResult
from mkm.design.spec import parse_requirement


def _result(requirements, forces_N, below_N, above_N) -> DesignResult:
    requirements = [parse_requirement(r) for r in requirements]
    row = {"meets_all": True}
    for k, (r, force) in enumerate(zip(requirements, forces_N, strict=True), start=1):
        row |= {f"r{k}_fe_N": force, f"r{k}_fe_margin_N": force - r.force_N}
    return DesignResult(pd.DataFrame([row]), pd.DataFrame(),
                        SimpleNamespace(requirements=requirements), "medium", 0.0, {},
                        identified_band_N=below_N, identified_above_N=above_N)


def test_the_identified_band_is_said_by_both_ends_and_the_most_the_cell_must_take():
    """The note gave each force +- the band's lower end alone (`302 +- 15.5 N`): the upper end,
    the most a muscle of the identified uncertainty pulls (what the load cell and the frame
    must take), was in the API alone. The forces of bench_design_band's case 15 (the widely
    identified 10 x 1.5 mm muscle at 4 bar: 158.1 N, 80.9 N below, 101.1 N above) and case 4
    (3.75 N just above its threshold, 9.07 N below and 9.36 N above: no muscle pulls less
    than nothing)."""
    result = _result(["150N@4bar,eps=0.1", "1N@1.2bar,eps=0.2"], [158.108, 3.753],
                     [80.933, 9.071], [101.132, 9.357])
    note = result._band_note(result.chosen, result.identified_probability())
    assert note == (
        "the chosen design's forces with the identified muscle's own uncertainty (95 %, its "
        "intervals carried through the FE model): r1 (150N@4bar,eps=0.1) pulls 77.2-259.2 N "
        "(158.1 N at the calibration's values, met by 8.11 N): holds with about 58 %; r2 "
        "(1N@1.2bar,eps=0.2) pulls 0.0-13.1 N (3.753 N at the calibration's values, met by "
        "2.75 N): holds with about 72 %; the load cell and the frame must take 259.2 N at "
        "these requirements (r1's upper end); r1, r2 below 95 %: design for 95 % (--tolerance: "
        "the intervals as build tolerances) or require more force")
    assert result.identified_range_N() == {1: pytest.approx((77.175, 259.24)),
                                           2: pytest.approx((0.0, 13.11))}
