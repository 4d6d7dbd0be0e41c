"""The FE dataset the surrogates learn from: inputs, forces, hash and provenance.

Reads ``data/mkm_dataset.csv`` (``#`` comment lines may precede the header; a sidecar
``mkm_dataset.json`` may hold the provenance). Rows the FE model did not solve (not converged,
not valid, NaN force) are left out and counted, never fed to a fit.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pandas as pd

from fem.interface import INPUTS, Domain
from fem.records import file_sha256, package_file

#: The shipped FE dataset (inside the package, so an installed wheel can train)
DEFAULT_DATASET = package_file("surrogate", "data", "mkm_dataset.csv")


@dataclass
class TrainingData:
    """Inputs ``X`` (columns ``fem.interface.INPUTS``), forces ``y`` [N] and their origin."""

    X: np.ndarray
    y: np.ndarray
    path: str
    sha256: str
    provenance: dict = field(default_factory=dict)
    n_dropped: int = 0
    fixed: dict = field(default_factory=dict)

    def domain(self) -> Domain:
        """The box the inputs span: the surrogate's domain of validity."""
        return Domain(**{name: (float(self.X[:, i].min()), float(self.X[:, i].max()))
                         for i, name in enumerate(INPUTS)})

    def summary(self) -> dict:
        return {"path": self.path, "sha256": self.sha256, "n_rows": int(len(self.y)),
                "n_dropped": self.n_dropped, "fixed": self.fixed, "provenance": self.provenance}


def load_training_data(path=DEFAULT_DATASET) -> TrainingData:
    """Read an FE dataset CSV; ``ValueError`` if it is missing, lacks columns or has no rows."""
    path = Path(path)
    if not path.is_file():
        raise ValueError(f"dataset {str(path)!r} does not exist: expected a CSV built by "
                         "`mkm fem dataset` (columns pressure_bar,D0_mm,t0_mm,eps,force_N,...)")
    frame = pd.read_csv(path, comment="#")
    missing = [c for c in (*INPUTS, "force_N") if c not in frame.columns]
    if missing:
        raise ValueError(f"dataset {str(path)!r} lacks column(s) {', '.join(missing)}: expected "
                         f"{', '.join((*INPUTS, 'force_N'))}")
    keep = np.isfinite(frame["force_N"].to_numpy(dtype=float))
    for flag in ("converged", "valid"):
        if flag in frame.columns:
            keep &= frame[flag].astype(str).str.lower().isin(("true", "1")).to_numpy()
    if not keep.any():
        raise ValueError(f"dataset {str(path)!r} has no converged, valid row to train on")
    used = frame[keep]
    # Inputs the surrogate does not take must be constant, or it would mix different muscles.
    fixed = {}
    for column in ("L0_mm", "theta0_deg", "model", "mesh"):
        if column in used.columns:
            values = used[column].dropna().unique()
            if len(values) > 1:
                raise ValueError(f"dataset {str(path)!r} mixes {column} = "
                                 f"{', '.join(map(str, values[:4]))}: expected one value")
            if len(values):
                fixed[column] = values[0].item() if hasattr(values[0], "item") else values[0]
    return TrainingData(X=used[list(INPUTS)].to_numpy(dtype=float),
                        y=used["force_N"].to_numpy(dtype=float), path=str(path),
                        sha256=file_sha256(path), provenance=_provenance(path),
                        n_dropped=int((~keep).sum()), fixed=fixed)


def _provenance(path: Path) -> dict:
    """The sidecar JSON if there is one, else the ``# key: value`` header lines."""
    sidecar = path.with_suffix(".json")
    if sidecar.is_file():
        return json.loads(sidecar.read_text(encoding="utf-8"))
    header = {}
    with open(path, encoding="utf-8") as f:
        for line in f:
            if not line.startswith("#"):
                break
            key, sep, value = line[1:].strip().partition(":")
            if sep:
                header[key.strip()] = value.strip()
    return header
