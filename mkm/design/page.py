"""The files of ``mkm design``: ``designs.csv``, ``designs.json``, ``design.html`` and figures.

``designs.csv`` is plain CSV (one row per verified design, columns in :data:`COLUMN_DOCS`),
``designs.json`` its sidecar (requirements, constraints, search and verification summary,
provenance), ``fe_curves.csv`` the FE force-pressure curves; ``design.html`` is one
self-contained page in the style of the validation report (:mod:`mkm.html`) with a contour
figure per requirement and the FE curves. Figures are built without pyplot (no global state).
"""

from __future__ import annotations

import re
import warnings
from pathlib import Path

import numpy as np
import pandas as pd
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Patch, Rectangle

from mkm.core.records import (
    check_output_folder,
    holds_provenance,
    provenance,
    save_figure,
    sidecar_path,
    source_version,
    write_atomic,
    write_csv_with_sidecar,
)
from mkm.design.box_search import (
    FE_SEARCH_MESH,
    box_text,
    geometry_text,
    span_text,
    surrogate_uncertainty,
)
from mkm.design.result import DesignResult, design_record
from mkm.design.robust import WORST_CORNER_UNSOLVED
from mkm.design.spec import NEAR_LOCK_FRACTION, rubber_of
from mkm.fem.calibration import calibration_provenance
from mkm.fem.thickwall import outer_diameter_mm
from mkm.html import (
    esc,
    figure_html,
    html_page,
    kv_html,
    provenance_details,
    table_html,
)
from mkm.registry import parse_spec


def output_files(n_requirements: int) -> list[str]:
    """The files :func:`write_design` writes for ``n_requirements`` requirements."""
    return ["designs.csv", "designs.json", "fe_curves.csv", "fe_curves.png", "design.html",
            *(f"requirement{k}_contours.png" for k in range(1, n_requirements + 1))]


def write_design(result: DesignResult, out: Path) -> Path:
    """``designs.csv``, ``designs.json``, ``design.html`` and the figures into ``out``: a new
    folder or one ``mkm design`` wrote (``ValueError`` naming a file of another in the way)."""
    s = result.search
    check_output_folder(out, output_files(len(s.requirements)), "designs.json")
    earlier = holds_provenance(out / "designs.json")
    out.mkdir(parents=True, exist_ok=True)
    record = design_record(result)
    surrogate = next(iter(s.models.values()))
    fe = next(iter(result.fe_models.values()), None)
    record["provenance"] = {
        "software": provenance(),
        "surrogate": {"name": surrogate.name, "params": surrogate.params(),
                      "sha256": (getattr(surrogate, "metadata", None) or {}).get("sha256"),
                      "trained": (getattr(surrogate, "metadata", None) or {}).get("trained"),
                      "dataset": (getattr(surrogate, "metadata", None) or {}).get("dataset"),
                      "families_L0_theta0_rubber": [list(key) for key in s.models]},
        "fe": {"name": fe.name, "params": fe.params(),
               "version": source_version(type(fe).__module__),
               "calibration": calibration_provenance(fe)} if fe else None,
        # where the default theta0 (the constraints' default) came from
        "default_theta0": calibration_provenance(parse_spec("axisym").build(s.calibration)),
        "design_version": source_version("mkm.design"),
    }
    record["columns"] = COLUMN_DOCS
    csv = write_csv_with_sidecar(out / "designs.csv", result.designs.to_csv(
        index=False, float_format="%.6g", lineterminator="\n"), record)
    write_atomic(out / "fe_curves.csv", result.curves.to_csv(index=False, float_format="%.6g",
                                                             lineterminator="\n"))
    figures = []
    best = result.chosen if result.chosen is not None else result.designs.iloc[0]
    # an FE search evaluated its coarse grid only: no model to draw over the whole box
    if not s.fe_search:
        data = contour_data(result, best)
        for k, req in enumerate(s.requirements, start=1):
            fig = contour_figure(result, k - 1, best, data)
            figures.append((save_figure(fig, out / f"requirement{k}_contours.png"),
                            f"Requirement {k} ({esc(req.label)}): surrogate force over D0 x t0 at "
                            f"{req.pressure_bar:g} bar and eps = {req.eps:g} (L0 = "
                            f"{best['L0_mm']:.4g} mm, theta0 = {best['theta0_deg']:.4g} deg, "
                            f"{esc(best['rubber'])}); black line: the required force, dashed: "
                            "plus the surrogate margin; hatched: feasible for every requirement "
                            "and the housing (dotted: its outer diameter limit); dashed box: the "
                            "constraints (the search's feasible set is the hatched region inside "
                            "it); markers: the verified designs (white: the FE confirms), star: "
                            "the chosen design."))
    # a design of more requirements written here before left its contours of the others (a
    # folder that held no design keeps its files)
    drawn = {path.name for path, _ in figures}
    for stale in out.glob("requirement*_contours.png") if earlier else ():
        if re.fullmatch(r"requirement\d+_contours\.png", stale.name) and stale.name not in drawn:
            stale.unlink(missing_ok=True)
    fig = curves_figure(result)
    figures.append((save_figure(fig, out / "fe_curves.png"),
                    "FE force against pressure of the "
                    + (f"{MAX_CURVES} best of the {len(result.designs)} verified designs (every "
                       "one in fe_curves.csv)" if len(result.designs) > MAX_CURVES
                       else "verified designs") + " (axisym, "
                    f"{esc(result.mesh)} mesh, the chosen design's fe_mesh) at each "
                    "requirement's eps; triangles: the "
                    "requirements (the force must reach them); crosses: FE points that did "
                    "not converge."))
    html = out / "design.html"
    write_atomic(html, html_page("McKibben muscle design", _html_body(result, record, figures)))
    result.files = {"csv": csv, "json": sidecar_path(csv), "html": html}
    return html


COLUMN_DOCS = {
    "rank": "rank of the design in the surrogate search (1: best by the objective)",
    "D0_mm": "inner tube diameter at rest [mm]", "t0_mm": "wall thickness at rest [mm]",
    "L0_mm": "length at rest [mm]", "theta0_deg": "braid angle at rest [deg]",
    "rubber": "wall material: calibrated (the calibration's, else Silastic S) or a set of "
              "mkm.fem.materials.MATERIALS",
    "outer_diameter_mm": "braid diameter of the unloaded muscle at the working pressure [mm] "
                         "(thick-wall kinematics, free contraction)",
    "rubber_volume_cm3": "wall volume at rest [cm^3]",
    "r<k>_surrogate_N": "surrogate force at requirement k [N]",
    "r<k>_uncertainty_N": "margin the surrogate force had to clear [N]",
    "r<k>_fe_N": "FE force at requirement k [N] (empty: not converged)",
    "r<k>_fe_low95_N": "with --calibration of an identified muscle, the chosen design's 95 % "
                       "band at requirement k: the least a muscle of the identified "
                       "uncertainty pulls [N] (empty for the other designs: the band is solved "
                       "for the chosen one alone)",
    "r<k>_fe_high95_N": "the same band's upper end: the most a muscle of the identified "
                        "uncertainty pulls [N], what the load cell and the frame must take",
    "r<k>_fe_margin_N": "FE force minus the required force [N]",
    "r<k>_fe_margin_pct": "FE margin over the required force [%]",
    "r<k>_threshold_bar": "FE threshold pressure of requirement k's eps [bar]",
    "r<k>_meets": "the FE force meets requirement k",
    "meets_all": "the FE force meets every requirement (the verdict)",
    "min_fe_margin_pct": "smallest FE margin over the requirements [%]",
    "fe_mesh": "FE mesh of the forces: the one asked for, or for the chosen design a finer "
               "one where that mesh met a requirement by less than its force may lie from the "
               "fine mesh's (mkm.mesh_errors)",
    "flags": "r<k>:near_lock, r<k>:threshold_above_pressure, r<k>:fe_not_converged, "
             "r<k>:margin_within_mesh_error",
    "fe_failure": "the FE's own failure message per requirement (and per worst corner of "
                  "the tolerances)",
}

FLAG_TEXT = {"near_lock": f"near the braid lock (eps >= {NEAR_LOCK_FRACTION:g} eps_max of "
                          "Equation 2, or the FE's braid locks before eps: a physical "
                          "limit, its reason under fe_failure)",
             "threshold_above_pressure": "the threshold pressure is at or above the "
                                         "requirement's pressure: the muscle does not pull",
             "fe_not_converged": "the FE did not converge",
             "margin_within_mesh_error": "met by less than the mesh's force may lie from the "
                                         "fine mesh's (mkm.mesh_errors; or the mesh's bound is "
                                         "not measured for this muscle's end zone): only the "
                                         "chosen design is verified again on a finer mesh; "
                                         "--mesh fine verifies every one there",
             "worst_corner_short": "the FE force at the worst corner of the tolerances is "
                                   "short of the requirement (a corner is rarer than the "
                                   "probability's complement)",
             WORST_CORNER_UNSOLVED: "the FE gave no force at the worst corner of the "
                                    "tolerances (its reason under fe_failure): whether the "
                                    "muscle built to them meets the requirement is unknown",
             "probability_below_target": "the Monte Carlo probability of meeting every "
                                         "requirement is below the one asked for"}


def _constraint_text(key: str, value) -> str:
    if isinstance(value, list) and key != "rubber":
        return f"{key} = {span_text(*value)}"
    if key == "rubber":
        return f"rubber = {', '.join(value)}"
    return f"{key} = {'none' if value is None else format(value, 'g')}"


def _cell(value) -> str:
    if isinstance(value, bool | np.bool_):
        return "yes" if value else "no"
    if isinstance(value, float | np.floating):
        return "—" if np.isnan(value) else f"{value:.5g}"
    return str(value) if value != "" else "—"


def _html_body(result: DesignResult, record: dict, figures) -> str:
    s = result.search
    software = record["provenance"]["software"]
    best = result.chosen
    status = (f'<p><span class="status status-complete">chosen: {esc(geometry_text(best))}, outer '
              f"diameter {best['outer_diameter_mm']:.1f} mm at {s.working_pressure_bar:g} bar"
              "</span></p>" if best is not None else
              '<p><span class="status status-other">no verified design meets every '
              "requirement by the FE: see the margins below</span></p>")
    reqs = pd.DataFrame([{"requirement": f"r{k}", "force [N] at least": r.force_N,
                          "pressure [bar]": r.pressure_bar, "eps": r.eps}
                         for k, r in enumerate(s.requirements, start=1)])
    keep = ("_surrogate_N", "_fe_N", "_fe_margin_pct", "_meets", "_fe_worst_corner_N")
    table = result.designs[[c for c in result.designs.columns
                            if not re.match(r"r\d+_", c) or c.endswith(keep)]]
    table = table.drop(columns=["fe_failure"]).set_index("rank").T  # a column per design
    table = table.map(_cell)
    table.columns = [f"design {rank}" for rank in table.columns]
    table.insert(0, "quantity", table.index)
    notes = []
    for _, row in result.designs.iterrows():
        for flag in filter(None, str(row["flags"]).split(";")):
            k, code = flag.split(":")
            notes.append(f"design rank {row['rank']}, {k}: {FLAG_TEXT[code]}")
    parts = [
        f"<p>Generated {esc(software['date_utc'])} by <code>{esc(software['command'])}</code>. "
        f"Objective: <b>{esc(s.objective)}</b>. The "
        f"{'FE model (' + FE_SEARCH_MESH + ' mesh)' if s.fe_search else esc(s.searcher)} searched "
        f"the box {esc(box_text(s.box))}; the FE model "
        "(axisym, " + esc(result.mesh) + " mesh) verified the best designs, the chosen one "
        "again on a finer mesh where it met a requirement by less than that mesh's error (its "
        "fe_mesh): a design meets "
        "the requirements only when the FE says so, and every margin below is the FE's.</p>",
        status,
        *(f'<p class="note">{esc(note)}</p>' for note in result.notes()),
        table_html(reqs, "Requirements: the force the muscle must develop at least, held at "
                   "eps, at that pressure."),
        kv_html({"constraints": ", ".join(_constraint_text(k, v)
                                          for k, v in s.constraints.items()),
                 "working pressure": f"{s.working_pressure_bar:g} bar (outer diameter check)",
                 "surrogate margin": s.uncertainty,
                 "search": record["summary"]}),
        "<h2>Verified designs</h2>",
        table_html(table, "Verified designs, one column each, those the FE confirms first: "
                   "geometry, outer diameter at the working pressure [mm], rubber volume "
                   "[cm³], per requirement r&lt;k&gt; the surrogate's and the FE's force [N] "
                   "and the FE margin [%]; meets_all is the FE's verdict. designs.csv has the "
                   "surrogate margins, FE threshold pressures and failures too."),
        ('<p class="note">Flags: ' + esc("; ".join(notes)) + "</p>") if notes else "",
        "<h2>Figures</h2>",
        *(figure_html(path, caption) for path, caption in figures),
        provenance_details(record["provenance"], "designs.json"),
    ]
    return "".join(parts)


# --- figures ------------------------------------------------------------------------------------


def contour_data(result: DesignResult, best, n_D0: int = 81, n_t0: int = 41) -> dict:
    """The surrogate over its whole D0 x t0 box at ``best``'s L0, theta0 and rubber, for the
    contour figures: ``D0``, ``t0`` grids [mm], per requirement ``force`` and ``margin`` [N],
    ``outer`` diameter [mm] and ``feasible`` (every requirement with its margin, the housing)."""
    s = result.search
    model = s.models[(best["L0_mm"], best["theta0_deg"], best["rubber"])]
    d = model.domain
    D0, t0 = np.meshgrid(np.linspace(*d.D0_mm, n_D0), np.linspace(*d.t0_mm, n_t0))
    out = {"D0": D0, "t0": t0, "force": [], "margin": []}
    # a box as wide as the practical range's holds walls thicker than the tube's radius: no tube
    wall = t0 < D0 / 2
    feasible = wall.copy()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for r in s.requirements:
            pred = model.predict(r.pressure_bar, D0[wall], t0[wall], r.eps)
            margin, _ = surrogate_uncertainty(model, pred, r.force_N)
            f, u = np.full(D0.shape, np.nan), np.full(D0.shape, np.nan)
            f[wall] = np.where(pred.valid, pred.force_N, np.nan)
            u[wall] = margin
            feasible &= np.nan_to_num(f - u, nan=-np.inf) >= r.force_N
            out["force"].append(f)
            out["margin"].append(u)
    out["outer"] = outer_diameter_mm(D0, t0, best["theta0_deg"], s.working_pressure_bar,
                                     rubber_of(best["rubber"], s.calibration).C10_MPa,
                                     rubber_of(best["rubber"], s.calibration).C01_MPa,
                                     s.gap_mm)
    limit = s.constraints.get("max_outer_diameter_mm")
    out["feasible"] = feasible if limit is None else feasible & (out["outer"] <= limit)
    return out


def contour_figure(result: DesignResult, index: int, best, data: dict) -> Figure:
    """Surrogate force over the surrogate's D0 x t0 box at requirement ``index`` (``data`` from
    :func:`contour_data`): the required force, the feasible region hatched, the housing limit,
    the constraint box dashed, the verified designs and the chosen one marked."""
    s = result.search
    req = s.requirements[index]
    D0, t0 = data["D0"], data["t0"]
    force, margin = data["force"][index], data["margin"][index]
    fig = Figure(figsize=(8.8, 4.8), layout="constrained")
    ax = fig.subplots()
    filled = ax.contourf(D0, t0, force, levels=14, cmap="viridis")
    fig.colorbar(filled, ax=ax, label=f"surrogate force at {req.pressure_bar:g} bar, "
                 f"eps {req.eps:g} [N]")
    ax.contour(D0, t0, force, levels=[req.force_N], colors="black", linewidths=1.6)
    ax.contour(D0, t0, force - margin, levels=[req.force_N], colors="black",
               linewidths=1.0, linestyles="--")
    if data["feasible"].any():
        ax.contourf(D0, t0, data["feasible"].astype(float), levels=[0.5, 1.5], colors="none",
                    hatches=["///"])
    limit = s.constraints.get("max_outer_diameter_mm")
    if limit is not None:
        ax.contour(D0, t0, data["outer"], levels=[limit], colors="white", linewidths=1.4,
                   linestyles=":")
    (lo_D, hi_D), (lo_t, hi_t) = s.constraints["D0_mm"], s.constraints["t0_mm"]
    ax.add_patch(Rectangle((lo_D, lo_t), hi_D - lo_D, hi_t - lo_t, fill=False, color="white",
                           linestyle="--", linewidth=1.2))
    ok = result.designs[result.designs["meets_all"]]
    bad = result.designs[~result.designs["meets_all"]]
    ax.plot(ok["D0_mm"], ok["t0_mm"], "o", color="white", markeredgecolor="black",
            clip_on=False, zorder=4)
    ax.plot(bad["D0_mm"], bad["t0_mm"], "o", color="none", markeredgecolor="red",
            clip_on=False, zorder=4)
    ax.plot([best["D0_mm"]], [best["t0_mm"]], "*", color="gold", markeredgecolor="black",
            markersize=16, clip_on=False, zorder=5)
    handles = [Line2D([], [], color="black", label=f"{req.force_N:g} N required"),
               Line2D([], [], color="black", linestyle="--", label="required + margin"),
               Patch(facecolor="none", hatch="///", edgecolor="black",
                     label="feasible (every\nrequirement, housing)"),
               Line2D([], [], color="0.5", linestyle="--", label="constraint box"),
               Line2D([], [], marker="o", color="white", markeredgecolor="black",
                      linestyle="none", label="verified: FE meets all"),
               Line2D([], [], marker="o", color="none", markeredgecolor="red",
                      linestyle="none", label="verified: FE falls short"),
               Line2D([], [], marker="*", color="gold", markeredgecolor="black",
                      linestyle="none", markersize=12, label="chosen")]
    if limit is not None:
        handles.insert(3, Line2D([], [], color="0.5", linestyle=":",
                                 label=f"outer diameter {limit:g} mm\nat "
                                       f"{s.working_pressure_bar:g} bar"))
    fig.legend(handles=handles, fontsize=7.5, loc="outside right upper")
    ax.set(xlabel="inner diameter D0 [mm]", ylabel="wall thickness t0 [mm]",
           title=f"requirement {index + 1}: {req.label}")
    return fig


#: Curves drawn in fe_curves.png, the best-ranked: more (--top 300) fill the figure with their
#: legend; every verified design's curve is in fe_curves.csv
MAX_CURVES = 10


def curves_figure(result: DesignResult) -> Figure:
    """FE force against pressure of the :data:`MAX_CURVES` best verified designs, one panel
    per eps, requirements as triangles."""
    eps_levels = sorted({r.eps for r in result.search.requirements})
    fig = Figure(figsize=(5.0 * len(eps_levels) + 1.0, 4.4), layout="constrained")
    axes = fig.subplots(1, len(eps_levels), squeeze=False)[0]
    curves = result.curves
    for ax, eps in zip(axes, eps_levels, strict=True):
        for j, (_, row) in enumerate(result.designs.head(MAX_CURVES).iterrows()):
            rows = curves[(curves["design"] == row["rank"]) & np.isclose(curves["eps"], eps)]
            rows = rows.sort_values("pressure_bar")
            style = "-" if row["meets_all"] else ":"
            ax.plot(rows["pressure_bar"], rows["force_N"], style, color=f"C{j}",
                    label=f"#{row['rank']}: D0 {row['D0_mm']:.2f}, t0 {row['t0_mm']:.2f}"
                    + ("" if row["meets_all"] else " (short)"))
            bad = rows[~rows["converged"].astype(bool)]
            if len(bad):
                ax.plot(bad["pressure_bar"], np.zeros(len(bad)), "x", color="0.45",
                        clip_on=False)
        for k, r in enumerate(result.search.requirements, start=1):
            if r.eps == eps:
                ax.plot([r.pressure_bar], [r.force_N], "^", color="black", markersize=10,
                        zorder=5)
                ax.annotate(f"r{k} ≥ {r.force_N:g} N", (r.pressure_bar, r.force_N),
                            textcoords="offset points", xytext=(-60, 8), fontsize=8)
        ax.set(xlabel="pressure P [bar]", ylabel="FE force F [N]", title=f"eps = {eps:g}")
        ax.set_xlim(left=0.0)
        ax.set_ylim(bottom=0.0)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7, loc="upper left")
    return fig
