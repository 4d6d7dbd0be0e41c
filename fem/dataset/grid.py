"""Dataset grids: values per parameter, from TOML (``fem/dataset/grids/paper.toml`` is Table 1).

Per parameter a number, a list of numbers or a ``"start:stop:step"`` range (stop included where
the steps reach it, never exceeded).
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from mkm.core.ranges import parse_range
from mkm.core.toml_text import read_toml, read_toml_file
from mkm.fem.eq2 import LOCKING_ANGLE_DEG
from mkm.fem.interface import validate_inputs
from mkm.fem.limits import check_value
from mkm.fem.paper import TABLE1_GRID

GRID_KEYS = ("pressure_bar", "D0_mm", "t0_mm", "eps", "L0_mm", "theta0_deg")
OPTIONAL_GRID_KEYS = ("L0_mm", "theta0_deg")  # left out: the model's default


@dataclass(frozen=True)
class Grid:
    """Values per parameter; the dataset is their full product. ``None``: the model's default."""

    pressure_bar: tuple[float, ...]
    D0_mm: tuple[float, ...]
    t0_mm: tuple[float, ...]
    eps: tuple[float, ...]
    L0_mm: tuple[float | None, ...] = (None,)
    theta0_deg: tuple[float | None, ...] = (None,)
    source: str = ""

    def as_dict(self) -> dict[str, Any]:
        return {"source": self.source,
                **{k: list(getattr(self, k)) for k in GRID_KEYS}}


def parse_grid(text: str, source: str) -> Grid:
    """A grid from TOML text: per key a number, a list of numbers or ``"start:stop:step"``.

    Raises ``ValueError`` naming the grid, the bad key or value and what was expected.
    """
    table = read_toml(text, f"grid {source}")
    unknown = sorted(set(table) - set(GRID_KEYS))
    if unknown:
        raise ValueError(f"grid {source}: unknown key {unknown[0]!r}: "
                         f"expected some of {', '.join(GRID_KEYS)}")
    required = [k for k in GRID_KEYS if k not in OPTIONAL_GRID_KEYS]
    missing = [k for k in required if k not in table]
    if missing:
        raise ValueError(f"grid {source}: missing key {missing[0]!r}: expected "
                         f"{', '.join(required)} (and optionally {', '.join(OPTIONAL_GRID_KEYS)})")
    values = {key: _grid_values(source, key, table[key]) for key in table}
    P, D0, t0, e = np.meshgrid(*(values[k] for k in ("pressure_bar", "D0_mm", "t0_mm", "eps")))
    try:
        validate_inputs(P, D0, t0, e)
    except ValueError as exc:
        raise ValueError(f"grid {source}: {exc}") from None
    for key in OPTIONAL_GRID_KEYS:  # the limits of every input (a typo is refused)
        for v in values.get(key, ()):
            check_value(key, v, prefix=f"grid {source}: ")
    for v in values.get("theta0_deg", ()):
        if not v < LOCKING_ANGLE_DEG:
            raise ValueError(f"grid {source}: theta0_deg={v:g} is invalid: expected "
                             f"theta0_deg < {LOCKING_ANGLE_DEG:g} (the braid locking angle)")
    return Grid(**{k: tuple(float(v) for v in vals) for k, vals in values.items()}, source=source)


def _grid_values(source: str, key: str, value) -> np.ndarray:
    where = f"grid {source}: {key}"
    if isinstance(value, str):
        values = parse_range(value, where)
    else:
        items = value if isinstance(value, list) else [value]
        if not items:
            raise ValueError(f"{where} is an empty list: expected at least one value")
        bad = [v for v in items if isinstance(v, bool) or not isinstance(v, int | float)]
        if bad:
            raise ValueError(f"{where}={bad[0]!r} is not a number: expected a number, a list of "
                             "numbers or a 'start:stop:step' range")
        values = np.array(items, dtype=float)
    if not np.isfinite(values).all():
        raise ValueError(f"{where}={values[~np.isfinite(values)][0]!r} is not a finite number")
    if (values < 0).any():
        raise ValueError(f"{where}={values[values < 0][0]:g} is negative: expected values >= 0")
    unique, counts = np.unique(values, return_counts=True)
    if (counts > 1).any():
        raise ValueError(f"{where} lists {unique[counts > 1][0]:g} twice: expected distinct values")
    return values


def load_grid(spec: str | os.PathLike) -> Grid:
    """``"paper"`` (Table 1 of the paper, ``fem/dataset/grids/paper.toml``) or a grid TOML path,
    read as a bench configuration is (:func:`mkm.core.toml_text.read_toml_file`: saved by
    Notepad as "Unicode", with a BOM or a Ctrl-Z; a bad line said with what a Windows user's
    typing needs)."""
    path = TABLE1_GRID if spec == "paper" else Path(spec)
    text, _ = read_toml_file(path, "grid ", "'paper' or the path of a grid TOML file")
    return parse_grid(text, str(spec))
