"""The figures of the validation report and of the speed-accuracy study (matplotlib).

Each function takes tidy pandas data and returns a :class:`matplotlib.figure.Figure` built without
pyplot (no global state, no backend or display needed). Conventions shared by every figure:
forces in N, pressures in bar, errors in % (the paper's Equation 7), models named as the paper
does (the caller's ``names``) and coloured by registry entry (:func:`model_colours`); a point
where a model is invalid or out of its domain is never drawn as a number but as a cross in a
strip above the axes, with a legend entry.
"""

from __future__ import annotations

import numpy as np
import pandas as pd
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Patch

from mkm.fem.outcomes import BRAID_LOCKS
from mkm.registry import colour as entry_colour

MEASURED = {"color": "black", "capsize": 3, "zorder": 5}
RUN_MARKERS = ("o", "s", "^", "D", "v", "P")
RUN_LINESTYLES = ("-", "--", ":", "-.")
# A point where a model gave no valid number is drawn as a cross in the model's colour in a
# strip ABOVE the axes (never on the force axis, where it would read as a measured 0 N).
INVALID_STYLE = {"marker": "x", "linestyle": "none", "markersize": 6, "clip_on": False}
INVALID_Y = 1.025  # axes fraction


def model_colours(specs) -> dict[str, str]:
    """``spec.text -> colour`` for :class:`mkm.registry.Spec` objects: the registry entry's
    colour, or the next unused default where two specs of one entry (``eq2``,
    ``eq2:theta0_deg=50``) would share it."""
    out: dict[str, str] = {}
    spare = (f"C{k}" for k in range(5, 100))
    for spec in specs:
        c = entry_colour(spec.name)  # the registry entry's, the same in every figure
        while c in out.values():
            c = next(spare)
        out[spec.text] = c
    return out


def _mark_invalid(ax, pressures, colour: str) -> bool:
    """Crosses above the axes at the pressures where a model gave no valid number."""
    pressures = np.asarray(pressures, dtype=float)
    if pressures.size:
        ax.plot(pressures, np.full(pressures.size, INVALID_Y),
                transform=ax.get_xaxis_transform(), color=colour, **INVALID_STYLE)
    return bool(pressures.size)


def _widths(models) -> dict[str, float]:
    """Line widths that shrink along the model list, so a model drawn over another one that
    agrees with it (the surrogate over the FE model it learnt) leaves it visible."""
    models = list(models)
    return {m: 3.6 - 2.4 * i / max(len(models) - 1, 1) for i, m in enumerate(models)}


# Each model its own dash pattern and marker besides its colour: two models that agree (the
# surrogate and the FE model it learnt) stay two lines, not one line of a mixed colour
MODEL_LINESTYLES = ("-", (0, (6, 2)), (0, (2, 1.5)), (0, (6, 2, 1, 2)), (0, (1, 1)))
MODEL_MARKERS = ("", "v", "^", "d", "x")


def _styles(models) -> dict[str, tuple]:
    """``model -> (linestyle, marker)``, one pair per model in the order given."""
    return {m: (MODEL_LINESTYLES[i % len(MODEL_LINESTYLES)],
                MODEL_MARKERS[i % len(MODEL_MARKERS)]) for i, m in enumerate(models)}


#: Two models whose forces differ by less than this fraction of the largest force at every point
#: are drawn as two lines and named as identical in the legend (one stripe is not two models).
IDENTICAL_FRACTION = 0.001


def _identical(predictions: pd.DataFrame, names: dict[str, str]) -> dict[str, str]:
    """``model -> " (identical to <name> within 0.1 %)"`` for each model whose forces match an
    earlier model's at every point where both are valid (and at least one is)."""
    notes: dict[str, str] = {}
    curves = {m: rows.drop_duplicates("pressure_bar").set_index("pressure_bar")
              for m, rows in predictions.groupby("model", sort=False)}
    scale = float(np.nanmax(np.abs(predictions["force_N"].where(predictions["valid"]))
                            .to_numpy(float), initial=0.0))
    if not scale > 0:
        return notes
    models = list(curves)
    for i, model in enumerate(models):
        for earlier in models[:i]:
            a, b = curves[model], curves[earlier]
            both = a.index.intersection(b.index)
            ok = a.loc[both, "valid"].to_numpy(bool) & b.loc[both, "valid"].to_numpy(bool)
            if not ok.any():
                continue
            gap = np.abs(a.loc[both, "force_N"].to_numpy(float)[ok]
                         - b.loc[both, "force_N"].to_numpy(float)[ok])
            if np.all(gap <= IDENTICAL_FRACTION * scale):
                notes[model] = (f" (identical to {names[earlier]} within "
                                f"{100 * IDENTICAL_FRACTION:g} %)")
                break
    return notes


def _time_axis(axis) -> None:
    """A log axis of seconds labelled as a reader takes durations in (``10 µs``, ``1 ms``),
    never in scientific notation."""
    from matplotlib.ticker import FuncFormatter, NullFormatter

    from mkm.verdict import format_seconds

    axis.set_major_formatter(FuncFormatter(lambda v, _: format_seconds(v)))
    axis.set_minor_formatter(NullFormatter())


def _invalid_handle() -> Line2D:
    return Line2D([], [], color="0.3", **INVALID_STYLE)


INVALID_LABEL = "x above the axes: no valid number (invalid or out of domain)"


def _measured(ax, steps: pd.DataFrame, label: str, marker_up="o", marker_down="s") -> None:
    """Measured mean force per step with its expanded uncertainty (95.45 %) in force and pressure
    (± std where the run has no budget): filled up sweep, open down sweep."""
    budget = "force_U_N" in steps and steps["force_U_N"].notna().any()
    for direction, marker, face in (("up", marker_up, "black"), ("down", marker_down, "white")):
        sweep = steps[steps["direction"] == direction].sort_values("pressure_bar_mean")
        if len(sweep):
            ax.errorbar(sweep["pressure_bar_mean"], sweep["force_N_mean"],
                        yerr=sweep["force_U_N" if budget else "force_N_std"],
                        xerr=sweep["pressure_U_bar"] if budget else None, fmt=marker,
                        markerfacecolor=face, label=f"{label}, {direction} "
                        f"({'mean ± U, 95.45 %' if budget else 'mean ± std'})", **MEASURED)


def _model_curve(ax, rows: pd.DataFrame, colour: str, label: str | None,
                 linestyle="-", linewidth: float = 1.5, marker: str = "") -> bool:
    """One model's forces against pressure, its ±2 std band where it has one; returns whether
    a point was invalid."""
    curve = rows.drop_duplicates("pressure_bar").sort_values("pressure_bar")
    force = curve["force_N"].where(curve["valid"])
    ax.plot(curve["pressure_bar"], force, linestyle=linestyle, color=colour, label=label,
            linewidth=linewidth, marker=marker or None, markersize=5, markerfacecolor="none")
    band = "force_u_N" if "force_u_N" in curve and curve["force_u_N"].notna().any() \
        else "force_std_N"
    if band in curve and curve[band].notna().any():
        std = curve[band].where(curve["valid"])
        ax.fill_between(curve["pressure_bar"], force - 2 * std, force + 2 * std, color=colour,
                        alpha=0.18, linewidth=0)
    return _mark_invalid(ax, curve.loc[~curve["valid"], "pressure_bar"], colour)


def run_figure(steps: pd.DataFrame, predictions: pd.DataFrame, title: str,
               names: dict[str, str], colours: dict[str, str]) -> Figure:
    """Force against pressure (measured up and down sweeps, every model with its uncertainty
    band), Err% (Equation 7) and the residual F_meas - F_model [N] per pressure.

    ``steps``: ``pressure_bar_mean, force_N_mean, force_N_std, direction``. ``predictions``: one
    row per model and step with ``model`` (spec text), ``pressure_bar, direction, force_N,
    valid, err_pct, residual_N`` and optionally ``force_std_N``. ``names``: legend name per
    spec text (the paper's name), ``colours``: :func:`model_colours`.
    """
    fig = Figure(figsize=(13, 4.8), layout="constrained")
    ax_f, ax_e, ax_r = fig.subplots(1, 3)
    _measured(ax_f, steps, "measured")
    any_invalid, any_band = False, False
    widths = _widths(dict.fromkeys(predictions["model"]))
    styles = _styles(dict.fromkeys(predictions["model"]))
    identical = _identical(predictions, names)
    for model, rows in predictions.groupby("model", sort=False):
        c = colours[model]
        linestyle, marker = styles[model]
        any_invalid |= _model_curve(ax_f, rows, c, names[model] + identical.get(model, ""),
                                    linestyle=linestyle, linewidth=widths[model],
                                    marker=marker)
        any_band |= any(c in rows and rows[c].notna().any()
                        for c in ("force_std_N", "force_u_N"))
        for direction, style, face in (("up", "-", c), ("down", "--", "white")):
            sweep = rows[rows["direction"] == direction].sort_values("pressure_bar")
            for ax, column in ((ax_e, "err_pct"), (ax_r, "residual_N")):
                ax.plot(sweep["pressure_bar"], sweep[column].where(sweep["valid"]), style,
                        marker="o" if direction == "up" else "s", markersize=4, color=c,
                        markerfacecolor=face, linewidth=widths[model])
        for ax in (ax_e, ax_r):
            _mark_invalid(ax, rows.loc[~rows["valid"], "pressure_bar"].unique(), c)
    ax_f.set_title("force against pressure", pad=14)  # room for the invalid strip
    ax_f.set(xlabel="pressure P [bar]", ylabel="force F [N]")
    ax_f.set_ylim(bottom=min(0.0, ax_f.get_ylim()[0]))
    handles, labels = ax_f.get_legend_handles_labels()
    if any_band:
        handles.append(Patch(color="0.5", alpha=0.3))
        labels.append("model ± 2 u (the muscle's tolerances and the model's own std)")
    if any_invalid:
        handles.append(_invalid_handle())
        labels.append(INVALID_LABEL)
    ax_e.set_title("Err% (Equation 7)", pad=14)
    ax_r.set_title("residual in newtons", pad=14)
    ax_e.set(xlabel="pressure P [bar]", ylabel="Err% = (F_meas − F_model) / max F_meas [%]")
    ax_r.set(xlabel="pressure P [bar]", ylabel="residual F_meas − F_model [N]")
    # the sweeps' styles of the Err% and residual panels: only the sweeps the run has
    drawn = set(predictions["direction"])
    for direction, handle in (("up", Line2D([], [], color="0.3", marker="o", linestyle="-")),
                              ("down", Line2D([], [], color="0.3", marker="s",
                                              markerfacecolor="white", linestyle="--"))):
        if direction in drawn:
            handles.append(handle)
            labels.append(f"Err% and residual: {direction} sweep")
    # below the panels, never over a point
    fig.legend(handles, labels, fontsize=8, loc="outside lower center", ncol=3)
    for ax in (ax_f, ax_e, ax_r):
        ax.grid(True, alpha=0.3)
        ax.set_xlim(left=0.0)
    for ax in (ax_e, ax_r):
        ax.axhline(0.0, color="0.6", linewidth=0.8)
    fig.suptitle(title)
    return fig


def overlay_figure(runs: list[tuple[str, pd.DataFrame, pd.DataFrame]], title: str,
                   names: dict[str, str], colours: dict[str, str]) -> Figure:
    """Runs of one muscle on the same axes, as the paper's Figure 7c/d (eps 0 and 12.2 %):
    measured forces (one marker per run) and every model (one line style per run), and Err%.

    ``runs``: ``(label, steps, predictions)`` per run, as :func:`run_figure` takes them.
    """
    fig = Figure(figsize=(13, 5.2), layout="constrained")
    ax_f, ax_e = fig.subplots(1, 2, width_ratios=[1.25, 1])
    any_invalid = False
    widths = _widths(dict.fromkeys(m for _, _, p in runs for m in p["model"]))
    for i, (_, steps, predictions) in enumerate(runs):
        marker = RUN_MARKERS[i % len(RUN_MARKERS)]
        style = RUN_LINESTYLES[i % len(RUN_LINESTYLES)]
        for direction, face in (("up", "black"), ("down", "white")):
            sweep = steps[steps["direction"] == direction].sort_values("pressure_bar_mean")
            ax_f.errorbar(sweep["pressure_bar_mean"], sweep["force_N_mean"],
                          yerr=sweep["force_N_std"], fmt=marker, markerfacecolor=face,
                          markersize=5, **MEASURED)
        for model, rows in predictions.groupby("model", sort=False):
            any_invalid |= _model_curve(ax_f, rows, colours[model], None, style, widths[model])
            up = rows[rows["direction"] == "up"].sort_values("pressure_bar")
            ax_e.plot(up["pressure_bar"], up["err_pct"].where(up["valid"]), style,
                      marker=marker, markersize=4, color=colours[model],
                      linewidth=widths[model])
    models = list(dict.fromkeys(m for _, _, p in runs for m in p["model"]))
    handles = [Line2D([], [], color=colours[m], linewidth=widths[m]) for m in models]
    # "identical within 0.1 %" only where it holds on every run of the figure
    notes = [_identical(p, names) for _, _, p in runs]
    same = {m: n for m, n in notes[0].items() if all(other.get(m) == n for other in notes)}
    labels = [names[m] + same.get(m, "") for m in models]
    for i, (label, _, _) in enumerate(runs):
        handles.append(Line2D([], [], color="black", marker=RUN_MARKERS[i % len(RUN_MARKERS)],
                              linestyle=RUN_LINESTYLES[i % len(RUN_LINESTYLES)]))
        labels.append(f"{label}: measured (filled up, open down) and models")
    if any_invalid:
        handles.append(_invalid_handle())
        labels.append(INVALID_LABEL)
    fig.legend(handles, labels, fontsize=8, loc="outside lower center", ncol=3)
    ax_f.set_title("measured and modelled force", pad=14)  # room for the invalid strip
    ax_f.set(xlabel="pressure P [bar]", ylabel="force F [N]")
    ax_f.set_ylim(bottom=min(0.0, ax_f.get_ylim()[0]))
    ax_e.axhline(0.0, color="0.6", linewidth=0.8)
    ax_e.set_title("Err% of each model, per run", pad=14)
    ax_e.set(xlabel="pressure P [bar]", ylabel="Err% (Equation 7), up sweep [%]")
    for ax in (ax_f, ax_e):
        ax.grid(True, alpha=0.3)
        ax.set_xlim(left=0.0)
    fig.suptitle(title)
    return fig


def time_figure(bins: pd.DataFrame, steps: pd.DataFrame, title: str,
                gaps: list[tuple[float, float]] = (),
                events: list[tuple[float, str]] = (),
                force_limit_N: float | None = None) -> Figure:
    """Pressure and force against time: the mean per time bin with its min-max band, each
    step's settling window (light) and averaging window (dark), gaps in the record (red) and
    events such as the force interlock (red lines), and the interlock's force limit (dashed)
    when it lies within twice the largest force drawn.

    ``bins``: :func:`mkm.bench.storage.aggregate_samples` output (``time_s``,
    ``pressure_bar_{min,mean,max}``, ``force_N_{min,mean,max}``); ``steps``: ``start_s,
    settle_s, end_s``; ``gaps``: ``(start_s, end_s)``; ``events``: ``(time_s, label)``.
    """
    fig = Figure(figsize=(13, 6.0), layout="constrained")
    ax_p, ax_f = fig.subplots(2, 1, sharex=True)
    scale, unit = (60.0, "min") if len(bins) and bins["time_s"].max() > 900 else (1.0, "s")
    t = bins["time_s"] / scale
    for ax, q, colour in ((ax_p, "pressure_bar", "tab:blue"), (ax_f, "force_N", "black")):
        # plain lines, not steps: the last sample (an interlock spike, say) stays visible
        ax.fill_between(t, bins[f"{q}_min"], bins[f"{q}_max"], color=colour, alpha=0.2,
                        linewidth=0)
        ax.plot(t, bins[f"{q}_mean"], color=colour, linewidth=0.9)
        for row in steps.itertuples():
            hold = row.start_s + row.settle_s
            ax.axvspan(row.start_s / scale, hold / scale, color="#ffe08a", alpha=0.45,
                       linewidth=0)
            ax.axvspan(hold / scale, row.end_s / scale, color="#9fd49b", alpha=0.55,
                       linewidth=0)
        for start, end in gaps:
            ax.axvspan(start / scale, max(end, start + 0.1) / scale, color="red", alpha=0.35,
                       linewidth=0)
        for when, _ in events:
            ax.axvline(when / scale, color="red", linewidth=1.2)
        ax.grid(True, alpha=0.3)
    for when, label in events:
        ax_f.annotate(label, (when / scale, 1.0), xycoords=("data", "axes fraction"),
                      xytext=(3, -12), textcoords="offset points", color="red", fontsize=8)
    shown_limit = (force_limit_N is not None and len(bins)
                   and force_limit_N < 2 * float(np.nanmax(bins["force_N_max"])))
    if shown_limit:
        ax_f.axhline(force_limit_N, color="red", linestyle="--", linewidth=1)
    ax_p.set(ylabel="pressure P [bar]")
    ax_f.set(ylabel="force F [N]", xlabel=f"time since the start of the run [{unit}]")
    handles = [Line2D([], [], color="tab:blue"), Line2D([], [], color="black"),
               Patch(color="0.6", alpha=0.4), Patch(color="#ffe08a"), Patch(color="#9fd49b")]
    labels = ["pressure (mean per bin)", "force (mean per bin)", "min-max within a bin",
              "settling (not averaged)", "averaging window (the step's mean ± std)"]
    if len(gaps):
        handles.append(Patch(color="red", alpha=0.35))
        labels.append("gap in the record (lost samples)")
    if len(events):
        handles.append(Line2D([], [], color="red"))
        labels.append("interlock / stop")
    if shown_limit:
        handles.append(Line2D([], [], color="red", linestyle="--"))
        labels.append(f"force interlock limit {force_limit_N:.0f} N")
    fig.legend(handles, labels, fontsize=8, loc="outside lower center", ncol=4)
    fig.suptitle(title)
    return fig


def surrogate_fe_figure(table: pd.DataFrame, title: str) -> Figure:
    """The paper's Figure 6 with our numbers: FE against surrogate for each test muscle.

    ``table``: ``muscle, pressure_bar, force_fe_N, force_N`` (or ``force_pred_N``, as
    :mod:`mkm.surrogate.testset` writes it), ``valid``, ``err_pct`` (drawn where valid) and
    optionally ``model`` (several surrogates: one line style each).
    """
    table = table.rename(columns={"force_pred_N": "force_N"})
    table = table.assign(err_pct=table["err_pct"].where(table["valid"]))
    fig = Figure(figsize=(11, 4.6), layout="constrained")
    ax_f, ax_e = fig.subplots(1, 2)
    models = list(dict.fromkeys(table["model"])) if "model" in table else [None]
    for i, (muscle, rows) in enumerate(table.groupby("muscle", sort=False)):
        c = f"C{i}"
        fe = rows.drop_duplicates("pressure_bar").sort_values("pressure_bar")
        ax_f.plot(fe["pressure_bar"], fe["force_fe_N"], "o", color=c, markersize=5,
                  label=f"{muscle}: FE")
        for j, model in enumerate(models):
            one = rows if model is None else rows[rows["model"] == model]
            one = one.sort_values("pressure_bar")
            style = RUN_LINESTYLES[j % len(RUN_LINESTYLES)]
            name = "surrogate" if model is None else str(model)
            ax_f.plot(one["pressure_bar"], one["force_N"].where(one["valid"]), style, color=c,
                      label=f"{muscle}: {name}")
            ax_e.plot(one["pressure_bar"], one["err_pct"].where(one["valid"]), style,
                      marker="o", color=c, markersize=4,
                      label=f"muscle {muscle}" + ("" if model is None else f", {name}"))
            _mark_invalid(ax_f, one.loc[~one["valid"], "pressure_bar"], c)
    ax_f.set(xlabel="pressure P [bar]", ylabel="force F [N]",
             title="FE (dots) and surrogate (lines)")
    ax_e.axhline(0.0, color="0.6", linewidth=0.8)
    ax_e.set(xlabel="pressure P [bar]", ylabel="Err% = (F_FE − F_sur) / max F_FE [%]",
             title="error against the FE model (Equation 7)")
    # one colour per muscle in both panels: one legend, below them, never over a point
    fig.legend(*ax_f.get_legend_handles_labels(), fontsize=8, ncol=4,
               loc="outside lower center")
    for ax in (ax_f, ax_e):
        ax.grid(True, alpha=0.3)
        ax.set_xlim(left=0.0)
    fig.suptitle(title)
    return fig


def report_speed_figure(summary: pd.DataFrame, names: dict[str, str],
                        colours: dict[str, str]) -> Figure:
    """Speed against accuracy of the report's models on its runs: seconds per predicted force
    (log) against the largest |Err%| against the measurement, one marker per run.

    ``summary``: ``run, model, seconds_per_point, max_abs_err_pct`` (NaN error: no valid point,
    not drawn).
    """
    fig = Figure(figsize=(8.5, 4.8), layout="constrained")
    ax = fig.subplots()
    runs = list(dict.fromkeys(summary["run"]))
    for _, row in summary.iterrows():
        if not np.isfinite(row["max_abs_err_pct"]) or not row["seconds_per_point"] > 0:
            continue
        ax.scatter(row["seconds_per_point"], max(row["max_abs_err_pct"], 1e-3), s=60,
                   marker=RUN_MARKERS[runs.index(row["run"]) % len(RUN_MARKERS)],
                   color=colours[row["model"]], zorder=3)
    models = list(dict.fromkeys(summary["model"]))
    handles = [Line2D([], [], color=colours[m], marker="o", linestyle="none") for m in models]
    labels = [names[m] for m in models]
    handles += [Line2D([], [], color="0.3", marker=RUN_MARKERS[i % len(RUN_MARKERS)],
                       linestyle="none") for i in range(len(runs))]
    labels += [f"run {i + 1}" for i in range(len(runs))]
    fig.legend(handles, labels, fontsize=7.5, loc="outside right upper")  # off the points
    ax.set_xscale("log")
    ax.set_yscale("log")
    from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter

    ax.yaxis.set_major_locator(LogLocator(subs=(1.0, 2.0, 5.0)))
    ax.yaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
    ax.yaxis.set_minor_formatter(NullFormatter())
    _time_axis(ax.xaxis)
    ax.set(xlabel="time per predicted force",
           ylabel="largest |Err%| against the measurement [%]",
           title="speed against accuracy on these runs (lower left is better)")
    ax.grid(True, which="major", alpha=0.35)
    ax.grid(True, which="minor", alpha=0.1)
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
    for family in dict.fromkeys(summary["family"]):
        marker = FAMILY_MARKERS.get(family, "o")
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
    _time_axis(ax.xaxis)
    ax.set(xlabel="time per predicted force (one call per muscle sweep, median)",
           ylabel="largest |Err%| against the reference [%]",
           title=f"speed against accuracy, measured on {machine}")
    ax.grid(True, which="major", alpha=0.35)
    ax.grid(True, which="minor", alpha=0.1)
    ax.legend(fontsize=8, loc="best")
    return fig


#: A colour per outcome of :func:`mkm.fem.outcomes.classify` (every one of its ``OUTCOMES``).
STABILITY_CLASSES = {
    "ok": "#d9f0d3",
    "invalid (model's own limit)": "#fdb863",
    BRAID_LOCKS: "#b35806",
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
