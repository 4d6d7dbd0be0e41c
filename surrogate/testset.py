"""Test on unseen muscles (the paper's section 3.3): our FE sweeps and Equation 7.

Muscles I, II and III are the paper's; IV and V are off-grid muscles of ours inside the
training box (between the dataset's grid values in every input). The reference forces come from
our own FE model (``build_fe_reference``), never from the paper, whose FE differs from ours.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pandas as pd

from mkm.core.records import (
    file_sha256,
    package_file,
    provenance,
    read_csv_checked,
    read_prediction_header,
    recorded_path,
    source_version,
    write_csv_with_sidecar,
)
from mkm.fem import paper
from mkm.fem.calibration import calibration_provenance
from mkm.fem.interface import ForceModel
from mkm.fem.paper import equation7_err_pct
from mkm.surrogate.model import SurrogateForceModel
from mkm.surrogate.training_data import PARAMETERS
from mkm.surrogate.validation import rmse

#: Our FE sweeps of the test muscles, shipped with the package (``mkm surrogate reference``).
FE_REFERENCE = package_file("mkm.surrogate", "data", "fe_test_muscles.csv")
#: the columns an FE reference must have (``converged`` and ``valid`` are read where present)
REFERENCE_COLUMNS = ("muscle", "pressure_bar", "D0_mm", "t0_mm", "eps", "force_N")

# name: (D0_mm, t0_mm, eps). I-III: the paper's section 3.3; IV, V: ours, off the grid.
TEST_MUSCLES = {**paper.TEST_MUSCLES, "IV": (32.0, 3.5, 0.08), "V": (47.0, 2.25, 0.12)}
PAPER_MUSCLES = tuple(paper.TEST_MUSCLES)
TEST_PRESSURES_BAR = paper.TEST_PRESSURES_BAR


def test_points(muscles=tuple(TEST_MUSCLES)) -> pd.DataFrame:
    """One row per muscle and pressure: ``muscle, pressure_bar, D0_mm, t0_mm, eps``."""
    rows = [(m, p, *TEST_MUSCLES[m]) for m in muscles for p in TEST_PRESSURES_BAR]
    return pd.DataFrame(rows, columns=["muscle", "pressure_bar", "D0_mm", "t0_mm", "eps"])


def build_fe_reference(model: ForceModel, out=FE_REFERENCE) -> pd.DataFrame:
    """Sweep every test muscle with ``model`` (our FE) and write the reference CSV to ``out``.

    A plain CSV with its metadata (the model, its parameters, the calibration and the library
    versions) in a JSON sidecar beside it (:func:`mkm.core.records.write_csv_with_sidecar`; read
    back with :func:`read_fe_reference`).
    """
    frames = []
    seconds = 0.0
    for muscle, (D0, t0, eps) in TEST_MUSCLES.items():
        prediction = model.predict(TEST_PRESSURES_BAR, D0, t0, eps)
        seconds += prediction.seconds
        frame = prediction.to_frame()[["pressure_bar", "D0_mm", "t0_mm", "eps", "force_N",
                                       "converged", "valid"]]
        frames.append(frame.assign(muscle=muscle, L0_mm=model.params().get("L0_mm")))
    table = pd.concat(frames, ignore_index=True)
    table = table[["muscle", *table.columns.drop("muscle")]]
    header = {"what": "FE reference of the test muscles (paper section 3.3 and ours)",
              "model": model.name, "params": model.params(), "seconds": seconds,
              "calibration": calibration_provenance(model), **provenance()}
    write_csv_with_sidecar(out, table.to_csv(index=False, float_format="%.6g",
                                             lineterminator="\n"),
                           json.loads(json.dumps(header, default=str)))
    return table


def read_fe_reference(path=FE_REFERENCE) -> pd.DataFrame:
    """The FE reference at ``path``: :data:`REFERENCE_COLUMNS`, and ``converged`` and ``valid``
    where the FE wrote them (a table of published forces has none); ``ValueError`` naming a
    missing column or a point the FE did not solve."""
    path = Path(path)
    table = read_csv_checked(path, "FE reference", f"expected a CSV with columns "
                             f"{','.join(REFERENCE_COLUMNS)} (as `mkm surrogate reference` "
                             "writes it)", REFERENCE_COLUMNS, comment="#")
    table.attrs["params"] = read_prediction_header(path).get("params", {})
    solved = np.ones(len(table), dtype=bool)
    for flag in ("converged", "valid"):
        if flag in table:
            solved &= table[flag].astype(bool).to_numpy()
    bad = table[~solved]
    if len(bad):
        raise ValueError(f"FE reference {str(path)!r} has {len(bad)} unconverged or invalid "
                         f"point(s) (first: muscle {bad['muscle'].iloc[0]}): expected a clean "
                         "reference sweep")
    return table


def compare_on_test_muscles(model: ForceModel, reference: pd.DataFrame):
    """Predict every reference point in one call; per-point errors and a per-muscle summary.

    Returns ``(points, summary)``: ``points`` has ``force_fe_N, force_pred_N, err_pct, valid``
    per row; ``summary`` per muscle ``max_abs_err_pct`` (Equation 7), ``rmse_N``,
    ``max_abs_error_N`` over the points the model answers (``valid``; NaN where it answers
    none), ``valid_points`` (answered of all) and the wall time of the whole call in
    ``seconds_all_points``. A surrogate is asked for the muscle parameters the reference's FE
    used (its header's ``params``: length, braid angle, rubber), or refuses with the reason.
    """
    params = reference.attrs.get("params", {})
    if hasattr(model, "with_parameters"):
        model = model.with_parameters(**{k: params[k] for k in PARAMETERS if k in params})
    prediction = model.predict(*(reference[c].to_numpy() for c in ("pressure_bar", "D0_mm",
                                                                    "t0_mm", "eps")))
    points = reference[["muscle", "pressure_bar", "D0_mm", "t0_mm", "eps"]].copy()
    points["force_fe_N"] = reference["force_N"].to_numpy()
    points["force_pred_N"] = prediction.force_N
    points["valid"] = prediction.valid
    points["err_pct"] = np.nan
    rows = []
    for muscle, group in points.groupby("muscle", sort=False):
        # a point the model flags invalid (outside its domain) has no error: its number is an
        # extrapolation the model disowns; Equation 7's scale stays the muscle's largest force
        ok = group["valid"].to_numpy(dtype=bool)
        err = np.where(ok, equation7_err_pct(group["force_fe_N"], group["force_pred_N"]), np.nan)
        points.loc[group.index, "err_pct"] = err
        residual = (group["force_fe_N"] - group["force_pred_N"]).to_numpy()[ok]
        answered = bool(ok.any())
        rows.append({"muscle": muscle, "model": model.name,
                     "max_abs_err_pct": float(np.nanmax(np.abs(err))) if answered else np.nan,
                     "rmse_N": rmse(residual, 0.0) if answered else np.nan,
                     "max_abs_error_N": float(np.max(np.abs(residual))) if answered else np.nan,
                     "valid_points": f"{int(ok.sum())}/{ok.size}",
                     "all_valid": bool(ok.all()),
                     "seconds_all_points": prediction.seconds})
    return points, pd.DataFrame(rows)


def run_test(models: dict[str, ForceModel], out_dir, reference_path=FE_REFERENCE) -> pd.DataFrame:
    """Table 3 and Figure 6 of the paper for ``models``, against our FE reference.

    Writes ``test_muscles.csv`` (summary), ``test_muscles_points.csv`` and ``test_muscles.md``
    (with the paper's figures for I-III beside ours) to ``out_dir``; Figure 6 is drawn from
    the points by the application (``mkm surrogate test``, :func:`mkm.figures.surrogate_fe_figure`).
    """
    reference = read_fe_reference(reference_path)
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    all_points, summaries = [], []
    for name, model in models.items():
        points, summary = compare_on_test_muscles(model, reference)
        all_points.append(points.assign(model=name))
        summaries.append(summary.assign(model=name))
    points = pd.concat(all_points, ignore_index=True)
    summary = pd.concat(summaries, ignore_index=True)
    # provenance: the reference read, each model and the code behind it, the command
    info = {"reference": recorded_path(reference_path),
            "reference_sha256": file_sha256(reference_path),
            "reference_params": reference.attrs.get("params", {}),
            "models": {name: {"model": model.name, "params": model.params(),
                              "version": source_version(type(model).__module__),
                              **({"surrogate": model.origin()}
                                 if isinstance(model, SurrogateForceModel) else {})}
                       for name, model in models.items()}, **provenance()}
    info = json.loads(json.dumps(info, default=str))
    for name, frame in (("test_muscles.csv", summary), ("test_muscles_points.csv", points)):
        write_csv_with_sidecar(out_dir / name, frame.to_csv(index=False, float_format="%.6g",
                                                             lineterminator="\n"), info)
    (out_dir / "test_muscles.md").write_text(markdown_table(summary), encoding="utf-8")
    return summary


def markdown_table(summary: pd.DataFrame) -> str:
    """Largest |Err%| per model and muscle, then RMSE and largest error, with the paper's row."""
    published = pd.read_csv(paper.TABLE3_CSV, comment="#").set_index("muscle")["max_abs_err_pct"]
    muscles = list(dict.fromkeys(summary["muscle"]))
    lines = ["| model | " + " | ".join(f"{m} max abs Err%" for m in muscles)
             + " | RMSE N (worst muscle) | largest abs error N | all points, one call, s |",
             "|---|" + "---|" * (len(muscles) + 3)]
    lines.append("| paper, 3 x 100 ReLU (its FE) | " + " | ".join(
        f"{published[m]:.2f}" if m in published else "" for m in muscles)
        + " | | 60.10 | 0.131 (33 points) |")
    for model, group in summary.groupby("model", sort=False):
        g = group.set_index("muscle")
        lines.append(f"| {model} | " + " | ".join(f"{g.loc[m, 'max_abs_err_pct']:.2f}"
                                                  for m in muscles)
                     + f" | {g['rmse_N'].max():.2f} | {g['max_abs_error_N'].max():.2f} | "
                     f"{g['seconds_all_points'].iloc[0]:.2g} |")
    return "\n".join(lines) + "\n"
