"""The FE datasets the surrogates learn from: inputs, forces, muscles, hash, box and provenance.

Two datasets ship inside the package (so an installed wheel can train):

- :data:`DEFAULT_DATASET`, ``data/mkm_design.csv``: the space-filling FE design over the whole
  box (:mod:`mkm.surrogate.design`), pressure and seven muscle parameters; the default surrogate's;
- :data:`PAPER_DATASET`, ``data/mkm_dataset.csv``: the paper's 3 x 3 x 3 grid at one length,
  braid angle and rubber (the 27-net study of its Table 2).

``#`` comment lines may precede the header; a sidecar ``<name>.json`` may hold the provenance
(and, for a design, its ``box``). Rows the FE did not solve (not converged, not valid, NaN
force) are left out and counted, never fed to a fit.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from mkm.core.records import (
    file_sha256,
    package_file,
    read_csv_checked,
    read_prediction_header,
    recorded_path,
)
from mkm.fem.interface import INPUTS, Domain

#: Parameters of a muscle that are not arguments of ``ForceModel.predict``: a surrogate takes
#: each either as an input (the dataset varies it) or as a recorded value (the dataset holds one).
PARAMETERS = ("L0_mm", "theta0_deg", "C10_MPa", "C01_MPa")
ALL_INPUTS = (*INPUTS, *PARAMETERS)
MUSCLE_COLUMNS = ALL_INPUTS[1:]  # what tells one muscle (one FE sweep) from another

DEFAULT_DATASET = package_file("mkm.surrogate", "data", "mkm_design.csv")
PAPER_DATASET = package_file("mkm.surrogate", "data", "mkm_dataset.csv")
#: Random muscles (seeds recorded in its sidecar) whose FE sweeps set the scale of the default
#: surrogate's std (:meth:`mkm.surrogate.muscle_gp.MuscleThresholdGP.calibrate_std`): drawn as the
#: off-grid evaluation draws, never used to fit the forces.
STD_CALIBRATION_SET = package_file("mkm.surrogate", "data", "mkm_std_calibration.csv")
#: Further random muscles (other seeds) that neither the fit nor the calibration saw: one factor
#: of the whole std (:meth:`mkm.surrogate.muscle_gp.MuscleThresholdGP.rescale_std`) makes 1, 2
#: and 3 std hold 68, 95 and 99.7 % of their errors.
STD_HOLDOUT_SET = package_file("mkm.surrogate", "data", "mkm_std_holdout.csv")


@dataclass
class TrainingData:
    """Inputs ``X`` (columns :attr:`inputs`), forces ``y`` [N], muscles and origin.

    ``fixed``: the :data:`PARAMETERS` the dataset holds at one value (a surrogate trained on it
    answers at that value only); ``box``: the closed range of each input the surrogate claims
    (the design's box when the sidecar has one, else the span of the data); ``path``: the file
    as records name it (:func:`~mkm.core.records.recorded_path`), beside its ``sha256``.
    """

    X: np.ndarray
    y: np.ndarray
    inputs: tuple[str, ...]
    fixed: dict
    box: dict
    groups: np.ndarray
    threshold_pressure_bar: np.ndarray
    path: str
    sha256: str
    provenance: dict = field(default_factory=dict)
    n_dropped: int = 0
    labels: dict = field(default_factory=dict)

    @property
    def n_muscles(self) -> int:
        return int(np.unique(self.groups).size)

    def domain(self) -> Domain:
        """The box of the four ``predict`` inputs."""
        return Domain(**{name: tuple(self.box[name]) for name in INPUTS})

    def summary(self) -> dict:
        return {"path": self.path, "sha256": self.sha256, "n_rows": int(len(self.y)),
                "n_muscles": self.n_muscles, "n_dropped": self.n_dropped,
                "inputs": list(self.inputs), "fixed": self.fixed, "labels": self.labels,
                "box": self.box, "provenance": self.provenance}


def load_training_data(path=DEFAULT_DATASET) -> TrainingData:
    """Read an FE dataset CSV; ``ValueError`` if it is missing, lacks columns or has no rows."""
    path = Path(path)
    columns = (*INPUTS, "force_N")
    frame = read_csv_checked(path, "dataset", "expected a CSV built by `mkm surrogate design` or "
                             f"`mkm fem dataset` (columns {','.join(columns)},...)", columns,
                             numeric=columns, comment="#")
    provenance = read_prediction_header(path)
    keep = np.isfinite(frame["force_N"].to_numpy(dtype=float))
    for flag in ("converged", "valid"):
        if flag in frame.columns:
            keep &= frame[flag].astype(str).str.lower().isin(("true", "1")).to_numpy()
    if not keep.any():
        raise ValueError(f"dataset {str(path)!r} has no converged, valid row to train on")
    used = frame[keep].copy()
    recorded = provenance.get("model_params", {}) if isinstance(provenance, dict) else {}
    for name in PARAMETERS:  # a parameter without a column: the one value the sidecar records
        if name not in used.columns:
            if recorded.get(name) is None:
                raise ValueError(f"dataset {str(path)!r} records no {name} (no column, none in "
                                 "the sidecar's model_params): expected the value the FE used")
            used[name] = float(recorded[name])
    labels = {}
    for column in ("model", "mesh"):  # one FE model and mesh, or the dataset mixes physics
        if column in used.columns:
            values = used[column].dropna().unique()
            if len(values) > 1:
                raise ValueError(f"dataset {str(path)!r} mixes {column} = "
                                 f"{', '.join(map(str, values[:4]))}: expected one value")
            if len(values):
                labels[column] = values[0].item() if hasattr(values[0], "item") else values[0]
    fixed = {}
    for name in PARAMETERS:
        values = used[name].to_numpy(dtype=float)
        if np.ptp(values) == 0.0:
            fixed[name] = float(values[0])
    inputs = tuple(name for name in ALL_INPUTS if name not in fixed)
    X = used[list(inputs)].to_numpy(dtype=float)
    _, groups = np.unique(used[list(MUSCLE_COLUMNS)].to_numpy(dtype=float), axis=0,
                          return_inverse=True)
    threshold = (used["threshold_pressure_bar"].to_numpy(dtype=float)
                 if "threshold_pressure_bar" in used.columns else np.full(len(used), np.nan))
    design_box = provenance.get("box", {}) if isinstance(provenance, dict) else {}
    box = {name: [float(v) for v in design_box[name]] if name in design_box
           else [float(X[:, i].min()), float(X[:, i].max())] for i, name in enumerate(inputs)}
    return TrainingData(X=X, y=used["force_N"].to_numpy(dtype=float), inputs=inputs,
                        fixed=fixed, box=box, groups=groups.ravel(),
                        threshold_pressure_bar=threshold, path=recorded_path(path),
                        sha256=file_sha256(path), provenance=provenance,
                        n_dropped=int((~keep).sum()), labels=labels)
