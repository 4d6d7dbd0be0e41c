"""Predict one muscle with every model

The paper's test muscle I (D0 35 mm, t0 2.5 mm, held at eps 5 %, L0 282 mm) over its pressure
sweep, with each rung of the physics ladder and the default surrogate, each built from its spec
(the same text `mkm fem solve --model SPEC` takes; `mkm models` lists them).

Every physics model's braid angle theta0 is calibrated on this very muscle (the paper's FE
forces, `fem/calibration.json`): Equation 2 by least squares on the forces, the models with a
wall on the slope above their threshold pressure. So each one's slope dF/dP above its threshold
must equal the paper's; what tells them apart is the threshold (zero for Equation 2) and how
they transfer to other muscles (see the speed-accuracy example).

The default surrogate is trained once, on first use, and cached.
"""

import numpy as np
import pandas as pd

from mkm.fem.calibration import line_above_threshold, read_reference
from mkm.fem.paper import CASE_I_CSV, L0_MM, TEST_MUSCLES, TEST_PRESSURES_BAR
from mkm.registry import build_spec

SPECS = ["eq2", "eq2:diameter=braid", "thickwall", "axisym", "surrogate"]
PHYSICS = SPECS[:4]  # calibrated on muscle I

D0_mm, t0_mm, eps = TEST_MUSCLES["I"]
forces = {}
for spec in SPECS:
    model = build_spec(spec, L0_mm=L0_MM)
    prediction = model.predict(TEST_PRESSURES_BAR, D0_mm, t0_mm, eps)
    assert prediction.valid.all(), f"{spec} is not valid on muscle I"
    forces[spec] = prediction.force_N

table = pd.DataFrame({"pressure_bar": TEST_PRESSURES_BAR, **forces})
print(table.round(2).to_string(index=False))

paper = read_reference(CASE_I_CSV)
paper_slope, _ = line_above_threshold(paper["pressure_bar"], paper["force_N"])
print(f"\npaper's FE slope on muscle I: {paper_slope:.2f} N/bar")
slopes = {}
for spec in SPECS:
    F = forces[spec]
    # the line through the points above 2 % of the largest force: above the threshold
    slopes[spec], threshold = line_above_threshold(TEST_PRESSURES_BAR, F, 0.02 * F.max())
    print(f"{spec:20s} slope {slopes[spec]:8.2f} N/bar, threshold {threshold:.3f} bar")

worst = max(abs(slopes[s] / paper_slope - 1) for s in PHYSICS)
print(f"largest slope difference of the calibrated physics models: {100 * worst:.3f} %")
assert np.isfinite(worst) and worst < 1e-3  # the calibration stores theta0 to 1e-3 deg
