"""Fixtures of the surrogate tests: a small dataset from the thick-wall model (exact, fast)."""

import itertools

import numpy as np
import pandas as pd
import pytest

from fem.calibration import calibrated
from fem.ladder import make_model


@pytest.fixture(scope="session")
def thickwall_dataset(tmp_path_factory):
    """The paper's Table 1 grid computed with ``thickwall``, as ``mkm fem dataset`` writes it,
    at the FE model's calibrated braid angle (a surrogate's default angle)."""
    model = make_model("thickwall", theta0_deg=calibrated("axisym")["theta0_deg"])
    frames = [model.predict(np.arange(0.0, 2.51, 0.5), D0, t0, eps).to_frame()
              for D0, t0, eps in itertools.product((30, 40, 50), (2, 3, 4), (0.0, 0.1, 0.2))]
    # the muscle parameters the FE would record (a surrogate checks them on every prediction)
    params = {k: model.params()[k] for k in ("L0_mm", "theta0_deg", "C10_MPa", "C01_MPa")}
    table = pd.concat(frames, ignore_index=True).assign(model="thickwall", **params)
    path = tmp_path_factory.mktemp("data") / "mkm_dataset.csv"
    with open(path, "w", encoding="utf-8") as f:
        f.write("# model: thickwall (test fixture)\n")
        table.to_csv(f, index=False)
    return path
