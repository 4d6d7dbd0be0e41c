"""The report's figures: invalid points never drawn as forces, uncertainty bands, registry
colours."""

from __future__ import annotations

import numpy as np
import pandas as pd
from matplotlib.collections import PolyCollection

from mkm.figures import INVALID_Y, model_colours, run_figure
from mkm.registry import parse_specs

STEPS = pd.DataFrame({"pressure_bar_mean": [1.0, 2.0, 1.0], "force_N_mean": [100.0, 210.0, 110.0],
                      "force_N_std": [1.0, 1.0, 1.0], "direction": ["up", "up", "down"]})


def _predictions(model, force, valid, std=None):
    rows = pd.DataFrame({"model": model, "pressure_bar": [1.0, 2.0, 1.0],
                         "direction": ["up", "up", "down"], "force_N": force, "valid": valid})
    rows["err_pct"] = 100 * (STEPS["force_N_mean"] - rows["force_N"]) / 210.0
    rows["residual_N"] = STEPS["force_N_mean"] - rows["force_N"]
    if std is not None:
        rows["force_std_N"] = std
    return rows


def test_colours_come_from_the_registry_entry_and_stay_distinct():
    specs = parse_specs("eq2,eq2:theta0_deg=50,thickwall,surrogate:kind=gp")
    colours = model_colours(specs)
    assert colours["eq2"] == "tab:blue" and colours["thickwall"] == "tab:orange"
    assert colours["surrogate:kind=gp"] == "tab:red"
    assert len(set(colours.values())) == 4  # the second eq2 gets a colour of its own


def test_invalid_points_are_crosses_above_the_axes_not_forces():
    pred = _predictions("eq2", [np.nan, 205.0, np.nan], [False, True, False])
    fig = run_figure(STEPS, pred, "t", {"eq2": "Equation 2"}, {"eq2": "tab:blue"})
    ax_f = fig.axes[0]
    crosses = [line for line in ax_f.lines if line.get_marker() == "x"
               and len(line.get_xdata())]
    assert crosses, "no invalid marker drawn"
    for line in crosses:
        np.testing.assert_array_equal(line.get_ydata(), INVALID_Y)  # axes fraction, > 1
        assert line.get_transform() != ax_f.transData  # not at a force value
    curve = next(line for line in ax_f.lines if line.get_label() == "Equation 2")
    assert np.isnan(np.asarray(curve.get_ydata(), float)[0])  # no 0 N stand-in


def test_uncertainty_band_where_the_model_has_one():
    with_std = _predictions("surrogate", [101.0, 209.0, 101.0], [True] * 3, std=[5.0, 8.0, 5.0])
    fig = run_figure(STEPS, with_std, "t", {"surrogate": "Surrogate"}, {"surrogate": "tab:red"})
    bands = [c for c in fig.axes[0].collections if isinstance(c, PolyCollection)]
    assert len(bands) == 1
    y = bands[0].get_paths()[0].vertices[:, 1]
    # the band spans force ± 2 std: 101 ± 10 N at 1 bar, 209 ± 16 N at 2 bar
    assert np.isclose(y.min(), 91.0) and np.isclose(y.max(), 225.0)
    plain = _predictions("eq2", [101.0, 209.0, 101.0], [True] * 3)
    fig = run_figure(STEPS, plain, "t", {"eq2": "Equation 2"}, {"eq2": "tab:blue"})
    assert not [c for c in fig.axes[0].collections if isinstance(c, PolyCollection)]


def test_models_that_agree_stay_two_lines():
    # the surrogate over the FE model it learnt: the same forces, two distinguishable lines
    same = [100.0, 205.0, 100.0]
    pred = pd.concat([_predictions("axisym", same, [True] * 3),
                      _predictions("surrogate", same, [True] * 3)])
    fig = run_figure(STEPS, pred, "t", {"axisym": "FE", "surrogate": "Surrogate"},
                     {"axisym": "tab:green", "surrogate": "tab:red"})
    lines = {line.get_label().split(" (")[0]: line for line in fig.axes[0].lines
             if line.get_label().split(" (")[0] in ("FE", "Surrogate")}
    fe, sur = lines["FE"], lines["Surrogate"]
    assert (fe.get_linestyle(), fe.get_marker()) != (sur.get_linestyle(), sur.get_marker())
    assert fe.get_linewidth() > sur.get_linewidth()  # the one beneath shows around the other


def test_speed_chart_names_models_in_the_legend_only():
    from mkm.figures import report_speed_figure

    summary = pd.DataFrame({"run": ["a", "a", "b", "b"], "model": ["axisym", "surrogate"] * 2,
                            "seconds_per_point": [0.01, 1e-5, 0.01, 1e-5],
                            "max_abs_err_pct": [4.63, 4.63, 1.0, 1.0]})
    fig = report_speed_figure(summary, {"axisym": "FE", "surrogate": "Surrogate"},
                              {"axisym": "tab:green", "surrogate": "tab:red"})
    ax = fig.axes[0]
    assert not ax.texts  # no labels beside the points: none can print over another
    assert {t.get_text() for t in fig.legends[0].get_texts()} >= {"FE", "Surrogate"}
    # the time axis in µs and ms, never 10^-5
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    FigureCanvasAgg(fig).draw()
    ticks = [t.get_text() for t in ax.get_xticklabels() if t.get_text()]
    assert "10.0 µs" in ticks and "10.0 ms" in ticks, ticks
    assert not any("e-" in t or "^" in t for t in ticks)
    assert not _overlaps(fig)


def _overlaps(fig) -> list[str]:
    """The axes a legend of ``fig`` covers (drawn extents in pixels)."""
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    legends = list(fig.legends) + [ax.get_legend() for ax in fig.axes if ax.get_legend()]
    hits = []
    for legend in legends:
        box = legend.get_window_extent(renderer)
        hits += [ax.get_title() for ax in fig.axes if box.overlaps(ax.get_window_extent(renderer))]
    return hits


def test_legends_stay_outside_the_data_and_list_only_what_is_drawn():
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    pred = pd.concat([_predictions("axisym", [100.0, 205.0, 100.0], [True] * 3),
                      _predictions("eq2", [110.0, 230.0, 110.0], [True] * 3)])
    fig = run_figure(STEPS, pred, "t", {"axisym": "FE", "eq2": "Equation 2"},
                     {"axisym": "tab:green", "eq2": "tab:blue"})
    FigureCanvasAgg(fig)
    assert not _overlaps(fig)
    texts = [t.get_text() for t in fig.legends[0].get_texts()]
    assert "Err% and residual: down sweep" in texts
    # an imported run without a down sweep: no "down sweep" in any legend
    up = STEPS[STEPS["direction"] == "up"].reset_index(drop=True)
    only_up = pred[pred["direction"] == "up"]
    fig = run_figure(up, only_up, "t", {"axisym": "FE", "eq2": "Equation 2"},
                     {"axisym": "tab:green", "eq2": "tab:blue"})
    FigureCanvasAgg(fig)
    texts = [t.get_text() for legend in fig.legends for t in legend.get_texts()]
    assert not any("down" in t for t in texts), texts


def test_coincident_models_are_named_identical_in_the_legend():
    same = [100.0, 205.0, 100.0]
    close = [100.05, 205.1, 100.05]  # within 0.1 % of 205 N
    pred = pd.concat([_predictions("axisym", same, [True] * 3),
                      _predictions("surrogate", close, [True] * 3),
                      _predictions("eq2", [110.0, 230.0, 110.0], [True] * 3)])
    names = {"axisym": "FE", "surrogate": "Surrogate", "eq2": "Equation 2"}
    fig = run_figure(STEPS, pred, "t", names, {"axisym": "tab:green", "surrogate": "tab:red",
                                              "eq2": "tab:blue"})
    texts = [t.get_text() for t in fig.legends[0].get_texts()]
    assert "Surrogate (identical to FE within 0.1 %)" in texts
    assert "Equation 2" in texts and "FE" in texts


def test_the_overlay_names_models_identical_on_every_run():
    from mkm.figures import overlay_figure

    same = [100.0, 205.0, 100.0]
    pred = pd.concat([_predictions("axisym", same, [True] * 3),
                      _predictions("surrogate", same, [True] * 3)])
    names = {"axisym": "FE", "surrogate": "Surrogate"}
    colours = {"axisym": "tab:green", "surrogate": "tab:red"}
    fig = overlay_figure([("run 1", STEPS, pred), ("run 2", STEPS, pred)], "t", names, colours)
    texts = [t.get_text() for t in fig.legends[0].get_texts()]
    assert "Surrogate (identical to FE within 0.1 %)" in texts
    apart = pd.concat([_predictions("axisym", same, [True] * 3),
                       _predictions("surrogate", [110.0, 230.0, 110.0], [True] * 3)])
    fig = overlay_figure([("run 1", STEPS, pred), ("run 2", STEPS, apart)], "t", names, colours)
    assert "Surrogate" in [t.get_text() for t in fig.legends[0].get_texts()]
