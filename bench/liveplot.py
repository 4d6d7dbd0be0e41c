"""Live plot of a run (``mkm acquire --plot``) that never slows acquisition.

Matplotlib runs in its own process; the run hands it points through a bounded queue with
``put_nowait`` and drops a point when the queue is full, so a slow or closed window costs the
acquisition loop one non-blocking call per block and nothing more.
"""

from __future__ import annotations

import multiprocessing as mp
import queue


def _show(points: mp.Queue, title: str) -> None:
    import matplotlib.pyplot as plt

    fig, (ax_p, ax_f) = plt.subplots(2, 1, sharex=True, figsize=(8, 6))
    fig.suptitle(title)
    t, p, f = [], [], []
    (line_p,) = ax_p.plot([], [], lw=1)
    (line_f,) = ax_f.plot([], [], lw=1)
    ax_p.set_ylabel("pressure_bar")
    ax_f.set_ylabel("force_N")
    ax_f.set_xlabel("time_s")
    while True:
        try:
            while True:
                point = points.get_nowait()
                if point is None:
                    plt.close(fig)
                    return
                t.append(point[0])
                p.append(point[1])
                f.append(point[2])
        except queue.Empty:
            pass
        line_p.set_data(t, p)
        line_f.set_data(t, f)
        for ax in (ax_p, ax_f):
            ax.relim()
            ax.autoscale_view()
        if not plt.fignum_exists(fig.number):
            return
        plt.pause(0.25)


class LivePlot:
    """Plot window in a child process, fed by :meth:`push`."""

    def __init__(self, title: str, maxsize: int = 2000):
        ctx = mp.get_context("spawn")  # a fresh interpreter: no state shared with the run
        self._points = ctx.Queue(maxsize=maxsize)
        self._process = ctx.Process(target=_show, args=(self._points, title), daemon=True)
        self._process.start()
        self.dropped = 0

    def push(self, time_s: float, pressure_bar: float, force_N: float) -> None:
        """Hand a point to the window, or drop it if the window is behind."""
        try:
            self._points.put_nowait((time_s, pressure_bar, force_N))
        except queue.Full:
            self.dropped += 1

    def close(self, timeout_s: float = 2.0) -> None:
        """Ask the window to close and wait for it; terminate it if it does not answer."""
        try:
            self._points.put(None, timeout=timeout_s)
        except queue.Full:
            pass
        self._process.join(timeout_s)
        if self._process.is_alive():
            self._process.terminate()
            self._process.join(timeout_s)
        self._points.close()
