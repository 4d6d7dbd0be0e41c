"""Mesh-convergence study of the axisymmetric FE model (``mkm fem convergence``).

Solves one isometric point on every mesh level, from coarse to fine, and reports the force, the
threshold pressure, the number of unknowns and the wall time, with the change relative to the
finest level; draws force and time against the number of unknowns.
"""

from __future__ import annotations

import time
from pathlib import Path

import pandas as pd

from mkm.core.records import provenance, save_figure, source_version, write_csv_with_sidecar
from mkm.fem.calibration import Calibration
from mkm.fem.fe.model import Axisym
from mkm.fem.interface import validate_inputs
from mkm.fem.options import MESH_LEVELS


def mesh_convergence(D0_mm: float = 35.0, t0_mm: float = 2.5, eps: float = 0.05,
                     pressure_bar: float = 2.5, theta0_deg: float | None = None,
                     L0_mm: float = 282.0, levels=tuple(MESH_LEVELS),
                     calibration: Calibration | None = None) -> pd.DataFrame:
    """Force of one isometric point per mesh level (default: muscle I at 2.5 bar).

    Returns one row per level: ``mesh``, ``elements_wall``, ``elements_length``, ``dofs``,
    ``force_N``, ``threshold_pressure_bar``, ``seconds``, ``iterations``, ``converged``,
    ``failure`` (why a level did not converge; empty otherwise) and ``force_change_vs_finest``
    (relative to the last level).
    """
    validate_inputs(pressure_bar, D0_mm, t0_mm, eps)
    rows, params = [], {}
    for level in levels:
        # the muscle of the calibration: its angle, and its rubber and gap where identified
        model = Axisym(theta0_deg=theta0_deg, L0_mm=L0_mm, mesh=level, calibration=calibration)
        start = time.perf_counter()
        out = model.predict([pressure_bar], D0_mm, t0_mm, eps)
        seconds = time.perf_counter() - start
        params = model.params()
        n_r, n_z, _ = MESH_LEVELS[level]
        rows.append({"mesh": level, "elements_wall": n_r, "elements_length": n_z,
                     "dofs": int(out.extras["dofs"][0]), "force_N": float(out.force_N[0]),
                     "threshold_pressure_bar": float(out.extras["threshold_pressure_bar"][0]),
                     "seconds": seconds,
                     "iterations": int(out.extras["iterations"][0]),
                     "converged": bool(out.converged[0]),
                     "failure": str(out.extras["failure"][0])})
    frame = pd.DataFrame(rows)
    finest = frame["force_N"].iloc[-1]
    frame["force_change_vs_finest"] = (frame["force_N"] - finest) / finest
    frame.attrs.update(D0_mm=D0_mm, t0_mm=t0_mm, eps=eps, pressure_bar=pressure_bar,
                       **{k: v for k, v in params.items() if k != "mesh"})
    return frame


def plot_mesh_convergence(frame: pd.DataFrame):
    """Force (left axis) and wall time (right axis) against the number of unknowns."""
    from matplotlib.figure import Figure

    fig = Figure(figsize=(6.4, 4.0), layout="constrained")
    ax = fig.add_subplot()
    ax.plot(frame["dofs"], frame["force_N"], "o-", color="C0")
    for _, row in frame.iterrows():
        ax.annotate(f"{row['mesh']}\n{row['force_change_vs_finest']:+.2e}",
                    (row["dofs"], row["force_N"]), textcoords="offset points", xytext=(4, 4),
                    fontsize=8)
    ax.set_xscale("log")
    ax.margins(x=0.15, y=0.2)  # room for the labels
    ax.set_xlabel("unknowns (dofs)")
    ax.set_ylabel("force [N]", color="C0")
    ax.ticklabel_format(axis="y", useOffset=False)
    ax2 = ax.twinx()
    ax2.plot(frame["dofs"], frame["seconds"], "s--", color="C1")
    ax2.set_ylabel("wall time of the isometric solve [s]", color="C1")
    a = frame.attrs
    ax.set_title(f"axisym mesh convergence: D0 {a['D0_mm']:g} mm, t0 {a['t0_mm']:g} mm, "
                 f"eps {a['eps']:g}, {a['pressure_bar']:g} bar, theta0 {a['theta0_deg']:g} deg",
                 fontsize=9)
    return fig


def convergence_study(out_dir="reports/fem-convergence", **kwargs) -> tuple[pd.DataFrame, Path]:
    """Run :func:`mesh_convergence`, write its CSV (with provenance JSON) and chart PNG."""
    frame = mesh_convergence(**kwargs)
    out = Path(out_dir)
    write_csv_with_sidecar(out / "mesh_convergence.csv",
                           frame.to_csv(index=False, float_format="%.8g", lineterminator="\n"),
                           {"inputs": frame.attrs, **provenance(),
                            "code_version": source_version(__name__, "mkm.fem.fe.model")})
    png = out / "mesh_convergence.png"
    save_figure(plot_mesh_convergence(frame), png)
    return frame, png
