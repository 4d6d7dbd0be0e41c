"""The figures of the validation report and of the speed-accuracy study (matplotlib, Agg).

Each function takes tidy pandas data and returns a :class:`matplotlib.figure.Figure` built without
pyplot (no global state, no display needed). Conventions shared by every figure: forces in N,
pressures in bar, errors in % (the paper's Equation 7); a point where a model is invalid or out
of its domain is never drawn as a number but as a grey cross on the axis, with a legend entry.
"""

from __future__ import annotations

import numpy as np
import pandas as pd
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Patch

MODEL_COLOURS = {"eq2": "tab:blue", "eq2-inner": "tab:blue", "eq2-braid": "tab:cyan",
                 "thickwall": "tab:orange", "axisym": "tab:green", "axisym-coarse": "yellowgreen",
                 "axisym-medium": "tab:green", "axisym-fine": "darkgreen",
                 "surrogate": "tab:red", "auto": "tab:purple"}
INVALID_STYLE = {"marker": "x", "color": "0.45", "linestyle": "none", "markersize": 7,
                 "clip_on": False}


def distinct_colours(labels) -> dict[str, str]:
    """One colour per label: the model's own, or the next unused default where two labels of the
    same model (``eq2``, ``eq2:theta0_deg=50``) would share it."""
    out: dict[str, str] = {}
    spare = (f"C{k}" for k in range(4, 100))
    for i, label in enumerate(labels):
        c = colour(label, i)
        while c in out.values():
            c = next(spare)
        out[label] = c
    return out


def colour(label: str, index: int = 0) -> str:
    """The model's colour in every figure (``axisym:mesh=coarse`` and ``axisym-coarse`` are
    axisym); unknown labels cycle through matplotlib's defaults."""
    for key in (label, label.split(":")[0], label.split("-")[0]):
        if key in MODEL_COLOURS:
            return MODEL_COLOURS[key]
    return f"C{index % 10}"


def _mark_invalid(ax, pressures) -> None:
    """Grey crosses on the bottom edge at the pressures where a model gave no valid number."""
    if len(pressures):
        ax.plot(pressures, np.zeros(len(pressures)), transform=ax.get_xaxis_transform(),
                **INVALID_STYLE)


def run_figure(steps: pd.DataFrame, predictions: pd.DataFrame, title: str) -> Figure:
    """Force against pressure (measured up and down sweeps, every model) and Err% per pressure.

    ``steps``: ``pressure_bar_mean, force_N_mean, force_N_std, direction``. ``predictions``: one
    row per model and step with ``model, pressure_bar, direction, force_N, valid, err_pct``.
    """
    fig = Figure(figsize=(11, 4.6), layout="constrained")
    ax_f, ax_e = fig.subplots(1, 2)
    for direction, marker, face in (("up", "o", "black"), ("down", "s", "white")):
        sweep = steps[steps["direction"] == direction].sort_values("pressure_bar_mean")
        if len(sweep):
            ax_f.errorbar(sweep["pressure_bar_mean"], sweep["force_N_mean"],
                          yerr=sweep["force_N_std"], fmt=marker, color="black",
                          markerfacecolor=face, capsize=3, zorder=5,
                          label=f"measured, {direction} sweep (mean ± std)")
    any_invalid = False
    colours = distinct_colours(dict.fromkeys(predictions["model"]))
    for model, rows in predictions.groupby("model", sort=False):
        c = colours[model]
        curve = rows.drop_duplicates("pressure_bar").sort_values("pressure_bar")
        ax_f.plot(curve["pressure_bar"], curve["force_N"].where(curve["valid"]), "-", color=c,
                  label=model)
        for direction, style in (("up", "-"), ("down", "--")):
            sweep = rows[rows["direction"] == direction].sort_values("pressure_bar")
            ax_e.plot(sweep["pressure_bar"], sweep["err_pct"].where(sweep["valid"]), style,
                      marker="o" if direction == "up" else "s", markersize=4, color=c,
                      markerfacecolor=c if direction == "up" else "white")
        bad = curve.loc[~curve["valid"], "pressure_bar"]
        _mark_invalid(ax_f, bad)
        _mark_invalid(ax_e, rows.loc[~rows["valid"], "pressure_bar"].unique())
        any_invalid |= len(bad) > 0
    ax_f.set(xlabel="pressure P [bar]", ylabel="force F [N]", title="force against pressure")
    ax_f.set_ylim(bottom=min(0.0, ax_f.get_ylim()[0]))
    handles, labels = ax_f.get_legend_handles_labels()
    if any_invalid:
        handles.append(Line2D([], [], **INVALID_STYLE))
        labels.append("model invalid / out of domain")
    ax_f.legend(handles, labels, fontsize=8, loc="upper left")
    ax_e.axhline(0.0, color="0.6", linewidth=0.8)
    ax_e.set(xlabel="pressure P [bar]", ylabel="Err% = (F_meas − F_model) / max F_meas [%]",
             title="error against the measurement (Equation 7)")
    models = list(colours)
    ax_e.legend([Line2D([], [], color=colours[m], linewidth=3) for m in models]
                + [Line2D([], [], color="0.3", marker="o", linestyle="-"),
                   Line2D([], [], color="0.3", marker="s", markerfacecolor="white",
                          linestyle="--")],
                [*models, "up sweep", "down sweep"], fontsize=8, loc="best")
    for ax in (ax_f, ax_e):
        ax.grid(True, alpha=0.3)
        ax.set_xlim(left=0.0)
    fig.suptitle(title)
    return fig


def surrogate_fe_figure(table: pd.DataFrame, title: str) -> Figure:
    """The paper's Figure 6 with our numbers: FE against surrogate for each test muscle.

    ``table``: ``muscle, pressure_bar, force_fe_N, force_N, valid, err_pct``.
    """
    fig = Figure(figsize=(11, 4.6), layout="constrained")
    ax_f, ax_e = fig.subplots(1, 2)
    for i, (muscle, rows) in enumerate(table.groupby("muscle", sort=False)):
        rows = rows.sort_values("pressure_bar")
        c = f"C{i}"
        ax_f.plot(rows["pressure_bar"], rows["force_fe_N"], "o", color=c, markersize=5,
                  label=f"{muscle}: FE")
        ax_f.plot(rows["pressure_bar"], rows["force_N"].where(rows["valid"]), "-", color=c,
                  label=f"{muscle}: surrogate")
        ax_e.plot(rows["pressure_bar"], rows["err_pct"].where(rows["valid"]), "-o", color=c,
                  markersize=4, label=f"muscle {muscle}")
        _mark_invalid(ax_f, rows.loc[~rows["valid"], "pressure_bar"])
    ax_f.set(xlabel="pressure P [bar]", ylabel="force F [N]",
             title="FE (dots) and surrogate (lines)")
    ax_f.legend(fontsize=7, ncol=2, loc="upper left")
    ax_e.axhline(0.0, color="0.6", linewidth=0.8)
    ax_e.set(xlabel="pressure P [bar]", ylabel="Err% = (F_FE − F_sur) / max F_FE [%]",
             title="error against the FE model (Equation 7)")
    ax_e.legend(fontsize=8)
    for ax in (ax_f, ax_e):
        ax.grid(True, alpha=0.3)
        ax.set_xlim(left=0.0)
    fig.suptitle(title)
    return fig


FAMILY_MARKERS = {"closed form": "D", "FE": "s", "surrogate": "o", "paper net": "x",
                  "paper net, standardised force": "+"}
SMALL_FAMILIES = ("paper net", "paper net, standardised force")  # 27 points each: no labels


def speed_accuracy_figure(summary: pd.DataFrame, machine: str) -> Figure:
    """Seconds per predicted force (log) against the largest |Err%| (log), Pareto front marked.

    ``summary``: one row per predictor with ``predictor, family, seconds_per_point,
    max_abs_err_pct, pareto``. The reference (error 0 by definition) is drawn as a star on the
    bottom edge.
    """
    from matplotlib.ticker import FuncFormatter

    fig = Figure(figsize=(10, 6.2), layout="constrained")
    ax = fig.subplots()
    positive = summary.loc[summary["max_abs_err_pct"] > 0, "max_abs_err_pct"]
    floor = 0.3 * positive.min() if len(positive) else 1e-3
    y = summary["max_abs_err_pct"].where(summary["max_abs_err_pct"] > 0, floor)
    is_reference = summary["max_abs_err_pct"] == 0
    for family, marker in FAMILY_MARKERS.items():
        rows = (summary["family"] == family) & ~is_reference
        if rows.any():
            small = family in SMALL_FAMILIES
            ax.scatter(summary.loc[rows, "seconds_per_point"], y[rows], marker=marker,
                       s=25 if small else 55, linewidths=1.0,
                       c="0.5" if family == "paper net" else "0.2" if small else None,
                       label=family + (" (27 nets)" if small else ""), zorder=3)
    ax.scatter(summary.loc[is_reference, "seconds_per_point"], y[is_reference], marker="*",
               s=160, color="black", label="reference (error 0 by definition)", zorder=4)
    front = summary[summary["pareto"]].sort_values("seconds_per_point")
    ax.step(front["seconds_per_point"], y[front.index], where="post", color="tab:red",
            linewidth=1.5, label="Pareto front (nothing both faster and more accurate)", zorder=2)
    # Label the front first, then the named predictors where there is room (a label closer than
    # 0.3 decade in time and 0.05 decade in error to a placed one is left to the CSV table).
    labelled = summary[~summary["family"].isin(SMALL_FAMILIES) | summary["pareto"]]
    labelled = labelled.assign(y=y).sort_values(["pareto", "y"], ascending=[False, True])
    placed: list[tuple[float, float]] = []
    for _, row in labelled.iterrows():
        at = (np.log10(row["seconds_per_point"]), np.log10(row["y"]))
        if not row["pareto"] and any(abs(at[0] - a) < 0.3 and abs(at[1] - b) < 0.05
                                     for a, b in placed):
            continue
        placed.append(at)
        ax.annotate(row["predictor"], (row["seconds_per_point"], row["y"]),
                    textcoords="offset points", xytext=(6, 3), fontsize=7.5)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.yaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
    ax.set(xlabel="seconds per predicted force [s] (one call per muscle sweep, median)",
           ylabel="largest |Err%| against the reference [%]",
           title=f"speed against accuracy, measured on {machine}")
    ax.grid(True, which="major", alpha=0.35)
    ax.grid(True, which="minor", alpha=0.1)
    ax.legend(fontsize=8, loc="best")
    return fig


STABILITY_CLASSES = {
    "ok": "#d9f0d3",
    "invalid (model's own limit)": "#fdb863",
    "not converged": "#d7191c",
    "out of training domain": "#abd9e9",
    "negative force": "#7b3294",
    "force falls with pressure": "#f1a6c9",
}


def stability_figure(cells: pd.DataFrame, method: str) -> Figure:
    """Where ``method`` fails over pressure and eps, one panel per muscle.

    ``cells``: ``muscle, pressure_bar, eps, status`` (a key of :data:`STABILITY_CLASSES`) and
    optionally ``cutbacks`` (written in the cell when > 0).
    """
    from matplotlib.colors import BoundaryNorm, ListedColormap

    names = list(STABILITY_CLASSES)
    cmap = ListedColormap(list(STABILITY_CLASSES.values()))
    norm = BoundaryNorm(np.arange(len(names) + 1) - 0.5, cmap.N)
    muscles = list(dict.fromkeys(cells["muscle"]))
    fig = Figure(figsize=(5.2 * len(muscles) + 1.5, 4.6), layout="constrained")
    axes = fig.subplots(1, len(muscles), squeeze=False)[0]
    for ax, muscle in zip(axes, muscles, strict=True):
        rows = cells[cells["muscle"] == muscle]
        grid = rows.pivot(index="eps", columns="pressure_bar", values="status")
        codes = grid.map(names.index).to_numpy(dtype=float)
        P = grid.columns.to_numpy(dtype=float)
        E = 100.0 * grid.index.to_numpy(dtype=float)
        ax.pcolormesh(_edges(P), _edges(E), codes, cmap=cmap, norm=norm, edgecolors="white",
                      linewidth=0.4)
        if "cutbacks" in rows:
            cut = rows.pivot(index="eps", columns="pressure_bar", values="cutbacks")
            for (e, p), n in cut.stack().items():
                if n > 0:
                    ax.text(p, 100.0 * e, f"{int(n)}", ha="center", va="center", fontsize=7)
        ax.set(xlabel="pressure P [bar]", ylabel="shortening ratio eps [%]", title=muscle)
    handles = [Patch(color=STABILITY_CLASSES[n], label=n) for n in names]
    if "cutbacks" in cells and (cells["cutbacks"] > 0).any():
        handles.append(Patch(color="white", label="number: Newton cut-backs needed"))
    fig.legend(handles=handles, loc="outside right center", fontsize=8)
    fig.suptitle(f"stability of {method}")
    return fig


def _edges(centres: np.ndarray) -> np.ndarray:
    """Cell edges around sorted, roughly even centres, for pcolormesh."""
    c = np.asarray(centres, dtype=float)
    if c.size == 1:
        return np.array([c[0] - 0.5, c[0] + 0.5])
    mid = (c[1:] + c[:-1]) / 2.0
    return np.concatenate([[c[0] - (mid[0] - c[0])], mid, [c[-1] + (c[-1] - mid[-1])]])
