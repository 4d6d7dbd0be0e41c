"""HTML helpers of the reports: metadata tables and folded provenance."""

from __future__ import annotations

import re

from mkm.html import mapping_table, provenance_details, provenance_links


def test_mapping_table_flattens_nested_metadata():
    html = mapping_table({"loadcell": {"capacity_N": 1961.33, "channel": "ai0"},
                          "channels": ["ai0", "ai1"], "tare": None}, "Calibration")
    rows = re.findall(r"<tr><td>([^<]*)</td><td>([^<]*)</td></tr>", html)
    assert rows == [("loadcell.capacity_N", "1961.33"), ("loadcell.channel", "ai0"),
                    ("channels", "ai0, ai1"), ("tare", "—")]
    assert "<caption>Calibration</caption>" in html


def test_provenance_is_folded_and_every_link_has_its_anchor():
    prov = {"software": {"date_utc": "x"}, "model-eq2": {"params": {"theta0_deg": 30.8}}}
    html = provenance_details(prov, "provenance.json") + provenance_links(prov)
    assert html.count("<details>") == 1 and 'href="provenance.json"' in html
    for anchor in re.findall(r'href="#(prov-[^"]+)"', html):
        assert f'id="{anchor}"' in html


def test_an_empty_cell_is_the_dash_never_none():
    import pandas as pd

    from mkm.html import table_html

    # an imported run has no budget: no step has an E_n, so "at step" is None throughout
    html = table_html(pd.DataFrame({"model": ["eq2", "thickwall"], "at step": [None, None],
                                    "worst E_n": [float("nan")] * 2}), "caption")
    assert "None" not in html and "nan" not in html
    assert html.count("<td>—</td>") == 4
