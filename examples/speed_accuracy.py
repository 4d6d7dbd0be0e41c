"""The speed-accuracy chart, from the study table

`mkm study` scores every predictor against the finest FE mesh on twelve study muscles and times
it; the table it writes (`model_errors.csv`, shipped as `mkm/data/model_errors.csv`, the one
`--model auto` reads) has one row per predictor, muscle and pressure. This example reads it with
pandas, reduces it to one point per predictor (seconds per predicted force, largest |Err%| of
the paper's Equation 7 over every valid point) and draws the chart with its Pareto front, the
predictors no other beats in both speed and accuracy.

The FE model's documentation states the contract its default mesh meets: `medium` is within 1 %
of `fine` in force. The study measures it on every study muscle.

Writes `speed_accuracy.png` into `mkm-out/examples/` (or `$MKM_OUT/examples/`).
"""

import numpy as np
import pandas as pd
from matplotlib.figure import Figure

from mkm.auto import MODEL_ERRORS_FILE
from mkm.paths import default_out

table = pd.read_csv(MODEL_ERRORS_FILE)
scored = table[table["force_ref_N"].notna() & table["valid"]]
summary = scored.groupby("predictor").agg(
    seconds_per_force=("seconds_per_point", "median"),
    largest_abs_err_pct=("err_pct", lambda e: e.abs().max()),
    muscles=("muscle", "nunique"),
).sort_values("seconds_per_force")
# every predictor is scored at every point; one invalid somewhere cannot answer every query
summary["valid_everywhere"] = (scored.groupby("predictor").size()
                               == table[table["force_ref_N"].notna()].groupby("predictor").size())
cost, error = summary["seconds_per_force"].to_numpy(), summary["largest_abs_err_pct"].to_numpy()
summary["pareto"] = [summary["valid_everywhere"].iloc[i] and not np.any(
    (cost <= cost[i]) & (error <= error[i]) & ((cost < cost[i]) | (error < error[i])))
    for i in range(len(summary))]
print(summary.to_string(float_format=lambda v: f"{v:.3g}"))

figure = Figure(figsize=(7, 4.5), layout="constrained")
ax = figure.subplots()
floor = 1e-4  # the reference's own error is 0: drawn at the floor of the log axis
ax.scatter(cost, np.maximum(error, floor), color="tab:blue")
front = summary[summary["pareto"]]
ax.plot(front["seconds_per_force"], np.maximum(front["largest_abs_err_pct"], floor), "r-o",
        label="Pareto front")
for name, row in summary.iterrows():
    ax.annotate(name, (row["seconds_per_force"], max(row["largest_abs_err_pct"], floor)),
                fontsize=7, xytext=(3, 3), textcoords="offset points")
ax.set(xscale="log", yscale="log", xlabel="seconds per predicted force",
       ylabel="largest |Err%| against axisym-fine")
ax.legend()
out = default_out("examples")
out.mkdir(parents=True, exist_ok=True)
figure.savefig(out / "speed_accuracy.png", dpi=100)
print(f"written {out / 'speed_accuracy.png'}")

medium = summary.loc["axisym-medium", "largest_abs_err_pct"]
print(f"axisym-medium against axisym-fine: largest |Err%| {medium:.3g} % over "
      f"{summary.loc['axisym-medium', 'muscles']} muscles")
assert medium < 1.0  # Axisym: "medium is converged to 1 % of fine in force"
