"""mkm.bench.reference: what mkm fem calibrate --reference reads."""

from __future__ import annotations

import pytest

from mkm.bench.reference import calibration_reference


def test_a_labs_own_table_as_reference_says_to_import_it(tmp_path):
    # was: only the reference columns listed, not the way from the lab's table to a reference
    table = tmp_path / "lab.csv"
    table.write_text("Druck [bar];Kraft [N]\n0;0\n1;100\n2;200\n", encoding="utf-8")
    with pytest.raises(ValueError) as caught:
        calibration_reference(table)
    message = str(caught.value)
    assert message.startswith(f"{table} lacks columns ['pressure_bar', 'D0_mm', 't0_mm', "
                              "'eps', 'force_N']: expected a reference table with")
    assert message.endswith(f'becomes one with mkm import "{table}" --id ... --D0 ... --t0 ...')
