"""Fixtures of the surrogate tests: a small dataset from the thick-wall model (exact, fast)."""

import itertools

import numpy as np
import pandas as pd
import pytest

from fem.ladder import make_model


@pytest.fixture(scope="session")
def thickwall_dataset(tmp_path_factory):
    """The paper's Table 1 grid computed with ``thickwall``, as ``mkm fem dataset`` writes it."""
    model = make_model("thickwall")
    frames = [model.predict(np.arange(0.0, 2.51, 0.5), D0, t0, eps).to_frame()
              for D0, t0, eps in itertools.product((30, 40, 50), (2, 3, 4), (0.0, 0.1, 0.2))]
    table = pd.concat(frames, ignore_index=True).assign(model="thickwall", L0_mm=282.0)
    path = tmp_path_factory.mktemp("data") / "mkm_dataset.csv"
    with open(path, "w", encoding="utf-8") as f:
        f.write("# model: thickwall (test fixture)\n")
        table.to_csv(f, index=False)
    return path
