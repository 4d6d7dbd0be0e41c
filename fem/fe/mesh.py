"""Meshes of the half muscle's wall in the (R, Z) meridian plane, graded towards the end cap.

The wall at rest is the rectangle ``R in [D0/2, D0/2 + t0]``, ``Z in [0, L0/2]`` (``Z = 0`` is
the mid-plane of symmetry, ``Z = L0/2`` the rigid cap). The deformation is nearly homogeneous in
the mid-section and varies over about one diameter next to the clamped cap (the end effect), so
the axial element size grows geometrically from the cap towards the mid-plane.
"""

from __future__ import annotations

import numpy as np
from skfem import MeshTri

from mkm.fem.options import MESH_LEVELS


def graded_spacing(length_mm: float, n: int, ratio: float) -> np.ndarray:
    """``n + 1`` node positions on ``[0, length_mm]`` whose spacing shrinks geometrically by
    ``ratio`` (largest/smallest) towards ``length_mm``."""
    q = ratio ** (1.0 / max(n - 1, 1))
    h = q ** np.arange(n)[::-1]
    x = np.concatenate([[0.0], np.cumsum(h)])
    return length_mm * x / x[-1]


def half_muscle_mesh(D0_mm: float, t0_mm: float, L0_mm: float, level: str = "medium") -> MeshTri:
    """Triangle mesh of the half muscle's wall at rest (coordinates ``(R, Z)`` in mm)."""
    if level not in MESH_LEVELS:
        raise ValueError(f"mesh={level!r} is invalid: expected one of {', '.join(MESH_LEVELS)}")
    n_r, n_z, ratio = MESH_LEVELS[level]
    R = np.linspace(D0_mm / 2.0, D0_mm / 2.0 + t0_mm, n_r + 1)
    Z = graded_spacing(L0_mm / 2.0, n_z, ratio)
    return MeshTri.init_tensor(R, Z)
