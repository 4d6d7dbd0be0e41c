"""bench.liveplot: the live plot runs in its own process and never makes the run wait."""

import pytest

from mkm.bench.liveplot import LivePlot


@pytest.mark.slow  # a plotting process
def test_live_plot_drops_points_instead_of_blocking(monkeypatch):
    monkeypatch.setenv("MPLBACKEND", "Agg")  # the child process has no display
    plot = LivePlot("test", maxsize=5)
    for k in range(1000):  # 1000 points in ~10 ms while the child still imports matplotlib
        plot.push(k / 10, 1.0, 100.0)
    assert plot.dropped > 0  # a full queue drops points; a blocking put would hang here
    plot.close(timeout_s=1.0)
    assert not plot._process.is_alive()
